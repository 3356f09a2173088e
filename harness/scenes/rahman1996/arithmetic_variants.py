"""The arithmetic study's variants (``arithmetic.py``): each arithmetic a 1996 machine may have
used for the Rahman (1996) program, as gfortran flags and source transforms on a temporary
copy of the listing (legacy/ is never written)."""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ....legacy import fixed_form
from ...readings import COMPILER, LEGACY_FLAGS, family

MAIN = "rahman1996_cssp_main.f"
#: meson.build's fortran_legacy_args for the run-time compiler (``readings.COMPILER``): the build of
#: the legacy engine (a test holds them equal); the variants' extra flags are gfortran's
REFERENCE_FLAGS = LEGACY_FLAGS[family(COMPILER)]

# ---------------------------------------------------------------- source transforms
# Fixed form: columns 1-6 label and continuation, 7-72 code; a C, c, * or ! in column 1
# is a comment.  Every transform works on a temporary copy and raises ValueError when the
# text it expects is not there (the listing changed: the variant must be looked at again).

_LITERAL = re.compile(r"(?<!\w)(\d+\.\d*|\.\d+|\d+(?=[EeDd][+-]?\d))([EeDd][+-]?\d+)?")
_split, _join, _statements, _as_double = fixed_form.split, fixed_form.join, fixed_form.statements, fixed_form.as_double


def _significant(mantissa: str) -> int:
    return len(mantissa.replace(".", "").lstrip("0"))


def _standalone(match: re.Match) -> bool:
    """Whether a match of _LITERAL is a whole real constant: not part of a name (K1X, F20.5),
    of a longer number or of an integer before an operator (1.AND.); after .GT. it is."""
    before, after = match.string[:match.start()], match.string[match.end():]
    if re.search(r"\w$", before) or re.match(r"\w|\.\d", after):
        return False
    return not before.endswith(".") or bool(re.search(r"\.[A-Za-z]+\.$", before))


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
    """Only the literal constants of more than seven significant digits written as double (the
    others REAL*4: ``single_constants`` first)."""
    single = single_constants(files)
    out = dict(single)
    for name in (MAIN, "rahman1996_subroutines.f"):
        out[name] = _promote(single[name], lambda m, e, s: _significant(m) <= 7)
    if out == single:
        raise ValueError("no literal constant of more than seven significant digits found")
    return out


def all_constants_double(files: dict[str, str]) -> dict[str, str]:
    """Every literal real constant of the listing as double (in DATA, where the variable's
    type decides, only those a REAL*4 cannot hold exactly)."""
    out = dict(files)
    for name in (MAIN, "rahman1996_subroutines.f"):
        out[name] = _promote(files[name], lambda m, e, s: s == "data" and _exact_in_single(m, e))
    return out


def context_constants(files: dict[str, str]) -> dict[str, str]:
    """A literal constant assigned directly to a REAL*8 variable taken as double (what the
    g77 manual calls context-sensitive constants, ``fixed_form.context_constants``): the
    arithmetic D180 adopts, for the listing as printed."""
    out = dict(files)
    changed = 0
    for name in (MAIN, "rahman1996_subroutines.f"):
        out[name], n = fixed_form.context_constants(files[name])
        changed += n
    if not changed:
        raise ValueError("no literal constant assigned to a REAL*8 variable found")
    return out


#: the register entry whose tag marks legacy/src's constants written as double (D180)
ADOPTED = "D180"
_TAGGED_DOUBLE = re.compile(r"(?<![\w.])(\d+\.\d*|\.\d+)D0(?!\w)")


