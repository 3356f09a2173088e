"""Differential tests, Ali (1977): the six K.E.D. programs, legacy against the port with the
listings' bugs, over the whole input space (issue 11).

The property: the same outcome, i.e. both return, or both raise the same typed error
(AssemblyError, SingularPositionError) at the same input angle (``exc.angle_deg``), with the same
linkrepro warnings (ListingBugWarning D141 where the cognate's BETA is wrong); and where
both return, every array the port returns equal to legacy's, bit for bit (the issue asks for
1e-12 relative; bit for bit holds everywhere we looked, so that is what is asserted: the port
emulates each listing's REAL*4 storage and MPRD's order of summation exactly, so there is no
REAL*4 tolerance to allow for).

How the two APIs map (what "the same input" means):

- the angles: legacy steps its input angle in REAL*4 (``P2=P2+DSTEP``, DSTEP a REAL*4); the port
  takes the angles, ``listing_angles(step)`` builds the same ones (and is checked against
  legacy's ``deg``);
- the port runs each listing's own bugs: ``PRINTED`` for Case I, ``case2.LISTING`` /
  ``COGNATE_LISTING`` and ``ked_case3.LISTING`` / ``COGNATE_LISTING`` (PRINTED without the bugs
  that listing does not have), with ``alp`` and ``rpm`` given explicitly (the listings' 101 deg
  and 400 rpm are only defaults);
- section values and the density are the listings' REAL*4 literals: the port rounds them to
  single precision, legacy passes what it is given to DOUBLE variables; so they are drawn as
  REAL*4 numbers (what the listing can hold), and ``test_section_values_are_the_listings_literals``
  checks the port at x against legacy at float32(x) for any double x.  The weight of Case I is a
  REAL*4 argument of the build itself (f2py rounds it), so it is passed as drawn.

Domain, and its edges on purpose: link lengths over five decades, with Grashof crank-rockers
(close everywhere), free lengths (most cannot close at some angle: AssemblyError at the same
angle), lengths on an assembly limit (l5 = l3 + l4 - l1, l5 = l1 + |l3 - l4|) moved by 0, a few
ulps or up to 1e-3 (discriminant near 0), folded linkages in small integers (a dead centre exactly
at 0 deg: SingularPositionError), Grashof's change point s + l = p + q, degenerate cognates (l2 =
l3 with alp = 0 makes the cognate's CL4 = 0); alp in every quadrant, on the axes and near 0 and
pi; speeds of either sign, zero, fractional (Case I truncates to INTEGER) up to 2**31 - 1; zero and
positive weights; section properties over several decades; angle steps that do and do not divide
360.  Case III's source needs l2 > 8 (its five nodes are 2 in apart).

The engine pairs are ``harness/scenes/ali1977/differential.py``'s, which ``linkrepro differential
ali1977`` runs on numpy samples of this domain (``--domain sample`` or ``edges``; differential.md
states them), e.g. ``--samples 500 --seed 20240611`` or ``--domain edges --seed 7``.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import event, given, settings
from hypothesis import strategies as st

from linkrepro.legacy import ali1977
from linkrepro.errors import AssemblyError, LinkreproWarning, SingularPositionError
from linkrepro.harness.scenes.ali1977.differential import (PI_22_7, PROGRAMS, legacy_call, listing_angles, port_call,
                                                            real4)
from linkrepro.port.ali1977 import case2, case3 as ked_case3
from linkrepro.port.ali1977.fourbar import Lengths
from linkrepro.port.ali1977.case1 import cognate_case1, source_case1
from linkrepro.port.ali1977.cognate import cognate_mechanics
from linkrepro.port.ali1977.source import source_mechanics
from linkrepro.port.ali1977.structure import Section

def outcome(call):
    """(result, None, warned), or (None, (error type, input angle), warned) for the typed errors
    of a run; ``warned``: the linkrepro warnings it gave (class and register entry)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", LinkreproWarning)
        try:
            result, error = call(), None
        except (AssemblyError, SingularPositionError) as exc:
            result, error = None, (type(exc).__name__, exc.angle_deg)
        except ValueError:
            result, error = None, ("ValueError", None)
    warned = sorted({(w.category.__name__, getattr(w.message, "entry", None)) for w in caught
                     if issubclass(w.category, LinkreproWarning)})
    return result, error, warned


