"""``report.html``: an output folder's report as one self-contained page (inline style, script and
figures; nothing fetched when it is viewed), rendered with Jinja2 from ``templates/report.html.j2``
over what ``report_folder.collect`` found in the folder.

Per table scene: the published table in its printed layout, each column headed short (its id
and unit; its words on hover) and the heads kept in view in the table's scroll box, each cell
coloured by what it counts as for the engine chosen in the page's selector
(``diff.classify_cells``: match, explained, within-tolerance, unresolved, unexplained,
not-produced) with how many of its printed digits that engine reproduces; a click (or Enter)
on a cell opens its trail (``harness/trail.py``): every engine's value, the register entries,
the listing lines.  The table's HTML holds only the printed texts: the page's script colours
the cells and writes their markers and hover text from the cells' data (``PageData``, JSON),
which keeps each repeated thing once.
Per other scene and per command's output: its markdown rendered (markdown-it, CommonMark with
tables), a command's ``###`` subsections folded behind ``<details>`` (``folded``).  Every
section's figures with their captions (``figures.caption_of``), inline as lossless WebP
(``data_uri``), and an overview of every table and engine (``diff.count_cells``, the counts
every report shows).  A full run's page keeps within ``PAGE_BUDGET``.
"""
from __future__ import annotations

import base64
import hashlib
import io
import json
import math
import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING

import jinja2
import pandas as pd
from markdown_it import MarkdownIt
import PIL
from PIL import Image, features

from . import build_cache, figures as figures_mod, listing_lines, manifest, register as register_mod
from .diff import CLASSES, COUNT_COLUMNS, EXPLAINED_BY, classify_cells, headline
from .engines import ENGINES
from .register import Deviation
from .report import ASSUMPTIONS_WORDS, heading
from .scenes import SCENES, TABLES
from .trail import digits_reproduced, printed_digits, published_source, read_diff

if TYPE_CHECKING:
    from .report_folder import Folder, OutputSection, SceneSection

TEMPLATES = Path(__file__).resolve().parent / "templates"
#: the page's size budget (bytes) for a full run's folder (reproduce, bench, arithmetic): a page to
#: open and read, not a data dump; ``report_folder.write`` warns ``PageSizeWarning`` beyond it
PAGE_BUDGET = 2_000_000
#: a figure's encoding on the page: lossless (every pixel as in the PNG); ``method``/``quality``
#: the encoder's effort: 3/25 is within 0.2 % of the smallest (6/100, 80 times slower), measured
#: on the 22 figures of a full run: 651 against 863 kB of PNG
WEBP = {"lossless": True, "method": 3, "quality": 25}
#: the heading level (``###`` in a command's markdown) whose subsections the page folds
FOLD_LEVEL = 3
#: tagged src edits shown per register entry (the rest are counted)
EDITS_SHOWN = 8
#: what a cell is coloured as: ``diff.classify_cells``'s class, a matched cell shown as ``match``
#: (its status in diff.csv); diff.csv's ``registered`` split into explained, within-tolerance and unresolved
SHOWN = {"matched": "match"}
CELL_STATUSES = tuple(SHOWN.get(c, c) for c in CLASSES)


def data_uri(path: Path) -> str:
    """A PNG or SVG file as a ``data:`` URI, for an ``<img>`` that needs no other file: a PNG as
    lossless WebP (``webp``), or as itself where Pillow has no WebP."""
    if path.suffix == ".png" and features.check("webp"):
        return "data:image/webp;base64," + base64.b64encode(webp(path.read_bytes())).decode("ascii")
    kind = "image/svg+xml" if path.suffix == ".svg" else "image/png"
    return f"data:{kind};base64," + base64.b64encode(path.read_bytes()).decode("ascii")


def webp(png: bytes) -> bytes:
    """A PNG's pixels as lossless WebP (``WEBP``: about 3/4 of the bytes), from the user cache
    when it holds them (``build_cache.fetch``, named by the PNG's bytes, the settings and
    Pillow's version): encoding takes ~25 ms of CPU a figure, 0.5 s over a full run's page,
    which every report write would pay again for figures that a run rewrites bit for bit."""
    entry = hashlib.sha256(repr(("webp", WEBP, PIL.__version__)).encode() + png).hexdigest()
    cached = build_cache.fetch(entry)
    if cached is not None:
        return cached
    buffer = io.BytesIO()
    with Image.open(io.BytesIO(png)) as image:
        image.save(buffer, format="webp", **WEBP)
    build_cache.store(entry, buffer.getvalue())
    return buffer.getvalue()


