"""Rahman (1991)'s part of the fuzz (``harness/fuzz.py``): the generalized slider-crank's
analysis and its printed position sweep in the port, the input dataclass; the names their call
texts use; the NaN they document (scrubbed: the rows that did not converge)."""
from __future__ import annotations

import sys

from ....port.rahman1991.quirks import GscQuirks
from ...fuzz_calls import ANGLES, CONTAINER, FLAG, FLOAT, QUIRKS, Arg, Call, Entry, angles, near, num, quirk_set


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


ENTRIES = [
    Entry("port.rahman1991.analysis.analyse", lambda rng: Call("port.rahman1991.analysis.analyse", [
        Arg("inputs", gsc_inputs(rng), CONTAINER, True),
        Arg("crank_deg", angles(rng, most=12), ANGLES, True),
        Arg("quirks", quirk_set(rng, GscQuirks.names(), ("GSC_PRINTED", "GSC_CORRECTED")), QUIRKS, True),
        Arg("strict", rng.choice(["False", "True"]), FLAG, True)]), angles=True, scrub="gsc"),
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
    """gsc.analyse documents NaN after ``converged`` in the rows that did not converge, and
    in the joint forces of rows whose status is 'dead centre' (no balancing torque)."""
    pd = sys.modules.get("pandas")
    if pd is None or not isinstance(frame, pd.DataFrame) or "converged" not in frame:
        return frame
    from linkrepro.port.rahman1991 import forces as gsc_forces
    from linkrepro.port.rahman1991.analysis import DEAD_CENTRE
    kept = frame[frame["converged"].astype(bool)]
    if "status" not in kept:
        return kept
    dead = kept["status"] == DEAD_CENTRE
    return [kept[~dead], kept[dead].drop(columns=gsc_forces.COMPONENTS, errors="ignore")]


def _positions_documented(run):
    """rahman1991.position.positions documents NaN in q and closure where a position did not
    converge or cannot assemble (its status says which)."""
    import numpy as np
    from linkrepro.port.rahman1991.position import DFP_THEN_NEWTON, NEWTON, PositionRun
    if not isinstance(run, PositionRun):
        return run
    solved = np.isin(run.status, [NEWTON, DFP_THEN_NEWTON])
    return [run.q[solved], run.closure[solved]]


SCRUBS = {"gsc": _gsc_documented, "positions": _positions_documented}
