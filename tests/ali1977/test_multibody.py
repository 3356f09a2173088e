"""Ali's (1977) K.E.D. deflections: the corrected port's flexibility method against Exudyn's beam
finite elements of the same frozen structure (scene ali1977-multibody; skipped without Exudyn:
``pip install 'linkrepro[multibody]'``).

Tolerances, from the scene's measurements (37 crank angles; here 13, every 30 deg):

- ``TOLERANCE`` = 1e-9 of the peak deflection, for Exudyn with a shear stiffness of 12 EI/h^2 per
  element (the linear element's own h^2 error cancelled, so one coarse mesh is the
  Euler-Bernoulli answer): measured 1e-12 to 1.3e-11 of the peak at 2 elements per link over
  every case and side (rounding, which grows with the mesh: in Case III's extender, the finest,
  7e-11 at 4 elements per link, 1.3e-9 at 8), a margin of 75.  It is small enough that every bug
  of the Case I listings, down to their REAL*4 storage (3e-8 to 1e-7 of the peak), is caught
  (``test_every_listing_bug_is_caught``).
- ``STIFF_TOLERANCE`` = 2e-5 of the peak, for stiff shear (1e4 EA) with the mesh error c h^2
  extrapolated from 4 and 8 elements per link: measured at most 5.4e-6 (Case III, rounding),
  a margin of 3.7; one mesh of 8 elements is 3.9e-3 off (the h^2 term), 200 tolerances.

Case II is held against the corrected port like the others since the two bugs Exudyn found there
are quirks (D144: eq. (30)'s f7 entry; D145: the cognate's reversed crank and coupler loads); each
switched on alone moves the port away from Exudyn, which the tests pin down.
"""
import math
import warnings
from dataclasses import fields

import numpy as np
import pytest

from tests.multibody import needs_exudyn

exudyn = needs_exudyn()

from linkrepro.harness.scenes.ali1977 import multibody as mb  # noqa: E402
from linkrepro.harness.scenes.ali1977 import quasi_static as qs  # noqa: E402
from linkrepro.port.ali1977.quirks import CORRECTED, Quirks  # noqa: E402

ANGLES = np.arange(0.0, 361.0, 30.0)
TOLERANCE = 1e-9
STIFF_TOLERANCE = 2e-5
CASES_SIDES = [(case, side) for case in mb.CASES for side in mb.SIDES]
#: the bugs of the Case I listings that act on the example (the cognate's D141 does not:
#: with alpha = 60 deg its listing's beta is right, fourbar.listing_beta_is_wrong)
CASE1_BUGS = {"source": {"pi_22_7", "source_alpha_101", "omega3_sign", "g_coefficient", "i_coefficient",
                         "input_link_bending_area", "source_rpm_400", "inertia_sign", "real4_storage"},
              "cognate": {"pi_22_7", "input_link_bending_area", "inertia_sign", "real4_storage", "cognate_frame",
                          "cognate_moment_row"}}


def largest(got: dict, ref: dict) -> float:
    """Largest |(dx, dy)| difference over the angles (in)."""
    return float(np.hypot(got["dx"] - ref["dx"], got["dy"] - ref["dy"]).max())


def peak(ref: dict) -> float:
    return float(np.hypot(ref["dx"], ref["dy"]).max())


def reference(case: int, side: str) -> dict:
    return mb.port_deflections(side, case, ANGLES)


@pytest.fixture(scope="module")
def exudyn_eb():
    """Exudyn, shear 12 EI/h^2, the scene's EB_ELEMENTS per link, every case and side."""
    return {key: mb.quasi_static(key[1], key[0], ANGLES, qs.EB_ELEMENTS, shear_per_element=qs.EB_KAPPA)
            for key in CASES_SIDES}


@pytest.mark.parametrize("case, side", CASES_SIDES)
def test_exudyn_agrees_with_the_corrected_port(exudyn_eb, case, side):
    ref = reference(case, side)
    got = exudyn_eb[case, side]
    assert largest(got, ref) < TOLERANCE * peak(ref)
    assert np.abs(got["rot"] - ref["rot"]).max() < TOLERANCE * peak(ref) / mb.rigid(side, [0.0]).lengths[1]


