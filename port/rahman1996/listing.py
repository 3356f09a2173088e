"""The CSSP listing's own mechanics (Rahman 1996, Appendix B), quirk by quirk.

Kinematics: the printed Newton-Raphson on the dual-number loop closure M1 L2 L3 M4 = I
with the pseudo-inverse (A'A)^-1 A' (6 equations, 5 unknowns theta2, eta2, theta3, eta3,
s4; register D079), velocities and accelerations by the listing's VM, VV, AV.  Loads:
per unit of each of the nine point masses, the inertia force and moment and the joint
reactions of the listing's equations (the 1991 method, eqs. 62-69).  Every quirk of
``CsspQuirks`` marked [listing] is switched here.

Units: inch, lbf, second, radians.  Arrays are over crank positions (n), point masses
(9) and components (3).  The Newton iteration is sequential (each position starts from
the previous one's answer, as printed) and compiled in the listing's order of operations
(``slider_crank._newton``: it is chaotic where it wanders, so only the same roundings give the
same answer); everything after it is vectorised.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...checks import angles_deg, finite_matrix, listing_condition, real_array, refuse_singular_position
from ...errors import ConvergenceError, SingularPositionError
from ..slider_crank import _newton as kernel
from .data import Constants
from .objective import UnitLoads
from .quirks import CsspQuirks
from ..dual import DualMatrix

_ROT_OPERATOR = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])


def _mat3(rows) -> np.ndarray:
    """A 3 x 3 matrix from nested rows of scalars or equal-shaped arrays: (..., 3, 3)."""
    shape = next((x.shape for row in rows for x in row if isinstance(x, np.ndarray) and x.ndim), ())
    out = np.empty(shape + (3, 3))
    for i, row in enumerate(rows):
        for j, x in enumerate(row):
            out[..., i, j] = x
    return out


def _m1(theta1, c: Constants) -> DualMatrix:
    """Eq. (2.3), the crank."""
    ct, st, z = np.cos(theta1), np.sin(theta1), 0.0
    return DualMatrix(_mat3([[ct, -st, z], [st, ct, z], [z, z, 1.0]]),
                      _mat3([[-c.s1 * st, -c.s1 * ct, c.a1 * st], [c.s1 * ct, -c.s1 * st, -c.a1 * ct],
                             [z, c.a1, z]]))


def _l2(theta2, eta2, c: Constants) -> DualMatrix:
    """Eq. (2.6), the connecting rod (row 3 of the real part reconstructed, D081)."""
    c2, s2, ce, se = np.cos(theta2), np.sin(theta2), np.cos(eta2), np.sin(eta2)
    return DualMatrix(_mat3([[c2 * ce, -s2, c2 * se], [s2 * ce, c2, s2 * se], [-se, 0.0, ce]]),
                      _mat3([[0.0, c.a2 * c2 * se, c.a2 * s2], [0.0, c.a2 * s2 * se, -c.a2 * c2],
                             [0.0, c.a2 * ce, 0.0]]))


def _l3_real(theta3, eta3) -> np.ndarray:
    """Eq. (2.7), the slider's ball joint (twist pi/2, no dual part); batched over positions."""
    c3, s3, ce, se = np.cos(theta3), np.sin(theta3), np.cos(eta3), np.sin(eta3)
    return _mat3([[c3 * ce, c3 * se, s3], [s3 * ce, s3 * se, -c3], [-se, ce, 0.0]])


def _m4(s4, c: Constants) -> DualMatrix:
    """Eq. (2.4), the ground link (theta4 = 0)."""
    ca, sa = np.cos(c.alpha4), np.sin(c.alpha4)
    return DualMatrix(_mat3([[1.0, 0.0, 0.0], [0.0, ca, -sa], [0.0, sa, ca]]),
                      _mat3([[0.0, -s4 * ca, s4 * sa], [s4, -c.a4 * sa, -c.a4 * ca],
                             [0.0, c.a4 * ca, -c.a4 * sa]]))


def _about_axis(theta) -> np.ndarray:
    """The listing's Q2R / Q4R operators: derivative of L2 wrt eta2 (L3 wrt eta3)."""
    ct, st = np.cos(theta), np.sin(theta)
    return _mat3([[0.0, 0.0, ct], [0.0, 0.0, st], [-ct, -st, 0.0]])


