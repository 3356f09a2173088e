"""Our QPROG stand-in (legacy/src/imsl_qprog.f, DQPROG; register D050), ported: ``qprog``.

Minimises g'x + x'Hx/2 subject to a[:neq] x = b[:neq] and a[neq:] x >= b[neq:] by the
Goldfarb-Idnani dual active-set method as DQPROG writes it.  Only the diagonal and the lower
triangle of H are read, as in the FORTRAN.

Every operation is DQPROG's (with QPCHSL and QPGAUS) in DQPROG's order: sums run in the
FORTRAN's loop order from the same start, the comparisons and tolerances are its own, MAX
and MIN pick what gfortran's maxsd/minsd pick, and numba compiles without fastmath (no
fused multiply-add, as the FORTRAN is built with -ffp-contract=off).  The result equals
``linkrepro.legacy.rahman1996.qprog`` bit for bit, warnings included
(tests/rahman1996/test_differential_qprog.py).

The contract (tests/rahman1996/test_qprog_contract.py, against 40-digit KKT solves, SciPy
and numpy):

- **Definite H, as given** (D160).  Where the Cholesky factorization of H has every pivot at
  least n eps max|H_ij| and kappa = tr(H) tr(H^-1) (>= cond(H)) is at most 1/(n eps), no
  perturbation of the size of H's rounding makes it singular: H is solved as given, DIAG =
  0, to its conditioning (condition 1e8..1e14: errors within 0.3 cond eps, measured).
  There QPRFN refines the stationarity as well as the active rows, a row whose multiplier
  it leaves negative is dropped, and a new row's normal independent of the active ones in
  the plain sense (``_independent``) is stepped to even where ZN lies below 1e3 eps ZR.
- **DIAG** (D050).  Else H + DIAG I is used, DIAG found by the rule of statements 5-130
  (``hessian_shift``: from 0, raised by the shortfall where a pivot falls below sqrt(eps)
  max|H_ij|; a shortfall below DIAG's last bit takes the next number up): the answer is the
  regularized problem's, min g'x + x'(H + DIAG I)x/2.  ``regularized`` says so and the
  public ``qprog`` warns ``PrecisionWarning`` naming DIAG; ``solve`` does not, for a caller
  that reads the field (the CSSP, whose H is singular by design: D057).
- **What is warned** (D160, D161).  ``condition`` = tr(H) tr(P H P), P the inverse of
  H + DIAG I on the directions the final active rows leave free: >= the condition of the
  answer on the directions H determines (H's null directions, DIAG decides them, and those
  the active rows pin count for nothing).  ``relative_error(h, result, unit)`` =
  condition (unit + DIAG/tr H) bounds the answer's relative error there, ``unit`` the
  rounding of H's data; ``qprog`` warns where it reaches 1 (unit eps), and the REAL*4 entry
  counts the calls where it does with unit 2**-24 (COMMON /QPWARN/; the CSSP's warning).
- **Rows** (D050, D162).  Every row holds at ``sol`` to GTOL = eps (1e3 + 8 kappa) of
  |a_i| |sol| + |b_i|, kappa = tr(H + DIAG I) tr((H + DIAG I)^-1) (``_kappa``): the method is
  not backward stable and its answers may miss rows by ~30 eps kappa, so no sol is returned
  that misses one by more (``MISSES_MESSAGE``).  Rows are tested relative to that size
  (``_row``), z = 0 unless ZN > 1e3 eps ZR (ZR the size of ZN's terms), a row that depends
  on the active ones and holds to GTOL (a repeated row, 0 x = 0, an inequality repeating an
  active equality) is held: not added, re-examined when sol moves, not in ``active``.
- **Unbounded** (D163).  Where DIAG > 0, a direction from the regularized answer (of the
  problem, then of its recession problem, b = 0) along which every row stays feasible and
  the objective falls without bound, to sqrt(eps) of the problem's scale (``_unbounded``):
  QPError 'unbounded'.  A convex (semidefinite) H's is found so; an indefinite H's only where
  the regularized answer moves along a direction of negative curvature (else the answer is
  the regularized problem's, with the DIAG warning).
- **Errors**.  QPError: inconsistent constraints, no solution within GTOL, unbounded, the
  iteration limit, a non-finite answer (overflow); ValueError/TypeError for bad arguments
  (shapes, sizes, non-finite h, g, a or b: ``linkrepro.checks``).

Scale: DQPROG solves the problem in its own units (``_dqprog``): each row of a and b scaled
by a power of two to a largest entry in [1, 2), H and g by a power of four to a largest
|H_ij| in [1, 4), QPSOLV (``_solve``) run on that, DIAG and the multipliers scaled back: a
copy scaled by such powers gives the same bits (D050).  Work arrays are sized by the
constraints (numerically dependent normals can enter before QPGAUS finds M singular).

Units are the caller's; in the CSSP balancing problem x holds the nine point masses
(lb*s^2/in) and H is twice the objective's quadratic form summed over the cycle.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
from numba import njit

from ...checks import finite_matrix, qp_arguments
from ...errors import PrecisionWarning, QPError

#: DQPROG's PARAMETERs: at most 60 variables and 200 constraints
MAXV, MAXC = 60, 200
#: status codes, COMMON /QPSTAT/ (MISSES: QPSOLV's last guard, D050; UNBOUNDED: D163)
SOLVED, INCONSISTENT, ITERATION_LIMIT, BAD_ARGUMENTS, MISSES, UNBOUNDED = 0, 1, 2, 3, 4, 5
#: QPError's message for status 4
MISSES_MESSAGE = ("QPROG: the solution found misses a constraint by more than the method's rounding "
                  "(the constraints are inconsistent within rounding, or the problem too ill-conditioned)")
#: QPError's message for each failing status, in both faces
STATUS_MESSAGES = {
    INCONSISTENT: "QPROG: the constraints are inconsistent",
    ITERATION_LIMIT: "QPROG: iteration limit reached",
    MISSES: MISSES_MESSAGE,
    UNBOUNDED: ("QPROG: the problem is unbounded below (a direction along which every constraint stays "
                "feasible and the objective falls without bound, to sqrt(eps) of its terms; D163)"),
}
#: EPSILON(1.0D0)
EPS = float(np.finfo(np.float64).eps)
#: the unit roundoff of REAL*4, 0.5*EPSILON(1.0E0): the precision of the REAL*4 entry's data (D161)
REAL4_UNIT = 2.0 ** -24


@njit(cache=True)
def _max(a, b):
    """gfortran's MAX as compiled here (maxsd): a if a > b else b."""
    return a if a > b else b


