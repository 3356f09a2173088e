"""The CSSP port (port/cssp*.py): PRINTED against the legacy build, the QP against other
solvers, CORRECTED against independent computations, typed errors on hard cases."""
import numpy as np
import quadprog
import pytest
from scipy.optimize import minimize

from linkrepro.legacy import rahman1996
from linkrepro.errors import AssemblyError, ConvergenceError
from linkrepro.harness.published_tables import PublishedTable
from linkrepro.port.rahman1996.balance import CRANK_DEG, CsspInputs, _listing_motions, balance, hessian_shift, solve_qp
from linkrepro.port.rahman1996.data import QP_EQUALITIES, QP_ROWS, Constants
from linkrepro.port.rahman1996.listing import printed_inverse
from linkrepro.port.rahman1996.mechanics import MassModel
from linkrepro.port.slider_crank.kinematics import Geometry, kinematics
from linkrepro.port.rahman1996.quirks import CSSP_CORRECTED


@pytest.fixture(scope="module")
def printed():
    return balance()


@pytest.fixture(scope="module")
def corrected():
    return balance(quirks=CSSP_CORRECTED)


def rel_to_column(a, b):
    return np.max(np.abs(a - b) / np.abs(b).max(axis=0))


@pytest.mark.parametrize("geometry", [{}, {"a4": 2.0, "alpha4_deg": 260.0}, {"a2": 3.1}, {"rpm": 100.0}])
def test_printed_equals_legacy(geometry):
    """Every quantity of Tables 5.1-5.7, the QP's Hessian, DIAG and answer."""
    port, ref = balance(CsspInputs(**geometry)), rahman1996.cssp(**geometry)
    assert rel_to_column(port["table"], ref["table"]) < 1e-12
    np.testing.assert_allclose(port["inertia"], ref["inertia"], rtol=1e-12)
    np.testing.assert_allclose(port["hessian"], ref["hessian"], rtol=1e-6, atol=1e-6 * np.abs(ref["hessian"]).max())
    np.testing.assert_allclose(port["solution"], ref["solution"], rtol=1e-7)
    assert port["diag"] == pytest.approx(ref["diag"], rel=1e-6)


def test_dual_matrices_compose_screws():
    """Eq. (2.15): the dual part of M1 carries the crank pin (eq. 2.44); a dual product is
    the composition of the two screw displacements (t = tA + RA tB)."""
    from linkrepro.port.rahman1996.listing import _l2, _m1
    from linkrepro.port.dual import skew
    c = Constants.of(CsspInputs(), False)
    m1, l2 = _m1(0.7, c), _l2(1.9, 0.3, c)
    np.testing.assert_allclose(m1.translation(), [2 * np.cos(0.7), 2 * np.sin(0.7), 0.4], rtol=1e-15)
    np.testing.assert_allclose((m1 @ l2).translation(), m1.translation() + m1.real @ l2.translation(), rtol=1e-14)
    np.testing.assert_allclose((m1 @ m1.T).real, np.eye(3), atol=1e-15)
    np.testing.assert_allclose((m1 @ m1.T).dual, 0.0, atol=1e-15)
    np.testing.assert_allclose(skew([1.0, 2.0, 3.0]) @ [4.0, 5.0, 6.0], np.cross([1, 2, 3], [4, 5, 6]))


def test_printed_inverse_is_the_inverse_and_the_legacy_routine():
    rng = np.random.default_rng(4)
    for _ in range(20):
        a = rng.normal(size=(6, 5))
        s = a.T @ a
        b = printed_inverse(s)
        np.testing.assert_allclose(b @ s, np.eye(5), atol=1e-10)
        np.testing.assert_allclose(b, rahman1996.inverse(s), rtol=1e-13, atol=1e-13 * np.abs(b).max())


