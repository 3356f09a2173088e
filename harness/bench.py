"""``linkrepro bench``: speed against error for every scene, from one run.

Two parts, printed as markdown and written to ``--out`` (bench.md, bench.png, bench.csv):

1. **Cost per position** of each computation (K.E.D. Cases I-III, the tables' 19 angles and
   3,601 angles; the CSSP balance of Tables 5.1-5.7; the 1991 printed Newton; the 1991
   corrected closed loop) for legacy (the FORTRAN through f2py), the port with the listing's
   bugs and the port corrected, against a flop-count limit: a hand count of the floating-point
   operations per position of the listing's algorithm (the constants ``KED_*``, ``NEWTON_*``,
   ``CSSP_*``, ... below, good to a factor of two) at ``FLOP_RATE``.  The ratios port/legacy
   and legacy/limit are the result.
2. **Speed against error** for each knob that trades one for the other (the angle step, Case
   III's sub-elements and mass rule, the Newton's tolerance and iteration cap, REAL*4 against
   double precision): the error against a converged reference, the time, and the Pareto front
   (the settings no other setting beats in both).

Times: ``time.perf_counter``, best of ``repeat`` calls, the engines of one computation (or
the settings of one knob) taken in turn within each round so that the machine's load falls on
all alike; every ``functools.lru_cache`` of ``linkrepro.port`` is cleared before each call
(a repeat measures the work, not a cache); every result shown is that of a timed call.  Read
the ratios, not the seconds: the machine is shared.  Units: seconds, microseconds (us) per
position, inches and radians for the errors unless a knob says otherwise.  What it is doing
shows on stderr's progress line (``harness/progress``) when stderr is a terminal.
"""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd

from ..legacy import ali1977, rahman1996
from ..port.ali1977 import CORRECTED, PRINTED, cognate_case1, source_case1
from ..port.rahman1991 import analysis, position as gsc_position
from ..port.ali1977 import case2, case3
from ..port.rahman1996.balance import CRANK_DEG, CsspInputs, balance, solve_qp
from ..port.rahman1996.data import Constants
from ..port.rahman1996.mechanics import closed_loop_loads, kinematics
from ..port.rahman1996.objective import position_forms
from ..port.rahman1996.quirks import CSSP_CORRECTED, CSSP_PRINTED
from ..port.rahman1991.data import GscInputs
from ..port.rahman1991.quirks import GSC_CORRECTED, GSC_PRINTED
from . import progress
from .scenes.ali1977.case3_convergence import case3_data

#: the port's package (linkrepro.port), whose caches are cleared before each timed call
PORT = __name__.split(".")[0] + ".port"
ENGINES = ("legacy", "port_printed", "port_corrected")
#: the files the bench writes into its output folder
OUTPUTS = ("bench.md", "bench.png", "bench.csv")
#: the columns of bench.csv, one row per engine of a computation or per setting of a knob
COLUMNS = ["kind", "subject", "setting", "engine", "positions", "seconds", "us_per_position",
           "flops_per_position", "error", "error_unit", "reference", "pareto", "note"]

# ------------------------------------------------------------------ the flop-count limit

#: the rate of the limit (flop/s): one core's scalar peak, 4 double-precision additions and
#: multiplications a cycle (two pipes each, no SIMD, no fused multiply-add: the FORTRAN is built
#: with -ffp-contract=off) at 2.5 GHz.  (At 1 GFLOP/s the CSSP legacy build beats the "limit".)
FLOP_RATE = 1e10
#: flops charged for one sin, cos, atan or sqrt (a libm call)
TRANSCENDENTAL = 20


def mprd(n: int, m: int, l: int) -> int:
    """Flops of an (n x m)(m x l) matrix product formed densely, as MPRD and MULTI do."""
    return 2 * n * m * l


