"""Fuzz every public entry point with random and hostile arguments (issue 11, item 3).

Each call is one line of Python text, evaluated in the namespace of ``namespace()``; the
text is its own reproducer.  For every entry point ``ENTRIES`` holds a generator of such
calls: valid values from the domain, with none, one or two arguments replaced by a hostile
value (NaN, +-inf, 0, negative, 1e300, 1e-300, wrong shapes, dtypes and container types).
The calls run in persistent worker processes ('spawn'), one call at a time per worker, with
a timeout the parent measures; a worker that dies or times out is replaced.

Outcomes of a call:

- ``ok``: it returned, and the result holds no NaN or infinity (documented NaN aside);
- ``typed``: ValueError, TypeError, a LinkageError (with its input angle) or QPError;
- findings: ``untyped`` (any other exception, numpy's LinAlgError and numba's errors
  included), ``nan`` (a non-finite value in a result from finite inputs), ``angle`` (a
  LinkageError without its input angle from a function that has input angles),
  ``accepted`` (a NaN or infinite argument, or an angle array that is not 1-D, returned a
  result instead of a ValueError), ``violated`` (a result that breaks what the function
  promises: a QP solution outside its constraints, a corrected cognate whose coupler point
  leaves the source's), ``crash`` (the worker died: a signal, a FORTRAN STOP) and ``hang``
  (the timeout).

The valid values reach the edges on purpose: link lengths scaled as a family over the whole
domain, coupler triangles of every shape, four-bars on or a few ulps off a toggle, QPs with
rows and Hessians scaled by 1e-150 to 1e150, slider-cranks next to their singular
position; the hostile values include subnormal and huge floats and integers beyond any
float (10**400).

Usage::

    python -m linkrepro.harness.fuzz --calls 10000 --seed 0 --timeout 20 --out out/fuzz.json
    python -m linkrepro.harness.fuzz --replay "ali1977.loc(1, 1, nan, 1, 0)"

The same seed gives the same calls.  The exit status is 1 when there are findings.  A
progress line on standard error when it is a terminal (else a line every 1000 calls).
"""
from __future__ import annotations

import argparse
import collections
import dataclasses
import importlib
import json
import math
import multiprocessing
import multiprocessing.connection
import os
import random
import re
import shlex
import shutil
import signal
import sys
import tempfile
import time
import traceback
import warnings
from dataclasses import dataclass, field
from typing import Callable

from .progress import Bar

FINDINGS = ("untyped", "nan", "angle", "accepted", "violated", "crash", "hang")
OUTCOMES = ("ok", "typed") + FINDINGS
STARTUP_SECONDS = 900          # importing linkrepro may rebuild the FORTRAN first
MEMORY_BYTES = 4 << 30         # address space of a worker: a runaway allocation is a MemoryError


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
                           "[2.0, 8.0]", "np.ones(5)", "Section(1.0, 1.0, 1.0)",
                           "Lengths(10.0, 10.0, 30.0, 25.0, 30.0)",
                           "CsspInputs()", "GscInputs()", "object()"))
QUIRKS = Pool("other", ("None", "'PRINTED'", "True", "0", "{}", "PRINTED", "CSSP_PRINTED", "GSC_CORRECTED",
                        "object()"))


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


def quirk_set(rng, family: str, presets: tuple) -> str:
    """A preset of a quirk family, or one with one switch flipped."""
    base = rng.choice(presets)
    if rng.random() < 0.3:
        names = _quirk_names(family)
        return f"{base}.only({rng.choice(names)!r}, {rng.random() < 0.5})"
    return base


def _quirk_names(family: str) -> list:
    module, cls = {"ali": ("linkrepro.port.ali1977.quirks", "Quirks"),
                   "cssp": ("linkrepro.port.rahman1996.quirks", "CsspQuirks"),
                   "gsc": ("linkrepro.port.rahman1991.quirks", "GscQuirks")}[family]
    return getattr(importlib.import_module(module), cls).names()


# --- the entry points --------------------------------------------------------------------

#: input-angle steps (deg) of the legacy grids: 0.0018 gives 200001 angles, one more than allowed
STEPS = ("20.0", "10.0", "1.0", "0.1", "45.0", "360.0", "7.5", "0.0018")


def ked_lengths(rng) -> list[str]:
    """l1..l5 (in) of a K.E.D. four-bar: near the example; the example scaled as a family
    (1e-7 to 1e7: the domain's limits, 1e-6 and 1e6 in, and beyond); a coupler triangle of
    any shape (l2 from 0.02 to 5 times l3); or a four-bar on a toggle (l1 + l5 = l3 + l4 or
    l5 - l1 = |l3 - l4|), exactly or a few ulps or 1e-9 off."""
    example = (10.0, 10.0, 30.0, 25.0, 30.0)
    kind = rng.choice(("near", "near", "scaled", "triangle", "toggle"))
    if kind == "scaled":
        factor = 10.0 ** rng.uniform(-7.0, 6.6)
        return [repr(v * factor) for v in example]
    values = [float(near(rng, v, spread=0.15)) for v in example]
    if kind == "triangle":
        values[1] = values[2] * 10.0 ** rng.uniform(-1.7, 0.7)
    elif kind == "toggle":
        l1, _, l3, l4, _ = values
        target = l3 + l4 - l1 if rng.random() < 0.5 else l1 + abs(l3 - l4)
        nudge = rng.choice((0.0, 0.0, 2.0**-52, -2.0**-52, 4 * 2.0**-52, 1e-9, -1e-9))
        values[4] = target * (1.0 + nudge)
    return [repr(v) for v in values]


