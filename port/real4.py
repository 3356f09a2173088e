"""Arithmetic of the original: REAL*4 storage and the SSP MPRD product.

With ``real4=True`` values are rounded to IEEE single precision where the
listing stores them in REAL*4 variables, and matrix products accumulate in
single precision in MPRD's order (row into column, k = 1..M, no fused
multiply-add): MPRD's loop, compiled by numba.  With ``real4=False`` everything stays float64.
All arrays carry a leading batch axis (one entry per input angle).
"""
from __future__ import annotations

import numpy as np
from numba import njit


def store(x, real4: bool) -> np.ndarray:
    """What a REAL*4 variable holds after ``X = <double expression>`` (a REAL*4 array as it is)."""
    x = np.asarray(x)
    if real4 and x.dtype == np.float32:
        return x
    x = x.astype(np.float64, copy=False)
    return x.astype(np.float32) if real4 else x


@njit(cache=True)
def _mprd(a, b):
    """SSP MPRD's loop in REAL*4 over a batch: R(i,j) = 0, then R(i,j) = R(i,j) + A(i,k)*B(k,j)
    for k = 1..m, each product and each sum rounded to single (no fused multiply-add);
    ``a`` (Na, n, m) and ``b`` (Nb, m, l) float32, Na and Nb equal or one of them 1.

    A plain ``@njit`` kernel, not a cached ``@guvectorize``: numba keeps a cached gufunc in
    two files (kernel and wrapper) that two processes compiling at once can write with
    mismatched symbol names, and the wrapper then calls nothing (a SIGSEGV on every later
    call; numba issue 10128, still open).  An njit function's cache is one self-contained
    file, written atomically."""
    batch = max(a.shape[0], b.shape[0])
    r = np.empty((batch, a.shape[1], b.shape[2]), dtype=np.float32)
    for p in range(batch):
        pa = p if a.shape[0] > 1 else 0
        pb = p if b.shape[0] > 1 else 0
        for i in range(a.shape[1]):
            for j in range(b.shape[2]):
                total = np.float32(0.0)
                for k in range(a.shape[2]):
                    total += a[pa, i, k] * b[pb, k, j]
                r[p, i, j] = total
    return r


def _stacked(x: np.ndarray, batch: tuple) -> np.ndarray:
    """``x`` (.., n, m) as a C-contiguous (N, n, m) stack over ``batch`` (N = 1 if x has no
    leading axes)."""
    if x.shape[:-2] not in (batch, ()):
        x = np.broadcast_to(x, batch + x.shape[-2:])
    return np.ascontiguousarray(x.reshape((-1,) + x.shape[-2:]))


def product(a: np.ndarray, b: np.ndarray, real4: bool) -> np.ndarray:
    """Batched A (.., n, m) @ B (.., m, l), the leading axes broadcast as numpy's matmul does;
    in REAL*4 (A and B stored REAL*4) exactly as SSP MPRD sums."""
    if not real4:
        return np.matmul(a, b)
    a, b = np.asarray(a, dtype=np.float32), np.asarray(b, dtype=np.float32)
    if a.ndim < 2 or b.ndim < 2 or a.shape[-1] != b.shape[-2]:
        raise ValueError(f"matrix shapes {a.shape} and {b.shape} do not chain")
    batch = a.shape[:-2] if a.shape[:-2] == b.shape[:-2] or b.ndim == 2 else np.broadcast_shapes(a.shape[:-2],
                                                                                               b.shape[:-2])
    return _mprd(_stacked(a, batch), _stacked(b, batch)).reshape(batch + (a.shape[-2], b.shape[-1]))
