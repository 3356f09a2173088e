"""The fuzz's calls: hostile values, call specifications and their generation.

Each call is one line of Python text, evaluated in the namespace the fuzz command builds
(``harness/fuzz.py``); the text is its own reproducer.  For every entry point an ``Entry``
holds a generator of such calls (``spec(rng) -> Call``): valid values from the domain, with
none, one or two arguments replaced by a hostile value (NaN, +-inf, 0, negative, 1e300,
1e-300, subnormal and huge floats, integers beyond any float, wrong shapes, dtypes and
container types).  The theses give their entry points (``harness/scenes/<thesis>/fuzz.py``);
this module knows none of them.  Two names of the namespace let a hostile value be another
thesis's object without naming it: ``ANY_INPUTS`` (every thesis's input dataclasses) and
``ANY_QUIRKS`` (every thesis's quirk presets).
"""
from __future__ import annotations

import random
import re
from dataclasses import dataclass
from typing import Callable


# --- hostile values ----------------------------------------------------------------------

@dataclass(frozen=True)
class Pool:
    """Hostile replacements for one kind of argument.  ``kind`` says which must be refused:
    'num' (NaN or infinity inside), 'angles' (that, or not 1-D), 'other' (none)."""
    kind: str
    values: tuple

    def refuses(self, text: str) -> bool:
        """True if the library must raise ValueError/TypeError for this value."""
        if self.kind == "other":
            return False
        return bool(re.search(r"\b(nan|inf)\b", text)) or (self.kind == "angles" and text in NOT_1D)


_SHARED = ("None", "'abc'", "'1.5'", "(1+2j)", "True", "object()", "{}", "[1.0, 2.0]")
FLOAT = Pool("num", ("nan", "inf", "-inf", "0.0", "-1.0", "1e300", "-1e300", "1e-300", "-1e-300",
                     "5e-324", "-5e-324", "1.7976931348623157e308", "10**400", "-10**400",
                     "np.float32('nan')", "np.int64(7)", "10**30", "np.array([1.0, 2.0])",
                     "np.array([])") + _SHARED)
INT = Pool("num", ("0", "-1", "2.5", "nan", "inf", "10**9", "10**30", "2**63", "-2**31", "3.0",
                   "10**400", "-10**400", "np.int8(3)", "np.array([1, 2])") + _SHARED)
#: angle arrays that must be refused (a 0-D array, like a scalar, may count as one angle)
NOT_1D = ("np.array([[0.0, 30.0], [60.0, 90.0]])", "np.zeros((2, 0))", "np.ones((1, 1, 3))")
ANGLES = Pool("angles", NOT_1D + ("np.array(30.0)", 
    "np.array([])", "np.array([0.0, nan])", "np.array([inf, 10.0])", "np.array([-inf])",
    "np.array([1e300, 0.0])", "np.array([1e-300])", "np.array([-1e300])", "np.array(['0', '10'])",
    "np.array([None, 1.0], dtype=object)", "np.array([1j, 2.0])", "np.array([True, False])",
    "np.array([0, 90, 180])", "np.array([0.0, 30.0], dtype=np.float16)", "(0.0, 45.0)",
    "30.0", "'30'", "None", "{0: 1.0}", "[0.0, [1.0]]"))
MATRIX = Pool("num", ("np.array([])", "np.array(1.0)", "np.zeros((0, 3))", "np.ones((2, 3, 4))",
                      "np.array([[nan, 1.0], [2.0, inf]])", "np.full((5, 5), nan)", "np.full((5, 5), 1e300)",
                      "np.full((5, 5), 1e-300)", "np.eye(5) * -1e300", "np.eye(4)", "np.eye(6)",
                      "np.zeros((5, 5))", "[[1.0, 2.0], [3.0]]", "np.array([['a', 'b']])",
                      "np.eye(5, dtype=complex)", "np.eye(5, dtype=bool)", "np.eye(5, dtype=int)",
                      "np.eye(5).astype(object)", "np.array([[None, 1.0]], dtype=object)",
                      "np.eye(5)[:, :4]", "np.eye(9) * inf", "np.eye(9)") + _SHARED)
