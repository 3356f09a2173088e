"""Shared fixtures: the repository root (for legacy/printed, legacy/src) and the register;
the hypothesis profiles of the property-based tests."""
import os
from pathlib import Path

from linkrepro.harness import blas_threads

blas_threads.use_one()           # as every linkrepro command: one BLAS thread (harness/blas_threads.py)

import pytest  # noqa: E402
from hypothesis import HealthCheck, settings  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
# a figure that breaks a rule of harness/figures.py (text under 9 pt, a label over data, ...)
# fails the test that draws it, here and in the runs the tests start
os.environ.setdefault("LINKREPRO_STRICT_FIGURES", "1")

# "ci" (the default): no example database, a fixed seed (derandomize), no deadline (the first
# call of a compiled kernel compiles it).  "thorough": ten times the examples, for `make fuzz`.
settings.register_profile("ci", database=None, derandomize=True, deadline=None, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("thorough", parent=settings.get_profile("ci"), max_examples=1000)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def register():
    from linkrepro.harness import register as reg
    return reg.load()
