"""Argument checks shared by the legacy faces and the port: one message, one error type per
mistake (TypeError for what is not a number, ValueError for a number out of its domain); and
the rule by which the CSSP engines refuse a singular position (SingularPositionError)."""
from __future__ import annotations

import math
import numbers

import numpy as np

from .errors import SingularPositionError

#: the largest magnitude a parameter may have (inch, rpm, deg, lbf*in): a bound on the
#: arithmetic, not on physics; beyond it the programs' powers of speeds and lengths overflow
LARGEST = 1e6


def parameter(name: str, value, *, positive: bool = False, largest: float | None = LARGEST) -> float:
    """One real parameter as a float: TypeError if it is not a real number (a bool is not),
    ValueError if it is not finite, not positive where it must be, or beyond ``largest``
    (None: no bound but finiteness)."""
    _real_number(name, value)
    try:
        value = float(value)
    except OverflowError:
        raise ValueError(f"{name} = {_shown(value)} is too large for a double") from None
    if not math.isfinite(value):
        raise ValueError(f"{name} must be finite, got {value!r}")
    if positive and value <= 0.0:
        raise ValueError(f"{name} must be positive, got {value!r}")
    if largest is not None and abs(value) > largest:
        raise ValueError(f"{name} = {value!r} is out of range (at most {largest:g} in magnitude)")
    return value


def _shown(value) -> str:
    """``value`` for a message: an integer of more than 20 digits by its number of digits."""
    if isinstance(value, numbers.Integral) and abs(int(value)) >= 10**20:
        return f"an integer of {len(str(abs(int(value))))} digits"
    return repr(value)


def _real_number(name: str, value) -> None:
    """TypeError unless ``value`` is a real number (a bool is not)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a real number, got {type(value).__name__} {value!r}")


def parameters(values: dict, positive: tuple = ()) -> dict:
    """Several real parameters (``parameter``, names as keys) as floats, those named in
    ``positive`` positive: every TypeError before any ValueError, so that the error's type
    does not depend on the order in which the arguments are checked."""
    for name, value in values.items():
        _real_number(name, value)
    return {name: parameter(name, value, positive=name in positive) for name, value in values.items()}


def as_real4(name: str, value: float, *, positive: bool = False) -> float:
    """What a listing's REAL*4 variable holds for ``value``: ValueError if that is not finite
    (or, with ``positive``, 0)."""
    with np.errstate(over="ignore"):
        held = float(np.float32(value))
    if not math.isfinite(held):
        raise ValueError(f"{name}={value!r} does not fit the listing's REAL*4 variable")
    if positive and held <= 0.0:
        raise ValueError(f"{name}={value!r} is 0 in the listing's REAL*4")
    return held


#: the largest FORTRAN INTEGER (INTEGER*4)
INTEGER_MAX = 2**31 - 1


def integer(name: str, value, smallest: int = 1, largest: int = INTEGER_MAX) -> int:
    """A FORTRAN INTEGER argument: TypeError unless an integer (an integral float is one, a
    bool is not), ValueError outside smallest..largest (a Python int of any size)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__} {value!r}")
    if not isinstance(value, numbers.Integral) and not (math.isfinite(value) and float(value).is_integer()):
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if not smallest <= value <= largest:
        raise ValueError(f"{name} must be from {smallest} to {largest}, got {_shown(value)}")
    return int(value)


def real_array(name: str, value) -> np.ndarray:
    """``value`` as a float64 array: TypeError unless it holds real numbers (not bool, str or
    other objects), ValueError for ragged nesting or a number too large for a double (a
    Python int beyond 1.8e308)."""
    try:
        raw = np.asarray(value)
    except ValueError as exc:                             # ragged nesting
        raise ValueError(f"{name} must be an array of numbers: {exc}") from None
    if raw.dtype.kind == "O" and all(isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))
                                     for v in raw.flat):
        try:
            return raw.astype(np.float64)                 # Python ints beyond int64
        except OverflowError:
            raise ValueError(f"{name} holds a number too large for a double") from None
    if raw.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be an array of real numbers, got dtype {raw.dtype}")
    return raw.astype(np.float64)


def real4_array(name: str, value) -> np.ndarray:
    """An array of numbers as the listing's REAL*4 holds them: TypeError unless numeric,
    ValueError if a value is not finite there (NaN, infinity, beyond 3.4e38)."""
    raw = real_array(name, value)
    with np.errstate(over="ignore"):
        held = raw.astype(np.float32)
    if not np.all(np.isfinite(held)):
        raise ValueError(f"{name} must be finite in REAL*4 (|x| < 3.4e38)")
    return held


# Ali (1977): rules of the listings' own variables, shared by the legacy face and the port.

