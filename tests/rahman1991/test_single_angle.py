"""Rahman (1991), the printed method called at single crank angles and in sweeps started
anywhere (issue 31): a row reported converged is a closed loop on the asked branch, the one
the sweep from 0 deg gives, against independent constructions (the complex-number planar
analysis, ``slider_crank.kinematics`` on either root, rotation matrices in numpy); what
misses it says so; angles are wrapped."""
import numpy as np
import pytest

from linkrepro.errors import ConvergenceError
from linkrepro.harness.scenes.rahman1991 import planar_reference
from linkrepro.port.rahman1991 import analysis as gsc, position
from linkrepro.port.rahman1991.data import GscInputs
from linkrepro.port.rahman1991.quirks import GSC_CORRECTED, GSC_PRINTED
from linkrepro.port.slider_crank.kinematics import kinematics

EXAMPLE = GscInputs()
PRINTED_FIXED = GSC_PRINTED.without("com_beyond_joint", "joint_force_signs")
TURN = np.arange(0.0, 361.0, 1.0)
POSITION = ["s4", "theta2", "eta2", "theta3", "eta3"]


def _rz(t):
    c, s, z, o = np.cos(t), np.sin(t), np.zeros_like(t), np.ones_like(t)
    return np.stack([np.stack([c, -s, z], -1), np.stack([s, c, z], -1), np.stack([z, z, o], -1)], -2)


def _ry(t):
    c, s, z, o = np.cos(t), np.sin(t), np.zeros_like(t), np.ones_like(t)
    return np.stack([np.stack([c, z, s], -1), np.stack([z, o, z], -1), np.stack([-s, z, c], -1)], -2)


def _rx(t):
    c, s, z, o = np.cos(t), np.sin(t), np.zeros_like(t), np.ones_like(t)
    return np.stack([np.stack([o, z, z], -1), np.stack([z, c, -s], -1), np.stack([z, s, c], -1)], -2)


def rotation_gap(inputs: GscInputs, frame) -> np.ndarray:
    """|Rz(theta1) Rz(theta2) Ry(eta2) Rz(theta3) Ry(eta3) Rx(pi/2) Rx(alpha4) - I| per row:
    the rotation part of the loop (eqs. 2, 3) from the row's angles, in numpy."""
    th1, t2, e2, t3, e3 = (np.radians(frame[k].to_numpy(float)) for k in ("crank_deg", "theta2", "eta2", "theta3", "eta3"))
    loop = _rz(th1) @ _rz(t2) @ _ry(e2) @ _rz(t3) @ _ry(e3) @ _rx(np.full_like(t3, np.pi / 2)) @ _rx(
        np.full_like(t3, inputs.alpha4))
    return np.linalg.norm(loop - np.eye(3), axis=(1, 2))


def closed_form(inputs: GscInputs, crank_deg, branch: int) -> dict:
    """S4 (in), theta2 (deg, [0, 360)), eta2 (deg) of the exact loop on a root of |Q - P| = a2."""
    kin = kinematics(inputs, np.radians(crank_deg), np.stack(inputs.axial(np.radians(crank_deg))), branch=branch)
    return {"s4": kin.s4, "theta2": np.degrees(kin.theta2), "eta2": np.degrees(kin.eta2)}


def angle_gap(a, b) -> np.ndarray:
    """|a - b| of angles (deg), modulo 360."""
    return np.abs((np.asarray(a) - np.asarray(b) + 180.0) % 360.0 - 180.0)


def assert_on_branch(inputs: GscInputs, frame, branch: int, scale: float = 1e-6) -> None:
    """Every row converged, on ``branch`` (reported), equal to the closed form there, its
    rotation loop closed."""
    assert frame.converged.all(), frame[~frame.converged][["crank_deg", "status", "closure"]]
    assert (frame.branch == branch).all()
    exact = closed_form(inputs, frame.crank_deg.to_numpy(), branch)
    size = inputs.a1 + inputs.a2 + abs(inputs.a4)
    assert np.max(np.abs(frame.s4 - exact["s4"])) < scale * size
    assert np.max(angle_gap(frame.theta2, exact["theta2"])) < 1e-5 and np.max(angle_gap(frame.eta2, exact["eta2"])) < 1e-5
    assert np.max(rotation_gap(inputs, frame)) < scale


