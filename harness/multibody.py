"""Exudyn, the established multibody code the corrected engines are checked against (optional).

Exudyn (University of Innsbruck, BSD-3-Clause; PyPI ``exudyn``) is independently written: the
scenes that model a thesis's mechanism in it (``harness/scenes/<thesis>/multibody*.py``) are a
check of the ports' physics by code not written here.  It is an optional dependency, pinned
(``PINNED``) as the extra ``linkrepro[multibody]``; ``make test`` and ``make reproduce`` install
it.  Without it, ``require()`` raises ``ExudynMissing`` (a ``SceneSkipped``): the scenes that
need it are skipped with the command that installs it, the tests that need it are skipped
(``tests/multibody.py``), never failed.
"""
from __future__ import annotations

import importlib.metadata
from types import ModuleType

from .scene import SceneSkipped

DISTRIBUTION = "exudyn"
#: the version the scenes' tolerances were measured with (pyproject.toml's extra pins the same)
PINNED = "1.13.6"
INSTALL = "pip install 'linkrepro[multibody]'"


class ExudynMissing(SceneSkipped, ImportError):
    """Exudyn is not installed (or not importable) here."""


def version() -> str | None:
    """The installed Exudyn's version, None where there is none."""
    try:
        return importlib.metadata.version(DISTRIBUTION)
    except importlib.metadata.PackageNotFoundError:
        return None


def available() -> bool:
    """Whether Exudyn can be imported here (``require`` would return it)."""
    try:
        require()
    except ExudynMissing:
        return False
    return True


def require() -> ModuleType:
    """The ``exudyn`` module, its ``utilities`` loaded (they add ``mbs.Create...``);
    ``ExudynMissing`` saying how to install it where it cannot be imported."""
    try:
        import exudyn
        import exudyn.utilities  # noqa: F401  (registers MainSystem.Create*)
    except ImportError as exc:
        raise ExudynMissing(f"needs Exudyn {PINNED}, not importable here ({exc}); `{INSTALL}` installs it, "
                            "`make reproduce` and `make test` do") from exc
    return exudyn
