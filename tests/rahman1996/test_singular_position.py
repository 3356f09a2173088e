"""The CSSP at and near a singular position (issue 22, item 3; register D150).

Where the rod is perpendicular to the slider's axis (or along the crank's axis) the loop's
velocity equations are singular: the slider's speed, the loads and H blow up.  Every engine
measures the condition number kappa of its own velocity equations at its own positions (the
listing's VM, ``linkrepro.checks.listing_condition``, for legacy and the port with the
listing's bugs; the closed loop's Jacobian, ``kinematics(...).condition``, for the corrected
port) and raises SingularPositionError at the first crank angle where kappa > 2**12 =
1/sqrt(u), u the unit roundoff of the listing's REAL*4 inputs.  The closed loop's kappa is
checked against mpmath; the geometries are the issue's, a family approaching the
singularity, the published example and six of the differential sample where the listing's
loop (which never closes, D079) sits far from where the closed loop's does.
"""
import mpmath
import numpy as np
import pytest

from linkrepro import checks
from linkrepro.errors import LinkageError, QPError, SingularPositionError
from linkrepro.legacy import rahman1996
from linkrepro.port.rahman1996.balance import CRANK_DEG, CSSP_CORRECTED, CSSP_PRINTED, balance
from linkrepro.port.rahman1996.data import Constants, CsspInputs
from linkrepro.port.rahman1996.listing import listing_pass
from linkrepro.port.slider_crank.geometry import initial_estimate
from linkrepro.port.slider_crank.kinematics import kinematics


def near_toggle(delta: float, alpha4_deg: float = 90.0) -> dict:
    """a2 = (a1 + a4)(1 + delta): at crank angle 0 the rod is 1.4*sqrt(delta) from perpendicular
    to the slider axis (alpha4 = 90 or 270 deg, s1 = 0)."""
    return dict(a1=2.0, a2=3.0 * (1.0 + delta), a4=1.0, alpha4_deg=alpha4_deg, s1=0.0)


ENGINES = {"legacy": lambda g: rahman1996.cssp(**g),
           "port_printed": lambda g: balance(CsspInputs(**g), CSSP_PRINTED),
           "port_corrected": lambda g: balance(CsspInputs(**g), CSSP_CORRECTED)}


def outcome(engine: str, geometry: dict):
    try:
        ENGINES[engine](geometry)
    except LinkageError as exc:
        return type(exc).__name__, exc.angle_deg
    except QPError as exc:
        return "QPError", None
    return "returns", None


@pytest.mark.parametrize("engine", ENGINES)
def test_the_issues_geometry_is_a_singular_position_at_0_deg(engine):
    """a2 = 3(1 + 1e-8): REAL*4 holds it as 3.0 = a1 + a4 (the rod exactly perpendicular to the
    slider axis at 0 deg, kappa 9e7 at the listing's Newton's position), the double engine
    1.4e-4 from it (kappa 1.4e4).  All three raised QPError with no angle (|H| ~ 1e20), and
    after the QPROG mend (item 2) returned tables with |H| up to 3e34."""
    with pytest.raises(SingularPositionError) as info:
        ENGINES[engine](near_toggle(1e-8))
    assert info.value.angle_deg == 0.0
    assert info.value.values["condition"] > checks.POSITION_CONDITION_LIMIT


@pytest.mark.parametrize("delta", [3e-8, 0.0])
@pytest.mark.parametrize("alpha4_deg", [90.0, 270.0])
def test_near_and_at_the_singularity_legacy_and_the_port_agree(delta, alpha4_deg):
    geometry = near_toggle(delta, alpha4_deg)
    assert outcome("legacy", geometry) == outcome("port_printed", geometry) == ("SingularPositionError", 0.0)
    assert outcome("port_corrected", geometry) == ("SingularPositionError", 0.0)


@pytest.mark.parametrize("delta", [1e-3, 1e-5])
def test_short_of_the_limit_every_engine_answers(delta):
    """delta = 1e-5: kappa 670 (listing) and 447 (closed loop); one REAL*4 rounding of a2 moves
    the tables by 0.6 %.  (At delta = 1e-7, kappa 7500 and 4470, by 37 %: register D150.)"""
    for engine in ENGINES:
        assert outcome(engine, near_toggle(delta)) == ("returns", None), engine


def test_the_published_example_is_far_inside():
    """Section 5.2's geometry: kappa at most 2.9 at the listing's positions (both passes) and
    1.5 at the closed loop's, 1400 times below the limit."""
    q = rahman1996.cssp()["positions"]                  # (pass, position, theta2 eta2 theta3 eta3 s4)
    listing = checks.listing_condition(q[..., 0], q[..., 1], q[..., 2])
    closed = kinematics(CsspInputs(), np.radians(CRANK_DEG)).condition
    assert listing.max() < 3.0 and closed.max() < 2.0
    assert checks.POSITION_CONDITION_LIMIT / max(listing.max(), closed.max()) > 1400


