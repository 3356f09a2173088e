"""Scene rahman1996-figures: Figures 5.1-5.6 (percentage decrement against crank angle)
replotted from every engine, and the percentages quoted in section 5.3 recomputed
beside the printed text.

The percentage is the listing's own: (before - after) * 100 / before, per position.
"""
from __future__ import annotations

from pathlib import Path

import pandas as pd

from ... import register
from . import quoted_numbers
from .quoted_numbers import decrement_pct
from ...csv_output import write_csv
from ...published_tables import PUBLISHED_DIR, PublishedTable
from ...figures import ENGINE_STYLE, save
from ...report import panel_grid, panel_width, top_legend, wrap_title
from ....port.rahman1996.quirks import CSSP_CORRECTED, CSSP_PRINTED
from ...scene import ReportScene
from .quantities import FIGURES as QUANTITIES, TABLE_QUANTITY
from .tables import CRANK_DEG, GROUP, START, legacy_tables, port_tables, printed_run

NAME = "rahman1996-figures"
TITLE = "Rahman (1996) Figures 5.1-5.6 and the section 5.3 percentages"
TABLES = ["5_2", "5_3", "5_4", "5_5", "5_6", "5_7"]


def percentages() -> pd.DataFrame:
    """Long table: table, engine, crank_deg, pct, for every engine that gives it."""
    sources = {"published": {t: PublishedTable.load(f"rahman1996_table{t}").values for t in TABLES},
               "legacy": legacy_tables(), "port_printed": port_tables(CSSP_PRINTED),
               "port_corrected": port_tables(CSSP_CORRECTED)}
    frames = [pd.DataFrame({"table": t, "engine": engine, "crank_deg": CRANK_DEG,
                            "pct": decrement_pct(tables[t])})
              for engine, tables in sources.items() for t in TABLES]
    frames.append(pd.DataFrame({"table": "5_7", "engine": "printed", "crank_deg": CRANK_DEG,
                                "pct": printed_run()["dint_pct"][:, 1]}))
    return pd.concat(frames, ignore_index=True)


def section_5_3(pct: pd.DataFrame) -> pd.DataFrame:
    """Per table and engine: largest and smallest decrement, averages, where it is negative;
    beside the text's quoted range and average."""
    text = pd.read_csv(PUBLISHED_DIR / "rahman1996_section5_3.csv", comment="#", dtype={"table": str})
    rows = []
    for (table, engine), group in pct.groupby(["table", "engine"], sort=False):
        quoted = text.set_index("table").loc[table]
        p = group["pct"].to_numpy()
        negative = group.loc[group["pct"] < 0, "crank_deg"].astype(int).tolist()
        rows.append({"table": table, "figure": quoted["figure"], "engine": engine,
                     "max_pct": p.max(), "at_deg": int(group["crank_deg"].iloc[p.argmax()]),
                     "min_pct": p.min(), "min_at_deg": int(group["crank_deg"].iloc[p.argmin()]),
                     "mean37_pct": p.mean(), "mean36_pct": p[:-1].mean(),
                     "negative_at_deg": " ".join(map(str, negative)) or "none",
                     "text_range": f"{quoted['range_from']} to {quoted['range_to']}",
                     "text_average": quoted["average"], "text_claim": quoted["claim"]})
    return pd.DataFrame(rows)


