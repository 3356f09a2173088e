"""Measure the literal scan text against the chosen reading.

For every register entry with ``[[deviation.reading]]`` items, the printed
listing is rebuilt with the scan's literal text put back, compiled with gfortran
like the printed engine, run, and its deflection columns compared with the
published table.  This is the measured evidence behind each uncertain reading.
A listing that cannot print its result as printed (the Case II cognate, D037) is
measured on its src program with a driver (``DRIVERS``).
The 1996 program (Rahman, CSSP: ``CSSP_FILES``) is measured on legacy/src: its printed main
program WRITEs none of Tables 5.2-5.7, so each reading is put back in the src copy, built and run
by harness/arithmetic.py's driver with the legacy engine's flags (one gfortran build per reading,
shared by the six table scenes), and the cells of Tables 5.2-5.7 within 1e-6 relative are counted.
Items of one entry that share a ``group`` are put back together (one row each group); an entry's
items without a ``group`` are put back together (one row per entry).
Needs gfortran on PATH: without it (or when it cannot build the listing as printed)
``measure`` raises ``CompilerError``; ``linkrepro reproduce`` checks for it before
the run starts (``require_compiler``) and skips the measurement only when asked to
(``--skip-readings``).  Without the source tree's listings it is skipped, and the
report says so.
"""
from __future__ import annotations

import shutil
import subprocess
import tempfile
import tomllib
from functools import lru_cache
from pathlib import Path

import pandas as pd

from .engines import parse_printed_output
from .published_tables import PublishedTable
from .register import REGISTER_PATH

PRINTED_DIR = Path(__file__).resolve().parent.parent / "legacy" / "printed"
SRC_DIR = PRINTED_DIR.parent / "src"
FLAGS = ["-std=legacy", "-fno-automatic", "-ffp-contract=off", "-fno-fast-math", "-O1"]
#: the published table and columns each printed program's WRITE gives
COLUMNS = {"ali1977_case1_source.f": ("ali1977_table1", ("src_dx", "src_dy")),
           "ali1977_case1_cognate.f": ("ali1977_table1", ("cog_dx", "cog_dy")),
           "ali1977_case2_source.f": ("ali1977_table2", ("src_dx", "src_dy")),
           "ali1977_case2_cognate.f": ("ali1977_table2", ("cog_dx", "cog_dy")),
           "ali1977_case3_source.f": ("ali1977_table3", ("src_dx", "src_dy"))}
SSP = ["ssp_gmtra.f", "ssp_mprd.f", "ssp_loc.f"]
#: A listing whose printed text cannot give its result (the Case II cognate's page with the
#: loads is missing, D037) is measured on its src program, the page reconstructed, called by
#: a driver with the printed inputs that WRITEs what the listing's statement 200 would.
DRIVERS = {"ali1977_case2_cognate.f": """\
      PROGRAM DRIVE
      DOUBLE PRECISION PI,ALP,DEG(19),XP(19),YP(19),CXP(19),CYP(19),
     *CXX(19),CYY(19),CRT(19),S,DNTY,CCA,CME,CMI,L1,L2,L3,L4,L5
      REAL DSTEP
      PI=3.142857143
      ALP=PI/3.0
      L1=10.0
      L2=10.0
      L3=30.0
      L4=25.0
      L5=30.0
      S=300.0
      DNTY=0.098
      CCA=0.1963495408
      CME=10000000.0
      CMI=0.0030679615
      DSTEP=20.0
      CALL KED2C(L1,L2,L3,L4,L5,ALP,S,DNTY,CCA,CME,CMI,DSTEP,19,DEG,XP,
     *YP,CXP,CYP,CXX,CYY,CRT,ISTAT)
      DO 10 I=1,19
   10 WRITE(6,200)DEG(I),CXX(I),CYY(I),CRT(I)
  200 FORMAT(1H0,5X,F12.6,8X,F12.6,8X,F12.6,8X,F12.6)
      END
"""}
#: The 1996 program is measured on legacy/src (the printed main program WRITEs no table but
#: Table 5.1's crank I_xx): a reading's ``chosen`` is an exact line of legacy/src/<file>.
CSSP_FILES = ("rahman1996_cssp_main.f", "rahman1996_subroutines.f")
#: the published tables its readings are counted on (Table 5.1 is not a series: arithmetic.SERIES)
CSSP_TABLES = tuple(f"rahman1996_table5_{k}" for k in range(2, 8))
#: D116's and D117's criterion: within 1e-6 relative (D056's REAL*4 floor; arithmetic.count_frame's
#: ``within_1e-6``), crank 0-350 deg (the published row 360 is a copy of row 0, D061)
CSSP_REL = 1e-6
CSSP_LAST_ROW = "350"
COMPILER = "gfortran"
COMPILE_TIMEOUT_S = 120