#: four-bar position (half-angle), velocity, acceleration, beta by Cramer's rule (statements
#: 14-106): sin, cos of t2, t3, t4, t3+alp, t4-t3, t2-t3, two sqrt, two atan; ~190 + - * /
KED_KINEMATICS = 16 * TRANSCENDENTAL + 190
#: Case I, one mechanism: delta = beta' F beta P (3x8, 8x8, 8x3, 3x1) as the listing's MPRDs
KED_CASE1 = KED_KINEMATICS + mprd(3, 8, 8) + mprd(3, 8, 3) + mprd(3, 3, 1)
#: Case II, one mechanism: 40 flops of joint loads; beta' F beta2 P (3x8, 8x8, 8x8, 8x1)
KED_CASE2 = KED_KINEMATICS + 40 + mprd(3, 8, 8) + mprd(3, 8, 8) + mprd(3, 8, 1)
#: Case III source: five node blocks (~15 flops each) into the dense beta* (40x15) and F*
#: (40x40); the listing multiplies beta*' F* (15x40x40), then beta* (15x40x15) twice (its
#: second MPRD with the loads keeps N=15, M=40, L=15), then the loads (15x15x1)
KED_CASE3_SOURCE = KED_KINEMATICS + 5 * 15 + mprd(15, 40, 40) + 2 * mprd(15, 40, 15) + mprd(15, 15, 1)
#: one step of the spatial Newton (spatial_newton.newton): sin, cos of five angles, 13 dual
#: 3x3 products (three products and a sum each), ~60 for the entries; A'A, its 5x5 inverse
#: (2 n^3), (A'A)^-1 A', Delta
NEWTON_STEP = (10 * TRANSCENDENTAL + 13 * (3 * mprd(3, 3, 3) + 9) + 60 + mprd(5, 6, 5) + 2 * 5 ** 3
               + mprd(5, 5, 6) + mprd(5, 6, 1))
#: the listing's DOT, DDOT (spatial_newton.rates): six sin/cos, the pseudo-inverse of VM, two
#: products, ~120 for VV and AV
NEWTON_RATES = 6 * TRANSCENDENTAL + mprd(5, 6, 5) + 2 * 5 ** 3 + mprd(5, 5, 6) + 2 * mprd(5, 6, 1) + 120
#: CSSP, per position and pass: the unit loads of 9 point masses (~300 each, frames, forces,
#: moments, reactions) and the 9x9 forms of eq. (4.2) from 10 load vectors (9x3 each)
CSSP_LOADS = 9 * 300 + 10 * mprd(9, 3, 9)
#: CSSP, per position: the tables before and after (10 weighted sums of 9x3, norms); the QP of
#: 9 masses (~20 active-set steps of ~1000 flops, twice) shared by the 37 positions
CSSP_TABLES = 2 * (10 * mprd(9, 3, 1) + 30) + 2 * 20 * 1000 // 37
#: the closed loop with second-order jets (cssp_mechanics.kinematics): ~10 sin/cos/sqrt/atan2,
#: ~60 jet operations of 9 flops, R2 as two 3x3 products of jets
CLOSED_LOOP = 10 * TRANSCENDENTAL + 60 * 9 + 2 * 27 * 9 * 2
#: the corrected Newton-Euler of the 1991 model (gsc_forces.corrected_forces): ~12 cross
#: products, ~150 more
GSC_FORCES = 12 * 9 + 150


def cssp_flops(newton_steps: float) -> float:
    """Flops per position of the CSSP program: two passes of Newton, rates, loads and forms."""
    return 2 * (newton_steps * NEWTON_STEP + NEWTON_RATES + CSSP_LOADS) + CSSP_TABLES


# ------------------------------------------------------------------ timing

def clear_port_caches() -> None:
    """Clear every functools cache of linkrepro.port (so that a repeat does the work again)."""
    for name, module in list(sys.modules.items()):
        if not name.startswith(PORT):
            continue
        for value in list(vars(module).values()):
            if hasattr(value, "cache_clear") and str(getattr(value, "__module__", "")).startswith(name):
                value.cache_clear()


def timed(funcs: dict[str, Callable], repeat: int) -> dict[str, tuple[float, object]]:
    """{name: (best seconds of ``repeat`` calls, the result of the last call)}; each round
    calls every function once, in turn, with the port's caches cleared before each call."""
    best = {name: float("inf") for name in funcs}
    results = {}
    for _ in range(repeat):
        for name, func in funcs.items():
            clear_port_caches()
            start = time.perf_counter()
            results[name] = func()
            best[name] = min(best[name], time.perf_counter() - start)
    return {name: (best[name], results[name]) for name in funcs}


def _step(what: str, func: Callable):
    """func(), shown as ``what`` on the progress line (stderr, when it is a terminal)."""
    progress.note("bench", what)
    result = func()
    progress.done("bench")
    return result


# ------------------------------------------------------------------ part 1: cost per position

