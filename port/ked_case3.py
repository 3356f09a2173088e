"""Case III of Ali (1977): the extender's mass distributed over n nodes.

The listing (n = 5) puts its nodes at r_k = L2, L2-2.0, ..., L2-8.0 in from the crank
pin (2 in apart: the example's L2/5 written as a constant; the port's listing model keeps
that spacing, 10 in/n, for any L2 and n), gives node k the weight
density*area*r_k (the extender up to it, D033) and treats every node as a separate
Case I structure with an extender of length r_k: beta* (40 x 15) and F* (40 x 40)
block-diagonal (chapter IV), so a node deflects under its own load only (D034).
Its blocks carry two slips the port reproduces, each its own switch: block 1's third
column stored in block 2's rows (D035, ``tip_rotation_node_2``: the tip rotation is taken
through node 2's structure) and U(470) (D036, ``u470_operands``: node 4's rotation).  With those quirks off the port is
a structural model: the extender is n beam segments in series (L2/n long), every
node loads the whole structure, and the tip deflection is their superposition
(unit-load method), each node carrying its own segment's weight density*area*L2/n.
Units: inch, pound-force, second; degrees for ``deg``.  Arguments and errors as in
``ked_case1``; ``n`` an integer 1..10000.
"""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from ..checks import angles_deg, as_real4, parameter, weight_lbf
from . import libm
from .fourbar import Lengths, check_finite
from .ked_case1 import (EXAMPLE, GRAVITY_IN, Section, _pi, cognate_mechanics, cramer_determinant, deflection,
                        expect, flexibility, source_mechanics)
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
#: The listing's nodes are L21=L2-2.0, L22=L2-4.0, L23=L2-6.0, L24=L2-8.0: its example's
#: extender (10 in) over its 5 nodes, as a constant; for n nodes, this length over n.
LISTING_EXTENDER = 10.0
#: The most sub-elements the port accepts.
MAX_NODES = 10_000


def node_count(n) -> int:
    """``n`` as an int: an integer (or integral real) from 1 to MAX_NODES."""
    value = parameter("n", n, largest=None)
    if value != int(value) or not 1 <= value <= MAX_NODES:
        raise ValueError(f"the number of sub-elements must be an integer from 1 to {MAX_NODES}, got {n!r}")
    return int(value)


def node_positions(l2: float, n: int, spacing: float | None = None) -> np.ndarray:
    """Distances (in) of the n nodes from the crank pin, tip first: L2, L2 - s, ..., L2 - (n-1) s,
    with s = L2/n, or ``spacing`` (the listing's blocks: LISTING_EXTENDER/n, 2 in for n = 5)."""
    n = node_count(n)
    step = l2 / n if spacing is None else spacing
    positions = l2 - np.arange(n) * step
    if not positions[-1] > 0.0:
        raise ValueError(f"l2={l2}: nodes L2, L2-{step:g}, ..., L2-{(n - 1) * step:g} need l2 > {(n - 1) * step:g} in")
    return positions


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
    c, s = libm.cos(t), libm.sin(t)
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
                       lengths.l1 * lengths.l1 * lengths.l1 / (3.0 * (ca if quirks.input_link_bending_area else mi) * me),
                       lengths.l4 / (ca * me), lengths.l3 / (ca * me), lengths.l3 / (3.0 * me * mi)])
    for i, (un, uv, um) in unit.items():
        for j, h in enumerate(seg):
            uv_j, um_j = uv * np.ones_like(t), um + (l_tip - r[j]) * uv
            delta[:, i] += un * n_force[j] * h / (ca * me)
            delta[:, i] += uv_j * (v_force[j] * h ** 3 / (3 * me * mi) + m_force[j] * h ** 2 / (2 * me * mi))
            delta[:, i] += um_j * (v_force[j] * h ** 2 / (2 * me * mi) + m_force[j] * h / (me * mi))
        delta[:, i] += np.einsum("ne,e,ne->n", tip.beta[:, 3:8, i], e_flex, rows)
    return delta


def _listing_blocks(mechs, quirks: Quirks):
    """The listing's two copies of beta* (statements 0105-0147 for GMTRA, 0384-0426 for the
    product), block by block: (left, right) per node, each (N, 8, 3).

    Rows f7 are written with the listing's association (L2k/L3 or L2/L3 as it groups them),
    and D036: the first copy holds U(470)=(A1*D1-B1*I1)/R4, the second (A1*D1-B1*E1)/R4, for
    node 4's (A1*E1-B1*D1)/R4.  D035 (block 1's third column in block 2's rows) is applied by
    the caller, on the products."""
    blocks = []
    tip_i1 = mechs[0].extra["coefficients"][8]
    for k, mech in enumerate(mechs):
        e = mech.extra
        r, l3 = mech.flex_lengths[0], mech.flex_lengths[2]
        ctx, s, c = e["ctx"], libm.sin(e["ext_angle"]), libm.cos(e["ext_angle"])
        left, right = mech.beta.copy(), mech.beta.copy()
        left[:, 6, 0] = ((ctx * s) * r) / l3                  # U(7)=CTX*DSIN(T3+ALP)*L2/L3 (... L21/L3)
        if k:
            right[:, 6, 0] = left[:, 6, 0]
            left[:, 6, 1] = right[:, 6, 1] = -(((ctx * c) * r) / l3)   # -(CTX*DCOS(T3+ALP))*L21/L3
        if k == 3 and quirks.u470_operands:                                         # D036
            a, b, _, d, e1, *_ = e["coefficients"]
            r4 = cramer_determinant(*e["coefficients"])
            left[:, 5, 2] = ((a * d) - (b * tip_i1)) / r4
            right[:, 5, 2] = ((a * d) - (b * e1)) / r4
        blocks.append((left, right))
    return blocks


