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
Per scene: its overview lines (other than a table's), its own report.md whole (``report_view``:
its opening shown, each part folded under its heading, the register entries it names shown once in
the page's register section, which a cell's trail reads too) and links to its folder's files; per
command's output: its markdown, its ``###`` subsections folded behind ``<details>`` (``folded``).
Every markdown string is rendered by one renderer (``markdown_text.html``, CommonMark with tables).  Every
section's figures with their captions (``figures.caption_of``), inline as lossless WebP
(``data_uri``), and an overview of every table and engine (``diff.count_cells``, the counts every
report shows) that links each section and the folder's manifest.json.  A full run's page keeps
within ``PAGE_BUDGET``.
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
import PIL
from PIL import Image, features

from . import build_cache, figures as figures_mod, listing_lines, manifest, markdown_text, register as register_mod
from .diff import CLASSES, COUNT_COLUMNS, EXPLAINED_BY, classify_cells, headline
from .engines import ENGINES
from .register import Deviation
from .report import REGISTER_PART, heading
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
    """A PNG file as a ``data:`` URI, for an ``<img>`` that needs no other file: as lossless WebP
    (``webp``), or as itself where Pillow has no WebP."""
    if features.check("webp"):
        return "data:image/webp;base64," + base64.b64encode(webp(path.read_bytes())).decode("ascii")
    return "data:image/png;base64," + base64.b64encode(path.read_bytes()).decode("ascii")


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


#: our markdown as HTML: the one way every string that reaches the page is rendered
markdown_html = markdown_text.html


def inline(text: str) -> str:
    """One line of our markdown (a skipped scene's reason, a failure, a note) as inline HTML."""
    return markdown_text.html(text, inline=True)


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
    """A register entry for the page: its words rendered as report.md's ``report.render_entry`` writes
    them (printed and meant as code, the rest as written)."""
    edits = listing_lines.tagged(entry.id)
    words = entry.how_known() + [(name, getattr(entry, name))
                                 for name in ("where", "printed", "meant", "evidence", "effect")]
    code = markdown_text.code_span
    return {"id": entry.id, "kind": entry.kind, "certainty": entry.certainty,
            "title": inline(markdown_text.prose(entry.title)),
            "fields": [(name, inline(code(text) if name in ("printed", "meant") else markdown_text.prose(text)))
                       for name, text in words],
            "quirk": entry.quirk, "cited": [_line(c) for c in listing_lines.cited(entry)],
            "edits": [_line(e) for e in edits[:EDITS_SHOWN]], "more_edits": max(0, len(edits) - EDITS_SHOWN)}


def _number(value: float) -> str | None:
    return None if math.isnan(value) else f"{value:.9g}"


def _column_head(scene, column: str) -> dict:
    what = scene.describe(column)
    return {"id": column, "unit": what.unit, "label": what.label}


@dataclass
class PageData:
    """What the page's script reads (``cells-data``): per scene its published table's cells
    (``table_view``), and what they repeat kept once, by index: a column's label (its words and
    unit, per table column), a cell's register ids' list and its trail block (the block's listing
    lines and the scene's notes are the page's ``<template>`` elements, named by that index)."""
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
    units and labels, the hover text); its cells go into ``data.tables[scene.name]``: per row, per column, the
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


#: a part of a report.md whose text (what a reader reads, markup aside) is up to this many characters
#: is shown open ("None.", a line of links); a longer one is folded, its heading the summary a reader
#: opens it by (the page stays short enough to scroll through)
OPEN_CHARS = 300
#: the files of a section's folder the page links, in this order (outcome.json is the run's record)
LINKED = ("*.md", "*.csv", "*.png", "*.svg")
#: a report.md's part naming register entries (``report.scene_report``): the page shows each entry once
ENTRY_HEAD = re.compile(r"^#### (D\d+) ", re.M)


def files(folder: Path, out_dir: Path) -> list[dict]:
    """The files of a section's ``folder`` a reader opens (``LINKED``), each with its link from the page."""
    found = [p for pattern in LINKED for p in sorted(folder.glob(pattern))] if folder.is_dir() else []
    return [{"name": p.name, "href": p.relative_to(out_dir).as_posix()} for p in found]


def report_parts(text: str) -> tuple[str, list[tuple[str, str]]]:
    """A report.md as (what precedes its first ``## `` heading, [(each such heading, its part)]), its
    ``# `` title left out (the section has its heading)."""
    lines = text.splitlines()
    if lines and lines[0].startswith("# "):
        lines = lines[1:]
    intro, parts = [], []
    for line in lines:
        if line.startswith("## "):
            parts.append((line[3:].strip(), []))
        else:
            (parts[-1][1] if parts else intro).append(line)
    return "\n".join(intro).strip(), [(head, "\n".join(body).strip()) for head, body in parts]


