"""The K.E.D. port's fast paths give what the direct calls give: the four-bar's kinematics
computed once and reused for every n (Case III), several path points at once, the nodes in
blocks, the Case III sweep's rows, and MPRD's single-precision sums as the listing's loop
makes them."""
import numpy as np
import pytest

from linkrepro.harness.scenes.ali1977 import case3_convergence
from linkrepro.port.ali1977 import CORRECTED, PRINTED, case3 as ked_case3
from linkrepro.port.ali1977.case3 import LISTING, case3_linkage, case3_on_linkage, case3_source
from linkrepro.port.ali1977.cognate import cognate_linkage
from linkrepro.port.ali1977.source import source_linkage
from linkrepro.port.real4 import product

DEG = np.arange(0.0, 361.0, 15.0)
#: the listing's model with the printed node masses and slips, and the coupled model
MODELS = [pytest.param(LISTING, True, id="listing"), pytest.param(CORRECTED, False, id="coupled"),
          pytest.param(CORRECTED.only("uncoupled_nodes", True), True, id="uncoupled-corrected")]


def assert_same(got: dict, want: dict):
    assert set(got) == set(want)
    for key in want:
        assert np.array_equal(got[key], want[key]), key


@pytest.mark.parametrize("quirks,all_nodes", MODELS)
@pytest.mark.parametrize("n", [1, 2, 5, 9])
def test_reused_kinematics_give_the_direct_call(quirks, all_nodes, n):
    linkage = case3_linkage(DEG, quirks=quirks)
    assert_same(case3_on_linkage(linkage, n, all_nodes=all_nodes),
                case3_source(DEG, n, quirks=quirks, all_nodes=all_nodes))


def test_reused_kinematics_off_the_example():
    lengths = ked_case3.Lengths(9.0, 12.5, 28.0, 26.0, 31.0)
    kw = dict(lengths=lengths, alp=1.2, rpm=-450.0)
    linkage = case3_linkage(DEG, quirks=LISTING, **kw)
    assert_same(case3_on_linkage(linkage, 5, density=0.2, all_nodes=True),
                case3_source(DEG, 5, density=0.2, quirks=LISTING, all_nodes=True, **kw))


@pytest.mark.parametrize("quirks,all_nodes", MODELS)
def test_a_linkage_is_not_changed_by_its_use(quirks, all_nodes):
    """Every n, density and section on one linkage: nothing carried from one call to the next."""
    linkage = case3_linkage(DEG, quirks=quirks)
    first = case3_on_linkage(linkage, 6, all_nodes=all_nodes)
    case3_on_linkage(linkage, 9, density=0.3, section=ked_case3.Section(0.5, 2e7, 0.01), all_nodes=all_nodes)
    assert_same(case3_on_linkage(linkage, 6, all_nodes=all_nodes), first)


def test_case3_on_linkage_refuses_what_case3_source_refuses():
    linkage = case3_linkage(DEG[:3], quirks=CORRECTED)
    with pytest.raises(TypeError):
        case3_on_linkage(DEG, 5)
    with pytest.raises(ValueError):
        case3_on_linkage(linkage, 0)
    with pytest.raises(ValueError):
        case3_on_linkage(linkage, 5, all_nodes=True)       # the coupled model prints no nodes


@pytest.mark.parametrize("quirks,all_nodes", MODELS)
def test_nodes_in_blocks_give_all_nodes_at_once(monkeypatch, quirks, all_nodes):
    """Blocks of four nodes (the smallest) against one block: the listing's slips on nodes 1, 2
    and 4 (D035, D036) and the nodes' own blocks are the same; the coupled model sums its
    reactions block by block (a different order of summation)."""
    n = 11
    whole = case3_source(DEG, n, quirks=quirks, all_nodes=all_nodes)
    monkeypatch.setattr(ked_case3, "NODE_BLOCK_SIZE", 1)
    blocks = case3_source(DEG, n, quirks=quirks, all_nodes=all_nodes)
    if quirks.uncoupled_nodes:
        assert_same(blocks, whole)
    else:
        for key in whole:
            np.testing.assert_allclose(blocks[key], whole[key], rtol=1e-13, atol=1e-15, err_msg=key)


@pytest.mark.parametrize("make", [
    pytest.param(lambda q: source_linkage(DEG, quirks=q), id="source"),
    pytest.param(lambda q: cognate_linkage(DEG, quirks=q), id="cognate")])
