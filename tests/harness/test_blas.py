"""harness/blas.py: inside ``one_thread`` every OpenBLAS found runs on one thread, after it on as
many as before (also when the block raises); a dense solve inside gives what numpy's own gives."""
import numpy as np
import pytest

from linkrepro.harness import blas


def test_one_thread_sets_and_restores_every_openblas():
    libraries = blas._libraries()
    if not libraries:
        pytest.skip("no OpenBLAS in numpy's or scipy's wheel here")
    before = [get() for _, get in libraries]
    try:
        for set_threads, _ in libraries:
            set_threads(2)
        with pytest.raises(RuntimeError):
            with blas.one_thread():
                assert [get() for _, get in libraries] == [1] * len(libraries)
                raise RuntimeError
        assert [get() for _, get in libraries] == [2] * len(libraries)
    finally:
        for (set_threads, _), count in zip(libraries, before):
            set_threads(count)


def test_a_solve_inside_is_right():
    rng = np.random.default_rng(3)
    a, b = rng.standard_normal((120, 120)) + 120.0 * np.eye(120), rng.standard_normal(120)
    with blas.one_thread():
        x = np.linalg.solve(a, b)
    assert np.abs(a @ x - b).max() < 1e-12
