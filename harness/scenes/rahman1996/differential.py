"""The port against the legacy build on a fixed random sample of Rahman (1996) geometries:
Rahman (1996)'s part of ``linkrepro differential`` (``DIFFERENTIAL``, ``harness/differential.py``)
and the CSSP's fixed sample that docs/port-and-legacy.md shows.

``python -m linkrepro.harness.scenes.rahman1996.differential [--geometries 500] [--seed 1]`` prints, for the
CSSP balancing program with the listing's bugs (legacy ``cssp`` against the port's
``balance(..., CSSP_PRINTED)``): how many geometries give the same outcome (both return, or
both raise the same error at the same crank angle) and how far the tables differ where both
return; then how chaotic the build itself is: one REAL*4 unit in the last place of a1, a2,
a4 or s1, and whether legacy's own outcome or tables move (register D079).

Sample: numpy ``default_rng(seed)``; per geometry a1 ~ U(0.5, 4), a2 ~ U(3, 12),
a4 ~ U(-3, 3), alpha4 ~ U(0, 360) deg, s1 ~ U(-1, 1) in, drawn in that order; 3000 rpm.
"""
from __future__ import annotations

import argparse
import collections

import numpy as np

from ....checks import LARGEST
from ....legacy import rahman1996
from ....errors import LinkageError, QPError
from ....port.rahman1996.balance import CSSP_PRINTED, _listing_motions, balance
from ....port.rahman1996.data import CsspInputs
from ...differential import Domain, Parameter, Program, Thesis

#: a table move above this (relative to a column's largest value) is a jump, not round-off
JUMP = 1e-3
#: tables: port with the listing's bugs against legacy, relative to each column's largest |value|
TABLE_RTOL = 1e-12


def draw(rng: np.random.Generator, program: str = "cssp") -> dict:
    """One geometry of the sampled domain (inches, degrees, rpm), drawn in the docstring's order."""
    return dict(a1=rng.uniform(0.5, 4), a2=rng.uniform(3, 12), a4=rng.uniform(-3, 3),
                alpha4_deg=rng.uniform(0, 360), s1=rng.uniform(-1, 1), rpm=3000.0)


def sample(n: int, seed: int = 1) -> list[dict]:
    """n geometries of the sampled domain (inches, degrees, rpm)."""
    rng = np.random.default_rng(seed)
    return [draw(rng) for _ in range(n)]


def outcome(call) -> tuple:
    """("returns", table) or (error type name, crank angle deg or None)."""
    try:
        return "returns", call()["table"]
    except LinkageError as exc:
        return type(exc).__name__, exc.angle_deg
    except QPError as exc:
        return type(exc).__name__, None


def relative_difference(a: np.ndarray, b: np.ndarray) -> float:
    """Largest |a - b| relative to each column's largest |a|."""
    scale = np.max(np.abs(a), axis=0)
    return float(np.max(np.abs(a - b) / np.where(scale > 0, scale, 1.0)))


def port_against_legacy(geometries: list[dict]) -> tuple[collections.Counter, float]:
    """Outcome counts and the largest table difference where both engines return."""
    counts, worst = collections.Counter(), 0.0
    for g in geometries:
        (lk, lv), (pk, pv) = outcome(lambda: rahman1996.cssp(**g)), outcome(lambda: balance(CsspInputs(**g), CSSP_PRINTED))
        if lk == pk == "returns":
            worst = max(worst, relative_difference(lv, pv))
            counts["both return"] += 1
        elif (lk, lv) == (pk, pv):
            counts[f"both raise {lk} at the same angle"] += 1
        else:
            counts[f"different: legacy {lk}, port {pk}"] += 1
    return counts, worst


def one_ulp_up(x: float) -> float:
    """The next REAL*4 number above x (the build's arguments are REAL*4)."""
    return float(np.nextafter(np.float32(x), np.float32(np.inf)))


