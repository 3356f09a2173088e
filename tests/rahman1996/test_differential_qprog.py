"""Differential tests: the port of our QPROG (port/qprog.py) against the legacy build's DQPROG.

The property: on the same double inputs, the same outcome (both solve, or both raise the same
error type, and for QPError the same reason), the same warnings, and where both solve,
``sol``, ``diag``, the active set, the multipliers and ``condition`` equal bit for bit
(compared as IEEE bit patterns, so -0.0 is not 0.0).  No tolerance is needed: the port does
DQPROG's operations in DQPROG's order.

Domain: n = 1..7 variables; H positive definite (condition up to 1e3, and 1e8..1e14),
positive semidefinite of any rank (zero included), near-singular (eigenvalues down to 1e-14
of the largest), slightly and strongly indefinite, not symmetric (both read only the lower
triangle), diagonal, and symmetric with entries of 1e-6..1e8 of either sign; at scales
1e-6..1e8; g of any scale or zero; constraints: none, feasible with some bounds tight,
redundant (repeated, scaled and summed rows), an inequality repeating (or summing)
equalities, integer rows with exactly dependent sets, infeasible (a contradicting pair),
random; m up to 3n+2 (more than n), neq from 0 to m (neq = n included); and unbounded
problems (H singular, g along its null space, rows that do not stop it).  And the CSSP's own balancing problem: its
constraint rows QP_ROWS, QP_EQUALITIES, the DATA b bounds as QPROG gets them (REAL*4), and the
Hessians rahman1996.cssp computes over the issue's geometry domain, also with g and the bounds
perturbed (which makes some problems infeasible).

Two faults of our FORTRAN stand-in found here are mended in both (register D050): the DIAG
rule stalled where raising DIAG by the shortfall left it unchanged in floating point (H =
diag(-1.3, 5.3): statement 100 repeated forever), and at 60 variables the active set's
work arrays overflowed.  Both now return the same answer there; the tests run legacy in a
child process, so that a regression fails instead of hanging or crashing the test run.
"""
import subprocess
import sys
import warnings

import numpy as np
import pytest
import quadprog
from hypothesis import assume, event, example, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from linkrepro.legacy import rahman1996
from linkrepro.errors import LinkageError, QPError
from linkrepro.port.rahman1996 import balance as port_cssp
from linkrepro.port.rahman1996 import qprog as port_qprog
from linkrepro.port.rahman1996.data import QP_BOUNDS, QP_EQUALITIES, QP_ROWS
from tests.patience import CHILD_SECONDS

