"""harness/readings.py with Rahman (1996)'s driver (harness/scenes/rahman1996/readings.py): the OCR
readings of D116 and D117 ([[deviation.reading]] items of rahman1996_cssp_main.f) put back in
legacy/src, built and run by the arithmetic study's driver, counted on Tables 5.2-5.7 (crank
0-350, within 1e-6 relative)."""
import shutil
import tomllib

import numpy as np
import pytest

from linkrepro.harness.scenes.rahman1996 import arithmetic as A
from linkrepro.harness.scenes.rahman1996 import arithmetic_build as B
from linkrepro.harness.scenes.rahman1996 import arithmetic_variants as V
from linkrepro.harness import readings as R
from linkrepro.harness.scenes.rahman1996 import readings as CR
from linkrepro.harness.register import REGISTER_PATH

needs_gfortran = pytest.mark.skipif(shutil.which("gfortran") is None, reason="needs gfortran")
ALL = ("5.2", "5.3", "5.4", "5.5", "5.6", "5.7")


def _entry(entry_id: str) -> dict:
    with open(REGISTER_PATH, "rb") as fh:
        return next(e for e in tomllib.load(fh)["deviation"] if e["id"] == entry_id)


def test_1996_tables_are_the_series_of_arithmetic():
    assert CR.CSSP_TABLES == tuple(f"rahman1996_table{t}" for t in A.SERIES)
    assert all(R.has_readings(t, CR) for t in CR.CSSP_TABLES)
    assert not R.has_readings("rahman1996_table5_1", CR)


def test_readings_are_whole_lines_of_legacy_src(root):
    """Each chosen text is a whole line of legacy/src (as often as its occurrence asks), and its
    scan text fits fixed form (gfortran drops what passes column 72)."""
    for entry_id in ("D116", "D117"):
        for item in _entry(entry_id)["reading"]:
            assert item["file"] in CR.CSSP_FILES
            lines = (root / "legacy" / "src" / item["file"]).read_text().split("\n")
            assert lines.count(item["chosen"]) >= item.get("occurrence", 1), item["chosen"]
            assert item["scan"] != item["chosen"] and len(item["scan"]) <= 72, item["scan"]


def test_occurrence_picks_the_statement_named():
    """f2y(7)'s continuation line is also f2y(5)'s (both print ty(5)): occurrence 2 is f2y(7)'s."""
    item = next(i for i in _entry("D117")["reading"] if "ty(5)*sin(ETA2)*sin(THT2)" in i["chosen"])
    text = (R.SRC_DIR / item["file"]).read_text()
    put = R.put_back(text, item["file"], [item]).split("\n")
    changed = [k for k, (a, b) in enumerate(zip(text.split("\n"), put)) if a != b]
    assert len(changed) == 1 and put[changed[0] - 1].strip().startswith("f2y(7)=")


def test_d116_scan_text_is_plus_for_star():
    """D116: each scan line is its chosen line with the '*' the OCR read as '+'."""
    for item in _entry("D116")["reading"]:
        assert item["scan"] == item["chosen"].replace("*", "+")
    assert [g for g, _ in R.groups(_entry("D116"))] == ["loop 50", "f1y", "f2z, first branch"]


def test_d117_scan_text_moves_one_parenthesis():
    """D117: each line differs from its chosen line by one ')' (f2z(5): the scan's '\\' for ')/')."""
    for item in _entry("D117")["reading"]:
        chosen, scan = item["chosen"], item["scan"]
        if item["group"] == "f2z(5)":
            assert scan == chosen.replace(")/cos", "\\cos")
        else:
            assert abs(chosen.count(")") - scan.count(")")) == 1
            assert chosen.replace(")", "") == scan.replace(")", "")
    assert [g for g, _ in R.groups(_entry("D117"))] == ["f2x(5..8)", "f2y(7), f2y(8)", "rsq", "msq", "f2z(5)"]


def test_a_chosen_line_not_in_legacy_src_is_an_error():
    with pytest.raises(ValueError, match="occurs fewer than"):
        CR.cssp_counts((("D999", "", (("rahman1996_cssp_main.f", "      NO SUCH LINE", "      X=1", 1),)),))


@pytest.fixture(scope="module")
def legacy_counts():
    """The legacy engine's own tables against the published ones: (before, after) cells of crank
    0-350 within 1e-6 relative, per table; the chosen readings are legacy/src as it is, so their
    build must count the same (computed here by another path: the f2py build, not the driver)."""
    if shutil.which("gfortran") is None:
        pytest.skip("needs gfortran")
    from linkrepro.harness.published_tables import PublishedTable
    from linkrepro.harness.scenes.rahman1996.tables import legacy_tables
    tables, counts = legacy_tables(), {}
    for table in ALL:
        key = table.replace(".", "_")
        pub, got = PublishedTable.load(f"rahman1996_table{key}").values, tables[key]
        rows = pub["crank_deg"] <= 350
        counts[table] = tuple(int((np.abs(got.loc[rows, c] - pub.loc[rows, c]) <= 1e-6 * np.abs(pub.loc[rows, c])).sum())
                              for c in ("before", "after"))
    return counts