def legacy_ked(func: str, mass: str):
    """ali1977.case{1,2,3}_{source,cognate}: keyword parameters, printed values as defaults."""
    def spec(rng):
        names = ("l1", "l2", "l3", "l4", "l5")
        args = [Arg(name, value, FLOAT, True) for name, value in zip(names, ked_lengths(rng))]
        mass_value = num(rng, 0.0, 10.0) if mass == "mass_lbf" else num(rng, 0.0, 0.3)
        args += [Arg("alp", ked_alp(rng), FLOAT, True),
                 Arg("rpm", rng.choice(["300.0", "400.0", num(rng, -3000, 5000)]), FLOAT, True),
                 Arg(mass, mass_value, FLOAT, True),
                 Arg("area", num(rng, 0.01, 1.0), FLOAT, True),
                 Arg("modulus", num(rng, 1e6, 3e7, 0), FLOAT, True),
                 Arg("inertia", num(rng, 1e-4, 0.1, 6), FLOAT, True),
                 Arg("step_deg", rng.choice(STEPS + (num(rng, 0.5, 400),)), FLOAT, True)]
        return Call(f"ali1977.{func}", args)
    return spec


def ked_alp(rng) -> str:
    """The coupler point's angle (rad): any quadrant, or on an axis."""
    return rng.choice([num(rng, -6.3, 6.3), num(rng, -6.3, 6.3), "0.0", "np.pi", "-np.pi / 2", "3 * np.pi / 2"])


def lengths_call(rng) -> Call:
    return Call("Lengths", [Arg(None, value, FLOAT) for value in ked_lengths(rng)])


def section_call(rng) -> Call:
    return Call("Section", [Arg(None, num(rng, 0.01, 1.0), FLOAT), Arg(None, num(rng, 1e6, 3e7, 0), FLOAT),
                            Arg(None, num(rng, 1e-4, 0.1, 6), FLOAT)])


def port_ked(module: str, func: str, case: int, presets: tuple):
    """port.ali1977.case*: deg plus lengths, alp, rpm, mass/density, section, quirks (and n)."""
    def spec(rng):
        args = [Arg(None, angles(rng), ANGLES)]
        if case == 3:
            args.append(Arg("n", str(rng.randint(1, 40)), INT, True))
        args += [Arg("lengths", lengths_call(rng), CONTAINER, True),
                 Arg("alp", rng.choice(["None", ked_alp(rng)]), FLOAT, True),
                 Arg("rpm", rng.choice(["300.0", num(rng, -3000, 5000)]), FLOAT, True),
                 Arg("mass_lbf" if case == 1 else "density",
                     num(rng, 0.0, 10.0) if case == 1 else num(rng, 0.0, 0.3), FLOAT, True),
                 Arg("section", section_call(rng), CONTAINER, True),
                 Arg("quirks", quirk_set(rng, "ali", ("PRINTED", "CORRECTED") + presets), QUIRKS, True)]
        if func == "case3_source":
            args.append(Arg("all_nodes", rng.choice(["False", "True"]), FLAG, True))
        return Call(f"{module}.{func}", args)
    return spec


def cssp_inputs(rng) -> Call:
    """The CSSP's geometry: near the example, or (one call in four) next to its singular
    position, the rod just long enough to reach (a2 = |a1 + a4| (1 + 1e-3 ... 1e-12), the
    issue's family a1 = 2, a2 = 3 (1 + 1e-8), a4 = 1, alpha4 = 90 deg, s1 = 0)."""
    if rng.random() < 0.25:
        a1, a4 = round(rng.uniform(0.5, 4.0), 4), round(rng.uniform(-3.0, 3.0), 4)
        reach = abs(a1 + a4) or 1.0
        a2 = repr(reach * (1.0 + 10.0 ** -rng.uniform(3.0, 12.0)))
        return Call("CsspInputs", [Arg("a1", repr(a1), FLOAT, True), Arg("a2", a2, FLOAT, True),
                                   Arg("a4", repr(a4), FLOAT, True), Arg("alpha4_deg", "90.0", FLOAT, True),
                                   Arg("s1", "0.0", FLOAT, True), Arg("rpm", "3000.0", FLOAT, True)])
    return Call("CsspInputs", [
        Arg("a1", near(rng, 2.0, lo=0.2, hi=10.0), FLOAT, True),
        Arg("a2", near(rng, 8.0, lo=1.0, hi=30.0), FLOAT, True),
        Arg("a4", rng.choice(["1.0", num(rng, -3.0, 3.0)]), FLOAT, True),
        Arg("alpha4_deg", rng.choice(["250.0", num(rng, 0.0, 360.0)]), FLOAT, True),
        Arg("s1", rng.choice(["0.4", num(rng, -2.0, 2.0)]), FLOAT, True),
        Arg("rpm", near(rng, 3000.0, lo=1.0, hi=20000.0), FLOAT, True)])


def gsc_inputs(rng) -> Call:
    def pick_or(values, lo, hi):
        return rng.choice([repr(v) for v in values] + [num(rng, lo, hi)])
    return Call("GscInputs", [
        Arg("a1", near(rng, 12.0, lo=1.0, hi=40.0), FLOAT, True),
        Arg("a2", near(rng, 50.0, lo=5.0, hi=100.0), FLOAT, True),
        Arg("a4", pick_or((0.0, 10.0, 20.0, 30.0), 0.0, 45.0), FLOAT, True),
        Arg("alpha4_deg", pick_or((232.0, 270.0, 310.0), 0.0, 360.0), FLOAT, True),
        Arg("s1", pick_or((0.0, 3.0, 3.5, 6.0, 9.0), -10.0, 10.0), FLOAT, True),
        Arg("rpm", near(rng, 50.0, lo=1.0, hi=500.0), FLOAT, True),
        Arg("torque", near(rng, 100.0, lo=-500.0, hi=500.0), FLOAT, True),
        Arg("r1", near(rng, 1.5, lo=0.1, hi=5.0), FLOAT, True),
        Arg("r2", near(rng, 1.0, lo=0.1, hi=5.0), FLOAT, True),
        Arg("r3", near(rng, 3.0, lo=0.1, hi=8.0), FLOAT, True),
        Arg("alpha", pick_or((0.0, 1.0, 2.0), 0.0, 3.0), FLOAT, True)])


