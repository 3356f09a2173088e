"""The run record: ``manifest.json`` in an output folder says how what it holds was made.

``linkrepro reproduce``, ``linkrepro bench`` and each thesis's own command (``linkrepro
arithmetic``) write it into their ``--out`` folder (``write``) before the folder's report, which
shows it under "How this run was made" (``summary``).  A command that writes a report folder's
subfolder (``out/bench``) enters its record into that folder's manifest too (``include``).
A run into a folder that has one keeps what it says of the other sections (the scenes not run
this time, a command's output): the manifest is read, merged and written whole or not at all
(a temporary file renamed), under the folder's lock (``run_folder.locked``), so that two runs
into one folder that finish together keep each other's sections.  A manifest that cannot be
read, lacks a field or holds one of another type is a ``ManifestError`` (``load``).

Format 1: a JSON object, flat but for the last three keys (``ENVIRONMENT``: the keys that say
with what a run ran, from ``version`` to ``inputs_sha256``):

- ``format``: 1
- ``version``: linkrepro's version (``linkrepro.__version__``)
- ``commit``: the git commit of the checkout linkrepro ran from (``git rev-parse HEAD``, read when
  the run writes its manifest); installed from a wheel, the commit it was built from (recorded
  when the build was configured, from the checkout or from what ``meson dist`` wrote into the
  sdist); else "unknown"
- ``dirty``: whether tracked files differed from ``commit`` (``git status``, untracked files
  not counted); null when unknown
- ``commit_from``: "git checkout", "build" (the build's record) or "unknown"
- ``python``: its version and implementation, e.g. "3.11.7 (CPython)"
- ``numpy``, ``scipy``, ``numba``, ``pandas``, ``matplotlib``, ``exudyn``: their versions
  (importlib.metadata; "not installed" for Exudyn where the optional extra is not)
- ``meson_python``: meson-python's version where it is installed at run time, else "not installed"
- ``build_meson``, ``build_meson_python``, ``build_numpy``: the versions the build used (numpy's
  f2py wrote the extensions' C)
- ``build_gfortran``: the first line of ``--version`` of the Fortran compiler the build used
- ``build_type``, ``build_optimization``, ``build_fortran_args``: meson's build type, its
  optimization level and the user's own Fortran flags (FFLAGS), which meson puts before the flags
  below on every compile line (their ``-O1`` comes last and wins)
- ``flags_f2py_extension``: the flags the f2py extensions (linkrepro.legacy._ali1977,
  _rahman1996) were compiled with, as the build recorded them (meson.build's fortran_legacy_args)
- ``flags_printed_programs``: the flags the printed programs (the ``printed`` engine) were
  compiled with, as the build recorded them
- ``flags_readings``: the flags of a run's rebuilds of a printed listing with the scan's reading
  put back (``readings.FLAGS``, with the ``gfortran`` below)
- ``gfortran``: the first line of ``--version`` of the run-time Fortran compiler (``readings.COMPILER``:
  ``$LINKREPRO_FC``, else ``gfortran`` on PATH; it does the run's own builds: the readings,
  ``linkrepro arithmetic``), or "not found"
- ``platform``, ``machine``: ``platform.platform()``, ``platform.machine()``
- ``cpu_model``: /proc/cpuinfo's first "model name" (else ``platform.processor()``)
- ``cpu_count``: ``os.cpu_count()``
- ``inputs_sha256``: the SHA-256 of the lines ``<sha256>  <path>`` of ``inputs``, sorted by path
- ``started``: when the run started, UTC, ISO 8601
- ``command``: its command line, e.g. "linkrepro reproduce --out out"
- ``scenes``: the sections it wrote: the scenes (reproduce) or the command's name
- ``inputs``: {path: SHA-256} of every input: ``INPUTS`` (legacy/printed/*, legacy/src/*,
  legacy/fixed_form.py, harness/published/*, harness/deviations.toml), paths relative to the package's root (an
  installed package holds the listings and tables it installs)
- ``outputs``: {path: SHA-256} of every CSV in the folder, at any depth, when it was written
- ``sections``: {name: {"folder", "started", "command", "differs"}}: every section of the folder
  (a scene's subfolder, a command's folder: ``folder``, relative, "." for the folder itself), when
  and by what command it was last written, and the fields of ``ENVIRONMENT`` whose value in that
  run differs from the top level's (``{}``: the same set-up).  A section whose folder is gone is
  dropped.

``differences(a, b)`` lists the fields of two manifests' set-ups that differ.
"""
from __future__ import annotations