@pytest.fixture(scope="module")
def single_angle_calls():
    """``analyse`` of the example at each whole degree of the turn, one call per angle (as
    printed); the same positions' loads with two sign bugs fixed (D086, D088)."""
    calls = [gsc.analyse(EXAMPLE, [d], GSC_PRINTED) for d in TURN]
    runs = [position.positions(EXAMPLE, np.radians([d])) for d in TURN]
    solved = position.PositionRun(*(np.concatenate([getattr(r, k) for r in runs])
                                    for k in ("q", "status", "closure", "iterations", "branch")))
    return {GSC_PRINTED: gsc.pd.concat(calls, ignore_index=True),
            PRINTED_FIXED: gsc.analyse(EXAMPLE, TURN, PRINTED_FIXED, positions=solved)}


def test_every_single_angle_call_of_the_example_is_the_complex_number_analysis(single_angle_calls):
    """361 calls, one angle each (102 of them closed the loop elsewhere, or not at all, before):
    positions against the complex-number analysis, forces (two sign bugs fixed) too."""
    frame = single_angle_calls[PRINTED_FIXED]
    ref = planar_reference.analyse(TURN, torque=-EXAMPLE.torque)
    assert_on_branch(EXAMPLE, frame, 1)
    assert np.max(np.abs(frame.s4 - ref["s4"])) < 1e-6
    assert np.max(angle_gap(frame.theta2, np.degrees(ref["th_rod"] - ref["theta1"]))) < 1e-5   # deg: 1e-7 rad
    away = np.abs(np.sin(ref["th_rod"] - ref["theta1"])) > np.sin(np.radians(2.0)) * 0.2   # off the dead centres
    for name, values in planar_reference.in_thesis_frames(ref).items():
        assert np.max(np.abs(frame[name] - values)[away]) < 1e-6 * np.max(np.abs(values[away])), name


def test_every_single_angle_call_of_the_example_is_the_sweep_from_zero(single_angle_calls):
    frame, sweep = single_angle_calls[GSC_PRINTED], gsc.analyse(EXAMPLE, TURN, GSC_PRINTED)
    assert sweep.converged.all() and (sweep.status == position.NEWTON).all()
    # to the Newton's tolerance (every |Delta| <= 1e-7 in, rad)
    assert np.max(np.abs(frame.s4 - sweep.s4)) < 1e-6 and np.max(angle_gap(frame[POSITION[1:]], sweep[POSITION[1:]])) < 1e-5
    ref = planar_reference.analyse(TURN)
    away = np.abs(np.sin(ref["th_rod"] - ref["theta1"])) > np.sin(np.radians(2.0)) * 0.2   # the poles: D091
    loads = frame[gsc.gsc_forces.COMPONENTS][away].to_numpy()
    of_sweep = sweep[gsc.gsc_forces.COMPONENTS][away].to_numpy()
    assert np.max(np.abs(loads - of_sweep)) < 1e-5 * np.max(np.abs(of_sweep))


@pytest.mark.parametrize("start", [46.0, 180.0, 300.5, -90.0])
def test_a_sweep_started_anywhere_is_the_sweep_from_zero(start):
    """A full turn from ``start`` (1-deg steps) and the turn's angles in random order."""
    deg = start + TURN
    assert_on_branch(EXAMPLE, gsc.analyse(EXAMPLE, deg), 1)
    assert_on_branch(EXAMPLE, gsc.analyse(EXAMPLE, np.random.default_rng(int(start) % 7).permutation(deg)), 1)


def test_the_unchecked_newton_says_what_it_found():
    """branch=None, the printed Newton alone from the plane-geometry estimate: at 46 deg it
    stops where the loop is open, at 48 deg it closes it on the other assembly (the issue's
    two cases); asked for a branch the same calls give the closed loop on it."""
    at46, at48 = (gsc.analyse(EXAMPLE, [d], branch=None).iloc[0] for d in (46.0, 48.0))
    assert at46.status == f"{position.NEWTON}: {position.LOOP_OPEN}" and not at46.converged
    assert at46.closure > 1e3 * position.closure_tolerance(EXAMPLE, 0.0)
    assert at48.converged and at48.branch == -1.0
    assert at48.s4 == pytest.approx(closed_form(EXAMPLE, [48.0], -1)["s4"][0], abs=1e-6)
    for d, branch, status in ((46.0, 1, position.RESTARTED), (46.0, -1, position.RESTARTED),
                              (48.0, 1, position.RESTARTED), (48.0, -1, position.NEWTON)):
        asked = gsc.analyse(EXAMPLE, [d], branch=branch)
        assert asked.status.iloc[0] == status
        assert_on_branch(EXAMPLE, asked, branch)
    with pytest.raises(ConvergenceError, match="does not close") as error:
        gsc.analyse(EXAMPLE, [46.0], branch=None, strict=True)
    assert error.value.angle_deg == 46.0


