"""The crossed cognate's geometry against Roberts-Chebyshev, for every coupler triangle.

Independent computation: the source four-bar is assembled here from its links alone (the
crank pin A on its circle, the follower pin B where the coupler's and the follower's circles
meet, in both assembly branches, the coupler point P = A + (B - A) (l2/l3) e^{i alp}).  By
Roberts-Chebyshev, with z = (P - A)/(B - A), the cognate that shares the follower's pivot O_B
is pivoted at O_C = z l5; its follower pin is B3 = O_B + (P - B), its crank pin C3 = P + (O_B -
B) z, and its coupler point is P itself at every input angle.  The corrected port must give
that point, those link lengths and that pivot (its frame turned by -beta) for any triangle:
alp in every quadrant, obtuse at A or at B, or nearly flat.

The port always assembles the source in one branch (sin(t4 - t3) > 0).  The other branch of
the linkage (L, alp) at input angle t2 is the mirror image, in the ground line, of the port's
branch of (L, -alp) at -t2; each example checks both branches that way.

The listing's own BETA (register D141) keeps the turn only for 0 <= alp <= 180 deg with a
triangle not obtuse at B; legacy and the port with the listing's bugs keep that, and warn.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from linkrepro import ListingBugWarning, SingularPositionError
from linkrepro.legacy import ali1977
from linkrepro.port.ali1977 import case2, case3
from linkrepro.port.ali1977.case1 import cognate_case1, source_case1
from linkrepro.port.ali1977.cognate import cognate_mechanics
from linkrepro.port.ali1977.fourbar import Lengths
from linkrepro.port.ali1977.quirks import CORRECTED, PRINTED

#: the four-bar's own links (in), a crank-rocker: l1 + l5 <= l3 + l4 with l1 shortest
FRAMES = [(10.0, 30.0, 25.0, 30.0), (2.0, 7.0, 9.0, 6.0), (1.0, 40.0, 25.0, 30.0)]


def roberts(l1, l2, l3, l4, l5, alp, t2, branch):
    """Source pins A, B, coupler point P and the Roberts cognate's O_C, B3, C3 (complex, in),
    in assembly ``branch`` +1 or -1, or None where the loop cannot close."""
    a, ob = l1 * np.exp(1j * t2), complex(l5, 0.0)
    d = abs(ob - a)
    along = (l3 * l3 - l4 * l4 + d * d) / (2.0 * d)
    if l3 * l3 - along * along < 1e-6 * l3 * l3:               # at or too near a toggle
        return None
    across = math.sqrt(l3 * l3 - along * along)
    u = (ob - a) / d
    b = a + u * (along + branch * 1j * across)
    z = (l2 / l3) * np.exp(1j * alp)
    p = a + (b - a) * z
    return {"A": a, "B": b, "P": p, "OC": z * l5, "B3": ob + (p - b), "C3": p + (ob - b) * z}


@st.composite
def triangles(draw):
    """Coupler triangles of every shape on one of FRAMES: l2 from a tenth to four times l3,
    alp anywhere in (-180, 360) deg (both senses, obtuse at A and at B, nearly flat)."""
    l1, l3, l4, l5 = draw(st.sampled_from(FRAMES))
    l2 = l3 * draw(st.floats(0.1, 4.0))
    alp = math.radians(draw(st.one_of(st.floats(-179.0, 359.0), st.sampled_from([-90.0, 0.5, 90.0, 179.5, 270.0]))))
    return Lengths(l1, l2, l3, l4, l5), alp


DEG = np.arange(0.0, 360.0, 15.0)


def _check_branch(lengths, alp, deg, mirror):
    """Run the corrected port on (lengths, alp) at ``deg`` and compare with Roberts-Chebyshev
    in whichever branch its source took (``mirror``: the port ran the mirrored linkage, so
    compare with the mirror image of the other branch)."""
    l1, l2, l3, l4, l5 = (lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5)
    sign = -1.0 if mirror else 1.0
    want = [roberts(l1, l2, l3, l4, l5, sign * alp, sign * math.radians(t), branch=-1 if mirror else 1)
            for t in deg]
    keep = np.array([w is not None for w in want])
    if keep.sum() < 3:
        return 0
    deg, want = deg[keep], [w for w in want if w is not None]
    conj = np.conj if mirror else (lambda x: x)
    scale = max(l2, l3, l5)
    src = source_case1(deg, lengths, alp=alp, rpm=300.0, quirks=CORRECTED)
    cog = cognate_case1(deg, lengths, alp=alp, rpm=300.0, quirks=CORRECTED)
    p = np.array([conj(w["P"]) for w in want])
    np.testing.assert_allclose(src["xp"] + 1j * src["yp"], p, atol=1e-9 * scale)          # the same branch
    np.testing.assert_allclose(cog["cxp"] + 1j * cog["cyp"], p, atol=1e-9 * scale)        # coincidence
    mech = cognate_mechanics(deg, lengths, alp=alp, rpm=300.0, quirks=CORRECTED)
    c = mech.extra["cognate"]
    w0 = want[0]
    ob = complex(l5, 0.0)
    lengths_roberts = [abs(w0["C3"] - w0["OC"]), abs(w0["C3"] - w0["P"]), abs(w0["C3"] - w0["B3"]),
                       abs(w0["B3"] - ob), abs(w0["OC"] - ob)]
    np.testing.assert_allclose([c.cl1, c.cl2, c.cl3, c.cl4, c.cl5], lengths_roberts, rtol=1e-9)
    pivot = ob - c.cl5 * np.exp(-1j * c.beta)           # the cognate frame's origin, turned into place
    np.testing.assert_allclose(pivot, conj(w0["OC"]), atol=1e-9 * scale)
    return len(deg)


@pytest.mark.filterwarnings("ignore::linkrepro.PrecisionWarning")      # nearly flat triangles say so
@given(triangles())
def test_corrected_cognate_is_roberts_chebyshev_for_every_triangle_and_both_branches(case):
    lengths, alp = case
    if abs(lengths.l2 * np.exp(1j * alp) - lengths.l3) < 1e-9 * lengths.l3:     # P on B: no cognate (CL4 = 0)
        with pytest.raises(SingularPositionError):
            cognate_case1(DEG, lengths, alp=alp, rpm=300.0, quirks=CORRECTED)
        return
    assert _check_branch(lengths, alp, DEG, mirror=False) >= 3
    _check_branch(lengths, -alp, -DEG % 360.0, mirror=True)


@pytest.mark.parametrize("alp_deg, lengths", [(-60.0, (10, 10, 30, 25, 30)), (200.0, (10, 10, 30, 25, 30)),
                                              (20.0, (10, 40, 30, 25, 30)), (60.0, (10, 10, 30, 25, 30))])
@pytest.mark.parametrize("program", [case2.case2_cognate, case3.case3_cognate])
def test_cases_2_and_3_inherit_the_corrected_cognate(program, alp_deg, lengths):
    out = program(DEG, lengths=Lengths(*lengths), alp=math.radians(alp_deg), quirks=CORRECTED)
    scale = max(lengths)
    assert np.hypot(out["cxp"] - out["xp"], out["cyp"] - out["yp"]).max() < 1e-12 * scale


# --- the listing's BETA (D141): kept where the listing is run, and signalled --------------

BITTEN = [(-60.0, (10, 10, 30, 25, 30)), (200.0, (10, 10, 30, 25, 30)), (300.0, (10, 10, 30, 25, 30)),
          (20.0, (10, 40, 30, 25, 30))]
SPARED = [(60.0, (10, 10, 30, 25, 30)), (150.0, (10, 10, 30, 25, 30)), (80.0, (10, 40, 30, 25, 30))]


def _gap(out) -> float:
    return float(np.hypot(out["cxp"] - out["xp"], out["cyp"] - out["yp"]).max())


@pytest.mark.parametrize("alp_deg, lengths", BITTEN)
def test_where_the_listing_beta_is_wrong_legacy_and_printed_port_leave_the_curve_and_warn(alp_deg, lengths):
    alp = math.radians(alp_deg)
    with pytest.warns(ListingBugWarning, match="D141") as caught:
        legacy = ali1977.case1_cognate(*lengths, alp=alp, rpm=300.0)
    assert {w.message.entry for w in caught} == {"D141"}
    with pytest.warns(ListingBugWarning, match="D141"):
        port = cognate_case1(DEG, Lengths(*lengths), alp=alp, rpm=300.0, quirks=PRINTED)
    assert _gap(legacy) > 1.0 and _gap(port) > 1.0          # inches off the source's coupler point


@pytest.mark.parametrize("alp_deg, lengths", SPARED)
def test_where_the_listing_beta_is_right_nothing_is_said_and_the_points_coincide(alp_deg, lengths):
    alp = math.radians(alp_deg)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ListingBugWarning)
        legacy = ali1977.case1_cognate(*lengths, alp=alp, rpm=300.0)
        port = cognate_case1(DEG, Lengths(*lengths), alp=alp, rpm=300.0, quirks=PRINTED)
    assert _gap(legacy) < 1e-5 and _gap(port) < 1e-5        # REAL*4 storage of the rotated point


def test_the_corrected_port_does_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error", ListingBugWarning)
        cognate_case1(DEG, Lengths(10, 10, 30, 25, 30), alp=-1.0, rpm=300.0, quirks=CORRECTED)
