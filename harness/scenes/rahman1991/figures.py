"""Rahman (1991), figures 5-38 replotted: slider displacement S4 and the joint forces and torques
against crank angle, for the three families of section 3.2 (seed 001, lines 1111-1113), every
panel with the ideal planar case (a4 = 0, S1 = 0, alpha4 = 270) as a thick black line.

  family "a4"     (a4 = 10, 20, 30 in; S1 = 3.5 in; alpha4 = 270):  figs. 5, 8, 11, 14, 16, 18, 21, 24, 27, 30, 33, 36
  family "s1"     (S1 = 3, 6, 9 in; a4 = 30 in; alpha4 = 270):      figs. 6, 9, 12, 15, 17, 19, 22, 25, 28, 31, 34, 37
  family "alpha4" (alpha4 = 232, 270, 310; a4 = 20 in; S1 = 0):     figs. 7, 10, 13, 20, 23, 26, 29, 32, 35, 38

Figs. 5-7 are the displacement; 14-17 are the two pairs of torque figures (no alpha4 member: T1i and
T1j vanish when S1 = 0); the rest are forces. The thesis does not name the component of each figure,
so no figure number is claimed for a panel. The seed prints each caption under the preceding figure
number: read one figure later, the captions agree with the text (a4 = 30 for the s1 family, a4 = 20
for the alpha4 family, S1 = 3.5 for the a4 family).

What is written (``plot_figures``), in reading order of the file names: ``fig_01_s4.png``, the
displacement (a row per engine, a column per family), then one figure of the joint loads per
engine (``fig_02_loads_port_printed.png``, ``fig_03_loads_port_corrected.png``): a row per
component that varies, joints 1 (crank on frame) to 4 (slider on frame), a column per family.  A
component constant over every drawn case (T1k, 2F2j, 4T4, and with the printed model 1F1k and
2F2k: eleven drawn components for the printed model, as the thesis's 27 force and torque
figures), or equal at every drawn point to a component drawn above it or to its negative (with
the corrected model 2F2k = -1F1k), is named in the caption instead (``load_rows``).

Every computed point is drawn (361 a curve).  Points near the dead centres can reach 1e6 lbf or
more; the thesis dropped them.  Here the y-limits are robust (2nd-98th percentile, widened,
``robust_limits``, one pair a row); a curve breaks where it changes sign through a point beyond
the limits (a pole: a line there would be no value of the load, ``broken``), and each run of
points beyond an edge is marked by one triangle on it (``excursions``).  Every number a caption
states is measured from the drawn data (``s4_facts``, ``load_facts``): how far the engines' S4
lie apart, where the printed method needed its fallback, how many points lie beyond the limits
and how far from a dead centre, which positions have no finite load.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.collections import LineCollection
from matplotlib.lines import TICKDOWN, Line2D
from matplotlib.ticker import FixedLocator, MaxNLocator, NullLocator
from matplotlib.transforms import ScaledTranslation, blended_transform_factory

from ... import figures
from ...report import draw_all
from ....port.rahman1991.analysis import ANSWERED
from .quantities import CONFIGURATION, JOINT_LOADS, POSITIONS

IDEAL = {"a4": 0.0, "s1": 0.0, "alpha4_deg": 270.0}
FAMILIES = {"a4": ("a4", [10.0, 20.0, 30.0], {"s1": 3.5, "alpha4_deg": 270.0}),
            "s1": ("s1", [3.0, 6.0, 9.0], {"a4": 30.0, "alpha4_deg": 270.0}),
            "alpha4": ("alpha4_deg", [232.0, 270.0, 310.0], {"a4": 20.0, "s1": 0.0})}
#: the joints, each with its loads (quantities.JOINT_LOADS), in the order of the figures
JOINTS = {1: ["F1", "T1"], 2: ["F2"], 3: ["F3"], 4: ["F4", "T4"]}
LOADS = [f"{load}{axis}" for loads in JOINTS.values() for load in loads for axis in "ijk"]
#: the columns a figure reads
USED = ["crank_deg", "converged", "status", "theta2", "s4", *LOADS]
ENGINE_WORDS = {"port_printed": "port_printed, the method as printed",
                "port_corrected": "port_corrected, every registered bug removed"}
LABEL = {"a4": "a4", "s1": "S1", "alpha4_deg": "alpha4"}
UNIT = {column: q.unit for column, q in CONFIGURATION.items()}
#: the ideal case, then the family's three members (Okabe-Ito colours: told apart in colour
#: blindness); drawn without antialiasing (``draw_row``): 3 px and 1 px of the colour, unblended
STYLES = [dict(color="k", lw=2.25, antialiased=False, zorder=1)] + [
    dict(color=color, lw=0.75, antialiased=False, zorder=2) for color in ("#0072B2", "#D55E00", "#009E73")]
#: a component is constant when its values differ by at most this, relative to max(1, |value|)
CONSTANT = 1e-9
#: inches: a row's height, the gap between rows, the figure's head and foot, its width
ROW_H, GAP_H, HEAD_H, FOOT_H, WIDTH = 0.8, 0.08, 0.9, 0.55, 12.0
#: inches: a row of the displacement figure (two rows, of one smooth quantity)
S4_ROW_H = 1.35
#: deg: how far along x each family's panel starts from the one before (360 and a gap)
STEP = 420.0
CRANK_TICKS = range(0, 361, 60)
RC_TICK = figures.RC["xtick.labelsize"]
#: points: the length of a crank tick under the last row; inches: the room left of the rows (their labels)
TICK_PT, LEFT_IN = 3.5, 1.75


@dataclass
class Row:
    """One row of a figure: its y label, its panels (per family, per case of ``family_cases``:
    crank deg and value) and its y-limits (None: no finite value)."""
    label: str
    panels: list[list[tuple[np.ndarray, np.ndarray]]]
    limits: tuple[float, float] | None


def case_rows(frame: pd.DataFrame) -> dict[tuple, dict[str, np.ndarray]]:
    """Each drawn case's columns (``USED``) as arrays, sorted by crank angle; keyed by (a4, s1,
    alpha4_deg) rounded to 1e-6 (``case_key``)."""
    keys, drawn, cases = [frame[col].astype(float).round(6) for col in IDEAL], drawn_cases(), {}
    for key, rows in frame.groupby(keys, sort=False):
        if key in drawn:
            rows = rows.sort_values("crank_deg")
            cases[key] = {col: rows[col].to_numpy() for col in USED if col in rows}
    return cases


def answered(rows: dict[str, np.ndarray]) -> np.ndarray:
    """Where a case's rows hold their engine's answer (``analysis.ANSWERED``)."""
    return np.isin(rows["status"].astype(str), ANSWERED)


def case_key(where: dict) -> tuple:
    return tuple(np.round(float(where[col]), 6) for col in IDEAL)


def select(cases: dict[tuple, dict], where: dict, quantity: str) -> tuple[np.ndarray, np.ndarray, int]:
    """Crank angles (deg) and values of one case (NaN where its engine gave no answer: the
    printed method's open loops are drawn, D085); and how many are not finite."""
    rows = cases.get(case_key(where))
    if rows is None:
        return np.empty(0), np.empty(0), 0
    y = np.where(answered(rows), rows[quantity].astype(float), np.nan)
    return rows["crank_deg"].astype(float), y, int((~np.isfinite(y)).sum())


def robust_limits(values: np.ndarray) -> tuple[float, float] | None:
    """2nd-98th percentile widened by half its span (kept inside the data range), plus a 5% margin."""
    v = values[np.isfinite(values)]
    if v.size == 0:
        return None
    lo, hi = np.percentile(v, [2, 98])
    span = hi - lo
    lo, hi = max(v.min(), lo - 0.5 * span), min(v.max(), hi + 0.5 * span)
    margin = 0.05 * (hi - lo) if hi > lo else max(abs(hi) * 0.1, 1.0)
    return lo - margin, hi + margin


def family_cases(family: str) -> list[tuple[str, dict]]:
    """The family's cases, the ideal first: (legend label, configuration)."""
    col, members, fixed = FAMILIES[family]
    return [("ideal", IDEAL)] + [(f"{value:g} {UNIT[col]}", {**fixed, col: value}) for value in members]


def case_words(where: dict) -> str:
    """A case in words: 'the ideal case' or its configuration."""
    if case_key(where) == case_key(IDEAL):
        return "the ideal case"
    return ", ".join(f"{LABEL[k]} = {where[k]:g} {UNIT[k]}" for k in ("a4", "s1", "alpha4_deg"))


def drawn_cases() -> dict[tuple, dict]:
    """Every case drawn in some panel, once: key -> configuration."""
    return {case_key(where): where for family in FAMILIES for _, where in family_cases(family)}


def family_title(family: str) -> str:
    """The family in words: what varies, what is held."""
    col, _, fixed = FAMILIES[family]
    held = ", ".join(f"{LABEL[k]} = {v:g} {UNIT[k]}" for k, v in fixed.items())
    return f"{LABEL[col]} varies; {held}"


def row(cases: dict[tuple, dict], quantity: str, label: str) -> Row:
    """The row of ``quantity``: a panel per family, y-limits robust over the row."""
    panels = [[select(cases, where, quantity)[:2] for _, where in family_cases(f)] for f in FAMILIES]
    return Row(label, panels, robust_limits(np.concatenate([y for curves in panels for _, y in curves])))


def constant_value(panels: list[list[tuple]]) -> float | None:
    """The value every finite point of these panels has (to ``CONSTANT``), or None."""
    values = np.concatenate([y for curves in panels for _, y in curves])
    values = values[np.isfinite(values)]
    if values.size == 0 or np.ptp(values) > CONSTANT * max(1.0, float(np.abs(values).max())):
        return None
    return float(np.median(values))


def same_as(panels: list[list[tuple]], drawn: list[tuple[str, Row]]) -> tuple[float, str] | None:
    """(sign, quantity) of a drawn row that these panels equal, times the sign, at every point (to
    ``CONSTANT`` relative to max(1, |value|) there; no finite value at the same points), or None."""
    values = np.concatenate([y for curves in panels for _, y in curves])
    finite = np.isfinite(values)
    for quantity, data in drawn:
        other = np.concatenate([y for curves in data.panels for _, y in curves])
        if other.shape != values.shape or not np.array_equal(finite, np.isfinite(other)):
            continue
        a, b = values[finite], other[finite]
        for sign in (1.0, -1.0):
            if np.all(np.abs(a - sign * b) <= CONSTANT * np.maximum(1.0, np.abs(a))):
                return sign, quantity
    return None


def dead_centres(crank_deg: np.ndarray, theta2_deg: np.ndarray) -> np.ndarray:
    """The crank angles (deg) after which theta2 passes 0 or 180 deg before the next step: the
    dead centres of a case (the rod in line with the crank)."""
    s2 = np.sin(np.radians(theta2_deg))
    return crank_deg[:-1][s2[:-1] * s2[1:] <= 0]


def joined(parts: list[np.ndarray]) -> np.ndarray:
    """Arrays joined with a NaN between them (a line breaks there)."""
    return np.concatenate([np.append(part, np.nan) for part in parts])[:-1]


def broken(x: np.ndarray, y: np.ndarray, lo: float, hi: float) -> tuple[np.ndarray, np.ndarray]:
    """x, y with a NaN put between two neighbours of opposite sign of which one lies beyond the
    limits: the curve breaks where it passes through a pole (a line there would be no value)."""
    beyond = (y > hi) | (y < lo)
    jumps = np.flatnonzero((np.sign(y[:-1]) * np.sign(y[1:]) < 0) & (beyond[:-1] | beyond[1:])) + 1
    return np.insert(x, jumps, np.nan), np.insert(y, jumps, np.nan)


def excursions(x: np.ndarray, y: np.ndarray, lo: float, hi: float) -> list[tuple[float, bool]]:
    """Each run of neighbouring points beyond one limit: (x of its farthest point, above)."""
    found = []
    for side, beyond in ((True, y > hi), (False, y < lo)):
        edges = np.diff(np.concatenate([[0], beyond.astype(np.int8), [0]]))
        for start, stop in zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)):
            part = y[start:stop]
            found.append((float(x[start + (np.argmax(part) if side else np.argmin(part))]), side))
    return found


