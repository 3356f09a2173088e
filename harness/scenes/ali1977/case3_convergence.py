"""The Case III convergence study: sub-elements n and angle step against the converged tip
deflection, with time, and which mass model each Ali (1977) table needs.

``reproduce`` writes it as scene ali1977-case3-convergence (case3_convergence.{csv,png}, report.md);
``linkrepro bench`` prints it.
Times are wall-clock seconds of this run (best of ``repeat``).
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
    """(the best wall-clock seconds of ``repeat`` calls of ``func``, the result of the last)."""
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
    time (s, best of ``repeat``) and max |tip dx, dy - converged| (in).  Converged: the
    coupled model at reference_n/2 and reference_n, Richardson-extrapolated.  The four-bar's
    kinematics are computed once per angle grid and model (case3_linkage) and reused for
    every n (case3_on_linkage); a row's time is theirs plus its n-node model's."""
    rows = []
    models = {"coupled": CORRECTED, "listing": CASE3_LISTING.without("real4_storage")}
    for quirks in models.values():         # the compiled kernels loaded (numba's cache) before any timing
        case3_on_linkage(case3_linkage([0.0], quirks=quirks), n=2)
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
    """The sweep as markdown, and which model each table needs."""
    data = case3_data(max(1, repeat // 10)) if data is None else data
    lines = ["", "## Case III: sub-elements n and angle step, against the converged tip deflection", "",
             "Error: max |tip dx, dy - converged| (in) over 0-360 at the step; converged = Richardson "
             "extrapolation of the coupled model at n = 1600, 3200. Port timed for every n (the four-bar's "
             "kinematics, computed once per angle grid and model, and the n-node model on them); legacy (the "
             "listing, n = 5, uncoupled) where the printed structure allows.", "",
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


def plot_case3(data: pd.DataFrame, path) -> None:
    """Error against n and against time, per angle step and model."""
    from matplotlib.figure import Figure
    from ...report import save_png
    fig = Figure(figsize=(10, 3.8))
    left, right = fig.subplots(1, 2)
    for (step, model), g in data.groupby(["step_deg", "model"]):
        style = "-o" if model == "coupled" else "--x"
        label = f"{model} model, {step:g} deg steps"
        left.loglog(g["n"], g["error_in"], style, ms=3, label=label)
        right.loglog(g["seconds"], g["error_in"], style, ms=3, label=label)
    for ax, x in ((left, "n"), (right, "seconds")):
        ax.axhline(0.0005, color="gray", lw=0.8, ls=":")
        ax.set_ylim(bottom=1e-4)
        ax.set_xlabel(CASE3[x].label)
        ax.set_ylabel(CASE3["error_in"].label)
        ax.grid(alpha=0.3, which="both")
    left.legend(fontsize=7)
    left.set_title("Case III: tip error against sub-elements (dotted: half the printed unit)", fontsize=9)
    right.set_title("Case III: tip error against the port's wall time", fontsize=9)
    save_png(fig, path, left=0.078, right=0.985, bottom=0.16, top=0.91, wspace=0.187)


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
TITLE = "Ali (1977) Case III: speed against error of the distributed-mass model"


def run(out_dir: Path) -> None:
    """out/ali1977-case3-convergence/: case3_convergence.{csv,png} and report.md."""
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    data = case3_data(repeat=1)
    write_csv(data, target / "case3_convergence.csv", "%.6g")
    plot_case3(data, target / "case3_convergence.png")
    (target / "report.md").write_text(
        "# Case III: speed against error\n" + "\n".join(case3_sweep(1, data))
        + "\n\n![case3 convergence](case3_convergence.png)\n")


def overview(_) -> list[str]:
    return ["Sub-elements n and angle step against the converged distributed-mass answer, and which "
            "mass model each table needs (timings from this one run)."]


#: its own process, beside the tables (it is as long as they are)
SCENE = ReportScene(name=NAME, title=TITLE, group=NAME, start=2, produce=run, overview=overview)
