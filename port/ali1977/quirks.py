"""Ali (1977): the K.E.D. listings' bugs, one switch each.

``PRINTED`` turns every quirk on: the port then reproduces the legacy FORTRAN.
``CORRECTED`` turns them all off: the port computes what the thesis meant.
Each field names its entry in ``harness/deviations.toml``.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..quirks import QuirkSwitches


@dataclass(frozen=True)
class Quirks(QuirkSwitches):
    pi_22_7: bool = True                 # D011  PI=3.142857143 (22/7) in every listing
    source_alpha_101: bool = True        # D012  source listing: ALP=1.762782545 (101 deg), not 60 deg
    omega3_sign: bool = True             # D013  OM3 uses SIN(T4-T3) for SIN(T4-T2)
    g_coefficient: bool = True           # D014  G1 uses COS(T2) where eq. (18) has SIN(theta2)
    i_coefficient: bool = True           # D015  I1 uses L2*COS(T3) where eq. (18) has L3
    input_link_bending_area: bool = True  # D016  F(5,5)=L1^3/(3*A*E), eq. (29) has E*I
    source_rpm_400: bool = True          # D017  source listing runs at 400 rpm, the data say 300
    inertia_sign: bool = True            # D018  P = +m*a; the inertia (d'Alembert) force is -m*a
    real4_storage: bool = True           # D019  matrices and forces stored REAL*4
    cognate_frame: bool = True           # D025  cognate deflections left in the cognate's own frame
    cognate_moment_row: bool = True      # D026  cognate CG1, CH1, CI1 are not the moments about P
    cognate_beta_quadrant: bool = True   # D141  cognate BETA=ATAN(SQRT(1-CBTA**2)/CBTA): beta's sign and quadrant lost
    toggle_as_open: bool = True          # D142  a toggle whose discriminant rounds below 0 is "cannot close"
    joint_load_components: bool = True   # D031  Case II: P5, P6, P7 not the components along the elements
    joint_b_acceleration_sign: bool = True  # D032  Case II: +L3*ALPH3*SIN(T3) in B's x-acceleration
    coupler_load_in_f7: bool = True      # D144  Case II: beta2's column 7 puts the crank pin's P7 into the coupler's f7
    cognate_joint_load_signs: bool = True  # D145  Case II cognate (reconstruction): P4, P5, P7 reversed (source's axes)
    node_mass_from_pin: bool = True      # D033  Case III: node k carries the mass of the extender up to it
    uncoupled_nodes: bool = True         # D034  Case III: block-diagonal beta*, F*: a node feels only its own load
    tip_rotation_node_2: bool = True     # D035  Case III: block 1's beta* column 3 in block 2's rows (with D034)
    u470_operands: bool = True           # D036  Case III: U(470)=(A1*D1-B1*..)/R4 for (A1*E1-B1*D1)/R4 (with D034)



PRINTED = Quirks()
CORRECTED = Quirks.all(False)