#: the printed first estimate of the CSSP's positions at the example (slider_crank.geometry)
LISTING_START = "np.array([1.955193, 0.0, 4.327992, 0.0, 7.416198])"


def matrix5(rng) -> str:
    """A 5 x 5 matrix: well-conditioned, random, singular, or needing a row exchange."""
    return rng.choice([f"spd(5, {any_seed(rng)})", f"rand((5, 5), {any_seed(rng)})", f"spd(5, {any_seed(rng)}, rank=3)",
                       "np.roll(np.eye(5), 1, axis=0)", f"np.diag(rand((5,), {any_seed(rng)}))"])


def qp_spec(func: str):
    """qprog(h, g, a, b, neq): a random convex QP, small half of the time, else large: up to
    the FORTRAN's limits (60 variables, 200 constraints) or one beyond, more constraints
    than variables."""
    def spec(rng):
        if rng.random() < 0.5:
            n, m = rng.randint(1, 6), rng.randint(0, 4)
        else:
            n = rng.choice([rng.randint(7, 61), 60, 61])
            m = rng.choice([rng.randint(n, 201), 200, 201])
        rank = f", rank={rng.randint(1, n)}" if rng.random() < 0.3 else ""
        objective, rows = scale_of(rng), scale_of(rng)        # H and g by one factor, each row by its own
        h = f"spd({n}, {any_seed(rng)}{rank}){objective}"
        args = [Arg(None, h, MATRIX), Arg(None, f"rand(({n},), {any_seed(rng)}){objective}", VECTOR)]
        if m:
            row_scale = f" * 10.0 ** rand(({m}, 1), {any_seed(rng)}).clip(-3, 3) * 50" if rows else ""
            args += [Arg("a", f"(rand(({m}, {n}), {any_seed(rng)}){row_scale})", MATRIX),
                     Arg("b", f"(rand(({m}, 1), {any_seed(rng)}){row_scale})[:, 0]", VECTOR),
                     Arg("neq", str(rng.randint(0, m)), INT, True)]
        return Call(func, args)
    return spec


def scale_of(rng) -> str:
    """Nothing (half the time), or a factor 10**k, k from -150 to 150, as call text."""
    return "" if rng.random() < 0.5 else f" * 1e{rng.randint(-150, 150)}"


