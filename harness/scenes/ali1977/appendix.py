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

from ....legacy import ali1977
from ....port.ali1977 import PRINTED, cognate_case1, source_case1
from ....port.ali1977.case2 import LISTING as CASE2
from ....port.ali1977.case2 import COGNATE_LISTING as CASE2_COG
from ....port.ali1977.case2 import case2_cognate, case2_source
from ....port.ali1977.case3 import COGNATE_LISTING as CASE3_COG
from ....port.ali1977.case3 import LISTING as CASE3
from ....port.ali1977.case3 import case3_cognate, case3_source
from ...report import curve_figure, draw_all
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
    curves.to_csv(target / "curves.csv", index=False, float_format="%.9g")
    plots = _plot(curves, target)
    claims = _claims(curves)
    claims.to_csv(target / "claims.csv", index=False, float_format="%.9g")
    gap = _engine_gap(curves)
    (target / "report.md").write_text(_report(curves, claims, gap, timings, missing, plots))
    n_curves = curves.groupby(["case", "mechanism", "rpm", "quantity"]).ngroups
    return {"scene": NAME, "title": TITLE, "curves": n_curves, "missing": missing, "timings": timings,
            "max_engine_gap": gap}


def _plot(curves: pd.DataFrame, target: Path) -> list[Path]:
    """One PNG per case, mechanism and quantity: legacy and port at both speeds."""
    jobs = []
    for (case, mech, q), group in curves.groupby(["case", "mechanism", "quantity"], sort=False):
        lines = [(g["input_deg"].to_numpy(), g["value"].to_numpy(), f"{engine}, {rpm:g} rpm",
                  dict(ls="-", lw=1.5) if engine == "legacy" else dict(ls="--", lw=1.0, color="k"))
                 for (rpm, engine), g in group.groupby(["rpm", "engine"])]
        jobs.append((lines, KED["input_deg"].label, QUANTITIES[q].label,
                     f"Case {case}, {mech} four-bar: {QUANTITIES[q].words}", target / f"case{case}_{mech}_{q}.png"))
    return draw_all(curve_figure, jobs)


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
    lines += ["", "## Plots", ""] + [f"![{p.stem}]({p.name})" for p in plots]
    return "\n".join(lines) + "\n"


def overview(result: dict) -> list[str]:
    """The run report's line: curves produced, the largest engine gap, what is missing."""
    return [f"{result['curves']} of 36 curves, engine against engine (no published numbers); largest "
            f"|port - legacy| {result['max_engine_gap']:.3g}; "
            f"{', '.join(result['missing']) or 'every curve from both engines'}."]


SCENE = ReportScene(name=NAME, title=TITLE, group=GROUP, start=START, produce=run, overview=overview)
