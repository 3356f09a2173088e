"""Scenes rahman1996-table5_1 ... table5_7: Rahman (1996), the CSSP balancing example
of section 5.2 (Tables 5.1-5.7).

One run of each engine gives every table (the program computes all of them in one
pass), so each engine's run is cached for the process and shared by the seven scenes.
"""
from __future__ import annotations

import tempfile
from functools import lru_cache
from pathlib import Path

import numpy as np
import pandas as pd

from ....legacy import rahman1996
from ....legacy.rahman1996 import CSSP_COLUMNS, INERTIA_ROWS
from ....port.rahman1996.balance import CRANK_DEG, CsspInputs, balance
from ....port.rahman1996.quirks import CSSP_CORRECTED, CSSP_PRINTED
from ...engines import PrintedProgramError, program_path, run_program
from ...listing_lines import Statement
from ...table_scene import TableScene
from . import arithmetic, readings
from .quantities import QUANTITIES
from .table_forms import INERTIA_COLUMNS, SERIES_COLUMNS, as_tables, inertia_frame, series_frame

PROGRAM = "rahman1996_cssp_main"
#: relative difference within the REAL*4 sensitivity measured in register D056
REL_FLOOR = 1e-6

TITLES = {
    "5_1": "mass properties (principal moments of inertia) of crank and connecting rod",
    "5_2": "objective function G at each crank position",
    "5_3": "shaking force (lbf)",
    "5_4": "shaking moment (lbf in)",
    "5_5": "bearing force (lbf)",
    "5_6": "bearing torque (lbf in)",
    "5_7": "input torque (lbf in)",
}
INPUTS = ("Section 5.2 and the listing's PARAMETERs: a1=2, a2=8, a4=1, s1=0.4 in, alpha4=250 deg, "
          "3000 rpm, g=386.4 in/s^2, weights 1.9, 7.6, 6.0 lbf, W1..W5=1, bearing length 0.4 in; "
          "37 crank positions 0..360 deg. 'before' = the four equal point masses per link, 'after' "
          "= the QP solution (our QPROG stand-in, D050). port_corrected: every registered bug of "
          "the listing removed.")


@lru_cache(maxsize=1)
def legacy_tables() -> dict[str, pd.DataFrame]:
    """Every table from one call of the FORTRAN (legacy/src)."""
    return as_tables(rahman1996.cssp())


def printed_run() -> dict:
    """The printed program as a subprocess, in a fresh directory (it OPENs dint.dat NEW);
    kept for the process, once per program file (``$LINKREPRO_PRINTED_BIN`` pointed elsewhere
    runs that one).

    Its one live per-position WRITE is ``TH1, dint`` (the input torque's percentage
    decrement, Figure 5.6); at the end it WRITEs ``I1X, NUI1X`` (Table 5.1, crank I_xx).
    """
    return _printed_run(program_path(PROGRAM))


@lru_cache(maxsize=2)
def _printed_run(exe: Path) -> dict:         # exe: the cache's key (run_program finds the same)
    with tempfile.TemporaryDirectory() as tmp:
        run_program(PROGRAM, cwd=Path(tmp))
        lines = [line.split() for line in (Path(tmp) / "dint.dat").read_text().splitlines() if line.strip()]
    try:
        numbers = np.array([[float(v) for v in fields] for fields in lines])
    except ValueError as exc:
        raise PrintedProgramError(f"{PROGRAM}: unreadable dint.dat: {exc}") from exc
    if numbers.shape != (len(CRANK_DEG) + 1, 2):
        raise PrintedProgramError(f"{PROGRAM}: dint.dat has shape {numbers.shape}, expected 38 x 2")
    return {"dint_pct": numbers[:-1], "crank_ixx": numbers[-1]}


def printed_tables() -> dict[str, pd.DataFrame]:
    """What the printed program gives of the tables: only Table 5.1's crank I_xx."""
    nan = np.full((len(CRANK_DEG), 2), np.nan)
    tables = {t: series_frame(nan) for t in TITLES if t != "5_1"}
    inertia = np.full((len(INERTIA_ROWS), 2), np.nan)
    inertia[0] = printed_run()["crank_ixx"]
    tables["5_1"] = inertia_frame(inertia)
    return tables


@lru_cache(maxsize=None)
def port_tables(quirks) -> dict[str, pd.DataFrame]:
    """Every table from one balance() of the port with these quirks."""
    return as_tables(balance(CsspInputs(), quirks=quirks))


