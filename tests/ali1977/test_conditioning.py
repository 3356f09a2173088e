"""The K.E.D. engines know their conditioning: checked against 60-digit mpmath.

The reference (``harness/scenes/ali1977/exact.py``) evaluates the thesis's corrected Case I
equations in 60 digits, written from the geometry (circle intersection, the loop's derivatives,
the coupler's equilibrium solved as a linear system), not from the listing.  The corrected
port must agree with it at ordinary positions; near a toggle every engine's measured error
must stay under the bound it reports (``port.ali1977.conditioning``), a result returned without
a PrecisionWarning must keep half its digits, and at a toggle to working precision the engines
raise SingularPositionError (not AssemblyError: the loop closes there).
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from linkrepro import AssemblyError, PrecisionWarning, SingularPositionError
from linkrepro.errors import LinkreproWarning
from linkrepro.harness.scenes.ali1977 import conditioning as scene
from linkrepro.harness.scenes.ali1977 import exact
from linkrepro.legacy import ali1977
from linkrepro.port.ali1977 import case2, case3
from linkrepro.port.ali1977.case1 import cognate_case1, source_case1
from linkrepro.port.ali1977.conditioning import transmission_sine_squared
from linkrepro.port.ali1977.fourbar import Lengths
from linkrepro.port.ali1977.quirks import CORRECTED, PRINTED
from linkrepro.port.ali1977.structure import Section


def _vector(out, l2, i=0):
    return np.array([out["dx"][i], out["dy"][i], l2 * out["rot"][i]])


@st.composite
def crank_rockers(draw):
    """A crank-rocker (the crank the shortest link, s + l < p + q) and an input angle (deg)."""
    s = draw(st.floats(1.0, 10.0))
    p, q = s * draw(st.floats(1.5, 5.0)), s * draw(st.floats(1.5, 5.0))
    longest = max(p, q) + draw(st.floats(0.05, 0.95)) * (min(p, q) - s)
    l3, l4, l5 = draw(st.permutations([p, q, longest]))
    return Lengths(s, s * draw(st.floats(0.3, 3.0)), l3, l4, l5), draw(st.floats(-180.0, 360.0)), \
        draw(st.floats(0.0, 360.0))


@given(crank_rockers())
def test_corrected_port_equals_the_60_digit_reference(case):
    lengths, alp_deg, deg = case
    want = exact.case1_source(deg, lengths, alp_deg=alp_deg)
    out = source_case1(np.array([deg]), lengths, alp=math.radians(alp_deg), rpm=300.0, quirks=CORRECTED)
    truth = np.array([want["dx"], want["dy"], lengths.l2 * want["rot"]])
    error = np.linalg.norm(_vector(out, lengths.l2) - truth) / np.linalg.norm(truth)
    assert error <= out["error_bound"][0]
    assert error < 1e-11
    assert abs(out["xp"][0] - want["xp"]) < 1e-12 * lengths.l5 and abs(out["yp"][0] - want["yp"]) < 1e-12 * lengths.l5


def test_near_toggles_the_error_stays_under_the_bound_and_nothing_is_silent():
    """A fresh sample (not the scene's seed): 25 four-bars, 10 angles each near their toggles."""
    table = scene.summary(scene.measure(scene.sample(seed=7, count=25))).set_index("engine")
    assert (table["worst_error_over_bound"] <= 1.0).all(), table
    assert (table["silent_failures"] == 0).all(), table
    assert (table["warned"] > 0).all() and (table["refused"] > 0).all()      # the sample reaches both limits


def test_the_issues_two_points_warn_and_refuse():
    """sin(mu) = 3e-5 (the issue measured 1e-6 lost there): a PrecisionWarning; 1e-8 (100 %):
    SingularPositionError, with the angle."""
    lengths = Lengths(10.0, 10.0, 30.0, 25.0, 50.0)
    star = scene.toggle_angles(lengths)[0]

    def angle_for(sin_mu):                       # bisect the offset from the toggle (deg)
        lo, hi = 0.0, 1.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if transmission_sine_squared([star - mid], math.pi, 10.0, 30.0, 25.0, 50.0)[0] < sin_mu ** 2:
                lo = mid
            else:
                hi = mid
        return star - hi

    with pytest.warns(PrecisionWarning) as caught:
        out = source_case1(np.array([angle_for(3e-5)]), lengths, alp=1.0, quirks=CORRECTED)
    assert caught[0].message.relative_error < 1e-2
    want = exact.case1_source(angle_for(3e-5), lengths, alp_deg=math.degrees(1.0))
    truth = np.array([want["dx"], want["dy"], 10.0 * want["rot"]])
    assert np.linalg.norm(_vector(out, 10.0) - truth) / np.linalg.norm(truth) <= caught[0].message.relative_error
    with pytest.raises(SingularPositionError) as info:
        source_case1(np.array([0.0, angle_for(1e-8)]), lengths, alp=1.0, quirks=CORRECTED)
    assert info.value.angle_deg == angle_for(1e-8)


def test_an_exact_toggle_is_singular_in_the_corrected_port():
    """L1 + L5 = L3 + L4: coupler and follower in line at 180 deg.  The loop closes there; the
    corrected port said AssemblyError (a discriminant rounded below zero), now
    SingularPositionError at 180 deg, for the source and the cognate programs of every case."""
    lengths = Lengths(10.0, 10.0, 30.0, 25.0, 45.0)
    deg = np.array([170.0, 180.0])
    for program in (source_case1, cognate_case1, case2.case2_source, case2.case2_cognate):
        with pytest.raises(SingularPositionError) as info:
            program(deg, lengths, alp=1.0, quirks=CORRECTED)
        assert info.value.angle_deg == 180.0
    for program in (case3.case3_source, case3.case3_cognate):
        with pytest.raises(SingularPositionError):
            program(deg, 5, lengths, alp=1.0, quirks=CORRECTED)
    with pytest.raises(AssemblyError):                    # beyond the toggle: open
        source_case1(np.array([180.0]), Lengths(10.0, 10.0, 30.0, 25.0, 45.001), alp=1.0, quirks=CORRECTED)


def test_legacy_and_the_listing_port_warn_alike_near_a_toggle():
    """A four-bar whose toggle falls on the listing's own 180 deg (PI = 22/7), missed by a
    hair: both REAL*4 engines return, both warn, with the same condition."""
    l1, l3, l5 = 10.0, 30.0, 45.0
    t2 = 2.0 * ali1977.PI_PRINTED * 180.0 / 360.0
    reach = math.hypot(l1 * math.cos(t2) - l5, l1 * math.sin(t2))
    lengths = (l1, 10.0, l3, reach - l3 + 1e-9, l5)
    with pytest.warns(PrecisionWarning):
        legacy = ali1977.case1_source(*lengths, alp=1.0, rpm=300.0, step_deg=20.0)
    with pytest.warns(PrecisionWarning):
        port = source_case1(legacy["deg"], Lengths(*lengths), alp=1.0, rpm=300.0, quirks=PRINTED)
    np.testing.assert_array_equal(port["condition"], legacy["condition"])
    assert legacy["condition"][9] > 1e9 > legacy["condition"][0]


def test_the_published_example_is_quiet():
    """Every listing at its printed inputs, and the corrected port at the example: no warning of
    any kind (the bound counts the deflection's cancellation; the example's rows stay under half
    the REAL*4 digits)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", LinkreproWarning)
        outs = [getattr(ali1977, name)() for name in ("case1_source", "case1_cognate", "case2_source",
                                                      "case2_cognate", "case3_source", "case3_cognate")]
        source_case1(np.arange(0.0, 360.0, 20.0), quirks=CORRECTED)
    assert outs[0]["condition"].max() < 10.0
    assert max(out["error_bound"].max() for out in outs) < math.sqrt(2.0 ** -24)


def test_links_of_very_different_lengths_keep_the_bound_in_real4_too():
    """Links from 1e-3 to 600 in (a factor 6e5).  The REAL*4 storage's error does not grow with
    the links' spread (the calibration sample measured spreads to 3e6; the spread enters through
    the condition alone, D166): legacy answers, within the bound it states against the listing's
    equations in 60 digits; the corrected port in double warns (the condition passes half its
    digits) and is within its bound too."""
    links = Lengths(1e-3, 1.0, 600.0, 600.0, 600.0)
    section = Section(ali1977.CA_PRINTED, ali1977.ME_PRINTED, ali1977.MI_PRINTED)
    legacy = ali1977.case1_source(*vars(links).values(), alp=1.0, rpm=300.0, step_deg=60.0)
    with pytest.warns(PrecisionWarning):
        port = source_case1(legacy["deg"], links, alp=1.0, rpm=300.0, quirks=CORRECTED)
    for out, quirks in ((legacy, PRINTED), (port, CORRECTED)):
        for k, deg in enumerate(legacy["deg"]):
            want = exact.listing("case1_source", float(deg), links, 1.0, 300.0, 2.0, section, quirks)
            truth = np.array([want["dx"], want["dy"], want["rot"]])
            got = np.array([out["dx"][k], out["dy"][k], out["rot"][k]])
            assert np.linalg.norm(got - truth) / np.linalg.norm(truth) <= out["error_bound"][k]
