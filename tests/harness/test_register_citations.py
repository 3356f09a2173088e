"""The register is checkable: what harness/deviations.toml cites exists, it names nothing a
reader cannot look up, and the figures its entries quote are re-measured.

- Paths: every repository path the register cites (``tests/...``, ``harness/...``,
  ``legacy/...``, ``port/...``, ``package/...``, with or without ``linkrepro/``; a glob or a
  ``<placeholder>`` must match a file) exists; a bare file name is read in the folder of the
  path cited before it in the same field (else anywhere in the repository); a path cited
  with line numbers (``file.f lines 68-72``, ``line 93``, ``lines 127, 143``) has those lines,
  and they are not blank.  A name cited right after a ``.py`` path (``fourbar.py Cognate.of``,
  ``checks.py (POSITION_CONDITION_LIMIT, ...)``) is defined in that file; a dotted
  ``linkrepro.x.y`` name imports.  A reading's ``file`` is a listing of legacy/printed or
  legacy/src.
- Words: no issue number and no "the issue" (our tracker is not the reader's), in entries and
  comments alike.
- Commands: every command an entry quotes (in backticks: ``python ...``, ``linkrepro ...``)
  is a ``[[deviation.check]]`` item of that entry, and no command is quoted outside
  backticks (nor in a comment).  Each check runs: its code in a fresh interpreter, whose
  printed numbers must reproduce the check's figures to the digits quoted, each figure being
  quoted in the entry's text; a quoted ``python -m MODULE`` must be runnable, a
  ``linkrepro COMMAND`` a command of the CLI, a ``python -m pytest ...`` must select tests
  (which the suite runs).  Checks marked ``slow`` run only with LINKREPRO_SLOW_CHECKS=1.
- The checkers are tested on made-up entries: each can fail.
"""
from __future__ import annotations

import importlib
import importlib.util
import os
import re
import shlex
import shutil
import subprocess
import sys
from functools import lru_cache
from pathlib import Path

import pytest

from linkrepro.harness import register as reg
from tests import python_c
from tests.patience import CHILD_SECONDS

ROOT = Path(__file__).resolve().parents[2]
RAW = reg.REGISTER_PATH.read_text()
ENTRIES = reg.load()
#: what the checks' code imports, and pytest (a quoted ``python -m pytest`` collects through ``run_code``):
#: imported once, before the checks run
CHECK_IMPORTS = frozenset({"pytest"}).union(*(python_c.imports(c.code) for e in ENTRIES.values() for c in e.checks if c.code))
SLOW = os.environ.get("LINKREPRO_SLOW_CHECKS", "") not in ("", "0")

#: a repository path: one of the package's top folders, a relative path under it
PATH = re.compile(r"(?<![\w/.<>*-])(?:linkrepro/)?(?:tests|harness|legacy|port|package)(?:/[\w.*<>-]*[\w*>])+")
#: a bare file name of a kind the repository holds (outputs, .csv, are not checked)
BARE = re.compile(r"(?<![\w/.<>*-])[A-Za-z_][\w-]*\.(?:f|py|pyf|toml)(?![\w/])")
#: line numbers right after a path: "line 93", "lines 68-72", "lines 127, 143", "lines 104, 111-112"
LINES = re.compile(r",?\s+lines?\s+(\d+(?:-\d+)?(?:,\s*\d+(?:-\d+)?)*)")
#: names cited right after a .py path: "fourbar.py Cognate.of", "checks.py (A, b_c)"
NAMES = re.compile(r",?\s+\(?((?:[A-Za-z_][\w.]*)(?:,\s*[A-Za-z_][\w.]*)*)")
DOTTED = re.compile(r"(?<![\w.])linkrepro(?:\.[A-Za-z_]\w*)+")
ISSUE = re.compile(r"\bissues?\b", re.IGNORECASE)
BACKTICKED = re.compile(r"`([^`]+)`")


def repo_files() -> dict[str, list[Path]]:
    """Every file of the repository's top folders, by name."""
    out: dict[str, list[Path]] = {}
    for top in ("tests", "harness", "legacy", "port", "package"):
        for path in (ROOT / top).rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts:
                out.setdefault(path.name, []).append(path)
    return out


