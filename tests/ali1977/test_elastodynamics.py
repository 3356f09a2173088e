"""The elastodynamics scene (ali1977-elastodynamics) at coarse settings: what it builds on can fail.

- the frozen linkage's frequencies from Exudyn's Jacobian equal those of the thesis's flexibility
  (the corrected port's beta^T F beta, eq. 29), and a free vibration of the frozen linkage in
  Exudyn's time integration has that frequency and the stated damping ratio;
- a clamped beam with a tip mass, built here from the same elements and settings, vibrates at
  Euler-Bernoulli's sqrt(3 EI / (m L^3)) / 2 pi with the thesis's section;
- at 20 rpm the elastodynamic steady state is the port's quasi-static deflection, which is its
  300 rpm answer times (20/300)^2;
- halving the step or doubling the mesh moves a steady state by less than stated, the nonlinear
  statics by less than 1 % of their gap from the linear answer;
- a run seeded from a converged neighbouring speed ends on the steady state of one started undeformed;
- the periodic solution of the thesis's structure run dynamically (``linear_periodic``) is where
  a plain time march from rest ends up.

Units: inch, lbf, second; angles in degrees.
"""
from tests.multibody import needs_exudyn

exudyn = needs_exudyn()

import math  # noqa: E402

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from linkrepro.harness.scenes.ali1977 import elastodynamics as ed  # noqa: E402
from linkrepro.harness.scenes.ali1977 import structure_dynamics as sd  # noqa: E402
from linkrepro.harness.scenes.ali1977 import multibody as mb  # noqa: E402
from linkrepro.port.ali1977.case1 import source_case1, source_mechanics  # noqa: E402
from linkrepro.port.ali1977.cognate import cognate_mechanics  # noqa: E402
from linkrepro.port.ali1977.data import EXAMPLE  # noqa: E402
from linkrepro.port.ali1977.quirks import CORRECTED  # noqa: E402
from linkrepro.port.ali1977.structure import GRAVITY_IN, flexibility  # noqa: E402


def _settings(model_settings, step: float, duration: float):
    """The scene's time-integration settings, for a fixed step (s) over ``duration`` (s)."""
    s = model_settings
    s.linearSolver.solverType = exudyn.LinearSolverType.EigenSparse
    s.timeIntegration.numberOfSteps = int(round(duration / step))
    s.timeIntegration.endTime = duration
    s.timeIntegration.adaptiveStep = False
    s.timeIntegration.newton.useModifiedNewton = False
    s.timeIntegration.generalizedAlpha.spectralRadius = ed.SPECTRAL_RADIUS
    s.timeIntegration.generalizedAlpha.computeInitialAccelerations = False
    return s


def _decay(signal: np.ndarray, step: float) -> tuple[float, float]:
    """(frequency in Hz, damping ratio) of a decaying oscillation about 0: upward zero crossings
    (interpolated) and the logarithmic decrement of its positive peaks."""
    up = np.flatnonzero((signal[:-1] < 0.0) & (signal[1:] >= 0.0))
    crossings = (up - signal[up] / (signal[up + 1] - signal[up])) * step
    frequency = (len(crossings) - 1) / (crossings[-1] - crossings[0])
    peaks = [i for i in range(1, len(signal) - 1) if signal[i - 1] < signal[i] >= signal[i + 1] and signal[i] > 0.0]
    decrement = math.log(signal[peaks[0]] / signal[peaks[-1]]) / (len(peaks) - 1)
    return frequency, decrement / math.sqrt(4.0 * math.pi ** 2 + decrement ** 2)


@pytest.mark.parametrize("side, deg", [("source", 0.0), ("source", 20.0), ("source", 200.0), ("cognate", 20.0),
                                       ("cognate", 200.0)])
def test_frozen_frequencies_are_those_of_the_thesis_flexibility(side, deg):
    """Exudyn's stiffness at the path point (its Jacobian condensed, 2 and 4 elements per link: the
    scene's mesh and twice it) gives the frequencies of the mass on the port's compliance beta^T F
    beta, to rounding: the thesis's eq. (29) is the linear statics of Euler-Bernoulli links (source
    and cognate; frequencies do not depend on the frame)."""
    mechanics = source_mechanics if side == "source" else cognate_mechanics
    mech = mechanics(np.array([deg]), quirks=CORRECTED)
    flex = flexibility(*mech.flex_lengths, EXAMPLE.section, CORRECTED)
    compliance = (mech.beta[0].T @ flex @ mech.beta[0])[:2, :2]
    mass = EXAMPLE.mass_lbf / GRAVITY_IN
    port = np.sort(np.sqrt(np.linalg.eigvals(np.linalg.inv(compliance) / mass).real)) / (2.0 * math.pi)
    for elements in (ed.FREQUENCY_ELEMENTS, 2 * ed.FREQUENCY_ELEMENTS):
        stiffness, check = ed.exudyn_stiffness(deg, elements=elements, side=side)
        assert check < 1e-9
        assert ed.frequencies_of(stiffness) == pytest.approx(port, rel=1e-9)


