"""Our QPROG (legacy and port) never returns a point outside its constraints (issue 22; D050).

The fuzz found infeasible problems returned as solved: where a violated constraint's normal
depends on the active ones (z = 0), rounding left ZN = z'n a few ulps above the absolute
test ZN > eps |n|^2, so the method took a full step of length S/ZN ~ 1e14 along noise and
added the constraint (more active constraints than variables), leaving the others violated.
Each finding is here, decided by an independent solver: SciPy's linprog for feasibility
(status 2: infeasible, which must be QPError), quadprog and the KKT conditions for the
optimum.  Then properties over random QPs with more constraints than variables, dependent,
repeated and inconsistent rows, rank-deficient H and families scaled by 1e-150..1e150.

The stated tolerance: a returned x meets every row to ``tolerance(...)`` of its size
|a_i| |x| + |b_i| (an equality on both sides): eps (1e3 + 8 kappa), kappa = tr(H~) tr(H~^-1)
>= cond(H~), H~ = H + DIAG I, the rounding the method commits on an ill-conditioned H~.
Computed here with numpy, not read from the solver.
"""
import numpy as np
import pytest
import quadprog
from hypothesis import event, example, given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from linkrepro.errors import QPError
from linkrepro.legacy import rahman1996
from linkrepro.port.rahman1996 import qprog as port_qprog
from tests.rahman1996.test_differential_qprog import assert_same

ENGINES = pytest.mark.parametrize("qprog", [port_qprog.qprog, rahman1996.qprog], ids=["port", "legacy"])
EPS = np.finfo(float).eps
#: ten times the examples under HYPOTHESIS_PROFILE=thorough
MORE = max(1, settings.default.max_examples // 100)


def rand(shape, seed):
    """The fuzz's reproducible standard-normal array (harness/fuzz.py ``rand``)."""
    return np.random.default_rng(seed).standard_normal(shape)


def spd(n, seed, rank=None):
    """The fuzz's symmetric positive (semi-)definite matrix (harness/fuzz.py ``spd``)."""
    m = rand((n, rank or n), seed)
    return m @ m.T + (0.0 if rank else 0.1) * np.eye(n)


# ------------------------------------------------------------------ independent judgements


def feasible(a, b, neq) -> bool:
    """linprog (HiGHS, feasibility tolerance 1e-10) on the rows scaled to a largest |a_ij| of
    1 and b to a largest |b_i| of 1 (feasibility does not change): False where status 2."""
    size = np.abs(a).max(axis=1)
    size[size == 0] = 1.0
    a, b = a / size[:, None], b / size
    if np.abs(b).max() > 0:
        b = b / np.abs(b).max()
    n = a.shape[1]
    res = linprog(np.zeros(n), A_ub=-a[neq:] if neq < len(b) else None, b_ub=-b[neq:] if neq < len(b) else None,
                  A_eq=a[:neq] if neq else None, b_eq=b[:neq] if neq else None, bounds=[(None, None)] * n,
                  options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10})
    assert res.status in (0, 2), res.message
    return res.status == 0


def shifted(h, diag) -> np.ndarray:
    """H~ = H + DIAG I as QPROG reads H: its lower triangle."""
    return np.tril(h) + np.tril(h, -1).T + diag * np.eye(len(h))


def tolerance(h, diag) -> float:
    """The stated tolerance, relative to each row's size: eps (1e3 + 8 kappa)."""
    ht = shifted(h, diag)
    ht = ht / np.abs(ht).max()                        # kappa is scale-free; no overflow
    return EPS * (1e3 + 8.0 * np.trace(ht) * np.trace(np.linalg.inv(ht)))


def misses(a, b, neq, x) -> np.ndarray:
    """How far x misses each row, relative to |a_i| |x| + |b_i| (<= 0 where it holds)."""
    slack = a @ x - b
    size = np.abs(a) @ np.abs(x) + np.abs(b)
    miss = np.where(np.arange(len(b)) < neq, np.abs(slack), -slack)
    return miss / np.where(size > 0, size, 1.0)