def mprd_spec(rng) -> Call:
    n, m, l = (rng.randint(1, 4) for _ in range(3))
    msa, msb = rng.choice([0, 0, 1, 2]), rng.choice([0, 0, 1, 2])
    m = n if msa else m
    l = m if msb else l
    size = {0: lambda r, c: r * c, 1: lambda r, c: r * (r + 1) // 2, 2: lambda r, c: r}
    return Call("ali1977.mprd", [Arg(None, f"rand(({size[msa](n, m)},), {any_seed(rng)})", VECTOR),
                                Arg(None, f"rand(({size[msb](m, l)},), {any_seed(rng)})", VECTOR),
                                *[Arg(None, str(v), INT) for v in (n, m, l)],
                                Arg("msa", str(msa), INT), Arg("msb", str(msb), INT)])


@dataclass(frozen=True)
class Entry:
    """A public entry point: its name, its call generator, whether it has input angles (a
    LinkageError must then name one), and the function that removes documented NaN."""
    name: str
    spec: Callable
    angles: bool = False
    scrub: str | None = None
    check: str | None = None


def entries() -> list:
    """Every public entry point (the port's QPROG only if it exists yet)."""
    case2 = ("port.ali1977.case2.LISTING", "port.ali1977.case2.COGNATE_LISTING")
    case3 = ("port.ali1977.case3.LISTING", "port.ali1977.case3.COGNATE_LISTING")
    out = [Entry(f"ali1977.{f}", legacy_ked(f, "mass_lbf" if f.startswith("case1") else "density"), angles=True)
           for f in ("case1_source", "case1_cognate", "case2_source", "case2_cognate", "case3_source", "case3_cognate")]
    out += [
        Entry("ali1977.gmtra", lambda rng: Call("ali1977.gmtra", [
            Arg(None, f"rand(({rng.randint(1, 5)}, {rng.randint(1, 5)}), {any_seed(rng)})", MATRIX)])),
        Entry("ali1977.mprd", mprd_spec),
        Entry("ali1977.loc", lambda rng: Call("ali1977.loc", [Arg(None, str(rng.randint(1, 6)), INT) for _ in range(4)]
                                             + [Arg(None, str(rng.randint(0, 2)), INT)])),
        Entry("ali1977.angle_grid", lambda rng: Call("ali1977.angle_grid", [Arg(None, num(rng, 0.5, 400.0), FLOAT)])),
        Entry("rahman1996.cssp", lambda rng: Call("rahman1996.cssp", cssp_inputs(rng).args + [
            Arg("solution", rng.choice(["None", f"0.001 + 0.01 * np.abs(rand((9,), {any_seed(rng)}))"]),
                VECTOR, True)]),
              angles=True),
        Entry("rahman1996.inverse", lambda rng: Call("rahman1996.inverse", [Arg(None, matrix5(rng), MATRIX)])),
        Entry("rahman1996.qprog", qp_spec("rahman1996.qprog"), check="qp"),
        Entry("port.ali1977.case1.source_case1", port_ked("port.ali1977.case1", "source_case1", 1, ()), angles=True),
        Entry("port.ali1977.case1.cognate_case1", port_ked("port.ali1977.case1", "cognate_case1", 1, ()), angles=True,
              check="cognate"),
        Entry("port.ali1977.case2.case2_source", port_ked("port.ali1977.case2", "case2_source", 2, case2), angles=True),
        Entry("port.ali1977.case2.case2_cognate", port_ked("port.ali1977.case2", "case2_cognate", 2, case2), angles=True,
              check="cognate"),
        Entry("port.ali1977.case3.case3_source", port_ked("port.ali1977.case3", "case3_source", 3, case3), angles=True),
        Entry("port.ali1977.case3.case3_cognate", port_ked("port.ali1977.case3", "case3_cognate", 3, case3), angles=True,
              check="cognate"),
        Entry("port.rahman1996.balance.balance", lambda rng: Call("port.rahman1996.balance.balance", [
            Arg("inputs", cssp_inputs(rng), CONTAINER, True),
            Arg("quirks", quirk_set(rng, "cssp", ("CSSP_PRINTED", "CSSP_CORRECTED")), QUIRKS, True)]), angles=True),
        Entry("port.rahman1996.balance.solve_qp", lambda rng: Call("port.rahman1996.balance.solve_qp", [
            Arg(None, f"1e-3 * spd(9, {any_seed(rng)}{rng.choice(['', ', rank=6'])})", MATRIX),
            Arg("rows", "QP_ROWS", MATRIX, True),
            Arg("bounds", rng.choice(["QP_BOUNDS", f"0.01 * np.abs(rand((11,), {any_seed(rng)}))"]), VECTOR),
            Arg("equalities", rng.choice(["3", str(rng.randint(0, 11))]), INT, True)])),
        Entry("port.rahman1996.listing.printed_inverse", lambda rng: Call("port.rahman1996.listing.printed_inverse",
                                                                    [Arg(None, matrix5(rng), MATRIX)])),
        Entry("port.rahman1991.analysis.analyse", lambda rng: Call("port.rahman1991.analysis.analyse", [
            Arg("inputs", gsc_inputs(rng), CONTAINER, True),
            Arg("crank_deg", angles(rng, most=12), ANGLES, True),
            Arg("quirks", quirk_set(rng, "gsc", ("GSC_PRINTED", "GSC_CORRECTED")), QUIRKS, True),
            Arg("strict", rng.choice(["False", "True"]), FLAG, True)]), angles=True, scrub="gsc"),
        Entry("port.slider_crank.kinematics.kinematics", lambda rng: Call("port.slider_crank.kinematics.kinematics", [
            Arg(None, cssp_inputs(rng), CONTAINER), Arg(None, f"np.radians({angles(rng)})", ANGLES)]), angles=True),
        Entry("port.rahman1996.listing.listing_pass", lambda rng: Call("port.rahman1996.listing.listing_pass", [
            Arg(None, angles(rng, lo=0.0, hi=360.0), ANGLES), Arg(None, LISTING_START, VECTOR),
            Arg(None, Call("Constants.of", [Arg(None, cssp_inputs(rng), CONTAINER), Arg(None, "True", FLAG)]),
                CONTAINER)]), angles=True),
        Entry("port.rahman1996.mechanics.closed_loop_loads", lambda rng: Call(
            "port.rahman1996.mechanics.closed_loop_loads", [
                Arg(None, Call("Constants.of", [Arg(None, cssp_inputs(rng), CONTAINER), Arg(None, "False", FLAG)]),
                    CONTAINER), Arg(None, angles(rng), ANGLES)]), angles=True),
        Entry("port.rahman1991.position.positions", lambda rng: Call("port.rahman1991.position.positions", [
            Arg(None, gsc_inputs(rng), CONTAINER), Arg(None, f"np.radians({angles(rng, most=12)})", ANGLES)]),
              angles=True, scrub="positions"),
        Entry("port.rahman1996.qprog.hessian_shift", lambda rng: Call("port.rahman1996.qprog.hessian_shift", [
            Arg(None, f"spd({(n := rng.randint(1, 9))}, {any_seed(rng)}){scale_of(rng)}", MATRIX),
            Arg(None, f"rand(({n},), {any_seed(rng)})", VECTOR, True)])),
        Entry("port.rahman1996.data.CsspInputs", lambda rng: cssp_inputs(rng)),
        Entry("port.rahman1991.data.GscInputs", lambda rng: gsc_inputs(rng)),
        Entry("port.ali1977.fourbar.Lengths", lengths_call),
        Entry("port.ali1977.case1.Section", section_call),
    ]
    if _port_qprog() is not None:
        out.append(Entry("port.rahman1996.qprog.qprog", qp_spec("port.rahman1996.qprog.qprog"), check="qp"))
    return out


def _port_qprog():
    """linkrepro.port.rahman1996.qprog if it defines ``qprog`` (another engineer is writing it)."""
    try:
        module = importlib.import_module("linkrepro.port.rahman1996.qprog")
    except ImportError:
        return None
    return module if callable(getattr(module, "qprog", None)) else None


# --- generating the calls ----------------------------------------------------------------

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


def generate(calls: int, seed_value: int, only: str | None = None) -> list:
    """``calls`` jobs spread evenly over the entry points, interleaved; one random stream per
    entry point (seeded by the seed and its name), so an entry's calls do not depend on the
    others."""
    chosen = [e for e in entries() if only is None or only in e.name]
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


# --- inside a worker: evaluate one call and classify it ---------------------------------

def rand(shape, seed_value):
    """A reproducible standard-normal array (for call texts)."""
    import numpy as np
    return np.random.default_rng(seed_value).standard_normal(shape)


def spd(n, seed_value, rank=None):
    """A reproducible symmetric positive (semi-)definite n x n matrix of the given rank."""
    import numpy as np
    m = rand((n, rank or n), seed_value)
    return m @ m.T + (0.0 if rank else 0.1) * np.eye(n)


def namespace() -> dict:
    """The names a call text may use."""
    import numpy as np
    from linkrepro import AssemblyError, ConvergenceError, LinkageError, QPError, SingularPositionError
    from linkrepro.legacy import ali1977, rahman1996
    import linkrepro.port.ali1977.case1
    import linkrepro.port.ali1977.case2
    import linkrepro.port.ali1977.case3
    import linkrepro.port.rahman1991.analysis
    import linkrepro.port.rahman1996.balance
    import linkrepro.port.rahman1996.listing
    import linkrepro.port.rahman1996.qprog
    import linkrepro.port.rahman1996.mechanics
    import linkrepro.port.rahman1991.position
    import linkrepro.port.slider_crank.kinematics
    from linkrepro import port
    from linkrepro.port.rahman1996.data import Constants
    from linkrepro.port.ali1977.case1 import Section
    from linkrepro.port.rahman1996.data import QP_BOUNDS, QP_ROWS, CsspInputs
    from linkrepro.port.ali1977.fourbar import Lengths
    from linkrepro.port.rahman1991.data import GscInputs
    from linkrepro.port.rahman1991.quirks import GSC_CORRECTED, GSC_PRINTED
    from linkrepro.port.rahman1996.quirks import CSSP_CORRECTED, CSSP_PRINTED
    from linkrepro.port.ali1977.quirks import CORRECTED, PRINTED
    ns = dict(locals())
    ns.update(nan=math.nan, inf=math.inf, rand=rand, spd=spd)
    return ns


#: one call of each engine at its example, in every quirk mode: compiles the numba kernels
#: (or loads them from the cache) before any call is timed
WARM_UP = [f"{engine}(np.arange(0.0, 360.0, 90.0), quirks={mode})" for mode in ("PRINTED", "CORRECTED")
           for engine in ("port.ali1977.case1.source_case1", "port.ali1977.case1.cognate_case1",
                          "port.ali1977.case2.case2_source", "port.ali1977.case2.case2_cognate",
                          "port.ali1977.case3.case3_source", "port.ali1977.case3.case3_cognate")]
WARM_UP += [f"port.rahman1996.balance.balance(CsspInputs(), {q})" for q in ("CSSP_PRINTED", "CSSP_CORRECTED")]
WARM_UP += [f"port.rahman1991.analysis.analyse(GscInputs(), np.array([0.0, 90.0]), {q})"
            for q in ("GSC_PRINTED", "GSC_CORRECTED")]
WARM_UP += ["port.rahman1996.qprog.qprog(np.eye(2), np.ones(2))"]


def warm_up(ns: dict) -> None:
    """Run WARM_UP in a new worker, so that a call's time is its own."""
    for text in WARM_UP:
        eval(text, dict(ns))                   # noqa: S307 - fixed text


def execute(text: str, ns: dict, angles: bool = False, scrub: str | None = None, refused=(),
            check: str | None = None) -> dict:
    """Evaluate one call text and classify what happened (everything but crash and hang)."""
    start = time.perf_counter()
    try:
        result = eval(text, dict(ns))          # noqa: S307 - the fuzz's own generated text
    except (Exception, SystemExit) as exc:     # noqa: BLE001 - classifying is the point
        out = describe_error(exc, angles)
    else:
        where = nonfinite(SCRUBS[scrub](result) if scrub else result)
        broken = None if (where or refused or check is None) else CHECKS[check](arguments_of(text, ns), result)
        outcome = "accepted" if refused else ("nan" if where else ("violated" if broken else "ok"))
        out = {"outcome": outcome, "detail": where or broken or ""}
    out["seconds"] = round(time.perf_counter() - start, 4)
    return out


def describe_error(exc: BaseException, angles: bool) -> dict:
    """typed / untyped / angle, with the traceback's last line and innermost frames."""
    from linkrepro.errors import LinkageError
    frames = traceback.extract_tb(exc.__traceback__)
    ours = [f for f in frames if "site-packages" not in f.filename and "/lib/python" not in f.filename
            and f.filename != "<string>"]
    out = {"exception": type(exc).__name__, "message": (str(exc).splitlines() or [""])[0][:300],
           "where": _frame(frames[-1]) if frames else "", "library_where": _frame(ours[-1]) if ours else ""}
    if isinstance(exc, LinkageError):
        named = exc.angle_deg is not None and math.isfinite(float(exc.angle_deg))
        out["outcome"] = "typed" if named or not angles else "angle"
    else:
        out["outcome"] = "typed" if is_typed(exc) else "untyped"
    return out


def is_typed(exc: BaseException) -> bool:
    """ValueError, TypeError or QPError, but not numpy's LinAlgError nor numba's errors
    (those should have been turned into a typed error before reaching the kernel)."""
    import numpy as np
    from linkrepro.errors import QPError
    if isinstance(exc, np.linalg.LinAlgError) or type(exc).__module__.startswith("numba"):
        return False
    return isinstance(exc, (ValueError, TypeError, QPError))


def _frame(f) -> str:
    path = f.filename
    for marker in ("/linkrepro/", "/work/main/"):
        if marker in path:
            path = path.split(marker, 1)[1]
    return f"{path}:{f.lineno} in {f.name}"


def nonfinite(value, path: str = "result", depth: int = 0) -> str | None:
    """Where the first NaN or infinity in a returned value is (dicts, sequences, arrays,
    DataFrames, dataclasses), or None."""
    import numpy as np
    pd = sys.modules.get("pandas")
    if depth > 6:
        return None
    if pd is not None and isinstance(value, (pd.DataFrame, pd.Series)):
        frame = value.to_frame() if isinstance(value, pd.Series) else value
        items = ((f"[{c!r}]", frame[c].to_numpy()) for c in frame.columns)
    elif isinstance(value, dict):
        items = ((f"[{k!r}]", v) for k, v in value.items())
    elif isinstance(value, (list, tuple)):
        items = ((f"[{i}]", v) for i, v in enumerate(value))
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        items = ((f".{f.name}", getattr(value, f.name)) for f in dataclasses.fields(value))
    elif isinstance(value, np.ndarray) and value.dtype == object:
        items = ((f"[{i}]", v) for i, v in enumerate(value.ravel()[:1000]))
    elif isinstance(value, (float, complex, np.ndarray, np.floating, np.complexfloating)):
        arr = np.asarray(value)
        if arr.dtype.kind in "fc" and not np.all(np.isfinite(arr)):
            at = tuple(int(i) for i in np.argwhere(~np.isfinite(arr))[0])
            return f"{path}{list(at) if at else ''} = {arr[at]}"
        return None
    else:
        return None
    for key, item in items:
        where = nonfinite(item, path + key, depth + 1)
        if where:
            return where
    return None


def _gsc_documented(frame):
    """gsc.analyse documents NaN after ``converged`` in the rows that did not converge, and
    in the joint forces of rows whose status is 'dead centre' (no balancing torque)."""
    pd = sys.modules.get("pandas")
    if pd is None or not isinstance(frame, pd.DataFrame) or "converged" not in frame:
        return frame
    from linkrepro.port.rahman1991 import forces as gsc_forces
    from linkrepro.port.rahman1991.analysis import DEAD_CENTRE
    kept = frame[frame["converged"].astype(bool)]
    if "status" not in kept:
        return kept
    dead = kept["status"] == DEAD_CENTRE
    return [kept[~dead], kept[dead].drop(columns=gsc_forces.COMPONENTS, errors="ignore")]


def _positions_documented(run):
    """rahman1991.position.positions documents NaN in q and closure where a position did not
    converge or cannot assemble (its status says which)."""
    import numpy as np
    from linkrepro.port.rahman1991.position import DFP_THEN_NEWTON, NEWTON, PositionRun
    if not isinstance(run, PositionRun):
        return run
    solved = np.isin(run.status, [NEWTON, DFP_THEN_NEWTON])
    return [run.q[solved], run.closure[solved]]


SCRUBS = {"gsc": _gsc_documented, "positions": _positions_documented}


# --- what a returned result must satisfy ---------------------------------------------------

def arguments_of(text: str, ns: dict) -> tuple[list, dict]:
    """The positional and keyword arguments a call text passes, each evaluated as the call
    evaluates it."""
    import ast
    call = ast.parse(text, mode="eval").body

    def value(node):
        return eval(compile(ast.Expression(node), "<argument>", "eval"), dict(ns))   # noqa: S307 - our own text
    return [value(a) for a in call.args], {k.arg: value(k.value) for k in call.keywords}


def _qp_feasible(arguments, result) -> str | None:
    """qprog's ``sol`` satisfies a[:neq] x = b[:neq] and a[neq:] x >= b[neq:] as QPROG promises
    (register D050): each row missed by at most eps (1e3 + 8 kappa) of its own size
    |a_i| |x| + |b_i|, kappa = tr(H~) tr(H~^-1) with H~ = H + diag I (H as QPROG reads it: its
    lower triangle); twice that is a finding."""
    import numpy as np
    args, kwargs = arguments
    names = ("h", "g", "a", "b", "neq")
    given = {**dict(zip(names, args)), **kwargs}
    if given.get("a") is None:
        return None
    a, b = np.atleast_2d(np.asarray(given["a"], dtype=float)), np.atleast_1d(np.asarray(given["b"], dtype=float))
    neq, x = int(given.get("neq", 0)), np.asarray(result["sol"], dtype=float)
    lower = np.tril(np.atleast_2d(np.asarray(given["h"], dtype=float)))
    shifted = lower + np.tril(lower, -1).T + result["diag"] * np.eye(len(x))
    with np.errstate(all="ignore"):
        try:
            kappa = float(np.trace(shifted) * np.trace(np.linalg.inv(shifted)))
        except np.linalg.LinAlgError:
            kappa = np.inf
    promise = np.finfo(float).eps * (1e3 + 8.0 * abs(kappa))
    slack = a @ x - b
    size = np.abs(a) @ np.abs(x) + np.abs(b)
    worst = np.where(np.arange(len(b)) < neq, np.abs(slack), -slack) / np.where(size > 0, size, 1.0)
    if worst.max(initial=0.0) > 2.0 * promise:
        k = int(np.argmax(worst))
        return (f"constraint {k} ({'equality' if k < neq else 'inequality'}) violated by {worst[k]:.3g} of its size "
                f"(QPROG promises {promise:.3g})")
    return None


def _cognate_coincides(arguments, result) -> str | None:
    """With the cognate's turn corrected (cognate_beta_quadrant off) and double storage, the
    cognate's coupler point is the source's at every angle (Roberts-Chebyshev)."""
    import numpy as np
    quirks = arguments[1].get("quirks")
    if quirks is None or quirks.cognate_beta_quadrant or quirks.real4_storage:
        return None
    gap = np.hypot(result["cxp"] - result["xp"], result["cyp"] - result["yp"])
    scale = np.abs(np.concatenate([result["xp"], result["yp"]])).max(initial=1e-300)
    if gap.max() > 1e-9 * scale:
        return f"the cognate's coupler point is {gap.max():.3g} in off the source's (scale {scale:.3g} in)"
    return None


CHECKS = {"qp": _qp_feasible, "cognate": _cognate_coincides}


def _serve(conn, log_path: str) -> None:
    """Worker main: output to a log (FORTRAN writes to fd 1), limited memory, one call at a
    time until told to stop (None)."""
    fd = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_APPEND)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    try:
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_BYTES, MEMORY_BYTES))
    except (ImportError, ValueError, OSError):
        pass
    warnings.simplefilter("ignore")
    ns = namespace()
    warm_up(ns)
    conn.send("ready")
    while (message := conn.recv()) is not None:
        os.ftruncate(1, 0)                   # the log holds this call's output only
        text, angles, scrub, refused, check = message
        conn.send(execute(text, ns, angles, scrub, refused, check))


