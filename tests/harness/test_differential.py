"""``linkrepro differential``: legacy against the port on samples of each thesis's geometries.

- each thesis's sampler and engine pair, on a small sample: status 0 and a CSV that says they
  agree everywhere (and, in the CSV, the inputs and outcomes it claims);
- an engine made to differ (one ulp of one output, or an error where legacy returns) is named in
  the CSV and the markdown, and the status is 1; a difference within a stated tolerance is not;
- bad requests are one line and status 2, never a traceback;
- the report folder shows the section where the command wrote into its ``differential/``.
"""
from __future__ import annotations

import dataclasses
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from linkrepro.harness import cli, differential, scenes
from linkrepro.harness.report_folder import collect
from tests.patience import CHILD_SECONDS

#: samples per program in the runs here (make test stays quick)
SMALL = {"ali1977": 4, "rahman1996": 8, "rahman1991": 8}


def _run(capsys, *args) -> tuple[int, str, str]:
    try:
        status = cli.main(list(args))
    except SystemExit as exc:
        status = exc.code
    out, err = capsys.readouterr()
    return status, out, err


@pytest.mark.parametrize("thesis", sorted(SMALL))
def test_a_small_sample_of_each_thesis_agrees(thesis, tmp_path, capsys):
    out = tmp_path / "differential"
    status, text, err = _run(capsys, "differential", thesis, "--samples", str(SMALL[thesis]), "--out", str(out))
    assert status == 0, err
    table = pd.read_csv(out / "differential.csv")
    programs = scenes.differentials()[thesis].programs
    assert len(table) == SMALL[thesis] * len(programs)
    assert set(table.program) == {p.name for p in programs} and set(table.thesis) == {thesis}
    assert table.agree.all(), table[~table.agree].to_string()
    assert (table.same_outcome | table.note.notna()).all()            # an accepted difference says why
    for p in scenes.differentials()[thesis].parameters:
        assert table[p.name].notna().all()
    assert (table.legacy.str.match(r"ok|\w+Error")).all()
    md = (out / "differential.md").read_text()
    assert f"agree on all {len(table)} samples" in md and "Criterion:" in md and "Domain `sample`" in md
    assert md in text                                                   # printed too


def test_the_sample_is_the_seeds_and_the_bounds_hold(tmp_path, capsys):
    args = ["differential", "rahman1996", "--samples", "5", "--seed", "3", "--bounds", "a4=0.5:1", "rpm=50"]
    for name in ("a", "b"):
        assert _run(capsys, *args, "--out", str(tmp_path / name))[0] == 0
    a, b = (pd.read_csv(tmp_path / name / "differential.csv") for name in ("a", "b"))
    pd.testing.assert_frame_equal(a, b)
    assert a.a4.between(0.5, 1.0).all() and (a.rpm == 50.0).all() and a.a1.between(0.5, 4.0).all()
    assert "User bounds" in (tmp_path / "a" / "differential.md").read_text()


def _with_port(monkeypatch, thesis: str, program: str, port):
    """The registry's theses, with one program's port engine replaced by ``port(original, geometry)``."""
    theses = scenes.differentials()
    t = theses[thesis]
    programs = tuple(dataclasses.replace(p, port=lambda g, p=p: port(p.port, g)) if p.name == program else p
                     for p in t.programs)
    monkeypatch.setattr(scenes, "differentials", lambda: dict(theses, **{thesis: dataclasses.replace(t, programs=programs)}))


def _one_ulp_up(output: str, index):
    def port(original, g):
        result = original(g)
        value = result[output].copy()
        value[index] = np.nextafter(value[index], np.inf)
        return dict(result, **{output: value})
    return port


def test_one_ulp_of_one_output_is_a_difference(monkeypatch, tmp_path, capsys):
    _with_port(monkeypatch, "ali1977", "case1_source", _one_ulp_up("dx", 3))
    out = tmp_path / "differential"
    status, _, err = _run(capsys, "differential", "ali1977", "--program", "case1_source", "--geometry", "l1=10",
                          "--out", str(out))
    assert status == 1 and "differ on 1 of 1 samples" in err and "Traceback" not in err
    row = pd.read_csv(out / "differential.csv").iloc[0]
    assert row.same_outcome and not row.agree and row.in_output == "dx[3]" and "dx differs" in row.note
    assert 0 < row.largest_abs_diff < 1e-15 and row.l1 == 10.0 and row.l3 == 30.0     # the example's other lengths
    md = (out / "differential.md").read_text()
    assert "differ on 1 of 1 samples" in md and "--geometry l1=10.0" in md


def test_a_difference_within_the_stated_tolerance_is_not(monkeypatch, tmp_path, capsys):
    """Rahman (1996)'s tables are compared to 1e-12 of each column's largest value (its tests'
    criterion); its positions bit for bit."""
    _with_port(monkeypatch, "rahman1996", "cssp", _one_ulp_up("table", (5, 3)))
    assert _run(capsys, "differential", "rahman1996", "--geometry", "a1=2", "--out", str(tmp_path / "t"))[0] == 0
    _with_port(monkeypatch, "rahman1996", "cssp", _one_ulp_up("positions", (0, 5, 1)))
    assert _run(capsys, "differential", "rahman1996", "--geometry", "a1=2", "--out", str(tmp_path / "p"))[0] == 1
    assert pd.read_csv(tmp_path / "p" / "differential.csv").in_output[0] == "positions[0,5,1]"


