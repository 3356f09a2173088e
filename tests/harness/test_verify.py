"""linkrepro verify (harness/verify.py): a run against a stored run of record, cell by cell."""
from __future__ import annotations

import contextlib
import io
import json
import lzma
import math
import re
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from linkrepro.harness import run_folder, verify as verify_mod
from linkrepro.harness.cli import main
from linkrepro.harness.run import reproduce
from linkrepro.harness.scene import Outcome

SCENES = ["rahman1996-table5_1", "ali1977-table1"]


@pytest.fixture(scope="module")
def recorded(tmp_path_factory) -> tuple[Path, Path]:
    """A run of two scenes, and a reference made of it by --refresh."""
    root = tmp_path_factory.mktemp("verify")
    reproduce(SCENES, root / "run", measure_readings=False)
    assert _cli("verify", "--out", str(root / "run"), "--reference", str(root / "ref"), "--refresh")[0] == 0
    return root / "run", root / "ref"


def _cli(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))
    return status, out.getvalue(), err.getvalue()


@pytest.fixture
def run(recorded, tmp_path) -> Path:
    """A copy of the recorded run to change."""
    return Path(shutil.copytree(recorded[0], tmp_path / "run"))


def _edit(path: Path, row: int, column: str, change) -> str:
    """Change one cell of a CSV's text (``change(text) -> text``), as a run that computed it so
    would have written it (its outcome records the file); returns the old text."""
    lines = path.read_text().splitlines()
    head = lines[0].split(",")
    cells = lines[row + 1].split(",")
    old = cells[head.index(column)]
    cells[head.index(column)] = change(old)
    lines[row + 1] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    _as_written(path.parent)
    return old


def _as_written(folder: Path) -> None:
    """Record a scene folder's files in its outcome, as a run that wrote them so does."""
    outcome = Outcome.load(folder.parent, folder.name)
    outcome.files = run_folder.file_hashes(folder)
    outcome.save(folder.parent)


def _manifest(folder: Path, **fields) -> None:
    """Change fields of the folder's manifest (the run's, copied into the reference)."""
    path = folder / "manifest.json"
    path.write_text(json.dumps({**json.loads(path.read_text()), **fields}))


def test_the_recorded_run_is_identical_to_its_reference(recorded):
    status, text, _ = _cli("verify", "--out", str(recorded[0]), "--reference", str(recorded[1]))
    assert status == 0 and text.rstrip().endswith("0 moved, 0 status changed: ok")
    assert re.search(r"\n\d+ CSVs compared, ", text)
    assert {p.name for p in recorded[1].iterdir()} == {*SCENES, "manifest.json"}     # the run's manifest copied
    stored = recorded[1] / "ali1977-table1" / "legacy.csv.xz"
    assert lzma.decompress(stored.read_bytes()) == (recorded[0] / "ali1977-table1" / "legacy.csv").read_bytes()


def test_a_number_one_ulp_off_moves_on_the_same_toolchain_and_not_across(recorded, run):
    ref = Path(shutil.copytree(recorded[1], run.parent / "ref"))
    old = _edit(run / "ali1977-table1" / "legacy.csv", 4, "src_dx", lambda t: repr(float(np.nextafter(float(t), np.inf))))
    assert len(old.lstrip("-").replace(".", "")) >= 15           # engines' outputs are written in full
    _manifest(ref, gfortran="GNU Fortran 12", numpy="2.0")
    _manifest(run, gfortran="GNU Fortran 12", numpy="2.0", started="later")       # the same toolchain
    status, text, _ = _cli("verify", "--out", str(run), "--reference", str(ref))
    assert status == 1 and "ali1977-table1/legacy.csv: 1 moved" in text and f"row 5, src_dx: reference {old!r}" in text
    _manifest(run, gfortran="GNU Fortran 13", numpy="2.0")                          # another one
    status, text, _ = _cli("verify", "--out", str(run), "--reference", str(ref))
    assert status == 0 and "manifest field gfortran: reference 'GNU Fortran 12', run 'GNU Fortran 13'" in text
    assert "1 within the policy" in text                                        # 1 ulp <= 4
    assert _cli("verify", "--out", str(run), "--reference", str(ref), "--units", "0.5")[0] == 1


