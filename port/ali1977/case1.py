"""Case I of Ali (1977): lumped mass at the path point, flexibility method.

delta = beta^T F beta P  (eq. 6), for the source four-bar (eqs. 9-18, ``source``) and its
crossed coupler cognate (eqs. 19-28, ``cognate``), with the 8x8 element flexibility F of
eq. (29) and the inertia load P of the path-point mass (``structure``): ``source_case1`` and
``cognate_case1`` are the two Case I listings, ``case1_deflection`` the deflection of any
path point's Mechanics.  The example's data are ``data``'s.

Units: inch, pound-force, second; ``alp`` in radians; input angles ``deg`` in
degrees; ``rpm`` in rev/min; ``mass_lbf`` a weight in lbf (mass = W/g,
g = 32.178*12 in/s^2 as the listings divide).  Deflections come out in inches,
rotations in radians.  Everything is vectorised over the input angles: the statements the
listings execute at each angle (positions, speeds, accelerations, beta) are loops over the
angles compiled by numba (``linkage``, "The listings' statements at each input angle"), the
matrices' products MPRD's (``real4.product``), the rest numpy.  A ``SourceLinkage`` or
``CognateLinkage`` is the four-bar's motion over the angles, once; ``path_point`` puts the
path point on it at any distance along the extender (Case III's nodes).

Arguments (every public function of the Ali ports): ``deg`` a non-empty 1-D array of
finite input angles (a scalar or 0-D array is refused like a 2-D one: ValueError; a
non-numeric dtype: TypeError); ``lengths`` a ``Lengths``, ``section`` a ``Section``,
``quirks`` a ``Quirks`` (TypeError otherwise); ``alp`` finite; ``rpm`` finite with
|rpm| <= 2**31 - 1; a weight or density finite, >= 0 and representable in REAL*4.
Section values and densities are the listings' REAL*4 literals: with ``real4_storage``
they are rounded to single precision first (ValueError if that gives 0 or infinity), so
``Section(a, e, i)`` here is the legacy build called with ``area=float32(a)``, ....
A linkage that cannot close raises AssemblyError at the first input angle where the
listing's test fails (source and cognate loops tested angle by angle); a result that is not
finite raises SingularPositionError at the first angle where the first non-finite quantity
(in the order the results are returned) is not finite: both as the legacy face does.  Every
program ends with ``Linkage.finish``: it adds ``condition`` and ``error_bound`` per input angle
(``conditioning``: the bound on the relative error of the deflection vector) and warns or
raises near a toggle, near a zero of the listing's own Cramer determinant (with the listing's
bugs) or where a deflection's terms cancel; ``run_*`` is a program before that check (the
legacy face checks its own results with it).

With ``quirks=PRINTED`` the formulas, the order of operations and the REAL*4
storage are the listings', and the results equal the legacy build's.  Each
quirk switched off removes one bug of the original (see ``quirks.py``).

``Section``, ``EXAMPLE``, ``Mechanics``, the linkages, ``source_mechanics`` and
``cognate_mechanics`` live in ``structure``, ``data``, ``linkage``, ``source`` and ``cognate``;
they are importable from here too (``__all__``), as before the split.
"""
from __future__ import annotations

import functools

import numpy as np

from ...checks import angles_deg, weight_lbf
from .. import libm
from .cognate import CognateLinkage, _cognate_linkage, cognate_linkage, cognate_mechanics
from .data import EXAMPLE, expect
from .fourbar import Lengths, check_finite
from .linkage import Linkage, ieee
from .quirks import CORRECTED, PRINTED, Quirks
from .source import SourceLinkage, _source_linkage, source_linkage, source_mechanics
from .structure import Mechanics, Section, deflection, flexibility, inertia_load, magnitude

__all__ = ["Section", "EXAMPLE", "Mechanics", "Linkage", "SourceLinkage", "CognateLinkage", "source_linkage",
           "cognate_linkage", "source_mechanics", "cognate_mechanics", "case1_deflection", "source_case1",
           "cognate_case1", "PRINTED", "CORRECTED", "Quirks"]