def assert_port_equals_legacy(name: str, g: dict):
    """The property on one set of inputs; returns the common outcome's label."""
    deg = listing_angles(g["step"])
    leg, leg_err, leg_warned = outcome(lambda: legacy_call(name, g))
    port, port_err, port_warned = outcome(lambda: port_call(name, g, deg))
    assert port_err == leg_err, f"{name} {g}: legacy {leg_err}, port {port_err}"
    assert port_warned == leg_warned, f"{name} {g}: legacy warned {leg_warned}, port {port_warned}"
    if leg is None:
        return f"both raise {leg_err[0]}"
    assert np.array_equal(leg["deg"], deg)
    assert set(port) == set(leg) - {"deg"}, f"{name}: the port returns {sorted(port)}, legacy {sorted(leg)}"
    for key, values in port.items():
        expected = leg[key]
        if not np.array_equal(values, expected):
            rel = np.max(np.abs(values - expected) / np.maximum(np.abs(expected), 1e-300))
            raise AssertionError(f"{name} {g}: {key} differs from legacy (max relative {rel:.3g})")
    return "both return"


# --- the input space ---------------------------------------------------------------------
# (strategies built once here: building them inside the composites costs more than the runs)

def log_uniform(lo: float, hi: float):
    return st.floats(math.log(lo), math.log(hi)).map(lambda x: float(np.exp(x)))


UNIT = st.floats(0.0, 1.0, exclude_max=True)
FREE_LENGTH = log_uniform(0.05, 500.0)
CRANK = log_uniform(0.5, 20.0)
RATIO = log_uniform(1.01, 10.0)
SMALL_INT = st.integers(1, 40)
KIND = st.sampled_from(["free", "crank-rocker", "crank-rocker", "limit", "limit", "folded", "change point"])
NUDGE = st.one_of(st.just(0.0), st.integers(-16, 16).map(lambda k: k * 2.0**-52), st.floats(-1e-3, 1e-3))
ALP = st.one_of(
    st.tuples(st.integers(-4, 7), UNIT).map(lambda qu: (qu[0] + qu[1]) * math.pi / 2),   # every quadrant
    st.sampled_from([0.0, math.pi / 2, math.pi, 1.5 * math.pi, 2 * math.pi, -math.pi / 2, -math.pi, PI_22_7,
                     ali1977.ALP_SOURCE_PRINTED, ali1977.ALP_COGNATE_PRINTED]),
    st.floats(-1e-6, 1e-6), st.floats(-1e-6, 1e-6).map(lambda d: math.pi + d))
RPM = st.one_of(st.integers(-3000, 6000).map(float), st.floats(-6000.0, 6000.0),
                st.sampled_from([0.0, 0.5, -0.5, 299.9, 300.0, 400.0, 2.0**31 - 1, -(2.0**31 - 1)]))
L2 = st.one_of(log_uniform(0.05, 200.0), st.integers(1, 60).map(float), st.just("l3"))
L2_CASE3 = st.one_of(log_uniform(1e-3, 100.0), st.integers(1, 50).map(float)).map(lambda d: 8.0 + d)
SCALE = st.one_of(st.just(1.0), log_uniform(0.01, 100.0))
WEIGHT = {"case1": st.one_of(st.just(0.0), log_uniform(1e-4, 1e3)).map(real4),
          "other": st.one_of(st.just(0.0), log_uniform(1e-4, 10.0)).map(real4)}
AREA, MODULUS, INERTIA = (log_uniform(lo, hi).map(real4) for lo, hi in ((1e-4, 10.0), (1e3, 1e9), (1e-8, 10.0)))
#: Case III's legacy takes 0.3 ms per angle: its steps start at 3 deg
STEP = {"case3_source": st.one_of(st.sampled_from([5.0, 7.5, 10.0, 20.0, 30.0, 45.0, 90.0, 360.0, 400.0, 7.0, 11.0]),
                                  st.floats(3.0, 400.0).map(real4)),
        "other": st.one_of(st.sampled_from([1.0, 2.5, 5.0, 7.5, 10.0, 20.0, 30.0, 45.0, 90.0, 360.0, 400.0, 7.0,
                                            11.0, 0.7]), st.floats(1.0, 400.0).map(real4))}


