"""Rahman (1991), the generalized slider crank: the port against independent computations
(complex-number planar analysis, energy balance, mpmath) and the claims of section 3.2
against the printed numbers (harness/published/rahman1991_claims.csv)."""
import numpy as np
import pandas as pd
import pytest

from linkrepro.errors import AssemblyError, ConvergenceError, SingularPositionError
from linkrepro.harness.scenes.rahman1991 import near_singular, planar_reference
from linkrepro.harness.published_tables import PUBLISHED_DIR
from linkrepro.port.rahman1991 import analysis as gsc, forces as gsc_forces, position
from linkrepro.port.slider_crank.geometry import CsspInputs
from linkrepro.port.slider_crank.kinematics import kinematics
from linkrepro.port.rahman1991.data import GscInputs, MassModel
from linkrepro.port.rahman1991.quirks import GSC_CORRECTED, GSC_PRINTED

DEG = np.arange(0.5, 360.0, 1.0)          # half degrees: no grid point on the a4 = 0 dead centres
PRINTED_FIXED = GSC_PRINTED.without("com_beyond_joint", "joint_force_signs")


@pytest.fixture(scope="module")
def claims():
    return pd.read_csv(PUBLISHED_DIR / "rahman1991_claims.csv", comment="#", dtype=str,
                       keep_default_na=False).set_index("claim")


def _gap_to_complex_numbers(frame: pd.DataFrame, a4: float) -> float:
    """Largest |port - complex-number analysis| relative to the column's largest value, at
    least 2 deg from the dead centres."""
    ref = planar_reference.analyse(frame.crank_deg.to_numpy(), a4=a4, torque=-GscInputs().torque)
    away = np.abs(np.sin(ref["th_rod"] - ref["theta1"])) > np.sin(np.radians(2.0)) * 0.2
    gaps = [np.max(np.abs(frame[k].to_numpy() - v)[away]) / np.max(np.abs(v[away]))
            for k, v in planar_reference.in_thesis_frames(ref).items()]
    return max(gaps)


@pytest.mark.parametrize("a4", [0.0, 10.0, 30.0])
def test_corrected_planar_case_equals_the_complex_number_analysis(a4):
    assert _gap_to_complex_numbers(gsc.analyse(GscInputs(a4=a4), DEG, GSC_CORRECTED), a4) < 1e-10


@pytest.mark.parametrize("quirks", [PRINTED_FIXED, PRINTED_FIXED.only("sine_denominator_rates", False)])
def test_printed_equations_with_two_sign_fixes_equal_the_complex_number_analysis(quirks):
    """Eqs. (46)-(69q) as printed, with the centre of mass on the link (D086) and action equal
    to reaction (D088), agree with the independent analysis to the Newton's 1e-7 tolerance."""
    for a4 in (0.0, 10.0, 30.0):
        assert _gap_to_complex_numbers(gsc.analyse(GscInputs(a4=a4), DEG, quirks), a4) < 1e-6


def test_printed_equations_as_printed_do_not_equal_the_complex_number_analysis():
    """The claim of section 3.2 (planar case = complex algebra) fails for the printed forces."""
    frame = gsc.analyse(GscInputs(a4=10.0), DEG, GSC_PRINTED)
    assert _gap_to_complex_numbers(frame, 10.0) > 0.1
    assert np.max(np.abs(frame.s4 - planar_reference.analyse(DEG, a4=10.0)["s4"])) < 1e-6   # kinematics agree


SPATIAL = [GscInputs(a4=30.0, s1=3.5), GscInputs(a4=20.0, alpha4_deg=232.0), GscInputs(a4=30.0, s1=9.0)]


