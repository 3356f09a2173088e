"""Scene rahman1991-example: Rahman (1991), section 3.1's example over its grid, and the
claims of section 3.2 checked one by one.

The thesis prints no table: its results are figures 5-38 and statements in words
(harness/published/rahman1991_claims.csv).  This scene writes, under out/rahman1991-example/:
port.csv (the method as printed, ``GSC_PRINTED``) and port_corrected.csv, one row per grid
point and crank angle (columns ``gsc.COLUMNS``), diagnostics.csv (status, closure error),
claims.csv (each claim, each engine: measured, verdict), convergence.csv (the convergence
limits: our Newton, Newton + DFP, and the 1996 legacy build), near_singular.csv (digits
lost near theta2 = 0), legacy.csv (the 1996 build on these inputs), the figures, report.md.
"""
from __future__ import annotations

import functools
import itertools
import time
from pathlib import Path

import numpy as np
import pandas as pd

from ....errors import LinkageError
from ....port.rahman1991 import analysis as gsc, position as gsc_position
from ....port.rahman1991.data import GscInputs
from ....port.rahman1991.quirks import GSC_CORRECTED, GSC_PRINTED
from . import near_singular, planar_reference, figures as rahman1991_figures
from ... import progress
from ...csv_output import FULL_PRECISION, write_csv
from ...published_tables import PUBLISHED_DIR
from ...scene import ReportScene

NAME = "rahman1991-example"
TITLE = ("Rahman (1991) section 3.1: slider displacement and joint forces over the example's grid; "
         "the claims of section 3.2")
ENGINES = {"port_printed": GSC_PRINTED, "port_corrected": GSC_CORRECTED}
ZERO = 1e-9            # lbf, lbf*in: a component "is zero" below this
#: S1 values (in) of the convergence study, a4 = 0, 10, 20, 30 with alpha4 = 270
STUDY_S1 = np.arange(0.0, 9.01, 0.5)
STUDY_ALPHA4 = np.arange(200.0, 341.0, 2.0)


def claims_text() -> pd.DataFrame:
    return pd.read_csv(PUBLISHED_DIR / "rahman1991_claims.csv", comment="#", dtype=str, keep_default_na=False)


@functools.lru_cache(maxsize=None)
def grid(engine: str) -> pd.DataFrame:
    """The example's grid by one engine (cached: the claims and figures share it)."""
    return gsc.sweep(ENGINES[engine])


def _ok(frame: pd.DataFrame) -> pd.DataFrame:
    """The rows that hold their engine's answer with its loads: the thesis's claims are about
    the printed method's numbers, its open loops (D085) included."""
    return frame[frame["status"].isin(gsc.ANSWERED) & frame["F1i"].notna()]


def _planar_gap(frame: pd.DataFrame) -> float:
    """Largest |engine - complex-number analysis| over the planar grid points (alpha4 = 270,
    S1 = 0), relative to each column's largest reference value; positions within 1.5 deg of a
    dead centre (where a constant torque cannot be balanced) left out."""
    worst = 0.0
    planar = _ok(frame[(frame.alpha4_deg == 270.0) & (frame.s1 == 0.0)])
    for a4 in planar.a4.unique():
        rows = planar[planar.a4 == a4]
        ref = planar_reference.analyse(rows.crank_deg.to_numpy(), a4=a4, torque=-GscInputs().torque)
        expected = planar_reference.in_thesis_frames(ref)
        away = np.abs(np.sin(ref["th_rod"] - ref["theta1"])) > np.sin(np.radians(1.5)) * 0.2
        for name, values in expected.items():
            gap = np.abs(rows[name].to_numpy() - values)[away]
            worst = max(worst, float(np.max(gap) / np.max(np.abs(values[away]))))
    return worst


