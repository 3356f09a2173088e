"""Which digits survive a change of arithmetic: Rahman (1996) Tables 5.1-5.7 (register D056, D180).

The legacy build (legacy/src, the FORTRAN the ``legacy`` engine runs) is rebuilt in a
temporary folder under each arithmetic a 1996 machine may have used: optimisation levels,
x87 extended intermediates (with and without ``-ffloat-store``, with the precision control
at 53 bits, with the x87's own SIN/COS/ATAN), fused multiply-add, REAL promoted to 64 bits,
and the ways of reading the listing's literal constants (a source transform on a temporary
copy; legacy/ is never written).  The reference is the arithmetic register D180 adopts: a
literal assigned to a REAL*8 variable taken as double; the standard's reading (every literal
REAL*4, gfortran's default) is the variant ``single-constants``.  Each build is run by a
small driver that WRITEs the whole TABLE and INERT of ``CSSP`` in full precision; the tables
are formed by the same ``as_tables`` as the legacy engine's and compared with
harness/published/ by the harness's rule (within half a unit of the printed last digit,
``diff.py``).

Per variant and per table: the cells at the printed digit, within 1e-7 and 1e-6 relative,
and the cells whose printed digits it changes (``arithmetic.csv``); per cell: which variants
reach the printed digit, how many distinct values the variants give and whether every
variant prints the same digits (``arithmetic_cells.csv``).  The criterion for adopting an
arithmetic (``meets_criterion``, never cell by cell): documented for machines of the time,
it raises the count of every table where it can act (where it changes a printed digit) and
lowers none.  ``--record`` also writes which arithmetics reach each cell's printed digit to
``RECORD`` (committed: the table scenes read it, ``reached``, to explain a cell by the run
that reaches it, register D181, without running the study).

Needs gfortran on PATH (``readings.CompilerError`` otherwise) and the source tree's legacy/.
Run: ``linkrepro arithmetic --out out/arithmetic`` (17 builds, about 20 s of CPU: 10-12 s on two
free cores), not part of ``linkrepro reproduce``, whose report links the result when it is there.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np
import pandas as pd

from ... import progress
from ...csv_output import write_csv
from ...markdown_text import code_span, prose
from ...published_tables import PublishedTable
from ...readings import CompilerError
from .arithmetic_build import Measurement, ReferenceFailed, measure
from .arithmetic_variants import VARIANTS, get
from .arithmetic_settings import OUTPUTS, RECORD, TITLE

TABLES = ("5_1", "5_2", "5_3", "5_4", "5_5", "5_6", "5_7")
#: the series tables (crank 0-360 deg), whose cells the reading driver counts
SERIES = TABLES[1:]
COMMAND = "linkrepro arithmetic --out out/arithmetic"
#: the standard's reading of the constants, which the reference (D180's) was adopted against
STANDARD = "single-constants"
RECORD_COMMAND = "linkrepro arithmetic --out out/arithmetic --record"

__all__ = ["TABLES", "SERIES", "COMMAND", "OUTPUTS", "STANDARD", "RECORD", "RECORD_COMMAND", "ReferenceFailed",
           "cell_frame", "count_frame", "meets_criterion", "record_frame", "reached", "consistent", "explaining",
           "trail_note", "as_markdown", "write", "run", "FAILURES"]
#: a failed run of ``linkrepro arithmetic`` (one line, status 1)
FAILURES = (CompilerError, ReferenceFailed)


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


def _printed_as(values: pd.Series, half: pd.Series) -> list[str]:
    """Each value rounded to its cell's published decimals, as text."""
    return [f"{round(x, _decimals(h)):.{_decimals(h)}f}" for x, h in zip(values, half)]