def single_constants(files: dict[str, str]) -> dict[str, str]:
    """The D180 edit undone: the literals of legacy/src's lines tagged D180 back in REAL*4, as the
    standard reads a constant without a D exponent wherever it stands (g77 and gfortran)."""
    lines = files[MAIN].split("\n")
    changed = 0
    for k, line in enumerate(lines):
        head, code, rest = _split(line)
        if rest.strip() == f"! {ADOPTED}":
            new = _TAGGED_DOUBLE.sub(r"\1", code)
            changed += new != code
            lines[k] = _join(head, new, rest, line)
    if not changed:
        raise ValueError(f"no literal written as double on a line of {MAIN} tagged {ADOPTED}")
    return {**files, MAIN: "\n".join(lines)}


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
    """The listing as printed, its constants read as the 1996 compiler read them (D180:
    ``context_constants``, as meson.build builds the printed engine), its WRITEs widened to
    every cell in full precision."""
    return _replace_each_once(context_constants(files), _PRINTED_IO, f"printed {MAIN}")


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
_FMA = ("-O2", "-mfma", "-ffp-contract=fast")
VARIANTS: tuple[Variant, ...] = (
    Variant("reference", "the adopted arithmetic (register D180): a literal assigned to a REAL*8 variable "
            "taken as double (the g77 manual's 'context-sensitive constants', which 'many other Fortran "
            "compilers' did; DEC's and Intel's /fpconstant, 'compatibility with FORTRAN 77'), every operation "
            "rounded to its declared type (IEEE: Sun SPARC f77, HP PA-RISC, SGI MIPS, DEC Alpha); "
            "the legacy engine's build", True),
    Variant("O0", "the same constants, unoptimised (f77 without -O, a debugging build)", True, ("-O0",)),
    Variant("O2", "the same constants, f77 -O2", True, ("-O2",)),
    Variant("x87", "the same constants on an Intel 486/Pentium PC, x87 80-bit registers with the precision "
            "control at 64 bits (the power-on default that DOS-extender and Linux compilers kept)", True, _X87),
    Variant("x87-float-store", "the same PC, every variable stored to memory in its own type "
            "(g77 -ffloat-store, the documented cure of x87 excess precision)", True, _X87 + ("-ffloat-store",)),
    Variant("x87-O0", "the same PC, unoptimised (results stored after each statement)", True, _X87 + ("-O0",)),
    Variant("x87-pc53", "a PC with the x87 precision control at 53 bits (the default control word of "
            "Win32 programs, e.g. Microsoft FORTRAN PowerStation)", True, _X87 + ("-mpc64",)),
    Variant("x87-intrinsics", "a PC compiler that inlines SIN, COS, ATAN, SQRT as the x87's FSIN, FCOS, "
            "FPATAN, FSQRT (gcc ties this to -funsafe-math-optimizations, e.g. X**0.5 as SQRT)", True,
            _X87 + ("-funsafe-math-optimizations", "-fno-associative-math", "-fno-reciprocal-math",
                    "-fsigned-zeros", "-ftrapping-math")),
    Variant("fma", "the same constants on an IBM RS/6000 POWER, xlf -O (multiply-add fused by default, -qmaf; "
            "also HP PA-8000); -O2 because gcc forms FMAs only from -O2", True, _FMA),
    Variant("real8", "REAL as 64 bits: Cray (64-bit REAL, though not IEEE), the -r8 switch of f77 "
            "(4.3BSD 1985, Sun, DEC), xlf -qautodbl", True,
            ("-fdefault-real-8", "-fdefault-double-8"), keeps_types=False),
    Variant("single-constants", "the standard's reading: a literal without a D exponent is REAL*4 wherever "
            "it stands (g77, which says so, and gfortran's default; the legacy build before D180)", True,
            transform=single_constants, keeps_types=False),
    Variant("single-constants-x87", "the same constants on the x87 PC (g77 on Linux or DOS, 80-bit registers)",
            True, _X87, transform=single_constants, keeps_types=False),
    Variant("single-constants-fma", "the same constants on the RS/6000 (xlf -O, fused multiply-add)", True,
            _FMA, transform=single_constants, keeps_types=False),
    Variant("long-constants-double", "only the literal constants of more than seven digits in double "
            "(1.1636867, 2.3139072, 4.6210569): a hypothesis tested here; no compiler found documented "
            "to decide by the count of digits", False, transform=long_constants_double, keeps_types=False),
    Variant("all-constants-double", "every literal constant as double (Sun f77 -r8const, "
            "HP f90 +real_constant=double; options read in later manuals)", True,
            transform=all_constants_double, keeps_types=False),
    Variant("selected-real8", "what-if, no machine: G, PI, M1..M3 = W/G in REAL*8 with double constants",
            False, transform=selected_real8, keeps_types=False),
    Variant("as-printed", "not an arithmetic: the listing as printed (link PARAMETERs the compiler "
            "folds), read as the printed engine's build reads it (D180), reference flags", False,
            transform=printed_output, source="printed"),
)


def get(name: str) -> Variant:
    return next(v for v in VARIANTS if v.name == name)