def assert_within_tolerance(h, a, b, neq, res):
    """Every row holds to the stated tolerance (twice it: numpy sums in another order)."""
    worst = misses(a, b, neq, res["sol"]).max()
    assert worst <= 2.0 * tolerance(h, res["diag"]), (worst, tolerance(h, res["diag"]))


def assert_kkt(h, g, a, b, neq, res, tol):
    """Optimal for H~: stationarity H~x + g = A_act' lambda, lambda >= 0 on inequalities, each
    active row on its bound; all to ``tol`` of the terms' sizes."""
    x, act, lam = res["sol"], res["active"], res["multipliers"]
    ht = shifted(h, res["diag"])
    grad = ht @ x + g
    scale = np.abs(ht) @ np.abs(x) + np.abs(g) + np.abs(a[act]).T @ np.abs(lam)
    assert np.all(np.abs(grad - a[act].T @ lam) <= tol * scale.max())
    assert np.all(lam[act >= neq] >= -tol * np.abs(lam).max(initial=1.0))
    assert np.all(np.abs(misses(a, b, len(b), x)[act]) <= tol)


def quadprog_optimum(h, g, a, b, neq, diag) -> float:
    """quadprog's objective value on H~ (scaled to a largest entry of 1: quadprog's
    tolerances are absolute)."""
    ht = shifted(h, diag)
    c = np.abs(ht).max()
    x = quadprog.solve_qp(ht / c, -g / c, a.T.copy(), b, neq)[0]
    return g @ x + x @ ht @ x / 2


# ------------------------------------------------------------------ the fuzz's findings

INFEASIBLE = {
    "4 active in 3 variables": (spd(3, 4283), rand((3,), 1850), rand((4, 3), 6363), rand((4, 1), 6344)[:, 0], 0),
    "constraint 3 violated": (spd(2, 1789), rand((2,), 3782), rand((4, 2), 2564), rand((4, 1), 142)[:, 0], 0),
    "3 equalities, H g * 1e-97": (spd(2, 7836) * 1e-97, rand((2,), 2944) * 1e-97, rand((4, 2), 9543),
                                  rand((4, 1), 6222)[:, 0], 3),
    "3 equalities": (spd(2, 7836), rand((2,), 2944), rand((4, 2), 9543), rand((4, 1), 6222)[:, 0], 3),
}


@ENGINES
@pytest.mark.parametrize("name", INFEASIBLE)
def test_the_fuzzs_infeasible_problems_are_qperror(qprog, name):
    """linprog proves each infeasible; QPROG returned the first three as solved (slacks down to
    -2.04, more active constraints than variables)."""
    h, g, a, b, neq = INFEASIBLE[name]
    assert not feasible(a, b, neq)
    with pytest.raises(QPError, match="inconsistent"):
        qprog(h, g, a, b, neq)


FEASIBLE = {
    "43 variables, rank-21 H": (spd(43, 2015, rank=21), rand((43,), 5977), rand((92, 43), 1448),
                                rand((92, 1), 7473)[:, 0], 0),
    "H = 1e-300, 3 equalities": (np.full((5, 5), 1e-300), rand((5,), 9465) * 1e-133, rand((4, 5), 9631),
                                 rand((4, 1), 8838)[:, 0], 3),
}


@ENGINES
@pytest.mark.parametrize("name", FEASIBLE)
def test_the_fuzzs_small_violations_are_rounding_of_a_singular_h(qprog, name):
    """Feasible (linprog); the answers miss rows by 1.3e-8 and 1.8e-8 of their size, before
    the mend and after.  Both H are singular, so H~ = H + DIAG I has cond 1e8..3e8: the
    misses are the method's rounding, within eps (1e3 + 8 kappa); the answer is optimal for
    H~ (KKT, to that rounding) and its objective is quadprog's (to that rounding)."""
    h, g, a, b, neq = FEASIBLE[name]
    assert feasible(a, b, neq)
    res = qprog(h, g, a, b, neq)
    assert res["diag"] > 0
    assert_within_tolerance(h, a, b, neq, res)
    assert_kkt(h, g, a, b, neq, res, tol=tolerance(h, res["diag"]))
    f = g @ res["sol"] + res["sol"] @ shifted(h, res["diag"]) @ res["sol"] / 2
    assert f == pytest.approx(quadprog_optimum(h, g, a, b, neq, res["diag"]), rel=tolerance(h, res["diag"]))