def report_view(path: Path, out_dir: Path) -> dict:
    """A section's report.md for the page, whole: its opening shown, each ``## `` part under its heading
    (folded beyond ``OPEN_CHARS`` of text); a part of images only left out (the section shows its figures with
    their captions); the register entries a part names linked to the page's register section, where
    each entry is shown once.  ``ids``: those entries."""
    base = PurePosixPath(path.parent.relative_to(out_dir).as_posix())
    intro, parts = report_parts(path.read_text())
    shown, ids = [], []
    for head, body in parts:
        if head == REGISTER_PART:
            named = ENTRY_HEAD.findall(body)
            ids += named
            body = ", ".join(f"[{i}](#entry-{i})" for i in named) + ": each shown once, under [Register entries](#register)."
        html = markdown_html(body, base)
        words = " ".join(re.sub(r"<[^>]*>", " ", html).split())
        if words:
            shown.append({"head": inline(head), "html": html, "open": len(words) <= OPEN_CHARS})
    return {"intro": markdown_html(intro, base), "parts": shown, "ids": ids}


def _scene_view(folder: "Folder", section: "SceneSection", register, data: PageData) -> dict:
    here = folder.out_dir / section.name
    view = {"kind": "scene", "name": section.name, "title": section.title,
            "problem": inline(markdown_text.prose(section.problem)), "outcome": section.outcome, "figures": [], "table": None, "overview": "", "counts": [], "report": None,
            "files": files(here, folder.out_dir), "skipped": "", "failures": []}
    if section.outcome is None:
        return view
    view["skipped"] = inline(section.outcome.skipped)
    view["failures"] = [inline(markdown_text.prose(f)) for f in section.outcome.failures]
    view["figures"] = figures(here) if here.is_dir() else []
    if (here / "report.md").is_file():
        try:
            view["report"] = report_view(here / "report.md", folder.out_dir)
        except (OSError, ValueError) as exc:          # damaged (not UTF-8) where its run kept no record of it
            said = f"**{section.name}/report.md cannot be read ({type(exc).__name__}); run the scene again.**"
            view["report"] = {"intro": markdown_html(said), "parts": [], "ids": []}
        view["used"] = set(view["report"]["ids"])
    if section.name in TABLES and (here / "diff.csv").is_file():
        diff = read_diff(TABLES[section.name], folder.out_dir)
        view["table"] = table_view(SCENES[section.name], diff, register, data)
        if section.outcome.counts is not None:
            view["counts"] = overview(section.outcome.counts)
        view["used"] = view.get("used", set()) | {i for ids in diff["register_ids"].fillna("") for i in str(ids).split()}
    else:
        view["overview"] = markdown_html("\n".join(section.outcome.overview), breaks=True)
    return view


def _output_view(folder: "Folder", section: "OutputSection") -> dict:
    view = {"kind": "output", "name": section.name, "title": section.title, "present": section.present,
            "command": section.command, "html": "", "figures": [], "files": files(section.folder, folder.out_dir)}
    if section.present:
        try:
            text = section.markdown.read_text()
            view["figures"] = figures(section.folder)
        except (OSError, ValueError) as exc:        # damaged: not UTF-8, a figure that is no image
            view["html"] = markdown_html(f"**{section.markdown.relative_to(folder.out_dir).as_posix()} or a figure "
                                         f"beside it cannot be read ({type(exc).__name__}); "
                                         f"{markdown_text.code_span(section.command)} writes it again.**")
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
        sections=sections, absent=folder.absent, absent_command=folder.absent_command, latest=inline(latest),
        notes=[inline(note) for note in folder.notes], engines=ENGINES,
        statuses=CELL_STATUSES, columns=[(c, heading(c)) for c in COUNT_COLUMNS if c not in EXPLAINED_BY or c in kinds],
        kinds=kinds, total=headline(totals, by_kind=True),
        manifest=manifest.FILE if (folder.out_dir / manifest.FILE).is_file() else "",
        made=(manifest.TITLE, markdown_html("\n".join(manifest.summary(folder.out_dir)))),
        entries=[_entry(register[i]) for i in sorted(used) if i in register],
        blocks={block: {"notes": [inline(note) for note in notes], "lines": [_line(line) for line in lines]}
                for (lines, notes), block in data.blocks.items()},
        cells_json=data.json())