#: DATA b as the listing's QPROG receives it (REAL*4)
CSSP_BOUNDS = np.asarray(QP_BOUNDS, dtype=np.float32).astype(np.float64)
#: the geometry on which quadprog declares the CSSP's QP inconsistent (issue 11)
HARD_GEOMETRY = {"a1": 3.157, "a2": 8.373, "a4": 2.506, "alpha4_deg": 248.267, "s1": 0.001}
#: ten times the examples under HYPOTHESIS_PROFILE=thorough (make fuzz; max_examples 1000 there, 100 by default)
MORE = max(1, settings.default.max_examples // 100)


def bits(x) -> np.ndarray:
    return np.asarray(x, dtype=np.float64).view(np.uint64)


def outcome(fn, *args):
    """(the result dict, or (error type, message) for the errors QPROG raises; the messages
    of the warnings it gave)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = fn(*args)
        except (QPError, ValueError) as exc:
            result = type(exc).__name__, str(exc)
    return result, [str(w.message) for w in caught]


RESULT_KEYS = {"sol", "diag", "active", "multipliers", "regularized", "condition"}


def assert_same(h, g, a=None, b=None, neq=0) -> str:
    """The property on one problem; returns the outcome's name (for hypothesis' statistics)."""
    ours, our_warnings = outcome(port_qprog.qprog, h, g, a, b, neq)
    theirs, their_warnings = outcome(rahman1996.qprog, h, g, a, b, neq)
    assert our_warnings == their_warnings
    if isinstance(ours, tuple) or isinstance(theirs, tuple):
        assert isinstance(ours, tuple) and isinstance(theirs, tuple), (ours, theirs)
        assert ours[0] == theirs[0], (ours, theirs)
        if ours[0] == "QPError":                      # inconsistent, unbounded, the iteration limit
            assert ours[1] == theirs[1]
        return ours[1]
    assert set(ours) == set(theirs) == RESULT_KEYS
    assert np.array_equal(bits(ours["sol"]), bits(theirs["sol"])), (ours["sol"], theirs["sol"])
    assert np.array_equal(bits(ours["diag"]), bits(theirs["diag"])), (ours["diag"], theirs["diag"])
    assert ours["active"].dtype == theirs["active"].dtype
    assert np.array_equal(ours["active"], theirs["active"]), (ours["active"], theirs["active"])
    assert np.array_equal(bits(ours["multipliers"]), bits(theirs["multipliers"]))
    assert np.array_equal(bits(ours["condition"]), bits(theirs["condition"]))
    assert ours["regularized"] == theirs["regularized"] == (ours["diag"] > 0) == bool(our_warnings and
                                                                                       "DIAG" in our_warnings[0])
    assert port_qprog.hessian_shift(h, g) == ours["diag"]       # one DIAG rule, used by the CSSP
    return "solved, diag > 0" if ours["diag"] > 0 else "solved"


# ------------------------------------------------------------------------------- strategies

UNIT = st.floats(-1.0, 1.0, allow_subnormal=False)
SCALE = st.integers(-6, 8).map(lambda e: 10.0 ** e)


@st.composite
def hessians(draw, n):
    kind = draw(st.sampled_from(["definite", "ill-conditioned", "semidefinite", "near singular",
                                 "slightly indefinite", "indefinite", "not symmetric", "diagonal", "entries"]))
    scale = draw(SCALE)
    m = draw(arrays(np.float64, (n, n), elements=UNIT))
    q = np.linalg.qr(m + 2.0 * np.eye(n))[0]                    # orthogonal
    if kind == "definite":
        h = m @ m.T + draw(st.floats(1e-3, 1.0)) * np.eye(n)
    elif kind == "ill-conditioned":                 # positive definite, condition 1e8..1e14 (D160)
        h = q @ np.diag(np.geomspace(1.0, 10.0 ** -draw(st.floats(8.0, 14.0)), n)) @ q.T
    elif kind == "semidefinite":
        rank = draw(st.integers(0, n - 1))
        h = m[:, :rank] @ m[:, :rank].T
    elif kind == "near singular":
        exponents = draw(arrays(np.float64, n, elements=st.floats(0.0, 14.0)))
        h = q @ np.diag(10.0 ** -exponents) @ q.T
    elif kind == "slightly indefinite":
        eig = np.abs(draw(arrays(np.float64, n, elements=UNIT))) + 0.1
        eig[0] = -10.0 ** -draw(st.floats(6.0, 12.0))
        h = q @ np.diag(eig) @ q.T
    elif kind == "indefinite":
        h = m + m.T
    elif kind == "not symmetric":
        h = m @ m.T + np.eye(n) + np.triu(draw(arrays(np.float64, (n, n), elements=UNIT)), 1)
    elif kind == "diagonal":
        h = np.diag(draw(arrays(np.float64, n, elements=st.sampled_from([0.0, 1e-12, 1.0, 3.0, -1.3, -2.9]))))
    else:
        sign = draw(arrays(np.float64, (n, n), elements=st.sampled_from([-1.0, 1.0])))
        mag = draw(arrays(np.float64, (n, n), elements=st.floats(1e-6, 1e8)))
        h = np.tril(sign * mag) + np.tril(sign * mag, -1).T
        scale = 1.0
    event(f"H {kind}")
    return h * scale


@st.composite
def constraint_sets(draw, n):
    kind = draw(st.sampled_from(["none", "feasible", "redundant", "repeats an equality", "integer", "infeasible",
                                 "random"]))
    event(f"constraints {kind}")
    if kind == "none":
        return None, None, 0
    m = draw(st.integers(1, 3 * n + 2))
    if kind == "integer":
        a = draw(arrays(np.float64, (m, n), elements=st.integers(-2, 2).map(float)))
        x0 = draw(arrays(np.float64, n, elements=st.integers(-3, 3).map(float)))
    else:
        a = draw(arrays(np.float64, (m, n), elements=UNIT)) * draw(SCALE)
        x0 = draw(arrays(np.float64, n, elements=UNIT)) * draw(SCALE)
    slack = draw(arrays(np.float64, m, elements=st.sampled_from([0.0, 0.0, 1e-9, 0.5, 1.0])))
    b = a @ x0 - slack
    if kind == "random":
        b = draw(arrays(np.float64, m, elements=UNIT)) * draw(SCALE)
    if kind == "redundant":                   # a row repeated, scaled, and two rows summed
        i, j = draw(st.integers(0, m - 1)), draw(st.integers(0, m - 1))
        c = draw(st.sampled_from([1.0, 2.0, 0.5]))
        a = np.vstack([a, a[i], c * a[i], a[i] + a[j]])
        b = np.concatenate([b, [b[i], c * b[i], b[i] + b[j]]])
    if kind == "repeats an equality":         # D162: inequalities repeating and summing equalities
        neq = draw(st.integers(1, min(m, n)))
        b[:neq] = a[:neq] @ x0
        return (np.vstack([a, a[0], a[0] + a[neq - 1]]),
                np.concatenate([b, [b[0], b[0] + b[neq - 1]]]), neq)
    if kind == "infeasible":                  # a_i x >= b_i and -a_i x >= -b_i + delta
        i = draw(st.integers(0, m - 1))
        delta = draw(st.sampled_from([1e-6, 1.0])) * max(1.0, abs(b[i]))
        a = np.vstack([a, -a[i]])
        b = np.concatenate([b, [-b[i] + delta]])
    order = draw(st.permutations(range(len(b))))
    a, b = a[list(order)], b[list(order)]
    neq = draw(st.one_of(st.integers(0, len(b)), st.just(min(n, len(b)))))
    if kind in ("feasible", "redundant", "integer"):
        b[:neq] = a[:neq] @ x0                # equalities hold at x0
    return a, b, neq


@st.composite
def problems(draw):
    n = draw(st.integers(1, 7))
    h = draw(hessians(n))
    g = draw(st.sampled_from([0.0, 1.0])) * draw(arrays(np.float64, n, elements=UNIT)) * draw(SCALE)
    a, b, neq = draw(constraint_sets(n))
    return h, g, a, b, neq


@st.composite
def unbounded_problems(draw):
    """Unbounded below (D163), from a seeded generator: H positive semidefinite of rank r < n
    (0: H = 0; eigenvalues 0.1..1 on its range), g with a part -d0 along a null direction d0,
    feasible rows that do not stop d0 (inequalities turned so that a_i d0 >= 0, equalities
    with d0 projected out of them), the family scaled by 1e-6..1e8."""
    rng = np.random.default_rng(draw(st.integers(0, 2 ** 32 - 1)))
    n = int(rng.integers(1, 7))
    r = int(rng.integers(0, n))
    q = np.linalg.qr(rng.standard_normal((n, n)))[0]
    h = q[:, :r] @ np.diag(rng.uniform(0.1, 1.0, r)) @ q[:, :r].T
    d0 = q[:, r:] @ rng.uniform(0.5, 1.0, n - r)
    g = -d0 + q[:, :r] @ rng.standard_normal(r)
    rows = int(rng.integers(0, 2 * n + 1))
    a = rng.standard_normal((rows, n))
    neq = int(rng.integers(0, min(rows, n - 1) + 1))
    a[:neq] -= np.outer(a[:neq] @ d0, d0) / (d0 @ d0)
    a[neq:] *= np.where(a[neq:] @ d0 < 0, -1.0, 1.0)[:, None]
    b = a @ rng.standard_normal(n) - np.r_[np.zeros(neq), rng.choice([0.0, 0.5], rows - neq)]
    scale = draw(SCALE)
    event("unbounded")
    return h * scale, g * scale, (a if rows else None), (b if rows else None), neq


# ------------------------------------------------------------------- the property, general QPs


@settings(max_examples=150 * MORE)
@given(st.one_of(problems(), problems(), problems(), unbounded_problems()))
@example((np.eye(2), np.zeros(2), np.array([[1.0, 0.0], [-1.0, 0.0]]), np.array([1.0, 0.0]), 0))   # inconsistent
@example((np.diag([4.0, 1.0, 0.0]), np.ones(3), None, None, 0))                                 # singular: diag
@example((np.diag([1.0, 0.0]), np.array([-1.0, 0.0]), None, None, 0))                           # a zero row
@example((np.eye(2), np.zeros(2), np.array([[1.0, 1.0], [1.0, 1.0]]), np.array([1.0, 2.0]), 2))  # equalities
def test_port_equals_legacy_on_random_qps(problem):
    event(assert_same(*problem))


@settings(max_examples=40 * MORE)
@given(n=st.integers(1, 7), extra=st.integers(0, 7), data=st.data())
def test_port_equals_legacy_with_neq_equal_n(n, extra, data):
    """n equalities in n variables (neq = n: at most one feasible point) and ``extra``
    inequalities, some violated there."""
    h = data.draw(hessians(n))
    a = data.draw(arrays(np.float64, (n + extra, n), elements=UNIT))
    x0 = data.draw(arrays(np.float64, n, elements=UNIT))
    b = a @ x0 - np.r_[np.zeros(n), data.draw(arrays(np.float64, extra, elements=st.floats(-1.0, 1.0)))]
    event(assert_same(h, data.draw(arrays(np.float64, n, elements=UNIT)), a, b, n))


# ------------------------------------------------------------ the property, the CSSP's own QP


@st.composite
def cssp_geometries(draw):
    """The issue's domain (in, deg), as the measurement draws it."""
    return {"a1": draw(st.floats(0.5, 4.0)), "a2": draw(st.floats(3.0, 12.0)),
            "a4": draw(st.floats(-3.0, 3.0)), "alpha4_deg": draw(st.floats(0.0, 360.0)),
            "s1": draw(st.floats(-1.0, 1.0))}


