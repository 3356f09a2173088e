"""The smallest context a fuzz worker can run the known calls of ``test_fuzz.py`` with (numpy,
linkrepro's errors): a worker starts in a fraction of a second, not after importing every
thesis and compiling its kernels as the fuzz's own context does."""
import numpy as np

from linkrepro.errors import AssemblyError, SingularPositionError
from linkrepro.harness.fuzz_runner import Context

REFERENCE = f"{__name__}:context"


def context() -> Context:
    return Context({"np": np, "AssemblyError": AssemblyError, "SingularPositionError": SingularPositionError})
