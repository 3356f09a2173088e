"""``linkrepro bench``: speed against error for each engine, from one run.

Times are the best of ``repeat`` runs (wall clock, this machine); compare the
ratios within one run, not absolute seconds across machines.
"""
from __future__ import annotations

import time

import numpy as np

from .. import legacy
from ..port import PRINTED, cognate_case1, source_case1
from .case3_convergence import case3_sweep
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
    lines += case3_sweep(repeat)
    lines += cssp_bench(repeat)
    lines += gsc_bench(repeat)
    return "\n".join(lines) + "\n"


def cssp_bench(repeat: int) -> list[str]:
    """Rahman (1996): each engine alone over Tables 5.1-5.7, and the corrected model's
    cycle integral (eq. 4.1) against the number of positions L."""
    from ..port.cssp import CsspInputs, balance, solve_qp
    from ..port.cssp_data import Constants
    from ..port.cssp_mechanics import closed_loop_loads
    from ..port.cssp_objective import position_forms
    from ..port.cssp_quirks import CSSP_CORRECTED, CSSP_PRINTED
    from .scenes_rahman1996 import as_tables, printed_run

    def port(quirks):
        return balance(CsspInputs(), quirks=quirks)

    runs = {"printed": printed_run.__wrapped__, "legacy": legacy.cssp,
            "port_printed": lambda: port(CSSP_PRINTED), "port_corrected": lambda: port(CSSP_CORRECTED)}
    reference = legacy.cssp()
    lines = ["", "## rahman1996: each engine alone (one run gives Tables 5.1-5.7)", "",
             "| engine | seconds | x legacy | published cells within half a printed unit | max |diff| / column max vs legacy |",
             "|---|---|---|---|---|"]
    timings = {name: _best(func, max(1, repeat // 10)) for name, func in runs.items()}
    for name, func in runs.items():
        if name == "printed":
            lines.append(f"| printed | {timings[name]:.4f} | {timings[name] / timings['legacy']:.1f} | "
                         "(WRITEs only dint and crank I_xx) | |")
            continue
        run = func()
        matched = _cells_matched(as_tables(run))
        gap = float(np.max(np.abs(run["table"] - reference["table"]) / np.abs(reference["table"]).max(axis=0)))
        lines.append(f"| {name} | {timings[name]:.4f} | {timings[name] / timings['legacy']:.1f} | "
                     f"{matched}/456 | {gap:.1e} |")
    lines += ["", "## rahman1996, corrected model: the cycle integral of eq. (4.1) against the positions L", "",
              "Closed-loop model (D079), no listing bug; G-bar of the original masses and the QP's answer "
              "with L equal intervals, against L = 36000. The thesis uses L = 36 (the listing 37, D070).", "",
              "| L | seconds (loads + objective + QP) | rel. error of G-bar (before) | max rel. change of the QP answer |",
              "|---|---|---|---|"]
    c = Constants.of(CsspInputs(), False)

    def cycle(count):
        theta = np.arange(count) * (2 * np.pi / count)
        forms = position_forms(closed_loop_loads(c, theta), c, CSSP_CORRECTED, count).sum(axis=0)
        return float(c.point_masses @ forms @ c.point_masses), solve_qp(2 * forms, bounds=c.qp_bounds)[0]

    g_ref, x_ref = cycle(36000)
    for count in (12, 18, 36, 72, 360, 3600):
        seconds = _best(lambda: cycle(count), max(1, repeat // 10))
        g, x = cycle(count)
        lines.append(f"| {count} | {seconds:.4f} | {abs(g - g_ref) / g_ref:.1e} | {np.max(np.abs(x - x_ref) / x_ref):.1e} |")
    return lines


def gsc_bench(repeat: int) -> list[str]:
    """Rahman 1991: one configuration, 0..360 step 1, each engine; error against the
    complex-number analysis (planar) and against the exact closed loop (spatial)."""
    from ..port import gsc
    from ..port.gsc_data import GscInputs
    from ..port.gsc_quirks import GSC_CORRECTED, GSC_PRINTED
    from .planar_reference import analyse, in_thesis_frames
    lines = ["", "## rahman1991: one configuration, 361 crank angles, each engine", "",
             "Error: planar (a4 = 10) against the complex-number analysis, largest |difference| over the "
             "largest value of s4 and the forces (>= 2 deg from the dead centres); spatial (a4 = 30, S1 = 3.5) "
             "S4 against the exact closed loop (in).", "",
             "| configuration | engine | seconds | error |", "|---|---|---|---|"]
    fixed = GSC_PRINTED.without("com_beyond_joint", "joint_force_signs")
    engines = {"printed": GSC_PRINTED, "printed, sign bugs fixed": fixed, "corrected": GSC_CORRECTED}
    exact = gsc.analyse(GscInputs(a4=30.0, s1=3.5), quirks=GSC_CORRECTED).s4.to_numpy()
    ref = analyse(gsc.CRANK_DEG, a4=10.0, torque=-GscInputs().torque)
    away = np.abs(np.sin(ref["th_rod"] - ref["theta1"])) > 0.2 * np.sin(np.radians(2.0))
    for name, quirks in engines.items():
        for label, inputs in (("planar a4 = 10", GscInputs(a4=10.0)), ("spatial a4 = 30, S1 = 3.5", GscInputs(a4=30.0, s1=3.5))):
            runs = max(1, repeat // 10) if quirks.five_variable_loop else repeat
            seconds = _best(lambda: gsc.analyse(inputs, quirks=quirks), runs)
            frame = gsc.analyse(inputs, quirks=quirks)
            if inputs.s1 != 0.0 and not quirks.five_variable_loop:
                lines.append(f"| {label} | {name} | {seconds:.4f} | (the reference) |")
                continue
            if inputs.s1 == 0.0:
                error = max(float(np.nanmax(np.abs(frame[k].to_numpy() - v)[away]) / np.max(np.abs(v[away])))
                            for k, v in in_thesis_frames(ref).items())
            else:
                error = float(np.nanmax(np.abs(frame.s4.to_numpy() - exact)))
            lines.append(f"| {label} | {name} | {seconds:.4f} | {error:.3g} |")
    return lines


def _cells_matched(tables: dict) -> int:
    """How many of the 456 published Rahman cells these tables give to the printed digit."""
    count = 0
    for key, frame in tables.items():
        published = PublishedTable.load(f"rahman1996_table{key}")
        for col in ("before", "after"):
            err = np.abs(frame[col].to_numpy(float) - published.values[col].to_numpy(float))
            count += int(np.sum(err <= published.half_unit[col].to_numpy(float) * (1 + 1e-9)))
    return count