def off_scale(y: np.ndarray, limits: tuple[float, float] | None) -> np.ndarray:
    """Where the finite values lie beyond ``limits``."""
    if limits is None:
        return np.zeros(y.shape, bool)
    return (y < limits[0]) | (y > limits[1])


def draw_row(ax, data: Row) -> None:
    """A row of panels, one per family, in one axes (drawing an axes costs more than its curves):
    family k's crank angles shifted by k * ``STEP`` deg, a frame and a grid drawn for each.  Every
    point of every curve, broken through a pole (``broken``); a triangle on the edge for each run
    of points beyond it (``excursions``).  Curves, triangles and frames are drawn without
    antialiasing: in the PNG's palette their colours stay unblended, within the few levels the
    palette's octree moves a colour (an antialiased 1 px blue line came out teal), and the file
    is half the size."""
    lo, hi = data.limits if data.limits is not None else (-1.0, 1.0)
    shifts = STEP * np.arange(len(data.panels))
    ax.set_ylim(lo, hi)
    ax.set_autoscale_on(False)                            # the limits are set: no autoscaling (it is slow)
    marks = {True: [], False: []}
    for case, style in enumerate(STYLES):
        parts = [broken(curves[case][0] + shift, curves[case][1], lo, hi) for curves, shift in zip(data.panels, shifts)]
        ax.plot(joined([x for x, _ in parts]), joined([y for _, y in parts]), **style)
        for curves, shift in zip(data.panels, shifts):
            for at, up in excursions(*curves[case], lo, hi):
                marks[up].append((at + shift, style["color"]))
    for up, points in marks.items():
        if points:
            ax.scatter([at for at, _ in points], np.full(len(points), hi if up else lo), s=22, linewidths=0,
                       marker="^" if up else "v", c=[color for _, color in points], clip_on=False, zorder=3,
                       antialiased=False)
    ticks = [t for t in MaxNLocator(3).tick_values(lo, hi) if lo <= t <= hi]
    grid = [[(x, lo), (x, hi)] for shift in shifts for x in shift + np.arange(60.0, 360.0, 60.0)]
    grid += [[(shift, t), (shift + 360.0, t)] for shift in shifts for t in ticks]
    frames = [[(shift, lo), (shift + 360.0, lo), (shift + 360.0, hi), (shift, hi), (shift, lo)] for shift in shifts]
    ax.add_collection(LineCollection(grid, colors="0.88", lw=0.75, zorder=0, snap=True), autolim=False)
    ax.add_collection(LineCollection(frames, colors="k", lw=0.75, zorder=4, clip_on=False, snap=True), autolim=False)
    if data.limits is None:
        ax.text(0.5, 0.5, "no finite value", transform=ax.transAxes, ha="center", va="center", color="0.3")
    ax.yaxis.set_major_locator(FixedLocator(ticks))
    ax.ticklabel_format(axis="y", style="plain", useOffset=False)


