"""``linkrepro verify``: a run's scene CSVs against the stored run of record, cell by cell.

The run of record is ``reference/`` (in the repository, installed with the package): every CSV
of every scene of a full ``linkrepro reproduce``, xz-compressed (``<scene>/<file>.csv.xz``),
with the run's ``manifest.json`` where it wrote one.  ``verify`` reads the scenes found in an
output folder (those with an ``outcome.json``) and compares each of their CSVs with the
reference's, cell by cell, as written (every engine's outputs and ``diff.csv`` in full: each
double's shortest repr; a printed engine's, at its printed digits; summaries rounded):

- *identical*: the same text;
- *within*: a number that differs by at most ``units`` units in the last place: ulps of a
  double where the column is written in full (16 or more significant digits), else units of
  the last digit the reference writes in that column (its most digits over the column);
- *moved*: any other difference (a number beyond that, a text, a NaN where there was a number);
- *status changed*: a ``diff.csv`` cell whose status (match, registered, unexplained,
  not-produced) differs from the reference's.

Policy: on the same toolchain (both have a manifest, and every field of their set-ups,
``manifest.ENVIRONMENT``, is equal but the commit) every cell must be identical; across
toolchains, or where a manifest is missing, a number may move by ``units`` (default 4) units in
the last place.  A status never changes.
Columns of measured times (a name with "seconds" or "time") are not compared.  The exit status
of the command: 0 when every cell keeps the policy, 1 when one does not, 2 for a usage error
(no reference, a damaged one, a manifest of another format, an output folder without the
scenes asked for).

``linkrepro verify --refresh`` prints the same comparison, then makes the output folder's
scenes the reference (written whole into a new folder and renamed into place).
"""
from __future__ import annotations

import io
import json
import lzma
import math
import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from .compare_runs import is_timing
from .manifest import ENVIRONMENT, FILE as MANIFEST, FORMAT
from .scene import Outcome
from .trail import printed_digits

REFERENCE_DIR = Path(__file__).resolve().parent.parent / "reference"
SUFFIX = ".csv.xz"
#: the set-up's fields that name the commit: a new commit on the same toolchain changes them
COMMIT = ("commit", "dirty", "commit_from")
#: the manifest formats this module reads
FORMATS = (FORMAT,)
STATUS_FILE, STATUS_COLUMN = "diff.csv", "status"
EXAMPLES = 5
#: a column whose numbers carry this many significant digits is written in full (each float's
#: shortest repr): a difference in it is counted in units in the last place of a double (ulps)
FULL_DIGITS = 16
#: the default of ``units`` across toolchains
UNITS = 4.0


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
    unchecked: list[str]

    @property
    def failed(self) -> list[FileResult]:
        return [f for f in self.files if f.problem or f.status_changed or f.moved]


def scenes_in(folder: Path) -> list[str]:
    """The scenes run into an output folder (their folders hold ``outcome.json``), sorted."""
    return sorted(p.parent.name for p in Path(folder).glob("*/outcome.json"))


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
        x, y = _numbers(ref[column]), _numbers(run[column])
        units = np.full(len(a), np.inf)
        if x is not None and y is not None:
            digits = max(printed_digits(t) for t in a if t != "") if (a != "").any() else 1
            scale = np.fmax(np.abs(x), np.abs(y))
            with np.errstate(divide="ignore", invalid="ignore"):
                unit = (np.spacing(scale) if digits >= FULL_DIGITS        # written in full: ulps
                        else 10.0 ** (np.floor(np.log10(scale)) - digits + 1))
                units = np.where(np.isfinite(x) & np.isfinite(y), np.abs(x - y) / unit, np.inf)
        for i in np.flatnonzero(~same):
            if units[i] <= allowed * (1 + 1e-6):      # (a difference of decimals, computed in binary)
                result.within += 1
            else:
                result.moved += 1
                if len(result.examples) < EXAMPLES:
                    result.examples.append((int(i), column, str(a[i]), str(b[i]), float(units[i])))
    return result


def load_manifest(folder: Path, what: str) -> dict | None:
    """A folder's manifest.json (None if there is none); ``VerifyError`` if it is damaged or of
    a format this version does not read."""
    path = Path(folder) / MANIFEST
    if not path.exists():
        return None
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError) as exc:
        raise VerifyError(f"the {what}'s {path} cannot be read: {exc}") from exc
    if not isinstance(data, dict) or data.get("format") not in FORMATS:
        raise VerifyError(f"the {what}'s {path} is of manifest format {data.get('format') if isinstance(data, dict) else '?'!r}; "
                          f"this linkrepro reads format {', '.join(map(str, FORMATS))}")
    return data


def manifest_differences(ref: dict | None, run: dict | None) -> dict[str, tuple]:
    """The fields of the two manifests' set-ups that differ ({field: (reference, run)}: the
    ``manifest.ENVIRONMENT`` fields but the commit, which every new commit changes)."""
    if ref is None or run is None:        # the toolchains cannot be compared
        return {"manifest": ("present" if ref else "absent", "present" if run else "absent")}
    return {k: (ref.get(k), run.get(k)) for k in ENVIRONMENT if k not in COMMIT and ref.get(k) != run.get(k)}


