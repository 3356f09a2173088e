"""meson.build's legacy flags mean the same under each compiler family (readings.LEGACY_FLAGS, which a
test holds equal to meson.build's branches): static storage (a subprogram's local keeps its value
between calls and starts at zero, as on the IBM 370) and no contraction of a*b+c into a fused
multiply-add, even where the target has one (-march=haswell -O2), against the unfused sum computed
here.  Each compiler found on PATH is run; one missing is skipped."""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from linkrepro.harness.readings import LEGACY_FLAGS, family

COMPILERS = ("gfortran", "flang-22")
PROGRAM = """\
      PROGRAM T
      DOUBLE PRECISION A, B, C, X
      INTEGER I
      READ (5, *) A, B, C
      X = A*B + C
      DO 10 I = 1, 3
        CALL COUNT
   10 CONTINUE
      WRITE (6, '(ES25.16E3)') X
      END
      SUBROUTINE COUNT
      INTEGER N
      N = N + 1
      WRITE (6, '(I3)') N
      END
"""
# a*b = 1 - 2**-60 rounds to 1 in double: unfused a*b + c is 0, fused -2**-60
A, B, C = 1 + 2.0**-30, 1 - 2.0**-30, -1.0


def _run(compiler: str, extra: tuple[str, ...], tmp_path) -> list[str]:
    (tmp_path / "t.f").write_text(PROGRAM)
    flags = [f for f in LEGACY_FLAGS[family(compiler)] if f != "-fallow-argument-mismatch"]
    subprocess.run([compiler, *flags, *extra, "-o", "t", "t.f"], cwd=tmp_path, check=True, capture_output=True,
                   timeout=120)
    done = subprocess.run(["./t"], cwd=tmp_path, input=f"{A!r} {B!r} {C!r}\n", capture_output=True, text=True,
                          check=True, timeout=60)
    return done.stdout.split()


@pytest.mark.parametrize("compiler", COMPILERS)
def test_static_storage_and_no_contraction(compiler, tmp_path):
    if shutil.which(compiler) is None:
        pytest.skip(f"{compiler} is not on PATH")
    cpuinfo = Path("/proc/cpuinfo")
    if not cpuinfo.is_file() or " fma " not in cpuinfo.read_text().replace("\n", " "):
        pytest.skip("the processor has no FMA instruction (the -march=haswell build would not run)")
    fma = ("-march=haswell", "-O2")          # a target with FMA, optimised enough to form it (gfortran: -O2)
    *counts, x = _run(compiler, fma, tmp_path)
    assert counts == ["1", "2", "3"]                         # N saved between calls, from zero
    assert float(x) == np.float64(A) * np.float64(B) + np.float64(C) == 0.0
    *_, fused = _run(compiler, (*fma, "-ffp-contract=fast"), tmp_path)
    assert float(fused) == -(2.0**-60)                       # the flag is what keeps it unfused
