"""legacy/fixed_form.py: the 1996 compiler's reading of a literal assigned to a REAL*8 variable
(register D180), held against what gfortran itself makes of the text, not against the module's
own parsing: its symbol table says which names are REAL*8, its parse tree (-fdump-fortran-original)
which values each assignment stores, and a compiled program what a context-typing compiler's
reading stores (the g77 manual's 'Context-Sensitive Constants', DEC's /fpconstant: a lone
literal assigned to a double variable in double, everything else as the standard reads it)."""
import re
import shutil
import subprocess

import numpy as np
import pytest

from linkrepro.legacy import fixed_form as F

needs_gfortran = pytest.mark.skipif(shutil.which("gfortran") is None, reason="needs gfortran")
LISTINGS = ("rahman1996_cssp_main.f", "rahman1996_subroutines.f")
RADII = ("K1XCG", "K1YCG", "K1ZCG", "K1X", "K1Y", "K1Z", "K2XCG", "K2YCG", "K2ZCG", "K2X", "K2Y", "K2Z",
         "K3X", "K3Y", "K3Z")
#: a statement assigning a lone literal (the test's own reading: any statement, continued or not)
LONE = re.compile(r"^\s*([A-Za-z]\w*)\s*(?:\([^=]*\))?\s*=\s*[+-]?\s*(?:\d+\.\d*|\.\d+|\d+(?=[Ee]))(?:[Ee][+-]?\d+)?\s*$")
HEADER = re.compile(r"^\s*(?:REAL\*8\s+|DOUBLE\s+PRECISION\s+)?(?:SUBROUTINE|FUNCTION|PROGRAM)\s+(\w+)", re.I)


def _parse_tree(text: str, tmp_path, name: str) -> str:
    (tmp_path / name).write_text(text)
    out = subprocess.run(["gfortran", "-std=legacy", "-fsyntax-only", "-fdump-fortran-original", name],
                         cwd=tmp_path, capture_output=True, text=True, timeout=60, check=True)
    return out.stdout


def _real8(tree: str) -> set[tuple[str, str]]:
    """(program unit, name) of every REAL(8) symbol, from gfortran's symbol tables."""
    out, unit = set(), None
    for block in re.split(r"\n(?=\s*(?:procedure name =|symtree:))", tree):
        if m := re.match(r"\s*procedure name = (\w+)", block):
            unit = m.group(1).lower()
        elif m := re.match(r"\s*symtree: '(\w+)'.*\n\s*type spec : \(REAL 8\)", block):
            out.add((unit, m.group(1).lower()))
    return out


def _assigns(tree: str) -> list[str]:
    return [line.split("ASSIGN", 1)[1].strip() for line in tree.splitlines() if "ASSIGN " in line]


def _lone_literal_lines(text: str, real8: set[tuple[str, str]]) -> set[int]:
    """Line numbers of the lone-literal assignments to a name gfortran types REAL(8) in its unit."""
    lines, found, unit = text.split("\n"), set(), "main__"
    for stmt in F.statements(lines):
        code = " ".join(lines[k][6:72].split("!")[0] for k in stmt)
        if m := HEADER.match(code):
            unit = m.group(1).lower()
        m = LONE.match(code)
        if m and (unit, m.group(1).lower()) in real8:
            found.add(stmt[0])
    return found


@needs_gfortran
@pytest.mark.parametrize("name", LISTINGS)
def test_the_listing_read_so_changes_the_radii_alone(root, tmp_path, name):
    """On the printed listing: the lines rewritten are exactly the lone-literal assignments to
    names gfortran types REAL(8); in gfortran's parse tree the stored values change only in the
    15 radii of gyration, each to its printed decimal in double (0.0, 1.0, -1.0, -4.0 are exact)."""
    text = (root / "legacy" / "printed" / name).read_text()
    new, count = F.context_constants(text)
    before, after = _parse_tree(text, tmp_path, name), _parse_tree(new, tmp_path, name)
    changed = {k for k, (a, b) in enumerate(zip(text.split("\n"), new.split("\n"))) if a != b}
    assert changed == _lone_literal_lines(text, _real8(before)) and len(changed) == count
    moved = [(a, b) for a, b in zip(_assigns(before), _assigns(after)) if a != b]
    assert len(_assigns(before)) == len(_assigns(after)) > 50
    if name != "rahman1996_cssp_main.f":
        assert moved == []
        return
    printed = dict(re.findall(r"^\s+(K\w+)=(\d+\.\d+)\s*$", text, re.M))
    assert sorted(a.split()[0] for a, _ in moved) == sorted(f"MAIN__:{k.lower()}" for k in RADII)
    for a, b in moved:
        target, value = b.split()
        decimal = float(printed[target.split(":")[1].upper()])
        assert float(value.removesuffix("_8")) == decimal                                     # in double
        assert float(a.split()[1].removesuffix("_8")) == float(np.float32(decimal)) != decimal   # was REAL*4