def cssp_hessian(geometry) -> np.ndarray:
    try:
        return rahman1996.cssp(**geometry)["hessian"]
    except (LinkageError, QPError):
        assume(False)


@settings(max_examples=50 * MORE)
@given(geometry=cssp_geometries(), variant=st.sampled_from(["as printed", "g", "bounds", "both"]),
       data=st.data())
@example(geometry=HARD_GEOMETRY, variant="as printed", data=None)
@example(geometry={}, variant="as printed", data=None)
def test_port_equals_legacy_on_the_cssp_qp(geometry, variant, data):
    """The balancing QP with the Hessians rahman1996.cssp computes (REAL*4, max|H| ~ 1e4..1e8,
    singular: D057), with g and the bounds perturbed in some examples."""
    h = cssp_hessian(geometry)
    g, bounds = np.zeros(9), CSSP_BOUNDS.copy()
    if variant in ("g", "both"):
        size = np.abs(h).max() * data.draw(st.sampled_from([1e-8, 1e-4]))
        g = data.draw(arrays(np.float64, 9, elements=UNIT)) * size
    if variant in ("bounds", "both"):
        bounds = bounds * data.draw(arrays(np.float64, 11, elements=st.floats(0.5, 2.0)))
    event(f"CSSP QP {variant}: {assert_same(h, g, QP_ROWS, bounds, QP_EQUALITIES)}")


