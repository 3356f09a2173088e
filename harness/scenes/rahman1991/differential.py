"""Rahman (1991)'s part of ``linkrepro differential`` (``harness/differential.py``).

The 1991 thesis printed no program; its method's Newton is the first pass of the 1996 CSSP
program by the same author.  So its differential is the 1991 method (``rahman1991.position``)
run in the 1996 build's arithmetic (``BUILD_1996``: REAL*4 inputs, the listing's INVERSE,
10-deg steps, no DFP fallback, no branch check) against the legacy 1996 build's first-pass
positions, on the 1991 example (a1 = 12, a2 = 50 in, 50 rpm) over its grid's range and
beyond, as tests/rahman1996/test_differential.py does.
"""
from __future__ import annotations

import numpy as np

from ....checks import LARGEST
from ....errors import AssemblyError, ConvergenceError
from ....legacy import rahman1996
from ....port.rahman1991.data import GscInputs
from ....port.rahman1991.position import BUILD_1996, CANNOT_ASSEMBLE, PositionRun, positions
from ....port.rahman1996.balance import CRANK_DEG
from ....port.rahman1996.data import Constants, CsspInputs
from ...differential import Domain, Outcome, Parameter, Program, Thesis

#: the slider crank's inputs of GscInputs (the rest, the section's loads, play no part in positions)
NAMES = ("a1", "a2", "a4", "alpha4_deg", "s1", "rpm")


def real4(x: float) -> float:
    return float(np.float32(x))


def draw(rng: np.random.Generator, program: str = "positions") -> dict:
    """One geometry: the 1991 example with a4 ~ U(0, 40) in, alpha4 ~ U(0, 360) deg, S1 ~ U(0, 10)
    in (a4, S1 as REAL*4 numbers, what the build receives)."""
    return geometry(GscInputs(a4=real4(rng.uniform(0.0, 40.0)), alpha4_deg=float(rng.uniform(0.0, 360.0)),
                              s1=real4(rng.uniform(0.0, 10.0))))


def geometry(inputs: GscInputs) -> dict:
    return {name: getattr(inputs, name) for name in NAMES}


def sweep_1991(g: dict) -> PositionRun:
    """The 1991 method's Newton in the 1996 build's arithmetic over the build's crank angles,
    stopping at its first failure."""
    pi = Constants.of(CsspInputs(**g), True).pi
    return positions(GscInputs(**g), CRANK_DEG * (pi / 180.0), use_dfp=False, stop_at_failure=True, setup=BUILD_1996,
                     branch=None)


def port_positions(g: dict) -> dict:
    """The 1991 sweep's positions (where its Newton stopped, the loop closed or not: the build
    checks no closure); where it stops, the error of its status at that crank angle."""
    run = sweep_1991(g)
    solved = run.stopped
    if not solved.all():
        k = int(np.argmin(solved))
        error = AssemblyError if run.status[k] == CANNOT_ASSEMBLE else ConvergenceError
        raise error(f"the 1991 Newton: {run.status[k]}", float(CRANK_DEG[k]))
    return {"positions": run.q}


def legacy_first_pass(g: dict) -> dict:
    """The 1996 build's first-pass positions (it runs both passes, its QP and rates too)."""
    return {"positions": rahman1996.cssp(**g)["positions"][0]}


def accepts(legacy: Outcome, port: Outcome) -> str:
    """The build raises where the 1991 sweep runs through, or stops at the build's angle with
    another error: the build can fail after its first pass (rates, second pass, QP), which the
    1991 method does not run."""
    if legacy.ok:
        return ""
    if port.ok:
        return "the build fails after its first pass, the 1991 sweep runs through"
    if port.angle == legacy.angle:
        return "the 1991 sweep stops where the build fails"
    return ""


DIFFERENTIAL = Thesis(
    title="Rahman (1991), the generalized slider crank's Newton against the 1996 build's first pass",
    parameters=(Parameter("a1", "in", limits=(1 / LARGEST, LARGEST)), Parameter("a2", "in", limits=(1 / LARGEST, LARGEST)),
                Parameter("a4", "in", real4=True, limits=(-LARGEST, LARGEST)),
                Parameter("alpha4_deg", "deg", limits=(-LARGEST, LARGEST)),
                Parameter("s1", "in", real4=True, limits=(-LARGEST, LARGEST)),
                Parameter("rpm", "rpm", limits=(1 / LARGEST, LARGEST))),
    domains=(Domain("sample", "the 1991 example (a1 = 12, a2 = 50 in, 50 rpm) with a4 ~ U(0, 40) in, alpha4 ~ U(0, 360) "
                    "deg, S1 ~ U(0, 10) in (a4 and S1 REAL*4), the 1996 build's 37 crank angles 0-360 deg.", draw),),
    programs=(Program("positions", "the 1991 Newton (BUILD_1996) against the 1996 build's first pass",
                      legacy_first_pass, port_positions, geometry(GscInputs()), accepts=accepts),),
    criterion="where the build returns, the 1991 sweep runs through and its positions (theta2, eta2, theta3, eta3, "
              "S4 at each crank angle) equal the build's first pass bit for bit; where the build raises, the 1991 "
              "sweep stops at the build's crank angle or runs through (the build failing after its first pass: in "
              "its rates, second pass or QP, which the 1991 method does not run), as "
              "tests/rahman1996/test_differential.py asserts.",
)
