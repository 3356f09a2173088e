"""The run of record across toolchains (``make toolchains``): the package built by each Fortran
compiler, every scene run with it, and the movement of each cell against ``reference/`` measured.

Per toolchain (``TOOLCHAINS``: a name and the compiler meson is given as ``FC``), under
``--out`` (default ``out/toolchains``) ``<name>/``:

- ``wheel/``: the package built from this source tree (``pip wheel --no-build-isolation``: the
  build tools of the running interpreter's environment, meson.build's flags for the compiler's
  family); ``build.log`` its messages; where it does not build, the matrix says why (the first
  error line) and the toolchain is not run;
- ``venv/``: a venv holding that wheel alone, which finds every other dependency in the running
  interpreter's site-packages (a ``.pth`` path line: that environment's own ``.pth`` files, an
  editable install's loader among them, are not read, so ``linkrepro`` is the wheel's);
- ``arithmetic/``: ``linkrepro arithmetic --out`` (the CSSP under the arithmetics of 1996 machines:
  their x87 and FMA variants are gfortran's flags, which another compiler may not take);
- ``run/``: ``linkrepro reproduce --out`` of every scene, run by that venv with
  ``LINKREPRO_FC`` set to the compiler (the listings the harness rebuilds at run time use it
  too); ``reproduce.log``, and ``verify.txt``: ``linkrepro verify`` against the reference.

Then ``matrix.csv`` and ``matrix.md`` (``measure``): one row per toolchain, scene and CSV of the
reference (a CSV is an engine's: legacy, printed, port_printed, port_corrected, port; diff.csv;
or a scene's summary), with its cells identical as written, within k units in the last place
(``verify.column_units``: ulps where written in full, else units of the last written digit) for
k in ``BINS``, beyond, not a number where the reference has one (or text changed), and the
status changes of diff.csv; the largest movement and its cell.  The arithmetic study, which
reference/ does not hold, is measured against the ``BASELINE`` toolchain's run: one row per variant.  ``--commit`` copies both to
the source tree's ``reference/toolchains/`` (verify's measured bounds), which ``docs/developing.md``'s block ``toolchains`` summarises.

Usage: ``python -m linkrepro.harness.toolchains [--only NAME ...] [--matrix-only] [--commit]``.
"""
from __future__ import annotations

import argparse
import json
import lzma
import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import numpy as np
import pandas as pd

from .compare_runs import is_timing
from .readings import FC_ENV, first_error
from .verify import (MATRIX, REFERENCE_DIR, STATUS_COLUMN, SUFFIX, column_units, engine_of, read_csv_text,
                     reference_scenes)

#: name: the compiler meson is given (FC); gfortran-12 is Debian 12's gfortran, the reference's
TOOLCHAINS = {"gfortran-11": "gfortran-11", "gfortran-12": "gfortran-12", "flang-22": "flang-22"}
#: where the committed matrix is: with the reference it measures (verify reads its bounds there)
COMMITTED = (REFERENCE_DIR / MATRIX).parent
#: the arithmetic study's rows are measured against this toolchain's own run (reference/ holds none)
BASELINE, ARITHMETIC = "gfortran-12", "arithmetic_cells.csv"
#: upper ends of the bins of units in the last place (a cell in the first bin it fits)
BINS = (1, 2, 4, 16, 1024)
COLUMNS = ("toolchain", "scene", "file", "engine", "cells", "identical",
           *[f"within_{k}" for k in BINS], "beyond", "not_a_number", "status_changed",
           "max_units", "max_row", "max_column", "max_reference", "max_run", "built", "compiler")


def compare_file(ref: pd.DataFrame, run: pd.DataFrame | None) -> dict:
    """One CSV's counts (``COLUMNS`` from ``cells`` to ``max_run``); ``run`` None: not produced."""
    compared = [column for column in ref.columns if not is_timing(column)]      # measured times are not
    cells = len(ref) * len(compared)
    row: dict = {"cells": cells, "identical": 0, **{f"within_{k}": 0 for k in BINS}, "beyond": 0,
                 "not_a_number": 0, "status_changed": 0, "max_units": 0.0, "max_row": "", "max_column": "",
                 "max_reference": "", "max_run": ""}
    if run is None or list(run.columns) != list(ref.columns) or len(run) != len(ref):
        row["not_a_number"] = cells
        return row
    for column in compared:
        a, b = ref[column].to_numpy(str), run[column].to_numpy(str)
        differ = a != b
        row["identical"] += int((~differ).sum())
        if not differ.any():
            continue
        if column == STATUS_COLUMN:
            row["status_changed"] += int(differ.sum())
            continue
        units = column_units(ref[column], run[column])
        for i in np.flatnonzero(differ):
            u = float(units[i])
            if not np.isfinite(u):
                row["not_a_number"] += 1
            else:
                row[next((f"within_{k}" for k in BINS if u <= k * (1 + 1e-6)), "beyond")] += 1
            if np.isfinite(u) and u > row["max_units"] or not np.isfinite(u) and np.isfinite(row["max_units"]):
                row.update(max_units=u, max_row=int(i) + 1, max_column=column, max_reference=a[i], max_run=b[i])
    return row


