"""One BLAS thread for every linkrepro command and the tests.

OpenBLAS (numpy's and scipy's wheels) reads ``OPENBLAS_NUM_THREADS`` once, when numpy loads it,
and otherwise starts a thread per core.  linkrepro's systems are small, and those threads cost
more than they give: in ``reproduce``'s pool (one process per core) each process's threads
compete for the same cores, and they change the last bits of a result with the number of
threads (measured 2026-11-28 on the 2-core machine: ali1977-multibody's stiff solves moved by
up to 2.7e-7 relative between 2 threads and 1, so the run of record in ``reference/`` would
depend on the core count of the machine that made it; on a loaded machine that scene took 25 s
of CPU with 2 threads, 3.2 s with one).  ``use_one`` sets the variable before numpy loads.
"""
from __future__ import annotations

import os
import sys

VARIABLE = "OPENBLAS_NUM_THREADS"


def use_one() -> bool:
    """Set ``OPENBLAS_NUM_THREADS=1`` for this process and its children; False (and nothing
    set) if numpy is loaded already, where the setting would come too late."""
    if "numpy" in sys.modules:
        return False
    os.environ[VARIABLE] = "1"
    return True