# --- the parent: workers, timeouts, replacements -----------------------------------------

class Worker:
    """One persistent child process."""

    def __init__(self, ctx, log_path: str):
        self.log_path = log_path
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_serve, args=(child, log_path), daemon=True)
        self.proc.start()
        child.close()
        self.job, self.deadline = None, math.inf

    def wait_ready(self) -> "Worker":
        if not self.conn.poll(STARTUP_SECONDS):
            raise RuntimeError(f"a fuzz worker did not start in {STARTUP_SECONDS} s:\n{self.log_tail()}")
        try:
            self.conn.recv()
        except EOFError:
            raise RuntimeError(f"a fuzz worker died while starting:\n{self.log_tail()}") from None
        return self

    def submit(self, job: Job, timeout: float) -> None:
        self.conn.send((job.text, job.angles, job.scrub, job.refused, job.check))
        self.job, self.deadline = job, time.monotonic() + (timeout if job.timeout is None else job.timeout)

    def log_tail(self, chars: int = 600) -> str:
        try:
            with open(self.log_path, errors="replace") as f:
                return f.read()[-chars:].strip()
        except OSError:
            return ""

    def death(self) -> str:
        self.proc.join(5)
        code = self.proc.exitcode
        if code is None:
            return "the worker closed its pipe"
        how = f"killed by {signal.Signals(-code).name}" if code < 0 else f"exit code {code}"
        return how + (" (a FORTRAN STOP exits 0)" if code == 0 else "")

    def stop(self, kill: bool = False) -> None:
        if not kill:
            try:
                self.conn.send(None)
            except OSError:
                pass
            self.proc.join(5)
        if self.proc.is_alive():
            self.proc.kill()
            self.proc.join()
        self.conn.close()