def test_another_outcome_is_a_difference(monkeypatch, tmp_path, capsys):
    from linkrepro.errors import AssemblyError

    def port(original, g):
        raise AssemblyError("made to fail", 0.0)
    _with_port(monkeypatch, "rahman1991", "positions", port)
    geometries = tmp_path / "g.toml"
    geometries.write_text("[[geometry]]\na4 = 30.0\nalpha4_deg = 270.0\ns1 = 3.5\n\n[[geometry]]\na4 = 10.0\n")
    out = tmp_path / "differential"
    assert _run(capsys, "differential", "rahman1991", "--geometry-file", str(geometries), "--out", str(out))[0] == 1
    table = pd.read_csv(out / "differential.csv")
    assert len(table) == 2 and list(table.port) == ["AssemblyError at 0 deg"] * 2
    assert table.legacy[0] == "ok" and not table.same_outcome[0] and not table.agree[0]


@pytest.mark.parametrize("args, words", [
    (["nobody1999"], "unknown thesis 'nobody1999'"),
    (["ali1977", "--samples", "0"], "--samples"),
    (["ali1977", "--samples", "x"], "--samples"),
    (["ali1977", "--seed", "-1"], "--seed"),
    (["ali1977", "--bounds", "l1=5:1"], "lower bound"),
    (["ali1977", "--bounds", "l1=-1:5"], "log-uniformly"),
    (["ali1977", "--bounds", "l9=1:5"], "unknown parameter 'l9'"),
    (["ali1977", "--bounds", "l1=a:b"], "not a number"),
    (["ali1977", "--bounds", "l1"], "NAME=LO:HI"),
    (["ali1977", "--bounds", "rpm=1:1e12"], "outside"),
    (["ali1977", "--program", "case9"], "unknown program"),
    (["ali1977", "--domain", "nowhere"], "unknown domain"),
    (["ali1977", "--geometry", "l1=x"], "not a number"),
    (["ali1977", "--geometry", "l1=10", "--samples", "3"], "--samples"),
    (["ali1977", "rahman1996", "--geometry", "a1=1"], "one thesis"),
    (["rahman1996", "--geometry-file", "/nonexistent/g.json"], "--geometry-file"),
])
def test_a_bad_request_is_a_usage_error(args, words, tmp_path, capsys):
    status, _, err = _run(capsys, "differential", *args, "--out", str(tmp_path / "d"))
    assert status == 2 and err.startswith("linkrepro: error:") and words in err and "Traceback" not in err
    assert not (tmp_path / "d").exists()


def test_an_out_that_is_a_file_and_a_bad_geometry_file(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("")
    status, _, err = _run(capsys, "differential", "rahman1996", "--samples", "1", "--out", str(blocker))
    assert status == 2 and "--out" in err
    bad = tmp_path / "g.json"
    bad.write_text("{not json")
    status, _, err = _run(capsys, "differential", "rahman1996", "--geometry-file", str(bad), "--out", str(tmp_path / "d"))
    assert status == 2 and "not valid json" in err


def test_no_traceback_from_the_console_script(tmp_path):
    done = subprocess.run([sys.executable, "-m", "linkrepro", "differential", "ali1977", "--samples", "0"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=CHILD_SECONDS)
    assert done.returncode == 2 and "Traceback" not in done.stderr and "--samples" in done.stderr


def test_the_report_folder_shows_it(tmp_path, capsys):
    names = lambda: {s.name: s for s in collect(tmp_path).sections}              # noqa: E731
    assert not names()["differential"].present
    assert "linkrepro differential" in names()["differential"].command
    status, text, _ = _run(capsys, "differential", "rahman1996", "--samples", "2", "--out", str(tmp_path / "differential"))
    assert status == 0 and names()["differential"].present and f"report: {tmp_path / 'report.html'}" in text
    assert "differential/differential.md" in (tmp_path / "report.md").read_text()
    assert "Legacy against the port on sampled geometries" in (tmp_path / "report.html").read_text()


def test_outputs_are_compared_nan_for_nan_and_by_shape():
    program = differential.Program("p", "p", lambda g: {}, lambda g: {}, {})
    ok = lambda **r: differential.Outcome(result=r)                             # noqa: E731
    same = differential.compare(program, ok(x=np.array([1.0, np.nan])), ok(x=np.array([1.0, np.nan])))
    assert same.agree and same.largest == 0.0
    one_nan = differential.compare(program, ok(x=np.array([1.0, 2.0])), ok(x=np.array([1.0, np.nan])))
    assert not one_nan.agree and one_nan.largest == np.inf and one_nan.where == "x[1]"
    shape = differential.compare(program, ok(x=np.zeros(3)), ok(x=np.zeros(4)))
    assert not shape.agree and "shape" in shape.note
    missing = differential.compare(program, ok(x=np.zeros(3)), ok(x=np.zeros(3), y=np.zeros(1)))
    assert not missing.agree and "y" in missing.note
