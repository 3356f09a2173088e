"""Ali (1977): the reading driver of the K.E.D. listings (``harness/readings.py``).

A reading of a printed listing is put back in ``legacy/printed``, the listing built as the
printed engine builds it (with the IBM SSP routines it calls), run, and its deflection columns
compared with the published table.  A listing that cannot print its result as printed (the Case
II cognate, D037) is measured on its src program with a driver (``DRIVERS``).
"""
from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

import pandas as pd

from .printed_output import parse_printed_output
from ... import build_cache
from ...published_tables import PublishedTable
from ...readings import (COMPILE_TIMEOUT_S, COMPILER, FLAGS, PRINTED_DIR, SRC_DIR, CompilerError, first_error, groups,
                         missing_message, put_back)

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
#: the listings whose readings this driver measures
files = tuple(COLUMNS)


def tables_of(program: str) -> tuple[str, ...]:
    """The published table a listing's readings are counted on."""
    return (COLUMNS[program][0],)


def _compile(src: Path, exe: Path, *extra: Path) -> None:
    """Build one listing as the printed engine is built (or take that build from the build
    cache, ``harness/build_cache.py``).  ``CalledProcessError``: the text does not compile (a
    scan's literal text may not); ``CompilerError``: gfortran cannot run."""
    inputs = [src, *extra, *[PRINTED_DIR / s for s in SSP]]

    def build() -> None:
        try:
            subprocess.run([COMPILER, *FLAGS, "-o", str(exe), *map(str, inputs)],
                           check=True, capture_output=True, text=True, timeout=COMPILE_TIMEOUT_S)
        except subprocess.TimeoutExpired as exc:
            raise CompilerError(f"{COMPILER} did not finish building {src.name} in {COMPILE_TIMEOUT_S} s") from exc
        except OSError as exc:             # not on PATH any more, not executable, ...
            raise CompilerError(f"{COMPILER} could not be run: {exc.strerror or exc}") from exc
    build_cache.executable(build_cache.key(COMPILER, FLAGS, [(p.name, p.read_text()) for p in inputs]), exe, build)


def _run_variant(program: str, edits: list[dict], workdir: Path) -> pd.DataFrame:
    text = put_back(((SRC_DIR if program in DRIVERS else PRINTED_DIR) / program).read_text(), program, edits)
    src = workdir / program
    src.write_text(text)
    exe = workdir / "variant"
    drivers = []
    if program in DRIVERS:
        drivers.append(workdir / "driver.f")
        drivers[0].write_text(DRIVERS[program])
    _compile(src, exe, *drivers)
    done = build_cache.run([str(exe)], capture_output=True, text=True, timeout=60)
    return parse_printed_output(done.stdout).drop_duplicates("deg").set_index("deg")


def _matched(frame: pd.DataFrame, program: str, published: PublishedTable) -> tuple[int, int, float]:
    pub = published.values
    rows = pub["input_deg"] < 360          # row 360 is a copy of row 0 (D011)
    matched, total, worst = 0, 0, 0.0
    for col, quantity in zip(COLUMNS[program][1], ("dx", "dy")):
        count, err = published.matched(col, frame[quantity].reindex(pub.loc[rows, "input_deg"]), rows)
        matched, total, worst = matched + count, total + int(rows.sum()), max(worst, err)
    return matched, total, worst


def measure(table: str, entries: list[dict]) -> pd.DataFrame:
    """One row per reading of ``entries`` (an entry, or a group of its items): the deflection
    cells of ``table`` matched with the chosen text and with the scan's."""
    if shutil.which(COMPILER) is None:
        raise CompilerError(missing_message([table]))
    published = PublishedTable.load(table)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        baselines = {}
        for entry in entries:
            for group, readings in groups(entry):
                program = readings[0]["file"]
                if program not in baselines:
                    try:
                        baselines[program] = _matched(_run_variant(program, [], tmp), program, published)
                    except subprocess.CalledProcessError as exc:   # the listing as printed builds with meson
                        raise CompilerError(f"{COMPILER} could not build the printed listing {program} as printed "
                                            f"({first_error(exc.stderr)}); check the {COMPILER} installation") from exc
                try:
                    scan = _matched(_run_variant(program, readings, tmp), program, published)
                except (subprocess.CalledProcessError, subprocess.TimeoutExpired):
                    scan = (0, baselines[program][1], float("nan"))   # the scan's text does not build or run
                chosen = baselines[program]
                rows.append({"id": entry["id"] + (f" ({group})" if group else ""), "program": program,
                             "chosen_matched": f"{chosen[0]}/{chosen[1]}", "chosen_max_err": chosen[2],
                             "scan_matched": f"{scan[0]}/{scan[1]}", "scan_max_err": scan[2]})
    return pd.DataFrame(rows)


def as_markdown(frame: pd.DataFrame) -> str:
    lines = ["## Reading alternatives (measured: the printed listing rebuilt with the scan's literal text)",
             "", "Deflection cells of rows 0-340 within half a unit of the printed digit.", "",
             "| entry | program | chosen reading | max err | scan's literal text | max err |",
             "|---|---|---|---|---|---|"]
    for r in frame.itertuples():
        lines.append(f"| {r.id} | {r.program} | {r.chosen_matched} | {r.chosen_max_err:.4f} | "
                     f"{r.scan_matched} | {r.scan_max_err:.4f} |")
    return "\n".join(lines)

