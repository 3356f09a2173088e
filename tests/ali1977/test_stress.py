"""The links' bending stresses (``harness/scenes/ali1977/stress.py``) against hand statics.

The frozen Case I linkage is statically determinate: the coupler-extender body carries the path
point's inertia force F = -(W/g) a_P at P, the follower's force along the follower at B (a two-force
member) and the crank's pin force at A; its three equilibrium equations give both, and the bending
moments are forces times lever arms: at A (the extender's and the coupler's) (P - A) x F, at the
crank's root (A - O2) x (the coupler's force on the crank).  The stress is M c / I with the example's
0.5 in round bar, S = pi d^3 / 32.  Here that is computed from the rigid linkage's positions alone
(not the port's beta) and held against the K.E.D. moments (the port's beta P), Exudyn's (from its
nodes' rotations: its linear statics, and a 20 rpm steady state, where the dynamics is quasi-static),
and the scene's stress table.

Units: inch, lbf; angles in degrees.
"""
from tests.multibody import needs_exudyn

exudyn = needs_exudyn()

import math  # noqa: E402

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import pytest  # noqa: E402

from linkrepro.harness.scenes.ali1977 import elastodynamics as ed  # noqa: E402
from linkrepro.harness.scenes.ali1977 import multibody as mb  # noqa: E402
from linkrepro.harness.scenes.ali1977 import stress  # noqa: E402
from linkrepro.port.ali1977.data import EXAMPLE  # noqa: E402
from linkrepro.port.ali1977.structure import GRAVITY_IN  # noqa: E402

#: the example's bar: 0.5 in round (its area pi d^2 / 4 = 0.19635 in^2)
DIAMETER = 0.5
#: the data's section literals hold 8 to 10 digits
LITERALS = 1e-7


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def hand_moments(side: str, deg, rpm: float = 300.0) -> dict:
    """|M| (lbf in) at A and at the crank's root by the statics of the frozen linkage (the rigid
    positions of ``multibody.rigid``; the load -(W/g) a_P scaled to ``rpm`` as the speed squared)."""
    rig = mb.rigid(side, deg)
    force = -(EXAMPLE.mass_lbf / GRAVITY_IN) * rig.acc_p * (rpm / 300.0) ** 2
    e4 = (rig.o4 - rig.b) / np.hypot(*(rig.o4 - rig.b))
    # moments about A: (P - A) x F + (B - A) x (T e4) = 0; forces: F + R + T e4 = 0 (R: the crank's on the body)
    tension = -cross(rig.p - rig.a, force) / cross(rig.b - rig.a, e4)
    on_crank = force + tension * e4                     # = -R
    return {"A": np.abs(cross(rig.p - rig.a, force)), "O2": np.abs(cross(rig.a - rig.o2, on_crank))}


def test_the_section_modulus_is_the_round_bars():
    """S = pi d^3 / 32 to the data's literals (I = 0.0030679615 in^4, 8 digits: 2.5e-8 off pi d^4 / 64)."""
    assert stress.section_modulus() == pytest.approx(math.pi * DIAMETER ** 3 / 32.0, rel=LITERALS)
    assert EXAMPLE.section.area == pytest.approx(math.pi * DIAMETER ** 2 / 4.0, rel=LITERALS)


@pytest.mark.parametrize("side", ["source", "cognate"])
def test_ked_and_exudyn_moments_are_the_hand_statics(side):
    """At 26 deg (near the source's quasi-static peak at A) and 200 deg: the K.E.D. moments and
    Exudyn's linear statics (2 elements per link) equal the hand statics to 1e-9; the follower, the
    free end P and the pins B (coupler) and A (crank) carry none."""
    for deg in (26.0, 200.0):
        hand = hand_moments(side, [deg])
        ked = stress.ked_moments([deg], side=side)
        assert abs(ked["crank"][0]) == pytest.approx(hand["O2"][0], rel=1e-9)
        for member in ("extender", "coupler"):
            assert abs(ked[member][0]) == pytest.approx(hand["A"][0], rel=1e-9)
        model = mb.build(side, deg, 1, 2, masses="none", shear_per_element=1.0)
        nodal = stress.exudyn_moments(model, model.linear_solution())
        scale = hand["A"][0] + hand["O2"][0]
        assert abs(nodal["crank"][0]) == pytest.approx(hand["O2"][0], abs=1e-9 * scale)
        assert abs(nodal["coupler"][0]) == pytest.approx(hand["A"][0], abs=1e-9 * scale)
        assert abs(nodal["extender"][0]) == pytest.approx(hand["A"][0], abs=1e-9 * scale)
        for member, end in (("crank", -1), ("coupler", -1), ("extender", -1), ("follower", 0), ("follower", -1)):
            assert abs(nodal[member][end]) < 1e-9 * scale


