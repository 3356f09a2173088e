"""Ali (1977)'s part of ``linkrepro differential`` (``harness/differential.py``): the six
K.E.D. programs, legacy against the port with each listing's bugs, on samples of the input
space; the samplers and the engine pairs that tests/ali1977/test_differential.py uses too.

How the two APIs map (what "the same input" means):

- the angles: legacy steps its input angle in REAL*4 (``P2=P2+DSTEP``, DSTEP a REAL*4); the port
  takes the angles, ``listing_angles(step)`` builds the same ones (and ``deg``, compared too,
  checks them against legacy's);
- the port runs each listing's own bugs: ``PRINTED`` for Case I, ``case2.LISTING`` /
  ``COGNATE_LISTING`` and ``case3.LISTING`` / ``COGNATE_LISTING``, with ``alp`` and ``rpm``
  given explicitly (the listings' 101 deg and 400 rpm are only defaults);
- section values and the density are the listings' REAL*4 literals: they are drawn as REAL*4
  numbers (what the listing can hold).

A geometry here is ``{"lengths": (l1, ..., l5), "alp", "rpm", "weight", "area", "modulus",
"inertia", "step"}`` (the tests' form); the command's rows spell the lengths out (``flat``).
"""
from __future__ import annotations

import inspect

import numpy as np

from ....legacy import ali1977
from ....port.ali1977 import case2, case3 as ked_case3
from ....port.ali1977.case1 import cognate_case1, source_case1
from ....port.ali1977.fourbar import Lengths
from ....port.ali1977.quirks import PRINTED
from ....port.ali1977.structure import Section
from ...differential import Domain, Parameter, Program, Thesis

PI_22_7 = ali1977.PI_PRINTED
PROGRAMS = ("case1_source", "case1_cognate", "case2_source", "case2_cognate", "case3_source", "case3_cognate")
LENGTHS = ("l1", "l2", "l3", "l4", "l5")


def real4(x: float) -> float:
    return float(np.float32(x))


def listing_angles(step: float) -> np.ndarray:
    """The input angles the listings step through: P2=-DSTEP, then P2=P2+DSTEP in REAL*4."""
    s = np.float32(step)
    p = -s
    out = []
    for _ in range(ali1977.angle_grid(step)):
        p = np.float32(p + s)
        out.append(float(p))
    return np.array(out)


def port_call(name: str, g: dict, deg: np.ndarray) -> dict:
    """The port of program ``name`` with its listing's bugs at the angles ``deg``."""
    lengths, section = Lengths(*g["lengths"]), Section(g["area"], g["modulus"], g["inertia"])
    args = dict(lengths=lengths, alp=g["alp"], rpm=g["rpm"], section=section)
    if name == "case1_source":
        return source_case1(deg, mass_lbf=g["weight"], quirks=PRINTED, **args)
    if name == "case1_cognate":
        return cognate_case1(deg, mass_lbf=g["weight"], quirks=PRINTED, **args)
    if name == "case2_source":
        return case2.case2_source(deg, density=g["weight"], quirks=case2.LISTING, **args)
    if name == "case2_cognate":
        return case2.case2_cognate(deg, density=g["weight"], quirks=case2.COGNATE_LISTING, **args)
    if name == "case3_source":
        return ked_case3.case3_source(deg, 5, density=g["weight"], quirks=ked_case3.LISTING, all_nodes=True, **args)
    return ked_case3.case3_cognate(deg, 5, density=g["weight"], quirks=ked_case3.COGNATE_LISTING, **args)


def legacy_call(name: str, g: dict) -> dict:
    """The legacy build of program ``name``."""
    weight = "mass_lbf" if name.startswith("case1") else "density"
    return getattr(ali1977, name)(*g["lengths"], alp=g["alp"], rpm=g["rpm"], area=g["area"], modulus=g["modulus"],
                                 inertia=g["inertia"], step_deg=g["step"], **{weight: g["weight"]})


# --- the samplers ------------------------------------------------------------------------

