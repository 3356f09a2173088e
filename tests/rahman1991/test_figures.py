"""The rahman1991-example figures (harness/scenes/rahman1991/figures.py), drawn from the drawn
cases of the example's grid under the figure rules (strict: tests/conftest.py), and the helpers
that decide what a curve shows; the convergence study's reading of the printed Newton."""
from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from PIL import Image

from linkrepro.harness import figures
from linkrepro.harness.scenes.rahman1991 import example, figures as gsc_figures
from linkrepro.port.rahman1991 import analysis as gsc, position
from linkrepro.port.rahman1991.data import GscInputs


@pytest.fixture(scope="module")
def frames() -> dict[str, pd.DataFrame]:
    """Both engines on every case a figure draws (the ideal and each family's members)."""
    configs = [GscInputs(**where) for where in gsc_figures.drawn_cases().values()]
    return {engine: pd.concat([gsc.analyse(inputs, quirks=quirks) for inputs in configs], ignore_index=True)
            for engine, quirks in example.ENGINES.items()}


@pytest.fixture(scope="module")
def written(frames, tmp_path_factory, monkeypatch_module):
    monkeypatch_module.setenv(figures.STRICT_ENV, "1")
    monkeypatch_module.setenv("LINKREPRO_IN_POOL", "1")          # drawn here, one after the other
    return gsc_figures.plot_figures(frames, tmp_path_factory.mktemp("r91"))


@pytest.fixture(scope="module")
def monkeypatch_module():
    with pytest.MonkeyPatch.context() as patch:
        yield patch


def test_the_figures_are_few_in_reading_order_light_and_captioned(written):
    names = [path.name for path in written]
    assert names == sorted(names) == ["fig_01_s4.png", "fig_02_loads_port_printed.png",
                                      "fig_03_loads_port_corrected.png"]
    assert sum(path.stat().st_size for path in written) < 150_000
    for path in written:
        text = figures.caption_of(path)
        assert "Measured in this run" in text and "crank steps of 1 deg" in text, path.name
        with Image.open(path) as image:
            assert image.width <= figures.MAX_WIDTH_IN * figures.DPI


def _number(pattern: str, text: str) -> float:
    found = re.search(pattern, text)
    assert found, (pattern, text)
    return float(found.group(1))


def test_the_displacement_caption_states_the_gaps_measured(frames, written):
    text = figures.caption_of(written[0])
    keys = ["a4", "alpha4_deg", "s1", "crank_deg"]
    both = frames["port_printed"].merge(frames["port_corrected"], on=keys)
    gap = (both.s4_x - both.s4_y).abs()
    planar = (both.alpha4_deg == 270.0) & (both.s1 == 0.0)
    assert _number(r"is ([0-9.e+-]+) in on the planar cases", text) == pytest.approx(gap[planar].max(), rel=0.06)
    assert _number(r"to ([0-9.]+) in on the others", text) == pytest.approx(gap[~planar].max(), rel=0.01)
    printed = frames["port_printed"]
    dfp = printed[printed.status.str.startswith(position.DFP_THEN_NEWTON)]
    assert len(dfp) == 1 and f"at {dfp.crank_deg.iloc[0]:g} deg" in text


def test_the_load_captions_name_what_is_not_drawn(frames, written):
    printed, corrected = (figures.caption_of(path) for path in written[1:])
    example = GscInputs()                      # the crank at constant speed: F2j a1 = -T1k about its bearing
    assert f"force 2F2, crank on rod, j = {-example.torque / example.a1:g} lbf" in printed
    assert f"torque 1T1, crank on frame, k = {example.torque:g} lbf in" in printed
    assert "force 2F2, crank on rod, k = minus force 1F1, crank on frame, k" in corrected
    f = frames["port_corrected"]
    assert np.allclose(f.F2k, -f.F1k, rtol=1e-9, atol=1e-9, equal_nan=True)
    dead = f[f.status == gsc.DEAD_CENTRE]
    assert f"at {', '.join(f'{v:g}' for v in dead.crank_deg)} deg (status: dead centre)" in corrected
    beyond = _number(r"([0-9]+) drawn points lie beyond the y-limits", corrected)
    assert beyond > 0 and f"{beyond:g} of them within" in corrected


