"""Write a scene's results: CSVs in the published table's columns, diff.csv,
plots and report.md; and the summary report over all scenes."""
from __future__ import annotations

import multiprocessing
import os
import textwrap
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import pandas as pd
from matplotlib.figure import Figure

from .diff import EXPLAINED_BY, classify_cells, column_max, count_cells
from .figures import ENGINE_STYLE, MAX_WIDTH_IN, RC, new_figure, save
from .markdown_text import code_span, prose
from .register import Deviation, assumed_by


def markdown_table(frame: pd.DataFrame, floatfmt: str = "{:.3g}") -> str:
    """``frame`` as a markdown table, its index first; floats as ``floatfmt``, any other cell's text as
    written (``prose``: a ``|Delta|`` or ``REAL*4`` in a cell is not markup)."""
    cols = [prose(str(c)) for c in frame.columns]
    head = "| " + " | ".join([prose(frame.index.name or "")] + cols) + " |"
    rule = "|" + "---|" * (len(cols) + 1)
    lines = [head, rule]
    for idx, row in frame.iterrows():
        cells = [floatfmt.format(v) if isinstance(v, float) else prose(str(v)) for v in row]
        lines.append("| " + " | ".join([prose(str(idx))] + cells) + " |")
    return "\n".join(lines)


def panel_grid(width_in: float, across: int, down: int, panel_height_in: float, title: str, *,
               title_lines: int = 1, legend_rows: int = 1, left: float = 0.8, right: float = 0.2,
               bottom: float = 0.55, gap_across: float = 0.8) -> tuple[Figure, dict]:
    """A figure ``width_in`` wide for ``down`` x ``across`` panels of ``panel_height_in`` each, its
    ``title`` on top (wrapped to the width) with room under it for ``top_legend``'s ``legend_rows``
    rows and for panel titles of ``title_lines`` lines; and the ``subplots_adjust`` margins (for
    ``figures.save``) that leave, in inches, ``left``, ``right``, ``bottom`` around the panels,
    ``gap_across`` between them, and between rows their tick labels, x labels and titles."""
    heading = wrap_title(title, width_in - 0.3, RC["figure.titlesize"])
    titles = title_lines * line_height(RC["axes.titlesize"])
    top = _legend_top(heading) + legend_rows * LEGEND_ROW_IN + LEGEND_GAP_IN + titles
    gap_down = 0.55 + titles
    height = top + bottom + down * panel_height_in + (down - 1) * gap_down
    fig = new_figure(width_in, height)
    fig.suptitle(heading, y=1 - 0.08 / height, va="top")
    margins = dict(left=left / width_in, right=1 - right / width_in, bottom=bottom / height, top=1 - top / height,
                   wspace=gap_across / panel_width(width_in, across, left, right, gap_across),
                   hspace=gap_down / panel_height_in)
    return fig, margins


def panel_width(width_in: float, across: int, left: float = 0.8, right: float = 0.2, gap_across: float = 0.8) -> float:
    """The width (in) of each of ``across`` panels in a figure ``width_in`` wide (``panel_grid``'s room)."""
    return (width_in - left - right - (across - 1) * gap_across) / across


def wrap_title(words: str, width_in: float, size_pt: float = RC["axes.titlesize"]) -> str:
    """``words`` broken into lines that fit ``width_in`` at ``size_pt`` (DejaVu Sans: about 0.55
    of the size per character, on average, in words like these)."""
    return textwrap.fill(words, max(12, int(width_in * 72 / (0.55 * size_pt))))


def line_height(size_pt: float) -> float:
    """The height (in) of one line of text of ``size_pt``, with its spacing."""
    return 1.3 * size_pt / 72


#: the height (in) of a legend's row of 9 pt entries, and the space under the legend
LEGEND_ROW_IN, LEGEND_GAP_IN = 0.24, 0.16


def _legend_top(heading: str) -> float:
    """How far (in) under the figure's top edge the legend row starts, under ``heading``."""
    return 0.14 + (heading.count("\n") + 1) * line_height(RC["figure.titlesize"])


