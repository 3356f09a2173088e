"""The IBM SSP routines as printed, against numpy on the same storage modes."""
import numpy as np
import pytest

from linkrepro.legacy import ali1977

RNG = np.random.default_rng(1977)


def symmetric_storage(s: np.ndarray) -> np.ndarray:
    """SSP mode 1: the upper triangle, column by column (LOC: IR = I + (J*J-J)/2, I <= J)."""
    n = s.shape[0]
    return np.array([s[i, j] for j in range(n) for i in range(j + 1)], dtype=np.float32)


def general_storage(a: np.ndarray) -> np.ndarray:
    return a.astype(np.float32).ravel(order="F")


def storage(mode: int, n: int):
    """A random matrix of the mode, as a full array and as SSP storage."""
    if mode == 0:
        full = RNG.normal(size=(n, n)).astype(np.float32)
        return full, general_storage(full)
    if mode == 1:
        half = RNG.normal(size=(n, n)).astype(np.float32)
        full = np.triu(half) + np.triu(half, 1).T
        return full, symmetric_storage(full)
    diag = RNG.normal(size=n).astype(np.float32)
    return np.diag(diag), diag


def test_gmtra_is_numpy_transpose():
    a = RNG.normal(size=(8, 3)).astype(np.float32)
    np.testing.assert_array_equal(ali1977.gmtra(a), a.T)


@pytest.mark.parametrize("msa", [0, 1, 2])
@pytest.mark.parametrize("msb", [0, 1, 2])
def test_mprd_every_storage_mode_matches_numpy(msa, msb):
    n = 5
    a_full, a_store = storage(msa, n)
    b_full, b_store = storage(msb, n)
    r = ali1977.mprd(a_store, b_store, n, n, n, msa, msb)
    expected = a_full.astype(np.float64) @ b_full.astype(np.float64)
    if msa == 2 and msb == 2:
        np.testing.assert_allclose(r, np.diag(expected), rtol=1e-6)
    else:
        np.testing.assert_allclose(r, expected, rtol=1e-5, atol=1e-5)


def test_mprd_rectangular_general():
    a = RNG.normal(size=(3, 8)).astype(np.float32)
    b = RNG.normal(size=(8, 2)).astype(np.float32)
    r = ali1977.mprd(general_storage(a), general_storage(b), 3, 8, 2)
    np.testing.assert_allclose(r, a.astype(np.float64) @ b, rtol=1e-5, atol=1e-6)


@pytest.mark.parametrize("i,j,ms,expected", [
    (2, 3, 0, 4 * 2 + 2),          # general 4x4: N*(J-1)+I
    (2, 3, 1, 2 + 3),              # symmetric upper: I+(J*J-J)/2
    (3, 2, 1, 2 + 3),              # lower element maps to the upper one
    (3, 3, 2, 3), (2, 3, 2, 0),    # diagonal: off-diagonal not stored
])
def test_loc_subscripts(i, j, ms, expected):
    assert ali1977.loc(i, j, 4, 4, ms) == expected


@pytest.mark.parametrize("kwargs", [dict(n=0, m=1, l=1), dict(n=2, m=2, l=2, msa=3),
                                    dict(n=2, m=3, l=2, msa=1)])
def test_mprd_bad_arguments_raise_value_error(kwargs):
    with pytest.raises(ValueError):
        ali1977.mprd(np.zeros(4), np.zeros(4), **kwargs)


def test_mprd_wrong_storage_length_raises():
    with pytest.raises(ValueError, match="storage vectors"):
        ali1977.mprd(np.zeros(5), np.zeros(4), 2, 2, 2)
