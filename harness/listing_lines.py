"""Lines of the listings, found for a reader: the printed ones (``legacy/printed/``, each with
the seed line it was read from) and the cleaned ones (``legacy/src/``, each with the register
ids its edit is tagged with, ``! D041`` at the end of the card).

A printed line's seed line comes from the scan (``legacy/scan/``): the listing's tokens are
aligned with the scan's (as ``ocr_audit`` aligns them) and a printed line takes the seed line
most of its tokens were matched on.  A line the scan does not hold (a reconstruction) has none.
"""
from __future__ import annotations

import difflib
import re
from collections import Counter
from dataclasses import dataclass
from functools import lru_cache

from . import ocr_audit
from .register import Deviation

ROOT = ocr_audit.ROOT
TIERS = ("printed", "src")
_TAG = re.compile(r"!\s*(D\d{3}(?:[\s,]+D\d{3})*)\s*$")
#: "legacy/printed/ali1977_case1_source.f lines 127, 143" (also "line 85", "lines 104-105")
#: "seed 003 lines 1191 and 1207", "(seed line 1149)"
_SEED_CITED = re.compile(r"seed (?:(\d{3}) )?lines? (\d+(?:\s*(?:-|,|and)\s*\d+)*)")
_CITED = re.compile(r"legacy/(printed|src)/(\w+\.f),? lines? (\d+(?:\s*(?:-|,|and)\s*\d+)*)")


class ListingNotFound(LookupError):
    """A listing or a line that is not in legacy/printed or legacy/src."""


@dataclass(frozen=True)
class Statement:
    """Where a quantity is computed or written in a listing: ``pattern`` (a regular expression)
    searched in each line of ``legacy/<tier>/<file>``."""
    tier: str
    file: str
    pattern: str


@dataclass(frozen=True)
class ListingLine:
    """One line of a listing: ``number`` counts from 1 in ``legacy/<tier>/<file>``; a printed
    line's ``seed_line`` (in ``seed``) is where the thesis prints it, None if the scan lacks it."""
    tier: str
    file: str
    number: int
    text: str
    seed: str | None = None
    seed_line: int | None = None

    @property
    def path(self) -> str:
        return f"legacy/{self.tier}/{self.file}"

    @property
    def tags(self) -> tuple[str, ...]:
        """The register ids the line is tagged with (``legacy/src`` edits)."""
        found = _TAG.search(self.text)
        return tuple(re.findall(r"D\d{3}", found.group(1))) if found else ()

    def where(self) -> str:
        """``legacy/printed/x.f:253 (seed 003 line 1290)``."""
        seed = f" (seed {self.seed[:3]} line {self.seed_line})" if self.seed_line else ""
        return f"{self.path}:{self.number}{seed}"


@lru_cache(maxsize=None)
def text(tier: str, file: str) -> tuple[str, ...]:
    """The listing's lines (trailing blanks stripped)."""
    if tier not in TIERS:
        raise ListingNotFound(f"no tier {tier!r}: {', '.join(TIERS)}")
    path = ROOT / "legacy" / tier / file
    if not path.is_file():
        raise ListingNotFound(f"no listing {path}")
    return tuple(line.rstrip() for line in path.read_text().splitlines())


def line(tier: str, file: str, number: int) -> ListingLine:
    """Line ``number`` (from 1) of ``legacy/<tier>/<file>``, with its seed line if printed."""
    lines = text(tier, file)
    if not 1 <= number <= len(lines):
        raise ListingNotFound(f"legacy/{tier}/{file} has {len(lines)} lines, not a line {number}")
    seed, seed_line = (None, None)
    if tier == "printed":
        seed, numbers = seed_lines(file)
        seed_line = numbers.get(number)
    return ListingLine(tier, file, number, lines[number - 1], seed, seed_line)


def find(statement: Statement) -> list[ListingLine]:
    """Every line of the statement's listing that its pattern matches, with the continuation
    cards that follow it (a character other than blank or 0 in column 6)."""
    return list(_found(statement))


@lru_cache(maxsize=None)
def _found(statement: Statement) -> tuple[ListingLine, ...]:
    pattern, cards = re.compile(statement.pattern), text(statement.tier, statement.file)
    numbers = []
    for n, card in enumerate(cards, 1):
        if pattern.search(card) or (numbers and numbers[-1] == n - 1 and _continues(card)):
            numbers.append(n)
    return tuple(line(statement.tier, statement.file, n) for n in numbers)


def _continues(card: str) -> bool:
    return len(card) > 5 and card[:1].upper() not in "C*" and card[:5].strip() == "" and card[5] not in " 0"


