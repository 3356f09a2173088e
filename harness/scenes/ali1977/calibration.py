"""Ali (1977): the K.E.D. engines' error bound on random geometries and sections, Cases I-III
(part of the scene ali1977-conditioning).

A fixed random sample of draws, each a program (Case I, II or III, source or cognate), a
crank-rocker (crank 1 to 10 in, the other links 1.4 to 20 times it; in one draw in twelve 3 to
100 in with a crank 3e-6 to 0.3 times them; the coupler point anywhere from 0.05 to 5 coupler
lengths out), a section (area 0.003 to 3 in^2, modulus 1e6 to 3e7 psi,
second moment 0.01 to 30 times a round bar's: slender and stocky), a speed (60 to 1200 rpm), a
weight or density, and an input-angle grid (step 30 to 90 deg: legacy computes the grid).  One
draw in six puts a four-bar within 1e-12 to 1e-3 (relative) of a change point, so that a grid
angle (0 or 180 deg) is near a toggle; one in four puts the coupler angle onto a zero of the
listing's Cramer determinant at a grid angle (``poles``: the bug's own pole), exactly or 1 to
1e9 ulps off.  Section values, weight and speed are REAL*4 and INTEGER numbers, so that every
engine takes the same inputs.  Each draw runs four engines over the grid (a "run" each):

- ``legacy``: the FORTRAN (REAL*4, the listing's bugs; the port with them equals it bit for bit);
- ``listing_double``: the port with the listing's bugs in double precision;
- ``corrected_real4``: the corrected port with the listings' REAL*4 storage;
- ``corrected_double``: the corrected port.

At three grid angles (always the toggle's or the pole's, where there is one) the deflection
vector (dx, dy, extender * rot) of each run is set against the same program's equations (the
listing's, or the corrected ones) evaluated in 60 digits from the same inputs
(``exact.listing``), relative to its length; each point's ``error_bound`` is the engine's own
(``port.ali1977.conditioning.expected_error``), ``verdict`` what the run said.  Over its bound
is a failure of the bound; a point over half the storage's digits in a run that did not warn is
a silent failure.
"""
from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from ....errors import LinkageError, LinkreproWarning
from ....legacy import ali1977 as legacy
from ....port.ali1977 import case1, case2, case3
from ....port.ali1977.conditioning import (CONDITION_FACTOR, DOUBLE_UNIT, POLE_FACTOR, REAL4_UNIT, STORAGE_FACTOR,
                                           spread)
from ....port.ali1977.fourbar import Lengths, construction_factor
from ....port.ali1977.quirks import CORRECTED
from ....port.ali1977.structure import GRAVITY_IN, GRAVITY_REAL4, Section
from ...csv_output import FULL_PRECISION, write_csv
from . import exact, poles
from .calibration_settings import DRAWS, SEED, TITLE

#: the programs, their port functions and their weight's name
PROGRAMS = {"case1_source": case1.source_case1, "case1_cognate": case1.cognate_case1,
            "case2_source": case2.case2_source, "case2_cognate": case2.case2_cognate,
            "case3_source": case3.case3_source, "case3_cognate": case3.case3_cognate}
ENGINES = ("legacy", "listing_double", "corrected_real4", "corrected_double")
STEPS = (30.0, 36.0, 45.0, 60.0, 90.0)
#: grid angles checked against the 60-digit reference per run
CHECKED = 3


def _f32(value: float) -> float:
    return float(np.float32(value))


def draw(rng: np.random.Generator) -> dict:
    """One draw's inputs (see the module's docstring); ``kind`` random, toggle or pole, and
    ``at``: the grid angle driven onto the toggle or pole (deg), or None."""
    program = list(PROGRAMS)[rng.integers(len(PROGRAMS))]
    kind = rng.choice(["random", "toggle", "pole", "spread"], p=[1 / 2, 1 / 6, 1 / 4, 1 / 12])
    s = 10.0 ** rng.uniform(0.0, 1.0)
    p, q = s * 10.0 ** rng.uniform(0.15, 1.3, 2)
    if kind == "spread":                                         # a crank 3e-6 to 0.3 of the other links
        p, q = 10.0 ** rng.uniform(0.5, 2.0, 2)
        s = min(p, q) * 10.0 ** -rng.uniform(0.5, 5.5)
    spare = 10.0 ** -rng.uniform(3.0, 12.0) if kind == "toggle" else rng.uniform(0.02, 0.98)
    longest = max(p, q) + (1.0 - spare) * (min(p, q) - s)
    l3, l4, l5 = rng.permutation([p, q, longest])
    l2 = l3 * 10.0 ** rng.uniform(-1.3, 0.7)
    links = np.array([s, l2, l3, l4, l5])
    if program.startswith("case3") and l2 < 8.5:                 # the listing's nodes need l2 > 8 in
        links *= rng.uniform(8.5, 20.0) / l2
    area = _f32(10.0 ** rng.uniform(-2.5, 0.5))
    section = Section(area, _f32(10.0 ** rng.uniform(6.0, 7.5)),
                      _f32(area * area / (4.0 * math.pi) * 10.0 ** rng.uniform(-2.0, 1.5)))
    step = float(rng.choice(STEPS))
    weight = _f32(rng.uniform(0.1, 10.0)) if program.startswith("case1") else _f32(rng.uniform(0.01, 0.3))
    lengths = Lengths(*links)
    out = {"program": program, "kind": kind, "lengths": lengths, "alp": float(rng.uniform(-math.pi, math.pi)),
           "rpm": float(rng.integers(60, 1201)), "weight": weight, "section": section, "step": step, "at": None}
    if kind == "toggle":
        out["at"] = 180.0 if abs(l5 + s - (l3 + l4)) < abs(abs(l5 - s) - abs(l3 - l4)) else 0.0
    elif kind == "pole":
        at = float(rng.integers(0, int(360.0 / step))) * step
        found = poles.pole_alps(program, at, lengths, grid=73)
        if found:
            off = int(rng.choice([0, 0, 1, -1, 3, -7, 100, -1000, 10**5, -10**7, 10**9]))
            out["alp"], out["at"] = _moved(found[rng.integers(len(found))], off), at
        else:
            out["kind"] = "random"
    return out