# ------------------------------------------------------------ scale and redundancy, closed forms


@ENGINES
@pytest.mark.parametrize("c", [1e-20, 1e-150, 1e20, 1e150])
def test_a_bound_binds_at_any_scale_of_x(qprog, c):
    """min |x|^2/2 + c(x1 + x2) s.t. x1 >= c: x = (c, -c), multiplier 2c.  The acceptance
    test was 1e3 eps |a| max(1, |b|), absolute in x: at c = 1e-20 the bound was ignored
    (x = (-c, -c) returned)."""
    res = qprog(np.eye(2), c * np.ones(2), [[1.0, 0.0]], [c])
    np.testing.assert_allclose(res["sol"], [c, -c], rtol=1e-14)
    assert res["active"].tolist() == [0]
    assert res["multipliers"][0] == pytest.approx(2.0 * c, rel=1e-14)


@ENGINES
@pytest.mark.parametrize("c", [1.0, 1e-150, 1e150])
def test_a_constraint_is_dropped_at_any_scale_of_x(qprog, c):
    """min |x - c(-3, 0)|^2/2 s.t. -x1 + x2 >= 0, 2x1 - x2 >= c, x1 + 2x2 >= -c: the dual
    method adds the second row, then the third, then the first, which depends on them and
    needs the third dropped.  Answer c(1, 1) on the first two rows, multipliers 6c and 5c
    (x - c(-3, 0) = 6c(-1, 1) + 5c(2, -1)).  The drop test compared r with eps |u|, u in g's
    units: at c = 1e150 nothing could be dropped ('inconsistent')."""
    res = qprog(np.eye(2), c * np.array([3.0, 0.0]), [[-1.0, 1.0], [2.0, -1.0], [1.0, 2.0]], [0.0, c, -c])
    np.testing.assert_allclose(res["sol"], [c, c], rtol=1e-14)
    assert sorted(res["active"].tolist()) == [0, 1]
    lam = dict(zip(res["active"].tolist(), res["multipliers"]))
    assert lam[0] == pytest.approx(6.0 * c, rel=1e-14) and lam[1] == pytest.approx(5.0 * c, rel=1e-14)


@ENGINES
@pytest.mark.parametrize("rows, neq", [
    ([[0.0, 0.0], [1.0, 1.0]], 1),                    # 0 x = 0, then x1 + x2 = 2
    ([[1.0, 1.0], [1.0, 1.0]], 2),                    # x1 + x2 = 2 twice
    ([[1.0, 1.0], [2.0, 2.0], [1.0, -1.0]], 3),       # a repeated row scaled, then x1 - x2 = 0
])
def test_equalities_that_repeat_or_vanish_are_kept_not_refused(qprog, rows, neq):
    """min |x|^2/2 s.t. the rows (right-hand sides consistent with x1 + x2 = 2, x1 - x2 = 0):
    x = (1, 1).  A dependent equality that already holds is not added (it was 'inconsistent')."""
    rows = np.array(rows)
    b = rows @ np.ones(2)
    res = qprog(np.eye(2), np.zeros(2), rows, b, neq)
    np.testing.assert_allclose(res["sol"], [1.0, 1.0], rtol=1e-15)
    with pytest.raises(QPError, match="inconsistent"):          # 0 x = 1, or two different sums
        qprog(np.eye(2), np.zeros(2), rows, b + np.r_[1.0, np.zeros(len(b) - 1)], neq)


# ------------------------------------------------------------------ properties, random QPs


