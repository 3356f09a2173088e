"""Rahman (1996): section 5.3's quoted percentages against the published tables' own rows.

Section 5.3 quotes, per Table 5.2-5.7, the range and the average of the percentage
decrement (before - after) * 100 / before; ``percentage_checks`` sets each quoted number
beside what the published table's own rows give (one unit of the quoted last digit
allowed: the text truncates as well as rounds, D059).
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from ...published_tables import PUBLISHED_DIR, PublishedTable


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

