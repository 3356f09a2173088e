"""Independent closed-form reference: planar offset slider-crank (Raven's method).

Reference for the planar case of S. Rahman (1991), "Dynamic analysis of the
generalized slider crank", example of section 3.1.  numpy only; it does not use
linkrepro.

Units: inches, radians, seconds, lbf; masses in lbf*s^2/in.  Fixed frame x, y,
z out of the plane; angles and moments positive counter-clockwise (about +z).

Geometry: crank pivot O at the origin; crank pin P = a1 (cos th1, sin th1);
slider pin Q = (-a4, s4) on the line x = -a4; rod of length a2 from P to Q.
Loop equation (complex numbers):  a1 e^{i th1} + a2 e^{i th_rod} = -a4 + i s4,
branch s4 > 0 at th1 = 0, i.e. s4 = a1 sin th1 + sqrt(a2^2 - (a1 cos th1 + a4)^2)
(equivalently sin th_rod > 0).  Constant crank speed w, th1'' = 0.

Dynamics: Newton-Euler for crank (1), rod (2), slider (3); no gravity loads (g
only converts weight to mass).  Crank and rod centres of mass at mid-length,
slider's at Q.  A constant torque T (about +z) acts on the crank from the frame;
the balancing unknown is the piston force (along y) on the slider from the frame.

Dead centres (crank and rod collinear, sin(th_rod - th1) = 0): s4' = 0, so the
piston force does no work and T*w cannot be balanced at constant speed; the
9x9 system is singular there.  At angles within rounding of a dead centre
(|sin(th_rod - th1)| < 1e-12) every force output is NaN; elsewhere it is finite
(and grows like 1/sin(th_rod - th1) near a dead centre).
"""
import numpy as np

DEAD_CENTRE_TOL = 1e-12


def _cross(r, f):
    return r[..., 0] * f[..., 1] - r[..., 1] * f[..., 0]


