"""The port: equal to legacy with PRINTED quirks; CORRECTED checked by independent computation."""
import numpy as np
import pytest

from linkrepro import AssemblyError, SingularPositionError
from linkrepro.legacy import ali1977
from linkrepro.port.ali1977 import CORRECTED, PRINTED, Lengths, Section, cognate_case1, source_case1
from linkrepro.port.ali1977.case1 import case1_deflection
from linkrepro.port.ali1977.cognate import cognate_mechanics
from linkrepro.port.ali1977.data import EXAMPLE
from linkrepro.port.ali1977.source import source_mechanics
from linkrepro.port.ali1977.structure import flexibility

DEG = np.arange(0.0, 361.0, 1.0)
RPM = 300.0


def test_port_printed_equals_legacy_on_every_angle():
    """1e-9 relative on every quantity at every degree (it is in fact bit for bit)."""
    pairs = [(source_case1(DEG, quirks=PRINTED), ali1977.case1_source(step_deg=1.0)),
             (cognate_case1(DEG, quirks=PRINTED), ali1977.case1_cognate(step_deg=1.0))]
    for port, leg in pairs:
        for key in port:
            np.testing.assert_allclose(port[key], leg[key], rtol=1e-9, atol=1e-300, err_msg=key)


def _finite_difference_acceleration(position, deg, step_deg=1e-3):
    """Second central difference of a position (in) in time at constant input speed."""
    dt = np.radians(step_deg) / (2 * np.pi * RPM / 60)
    return (position(deg + step_deg) - 2 * position(deg) + position(deg - step_deg)) / dt**2


@pytest.mark.parametrize("which", ["source", "cognate"])
def test_corrected_acceleration_is_second_derivative_of_position(which):
    """The path point's acceleration (listing XPA, YPA) against finite differences of its
    position: independent of every velocity/acceleration formula of the listings."""
    deg = np.arange(5.0, 360.0, 25.0)
    mech = {"source": source_mechanics, "cognate": cognate_mechanics}[which]
    acc = mech(deg, rpm=RPM, quirks=CORRECTED).acc
    fd_x = _finite_difference_acceleration(lambda d: mech(d, rpm=RPM, quirks=CORRECTED).xp, deg)
    fd_y = _finite_difference_acceleration(lambda d: mech(d, rpm=RPM, quirks=CORRECTED).yp, deg)
    scale = np.abs(acc).max()
    np.testing.assert_allclose(acc[:, 0], fd_x, atol=1e-5 * scale)
    np.testing.assert_allclose(acc[:, 1], fd_y, atol=1e-5 * scale)


def test_printed_omega3_fails_the_same_check():
    """D013: with the listing's OM3 the acceleration is not the position's second derivative."""
    deg = np.arange(5.0, 360.0, 25.0)
    quirks = CORRECTED.only("omega3_sign", True)
    acc = source_mechanics(deg, rpm=RPM, quirks=quirks).acc
    fd_x = _finite_difference_acceleration(lambda d: source_mechanics(d, rpm=RPM, quirks=quirks).xp, deg)
    assert np.abs(acc[:, 0] - fd_x).max() > 0.01 * np.abs(acc).max()


def test_cognate_traces_the_source_path_with_the_same_acceleration():
    """A coupler cognate's path point is the same point at the same time: its position and
    acceleration, turned from the cognate frame into the source's, equal the source's."""
    deg = np.arange(0.0, 360.0, 15.0)
    src = source_mechanics(deg, rpm=RPM, quirks=CORRECTED)
    cog = cognate_mechanics(deg, rpm=RPM, quirks=CORRECTED)
    np.testing.assert_allclose(cog.extra["cxp"], src.xp, atol=1e-12)
    np.testing.assert_allclose(cog.extra["cyp"], src.yp, atol=1e-12)
    c, s = np.cos(cog.frame_angle), np.sin(cog.frame_angle)
    turned = np.stack([c * cog.acc[:, 0] - s * cog.acc[:, 1], s * cog.acc[:, 0] + c * cog.acc[:, 1]], -1)
    np.testing.assert_allclose(turned, src.acc, atol=1e-9 * np.abs(src.acc).max())