def plot_figures(pct: pd.DataFrame, outdir: Path, misprinted: set[tuple[str, float]]) -> list[Path]:
    """Figures 5.1-5.6 in one figure, ``figures5_1-5_6.png``: a panel per figure, every engine's
    decrement (%) against crank angle (deg); ``misprinted``: the (table, crank angle) of the
    cells the register gives as misprinted (its caption counts the published outliers among them)."""
    across = 3
    fig, margins = panel_grid(12.0, across, -(-len(TABLES) // across), 2.4,
                              "Rahman (1996) Figures 5.1-5.6: decrement by optimum balancing, (before - after) / "
                              "before, against crank angle", title_lines=2)
    axes = fig.subplots(-(-len(TABLES) // across), across, squeeze=False, sharex=True)
    for k, (ax, table) in enumerate(zip(axes.flat, TABLES), start=1):
        for engine, group in pct[pct["table"] == table].groupby("engine", sort=False):
            ax.plot(group["crank_deg"].to_numpy(), group["pct"].to_numpy(), label=engine, **ENGINE_STYLE[engine])
        ax.set_title(f"Figure 5.{k} (Table 5.{k + 1})\n"
                     + wrap_title(TABLE_QUANTITY[table].words, panel_width(12.0, across)), y=1.0)   # no layout pass
        ax.set_ylabel(f"decrement ({QUANTITIES['pct'].unit})")
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel(QUANTITIES["crank_deg"].label)
    top_legend(fig, {label: h for ax in axes.flat for h, label in zip(*ax.get_legend_handles_labels())})
    caption = ("The decrement of each quantity by optimum balancing, (before - after) * 100 / before at each "
               "crank position, as Figures 5.1-5.6 plot it: black dots from the published Tables 5.2-5.7, a line or "
               "mark per engine (the legend). Measured: " + "; ".join(_figure_facts(pct, misprinted)) + ".")
    return [save(fig, outdir / "figures5_1-5_6.png", caption, **margins)]


#: a published point this far from legacy's (percentage points) is an outlier the caption names
OUTLIER_PCT = 1.0


def _figure_facts(pct: pd.DataFrame, misprinted: set[tuple[str, float]]) -> list[str]:
    """What ``plot_figures`` shows, measured on ``pct``: port_printed against legacy, the figures
    the printed program gives, the published outliers and how many sit at a misprinted cell."""
    wide = pct.pivot_table(index=["table", "crank_deg"], columns="engine", values="pct")
    figure = {t: f"5.{k}" for k, t in enumerate(TABLES, start=1)}
    gap = float((wide["port_printed"] - wide["legacy"]).abs().max())
    facts = ["the port with the listing's bugs (port_printed, dashed) " +
             ("lies on legacy's line, equal at every point" if gap == 0 else f"differs from legacy by {gap:.2g} % at most")]
    printed = sorted(pct.loc[pct["engine"] == "printed", "table"].unique())
    facts.append(f"the printed program gives Figure{'s' if len(printed) > 1 else ''} "
                 f"{', '.join(figure[t] for t in printed) or 'none'} (grey crosses)")
    off = (wide["published"] - wide["legacy"]).abs()
    outliers = off[off > OUTLIER_PCT].index.tolist()
    where = ", ".join(f"Figure {figure[t]} at {deg:g} deg" for t, deg in outliers)
    facts.append(f"{len(outliers)} published points lie more than {OUTLIER_PCT:g} percentage point from legacy's "
                 f"({where or 'none'}), {sum(o in misprinted for o in outliers)} of them at a table cell the "
                 "register gives as misprinted" if outliers else
                 f"no published point lies more than {OUTLIER_PCT:g} percentage point from legacy's")
    facts.append("port_corrected is the port with the registered bugs removed")
    return facts


def misprinted_cells(entries: dict) -> set[tuple[str, float]]:
    """(table, crank angle) of every cell of Tables 5.2-5.7 a published-misprint entry names."""
    return {(t, float(row)) for entry in entries.values() if entry.kind == "published-misprint"
            for claim in entry.cells for t in TABLES if claim.scene == f"rahman1996-table{t}"
            for row in claim.rows if row != "*"}


def run(out_dir: Path) -> dict:
    """Write out/rahman1996-figures/: percentages.csv, section5_3.csv, identities.csv (section
    5.3's quoted numbers against the published tables), figures, report.md."""
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    pct = percentages()
    pct.to_csv(target / "percentages.csv", index=False, float_format="%.6g")
    stats = section_5_3(pct)
    stats.to_csv(target / "section5_3.csv", index=False, float_format="%.6g")
    entries = register.load()
    quoted = quoted_numbers.percentage_checks(entries)
    write_csv(quoted, target / "identities.csv", "%.9g")
    plots = plot_figures(pct, target, misprinted_cells(entries))
    lines = ["# Rahman (1996), Figures 5.1-5.6 and the percentages of section 5.3", "",
             "Decrement (before - after) * 100 / before at each of the 37 crank positions, as the listing "
             "computes it (DOBJFUN, dshf, dsht, dbrf, dbrt, dint), from the published tables and from each "
             "engine; the printed engine gives only dint (the one live WRITE). The text's range and average "
             "(seed 000 lines 1213-1225) are set beside; mean37 averages all 37 rows, mean36 leaves out the "
             "repeated 360 row.", "",
             "| table | figure | engine | max % (deg) | min % (deg) | mean37 % | mean36 % | negative at | text: range; average | text claim |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in stats.itertuples(index=False):
        lines.append(f"| {r.table} | {r.figure} | {r.engine} | {r.max_pct:.4f} ({r.at_deg}) | "
                     f"{r.min_pct:.4f} ({r.min_at_deg}) | {r.mean37_pct:.4f} | {r.mean36_pct:.4f} | "
                     f"{r.negative_at_deg} | {r.text_range}; {r.text_average} | {r.text_claim} |")
    lines += ["", "See register entries D058 (misprints that produce the published outliers) and D059 "
              "(the averages).", "", quoted_numbers.percentages_markdown(quoted), "", "## Figures", ""] + [f"![{p.stem}]({p.name})" for p in plots]
    (target / "report.md").write_text("\n".join(lines) + "\n")
    return {"scene": NAME, "title": TITLE, "stats": stats}


def overview(_) -> list[str]:
    return ["Recomputed from every engine beside the printed text."]


SCENE = ReportScene(name=NAME, title=TITLE, group=GROUP, start=START, produce=run, overview=overview)