def crank_rocker(draw):
    """l1, l3, l4, l5 with the crank l1 the shortest and s + l < p + q: it turns fully."""
    s = draw(CRANK)
    p, q = s * draw(RATIO), s * draw(RATIO)
    longest = max(p, q) + draw(UNIT) * (min(p, q) - s)          # below p + q - s
    order = draw(st.permutations([0, 1, 2]))
    l3, l4, l5 = (np.array([p, q, longest])[order]).tolist()
    return s, l3, l4, l5


def four_bar(draw):
    """l1, l3, l4, l5 (l2 is drawn apart): see the module docstring."""
    kind = draw(KIND)
    if kind == "free":
        return tuple(draw(FREE_LENGTH) for _ in range(4))
    if kind == "crank-rocker":
        return crank_rocker(draw)
    if kind == "limit":      # the discriminant's zero at 180 deg (l1 + l5 = l3 + l4) or at 0 deg
        l1, l3, l4, _ = crank_rocker(draw)
        target = l3 + l4 - l1 if draw(st.booleans()) else l1 + abs(l3 - l4)
        return l1, l3, l4, target * (1.0 + draw(NUDGE))
    if kind == "folded":     # coupler and follower in line at 0 deg, in exact small integers
        l1, l3, l4 = (float(draw(SMALL_INT)) for _ in range(3))
        if l3 == l4:
            l4 += 1.0
        if draw(st.booleans()):
            return l1, l3, l4, l1 + abs(l3 - l4)
        return abs(l3 - l4) + l1, l3, l4, l1      # l1 - l5 = |l3 - l4|
    s = float(1 + draw(SMALL_INT) % 10)           # Grashof's change point: s + l = p + q exactly
    p, q = s + draw(SMALL_INT) % 20, s + draw(SMALL_INT) % 20
    return s, p, q, p + q - s


@st.composite
def inputs(draw, name: str):
    l1, l3, l4, l5 = four_bar(draw)
    if name == "case3_source":
        l2 = draw(L2_CASE3)
    else:
        l2 = draw(L2)
        l2 = l3 if l2 == "l3" else l2                # with alp = 0: a degenerate cognate
    scale = draw(SCALE)                               # five decades of lengths (Case III's l2 kept > 8)
    lengths = (l1 * scale, l2 if name == "case3_source" else l2 * scale, l3 * scale, l4 * scale, l5 * scale)
    return {
        "lengths": lengths,
        "alp": draw(ALP),
        "rpm": draw(RPM),
        "weight": draw(WEIGHT["case1" if name.startswith("case1") else "other"]),
        "area": draw(AREA),
        "modulus": draw(MODULUS),
        "inertia": draw(INERTIA),
        "step": draw(STEP["case3_source" if name == "case3_source" else "other"]),
    }


def _property_test(name: str, factor: float):
    """The property for one program, with ``factor`` times the profile's number of examples
    (the "ci" profile's 100, or "thorough"'s 1000 for ``make fuzz``)."""
    @settings(max_examples=int(factor * settings.default.max_examples))
    @given(g=inputs(name))
    def test(g):
        event(assert_port_equals_legacy(name, g))
    test.__doc__ = f"{name}: legacy and the port with the listing's bugs, the same outcome and the same bits."
    test.__name__ = test.__qualname__ = f"test_{name}_over_the_input_space"    # its own examples
    return test


test_case1_source_over_the_input_space = _property_test("case1_source", 2)
test_case1_cognate_over_the_input_space = _property_test("case1_cognate", 2)
test_case2_source_over_the_input_space = _property_test("case2_source", 2)
test_case2_cognate_over_the_input_space = _property_test("case2_cognate", 2)
test_case3_source_over_the_input_space = _property_test("case3_source", 1.5)
test_case3_cognate_over_the_input_space = _property_test("case3_cognate", 2)


def _g(lengths, alp=PI_22_7 / 3, rpm=300.0, weight=real4(0.098), step=20.0, area=ali1977.CA_PRINTED,
       modulus=ali1977.ME_PRINTED, inertia=ali1977.MI_PRINTED):
    return {"lengths": tuple(float(v) for v in lengths), "alp": alp, "rpm": rpm, "weight": weight,
            "area": area, "modulus": modulus, "inertia": inertia, "step": step}


