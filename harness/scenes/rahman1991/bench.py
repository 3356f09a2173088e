"""Rahman (1991)'s part of ``linkrepro bench`` (the machine: ``harness/bench.py``): the cost
of the printed Newton (against the 1996 legacy build, the only program) and of the corrected
positions, rates and joint forces, against their flop counts (``NEWTON_*``, ``CLOSED_LOOP``,
``GSC_FORCES``; the Newton's are the 1996 listing's too); the knobs of the printed Newton:
angle step, tolerance, iteration cap, REAL*4."""
from __future__ import annotations

from typing import Callable

import numpy as np

from ....legacy import rahman1996
from ....port.rahman1991 import analysis, position as gsc_position
from ....port.rahman1991.data import GscInputs
from ....port.rahman1991.quirks import GSC_CORRECTED, GSC_PRINTED
from ....port.rahman1996.balance import CRANK_DEG
from ....port.slider_crank.geometry import CsspInputs
from ....port.slider_crank.kinematics import kinematics
from ...bench import TRANSCENDENTAL, Computation, Knob, crank_grid, step_label, relative_error, mprd

#: one step of the spatial Newton (slider_crank._newton.newton): sin, cos of five angles, 13 dual
#: 3x3 products (three products and a sum each), ~60 for the entries; A'A, its 5x5 inverse
#: (2 n^3), (A'A)^-1 A', Delta
NEWTON_STEP = (10 * TRANSCENDENTAL + 13 * (3 * mprd(3, 3, 3) + 9) + 60 + mprd(5, 6, 5) + 2 * 5 ** 3
               + mprd(5, 5, 6) + mprd(5, 6, 1))
#: the listing's DOT, DDOT (slider_crank._newton.rates): six sin/cos, the pseudo-inverse of VM, two
#: products, ~120 for VV and AV
NEWTON_RATES = 6 * TRANSCENDENTAL + mprd(5, 6, 5) + 2 * 5 ** 3 + mprd(5, 5, 6) + 2 * mprd(5, 6, 1) + 120
#: the closed loop with second-order jets (slider_crank.kinematics.kinematics): ~10 sin/cos/sqrt/atan2,
#: ~60 jet operations of 9 flops, R2 as two 3x3 products of jets
CLOSED_LOOP = 10 * TRANSCENDENTAL + 60 * 9 + 2 * 27 * 9 * 2
#: the corrected Newton-Euler of the 1991 model (rahman1991.forces.corrected_forces): ~12 cross
#: products, ~150 more
GSC_FORCES = 12 * 9 + 150

#: Rahman (1991): the spatial configuration of section 3.1 where the 1996 build runs a full turn
GSC_SPATIAL = GscInputs(a4=30.0, s1=3.5)
#: its Newton's converged reference (every |Delta| <= 1e-13)
CONVERGED = gsc_position.NewtonSetup(tol=1e-13)


# ------------------------------------------------------------------ cost per position

def _legacy_on(inputs: CsspInputs) -> Callable:
    """The 1996 legacy build (the whole CSSP program) on this geometry."""
    return lambda: rahman1996.cssp(a1=inputs.a1, a2=inputs.a2, a4=inputs.a4, alpha4_deg=inputs.alpha4_deg,
                                   s1=inputs.s1, rpm=inputs.rpm)


def computations(quick: bool) -> list[Computation]:
    """The 1991 printed Newton and corrected closed loop (the same when ``quick``)."""
    th10, th1 = np.radians(CRANK_DEG), np.radians(analysis.CRANK_DEG)
    closed = lambda: kinematics(GSC_SPATIAL, th10, np.stack(GSC_SPATIAL.axial(th10)))   # noqa: E731
    return [
        Computation("Rahman 1991 Newton, a4 = 30, S1 = 3.5, 10-deg steps", len(th10),
                    {"legacy": _legacy_on(GSC_SPATIAL),
                     "port_printed": lambda: gsc_position.positions(GSC_SPATIAL, th10, setup=gsc_position.THESIS_1991,
                                                                     branch=None),
                     "port_corrected": closed},
                    lambda r: float(r["port_printed"].iterations.mean()) * NEWTON_STEP,
                    lambda leg, prt: relative_error(prt.q, leg["positions"][0]), legacy_positions=2 * len(th10),
                    note="legacy: the whole 1996 program (two Newton passes, rates, loads, QP) over its "
                         f"{2 * len(th10)} Newton solves, an upper bound on its Newton; port corrected: the "
                         "closed loop's positions and rates"),
        Computation("Rahman 1991 positions, rates, joint forces, 361 angles", len(th1),
                    {"port_printed": lambda: analysis.analyse(GSC_SPATIAL, quirks=GSC_PRINTED),
                     "port_corrected": lambda: analysis.analyse(GSC_SPATIAL, quirks=GSC_CORRECTED)},
                    lambda _: CLOSED_LOOP + GSC_FORCES,
                    note="no program exists (the 1991 thesis prints none); limit: the corrected closed loop"),
    ]


