"""Rahman (1996)'s part of ``linkrepro bench`` (the machine: ``harness/bench.py``): the cost
of the CSSP balance of Tables 5.1-5.7 against the listing's flop count (``CSSP_*`` and the
Newton's ``NEWTON_*`` of ``scenes/rahman1991/bench``); the knobs CSSP positions L and REAL*4
constants; Exudyn's step (``multibody``, where Exudyn is installed)."""
from __future__ import annotations

import numpy as np

from ....legacy import rahman1996
from ....port.rahman1991 import position as gsc_position
from ....port.rahman1991.data import GscInputs
from ....port.rahman1996.balance import CRANK_DEG, CsspInputs, balance, solve_qp
from ....port.rahman1996.data import Constants
from ....port.rahman1996.mechanics import closed_loop_loads
from ....port.rahman1996.objective import position_forms
from ....port.rahman1996.quirks import CSSP_CORRECTED, CSSP_PRINTED
from ... import multibody as exudyn_gate
from ...bench import Computation, Knob, mprd
from . import multibody
from ..rahman1991.bench import NEWTON_RATES, NEWTON_STEP

#: CSSP, per position and pass: the unit loads of 9 point masses (~300 each, frames, forces,
#: moments, reactions) and the 9x9 forms of eq. (4.2) from 10 load vectors (9x3 each)
CSSP_LOADS = 9 * 300 + 10 * mprd(9, 3, 9)
#: CSSP, per position: the tables before and after (10 weighted sums of 9x3, norms); the QP of
#: 9 masses (~20 active-set steps of ~1000 flops, twice) shared by the 37 positions
CSSP_TABLES = 2 * (10 * mprd(9, 3, 1) + 30) + 2 * 20 * 1000 // 37


def cssp_flops(newton_steps: float) -> float:
    """Flops per position of the CSSP program: two passes of Newton, rates, loads and forms."""
    return 2 * (newton_steps * NEWTON_STEP + NEWTON_RATES + CSSP_LOADS) + CSSP_TABLES


# ------------------------------------------------------------------ cost per position

def _cssp_newton_steps() -> float:
    """Mean Newton steps per position of the CSSP listing's first pass (the port's replica of
    the build's arithmetic, ``BUILD_1996``; untimed: an input of the flop count only)."""
    inputs = GscInputs(**{k: getattr(CsspInputs(), k) for k in ("a1", "a2", "a4", "alpha4_deg", "s1", "rpm")})
    run = gsc_position.positions(inputs, np.radians(CRANK_DEG), use_dfp=False, setup=gsc_position.BUILD_1996)
    return float(run.iterations.mean())


def _table_error(out, ref) -> tuple[float, str]:
    """Largest |table - table_ref| over each column's largest |value| (Tables 5.2-5.7)."""
    return float(np.max(np.abs(out["table"] - ref["table"]) / np.abs(ref["table"]).max(axis=0))), ""


def computations(quick: bool) -> list[Computation]:
    """The CSSP balance (the same when ``quick``)."""
    steps = _cssp_newton_steps()
    return [
        Computation("CSSP balance, Tables 5.1-5.7", len(CRANK_DEG),
                    {"legacy": rahman1996.cssp, "port_printed": lambda: balance(CsspInputs(), CSSP_PRINTED),
                     "port_corrected": lambda: balance(CsspInputs(), CSSP_CORRECTED)},
                    lambda _: cssp_flops(steps), lambda leg, prt: _table_error(prt, leg)[0],
                    note=f"two Newton passes of {steps:.1f} steps a position (the listing's first pass)"),
    ]


# ------------------------------------------------------------------ knobs

def cssp_cycle(count: int) -> tuple[int, float, np.ndarray]:
    """The corrected CSSP model over ``count`` equal intervals of the turn: (count, its cycle
    integral G-bar of eq. (4.1) for the original masses, the QP's masses in lb*s^2/in)."""
    c = Constants.of(CsspInputs(), False)
    forms = position_forms(closed_loop_loads(c, np.arange(count) * (360.0 / count)), c, CSSP_CORRECTED,
                           count).sum(axis=0)
    return count, float(c.point_masses @ forms @ c.point_masses), solve_qp(2 * forms, bounds=c.qp_bounds)[0]


def _against_port(result, port) -> tuple[float, str]:
    """Largest |Exudyn - port| over the column's peak, the worst of Tables 5.3, 5.4, 5.7."""
    if result is port:
        return 0.0, "the reference"
    return max(difference / peak for peak, difference in multibody.agreement(port, result).values()), ""


def exudyn_step(quick: bool) -> list[Knob]:
    """Exudyn's step against the corrected port's closed-loop columns (before masses, the port's
    universal crank pin); none where Exudyn is not installed."""
    if not exudyn_gate.available():
        return []
    steps = (1.0, 0.5) if quick else multibody.STEPS
    masses = Constants.of(CsspInputs(), False).point_masses
    settings = {f"{s:g} deg": (lambda s=s: multibody.simulate(masses, "universal", s)) for s in steps}
    settings["port_corrected"] = lambda: multibody.port_columns()[0]["before"]
    return [Knob("Exudyn step (CSSP)", "exudyn", "relative",
                 "rigid CSSP in Exudyn at a step of crank (the scene's: one revolution, two where 10 deg is under "
                 f"{multibody.START_UP_STEPS} steps): largest |difference| / peak of Tables 5.3, 5.4, 5.7 against the "
                 "corrected port (the reference; its time is the whole balance)", settings, "port_corrected", _against_port,
                 lambda r: len(CRANK_DEG))]


def knobs(quick: bool) -> list[Knob]:
    """The CSSP positions L (``quick``: three settings), REAL*4 constants against double,
    Exudyn's step."""
    counts = (6, 12, 72) if quick else (6, 9, 12, 18, 24, 36, 72, 360)
    return [
        Knob("CSSP positions L", "port_corrected", "relative",
             "corrected model: |G-bar - G-bar_ref| / G-bar_ref of the original masses, eq. (4.1) with L equal "
             "intervals (the thesis: 36), loads + objective + QP",
             {f"L = {n}": (lambda n=n: cssp_cycle(n)) for n in counts}, f"L = {counts[-1]}",
             lambda r, ref: (abs(r[1] - ref[1]) / ref[1], ""), lambda r: r[0]),
        Knob("CSSP precision", "port_corrected", "relative",
             "corrected model, Tables 5.2-5.7: largest |difference| / column's largest value, against double",
             {"double": lambda: balance(CsspInputs(), CSSP_CORRECTED),
              "REAL*4 constants": lambda: balance(CsspInputs(), CSSP_CORRECTED.only("cssp_real4", True))},
             "double", _table_error, lambda r: len(CRANK_DEG)),
    ] + exudyn_step(quick)
