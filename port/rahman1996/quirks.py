"""The bugs of Rahman's (1996) CSSP listing, one switch each (register ids in comments).

``CSSP_PRINTED`` (all on) makes the port reproduce the legacy build; ``CSSP_CORRECTED``
(all off) computes what the thesis means.  ``open_loop_model`` decides the model:
on, the listing's own kinematics and reaction equations run (``rahman1996.listing``) and the
switches marked [listing] fix its formulas one at a time; off, the closed-loop
Newton-Euler model runs (``rahman1996.mechanics``), where only the switches marked [both]
(the objective's and the tables' definitions, and REAL*4) still apply.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..quirks import QuirkSwitches


@dataclass(frozen=True)
class CsspQuirks(QuirkSwitches):
    open_loop_model: bool = True               # D079 [model] Newton on 6 eqs in 5 unknowns: the loop never closes
    cssp_real4: bool = True                    # D078 [both] REAL*4 inputs and literals; H and the solution in REAL*4
    eat3: bool = True                          # D060 [listing] COS(EAT3), SIN(EAT3) in L3RDD
    stale_slider_moment: bool = True           # D061 [listing] qy(9), qz(9) from the previous position's fz(9), fy(9)
    f3x7_twice: bool = True                    # D062 [listing] f3x(7) assigned twice, f3x(8) carried over
    ty5_for_ty7: bool = True                   # D063 [listing] f2y(7) uses ty(5)
    objective_offdiag_doubling: bool = True    # D064 [both] OBJFUN, NUOBJFUN double the off-diagonal of F
    bearing_force_no_z: bool = True            # D065 [both] the bearing force leaves out R4z
    in_place_frame_change: bool = True         # D066 [listing] loops 50, 60, 70 rotate vectors into themselves
    crank_bearing_moment_form: bool = True     # D067 [listing] t1x, t1y lack sin/cos; t1x(5..9) = t1z*A1
    f4y9_sign: bool = True                     # D068 [listing] f4y(9) with the opposite sign
    objective_37_positions: bool = True        # D070 [both] 0 and 360 deg both counted, L = 37
    pair_force_doubled: bool = True            # D071 [listing] px..pz(1..3, 5..7): the half masses' accelerations not halved
    slider_mass_twice: bool = True             # D072 [listing] py(9), pz(9) per unit mass still carry M3
    f3z_ty_sign: bool = True                   # D073 [listing] f3z = -(fz + ty/A2); eq. (69c) has -ty
    crank_pin_force_rotated_twice: bool = True  # D074 [listing] f1x, f1y turn f2 by theta1 again after loop 60
    slider_skips_frame_loops: bool = True      # D075 [listing] loops 50, 60, 70 stop at 8: the slider's stay local
    shaking_in_link_frames: bool = True        # D076 [listing] shaking force and moment sum components of different frames
    moments_about_origin: bool = True          # D077 [listing] the reaction equations take inertia moments about O
    inverse_without_pivoting: bool = True      # D084 [listing] INVERSE: Gauss-Jordan, no pivoting
    qp_cg_masses_free: bool = True             # D130 [both] the QP fixes x1+x2+x3, x5+x6+x7 only: x4, x8 fall, the links lose mass
    qp_data_rounded: bool = True               # D131 [both] DATA b typed to 4 digits: x9 = 0.01553 for M3, bounds, sums
    bearing_torque_with_input_torque: bool = True  # D132 [both] Table 5.6 = |M1 + M4| with T0; eq. (4.1) has M1 - T0


CSSP_PRINTED = CsspQuirks()
CSSP_CORRECTED = CsspQuirks.all(False)
