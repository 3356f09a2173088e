"""Fuzz every public entry point with random and hostile arguments: the command.

Each thesis gives its entry points in ``harness/scenes/<thesis>/fuzz.py`` (``ENTRIES``,
``namespace()``, and where it has them ``SCRUBS``, ``CHECKS``, ``WARM_UP``), found through the
scene registry; the harness gives its own the same way (``harness/fuzz_folders.py``: damaged
run folders, verified and reported); ``harness/fuzz_calls.py`` generates the calls (valid values to the edges of the
domain, hostile values in their place), ``harness/fuzz_runner.py`` runs them in worker
processes and classifies each outcome (ok, typed, or a finding: untyped, nan, angle,
accepted, violated, crash, hang).

Usage::

    python -m linkrepro.harness.fuzz --calls 20000 --seed 0 --timeout 60 --out out/fuzz-0.json
    python -m linkrepro.harness.fuzz --replay "ali1977.loc(1, 1, nan, 1, 0)"

The same seed gives the same calls.  The exit status is 1 when there are findings.  A
progress line on standard error when it is a terminal (else a line every 1000 calls).
"""
from __future__ import annotations

import argparse
import math
import os
import sys
import time
import warnings
from typing import Callable

from . import fuzz_folders
from .fuzz_calls import generate as generate_calls, rand, spd
from .fuzz_runner import Context, Report, format_report, nonfinite, run as run_calls, write_report
from .progress import Bar
from .scenes import hook_modules

#: how a worker builds its names, scrubs, checks and warm-up (``context``)
CONTEXT = f"{__name__}:context"


def parts() -> list:
    """Each thesis's fuzz module, and the harness's own (``fuzz_folders``)."""
    return [*hook_modules("fuzz"), fuzz_folders]


def entries() -> list:
    """Every entry point: the theses' and the harness's."""
    return [entry for part in parts() for entry in part.ENTRIES]


def context() -> Context:
    """The names every call text may use (each thesis's ``namespace()``, and ``np``, ``nan``,
    ``inf``, ``rand``, ``spd``, linkrepro's errors; ``ANY_INPUTS`` and ``ANY_QUIRKS``: every
    thesis's dataclass and quirk instances, hostile values for the others), the scrubs, the
    checks and the warm-up calls of every thesis."""
    import numpy as np
    from linkrepro import errors
    names = {"np": np, "nan": math.nan, "inf": math.inf, "rand": rand, "spd": spd,
             **{name: getattr(errors, name) for name in ("AssemblyError", "ConvergenceError", "LinkageError",
                                                          "QPError", "SingularPositionError")}}
    inputs, quirks, scrubs, checks, warm = [], [], {}, {}, []
    for part in parts():
        own = dict(part.namespace())
        inputs += own.pop("inputs", ())
        quirks += own.pop("quirks", ())
        names.update(own)
        scrubs.update(getattr(part, "SCRUBS", {}))
        checks.update(getattr(part, "CHECKS", {}))
        warm += getattr(part, "WARM_UP", ())
    names.update(ANY_INPUTS=tuple(inputs), ANY_QUIRKS=tuple(quirks))
    return Context(names, scrubs, checks, tuple(warm))


def namespace() -> dict:
    """The names a call text may use (``context().namespace``)."""
    return context().namespace


def generate(calls: int, seed_value: int, only: str | None = None) -> list:
    """``calls`` jobs over every thesis's entry points (``fuzz_calls.generate``)."""
    return generate_calls(entries(), calls, seed_value, only)


def run(jobs: list, timeout: float = 20.0, workers: int = 2, progress=None) -> list:
    """Run the jobs in workers with every thesis's context (``fuzz_runner.run``)."""
    return run_calls(jobs, CONTEXT, timeout, workers, progress)


def fuzz(calls: int = 20_000, seed: int = 0, timeout: float = 60.0, workers: int | None = None,
         only: str | None = None, progress=None) -> Report:
    """Generate and run ``calls`` calls; the report."""
    workers = workers or min(2, len(os.sched_getaffinity(0)))
    jobs = generate(calls, seed, only)
    start = time.monotonic()
    results = run(jobs, timeout, workers, progress)
    return Report(jobs, results, time.monotonic() - start, seed, timeout, workers)


def replay(text: str) -> int:
    """Run one call text here, in this process, and print its result or traceback."""
    warnings.simplefilter("ignore")
    ns = namespace()
    result = eval(text, ns)                   # noqa: S307 - lets the traceback through
    print(repr(result)[:2000])
    where = nonfinite(result)
    print(f"non-finite: {where}" if where else "finite")
    return 0


def _shown(bar: Bar) -> Callable[[int, int], None]:
    """After each call: the progress line on a terminal (stderr); else a line every 1000 calls."""
    def step(done: int, total: int) -> None:
        bar.done("fuzz")
        if not bar.active and done % 1000 == 0:
            print(f"  {done}/{total} calls", file=sys.stderr, flush=True)
    return step


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m linkrepro.harness.fuzz", description=__doc__.split("\n")[0])
    parser.add_argument("--calls", type=int, default=20_000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per call")
    parser.add_argument("--workers", type=int, default=None, help="worker processes (default: 2 or the cores)")
    parser.add_argument("--only", help="entry points whose name contains this")
    parser.add_argument("--out", help="write the report: .json (everything) or .csv (the findings)")
    parser.add_argument("--all", action="store_true", help="print every finding, not one per group")
    parser.add_argument("--replay", metavar="CALL", help="run one call text in this process")
    args = parser.parse_args(argv)
    if args.replay:
        return replay(args.replay)
    with Bar(args.calls) as bar:
        bar.note("fuzz", "starting the workers (importing linkrepro)")
        report = fuzz(args.calls, args.seed, args.timeout, args.workers, args.only, progress=_shown(bar))
    print(format_report(report, args.all))
    if args.out:
        write_report(report, args.out)
    return 1 if report.findings else 0


if __name__ == "__main__":
    sys.exit(main())
