"""One rule for arguments, Rahman (1996) and the slider crank (issue 22, item 6).

Public functions check their arguments with ``linkrepro.checks``: TypeError for what is not
a number of the right kind, ValueError for a number outside the domain (non-finite, a Python
int too large for a double, out of range), the typed linkage errors for positions; helpers
not meant for users are private.  The error's type does not depend on which argument is
checked first, and legacy and the port give the same one.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from linkrepro.errors import LinkageError, QPError
from linkrepro.legacy import rahman1996
from linkrepro.port.rahman1991 import position
from linkrepro.port.rahman1991.data import GscInputs
from linkrepro.port.rahman1996 import qprog as port_qprog
from linkrepro.port.rahman1996.balance import CSSP_CORRECTED, CSSP_PRINTED, balance
from linkrepro.port.rahman1996.data import Constants, CsspInputs
from linkrepro.port.rahman1996.listing import listing_pass
from linkrepro.port.rahman1996.mechanics import closed_loop_loads
from linkrepro.port.slider_crank.geometry import initial_estimate
from linkrepro.port.slider_crank.kinematics import kinematics

HUGE = 10 ** 400                   # a Python int beyond any double
C = Constants.of(CsspInputs(), True)
GSC = position.constants(GscInputs(), GscInputs().s1)

HUGE_CALLS = {
    "legacy qprog neq": lambda: rahman1996.qprog(np.eye(2), [1.0, 1.0], [[1.0, 0.0]], [0.0], HUGE),
    "port qprog neq": lambda: port_qprog.qprog(np.eye(2), [1.0, 1.0], [[1.0, 0.0]], [0.0], HUGE),
    "legacy qprog h": lambda: rahman1996.qprog([[HUGE, 0], [0, 1]], [1.0, 1.0]),
    "port qprog g": lambda: port_qprog.qprog(np.eye(2), [HUGE, 1]),
    "hessian_shift": lambda: port_qprog.hessian_shift([[HUGE]]),
    "legacy inverse": lambda: rahman1996.inverse([[HUGE] * 5] * 5),
    "legacy cssp a1": lambda: rahman1996.cssp(a1=HUGE),
    "legacy cssp solution": lambda: rahman1996.cssp(solution=[HUGE] * 9),
    "CsspInputs": lambda: CsspInputs(s1=HUGE),
    "balance solution": lambda: balance(solution=[HUGE] * 9),
    "listing_pass": lambda: listing_pass([HUGE], initial_estimate(C, True), C),
    "kinematics": lambda: kinematics(CsspInputs(), [HUGE]),
    "closed_loop_loads": lambda: closed_loop_loads(Constants.of(CsspInputs(), False), [HUGE]),
    "positions": lambda: position.positions(GscInputs(), [HUGE]),
    "newton": lambda: position.newton(HUGE, np.zeros(5), GSC),
}


@pytest.mark.parametrize("call", HUGE_CALLS.values(), ids=HUGE_CALLS.keys())
def test_a_python_int_too_large_for_a_double_is_a_value_error(call):
    with pytest.raises(ValueError):
        call()


NON_FINITE_ANGLES = {
    "listing_pass inf": lambda: listing_pass([0.0, np.inf], initial_estimate(C, True), C),
    "kinematics nan": lambda: kinematics(CsspInputs(), [0.1, np.nan]),
    "kinematics s1 jet": lambda: kinematics(CsspInputs(), [0.1], np.full((3, 1), np.nan)),
    "closed_loop_loads -inf": lambda: closed_loop_loads(Constants.of(CsspInputs(), False), [-np.inf]),
    "positions nan": lambda: position.positions(GscInputs(), [np.nan, 0.0]),
    "newton nan": lambda: position.newton(np.nan, np.zeros(5), GSC),
    "newton inf": lambda: position.newton(np.inf, np.zeros(5), GSC),
}


@pytest.mark.parametrize("call", NON_FINITE_ANGLES.values(), ids=NON_FINITE_ANGLES.keys())
def test_lower_level_functions_refuse_non_finite_angles(call):
    """They computed on (NaN positions, "at input angle inf deg", "not converged")."""
    with pytest.raises(ValueError, match="finite"):
        call()


@pytest.mark.parametrize("call, error", [
    (lambda: kinematics({"a1": 2.0}, [0.0]), TypeError),
    (lambda: kinematics(CsspInputs(), ["0"]), TypeError),
    (lambda: position.positions(CsspInputs(), [0.0]), TypeError),
    (lambda: position.newton(0.0, np.zeros(4), GSC), ValueError),
    (lambda: position.newton(0.0, np.zeros(5), "c"), TypeError),
])
def test_lower_level_functions_refuse_wrong_kinds(call, error):
    with pytest.raises(error):
        call()


def test_the_kernels_are_private():
    """The compiled kernels of the printed Newton take bare numbers and answer NaN: not for
    users, so their module is private, as are the 1991 Newton's residual and DFP."""
    from linkrepro.port import slider_crank
    assert not hasattr(slider_crank, "newton")
    with pytest.raises(ImportError):
        from linkrepro.port.slider_crank import newton  # noqa: F401
    assert not hasattr(position, "residual") and not hasattr(position, "dfp")