VECTOR = Pool("num", ("np.array([])", "np.array(1.0)", "np.array([nan])", "np.full(9, inf)",
                      "np.full(9, 1e300)", "np.full(9, -1e300)", "np.full(9, 1e-300)", "np.zeros(9)",
                      "-np.ones(9)", "np.ones(10)", "np.ones((3, 3))", "np.array(['a'] * 9)",
                      "np.ones(9, dtype=complex)", "np.ones(9, dtype=bool)", "np.ones(9, dtype=object)",
                      "np.array([None] * 9)") + _SHARED)
FLAG = Pool("other", ("None", "'yes'", "np.array([True, False])", "2", "nan", "[]"))
CONTAINER = Pool("other", ("None", "(10.0, 10.0, 30.0, 25.0, 30.0)", "{'l1': 10.0}", "'x'", "1.0",
                           "[2.0, 8.0]", "np.ones(5)", "object()")
                 + tuple(f"ANY_INPUTS[{k} % len(ANY_INPUTS)]" for k in range(4)))
QUIRKS = Pool("other", ("None", "'PRINTED'", "True", "0", "{}", "object()")
              + tuple(f"ANY_QUIRKS[{k} % len(ANY_QUIRKS)]" for k in range(6)))


# --- call specifications -----------------------------------------------------------------

@dataclass
class Arg:
    """One argument: its valid value (text, or a nested Call), hostile pool, and whether it
    may be left to its default (keyword arguments only)."""
    name: str | None
    valid: "str | Call"
    pool: Pool
    optional: bool = False
    hostile: str | None = None


@dataclass
class Call:
    """A call of ``func`` (text) with arguments; nested Calls build dataclass arguments."""
    func: str
    args: list

    def slots(self) -> list:
        """Every argument, nested ones included."""
        out = []
        for arg in self.args:
            out.append(arg)
            if isinstance(arg.valid, Call):
                out += arg.valid.slots()
        return out

    def pick(self, rng: random.Random) -> Arg:
        """An argument to make hostile: each of this call's arguments equally likely (so the
        angles are as likely as a whole dataclass), a nested one's fields 3 times in 4."""
        arg = rng.choice(self.args)
        if isinstance(arg.valid, Call) and arg.valid.args and rng.random() < 0.75:
            return arg.valid.pick(rng)
        return arg

    def render(self, rng: random.Random) -> tuple[str, list]:
        """The call as Python text and its hostile arguments (label, value, must be refused);
        optional arguments without a hostile value are left to their defaults now and then."""
        parts, used = [], []
        for i, arg in enumerate(self.args):
            nested = isinstance(arg.valid, Call)
            touched = arg.hostile is not None or (nested and any(a.hostile for a in arg.valid.slots()))
            if not touched and arg.optional and rng.random() < 0.25:
                continue
            if arg.hostile is not None:
                label = arg.name or f"{self.func.rsplit('.', 1)[-1]}[{i}]"
                value, inner = arg.hostile, [(label, arg.hostile, arg.pool.refuses(arg.hostile))]
            else:
                value, inner = arg.valid.render(rng) if nested else (arg.valid, [])
            parts.append(value if arg.name is None else f"{arg.name}={value}")
            used += inner
        return f"{self.func}({', '.join(parts)})", used


def num(rng, lo, hi, digits=4) -> str:
    return repr(round(rng.uniform(lo, hi), digits))


def near(rng, value, spread=0.2, lo=0.5, hi=60.0) -> str:
    """The default, a value close to it, or one anywhere in [lo, hi]."""
    u = rng.random()
    if u < 0.2:
        return repr(float(value))
    return num(rng, value * (1 - spread), value * (1 + spread)) if u < 0.8 else num(rng, lo, hi)