#: Inputs where the port differed from legacy before the fixes of issue 11 (and three dead
#: centres where it did not), with legacy's outcome: "return" or (error, input angle).
FOUND = [
    # the cognate cannot close before the source does: the listing tests both loops at each
    # angle, the port tested every angle of the source first (AssemblyError at 77 deg, not 0)
    ("case1_cognate", _g((15, 0.23169579649373395, 7, 37, 45), alp=-math.pi, step=1.0), ("AssemblyError", 0.0)),
    ("case2_cognate", _g((14, 28, 38, 8, 44), alp=3.1415926456516763, step=11.0), ("AssemblyError", 0.0)),
    ("case3_cognate", _g((38, 11, 21, 12, 47), alp=3.1415926605377185, step=45.0), ("AssemblyError", 0.0)),
    # a degenerate cognate (l2 = l3, alp = 0: CL4 = CL1 = CL3 = 0): the port divided Python
    # floats (ZeroDivisionError); the listing gets inf and NaN
    ("case1_cognate", _g((1.5391367544881518, 3.7530703498718334, 3.7530703498718334, 3.3627316544910806,
                          4.974988692775746), alp=0.0, step=1.0), ("SingularPositionError", 0.0)),
    # Case III: rot is the listing's (D035), the nodes 2 in apart; the port computed the tip
    # alone, so it returned where another node is not finite (legacy: SingularPositionError, or
    # IndexError before, its face taking a flat index of the (N, 5, 3) nodes for an angle)
    ("case3_source", _g((10, 12, 30, 25, 30)), "return"),
    ("case3_source", _g((5.737780712528516, 14.0, 8.311214944053603, 13.044970643429972, 11.941702809349444),
                        alp=9.254404521340081e-09, rpm=299.9, weight=real4(1e30), area=real4(1e-6), modulus=1.0,
                        inertia=real4(1e-8), step=45.0), ("SingularPositionError", 180.0)),
    ("case3_source", _g((4.731029599568804, 25.0, 23.001141986111797, 26.185623631705393, 44.45573601824838),
                        alp=math.pi, rpm=465.3919575669206, weight=real4(1e30), inertia=real4(1e-8), step=1.0),
     ("SingularPositionError", 180.0)),
    ("case3_source", _g((10.893602301050043, 10.118878485092722, 15.694012994933601, 77.71698910045923,
                         73.024046992518), alp=2 * math.pi, rpm=1.0, weight=real4(1e30), area=1.0, modulus=1.0,
                        inertia=real4(1e-8)), ("SingularPositionError", 0.0)),
    # Case III cognate: the port returned neither cxp, cyp nor checked them (legacy: 68 deg)
    ("case3_cognate", _g((25.767821354619464, 0.49891851158647194, 25.767821354619464, 27.124022478546802,
                          27.124022478546802), alp=3.142857074737549, rpm=0.0, weight=0.0, area=1.0,
                         modulus=1096.6331787109375, inertia=1.0, step=1.0), ("SingularPositionError", 68.0)),
    # folded at 0 deg (L5 - L1 = L3 - L4): a dead centre exactly on the grid (equal before too)
    ("case1_source", _g((10, 10, 30, 10, 30)), ("SingularPositionError", 0.0)),
    ("case2_source", _g((10, 10, 30, 10, 30)), ("SingularPositionError", 0.0)),
    ("case3_source", _g((10, 10, 30, 10, 30)), ("SingularPositionError", 0.0)),
]


@pytest.mark.parametrize("name,g,expected", FOUND)
def test_inputs_where_the_port_differed(name, g, expected):
    assert_port_equals_legacy(name, g)
    assert outcome(lambda: legacy_call(name, g))[1] == (None if expected == "return" else expected)


def test_case3_rotation_and_nodes_are_the_listings_off_the_example():
    """Off the published l2 = 10, the listing's nodes stay 2 in apart (L21 = L2 - 2.0 ...) and
    its tip rotation goes through node 2's block (D035): the port does both (it used even
    spacing, l2/5, and the tip block's own rotation)."""
    deg = listing_angles(20.0)
    leg = ali1977.case3_source(l2=13.0)
    port = ked_case3.case3_source(deg, lengths=Lengths(10.0, 13.0, 30.0, 25.0, 30.0), all_nodes=True)
    assert np.array_equal(port["nodes"], leg["nodes"]) and np.array_equal(port["rot"], leg["rot"])
    uncoupled_tip = ked_case3.case3_source(deg, n=1, lengths=Lengths(10.0, 13.0, 30.0, 25.0, 30.0))
    assert np.array_equal(port["dx"], uncoupled_tip["dx"]) and not np.array_equal(port["rot"], uncoupled_tip["rot"])


