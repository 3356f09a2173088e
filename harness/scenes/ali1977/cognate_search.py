"""A systematic sign and frame search over the reconstructed cognate loads (D037).

Appendix C lost the page of the Case II cognate listing that forms the loads (statements
241-281) and Appendix D prints no cognate program: both cognate columns come from our
reconstructions.  Rather than guess at a sign, this module measures every variant of a
reconstruction's terms, alone and in pairs, and counts how many published cells each
reproduces (as ``readings.py`` does for the OCR readings), so that a reader can judge how
much the table chose.

A *term* is one signed quantity of the reconstruction (a load, an acceleration component
that feeds the loads, a column of beta2 the printed page builds): its variant is the term
with the opposite sign.  A *frame* variant changes a convention as a whole (the loads'
projection, the output frame, the point a mass sits at).  Each case is searched over the
reconstruction, every single variant and every pair: ``search("II")`` /
``search("III")``, or ``python -m linkrepro.harness.scenes.ali1977.cognate_search``.

Cells: the cognate columns dX, dY, X_new, Y_new of rows 0-340 (72 cells; row 360 repeats
row 0) within half a unit of the printed digit.  Units: inch.
"""
from __future__ import annotations

import itertools
import sys
from functools import lru_cache

import numpy as np
import pandas as pd

from ....port import libm
from ....port.ali1977.cognate import _cognate_linkage
from ....port.ali1977.data import EXAMPLE
from ....port.ali1977.case2 import COGNATE_LISTING as CASE2_COGNATE
from ....port.ali1977.case2 import DENSITY, beta2, case2_source
from ....port.ali1977.case3 import COGNATE_LISTING as CASE3_COGNATE
from ....port.ali1977.case3 import case3_source, node_weights
from ....port.ali1977.structure import GRAVITY_IN, GRAVITY_REAL4, deflection, flexibility
from ....port.real4 import store
from ...published_tables import PublishedTable

DEG = np.arange(0.0, 341.0, 20.0)
COLUMNS = ("cog_dx", "cog_dy", "cog_xnew", "cog_ynew")

#: Case II: the terms of the reconstructed page (legacy/src/ali1977_case2_cognate.f, D037)
CASE2_TERMS = {
    "P1": "the extender's mass at the path point, x (P1 = CM2*CXPA/GC)",
    "P2": "the extender's mass at the path point, y (Z2 = CM2*CYPA/GC)",
    "P4": "the crank's mass at the crank pin, along the crank",
    "P5": "the crank's mass at the crank pin, across the crank",
    "P6": "the follower's mass at the follower pin, along the follower",
    "P7": "the coupler's mass at the crank pin, along the coupler",
    "XAA": "the crank pin's acceleration, x (feeds P4, P5, P7 and the follower pin's)",
    "YAA": "the crank pin's acceleration, y",
    "W3": "the follower pin relative to the crank pin: the centripetal term CL3*COM3**2",
    "AL3": "the follower pin relative to the crank pin: the tangential term CL3*CALPH3",
    "U52": "the printed page's beta2 column 7 (P7 into f4): U(52)=DCOS(CT3-T2)",
    "U53": "the printed page's beta2 column 7 (P7 into f5): U(53)=DSIN(CT3-T2)",
}
CASE2_FRAMES = {
    "element-axes": "every joint load along its element's axes instead of the source listing's "
                    "components (D031 switched)",
    "P7-at-follower-pin": "the coupler's mass at the follower pin B' instead of the crank pin A'",
    "source-frame": "the deflection turned into the source's frame (D025 switched)",
}
#: Case III: the terms of the reconstruction (legacy/src/ali1977_case3_cognate.f, D037)
CASE3_TERMS = {
    "P1": "the extender's weight at the tip, x",
    "P2": "the extender's weight at the tip, y",
    "CRANK": "the path point's acceleration: the crank pin's term CL1*COM2**2",
    "W3": "the path point's acceleration: the extender's centripetal term CL2*COM3**2",
    "AL3": "the path point's acceleration: the extender's tangential term CL2*CALPH3",
    "U8": "beta's extender arm into f8, x against y: U(8)=-CL2*DSIN(CALP-CT3) (flipping U(16) "
          "instead is the same variant: a whole row's sign cancels in beta^T F beta, F diagonal)",
}
CASE3_FRAMES = {
    "source-frame": "the deflection turned into the source's frame (D025 switched)",
    "moment-row": "the geometric moment row instead of the listing's CG1, CH1, CI1 (D026 switched)",
    "area-bending": "the Case I listing's bending flexibility with the area (as Case I's cognate)",
}
CASES = {"II": (CASE2_TERMS, CASE2_FRAMES), "III": (CASE3_TERMS, CASE3_FRAMES)}


