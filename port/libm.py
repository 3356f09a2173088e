"""sin, cos and arctan of the C library, as numpy ufuncs (compiled by numba).

The listings call DSIN, DCOS and DATAN, which gfortran compiles to calls of the C library
(glibc's sin, cos, atan).  numpy computes these functions itself, and on some CPUs
(AVX-512) with SIMD code that can differ from the C library's in the last bits; where the
port must round as the FORTRAN does, it calls these instead.  They behave as numpy's ufuncs:
arrays broadcast, a scalar gives a numpy scalar.  Arguments in radians.
"""
from __future__ import annotations

import math

from numba import vectorize


@vectorize(["float64(float64)"], cache=True)
def sin(x):
    return math.sin(x)


@vectorize(["float64(float64)"], cache=True)
def cos(x):
    return math.cos(x)


@vectorize(["float64(float64)"], cache=True)
def arctan(x):
    return math.atan(x)
