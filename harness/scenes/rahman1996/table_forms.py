"""Rahman (1996): a CSSP run (the legacy face's ``cssp()``, the port's ``balance()``, the
arithmetic study's build) as the seven published tables, in their columns."""
from __future__ import annotations

import numpy as np
import pandas as pd

from ....legacy.rahman1996 import CSSP_COLUMNS, INERTIA_ROWS
from ....port.rahman1996.balance import CRANK_DEG

SERIES_COLUMNS = ["crank_deg", "before", "after"]
INERTIA_COLUMNS = ["link", "quantity", "before", "after"]


def series_frame(values: np.ndarray) -> pd.DataFrame:
    """A 37 x 2 array (before, after) as a crank_deg, before, after table."""
    return pd.DataFrame({"crank_deg": CRANK_DEG, "before": values[:, 0], "after": values[:, 1]})


def inertia_frame(values: np.ndarray) -> pd.DataFrame:
    """A 6 x 2 array (before, after) as Table 5.1 (link, quantity, before, after)."""
    links, quantities = zip(*INERTIA_ROWS)
    return pd.DataFrame({"link": links, "quantity": quantities,
                         "before": values[:, 0], "after": values[:, 1]})


def as_tables(run: dict) -> dict[str, pd.DataFrame]:
    """A CSSP run (rahman1996.cssp() or port.cssp.balance(): ``table``, ``inertia``) as the seven tables."""
    tables = {"5_1": inertia_frame(run["inertia"])}
    for k, table in enumerate(dict.fromkeys(t for t, _ in CSSP_COLUMNS)):
        tables[table] = series_frame(run["table"][:, 2 * k:2 * k + 2])
    return tables
