"""The 1996 listing's QP and bearing torque against the thesis text (register D130-D132).

D130: the QP fixes only the pair sums x1+x2+x3 and x5+x6+x7, so the masses at the centres of
mass (x4, x8) fall to their bounds and the links lose mass, while the text says the mass stays
constant; Table 5.1 cannot show it, Tables 5.3-5.7 need it.  D131: the QP's data are typed
rounded (the slider x9 = 0.01553 for M3).  D132: Table 5.6's norm includes the input torque
T0, which eq. (4.1) subtracts (and D067 puts it into the objective's bearing-moment term).
Every expected value is computed here (the DATA, the masses, w' of eq. 4.5, the published
tables through harness/published), none typed from a table.
"""
import numpy as np
import pandas as pd
import pytest

from linkrepro.legacy import rahman1996
from linkrepro.harness.scenes.rahman1996 import figures
from linkrepro.harness.published_tables import PublishedTable
from linkrepro.port.rahman1996 import balance as cssp
from linkrepro.port.rahman1996.balance import CsspInputs, balance, link_masses
from linkrepro.port.rahman1996.data import MASS_DECREASE, QP_BOUNDS, Constants, qp_constraints
from linkrepro.port.rahman1996.quirks import CSSP_CORRECTED, CSSP_PRINTED

#: the series tables in the order of the 37 x 12 ``table`` (before, after pairs)
SERIES = ("5_2", "5_3", "5_4", "5_5", "5_6", "5_7")


@pytest.fixture(scope="module")
def run():
    return rahman1996.cssp()


@pytest.fixture(scope="module")
def consts():
    return Constants.of(CsspInputs(), True)


def published_after(table: str) -> np.ndarray:
    """Rows 0-350 of a published 'after' column (row 360 is a copy of row 0, D061/D062)."""
    return PublishedTable.load(f"rahman1996_table{table}").values["after"].to_numpy()[:36]


def median_rel(column: np.ndarray, published: np.ndarray) -> float:
    """Median relative difference over rows 0-350 (robust to D058's one-digit misprints)."""
    return float(np.median(np.abs(column[:36] - published) / np.abs(published)))


def mean_decrement(table: np.ndarray, k: int) -> float:
    """Section 5.3's average: the 37-row mean of (before - after) * 100 / before (D059)."""
    before, after = table[:, 2 * k], table[:, 2 * k + 1]
    return float(np.mean((before - after) * 100.0 / before))


def test_listing_qp_lets_the_cg_masses_fall_and_the_links_lose_mass(run, consts):
    """D130: x4, x8 sit on their lower bounds; the loss is what the DATA alone predict
    (pair sum b(1) plus the bound b(7), against M1), about w'/4 of each link (the centre's
    mass is a quarter of the link and may lose w' = 5 %); the port gives the same masses."""
    b, x = consts.qp_bounds, run["solution"]
    assert x[3] == b[6] and x[7] == b[10]
    before, after = link_masses(consts.point_masses), link_masses(x)
    loss = after / before - 1.0
    predicted = np.array([(b[0] + b[6]) / before[0], (b[1] + b[10]) / before[1]]) - 1.0
    np.testing.assert_allclose(loss[:2], predicted, rtol=0, atol=4 * np.finfo(np.float32).eps)   # REAL*4 sol
    np.testing.assert_allclose(loss[:2], -MASS_DECREASE / 4, rtol=0.02)
    np.testing.assert_allclose(before[:2], consts.masses[:2], rtol=1e-15)
    np.testing.assert_allclose(balance()["solution"], x, rtol=1e-7)


def test_published_after_columns_need_the_lost_mass(run, consts):
    """D130: with x4, x8 raised back so that each link keeps its mass (the pairs as the QP
    left them), no published 'after' column of Tables 5.3-5.7 is reproduced; with the
    QP's masses every one is, to the REAL*4 floor (D056)."""
    kept = run["solution"].copy()
    kept[3] = consts.masses[0] - kept[0:3].sum()
    kept[7] = consts.masses[1] - kept[4:7].sum()
    np.testing.assert_allclose(link_masses(kept)[:2], consts.masses[:2], rtol=1e-7)
    restored = rahman1996.cssp(solution=kept)["table"]
    for k, table in enumerate(SERIES[1:], start=1):
        published = published_after(table)
        assert median_rel(run["table"][:, 2 * k + 1], published) < 1e-7, table
        assert median_rel(restored[:, 2 * k + 1], published) > 3e-3, table


