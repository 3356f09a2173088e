"""Rahman (1996)'s part of the fuzz (``harness/fuzz.py``): the CSSP program, INVERSE and our
QPROG in legacy and port, the port's balance and its lower-level pieces (the listing's pass,
the closed loop's loads, the shared slider-crank kinematics), the input dataclass; the names
their call texts use; the check a QP solution must pass (its constraints and optimality, as
QPROG promises, and never an answer for a problem unbounded below)."""
from __future__ import annotations

from functools import lru_cache

from ....port.rahman1996.quirks import CsspQuirks
from ...fuzz_calls import (ANGLES, CONTAINER, FLAG, FLOAT, INT, MATRIX, QUIRKS, VECTOR, Arg, Call, Entry, angles,
                           any_seed, near, num, quirk_set, scale_of)


def cssp_inputs(rng) -> Call:
    """The CSSP's geometry: near the example, or (one call in four) next to its singular
    position, the rod just long enough to reach (a2 = |a1 + a4| (1 + 1e-3 ... 1e-12), the
    family of the singular example a1 = 2, a2 = 3 (1 + 1e-8), a4 = 1, alpha4 = 90 deg, s1 = 0)."""
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


#: the printed first estimate of the CSSP's positions at the example (slider_crank.geometry)
LISTING_START = "np.array([1.955193, 0.0, 4.327992, 0.0, 7.416198])"


def matrix5(rng) -> str:
    """A 5 x 5 matrix: well-conditioned, random, singular, or needing a row exchange."""
    return rng.choice([f"spd(5, {any_seed(rng)})", f"rand((5, 5), {any_seed(rng)})", f"spd(5, {any_seed(rng)}, rank=3)",
                       "np.roll(np.eye(5), 1, axis=0)", f"np.diag(rand((5,), {any_seed(rng)}))"])


@lru_cache(maxsize=64)
def qp_case(kind: str, n: int, m: int, seed: int) -> tuple:
    """(h, g, a, b, neq) of a QP of a class QPROG must get right (registers D160-D163), from a
    seeded generator: ``'ill-conditioned'``, H positive definite of condition 1e8..1e14 and m
    rows feasible at a point (some tight, fewer than n equalities); ``'repeated rows'``, H of
    condition 1..1e7 with 1..n-1 equalities and m inequalities holding at a point, then an
    equality repeated and two summed as inequalities; ``'unbounded'``, H positive
    semidefinite of rank < n, g with a part -d0 along a null direction d0 and m feasible rows
    that do not stop it (inequalities turned so that a_i d0 >= 0, equalities with d0
    projected out)."""
    import numpy as np
    rng = np.random.default_rng(seed)
    q = np.linalg.qr(rng.standard_normal((n, n)))[0]
    a, x0 = rng.standard_normal((m, n)), rng.standard_normal(n)
    if kind == "unbounded":
        r = int(rng.integers(0, n))
        h = q[:, :r] @ np.diag(rng.uniform(0.1, 1.0, r)) @ q[:, :r].T
        d0 = q[:, r:] @ rng.uniform(0.5, 1.0, n - r)
        neq = int(rng.integers(0, min(m, n - 1) + 1))
        a[:neq] -= np.outer(a[:neq] @ d0, d0) / (d0 @ d0)
        a[neq:] *= np.where(a[neq:] @ d0 < 0, -1.0, 1.0)[:, None]
        g = -d0 + q[:, :r] @ rng.standard_normal(r)
        return h, g, a, a @ x0 - np.r_[np.zeros(neq), rng.choice([0.0, 0.5], m - neq)], neq
    low, high = (8.0, 14.0) if kind == "ill-conditioned" else (0.0, 7.0)
    h = q @ np.diag(np.geomspace(1.0, 10.0 ** -rng.uniform(low, high), n)) @ q.T
    h, g = (h + h.T) / 2, rng.standard_normal(n)
    neq = int(rng.integers(0, min(m, n - 1) + 1)) if kind == "ill-conditioned" else int(rng.integers(1, n))
    if kind == "repeated rows":
        a = np.vstack([rng.standard_normal((neq, n)), a])
    b = a @ x0 - np.r_[np.zeros(neq), rng.choice([0.0, 0.0, 0.5], len(a) - neq)]
    if kind == "repeated rows":
        a, b = np.vstack([a, a[0], a[0] + a[neq - 1]]), np.r_[b, b[0], b[0] + b[neq - 1]]
    return h, g, a, b, neq


def qp_spec(func: str):
    """qprog(h, g, a, b, neq): a random convex QP, small half of the time, else large: up to
    the FORTRAN's limits (60 variables, 200 constraints) or one beyond, more constraints
    than variables; or (two calls in five) one of ``qp_case``'s classes, H and g scaled
    together."""
    def spec(rng):
        if rng.random() < 0.4:
            kind = rng.choice(["ill-conditioned", "repeated rows", "unbounded"])
            n, m = rng.randint(1 if kind == "ill-conditioned" else 2, 8), rng.randint(0, 6)
            case, objective = f"qp_case({kind!r}, {n}, {m}, {any_seed(rng)})", scale_of(rng)
            args = [Arg(None, f"{case}[0]{objective}", MATRIX), Arg(None, f"{case}[1]{objective}", VECTOR)]
            if m or kind == "repeated rows":
                args += [Arg("a", f"{case}[2]", MATRIX), Arg("b", f"{case}[3]", VECTOR),
                         Arg("neq", f"{case}[4]", INT, True)]
            return Call(func, args)
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