@dataclass
class Computation:
    """One computation timed on each engine.  ``engines``: name -> call (absent: the engine
    does not exist); ``flops(results)``: the limit's flops per position; ``agreement(legacy,
    port_printed)``: how far the port with the bugs is from legacy (a relative number)."""
    name: str
    positions: int
    engines: dict[str, Callable]
    flops: Callable[[dict], float]
    agreement: Callable | None = None
    legacy_positions: int | None = None     # positions the legacy call solves, if not ``positions``
    note: str = ""


def _ked_pair(out: tuple) -> np.ndarray:
    """dx, dy of source and cognate, stacked."""
    return np.stack([part[k] for part in out for k in ("dx", "dy")])


def _relative(a: np.ndarray, b: np.ndarray) -> float:
    """max |a - b| / max |b|."""
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


#: per K.E.D. case: legacy (source, cognate), port (source, cognate), the listings' quirks,
#: the flops per angle (source + cognate)
KED = {
    "I": ((ali1977.case1_source, ali1977.case1_cognate), (source_case1, cognate_case1), (PRINTED, PRINTED),
          2 * KED_CASE1),
    "II": ((ali1977.case2_source, ali1977.case2_cognate), (case2.case2_source, case2.case2_cognate),
           (case2.LISTING, case2.COGNATE_LISTING), 2 * KED_CASE2),
    "III": ((ali1977.case3_source, ali1977.case3_cognate), (case3.case3_source, case3.case3_cognate),
            (case3.LISTING, case3.COGNATE_LISTING), KED_CASE3_SOURCE + KED_CASE1),
}


def ked_computation(case: str, step: float) -> Computation:
    """K.E.D. Case I, II or III, source and cognate, at the listings' angle step (deg); the port
    is given the listings' own angles (their REAL*4 P2=P2+DSTEP drifts), read once untimed."""
    (leg_src, leg_cog), (src, cog), listing, flops = KED[case]
    deg = ali1977.case1_source(step_deg=step)["deg"]

    def port(quirks):
        return lambda: (src(deg, quirks=quirks & listing[0]), cog(deg, quirks=quirks & listing[1]))
    engines = {"legacy": lambda: (leg_src(step_deg=step), leg_cog(step_deg=step)),
               "port_printed": port(PRINTED), "port_corrected": port(CORRECTED)}
    note = ("port corrected: the coupled model with n = 5 (another algorithm); limit: the listing's dense "
            "40 x 40 products" if case == "III" else "")
    return Computation(f"K.E.D. Case {case}, source + cognate, {len(deg)} angles", len(deg), engines,
                       lambda _: flops, lambda leg, prt: _relative(_ked_pair(prt), _ked_pair(leg)), note=note)


#: Rahman (1991): the spatial configuration of section 3.1 where the 1996 build runs a full turn
GSC_SPATIAL = GscInputs(a4=30.0, s1=3.5)
#: its Newton's converged reference (every |Delta| <= 1e-13)
CONVERGED = gsc_position.NewtonSetup(tol=1e-13)


def _legacy_on(inputs: CsspInputs) -> Callable:
    """The 1996 legacy build (the whole CSSP program) on this geometry."""
    return lambda: rahman1996.cssp(a1=inputs.a1, a2=inputs.a2, a4=inputs.a4, alpha4_deg=inputs.alpha4_deg,
                                   s1=inputs.s1, rpm=inputs.rpm)


def _cssp_newton_steps() -> float:
    """Mean Newton steps per position of the CSSP listing's first pass (the port's replica of
    the build's arithmetic, ``BUILD_1996``; untimed: an input of the flop count only)."""
    inputs = GscInputs(**{k: getattr(CsspInputs(), k) for k in ("a1", "a2", "a4", "alpha4_deg", "s1", "rpm")})
    run = gsc_position.positions(inputs, np.radians(CRANK_DEG), use_dfp=False, setup=gsc_position.BUILD_1996)
    return float(run.iterations.mean())