def printed_inverse(s) -> np.ndarray:
    """The listing's INVERSE of a 5 x 5 matrix (D084): Gauss-Jordan without pivoting, rows
    exchanged only on an exactly zero pivot.  Raises SingularPositionError where the listing
    prints MATRIX IS SINGULAR and STOPs."""
    s = finite_matrix("INVERSE's argument", s, (5, 5))
    b, singular = kernel.listing_inverse(np.ascontiguousarray(s))
    if singular:
        raise SingularPositionError("INVERSE: MATRIX IS SINGULAR")
    if not np.all(np.isfinite(b)):
        raise SingularPositionError("INVERSE: a pivot under- or overflowed (non-finite inverse)")
    return b


def _loop_operators(theta1, q: np.ndarray, c: Constants) -> tuple[DualMatrix, DualMatrix]:
    """H_j = G_j Q_j G_j' for q (..., 5) = (theta2, eta2, theta3, eta3, s4), stacked
    (5, ..., 3, 3), and the loop product B = M1 L2 L3 M4: d B / d q_j = H_j B (eqs.
    2.18-2.24; Rahman 1991 eqs. 11-18).  theta1 and the fields of c broadcast with q[..., 0]."""
    q = np.asarray(q, dtype=float)
    m1, l2 = _m1(theta1, c), _l2(q[..., 0], q[..., 1], c)
    m1l2 = m1 @ l2
    l3 = _l3_real(q[..., 2], q[..., 3])
    h5 = m1l2 @ DualMatrix(l3, np.zeros_like(l3))
    shape = h5.real.shape
    zero, rot = np.zeros(shape), np.broadcast_to(_ROT_OPERATOR, shape)
    parts = [np.broadcast_to(x, shape) for x in (m1.real, m1l2.real, h5.real, m1.dual, m1l2.dual, h5.dual)]
    carry = DualMatrix(np.stack([parts[0], parts[0], parts[1], parts[1], parts[2]]),
                       np.stack([parts[3], parts[3], parts[4], parts[4], parts[5]]))
    eta_ops = [np.broadcast_to(_about_axis(q[..., k]), shape) for k in (0, 2)]
    operators = DualMatrix(np.stack([rot, eta_ops[0], rot, eta_ops[1], zero]),
                           np.stack([zero, zero, zero, zero, rot]))     # theta2 eta2 theta3 eta3 s4
    return carry @ operators @ carry.T, h5 @ _m4(q[..., 4], c)


@dataclass
class Motion:
    """Joint variables and their first and second time derivatives, over positions."""
    theta1: np.ndarray
    theta2: np.ndarray
    eta2: np.ndarray
    theta3: np.ndarray
    eta3: np.ndarray
    s4: np.ndarray
    rates: np.ndarray        # (n, 5): theta2', theta3', eta2', eta3', s4' (the listing's DOT order)
    accels: np.ndarray       # (n, 5): the same order (DDOT)

    @property
    def q(self) -> np.ndarray:
        """(n, 5): theta2, eta2, theta3, eta3 (rad), s4 (in), the Newton's order."""
        return np.stack([self.theta2, self.eta2, self.theta3, self.eta3, self.s4], axis=1)


def listing_pass(crank_deg: np.ndarray, q0: np.ndarray, c: Constants, printed: bool = True) -> Motion:
    """One pass of the listing's DO 400 loop over the crank angles (deg): at each, the
    printed Newton from the last answer, then the rates by VM, VV and AV (constant crank
    speed), compiled in the listing's order of operations (``slider_crank._newton``).

    Raises where the listing STOPs, at the same crank angle: ConvergenceError after 150
    Newton evaluations, SingularPositionError when INVERSE meets a zero pivot (in the
    Newton's A'A or the rates' VM'VM); before either, SingularPositionError at the first
    position computed whose loop is ill-conditioned (``linkrepro.checks``, register D150).
    ``printed``: invert with the listing's INVERSE, else by LU with pivoting.
    """
    deg = angles_deg("crank_deg", crank_deg)
    if not isinstance(c, Constants):
        raise TypeError(f"c must be rahman1996.data.Constants, got {type(c).__name__}")
    q0 = real_array("q0", q0)
    if q0.shape != (5,):
        raise ValueError(f"q0 must hold the five positions, got shape {q0.shape}")
    theta1 = deg * (c.pi / 180.0)
    q, dot, ddot, _, status, j = kernel.listing_sweep(theta1, q0, c.a1, c.a2, c.a4,
                                                      c.alpha4, c.s1, c.omega, c.newton_tol, printed)
    refuse_singular_position(deg, listing_condition(q[:, 0], q[:, 1], q[:, 2]))   # NaN where not computed
    if status == kernel.NOT_CONVERGED:
        why = ("the first estimate sqrt(a2^2-(a1+a4)^2) is not real" if not np.all(np.isfinite(q0))
               else f"no convergence after {kernel.MAX_ITERATIONS} iterations")
        raise ConvergenceError(f"CSSP Newton-Raphson: {why}", float(deg[j]))
    if status == kernel.SINGULAR:
        raise SingularPositionError("CSSP: INVERSE met a zero pivot (MATRIX IS SINGULAR)", float(deg[j]))
    t2, e2, t3, e3, s4 = q.T
    return Motion(theta1, t2, e2, t3, e3, s4, dot, ddot)


