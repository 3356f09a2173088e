"""A small dual-number 3x3 matrix type: A = R + eps*D with eps^2 = 0.

The 1996 program (after Uicker, Denavit and Hartenberg, and Fischer) describes each
link's screw displacement by one such matrix: the real part R is the rotation, the
dual part D = [d] R carries the translation d (the "principle of transference").
Arrays carry any leading batch axes (one entry per crank angle): shape (..., 3, 3).
Units: the dual part is in inches when the real part is dimensionless.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class DualMatrix:
    real: np.ndarray        # (..., 3, 3)
    dual: np.ndarray        # (..., 3, 3)

    def __matmul__(self, other: "DualMatrix") -> "DualMatrix":
        """(Ar + eps Ad)(Br + eps Bd) = Ar Br + eps (Ad Br + Ar Bd)  (listing: PRODUCTDUAL)."""
        return DualMatrix(self.real @ other.real, self.dual @ other.real + self.real @ other.dual)

    @property
    def T(self) -> "DualMatrix":
        """Both parts transposed (listing: TRANSPOSE); the inverse of a dual rotation."""
        return DualMatrix(np.swapaxes(self.real, -1, -2), np.swapaxes(self.dual, -1, -2))

    def translation(self) -> np.ndarray:
        """d from D = [d] R (eq. 2.15): the skew matrix D R^T read off (..., 3)."""
        skew = self.dual @ np.swapaxes(self.real, -1, -2)
        return np.stack([skew[..., 2, 1], skew[..., 0, 2], skew[..., 1, 0]], axis=-1)


def skew(v: np.ndarray) -> np.ndarray:
    """[v], the 3x3 matrix of the cross product v x . (..., 3) -> (..., 3, 3)."""
    v = np.asarray(v, dtype=float)
    zero = np.zeros(v.shape[:-1])
    return np.stack([np.stack([zero, -v[..., 2], v[..., 1]], -1),
                     np.stack([v[..., 2], zero, -v[..., 0]], -1),
                     np.stack([-v[..., 1], v[..., 0], zero], -1)], axis=-2)