def _spikes(frame: pd.DataFrame, engine: str) -> dict:
    """Where the largest |2F2i| of each a4-family curve (S1 = 3.5, alpha4 = 270) lies: its
    distance (deg) to the nearest crank angle where theta2 passes 0 or 180 deg (dead centre)."""
    worst, where = 0.0, []
    for a4 in (10.0, 20.0, 30.0):
        rows = _ok(frame[(frame.a4 == a4) & (frame.alpha4_deg == 270.0) & (frame.s1 == 3.5)])
        if rows.empty:
            continue
        dead = rahman1991_figures.dead_centres(rows.crank_deg.to_numpy(), rows.theta2.to_numpy())
        peak = float(rows.crank_deg.to_numpy()[np.argmax(np.abs(rows.F2i.to_numpy()))])
        where.append(f"a4 = {a4:g}: {peak:g}")
        if len(dead):
            worst = max(worst, float(np.min(np.abs(dead - peak))))
    return {"spikes": (worst, 2.0, "largest |2F2i| at crank deg (" + "; ".join(where) + "); value: its "
                       "distance to the nearest theta2 = 0/180 (dead centre), deg")}


def _iterations(frame: pd.DataFrame, engine: str, text: pd.DataFrame) -> dict:
    """Newton steps per position the Newton stopped at (the last, small step counted), planar points."""
    if engine != "port_printed":
        return {}
    lo, hi = (float(v) for v in text.loc["iterations", "value"].split())
    ok = frame[frame.status.isin(gsc.ANSWERED)]
    planar = ok[(ok.alpha4_deg == 270.0) & (ok.s1 == 0.0)].iterations
    spatial = ok.drop(planar.index).iterations
    median = float(planar.median())
    return {"iterations": (0.0 if lo <= median <= hi else abs(median - hi), 0.0,
                           f"median Newton steps per position: planar {median:g} (max {planar.max()}), "
                           f"spatial {spatial.median():g} (max {spatial.max()}); value: distance of the "
                           f"planar median from [{lo:g}, {hi:g}]")}


def measure_claims(frames: dict[str, pd.DataFrame], limits: pd.DataFrame) -> pd.DataFrame:
    """claims.csv: each claim of rahman1991_claims.csv, each engine, measured and verdict."""
    text = claims_text().set_index("claim")
    torque, a1 = GscInputs().torque, GscInputs().a1
    printed_f2j = float(text.loc["f2j_constant", "value"])
    rows = []
    for engine, frame in frames.items():
        ok = _ok(frame)
        planar = ok[(ok.alpha4_deg == 270.0) & (ok.s1 == 0.0)]
        spatial = ok.drop(planar.index)
        t1 = np.maximum(np.abs(ok.T1i + ok.F1j * ok.s1), np.abs(ok.T1j - ok.F1i * ok.s1)).max()
        found = {
            "t4_zero": (ok[["T4i", "T4j", "T4k"]].abs().to_numpy().max(), ZERO, "max |4T4| (lbf in)"),
            "f2k_zero": (ok.F2k.abs().max(), ZERO, f"max |2F2k| (lbf); planar points {planar.F2k.abs().max():.3g}, "
                                                   f"spatial {spatial.F2k.abs().max() if len(spatial) else float('nan'):.3g}"),
            "f2j_constant": ((ok.F2j - printed_f2j).abs().max(), 0.005, "max |2F2j - (-8.33)| (lbf), printed to 0.01"),
            "f2j_ratio": ((ok.F2j + torque / a1).abs().max(), ZERO, "max |2F2j + T1k/a1| (lbf)"),
            "t1_moments": (t1, ZERO, "max |1T1i + 1F1j S1|, |1T1j - 1F1i S1| (lbf in)"),
            "t1_zero_without_s1": (ok[ok.s1 == 0.0][["T1i", "T1j"]].abs().to_numpy().max(), ZERO, "max |1T1i|, |1T1j| at S1 = 0 (lbf in)"),
            "planar_complex": (_planar_gap(frame), 1e-6, "largest relative gap to the complex-number analysis "
                                                         "(s4, forces; >= 1.5 deg from dead centres)"),
        }
        found.update(_spikes(frame, engine), **_iterations(frame, engine, text))
        for claim, (value, tol, what) in found.items():
            rows.append(dict(claim=claim, engine=engine, measured=float(value), tolerance=tol,
                             verdict="reproduced" if value <= tol else "contradicted", what=what))
    for _, row in limits.iterrows():
        rows.append(dict(claim=row["claim"], engine=row["engine"], measured=row["measured"],
                         tolerance=np.nan, verdict=row["verdict"], what=row["what"]))
    return pd.DataFrame(rows)