def test_section_5_3_improvements_are_mostly_the_lost_mass(run):
    """D130: the port with the links' masses kept (qp_cg_masses_free off) leaves a tenth or
    less of the shaking force's and the input torque's quoted average decrement, which the
    listing's own run reproduces (D059)."""
    kept = balance(quirks=CSSP_PRINTED.only("qp_cg_masses_free", False))
    np.testing.assert_allclose(link_masses(kept["solution"])[:2],
                               link_masses(Constants.of(CsspInputs(), True).point_masses)[:2], rtol=1e-4)
    quoted = pd.read_csv(figures.PUBLISHED_DIR / "rahman1996_section5_3.csv", comment="#",
                         dtype={"table": str}).set_index("table")["average"]
    for table in ("5_3", "5_7"):
        k = SERIES.index(table)
        assert abs(mean_decrement(run["table"], k) - quoted[table]) < 1e-3, table
        assert abs(mean_decrement(kept["table"], k)) < quoted[table] / 10, table


def test_kept_mass_qp_port_equals_legacy(run, consts):
    """The corrected constraints (x4 = m14, x8 = m24) on legacy's own Hessian, solved by our
    FORTRAN QPROG, and the legacy run at that answer (D055) equal the port with the switch off."""
    port = balance(quirks=CSSP_PRINTED.only("qp_cg_masses_free", False))
    rows, bounds, equalities = qp_constraints(consts, False, True, True)
    ref = rahman1996.qprog(run["hessian"], np.zeros(9), rows, bounds, equalities)["sol"]
    np.testing.assert_allclose(port["solution"], ref, rtol=1e-7)
    np.testing.assert_allclose(port["solution"][[3, 7]], consts.point_masses[[3, 7]], rtol=1e-7)
    table = rahman1996.cssp(solution=port["solution"])["table"]
    assert np.max(np.abs(port["table"] - table) / np.abs(table).max(axis=0)) < 1e-12


def test_table_5_1_implies_the_pair_sums_and_cannot_see_the_centre_masses(run, consts):
    """D130: the published 'after' moments (harness/published) give each link's three pair
    masses (eq. 2.9 with the arms of eq. 2.12); their sums are the listing's fixed b(1), b(2).
    The mass at the centre enters no moment: legacy prints the same Table 5.1 whether x4, x8
    fell or not, so the table cannot show the lost mass."""
    after = PublishedTable.load("rahman1996_table5_1").values["after"].to_numpy()
    for link, arms in enumerate((consts.crank_arms, consts.rod_arms)):
        xa, ya, za = np.square(arms)
        system = np.array([[0.0, ya, za], [xa, 0.0, za], [xa, ya, 0.0]])
        pairs = np.linalg.solve(system, after[3 * link:3 * link + 3])
        np.testing.assert_allclose(pairs.sum(), consts.qp_bounds[link], rtol=2e-5)
        assert np.all(pairs >= consts.qp_bounds[3 + 4 * link] * (1 - 2e-5))
    raised = run["solution_table51"].copy()
    raised[[3, 7]] = consts.point_masses[[3, 7]]
    np.testing.assert_array_equal(rahman1996.cssp(solution=raised)["inertia"], run["inertia"])