FILES = repo_files()


def _matches(cited: str, root: Path) -> list[Path]:
    rel = cited.removeprefix("linkrepro/")
    if "*" in rel or "<" in rel:
        return sorted(root.glob(re.sub(r"<[^>]*>", "*", rel)))
    return [root / rel] if (root / rel).exists() else []


def _line_numbers(spec: str) -> list[int]:
    out = []
    for part in spec.split(","):
        lo, _, hi = part.strip().partition("-")
        out += [int(lo)] + ([int(hi)] if hi else [])
    return out


def _defined(name: str, path: Path) -> bool:
    """``name`` (its first dotted part) is defined or assigned in ``path``, or, dotted, its
    parts are all names the file uses (an attribute of a local object)."""
    text = path.read_text()
    head = name.split(".")[0]
    if re.search(rf"^\s*(?:def|class)\s+{re.escape(head)}\b|^\s*{re.escape(head)}\s*[:=]", text, re.M):
        return True
    return "." in name and all(re.search(rf"\b{re.escape(part)}\b", text) for part in name.split("."))


def _looks_like_code(name: str) -> bool:
    return "_" in name or "." in name or any(c.isupper() for c in name)


def path_problems(text: str, root: Path = ROOT, files: dict[str, list[Path]] | None = None) -> list[str]:
    """What a register field cites that is not in the repository (see the module's text)."""
    files = FILES if files is None else files
    problems, folder = [], None
    found = sorted([(m.start(), m.end(), m.group(0), True) for m in PATH.finditer(text)]
                   + [(m.start(), m.end(), m.group(0), False) for m in BARE.finditer(text)])
    for start, end, cited, full in found:
        cited = cited.rstrip(".")
        if full:
            hits = _matches(cited, root)
            if hits and hits[0].is_file():
                folder = hits[0].parent
        else:
            near = folder / cited if folder is not None else None
            hits = [near] if near is not None and near.is_file() else list(files.get(cited, []))
        if not hits:
            problems.append(f"{cited}: no such file or folder in the repository")
            continue
        after = text[start + len(cited):]
        lines = LINES.match(after)
        if lines:
            for path in hits[:1]:
                held = path.read_text().splitlines()
                for n in _line_numbers(lines.group(1)):
                    if n > len(held):
                        problems.append(f"{cited} line {n}: the file has {len(held)} lines")
                    elif not held[n - 1].strip():
                        problems.append(f"{cited} line {n}: a blank line")
        elif cited.endswith(".py") and hits[0].is_file():
            names = NAMES.match(after)
            for name in (names.group(1).split(",") if names else []):
                name = name.strip().rstrip(".")
                if _looks_like_code(name) and not _defined(name, hits[0]):
                    problems.append(f"{cited}: {name} is not defined there")
    for dotted in DOTTED.findall(text):
        if not _imports(dotted):
            problems.append(f"{dotted}: does not import")
    return problems


@lru_cache(maxsize=None)
def _imports(dotted: str) -> bool:
    parts = dotted.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for attr in parts[k:]:
            if not hasattr(obj, attr):
                return False
            obj = getattr(obj, attr)
        return True
    return False


def issue_problems(text: str) -> list[str]:
    """References to our issue tracker, which a reader cannot look up."""
    return [f"...{text[max(0, m.start() - 40):m.end() + 30]}..." for m in ISSUE.finditer(text)]


@lru_cache(maxsize=1)
def cli_commands() -> tuple[str, ...]:
    out = subprocess.run([sys.executable, "-m", "linkrepro", "--help"], capture_output=True, text=True,
                         timeout=CHILD_SECONDS, cwd=ROOT)
    return tuple(re.search(r"\{([\w,-]+)\}", out.stdout).group(1).split(","))


def loose_commands(text: str) -> list[str]:
    """Commands written outside backticks (a reader copies a command; a check finds it)."""
    prose = BACKTICKED.sub("", text)
    pattern = rf"\bpython3? -[cm]\s+\S+|\blinkrepro (?:{'|'.join(cli_commands())})\b"
    return re.findall(pattern, prose)