def run(jobs: list, timeout: float = 20.0, workers: int = 2, progress=None) -> list:
    """Run the jobs on ``workers`` persistent processes; one result dict per job, in order.
    ``progress(done, total)``: called after each call."""
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS"):
        os.environ.setdefault(var, "1")
    ctx = multiprocessing.get_context("spawn")
    logs = tempfile.mkdtemp(prefix="linkrepro-fuzz-")
    pool = [Worker(ctx, os.path.join(logs, f"worker{k}.log")) for k in range(max(1, workers))]
    pool = [w.wait_ready() for w in pool]
    todo, results, done = collections.deque(jobs), {}, 0
    try:
        while todo or any(w.job for w in pool):
            for w in pool:
                if w.job is None and todo:
                    w.submit(todo.popleft(), timeout)
            busy = [w for w in pool if w.job]
            wait = max(0.0, min(w.deadline for w in busy) - time.monotonic())
            ready = multiprocessing.connection.wait([w.conn for w in busy], timeout=wait)
            for k, w in enumerate(pool):
                if w.job is None or (w.conn not in ready and time.monotonic() < w.deadline):
                    continue
                result, replace = _collect(w, w.conn in ready, timeout if w.job.timeout is None else w.job.timeout)
                results[w.job.index] = result
                done += 1
                w.job = None
                if replace:
                    w.stop(kill=True)
                    pool[k] = Worker(ctx, os.path.join(logs, f"worker{k}-{done}.log")).wait_ready()
                if progress:
                    progress(done, len(jobs))
    finally:
        for w in pool:
            w.stop()
        shutil.rmtree(logs, ignore_errors=True)
    return [results[job.index] for job in jobs]