def angles(rng, most=24, lo=-360.0, hi=720.0) -> str:
    """A short 1-D array of angles (deg): special ones and random ones."""
    special = (0.0, 90.0, 180.0, 270.0, 360.0, -90.0, 45.0, 100.0, 300.0, 20.0)
    values = [rng.choice(special) if rng.random() < 0.5 else round(rng.uniform(lo, hi), 3)
              for _ in range(rng.randint(1, most))]
    return f"np.array({values})" if rng.random() < 0.85 else repr(values)


def any_seed(rng) -> int:
    return rng.randint(0, 9999)


def quirk_set(rng, names: list[str], presets: tuple) -> str:
    """A preset of a quirk family (call text), or one with one of its switches ``names`` flipped."""
    base = rng.choice(presets)
    if rng.random() < 0.3:
        return f"{base}.only({rng.choice(names)!r}, {rng.random() < 0.5})"
    return base


def scale_of(rng) -> str:
    """Nothing (half the time), or a factor 10**k, k from -150 to 150, as call text."""
    return "" if rng.random() < 0.5 else f" * 1e{rng.randint(-150, 150)}"


@dataclass(frozen=True)
class Entry:
    """A public entry point: its name, its call generator, whether it has input angles (a
    LinkageError must then name one), and the function that removes documented NaN."""
    name: str
    spec: Callable
    angles: bool = False
    scrub: str | None = None
    check: str | None = None


@dataclass
class Job:
    """One call to run: its text and what the classification needs to know."""
    index: int
    entry: str
    text: str
    angles: bool = False
    scrub: str | None = None
    refused: tuple = ()         # names of arguments whose value must be refused
    hostile: tuple = ()         # name=value of every hostile argument
    timeout: float | None = None  # seconds before it counts as a hang (None: the run's)
    check: str | None = None    # CHECKS: what a returned result must satisfy


def make_job(entry: Entry, rng: random.Random) -> Job:
    """Build a valid call and replace 0, 1 or 2 of its arguments by hostile values."""
    call = entry.spec(rng)
    for _ in range(rng.choices((0, 1, 2), weights=(30, 50, 20))[0]):
        arg = call.pick(rng)
        arg.hostile = rng.choice(arg.pool.values)
    text, chosen = call.render(rng)
    return Job(0, entry.name, text, entry.angles, entry.scrub,
               refused=tuple(label for label, _, refuses in chosen if refuses),
               hostile=tuple(f"{label}={value}" for label, value, _ in chosen), check=entry.check)


def generate(entries: list, calls: int, seed_value: int, only: str | None = None) -> list:
    """``calls`` jobs spread evenly over ``entries`` (those whose name contains ``only``),
    interleaved; one random stream per entry point (seeded by the seed and its name), so an
    entry's calls do not depend on the others."""
    chosen = [e for e in entries if only is None or only in e.name]
    if not chosen:
        raise ValueError(f"no entry point matches {only!r}")
    per_entry = []
    for k, entry in enumerate(chosen):
        rng = random.Random(f"{seed_value}:{entry.name}")
        count = calls // len(chosen) + (k < calls % len(chosen))
        per_entry.append([make_job(entry, rng) for _ in range(count)])
    jobs = [job for round_ in _interleave(per_entry) for job in round_]
    for i, job in enumerate(jobs):
        job.index = i
    return jobs


def _interleave(lists):
    for i in range(max(map(len, lists))):
        yield [lst[i] for lst in lists if i < len(lst)]


def rand(shape, seed_value):
    """A reproducible standard-normal array (for call texts)."""
    import numpy as np
    return np.random.default_rng(seed_value).standard_normal(shape)


def spd(n, seed_value, rank=None):
    """A reproducible symmetric positive (semi-)definite n x n matrix of the given rank."""
    import numpy as np
    m = rand((n, rank or n), seed_value)
    return m @ m.T + (0.0 if rank else 0.1) * np.eye(n)
