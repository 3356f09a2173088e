"""Ali (1977): would the example's links stay elastic?  The peak bending stress per link, quasi-static
and dynamic (scene ali1977-elastodynamics, ``stress.csv``).

The links are the example's 0.5 in round bar (``EXAMPLE.section``: its diameter from the area, d =
sqrt(4 A / pi), c = d / 2, sigma = M c / I = M / S with S = pi d^3 / 32).  The bending moment M:

- quasi-static, the thesis's K.E.D. model (``ked_moments``): the port's own member forces S = beta P
  (eq. 6's beta, the path point's inertia load P, the corrected port), the members as eq. (29) has them:
  the crank a cantilever from O2 with a tip force (S5: moment S5 L1 at O2), the extender a cantilever
  from A with a tip force and moment (S2, S3: S3 + S2 L2 at A), the coupler an end moment at A (S8),
  the follower axial only (no moment).  Massless links with loads at the joints only: the moment is
  linear along every link, its peak at a joint;
- in Exudyn (``exudyn_moments``), from the nodes' rotations: each beam element's moment EI (phi1 -
  phi0) / h (its mean curvature: the moment at its midpoint where the moment is linear), at the
  nodes the neighbouring elements' mean, at a link's ends extrapolated linearly from its last two
  elements (exact for a linear moment).  Exudyn's linear and nonlinear statics (the 300 rpm load
  every 10 deg) and its steady states.

Yield: the thesis says aluminium (E = 1e7 psi; 0.098 lbf/in^3, Cases II and III) but names no alloy;
0.098 lbf/in^3 is 6061's density (0.0975; 2024 and 7075 are 0.100-0.101), so 6061-T6 is assumed, its
tensile yield 35 ksi (the minimum of the design handbooks) to 40 ksi (typical): an assumption, stated
as one.  The strongest common alloy, 7075-T6 (yield about 73 ksi), bounds what
any aluminium could take.

Units: inch, pound-force; moments lbf in, stresses psi; crank angles deg; speeds rev/min.
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ....port.ali1977.case2 import DENSITY
from ....port.ali1977.data import EXAMPLE
from ....port.ali1977.quirks import CORRECTED
from ....port.ali1977.structure import inertia_load
from .structure_dynamics import RPM, SIDES, _mechanics

#: the links reported: the crank, the coupler with its extender (one body), the follower; the members
#: each is made of, and the joint a member's distances are measured from
LINKS = {"crank": ("crank",), "coupler": ("coupler", "extender"), "follower": ("follower",)}
FROM = {"crank": "O2", "coupler": "A", "extender": "A", "follower": "B"}
#: the assumed alloy and its tensile yield (psi): minimum, typical
ALLOY = "6061-T6"
YIELD_PSI = (35.0e3, 40.0e3)
#: a moment below this fraction of the largest is none (the follower's: a two-force member; Exudyn's rounding)
ROUNDING = 1e-9
#: the strongest common aluminium alloy and its typical tensile yield (psi)
STRONGEST = ("7075-T6", 73.0e3)


def section_modulus(section=EXAMPLE.section) -> float:
    """S = I / c (in^3) of the round bar whose area is ``section.area`` (c = d / 2, d = sqrt(4 A / pi))."""
    return section.inertia / (0.5 * math.sqrt(4.0 * section.area / math.pi))


def ked_moments(deg, rpm: float = RPM, side: str = "source") -> dict[str, np.ndarray]:
    """The K.E.D. model's bending moments (lbf in, signed) over ``deg``, from the corrected port's
    member forces S = beta P: {"crank": at O2, "extender": at A, "coupler": at A, "follower": 0}."""
    mech, _ = _mechanics(np.atleast_1d(np.asarray(deg, dtype=float)), side, rpm)
    members = np.einsum("nij,nj->ni", mech.beta, inertia_load(mech.acc, EXAMPLE.mass_lbf, CORRECTED))
    l_ext, l_in, _, _ = mech.flex_lengths
    return {"crank": members[:, 4] * l_in, "extender": members[:, 2] + members[:, 1] * l_ext,
            "coupler": members[:, 7], "follower": np.zeros(len(members))}


def exudyn_moments(model, coordinates) -> dict[str, np.ndarray]:
    """The bending moment (lbf in) at every node of every member of ``model`` (a ``multibody.Model``),
    from its ODE2 ``coordinates`` (..., n): {member: (..., its nodes)}, from the member's first joint."""
    coordinates = np.asarray(coordinates, dtype=float)
    ei = EXAMPLE.section.modulus * EXAMPLE.section.inertia
    lengths = dict(zip(("crank", "extender", "coupler", "follower"), model.rigid.lengths))
    out = {}
    for member, nodes in model.nodes.items():
        phi = coordinates[..., [model.mbs.GetNodeODE2Index(n) + 2 for n in nodes]]
        m = ei * np.diff(phi, axis=-1) / (lengths[member] / (len(nodes) - 1))
        if m.shape[-1] < 2:
            raise ValueError(f"the {member} has {m.shape[-1]} element: its moments need two at least")
        out[member] = np.concatenate([1.5 * m[..., :1] - 0.5 * m[..., 1:2], 0.5 * (m[..., 1:] + m[..., :-1]),
                                      1.5 * m[..., -1:] - 0.5 * m[..., -2:-1]], axis=-1)
    return out