#: geometries 291, 294, 310 and 419 of the differential sample (harness/scenes/rahman1996/
#: differential.py; a1, a2, a4, s1 as the build's REAL*4 holds them, alpha4 to the last bit: the
#: listing is chaotic there): the closed loop's formula for kappa, taken at the listing's theta2
#: and eta2, gives 7e3..1.3e4 (that rod would be nearly perpendicular to the slider's axis), but
#: the listing's own velocity equations have kappa <= 3 there: its loop never closes (D079)
LISTING_FAR_FROM_ITS_SINGULARITY = [
    dict(a1=1.7759770154953003, a2=10.919560432434082, a4=-2.0461246967315674, s1=-0.800599992275238,
         alpha4_deg=6.627755225770051),
    dict(a1=1.676375389099121, a2=8.820219993591309, a4=0.10299286991357803, s1=-0.4887320399284363,
         alpha4_deg=358.8615089753694),
    dict(a1=0.5511613488197327, a2=8.414385795593262, a4=-1.6511118412017822, s1=-0.24994251132011414,
         alpha4_deg=1.7374593175069775),
    dict(a1=2.4408013820648193, a2=6.278026580810547, a4=0.17996110022068024, s1=-0.7385988235473633,
         alpha4_deg=1.4272566792764696)]


@pytest.mark.parametrize("geometry", LISTING_FAR_FROM_ITS_SINGULARITY)
def test_the_listing_is_judged_by_its_own_equations(geometry):
    """kappa of the listing's VM is measured, not the closed loop's formula at the listing's
    angles: legacy and the port with the listing's bugs return there, with tables of the
    example's size (|H| < 1e7)."""
    run = rahman1996.cssp(**geometry)
    assert np.abs(run["hessian"]).max() < 1e7
    assert outcome("port_printed", geometry) == ("returns", None)


def test_listing_pass_refuses_a_singular_position():
    c = Constants.of(CsspInputs(**near_toggle(0.0)), True)
    with pytest.raises(SingularPositionError) as info:
        listing_pass(CRANK_DEG, initial_estimate(c, True), c)
    assert info.value.angle_deg == 0.0


def mp_condition(geometry: dict, crank_deg: float) -> float:
    """kappa of the exact closed loop at one crank angle, in 30-digit mpmath: the loop
    Q(s4) - P - a2 u(theta1 + theta2, eta2) = 0 solved in closed form, its Jacobian in
    (s4, a2 theta2, a2 eta2) by numerical differentiation, kappa from its singular values."""
    mp = mpmath.mp
    mp.dps = 30
    a1, a2, a4, s1 = (mp.mpf(geometry[k]) for k in ("a1", "a2", "a4", "s1"))
    al, th = mp.radians(mp.mpf(geometry["alpha4_deg"])), mp.radians(mp.mpf(crank_deg))
    k4 = mp.matrix([0, mp.sin(al), mp.cos(al)])
    p = mp.matrix([a1 * mp.cos(th), a1 * mp.sin(th), s1])
    b = a1 * mp.sin(al) * mp.sin(th) + s1 * mp.cos(al)
    c = 2 * a1 * a4 * mp.cos(th) + s1 ** 2 + a4 ** 2 + a1 ** 2 - a2 ** 2
    s4 = mp.sqrt(b * b - c) - b
    u = (mp.matrix([-a4, 0, 0]) - s4 * k4 - p) / a2
    phi, eta = mp.atan2(u[1], u[0]), -mp.asin(u[2])

    def closure(s, f, e):
        rod = mp.matrix([mp.cos(f) * mp.cos(e), mp.sin(f) * mp.cos(e), -mp.sin(e)])
        return mp.matrix([-a4, 0, 0]) - s * k4 - p - a2 * rod

    jac = mp.matrix(3, 3)
    for row in range(3):
        jac[row, 0] = mp.diff(lambda s: closure(s, phi, eta)[row], s4)
        jac[row, 1] = mp.diff(lambda f: closure(s4, f, eta)[row], phi) / a2
        jac[row, 2] = mp.diff(lambda e: closure(s4, phi, e)[row], eta) / a2
    sigma = mp.svd_r(jac, compute_uv=False)
    return float(max(sigma) / min(sigma))


@pytest.mark.parametrize("geometry, crank_deg", [
    (dict(CsspInputs().__dict__), 0.0), (dict(CsspInputs().__dict__), 130.0),
    (dict(a1=3.157, a2=8.373, a4=2.506, alpha4_deg=248.267, s1=0.001), 70.0),
    (near_toggle(1e-5), 0.0), (near_toggle(1e-8), 0.0), (near_toggle(1e-3, 270.0), 10.0)])
def test_the_closed_loops_condition_agrees_with_mpmath(geometry, crank_deg):
    """kinematics' kappa (double) against 30-digit mpmath.  The position itself carries
    eps * kappa^2 relative error (the cancellation in the loop's discriminant): 1e-6 covers
    kappa up to 1.4e4."""
    ours = kinematics(CsspInputs(**geometry), np.radians([crank_deg])).condition[0]
    assert ours == pytest.approx(mp_condition(geometry, crank_deg), rel=1e-6)
