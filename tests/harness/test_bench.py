"""``linkrepro bench``: what it computes, not how fast (no timing is asserted).

The Pareto front on hand-made points, the knobs' reference settings at error 0, and the
command's output files on the reduced configuration (``--quick``).
"""
from __future__ import annotations

import contextlib
import io
import json
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from PIL import Image

from linkrepro.harness import bench, bench_run, figures, multibody
from linkrepro.harness.cli import main


def test_pareto_front_on_hand_made_points():
    # (seconds, error): a staircase 1-4, a point beaten in both (5), one beaten in time
    # only at equal error (6), a duplicate of a front point (7), a failed setting (8)
    points = [(1.0, 8.0), (2.0, 4.0), (4.0, 2.0), (8.0, 1.0), (3.0, 5.0), (5.0, 2.0), (2.0, 4.0), (0.5, np.inf)]
    front = bench.pareto_front(*zip(*points))
    assert front.tolist() == [True, True, True, True, False, False, True, False]


def test_pareto_front_single_and_dominating_points():
    assert bench.pareto_front([1.0], [1.0]).tolist() == [True]
    assert bench.pareto_front([1.0, 2.0, 3.0], [1.0, 2.0, 0.5]).tolist() == [True, False, True]
    assert bench.pareto_front([1.0, 1.0], [np.nan, 2.0]).tolist() == [False, True]


def test_a_failed_newton_setting_is_inf_and_off_the_front():
    cap = next(k for k in bench_run.knobs(quick=True) if k.name == "1991 Newton iteration cap")
    rows = {row["setting"]: row for row in bench.knob_rows(cap, repeat=1)}
    assert rows["10"]["error"] == np.inf and "failed at" in rows["10"]["note"]
    assert not rows["10"]["pareto"]


def test_clearing_caches_clears_the_port_geometry_cache():
    from linkrepro.port.rahman1991 import position
    from linkrepro.port.rahman1991.data import GscInputs
    position.constants(GscInputs(), 0.0)
    assert position._geometry_constants.cache_info().currsize > 0
    bench.clear_port_caches()
    assert position._geometry_constants.cache_info().currsize == 0


def test_quick_bench_writes_its_three_files(tmp_path, monkeypatch):
    monkeypatch.setenv("LINKREPRO_PRINTED_BIN", str(tmp_path))     # no printed program is needed
    out = tmp_path / "b"
    stdout, stderr = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
        status = main(["bench", "--quick", "--out", str(out)])             # --quick: one call a setting
    assert status == 0, stderr.getvalue()
    assert sorted(p.name for p in out.iterdir()) == sorted([*bench.OUTPUTS, "manifest.json", ".linkrepro.lock"])
    record = json.loads((out / "manifest.json").read_text())
    assert record["command"] == f"linkrepro bench --quick --out {out}" and record["scenes"] == ["bench"]
    assert "One call each" in (out / "bench.md").read_text()
    assert list(record["outputs"]) == ["bench.csv"]
    frame = pd.read_csv(out / "bench.csv")
    assert list(frame.columns) == bench.COLUMNS
    costs, knobs = frame[frame.kind == "cost"], frame[frame.kind == "knob"]
    assert set(costs.engine) == {"legacy", "port_printed", "port_corrected", "limit"}
    assert costs.groupby("subject").engine.apply(lambda e: "limit" in set(e)).all()
    assert (costs.us_per_position > 0).all() and (costs.flops_per_position > 0).all()
    assert knobs.groupby("subject").pareto.any().all()
    # every knob's reference setting: the one reference of its knob, with zero error
    assert set(knobs.subject) == {k.name for k in bench_run.knobs(quick=True)}
    for knob in bench_run.knobs(quick=True):
        rows = knobs[knobs.subject == knob.name]
        assert rows.reference.tolist().count(True) == 1 and rows[rows.reference].setting.tolist() == [knob.reference]
        assert rows[rows.reference].error.iloc[0] == pytest.approx(0.0, abs=1e-15)
    text = (out / "bench.md").read_text()
    printed, last = stdout.getvalue().strip().rsplit("\n", 1)
    assert text.strip() == printed.strip()     # the markdown, then where it went (not a report folder)
    assert last.startswith(f"written: {out} ")
    assert "port (bugs) / legacy" in text and "legacy / limit" in text and "bench.png" in text
    # the figure: drawn and checked by figures.save (strict here: a broken rule fails the run), a
    # panel per knob of three settings or more, every label placed; the others told in words
    caption = figures.caption_of(out / "bench.png")
    fronts, told = caption.split("The fronts: ")[1].split(" Without a panel: ")        # which: timing-free
    exudyn = multibody.available()
    assert [f.split(": ")[0] for f in fronts.split("; ")] == [
        "K.E.D. angle step", *(["Exudyn settings (K.E.D. dynamics)", "Exudyn mesh (K.E.D.)", "Exudyn step (K.E.D. dynamics)",
                             "Exudyn mesh (frozen frequencies)"] if exudyn else []),
        "1991 angle step", "1991 Newton tolerance", "1991 Newton precision", "CSSP positions L",
        *(["Exudyn step (CSSP)"] if exudyn else [])]
    assert "left out" not in caption
    assert told.startswith("K.E.D. precision: double error 0 (") and "1991 Newton iteration cap: 10 failed (" in told
    with Image.open(out / "bench.png") as image:
        assert image.mode == "P" and image.width <= figures.MAX_WIDTH_IN * figures.DPI
    # the port with the listings' bugs equals legacy on the tables' angles
    agree = costs[(costs.engine == "port_printed") & costs.subject.str.startswith("K.E.D.")].error
    assert (agree <= 1e-12).all()


