"""The toolchain matrix (harness/toolchains.py): its cell classes against numbers moved by a known
number of ulps, and the committed matrix (reference/toolchains/matrix.csv, made by `make toolchains`)
covering every CSV of every scene of reference/ for every toolchain, with the port unmoved."""
from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from linkrepro.harness import readings, toolchains
from linkrepro.harness.verify import REFERENCE_DIR, SUFFIX, reference_scenes

COMMITTED = toolchains.COMMITTED / "matrix.csv"


def _text(values) -> list[str]:
    return [repr(float(v)) for v in values]


def test_cells_fall_in_the_bin_of_their_ulps():
    """A double moved by k ulps (np.nextafter, k times) is in the first bin >= k; a NaN, a status."""
    base = np.array([1.0, 3.0e-7, 123456.789, 2.5, 7.0, 1.0]) / 3.0     # written in full: 16-17 digits
    moved = base.copy()
    for i, k in enumerate([0, 1, 2, 3, 10, 5000]):
        for _ in range(k):
            moved[i] = np.nextafter(moved[i], np.inf)
    ref = pd.DataFrame({"value": _text(base), "status": ["match"] * 6, "seconds": ["1.0"] * 6})
    run = pd.DataFrame({"value": _text(moved), "status": ["match"] * 5 + ["unexplained"], "seconds": ["9.0"] * 6})
    row = toolchains.compare_file(ref, run)
    assert row["cells"] == 12                          # the measured times are not compared
    assert (row["identical"], row["within_1"], row["within_2"], row["within_4"], row["within_16"]) == (6, 1, 1, 1, 1)
    assert (row["within_1024"], row["beyond"], row["status_changed"], row["not_a_number"]) == (0, 1, 1, 0)
    assert row["max_units"] == pytest.approx(5000) and (row["max_row"], row["max_column"]) == (6, "value")
    run.loc[0, "value"] = "nan"
    assert toolchains.compare_file(ref, run)["not_a_number"] == 1
    assert toolchains.compare_file(ref, None)["not_a_number"] == 12        # a CSV the run lacks


def test_a_printed_column_counts_units_of_its_last_digit():
    ref = pd.DataFrame({"x": ["5.648", "9.004", "1.000"]})
    run = pd.DataFrame({"x": ["5.649", "9.004", "1.003"]})
    row = toolchains.compare_file(ref, run)
    assert (row["identical"], row["within_1"], row["within_4"]) == (1, 1, 1)


@pytest.fixture(scope="module")
def committed() -> pd.DataFrame:
    if not COMMITTED.is_file():
        pytest.fail(f"{COMMITTED} is missing: `make toolchains` writes it (python -m linkrepro.harness.toolchains --commit)")
    return pd.read_csv(COMMITTED, dtype=str, keep_default_na=False)


def test_the_committed_matrix_covers_every_csv_of_the_reference(committed):
    wanted = {(scene, p.name[:-len(SUFFIX)] + ".csv") for scene in reference_scenes(REFERENCE_DIR)
              for p in (REFERENCE_DIR / scene).glob(f"*{SUFFIX}")}
    assert set(committed["toolchain"]) == set(toolchains.TOOLCHAINS)
    for name, part in committed[committed["scene"] != "arithmetic"].groupby("toolchain"):
        assert set(zip(part["scene"], part["file"])) == wanted, name
    counts = committed[["identical", *[f"within_{k}" for k in toolchains.BINS], "beyond", "not_a_number",
                        "status_changed"]].astype(int)
    assert (counts.sum(axis=1) == committed["cells"].astype(int)).all()


def test_the_port_does_not_move_under_any_toolchain(committed):
    """The numba kernels are the same in every build: the port's cells are identical as written."""
    built = committed[committed["built"].str.startswith("built with")]
    port = built[built["engine"].str.startswith("port")]
    assert len(port) and (port["identical"] == port["cells"]).all()


def test_a_compiler_that_is_not_there_is_said_and_not_run(tmp_path, monkeypatch):
    monkeypatch.setitem(toolchains.TOOLCHAINS, "absent", "no-such-fortran-35")
    said = toolchains.build_and_run("absent", tmp_path, REFERENCE_DIR.parent)
    assert said == "not built: no-such-fortran-35 is not on PATH (apt-get install no-such-fortran-35)"
    matrix = toolchains.measure(tmp_path, REFERENCE_DIR, ["absent"])
    assert (matrix["built"] == said).all() and (matrix["not_a_number"] == matrix["cells"]).all()
    assert f"- absent: {said}" in toolchains.as_markdown(matrix)


def test_the_run_time_compiler_and_its_flags_follow_linkrepro_fc():
    code = "from linkrepro.harness import readings as r; print(r.COMPILER, ' '.join(r.FLAGS))"
    for fc, family in (("flang-22", "flang"), ("gfortran-11", "gfortran"), ("", "gfortran")):
        out = subprocess.run([sys.executable, "-c", code], env={**os.environ, "LINKREPRO_FC": fc},
                             capture_output=True, text=True, check=True).stdout.split()
        flags = [f for f in readings.LEGACY_FLAGS[family] if f != "-fallow-argument-mismatch"]
        assert out == [fc or "gfortran", *flags]


def test_the_committed_markdown_is_the_committed_matrix():
    """matrix.md is as_markdown of matrix.csv (both written by one measurement)."""
    matrix = pd.read_csv(COMMITTED, dtype={"max_row": str, "max_reference": str, "max_run": str})
    assert (toolchains.COMMITTED / "matrix.md").read_text() == toolchains.as_markdown(matrix)


def test_a_report_folder_shows_its_matrix(tmp_path):
    """A report folder's toolchains/matrix.md is a section of its report (absent: the command that writes it)."""
    from linkrepro.harness import report_folder
    section = lambda: {s.name: s for s in report_folder.collect(tmp_path).sections}["toolchains"]   # noqa: E731
    assert not section().present and "linkrepro.harness.toolchains" in section().command
    (tmp_path / "toolchains").mkdir()
    (tmp_path / "toolchains" / "matrix.md").write_text((toolchains.COMMITTED / "matrix.md").read_text())
    assert section().present
    report_folder.write(tmp_path)
    page = (tmp_path / "report.html").read_text()
    assert "The run of record across Fortran compilers" in page and "<td>flang-22</td>" in page
