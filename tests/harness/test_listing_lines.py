"""The listing lines behind a cell: printed lines with their seed line, tagged src edits.

The seed line of a printed line is found by aligning the listing with the scan; it is checked
here against the scan's text at that line (read from legacy/scan directly) and against the
seed lines the register's entries cite by hand.
"""
from __future__ import annotations

import math
import re

import pytest

from linkrepro.harness import listing_lines as L
from linkrepro.harness import ocr_audit, register
from linkrepro.harness.scenes import TABLES
from linkrepro.harness.diff import agreed_digits
from linkrepro.harness.trail import printed_digits


def scan_text(listing: str) -> dict[int, str]:
    """{seed line: the scan's text of it}, from legacy/scan/<listing>.txt and its ranges."""
    config = ocr_audit.scan_config(listing)
    numbers = [n for first, last in config["lines"] for n in range(first, last + 1)]
    return dict(zip(numbers, (L.ROOT / "legacy" / "scan" / (listing[:-2] + ".txt")).read_text().splitlines()))


@pytest.mark.parametrize("listing", ocr_audit.listings())
def test_a_printed_line_and_its_seed_line_say_the_same(listing):
    seed, numbers = L.seed_lines(listing)
    assert seed == ocr_audit.scan_config(listing)["seed"]
    scan = scan_text(listing)
    code = [n for n in range(1, len(L.text("printed", listing)) + 1)
            if not re.match(r"[Cc*]", L.text("printed", listing)[n - 1]) and L.text("printed", listing)[n - 1].strip()]
    assert sum(n in numbers for n in code) >= 0.9 * len(code)          # almost every statement is found
    unlike = []
    for n, seed_line in numbers.items():        # tokens as the audit reads them, or words of a joined card
        ours, theirs = L.text("printed", listing)[n - 1], scan[seed_line]
        alike = [(set(ocr_audit.tokens([ours], ocr_audit._PRINTED_COMMENT)), set(ocr_audit.tokens([theirs], ocr_audit._SCAN_COMMENT))),
                 (set(re.findall(r"[A-Z0-9]+", ours.upper())), set(re.findall(r"[A-Z0-9]+", theirs.upper())))]
        unlike += [n] if all(len(a & b) < len(a) / 2 for a, b in alike) else []
    assert len(unlike) <= 0.02 * len(numbers), unlike    # OCR damage, cards the OCR joined into a comment


def cited_pairs():
    """(entry, listing, printed line numbers, seed line numbers) where an entry's `where` names
    as many printed lines as seed lines, one by one: its k-th printed citation against its k-th
    seed citation."""
    for entry in register.load().values():
        seeds = re.findall(r"seed \d{3} lines? (\d+(?:\s*(?:-|,|and)\s*\d+)*)", entry.where)
        printed = [(listing, numbers) for tier, listing, numbers in L._CITED.findall(entry.where) if tier == "printed"]
        for (listing, numbers), seed in zip(printed, seeds):
            if len(L._numbers(numbers)) == len(L._numbers(seed)):
                yield entry.id, listing, L._numbers(numbers), L._numbers(seed)


def test_the_register_cites_the_seed_lines_the_alignment_finds():
    pairs = list(cited_pairs())
    assert len(pairs) >= 8
    for entry, listing, printed, seed in pairs:
        assert [L.seed_lines(listing)[1].get(n) for n in printed] == seed, entry


def test_an_entry_shows_the_lines_it_cites_and_its_tagged_edits():
    entries = register.load()
    d006 = [line.where() for line in L.cited(entries["D006"])]
    assert d006 == ["legacy/printed/ali1977_case1_source.f:127 (seed 003 line 1191)",
                    "legacy/printed/ali1977_case1_source.f:143 (seed 003 line 1207)"]
    assert L.cited(entries["D006"])[0].text.strip() == entries["D006"].readings[0]["chosen"].strip()
    edits = L.tagged("D053")
    assert edits and all(line.tier == "src" and "D053" in line.tags for line in edits)
    assert any("TABLE(J,1)=OBJFUN" in line.text for line in edits)


@pytest.mark.parametrize("name", list(TABLES))
def test_every_cell_names_the_lines_behind_it(name):
    scene = TABLES[name]
    rows = ["crank/i_xx", "connecting_rod/i_zz"] if not isinstance(scene.key, str) else ["0"]
    for row in rows:
        for column in scene.values:
            lines = [line for s in scene.statements(row, column) for line in L.find(s)]
            assert any(line.tier == "src" for line in lines), (row, column)
            assert all(line.seed_line for line in lines if line.tier == "printed"), (row, column)


def test_unknown_listing_and_line_are_typed_errors():
    with pytest.raises(L.ListingNotFound, match="no listing"):
        L.text("printed", "nothing.f")
    with pytest.raises(L.ListingNotFound, match="lines, not a line 99999"):
        L.line("printed", "ssp_loc.f", 99999)


def test_digits_agreed_and_printed():
    assert agreed_digits(1.0000001, 1.0) == pytest.approx(7.0, abs=0.01)
    assert agreed_digits(2.0, 2.0) == math.inf and math.isnan(agreed_digits(math.nan, 1.0))
    assert agreed_digits(0.655, -0.655) == 0.0
    assert [printed_digits(t) for t in ("-0.238", "2457.133427", "1.946666E-04", "0.007")] == [3, 10, 7, 1]
