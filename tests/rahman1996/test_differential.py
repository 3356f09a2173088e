"""Differential tests, Rahman (1996) and (1991): the port against the legacy build over the input space.

The property (issue 11): the same outcome, i.e. a result or the same error type at the same
crank angle, and where both return, the same numbers.  The printed Newton is chaotic where it
wanders (see ``test_chaotic_inputs_...``), so the port runs it in the listing's order of
operations and its positions must equal the build's bit for bit; the tables are then equal to
1e-12 of each column's largest value (the loads after the Newton are numpy, summed in another
order than the listing's loops).

Domain: the issue's (a1 0.5-4, a2 3-12, a4 -3..3, s1 -1..1 in, alpha4 in every quadrant), at
three crank speeds, and the edges on purpose: a2 just above and below |a1 + a4| (the listing's
first estimate sqrt(a2^2 - (a1 + a4)^2) barely real, or not real), a4 = -a1 (its THT2 = PI -
ATAN(S4/0)), alpha4 on the axes.  Each value is drawn as a REAL*4 number, what the build receives.
"""
import numpy as np
import pytest
from hypothesis import event, example, given, settings
from hypothesis import strategies as st

from linkrepro.legacy import rahman1996
from linkrepro.errors import LinkageError, QPError, SingularPositionError
from linkrepro.harness.scenes.rahman1991.differential import geometry, sweep_1991
from linkrepro.harness.scenes.rahman1996.differential import TABLE_RTOL, one_ulp_up
from linkrepro.port.rahman1996.balance import CSSP_PRINTED, CRANK_DEG, _listing_motions, balance
from linkrepro.port.rahman1996.data import CsspInputs
from linkrepro.port.rahman1996.listing import printed_inverse
from linkrepro.port.rahman1991.data import GscInputs
#: ten times the examples under HYPOTHESIS_PROFILE=thorough (make fuzz; max_examples 1000 there, 100 by default)
MORE = max(1, settings.default.max_examples // 100)


def real4(x: float) -> float:
    return float(np.float32(x))


def outcome(call):
    """(result, None) or (None, (error type, crank angle)) for the typed errors both engines raise."""
    try:
        return call(), None
    except LinkageError as exc:
        return None, (type(exc).__name__, exc.angle_deg)
    except QPError as exc:
        return None, (type(exc).__name__, None)


@st.composite
def geometries(draw):
    """A CSSP geometry (in, deg, rpm) over the issue's domain and its edges."""
    a1 = draw(st.floats(0.5, 4.0))
    a4 = draw(st.one_of(st.floats(-3.0, 3.0), st.just(-a1)))    # a4 = -a1: the first estimate divides by 0
    edge = draw(st.sampled_from(["free", "free", "free", "estimate barely real", "estimate not real"]))
    reach = abs(a1 + a4)
    if edge == "free" or reach < 3.0 / 1.01:
        a2 = draw(st.floats(3.0, 12.0))
    elif edge == "estimate barely real":
        a2 = reach * (1.0 + draw(st.floats(1e-6, 1e-2)))
    else:
        a2 = reach * (1.0 - draw(st.floats(1e-6, 1e-2)))
    quadrant = draw(st.integers(0, 3))
    alpha4 = draw(st.one_of(st.just(90.0 * quadrant), st.floats(0.0, 90.0, exclude_max=True).map(lambda d: 90.0 * quadrant + d)))
    return {"a1": real4(a1), "a2": real4(a2), "a4": real4(a4), "alpha4_deg": alpha4,
            "s1": real4(draw(st.floats(-1.0, 1.0))), "rpm": real4(draw(st.sampled_from([3000.0, 50.0, 12000.0])))}


def assert_port_equals_legacy(g: dict) -> tuple:
    """The property on one geometry; returns legacy's (result, error)."""
    leg, leg_err = outcome(lambda: rahman1996.cssp(**g))
    port, port_err = outcome(lambda: balance(CsspInputs(**g), CSSP_PRINTED))
    assert port_err == leg_err, f"{g}: legacy {leg_err}, port {port_err}"
    if leg is None:
        return leg, leg_err
    for k, motion in enumerate(_listing_motions(CsspInputs(**g), True, True)):
        assert np.array_equal(motion.q, leg["positions"][k]), f"{g}: pass {k + 1} positions differ"
    diff = np.abs(port["table"] - leg["table"])
    bound = np.broadcast_to(TABLE_RTOL * np.max(np.abs(leg["table"]), axis=0), diff.shape)
    np.testing.assert_array_less(diff, bound + 1e-300, err_msg=f"{g}: tables differ")
    return leg, leg_err


@settings(max_examples=60 * MORE)
@given(geometries())
@example({"a1": 1.5, "a2": 3.0, "a4": 1.5, "alpha4_deg": 91.0, "s1": 0.0, "rpm": 3000.0})    # quadprog failed
@example({"a1": 1.5, "a2": 6.0, "a4": 0.0, "alpha4_deg": 0.0, "s1": 1.0, "rpm": 3000.0})     # QP's last bits
@example({"a1": 12.0, "a2": 50.0, "a4": real4(0.5178689360618591), "alpha4_deg": 0.0, "s1": 0.0,
          "rpm": 50.0})                                                                    # glibc's powf
def test_cssp_port_equals_legacy_over_the_input_space(g):
    leg, err = assert_port_equals_legacy(g)
    event("returns" if err is None else f"both raise {err[0]}")


def test_the_issues_diverging_geometries():
    """Geometries of the issue's trial where the port converged to another branch (a numpy matrix
    product rounded unlike MULTI) or failed at another angle (the first estimate added A4+A1 in
    double, the listing in REAL*4)."""
    for g in ({"a1": 1.982, "a2": 10.449, "a4": -0.545, "alpha4_deg": 197.854, "s1": -0.945},
              {"a1": 2.087, "a2": 4.206, "a4": -0.581, "alpha4_deg": 73.244, "s1": -0.475},
              {"a1": 0.72, "a2": 10.429, "a4": -2.013, "alpha4_deg": 135.053, "s1": -0.367}):
        assert_port_equals_legacy(g)


def test_chaotic_inputs_move_legacy_itself_and_the_port_follows():
    """Where the Newton wanders, legacy's own answer jumps when an input moves by one ulp: the
    documented class of chaotic inputs.  Measured on the issue's first diverging geometry: a1
    one REAL*4 ulp up moves legacy's tables by more than 10 % of a column; the port follows
    legacy to the bit on both sides (which is why its Newton runs in the listing's order)."""
    g = {"a1": 1.982, "a2": 10.449, "a4": -0.545, "alpha4_deg": 197.854, "s1": -0.945}
    nudged = dict(g, a1=one_ulp_up(g["a1"]))
    base, _ = assert_port_equals_legacy(g)
    moved, moved_err = assert_port_equals_legacy(nudged)
    if moved_err is None:
        scale = np.max(np.abs(base["table"]), axis=0)
        assert np.max(np.abs(moved["table"] - base["table"]) / scale) > 0.1
    # a1's ulp is 1.2e-7 in: a smooth map would move the tables by ~1e-7 relative


@st.composite
def inverse_inputs(draw):
    """5 x 5 matrices that reach every path of INVERSE: small integers (exact zero pivots, row
    exchanges at each pivot, singular matrices), A'A of random 6 x 5 A, and wide magnitudes."""
    kind = draw(st.sampled_from(["integers", "normal equations", "scaled"]))
    if kind == "integers":
        return np.array(draw(st.lists(st.integers(-2, 2), min_size=25, max_size=25)), dtype=float).reshape(5, 5)
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    if kind == "normal equations":
        a = rng.normal(size=(6, 5))
        return a.T @ a
    return rng.normal(size=(5, 5)) * 10.0 ** rng.integers(-150, 150, size=(5, 1))


@settings(max_examples=300 * MORE)
@given(inverse_inputs())
def test_printed_inverse_equals_legacy(s):
    """Same outcome (SingularPositionError where the listing prints MATRIX IS SINGULAR) and the
    same bits, on every path of the routine."""
    leg, leg_err = outcome(lambda: rahman1996.inverse(s))
    port, port_err = outcome(lambda: printed_inverse(s))
    assert port_err == leg_err
    event("singular" if leg_err else "inverted")
    if leg_err is None:
        assert np.array_equal(port, leg, equal_nan=True)


@pytest.mark.parametrize("bad", [np.full((5, 5), np.nan), np.eye(4), np.array([[1.0, np.inf]])])
def test_inverse_refuses_bad_matrices_alike(bad):
    for inverse in (rahman1996.inverse, printed_inverse):
        with pytest.raises(ValueError):
            inverse(bad)


@st.composite
def example_1991(draw):
    """Rahman (1991)'s example (a1 = 12, a2 = 50 in, 50 rpm, section 3.1) over its grid's range
    and beyond: a4 0..40 in, alpha4 anywhere, S1 0..10 in, constant."""
    return GscInputs(a4=real4(draw(st.floats(0.0, 40.0))), alpha4_deg=draw(st.floats(0.0, 360.0, exclude_max=True)),
                     s1=real4(draw(st.floats(0.0, 10.0))))


def assert_1991_method_is_the_build(inputs: GscInputs) -> str:
    """The 1991 method's Newton (rahman1991.position), run in the 1996 build's arithmetic (REAL*4
    inputs, the listing's INVERSE, 10-deg steps, no DFP fallback), gives the build's first-pass
    positions bit for bit; where the build fails in its first pass, the 1991 sweep stops at the
    same crank angle.  (The build can also fail later, in its rates, second pass or QP: then the
    1991 sweep either stops at the build's angle or runs through.)"""
    g = geometry(inputs)
    leg, leg_err = outcome(lambda: rahman1996.cssp(**g))
    run = sweep_1991(g)
    solved = run.stopped                      # the build checks no closure: a stop is its answer
    if leg_err is None:
        assert solved.all()
        assert np.array_equal(run.q, leg["positions"][0])
        return "build runs"
    stop = CRANK_DEG[np.argmin(solved)] if not solved.all() else None
    assert stop in (None, leg_err[1]), f"1991 sweep stops at {stop}, build fails with {leg_err}"
    return f"build raises {leg_err[0]}; 1991 sweep {'runs through' if stop is None else 'stops there'}"


@settings(max_examples=40 * MORE)
@given(example_1991())
def test_1991_method_is_the_1996_build_first_pass(inputs):
    event(assert_1991_method_is_the_build(inputs))


def test_1991_method_at_grid_points_of_the_thesis():
    """Grid points the thesis plots (section 3.1): planar a4 = 10 and spatial a4 = 30."""
    assert assert_1991_method_is_the_build(GscInputs(a4=30.0, alpha4_deg=270.0, s1=3.5)) == "build runs"
    assert_1991_method_is_the_build(GscInputs(a4=10.0, alpha4_deg=232.0, s1=0.0))


def test_a_failure_is_a_typed_error_naming_the_angle():
    """A geometry whose first estimate is not real: both engines fail at 0 deg, alike."""
    g = {"a1": 2.0, "a2": 2.5, "a4": 1.0, "alpha4_deg": 250.0, "s1": 0.4}
    _, err = assert_port_equals_legacy(g)
    assert err == ("ConvergenceError", 0.0)
    with pytest.raises(SingularPositionError):
        printed_inverse(np.zeros((5, 5)))