def count_frame(m: Measurement, cells: pd.DataFrame | None = None, base: str | None = None) -> pd.DataFrame:
    """One row per variant and table (and an 'all' row per variant): cells at the printed
    digit, within 1e-7 and 1e-6 relative, cells whose value differs from the reference, and
    against ``base`` (default the reference): the cells whose printed digits differ from the
    base's (``digits_changed``: where the variant can act) and the ``gain`` in cells at the
    printed digit."""
    cells = cell_frame(m) if cells is None else cells
    ref = m.ran[0].name
    base = base or ref
    base_digits = _printed_as(cells[f"value:{base}"], cells["half_unit"])
    rows = []
    for v in m.ran:
        value = cells[f"value:{v.name}"]
        rel = (value - cells["published"]).abs() / cells["published"].abs()
        frame = pd.DataFrame({"table": cells["table"],
                              "at": (value - cells["published"]).abs() <= cells["half_unit"] * (1.0 + 1e-9),
                              "r7": rel <= 1e-7, "r6": rel <= 1e-6,
                              "changed": value != cells[f"value:{ref}"],
                              "digits": [a != b for a, b in zip(_printed_as(value, cells["half_unit"]), base_digits)],
                              "move": (value - cells[f"value:{ref}"]).abs() / cells[f"value:{ref}"].abs()})
        for table, part in list(frame.groupby("table", sort=True)) + [("all", frame)]:
            rows.append({"variant": v.name, "table": table, "cells": len(part),
                         "at_printed_digit": int(part["at"].sum()), "within_1e-7": int(part["r7"].sum()),
                         "within_1e-6": int(part["r6"].sum()), "cells_changed": int(part["changed"].sum()),
                         "max_rel_change": float(part["move"].max()), "documented": v.documented,
                         "digits_changed": int(part["digits"].sum())})
    counts = pd.DataFrame(rows)
    at_base = counts[counts["variant"] == base].set_index("table")["at_printed_digit"]
    counts["gain"] = counts["at_printed_digit"] - counts["table"].map(at_base)
    return counts


def meets_criterion(counts: pd.DataFrame) -> dict[str, bool]:
    """Per variant, against the base of ``counts`` (``count_frame``'s ``base``): its arithmetic
    is documented for machines of the time, it acts somewhere (changes a printed digit), raises
    the count of every table where it acts and lowers none.  A table where it changes no
    printed digit is not asked to rise: the change cannot act there.  Never cell by cell."""
    out = {}
    for name, part in counts.groupby("variant", sort=False):
        part = part[part["table"] != "all"].set_index("table")
        acts = part["digits_changed"] > 0
        out[name] = bool(part["documented"].iloc[0] and acts.any()
                         and (part.loc[acts, "gain"] > 0).all() and (part["gain"] >= 0).all())
    return out


def record_frame(cells: pd.DataFrame) -> pd.DataFrame:
    """The per-cell record (``RECORD``): table, row, column, the published text and the
    variants that reach its printed digit (space-separated, in the study's order)."""
    return cells[["table", "row", "column", "published_text", "reached_by", "n_variants"]].copy()


@lru_cache(maxsize=1)
def _record() -> dict[tuple[str, str, str], tuple[str, ...]]:
    frame = pd.read_csv(RECORD, dtype=str, keep_default_na=False)
    return {(t, r, c): tuple(by.split()) for t, r, c, by in
            zip(frame["table"], frame["row"], frame["column"], frame["reached_by"])}


def reached(table: str, row: str, column: str) -> tuple[str, ...] | None:
    """The arithmetics of the study that reach the printed digit of a cell (``table`` as "5.2",
    ``row`` as the study names it: "120" or "crank/i_xx"), as ``RECORD`` holds them; None
    for a cell the record does not hold."""
    return _record().get((table, row, column))


@lru_cache(maxsize=1)
def _lowered() -> dict[str, tuple[str, ...]]:
    """Per variant of ``RECORD``: the tables whose count of cells at the printed digit it
    lowers against the reference."""
    ref = VARIANTS[0].name
    count: dict[tuple[str, str], int] = {}
    for (table, _, _), by in _record().items():
        for name in by:
            count[name, table] = count.get((name, table), 0) + 1
    tables = sorted({table for table, _, _ in _record()})
    return {v.name: tuple(t for t in tables if count.get((v.name, t), 0) < count.get((ref, t), 0)) for v in VARIANTS}


def consistent() -> tuple[str, ...]:
    """The documented arithmetics of ``RECORD`` (but the reference) that lower no table's count
    of cells at the printed digit against the reference: the published tables as a whole cannot
    tell them from the adopted arithmetic, so a cell one of them reaches is explained by its run
    (D181).  One that lowers a table (e.g. REAL promoted to 64 bits) reaching a cell is a
    coincidence, not an explanation."""
    return tuple(v.name for v in VARIANTS[1:] if v.documented and not _lowered()[v.name])


def explaining(table: str, row: str, column: str) -> tuple[str, ...]:
    """The ``consistent`` arithmetics that reach a cell's printed digit where the reference
    does not (none where the reference reaches it, or the record does not hold the cell)."""
    by = reached(table, row, column) or ()
    return () if VARIANTS[0].name in by else tuple(n for n in by if n in consistent())


