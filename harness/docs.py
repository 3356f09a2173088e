"""The generated blocks of README.md and docs/*.md: every count the pages show of a run.

A page holds a block as

    <!-- generated: NAME -->
    ...
    <!-- end generated -->

and ``python -m linkrepro.harness.docs`` fills each from a fresh computation (``--check``: exit 1
if a page differs from what it would write, and say where).  The blocks:

- ``results summary``, ``results <thesis>``: each published table's cells per engine, matched /
  explained (by kind) / within tolerance / unresolved / unexplained / not produced
  (``diff.count_cells``, every table scene's engines run now);
- ``explain``: ``linkrepro explain ali1977-table1 160 src_dx`` as it prints (its first lines);
- ``model assumptions NAME ...``: the register's model assumptions (kind ``model-assumption``)
  whose ``scenes`` hold a scene NAME, or a scene of the thesis NAME, with their effect;
- ``toolchains``: the measured matrix of the run across toolchains, per toolchain and engine
  (``harness/toolchains.py``, from the committed ``reference/toolchains/matrix.csv``);
- a thesis's own blocks (``BLOCKS`` of its ``harness/scenes/<thesis>/docs.py``, found through
  the registry): ``differential``, the CSSP's fixed sample of the port against legacy.

``tests/harness/test_docs.py`` computes every block afresh and fails where a page shows
something else.  Pages are found under ``--root`` (default: the current folder, a source tree).
"""
from __future__ import annotations

import argparse
import contextlib
import io
import re
import sys
from functools import lru_cache
from pathlib import Path

import pandas as pd

from . import register as register_mod
from .diff import CLASSES, EXPLAINED_BY, count_cells, words
from .markdown_text import prose

BLOCK = re.compile(r"(<!-- generated: (?P<name>[^>]+?) -->\n)(?P<body>.*?)(<!-- end generated -->)", re.S)
PAGES = ("README.md", "docs/*.md")
EXPLAIN = ("explain", "ali1977-table1", "160", "src_dx", "--run")


def pages(root: Path) -> list[Path]:
    return [path for pattern in PAGES for path in sorted(root.glob(pattern))]


@lru_cache(maxsize=None)
def table_counts() -> dict[str, pd.DataFrame]:
    """Every table scene's ``count_cells``, its engines run now (scene name -> frame)."""
    from .scenes import TABLES
    register = register_mod.load()
    return {name: count_cells(scene.compute().diff, register) for name, scene in TABLES.items()}


def _kinds(row: pd.Series) -> str:
    parts = [f"{row[kind]} {kind}" for kind in EXPLAINED_BY if row[kind]]
    return f"{row['explained']}" + (f" ({', '.join(parts)})" if parts else "")


def results(thesis: str | None = None, engines: tuple[str, ...] = ("legacy",)) -> str:
    """A markdown table: per table scene (of ``thesis``, or all) and engine, the cells by what
    they count as."""
    heads = ["table", "engine", "cells"] + [words(c) + (" (by kind)" if c == "explained" else "") for c in CLASSES]
    lines = ["| " + " | ".join(heads) + " |", "|" + "---|" * len(heads)]
    for name, counts in table_counts().items():
        if thesis is not None and not name.startswith(thesis + "-"):
            continue
        for engine in engines:
            row = counts.loc[engine]
            shown = [name, engine, row["cells"]] + [_kinds(row) if c == "explained" else row[c] for c in CLASSES]
            lines.append("| " + " | ".join(str(v) for v in shown) + " |")
    return "\n".join(lines) + "\n"


#: the lines of the explain trail the README shows (the rest: run it)
EXPLAIN_LINES = 28


def explain() -> str:
    """The console block: the command and the first EXPLAIN_LINES lines it prints."""
    from .cli import main
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = main(list(EXPLAIN))
    if status != 0:
        raise RuntimeError(f"linkrepro {' '.join(EXPLAIN)} exited {status}")
    lines = out.getvalue().rstrip().splitlines()
    shown = "\n".join(lines[:EXPLAIN_LINES] + (["  ..."] if len(lines) > EXPLAIN_LINES else []))
    return f"```console\n$ linkrepro {' '.join(EXPLAIN)}\n{shown}\n```\n"


def model_assumptions(names: list[str]) -> str:
    """A markdown list: the register's model assumptions that a scene of ``names`` keeps (a name is a
    scene or a thesis, every scene ``thesis-...``), each with those scenes and its measured effect."""
    def named(scene: str) -> bool:
        return any(scene == name or scene.startswith(name + "-") for name in names)
    lines = []
    for _, entry in sorted(register_mod.load().items()):
        scenes = [f"`{scene}`" for scene in entry.scenes if named(scene)]
        if scenes:
            lines.append(f"- **{entry.id}** {prose(entry.title)} ({', '.join(scenes)}). {prose(entry.effect)}")
    if not lines:
        raise KeyError(f"no model assumption of the register names a scene of {names}")
    return "\n".join(lines) + "\n"


def block(name: str) -> str:
    """The text of the block ``name``."""
    if name.startswith("model assumptions "):
        return model_assumptions(name.removeprefix("model assumptions ").split())
    if name == "results summary":
        return results(engines=("legacy",))
    if name.startswith("results "):
        return results(name.removeprefix("results "), engines=("printed", "legacy", "port_printed", "port_corrected"))
    if name == "explain":
        return explain()
    if name == "toolchains":
        from .toolchains import summary
        return summary()
    theirs = thesis_blocks()
    if name in theirs:
        return theirs[name]()
    raise KeyError(f"no generated block {name!r}")


def thesis_blocks() -> dict:
    """The blocks the theses give (``BLOCKS`` of each ``harness/scenes/<thesis>/docs.py``)."""
    from .scenes import hook_modules
    return {name: make for module in hook_modules("docs") for name, make in module.BLOCKS.items()}


def filled(text: str, keep: frozenset[str] = frozenset()) -> str:
    """``text`` with every generated block computed afresh (those named in ``keep`` left as they are)."""
    return BLOCK.sub(lambda m: m.group(0) if m.group("name") in keep else m.group(1) + block(m.group("name")) + m.group(4),
                     text)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m linkrepro.harness.docs", description=__doc__.split("\n")[0])
    parser.add_argument("--root", type=Path, default=Path("."), help="the source tree (default: here)")
    parser.add_argument("--check", action="store_true", help="write nothing; exit 1 where a page is out of date")
    args = parser.parse_args(argv)
    stale = []
    for path in pages(args.root):
        text = path.read_text()
        new = filled(text)
        if new != text:
            stale.append(path)
            if not args.check:
                path.write_text(new)
    for path in stale:
        print(f"{path}: {'out of date' if args.check else 'rewritten'}")
    return 1 if (stale and args.check) else 0


if __name__ == "__main__":
    sys.exit(main())
