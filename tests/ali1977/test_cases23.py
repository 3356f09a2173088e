"""Cases II and III: the port against legacy, and against the theory's own reductions."""
from types import SimpleNamespace

import numpy as np
import pytest

from linkrepro.legacy import ali1977
from linkrepro.port.ali1977 import CORRECTED, Lengths, source_case1
from linkrepro.port.ali1977.case2 import LISTING as CASE2, beta2, case2_cognate, case2_source, joint_loads
from linkrepro.port.ali1977.case3 import LISTING as CASE3, _coupled_tip, case3_cognate, case3_source, node_positions
from linkrepro.port.ali1977.cognate import cognate_mechanics
from linkrepro.port.ali1977.data import EXAMPLE
from linkrepro.port.ali1977.source import source_mechanics
from linkrepro.port.ali1977.structure import deflection, flexibility

DEG = np.arange(0.0, 361.0, 1.0)
AREA, DENSITY = EXAMPLE.section.area, 0.098


def test_case2_port_equals_legacy():
    port, leg = case2_source(DEG, quirks=CASE2), ali1977.case2_source(step_deg=1.0)
    for key in ("xp", "yp", "dx", "dy", "rot"):
        np.testing.assert_allclose(port[key], leg[key], rtol=1e-9, atol=1e-300, err_msg=key)


def test_case2_cognate_reconstruction_port_equals_legacy():
    """The reconstructed page (D037) is the same in the FORTRAN and in the port."""
    port, leg = case2_cognate(DEG), ali1977.case2_cognate(step_deg=1.0)
    for key in ("xp", "yp", "cxp", "cyp", "dx", "dy", "rot"):
        np.testing.assert_allclose(port[key], leg[key], rtol=1e-9, atol=1e-300, err_msg=key)


def test_case3_cognate_reconstruction_port_equals_legacy():
    port, leg = case3_cognate(DEG), ali1977.case3_cognate(step_deg=1.0)
    for key in ("xp", "yp", "dx", "dy", "rot"):
        np.testing.assert_allclose(port[key], leg[key], rtol=1e-9, atol=1e-300, err_msg=key)


def test_case3_port_equals_legacy_for_every_node():
    """dx, dy and the rotation of all five nodes, with the listing's slips D035, D036."""
    port, leg = case3_source(DEG, quirks=CASE3, all_nodes=True), ali1977.case3_source(step_deg=1.0)
    for key in ("xp", "yp", "dx", "dy", "rot"):
        np.testing.assert_allclose(port[key], leg[key], rtol=1e-9, atol=1e-300, err_msg=key)
    np.testing.assert_allclose(port["nodes"], leg["nodes"], rtol=1e-9, atol=1e-300)


def test_case2_with_only_the_path_point_load_is_case1():
    """Eq. (32) with P4..P8 = 0: beta2 P = beta1 (P1, P2, P3), so delta is Case I's eq. (6)."""
    deg = np.arange(0.0, 360.0, 15.0)
    mech = source_mechanics(deg, rpm=300.0, quirks=CORRECTED, speed_type="REAL")
    flex = flexibility(10.0, 10.0, 30.0, 25.0, EXAMPLE.section, CORRECTED)
    loads = joint_loads(mech, EXAMPLE.lengths, DENSITY, AREA, CORRECTED)
    only_p = loads.copy()
    only_p[:, 3:] = 0.0
    case2 = deflection(mech.beta, flex, only_p, CORRECTED, right=beta2(mech, CORRECTED))
    case1 = deflection(mech.beta, flex, only_p[:, :3], CORRECTED)
    np.testing.assert_allclose(case2, case1, rtol=1e-12, atol=1e-18)
    full = deflection(mech.beta, flex, loads, CORRECTED, right=beta2(mech, CORRECTED))
    assert np.abs(full - case1).max() > 1e-4          # the joint masses do matter


def _fd_acceleration(point, deg, rpm=300.0, step=1e-3):
    dt = np.radians(step) / (2 * np.pi * rpm / 60)
    return (point(deg + step) - 2 * point(deg) + point(deg - step)) / dt**2