@pytest.mark.parametrize("seed", range(4))
def test_random_planar_configurations_on_either_branch(seed):
    """Random lengths and offsets, the slider axis at 90 or 270 deg, S1 = 0 (the five-variable
    loop closes): single angles, a sweep from 0 and one from a random angle, on each branch
    (where the rod reaches the axis at every angle; the branch is then defined everywhere)."""
    rng = np.random.default_rng(seed)
    a1 = rng.uniform(1.0, 30.0)
    inputs = GscInputs(a1=a1, a2=rng.uniform(1.2, 4.0) * a1, a4=rng.uniform(-0.15, 0.15) * a1,
                       alpha4_deg=float(rng.choice([90.0, 270.0])), s1=0.0)
    for branch in (1, -1):
        single = gsc.pd.concat([gsc.analyse(inputs, [d], branch=branch) for d in rng.uniform(-360.0, 720.0, 24)])
        assert_on_branch(inputs, single, branch)
        for start in (0.0, rng.uniform(0.0, 360.0)):
            assert_on_branch(inputs, gsc.analyse(inputs, start + np.arange(0.0, 361.0, 2.0), branch=branch), branch)
        corrected = gsc.analyse(inputs, single.crank_deg, GSC_CORRECTED, branch=branch)
        assert np.max(np.abs(corrected.s4.to_numpy() - single.s4.to_numpy())) < 1e-6 * inputs.a2


@pytest.mark.parametrize("seed", range(3))
def test_random_spatial_configurations_report_open_loops(seed):
    """Off the plane the five variables cannot close the loop (D085): a row is converged only
    where it closes to CLOSURE_RTOL; the rest say "loop open" (or did not stop), keep the
    printed method's answer, and report its branch, the sign of S4 + b."""
    rng = np.random.default_rng(100 + seed)
    inputs = GscInputs(a4=rng.uniform(0.0, 30.0), alpha4_deg=rng.uniform(200.0, 340.0), s1=rng.uniform(0.5, 9.0))
    deg = rng.uniform(0.0, 360.0, 40)
    frames = [gsc.analyse(inputs, [d]) for d in deg] + [gsc.analyse(inputs, deg)]
    frame = gsc.pd.concat(frames, ignore_index=True)
    th = np.radians(frame.crank_deg)
    limit = position.closure_tolerance(inputs, inputs.s1)
    assert (frame.closure[frame.converged] <= limit).all()
    open_ = frame.status.str.endswith(position.LOOP_OPEN)
    assert open_.sum() > 20 and (frame.closure[open_] > limit).all() and not frame.converged[open_].any()
    assert frame[open_].s4.notna().all()
    side = frame.s4 + inputs.a1 * np.sin(inputs.alpha4) * np.sin(th) + inputs.s1 * np.cos(inputs.alpha4)
    answered = frame.status.isin(gsc.ANSWERED)
    assert (frame.branch[answered] == np.sign(side[answered])).all()
    if frame.converged.any():
        assert_on_branch(inputs, frame[frame.converged], 1, scale=10 * position.CLOSURE_RTOL * 50)


def test_angles_are_wrapped():
    """theta in [0, 360), eta in [-180, 180) in every row of both engines (off the plane the
    printed Newton wandered to eta2 = -2.2e6 deg before)."""
    frames = [gsc.analyse(GscInputs(a4=a4, alpha4_deg=al, s1=s1), quirks=q)
              for a4, al, s1 in ((30.0, 310.0, 9.0), (10.0, 232.0, 3.0), (0.0, 90.0, 0.0)) for q in (GSC_PRINTED, GSC_CORRECTED)]
    frame = gsc.pd.concat(frames + [gsc.analyse(EXAMPLE, [-1e-30, 720.0, -180.0])])
    for name in ("theta2", "theta3"):
        values = frame[name].dropna()
        assert ((values >= 0.0) & (values < 360.0)).all(), name
    for name in ("eta2", "eta3"):
        values = frame[name].dropna()
        assert ((values >= -180.0) & (values < 180.0)).all(), name
    turned = frames[4]                                  # the slider axis at 90 deg: its frame upside down
    assert turned.converged.all() and np.max(angle_gap(turned.eta3, 180.0)) < 1e-5
    assert gsc.wrapped_deg(np.array([-1e-300, 2 * np.pi, 7 * np.pi]), False).tolist() == [0.0, 0.0, 180.0]
    assert gsc.wrapped_deg(np.array([np.pi, -np.pi, 3 * np.pi, 1e-300]), True).tolist() == [-180.0, -180.0, -180.0, np.degrees(1e-300)]


