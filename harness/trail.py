"""A published cell's trail: what the thesis printed, what every engine gives and with what
status, the register entries that explain a difference, the listing lines behind the cell.

``cell_trail(scene, row, column, diff)`` gathers it from a table scene's diff (``diff.csv`` of
a run, or ``compute_diff``); ``linkrepro explain`` prints it and the HTML report shows it.
"""
from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from . import listing_lines, register as register_mod
from .diff import classify_cells, words
from .engines import ENGINES
from .listing_lines import ListingLine
from .published_tables import PUBLISHED_DIR
from .register import Deviation
from .table_scene import TableScene


class CellNotFound(LookupError):
    """A row or column that the scene's published table does not have."""


@dataclass(frozen=True)
class EngineCell:
    """One engine's value of a cell: ``difference`` = |value - published| (the table's unit) and
    the ``digits`` agreed with the published value (``diff.agreed_digits``), at full precision
    (as ``diff.csv`` gives them); NaN when not produced.  ``counts_as``: what the cell counts as
    (``diff.classify_cells``: 'matched', 'explained: KIND', 'within tolerance', 'unresolved', ...)."""
    engine: str
    value: float
    status: str
    difference: float
    digits: float
    register_ids: tuple[str, ...]
    counts_as: str


@dataclass(frozen=True)
class Trail:
    scene: TableScene
    row: str
    column: str
    published_text: str
    published: float
    half_unit: float
    source: str                                  # where the thesis prints the table
    engines: tuple[EngineCell, ...]
    entries: tuple[Deviation, ...]               # every entry any engine's status names
    statements: tuple[ListingLine, ...]          # where the listings compute or write the cell
    notes: tuple[str, ...] = ()                  # the scene's ``trail_notes`` (e.g. which arithmetics reach it)
    assumptions: str = ""                        # the model assumptions its corrected engine keeps, said


def printed_digits(text: str) -> int:
    """Significant digits of a number as printed ("-0.238" 3, "1.946666E-04" 7)."""
    mantissa = text.strip().upper().partition("E")[0].lstrip("+-").replace(".", "")
    return len(mantissa.lstrip("0")) or 1


def digits_reproduced(difference: float, half_unit: float, printed: int) -> int | None:
    """How many of the ``printed`` significant digits a value reproduces: the most k <= printed
    such that |value - published| is within half a unit of the k-th digit (a matched cell: all
    of them; a wrong sign: 0).  None where the engine gives no value."""
    if math.isnan(difference):
        return None
    if difference <= half_unit * (1.0 + 1e-9):
        return printed
    return max(0, printed - math.ceil(math.log10(difference / half_unit) - 1e-9))


def published_source(table: str) -> str:
    """The published CSV's first comment: where the thesis prints the table (seed lines)."""
    for line in (PUBLISHED_DIR / f"{table}.csv").read_text().splitlines():
        if line.startswith("#"):
            return line.lstrip("# ").strip()
    return f"harness/published/{table}.csv"


def same_row(key, row: str) -> bool:
    """Whether a diff row's key (a number or ``link/quantity`` text) names ``row``."""
    try:
        return float(key) == float(row)
    except (TypeError, ValueError):
        return str(key) == str(row)


def cell_trail(scene: TableScene, row: str, column: str, diff: pd.DataFrame,
               register: dict[str, Deviation] | None = None) -> Trail:
    """The trail of the cell (``row``: the key as printed, e.g. ``160`` or ``crank/i_xx``)."""
    register = register if register is not None else register_mod.load()
    if column not in scene.values:
        raise CellNotFound(f"{scene.name} has no column {column!r}; its columns: {', '.join(scene.values)}")
    keys = diff[scene.key_name]
    cell = diff[(diff["column"] == column) & keys.map(lambda k: same_row(k, row))]
    if cell.empty:
        rows = ", ".join(dict.fromkeys(str(k) for k in keys))
        raise CellNotFound(f"{scene.name} has no row {row!r}; its rows ({scene.key_name}): {rows}")
    engines, ids = [], []
    classes = classify_cells(cell, register)
    for engine in ENGINES:
        found = cell[cell["engine"] == engine]
        if found.empty:
            continue
        r = found.iloc[0]
        names = tuple(str(r["register_ids"]).split()) if isinstance(r["register_ids"], str) else ()
        ids += names
        count, kind = classes.loc[found.index[0]]
        engines.append(EngineCell(engine, float(r["value"]), str(r["status"]), float(r["abs_diff"]),
                                  float(r["digits"]), names, words(count) + (f": {kind}" if kind else "")))
    first = cell.iloc[0]
    key = str(first[scene.key_name])
    statements = [line for statement in scene.statements(key, column) for line in listing_lines.find(statement)]
    return Trail(scene, key, column, str(first["published_text"]), float(first["published"]),
                 float(first["half_unit"]), published_source(scene.table), tuple(engines),
                 tuple(register[i] for i in dict.fromkeys(ids) if i in register), tuple(statements),
                 notes=tuple(scene.trail_notes(key, column)),
                 assumptions=register_mod.assumptions_said(scene.name, register))


