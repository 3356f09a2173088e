"""Ali (1977): what the printed K.E.D. programs WRITE, read back (the ``printed`` engine's
tables and the readings driver's rebuilt listings)."""
from __future__ import annotations

import pandas as pd

from ...engines import PrintedProgramError, run_program


def run_printed(program: str, timeout_s: float = 60.0) -> pd.DataFrame:
    """Run one Ali (1977) printed program; return the path point's rows (deg, dx, dy, rot).

    Cases I and II WRITE with FORMAT 200, (1H0,5X,F12.6,8X,F12.6,8X,F12.6,8X,F12.6):
    a carriage-control '0' then four numbers.  Case III's FORMAT 500 starts a page
    ('1') per angle with the angle and the tip's three values, then the other nodes.
    """
    frame = parse_printed_output(run_program(program, timeout_s=timeout_s))
    if frame.empty:
        raise PrintedProgramError(f"{program} printed no result line")
    return frame


def parse_printed_output(text: str) -> pd.DataFrame:
    """The path point's rows (deg, dx, dy, rot) of a printed program's output."""
    rows = []
    for line in text.splitlines():
        fields = line[1:].split()
        if line[:1] not in "01" or len(fields) != 4:
            continue                       # page headers; Case III's lines for nodes 2-5
        try:
            rows.append([float(v) for v in fields])
        except ValueError:
            continue                       # the 1H1 column-heading line
    return pd.DataFrame(rows, columns=["deg", "dx", "dy", "rot"])
