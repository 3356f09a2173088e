"""The harness on Rahman (1996): the published tables as transcribed, every cell explained,
the section 5.3 percentages."""
import numpy as np
import pandas as pd
import pytest

from linkrepro.harness.scenes.rahman1996 import figures
from linkrepro.harness.diff import diff_scene, quirk_effects
from linkrepro.harness.published_tables import PublishedTable
from linkrepro.harness.scenes import TABLES as SCENES, get

NAMES = [name for name in SCENES if name.startswith("rahman1996")]


def test_seven_scenes():
    assert NAMES == [f"rahman1996-table5_{k}" for k in range(1, 8)]


@pytest.mark.parametrize("name", NAMES)
def test_published_table_shape(name):
    scene = get(name)
    table = PublishedTable.load(scene.table)
    assert list(table.text.columns) == scene.columns
    if name.endswith("5_1"):
        assert len(table.text) == 6 and table.values[["before", "after"]].notna().all().all()
    else:
        assert list(table.values["crank_deg"]) == list(range(0, 361, 10))
        # as printed, every table repeats row 0 as row 360
        assert table.text.iloc[-1, 1:].tolist() == table.text.iloc[0, 1:].tolist()


@pytest.mark.parametrize("name", NAMES)
def test_no_cell_is_unexplained(name, register):
    scene = get(name)
    published = PublishedTable.load(scene.table)
    results = {engine: scene.run(engine) for engine in ("printed", "legacy", "port_printed", "port_corrected")}
    diff = diff_scene(scene, published, results, register)
    assert (diff["status"] == "unexplained").sum() == 0, diff[diff["status"] == "unexplained"]
    registered = diff[diff["status"] == "registered"]
    for ids in registered["register_ids"]:
        assert set(ids.split()) <= set(register)


@pytest.mark.parametrize("name", NAMES)
def test_each_quirk_moves_exactly_the_columns_its_entry_names(name, register):
    """Switch each bug of the listing off alone: the columns it moves are those registered."""
    scene = get(name)
    effects = quirk_effects(scene, PublishedTable.load(scene.table), scene.port(scene.quirks[0]))
    for quirk, moved in effects.items():
        entry = next(e for e in register.values() if e.quirk == quirk)
        assert sorted(c for c in scene.values if moved[c].any()) == sorted(entry.moves[name]), (entry.id, name)


def test_half_unit_reads_exponents():
    half = PublishedTable.load("rahman1996_table5_1").half_unit
    assert half.at[0, "before"] == pytest.approx(0.5e-10)          # 2.048826E-04
    assert np.isnan(half.at[0, "link"])


def test_section_5_3_averages_are_legacy_means():
    """D059: five of the six averages quoted in section 5.3 are legacy's 37-row means to
    the quoted digits; the shaking moment's is not."""
    stats = figures.section_5_3(figures.percentages())
    legacy = stats[stats["engine"] == "legacy"].set_index("table")
    quoted = pd.read_csv(figures.PUBLISHED_DIR / "rahman1996_section5_3.csv", comment="#",
                         dtype={"table": str}).set_index("table")
    for table in ["5_2", "5_3", "5_5", "5_6", "5_7"]:
        digits = len(str(quoted.at[table, "average"]).split(".")[1])
        assert abs(legacy.at[table, "mean37_pct"] - quoted.at[table, "average"]) < 10.0 ** -digits, table
    assert abs(legacy.at["5_4", "mean37_pct"] - quoted.at["5_4", "average"]) > 0.01
