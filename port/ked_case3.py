"""Case III of Ali (1977): the extender's mass distributed over n nodes.

The listing (n = 5) puts node k at distance r_k = L2 - (k-1) L2/n from the crank
pin, gives it the weight density*area*r_k (the extender up to it, D033) and
treats every node as a separate Case I structure with an extender of length r_k:
beta* and F* block-diagonal (chapter IV), so a node deflects under its own load
only (D034).  With those quirks off the port is a structural model: the
extender is n beam segments in series, every node loads the whole structure, and
the tip deflection is their superposition (unit-load method), each node carrying
its own segment's weight density*area*L2/n.
Units: inch, pound-force, second; degrees for ``deg``.
"""
from __future__ import annotations

import numpy as np

from .fourbar import Lengths, check_finite
from .ked_case1 import (EXAMPLE, GRAVITY_IN, Section, _pi, cognate_mechanics, deflection, flexibility,
                        source_mechanics)
from .quirks import PRINTED, Quirks
from .real4 import store

#: The bugs the Case III source listing has: Case I's fixed I1 (L3), the bending
#: flexibility (E*I), 60 deg and 300 rpm; it adds the node masses and the uncoupled nodes.
LISTING = PRINTED.without("source_alpha_101", "source_rpm_400", "i_coefficient", "input_link_bending_area",
                          "cognate_frame", "cognate_moment_row", "joint_load_components",
                          "joint_b_acceleration_sign")
#: The reconstruction's quirks for the cognate (no listing, D037): the Case I cognate
#: listing's bugs with the Case III source listing's changes (E*I bending, node weights).
COGNATE_LISTING = PRINTED.without("source_alpha_101", "source_rpm_400", "i_coefficient", "g_coefficient",
                                  "omega3_sign", "input_link_bending_area", "joint_load_components",
                                  "joint_b_acceleration_sign")
DENSITY = 0.098          # lbf/in^3 (DNTY)


def node_positions(l2: float, n: int) -> np.ndarray:
    """Distances (in) of the n nodes from the crank pin, tip first: L2, L2 - L2/n, ..."""
    if int(n) != n or n < 1:
        raise ValueError(f"the number of sub-elements must be an integer >= 1, got {n!r}")
    return l2 - np.arange(n) * (l2 / n)


def node_weights(positions, l2, density, area, quirks: Quirks) -> np.ndarray:
    """Weight (lbf) at each node.  The listing: density*(area*r_k), the volumes of
    nodes 2.. in REAL*4 (VOL21.. are undeclared); corrected: density*area*L2/n each."""
    if quirks.node_mass_from_pin:                                                   # D033
        volumes = area * positions
        if quirks.real4_storage:
            volumes = np.concatenate([volumes[:1], store(volumes[1:], True).astype(np.float64)])
        return volumes * density
    return np.full(len(positions), density * area * (l2 / len(positions)))


def _load(mech, weight, quirks: Quirks) -> np.ndarray:
    """P = (XPAk*Mk)/GC in double, stored REAL*4 by B(k)=Pk; +m*a as printed (D018)."""
    g_const = float(np.float32(32.178) * np.float32(12.0)) if quirks.real4_storage else GRAVITY_IN
    sign = 1.0 if quirks.inertia_sign else -1.0
    xpa, ypa = mech.acc.T
    zero = np.zeros_like(xpa)
    return store(np.stack([sign * ((xpa * weight) / g_const), sign * ((ypa * weight) / g_const), zero], -1),
                 quirks.real4_storage)


def _coupled_tip(mechs, loads, positions, lengths: Lengths, section: Section, quirks: Quirks):
    """Tip deflection (N, 3) of the extender as n segments in series, all nodes loaded.

    Virtual work with unit loads at the tip: sum over elements of u^T F f.  Segment j
    (between nodes, outer node j) carries every load beyond it: axial, shear and the
    shear's moment about node j; the crank, follower and coupler carry the sum of each
    node's Case I reaction (rows f4..f8 of that node's beta).
    """
    ca, me, mi = section.area, section.modulus, section.inertia
    ascending = np.argsort(positions)
    r = positions[ascending]                                  # node radii, pin outward
    seg = np.diff(np.concatenate([[0.0], r]))                 # segment lengths
    tip = mechs[int(np.argmax(positions))]
    t = tip.extra["ext_angle"]
    c, s = np.cos(t), np.sin(t)
    loads = loads[ascending]                                  # (n, N, 3)
    axial = loads[..., 0] * c + loads[..., 1] * s             # (n, N)
    shear = -loads[..., 0] * s + loads[..., 1] * c
    outward = lambda v: np.cumsum(v[::-1], axis=0)[::-1]      # noqa: E731  sum over nodes k >= j
    n_force, v_force = outward(axial), outward(shear)
    m_force = outward(shear * r[:, None]) - r[:, None] * v_force
    rows = sum(mechs[k].beta[:, 3:8, :2] @ loads[j, :, :2, None] for j, k in enumerate(ascending))[..., 0]
    l_tip = r[-1]
    delta = np.zeros((len(t), 3))
    unit = {0: (c, -s, 0.0), 1: (s, c, 0.0), 2: (0.0 * c, 0.0 * c, 1.0)}
    e_flex = np.array([lengths.l1 / (ca * me),
                       lengths.l1 ** 3 / (3.0 * (ca if quirks.input_link_bending_area else mi) * me),
                       lengths.l4 / (ca * me), lengths.l3 / (ca * me), lengths.l3 / (3.0 * me * mi)])
    for i, (un, uv, um) in unit.items():
        for j, h in enumerate(seg):
            uv_j, um_j = uv * np.ones_like(t), um + (l_tip - r[j]) * uv
            delta[:, i] += un * n_force[j] * h / (ca * me)
            delta[:, i] += uv_j * (v_force[j] * h ** 3 / (3 * me * mi) + m_force[j] * h ** 2 / (2 * me * mi))
            delta[:, i] += um_j * (v_force[j] * h ** 2 / (2 * me * mi) + m_force[j] * h / (me * mi))
        delta[:, i] += np.einsum("ne,e,ne->n", tip.beta[:, 3:8, i], e_flex, rows)
    return delta


