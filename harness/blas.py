"""One BLAS thread inside a block (``one_thread``): numpy's and scipy's OpenBLAS, found by name
in their wheels' ``.libs`` folders and set through their own ``set_num_threads``.

Why: a scene that makes many small dense solves (Exudyn's Jacobians, about 100 x 100) on a
loaded machine, with OpenBLAS's default of a thread per core, spends most of its CPU in threads
that wait for one another (the ali1977-elastodynamics statics: 3.4 s of CPU against 0.4 s with
one thread, measured on the 2-core machine with other work running).  Where no OpenBLAS is found
(another BLAS, another system) the block runs unchanged.
"""
from __future__ import annotations

import ctypes
import importlib.util
from contextlib import contextmanager
from pathlib import Path

#: the exported thread setters and getters, as the wheels' OpenBLAS builds name them
_NAMES = (("scipy_openblas_set_num_threads64_", "scipy_openblas_get_num_threads64_"),
          ("scipy_openblas_set_num_threads", "scipy_openblas_get_num_threads"),
          ("openblas_set_num_threads", "openblas_get_num_threads"))


def _libraries() -> list[tuple]:
    """(set, get) of every OpenBLAS in numpy's and scipy's wheels (none where there is none)."""
    found = []
    for package in ("numpy", "scipy"):
        spec = importlib.util.find_spec(package)
        if spec is None or spec.origin is None:
            continue
        for path in sorted(Path(spec.origin).parent.parent.glob(f"{package}.libs/lib*openblas*.so*")):
            try:
                lib = ctypes.CDLL(str(path))
            except OSError:
                continue
            for set_name, get_name in _NAMES:
                if hasattr(lib, set_name) and hasattr(lib, get_name):
                    found.append((getattr(lib, set_name), getattr(lib, get_name)))
                    break
    return found


@contextmanager
def one_thread():
    """Inside the block every OpenBLAS found runs on one thread; after it, as many as before."""
    libraries = _libraries()
    before = [get() for _, get in libraries]
    for set_threads, _ in libraries:
        set_threads(1)
    try:
        yield
    finally:
        for (set_threads, _), count in zip(libraries, before):
            set_threads(count)
