"""``linkrepro verify``: a run's scene CSVs against the stored run of record, cell by cell.

The run of record is ``reference/`` (in the repository, installed with the package): every CSV
of every scene of a full ``linkrepro reproduce``, xz-compressed (``<scene>/<file>.csv.xz``),
with the run's ``manifest.json`` where it wrote one.  ``verify`` reads the scenes found in an
output folder (its folders that hold an ``outcome.json``, and those named as a reference scene
that hold files) and compares each of their CSVs with the reference's, cell by cell, as written
(every engine's outputs and ``diff.csv`` in full: each double's shortest repr; a printed
engine's, at its printed digits; summaries rounded):

- *identical*: the same text;
- *within*: a number that differs by at most ``units`` units in the last place: ulps of a
  double where the column is written in full (16 or more significant digits), else units of
  the last digit the reference writes in that column (its most digits over the column);
- *moved*: any other difference (a number beyond that, a text, a NaN where there was a number);
- *status changed*: a ``diff.csv`` cell whose status (match, registered, unexplained,
  not-produced) differs from the reference's.

Policy: on the same toolchain (both have a manifest, and every field of their set-ups,
``manifest.ENVIRONMENT``, is equal but the commit) every cell must be identical; where the
set-ups differ in the Fortran compiler and its build alone (``TOOLCHAIN_FIELDS``) and the
reference's measured matrix (``toolchains/matrix.csv``, ``make toolchains``) holds the run's
compiler, each engine's numbers may move as far as they moved there (per engine, the most any
cell moved: 0 where none moved, so every cell identical); across other toolchains, or where a
manifest is missing, a number may move by ``units`` (default 4, not measured) units in the last
place.  A status never changes.
Columns of measured times (a name with "seconds" or "time") are not compared.  The exit status
of the command: 0 when every cell keeps the policy, 1 when one does not or the folder cannot be
trusted, 2 for a usage error (no reference, a damaged one, a manifest of another format or
damaged, an output folder without the scenes asked for).  A folder cannot be trusted (each
said in a line) where a scene's folder is not what its run wrote (``run_folder.read_scene``:
no outcome.json, a file changed, missing, added, unreadable), a scene's folder is not in the
reference (renamed?), a CSV cannot be read (empty, not UTF-8, a folder, cut short), a scene
was skipped, or nothing was compared.  A run killed before it finished, or one still running,
in the folder is said too (the scenes it left are as before it).

``linkrepro verify --refresh`` prints the same comparison, then makes the output folder's
scenes the reference (written whole into a new folder and renamed into place).
"""
from __future__ import annotations

import io
import lzma
import math
import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from . import run_folder
from .compare_runs import is_timing
from .manifest import ENVIRONMENT, FILE as MANIFEST, ManifestError, command_line, load as load_record
from .scene import Outcome
from .trail import printed_digits

REFERENCE_DIR = Path(__file__).resolve().parent.parent / "reference"
SUFFIX = ".csv.xz"
#: the set-up's fields that name the commit: a new commit on the same toolchain changes them
COMMIT = ("commit", "dirty", "commit_from")
STATUS_FILE, STATUS_COLUMN = "diff.csv", "status"
ENGINES = ("legacy", "printed", "port_printed", "port_corrected", "port")
EXAMPLES = 5
#: a column whose numbers carry this many significant digits is written in full (each float's
#: shortest repr): a difference in it is counted in units in the last place of a double (ulps)
FULL_DIGITS = 16
#: the default of ``units`` across toolchains the matrix has not measured
UNITS = 4.0
#: the measured matrix of the run across toolchains (``make toolchains``, harness/toolchains.py),
#: kept with the reference it was measured against
MATRIX = Path("toolchains") / "matrix.csv"
#: the set-up's fields a change of Fortran compiler changes (and the build tools it was built with):
#: where the manifests differ in these alone and the run's compiler is one the matrix measured, the
#: bound is the matrix's
TOOLCHAIN_FIELDS = ("build_gfortran", "flags_f2py_extension", "flags_printed_programs", "flags_readings",
                    "gfortran", "meson_python", "build_meson", "build_meson_python")