def test_the_upper_speed_bound_is_the_same_for_every_engine():
    """rpm = 1e6 (LARGEST) was refused by the corrected model, which rebuilt rpm from omega
    (1000000.0000000001).  The objective is normalized by C1 ~ omega^4 and the loads grow as
    omega^2, so its 'before' column does not depend on the speed: equal to 3000 rpm's."""
    fast = balance(CsspInputs(rpm=1e6), CSSP_CORRECTED)["table"][:, 0]
    slow = balance(CsspInputs(), CSSP_CORRECTED)["table"][:, 0]
    np.testing.assert_allclose(fast, slow, rtol=1e-12)
    balance(CsspInputs(rpm=1e6), CSSP_PRINTED)


@pytest.mark.parametrize("name", ["a1", "a2"])
def test_a_crank_or_rod_shorter_than_the_smallest_length_is_refused_by_every_engine(name):
    """a1 = 5e-324 in gave NaN joint forces (-T / a1 overflowed) with converged rows (the
    issue 31 fuzz); the slider crank's a1 and a2 now have the K.E.D. links' floor, 1e-6 in."""
    with pytest.raises(ValueError, match=f"{name} = 5e-324 is out of range"):
        GscInputs(**{name: 5e-324})
    with pytest.raises(ValueError, match=f"{name} = 5e-324 is out of range"):
        CsspInputs(**{name: 5e-324})
    with pytest.raises(ValueError, match=f"{name} = 5e-324 is out of range"):
        rahman1996.cssp(**{name: 5e-324})


BAD_TYPE = st.sampled_from(["2", None, True, [1.0], complex(1, 0)])
BAD_VALUE = st.sampled_from([float("nan"), float("inf"), -2.0, 2e6, HUGE])
GOOD = {"a1": 2.0, "a2": 8.0, "a4": 1.0, "alpha4_deg": 250.0, "s1": 0.4, "rpm": 3000.0}


@settings(max_examples=60)
@given(kinds=st.fixed_dictionaries({k: st.sampled_from(["good", "type", "value"]) for k in GOOD}),
       data=st.data())
def test_the_same_error_type_in_legacy_and_the_port_whatever_the_argument(kinds, data):
    """Any mix of wrong kinds and bad values among the six inputs: TypeError if any argument
    is of the wrong kind, else ValueError (-2.0 is bad only for a1, a2, rpm); the same from
    legacy's cssp and the port's CsspInputs."""
    args = {k: GOOD[k] if kind == "good" else data.draw(BAD_TYPE if kind == "type" else BAD_VALUE)
            for k, kind in kinds.items()}
    wrong_kind = "type" in kinds.values()
    bad_value = any(kinds[k] == "value" and not (args[k] == -2.0 and k not in ("a1", "a2", "rpm")) for k in GOOD)
    if not (wrong_kind or bad_value):
        return
    expected = TypeError if wrong_kind else ValueError
    for build in (lambda: rahman1996.cssp(**args), lambda: CsspInputs(**args)):
        with pytest.raises(expected):
            build()


def test_the_issues_example_of_the_order_rule():
    for build in (lambda: rahman1996.cssp(alpha4_deg=float("nan"), rpm="2"),
                  lambda: balance(CsspInputs(alpha4_deg=float("nan"), rpm="2"))):
        with pytest.raises(TypeError):
            build()


def test_errors_stay_typed_where_the_inputs_are_good():
    """A geometry that cannot close still gives a linkage error, not an argument error."""
    with pytest.raises((LinkageError, QPError)):
        balance(CsspInputs(a2=2.5), CSSP_CORRECTED)


def test_the_lower_level_functions_refuse_the_wrong_kind_of_argument():
    """Found by the fuzz: Constants.of(Lengths(...)) and closed_loop_loads('x', ...) raised
    AttributeError, listing_pass with a 3 x 3 q0 a numba TypingError."""
    c = Constants.of(CsspInputs(), True)
    with pytest.raises(TypeError):
        Constants.of(np.ones(5), True)
    with pytest.raises(TypeError):
        closed_loop_loads("x", np.array([10.0]))
    with pytest.raises(TypeError):
        listing_pass(np.array([0.0, 10.0]), initial_estimate(c, True), "c")
    with pytest.raises(ValueError):
        listing_pass(np.array([0.0, 10.0]), np.ones((3, 3)), c)
    with pytest.raises(TypeError):
        listing_pass(np.array([0.0, 10.0]), np.ones(5, dtype=bool), c)
