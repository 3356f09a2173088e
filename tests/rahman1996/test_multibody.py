"""The corrected CSSP engine against Exudyn, an independently written multibody code
(scene rahman1996-multibody; skipped without Exudyn: ``pip install 'linkrepro[multibody]'``).

Exudyn integrates the mechanism in time from the port's position and velocities at 0 deg; the
port computes each position's kinematics in closed loop.  The step: at 0.2 deg the measured
differences are 3.0e-6, 3.0e-6 and 3.8e-6 of the peaks of Tables 5.3, 5.4 and 5.7 (falling as
h^2: 7e-5 at 1 deg, 8e-7 at 0.1 deg), so 1e-5 of the peak holds with a margin of 2.6 and is
still small enough to tell the crank pin's two readings apart (the spherical one moves the
moment by 2.4e-4 of its peak).  The scene's own step is the bench's choice; the tests here check
that the difference falls as the integrator's order says and that the scene's one revolution is
past the solver's start-up.
"""
from pathlib import Path

import numpy as np
import pytest

from tests.multibody import needs_exudyn

exudyn = needs_exudyn()

from linkrepro.harness.scenes.rahman1996 import multibody as scene  # noqa: E402

STEP_DEG = 0.2
TOLERANCE = 1e-5
SEEDS = Path(__file__).resolve().parents[3] / "shared" / "seeds"


@pytest.fixture(scope="module")
def port():
    return scene.port_columns()


@pytest.fixture(scope="module")
def runs(port):
    columns, masses = port
    return {(kind, pin): scene.simulate(masses[kind], pin, STEP_DEG) for kind in scene.MASSES for pin in scene.JOINTS}


@pytest.mark.parametrize("kind", scene.MASSES)
def test_the_port_s_joint_reading_agrees_with_exudyn(port, runs, kind):
    for table, (peak, difference) in scene.agreement(port[0][kind], runs[kind, "universal"]).items():
        assert difference < TOLERANCE * peak, (kind, table, difference / peak)


@pytest.mark.parametrize("kind", scene.MASSES)
def test_a_spherical_crank_pin_moves_the_moment_and_the_torque_not_the_force(port, runs, kind):
    """The comparison tells the two readings apart: the rod's free spin changes its angular
    momentum (the moment, the torque) but not the centres of mass (the force)."""
    found = scene.agreement(port[0][kind], runs[kind, "spherical"])
    assert found["5_3"][1] < TOLERANCE * found["5_3"][0]
    for table in ("5_4", "5_7"):
        assert found[table][1] > 5 * TOLERANCE * found[table][0], table


def test_the_ground_reactions_balance_the_inertia_forces(port, runs):
    """Newton's law inside Exudyn: its ground joints' reaction forces are minus the sum of its
    bodies' m a, to round-off (the force of Table 5.3 by a second path)."""
    for ex in runs.values():
        assert ex["ground_residual"].iloc[0] < 1e-9 * port[0]["before"]["5_3"].abs().max()


def test_the_difference_falls_as_the_step_squared(port, runs):
    """Exudyn's generalized-alpha scheme is second order: from 1 deg to this module's step the
    largest difference of each column falls as the step squared (order 2 within 0.1)."""
    coarse = scene.agreement(port[0]["before"], scene.simulate(port[1]["before"], "universal", 1.0))
    fine = scene.agreement(port[0]["before"], runs["before", "universal"])
    for table in coarse:
        order = np.log(coarse[table][1] / fine[table][1]) / np.log(1.0 / STEP_DEG)
        assert abs(order - 2.0) < 0.1, (table, order)


def test_one_revolution_at_the_scene_s_step_is_past_the_solver_s_start_up(port, runs):
    """At the scene's step the comparison reads one revolution from 0 deg (``revolutions``): its
    difference is what the h^2 law predicts from this module's step, not the start-up's (which
    at 1 deg, one revolution, is measured at 4e-2 of the peak)."""
    assert scene.revolutions(scene.STEP_DEG) == 1 and scene.revolutions(STEP_DEG) == 2
    coarse = scene.agreement(port[0]["before"], runs["before", "universal"])
    found = scene.agreement(port[0]["before"], scene.simulate(port[1]["before"], "universal"))
    for table, (peak, difference) in found.items():
        assert difference < 1.5 * coarse[table][1] * (scene.STEP_DEG / STEP_DEG) ** 2, (table, difference / peak)


def test_the_wrong_masses_are_caught(port, runs):
    """The 'after' Exudyn run against the 'before' port columns: the moment and the torque differ
    beyond the tolerance, so the comparison sees a change of the masses."""
    found = scene.agreement(port[0]["before"], runs["after", "universal"])
    assert found["5_4"][1] > 100 * TOLERANCE * found["5_4"][0]


def test_an_unknown_crank_pin_is_refused(port):
    with pytest.raises(ValueError, match="crank_pin"):
        scene.simulate(port[1]["before"], "cylindrical", 1.0)


@pytest.mark.skipif(not SEEDS.is_dir(), reason="the seeds (../shared/seeds) are not at hand")
def test_the_1996_thesis_gives_no_stiffness_of_its_links():
    """The scene's report says so; the thesis's text names no modulus, stiffness or elasticity."""
    text = (SEEDS / "000_27bd930f3bd30dfe.txt").read_text().lower()
    for word in ("modulus", "stiffness", "elastic", "young's", "rigidity"):
        assert word not in text, word