@pytest.mark.parametrize("case, side", [(1, "source"), (3, "source"), (2, "cognate")])
def test_stiff_shear_agrees_once_the_h2_error_is_extrapolated_away(case, side):
    """A second reading without the element theory: stiff shear, one mesh off by c h^2 (a ratio
    of 4 between 4 and 8 elements per link), the two meshes extrapolated within STIFF_TOLERANCE."""
    ref = reference(case, side)
    coarse, fine = (mb.quasi_static(side, case, ANGLES, n) for n in qs.PAIR)
    assert 3.9 < largest(coarse, ref) / largest(fine, ref) < 4.1
    assert largest(fine, ref) > 100 * STIFF_TOLERANCE * peak(ref)
    assert largest(qs.richardson(coarse, fine), ref) < STIFF_TOLERANCE * peak(ref)


@pytest.mark.parametrize("side", mb.SIDES)
def test_every_listing_bug_is_caught(exudyn_eb, side):
    """The comparison is sharp enough to fail: each quirk of the Case I listings alone moves the
    port away from Exudyn by more than the tolerance, and those are the quirks that do."""
    got = exudyn_eb[1, side]
    caught = set()
    for field in fields(Quirks):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            port = mb.port_deflections(side, 1, ANGLES, quirks=CORRECTED.only(field.name, True))
        if largest(got, port) > TOLERANCE * peak(port):
            caught.add(field.name)
    assert caught == CASE1_BUGS[side]


def test_the_source_case2_f7_entry_is_the_whole_difference(exudyn_eb):
    """The listing's eq. (30) puts f7 = +P7 (D144, switched on alone here); Exudyn's coupler load at A
    gives f7 = 0, at B f7 = -P7: so at B Exudyn is twice as far from that port as at A, the same way."""
    port = mb.port_deflections("source", 2, ANGLES, quirks=CORRECTED.only("coupler_load_in_f7", True))
    at_a = exudyn_eb[2, "source"]
    at_b = mb.quasi_static("source", 2, ANGLES, qs.EB_ELEMENTS, shear_per_element=qs.EB_KAPPA, coupler_load_at="B")
    assert largest(at_a, port) > 1e3 * TOLERANCE * peak(port)
    for k in ("dx", "dy", "rot"):
        np.testing.assert_allclose(at_b[k] - port[k], 2.0 * (at_a[k] - port[k]), rtol=0,
                                   atol=TOLERANCE * peak(port))


def test_the_cognate_case2_port_reverses_its_crank_and_coupler_loads(exudyn_eb):
    """The reconstruction's signs of P4, P5, P7 (D145, switched on alone here) are far from Exudyn."""
    port = mb.port_deflections("cognate", 2, ANGLES, quirks=CORRECTED.only("cognate_joint_load_signs", True))
    assert largest(exudyn_eb[2, "cognate"], port) > 0.5 * peak(port)


@pytest.mark.parametrize("side", mb.SIDES)
def test_the_port_s_case2_as_it_is(exudyn_eb, side):
    """The corrected port's Case II itself (no patched copy): within the tolerance of Exudyn."""
    port = mb.port_deflections(side, 2, ANGLES)
    assert largest(exudyn_eb[2, side], port) < TOLERANCE * peak(port)


@pytest.mark.parametrize("side", mb.SIDES)
def test_case2_with_the_masses_whole_inertia_forces(side):
    """D185: the thesis's Case II keeps only the coupler's and the follower's inertia loads along
    their links; the port's ``lumped="full"`` (two system forces and their beta2 columns added,
    ``case2.transverse``) against Exudyn's frozen structure loaded with the masses' whole
    d'Alembert forces; the thesis's axial loads are far from it (the choice matters)."""
    port = mb.port_deflections(side, 2, ANGLES, lumped="full")
    got = mb.quasi_static(side, 2, ANGLES, qs.EB_ELEMENTS, shear_per_element=qs.EB_KAPPA, lumped="full")
    assert largest(got, port) < TOLERANCE * peak(port)
    assert np.abs(got["rot"] - port["rot"]).max() < TOLERANCE * peak(port) / mb.rigid(side, [0.0]).lengths[1]
    assert largest(got, reference(2, side)) > 0.3 * peak(reference(2, side))


def test_the_solve_is_linear_and_the_nonlinear_solve_is_not():
    """Scaled back, the linear answer does not depend on the load factor; Exudyn's nonlinear
    static solve differs from it in proportion to the load (geometric nonlinearity)."""
    def build(scale):
        return mb.build("source", 20.0, 1, 4, masses="none", load_scale=scale)
    answers = [build(scale).linear_deflection() / scale for scale in (1e-3, 1.0, 1e3)]
    for u in answers[1:]:
        np.testing.assert_allclose(u, answers[0], rtol=1e-8)
    linear = answers[1]
    gaps = []
    for scale in (1.0, 0.1):
        model = build(scale)
        model.mbs.SolveStatic(model.settings)
        u = model.node_displacement(model.path_node) / scale
        gaps.append(math.hypot(*(u - linear)[:2]) / math.hypot(*linear[:2]))
    assert gaps[0] > 0.1
    assert 8.0 < gaps[0] / gaps[1] < 12.0


