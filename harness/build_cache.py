"""A per-user cache of the executables gfortran builds during a run (a listing with a reading
put back, an arithmetic variant), so that a warm run does not build them again.

An entry is named by the SHA-256 of everything that makes the executable: the compiler (its
resolved path, size and modification time, and what ``--version`` prints), the flags, and
every input's name and text in the order of the build (the caller's names also say how an
input enters it: a source, or an object compiled from that text with the same flags).  A
changed listing, flag or compiler is a new entry, never a stale one.

Entries are files in ``$XDG_CACHE_HOME/linkrepro/builds`` (``~/.cache/linkrepro/builds``
when XDG_CACHE_HOME is not set or not absolute); ``LINKREPRO_BUILD_CACHE`` names another
folder, or ``off`` for none.  An entry is the SHA-256 of the executable (64 hex digits and a
newline) followed by the executable.  It is written to a temporary file in that folder and
renamed into place (``os.replace``), so that processes and threads building side by side
(``linkrepro reproduce``'s workers, ``pytest -n``) see a whole entry or none; an entry whose
bytes do not match its digest (cut short, damaged) is built again and replaced.  The
executable is copied out of the entry and run from the caller's folder, against the C and
FORTRAN libraries of this machine (``run``: a thread's fork may hold a file just written open
until the child execs, and running it then fails with ETXTBSY; it is tried again).  A folder
that cannot be read or written is no cache: the build runs as without one.  Removing the folder
empties the cache; beyond ``MAX_BYTES`` the least recently used entries are removed (``prune``:
a stored or fetched entry is used).
``fetch`` and ``store`` keep other derived bytes the same way (the report page's WebP figures,
``html_report.data_uri``), each named by the SHA-256 of what makes it.
"""
from __future__ import annotations

import errno
import hashlib
import json
import os
import shutil
import subprocess
import tempfile
import time
from functools import lru_cache
from pathlib import Path
from typing import Callable, Sequence

ENV = "LINKREPRO_BUILD_CACHE"
DIGEST_LEN = 64          # hex digits of a SHA-256
BUSY_TRIES, BUSY_WAIT_S = 20, 0.05
#: the cache's size at most (bytes): the least recently used entries go beyond it (``prune``); a
#: full run's builds and figures (reproduce and arithmetic) take 3.5 MB in 70 entries, measured 2026-11-28
MAX_BYTES = 256 * 2**20


def folder() -> Path | None:
    """The cache folder (not created here), or None when ``LINKREPRO_BUILD_CACHE=off``."""
    chosen = os.environ.get(ENV, "")
    if chosen.lower() == "off":
        return None
    if chosen:
        return Path(chosen)
    xdg = os.environ.get("XDG_CACHE_HOME", "")
    base = Path(xdg) if os.path.isabs(xdg) else Path.home() / ".cache"
    return base / "linkrepro" / "builds"


def compiler_identity(compiler: str) -> str | None:
    """What identifies the compiler ``compiler`` (a name on PATH): its resolved path, size,
    modification time (ns) and ``--version`` text; None if it is not found or does not answer."""
    path = shutil.which(compiler)
    if path is None:
        return None
    real = os.path.realpath(path)
    try:
        stat = os.stat(real)
    except OSError:
        return None
    return _identity(real, stat.st_size, stat.st_mtime_ns)


@lru_cache(maxsize=8)
def _identity(real: str, size: int, mtime_ns: int) -> str | None:
    try:
        version = subprocess.run([real, "--version"], capture_output=True, text=True, timeout=60, check=True).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    return json.dumps([real, size, mtime_ns, version])


def key(compiler: str, flags: Sequence[str], inputs: Sequence[tuple[str, str]]) -> str | None:
    """The entry of a build: ``compiler`` run with ``flags`` on ``inputs`` ((name, text) in
    build order).  None (do not cache) when the cache is off or the compiler unidentified."""
    identity = compiler_identity(compiler)
    if identity is None or folder() is None:
        return None
    recipe = json.dumps([identity, list(flags), [list(pair) for pair in inputs]])
    return hashlib.sha256(recipe.encode()).hexdigest()