def quoted_commands(text: str) -> list[str]:
    return [span for span in BACKTICKED.findall(text) if re.match(r"(?:python3?|linkrepro) ", span)]


def run_code(code: str) -> subprocess.CompletedProcess:
    """``python -c code`` in the repository (``tests/python_c.py``: in a child of a server that has
    imported what every check imports, or with LINKREPRO_FULL_TESTS=1 a fresh interpreter)."""
    return python_c.run(code, ROOT, CHECK_IMPORTS)


def check_problems(check: reg.Check) -> list[str]:
    """Run a check's code in a fresh interpreter; what its output gets wrong (empty: none)."""
    if check.code is None:
        return []
    out = run_code(check.code)
    if out.returncode != 0 and "CompilerError" in out.stderr and shutil.which("gfortran") is None:
        pytest.skip("the check rebuilds FORTRAN: needs gfortran")
    if out.returncode != 0 and "ExudynMissing" in out.stderr:
        pytest.skip("the check runs Exudyn: pip install 'linkrepro[multibody]'")
    if out.returncode != 0:
        return [f"the check's code failed (exit {out.returncode}): {out.stderr.strip()[-3000:]}"]
    return reg.figures_reproduced(check.figures, out.stdout)


@lru_cache(maxsize=None)
def command_options(name: str) -> tuple[int, frozenset[str]]:
    """``linkrepro NAME --help``'s exit status and the options it lists (run once a command)."""
    out = subprocess.run([sys.executable, "-m", "linkrepro", name, "--help"], capture_output=True,
                         text=True, cwd=ROOT, timeout=CHILD_SECONDS)
    return out.returncode, frozenset(re.findall(r"--[\w-]+", out.stdout))


def command_problems(command: str) -> list[str]:
    """Whether a quoted command can be run as written (its figures are ``check_problems``')."""
    words = shlex.split(command)
    if words[0] in ("python", "python3") and words[1:2] == ["-c"]:
        return [] if len(words) == 3 else [f"{command}: python -c takes one argument"]
    if words[0] in ("python", "python3") and words[1:3] == ["-m", "pytest"]:
        args = ["--collect-only", "-q", "-p", "no:cacheprovider", *words[3:]]
        out = run_code(f"import sys, pytest; sys.exit(pytest.main({args!r}))")     # python -m pytest ARGS
        selected = re.search(r"(\d+)(?:/\d+)? tests? (?:collected|selected)", out.stdout)
        if out.returncode != 0 or not selected or int(selected.group(1)) == 0:
            return [f"{command}: selects no test ({out.stdout.strip()[-500:]})"]
        return []
    if words[0] in ("python", "python3") and words[1:2] == ["-m"]:
        spec = importlib.util.find_spec(words[2])
        if spec is None or spec.origin is None or "__main__" not in Path(spec.origin).read_text():
            return [f"{command}: {words[2]} is not a module that runs"]
        return []
    if words[0] == "linkrepro":
        if words[1] not in cli_commands():
            return [f"{command}: linkrepro has no command {words[1]!r} ({', '.join(cli_commands())})"]
        status, options = command_options(words[1])
        unknown = [w for w in words[2:] if w.startswith("--") and w.split("=")[0] not in options]
        return [f"{command}: no option {unknown}"] if status or unknown else []
    return [f"{command}: not a command of this project"]


def figure_quoted(figure: str, text: str) -> bool:
    return re.search(rf"(?<![\w.]){re.escape(figure)}(?![\d])", text) is not None


def comments(raw: str) -> str:
    return "\n".join(line for line in raw.splitlines() if line.lstrip().startswith("#"))


# ---------------------------------------------------------------------------------------------
# the register as it is
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("entry_id", list(ENTRIES))
def test_every_path_the_entry_cites_exists(entry_id):
    entry = ENTRIES[entry_id]
    problems = [p for name in reg.TEXT_FIELDS for p in path_problems(getattr(entry, name))]
    for reading in entry.readings:
        if not any((ROOT / "legacy" / tier / reading["file"]).is_file() for tier in ("printed", "src")):
            problems.append(f"reading of {reading['file']}: not a listing of legacy/printed or legacy/src")
    assert not problems, problems