def test_load_rows_drop_the_constant_and_the_repeated_components(frames):
    drawn, constants, equal = gsc_figures.load_rows(gsc_figures.case_rows(frames["port_corrected"]))
    assert [q for q, _ in drawn] == ["F1i", "F1j", "F1k", "T1i", "T1j", "F2i", "F3i", "F3j", "F3k", "F4i", "F4j", "F4k"]
    assert set(constants) == {"T1k", "F2j", "T4i", "T4j", "T4k"} and equal == {"F2k": (-1.0, "F1k")}
    drawn, constants, equal = gsc_figures.load_rows(gsc_figures.case_rows(frames["port_printed"]))
    assert len(drawn) == 11 and not equal


def test_same_as_needs_every_point_equal():
    x = np.arange(5.0)
    row = gsc_figures.Row("a", [[(x, np.array([1.0, -2.0, np.nan, 1e15, 3.0]))]], None)
    assert gsc_figures.same_as([[(x, np.array([-1.0, 2.0, np.nan, -1e15, -3.0]))]], [("a", row)]) == (-1.0, "a")
    assert gsc_figures.same_as([[(x, np.array([1.0, -2.0, np.nan, 1e15, 3.001]))]], [("a", row)]) is None
    assert gsc_figures.same_as([[(x, np.array([1.0, -2.0, 0.0, 1e15, 3.0]))]], [("a", row)]) is None


def test_a_curve_breaks_through_a_pole_and_each_run_beyond_a_limit_is_marked_once():
    x = np.arange(7.0)
    y = np.array([10.0, 900.0, 5e14, -400.0, -20.0, 2000.0, 30.0])
    bx, by = gsc_figures.broken(x, y, -100.0, 100.0)
    assert np.isnan(by).sum() == 2 and np.isnan(bx[3]) and np.isnan(bx[6])   # after 5e14, after -20
    assert np.array_equal(by[~np.isnan(by)], y)
    assert gsc_figures.excursions(x, y, -100.0, 100.0) == [(2.0, True), (5.0, True), (3.0, False)]


def test_a_dead_centre_is_where_theta2_passes_0_or_180():
    crank = np.arange(0.0, 6.0)
    assert list(gsc_figures.dead_centres(crank, np.array([3.0, 1.0, -1.0, -90.0, -179.0, 179.0]))) == [1.0, 4.0]


def test_the_study_counts_a_stop_of_the_printed_newton_as_the_thesis_does():
    """The convergence study's verdicts are the printed Newton's, unchecked: a pass that goes
    on after a failure is, until then, the one that stops; "Newton alone" is the DFP pass that
    never ran DFP; its Newton stops where the loop is open too (the thesis's word)."""
    configs = [GscInputs(a4=0.0, s1=9.0), GscInputs(a4=0.0, s1=6.0), GscInputs(a4=10.0, s1=3.5),
               GscInputs(a4=20.0, alpha4_deg=232.0)]
    th = np.radians(gsc.CRANK_DEG)
    going, stopping, alone = (position.positions_batch(configs, th, use_dfp=dfp, stop_at_failure=stop, branch=None)
                              for dfp, stop in ((True, False), (True, True), (False, True)))
    assert any(not run.stopped.all() for run in going) and any(run.stopped.all() for run in going)
    for a, b, c in zip(going, stopping, alone):
        failed = np.flatnonzero(~b.stopped)
        end = failed[0] if failed.size else th.size
        assert np.array_equal(a.status[:end + 1], b.status[:end + 1])
        np.testing.assert_array_equal(a.q[:end], b.q[:end])
        assert c.stopped.all() == (b.stopped.all() and not b.dfp.any())


def test_the_study_takes_the_grid_s_runs_where_they_restarted_nowhere():
    """A grid run (branch checked, going on after a failure) that restarted nowhere gives the
    verdicts of the study's own pass (unchecked, stopping at the first failure); one that
    restarted is solved again."""
    frame = gsc.sweep(a4=(0.0, 10.0), alpha4_deg=(270.0,), s1=(0.0, 3.5, 6.0))
    known = example._grid_statuses(frame)
    th = np.radians(gsc.CRANK_DEG)
    verdicts = set()
    for (a4, alpha4, s1), status in known.items():
        own = position.positions(GscInputs(a4=a4, alpha4_deg=alpha4, s1=s1), th, use_dfp=True,
                                 stop_at_failure=True, branch=None)
        verdicts.add(example._port_verdicts(status))
        assert example._port_verdicts(status) == example._port_verdicts(own.status)
    assert len(known) == 6 and verdicts == {(True, True), (False, True), (False, False)}
    restarted = frame.assign(status=np.where(frame.index == 5, position.RESTARTED, frame.status))
    assert len(example._grid_statuses(restarted)) == 5
