"""The K.E.D. listings' own poles and the error bound, checked against 60-digit mpmath.

The listings' bugs D014, D015 (the source listings' G1, I1) and D026 (the cognate listings'
moment row) make the Cramer determinant R1 of the pin forces vanish where the mechanism has no
toggle.  Legacy and the port with the listing's bugs must see it: near such a zero a
ListingBugWarning naming the bug, at it (where no digit is left) a SingularPositionError; every
value they return lies within the bound they state (``error_bound``), against the listing's own
equations evaluated in 60 digits (``harness/scenes/ali1977/exact.py``, written from the
listings, not from the port's kernels).  The poles are found by bisection in the coupler angle
(``harness/scenes/ali1977/poles.py``) on geometries other than the issue's reproducer.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from linkrepro import ListingBugWarning, PrecisionWarning, SingularPositionError
from linkrepro.errors import LinkreproWarning
from linkrepro.harness.scenes.ali1977 import calibration, exact, poles
from linkrepro.legacy import ali1977
from linkrepro.port.ali1977 import case1, case2, case3
from linkrepro.port.ali1977.conditioning import POLE_NEAR, REAL4_UNIT
from linkrepro.port.ali1977.fourbar import Lengths
from linkrepro.port.ali1977.quirks import CORRECTED
from linkrepro.port.ali1977.structure import Section

SECTION = Section(ali1977.CA_PRINTED, ali1977.ME_PRINTED, ali1977.MI_PRINTED)
PORT = {"case1_source": case1.source_case1, "case1_cognate": case1.cognate_case1,
        "case2_source": case2.case2_source, "case2_cognate": case2.case2_cognate,
        "case3_source": case3.case3_source, "case3_cognate": case3.case3_cognate}
#: (program, lengths, the grid angle the pole is put at, the bugs it names), none the reproducer's
POLES = [("case1_source", (10.0, 12.0, 30.0, 25.0, 30.0), 100.0, "D014, D015"),
         ("case2_source", (8.0, 20.0, 26.0, 30.0, 28.0), 300.0, "D014, D015"),
         ("case3_source", (10.0, 25.0, 30.0, 25.0, 30.0), 100.0, "D014"),
         ("case1_cognate", (5.0, 9.0, 22.0, 18.0, 24.0), 200.0, "D026")]
#: from the pole: 0, a few ulps, and on to where R1 is a few hundredths of its terms, on both sides
ULPS = [0, 1, -1, 7, -7, 2**12, -2**12, 2**24, -2**24, 2**36, -2**36, 2**44, -2**44, 2**48, -2**48, 2**50, -2**50]
STEP = 100.0


def _weight(program: str) -> dict:
    return {"mass_lbf": 2.0} if program.startswith("case1") else {"density": float(np.float32(0.098))}


def _run(engine: str, program: str, lengths: Lengths, alp: float):
    """(result or None, error or None, warnings) of one engine over the grid 0, 100, 200, 300."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", LinkreproWarning)
        try:
            if engine == "legacy":
                out = getattr(ali1977, program)(*vars(lengths).values(), alp=alp, rpm=300.0, step_deg=STEP,
                                                **_weight(program))
            else:
                out = PORT[program](np.arange(0.0, 360.0, STEP), lengths=lengths, alp=alp, rpm=300.0, section=SECTION,
                                    quirks=poles.LISTINGS[program][0], **_weight(program))
        except SingularPositionError as exc:
            return None, exc, caught
    return out, None, caught


def _assert_within_bound(program, lengths, alp, out):
    """Every returned deflection vector (and the source's coupler point) against 60 digits."""
    weight = next(iter(_weight(program).values()))
    for k, deg in enumerate(out["deg"] if "deg" in out else np.arange(0.0, 360.0, STEP)):
        ref = exact.listing(program, float(deg), lengths, alp, 300.0, weight, SECTION, poles.LISTINGS[program][0])
        truth = np.array([ref["dx"], ref["dy"], ref["extender"] * ref["rot"]])
        got = np.array([out["dx"][k], out["dy"][k], ref["extender"] * out["rot"][k]])
        error = np.linalg.norm(got - truth) / np.linalg.norm(truth)
        assert error <= out["error_bound"][k], (program, deg, error, out["error_bound"][k])
        if program.endswith("source"):
            assert abs(out["xp"][k] - ref["xp"]) + abs(out["yp"][k] - ref["yp"]) < 1e-12 * sum(vars(lengths).values())


