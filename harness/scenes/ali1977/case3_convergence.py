"""The Case III convergence study: sub-elements n and angle step against the converged tip
deflection, with time, and which mass model each Ali (1977) table needs.

``reproduce`` writes it as scene ali1977-case3-convergence (case3_convergence.{csv,png}, report.md);
``linkrepro bench`` prints it.
Times are wall-clock seconds of this run (best of ``repeat``, after a warm-up call).
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pandas as pd

from ....legacy import ali1977
from ....port.ali1977 import CORRECTED, source_case1
from ....port.ali1977.case3 import LISTING as CASE3_LISTING
from ....port.ali1977.case3 import case3_linkage, case3_on_linkage
from ...csv_output import write_csv
from ...scene import ReportScene
from .quantities import CASE3


def _timed(func, repeat: int):
    """(the best wall-clock seconds of ``repeat`` calls of ``func``, the result of the last), the
    calls timed after one untimed warm-up call (a first call's own costs, such as filling the
    caches of a new n, are not the model's)."""
    func()
    best, result = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        result = func()
        best = min(best, time.perf_counter() - start)
    return best, result


CASE3_NS = (1, 2, 5, 10, 20, 50, 100, 200)
CASE3_STEPS = (20.0, 10.0, 1.0)


def _converged(linkage, reference_n: int) -> dict:
    """The coupled model's tip dx, dy at reference_n/2 and reference_n sub-elements,
    Richardson-extrapolated (the node-end lumping is first order: 2 d(2n) - d(n))."""
    fine = case3_on_linkage(linkage, n=reference_n)
    half = case3_on_linkage(linkage, n=reference_n // 2)
    return {k: 2 * fine[k] - half[k] for k in ("dx", "dy")}


def _error(got: dict, converged: dict) -> float:
    """max |tip dx, dy - converged| (in)."""
    return max(float(np.max(np.abs(got[k] - converged[k]))) for k in ("dx", "dy"))


def case3_data(repeat: int, reference_n: int = 3200) -> pd.DataFrame:
    """Case III sweep: one row per (angle step, n) with the coupled and the listing's model:
    time (s, best of ``repeat`` after a warm-up call) and max |tip dx, dy - converged| (in).  Converged: the
    coupled model at reference_n/2 and reference_n, Richardson-extrapolated.  The four-bar's
    kinematics are computed once per angle grid and model (case3_linkage) and reused for
    every n (case3_on_linkage); a row's time is theirs plus its n-node model's."""
    rows = []
    models = {"coupled": CORRECTED, "listing": CASE3_LISTING.without("real4_storage")}
    for step in CASE3_STEPS:
        deg = np.arange(0.0, 360.0 + 1e-9, step)
        linkages = {model: _timed(lambda: case3_linkage(deg, quirks=quirks), repeat)
                    for model, quirks in models.items()}
        converged = _converged(linkages["coupled"][1], reference_n)
        t_leg, _ = _timed(lambda: ali1977.case3_source(step_deg=step), repeat)
        for n in CASE3_NS:
            for model, (t_kinematics, linkage) in linkages.items():
                seconds, got = _timed(lambda: case3_on_linkage(linkage, n=n), repeat)
                rows.append({"step_deg": step, "n": n, "model": model, "seconds": t_kinematics + seconds,
                             "error_in": _error(got, converged), "legacy_seconds_n5": t_leg if n == 5 else np.nan})
    return pd.DataFrame(rows)


def case3_sweep(repeat: int, data: pd.DataFrame | None = None) -> list[str]:
    """The sweep as markdown (``data``: case3_data(repeat), computed here if not given), and which
    model each table needs."""
    data = case3_data(repeat) if data is None else data
    lines = ["", "## Case III: sub-elements n and angle step, against the converged tip deflection", "",
             "Error: max |tip dx, dy - converged| (in) over 0-360 at the step; converged = Richardson "
             "extrapolation of the coupled model at n = 1600, 3200. Port timed for every n (the four-bar's "
             "kinematics, computed once per angle grid and model, and the n-node model on them); legacy (the "
             "listing, n = 5, uncoupled) where the printed structure allows; every time the best of "
             f"{repeat} calls after a warm-up call.", "",
             "| step (deg) | n | coupled port s | coupled error (in) | listing-model port s | listing-model error (in) | legacy s (n=5) |",
             "|---|---|---|---|---|---|---|"]
    for (step, n), g in data.groupby(["step_deg", "n"], sort=False):
        c, li = g[g["model"] == "coupled"].iloc[0], g[g["model"] == "listing"].iloc[0]
        leg = f"{c.legacy_seconds_n5:.5f}" if n == 5 else ""
        lines.append(f"| {step:g} | {n} | {c.seconds:.5f} | {c.error_in:.2e} | {li.seconds:.5f} | "
                     f"{li.error_in:.2e} | {leg} |")
    lines += ["", "The listing's model keeps the tip's own load only (D034) and lumps the extender up to each "
              "node (D033): its tip deflection does not depend on n, and its error against the converged "
              "coupled model does not shrink as n grows.", ""]
    lines += table_model_needs()
    return lines


#: one colour per angle step (deg); the mass model by line: coupled solid with dots, the listing's dashed with crosses
STEP_COLOUR = {20.0: "tab:purple", 10.0: "tab:green", 1.0: "tab:blue"}
MODEL_LINE = {"coupled": dict(ls="-", marker="o", ms=4), "listing": dict(ls="--", marker="x", ms=6)}
#: half a unit of the tables' last printed digit (in)
HALF_UNIT_IN = 0.0005


def plot_case3(data: pd.DataFrame, path) -> None:
    """The tip error (in) against sub-elements n and against the port's wall time (s), one line per
    angle step (colour) and mass model (line), half the printed unit dotted."""
    from ...figures import save
    from ...report import panel_grid, top_legend
    fig, margins = panel_grid(11.0, 2, 1, 3.6, TITLE, legend_rows=2, gap_across=0.35)
    by_n, by_time = fig.subplots(1, 2, sharey=True)
    for (step, model), g in data.groupby(["step_deg", "model"], sort=False):
        style = dict(color=STEP_COLOUR[step], **MODEL_LINE[model], label=f"{model} model, {step:g} deg steps")
        by_n.loglog(g["n"], g["error_in"], **style)
        by_time.loglog(g["seconds"], g["error_in"], **style)
    for ax, x in ((by_n, "n"), (by_time, "seconds")):
        ax.axhline(HALF_UNIT_IN, color="0.3", lw=1.0, ls=":", label=f"half the printed unit, {HALF_UNIT_IN:g} in")
        ax.set_ylim(bottom=1e-4)
        ax.set_xlabel(CASE3[x].label)
        ax.grid(alpha=0.3, which="both")
    by_n.set_ylabel(CASE3["error_in"].label)
    by_n.set_title("tip error against sub-elements n", y=1.0)   # no layout pass
    by_time.set_title("tip error against the port's wall time (after a warm-up call)", y=1.0)
    top_legend(fig, dict(zip(*reversed(by_n.get_legend_handles_labels()))), rows=2)
    coupled = data[data["model"] == "coupled"]
    most = coupled[coupled["n"] == coupled["n"].max()]
    listing = data[data["model"] == "listing"]["error_in"]
    slopes = sorted({round(float(np.polyfit(np.log(g["n"]), np.log(g["error_in"]), 1)[0]), 2)
                     for _, g in coupled.groupby("step_deg")})
    steps = sorted(data["step_deg"].unique())
    by_step = most.set_index("step_deg")
    per_n = data.groupby(["model", "n"])["error_in"]
    apart = float(((per_n.transform("max") - per_n.transform("min")) / per_n.transform("min")).max())
    caption = ("Case III, source four-bar: the largest error of the tip deflection (in) against the converged "
               "distributed-mass answer over a turn, against the extender's sub-elements n (left) and the port's "
               "wall time (right: the four-bar's kinematics plus the n-node model, each n timed after a warm-up "
               "call; this run's seconds). Colours are the input-angle steps, solid lines with dots the coupled "
               f"model, dashed lines with crosses the listing's; on the left the steps' lines "
               f"{'lie on one another' if apart < 0.1 else 'stand apart'} (at each n and model their errors differ "
               f"by {100 * apart:.0f} % at most). Measured: the coupled "
               "model's error falls as n to "
               f"the power {' to '.join(f'{x:.2f}' for x in dict.fromkeys([slopes[0], slopes[-1]]))} (a least-squares "
               f"slope per step), to {most['error_in'].min():.1e}-{most['error_in'].max():.1e} in at n = "
               f"{coupled['n'].max()}, against half the printed unit (dotted, {HALF_UNIT_IN:g} in); the listing's lies "
               f"between {listing.min():.2f} and {listing.max():.2f} in at every n. At n = {coupled['n'].max()} the "
               f"{steps[0]:g} deg step takes {by_step.at[steps[0], 'seconds'] / by_step.at[steps[-1], 'seconds']:.0f} "
               f"times the {steps[-1]:g} deg step's time.")
    save(fig, path, caption, **margins)


def table_model_needs() -> list[str]:
    """For each published table: how far its mass model (with the listings' other quirks
    removed) is from the converged distributed-mass answer, against its half unit."""
    deg = np.arange(0.0, 341.0, 20.0)
    linkage = case3_linkage(deg, quirks=CORRECTED)
    converged = _converged(linkage, 1600)
    candidates = [("Case I (2 lbf at the path point)", source_case1(deg, rpm=300.0, quirks=CORRECTED)),
                  ("Case I with the extender's weight at the path point",
                   source_case1(deg, rpm=300.0, mass_lbf=0.098 * 0.1963495408 * 10.0, quirks=CORRECTED))]
    candidates += [(f"Case III coupled, n = {n}", case3_on_linkage(linkage, n=n))
                   for n in (1, 5, 10, 20, 50, 100, 200, 400)]
    lines = ["## Which model is within the printed precision (0.0005 in) of the converged answer", "",
             "Source four-bar, rows 0-340, every listing bug removed (CORRECTED), the extender's own "
             "distributed weight as the load.", "", "| model | max abs error (in) | within 0.0005 in |", "|---|---|---|"]
    for label, out in candidates:
        err = _error(out, converged)
        lines.append(f"| {label} | {err:.2e} | {'yes' if err <= 0.0005 else 'no'} |")
    return lines


NAME = "ali1977-case3-convergence"
#: the scene's timings: best of 3 calls after a warm-up (one call is at the mercy of a busy machine)
RUN_REPEAT = 3
TITLE = "Ali (1977) Case III: speed against error of the distributed-mass model"


def run(out_dir: Path) -> None:
    """out/ali1977-case3-convergence/: case3_convergence.{csv,png} and report.md."""
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    data = case3_data(repeat=RUN_REPEAT)
    write_csv(data, target / "case3_convergence.csv", "%.6g")
    plot_case3(data, target / "case3_convergence.png")
    (target / "report.md").write_text(
        "# Case III: speed against error\n" + "\n".join(case3_sweep(RUN_REPEAT, data))
        + "\n\n![case3 convergence](case3_convergence.png)\n")


def overview(_) -> list[str]:
    return ["Sub-elements n and angle step against the converged distributed-mass answer, and which "
            "mass model each table needs (timings from this one run)."]


#: its own process, beside the tables (it is as long as they are)
SCENE = ReportScene(name=NAME, title=TITLE, group=NAME, start=3, produce=run, overview=overview)
