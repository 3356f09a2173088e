"""The links as an elastic structure: Ali's (1977) flexibility method, delta = beta^T F beta P.

``Section`` the links' uniform cross-section; ``flexibility`` the 8x8 element flexibility F
of eq. (29); ``inertia_load`` the system forces P of a point mass (mass = W/g, g as the
listings write it, ``GRAVITY_IN``, or as Cases II and III compute it in REAL*4,
``GRAVITY_REAL4``); ``deflection`` delta = beta^T F beta P (eq. 6; beta1^T F beta2 P in Case
II, eq. 32) in the listings' MPRD order and precision (``real4.product``); ``Mechanics``
what a mechanism hands to them: its path point's position, acceleration and force
transformation beta, and the lengths of F.  Cases I-III build on these, for the source
four-bar and for its cognate alike; nothing here computes a linkage's motion.

Units: inch, pound-force, second (areas in^2, moduli psi, second moments in^4); deflections
in inches, rotations in radians.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from ...checks import as_real4, parameter
from .quirks import Quirks
from ..real4 import product, store


#: g in in/s^2 as the listings write it (12.0*32.178), and as Cases II and III compute it
#: (GC=32.178*12.0 in REAL*4).
GRAVITY_IN = 12.0 * 32.178
GRAVITY_REAL4 = float(np.float32(32.178) * np.float32(12.0))


@dataclass(frozen=True)
class Section:
    """Uniform cross-section of every link: area (in^2), Young's modulus (psi),
    second moment of area (in^4); each positive and within what the listings' REAL*4 literals
    hold (about 1.4e-45 to 3.4e38: a subnormal double modulus divided F by zero)."""
    area: float
    modulus: float
    inertia: float

    def __post_init__(self):
        for name in ("area", "modulus", "inertia"):     # positive, and what a REAL*4 literal can hold
            value = parameter(f"section {name}", getattr(self, name), positive=True, largest=None)
            as_real4(f"section {name}", value, positive=True)
            object.__setattr__(self, name, value)

    @functools.lru_cache(maxsize=256)      # a pure function of the (immutable) section, asked for on every call
    def as_listing_holds(self, real4: bool) -> "Section":
        """The listing assigns REAL*4 literals to its DOUBLE section variables (ValueError if
        a value is 0 or infinite in single precision)."""
        if not real4:
            return self
        return Section(*(as_real4(f"section {name}", getattr(self, name), positive=True)
                         for name in ("area", "modulus", "inertia")))


def inertia_load(acc, mass_lbf, quirks: Quirks):
    """System forces P1, P2, P3 (lbf, last axis) of a point mass of weight ``mass_lbf`` with
    acceleration ``acc`` (.., 2) in/s^2; P3 = 0 (no rotary inertia).

    The listings store the acceleration and the force in REAL*4 and use +m*a;
    the inertia (d'Alembert) force is -m*a (D018).
    """
    real4 = quirks.real4_storage
    sign = 1.0 if quirks.inertia_sign else -1.0
    acc = store(acc, real4)
    if real4:
        m, g = np.float32(mass_lbf), np.float32(12.0) * np.float32(32.178)
    else:
        m, g = float(mass_lbf), GRAVITY_IN
    load = np.zeros(acc.shape[:-1] + (3,), acc.dtype)
    load[..., :2] = sign * (acc * m / g)
    return load


def flexibility(l_ext, l_in, l_cpl, l_fol, section: Section, quirks: Quirks,
                modulus_first: bool = False) -> np.ndarray:
    """Element flexibility F (8x8) of eq. (29): extender (axial; bending 2x2),
    input link (axial, bending), follower (axial), coupler (axial, end moment).

    ``l_ext`` may be an array of extender lengths (F then has its shape in front).
    ``modulus_first``: the input link's bending term written (L1*L1*L1)/(3.0*CE*CI), as
    the Case III source listing has it, instead of 3.0*CA*ME (or 3.0*CMI*CME): the same
    number in exact arithmetic, the listing's own rounding here."""
    ca, me, mi = section.area, section.modulus, section.inertia
    f = np.zeros(np.shape(l_ext) + (8, 8))
    f[..., 0, 0] = l_ext / (ca * me)
    f[..., 1, 1] = (l_ext * l_ext * l_ext) / (3.0 * me * mi)
    f[..., 2, 1] = f[..., 1, 2] = (l_ext * l_ext) / (2.0 * me * mi)
    f[..., 2, 2] = l_ext / (me * mi)
    f[..., 3, 3] = l_in / (ca * me)
    bending = ca if quirks.input_link_bending_area else mi          # D016
    f[..., 4, 4] = (l_in * l_in * l_in) / ((3.0 * me * bending) if modulus_first else (3.0 * bending * me))
    f[..., 5, 5] = l_fol / (ca * me)
    f[..., 6, 6] = l_cpl / (ca * me)
    f[..., 7, 7] = l_cpl / (3.0 * me * mi)
    return store(f, quirks.real4_storage)


def deflection(beta: np.ndarray, flex: np.ndarray, load: np.ndarray, quirks: Quirks,
               right: np.ndarray | None = None) -> np.ndarray:
    """delta = beta^T F right P (right = beta unless given: Case II's beta2), per angle;
    in the listings' MPRD order and precision."""
    real4 = quirks.real4_storage
    beta = store(beta, real4)
    right = beta if right is None else store(right, real4)
    left = product(np.swapaxes(beta, -1, -2), flex, real4)       # CALL GMTRA; MPRD(A,B,R,3,8,..,8)
    left = product(left, right, real4)                           # MPRD(A,B,R,3,8,..,3 or 8)
    return product(left, load[..., :, None], real4)[..., 0]      # MPRD(A,B,R,3,3 or 8,..,1)


def magnitude(beta: np.ndarray, flex: np.ndarray, load: np.ndarray, right: np.ndarray | None = None) -> np.ndarray:
    """|beta|^T |F| |right| |P| (.., 3), in double: the size of the deflection delta = beta^T F
    right P before its terms cancel, the scale of the rounding error of every product and stored
    entry (``conditioning.cancellation``)."""
    beta = np.abs(np.asarray(beta, dtype=np.float64))
    right = beta if right is None else np.abs(np.asarray(right, dtype=np.float64))
    size = np.matmul(np.matmul(np.swapaxes(beta, -1, -2), np.abs(np.asarray(flex, dtype=np.float64))), right)
    return np.matmul(size, np.abs(np.asarray(load, dtype=np.float64))[..., :, None])[..., 0]


@dataclass(frozen=True)
class Mechanics:
    """One mechanism's Case I state over the input angles, in its own frame.

    ``acc`` (N, 2) is the path point's acceleration (in/s^2) as the listing forms
    it; ``beta`` (N, 8, 3) the force-transformation matrix; ``flex_lengths`` the
    (extender, input, coupler, follower) lengths of F; ``frame_angle`` (rad) turns
    the mechanism's frame into the source's (0 for the source).  For several path
    points at once (``path_point`` of an (n, 1) array of extender lengths) every array
    has the points' axis in front: (n, N), (n, N, 2), (n, N, 8, 3).
    """
    xp: np.ndarray
    yp: np.ndarray
    acc: np.ndarray
    beta: np.ndarray
    flex_lengths: tuple
    frame_angle: float = 0.0
    extra: dict = field(default_factory=dict)
