"""``linkrepro bench``: speed against error for each engine, from one run.

Times are the best of ``repeat`` runs (wall clock, this machine); compare the
ratios within one run, not absolute seconds across machines.
"""
from __future__ import annotations

import time

import numpy as np

from .. import legacy
from ..port import PRINTED, cognate_case1, source_case1
from .published_tables import PublishedTable
from .scenes import get


def _best(func, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        best = min(best, time.perf_counter() - start)
    return best


def run_bench(repeat: int = 20) -> str:
    if repeat < 1:
        raise ValueError("repeat must be >= 1")
    scene = get("ali1977-table1")
    published = PublishedTable.load(scene.table)
    pub, half = published.values[scene.columns], published.half_unit[scene.columns]
    lines = ["# linkrepro bench", "", f"Best of {repeat} runs; wall-clock seconds on this machine.", "",
             "## ali1977-table1: each engine alone, against Table I", "",
             "| engine | seconds | x legacy | cells within half a printed unit | max abs error (in) |",
             "|---|---|---|---|---|"]
    rows = []
    for engine in ("printed", "legacy", "port_printed", "port_corrected"):
        seconds = _best(lambda e=engine: scene.run(e), max(1, repeat // (4 if engine == "printed" else 1)))
        frame = scene.run(engine)[scene.columns]
        err = (frame - pub).abs().iloc[:, 1:]
        produced = err.notna()
        matched = int((err <= half.iloc[:, 1:] * (1 + 1e-9)).sum().sum())
        rows.append((engine, seconds, matched, int(produced.sum().sum()), float(np.nanmax(err.to_numpy()))))
    legacy_s = next(r[1] for r in rows if r[0] == "legacy")
    for engine, seconds, matched, produced, worst in rows:
        lines.append(f"| {engine} | {seconds:.5f} | {seconds / legacy_s:.2f} | {matched}/{produced} | {worst:.4g} |")
    lines += ["", "## Case I source + cognate over finer angle grids: legacy (f2py) vs port (numpy)", "",
              "The listing steps the angle by P2=P2+DSTEP in REAL*4, which drifts when the step is not a",
              "binary fraction; the port is given legacy's own angles, and the drift is shown apart.", "",
              "| step (deg) | angles | legacy s | port s | port / legacy | max diff / max value | REAL*4 angle drift (deg) |",
              "|---|---|---|---|---|---|---|"]
    for step in (20.0, 1.0, 0.1, 0.01):
        n = legacy.angle_grid(step)
        leg = legacy.case1_source(step_deg=step)
        deg = leg["deg"]
        t_leg = _best(lambda: (legacy.case1_source(step_deg=step), legacy.case1_cognate(step_deg=step)),
                      max(1, repeat // 4))
        t_port = _best(lambda: (source_case1(deg, quirks=PRINTED), cognate_case1(deg, quirks=PRINTED)),
                       max(1, repeat // 4))
        port = source_case1(deg, quirks=PRINTED)
        rel = max(float(np.max(np.abs(port[k] - leg[k])) / np.max(np.abs(leg[k]))) for k in ("dx", "dy", "rot"))
        drift = float(np.max(np.abs(deg - np.arange(n) * step)))
        lines.append(f"| {step:g} | {n} | {t_leg:.5f} | {t_port:.5f} | {t_port / t_leg:.2f} | {rel:.1e} | {drift:.2g} |")
    return "\n".join(lines) + "\n"
