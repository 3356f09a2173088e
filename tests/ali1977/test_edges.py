"""Ali (1977) at the edges of the input space: every refusal typed, no NaN returned silently.

The rule for the K.E.D. engines (``linkrepro.checks``, shared by legacy and port): TypeError
for what is not a number, ValueError for a value outside the domain (link lengths from 1e-6
to 1e6 in, where the analysis's squares, cubes and speed products stay representable),
SingularPositionError with the input angle where a position is singular.
"""
from __future__ import annotations

import numpy as np
import pytest

from linkrepro import SingularPositionError
from linkrepro.legacy import ali1977
from linkrepro.port.ali1977 import case1
from linkrepro.port.ali1977.case1 import case1_deflection
from linkrepro.port.ali1977.case3 import node_positions
from linkrepro.port.ali1977.cognate import cognate_mechanics
from linkrepro.port.ali1977.data import EXAMPLE
from linkrepro.port.ali1977.fourbar import Lengths
from linkrepro.port.ali1977.quirks import CORRECTED, PRINTED
from linkrepro.port.ali1977.source import source_mechanics
from linkrepro.port.ali1977.structure import Mechanics

EXAMPLE_LINKS = np.array([10.0, 10.0, 30.0, 25.0, 30.0])
DEG = np.arange(0.0, 360.0, 30.0)


@pytest.mark.parametrize("scale", [1e-155, 1e-170, 5e-324, 1e200, 1e300])
def test_lengths_beyond_the_arithmetic_are_refused_alike(scale):
    """1e-170 in made the port's Freudenstein constants divide by zero (ZeroDivisionError)
    where legacy said SingularPositionError; 1e200 gave 'non-finite xp'."""
    links = EXAMPLE_LINKS * scale
    with pytest.raises(ValueError, match="link length l1"):
        Lengths(*links)
    with pytest.raises(ValueError, match="link length l1"):
        ali1977.case1_source(*links)


def test_lengths_at_the_domain_limits_still_run():
    for links in (EXAMPLE_LINKS / 10.0 * 1e-6, EXAMPLE_LINKS / 30.0 * 1e6):
        out = case1.source_case1(DEG, Lengths(*links), alp=1.0, quirks=CORRECTED)
        assert all(np.isfinite(v).all() for v in out.values())


CHANGE_POINT = Lengths(1.0, 10.0, 3.0, 3.0, 1.0)        # s + l = p + q: flat at 0 deg


@pytest.mark.parametrize("quirks", [PRINTED, CORRECTED])
def test_mechanics_at_a_change_point_raise_with_the_angle(quirks):
    """source_mechanics returned NaN positions and beta there, silently."""
    with pytest.raises(SingularPositionError) as info:
        source_mechanics(DEG, CHANGE_POINT, alp=1.0, rpm=300.0, quirks=quirks)
    assert info.value.angle_deg == 0.0
    with pytest.raises(SingularPositionError):
        case1.source_case1(DEG, CHANGE_POINT, alp=1.0, rpm=300.0, quirks=quirks)


def test_cognate_mechanics_of_a_degenerate_cognate_raise():
    """L2 = L3 at ALP = 0: the cognate's CL4 is 0."""
    with pytest.raises(SingularPositionError):
        cognate_mechanics(DEG, Lengths(10.0, 30.0, 30.0, 25.0, 30.0), alp=0.0, quirks=CORRECTED)


def test_mechanics_of_several_points_are_checked_by_angle():
    mech = source_mechanics(DEG, quirks=CORRECTED)
    points = mech.extra["linkage"].path_point(np.array([[2.0], [5.0], [10.0]]))
    assert points.xp.shape == (3, DEG.size)
    np.testing.assert_array_equal(points.xp[2], mech.xp)


def test_case1_deflection_refuses_a_non_finite_state():
    mech = source_mechanics(DEG, quirks=CORRECTED)
    beta = mech.beta.copy()
    beta[4, 3, 0] = np.nan
    broken = Mechanics(mech.xp, mech.yp, mech.acc, beta, mech.flex_lengths, extra=mech.extra)
    with pytest.raises(SingularPositionError) as info:
        case1_deflection(broken, 2.0, EXAMPLE.section, CORRECTED)
    assert info.value.angle_deg == DEG[4]
    with pytest.raises(TypeError):
        case1_deflection("mech", 2.0, EXAMPLE.section, CORRECTED)


@pytest.mark.parametrize("args", [(10**400, 5), (10.0, 10**400), (float("nan"), 5), (10.0, 5, -1.0), ("10", 5)])
def test_node_positions_refuse_what_they_cannot_place(args):
    """node_positions(10**400, 5) raised OverflowError."""
    with pytest.raises((ValueError, TypeError)):
        node_positions(*args)


def test_huge_integers_are_value_errors():
    """loc(1, 10**400, 1, 1, 0) raised OverflowError."""
    with pytest.raises(ValueError):
        ali1977.loc(1, 10**400, 1, 1, 0)
    with pytest.raises(ValueError):
        ali1977.case1_source(rpm=10**400)


def test_an_alp_beyond_a_million_radians_is_refused_alike():
    """alp = -1e300 rad: alp + t3 rounds to alp, and the corrected cognate's coupler point left
    the source's by 8 in (found by the fuzz's coincidence check)."""
    with pytest.raises(ValueError, match="alp"):
        ali1977.case1_cognate(alp=-1e300)
    with pytest.raises(ValueError, match="alp"):
        case1.cognate_case1(DEG, alp=-1e300, quirks=CORRECTED)


@pytest.mark.parametrize("value", [5e-324, 1e-50, 1e300])
def test_section_values_beyond_a_real4_literal_are_refused_in_every_mode(value):
    """A subnormal modulus divided the corrected port's F by zero (ZeroDivisionError)."""
    from linkrepro.port.ali1977.structure import Section
    with pytest.raises(ValueError, match="section modulus"):
        Section(0.2, value, 0.003)
    with pytest.raises(ValueError, match="section modulus"):
        ali1977.case1_source(modulus=value)