def draw_figure(path: Path, title: str, rows: list[Row], caption: str, row_h: float = ROW_H) -> Path:
    """One PNG: a row per ``Row`` (``row_h`` in high), a column per family; a legend heads each column."""
    height = HEAD_H + FOOT_H + len(rows) * row_h + (len(rows) - 1) * GAP_H
    fig = figures.new_figure(WIDTH, height)
    axes = fig.subplots(len(rows), 1, squeeze=False, sharex=True)[:, 0]
    axes[0].set_xlim(0.0, STEP * (len(FAMILIES) - 1) + 360.0)          # before any artist: no autoscaling
    axes[0].xaxis.set_major_locator(NullLocator())        # shared: no tick objects on any row (each costs ...
    for ax, data in zip(axes, rows):
        draw_row(ax, data)
        ax.set_ylabel(data.label, rotation=0, ha="right", va="center", labelpad=12)   # across: rows are low
        ax.spines[:].set_visible(False)
    last = axes[-1]                                       # ... more than its curves): under the last
    ticks = [k * STEP + deg for k in range(len(FAMILIES)) for deg in CRANK_TICKS]  # row, marks and labels
    below = blended_transform_factory(last.transData, last.transAxes)
    last.plot(ticks, np.zeros(len(ticks)), ls="none", marker=TICKDOWN, ms=TICK_PT, mew=0.75, color="k",
              clip_on=False, transform=below)
    down = below + ScaledTranslation(0, -2 * TICK_PT / 72, fig.dpi_scale_trans)
    for x, deg in zip(ticks, [deg for _ in FAMILIES for deg in CRANK_TICKS]):
        fig.text(x, 0.0, f"{deg}", transform=down, ha="center", va="top", fontsize=RC_TICK)
    last.set_xlabel(POSITIONS["crank_deg"].label, labelpad=2 * TICK_PT + RC_TICK)
    top = 1 - HEAD_H / height
    fig.subplots_adjust(left=LEFT_IN / WIDTH, right=1 - 0.2 / WIDTH, bottom=FOOT_H / height, top=top,
                        hspace=GAP_H / row_h)
    handles = [Line2D([], [], **{**style, "lw": max(style["lw"], 2.0)}) for style in STYLES]
    edges = {0: ("left", 0.0), len(FAMILIES) - 1: ("right", 360.0)}
    for k, family in enumerate(FAMILIES):            # over its column, the outer ones flush with its edge
        loc, deg = edges.get(k, ("center", 180.0))
        x = fig.transFigure.inverted().transform(axes[0].transData.transform((k * STEP + deg, 0.0)))[0]
        fig.legend(handles, [label for label, _ in family_cases(family)], title=family_title(family),
                   ncols=len(STYLES), loc=f"lower {loc}", bbox_to_anchor=(x, top + 0.1 / height),
                   handlelength=1.2, handletextpad=0.5, columnspacing=0.7, borderaxespad=0.0)
    fig.suptitle(title, x=0.01, y=1 - 0.06 / height, ha="left", va="top")
    return figures.save(fig, path, caption)


