"""harness/quantities.py and harness/results.py: every column in words with its unit, and a
scene's CSVs as DataFrames carrying their units.

The units expected are read from the published tables' own headers (harness/published/*.csv,
"Units: ..."), not from our output.  The runs: two fast table scenes (about 2 s together),
written once for the module.
"""
from __future__ import annotations

import os
import subprocess
import sys

import pandas as pd
import pytest

from linkrepro.harness import load
from linkrepro.harness.published_tables import PUBLISHED_DIR, PublishedTable
from linkrepro.harness.quantities import Quantity
from linkrepro.harness.results import describe
from linkrepro.harness.scene import RunOptions
from linkrepro.harness.scenes import SCENES, TABLES

#: a published table's "Units: ..." header (its start) -> the unit of its value columns
HEADER_UNITS = {"degrees, inches": "in", "lb-sec^2-inch": "lbf s^2 in", "none printed": "",
                "lbs;": "lbf", "lb-in;": "lbf in"}
#: the unit of the columns naming a row by angle
KEY_UNITS = {"input_deg": "deg", "crank_deg": "deg"}
SMALL = ("ali1977-table1", "rahman1996-table5_1")


def header_unit(table: str) -> str:
    """The unit a published table's header gives its values (KeyError if not in HEADER_UNITS)."""
    header = " ".join(line for line in (PUBLISHED_DIR / f"{table}.csv").read_text().splitlines()
                      if line.startswith("#"))
    printed = header.split("Units: ", 1)[1]
    return next(unit for start, unit in HEADER_UNITS.items() if printed.startswith(start))


@pytest.fixture(scope="module")
def out(tmp_path_factory):
    """An output folder with the SMALL scenes, as ``linkrepro reproduce --skip-readings`` writes it."""
    folder = tmp_path_factory.mktemp("run")
    for name in SMALL:
        SCENES[name].write(folder, RunOptions(measure_readings=False))
    return folder


def test_a_label_is_words_and_unit():
    assert Quantity("crank angle", "deg").label == "crank angle (deg)"
    assert Quantity("objective function G", "").label == "objective function G"


@pytest.mark.parametrize("name", TABLES)
def test_every_published_column_is_described_in_its_printed_unit(name):
    scene = TABLES[name]
    published = PublishedTable.load(scene.table)
    assert list(published.text.columns) == scene.columns
    value_unit = header_unit(scene.table)
    for column in scene.columns:
        quantity = describe(name, column)
        assert quantity.words and quantity.words != column, (name, column)
        assert not quantity.per_row
        expected = value_unit if column in scene.values else KEY_UNITS.get(column, "")
        assert quantity.unit == expected, (name, column)


def test_the_column_lists_of_the_other_scenes_are_described():
    """The columns the report scenes declare in code (the runs are too long for a test)."""
    from linkrepro.harness.scenes.ali1977 import appendix, sums
    from linkrepro.harness.scenes.rahman1991 import near_singular
    from linkrepro.harness.scenes.rahman1996 import quoted_numbers
    from linkrepro.port.rahman1991 import analysis
    names = {"rahman1991-example": [*analysis.COLUMNS, "status", "closure", *near_singular.QUANTITIES],
             "ali1977-appendixA": list(appendix.QUANTITIES),
             "rahman1996-figures": quoted_numbers.PERCENTAGE_COLUMNS,
             **{name: sums.COLUMNS for name, scene in TABLES.items() if scene.table in sums.SUMS}}
    for scene, columns in names.items():
        for column in columns:
            assert describe(scene, column).words, (scene, column)


def test_every_csv_of_a_run_is_read_with_units(out):
    for name in SMALL:
        frames = load(name, out)
        engines = {"published", "printed", "legacy", "port_printed", "port_corrected"}
        assert engines | {"diff"} <= set(frames)
        for stem, frame in frames.items():
            assert frame.attrs["scene"] == name
            assert frame.attrs["path"] == out / name / f"{stem}.csv"
            per_row = {c for c in frame.columns if c != "unit" and describe(name, c).per_row}
            assert set(frame.attrs["units"]) == set(frame.columns) - per_row - {"unit"}, (name, stem)
            assert ("unit" in frame) == bool(per_row), (name, stem)
        for stem in engines:
            assert frames[stem].attrs["units"] == {c: describe(name, c).unit for c in TABLES[name].columns}