@njit(cache=True)
def _hmax(h):
    """QPHMAX: the largest |H_ij| of the lower triangle (the part QPROG reads)."""
    big = 0.0
    for j in range(h.shape[0]):                           # DO 20
        for i in range(j, h.shape[0]):                    # DO 10
            big = _max(big, abs(h[i, j]))
    return big


@njit(cache=True)
def _cholesky_shift(h, low):
    """Statements 5-130: L L' = H + DIAG*I.  First with DIAG = 0 and TINY = n eps max |H_ij|
    (lower triangle), the rounding of a pivot: where every pivot passes and kappa =
    tr(H) tr(H^-1) (``_kappa``, >= cond(H)) stays within 1/(n eps), no perturbation of H of
    the size of its rounding makes it singular: H is positive definite to its rounding and
    DIAG = 0 (D160).  Else the DIAG rule, unchanged: from DIAG = 0, DIAG raised where a pivot
    falls below TINY = sqrt(eps) max |H_ij|.

    Fills ``low`` (L, lower triangle) and returns DIAG.  A shortfall below DIAG's last bit
    takes the next number up (DNEW = NEAREST(DIAG, 1.0D0)).
    """
    n = h.shape[0]
    scale = _hmax(h)
    if scale == 0.0:
        scale = 1.0
    definite = True
    tiny = float(n) * EPS * scale
    diag = 0.0
    while True:                                           # 100 CONTINUE
        restart = False
        for j in range(n):                                # DO 130
            pivot = h[j, j] + diag
            for k in range(j):                            # DO 110: - L(J,K)**2
                pivot = pivot - low[j, k] * low[j, k]
            if pivot < tiny and definite:                 # not definite to its rounding: the DIAG rule
                definite = False
                tiny = math.sqrt(EPS) * scale
                restart = True
                break                                     # GO TO 100
            if pivot < tiny:
                raised = diag + (tiny - pivot)
                if raised <= diag:
                    raised = np.nextafter(diag, np.inf)
                diag = raised
                restart = True
                break                                     # GO TO 100
            low[j, j] = math.sqrt(pivot)
            for i in range(j + 1, n):                     # DO 125
                s = h[i, j]
                for k in range(j):                        # DO 120
                    s = s - low[i, k] * low[j, k]
                low[i, j] = s / low[j, j]
        if not restart and definite and float(n) * EPS * _kappa(h, 0.0, low, np.empty(n), np.empty(n)) > 1.0:
            definite = False                              # kappa past 1/(n eps): the DIAG rule
            tiny = math.sqrt(EPS) * scale
            restart = True
        if not restart:
            return diag


@njit(cache=True)
def _chsl(low, rhs, x):
    """QPCHSL: solve (L L') X = RHS, forward then backward substitution."""
    n = low.shape[0]
    for i in range(n):                                    # DO 20
        s = rhs[i]
        for k in range(i):                                # DO 10
            s = s - low[i, k] * x[k]
        x[i] = s / low[i, i]
    for i in range(n - 1, -1, -1):                        # DO 40
        s = x[i]
        for k in range(i + 1, n):                         # DO 30
            s = s - low[k, i] * x[k]
        x[i] = s / low[i, i]