def test_qp_three_solvers_and_kkt(printed):
    """The thesis QP (Hessian as QPROG gets it): the port's QPROG = our FORTRAN QPROG bit for
    bit; quadprog (another Goldfarb-Idnani code) with the same DIAG agrees to the conditioning;
    the optimal value equals SciPy's (which does not need the shift), and KKT holds."""
    h = printed["hessian"]
    bounds = Constants.of(CsspInputs(), True).qp_bounds
    x, diag = solve_qp(h, bounds=bounds)
    ours = rahman1996.qprog(h, np.zeros(9), QP_ROWS, bounds, QP_EQUALITIES)
    assert diag == ours["diag"] and np.array_equal(x, ours["sol"])
    # H + DIAG*I has condition ~ 1.4e7 / 0.07 = 2e8: agreement to eps * 2e8 ~ 4e-8
    other = quadprog.solve_qp(h + diag * np.eye(9), np.zeros(9), QP_ROWS.T, bounds, QP_EQUALITIES)[0]
    np.testing.assert_allclose(x, other, rtol=1e-7)
    cons = [{"type": "eq", "fun": lambda v, r=r, b=b: r @ v - b} for r, b in zip(QP_ROWS[:3], bounds[:3])]
    cons += [{"type": "ineq", "fun": lambda v, r=r, b=b: r @ v - b} for r, b in zip(QP_ROWS[3:], bounds[3:])]
    scale = 1.0 / np.abs(h).max()
    sp = minimize(lambda v: 0.5 * scale * v @ h @ v, np.full(9, 0.002), jac=lambda v: scale * h @ v,
                  constraints=cons, method="SLSQP", options={"ftol": 1e-16, "maxiter": 500})
    assert 0.5 * x @ h @ x == pytest.approx(0.5 * sp.x @ h @ sp.x, rel=1e-6)
    # KKT of the shifted problem: gradient = A' lambda with lambda >= 0 on the inequalities
    hs = h + diag * np.eye(9)
    active = np.r_[np.arange(3), 3 + np.flatnonzero(np.abs(QP_ROWS[3:] @ x - bounds[3:]) < 1e-12)]
    lam, *_ = np.linalg.lstsq(QP_ROWS[active].T, hs @ x, rcond=None)
    np.testing.assert_allclose(QP_ROWS[active].T @ lam, hs @ x, atol=1e-9 * np.abs(hs @ x).max())
    assert np.all(lam[3:] >= -1e-9 * np.abs(lam).max())
    assert np.all(QP_ROWS[3:] @ x >= bounds[3:] * (1 - 1e-12))          # to round-off of the active set


def test_hessian_shift_is_zero_for_positive_definite_and_minimal_otherwise():
    rng = np.random.default_rng(1)
    a = rng.normal(size=(9, 9))
    assert hessian_shift(a @ a.T + np.eye(9)) == 0.0
    singular = np.diag([4.0, 1.0, 0.0])
    shift = hessian_shift(singular)
    assert 0 < shift <= 1e-7 * 4.0
    assert np.linalg.eigvalsh(singular + shift * np.eye(3)).min() > 0


def test_listing_loop_does_not_close_and_corrected_does(printed):
    """D079: the printed Newton's positions leave the rod 7.7-8.5 in long (a2 = 8)."""
    motion = list(_listing_motions(CsspInputs(), True, True))[1]
    c = Constants.of(CsspInputs(), True)
    th = CRANK_DEG * c.pi / 180
    pin = np.stack([c.a1 * np.cos(th), c.a1 * np.sin(th), np.full(37, c.s1)], -1)
    joint = np.stack([np.full(37, -c.a4), -motion.s4 * np.sin(c.alpha4), -motion.s4 * np.cos(c.alpha4)], -1)
    assert np.abs(np.linalg.norm(joint - pin, axis=1) - c.a2).max() > 0.4
    kin = kinematics(Geometry(), np.radians(CRANK_DEG))
    np.testing.assert_allclose(np.linalg.norm(kin.Q - kin.P, axis=1), 8.0, rtol=1e-13)


def test_corrected_table_5_1_from_equations_2_8_to_2_13(corrected):
    """'before': the principal moments M k^2 from the section 5.2 data, equal to the
    published cells; the four point masses of eq. (2.11)-(2.13) reproduce them (eq. 2.9)."""
    published = PublishedTable.load("rahman1996_table5_1")
    weights, radii = (1.9, 7.6), ((0.2041241, 0.595119, 0.595119), (0.2041241, 2.3139072, 2.3139072))
    direct = np.concatenate([w / 386.4 * np.square(k) for w, k in zip(weights, radii)])
    np.testing.assert_allclose(corrected["inertia"][:, 0], direct, rtol=1e-14)
    # to the printed digit, or (rod I_xx, printed from REAL*4 inputs, D078) to 1e-7 relative
    pub, half = published.values["before"].to_numpy(), published.half_unit["before"].to_numpy()
    assert np.all(np.abs(direct - pub) <= np.maximum(half, 1e-7 * pub))
    x = corrected["solution_table51"]
    model = MassModel.default()
    for link in (0, 1):
        xs, ys, zs = model.distances[link]
        m = x[4 * link:4 * link + 3]
        expected = [m[1] * ys ** 2 + m[2] * zs ** 2, m[0] * xs ** 2 + m[2] * zs ** 2, m[0] * xs ** 2 + m[1] * ys ** 2]
        np.testing.assert_allclose(corrected["inertia"][3 * link:3 * link + 3, 1], expected, rtol=1e-12)
    # the constraints of eq. (4.5) with the links' masses kept (D130) and computed, not the
    # DATA b's rounded literals (D131): active sums, centre masses and x9 kept to the QP's
    # conditioning (eps * cond(H + DIAG*I), about 6e-8, of the largest mass), bounds (1 - w') m held
    m = Constants.of(CsspInputs(), False).point_masses
    shifted = corrected["hessian"] + corrected["diag"] * np.eye(9)
    rtol = np.finfo(float).eps * np.linalg.cond(shifted)
    np.testing.assert_allclose([x[:3].sum(), x[3], x[4:7].sum(), x[7], x[8]],
                               [m[:3].sum(), m[3], m[4:7].sum(), m[7], m[8]], rtol=0, atol=rtol * m.max())
    assert np.all(x[:8] >= 0.95 * m[:8] * (1 - 1e-10))