@settings(max_examples=40)
@given(area=log_uniform(1e-4, 10.0), modulus=log_uniform(1e3, 1e9), inertia=log_uniform(1e-8, 10.0),
       density=log_uniform(1e-4, 10.0))
def test_section_values_are_the_listings_literals(area, modulus, inertia, density):
    """The port at any double x equals legacy at float32(x): the listing's CA, ME, MI, DNTY are
    REAL*4 literals assigned to DOUBLE variables, which is what the port models."""
    deg = listing_angles(30.0)
    port = case2.case2_source(deg, density=density, section=Section(area, modulus, inertia))
    leg = ali1977.case2_source(density=real4(density), area=real4(area), modulus=real4(modulus),
                              inertia=real4(inertia), step_deg=30.0)
    for key in port:
        assert np.array_equal(port[key], leg[key]), key


# --- one error vocabulary ----------------------------------------------------------------

PORT_FUNCTIONS = {"source_case1": source_case1, "cognate_case1": cognate_case1,
                  "case2_source": case2.case2_source, "case2_cognate": case2.case2_cognate,
                  "case3_source": ked_case3.case3_source, "case3_cognate": ked_case3.case3_cognate,
                  "source_mechanics": source_mechanics, "cognate_mechanics": cognate_mechanics}


@pytest.mark.parametrize("func", PORT_FUNCTIONS)
@pytest.mark.parametrize("deg,error", [
    (np.array(30.0), ValueError),                      # 0-D: refused (the docstring says so)
    (30.0, ValueError),
    (np.array([[0.0, 30.0], [60.0, 90.0]]), ValueError),
    (np.zeros((2, 0)), ValueError),
    (np.ones((1, 1, 3)), ValueError),
    (np.array([]), ValueError),
    (np.array([0.0, np.nan]), ValueError),
    (np.array([np.inf, 10.0]), ValueError),
    ([-np.inf], ValueError),
    (np.array([1e308, 0.0]), ValueError),              # finite in degrees, not in radians
    ([0.0, [1.0]], ValueError),                        # ragged
    (np.array(["0", "10"]), TypeError),
    ("30", TypeError),
    (None, TypeError),
    (np.array([None, 1.0], dtype=object), TypeError),
    (np.array([1j, 2.0]), TypeError),
    (np.array([True, False]), TypeError),
    ({0: 1.0}, TypeError),
])
def test_port_refuses_bad_angle_arrays(func, deg, error):
    with pytest.raises(error, match="deg|angle"):
        PORT_FUNCTIONS[func](deg)


@pytest.mark.parametrize("func", PORT_FUNCTIONS)
def test_port_takes_any_real_1d_angles(func):
    """ints, float16, tuples and lists are 1-D arrays of real numbers: accepted."""
    base = PORT_FUNCTIONS[func](np.array([0.0, 90.0, 180.0]))
    for deg in ([0, 90, 180], (0.0, 90.0, 180.0), np.array([0.0, 90.0, 180.0], dtype=np.float16)):
        got = PORT_FUNCTIONS[func](deg)
        got = got if isinstance(got, dict) else {"xp": got.xp}
        want = base if isinstance(base, dict) else {"xp": base.xp}
        for key in want:
            assert np.array_equal(got[key], want[key])


LEGACY_PORT = [(n, n.replace("case1_source", "source_case1").replace("case1_cognate", "cognate_case1")) for n in PROGRAMS]


def _both(legacy_name: str, port_name: str, **bad):
    """Call legacy and the port with one bad parameter (lengths, alp, rpm, weight, section)."""
    weight = "mass_lbf" if legacy_name.startswith("case1") else "density"
    leg_kw, port_kw = {}, {}
    lengths = dict(l1=10.0, l2=10.0, l3=30.0, l4=25.0, l5=30.0)
    section = dict(area=ali1977.CA_PRINTED, modulus=ali1977.ME_PRINTED, inertia=ali1977.MI_PRINTED)
    for key, value in bad.items():
        if key in lengths:
            lengths[key] = value
        elif key in section:
            section[key] = value
        elif key == "weight":
            leg_kw[weight] = port_kw[weight] = value
        else:
            leg_kw[key] = port_kw[key] = value
    calls = [lambda: getattr(ali1977, legacy_name)(**lengths, **section, **leg_kw),
             lambda: PORT_FUNCTIONS[port_name](np.array([0.0, 20.0]), lengths=Lengths(*lengths.values()),
                                               section=Section(*section.values()), **port_kw)]
    return calls