@njit(cache=True)
def _gaus(n, m, rhs, x):
    """QPGAUS: solve M X = RHS (first n rows and columns) by Gaussian elimination with
    partial pivoting; M and RHS are overwritten.  Returns INFO: 1 if M is singular."""
    big = 0.0
    for i in range(n):                                    # DO 5
        for j in range(n):                                # DO 4
            big = _max(big, abs(m[i, j]))
    for k in range(n):                                    # DO 40
        ip = k
        for i in range(k + 1, n):                         # DO 10
            if abs(m[i, k]) > abs(m[ip, k]):
                ip = i
        if abs(m[ip, k]) <= 1.0e-14 * big:
            return 1
        if ip != k:
            for j in range(n):                            # DO 15
                t = m[k, j]
                m[k, j] = m[ip, j]
                m[ip, j] = t
            t = rhs[k]
            rhs[k] = rhs[ip]
            rhs[ip] = t
        for i in range(k + 1, n):                         # DO 30
            t = m[i, k] / m[k, k]
            for j in range(k, n):                         # DO 20
                m[i, j] = m[i, j] - t * m[k, j]
            rhs[i] = rhs[i] - t * rhs[k]
    for i in range(n - 1, -1, -1):                        # DO 60
        t = rhs[i]
        for j in range(i + 1, n):                         # DO 50
            t = t - m[i, j] * x[j]
        x[i] = t / m[i, i]
    return 0


@njit(cache=True)
def _row(a, b, i, sol):
    """QPROW: (S, SIZE), S = a_i sol - b_i summed from -b_i in the variables' order and
    SIZE = |b_i| + sum |a_ij sol_j|, the scale of its rounding."""
    s = -b[i]
    size = abs(b[i])
    for j in range(sol.shape[0]):                         # DO 10
        s = s + a[i, j] * sol[j]
        size = size + abs(a[i, j] * sol[j])
    return s, size


@njit(cache=True)
def _nmat(low, a, sgn, iact, nact, gn, m, e):
    """QPNMAT: for the active normals n_k = sgn a[iact[k]], gn[k] = H^-1 n_k (H = L L') and
    M = N'H^-1N; ``e`` is work space."""
    nvar = low.shape[0]
    for k in range(nact):                                 # DO 20
        jj = iact[k]
        for j in range(nvar):                             # DO 10
            e[j] = sgn[jj] * a[jj, j]
        _chsl(low, e, gn[k])
    for i in range(nact):                                 # DO 50
        ii = iact[i]
        for k in range(nact):                             # DO 40
            s = 0.0
            for j in range(nvar):                         # DO 30
                s = s + sgn[ii] * a[ii, j] * gn[k, j]
            m[i, k] = s


@njit(cache=True)
def _refine(h, g, diag, low, a, b, sgn, iact, nact, gtol, stol, sol, u, gn, m, rhs, r, w, e):
    """QPRFN: where an active row misses its bound by more than gtol of its size, or a
    component of the stationarity residual e = (H + DIAG I) sol + g - N u by more than stol of
    the size of its terms (D160: the steps' rounding, from far out where H is ill-conditioned;
    stol = 1e3 eps where H is solved as given, gtol where DIAG > 0, which leaves the CSSP's
    QPs as they were), at most two sweeps of refinement of the KKT system on the active set:
    sol += GN y - (H + DIAG I)^-1 e, u += y, (N'H^-1N) y = N'(H + DIAG I)^-1 e - (N'sol - b).
    Without a stationarity miss e is not used (sol += GN y, as D050 had it)."""
    nvar = sol.shape[0]
    for _ in range(2):                                    # DO 40 SWEEP
        off = False
        for k in range(nact):                             # DO 10
            s, size = _row(a, b, iact[k], sol)
            rhs[k] = -(sgn[iact[k]] * s)
            if abs(s) > gtol * size:
                off = True
        stationary = True
        for j in range(nvar):                             # DO 14
            s = g[j] + diag * sol[j]
            size = abs(g[j]) + abs(diag * sol[j])
            for i in range(nvar):                         # DO 12
                hji = h[j, i] if j >= i else h[i, j]
                s = s + hji * sol[i]
                size = size + abs(hji * sol[i])
            for k in range(nact):                         # DO 13
                t = sgn[iact[k]] * a[iact[k], j] * u[k]
                s = s - t
                size = size + abs(t)
            e[j] = s
            if abs(s) > stol * size:
                stationary = False
        if not off and stationary:
            return
        _nmat(low, a, sgn, iact, nact, gn, m, w)
        if not stationary:
            _chsl(low, e, w)                              # W = (H + DIAG I)^-1 E
            for k in range(nact):                         # DO 18
                s = rhs[k]
                for j in range(nvar):                     # DO 17
                    s = s + sgn[iact[k]] * a[iact[k], j] * w[j]
                rhs[k] = s
        if _gaus(nact, m, rhs, r) != 0:
            return
        for j in range(nvar):                             # DO 30
            s = sol[j]
            if not stationary:
                s = s - w[j]
            for k in range(nact):                         # DO 20
                s = s + gn[k, j] * r[k]
            sol[j] = s
        for k in range(nact):                             # DO 35
            u[k] = u[k] + r[k]