import hashlib
import importlib.metadata
import json
import os
import platform
import shlex
import shutil
import subprocess
from datetime import datetime, timezone
from functools import lru_cache
from pathlib import Path
from typing import Iterable

from .markdown_text import code_span
from .readings import COMPILER, FLAGS as READINGS_FLAGS
from .run_folder import locked, replace_text, sha256

FORMAT = 1
FILE = "manifest.json"
#: the heading of the report's section on it (``summary``)
TITLE = "How this run was made"
#: the package's root: the source tree (a checkout) or the installed package's folder
ROOT = Path(__file__).resolve().parent.parent
#: the inputs hashed: folders (every file in them) and files, relative to ROOT
INPUTS = ("legacy/printed", "legacy/src", "legacy/fixed_form.py", "harness/published", "harness/deviations.toml")
#: the libraries whose versions are recorded, by their distribution's name
LIBRARIES = ("numpy", "scipy", "numba", "pandas", "matplotlib", "exudyn")
NOT_INSTALLED = "not installed"
#: the fields that say with what a run ran (a section's ``differs`` holds those of its run's)
ENVIRONMENT = ("version", "commit", "dirty", "commit_from", "python", *LIBRARIES, "meson_python",
               "build_meson", "build_meson_python", "build_numpy", "build_gfortran", "build_type",
               "build_optimization", "build_fortran_args", "flags_f2py_extension", "flags_printed_programs",
               "flags_readings", "gfortran", "platform", "machine", "cpu_model", "cpu_count", "inputs_sha256")
#: the manifest's keys, in their order
KEYS = ("format", *ENVIRONMENT, "started", "command", "scenes", "inputs", "outputs", "sections")


class ManifestError(ValueError):
    """A manifest.json that cannot be read, or of another format."""


def now() -> str:
    """The time now, UTC, ISO 8601 to the second (a run's ``started``)."""
    return datetime.now(timezone.utc).isoformat(timespec="seconds")


def _files(folder: Path, pattern: str) -> list[Path]:
    """The files under ``folder`` matching ``pattern``, none hidden or in a hidden or cache
    folder (a temporary file, __pycache__), sorted."""
    return sorted(p for p in folder.rglob(pattern) if p.is_file()
                  and not any(part.startswith(".") or part == "__pycache__" for part in p.relative_to(folder).parts))


def input_hashes(root: Path = ROOT) -> dict[str, str]:
    """{path relative to ``root``: SHA-256} of every input (``INPUTS``) found there."""
    found = {}
    for name in INPUTS:
        path = root / name
        paths = _files(path, "*") if path.is_dir() else [path] if path.is_file() else []
        found.update({p.relative_to(root).as_posix(): sha256(p) for p in paths})
    return dict(sorted(found.items()))


def output_hashes(out_dir: Path) -> dict[str, str]:
    """{path relative to ``out_dir``: SHA-256} of every CSV in it, at any depth."""
    return {p.relative_to(out_dir).as_posix(): sha256(p) for p in _files(Path(out_dir), "*.csv")}


def digest(hashes: dict[str, str]) -> str:
    """The SHA-256 of ``hashes`` as sha256sum prints them (``<sha256>  <path>``), sorted by path."""
    return hashlib.sha256("".join(f"{h}  {p}\n" for p, h in sorted(hashes.items())).encode()).hexdigest()


def _library(name: str) -> str:
    try:
        return importlib.metadata.version(name)
    except importlib.metadata.PackageNotFoundError:
        return NOT_INSTALLED


def _git(*args: str) -> str | None:
    try:
        done = subprocess.run(["git", "--no-optional-locks", "-C", str(ROOT), *args], capture_output=True,
                              text=True, timeout=60)
    except (OSError, subprocess.SubprocessError):
        return None
    return done.stdout.strip() if done.returncode == 0 else None


