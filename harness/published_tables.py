"""Published tables (harness/published/*.csv), read as printed.

Each cell keeps its printed text, from which its precision is taken: a value
printed with k decimals is reproduced when it is within half a unit of its last
digit.  The numbers and half units are read from the text once per table object
(``text`` is not to be changed after).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
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
        """The cells as numbers (NaN where a cell is text); a fresh copy on every call."""
        return self._values.copy()

    @property
    def half_unit(self) -> pd.DataFrame:
        """Half a unit of each cell's last printed digit; a fresh copy on every call."""
        return self._half_unit.copy()

    @cached_property
    def _values(self) -> pd.DataFrame:
        return self.text.apply(lambda col: pd.to_numeric(col, errors="coerce"))

    @cached_property
    def _half_unit(self) -> pd.DataFrame:
        return self.text.map(_half)

    def matched(self, column: str, got, rows) -> tuple[int, float]:
        """(how many of ``got``, the values of ``column`` at the rows selected by ``rows`` (a
        boolean mask over the table's rows), are within half a unit of the printed digit; the
        largest error, inf where ``got`` is NaN)."""
        mask = np.asarray(rows)
        if mask.dtype != bool or mask.shape != (len(self.text),):
            raise ValueError(f"rows must be a boolean mask of {len(self.text)} rows")
        err = np.abs(np.asarray(got, dtype=float) - self._values[column].to_numpy()[mask])
        err = np.where(np.isnan(err), np.inf, err)
        return int((err <= self._half_unit[column].to_numpy()[mask] * (1 + 1e-9)).sum()), float(np.max(err))


def _half(cell: str) -> float:
    """Half a unit of a printed cell's last digit (NaN for a text cell: a row name)."""
    cell = cell.strip()
    try:
        float(cell)
    except ValueError:
        return np.nan
    mantissa, _, exponent = cell.upper().partition("E")      # 1.946666E-04
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    decimals -= int(exponent) if exponent else 0
    return 0.5 * 10.0 ** (-decimals) if cell else np.nan