@njit(cache=True)
def _independent(a, iact, nact, p, gram, rhs, c):
    """QPINDP (D160): is row p's normal independent of the active normals, in the plain
    (Euclidean) sense?  The least-squares residual rho = n+ - N c, (N'N) c = N'n+, stands in
    some component above 1e3 eps of the largest size of its terms (|n+_j| + sum |N_jk c_k|);
    not where N'N is singular.  Where H is ill-conditioned ZN falls below 1e3 eps ZR for
    independent rows too (ZR grows with cond(H), ZN with the reduced problem's), while a
    dependent normal (a repeated or summed row, more rows than variables) leaves rho at its
    rounding.  ``gram``, ``rhs``, ``c``: work."""
    nvar = a.shape[1]
    for i in range(nact):                                 # DO 20
        for k in range(nact):                             # DO 10
            s = 0.0
            for j in range(nvar):                         # DO 5
                s = s + a[iact[i], j] * a[iact[k], j]
            gram[i, k] = s
        s = 0.0
        for j in range(nvar):                             # DO 15
            s = s + a[iact[i], j] * a[p, j]
        rhs[i] = s
    if _gaus(nact, gram, rhs, c) != 0:
        return False
    big = 0.0
    scale = 0.0
    for j in range(nvar):                                 # DO 40
        s = a[p, j]
        size = abs(a[p, j])
        for k in range(nact):                             # DO 30
            t = a[iact[k], j] * c[k]
            s = s - t
            size = size + abs(t)
        big = _max(big, abs(s))
        scale = _max(scale, size)
    return big > 1.0e3 * EPS * scale


@njit(cache=True)
def _kappa(h, diag, low, e, y):
    """QPKAPP: tr(H + DIAG I) tr((H + DIAG I)^-1), at least the condition number of
    H + DIAG I and at most n^2 times it; ``e`` and ``y`` are work space."""
    n = low.shape[0]
    th = 0.0
    ti = 0.0
    for j in range(n):                                    # DO 20
        th = th + (h[j, j] + diag)
        for i in range(n):                                # DO 10
            e[i] = 0.0
        e[j] = 1.0
        _chsl(low, e, y)
        ti = ti + y[j]
    return th * ti


@njit(cache=True)
def _less_gn(gn, nact, r, y):
    """QPLGN: y = y - GN r over the first nact columns of GN."""
    for i in range(y.shape[0]):                           # DO 20
        s = y[i]
        for k in range(nact):                             # DO 10
            s = s - gn[k, i] * r[k]
        y[i] = s


@njit(cache=True)
def _hv(h, x, y):
    """QPHV: y = H x, H read from its lower triangle."""
    n = x.shape[0]
    for i in range(n):                                    # DO 20
        s = 0.0
        for j in range(n):                                # DO 10
            if i >= j:
                s = s + h[i, j] * x[j]
            else:
                s = s + h[j, i] * x[j]
        y[i] = s


@njit(cache=True)
def _condition(h, low, a, sgn, iact, nact, gn, m, rhs, r, y, e):
    """QPCOND (D160): tr(H) tr(P H P), P = (H + DIAG I)^-1 - GN M^-1 GN' the inverse of
    H + DIAG I on the directions the active rows leave free.  A direction of H's of
    eigenvalue lambda counts lambda/(lambda + DIAG)^2: 1/lambda where H determines it,
    nothing on H's null directions (DIAG decides those) nor on those the active rows pin.
    It bounds the relative change of sol per relative change of H on the directions H
    determines; with DIAG = 0 and no active row it is tr(H) tr(H^-1).  Where M is singular
    (numerically dependent active rows), P = (H + DIAG I)^-1.  Free of units."""
    nvar = low.shape[0]
    size = max(nact, 1)
    mc = np.empty((size, size))
    _nmat(low, a, sgn, iact, nact, gn, mc, e)
    project = nact > 0
    th = 0.0
    tr = 0.0
    for j in range(nvar):                                 # DO 60
        th = th + h[j, j]
        for i in range(nvar):                             # DO 10
            e[i] = 0.0
        e[j] = 1.0
        _chsl(low, e, y)
        if project:
            for k in range(nact):                         # DO 20
                rhs[k] = gn[k, j]
                for i in range(nact):                     # DO 15
                    m[i, k] = mc[i, k]
            project = _gaus(nact, m, rhs, r) == 0
        if project:
            _less_gn(gn, nact, r, y)
        _hv(h, y, e)
        for i in range(nvar):                             # DO 50
            tr = tr + y[i] * e[i]
    return th * tr


@njit(cache=True)
def _unbounded(h, g, a, neq, low, sgn, iact, nact, sol, gn, m, rhs, r, d, e):
    """QPUNBD (D163): is the problem unbounded below?  ``sol`` is a regularized answer, of the
    problem or of its recession problem (b = 0, whose answer does not depend on b's scale):
    far out along H's null directions if the objective falls along a feasible one.  Two
    directions from it, each damping H's range by DIAG/(lambda + DIAG): d = P sol, P =
    (H + DIAG I)^-1 - GN M^-1 GN' the inverse on the directions the active rows leave free
    (as ``_condition``), which leaves those rows where they are; and d = sol - (H + DIAG I)^-1
    H sol, which may leave an active inequality (as a direction of negative curvature does).
    Either certifies it (``_ray``).  ``gn``, ``m``, ``rhs``, ``r``, ``d``, ``e``: work."""
    nvar = sol.shape[0]
    _chsl(low, sol, d)
    free = True
    if nact > 0:
        _nmat(low, a, sgn, iact, nact, gn, m, e)
        for k in range(nact):                             # DO 5
            s = 0.0
            for j in range(nvar):                         # DO 4
                s = s + gn[k, j] * sol[j]
            rhs[k] = s
        free = _gaus(nact, m, rhs, r) == 0
        if free:
            _less_gn(gn, nact, r, d)
    if free and _ray(h, g, a, neq, d, e):
        return True
    _hv(h, sol, e)
    _chsl(low, e, d)
    for j in range(nvar):                                 # DO 9
        d[j] = sol[j] - d[j]
    return _ray(h, g, a, neq, d, e)


