"""The arithmetic study (harness/scenes/rahman1996/arithmetic*.py): the legacy FORTRAN rebuilt under
other arithmetics (registers D056, D180), and its committed record of which arithmetics reach each
cell (D181)."""
import os
import re
import shutil
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from linkrepro.harness.scenes.rahman1996 import arithmetic as A
from linkrepro.harness.scenes.rahman1996 import arithmetic_build as B
from linkrepro.harness.scenes.rahman1996 import arithmetic_variants as V
from linkrepro.harness.readings import CompilerError

needs_gfortran = pytest.mark.skipif(shutil.which("gfortran") is None, reason="needs gfortran")

#: the reference flags spelled differently: reordered, and x86-64's defaults written out
RESPELLED = V.Variant("respelled", "control: the reference, spelled differently", True,
                      flags_base=("-O1", "-fallow-argument-mismatch", "-fno-fast-math", "-ffp-contract=off",
                                  "-fno-automatic", "-std=legacy", "-fno-unsafe-math-optimizations"))
BROKEN = V.Variant("broken", "control: a flag gfortran does not know", True, ("-fno-such-arithmetic",))


@pytest.fixture(scope="module")
def measured():
    if shutil.which("gfortran") is None:
        pytest.skip("needs gfortran")
    m = B.measure([V.get("reference"), RESPELLED, V.get(A.STANDARD), V.get("x87"), BROKEN])
    cells = A.cell_frame(m)
    return m, cells, A.count_frame(m, cells)


def test_reference_flags_are_the_legacy_builds(root):
    """The reference variant is built as meson.build builds the legacy engine, for each compiler family."""
    from linkrepro.harness import readings
    from tests.harness.test_manifest import meson_legacy_args
    declared = meson_legacy_args()
    assert {k: tuple(v) for k, v in declared.items()} == readings.LEGACY_FLAGS
    assert V.REFERENCE_FLAGS == readings.LEGACY_FLAGS[readings.family(readings.COMPILER)]


@needs_gfortran
def test_reference_is_the_legacy_engine_bit_for_bit(measured):
    from linkrepro.harness.scenes.rahman1996.tables import legacy_tables
    m, _, _ = measured
    for table, frame in legacy_tables().items():
        for col in ("before", "after"):
            assert np.array_equal(m.values["reference"][table][col].to_numpy(), frame[col].to_numpy()), (table, col)


@needs_gfortran
def test_reference_counts_are_the_harness_diff(measured, register):
    """Cells at the printed digit under the reference = the harness's `match` cells of legacy."""
    from linkrepro.harness.diff import diff_scene
    from linkrepro.harness.published_tables import PublishedTable
    from linkrepro.harness.scenes.rahman1996.tables import TABLES as RAHMAN1996_SCENES
    _, _, counts = measured
    ref = counts[counts["variant"] == "reference"].set_index("table")
    total = 0
    for scene in RAHMAN1996_SCENES:
        diff = diff_scene(scene, PublishedTable.load(scene.table), {"legacy": scene.run("legacy")}, register)
        table = scene.table.removeprefix("rahman1996_table").replace("_", ".")
        assert ref.at[table, "at_printed_digit"] == int((diff["status"] == "match").sum()), table
        assert ref.at[table, "cells"] == len(diff)
        total += len(diff)
    assert ref.at["all", "cells"] == total == 456


@needs_gfortran
def test_a_variant_that_changes_nothing_gives_the_identical_matrix(measured):
    m, cells, counts = measured
    assert np.array_equal(cells["value:respelled"].to_numpy(), cells["value:reference"].to_numpy())
    a = counts[counts["variant"] == "reference"].drop(columns="variant").reset_index(drop=True)
    b = counts[counts["variant"] == "respelled"].drop(columns="variant").reset_index(drop=True)
    pd.testing.assert_frame_equal(a, b)
    assert (b["cells_changed"] == 0).all()


@needs_gfortran
def test_the_variants_do_change_the_arithmetic(measured):
    """x87 moves cells without changing the printed-digit counts; the standard's reading of the
    radii (REAL*4) loses the 'before' columns of Tables 5.4-5.7 that the reference (D180) reaches."""
    _, cells, counts = measured
    c = counts.set_index(["variant", "table"])
    assert c.at[("x87", "all"), "cells_changed"] > 100
    assert c.at[("x87", "all"), "max_rel_change"] < 1e-7
    for table in ("5.4", "5.5", "5.6", "5.7"):
        assert c.at[(A.STANDARD, table), "gain"] < -20, table
    assert c.at[(A.STANDARD, "5.3"), "digits_changed"] == 0
    assert set(cells["sensitivity"]) <= {"always", "never", "compiler-sensitive"}
    assert (cells.loc[cells["distinct_values"] == 1, "same_printed_digits"]).all()