def _why_not(name: str) -> str:
    """Why a variant's run does not explain a cell it reaches."""
    lowered = _lowered()[name]
    why = [] if get(name).documented else ["no documented arithmetic"]
    why += [f"lowers Table{'s' if len(lowered) > 1 else ''} {', '.join(lowered)} against the adopted one"] if lowered else []
    return f"{name} ({' and '.join(why)})"


def trail_note(table: str, row: str, column: str) -> tuple[str, ...]:
    """The sentence a cell's trail shows: which of the study's arithmetics reach its printed
    digit, and whether one explains the cell where the adopted arithmetic misses it."""
    by = reached(table, row, column)
    if by is None:
        return ()
    names = [v.name for v in VARIANTS]
    text = "Arithmetic study (D180, `linkrepro arithmetic`): "
    if len(by) == len(names):
        return (text + f"all {len(names)} of its arithmetics reach the printed digit.",)
    if not by:
        return (text + f"none of its {len(names)} arithmetics reaches the printed digit.",)
    reach = f"{len(by)} of its {len(names)} arithmetics {'reaches' if len(by) == 1 else 'reach'} the printed digit"
    if names[0] in by:
        return (text + f"{reach}, the adopted one ({names[0]}) among them; not "
                f"{', '.join(n for n in names if n not in by)}.",)
    text += f"{reach}, not the adopted one ({names[0]}): {', '.join(by)}."
    runs = explaining(table, row, column)
    other = [_why_not(n) for n in by if n not in runs]
    if runs:
        text += (f" {', '.join(runs)} {'lowers' if len(runs) == 1 else 'lower'} no table against the adopted "
                 "arithmetic: the cell is explained by that run (D181).")
    if other:
        text += f" Not an explanation: {'; '.join(other)}."
    return (text,)


def _gains(part: pd.DataFrame) -> str:
    return ", ".join(f"{t} {int(g):+d}" for t, g in part["gain"].items())


def adoption(m: Measurement, cells: pd.DataFrame) -> str:
    """The reference (the arithmetic D180 adopts) against ``STANDARD`` (the standard's reading
    of the constants) by the criterion: one paragraph; "" when ``STANDARD`` did not run."""
    ref = m.ran[0].name
    if STANDARD not in m.values:
        return ""
    counts = count_frame(m, cells, base=STANDARD)
    part = counts[(counts["variant"] == ref) & (counts["table"] != "all")].set_index("table")
    total = counts[counts["table"] == "all"].set_index("variant")["at_printed_digit"]
    acts = part["digits_changed"] > 0
    quiet = [t for t in part.index if not acts[t]]
    return (f"**The adopted arithmetic** (`{ref}`, register D180) against `{STANDARD}` (the standard's reading, "
            f"gfortran's default, the legacy build before D180): {int(total[ref])} cells at the printed digit "
            f"against {int(total[STANDARD])} (per table: {_gains(part)}); it changes printed digits in "
            f"{', '.join(part.index[acts])}"
            + (f", none in {', '.join(quiet)} (it cannot act there)" if quiet else "")
            + f", raises {int((part.loc[acts, 'gain'] > 0).sum())} of the {int(acts.sum())} tables where it acts "
            f"and lowers {int((part['gain'] < 0).sum())}: "
            + ("it meets the criterion." if meets_criterion(counts)[ref] else "it does not meet the criterion."))


def _rows_list(part: pd.DataFrame) -> str:
    out = []
    for col, sub in part.groupby("column", sort=False):
        out.append(f"{col} {', '.join(sub['row'])}")
    return "; ".join(out)


def _verdict(name: str, ref: str, verdict: dict[str, bool]) -> str:
    """The 'adopt?' column: the reference is the adopted arithmetic (D180), the others meet the
    criterion against it or not."""
    return "adopted (D180)" if name == ref else "yes" if verdict[name] else "no"


