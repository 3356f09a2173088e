"""A package's names imported when first asked for (PEP 562), not when the package is.

The scene registry and each thesis's package hand out their scenes this way: the scenes import
every engine (numpy, numba, scipy, matplotlib, pandas, the FORTRAN), about 1.3 s, while
``linkrepro --help`` only needs the theses' commands (``harness/command.py``), which live in
the same packages.
"""
from __future__ import annotations

import importlib
import sys
from typing import Any, Callable, Iterable


def deferred(package: str, module: str, names: Iterable[str]) -> Callable[[str], Any]:
    """``package``'s module-level ``__getattr__``: each of ``names`` is taken from its submodule
    ``module``, imported at the first ask, and kept on the package (asked once)."""
    names = frozenset(names)

    def __getattr__(name: str) -> Any:
        if name not in names:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(f"{package}.{module}"), name)
        setattr(sys.modules[package], name, value)
        return value
    return __getattr__