@needs_gfortran
def test_legacy_src_holds_the_same_reading(root, tmp_path):
    """legacy/src's lines tagged D180 are the printed lines read so, and reading legacy/src so
    again stores no other value (gfortran's parse tree unchanged)."""
    name = "rahman1996_cssp_main.f"
    read, _ = F.context_constants((root / "legacy" / "printed" / name).read_text())
    src = (root / "legacy" / "src" / name).read_text()
    tagged = [line[:72].rstrip() for line in src.split("\n") if line.rstrip().endswith("! D180")]
    assert len(tagged) == len(RADII) and all(line in read.split("\n") for line in tagged)
    again, _ = F.context_constants(src)
    assert _assigns(_parse_tree(src, tmp_path, name)) == _assigns(_parse_tree(again, tmp_path, name))


PROGRAM = """\
      PROGRAM T
      REAL*8 A, B(2), C, E, F, H
      DOUBLE PRECISION D
      REAL Y, Z
      A=0.1
      B(2)=-0.3
   10 C=1.5E-3
      D=0.7
      Y=0.1
      E=0.1*2.0
      IF (Y.GT.0.0) F=0.2
      H=1E-1
      CALL S(Z)
      WRITE(*,'(9ES26.17E3)') A,B(2),C,D,Y,E,F,H,Z
      END
      SUBROUTINE S(A)
      REAL A
      A=0.1
      END
"""


@needs_gfortran
def test_a_compiled_program_stores_what_a_context_typing_compiler_stores(tmp_path):
    """A lone literal assigned to a REAL*8 name (in any unit that declares it so, after a label
    or a logical IF, with an exponent) is stored in double; a REAL*4 target, a literal in an
    expression and a unit where the name is REAL*4 keep the standard's reading."""
    new, count = F.context_constants(PROGRAM)
    assert count == 6
    (tmp_path / "t.f").write_text(new)
    subprocess.run(["gfortran", "-std=legacy", "-o", "t", "t.f"], cwd=tmp_path, check=True, timeout=60)
    got = [float(x) for x in subprocess.run(["./t"], cwd=tmp_path, capture_output=True, text=True,
                                            timeout=60, check=True).stdout.split()]
    s = lambda x: float(np.float32(x))
    assert got == [0.1, -0.3, 1.5e-3, 0.7, s(0.1), float(np.float32(0.1) * np.float32(2.0)), 0.2, 0.1, s(0.1)]


def test_the_tag_keeps_its_column_and_what_is_not_read_says_so():
    line = "      K1X=0.2041241".ljust(72) + "! D180"
    out, _ = F.context_constants("      REAL*8 K1X\n" + line + "\n      END")
    assert out.split("\n")[1] == "      K1X=0.2041241D0".ljust(72) + "! D180"
    with pytest.raises(ValueError, match="column 72"):
        F.context_constants("      REAL*8 X\n      X=" + "1" * 61 + ".0\n      END")
    with pytest.raises(ValueError, match="continuation"):
        F.context_constants("      REAL*8 X\n      X=\n     1 0.5\n      END")
    with pytest.raises(ValueError, match="IMPLICIT"):
        F.context_constants("      IMPLICIT DOUBLE PRECISION (A-H)\n      A=0.5\n      END")
    assert F.context_constants("      IMPLICIT NONE\n      REAL X\n      X=0.5\n      END")[1] == 0


def test_the_build_script_writes_each_file(tmp_path):
    (tmp_path / "a.f").write_text("      REAL*8 X\n      X=0.5\n      END\n")
    assert F.main([str(tmp_path / "a.f"), str(tmp_path / "b.f")]) == 0
    assert (tmp_path / "b.f").read_text() == "      REAL*8 X\n      X=0.5D0\n      END\n"
    assert F.main([str(tmp_path / "a.f")]) == 2


def test_the_printed_engine_is_built_from_the_listing_read_so():
    """The printed CSSP program (meson.build compiles a copy of legacy/printed/ read by
    context_constants) writes the crank's I_xx = M1*K1XCG**2 with M1 = 1.9/G in REAL*4 and
    K1XCG = 0.2041241 in double, as the legacy build does."""
    from linkrepro.harness.scenes import get
    scene = get("rahman1996-table5_1")
    printed, legacy = scene.run("printed"), scene.run("legacy")
    m1 = float(np.float32(1.9) / np.float32(386.4))
    assert printed.at[0, "before"] == legacy.at[0, "before"] == m1 * (0.2041241 * 0.2041241)