# ------------------------------------------------------------------ knobs

def _newton_error(measure: Callable) -> Callable:
    """error(run, ref): largest |measure(run) - measure(ref)| of two ``PositionRun``s; inf, with
    a note, where the run's Newton failed at some position (off the plane it stops where the
    loop is open, D085: that is the printed method's answer, measured as such)."""
    def error(run, ref) -> tuple[float, str]:
        failed = int(np.sum(~run.stopped))
        if failed:
            return np.inf, f"failed at {failed} of {run.stopped.size} positions"
        return float(np.max(np.abs(measure(run) - measure(ref)))), ""
    return error


#: joint variables theta2, eta2, theta3, eta3 (rad), S4 (in) at every position
_q_error = _newton_error(lambda run: run.q)
#: the slider's stroke, max S4 - min S4 over the turn (in)
_stroke_error = _newton_error(lambda run: np.ptp(run.q[:, 4]))


def _newton(theta1: np.ndarray, setup, use_dfp: bool = True) -> Callable:
    return lambda: gsc_position.positions(GSC_SPATIAL, theta1, use_dfp=use_dfp, setup=setup, branch=None)


def _positions(run) -> int:
    return run.q.shape[0]


def newton_knobs(steps: tuple, tols: tuple, caps: tuple) -> list[Knob]:
    """The 1991 printed Newton (a4 = 30, S1 = 3.5): angle step, tolerance, iteration cap, REAL*4."""
    th10 = np.radians(CRANK_DEG)
    cap_ref = gsc_position.THESIS_1991.max_iterations
    precision = {"double, |Delta| <= 1e-13": CONVERGED, "double, |Delta| <= 1e-7": gsc_position.THESIS_1991,
                 "REAL*4, |Delta| <= 1e-7": gsc_position.NewtonSetup(real4=True)}
    return [
        Knob("1991 angle step", "port_printed", "in",
             "printed Newton from the last answer: the slider's stroke (max - min S4), against the finest step",
             {step_label(s): _newton(np.radians(crank_grid(s)), gsc_position.THESIS_1991) for s in steps},
             step_label(steps[-1]), _stroke_error, _positions),
        Knob("1991 Newton tolerance", "port_printed", "in, rad",
             "10-deg steps: largest |q - q_ref| over theta2, eta2, theta3, eta3 (rad), S4 (in)",
             {f"{t:g}": _newton(th10, gsc_position.NewtonSetup(tol=t)) for t in tols}, f"{tols[-1]:g}",
             _q_error, _positions),
        Knob("1991 Newton iteration cap", "port_printed", "in, rad",
             "10-deg steps, |Delta| <= 1e-7, Newton alone (no DFP fallback): largest |q - q_ref|, against "
             f"the listing's {cap_ref}",
             {f"{c}": _newton(th10, gsc_position.NewtonSetup(max_iterations=c), use_dfp=False) for c in caps},
             f"{cap_ref}", _q_error, _positions),
        Knob("1991 Newton precision", "port_printed", "in, rad",
             "10-deg steps: largest |q - q_ref| against double precision converged to 1e-13",
             {label: _newton(th10, setup) for label, setup in precision.items()}, next(iter(precision)),
             _q_error, _positions),
    ]


def knobs(quick: bool) -> list[Knob]:
    """The printed Newton's knobs (``quick``: three settings each)."""
    if quick:
        return newton_knobs((30.0, 10.0, 5.0), (1e-2, 1e-7, 1e-13), (10, 20, 150))
    return newton_knobs((45.0, 30.0, 20.0, 10.0, 5.0, 2.0, 1.0, 0.5, 0.25),
                        (1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13), (5, 8, 10, 15, 20, 30, 150))
