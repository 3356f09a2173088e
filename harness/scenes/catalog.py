"""Every thesis's scenes: imported when first asked for (``__init__.py``), since they import
every engine."""
from __future__ import annotations

import importlib

from ..scene import Scene
from ..table_scene import TableScene
from . import thesis_names

THESES = [importlib.import_module(f"{__package__}.{name}") for name in thesis_names()]
SCENES = {scene.name: scene for thesis in THESES for scene in thesis.SCENES}
#: the scenes of a published table (the others are curves, figures, claims)
TABLES = {name: scene for name, scene in SCENES.items() if isinstance(scene, TableScene)}


def get(name: str) -> Scene:
    try:
        return SCENES[name]
    except KeyError:
        raise KeyError(f"unknown scene {name!r}; known: {', '.join(SCENES)}") from None