@lru_cache(maxsize=None)
def seed_lines(file: str) -> tuple[str | None, dict[int, int]]:
    """(the seed file, {printed line number: seed line number}) for ``legacy/printed/<file>``;
    (None, {}) where the scan is not at hand.  Lines equal token for token are paired first;
    the tokens of the lines between two such pairs are then aligned one by one."""
    try:
        config = ocr_audit.scan_config(file)
        scan = ocr_audit.numbered_scan_lines(file)
    except FileNotFoundError:
        return None, {}
    ours = [ocr_audit.tokens([card], ocr_audit._PRINTED_COMMENT) for card in text("printed", file)]
    theirs = [ocr_audit.tokens([card], ocr_audit._SCAN_COMMENT) for _, card in scan]
    found: dict[int, int] = {}
    lines = difflib.SequenceMatcher(a=[" ".join(t) for t in ours], b=[" ".join(t) for t in theirs], autojunk=False)
    for op, i1, i2, j1, j2 in lines.get_opcodes():
        if op == "equal":
            found.update({i1 + k + 1: scan[j1 + k][0] for k in range(i2 - i1) if ours[i1 + k]})
            continue
        a, a_line = _flatten(ours, i1, i2)
        b, b_line = _flatten(theirs, j1, j2)
        votes: dict[int, Counter] = {}
        for x, y, size in difflib.SequenceMatcher(a=a, b=b, autojunk=False).get_matching_blocks():
            for k in range(size):
                votes.setdefault(a_line[x + k], Counter())[scan[b_line[y + k]][0]] += 1
        found.update({n + 1: count.most_common(1)[0][0] for n, count in votes.items()})
    return config["seed"], found


def align_every_listing() -> None:
    """Compute ``seed_lines`` for every printed listing now (about 0.4 s): a process that forks
    workers calls it first, so that they and its report share one alignment."""
    for path in sorted((ROOT / "legacy" / "printed").glob("*.f")):
        seed_lines(path.name)


def _flatten(cards: list[list[str]], first: int, last: int) -> tuple[list[str], list[int]]:
    """The tokens of cards[first:last] in one list, and the index of the card of each."""
    tokens, where = [], []
    for index in range(first, last):
        tokens += cards[index]
        where += [index] * len(cards[index])
    return tokens, where


@lru_cache(maxsize=None)
def _tagged() -> dict[str, tuple[ListingLine, ...]]:
    lines: dict[str, list[ListingLine]] = {}
    for path in sorted((ROOT / "legacy" / "src").glob("*.f")):
        for n, card in enumerate(text("src", path.name), 1):
            for tag in ListingLine("src", path.name, n, card).tags:
                lines.setdefault(tag, []).append(ListingLine("src", path.name, n, card))
    return {tag: tuple(found) for tag, found in lines.items()}


def tagged(entry_id: str) -> list[ListingLine]:
    """The ``legacy/src`` lines whose edit is tagged with ``entry_id``."""
    return list(_tagged().get(entry_id, ()))


def _numbers(text: str) -> list[int]:
    """"127, 143", "104-105", "1129 and 1342" as line numbers."""
    found = []
    for part in re.split(r"\s*(?:,|and)\s*", text.strip()):
        first, _, last = part.partition("-")
        found += range(int(first), int(last or first) + 1)
    return found


@lru_cache(maxsize=None)
def _printed_at(seed: str) -> dict[int, tuple[str, int]]:
    """{seed line: (printed listing, line number)} over every printed listing read from ``seed``
    (the first three characters of its file name, e.g. "003")."""
    found = {}
    for path in sorted((ROOT / "legacy" / "printed").glob("*.f")):
        name, numbers = seed_lines(path.name)
        if name and name.startswith(seed):
            for number, seed_line in sorted(numbers.items()):
                found.setdefault(seed_line, (path.name, number))
    return found


def _listing_seed(prefix: str) -> str | None:
    """The seed a thesis's listings were read from (``prefix``: "ali1977", the scene's first word)."""
    for path in sorted((ROOT / "legacy" / "printed").glob(f"{prefix}_*.f")):
        name, _ = seed_lines(path.name)
        if name:
            return name[:3]
    return None


def _seeds() -> list[str]:
    """Every seed a printed listing was read from ("000", "003")."""
    return sorted({name[:3] for path in (ROOT / "legacy" / "printed").glob("*.f")
                   if (name := seed_lines(path.name)[0])})


def cited(entry: Deviation) -> list[ListingLine]:
    """The listing lines a register entry names: ``legacy/printed/<file> line(s) ...`` in its
    ``where``; the printed lines read from the seed lines it names (``seed 003 lines 1191 and
    1207``, or ``seed line(s) ...`` of the seed of its table's listings); the chosen line of each
    of its readings."""
    found = []
    for tier, file, numbers in _CITED.findall(entry.where):
        for n in _numbers(numbers):
            try:
                found.append(line(tier, file, n))
            except ListingNotFound:
                pass                     # the register's tests flag a wrong citation
    thesis = entry.cells[0].scene.split("-")[0] if entry.cells else None
    for seed, numbers in _SEED_CITED.findall(entry.where):
        seeds = [seed or _listing_seed(thesis)] if seed or thesis else _seeds()
        for n in _numbers(numbers):
            places = [_printed_at(s)[n] for s in seeds if n in _printed_at(s)]
            if len(places) == 1 and line("printed", *places[0]) not in found:   # never a guess between theses
                found.append(line("printed", *places[0]))
    for reading in entry.readings:             # in printed/ (Ali) or, where it is not there, src/
        exact = "^" + re.escape(reading["chosen"].rstrip()) + "$"
        for tier in TIERS:
            cards = find(Statement(tier, reading["file"], exact))
            if cards:
                found += [card for card in cards if card not in found]
                break
    return found
