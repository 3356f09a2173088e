"""The arithmetic study's build (``arithmetic.py``): legacy/src (or the listing as printed)
rebuilt under a variant's flags and source transform in a temporary folder (or taken from the
build cache, ``harness/build_cache.py``), run by a driver that WRITEs every cell of TABLE and
INERT in full precision, measured side by side."""
from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd

from ... import build_cache
from ...readings import COMPILE_TIMEOUT_S, COMPILER, PRINTED_DIR, CompilerError, first_error
from .arithmetic_variants import MAIN, VARIANTS, Variant
from .table_forms import as_tables

LEGACY_DIR = PRINTED_DIR.parent
SRC = ("src/rahman1996_cssp_main.f", "src/rahman1996_subroutines.f", "src/imsl_qprog.f")
PRINTED = ("printed/rahman1996_cssp_main.f", "printed/rahman1996_subroutines.f", "src/imsl_qprog.f")
RUN_TIMEOUT_S = 60

#: a driver for legacy/src, whose main program is SUBROUTINE CSSP (D051): the printed
#: PARAMETERs as arguments, every cell of TABLE and INERT written in full precision
DRIVER = """\
      PROGRAM ARITHD
      INTEGER ISTAT,USESOL,J,K
      REAL SOLIN(9),SOLOUT(9),HOUT(9,9),DIAGO,FAILDG,SOLAFT(9)
      REAL A1,A2,A4,S1,RPM
      REAL*8 AL4,QOUT(5,37,2)
      DOUBLE PRECISION TABLE(37,12),INERT(6,2)
      DATA SOLIN/9*0.0/
      A1=2.0
      A2=8.0
      A4=1.0
      AL4=250.0
      S1=0.4
      RPM=3000.0
      USESOL=0
      CALL CSSP(A1,A2,A4,AL4,S1,RPM,USESOL,SOLIN,TABLE,SOLOUT,
     1 INERT,HOUT,DIAGO,ISTAT,FAILDG,QOUT,SOLAFT)
      WRITE(*,'(A,I3)') ' ISTAT',ISTAT
      DO 10 J=1,37
   10 WRITE(*,'(A,12ES26.17E3)') ' T',(TABLE(J,K),K=1,12)
      DO 20 J=1,6
   20 WRITE(*,'(A,2ES26.17E3)') ' I',(INERT(J,K),K=1,2)
      END
"""


class VariantFailed(RuntimeError):
    """One variant could not be built or run (e.g. x87 flags on a machine without an x87)."""


class ReferenceFailed(RuntimeError):
    """The reference build itself could not be built or run, or legacy/ is not there."""


# ---------------------------------------------------------------- build and run

def require_compiler() -> None:
    if shutil.which(COMPILER) is None:
        raise CompilerError(f"{COMPILER} is not on PATH; it rebuilds the legacy FORTRAN under each arithmetic: "
                            f"install it (apt-get install {COMPILER})")
    if not all((LEGACY_DIR / path).is_file() for path in SRC + PRINTED):
        raise ReferenceFailed(f"the FORTRAN sources are not under {LEGACY_DIR} (an installed package without "
                              "the source tree): run from the source tree")


def _files(variant: Variant) -> dict[str, str]:
    paths = PRINTED if variant.source == "printed" else SRC
    files = {Path(p).name: (LEGACY_DIR / p).read_text() for p in paths}
    if variant.source != "printed":
        files["driver.f"] = DRIVER
    return variant.transform(files) if variant.transform is not None else files


def _transformed(variant: Variant) -> dict[str, str]:
    try:
        return _files(variant)
    except ValueError as exc:
        raise VariantFailed(f"source transform: {exc}") from exc


def _gfortran(flags: tuple[str, ...], args: list[str], workdir: Path) -> None:
    try:
        subprocess.run([COMPILER, *flags, *args], cwd=workdir, check=True,
                       capture_output=True, text=True, timeout=COMPILE_TIMEOUT_S)
    except subprocess.CalledProcessError as exc:
        raise VariantFailed(f"does not build: {first_error(exc.stderr)}") from exc
    except subprocess.TimeoutExpired as exc:
        raise VariantFailed(f"{COMPILER} did not finish in {COMPILE_TIMEOUT_S} s") from exc
    except OSError as exc:
        raise CompilerError(f"{COMPILER} could not be run: {exc.strerror or exc}") from exc


class Shared:
    """Files of a variant (``names``) compiled once with its flags to object files in
    ``workdir``, when a build first needs them: ``build_and_run`` links them into every variant
    with the same text of them and the same flags.  ``VariantFailed`` if the variant's source
    transform fails (at once) or the files do not compile (``objects``)."""

    def __init__(self, variant: Variant, names: tuple[str, ...], workdir: Path):
        files = _transformed(variant)
        self.texts, self.flags, self.workdir = {name: files[name] for name in names}, variant.flags, workdir
        self._objects: dict[str, Path] | None = None
        self._lock = threading.Lock()

    def objects(self) -> dict[str, Path]:
        """name: its object file, compiled on the first call."""
        with self._lock:
            if self._objects is None:
                self.workdir.mkdir(parents=True, exist_ok=True)
                for name, text in self.texts.items():
                    (self.workdir / name).write_text(text)
                _gfortran(self.flags, ["-c", *self.texts], self.workdir)
                self._objects = {name: self.workdir / (Path(name).stem + ".o") for name in self.texts}
            return self._objects


