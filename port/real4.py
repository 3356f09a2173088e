"""Arithmetic of the original: REAL*4 storage and the SSP MPRD product.

With ``real4=True`` values are rounded to IEEE single precision where the
listing stores them in REAL*4 variables, and matrix products accumulate in
single precision in MPRD's order (row into column, k = 1..M, no fused
multiply-add).  With ``real4=False`` everything stays float64.
All arrays carry a leading batch axis (one entry per input angle).
"""
from __future__ import annotations

import numpy as np


def store(x, real4: bool) -> np.ndarray:
    """What a REAL*4 variable holds after ``X = <double expression>``."""
    x = np.asarray(x, dtype=np.float64)
    return x.astype(np.float32) if real4 else x


def product(a: np.ndarray, b: np.ndarray, real4: bool) -> np.ndarray:
    """Batched A (.., n, m) @ B (.., m, l); in REAL*4 exactly as SSP MPRD sums."""
    if not real4:
        return np.matmul(a, b)
    a = np.asarray(a, dtype=np.float32)
    b = np.asarray(b, dtype=np.float32)
    batch = np.broadcast_shapes(a.shape[:-2], b.shape[:-2])
    r = np.zeros(batch + (a.shape[-2], b.shape[-1]), dtype=np.float32)
    for k in range(a.shape[-1]):
        r = r + a[..., :, k, None] * b[..., None, k, :]
    return r