def test_a_compiler_the_matrix_measured_is_held_to_what_it_moved(recorded, run):
    """The reference's toolchains/matrix.csv bounds a run whose set-up differs in its Fortran compiler
    alone, per engine, where it measured that compiler; another compiler, or another change too, 4 ulps."""
    ref = Path(shutil.copytree(recorded[1], run.parent / "ref"))
    _edit(run / "ali1977-table1" / "legacy.csv", 4, "src_dx", lambda t: repr(float(np.nextafter(float(t), np.inf))))
    (ref / "toolchains").mkdir()
    pd.DataFrame({"compiler": ["GNU Fortran 11", "GNU Fortran 11", "flang 22"], "engine": ["legacy", "printed", "legacy"],
                  "max_units": [0.0, 3.0, 2.0]}).to_csv(ref / verify_mod.MATRIX, index=False)
    _manifest(ref, build_gfortran="GNU Fortran 12", numpy="2.0")

    def verdict(**fields):
        _manifest(run, **{"numpy": "2.0", **fields})
        return _cli("verify", "--out", str(run), "--reference", str(ref))
    status, text, _ = verdict(build_gfortran="GNU Fortran 11")               # measured: no legacy cell moved
    assert status == 1 and "ali1977-table1/legacy.csv: 1 moved" in text and "legacy 0, printed 3" in text
    assert verdict(build_gfortran="flang 22")[0] == 0                          # measured: 2 ulps
    status, text, _ = verdict(build_gfortran="GNU Fortran 13")                 # not measured: 4 ulps
    assert status == 0 and "1 within the policy" in text
    assert verdict(build_gfortran="GNU Fortran 11", numpy="2.1")[0] == 0       # more than the compiler changed
    assert _cli("verify", "--out", str(run), "--reference", str(ref), "--units", "4")[0] == 0      # as asked
    assert (run.parent / "ref" / verify_mod.MATRIX).is_file()


def test_a_compiler_under_which_a_cell_turned_text_is_held_to_the_default(tmp_path):
    """A matrix row with no finite bound (a cell that turned NaN or text: inf units) bounds that
    engine by the unmeasured 4 ulps, not by infinity (which would let any cell through)."""
    (tmp_path / "toolchains").mkdir()
    pd.DataFrame({"compiler": ["flang 22", "flang 22"], "engine": ["legacy", "printed"],
                  "max_units": [math.inf, 1.0]}).to_csv(tmp_path / verify_mod.MATRIX, index=False)
    assert verify_mod.measured_bounds(tmp_path, "flang 22") == {"legacy": verify_mod.UNITS, "printed": 1.0}


def test_a_rounded_column_counts_units_of_its_last_written_digit():
    ref = pd.DataFrame({"x": ["1.23456789", "2.5", "-0.000123456789"]})
    run = pd.DataFrame({"x": ["1.23456791", "2.50000001", "-0.000123456786"]})
    result = verify_mod.compare_frames("s/summary.csv", ref, run, 2.0)
    assert (result.identical, result.within, result.moved) == (0, 2, 1)           # 2, 1 and 3 units
    assert result.examples[0][1:4] == ("x", "-0.000123456789", "-0.000123456786")


def test_a_status_that_changes_fails_under_any_policy(recorded, run):
    diff = run / "rahman1996-table5_1" / "diff.csv"
    _edit(diff, 0, "status", lambda t: "unexplained" if t != "unexplained" else "match")
    status, text, _ = _cli("verify", "--out", str(run), "--reference", str(recorded[1]), "--units", "1e9")
    assert status == 1 and "rahman1996-table5_1/diff.csv: 0 moved, 1 status changed" in text