@needs_gfortran
def test_a_variant_that_cannot_build_is_reported_not_fatal(measured):
    m, cells, _ = measured
    assert "broken" in m.failures and "does not build" in m.failures["broken"]
    assert "value:broken" not in cells.columns


def test_a_missing_compiler_is_a_typed_error(monkeypatch, tmp_path):
    monkeypatch.setattr(B, "COMPILER", "gfortran-that-is-not-there")
    with pytest.raises(CompilerError, match="not on PATH"):
        B.measure()
    from linkrepro.harness.cli import main
    assert main(["arithmetic", "--out", str(tmp_path / "a")]) == 1
    assert not (tmp_path / "a" / "arithmetic.csv").exists()


def test_a_reference_that_fails_is_a_typed_error(monkeypatch):
    if shutil.which("gfortran") is None:
        pytest.skip("needs gfortran")
    with pytest.raises(B.ReferenceFailed, match="broken"):
        B.measure([BROKEN])


def _sources():
    return {name.split("/")[-1]: (B.LEGACY_DIR / name).read_text() for name in B.SRC}


def test_long_constants_touch_only_the_eight_digit_literals():
    before, after = V.single_constants(_sources()), V.long_constants_double(_sources())
    changed = [(a, b) for a, b in zip(before[V.MAIN].split("\n"), after[V.MAIN].split("\n")) if a != b]
    assert {re.search(r"=(\S+)", b).group(1) for _, b in changed} == {"1.1636867D0", "2.3139072D0", "4.6210569D0"}
    assert after["rahman1996_subroutines.f"] == before["rahman1996_subroutines.f"]


def test_the_standards_reading_is_the_printed_radii(root):
    """single_constants undoes D180 alone: the lines it changes are the 15 tagged D180, each
    back to the printed line's code."""
    src, printed = _sources()[V.MAIN].split("\n"), (root / "legacy" / "printed" / V.MAIN).read_text().split("\n")
    undone = V.single_constants(_sources())[V.MAIN].split("\n")
    changed = [(a, b) for a, b in zip(src, undone) if a != b]
    assert len(changed) == 15 and all(a.rstrip().endswith("! D180") for a, _ in changed)
    assert all(b[:72].rstrip() in printed for _, b in changed)


def test_promotion_reads_fortran_not_text():
    text = ("      X=F(K1X)+0.1*Y\n"
            "    1 FORMAT(3F20.5)\n"
            "      IF (A.GT.0.3 .AND. I.EQ.1) Z=1.5E-3\n"
            "C     K=0.7 in a comment\n"
            "      WRITE(6,*) 'text 0.5'\n")
    out = V._promote(text, lambda m, e, s: False).split("\n")
    assert out[0] == "      X=F(K1X)+0.1D0*Y"
    assert out[1] == "    1 FORMAT(3F20.5)"
    assert out[2] == "      IF (A.GT.0.3D0 .AND. I.EQ.1) Z=1.5D-3"
    assert out[3:5] == ["C     K=0.7 in a comment", "      WRITE(6,*) 'text 0.5'"]


def test_a_transform_whose_text_is_gone_says_so():
    files = _sources()
    files[V.MAIN] = files[V.MAIN].replace("      M1=1.9/G\n", "      M1=1.90/G\n")
    with pytest.raises(ValueError, match="M1=1.9/G"):
        V.selected_real8(files)


def test_the_criterion_asks_every_table_where_the_variant_acts():
    def counts(gains, acts=(1,) * 7, documented=True):
        rows = [{"variant": "v", "table": t, "gain": g, "digits_changed": d, "documented": documented}
                for t, g, d in zip(["5.1", "5.2", "5.3", "5.4", "5.5", "5.6", "5.7"], gains, acts)]
        return pd.DataFrame(rows)
    assert A.meets_criterion(counts([1, 1, 1, 1, 1, 1, 1])) == {"v": True}
    assert A.meets_criterion(counts([1, 4, 0, 41, 33, 35, 63], (1, 5, 0, 41, 33, 35, 63))) == {"v": True}  # 5.3 cannot move
    assert A.meets_criterion(counts([1, 4, 0, 41, 33, 35, 63])) == {"v": False}     # 5.3 moves, not raised
    assert A.meets_criterion(counts([-1, 1, 1, 1, 1, 1, 1])) == {"v": False}        # Table 5.1 lowered
    assert A.meets_criterion(counts([0] * 7, (0,) * 7)) == {"v": False}              # acts nowhere
    assert A.meets_criterion(counts([1] * 7, documented=False)) == {"v": False}


