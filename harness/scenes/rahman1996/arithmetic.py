"""Which digits survive a change of arithmetic: Rahman (1996) Tables 5.1-5.7 (register D056).

The legacy build (legacy/src, the FORTRAN the ``legacy`` engine runs) is rebuilt in a
temporary folder under each arithmetic a 1996 machine may have used: optimisation levels,
x87 extended intermediates (with and without ``-ffloat-store``, with the precision control
at 53 bits, with the x87's own SIN/COS/ATAN), fused multiply-add, REAL promoted to 64 bits,
and three ways of keeping the listing's literal constants in double (a source transform on
a temporary copy; legacy/ is never written).  Each build is run by a small driver that WRITEs
the whole TABLE and INERT of ``CSSP`` in full precision; the tables are formed by the same
``as_tables`` as the legacy engine's and compared with harness/published/ by the harness's
rule (within half a unit of the printed last digit, ``diff.py``).

Per variant and per table: the cells at the printed digit, within 1e-7 and 1e-6 relative
(``arithmetic.csv``); per cell: which variants reach the printed digit, how many distinct
values the variants give and whether every variant prints the same digits
(``arithmetic_cells.csv``).  A variant is adopted only if it stands for an arithmetic
documented for machines of the time AND raises the count in every one of Tables 5.2-5.7
without lowering Table 5.1: ``meets_criterion``.  None is adopted into
the default build here; the verdict is reported.

Needs gfortran on PATH (``readings.CompilerError`` otherwise) and the source tree's legacy/.
Run: ``linkrepro arithmetic --out out/arithmetic`` (17 builds, about 20 s of CPU: 10-12 s on two
free cores), not part of ``linkrepro reproduce``, whose report links the result when it is there.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from ... import progress
from ...csv_output import write_csv
from ...published_tables import PublishedTable
from .arithmetic_build import Measurement, ReferenceFailed, measure
from .arithmetic_variants import VARIANTS

TABLES = ("5_1", "5_2", "5_3", "5_4", "5_5", "5_6", "5_7")
#: the tables whose every count a variant must raise to be adopted (Table 5.1 must not drop)
SERIES = TABLES[1:]
COMMAND = "linkrepro arithmetic --out out/arithmetic"
OUTPUTS = ("arithmetic.csv", "arithmetic_cells.csv", "arithmetic.md")

__all__ = ["TABLES", "SERIES", "COMMAND", "OUTPUTS", "ReferenceFailed", "cell_frame", "count_frame",
           "meets_criterion", "as_markdown", "write"]


def _published(table: str) -> PublishedTable:
    return PublishedTable.load(f"rahman1996_table{table}")


def _cells(table: str) -> tuple[pd.DataFrame, list[str], list[str]]:
    """(published values, the value columns, each row's name as the harness writes it)."""
    pub = _published(table)
    if table == "5_1":
        names = [f"{a}/{b}" for a, b in zip(pub.text["link"], pub.text["quantity"])]
    else:
        names = [str(int(v)) for v in pub.values["crank_deg"]]
    return pub, ["before", "after"], names


def _decimals(half: float) -> int:
    return int(round(-np.log10(2.0 * half)))


def cell_frame(m: Measurement) -> pd.DataFrame:
    """One row per published cell: reference value, per variant value and whether it is
    at the printed digit, and the summary columns (see ``as_markdown``)."""
    rows = []
    ran = m.ran
    ref = ran[0].name
    rounding = [ref] + [v.name for v in ran[1:] if v.keeps_types]
    for table in TABLES:
        pub, cols, names = _cells(table)
        values, half, text = pub.values, pub.half_unit, pub.text
        for name in [v.name for v in ran]:
            frame = m.values[name][table]
            if table == "5_1":
                same = [f"{x}/{y}" for x, y in zip(frame["link"], frame["quantity"])] == names
            else:
                same = np.array_equal(frame["crank_deg"].to_numpy(float), values["crank_deg"].to_numpy(float))
            if not same:
                raise ReferenceFailed(f"Table {table}: the rows of variant {name} are not the published rows")
        rows_at = values.index               # each variant's column at the published rows' labels
        columns = {(v.name, col): m.values[v.name][table][col].loc[rows_at].tolist() for v in ran for col in cols}
        for i, row in enumerate(names):
            for col in cols:
                target, tol = float(values.at[i, col]), float(half.at[i, col])
                got = {v.name: float(columns[v.name, col][i]) for v in ran}
                at = {n: abs(x - target) <= tol * (1.0 + 1e-9) for n, x in got.items()}
                d = _decimals(tol)
                printed_as = {n: f"{round(x, d):.{d}f}" for n, x in got.items()}
                same = len(set(printed_as.values())) == 1
                same_rounding = len({printed_as[n] for n in rounding}) == 1
                spread = max(got.values()) - min(got.values())
                spread_rounding = max(got[n] for n in rounding) - min(got[n] for n in rounding)
                reached = [n for n in got if at[n]]
                record = {"table": table.replace("_", "."), "row": row, "column": col,
                          "published_text": text.at[i, col], "published": target, "half_unit": tol,
                          "reference": got[ref], "reference_rel_err": abs(got[ref] - target) / abs(target),
                          "reached_by": " ".join(reached), "n_reached": len(reached), "n_variants": len(got),
                          "distinct_values": len(set(got.values())),
                          "rel_spread": spread / abs(got[ref]) if got[ref] else np.nan,
                          "rel_spread_rounding": spread_rounding / abs(got[ref]) if got[ref] else np.nan,
                          "same_printed_digits": same, "same_printed_digits_rounding": same_rounding,
                          "sensitivity": ("always" if len(reached) == len(got) else
                                          "never" if not reached else "compiler-sensitive")}
                record.update({f"value:{n}": x for n, x in got.items()})
                rows.append(record)
    return pd.DataFrame(rows)


def count_frame(m: Measurement, cells: pd.DataFrame | None = None) -> pd.DataFrame:
    """One row per variant and table (and an 'all' row per variant): cells at the printed
    digit, within 1e-7 and 1e-6 relative, and cells whose value differs from the reference."""
    cells = cell_frame(m) if cells is None else cells
    ref = m.ran[0].name
    rows = []
    for v in m.ran:
        value = cells[f"value:{v.name}"]
        rel = (value - cells["published"]).abs() / cells["published"].abs()
        frame = pd.DataFrame({"table": cells["table"],
                              "at": (value - cells["published"]).abs() <= cells["half_unit"] * (1.0 + 1e-9),
                              "r7": rel <= 1e-7, "r6": rel <= 1e-6,
                              "changed": value != cells[f"value:{ref}"],
                              "move": (value - cells[f"value:{ref}"]).abs() / cells[f"value:{ref}"].abs()})
        for table, part in list(frame.groupby("table", sort=True)) + [("all", frame)]:
            rows.append({"variant": v.name, "table": table, "cells": len(part),
                         "at_printed_digit": int(part["at"].sum()), "within_1e-7": int(part["r7"].sum()),
                         "within_1e-6": int(part["r6"].sum()), "cells_changed": int(part["changed"].sum()),
                         "max_rel_change": float(part["move"].max()), "documented": v.documented})
    counts = pd.DataFrame(rows)
    base = counts[counts["variant"] == ref].set_index("table")["at_printed_digit"]
    counts["gain"] = counts["at_printed_digit"] - counts["table"].map(base)
    return counts


def meets_criterion(counts: pd.DataFrame) -> dict[str, bool]:
    """Per variant: documented for machines of the time, raises the count in every one of
    Tables 5.2-5.7 and does not lower Table 5.1."""
    out = {}
    for name, part in counts.groupby("variant", sort=False):
        gain = part.set_index("table")["gain"]
        out[name] = bool(part["documented"].iloc[0]
                         and all(gain[t.replace("_", ".")] > 0 for t in SERIES) and gain["5.1"] >= 0)
    return out


def _closest(m: Measurement, counts: pd.DataFrame) -> str:
    """One sentence on the documented variant with the most cells at the printed digit."""
    ref = m.ran[0].name
    total = counts[(counts["table"] == "all") & counts["documented"] & (counts["variant"] != ref)]
    if total.empty:
        return ""
    best = total.sort_values("at_printed_digit", ascending=False, kind="stable").iloc[0]
    part = counts[(counts["variant"] == best["variant"]) & (counts["table"] != "all")].set_index("table")
    base = counts[(counts["variant"] == ref) & (counts["table"] == "all")]["at_printed_digit"].iloc[0]
    gains = ", ".join(f"{t} {int(g):+d}" for t, g in part["gain"].items())
    flat = [t for t, g in part["gain"].items() if g == 0]
    return (f"Closest documented variant: **{best['variant']}**, {int(best['at_printed_digit'])} cells at the "
            f"printed digit against {int(base)} for {ref} (per table: {gains})"
            + (f"; it does not raise {', '.join(flat)}" if flat else "") + ".")


def _rows_list(part: pd.DataFrame) -> str:
    out = []
    for col, sub in part.groupby("column", sort=False):
        out.append(f"{col} {', '.join(sub['row'])}")
    return "; ".join(out)


def as_markdown(m: Measurement, counts: pd.DataFrame, cells: pd.DataFrame) -> str:
    ref = m.ran[0].name
    verdict = meets_criterion(counts)
    adopted = [n for n, ok in verdict.items() if ok]
    lines = ["## Which digits survive a change of arithmetic (register D056)", "",
             f"The legacy FORTRAN (legacy/src) rebuilt under {len(m.variants)} arithmetics a 1996 machine "
             f"may have used, each run once; its Tables 5.1-5.7 ({len(cells)} cells) against the published "
             "digits. Re-measure: `" + COMMAND + "`; per-variant counts in arithmetic.csv, the per-cell "
             "matrix in arithmetic_cells.csv.", "",
             "The seed (000, Rahman 1996) names no computer or compiler; it names only the IMSL routines "
             "QPROG and UMACH (chapter 4, Appendix B), whose single-precision QPROG the listing calls "
             "with REAL arrays. The variants stand for the machines below; 'documented' means the "
             "arithmetic is described for compilers of the time.", "",
             "| variant | how | stands for | documented |", "|---|---|---|---|"]
    lines += [f"| {v.name} | `{v.how}` | {v.machine} | {'yes' if v.documented else 'no'} |" for v in m.variants]
    if m.failures:
        lines += ["", "Not run on this machine: " + "; ".join(f"{n} ({why})" for n, why in m.failures.items()) + "."]
    head = [t.replace("_", ".") for t in TABLES]
    lines += ["", "### Cells at the printed digit, per variant and table", "",
              "| variant | " + " | ".join(head) + " | all | within 1e-7 | within 1e-6 | cells changed | "
              "largest change (rel) | tables raised / lowered | 'before' / 'after' cells | adopt? |",
              "|---|" + "---|" * (len(head) + 8)]
    by_column = {v.name: {col: int(sum(v.name in str(r).split() for r in part["reached_by"]))
                          for col, part in cells.groupby("column")} for v in m.ran}
    for v in m.ran:
        part = counts[counts["variant"] == v.name].set_index("table")
        ncells = part["cells"]
        lines.append(f"| {v.name} | " + " | ".join(f"{part.at[t, 'at_printed_digit']}/{ncells[t]}" for t in head)
                     + f" | {part.at['all', 'at_printed_digit']}/{ncells['all']} | {part.at['all', 'within_1e-7']}"
                     f" | {part.at['all', 'within_1e-6']} | {part.at['all', 'cells_changed']}"
                     f" | {part.at['all', 'max_rel_change']:.1e} | {(part.loc[head, 'gain'] > 0).sum()} / "
                     f"{(part.loc[head, 'gain'] < 0).sum()} | {by_column[v.name].get('before', 0)} / "
                     f"{by_column[v.name].get('after', 0)} | {'yes' if verdict[v.name] else 'no'} |")
    lines += ["", "**Criterion**: a variant is adopted only if its arithmetic is documented for "
              "machines of the time and it raises the count in every one of Tables 5.2-5.7 without "
              "lowering Table 5.1; never cell by cell. "
              + (f"Met by: {', '.join(adopted)} (not adopted into the default build here: the register decides)."
                 if adopted else "Met by no variant: the default build stays as it is.")]
    closest = _closest(m, counts)
    if closest:
        lines += ["", closest]
    sens = cells.groupby("table")["sensitivity"].value_counts().unstack(fill_value=0)
    sens = sens.reindex(columns=["always", "compiler-sensitive", "never"], fill_value=0)
    same = cells.groupby("table")["same_printed_digits"].sum()
    same_r = cells.groupby("table")["same_printed_digits_rounding"].sum()
    rounding = ", ".join(v.name for v in m.ran if v.keeps_types)
    lines += ["", "### Which cells are sensitive to the compiler at all", "",
              "Per table: cells at the printed digit under every variant (always), under some "
              "(compiler-sensitive), under none (never); and cells whose printed digits (rounded to the "
              "published decimals) are the same under every variant that keeps the program's types "
              f"({rounding}: a change of compiler, optimisation or floating-point unit) and under every "
              "variant. Those are the digits an archival regression test may hold fixed across compilers.", "",
              "| table | cells | always | compiler-sensitive | never | same printed digits, types kept | "
              "same printed digits, every variant |", "|---|---|---|---|---|---|---|"]
    for table, row in sens.iterrows():
        lines.append(f"| {table} | {int(row.sum())} | {row['always']} | {row['compiler-sensitive']} | "
                     f"{row['never']} | {int(same_r[table])} | {int(same[table])} |")
    lines.append(f"| all | {len(cells)} | {int(sens['always'].sum())} | {int(sens['compiler-sensitive'].sum())} | "
                 f"{int(sens['never'].sum())} | {int(same_r.sum())} | {int(cells['same_printed_digits'].sum())} |")
    moved = cells[cells["distinct_values"] > 1]
    lines += ["", f"{len(moved)} of {len(cells)} cells take more than one value across the variants; the largest "
              f"spread is {cells['rel_spread'].max():.1e} relative (median over those cells "
              f"{moved['rel_spread'].median() if len(moved) else 0.0:.1e}); over the variants that keep the "
              f"types, {cells['rel_spread_rounding'].max():.1e} (median "
              f"{cells['rel_spread_rounding'].median():.1e}).", "",
              "Compiler-sensitive cells (the printed digit is reached under some arithmetics and not others):", ""]
    sensitive = cells[cells["sensitivity"] == "compiler-sensitive"]
    for table, part in sensitive.groupby("table"):
        lines.append(f"- {table}: {_rows_list(part)}")
    if sensitive.empty:
        lines.append("- none")
    flipped = cells[~cells["same_printed_digits_rounding"]]
    lines += ["", "Cells whose printed digits change under a variant that keeps the types (a change of compiler "
              "alone):", ""]
    lines += [f"- {table}: {_rows_list(part)}" for table, part in flipped.groupby("table")] or ["- none"]
    lines += ["", f"Reference: `{ref}` (meson.build's flags), the legacy engine's own build; {m.seconds:.1f} s "
              "for the builds and runs of this measurement."]
    return "\n".join(lines)


def write(out_dir: Path, variants=VARIANTS) -> tuple[Measurement, pd.DataFrame, pd.DataFrame, str]:
    """Measure and write DIR/arithmetic.csv, DIR/arithmetic_cells.csv, DIR/arithmetic.md; a
    progress line over the builds on standard error when it is a terminal."""
    variants = list(variants)
    with progress.Bar(len(variants)):
        progress.note("arithmetic", "gfortran builds and runs")
        m = measure(variants, on_done=progress.done)
    cells = cell_frame(m)
    counts = count_frame(m, cells)
    text = as_markdown(m, counts, cells)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    write_csv(counts, out_dir / "arithmetic.csv", "%.9g")
    write_csv(cells, out_dir / "arithmetic_cells.csv", "%.17g")
    (out_dir / "arithmetic.md").write_text("# Rahman (1996): which digits survive a change of arithmetic\n\n"
                                           + text.split("\n", 1)[1].lstrip() + "\n")
    return m, counts, cells, text


if __name__ == "__main__":                 # python -m linkrepro.harness.scenes.rahman1996.arithmetic [DIR]
    import sys
    print(write(Path(sys.argv[1] if len(sys.argv) > 1 else "out/arithmetic"))[3])
