"""harness/scenes/ali1977/sums.py: the K.E.D. tables' printed sums X_new = X + dX, Y_new = Y + dY."""
import pandas as pd
import pytest

from linkrepro.harness import register
from linkrepro.harness.scenes.ali1977 import sums
from linkrepro.harness.published_tables import PublishedTable

COLUMNS = ["input_deg", "rigid_x", "rigid_y", "src_dx", "src_dy", "src_xnew", "src_ynew",
           "cog_dx", "cog_dy", "cog_xnew", "cog_ynew"]


def _table(*rows) -> PublishedTable:
    return PublishedTable("ali1977_table1", pd.DataFrame(list(rows), columns=COLUMNS))


def test_a_sum_within_the_half_units_is_consistent_and_beyond_them_a_misprint():
    # X = 1.0004, dX = 0.0014 print as 1.000, 0.001 and X_new = 1.0018 as 1.002: one unit off is
    # rounding (three half-units at most), two units off is not
    good = ["0", "1.000", "2.000", "0.001", "0.002", "1.002", "2.002", "0.000", "0.000", "1.000", "2.000"]
    bad = ["20", "1.000", "2.000", "0.001", "0.002", "1.003", "2.102", "0.000", "0.000", "1.000", "2.000"]
    checks = sums.sum_checks("ali1977_table1", _table(good, bad)).set_index(["input_deg", "sum_column"])
    assert checks.loc[(0, "src_xnew"), "verdict"] == "consistent"
    assert checks.loc[(20, "src_xnew"), "verdict"] == "misprint"        # 2 units off, bound 1.5
    assert checks.loc[(20, "src_ynew"), "gap"] == pytest.approx(0.1)
    assert (checks.drop([(20, "src_xnew"), (20, "src_ynew")])["verdict"] == "consistent").all()


def test_table_three_prints_two_cognate_y_new_that_are_not_y_plus_dy():
    checks = sums.sum_checks("ali1977_table3")
    bad = checks[checks.verdict == "misprint"]
    cognate = bad[bad.sum_column == "cog_ynew"]
    assert sorted(cognate.input_deg) == [40, 280]
    assert list(cognate.gap.round(3)) == [0.2, 0.1]


@pytest.mark.parametrize("table", sorted(sums.SUMS))
def test_every_misprint_the_sums_reveal_is_registered_as_one(table):
    """Each failed identity has one of its three cells claimed by a published-misprint entry."""
    entries = [e for e in register.load().values() if e.kind == "published-misprint"]
    scene = table.replace("_", "-")
    for row in sums.sum_checks(table).query("verdict == 'misprint'").itertuples():
        cells = (row.sum_column, *dict(sums.SUMS[table])[row.sum_column])
        assert any(claim.covers(scene, int(row.input_deg), cell, "legacy")
                   for entry in entries for claim in entry.cells for cell in cells), (table, row)