@njit(cache=True)
def _ray(h, g, a, neq, d, e):
    """QPRAY (D163): does d certify that the problem is unbounded below?  Every row stays
    feasible along d (a_i d = 0 for an equality, >= 0 for an inequality) and the objective
    falls without bound along it, H d = 0 and g'd < 0, or d'H d < 0; each to tau = sqrt(eps)
    of the problem's scale along d, d taken to max|d_j| = 1 first (a_i d of sum_j |a_ij|,
    g'd of sum_j |g_j|, H d of max|H_ij|, d'H d of max|H_ij| d'd): the DIAG rule's own level,
    which takes a curvature below it for none.  ``e``: work."""
    nvar, ncon = d.shape[0], a.shape[0]
    tau = math.sqrt(EPS)
    dmax = 0.0
    for j in range(nvar):                                 # DO 5
        dmax = _max(dmax, abs(d[j]))
    if dmax == 0.0:
        return False
    dd = 0.0
    gd = 0.0
    gs = 0.0
    for j in range(nvar):                                 # DO 10
        d[j] = d[j] / dmax
        dd = dd + d[j] * d[j]
        gd = gd + g[j] * d[j]
        gs = gs + abs(g[j])
    hmax = _hmax(h)
    _hv(h, d, e)
    flat = True
    curv = 0.0
    for i in range(nvar):                                 # DO 20
        if abs(e[i]) > tau * hmax:
            flat = False
        curv = curv + d[i] * e[i]
    if not ((flat and gd < -tau * gs) or curv < -tau * hmax * dd):
        return False
    for i in range(ncon):                                 # DO 40
        s = 0.0
        size = 0.0
        for j in range(nvar):                             # DO 30
            s = s + a[i, j] * d[j]
            size = size + abs(a[i, j])
        if i < neq:
            s = -abs(s)
        if s < -tau * size:
            return False
    return True


@njit(cache=True)
def _dqprog(h, g, a, b, neq):
    """DQPROG on validated arguments: (status, DIAG, SOL, NACT, IACT, ALAMDA, QCOND).

    QPSOLV (``_solve``) on the problem in its own units: row i of a and b times 2**e_i, so
    that its largest |a_ij| is in [1, 2); H and g times 4**(-k), so that the largest |H_ij|
    of the lower triangle (of g where H = 0) is in [1, 4).  Powers of two, so the scaled
    numbers hold the same digits; DIAG and the multipliers are scaled back.
    """
    nvar, ncon = g.shape[0], b.shape[0]
    a_s, b_s, rows = np.empty((ncon, nvar)), np.empty(ncon), np.zeros(ncon, dtype=np.int64)
    for i in range(ncon):                                 # DO 20
        big = 0.0
        for j in range(nvar):                             # DO 10
            big = _max(big, abs(a[i, j]))
        if big > 0.0:
            rows[i] = 1 - math.frexp(big)[1]              # 1 - EXPONENT(BIG)
        for j in range(nvar):                             # DO 15
            a_s[i, j] = math.ldexp(a[i, j], rows[i])      # SCALE(A(I,J), IRS(I))
        b_s[i] = math.ldexp(b[i], rows[i])
    h_s, g_s, kh = _scaled_objective(h, g)
    status, diag, sol, nact, iact, alamda, cond = _solve(h_s, g_s, a_s, b_s, neq, False)
    if status == SOLVED and diag > 0.0:
        # D163: the recession problem (b = 0) decides whether it is unbounded below
        if _solve(h_s, g_s, a_s, np.zeros(ncon), neq, True)[0] == UNBOUNDED:
            status = UNBOUNDED
    diag = math.ldexp(diag, 2 * kh)
    for k in range(nact):                                 # DO 50
        alamda[k] = math.ldexp(alamda[k], 2 * kh + rows[iact[k]])
    return status, diag, sol, nact, iact, alamda, cond


@njit(cache=True)
def _scaled_objective(h, g):
    """DQPROG's H and g times 4**(-kh), the largest |H_ij| of the lower triangle (of g where
    H = 0) in [1, 4): (H_s, g_s, kh), H_s's upper triangle zero."""
    nvar = g.shape[0]
    big = _hmax(h)
    if big == 0.0:
        for j in range(nvar):                             # DO 35
            big = _max(big, abs(g[j]))
    kh = 0
    if big > 0.0:
        kh = math.floor(0.5 * (math.frexp(big)[1] - 1))
    g_s, h_s = np.empty(nvar), np.zeros((nvar, nvar))
    for j in range(nvar):                                 # DO 45
        g_s[j] = math.ldexp(g[j], -2 * kh)
        for i in range(j, nvar):                          # DO 40
            h_s[i, j] = math.ldexp(h[i, j], -2 * kh)
    return h_s, g_s, kh


@njit(cache=True)
def _shift(h, g):
    """DIAG as DQPROG finds it: the DIAG rule on the scaled H, scaled back."""
    h_s, g_s, kh = _scaled_objective(h, g)
    low = np.zeros(h_s.shape)
    return math.ldexp(_cholesky_shift(h_s, low), 2 * kh)


