"""The one count every report shows (``harness/diff.py``: ``classify_cells``, ``count_cells``,
``total_counts``, ``headline``): first on a made-up diff with known answers, then on a fresh run of
Table III (readings skipped; it has unresolved cells): the numbers in the run's report.md, the
scene's report.md, report.html's overview and cell colours, and the CLI's lines are those of
``count_cells`` on the diff.csv the run wrote, and they add up.
"""
from __future__ import annotations

import contextlib
import io
import json
import re
from html.parser import HTMLParser
from pathlib import Path

import pandas as pd
import pytest

from linkrepro.harness import register as register_mod
from linkrepro.harness.cli import main
from linkrepro.harness.diff import (CLASSES, COUNT_COLUMNS, EXPLAINED_BY, SEVERAL, classify_cells, count_cells,
                                    headline, total_counts)
from linkrepro.harness.register import CellClaim, Check, Deviation

SCENE = "ali1977-table3"


def _entry(id_: str, kind: str, **more) -> Deviation:
    return Deviation(id=id_, kind=kind, title="t", where="w", printed="p", meant="m", evidence="e", effect="f", **more)


#: W1 accounts for the whole difference of scene s's 'after' cell at row 10 for legacy (and claims row 20 too)
WHOLE = (CellClaim("s", (10,), ("after",), ("legacy",), whole=True), CellClaim("s", (20,), ("after",), ("legacy",)))
REGISTER = {e.id: e for e in (_entry("U1", "unresolved"), _entry("U2", "unresolved"), _entry("B1", "original-bug"),
                              _entry("M1", "published-misprint"), _entry("P1", "portability"),
                              _entry("T1", "portability", tolerance=1e-6),
                              _entry("W1", "original-bug", cells=WHOLE, checks=(Check(command="true"),)))}

#: (engine, row, status, register ids) -> what it must count as, and the kind of an explained cell
CELLS = [
    ("legacy", 0, "match", None, "matched", ""),
    ("legacy", 0, "registered", "U1", "unresolved", ""),                 # only an unresolved entry
    ("legacy", 0, "registered", "U1 U2", "unresolved", ""),              # two, both unresolved
    ("legacy", 0, "registered", "B1 U1", "unresolved", ""),              # a cause that is not the whole: unresolved wins
    ("legacy", 0, "registered", "X9", "unexplained", ""),                # an id the register lacks
    ("legacy", 0, "registered", "U1 X9", "unresolved", ""),              # the missing id is ignored
    ("legacy", 0, "registered", "P1 X9", "explained", "portability"),
    ("legacy", 0, "registered", "B1 M1", "explained", SEVERAL),          # two real kinds: once
    ("legacy", 0, "registered", "B1 M1 U1", "unresolved", ""),
    ("legacy", 0, "registered", "T1", "within-tolerance", ""),           # closeness only: apart
    ("legacy", 0, "registered", "T1 X9", "within-tolerance", ""),
    ("legacy", 0, "registered", "T1 U1", "unresolved", ""),              # a tolerance never hides an unresolved cause
    ("legacy", 0, "registered", "M1 T1", "explained", "published-misprint"),   # a cause: the tolerance is no kind
    ("legacy", 10, "registered", "U1 W1", "explained", "original-bug"),  # W1 accounts for the whole difference
    ("legacy", 10, "registered", "T1 U1 W1", "explained", "original-bug"),
    ("legacy", 20, "registered", "U1 W1", "unresolved", ""),             # W1's claim there is not whole
    ("legacy", 0, "unexplained", "", "unexplained", ""),
    ("legacy", 0, "not-produced", "B1", "not-produced", ""),             # not produced, whatever its ids
    ("printed", 10, "registered", "U1 W1", "unresolved", ""),            # the whole claim is legacy's only
    ("printed", 0, "not-produced", None, "not-produced", ""),
    ("printed", 0, "registered", "M1", "explained", "published-misprint"),
    ("printed", 0, "registered", "M1 M1", "explained", "published-misprint"),
    ("printed", 0, "registered", "T1", "within-tolerance", ""),
    ("printed", 0, "match", "", "matched", ""),
]


