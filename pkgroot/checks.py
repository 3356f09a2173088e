"""Argument checks shared by the legacy faces and the port: one message, one error type per
mistake (TypeError for what is not a number, ValueError for a number out of its domain)."""
from __future__ import annotations

import numpy as np


def finite_matrix(name: str, value, shape: tuple[int, int]) -> np.ndarray:
    """``value`` as a finite float64 matrix of the given shape."""
    try:
        matrix = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name} must be a {shape[0]} x {shape[1]} matrix of numbers ({exc})") from None
    if matrix.shape != shape:
        raise ValueError(f"{name} must be a {shape[0]} x {shape[1]} matrix, got shape {matrix.shape}")
    if not np.all(np.isfinite(matrix)):
        raise ValueError(f"{name} must be finite")
    return matrix
