"""CSV files as ``DataFrame.to_csv(path, index=False, float_format=...)`` writes them, byte for
byte, in a fraction of the time: pandas formats each float through a Python callback with a
missing-value test per cell; here each float column's distinct values (by bit pattern: 0.0 and
-0.0 are two) are formatted once (NaN written empty, as pandas does), and the rows are joined
with commas where no cell needs quoting, else written by Python's csv module (which pandas
uses, quoting only where needed).  tests/harness/test_csv_output.py checks the bytes against
pandas.
"""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pandas as pd


#: ``float_format`` for values written in full: each float's shortest repr that reads back to the
#: same double (an engine's outputs, so that ``linkrepro verify`` sees every bit)
FULL_PRECISION = None
#: what makes the csv module quote a cell (QUOTE_MINIMAL: the delimiter, the quote character,
#: a line break)
_QUOTED = (",", '"', "\n", "\r")


def _floats(values: np.ndarray, float_format: str | None) -> list:
    """Each float formatted (repr, or ``float_format``), NaN empty; every distinct bit pattern once."""
    bits, where = np.unique(values.astype(float).view(np.int64), return_inverse=True)
    distinct = bits.view(float).tolist()
    text = np.array([float_format % v if float_format else repr(v) for v in distinct], dtype=object)
    text[np.isnan(bits.view(float))] = ""
    return text[where.reshape(-1)].tolist()


def _cells(column: pd.Series, float_format: str | None) -> list:
    values = column.to_numpy()
    if column.dtype.kind == "f":
        return _floats(values, float_format)
    if column.dtype.kind in "biu":
        return [str(v) for v in values.tolist()]
    return ["" if v is None or (isinstance(v, float) and np.isnan(v)) else v for v in values.tolist()]


def _plain(cells: list) -> bool:
    """No cell of an object column is quoted by the csv module (each a str without _QUOTED)."""
    return all(type(v) is str and not any(c in v for c in _QUOTED) for v in cells)


def write_csv(frame: pd.DataFrame, path: Path, float_format: str | None = None) -> None:
    """``frame.to_csv(path, index=False, float_format=float_format)``, faster."""
    if any(column.dtype.kind not in "fbiuO" for _, column in frame.items()):
        frame.to_csv(path, index=False, float_format=float_format)      # dates, categories: pandas
        return
    columns = [_cells(column, float_format) for _, column in frame.items()]
    # one column: the csv module writes an empty cell as "" (a blank line would read as no row)
    plain = len(columns) > 1 and all(_plain(cells) for cells, (_, column) in zip(columns, frame.items())
                                     if column.dtype.kind == "O") and _plain([str(c) for c in frame.columns])
    with open(path, "w", newline="") as handle:
        if plain:                       # the csv module would write the same, more slowly
            handle.write(",".join(str(c) for c in frame.columns) + "\n")
            handle.writelines(",".join(row) + "\n" for row in zip(*columns))
            return
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(frame.columns)
        writer.writerows(zip(*columns))