def markdown_html(text: str, base: PurePosixPath = PurePosixPath("."), breaks: bool = False) -> str:
    """Markdown as HTML (CommonMark and tables; raw HTML escaped; ``breaks``: a line break is
    kept, as in a scene's overview lines).  Images are left out (a section shows its figures
    with their captions); a relative link is made relative to the report's folder (``base``:
    the markdown's folder there)."""
    md = MarkdownIt("commonmark", {"html": False, "breaks": breaks}).enable("table")
    md.renderer.rules["image"] = lambda tokens, idx, options, env: ""

    def link_open(tokens, idx, options, env):
        href = tokens[idx].attrGet("href") or ""
        if href and not href.startswith(("#", "/")) and ":" not in href.split("/")[0]:
            tokens[idx].attrSet("href", (base / href).as_posix())
        return md.renderer.renderToken(tokens, idx, options, env)

    md.renderer.rules["link_open"] = link_open
    return md.render(text)


HEADING = re.compile(r"<h([1-6])>.*?</h\1>\n?", re.S)


def _inside(html: str) -> str:
    """What a folded subsection holds, in words: its tables and their rows ("a table of 11
    rows"), or its paragraphs."""
    rows = [body.count("<tr>") for body in re.findall(r"<tbody>(.*?)</tbody>", html, re.S)]
    if len(rows) == 1:
        return f"a table of {rows[0]} row{'s' * (rows[0] != 1)}"
    if rows:
        return f"{len(rows)} tables, {sum(rows)} rows"
    paragraphs = html.count("<p>")
    return f"{paragraphs} paragraph{'s' * (paragraphs != 1)}"


def folded(html: str, level: int = FOLD_LEVEL) -> str:
    """``markdown_html``'s HTML with each subsection headed at ``level`` (up to the next heading
    at that level or above) behind ``<details>``: its heading and what it holds (``_inside``)
    are the summary, a reader opens the one wanted."""
    out, start, open_at = [], 0, None

    def close(end: int) -> None:
        if open_at is not None:
            head, body = html[open_at[0]:open_at[1]], html[open_at[1]:end]
            out.append(f'<details class="fold"><summary>{head.rstrip()} <span class="inside">({_inside(body)})</span>'
                       f"</summary>\n{body}</details>\n")
    for match in HEADING.finditer(html):
        depth = int(match.group(1))
        if depth > level:
            continue
        close(match.start())
        if open_at is None:
            out.append(html[start:match.start()])
        open_at = (match.start(), match.end()) if depth == level else None
        if open_at is None:
            out.append(match.group(0))
        start = match.end()
    close(len(html))
    if open_at is None:
        out.append(html[start:])
    return "".join(out)


def _line(line: listing_lines.ListingLine) -> dict:
    return {"where": line.where(), "text": line.text.rstrip(), "tier": line.tier}


def _entry(entry: Deviation) -> dict:
    edits = listing_lines.tagged(entry.id)
    return {"id": entry.id, "kind": entry.kind, "certainty": entry.certainty, "title": entry.title,
            "fields": entry.how_known() + [(name, getattr(entry, name))
                                           for name in ("where", "printed", "meant", "evidence", "effect")],
            "quirk": entry.quirk, "cited": [_line(c) for c in listing_lines.cited(entry)],
            "edits": [_line(e) for e in edits[:EDITS_SHOWN]], "more_edits": max(0, len(edits) - EDITS_SHOWN)}


def _number(value: float) -> str | None:
    return None if math.isnan(value) else f"{value:.9g}"


def _column_head(scene, column: str) -> dict:
    what = scene.describe(column)
    return {"id": column, "words": what.words, "unit": what.unit, "label": what.label}


