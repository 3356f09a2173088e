"""Cell-by-cell comparison of every engine with the published table and with legacy.

A cell's status, per engine (diff.csv's ``status``):
``match``         within half a unit of the printed last digit;
``registered``    outside it, and register entries name it (ids given);
``unexplained``   outside it, and nothing in the register names it;
``not-produced``  the engine does not give this cell (the printed listings only
                  WRITE some quantities).
The entries a cell names: those whose ``cells`` claim it; for ``port_corrected`` also each
quirk whose switching alone (from PRINTED) moves that cell beyond its half unit (measured, per
cell); and a scene's ``floor_id`` where the cell is within the scene's ``rel_floor`` relative of
the printed value (the entry must state that tolerance: its ``tolerance`` field).

What a cell counts as (``classify_cells``; ``count_cells`` is the one count every report shows:
each scene's report.md, the run's report.md, report.html's overview and cell colours, the
lines of ``linkrepro reproduce``, README's generated tables, ``linkrepro explain``): per engine,
matched / explained (by kind) / within tolerance / unresolved / unexplained / not-produced.
Of a ``registered`` cell's entries, an entry that states a ``tolerance`` explains it only by
closeness, an ``unresolved`` one says we do not know, any other explains it by a cause:

- a cause that accounts for the cell's whole difference (its claim says ``whole = true``)
  -> explained, whatever else names the cell;
- an ``unresolved`` entry -> unresolved: it wins over causes that do not account for the
  whole difference, and over any tolerance (closeness does not remove a known cause);
- else a cause -> explained (counted under its kind, once);
- else a tolerance only -> within tolerance: counted apart, not explained.
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


def check_floor(scene: TableScene, register: dict[str, Deviation]) -> None:
    """A scene's ``floor_id`` must name an entry stating the scene's ``rel_floor`` as its
    ``tolerance`` (ValueError otherwise): the cells within it are explained by closeness only."""
    if not scene.floor_id:
        return
    entry = register.get(scene.floor_id)
    stated = entry.tolerance if entry is not None else None
    if stated != scene.rel_floor:
        raise ValueError(f"scene {scene.name}: floor_id {scene.floor_id} states "
                         f"{'no entry' if entry is None else f'tolerance {stated!r}'}, not the scene's "
                         f"rel_floor {scene.rel_floor!r} (give the entry `tolerance = {scene.rel_floor!r}`)")


def diff_scene(scene: TableScene, published: PublishedTable, results: dict[str, pd.DataFrame],
               register: dict[str, Deviation]) -> pd.DataFrame:
    """Long table: one row per (engine, published cell).  A cell that misses the printed digit
    is registered to the ids the scene's ``explained_by_run`` gives it (a run reaches the digit)
    before any tolerance (``floor_id``) is asked."""
    pub_val, pub_text, half = published.values, published.text, published.half_unit
    legacy = results.get("legacy")
    effects = None
    if "port_corrected" in results:
        base = results.get("port_printed")
        effects = quirk_effects(scene, published, base if base is not None else scene.port(scene.quirks[0]))
    check_floor(scene, register)
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
                elif run := scene.explained_by_run(key, col, engine):      # a run reaches the digit
                    ids += run
                    status = "registered"
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


#: what a cell counts as (``classify_cells``, ``count_cells``); in words with a space for the hyphen
CLASSES = ("matched", "explained", "within-tolerance", "unresolved", "unexplained", "not-produced")
#: the kinds an explained cell is counted under: every kind but ``unresolved`` and
#: ``model-assumption`` (which claims no cell), and SEVERAL
SEVERAL = "several kinds"
EXPLAINED_BY = tuple(k for k in KINDS if k not in ("unresolved", "model-assumption")) + (SEVERAL,)
#: the columns of ``count_cells``: the total, then the classes with ``explained`` split by kind
COUNT_COLUMNS = ("cells", "matched", "explained", *EXPLAINED_BY, *CLASSES[2:])


def words(column: str) -> str:
    """A class or count column as a sentence says it ('within-tolerance' -> 'within tolerance')."""
    return column.replace("-", " ")


def _key_column(diff: pd.DataFrame) -> str:
    """The diff's row key (``diff_scene`` puts it right after ``engine``)."""
    return diff.columns[list(diff.columns).index("engine") + 1]


