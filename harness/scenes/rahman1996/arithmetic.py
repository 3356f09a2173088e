"""Which digits survive a change of arithmetic: Rahman (1996) Tables 5.1-5.7 (register D056).

The legacy build (legacy/src, the FORTRAN the ``legacy`` engine runs) is rebuilt in a
temporary folder under each arithmetic a 1996 machine may have used: optimisation levels,
x87 extended intermediates (with and without ``-ffloat-store``, with the precision control
at 53 bits, with the x87's own SIN/COS/ATAN), fused multiply-add, REAL promoted to 64 bits,
and three ways of keeping the listing's literal constants in double (a source transform on
a temporary copy; legacy/ is never written).  Each build is run by a small driver that WRITEs
the whole TABLE and INERT of ``CSSP`` in full precision; the tables are formed by the same
``as_tables`` as the legacy engine's and compared with harness/published/ by the harness's
rule (within half a unit of the printed last digit, ``diff.py``).

Per variant and per table: the cells at the printed digit, within 1e-7 and 1e-6 relative
(``arithmetic.csv``); per cell: which variants reach the printed digit, how many distinct
values the variants give and whether every variant prints the same digits
(``arithmetic_cells.csv``).  A variant is adopted only if it stands for an arithmetic
documented for machines of the time AND raises the count in every one of Tables 5.2-5.7
without lowering Table 5.1 (issue 13, section 4): ``meets_criterion``.  None is adopted into
the default build here; the verdict is reported.

Needs gfortran on PATH (``readings.CompilerError`` otherwise) and the source tree's legacy/.
Run: ``linkrepro arithmetic --out out/arithmetic`` (17 builds, about 20 s of CPU: 10-12 s on two
free cores), not part of ``linkrepro reproduce``, whose report links the result when it is there.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd

from ... import progress
from ...csv_output import write_csv
from ...published_tables import PublishedTable
from ...readings import COMPILE_TIMEOUT_S, COMPILER, PRINTED_DIR, CompilerError
from .table_forms import as_tables

LEGACY_DIR = PRINTED_DIR.parent
SRC = ("src/rahman1996_cssp_main.f", "src/rahman1996_subroutines.f", "src/imsl_qprog.f")
PRINTED = ("printed/rahman1996_cssp_main.f", "printed/rahman1996_subroutines.f", "src/imsl_qprog.f")
MAIN = "rahman1996_cssp_main.f"
#: meson.build's fortran_legacy_args: the build of the legacy engine (a test holds them equal)
REFERENCE_FLAGS = ("-std=legacy", "-fno-automatic", "-ffp-contract=off", "-fno-fast-math",
                   "-fallow-argument-mismatch", "-O1")
TABLES = ("5_1", "5_2", "5_3", "5_4", "5_5", "5_6", "5_7")
#: the tables whose every count a variant must raise to be adopted (Table 5.1 must not drop)
SERIES = TABLES[1:]
RUN_TIMEOUT_S = 60
COMMAND = "linkrepro arithmetic --out out/arithmetic"
OUTPUTS = ("arithmetic.csv", "arithmetic_cells.csv", "arithmetic.md")

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


# ---------------------------------------------------------------- source transforms
# Fixed form: columns 1-6 label and continuation, 7-72 code; a C, c, * or ! in column 1
# is a comment.  Every transform works on a temporary copy and raises ValueError when the
# text it expects is not there (the listing changed: the variant must be looked at again).

_LITERAL = re.compile(r"(?<!\w)(\d+\.\d*|\.\d+|\d+(?=[EeDd][+-]?\d))([EeDd][+-]?\d+)?")
_DECL = re.compile(r"^\s*(?:REAL\s*\*\s*8|DOUBLE\s+PRECISION)\s+(.*)$", re.IGNORECASE)
_ASSIGN_LITERAL = re.compile(r"^(\s*)([A-Za-z]\w*)(\s*(?:\([^=]*\))?\s*=\s*[+-]?\s*)"
                             r"(\d+\.\d*|\.\d+)([Ee][+-]?\d+)?(\s*)$")


def _is_comment(line: str) -> bool:
    return not line.strip() or line[0] in "Cc*!"


def _split(line: str) -> tuple[str, str, str]:
    """(columns 1-6, code of columns 7-72 before any '!' comment, the rest)."""
    head, code = line[:6], line[6:72]
    bang = _bang(code)
    if bang >= 0:
        return head, code[:bang], code[bang:] + line[72:]
    return head, code, line[72:]


def _bang(code: str) -> int:
    """Where a '!' comment starts outside quotes, or -1."""
    quote = None
    for k, ch in enumerate(code):
        if quote:
            quote = None if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return k
    return -1


def _join(head: str, code: str, rest: str, original: str) -> str:
    if len(head) + len(code.rstrip()) > 72:
        raise ValueError(f"a promoted constant pushes code past column 72: {original.rstrip()!r}")
    return head + code.rstrip().ljust(66) + rest if rest else head + code.rstrip()


def _statements(lines: list[str]) -> list[list[int]]:
    """Line indices of each statement (initial line and its continuations)."""
    out: list[list[int]] = []
    for k, line in enumerate(lines):
        if _is_comment(line):
            continue
        if len(line) > 5 and line[5] not in " 0" and out:
            out[-1].append(k)
        else:
            out.append([k])
    return out


def _significant(mantissa: str) -> int:
    return len(mantissa.replace(".", "").lstrip("0"))


def _standalone(match: re.Match) -> bool:
    """Whether a match of _LITERAL is a whole real constant: not part of a name (K1X, F20.5),
    of a longer number or of an integer before an operator (1.AND.); after .GT. it is."""
    before, after = match.string[:match.start()], match.string[match.end():]
    if re.search(r"\w$", before) or re.match(r"\w|\.\d", after):
        return False
    return not before.endswith(".") or bool(re.search(r"\.[A-Za-z]+\.$", before))


def _as_double(text: str, mantissa: str, exponent: str | None) -> str:
    if exponent is None:
        return mantissa + "D0"
    return mantissa + "D" + exponent[1:] if exponent[0] in "Ee" else text


def _promote(text: str, keep: Callable[[str, str | None, str], bool]) -> str:
    """Every real literal of the code (not FORMAT, not inside quotes) for which
    keep(mantissa, exponent, statement) is false written as double (D exponent)."""
    lines = text.split("\n")
    for stmt in _statements(lines):
        whole = " ".join(_split(lines[k])[1] for k in stmt)
        if re.match(r"^\s*(\d+\s+)?FORMAT\s*\(", (lines[stmt[0]][:6] + whole).strip(), re.IGNORECASE):
            continue
        data = bool(re.match(r"^\s*DATA\b", whole, re.IGNORECASE))
        for k in stmt:
            head, code, rest = _split(lines[k])
            parts = re.split(r"('[^']*')", code)             # leave quoted text alone

            def one(match: re.Match) -> str:
                mantissa, exponent = match.group(1), match.group(2)
                if not _standalone(match):
                    return match.group(0)
                if exponent and exponent[0] in "Dd":
                    return match.group(0)                    # already double
                if keep(mantissa, exponent, "data" if data else whole):
                    return match.group(0)
                return _as_double(match.group(0), mantissa, exponent)

            new = "".join(p if p.startswith("'") else _LITERAL.sub(one, p) for p in parts)
            if new != code:
                lines[k] = _join(head, new, rest, lines[k])
    return "\n".join(lines)


def _exact_in_single(mantissa: str, exponent: str | None) -> bool:
    value = float(mantissa + (("E" + exponent[1:]) if exponent else ""))
    return float(np.float32(value)) == value


def long_constants_double(files: dict[str, str]) -> dict[str, str]:
    """Literal constants of more than seven significant digits written as double."""
    out = dict(files)
    for name in (MAIN, "rahman1996_subroutines.f"):
        out[name] = _promote(files[name], lambda m, e, s: _significant(m) <= 7)
    if out == files:
        raise ValueError("no literal constant of more than seven significant digits found")
    return out


def all_constants_double(files: dict[str, str]) -> dict[str, str]:
    """Every literal real constant of the listing as double (in DATA, where the variable's
    type decides, only those a REAL*4 cannot hold exactly)."""
    out = dict(files)
    for name in (MAIN, "rahman1996_subroutines.f"):
        out[name] = _promote(files[name], lambda m, e, s: s == "data" and _exact_in_single(m, e))
    return out


def _real8_names(text: str) -> set[str]:
    lines = text.split("\n")
    names: set[str] = set()
    for stmt in _statements(lines):
        whole = " ".join(_split(lines[k])[1] for k in stmt)
        match = _DECL.match(whole)
        if match:
            flat = match.group(1)
            while re.search(r"\([^()]*\)", flat):
                flat = re.sub(r"\([^()]*\)", "", flat)
            names |= {n.strip().upper() for n in flat.split(",") if re.fullmatch(r"\s*[A-Za-z]\w*\s*", n)}
    return names


def context_constants(files: dict[str, str]) -> dict[str, str]:
    """A literal constant assigned directly to a REAL*8 variable taken as double (what the
    g77 manual calls context-sensitive constants: 'many other compilers' did it)."""
    out = dict(files)
    changed = 0
    for name in (MAIN, "rahman1996_subroutines.f"):
        lines = files[name].split("\n")
        real8 = _real8_names(files[name])
        for k, line in enumerate(lines):
            if _is_comment(line) or (len(line) > 5 and line[5] not in " 0"):
                continue
            head, code, rest = _split(line)
            match = _ASSIGN_LITERAL.match(code)
            if match and match.group(2).upper() in real8:
                new = (match.group(1) + match.group(2) + match.group(3)
                       + _as_double(match.group(4) + (match.group(5) or ""), match.group(4), match.group(5))
                       + match.group(6))
                lines[k] = _join(head, new, rest, line)
                changed += 1
        out[name] = "\n".join(lines)
    if not changed:
        raise ValueError("no literal constant assigned to a REAL*8 variable found")
    return out


#: (text expected exactly once in the main program, its replacement)
_SELECTED = (("      PARAMETER (G=386.4,", "      REAL*8 G\n      PARAMETER (G=386.4D0,"),
             ("      PI=4.0*ATAN(1.0)\n", "      PI=4.0D0*ATAN(1.0D0)\n"),
             ("      M1=1.9/G\n", "      M1=1.9D0/G\n"),
             ("      M2=7.6/G\n", "      M2=7.6D0/G\n"),
             ("      M3=6.0/G\n", "      M3=6.0D0/G\n"))


def _replace_each_once(files: dict[str, str], pairs, where: str) -> dict[str, str]:
    """``files`` with each (old, new) of ``pairs`` replaced in the main program, where ``old``
    must occur exactly once (ValueError naming ``where`` otherwise)."""
    text = files[MAIN]
    for old, new in pairs:
        if text.count(old) != 1:
            raise ValueError(f"{where}: {old.strip()!r} occurs {text.count(old)} times, expected once")
        text = text.replace(old, new)
    return {**files, MAIN: text}


def selected_real8(files: dict[str, str]) -> dict[str, str]:
    """G, PI and M1..M3 = W/G in REAL*8 with double constants (a what-if: the quantities
    the listing declares REAL*8 but computes from REAL*4 constants)."""
    return _replace_each_once(files, _SELECTED, MAIN)


#: the printed main program's three I/O statements, made to WRITE every cell (as-printed)
_PRINTED_IO = (("      OPEN (6,FILE='dint.dat',STATUS='new')\n", "C     OPEN: TO STANDARD OUTPUT\n"),
               ("      write(6,*) TH1,dint\n",
                "      write(6,'(A,12ES26.17E3)') ' T',OBJFUN,NUOBJFUN,shf,nushf,\n"
                "     1 sht,nusht,brf,nubrf,brt,nubrt,int,nuint\n"),
               ("      write(6,*) I1X,NUI1X\n",
                "".join(f"      write(6,'(A,2ES26.17E3)') ' I',{a},NU{a}\n"
                        for a in ("I1X", "I1Y", "I1Z", "I2X", "I2Y", "I2Z"))))


def printed_output(files: dict[str, str]) -> dict[str, str]:
    """The listing as printed, its WRITEs widened to every cell in full precision."""
    return _replace_each_once(files, _PRINTED_IO, f"printed {MAIN}")


# ---------------------------------------------------------------- the variants

@dataclass(frozen=True)
class Variant:
    name: str
    machine: str                                 # the 1996-era machine or compiler it stands for
    documented: bool                             # an arithmetic documented for machines of the time
    extra: tuple[str, ...] = ()                  # gfortran flags after the reference's (later wins)
    transform: Callable[[dict[str, str]], dict[str, str]] | None = None
    source: str = "src"                          # "src" (legacy/src + driver) or "printed"
    keeps_types: bool = True                     # every variable and constant keeps its declared precision
    flags_base: tuple[str, ...] = REFERENCE_FLAGS

    @property
    def flags(self) -> tuple[str, ...]:
        return tuple(self.flags_base) + tuple(self.extra)

    @property
    def how(self) -> str:
        parts = [" ".join(self.extra)] if self.extra else []
        if self.transform is not None:
            parts.append(f"source: {self.transform.__name__}")
        if self.source == "printed":
            parts.append("legacy/printed")
        return "; ".join(parts) or "meson.build's flags"


_X87 = ("-mfpmath=387",)
VARIANTS: tuple[Variant, ...] = (
    Variant("reference", "IEEE single and double, every operation rounded to its declared type "
            "(RISC workstations: Sun SPARC f77, HP PA-RISC, SGI MIPS, DEC Alpha); the legacy engine's build", True),
    Variant("O0", "the same machine, unoptimised (f77 without -O, a debugging build)", True, ("-O0",)),
    Variant("O2", "the same machine, f77 -O2", True, ("-O2",)),
    Variant("x87", "Intel 486/Pentium PC, x87 80-bit registers with the precision control at 64 bits "
            "(the power-on default that DOS-extender and Linux compilers, e.g. g77, kept)", True, _X87),
    Variant("x87-float-store", "the same PC, every variable stored to memory in its own type "
            "(g77 -ffloat-store, the documented cure of x87 excess precision)", True, _X87 + ("-ffloat-store",)),
    Variant("x87-O0", "the same PC, unoptimised (results stored after each statement)", True, _X87 + ("-O0",)),
    Variant("x87-pc53", "a PC with the x87 precision control at 53 bits (the default control word of "
            "Win32 programs, e.g. Microsoft FORTRAN PowerStation)", True, _X87 + ("-mpc64",)),
    Variant("x87-intrinsics", "a PC compiler that inlines SIN, COS, ATAN, SQRT as the x87's FSIN, FCOS, "
            "FPATAN, FSQRT (gcc ties this to -funsafe-math-optimizations, e.g. X**0.5 as SQRT)", True,
            _X87 + ("-funsafe-math-optimizations", "-fno-associative-math", "-fno-reciprocal-math",
                    "-fsigned-zeros", "-ftrapping-math")),
    Variant("fma", "IBM RS/6000 POWER, xlf -O (multiply-add fused by default, -qmaf; also HP PA-8000); "
            "-O2 because gcc forms FMAs only from -O2", True, ("-O2", "-mfma", "-ffp-contract=fast")),
    Variant("real8", "REAL as 64 bits: Cray (64-bit REAL, though not IEEE), the -r8 switch of f77 "
            "(4.3BSD 1985, Sun, DEC), xlf -qautodbl", True,
            ("-fdefault-real-8", "-fdefault-double-8"), keeps_types=False),
    Variant("long-constants-double", "literal constants of more than seven digits kept in double "
            "(1.1636867, 2.3139072, 4.6210569): the issue's hypothesis; no compiler found documented "
            "to decide by the count of digits", False, transform=long_constants_double, keeps_types=False),
    Variant("context-constants", "a constant assigned to a REAL*8 variable taken as double, "
            "W/G and 4.0*ATAN(1.0) left single (the g77 manual, 'Context-Sensitive Constants': "
            "what 'many other compilers' of its time did)", True, transform=context_constants, keeps_types=False),
    Variant("context-constants-x87", "the same constants on the x87 PC (80-bit registers)", True,
            _X87, transform=context_constants, keeps_types=False),
    Variant("context-constants-fma", "the same constants on the RS/6000 (xlf -O, fused multiply-add)", True,
            ("-O2", "-mfma", "-ffp-contract=fast"), transform=context_constants, keeps_types=False),
    Variant("all-constants-double", "every literal constant as double (Sun f77 -r8const, "
            "HP f90 +real_constant=double; options read in later manuals)", True,
            transform=all_constants_double, keeps_types=False),
    Variant("selected-real8", "what-if, no machine: G, PI, M1..M3 = W/G in REAL*8 with double constants",
            False, transform=selected_real8, keeps_types=False),
    Variant("as-printed", "not an arithmetic: the listing as printed (link PARAMETERs the compiler "
            "folds), reference flags", False, transform=printed_output, source="printed"),
)


def get(name: str) -> Variant:
    return next(v for v in VARIANTS if v.name == name)


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


def _first_error(stderr: str) -> str:
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    return next((line for line in lines if "error" in line.lower()), lines[-1] if lines else "no message")


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
        raise VariantFailed(f"does not build: {_first_error(exc.stderr)}") from exc
    except subprocess.TimeoutExpired as exc:
        raise VariantFailed(f"{COMPILER} did not finish in {COMPILE_TIMEOUT_S} s") from exc
    except OSError as exc:
        raise CompilerError(f"{COMPILER} could not be run: {exc.strerror or exc}") from exc


def prebuild(variant: Variant, names: tuple[str, ...], workdir: Path) -> dict[str, tuple[str, Path, tuple]]:
    """These files of a variant compiled once to object files with its flags: for
    ``build_and_run``'s ``prebuilt`` (name: (text, object, flags)).  ``VariantFailed`` if not."""
    workdir.mkdir(parents=True, exist_ok=True)
    files = _transformed(variant)
    for name in names:
        (workdir / name).write_text(files[name])
    _gfortran(variant.flags, ["-c", *names], workdir)
    return {name: (files[name], workdir / (Path(name).stem + ".o"), variant.flags) for name in names}