@st.composite
def problems(draw):
    """A QP of the fuzz's kinds: mostly more constraints than variables; H definite, of any
    rank, all ones or near-singular; rows normal, integer, dependent (later rows combinations
    of earlier ones), one repeated or negated, one zero; b random, feasible at x0 with some
    rows tight there, or with an inconsistent pair; the family scaled: x (g and b), H and g,
    or each row by 10^k, k in -150..150."""
    rng = np.random.default_rng(draw(st.integers(0, 2 ** 32 - 1)))
    n = draw(st.integers(1, 8))
    m = draw(st.integers(n + 1, 3 * n + 3)) if draw(st.booleans()) else draw(st.integers(1, 3 * n + 3))
    h_kind = draw(st.sampled_from(["definite", "rank", "ones", "near singular"]))
    root = rng.standard_normal((n, n))
    if h_kind == "definite":
        h = root @ root.T + 0.1 * np.eye(n)
    elif h_kind == "rank":
        r = draw(st.integers(0, n - 1))
        h = root[:, :r] @ root[:, :r].T
    elif h_kind == "ones":
        h = np.ones((n, n))
    else:
        q = np.linalg.qr(root)[0]
        h = q @ np.diag(10.0 ** -rng.uniform(0.0, 14.0, n)) @ q.T
    a_kind = draw(st.sampled_from(["normal", "integer", "dependent", "repeated", "zero row"]))
    a = rng.integers(-2, 3, (m, n)).astype(float) if a_kind == "integer" else rng.standard_normal((m, n))
    if a_kind == "dependent" and m > 1:
        k = draw(st.integers(1, m - 1))
        a[k:] = rng.standard_normal((m - k, k)) @ a[:k]
    elif a_kind in ("repeated", "zero row") and m > 1:
        i, j = rng.integers(0, m, 2)
        a[j] = 0.0 if a_kind == "zero row" else a[i] * draw(st.sampled_from([1.0, 2.0, -1.0]))
    b_kind = draw(st.sampled_from(["random", "feasible", "inconsistent"]))
    x0 = rng.standard_normal(n)
    b = rng.standard_normal(m) if b_kind == "random" else a @ x0 - rng.choice([0.0, 0.0, 1e-9, 0.5, 1.0], m)
    neq = draw(st.integers(0, min(m, n + 1)))
    if b_kind == "feasible":
        b[:neq] = a[:neq] @ x0
    elif b_kind == "inconsistent":
        i = draw(st.integers(0, m - 1))
        a, b = np.vstack([a, -a[i]]), np.r_[b, -b[i] + draw(st.sampled_from([1e-6, 1.0]))]
    order = rng.permutation(len(b))
    a, b, g = a[order], b[order], rng.standard_normal(n)
    scaling, k = draw(st.sampled_from(["none", "x", "H and g", "rows"])), draw(st.integers(-150, 150))
    if scaling == "x":
        g, b = g * 10.0 ** k, b * 10.0 ** k
    elif scaling == "H and g":
        h, g = h * 10.0 ** k, g * 10.0 ** k
    elif scaling == "rows":
        r = 10.0 ** rng.integers(-150, 151, len(b))
        a, b = a * r[:, None], b * r
    event(f"H {h_kind}, rows {a_kind}, b {b_kind}, scaled {scaling}")
    return h, g, a, b, neq


@settings(max_examples=200 * MORE)
@given(problems())
@example(INFEASIBLE["4 active in 3 variables"])
@example(INFEASIBLE["3 equalities, H g * 1e-97"])
@example(FEASIBLE["H = 1e-300, 3 equalities"])
def test_an_answer_meets_its_constraints_and_infeasible_is_qperror(problem):
    """Legacy and port: the same outcome and bits; an answer meets every row to the stated
    tolerance; where linprog says infeasible, QPError -- or an answer within that tolerance:
    an infeasibility below the rows' rounding at the answer's magnitude (|x| ~ 1e8 where a
    singular H is shifted by DIAG = sqrt(eps) max|H|), which no floating-point test sees."""
    h, g, a, b, neq = problem
    outcome = assert_same(h, g, a, b, neq)
    solvable = feasible(a, b, neq)
    if outcome.startswith("solved"):
        assert_within_tolerance(h, a, b, neq, port_qprog.qprog(h, g, a, b, neq))
        if not solvable:
            event("infeasible below rounding at the answer")
    event(f"linprog {'feasible' if solvable else 'infeasible'}: {outcome if outcome.startswith('solved') else 'QPError'}")