def test_a_missing_or_new_csv_is_named(recorded, run):
    (run / "ali1977-table1" / "identities.csv").unlink()
    shutil.copyfile(run / "ali1977-table1" / "legacy.csv", run / "ali1977-table1" / "extra.csv")
    _as_written(run / "ali1977-table1")
    status, text, _ = _cli("verify", "--out", str(run), "--reference", str(recorded[1]))
    assert status == 1 and "identities.csv: missing in the run" in text and "extra.csv: not in the reference" in text


@pytest.mark.parametrize("case", ["no reference", "damaged", "no scenes", "scene not run", "manifest format",
                                  "no folder", "a file"])
def test_what_cannot_be_verified_is_a_usage_error(recorded, run, tmp_path, case):
    ref = Path(shutil.copytree(recorded[1], tmp_path / "ref"))
    args = ["verify", "--out", str(run), "--reference", str(ref)]
    if case == "no reference":
        args[-1] = str(tmp_path / "nowhere")
    elif case == "damaged":
        (ref / "ali1977-table1" / "legacy.csv.xz").write_bytes(b"not xz")
    elif case == "no scenes":
        args[2] = str(tmp_path)
    elif case == "scene not run":
        args.append("rahman1996-table5_7")
    elif case == "no folder":
        args[2] = str(tmp_path / "nosuchdir")
    elif case == "a file":
        args[2] = __file__
    else:
        _manifest(ref)
        (run / "manifest.json").write_text(json.dumps({"format": 99}))
    status, _, err = _cli(*args)
    assert status == 2 and err.startswith("linkrepro: ") and "Traceback" not in err
    assert {"no reference": "no reference", "damaged": "damaged", "no scenes": "no scene run",
            "scene not run": "no run of rahman1996-table5_7", "manifest format": "format 99",
            "no folder": "nosuchdir does not exist", "a file": "is a file, not a run's folder"}[case] in err


def test_the_reference_carried_by_the_package_covers_every_scene():
    """The run of record holds every scene `linkrepro reproduce` runs (`make test` then runs a
    full reproduce and verifies it against this reference)."""
    from linkrepro.harness.scenes import SCENES as ALL
    assert verify_mod.reference_scenes(verify_mod.REFERENCE_DIR) == sorted(ALL)


def test_the_size_the_docs_quote_is_the_references():
    """docs/developing.md quotes the reference's size: it is the size of reference/ (MB, 0.1)."""
    docs = Path(__file__).resolve().parents[2] / "docs" / "developing.md"
    if not docs.exists():
        pytest.skip("the docs are not at hand")
    quoted = float(re.search(r"xz-compressed \(([0-9.]+) MB\)", docs.read_text()).group(1))
    size = sum(p.stat().st_size for p in verify_mod.REFERENCE_DIR.rglob("*") if p.is_file())
    assert quoted == round(size / 1e6, 1)


def _without_record(folder: Path) -> None:
    """The scene's outcome as versions before this one wrote it: no record of its files."""
    record = json.loads((folder / "outcome.json").read_text())
    del record["files"]
    (folder / "outcome.json").write_text(json.dumps(record))