def _case2(flips: frozenset) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The Case II cognate reconstruction with the variants ``flips``: (dx, dy, rigid x, y)."""
    quirks = CASE2_COGNATE
    if "element-axes" in flips:
        quirks = quirks.only("joint_load_components", not quirks.joint_load_components)
    link = _cognate_linkage(DEG, EXAMPLE.lengths, None, EXAMPLE.rpm, quirks)
    mech, cog = link.path_point(), link.cognate
    sign = {term: -1.0 if term in flips else 1.0 for term in CASE2_TERMS}
    t2, om2 = link.t2, link.om2
    xaa = sign["XAA"] * -(cog.cl1 * libm.cos(t2) * om2 * om2)
    yaa = sign["YAA"] * -(cog.cl1 * libm.sin(t2) * om2 * om2)
    xba = xaa + sign["W3"] * (cog.cl3 * link.om3 * link.om3 * link.c3) + sign["AL3"] * (cog.cl3 * link.alph3 * link.s3)
    yba = yaa + sign["W3"] * (cog.cl3 * link.om3 * link.om3 * link.s3) - sign["AL3"] * (cog.cl3 * link.alph3 * link.c3)
    x7, y7 = (xba, yba) if "P7-at-follower-pin" in flips else (xaa, yaa)
    sec = EXAMPLE.section.as_listing_holds(True)
    dens = float(np.float32(DENSITY))
    m1, m2, m3, m4 = (dens * (sec.area * length) for length in (cog.cl1, cog.cl2, cog.cl3, cog.cl4))
    c2, s2, c3, s3, c4, s4 = link.c2, link.s2, link.c3, link.s3, link.c4, link.s4
    if quirks.joint_load_components:
        p5, p6, p7 = m1 * (yaa * s2 - xaa * c2), m4 * (yba * s4 - xba * c4), m3 * (y7 * s3 - x7 * c3)
    else:
        p5, p6, p7 = m1 * (-xaa * s2 + yaa * c2), m4 * (xba * c4 + yba * s4), m3 * (-x7 * c3 - y7 * s3)
    p7 = -p7               # the reconstruction's sign (D037), the one Table II prefers, against the statics (D145)
    g = GRAVITY_REAL4
    xpa, ypa = (mech.acc[:, k].astype(np.float32).astype(np.float64) for k in (0, 1))
    zero = np.zeros_like(xpa)
    loads = np.stack([sign["P1"] * ((m2 * xpa) / g), sign["P2"] * ((m2 * ypa) / g), zero,
                      sign["P4"] * ((m1 * (xaa * c2 + yaa * s2)) / g), sign["P5"] * (p5 / g),
                      sign["P6"] * (p6 / g), sign["P7"] * (p7 / g), zero], axis=1)
    if not quirks.inertia_sign:
        loads = -loads
    right = beta2(mech, quirks, cognate=True).astype(np.float64)
    right[:, 3, 6] *= sign["U52"]
    right[:, 4, 6] *= sign["U53"]
    flex = flexibility(cog.cl2, cog.cl1, cog.cl3, cog.cl4, sec, quirks)
    delta = deflection(mech.beta, flex, store(loads, True), quirks, right=right).astype(np.float64)
    dx, dy = _frame(delta, mech, quirks.cognate_frame != ("source-frame" in flips))
    src = case2_source(DEG)
    return dx, dy, src["xp"], src["yp"]


def _case3(flips: frozenset):
    """The Case III cognate reconstruction (the listing's tip node) with the variants ``flips``."""
    quirks = CASE3_COGNATE
    for frame, quirk in (("moment-row", "cognate_moment_row"), ("area-bending", "input_link_bending_area")):
        if frame in flips:
            quirks = quirks.only(quirk, not getattr(quirks, quirk))
    link = _cognate_linkage(DEG, EXAMPLE.lengths, None, EXAMPLE.rpm, quirks)
    mech, cog = link.path_point(), link.cognate
    sign = {term: -1.0 if term in flips else 1.0 for term in CASE3_TERMS}
    r, l1, om2, om3, al3 = cog.cl2, cog.cl1, link.om2, link.om3, link.alph3
    acc_x = sign["CRANK"] * -(l1 * om2 * om2 * link.c2) + sign["W3"] * (r * om3 * om3 * link.cg) \
        - sign["AL3"] * (r * al3 * link.sg)
    acc_y = sign["CRANK"] * -(l1 * om2 * om2 * link.s2) - sign["W3"] * (r * om3 * om3 * link.sg) \
        - sign["AL3"] * (r * al3 * link.cg)
    sec = EXAMPLE.section.as_listing_holds(True)
    weight = node_weights(np.array([r]), r, float(np.float32(DENSITY)), sec.area, quirks)[0]
    g = GRAVITY_REAL4 if quirks.real4_storage else GRAVITY_IN
    inertia = 1.0 if quirks.inertia_sign else -1.0
    loads = np.zeros((DEG.size, 3))
    loads[:, 0] = inertia * sign["P1"] * ((acc_x * weight) / g)
    loads[:, 1] = inertia * sign["P2"] * ((acc_y * weight) / g)
    beta = mech.beta.copy()
    beta[:, 7, 0] *= sign["U8"]
    flex = flexibility(cog.cl2, cog.cl1, cog.cl3, cog.cl4, sec, quirks)
    delta = deflection(beta, flex, store(loads, True), quirks).astype(np.float64)
    dx, dy = _frame(delta, mech, quirks.cognate_frame != ("source-frame" in flips))
    src = case3_source(DEG)
    return dx, dy, src["xp"], src["yp"]


def _frame(delta, mech, cognate_frame: bool):
    """dx, dy as the reconstruction prints them: in the cognate's frame, or turned (D025)."""
    dx, dy = delta[:, 0], delta[:, 1]
    if cognate_frame:
        return dx, dy
    c, s = libm.cos(mech.frame_angle), libm.sin(mech.frame_angle)
    return dx * c - dy * s, dx * s + dy * c


EVALUATE = {"II": _case2, "III": _case3}
TABLES = {"II": "ali1977_table2", "III": "ali1977_table3"}


def case_of(table: str) -> str | None:
    """The case whose cognate reconstruction a published table's cognate columns come from."""
    return next((case for case, name in TABLES.items() if name == table), None)


def columns(case: str, flips=()) -> pd.DataFrame:
    """The cognate columns of the variant ``flips`` (term and frame names) at rows 0-340."""
    terms, frames = CASES[case]
    unknown = set(flips) - set(terms) - set(frames)
    if unknown:
        raise ValueError(f"case {case}: no term or frame {sorted(unknown)}; known: {sorted(terms) + sorted(frames)}")
    with np.errstate(divide="ignore", invalid="ignore"):
        dx, dy, rigid_x, rigid_y = EVALUATE[case](frozenset(flips))
    return pd.DataFrame({"input_deg": DEG, "cog_dx": dx, "cog_dy": dy,
                         "cog_xnew": rigid_x + dx, "cog_ynew": rigid_y + dy})


@lru_cache(maxsize=None)
def _published(case: str) -> tuple[PublishedTable, np.ndarray]:
    """The case's published table and its rows at DEG (read once: a search compares hundreds
    of variants with it)."""
    published = PublishedTable.load(TABLES[case])
    rows = published.values["input_deg"].isin(DEG).to_numpy()
    rows.flags.writeable = False
    return published, rows


def matched(case: str, frame: pd.DataFrame) -> tuple[int, float]:
    """(cells of the cognate columns within half a unit of the printed digit, worst error)."""
    published, rows = _published(case)
    count, worst = 0, 0.0
    for col in COLUMNS:
        matched, err = published.matched(col, frame[col], rows)
        count, worst = count + matched, max(worst, err)
    return count, worst


def variants(case: str) -> list[tuple[str, ...]]:
    """The reconstruction (), every single variant and every pair, in a fixed order."""
    terms, frames = CASES[case]
    names = list(terms) + list(frames)
    return [()] + [(n,) for n in names] + list(itertools.combinations(names, 2))


def search(case: str) -> pd.DataFrame:
    """Every variant of ``variants(case)``: cells matched (of 72) and the worst error (in),
    best first; the reconstruction is the row with ``variant`` '(reconstruction)'."""
    rows = []
    for flips in variants(case):
        count, worst = matched(case, columns(case, flips))
        rows.append({"case": case, "variant": " + ".join(flips) or "(reconstruction)", "changes": len(flips),
                     "cells_matched": count, "cells": len(DEG) * len(COLUMNS), "max_err_in": worst})
    return pd.DataFrame(rows).sort_values(["cells_matched", "changes"], ascending=[False, True], kind="stable")


def as_markdown(found: pd.DataFrame, top: int = 8) -> str:
    """The search's summary for the report: how many variants, the reconstruction, the best."""
    lines = ["## Sign and frame search over the reconstructed cognate loads (D037)", "",
             "Every term of a reconstruction flipped alone and in pairs (`linkrepro.harness.scenes.ali1977.cognate_search`); "
             "cells: the cognate columns dX, dY, X_new, Y_new of rows 0-340 at the printed digit.", ""]
    for case, group in found.groupby("case", sort=False):
        base = group[group["variant"] == "(reconstruction)"].iloc[0]
        lines += [f"Case {case}: {len(group)} variants; the reconstruction {base.cells_matched}/{base.cells} "
                  f"(max err {base.max_err_in:.4f} in).", "",
                  "| variant | cells | max err (in) |", "|---|---|---|"]
        lines += [f"| {r.variant} | {r.cells_matched}/{r.cells} | {r.max_err_in:.4f} |"
                  for r in group.head(top).itertuples()]
        lines.append("")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    cases = (argv if argv is not None else sys.argv[1:]) or list(CASES)
    found = pd.concat([search(case) for case in cases])
    print(as_markdown(found, top=15))
    return 0


if __name__ == "__main__":
    sys.exit(main())


__all__ = ["CASE2_TERMS", "CASE2_FRAMES", "CASE3_TERMS", "CASE3_FRAMES", "case_of", "columns", "matched", "variants", "search",
           "as_markdown"]