@njit(cache=True)
def _solve(h, g, a, b, neq, recession):
    """QPSOLV, the Goldfarb-Idnani method on the scaled problem: (status, DIAG, SOL, NACT,
    IACT, ALAMDA, QCOND).  Where DIAG > 0, UNBOUNDED where ``_unbounded`` certifies it from
    SOL (D163); ``recession``: this is the recession problem (b = 0), solved for that alone.

    Indices are 0-based (constraint i is the FORTRAN's I = i+1; P = 0 is p = -1).
    ``gn[k]`` holds the column GN(.,K).  Work arrays are sized by NCON (see the module
    docstring), the FORTRAN's by MAXV.  ``held[i]``: row i holds and depends on the
    active rows; not added, and not picked again until sol moves (D050, D162).
    """
    nvar, ncon = g.shape[0], b.shape[0]
    low = np.zeros((nvar, nvar))
    sol = np.zeros(nvar)
    iact = np.zeros(ncon, dtype=np.int32)
    alamda = np.zeros(ncon)
    nact = 0
    diag = _cholesky_shift(h, low)
    w = np.empty(nvar)
    z = np.empty(nvar)
    # how far a solved sol may miss a row, relative to its size: 1e3 eps, and 8 eps kappa
    # for the rounding of the method where H + DIAG I is ill-conditioned (D050)
    gtol = EPS * (1.0e3 + 8.0 * _kappa(h, diag, low, w, z))
    # how far the stationarity may miss before QPRFN refines it (D160)
    stol = gtol
    if diag == 0.0:
        stol = 1.0e3 * EPS
    # ---- unconstrained minimum: SOL = -(H+DIAG I)^-1 G (140)
    rhs = np.empty(max(nvar, ncon))
    for i in range(nvar):                                 # DO 140
        rhs[i] = -g[i]
    _chsl(low, rhs, sol)
    active = np.zeros(ncon, dtype=np.bool_)
    held = np.zeros(ncon, dtype=np.bool_)
    sgn = np.empty(ncon)
    enorm = np.empty(ncon)
    for i in range(ncon):                                 # DO 150
        active[i] = False
        sgn[i] = 1.0
        s = 0.0
        for j in range(nvar):                             # DO 145: + A(I,J)**2
            s = s + a[i, j] * a[i, j]
        enorm[i] = _max(math.sqrt(s), 1.0)
    gn = np.empty((ncon, nvar))
    m = np.empty((ncon, ncon))
    r = np.empty(ncon)
    u = np.empty(ncon)
    c = np.empty(ncon)
    maxit = 50 * (ncon + nvar) + 100
    it = 0
    while True:
        # ---- outer loop: pick a violated constraint P (200)
        it += 1
        if it > maxit:
            return ITERATION_LIMIT, diag, sol, nact, iact, alamda, 0.0
        p = -1
        smin = 0.0
        for i in range(ncon):                             # DO 210
            if active[i] or held[i]:
                continue
            s, size = _row(a, b, i, sol)
            if i < neq:
                # an equality enters first, turned so that it is violated (GO TO 220)
                sgn[i] = 1.0
                if s > 0.0:
                    sgn[i] = -1.0
                p = i
                smin = sgn[i] * s
                break
            tol = 1.0e3 * EPS * size                      # violated beyond its rounding
            if s < -tol and s / enorm[i] < smin:
                p = i
                smin = s / enorm[i]
        if p < 0:
            break                                         # GO TO 900
        uplus = 0.0                                       # 220
        while True:
            # ---- inner loop: step towards satisfying constraint P (300)
            it += 1
            if it > maxit:
                return ITERATION_LIMIT, diag, sol, nact, iact, alamda, 0.0
            # W = H^-1 N+, GN(.,K) = H^-1 N_K for the active normals
            for j in range(nvar):                         # DO 305
                rhs[j] = sgn[p] * a[p, j]
            _chsl(low, rhs, w)
            _nmat(low, a, sgn, iact, nact, gn, m, rhs)
            # R = (N'H^-1N)^-1 N'W ; Z = W - GN R
            if nact > 0:
                for i in range(nact):                     # DO 340
                    ii = iact[i]
                    s = 0.0
                    for j in range(nvar):                 # DO 330
                        s = s + sgn[ii] * a[ii, j] * w[j]
                    rhs[i] = s
                if _gaus(nact, m, rhs, r) != 0:
                    return INCONSISTENT, diag, sol, nact, iact, alamda, 0.0
            zn = 0.0
            zr = 0.0                                      # the scale of ZN's rounding
            for j in range(nvar):                         # DO 360
                s = w[j]
                size = abs(w[j])
                for k in range(nact):                     # DO 350
                    s = s - gn[k, j] * r[k]
                    size = size + abs(gn[k, j] * r[k])
                z[j] = s
                zn = zn + z[j] * sgn[p] * a[p, j]
                zr = zr + size * abs(a[p, j])
            # partial step T1 (a dual variable reaches zero), full step T2
            t1 = -1.0
            kdrop = -1
            for k in range(nact):                         # DO 370
                if iact[k] < neq:
                    continue
                if r[k] > EPS:                            # r is free of units
                    t = u[k] / r[k]
                    if kdrop < 0 or t < t1:
                        t1 = t
                        kdrop = k
            s, size = _row(a, b, p, sol)
            s = sgn[p] * s
            # z = 0 (n+ depends on the active normals) unless ZN stands above its rounding
            t2 = -1.0
            if zn > 1.0e3 * EPS * zr:
                t2 = -(s / zn)
            elif zn > 0.0 and nact > 0 and _independent(a, iact, nact, p, m, rhs, c):
                t2 = -(s / zn)                            # D160: ZN below its rounding's scale, n+ independent
            if t2 < 0.0 and uplus == 0.0 and -s <= gtol * size:
                held[p] = True                            # a dependent row that holds to GTOL (D162)
                break                                     # GO TO 200
            if t2 < 0.0 and kdrop < 0:
                # no step can satisfy constraint P: the constraints are inconsistent
                return INCONSISTENT, diag, sol, nact, iact, alamda, 0.0
            if t2 < 0.0:
                t = t1                                    # dual step only, then drop
            elif kdrop < 0:
                t = t2
            else:
                t = t2 if t2 < t1 else t1                 # MIN(T1, T2) as minsd picks
            if t2 >= 0.0:
                for j in range(nvar):                     # DO 380
                    sol[j] = sol[j] + t * z[j]
                for i in range(ncon):                     # DO 382
                    held[i] = False
            for k in range(nact):                         # DO 385
                u[k] = u[k] - t * r[k]
            uplus = uplus + t
            if t2 >= 0.0 and (kdrop < 0 or t2 <= t1):
                # full step: P joins the active set
                iact[nact] = p
                u[nact] = uplus
                nact += 1
                active[p] = True
                _refine(h, g, diag, low, a, b, sgn, iact, nact, gtol, stol, sol, u, gn, m, rhs, r, w, z)
                while diag == 0.0:
                    # D160: an inequality's multiplier the refinement left negative: drop that
                    # row (the method keeps u >= 0) and refine on the rest
                    kdrop = -1
                    t = 0.0
                    for k in range(nact):                 # DO 387
                        if iact[k] >= neq and u[k] < t:
                            t = u[k]
                            kdrop = k
                    if kdrop < 0:
                        break
                    active[iact[kdrop]] = False
                    for k in range(kdrop, nact - 1):      # DO 388
                        iact[k] = iact[k + 1]
                        u[k] = u[k + 1]
                    nact -= 1
                    _refine(h, g, diag, low, a, b, sgn, iact, nact, gtol, stol, sol, u, gn, m, rhs, r, w, z)
                break                                     # GO TO 200
            # partial step: drop the active constraint KDROP, stay with P
            active[iact[kdrop]] = False
            for k in range(kdrop, nact - 1):              # DO 390
                iact[k] = iact[k + 1]
                u[k] = u[k + 1]
            nact -= 1                                     # GO TO 300
    # ---- solved: the last guard (905), then the multipliers in the constraints' sense (910)
    for i in range(ncon):
        s, size = _row(a, b, i, sol)
        if i < neq:
            s = -abs(s)
        if s < -gtol * size:
            return MISSES, diag, sol, nact, iact, alamda, 0.0
    if diag > 0.0 and _unbounded(h, g, a, neq, low, sgn, iact, nact, sol, gn, m, rhs, r, w, z):   # D163
        return UNBOUNDED, diag, sol, nact, iact, alamda, 0.0
    if recession:
        return SOLVED, diag, sol, nact, iact, alamda, 0.0
    cond = _condition(h, low, a, sgn, iact, nact, gn, m, rhs, r, w, z)   # D160
    for k in range(nact):                                 # DO 910
        alamda[k] = sgn[iact[k]] * u[k]
    return SOLVED, diag, sol, nact, iact, alamda, cond


