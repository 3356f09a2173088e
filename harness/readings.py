"""Measure the literal scan text against the chosen reading: the machine.

For every register entry with ``[[deviation.reading]]`` items, a listing is rebuilt with the
scan's literal text put back, compiled with gfortran, run, and its cells compared with the
published table: the measured evidence behind each uncertain reading.  Items of one entry that
share a ``group`` are put back together (one row each group); an entry's items without a
``group`` are put back together (one row per entry).

What a thesis's listings need to be rebuilt and counted is its reading driver (a table
scene's ``readings``: ``harness/scenes/<thesis>/readings.py``): ``files`` (the listings its
readings edit), ``tables_of(file)`` (the published tables a file's readings are counted on),
``measure(table, entries)`` (one row per reading of those entries, as a DataFrame: empty when
the listings are not at hand) and ``as_markdown(frame)``.  Here: the register's readings,
putting a reading back, finding gfortran, and the driver-independent parts of the report.

Needs the run-time compiler on PATH (``COMPILER``: ``$LINKREPRO_FC``, else gfortran; its family's
flags, ``FLAGS``, as meson.build gives the legacy build): without it ``measure`` raises ``CompilerError``; ``linkrepro
reproduce`` checks for it before the run starts (``require_compiler``) and skips the
measurement only when asked to (``--skip-readings``).  Without the source tree's listings it
is skipped, and the report says so.
"""
from __future__ import annotations

import os
import shutil
from pathlib import Path
from typing import Any

import pandas as pd

from .register import REGISTER_PATH, raw_entries

PRINTED_DIR = Path(__file__).resolve().parent.parent / "legacy" / "printed"
SRC_DIR = PRINTED_DIR.parent / "src"
#: the Fortran compiler that builds the listings at run time: ``$LINKREPRO_FC`` (a name on PATH or
#: a path: ``gfortran-11``, ``flang-22``), else ``gfortran``; ``make toolchains`` sets it to the
#: compiler that built the package, so a run's engines and its rebuilt listings share a toolchain
FC_ENV = "LINKREPRO_FC"
COMPILER = os.environ.get(FC_ENV, "").strip() or "gfortran"
#: meson.build's fortran_legacy_args per compiler family (tests hold them equal): LLVM flang spells
#: gfortran's static storage -fno-automatic -fsave-main-program and has no -std=legacy (it takes the
#: extensions by default) and no -fallow-argument-mismatch (it warns): meson.build says why
LEGACY_FLAGS = {"gfortran": ("-std=legacy", "-fno-automatic", "-ffp-contract=off", "-fno-fast-math",
                             "-fallow-argument-mismatch", "-O1"),
                "flang": ("-fno-automatic", "-fsave-main-program", "-ffp-contract=off", "-fno-fast-math", "-O1")}


def family(compiler: str) -> str:
    """``compiler``'s family by its name: "flang" (LLVM flang) where the name says flang, else "gfortran"."""
    return "flang" if "flang" in Path(compiler).name else "gfortran"


#: the flags a listing with a reading put back is built with: the legacy build's, but the
#: argument-mismatch allowance no printed listing needs
FLAGS = [flag for flag in LEGACY_FLAGS[family(COMPILER)] if flag != "-fallow-argument-mismatch"]
COMPILE_TIMEOUT_S = 120


class CompilerError(RuntimeError):
    """gfortran is missing or cannot build a printed listing as printed."""


def entries() -> list[dict]:
    """Every register entry (as the TOML holds it)."""
    return list(raw_entries(REGISTER_PATH))


def tables_of(entry: dict, driver: Any) -> tuple[str, ...]:
    """The published tables ``driver`` counts ``entry``'s readings on (none: not its listings)."""
    readings = entry.get("reading", [])
    if not readings or readings[0]["file"] not in driver.files:
        return ()
    return driver.tables_of(readings[0]["file"])


def groups(entry: dict) -> list[tuple[str, list[dict]]]:
    """An entry's readings as (group, items), in register order: items sharing a ``group``
    are put back together; without one, all of the entry's items are one group ("")."""
    out: dict[str, list[dict]] = {}
    for item in entry.get("reading", []):
        out.setdefault(str(item.get("group", "")), []).append(item)
    return list(out.items())


def has_readings(table: str, driver: Any) -> bool:
    """Whether the register has reading alternatives ``driver`` measures against this table."""
    return driver is not None and any(table in tables_of(entry, driver) for entry in entries())


def require_compiler(scenes: dict[str, tuple[str, Any]]) -> None:
    """Raise ``CompilerError`` now, before a long run, if measuring the readings of these
    scenes (name: (published table, reading driver)) will need gfortran and it is not on PATH."""
    needing = [name for name, (table, driver) in scenes.items() if has_readings(table, driver)]
    if needing and printed_dir() is not None and shutil.which(COMPILER) is None:
        raise CompilerError(missing_message(needing))


def missing_message(names: list[str]) -> str:
    return (f"{COMPILER} is not on PATH; it rebuilds the printed listings with the scan's literal text "
            f"to measure the OCR readings of {', '.join(names)}: install it (apt-get install {COMPILER}) "
            "or pass --skip-readings")


def first_error(stderr: str) -> str:
    """The line of a compiler's messages that says what went wrong."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    return next((line for line in lines if "error" in line.lower()), lines[-1] if lines else "no message")


def printed_dir() -> Path | None:
    """The listings ship with the source tree; an installed package may lack them."""
    return PRINTED_DIR if PRINTED_DIR.is_dir() else None


def put_back(text: str, program: str, edits: list[dict]) -> str:
    """``text`` with each edit's ``chosen`` line (its ``occurrence``-th, a whole line) replaced by
    its ``scan`` text; ``ValueError`` if a chosen line is not there."""
    for edit in edits:
        chosen, scan, nth = edit["chosen"], edit["scan"], int(edit.get("occurrence", 1))
        parts = text.split(chosen + "\n")
        if len(parts) <= nth:
            raise ValueError(f"{program}: chosen text {chosen!r} occurs fewer than {nth} times")
        text = (chosen + "\n").join(parts[:nth]) + scan + "\n" + (chosen + "\n").join(parts[nth:])
    return text


def measure(table: str, driver: Any) -> pd.DataFrame:
    """One row per reading (an entry, or a group of its items) ``driver`` counts on ``table``:
    cells matched with the chosen text and with the scan's (empty without readings or without
    the source tree's listings)."""
    chosen = [entry for entry in entries() if table in tables_of(entry, driver)]
    if not chosen or printed_dir() is None:
        return pd.DataFrame()
    return driver.measure(table, chosen)


def as_markdown(frame: pd.DataFrame, driver: Any) -> str:
    """The report's section: ``driver``'s table, or why nothing was measured."""
    if frame.empty:
        return ("## Reading alternatives\n\nNot measured (needs gfortran on PATH and the source "
                "tree's legacy/printed and legacy/src).")
    return driver.as_markdown(frame)
