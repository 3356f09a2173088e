"""Python face of Rahman (1996), Appendix B: the CSSP balancing program, INVERSE, our QPROG.

``cssp`` runs the main program (legacy/src/rahman1996_cssp_main.f, a SUBROUTINE since
D051) over its 37 crank positions, 0..360 deg in 10-deg steps, and returns every quantity
of Tables 5.1-5.7.  Defaults are the printed PARAMETERs (section 5.2).

Units as printed: inch, lbf, second; masses lb*s^2/in; inertias lb*s^2*in; angles deg.
Errors: ``ValueError`` for bad parameters (a crank speed below 2**-126 rpm included, D164),
``ConvergenceError`` when the printed
Newton-Raphson gives up after 150 iterations (the listing's STOP), ``SingularPositionError``
when INVERSE meets an exactly zero pivot (its STOP) or, before any other failure, at the
first position the program computed whose velocity equations have a condition number beyond
``linkrepro.checks.POSITION_CONDITION_LIMIT`` (the listing computes on there; register D150),
``QPError`` when QPROG fails.  ``PrecisionWarning`` where QPROG's REAL*4 entry finds that
single precision cannot carry the masses its Hessian determines (D161; QPROG's DIAG is by
design there, D057, and not warned).

Threads: the FORTRAN keeps static storage (-fno-automatic, COMMON /INVERR/, /QPSTAT/), and
a status is read by a second call after the routine returns.  Every call sequence here holds
``FORTRAN_LOCK``, so calls from several threads are serialized and each returns what it
would alone (f2py holds the GIL during a call as well: the FORTRAN never runs twice at once).
"""
from __future__ import annotations

import threading
import warnings

import numpy as np

from ..checks import (cssp_speed, finite_matrix, listing_condition, masses, qp_arguments,
                      refuse_singular_position, slider_crank)
from ..errors import ConvergenceError, QPError, SingularPositionError
from ..port.rahman1996 import balance as _balance
from ..port.rahman1996.qprog import answer, precision_warning
from . import _rahman1996 as _f

#: held around every call into the compiled Rahman (1996) FORTRAN (static storage, see above)
FORTRAN_LOCK = threading.Lock()

#: TABLE columns of ``cssp``: (table, quantity) in the order the FORTRAN fills them.
CSSP_COLUMNS = [("5_2", "before"), ("5_2", "after"), ("5_3", "before"), ("5_3", "after"),
                ("5_4", "before"), ("5_4", "after"), ("5_5", "before"), ("5_5", "after"),
                ("5_6", "before"), ("5_6", "after"), ("5_7", "before"), ("5_7", "after")]
#: rows of the inertia output: (link, quantity) of Table 5.1
INERTIA_ROWS = [("crank", "i_xx"), ("crank", "i_yy"), ("crank", "i_zz"),
                ("connecting_rod", "i_xx"), ("connecting_rod", "i_yy"), ("connecting_rod", "i_zz")]


