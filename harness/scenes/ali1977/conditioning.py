"""Ali (1977), the K.E.D. results near a toggle: error against conditioning, and the rule that
says so (scene ali1977-conditioning).

A fixed random sample of four-bars that reach a toggle (coupler and follower in line) at some
input angle: link lengths log-uniform over three decades, alp anywhere; for each, input angles
at 10^-13 to 1 deg from the toggle on both sides, and one angle far from it.  At each, the
Case I source deflection (dx, dy, l2 rot: one vector, in) of two engines against the same
equations evaluated in 60 digits (``exact.case1_source``):

- ``float64``: the corrected port (every quirk off);
- ``real4``: the same with the listings' ``REAL*4`` storage of matrices and loads (the arithmetic
  of legacy and of the listing port, without their bugs, so that the 60-digit reference applies).

Each point's relative error is set against its condition (``port.ali1977.conditioning``:
the links' spread over sin^2 of the transmission angle) and the bound the engine returns with
it (``error_bound``), which it uses to warn and to refuse; ``verdict`` is what the engine said
(returned, PrecisionWarning, SingularPositionError, AssemblyError).  Random geometries, sections,
Cases I-III and the listings' own equations are the calibration sample's (``calibration``, the
command ``linkrepro ked-bound``).
"""
from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from ....errors import LinkageError, PrecisionWarning
from ....port.ali1977.case1 import source_case1
from ....port.ali1977.conditioning import (CONDITION_FACTOR, DOUBLE_UNIT, POLE_FACTOR, REAL4_UNIT, STORAGE_FACTOR,
                                           condition, expected_error, spread)
from ....port.ali1977.fourbar import Lengths
from ....port.ali1977.quirks import CORRECTED
from ...csv_output import FULL_PRECISION, write_csv
from ...scene import ReportScene
from . import exact
from .tables import GROUP, START

NAME = "ali1977-conditioning"
TITLE = "Ali (1977): the deflections' error near a toggle, against the conditioning the engines report"
ENGINES = {"float64": CORRECTED, "real4": CORRECTED.only("real4_storage", True)}
RPM = 300.0


def toggle_angles(lengths: Lengths) -> list[float]:
    """The input angles (deg, in [0, 180]) where the loop is at a toggle: the crank pin at
    distance l3 + l4 or |l3 - l4| from the follower's pivot."""
    out = []
    for d in (lengths.l3 + lengths.l4, abs(lengths.l3 - lengths.l4)):
        c = (lengths.l1 ** 2 + lengths.l5 ** 2 - d * d) / (2.0 * lengths.l1 * lengths.l5)
        if abs(c) < 0.9999:
            out.append(math.degrees(math.acos(c)))
    return out


def sample(seed: int, count: int) -> list[tuple[Lengths, float, float]]:
    """(lengths, alp in deg, input angle in deg) near the toggles of ``count`` random four-bars."""
    rng = np.random.default_rng(seed)
    points = []
    while len({id(p[0]) for p in points}) < count:
        lengths = Lengths(*np.exp(rng.uniform(math.log(0.1), math.log(100.0), 5)))
        toggles = toggle_angles(lengths)
        if not toggles:
            continue
        star, alp = toggles[rng.integers(len(toggles))], float(rng.uniform(-180.0, 360.0))
        offsets = [*10.0 ** -rng.uniform(0.0, 13.0, 4), float(rng.uniform(1.0, 179.0))]
        points += [(lengths, alp, star + side * off) for off in offsets for side in (1.0, -1.0)]
    return points


