"""Rahman (1991)'s part of the fuzz (``harness/fuzz.py``): the generalized slider-crank's
analysis and its printed position sweep in the port, the input dataclass; the names their call
texts use; the NaN they document (scrubbed: the rows that hold no answer); the check a row
reported converged must pass (its loop closes, on its branch).  The class of single-angle
calls: ``analyse`` at one crank angle, on the thesis's planar example, random planar
configurations (where the five-variable loop closes) and the spatial ones, each branch."""
from __future__ import annotations

import sys

from ....port.rahman1991.quirks import GscQuirks
from ...fuzz_calls import ANGLES, CONTAINER, FLAG, FLOAT, QUIRKS, Arg, Call, Entry, Pool, angles, near, num, quirk_set

#: hostile branches (none must be refused as NaN: a wrong type or value is a TypeError, ValueError)
BRANCH = Pool("other", ("0", "2", "-2", "1.0", "True", "'+1'", "np.int64(-1)", "np.array([1])", "nan", "[1]"))


def gsc_inputs(rng) -> Call:
    def pick_or(values, lo, hi):
        return rng.choice([repr(v) for v in values] + [num(rng, lo, hi)])
    return Call("GscInputs", [
        Arg("a1", near(rng, 12.0, lo=1.0, hi=40.0), FLOAT, True),
        Arg("a2", near(rng, 50.0, lo=5.0, hi=100.0), FLOAT, True),
        Arg("a4", pick_or((0.0, 10.0, 20.0, 30.0), 0.0, 45.0), FLOAT, True),
        Arg("alpha4_deg", pick_or((232.0, 270.0, 310.0), 0.0, 360.0), FLOAT, True),
        Arg("s1", pick_or((0.0, 3.0, 3.5, 6.0, 9.0), -10.0, 10.0), FLOAT, True),
        Arg("rpm", near(rng, 50.0, lo=1.0, hi=500.0), FLOAT, True),
        Arg("torque", near(rng, 100.0, lo=-500.0, hi=500.0), FLOAT, True),
        Arg("r1", near(rng, 1.5, lo=0.1, hi=5.0), FLOAT, True),
        Arg("r2", near(rng, 1.0, lo=0.1, hi=5.0), FLOAT, True),
        Arg("r3", near(rng, 3.0, lo=0.1, hi=8.0), FLOAT, True),
        Arg("alpha", pick_or((0.0, 1.0, 2.0), 0.0, 3.0), FLOAT, True)])


def single_angle_inputs(rng) -> Call:
    """The thesis's example (one call in four), a planar configuration (S1 = 0, alpha4 = 90 or
    270 deg: the five-variable loop closes) of random lengths and offset (one in two, some
    that cannot assemble at every angle), or a spatial one (``gsc_inputs``)."""
    kind = rng.choice(("example", "planar", "planar", "spatial"))
    if kind == "example":
        return Call("GscInputs", [])
    if kind == "spatial":
        return gsc_inputs(rng)
    return Call("GscInputs", [Arg("a1", num(rng, 1.0, 40.0), FLOAT, True), Arg("a2", num(rng, 5.0, 100.0), FLOAT, True),
                              Arg("a4", num(rng, -45.0, 45.0), FLOAT, True),
                              Arg("alpha4_deg", rng.choice(["270.0", "90.0"]), FLOAT, True),
                              Arg("s1", "0.0", FLOAT, True)])


def one_angle(rng) -> str:
    """One crank angle (deg): a whole degree of the turn, any angle of -360..720, or a special one."""
    angle = rng.choice([float(rng.randint(0, 360)), round(rng.uniform(-360.0, 720.0), 3),
                        rng.choice((0.0, 46.0, 48.0, 90.0, 180.0, 270.0, 360.0, -90.0))])
    return f"np.array([{angle!r}])"


ENTRIES = [
    Entry("port.rahman1991.analysis.analyse", lambda rng: Call("port.rahman1991.analysis.analyse", [
        Arg("inputs", gsc_inputs(rng), CONTAINER, True),
        Arg("crank_deg", angles(rng, most=12), ANGLES, True),
        Arg("quirks", quirk_set(rng, GscQuirks.names(), ("GSC_PRINTED", "GSC_CORRECTED")), QUIRKS, True),
        Arg("strict", rng.choice(["False", "True"]), FLAG, True)]), angles=True, scrub="gsc", check="gsc_closes"),
    Entry("port.rahman1991.analysis.analyse at one angle", lambda rng: Call("port.rahman1991.analysis.analyse", [
        Arg("inputs", single_angle_inputs(rng), CONTAINER, True),
        Arg("crank_deg", one_angle(rng), ANGLES, True),
        Arg("quirks", rng.choice(["GSC_PRINTED", "GSC_PRINTED", "GSC_CORRECTED"]), QUIRKS, True),
        Arg("branch", rng.choice(["1", "1", "-1", "None"]), BRANCH, True)]),
          angles=True, scrub="gsc", check="gsc_closes"),
    Entry("port.rahman1991.position.positions", lambda rng: Call("port.rahman1991.position.positions", [
        Arg(None, gsc_inputs(rng), CONTAINER), Arg(None, f"np.radians({angles(rng, most=12)})", ANGLES)]),
          angles=True, scrub="positions"),
    Entry("port.rahman1991.data.GscInputs", lambda rng: gsc_inputs(rng)),
]

WARM_UP = tuple(f"port.rahman1991.analysis.analyse(GscInputs(), np.array([0.0, 90.0]), {q})"
                for q in ("GSC_PRINTED", "GSC_CORRECTED"))


