"""The printed Newton-Raphson of the spatial slider-crank loop, compiled, in the listing's order.

Private: kernels on bare, unchecked numbers (a NaN gives a NaN or a failure status); users call
``rahman1996.listing.listing_pass`` and ``rahman1991.position.newton`` / ``positions``, which
check their arguments (``linkrepro.checks``).

Rahman's 1991 method (eqs. 5-26) and his 1996 program (Appendix B, statements 10 to the
DDOT block) solve the dual-number loop closure M1 L2 L3 M4 = I for q = (theta2, eta2,
theta3, eta3, s4) by DELTA = (A'A)^-1 A' V, position after position, each from the last
answer.  Where the first estimate is poor the iteration wanders for tens of steps over
radians before it settles, and there it is chaotic: a difference in the last bit of one
product can send it to another branch (measured while the port was built: numpy's matrix product,
which rounds through BLAS with fused multiply-adds, made the port and the legacy build
converge to different positions on a quarter of random geometries).  So every operation
here is the listing's, in the listing's order: MULTI and MULMAVEC sum left to right from
0.0, PRODUCTDUAL is MULTI, MULTI, MULTI, ADDMAT, INVERSE is the printed Gauss-Jordan with
its row exchanges; no sum is reassociated and no multiply-add fused (numba compiles
without fastmath, as the FORTRAN is built with -ffp-contract=off).  The result equals the
legacy build bit for bit (tests/test_differential_rahman.py).

Units: inch, radian, rad/s.  Status codes: OK, NOT_CONVERGED (150 steps, the listing's
STOP), SINGULAR (INVERSE met a zero pivot after every row exchange, its STOP).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

OK, NOT_CONVERGED, SINGULAR = 0, 1, 2
#: the listing's limit on Newton evaluations per position
MAX_ITERATIONS = 150


@njit(cache=True)
def multi(a, b):
    """MULTI: C(I,J) = C(I,J) + A(I,K)*B(K,J) for K = 1..N, from C(I,J) = 0.0."""
    rows, inner, cols = a.shape[0], a.shape[1], b.shape[1]
    c = np.empty((rows, cols))
    for i in range(rows):
        for j in range(cols):
            s = 0.0
            for k in range(inner):
                s = s + a[i, k] * b[k, j]
            c[i, j] = s
    return c


@njit(cache=True)
def mulmavec(a, v):
    """MULMAVEC: C(I) = C(I) + A(I,J)*B(J) for J = 1..M, from C(I) = 0.0."""
    out = np.empty(a.shape[0])
    for i in range(a.shape[0]):
        s = 0.0
        for j in range(a.shape[1]):
            s = s + a[i, j] * v[j]
        out[i] = s
    return out


@njit(cache=True)
def productdual(ar, ad, br, bd, cr, cd):
    """PRODUCTDUAL into (CR, CD): (AR + e AD)(BR + e BD) = AR BR + e (AD BR + AR BD), each
    product a MULTI (a sum from 0.0, k = 1..3 in turn), the dual part their ADDMAT."""
    for i in range(3):
        for j in range(3):
            real, left, right = 0.0, 0.0, 0.0
            for k in range(3):
                real = real + ar[i, k] * br[k, j]
                left = left + ad[i, k] * br[k, j]
                right = right + ar[i, k] * bd[k, j]
            cr[i, j], cd[i, j] = real, left + right


@njit(cache=True)
def listing_inverse(s):
    """The printed INVERSE of a 5 x 5 matrix: (B, singular).

    Gauss-Jordan without pivoting; a pivot exactly 0.0 is exchanged with the rows below it
    in turn (which then inverts the row-exchanged matrix, as printed); still 0.0 after the
    last exchange is singular (MATRIX IS SINGULAR, STOP).  Indices are the listing's: C is
    (6, 11) so that C[I, J] reads C(I,J).
    """
    c = np.zeros((6, 11))
    for i in range(1, 6):
        for j in range(1, 6):
            c[i, j] = s[i - 1, j - 1]
        c[i, i + 5] = 1.0
    b = np.zeros((5, 5))
    for k in range(1, 5):                         # pivots C(1,1) .. C(4,4)
        for other in range(k + 1, 6):             # exchange while the pivot is exactly zero
            if c[k, k] != 0.0:
                break
            for j in range(1 if k == 1 else k, 11):
                c[k, j], c[other, j] = c[other, j], c[k, j]
        if c[k, k] == 0.0:
            return b, True
        for i in range(k + 1, 6):                 # loops 61-74, 111-123, 161-172, 220
            for j in range(k + 1, k + 5):
                c[i, j] = c[i, j] - (c[i, k] * c[k, j] / c[k, k])
        for i in range(k + 1, 6):                 # statements 75, 114, 430, 190
            c[i, k + 5] = -c[i, k] / c[k, k]
    if c[5, 5] == 0.0:
        return b, True
    c[5, 10] = 1.0
    c[4, 10] = -c[4, 5] / c[5, 5]
    c[4, 9] = 1.0 - (c[5, 9] * c[4, 5] / c[5, 5])
    c[4, 8] = c[4, 8] - (c[5, 8] * c[4, 5] / c[5, 5])
    c[4, 7] = c[4, 7] - (c[5, 7] * c[4, 5] / c[5, 5])
    c[4, 6] = c[4, 6] - (c[5, 6] * c[4, 5] / c[5, 5])
    c[3, 10] = -c[3, 5] / c[5, 5]
    c[3, 9] = -c[5, 9] * c[3, 5] / c[5, 5]
    c[3, 8] = 1.0 - (c[5, 8] * c[3, 5] / c[5, 5])
    c[3, 7] = c[3, 7] - (c[5, 7] * c[3, 5] / c[5, 5])
    c[3, 6] = c[3, 6] - (c[5, 6] * c[3, 5] / c[5, 5])
    c[2, 10] = -c[2, 5] / c[5, 5]
    c[2, 9] = -c[5, 9] * c[2, 5] / c[5, 5]
    c[2, 8] = -c[5, 8] * c[2, 5] / c[5, 5]
    c[2, 7] = 1.0 - (c[5, 7] * c[2, 5] / c[5, 5])
    c[2, 6] = c[2, 6] - (c[5, 6] * c[2, 5] / c[5, 5])
    c[1, 10] = -c[1, 5] / c[5, 5]
    c[1, 9] = -c[5, 9] * c[1, 5] / c[5, 5]
    c[1, 8] = -c[5, 8] * c[1, 5] / c[5, 5]
    c[1, 7] = -c[5, 7] * c[1, 5] / c[5, 5]
    c[1, 6] = 1.0 - (c[5, 6] * c[1, 5] / c[5, 5])
    for i in range(3, 0, -1):                     # loop 250
        for j in range(5, 11):
            c[i, j] = c[i, j] - (c[i, 4] * c[4, j] / c[4, 4])
    for i in range(2, 0, -1):                     # loop 270
        for j in range(4, 11):
            c[i, j] = c[i, j] - (c[i, 3] * c[3, j] / c[3, 3])
    for j in range(3, 11):                        # loop 300
        c[1, j] = c[1, j] - (c[1, 2] * c[2, j] / c[2, 2])
    for i in range(1, 6):                         # loop 310: B(I,J) = C(I,J+5)/C(I,I)
        for j in range(1, 6):
            b[i - 1, j - 1] = c[i, j + 5] / c[i, i]
    return b, False


@njit(cache=True)
def lu_solve(m, rhs):
    """m^-1 rhs by LU with partial pivoting (the 1991 method's choice; the thesis prints
    no inverse): (X, singular)."""
    n = m.shape[0]
    a, x = m.copy(), rhs.copy()
    for k in range(n):
        p = k
        for i in range(k + 1, n):
            if abs(a[i, k]) > abs(a[p, k]):
                p = i
        if a[p, k] == 0.0 or not math.isfinite(a[p, k]):
            return x, True
        if p != k:
            for j in range(n):
                a[k, j], a[p, j] = a[p, j], a[k, j]
            for j in range(x.shape[1]):
                x[k, j], x[p, j] = x[p, j], x[k, j]
        for i in range(k + 1, n):
            f = a[i, k] / a[k, k]
            for j in range(k + 1, n):
                a[i, j] = a[i, j] - f * a[k, j]
            for j in range(x.shape[1]):
                x[i, j] = x[i, j] - f * x[k, j]
    for k in range(n - 1, -1, -1):
        for j in range(x.shape[1]):
            s = x[k, j]
            for i in range(k + 1, n):
                s = s - a[k, i] * x[i, j]
            x[k, j] = s / a[k, k]
    return x, False


@njit(cache=True)
def pseudo_inverse(a, printed):
    """(A'A)^-1 A' of a 6 x 5 matrix as the listing forms it (TRANS, MULTI, INVERSE, MULTI),
    or by LU with pivoting: (IA, singular)."""
    at = a.T.copy()
    ata = multi(at, a)
    if printed:
        inv, singular = listing_inverse(ata)
        return multi(inv, at), singular
    return lu_solve(ata, at)


@njit(cache=True)
def loop_product(th1, q, a1, a2, a4, alp4, s1):
    """The listing's H_j (real, dual: (3, 3) each) of q_j = THT2, ETA2, THT3, ETA3, S4
    (dB/dq_j = H_j B; the listing's H2, H2D, H3, H3D, H4DD) and the loop product
    B = M1 L2 L3 M4 (real, dual), at q."""
    tht2, eta2, tht3, eta3, s4 = q[0], q[1], q[2], q[3], q[4]
    w = np.zeros((38, 3, 3))           # every matrix below is a view of one work array
    m1r, m1d, l2r, l2d, l3r, zero, m4r, m4d = w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]
    q1r, q2r, q3d, q4r = w[8], w[9], w[10], w[11]
    m1r[0, 0], m1r[0, 1], m1r[1, 0], m1r[1, 1], m1r[2, 2] = \
        math.cos(th1), -math.sin(th1), math.sin(th1), math.cos(th1), 1.0
    m1d[0, 0], m1d[0, 1], m1d[0, 2] = -s1 * math.sin(th1), -s1 * math.cos(th1), a1 * math.sin(th1)
    m1d[1, 0], m1d[1, 1], m1d[1, 2] = s1 * math.cos(th1), -s1 * math.sin(th1), -a1 * math.cos(th1)
    m1d[2, 1] = a1
    l2r[0, 0], l2r[0, 1], l2r[0, 2] = math.cos(tht2) * math.cos(eta2), -math.sin(tht2), math.cos(tht2) * math.sin(eta2)
    l2r[1, 0], l2r[1, 1], l2r[1, 2] = math.sin(tht2) * math.cos(eta2), math.cos(tht2), math.sin(tht2) * math.sin(eta2)
    l2r[2, 0], l2r[2, 2] = -math.sin(eta2), math.cos(eta2)
    l2d[0, 1], l2d[0, 2] = a2 * math.cos(tht2) * math.sin(eta2), a2 * math.sin(tht2)
    l2d[1, 1], l2d[1, 2] = a2 * math.sin(tht2) * math.sin(eta2), -a2 * math.cos(tht2)
    l2d[2, 1] = a2 * math.cos(eta2)
    l3r[0, 0], l3r[0, 1], l3r[0, 2] = math.cos(tht3) * math.cos(eta3), math.cos(tht3) * math.sin(eta3), math.sin(tht3)
    l3r[1, 0], l3r[1, 1], l3r[1, 2] = math.sin(tht3) * math.cos(eta3), math.sin(tht3) * math.sin(eta3), -math.cos(tht3)
    l3r[2, 0], l3r[2, 1] = -math.sin(eta3), math.cos(eta3)
    m4r[0, 0], m4r[1, 1], m4r[1, 2], m4r[2, 1], m4r[2, 2] = \
        1.0, math.cos(alp4), -math.sin(alp4), math.sin(alp4), math.cos(alp4)
    m4d[0, 1], m4d[0, 2] = -s4 * math.cos(alp4), s4 * math.sin(alp4)
    m4d[1, 0], m4d[1, 1], m4d[1, 2] = s4, -a4 * math.sin(alp4), -a4 * math.cos(alp4)
    m4d[2, 1], m4d[2, 2] = a4 * math.cos(alp4), -a4 * math.sin(alp4)
    q1r[0, 1], q1r[1, 0] = -1.0, 1.0
    q2r[0, 2], q2r[1, 2], q2r[2, 0], q2r[2, 1] = math.cos(tht2), math.sin(tht2), -math.cos(tht2), -math.sin(tht2)
    q3d[0, 1], q3d[1, 0] = -1.0, 1.0
    q4r[0, 2], q4r[1, 2], q4r[2, 0], q4r[2, 1] = math.cos(tht3), math.sin(tht3), -math.cos(tht3), -math.sin(tht3)
    m1q1r, m1q1d, h2r, h2d, m1q2r, m1q2d, h2dr, h2dd = w[12], w[13], w[14], w[15], w[16], w[17], w[18], w[19]
    m1l2r, m1l2d, h6r, h6d, h3r, h3d, h7r, h7d = w[20], w[21], w[22], w[23], w[24], w[25], w[26], w[27]
    h3dr, h3dd, h5r, h5d, h5q3r, h5q3d, h4ddr, h4ddd = w[28], w[29], w[30], w[31], w[32], w[33], w[34], w[35]
    br, bd = w[36], w[37]
    tm1r, tm1d = m1r.T, m1d.T
    productdual(m1r, m1d, q1r, zero, m1q1r, m1q1d)
    productdual(m1q1r, m1q1d, tm1r, tm1d, h2r, h2d)
    productdual(m1r, m1d, q2r, zero, m1q2r, m1q2d)
    productdual(m1q2r, m1q2d, tm1r, tm1d, h2dr, h2dd)
    productdual(m1r, m1d, l2r, l2d, m1l2r, m1l2d)
    tm1l2r, tm1l2d = m1l2r.T, m1l2d.T
    productdual(m1l2r, m1l2d, q1r, zero, h6r, h6d)
    productdual(h6r, h6d, tm1l2r, tm1l2d, h3r, h3d)
    productdual(m1l2r, m1l2d, q4r, zero, h7r, h7d)
    productdual(h7r, h7d, tm1l2r, tm1l2d, h3dr, h3dd)
    productdual(m1l2r, m1l2d, l3r, zero, h5r, h5d)
    productdual(h5r, h5d, zero, q3d, h5q3r, h5q3d)
    productdual(h5q3r, h5q3d, h5r.T, h5d.T, h4ddr, h4ddd)
    productdual(h5r, h5d, m4r, m4d, br, bd)
    return ((h2r, h2d), (h2dr, h2dd), (h3r, h3d), (h3dr, h3dd), (h4ddr, h4ddd)), (br, bd)


@njit(cache=True)
def loop_matrices(th1, q, a1, a2, a4, alp4, s1):
    """A (6 x 5) and V (6) of the listing at q = (THT2, ETA2, THT3, ETA3, S4)."""
    h, (br, bd) = loop_product(th1, q, a1, a2, a4, alp4, s1)
    a = np.empty((6, 5))
    for col, (real, dual) in enumerate(h):
        a[0, col], a[1, col], a[2, col] = real[0, 1], real[0, 2], real[1, 2]
        a[3, col], a[4, col], a[5, col] = dual[0, 1], dual[0, 2], dual[1, 2]
    v = np.empty(6)
    v[0] = br[1, 0] + br[0, 0] + br[1, 1] - 2.0
    v[1] = br[2, 0] + br[0, 0] + br[2, 2] - 2.0
    v[2] = br[2, 1] + br[1, 1] + br[2, 2] - 2.0
    v[3], v[4], v[5] = bd[1, 0], bd[2, 0], bd[2, 1]
    return a, v


@njit(cache=True)
def newton(th1, q, a1, a2, a4, alp4, s1, tol, max_iterations, printed):
    """The printed iteration at one crank angle th1 (rad) from q: (answer, status, steps).

    It stops when every |DELTA| <= tol and keeps the point before that step (the listing
    adds DELTA only when it does not stop); after ``max_iterations`` evaluations it fails.
    A non-finite DELTA fails at once: the listing carries the NaN on to its 150th step,
    where it stops at the same crank angle (a NaN in q makes every later DELTA NaN).
    """
    q = q.copy()
    for i in range(1, max_iterations + 1):
        a, v = loop_matrices(th1, q, a1, a2, a4, alp4, s1)
        ia, singular = pseudo_inverse(a, printed)
        if singular:
            return q, SINGULAR, i
        delta = mulmavec(ia, v)
        done = True
        for k in range(5):
            if not math.isfinite(delta[k]):
                return q, NOT_CONVERGED, i
            if abs(delta[k]) > tol:
                done = False
        if done:
            return q, OK, i
        for k in range(5):
            q[k] = q[k] + delta[k]
    return q, NOT_CONVERGED, max_iterations


@njit(cache=True)
def rates(th1d, q, a1, a2, printed):
    """The listing's DOT and DDOT (theta2, theta3, eta2, eta3, s4 order) at constant crank
    speed th1d (rad/s) and fixed S1: (dot, ddot, singular)."""
    tht1dd, s1d, s1dd = 0.0, 0.0, 0.0                 # the listing's PARAMETERs
    tht2, eta2, tht3 = q[0], q[1], q[2]
    vm = np.zeros((6, 5))
    vm[0, 0], vm[0, 2], vm[1, 4] = -math.sin(eta2), math.sin(tht2) * math.cos(eta2), math.sin(tht3)
    vm[2, 2], vm[2, 3] = math.cos(tht2), 1.0
    vm[3, 0], vm[3, 2], vm[3, 4] = a2 * math.cos(eta2), a2 * math.sin(tht2) * math.sin(eta2), -math.cos(tht3)
    vm[4, 0], vm[4, 1], vm[4, 2] = math.cos(eta2), 1.0, math.sin(tht2) * math.sin(eta2)
    vm[5, 2] = -a2 * math.cos(tht2)
    vv = np.zeros(6)
    vv[0] = th1d * math.sin(eta2)
    vv[1] = s1d * math.sin(eta2) - a1 * th1d * math.sin(tht2) * math.cos(eta2)
    vv[3] = -(th1d * (a1 * math.cos(tht2) + a2 * math.cos(eta2)))
    vv[4] = -(th1d * math.cos(eta2))
    vv[5] = -(th1d * a1 * math.sin(tht2) * math.sin(eta2)) - s1d * math.cos(eta2)
    ivm, singular = pseudo_inverse(vm, printed)
    if singular:
        return np.zeros(5), np.zeros(5), True
    dot = mulmavec(ivm, vv)
    d_t2, d_t3, d_e2, d_s4 = dot[0], dot[1], dot[2], dot[4]
    s_t2, c_t2, s_e2, c_e2, s_t3, c_t3 = \
        math.sin(tht2), math.cos(tht2), math.sin(eta2), math.cos(eta2), math.sin(tht3), math.cos(tht3)
    av = np.empty(6)
    av[0] = (tht1dd * s_e2 + d_e2 * (th1d + d_t2) * c_e2
             - d_e2 * (d_t2 * c_t2 * c_e2 - d_e2 * s_t2 * s_e2))
    av[1] = (a1 * (th1d * s_t2 * s_e2 * d_e2 - tht1dd * s_t2 * c_e2 - th1d * d_t2 * c_t2 * c_e2)
             + s1dd * s_e2 + s1d * d_e2 * c_e2 - d_s4 * d_t3 * c_t3)
    av[2] = d_t2 * d_e2 * s_t2
    av[3] = (a1 * s_t2 * th1d * d_t2 + a2 * s_e2 * d_e2 * (th1d + d_t2)
             - tht1dd * (a1 * c_t2 + a2 * c_e2)
             - a2 * d_e2 * (c_t2 * s_e2 * d_t2 + s_t2 * c_e2 * d_e2) - s_t3 * d_t3 * d_s4)
    av[4] = (th1d * d_e2 * s_e2 - tht1dd * c_e2 + s_e2 * d_e2 * d_t2
             - d_e2 * (c_t2 * s_e2 * d_t2 + s_t2 * c_e2 * d_e2))
    av[5] = (s1d * s_e2 * d_e2 - a1 * tht1dd * s_t2 * s_e2
             - a1 * th1d * d_t2 * c_t2 * s_e2 - s1dd * c_e2
             - a1 * s_t2 * c_e2 * th1d * d_e2
             - a2 * d_t2 * d_e2 * s_t2)
    return dot, mulmavec(ivm, av), False


@njit(cache=True)
def listing_sweep(theta1, q0, a1, a2, a4, alp4, s1, th1d, tol, printed):
    """One pass of the 1996 listing's DO 400 loop: at each crank angle the Newton from the
    last answer, then the rates, in the listing's order (a failure ends the pass there).

    Returns q (n, 5), dot (n, 5), ddot (n, 5), steps (n,), status, index of the failing
    position (-1 when none).
    """
    n = theta1.shape[0]
    q_out, dot_out, ddot_out = np.full((n, 5), np.nan), np.full((n, 5), np.nan), np.full((n, 5), np.nan)
    steps = np.zeros(n, dtype=np.int64)
    q = q0.copy()
    for j in range(n):
        q, status, steps[j] = newton(theta1[j], q, a1, a2, a4, alp4, s1, tol, MAX_ITERATIONS, printed)
        if status != OK:
            return q_out, dot_out, ddot_out, steps, status, j
        dot, ddot, singular = rates(th1d, q, a1, a2, printed)
        if singular:
            return q_out, dot_out, ddot_out, steps, SINGULAR, j
        for k in range(5):
            q_out[j, k], dot_out[j, k], ddot_out[j, k] = q[k], dot[k], ddot[k]
    return q_out, dot_out, ddot_out, steps, OK, -1