def _crank_frames(theta1, omega):
    """Rz(theta1) and its first and second time derivatives at constant speed."""
    c, s = np.cos(theta1), np.sin(theta1)
    zero, one = np.zeros_like(c), np.ones_like(c)
    r = np.stack([np.stack([c, -s, zero], -1), np.stack([s, c, zero], -1), np.stack([zero, zero, one], -1)], -2)
    rd = omega * np.stack([np.stack([-s, -c, zero], -1), np.stack([c, -s, zero], -1),
                           np.stack([zero, zero, zero], -1)], -2)
    rdd = -omega ** 2 * np.stack([np.stack([c, -s, zero], -1), np.stack([s, c, zero], -1),
                                  np.stack([zero, zero, zero], -1)], -2)
    return r, rd, rdd


def _slider_frames(m: Motion, eat3: bool):
    """TL3R (= L3R') and the listing's L3RD, L3RDD (its time derivatives; EAT3 typos, D060)."""
    c3, s3, ce, se = np.cos(m.theta3), np.sin(m.theta3), np.cos(m.eta3), np.sin(m.eta3)
    d3, de = m.rates[:, 1], m.rates[:, 3]
    dd3, dde = m.accels[:, 1], m.accels[:, 3]
    ce_typo, se_typo = (np.ones_like(ce), np.zeros_like(se)) if eat3 else (ce, se)
    zero = np.zeros_like(c3)
    rd = np.stack([np.stack([-s3 * ce * d3 - c3 * se * de, c3 * ce * d3 - s3 * se * de, -ce * de], -1),
                   np.stack([c3 * ce * de - s3 * se * d3, c3 * se * d3 + s3 * ce * de, -se * de], -1),
                   np.stack([c3 * d3, s3 * d3, zero], -1)], -2)
    sq = d3 ** 2 + de ** 2
    rdd = np.stack([
        np.stack([2 * s3 * se * d3 * de - c3 * ce_typo * sq - s3 * ce * dd3 - c3 * se * dde,
                  -2 * se * c3 * d3 * de - s3 * ce_typo * sq - s3 * se * dde + c3 * ce * dd3,
                  se * de ** 2 - ce * dde], -1),
        np.stack([-2 * s3 * ce * d3 * de - c3 * se_typo * sq + c3 * ce * dde - s3 * se * dd3,
                  2 * c3 * ce * d3 * de - s3 * se_typo * sq + c3 * se * dd3 + s3 * ce * dde,
                  -ce * de ** 2 - se * dde], -1),
        np.stack([-s3 * d3 ** 2 + c3 * dd3, c3 * d3 ** 2 + s3 * dd3, zero], -1)], -2)
    return np.swapaxes(_l3_real(m.theta3, m.eta3), -1, -2), rd, rdd


def _body_points(cg: float, arms: tuple) -> np.ndarray:
    """Frame coordinates of +-X on x, +-Y on y, +-Z on z about the CG (cg, 0, 0), then the CG."""
    pts = np.zeros((7, 3))
    pts[:, 0] = cg
    for axis, arm in enumerate(arms):
        pts[2 * axis, axis] += arm
        pts[2 * axis + 1, axis] -= arm
    return pts