def namespace() -> dict:
    """The names Rahman (1991)'s call texts use; ``inputs`` and ``quirks`` as Ali's."""
    import linkrepro.port.rahman1991.analysis  # noqa: F401 (reached through ``port``)
    import linkrepro.port.rahman1991.position  # noqa: F401 (reached through ``port``)
    from linkrepro import port
    from linkrepro.port.rahman1991.data import GscInputs
    from linkrepro.port.rahman1991.quirks import GSC_CORRECTED, GSC_PRINTED
    return {"port": port, "GscInputs": GscInputs, "GSC_PRINTED": GSC_PRINTED, "GSC_CORRECTED": GSC_CORRECTED,
            "inputs": (GscInputs(),), "quirks": (GSC_PRINTED, GSC_CORRECTED)}


def _gsc_documented(frame):
    """gsc.analyse documents NaN after ``converged`` in the rows that hold no answer (status
    not in ``ANSWERED``), and in the joint forces of rows whose status is 'dead centre' (no
    balancing torque)."""
    pd = sys.modules.get("pandas")
    if pd is None or not isinstance(frame, pd.DataFrame) or "status" not in frame:
        return frame
    from linkrepro.port.rahman1991 import forces as gsc_forces
    from linkrepro.port.rahman1991.analysis import ANSWERED, DEAD_CENTRE
    kept = frame[frame["status"].isin(ANSWERED)]
    dead = kept["status"] == DEAD_CENTRE
    return [kept[~dead], kept[dead].drop(columns=gsc_forces.COMPONENTS, errors="ignore")]


def _positions_documented(run):
    """rahman1991.position.positions documents NaN in q, closure and branch where the Newton
    did not stop or the mechanism cannot assemble (its status says which)."""
    from linkrepro.port.rahman1991.position import PositionRun
    if not isinstance(run, PositionRun):
        return run
    return [run.q[run.stopped], run.closure[run.stopped], run.branch[run.stopped]]


SCRUBS = {"gsc": _gsc_documented, "positions": _positions_documented}


def _gsc_closes(arguments, frame) -> str | None:
    """Every row ``analyse`` reports converged is a position of the mechanism on its branch,
    checked by a construction of its own: the rod from the crank pin P along the row's theta2,
    eta2 ends at the slider point Q(S4) and the ball angles theta3, eta3 give the slider's i4
    seen from the rod (to 10 CLOSURE_RTOL of the loop's size); its branch column is the sign of
    S4 + b, the branch asked (or 0: both roots meet); cos(eta2) > 0 (the closed form's angles)
    when a branch is asked; the printed model's closure column within its promise."""
    import inspect
    import numpy as np
    from linkrepro.port.rahman1991 import analysis, position
    bound = inspect.signature(analysis.analyse).bind(*arguments[0], **arguments[1])
    bound.apply_defaults()
    inputs, branch, rows = bound.arguments["inputs"], bound.arguments["branch"], frame[frame["converged"]]
    if rows.empty:
        return None
    th = np.radians(rows["crank_deg"].to_numpy(float))
    t2, e2, t3, e3 = (np.radians(rows[k].to_numpy(float)) for k in ("theta2", "eta2", "theta3", "eta3"))
    s4, s1, sa, ca = rows["s4"].to_numpy(float), inputs.axial(th)[0], np.sin(inputs.alpha4), np.cos(inputs.alpha4)
    phi = th + t2
    rod = inputs.a2 * np.stack([np.cos(phi) * np.cos(e2), np.sin(phi) * np.cos(e2), -np.sin(e2)], axis=1)
    pin = np.stack([inputs.a1 * np.cos(th), inputs.a1 * np.sin(th), s1], axis=1)
    slider = np.stack([np.full(th.size, -inputs.a4), -s4 * sa, -s4 * ca], axis=1)
    i4 = np.stack([np.cos(phi) * np.cos(e2), -np.sin(phi), np.cos(phi) * np.sin(e2)], axis=1)
    ball = np.stack([np.cos(t3) * np.cos(e3), np.sin(t3) * np.cos(e3), -np.sin(e3)], axis=1)
    gap = np.maximum(np.linalg.norm(pin + rod - slider, axis=1), inputs.a2 * np.linalg.norm(i4 - ball, axis=1))
    limit = position.closure_tolerance(inputs, s1)
    side = s4 + inputs.a1 * sa * np.sin(th) + s1 * ca
    reported = rows["branch"].to_numpy(float)
    for k in range(th.size):
        where = f"at crank {rows['crank_deg'].iloc[k]:g} deg (status {rows['status'].iloc[k]!r})"
        if not gap[k] <= 10.0 * limit[k]:
            return f"a converged row does not close: {gap[k]:.3g} in {where}, tolerance {10.0 * limit[k]:.3g}"
        if not (rows["closure"].iloc[k] <= limit[k]):
            return f"a converged row's closure {rows['closure'].iloc[k]:.3g} passes {limit[k]:.3g} {where}"
        if abs(side[k]) > 2.0 * limit[k] and reported[k] != np.sign(side[k]):
            return f"branch {reported[k]:g} reported where S4 + b = {side[k]:.6g} {where}"
        if branch is not None and reported[k] not in (branch, 0.0):
            return f"branch {reported[k]:g} reported converged where {branch} was asked {where}"
        if branch is not None and not np.cos(e2[k]) > 0.0:
            return f"eta2 = {rows['eta2'].iloc[k]:g} deg is not the closed form's (cos eta2 > 0) {where}"
    return None


CHECKS = {"gsc_closes": _gsc_closes}
