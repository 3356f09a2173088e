"""The printed 5x5 INVERSE (Rahman 1996, Appendix B; legacy/src/rahman1996_subroutines.f).

An unnormalised Gauss-Jordan with a row exchange only when a pivot is exactly 0.0 (rows
below k tried in order, swaps cumulative) and no guard against small pivots.  The right
half of the augmented matrix is rebuilt rather than permuted, so after row exchanges it
returns (P S)^-1 and S.B = P^T, not I (an author bug, latent in the thesis because it only
inverts symmetric positive definite matrices).  Where the listing printed MATRIX IS
SINGULAR and STOPped, ``inverse`` raises SingularPositionError.

Expected values come from numpy.linalg.inv and from an exact (Fraction) replay of the
pivot rule, never from INVERSE itself.
"""
import subprocess
import sys
from fractions import Fraction

import numpy as np
import pytest

from linkrepro.errors import SingularPositionError
from linkrepro.legacy.rahman1996 import inverse
from tests.patience import CHILD_SECONDS

#: symmetric, diagonally dominant base matrix of the driver cases (/tmp/cssp_sub_notes.md)
S0 = np.array([[4.0, 1, 0, 0, 1], [1, 5, 2, 0, 0], [0, 2, 6, 1, 0], [0, 0, 1, 7, 2], [1, 0, 0, 2, 8]])


def modified(**rows_and_entries):
    s = S0.copy()
    for key, value in rows_and_entries.items():
        s[tuple(int(c) - 1 for c in key[1:])] = value      # s11=0 -> S(1,1)=0 (1-based)
    return s


def predicted_row_order(s):
    """Replay the listing's pivot rule in exact arithmetic: at step k, while the pivot is
    exactly zero, swap row k with row k+1, then with row k+2, ... (cumulative swaps).
    Returns the original row indices (0-based) in the order they end up, i.e. P S = s[order]."""
    c = [[Fraction(v) for v in row] for row in s]
    order = list(range(5))
    for k in range(5):
        for cand in range(k + 1, 5):
            if c[k][k] != 0:
                break
            c[k], c[cand] = c[cand], c[k]
            order[k], order[cand] = order[cand], order[k]
        assert c[k][k] != 0, "singular: not a pivoting case"
        for i in range(k + 1, 5):
            f = c[i][k] / c[k][k]
            c[i] = [x - f * y for x, y in zip(c[i], c[k])]
    return order


# ---------------------------------------------------------------- regular matrices


def assert_inverse(s):
    b = inverse(s)
    ref = np.linalg.inv(s)
    assert np.abs(b - ref).max() <= 1e-12 * np.abs(ref).max()


def test_spd_matrix_matches_numpy_inverse():
    assert np.linalg.cond(S0) < 10
    assert_inverse(S0)


@pytest.mark.parametrize("seed", range(5))
def test_random_nonsymmetric_matrices_match_numpy_inverse(seed):
    rng = np.random.default_rng(seed)
    s = rng.uniform(-1, 1, (5, 5)) + 5 * np.eye(5)   # diagonally dominant: no zero pivot
    assert not np.allclose(s, s.T) and np.linalg.cond(s) < 10
    assert_inverse(s)


# ------------------------------------------------- row exchanges (the author bug)

# (case of the notes, matrix, final row order worked out by hand from the rule)
PIVOT_CASES = [
    ("2: S(1,1)=0, swap 1-2 at step 1", modified(s11=0.0), [1, 0, 2, 3, 4]),
    ("3: column 1 only in row 5, swaps 1-2, 1-3, 1-4, 1-5",
     modified(s11=0.0, s21=0.0), [4, 0, 1, 2, 3]),
    ("4: zero pivots at steps 2, 3, 4: swaps 2-3, 3-4, 4-5",
     np.vstack([[1, 3, 0.5, 0, 1], [2, 6, 1, 0, 0], S0[2:]]), [0, 2, 3, 4, 1]),
    ("13: S(3,2)=S(3,3)=0, swap 3-4 at step 3", modified(s32=0.0, s33=0.0), [0, 1, 3, 2, 4]),
    ("5: zero pivot at step 4 only, swap 4-5 (the DO 200 path)",
     np.array([[1.0, 2, 0, 0, 0], [0, 1, 0, 0, 0], [1, 0, 1, 0, 0], [0, 0, 0, 0, 1], [0, 0, 0, 1, 0]]),
     [0, 1, 2, 4, 3]),
]