def test_the_stress_table_is_the_hand_statics_peak_over_m_c_over_i():
    """The table's quasi-static rows: the largest hand-statics moment over every degree, its angle,
    and sigma = M (d / 2) / (pi d^4 / 64), at 300 rpm and at a limit speed (the moment as the speed
    squared); its Exudyn linear statics rows (two angles, 2 elements, one load step) the hand
    statics' larger at those angles."""
    deg = np.arange(0.0, 360.0, 1.0)
    angles = (20.0, 30.0)
    rows = []
    for side in ("source", "cognate"):
        for d in angles:
            _, _, moments = ed.exudyn_static(d, 2, 1, side, moments=True)
            rows.append({"side": side, "crank_deg": d, **stress.static_columns("exudyn_linear", moments["linear"]),
                         **stress.static_columns("nonlinear", moments["nonlinear"])})
    limits = {"source": 61.0, "cognate": 64.0}
    table = stress.table(pd.DataFrame(rows), [], limits)
    inertia = math.pi * DIAMETER ** 4 / 64.0
    for side in ("source", "cognate"):
        for rpm in (300.0, limits[side]):
            hand = hand_moments(side, deg, rpm)
            for link, joint in (("coupler", "A"), ("crank", "O2")):
                row = table[(table.side == side) & (table.rpm == rpm) & (table.link == link)
                            & (table.model == "quasi-static (K.E.D., the port)")].iloc[0]
                k = int(np.argmax(hand[joint]))
                assert row.moment_lbf_in == pytest.approx(hand[joint][k], rel=1e-9)
                assert row.crank_deg == deg[k] and row.from_joint == joint and row.at_in == 0.0
                assert row.stress_psi == pytest.approx(hand[joint][k] * (DIAMETER / 2.0) / inertia, rel=LITERALS)
                assert row.stress_over_yield == pytest.approx(row.stress_psi / stress.YIELD_PSI[0], rel=1e-12)
        hand = hand_moments(side, list(angles))
        for link, joint in (("coupler", "A"), ("crank", "O2")):
            row = table[(table.side == side) & (table.link == link) & (table.model == "linear static (Exudyn)")].iloc[0]
            assert row.moment_lbf_in == pytest.approx(hand[joint].max(), rel=1e-8)


def test_at_20_rpm_the_steady_states_moments_are_the_hand_statics():
    """At 20 rpm (4 elements per link) the elastodynamic steady state is quasi-static to about 2 % of
    the peak deflection (test_elastodynamics): its moments at the crank's root and at A (both members)
    are the hand statics' at 20 rpm to 2 % of their peak (1.1 % measured); the follower and the free ends carry
    less than 1e-4 of it."""
    run = ed.steady_state(20.0, elements=4)
    hand = hand_moments("source", run.deg, 20.0)
    peak = max(hand["A"].max(), hand["O2"].max())
    assert np.abs(np.abs(run.moments["crank"][:, 0]) - hand["O2"]).max() < 0.02 * peak
    for member in ("coupler", "extender"):
        assert np.abs(np.abs(run.moments[member][:, 0]) - hand["A"]).max() < 0.02 * peak
    for member, end in (("crank", -1), ("coupler", -1), ("extender", -1), ("follower", 0), ("follower", -1)):
        assert np.abs(run.moments[member][:, end]).max() < 1e-4 * peak
