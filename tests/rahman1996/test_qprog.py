"""Our stand-in for IMSL QPROG (legacy/src/imsl_qprog.f, Goldfarb-Idnani dual active set).

``qprog(h, g, a, b, neq)`` minimises g'x + x'Hx/2 s.t. a[:neq]x = b[:neq], a[neq:]x >= b[neq:].
Every expected number comes from a closed form, a textbook or another solver (the PyPI
``quadprog`` package, SciPy SLSQP), never from our own output:

* closed forms (unconstrained, one equality, an active and an inactive bound) and three
  published problems: R quadprog's ``solve.QP`` help example and Nocedal & Wright,
  Numerical Optimization (2nd ed.), examples 16.2 and 16.4;
* KKT conditions on random strictly convex problems, and agreement with quadprog / SLSQP;
* DIAG: 0 for positive definite H; > 0 for a singular or slightly indefinite H, with the
  answer optimal for H + diag*I and (for a PSD H) optimal for the original problem;
* failures: inconsistent constraints -> QPError, bad shapes -> ValueError, never a STOP;
* the thesis's balancing problem (rahman1996.cssp(), REAL*4 QPROG): KKT and quadprog's optimum.

quadprog's convention: solve_qp(G, a, C, b, meq) minimises x'Gx/2 - a'x s.t. C'x >= b
(first meq columns equalities), so we call it with a = -g and C = A.T; it needs G > 0.
"""
import re
import subprocess
import sys

import numpy as np
import pytest
import quadprog
from scipy.optimize import minimize

from linkrepro.legacy import rahman1996
from linkrepro.legacy.rahman1996 import QPError, qprog
from tests.patience import CHILD_SECONDS

EPS = np.finfo(float).eps


def objective(h, g, x):
    return g @ x + x @ h @ x / 2


def full_multipliers(res, m):
    """The multipliers scattered onto all m constraints (0 for the inactive ones)."""
    lam = np.zeros(m)
    lam[res["active"]] = res["multipliers"]
    return lam


def quadprog_solve(h, g, a=None, b=None, neq=0):
    if a is None:                                   # quadprog wants C=None, not 0 columns
        return quadprog.solve_qp(h, -g)[:2] + (np.zeros(0),)
    x, f, _, _, lam, _ = quadprog.solve_qp(h, -g, a.T.copy(), b, neq)
    return x, f, lam


# ---------------------------------------------------------------- closed forms


def test_unconstrained_minimum_is_minus_h_inverse_g():
    h = np.array([[4.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 2.0]])
    g = np.array([1.0, -2.0, 3.0])
    res = qprog(h, g)
    np.testing.assert_allclose(res["sol"], -np.linalg.solve(h, g), rtol=1e-13, atol=1e-14)
    assert res["diag"] == 0.0 and res["active"].size == 0


def test_one_equality_matches_the_lagrange_closed_form():
    # H x + g = a*lam, a'x = beta  =>  lam = (beta + a'H^-1 g)/(a'H^-1 a), x = H^-1(a lam - g)
    h = np.array([[2.0, 0.5], [0.5, 1.0]])
    g = np.array([-1.0, 1.0])
    a, beta = np.array([1.0, 2.0]), 3.0
    hi = np.linalg.inv(h)
    lam = (beta + a @ hi @ g) / (a @ hi @ a)
    res = qprog(h, g, a[None, :], [beta], neq=1)
    np.testing.assert_allclose(res["sol"], hi @ (a * lam - g), rtol=1e-13)
    assert res["active"].tolist() == [0]
    assert res["multipliers"][0] == pytest.approx(lam, rel=1e-13)


def test_active_and_inactive_bounds():
    # H = diag(2, 4), g = (-2, 4): unconstrained minimum (1, -1).  x1 >= 2 binds (x = (2, -1),
    # multiplier H11*2 + g1 = 2); x2 >= -3 does not.
    h, g = np.diag([2.0, 4.0]), np.array([-2.0, 4.0])
    res = qprog(h, g, np.eye(2), [2.0, -3.0])
    np.testing.assert_allclose(res["sol"], [2.0, -1.0], rtol=1e-14)
    assert res["active"].tolist() == [0]
    assert res["multipliers"] == pytest.approx([2.0])


