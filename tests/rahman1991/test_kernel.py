"""The compiled position sweep of the 1991 method (port/gsc_position.py): its loop-closure
residual against the independent numpy formulation of eqs. 2.18-2.24 (cssp_listing.
_loop_operators, stacked dual-matrix products), its DFP descent, and the sweep's bookkeeping
against the single-position Newton."""
import numpy as np
import pytest

from linkrepro.port.rahman1991 import position as gsc_position
from linkrepro.port.slider_crank import _newton as spatial_newton
from linkrepro.port.rahman1996.listing import _loop_operators
from linkrepro.port.rahman1991.data import GscInputs


def _numpy_residual(theta1, q, c):
    """r = (B - I, B dual) and dB/dq_j = H_j B by numpy's stacked products."""
    h, b = _loop_operators(theta1, q, c)
    r = np.concatenate([(b.real - np.eye(3)).ravel(), b.dual.ravel()])
    hb = h @ type(h)(np.broadcast_to(b.real, (5, 3, 3)), np.broadcast_to(b.dual, (5, 3, 3)))
    return r, np.concatenate([hb.real.reshape(5, 9), hb.dual.reshape(5, 9)], axis=1).T


def _args(c):
    return c.a1, c.a2, c.a4, c.alpha4, c.s1


@pytest.mark.parametrize("seed", range(5))
def test_compiled_residual_equals_the_numpy_formulation(seed):
    rng = np.random.default_rng(seed)
    inputs = GscInputs(a4=float(rng.uniform(0, 30)), alpha4_deg=float(rng.uniform(200, 340)), s1=float(rng.uniform(0, 9)))
    c = gsc_position.constants(inputs, inputs.s1)
    for _ in range(20):
        theta1, q = float(rng.uniform(0, 2 * np.pi)), rng.uniform(-3, 3, 5) + np.array([0, 0, 0, 0, 50.0])
        r, jac = gsc_position._residual(theta1, q, *_args(c))
        r_np, jac_np = _numpy_residual(theta1, q, c)
        np.testing.assert_allclose(r, r_np, rtol=0, atol=1e-12 * max(1.0, np.abs(r_np).max()))
        np.testing.assert_allclose(jac, jac_np, rtol=0, atol=1e-12 * max(1.0, np.abs(jac_np).max()))


def test_the_jacobian_is_the_derivative_of_the_residual():
    """Central differences of r against J (an independent check of dB/dq_j = H_j B)."""
    c = gsc_position.constants(GscInputs(a4=20.0, s1=3.0), 3.0)
    q, h = np.array([1.4, 0.2, 4.8, -0.1, 48.0]), 1e-6
    _, jac = gsc_position._residual(0.7, q, *_args(c))
    for j in range(5):
        step = np.zeros(5)
        step[j] = h
        numeric = (gsc_position._residual(0.7, q + step, *_args(c))[0]
                   - gsc_position._residual(0.7, q - step, *_args(c))[0]) / (2 * h)
        np.testing.assert_allclose(jac[:, j], numeric, atol=1e-7)


def test_dfp_lowers_the_closure_error_from_a_poor_start():
    c = gsc_position.constants(GscInputs(a4=10.0, s1=3.5), 3.5)
    start = np.array([2.5, 0.5, 3.0, 0.4, 40.0])
    before = gsc_position._residual(0.3, start, *_args(c))[0]
    after = gsc_position._residual(0.3, gsc_position._dfp(0.3, start, *_args(c), 400), *_args(c))[0]
    assert after @ after < 1e-3 * (before @ before)


def test_the_sweep_is_the_newton_position_after_position():
    """Where no DFP is needed, positions() is kernel.newton from the last answer."""
    inputs = GscInputs(a4=10.0)
    theta1 = np.radians(np.arange(0.0, 40.0, 1.0))
    run = gsc_position.positions(inputs, theta1)
    assert set(run.status) == {gsc_position.NEWTON}
    c = gsc_position.constants(inputs, 0.0)
    guess = gsc_position.positions(inputs, theta1[:1]).q[0]
    for i, th in enumerate(theta1[1:], start=1):
        q, status, steps = spatial_newton.newton(th, guess, *_args(c), c.newton_tol, 150, False)
        assert status == spatial_newton.OK and steps == run.iterations[i]
        np.testing.assert_array_equal(q, run.q[i])
        guess = q
    r = gsc_position._residual(theta1[-1], run.q[-1], *_args(c))[0]
    assert run.closure[-1] == pytest.approx(np.linalg.norm(r), rel=1e-15)


def test_stop_at_failure_ends_the_sweep_at_the_first_failure():
    inputs = GscInputs(a4=0.0, s1=9.0)
    theta1 = np.radians(np.arange(0.0, 361.0))
    full = gsc_position.positions(inputs, theta1)
    stopped = gsc_position.positions(inputs, theta1, stop_at_failure=True)
    first = int(np.argmax(full.status == gsc_position.NOT_CONVERGED))
    np.testing.assert_array_equal(stopped.q[:first], full.q[:first])
    assert np.all(np.isnan(stopped.q[first:]))