@pytest.mark.parametrize("side", ["source", "cognate"])
def test_the_nonlinear_statics_barely_move_with_twice_the_mesh_or_the_load_steps(side):
    """The scene's nonlinear statics (STATIC_ELEMENTS per link, LOAD_STEPS load steps, the 300 rpm
    load) at 0, 120 and 240 deg: twice the mesh or twice the load steps moves the deflection by less
    than 1 % of the largest gap between the nonlinear and the linear answer there (the study's
    headline, the gap over the peak, holds to 1 %)."""
    gaps, changes = [], []
    for deg in (0.0, 120.0, 240.0):
        linear, nonlinear = ed.exudyn_static(deg, side=side)
        _, fine = ed.exudyn_static(deg, 2 * ed.STATIC_ELEMENTS, side=side)
        _, stepped = ed.exudyn_static(deg, load_steps=2 * ed.LOAD_STEPS, side=side)
        gaps.append(np.hypot(*(nonlinear - linear)))
        changes += [np.hypot(*(fine - nonlinear)), np.hypot(*(stepped - nonlinear))]
    assert max(changes) < 0.01 * max(gaps)


@pytest.mark.parametrize("deg", [20.0, 200.0])
def test_free_vibration_of_the_frozen_linkage(deg):
    """The frozen linkage (8 elements per link, lumped mass, damped as the scene damps it) under a
    small suddenly applied Case I load: its path point's motion along the first mode oscillates at
    the first frequency of the port's flexibility (damped: f1 sqrt(1 - zeta1^2)) to 0.3 %, and
    decays with zeta1 = ZETA f1 / DAMPING_HZ (stiffness-proportional damping) to 2 %."""
    model = mb.build("source", deg, 1, ed.ELEMENTS, shear_per_element=ed.SHEAR_PER_ELEMENT, load_scale=1e-3)
    equilibrium = model.linear_deflection()[:2]
    model.damp(ed.damping_beta(ed.ZETA))
    track = []
    model.mbs.SetPreStepUserFunction(
        lambda mbs, t: track.append(mbs.GetNodeOutput(model.path_node, exudyn.OutputVariableType.Displacement)[:2])
        or True)
    model.mbs.Assemble()
    step = 5e-4
    model.mbs.SolveDynamic(_settings(model.settings, step, 1.5))
    stiffness = ed.port_stiffness([deg])[0]
    w2, modes = np.linalg.eigh(stiffness / sd.MASS)
    f1 = math.sqrt(w2[0]) / (2.0 * math.pi)
    zeta1 = ed.ZETA * f1 / sd.DAMPING_HZ
    frequency, zeta = _decay((np.asarray(track) - equilibrium) @ modes[:, 0], step)
    assert frequency == pytest.approx(f1 * math.sqrt(1.0 - zeta1 ** 2), rel=3e-3)
    assert zeta == pytest.approx(zeta1, rel=2e-2)