# ---- the captions: every number measured from the drawn data ---------------------------------

def _angles(values) -> str:
    return ", ".join(f"{v:g}" for v in values)


def _step(cases: dict[tuple, dict]) -> str:
    """The crank step of the drawn cases, in words (to 1e-9 deg)."""
    steps = np.unique(np.round(np.concatenate([np.diff(cases[key]["crank_deg"].astype(float))
                                               for key in drawn_cases() if key in cases]), 9))
    return f"{steps[0]:g} deg" if steps.size == 1 else f"{steps.min():g} to {steps.max():g} deg"


def s4_facts(cases: dict[str, dict]) -> str:
    """What the S4 figure shows, measured: where the engines agree, how far apart they are
    elsewhere; the positions the printed method needed DFP for, or did not solve."""
    engines = list(cases)
    planar, other = [], []
    for key, where in drawn_cases().items():
        a, b = (cases[e].get(key) for e in engines[:2])
        if a is None or b is None:
            continue
        gap = np.abs(a["s4"].astype(float) - b["s4"].astype(float))
        gap = float(np.nanmax(gap)) if np.isfinite(gap).any() else np.nan
        (planar if where["alpha4_deg"] == 270.0 and where["s1"] == 0.0 else other).append((gap, case_words(where)))
    planar, other = [(g, w) for g, w in planar if np.isfinite(g)], [(g, w) for g, w in other if np.isfinite(g)]
    text = []
    if planar:
        text.append(f"the largest S4 gap between {engines[0]} and {engines[1]} is {max(planar)[0]:.1e} in on the "
                    f"planar cases ({'; '.join(w for _, w in planar)})")
    if other:
        text.append(f"{min(other)[0]:.2g} to {max(other)[0]:.2g} in on the others (largest: {max(other)[1]})")
    sentences = ["Measured in this run: " + ", ".join(text) + "."] if text else []
    for engine, rows_of in cases.items():
        for status, what in (("dfp+newton", "needed the DFP fallback before Newton converged"),
                             ("not converged", "did not converge")):
            found = []
            for key, where in drawn_cases().items():
                rows = rows_of.get(key)
                k = np.flatnonzero(np.char.startswith(rows["status"].astype(str), status)) if rows is not None else []
                if len(k) == 0:
                    continue
                s4, at = rows["s4"].astype(float), rows["crank_deg"].astype(float)[k]
                jump = np.abs(s4[k] - s4[np.maximum(k - 1, 0)])
                found.append(f"{case_words(where)} at {_angles(at)} deg" + (
                    f" (S4 {np.nanmax(jump):.3g} in from the step before)" if np.isfinite(jump).any() else ""))
            if found:
                sentences.append(f"{engine} {what} at: " + "; ".join(found) + ".")
    return " ".join(sentences)