def hessian_shift(h, g=None) -> float:
    """DIAG: the multiple of I that QPROG adds to H for min g'x + x'Hx/2 (g, default 0, sets
    the scale only where H = 0): 0 where H is positive definite to its rounding (every
    Cholesky pivot at least n eps max|H_ij|, D160), else the DIAG rule of statements 5-130
    on the scaled H, as ``qprog`` finds it (its answer's ``diag``, whatever the constraints).
    """
    h = finite_matrix("h", h)
    h, g, _, _, _ = qp_arguments(h, np.zeros(len(h)) if g is None else g, None, None, 0, MAXV, MAXC)
    return float(_shift(np.ascontiguousarray(h), g))


def answer(status: int, diag: float, sol, active, multipliers, condition: float) -> dict:
    """What QPROG returns, in both faces: QPError for a failing status (``STATUS_MESSAGES``) or
    a non-finite result, else the result dict (``qprog``'s docstring)."""
    if status in STATUS_MESSAGES:
        raise QPError(STATUS_MESSAGES[status])
    if not (np.isfinite(diag) and np.isfinite(condition) and np.all(np.isfinite(sol))
            and np.all(np.isfinite(multipliers))):
        raise QPError("QPROG: the solution or DIAG (the shift of H) is not finite (the arithmetic overflowed)")
    return {"sol": sol, "diag": float(diag), "active": active, "multipliers": multipliers,
            "regularized": bool(diag > 0.0), "condition": float(condition)}