def measure(out: Path, reference: Path = REFERENCE_DIR, names: list[str] | None = None) -> pd.DataFrame:
    """The matrix (``COLUMNS``) of the toolchains' runs under ``out`` against ``reference``."""
    rows = []
    for name in names or list(TOOLCHAINS):
        built = (out / name / "built").read_text().strip() if (out / name / "built").is_file() else "not built"
        record = out / name / "run" / "manifest.json"
        compiler = json.loads(record.read_text()).get("build_gfortran", "") if record.is_file() else ""
        for scene in reference_scenes(reference):
            for stored in sorted((reference / scene).glob(f"*{SUFFIX}")):
                file = stored.name[:-len(SUFFIX)] + ".csv"
                ref = read_csv_text(lzma.decompress(stored.read_bytes()))
                path = out / name / "run" / scene / file
                run = read_csv_text(path.read_bytes()) if path.is_file() else None
                rows.append({"toolchain": name, "scene": scene, "file": file, "engine": engine_of(file),
                             **compare_file(ref, run), "built": built, "compiler": compiler})
        rows += [{**row, "toolchain": name, "built": built, "compiler": compiler} for row in _arithmetic(out, name)]
    return pd.DataFrame(rows, columns=list(COLUMNS))


def _arithmetic(out: Path, name: str) -> list[dict]:
    """The arithmetic study's values (``linkrepro arithmetic``: the CSSP under each arithmetic
    variant, ``arithmetic_cells.csv``) of toolchain ``name`` against ``BASELINE``'s, one row per
    variant (engine ``arithmetic``; a variant this toolchain did not build: every cell NaN/text)."""
    base, own = (out / n / "arithmetic" / ARITHMETIC for n in (BASELINE, name))
    if name == BASELINE or not base.is_file() or not own.is_file():
        return []
    ref, run = read_csv_text(base.read_bytes()), read_csv_text(own.read_bytes())
    rows = []
    for column in [c for c in ref.columns if c.startswith("value:")]:
        row = compare_file(ref[[column]], run[[column]] if column in run.columns else None)
        rows.append({"scene": "arithmetic", "file": f"{ARITHMETIC}[{column}]", "engine": "arithmetic", **row})
    return rows