def build_and_run(variant: Variant, workdir: Path, shared: Shared | None = None) -> str:
    """Build one variant in ``workdir`` (or take the build from the build cache,
    ``harness/build_cache.py``) and return its standard output.  A file whose text and flags
    are those of ``shared`` is linked from its object file, not compiled.  ``VariantFailed`` if
    it does not build or run; ``CompilerError`` if gfortran cannot run."""
    workdir.mkdir(parents=True, exist_ok=True)
    files = _transformed(variant)
    order = ["driver.f", MAIN] + [n for n in files if n not in ("driver.f", MAIN)]
    names = [n for n in order if n in files]
    linked = [n for n in names if shared is not None and shared.flags == variant.flags
              and shared.texts.get(n) == files[n]]
    own = [n for n in names if n not in linked]
    exe = workdir / "cssp"

    def build() -> None:
        for name in own:
            (workdir / name).write_text(files[name])
        if own:                                  # a text that does not compile fails here, first
            _gfortran(variant.flags, ["-c", *own], workdir)
        objects = shared.objects() if linked else {}
        _gfortran(variant.flags, ["-o", str(exe), *[Path(n).stem + ".o" for n in own],
                                  *[str(objects[n]) for n in linked]], workdir)
    inputs = [(name, files[name]) for name in own] + [(f"{name} (object)", files[name]) for name in linked]
    build_cache.executable(build_cache.key(COMPILER, variant.flags, inputs), exe, build)
    try:
        done = build_cache.run([str(exe)], cwd=workdir, capture_output=True, text=True, timeout=RUN_TIMEOUT_S)
    except subprocess.TimeoutExpired as exc:
        raise VariantFailed(f"did not finish in {RUN_TIMEOUT_S} s") from exc
    if done.returncode != 0:
        raise VariantFailed(f"stopped with status {done.returncode}: {first_error(done.stderr + done.stdout)}")
    return done.stdout


def parse(stdout: str) -> dict:
    """The driver's (or the widened printed program's) output as legacy.cssp() gives it:
    ``table`` 37 x 12, ``inertia`` 6 x 2.  ``VariantFailed`` if it is not that."""
    rows: dict[str, list] = {"T": [], "I": []}
    for line in stdout.splitlines():
        fields = line.split()
        if fields and fields[0] == "ISTAT" and int(fields[1]) != 0:
            raise VariantFailed(f"CSSP ended with ISTAT = {fields[1]}")
        if fields and fields[0] in rows:
            try:
                rows[fields[0]].append([float(v) for v in fields[1:]])
            except ValueError as exc:
                raise VariantFailed(f"unreadable output line {line.strip()!r}") from exc
    try:
        table, inertia = np.array(rows["T"], dtype=float), np.array(rows["I"], dtype=float)
    except ValueError as exc:
        raise VariantFailed("ragged output") from exc
    if table.shape != (37, 12) or inertia.shape != (6, 2):
        raise VariantFailed(f"output has {table.shape} table and {inertia.shape} inertia cells, "
                            "expected (37, 12) and (6, 2)")
    return {"table": table, "inertia": inertia}


def tables_of(run: dict) -> dict[str, pd.DataFrame]:
    """A run as Tables 5.1-5.7, by the legacy engine's own ``as_tables``."""
    return as_tables(run)


# ---------------------------------------------------------------- the measurement

@dataclass
class Measurement:
    variants: list[Variant]
    values: dict[str, dict[str, pd.DataFrame]]           # variant -> table -> frame
    failures: dict[str, str] = field(default_factory=dict)
    seconds: float = 0.0

    @property
    def ran(self) -> list[Variant]:
        return [v for v in self.variants if v.name in self.values]


def measure(variants: tuple[Variant, ...] | list[Variant] = VARIANTS, workers: int | None = None,
            shared: tuple[str, ...] = (), on_done: Callable[[str], None] = lambda name: None) -> Measurement:
    """Build and run every variant (side by side on the cores); the first must run
    (``ReferenceFailed`` if not), the others are reported when they fail.  ``shared``: files
    (e.g. "driver.f") compiled once from the first variant, when a build not in the build cache
    first needs them, and linked into every variant with the same text of them and the same
    flags (variants that differ in one file).  ``on_done(name)``: called in this thread as each variant is built and run (or fails)."""
    require_compiler()
    variants = list(variants)
    start = time.perf_counter()
    workers = max(1, min(len(variants), workers or os.cpu_count() or 1))
    with tempfile.TemporaryDirectory(prefix="linkrepro-arith-") as tmp:
        try:
            common = Shared(variants[0], shared, Path(tmp) / ".shared") if shared else None
        except VariantFailed as exc:
            raise ReferenceFailed(f"the {variants[0].name} build failed: {exc}") from exc

        def one(variant: Variant):
            try:
                return variant.name, tables_of(parse(build_and_run(variant, Path(tmp) / variant.name, common)))
            except VariantFailed as exc:
                return variant.name, str(exc)
        with ThreadPoolExecutor(workers) as pool:
            futures = [pool.submit(one, variant) for variant in variants]
            for future in as_completed(futures):
                on_done(future.result()[0])
            done = dict(future.result() for future in futures)
    failures = {name: r for name, r in done.items() if isinstance(r, str)}
    if variants[0].name in failures:
        raise ReferenceFailed(f"the {variants[0].name} build failed: {failures[variants[0].name]}")
    values = {name: r for name, r in done.items() if not isinstance(r, str)}
    return Measurement(variants, values, failures, time.perf_counter() - start)