@functools.lru_cache(maxsize=None)
def legacy_failure(inputs: GscInputs) -> tuple[str, float] | None:
    """Where the 1996 legacy build's Newton (10-deg steps, REAL*4) fails on a full turn: (the
    error's type, crank deg); None when it runs the turn.  Cached: the convergence study and
    ``legacy_on_grid`` share the grid's configurations."""
    from ....legacy import rahman1996
    try:
        rahman1996.cssp(a1=inputs.a1, a2=inputs.a2, a4=inputs.a4, alpha4_deg=inputs.alpha4_deg,
                        s1=inputs.s1, rpm=inputs.rpm)
    except LinkageError as exc:
        return type(exc).__name__, exc.angle_deg
    return None


def _port_verdicts(status: np.ndarray) -> tuple[bool, bool]:
    """(Newton alone, Newton + DFP) converge: the statuses of a pass are all stops, and none
    after the DFP fallback."""
    stopped = bool(np.isin(status, gsc_position.STOPPED).all())
    return stopped and not np.char.startswith(status.astype(str), gsc_position.DFP_THEN_NEWTON).any(), stopped


def _grid_statuses(printed: pd.DataFrame | None) -> dict:
    """{(a4, alpha4_deg, s1): statuses} of the grid's printed runs (``grid``) that restarted
    nowhere from the closed form.  Such a run is the study's pass (``convergence_study``) until
    its first failure: the same Newton from the same answers, the branch check only relabelling
    stops (a stop on the other branch, or one it failed to restart, is a stop there too); and a
    failure anywhere fails both verdicts of both."""
    if printed is None:
        return {}
    found = {key: rows.to_numpy() for key, rows in printed.groupby(["a4", "alpha4_deg", "s1"]).status}
    return {key: status for key, status in found.items() if not (status == gsc_position.RESTARTED).any()}


def convergence_study(printed: pd.DataFrame | None = None) -> pd.DataFrame:
    """Which configurations converge over a full turn (0..360 step 1, stopping at the first
    failure as the thesis's program does), per engine; and whether each one assembles.

    "Converge" is the thesis's word: the printed Newton stops (every |Delta| <= 1e-7) at every
    position, closed loop or not (``position.STOPPED``; off the plane the loop cannot close,
    D085), unchecked (``branch=None``).  One pass with the DFP fallback: until its first Newton
    failure it is the pass without it, so that pass converges where this one never ran DFP.
    ``printed``: the grid by the printed method (``grid``), whose configurations are read from
    it where ``_grid_statuses`` holds them, not solved again."""
    configs = [GscInputs(a4=a4, s1=s1) for a4, s1 in itertools.product(gsc.GRID_A4, STUDY_S1)]
    configs += [GscInputs(a4=20.0, alpha4_deg=al) for al in STUDY_ALPHA4]
    th = np.radians(gsc.CRANK_DEG)
    known = _grid_statuses(printed)
    keys = [(x.a4, x.alpha4_deg, x.s1) for x in configs]
    todo = list(dict.fromkeys(key for key in keys if key not in known))
    runs = gsc_position.positions_batch([GscInputs(a4=a4, alpha4_deg=al, s1=s1) for a4, al, s1 in todo], th,
                                        use_dfp=True, stop_at_failure=True, branch=None)
    port = {**{key: _port_verdicts(status) for key, status in known.items()},
            **{key: _port_verdicts(run.status) for key, run in zip(todo, runs)}}
    verdicts = {"port Newton (1 deg steps)": [port[key][0] for key in keys],
                "port Newton + DFP (1 deg steps)": [port[key][1] for key in keys]}
    verdicts["legacy 1996 build (10 deg steps, REAL*4)"] = [legacy_failure(x) is None for x in configs]
    rows = []
    for k, inputs in enumerate(configs):
        assembles = bool(gsc_position.assembles(inputs, th, inputs.s1).all())
        for engine, converges in verdicts.items():
            rows.append(dict(a4=inputs.a4, alpha4_deg=inputs.alpha4_deg, s1=inputs.s1, engine=engine,
                             assembles=assembles, converges=bool(converges[k])))
    return pd.DataFrame(rows)


