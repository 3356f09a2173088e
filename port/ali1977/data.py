"""The example of Ali (1977) and the listings' constants.

Chapter IV's "Data for Numerical Example" (``EXAMPLE``: the links, the coupler angle, the
speed, the path point's weight and the section); the listings' pi, 22/7 as a REAL*4 literal
(``_pi`` gives it or numpy's, by the quirk D011), and the source listing's coupler angle of
101 deg (D012); ``expect``, the type check every function of the Ali ports makes of the
records it takes (Lengths, Section, Quirks).

Units: inch, pound-force, second; ``alpha_deg`` in degrees, ALP in radians, ``rpm`` in
rev/min, ``mass_lbf`` a weight in lbf.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .fourbar import Lengths
from .quirks import Quirks
from .structure import Section


#: The listings' PI=3.142857143 (22/7) as the REAL*4 literal holds it (D011).
PI_22_7 = float(np.float32(3.142857143))
#: The source listing's ALP=1.762782545 rad (101 deg) as REAL*4 holds it (D012).
ALP_SOURCE_LISTING = float(np.float32(1.762782545))


@dataclass(frozen=True)
class Example:
    """Chapter IV, "Data for Numerical Example" (and the listings' constants)."""
    lengths: Lengths = Lengths(10.0, 10.0, 30.0, 25.0, 30.0)
    alpha_deg: float = 60.0
    rpm: float = 300.0
    mass_lbf: float = 2.0
    section: Section = Section(0.1963495408, 10000000.0, 0.0030679615)


EXAMPLE = Example()


def _pi(quirks: Quirks) -> float:
    return PI_22_7 if quirks.pi_22_7 else np.pi


def expect(name: str, value, kind: type):
    """TypeError unless ``value`` is a ``kind`` (Lengths, Section, Quirks)."""
    if not isinstance(value, kind):
        raise TypeError(f"{name} must be a {kind.__name__}, got {type(value).__name__} {value!r}")
    return value
