"""The harness: scenes, engines, cell-by-cell diff against the published tables, report.

``load(scene, out=None)`` (``harness/results.py``): a scene's CSVs as pandas DataFrames with
their units; ``describe(scene, column)`` (also ``harness/results.py``): what a column means, in
words, and its unit.  Both are imported when first used (the scenes import every engine).
"""
from __future__ import annotations

_LAZY = {"load": "results", "describe": "results"}
__all__ = list(_LAZY)


def __getattr__(name: str):
    if name in _LAZY:
        import importlib
        return getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
