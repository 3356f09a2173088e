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
from .register import Deviation

STYLE = {"published": dict(marker="o", ls="none", color="k", ms=4),
         "printed": dict(marker="x", ls="none", color="tab:gray"),
         "legacy": dict(ls="-", color="tab:blue"),
         "port_printed": dict(ls="--", color="tab:orange"),
         "port_corrected": dict(ls="-", color="tab:green", alpha=0.8)}


def markdown_table(frame: pd.DataFrame, floatfmt: str = "{:.3g}") -> str:
    cols = [str(c) for c in frame.columns]
    head = "| " + " | ".join([frame.index.name or ""] + cols) + " |"
    rule = "|" + "---|" * (len(cols) + 1)
    lines = [head, rule]
    for idx, row in frame.iterrows():
        cells = [floatfmt.format(v) if isinstance(v, float) else str(v) for v in row]
        lines.append("| " + " | ".join([str(idx)] + cells) + " |")
    return "\n".join(lines)


def plot_scene(scene, published, results: dict[str, pd.DataFrame], outdir: Path) -> list[Path]:
    """One figure for the table, ``<scene>/table.png``: small multiples, one axes per column, the
    published points over every engine's curve against the key column (its words and unit)."""
    if not isinstance(scene.key, str):
        return []                          # rows named by text (Table 5.1): the CSVs say it all
    frames = {"published": published.values, **results}
    columns = len(scene.values)
    across = min(columns, 4)
    down = -(-columns // across)
    fig = Figure(figsize=(3.3 * across, 2.35 * down + 0.85))
    axes = fig.subplots(down, across, squeeze=False, sharex=True)
    key = scene.describe(scene.key)
    for ax, col in zip(axes.flat, scene.values):
        what = scene.describe(col)
        for engine, frame in frames.items():
            if engine == "published" or frame[col].notna().any():
                ax.plot(frame[scene.key].to_numpy(), frame[col].to_numpy(), label=engine, **STYLE.get(engine, {}))
        ax.set_title(textwrap.fill(what.words, 40), fontsize=7.5)
        ax.set_ylabel(what.unit, fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
    for ax in axes.flat[columns:]:
        ax.set_visible(False)
    for ax in axes.flat[max(0, columns - across):columns]:        # the lowest axes of each column
        ax.set_xlabel(key.label, fontsize=8)
        ax.xaxis.set_tick_params(labelbottom=True)
    legend = {label: handle for ax in axes.flat for handle, label in zip(*ax.get_legend_handles_labels())}
    height = 2.35 * down + 0.85
    fig.suptitle(scene.title, fontsize=9, y=1 - 0.08 / height, va="top")
    fig.legend(list(legend.values()), list(legend), loc="upper center", ncol=len(legend), fontsize=8,
               frameon=False, bbox_to_anchor=(0.5, 1 - 0.3 / height))
    return [save_png(fig, outdir / "table.png", left=0.6 / (3.3 * across), right=0.99, bottom=0.5 / height,
                     top=1 - 0.85 / height, hspace=0.6, wspace=0.3)]


def curve_figure(curves: list[tuple], xlabel: str, ylabel: str, title: str, path: Path) -> Path:
    """The one style of every curve plot: curves (x, y, label, plot style) on one 6.4 x 3.6 in
    axes, labelled, gridded, with a legend; saved as PNG."""
    fig = Figure(figsize=(6.4, 3.6))
    ax = fig.add_subplot()
    for x, y, label, style in curves:
        ax.plot(x, y, label=label, **style)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return save_png(fig, path, left=0.155, right=0.977, bottom=0.165, top=0.905)


def save_png(fig: Figure, path: Path, **margins) -> Path:
    """Save at 90 dpi with fixed margins (fig.subplots_adjust: tight_layout would cost as much
    as the drawing, and a second drawing in savefig); fast zlib level, the same pixels."""
    fig.subplots_adjust(**margins)
    fig.savefig(path, dpi=90, pil_kwargs={"compress_level": 1})
    return path


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
        return list(pool.map(draw, *zip(*jobs)))
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
                "produced cell is *explained* when a register entry of a kind other than `unresolved` names "
                "it (counted once, under that kind, or under `several kinds` when its entries are of more "
                "than one), *unresolved* when only `unresolved` entries name it (we do not know why it "
                "differs), else *unexplained*; *not-produced*: the engine does not give it. diff.csv's "
                "status `registered` covers both explained and unresolved cells.")


def render_entry(entry: Deviation) -> str:
    lines = [f"#### {entry.id} ({entry.kind}{', ' + entry.certainty if entry.certainty else ''}): {entry.title}",
             f"- where: {entry.where}", f"- printed: `{entry.printed}`", f"- meant: `{entry.meant}`",
             f"- evidence: {entry.evidence}", f"- effect: {entry.effect}"]
    if entry.quirk:
        lines.append(f"- port quirk: `{entry.quirk}`")
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
    out += ["", "## Register entries involved", ""] + [render_entry(register[i]) + "\n" for i in ids if i in register]
    return "\n".join(out) + "\n"