# ------------------------------------------------------------ solve_qp where quadprog failed


def test_solve_qp_solves_where_quadprog_failed_and_equals_legacy():
    """The CSSP's QP on a geometry where the quadprog-based port raised QPError: H of
    max|H| ~ 4e7 (norm ~1e8), DIAG ~ 0.58.  The port's solve_qp now solves it, equal to the
    legacy QPROG bit for bit; the answer satisfies the KKT conditions of
    min x'(H + DIAG I)x/2 computed here; and the port's whole run (balance, which raised
    QPError there) gives rahman1996.cssp's Hessian and Table 5.1 masses (REAL*4) exactly."""
    run = rahman1996.cssp(**HARD_GEOMETRY)
    h = run["hessian"]
    assert 1e7 < np.abs(h).max() < 1e8
    x, diag = port_cssp.solve_qp(h, bounds=CSSP_BOUNDS)
    with pytest.raises(ValueError, match="inconsistent"):
        quadprog.solve_qp(h + diag * np.eye(9), np.zeros(9), QP_ROWS.T.copy(), CSSP_BOUNDS, QP_EQUALITIES)
    ref = rahman1996.qprog(h, np.zeros(9), QP_ROWS, CSSP_BOUNDS, QP_EQUALITIES)
    assert np.array_equal(bits(x), bits(ref["sol"])) and diag == ref["diag"] > 0
    # KKT of min x'(H + DIAG I)x/2, computed here: feasibility, stationarity (H + DIAG I)x =
    # A_act' lambda, lambda >= 0 on the bounds.  Rounding is bounded by eps * cond(H + DIAG I)
    # ~ 2e-16 * 2e8 = 4e-8 relative (measured: 1.3e-12 on the bounds, 6e-16 on stationarity);
    # 1e-9 is far below what a wrong active set or a wrong sign would give (O(1)).
    tol = 1e-9
    slack = QP_ROWS @ x - CSSP_BOUNDS
    assert np.all(np.abs(slack[:QP_EQUALITIES]) <= tol * CSSP_BOUNDS[:QP_EQUALITIES])
    assert np.all(slack[QP_EQUALITIES:] >= -tol * CSSP_BOUNDS[QP_EQUALITIES:])
    act = np.r_[np.arange(QP_EQUALITIES),
                QP_EQUALITIES + np.flatnonzero(slack[QP_EQUALITIES:] <= tol * CSSP_BOUNDS[QP_EQUALITIES:])]
    grad = (h + diag * np.eye(9)) @ x
    lam, *_ = np.linalg.lstsq(QP_ROWS[act].T, grad, rcond=None)
    assert np.abs(QP_ROWS[act].T @ lam - grad).max() <= tol * np.abs(grad).max()
    assert np.all(lam[QP_EQUALITIES:] > 0)
    port = port_cssp.balance(port_cssp.CsspInputs(**HARD_GEOMETRY), port_cssp.CSSP_PRINTED)
    assert np.array_equal(port["hessian"], h)
    assert np.array_equal(np.float32(port["solution_table51"]), np.float32(run["solution"]))


