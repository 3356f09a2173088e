"""A run folder that never lies: how a run writes an output folder, and how to tell what it holds.

- A scene's folder is whole or as it was: ``linkrepro reproduce`` writes each scene into the
  run's own hidden partial folder (``partial``: ``.linkrepro-partial-<pid>-<random>/<scene>/``),
  records every file it wrote, with its SHA-256, in the scene's ``outcome.json`` (written last),
  and puts the scene's folder in place in one rename (``place``).  A run interrupted or killed
  at any moment leaves every scene as it was before or as the run finished it; a killed run's
  partial folder stays behind, hidden, and the next run into the folder removes it
  (``unfinished`` names the scenes it was writing).
- ``read_scene`` says whether a scene's folder is what its run wrote: an outcome.json that
  cannot be read, or is another scene's, a recorded file changed, missing or unreadable, a file
  the run did not write, or files without an outcome.json (a run of an earlier version killed)
  make it damaged or incomplete, and counts under other classes than ``diff.COUNT_COLUMNS``
  (an earlier version's) outdated; ``linkrepro verify`` fails on it and the report says it.
- manifest.json and the reports are replaced whole (``replace_text``: a temporary file renamed)
  under the folder's lock (``locked``: ``flock`` on ``.linkrepro.lock``, held across the
  manifest's read, merge and replace and the report's collect, render and replace), so that two
  runs into one folder that finish together keep each other's sections.
"""
from __future__ import annotations

import ctypes
import errno
import hashlib
import os
import shutil
import tempfile
import threading
from contextlib import contextmanager
from pathlib import Path

from .diff import COUNT_COLUMNS
from .scene import Outcome

try:
    import fcntl
except ImportError:                      # not POSIX: no lock (two runs into one folder may race)
    fcntl = None

#: the folder's lock file, and the prefix of a run's partial folder (both hidden)
LOCK = ".linkrepro.lock"
PARTIAL = ".linkrepro-partial-"
_held = threading.local()                # the folders this thread has locked: {path: depth}


def sha256(path: Path) -> str:
    with open(path, "rb") as handle:
        return hashlib.file_digest(handle, "sha256").hexdigest()


def replace_text(path: Path, text: str) -> None:
    """Write ``path`` whole or not at all: a temporary file beside it, renamed over it."""
    path = Path(path)
    temporary = path.with_name(f".{path.name}.{os.getpid()}.{threading.get_ident()}.tmp")
    try:
        temporary.write_text(text)
        os.replace(temporary, path)
    finally:
        temporary.unlink(missing_ok=True)


def _flock(path: Path, wait: bool = True):
    """``path`` opened and locked (exclusive), or None where another holds it and ``wait`` is false."""
    handle = open(path, "a+")
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | (0 if wait else fcntl.LOCK_NB))
    except BlockingIOError:
        handle.close()
        return None
    return handle


@contextmanager
def locked(folder: Path):
    """Hold ``folder``'s lock (``LOCK``, created there) for the block: one writer of its manifest
    and reports at a time, across processes and threads; a thread that holds it may enter again."""
    key = os.path.realpath(folder)
    depth = getattr(_held, "folders", None)
    if depth is None:
        depth = _held.folders = {}
    if depth.get(key) or fcntl is None:
        depth[key] = depth.get(key, 0) + 1
        try:
            yield
        finally:
            depth[key] -= 1
        return
    handle = _flock(Path(folder) / LOCK)
    depth[key] = 1
    try:
        yield
    finally:
        depth[key] = 0
        handle.close()                   # releases the lock


def _owner_gone(partial_dir: Path) -> bool:
    """Whether the run that made ``partial_dir`` has ended (its lock is free)."""
    if fcntl is None:
        return False
    try:
        handle = open(partial_dir / LOCK)
    except OSError:
        return True
    with handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return False
    return True


def _partials(out_dir: Path) -> list[Path]:
    return sorted(p for p in Path(out_dir).glob(f"{PARTIAL}*") if p.is_dir())


@contextmanager
def partial(out_dir: Path):
    """A run's partial folder in ``out_dir`` (hidden, on the same file system), locked while the
    run lives and removed after it; killed runs' partial folders are removed first."""
    with locked(out_dir):
        for old in _partials(out_dir):
            if _owner_gone(old):
                shutil.rmtree(old, ignore_errors=True)
        folder = Path(tempfile.mkdtemp(prefix=f"{PARTIAL}{os.getpid()}-", dir=out_dir))
        handle = _flock(folder / LOCK) if fcntl is not None else None
    try:
        yield folder
    finally:
        try:
            shutil.rmtree(folder, ignore_errors=True)
        finally:
            if handle is not None:
                handle.close()


