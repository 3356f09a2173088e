"""The sign and frame search over the reconstructed cognate loads (D037)."""
import numpy as np
import pytest

from linkrepro.harness.scenes.ali1977 import cognate_search
from linkrepro.harness.published_tables import PublishedTable
from linkrepro.port.ali1977.case2 import case2_cognate
from linkrepro.port.ali1977.case3 import case3_cognate


@pytest.mark.parametrize("case, reconstruction", [("II", case2_cognate), ("III", case3_cognate)])
def test_the_search_starts_from_the_reconstruction_itself(case, reconstruction):
    """The search's own formulation, with no variant, is the port's reconstruction, bit for bit."""
    frame = cognate_search.columns(case)
    port = reconstruction(cognate_search.DEG)
    np.testing.assert_array_equal(frame["cog_dx"], port["dx"])
    np.testing.assert_array_equal(frame["cog_dy"], port["dy"])


@pytest.mark.parametrize("case", ["II", "III"])
def test_every_variant_changes_the_result(case):
    """A term whose flip changed nothing would be no variant (e.g. a whole row of beta)."""
    base = cognate_search.columns(case)
    for flips in cognate_search.variants(case)[1:]:
        frame = cognate_search.columns(case, flips)
        assert not np.array_equal(frame["cog_dx"], base["cog_dx"]) or \
            not np.array_equal(frame["cog_dy"], base["cog_dy"]), flips


def test_case2_reconstruction_reproduces_every_cognate_deflection_of_table2():
    """All 36 cognate dX, dY cells of rows 0-340 within half a unit of the printed digit."""
    published = PublishedTable.load("ali1977_table2")
    pub = published.values.set_index("input_deg").loc[cognate_search.DEG]
    half = published.half_unit.set_index(published.values["input_deg"]).loc[cognate_search.DEG]
    frame = cognate_search.columns("II")
    for col in ("cog_dx", "cog_dy"):
        err = np.abs(frame[col].to_numpy() - pub[col].to_numpy())
        assert (err <= half[col].to_numpy() * (1 + 1e-9)).all(), col


def test_case2_reconstruction_is_the_search_s_unique_best():
    found = cognate_search.search("II")
    assert found.iloc[0]["variant"] == "(reconstruction)"
    assert found.iloc[1]["cells_matched"] < found.iloc[0]["cells_matched"]
    n = len(cognate_search.CASE2_TERMS) + len(cognate_search.CASE2_FRAMES)
    assert len(found) == 1 + n + n * (n - 1) // 2          # the reconstruction, singles, pairs


def test_an_unknown_variant_is_a_clear_error():
    with pytest.raises(ValueError, match="no term or frame"):
        cognate_search.columns("II", ("P9",))
