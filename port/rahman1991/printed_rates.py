"""Rahman (1991), generalized slider crank: the printed closed-form rates, literally.

Velocities are eqs. (39)-(43) of section 2.7 (seed lines 565-573). Accelerations are
eqs. (38a)-(42a) at the end of section 2.8 (seed lines 1037-1045). The thesis numbers them
oddly, so here they are side by side:

    theta2'  (39)    theta2''  (38a)
    theta3'  (40)    theta3''  (39a)
    eta2'    (41)    eta2''    (40a)
    eta3'    (42)    eta3''    (41a)
    S4'      (43)    S4''      (42a)

Joint variables: theta2, eta2 (ball joint 2), theta3, eta3 (ball joint 3), S4 (slider).
Inputs: the crank angle theta1 and its axial slide S1 (only their rates enter), and the
crank and rod lengths a1, a2. Units: inch, rad, s (rates in rad/s and in/s, rad/s^2 and
in/s^2).

Each formula is evaluated the way it is printed: same terms, same grouping, left-to-right
products, no simplification, because the port measures their round-off. This is the printed
formulation. Its denominators s(theta3) (in (39), (40), (43)) and s(theta2) s(theta3) (in (41),
(42)) vanish, and the accelerations divide by their squares. So everything blows up as
theta2 -> 0 (thesis, section 3.2). The functions never guard a division. With numpy a
near-zero sine gives huge values, and an exact zero gives inf/nan with a RuntimeWarning.
With mpmath an exact zero raises ZeroDivisionError.

The code is generic over the arithmetic. ``m`` supplies ``sin`` and ``cos``: ``m=numpy``
(the default; the arguments can be arrays that broadcast) or ``m=mpmath`` (the arguments
are mpf scalars). Only ``m.sin``, ``m.cos`` and + - * / ** are used.

Restored dots. The OCR renders S1'' as S1' in the first term of each acceleration
numerator bracket. The terms these replace are the time derivatives of the S1' terms of
(39)-(43), and the quotient rule needs S1'' there. Each line that restores a dot has a
comment giving the seed line. Apart from these, the printed text is kept.

Errors of the author are kept as printed and listed in PRINTED_ERRORS: a missing c^2(eta2)
in (39), and joint twists (30), (31) put in the wrong frame. Because of these, (39), (41) and
(42) are exact only in planar motion (eta2 = eta3 = 0).
"""
from __future__ import annotations

import numpy as np

#: Errors of the author (not OCR) that touch these formulas. The formulas are kept as printed.
PRINTED_ERRORS = [
    "(39) theta2', seed l. 565: the term a1 theta1' s(theta2) c(theta3) lacks a factor "
    "c^2(eta2), so (39) breaks (37a), (37d) and (37e) by a1 theta1' s(theta2) c(theta3) "
    "s^2(eta2) / (a2 s(theta3)) when eta2 != 0. (38a) differentiates the printed form.",
    "(38) row 6, seed l. 561: the right-hand side is printed -theta1' a1 s(theta2) - S1' c(eta2); "
    "(37f) gives -theta1' a1 s(theta2) s(eta2) - S1' c(eta2). (39)-(43) do not use row 6.",
    "(30), (31), seed l. 503, 507: the joint twists are printed as (0, eta', theta'). For "
    "Z(theta) Y(eta) the twist in frames {2}, {3} is (-eta' s(theta), eta' c(theta), theta'). "
    "So (37) and (39), (41), (42) are wrong when eta2' != 0. On a closed spatial trajectory "
    "of loop (1)-(5), (40) and (43) still give the exact theta3' and S4'.",
]


def velocities(theta2, eta2, theta3, eta3, theta1_d, s1_d, a1, a2, m=np):
    """(theta2', theta3', eta2', eta3', S4') from eqs. (39)-(43), as printed.

    theta1_d = theta1' (rad/s) and s1_d = S1' (in/s) are the crank's rates; a1 and a2 are
    in inches. eta3 is not used: it does not appear in (39)-(43).
    """
    s2, c2 = m.sin(theta2), m.cos(theta2)
    s3, c3 = m.sin(theta3), m.cos(theta3)
    se2, ce2 = m.sin(eta2), m.cos(eta2)
    t1d, s1d = theta1_d, s1_d

    # (39), seed l. 565 (see PRINTED_ERRORS[0])
    theta2_d = (s1d*c3*se2*ce2 - a1*(t1d*s2*c3 + t1d*c2*s3*ce2) - a2*t1d*s3) / (a2*s3)
    # (40), seed l. 567
    theta3_d = (a1*(t1d*c2*s3 + t1d*s2*c3*ce2) - s1d*c3*se2) / (a2*s3)
    # (41), seed l. 569
    eta2_d = (-se2*(a1*(t1d*c2*s3 + t1d*s2*c3*ce2) - s1d*se2*c3)) / (a2*s2*s3)
    # (42), seed l. 571
    eta3_d = (c2*se2*(t1d*a1*(s2*c3*ce2 + c2*s3) - s1d*se2*c3)) / (a2*s2*s3)
    # (43), seed l. 573
    s4_d = (s1d*se2 - t1d*a1*s2*ce2) / s3
    return theta2_d, theta3_d, eta2_d, eta3_d, s4_d