def executable(entry: str | None, exe: Path, build: Callable[[], None]) -> bool:
    """Put the executable of build ``entry`` (``key``) at ``exe``: copied from the cache when
    it holds a whole entry (returns True), else made by ``build()``, which writes ``exe``, and
    stored (returns False).  ``entry`` None: ``build()`` only.  What ``build`` raises is raised
    and nothing is stored."""
    if entry is not None and _fetch(entry, exe):
        return True
    build()
    if entry is not None:
        _store(entry, exe)
    return False


def _fetch(entry: str, exe: Path) -> bool:
    payload = fetch(entry)
    if payload is None:
        return False
    exe.write_bytes(payload)
    exe.chmod(0o755)
    return True


def _store(entry: str, exe: Path) -> None:
    try:
        store(entry, exe.read_bytes())
    except OSError:
        pass                                           # nothing to store: the build stands


def fetch(entry: str) -> bytes | None:
    """The bytes stored under ``entry`` (a SHA-256 in hex), or None when the cache holds no
    whole entry (none, off, damaged or cut short)."""
    where = folder()
    if where is None:
        return None
    try:
        data = (where / entry).read_bytes()
    except OSError:
        return None
    digest, payload = data[:DIGEST_LEN], data[DIGEST_LEN + 1:]
    if data[DIGEST_LEN:DIGEST_LEN + 1] != b"\n" or hashlib.sha256(payload).hexdigest().encode() != digest:
        return None
    try:
        os.utime(where / entry)                        # used now: what ``prune`` keeps longest
    except OSError:
        pass
    return payload


def store(entry: str, payload: bytes) -> None:
    """Store ``payload`` under ``entry``, whole or not at all (a temporary file renamed); a
    cache that is off or cannot be written stores nothing."""
    target = folder()
    if target is None:
        return
    try:
        target.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=target, prefix=f".{entry[:16]}-", suffix=".tmp")
        try:
            with os.fdopen(handle, "wb") as out:
                out.write(hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload)
            os.replace(temporary, target / entry)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise
        prune(target)
    except OSError:
        pass                                           # no cache to write: the caller has its bytes


def prune(target: Path, limit: int = MAX_BYTES) -> list[str]:
    """Remove ``target``'s least recently used entries (stored or fetched longest ago) until the
    rest take at most ``limit`` bytes; return the names removed.  Every changed listing, flag or
    figure is a new entry (a figure of measured times is new at every run), so without this the
    cache would only grow.  Another process may be removing the same entries: a missing one is no
    error."""
    entries = []
    for item in os.scandir(target):
        if len(item.name) == DIGEST_LEN and not item.name.startswith("."):
            try:
                stat = item.stat()
            except OSError:
                continue
            entries.append((stat.st_mtime, stat.st_size, item.name))
    total, removed = sum(size for _, size, _ in entries), []
    for _, size, name in sorted(entries):
        if total <= limit:
            break
        try:
            (target / name).unlink()
        except FileNotFoundError:
            pass
        total -= size
        removed.append(name)
    return removed


def run(command: Sequence[str], **kwargs) -> subprocess.CompletedProcess:
    """``subprocess.run(command, **kwargs)``, tried again (every ``BUSY_WAIT_S`` s, at most
    ``BUSY_TRIES`` times) while the executable is busy (ETXTBSY): an executable copied out of the
    cache is open for writing in any child another thread forked meanwhile, until it execs."""
    for _ in range(BUSY_TRIES - 1):
        try:
            return subprocess.run(command, **kwargs)
        except OSError as exc:
            if exc.errno != errno.ETXTBSY:
                raise
        time.sleep(BUSY_WAIT_S)
    return subprocess.run(command, **kwargs)