def _collect(w: Worker, ready: bool, timeout: float) -> tuple[dict, bool]:
    """The result of a worker's call, or a crash or hang record; and whether to replace it."""
    if ready:
        try:
            return w.conn.recv(), False
        except (EOFError, OSError):
            return {"outcome": "crash", "detail": w.death(), "log": w.log_tail()}, True
    return {"outcome": "hang", "detail": f"no answer in {timeout:g} s", "log": w.log_tail()}, True


# --- the report --------------------------------------------------------------------------

@dataclass
class Report:
    jobs: list
    results: list
    seconds: float
    seed: int
    timeout: float
    workers: int
    counts: dict = field(default_factory=dict)
    findings: list = field(default_factory=list)

    def __post_init__(self):
        self.counts = collections.defaultdict(collections.Counter)
        for job, res in zip(self.jobs, self.results):
            self.counts[job.entry][res["outcome"]] += 1
            if res["outcome"] in FINDINGS:
                self.findings.append({"index": job.index, "entry": job.entry, "call": job.text,
                                      "hostile": list(job.hostile), "group": group_key(job, res), **res})


def group_key(job: Job, res: dict) -> str:
    """The cause of a finding, with numbers and indices left out."""
    outcome = res["outcome"]
    if outcome == "accepted":
        cause = "refusable argument returned a result: " + ", ".join(sorted(set(job.refused)))
    elif outcome == "nan":
        cause = "non-finite value in " + re.sub(r"\[[\d, ]*\]| = .*", "", res["detail"])
    elif outcome == "violated":
        cause = _normalise(res["detail"])
    elif outcome in ("crash", "hang"):
        cause = res["detail"]
    else:
        cause = f"{res['exception']}: {_normalise(res['message'])} [{res.get('library_where', '')}]"
    return f"{outcome} | {job.entry} | {cause}"