def as_markdown(matrix: pd.DataFrame) -> str:
    """Per toolchain and engine: the cells in each class, and the largest movement and where."""
    counts = ["cells", "identical", *[f"within_{k}" for k in BINS], "beyond", "not_a_number", "status_changed"]
    head = ["toolchain", "engine", "cells", "identical", *[f"<= {k}" for k in BINS], "beyond", "NaN/text",
            "status", "largest (units), where"]
    lines = ["Every cell of the run of record (`reference/`) as each Fortran compiler's build of the package "
             "gives it, per engine's CSVs: identical as written, within k units in the last place (ulps where "
             "written in full, else units of the last written digit), beyond, not a number or text changed, and "
             "diff.csv statuses changed; the arithmetic study (not in reference/) against gfortran-12's run.", "",
             "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for (name, engine), part in matrix.groupby(["toolchain", "engine"], sort=False):
        top = part.loc[part["max_units"].astype(float).idxmax()]
        where = (f"{float(top['max_units']):.3g}: {top['scene']}/{top['file']} row {top['max_row']} "
                 f"{top['max_column']} ({top['max_reference']} -> {top['max_run']})" if float(top["max_units"]) > 0
                 else "none")
        lines.append(f"| {name} | {engine} | " + " | ".join(str(int(part[c].sum())) for c in counts)
                     + f" | {where} |")
    built = matrix.drop_duplicates("toolchain")[["toolchain", "built"]]
    lines += ["", *[f"- {r.toolchain}: {r.built}" for r in built.itertuples()]]
    unbuilt = matrix[(matrix["scene"] == "arithmetic") & (matrix["not_a_number"] == matrix["cells"])]
    lines += [f"- {name}: arithmetic variants not built (gfortran's flags): "
              + ", ".join(f.split("[value:")[1].rstrip("]") for f in part["file"]) for name, part in unbuilt.groupby("toolchain", sort=False)]
    ran = matrix[matrix["built"].str.startswith("built with") & (matrix["scene"] != "arithmetic")]
    fixed = ran.groupby(["scene", "file"]).filter(lambda part: (part["identical"] == part["cells"]).all())
    fixed = fixed.drop_duplicates(["scene", "file"])
    files = ran.drop_duplicates(["scene", "file"])
    lines.append(f"- unmoved by every toolchain that ran ({', '.join(ran['toolchain'].unique())}): "
                 f"{len(fixed)} of {len(files)} CSVs of the reference, {int(fixed['cells'].sum())} of "
                 f"{int(files['cells'].sum())} cells, the ones an archival test may hold fixed"
                 + ("" if len(fixed) == len(files) else ": all but "
                    + ", ".join(sorted(set(files["scene"] + "/" + files["file"]) - set(fixed["scene"] + "/" + fixed["file"])))))
    return "\n".join(lines) + "\n"


def summary(folder: Path = COMMITTED) -> str:
    """docs/developing.md's block: the committed matrix (``folder``'s matrix.csv) as ``as_markdown``."""
    return as_markdown(pd.read_csv(folder / "matrix.csv", dtype={"max_reference": str, "max_run": str},
                                   keep_default_na=False))


def _step(command: list[str], log: Path, env: dict | None = None) -> str:
    """Run ``command`` with its output in ``log``; "" when it succeeded, else its first error line."""
    with log.open("w") as handle:
        done = subprocess.run(command, stdout=handle, stderr=subprocess.STDOUT, env=env)
    return "" if done.returncode == 0 else first_error(log.read_text())


def build_and_run(name: str, out: Path, source: Path) -> str:
    """Build the package from the source tree ``source`` with toolchain ``name`` and run every
    scene with it (see the module's docstring); returns what ``built`` says: "built with <FC>"
    or why it did not build."""
    fc, where = TOOLCHAINS[name], out / name
    shutil.rmtree(where, ignore_errors=True)
    where.mkdir(parents=True)
    said = ""
    if shutil.which(fc) is None:
        said = f"not built: {fc} is not on PATH (apt-get install {fc})"
    elif error := _step([sys.executable, "-m", "pip", "wheel", "-q", "--no-build-isolation", "--no-deps",
                         "-w", str(where / "wheel"), str(source)], where / "build.log", {**os.environ, "FC": fc}):
        said = f"not built: {error}"
    if said:
        (where / "built").write_text(said + "\n")
        return said
    venv = where / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    python = venv / "bin" / "python"
    subprocess.run([sys.executable, "-m", "pip", "--python", str(python), "install", "-q", "--no-deps",
                    *map(str, (where / "wheel").glob("*.whl"))], check=True)
    site = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                          capture_output=True, text=True, check=True).stdout.strip()
    Path(site, "zz_dependencies.pth").write_text(sysconfig.get_path("purelib") + "\n")
    env = {**os.environ, FC_ENV: fc}
    run_error = _step([str(python), "-m", "linkrepro", "reproduce", "--out", str(where / "run")],
                      where / "reproduce.log", env)
    _step([str(python), "-m", "linkrepro", "arithmetic", "--out", str(where / "arithmetic")],
          where / "arithmetic.log", env)
    _step([str(python), "-m", "linkrepro", "verify", "--out", str(where / "run"), "--reference", str(REFERENCE_DIR)],
          where / "verify.txt", env)
    said = f"built with {fc}" + (f"; the run stopped: {run_error}" if run_error else "")
    (where / "built").write_text(said + "\n")
    return said


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m linkrepro.harness.toolchains", description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=Path, default=Path("out/toolchains"))
    parser.add_argument("--only", nargs="*", choices=list(TOOLCHAINS), help="these toolchains (default: all)")
    parser.add_argument("--matrix-only", action="store_true", help="measure the runs already under --out")
    parser.add_argument("--source", type=Path, default=Path.cwd(), help="the source tree to build (default: here)")
    parser.add_argument("--commit", action="store_true", help="copy matrix.csv and matrix.md to SOURCE/reference/toolchains/")
    args = parser.parse_args(argv)
    names = args.only or list(TOOLCHAINS)
    if not (args.source / "meson.build").is_file():
        parser.error(f"{args.source} is not linkrepro's source tree (no meson.build): run it in a checkout")
    if not args.matrix_only:
        for name in names:
            print(f"{name}: {build_and_run(name, args.out, args.source.resolve())}", flush=True)
    matrix = measure(args.out, REFERENCE_DIR, names)
    matrix.to_csv(args.out / "matrix.csv", index=False)
    (args.out / "matrix.md").write_text(as_markdown(matrix))
    print(as_markdown(matrix))
    if args.out.name == "toolchains" and (args.out.parent / "report.md").is_file():
        from .report_folder import write             # a report folder's toolchains/: its report shows the matrix
        write(args.out.parent)
        print(f"report: {args.out.parent / 'report.html'}")
    unbuilt = sorted(set(matrix.loc[~matrix["built"].str.startswith("built with"), "toolchain"]))
    if args.commit and unbuilt:                        # verify would lose those compilers' measured bounds
        print(f"not committed: {', '.join(unbuilt)} did not build (matrix.md says why)", file=sys.stderr)
        return 1
    if args.commit:
        committed = args.source / "reference" / MATRIX.parent
        committed.mkdir(parents=True, exist_ok=True)
        for file in ("matrix.csv", "matrix.md"):
            shutil.copyfile(args.out / file, committed / file)
    return 0


if __name__ == "__main__":
    sys.exit(main())
