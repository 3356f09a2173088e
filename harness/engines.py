"""The four engines the harness runs for every scene.

``printed``         the listings exactly as printed (legacy/printed), built as the
                    standalone programs they are; run as subprocesses (``run_program``),
                    their WRITE output parsed by each thesis.  They only give what they print.
``legacy``          the cleaned listings (legacy/src) through f2py.
``port_printed``    the Python port with every quirk of the original on.
``port_corrected``  the Python port with every registered bug removed.
"""
from __future__ import annotations

import os
import subprocess
from pathlib import Path

ENGINES = ("printed", "legacy", "port_printed", "port_corrected")

BIN_DIR = Path(__file__).resolve().parent.parent / "legacy" / "bin"


#: a folder that holds the printed programs instead of the installed ones (e.g. a build of
#: your own); the CLI's tests point it at an empty folder to check the missing-program message
BIN_ENV = "LINKREPRO_PRINTED_BIN"


def program_path(program: str) -> Path:
    """Where a printed program is: in the folder named by ``$LINKREPRO_PRINTED_BIN`` if that is
    set, else installed beside the package (``legacy/bin``), or, in an editable install
    (``pip install --no-build-isolation -e .``), in meson's build folder."""
    override = os.environ.get(BIN_ENV)
    if override:
        return Path(override) / program
    exe = BIN_DIR / program
    if not exe.exists():
        built = sorted(BIN_DIR.parent.parent.glob(f"build/*/{program}"))
        exe = built[0] if built else exe
    return exe


class PrintedProgramError(RuntimeError):
    """A printed program could not be run or its output could not be read."""


def run_program(program: str, cwd: Path | None = None, timeout_s: float = 60.0) -> str:
    """Run one printed program (in ``cwd``, for programs that OPEN files); return its stdout.
    Every way it can fail (not built, not executable, killed, too slow) is a
    ``PrintedProgramError`` whose message names the program and the file."""
    exe = program_path(program)
    fix = (f"(${BIN_ENV} points there: unset it to use the installed programs)" if os.environ.get(BIN_ENV)
           else "reinstall the package (`pip install .`, or `make test` in a checkout)")
    if not exe.exists():
        raise PrintedProgramError(f"printed program {program!r} is not built: {exe} is missing; {fix}")
    try:
        done = subprocess.run([str(exe)], capture_output=True, text=True, timeout=timeout_s,
                              stdin=subprocess.DEVNULL, cwd=cwd)
    except subprocess.TimeoutExpired as exc:
        raise PrintedProgramError(f"printed program {program!r} did not finish in {timeout_s:g} s ({exe})") from exc
    except OSError as exc:                 # not executable, wrong format, ...
        raise PrintedProgramError(f"printed program {program!r} could not be started: {exe}: "
                                  f"{exc.strerror or exc}; {fix}") from exc
    if done.returncode != 0:
        status = (f"was killed by signal {-done.returncode}" if done.returncode < 0
                  else f"exited with status {done.returncode}")
        detail = " | ".join(line.strip() for line in done.stderr.splitlines() if line.strip())
        raise PrintedProgramError(f"printed program {program!r} {status} ({exe})" + (f": {detail}" if detail else ""))
    return done.stdout
