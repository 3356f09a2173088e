"""Scene ali1977-appendixA: the Appendix A curves (input-link rotation against the
elastic deflections X, Y and rotation Z; source and cognate; Cases I-III; 300 and
400 rpm).  The thesis prints them only as graphs, so this scene compares engine
with engine (legacy against port, PRINTED quirks) and recomputes the two claims
chapter V makes about them.
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.colors import to_rgb

from ....legacy import ali1977
from ....port.ali1977 import PRINTED, cognate_case1, source_case1
from ....port.ali1977.case2 import LISTING as CASE2
from ....port.ali1977.case2 import COGNATE_LISTING as CASE2_COG
from ....port.ali1977.case2 import case2_cognate, case2_source
from ....port.ali1977.case3 import COGNATE_LISTING as CASE3_COG
from ....port.ali1977.case3 import LISTING as CASE3
from ....port.ali1977.case3 import case3_cognate, case3_source
from ...csv_output import FULL_PRECISION, write_csv
from ...figures import ENGINE_STYLE, save
from ...report import draw_all, panel_grid, top_legend, wrap_title
from ...scene import ReportScene
from .quantities import CURVES as QUANTITIES, KED
from .tables import GROUP, START

NAME = "ali1977-appendixA"
TITLE = "Ali (1977) Appendix A: elastic deflections against input-link rotation, 300 and 400 rpm"
SPEEDS = (300.0, 400.0)
STEP = 10.0
DEG = np.arange(0.0, 360.0 + 1e-9, STEP)

#: (case, mechanism) -> (legacy function, port function); the Case II cognate's missing page
#: and the whole Case III cognate are reconstructions (D037).
CURVES = {
    ("I", "source"): (lambda rpm: ali1977.case1_source(rpm=rpm, step_deg=STEP),
                      lambda rpm: source_case1(DEG, rpm=rpm, quirks=PRINTED)),
    ("I", "cognate"): (lambda rpm: ali1977.case1_cognate(rpm=rpm, step_deg=STEP),
                       lambda rpm: cognate_case1(DEG, rpm=rpm, quirks=PRINTED)),
    ("II", "source"): (lambda rpm: ali1977.case2_source(rpm=rpm, step_deg=STEP),
                       lambda rpm: case2_source(DEG, rpm=rpm, quirks=CASE2)),
    ("II", "cognate"): (lambda rpm: ali1977.case2_cognate(rpm=rpm, step_deg=STEP),
                        lambda rpm: case2_cognate(DEG, rpm=rpm, quirks=CASE2_COG)),
    ("III", "source"): (lambda rpm: ali1977.case3_source(rpm=rpm, step_deg=STEP),
                        lambda rpm: case3_source(DEG, rpm=rpm, quirks=CASE3)),
    ("III", "cognate"): (lambda rpm: ali1977.case3_cognate(rpm=rpm, step_deg=STEP),
                         lambda rpm: case3_cognate(DEG, rpm=rpm, quirks=CASE3_COG)),
}


def run(out_dir: Path) -> dict:
    """Write DIR/ali1977-appendixA/{curves.csv, *.png, report.md}; return counts and timings."""
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    rows, timings, missing = [], {"legacy": 0.0, "port_printed": 0.0}, []
    for (case, mech), engines in CURVES.items():
        if engines[0] is None:
            missing.append(f"legacy for Case {case} {mech} (port-only reconstruction)")
        for rpm in SPEEDS:
            for engine, func in zip(("legacy", "port_printed"), engines):
                if func is None:
                    continue
                start = time.perf_counter()
                out = func(rpm)
                timings[engine] += time.perf_counter() - start
                for q in QUANTITIES:
                    for deg, value in zip(DEG, out[q]):
                        rows.append((case, mech, rpm, engine, q, deg, float(value)))
    curves = pd.DataFrame(rows, columns=["case", "mechanism", "rpm", "engine", "quantity", "input_deg", "value"])
    write_csv(curves, target / "curves.csv", FULL_PRECISION)
    plots = _plot(curves, target)
    claims = _claims(curves)
    claims.to_csv(target / "claims.csv", index=False, float_format="%.9g")
    gap = _engine_gap(curves)
    (target / "report.md").write_text(_report(curves, claims, gap, timings, missing, plots))
    n_curves = curves.groupby(["case", "mechanism", "rpm", "quantity"]).ngroups
    return {"scene": NAME, "title": TITLE, "curves": n_curves, "missing": missing, "timings": timings,
            "max_engine_gap": gap}


def _plot(curves: pd.DataFrame, target: Path) -> list[Path]:
    """One figure per case, ``case1.png`` ... ``case3.png`` (reading order): a panel per
    mechanism (rows) and quantity (columns), both engines at both speeds in each."""
    cases = list(dict.fromkeys(curves["case"]))
    return draw_all(_draw_case, [(case, curves[curves["case"] == case], target / f"case{k}.png")
                                 for k, case in enumerate(cases, start=1)])


#: how much paler (towards white) the 300 rpm curves are than the engine's own colour
PALE = 0.55


def _style(engine: str, rpm: float) -> dict:
    """The engine's look (figures.ENGINE_STYLE), pale at the lower speed."""
    style = dict(ENGINE_STYLE[engine])
    if rpm == min(SPEEDS):
        style["color"] = tuple(c + PALE * (1.0 - c) for c in to_rgb(style["color"]))
    return style


