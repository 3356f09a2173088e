"""``out/report.html``: the run's report as one self-contained page (inline style, script and
figures; nothing fetched when it is viewed), rendered with Jinja2 from ``templates/report.html.j2``.

Per table scene: the published table in its printed layout, each cell coloured by what it counts as
for the engine chosen in the page's selector (``diff.classify_cells``: match, explained, unresolved,
unexplained, not-produced), with the digits it agrees to; a click (or Enter) on a
cell opens its trail (``harness/trail.py``): every engine's value, the register entries, the
listing lines.  Then the scene's figures, and an overview of every table and engine
(``diff.count_cells``, the counts every report shows).
"""
from __future__ import annotations

import base64
import json
import math
from pathlib import Path

import jinja2
import pandas as pd

from . import listing_lines, register as register_mod
from .diff import CLASSES, COUNT_COLUMNS, classify_cells, count_cells, headline, total_counts
from .engines import ENGINES
from .register import Deviation
from .report import heading
from .scene import Outcome
from .scenes import SCENES, TABLES
from .trail import printed_digits, published_source, read_diff

TEMPLATES = Path(__file__).resolve().parent / "templates"
#: tagged src edits shown per register entry (the rest are counted)
EDITS_SHOWN = 8
#: what a cell is coloured as: ``diff.classify_cells``'s class, a matched cell shown as ``match``
#: (its status in diff.csv); diff.csv's ``registered`` split into explained and unresolved
SHOWN = {"matched": "match"}
CELL_STATUSES = tuple(SHOWN.get(c, c) for c in CLASSES)


def data_uri(path: Path) -> str:
    """A PNG or SVG file as a ``data:`` URI, for an ``<img>`` that needs no other file."""
    kind = "image/svg+xml" if path.suffix == ".svg" else "image/png"
    return f"data:{kind};base64," + base64.b64encode(path.read_bytes()).decode("ascii")


def _line(line: listing_lines.ListingLine) -> dict:
    return {"where": line.where(), "text": line.text.rstrip(), "tier": line.tier}


def _entry(entry: Deviation) -> dict:
    edits = listing_lines.tagged(entry.id)
    return {"id": entry.id, "kind": entry.kind, "certainty": entry.certainty, "title": entry.title,
            "fields": [(name, getattr(entry, name)) for name in ("where", "printed", "meant", "evidence", "effect")],
            "quirk": entry.quirk, "cited": [_line(c) for c in listing_lines.cited(entry)],
            "edits": [_line(e) for e in edits[:EDITS_SHOWN]], "more_edits": max(0, len(edits) - EDITS_SHOWN)}


def _number(value: float) -> str | None:
    return None if math.isnan(value) else f"{value:.9g}"


def table_view(scene, diff: pd.DataFrame, register: dict[str, Deviation], blocks: dict, cells: dict) -> dict:
    """The published table as printed (rows, columns, what each cell counts as per engine:
    CELL_STATUSES) for the template; each cell's trail data goes into ``cells`` and its listing
    lines into ``blocks``."""
    key = scene.key_name
    classes = classify_cells(diff, register)
    diff = diff.assign(shown=classes["count"].map(lambda c: SHOWN.get(c, c)), kind=classes["kind"])
    rows = []
    for row_key in dict.fromkeys(diff[key].astype(str)):
        row = diff[diff[key].astype(str) == row_key]
        shown = []
        for column in scene.values:
            here = row[row["column"] == column]
            if here.empty:
                continue
            first = here.iloc[0]
            engines = {}
            for r in here.itertuples(index=False):
                ids = r.register_ids if isinstance(r.register_ids, str) else ""
                engines[r.engine] = {"status": r.shown, "kind": r.kind, "value": _number(float(r.value)),
                                     "difference": _number(float(r.abs_diff)),
                                     "digits": None if math.isnan(r.digits) else min(float(r.digits), 99.0),
                                     "ids": ids.split()}
            cell_id = f"{scene.name}|{row_key}|{column}"
            lines = tuple(line for s in scene.statements(str(first[key]), column) for line in listing_lines.find(s))
            block = blocks.setdefault(lines, f"L{len(blocks)}")
            cells[cell_id] = {"scene": scene.name, "row": row_key, "column": column,
                              "published": str(first["published_text"]), "half_unit": float(first["half_unit"]),
                              "printed_digits": printed_digits(str(first["published_text"])),
                              "engines": engines, "lines": block}
            shown.append({"id": cell_id, "text": str(first["published_text"]),
                          "status": {e: v["status"] for e, v in engines.items()},
                          "digits": {e: v["digits"] for e, v in engines.items()}})
        rows.append({"key": row_key, "cells": shown})
    return {"key": key, "columns": [c for c in scene.values if c in set(diff["column"])], "rows": rows,
            "source": published_source(scene.table)}


def overview(counts: pd.DataFrame) -> list[dict]:
    """A scene's ``diff.count_cells`` (cells; matched, explained by kind, unresolved,
    unexplained, not-produced) as the overview's rows, the engines in their order."""
    return [{"engine": engine, **{c: int(counts.at[engine, c]) for c in counts.columns}}
            for engine in ENGINES if engine in counts.index]


def figures(folder: Path) -> list[dict]:
    """Every figure a scene wrote (PNG or SVG), inline."""
    return [{"name": p.name, "uri": data_uri(p)} for p in sorted(folder.glob("*.png")) + sorted(folder.glob("*.svg"))]


def render(out_dir: Path, done: list[Outcome], bench_dir: Path | None = None) -> str:
    """The page's HTML for the scenes of ``done`` (written in ``out_dir``)."""
    register = register_mod.load()
    blocks: dict[tuple, str] = {}
    cells: dict[str, dict] = {}
    scenes, used, counted = [], set(), []
    for item in done:
        scene, folder = SCENES[item.scene], out_dir / item.scene
        view = {"name": item.scene, "title": item.title, "seconds": item.seconds, "failures": item.failures,
                "overview": item.overview, "figures": figures(folder) if folder.is_dir() else [], "table": None}
        if item.scene in TABLES and (folder / "diff.csv").is_file():
            diff = read_diff(TABLES[item.scene], out_dir)
            view["table"] = table_view(scene, diff, register, blocks, cells)
            counted.append(count_cells(diff, register))
            view["counts"] = overview(counted[-1])
            used |= {i for ids in diff["register_ids"].fillna("") for i in str(ids).split()}
        scenes.append(view)
    bench = figures(bench_dir) if bench_dir is not None and bench_dir.is_dir() else []
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(TEMPLATES), autoescape=True,
                             undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True)
    return env.get_template("report.html.j2").render(
        scenes=scenes, engines=ENGINES, statuses=CELL_STATUSES,
        columns=[(c, heading(c)) for c in COUNT_COLUMNS], total=headline(total_counts(counted), by_kind=True),
        entries=[_entry(register[i]) for i in sorted(used) if i in register],
        blocks={block: [_line(line) for line in lines] for lines, block in blocks.items()},
        cells_json=json.dumps(cells, separators=(",", ":")).replace("</", "<\\/"),
        bench=bench, bench_dir=str(bench_dir) if bench_dir else "")


def write(out_dir: Path, done: list[Outcome], bench_dir: Path | None = None) -> Path:
    """Write ``out_dir/report.html``; returns its path."""
    path = Path(out_dir) / "report.html"
    path.write_text(render(Path(out_dir), done, bench_dir))
    return path

