"""QPROG's contract (issue 31; registers D160-D164), legacy and port alike, against
independent computations.

- A positive definite H is solved as given (DIAG = 0, no warning), to its conditioning:
  random problems of condition 1e8..1e14, without constraints, with equalities, and with
  inequalities whose active set is known by construction, against the KKT system of that
  active set solved in 40 digits (mpmath), and, on the issue's reproducers, SciPy's SLSQP.
- Where DIAG is added, a PrecisionWarning names it and ``regularized`` says so.
- An inequality that repeats (or sums) active equality rows is held, not 'inconsistent'.
- Unbounded problems raise QPError 'unbounded'; bounded singular ones (the CSSP's) do not.
- ``condition`` is tr(H) tr(P H P) as numpy computes it.
- The CSSP: the published example gives no warning; a geometry whose masses its REAL*4
  Hessian does not determine warns in legacy and PRINTED alike; speeds below 2**-126 rpm are
  a ValueError naming the speed and the limit, and 2**-126 computes without a RuntimeWarning.
"""
import warnings

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from scipy.optimize import minimize

from linkrepro.errors import PrecisionWarning, QPError
from linkrepro.legacy import rahman1996
from linkrepro.port.rahman1996 import balance as port_cssp
from linkrepro.port.rahman1996 import qprog as port_qprog
from tests.rahman1996.test_differential_qprog import assert_same, unbounded_problems