def read_diff(scene: TableScene, out_dir: Path | None) -> pd.DataFrame:
    """The scene's diff: ``out_dir/<scene>/diff.csv`` when a run wrote it, else computed now
    (every engine run: seconds to a minute)."""
    path = Path(out_dir) / scene.name / "diff.csv" if out_dir is not None else None
    if path is not None and path.is_file():
        return pd.read_csv(path, keep_default_na=True, dtype={"published_text": str, "register_ids": str})
    return scene.compute().diff


def _number(value: float) -> str:
    return "not produced" if math.isnan(value) else f"{value:.9g}"


def _digits(engine: EngineCell, trail: Trail) -> str:
    """The printed digits ``engine`` reproduces, as the page's marker shows them ("2/3"; "-": no value)."""
    printed = printed_digits(trail.published_text)
    found = digits_reproduced(engine.difference, trail.half_unit, printed)
    return "-" if found is None else f"{found}/{printed}"


def as_text(trail: Trail, edits_shown: int = 6, width: int = 100) -> str:
    """The trail for a terminal: published cell, engines, entries, listing lines."""
    scene = trail.scene
    out = [f"{scene.name}  {scene.key_name} = {trail.row}  column {trail.column}", f"  {scene.title}", "",
           f"published  {trail.published_text}  (+/- {trail.half_unit:g}, {printed_digits(trail.published_text)} "
           f"significant digits; {trail.source})", "",
           f"  {'engine':15s} {'value':>16s} {'|- published|':>13s} {'digits':>6s}  counts as (register ids)"]
    for e in trail.engines:
        ids = f"  ({' '.join(e.register_ids)})" if e.register_ids else ""
        diff = "" if math.isnan(e.value) else f"{e.difference:.3g}"
        out.append(f"  {e.engine:15s} {_number(e.value):>16s} {diff:>13s} {_digits(e, trail):>6s}  {e.counts_as}{ids}")
    for note in trail.notes:
        out += [""] + textwrap.wrap(note, width, break_on_hyphens=False)
    if trail.assumptions:
        out += ["", textwrap.fill(trail.assumptions, width, break_on_hyphens=False)]
    out += ["", "listing lines behind the cell:"]
    out += [f"  {line.where()}\n      {line.text.strip()}" for line in trail.statements] or ["  (none named)"]
    for entry in trail.entries:
        out += ["", f"{entry.id}  {entry.kind}{', ' + entry.certainty if entry.certainty else ''}: {entry.title}"]
        fields = entry.how_known() + [(field, getattr(entry, field)) for field in ("where", "printed", "meant",
                                                                                     "evidence", "effect")]
        out += [textwrap.fill(text, width, initial_indent=f"  {field + ':':10s}", subsequent_indent=" " * 12,
                              break_on_hyphens=False) for field, text in fields]
        if entry.quirk:
            out.append(f"  port quirk: {entry.quirk}")
        out += [f"  printed line {line.where()}\n      {line.text.strip()}" for line in listing_lines.cited(entry)]
        edits = listing_lines.tagged(entry.id)
        out += [f"  edit in {line.where()}\n      {line.text.strip()}" for line in edits[:edits_shown]]
        if len(edits) > edits_shown:
            out.append(f"  ... and {len(edits) - edits_shown} more lines of legacy/src tagged {entry.id}")
    return "\n".join(out)