class VerifyError(ValueError):
    """A verify that cannot be done: no or a damaged reference, no scenes to compare."""


@dataclass
class FileResult:
    """One CSV compared: cells per class, and a few of those that moved (row, column, reference,
    run, units of the last digit)."""
    path: str
    identical: int = 0
    within: int = 0
    moved: int = 0
    status_changed: int = 0
    examples: list[tuple] = field(default_factory=list)
    problem: str = ""


@dataclass
class Verdict:
    out_dir: Path
    reference_dir: Path
    units: float
    same_toolchain: bool
    manifest_differences: dict[str, tuple]
    files: list[FileResult]
    notes: list[str] = field(default_factory=list)       # runs killed or running in the folder
    measured: dict[str, float] | None = None             # engine: its bound, where the matrix measured the run's compiler

    @property
    def failed(self) -> list[FileResult]:
        return [f for f in self.files if f.problem or f.status_changed or f.moved]


def scenes_in(folder: Path, known: tuple[str, ...] = ()) -> list[str]:
    """The scenes run into an output folder, sorted: its folders (none hidden) that hold
    ``outcome.json``, and those named as a ``known`` scene that hold files."""
    folder = Path(folder)
    found = {p.parent.name for p in folder.glob(f"*/{Outcome.FILE}")}
    found |= {name for name in known if (folder / name).is_dir() and any(folder.joinpath(name).iterdir())}
    return sorted(name for name in found if not name.startswith("."))


def reference_scenes(reference_dir: Path) -> list[str]:
    return sorted(p.name for p in Path(reference_dir).iterdir() if p.is_dir() and any(p.glob(f"*{SUFFIX}")))


def read_csv_text(data: bytes) -> pd.DataFrame:
    """A CSV as text cells (missing = "")."""
    return pd.read_csv(io.BytesIO(data), dtype=str, keep_default_na=False)


def _numbers(column: pd.Series) -> np.ndarray | None:
    """The column as floats ("" as NaN), or None if a cell is not a number."""
    try:
        return np.array([float(v) if v != "" else math.nan for v in column], dtype=float)
    except ValueError:
        return None


def column_units(ref: pd.Series, run: pd.Series) -> np.ndarray:
    """Per cell of a column (text cells), how far the run's number is from the reference's, in
    units in the last place (ulps of a double where the reference writes the column in full, else
    units of its last written digit); inf where either is not a finite number.  (Identical text
    may still show 0 or a NaN: compare the text first.)"""
    a = ref.to_numpy(str)
    x, y = _numbers(ref), _numbers(run)
    if x is None or y is None:
        return np.full(len(a), np.inf)
    digits = max(printed_digits(t) for t in a if t != "") if (a != "").any() else 1
    scale = np.fmax(np.abs(x), np.abs(y))
    with np.errstate(divide="ignore", invalid="ignore"):
        unit = (np.spacing(scale) if digits >= FULL_DIGITS        # written in full: ulps
                else 10.0 ** (np.floor(np.log10(scale)) - digits + 1))
        return np.where(np.isfinite(x) & np.isfinite(y), np.abs(x - y) / unit, np.inf)


def engine_of(path: str) -> str:
    """The engine a scene's CSV is written by (``legacy.csv``: legacy), ``diff`` or ``summary``."""
    stem = Path(path).stem
    return stem if stem in ENGINES else ("diff" if stem == Path(STATUS_FILE).stem else "summary")


def measured_bounds(reference_dir: Path, compiler: str | None) -> dict[str, float] | None:
    """Per engine, the most units in the last place any cell moved under ``compiler`` (a build's
    ``build_gfortran``) in the reference's matrix (``MATRIX``); None where the matrix did not
    measure that compiler (or there is no matrix).  An engine a cell of which turned not a number
    or other text there (no finite bound) is held to the unmeasured ``UNITS``, never to no bound."""
    path = Path(reference_dir) / MATRIX
    if compiler is None or not path.is_file():
        return None
    matrix = pd.read_csv(path, dtype={"compiler": str}, keep_default_na=False)
    rows = matrix[matrix["compiler"] == compiler]
    if rows.empty:
        return None
    moved = {engine: float(part["max_units"].astype(float).max()) for engine, part in rows.groupby("engine")}
    return {engine: units if math.isfinite(units) else UNITS for engine, units in moved.items()}