def test_bench_out_that_is_a_file_is_a_usage_error(tmp_path):
    target = tmp_path / "file"
    target.write_text("")
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        assert main(["bench", "--quick", "--out", str(target)]) == 2
    assert "--out" in err.getvalue() and "Traceback" not in err.getvalue()


def test_run_bench_rejects_a_bad_repeat(tmp_path):
    with pytest.raises(ValueError):
        bench_run.run_bench(0, Path(tmp_path), quick=True)


def test_the_figure_labels_every_setting_of_a_crowded_knob(tmp_path):
    """bench.png on made-up knobs: settings a few pixels apart (each labelled, the figure checked
    strictly), a sweep drawn as series, a knob of two settings told in the caption instead."""
    def knob(name, points, engine="port_corrected"):
        rows = [dict(kind="knob", subject=name, setting=setting, engine=engine, seconds=seconds, error=error,
                     error_unit="in", reference=error == 0) for setting, seconds, error in points]
        return bench.with_pareto_front(rows)
    crowded = knob("crowded", [(f"L = {n}", 1e-3 * (1 + 0.02 * k), 10.0 ** -k if n < 72 else 0.0)
                               for k, n in enumerate((6, 9, 12, 18, 24, 36, 72))])
    sweep = knob("sweep", [(f"n = {n}, {model}, {step} deg", 1e-4 * n * (2 if step == 1 else 1),
                            0.1 / n + (model == "listing"))
                           for n in (1, 2, 5, 10) for model in ("coupled", "listing") for step in (10, 1)])
    two = knob("two", [("double", 1e-3, 0.0), ("REAL*4", 1e-3, 1e-7)])
    frame = pd.DataFrame(crowded + sweep + two).reindex(columns=bench.COLUMNS)
    caption = figures.caption_of(bench.plot(frame, tmp_path / "bench.png", {"sweep": bench.series_of_setting}))
    assert "crowded: L = 6, L = 9, L = 12, L = 18, L = 24, L = 36, L = 72" in caption
    assert "left out" not in caption and caption.endswith('Without a panel: two: double error 0 (1 ms), REAL*4 '
                                                          'error 1e-07 in (1 ms).')


def test_an_engine_s_warnings_are_in_bench_md_not_on_stderr(tmp_path, monkeypatch, capsys):
    """A computation whose engine warns (the bench times settings near the listings' limits):
    bench.md lists each distinct warning with how many times it was given; stderr stays clean."""
    from linkrepro.errors import PrecisionWarning

    def warns():
        warnings.warn("KED1S: fewer digits at input angle 143.7 deg (REAL*4)", PrecisionWarning)
        return np.ones(3)
    comp = bench.Computation("a warning computation", 3, {"legacy": warns, "port_printed": lambda: np.ones(3)},
                             lambda _: 1.0)
    monkeypatch.setattr(bench_run, "computations", lambda quick: [comp])
    monkeypatch.setattr(bench_run, "knobs", lambda quick: [])
    monkeypatch.setattr(bench_run, "sweeps", lambda quick: [])
    monkeypatch.setattr(bench_run, "plot", lambda *args: None)
    text = bench_run.run_bench(repeat=2, out=tmp_path)
    assert "PrecisionWarning" not in capsys.readouterr().err
    # the warm-up call and two timed calls; the words as written (REAL*4's asterisk kept)
    assert "- `PrecisionWarning` (3 times): KED1S: fewer digits at input angle 143.7 deg (REAL\\*4)" in text