def _build_record():
    """The build's record (``linkrepro._build_record``, generated by meson), or None."""
    try:
        from .. import _build_record
    except ImportError:
        return None
    return _build_record


def commit() -> tuple[str, bool | None, str]:
    """(commit, dirty, where it was read): the git checkout linkrepro runs from, else the build's record."""
    top = _git("rev-parse", "--show-toplevel") if (ROOT / ".git").exists() else None
    if top is not None and Path(top).resolve() == ROOT:
        head, status = _git("rev-parse", "HEAD"), _git("status", "--porcelain", "--untracked-files=no")
        if head:
            return head, None if status is None else status != "", "git checkout"
    record = _build_record()
    if record is not None and record.COMMIT != "unknown":
        return record.COMMIT, record.DIRTY, "build"
    return "unknown", None, "unknown"


@lru_cache(maxsize=4)
def _compiler_version(compiler: str) -> str:
    path = shutil.which(compiler)
    if path is None:
        return "not found"
    try:
        done = subprocess.run([path, "--version"], capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.SubprocessError):
        return "does not answer"
    lines = done.stdout.strip().splitlines()
    return lines[0] if done.returncode == 0 and lines else "does not answer"


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            name, _, value = line.partition(":")
            if name.strip() == "model name" and value.strip():
                return value.strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def environment(inputs: dict[str, str]) -> dict:
    """With what a run runs (``ENVIRONMENT``'s fields), ``inputs`` the hashes of its inputs."""
    from .. import __version__
    record = _build_record()
    build = (lambda name, default="unknown": getattr(record, name, default))
    head, dirty, where = commit()
    fields = {"version": __version__, "commit": head, "dirty": dirty, "commit_from": where,
              "python": f"{platform.python_version()} ({platform.python_implementation()})",
              **{name: _library(name) for name in LIBRARIES}, "meson_python": _library("meson-python"),
              "build_meson": build("MESON"), "build_meson_python": build("MESON_PYTHON"), "build_numpy": build("NUMPY"),
              "build_gfortran": build("GFORTRAN"), "build_type": build("BUILD_TYPE"),
              "build_optimization": build("OPTIMIZATION"), "build_fortran_args": list(build("FORTRAN_ARGS", [])),
              "flags_f2py_extension": list(build("FLAGS_F2PY_EXTENSION", [])),
              "flags_printed_programs": list(build("FLAGS_PRINTED_PROGRAMS", [])),
              "flags_readings": list(READINGS_FLAGS), "gfortran": _compiler_version(COMPILER),
              "platform": platform.platform(), "machine": platform.machine(), "cpu_model": cpu_model(),
              "cpu_count": os.cpu_count(), "inputs_sha256": digest(inputs)}
    assert tuple(fields) == ENVIRONMENT
    return fields


#: the fields that hold a list of strings, a mapping, a value or None (the others hold a string)
_LISTS = ("build_fortran_args", "flags_f2py_extension", "flags_printed_programs", "flags_readings", "scenes")
_MAPS = ("inputs", "outputs", "sections")
_OR_NONE = {"dirty": bool, "cpu_count": int}


def _damage(data: dict) -> str:
    """What in a manifest of this format is not as ``write`` writes it (a field missing or of
    another type), or ''."""
    for key in KEYS[1:]:
        if key not in data:
            return f"it has no field {key!r}"
        value = data[key]
        if key in _LISTS:
            fits = isinstance(value, list) and all(isinstance(v, str) for v in value)
        elif key in _MAPS:
            fits = isinstance(value, dict) and all(isinstance(v, dict if key == "sections" else str)
                                                   for v in value.values())
        else:
            fits = isinstance(value, (_OR_NONE[key], type(None)) if key in _OR_NONE else str)
        if not fits:
            return f"its field {key!r} is {value!r:.80}"
    for name, section in data["sections"].items():
        if not (isinstance(section.get("folder"), str) and isinstance(section.get("differs"), dict)
                and all(isinstance(section.get(k), (str, type(None))) for k in ("started", "command"))):
            return f"its section {name!r} is {section!r:.80}"
    return ""