def compare_frames(name: str, ref: pd.DataFrame, run: pd.DataFrame, allowed: float) -> FileResult:
    """Cell by cell (see the module's docstring); ``allowed``: units of the last digit a number may move."""
    result = FileResult(name)
    if list(ref.columns) != list(run.columns) or len(ref) != len(run):
        result.problem = f"shape or columns differ: reference {ref.shape}, run {run.shape}"
        return result
    for column in ref.columns:
        if is_timing(column):
            continue
        a, b = ref[column].to_numpy(str), run[column].to_numpy(str)
        same = a == b
        result.identical += int(same.sum())
        if same.all():
            continue
        if Path(name).name == STATUS_FILE and column == STATUS_COLUMN:
            result.status_changed += int((~same).sum())
            result.examples += [(int(i), column, str(a[i]), str(b[i]), math.nan) for i in np.flatnonzero(~same)[:EXAMPLES]]
            continue
        units = column_units(ref[column], run[column])
        for i in np.flatnonzero(~same):
            if units[i] <= allowed * (1 + 1e-6):      # (a difference of decimals, computed in binary)
                result.within += 1
            else:
                result.moved += 1
                if len(result.examples) < EXAMPLES:
                    result.examples.append((int(i), column, str(a[i]), str(b[i]), float(units[i])))
    return result


def load_manifest(folder: Path, what: str) -> dict | None:
    """A folder's manifest.json (None if there is none); ``VerifyError`` if it cannot be read, is
    damaged or is of a format this version does not read (``manifest.load``)."""
    try:
        return load_record(folder)
    except ManifestError as exc:
        raise VerifyError(f"the {what}'s {exc}") from exc


def manifest_differences(ref: dict | None, run: dict | None) -> dict[str, tuple]:
    """The fields of the two manifests' set-ups that differ ({field: (reference, run)}: the
    ``manifest.ENVIRONMENT`` fields but the commit, which every new commit changes)."""
    if ref is None or run is None:        # the toolchains cannot be compared
        return {"manifest": ("present" if ref else "absent", "present" if run else "absent")}
    return {k: (ref.get(k), run.get(k)) for k in ENVIRONMENT if k not in COMMIT and ref.get(k) != run.get(k)}


def _read_run_csv(path: Path) -> pd.DataFrame | str:
    """A run's CSV as text cells, or why it cannot be read."""
    try:
        return read_csv_text(path.read_bytes())
    except (OSError, ValueError) as exc:         # a folder, empty, not UTF-8, cut inside a quote
        return f"cannot be read ({type(exc).__name__}: {(str(exc).splitlines() or [''])[0]})"


def _a_folder(out_dir: Path) -> None:
    """``VerifyError`` where ``out_dir`` does not exist or is not a folder (said as such, not as a
    folder that holds no run)."""
    if not out_dir.exists():
        raise VerifyError(f"{out_dir} does not exist: `{command_line(['reproduce', '--out', str(out_dir)])}` "
                          "makes a run there")
    if not out_dir.is_dir():
        raise VerifyError(f"{out_dir} is a file, not a run's folder")