def _skipped(out_dir: Path, scene: str) -> str:
    """Why the run skipped ``scene`` ("" where it ran)."""
    try:
        return Outcome.load(out_dir, scene).skipped
    except (FileNotFoundError, ValueError):
        return ""


def verify(out_dir: Path, reference_dir: Path = REFERENCE_DIR, units: float = UNITS,
           scenes: list[str] | None = None) -> Verdict:
    """Compare the scenes of ``out_dir`` (``scenes``: those only) with ``reference_dir``."""
    out_dir, reference_dir = Path(out_dir), Path(reference_dir)
    if not reference_dir.is_dir() or not reference_scenes(reference_dir):
        raise VerifyError(f"no reference at {reference_dir} (a folder of <scene>/<file>{SUFFIX}); "
                          "`linkrepro verify --refresh --reference DIR` makes one from a run")
    found = scenes_in(out_dir)
    if scenes:
        missing = [s for s in scenes if s not in found]
        if missing:
            raise VerifyError(f"{out_dir} holds no run of {', '.join(missing)}: "
                              f"`linkrepro reproduce {' '.join(missing)} --out {out_dir}` runs them")
        found = list(scenes)
    if not found:
        raise VerifyError(f"{out_dir} holds no scene run (no <scene>/outcome.json): `linkrepro reproduce --out {out_dir}`")
    manifests = load_manifest(reference_dir, "reference"), load_manifest(out_dir, "run")
    differences = manifest_differences(*manifests)
    same = not differences and None not in manifests
    files, unchecked = [], []
    known = set(reference_scenes(reference_dir))
    for scene in found:
        if scene not in known:
            unchecked.append(scene)
            continue
        skipped = _skipped(out_dir, scene)
        if skipped:
            files.append(FileResult(scene, problem=f"skipped in the run: {skipped}"))
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
            files.append(compare_frames(name, ref, read_csv_text(path.read_bytes()), 0.0 if same else units))
        for path in sorted((out_dir / scene).glob("*.csv")):
            if not (reference_dir / scene / (path.stem + SUFFIX)).exists():
                files.append(FileResult(f"{scene}/{path.name}", problem="not in the reference"))
    return Verdict(out_dir, reference_dir, units, same, differences, files, unchecked)


def describe(verdict: Verdict) -> str:
    """The comparison in words: the policy, what differs in the manifests, what moved."""
    total = {k: sum(getattr(f, k) for f in verdict.files) for k in ("identical", "within", "moved", "status_changed")}
    lines = [f"linkrepro verify: {verdict.out_dir} against the reference {verdict.reference_dir}",
             "policy: " + ("the same toolchain (the manifests agree): every cell identical as written"
                           if verdict.same_toolchain else
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
    if verdict.unchecked:
        lines.append(f"not in the reference (not compared): {', '.join(verdict.unchecked)}")
    lines.append(f"{len(verdict.files)} CSVs, {sum(total.values())} cells: {total['identical']} identical, "
                 f"{total['within']} within the policy, {total['moved']} moved, {total['status_changed']} status "
                 f"changed: {'FAILED' if verdict.failed else 'ok'}")
    return "\n".join(lines)


def refresh(out_dir: Path, reference_dir: Path = REFERENCE_DIR) -> int:
    """Make the scenes of ``out_dir`` the reference: every CSV xz-compressed, the manifest copied;
    written whole into a new folder beside ``reference_dir`` and renamed into place.  Returns
    the bytes the reference takes."""
    out_dir, reference_dir = Path(out_dir), Path(reference_dir)
    scenes = scenes_in(out_dir)
    if not scenes:
        raise VerifyError(f"{out_dir} holds no scene run to make the reference of")
    reference_dir.parent.mkdir(parents=True, exist_ok=True)
    fresh = Path(tempfile.mkdtemp(prefix=".reference-", dir=reference_dir.parent))
    try:
        for scene in scenes:
            (fresh / scene).mkdir()
            for path in sorted((out_dir / scene).glob("*.csv")):
                (fresh / scene / (path.stem + SUFFIX)).write_bytes(lzma.compress(path.read_bytes(), preset=9))
        if (out_dir / MANIFEST).exists():
            shutil.copyfile(out_dir / MANIFEST, fresh / MANIFEST)
        old = reference_dir.with_name(reference_dir.name + ".old")
        if reference_dir.exists():
            os.replace(reference_dir, old)
        os.replace(fresh, reference_dir)
        shutil.rmtree(old, ignore_errors=True)
    except BaseException:
        shutil.rmtree(fresh, ignore_errors=True)
        raise
    return sum(p.stat().st_size for p in reference_dir.rglob("*") if p.is_file())
