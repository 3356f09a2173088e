"""The original errors of Rahman's (1991) method, one switch each (register ids in comments).

``GSC_PRINTED`` (all on) runs the thesis as printed; ``GSC_CORRECTED`` (all off) what it
means.  ``five_variable_loop`` decides the model: on, the printed displacement analysis and
force equations run (``rahman1991.position``, ``rahman1991.forces.printed_forces``) and the switches marked
[printed] fix them one at a time; off, the exact closed loop with a spin-free rod and
Newton-Euler (``slider_crank.kinematics.kinematics``, ``rahman1991.forces.corrected_forces``) runs.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..quirks import QuirkSwitches


@dataclass(frozen=True)
class GscQuirks(QuirkSwitches):
    five_variable_loop: bool = True       # D085 [model] two angles per ball joint: the loop cannot close unless k3 is normal to k4
    com_beyond_joint: bool = True         # D086 [printed] g1 = a1/2, g2 = a2/2 put the centres of mass beyond the distal joints
    sine_denominator_rates: bool = True   # D087 [printed] closed forms (39)-(43), (38a)-(42a) divide by s(theta3), s(theta2) s(theta3)
    joint_force_signs: bool = True        # D088 [printed] (63), (64) add 2F2 and 3F3 with the sign (62), (63) gave them


GSC_PRINTED = GscQuirks()
GSC_CORRECTED = GscQuirks.all(False)