def verify(out_dir: Path, reference_dir: Path = REFERENCE_DIR, units: float | None = None,
           scenes: list[str] | None = None) -> Verdict:
    """Compare the scenes of ``out_dir`` (``scenes``: those only) with ``reference_dir``.  Across
    toolchains: ``units`` where given; else, where the manifests differ in ``TOOLCHAIN_FIELDS``
    alone and the matrix measured the run's compiler, each engine's measured bound; else ``UNITS``."""
    out_dir, reference_dir = Path(out_dir), Path(reference_dir)
    if not reference_dir.is_dir() or not reference_scenes(reference_dir):
        raise VerifyError(f"no reference at {reference_dir} (a folder of <scene>/<file>{SUFFIX}); "
                          "`linkrepro verify --refresh --reference DIR` makes one from a run")
    _a_folder(out_dir)
    known = reference_scenes(reference_dir)
    found = scenes_in(out_dir, tuple(known))
    if scenes:
        missing = [s for s in scenes if s not in found]
        if missing:
            raise VerifyError(f"{out_dir} holds no run of {', '.join(missing)}: "
                              f"`{command_line(['reproduce', *missing, '--out', str(out_dir)])}` runs them")
        found = list(scenes)
    if not found:
        raise VerifyError(f"{out_dir} holds no scene run (no <scene>/outcome.json): "
                          f"`{command_line(['reproduce', '--out', str(out_dir)])}`")
    manifests = load_manifest(reference_dir, "reference"), load_manifest(out_dir, "run")
    differences = manifest_differences(*manifests)
    same = not differences and None not in manifests
    measured = (measured_bounds(reference_dir, manifests[1].get("build_gfortran"))
                if units is None and not same and None not in manifests and set(differences) <= set(TOOLCHAIN_FIELDS)
                else None)
    units = UNITS if units is None else units
    files = []
    for scene in found:
        if scene not in known:
            files.append(FileResult(scene, problem="not in the reference: a scene folder verify does not know "
                                                   "(renamed? a scene the reference lacks?)"))
            continue
        outcome, why = run_folder.read_scene(out_dir, scene)
        if outcome is None:
            files.append(FileResult(scene, problem=why))
            continue
        if outcome.skipped:
            files.append(FileResult(scene, problem=f"skipped in the run: {outcome.skipped}"))
            continue
        for stored in sorted((reference_dir / scene).glob(f"*{SUFFIX}")):
            name = f"{scene}/{stored.name[:-len(SUFFIX)]}.csv"
            try:
                ref = read_csv_text(lzma.decompress(stored.read_bytes()))
            except (OSError, lzma.LZMAError, ValueError) as exc:
                raise VerifyError(f"the reference's {stored} is damaged: {exc}") from exc
            path = out_dir / name
            if not path.exists():
                files.append(FileResult(name, problem="missing in the run"))
                continue
            run = _read_run_csv(path)
            files.append(FileResult(name, problem=run) if isinstance(run, str) else
                         compare_frames(name, ref, run, 0.0 if same else
                                        units if measured is None else measured.get(engine_of(name), 0.0)))
        for path in sorted((out_dir / scene).glob("*.csv")):
            if not (reference_dir / scene / (path.stem + SUFFIX)).exists():
                files.append(FileResult(f"{scene}/{path.name}", problem="not in the reference"))
    if not any(not f.problem for f in files):
        files.append(FileResult(str(out_dir), problem="nothing was compared: no CSV of a scene the reference holds"))
    killed, running = run_folder.unfinished(out_dir)
    notes = ([f"a run into this folder was killed before it finished {', '.join(killed)}: as compared, they are "
              "as the runs before it left them (its partial files are hidden in the folder; the next run removes them)"]
             if killed else [])
    notes += [f"a run is writing {', '.join(running)} into this folder now: verify again when it ends"] if running else []
    return Verdict(out_dir, reference_dir, units, same, differences, files, notes, measured)