def _draw_case(case: str, curves: pd.DataFrame, path: Path) -> Path:
    """Case ``case``'s figure: rows source and cognate, columns dx, dy, rot (in, in, rad)."""
    mechanisms = list(dict.fromkeys(curves["mechanism"]))
    fig, margins = panel_grid(12.0, len(QUANTITIES), len(mechanisms), 2.1,
                              f"Ali (1977) Appendix A, Case {case}: elastic deflections of the path point "
                              "against input-link rotation", title_lines=2)
    axes = fig.subplots(len(mechanisms), len(QUANTITIES), squeeze=False, sharex=True)
    for row, mech in zip(axes, mechanisms):
        for ax, q in zip(row, QUANTITIES):
            one = curves[(curves["mechanism"] == mech) & (curves["quantity"] == q)]
            for (rpm, engine), g in one.groupby(["rpm", "engine"], sort=False):
                ax.plot(g["input_deg"].to_numpy(), g["value"].to_numpy(), label=f"{engine}, {rpm:g} rpm",
                        **_style(engine, rpm))
            ax.set_title(wrap_title(f"{mech} four-bar: {QUANTITIES[q].words}", 3.0), y=1.0)   # no layout pass
            ax.set_ylabel(QUANTITIES[q].unit)
            ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel(KED["input_deg"].label)
    top_legend(fig, {label: h for ax in axes.flat for h, label in zip(*ax.get_legend_handles_labels())})
    low, high = _speed_ratio(curves)
    gap = _engine_gap(curves)
    caption = (f"Case {case}: the path point's deflection along x and y (in) and its rotation (rad) against "
               f"input-link rotation, source four-bar above, cognate below, at {SPEEDS[0]:g} rpm (pale) and "
               f"{SPEEDS[1]:g} rpm (strong colours). The port with the listings' quirks (dashed) "
               + ("lies on legacy's line: the two are equal at every point" if gap == 0 else
                  f"differs from legacy by {gap:.2g} at most (in or rad)")
               + f". Each {SPEEDS[1]:g} rpm curve is the {SPEEDS[0]:g} rpm one times {low:.5f} to {high:.5f} "
               f"(legacy, at every point where the {SPEEDS[0]:g} rpm value is over a thousandth of its curve's "
               f"largest), against ({SPEEDS[1]:g}/{SPEEDS[0]:g})^2 = {(SPEEDS[1] / SPEEDS[0]) ** 2:.5f}; where the "
               "largest deflections fall, against chapter V's 'second half of the cycle', is in the table above.")
    return save(fig, path, caption, **margins)