@dataclass
class PageData:
    """What the page's script reads (``cells-data``): per scene its published table's cells
    (``table_view``), and what they repeat kept once, each cell holding its index: the columns'
    words, the register ids' lists, the trail blocks (listing lines and the scene's notes,
    shown from the page's templates)."""
    tables: dict[str, dict] = field(default_factory=dict)
    labels: dict[str, int] = field(default_factory=dict)
    ids: dict[str, int] = field(default_factory=dict)
    blocks: dict[tuple, int] = field(default_factory=dict)

    @staticmethod
    def once(kept: dict, value) -> int:
        """``value``'s index in ``kept`` (added at its end the first time)."""
        return kept.setdefault(value, len(kept))

    def json(self) -> str:
        """The page's data as JSON, safe inside ``<script>``."""
        return json.dumps({"engines": ENGINES, "statuses": CELL_STATUSES, "labels": list(self.labels),
                           "ids": [ids.split() for ids in self.ids], "tables": self.tables},
                          separators=(",", ":")).replace("</", "<\\/")


def _engine_record(record: dict, printed: int, data: PageData) -> list:
    """One engine's side of a cell for the page's data: [status (index in CELL_STATUSES), value,
    |difference|, digits reproduced, register ids (index in ``data.ids``), kind], the empty
    fields at its end left out (the page's script reads them as empty: not produced is ``[5]``)."""
    ids = " ".join(record["register_ids"].split()) if isinstance(record["register_ids"], str) else ""
    fields = [CELL_STATUSES.index(record["shown"]), _number(float(record["value"])), _number(float(record["abs_diff"])),
              digits_reproduced(float(record["abs_diff"]), float(record["half_unit"]), printed),
              data.once(data.ids, ids) if ids else None, record["kind"] if isinstance(record["kind"], str) else None]
    while fields and fields[-1] is None:
        fields.pop()
    return fields


def _engines(here: dict[str, dict], printed: int, data: PageData) -> list:
    """Each engine's record (ENGINES' order; None where it has none), one the same as an earlier
    engine's (the port with the listing's bugs as legacy, bit for bit) given as that engine's index."""
    shown = [_engine_record(here[e], printed, data) if e in here else None for e in ENGINES]
    return [next((j for j in range(k) if shown[j] == record), record)
            if record is not None else None for k, record in enumerate(shown)]


def table_view(scene, diff: pd.DataFrame, register: dict[str, Deviation], data: PageData) -> dict:
    """The published table as printed for the template (rows of texts; columns: their ids,
    words and unit); its cells go into ``data.tables[scene.name]``: per row, per column, the
    printed text, half a unit of its last digit, its significant digits, its trail block and
    per engine ``_engines``; null where the table prints no cell.  The page's script colours
    the cells, writes their digits markers and hover text from it."""
    key = scene.key_name
    classes = classify_cells(diff, register)
    diff = diff.assign(shown=classes["count"].map(lambda c: SHOWN.get(c, c)), kind=classes["kind"])
    records: dict[str, dict[str, dict[str, dict]]] = {}     # row key: column: engine: record
    for record in diff.assign(row_key=diff[key].astype(str)).to_dict("records"):
        records.setdefault(record["row_key"], {}).setdefault(record["column"], {})[record["engine"]] = record
    columns = [c for c in scene.values if c in set(diff["column"])]
    rows, cells = [], []
    for row_key, by_column in records.items():
        texts, row = [], []
        for column in columns:
            here = by_column.get(column)
            if not here:
                texts.append(None)
                row.append(None)
                continue
            first = next(iter(here.values()))
            text = str(first["published_text"])
            printed = printed_digits(text)
            lines = tuple(line for s in scene.statements(str(first[key]), column) for line in listing_lines.find(s))
            block = data.once(data.blocks, (lines, tuple(scene.trail_notes(str(first[key]), column))))
            texts.append(text)
            row.append([text, float(first["half_unit"]), printed, block, *_engines(here, printed, data)])
        rows.append({"key": row_key, "texts": texts})
        cells.append(row)
    heads = [_column_head(scene, c) for c in columns]
    data.tables[scene.name] = {"columns": columns, "labels": [data.once(data.labels, h["label"]) for h in heads],
                               "rows": list(records), "cells": cells}
    return {"key_heads": [_column_head(scene, k) for k in scene.keys], "columns": heads, "rows": rows,
            "source": published_source(scene.table)}


def overview(counts: pd.DataFrame) -> list[dict]:
    """A scene's ``diff.count_cells`` (cells; matched, explained by kind, within-tolerance,
    unresolved, unexplained, not-produced) as the overview's rows, the engines in their order."""
    return [{"engine": engine, **{c: int(counts.at[engine, c]) for c in counts.columns}}
            for engine in ENGINES if engine in counts.index]


