"""The spatial slider crank both Rahman theses solve: its inputs and the numbers its loop
closure computes with, and the printed Newton's first estimate.

Units as printed: inch, second; angles in degrees at the interface, radians inside.
``LoopConstants.of(inputs, real4)`` gives the loop's numbers: with ``real4`` they are what
the 1996 listing's REAL*4 arguments, literals and single-precision expressions hold
(S1 = 0.4 is 0.4000000059604645), without it the decimal values.  The 1996 example adds its
masses and QP data (``rahman1996.data.Constants``); the 1991 method uses these alone.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import math
from dataclasses import dataclass

import numpy as np

from ...checks import slider_crank

@dataclass(frozen=True)
class CsspInputs:
    """A spatial slider crank: lengths (in), ground twist (deg), crank offset (in), crank speed
    (rpm); the defaults are Rahman's (1996) example of section 5.2."""
    a1: float = 2.0
    a2: float = 8.0
    a4: float = 1.0
    alpha4_deg: float = 250.0
    s1: float = 0.4
    rpm: float = 3000.0

    def __post_init__(self):
        """Each field a real number (TypeError, before any ValueError), finite, within
        linkrepro.checks.LARGEST, and a1, a2, rpm positive (ValueError): the rules of the
        legacy face too (``linkrepro.checks.slider_crank``)."""
        checked = slider_crank(self.a1, self.a2, self.a4, self.alpha4_deg, self.s1, self.rpm)
        for name, value in checked.items():
            object.__setattr__(self, name, value)

    @property
    def omega(self) -> float:
        """Crank speed (rad/s)."""
        return self.rpm * 2.0 * math.pi / 60.0

    @property
    def alpha4(self) -> float:
        """Ground twist (rad)."""
        return math.radians(self.alpha4_deg)

    @property
    def k4(self) -> np.ndarray:
        """Unit vector of the slider's travel (its joint moves along -k4 as s4 grows)."""
        return slider_axis(self.alpha4)


def slider_axis(alpha4: float) -> np.ndarray:
    """k4 = (0, sin alpha4, cos alpha4), the slider's axis for the ground twist alpha4 (rad)."""
    return np.array([0.0, math.sin(alpha4), math.cos(alpha4)])


def single(x, real4: bool) -> float:
    """A REAL*4 literal or argument (as the listing holds it) or the exact value."""
    return float(np.float32(x)) if real4 else float(x)


@dataclass(frozen=True)
class LoopConstants:
    """The numbers the loop closure and its Newton use, as one precision regime holds them."""
    a1: float
    a2: float
    a4: float
    s1: float
    alpha4: float              # rad
    omega: float               # crank speed, rad/s
    pi: float
    newton_tol: float          # the listing's 0.0000001

    @property
    def k4(self) -> np.ndarray:
        """Unit vector of the slider's travel (as ``CsspInputs.k4``)."""
        return slider_axis(self.alpha4)

    @classmethod
    def of(cls, inputs: CsspInputs, real4: bool) -> "LoopConstants":
        if not isinstance(inputs, CsspInputs):
            raise TypeError(f"inputs must be CsspInputs, got {type(inputs).__name__} {inputs!r}")
        s = lambda x: single(x, real4)                                   # noqa: E731
        pi = float(np.float32(4.0) * np.arctan(np.float32(1.0))) if real4 else math.pi
        degrad = pi / 180.0
        # THT1D=6.0*RPM*DEGRAD: 6.0*RPM a REAL*4 product
        omega = (float(np.float32(6.0) * np.float32(inputs.rpm)) if real4 else 6.0 * inputs.rpm) * degrad
        return cls(a1=s(inputs.a1), a2=s(inputs.a2), a4=s(inputs.a4), s1=s(inputs.s1),
                   alpha4=inputs.alpha4_deg * degrad, omega=omega, pi=pi, newton_tol=s(1e-7))


def _powf(x: np.float32, y: float) -> float:
    """x**y for REAL*4 x as gfortran evaluates it: the C library's powf (not sqrtf: glibc's
    powf(x, 0.5) can differ from the correctly rounded root by one REAL*4 unit)."""
    return float(_LIBM.powf(float(x), y))


_LIBM = ctypes.CDLL(ctypes.util.find_library("m"))
_LIBM.powf.restype, _LIBM.powf.argtypes = ctypes.c_float, [ctypes.c_float, ctypes.c_float]


def initial_estimate(c: LoopConstants, real4: bool) -> np.ndarray:
    """The listing's start: S4=(A2**2-(A1+A4)**2)**0.5 (REAL*4), THT2=PI-ATAN(S4/(A4+A1)),
    THT3=2*PI-THT2, ETA2 = ETA3 = 0; NaN where the root is not real (the Newton refuses it)."""
    kind = np.float32 if real4 else np.float64
    a1, a2, a4 = (kind(v) for v in (c.a1, c.a2, c.a4))
    with np.errstate(invalid="ignore", divide="ignore"):
        square = a2 ** 2 - (a1 + a4) ** 2
        s4 = _powf(square, 0.5) if real4 else float(square) ** 0.5 if square >= 0 else math.nan
        theta2 = c.pi - math.atan(np.float64(s4) / np.float64(a4 + a1))   # A4+A1 a REAL*4 sum; the C library's atan
    return np.array([theta2, 0.0, 2.0 * c.pi - theta2, 0.0, s4])