def _unit_inertia(r: np.ndarray, a: np.ndarray, halve_pairs: bool):
    """Per unit of the link's four design variables: -(a+ + a-) [/2] and -(r x a)/2 summed.

    r, a: (n, 7, 3) for +x, -x, +y, -y, +z, -z and the CG.  The listing does not halve
    the pair's force (D071); it does halve the moments.
    """
    half = 0.5 if halve_pairs else 1.0
    pair_a = a[:, 0:6:2] + a[:, 1:6:2]
    pair_m = np.cross(r[:, 0:6:2], a[:, 0:6:2]) / 2 + np.cross(r[:, 1:6:2], a[:, 1:6:2]) / 2
    force = np.concatenate([-half * pair_a, -a[:, 6:7]], axis=1)
    moment = np.concatenate([-pair_m, -np.cross(r[:, 6:7], a[:, 6:7])], axis=1)
    return force, moment


def _rotate(t: np.ndarray, v: np.ndarray, in_place: bool) -> np.ndarray:
    """t @ v per position, or component by component into itself as loops 50-70 do (D066)."""
    if not in_place:
        return np.einsum("nij,nj->ni", t, v)
    x = np.einsum("nj,nj->n", t[:, 0], v)
    y = t[:, 1, 0] * x + t[:, 1, 1] * v[:, 1] + t[:, 1, 2] * v[:, 2]
    z = t[:, 2, 0] * x + t[:, 2, 1] * y + t[:, 2, 2] * v[:, 2]
    return np.stack([x, y, z], -1)


@dataclass
class Carry:
    """What the listing's static storage carries from one position to the next."""
    fy9: float = 0.0         # fy(9), fz(9): read by qz(9), qy(9) before they are set (D061)
    fz9: float = 0.0
    f3x8: float = 0.0        # f3x(8): never assigned, left by loop 50 (D062)