def _equilibrium_rows(pin_a, pin_b, d4, d5, d6):
    """f4, f5, f6 per unit P1, P2, P3 by solving the coupler's force and moment balance about
    the path point with numpy (moments (pin - P) x direction): no Cramer's rule."""
    cross = lambda r, d: r[0] * d[1] - r[1] * d[0]  # noqa: E731
    rows = []
    for k in range(len(pin_a[0])):
        m = np.array([[d4[0][k], d5[0][k], d6[0][k]], [d4[1][k], d5[1][k], d6[1][k]],
                      [cross((pin_a[0][k], pin_a[1][k]), (d4[0][k], d4[1][k])),
                       cross((pin_a[0][k], pin_a[1][k]), (d5[0][k], d5[1][k])),
                       cross((pin_b[0][k], pin_b[1][k]), (d6[0][k], d6[1][k]))]])
        rows.append(np.linalg.solve(m, np.eye(3)))
    return np.array(rows)


def test_corrected_source_beta_solves_coupler_equilibrium():
    """Rows f4-f6 of beta (eqs. 10-14) against a numpy solve of the equilibrium built from
    the joint positions: A = P - L2 e^{i(t3+alpha)}, B = A + L3 e^{i t3}."""
    deg = np.arange(0.0, 360.0, 20.0)
    mech = source_mechanics(deg, rpm=RPM, quirks=CORRECTED)
    t2, t3, t4, alp = (mech.extra[k] for k in ("t2", "t3", "t4", "alp"))
    l2, l3 = EXAMPLE.lengths.l2, EXAMPLE.lengths.l3
    a = (-l2 * np.cos(t3 + alp), -l2 * np.sin(t3 + alp))
    b = (a[0] + l3 * np.cos(t3), a[1] + l3 * np.sin(t3))
    solved = _equilibrium_rows(a, b, (np.cos(t2), np.sin(t2)), (-np.sin(t2), np.cos(t2)),
                               (np.cos(t4), np.sin(t4)))
    np.testing.assert_allclose(mech.beta[:, 3:6, :], solved, atol=1e-12)


@pytest.mark.parametrize("which", ["source", "cognate"])
def test_corrected_beta_gives_f6_twice_alike(which):
    """The listings get the follower force f6 twice: from the 3x3 solve (row 6) and from the
    moment about the crank pin (row 8 = f6 L3 sin(t4-t3), eqs. 15 and 25).  They must agree;
    with the printed coefficients (D014, D015, D026) they do not."""
    deg = np.arange(0.0, 360.0, 20.0)
    mech_of = source_mechanics if which == "source" else cognate_mechanics
    for quirks, agree in ((CORRECTED, True), (PRINTED, False)):
        mech = mech_of(deg, rpm=RPM, quirks=quirks)
        e = mech.extra
        l3 = EXAMPLE.lengths.l3 if which == "source" else e["cognate"].cl3
        arm = l3 * (np.sin(e["t4"] - e["t3"]) if which == "source" else np.sin(e["t3"] - e["t4"]))
        gap = np.abs(mech.beta[:, 5, :2] - mech.beta[:, 7, :2] / arm[:, None]).max()
        assert (gap < 1e-12) == agree, (quirks, gap)


@pytest.mark.parametrize("which", ["source", "cognate"])
def test_system_flexibility_is_symmetric_positive_definite(which):
    """beta^T F beta maps loads to deflections: by Maxwell-Betti it is symmetric, and a
    stable structure makes it positive definite."""
    deg = np.arange(0.0, 360.0, 30.0)
    mech = (source_mechanics if which == "source" else cognate_mechanics)(deg, quirks=CORRECTED)
    flex = flexibility(*mech.flex_lengths, EXAMPLE.section, CORRECTED)
    system = np.swapaxes(mech.beta, 1, 2) @ flex @ mech.beta
    np.testing.assert_allclose(system, np.swapaxes(system, 1, 2), rtol=1e-10, atol=1e-15)
    assert np.all(np.linalg.eigvalsh(system) > 0)


