"""Our QPROG (legacy and port) on rescaled copies of a problem (issue 22, item 2; register D050).

A QP and its copy with constraint row i (a_i and b_i) multiplied by r_i, and H and g by s, have
the same solution x; the copy's multipliers are lambda_i * s / r_i and its DIAG is s * DIAG.
QPROG's tolerances must therefore be relative to the rows' and H's own scale.  Expected numbers
come from closed forms and from quadprog on the unscaled (well-scaled) problem, never from our
own output; the bit-for-bit checks compare a problem with its copy scaled by powers of two.
"""
import numpy as np
import pytest
import quadprog
from hypothesis import event, given, settings
from hypothesis import strategies as st

from linkrepro.errors import QPError
from linkrepro.legacy import rahman1996
from linkrepro.port.rahman1996 import qprog as port_qprog

ENGINES = pytest.mark.parametrize("qprog", [port_qprog.qprog, rahman1996.qprog], ids=["port", "legacy"])
#: ten times the examples under HYPOTHESIS_PROFILE=thorough
MORE = max(1, settings.default.max_examples // 100)


def bits(x) -> np.ndarray:
    return np.asarray(x, dtype=np.float64).view(np.uint64)


# ------------------------------------------------------------ the examples, closed form

# min |x|^2/2 - x1 - x2 s.t. x1 + x2 >= 3 (or = 3): x = (1.5, 1.5), multiplier 0.5 (H x + g = lam a).
@ENGINES
@pytest.mark.parametrize("row, hg, neq", [(1e13, 1.0, 0), (1e-13, 1.0, 0), (1.0, 1e16, 0), (1e160, 1.0, 1),
                                          (1e-160, 1.0, 1), (1e150, 1e-150, 0), (1e-150, 1e150, 1)])
def test_scaled_copies_of_one_problem_have_its_closed_form_answer(qprog, row, hg, neq):
    res = qprog(hg * np.eye(2), hg * np.array([-1.0, -1.0]), [[row, row]], [3.0 * row], neq)
    np.testing.assert_allclose(res["sol"], [1.5, 1.5], rtol=1e-14)
    assert res["active"].tolist() == [0]
    assert res["multipliers"][0] == pytest.approx(0.5 * hg / row, rel=1e-14)
    assert res["diag"] == 0.0


# ------------------------------------------------- families of scaled problems against quadprog


@st.composite
def scaled_problems(draw):
    """A strictly convex, well-conditioned, feasible QP (cond(H) ~ 10, several bounds binding)
    and its copy with rows, H and g, or both multiplied by 10^k, k in -150..150."""
    n = draw(st.integers(1, 6))
    neq = draw(st.integers(0, n - 1))
    m = neq + draw(st.integers(1, 2 * n))
    rng = np.random.default_rng(draw(st.integers(0, 2 ** 32 - 1)))
    root = rng.standard_normal((n, n))
    h = root @ root.T + n * np.eye(n)
    g, a = 5.0 * rng.standard_normal(n), rng.standard_normal((m, n))
    b = a @ rng.standard_normal(n)
    b[neq:] -= rng.uniform(0.0, 1.0, m - neq)
    kind = draw(st.sampled_from(["rows", "H and g", "both"]))
    event(f"scaled: {kind}")
    exponent = st.integers(-150, 150)
    r = 10.0 ** np.array([draw(exponent) for _ in range(m)]) if kind != "H and g" else np.ones(m)
    s = 10.0 ** draw(exponent) if kind != "rows" else 1.0
    return (h, g, a, b, neq), (s * h, s * g, r[:, None] * a, r * b, neq), r, s


@ENGINES
@settings(max_examples=60 * MORE)
@given(problem=scaled_problems())
def test_scaled_families_agree_with_quadprog_on_the_unscaled_problem(qprog, problem):
    """quadprog solves the well-scaled original (cond(H) ~ 10: its answer is good to ~1e-15);
    ours solves the copy scaled by up to 1e+-150 per row and in H.  Rounding in the scaled
    copy's arithmetic is relative, so the solutions agree to 1e-10 of |x|, and the copy's
    multipliers are quadprog's times s / r_i."""
    (h, g, a, b, neq), scaled, r, s = problem
    x_ref, _, _, _, lam_ref, _ = quadprog.solve_qp(h, -g, a.T.copy(), b, neq)
    res = qprog(*scaled)
    size = 1.0 + np.abs(x_ref).max()
    np.testing.assert_allclose(res["sol"], x_ref, rtol=0, atol=1e-10 * size)
    lam = np.zeros(len(b))
    lam[res["active"]] = res["multipliers"] * r[res["active"]] / s
    np.testing.assert_allclose(lam, lam_ref, rtol=0, atol=1e-9 * (1.0 + np.abs(lam_ref).max()))


@ENGINES
@settings(max_examples=40 * MORE)
@given(problem=scaled_problems(), rows=st.lists(st.integers(-400, 400), min_size=17, max_size=17),
       quarter=st.integers(-200, 200))
def test_power_of_two_copies_give_the_same_bits(qprog, problem, rows, quarter):
    """Rows scaled by 2^k_i and H, g by 4^j are exact in floating point: the copy is the same
    problem in the same numbers, so QPROG's answer is the same bit for bit, its multipliers
    are exactly lambda_i * 4^j / 2^k_i and its DIAG 4^j * DIAG."""
    (h, g, a, b, neq), _, _, _ = problem
    r = np.ldexp(1.0, np.array(rows[:len(b)]))
    s = np.ldexp(1.0, 2 * quarter)
    base, copy = qprog(h, g, a, b, neq), qprog(s * h, s * g, r[:, None] * a, r * b, neq)
    assert np.array_equal(bits(copy["sol"]), bits(base["sol"]))
    assert np.array_equal(copy["active"], base["active"])
    expected = base["multipliers"] * s / r[base["active"]]
    assert np.array_equal(bits(copy["multipliers"]), bits(expected))
    assert copy["diag"] == s * base["diag"]


# --------------------------------------------------------- extreme Hessians (item 6 of the issue)


@ENGINES
@pytest.mark.parametrize("tiny", [5e-324, 1e-310, 1e-300])
def test_a_subnormal_hessian_is_solved_as_its_normal_copy(qprog, tiny):
    """H = tiny * [[2, 1], [1, 2]], g = tiny * (-1, 1): the same problem as at tiny = 1,
    x = -H^-1 g = (1, -1) (closed form).  The port raised ZeroDivisionError and the DIAG rule
    saw a singular H where TINY = sqrt(eps) * max H_ii underflowed.  (Subnormals are integer
    multiples of 2^-1074: tiny * H and tiny * g hold the 2:1 pattern exactly.)"""
    h = np.array([[2.0, 1.0], [1.0, 2.0]])
    g = np.array([-1.0, 1.0])
    with np.errstate(under="ignore"):
        res = qprog(tiny * h, tiny * g)
    np.testing.assert_allclose(res["sol"], [1.0, -1.0], rtol=1e-12)
    assert res["diag"] == 0.0


@ENGINES
def test_a_huge_indefinite_hessian_gets_a_finite_shift_or_a_qperror(qprog):
    """H = [[1, 1e300], [1e300, 1]] (eigenvalues 1 +- 1e300): DIAG was returned as inf.  Now
    DIAG is finite with H + DIAG*I positive definite and the answer solves (H + DIAG I) x = -g
    (checked here, scaled by 1e-300; g has no part along the negative direction, which the
    regularized answer therefore does not show: not found unbounded, D163); where the shift
    itself overflows, QPError: -max I is unbounded below without rows, and with -1 <= x <= 1
    its shift is not finite."""
    h, g = np.array([[1.0, 1e300], [1e300, 1.0]]), np.array([1.0, 1.0])
    res = qprog(h, g)
    d = res["diag"]
    assert np.isfinite(d) and d > 1e300
    shifted = (h + d * np.eye(2)) * 1e-300
    assert np.linalg.eigvalsh(shifted).min() > 0
    np.testing.assert_allclose(shifted @ res["sol"], -g * 1e-300, rtol=1e-10, atol=1e-310)
    with pytest.raises(QPError, match="unbounded"):
        qprog(-np.finfo(float).max * np.eye(3), np.ones(3))
    with pytest.raises(QPError, match="shift"):                  # DIAG = |H_ii|(1 + sqrt(eps))
        qprog(-np.finfo(float).max * np.eye(3), np.ones(3), np.vstack([np.eye(3), -np.eye(3)]), -np.ones(6))