def test_the_comments_cite_what_exists():
    assert not path_problems(comments(RAW))


def test_no_issue_numbers():
    """Neither "issue 11" nor "the issue": say what it refers to."""
    assert not issue_problems(RAW)


def test_every_quoted_command_is_a_check():
    problems = []
    for entry in ENTRIES.values():
        quoted = set(quoted_commands(entry.text))
        checked = {c.command for c in entry.checks if c.command}
        problems += [f"{entry.id}: `{c}` is quoted but no check of the entry has it" for c in quoted - checked]
        problems += [f"{entry.id}: the check's command `{c}` is not quoted in the entry" for c in checked - quoted]
        problems += [f"{entry.id}: {c!r} is not in backticks" for c in loose_commands(entry.text)]
        for check in entry.checks:
            if check.python and check.command and shlex.split(check.command)[1:2] == ["-c"]:
                problems.append(f"{entry.id}: a python -c command is its own code; no python item")
            problems += [f"{entry.id}: figure {f} is not quoted in the entry" for f in check.figures
                         if not figure_quoted(f, entry.text)]
    problems += [f"comment: {c!r}" for c in loose_commands(comments(RAW)) + quoted_commands(comments(RAW))]
    assert not problems, problems


CHECKS = [pytest.param(entry.id, k, id=f"{entry.id}-{k}") for entry in ENTRIES.values()
          for k in range(len(entry.checks))]


@pytest.mark.parametrize("entry_id, k", CHECKS)
def test_the_check_reproduces_the_quoted_figures(entry_id, k):
    check = ENTRIES[entry_id].checks[k]
    if check.slow and not SLOW:
        pytest.skip("a slow check: LINKREPRO_SLOW_CHECKS=1 runs it")
    problems = (command_problems(check.command) if check.command else []) + check_problems(check)
    assert not problems, problems


def test_the_register_has_checks():
    """The entries that quote a command to re-measure with keep their checks."""
    assert {"D037", "D056", "D079", "D130", "D131", "D132"} <= {e.id for e in ENTRIES.values() if e.checks}


# ---------------------------------------------------------------------------------------------
# the checkers on made-up entries: each can fail
# ---------------------------------------------------------------------------------------------

def test_path_checker_on_made_up_text(tmp_path):
    (tmp_path / "legacy" / "src").mkdir(parents=True)
    (tmp_path / "legacy" / "src" / "a.f").write_text("      A=1\n\n      B=2\n")
    (tmp_path / "port").mkdir()
    (tmp_path / "port" / "m.py").write_text("class Cognate:\n    pass\n\ndef raise_first(x):\n    return x\n")
    files = {"a.f": [tmp_path / "legacy" / "src" / "a.f"], "m.py": [tmp_path / "port" / "m.py"]}
    check = lambda text: path_problems(text, tmp_path, files)  # noqa: E731
    assert check("legacy/src/a.f line 3; legacy/src/a.f lines 1, 3; linkrepro/port/m.py Cognate.of, raise_first") == []
    assert check("legacy/src/*.f and legacy/<tier>/a.f; port/m.py (raise_first)") == []
    assert check("tests/test_port.py checks it") == ["tests/test_port.py: no such file or folder in the repository"]
    assert check("legacy/src/a.f lines 2-4") == ["legacy/src/a.f line 2: a blank line",
                                                   "legacy/src/a.f line 4: the file has 3 lines"]
    assert check("legacy/src/a.f line 1, a.f line 5") == ["a.f line 5: the file has 3 lines"]
    assert check("legacy/scan/nothing_*.toml") == ["legacy/scan/nothing_*.toml: no such file or folder in the repository"]
    assert check("port/m.py raise_last") == ["port/m.py: raise_last is not defined there"]
    assert check("b.f line 1") == ["b.f: no such file or folder in the repository"]
    assert path_problems("linkrepro.harness.no_such_module and linkrepro.harness.register.load") == [
        "linkrepro.harness.no_such_module: does not import"]


def test_issue_checker_on_made_up_text():
    assert issue_problems("mended in both (the tests found them)") == []
    assert len(issue_problems("mended in both (issue 11); named in the project's issue; Issue 22: x")) == 3