ENTRIES = [
    Entry("rahman1996.cssp", lambda rng: Call("rahman1996.cssp", cssp_inputs(rng).args + [
        Arg("solution", rng.choice(["None", f"0.001 + 0.01 * np.abs(rand((9,), {any_seed(rng)}))"]),
            VECTOR, True)]),
          angles=True),
    Entry("rahman1996.inverse", lambda rng: Call("rahman1996.inverse", [Arg(None, matrix5(rng), MATRIX)])),
    Entry("rahman1996.qprog", qp_spec("rahman1996.qprog"), check="qp"),
    Entry("port.rahman1996.balance.balance", lambda rng: Call("port.rahman1996.balance.balance", [
        Arg("inputs", cssp_inputs(rng), CONTAINER, True),
        Arg("quirks", quirk_set(rng, CsspQuirks.names(), ("CSSP_PRINTED", "CSSP_CORRECTED")), QUIRKS, True)]),
          angles=True),
    Entry("port.rahman1996.balance.solve_qp", lambda rng: Call("port.rahman1996.balance.solve_qp", [
        Arg(None, f"1e-3 * spd(9, {any_seed(rng)}{rng.choice(['', ', rank=6'])})", MATRIX),
        Arg("rows", "QP_ROWS", MATRIX, True),
        Arg("bounds", rng.choice(["QP_BOUNDS", f"0.01 * np.abs(rand((11,), {any_seed(rng)}))"]), VECTOR),
        Arg("equalities", rng.choice(["3", str(rng.randint(0, 11))]), INT, True)])),
    Entry("port.rahman1996.listing.printed_inverse", lambda rng: Call("port.rahman1996.listing.printed_inverse",
                                                                [Arg(None, matrix5(rng), MATRIX)])),
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
    Entry("port.rahman1996.qprog.hessian_shift", lambda rng: Call("port.rahman1996.qprog.hessian_shift", [
        Arg(None, f"spd({(n := rng.randint(1, 9))}, {any_seed(rng)}){scale_of(rng)}", MATRIX),
        Arg(None, f"rand(({n},), {any_seed(rng)})", VECTOR, True)])),
    Entry("port.rahman1996.data.CsspInputs", lambda rng: cssp_inputs(rng)),
    Entry("port.rahman1996.qprog.qprog", qp_spec("port.rahman1996.qprog.qprog"), check="qp"),
]

WARM_UP = tuple(f"port.rahman1996.balance.balance(CsspInputs(), {q})" for q in ("CSSP_PRINTED", "CSSP_CORRECTED")) + (
    "port.rahman1996.qprog.qprog(np.eye(2), np.ones(2))",)


def namespace() -> dict:
    """The names Rahman (1996)'s call texts use; ``inputs`` and ``quirks`` as Ali's."""
    import linkrepro.port.rahman1996.balance  # noqa: F401 (reached through ``port``)
    import linkrepro.port.rahman1996.listing  # noqa: F401 (reached through ``port``)
    import linkrepro.port.rahman1996.mechanics  # noqa: F401 (reached through ``port``)
    import linkrepro.port.rahman1996.qprog  # noqa: F401 (reached through ``port``)
    import linkrepro.port.slider_crank.kinematics  # noqa: F401 (reached through ``port``)
    from linkrepro import port
    from linkrepro.legacy import rahman1996
    from linkrepro.port.rahman1996.data import QP_BOUNDS, QP_ROWS, Constants, CsspInputs
    from linkrepro.port.rahman1996.quirks import CSSP_CORRECTED, CSSP_PRINTED
    return {"port": port, "rahman1996": rahman1996, "QP_BOUNDS": QP_BOUNDS, "QP_ROWS": QP_ROWS, "qp_case": qp_case,
            "Constants": Constants, "CsspInputs": CsspInputs, "CSSP_PRINTED": CSSP_PRINTED,
            "CSSP_CORRECTED": CSSP_CORRECTED, "inputs": (CsspInputs(),), "quirks": (CSSP_PRINTED, CSSP_CORRECTED)}