@st.composite
def clearly_infeasible(draw):
    """H definite (cond <= ~100), g ~ N(0, 1), m > n rows of which a Farkas combination
    y >= 0, y'A = 0 has y'b = 1 (normalised rows): no x has every row within 1/sum(y) of its
    bound, so an answer within rounding would need |x| > ~1e10.  Equalities as drawn."""
    rng = np.random.default_rng(draw(st.integers(0, 2 ** 32 - 1)))
    n = draw(st.integers(1, 8))
    m = draw(st.integers(n + 1, 3 * n + 3))
    root = rng.standard_normal((n, n))
    h = root @ root.T / n + np.eye(n)
    a = rng.standard_normal((m, n))
    a /= np.abs(a).max(axis=1)[:, None]
    y = rng.uniform(0.1, 1.0, m)
    a[-1] = -(y[:-1] @ a[:-1]) / y[-1]
    b = rng.standard_normal(m)
    b[-1] = (1.0 - y[:-1] @ b[:-1]) / y[-1]
    order = rng.permutation(m)
    return h, rng.standard_normal(n), a[order], b[order], draw(st.integers(0, n))


@settings(max_examples=100 * MORE)
@given(clearly_infeasible())
def test_a_clearly_infeasible_problem_is_qperror(problem):
    """Where infeasibility cannot hide in rounding, both raise QPError; and linprog agrees."""
    h, g, a, b, neq = problem
    assert not feasible(a, b, neq)
    for qprog in (port_qprog.qprog, rahman1996.qprog):
        with pytest.raises(QPError, match="inconsistent"):
            qprog(h, g, a, b, neq)


@st.composite
def feasible_definite(draw):
    """H definite (cond <= ~100), n + 1 .. 3n + 3 normal rows, feasible at x0 with some rows
    nearly tight there (quadprog itself fails on exactly tight, degenerate ones), fewer than
    n equalities."""
    rng = np.random.default_rng(draw(st.integers(0, 2 ** 32 - 1)))
    n = draw(st.integers(1, 8))
    m = draw(st.integers(n + 1, 3 * n + 3))
    root = rng.standard_normal((n, n))
    h = root @ root.T / n + np.eye(n)
    a, x0, g = rng.standard_normal((m, n)), rng.standard_normal(n), 3.0 * rng.standard_normal(n)
    b = a @ x0 - rng.choice([1e-3, 0.5, 1.0], m)
    neq = draw(st.integers(0, n - 1))
    b[:neq] = a[:neq] @ x0
    return h, g, a, b, neq


@settings(max_examples=100 * MORE)
@given(feasible_definite(), st.sampled_from(["none", "x", "H and g", "rows"]), st.integers(-150, 150))
def test_a_feasible_definite_problem_is_solved_at_quadprogs_optimum(problem, scaling, k):
    """quadprog solves the unscaled, well-conditioned problem; both of ours solve the copy
    scaled by 10^k (x: g and b; H and g; or every row) and return quadprog's x (scaled back,
    to 1e-9 of |x|), meeting every row to the stated tolerance."""
    h, g, a, b, neq = problem
    x_ref = quadprog.solve_qp(h, -g, a.T.copy(), b, neq)[0]
    s = 10.0 ** k
    if scaling == "x":
        scaled, back = (h, g * s, a, b * s, neq), s
    elif scaling == "H and g":
        scaled, back = (h * s, g * s, a, b, neq), 1.0
    elif scaling == "rows":
        r = 10.0 ** np.random.default_rng(k + 150).integers(-150, 151, len(b))
        scaled, back = (h, g, a * r[:, None], b * r, neq), 1.0
    else:
        scaled, back = problem, 1.0
    assert_same(*scaled)
    res = port_qprog.qprog(*scaled)
    assert_within_tolerance(scaled[0], scaled[2], scaled[3], neq, res)
    np.testing.assert_allclose(res["sol"] / back, x_ref, rtol=0, atol=1e-9 * (1.0 + np.abs(x_ref).max()))