def top_legend(fig: Figure, handles: dict, rows: int = 1) -> None:
    """The legend of ``handles`` (label -> artist) in ``rows`` rows under the title ``panel_grid`` put."""
    fig.legend(list(handles.values()), list(handles), loc="upper center", ncols=-(-len(handles) // rows),
               frameon=False, borderaxespad=0.0,
               bbox_to_anchor=(0.5, 1 - _legend_top(fig.get_suptitle()) / fig.get_figheight()))


def plot_scene(scene, published, results: dict[str, pd.DataFrame], outdir: Path) -> list[Path]:
    """One figure for the table, ``<scene>/table.png``: small multiples, one panel per column (its
    words above, its unit on the axis), the published points over every engine's curve against
    the key column; the legend above the panels."""
    if not isinstance(scene.key, str):
        return []                          # rows named by text (Table 5.1): the CSVs say it all
    columns = len(scene.values)
    across = min(columns, 4)
    down = -(-columns // across)
    width = min(MAX_WIDTH_IN, 0.2 + across * (4.2 if across <= 2 else 2.95))
    titles = [wrap_title(scene.describe(col).words, panel_width(width, across)) for col in scene.values]
    fig, margins = panel_grid(width, across, down, 1.9 if across > 2 else 2.3, scene.title,
                              title_lines=max(t.count("\n") + 1 for t in titles))
    axes = fig.subplots(down, across, squeeze=False, sharex=True)
    key = scene.describe(scene.key)
    off_scale = []
    for ax, col, title in zip(axes.flat, scene.values, titles):
        for engine, frame in results.items():
            if frame[col].notna().any():
                ax.plot(frame[scene.key].to_numpy(), frame[col].to_numpy(), label=engine, **ENGINE_STYLE[engine])
        off = _published_points(ax, published.values[scene.key], published.values[col],
                                [frame[col] for frame in results.values()])
        off_scale += [f"{scene.describe(col).words} at {k:g} {key.unit}: {v:g}" for k, v in off.items()]
        ax.set_title(title, y=1.0)        # placed above the axes: matplotlib does not fit it (a layout pass)
        ax.set_ylabel(scene.describe(col).unit or "pure number")
        ax.grid(alpha=0.3)
    for ax in axes.flat[columns:]:
        ax.set_visible(False)
    for ax in axes.flat[max(0, columns - across):columns]:        # the lowest axes of each column
        ax.set_xlabel(key.label)
        ax.xaxis.set_tick_params(labelbottom=True)
    handles = {label: handle for ax in axes.flat for handle, label in zip(*ax.get_legend_handles_labels())}
    top_legend(fig, {label: handles[label] for label in sorted(handles, key=lambda h: h != "published")})
    caption = (f"{scene.title}: every column of the table against {key.label}, one panel per column (its "
               f"words above it, its unit on the axis); black dots the table as published, a line or mark per "
               f"engine (the legend). " + " ".join(_table_facts(scene, published, results))
               + (f" Published cells so far off the engines' curves that drawn to scale they would flatten them, "
                  f"drawn as a triangle at the panel's edge: {'; '.join(off_scale)}." if off_scale else ""))
    return [save(fig, outdir / "table.png", caption, **margins)]


#: a published cell farther than this many times its panel's curves' span beyond them is off the scale
OFF_SCALE_SPANS = 1.0
#: the look of a published cell off the scale: a triangle at the panel's edge, pointing out
OFF_SCALE = dict(color="k", ls="none", ms=6, clip_on=False, zorder=4)


def _published_points(ax, keys: pd.Series, values: pd.Series, curves: list[pd.Series]) -> dict:
    """Draw the published cells of one panel over the engines' ``curves``; a cell so far off them
    (``OFF_SCALE_SPANS``) that it would flatten the curves is drawn at the panel's edge as a
    triangle pointing its way, the panel scaled to the rest; returns those cells, key -> value."""
    drawn = pd.concat(curves).dropna()
    low, high = (drawn.min(), drawn.max()) if len(drawn) else (values.min(), values.max())
    span = (high - low) or abs(high) or 1.0
    off = (values < low - OFF_SCALE_SPANS * span) | (values > high + OFF_SCALE_SPANS * span)
    ax.plot(keys[~off].to_numpy(), values[~off].to_numpy(), label="published", **ENGINE_STYLE["published"])
    if off.any():
        shown = pd.concat([drawn, values[~off]]).dropna()
        pad = 0.06 * ((shown.max() - shown.min()) or span)
        bottom, top = shown.min() - pad, shown.max() + pad
        ax.set_ylim(bottom, top)
        for below in (True, False):
            at = off & ((values < low) if below else (values > high))
            if at.any():
                ax.plot(keys[at].to_numpy(), [bottom if below else top] * int(at.sum()), marker="v" if below else "^",
                        label="published, off the scale", **OFF_SCALE)
    return dict(zip(keys[off], values[off]))


def _table_facts(scene, published, results: dict[str, pd.DataFrame]) -> list[str]:
    """What ``plot_scene``'s figure shows, measured on its data: how many published cells lie more
    than half a unit of their last digit from legacy's value, how far port_printed is from legacy,
    how many cells the printed program gives and how many of them as published."""
    facts = []
    pub = published.values.set_index(scene.key)[scene.values]
    half = published.half_unit.set_axis(pub.index)[scene.values]
    engine = {name: frame.set_index(scene.key).reindex(pub.index)[scene.values] for name, frame in results.items()}

    def count(mask: pd.DataFrame) -> int:
        return int(mask.to_numpy().sum())

    def as_published(values: pd.DataFrame) -> pd.DataFrame:
        return (values - pub).abs() <= half * (1 + 1e-9)

    if "legacy" in engine:
        shown = pub.notna() & engine["legacy"].notna()
        facts.append(f"{count(shown & ~as_published(engine['legacy']))} of {count(shown)} published cells lie more "
                     "than half a unit of their last printed digit from legacy's value (the table's cells give "
                     "each one's status and register entries).")
        if "port_printed" in engine:
            gap = float((engine["port_printed"] - engine["legacy"]).abs().max().max())
            facts.append("The port with the listing's bugs (port_printed, dashed) lies on legacy's line: the two "
                         "are equal at every row." if gap == 0 else
                         f"The port with the listing's bugs (port_printed, dashed) differs from legacy by "
                         f"{gap:.2g} at most (in the columns' units).")
    given = pub.notna() & engine["printed"].notna() if "printed" in engine else pd.DataFrame()
    if count(given):
        facts.append(f"The printed program's own output (grey crosses, hidden under a dot where they agree) gives "
                     f"{count(given)} of the cells, {count(given & as_published(engine['printed']))} of them as "
                     "published.")
    if "port_corrected" in engine:
        facts.append("port_corrected is the port with the registered bugs removed.")
    return facts


def draw_all(draw, jobs: list[tuple]) -> list:
    """[draw(*job) for job in jobs], the figures drawn side by side: in a pool of os.cpu_count()
    forked processes (draw module-level, jobs picklable) when there are several jobs and cores
    and this is not a pool process itself (reproduce's, LINKREPRO_IN_POOL, or a daemon), else
    here.  The pool is shut down before this returns or raises."""
    workers = min(len(jobs), os.cpu_count() or 1)
    in_pool = os.environ.get("LINKREPRO_IN_POOL") or multiprocessing.current_process().daemon
    if workers < 2 or in_pool or "fork" not in multiprocessing.get_all_start_methods():
        return [draw(*job) for job in jobs]
    pool = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("fork"))
    try:
        return list(pool.map(draw, *zip(*jobs, strict=True)))     # jobs of unequal length: an error
    finally:
        pool.shutdown(cancel_futures=True)


def heading(column: str) -> str:
    """A column of ``diff.count_cells`` as every report heads it: a kind as 'explained: KIND'."""
    return f"explained: {column}" if column in EXPLAINED_BY else column


def counts_table(counts: pd.DataFrame) -> pd.DataFrame:
    """``diff.count_cells`` for a markdown table: every column headed by ``heading``, the kinds
    of ``explained`` that explain no cell of the table left out (their counts are all 0)."""
    shown = [c for c in counts.columns if c not in EXPLAINED_BY or counts[c].any()]
    return counts[shown].rename(columns=heading)


COUNTS_WORDS = ("A cell is *matched* when it is within half a unit of the printed last digit. Any other "
                "produced cell that register entries name is *explained* when an entry shows its cause (counted "
                "once, under that entry's kind, or under `several kinds` when its causes are of more than one); "
                "*within-tolerance* when its only explanation is closeness (an entry that states a tolerance: "
                "counted apart, not explained); *unresolved* when an `unresolved` entry names it (we do not know "
                "why it differs), unless a cause accounts for its whole difference; else *unexplained*, as is a "
                "cell nothing names; *not-produced*: the engine does not give it. diff.csv's status "
                "`registered` covers the explained, within-tolerance and unresolved cells.")


#: the heading of a scene report's part that renders the register entries its cells name
REGISTER_PART = "Register entries involved"
ASSUMPTIONS_WORDS = ("'Corrected' means the listings' bugs removed within the thesis's model: the corrected engine "
                     "keeps the thesis's modelling choices below (register kind `model-assumption`, not bugs), each "
                     "with the effect an alternative was measured to have.")


def assumptions_markdown(scene: str, register: dict[str, Deviation]) -> list[str]:
    """The section on what the corrected engine of ``scene`` still assumes (no lines where nothing)."""
    found = assumed_by(scene, register)
    if not found:
        return []
    return (["## What the corrected engine still assumes", "", ASSUMPTIONS_WORDS, ""]
            + [f"- **{entry.id}** {prose(entry.title)}. {prose(entry.effect)}" for entry in found] + [""])


def render_entry(entry: Deviation) -> str:
    """A register entry in markdown: its words as written (``prose``), printed, meant and quirk as code."""
    lines = [f"#### {entry.id} ({entry.kind}{', ' + entry.certainty if entry.certainty else ''}): {prose(entry.title)}",
             *(f"- {name}: {prose(text)}" for name, text in entry.how_known()),
             f"- where: {prose(entry.where)}", f"- printed: {code_span(entry.printed)}",
             f"- meant: {code_span(entry.meant)}", f"- evidence: {prose(entry.evidence)}", f"- effect: {prose(entry.effect)}"]
    if entry.quirk:
        lines.append(f"- port quirk: {code_span(entry.quirk)}")
    return "\n".join(lines)


def scene_report(scene, diff: pd.DataFrame, timings: dict[str, float], register: dict[str, Deviation],
                 plots: list[Path], extra: str = "") -> str:
    counts = count_cells(diff, register)
    ids = sorted({i for s in diff["register_ids"] for i in s.split()})
    unexplained = diff[classify_cells(diff, register)["count"] == "unexplained"]
    out = [f"# {scene.title}", "", f"Scene `{scene.name}`; published table `harness/published/{scene.table}.csv`.",
           "", f"**Inputs.** {scene.inputs}", ""]
    out += [f"- {n}" for n in scene.notes]
    out += ["", "## Cells against the published table",
            "", COUNTS_WORDS + " Kinds that explain no cell of this table are left out.", "",
            markdown_table(counts_table(counts), "{}"), "",
            *assumptions_markdown(scene.name, register),
            "## Largest |engine - published| per column (over produced cells)", "",
            markdown_table(column_max(diff, "abs_diff")), "",
            "## Largest |engine - legacy| per column", "",
            markdown_table(column_max(diff, "diff_vs_legacy"), "{:.2e}"), "",
            "## Wall time per engine (s, this run)", "",
            "| engine | seconds |", "|---|---|"]
    out += [f"| {k} | {v:.4f} |" for k, v in timings.items()]
    out += ["", "## Unexplained cells", ""]
    if unexplained.empty:
        out.append("None.")
    else:
        out.append(markdown_table(unexplained.set_index("engine")[[scene.key_name, "column", "published_text", "value"]],
                             "{:.6g}"))
    if extra:
        out += ["", extra]
    out += ["", "## Plot", ""] + [f"![{p.stem}]({p.name})" for p in plots]
    out += ["", f"## {REGISTER_PART}", ""] + [render_entry(register[i]) + "\n" for i in ids if i in register]
    return "\n".join(out) + "\n"