def _normalise(message: str) -> str:
    message = re.sub(r"'[^']*'|\"[^\"]*\"", "'…'", message)
    return re.sub(r"(?<![\w.])[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(?!\w)", "#", message)[:160]


def replay_command(text: str) -> str:
    return f"python -m linkrepro.harness.fuzz --replay {shlex.quote(text)}"


def format_report(report: Report, every: bool = False) -> str:
    """Counts per entry point and outcome, then the findings grouped by cause."""
    name_width = max(map(len, report.counts)) if report.counts else 10
    lines = [f"linkrepro fuzz: {len(report.jobs)} calls, seed {report.seed}, timeout {report.timeout:g} s, "
             f"{report.workers} workers, {report.seconds:.1f} s", "",
             f"{'entry point':{name_width}} " + " ".join(f"{o:>8}" for o in OUTCOMES)]
    total = collections.Counter()
    for name, counter in report.counts.items():
        total.update(counter)
        lines.append(f"{name:{name_width}} " + " ".join(f"{counter[o]:8d}" for o in OUTCOMES))
    lines.append(f"{'total':{name_width}} " + " ".join(f"{total[o]:8d}" for o in OUTCOMES))
    timed = [(r.get("seconds", 0.0), j) for j, r in zip(report.jobs, report.results)]
    if timed:
        seconds, job = max(timed, key=lambda t: t[0])
        lines.append(f"slowest call that answered: {seconds:.2f} s, {job.text}")
    lines += ["", format_findings(report, every)]
    return "\n".join(lines)


def format_findings(report: Report, every: bool = False) -> str:
    """Each group of findings: its cause, count, last traceback line and one reproducer (the
    shortest), or every reproducer with ``every``."""
    groups = collections.defaultdict(list)
    for f in report.findings:
        groups[f["group"]].append(f)
    lines = [f"findings: {len(report.findings)} calls in {len(groups)} groups"]
    for key, items in sorted(groups.items(), key=lambda kv: kv[0]):
        lines.append(f"\n[{len(items)}] {key}")
        shown = items if every else [min(items, key=lambda f: len(f["call"]))]
        for f in shown:
            if "exception" in f:
                lines.append(f"    {f['exception']}: {f['message']}")
            if f.get("detail"):
                lines.append(f"    {f['detail']}")
            if f["hostile"]:
                lines.append(f"    hostile: {', '.join(f['hostile'])}")
            if f.get("where") and f.get("where") != f.get("library_where"):
                lines.append(f"    innermost frame: {f['where']}")
            if f.get("log"):
                lines.append("    worker output: " + f["log"].replace("\n", " | ")[-300:])
            lines.append(f"    {replay_command(f['call'])}")
    return "\n".join(lines)


def write_report(report: Report, path: str) -> None:
    """JSON (everything) or CSV (one row per finding), by the file's extension."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    if path.endswith(".csv"):
        import csv
        columns = ["index", "entry", "outcome", "group", "exception", "message", "library_where", "where",
                   "detail", "call"]
        with open(path, "w", newline="") as f:
            writer = csv.DictWriter(f, columns, extrasaction="ignore")
            writer.writeheader()
            writer.writerows(report.findings)
        return
    with open(path, "w") as f:
        json.dump({"seed": report.seed, "calls": len(report.jobs), "timeout": report.timeout,
                   "workers": report.workers, "seconds": round(report.seconds, 1),
                   "counts": {k: dict(v) for k, v in report.counts.items()},
                   "findings": report.findings}, f, indent=1)


def fuzz(calls: int = 10_000, seed: int = 0, timeout: float = 20.0, workers: int | None = None,
         only: str | None = None, progress=None) -> Report:
    """Generate and run ``calls`` calls; the report."""
    workers = workers or min(2, len(os.sched_getaffinity(0)))
    jobs = generate(calls, seed, only)
    start = time.monotonic()
    results = run(jobs, timeout, workers, progress)
    return Report(jobs, results, time.monotonic() - start, seed, timeout, workers)


def replay(text: str) -> int:
    """Run one call text here, in this process, and print its result or traceback."""
    warnings.simplefilter("ignore")
    ns = namespace()
    result = eval(text, ns)                   # noqa: S307 - lets the traceback through
    print(repr(result)[:2000])
    where = nonfinite(result)
    print(f"non-finite: {where}" if where else "finite")
    return 0


def _shown(bar: Bar) -> Callable[[int, int], None]:
    """After each call: the progress line on a terminal (stderr); else a line every 1000 calls."""
    def step(done: int, total: int) -> None:
        bar.done("fuzz")
        if not bar.active and done % 1000 == 0:
            print(f"  {done}/{total} calls", file=sys.stderr, flush=True)
    return step


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m linkrepro.harness.fuzz", description=__doc__.split("\n")[0])
    parser.add_argument("--calls", type=int, default=10_000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds per call")
    parser.add_argument("--workers", type=int, default=None, help="worker processes (default: 2 or the cores)")
    parser.add_argument("--only", help="entry points whose name contains this")
    parser.add_argument("--out", help="write the report: .json (everything) or .csv (the findings)")
    parser.add_argument("--all", action="store_true", help="print every finding, not one per group")
    parser.add_argument("--replay", metavar="CALL", help="run one call text in this process")
    args = parser.parse_args(argv)
    if args.replay:
        return replay(args.replay)
    with Bar(args.calls) as bar:
        bar.note("fuzz", "starting the workers (importing linkrepro)")
        report = fuzz(args.calls, args.seed, args.timeout, args.workers, args.only, progress=_shown(bar))
    print(format_report(report, args.all))
    if args.out:
        write_report(report, args.out)
    return 1 if report.findings else 0


if __name__ == "__main__":
    sys.exit(main())