BAD_PARAMETERS = [
    ({"l1": 0.0}, ValueError), ({"l3": -30.0}, ValueError), ({"l5": math.nan}, ValueError), ({"l2": math.inf}, ValueError),
    ({"l4": "25"}, TypeError), ({"l2": None}, TypeError), ({"l1": True}, TypeError), ({"l3": 1 + 2j}, TypeError),
    ({"l1": [10.0]}, TypeError), ({"l1": 10**400}, ValueError),
    ({"alp": math.nan}, ValueError), ({"alp": math.inf}, ValueError), ({"alp": "1.0"}, TypeError),
    ({"rpm": math.nan}, ValueError), ({"rpm": -math.inf}, ValueError), ({"rpm": 2.0**31}, ValueError),
    ({"rpm": np.array([300.0])}, TypeError),
    ({"weight": -1.0}, ValueError), ({"weight": math.nan}, ValueError), ({"weight": 1e39}, ValueError),
    ({"weight": object()}, TypeError),
    ({"area": 0.0}, ValueError), ({"modulus": -1e7}, ValueError), ({"inertia": math.inf}, ValueError),
    ({"area": 1e39}, ValueError), ({"inertia": 1e-50}, ValueError), ({"modulus": "1e7"}, TypeError),
]


@pytest.mark.parametrize("legacy_name,port_name", LEGACY_PORT)
@pytest.mark.parametrize("bad,error", BAD_PARAMETERS)
def test_both_engines_refuse_bad_parameters_alike(legacy_name, port_name, bad, error):
    for call in _both(legacy_name, port_name, **bad):
        with pytest.raises(error):
            call()


@pytest.mark.parametrize("step,error", [(0.0, ValueError), (-20.0, ValueError), (math.nan, ValueError),
                                        (math.inf, ValueError), (1e-3, ValueError), (1e39, ValueError),
                                        (1e-50, ValueError), ("20", TypeError), (None, TypeError)])
def test_legacy_refuses_bad_steps(step, error):
    """The step (legacy only: the port takes its angles) is a REAL*4 of the listings: positive,
    representable, and at most 200000 angles."""
    for program in PROGRAMS:
        with pytest.raises(error):
            getattr(ali1977, program)(step_deg=step)


def test_case3_source_nodes_need_l2_above_8_in_both():
    for l2 in (8.0, 5.0):
        with pytest.raises(ValueError, match="l2"):
            ali1977.case3_source(l2=l2)
        with pytest.raises(ValueError, match="l2"):
            ked_case3.case3_source(np.array([0.0]), lengths=Lengths(10.0, l2, 30.0, 25.0, 30.0))


@pytest.mark.parametrize("n,error", [(0, ValueError), (2.5, ValueError), (math.nan, ValueError), (math.inf, ValueError),
                                     (10**30, ValueError), (True, TypeError), (None, TypeError), ("5", TypeError)])
def test_port_refuses_bad_node_counts(n, error):
    for case3 in (ked_case3.case3_source, ked_case3.case3_cognate):
        with pytest.raises(error):
            case3(np.array([0.0]), n=n)


@pytest.mark.parametrize("func", PORT_FUNCTIONS)
@pytest.mark.parametrize("kw", [{"lengths": (10.0, 10.0, 30.0, 25.0, 30.0)}, {"lengths": None},
                                {"quirks": "PRINTED"}, {"quirks": None}])
def test_port_refuses_wrong_containers(func, kw):
    with pytest.raises(TypeError):
        PORT_FUNCTIONS[func](np.array([0.0]), **kw)


@pytest.mark.parametrize("func", [f for f in PORT_FUNCTIONS if "mechanics" not in f])
def test_port_refuses_a_section_that_is_not_a_section(func):
    with pytest.raises(TypeError):
        PORT_FUNCTIONS[func](np.array([0.0]), section=(0.2, 1e7, 0.003))
