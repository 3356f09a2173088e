"""Our QPROG (IMSL's convention, Goldfarb-Idnani; D050) and the printed INVERSE (D084),
against closed forms, the PyPI quadprog package and numpy."""
import numpy as np
import pytest
import quadprog

from linkrepro.errors import SingularPositionError
from linkrepro.legacy import QPError, inverse, qprog


def test_unconstrained_is_minus_h_inverse_g():
    h = np.array([[4.0, 1.0], [1.0, 3.0]])
    g = np.array([1.0, -2.0])
    np.testing.assert_allclose(qprog(h, g)["sol"], -np.linalg.solve(h, g), rtol=1e-13)


def test_one_equality_by_lagrange():
    """min |x|^2/2 s.t. x1 + x2 = 1: x = (1/2, 1/2), multiplier 1/2."""
    out = qprog(np.eye(2), np.zeros(2), a=[[1.0, 1.0]], b=[1.0], neq=1)
    np.testing.assert_allclose(out["sol"], [0.5, 0.5], rtol=1e-13)
    np.testing.assert_allclose(out["multipliers"], [0.5], rtol=1e-13)


def test_solve_qp_textbook_example():
    """The R quadprog documentation's example (solve.QP): Dmat = I, dvec = (0, 5, 0),
    A^T b >= b0 with Amat = [[-4, 2, 0], [-3, 1, -2], [0, 0, 1]] (columns), b0 = (-8, 2, 0).
    Published solution: (0.4761905, 1.0476190, 2.0952381)."""
    amat = np.array([[-4.0, 2.0, 0.0], [-3.0, 1.0, -2.0], [0.0, 0.0, 1.0]])
    out = qprog(np.eye(3), -np.array([0.0, 5.0, 0.0]), a=amat.T, b=[-8.0, 2.0, 0.0])
    np.testing.assert_allclose(out["sol"], [0.4761905, 1.0476190, 2.0952381], atol=5e-8)


@pytest.mark.parametrize("seed", range(20))
def test_random_convex_problems_agree_with_quadprog(seed):
    rng = np.random.default_rng(seed)
    n, m, neq = 6, 8, 2
    r = rng.normal(size=(n, n))
    h = r @ r.T + n * np.eye(n)
    g = rng.normal(size=n)
    a = rng.normal(size=(m, n))
    x0 = rng.normal(size=n)                                  # a feasible point
    b = a @ x0 - np.r_[np.zeros(neq), rng.uniform(0.0, 1.0, m - neq)]
    ours = qprog(h, g, a, b, neq)["sol"]
    theirs = quadprog.solve_qp(h, -g, a.T, b, neq)[0]
    np.testing.assert_allclose(ours, theirs, rtol=1e-9, atol=1e-10)
    assert np.all(a[neq:] @ ours >= b[neq:] - 1e-10) and np.allclose(a[:neq] @ ours, b[:neq])


def test_positive_definite_h_needs_no_diag():
    assert qprog(np.diag([1.0, 2.0, 3.0]), np.ones(3))["diag"] == 0.0


def test_semidefinite_h_gets_a_diag_and_stays_optimal():
    """H singular along (1, -1): IMSL adds DIAG*I. The answer is optimal for the original
    problem (objective equal to quadprog's on H + 1e-9 I) and feasible."""
    h = np.array([[1.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.0, 0.0, 2.0]])
    g = np.array([-1.0, -1.0, 1.0])
    a, b = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]), np.array([0.0, 0.0])
    out = qprog(h, g, a, b, 0)
    assert out["diag"] > 0.0
    f = lambda x: g @ x + x @ h @ x / 2
    ref = quadprog.solve_qp(h + 1e-9 * np.eye(3), -g, a.T, b, 0)[0]
    assert f(out["sol"]) == pytest.approx(f(ref), abs=1e-7)
    assert np.all(out["sol"][:2] >= -1e-12)


def test_inconsistent_constraints_raise():
    with pytest.raises(QPError):
        qprog(np.eye(1), np.zeros(1), a=[[1.0], [-1.0]], b=[1.0, 0.0])


def test_bad_shapes_raise_value_error():
    with pytest.raises(ValueError):
        qprog(np.eye(2), np.zeros(3))


S0 = np.array([[4, 1, 0, 0, 1], [1, 5, 2, 0, 0], [0, 2, 6, 1, 0], [0, 0, 1, 7, 2], [1, 0, 0, 2, 8]], float)


def test_inverse_of_a_regular_matrix():
    rng = np.random.default_rng(1)
    for s in (S0, rng.normal(size=(5, 5)) + 5 * np.eye(5)):
        np.testing.assert_allclose(inverse(s), np.linalg.inv(s), rtol=1e-12, atol=1e-14)


def test_inverse_row_exchange_returns_the_permuted_inverse():
    """D084: with S(1,1) = 0 the listing swaps rows 1 and 2 but rebuilds the right half as
    the identity: the result is (P S)^-1, so S B is the row exchange, not I."""
    s = S0.copy()
    s[0, 0] = 0.0
    p = np.eye(5)[[1, 0, 2, 3, 4]]
    b = inverse(s)
    np.testing.assert_allclose(b, np.linalg.inv(p @ s), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(s @ b, p.T, atol=1e-12)


@pytest.mark.parametrize("make", [lambda s: s * np.r_[0, 1, 1, 1, 1],            # a zero column
                                  lambda s: np.vstack([s[:4], s[3]])])           # row 5 = row 4
def test_inverse_of_a_singular_matrix_is_a_typed_error(make):
    s = make(S0.copy())
    with pytest.raises(SingularPositionError):
        inverse(s)


def test_inverse_has_no_small_pivot_guard():
    """A pivot of 1e-20 is accepted: the answer is wrong by orders of magnitude (D084)."""
    s = S0.copy()
    s[0, 0], s[1, 1] = 1e-20, 1.0
    assert np.abs(s @ inverse(s) - np.eye(5)).max() > 1.0
    with pytest.raises(ValueError):
        inverse(np.eye(4))