class CompilerError(RuntimeError):
    """gfortran is missing or cannot build a printed listing as printed."""


def _entries() -> list[dict]:
    with open(REGISTER_PATH, "rb") as fh:
        return tomllib.load(fh).get("deviation", [])


def _tables_of(entry: dict) -> tuple[str, ...]:
    readings = entry.get("reading", [])
    if not readings:
        return ()
    if readings[0]["file"] in CSSP_FILES:
        return CSSP_TABLES
    return (COLUMNS[readings[0]["file"]][0],) if readings[0]["file"] in COLUMNS else ()


def _groups(entry: dict) -> list[tuple[str, list[dict]]]:
    """An entry's readings as (group, items), in register order: items sharing a ``group``
    are put back together; without one, all of the entry's items are one group ("")."""
    groups: dict[str, list[dict]] = {}
    for item in entry.get("reading", []):
        groups.setdefault(str(item.get("group", "")), []).append(item)
    return list(groups.items())


def has_readings(table: str) -> bool:
    """Whether the register has reading alternatives measured against this published table."""
    return any(table in _tables_of(entry) for entry in _entries())


def require_compiler(scenes: dict[str, str]) -> None:
    """Raise ``CompilerError`` now, before a long run, if measuring the readings of these
    scenes (name: published table) will need gfortran and it is not on PATH."""
    needing = [name for name, table in scenes.items() if has_readings(table)]
    if needing and _printed_dir() is not None and shutil.which(COMPILER) is None:
        raise CompilerError(_missing_message(needing))


def _missing_message(names: list[str]) -> str:
    return (f"{COMPILER} is not on PATH; it rebuilds the printed listings with the scan's literal text "
            f"to measure the OCR readings of {', '.join(names)}: install it (apt-get install {COMPILER}) "
            "or pass --skip-readings")