def load_facts(rows_of: dict[tuple, dict], drawn: list[tuple[str, Row]]) -> str:
    """What a loads figure shows, measured: the points beyond the y-limits and how far each
    lies from a dead centre of its case; the positions with no finite load, by status."""
    distances, far = [], 0
    for quantity, data in drawn:
        for family, curves in zip(FAMILIES, data.panels):
            for (_, where), (x, y) in zip(family_cases(family), curves):
                rows = rows_of.get(case_key(where))
                beyond = x[off_scale(y, data.limits)]
                if rows is None or beyond.size == 0:
                    continue
                dead = dead_centres(rows["crank_deg"].astype(float), rows["theta2"].astype(float))
                if dead.size == 0:
                    far += beyond.size
                    continue
                distances.append(np.min(np.abs(beyond[:, None] - dead[None, :]), axis=1))
    near = np.concatenate(distances) if distances else np.empty(0)
    sentence = f"Measured in this run: {near.size + far} drawn points lie beyond the y-limits"
    if near.size:
        sentence += (f"; {near.size} of them within {near.max():g} deg (median {np.median(near):g} deg) of a dead "
                     "centre of their case (a crank step over which the rod angle theta2 passes 0 or 180 deg)")
    text = [sentence + (f"; {far} in cases without a dead centre." if far else ".")]
    quantities = [quantity for quantity, _ in drawn]
    for key, where in drawn_cases().items():
        rows = rows_of.get(key)
        if rows is None:
            continue
        values = np.stack([rows[q].astype(float) for q in quantities], axis=1)
        missing = ~answered(rows) | ~np.isfinite(values).all(axis=1)
        for status in sorted(set(rows["status"][missing])):
            at = rows["crank_deg"][missing & (rows["status"] == status)]
            text.append(f"No finite load for {case_words(where)} at {_angles(at)} deg (status: {status}).")
    return " ".join(text)


