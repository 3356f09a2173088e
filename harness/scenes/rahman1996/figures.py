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
from ...report import STYLE, curve_figure, draw_all
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


def plot_figures(pct: pd.DataFrame, outdir: Path) -> list[Path]:
    """Figures 5.1-5.6: every engine's decrement against crank angle."""
    jobs = []
    for k, table in enumerate(TABLES, start=1):
        curves = [(group["crank_deg"].to_numpy(), group["pct"].to_numpy(), engine, STYLE.get(engine, {}))
                  for engine, group in pct[pct["table"] == table].groupby("engine", sort=False)]
        title = f"Figure 5.{k}: {TABLE_QUANTITY[table].words} (Table 5.{k + 1}), decrement by balancing"
        jobs.append((curves, QUANTITIES["crank_deg"].label, QUANTITIES["pct"].label, title,
                     outdir / f"figure5_{k}.png"))
    return draw_all(curve_figure, jobs)


def run(out_dir: Path) -> dict:
    """Write out/rahman1996-figures/: percentages.csv, section5_3.csv, identities.csv (section
    5.3's quoted numbers against the published tables), figures, report.md."""
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    pct = percentages()
    pct.to_csv(target / "percentages.csv", index=False, float_format="%.6g")
    stats = section_5_3(pct)
    stats.to_csv(target / "section5_3.csv", index=False, float_format="%.6g")
    quoted = quoted_numbers.percentage_checks(register.load())
    write_csv(quoted, target / "identities.csv", "%.9g")
    plots = plot_figures(pct, target)
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