def as_markdown(m: Measurement, counts: pd.DataFrame, cells: pd.DataFrame) -> str:
    ref = m.ran[0].name
    verdict = meets_criterion(counts)
    adopted = [n for n, ok in verdict.items() if ok]
    lines = ["## Which digits survive a change of arithmetic (registers D056, D180)", "",
             f"The legacy FORTRAN (legacy/src) rebuilt under {len(m.variants)} arithmetics a 1996 machine "
             f"may have used, each run once; its Tables 5.1-5.7 ({len(cells)} cells) against the published "
             "digits. Re-measure: `" + COMMAND + "`; per-variant counts in arithmetic.csv, the per-cell "
             "matrix in arithmetic_cells.csv.", "",
             "The seed (000, Rahman 1996) names no computer or compiler; it names only the IMSL routines "
             "QPROG and UMACH (chapter 4, Appendix B), whose single-precision QPROG the listing calls "
             "with REAL arrays. The variants stand for the machines below; 'documented' means the "
             "arithmetic is described for compilers of the time.", "",
             "| variant | how | stands for | documented |", "|---|---|---|---|"]
    lines += [f"| {v.name} | {code_span(v.how)} | {prose(v.machine)} | {'yes' if v.documented else 'no'} |" for v in m.variants]
    if m.failures:
        lines += ["", "Not run on this machine: " + "; ".join(f"{n} ({why})" for n, why in m.failures.items()) + "."]
    head = [t.replace("_", ".") for t in TABLES]
    lines += ["", "### Cells at the printed digit, per variant and table", "",
              "| variant | " + " | ".join(head) + " | all | within 1e-7 | within 1e-6 | cells changed | "
              "largest change (rel) | tables acted on / raised / lowered | 'before' / 'after' cells | adopt? |",
              "|---|" + "---|" * (len(head) + 8)]
    by_column = {v.name: {col: int(sum(v.name in str(r).split() for r in part["reached_by"]))
                          for col, part in cells.groupby("column")} for v in m.ran}
    for v in m.ran:
        part = counts[counts["variant"] == v.name].set_index("table")
        ncells = part["cells"]
        lines.append(f"| {v.name} | " + " | ".join(f"{part.at[t, 'at_printed_digit']}/{ncells[t]}" for t in head)
                     + f" | {part.at['all', 'at_printed_digit']}/{ncells['all']} | {part.at['all', 'within_1e-7']}"
                     f" | {part.at['all', 'within_1e-6']} | {part.at['all', 'cells_changed']}"
                     f" | {part.at['all', 'max_rel_change']:.1e} | {(part.loc[head, 'digits_changed'] > 0).sum()} / "
                     f"{(part.loc[head, 'gain'] > 0).sum()} / {(part.loc[head, 'gain'] < 0).sum()} | {by_column[v.name].get('before', 0)} / "
                     f"{by_column[v.name].get('after', 0)} | {_verdict(v.name, ref, verdict)} |")
    lines += ["", "**Criterion** (never cell by cell): an arithmetic is adopted if it is documented for machines "
              "of the time, raises the count of every table where it can act (where it changes a printed digit: "
              "'acted on') and lowers none. Against the reference: "
              + (f"met by {', '.join(adopted)}: the register must look at it again."
                 if adopted else "met by no variant: the adopted arithmetic stands.")]
    paragraph = adoption(m, cells)
    if paragraph:
        lines += ["", paragraph]
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
    lines += ["", f"Reference: `{ref}` (legacy/src with meson.build's flags: the constants as D180 reads them), "
              f"the legacy engine's own build; {m.seconds:.1f} s for the builds and runs of this measurement. "
              f"Which arithmetics reach each cell's printed digit is recorded in "
              f"harness/scenes/rahman1996/{RECORD.name} (`{RECORD_COMMAND}`), which the table scenes read (D181)."]
    return "\n".join(lines)


def write(out_dir: Path, variants=VARIANTS, record: bool = False) -> tuple[Measurement, pd.DataFrame, pd.DataFrame, str]:
    """Measure and write DIR/arithmetic.csv, DIR/arithmetic_cells.csv, DIR/arithmetic.md (and
    with ``record`` the committed ``RECORD``); a progress line over the builds on standard
    error when it is a terminal."""
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
    (out_dir / "arithmetic.md").write_text(f"# {TITLE}\n\n" + text.split("\n", 1)[1].lstrip() + "\n")
    if record:
        if m.failures:
            raise ReferenceFailed(f"not recorded: {', '.join(m.failures)} did not run (the record holds every variant)")
        write_csv(record_frame(cells), RECORD, "%.17g")
        _record.cache_clear(), _lowered.cache_clear()
    return m, counts, cells, text


def run(args) -> str:
    """``linkrepro arithmetic`` (``commands.py`` declares its arguments): the study written into
    ``args.out``; its markdown."""
    return write(args.out, record=args.record)[3]


if __name__ == "__main__":                 # python -m linkrepro.harness.scenes.rahman1996.arithmetic [DIR]
    import sys
    print(write(Path(sys.argv[1] if len(sys.argv) > 1 else "out/arithmetic"))[3])