@pytest.mark.parametrize("program, links, at, bugs", POLES)
@pytest.mark.parametrize("engine", ["legacy", "port"])
def test_approaching_a_listing_pole_from_both_sides(engine, program, links, at, bugs):
    lengths = Lengths(*links)
    (pole,) = [a for a in poles.pole_alps(program, at, lengths) if math.sin(a) > 0 or program.endswith("source")][:1]
    said = set()
    for ulps in ULPS:
        alp = poles.nudged(pole, ulps) if abs(ulps) < 8 else pole + ulps * float(np.spacing(pole))
        rho = min(exact.listing(program, at, lengths, alp, 300.0, 1.0, SECTION, poles.LISTINGS[program][0])["rho"])
        out, error, caught = _run(engine, program, lengths, alp)
        bug_warnings = [w.message for w in caught if issubclass(w.category, ListingBugWarning)
                        and w.message.entry != "D141"]
        if error is not None:                     # only where no digit is left, at the pole's angle
            assert error.angle_deg == at and bugs.split(",")[0] in str(error) and rho < 1e-12, (ulps, rho, error)
            said.add("raised")
            continue
        _assert_within_bound(program, lengths, alp, out)
        if rho < POLE_NEAR / 10:                  # near the pole: the bug is named, with the angle
            assert bug_warnings and bug_warnings[0].entry == bugs and bug_warnings[0].angle_deg == at, (ulps, rho)
            said.add("warned")
        elif rho > 10 * POLE_NEAR:
            assert not bug_warnings, (ulps, rho)
            said.add("quiet")
    assert said == {"raised", "warned", "quiet"}


@pytest.mark.parametrize("program, links, at, bugs", POLES)
def test_the_corrected_engines_do_not_warn_for_the_listings_bug(program, links, at, bugs):
    lengths = Lengths(*links)
    pole = poles.pole_alps(program, at, lengths)[0]
    with warnings.catch_warnings():
        warnings.simplefilter("error", ListingBugWarning)
        out = PORT[program](np.array([at]), lengths=lengths, alp=pole, rpm=300.0, section=SECTION, quirks=CORRECTED,
                            **_weight(program))
    ref = exact.listing(program, at, lengths, pole, 300.0, next(iter(_weight(program).values())), SECTION, CORRECTED)
    truth = np.array([ref["dx"], ref["dy"], ref["extender"] * ref["rot"]])
    got = np.array([out["dx"][0], out["dy"][0], ref["extender"] * out["rot"][0]])
    assert np.linalg.norm(got - truth) / np.linalg.norm(truth) <= out["error_bound"][0]


def test_the_issues_reproducer_raises_naming_the_bug():
    """R1 is 5e-18 of its terms at 80 deg; legacy returned dx = -2.9e26 in, 60 digits give -1.0e30."""
    with pytest.raises(SingularPositionError, match="D014") as info:
        ali1977.case1_source(2, 7, 7, 9, 6, alp=-0.8506908478996017, rpm=300)
    assert info.value.angle_deg == 80.0
    ref = exact.listing("case1_source", 80.0, Lengths(2, 7, 7, 9, 6), -0.8506908478996017, 300.0, 2.0, SECTION,
                        poles.LISTINGS["case1_source"][0])
    assert abs(ref["dx"]) > 1e29 and min(ref["rho"]) < 1e-16


def test_a_deflection_whose_terms_cancel_warns_and_keeps_its_bound():
    """A draw of the calibration sample (Case II source): at 270 deg the deflection is 2263 times
    smaller than its terms; the REAL*4 error (9e-5 relative) was 18 times the bound that ignored
    the cancellation, silently.  Now the bound counts it and the engine says so."""
    links = Lengths(5.587986450143678, 18.88987802760107, 13.794665641771132, 14.440086645291222,
                    17.228018342942597)
    alp, density = -2.040844435210018, 0.2408245950937271
    section = Section(0.593715488910675, 3154218.75, 0.003154368605464697)
    with pytest.warns(PrecisionWarning, match="cancel") as caught:
        out = ali1977.case2_source(*vars(links).values(), alp=alp, rpm=346.0, density=density, area=section.area,
                                   modulus=section.modulus, inertia=section.inertia, step_deg=45.0)
    k = list(out["deg"]).index(270.0)
    assert caught[0].message.angle_deg == 270.0
    ref = exact.listing("case2_source", 270.0, links, alp, 346.0, density, section, poles.LISTINGS["case2_source"][0])
    truth = np.array([ref["dx"], ref["dy"], ref["extender"] * ref["rot"]])
    error = np.linalg.norm(np.array([out["dx"][k], out["dy"][k], ref["extender"] * out["rot"][k]]) - truth) / \
        np.linalg.norm(truth)
    assert math.sqrt(REAL4_UNIT) / 10 < error <= out["error_bound"][k]
    assert ref["magnitude"] / np.linalg.norm(truth) > 1000.0