def _qp_promise(arguments, result) -> str | None:
    """What qprog's ``sol`` must be (registers D050, D160-D163), each to twice QPROG's own
    rounding GTOL = eps (1e3 + 8 kappa), kappa = tr(H~) tr(H~^-1) with H~ = H + diag I (H as
    QPROG reads it: its lower triangle), the tolerance its last guard holds the rows to:

    - every row met: a[:neq] x = b[:neq] and a[neq:] x >= b[neq:], each missed by at most
      that of its own size |a_i| |x| + |b_i|;
    - optimal for H~ (H itself where diag = 0): the stationarity residual H~ x + g - A_act'
      lambda at most that of the largest size of its terms, the inequalities' multipliers at
      least minus that of the largest |lambda|;
    - never a problem unbounded below (``_unbounded``)."""
    import numpy as np
    args, kwargs = arguments
    names = ("h", "g", "a", "b", "neq")
    given = {**dict(zip(names, args)), **kwargs}
    x = np.asarray(result["sol"], dtype=float)
    n = len(x)
    lower = np.tril(np.atleast_2d(np.asarray(given["h"], dtype=float)))
    h = lower + np.tril(lower, -1).T
    g = np.asarray(given["g"], dtype=float).ravel()
    if given.get("a") is None:
        a, b, neq = np.zeros((0, n)), np.zeros(0), 0
    else:
        a, b = np.atleast_2d(np.asarray(given["a"], dtype=float)), np.atleast_1d(np.asarray(given["b"], dtype=float))
        neq = int(given.get("neq", 0))
    shifted = h + result["diag"] * np.eye(n)
    with np.errstate(all="ignore"):
        scaled = shifted / np.abs(shifted).max() if np.abs(shifted).max() > 0 else shifted
        try:
            kappa = float(np.trace(scaled) * np.trace(np.linalg.inv(scaled)))
        except np.linalg.LinAlgError:
            kappa = np.inf
    promise = 2.0 * np.finfo(float).eps * (1e3 + 8.0 * abs(kappa))
    slack = a @ x - b
    size = np.abs(a) @ np.abs(x) + np.abs(b)
    worst = np.where(np.arange(len(b)) < neq, np.abs(slack), -slack) / np.where(size > 0, size, 1.0)
    if worst.max(initial=0.0) > promise:
        k = int(np.argmax(worst))
        return (f"constraint {k} ({'equality' if k < neq else 'inequality'}) violated by {worst[k]:.3g} of its size "
                f"(QPROG promises {promise / 2:.3g})")
    active, lam = np.asarray(result["active"], dtype=int), np.asarray(result["multipliers"], dtype=float)
    with np.errstate(all="ignore"):
        residual = shifted @ x + g - a[active].T @ lam
        terms = np.abs(shifted) @ np.abs(x) + np.abs(g) + np.abs(a[active]).T @ np.abs(lam)
    if np.abs(residual).max(initial=0.0) > promise * terms.max(initial=0.0):
        return (f"not optimal: stationarity residual {np.abs(residual).max():.3g} of terms {terms.max():.3g} "
                f"(QPROG promises {promise / 2:.3g} of them)")
    if np.any(lam[active >= neq] < -promise * np.abs(lam).max(initial=0.0)):
        return f"not optimal: an inequality's multiplier {lam[active >= neq].min():.3g} < 0"
    direction = _unbounded(h, g, a, b, neq)
    if direction is not None:
        return f"returned a solution for a problem unbounded below ({direction})"
    return None


def _unbounded(h, g, a, b, neq) -> str | None:
    """A linear program's certificate that min g'x + x'Hx/2 over the rows is unbounded below,
    where H is positive semidefinite with a clear null space (every eigenvalue at most 1e-13
    or at least 1e-6 of the largest, else not judged): a direction d of H's null space,
    |d| <= 1, with a[:neq] d = 0, a[neq:] d >= 0 (rows scaled to a largest entry of 1) and
    g'd < -1e-6 sum |g_j|.  None where there is none (or it is not judged)."""
    import numpy as np
    from scipy.optimize import linprog
    with np.errstate(all="ignore"):
        top = np.abs(h).max()
        if not np.any(g) or not np.all(np.isfinite(h)) or not np.all(np.isfinite(g)):
            return None
        w, v = np.linalg.eigh(h / top) if top > 0 else (np.zeros(len(g)), np.eye(len(g)))
        big = np.abs(w).max(initial=0.0)
        null = np.abs(w) <= 1e-13 * big if big > 0 else np.ones(len(w), bool)
        if not null.any() or np.any(~null & (w < 1e-6 * big)):
            return None
        z = v[:, null]
        rows = a / np.where(np.abs(a).max(axis=1) > 0, np.abs(a).max(axis=1), 1.0)[:, None]
        gz = (g / np.abs(g).max()) @ z
    box = np.vstack([z, -z])
    a_ub = np.vstack([-(rows[neq:] @ z), box])
    b_ub = np.r_[np.zeros(len(rows) - neq), np.ones(2 * len(g))]
    res = linprog(gz, A_ub=a_ub, b_ub=b_ub, A_eq=rows[:neq] @ z if neq else None, b_eq=np.zeros(neq) if neq else None,
                  bounds=[(None, None)] * z.shape[1], method="highs")
    if res.status == 0 and res.fun < -1e-6 * np.abs(g / np.abs(g).max()).sum():
        return f"a feasible direction of H's null space with g'd = {res.fun:.3g} (sum |g| = 1 scale)"
    return None


CHECKS = {"qp": _qp_promise}