@pytest.mark.parametrize("case", mb.CASES)
def test_the_model_carries_the_loads_it_lists(case):
    """Exudyn's static residual at the unloaded reference holds exactly the listed forces."""
    model = mb.build("cognate", 50.0, case, 5, masses="none")
    expected = np.zeros(model.mbs.systemData.ODE2Size())
    for node, (fx, fy) in model.loads:
        index = model.mbs.GetNodeODE2Index(node)
        expected[index:index + 2] += (fx, fy)
    np.testing.assert_allclose(model.load_vector(), expected, rtol=0, atol=1e-12 * np.abs(expected).max())
    assert len(model.loads) == {1: 1, 2: 3, 3: mb.CASE3_NODES}[case]


@pytest.mark.parametrize("case", mb.CASES)
def test_a_moved_model_is_the_model_built_there(case):
    """``Model.move`` (the scene moves one frozen model from angle to angle): its Jacobian, load
    vector and loads equal, bit for bit, those of the model built at the new angle; a driven model
    cannot be moved."""
    options = dict(masses="lumped", load_scale=2.0, coupler_load_at="B")
    model = mb.build("cognate", 50.0, case, 3, **options)
    model.move(200.0)
    built = mb.build("cognate", 200.0, case, 3, **options)
    for got, expected in zip(model._static_system(), built._static_system()):
        np.testing.assert_array_equal(got, expected)
    assert [(int(n), f) for n, f in model.loads] == [(int(n), f) for n, f in built.loads] and model.deg == 200.0
    with pytest.raises(ValueError, match="frozen"):
        mb.build("source", 30.0, 1, 2, mode="driven").move(40.0)


@pytest.mark.parametrize("side", mb.SIDES)
def test_the_port_s_accelerations_are_its_positions_differentiated(side):
    """The loads come from the port's accelerations: they are the second derivatives of its own
    positions in time (a central difference over +-0.01 deg), path point and both pins."""
    step = 0.01
    rig = mb.rigid(side, ANGLES)
    around = [mb.rigid(side, ANGLES + d) for d in (-step, step)]
    scale = (rig.om2 / math.radians(step)) ** 2
    for point in ("p", "a", "b"):
        second = (getattr(around[0], point) - 2.0 * getattr(rig, point) + getattr(around[1], point)) * scale
        acc = getattr(rig, "acc_" + point)
        np.testing.assert_allclose(second, acc, rtol=0, atol=1e-5 * np.abs(acc).max())


def test_the_cognate_traces_the_source_s_coupler_curve_and_closes():
    source, cognate = mb.rigid("source", ANGLES), mb.rigid("cognate", ANGLES)
    np.testing.assert_allclose(cognate.p, source.p, rtol=0, atol=1e-12)
    for rig in (source, cognate):
        l1, l2, l3, l4 = rig.lengths
        for points, length in (((rig.o2, rig.a), l1), ((rig.a, rig.p), l2), ((rig.a, rig.b), l3),
                               ((rig.b, rig.o4), l4)):
            np.testing.assert_allclose(np.hypot(*(points[1] - points[0])), length, rtol=1e-13)
    np.testing.assert_allclose(cognate.o4, source.o4, atol=1e-12)


def test_the_driven_crank_turns_at_the_port_s_speed():
    """Driven mode (for the elastodynamic study): the crank's root turns om2 t, the path point
    stays near the rigid one over a short run."""
    model = mb.build("source", 30.0, 1, 2, mode="driven", masses="distributed")
    settings = model.settings
    settings.timeIntegration.numberOfSteps = 20
    settings.timeIntegration.endTime = 0.002
    model.mbs.SolveDynamic(settings)
    assert model.node_displacement(model.crank_root)[2] == pytest.approx(model.rigid.om2 * 0.002, rel=1e-9)
    rigid = mb.rigid_path_point("source", [mb.crank_angle(model.rigid, 0.002, 30.0)])[:, 0]
    assert np.hypot(*(model.path_point() - rigid)) < 0.1
