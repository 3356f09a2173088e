"""``linkrepro differential``: legacy against the port with the listing's bugs, on a random
sample of geometries (or on geometries a user gives).

Each thesis gives its part in ``harness/scenes/<thesis>/differential.py``: a ``Thesis`` named
``DIFFERENTIAL`` with its parameters, the domains its samplers draw from, its programs (each a
pair of engines, legacy and the port with the listing's bugs, that take one geometry and return
named arrays) and its criterion, the one its differential tests assert.  This module names no
thesis: it draws the samples, runs both engines on each, classifies the outcomes, compares the
outputs and writes ``differential.csv`` and ``differential.md``.

What counts as the same:

- the outcome: both return, or both raise the same error class at the same input angle (the
  angle a ``LinkageError`` carries), with the same linkrepro warnings.  A program may accept a
  named difference of outcome its tests accept (``Program.accepts``), listed as such;
- the numbers, where both return: the same outputs, each equal bit for bit, or within its
  tolerance relative to the largest |legacy| of its column (``Program.rtol``), NaN where both
  hold NaN.

Units are the thesis's, as printed (its parameters say which).
"""
from __future__ import annotations

import json
import math
import time
import tomllib
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd

from ..errors import LinkreproWarning
from . import progress
from .csv_output import write_csv

OUTPUTS = ("differential.md", "differential.csv")
#: the disagreeing rows differential.md lists (all are in differential.csv)
LISTED = 20


class DifferentialUsageError(ValueError):
    """A request the command cannot run: an unknown parameter, program or domain, bad bounds,
    a bad geometry or geometry file (a usage error: status 2)."""


@dataclass(frozen=True)
class Parameter:
    """One input of a thesis's programs: its name (a column of differential.csv), its unit, how
    a bounded draw spreads it, and the range a user's bounds must keep within."""
    name: str
    unit: str
    log: bool = False                    # drawn log-uniformly in a user's bounds (positive ones)
    real4: bool = False                  # rounded to REAL*4 once drawn: what the listing holds
    limits: tuple[float, float] = (-math.inf, math.inf)    # bounds beyond these: a usage error


@dataclass(frozen=True)
class Domain:
    """A sampler: ``draw(rng, program)`` gives one geometry (every parameter) for a program."""
    name: str
    description: str
    draw: Callable[[np.random.Generator, str], dict]


@dataclass(frozen=True)
class Outcome:
    """What an engine did with a geometry: returned ``result`` (error ''), or raised ``error``
    (its class name) at ``angle`` (deg; None where the error names none); and the linkrepro
    warnings it gave (class and register entry)."""
    error: str = ""
    angle: float | None = None
    warnings: tuple[str, ...] = ()
    result: dict | None = field(default=None, compare=False, repr=False)

    @property
    def ok(self) -> bool:
        return not self.error

    @property
    def label(self) -> str:
        text = "ok" if self.ok else self.error + (f" at {self.angle:g} deg" if self.angle is not None else "")
        return text + (f" (warns {', '.join(self.warnings)})" if self.warnings else "")


@dataclass(frozen=True)
class Program:
    """One program of a thesis: its two engines (geometry -> outputs, name -> array) and how
    they are compared.  ``example``: the published run's geometry (a given geometry's missing
    parameters); ``rtol``: output -> tolerance relative to each column's largest |legacy| (an
    output not named: bit for bit); ``accepts(legacy, port)``: where the outcomes differ in a
    way the thesis's tests accept, why ('' where they do not)."""
    name: str
    title: str
    legacy: Callable[[dict], dict]
    port: Callable[[dict], dict]
    example: dict
    rtol: dict = field(default_factory=dict)
    accepts: Callable[[Outcome, Outcome], str] = lambda legacy, port: ""


@dataclass(frozen=True)
class Thesis:
    """A thesis's part of the differential (its hook module's ``DIFFERENTIAL``)."""
    title: str
    parameters: tuple[Parameter, ...]
    domains: tuple[Domain, ...]          # the first is the default
    programs: tuple[Program, ...]
    criterion: str                       # how its tests compare legacy and port, in words

    def parameter(self, name: str) -> Parameter:
        for p in self.parameters:
            if p.name == name:
                return p
        raise DifferentialUsageError(f"unknown parameter {name!r}; this thesis's: "
                                     f"{', '.join(p.name for p in self.parameters)}")

    def domain(self, name: str | None) -> Domain:
        if name is None:
            return self.domains[0]
        for d in self.domains:
            if d.name == name:
                return d
        raise DifferentialUsageError(f"unknown domain {name!r}; this thesis's: {', '.join(d.name for d in self.domains)}")

    def chosen(self, names: list[str] | None) -> tuple[Program, ...]:
        known = {p.name: p for p in self.programs}
        unknown = [n for n in names or [] if n not in known]
        if unknown:
            raise DifferentialUsageError(f"unknown program {', '.join(map(repr, unknown))}; this thesis's: {', '.join(known)}")
        return tuple(p for p in self.programs if not names or p.name in names)