def load(out_dir: Path) -> dict | None:
    """``out_dir``'s manifest (None where there is none); ``ManifestError`` where it cannot be
    read, is of another format or is damaged (``_damage``)."""
    path = Path(out_dir) / FILE
    try:
        data = json.loads(path.read_text())
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as exc:
        raise ManifestError(f"{path} cannot be read ({type(exc).__name__}: {exc})") from exc
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        found = data.get("format") if isinstance(data, dict) else None
        raise ManifestError(f"{path} is of manifest format {found!r}; this linkrepro writes format {FORMAT}")
    damage = _damage(data)
    if damage:
        raise ManifestError(f"{path} is damaged: {damage}")
    return data


def _earlier_sections(old: dict | None, top: dict, out_dir: Path, written: Iterable[str]) -> dict:
    """The sections of the folder's last manifest not written now, their ``differs`` against
    ``top`` (each one's own set-up is the old top level's with its old ``differs``)."""
    if old is None:
        return {}
    kept = {}
    for name, section in old.get("sections", {}).items():
        if name in written or not (out_dir / section.get("folder", name)).is_dir():
            continue
        own = {**{k: old.get(k) for k in ENVIRONMENT}, **section.get("differs", {})}
        kept[name] = {**section, "differs": {k: own.get(k) for k in ENVIRONMENT if own.get(k) != top[k]}}
    return kept


def _merge(out_dir: Path, run: dict, inputs: dict[str, str], written: dict[str, str]) -> Path:
    """Write ``out_dir``'s manifest: ``run`` (``ENVIRONMENT``, started, command, scenes) at the
    top, ``written`` ({section: folder}) its sections, the others kept from the last one."""
    out_dir = Path(out_dir)
    with locked(out_dir):                   # read, merged and replaced by one writer at a time
        try:
            old = load(out_dir)
        except ManifestError:
            old = None                      # damaged or of another format: what it said is lost
        sections = {name: {"folder": folder, "started": run["started"], "command": run["command"], "differs": {}}
                    for name, folder in written.items()}
        sections.update(_earlier_sections(old, run, out_dir, written))
        manifest = {"format": FORMAT, **{k: run[k] for k in ENVIRONMENT}, "started": run["started"],
                    "command": run["command"], "scenes": list(run["scenes"]), "inputs": inputs,
                    "outputs": output_hashes(out_dir), "sections": dict(sorted(sections.items()))}
        replace_text(out_dir / FILE, json.dumps(manifest, indent=1) + "\n")
    return out_dir / FILE


def command_line(argv: Iterable[str]) -> str:
    """``linkrepro`` and its arguments as a shell would take them (each quoted where it must be)."""
    return shlex.join(["linkrepro", *argv])


def write(out_dir: Path, command: str, scenes: Iterable[str] = (), outputs: Iterable[str] = (),
          started: str | None = None, name: str = "") -> Path:
    """Write ``out_dir/manifest.json`` for a run of ``command`` (its command line) that started at
    ``started`` (``now()`` when not given) and wrote ``scenes`` (each a subfolder of ``out_dir``:
    reproduce's scenes) or ``outputs`` (files directly in ``out_dir``: a command's, its section
    ``name``, by default the command's name, ``command``'s second word); the other sections are kept."""
    scenes, outputs = list(scenes), list(outputs)
    written = {scene: scene for scene in scenes}
    if outputs:
        words = command.split()
        name = name or (words[1] if len(words) > 1 else Path(out_dir).name)
        written[name] = "."
        scenes.append(name)
    inputs = input_hashes()
    run = {**environment(inputs), "started": started or now(), "command": command, "scenes": scenes}
    return _merge(out_dir, run, inputs, written)


def include(parent: Path, child: Path) -> Path | None:
    """Enter the last run recorded in ``child``'s manifest (a command's folder in a report folder,
    ``out/bench``) into ``parent``'s, as the section named after ``child``'s folder; None where
    ``child`` has no readable manifest."""
    try:
        record = load(child)
    except ManifestError:
        return None
    if record is None:
        return None
    child = Path(child)
    run = {**{k: record.get(k) for k in ENVIRONMENT}, "started": record.get("started"),
           "command": record.get("command"), "scenes": [child.name]}
    return _merge(parent, run, record.get("inputs", {}), {child.name: child.relative_to(parent).as_posix()})


