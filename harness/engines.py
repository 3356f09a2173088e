"""The four engines the harness runs for every scene.

``printed``         the listings exactly as printed (legacy/printed), built as the
                    standalone programs they are; run as subprocesses, their WRITE
                    output parsed.  They only give what they print.
``legacy``          the cleaned listings (legacy/src) through f2py.
``port_printed``    the Python port with every quirk of the original on.
``port_corrected``  the Python port with every registered bug removed.
"""
from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pandas as pd

ENGINES = ("printed", "legacy", "port_printed", "port_corrected")

BIN_DIR = Path(__file__).resolve().parent.parent / "legacy" / "bin"


class PrintedProgramError(RuntimeError):
    """A printed program could not be run or its output could not be read."""


def run_printed(program: str, timeout_s: float = 60.0) -> pd.DataFrame:
    """Run one printed program; return its WRITE(6,200) rows (deg, dx, dy, rot).

    FORMAT 200 is (1H0,5X,F12.6,8X,F12.6,8X,F12.6,8X,F12.6): a carriage-control
    character then four fixed-point numbers; the 1H1 line is the page header.
    """
    exe = BIN_DIR / program
    if not exe.exists():
        raise PrintedProgramError(f"printed program {program!r} is not built ({exe} missing); "
                                  "reinstall the package")
    try:
        done = subprocess.run([str(exe)], capture_output=True, text=True, timeout=timeout_s,
                              stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired as exc:
        raise PrintedProgramError(f"{program} did not finish in {timeout_s} s") from exc
    if done.returncode != 0:
        raise PrintedProgramError(f"{program} exited with {done.returncode}: {done.stderr.strip()}")
    rows = []
    for line in done.stdout.splitlines():
        if line[:1] != "0":
            continue
        fields = line[1:].split()
        if len(fields) != 4:
            raise PrintedProgramError(f"{program}: unexpected output line {line!r}")
        rows.append([float(v) if v.lower() != "nan" else np.nan for v in fields])
    if not rows:
        raise PrintedProgramError(f"{program} printed no result line")
    return pd.DataFrame(rows, columns=["deg", "dx", "dy", "rot"])