def case3_source(deg, n: int = 5, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                 rpm: float = EXAMPLE.rpm, density: float = DENSITY,
                 section: Section = EXAMPLE.section, quirks: Quirks = LISTING,
                 all_nodes: bool = False) -> dict:
    """Case III, source four-bar with n sub-elements: ``xp, yp`` (in) and the path
    point's ``dx, dy`` (in), ``rot`` (rad).  With ``all_nodes`` (uncoupled model only)
    also ``nodes`` (N, n, 3), tip first, as the listing prints them.
    """
    deg = np.atleast_1d(np.asarray(deg, dtype=np.float64))
    if not np.isfinite(density) or density < 0:
        raise ValueError(f"density must be finite and >= 0, got {density!r}")
    real4 = quirks.real4_storage
    alp = _pi(quirks) / 3.0 if alp is None else alp
    sec = section.as_listing_holds(real4)
    dens = float(np.float32(density)) if real4 else float(density)
    positions = node_positions(lengths.l2, n)
    weights = node_weights(positions, lengths.l2, dens, sec.area, quirks)
    # Model only what is needed: the uncoupled listing needs the tip block alone.
    wanted = range(n) if (all_nodes or not quirks.uncoupled_nodes) else range(1)
    mechs = {k: source_mechanics(deg, Lengths(lengths.l1, positions[k], lengths.l3, lengths.l4, lengths.l5),
                                 alp, rpm, quirks, speed_type="REAL") for k in wanted}
    with np.errstate(invalid="ignore", over="ignore"):
        loads = {k: _load(mechs[k], weights[k], quirks) for k in wanted}
        if quirks.uncoupled_nodes:                                                  # D034
            blocks = {k: deflection(mechs[k].beta, flexibility(positions[k], lengths.l1, lengths.l3,
                                                               lengths.l4, sec, quirks), loads[k], quirks)
                      for k in wanted}
            tip = blocks[0].astype(np.float64)
        else:
            if all_nodes:
                raise ValueError("all_nodes is the uncoupled (listing) model's output")
            tip = _coupled_tip([mechs[k] for k in range(n)], np.array([loads[k] for k in range(n)]),
                               positions, lengths, sec, quirks)
    out = {"xp": mechs[0].xp, "yp": mechs[0].yp, "dx": tip[:, 0], "dy": tip[:, 1], "rot": tip[:, 2]}
    if all_nodes:
        out["nodes"] = np.stack([blocks[k].astype(np.float64) for k in range(n)], axis=1)
    check_finite(deg, "case III source", **out)
    return out


def case3_cognate(deg, n: int = 5, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                  rpm: float = EXAMPLE.rpm, density: float = DENSITY,
                  section: Section = EXAMPLE.section, quirks: Quirks = COGNATE_LISTING) -> dict:
    """Case III, crossed cognate: a RECONSTRUCTION (D037: Appendix D prints no cognate
    program; the same reconstruction is legacy/src/ali1977_case3_cognate.f): the source
    listing's node scheme on the Case I cognate (the listing's
    quirks: the tip block, the cognate extender's weight at the path point) or, with
    D033/D034 off, the coupled n-segment model along the cognate's extender.
    Returns ``xp, yp``, ``dx, dy`` (in), ``rot`` (rad)."""
    deg = np.atleast_1d(np.asarray(deg, dtype=np.float64))
    real4 = quirks.real4_storage
    sec = section.as_listing_holds(real4)
    dens = float(np.float32(density)) if real4 else float(density)
    tip_mech = cognate_mechanics(deg, lengths, alp, rpm, quirks)
    cog = tip_mech.extra["cognate"]
    positions = node_positions(cog.cl2, n)
    weights = node_weights(positions, cog.cl2, dens, sec.area, quirks)
    cog_lengths = Lengths(cog.cl1, cog.cl2, cog.cl3, cog.cl4, cog.cl5)
    with np.errstate(invalid="ignore", over="ignore"):
        if quirks.uncoupled_nodes:                                                  # D034
            flex = flexibility(cog.cl2, cog.cl1, cog.cl3, cog.cl4, sec, quirks)
            delta = deflection(tip_mech.beta, flex, _load(tip_mech, weights[0], quirks), quirks)
        else:
            mechs = [tip_mech] + [cognate_mechanics(deg, lengths, alp, rpm, quirks, extender=r)
                                  for r in positions[1:]]
            loads = np.array([_load(m, w, quirks) for m, w in zip(mechs, weights)])
            delta = _coupled_tip(mechs, loads, positions, cog_lengths, sec, quirks)
    mech = tip_mech
    dx, dy = delta[:, 0].astype(np.float64), delta[:, 1].astype(np.float64)
    if not quirks.cognate_frame:                                                     # D025
        c, s = np.cos(mech.frame_angle), np.sin(mech.frame_angle)
        dx, dy = dx * c - dy * s, dx * s + dy * c
    out = {"xp": mech.extra["xp"], "yp": mech.extra["yp"], "dx": dx, "dy": dy, "rot": delta[:, 2].astype(np.float64)}
    check_finite(deg, "case III cognate", **out)
    return out


__all__ = ["LISTING", "COGNATE_LISTING", "DENSITY", "node_positions", "node_weights", "case3_source",
           "case3_cognate"]
