"""The words a reader is shown: README.md and docs/*.md.

- every generated block (``harness/docs.py``: the counts of a run, the explain trail, the CSSP's
  differential sample) is what a fresh computation gives now (the CSSP's sample only in
  ``make fuzz``: ``WHOLE_ONLY``);
- every ``python`` block runs, each as ``python -c`` runs it (``tests/python_c.py``; an intended
  error is caught in the block itself);
- every relative link leads to a file, and no page speaks of tools a reader does not have or of
  issue numbers they cannot look up;
- the README stays a newcomer's page: short, the findings in docs/.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from linkrepro.harness import docs
from tests import python_c
from tests.sizes import FULL

ROOT = Path(__file__).resolve().parents[2]
PAGES = docs.pages(ROOT)
PYTHON = re.compile(r"```python\n(.*?)```", re.S)
LINK = re.compile(r"\]\(([^)#:]+?)(?:#[^)]*)?\)")
#: what no page may say: tools of the developers' machine, the issue tracker
FORBIDDEN = re.compile(r"duplicates --change|\.\./shared|\bissue \d+|the issue named|the project's issue")


def test_the_pages_are_found():
    names = {p.relative_to(ROOT).as_posix() for p in PAGES}
    assert "README.md" in names and "docs/reliability.md" in names


#: blocks recomputed only in the whole run (``make fuzz``, ``LINKREPRO_FULL_TESTS=1``): the CSSP's
#: 500-geometry sample and its REAL*4 chaos, about 3000 calls of legacy and the port, more than half
#: of the blocks' time.  In ``make test`` the same computation runs once, as register D079's check
#: (tests/harness/test_register_citations.py), which asserts the block's counts and moves (500 agree,
#: 150 and 350, 44, 31, 206, 2.3e-15, 2.5e-7, 2.1; the block's 144 and 75 are their differences);
#: only the block's wording and its 99th percentile wait for ``make fuzz``
WHOLE_ONLY = frozenset({"differential"})


def test_every_generated_block_is_what_a_run_gives_now():
    """Every block but WHOLE_ONLY in ``make test``; every block in ``make fuzz``."""
    keep = frozenset() if FULL else WHOLE_ONLY
    stale = [p.relative_to(ROOT).as_posix() for p in PAGES if docs.filled(p.read_text(), keep) != p.read_text()]
    assert stale == [], f"out of date (python -m linkrepro.harness.docs rewrites them): {stale}"


def test_the_generated_blocks_are_there():
    names = {m.group("name") for p in PAGES for m in docs.BLOCK.finditer(p.read_text())}
    assert {"results summary", "results ali1977", "results rahman1996", "explain", "differential", "toolchains"} <= names


EXAMPLES = [(p.relative_to(ROOT).as_posix(), k, code) for p in PAGES for k, code in enumerate(PYTHON.findall(p.read_text()))]


#: what the examples import: imported once, before they run (``tests/python_c.py``)
EXAMPLE_IMPORTS = frozenset().union(*(python_c.imports(code) for _, _, code in EXAMPLES))


@pytest.mark.parametrize("page, index, code", EXAMPLES, ids=[f"{p}#{k}" for p, k, _ in EXAMPLES])
def test_every_python_example_runs(page, index, code, tmp_path):
    """As ``python -c``: in make test forked from a process that has imported what they import, in a
    fresh interpreter with LINKREPRO_FULL_TESTS=1."""
    done = python_c.run(code, tmp_path, EXAMPLE_IMPORTS)
    assert done.returncode == 0, f"{page} example {index}:\n{done.stderr[-2000:]}"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_links_lead_somewhere_and_no_page_speaks_of_what_a_reader_lacks(page):
    text = page.read_text()
    for target in LINK.findall(text):
        assert (page.parent / target).exists(), f"{page.name}: link to {target}"
    assert not FORBIDDEN.search(text), FORBIDDEN.search(text).group(0)


def test_the_readme_is_a_newcomers_page():
    lines = (ROOT / "README.md").read_text().splitlines()
    heads = [line for line in lines if line.startswith("## ")]
    assert len(lines) <= 200
    assert heads[:2] == ["## Set-up: two commands", "## What comes out"] and "## Where to go next" in heads


def test_the_checks_can_fail(tmp_path):
    page = tmp_path / "README.md"
    stale = "<!-- generated: model assumptions rahman1996 -->\nstale\n<!-- end generated -->\n"
    page.write_text(stale)
    assert docs.main(["--root", str(tmp_path), "--check"]) == 1
    assert docs.filled(stale, frozenset({"model assumptions rahman1996"})) == stale != docs.filled(stale)
    assert FORBIDDEN.search("see issue 12") and FORBIDDEN.search("run duplicates --change")


def test_the_fuzz_count_a_page_quotes_is_the_one_make_fuzz_runs():
    calls = int(re.search(r"--calls (\d+)", (ROOT / "Makefile").read_text()).group(1))
    quoted = [(p.name, int(n.replace(",", ""))) for p in PAGES
              for n in re.findall(r"([\d,]+) random and hostile calls", p.read_text())]
    assert quoted and all(n == calls for _, n in quoted), (calls, quoted)