def draw_sample(rng: np.random.Generator, name: str) -> dict:
    """One input of the report's fixed sample (numpy's generator, not hypothesis's): a quarter
    free lengths, a quarter Grashof crank-rockers, half on an assembly limit moved by up to
    1e-1 relative (log-uniform from 1e-14); alp anywhere in -2 pi .. 4 pi; 1 to 3000 rpm;
    log-uniform weights and section values; steps from a list that does and does not divide 360."""
    def log_u(lo, hi, size=None):
        return np.exp(rng.uniform(np.log(lo), np.log(hi), size))

    def rocker():
        s = rng.uniform(0.5, 20.0)
        p, q = s * log_u(1.01, 10.0, 2)
        l3, l4, l5 = rng.permutation([p, q, rng.uniform(max(p, q), p + q - s)])
        return s, l3, l4, l5
    kind = rng.integers(4)
    if kind == 0:
        l1, l3, l4, l5 = log_u(0.5, 100.0, 4)
    elif kind == 1:
        l1, l3, l4, l5 = rocker()
    else:
        l1, l3, l4, _ = rocker()
        target = (l3 + l4 - l1) if kind == 2 else l1 + abs(l3 - l4)
        l5 = target * (1 + rng.choice([-1, 1]) * 10.0 ** rng.uniform(-14, -1))
    l2 = 8.0 + log_u(0.01, 40.0) if name == "case3_source" else log_u(0.2, 60.0)
    return {"lengths": tuple(float(v) for v in (l1, l2, l3, l4, l5)), "alp": float(rng.uniform(-2 * np.pi, 4 * np.pi)),
            "rpm": float(rng.uniform(1, 3000) if rng.random() < 0.5 else rng.integers(1, 3000)),
            "weight": real4(log_u(1e-3, 10.0)), "area": real4(log_u(0.01, 5.0)), "modulus": real4(log_u(1e6, 3e7)),
            "inertia": real4(log_u(1e-5, 1.0)),
            "step": float(rng.choice([1.0, 2.5, 5.0, 7.5, 10.0, 15.0, 20.0, 30.0, 0.7, 3.3]))}


def _rejection_rocker(rng: np.random.Generator):
    while True:
        s = rng.uniform(0.5, 20.0)
        l3, l4, l5 = s * np.exp(rng.uniform(0.02, 2.0, 3))
        if s + max(l3, l4, l5) < l3 + l4 + l5 - max(l3, l4, l5):
            return s, l3, l4, l5


def draw_edges(rng: np.random.Generator, name: str) -> dict:
    """One input of the report's edge sample: a fifth each folded at 0 deg in small integers
    (l5 = l1 + |l3 - l4|, l1 = l5 + |l3 - l4|), on an assembly limit moved by -8..8 ulps, on
    Grashof's change point, and degenerate cognates (l2 = l3 half the time); alp on the axes,
    PI_22_7, within 1e-8 of 0 or pi, or anywhere; speeds, section values, weights and steps
    from short lists of ordinary and extreme values."""
    kind = rng.integers(5)
    if kind == 0:
        l1, l3, l4 = (float(x) for x in rng.integers(1, 40, 3))
        l5 = l1 + abs(l3 - l4)
        if l5 == l1:
            l5 = l1 + 1.0
    elif kind == 1:
        l3, l4 = (float(x) for x in rng.integers(1, 40, 2))
        l5 = float(rng.integers(1, 40))
        l1 = l5 + abs(l3 - l4)
    elif kind == 2:
        l1, l3, l4, _ = _rejection_rocker(rng)
        target = (l3 + l4 - l1) if rng.random() < 0.5 else l1 + abs(l3 - l4)
        l5 = target * (1 + rng.integers(-8, 9) * 2.0 ** -52)
    elif kind == 3:
        l1, l3, l4, l5 = _rejection_rocker(rng)
        vals = [l3, l4, l5]
        i = int(np.argmax(vals))
        vals[i] = sum(vals) - vals[i] - l1
        l3, l4, l5 = vals
    else:
        l1, l3, l4, l5 = _rejection_rocker(rng)
    l2 = float(rng.integers(1, 40)) if rng.random() < 0.5 else float(np.exp(rng.uniform(np.log(0.2), np.log(60))))
    if kind == 4 and rng.random() < 0.5:
        l2 = l3
    if name == "case3_source":
        l2 = 8.0 + float(rng.integers(1, 30)) * (1 if rng.random() < .5 else rng.random())
    alp = float(rng.choice([0.0, np.pi, -np.pi, 2 * np.pi, np.pi / 2, 3 * np.pi / 2, PI_22_7,
                            rng.uniform(-1e-8, 1e-8), np.pi + rng.uniform(-1e-8, 1e-8), rng.uniform(0, 2 * np.pi)]))
    return {"lengths": (float(l1), l2, float(l3), float(l4), float(l5)), "alp": alp,
            "rpm": float(rng.choice([0.0, 0.5, 1.0, 300.0, -300.0, 299.9, 1e6, rng.uniform(1, 3000)])),
            "area": real4(rng.choice([0.1963495408, 1.0, 1e-6, 1e3])), "modulus": real4(rng.choice([1e7, 1.0, 3e7, 1e12])),
            "inertia": real4(rng.choice([0.0030679615, 1.0, 1e-8, 1e3])),
            "step": float(rng.choice([1.0, 20.0, 45.0, 90.0, 0.5, 7.0, 360.0, 400.0, 11.0])),
            "weight": real4(rng.choice([0.0, 2.0, 1e-30, 1e30, 0.098]))}