# ------------------------------------------------------------------ what a user gives

def _number(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise DifferentialUsageError(f"{what}: {text!r} is not a number") from None
    if not math.isfinite(value):
        raise DifferentialUsageError(f"{what}: {text!r} is not a finite number")
    return value


def _in_limits(p: Parameter, value: float, what: str) -> None:
    lo, hi = p.limits
    if not lo <= value <= hi:
        raise DifferentialUsageError(f"{what}: {p.name} = {value:g} {p.unit} is outside {lo:g}..{hi:g}")


def parse_bounds(thesis: Thesis, texts: list[str]) -> dict[str, tuple[float, float]]:
    """``NAME=LO:HI`` (or ``NAME=VALUE``, a constant) -> {name: (lo, hi)}."""
    bounds = {}
    for text in texts:
        name, sep, span = text.partition("=")
        if not sep or not name.strip():
            raise DifferentialUsageError(f"--bounds {text!r}: write NAME=LO:HI (or NAME=VALUE)")
        p = thesis.parameter(name.strip())
        lo_text, colon, hi_text = span.partition(":")
        lo = _number(lo_text, f"--bounds {text}")
        hi = _number(hi_text, f"--bounds {text}") if colon else lo
        if lo > hi:
            raise DifferentialUsageError(f"--bounds {text}: the lower bound {lo:g} is above the upper {hi:g}")
        if p.log and lo <= 0 < hi:
            raise DifferentialUsageError(f"--bounds {text}: {p.name} is drawn log-uniformly, its bounds must be > 0")
        for value in (lo, hi):
            _in_limits(p, value, f"--bounds {text}")
        if p.name in bounds:
            raise DifferentialUsageError(f"--bounds: {p.name} is bounded twice")
        bounds[p.name] = (lo, hi)
    return bounds


def parse_geometry(thesis: Thesis, texts: list[str]) -> dict[str, float]:
    """``NAME=VALUE ...`` -> {name: value} (a REAL*4 parameter rounded to REAL*4)."""
    geometry = {}
    for text in texts:
        name, sep, value = text.partition("=")
        if not sep:
            raise DifferentialUsageError(f"--geometry {text!r}: write NAME=VALUE")
        geometry[thesis.parameter(name.strip()).name] = _number(value, f"--geometry {text}")
    return _checked(thesis, geometry, "--geometry")


def _checked(thesis: Thesis, geometry: dict, what: str) -> dict[str, float]:
    out = {}
    for name, value in geometry.items():
        p = thesis.parameter(str(name))
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise DifferentialUsageError(f"{what}: {name} = {value!r} is not a number")
        value = _number(repr(value), what)
        _in_limits(p, value, what)
        out[p.name] = float(np.float32(value)) if p.real4 else value
    return out


def read_geometries(thesis: Thesis, path: Path) -> list[dict[str, float]]:
    """A JSON or TOML file: one geometry (a table of NAME = VALUE), or several (a JSON list of
    them, or TOML ``[[geometry]]`` tables)."""
    try:
        text = Path(path).read_text()
    except OSError as exc:
        raise DifferentialUsageError(f"--geometry-file {path}: {exc.strerror or exc}") from None
    try:
        data = json.loads(text) if Path(path).suffix.lower() == ".json" else tomllib.loads(text)
    except (ValueError, tomllib.TOMLDecodeError) as exc:
        raise DifferentialUsageError(f"--geometry-file {path}: not valid {Path(path).suffix.lstrip('.') or 'TOML'} ({exc})") from None
    if isinstance(data, dict) and set(data) == {"geometry"} and isinstance(data["geometry"], list):
        data = data["geometry"]
    items = data if isinstance(data, list) else [data]
    if not items or not all(isinstance(item, dict) for item in items):
        raise DifferentialUsageError(f"--geometry-file {path}: expected a table of NAME = VALUE, or a list of them")
    return [_checked(thesis, item, f"--geometry-file {path}") for item in items]


# ------------------------------------------------------------------ the samples

def _bounded(rng: np.random.Generator, p: Parameter, lo: float, hi: float) -> float:
    if lo == hi:
        value = lo
    elif p.log and lo > 0:
        value = float(np.exp(rng.uniform(math.log(lo), math.log(hi))))
    else:
        value = float(rng.uniform(lo, hi))
    return float(np.float32(value)) if p.real4 else value


def draw(thesis: Thesis, domain: Domain, program: str, count: int, seed: int,
         bounds: dict[str, tuple[float, float]] | None = None) -> list[dict]:
    """``count`` geometries of ``domain`` for ``program`` (numpy's ``default_rng(seed)``, one
    generator per program: a program's sample does not depend on the others run beside it);
    each bounded parameter drawn afterwards in its bounds, independently of the others."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(count):
        g = domain.draw(rng, program)
        for name, (lo, hi) in (bounds or {}).items():
            g[name] = _bounded(rng, thesis.parameter(name), lo, hi)
        out.append(g)
    return out


# ------------------------------------------------------------------ one sample

def run_engine(call: Callable[[dict], dict], geometry: dict) -> Outcome:
    """Run one engine on one geometry: its outputs, or the error it raised.  An exception of
    any class is an outcome (an untyped one is a difference to report, not a reason to stop)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", LinkreproWarning)
        try:
            result, error, angle = call(dict(geometry)), "", None
        except Exception as exc:               # noqa: BLE001 -- every failure is an outcome here
            result, error, angle = None, type(exc).__name__, getattr(exc, "angle_deg", None)
    warned = tuple(sorted({f"{w.category.__name__} {getattr(w.message, 'entry', '')}".strip() for w in caught
                           if issubclass(w.category, LinkreproWarning)}))
    return Outcome(error, None if angle is None else float(angle), warned, result)


@dataclass(frozen=True)
class Comparison:
    """How one sample's two runs compare."""
    same_outcome: bool
    agree: bool                          # the same by the thesis's criterion
    largest: float                       # the largest |port - legacy| over the outputs beyond the criterion
    where: str                           # where there are any, else over all (NaN: none compared); its output and index
    note: str                            # why they differ, or the accepted difference


def _output_difference(name: str, legacy, port, rtol: float) -> tuple[float, str, bool, str]:
    """(largest |port - legacy|, where, within the tolerance, why not)."""
    a, b = np.asarray(legacy, dtype=float), np.asarray(port, dtype=float)
    if a.shape != b.shape:
        return math.nan, name, False, f"{name}: shape {b.shape} in the port, {a.shape} in legacy"
    if a.size == 0:
        return 0.0, name, True, ""
    both_nan = np.isnan(a) & np.isnan(b)
    with np.errstate(invalid="ignore"):
        diff = np.where(both_nan, 0.0, np.abs(b - a))
    diff = np.where(np.isnan(diff), np.inf, diff)          # NaN on one side only
    index = np.unravel_index(int(np.argmax(diff)), diff.shape)
    where = name + (f"[{','.join(map(str, index))}]" if diff.ndim else "")
    largest = float(diff[index])
    if rtol == 0.0:
        within = bool(np.array_equal(a, b, equal_nan=True))
    else:
        scale = np.nanmax(np.abs(a), axis=0) if a.ndim else np.abs(a)
        within = bool(np.all(diff <= rtol * scale))
    why = "" if within else (f"{name} differs bit-wise" if rtol == 0.0 else f"{name} differs by more than {rtol:g} "
                             "of its column's largest |legacy|")
    return largest, where, within, why


def compare(program: Program, legacy: Outcome, port: Outcome) -> Comparison:
    """The thesis's criterion on one sample (see the module docstring)."""
    same = legacy == port
    if not same:
        accepted = program.accepts(legacy, port)
        return Comparison(False, bool(accepted), math.nan, "", accepted or "the outcomes differ")
    if not legacy.ok:
        return Comparison(True, True, math.nan, "", "")
    missing = sorted(set(legacy.result) ^ set(port.result))
    if missing:
        return Comparison(True, False, math.nan, "", f"outputs only one engine gives: {', '.join(missing)}")
    found = [(name, *_output_difference(name, legacy.result[name], port.result[name], program.rtol.get(name, 0.0)))
             for name in sorted(legacy.result)]
    beyond = [f for f in found if not f[3]]
    largest, where = math.nan, ""
    for _, d, at, _, _ in beyond or found:   # the largest where the criterion fails, else anywhere
        if math.isnan(largest) or not d <= largest:          # NaN (a shape mismatch) wins too
            largest, where = d, (at if d != 0 else "")
    return Comparison(True, not beyond, largest, where, "; ".join(f[4] for f in beyond))


# ------------------------------------------------------------------ a run

@dataclass
class Run:
    """One command's samples, compared: ``rows`` (differential.csv) and what the markdown states."""
    command: str
    seed: int
    parts: list = field(default_factory=list)      # (thesis key, Thesis, Domain | None, bounds, programs)
    rows: list = field(default_factory=list)
    seconds: dict = field(default_factory=dict)    # (thesis key, program) -> seconds of both engines

    @property
    def differ(self) -> int:
        return sum(not row["agree"] for row in self.rows)


def run(command: str, plan: list[tuple], seed: int) -> Run:
    """Run ``plan``: (thesis key, Thesis, programs, Domain or None, bounds, geometries by program)."""
    result = Run(command, seed)
    total = sum(len(geometries[p.name]) for _, _, programs, _, _, geometries in plan for p in programs)
    with progress.Bar(total):
        for key, thesis, programs, domain, bounds, geometries in plan:
            result.parts.append((key, thesis, domain, bounds, programs))
            for program in programs:
                progress.note("differential", f"{key} {program.name}")
                start = time.perf_counter()
                for index, g in enumerate(geometries[program.name]):
                    legacy, port = run_engine(program.legacy, g), run_engine(program.port, g)
                    c = compare(program, legacy, port)
                    result.rows.append(dict(thesis=key, program=program.name, sample=index, **g, legacy=legacy.label,
                                            port=port.label, same_outcome=c.same_outcome, largest_abs_diff=c.largest,
                                            in_output=c.where, agree=c.agree, note=c.note))
                    progress.done("differential")
                result.seconds[key, program.name] = time.perf_counter() - start
    return result


def frame(result: Run) -> pd.DataFrame:
    """differential.csv: a row per sample and program; the inputs (every thesis's parameters)
    between ``sample`` and ``legacy``."""
    names = list(dict.fromkeys(p.name for _, thesis, *_ in result.parts for p in thesis.parameters))
    columns = ["thesis", "program", "sample", *names, "legacy", "port", "same_outcome", "largest_abs_diff",
               "in_output", "agree", "note"]
    return pd.DataFrame(result.rows, columns=columns)


def _span(values: pd.Series) -> str:
    values = values.dropna()
    if values.empty:
        return ""
    lo, hi = values.min(), values.max()
    return f"{lo:.6g}" if lo == hi else f"{lo:.6g} .. {hi:.6g}"


def _rerun(key: str, program: str, row: dict, names: list[str]) -> str:
    given = " ".join(f"{name}={float(row[name])!r}" for name in names)
    return f"linkrepro differential {key} --program {program} --geometry {given}"


def markdown(result: Run, table: pd.DataFrame, seconds: float) -> str:
    """differential.md: the verdict, the criterion, the domain, the counts per program, the
    timings, and the samples where legacy and port differ."""
    n, differ = len(table), result.differ
    lines = ["# Legacy against the port with the listing's bugs", "",
             f"`{result.command}`: {n} samples, each run on both engines, in {seconds:.1f} s.", "",
             (f"**Legacy and the port agree on all {n} samples.**" if not differ else
              f"**Legacy and the port differ on {differ} of {n} samples** (listed below; every row is in differential.csv)."),
             ""]
    for key, thesis, domain, bounds, programs in result.parts:
        rows = table[table.thesis == key]
        names = [p.name for p in thesis.parameters]
        lines += [f"## {thesis.title} ({key})", "", f"Criterion: {thesis.criterion}", ""]
        if domain is None:
            lines += ["Geometries: given by the user (parameters not given: the published example's, per program; "
                      "those the listing holds in REAL*4 rounded to REAL*4).", ""]
        else:
            lines += [f"Domain `{domain.name}` (seed {result.seed}): {domain.description}", ""]
        if bounds:
            lines += ["User bounds (each drawn in its bounds after the domain's draw, independently of the other "
                      "parameters; log-uniformly where marked, rounded to REAL*4 where marked): "
                      + "; ".join(f"{name} {lo:g}..{hi:g} {thesis.parameter(name).unit}"
                                  f"{' (log)' if thesis.parameter(name).log else ''}"
                                  f"{' (REAL*4)' if thesis.parameter(name).real4 else ''}"
                                  for name, (lo, hi) in bounds.items()), ""]
        lines += ["| parameter | unit | values drawn |", "|---|---|---|"]
        lines += [f"| {p.name} | {p.unit} | {_span(rows[p.name])} |" for p in thesis.parameters]
        lines += ["", "| program | samples | same outcome: both return | both raise | accepted difference | differ "
                  "| largest \\|port - legacy\\| (where) | samples/s |", "|---|---|---|---|---|---|---|---|"]
        for program in programs:
            mine = rows[rows.program == program.name]
            both_ok = mine.same_outcome & (mine.legacy.str.startswith("ok"))
            raised = mine[mine.same_outcome & ~mine.legacy.str.startswith("ok")]
            by_class = raised.legacy.str.split(" ").str[0].value_counts()
            accepted = (~mine.same_outcome & mine.agree).sum()
            finite = mine.largest_abs_diff.dropna()
            at = mine.loc[finite.idxmax(), "in_output"] if not finite.empty else ""
            worst = "-" if finite.empty else f"{finite.max():.3g}" + (f" ({at})" if at else "")
            rate = len(mine) / max(result.seconds[key, program.name], 1e-9)
            lines.append(f"| {program.name} | {len(mine)} | {both_ok.sum()} | "
                         f"{', '.join(f'{k} {v}' for k, v in by_class.items()) or 0} | {accepted} | "
                         f"{(~mine.agree).sum()} | {worst} | {rate:.0f} |")
        lines += ["", "The largest |port - legacy| over the outputs compared (on a sample where one is beyond the "
                  "criterion, over those), in that output's unit (where: the output and its index); samples/s: both "
                  "engines on a sample, per second of this run."]
        notes = rows[~rows.same_outcome & rows.agree].note.value_counts()
        if not notes.empty:
            lines += ["", "Accepted differences of outcome: " + "; ".join(f"{k} ({v})" for k, v in notes.items()) + "."]
        lines.append("")
        bad = rows[~rows.agree]
        if not bad.empty:
            lines += [f"### Where they differ ({len(bad)}{f', the first {LISTED}' if len(bad) > LISTED else ''})", "",
                      "| program | sample | legacy | port | largest \\|port - legacy\\| | why |", "|---|---|---|---|---|---|"]
            for _, row in bad.head(LISTED).iterrows():
                size = "" if math.isnan(row.largest_abs_diff) else f"{row.largest_abs_diff:.3g} in {row.in_output}"
                lines.append(f"| {row.program} | {row['sample']} | {row.legacy} | {row.port} | {size} | {row.note} |")
            row = bad.iloc[0]
            lines += ["", "To run the first again alone:", "", "```console",
                      _rerun(key, row.program, row.to_dict(), names), "```", ""]
    return "\n".join(lines) + "\n"


def write(result: Run, out: Path, seconds: float) -> str:
    """Write differential.csv and differential.md into ``out``; return the markdown."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    table = frame(result)
    write_csv(table, out / "differential.csv")
    text = markdown(result, table, seconds)
    (out / "differential.md").write_text(text)
    return text


def plan_of(key: str, thesis: Thesis, programs: list[str] | None, samples: int, seed: int, domain: str | None,
            bounds: list[str], geometries: list[dict] | None) -> tuple:
    """One thesis's part of a run: its programs, its domain (None for given geometries), its
    bounds, and the geometries by program.  Bad requests raise DifferentialUsageError."""
    chosen = thesis.chosen(programs)
    if geometries is not None:
        if bounds or domain:
            raise DifferentialUsageError("a given geometry takes no --bounds or --domain (they shape the random sample)")
        return key, thesis, chosen, None, {}, {p.name: [dict(p.example, **g) for g in geometries] for p in chosen}
    if samples < 1:
        raise DifferentialUsageError(f"--samples must be a whole number >= 1, not {samples}")
    d, limits = thesis.domain(domain), parse_bounds(thesis, bounds)
    return key, thesis, chosen, d, limits, {p.name: draw(thesis, d, p.name, samples, seed, limits) for p in chosen}
