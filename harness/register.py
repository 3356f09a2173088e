"""The deviation register, harness/deviations.toml: every difference between what
the thesis meant and what a run shows, with its evidence.
"""
from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path

REGISTER_PATH = Path(__file__).resolve().parent / "deviations.toml"
KINDS = ("ocr", "original-bug", "portability", "published-misprint", "published-rounding", "unresolved")
REQUIRED = ("id", "kind", "title", "where", "printed", "meant", "evidence", "effect")


@dataclass(frozen=True)
class CellClaim:
    """Cells of a published table that an entry explains, for some engines."""
    scene: str
    rows: tuple          # key values (e.g. input angles); ("*",) for every row
    columns: tuple       # column names; ("*",) for every column
    engines: tuple

    def covers(self, scene: str, row, column: str, engine: str) -> bool:
        return (scene == self.scene and engine in self.engines
                and ("*" in self.rows or row in self.rows)
                and ("*" in self.columns or column in self.columns))


@dataclass(frozen=True)
class Deviation:
    id: str
    kind: str
    title: str
    where: str
    printed: str
    meant: str
    evidence: str
    effect: str
    quirk: str | None = None
    certainty: str | None = None
    cells: tuple = ()
    moves: dict = field(default_factory=dict)     # scene -> columns the quirk moves
    readings: tuple = ()                          # {file, chosen, scan}: the scan's text put back


def load(path: Path = REGISTER_PATH) -> dict[str, Deviation]:
    """Read and validate the register; raise ValueError on a malformed entry."""
    with open(path, "rb") as fh:
        data = tomllib.load(fh)
    entries: dict[str, Deviation] = {}
    for raw in data.get("deviation", []):
        missing = [k for k in REQUIRED if not str(raw.get(k, "")).strip()]
        if missing:
            raise ValueError(f"register entry {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["kind"] not in KINDS:
            raise ValueError(f"register entry {raw['id']}: kind {raw['kind']!r} not in {KINDS}")
        if raw["id"] in entries:
            raise ValueError(f"register id {raw['id']} appears twice")
        cells = tuple(CellClaim(c["scene"], tuple(c.get("rows", ["*"])), tuple(c.get("columns", ["*"])),
                                tuple(c["engines"])) for c in raw.get("cells", []))
        entries[raw["id"]] = Deviation(
            id=raw["id"], kind=raw["kind"], title=raw["title"], where=raw["where"],
            printed=raw["printed"], meant=raw["meant"], evidence=raw["evidence"],
            effect=raw["effect"], quirk=raw.get("quirk"), certainty=raw.get("certainty"),
            cells=cells, moves=dict(raw.get("moves", {})), readings=tuple(raw.get("reading", [])))
    return entries


def by_quirk(entries: dict[str, Deviation]) -> dict[str, Deviation]:
    return {e.quirk: e for e in entries.values() if e.quirk}