def caption(what: str, step: str, rows: list[Row], facts: str, constants: dict[str, float] | None = None,
            equal: dict[str, tuple[float, str]] | None = None) -> str:
    """A figure's caption: what it shows, how to read it, what was measured, what is not drawn
    (constant, or equal to a drawn row or its negative)."""
    beyond = sum(int(off_scale(y, data.limits).sum()) for data in rows for curves in data.panels for _, y in curves)
    limits = ("a triangle on a panel's edge marks each run of points beyond it, and a curve breaks where it changes "
              "sign through a point beyond the limits (a pole) or has no finite value" if beyond else
              "no point lies beyond them, and a curve breaks only where it has no finite value")
    text = (f"{what}; against crank angle theta1 (deg), every computed point (crank steps of {step}). Columns: "
            "the three families of Rahman (1991) section 3.2 (figs. 5-38), each named above its column; in each "
            "panel the thick black line is the ideal planar case (a4 = 0, S1 = 0, alpha4 = 270 deg), the "
            f"coloured lines the family's three members. The y-limits of a row keep its 2nd to 98th percentile, "
            f"widened: {limits}. " + facts)
    if constants:
        text += " Constant over every drawn case, so not drawn: " + "; ".join(
            f"{POSITIONS[q].words} = {value:.6g} {POSITIONS[q].unit}" for q, value in constants.items()) + "."
    if equal:
        text += " Equal at every drawn point to a drawn row, so not drawn: " + "; ".join(
            f"{POSITIONS[q].words} = {'' if sign > 0 else 'minus '}{POSITIONS[other].words}"
            for q, (sign, other) in equal.items()) + "."
    return text


