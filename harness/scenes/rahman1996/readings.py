"""Rahman (1996): the reading driver of the CSSP program (``harness/readings.py``).

The 1996 program is measured on legacy/src: its printed main program WRITEs none of Tables
5.2-5.7, so each reading is put back in the src copy, built and run by the arithmetic study's
driver with the legacy engine's flags (one gfortran build per reading, shared by the six table
scenes), and the cells of Tables 5.2-5.7 within 1e-6 relative are counted.
"""
from __future__ import annotations

import shutil
from functools import lru_cache

import pandas as pd

from ... import readings as machine
from ...readings import COMPILER, SRC_DIR, CompilerError, missing_message, put_back
from . import arithmetic, arithmetic_build as build
from .arithmetic_variants import Variant

#: The 1996 program is measured on legacy/src (the printed main program WRITEs no table but
#: Table 5.1's crank I_xx): a reading's ``chosen`` is an exact line of legacy/src/<file>.
CSSP_FILES = ("rahman1996_cssp_main.f", "rahman1996_subroutines.f")
#: the published tables its readings are counted on (Table 5.1 is not a series: arithmetic.SERIES)
CSSP_TABLES = tuple(f"rahman1996_table5_{k}" for k in range(2, 8))
#: D116's and D117's criterion: within 1e-6 relative (D056's REAL*4 floor; arithmetic.count_frame's
#: ``within_1e-6``), crank 0-350 deg (the published row 360 is a copy of row 0, D061)
CSSP_REL = 1e-6
CSSP_LAST_ROW = "350"
#: the listings whose readings this driver measures
files = CSSP_FILES


def tables_of(program: str) -> tuple[str, ...]:
    """The published tables the 1996 program's readings are counted on (Tables 5.2-5.7)."""
    return CSSP_TABLES


def _cssp_sources() -> bool:
    """legacy/src's CSSP sources (and what the arithmetic study's build needs) are at hand."""
    return all((build.LEGACY_DIR / path).is_file() for path in build.SRC + build.PRINTED)


def _cssp_readings() -> tuple[tuple[str, str, tuple[tuple[str, str, str, int], ...]], ...]:
    """The register's 1996 readings as (entry id, group, ((file, chosen, scan, occurrence), ...))."""
    out = []
    for entry in machine.entries():
        items = entry.get("reading", [])
        if not items or items[0]["file"] not in CSSP_FILES:
            continue
        for group, items in machine.groups(entry):
            other = [item["file"] for item in items if item["file"] not in CSSP_FILES]
            if other:
                raise ValueError(f"{entry['id']}: reading of {other[0]} grouped with the 1996 program's")
            out.append((entry["id"], group, tuple((item["file"], item["chosen"], item["scan"],
                                                   int(item.get("occurrence", 1))) for item in items)))
    return tuple(out)


@lru_cache(maxsize=4)
def cssp_counts(readings: tuple) -> tuple[pd.DataFrame, dict[str, str], float]:
    """Build and run legacy/src as it is ("chosen") and once per reading with its scan text put
    back (as ``_cssp_readings`` gives them; the builds side by side on the cores), by the
    arithmetic study's driver and reference flags (arithmetic_build.py).  Returns (counts,
    failures, seconds): counts one row per build, table (5.2-5.7) and column with the cells of crank 0-350 within ``CSSP_REL``
    of the published value and the largest change from the chosen build (relative); failures
    the builds that did not build or run (name: why).  Cached: the six scenes share one call.
    ``ValueError`` if a chosen line is not in legacy/src; ``CompilerError`` if the chosen build fails."""
    texts = {name: (SRC_DIR / name).read_text() for name in CSSP_FILES}
    variants = [Variant("chosen", "legacy/src as it is: the readings as chosen", False)]
    for k, (entry, group, items) in enumerate(readings):
        edited = dict(texts)
        for file, chosen, scan, nth in items:
            edited[file] = put_back(edited[file], file, [{"chosen": chosen, "scan": scan, "occurrence": nth}])

        def with_reading(files: dict[str, str], edited=edited) -> dict[str, str]:
            return {**files, **edited}
        variants.append(Variant(f"reading{k}", f"{entry} {group}".strip(), False, transform=with_reading))
    try:                                            # what no reading edits is compiled once
        m = build.measure(variants, shared=("driver.f", "imsl_qprog.f", "rahman1996_subroutines.f"))
    except build.ReferenceFailed as exc:       # legacy/src as it is builds with meson
        raise CompilerError(f"{COMPILER} could not build legacy/src's CSSP as it is ({exc}); "
                            f"check the {COMPILER} installation") from exc
    cells = arithmetic.cell_frame(m)
    series = [t.removeprefix("rahman1996_table").replace("_", ".") for t in CSSP_TABLES]
    rows = pd.to_numeric(cells["row"], errors="coerce")
    cells = cells[cells["table"].isin(series) & (rows <= float(CSSP_LAST_ROW))]
    parts = []
    for column, part in cells.groupby("column", sort=False):
        counts = arithmetic.count_frame(m, part)
        counts = counts[counts["table"] != "all"].assign(column=column)
        parts.append(counts[["variant", "table", "column", "cells", "within_1e-6", "max_rel_change"]])
    return pd.concat(parts, ignore_index=True), dict(m.failures), m.seconds


