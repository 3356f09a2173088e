"""The corrected CSSP mechanics (port/rahman1996.mechanics.py) against independent computations.

The reference here rebuilds the positions from scratch (another closure formula, the rod
frame from cross products, the point masses from the thesis's numbers) and differentiates
them by 8th-order central differences in the crank angle; nothing is copied from the module.
"""
import numpy as np
import pytest

from linkrepro.errors import AssemblyError, SingularPositionError
from linkrepro.port.rahman1996.mechanics import MassModel, kinetic_energy, unit_loads
from linkrepro.port.slider_crank.kinematics import Geometry, kinematics

DEG = np.r_[np.arange(0.0, 360.0, 5.0), 13.7, 101.3, 222.2, 333.3]
TH = np.radians(DEG)
BODY = np.array([0, 0, 0, 0, 1, 1, 1, 1, 2])
C1 = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0.0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])
C2 = np.array([-1 / 560, 8 / 315, -1 / 5, 8 / 5, -205 / 72, 8 / 5, -1 / 5, 8 / 315, -1 / 560])
H = 4e-3  # rad


def rel(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def thesis_points():
    """(9, 2, 3) halves of each point mass in its link frame, from section 2.2 and the listing."""
    pts = np.zeros((9, 2, 3))
    for link, (w, cg, k) in enumerate([(1.9, -1.0, (0.2041241, 0.595119, 0.595119)),
                                       (7.6, -4.0, (0.2041241, 2.3139072, 2.3139072))]):
        ix, iy, iz = (w / 386.4) * np.square(k)
        m_i = w / 386.4 / 4
        dist = np.sqrt([(iy + iz - ix) / (2 * m_i), (ix + iz - iy) / (2 * m_i), (ix + iy - iz) / (2 * m_i)])
        for j in range(3):
            pts[4 * link + j, :, 0] = cg
            pts[4 * link + j, 0, j] += dist[j]
            pts[4 * link + j, 1, j] -= dist[j]
        pts[4 * link + 3, :, 0] = cg
    return pts


def reference(g, th):
    """Independent positions: dict with P, Q, s4, R2, Rc and pts (n, 9, 2, 3)."""
    al = np.radians(g.alpha4_deg)
    k4, o4 = np.array([0.0, np.sin(al), np.cos(al)]), np.array([-g.a4, 0.0, 0.0])
    P = np.stack([g.a1 * np.cos(th), g.a1 * np.sin(th), np.full_like(th, g.s1)], axis=-1)
    w = o4 - P
    wk = w @ k4
    s4 = wk + np.sqrt(wk ** 2 - (w * w).sum(-1) + g.a2 ** 2)   # Q = o4 - s4 k4, farther root
    Q = o4 - s4[:, None] * k4
    u = (Q - P) / g.a2
    y = np.cross([0.0, 0.0, 1.0], u)
    y /= np.linalg.norm(y, axis=-1, keepdims=True)
    R2 = np.stack([u, y, np.cross(u, y)], axis=-1)
    c, s, z, o = np.cos(th), np.sin(th), np.zeros_like(th), np.ones_like(th)
    Rc = np.stack([np.stack([c, -s, z], -1), np.stack([s, c, z], -1), np.stack([z, z, o], -1)], -2)
    loc = thesis_points()
    pts = np.concatenate([P[:, None, None] + np.einsum("nij,khj->nkhi", Rc, loc[:4]),
                          Q[:, None, None] + np.einsum("nij,khj->nkhi", R2, loc[4:8]),
                          np.broadcast_to(Q[:, None, None], (th.size, 1, 2, 3))], axis=1)
    return dict(P=P, Q=Q, s4=s4, R2=R2, u=u, y=y, pts=pts)


def fd(f, th, h=H):
    """Value, d/dtheta, d2/dtheta2 of f by 8th-order central differences."""
    vals = np.stack([f(th + j * h) for j in range(-4, 5)])
    return vals[4], np.tensordot(C1, vals, 1) / h, np.tensordot(C2, vals, 1) / h ** 2


def fd_ref(g, th, key):
    """Reference position, velocity, acceleration (time derivatives at constant omega)."""
    r, d1, d2 = fd(lambda t: reference(g, t)[key], th)
    return r, g.omega * d1, g.omega ** 2 * d2


def masses():
    rng = np.random.default_rng(1996)
    m = MassModel.default().m
    return [m, m * rng.uniform(0.2, 2.0, 9)]


def test_mass_model_is_dynamically_equivalent():
    """Eqs. 2.8-2.12: the four point masses keep the mass, the CG and the inertia tensor."""
    model = MassModel.default()
    loc, m = model.local_points(), model.m
    np.testing.assert_allclose(m, np.repeat(np.array([1.9, 7.6, 6.0]) / 386.4 / [4, 4, 1], [4, 4, 1]))
    for link, (w, cg, k) in enumerate([(1.9, -1.0, (0.2041241, 0.595119, 0.595119)),
                                       (7.6, -4.0, (0.2041241, 2.3139072, 2.3139072))]):
        pts, mh = loc[4 * link:4 * link + 4].reshape(-1, 3), np.repeat(m[4 * link:4 * link + 4] / 2, 2)
        assert mh.sum() == pytest.approx(w / 386.4, rel=1e-14)
        np.testing.assert_allclose(mh @ pts / mh.sum(), [cg, 0, 0], atol=1e-14)
        d = pts - [cg, 0, 0]
        inertia = np.einsum("p,pi,pj->ij", mh, d, d)
        inertia = np.trace(inertia) * np.eye(3) - inertia
        np.testing.assert_allclose(inertia, np.diag(w / 386.4 * np.square(k)), rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(loc, thesis_points(), rtol=1e-14)


def test_closure_and_rod_frame():
    g = Geometry()
    kin = kinematics(g, TH)
    assert np.max(np.abs(np.linalg.norm(kin.Q - kin.P, axis=-1) - g.a2)) < 1e-12
    np.testing.assert_allclose(kin.R2[:, :, 0], kin.u, atol=1e-14)
    np.testing.assert_allclose(kin.R2 @ np.swapaxes(kin.R2, 1, 2), np.broadcast_to(np.eye(3), kin.R2.shape),
                               atol=1e-14)
    np.testing.assert_allclose(np.linalg.det(kin.R2), 1.0, atol=1e-14)
    # the listing's first estimate sqrt(a2^2 - (a1 + a4)^2) lies nearer this root than the other
    s4_0 = kinematics(g, 0.0).s4[0]
    est = np.sqrt(g.a2 ** 2 - (g.a1 + g.a4) ** 2)
    other = -2 * g.s1 * np.cos(g.alpha4) - s4_0           # roots sum to -2b
    assert abs(s4_0 - est) < abs(other - est)


@pytest.mark.parametrize("g", [Geometry(), Geometry(a1=1.5, a2=5.0, a4=-0.7, alpha4_deg=215.0, s1=-0.9)])
def test_positions_and_exact_derivatives(g):
    """Positions equal the independent ones; v, a equal their finite differences."""
    kin, loads = kinematics(g, TH), unit_loads(g, MassModel.default(), TH)
    ref = reference(g, TH)
    for key in ("P", "Q", "s4"):
        r, v, a = fd_ref(g, TH, key)
        np.testing.assert_allclose(getattr(kin, key), r, atol=1e-12)
        assert rel(getattr(kin, key + "d"), v) < 1e-9, key
        assert rel(getattr(kin, key + "dd"), a) < 1e-7, key
    r, v, a = fd_ref(g, TH, "pts")
    np.testing.assert_allclose(loads.r_half, ref["pts"], atol=1e-12)
    assert rel(loads.v_half, v) < 1e-9
    assert rel(loads.a_half, a) < 1e-7
    # rod angular velocity and acceleration from dR/dt R^T and d2R/dt2 R^T - W^2
    R, Rd, Rdd = fd_ref(g, TH, "R2")
    W = Rd @ np.swapaxes(R, 1, 2)
    Wd = Rdd @ np.swapaxes(R, 1, 2) - W @ W
    assert rel(kin.w2, np.stack([W[:, 2, 1], W[:, 0, 2], W[:, 1, 0]], -1)) < 1e-9
    assert rel(kin.alpha2, np.stack([Wd[:, 2, 1], Wd[:, 0, 2], Wd[:, 1, 0]], -1)) < 1e-7
    for key in ("theta2", "eta2"):   # joint angles: differences of the wrapped angle
        _, d1, d2 = fd(lambda t: np.angle(np.exp(1j * (getattr(kinematics(g, t), key)
                                                       - getattr(kin, key)))), TH)
        assert rel(getattr(kin, key + "d"), g.omega * d1) < 1e-9, key
        assert rel(getattr(kin, key + "dd"), g.omega ** 2 * d2) < 1e-7, key


@pytest.mark.parametrize("x", masses(), ids=["default", "random"])
def test_shaking_force_and_moment(x):
    g = Geometry()
    loads = unit_loads(g, MassModel.default(), TH)
    r, _, a = fd_ref(g, TH, "pts")
    mh = np.repeat(x / 2, 2).reshape(9, 2, 1)
    assert rel(loads.total("force", x), (mh * a).sum(axis=(1, 2))) < 1e-7
    assert rel(loads.total("moment", x), (mh * np.cross(r, a)).sum(axis=(1, 2))) < 1e-7


@pytest.mark.parametrize("x", masses(), ids=["default", "random"])
def test_input_torque_is_the_rate_of_kinetic_energy(x):
    """No gravity, constant speed, workless joints: T0 = dKE/dtheta1 and T0 omega = sum m a.v."""
    g, model = Geometry(), MassModel.default()
    loads = unit_loads(g, model, TH)
    mh = np.repeat(x / 2, 2).reshape(9, 2)

    def ke(t):
        v = g.omega * fd(lambda s: reference(g, s)["pts"], t)[1]
        return 0.5 * np.einsum("kh,nkh->n", mh, (v * v).sum(-1))

    ke0, dke, _ = fd(ke, TH, 1e-2)
    t0 = loads.total("T0", x)
    assert rel(t0, dke) < 1e-7
    assert rel(kinetic_energy(g, model, TH, x), ke0) < 1e-10
    power = np.einsum("kh,nkh->n", mh, (loads.a_half * loads.v_half).sum(-1))
    assert rel(t0 * g.omega, power) < 1e-11


@pytest.mark.parametrize("x", masses(), ids=["default", "random"])
def test_joint_reactions_balance_every_body(x):
    """Newton-Euler of each link and of the whole mechanism with finite-difference inertia."""
    g = Geometry()
    L = unit_loads(g, MassModel.default(), TH)
    F1, M1, F2, M2, F3, F4, M4 = (L.total(k, x) for k in ("F1", "M1", "F2", "M2", "F3", "F4", "M4"))
    ref = reference(g, TH)
    r, _, a = fd_ref(g, TH, "pts")
    ma = np.repeat(x / 2, 2).reshape(9, 2, 1) * a
    f = [ma[:, BODY == b].sum(axis=(1, 2)) for b in range(3)]
    m = [np.cross(r, ma)[:, BODY == b].sum(axis=(1, 2)) for b in range(3)]
    P, Q = ref["P"], ref["Q"]
    scale_f, scale_m = np.abs(f[2]).max(), np.abs(m[2]).max()
    checks = [(F1 - F2, f[0], scale_f), (M1 - np.cross(P, F2) - M2, m[0], scale_m),
              (F2 - F3, f[1], scale_f), (np.cross(P, F2) + M2 - np.cross(Q, F3), m[1], scale_m),
              (F3 + F4, f[2], scale_f), (np.cross(Q, F3 + F4) + M4, m[2], scale_m),
              (F1 + F4, f[0] + f[1] + f[2], scale_f),
              (M1 + np.cross(Q, F4) + M4, m[0] + m[1] + m[2], scale_m)]
    for i, (lhs, rhs, scale) in enumerate(checks):
        assert np.max(np.abs(lhs - rhs)) < 1e-7 * scale, i
    # joint types: the prismatic force is normal to k4, the Hooke moment to both joint axes
    assert np.max(np.abs(F4 @ g.k4)) < 1e-10 * scale_f
    assert np.max(np.abs(M2[:, 2])) < 1e-10 * scale_m
    assert np.max(np.abs((M2 * ref["y"]).sum(-1))) < 1e-10 * scale_m
    assert np.max(np.abs(M4)) < 1e-10 * scale_m   # the slider is a point mass
    np.testing.assert_array_equal(L.T0, L.M1[..., 2])


def test_planar_case_is_the_inline_slider_crank():
    """alpha4 = 270, s1 = a4 = 0: the slider runs along y1; closed-form planar slider crank."""
    g = Geometry(a4=0.0, alpha4_deg=270.0, s1=0.0)
    L = unit_loads(g, MassModel.default(), TH)
    a1, a2, w = g.a1, g.a2, g.omega
    psi = TH - np.pi / 2             # crank angle measured from the slider axis
    S = a2 ** 2 - a1 ** 2 * np.sin(psi) ** 2
    x = a1 * np.cos(psi) + np.sqrt(S)
    xdd = w ** 2 * (-a1 * np.cos(psi) - a1 ** 2 * np.cos(2 * psi) / np.sqrt(S)
                    - a1 ** 4 * np.sin(2 * psi) ** 2 / (4 * S ** 1.5))
    np.testing.assert_allclose(L.kin.s4, x, rtol=1e-13)
    assert rel(L.kin.s4dd, xdd) < 1e-12
    assert rel(L.force[:, 8], np.stack([0 * x, xdd, 0 * x], -1)) < 1e-12
    # a mass distribution symmetric about the plane z1 = 0 loads no joint out of it
    sf = max(np.abs(L.F1[..., :2]).max(), np.abs(L.F3[..., :2]).max())
    sm = np.abs(L.M1[..., 2]).max()
    for name in ("F1", "F2", "F3", "F4"):
        assert np.abs(getattr(L, name)[..., 2]).max() < 1e-12 * sf, name
    for name in ("M1", "M4"):
        assert np.abs(getattr(L, name)[..., :2]).max() < 1e-12 * sm, name
    assert np.abs(L.M2).max() < 1e-12 * sm
    assert sf > 1.0 and sm > 1.0


def test_cannot_close_raises_assembly_error_at_the_first_bad_angle():
    g = Geometry(a2=2.5)
    deg = np.r_[90.0, 180.0, 135.0, 20.0, 0.0]
    th = np.radians(deg)
    P = np.stack([g.a1 * np.cos(th), g.a1 * np.sin(th), np.full_like(th, g.s1)], -1)
    w = P - [-g.a4, 0.0, 0.0]
    dist = np.linalg.norm(w - np.outer(w @ g.k4, g.k4), axis=-1)   # P to the slider line
    assert (dist <= g.a2).any() and (dist > g.a2).any()
    with pytest.raises(AssemblyError) as err:
        unit_loads(g, MassModel.default(), th)
    assert err.value.angle_deg == pytest.approx(deg[np.argmax(dist > g.a2)])
    kinematics(g, th[dist <= g.a2])   # the angles that close do not raise


@pytest.mark.parametrize("g, deg", [
    (Geometry(a1=2.0, a2=3.0, a4=1.0, alpha4_deg=270.0, s1=0.0), 0.0),    # rod normal to the slider
    (Geometry(a1=2.0, a2=8.0, a4=2.0, alpha4_deg=0.0, s1=0.4), 180.0)])   # rod along z1: Hooke lock
def test_singular_positions_raise(g, deg):
    with pytest.raises(SingularPositionError) as err:
        unit_loads(g, MassModel.default(), np.radians([60.0, deg]))
    assert err.value.angle_deg == pytest.approx(deg)