def describe(verdict: Verdict) -> str:
    """The comparison in words: the policy, what differs in the manifests, what moved."""
    total = {k: sum(getattr(f, k) for f in verdict.files) for k in ("identical", "within", "moved", "status_changed")}
    lines = [f"linkrepro verify: {verdict.out_dir} against the reference {verdict.reference_dir}",
             "policy: " + ("the same toolchain (the manifests agree): every cell identical as written"
                           if verdict.same_toolchain else
                           "another Fortran compiler, measured (the reference's toolchains/matrix.csv, `make "
                           "toolchains`): each engine's cells may move as far as they moved there, "
                           + ", ".join(f"{e} {u:g}" for e, u in sorted(verdict.measured.items()))
                           + " unit(s) in the last place" if verdict.measured is not None else
                           f"toolchains that differ or cannot be compared: a number may move by {verdict.units:g} "
                           "unit(s) in the last place (ulps where written in full, else of the last written digit)")
             + "; a diff.csv status never changes; measured times are not compared",
             "  per engine: legacy, port_printed, port_corrected and diff.csv are written in full (ulps); "
             "printed at the digits its program prints; summaries at the digits they are written with"]
    for key, (ref, run) in verdict.manifest_differences.items():
        lines.append(f"  {key}: reference {ref}, run {run}" if key == "manifest" else
                     f"  manifest field {key}: reference {ref!r}, run {run!r}")
    for f in verdict.failed:
        if f.problem:
            lines.append(f"{f.path}: {f.problem}")
            continue
        lines.append(f"{f.path}: {f.moved} moved, {f.status_changed} status changed")
        for row, column, ref, run, units in f.examples:
            size = "" if math.isnan(units) else (f" ({units:.3g} units)" if math.isfinite(units) else " (not a number)")
            lines.append(f"  row {row + 1}, {column}: reference {ref!r}, run {run!r}{size}")
    lines += [f"note: {note}" for note in verdict.notes]
    compared = sum(not f.problem for f in verdict.files)
    lines.append(f"{compared} CSVs compared, {sum(total.values())} cells: {total['identical']} identical, "
                 f"{total['within']} within the policy, {total['moved']} moved, {total['status_changed']} status "
                 f"changed: {'FAILED' if verdict.failed else 'ok'}")
    return "\n".join(lines)


def refresh(out_dir: Path, reference_dir: Path = REFERENCE_DIR) -> int:
    """Make the scenes of ``out_dir`` the reference: every CSV xz-compressed, the manifest copied;
    written whole into a new folder beside ``reference_dir`` and renamed into place.  Returns
    the bytes the reference takes.  ``VerifyError`` where a scene's folder is not what its run
    wrote (``run_folder.read_scene``), or where ``out_dir`` lacks a scene the reference holds
    (nothing is dropped: the reference stays as it was)."""
    out_dir, reference_dir = Path(out_dir), Path(reference_dir)
    _a_folder(out_dir)
    scenes = scenes_in(out_dir)
    if not scenes:
        raise VerifyError(f"{out_dir} holds no scene run to make the reference of")
    damaged = [f"{scene}: {why}" for scene in scenes if (why := run_folder.read_scene(out_dir, scene)[1])]
    if damaged:
        raise VerifyError(f"{out_dir} cannot be made the reference: {'; '.join(damaged)}")
    dropped = sorted(set(reference_scenes(reference_dir)) - set(scenes)) if reference_dir.is_dir() else []
    if dropped:
        raise VerifyError(f"{out_dir} cannot be made the reference: it holds no run of {', '.join(dropped)}, which "
                          f"{reference_dir} does (a refresh replaces the whole reference: run every scene into --out)")
    reference_dir.parent.mkdir(parents=True, exist_ok=True)
    fresh = Path(tempfile.mkdtemp(prefix=".reference-", dir=reference_dir.parent))
    try:
        for scene in scenes:
            (fresh / scene).mkdir()
            for path in sorted((out_dir / scene).glob("*.csv")):
                (fresh / scene / (path.stem + SUFFIX)).write_bytes(lzma.compress(path.read_bytes(), preset=9))
        if (out_dir / MANIFEST).exists():
            shutil.copyfile(out_dir / MANIFEST, fresh / MANIFEST)
        if (reference_dir / MATRIX).is_file():     # measured against the reference: `make toolchains` again
            shutil.copytree(reference_dir / MATRIX.parent, fresh / MATRIX.parent)
        old = reference_dir.with_name(reference_dir.name + ".old")
        if reference_dir.exists():
            os.replace(reference_dir, old)
        os.replace(fresh, reference_dir)
        shutil.rmtree(old, ignore_errors=True)
    except BaseException:
        shutil.rmtree(fresh, ignore_errors=True)
        raise
    return sum(p.stat().st_size for p in reference_dir.rglob("*") if p.is_file())