def convergence_limits(study: pd.DataFrame) -> pd.DataFrame:
    """The four convergence claims against the study: largest S1 below which every S1 converges."""
    text = claims_text().set_index("claim")
    rows = []
    for engine, runs in study.groupby("engine"):
        by_s1 = runs[runs.alpha4_deg == 270.0]
        for claim, a4 in (("converge_a4_0", 0.0), ("converge_a4_10", 10.0), ("converge_a4_30", 30.0)):
            series = by_s1[by_s1.a4 == a4].sort_values("s1")
            failed = series[~series.converges]
            limit = float(series.s1[series.s1 < failed.s1.min()].max()) if len(failed) else float(series.s1.max())
            printed = float(text.loc[claim, "value"])
            rows.append(dict(claim=claim, engine=engine, measured=limit,
                             verdict="reproduced" if abs(limit - printed) < 0.5 else "contradicted",
                             what=f"largest S1 (in, step 0.5) up to which every S1 converges; printed {printed:g}"))
        alpha = runs[(runs.a4 == 20.0) & (runs.s1 == 0.0)]
        lo, hi = (float(v) for v in text.loc["converge_alpha4", "value"].split())
        inside = alpha[(alpha.alpha4_deg >= lo) & (alpha.alpha4_deg <= hi)]
        good = alpha[alpha.converges].alpha4_deg
        rows.append(dict(claim="converge_alpha4", engine=engine,
                         measured=float(inside.converges.mean()),
                         verdict="reproduced" if inside.converges.all() else "contradicted",
                         what=f"share of alpha4 in [{lo:g}, {hi:g}] (step 2) converging; converging range "
                              f"{good.min():g}..{good.max():g} deg" if len(good) else "none converges"))
    return pd.DataFrame(rows)


def legacy_on_grid(printed: pd.DataFrame) -> pd.DataFrame:
    """The 1996 legacy build on each grid point (its Newton is the 1991 method: 10-deg steps,
    REAL*4, the listing's INVERSE): runs or fails, and where.  The port's replica of its first
    pass (``cssp_listing.listing_pass``, equal to the build's own positions bit for bit,
    tests/test_differential_rahman.py) runs on where the build stops after a later failure;
    its positions are diffed against the 1991 port's (1-deg steps, float64) at the angles
    both solved: largest |S4 difference| (in) and |theta2 difference| (deg)."""
    from ....port.rahman1996.data import Constants
    from ....port.rahman1996.listing import listing_pass
    from ....port.slider_crank.geometry import initial_estimate
    rows = []
    for a4, al, s1 in itertools.product(gsc.GRID_A4, gsc.GRID_ALPHA4, gsc.GRID_S1):
        inputs = GscInputs(a4=a4, alpha4_deg=al, s1=s1)
        row = dict(a4=a4, alpha4_deg=al, s1=s1, legacy="converged", legacy_fail_deg=np.nan,
                   replica="converged", replica_fail_deg=np.nan, max_ds4_in=np.nan, max_dtheta2_deg=np.nan)
        failure = legacy_failure(inputs)
        if failure is not None:
            row.update(legacy=failure[0], legacy_fail_deg=failure[1])
        c = Constants.of(inputs, real4=True)
        try:
            q = listing_pass(gsc.CRANK_DEG[::10], initial_estimate(c, True), c, True).q
        except LinkageError as exc:
            row.update(replica=type(exc).__name__, replica_fail_deg=exc.angle_deg)
        else:
            ours = printed[(printed.a4 == a4) & (printed.alpha4_deg == al) & (printed.s1 == s1)].iloc[::10]
            both = ours.status.isin(gsc.ANSWERED).to_numpy()
            if both.any():
                dtheta = np.degrees(np.mod(q[:, 0], 2 * np.pi)) - ours.theta2.to_numpy()
                row.update(max_ds4_in=float(np.max(np.abs(q[both, 4] - ours.s4.to_numpy()[both]))),
                           max_dtheta2_deg=float(np.max(np.abs((dtheta[both] + 180.0) % 360.0 - 180.0))))
        rows.append(row)
    return pd.DataFrame(rows)


