"""Cell-by-cell comparison of every engine with the published table and with legacy.

A cell's status, per engine:
``match``         within half a unit of the printed last digit;
``registered``    outside it, and a register entry explains it (ids given);
``unexplained``   outside it, and nothing in the register explains it;
``not-produced``  the engine does not give this cell (the printed listings only
                  WRITE some quantities).
For ``port_corrected`` a cell is also registered to each quirk whose switching
alone (from PRINTED) moves that cell beyond its half unit: measured, per cell.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .published_tables import PublishedTable
from .register import Deviation, by_quirk

if TYPE_CHECKING:
    from .table_scene import TableScene

STATUSES = ("match", "registered", "unexplained", "not-produced")


def agreed_digits(value: float, published: float) -> float:
    """Significant digits two numbers share: -log10 of their relative difference (inf when
    equal, NaN when ``value`` is NaN; a published zero counts the difference itself)."""
    if math.isnan(value):
        return math.nan
    error = abs(value - published)
    if error == 0.0:
        return math.inf
    return max(0.0, -math.log10(error / abs(published) if published else error))


def quirk_effects(scene: TableScene, published: PublishedTable, base: pd.DataFrame) -> dict[str, pd.DataFrame]:
    """For each quirk: a boolean frame, True where switching it off alone moves a cell
    of the PRINTED port by more than that cell's half unit."""
    half = published.half_unit
    printed = scene.quirks[0]
    effects = {}
    for name in printed.names():
        moved = scene.port(printed.only(name, False))
        delta = (moved[scene.values] - base[scene.values]).abs()
        effects[name] = delta > half[scene.values].to_numpy()
    return effects


def diff_scene(scene: TableScene, published: PublishedTable, results: dict[str, pd.DataFrame],
               register: dict[str, Deviation]) -> pd.DataFrame:
    """Long table: one row per (engine, published cell)."""
    pub_val, pub_text, half = published.values, published.text, published.half_unit
    legacy = results.get("legacy")
    effects = None
    if "port_corrected" in results:
        base = results.get("port_printed")
        effects = quirk_effects(scene, published, base if base is not None else scene.port(scene.quirks[0]))
    quirk_ids = {name: entry.id for name, entry in by_quirk(register).items()}
    rows = []
    for engine, frame in results.items():
        for i in range(len(pub_val)):
            key = (pub_val.at[i, scene.key] if isinstance(scene.key, str)
                   else "/".join(pub_text.at[i, k] for k in scene.keys))
            for col in scene.values:
                value = float(frame.at[i, col])
                target, tol = float(pub_val.at[i, col]), float(half.at[i, col])
                ref = float(legacy.at[i, col]) if legacy is not None else np.nan
                err = abs(value - target)
                ids = [e.id for e in register.values()
                       if any(c.covers(scene.name, key, col, engine) for c in e.cells)]
                if engine == "port_corrected" and effects is not None:
                    ids += [quirk_ids[q] for q, moved in effects.items()
                            if q in quirk_ids and bool(moved.at[i, col])]
                if np.isnan(value):
                    status = "not-produced"
                elif err <= tol * (1.0 + 1e-9):
                    status = "match"
                elif scene.floor_id and err <= scene.rel_floor * abs(target):
                    ids.append(scene.floor_id)
                    status = "registered"
                elif ids:
                    status = "registered"
                else:
                    status = "unexplained"
                rows.append({"scene": scene.name, "engine": engine, scene.key_name: key, "column": col,
                             "published_text": pub_text.at[i, col], "published": target,
                             "value": value, "abs_diff": err, "digits": agreed_digits(value, target),
                             "half_unit": tol, "status": status,
                             "register_ids": " ".join(sorted(set(ids))) if status != "match" else "",
                             "legacy": ref, "diff_vs_legacy": value - ref})
    return pd.DataFrame(rows)


def summary(diff: pd.DataFrame) -> pd.DataFrame:
    """Counts of each status per engine."""
    counts = diff.groupby(["engine", "status"]).size().unstack(fill_value=0)
    return counts.reindex(columns=list(STATUSES), fill_value=0)


def column_max(diff: pd.DataFrame, what: str = "abs_diff") -> pd.DataFrame:
    """Per engine and column: the largest |difference| over produced cells."""
    produced = diff[diff["status"] != "not-produced"].copy()
    produced["v"] = produced[what].abs()
    return produced.pivot_table(index="engine", columns="column", values="v", aggfunc="max")
