"""The project's imports run one way: no cycle, and the generic layer knows no thesis.

The graph is built from the source (every ``import`` and ``from ... import``, relative ones
resolved, those inside functions included, those under ``if TYPE_CHECKING:`` left out: they
never run), with the installed names (``package/`` is ``linkrepro``, ``legacy/`` is
``linkrepro.legacy``, ...).  The scene registry (``harness/scenes/__init__.py``) imports every
thesis's subpackage, and each thesis's hook modules (bench, fuzz, commands), at run time by
name, and a thesis's command the module that does its work (``harness/command.py``): those
edges are added here, so that a module the registry reaches which asks the registry back is a
cycle too.

Rules:
- no import cycle among the project's modules;
- no generic module (``harness/*.py``) imports a thesis's module (``harness/scenes/<thesis>/``,
  ``port/<thesis>/``, ``legacy/<thesis>.py``);
- only the top of the harness asks the registry (TOP below).
"""
from __future__ import annotations

import ast
import importlib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TIERS = {"package": "linkrepro", "legacy": "linkrepro.legacy", "port": "linkrepro.port", "harness": "linkrepro.harness"}
THESES = ("ali1977", "rahman1996", "rahman1991")
REGISTRY = "linkrepro.harness.scenes"
#: the registry's hook modules: a thesis's ``<thesis>/<hook>.py``, imported by name where it has one
HOOKS = ("bench", "fuzz", "commands", "docs", "differential")
#: the top of the harness: the commands and report writers, which may ask the registry
TOP = {f"linkrepro.harness.{name}" for name in ("run", "cli", "html_report", "results", "bench_run", "fuzz", "fuzz_folders", "docs", "report_folder")}


def modules() -> dict[str, tuple[Path, bool]]:
    """Installed module name -> (its file, whether it is a package's __init__)."""
    out = {}
    for tier, package in TIERS.items():
        for path in (ROOT / tier).rglob("*.py"):
            parts = list(path.relative_to(ROOT / tier).with_suffix("").parts)
            is_package = parts[-1] == "__init__"
            out[".".join([package] + (parts[:-1] if is_package else parts))] = (path, is_package)
    return out


MODULES = modules()


def _type_checking_only(tree: ast.Module) -> set[int]:
    """Line numbers of the imports under ``if TYPE_CHECKING:``."""
    lines = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and getattr(node.test, "id", getattr(node.test, "attr", "")) == "TYPE_CHECKING":
            lines |= {n.lineno for n in ast.walk(node) if isinstance(n, (ast.Import, ast.ImportFrom))}
    return lines


def _targets(name: str, is_package: bool, node) -> list[str]:
    if isinstance(node, ast.Import):
        return [alias.name for alias in node.names]
    base = name if is_package else name.rsplit(".", 1)[0]
    for _ in range(max(0, node.level - 1)):
        base = base.rsplit(".", 1)[0]
    module = (f"{base}.{node.module}" if node.module else base) if node.level else node.module
    return [f"{module}.{alias.name}" if f"{module}.{alias.name}" in MODULES else module for alias in node.names]


def _known(target: str) -> str | None:
    """The project module a dotted name lies in (a name imported from it: its module)."""
    while target not in MODULES and "." in target:
        target = target.rsplit(".", 1)[0]
    return target if target in MODULES else None


def graph() -> dict[str, set[str]]:
    """Module -> the project modules it imports; and the registry's run-time edges."""
    edges = {}
    for name, (path, is_package) in MODULES.items():
        tree = ast.parse(path.read_text())
        skip = _type_checking_only(tree)
        found = set()
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)) and node.lineno not in skip:
                found |= {m for m in map(_known, _targets(name, is_package, node)) if m and m != name}
        edges[name] = found
    for thesis in THESES:
        package = f"{REGISTRY}.{thesis}"
        edges[REGISTRY] |= {m for m in (package, *(f"{package}.{hook}" for hook in HOOKS)) if m in MODULES}
        if f"{package}.commands" in MODULES:
            edges[f"{package}.commands"] |= {command.work for command in
                                             importlib.import_module(f"{package}.commands").COMMANDS}
    return edges


def cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return found


def is_generic(module: str) -> bool:
    """A module of the harness's generic layer (``harness/*.py``; the registry finds theses)."""
    return module.startswith("linkrepro.harness.") and module.count(".") == 2 and module != REGISTRY


def is_thesis(module: str) -> bool:
    return any(module == f"{REGISTRY}.{t}" or module.startswith(f"{REGISTRY}.{t}.")
               or module == f"linkrepro.port.{t}" or module.startswith(f"linkrepro.port.{t}.")
               or module == f"linkrepro.legacy.{t}" for t in THESES)


def test_the_graph_sees_every_module_and_the_registry():
    edges = graph()
    assert "linkrepro.harness.table_scene" in edges and "linkrepro.port.ali1977.case1" in edges
    assert f"{REGISTRY}.ali1977" in edges[REGISTRY]
    assert f"{REGISTRY}.rahman1996.arithmetic" in edges[f"{REGISTRY}.rahman1996.commands"]


def test_no_import_cycle():
    assert cycles(graph()) == []


def test_the_generic_harness_imports_no_thesis():
    edges = graph()
    wrong = {m: sorted(d for d in deps if is_thesis(d)) for m, deps in edges.items() if is_generic(m)}
    assert {m: d for m, d in wrong.items() if d} == {}


def test_only_the_top_of_the_harness_asks_the_registry():
    edges = graph()
    askers = {m for m, deps in edges.items() if REGISTRY in deps and not m.startswith(f"{REGISTRY}.")}
    assert askers <= TOP, sorted(askers - TOP)


def test_the_rules_catch_what_they_forbid():
    """The checks fail on a cycle and on a generic-to-thesis import (they can fail)."""
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": set()}) == [["a", "b", "c"]]
    assert is_generic("linkrepro.harness.diff") and not is_generic(f"{REGISTRY}.ali1977.tables")
    assert is_thesis("linkrepro.port.ali1977.case1") and is_thesis("linkrepro.legacy.rahman1996")
    assert not is_thesis("linkrepro.port.real4") and not is_thesis(REGISTRY) and not is_generic(REGISTRY)