def test_every_variant_is_named_once_and_says_what_it_stands_for():
    names = [v.name for v in V.VARIANTS]
    assert names[0] == "reference" and len(names) == len(set(names))
    assert all(v.machine for v in V.VARIANTS)
    assert replace(V.get("O2"), extra=()).flags == V.REFERENCE_FLAGS


def test_the_record_reaches_what_the_legacy_engine_matches(register):
    """The committed record's reference column (D181: the table scenes read it) is the legacy
    engine's cells at the printed digit, by the harness's own diff."""
    from linkrepro.harness.diff import diff_scene
    from linkrepro.harness.published_tables import PublishedTable
    from linkrepro.harness.scenes.rahman1996.tables import TABLES as RAHMAN1996_SCENES, _study_cell
    record = pd.read_csv(A.RECORD, dtype=str, keep_default_na=False)
    assert len(record) == 456 and (record["n_variants"] == str(len(V.VARIANTS))).all()
    ours = {(t, r, c) for t, r, c, by in zip(record["table"], record["row"], record["column"], record["reached_by"])
            if "reference" in by.split()}
    matched = set()
    for scene in RAHMAN1996_SCENES:
        diff = diff_scene(scene, PublishedTable.load(scene.table), {"legacy": scene.run("legacy")}, register)
        table = scene.table.removeprefix("rahman1996_table")
        matched |= {(*_study_cell(table, key), col) for key, col in
                    zip(diff.loc[diff["status"] == "match", scene.key_name], diff.loc[diff["status"] == "match", "column"])}
    assert matched and ours == matched


@pytest.mark.skipif(os.environ.get("LINKREPRO_SLOW_CHECKS", "") in ("", "0"),
                    reason="a fresh study (17 builds): LINKREPRO_SLOW_CHECKS=1 runs it")
def test_the_record_is_a_fresh_measurement():
    if shutil.which("gfortran") is None:
        pytest.skip("needs gfortran")
    fresh = A.record_frame(A.cell_frame(B.measure()))
    record = pd.read_csv(A.RECORD, dtype=str, keep_default_na=False)
    pd.testing.assert_frame_equal(fresh.astype(str).reset_index(drop=True), record)


def test_a_cell_a_consistent_arithmetic_reaches_is_explained_by_that_run(monkeypatch, register):
    """D181 on a made-up record: where the adopted arithmetic misses a cell and an arithmetic that
    lowers no table reaches it, the cell is explained (by that run), not within tolerance; one
    reached only by an arithmetic that lowers tables stays within D056's tolerance, and its trail
    says why the run does not count."""
    from linkrepro.harness.diff import classify_cells, diff_scene
    from linkrepro.harness.published_tables import PublishedTable
    from linkrepro.harness.scenes import get
    record = dict(A._record())
    misses = [cell for cell, by in record.items() if cell[0] == "5.4" and "reference" not in by
              and cell[2] == "after" and cell[1] not in ("90", "170", "360")]     # not D058's, not row 360's
    consistent, coincidence = misses[0], misses[1]
    for cell, by in record.items():          # x87 reaches what the reference reaches, and one cell more
        record[cell] = tuple(n for n in by if n != "x87") + (("x87",) if "reference" in by or cell == consistent else ())
    record[coincidence] = ("real8",)
    monkeypatch.setattr(A, "_record", lambda: record)
    A._lowered.cache_clear()
    try:
        assert "x87" in A.consistent() and "real8" not in A.consistent()
        scene = get("rahman1996-table5_4")
        diff = diff_scene(scene, PublishedTable.load(scene.table), {"legacy": scene.run("legacy")}, register)
        classes = classify_cells(diff, register).join(diff)
        at = lambda cell: classes[(classes["crank_deg"] == int(cell[1])) & (classes["column"] == cell[2])].iloc[0]
        assert (at(consistent)["count"], at(consistent)["kind"], at(consistent)["register_ids"]) == \
            ("explained", "portability", "D181")
        assert (at(coincidence)["count"], at(coincidence)["register_ids"]) == ("within-tolerance", "D056")
        assert "explained by that run (D181)" in A.trail_note(*consistent)[0]
        from linkrepro.harness.trail import as_text, cell_trail
        shown = " ".join(as_text(cell_trail(scene, consistent[1], consistent[2], diff, register)).split())
        assert " ".join(A.trail_note(*consistent)[0].split()) in shown and "legacy" in shown
        assert "Not an explanation: real8 (lowers Tables" in A.trail_note(*coincidence)[0]
    finally:
        A._lowered.cache_clear()