def _listing_deflections(mechs, loads, positions, lengths: Lengths, section: Section, quirks: Quirks):
    """dx, dy, rot of every node (N, n, 3) as the listing's block-diagonal product gives them
    (D034), MPRD's order and REAL*4 storage: blocks do not mix, but for D035, the tip
    rotation taken with block 1's third column through node 2's F and beta."""
    flex = [flexibility(r, lengths.l1, lengths.l3, lengths.l4, section, quirks, modulus_first=True)
            for r in positions]                                   # B(165)=(L1*L1*L1)/(3.0*CE*CI)
    blocks = _listing_blocks(mechs, quirks)
    nodes = [deflection(left, flex[k], loads[k], quirks, right=right) for k, (left, right) in enumerate(blocks)]
    if len(mechs) > 1 and quirks.tip_rotation_node_2:                               # D035
        nodes[0][:, 2] = deflection(blocks[0][0][:, :, 2:3], flex[1], loads[1], quirks, right=blocks[1][1])[:, 0]
    return np.stack([d.astype(np.float64) for d in nodes], axis=1)


def case3_source(deg, n: int = 5, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                 rpm: float = EXAMPLE.rpm, density: float = DENSITY,
                 section: Section = EXAMPLE.section, quirks: Quirks = LISTING,
                 all_nodes: bool = False) -> dict:
    """Case III, source four-bar with n sub-elements: ``xp, yp`` (in) and the path
    point's ``dx, dy`` (in), ``rot`` (rad).  With ``all_nodes`` (uncoupled model only)
    also ``nodes`` (N, n, 3), tip first, as the listing prints them.

    The uncoupled (listing) model places its nodes 10/n in apart (2 in for the listing's
    five: ValueError unless l2 > 10 (n-1)/n, 8 in for n = 5) and computes every node, as
    the listing does: a non-finite value at any node is a SingularPositionError there.
    """
    deg = angles_deg("deg", deg)
    n = node_count(n)
    density = weight_lbf("density", density)
    expect("lengths", lengths, Lengths)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    real4 = quirks.real4_storage
    alp = _pi(quirks) / 3.0 if alp is None else alp
    sec = section.as_listing_holds(real4)
    dens = as_real4("density", density) if real4 else density
    listing = quirks.uncoupled_nodes                                                # D034
    if all_nodes and not listing:
        raise ValueError("all_nodes is the uncoupled (listing) model's output")
    positions = node_positions(lengths.l2, n, LISTING_EXTENDER / n if listing else None)
    weights = node_weights(positions, lengths.l2, dens, sec.area, quirks)
    mechs = [source_mechanics(deg, Lengths(lengths.l1, r, lengths.l3, lengths.l4, lengths.l5),
                              alp, rpm, quirks, speed_type="REAL") for r in positions]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        loads = [_load(mech, weight, quirks) for mech, weight in zip(mechs, weights)]
        if listing:
            nodes = _listing_deflections(mechs, loads, positions, lengths, sec, quirks)
            tip = nodes[:, 0, :]
        else:
            tip = _coupled_tip(mechs, np.array(loads), positions, lengths, sec, quirks)
    out = {"xp": mechs[0].xp, "yp": mechs[0].yp, "dx": tip[:, 0], "dy": tip[:, 1], "rot": tip[:, 2]}
    if listing:     # the listing's output is every node: the legacy face checks xp, yp, then all nodes
        check_finite(deg, "case III source", xp=out["xp"], yp=out["yp"], nodes=nodes)
        if all_nodes:
            out["nodes"] = nodes
    else:
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
    Returns ``xp, yp`` (source), ``cxp, cyp`` (the cognate's), ``dx, dy`` (in), ``rot`` (rad), as
    case2_cognate."""
    deg = angles_deg("deg", deg)
    n = node_count(n)
    density = weight_lbf("density", density)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    real4 = quirks.real4_storage
    sec = section.as_listing_holds(real4)
    dens = as_real4("density", density) if real4 else density
    tip_mech = cognate_mechanics(deg, lengths, alp, rpm, quirks)
    cog = tip_mech.extra["cognate"]
    with np.errstate(invalid="ignore", over="ignore"):      # a degenerate cognate's CL2 may be inf
        positions = cog.cl2 - np.arange(n) * (cog.cl2 / n)   # node_positions, unchecked: only the tip's is used
    weights = node_weights(positions, cog.cl2, dens, sec.area, quirks)
    # the cognate's links as they are (a degenerate cognate may have zero or NaN lengths)
    cog_lengths = SimpleNamespace(l1=cog.cl1, l2=cog.cl2, l3=cog.cl3, l4=cog.cl4, l5=cog.cl5)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
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
        c, s = libm.cos(mech.frame_angle), libm.sin(mech.frame_angle)
        dx, dy = dx * c - dy * s, dx * s + dy * c
    out = {"xp": mech.extra["xp"], "yp": mech.extra["yp"], "cxp": mech.extra["cxp"], "cyp": mech.extra["cyp"],
           "dx": dx, "dy": dy, "rot": delta[:, 2].astype(np.float64)}
    check_finite(deg, "case III cognate", **out)
    return out


__all__ = ["LISTING", "COGNATE_LISTING", "DENSITY", "node_positions", "node_weights", "case3_source",
           "case3_cognate", "LISTING_EXTENDER", "MAX_NODES", "node_count"]