def unit_loads(m: Motion, c: Constants, quirks: CsspQuirks, carry: Carry):
    """The listing's per-unit loads at every position of one pass; returns (UnitLoads, Carry)."""
    n, q = len(m.theta1), quirks
    ca, sa = np.cos(c.alpha4), np.sin(c.alpha4)
    c1, s1 = np.cos(m.theta1), np.sin(m.theta1)
    c2, s2, ce2, se2 = np.cos(m.theta2), np.sin(m.theta2), np.cos(m.eta2), np.sin(m.eta2)
    c3, s3, ce3, se3 = np.cos(m.theta3), np.sin(m.theta3), np.cos(m.eta3), np.sin(m.eta3)
    s4, dd_s4 = m.s4, m.accels[:, 4]

    # the crank's point masses (KINEMATIC) and the rod's (CORRLS, through the ground side)
    r1, r1d, r1dd = _crank_frames(m.theta1, c.omega)
    pin = np.stack([c.a1 * c1, c.a1 * s1, np.full(n, c.s1)], -1)
    pin_dd = np.stack([-c.a1 * c1 * c.omega ** 2, -c.a1 * s1 * c.omega ** 2, np.zeros(n)], -1)
    local = np.einsum("nij,pj->npi", r1, _body_points(c.cg[0], c.crank_arms))
    crank_r = pin[:, None] + local
    crank_a = pin_dd[:, None] + np.einsum("nij,pj->npi", r1dd, _body_points(c.cg[0], c.crank_arms))
    m4r = np.array([[1.0, 0.0, 0.0], [0.0, ca, -sa], [0.0, sa, ca]])
    tl3r, l3rd, l3rdd = _slider_frames(m, q.eat3)
    rod_rot, rod_rd, rod_rdd = m4r.T @ tl3r, m4r.T @ l3rd, m4r.T @ l3rdd
    joint = np.stack([np.full(n, -c.a4), -s4 * sa, -s4 * ca], -1)
    joint_dd = np.stack([np.zeros(n), -dd_s4 * sa, -dd_s4 * ca], -1)
    omega = rod_rd @ np.swapaxes(rod_rot, -1, -2)
    alpha = rod_rdd @ np.swapaxes(rod_rot, -1, -2) + rod_rd @ np.swapaxes(rod_rd, -1, -2)
    w = np.stack([omega[:, 2, 1], omega[:, 0, 2], omega[:, 1, 0]], -1)[:, None]
    al = np.stack([alpha[:, 2, 1], alpha[:, 0, 2], alpha[:, 1, 0]], -1)[:, None]
    local = np.einsum("nij,pj->npi", rod_rot, _body_points(c.cg[1], c.rod_arms))
    rod_r = joint[:, None] + local
    rod_a = joint_dd[:, None] + np.cross(w, np.cross(w, local)) + np.cross(al, local)

    # per-unit inertia force p and moment q about the origin of {1} (frame {1})
    halve = not q.pair_force_doubled
    p, mom = np.zeros((n, 9, 3)), np.zeros((n, 9, 3))
    p[:, 0:4], mom[:, 0:4] = _unit_inertia(crank_r, crank_a, halve)
    p[:, 4:8], mom[:, 4:8] = _unit_inertia(rod_r, rod_a, halve)
    slider_scale = c.masses[2] if q.slider_mass_twice else 1.0
    p[:, 8] = slider_scale * np.stack([np.zeros(n), dd_s4 * sa, dd_s4 * ca], -1)

    # each link's frame: crank {2} (M1R'), rod {3} from the crank side (M1R L2R)', slider M4R
    l2r = np.stack([np.stack([c2 * ce2, -s2, c2 * se2], -1), np.stack([s2 * ce2, c2, s2 * se2], -1),
                    np.stack([-se2, np.zeros(n), ce2], -1)], -2)
    m1l2r = r1 @ l2r
    frame = np.empty((n, 9, 3, 3))
    frame[:, 0:4], frame[:, 4:8], frame[:, 8] = np.swapaxes(r1, -1, -2)[:, None], \
        np.swapaxes(m1l2r, -1, -2)[:, None], m4r
    f = np.einsum("nkij,nkj->nki", frame, p)
    if q.stale_slider_moment:                       # the previous position's fz(9), fy(9)
        fz9_prev = np.concatenate([[carry.fz9], f[:-1, 8, 2]])
        fy9_prev = np.concatenate([[carry.fy9], f[:-1, 8, 1]])
        mom[:, 8] = np.stack([np.zeros(n), c.a4 * fz9_prev, c.a4 * fy9_prev], -1)
    else:                                           # D3 x p(9)
        mom[:, 8] = np.cross(joint, p[:, 8])
    t_shake = np.einsum("nkij,nkj->nki", frame, mom)
    if q.moments_about_origin:
        t = t_shake
    else:                                           # about each link frame's origin: pin, joint, joint
        origin = np.concatenate([np.repeat(pin[:, None], 4, 1), np.repeat(joint[:, None], 5, 1)], 1)
        t = np.einsum("nkij,nkj->nki", frame, mom - np.cross(origin, p))
    fx, fy, fz = f[..., 0], f[..., 1], f[..., 2]
    tx, ty, tz = t[..., 0], t[..., 1], t[..., 2]
    rod = slice(4, 8)

    # the pin force f3 (eqs. 69b, 69c), the slider force f4, the crank-pin force f2
    f3 = np.zeros((n, 9, 3))
    f3[:, rod, 1] = -(fy[:, rod] + tz[:, rod] / c.a2)
    f3[:, rod, 2] = -(fz[:, rod] + ty[:, rod] / c.a2) if q.f3z_ty_sign else -(fz[:, rod] - ty[:, rod] / c.a2)
    f3[:, 4:7, 0] = (c3[:, None] * f3[:, 4:7, 1]) / s3[:, None]
    if not q.f3x7_twice:
        f3[:, 7, 0] = c3 * f3[:, 7, 1] / s3
    f3[:, 8, 0] = fz[:, 8] / s3
    rotated = list(range(4, 8)) if q.slider_skips_frame_loops else list(range(4, 9))
    if q.f3x7_twice:                                 # f3x(8) is what loop 50 left there
        f3x8, prev = np.empty(n), carry.f3x8
        for j in range(n):
            f3x8[j] = prev
            prev = m1l2r[j, 0] @ np.array([prev, f3[j, 7, 1], f3[j, 7, 2]])
        f3[:, 7, 0], f3x8_out = f3x8, prev
    else:
        f3x8_out = carry.f3x8
    f3x, f3y, f3z = f3[..., 0], f3[..., 1], f3[..., 2]
    f4 = np.zeros((n, 9, 3))
    c3_, s3_, ce3_, se3_ = c3[:, None], s3[:, None], ce3[:, None], se3[:, None]
    f4[:, rod, 0] = (se3_ * f3z[:, rod] - c3_ * ce3_ * f3x[:, rod] - s3_ * ce3_ * f3y[:, rod])
    f4[:, rod, 1] = -(ce3_ * f3z[:, rod] + c3_ * se3_ * f3x[:, rod] + s3_ * se3_ * f3y[:, rod])
    f4[:, 8, 0] = -c3 * ce3 * f3x[:, 8] - fx[:, 8]
    f4y9 = c3 * se3 * f3x[:, 8] + fy[:, 8]
    f4[:, 8, 1] = f4y9 if q.f4y9_sign else -f4y9
    f2 = np.zeros((n, 9, 3))
    c2_, s2_, ce2_, se2_ = c2[:, None], s2[:, None], ce2[:, None], se2[:, None]
    ty_f2y = ty[:, rod].copy()
    if q.ty5_for_ty7:
        ty_f2y[:, 2] = ty[:, 4]
    f2[:, rod, 0] = ((-f3x[:, rod] - fx[:, rod]) * c2_ * ce2_ + (f3y[:, rod] + fy[:, rod]) * s2_
                     - ty[:, rod] * se2_ * c2_ / c.a2)
    f2[:, rod, 1] = ((-f3x[:, rod] - fx[:, rod]) * s2_ * ce2_ - (f3y[:, rod] + fy[:, rod]) * c2_
                     - ty_f2y * se2_ * s2_ / c.a2)
    f2[:, 8, 0] = -f3x[:, 8] * c2 * ce2
    f2[:, 8, 1] = -f3x[:, 8] * s2 * ce2
    axial = np.zeros((n, 9))                         # fz + f3z, absent for the slider's unit
    axial[:, rod] = fz[:, rod] + f3z[:, rod]
    eta = _pin_eta(m, c)
    by_cos = np.abs(np.cos(eta)) > np.abs(np.sin(eta))
    f2z_cos = -(axial + f2[..., 1] * (s2 * se2)[:, None] + f2[..., 0] * (c2 * se2)[:, None]) / ce2_
    f2z_sin = (axial + f2[..., 1] * (s2 * ce2)[:, None] + f2[..., 0] * (c2 * ce2)[:, None]) / se2_
    f2[:, 4:9, 2] = np.where(by_cos[:, None], f2z_cos, f2z_sin)[:, 4:9]

    # loops 50, 60, 70: into frame {1} (f4 with two terms: its local z is taken as 0)
    in_place = q.in_place_frame_change
    tm4r = np.broadcast_to(m4r.T, (n, 3, 3))
    f4[:, :, 2] = 0.0
    for k in rotated:
        f3[:, k] = _rotate(m1l2r, f3[:, k], in_place)
        f2[:, k] = _rotate(r1, f2[:, k], in_place)
        f4[:, k] = _rotate(tm4r, f4[:, k], in_place)

    # the crank bearing: force f1, moments t1x, t1y and the input torque t1z (eq. 62)
    f1 = np.zeros((n, 9, 3))
    c1_, s1_ = c1[:, None], s1[:, None]
    f1[:, 0:4, 0] = -fx[:, 0:4] * c1_ + fy[:, 0:4] * s1_
    f1[:, 0:4, 1] = -(fx[:, 0:4] * s1_ + fy[:, 0:4] * c1_)
    f1[:, 0:4, 2] = -fz[:, 0:4]
    f1[:, 4:9, 0] = -f2[:, 4:9, 0] * c1_ + f2[:, 4:9, 1] * s1_
    f1[:, 4:9, 1] = -(f2[:, 4:9, 0] * s1_ + f2[:, 4:9, 1] * c1_)
    if not q.crank_pin_force_rotated_twice:          # f2 is in frame {1} after loop 60
        f1[:, rotated, 0:2] = -f2[:, rotated, 0:2]
    f1[:, 4:9, 2] = -f2[:, 4:9, 2]
    crank_t = np.zeros((n, 9, 3))
    crank_t[:, 0:4] = t[:, 0:4]
    t1z = f1[..., 1] * c.a1 * c1_ - f1[..., 0] * c.a1 * s1_ - crank_t[..., 2]
    t1 = np.zeros((n, 9, 3))
    if q.crank_bearing_moment_form:
        t1[:, 0:4, 0] = -f1[:, 0:4, 1] * c.s1 - tx[:, 0:4] * c1_ + f1[:, 0:4, 2] * c.a1 + ty[:, 0:4] * s1_
        t1[:, 0:4, 1] = f1[:, 0:4, 0] * c.s1 - f1[:, 0:4, 2] * c.a1 - tx[:, 0:4] * s1_ - ty[:, 0:4] * c1_
        t1[:, 4:9, 0] = t1z[:, 4:9] * c.a1 - f1[:, 4:9, 1] * c.s1
        t1[:, 4:9, 1] = f1[:, 4:9, 0] * c.s1 - f1[:, 4:9, 2] * c.a1
    else:                                            # T1I, T1J of the original link
        t1[..., 0] = -c.s1 * f1[..., 1] - crank_t[..., 0] * c1_ + (c.a1 * f1[..., 2] + crank_t[..., 1]) * s1_
        t1[..., 1] = c.s1 * f1[..., 0] - crank_t[..., 0] * s1_ - (c.a1 * f1[..., 2] + crank_t[..., 1]) * c1_
    shake_f, shake_m = (f, t_shake) if q.shaking_in_link_frames else (p, mom)
    loads = UnitLoads(shaking_force=shake_f, shaking_moment=shake_m, reactions=(f1, f2, f3, f4),
                      moments=(t1, np.zeros_like(t1)), input_torque=t1z)
    return loads, Carry(fy9=float(f[-1, 8, 1]), fz9=float(f[-1, 8, 2]), f3x8=float(f3x8_out))