def peaks(moments: dict[str, np.ndarray], deg, lengths: dict[str, float] | None) -> list[dict]:
    """Per link (LINKS), the largest |M| over ``moments`` ({member: (angles, points)} along it, at
    equal spacing from its first joint) and where: the member, the distance from its first joint
    (in; NaN where ``lengths`` is None: one point, the member's largest), the crank angle."""
    rows = []
    for link, members in LINKS.items():
        best = None
        for member in members:
            m = np.abs(np.asarray(moments[member], dtype=float).reshape(len(deg), -1))
            k, j = np.unravel_index(int(np.argmax(m)), m.shape)
            at = math.nan if lengths is None else lengths[member] * j / max(m.shape[1] - 1, 1)
            if best is None or m[k, j] > best["moment_lbf_in"]:
                best = {"link": link, "member": member, "from_joint": FROM[member], "at_in": float(at),
                        "crank_deg": float(deg[k]), "moment_lbf_in": float(m[k, j])}
        rows.append(best)
    return rows


def table(static: pd.DataFrame, runs, limits: dict[str, float]) -> pd.DataFrame:
    """stress.csv: per side, per link, the peak bending moment and stress, quasi-static (the K.E.D.
    model every degree, at RPM and at the side's limit speed ``limits[side]``, its moments at the
    members' first joints; Exudyn's linear and nonlinear statics at RPM, at the angles of ``static``,
    its ``<kind>_moment_<member>`` columns) and dynamic (the SteadyStates ``runs``, their ``moments``)."""
    from . import multibody as mb
    deg = np.arange(0.0, 360.0, 1.0)
    rows = []
    for side in SIDES:
        parts = [("quasi-static (K.E.D., the port)", rpm, ked_moments(deg, rpm, side), deg, dict.fromkeys(FROM, 0.0))
                 for rpm in (RPM, limits[side])]
        st = static[static["side"] == side]
        for kind, name in (("exudyn_linear", "linear static (Exudyn)"), ("nonlinear", "nonlinear static (Exudyn)")):
            parts.append((name, RPM, {m: st[f"{kind}_moment_{m}"].to_numpy() for m in FROM}, st["crank_deg"].to_numpy(),
                          None))
        lengths = dict(zip(("crank", "extender", "coupler", "follower"), mb.rigid(side, [0.0]).lengths))
        parts += [("steady state (Exudyn)", run.rpm, run.moments, run.deg, lengths) for run in runs if run.side == side]
        for model, rpm, moments, angles, along in parts:
            rows += [{"side": side, "model": model, "rpm": float(rpm), **row} for row in peaks(moments, angles, along)]
    out = pd.DataFrame(rows)
    out["stress_psi"] = out["moment_lbf_in"] / section_modulus()
    out["stress_over_yield"] = out["stress_psi"] / YIELD_PSI[0]
    return out


def static_columns(kind: str, moments: dict[str, np.ndarray]) -> dict:
    """statics.csv's columns of one solve (``exudyn_moments`` of one state): per member, its moment
    (lbf in) of the largest size along it, ``<kind>_moment_<member>``."""
    return {f"{kind}_moment_{member}": float(m[np.argmax(np.abs(m))]) for member, m in moments.items()}


def _one(frame: pd.DataFrame, side: str, model: str, rpm: float, link: str) -> pd.Series:
    rows = frame[(frame["side"] == side) & (frame["model"] == model) & (frame["rpm"] == rpm) & (frame["link"] == link)]
    return rows.iloc[0]


def _where(r) -> str:
    """Where a peak is: the member, and the joint or the distance from it (or, unknown, the member alone)."""
    if math.isnan(r.at_in):
        return f"the {r.member}"
    return f"the {r.member} at {r.from_joint}" if r.at_in == 0.0 else f"the {r.member} {r.at_in:.1f} in from {r.from_joint}"


def _words(r: pd.Series) -> str:
    return (f"{r.moment_lbf_in:.0f} lbf in ({_where(r)}, crank angle {r.crank_deg:g} deg): {r.stress_psi / 1e3:.1f} ksi, "
            f"{r.stress_over_yield:.2f} times the yield")