def test_flexibility_matches_cantilever_formulas():
    """Eq. (29) entries against beam theory written out here: tip deflection of a cantilever
    L^3/3EI, rotation L/EI, coupling L^2/2EI, axial L/AE."""
    sec = Section(0.2, 1.0e7, 0.003)
    f = flexibility(10.0, 8.0, 30.0, 25.0, sec, CORRECTED)
    ei, ea = sec.modulus * sec.inertia, sec.modulus * sec.area
    assert f[1, 1] == pytest.approx(1000 / (3 * ei)) and f[2, 2] == pytest.approx(10 / ei)
    assert f[1, 2] == pytest.approx(100 / (2 * ei)) and f[0, 0] == pytest.approx(10 / ea)
    assert f[4, 4] == pytest.approx(512 / (3 * ei))
    assert flexibility(10.0, 8.0, 30.0, 25.0, sec, PRINTED)[4, 4] == pytest.approx(512 / (3 * ea), rel=1e-6)


def test_deflection_scales_with_mass_and_speed_squared():
    """Linear elasticity and an inertia load m*omega^2*(...): doubling the mass doubles the
    deflection, doubling the speed quadruples it."""
    deg = np.arange(0.0, 360.0, 40.0)
    base = source_case1(deg, rpm=300.0, mass_lbf=2.0, quirks=CORRECTED)
    heavy = source_case1(deg, rpm=300.0, mass_lbf=4.0, quirks=CORRECTED)
    fast = source_case1(deg, rpm=600.0, mass_lbf=2.0, quirks=CORRECTED)
    np.testing.assert_allclose(heavy["dx"], 2 * base["dx"], rtol=1e-12)
    np.testing.assert_allclose(fast["dy"], 4 * base["dy"], rtol=1e-12)


@pytest.mark.parametrize("lengths", [(10, 10, 30, 10, 30), (10, 10, 20, 20, 10)])
def test_folded_linkage_raises_singular_position_in_both_engines(lengths):
    """Coupler and follower collinear at 0 deg (L5 - L1 = L3 - L4), or crank pin on the
    follower pivot: beta divides by zero there.  Both engines name the angle."""
    with pytest.raises(SingularPositionError) as from_port:
        source_case1(np.arange(0.0, 361.0, 20.0), lengths=Lengths(*lengths), quirks=PRINTED)
    with pytest.raises(SingularPositionError) as from_legacy:
        ali1977.case1_source(*lengths)
    assert from_port.value.angle_deg == from_legacy.value.angle_deg == 0.0


def test_port_bad_input_typed_errors():
    with pytest.raises(ValueError):
        Lengths(10, 10, 0, 25, 30)
    with pytest.raises(ValueError):
        Section(float("nan"), 1e7, 0.003)
    with pytest.raises(AssemblyError):
        source_case1(DEG, lengths=Lengths(10, 10, 30, 25, 100), quirks=CORRECTED)
    with pytest.raises(ValueError):
        source_case1([0.0, float("nan")], quirks=CORRECTED)
    with pytest.raises(ValueError):
        case1_deflection(source_mechanics([0.0]), float("inf"), EXAMPLE.section, PRINTED)


def test_case1_names_where_users_and_the_fuzz_find_them():
    """Case I's module split into data, structure, linkage, source, cognate and case1 (issue 23):
    every name of case1's ``__all__`` is importable from it and is the object its own module
    defines; the package exports what it did."""
    import linkrepro.port.ali1977 as package
    from linkrepro.port.ali1977 import case1, cognate, data, linkage, quirks, source, structure

    home = {"Section": structure, "Mechanics": structure, "EXAMPLE": data, "Linkage": linkage,
            "SourceLinkage": source, "source_linkage": source, "source_mechanics": source,
            "CognateLinkage": cognate, "cognate_linkage": cognate, "cognate_mechanics": cognate,
            "PRINTED": quirks, "CORRECTED": quirks, "Quirks": quirks,
            "case1_deflection": case1, "source_case1": case1, "cognate_case1": case1}
    assert sorted(case1.__all__) == sorted(home)
    for name, module in home.items():
        assert getattr(case1, name) is getattr(module, name), name
    assert sorted(package.__all__) == sorted(["CORRECTED", "PRINTED", "Quirks", "Lengths", "Section", "Cognate",
                                              "EXAMPLE", "source_case1", "cognate_case1"])
    assert package.Section is structure.Section and package.EXAMPLE is data.EXAMPLE
    assert package.source_case1 is case1.source_case1 and package.cognate_case1 is case1.cognate_case1
