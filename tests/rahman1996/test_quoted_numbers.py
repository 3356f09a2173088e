"""harness/scenes/rahman1996/quoted_numbers.py: section 5.3's quoted numbers against the tables' rows."""
import pytest

from linkrepro.harness import register
from linkrepro.harness.published_tables import PublishedTable
from linkrepro.harness.scenes.rahman1996 import quoted_numbers


def test_section_5_3_numbers_the_published_tables_give_are_consistent():
    """The quoted extremes and averages of Table 5.3 (0.7248 to 0.732, 0.728) are the table's own,
    to one unit of the quoted digit; Figure 5.1's +4.59 % is not (5.2's printed 240 row gives 16.77)."""
    checks = quoted_numbers.percentage_checks().set_index(["table", "quantity"])
    assert (checks.loc["5_3", "verdict"] == "consistent").all()
    assert checks.loc[("5_2", "range_from"), "verdict"] == "differs"
    row = PublishedTable.load("rahman1996_table5_2").values.set_index("crank_deg").loc[240]
    assert checks.loc[("5_2", "range_from"), "from_table"] == pytest.approx(
        (row["before"] - row["after"]) * 100 / row["before"])


def test_a_quoted_digit_allows_one_unit():
    assert quoted_numbers._last_digit_unit("0.7248") == pytest.approx(1e-4)
    assert quoted_numbers._last_digit_unit("1.3") == pytest.approx(0.1)
    assert quoted_numbers._last_digit_unit("22") == 1.0


def test_every_section_5_3_number_the_tables_do_not_give_is_registered():
    checks = quoted_numbers.percentage_checks(register.load())
    bad = checks[checks["verdict"] == "differs"]
    assert len(bad), "the check found nothing: section 5.3 quotes three extremes no table row gives (D058)"
    assert (bad["register_ids"] != "").all(), bad[bad["register_ids"] == ""]


def test_no_register_claim_on_section_5_3_names_a_consistent_number():
    checks = quoted_numbers.percentage_checks(register.load())
    consistent = checks[checks["verdict"] == "consistent"]
    assert (consistent["register_ids"] == "").all(), consistent[consistent["register_ids"] != ""]
