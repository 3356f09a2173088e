"""Every scene, found by thesis: each subpackage here is one thesis and lists its scenes in
``SCENES`` (see ``harness/scene.py`` for the protocol).  Adding a thesis is adding a
subpackage; nothing here names one."""
from __future__ import annotations

import importlib
import pkgutil

from ..table_scene import TableScene

THESES = [importlib.import_module(f"{__name__}.{module.name}")
          for module in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name) if module.ispkg]
SCENES = {scene.name: scene for thesis in THESES for scene in thesis.SCENES}
#: the scenes of a published table (the others are curves, figures, claims)
TABLES = {name: scene for name, scene in SCENES.items() if isinstance(scene, TableScene)}


def get(name: str):
    try:
        return SCENES[name]
    except KeyError:
        raise KeyError(f"unknown scene {name!r}; known: {', '.join(SCENES)}") from None


def report_links(out_dir) -> list[str]:
    """The run report's lines about outputs of other commands (a thesis's ``report_links``,
    where it has one: ``linkrepro arithmetic``'s matrix for Rahman 1996)."""
    return [line for thesis in THESES for line in getattr(thesis, "report_links", lambda _: [])(out_dir)]