# --------------------------------------------------------------- where the two cannot agree


def in_child(code: str, timeout: float = CHILD_SECONDS) -> str:
    """Run ``code`` in a child interpreter; its stdout.  A hang or a crash fails the test."""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=timeout)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_where_the_diag_rule_stalled_both_return_alike():
    """H = diag(-1.3, 5.3): DIAG = fl(1.3 + TINY) rounds down, so the first pivot stays below
    TINY and DIAG + (TINY - PIVOT) == DIAG: statement 100 repeated forever.  Now DIAG takes the
    next number up, in the FORTRAN and the port; with -2.9 (rounding up) nothing changed.
    (Without constraints the problem is unbounded below, D163; with x1 bounded it is not.)"""
    code = ("import numpy as np; from linkrepro.legacy import rahman1996\n"
            "print(rahman1996.qprog(np.diag([-1.3, 5.3]), np.ones(2), [[1.0, 0.0], [-1.0, 0.0]], [-1.0, -1.0])['diag'])")
    assert float(in_child(code)) > 1.3
    for h11 in (-1.3, -2.9):
        assert "unbounded" in assert_same(np.diag([h11, 5.3]), np.ones(2))
        assert_same(np.diag([h11, 5.3]), np.ones(2), [[1.0, 0.0], [-1.0, 0.0]], [-1.0, -1.0])