def _moved(alp: float, ulps: int) -> float:
    """``alp`` moved by ``ulps`` units in its last place (at most a few steps of nextafter:
    larger moves as a multiple of its spacing)."""
    return alp + ulps * float(np.spacing(alp)) if abs(ulps) > 8 else poles.nudged(alp, ulps)


def _engine_call(engine: str, d: dict, deg: np.ndarray | None):
    """The engine's run over the draw's grid (legacy computes it; the port takes legacy's angles
    ``deg``)."""
    program, lengths, section = d["program"], d["lengths"], d["section"]
    weight = "mass_lbf" if program.startswith("case1") else "density"
    if engine == "legacy":
        return getattr(legacy, program)(*vars(lengths).values(), alp=d["alp"], rpm=d["rpm"],
                                        area=section.area, modulus=section.modulus, inertia=section.inertia,
                                        step_deg=d["step"], **{weight: d["weight"]})
    listing, _ = poles.LISTINGS[program]
    quirks = {"listing_double": listing.only("real4_storage", False),
              "corrected_real4": CORRECTED.only("real4_storage", True), "corrected_double": CORRECTED}[engine]
    return PROGRAMS[program](deg, lengths=lengths, alp=d["alp"], rpm=d["rpm"], section=section, quirks=quirks,
                             **{weight: d["weight"]})


def _outcome(engine: str, d: dict, deg):
    """(results or None, verdict): what the engine returned and said."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", LinkreproWarning)
        try:
            out = _engine_call(engine, d, deg)
        except (LinkageError, ValueError) as exc:
            return None, type(exc).__name__
    said = sorted({w.category.__name__ for w in caught if issubclass(w.category, LinkreproWarning)})
    return out, "+".join(said) or "returned"


def _reference(d: dict, deg: float, corrected: bool) -> dict | None:
    """The 60-digit reference (REAL*4 inputs: g as Cases II, III compute it in REAL*4), or None
    where the loop cannot close there."""
    listing, _ = poles.LISTINGS[d["program"]]
    quirks = CORRECTED.only("real4_storage", True) if corrected else listing
    try:
        return exact.listing(d["program"], deg, d["lengths"], d["alp"], d["rpm"], d["weight"], d["section"], quirks)
    except (ArithmeticError, ZeroDivisionError):
        return None


def measure_draw(d: dict, rng: np.random.Generator, index: int = 0) -> list[dict]:
    """The rows of one draw (number ``index``): each engine's run, at the checked angles."""
    legacy_out, legacy_verdict = _outcome("legacy", d, None)
    deg = legacy_out["deg"] if legacy_out is not None else np.arange(0.0, 360.0 + 1e-9, d["step"])
    picks = sorted(set(rng.choice(len(deg), size=min(CHECKED, len(deg)), replace=False).tolist())
                   | ({int(np.argmin(np.abs(deg - d["at"])))} if d["at"] is not None else set()))
    refs = {corrected: {k: _reference(d, float(deg[k]), corrected) for k in picks} for corrected in (False, True)}
    rows = []
    for engine in ENGINES:
        out, verdict = (legacy_out, legacy_verdict) if engine == "legacy" else _outcome(engine, d, deg)
        real4 = engine in ("legacy", "corrected_real4")
        for k in picks:
            ref = refs[engine.startswith("corrected")][k]
            if ref is None:
                continue
            scale = 1.0 if real4 else GRAVITY_REAL4 / GRAVITY_IN        # the loads' 1/g
            truth = scale * np.array([ref["dx"], ref["dy"], ref["extender"] * ref["rot"]])
            row = {"draw": index, "program": d["program"], "kind": d["kind"], "engine": engine, "input_deg": float(deg[k]),
                   "at_pole_or_toggle": d["at"] is not None and k == int(np.argmin(np.abs(deg - d["at"]))),
                   "l1": d["lengths"].l1, "l2": d["lengths"].l2, "l3": d["lengths"].l3, "l4": d["lengths"].l4,
                   "l5": d["lengths"].l5, "alp_deg": math.degrees(d["alp"]), "rpm": d["rpm"], "weight": d["weight"],
                   "area": d["section"].area, "modulus": d["section"].modulus, "inertia": d["section"].inertia,
                   "spread": spread(list(vars(d["lengths"]).values())),
                   "construction": construction_factor(d["lengths"].l2, d["lengths"].l3, d["alp"], engine in (
                       "legacy", "listing_double")) if d["program"].endswith("cognate") else 1.0,
                   "rho": min(ref["rho"]), "cancellation": ref["magnitude"] / float(np.linalg.norm(truth / scale)),
                   "condition": np.nan, "error_bound": np.nan, "error": np.nan, "verdict": verdict}
            if out is not None:
                got = np.array([out["dx"][k], out["dy"][k], ref["extender"] * out["rot"][k]])
                row.update(condition=float(out["condition"][k]), error_bound=float(out["error_bound"][k]),
                           error=float(np.linalg.norm(got - truth) / np.linalg.norm(truth)))
            rows.append(row)
    return rows