#: each series table's variables in the listing: before, after (TABLE(J,k) in the src copy)
SERIES_VARIABLES = {"5_2": ("OBJFUN", "NUOBJFUN"), "5_3": ("shf", "nushf"), "5_4": ("sht", "nusht"),
                    "5_5": ("brf", "nubrf"), "5_6": ("brt", "nubrt"), "5_7": ("int", "nuint")}


def statements(table: str):
    """Where the listing computes a cell of ``table`` (printed/, the main program) and where the
    src copy hands it to Python (``TABLE(J,k)=`` or ``INERT(i,j)=``, the D053 edit)."""
    main = "rahman1996_cssp_main.f"

    def lines(variable: str, handed: str) -> tuple[Statement, ...]:
        return (Statement("printed", main, rf"(?i)^\s+{variable}="),
                Statement("src", main, rf"(?i)^\s+{handed}={variable}\s"))

    def where(row: str, column: str) -> tuple[Statement, ...]:
        after = column == "after"
        if table == "5_1":
            link, quantity = row.split("/")
            variable = ("NU" if after else "") + f"I{1 if link == 'crank' else 2}{quantity[-1].upper()}"
            index = INERTIA_ROWS.index((link, quantity)) + 1
            return lines(variable, rf"INERT\({index},{2 if after else 1}\)")
        variable = SERIES_VARIABLES[table][after]
        return lines(variable, rf"TABLE\(J,{CSSP_COLUMNS.index((table, column)) + 1}\)")
    return where


#: the engines that compute in the listing's arithmetic: a run of the listing under another
#: arithmetic of the time explains their cells (D181); port_corrected is another model
LISTING_ENGINES = ("printed", "legacy", "port_printed")


def _study_cell(table: str, row) -> tuple[str, str]:
    """A diff's (table, row key) as the arithmetic study names the cell ("5.2", "120")."""
    return table.replace("_", "."), str(row) if table == "5_1" else str(int(float(row)))


def explained_by_run(table: str):
    """A cell of ``table`` that an engine in the listing's arithmetic misses is explained by
    D181 where an arithmetic of the study as consistent with the tables as the adopted one
    reaches its printed digit (``arithmetic.explaining``, from the committed record)."""
    def ids(row, column: str, engine: str) -> tuple[str, ...]:
        if engine not in LISTING_ENGINES:
            return ()
        return ("D181",) if arithmetic.explaining(*_study_cell(table, row), column) else ()
    return ids


def trail_notes(table: str):
    """Which of the study's arithmetics reach a cell's printed digit (``arithmetic.trail_note``)."""
    return lambda row, column: arithmetic.trail_note(*_study_cell(table, row), column)


#: the process the Rahman (1996) scenes share (one run of each engine gives every table); it
#: starts last, when the Newton kernels it shares with Rahman (1991) are compiled
GROUP, START = "rahman1996", 2


def _scene(table: str) -> TableScene:
    inertia = table == "5_1"
    return TableScene(
        name=f"rahman1996-table{table}",
        title=f"Rahman (1996) Table {table.replace('_', '.')}: {TITLES[table]}, before and after optimum balancing",
        group=GROUP,
        start=START,
        table=f"rahman1996_table{table}",
        columns=INERTIA_COLUMNS if inertia else SERIES_COLUMNS,
        statements=statements(table),
        key=("link", "quantity") if inertia else "crank_deg",
        inputs=INPUTS,
        printed=lambda: printed_tables()[table],
        legacy=lambda: legacy_tables()[table],
        port=lambda quirks: port_tables(quirks)[table],
        notes=["The seven Rahman scenes share one run of each engine (the program computes every table "
               "at once): the first scene's timings include the run, the others read its cache.",
               "port_corrected is the closed-loop Newton-Euler model (register D079), not the listing's "
               "open loop: its cells differ from the published ones by design.",
               "printed engine: the printed program WRITEs only Table 5.1's crank I_xx (and the input "
               "torque's percentage, replotted in rahman1996-figures); it is built with its constants read "
               "as the 1996 compiler read them (register D180: applied at build time, legacy/printed/ as printed).",
               "Which arithmetics of 1996 machines reach each cell's printed digit is in the cell's trail "
               "(`linkrepro explain`, report.html), from the arithmetic study's record (D180, D181)."],
        quirks=(CSSP_PRINTED, CSSP_CORRECTED),
        rel_floor=REL_FLOOR,
        floor_id="D056",
        quantities=QUANTITIES[f"rahman1996-table{table}"],
        readings=readings,
        explained_by_run=explained_by_run(table),
        trail_notes=trail_notes(table),
    )


TABLES = [_scene(t) for t in TITLES]