def test_at_60_variables_both_report_the_inconsistency():
    """n = 60 (MAXV), 194 random inequalities, infeasible (SciPy's HiGHS says so).  The dual
    method adds a 61st, numerically dependent constraint before QPGAUS finds M singular; the
    FORTRAN's GN(60,60), M(60,60) and RHS(60) could not hold it (SIGSEGV in the fuzz run) and
    now can.  Both report the inconsistency."""
    from scipy.optimize import linprog
    rng = np.random.default_rng(1)
    n, m = 60, 194
    root = rng.standard_normal((n, n))
    h, g = root @ root.T + n * np.eye(n), rng.standard_normal(n)
    a, b = rng.standard_normal((m, n)), rng.standard_normal(m) + 3.0
    assert linprog(np.zeros(n), A_ub=-a, b_ub=-b, bounds=[(None, None)] * n).status == 2   # infeasible
    with pytest.raises(QPError, match="inconsistent"):
        port_qprog.qprog(h, g, a, b)
    code = ("import numpy as np; from linkrepro.legacy import rahman1996; from linkrepro.errors import QPError\n"
            "rng = np.random.default_rng(1); root = rng.standard_normal((60, 60))\n"
            "h, g = root @ root.T + 60 * np.eye(60), rng.standard_normal(60)\n"
            "a, b = rng.standard_normal((194, 60)), rng.standard_normal(194) + 3.0\n"
            "try:\n    rahman1996.qprog(h, g, a, b)\nexcept QPError as exc:\n    print(exc)")
    assert "inconsistent" in in_child(code)


@pytest.mark.parametrize("qprog", [port_qprog.qprog, rahman1996.qprog], ids=["port", "legacy"])
def test_both_refuse_what_dqprog_would_return_silently(qprog):
    """Non-finite a or b: DQPROG's comparisons with NaN are false, so it would ignore the
    constraint and return a result: ValueError.  An overflowing problem: DQPROG returns a NaN
    solution: QPError."""
    for a, b in (([[np.nan, 1.0]], [0.0]), ([[1.0, 1.0]], [np.inf])):
        with pytest.raises(ValueError):
            qprog(np.eye(2), np.ones(2), a, b)
    with pytest.raises(QPError, match="not finite"):
        qprog(1e-300 * np.eye(2), np.array([1e300, 1e300]))


@pytest.mark.parametrize("args", [
    (np.eye(2), [0.0, 0.0, 0.0]),                                      # g longer than H
    (np.ones((2, 3)), [0.0, 0.0]),                                     # H not square
    (np.eye(2), [0.0, 0.0], [[1.0, 0.0, 0.0]], [1.0]),                 # a has 3 columns
    (np.eye(2), [0.0, 0.0], [[1.0, 0.0]], [1.0, 2.0]),                 # b too long
    (np.eye(2), [0.0, 0.0], [[1.0, 0.0]], [1.0], 2),                   # neq > m
    (np.eye(2), [0.0, 0.0], [[1.0, 0.0]], [1.0], -1),                  # neq < 0
    (np.eye(2), [np.nan, 0.0]),                                        # not finite
    (np.array([[1.0, 0.0], [np.inf, 1.0]]), [0.0, 0.0]),               # not finite
    (np.eye(61), np.zeros(61)),                                        # above MAXV = 60
    (np.eye(1), [0.0], np.ones((201, 1)), np.zeros(201)),              # above MAXC = 200
    (np.zeros((0, 0)), []),                                            # no variables
])
def test_bad_arguments_raise_value_error_in_both(args):
    with pytest.raises(ValueError):
        port_qprog.qprog(*args)
    with pytest.raises(ValueError):
        rahman1996.qprog(*args)
