"""``out/report.html``: the run's report as one self-contained page (inline style, script and
figures; nothing fetched when it is viewed), rendered with Jinja2 from ``templates/report.html.j2``.

Per table scene: the published table in its printed layout, each cell coloured by its status for
the engine chosen in the page's selector, with the digits it agrees to; a click (or Enter) on a
cell opens its trail (``harness/trail.py``): every engine's value, the register entries, the
listing lines.  Then the scene's figures, and an overview of every table and engine.
"""
from __future__ import annotations

import base64
import json
import math
from pathlib import Path

import jinja2
import pandas as pd

from . import listing_lines, register as register_mod
from .diff import STATUSES, summary
from .engines import ENGINES
from .register import KINDS, Deviation
from .report import registered_by_kind
from .scene import Outcome
from .scenes import SCENES, TABLES
from .trail import printed_digits, published_source, read_diff

TEMPLATES = Path(__file__).resolve().parent / "templates"
#: tagged src edits shown per register entry (the rest are counted)
EDITS_SHOWN = 8


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


def table_view(scene, diff: pd.DataFrame, blocks: dict, cells: dict) -> dict:
    """The published table as printed (rows, columns, the cells' statuses per engine) for the
    template; each cell's trail data goes into ``cells`` and its listing lines into ``blocks``."""
    key = scene.key_name
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
                engines[r.engine] = {"status": r.status, "value": _number(float(r.value)),
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


def overview(diff: pd.DataFrame, register: dict[str, Deviation]) -> list[dict]:
    """Per engine: cells by status (``diff.summary``) and registered cells by the kind of entry
    (``report.registered_by_kind``: a cell explained by entries of several kinds counts under each)."""
    counts = summary(diff)
    kinds = registered_by_kind(diff.fillna({"register_ids": ""}), register).reindex(
        index=counts.index, columns=list(KINDS), fill_value=0)
    return [{"engine": engine, "cells": int(counts.loc[engine].sum()),
             **{s: int(counts.at[engine, s]) for s in STATUSES},
             "kinds": {k: int(kinds.at[engine, k]) for k in KINDS}}
            for engine in ENGINES if engine in counts.index]


def figures(folder: Path) -> list[dict]:
    """Every figure a scene wrote (PNG or SVG), inline."""
    return [{"name": p.name, "uri": data_uri(p)} for p in sorted(folder.glob("*.png")) + sorted(folder.glob("*.svg"))]


def render(out_dir: Path, done: list[Outcome], bench_dir: Path | None = None) -> str:
    """The page's HTML for the scenes of ``done`` (written in ``out_dir``)."""
    register = register_mod.load()
    blocks: dict[tuple, str] = {}
    cells: dict[str, dict] = {}
    scenes, used = [], set()
    for item in done:
        scene, folder = SCENES[item.scene], out_dir / item.scene
        view = {"name": item.scene, "title": item.title, "seconds": item.seconds, "failures": item.failures,
                "overview": item.overview, "figures": figures(folder) if folder.is_dir() else [], "table": None}
        if item.scene in TABLES and (folder / "diff.csv").is_file():
            diff = read_diff(TABLES[item.scene], out_dir)
            view["table"] = table_view(scene, diff, blocks, cells)
            view["counts"] = overview(diff, register)
            used |= {i for ids in diff["register_ids"].fillna("") for i in str(ids).split()}
        scenes.append(view)
    bench = figures(bench_dir) if bench_dir is not None and bench_dir.is_dir() else []
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(TEMPLATES), autoescape=True,
                             undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True)
    return env.get_template("report.html.j2").render(
        scenes=scenes, engines=ENGINES, statuses=STATUSES, kinds=KINDS,
        entries=[_entry(register[i]) for i in sorted(used) if i in register],
        blocks={block: [_line(line) for line in lines] for lines, block in blocks.items()},
        cells_json=json.dumps(cells, separators=(",", ":")).replace("</", "<\\/"),
        bench=bench, bench_dir=str(bench_dir) if bench_dir else "")


def write(out_dir: Path, done: list[Outcome], bench_dir: Path | None = None) -> Path:
    """Write ``out_dir/report.html``; returns its path."""
    path = Path(out_dir) / "report.html"
    path.write_text(render(Path(out_dir), done, bench_dir))
    return path

