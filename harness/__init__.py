"""The harness: scenes, engines, cell-by-cell diff against the published tables, report.

``load(scene, out=None)`` (``harness/results.py``): a scene's CSVs as pandas DataFrames with
their units; ``describe(scene, column)`` (also ``harness/results.py``): what a column means, in
words, and its unit.  Both are imported when first used (the scenes import every engine).
"""
from __future__ import annotations

from .lazy import deferred

__all__ = ["load", "describe"]
__getattr__ = deferred(__name__, "results", __all__)