def relative_error(h, result: dict, unit: float = EPS) -> float:
    """The bound on the answer's relative error on the directions H determines (D160, D161):
    condition * (unit + DIAG / tr(H)), ``unit`` the rounding of H's data (eps, or 2**-24 for
    the REAL*4 entry), DIAG / tr(H) the regularization's share (where tr(H) > 0).  The REAL*4
    entry's test, operation for operation as the FORTRAN (QPROG, statements after DQPROG)."""
    h = np.asarray(h, dtype=np.float64)
    trace = 0.0
    for j in range(h.shape[0]):                           # DO 35
        trace = trace + float(h[j, j])
    if trace > 0.0:
        return result["condition"] * (unit + result["diag"] / trace)
    return result["condition"] * unit


def precision_warning(h, result: dict) -> PrecisionWarning | None:
    """The warning ``qprog`` gives (both faces): where DIAG > 0 the answer is the regularized
    problem's; where the relative error bound (``relative_error``) reaches 1, no digit of it
    may be right.  None otherwise."""
    error = relative_error(h, result)
    if result["regularized"]:
        # where H (as QPROG reads it: its lower triangle) has negative curvature, neither the
        # trace product nor the bound means anything (H = -I gave "condition -2.5e-323")
        lower = np.tril(np.asarray(h, dtype=np.float64))
        curvature = np.linalg.eigvalsh(lower + np.tril(lower, -1).T)
        indefinite = curvature[0] < -len(curvature) * EPS * max(np.abs(curvature).max(), np.finfo(float).tiny)
        return PrecisionWarning(
            f"QPROG: H is not positive definite to its rounding (a Cholesky pivot below n eps max|H_ij|), so "
            f"H + DIAG*I was used with DIAG = {result['diag']:.3g}: the answer minimizes g'x + x'(H + DIAG*I)x/2, "
            "the regularized problem's, not H's (result['regularized'], register D160)"
            + (f"; H is indefinite (an eigenvalue {curvature[0]:.3g}): the regularized answer need not be "
               "near a minimizer of H's problem, which may be unbounded" if indefinite else ""),
            condition=None if indefinite else result["condition"], relative_error=None if indefinite else error)
    if error >= 1.0:
        return PrecisionWarning(
            f"QPROG: the answer's condition {result['condition']:.3g} passes what double precision carries: "
            "it may have no correct digit (register D160)", condition=result["condition"], relative_error=error)
    return None


def solve(h, g, a=None, b=None, neq: int = 0) -> dict:
    """``qprog`` without its warning, for a caller that reads ``regularized`` and
    ``condition`` itself (the CSSP, whose H is singular by design: D057)."""
    h, g, a, b, neq = qp_arguments(h, g, a, b, neq, MAXV, MAXC)
    status, diag, sol, nact, iact, lam, cond = _dqprog(np.ascontiguousarray(h), g, np.ascontiguousarray(a), b, neq)
    return answer(status, diag, sol, iact[:nact].copy(), lam[:nact].copy(), cond)


def qprog(h, g, a=None, b=None, neq: int = 0) -> dict:
    """Our QPROG, ported (IMSL's calling convention, Goldfarb-Idnani; register D050).

    Minimizes g'x + x'Hx/2 subject to a[:neq] x = b[:neq] and a[neq:] x >= b[neq:].
    Returns, as ``linkrepro.legacy.rahman1996.qprog``:

    - ``sol``; ``active`` (0-based constraint indices) and their ``multipliers``;
    - ``diag``: 0 where H is positive definite to its rounding (every Cholesky pivot at least
      n eps max|H_ij|): H is solved as given, a condition of 1e14 included.  Else the multiple
      of I added to H (the DIAG rule) and ``regularized`` is True: the answer is the
      regularized problem's, min g'x + x'(H + DIAG I)x/2, and a ``PrecisionWarning`` names
      DIAG (D160);
    - ``condition``: tr(H) tr(P H P), P the inverse of H + DIAG I on the directions the
      active rows leave free, >= the condition of the answer on the directions H determines
      (H's null directions, decided by DIAG, and the directions the active rows pin count for
      nothing).  ``relative_error`` (condition (eps + DIAG/tr H)) bounds the answer's relative
      error there; where it reaches 1, a ``PrecisionWarning``.

    Every row holds at ``sol`` to GTOL = eps (1e3 + 8 kappa) of |a_i| |sol| + |b_i|,
    kappa = tr(H + DIAG I) tr((H + DIAG I)^-1) >= its condition number.  A row that depends
    on the active ones and holds to GTOL (a repeated row, 0 x = 0, an inequality repeating an
    equality) is held, not added: not in ``active`` (D162).  QPError: the constraints are
    inconsistent; no solution meets them to GTOL; the problem is unbounded below (where DIAG
    > 0, certified by a direction ``_unbounded`` finds, D163); the iteration limit; a
    non-finite answer (overflow).  ValueError/TypeError for bad arguments (shapes, sizes,
    non-finite h, g, a or b).
    """
    result = solve(h, g, a, b, neq)
    warning = precision_warning(h, result)
    if warning is not None:
        warnings.warn(warning, stacklevel=2)
    return result
