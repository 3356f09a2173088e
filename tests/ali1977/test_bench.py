"""Ali (1977)'s part of ``linkrepro bench`` (harness/scenes/ali1977/bench.py): its flop counts."""
from __future__ import annotations

from linkrepro.harness.scenes.ali1977 import bench


def test_mprd_flops_count_multiply_adds():
    assert bench.mprd(3, 8, 8) == 2 * 3 * 8 * 8
    assert bench.KED_CASE1 == bench.KED_KINEMATICS + 384 + 144 + 18