def test_case2_corrected_joint_loads_project_finite_difference_accelerations():
    """D031/D032: P4, P5 = m1 a_A along/across the crank, P6 = m4 a_B along the follower,
    with a_A, a_B from finite differences of the pins' positions (A = L1 e^{i t2},
    B = A + L3 e^{i t3})."""
    deg = np.arange(5.0, 360.0, 35.0)
    mech = source_mechanics(deg, rpm=300.0, quirks=CORRECTED, speed_type="REAL")
    loads = joint_loads(mech, EXAMPLE.lengths, DENSITY, AREA, CORRECTED)
    def pins(d):
        m = source_mechanics(d, rpm=300.0, quirks=CORRECTED, speed_type="REAL")
        t2, t3 = m.extra["t2"], m.extra["t3"]
        a = 10.0 * np.exp(1j * t2)
        return a, a + 30.0 * np.exp(1j * t3)
    acc_a = _fd_acceleration(lambda d: pins(d)[0], deg)
    acc_b = _fd_acceleration(lambda d: pins(d)[1], deg)
    t2, t4 = mech.extra["t2"], mech.extra["t4"]
    g = 12.0 * 32.178
    m1, m4 = DENSITY * AREA * 10.0, DENSITY * AREA * 25.0
    along = lambda acc, t: acc.real * np.cos(t) + acc.imag * np.sin(t)     # noqa: E731
    across = lambda acc, t: -acc.real * np.sin(t) + acc.imag * np.cos(t)   # noqa: E731
    scale = m4 * np.abs(acc_b).max() / g
    # CORRECTED loads are inertia forces, -m a
    np.testing.assert_allclose(loads[:, 3], -m1 * along(acc_a, t2) / g, atol=1e-5 * scale)
    np.testing.assert_allclose(loads[:, 4], -m1 * across(acc_a, t2) / g, atol=1e-5 * scale)
    np.testing.assert_allclose(loads[:, 5], -m4 * along(acc_b, t4) / g, atol=1e-5 * scale)


@pytest.mark.parametrize("cognate", [False, True])
def test_case2_joint_loads_times_their_columns_are_the_statics_of_the_joint_masses(cognate):
    """D144, D145: beta2's columns 4, 5 and 7 times P4, P5 and P7 (CORRECTED) are the element
    forces f4..f8 that the masses at the crank pin A put on the frozen structure: the crank's
    d'Alembert force -(m1/g) a_A and the coupler's component along the coupler, -(m3/g)(a_A . e3) e3,
    with a_A by finite differences of A = L1 e^{i t2}.  The statics uses neither beta2 nor
    joint_loads: a force Q at A on the coupler body is the force Q at the path point P with the
    moment (A - P) x Q, whose element forces are beta1's (rows f4..f8, each mechanism's own
    signs: the cognate's f4, f5 run along -e2, -n2, eqs. 20-21).  A force at the pin has no moment
    about A: the follower and the coupler element carry nothing (f6 = f7 = f8 = 0), whichever
    link the mass belongs to."""
    deg = np.arange(5.0, 360.0, 35.0)
    mechanics = cognate_mechanics if cognate else source_mechanics
    kw = {} if cognate else {"speed_type": "REAL"}
    mech = mechanics(deg, rpm=300.0, quirks=CORRECTED, **kw)
    lengths = mech.extra["cognate"] if cognate else EXAMPLE.lengths
    l1, l2, l3, l4 = ((lengths.cl1, lengths.cl2, lengths.cl3, lengths.cl4) if cognate
                      else (lengths.l1, lengths.l2, lengths.l3, lengths.l4))
    links = SimpleNamespace(l1=l1, l2=l2, l3=l3, l4=l4)
    loads = joint_loads(mech, links, DENSITY, AREA, CORRECTED, cognate=cognate)
    right = beta2(mech, CORRECTED, cognate=cognate)
    t2, t3 = mech.extra["t2"], mech.extra["t3"]
    pin = l1 * np.exp(1j * t2)
    arm = pin - (mech.xp + 1j * mech.yp)                                     # A - P
    acc_a = _fd_acceleration(lambda d: l1 * np.exp(1j * np.radians(d)), deg)
    g = 12.0 * 32.178
    axis = np.exp(1j * t3)
    crank_mass = -(DENSITY * AREA * l1 / g) * acc_a
    coupler_mass = -(DENSITY * AREA * l3 / g) * (acc_a.real * axis.real + acc_a.imag * axis.imag) * axis

    def statics(force):
        """f4..f8 (N, 5) of the force (complex, lbf) at A."""
        moment = arm.real * force.imag - arm.imag * force.real
        return np.einsum("nij,nj->ni", mech.beta[:, 3:8], np.stack([force.real, force.imag, moment], axis=1))

    for got, force in ((loads[:, 3, None] * right[:, 3:8, 3] + loads[:, 4, None] * right[:, 3:8, 4], crank_mass),
                       (loads[:, 6, None] * right[:, 3:8, 6], coupler_mass)):
        expected = statics(force)
        scale = np.abs(expected).max()
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-5 * scale)
        assert np.abs(expected[:, 2:]).max() < 1e-12 * scale                 # f6 = f7 = f8 = 0
    assert (right[:, :3, 3:] == 0.0).all()                                    # nor the extender
    # the listings' column 7 (f7 = P7, D144), and the reconstruction's signs (D145): P4, P5, P7 reversed
    assert (beta2(mech, CORRECTED.only("coupler_load_in_f7", True), cognate=cognate)[:, 6, 6] == 1.0).all()
    reconstruction = joint_loads(mech, links, DENSITY, AREA, CORRECTED.only("cognate_joint_load_signs", True),
                                 cognate=cognate)
    flips = np.array([1, 1, 1, -1, -1, 1, -1, 1]) if cognate else np.ones(8)
    np.testing.assert_array_equal(reconstruction, loads * flips)