def _pin_eta(m: Motion, c: Constants) -> np.ndarray:
    """ETA = ATAN2(F2K2, F2K1) from the original rod's forces: it picks the f2z formula."""
    mass = c.masses[1]
    g2, (_, k2y, k2z) = c.cg[1], c.rod_radii_distal
    c2, s2, ce2, se2 = np.cos(m.theta2), np.sin(m.theta2), np.cos(m.eta2), np.sin(m.eta2)
    c3, s3 = np.cos(m.theta3), np.sin(m.theta3)
    d_t3, d_e3, d_s4 = m.rates[:, 1], m.rates[:, 3], m.rates[:, 4]
    dd_t3, dd_e3, dd_s4 = m.accels[:, 1], m.accels[:, 3], m.accels[:, 4]
    v2yp, v2zp, v2xd, v2yd = -d_e3, -d_t3, -d_s4 * s3, d_s4 * c3
    h2xp, h2yp, h2zp = -d_s4 * s3, -g2 * d_t3 + d_s4 * c3, d_e3 * g2
    h2dxp = -dd_s4 * s3 - d_s4 * d_t3 * c3
    h2dyp = -g2 * dd_t3 - d_t3 * d_s4 * s3 + dd_s4 * c3
    h2dyd, h2dzp = -(k2y ** 2) * dd_e3, g2 * dd_e3
    h2dzd = -(k2z ** 2) * dd_t3 + g2 * (dd_s4 * c3 - s3 * d_t3 * d_s4)
    r2p = mass * np.stack([h2dxp - v2zp * h2yp + v2yp * h2zp, h2dyp + v2zp * h2xp, h2dzp - v2yp * h2xp], -1)
    r2d2 = mass * (h2dyd - v2xd * h2zp)
    r2d3 = mass * (h2dzd - v2yd * h2xp + v2xd * h2yp)
    f3j = -(r2p[:, 1] + r2d3 / c.a2)
    f3k = r2d2 / c.a2 - r2p[:, 2]
    f3i = f3j * c3 / s3
    f2j = -(f3j + r2p[:, 1]) * c2 - r2d2 * se2 * s2 / c.a2 - (f3i + r2p[:, 0]) * s2 * ce2
    f2i = (f3j + r2p[:, 1]) * s2 - r2d2 * se2 * c2 / c.a2 - (f3i + r2p[:, 0]) * c2 * ce2
    f2k1 = -(f2i * c2 * se2 + f2j * s2 * se2 + f3k + r2p[:, 2])
    f2k2 = f2i * c2 * ce2 + f2j * s2 * ce2 + f3i + r2p[:, 0]
    return np.arctan2(f2k2, f2k1)
