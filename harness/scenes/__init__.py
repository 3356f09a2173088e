"""Every scene, found by thesis: each subpackage here is one thesis and lists its scenes in
``SCENES`` (see ``harness/scene.py`` for the protocol) and describes their CSVs' columns in
``QUANTITIES`` (see ``harness/quantities.py``).  Adding a thesis is adding a subpackage;
nothing here names one.

``THESES`` (the subpackages), ``SCENES`` and ``TABLES`` (by name) and ``get`` come from
``catalog.py`` when first asked for (``harness/lazy.py``): the scenes import every engine,
which the theses' hook modules (their commands for ``linkrepro --help``) do not need."""
from __future__ import annotations

import importlib
import pkgutil
from functools import lru_cache

from ..lazy import deferred

__getattr__ = deferred(__name__, "catalog", ("THESES", "SCENES", "TABLES", "get"))


def thesis_names() -> list[str]:
    """The theses' subpackages by name, in order, none imported."""
    return sorted(module.name for module in pkgutil.iter_modules(__path__) if module.ispkg)


def hook_modules(hook: str) -> list:
    """Each thesis's ``<hook>`` module (``bench``: its part of ``linkrepro bench``, see
    ``harness/bench.py``; ``fuzz``: its entry points, ``harness/fuzz_calls.py``; ``commands``: its
    own commands, ``harness/command.py``; ``docs``: its generated blocks of the docs,
    ``harness/docs.py``; ``differential``: its samplers and engine pairs,
    ``harness/differential.py``), where it has one; looked for once a process (each report
    asks).  Found in the thesis's folder, not by trying to import it: a module that is not there
    is asked of every importer in turn (in an editable install, each one runs the rebuild's
    ninja: some 0.1 s a miss, measured 2026-11-28)."""
    return list(_hook_modules(hook))


@lru_cache(maxsize=None)
def _hook_modules(hook: str) -> tuple:
    modules = []
    for thesis in thesis_names():
        package = importlib.import_module(f"{__name__}.{thesis}")
        if any(module.name == hook for module in pkgutil.iter_modules(package.__path__)):
            modules.append(importlib.import_module(f"{package.__name__}.{hook}"))
    return tuple(modules)


def differentials() -> dict:
    """Every thesis's part of ``linkrepro differential`` (``DIFFERENTIAL`` of its ``differential``
    module), by thesis name."""
    return {module.__name__.split(".")[-2]: module.DIFFERENTIAL for module in hook_modules("differential")}


def commands() -> list:
    """Every thesis's own commands (``COMMANDS`` of its ``commands`` module)."""
    return [command for module in hook_modules("commands") for command in module.COMMANDS]


def commands_of(thesis) -> list:
    """One thesis's own commands (a module of ``THESES``)."""
    return [command for module in hook_modules("commands") if module.__name__.rpartition(".")[0] == thesis.__name__
            for command in module.COMMANDS]


def _bench_hook(hook: str, quick: bool) -> list:
    """What each thesis's ``bench.<hook>(quick)`` returns, thesis by thesis (none: nothing)."""
    return [item for module in hook_modules("bench") for item in getattr(module, hook, lambda _: [])(quick)]


def bench_computations(quick: bool) -> list:
    """Part 1 of the bench: every thesis's ``Computation``s, timed on each engine (``quick``:
    the reduced configuration)."""
    return _bench_hook("computations", quick)


def bench_knobs(quick: bool) -> list:
    """Part 2 of the bench: every thesis's ``Knob``s (``quick``: the reduced configuration)."""
    return _bench_hook("knobs", quick)


def bench_sweeps(quick: bool) -> list:
    """Part 2 of the bench: every thesis's ``Sweep``s, knobs measured by a study of their own
    (``quick``: the reduced configuration)."""
    return _bench_hook("sweeps", quick)
