"""Cell-by-cell comparison of every engine with the published table and with legacy.

A cell's status, per engine:
``match``         within half a unit of the printed last digit;
``registered``    outside it, and a register entry explains it (ids given);
``unexplained``   outside it, and nothing in the register explains it;
``not-produced``  the engine does not give this cell (the printed listings only
                  WRITE some quantities).
For ``port_corrected`` a cell is also registered to each quirk whose switching
alone (from PRINTED) moves that cell beyond its half unit: measured, per cell.

A ``registered`` cell is not always explained: an entry of kind ``unresolved`` records that
we do not know.  ``count_cells`` is the one count every report shows (each scene's report.md,
the run's report.md, report.html's overview, the last line of ``linkrepro reproduce``): per
engine, matched / explained (by kind) / unresolved / unexplained / not-produced.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .published_tables import PublishedTable
from .register import KINDS, Deviation, by_quirk

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
    claiming = [e for e in register.values() if any(c.scene == scene.name for c in e.cells)]
    index = pub_val.index                   # every frame read at the published rows' labels

    def at(frame: pd.DataFrame | None, col: str) -> list:
        if frame is None:
            return [np.nan] * len(index)
        return (frame[col] if frame.index.equals(index) else frame.loc[index, col]).to_numpy().tolist()

    keys = (pub_val[scene.key].to_numpy() if isinstance(scene.key, str)
            else ["/".join(texts) for texts in zip(*(pub_text[k] for k in scene.keys))])
    targets = {col: at(pub_val, col) for col in scene.values}
    tols = {col: at(half, col) for col in scene.values}
    texts = {col: pub_text[col].to_numpy() for col in scene.values}
    refs = {col: at(legacy, col) for col in scene.values}
    moves = {q: {col: at(moved, col) for col in scene.values} for q, moved in (effects or {}).items()}
    rows = []
    for engine, frame in results.items():
        got = {col: at(frame, col) for col in scene.values}
        for i, key in enumerate(keys):
            for col in scene.values:
                value, target, tol, ref = (float(got[col][i]), float(targets[col][i]), float(tols[col][i]),
                                           float(refs[col][i]))
                err = abs(value - target)
                ids = [e.id for e in claiming if any(c.covers(scene.name, key, col, engine) for c in e.cells)]
                if engine == "port_corrected" and effects is not None:
                    ids += [quirk_ids[q] for q, moved in moves.items() if q in quirk_ids and bool(moved[col][i])]
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
                             "published_text": texts[col][i], "published": target,
                             "value": value, "abs_diff": err, "digits": agreed_digits(value, target),
                             "half_unit": tol, "status": status,
                             "register_ids": " ".join(sorted(set(ids))) if status != "match" else "",
                             "legacy": ref, "diff_vs_legacy": value - ref})
    return pd.DataFrame(rows)


#: what a cell counts as (``classify_cells``, ``count_cells``)
CLASSES = ("matched", "explained", "unresolved", "unexplained", "not-produced")
#: the kinds an explained cell is counted under: every kind but ``unresolved`` and
#: ``model-assumption`` (which claims no cell), and SEVERAL
SEVERAL = "several kinds"
EXPLAINED_BY = tuple(k for k in KINDS if k not in ("unresolved", "model-assumption")) + (SEVERAL,)
#: the columns of ``count_cells``: the total, then the classes with ``explained`` split by kind
COUNT_COLUMNS = ("cells", "matched", "explained", *EXPLAINED_BY, "unresolved", "unexplained", "not-produced")


def classify_cells(diff: pd.DataFrame, register: dict[str, Deviation]) -> pd.DataFrame:
    """What each row of a diff (``diff_scene``, or a diff.csv read back) counts as: a frame on
    the diff's index with ``count`` (one of CLASSES) and ``kind`` (for an explained cell, the
    kind of the entries that explain it, or SEVERAL; else "").

    - ``match`` -> matched; ``not-produced`` -> not-produced (whatever ids it carries);
      ``unexplained`` -> unexplained.
    - ``registered``: the kinds of the register entries its ids name (ids that name no entry
      of ``register`` are ignored: they explain nothing).  Entries of any kind but
      ``unresolved`` -> explained, under that kind, or under SEVERAL when they are of more than
      one kind (counted once, never under each; which kinds is in the cell's register ids).
      A cell named by an ``unresolved`` entry AND a real explanation is explained: the
      unresolved entry is ignored.  Only ``unresolved`` entries -> unresolved: we do not know.
      No entry at all (every id missing from the register) -> unexplained.
    An unresolved cell is never counted as explained or matched."""
    if diff.empty:                            # no engine ran: no rows, and maybe no columns
        return pd.DataFrame({"count": pd.Series(dtype=str), "kind": pd.Series(dtype=str)}, index=diff.index)
    ids = diff["register_ids"].fillna("").astype(str) if "register_ids" in diff else pd.Series("", index=diff.index)
    count, kind = [], []
    for status, names in zip(diff["status"], ids):
        if status == "match":
            count.append("matched"), kind.append("")
        elif status in ("not-produced", "unexplained"):
            count.append(status), kind.append("")
        elif status == "registered":
            kinds = {register[i].kind for i in names.split() if i in register}
            real = sorted(kinds - {"unresolved"})
            if real:
                count.append("explained"), kind.append(real[0] if len(real) == 1 else SEVERAL)
            else:
                count.append("unresolved" if kinds else "unexplained"), kind.append("")
        else:
            raise ValueError(f"unknown cell status {status!r}")
    return pd.DataFrame({"count": count, "kind": kind}, index=diff.index)


def count_cells(diff: pd.DataFrame, register: dict[str, Deviation]) -> pd.DataFrame:
    """Per engine (rows, in the diff's order), the cells of a scene's diff by what they count as
    (``classify_cells``): columns COUNT_COLUMNS, integers.  ``cells`` = matched + explained +
    unresolved + unexplained + not-produced, and ``explained`` = the sum of its kinds
    (EXPLAINED_BY: a cell explained by entries of several kinds counts once, under SEVERAL)."""
    classes = classify_cells(diff, register)
    engines = diff["engine"] if not diff.empty else pd.Series(dtype=str)
    tally = {engine: dict.fromkeys(COUNT_COLUMNS, 0) for engine in dict.fromkeys(engines)}
    for engine, count, kind in zip(engines, classes["count"], classes["kind"]):
        row = tally[engine]
        row["cells"] += 1
        row[count] += 1
        if kind:
            row[kind] += 1
    frame = pd.DataFrame([list(row.values()) for row in tally.values()] or None,
                         index=pd.Index(list(tally), name="engine"), columns=list(COUNT_COLUMNS), dtype=int)
    assert (frame["cells"] == frame[list(CLASSES)].sum(axis=1)).all()
    assert (frame["explained"] == frame[list(EXPLAINED_BY)].sum(axis=1)).all()
    return frame


def total_counts(counts: list[pd.DataFrame]) -> pd.Series:
    """``count_cells`` frames (scenes) added up over every engine: one count per COUNT_COLUMNS."""
    total = pd.Series(0, index=list(COUNT_COLUMNS), dtype=int)
    for frame in counts:
        total += frame[list(COUNT_COLUMNS)].sum(axis=0).astype(int)
    return total


def headline(total: pd.Series, by_kind: bool = False) -> str:
    """The counts in words (``total_counts``, or one engine's row of ``count_cells``): 'N cells:
    a matched, b explained, c unresolved, d unexplained, e not produced'; the five add up to N.
    ``by_kind``: the explained cells' kinds that count any, after b ('b explained (KIND k, ...)')."""
    kinds = ", ".join(f"{k} {total[k]}" for k in EXPLAINED_BY if total[k])
    explained = f"{total['explained']} explained" + (f" ({kinds})" if by_kind and kinds else "")
    return (f"{total['cells']} cells: {total['matched']} matched, {explained}, "
            f"{total['unresolved']} unresolved, {total['unexplained']} unexplained, "
            f"{total['not-produced']} not produced")


def column_max(diff: pd.DataFrame, what: str = "abs_diff") -> pd.DataFrame:
    """Per engine and column: the largest |difference| over produced cells."""
    produced = diff[diff["status"] != "not-produced"].copy()
    produced["v"] = produced[what].abs()
    return produced.pivot_table(index="engine", columns="column", values="v", aggfunc="max")
