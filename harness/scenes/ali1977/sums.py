"""The published tables' own arithmetic: printed cells that disagree with the cells they are
printed from.

Each of Ali's (1977) K.E.D. tables prints, for the source and the cognate, the rigid
position X, Y, the deflection dX, dY and the deflected position X_new = X + dX, Y_new = Y +
dY.  If every printed number is its exact value rounded to the printed digit, the printed
sum and the sum of the printed terms differ by at most the three half-units; beyond that,
one of the three cells is a misprint, whatever program produced the table.  Which of the
three it is, the identity cannot tell: the register (the ids listed for each finding) or
the engines can.

Rahman's (1996) section 5.3 quotes, per Table 5.2-5.7, the range and the average of the
percentage decrement (before - after) * 100 / before; ``percentage_checks`` sets each quoted
number beside what the published table's own rows give (one unit of the quoted last digit
allowed: the text truncates as well as rounds, D059).
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from .published_tables import PUBLISHED_DIR, PublishedTable

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


#: the scene whose register claims name section 5.3's quoted numbers (rows: the table, 5_2..5_7)
SECTION_5_3_SCENE = "rahman1996-figures"
PERCENTAGE_COLUMNS = ["table", "quantity", "quoted", "from_table", "gap", "bound", "verdict", "register_ids"]


def decrement_pct(table: pd.DataFrame) -> np.ndarray:
    """The listing's percentage decrement (before - after) * 100 / before, per crank position (%)."""
    before, after = table["before"].to_numpy(float), table["after"].to_numpy(float)
    return (before - after) * 100.0 / before


def _last_digit_unit(text: str) -> float:
    """One unit of the last printed digit of a quoted number ('0.7248' -> 1e-4, '1.3' -> 0.1)."""
    return 10.0 ** -len(text.split(".")[1]) if "." in text else 1.0


def percentage_checks(register: dict | None = None) -> pd.DataFrame:
    """One row per number section 5.3 quotes: the range's ends (``range_from``, ``range_to``,
    matched to the table's largest and smallest decrement, whichever pairing is closer) and the
    ``average`` (the mean of the table's 37 rows), the value from the published table, |gap|,
    the bound (one unit of the quoted digit) and the verdict ``consistent`` or ``differs``; with
    ``register`` the ids of the entries that claim the quoted cell (scene SECTION_5_3_SCENE)."""
    text = pd.read_csv(PUBLISHED_DIR / "rahman1996_section5_3.csv", comment="#", dtype=str)
    rows = []
    for quote in text.itertuples():
        pct = decrement_pct(PublishedTable.load(f"rahman1996_table{quote.table}").values)
        ends = (float(quote.range_from), float(quote.range_to))
        pair = (pct.max(), pct.min())
        if abs(ends[0] - pair[1]) + abs(ends[1] - pair[0]) < abs(ends[0] - pair[0]) + abs(ends[1] - pair[1]):
            pair = pair[::-1]
        for quantity, quoted, value in (("range_from", quote.range_from, pair[0]),
                                        ("range_to", quote.range_to, pair[1]),
                                        ("average", quote.average, pct.mean())):
            gap, bound = abs(float(quoted) - value), _last_digit_unit(quoted)
            ids = sorted(entry.id for entry in (register or {}).values() for claim in entry.cells
                         if claim.covers(SECTION_5_3_SCENE, quote.table, quantity, "published"))
            rows.append(dict(table=quote.table, quantity=quantity, quoted=float(quoted), from_table=value,
                             gap=gap, bound=bound, verdict="differs" if gap > bound * (1 + 1e-9) else "consistent",
                             register_ids=" ".join(ids)))
    return pd.DataFrame(rows, columns=PERCENTAGE_COLUMNS)


def percentages_markdown(checks: pd.DataFrame) -> str:
    """Section 5.3's quoted numbers that the published tables do not give, for the report."""
    bad = checks[checks["verdict"] == "differs"]
    lines = ["## Section 5.3 against the published tables", "",
             f"{len(checks)} numbers quoted in section 5.3 (the range and average of each table's percentage "
             f"decrement) recomputed from the published tables' own rows; {len(bad)} differ by more than one unit "
             "of the quoted digit. Register ids: the entries that explain them.", ""]
    if bad.empty:
        return "\n".join(lines + ["None."])
    lines += ["| table | quoted | text | from the table | gap | register ids |", "|---|---|---|---|---|---|"]
    lines += [f"| {r.table} | {r.quantity} | {r.quoted:g} | {r.from_table:.6g} | {r.gap:.4g} | "
              f"{r.register_ids or '(none)'} |" for r in bad.itertuples()]
    return "\n".join(lines)