def build_and_run(variant: Variant, workdir: Path, prebuilt: dict[str, tuple[str, Path, tuple]] | None = None) -> str:
    """Build one variant in ``workdir`` and return its standard output.  A file whose text
    and flags are those of a ``prebuilt`` object (``prebuild``) is linked from it, not compiled.
    ``VariantFailed`` if it does not build or run; ``CompilerError`` if gfortran cannot run."""
    workdir.mkdir(parents=True, exist_ok=True)
    files = _transformed(variant)
    order = ["driver.f", MAIN] + [n for n in files if n not in ("driver.f", MAIN)]
    names = [n for n in order if n in files]
    linked = {n: obj for n, (text, obj, flags) in (prebuilt or {}).items()
              if files.get(n) == text and flags == variant.flags}
    for name in names:
        if name not in linked:
            (workdir / name).write_text(files[name])
    exe = workdir / "cssp"
    _gfortran(variant.flags, ["-o", str(exe), *[n for n in names if n not in linked],
                              *[str(linked[n]) for n in names if n in linked]], workdir)
    try:
        done = subprocess.run([str(exe)], cwd=workdir, capture_output=True, text=True, timeout=RUN_TIMEOUT_S)
    except subprocess.TimeoutExpired as exc:
        raise VariantFailed(f"did not finish in {RUN_TIMEOUT_S} s") from exc
    if done.returncode != 0:
        raise VariantFailed(f"stopped with status {done.returncode}: {_first_error(done.stderr + done.stdout)}")
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
    (e.g. "driver.f") compiled once from the first variant and linked into every variant
    with the same text of them and the same flags (variants that differ in one file).
    ``on_done(name)``: called in this thread as each variant is built and run (or fails)."""
    require_compiler()
    variants = list(variants)
    start = time.perf_counter()
    workers = max(1, min(len(variants), workers or os.cpu_count() or 1))
    with tempfile.TemporaryDirectory(prefix="linkrepro-arith-") as tmp:
        try:
            prebuilt = prebuild(variants[0], shared, Path(tmp) / ".shared") if shared else None
        except VariantFailed as exc:
            raise ReferenceFailed(f"the {variants[0].name} build failed: {exc}") from exc

        def one(variant: Variant):
            try:
                return variant.name, tables_of(parse(build_and_run(variant, Path(tmp) / variant.name, prebuilt)))
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


def _published(table: str) -> PublishedTable:
    return PublishedTable.load(f"rahman1996_table{table}")


def _cells(table: str) -> tuple[pd.DataFrame, list[str], list[str]]:
    """(published values, the value columns, each row's name as the harness writes it)."""
    pub = _published(table)
    if table == "5_1":
        names = [f"{a}/{b}" for a, b in zip(pub.text["link"], pub.text["quantity"])]
    else:
        names = [str(int(v)) for v in pub.values["crank_deg"]]
    return pub, ["before", "after"], names


def _decimals(half: float) -> int:
    return int(round(-np.log10(2.0 * half)))


def cell_frame(m: Measurement) -> pd.DataFrame:
    """One row per published cell: reference value, per variant value and whether it is
    at the printed digit, and the summary columns (see ``as_markdown``)."""
    rows = []
    ran = m.ran
    ref = ran[0].name
    rounding = [ref] + [v.name for v in ran[1:] if v.keeps_types]
    for table in TABLES:
        pub, cols, names = _cells(table)
        values, half, text = pub.values, pub.half_unit, pub.text
        for name in [v.name for v in ran]:
            frame = m.values[name][table]
            if table == "5_1":
                same = [f"{x}/{y}" for x, y in zip(frame["link"], frame["quantity"])] == names
            else:
                same = np.array_equal(frame["crank_deg"].to_numpy(float), values["crank_deg"].to_numpy(float))
            if not same:
                raise ReferenceFailed(f"Table {table}: the rows of variant {name} are not the published rows")
        for i, row in enumerate(names):
            for col in cols:
                target, tol = float(values.at[i, col]), float(half.at[i, col])
                got = {v.name: float(m.values[v.name][table].at[i, col]) for v in ran}
                at = {n: abs(x - target) <= tol * (1.0 + 1e-9) for n, x in got.items()}
                d = _decimals(tol)
                printed_as = {n: f"{round(x, d):.{d}f}" for n, x in got.items()}
                same = len(set(printed_as.values())) == 1
                same_rounding = len({printed_as[n] for n in rounding}) == 1
                spread = max(got.values()) - min(got.values())
                spread_rounding = max(got[n] for n in rounding) - min(got[n] for n in rounding)
                reached = [n for n in got if at[n]]
                record = {"table": table.replace("_", "."), "row": row, "column": col,
                          "published_text": text.at[i, col], "published": target, "half_unit": tol,
                          "reference": got[ref], "reference_rel_err": abs(got[ref] - target) / abs(target),
                          "reached_by": " ".join(reached), "n_reached": len(reached), "n_variants": len(got),
                          "distinct_values": len(set(got.values())),
                          "rel_spread": spread / abs(got[ref]) if got[ref] else np.nan,
                          "rel_spread_rounding": spread_rounding / abs(got[ref]) if got[ref] else np.nan,
                          "same_printed_digits": same, "same_printed_digits_rounding": same_rounding,
                          "sensitivity": ("always" if len(reached) == len(got) else
                                          "never" if not reached else "compiler-sensitive")}
                record.update({f"value:{n}": x for n, x in got.items()})
                rows.append(record)
    return pd.DataFrame(rows)


def count_frame(m: Measurement, cells: pd.DataFrame | None = None) -> pd.DataFrame:
    """One row per variant and table (and an 'all' row per variant): cells at the printed
    digit, within 1e-7 and 1e-6 relative, and cells whose value differs from the reference."""
    cells = cell_frame(m) if cells is None else cells
    ref = m.ran[0].name
    rows = []
    for v in m.ran:
        value = cells[f"value:{v.name}"]
        rel = (value - cells["published"]).abs() / cells["published"].abs()
        frame = pd.DataFrame({"table": cells["table"],
                              "at": (value - cells["published"]).abs() <= cells["half_unit"] * (1.0 + 1e-9),
                              "r7": rel <= 1e-7, "r6": rel <= 1e-6,
                              "changed": value != cells[f"value:{ref}"],
                              "move": (value - cells[f"value:{ref}"]).abs() / cells[f"value:{ref}"].abs()})
        for table, part in list(frame.groupby("table", sort=True)) + [("all", frame)]:
            rows.append({"variant": v.name, "table": table, "cells": len(part),
                         "at_printed_digit": int(part["at"].sum()), "within_1e-7": int(part["r7"].sum()),
                         "within_1e-6": int(part["r6"].sum()), "cells_changed": int(part["changed"].sum()),
                         "max_rel_change": float(part["move"].max()), "documented": v.documented})
    counts = pd.DataFrame(rows)
    base = counts[counts["variant"] == ref].set_index("table")["at_printed_digit"]
    counts["gain"] = counts["at_printed_digit"] - counts["table"].map(base)
    return counts


def meets_criterion(counts: pd.DataFrame) -> dict[str, bool]:
    """Per variant: documented for machines of the time, raises the count in every one of
    Tables 5.2-5.7 and does not lower Table 5.1 (issue 13, section 4)."""
    out = {}
    for name, part in counts.groupby("variant", sort=False):
        gain = part.set_index("table")["gain"]
        out[name] = bool(part["documented"].iloc[0]
                         and all(gain[t.replace("_", ".")] > 0 for t in SERIES) and gain["5.1"] >= 0)
    return out


def report_link(out_dir: Path) -> list[str]:
    """Lines for reproduce's report.md when ``linkrepro arithmetic`` has written DIR/arithmetic/."""
    if not (Path(out_dir) / "arithmetic" / "arithmetic.md").is_file():
        return ["## Which digits survive a change of arithmetic", "",
                f"Not measured in this run: `linkrepro arithmetic --out {Path(out_dir) / 'arithmetic'}` rebuilds "
                "Rahman (1996) Tables 5.1-5.7 under the arithmetics of 1996 machines (about 20 s of CPU; "
                "`make reproduce` runs it) and this report then links its matrix (register D056).", ""]
    return ["## [Which digits survive a change of arithmetic](arithmetic/arithmetic.md)", "",
            "Rahman (1996) Tables 5.1-5.7 rebuilt under the arithmetics of 1996 machines, per variant "
            "and per cell (written by `linkrepro arithmetic`; register D056).", ""]


def _closest(m: Measurement, counts: pd.DataFrame) -> str:
    """One sentence on the documented variant with the most cells at the printed digit."""
    ref = m.ran[0].name
    total = counts[(counts["table"] == "all") & counts["documented"] & (counts["variant"] != ref)]
    if total.empty:
        return ""
    best = total.sort_values("at_printed_digit", ascending=False, kind="stable").iloc[0]
    part = counts[(counts["variant"] == best["variant"]) & (counts["table"] != "all")].set_index("table")
    base = counts[(counts["variant"] == ref) & (counts["table"] == "all")]["at_printed_digit"].iloc[0]
    gains = ", ".join(f"{t} {int(g):+d}" for t, g in part["gain"].items())
    flat = [t for t, g in part["gain"].items() if g == 0]
    return (f"Closest documented variant: **{best['variant']}**, {int(best['at_printed_digit'])} cells at the "
            f"printed digit against {int(base)} for {ref} (per table: {gains})"
            + (f"; it does not raise {', '.join(flat)}" if flat else "") + ".")


def _rows_list(part: pd.DataFrame) -> str:
    out = []
    for col, sub in part.groupby("column", sort=False):
        out.append(f"{col} {', '.join(sub['row'])}")
    return "; ".join(out)


def as_markdown(m: Measurement, counts: pd.DataFrame, cells: pd.DataFrame) -> str:
    ref = m.ran[0].name
    verdict = meets_criterion(counts)
    adopted = [n for n, ok in verdict.items() if ok]
    lines = ["## Which digits survive a change of arithmetic (register D056)", "",
             f"The legacy FORTRAN (legacy/src) rebuilt under {len(m.variants)} arithmetics a 1996 machine "
             f"may have used, each run once; its Tables 5.1-5.7 ({len(cells)} cells) against the published "
             "digits. Re-measure: `" + COMMAND + "`; per-variant counts in arithmetic.csv, the per-cell "
             "matrix in arithmetic_cells.csv.", "",
             "The seed (000, Rahman 1996) names no computer or compiler; it names only the IMSL routines "
             "QPROG and UMACH (chapter 4, Appendix B), whose single-precision QPROG the listing calls "
             "with REAL arrays. The variants stand for the machines below; 'documented' means the "
             "arithmetic is described for compilers of the time.", "",
             "| variant | how | stands for | documented |", "|---|---|---|---|"]
    lines += [f"| {v.name} | `{v.how}` | {v.machine} | {'yes' if v.documented else 'no'} |" for v in m.variants]
    if m.failures:
        lines += ["", "Not run on this machine: " + "; ".join(f"{n} ({why})" for n, why in m.failures.items()) + "."]
    head = [t.replace("_", ".") for t in TABLES]
    lines += ["", "### Cells at the printed digit, per variant and table", "",
              "| variant | " + " | ".join(head) + " | all | within 1e-7 | within 1e-6 | cells changed | "
              "largest change (rel) | tables raised / lowered | 'before' / 'after' cells | adopt? |",
              "|---|" + "---|" * (len(head) + 8)]
    by_column = {v.name: {col: int(sum(v.name in str(r).split() for r in part["reached_by"]))
                          for col, part in cells.groupby("column")} for v in m.ran}
    for v in m.ran:
        part = counts[counts["variant"] == v.name].set_index("table")
        ncells = part["cells"]
        lines.append(f"| {v.name} | " + " | ".join(f"{part.at[t, 'at_printed_digit']}/{ncells[t]}" for t in head)
                     + f" | {part.at['all', 'at_printed_digit']}/{ncells['all']} | {part.at['all', 'within_1e-7']}"
                     f" | {part.at['all', 'within_1e-6']} | {part.at['all', 'cells_changed']}"
                     f" | {part.at['all', 'max_rel_change']:.1e} | {(part.loc[head, 'gain'] > 0).sum()} / "
                     f"{(part.loc[head, 'gain'] < 0).sum()} | {by_column[v.name].get('before', 0)} / "
                     f"{by_column[v.name].get('after', 0)} | {'yes' if verdict[v.name] else 'no'} |")
    lines += ["", "**Criterion** (issue 13): a variant is adopted only if its arithmetic is documented for "
              "machines of the time and it raises the count in every one of Tables 5.2-5.7 without "
              "lowering Table 5.1; never cell by cell. "
              + (f"Met by: {', '.join(adopted)} (not adopted into the default build here: the register decides)."
                 if adopted else "Met by no variant: the default build stays as it is.")]
    closest = _closest(m, counts)
    if closest:
        lines += ["", closest]
    sens = cells.groupby("table")["sensitivity"].value_counts().unstack(fill_value=0)
    sens = sens.reindex(columns=["always", "compiler-sensitive", "never"], fill_value=0)
    same = cells.groupby("table")["same_printed_digits"].sum()
    same_r = cells.groupby("table")["same_printed_digits_rounding"].sum()
    rounding = ", ".join(v.name for v in m.ran if v.keeps_types)
    lines += ["", "### Which cells are sensitive to the compiler at all", "",
              "Per table: cells at the printed digit under every variant (always), under some "
              "(compiler-sensitive), under none (never); and cells whose printed digits (rounded to the "
              "published decimals) are the same under every variant that keeps the program's types "
              f"({rounding}: a change of compiler, optimisation or floating-point unit) and under every "
              "variant. Those are the digits an archival regression test may hold fixed across compilers.", "",
              "| table | cells | always | compiler-sensitive | never | same printed digits, types kept | "
              "same printed digits, every variant |", "|---|---|---|---|---|---|---|"]
    for table, row in sens.iterrows():
        lines.append(f"| {table} | {int(row.sum())} | {row['always']} | {row['compiler-sensitive']} | "
                     f"{row['never']} | {int(same_r[table])} | {int(same[table])} |")
    lines.append(f"| all | {len(cells)} | {int(sens['always'].sum())} | {int(sens['compiler-sensitive'].sum())} | "
                 f"{int(sens['never'].sum())} | {int(same_r.sum())} | {int(cells['same_printed_digits'].sum())} |")
    moved = cells[cells["distinct_values"] > 1]
    lines += ["", f"{len(moved)} of {len(cells)} cells take more than one value across the variants; the largest "
              f"spread is {cells['rel_spread'].max():.1e} relative (median over those cells "
              f"{moved['rel_spread'].median() if len(moved) else 0.0:.1e}); over the variants that keep the "
              f"types, {cells['rel_spread_rounding'].max():.1e} (median "
              f"{cells['rel_spread_rounding'].median():.1e}).", "",
              "Compiler-sensitive cells (the printed digit is reached under some arithmetics and not others):", ""]
    sensitive = cells[cells["sensitivity"] == "compiler-sensitive"]
    for table, part in sensitive.groupby("table"):
        lines.append(f"- {table}: {_rows_list(part)}")
    if sensitive.empty:
        lines.append("- none")
    flipped = cells[~cells["same_printed_digits_rounding"]]
    lines += ["", "Cells whose printed digits change under a variant that keeps the types (a change of compiler "
              "alone):", ""]
    lines += [f"- {table}: {_rows_list(part)}" for table, part in flipped.groupby("table")] or ["- none"]
    lines += ["", f"Reference: `{ref}` (meson.build's flags), the legacy engine's own build; {m.seconds:.1f} s "
              "for the builds and runs of this measurement."]
    return "\n".join(lines)


def write(out_dir: Path, variants=VARIANTS) -> tuple[Measurement, pd.DataFrame, pd.DataFrame, str]:
    """Measure and write DIR/arithmetic.csv, DIR/arithmetic_cells.csv, DIR/arithmetic.md; a
    progress line over the builds on standard error when it is a terminal."""
    variants = list(variants)
    with progress.Bar(len(variants)):
        progress.note("arithmetic", "gfortran builds and runs")
        m = measure(variants, on_done=progress.done)
    cells = cell_frame(m)
    counts = count_frame(m, cells)
    text = as_markdown(m, counts, cells)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    write_csv(counts, out_dir / "arithmetic.csv", "%.9g")
    write_csv(cells, out_dir / "arithmetic_cells.csv", "%.17g")
    (out_dir / "arithmetic.md").write_text("# Rahman (1996): which digits survive a change of arithmetic\n\n"
                                           + text.split("\n", 1)[1].lstrip() + "\n")
    return m, counts, cells, text


if __name__ == "__main__":                 # python -m linkrepro.harness.scenes.rahman1996.arithmetic [DIR]
    import sys
    print(write(Path(sys.argv[1] if len(sys.argv) > 1 else "out/arithmetic"))[3])