def rahman_computations() -> list[Computation]:
    """The CSSP balance (1996) and the 1991 printed Newton and corrected closed loop."""
    steps = _cssp_newton_steps()
    th10, th1 = np.radians(CRANK_DEG), np.radians(analysis.CRANK_DEG)
    closed = lambda: kinematics(GSC_SPATIAL, th10, np.stack(GSC_SPATIAL.axial(th10)))   # noqa: E731
    return [
        Computation("CSSP balance, Tables 5.1-5.7", len(CRANK_DEG),
                    {"legacy": rahman1996.cssp, "port_printed": lambda: balance(CsspInputs(), CSSP_PRINTED),
                     "port_corrected": lambda: balance(CsspInputs(), CSSP_CORRECTED)},
                    lambda _: cssp_flops(steps), lambda leg, prt: float(np.max(
                        np.abs(prt["table"] - leg["table"]) / np.abs(leg["table"]).max(axis=0))),
                    note=f"two Newton passes of {steps:.1f} steps a position (the listing's first pass)"),
        Computation("Rahman 1991 Newton, a4 = 30, S1 = 3.5, 10-deg steps", len(th10),
                    {"legacy": _legacy_on(GSC_SPATIAL),
                     "port_printed": lambda: gsc_position.positions(GSC_SPATIAL, th10, setup=gsc_position.THESIS_1991),
                     "port_corrected": closed},
                    lambda r: float(r["port_printed"].iterations.mean()) * NEWTON_STEP,
                    lambda leg, prt: _relative(prt.q, leg["positions"][0]), legacy_positions=2 * len(th10),
                    note="legacy: the whole 1996 program (two Newton passes, rates, loads, QP) over its "
                         f"{2 * len(th10)} Newton solves, an upper bound on its Newton; port corrected: the "
                         "closed loop's positions and rates"),
        Computation("Rahman 1991 positions, rates, joint forces, 361 angles", len(th1),
                    {"port_printed": lambda: analysis.analyse(GSC_SPATIAL, quirks=GSC_PRINTED),
                     "port_corrected": lambda: analysis.analyse(GSC_SPATIAL, quirks=GSC_CORRECTED)},
                    lambda _: CLOSED_LOOP + GSC_FORCES,
                    note="no program exists (the 1991 thesis prints none); limit: the corrected closed loop"),
    ]


def computations(quick: bool) -> list[Computation]:
    """Every computation of part 1 (``quick``: the tables' 19 angles only)."""
    steps = (20.0,) if quick else (20.0, 0.1)
    return [ked_computation(case, step) for step in steps for case in KED] + rahman_computations()


def warm_up() -> None:
    """Call every engine once on the tables' angles, untimed: numba compiles (or loads) its
    kernels at their first call, which a timing must not see."""
    for comp in computations(quick=True):
        for func in comp.engines.values():
            func()


def cost_rows(comp: Computation, repeat: int) -> list[dict]:
    """The computation's rows of bench.csv: one per engine and one for the limit."""
    runs = timed(comp.engines, repeat)
    flops = comp.flops({name: result for name, (_, result) in runs.items()})
    rows = []
    for engine in ENGINES:
        if engine not in runs:
            continue
        seconds, result = runs[engine]
        positions = comp.legacy_positions if engine == "legacy" and comp.legacy_positions else comp.positions
        agrees = (comp.agreement(runs["legacy"][1], result)
                  if engine == "port_printed" and comp.agreement and "legacy" in runs else np.nan)
        rows.append(dict(kind="cost", subject=comp.name, engine=engine, positions=positions, seconds=seconds,
                         us_per_position=1e6 * seconds / positions, flops_per_position=flops, error=agrees,
                         error_unit="max |port - legacy| / max |legacy|" if np.isfinite(agrees) else "",
                         note=comp.note))
    rows.append(dict(kind="cost", subject=comp.name, engine="limit", positions=comp.positions,
                     seconds=flops * comp.positions / FLOP_RATE, us_per_position=1e6 * flops / FLOP_RATE,
                     flops_per_position=flops, note=f"{flops:.0f} flops a position at {FLOP_RATE:.0e} flop/s"))
    return rows


# ------------------------------------------------------------------ part 2: knobs

@dataclass
class Knob:
    """Settings of one knob (label -> call), the one taken as converged (``reference``),
    ``error(result, reference_result)`` -> (error, note), np.inf with a note where a setting
    fails, and ``positions(result)``: the positions one call computes."""
    name: str
    engine: str
    unit: str
    what: str
    settings: dict[str, Callable]
    reference: str
    error: Callable[[object, object], tuple[float, str]]
    positions: Callable[[object], int]


def _peak_deflection(out: tuple) -> np.ndarray:
    """Largest |deflection| (in) over the cycle, source and cognate."""
    return np.array([np.max(np.hypot(part["dx"], part["dy"])) for part in out])