def load_rows(rows: dict[tuple, dict]) -> tuple[list[tuple[str, Row]], dict, dict]:
    """The loads' rows to draw, (quantity, row) in the order of ``LOADS``; the constant ones
    (quantity -> value) and those equal to a drawn one or its negative (quantity -> (sign, other))."""
    drawn, constants, equal = [], {}, {}
    for quantity in LOADS:
        words, unit = JOINT_LOADS[quantity[:2]]
        data = row(rows, quantity, f"{words.split(',')[0]}, {quantity[2]}\n({unit})")
        value, twin = constant_value(data.panels), same_as(data.panels, drawn)
        if value is not None:
            constants[quantity] = value
        elif twin is not None:
            equal[quantity] = twin
        else:
            drawn.append((quantity, data))
    return drawn, constants, equal


def figure_jobs(cases: dict[str, dict], out_dir: Path) -> list[tuple]:
    """``draw_figure``'s arguments for every figure: the displacement, then the loads per engine
    (every job the same length: ``draw_all`` zips them)."""
    step = _step(next(iter(cases.values())))
    s4 = [row(rows, "s4", f"{engine}\nS4 (in)") for engine, rows in cases.items()]
    jobs = [(out_dir / "fig_01_s4.png", "Slider displacement S4 (in), a row per engine", s4,
             caption("Slider displacement S4 (in), a row per engine (port_printed: the method as printed; "
                     "port_corrected: every registered bug removed)", step, s4, s4_facts(cases)), S4_ROW_H)]
    for engine, rows in cases.items():
        drawn, constants, equal = load_rows(rows)
        what = (f"The joint loads by {ENGINE_WORDS[engine]}: a row per component that varies (i, j, k along the "
                "axes of the frame of the link it acts on), joints 1 (crank on frame) to 4 (slider on frame)")
        loads = [data for _, data in drawn]
        jobs.append((out_dir / f"fig_{len(jobs) + 1:02d}_loads_{engine}.png", f"Joint loads, {ENGINE_WORDS[engine]}",
                     loads, caption(what, step, loads, load_facts(rows, drawn), constants, equal), ROW_H))
    return jobs


def plot_figures(results: dict[str, pd.DataFrame], out_dir: Path) -> list[Path]:
    """The figures (see the module docstring), drawn side by side (``report.draw_all``); returns
    the paths written, in reading order."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    cases = {engine: case_rows(frame) for engine, frame in results.items()}
    return draw_all(draw_figure, figure_jobs(cases, out_dir))