def test_the_crank_angles_are_given_back_as_asked():
    """crank_deg holds the angles the caller asked for, not their round trip through radians
    (48 deg came back as 48.00000000000001), in both models and in the strict error."""
    asked = np.arange(0.0, 361.0)
    for quirks in (GSC_PRINTED, GSC_CORRECTED):
        assert gsc.analyse(EXAMPLE, asked, quirks).crank_deg.tolist() == asked.tolist()
    with pytest.raises(ConvergenceError) as caught:
        gsc.analyse(GscInputs(a4=30.0, alpha4_deg=310.0, s1=9.0), [48.0], strict=True)
    assert caught.value.angle_deg == 48.0


def test_branch_argument_is_checked():
    for bad, error in ((0, ValueError), (2, ValueError), (1.0, TypeError), (True, TypeError), ("1", TypeError)):
        with pytest.raises(error):
            gsc.analyse(EXAMPLE, [0.0], branch=bad)
        with pytest.raises(error):
            position.positions(EXAMPLE, [0.0], branch=bad)


@pytest.mark.parametrize("seed", range(3))
def test_the_branch_is_the_rods_reach_along_the_slider_travel(seed):
    """S4 + b = (Q - P) . (-k4): the branch is the side of the rod's normal plane the slider is
    on (``slider_crank.kinematics`` on each root, spatial configurations, harmonic S1)."""
    rng = np.random.default_rng(200 + seed)
    inputs = GscInputs(a4=rng.uniform(-10.0, 10.0), alpha4_deg=rng.uniform(0.0, 360.0), s1=rng.uniform(-5.0, 5.0),
                       alpha=float(rng.choice([0.0, 1.0])))
    th = np.radians(np.arange(0.0, 360.0, 7.0))
    s1 = inputs.axial(th)[0]
    for branch in (1, -1):
        kin = kinematics(inputs, th, np.stack(inputs.axial(th)), branch=branch)
        reach = (kin.Q - kin.P) @ -inputs.k4
        side = kin.s4 + inputs.a1 * np.sin(inputs.alpha4) * np.sin(th) + s1 * np.cos(inputs.alpha4)
        np.testing.assert_allclose(reach, side, atol=1e-12 * inputs.a2)
        assert (np.sign(reach) == branch).all()
        printed = position.positions(inputs, th, branch=branch)
        assert (printed.branch[printed.stopped] == np.sign(printed.q[printed.stopped, 4] + (side - kin.s4)[printed.stopped])).all()


def test_the_fuzz_check_flags_a_converged_row_that_is_not_the_position():
    """The fuzz's check (harness/scenes/rahman1991/fuzz.py) passes the analysis and flags a
    row moved to the other root, off its reported branch, in the other angles, or open."""
    from linkrepro.harness.scenes.rahman1991.fuzz import CHECKS
    check = CHECKS["gsc_closes"]
    call = ([], {"inputs": EXAMPLE, "crank_deg": [48.0, 200.0]})
    frame = gsc.analyse(EXAMPLE, [48.0, 200.0])
    assert check(call, frame) is None and check(([], {"branch": -1}), gsc.analyse(EXAMPLE, branch=-1)) is None
    spatial = GscInputs(a4=30.0, s1=3.5)
    assert check(([spatial], {"quirks": GSC_CORRECTED}), gsc.analyse(spatial, quirks=GSC_CORRECTED)) is None
    other = closed_form(EXAMPLE, [48.0], -1)["s4"][0]
    broken = [frame.assign(s4=[other, frame.s4[1]]), frame.assign(branch=[-1.0, 1.0]),
              frame.assign(closure=[1.0, 0.0]),
              frame.assign(theta2=(frame.theta2 + 180.0) % 360.0, eta2=180.0 - frame.eta2,
                           theta3=(180.0 - frame.theta3) % 360.0, eta3=frame.eta3 + 180.0)]
    words = ["does not close", "branch -1 reported", "closure 1 passes", "is not the closed form's"]
    for bad, said in zip(broken, words):
        assert said in check(call, bad)
