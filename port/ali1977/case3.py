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
``ali1977.case1``; ``n`` an integer 1..10000.  ``case3_linkage`` is the four-bar's motion over an
angle grid, computed once; ``case3_on_linkage`` puts n nodes on it, for any n (the convergence
study's sweep): ``case3_source`` is the two in one call.  The nodes' path points are computed
a block of nodes at a time.
"""
from __future__ import annotations

import functools
from types import SimpleNamespace

import numpy as np

from ...checks import angles_deg, as_real4, parameter, weight_lbf
from .. import libm
from .fourbar import Lengths
from .cognate import _cognate_linkage
from .data import EXAMPLE, _pi, expect
from .linkage import cramer_determinant
from .source import SourceLinkage, _source_linkage
from .structure import GRAVITY_IN, GRAVITY_REAL4, Section, deflection, flexibility, magnitude
from .quirks import PRINTED, Quirks
from ..real4 import store

#: The bugs the Case III source listing has: Case I's fixed I1 (L3), the bending
#: flexibility (E*I), 60 deg and 300 rpm; it adds the node masses and the uncoupled nodes.
LISTING = PRINTED.without("source_alpha_101", "source_rpm_400", "i_coefficient", "input_link_bending_area",
                          "cognate_frame", "cognate_moment_row", "joint_load_components",
                          "joint_b_acceleration_sign", "coupler_load_in_f7", "cognate_joint_load_signs")
#: The reconstruction's quirks for the cognate (no listing, D037): the Case I cognate
#: listing's bugs with the Case III source listing's changes (E*I bending, node weights).
COGNATE_LISTING = PRINTED.without("source_alpha_101", "source_rpm_400", "i_coefficient", "g_coefficient",
                                  "omega3_sign", "input_link_bending_area", "joint_load_components",
                                  "joint_b_acceleration_sign", "coupler_load_in_f7", "cognate_joint_load_signs")
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
    l2, n = parameter("l2", l2, positive=True, largest=None), node_count(n)
    step = l2 / n if spacing is None else parameter("spacing", spacing, positive=True, largest=None)
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


def _load(acc, weight, quirks: Quirks) -> np.ndarray:
    """P = (XPAk*Mk)/GC in double, stored REAL*4 by B(k)=Pk; +m*a as printed (D018): loads
    (.., 3) for accelerations ``acc`` (.., 2) in/s^2 and weights (lbf) broadcasting against
    ``acc[..., :1]``."""
    g_const = GRAVITY_REAL4 if quirks.real4_storage else GRAVITY_IN
    sign = 1.0 if quirks.inertia_sign else -1.0
    load = np.zeros(acc.shape[:-1] + (3,))
    load[..., :2] = sign * ((acc * weight) / g_const)
    return store(load, quirks.real4_storage)


#: Node-angle pairs whose path points the n-node models compute at once (bounds the memory).
NODE_BLOCK_SIZE = 2**16


def _node_blocks(linkage, positions):
    """The nodes' path points a block of consecutive nodes at a time (Mechanics with a leading
    node axis), each with the index of its first node: at most NODE_BLOCK_SIZE nodes x angles,
    and at least four nodes, so that the first block holds the listing's nodes 1 to 4."""
    size = max(4, NODE_BLOCK_SIZE // len(linkage.t2))
    for start in range(0, len(positions), size):
        yield start, linkage.path_point(positions[start:start + size, None])


def _coupled_tip(mechs, loads, positions, lengths: Lengths, section: Section, quirks: Quirks):
    """Tip deflection (N, 3) of the extender as n segments in series, all nodes loaded; the same
    sums of the terms' magnitudes (N, 3: the deflection's size before cancellation,
    ``conditioning.cancellation``); and the nodes' ``Linkage.pole_distance`` (N,), or None.

    ``positions`` (n,) are the nodes' distances from the crank pin, tip first (node_positions),
    ``loads`` (n, N, 3) their loads, ``mechs`` their Mechanics in the same order: an iterable,
    read once, of single nodes or of blocks of consecutive nodes (a leading node axis).

    Virtual work with unit loads at the tip: sum over elements of u^T F f.  Segment j
    (between nodes, outer node j) carries every load beyond it: axial, shear and the
    shear's moment about node j; the crank, follower and coupler carry the sum of each
    node's Case I reaction (rows f4..f8 of that node's beta).
    """
    reactions, sizes, tip, k, poles = 0.0, 0.0, None, 0, []
    for mech in mechs:
        beta = mech.beta.reshape((-1,) + mech.beta.shape[-3:])           # (nodes, N, 8, 3)
        tip = (mech.extra["ext_angle"], beta[0]) if tip is None else tip
        reactions = reactions + np.einsum("knij,knj->ni", beta[..., 3:8, :2], loads[k:k + len(beta), :, :2])
        sizes = sizes + np.einsum("knij,knj->ni", np.abs(beta[..., 3:8, :2]), np.abs(loads[k:k + len(beta), :, :2]))
        rho = mech.extra["linkage"].pole_distance(mech)
        poles += [] if rho is None else [rho]
        k += len(beta)
    t, tip_beta = tip
    c, s = libm.cos(t), libm.sin(t)
    delta = _tip_work(c, s, -1.0, loads, tip_beta, reactions, positions, lengths, section, quirks)
    size = _tip_work(np.abs(c), np.abs(s), 1.0, np.abs(loads), np.abs(tip_beta), sizes, positions, lengths, section,
                     quirks)
    return delta, size, (np.minimum.reduce(poles) if poles else None)


def _tip_work(c, s, sign, loads, tip_beta, reactions, positions, lengths: Lengths, section: Section, quirks: Quirks):
    """_coupled_tip's virtual work, from the extender's direction (c, s: its cos and sin), the
    nodes' loads, the tip's beta and the links' reactions; ``sign`` -1.0 (with the magnitudes
    of every input and +1.0: the sum of the terms' magnitudes)."""
    ca, me, mi = section.area, section.modulus, section.inertia
    ascending = np.argsort(positions)
    r = positions[ascending]                                  # node radii, pin outward
    h = np.diff(np.concatenate([[0.0], r]))                   # segment lengths
    loads = loads[ascending]                                  # (n, N, 3)
    axial = loads[..., 0] * c + loads[..., 1] * s             # (n, N)
    shear = sign * loads[..., 0] * s + loads[..., 1] * c
    outward = lambda v: np.cumsum(v[::-1], axis=0)[::-1]      # noqa: E731  sum over nodes k >= j
    n_force, v_force = outward(axial), outward(shear)
    m_force = outward(shear * r[:, None]) + sign * r[:, None] * v_force
    # each segment's work under a unit axial force, shear and moment at the tip (the shear's
    # moment about node j has the arm l_tip - r_j), summed over the segments
    arm = r[-1] - r
    axial_work = (h / (ca * me)) @ n_force
    shear_work = (h ** 3 / (3 * me * mi)) @ v_force + (h ** 2 / (2 * me * mi)) @ m_force
    moment_work = (h ** 2 / (2 * me * mi)) @ v_force + (h / (me * mi)) @ m_force
    arm_work = (arm * h ** 2 / (2 * me * mi)) @ v_force + (arm * h / (me * mi)) @ m_force
    e_flex = np.array([lengths.l1 / (ca * me),
                       lengths.l1 * lengths.l1 * lengths.l1 / (3.0 * (ca if quirks.input_link_bending_area else mi) * me),
                       lengths.l4 / (ca * me), lengths.l3 / (ca * me), lengths.l3 / (3.0 * me * mi)])
    delta = np.zeros((len(c), 3))
    for i, (un, uv, um) in enumerate(((c, sign * s, 0.0), (s, c, 0.0), (0.0, 0.0, 1.0))):   # unit loads at the tip
        delta[:, i] = un * axial_work + uv * (shear_work + arm_work) + um * moment_work
        delta[:, i] += np.einsum("ne,e,ne->n", tip_beta[:, 3:8, i], e_flex, reactions)
    return delta


def _listing_blocks(mech, start: int, quirks: Quirks):
    """The listing's two copies of beta* (statements 0105-0147 for GMTRA, 0384-0426 for the
    product) for a block of nodes from node ``start`` (0: the tip) on: (left, right), each
    (nodes, N, 8, 3).

    Rows f7 are written with the listing's association (L2k/L3 or L2/L3 as it groups them),
    and D036: the first copy holds U(470)=(A1*D1-B1*I1)/R4, the second (A1*D1-B1*E1)/R4, for
    node 4's (A1*E1-B1*D1)/R4.  D035 (block 1's third column in block 2's rows) is applied by
    the caller, on the products."""
    link = mech.extra["linkage"]
    r, l3 = mech.flex_lengths[0], mech.flex_lengths[2]       # r: (nodes, 1)
    ctx, s, c = link.ctx, link.se, link.ce
    left, right = mech.beta.copy(), mech.beta.copy()
    left[..., 6, 0] = ((ctx * s) * r) / l3                    # U(7)=CTX*DSIN(T3+ALP)*L2/L3 (... L21/L3)
    inner = slice(1 if start == 0 else 0, None)               # nodes 2, 3, ...
    right[inner, :, 6, 0] = left[inner, :, 6, 0]
    left[inner, :, 6, 1] = right[inner, :, 6, 1] = -(((ctx * c) * r[inner]) / l3)   # -(CTX*DCOS(T3+ALP))*L21/L3
    if start == 0 and len(r) > 3 and quirks.u470_operands:                          # D036
        a, b, c3, d, e, f, g, h, i = mech.extra["coefficients"]
        r4 = cramer_determinant(a, b, c3, d, e, f, g[3], h[3], i[3])
        left[3, :, 5, 2] = ((a * d) - (b * i[0])) / r4
        right[3, :, 5, 2] = ((a * d) - (b * e)) / r4
    return left, right


def _listing_deflections(linkage, positions, weights, section: Section):
    """dx, dy, rot of every node (N, n, 3) as the listing's block-diagonal product gives them
    (D034), MPRD's order and REAL*4 storage: blocks do not mix, but for D035, the tip
    rotation taken with block 1's third column through node 2's F and beta; the tip's terms'
    size (N, 3, ``structure.magnitude``) and the nodes' ``Linkage.pole_distance`` (or None)."""
    quirks, lengths = linkage.quirks, linkage.lengths
    nodes, poles, size = [], [], None
    for start, mech in _node_blocks(linkage, positions):
        r = mech.flex_lengths[0]
        flex = flexibility(r, lengths.l1, lengths.l3, lengths.l4, section, quirks,
                           modulus_first=True)                    # B(165)=(L1*L1*L1)/(3.0*CE*CI)
        left, right = _listing_blocks(mech, start, quirks)
        loads = _load(mech.acc, weights[start:start + len(r), None, None], quirks)
        block = deflection(left, flex, loads, quirks, right=right)
        if start == 0:
            size = magnitude(left[0], flex[0], loads[0], right[0])
        if start == 0 and len(positions) > 1 and quirks.tip_rotation_node_2:        # D035
            block[0, :, 2] = deflection(left[0, :, :, 2:3], flex[1], loads[1], quirks, right=right[1])[:, 0]
            size[:, 2] = magnitude(left[0, :, :, 2:3], flex[1], loads[1], right[1])[:, 0]
        nodes.append(block)
        rho = linkage.pole_distance(mech)
        poles += [] if rho is None else [rho]
    return (np.moveaxis(np.concatenate(nodes).astype(np.float64), 0, 1), size,
            np.minimum.reduce(poles) if poles else None)


def case3_linkage(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                  rpm: float = EXAMPLE.rpm, quirks: Quirks = LISTING):
    """The source four-bar's motion over ``deg`` as Case III takes it (the listing's REAL*4
    speed; ``alp`` by default 60 deg with the listing's pi): a SourceLinkage, to be computed
    once for an angle grid and given to case3_on_linkage for every n (its quirks go with it)."""
    return _case3_linkage(angles_deg("deg", deg), lengths, alp, rpm, quirks)


def _case3_linkage(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float, quirks: Quirks):
    """case3_linkage of checked angles ``deg``."""
    expect("quirks", quirks, Quirks)
    alp = _pi(quirks) / 3.0 if alp is None else alp
    return _source_linkage(deg, lengths, alp, rpm, quirks, "REAL")


def _nodes(n, l2: float, density, section: Section, quirks: Quirks, all_nodes: bool):
    """The section as the listing holds it, the nodes' positions (tip first) and weights."""
    sec = section.as_listing_holds(quirks.real4_storage)
    dens = as_real4("density", density) if quirks.real4_storage else density
    listing = quirks.uncoupled_nodes                                                # D034
    if all_nodes and not listing:
        raise ValueError("all_nodes is the uncoupled (listing) model's output")
    positions = node_positions(l2, n, LISTING_EXTENDER / n if listing else None)
    return sec, positions, node_weights(positions, l2, dens, sec.area, quirks)


def _case3_on(linkage, sec: Section, positions, weights, all_nodes: bool):
    """Case III's tip (and with ``all_nodes`` every node) on a linkage, and its precision check
    (as ``case1.run_source_case1``); see case3_source."""
    quirks, deg = linkage.quirks, linkage.deg
    listing = quirks.uncoupled_nodes                                                # D034
    xp, yp = linkage.position(positions[0])
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        if listing:
            nodes, size, rho = _listing_deflections(linkage, positions, weights, sec)
            tip = nodes[:, 0, :]
        else:
            loads = _load(linkage.acceleration(positions[:, None]), weights[:, None, None], quirks)
            blocks = (mech for _, mech in _node_blocks(linkage, positions))
            tip, size, rho = _coupled_tip(blocks, loads, positions, linkage.lengths, sec, quirks)
    out = {"xp": xp, "yp": yp, "dx": tip[:, 0], "dy": tip[:, 1], "rot": tip[:, 2]}
    finite = None
    if listing:     # the listing's output is every node: the legacy face checks xp, yp, then all nodes
        finite = {"xp": out["xp"], "yp": out["yp"], "nodes": nodes}
        if all_nodes:
            out["nodes"] = nodes
    return out, functools.partial(linkage.finish, rho=rho, size=size, extender=positions[0], finite=finite)


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
    The same as case3_on_linkage(case3_linkage(deg, lengths, alp, rpm, quirks), n, ...).
    """
    out, finish = run_case3_source(angles_deg("deg", deg), n, lengths, alp, rpm, density, section, quirks, all_nodes)
    return finish(out, "case III source")


def run_case3_source(deg: np.ndarray, n: int, lengths: Lengths, alp: float | None, rpm: float, density: float,
                     section: Section, quirks: Quirks, all_nodes: bool = False):
    """case3_source of checked angles ``deg``, before its precision check (as
    ``case1.run_source_case1``)."""
    n = node_count(n)
    density = weight_lbf("density", density)
    expect("lengths", lengths, Lengths)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    sec, positions, weights = _nodes(n, lengths.l2, density, section, quirks, all_nodes)
    return _case3_on(_case3_linkage(deg, lengths, alp, rpm, quirks), sec, positions, weights, all_nodes)


def case3_on_linkage(linkage: SourceLinkage, n: int = 5, density: float = DENSITY,
                     section: Section = EXAMPLE.section, all_nodes: bool = False) -> dict:
    """case3_source on a linkage from case3_linkage (its angles, lengths and quirks): the
    four-bar's kinematics computed once for an angle grid, reused for every n and section."""
    expect("linkage", linkage, SourceLinkage)
    n = node_count(n)
    density = weight_lbf("density", density)
    expect("section", section, Section)
    sec, positions, weights = _nodes(n, linkage.lengths.l2, density, section, linkage.quirks, all_nodes)
    out, finish = _case3_on(linkage, sec, positions, weights, all_nodes)
    return finish(out, "case III source")


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
    out, finish = run_case3_cognate(angles_deg("deg", deg), n, lengths, alp, rpm, density, section, quirks)
    return finish(out, "case III cognate")


def run_case3_cognate(deg: np.ndarray, n: int, lengths: Lengths, alp: float | None, rpm: float, density: float,
                      section: Section, quirks: Quirks, warn_beta: bool = True):
    """case3_cognate of checked angles ``deg``, before its precision check (as
    ``case1.run_cognate_case1``)."""
    n = node_count(n)
    density = weight_lbf("density", density)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    real4 = quirks.real4_storage
    sec = section.as_listing_holds(real4)
    dens = as_real4("density", density) if real4 else density
    tip_mech = _cognate_linkage(deg, lengths, alp, rpm, quirks, warn_beta).path_point()
    cog = tip_mech.extra["cognate"]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):     # a degenerate cognate's CL2 may be inf
        positions = cog.cl2 - np.arange(n) * (cog.cl2 / n)   # node_positions, unchecked: only the tip's is used
        weights = node_weights(positions, cog.cl2, dens, sec.area, quirks)
        # the cognate's links as they are (a degenerate cognate may have zero or NaN lengths)
        cog_lengths = SimpleNamespace(l1=cog.cl1, l2=cog.cl2, l3=cog.cl3, l4=cog.cl4, l5=cog.cl5)
        if quirks.uncoupled_nodes:                                                  # D034
            flex = flexibility(cog.cl2, cog.cl1, cog.cl3, cog.cl4, sec, quirks)
            load = _load(tip_mech.acc, weights[0], quirks)
            delta, size = deflection(tip_mech.beta, flex, load, quirks), magnitude(tip_mech.beta, flex, load)
            rho = tip_mech.extra["linkage"].pole_distance(tip_mech)
        else:
            inner = positions[1:]
            if not np.isfinite(inner).all():        # as cognate_mechanics(extender=...) refuses a node there
                parameter("extender", inner[~np.isfinite(inner)][0], largest=None)
            linkage = tip_mech.extra["linkage"]
            loads = _load(linkage.acceleration(positions[:, None]), weights[:, None, None], quirks)
            blocks = (mech for _, mech in _node_blocks(linkage, positions))
            delta, size, rho = _coupled_tip(blocks, loads, positions, cog_lengths, sec, quirks)
    mech = tip_mech
    dx, dy = delta[:, 0].astype(np.float64), delta[:, 1].astype(np.float64)
    if not quirks.cognate_frame:                                                     # D025
        c, s = libm.cos(mech.frame_angle), libm.sin(mech.frame_angle)
        dx, dy = dx * c - dy * s, dx * s + dy * c
    out = {"xp": mech.extra["xp"], "yp": mech.extra["yp"], "cxp": mech.extra["cxp"], "cyp": mech.extra["cyp"],
           "dx": dx, "dy": dy, "rot": delta[:, 2].astype(np.float64)}
    return out, functools.partial(mech.extra["linkage"].finish, rho=rho, size=size, extender=cog.cl2)


__all__ = ["LISTING", "COGNATE_LISTING", "DENSITY", "node_positions", "node_weights", "case3_source",
           "case3_linkage", "case3_on_linkage", "case3_cognate", "LISTING_EXTENDER", "MAX_NODES", "node_count"]