def figures(folder: Path) -> list[dict]:
    """Every figure in ``folder`` (PNG), inline, in the order of its file names, with its caption
    (``figures.caption_of``; a figure written without one is named by its file) and its size in
    CSS pixels (shown at its natural size: ``harness/figures.py``)."""
    shown = []
    for path in sorted(Path(folder).glob("*.png")):
        with Image.open(path) as image:
            width, height = image.size
        shown.append({"name": path.name, "uri": data_uri(path), "width": width, "height": height,
                      "caption": figures_mod.caption_of(path) or path.stem.replace("_", " ")})
    return shown


def _scene_view(folder: "Folder", section: "SceneSection", register, data: PageData) -> dict:
    view = {"kind": "scene", "name": section.name, "title": section.title, "problem": section.problem,
            "outcome": section.outcome, "figures": [], "table": None, "overview": "", "counts": [], "assumptions": []}
    if section.outcome is None:
        return view
    view["assumptions"] = [{"id": e.id, "title": e.title, "effect": e.effect}
                           for e in register_mod.assumed_by(section.name, register)]
    here = folder.out_dir / section.name
    view["figures"] = figures(here) if here.is_dir() else []
    if section.name in TABLES and (here / "diff.csv").is_file():
        diff = read_diff(TABLES[section.name], folder.out_dir)
        view["table"] = table_view(SCENES[section.name], diff, register, data)
        if section.outcome.counts is not None:
            view["counts"] = overview(section.outcome.counts)
        view["used"] = {i for ids in diff["register_ids"].fillna("") for i in str(ids).split()}
    else:
        view["overview"] = markdown_html("\n".join(section.outcome.overview), breaks=True)
    return view


def _output_view(folder: "Folder", section: "OutputSection") -> dict:
    view = {"kind": "output", "name": section.name, "title": section.title, "present": section.present,
            "command": section.command, "html": "", "figures": []}
    if section.present:
        try:
            text = section.markdown.read_text()
            view["figures"] = figures(section.folder)
        except (OSError, ValueError) as exc:        # damaged: not UTF-8, a figure that is no image
            view["html"] = markdown_html(f"**{section.markdown.relative_to(folder.out_dir).as_posix()} or a figure "
                                         f"beside it cannot be read ({type(exc).__name__}); "
                                         f"{manifest.code_span(section.command)} writes it again.**")
            return view
        body = text.split("\n", 1)[1] if text.startswith("# ") else text      # the section has its heading
        view["html"] = folded(markdown_html(body, PurePosixPath(section.folder.relative_to(folder.out_dir).as_posix())))
    return view


class PageSizeWarning(UserWarning):
    """report.html is larger than ``PAGE_BUDGET``; it is still written."""


@lru_cache(maxsize=None)
def template() -> jinja2.Template:
    """The page's template, compiled once a process."""
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(TEMPLATES), autoescape=True,
                             undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True)
    return env.get_template("report.html.j2")


def render(folder: "Folder", latest: str = "") -> str:
    """The page's HTML over what ``folder`` holds (``report_folder.collect``); ``latest``: a line
    on the run that just ended."""
    register = register_mod.load()
    data = PageData()
    sections = [_scene_view(folder, s, register, data) if s.kind == "scene" else _output_view(folder, s)
                for s in folder.sections]
    used = set().union(*(s.get("used", set()) for s in sections))
    totals = folder.cell_totals()
    kinds = [k for k in EXPLAINED_BY if totals.get(k, 0)]      # the overview's kinds: those that explain a cell
    return template().render(
        sections=sections, absent=folder.absent, absent_command=folder.absent_command, latest=latest,
        notes=folder.notes, engines=ENGINES,
        statuses=CELL_STATUSES, columns=[(c, heading(c)) for c in COUNT_COLUMNS if c not in EXPLAINED_BY or c in kinds],
        kinds=kinds, total=headline(totals, by_kind=True), assumptions_words=ASSUMPTIONS_WORDS,
        made=(manifest.TITLE, markdown_html("\n".join(manifest.summary(folder.out_dir)))),
        entries=[_entry(register[i]) for i in sorted(used) if i in register],
        blocks={block: {"notes": notes, "lines": [_line(line) for line in lines]}
                for (lines, notes), block in data.blocks.items()},
        cells_json=data.json())