def _positions(deg):
    """Every half point mass's position (n, 9, 2, 3), from the module's positions only."""
    kin = kinematics(Geometry(), np.radians(deg))
    pts = MassModel.default().local_points()
    crank = kin.P[:, None, None] + np.einsum("nij,khj->nkhi", kin.M1R, pts[:4])
    rod = kin.Q[:, None, None] + np.einsum("nij,khj->nkhi", kin.R2, pts[4:8])
    slider = np.repeat(kin.Q[:, None, None], 2, axis=2)
    return np.concatenate([crank, rod, slider], axis=1)


def test_corrected_shaking_force_and_input_torque_independently(corrected):
    """Through the whole pipeline (balance, CORRECTED): Table 5.3 'before' = |sum m a| and
    Table 5.7 'before' = dKE/dtheta1 (energy method, constant speed, no gravity), with
    accelerations and velocities from 8th-order central differences of positions."""
    omega, h = 3000 * np.pi / 30, 2e-3
    coeff1 = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0.0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])
    coeff2 = np.array([-1 / 560, 8 / 315, -1 / 5, 8 / 5, -205 / 72, 8 / 5, -1 / 5, 8 / 315, -1 / 560])
    offsets = np.arange(-4, 5)
    stack = np.stack([_positions(CRANK_DEG + np.degrees(k * h)) for k in offsets])
    acc = np.einsum("s,snkhc->nkhc", coeff2, stack) * (omega / h) ** 2
    m = Constants.of(CsspInputs(), False).point_masses
    force = np.einsum("k,nkhc->nc", m, acc) / 2.0            # two halves of m/2 each
    np.testing.assert_allclose(corrected["table"][:, 2], np.linalg.norm(force, axis=1), rtol=1e-8)

    def kinetic(deg):
        vel = np.einsum("s,snkhc->nkhc", coeff1, np.stack([_positions(deg + np.degrees(k * h)) for k in offsets]))
        return 0.5 * np.einsum("k,nkh->n", m, ((vel * omega / h) ** 2).sum(-1)) / 2.0

    dke = sum(c * kinetic(CRANK_DEG + np.degrees(k * h)) for c, k in zip(coeff1, offsets)) / h
    np.testing.assert_allclose(corrected["table"][:, 10], dke, atol=1e-7 * np.abs(dke).max())


def test_corrected_has_no_lag_and_row_360_equals_row_0(corrected, printed):
    np.testing.assert_allclose(corrected["table"][36], corrected["table"][0], rtol=1e-12)
    assert np.abs(printed["table"][36] - printed["table"][0]).max() > 1.0     # D061, D062


def test_bad_input_is_a_value_error():
    for bad in ({"a1": -1.0}, {"a2": float("nan")}, {"rpm": 0.0}, {"s1": float("inf")}):
        with pytest.raises(ValueError):
            CsspInputs(**bad)


def test_linkage_that_cannot_close():
    """a2 = 2.5 < a1 + a4: the closed loop names the first crank angle where it cannot
    assemble; the listing's first estimate is not real (the legacy build loops 150 times)."""
    with pytest.raises(AssemblyError) as info:
        balance(CsspInputs(a2=2.5), CSSP_CORRECTED)
    assert info.value.angle_deg == 0.0
    with pytest.raises(ConvergenceError):
        balance(CsspInputs(a2=2.5))
    with pytest.raises(ConvergenceError):
        rahman1996.cssp(a2=2.5)


@pytest.mark.parametrize("geometry", [{"a2": 3.2}, {"a2": 3.05}, {"alpha4_deg": 300.0}])
def test_printed_newton_fails_where_legacy_fails(geometry):
    """Near the edge of assembly the printed Newton wanders for 150 iterations; with the
    listing's INVERSE the port gives up at the same crank angle as the legacy build, while
    the closed loop assembles at every position."""
    angles = []
    for run in (lambda: rahman1996.cssp(**geometry), lambda: balance(CsspInputs(**geometry))):
        with pytest.raises(ConvergenceError) as info:
            run()
        angles.append(info.value.angle_deg)
    assert angles[0] == pytest.approx(angles[1], abs=1e-4)
    balance(CsspInputs(**geometry), CSSP_CORRECTED)