def made_up_diff() -> pd.DataFrame:
    """A diff as diff_scene writes it (scene, engine, the row key, column first)."""
    return pd.DataFrame([{"scene": "s", "engine": e, "crank_deg": row, "column": "after", "status": s,
                          "register_ids": ids} for e, row, s, ids, _, _ in CELLS])


def test_classify_cells_on_a_made_up_diff():
    classes = classify_cells(made_up_diff(), REGISTER)
    assert list(classes["count"]) == [c[4] for c in CELLS]
    assert list(classes["kind"]) == [c[5] for c in CELLS]


def test_the_whole_claim_decides_for_its_cells_only():
    """Without W1's whole claim, every cell it names with U1 is unresolved; a register without any
    whole claim classifies a diff that has no scene or key columns."""
    plain = {**REGISTER, "W1": _entry("W1", "original-bug", cells=(CellClaim("s", (10, 20), ("after",), ("legacy",)),))}
    classes = classify_cells(made_up_diff(), plain)
    named = [i for i, c in enumerate(CELLS) if c[3] and "U1" in c[3].split()]
    assert set(classes["count"].iloc[named]) == {"unresolved"}
    bare = made_up_diff().drop(columns=["scene", "crank_deg", "column"])
    assert list(classify_cells(bare, plain)["count"]) == list(classes["count"])
    with pytest.raises(ValueError, match="whole"):
        classify_cells(bare, REGISTER)


def test_count_cells_on_a_made_up_diff():
    counts = count_cells(made_up_diff(), REGISTER)
    assert list(counts.index) == ["legacy", "printed"] and list(counts.columns) == list(COUNT_COLUMNS)
    legacy = {"cells": 18, "matched": 1, "explained": 5, "original-bug": 2, "portability": 1, SEVERAL: 1,
              "published-misprint": 1, "within-tolerance": 2, "unresolved": 7, "unexplained": 2, "not-produced": 1}
    printed = {"cells": 6, "matched": 1, "explained": 2, "published-misprint": 2, "within-tolerance": 1,
               "unresolved": 1, "not-produced": 1}
    for engine, expected in (("legacy", legacy), ("printed", printed)):
        assert counts.loc[engine].to_dict() == {c: expected.get(c, 0) for c in COUNT_COLUMNS}, engine
    total = total_counts([counts, counts.loc[["printed"]]])
    assert total["cells"] == 30 and total["explained"] == 9 and total["unresolved"] == 9
    assert total["within-tolerance"] == 4 and total["published-misprint"] == 5
    assert total["unexplained"] == 2 and total["not-produced"] == 3
    assert headline(counts.loc["legacy"]) == ("18 cells: 1 matched, 5 explained, 2 within tolerance, 7 unresolved, "
                                              "2 unexplained, 1 not produced")
    assert headline(counts.loc["legacy"], by_kind=True) == (
        "18 cells: 1 matched, 5 explained (original-bug 2, portability 1, published-misprint 1, several kinds 1), "
        "2 within tolerance, 7 unresolved, 2 unexplained, 1 not produced")


def test_an_unresolved_entry_never_explains():
    """Every cell named only by unresolved entries counts as unresolved, with no kind of explained."""
    diff = pd.DataFrame({"engine": ["a"] * 3, "status": ["registered"] * 3, "register_ids": ["U1", "U2", "U1 U2"]})
    counts = count_cells(diff, {k: REGISTER[k] for k in ("U1", "U2")}).loc["a"]
    assert counts["unresolved"] == 3 and counts["explained"] == 0 and counts[list(EXPLAINED_BY)].sum() == 0


def test_no_engine_ran_counts_nothing():
    counts = count_cells(pd.DataFrame([]), REGISTER)
    assert counts.empty and list(counts.columns) == list(COUNT_COLUMNS)
    assert headline(total_counts([counts])) == ("0 cells: 0 matched, 0 explained, 0 within tolerance, 0 unresolved, "
                                                "0 unexplained, 0 not produced")


def test_an_unknown_status_is_an_error():
    with pytest.raises(ValueError, match="registred"):
        classify_cells(pd.DataFrame({"engine": ["a"], "status": ["registred"], "register_ids": [""]}), {})


# -- a fresh run: every place shows the function's numbers -------------------------------------