@pytest.mark.parametrize("name, s, order", PIVOT_CASES, ids=[c[0].split(":")[0] for c in PIVOT_CASES])
def test_row_exchange_returns_inverse_of_row_permuted_matrix(name, s, order):
    """S.B is the permutation P^T predicted by the pivot rule (not I): B = (P S)^-1."""
    assert predicted_row_order(s) == order                  # the hand reasoning, replayed
    assert np.linalg.cond(s) < 1e3
    p = np.eye(5)[order]                                    # P S = s[order]
    b = inverse(s)
    np.testing.assert_allclose(s @ b, p.T, rtol=0, atol=1e-12)
    np.testing.assert_allclose(b, np.linalg.inv(s[order]), rtol=0,
                               atol=1e-12 * np.abs(np.linalg.inv(s)).max())
    assert np.abs(s @ b - np.eye(5)).max() >= 1.0          # i.e. not the inverse of S


# ----------------------------------------------------------- no small-pivot guard


def test_nearly_singular_matrix_returns_huge_entries_without_error():
    s = S0.copy()
    s[4] = 0.1 * s[0] + 0.3 * s[1]            # singular in exact arithmetic, not in binary
    assert np.linalg.cond(s) > 1e15
    assert np.abs(inverse(s)).max() > 1e10


def test_tiny_pivot_on_a_well_conditioned_matrix_gives_a_wrong_inverse():
    # driver case 6: cond(S) ~ 11, yet S(1,1) = 1e-20 is taken as the pivot (no
    # partial pivoting): B(1,1) comes out ~ -5551 instead of ~ -0.311.
    s = modified(s11=1e-20, s22=1.0)
    assert np.linalg.cond(s) < 20
    b = inverse(s)
    assert np.linalg.inv(s)[0, 0] == pytest.approx(-0.3107, abs=1e-3)
    assert np.abs(s @ b - np.eye(5)).max() > 1e3


# ------------------------------------------------------------------ arguments


@pytest.mark.parametrize("shape", [(4, 4), (5, 6), (6, 5), (25,), (1, 5, 5)])
def test_wrong_shape_raises_value_error(shape):
    with pytest.raises(ValueError):
        inverse(np.ones(shape))


@pytest.mark.parametrize("order", ["C", "F"])
def test_s_is_not_modified(order):
    """F order float64 reaches the FORTRAN without a copy, so this checks INVERSE itself."""
    for s in (np.array(S0, order=order), np.array(PIVOT_CASES[1][1], order=order)):
        before = s.copy()
        inverse(s)
        np.testing.assert_array_equal(s, before)


# ------------------------------------------------------------------ singular matrices

SINGULAR_CHILD = """
import numpy as np
from linkrepro.errors import SingularPositionError
from linkrepro.legacy.rahman1996 import inverse
s = np.eye(5)
s[:, 0] = 0.0
try:
    inverse(s)
except SingularPositionError:
    print("caught")
print("alive")
"""


def test_singular_matrix_does_not_stop_or_print_in_a_child_process():
    out = subprocess.run([sys.executable, "-c", SINGULAR_CHILD], capture_output=True, text=True,
                         timeout=CHILD_SECONDS)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["caught", "alive"]
    assert "SINGULAR" not in (out.stdout + out.stderr).upper()


def test_zero_column_is_singular():
    s = S0.copy()
    s[:, 0] = 0.0                             # four swaps at step 1, pivot still 0
    with pytest.raises(SingularPositionError):
        inverse(s)


@pytest.mark.parametrize("dependent_row", [lambda s: s[3], lambda s: s[0] + s[1]],
                         ids=["row5=row4", "row5=row1+row2"])
def test_dependent_last_row_is_singular(dependent_row):
    s = S0.copy()
    s[4] = dependent_row(s)                   # C(5,5) exactly 0 at step 5
    with pytest.raises(SingularPositionError):
        inverse(s)


def test_a_regular_matrix_inverts_after_a_singular_one():
    """The /INVERR/ flag must describe the last call only (it was once never reset, so
    every later inversion in the process raised)."""
    with pytest.raises(SingularPositionError):
        inverse(np.zeros((5, 5)))
    assert_inverse(S0)