@pytest.mark.parametrize("inputs", SPATIAL)
def test_printed_reproduces_the_constant_and_zero_components(inputs, claims):
    """On the printed method's answers off the plane: each a stop of its Newton where the loop
    stays open (D085), reported as such, not converged."""
    frame = gsc.analyse(inputs, DEG, GSC_PRINTED)
    ok = frame[frame.status.isin(gsc.ANSWERED)]
    assert len(ok) > 300 and not ok.converged.any() and (ok.closure > position.closure_tolerance(inputs, inputs.s1)).all()
    assert set(ok.status) <= {f"{position.NEWTON}: {position.LOOP_OPEN}", f"{position.DFP_THEN_NEWTON}: {position.LOOP_OPEN}"}
    assert np.max(np.abs(ok.F2j - float(claims.loc["f2j_constant", "value"]))) <= 0.005
    assert np.max(np.abs(ok[["T4i", "T4j", "T4k", "F2k"]].to_numpy())) < 1e-9
    assert np.max(np.abs(ok.T1i + ok.F1j * inputs.s1)) < 1e-9
    assert np.max(np.abs(ok.T1j - ok.F1i * inputs.s1)) < 1e-9


def _kinetic_energy(inputs: GscInputs, kin) -> np.ndarray:
    """Kinetic energy (lbf in) from the exact loop's velocities: crank about its axis and
    sliding, spin-free rod, translating slider (centres of mass at mid-link)."""
    mass = MassModel.of(inputs, com_beyond_joint=False)
    (m1, m2, m3), w = mass.m, inputs.omega
    crank = 0.5 * m1 * mass.k2[0][2] * w ** 2 + 0.5 * m1 * kin.Pd[:, 2] ** 2
    i_t = m2 * (mass.k2[1][1] - inputs.a2 ** 2 / 4.0)
    v_g2 = (kin.Pd + kin.Qd) / 2.0
    rod = 0.5 * m2 * np.sum(v_g2 ** 2, axis=1) + 0.5 * i_t * np.sum(np.cross(kin.u, kin.ud) ** 2, axis=1)
    return crank + rod + 0.5 * m3 * np.sum(kin.Qd ** 2, axis=1)


@pytest.mark.parametrize("inputs, branch", [(x, 1) for x in SPATIAL + [GscInputs(a4=10.0, s1=2.0, alpha=1.0), GscInputs(a4=20.0)]]
                         + [(GscInputs(a4=30.0, s1=3.5), -1), (GscInputs(a4=10.0, s1=2.0, alpha=1.0), -1)])
def test_corrected_forces_satisfy_the_energy_balance(inputs, branch):
    """dKE/dt = power of the frame's loads on the moving links: -T1k w - F1k S1' + F4k S4'
    (the loads are the links' own on the frame).  dKE/dt by 8th-order differences in theta1;
    on either root of |Q - P| = a2 (``branch``)."""
    geom = CsspInputs(a1=inputs.a1, a2=inputs.a2, a4=inputs.a4, alpha4_deg=inputs.alpha4_deg,
                      s1=inputs.s1, rpm=inputs.rpm)
    th, h = np.radians(DEG), 1e-3
    ke = lambda t: _kinetic_energy(inputs, kinematics(geom, t, np.stack(inputs.axial(t)), branch=branch))
    coef = [(1, 4 / 5), (2, -1 / 5), (3, 4 / 105), (4, -1 / 280)]
    dke = sum(c * (ke(th + k * h) - ke(th - k * h)) for k, c in coef) / h * inputs.omega
    kin = kinematics(geom, th, np.stack(inputs.axial(th)), branch=branch)
    assert np.all(np.sign(kin.s4 + inputs.a1 * np.sin(inputs.alpha4) * np.sin(th)
                          + inputs.axial(th)[0] * np.cos(inputs.alpha4)) == branch)
    f = gsc_forces.corrected_forces(inputs, kin)
    power = -f["T1k"] * inputs.omega - f["F1k"] * inputs.axial(th)[1] + f["F4k"] * kin.s4d
    assert np.max(np.abs(dke - power)) < 1e-6 * np.max(np.abs(power))