@pytest.fixture(scope="module")
def fresh(tmp_path_factory) -> tuple[Path, list[str]]:
    """``linkrepro reproduce ali1977-table3 --skip-readings``, in this process: (folder, stdout lines)."""
    out = tmp_path_factory.mktemp("counts") / "out"
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        assert main(["reproduce", SCENE, "--skip-readings", "--out", str(out)]) == 0
    return out, stdout.getvalue().splitlines()


@pytest.fixture(scope="module")
def expected(fresh) -> pd.DataFrame:
    """``count_cells`` on the diff.csv the run wrote."""
    out, _ = fresh
    diff = pd.read_csv(out / SCENE / "diff.csv", dtype={"register_ids": str, "published_text": str})
    return count_cells(diff, register_mod.load())


def _adds_up(words_: str) -> dict[str, int]:
    """The numbers of a headline, read back (every class of CLASSES, in order); checked to add up."""
    found = re.fullmatch(r"(\d+) cells: (\d+) matched, (\d+) explained(?: \(([^)]*)\))?, (\d+) within tolerance, "
                         r"(\d+) unresolved, (\d+) unexplained, (\d+) not produced", words_)
    assert found, words_
    cells, matched, explained, kinds, *rest = found.groups()
    numbers = {"cells": int(cells), "matched": int(matched), "explained": int(explained),
               **{c: int(n) for c, n in zip(CLASSES[2:], rest, strict=True)}}
    assert set(numbers) == {"cells", *CLASSES} and numbers["cells"] == sum(numbers[c] for c in CLASSES), words_
    if kinds:
        by_kind = {k: int(n) for k, n in (part.rsplit(" ", 1) for part in kinds.split(", "))}
        assert sum(by_kind.values()) == numbers["explained"] and set(by_kind) <= set(EXPLAINED_BY), words_
        numbers.update(by_kind)
    return numbers


def _markdown_table(lines: list[str], after: str) -> pd.DataFrame:
    """The first markdown table after the line starting with ``after``: integers, engine as index."""
    start = next(i for i, line in enumerate(lines) if line.startswith(after))
    first = next(i for i in range(start, len(lines)) if lines[i].startswith("|"))
    rows = []
    for line in lines[first:]:
        if not line.startswith("|"):
            break
        rows.append([c.strip() for c in line.strip("|").split("|")])
    head, body = rows[0], rows[2:]
    frame = pd.DataFrame(body, columns=head).set_index("engine").drop(columns=["seconds"], errors="ignore")
    return frame.astype(int)


def _as_shown(counts: pd.DataFrame) -> pd.DataFrame:
    return counts.rename(columns=_as_shown_name)


def _as_shown_name(column: str) -> str:
    return f"explained: {column}" if column in EXPLAINED_BY else column


def _same(shown: pd.DataFrame, counts: pd.DataFrame) -> None:
    """A table shown: the counts' numbers under their headings (a kind of explained that counts no
    cell may be left out), every row adding up."""
    full = _as_shown(counts)
    assert list(shown.index) == list(full.index)
    left_out = set(full.columns) - set(shown.columns)
    assert all(full[c].eq(0).all() for c in left_out), left_out
    pd.testing.assert_frame_equal(shown, full[list(shown.columns)], check_dtype=False)
    assert (shown["cells"] == shown[list(CLASSES)].sum(axis=1)).all()


def test_the_run_has_unresolved_cells(expected):
    """Table III has them (the cognate columns: no program was printed); else this test checks little."""
    assert expected["unresolved"].sum() > 0 and expected["explained"].sum() > 0


def test_cli_lines_are_the_counts(fresh, expected):
    out, lines = fresh
    total = expected[list(COUNT_COLUMNS)].sum(axis=0)
    assert lines[-1] == f"report: {out / 'report.html'} and report.md  (1 scene; {headline(total)})"
    shown = _adds_up(lines[-1].split("; ", 1)[1][:-1])
    assert shown == {c: int(total[c]) for c in ("cells", *CLASSES)}
    assert lines[0] == f"{SCENE}:"
    for engine, line in zip(expected.index, lines[1:-1], strict=True):
        name, words = line.strip().split(": ", 1)
        assert name == engine
        numbers = _adds_up(words)
        assert numbers == {c: int(expected.at[engine, c]) for c in numbers}
        assert {k: int(n) for k, n in expected.loc[engine, list(EXPLAINED_BY)].items() if n} == \
               {k: n for k, n in numbers.items() if k in EXPLAINED_BY}