def _verdict(psi: float) -> str:
    """Whether a stress (psi) stays under the assumed alloy's yield, and under the strongest's."""
    if psi < YIELD_PSI[0]:
        return f"stays elastic ({psi / 1e3:.1f} ksi)"
    if psi < STRONGEST[1]:
        return f"yields ({psi / 1e3:.1f} ksi; {STRONGEST[0]} would hold)"
    return f"yields ({psi / 1e3:.0f} ksi, {psi / STRONGEST[1]:.1f} times even {STRONGEST[0]}'s yield)"


def report_lines(frame: pd.DataFrame, limit_rpm: float) -> list[str]:
    """report.md's section: would the source's links stay elastic, at RPM and at ``limit_rpm`` (its
    speed limit), quasi-statically and dynamically; then stress.csv as a table."""
    ked, nonlinear, dynamic = "quasi-static (K.E.D., the port)", "nonlinear static (Exudyn)", "steady state (Exudyn)"
    src = frame[frame["side"] == "source"]
    near = float(src.loc[(src["model"] == dynamic) & (src["rpm"] != RPM), "rpm"].iloc[0])
    worst = {key: src[(src["model"] == model) & (src["rpm"] == rpm)]["stress_psi"].max()
             for key, model, rpm in (("ked", ked, RPM), ("dynamic", dynamic, RPM), ("ked_limit", ked, limit_rpm),
                                     ("dynamic_limit", dynamic, near))}
    lines = ["", "## Would the example stay elastic?", "",
             f"The thesis says aluminium (E = {EXAMPLE.section.modulus / 1e6:g}e6 psi; {DENSITY:g} lbf/in^3 in Cases II and "
             f"III) but names no alloy; {DENSITY:g} lbf/in^3 is 6061's density, so assumed here: {ALLOY}, tensile yield "
             f"{YIELD_PSI[0] / 1e3:.0f} ksi (the handbooks' minimum) to {YIELD_PSI[1] / 1e3:.0f} ksi (typical); the "
             f"strongest common alloy, {STRONGEST[0]}, yields at about {STRONGEST[1] / 1e3:.0f} ksi. The links are the "
             f"example's round bar (d = {2.0 * math.sqrt(EXAMPLE.section.area / math.pi):.2f} in, S = pi d^3 / 32 = "
             f"{section_modulus():.4f} in^3): sigma = M c / I. Stress over the {YIELD_PSI[0] / 1e3:.0f} ksi yield:",
             "",
             f"- **At {RPM:g} rpm, quasi-statically** (the K.E.D. model, the port's member forces, every degree): the "
             f"coupler {_words(_one(src, 'source', ked, RPM, 'coupler'))}; the crank "
             f"{_words(_one(src, 'source', ked, RPM, 'crank'))}. Exudyn's nonlinear statics (every 10 deg): the "
             f"coupler {_words(_one(src, 'source', nonlinear, RPM, 'coupler'))}. The follower, a two-force member, "
             "carries no bending.",
             f"- **At {RPM:g} rpm, dynamically** (Exudyn's steady state): the crank "
             f"{_words(_one(src, 'source', dynamic, RPM, 'crank'))}; the coupler "
             f"{_words(_one(src, 'source', dynamic, RPM, 'coupler'))}.",
             f"- **At the speed limit, {limit_rpm:.0f} rpm**: quasi-statically the largest stress is "
             f"{worst['ked_limit'] / 1e3:.1f} ksi; dynamically (Exudyn's steady state at the limit, {near:.2f} rpm) "
             f"{worst['dynamic_limit'] / 1e3:.1f} ksi.",
             f"- **So**: at its design speed the thesis's example {_verdict(worst['dynamic'])} dynamically, and "
             f"{_verdict(worst['ked'])} under the thesis's own quasi-static loads; at the speed limit it "
             f"{_verdict(max(worst['ked_limit'], worst['dynamic_limit']))}. Its {RPM:g} rpm deflections are those of a "
             "linkage past its yield: linear elasticity, which the 1977 method and Exudyn's beams both assume, no longer "
             "holds there.",
             "", "| side | model | rpm | link | peak moment (lbf in) | where | crank (deg) | stress (ksi) | / yield |",
             "|---|---|---|---|---|---|---|---|---|"]
    rounding = ROUNDING * frame["moment_lbf_in"].max()
    lines += [f"| {r.side} | {r.model} | {r.rpm:.1f} | {r.link} | {r.moment_lbf_in:.1f} | "
              + (f"{_where(r)} | {r.crank_deg:g}" if r.moment_lbf_in > rounding else "none | ")
              + f" | {r.stress_psi / 1e3:.2f} | {r.stress_over_yield:.2f} |" for r in frame.itertuples()]
    return lines