def test_corrected_crank_pin_thrust_and_bearing_moments_when_the_rod_tilts():
    """The rod tilted out of the crank's plane pushes the crank along its axis: 2F2k != 0, the
    frame takes it (1F1k = -2F2k), and 1T1i = -1F1j S1 - a1 s(theta1) 2F2k (crank moments about
    the origin of {1}): the claims f2k_zero and t1_moments hold only in the plane."""
    inputs = GscInputs(a4=30.0, s1=3.5)
    frame = gsc.analyse(inputs, DEG, GSC_CORRECTED)
    assert np.max(np.abs(frame.F2k)) > 0.5
    np.testing.assert_allclose(frame.F1k, -frame.F2k, atol=1e-9)
    th = np.radians(frame.crank_deg)
    np.testing.assert_allclose(frame.T1i, -frame.F1j * inputs.s1 - inputs.a1 * np.sin(th) * frame.F2k,
                               atol=1e-8 * np.max(np.abs(frame.T1i)))
    assert np.max(np.abs(frame[["T4i", "T4j", "T4k"]].to_numpy())) < 1e-9 * np.max(np.abs(frame.F4k))


def test_the_iterative_correction_69h_69k_never_changes_2F2i():
    """(69i), (69j) satisfy (62a) identically, so the loop of (69k) exits at once."""
    inputs = GscInputs(a4=30.0, s1=3.5)
    th = np.radians(DEG)
    run = position.positions(inputs, th)
    q_d, q_dd = gsc.printed_rates(run.q, inputs, th, True)
    with np.errstate(all="ignore"):
        out = gsc_forces.printed_forces(inputs, th, run.q, q_d, q_dd)
    assert out["corrections"] == 0
    assert np.max(np.abs(out["eq62a"])) < 1e-9


def test_typed_errors_with_the_crank_angle():
    with pytest.raises(AssemblyError) as exc:
        gsc.analyse(GscInputs(a4=40.0), DEG, GSC_CORRECTED, strict=True)
    assert exc.value.angle_deg == 0.5
    with pytest.raises(ConvergenceError) as exc:
        gsc.analyse(GscInputs(a4=0.0, s1=9.0), DEG, GSC_PRINTED, strict=True)
    assert exc.value.angle_deg is not None
    with pytest.raises(SingularPositionError) as exc:
        gsc.analyse(GscInputs(a4=0.0), [80.0, 90.0, 100.0], GSC_CORRECTED, strict=True)
    assert exc.value.angle_deg == 90.0
    for bad in (dict(a1=-1.0), dict(a2=float("nan")), dict(rpm=0.0), dict(s1=float("inf"))):
        with pytest.raises(ValueError):
            GscInputs(**bad)


def test_non_convergence_is_told_apart_from_non_assembly():
    """a4 = 0, S1 = 9: the mechanism assembles at every angle; the printed Newton fails."""
    inputs = GscInputs(a4=0.0, s1=9.0)
    th = np.radians(gsc.CRANK_DEG)
    assert position.assembles(inputs, th, 9.0).all()
    run = position.positions(inputs, th)
    assert (run.status == position.NOT_CONVERGED).any()
    assert not (run.status == position.CANNOT_ASSEMBLE).any()
    frame = gsc.analyse(GscInputs(a4=40.0), gsc.CRANK_DEG, GSC_PRINTED)
    assert (frame.status == position.CANNOT_ASSEMBLE).any() and frame[~frame.converged].F1i.isna().all()


def test_a4_30_converges_up_to_s1_9_as_the_thesis_says(claims):
    s1 = float(claims.loc["converge_a4_30", "value"])
    run = position.positions(GscInputs(a4=30.0, s1=s1), np.radians(gsc.CRANK_DEG), stop_at_failure=True, branch=None)
    assert run.stopped.all()                  # the thesis's "converges": its Newton stops (the loop is open, D085)


def test_printed_positions_close_only_in_the_plane():
    th = np.radians(DEG)
    planar = position.positions(GscInputs(a4=10.0), th)
    spatial = position.positions(GscInputs(a4=30.0, s1=3.5), th)
    assert np.nanmax(planar.closure) < 1e-5 and np.nanmin(spatial.closure) > 1e-3


