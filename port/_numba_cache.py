"""Where numba caches the port's compiled kernels: a folder named by the port's source.

numba reuses a cached kernel while the kernel's own file is unchanged; the machine code of a
kernel it calls from another module (compiled, often inlined, into the caller's) and a global
read as a constant are not checked (numba issue 1833, open since 2016; numba's documentation:
"Cache invalidation fails to recognize changes in functions defined in a different file").  An
edit to a callee would leave the caller's old machine code in use: a wrong number, silently.

So ``configure`` (called by ``linkrepro.port`` before any of its modules imports numba) sets
``NUMBA_CACHE_DIR`` to ``<root>/linkrepro-<key>``, ``key`` the SHA-256 of every ``.py`` file of
the port and of the package's top modules (their paths and bytes): any edit gives
a new folder, and every kernel compiles anew there.  ``root`` is ``$XDG_CACHE_HOME/linkrepro/numba``
(``~/.cache/linkrepro/numba`` when XDG_CACHE_HOME is not set or not absolute), never the
installation's folder (which may be read-only); a ``NUMBA_CACHE_DIR`` of the user's is the root
instead.  Where the root cannot be written, the temporary folder's ``linkrepro-numba-<uid>`` is.
Child processes inherit the variable, and with ``LINKREPRO_NUMBA_CACHE_DIR`` (equal to it) know
it for linkrepro's: they key it again by the source they import.  A new folder prunes its
siblings: the ``KEEP`` most recently used stay, and any used within ``IDLE_S``.  Removing the
root empties the cache.
"""
from __future__ import annotations

import hashlib
import os
import re
import shutil
import sys
import tempfile
import time
import warnings
from pathlib import Path

ENV = "NUMBA_CACHE_DIR"
#: the folder this module set ``ENV`` to (a child process inherits both)
OURS = "LINKREPRO_NUMBA_CACHE_DIR"
PREFIX = "linkrepro-"
KEY_LEN = 16                   # hex digits of the SHA-256 kept in a folder's name
KEEP, IDLE_S = 4, 3600.0       # folders kept, and seconds since its last use that keep one more
_OURS_NAME = re.compile(re.escape(PREFIX) + f"[0-9a-f]{{{KEY_LEN}}}")


def source_files(port: Path, top: Path) -> dict[str, Path]:
    """Every module a cached kernel can be compiled from, by name: the port's ``.py`` files
    (``ali1977/fourbar.py``) and the package's top modules (``../errors.py``, ``../checks.py``)."""
    found = {Path(d, f).relative_to(port).as_posix(): Path(d, f)
             for d, _, names in os.walk(port) for f in names if f.endswith(".py")}
    return found | {f"../{p.name}": p for p in top.glob("*.py")}


def source_key(port: Path, top: Path) -> str:
    """``KEY_LEN`` hex digits of the SHA-256 of ``source_files``' names and bytes."""
    digest = hashlib.sha256()
    for name, path in sorted(source_files(port, top).items()):
        text = path.read_bytes()
        digest.update(f"{name}\0{len(text)}\0".encode())
        digest.update(text)
    return digest.hexdigest()[:KEY_LEN]


def roots() -> list[Path]:
    """Where the keyed folders may go, in order of preference."""
    current = os.environ.get(ENV, "")
    if current and current == os.environ.get(OURS):
        first = Path(current).parent                  # set by linkrepro in a parent process
    elif current:
        first = Path(current)                         # the user's own
    else:
        xdg = os.environ.get("XDG_CACHE_HOME", "")
        try:
            first = (Path(xdg) if os.path.isabs(xdg) else Path.home() / ".cache") / "linkrepro" / "numba"
        except (RuntimeError, KeyError):              # no home folder: the fallback alone
            first = None
    fallback = Path(tempfile.gettempdir()) / f"{PREFIX}numba-{os.getuid() if hasattr(os, 'getuid') else 0}"
    return [root for root in (first, fallback) if root is not None]


def prune(root: Path, keep: int = KEEP, idle_s: float = IDLE_S) -> list[Path]:
    """Remove ``root``'s keyed folders but the ``keep`` most recently used and those used within
    ``idle_s`` seconds; return those removed (another process may be removing them too)."""
    try:
        folders = [p for p in root.iterdir() if _OURS_NAME.fullmatch(p.name)]
    except OSError:
        return []
    used = []
    for path in folders:
        try:
            used.append((path.stat().st_mtime, path))
        except OSError:                               # removed meanwhile by another process
            continue
    used.sort(reverse=True)
    removed = [p for mtime, p in used[keep:] if time.time() - mtime > idle_s]
    for path in removed:
        shutil.rmtree(path, ignore_errors=True)
    return removed


def configure(port: Path | None = None, top: Path | None = None) -> Path | None:
    """Set ``NUMBA_CACHE_DIR`` to the keyed folder of the port's source and return it (None, with
    a warning, where no root can be written: numba then keeps its own locations and rule)."""
    port = Path(__file__).parent if port is None else port
    top = Path(sys.modules[__name__.partition(".")[0]].__file__).parent if top is None else top
    key = PREFIX + source_key(port, top)
    for root in roots():
        folder = root / key
        try:
            new = not folder.is_dir()
            folder.mkdir(parents=True, exist_ok=True)
            os.utime(folder)                          # used now: what prune keeps
        except OSError:
            continue
        if os.access(folder, os.W_OK):
            break
    else:
        warnings.warn(f"no writable folder for numba's cache ({', '.join(map(str, roots()))}): the port's kernels are "
                      "cached where numba chooses, and an edit to a kernel in another module than its caller's is "
                      "not seen (numba issue 1833)", stacklevel=2)
        return None
    if new:
        prune(root)
    os.environ[ENV] = os.environ[OURS] = str(folder)
    if "numba" in sys.modules:                        # imported before linkrepro: read the variable again
        sys.modules["numba"].core.config.reload_config()
    return folder