def test_case3_with_one_node_is_case1_with_the_extender_at_the_tip():
    """n = 1: the whole extender's weight at the path point; the coupled and the listing's
    uncoupled model are then both Case I (eq. 6) with that weight."""
    deg = np.arange(0.0, 360.0, 20.0)
    weight = DENSITY * AREA * 10.0
    case1 = source_case1(deg, rpm=300.0, mass_lbf=weight, quirks=CORRECTED)
    for uncoupled in (True, False):
        q = CORRECTED.only("uncoupled_nodes", uncoupled)
        case3 = case3_source(deg, n=1, quirks=q)
        np.testing.assert_allclose(case3["dx"], case1["dx"], rtol=1e-12)
        np.testing.assert_allclose(case3["dy"], case1["dy"], rtol=1e-12)


@pytest.mark.parametrize("n", [1, 4])
def test_cognate_segmented_extender_with_a_tip_load_is_the_same_beam(n):
    """The same identity on the crossed cognate's extender (its direction pi - (gamma - t3))."""
    deg = np.arange(0.0, 360.0, 30.0)
    tip = cognate_mechanics(deg, rpm=300.0, quirks=CORRECTED)
    cog = tip.extra["cognate"]
    positions = node_positions(cog.cl2, n)
    mechs = [tip] + [cognate_mechanics(deg, rpm=300.0, quirks=CORRECTED, extender=r) for r in positions[1:]]
    loads = np.zeros((n, len(deg), 3))
    loads[0] = np.stack([-tip.acc[:, 0], -tip.acc[:, 1], 0 * deg], -1) * (2.0 / (12 * 32.178))
    lengths = Lengths(cog.cl1, cog.cl2, cog.cl3, cog.cl4, cog.cl5)
    coupled, _, _ = _coupled_tip(mechs, loads, positions, lengths, EXAMPLE.section, CORRECTED)
    single = deflection(tip.beta, flexibility(cog.cl2, cog.cl1, cog.cl3, cog.cl4, EXAMPLE.section, CORRECTED),
                        loads[0], CORRECTED)
    np.testing.assert_allclose(coupled, single, rtol=1e-10, atol=1e-15)


