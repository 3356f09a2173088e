"""Rahman's (1996) optimum balancing of the CSSP mechanism, ported: ``balance``.

Over the 37 crank positions 0, 10, ..., 360 deg: the mechanics (the listing's own, or the
closed-loop model: ``CsspQuirks.open_loop_model``), the objective of eq. (4.3) summed over
the cycle, the quadratic program of section 4.4 for the nine point masses, and the
quantities of Tables 5.1-5.7 before (equal point masses) and after (the QP's masses).

The QP is solved by the port of our QPROG stand-in (``port/qprog.py``: Goldfarb-Idnani, the
method of IMSL's QPROG, equal to the legacy build bit for bit).  Its Hessian is singular by
design (the split of the crank's three pair masses enters nothing, register D057), so, as
IMSL documents for QPROG, H + DIAG*I is used with DIAG the smallest shift found by raising
Cholesky pivots (``hessian_shift``): the answer is the regularized problem's (QPROG's
``regularized``), which on H's null directions is the smallest-norm split, the equal one,
and elsewhere differs from H's by DIAG / lambda.  That is the design, not a loss, so the
CSSP does not give QPROG's warning for it; it warns (``PrecisionWarning``) where the bound on
the answer's relative error, ``qprog.relative_error`` with the unit of the Hessian's
precision (2**-24 with the listing's REAL*4, eps in double), reaches 1 (D161).

Units: inch, lbf, second, lb*s^2/in; crank angles in degrees at the interface.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ...checks import cssp_speed, masses
from ...errors import PrecisionWarning, QPError, SingularPositionError
from . import qprog
from .data import QP_EQUALITIES, QP_ROWS, Constants, CsspInputs, qp_constraints
from ..slider_crank.geometry import initial_estimate
from .listing import Carry, listing_pass, unit_loads
from .objective import UnitLoads, objective, position_forms, table_quantities
from .quirks import CSSP_CORRECTED, CSSP_PRINTED, CsspQuirks

__all__ = ["CsspInputs", "balance", "solve_qp", "hessian_shift", "link_masses", "principal_moments", "CRANK_DEG", "CSSP_PRINTED",
           "CSSP_CORRECTED"]

#: the listing's positions: TH1 = J*10 - 10, J = 1..37
CRANK_DEG = np.arange(37) * 10.0
#: the series tables, in the order of ``table``'s column pairs (legacy.rahman1996.CSSP_COLUMNS)
TABLES = ("5_2", "5_3", "5_4", "5_5", "5_6", "5_7")


def hessian_shift(h: np.ndarray) -> float:
    """DIAG: the multiple of I that our QPROG adds to H (D050, D160).

    0 where H is positive definite to its rounding (every Cholesky pivot at least n eps
    max|H_ij| and tr(H) tr(H^-1) within 1/(n eps)); else Cholesky pivot by pivot on H scaled
    to a largest entry in [1, 4), a pivot below sqrt(eps)*max|H_ij| raising DIAG by the
    shortfall.  The rule is port/qprog.py's, operation for operation the FORTRAN's.
    """
    return qprog.hessian_shift(h)


def solve_qp(h: np.ndarray, rows: np.ndarray = QP_ROWS, bounds=None, equalities: int = QP_EQUALITIES):
    """min x'Hx/2 s.t. the first ``equalities`` rows x = bounds, the rest x >= bounds.

    Solved by the port of our QPROG (port/qprog.py, equal to the legacy build bit for bit),
    on H + DIAG*I where DIAG > 0 (by design here: D057; QPROG's warning is not given).
    Returns (x, diag).  Raises QPError when the QP has no solution (inconsistent
    constraints, unbounded, QPROG's iteration limit) or H is not finite.
    """
    result = _balancing_qp(h, rows, bounds, equalities)
    return result["sol"], result["diag"]


def _balancing_qp(h, rows, bounds, equalities) -> dict:
    """``solve_qp``'s QPROG result (``qprog.solve``: no warning; the caller reads it)."""
    h = np.asarray(h, dtype=float)
    if not np.all(np.isfinite(h)):
        raise QPError("the balancing QP has a non-finite Hessian")
    try:
        return qprog.solve(h, np.zeros(len(h)), rows, np.asarray(bounds, float), equalities)
    except QPError as exc:
        raise QPError(f"the balancing QP has no solution: {exc}") from exc


def precision_warning(worst: float) -> PrecisionWarning:
    """The CSSP's warning where a QP's answer is not carried by the Hessian's precision
    (``worst``: the largest ``qprog.relative_error`` at or above 1; register D161)."""
    return PrecisionWarning("CSSP: the balancing QP's masses are not determined by its Hessian: the bound on "
                            "their relative error, on the directions the Hessian determines, reaches 1 (register D161)",
                            relative_error=worst)


@dataclass
class Pass:
    """One sweep of the 37 positions: the per-unit loads and each position's form F."""
    loads: UnitLoads
    forms: np.ndarray        # (37, 9, 9)


def _listing_motions(inputs: CsspInputs, real4: bool, printed_inverse: bool):
    """The printed Newton's two passes, one at a time (pass 2 starts with pass 1's last
    eta2, eta3), so that a failure surfaces where the listing's would: after QP 1."""
    c = Constants.of(inputs, real4)
    start = initial_estimate(c, real4)
    first = listing_pass(CRANK_DEG, start, c, printed_inverse)
    yield first
    start[[1, 3]] = first.eta2[-1], first.eta3[-1]
    yield listing_pass(CRANK_DEG, start, c, printed_inverse)


def _passes(inputs: CsspInputs, quirks: CsspQuirks, c: Constants):
    """The sweeps whose forms OF accumulates: the listing's two, or the closed loop's one."""
    positions = 37 if quirks.objective_37_positions else 36
    if quirks.open_loop_model:
        carry = Carry()
        for motion in _listing_motions(inputs, quirks.cssp_real4, quirks.inverse_without_pivoting):
            loads, carry = unit_loads(motion, c, quirks, carry)
            yield Pass(loads, position_forms(loads, c, quirks, positions))
        return
    from .mechanics import closed_loop_loads
    loads = closed_loop_loads(c, CRANK_DEG)
    yield Pass(loads, position_forms(loads, c, quirks, positions))


def balance(inputs: CsspInputs = CsspInputs(), quirks: CsspQuirks = CSSP_PRINTED, solution=None) -> dict:
    """Run the balancing example; every quantity of Tables 5.1-5.7.

    Returns ``table`` (37 x 12: objective, shaking force, shaking moment, bearing force,
    bearing torque, input torque, each before and after, rows 0..360 deg), ``inertia``
    (6 x 2: I_xx, I_yy, I_zz of crank and rod, before and after), ``solution`` (9 masses,
    lb*s^2/in: those behind the 'after' columns, the first QP's answer; fed back, it gives
    the same 'after' columns), ``solution_table51`` (those of Table 5.1, the last QP's
    answer), and ``diag`` and ``hessian`` of the first QP; the same meanings as
    ``linkrepro.legacy.rahman1996.cssp`` (register D151).
    With ``open_loop_model`` the listing's two passes run: OF accumulates over both, the
    tables use the first QP's answer, Table 5.1 the second's (as printed).  ``solution``
    (9 masses), if given, replaces every QP's answer, as the legacy face's (D055).
    ValueError for a speed below 2**-126 rpm (D164); a ``PrecisionWarning`` where a QP's
    masses are not carried by its Hessian's precision (D161, as the legacy face).
    """
    if not isinstance(inputs, CsspInputs):
        raise TypeError(f"inputs must be CsspInputs, got {type(inputs).__name__}")
    if not isinstance(quirks, CsspQuirks):
        raise TypeError(f"quirks must be CsspQuirks (CSSP_PRINTED, CSSP_CORRECTED, ...), got {type(quirks).__name__}")
    cssp_speed(inputs.rpm)
    given = None if solution is None else masses("solution", solution)
    c = Constants.of(inputs, quirks.cssp_real4)
    single = (lambda v: np.asarray(v, np.float32).astype(float)) if quirks.cssp_real4 else np.asarray
    counted = slice(0, 37 if quirks.objective_37_positions else 36)
    rows, bounds, equalities = qp_constraints(c, quirks.qp_cg_masses_free, quirks.qp_data_rounded,
                                              quirks.cssp_real4)
    unit = qprog.REAL4_UNIT if quirks.cssp_real4 else qprog.EPS
    passes, accumulated, solutions, first_qp, worst = [], np.zeros((9, 9)), [], None, 0.0
    for sweep in _passes(inputs, quirks, c):
        passes.append(sweep)
        accumulated = accumulated + sweep.forms[counted].sum(axis=0)
        hessian = single(2.0 * accumulated)
        result = _balancing_qp(hessian, rows, bounds, equalities)
        error = qprog.relative_error(hessian, result, unit)       # as QPROG's REAL*4 entry (D161)
        worst = error if error >= 1.0 and error > worst else worst
        solutions.append(single(result["sol"] if given is None else given))
        first_qp = first_qp or (hessian, result["diag"])
    last, after = passes[-1], solutions[0]
    before = c.point_masses
    columns = [objective(last.forms, before, quirks),
               objective(last.forms, after, quirks, single=quirks.cssp_real4)]
    quantities = [table_quantities(last.loads, x, quirks) for x in (before, after)]
    for table in TABLES[1:]:
        columns += [quantities[0][table], quantities[1][table]]
    table = np.stack(columns, axis=1)
    bad = ~np.isfinite(table).all(axis=1)
    if bad.any():
        raise SingularPositionError("CSSP: a non-finite value in the tables", float(CRANK_DEG[np.argmax(bad)]))
    if worst:
        warnings.warn(precision_warning(worst), stacklevel=2)
    return {"table": table, "inertia": _inertia_table(c, solutions[-1]),
            "solution": after, "solution_table51": solutions[-1], "hessian": first_qp[0],
            "diag": first_qp[1]}


def link_masses(x) -> np.ndarray:
    """Crank, connecting rod, slider: the sums of their point masses (eq. 4.4), lb*s^2/in.

    The principal moments of Table 5.1 do not see x4 and x8 (the masses at the centres of
    mass), so only these sums show what the QP did to the links' masses (register D130).
    """
    x = np.asarray(x, dtype=float)
    return np.array([x[0:4].sum(), x[4:8].sum(), x[8]])


def principal_moments(arms, masses) -> tuple[float, float, float]:
    """I_xx, I_yy, I_zz about a link's centre of mass (lb*s^2*in, eq. 2.9) of its point masses:
    ``masses`` m1, m2, m3 (lb*s^2/in) in pairs at +-X, +-Y, +-Z (``arms``, in); a fourth mass at
    the centre adds nothing."""
    (xa, ya, za), (m1, m2, m3) = arms, masses[:3]
    return ya ** 2 * m2 + za ** 2 * m3, xa ** 2 * m1 + za ** 2 * m3, xa ** 2 * m1 + ya ** 2 * m2


def _inertia_table(c: Constants, x: np.ndarray) -> np.ndarray:
    """Table 5.1: principal moments of crank and rod (eq. 2.9), before and after."""
    rows = []
    for link, (arms, inertia) in enumerate(((c.crank_arms, c.inertia_crank), (c.rod_arms, c.inertia_rod))):
        rows += list(zip(inertia, principal_moments(arms, x[4 * link:4 * link + 3])))
    return np.array(rows)