def _first_error(stderr: str) -> str:
    """The line of a compiler's messages that says what went wrong."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    return next((line for line in lines if "error" in line.lower()), lines[-1] if lines else "no message")


def _compile(src: Path, exe: Path, *extra: Path) -> None:
    """Build one listing as the printed engine is built.  ``CalledProcessError``: the text
    does not compile (a scan's literal text may not); ``CompilerError``: gfortran cannot run."""
    try:
        subprocess.run([COMPILER, *FLAGS, "-o", str(exe), str(src), *map(str, extra),
                        *[str(PRINTED_DIR / s) for s in SSP]],
                       check=True, capture_output=True, text=True, timeout=COMPILE_TIMEOUT_S)
    except subprocess.TimeoutExpired as exc:
        raise CompilerError(f"{COMPILER} did not finish building {src.name} in {COMPILE_TIMEOUT_S} s") from exc
    except OSError as exc:                 # not on PATH any more, not executable, ...
        raise CompilerError(f"{COMPILER} could not be run: {exc.strerror or exc}") from exc


def _printed_dir() -> Path | None:
    """The listings ship with the source tree; an installed package may lack them."""
    return PRINTED_DIR if PRINTED_DIR.is_dir() else None


def _put_back(text: str, program: str, edits: list[dict]) -> str:
    """``text`` with each edit's ``chosen`` line (its ``occurrence``-th, a whole line) replaced by
    its ``scan`` text; ``ValueError`` if a chosen line is not there."""
    for edit in edits:
        chosen, scan, nth = edit["chosen"], edit["scan"], int(edit.get("occurrence", 1))
        parts = text.split(chosen + "\n")
        if len(parts) <= nth:
            raise ValueError(f"{program}: chosen text {chosen!r} occurs fewer than {nth} times")
        text = (chosen + "\n").join(parts[:nth]) + scan + "\n" + (chosen + "\n").join(parts[nth:])
    return text


def _run_variant(program: str, edits: list[dict], workdir: Path) -> pd.DataFrame:
    text = _put_back(((SRC_DIR if program in DRIVERS else PRINTED_DIR) / program).read_text(), program, edits)
    src = workdir / program
    src.write_text(text)
    exe = workdir / "variant"
    drivers = []
    if program in DRIVERS:
        drivers.append(workdir / "driver.f")
        drivers[0].write_text(DRIVERS[program])
    _compile(src, exe, *drivers)
    done = subprocess.run([str(exe)], capture_output=True, text=True, timeout=60)
    return parse_printed_output(done.stdout).drop_duplicates("deg").set_index("deg")


def _matched(frame: pd.DataFrame, program: str, published: PublishedTable) -> tuple[int, int, float]:
    pub = published.values
    rows = pub["input_deg"] < 360          # row 360 is a copy of row 0 (D011)
    matched, total, worst = 0, 0, 0.0
    for col, quantity in zip(COLUMNS[program][1], ("dx", "dy")):
        count, err = published.matched(col, frame[quantity].reindex(pub.loc[rows, "input_deg"]), rows)
        matched, total, worst = matched + count, total + int(rows.sum()), max(worst, err)
    return matched, total, worst


def measure(table: str = "ali1977_table1") -> pd.DataFrame:
    """One row per reading (an entry, or a group of its items): cells matched with the chosen
    text and with the scan's.  A 1996 table (``CSSP_TABLES``): see ``measure_cssp``."""
    if table in CSSP_TABLES:
        return measure_cssp(table)
    entries = [entry for entry in _entries() if table in _tables_of(entry)]
    if not entries or _printed_dir() is None:
        return pd.DataFrame()
    if shutil.which(COMPILER) is None:
        raise CompilerError(_missing_message([table]))
    published = PublishedTable.load(table)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        baselines = {}
        for entry in entries:
            for group, readings in _groups(entry):
                program = readings[0]["file"]
                if program not in baselines:
                    try:
                        baselines[program] = _matched(_run_variant(program, [], tmp), program, published)
                    except subprocess.CalledProcessError as exc:   # the listing as printed builds with meson
                        raise CompilerError(f"{COMPILER} could not build the printed listing {program} as printed "
                                            f"({_first_error(exc.stderr)}); check the {COMPILER} installation") from exc
                try:
                    scan = _matched(_run_variant(program, readings, tmp), program, published)
                except (subprocess.CalledProcessError, subprocess.TimeoutExpired):
                    scan = (0, baselines[program][1], float("nan"))   # the scan's text does not build or run
                chosen = baselines[program]
                rows.append({"id": entry["id"] + (f" ({group})" if group else ""), "program": program,
                             "chosen_matched": f"{chosen[0]}/{chosen[1]}", "chosen_max_err": chosen[2],
                             "scan_matched": f"{scan[0]}/{scan[1]}", "scan_max_err": scan[2]})
    return pd.DataFrame(rows)


# ---------------------------------------------------------------- the 1996 program (legacy/src)

def _cssp_sources() -> bool:
    """legacy/src's CSSP sources (and what arithmetic.py's build needs) are at hand."""
    from .scenes.rahman1996.arithmetic import LEGACY_DIR, PRINTED, SRC
    return all((LEGACY_DIR / path).is_file() for path in SRC + PRINTED)


def _cssp_readings() -> tuple[tuple[str, str, tuple[tuple[str, str, str, int], ...]], ...]:
    """The register's 1996 readings as (entry id, group, ((file, chosen, scan, occurrence), ...))."""
    out = []
    for entry in _entries():
        if _tables_of(entry) != CSSP_TABLES:
            continue
        for group, items in _groups(entry):
            other = [item["file"] for item in items if item["file"] not in CSSP_FILES]
            if other:
                raise ValueError(f"{entry['id']}: reading of {other[0]} grouped with the 1996 program's")
            out.append((entry["id"], group, tuple((item["file"], item["chosen"], item["scan"],
                                                   int(item.get("occurrence", 1))) for item in items)))
    return tuple(out)


@lru_cache(maxsize=4)
def cssp_counts(readings: tuple) -> tuple[pd.DataFrame, dict[str, str], float]:
    """Build and run legacy/src as it is ("chosen") and once per reading with its scan text put
    back (as ``_cssp_readings`` gives them; the builds side by side on the cores), by
    arithmetic.py's driver and reference flags.  Returns (counts, failures, seconds): counts one
    row per build, table (5.2-5.7) and column with the cells of crank 0-350 within ``CSSP_REL``
    of the published value and the largest change from the chosen build (relative); failures
    the builds that did not build or run (name: why).  Cached: the six scenes share one call.
    ``ValueError`` if a chosen line is not in legacy/src; ``CompilerError`` if the chosen build fails."""
    from .scenes.rahman1996 import arithmetic
    texts = {name: (SRC_DIR / name).read_text() for name in CSSP_FILES}
    variants = [arithmetic.Variant("chosen", "legacy/src as it is: the readings as chosen", False)]
    for k, (entry, group, items) in enumerate(readings):
        edited = dict(texts)
        for file, chosen, scan, nth in items:
            edited[file] = _put_back(edited[file], file, [{"chosen": chosen, "scan": scan, "occurrence": nth}])

        def put_back(files: dict[str, str], edited=edited) -> dict[str, str]:
            return {**files, **edited}
        variants.append(arithmetic.Variant(f"reading{k}", f"{entry} {group}".strip(), False, transform=put_back))
    try:                                            # what no reading edits is compiled once
        m = arithmetic.measure(variants, shared=("driver.f", "imsl_qprog.f", "rahman1996_subroutines.f"))
    except arithmetic.ReferenceFailed as exc:       # legacy/src as it is builds with meson
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


def measure_cssp(table: str = "rahman1996_table5_2") -> pd.DataFrame:
    """One row per 1996 reading (entry and group): the cells of this table, crank 0-350 per
    column, within 1e-6 relative with the chosen text (legacy/src as it is) and with the scan's
    text put back; the largest relative change the scan's text makes in the table.  Empty
    without register readings or the source tree's legacy/; ``CompilerError`` without gfortran."""
    readings = _cssp_readings()
    if not readings or _printed_dir() is None or not _cssp_sources():
        return pd.DataFrame()
    if shutil.which(COMPILER) is None:
        raise CompilerError(_missing_message([table]))
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
    if frame.empty:
        return ("## Reading alternatives\n\nNot measured (needs gfortran on PATH and the source "
                "tree's legacy/printed and legacy/src).")
    if "scan_before" in frame.columns:
        return _cssp_markdown(frame)
    lines = ["## Reading alternatives (measured: the printed listing rebuilt with the scan's literal text)",
             "", "Deflection cells of rows 0-340 within half a unit of the printed digit.", "",
             "| entry | program | chosen reading | max err | scan's literal text | max err |",
             "|---|---|---|---|---|---|"]
    for r in frame.itertuples():
        lines.append(f"| {r.id} | {r.program} | {r.chosen_matched} | {r.chosen_max_err:.4f} | "
                     f"{r.scan_matched} | {r.scan_max_err:.4f} |")
    return "\n".join(lines)


def _cssp_markdown(frame: pd.DataFrame) -> str:
    table = frame.attrs.get("table", "rahman1996_table5_2")
    label = table.removeprefix("rahman1996_table").replace("_", ".")
    rel = f"{CSSP_REL:.0e}".replace("e-0", "e-")
    lines = ["## Reading alternatives (measured: legacy/src rebuilt with the scan's text put back)", "",
             f"Cells of Table {label}, crank 0-{CSSP_LAST_ROW} deg per column (row 360 is a copy of row 0, "
             f"D061), within {rel} relative of the published value (the criterion of D116 and D117, "
             "D056's floor): legacy/src as it is (the chosen readings) and with each reading's lines put back "
             "as the scan prints them (where that does not compile, as the other grouping the scan admits: see "
             "the entry), built with the legacy engine's flags and run by harness/arithmetic.py's driver. "
             f"{frame.attrs.get('builds', len(frame) + 1)} gfortran builds shared by the six table scenes, "
             f"{frame.attrs.get('seconds', float('nan')):.1f} s. Re-measure: "
             f"`python -c \"from linkrepro.harness import readings; print(readings.measure('{table}'))\"`.", "",
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
