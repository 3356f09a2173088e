"""Published tables (harness/published/*.csv), read as printed.

Each cell keeps its printed text, from which its precision is taken: a value
printed with k decimals is reproduced when it is within half a unit of its last
digit.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

PUBLISHED_DIR = Path(__file__).resolve().parent / "published"


@dataclass(frozen=True)
class PublishedTable:
    name: str
    text: pd.DataFrame        # the cells as printed (strings)

    @classmethod
    def load(cls, name: str) -> "PublishedTable":
        path = PUBLISHED_DIR / f"{name}.csv"
        if not path.exists():
            raise FileNotFoundError(f"no published table {path}")
        return cls(name, pd.read_csv(path, comment="#", dtype=str, keep_default_na=False))

    @property
    def values(self) -> pd.DataFrame:
        return self.text.apply(lambda col: pd.to_numeric(col, errors="coerce"))

    @property
    def half_unit(self) -> pd.DataFrame:
        """Half a unit of each cell's last printed digit."""
        def half(cell: str) -> float:
            cell = cell.strip()
            try:
                float(cell)
            except ValueError:
                return np.nan                                          # a text cell: a row name
            mantissa, _, exponent = cell.upper().partition("E")      # 1.946666E-04
            decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
            decimals -= int(exponent) if exponent else 0
            return 0.5 * 10.0 ** (-decimals) if cell else np.nan
        return self.text.map(half)

    def matched(self, column: str, got, rows) -> tuple[int, float]:
        """(how many of ``got``, the values of ``column`` at the rows selected by ``rows``, are
        within half a unit of the printed digit; the largest error, inf where ``got`` is NaN)."""
        err = np.abs(np.asarray(got, dtype=float) - self.values.loc[rows, column].to_numpy())
        err = np.where(np.isnan(err), np.inf, err)
        return int((err <= self.half_unit.loc[rows, column].to_numpy() * (1 + 1e-9)).sum()), float(np.max(err))