def _case1(deg: np.ndarray, quirks) -> Callable:
    return lambda: (deg, source_case1(deg, quirks=quirks), cognate_case1(deg, quirks=quirks))


def _grid(step: float) -> np.ndarray:
    """0, step, ... up to 360 deg."""
    return np.arange(0.0, 360.0 + 1e-9, step)


def _label(step: float) -> str:
    return f"{step:g} deg"


def ked_step_knob(steps: tuple) -> Knob:
    """K.E.D. Case I (corrected), source and cognate: the angle step against the peak deflection."""
    return Knob("K.E.D. angle step", "port_corrected", "in",
                "Case I corrected, source and cognate: largest |deflection| over the cycle, against the finest step",
                {_label(s): _case1(_grid(s), CORRECTED) for s in steps}, _label(steps[-1]),
                lambda r, ref: (float(np.max(np.abs(_peak_deflection(r[1:]) - _peak_deflection(ref[1:])))), ""),
                lambda r: len(r[0]))


def _newton_error(measure: Callable) -> Callable:
    """error(run, ref): largest |measure(run) - measure(ref)| of two ``PositionRun``s; inf, with
    a note, where the run failed at some position."""
    def error(run, ref) -> tuple[float, str]:
        failed = int(np.sum(~run.converged))
        if failed:
            return np.inf, f"failed at {failed} of {run.converged.size} positions"
        return float(np.max(np.abs(measure(run) - measure(ref)))), ""
    return error


#: joint variables theta2, eta2, theta3, eta3 (rad), S4 (in) at every position
_q_error = _newton_error(lambda run: run.q)
#: the slider's stroke, max S4 - min S4 over the turn (in)
_stroke_error = _newton_error(lambda run: np.ptp(run.q[:, 4]))


def _newton(theta1: np.ndarray, setup, use_dfp: bool = True) -> Callable:
    return lambda: gsc_position.positions(GSC_SPATIAL, theta1, use_dfp=use_dfp, setup=setup)


def _positions(run) -> int:
    return run.q.shape[0]


def newton_knobs(steps: tuple, tols: tuple, caps: tuple) -> list[Knob]:
    """The 1991 printed Newton (a4 = 30, S1 = 3.5): angle step, tolerance, iteration cap, REAL*4."""
    th10 = np.radians(CRANK_DEG)
    cap_ref = gsc_position.THESIS_1991.max_iterations
    precision = {"double, |Delta| <= 1e-13": CONVERGED, "double, |Delta| <= 1e-7": gsc_position.THESIS_1991,
                 "REAL*4, |Delta| <= 1e-7": gsc_position.NewtonSetup(real4=True)}
    return [
        Knob("1991 angle step", "port_printed", "in",
             "printed Newton from the last answer: the slider's stroke (max - min S4), against the finest step",
             {_label(s): _newton(np.radians(_grid(s)), gsc_position.THESIS_1991) for s in steps},
             _label(steps[-1]), _stroke_error, _positions),
        Knob("1991 Newton tolerance", "port_printed", "in, rad",
             "10-deg steps: largest |q - q_ref| over theta2, eta2, theta3, eta3 (rad), S4 (in)",
             {f"{t:g}": _newton(th10, gsc_position.NewtonSetup(tol=t)) for t in tols}, f"{tols[-1]:g}",
             _q_error, _positions),
        Knob("1991 Newton iteration cap", "port_printed", "in, rad",
             "10-deg steps, |Delta| <= 1e-7, Newton alone (no DFP fallback): largest |q - q_ref|, against "
             f"the listing's {cap_ref}",
             {f"{c}": _newton(th10, gsc_position.NewtonSetup(max_iterations=c), use_dfp=False) for c in caps},
             f"{cap_ref}", _q_error, _positions),
        Knob("1991 Newton precision", "port_printed", "in, rad",
             "10-deg steps: largest |q - q_ref| against double precision converged to 1e-13",
             {label: _newton(th10, setup) for label, setup in precision.items()}, next(iter(precision)),
             _q_error, _positions),
    ]


def cssp_cycle(count: int) -> tuple[int, float, np.ndarray]:
    """The corrected CSSP model over ``count`` equal intervals of the turn: (count, its cycle
    integral G-bar of eq. (4.1) for the original masses, the QP's masses in lb*s^2/in)."""
    c = Constants.of(CsspInputs(), False)
    theta = np.arange(count) * (2 * np.pi / count)
    forms = position_forms(closed_loop_loads(c, theta), c, CSSP_CORRECTED, count).sum(axis=0)
    return count, float(c.point_masses @ forms @ c.point_masses), solve_qp(2 * forms, bounds=c.qp_bounds)[0]


