"""The deviation register, harness/deviations.toml: every difference between what
the thesis meant and what a run shows, with its evidence.

An entry's ``[[deviation.check]]`` items make its quoted measurements re-runnable: ``command``
is a command the entry's text quotes (in backticks) for a reader to re-measure with;
``python`` is code that prints the entry's quoted figures, in order (for a quoted
``python -c "CODE"`` command, CODE itself when ``python`` is left out); ``figures`` are
those figures as the text quotes them.  ``figures_reproduced`` says whether what the code
printed reproduces them to the digits quoted (tests/harness/test_register_citations.py runs
every check).
"""
from __future__ import annotations

import copy
import re
import shlex
import tomllib
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation, ROUND_HALF_EVEN
from functools import lru_cache
from pathlib import Path

REGISTER_PATH = Path(__file__).resolve().parent / "deviations.toml"
KINDS = ("ocr", "original-bug", "portability", "published-misprint", "published-rounding", "unresolved",
         "model-assumption")
#: a modelling choice of a thesis that the corrected engines keep (not a bug): it claims no cell
#: and switches no quirk; its ``scenes`` are those whose corrected results still assume it
MODEL_ASSUMPTION = "model-assumption"
REQUIRED = ("id", "kind", "title", "where", "printed", "meant", "evidence", "effect")
#: the text fields of an entry a reader reads (and the register's tests search)
TEXT_FIELDS = ("title", "where", "printed", "meant", "evidence", "effect")
#: a number as a check prints it or an entry quotes it: 70, -1.2443, +1.320e-4, 2.1e+00
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")


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
class Check:
    """A re-measurement of figures an entry quotes (``[[deviation.check]]``)."""
    command: str | None = None    # the command the entry's text quotes, as a reader types it
    python: str | None = None     # code that prints ``figures`` in order (default: a quoted python -c's code)
    figures: tuple = ()           # the quoted figures, as quoted ("70", "-1.2443", "+1.320e-4")
    slow: bool = False            # run only on request (tests/harness/test_register_citations.py)

    @property
    def code(self) -> str | None:
        """The Python code that prints the figures: ``python``, or the code of a quoted
        ``python -c "..."`` command; None for a command whose own tests hold the figures."""
        if self.python:
            return self.python
        words = shlex.split(self.command or "")
        if words[:2] == ["python", "-c"] and len(words) == 3:
            return words[2]
        return None


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
    checks: tuple = ()                            # Check items: quoted figures and how to re-measure them
    scenes: tuple = ()                            # a model assumption's scenes (their corrected results assume it)

    @property
    def text(self) -> str:
        """Every field a reader reads, one per line."""
        return "\n".join(getattr(self, name) for name in TEXT_FIELDS)


def _check(entry_id: str, raw: dict) -> Check:
    unknown = set(raw) - {"command", "python", "figures", "slow"}
    if unknown:
        raise ValueError(f"register entry {entry_id}: check with unknown keys {sorted(unknown)}")
    figures = tuple(raw.get("figures", []))
    for figure in figures:
        if not isinstance(figure, str) or not NUMBER.fullmatch(figure):
            raise ValueError(f"register entry {entry_id}: check figure {figure!r} is not a number written as quoted")
    check = Check(command=raw.get("command"), python=raw.get("python"), figures=figures, slow=bool(raw.get("slow", False)))
    if not check.command and not check.python:
        raise ValueError(f"register entry {entry_id}: a check needs a command or python code")
    if figures and check.code is None:
        raise ValueError(f"register entry {entry_id}: check figures {figures} need code that prints them")
    return check


def parsed(path: Path = REGISTER_PATH) -> dict:
    """The register file as TOML data, read now; a fresh copy on every call (the text is
    parsed once per process for each content it has had: a run reads it in every scene)."""
    return copy.deepcopy(_parse(Path(path).read_bytes()))


@lru_cache(maxsize=4)
def _parse(data: bytes) -> dict:
    return tomllib.loads(data.decode())


def load(path: Path = REGISTER_PATH) -> dict[str, Deviation]:
    """Read and validate the register; raise ValueError on a malformed entry."""
    data = parsed(path)
    entries: dict[str, Deviation] = {}
    for raw in data.get("deviation", []):
        missing = [k for k in REQUIRED if not str(raw.get(k, "")).strip()]
        if missing:
            raise ValueError(f"register entry {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["kind"] not in KINDS:
            raise ValueError(f"register entry {raw['id']}: kind {raw['kind']!r} not in {KINDS}")
        if raw["id"] in entries:
            raise ValueError(f"register id {raw['id']} appears twice")
        if (raw["kind"] == MODEL_ASSUMPTION) != bool(raw.get("scenes")) or (
                raw["kind"] == MODEL_ASSUMPTION and any(raw.get(k) for k in ("cells", "quirk", "moves"))):
            raise ValueError(f"register entry {raw['id']}: `scenes` (the scenes whose corrected results assume it) "
                             f"for a {MODEL_ASSUMPTION} and only for one, which claims no cells and has no quirk")
        cells = tuple(CellClaim(c["scene"], tuple(c.get("rows", ["*"])), tuple(c.get("columns", ["*"])),
                                tuple(c["engines"])) for c in raw.get("cells", []))
        entries[raw["id"]] = Deviation(
            id=raw["id"], kind=raw["kind"], title=raw["title"], where=raw["where"],
            printed=raw["printed"], meant=raw["meant"], evidence=raw["evidence"],
            effect=raw["effect"], quirk=raw.get("quirk"), certainty=raw.get("certainty"),
            cells=cells, moves=dict(raw.get("moves", {})), readings=tuple(raw.get("reading", [])),
            checks=tuple(_check(raw["id"], c) for c in raw.get("check", [])), scenes=tuple(raw.get("scenes", ())))
    return entries


def by_quirk(entries: dict[str, Deviation]) -> dict[str, Deviation]:
    return {e.quirk: e for e in entries.values() if e.quirk}


def figure_reproduced(figure: str, printed: str) -> bool:
    """Whether a printed number reproduces a quoted figure to the digits quoted: the printed
    number rounded (half to even) at the figure's last digit is the figure, sign included
    ("-0.000" is not "0.000").  The printed text is taken as the number: print with enough
    digits (repr) for the figures quoted."""
    try:
        want, got = Decimal(figure), Decimal(printed)
    except InvalidOperation:
        return False
    quantum = Decimal(1).scaleb(want.as_tuple().exponent)
    return got.quantize(quantum, rounding=ROUND_HALF_EVEN) == want and got.is_signed() == want.is_signed()


def figures_reproduced(figures: tuple | list, output: str) -> list[str]:
    """What a check's output gets wrong (empty: every figure reproduced): the numbers ``output``
    prints, in order, against ``figures``, one for one."""
    printed = NUMBER.findall(output)
    if len(printed) != len(figures):
        return [f"printed {len(printed)} numbers {printed} for the {len(figures)} figures {list(figures)}"]
    return [f"quoted {want}, measured {got}" for want, got in zip(figures, printed)
            if not figure_reproduced(want, got)]
