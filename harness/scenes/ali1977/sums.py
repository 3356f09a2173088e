"""Ali (1977): the published tables' own arithmetic, printed cells that disagree with the
cells they are printed from.

Each of Ali's (1977) K.E.D. tables prints, for the source and the cognate, the rigid
position X, Y, the deflection dX, dY and the deflected position X_new = X + dX, Y_new = Y +
dY.  If every printed number is its exact value rounded to the printed digit, the printed
sum and the sum of the printed terms differ by at most the three half-units; beyond that,
one of the three cells is a misprint, whatever program produced the table.  Which of the
three it is, the identity cannot tell: the register (the ids listed for each finding) or
the engines can.
"""
from __future__ import annotations

import pandas as pd

from ...published_tables import PublishedTable

#: table -> [(printed sum, (terms))] of the K.E.D. tables
SUMS = {table: [(f"{side}_{axis}new", (f"rigid_{axis}", f"{side}_d{axis}")) for side in ("src", "cog")
                for axis in ("x", "y")]
        for table in ("ali1977_table1", "ali1977_table2", "ali1977_table3")}
COLUMNS = ["table", "input_deg", "sum_column", "printed_sum", "sum_of_printed_terms", "gap", "rounding_bound",
           "verdict", "register_ids"]


def sum_checks(table: str, published: PublishedTable | None = None) -> pd.DataFrame:
    """One row per printed sum of ``table`` (empty if it prints none): the printed sum, the
    sum of its printed terms, |gap| and the rounding bound (the cells' half-units added),
    and the verdict: ``consistent`` or ``misprint`` (gap beyond the bound)."""
    published = published or PublishedTable.load(table)
    values, half = published.values, published.half_unit
    rows = []
    for total, terms in SUMS.get(table, []):
        addends = values[list(terms)].sum(axis=1, skipna=False)
        gap = (values[total] - addends).abs()
        bound = half[total] + half[list(terms)].sum(axis=1, skipna=False)
        for i in values.index[values[total].notna() & addends.notna()]:
            rows.append(dict(table=table, input_deg=values.at[i, "input_deg"], sum_column=total,
                             printed_sum=values.at[i, total], sum_of_printed_terms=addends[i], gap=gap[i],
                             rounding_bound=bound[i],
                             verdict="misprint" if gap[i] > bound[i] * (1 + 1e-9) else "consistent"))
    return pd.DataFrame(rows, columns=COLUMNS[:-1])


def with_register(checks: pd.DataFrame, diff: pd.DataFrame, engine: str = "legacy") -> pd.DataFrame:
    """``checks`` with, per row, the register ids that explain any of its three cells for
    ``engine`` in the scene's diff (empty where none does)."""
    terms = dict(SUMS.get(checks["table"].iloc[0], [])) if len(checks) else {}
    ids = diff[diff["engine"] == engine].set_index(["input_deg", "column"])["register_ids"]
    found = []
    for row in checks.itertuples():
        cells = (row.sum_column, *terms[row.sum_column])
        found.append(" ".join(sorted({i for c in cells for i in str(ids.get((row.input_deg, c), "")).split()
                                      if i and i != "nan"})))
    return checks.assign(register_ids=found)


def as_markdown(checks: pd.DataFrame) -> str:
    """The misprints the table's own sums reveal, for a scene report."""
    if checks.empty:
        return ""
    bad = checks[checks["verdict"] == "misprint"]
    lines = ["## The table's own arithmetic (X_new = X + dX, Y_new = Y + dY)", "",
             f"{len(checks)} printed sums checked against their printed terms; {len(bad)} differ by more than "
             "the cells' half-units added (one of the three cells is misprinted). Register ids: the entries "
             "that already explain one of the three cells (for legacy).", ""]
    if bad.empty:
        return "\n".join(lines + ["None."])
    lines += ["| input deg | sum | printed | sum of printed terms | gap | bound | register ids |",
              "|---|---|---|---|---|---|---|"]
    lines += [f"| {r.input_deg:g} | {r.sum_column} | {r.printed_sum:.3f} | {r.sum_of_printed_terms:.3f} | "
              f"{r.gap:.4g} | {r.rounding_bound:.4g} | {r.register_ids or '(none)'} |" for r in bad.itertuples()]
    return "\n".join(lines)