def _table_error(out, ref) -> tuple[float, str]:
    """Largest |table - table_ref| over each column's largest |value| (Tables 5.2-5.7)."""
    return float(np.max(np.abs(out["table"] - ref["table"]) / np.abs(ref["table"]).max(axis=0))), ""


def other_knobs(counts: tuple) -> list[Knob]:
    """The CSSP positions L, and REAL*4 against double for K.E.D. and the CSSP."""
    deg = _grid(0.1)
    return [
        Knob("CSSP positions L", "port_corrected", "relative",
             "corrected model: |G-bar - G-bar_ref| / G-bar_ref of the original masses, eq. (4.1) with L equal "
             "intervals (the thesis: 36), loads + objective + QP",
             {f"L = {n}": (lambda n=n: cssp_cycle(n)) for n in counts}, f"L = {counts[-1]}",
             lambda r, ref: (abs(r[1] - ref[1]) / ref[1], ""), lambda r: r[0]),
        Knob("K.E.D. precision", "port_corrected", "in",
             f"Case I corrected, {len(deg)} angles: largest |deflection - double's| (source and cognate)",
             {"double": _case1(deg, CORRECTED), "REAL*4 storage": _case1(deg, CORRECTED.only("real4_storage", True))},
             "double", lambda r, ref: (float(np.max(np.abs(_ked_pair(r[1:]) - _ked_pair(ref[1:])))), ""),
             lambda r: len(r[0])),
        Knob("CSSP precision", "port_corrected", "relative",
             "corrected model, Tables 5.2-5.7: largest |difference| / column's largest value, against double",
             {"double": lambda: balance(CsspInputs(), CSSP_CORRECTED),
              "REAL*4 constants": lambda: balance(CsspInputs(), CSSP_CORRECTED.only("cssp_real4", True))},
             "double", _table_error, lambda r: len(CRANK_DEG)),
    ]


def knob_rows(knob: Knob, repeat: int) -> list[dict]:
    """The knob's rows of bench.csv, one per setting, with the Pareto front marked."""
    runs = timed(knob.settings, repeat)
    reference = runs[knob.reference][1]
    rows = []
    for label, (seconds, result) in runs.items():
        error, note = knob.error(result, reference)
        positions = knob.positions(result)
        rows.append(dict(kind="knob", subject=knob.name, setting=label, engine=knob.engine, positions=positions,
                         seconds=seconds, us_per_position=1e6 * seconds / positions if positions else np.nan,
                         error=error, error_unit=knob.unit, reference=label == knob.reference, note=note))
    return _with_front(rows)


CASE3 = "Case III sub-elements n and mass rule"
CASE3_WHAT = ("tip deflection, max |dx, dy - converged| over the turn at 20, 10 and 1 deg, the converged answer "
              "the coupled model Richardson-extrapolated from n = 1600, 3200 (harness/case3_convergence); "
              "coupled: port corrected; listing: the listing's mass rule, uncoupled")


def case3_rows(repeat: int) -> list[dict]:
    """Case III's sweep (harness/case3_convergence.case3_data): n and the mass rule at three
    angle steps, against the converged coupled model."""
    rows = [dict(kind="knob", subject=CASE3, setting=f"n = {r.n}, {r.model}, {r.step_deg:g} deg",
                 engine="port_corrected" if r.model == "coupled" else "port_listing_model",
                 positions=len(_grid(r.step_deg)), seconds=r.seconds,
                 us_per_position=1e6 * r.seconds / len(_grid(r.step_deg)), error=r.error_in, error_unit="in",
                 reference=False, note="")
            for r in case3_data(repeat).itertuples()]
    return _with_front(rows)


def pareto_front(seconds, errors) -> np.ndarray:
    """True for the points no other point beats: none as fast or faster and as accurate or more,
    better in one.  A non-finite error (a failed setting) is never on the front."""
    t, e = np.asarray(seconds, dtype=float), np.asarray(errors, dtype=float)
    ok = np.isfinite(t) & np.isfinite(e)
    front = np.zeros(t.size, dtype=bool)
    for i in np.flatnonzero(ok):
        beaten = ok & (t <= t[i]) & (e <= e[i]) & ((t < t[i]) | (e < e[i]))
        front[i] = not beaten.any()
    return front