@pytest.mark.parametrize("quirks", [PRINTED, CORRECTED], ids=["printed", "corrected"])
def test_many_path_points_are_each_path_point(make, quirks):
    linkage = make(quirks)
    radii = np.array([10.0, 7.5, 3.25, 0.5])
    many = linkage.path_point(radii[:, None])
    assert np.array_equal(linkage.acceleration(radii[:, None]), many.acc)
    assert all(np.array_equal(a, b) for a, b in zip(linkage.position(radii[:, None]), (many.xp, many.yp)))
    for k, r in enumerate(radii):
        one = linkage.path_point(r)
        for name in ("xp", "yp", "acc", "beta"):
            assert np.array_equal(getattr(many, name)[k], getattr(one, name)), (name, r)
        if "cxp" in one.extra:                                              # the cognate turned into place
            pairs = [(many.extra[name][k], one.extra[name]) for name in ("cxp", "cyp")]
        else:                                                               # G1, H1, I1 (Case III's D036)
            pairs = [(g[k], h) for g, h in zip(many.extra["coefficients"][6:], one.extra["coefficients"][6:])]
        assert all(np.array_equal(x, y) for x, y in pairs), r


def _mprd_as_printed(a, b):
    """SSP MPRD in REAL*4: R(I,J) = 0, then R(I,J) = R(I,J) + A(I,K)*B(K,J), K = 1..M."""
    r = np.zeros((a.shape[0], b.shape[1]), np.float32)
    for i in range(a.shape[0]):
        for j in range(b.shape[1]):
            for k in range(a.shape[1]):
                r[i, j] = r[i, j] + a[i, k] * b[k, j]
    return r


def test_real4_product_sums_as_mprd():
    """Every product and every partial sum rounded to single, in MPRD's order, from +0: signed
    zeros, overflow to infinity, NaN and products that cancel included."""
    rng = np.random.default_rng(5)
    a = (rng.standard_normal((8, 3, 8)) * 10.0 ** rng.integers(-19, 19, (8, 3, 8))).astype(np.float32)
    b = (rng.standard_normal((8, 8, 4)) * 10.0 ** rng.integers(-19, 19, (8, 8, 4))).astype(np.float32)
    a[0, 0, :] = -0.0
    a[1, 1, 2], b[2, 3, 1], a[3, 2, 5], b[3, 5, :] = np.inf, np.nan, 3e38, 10.0
    a[4, 0, :2], b[4, :2, 0] = (1e8, 1.0), (1.0, -1.0)                  # 1e8 - 1e8 + ...: order matters
    with np.errstate(over="ignore", invalid="ignore"):
        got = product(a, b, True)
        want = np.stack([_mprd_as_printed(x, y) for x, y in zip(a, b)])
        from_doubles = product(a.astype(np.float64), b, True)                  # stored REAL*4 first
    assert got.dtype == np.float32
    assert np.array_equal(got, want, equal_nan=True)
    assert np.array_equal(np.signbit(got), np.signbit(want))
    assert np.array_equal(from_doubles, got, equal_nan=True)


def test_case3_sweep_rows_are_the_direct_calls(monkeypatch):
    """The sweep's errors are those of case3_source for each model and n, against the coupled
    model Richardson-extrapolated from case3_source at reference_n / 2 and reference_n."""
    monkeypatch.setattr(case3_convergence, "CASE3_STEPS", (30.0,))
    monkeypatch.setattr(case3_convergence, "CASE3_NS", (1, 3))
    data = case3_convergence.case3_data(repeat=1, reference_n=16)
    deg = np.arange(0.0, 360.0 + 1e-9, 30.0)
    fine, half = case3_source(deg, 16, quirks=CORRECTED), case3_source(deg, 8, quirks=CORRECTED)
    converged = {k: 2 * fine[k] - half[k] for k in ("dx", "dy")}
    models = {"coupled": CORRECTED, "listing": LISTING.without("real4_storage")}
    assert sorted(zip(data.n, data.model)) == sorted((n, m) for n in (1, 3) for m in models)
    for row in data.itertuples():
        got = case3_source(deg, row.n, quirks=models[row.model])
        assert row.error_in == max(float(np.max(np.abs(got[k] - converged[k]))) for k in ("dx", "dy"))