def analyse(theta1_deg, a1=12.0, a2=50.0, a4=0.0, rpm=50.0, torque=100.0,
            r1=1.5, r2=1.0, r3=3.0, density=0.28, g=386.4):
    """Kinematics and joint forces of the offset slider-crank at crank angles theta1_deg.

    Returns a dict of numpy arrays (n = number of angles):
      theta1 (n,) rad; s4, s4_d, s4_dd (n,) slider position along y [in, in/s, in/s^2];
      th_rod, th_rod_d, th_rod_dd (n,) absolute rod angle of Q - P from +x [rad, rad/s, rad/s^2];
      P, Q (n, 2) crank pin and slider pin [in];
      a_G1, a_G2, a_G3 (n, 2) centre-of-mass accelerations of crank, rod, slider [in/s^2];
      F_frame_on_crank (n, 2) force on crank from frame at O [lbf];
      F_crank_on_rod (n, 2) force on rod from crank at P [lbf];
      F_rod_on_slider (n, 2) force on slider from rod at Q [lbf];
      guide_normal_on_slider (n,) x-force on slider from guide [lbf];
      piston_on_slider (n,) y-force on slider from frame [lbf] (positive along +y);
      guide_moment_on_slider (n,) z-moment on slider from guide [lbf*in] (zero in the plane).
    Raises ValueError if a2 < |a1 cos th1 + a4| for some angle (cannot assemble).
    """
    th1 = np.radians(np.atleast_1d(np.asarray(theta1_deg, dtype=float)))
    w = rpm * 2.0 * np.pi / 60.0
    c1, sn1 = np.cos(th1), np.sin(th1)
    h = a1 * c1 + a4                       # horizontal reach the rod must span
    if np.any(a2 < np.abs(h)):
        raise ValueError("rod too short: a2 < |a1 cos th1 + a4| (cannot assemble)")
    root = np.sqrt(a2**2 - h**2)           # = a2 sin th_rod >= 0
    s4 = a1 * sn1 + root
    th = np.arctan2(root, -h)              # a2 e^{i th} = Q - P
    c, sn = np.cos(th), np.sin(th)
    # d/dt of loop: i a1 w e^{i th1} + i a2 th' e^{i th} = i s4'
    th_d = -a1 * w * sn1 / (a2 * sn)
    s4_d = a1 * w * c1 + a2 * th_d * c
    # d2/dt2: -a1 w^2 e^{i th1} + (i a2 th'' - a2 th'^2) e^{i th} = i s4''
    th_dd = -(a1 * w**2 * c1 + a2 * th_d**2 * c) / (a2 * sn)
    s4_dd = -a1 * w**2 * sn1 + a2 * th_dd * c - a2 * th_d**2 * sn

    n = th1.size
    P = a1 * np.stack([c1, sn1], axis=-1)
    Q = np.stack([np.full(n, -a4), s4], axis=-1)
    G1, G2, G3 = 0.5 * P, 0.5 * (P + Q), Q
    aP = -w**2 * P
    aQ = np.stack([np.zeros(n), s4_dd], axis=-1)
    a_G1, a_G2, a_G3 = 0.5 * aP, 0.5 * (aP + aQ), aQ

    m1 = np.pi * r1**2 * a1 * density / g
    m2 = np.pi * r2**2 * a2 * density / g
    m3 = r3**3 * density / g
    I1 = m1 * (r1**2 / 4 + a1**2 / 12)
    I2 = m2 * (r2**2 / 4 + a2**2 / 12)

    # Unknowns x = [F01x, F01y, F12x, F12y, F23x, F23y, N, Fp, M]; rows 3b..3b+2 of
    # body b = (sum Fx, sum Fy, sum Mz about its centre of mass).
    A = np.zeros((n, 9, 9))
    rhs = np.zeros((n, 9))

    def force(body, col, sign, r):         # force x[col:col+2] (times sign) at r - G
        A[:, 3 * body, col] += sign
        A[:, 3 * body + 1, col + 1] += sign
        A[:, 3 * body + 2, col] += -sign * r[:, 1]
        A[:, 3 * body + 2, col + 1] += sign * r[:, 0]

    force(0, 0, +1, -G1)                   # frame -> crank at O
    force(0, 2, -1, P - G1)                # rod -> crank at P (= -F12)
    force(1, 2, +1, P - G2)                # crank -> rod at P
    force(1, 4, -1, Q - G2)                # slider -> rod at Q (= -F23)
    force(2, 4, +1, Q - G3)                # rod -> slider at Q
    A[:, 6, 6] = A[:, 7, 7] = A[:, 8, 8] = 1.0   # guide N (x), piston Fp (y), moment M
    rhs[:, 0:2] = m1 * a_G1
    rhs[:, 2] = I1 * 0.0 - torque          # crank: constant speed, applied torque T
    rhs[:, 3:5] = m2 * a_G2
    rhs[:, 5] = I2 * th_dd
    rhs[:, 6:8] = m3 * a_G3                # slider does not rotate: row 8 rhs = 0

    x = np.full((n, 9), np.nan)
    ok = np.abs(np.sin(th - th1)) >= DEAD_CENTRE_TOL
    if ok.any():
        x[ok] = np.linalg.solve(A[ok], rhs[ok][..., None])[..., 0]

    return dict(theta1=th1, s4=s4, s4_d=s4_d, s4_dd=s4_dd,
                th_rod=th, th_rod_d=th_d, th_rod_dd=th_dd, P=P, Q=Q,
                a_G1=a_G1, a_G2=a_G2, a_G3=a_G3,
                F_frame_on_crank=x[:, 0:2], F_crank_on_rod=x[:, 2:4],
                F_rod_on_slider=x[:, 4:6], guide_normal_on_slider=x[:, 6],
                piston_on_slider=x[:, 7], guide_moment_on_slider=x[:, 8])


def in_thesis_frames(ref):
    """The reference's forces as Rahman's (1991) joint vectors for alpha4 = 270 deg (dict of
    arrays keyed like ``port.gsc_forces.COMPONENTS``, plus s4).  His vectors are the loads the
    link nearer the crank exerts (crank on frame, crank on rod, rod on slider, slider on
    frame); call ``analyse`` with torque = -T1k (its torque acts on the crank).  2F2 is in the
    crank's frame, 3F3 in the rod's (i along Q - P), 4F4 in the slider's: i4 = x, k4 = -y."""
    c1, s1 = np.cos(ref["theta1"]), np.sin(ref["theta1"])
    cr, sr = np.cos(ref["th_rod"]), np.sin(ref["th_rod"])
    f1, f2, f3 = -ref["F_frame_on_crank"], ref["F_crank_on_rod"], ref["F_rod_on_slider"]
    return {"s4": ref["s4"], "F1i": f1[:, 0], "F1j": f1[:, 1],
            "F2i": c1 * f2[:, 0] + s1 * f2[:, 1], "F2j": -s1 * f2[:, 0] + c1 * f2[:, 1],
            "F3i": cr * f3[:, 0] + sr * f3[:, 1], "F3j": -sr * f3[:, 0] + cr * f3[:, 1],
            "F4i": -ref["guide_normal_on_slider"], "F4k": ref["piston_on_slider"]}
