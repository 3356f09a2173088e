"""Arithmetic of the original: REAL*4 storage and the SSP MPRD product.

With ``real4=True`` values are rounded to IEEE single precision where the
listing stores them in REAL*4 variables, and matrix products accumulate in
single precision in MPRD's order (row into column, k = 1..M, no fused
multiply-add): MPRD's loop, compiled by numba.  With ``real4=False`` everything stays float64.
All arrays carry a leading batch axis (one entry per input angle).
"""
from __future__ import annotations

import numpy as np
from numba import guvectorize


def store(x, real4: bool) -> np.ndarray:
    """What a REAL*4 variable holds after ``X = <double expression>`` (a REAL*4 array as it is)."""
    x = np.asarray(x)
    if real4 and x.dtype == np.float32:
        return x
    x = x.astype(np.float64, copy=False)
    return x.astype(np.float32) if real4 else x


@guvectorize(["void(float32[:, :], float32[:, :], float32[:, :])"], "(n,m),(m,l)->(n,l)", cache=True)
def _mprd(a, b, r):
    """SSP MPRD's loop in REAL*4: R(i,j) = 0, then R(i,j) = R(i,j) + A(i,k)*B(k,j) for
    k = 1..m, each product and each sum rounded to single (no fused multiply-add)."""
    for i in range(a.shape[0]):
        for j in range(b.shape[1]):
            total = np.float32(0.0)
            for k in range(a.shape[1]):
                total += a[i, k] * b[k, j]
            r[i, j] = total


def product(a: np.ndarray, b: np.ndarray, real4: bool) -> np.ndarray:
    """Batched A (.., n, m) @ B (.., m, l); in REAL*4 (A and B stored REAL*4) exactly as SSP
    MPRD sums."""
    if not real4:
        return np.matmul(a, b)
    return _mprd(np.asarray(a, dtype=np.float32), np.asarray(b, dtype=np.float32))