def measure(table: str = "rahman1996_table5_2", entries: list[dict] | None = None) -> pd.DataFrame:
    """One row per 1996 reading (entry and group): the cells of this table, crank 0-350 per
    column, within 1e-6 relative with the chosen text (legacy/src as it is) and with the scan's
    text put back; the largest relative change the scan's text makes in the table.  Empty
    without register readings or the source tree's legacy/; ``CompilerError`` without gfortran.
    ``entries``: as ``harness/readings.measure`` passes them (the register's, which this reads
    itself)."""
    readings = _cssp_readings()
    if not readings or machine.printed_dir() is None or not _cssp_sources():
        return pd.DataFrame()
    if shutil.which(COMPILER) is None:
        raise CompilerError(missing_message([table]))
    counts, failures, seconds = cssp_counts(readings)
    label = table.removeprefix("rahman1996_table").replace("_", ".")
    part = counts[counts["table"] == label].set_index(["variant", "column"])

    def matched(variant: str, column: str) -> str:
        if variant in failures:
            return failures[variant].split(":")[0]
        return f"{part.at[(variant, column), 'within_1e-6']}/{part.at[(variant, column), 'cells']}"

    rows = []
    for k, (entry, group, items) in enumerate(readings):
        name = f"reading{k}"
        rows.append({"id": entry, "reading": group, "program": ", ".join(dict.fromkeys(i[0] for i in items)),
                     "lines": len(items),
                     "chosen_before": matched("chosen", "before"), "chosen_after": matched("chosen", "after"),
                     "scan_before": matched(name, "before"), "scan_after": matched(name, "after"),
                     "scan_max_rel_change": (float("nan") if name in failures
                                             else float(part.loc[name, "max_rel_change"].max())),
                     "why": failures.get(name, "")})
    frame = pd.DataFrame(rows)
    frame.attrs.update(table=table, builds=len(readings) + 1, seconds=seconds)
    return frame


def as_markdown(frame: pd.DataFrame) -> str:
    table = frame.attrs.get("table", "rahman1996_table5_2")
    label = table.removeprefix("rahman1996_table").replace("_", ".")
    rel = f"{CSSP_REL:.0e}".replace("e-0", "e-")
    lines = ["## Reading alternatives (measured: legacy/src rebuilt with the scan's text put back)", "",
             f"Cells of Table {label}, crank 0-{CSSP_LAST_ROW} deg per column (row 360 is a copy of row 0, "
             f"D061), within {rel} relative of the published value (the criterion of D116 and D117, "
             "D056's floor): legacy/src as it is (the chosen readings) and with each reading's lines put back "
             "as the scan prints them (where that does not compile, as the other grouping the scan admits: see "
             "the entry), built with the legacy engine's flags and run by the arithmetic study's driver "
             "(harness/scenes/rahman1996/arithmetic_build.py). "
             f"{frame.attrs.get('builds', len(frame) + 1)} gfortran builds shared by the six table scenes, "
             f"{frame.attrs.get('seconds', float('nan')):.1f} s. Re-measure: "
             f"`python -c \"from linkrepro.harness.scenes.rahman1996 import readings; print(readings.measure('{table}'))\"`.", "",
             "| entry | reading | lines put back | chosen: before | chosen: after | scan's text: before | "
             "scan's text: after | largest change (rel) |", "|---|---|---|---|---|---|---|---|"]
    for r in frame.itertuples():
        change = "-" if r.scan_max_rel_change != r.scan_max_rel_change else f"{r.scan_max_rel_change:.1e}"
        lines.append(f"| {r.id} | {r.reading or '(all)'} | {r.lines} | {r.chosen_before} | {r.chosen_after} | "
                     f"{r.scan_before} | {r.scan_after} | {change} |")
    failed = frame[frame["why"] != ""]
    if len(failed):
        lines += [""] + [f"- {r.id} {r.reading}: {r.why}" for r in failed.itertuples()]
    return "\n".join(lines)