def _run(lengths: Lengths, alp: float, deg: float, quirks) -> tuple[np.ndarray | None, float, str]:
    """(dx, dy, l2 rot) of the engine at one angle, or None, its error bound and what it said."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PrecisionWarning)
        try:
            out = source_case1(np.array([deg]), lengths, alp=math.radians(alp), rpm=RPM, quirks=quirks)
        except LinkageError as exc:
            return None, np.nan, type(exc).__name__
    verdict = "PrecisionWarning" if any(issubclass(w.category, PrecisionWarning) for w in caught) else "returned"
    return np.array([out["dx"][0], out["dy"][0], lengths.l2 * out["rot"][0]]), float(out["error_bound"][0]), verdict


def measure(points) -> pd.DataFrame:
    """One row per point and engine: the geometry, sin(mu), the condition, the bound, the
    measured relative error (NaN where the engine refused) and the verdict."""
    rows = []
    for lengths, alp, deg in points:
        ref = exact.case1_source(deg, lengths, alp_deg=alp)
        if ref is None:
            continue
        truth = np.array([ref["dx"], ref["dy"], lengths.l2 * ref["rot"]])
        link_spread = spread(list(vars(lengths).values()))
        kappa = float(condition([deg], math.pi, [(lengths.l1, lengths.l3, lengths.l4, lengths.l5)], link_spread)[0])
        for engine, quirks in ENGINES.items():
            got, bound, verdict = _run(lengths, alp, deg, quirks)
            error = np.nan if got is None else float(np.linalg.norm(got - truth) / np.linalg.norm(truth))
            rows.append({"l1": lengths.l1, "l2": lengths.l2, "l3": lengths.l3, "l4": lengths.l4, "l5": lengths.l5,
                         "alp_deg": alp, "input_deg": deg, "sin_mu": ref["sin_mu"], "spread": link_spread,
                         "condition": kappa, "engine": engine,
                         "bound": float(expected_error(kappa, engine == "real4")) if np.isnan(bound) else bound,
                         "error": error, "verdict": verdict})
    return pd.DataFrame(rows)


def summary(data: pd.DataFrame) -> pd.DataFrame:
    """Per engine: points, refused, warned, the worst error over its bound, and the silent
    failures (returned without a warning, error beyond half the storage's digits)."""
    rows = []
    for engine, g in data.groupby("engine", sort=False):
        claim = math.sqrt(REAL4_UNIT if engine == "real4" else DOUBLE_UNIT)
        answered = g[g["error"].notna()]
        rows.append({"engine": engine, "points": len(g), "refused": int(g["error"].isna().sum()),
                     "warned": int((g["verdict"] == "PrecisionWarning").sum()),
                     "worst_error_over_bound": float((answered["error"] / answered["bound"]).max()),
                     "silent_failures": int(((answered["verdict"] == "returned") & (answered["error"] > claim)).sum())})
    return pd.DataFrame(rows)


def plot(data: pd.DataFrame, path: Path) -> None:
    """Relative error (no unit) against condition (no unit), one panel per engine, with the bound
    (where the deflection's terms do not cancel) and the engines' two limits (warning, refusal)."""
    from ...figures import save
    from ...report import panel_grid, top_legend
    fig, margins = panel_grid(11.0, 2, 1, 3.6, TITLE, legend_rows=2, gap_across=0.35)
    axes = fig.subplots(1, 2, sharey=True)
    kappa = np.logspace(0, 16, 200)
    for ax, (engine, g) in zip(axes, data.groupby("engine", sort=False)):
        real4 = engine == "real4"
        answered = g[g["error"].notna()]
        ax.loglog(answered["condition"], np.maximum(answered["error"], 1e-18), "o", color="tab:blue", ms=2.5,
                  alpha=0.5, mew=0, label="measured (60-digit reference)")
        ax.loglog(kappa, expected_error(kappa, real4), color="k", lw=1.0,
                  label="bound (the deflection's terms not cancelling)")
        ax.axhline(math.sqrt(REAL4_UNIT if real4 else DOUBLE_UNIT), color="tab:orange", lw=1.2,
                   label="warning level: half the stored digits")
        ax.axhline(1.0, color="tab:red", lw=1.2, label="refusal level: 1 (SingularPositionError)")
        ax.set_xlabel("condition: links' spread / sin^2(transmission angle)")
        ax.set_title(f"{engine}: {'REAL*4 storage, as the listings' if real4 else 'IEEE double, the corrected port'}",
                     y=1.0)                                      # no layout pass
        ax.set_ylim(1e-18, 10.0)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel("relative error of dx, dy and l2 * rot")
    top_legend(fig, dict(zip(*reversed(axes[0].get_legend_handles_labels()))), rows=2)
    caption = ("Four-bars near a toggle (a fixed random sample, Case I loads): the relative error of the "
               "deflection vector (dx, dy, l2 * rot) of each engine against the same equations in 60 digits, "
               "against the condition the engines compute; the black line is the engines' error bound where the "
               "deflection's terms do not cancel (a point's own bound, which the engine returns, is larger by its "
               "cancellation). An engine warns (PrecisionWarning) where its "
               "bound passes the orange line and refuses where it reaches the red one; a refused point is not "
               "drawn, an error under 1e-18 is drawn at 1e-18. Left the double-precision port, right the "
               "listings' REAL*4 storage. Measured: " + "; ".join(_plotted_facts(data)) + ".")
    save(fig, path, caption, **margins)


def _plotted_facts(data: pd.DataFrame) -> list[str]:
    """Per engine, what ``plot`` shows, counted on ``data``: the points drawn, how many lie over
    their bound, the warned and refused ones, those drawn at the floor; for REAL*4, where its
    errors lie at conditions under 1e4 against its unit roundoff."""
    facts = []
    for engine, g in data.groupby("engine", sort=False):
        answered = g[g["error"].notna()]
        over = int((answered["error"] > answered["bound"]).sum())
        fact = (f"{engine}: {len(answered)} of {len(g)} points drawn, {over or 'none'} over their bound "
                f"(largest error / bound {(answered['error'] / answered['bound']).max():.2g}), "
                f"{int((g['verdict'] == 'PrecisionWarning').sum())} warned, {int(g['error'].isna().sum())} refused")
        floor = int((answered["error"] < 1e-18).sum())
        fact += f", {floor} at the floor" if floor else ""
        easy = answered[answered["condition"] < 1e4]["error"]
        if engine == "real4" and len(easy):
            fact += (f"; at conditions under 1e4 its errors lie between {easy.min():.1e} and {easy.max():.1e} "
                     f"(REAL*4's unit roundoff {REAL4_UNIT:.1e})")
        facts.append(fact)
    return facts


def run(out_dir: Path, seed: int = 2026, count: int = 60) -> pd.DataFrame:
    """out/ali1977-conditioning/: conditioning.csv (every point), summary.csv, conditioning.png,
    report.md."""
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    data = measure(sample(seed, count))
    table = summary(data)
    write_csv(data, target / "conditioning.csv", FULL_PRECISION)
    write_csv(table, target / "summary.csv", "%.6g")
    plot(data, target / "conditioning.png")
    lines = [f"# {TITLE}", "", __doc__.split("\n\n", 1)[1].strip(), "",
             f"Bound (relative to the deflection vector, per point): ({STORAGE_FACTOR:g} u_s + {CONDITION_FACTOR:g} u "
             "kappa) times the deflection's cancellation (u_s the storage's unit roundoff, u the double's; with the "
             f"listings' bugs + {POLE_FACTOR:g} u / rho, rho the listing's Cramer determinant over its terms); a "
             "PrecisionWarning where it passes sqrt(u_s), a SingularPositionError where it reaches 1.", "",
             "| engine | points | refused | warned | worst error / bound | silent failures |", "|---|---|---|---|---|---|"]
    lines += [f"| {r.engine} | {r.points} | {r.refused} | {r.warned} | {r.worst_error_over_bound:.3g} | "
              f"{r.silent_failures} |" for r in table.itertuples()]
    lines += ["", "![error against condition](conditioning.png)", ""]
    (target / "report.md").write_text("\n".join(lines))
    return table


def overview(table: pd.DataFrame) -> list[str]:
    return [f"{r.engine}: {r.points} points near toggles, worst error {r.worst_error_over_bound:.2g} of the bound, "
            f"{r.warned} warned, {r.refused} refused, {r.silent_failures} silent failures"
            for r in table.itertuples()]


SCENE = ReportScene(name=NAME, title=TITLE, group=GROUP, start=START, produce=run, overview=overview)