def test_clamped_beam_with_a_tip_mass_against_euler_bernoulli():
    """A 10 in beam of the thesis's section, clamped, massless, the path-point mass at its tip,
    built from the scene's elements (4 of them, shear 12 EI / h^2 per element) and integrated as the
    scene integrates: its free vibration has Euler-Bernoulli's frequency sqrt(3 EI / (m L^3)) / 2 pi
    to 0.3 %, and the damping ratio zeta f / DAMPING_HZ to 2 %."""
    from exudyn.itemInterface import (CoordinateConstraint, LoadForceVector, MarkerNodeCoordinate, MarkerNodePosition,
                                      NodePointGround, NodeRigidBody2D, ObjectBeamGeometricallyExact2D,
                                      ObjectMassPoint2D)
    sec, length, count = EXAMPLE.section, 10.0, 4
    ei, ea, h = sec.modulus * sec.inertia, sec.modulus * sec.area, length / count
    beta = ed.damping_beta(ed.ZETA)
    mbs = exudyn.SystemContainer().AddSystem()
    nodes = [mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[k * h, 0.0, 0.0])) for k in range(count + 1)]
    shear = ed.SHEAR_PER_ELEMENT * 12.0 * ei / (h * h)
    for n0, n1 in zip(nodes[:-1], nodes[1:]):
        mbs.AddObject(ObjectBeamGeometricallyExact2D(nodeNumbers=[n0, n1], length=h, bendingStiffness=ei,
                                                     axialStiffness=ea, shearStiffness=shear, bendingDamping=beta * ei,
                                                     axialDamping=beta * ea, shearDamping=beta * shear))
    ground = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=mbs.AddNode(NodePointGround()), coordinate=0))
    for c in range(3):
        mbs.AddObject(CoordinateConstraint(markerNumbers=[ground, mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nodes[0],
                                                                                                       coordinate=c))]))
    mass = EXAMPLE.mass_lbf / GRAVITY_IN
    mbs.AddObject(ObjectMassPoint2D(nodeNumber=nodes[-1], mass=mass))
    force = 0.1
    mbs.AddLoad(LoadForceVector(markerNumber=mbs.AddMarker(MarkerNodePosition(nodeNumber=nodes[-1])),
                                loadVector=[0.0, force, 0.0]))
    track = []
    mbs.SetPreStepUserFunction(lambda m, t: track.append(m.GetNodeOutput(nodes[-1], exudyn.OutputVariableType.Displacement)[1])
                               or True)
    mbs.Assemble()
    settings = exudyn.SimulationSettings()
    settings.timeIntegration.newton.relativeTolerance = ed.NEWTON_TOLERANCE
    settings.parallel.numberOfThreads = 1
    settings.solution.file.write = False
    step = 2e-4
    mbs.SolveDynamic(_settings(settings, step, 0.5))
    tip = force * length ** 3 / (3.0 * ei)                        # the static tip deflection
    closed = math.sqrt(3.0 * ei / (mass * length ** 3)) / (2.0 * math.pi)
    zeta_closed = ed.ZETA * closed / sd.DAMPING_HZ
    frequency, zeta = _decay(np.asarray(track) - tip, step)
    assert frequency == pytest.approx(closed * math.sqrt(1.0 - zeta_closed ** 2), rel=3e-3)
    assert zeta == pytest.approx(zeta_closed, rel=2e-2)


def test_at_20_rpm_the_dynamics_is_the_port_quasi_static_answer():
    """At 20 rpm (crank 1/3 Hz, 1/27 of the lowest first frequency) the steady state (4 elements per
    link) is periodic and within 2 % of the peak of the port's quasi-static deflection, which is its
    300 rpm deflection times (20/300)^2 (constant crank speed: every acceleration scales so); the
    dynamic part, 1.2 % of the peak, is what the thesis's structure run dynamically gives too."""
    run = ed.steady_state(20.0, elements=4)
    assert run.period == 1 and run.periodicity < ed.PERIODICITY_IN
    at_300 = source_case1(run.deg, rpm=300.0, quirks=CORRECTED)
    expected = np.column_stack([at_300["dx"], at_300["dy"]]) * (20.0 / 300.0) ** 2
    peak = np.hypot(*expected.T).max()
    assert np.hypot(*(run.deflection - expected).T).max() < 0.02 * peak
    # and the thesis's structure run dynamically (the port's stiffness, our time integration) is
    # Exudyn's answer to 0.5 % of the peak (geometric nonlinearity is small at these deflections)
    linear, _ = ed.linear_periodic([20.0], ed.ZETA, run.steps)
    assert np.hypot(*(run.deflection - linear[0]).T).max() < 0.005 * peak


def test_halving_the_step_or_doubling_the_mesh_barely_moves_a_steady_state():
    """At 100 rpm (4 elements per link, 360 steps per revolution), where the quasi-static answer is
    already off by about 40 % of its peak: 720 steps move the steady state by less than 1 % of that
    peak, 8 elements by less than 0.5 %; every run periodic to PERIODICITY_IN."""
    base = ed.steady_state(100.0, elements=4, steps=360)
    peak = np.hypot(*ed.quasi_static(base.deg, 100.0).T).max()
    finer_step = ed.steady_state(100.0, elements=4, steps=720)
    finer_mesh = ed.steady_state(100.0, elements=8, steps=360)
    for run in (base, finer_step, finer_mesh):
        assert run.period == 1 and run.periodicity < ed.PERIODICITY_IN
    assert ed.orbit_change(finer_step, base) < 0.01 * peak
    assert ed.orbit_change(finer_mesh, base) < 0.005 * peak
    _, _, error = ed.error_of(base.deflection, ed.quasi_static(base.deg, 100.0))
    assert error > 0.3 * peak                       # the effect measured is far above both