#: damage to a recorded run, and what verify's failing line says of it
DAMAGE = {
    "renamed": (lambda s: s.rename(s.with_name("renamed-scene")), "renamed-scene: not in the reference"),
    "empty": (lambda s: (s / "legacy.csv").write_bytes(b""), "changed since the run wrote it: legacy.csv"),
    "not utf-8": (lambda s: (s / "legacy.csv").write_bytes(b"\xff\xfe\x00x\n"), "changed since the run wrote it: legacy.csv"),
    "a folder": (lambda s: ((s / "legacy.csv").unlink(), (s / "legacy.csv").mkdir()), "missing or not a file: legacy.csv"),
    "cut short": (lambda s: (s / "diff.csv").write_bytes((s / "diff.csv").read_bytes()[:333]),
                  "changed since the run wrote it: diff.csv"),
    "no outcome": (lambda s: (s / "outcome.json").unlink(), "holds files but no outcome.json"),
    "another's outcome": (lambda s: shutil.copyfile(s.with_name("ali1977-table1") / "outcome.json", s / "outcome.json"),
                          "is the outcome of 'ali1977-table1'"),
    "a file added": (lambda s: (s / "notes.csv").write_text("a\n1\n"), "not written by its run: notes.csv"),
    # an outcome of an earlier version records no files: the CSV itself is found unreadable
    "empty, no record": (lambda s: (_without_record(s), (s / "legacy.csv").write_bytes(b"")),
                         "legacy.csv: cannot be read (EmptyDataError"),
    "not utf-8, no record": (lambda s: (_without_record(s), (s / "legacy.csv").write_bytes(b"a\n\xff\n")),
                             "legacy.csv: cannot be read (UnicodeDecodeError"),
    "a folder, no record": (lambda s: (_without_record(s), (s / "legacy.csv").unlink(), (s / "legacy.csv").mkdir()),
                            "legacy.csv: cannot be read (IsADirectoryError"),
    "cut short, no record": (lambda s: (_without_record(s), (s / "diff.csv").write_bytes((s / "diff.csv").read_bytes()[:333])),
                             "diff.csv: shape or columns differ"),
}


@pytest.mark.parametrize("case", DAMAGE)
def test_a_folder_that_cannot_be_trusted_fails_in_a_line(recorded, run, case):
    """A scene folder verify does not know, a CSV it cannot read, a scene's files without the
    outcome that says it finished, or not those its outcome records: status 1, the line says
    which, no traceback."""
    damage, said = DAMAGE[case]
    scene = run / "rahman1996-table5_1"
    damage(scene)
    status, text, err = _cli("verify", "--out", str(run), "--reference", str(recorded[1]))
    assert status == 1 and err == "" and text.rstrip().endswith(": FAILED"), (status, err)
    assert any(line.startswith(("rahman1996-table5_1", "renamed-scene")) and said in line
               for line in text.splitlines()), text


def test_a_folder_that_compares_nothing_fails(recorded, run):
    """Its only scene renamed: nothing is compared, and verify says so (it used to pass)."""
    shutil.rmtree(run / "ali1977-table1")
    (run / "rahman1996-table5_1").rename(run / "renamed-scene")
    status, text, _ = _cli("verify", "--out", str(run), "--reference", str(recorded[1]))
    assert status == 1 and f"{run}: nothing was compared" in text and "\n0 CSVs compared, 0 cells" in text


def test_a_damaged_manifest_is_a_usage_error_not_a_pass(recorded, run):
    (run / "manifest.json").write_text(json.dumps({"format": 1}))
    status, _, err = _cli("verify", "--out", str(run), "--reference", str(recorded[1]))
    assert status == 2 and "manifest.json is damaged: it has no field 'version'" in err and "Traceback" not in err


def test_a_damaged_folder_is_not_made_the_reference(recorded, run, tmp_path):
    (run / "ali1977-table1" / "legacy.csv").write_text("x\n")
    status, _, err = _cli("verify", "--out", str(run), "--reference", str(tmp_path / "ref"), "--refresh")
    assert status == 2 and "cannot be made the reference" in err and not (tmp_path / "ref").exists()


def test_a_run_of_fewer_scenes_does_not_replace_the_reference(recorded, run, tmp_path):
    """--refresh from a run that lacks one of the reference's scenes refuses and keeps the reference whole."""
    reference = Path(shutil.copytree(recorded[1], tmp_path / "ref"))
    before = sorted(p.relative_to(reference).as_posix() for p in reference.rglob("*"))
    shutil.rmtree(run / "ali1977-table1")
    status, _, err = _cli("verify", "--out", str(run), "--reference", str(reference), "--refresh")
    assert status == 2 and "it holds no run of ali1977-table1" in err and "Traceback" not in err
    assert sorted(p.relative_to(reference).as_posix() for p in reference.rglob("*")) == before