def classify_cells(diff: pd.DataFrame, register: dict[str, Deviation]) -> pd.DataFrame:
    """What each row of a diff (``diff_scene``, or a diff.csv read back) counts as: a frame on
    the diff's index with ``count`` (one of CLASSES) and ``kind`` (for an explained cell, the
    kind of the entries that explain it, or SEVERAL; else "").  The rules: the module's
    docstring.  ``match`` -> matched; ``not-produced`` -> not-produced (whatever ids it
    carries); ``unexplained`` -> unexplained; ``registered`` by its entries (ids that name no
    entry of ``register`` are ignored: they explain nothing; none left -> unexplained).  A
    cell explained by causes of several kinds counts once, under SEVERAL (which kinds: its
    register ids).  A ``whole`` claim is looked up by the diff's ``scene``, ``engine``,
    ``column`` and row key."""
    if diff.empty:                            # no engine ran: no rows, and maybe no columns
        return pd.DataFrame({"count": pd.Series(dtype=str), "kind": pd.Series(dtype=str)}, index=diff.index)
    ids = diff["register_ids"].fillna("").astype(str) if "register_ids" in diff else pd.Series("", index=diff.index)
    wholes = any(claim.whole for entry in register.values() for claim in entry.cells)
    if wholes and not {"scene", "engine", "column"} <= set(diff.columns):
        raise ValueError("the register's 'whole' claims need the diff's scene, engine, row key and column; "
                         f"this diff has {list(diff.columns)}")
    cells = (zip(diff["scene"], diff[_key_column(diff)], diff["column"], diff["engine"]) if wholes
             else [None] * len(diff))
    count, kind = [], []
    for status, names, cell in zip(diff["status"], ids, cells):
        if status == "match":
            count.append("matched"), kind.append("")
        elif status in ("not-produced", "unexplained"):
            count.append(status), kind.append("")
        elif status == "registered":
            counted = _registered([register[i] for i in names.split() if i in register], cell)
            count.append(counted[0]), kind.append(counted[1])
        else:
            raise ValueError(f"unknown cell status {status!r}")
    return pd.DataFrame({"count": count, "kind": kind}, index=diff.index)


def _registered(entries: list[Deviation], cell: tuple | None) -> tuple[str, str]:
    """(class, kind) of a registered cell named by ``entries`` (``cell``: its scene, row key,
    column and engine, for ``whole`` claims; None where the register has none)."""
    causes = [e for e in entries if e.kind != "unresolved" and e.tolerance is None]
    unresolved = any(e.kind == "unresolved" for e in entries)
    if causes and (not unresolved or (cell is not None and any(c.whole and c.covers(*cell)
                                                               for e in causes for c in e.cells))):
        kinds = sorted({e.kind for e in causes})
        return "explained", kinds[0] if len(kinds) == 1 else SEVERAL
    if unresolved:
        return "unresolved", ""
    return ("within-tolerance" if entries else "unexplained"), ""


def count_cells(diff: pd.DataFrame, register: dict[str, Deviation]) -> pd.DataFrame:
    """Per engine (rows, in the diff's order), the cells of a scene's diff by what they count as
    (``classify_cells``): columns COUNT_COLUMNS, integers.  ``cells`` = the sum of CLASSES
    (matched + explained + within-tolerance + unresolved + ...), ``explained`` = the sum of its kinds
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
    a matched, b explained, t within tolerance, c unresolved, d unexplained, e not produced'
    (CLASSES, in order); they add up to N.  ``by_kind``: the explained cells' kinds that count
    any, after b ('b explained (KIND k, ...)')."""
    kinds = ", ".join(f"{k} {total[k]}" for k in EXPLAINED_BY if total[k])
    parts = [f"{total[c]} {words(c)}" + (f" ({kinds})" if c == "explained" and by_kind and kinds else "")
             for c in CLASSES]
    return f"{total['cells']} cells: " + ", ".join(parts)


def column_max(diff: pd.DataFrame, what: str = "abs_diff") -> pd.DataFrame:
    """Per engine and column: the largest |difference| over produced cells."""
    produced = diff[diff["status"] != "not-produced"].copy()
    produced["v"] = produced[what].abs()
    return produced.pivot_table(index="engine", columns="column", values="v", aggfunc="max")