def differences(a: dict, b: dict) -> dict[str, tuple]:
    """The set-up fields of two manifests that differ, {field: (a's, b's)}: ``ENVIRONMENT``'s
    (but ``inputs_sha256``) and each input by its path (``inputs/<path>``; None where one lacks it)."""
    out = {k: (a.get(k), b.get(k)) for k in ENVIRONMENT if k != "inputs_sha256" and a.get(k) != b.get(k)}
    ins, other = a.get("inputs", {}), b.get("inputs", {})
    out.update({f"inputs/{p}": (ins.get(p), other.get(p)) for p in sorted(set(ins) | set(other))
                if ins.get(p) != other.get(p)})
    return out


# ---------------------------------------------------------------- the report's section

def _flags(flags: list) -> str:
    return f"`{' '.join(flags)}`" if flags else "(none recorded)"


def _value(value) -> str:
    if isinstance(value, list):
        return " ".join(map(str, value)) or "(none)"
    return str(value)


def _short(key: str, value) -> str:
    return value[:12] if key in ("commit", "inputs_sha256") and isinstance(value, str) else _value(value)


def summary(out_dir: Path) -> list[str]:
    """The report's "How this run was made": markdown lines from ``out_dir``'s manifest (the
    latest run's set-up, then the sections written by earlier runs and how theirs differed)."""
    try:
        m = load(out_dir)
    except ManifestError as exc:
        return [f"**{exc}**"]
    if m is None:
        return [f"No {FILE} in this folder: a run of this version of linkrepro writes one."]
    state = {True: "with uncommitted changes", False: "clean", None: "whether clean unknown"}[m["dirty"]]
    commit_text = "unknown" if m["commit"] == "unknown" else f"{m['commit'][:12]} ({state}; read from the {m['commit_from']})"
    libraries = ", ".join(f"{name} {m[name]}" for name in LIBRARIES)
    scenes = len(m["scenes"])
    lines = [f"The latest run: {code_span(m['command'])}, started {m['started']}, wrote {scenes} section{'s' * (scenes != 1)}. "
             f"[{FILE}]({FILE}) has every field, with the SHA-256 of every input and output CSV.", "",
             f"- linkrepro {m['version']}, commit {commit_text}",
             f"- Python {m['python']}; {libraries}; meson-python {m['meson_python']}",
             f"- Built with {m['build_gfortran']}, meson {m['build_meson']}, meson-python {m['build_meson_python']}, "
             f"numpy {m['build_numpy']} (build type {m['build_type']}); gfortran on PATH: "
             + ("the same" if m["gfortran"] == m["build_gfortran"] else m["gfortran"]),
             f"- Legacy flags: f2py extensions {_flags(m['flags_f2py_extension'])}; printed programs "
             + ("the same" if m["flags_printed_programs"] == m["flags_f2py_extension"]
                else _flags(m["flags_printed_programs"]))
             + f" (after meson's -O{m['build_optimization']} and FFLAGS {_value(m['build_fortran_args'])}); "
             f"rebuilds with a reading put back {_flags(m['flags_readings'])}",
             f"- {m['platform']}, {m['cpu_model']}, {m['cpu_count']} CPUs",
             f"- SHA-256 of {len(m['inputs'])} inputs ({', '.join(INPUTS)}; together {m['inputs_sha256'][:12]}) "
             f"and of {len(m['outputs'])} output CSVs", ""]
    earlier: dict[tuple, list[str]] = {}
    for name, section in m["sections"].items():
        if name not in m["scenes"]:
            key = (section["command"], section["started"], json.dumps(section["differs"], sort_keys=True))
            earlier.setdefault(key, []).append(name)
    for (command, started, differs), names in sorted(earlier.items(), key=lambda item: item[0][1] or ""):
        changed = json.loads(differs)
        how = ("the same set-up" if not changed else "differing in " +
               "; ".join(f"{k} {_short(k, v)}" for k, v in changed.items()))
        lines += [f"Run earlier: {', '.join(names)}, by {code_span(str(command))} started {started} ({how}).", ""]
    return lines