def remove_own_partials(out_dir: Path) -> None:
    """Remove this process's partial folders in ``out_dir`` (a Ctrl-C may have cut their making
    or their removal short)."""
    for folder in Path(out_dir).glob(f"{PARTIAL}{os.getpid()}-*"):
        shutil.rmtree(folder, ignore_errors=True)


def unfinished(out_dir: Path) -> tuple[list[str], list[str]]:
    """The scenes that partial folders in ``out_dir`` hold: (those of runs that were killed,
    those of runs still going)."""
    killed, running = [], []
    for folder in _partials(out_dir):
        try:
            names = sorted(p.name for p in folder.iterdir() if p.is_dir())
        except OSError:                  # removed meanwhile: its run has just ended
            continue
        (killed if _owner_gone(folder) else running).extend(names)
    return killed, running


_RENAME_EXCHANGE = 2


def _exchange(a: Path, b: Path) -> bool:
    """Swap the folders ``a`` and ``b`` in one step (Linux renameat2); False where the system
    cannot."""
    try:
        renameat2 = ctypes.CDLL(None, use_errno=True).renameat2
    except (AttributeError, OSError):
        return False
    at_cwd = -100
    if renameat2(at_cwd, os.fsencode(a), at_cwd, os.fsencode(b), _RENAME_EXCHANGE) == 0:
        return True
    code = ctypes.get_errno()
    if code in (errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP):
        return False
    raise OSError(code, os.strerror(code), str(a), None, str(b))


def place(new: Path, target: Path) -> None:
    """Put the folder ``new`` at ``target`` in one step, the old ``target`` (if any) removed.
    Where the system cannot swap two folders, the old one is moved aside first (for a moment
    neither is there)."""
    new, target = Path(new), Path(target)
    while True:
        try:
            os.rename(new, target)       # no folder there (or an empty one)
            return
        except OSError as exc:
            if exc.errno not in (errno.ENOTEMPTY, errno.EEXIST):
                raise
        if _exchange(new, target):
            shutil.rmtree(new)           # what was there
            return
        aside = new.with_name(new.name + ".old")
        try:
            os.rename(target, aside)
        except FileNotFoundError:
            continue                     # another run moved it meanwhile
        os.rename(new, target)
        shutil.rmtree(aside)
        return


def file_hashes(folder: Path) -> dict[str, str]:
    """{path relative to ``folder``: SHA-256} of every file in it (none hidden, not outcome.json)."""
    folder = Path(folder)
    paths = (p for p in folder.rglob("*") if p.is_file() and not p.is_symlink())
    return {p.relative_to(folder).as_posix(): sha256(p) for p in sorted(paths)
            if p.name != Outcome.FILE and not any(part.startswith(".") for part in p.relative_to(folder).parts)}


def _holds_files(folder: Path) -> bool:
    return any(not p.name.startswith(".") for p in folder.iterdir())


def read_scene(out_dir: Path, name: str) -> tuple[Outcome | None, str]:
    """``out_dir/name``'s outcome where the folder is whole, what its run wrote (else None), and
    why not ('' where it is whole or there is no such folder or it is empty)."""
    folder = Path(out_dir) / name
    if not folder.is_dir():
        return None, ""
    try:
        outcome = Outcome.load(out_dir, name)
    except FileNotFoundError:
        return None, (f"incomplete: {name}/ holds files but no {Outcome.FILE} (the run that wrote it did not "
                      "finish); run the scene again") if _holds_files(folder) else ""
    except ValueError as exc:
        return None, f"damaged: {exc}"
    if outcome.scene != name:
        return None, f"damaged: {name}/{Outcome.FILE} is the outcome of {outcome.scene!r} (a folder renamed?)"
    if outcome.counts is not None and list(outcome.counts.columns) != list(COUNT_COLUMNS):
        return None, (f"outdated: {name}/{Outcome.FILE} counts its cells as {', '.join(outcome.counts.columns)}, "
                      f"not as this linkrepro does ({', '.join(COUNT_COLUMNS)}); run the scene again")
    if outcome.files is None:              # written before outcomes recorded their files
        return outcome, ""
    try:
        found = file_hashes(folder)
    except OSError as exc:
        return None, f"damaged: {name}/ cannot be read ({exc.strerror or exc}); run the scene again"
    missing = [f for f in outcome.files if f not in found]
    changed = [f for f in outcome.files if f in found and found[f] != outcome.files[f]]
    added = [f for f in found if f not in outcome.files]
    if missing or changed or added:
        said = [f"{what} {', '.join(files)}" for what, files in
                (("missing or not a file:", missing), ("changed since the run wrote it:", changed),
                 ("not written by its run:", added)) if files]
        return None, f"damaged: {name}/ is not what its run wrote ({'; '.join(said)}); run the scene again"
    return outcome, ""
