"""A scene's results as pandas DataFrames with their units: ``load(scene, out)``.

Each CSV of the scene's folder (``linkrepro reproduce --out OUT`` writes ``OUT/<scene>/``)
becomes a DataFrame keyed by its file stem, with

- ``attrs["units"]``: {column: unit} for every column whose unit is fixed ("in", "deg",
  "lbf", "lbf in", "lbf s^2 in", "%", "s", ...; "" for a pure number or a text);
- ``attrs["scene"]`` and ``attrs["path"]`` (the CSV read);
- in a long file whose unit changes from row to row (diff.csv: the table column each row
  names; a curve's quantity), a ``unit`` column: that row's unit for those columns.

What each column means: ``describe(scene, column)``, a ``harness.quantities.Quantity``.
"""
from __future__ import annotations

import tempfile
import warnings
from functools import lru_cache
from pathlib import Path

import pandas as pd

from . import progress
from .quantities import DIFF, Quantity
from .scene import RunOptions


@lru_cache(maxsize=None)
def described(scene: str) -> dict[str, Quantity]:
    """Every name ``scene``'s CSVs use (columns, and the row quantities of its long files),
    described.  KeyError naming the known scenes if ``scene`` is not one."""
    from . import scenes                   # every thesis's engines: imported when first asked
    scenes.get(scene)
    names = dict(DIFF) if scene in scenes.TABLES else {}
    for thesis in scenes.THESES:
        names.update(getattr(thesis, "QUANTITIES", {}).get(scene, {}))
    return names


def describe(scene: str, column: str) -> Quantity:
    """What ``column`` (or a row's quantity) of ``scene``'s CSVs means, and its unit.
    KeyError, saying what is described, if the scene or the name is unknown."""
    names = described(scene)
    try:
        return names[column]
    except KeyError:
        raise KeyError(f"scene {scene!r} describes no column or quantity {column!r}; it describes "
                       f"{', '.join(names) or 'nothing'}") from None


def load(scene: str, out: str | Path | None = None) -> dict[str, pd.DataFrame]:
    """Every CSV of ``scene``'s output as a DataFrame, keyed by file stem (``published``,
    ``diff``, ``curves``, ...), read from ``out/<scene>/`` when that folder exists; otherwise
    the scene is run first (without the gfortran readings) into a new temporary folder,
    which is kept (``attrs["path"]`` points into it, beside the scene's figures and report).
    KeyError naming the known scenes if ``scene`` is not one."""
    from .scenes import get                # every thesis's engines: imported when first asked
    the_scene = get(scene)
    folder = Path(out) / scene if out is not None else None
    if folder is None or not folder.is_dir():
        folder = _run(the_scene)
    paths = sorted(folder.glob("*.csv"))
    if not paths:
        raise FileNotFoundError(f"no CSV in {folder}: is it the output of scene {scene}?")
    return {path.stem: read(scene, path) for path in paths}


def read(scene: str, path: str | Path) -> pd.DataFrame:
    """One CSV of ``scene``'s output, with its units (see the module's docstring).
    KeyError if a column is not described (``describe``)."""
    frame = pd.read_csv(path)
    described = {column: describe(scene, column) for column in frame.columns}
    keys = {q.per_row for q in described.values() if q.per_row}
    if len(keys) > 1:
        raise ValueError(f"{path}: units named by several columns ({', '.join(sorted(keys))}), one unit column")
    if keys:
        key = keys.pop()
        frame["unit"] = frame[key].map({name: describe(scene, name).unit for name in frame[key].unique()})
    frame.attrs.update(scene=scene, path=Path(path),
                       units={column: q.unit for column, q in described.items() if not q.per_row})
    return frame


def _run(scene) -> Path:
    """Run ``scene`` (RunOptions(measure_readings=False)) into a new temporary folder; its
    folder in it.  A progress line on standard error when it is a terminal."""
    out = Path(tempfile.mkdtemp(prefix=f"linkrepro-{scene.name}-"))
    with progress.Bar(1):
        progress.note(scene.name, "running")
        outcome = scene.write(out, RunOptions(measure_readings=False))
        progress.done(scene.name)
    for failure in outcome.failures:
        warnings.warn(f"{scene.name}: {failure}", RuntimeWarning, stacklevel=3)
    return out / scene.name