ENGINES = pytest.mark.parametrize("qprog", [port_qprog.qprog, rahman1996.qprog], ids=["port", "legacy"])
EPS = np.finfo(float).eps
MORE = max(1, settings.default.max_examples // 100)


def symmetric(h) -> np.ndarray:
    """H as QPROG reads it: its lower triangle."""
    return np.tril(h) + np.tril(h, -1).T


def definite(rng, n: int, cond: float) -> np.ndarray:
    """A random positive definite n x n matrix of eigenvalues 1 .. 1/cond."""
    q = np.linalg.qr(rng.standard_normal((n, n)))[0]
    h = q @ np.diag(np.geomspace(1.0, 1.0 / cond, n)) @ q.T
    return (h + h.T) / 2


def kkt(h, g, a, b) -> tuple[np.ndarray, np.ndarray]:
    """min g'x + x'Hx/2 s.t. a x = b, by the KKT system in 40 digits: (x, multipliers)."""
    n, m = len(g), len(b)
    with mpmath.workdps(40):
        k = mpmath.zeros(n + m, n + m)
        rhs = mpmath.zeros(n + m, 1)
        hs = symmetric(h)
        for i in range(n):
            for j in range(n):
                k[i, j] = mpmath.mpf(float(hs[i, j]))
            rhs[i] = -mpmath.mpf(float(g[i]))
        for r in range(m):
            for j in range(n):
                k[n + r, j] = k[j, n + r] = mpmath.mpf(float(a[r, j]))
            rhs[n + r] = mpmath.mpf(float(b[r]))
        z = mpmath.lu_solve(k, rhs)
        return np.array([float(z[i]) for i in range(n)]), np.array([-float(z[n + r]) for r in range(m)])


def quietly(qprog, *args):
    """qprog's result and the messages of the warnings it gave."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = qprog(*args)
    return res, [str(w.message) for w in caught]


# ------------------------------------------------------------- positive definite, as given


def ill_conditioned(seed: int):
    """A problem of condition 1e8..1e14 and its answer (40 digits): no constraints, equalities,
    or inequalities active by construction (g = a' lambda - H x*, lambda in [0.5, 2]) with
    three inactive rows of slack 1 at the answer."""
    rng = np.random.default_rng(seed)
    n, cond, kind = int(rng.integers(2, 7)), 10.0 ** rng.uniform(8.0, 14.0), seed % 3
    h = definite(rng, n, cond)
    if kind == 0:
        g = rng.standard_normal(n)
        return (h, g, None, None, 0), kkt(h, g, np.zeros((0, n)), np.zeros(0))[0], cond
    k = int(rng.integers(1, n))
    a, x_star = rng.standard_normal((k, n)), rng.standard_normal(n)
    b = a @ x_star
    if kind == 1:
        g = rng.standard_normal(n)
        return (h, g, a, b, k), kkt(h, g, a, b)[0], cond
    g = a.T @ rng.uniform(0.5, 2.0, k) - symmetric(h) @ x_star
    x, lam = kkt(h, g, a, b)
    assert np.all(lam > 0.1)
    inactive = rng.standard_normal((3, n))
    return (h, g, np.vstack([a, inactive]), np.r_[b, inactive @ x - 1.0], 0), x, cond


@pytest.mark.parametrize("kind", ["no constraints", "equalities", "inequalities"])
def test_a_definite_h_of_condition_1e8_to_1e14_is_solved_as_given(kind):
    """DIAG = 0 and no warning; the answer within 2 cond eps of the 40-digit KKT answer
    (measured on 1,200 such problems: at most 0.3 cond eps; before the mend DIAG > 0 on all
    and errors up to 100 %); legacy equal to the port bit for bit."""
    offset = ["no constraints", "equalities", "inequalities"].index(kind)
    for seed in range(offset, 90, 3):
        problem, x, cond = ill_conditioned(seed)
        res, caught = quietly(port_qprog.qprog, *problem)
        assert res["diag"] == 0.0 and not res["regularized"] and caught == []
        assert np.abs(res["sol"] - x).max() <= 2.0 * cond * EPS * np.abs(x).max(), (seed, cond)
        assert_same(*problem)


@ENGINES
def test_the_issues_definite_reproducers(qprog):
    """diag(1, 1e-9), g = (0, -1): the minimiser (0, 1e9) (was DIAG = 1.4e-8, sol 6.7e7); and
    one equality with cond(H) = 1e10 (was 3.8 % off): the KKT answer, and SLSQP's."""
    res, caught = quietly(qprog, np.diag([1.0, 1e-9]), [0.0, -1.0])
    assert res["diag"] == 0.0 and caught == []
    np.testing.assert_allclose(res["sol"], [0.0, 1.0 / 1e-9], rtol=1e-7, atol=0)
    rng = np.random.default_rng(3)
    h = definite(rng, 3, 1e10)
    g, a, b = rng.standard_normal(3), rng.standard_normal((1, 3)), np.array([0.7])
    res, caught = quietly(qprog, h, g, a, b, 1)
    x = kkt(h, g, a, b)[0]
    assert res["diag"] == 0.0 and caught == []
    assert np.abs(res["sol"] - x).max() <= 1e10 * EPS * np.abs(x).max()
    slsqp = minimize(lambda y: g @ y + y @ h @ y / 2, np.zeros(3), jac=lambda y: g + h @ y, method="SLSQP",
                     constraints=[{"type": "eq", "fun": lambda y: a @ y - b, "jac": lambda y: a}],
                     options={"ftol": 1e-16, "maxiter": 1000})
    np.testing.assert_allclose(res["sol"], slsqp.x, rtol=1e-6)       # SLSQP stops at ~5e-8


# ------------------------------------------------------------------------ the DIAG warning


@ENGINES
def test_where_diag_is_added_a_precision_warning_says_the_answer_is_the_regularized_ones(qprog):
    """H = diag(1, 0) with x2 <= 5 (bounded, singular): DIAG > 0, ``regularized``, and a
    PrecisionWarning naming DIAG; the answer minimizes the regularized problem: x2 = 5 (the
    bound binds before 1/DIAG)."""
    with pytest.warns(PrecisionWarning, match="DIAG") as caught:
        res = qprog(np.diag([1.0, 0.0]), [0.0, -1.0], [[0.0, -1.0]], [-5.0])
    assert res["regularized"] and res["diag"] > 0 and caught[0].message.relative_error is not None
    np.testing.assert_allclose(res["sol"], [0.0, 5.0], atol=1e-12)


@ENGINES
def test_an_indefinite_hessian_is_said_indefinite_with_no_meaningless_condition(qprog):
    """H = -1e300 I (eigenvalue -1e300, a closed form) with x >= 0: the regularized answer
    is returned with a warning that says H is indefinite, and no 'condition' or error bound
    (the trace product is meaningless there; it printed as -2.5e-323)."""
    with pytest.warns(PrecisionWarning, match=r"H is indefinite \(an eigenvalue -1e\+300\)") as caught:
        res = qprog(-1e300 * np.eye(2), np.zeros(2), np.eye(2), np.zeros(2))
    assert res["regularized"]
    assert caught[0].message.condition is None and caught[0].message.relative_error is None
    assert "condition" not in str(caught[0].message).split("register D160")[1]


@ENGINES
def test_condition_is_the_trace_product_on_the_free_directions(qprog):
    """``condition`` = tr(H) tr(P H P), P = H~^-1 - H~^-1 N (N'H~^-1 N)^-1 N'H~^-1 over the
    active normals N (H~ = H + DIAG I), computed here with numpy; with DIAG = 0 and no active
    row it is tr(H) tr(H^-1)."""
    rng = np.random.default_rng(11)
    for cond, rows in ((1e3, 0), (1e6, 2), (1e9, 3)):
        h = definite(rng, 5, cond)
        g, a = rng.standard_normal(5), rng.standard_normal((rows, 5))
        res = qprog(h, g, a, a @ rng.standard_normal(5), rows)
        hi = np.linalg.inv(symmetric(h))
        n = a[res["active"]].T
        p = hi - hi @ n @ np.linalg.solve(n.T @ hi @ n, n.T @ hi) if rows else hi
        assert res["condition"] == pytest.approx(np.trace(h) * np.trace(p @ symmetric(h) @ p), rel=1e3 * cond * EPS)


# ---------------------------------------------------------------- dependent and repeated rows


def repeated_equality(rng, low: float, high: float):
    """n = 3, cond(H) 10**low..10**high, one equality and up to two inequalities that hold at
    a point x0 (some tight), and the equality again as an inequality (the issue's class)."""
    h, g = definite(rng, 3, 10.0 ** rng.uniform(low, high)), rng.standard_normal(3)
    m = 1 + int(rng.integers(0, 3))
    a, x0 = rng.standard_normal((m, 3)), rng.standard_normal(3)
    b = a @ x0
    b[1:] -= rng.choice([0.0, 0.5], m - 1)
    return h, g, np.vstack([a, a[0]]), np.r_[b, b[0]], 1


@ENGINES
@pytest.mark.parametrize("low, high", [(0, 2), (3, 4), (5, 6)])
def test_an_inequality_repeating_an_active_equality_is_held_not_inconsistent(qprog, low, high):
    """The issue's rates (QPError 'inconsistent': 0 of 800 at cond <= 1e2, 16/400 at 1e3-1e4,
    124/400 at 1e5-1e6; this sample before the mend: 0/800, 15/400, 81/400): now none, and
    the answer is the answer without the repeated row, to the method's rounding GTOL."""
    rng = np.random.default_rng(low)
    for _ in range(100):
        h, g, a, b, neq = repeated_equality(rng, low, high)
        res = qprog(h, g, a, b, neq)
        without = qprog(h, g, a[:-1], b[:-1], neq)
        kappa = np.trace(h) * np.trace(np.linalg.inv(h))
        scale = np.abs(without["sol"]).max()
        assert np.abs(res["sol"] - without["sol"]).max() <= EPS * (1e3 + 8 * kappa) * scale


@ENGINES
def test_an_inequality_summing_two_equalities_is_held(qprog):
    """x1 + x2 = 2, x1 - x2 = 0 and x1 + x2 + (x1 - x2) >= 2 (their sum), H of condition 1e6:
    x = (1, 1), the sum row not in the active set."""
    h = definite(np.random.default_rng(2), 2, 1e6)
    a = np.array([[1.0, 1.0], [1.0, -1.0], [2.0, 0.0]])
    res = qprog(h, np.ones(2), a, a @ np.ones(2), 2)
    np.testing.assert_allclose(res["sol"], [1.0, 1.0], rtol=1e-9)
    assert 2 not in res["active"]


# ------------------------------------------------------------------------------ unbounded


@ENGINES
@pytest.mark.parametrize("args", [
    (np.diag([1.0, 0.0]), [0.0, -1.0]),                                  # min -x2: the issue's
    (np.zeros((2, 2)), [1.0, -1.0], np.eye(2), np.zeros(2)),             # H = 0, x >= 0
    (np.diag([1.0, 0.0, 4.0]), [1.0, -1.0, 0.0], [[1.0, 0.0, 1.0]], [2.0], 1),
    (np.diag([-1.0, 2.0]), [0.0, 0.0], [[1.0, 0.0]], [1.0]),             # negative curvature
], ids=["-x2", "H=0", "equality", "indefinite"])
def test_an_unbounded_problem_is_qperror_unbounded(qprog, args):
    """Each has a feasible ray along which the objective falls without bound (checked here:
    d with H d = 0 and g'd < 0, or d'Hd < 0, rows feasible along it)."""
    with pytest.raises(QPError, match="unbounded"):
        qprog(*args)


@settings(max_examples=40 * MORE)
@given(unbounded_problems())
def test_every_unbounded_problem_of_the_strategy_is_qperror_unbounded(problem):
    """H singular of any rank (0 included), g with a part along a null direction d0, rows that
    stay feasible along d0 (the strategy builds the certificate): both faces say unbounded."""
    assert "unbounded" in assert_same(*problem)


@ENGINES
def test_bounded_singular_problems_are_not_called_unbounded(qprog):
    """The CSSP's own QP (singular by design, D057; g = 0) and min -x2 with x2 <= 1e8: solved,
    DIAG > 0.  (x2 <= 1e8 binds only for the unregularized problem: the regularized answer
    1/DIAG = 6.7e7 lies inside, which the warning says.)"""
    run = rahman1996.cssp()
    from linkrepro.port.rahman1996.data import QP_BOUNDS, QP_EQUALITIES, QP_ROWS
    bounds = np.asarray(QP_BOUNDS, dtype=np.float32).astype(float)
    with pytest.warns(PrecisionWarning, match="DIAG"):
        res = qprog(run["hessian"], np.zeros(9), QP_ROWS, bounds, QP_EQUALITIES)
    assert res["diag"] == run["diag"] > 0
    with pytest.warns(PrecisionWarning, match="DIAG"):
        res = qprog(np.diag([1.0, 0.0]), [0.0, -1.0], [[0.0, -1.0]], [-1e8])
    assert 0 < res["sol"][1] <= 1e8


# -------------------------------------------------------------------------------- the CSSP


def cssp_warnings(call) -> list[str]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call()
    return [str(w.message) for w in caught if issubclass(w.category, PrecisionWarning)]


#: a geometry (in, deg) whose QPs' masses the REAL*4 Hessian does not determine: the crank's
#: centre mass x4 enters H with 1.2e-7 of its largest entry (1 of 2,000 random geometries)
UNDETERMINED = dict(a1=0.9990059473056447, a2=5.343934937309799, a4=1.6129345202917875,
                    alpha4_deg=232.30070150549767, s1=0.12903340083681192)


def test_the_cssp_warns_only_where_single_precision_cannot_carry_the_masses():
    """The published example: no warning in legacy, PRINTED or CORRECTED (its bound is 1e-25:
    the constraints pin all but the crank's split, which its H does not see).  UNDETERMINED:
    the same warning in legacy and PRINTED (the bound 1.36, from QPROG's REAL*4 entry and its
    port), none in CORRECTED (double); and the loss is real: H moved by one REAL*4 unit of its
    largest entry along the weak direction moves the masses by more than 10 %."""
    assert cssp_warnings(rahman1996.cssp) == []
    for quirks in (port_cssp.CSSP_PRINTED, port_cssp.CSSP_CORRECTED):
        assert cssp_warnings(lambda: port_cssp.balance(port_cssp.CsspInputs(), quirks)) == []
    legacy = cssp_warnings(lambda: rahman1996.cssp(**UNDETERMINED))
    assert len(legacy) == 1 and "D161" in legacy[0]
    assert cssp_warnings(lambda: port_cssp.balance(port_cssp.CsspInputs(**UNDETERMINED), port_cssp.CSSP_PRINTED)) == legacy
    assert cssp_warnings(lambda: port_cssp.balance(port_cssp.CsspInputs(**UNDETERMINED), port_cssp.CSSP_CORRECTED)) == []
    h = rahman1996.cssp(**UNDETERMINED)["hessian"]
    from linkrepro.port.rahman1996.data import QP_BOUNDS, QP_EQUALITIES, QP_ROWS
    bounds = np.asarray(QP_BOUNDS, dtype=np.float32).astype(float)
    res = port_qprog.solve(h, np.zeros(9), QP_ROWS, bounds, QP_EQUALITIES)
    hs = symmetric(h)
    hi = np.linalg.inv(hs + res["diag"] * np.eye(9))
    n = QP_ROWS[res["active"]].T
    p = hi - hi @ n @ np.linalg.solve(n.T @ hi @ n, n.T @ hi)
    assert np.trace(hs) * np.trace(p @ hs @ p) * (2.0 ** -24 + res["diag"] / np.trace(hs)) >= 1.0
    weak = np.linalg.eigh(p @ hs @ p)[1][:, -1]
    moved = port_qprog.solve(h + 2.0 ** -24 * np.abs(hs).max() * np.outer(weak, weak), np.zeros(9), QP_ROWS, bounds,
                             QP_EQUALITIES)
    assert np.abs(moved["sol"] - res["sol"]).max() > 0.1 * np.abs(res["sol"]).max()


@pytest.mark.parametrize("rpm", [1e-38, 1e-50, 1e-100])
def test_a_speed_below_2_to_the_minus_126_is_a_value_error_naming_it(rpm):
    """rpm = 1e-50 (legacy, PRINTED) and 1e-100 (CORRECTED) gave QPError 'non-finite Hessian'
    with RuntimeWarnings: REAL*4 holds 0 (or a subnormal) and C1..C3 of eq. (4.2) carry the
    speed's fourth power."""
    calls = [lambda: rahman1996.cssp(rpm=rpm)] + [
        lambda q=q: port_cssp.balance(port_cssp.CsspInputs(rpm=rpm), q)
        for q in (port_cssp.CSSP_PRINTED, port_cssp.CSSP_CORRECTED)]
    for call in calls:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            with pytest.raises(ValueError, match=rf"rpm={rpm!r}.*2\*\*-126"):
                call()


def test_the_slowest_speed_computes_without_a_runtime_warning():
    """At 2**-126 rpm the three engines return the example's masses (the QP does not see the
    speed: H scales with its fourth power, and QPROG with powers of four); no warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        slow = rahman1996.cssp(rpm=2.0 ** -126)
        assert np.array_equal(slow["solution"], rahman1996.cssp()["solution"])
        for quirks in (port_cssp.CSSP_PRINTED, port_cssp.CSSP_CORRECTED):
            slow = port_cssp.balance(port_cssp.CsspInputs(rpm=2.0 ** -126), quirks)
            np.testing.assert_allclose(slow["solution"], port_cssp.balance(port_cssp.CsspInputs(), quirks)["solution"],
                                       rtol=1e-6)


# ------------------------------------------------------------------- the fuzz's QP check


def test_the_fuzzs_qp_check_fails_on_what_it_must_find():
    """harness/scenes/rahman1996/fuzz.py's check: silent on QPROG's answers; a finding for the
    old answer to the unbounded min -x2 (sol (0, 6.7e7), DIAG 1.5e-8), for a point off the
    optimum, for a negative inequality multiplier, for a row missed."""
    from linkrepro.harness.scenes.rahman1996.fuzz import CHECKS
    check = CHECKS["qp"]
    h, g, a, b = np.eye(2), np.array([-1.0, -1.0]), np.array([[1.0, 1.0]]), np.array([3.0])
    good = port_qprog.qprog(h, g, a, b)                                   # x = (1.5, 1.5), lambda = 0.5
    assert check(((h, g), {"a": a, "b": b}), good) is None
    off = dict(good, sol=good["sol"] + [1e-6, -1e-6])
    assert "not optimal" in check(((h, g), {"a": a, "b": b}), off)
    negative = dict(good, multipliers=-good["multipliers"], sol=np.array([0.5, 0.5]))
    assert check(((h, g), {"a": a, "b": b}), negative) is not None
    missed = dict(good, sol=np.array([1.4, 1.5]))
    assert "violated" in check(((h, g), {"a": a, "b": b}), missed)
    old = {"sol": np.array([0.0, 67108864.0]), "diag": 1.4901161193847656e-08, "active": np.zeros(0, int),
           "multipliers": np.zeros(0), "regularized": True, "condition": 1.0}
    assert "unbounded" in check(((np.diag([1.0, 0.0]), np.array([0.0, -1.0])), {}), old)
