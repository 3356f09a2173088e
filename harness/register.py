"""The deviation register, harness/deviations.toml: every difference between what
the thesis meant and what a run shows, with its evidence.

An entry's ``[[deviation.check]]`` items make its quoted measurements re-runnable: ``command``
is a command the entry's text quotes (in backticks) for a reader to re-measure with;
``python`` is code that prints the entry's quoted figures, in order (for a quoted
``python -c "CODE"`` command, CODE itself when ``python`` is left out); ``figures`` are
those figures as the text quotes them.  ``figures_reproduced`` says whether what the code
printed reproduces them to the digits quoted (tests/harness/test_register_citations.py runs
every check).

How an entry knows (``basis``, one of BASES; ``settles``: what would settle an inferred one) and
how it explains cells: by a cause, or only by closeness (``tolerance``: a relative tolerance
within which it puts a cell's difference down to itself, without a run showing that cell's
cause; ``diff.classify_cells`` counts such cells apart, as within tolerance).  A ``cells`` claim
with ``whole = true`` says the entry accounts for those cells' whole difference, so that an
``unresolved`` entry naming them too does not make them unresolved (the entry's evidence and a
``[[deviation.check]]`` show it).
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
#: how an entry knows what it says (``basis``), and what each means
BASES = {"measured": "a run shows it (a scene, a check, a test or a command computes the effect or the cause)",
         "inferred": "from the published table's fit, neighbouring rows or a reconstruction of a lost page; "
                     "no run shows the cause itself",
         "theory": "from the thesis's theory chapter, an equation or an identity, not a run"}
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
    whole: bool = False  # the entry accounts for these cells' whole difference (wins over ``unresolved``)

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
    basis: str | None = None                      # one of BASES (None: not stated)
    settles: str | None = None                    # what would settle it (required where inferred)
    tolerance: float | None = None                # explains a cell only by closeness: relative tolerance
    cells: tuple = ()
    moves: dict = field(default_factory=dict)     # scene -> columns the quirk moves
    readings: tuple = ()                          # {file, chosen, scan}: the scan's text put back
    checks: tuple = ()                            # Check items: quoted figures and how to re-measure them
    scenes: tuple = ()                            # a model assumption's scenes (their corrected results assume it)

    @property
    def text(self) -> str:
        """Every field a reader reads, one per line."""
        return "\n".join(getattr(self, name) for name in TEXT_FIELDS)

    def how_known(self) -> list[tuple[str, str]]:
        """(field, words) for a reader: its basis and what it means, what would settle it, and
        the tolerance within which it explains a cell (the last two only where stated)."""
        shown = [("basis", f"{self.basis}: {BASES[self.basis]}" if self.basis else "not stated")]
        if self.settles:
            shown.append(("settles", self.settles))
        if self.tolerance is not None:
            shown.append(("tolerance", f"explains a cell only by closeness: within {self.tolerance:g} relative "
                                       "of the printed value (counted as within tolerance, not as explained)"))
        return shown


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


def _cells(raw: dict) -> tuple[CellClaim, ...]:
    claims = []
    for c in raw.get("cells", []):
        whole = c.get("whole", False)
        if not isinstance(whole, bool):
            raise ValueError(f"register entry {raw['id']}: cells 'whole' is {whole!r}, not true or false")
        claims.append(CellClaim(c["scene"], tuple(c.get("rows", ["*"])), tuple(c.get("columns", ["*"])),
                                tuple(c["engines"]), whole))
    return tuple(claims)


def _how_known(raw: dict) -> dict:
    """``basis``, ``settles`` and ``tolerance`` of an entry, validated (ValueError naming the entry)."""
    name, basis, settles, tolerance = raw["id"], raw.get("basis"), raw.get("settles"), raw.get("tolerance")
    if basis is not None and basis not in BASES:
        raise ValueError(f"register entry {name}: basis {basis!r} not in {tuple(BASES)}")
    if settles is not None and not (isinstance(settles, str) and settles.strip()):
        raise ValueError(f"register entry {name}: settles must say what evidence would settle it, not {settles!r}")
    if basis == "inferred" and settles is None:
        raise ValueError(f"register entry {name}: basis 'inferred' needs 'settles' (what evidence would settle it)")
    if tolerance is not None:
        if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float)) or not 0 < tolerance < 1:
            raise ValueError(f"register entry {name}: tolerance {tolerance!r} is not a relative tolerance in (0, 1)")
        if raw["kind"] == "unresolved":
            raise ValueError(f"register entry {name}: an unresolved entry explains nothing, within a tolerance or not")
        tolerance = float(tolerance)
    return {"basis": basis, "settles": settles, "tolerance": tolerance}


def _check_assumption(raw: dict) -> None:
    """``scenes`` for a model assumption, and only for one: a list of scene names; a model
    assumption claims no cells, switches no quirk and explains nothing within a tolerance."""
    name, scenes, assumed = raw["id"], raw.get("scenes"), raw["kind"] == MODEL_ASSUMPTION
    if not assumed and scenes is not None:
        raise ValueError(f"register entry {name}: `scenes` is for a {MODEL_ASSUMPTION} only (kind {raw['kind']!r})")
    if not assumed:
        return
    if not (isinstance(scenes, list) and scenes and all(isinstance(s, str) and s.strip() for s in scenes)):
        raise ValueError(f"register entry {name}: a {MODEL_ASSUMPTION} needs `scenes`, the names of the scenes "
                         f"whose corrected results assume it, not {scenes!r}")
    extra = [key for key in ("cells", "quirk", "moves", "tolerance") if raw.get(key) is not None]
    if extra:
        raise ValueError(f"register entry {name}: a {MODEL_ASSUMPTION} claims no cells and switches no quirk, "
                         f"but gives {', '.join(extra)}")


def _check_whole(entry: Deviation) -> None:
    """A claim that an entry accounts for cells' whole difference needs an entry that explains
    by a cause (not unresolved, not a tolerance) and a check that re-measures it."""
    if not any(c.whole for c in entry.cells):
        return
    if entry.kind == "unresolved" or entry.tolerance is not None:
        raise ValueError(f"register entry {entry.id}: 'whole' cells need an entry that explains by a cause, "
                         f"not {'an unresolved one' if entry.kind == 'unresolved' else 'a tolerance'}")
    if not entry.checks:
        raise ValueError(f"register entry {entry.id}: 'whole' cells need a [[deviation.check]] that measures "
                         "the whole difference")


def parsed(path: Path = REGISTER_PATH) -> dict:
    """The register file as TOML data, read now; a fresh copy on every call (the text is
    parsed once per process for each content it has had: a run reads it in every scene)."""
    return copy.deepcopy(_parse(Path(path).read_bytes()))


@lru_cache(maxsize=4)
def _parse(data: bytes) -> dict:
    return tomllib.loads(data.decode())


def raw_entries(path: Path = REGISTER_PATH) -> tuple[dict, ...]:
    """The register's entries as the TOML holds them, read now, parsed once a process for each
    content: shared, to be read and never changed (``parsed`` gives a copy to change)."""
    return tuple(_parse(Path(path).read_bytes()).get("deviation", []))


def load(path: Path = REGISTER_PATH) -> dict[str, Deviation]:
    """Read and validate the register; raise ValueError on a malformed entry.  The entries are
    built once a process for each content the file has had (a run reads it in every scene, a
    deep copy of the TOML each time cost about 0.5 s of a run's CPU) and shared: every call gives
    a new dict of the same frozen entries."""
    return dict(_entries(Path(path).read_bytes()))


@lru_cache(maxsize=4)
def _entries(data: bytes) -> dict[str, Deviation]:
    entries: dict[str, Deviation] = {}
    for raw in _parse(data).get("deviation", []):
        missing = [k for k in REQUIRED if not str(raw.get(k, "")).strip()]
        if missing:
            raise ValueError(f"register entry {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["kind"] not in KINDS:
            raise ValueError(f"register entry {raw['id']}: kind {raw['kind']!r} not in {KINDS}")
        if raw["id"] in entries:
            raise ValueError(f"register id {raw['id']} appears twice")
        _check_assumption(raw)
        entry = Deviation(
            id=raw["id"], kind=raw["kind"], title=raw["title"], where=raw["where"],
            printed=raw["printed"], meant=raw["meant"], evidence=raw["evidence"],
            effect=raw["effect"], quirk=raw.get("quirk"), certainty=raw.get("certainty"), **_how_known(raw),
            cells=_cells(raw), moves=dict(raw.get("moves", {})), readings=tuple(raw.get("reading", [])),
            checks=tuple(_check(raw["id"], c) for c in raw.get("check", [])), scenes=tuple(raw.get("scenes", ())))
        _check_whole(entry)
        entries[raw["id"]] = entry
    return entries


def assumed_by(scene: str, entries: dict[str, Deviation]) -> list[Deviation]:
    """The model assumptions (kind MODEL_ASSUMPTION) whose ``scenes`` name ``scene``: the thesis's
    modelling choices its corrected results keep, by id."""
    return [entry for _, entry in sorted(entries.items()) if scene in entry.scenes]


def assumptions_said(scene: str, entries: dict[str, Deviation]) -> str:
    """One sentence naming the model assumptions ``scene``'s corrected engine keeps ("" where none)."""
    kept = "; ".join(f"{entry.id} {entry.title}" for entry in assumed_by(scene, entries))
    return (f"The corrected engine (port_corrected) keeps the thesis's model (register kind `model-assumption`, "
            f"not bugs): {kept}.") if kept else ""


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