def case1_deflection(mech: Mechanics, mass_lbf: float, section: Section, quirks: Quirks):
    """dx, dy (in, in the source frame unless D025 is on) and rot (rad) of the path point;
    SingularPositionError where they are not finite."""
    expect("mech", mech, Mechanics)
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    dx, dy, rot, _ = _case1_deflection(mech, mass_lbf, section, quirks)
    if "linkage" in mech.extra:
        check_finite(mech.extra["linkage"].deg, "case I", dx=dx, dy=dy, rot=rot)
    return dx, dy, rot


@ieee
def _case1_deflection(mech: Mechanics, mass_lbf: float, section: Section, quirks: Quirks):
    """case1_deflection of a checked weight and section, and the deflection's terms' size
    (``structure.magnitude``, (N, 3))."""
    flex = flexibility(*mech.flex_lengths, section.as_listing_holds(quirks.real4_storage), quirks)
    load = inertia_load(mech.acc, mass_lbf, quirks)
    delta = deflection(mech.beta, flex, load, quirks)
    dx, dy = delta[:, 0].astype(np.float64), delta[:, 1].astype(np.float64)
    if mech.frame_angle and not quirks.cognate_frame:       # D025: into the source frame
        turn = mech.frame_angle
        dx, dy = dx * libm.cos(turn) - dy * libm.sin(turn), dx * libm.sin(turn) + dy * libm.cos(turn)
    return dx, dy, delta[:, 2].astype(np.float64), magnitude(mech.beta, flex, load)


def source_case1(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                 rpm: float | None = None, mass_lbf: float = 2.0,
                 section: Section = EXAMPLE.section, quirks: Quirks = PRINTED) -> dict:
    """Case I, source four-bar: coupler point ``xp, yp`` (in), its elastic deflection
    ``dx, dy`` (in) and rotation ``rot`` (rad) over ``deg``; see source_mechanics."""
    out, finish = run_source_case1(angles_deg("deg", deg), lengths, alp, rpm, mass_lbf, section, quirks)
    return finish(out, "case I source")


def run_source_case1(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float | None, mass_lbf: float,
                     section: Section, quirks: Quirks):
    """source_case1 of checked angles ``deg``, before its checks: the results, and the checks
    (``Linkage.finish`` with this run's poles and deflection size: call it with the results to
    check, the legacy face's or these, and the program's name: a SingularPositionError where a
    result is not finite, then the precision rule)."""
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    mech = _source_linkage(deg, lengths, alp, rpm, quirks, "INTEGER").path_point(lengths.l2)
    dx, dy, rot, size = _case1_deflection(mech, mass_lbf, section, quirks)
    out = {"xp": mech.xp, "yp": mech.yp, "dx": dx, "dy": dy, "rot": rot}
    link = mech.extra["linkage"]
    return out, functools.partial(link.finish, rho=link.pole_distance(mech), size=size, extender=lengths.l2)


def cognate_case1(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                  rpm: float = EXAMPLE.rpm, mass_lbf: float = 2.0,
                  section: Section = EXAMPLE.section, quirks: Quirks = PRINTED) -> dict:
    """Case I, crossed coupler cognate: ``xp, yp`` (the source's coupler point as the
    cognate listing computes it), ``cxp, cyp`` (the cognate's, in the source frame),
    ``dx, dy`` (in) and ``rot`` (rad) over ``deg``; see cognate_mechanics."""
    out, finish = run_cognate_case1(angles_deg("deg", deg), lengths, alp, rpm, mass_lbf, section, quirks)
    return finish(out, "case I cognate")


def run_cognate_case1(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float, mass_lbf: float,
                      section: Section, quirks: Quirks, warn_beta: bool = True):
    """cognate_case1 of checked angles ``deg``, before its precision check, as run_source_case1;
    ``warn_beta``: warn D141 (the legacy face warns it itself)."""
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    mech = _cognate_linkage(deg, lengths, alp, rpm, quirks, warn_beta).path_point()
    dx, dy, rot, size = _case1_deflection(mech, mass_lbf, section, quirks)
    out = {"xp": mech.extra["xp"], "yp": mech.extra["yp"], "cxp": mech.extra["cxp"],
           "cyp": mech.extra["cyp"], "dx": dx, "dy": dy, "rot": rot}
    link = mech.extra["linkage"]
    return out, functools.partial(link.finish, rho=link.pole_distance(mech), size=size,
                                  extender=mech.extra["cognate"].cl2)
