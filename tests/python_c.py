"""Run Python code as ``python -c CODE`` does, for the tests that run code a reader runs (the
docs' examples, the register's checks).

In ``make test`` the code runs in a child forked from a server that has imported the modules the
code imports (``imports``) once: the child's ``__main__``, globals, ``sys.argv``, working folder
and output are its own, as in a fresh interpreter, but not its imports (about 1.5 s of CPU a
run, most of a check's time).  With ``LINKREPRO_FULL_TESTS=1`` (``make fuzz``) each runs in a
fresh interpreter, as written.
"""
from __future__ import annotations

import ast
import atexit
import os
import socket
import subprocess
import sys
import tempfile
import traceback
import types
from functools import lru_cache
from multiprocessing.connection import Connection
from pathlib import Path

from tests.patience import CHILD_SECONDS
from tests.sizes import FULL


def imports(code: str) -> set[str]:
    """The modules ``code`` imports (``import a.b``, ``from a.b import c``), at any depth."""
    found = set()
    for node in ast.walk(ast.parse(code)):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.add(node.module)
    return found


def run(code: str, cwd: Path | str, preload: frozenset[str] = frozenset()) -> subprocess.CompletedProcess:
    """``python -c code`` in ``cwd``: exit status, stdout and stderr (text).  ``preload``: the
    modules the server imports first (the codes' ``imports``; one server a preload set)."""
    if FULL:
        return subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True, text=True,
                              timeout=CHILD_SECONDS)
    conn = _server(frozenset(preload))
    conn.send((code, str(cwd)))
    if not conn.poll(CHILD_SECONDS):
        conn.close()                    # its late answer must not be read as the next code's:
        _server.cache_clear()           # the next run starts a server of its own (this one sees EOF)
        raise TimeoutError(f"no answer in {CHILD_SECONDS} s from: {code[:200]}")
    status, out, err = conn.recv()
    return subprocess.CompletedProcess(["python", "-c", code], status, out, err)


@lru_cache(maxsize=None)
def _server(preload: frozenset[str]) -> Connection:
    """A server for ``preload``: an interpreter (not a multiprocessing child, which a test of the
    runs' workers would count as left behind) that answers on a socket; this process ends it at exit."""
    ours, theirs = socket.socketpair()
    start = f"import sys; sys.path[:0] = {sys.path!r}; from tests.python_c import serve; serve({theirs.fileno()}, {sorted(preload)!r})"
    server = subprocess.Popen([sys.executable, "-c", start], pass_fds=(theirs.fileno(),),
                              stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    theirs.close()
    conn = Connection(ours.detach())
    atexit.register(lambda: (conn.close(), server.wait(CHILD_SECONDS)))      # its end: EOF
    return conn


def serve(fd: int, preload: list[str]) -> None:
    """The server: import ``preload``, then fork a child for each code received on ``fd``."""
    import importlib
    for name in preload:
        try:
            importlib.import_module(name)
        except Exception:           # noqa: BLE001 - the child imports it again and says why
            pass
    conn = Connection(fd)
    while True:
        try:
            code, cwd = conn.recv()
        except (EOFError, OSError):
            return
        with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
            pid = os.fork()
            if pid == 0:
                conn.close()
                os.dup2(out.fileno(), 1)
                os.dup2(err.fileno(), 2)
                os._exit(_child(code, cwd))
            status = os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1])
            out.seek(0)
            err.seek(0)
            conn.send((status, out.read().decode(errors="replace"), err.read().decode(errors="replace")))


def _child(code: str, cwd: str) -> int:
    """Run ``code`` as ``python -c`` does: a new ``__main__``, '' first on the path; its exit status."""
    os.chdir(cwd)
    sys.argv, sys.path[0:0] = ["-c"], [""]
    main = types.ModuleType("__main__")
    sys.modules["__main__"] = main
    try:
        exec(compile(code, "<string>", "exec"), main.__dict__)    # noqa: S102 - the code a reader runs
        status = 0
    except SystemExit as exc:
        status = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
        if not isinstance(exc.code, (int, type(None))):
            print(exc.code, file=sys.stderr)
    except BaseException:           # noqa: BLE001 - as the interpreter: a traceback and status 1
        traceback.print_exc()
        status = 1
    sys.stdout.flush()
    sys.stderr.flush()
    return status
