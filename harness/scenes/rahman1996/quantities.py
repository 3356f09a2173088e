"""Rahman (1996): what each column of the scenes' CSVs means, and its unit (``harness/quantities.py``).

Units as the published tables print them (harness/published/rahman1996_table5_*.csv):
lb-sec^2-inch (written lbf s^2 in), lbs (lbf), lb-in (lbf in); Table 5.2's objective G
is non-dimensional (eq. 4.2); crank angles in degrees.
"""
from __future__ import annotations

from ...quantities import DIFF, Quantity as Q

#: what each table gives, before and after optimum balancing
TABLE_QUANTITY = {
    "5_1": Q("principal moment of inertia about the link's centre of mass", "lbf s^2 in"),
    "5_2": Q("objective function G", ""),
    "5_3": Q("shaking force", "lbf"),
    "5_4": Q("shaking moment", "lbf in"),
    "5_5": Q("bearing force", "lbf"),
    "5_6": Q("bearing torque", "lbf in"),
    "5_7": Q("input torque", "lbf in"),
}
CRANK = Q("crank angle", "deg")
#: Table 5.1's rows are named by link and quantity (diff.csv joins them: link/quantity)
INERTIA_KEYS = {
    "link": Q("link (crank or connecting_rod)", ""),
    "quantity": Q("principal moment of inertia (i_xx, i_yy or i_zz)", ""),
    "link/quantity": Q("link and principal moment of inertia", ""),
}


def _table(table: str) -> dict[str, Q]:
    """A table's columns: its row names, and its quantity before and after balancing."""
    q = TABLE_QUANTITY[table]
    keys = INERTIA_KEYS if table == "5_1" else {"crank_deg": CRANK}
    return keys | {"before": Q(f"{q.words}, before optimum balancing", q.unit),
                   "after": Q(f"{q.words}, after optimum balancing", q.unit)}


#: rahman1996-figures: percentages.csv, section5_3.csv, identities.csv (figures.py, quoted_numbers.py)
FIGURES = {
    "table": Q("Rahman (1996) table (5_2 ... 5_7)", ""),
    "figure": Q("Rahman (1996) figure (5.1 ... 5.6)", ""),
    "engine": Q("engine, or published (the table's own rows)", ""),
    "crank_deg": CRANK,
    "pct": Q("decrement, (before - after) / before", "%"),
    "max_pct": Q("largest decrement", "%"),
    "at_deg": Q("crank angle of the largest decrement", "deg"),
    "min_pct": Q("smallest decrement", "%"),
    "min_at_deg": Q("crank angle of the smallest decrement", "deg"),
    "mean37_pct": Q("mean decrement over the 37 rows", "%"),
    "mean36_pct": Q("mean decrement over 36 rows (the repeated 360 deg row left out)", "%"),
    "negative_at_deg": Q("crank angles where the decrement is negative", "deg"),
    "text_range": Q("the decrement's range quoted in section 5.3", "%"),
    "text_average": Q("the average decrement quoted in section 5.3", "%"),
    "text_claim": Q("section 5.3's statement about the decrement's sign", ""),
    "quantity": Q("the quoted number (range_from, range_to or average)", ""),
    "quoted": Q("the number section 5.3 quotes", "%"),
    "from_table": Q("the same number from the published table's rows", "%"),
    "gap": Q("|quoted - from the table|", "%"),
    "bound": Q("one unit of the quoted last digit", "%"),
    "verdict": Q("consistent, or differs (gap beyond the bound)", ""),
    "register_ids": DIFF["register_ids"],
}

#: rahman1996-multibody (multibody.py): curves.csv (long: ``port``, ``exudyn`` in the unit of
#: the row's ``table``), agreement.csv (``peak``, ``max_difference`` likewise)
_COMPARED = ("5_3", "5_4", "5_7")
MULTIBODY = {
    **{table: TABLE_QUANTITY[table] for table in _COMPARED},
    "masses": Q("point masses (before: the equal ones; after: the optimum balancing's)", ""),
    "crank_pin": Q("Exudyn's crank-pin joint (universal: the rod cannot spin about its axis; spherical: it can)", ""),
    "table": Q("Rahman (1996) table (5_3 shaking force, 5_4 shaking moment, 5_7 input torque)", ""),
    "crank_deg": CRANK,
    "port": Q("the corrected port's value (the table's column for the masses)", "", per_row="table"),
    "exudyn": Q("Exudyn's value", "", per_row="table"),
    "peak": Q("peak |the corrected port's value| over the 37 crank angles", "", per_row="table"),
    "max_difference": Q("largest |Exudyn - the corrected port| over the 37 crank angles", "", per_row="table"),
    "relative": Q("largest |Exudyn - the corrected port| / the peak", ""),
    "ground_residual": Q("largest |sum of m a + the ground joints' reactions| over the revolution (Newton's law by "
                         "Exudyn's constraint forces)", "lbf"),
    "exudyn_seconds": Q("Exudyn's wall time for the run (masses and crank pin)", "s"),
}

QUANTITIES = {f"rahman1996-table{table}": _table(table) for table in TABLE_QUANTITY}
QUANTITIES["rahman1996-figures"] = FIGURES
QUANTITIES["rahman1996-multibody"] = MULTIBODY
