"""Compare two ``linkrepro reproduce`` output folders: did anything printed change?

``python -m linkrepro.harness.compare_runs BEFORE AFTER [--tol 1e-12]`` reads every CSV of
both folders.  Text columns (statuses, verdicts, register ids) must be equal; numeric
columns must agree, where both are finite, to ``tol`` relative to the column's largest magnitude in BEFORE (a
column of round-off, such as a closure error, is compared to its own scale), and hold NaN at
the same rows.  Columns that hold timings (their name contains "seconds" or "time") are not
compared.  Prints one line per CSV that differs and the largest relative difference over
all; exit status 0 when everything agrees, 1 otherwise.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
import pandas as pd


def is_timing(column: str) -> bool:
    """A column of measured times (its name says "seconds" or "time"): never compared."""
    return "seconds" in column or "time" in column


def compare_csv(before: Path, after: Path, tol: float) -> tuple[float, list[str]]:
    """(largest relative numeric difference, problems) between two CSV files."""
    a = pd.read_csv(before, keep_default_na=False, na_values=["", "nan", "NaN"])
    b = pd.read_csv(after, keep_default_na=False, na_values=["", "nan", "NaN"])
    if list(a.columns) != list(b.columns) or len(a) != len(b):
        return np.inf, [f"shape or columns differ: {a.shape} {list(a.columns)[:5]}... vs {b.shape}"]
    worst, problems = 0.0, []
    for col in a.columns:
        if is_timing(col):
            continue
        x, y = a[col], b[col]
        if pd.api.types.is_numeric_dtype(x) and pd.api.types.is_numeric_dtype(y):
            xv, yv = x.to_numpy(float), y.to_numpy(float)
            if not np.array_equal(np.isnan(xv), np.isnan(yv)):
                problems.append(f"{col}: NaN at different rows ({int(np.sum(np.isnan(xv) != np.isnan(yv)))})")
            finite = np.isfinite(xv) & np.isfinite(yv)
            infinite = np.isinf(xv)
            if not (np.array_equal(infinite, np.isinf(yv)) and np.array_equal(xv[infinite], yv[infinite])):
                problems.append(f"{col}: infinities differ")
            scale = np.max(np.abs(xv[finite]), initial=0.0)
            gap = np.max(np.abs(xv[finite] - yv[finite]), initial=0.0)
            rel = gap / scale if scale > 0 else gap
            worst = max(worst, rel)
            if rel > tol:
                problems.append(f"{col}: relative difference {rel:.3g} where both are finite")
        else:
            xs, ys = (v.astype(object).where(v.notna(), "").astype(str) for v in (x, y))   # missing = ""
            if not xs.equals(ys):
                problems.append(f"{col}: text differs in {int((xs != ys).sum())} rows")
    return worst, problems


def compare(before: Path, after: Path, tol: float = 1e-12) -> tuple[float, dict[str, list[str]]]:
    """(largest relative difference, {csv path: problems}) over every CSV under ``before``."""
    worst, found = 0.0, {}
    for path in sorted(Path(before).rglob("*.csv")):
        rel = path.relative_to(before)
        other = Path(after) / rel
        if not other.exists():
            found[str(rel)] = ["missing in AFTER"]
            continue
        gap, problems = compare_csv(path, other, tol)
        worst = max(worst, gap)
        if problems:
            found[str(rel)] = problems
    for path in sorted(Path(after).rglob("*.csv")):
        if not (Path(before) / path.relative_to(after)).exists():
            found[str(path.relative_to(after))] = ["new in AFTER"]
    return worst, found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m linkrepro.harness.compare_runs", description=__doc__.split("\n")[0])
    parser.add_argument("before", type=Path)
    parser.add_argument("after", type=Path)
    parser.add_argument("--tol", type=float, default=1e-12)
    args = parser.parse_args(argv)
    worst, found = compare(args.before, args.after, args.tol)
    count = len(list(Path(args.before).rglob("*.csv")))
    for name, problems in found.items():
        print(f"{name}: " + "; ".join(problems))
    print(f"{count} CSVs compared; largest relative difference {worst:.3g}; "
          f"{'all agree' if not found else f'{len(found)} differ'} (tolerance {args.tol:g})")
    return 0 if not found else 1


if __name__ == "__main__":
    sys.exit(main())