def chaos(geometries: list[dict]) -> tuple[collections.Counter, np.ndarray]:
    """Per geometry, the largest effect on legacy of one ulp up in a1, a2, a4 or s1: outcome
    counts, and the relative table moves where the nudged build still returns."""
    counts, moves = collections.Counter(), []
    for g in geometries:
        base_kind, base = outcome(lambda: rahman1996.cssp(**g))
        effect = "smooth"
        for name in ("a1", "a2", "a4", "s1"):
            kind, value = outcome(lambda: rahman1996.cssp(**dict(g, **{name: one_ulp_up(g[name])})))
            if kind != base_kind or (kind != "returns" and value != base):
                effect = "outcome changes"
                break
            if kind == "returns":
                moves.append(relative_difference(base, value))
                effect = "tables jump" if moves[-1] > JUMP or effect == "tables jump" else effect
        counts[(base_kind, effect)] += 1
    return counts, np.array(moves)


def legacy_cssp(g: dict) -> dict:
    """The build's tables and both passes' positions."""
    leg = rahman1996.cssp(**g)
    return {"table": leg["table"], "positions": leg["positions"]}


def port_cssp(g: dict) -> dict:
    """The port's (CSSP_PRINTED) tables, and both passes of the printed Newton's positions."""
    inputs = CsspInputs(**g)
    table = balance(inputs, CSSP_PRINTED)["table"]
    return {"table": table, "positions": np.stack([motion.q for motion in _listing_motions(inputs, True, True)])}


DIFFERENTIAL = Thesis(
    title="Rahman (1996), the CSSP balancing program",
    parameters=(Parameter("a1", "in", limits=(1 / LARGEST, LARGEST)), Parameter("a2", "in", limits=(1 / LARGEST, LARGEST)),
                Parameter("a4", "in", limits=(-LARGEST, LARGEST)), Parameter("alpha4_deg", "deg", limits=(-LARGEST, LARGEST)),
                Parameter("s1", "in", limits=(-LARGEST, LARGEST)), Parameter("rpm", "rpm", limits=(1 / LARGEST, LARGEST))),
    domains=(Domain("sample", "the CSSP's fixed sample (the one docs/port-and-legacy.md shows at seed 1): a1 ~ U(0.5, 4), "
                    "a2 ~ U(3, 12), a4 ~ U(-3, 3) in, alpha4 ~ U(0, 360) deg, s1 ~ U(-1, 1) in, 3000 rpm.", draw),),
    programs=(Program("cssp", "CSSP (legacy cssp, port balance(..., CSSP_PRINTED))", legacy_cssp, port_cssp,
                      dict(CsspInputs().__dict__), rtol={"table": TABLE_RTOL}),),
    criterion=f"the same outcome (both return, or both raise the same error at the same crank angle) and, where both "
              f"return, the printed Newton's positions of both passes equal bit for bit (the port runs it in the "
              f"listing's order of operations) and Tables 5.2-5.7 within {TABLE_RTOL:g} of each column's largest "
              f"|value| (the loads after the Newton are numpy, summed in another order than the listing's loops), as "
              f"tests/rahman1996/test_differential.py asserts.",
)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m linkrepro.harness.scenes.rahman1996.differential", description=__doc__.split("\n")[0])
    parser.add_argument("--geometries", type=int, default=500)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)
    geometries = sample(args.geometries, args.seed)
    agreement, worst = port_against_legacy(geometries)
    print(f"CSSP, port (CSSP_PRINTED) against legacy, {len(geometries)} geometries (seed {args.seed}):")
    for what, n in sorted(agreement.items()):
        print(f"  {n:5d}  {what}")
    print(f"  largest table difference where both return: {worst:.1e} of the column's largest value")
    counts, moves = chaos(geometries)
    print("legacy itself, one REAL*4 ulp up in a1, a2, a4 or s1:")
    for (kind, effect), n in sorted(counts.items()):
        print(f"  {n:5d}  legacy {kind:22s} {effect}")
    if moves.size:
        print(f"  table moves where both return: median {np.median(moves):.1e}, "
              f"99th percentile {np.percentile(moves, 99):.1e}, largest {moves.max():.1e}")
    return 0 if all(k.startswith("both") for k in agreement) else 1


if __name__ == "__main__":
    raise SystemExit(main())