def test_at_the_listings_beta_edge_rounding_decides_and_d141_warns():
    """l2, l3 = 40, 30 in, alp one ulp below acos(3/4): l2 cos(alp) = l3 in double, and the
    listing's CBTA is within its rounding of 0, so rounding picks BETA's quadrant (D165): legacy's
    deflection at 90 deg is 40 times its length off the listing's equations in 60 digits.  D141
    warns there now (it did not: l2 cos(alp) > l3 is false in double)."""
    lengths = Lengths(10.0, 40.0, 30.0, 25.0, 30.0)
    alp = float(np.nextafter(math.acos(0.75), 0.0))
    assert lengths.l2 * math.cos(alp) == lengths.l3
    with pytest.warns(ListingBugWarning, match="D141"):
        out = ali1977.case1_cognate(*vars(lengths).values(), alp=alp, rpm=300.0, step_deg=90.0)
    ref = exact.listing("case1_cognate", 90.0, lengths, alp, 300.0, 2.0, SECTION, poles.LISTINGS["case1_cognate"][0])
    truth = np.array([ref["dx"], ref["dy"], ref["extender"] * ref["rot"]])
    got = np.array([out["dx"][1], out["dy"][1], ref["extender"] * out["rot"][1]])
    assert np.linalg.norm(got - truth) > np.linalg.norm(truth)


def test_the_bound_holds_on_a_fresh_calibration_sample():
    """25 draws (100 runs) of the calibration sample from a seed of their own: no point over its
    bound, none silent (the full sample: ``linkrepro ked-bound``)."""
    table = calibration.summary(calibration.measure(seed=7, draws=25)).set_index("engine")
    assert (table["over_bound"] == 0).all() and (table["silent_failures"] == 0).all(), table
    assert table["points"].min() > 50


@pytest.mark.parametrize("program", list(poles.LISTINGS))
def test_the_60_digit_listing_is_the_double_port_at_ordinary_positions(program):
    """exact.listing, written from the listings' statements, against the port in double precision
    (the listing's quirks and the corrected ones) at three ordinary angles: the same equations,
    so they agree to the double's rounding; and the corrected Case I against the independent
    construction from the geometry (``exact.case1_source``)."""
    lengths, section = Lengths(10.0, 12.0, 30.0, 25.0, 30.0), Section(0.2, 1e7, 0.003)
    deg = np.array([17.0, 133.0, 250.0])
    weight = 2.0 if program.startswith("case1") else 0.098
    for quirks in (poles.LISTINGS[program][0].only("real4_storage", False), CORRECTED):
        out = PORT[program](deg, lengths=lengths, alp=1.0, rpm=300.0, section=section, quirks=quirks,
                                **{"mass_lbf" if program.startswith("case1") else "density": weight})
        for k, d in enumerate(deg):
            ref = exact.listing(program, float(d), lengths, 1.0, 300.0, weight, section, quirks)
            truth = np.array([ref["dx"], ref["dy"], ref["extender"] * ref["rot"]])
            got = np.array([out["dx"][k], out["dy"][k], ref["extender"] * out["rot"][k]])
            assert np.linalg.norm(got - truth) <= 1e-13 * np.linalg.norm(truth), (quirks, d)
    if program == "case1_source":
        for d in deg:
            geometric = exact.case1_source(float(d), lengths, alp_deg=math.degrees(1.0), section=section)
            ref = exact.listing(program, float(d), lengths, 1.0, 300.0, 2.0, section, CORRECTED)
            assert abs(geometric["dx"] - ref["dx"]) + abs(geometric["dy"] - ref["dy"]) < 1e-12 * abs(ref["dx"])