def cssp(a1=2.0, a2=8.0, a4=1.0, alpha4_deg=250.0, s1=0.4, rpm=3000.0, solution=None) -> dict:
    """Run the CSSP program (both passes: objective, QPROG, comparison) once.

    a1, a2, a4, s1 in inches, alpha4_deg in degrees, rpm the crank speed (the six checked
    together: a TypeError before any ValueError, as ``CsspInputs``).  The program solves its
    QP twice: after pass 1 (the masses its 'after' columns of Tables 5.2-5.7 are computed
    with in pass 2) and after pass 2 (the masses of Table 5.1).  ``solution`` (9 masses,
    lb*s^2/in), if given, replaces both answers (D055).  Returns ``table`` (37 x 12, columns
    CSSP_COLUMNS, rows crank 0..360 deg), ``solution`` (9: the masses behind the 'after'
    columns, the first QP's answer; fed back, it gives the same 'after' columns), ``solution_table51``
    (9: Table 5.1's, the second QP's answer; D151), ``inertia`` (6 x 2: before, after; rows
    INERTIA_ROWS), ``hessian`` (9 x 9, h = 2*OF of the first QP, REAL*4 as QPROG gets it),
    ``diag``, and ``positions`` (2 passes x 37 crank angles x theta2, eta2, theta3, eta3 in
    rad, s4 in in: the Newton's converged joint variables, D053).
    """
    p = slider_crank(a1, a2, a4, alpha4_deg, s1, rpm)
    cssp_speed(p["rpm"])
    sol_in = np.zeros(9, dtype=np.float32) if solution is None else masses("solution", solution).astype(np.float32)
    qout = np.full((5, 37, 2), np.nan, order="F")      # NaN where the program computes no position
    with FORTRAN_LOCK:
        _f.qpwarn_get(1)                                   # clear QPROG's REAL*4 count (D161)
        table, sol51, inert, hout, diag, istat, fail_deg, qout, sol = _f.cssp(
            p["a1"], p["a2"], p["a4"], p["alpha4_deg"], p["s1"], p["rpm"], int(solution is not None), sol_in, qout)
        unsure, worst = _f.qpwarn_get(1)
    positions = qout.transpose(2, 1, 0)
    refuse_singular_position(np.tile(10.0 * np.arange(37), 2),
                             listing_condition(positions[..., 0], positions[..., 1], positions[..., 2]))
    if istat == 1:
        raise ConvergenceError("CSSP: Newton-Raphson failed after 150 iterations", float(fail_deg))
    if istat == 2:
        raise SingularPositionError("CSSP: INVERSE met a zero pivot (MATRIX IS SINGULAR)", float(fail_deg))
    if istat == 3:
        raise QPError("CSSP: QPROG could not solve the balancing problem")
    bad = ~np.isfinite(table).all(axis=1)
    if bad.any():
        raise SingularPositionError("CSSP: a non-finite value in the tables",
                                    float(10 * np.argmax(bad)))
    if unsure:
        warnings.warn(_balance.precision_warning(float(worst)), stacklevel=2)
    return {"table": table, "solution": sol.astype(np.float64), "solution_table51": sol51.astype(np.float64),
            "inertia": inert,
            "hessian": hout.astype(np.float64), "diag": float(diag),
            "positions": positions.copy()}


def inverse(s) -> np.ndarray:
    """The printed INVERSE: 5 x 5 Gauss-Jordan, row exchange only on an exactly zero pivot.

    Raises ``SingularPositionError`` where the listing prints MATRIX IS SINGULAR and STOPs.
    """
    s = finite_matrix("INVERSE's argument", s, (5, 5))
    with FORTRAN_LOCK:
        b = _f.inverse(np.asfortranarray(s))
        singular = _f.inverr_get()
    if singular:
        raise SingularPositionError("INVERSE: MATRIX IS SINGULAR")
    if not np.all(np.isfinite(b)):
        raise SingularPositionError("INVERSE: a pivot under- or overflowed (non-finite inverse)")
    return b


def qprog(h, g, a=None, b=None, neq: int = 0) -> dict:
    """Our QPROG (IMSL's calling convention, Goldfarb-Idnani; registers D050, D160-D163).

    Minimizes g'x + x'Hx/2 subject to a[:neq] x = b[:neq] and a[neq:] x >= b[neq:].
    Returns ``sol``, ``diag`` (0 where H is positive definite to its rounding; else the
    multiple of I added to H, and ``regularized`` True: the answer is the regularized
    problem's, with a ``PrecisionWarning``), ``active`` (0-based constraint indices),
    ``multipliers`` and ``condition``; QPError for inconsistent constraints, an unbounded
    problem, the iteration limit, a non-finite answer, or one that would miss a row by more
    than the method's rounding.  The contract in full: port.rahman1996.qprog's ``qprog``.
    """
    h, g, a, b, neq = qp_arguments(h, g, a, b, neq, 60, 200)
    n = g.size
    a_f = np.asfortranarray(np.vstack([a, np.zeros((1, n))]))        # LDA >= 1
    b_f = np.concatenate([b, [0.0]])
    with FORTRAN_LOCK:
        diag, sol, nact, iact, lam = _f.dqprog(b.size, neq, a_f, b_f, g, np.asfortranarray(h))
        status = int(_f.qpstat_get())
        condition = float(_f.qpcond_get())
    if status == 3:
        raise ValueError("QPROG: bad arguments")
    result = answer(status, diag, sol, iact[:nact] - 1, lam[:nact], condition)
    warning = precision_warning(h, result)
    if warning is not None:
        warnings.warn(warning, stacklevel=2)
    return result