@pytest.mark.parametrize("n", [1, 3, 7])
def test_segmented_extender_with_a_tip_load_is_the_same_beam(n):
    """Euler-Bernoulli segments in series carry a tip load exactly as one beam: the coupled
    model with only the tip node loaded must equal Case I for any n."""
    deg = np.arange(0.0, 360.0, 30.0)
    positions = node_positions(10.0, n)
    mechs = [source_mechanics(deg, Lengths(10.0, r, 30.0, 25.0, 30.0), rpm=300.0, quirks=CORRECTED)
             for r in positions]
    tip_load = np.stack([-mechs[0].acc[:, 0], -mechs[0].acc[:, 1], 0 * deg], -1) * (2.0 / (12 * 32.178))
    loads = np.zeros((n,) + tip_load.shape)
    loads[0] = tip_load
    coupled, _, _ = _coupled_tip(mechs, loads, positions, EXAMPLE.lengths, EXAMPLE.section, CORRECTED)
    case1 = source_case1(deg, rpm=300.0, quirks=CORRECTED)
    np.testing.assert_allclose(coupled[:, 0], case1["dx"], rtol=1e-10)
    np.testing.assert_allclose(coupled[:, 1], case1["dy"], rtol=1e-10)
    np.testing.assert_allclose(coupled[:, 2], case1["rot"], rtol=1e-10)


def test_coupled_model_converges_as_the_extender_is_refined():
    """Distributing a fixed mass over more nodes converges (lumping at the node ends is a
    first-order rule: the successive differences shrink about as 1/n)."""
    deg = np.array([20.0, 100.0, 200.0, 300.0])
    tips = [case3_source(deg, n=n, quirks=CORRECTED)["dx"] for n in (5, 10, 20, 40, 80)]
    gaps = [np.abs(b - a).max() for a, b in zip(tips, tips[1:])]
    assert all(later < earlier for earlier, later in zip(gaps, gaps[1:])), gaps
    assert gaps[-1] < 0.6 * gaps[-2]


def test_case3_rejects_bad_node_counts():
    with pytest.raises(ValueError):
        case3_source(DEG[:3], n=0)
    with pytest.raises(ValueError):
        case3_source(DEG[:3], n=2.5)


@pytest.mark.parametrize("legacy_func,port_func", [
    (ali1977.case2_source, lambda **kw: case2_source(DEG[::20], **kw)),
    (ali1977.case2_cognate, lambda **kw: case2_cognate(DEG[::20], **kw)),
    (ali1977.case3_source, lambda **kw: case3_source(DEG[::20], **kw))])
def test_cases23_typed_errors_from_both_engines(legacy_func, port_func):
    from linkrepro import AssemblyError
    with pytest.raises(AssemblyError):
        legacy_func(l5=100.0)
    with pytest.raises(AssemblyError):
        port_func(lengths=Lengths(10.0, 10.0, 30.0, 25.0, 100.0))
    with pytest.raises(ValueError):
        legacy_func(density=-0.1)
    with pytest.raises(ValueError):
        port_func(density=float("nan"))


def test_case2_lumped_takes_the_corrected_loads_only():
    """D185: ``lumped="full"`` completes the corrected joint loads; with a listing's load quirk on,
    or another value, it is refused by name."""
    with pytest.raises(ValueError, match="coupler_load_in_f7"):
        case2_source(DEG[:3], lumped="full")
    with pytest.raises(ValueError, match="cognate_joint_load_signs"):
        case2_cognate(DEG[:3], quirks=CORRECTED.only("cognate_joint_load_signs", True), lumped="full")
    with pytest.raises(ValueError, match="lumped"):
        case2_source(DEG[:3], quirks=CORRECTED, lumped="radial")
    with pytest.raises(TypeError, match="lumped"):
        case2_cognate(DEG[:3], quirks=CORRECTED, lumped=None)


def test_legacy_case3_needs_room_for_its_five_nodes():
    with pytest.raises(ValueError, match="nodes"):
        ali1977.case3_source(l2=8.0)
