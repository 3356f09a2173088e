"""Rahman (1996)'s part of the fuzz (``harness/fuzz.py``): the CSSP program, INVERSE and our
QPROG in legacy and port, the port's balance and its lower-level pieces (the listing's pass,
the closed loop's loads, the shared slider-crank kinematics), the input dataclass; the names
their call texts use; the check a QP solution must pass (its constraints, as QPROG promises)."""
from __future__ import annotations

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
    return {"port": port, "rahman1996": rahman1996, "QP_BOUNDS": QP_BOUNDS, "QP_ROWS": QP_ROWS,
            "Constants": Constants, "CsspInputs": CsspInputs, "CSSP_PRINTED": CSSP_PRINTED,
            "CSSP_CORRECTED": CSSP_CORRECTED, "inputs": (CsspInputs(),), "quirks": (CSSP_PRINTED, CSSP_CORRECTED)}


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


CHECKS = {"qp": _qp_feasible}