def _with_front(rows: list[dict]) -> list[dict]:
    front = pareto_front([r["seconds"] for r in rows], [r["error"] for r in rows])
    return [{**row, "pareto": bool(on)} for row, on in zip(rows, front)]


def knobs(quick: bool) -> list[Knob]:
    """Every knob of part 2 but Case III's (``quick``: three settings each)."""
    if quick:
        return [ked_step_knob((20.0, 5.0, 1.0)), *newton_knobs((30.0, 10.0, 5.0), (1e-2, 1e-7, 1e-13), (10, 20, 150)),
                *other_knobs((6, 12, 72))]
    return [ked_step_knob((20.0, 10.0, 5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01)),
            *newton_knobs((45.0, 30.0, 20.0, 10.0, 5.0, 2.0, 1.0, 0.5, 0.25),
                          (1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13), (5, 8, 10, 15, 20, 30, 150)),
            *other_knobs((6, 9, 12, 18, 24, 36, 72, 360))]


# ------------------------------------------------------------------ output

def _us(value: float) -> str:
    return "" if not np.isfinite(value) else f"{value:.3g}"


def _ratio(a: float, b: float) -> str:
    return f"{a / b:.3g}" if np.isfinite(a) and np.isfinite(b) and b > 0 else ""


def cost_table(rows: pd.DataFrame) -> list[str]:
    """Part 1 as markdown: one line per computation, then its notes."""
    lines = ["| computation | positions | legacy us | port (bugs) us | port corrected us | limit us (flops) | "
             "port (bugs) / legacy | port corrected / legacy | legacy / limit | port corrected / limit | "
             "port (bugs) vs legacy |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    notes = []
    for name, g in rows.groupby("subject", sort=False):
        us = dict(zip(g.engine, g.us_per_position))
        legacy_us, printed, corrected, limit = (us.get(e, np.nan) for e in (*ENGINES, "limit"))
        agree = g.error[g.engine == "port_printed"].dropna()
        lines.append(f"| {name} | {g.positions.iloc[-1]} | {_us(legacy_us)} | {_us(printed)} | {_us(corrected)} | "
                     f"{_us(limit)} ({g.flops_per_position.iloc[0]:.3g}) | {_ratio(printed, legacy_us)} | "
                     f"{_ratio(corrected, legacy_us)} | {_ratio(legacy_us, limit)} | {_ratio(corrected, limit)} | "
                     f"{f'{agree.iloc[0]:.1e}' if len(agree) else ''} |")
        notes += [f"- {name}: {g.note.iloc[0]}."] if isinstance(g.note.iloc[0], str) and g.note.iloc[0] else []
    return lines + [""] + notes


def knob_tables(rows: pd.DataFrame, descriptions: dict[str, str]) -> list[str]:
    """Part 2 as markdown: one table per knob."""
    lines = []
    for name, g in rows.groupby("subject", sort=False):
        lines += [f"### {name}", "", f"{descriptions[name]}. Error unit: {g.error_unit.iloc[0]}; "
                  "* on the Pareto front, = the reference.", "", "| setting | seconds | error | |", "|---|---|---|---|"]
        for r in g.itertuples():
            error = f"{r.error:.2e}" if np.isfinite(r.error) else r.note
            lines.append(f"| {r.setting} | {r.seconds:.3g} | {error} | {'* ' if r.pareto else ''}"
                         f"{'=' if r.reference is True else ''} |")
        lines.append("")
    return lines


def markdown(frame: pd.DataFrame, descriptions: dict[str, str], repeat: int, elapsed: float, png: str) -> str:
    """bench.md: the cost table, the figure, the knobs' tables."""
    lines = ["# linkrepro bench", "",
             f"Best of {repeat} calls each (time.perf_counter; the port's caches cleared before each call), all "
             f"from one run of {elapsed:.0f} s. The machine is shared: read the ratios, measured side by side, "
             "not the seconds.", "", "## Cost per position", "",
             "Microseconds per position (an input angle, a crank position). Limit: the flops per position of the "
             "listing's algorithm, counted by hand (harness/bench.py: KED_*, NEWTON_*, CSSP_*, CLOSED_LOOP, "
             f"GSC_FORCES; matrix products dense as the listings form them, {TRANSCENDENTAL} flops for a sin, "
             f"cos, atan or sqrt), at {FLOP_RATE / 1e9:g} GFLOP/s (one core's scalar peak: 4 flops a cycle at "
             "2.5 GHz, no SIMD). Last column: the port with the listing's bugs against legacy on the same inputs, "
             "max |difference| / max |legacy|.", ""]
    lines += cost_table(frame[frame.kind == "cost"])
    lines += ["", "## Speed against error, per knob", "",
              "Seconds of one call (every position of the setting); error against the knob's converged "
              "reference. The figure plots them per knob, the Pareto front joined.", "",
              f"![error against time]({png})", ""]
    lines += knob_tables(frame[frame.kind == "knob"], descriptions)
    return "\n".join(lines) + "\n"


def plot(frame: pd.DataFrame, path: Path) -> None:
    """Error against time, one panel per knob, the Pareto front joined; a zero error (the
    reference, or as good) at the panel's floor, a failed setting at its ceiling."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter
    groups = list(frame[frame.kind == "knob"].groupby("subject", sort=False))
    rows = -(-len(groups) // 3)
    fig, axes = plt.subplots(rows, 3, figsize=(12, 3.4 * rows), squeeze=False)
    for ax, (name, g) in zip(axes.flat, groups):
        error = g.error.astype(float)
        positive = error[np.isfinite(error) & (error > 0)]
        floor, ceiling = (positive.min() / 10, positive.max() * 10) if len(positive) else (1e-16, 1.0)
        shown = error.where(np.isfinite(error), ceiling).clip(lower=floor)
        kinds = [(np.isfinite(error) & (error > 0), "o", "0.6", "setting"),
                 (error <= 0, "v", "C0", "error 0 (the reference)"), (~np.isfinite(error), "x", "k", "failed")]
        for where, marker, colour, label in kinds:
            ax.loglog(g.seconds[where], shown[where], marker, color=colour, ms=5, label=label)
        front = g.seconds[g.pareto.astype(bool)].sort_values().index
        ax.loglog(g.seconds[front], shown[front], "-o", color="C3", ms=5, label="Pareto front")
        for i in front:
            ax.annotate(str(g.setting[i]), (g.seconds[i], shown[i]), fontsize=6, xytext=(3, 3),
                        textcoords="offset points")
        ax.set_xlim(g.seconds.min() / 1.6, g.seconds.max() * 1.6)
        ax.set_ylim(floor / 3, ceiling * 3)
        ax.yaxis.set_minor_formatter(NullFormatter())
        ax.tick_params(axis="x", which="both", labelsize=6, labelrotation=40)
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("seconds (one call)")
        ax.set_ylabel(f"error ({g.error_unit.iloc[0]})")
        ax.grid(alpha=0.3, which="both")
    for ax in list(axes.flat)[len(groups):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def run_bench(repeat: int = 10, out: Path | str = Path("out/bench"), quick: bool = False) -> str:
    """Run the bench; write OUT/bench.md, bench.png, bench.csv; return the markdown.

    ``repeat``: calls per timing (best of; the Case III sweep, 48 settings, takes repeat // 10,
    at least 1); ``quick``: the reduced configuration (the tables' 19 angles, three settings a
    knob, no Case III sweep), a smoke test of a few seconds."""
    if repeat < 1:
        raise ValueError("repeat must be >= 1")
    start, out = time.perf_counter(), Path(out)
    comps, knob_list = computations(quick), knobs(quick)
    descriptions = {k.name: f"{k.what} ({k.engine})" for k in knob_list} | {CASE3: CASE3_WHAT}
    with progress.Bar(1 + len(comps) + len(knob_list) + (0 if quick else 1)):
        _step("warming up (the first run compiles the numba kernels)", warm_up)
        rows = []
        for comp in comps:
            rows += _step(comp.name, lambda: cost_rows(comp, repeat))
        for knob in knob_list:
            rows += _step(f"knob: {knob.name}", lambda: knob_rows(knob, repeat))
        if not quick:
            rows += _step(f"knob: {CASE3}", lambda: case3_rows(max(1, repeat // 10)))
    frame = pd.DataFrame(rows).reindex(columns=COLUMNS)
    out.mkdir(parents=True, exist_ok=True)
    md, png, csv = (out / name for name in OUTPUTS)
    frame.to_csv(csv, index=False)
    plot(frame, png)
    text = markdown(frame, descriptions, repeat, time.perf_counter() - start, png.name)
    md.write_text(text)
    return text