def test_r_solve_qp_help_example():
    # R quadprog ?solve.QP: Dmat = I3, dvec = (0,5,0), Amat columns (-4,-3,0), (2,1,0),
    # (0,-2,1), bvec = (-8,2,0).  Published: solution 0.4761905 1.0476190 2.0952381,
    # value -2.380952, Lagrangian 0 0.2380952 2.0952381, i.e. exactly (10,22,44)/21,
    # -50/21 and (0, 5, 44)/21.
    a = np.array([[-4.0, -3.0, 0.0], [2.0, 1.0, 0.0], [0.0, -2.0, 1.0]])
    g = -np.array([0.0, 5.0, 0.0])
    res = qprog(np.eye(3), g, a, [-8.0, 2.0, 0.0])
    np.testing.assert_allclose(res["sol"], np.array([10, 22, 44]) / 21, rtol=1e-14)
    assert objective(np.eye(3), g, res["sol"]) == pytest.approx(-50 / 21, rel=1e-14)
    np.testing.assert_allclose(full_multipliers(res, 3), np.array([0, 5, 44]) / 21, atol=1e-14)


def test_nocedal_wright_example_16_2_equality_qp():
    # N&W example 16.2: min 3x1^2+2x1x2+x1x3+2.5x2^2+2x2x3+2x3^2-8x1-3x2-3x3
    # s.t. x1 + x3 = 3, x2 + x3 = 0.  Published: x* = (2, -1, 1), lambda* = (3, -2).
    h = np.array([[6.0, 2.0, 1.0], [2.0, 5.0, 2.0], [1.0, 2.0, 4.0]])
    res = qprog(h, [-8.0, -3.0, -3.0], [[1.0, 0.0, 1.0], [0.0, 1.0, 1.0]], [3.0, 0.0], neq=2)
    np.testing.assert_allclose(res["sol"], [2.0, -1.0, 1.0], rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(full_multipliers(res, 2), [3.0, -2.0], rtol=1e-13)


def test_nocedal_wright_example_16_4_active_set_qp():
    # N&W example 16.4: min (x1-1)^2 + (x2-2.5)^2 s.t. x1-2x2+2 >= 0, -x1-2x2+6 >= 0,
    # -x1+2x2+2 >= 0, x1 >= 0, x2 >= 0.  Published: x* = (1.4, 1.7), only the first
    # constraint active, lambda1 = 0.8.  Objective = x'(2I)x/2 + (-2,-5)'x + const.
    a = np.array([[1.0, -2.0], [-1.0, -2.0], [-1.0, 2.0], [1.0, 0.0], [0.0, 1.0]])
    res = qprog(2 * np.eye(2), [-2.0, -5.0], a, [-2.0, -6.0, -2.0, 0.0, 0.0])
    np.testing.assert_allclose(res["sol"], [1.4, 1.7], rtol=1e-14)
    assert res["active"].tolist() == [0]
    assert res["multipliers"] == pytest.approx([0.8], rel=1e-13)


# --------------------------------------------------- random convex problems: KKT, other solvers


def random_problem(seed, n=6, neq=2, nin=8):
    """H = MM' + nI (eigenvalues >= n, cond(H) ~ 10), constraints feasible at a random x0
    with slack in (0, 1) on every inequality, so several of them bind at the optimum."""
    rng = np.random.default_rng(seed)
    m = rng.standard_normal((n, n))
    h = m @ m.T + n * np.eye(n)
    g = 5 * rng.standard_normal(n)
    a = rng.standard_normal((neq + nin, n))
    b = a @ rng.standard_normal(n)
    b[neq:] -= rng.uniform(0, 1, nin)
    return h, g, a, b, neq


SEEDS = range(8)


@pytest.mark.parametrize("seed", SEEDS)
def test_kkt_conditions_on_random_convex_problems(seed):
    """Tolerance 1e-11 relative to the size of the terms (|H||x|+|g|, |A||x|+|b|): the
    problems are well conditioned (cond(H) ~ 10), so the rounding is ~1e-14; a wrong active
    set or a wrong multiplier shows up at O(1)."""
    h, g, a, b, neq = random_problem(seed)
    res = qprog(h, g, a, b, neq)
    x, lam = res["sol"], full_multipliers(res, len(b))
    assert res["diag"] == 0.0
    scale_grad = np.abs(h) @ np.abs(x) + np.abs(g)
    scale_con = np.abs(a) @ np.abs(x) + np.abs(b)
    tol = 1e-11
    residual = a @ x - b
    assert np.all(np.abs(h @ x + g - a.T @ lam) <= tol * scale_grad)          # stationarity
    assert np.all(np.abs(residual[:neq]) <= tol * scale_con[:neq])            # equalities
    assert np.all(residual[neq:] >= -tol * scale_con[neq:])                  # inequalities
    assert np.all(lam[neq:] >= 0)                                            # dual feasibility
    act = res["active"]                                      # complementarity: only tight
    assert np.all(np.abs(residual[act]) <= tol * scale_con[act])     # constraints carry lambda
    assert len(set(res["active"].tolist())) == res["active"].size            # no duplicates
    assert set(range(neq)) <= set(res["active"].tolist())                     # equalities active
    assert np.count_nonzero(lam[neq:] > 1e-8) >= 1                           # a bound binds


@pytest.mark.parametrize("seed", SEEDS)
def test_random_problems_agree_with_quadprog(seed):
    """Both are exact dual active-set solvers in double on a strictly convex problem with
    cond(H) ~ 10: solutions agree to ~1e-15 (measured); 1e-10 leaves room for the
    conditioning of the active constraints yet is far below any active-set error."""
    h, g, a, b, neq = random_problem(seed)
    res = qprog(h, g, a, b, neq)
    x_qp, f_qp, lam_qp = quadprog_solve(h, g, a, b, neq)
    np.testing.assert_allclose(res["sol"], x_qp, rtol=0, atol=1e-10)
    assert objective(h, g, res["sol"]) == pytest.approx(f_qp, rel=1e-12, abs=1e-12)
    np.testing.assert_allclose(full_multipliers(res, len(b)), lam_qp, rtol=0,
                               atol=1e-10 * max(1.0, np.abs(lam_qp).max()))


@pytest.mark.parametrize("seed", SEEDS)
def test_random_problems_agree_with_scipy_slsqp(seed):
    """SLSQP with ftol=1e-12 stops when f changes by < 1e-12; with the smallest eigenvalue
    of H >= 6, f - f* ~ lambda_min |dx|^2 / 2 gives |dx| ~ sqrt(2e-12/6) ~ 6e-7 (measured
    worst 1e-7), hence 1e-5 on x and 1e-9 on f. Ours, the exact minimiser, may not be
    worse than SLSQP's point by more than that."""
    h, g, a, b, neq = random_problem(seed)
    res = qprog(h, g, a, b, neq)
    cons = [{"type": "eq", "fun": lambda z: a[:neq] @ z - b[:neq], "jac": lambda z: a[:neq]},
            {"type": "ineq", "fun": lambda z: a[neq:] @ z - b[neq:], "jac": lambda z: a[neq:]}]
    sp = minimize(lambda z: objective(h, g, z), np.zeros(len(g)), jac=lambda z: h @ z + g,
                  method="SLSQP", constraints=cons, options={"ftol": 1e-12, "maxiter": 500})
    assert sp.success, sp.message
    np.testing.assert_allclose(res["sol"], sp.x, rtol=0, atol=1e-5)
    f_ours, f_sp = objective(h, g, res["sol"]), objective(h, g, sp.x)
    assert abs(f_ours - f_sp) <= 1e-9 * (1 + abs(f_sp))
    assert f_ours <= f_sp + 1e-9 * (1 + abs(f_sp))


# ------------------------------------------------------------------------- DIAG


def test_diag_is_zero_for_positive_definite_h():
    h, g, a, b, neq = random_problem(0)
    assert np.linalg.eigvalsh(h).min() > 0
    assert qprog(h, g, a, b, neq)["diag"] == 0.0
    assert qprog(np.diag([1e-3, 1.0, 1e3]), np.ones(3))["diag"] == 0.0


def kkt_residual(h, g, a, b, res):
    lam = full_multipliers(res, len(b))
    return h @ res["sol"] + g - a.T @ lam, lam


def test_rank_one_h_gets_a_diag_and_is_optimal_for_h_plus_diag():
    # H = vv' (rank 1, eigenvalues 14, 0, 0); x on the simplex: sum x = 1, x >= 0.
    # Closed form for the original problem: on the simplex f = (v'x)^2/2 + g'x is
    # minimised at the vertex (0, 1, 0), f* = 2 - 1 = 1.
    v = np.array([1.0, 2.0, 3.0])
    h, g = np.outer(v, v), np.array([1.0, -1.0, 0.5])
    a = np.vstack([np.ones(3), np.eye(3)])
    b = np.array([1.0, 0.0, 0.0, 0.0])
    res = qprog(h, g, a, b, neq=1)
    d = res["diag"]
    assert 0 < d <= 1e-6 * np.abs(h).max()
    hd = h + d * np.eye(3)
    # optimal for H + diag*I: KKT, and quadprog on the same (now definite) matrix.  cond(hd)
    # ~ 14/d ~ 1e8, so rounding is ~1e8*eps relative: 1e-6 is the justified tolerance.
    r, lam = kkt_residual(hd, g, a, b, res)
    assert np.abs(r).max() <= 1e-6 and np.all(lam[1:] >= 0)
    x_qp, _, lam_qp = quadprog_solve(hd, g, a, b, 1)
    np.testing.assert_allclose(res["sol"], x_qp, atol=1e-6)
    # and near-optimal for H itself: f_H(x) <= f* + d*|x*|^2/2 (x* = (0,1,0))
    assert 1.0 - 1e-12 <= objective(h, g, res["sol"]) <= 1.0 + d / 2 + 1e-12


def test_slightly_indefinite_h_gets_a_diag_that_makes_it_definite():
    rng = np.random.default_rng(0)
    q, _ = np.linalg.qr(rng.standard_normal((4, 4)))
    h = q @ np.diag([3.0, 2.0, 1.0, -1e-9]) @ q.T
    g, a, b = np.array([1.0, 2.0, 3.0, 4.0]), np.eye(4), -np.ones(4)
    res = qprog(h, g, a, b)
    d = res["diag"]
    assert 1e-9 < d <= 1e-6                       # at least -lambda_min, and small
    hd = h + d * np.eye(4)
    assert np.linalg.eigvalsh(hd).min() > 0
    r, lam = kkt_residual(hd, g, a, b, res)
    assert np.abs(r).max() <= 1e-7 and np.all(lam >= 0)   # cond(hd) ~ 3/6e-8 ~ 5e7
    np.testing.assert_allclose(res["sol"], quadprog_solve(hd, g, a, b, 0)[0], atol=1e-7)


def test_psd_h_with_a_free_direction_reaches_the_true_minimum():
    # H = vv' + e3e3', v = (1,2,0): null direction (2,-1,0), g = v is orthogonal to it, so
    # the minimisers form a line (v'x = -1, x3 = 0) and f* = -1/2.  For any t > 0,
    # f_H(x_{H+tI}) - f* <= t |x*|^2/2: quadprog on H + 1e-10 I gives the reference.
    v = np.array([1.0, 2.0, 0.0])
    h, g = np.outer(v, v) + np.diag([0.0, 0.0, 1.0]), v.copy()
    res = qprog(h, g)
    assert res["diag"] > 0
    _, f_qp, _ = quadprog_solve(h + 1e-10 * np.eye(3), g)
    assert f_qp == pytest.approx(-0.5, abs=1e-10)
    assert objective(h, g, res["sol"]) == pytest.approx(f_qp, abs=res["diag"] + 1e-12)


FREE_DIAGONAL_CHILD = """
import numpy as np
from linkrepro.legacy.rahman1996 import qprog
res = qprog(np.diag([1.0, 0.0]), [-1.0, 0.0])   # f = x1^2/2 - x1: f* = -1/2, x2 free
print(repr(float(res["sol"] @ np.diag([1.0, 0.0]) @ res["sol"] / 2 - res["sol"][0])))
"""


def test_psd_h_with_a_zero_row_terminates_and_reaches_the_true_minimum():
    """H = diag(1, 0), g = (-1, 0): the simplest PSD H with a free direction.  Run in a
    child process with a timeout so that a non-terminating DIAG search cannot hang the
    suite.  Expected f* = -1/2 (x1 = 1, x2 arbitrary), as quadprog on H + tiny*I gives."""
    _, f_qp, _ = quadprog_solve(np.diag([1.0, 1e-10]), np.array([-1.0, 0.0]))
    try:
        out = subprocess.run([sys.executable, "-c", FREE_DIAGONAL_CHILD], capture_output=True,
                             text=True, timeout=CHILD_SECONDS)       # run() kills the child on timeout
    except subprocess.TimeoutExpired:
        out = None
    assert out is not None, f"qprog(diag(1, 0), (-1, 0)) did not return within {CHILD_SECONDS:g} s"
    assert out.returncode == 0, out.stderr
    assert float(out.stdout) == pytest.approx(f_qp, abs=1e-7)


# ---------------------------------------------------------------------- failures


def test_inconsistent_constraints_raise_qperror_and_the_next_call_works():
    with pytest.raises(QPError):
        qprog(np.eye(1), [0.0], [[1.0], [-1.0]], [1.0, 0.0])          # x1 >= 1 and -x1 >= 0
    with pytest.raises(QPError):
        qprog(np.eye(2), [0.0, 0.0], [[1.0, 0.0], [1.0, 0.0]], [1.0, 2.0], neq=2)
    res = qprog(np.eye(2), [0.0, 0.0], [[1.0, 0.0]], [1.0])               # status reset
    np.testing.assert_allclose(res["sol"], [1.0, 0.0])


# bad arguments: tests/test_differential_qprog.py::test_bad_arguments_raise_value_error_in_both


def test_a_failing_qprog_does_not_stop_the_interpreter():
    code = ("import numpy as np\nfrom linkrepro.legacy.rahman1996 import qprog, QPError\n"
            "try:\n    qprog(np.eye(1), [0.0], [[1.0], [-1.0]], [1.0, 0.0])\n"
            "except QPError:\n    print('caught')\nprint('alive')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=CHILD_SECONDS)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["caught", "alive"]


# ------------------------------------------------- the thesis's balancing problem (CSSP)

#: Rows of aa (DATA, legacy/src/rahman1996_cssp_main.f, ~line 128; column-major 11 x 9):
#: x1+x2+x3 = b1, x5+x6+x7 = b2, x9 = b3, x1..x4 >= b4..b7, x5..x8 >= b8..b11.
CSSP_A = np.zeros((11, 9))
CSSP_A[0, [0, 1, 2]] = CSSP_A[1, [4, 5, 6]] = CSSP_A[2, 8] = 1.0
CSSP_A[3:7, 0:4] = CSSP_A[7:11, 4:8] = np.eye(4)
#: DATA b (REAL*4 as QPROG gets it)
CSSP_B = np.array([0.003688, 0.01475, 0.01553] + [0.001168] * 4 + [0.00467] * 4,
                  dtype=np.float32).astype(float)
CSSP_NEQ = 3


def test_cssp_constraint_rows_match_the_data_statements(root):
    text = (root / "legacy/src/rahman1996_cssp_main.f").read_text()

    def data(name):
        body = re.search(rf"^ +data {name}/(.*?)/", text, re.S | re.M | re.I).group(1)
        body = re.sub(r"\n +1 ", "", body)                    # continuation markers
        vals = []
        for item in body.split(","):
            count, _, value = item.strip().rpartition("*")
            vals += [float(value)] * int(count or 1)
        return np.array(vals)

    np.testing.assert_array_equal(data("aa").reshape(9, 11).T, CSSP_A)
    np.testing.assert_array_equal(data("b").astype(np.float32), CSSP_B)


@pytest.fixture(scope="module")
def cssp_run():
    return rahman1996.cssp()


def test_cssp_solution_satisfies_kkt_in_single_precision(cssp_run):
    """The QP: min x'Hx/2 (H = cssp()['hessian'], REAL*4, PSD of rank 7, so QPROG adds
    diag) s.t. CSSP_A x (=, >=) CSSP_B.  The solution is REAL*4 (relative rounding 6e-8)
    and so are H and b: tolerances are 1e-6 relative (about 16 single-precision ulps)."""
    h, x, d = cssp_run["hessian"], cssp_run["solution"], cssp_run["diag"]
    assert 0 < d <= 1e-6 * np.abs(h).max()
    slack = CSSP_A @ x - CSSP_B
    tol = 1e-6 * CSSP_B
    assert np.all(np.abs(slack[:CSSP_NEQ]) <= tol[:CSSP_NEQ])
    assert np.all(slack[CSSP_NEQ:] >= -tol[CSSP_NEQ:])
    active = np.r_[np.arange(CSSP_NEQ), CSSP_NEQ + np.flatnonzero(slack[CSSP_NEQ:] <= tol[CSSP_NEQ:])]
    grad = (h + d * np.eye(9)) @ x
    lam_act, *_ = np.linalg.lstsq(CSSP_A[active].T, grad, rcond=None)
    lam = np.zeros(11)
    lam[active] = lam_act
    assert np.abs(grad - CSSP_A.T @ lam).max() <= 1e-6 * np.abs(grad).max()   # stationarity
    assert np.all(lam[CSSP_NEQ:] >= 0)                                          # dual feasibility
    assert np.all(np.abs(lam * slack) <= 1e-6 * np.abs(lam) * CSSP_B)           # complementarity
    assert np.all(lam[active[CSSP_NEQ:]] > 0)             # the binding bounds really bind


def test_cssp_solution_has_quadprogs_optimal_value(cssp_run):
    """quadprog on H + 1e-10*max|H|*I (it needs a definite matrix): that shift moves f* by
    at most 1e-10*max|H|*|x|^2/2 ~ 1e-7 relative.  Our x is REAL*4: |Hx|*|dx| with
    |dx| ~ 6e-8|x| bounds the change in f by ~3e-7 relative, hence rel=1e-6."""
    h, x = cssp_run["hessian"], cssp_run["solution"]
    x_qp, _, _ = quadprog_solve(h + 1e-10 * np.abs(h).max() * np.eye(9), np.zeros(9),
                                CSSP_A, CSSP_B, CSSP_NEQ)
    assert x @ h @ x / 2 == pytest.approx(x_qp @ h @ x_qp / 2, rel=1e-6)