def test_slider_mass_is_the_rounded_literal_not_m3(run, consts):
    """D131: sol(9) is DATA b(3) = M3 rounded to four significant digits, not M3 = 6.0/386.4;
    the published 'after' columns need the literal (their median error grows tenfold or more
    with x9 = M3); without the switch the port's x9 is M3 and, with D130 off as well, every
    link keeps its mass."""
    m3, x9 = consts.masses[2], run["solution"][8]
    assert x9 == np.float32(float(f"{m3:.4g}")) == np.float32(QP_BOUNDS[2])
    assert abs(x9 / m3 - 1.0) > 100 * np.finfo(np.float32).eps
    with_m3 = run["solution"].copy()
    with_m3[8] = m3
    table = rahman1996.cssp(solution=with_m3)["table"]
    for k, name in enumerate(SERIES[1:], start=1):
        published = published_after(name)
        assert median_rel(table[:, 2 * k + 1], published) > 10 * median_rel(run["table"][:, 2 * k + 1], published)
    exact = balance(quirks=CSSP_PRINTED.only("qp_data_rounded", False))
    assert exact["solution"][8] == np.float32(m3)
    both = balance(quirks=CSSP_PRINTED.without("qp_data_rounded", "qp_cg_masses_free"))
    np.testing.assert_allclose(link_masses(both["solution"]), consts.masses, rtol=2e-7)


def test_corrected_keeps_the_masses_so_the_shaking_force_cannot_change():
    """With each link's mass and centre of mass kept, the shaking force |sum m a_G| cannot
    change, whatever the QP does with the pairs (symmetric about the centre): CORRECTED's
    Table 5.3 'after' equals 'before'; with D130's switch on it falls with the lost mass."""
    table = balance(quirks=CSSP_CORRECTED)["table"]
    np.testing.assert_allclose(table[:, 3], table[:, 2], rtol=1e-8)
    lossy = balance(quirks=CSSP_CORRECTED.only("qp_cg_masses_free", True))["table"]
    assert np.all(lossy[:, 3] < table[:, 2] * (1 - 1e-3))


def test_table_5_6_includes_the_input_torque(run):
    """D132: legacy's bearing torque squared is the port's without T0 (switch off) squared
    plus legacy's own input torque (Table 5.7) squared, before and after: brt includes
    mt1z, where eq. (4.1)'s bearing moment is M1 - T0."""
    off = balance(quirks=CSSP_PRINTED.only("bearing_torque_with_input_torque", False))["table"]
    t = run["table"]
    for col in (8, 9):
        np.testing.assert_allclose(t[:, col] ** 2, off[:, col] ** 2 + t[:, col + 2] ** 2, rtol=1e-10)
    assert np.all(off[:, 8] < t[:, 8])


def test_input_torque_dominates_the_objective_through_the_crank_bearing_moment(consts, register):
    """D067/D132: the objective's bearing-moment term leaves t1z out (msq = t1x^2 + t1y^2, as
    eq. 4.1's M1 - T0), but t1x(5..9) = A1*t1z - S1*f1y brings it back: at the 'before'
    masses that part is 90.0 % of M-bar, and M-bar 86.4 % of the objective (both passes),
    the figures the two entries quote, to the digits they quote."""
    passes = list(cssp._passes(CsspInputs(), CSSP_PRINTED, consts))
    x = consts.point_masses
    full = stripped = 0.0
    for sweep in passes:
        moments, t0 = sweep.loads.moments[0], sweep.loads.input_torque
        assert not moments[..., 2].any()
        without = moments.copy()
        without[:, 4:9, 0] -= consts.a1 * t0[:, 4:9]
        full += np.sum(np.einsum("k,nkc->nc", x, moments) ** 2)
        stripped += np.sum(np.einsum("k,nkc->nc", x, without) ** 2)
    c3 = 37 * consts.masses[0] ** 2 * consts.a1_sq * consts.omega ** 4 * consts.bearing_length_sq
    objective = sum(x @ sweep.forms.sum(axis=0) @ x for sweep in passes)
    share_of_m_bar = f"{100 * (1.0 - stripped / full):.1f}"
    share_of_objective = f"{100 * full / c3 / objective:.1f}"
    assert (share_of_m_bar, share_of_objective) == ("90.0", "86.4")
    for entry in ("D067", "D132"):
        text = register[entry].evidence
        assert f"{share_of_m_bar} % of M-bar" in text and f"M-bar {share_of_objective} % of the objective" in text, entry