def test_command_checkers_on_made_up_text():
    assert loose_commands("Measured (`python -m linkrepro.harness.fuzz`)") == []
    assert loose_commands("Measured (python -m linkrepro.harness.differential, 500 geometries)") == [
        "python -m linkrepro.harness.differential,"]
    assert loose_commands("converges as n grows (linkrepro bench)") == ["linkrepro bench"]
    assert quoted_commands("re-measure: `linkrepro arithmetic --out x`; ``solution``") == ["linkrepro arithmetic --out x"]
    assert command_problems("python -m linkrepro.harness.differential") == [
        "python -m linkrepro.harness.differential: linkrepro.harness.differential is not a module that runs"]
    assert command_problems("python -m linkrepro.harness.scenes.rahman1996.differential") == []
    assert command_problems("linkrepro arithmetic --out out/arithmetic") == []
    assert command_problems("linkrepro arithmetic --no-such-option") != []
    assert command_problems("linkrepro frobnicate") != []
    assert command_problems("python -m pytest tests/harness/test_register_citations.py -k no_such_test_at_all") != []


def test_the_checker_fails_a_wrong_figure():
    """A made-up entry whose check quotes a figure its code does not print fails; one digit
    more than the measurement holds fails; the right figures at fewer digits pass."""
    code = "print(0.015530000440776348, 0.0001320097570864931, 70)"
    assert check_problems(reg.Check(python=code, figures=("0.0155300004", "+1.320e-4", "70"))) == []
    assert check_problems(reg.Check(python=code, figures=("0.01553", "1.32e-4", "70"))) == []
    assert check_problems(reg.Check(python=code, figures=("0.0155300005", "+1.320e-4", "70"))) == [
        "quoted 0.0155300005, measured 0.015530000440776348"]
    assert check_problems(reg.Check(python=code, figures=("0.0155300004", "+1.320e-4", "69"))) == [
        "quoted 69, measured 70"]
    assert check_problems(reg.Check(python=code, figures=("0.0155300004", "+1.320e-4"))) != []
    assert check_problems(reg.Check(python="raise SystemExit('no')", figures=())) != []
    assert check_problems(reg.Check(command='python -c "print(-1.2443)"', figures=("1.2443",))) == [
        "quoted 1.2443, measured -1.2443"]


def test_a_made_up_register_with_a_wrong_check_is_caught(tmp_path):
    """The whole path: a register file with a check, loaded, run, and found wrong."""
    entry = '''[[deviation]]
id = "D999"
kind = "published-misprint"
title = "t"
where = "seed 003 line 1"
printed = "p"
meant = "m"
evidence = "The sum is 6.633 (`python -c \\"print(6.637340 - 0.004)\\"`)."
effect = "e"
  [[deviation.check]]
  command = "python -c \\"print(6.637340 - 0.004)\\""
  figures = ["{figure}"]
'''
    for figure, ok in (("6.633", True), ("6.634", False)):
        path = tmp_path / f"register_{figure}.toml"
        path.write_text(entry.replace("{figure}", figure))
        found = reg.load(path)["D999"]
        assert quoted_commands(found.text) == [found.checks[0].command]
        assert (check_problems(found.checks[0]) == []) == ok
    path.write_text(entry.replace("{figure}", "six"))
    with pytest.raises(ValueError, match="not a number"):
        reg.load(path)
    path.write_text(entry.replace('  command = "python -c \\"print(6.637340 - 0.004)\\""\n', '  command = "linkrepro bench"\n')
                    .replace("{figure}", "6.633"))
    with pytest.raises(ValueError, match="need code"):
        reg.load(path)


def test_figure_matching_is_to_the_digits_quoted():
    ok = reg.figure_reproduced
    assert ok("3e-15", "2.6e-15") and ok("2.1", "2.1e+00") and ok("0.0048560", "0.004856")
    assert ok("2.048888E-04", "0.00020488878625")
    assert not ok("3e-15", "3.6e-15") and not ok("0.00485601", "0.004856") and not ok("0.000", "-0.0001")
    assert ok("-5.0", "-4.98912") and not ok("-5.0", "-5.0512")