@pytest.mark.parametrize("name", SMALL)
def test_the_diff_gives_each_row_the_unit_of_its_column(out, name):
    diff = load(name, out)["diff"]
    scene = TABLES[name]
    assert set(diff["column"]) == set(scene.values)
    assert set(diff["unit"]) == {header_unit(scene.table)}
    for column in ("published", "value", "abs_diff", "half_unit", "legacy", "diff_vs_legacy"):
        assert column not in diff.attrs["units"]
    key_unit = KEY_UNITS.get(scene.key_name, "")
    assert diff.attrs["units"][scene.key_name] == key_unit


def test_a_long_file_with_several_units_gives_each_row_its_own(tmp_path):
    folder = tmp_path / "ali1977-appendixA"
    folder.mkdir()
    pd.DataFrame({"case": ["I", "I"], "mechanism": ["source", "source"], "rpm": [300.0, 300.0],
                  "engine": ["legacy", "legacy"], "quantity": ["dx", "rot"], "input_deg": [0.0, 0.0],
                  "value": [0.1, 0.01]}).to_csv(folder / "curves.csv", index=False)
    curves = load("ali1977-appendixA", tmp_path)["curves"]
    assert list(curves["unit"]) == ["in", "rad"]
    assert curves.attrs["units"]["rpm"] == "rpm"
    assert curves.attrs["units"]["input_deg"] == "deg"
    assert "value" not in curves.attrs["units"]


@pytest.mark.parametrize("name", SMALL)
def test_published_values_read_back_as_printed(out, name):
    published = load(name, out)["published"]
    expected = PublishedTable.load(TABLES[name].table).values
    got = published.apply(lambda col: pd.to_numeric(col, errors="coerce"))
    pd.testing.assert_frame_equal(got, expected, check_dtype=False)


def test_a_scene_not_yet_written_is_run(tmp_path, monkeypatch):
    from linkrepro.harness import results
    monkeypatch.setattr(results.tempfile, "mkdtemp", lambda prefix: str(tmp_path))
    frames = load("rahman1996-table5_1", tmp_path / "nothing here")
    assert frames["published"].attrs["path"] == tmp_path / "rahman1996-table5_1" / "published.csv"
    assert set(frames["legacy"].columns) == set(TABLES["rahman1996-table5_1"].columns)


def test_an_unknown_scene_or_column_is_a_key_error_naming_what_is_known(out):
    with pytest.raises(KeyError, match="ali1977-table1"):
        load("no-such-scene", out)
    with pytest.raises(KeyError, match="src_dx"):
        describe("ali1977-table1", "no_such_column")
    with pytest.raises(KeyError, match="rahman1996-figures"):
        describe("no-such-scene", "crank_deg")


def test_importing_the_harness_stays_light():
    code = ("import sys, linkrepro.harness as h; "
            "assert 'linkrepro.harness.scenes' not in sys.modules and 'pandas' not in sys.modules; "
            "assert callable(h.load) and 'linkrepro.harness.scenes' not in sys.modules")
    subprocess.run([sys.executable, "-c", code], check=True, env=os.environ.copy())


def test_every_scene_s_run_of_record_reads_with_units(tmp_path):
    """``load`` reads every CSV of every scene's run of record (reference/: a full run, the long
    scenes included) with a unit for every column: no scene writes a column it does not describe."""
    import lzma

    from linkrepro.harness.verify import REFERENCE_DIR, SUFFIX
    stored = sorted(REFERENCE_DIR.glob(f"*/*{SUFFIX}"))
    assert {p.parent.name for p in stored} == set(SCENES)
    for path in stored:
        target = tmp_path / path.parent.name / path.name.removesuffix(".xz")      # <scene>/<file>.csv
        target.parent.mkdir(exist_ok=True)
        target.write_bytes(lzma.decompress(path.read_bytes()))
    for name in SCENES:
        for stem, frame in load(name, tmp_path).items():
            per_row = {c for c in frame.columns if c != "unit" and describe(name, c).per_row}
            assert set(frame.attrs["units"]) == set(frame.columns) - per_row - {"unit"}, (name, stem)