def measure(seed: int, draws: int) -> pd.DataFrame:
    """The sample: ``draws`` draws (4 runs each) from ``seed``."""
    rng = np.random.default_rng(seed)
    rows = []
    for index in range(draws):
        rows += measure_draw(draw(rng), rng, index)
    return pd.DataFrame(rows)


def summary(data: pd.DataFrame) -> pd.DataFrame:
    """Per engine: runs, points checked, points refused, warned, the largest error over its
    bound, the points over their bound and the silent failures (a point over half the
    storage's digits in a run that did not warn)."""
    rows = []
    for engine, g in data.groupby("engine", sort=False):
        claim = math.sqrt(REAL4_UNIT if engine in ("legacy", "corrected_real4") else DOUBLE_UNIT)
        answered = g[g["error"].notna()]
        rows.append({"engine": engine, "runs": int(g["draw"].nunique()),
                     "points": len(g), "refused": int(g["error"].isna().sum()),
                     "warned": int((answered["verdict"] != "returned").sum()),
                     "worst_error_over_bound": float((answered["error"] / answered["error_bound"]).max()),
                     "over_bound": int((answered["error"] > answered["error_bound"]).sum()),
                     "silent_failures": int(((answered["verdict"] == "returned") & (answered["error"] > claim)).sum())})
    return pd.DataFrame(rows)


#: the sample's summary as the command last recorded it (``--record``): what the docs show
RECORD = Path(__file__).with_name("ked_bound.csv")


def as_markdown(table: pd.DataFrame, seed: int, draws: int) -> str:
    """The summary as a markdown table, with what was run."""
    lines = [f"{draws} draws from seed {seed}, {int(table['runs'].sum())} runs "
             f"(`linkrepro ked-bound --draws {draws} --seed {seed}`); bound: "
             f"({STORAGE_FACTOR:g} u_s + {CONDITION_FACTOR:g} u kappa K + {POLE_FACTOR:g} u K / rho) x cancellation.",
             "", "| engine | runs | points checked | refused | warned | worst error / bound | over the bound | "
             "silent failures |", "|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r.engine} | {r.runs} | {r.points} | {r.refused} | {r.warned} | {r.worst_error_over_bound:.2g} | "
              f"{r.over_bound} | {r.silent_failures} |" for r in table.itertuples()]
    return "\n".join(lines) + "\n"


def write(out_dir: Path, seed: int = SEED, draws: int = DRAWS, record: bool = False) -> str:
    """Measure the sample and write DIR/calibration.csv (every point), DIR/summary.csv and
    DIR/calibration.md; with ``record`` also RECORD (the summary, with the seed and draws)."""
    data = measure(seed, draws)
    table = summary(data)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    write_csv(data, out_dir / "calibration.csv", FULL_PRECISION)
    write_csv(table, out_dir / "summary.csv", "%.6g")
    text = as_markdown(table, seed, draws)
    (out_dir / "calibration.md").write_text(f"# {TITLE}\n\n{__doc__.split(chr(10) * 2, 1)[1].strip()}\n\n{text}")
    if record:
        write_csv(table.assign(seed=seed, draws=draws), RECORD, "%.6g")
    return text


def run(args) -> str:
    """``linkrepro ked-bound`` (``commands.py`` declares its arguments): the sample written into
    ``args.out``; its markdown."""
    return write(args.out, args.seed, args.draws, args.record)