@pytest.fixture(scope="module")
def measured():
    if shutil.which("gfortran") is None:
        pytest.skip("needs gfortran")
    frames = {t: R.measure(f"rahman1996_table{t.replace('.', '_')}", CR) for t in ALL}
    for frame in frames.values():
        assert not frame.empty
    return frames


def _row(frames, table, entry_id, group):
    frame = frames[table]
    return frame[(frame["id"] == entry_id) & (frame["reading"] == group)].iloc[0]


def _counts(row, which):
    return tuple(int(str(row[f"{which}_{c}"]).split("/")[0]) for c in ("before", "after"))


@needs_gfortran
def test_chosen_readings_count_what_the_legacy_engine_counts(measured, legacy_counts):
    """The chosen build (legacy/src as it is, shared objects linked) reproduces the published
    cells the legacy engine's own tables reproduce."""
    for table, frame in measured.items():
        for row in frame.itertuples():
            assert (row.chosen_before, row.chosen_after) == tuple(f"{n}/36" for n in legacy_counts[table]), table


def _fewer(scan, chosen):
    """The scan's text reproduces fewer cells than the chosen reading, in one column at least,
    and more in none."""
    return all(s <= c for s, c in zip(scan, chosen)) and scan != chosen


@needs_gfortran
def test_d116_scan_text_loses_the_tables_it_claims(measured, legacy_counts):
    """D116 claims: with '+' no cell of these tables reproduces (f1y: few of 5.7); elsewhere the
    counts do not move."""
    loses = {"loop 50": ("5.2", "5.5", "5.6", "5.7"), "f1y": ("5.2", "5.5", "5.6"), "f2z, first branch": ("5.2", "5.6")}
    for group, tables in loses.items():
        for table in ALL:
            scan = _counts(_row(measured, table, "D116", group), "scan")
            if table in tables:
                assert scan == (0, 0), (group, table)
            elif group == "f1y" and table == "5.7":
                assert _fewer(scan, legacy_counts[table])
            else:
                assert scan == legacy_counts[table], (group, table)      # 5.3, 5.4 (and f2z: 5.5, 5.7)


@needs_gfortran
def test_d117_other_grouping_loses_the_tables_it_claims(measured, legacy_counts):
    scan = {t: _counts(_row(measured, t, "D117", "f2x(5..8)"), "scan") for t in ALL}
    assert scan["5.2"] == scan["5.6"] == (0, 0)
    assert _fewer(scan["5.5"], legacy_counts["5.5"]) and _fewer(scan["5.7"], legacy_counts["5.7"])
    scan = {t: _counts(_row(measured, t, "D117", "f2y(7), f2y(8)"), "scan") for t in ALL}
    assert scan["5.2"] == scan["5.6"] == scan["5.7"] == (0, 0) and scan["5.4"][1] == 0
    assert _fewer(scan["5.5"], legacy_counts["5.5"])
    for group in ("rsq", "msq"):                        # D117: Table 5.2 off by factors of millions
        row = _row(measured, "5.2", "D117", group)
        assert _counts(row, "scan") == (0, 0)
        assert row.scan_max_rel_change > 1e6
        for table in ALL[1:]:                           # the QP's answer does not move
            assert _row(measured, table, "D117", group).scan_max_rel_change == 0.0
    row = _row(measured, "5.2", "D117", "f2z(5)")
    assert row.scan_before == row.scan_after == "does not build" and "parenthesis" in row.why


@needs_gfortran
def test_report_section(measured):
    frame = measured["5.2"]
    text = R.as_markdown(frame, CR)
    assert text.startswith("## Reading alternatives (measured: legacy/src rebuilt")
    for entry_id, group in (("D116", "loop 50"), ("D117", "f2z(5)")):
        row = _row(measured, "5.2", entry_id, group)
        assert f"| {entry_id} | {group} | " in text
        assert f"| {row.chosen_before} | {row.chosen_after} | {row.scan_before} | {row.scan_after} |" in text
    assert "readings.measure('rahman1996_table5_2')" in text


@needs_gfortran
def test_shared_objects_build_the_reference_bit_for_bit():
    from linkrepro.harness.scenes.rahman1996.tables import legacy_tables
    m = B.measure([V.get("reference")], shared=("driver.f", "imsl_qprog.f", "rahman1996_subroutines.f"))
    for table, frame in legacy_tables().items():
        for col in ("before", "after"):
            assert np.array_equal(m.values["reference"][table][col].to_numpy(), frame[col].to_numpy()), (table, col)
