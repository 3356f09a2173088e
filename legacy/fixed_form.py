"""Fixed-form FORTRAN 77 source text: its statements and literal constants, and the 1996
compiler's reading of a constant assigned to a REAL*8 variable (register D180).

Columns 1-6 hold the label and the continuation mark, 7-72 the code; a C, c, * or ! in
column 1 makes a comment card.  ``context_constants`` writes every real literal assigned
directly to a variable its program unit declares REAL*8 as a double constant
(``K1XCG=0.2041241`` becomes ``K1XCG=0.2041241D0``): what the g77 manual calls context-sensitive constants, which 'many
other Fortran compilers' did, and what DEC's and Intel's ``/fpconstant`` still do.

The standard library only: meson runs this file as a script when it builds the printed CSSP
program (``python fixed_form.py IN OUT [IN OUT ...]``, each IN read, each OUT written), so
that the ``printed`` engine reads its constants as the 1996 compiler did while
legacy/printed/ stays as printed; the arithmetic study (harness/scenes/rahman1996/
arithmetic_variants.py) imports it.
"""
from __future__ import annotations

import re
import sys

__all__ = ["is_comment", "split", "join", "statements", "units", "as_double", "real8_names", "context_constants"]

_DECL = re.compile(r"^\s*(?:REAL\s*\*\s*8|DOUBLE\s+PRECISION)\s+(.*)$", re.IGNORECASE)
_IMPLICIT = re.compile(r"^\s*IMPLICIT\b", re.IGNORECASE)
_END = re.compile(r"^\s*END\s*$", re.IGNORECASE)
#: an assignment of a lone real literal, after a logical IF or not: (lead, name, subscript and '=', mantissa,
#: exponent, trailing blanks)
_ASSIGN_LITERAL = re.compile(r"^(\s*(?:IF\s*\(.*\)\s*)?)([A-Za-z]\w*)(\s*(?:\([^=]*\))?\s*=\s*[+-]?\s*)"
                             r"(\d+\.\d*|\.\d+|\d+(?=[Ee]))([Ee][+-]?\d+)?(\s*)$", re.IGNORECASE)


def is_comment(line: str) -> bool:
    """A blank line or a comment card."""
    return not line.strip() or line[0] in "Cc*!"


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


def split(line: str) -> tuple[str, str, str]:
    """(columns 1-6, code of columns 7-72 before any '!' comment, the rest)."""
    head, code = line[:6], line[6:72]
    bang = _bang(code)
    if bang >= 0:
        return head, code[:bang], code[bang:] + line[72:]
    return head, code, line[72:]


def join(head: str, code: str, rest: str, original: str) -> str:
    """``split``'s parts put back, the rest (a tag such as ``! D180``) kept at column 73;
    ValueError if the code no longer fits in column 72."""
    if len(head) + len(code.rstrip()) > 72:
        raise ValueError(f"a promoted constant pushes code past column 72: {original.rstrip()!r}")
    return head + code.rstrip().ljust(66) + rest if rest else head + code.rstrip()


def statements(lines: list[str]) -> list[list[int]]:
    """Line indices of each statement (initial line and its continuations)."""
    out: list[list[int]] = []
    for k, line in enumerate(lines):
        if is_comment(line):
            continue
        if len(line) > 5 and line[5] not in " 0" and out:
            out[-1].append(k)
        else:
            out.append([k])
    return out


def as_double(text: str, mantissa: str, exponent: str | None) -> str:
    """A real literal written as a double constant (``0.5`` -> ``0.5D0``, ``1.5E-3`` -> ``1.5D-3``)."""
    if exponent is None:
        return mantissa + "D0"
    return mantissa + "D" + exponent[1:] if exponent[0] in "Ee" else text


def _code(lines: list[str], stmt: list[int]) -> str:
    """A statement's code, its continuation lines joined."""
    return " ".join(split(lines[k])[1] for k in stmt)


def units(lines: list[str]) -> list[list[list[int]]]:
    """The statements (``statements``) of each program unit: a unit ends with its END statement."""
    out: list[list[list[int]]] = [[]]
    for stmt in statements(lines):
        out[-1].append(stmt)
        if _END.match(_code(lines, stmt)):
            out.append([])
    return [unit for unit in out if unit]


def real8_names(lines: list[str], unit: list[list[int]]) -> set[str]:
    """The names one program unit declares REAL*8 or DOUBLE PRECISION (upper case);
    ValueError at an IMPLICIT statement other than IMPLICIT NONE (its typing is not read here)."""
    names: set[str] = set()
    for stmt in unit:
        whole = _code(lines, stmt)
        if _IMPLICIT.match(whole) and not re.match(r"^\s*IMPLICIT\s+NONE\s*$", whole, re.IGNORECASE):
            raise ValueError(f"an IMPLICIT statement types names by their letter, which is not read here: {whole.strip()!r}")
        match = _DECL.match(whole)
        if match:
            flat = match.group(1)
            while re.search(r"\([^()]*\)", flat):
                flat = re.sub(r"\([^()]*\)", "", flat)
            names |= {n.strip().upper() for n in flat.split(",") if re.fullmatch(r"\s*[A-Za-z]\w*\s*", n)}
    return names


def context_constants(text: str) -> tuple[str, int]:
    """(``text`` with every literal assigned directly to a REAL*8 variable of its program unit
    written as double, how many assignments were rewritten).  Only assignments of a lone literal
    (``X=0.5``, ``A(I)=-1.0``) are read so, a literal in an expression keeps its type; ValueError
    where such an assignment runs over continuation lines (not rewritten here)."""
    lines = text.split("\n")
    changed = 0
    for unit in units(lines):
        real8 = real8_names(lines, unit)
        for stmt in unit:
            k = stmt[0]
            head, code, rest = split(lines[k])
            match = _ASSIGN_LITERAL.match(_code(lines, stmt))
            if match and match.group(2).upper() in real8 and len(stmt) > 1:
                raise ValueError(f"a literal assigned to a REAL*8 variable over continuation lines is not read here: "
                                 f"{_code(lines, stmt).strip()!r}")
            if match and match.group(2).upper() in real8:
                literal = match.group(4) + (match.group(5) or "")
                new = (match.group(1) + match.group(2) + match.group(3)
                       + as_double(literal, match.group(4), match.group(5)) + match.group(6))
                lines[k] = join(head, new, rest, lines[k])
                changed += 1
    return "\n".join(lines), changed


def main(argv: list[str]) -> int:
    """``IN OUT [IN OUT ...]``: each IN's text, its constants read as ``context_constants``
    reads them, written to OUT (the build of the printed CSSP program, meson.build)."""
    if not argv or len(argv) % 2:
        print("usage: fixed_form.py IN OUT [IN OUT ...]", file=sys.stderr)
        return 2
    for source, target in zip(argv[::2], argv[1::2]):
        with open(source, encoding="utf-8") as f:
            text, _ = context_constants(f.read())
        with open(target, "w", encoding="utf-8") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