#: The Case I listing keeps the speed in an INTEGER (N=SPEED); the same bound holds for the
#: REAL*4 speed of Cases II and III, so that every program has one domain.
RPM_LIMIT = 2**31 - 1


def speed_rpm(value) -> float:
    """The input speed (rpm): finite, |rpm| <= 2**31 - 1."""
    value = parameter("rpm", value, largest=None)
    if abs(value) > RPM_LIMIT:
        raise ValueError(f"rpm={value} is out of range: |rpm| <= 2**31 - 1 (Case I's INTEGER speed N)")
    return value


def link_length(name: str, value) -> float:
    """A link length (in) of the K.E.D. four-bar: from 1/LARGEST to LARGEST (1e-6 to 1e6 in).
    The analysis forms squares, cubes and products of the lengths with the speed squared;
    outside that range they underflow or overflow in double precision (a length of 1e-170 in
    made the Freudenstein constants divide by zero) and every engine would be silently wrong."""
    value = parameter(name, value, positive=True)
    if value < 1.0 / LARGEST:
        raise ValueError(f"{name} = {value!r} is out of range (at least {1.0 / LARGEST:g} in)")
    return value


def weight_lbf(name: str, value) -> float:
    """A weight (lbf) or weight density (lbf/in^3): finite, >= 0, representable in REAL*4."""
    value = parameter(name, value, largest=None)
    if value < 0.0:
        raise ValueError(f"{name} must be >= 0, got {value!r}")
    as_real4(name, value)
    return value


def angles_deg(name: str, value, *, largest: float = LARGEST) -> np.ndarray:
    """Input angles (deg) as a float64 array: TypeError unless an array of numbers (not bool,
    str or object), ValueError unless non-empty, 1-D (a scalar is not) and finite, within
    ``largest``."""
    return _angles(name, real_array(name, value), "deg", largest)


def angles_rad(name: str, value) -> np.ndarray:
    """Crank angles (rad) of a lower-level function as a 1-D float64 array (a scalar is one
    angle): otherwise the rules of ``angles_deg``, within LARGEST degrees."""
    return _angles(name, np.atleast_1d(real_array(name, value)), "rad", math.radians(LARGEST))


def _angles(name: str, values: np.ndarray, unit: str, largest: float) -> np.ndarray:
    if values.ndim != 1 or values.size == 0:
        raise ValueError(f"{name} must be a non-empty 1-D array of angles ({unit}), got shape {values.shape}")
    if not np.all(np.isfinite(values)):
        raise ValueError(f"{name} must be finite, got {values[~np.isfinite(values)][0]!r} at index "
                         f"{int(np.argmax(~np.isfinite(values)))}")
    if np.any(np.abs(values) > largest):
        raise ValueError(f"{name} is out of range (at most {largest:g} {unit} in magnitude)")
    return values


def finite_matrix(name: str, value, shape: tuple[int, int] | None = None) -> np.ndarray:
    """``value`` as a finite float64 matrix of the given shape (None: any non-empty square)."""
    wanted = f"a {shape[0]} x {shape[1]} matrix" if shape else "a non-empty square matrix"
    matrix = real_array(name, value)
    square = matrix.ndim == 2 and matrix.shape[0] == matrix.shape[1] and matrix.size > 0
    if (matrix.shape != shape) if shape else not square:
        raise ValueError(f"{name} must be {wanted}, got shape {matrix.shape}")
    if not np.all(np.isfinite(matrix)):
        raise ValueError(f"{name} must be finite")
    return matrix


def masses(name: str, value, count: int = 9) -> np.ndarray:
    """``count`` point masses (lb*s^2/in) as a float64 array: TypeError unless numbers,
    ValueError unless that many, finite and within LARGEST."""
    x = real_array(name, value).ravel()
    if x.shape != (count,) or not np.all(np.isfinite(x)) or np.any(np.abs(x) > LARGEST):
        raise ValueError(f"{name} must hold {count} finite masses (lb*s^2/in, at most {LARGEST:g} in magnitude)")
    return x


def qp_arguments(h, g, a, b, neq, max_variables: int, max_constraints: int):
    """QPROG's arguments (minimize g'x + x'Hx/2 s.t. a[:neq] x = b[:neq], a[neq:] x >= b[neq:])
    as finite float64 arrays: (h, g, a, b, neq); ValueError/TypeError otherwise."""
    g, h = real_array("g", g).ravel(), real_array("h", h)
    a = np.zeros((0, g.size)) if a is None else np.atleast_2d(real_array("a", a))
    b = np.zeros(0) if b is None else real_array("b", b).ravel()
    n = g.size
    if n == 0 or h.shape != (n, n):
        raise ValueError(f"h must be an n x n matrix and g an n-vector with n >= 1, got {h.shape} and {n}")
    if a.ndim != 2 or a.shape[1] != n or a.shape[0] != b.size:
        raise ValueError(f"a must be m x {n} with b of length m, got {a.shape} and {b.size}")
    neq = integer("neq", neq, 0, b.size)
    if n > max_variables or b.size > max_constraints:
        raise ValueError(f"QPROG holds at most {max_variables} variables and {max_constraints} constraints")
    for name, value in (("h", h), ("g", g), ("a", a), ("b", b)):
        if not np.all(np.isfinite(value)):
            raise ValueError(f"{name} must be finite")
    return h, g, a, b, neq