def _speed_ratio(curves: pd.DataFrame) -> tuple[float, float]:
    """The smallest and largest ratio of legacy's faster curve to its slower one, point by point,
    over the points where the slower curve's |value| exceeds a thousandth of its largest."""
    legacy = curves[curves["engine"] == "legacy"]
    wide = legacy.pivot_table(index=["mechanism", "quantity", "input_deg"], columns="rpm", values="value")
    slow, fast = wide[SPEEDS[0]], wide[SPEEDS[1]]
    largest = slow.abs().groupby(level=["mechanism", "quantity"]).transform("max")
    ratio = (fast / slow)[slow.abs() > 1e-3 * largest]
    return float(ratio.min()), float(ratio.max())


def _claims(curves: pd.DataFrame) -> pd.DataFrame:
    """Chapter V: (1) 100 rpm more nearly doubles the deflections; (2) the maxima fall in the
    second half of the cycle.  Per curve pair, legacy engine."""
    leg = curves[curves["engine"] == "legacy"]
    rows = []
    for (case, mech, q), g in leg.groupby(["case", "mechanism", "quantity"], sort=False):
        peak = {rpm: g[g["rpm"] == rpm].loc[lambda d: d["value"].abs().idxmax()] for rpm in SPEEDS}
        rows.append({"case": case, "mechanism": mech, "quantity": q,
                     "ratio_400_300": abs(peak[400.0]["value"]) / abs(peak[300.0]["value"]),
                     "peak_deg_300": peak[300.0]["input_deg"], "peak_deg_400": peak[400.0]["input_deg"],
                     "peak_in_second_half": bool(peak[300.0]["input_deg"] > 180 and peak[400.0]["input_deg"] > 180)})
    return pd.DataFrame(rows)


def _engine_gap(curves: pd.DataFrame) -> float:
    """Largest |port - legacy| over every curve point."""
    wide = curves.pivot_table(index=["case", "mechanism", "rpm", "quantity", "input_deg"],
                              columns="engine", values="value").reset_index().dropna()
    return float((wide["port_printed"] - wide["legacy"]).abs().max())


def _report(curves, claims, gap, timings, missing, plots) -> str:
    n = curves.groupby(["case", "mechanism", "rpm", "quantity"]).ngroups
    lines = [f"# {TITLE}", "", "No numbers are published for Appendix A: this scene compares engine with engine "
             "(legacy and port with the listings' quirks) and recomputes chapter V's two claims about the "
             "curves. Inputs: each listing as printed, the speed set to 300 and 400 rpm, angles every 10 deg.", "",
             f"- curves produced: {n} of 36; the Case II cognate's are its listing with the missing page "
             f"reconstructed, the Case III cognate's a reconstruction (D037); "
             f"not available: {', '.join(missing) or 'none'}",
             f"- largest |port - legacy| over all curve points: {gap:.3g}",
             f"- wall time: legacy {timings['legacy']:.3f} s, port {timings['port_printed']:.3f} s", "",
             "## Chapter V's claims, recomputed (legacy)", "",
             "1. 'with an increase of 100 rpm ... the elastic deflections were nearly doubled': the inertia loads "
             "grow as the speed squared, (400/300)^2 = 1.78.",
             "2. 'Maximum deflections occur in the second half of the cycle'.", "",
             "| case | mechanism | quantity | peak ratio 400/300 | peak at (deg) 300 / 400 rpm | second half |",
             "|---|---|---|---|---|---|"]
    for r in claims.itertuples():
        lines.append(f"| {r.case} | {r.mechanism} | {r.quantity} | {r.ratio_400_300:.3f} | "
                     f"{r.peak_deg_300:g} / {r.peak_deg_400:g} | {'yes' if r.peak_in_second_half else 'no'} |")
    lines += ["", "## Figures", ""] + [f"![{p.stem}]({p.name})" for p in plots]
    return "\n".join(lines) + "\n"


def overview(result: dict) -> list[str]:
    """The run report's line: curves produced, the largest engine gap, what is missing."""
    return [f"{result['curves']} of 36 curves, engine against engine (no published numbers); largest "
            f"|port - legacy| {result['max_engine_gap']:.3g}; "
            f"{', '.join(result['missing']) or 'every curve from both engines'}."]


SCENE = ReportScene(name=NAME, title=TITLE, group=GROUP, start=START, produce=run, overview=overview)
