"""The port's compiled kernels survive a cold cache compiled by several processes at once.

`pytest -n auto` and `linkrepro reproduce`'s parallel groups start several processes on a
fresh install, each compiling numba's cached kernels at the same moment.  A cached
``@guvectorize`` is kept in two files (kernel and wrapper) that two such processes can write
with mismatched symbol names; every later call then crashes (SIGSEGV, numba issue 10128,
open).  The port therefore uses no cached gufunc, and this test compiles every cached kernel
from an empty cache in several processes at once, repeatedly, then calls them all again from
the cache those processes wrote: no crash, and the same numbers as a process that compiled
alone.  ``make test`` runs it small (two processes, one round, a kernel of each kind the port
caches: ``@vectorize`` and ``@njit``: seconds); ``make fuzz`` runs it whole (every kernel, three
processes, two rounds: minutes), with ``LINKREPRO_FULL_NUMBA_RACE=1``.
"""
from __future__ import annotations

import ast
import os
import pathlib
import subprocess
import sys

import linkrepro.port

PORT = pathlib.Path(linkrepro.port.__file__).parent

#: every engine that runs a cached kernel, at its published example (PRINTED and CORRECTED);
#: prints a digest of every number it returned
WORKLOAD = r"""
import hashlib
import numpy as np
from linkrepro.port.ali1977 import case1, case2, case3
from linkrepro.port.ali1977.quirks import PRINTED, CORRECTED
from linkrepro.port.rahman1996.balance import balance, solve_qp
from linkrepro.port.rahman1996.data import CsspInputs
from linkrepro.port.rahman1996.quirks import CSSP_PRINTED, CSSP_CORRECTED
from linkrepro.port.rahman1996.qprog import hessian_shift, qprog
from linkrepro.port.rahman1991.analysis import analyse
from linkrepro.port.rahman1991.quirks import GSC_PRINTED, GSC_CORRECTED
from linkrepro.port import libm, real4

digest = hashlib.sha256()
def take(value):
    if isinstance(value, dict):
        for key in sorted(value):
            take(value[key])
    elif isinstance(value, (list, tuple)):
        for item in value:
            take(item)
    elif hasattr(value, "to_csv"):
        digest.update(value.to_csv().encode())          # repr of floats: every bit
    elif isinstance(value, (np.ndarray, np.generic, float, int)) and np.asarray(value).dtype.kind in "fiub":
        digest.update(np.ascontiguousarray(np.asarray(value, dtype=np.float64)).tobytes())
    else:
        digest.update(repr(value).encode())

deg = np.arange(0.0, 360.0, 30.0)
for q in (PRINTED, CORRECTED):
    for f in (case1.source_case1, case1.cognate_case1, case2.case2_source, case2.case2_cognate,
              case3.case3_source, case3.case3_cognate):
        take(f(deg, quirks=q))
for q in (CSSP_PRINTED, CSSP_CORRECTED):
    take(balance(CsspInputs(), q))
for q in (GSC_PRINTED, GSC_CORRECTED):
    take(analyse(crank_deg=deg, quirks=q))
take(qprog(np.eye(2), np.array([-1.0, -1.0]), np.array([[1.0, 1.0]]), np.array([3.0]), 0))
take(hessian_shift(np.diag([1.0, 0.0])))
take([libm.sin(deg), libm.cos(deg), libm.arctan(deg)])
take(real4.product(np.ones((3, 2, 4)), np.full((4, 5), 0.1), True))

print(digest.hexdigest())
"""


#: the small workload: the C library's functions (``@vectorize``, libm) and REAL*4 products
#: (``@njit``, real4), one of each kind of cached kernel
SMALL_WORKLOAD = r"""
import hashlib
import numpy as np
from linkrepro.port import libm, real4

digest = hashlib.sha256()
deg = np.arange(0.0, 360.0, 30.0)
for value in (libm.sin(deg), libm.cos(deg), libm.arctan(deg), real4.product(np.ones((3, 2, 4)), np.full((4, 5), 0.1), True)):
    digest.update(np.ascontiguousarray(value, dtype=np.float64).tobytes())
print(digest.hexdigest())
"""
SMALL_KERNELS = {"libm.sin", "libm.cos", "libm.arctan", "real4._mprd"}
FULL_ENV = "LINKREPRO_FULL_NUMBA_RACE"


def cached_kernels() -> set[str]:
    """``module.function`` of every kernel the port compiles with ``cache=True``, read from the
    source: decorated functions, and functions passed to ``njit(f, cache=True)``."""
    found = set()
    for path in PORT.rglob("*.py"):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            calls = [d for d in getattr(node, "decorator_list", ()) if isinstance(d, ast.Call)]
            if isinstance(node, ast.FunctionDef) and any(_caches(c) for c in calls):
                found.add(f"{path.stem}.{node.name}")
            if isinstance(node, ast.Call) and _caches(node) and node.args and isinstance(node.args[0], ast.Name):
                found.add(f"{path.stem}.{node.args[0].id}")
    return found


def _caches(call: ast.Call) -> bool:
    return any(k.arg == "cache" and getattr(k.value, "value", False) is True for k in call.keywords)


def _run_many(workload: str, cache_dir: pathlib.Path | None, processes: int) -> list[str]:
    """Start ``processes`` interpreters on ``workload`` at once with numba's cache in ``cache_dir``
    (in its folder keyed by the port's source, ``port/_numba_cache.py``; None: linkrepro's own
    folder in the user's cache)."""
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = str(cache_dir)
    started = [subprocess.Popen([sys.executable, "-c", workload], env=env, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True) for _ in range(processes)]
    outputs = []
    for proc in started:
        out, err = proc.communicate(timeout=1800)
        assert proc.returncode == 0, f"exit {proc.returncode} (SIGSEGV is -11):\n{err[-2000:]}"
        outputs.append(out.strip())
    return outputs


def test_no_cached_gufunc_in_the_port():
    """No ``@guvectorize(..., cache=True)`` anywhere in the port (numba issue 10128)."""
    found = []
    for path in PORT.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and getattr(node.func, "id", getattr(node.func, "attr", "")) == "guvectorize":
                if any(k.arg == "cache" and getattr(k.value, "value", False) for k in node.keywords):
                    found.append(f"{path.relative_to(PORT)}:{node.lineno}")
    assert not found


def test_cold_cache_compiled_concurrently_then_reused(tmp_path):
    """The reference: the workload in a process of its own on the installation's cache.  Then,
    for each round, several processes compile its kernels into an empty cache at the same
    moment, and as many more load what they wrote: each exits cleanly with the reference
    digest.  Whole (``FULL_ENV``): every kernel of the port, three processes, two rounds, and
    the cold wave caches every kernel (none escapes the test)."""
    full = bool(os.environ.get(FULL_ENV))
    workload, processes, rounds = (WORKLOAD, 3, 2) if full else (SMALL_WORKLOAD, 2, 1)
    (reference,) = _run_many(workload, None, 1)
    kernels = cached_kernels()
    assert len(kernels) > 20
    for r in range(rounds):
        cache = tmp_path / f"race{r}"
        assert _run_many(workload, cache, processes) == [reference] * processes
        written = {p.name.split("-")[0] for p in cache.rglob("*.nbi")}
        expected = kernels if full else SMALL_KERNELS
        assert expected <= written, f"kernels the workload does not compile: {sorted(expected - written)}"
        assert _run_many(workload, cache, processes) == [reference] * processes