def accelerations(theta2, eta2, theta3, eta3, rates, theta1_d, theta1_dd, s1_d, s1_dd,
                  a1, a2, m=np):
    """(theta2'', theta3'', eta2'', eta3'', S4'') from eqs. (38a)-(42a), as printed.

    ``rates`` is the tuple that velocities() returns, (theta2', theta3', eta2', eta3', S4').
    Only theta2', theta3' and eta2' appear in the printed formulas. theta1_dd = theta1''
    (rad/s^2) and s1_dd = S1'' (in/s^2) enter where the dots were restored. eta3 is not used.
    """
    s2, c2 = m.sin(theta2), m.cos(theta2)
    s3, c3 = m.sin(theta3), m.cos(theta3)
    se2, ce2 = m.sin(eta2), m.cos(eta2)
    t2d, t3d, e2d, _e3d, _s4d = rates
    t1d, t1dd, s1d, s1dd = theta1_d, theta1_dd, s1_d, s1_dd

    # (38a) theta2'', seed l. 1037
    theta2_dd = (
        a2*s3*(s1dd*c3*se2*ce2              # s1dd: printed S1' (lost dot), seed l. 1037
               - s1d*t3d*s3*se2*ce2 + s1d*e2d*c3*ce2**2 - s1d*e2d*c3*se2**2
               - a1*(t1dd*s2*c3 + t1d*t2d*c2*c3 - t1d*t3d*s2*s3 + t1dd*c2*s3*ce2
                     - t1d*t2d*s2*s3*ce2 + t1d*t3d*c2*c3*ce2 - t1d*e2d*c2*s3*se2)
               - a2*t1dd*s3 - a2*t1d*t3d*c3)
        - a2*t3d*c3*(s1d*c3*se2*ce2 - a1*(t1d*s2*c3 + t1d*c2*s3*ce2) - a2*t1d*s3)
    ) / (a2*s3)**2

    # (39a) theta3'', seed l. 1039
    theta3_dd = (
        a2*s3*(a1*(t1dd*c2*s3 - t1d*t2d*s2*s3 + t1d*t3d*c2*c3 + t1dd*s2*c3*ce2
                   + t1d*t2d*c2*c3*ce2 - t1d*t3d*s2*s3*ce2 - t1d*e2d*s2*c3*se2)
               - s1dd*c3*se2                # s1dd: printed S1' (lost dot), seed l. 1039
               + s1d*t3d*s3*se2 - s1d*e2d*c3*ce2)
        - a2*t3d*c3*(a1*(t1d*c2*s3 + t1d*s2*c3*ce2) - s1d*c3*se2)
    ) / (a2*s3)**2

    # (40a) eta2'', seed l. 1041
    eta2_dd = (
        a2*s2*s3*(-e2d*ce2*(a1*(t1d*c2*s3 + t1d*s2*c3*ce2) - s1d*se2*c3)
                  - se2*(a1*(t1dd*c2*s3 - t1d*t2d*s2*s3 + t1d*t3d*c2*c3 + t1dd*s2*c3*ce2
                             + t1d*t2d*c2*c3*ce2 - t1d*t3d*s2*s3*ce2 - t1d*e2d*s2*c3*se2)
                         - s1dd*se2*c3      # s1dd: printed S1' (lost dot), seed l. 1041
                         - s1d*e2d*ce2*c3 + s1d*t3d*se2*s3))
        + a2*se2*(a1*(t1d*c2*s3 + t1d*s2*c3*ce2) - s1d*se2*c3)*(t2d*c2*s3 + t3d*s2*c3)
    ) / (a2*s2*s3)**2

    # (41a) eta3'', seed l. 1043
    eta3_dd = (
        a2*s2*s3*((-t2d*s2*se2 + e2d*c2*ce2)*(t1d*a1*(s2*c3*ce2 + c2*s3) - s1d*se2*c3)
                  + c2*se2*(t1dd*a1*(s2*c3*ce2 + c2*s3)
                            + t1d*a1*(t2d*c2*c3*ce2 - t3d*s2*s3*ce2 - e2d*s2*c3*se2
                                      + t3d*c2*c3 - t2d*s2*s3)
                            - s1dd*se2*c3   # s1dd: printed S1' (lost dot), seed l. 1043
                            - s1d*e2d*ce2*c3 + s1d*t3d*se2*s3))
        - a2*c2*se2*(t1d*a1*(s2*c3*ce2 + c2*s3) - s1d*se2*c3)*(t2d*c2*s3 + t3d*s2*c3)
    ) / (a2*s2*s3)**2

    # (42a) S4'', seed l. 1045
    s4_dd = (
        s3*(s1dd*se2                        # s1dd: printed S1' (lost dot), seed l. 1045
            + s1d*e2d*ce2
            - a1*(t1dd*s2*ce2 + t1d*t2d*c2*ce2 - t1d*e2d*s2*se2))
        - (s1d*se2 - t1d*a1*s2*ce2)*t3d*c3
    ) / s3**2

    return theta2_dd, theta3_dd, eta2_dd, eta3_dd, s4_dd