def test_linear_periodic_is_where_a_time_march_from_rest_ends():
    """The thesis's structure run dynamically: ``linear_periodic``'s fixed point against a plain
    trapezoidal march of m u'' + beta K u' + K u = -m a from rest over 40 revolutions (100 rpm)."""
    rpm, steps = 100.0, 360
    orbit, decay = ed.linear_periodic([rpm], ed.ZETA, steps)
    assert decay[0] < 0.5
    deg = np.arange(steps) * 360.0 / steps
    stiffness = ed.port_stiffness(deg)
    load = -sd.MASS * source_mechanics(deg, rpm=rpm, quirks=CORRECTED).acc
    beta, h = ed.damping_beta(ed.ZETA), 60.0 / rpm / steps
    u, v = np.zeros(2), np.zeros(2)
    a = load[0] / sd.MASS
    for n in range(40 * steps):
        j = (n + 1) % steps
        k = stiffness[j]
        # m a1 + beta K v1 + K u1 = P1, u1 = u + h/2 (v + v1), v1 = v + h/2 (a + a1)
        lhs = sd.MASS * 4.0 / h ** 2 * np.eye(2) + beta * k * 2.0 / h + k
        rhs = load[j] + sd.MASS * (4.0 / h ** 2 * u + 4.0 / h * v + a) + beta * k @ (2.0 / h * u + v)
        u1 = np.linalg.solve(lhs, rhs)
        v1 = 2.0 / h * (u1 - u) - v
        a = 4.0 / h ** 2 * (u1 - u) - 4.0 / h * v - a
        u, v = u1, v1
        if n >= 39 * steps:
            assert np.abs(u - orbit[0, j]).max() < 1e-9


def test_the_low_damping_steady_state_does_not_depend_on_the_start():
    """At ZETA_LOW (2 %) and 300 rpm with the links' own mass (the scene's method: the massless links'
    run fails in Exudyn's start-up), runs started undeformed at 0, 90, 180 and 270 deg end on the
    same steady state: every orbit within 1e-3 in (about 1.5e-4 of its 6.5 in peak; the periodicity
    tolerance is 1e-4 in) of the one started at 0 deg, and periodic (period 1)."""
    runs = [ed.steady_state(sd.RPM, zeta=sd.ZETA_LOW, link_mass=ed.LINK_MASS, start_deg=deg, cached=False)
            for deg in (0.0, 90.0, 180.0, 270.0)]
    assert all(run.period == 1 for run in runs)
    assert max(ed.orbit_change(runs[0], run) for run in runs[1:]) < 1e-3


def test_a_seeded_steady_state_is_the_one_from_an_undeformed_start():
    """A run started from a converged run at a neighbouring speed (``seed``, as the scene's limit
    searches do) ends on the steady state of the run started undeformed, whichever side the seed's
    speed lies: at 62 rpm and 2 % damping (the slowest decay the searches meet), seeded from 58 and
    from 66 rpm, every orbit within 2e-4 in (0.16 % of its 0.13 in peak; the periodicity tolerance
    is 1e-4 in) of the unseeded one's, in fewer revolutions; a seed of another model is refused."""
    plain = ed.steady_state(62.0, zeta=sd.ZETA_LOW, cached=False)
    for rpm in (58.0, 66.0):
        seed = ed.steady_state(rpm, zeta=sd.ZETA_LOW, cached=False)
        seeded = ed.steady_state(62.0, zeta=sd.ZETA_LOW, seed=seed, cached=False)
        assert seeded.period == 1 and seeded.seed_rpm == rpm
        assert ed.orbit_change(plain, seeded) < 2e-4
        assert seeded.revolutions < plain.revolutions
    with pytest.raises(ValueError, match="seed"):
        ed.steady_state(62.0, side="cognate", seed=seed, cached=False)


def test_speed_limit_finds_a_closed_form_crossing():
    """``speed_limit`` on ratio = 0.1 (rpm / 61.3)^2.7 (1 + 3 (rpm / 61.3 - 1)^2) (the error's growth
    below the limit, bent so that the log-log secant is not exact) finds 61.3 rpm to 0.1 %, from a
    guess 3 % off, and refuses a failed run (NaN) with ConvergenceError."""
    from linkrepro.errors import ConvergenceError
    calls = []

    def ratio(rpm):
        calls.append(rpm)
        return sd.ERROR_LEVEL * (rpm / 61.3) ** 2.7 * (1.0 + 3.0 * (rpm / 61.3 - 1.0) ** 2)
    assert sd.speed_limit(ratio, 61.3 * 1.03) == pytest.approx(61.3, rel=1e-3)
    assert len(calls) <= sd.LIMIT_RUNS
    with pytest.raises(ConvergenceError, match="NaN"):
        sd.speed_limit(lambda rpm: math.nan, 60.0)