def run(out_dir: Path) -> dict:
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    timings, frames = {}, {}
    for engine in ENGINES:
        progress.note(NAME, f"grid, {engine}")
        start = time.perf_counter()
        frames[engine] = grid(engine)
        timings[engine] = time.perf_counter() - start
        name = "port.csv" if engine == "port_printed" else f"{engine}.csv"
        write_csv(frames[engine][gsc.COLUMNS], target / name, FULL_PRECISION)
    diagnostics = pd.concat([f[["a4", "alpha4_deg", "s1", "crank_deg", "status", "closure"]].assign(engine=e)
                             for e, f in frames.items()])
    write_csv(diagnostics, target / "diagnostics.csv", "%.6g")
    progress.note(NAME, "convergence study")
    start = time.perf_counter()
    study = convergence_study(frames["port_printed"])
    timings["convergence study"] = time.perf_counter() - start
    study.to_csv(target / "convergence.csv", index=False)
    claims = measure_claims(frames, convergence_limits(study))
    claims.to_csv(target / "claims.csv", index=False, float_format="%.6g")
    progress.note(NAME, "near theta2 = 0")
    singular = near_singular.table()
    singular.to_csv(target / "near_singular.csv", index=False, float_format="%.6g")
    progress.note(NAME, "figures")
    plots = rahman1991_figures.plot_figures(frames, target)
    progress.note(NAME, "the 1996 build on the grid")     # last: its kernel may be compiled by now
    legacy = legacy_on_grid(frames["port_printed"])
    legacy.to_csv(target / "legacy.csv", index=False)
    (target / "report.md").write_text(report(frames, claims, study, singular, legacy, plots, timings))
    return {"scene": NAME, "title": TITLE, "claims": claims, "timings": timings}


def _md(frame: pd.DataFrame) -> str:
    from ...report import markdown_table
    return markdown_table(frame.set_index(frame.columns[0]), "{:.4g}")


def report(frames, claims, study, singular, legacy, plots, timings) -> str:
    lines = [f"# {NAME}", "", TITLE, "",
             "No numeric table is printed in the thesis; its statements are checked instead "
             "(`claims.csv`; the printed words in harness/published/rahman1991_claims.csv; "
             "register D085-D094).", "", "## Claims of section 3.2", "",
             _md(claims), "", "## Convergence: does the mechanism assemble, does the solver converge", "",
             "Every configuration of the study assembles (a rod of 50 in reaches the slider axis at every crank "
             "angle); the failures are the solver's.", "",
             _md(study.pivot_table(index=["a4", "alpha4_deg", "s1"], columns="engine",
                                              values="converges").reset_index()), "",
             "## Near theta2 = 0: digits lost", "", _md(singular), "",
             "## The 1996 legacy build on the example's grid", "", _md(legacy), "",
             "## Timings (this run)", ""]
    lines += [f"- {k}: {v:.2f} s" for k, v in timings.items()]
    lines += ["", "## Figures", ""] + [f"![{p.stem}]({p.name})" for p in plots]
    lines[4:4] = [f"- {engine}: positions by status {frame['status'].value_counts().to_dict()}"
                  for engine, frame in reversed(frames.items())] + [""]     # a list, then the paragraph after it
    return "\n".join(lines) + "\n"


def overview(result: dict) -> list[str]:
    """The run report's table: each claim's verdicts per engine."""
    verdicts = result["claims"].groupby(["engine", "verdict"]).size().unstack(fill_value=0)
    return (["No numeric table is printed; each claim of section 3.2, per engine "
             f"(see [the scene report]({NAME}/report.md) and register D085-D094):", "",
             "| engine | " + " | ".join(verdicts.columns) + " |", "|---|" + "---|" * len(verdicts.columns)]
            + [f"| {engine} | " + " | ".join(str(v) for v in row) + " |" for engine, row in verdicts.iterrows()])


#: the third longest group; it compiles the Newton kernels the 1996 tables load, so it starts before them
SCENE = ReportScene(name=NAME, title=TITLE, group="rahman1991", start=1, produce=run, overview=overview)