def test_run_report_shows_the_counts(fresh, expected):
    out, _ = fresh
    lines = (out / "report.md").read_text().splitlines()
    head = next(line for line in lines if line.startswith("The published cells of every table below"))
    numbers = _adds_up(head.split(": ", 1)[1].rstrip("."))
    assert numbers == {c: int(n) for c, n in expected.sum(axis=0).items() if c in numbers}
    _same(_markdown_table(lines, f"## [{SCENE}]"), expected)


def test_scene_report_shows_the_counts(fresh, expected):
    out, _ = fresh
    lines = (out / SCENE / "report.md").read_text().splitlines()
    _same(_markdown_table(lines, "## Cells against the published table"), expected)
    assert "registered cells by the kind" not in "\n".join(lines).lower()


class _Page(HTMLParser):
    """report.html's overview table (rows of cell texts), its total line, and every table cell's
    status per engine (the page's cells data, from which its script sets data-<engine>)."""

    def __init__(self):
        super().__init__()
        self.overview, self.total, self.cells = [], "", []
        self._in, self._row, self._text = None, None, None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "table" and "overview" in (attrs.get("class") or ""):
            self._in = "overview"
        elif tag == "p" and attrs.get("id") == "total":
            self._in, self._text = "total", []
        elif tag == "tr" and self._in == "overview":
            self._row = []
        elif tag in ("td", "th") and self._row is not None:
            self._text, self._count = [], attrs.get("data-count")
        if tag == "script" and attrs.get("id") == "cells-data":
            self._in, self._text = "cells", []

    def handle_data(self, data):
        if self._text is not None:
            self._text.append(data)

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._row is not None:       # (the count it shows, or None; its text)
            self._row.append((self._count, "".join(self._text).strip()))
            self._text = None
        elif tag == "tr" and self._row is not None:
            self.overview.append(self._row)
            self._row = None
        elif tag == "table" and self._in == "overview":
            self._in = None
        elif tag == "p" and self._in == "total":
            self.total, self._in, self._text = "".join(self._text).strip(), None, None
        elif tag == "script" and self._in == "cells":       # per cell: per engine [status, ...] or null
            data, self._in, self._text = json.loads("".join(self._text)), None, None
            records = [[c[4 + e] if isinstance(e, int) else e for e in c[4:]]     # an int: an earlier engine's
                       for table in data["tables"].values() for row in table["cells"] for c in row if c]
            self.cells = [{e: data["statuses"][r[0]] for e, r in zip(data["engines"], rs) if r} for rs in records]


def test_html_overview_shows_the_counts(fresh, expected):
    out, _ = fresh
    page = _Page()
    page.feed((out / "report.html").read_text())
    first, second, *rows = page.overview                     # two header rows: explained's kinds under it
    assert [text for _, text in first[:2]] == ["scene", "engine"] and (None, "explained") in first
    assert {count for count, _ in second} <= {"explained", *EXPLAINED_BY}
    assert {row[0][1] for row in rows} == {SCENE}
    shown = pd.DataFrame([{"engine": row[1][1], **{_as_shown_name(c): t for c, t in row[2:]}} for row in rows])
    shown = shown.set_index("engine").astype(int)
    _same(shown, expected)
    assert page.total.endswith(f": {headline(expected.sum(axis=0), by_kind=True)}.")
    numbers = _adds_up(page.total.split(": ", 1)[1].rstrip("."))
    assert numbers == {c: int(n) for c, n in expected.sum(axis=0).items() if c in numbers}
    # the cells' colours count the same: diff.csv's "registered" split into explained, within-tolerance, unresolved
    for engine in expected.index:
        colours = pd.Series([c[engine] for c in page.cells]).value_counts()
        assert {s: int(colours.get(s, 0)) for s in ("match", *CLASSES[1:])} \
            == {"match": expected.at[engine, "matched"], **{c: expected.at[engine, c] for c in CLASSES[1:]}}, engine
        assert "registered" not in colours