# --- the command's part ------------------------------------------------------------------

def flat(g: dict) -> dict:
    """A geometry of the tests' form as the command's row: the lengths spelled out."""
    return dict(zip(LENGTHS, g["lengths"]), **{k: v for k, v in g.items() if k != "lengths"})


def nested(row: dict) -> dict:
    """A command's row in the tests' form."""
    return dict({k: v for k, v in row.items() if k not in LENGTHS}, lengths=tuple(row[k] for k in LENGTHS))


def _legacy(name: str):
    return lambda row: legacy_call(name, nested(row))


def _port(name: str):
    def call(row: dict) -> dict:
        g = nested(row)
        deg = listing_angles(g["step"])
        return dict(port_call(name, g, deg), deg=deg)      # legacy's deg is compared with the angles given
    return call


def _example(name: str) -> dict:
    """The published run's inputs (the legacy face's defaults, the listing's values)."""
    spelled = {"mass_lbf": "weight", "density": "weight", "step_deg": "step"}
    return {spelled.get(k, k): float(p.default) for k, p in inspect.signature(getattr(ali1977, name)).parameters.items()}


def _sampler(draw):
    return lambda rng, name: flat(draw(rng, name))


LARGEST = 1e6
DIFFERENTIAL = Thesis(
    title="Ali (1977), the six K.E.D. programs",
    parameters=(*(Parameter(n, "in", log=True, limits=(1 / LARGEST, LARGEST)) for n in LENGTHS),
                Parameter("alp", "rad", limits=(-LARGEST, LARGEST)),
                Parameter("rpm", "rpm", limits=(-(2.0**31 - 1), 2.0**31 - 1)),
                Parameter("weight", "lbf (Case I's weight), lb/in^3 (Cases II, III's density)", log=True, real4=True,
                          limits=(0.0, 1e38)),
                Parameter("area", "in^2", log=True, real4=True, limits=(1e-38, 1e38)),
                Parameter("modulus", "psi", log=True, real4=True, limits=(1e-38, 1e38)),
                Parameter("inertia", "in^4", log=True, real4=True, limits=(1e-38, 1e38)),
                Parameter("step", "deg", real4=True, limits=(0.0018, 1e38))),
    domains=(Domain("sample", "the report's fixed sample (draw_sample): a quarter free lengths 0.5-100 in, a quarter "
                    "Grashof crank-rockers (crank 0.5-20 in), half on an assembly limit (l5 = l3 + l4 - l1 or "
                    "l1 + |l3 - l4|) moved by 1e-14 to 1e-1 relative; l2 0.2-60 in (Case III's source 8.01-48); "
                    "alp -2 pi .. 4 pi; 1-3000 rpm; weight 1e-3-10, area 0.01-5 in^2, modulus 1e6-3e7 psi, inertia "
                    "1e-5-1 in^4, log-uniform, REAL*4; steps 0.7, 1, 2.5, 3.3, 5, 7.5, 10, 15, 20, 30 deg.",
                    _sampler(draw_sample)),
             Domain("edges", "the report's edge sample (draw_edges): a fifth each folded at 0 deg in small integers, on "
                    "an assembly limit moved by -8..8 ulps, on Grashof's change point, degenerate cognates (l2 = l3) "
                    "and crank-rockers; alp on the axes, 22/7, within 1e-8 of 0 or pi; speeds, section values, "
                    "weights and steps from lists of ordinary and extreme values (0 and 1e6 rpm, 1e-30 and 1e30 lbf, "
                    "steps 0.5 to 400 deg).", _sampler(draw_edges))),
    programs=tuple(Program(name, name.replace("_", " "), _legacy(name), _port(name), _example(name))
                   for name in PROGRAMS),
    criterion="the same outcome (both return, or both raise the same error at the same input angle, with the same "
              "linkrepro warnings) and, where both return, every array equal bit for bit (deg, xp, yp, dx, dy, rot, "
              "and the cognates' cxp, cyp; Case III's nodes): the port emulates each listing's REAL*4 storage and "
              "MPRD's order of summation, as tests/ali1977/test_differential.py asserts.",
)

__all__ = ["DIFFERENTIAL", "PROGRAMS", "PI_22_7", "real4", "listing_angles", "port_call", "legacy_call",
           "draw_sample", "draw_edges", "flat", "nested"]