# Rahman (1996) and (1991): the slider crank's rules, shared by the legacy face and the port.

def slider_crank(a1, a2, a4, alpha4_deg, s1, rpm) -> dict:
    """The slider crank's inputs (in, deg, rpm) as floats (``parameters``): a1, a2 and rpm
    positive, the crank a1 and the rod a2 lengths from 1/LARGEST to LARGEST in as
    ``link_length`` (the joint forces divide by a1: at a1 = 5e-324 in they overflowed to NaN);
    every TypeError before any ValueError."""
    checked = parameters(dict(a1=a1, a2=a2, a4=a4, alpha4_deg=alpha4_deg, s1=s1, rpm=rpm),
                         positive=("a1", "a2", "rpm"))
    for name in ("a1", "a2"):
        link_length(name, checked[name])
    return checked


#: the slowest crank the CSSP engines take (rpm): 2**-126, the smallest normal REAL*4.  The
#: listing holds the speed in REAL*4 (slower, it is subnormal, with fewer digits, or 0: at
#: 1e-50 rpm the QP's Hessian was 0/0), and the objective's constants C1..C3 of eq. (4.2)
#: carry its fourth power (in double they underflow near 1e-78 rpm); register D164
CSSP_RPM_MIN = 2.0 ** -126


def cssp_speed(rpm: float) -> float:
    """The CSSP's crank speed (rpm; a positive float, ``slider_crank``): ValueError below
    ``CSSP_RPM_MIN``, naming the speed and the limit."""
    if rpm < CSSP_RPM_MIN:
        raise ValueError(f"rpm={rpm!r} is below the CSSP's slowest speed, 2**-126 = {CSSP_RPM_MIN:.6g} rpm (the "
                         "smallest normal number of the listing's REAL*4 speed; register D164)")
    return rpm


#: the largest condition number of the slider crank's velocity equations the CSSP engines
#: accept: 1/sqrt(u) for the unit roundoff u = 2**-24 of the listing's REAL*4 inputs.  Beyond
#: it one rounding of an input moves the tables by tens of per cent (register D150)
POSITION_CONDITION_LIMIT = 2.0 ** 12


def listing_condition(theta2, eta2, theta3) -> np.ndarray:
    """kappa at each of the listing's positions: the 2-norm condition number of its velocity
    equations VM DOT = VV (VM'VM is what its INVERSE inverts for the rates; DOT = theta2', theta3',
    eta2', eta3', s4'), in units of the rod length (A2 = 1: s4' per rod length, the length
    rows per rod length), so that it is dimensionless.  Angles in radians, arrays of one shape;
    NaN where a position is not finite (not computed)."""
    done = np.isfinite(theta2) & np.isfinite(eta2) & np.isfinite(theta3)
    t2, e2, t3 = (np.asarray(v, dtype=float)[done] for v in (theta2, eta2, theta3))
    z, o = np.zeros_like(t2), np.ones_like(t2)
    rows = [[-np.sin(e2), z, np.sin(t2) * np.cos(e2), z, z],
            [z, z, z, z, np.sin(t3)],
            [z, z, np.cos(t2), o, z],
            [np.cos(e2), z, np.sin(t2) * np.sin(e2), z, -np.cos(t3)],
            [np.cos(e2), o, np.sin(t2) * np.sin(e2), z, z],
            [z, z, -np.cos(t2), z, z]]
    kappa = np.full(done.shape, np.nan)
    kappa[done] = np.linalg.cond(np.stack([np.stack(row, axis=-1) for row in rows], axis=-2))
    return kappa


def refuse_singular_position(crank_deg, kappa) -> None:
    """SingularPositionError at the first position (in the order given) whose condition number
    ``kappa`` passes POSITION_CONDITION_LIMIT; NaN (a position not computed) is skipped."""
    crank_deg, kappa = np.ravel(crank_deg), np.ravel(kappa)
    beyond = kappa > POSITION_CONDITION_LIMIT
    if np.any(beyond):
        i = int(np.argmax(beyond))
        raise SingularPositionError("CSSP: singular position (the loop's velocity equations have a condition "
                                    f"number beyond {POSITION_CONDITION_LIMIT:g})", float(crank_deg[i]),
                                    condition=float(kappa[i]))