@pytest.fixture(scope="module")
def singular():
    return near_singular.table()


def test_near_theta2_zero_round_off_is_not_the_cause(singular):
    """The printed formulas evaluate to 14+ digits against 40-digit mpmath at the same inputs;
    the corrected path keeps 14+ digits of the exact closed loop's rates everywhere."""
    assert singular.digits_printed_roundoff.min() > 14.0
    assert singular.digits_corrected_vs_truth.min() > 14.0


def test_near_theta2_zero_the_printed_formulation_loses_its_digits(singular):
    """Planar case: within 1e-6 deg of theta2 = 0 the printed eta2'' keeps fewer than 8 digits
    (input errors of 1e-16 amplified by 1/sin^2 theta2); the corrected one keeps them."""
    planar = singular[(singular.s1 == 0.0) & (singular.alpha4_deg == 270.0)]
    close = planar[(planar.offset_deg <= 1e-6) & (planar.quantity == "eta2_dd")]
    assert len(close) > 0 and (close.digits_printed_vs_truth < 8.0).all()
    assert (close.digits_corrected_vs_truth > 14.0).all()


def test_printed_rates_in_the_plane_equal_the_exact_rates():
    """Away from theta2 = 0, eqs. (39)-(43), (38a)-(42a) give the closed loop's rates."""
    inputs = GscInputs(a4=10.0)
    th = np.radians(np.arange(5.0, 90.0, 5.0))
    kin = kinematics(CsspInputs(a1=12.0, a2=50.0, a4=10.0, alpha4_deg=270.0, s1=0.0, rpm=50.0), th)
    q = np.stack([kin.theta2, kin.eta2, *gsc.ball_angles(kin), kin.s4], axis=1)
    q_d, q_dd = gsc.printed_rates(q, inputs, th, True)
    np.testing.assert_allclose(q_d[:, [0, 4]], np.stack([kin.theta2d, kin.s4d], 1), rtol=1e-10)
    np.testing.assert_allclose(q_dd[:, [0, 4]], np.stack([kin.theta2dd, kin.s4dd], 1), rtol=1e-9)


def test_scene_csv_has_the_issue_columns_and_claims_table(tmp_path):
    """port.csv's columns as specified; claims measured on a small grid."""
    from linkrepro.harness.scenes.rahman1991 import example
    spec = ("a4, alpha4_deg, s1, crank_deg, converged, s4, theta2, eta2, theta3, eta3, F1i, F1j, F1k, T1i, "
            "T1j, T1k, F2i, F2j, F2k, F3i, F3j, F3k, F4i, F4j, F4k, T4i, T4j, T4k").split(", ")
    assert gsc.COLUMNS == spec
    frames = {name: gsc.sweep(q, a4=(0.0, 30.0), alpha4_deg=(270.0,), s1=(0.0, 3.5))
              for name, q in example.ENGINES.items()}
    assert all(len(f) == 4 * 361 and f.converged.dtype == bool for f in frames.values())
    table = example.measure_claims(frames, pd.DataFrame(columns=["claim", "engine", "measured", "verdict", "what"]))
    verdict = table.set_index(["claim", "engine"]).verdict
    assert verdict["f2j_constant", "port_printed"] == verdict["f2j_constant", "port_corrected"] == "reproduced"
    assert verdict["planar_complex", "port_corrected"] == "reproduced"
    assert verdict["planar_complex", "port_printed"] == "contradicted"
    assert verdict["f2k_zero", "port_corrected"] == "contradicted"


def test_a4_20_converges_from_alpha4_232_to_310_as_the_thesis_says(claims):
    lo, hi = (float(v) for v in claims.loc["converge_alpha4", "value"].split())
    configs = [GscInputs(a4=20.0, alpha4_deg=lo), GscInputs(a4=20.0, alpha4_deg=hi)]
    runs = position.positions_batch(configs, np.radians(gsc.CRANK_DEG), stop_at_failure=True, branch=None)
    assert all(run.stopped.all() for run in runs)
