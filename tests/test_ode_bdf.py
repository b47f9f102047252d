"""The compiled BDF integrator (sealsim.ode.bdf) against scipy's solve_ivp(method="BDF"), the
algorithm it follows, on stiff test problems: the same steps and the same solution; its event
location against solve_ivp's; quadrature states against their exact integral."""

from __future__ import annotations

import numpy as np
import pytest
from numba import njit
from scipy.integrate import solve_ivp

from sealsim.ode import compile_bdf, workspace
from sealsim.ode.bdf import I_NFEV, I_NJEV, I_NSTEPS, OK, S_T, dense, lu_factor, lu_solve

MU = 50.0     # van der Pol: stiff, with relaxation jumps the step control must follow


@njit(cache=True)
def vdp(t, y, args, dy):
    mu = args[0]
    dy[0] = y[1]
    dy[1] = mu * (1.0 - y[0] * y[0]) * y[1] - y[0]
    for i in range(2, y.shape[0]):      # quadratures: ∫ y0² dt, ∫ 1 dt, ∫ y1 dt
        dy[i] = y[0] * y[0] if i == 2 else (1.0 if i == 3 else y[1])


@njit(cache=True)
def vdp_jac(t, y, f, args, J):
    mu = args[0]
    J[0, 0] = 0.0
    J[0, 1] = 1.0
    J[1, 0] = -2.0 * mu * y[0] * y[1] - 1.0
    J[1, 1] = mu * (1.0 - y[0] * y[0])
    for i in range(2, y.shape[0]):      # the quadratures' rows
        J[i, 0] = 2.0 * y[0] if i == 2 else 0.0
        J[i, 1] = 1.0 if i == 4 else 0.0


@njit(cache=True)
def vdp_event(t, y, args):
    return y[0]


SOLVER = compile_bdf("test_vdp", vdp, vdp_jac, vdp_event)
start, step, locate = SOLVER.start, SOLVER.step, SOLVER.locate     # globals numba can call


@njit(cache=True)
def run(ws, t0, y0, t1, args, events):
    """Integrate to t1, record the step ends and the down-crossings of y0 = 0."""
    start(ws, t0, y0, t1, args)
    y = ws[2]
    ytmp = np.empty(y0.shape[0])
    times = [t0]
    g_old = y0[0]
    ne = 0
    while ws[0][S_T] < t1:
        if step(ws, args) != OK:
            return np.array(times), y.copy(), events[:ne], False
        times.append(ws[0][S_T])
        g_new = y[0]
        if g_old > 0.0 >= g_new and ne < events.shape[0]:
            events[ne] = locate(ws, args, g_old, g_new, ytmp)
            ne += 1
        g_old = g_new
    return np.array(times), y.copy(), events[:ne], True


def scipy_vdp(t, y):
    return [y[1], MU * (1 - y[0] ** 2) * y[1] - y[0]]


def scipy_jac(t, y):
    return [[0.0, 1.0], [-2 * MU * y[0] * y[1] - 1, MU * (1 - y[0] ** 2)]]


def down(t, y):
    return y[0]


down.direction = -1


@pytest.mark.parametrize("rtol, agree", [(1e-4, 1e-7), (1e-7, 1e-5)])
def test_same_steps_and_solution_as_scipy_bdf(rtol, agree):
    # the same algorithm: the same accepted steps; step times and solutions differ by
    # rounding only (operation order in the difference updates), which the step-size control
    # feeds back: over 570 (rtol 1e-4) and 1600 (rtol 1e-7) steps of five relaxation cycles
    # they grow to 4e-9 and 7e-7 -- far below a difference of the algorithm (a wrong
    # coefficient changes the step count and the solution at the rtol level)
    y0 = np.array([2.0, 0.0])
    ref = solve_ivp(scipy_vdp, (0, 150), y0, method="BDF", rtol=rtol, atol=1e-8,
                    jac=scipy_jac, events=down)
    ws = workspace(2, 2, rtol, 1e-8)
    times, y, events, ok = run(ws, 0.0, y0, 150.0, (MU,), np.zeros(100))
    assert ok
    assert times.size == ref.t.size
    np.testing.assert_allclose(times, ref.t, rtol=agree)
    np.testing.assert_allclose(y, ref.y[:, -1], atol=agree * 2.0)
    assert ws[1][I_NFEV] == ref.nfev and ws[1][I_NJEV] == ref.njev
    # events: the same crossings, located to the same precision (4 eps, Brent)
    np.testing.assert_allclose(events, ref.t_events[0], rtol=agree)


def test_dense_output_is_scipys_interpolant():
    y0 = np.array([2.0, 0.0])
    ws = workspace(2, 2, 1e-6, 1e-8)
    SOLVER.start(ws, 0.0, y0, 10.0, (MU,))
    solver = __import__("scipy.integrate", fromlist=["BDF"]).BDF(
        scipy_vdp, 0.0, y0, 10.0, rtol=1e-6, atol=1e-8, jac=scipy_jac)
    out = np.empty(2)
    for _ in range(40):
        assert SOLVER.step(ws, (MU,)) == OK
        solver.step()
        sol = solver.dense_output()
        for t in np.linspace(solver.t_old, solver.t, 5):
            dense(ws, t, out)
            np.testing.assert_allclose(out, sol(t), rtol=1e-10, atol=1e-12)


def test_quadrature_states_are_integrated_but_not_controlled():
    # ∫ 1 dt is exact for any step sequence; ∫ y0² dt against a tight scipy run.  The
    # quadratures do not change the steps (they are outside the LU and the norms).
    y0 = np.array([2.0, 0.0, 0.0, 0.0, 0.0])
    ws4 = workspace(5, 2, 1e-6, 1e-8)
    times4, y4, _, _ = run(ws4, 0.0, y0, 20.0, (MU,), np.zeros(10))
    ws2 = workspace(2, 2, 1e-6, 1e-8)
    times2, _, _, _ = run(ws2, 0.0, y0[:2].copy(), 20.0, (MU,), np.zeros(10))
    assert ws4[1][I_NSTEPS] == ws2[1][I_NSTEPS]
    np.testing.assert_array_equal(times4, times2)
    assert y4[3] == pytest.approx(20.0, rel=1e-12)
    # a linear invariant (y0 − ∫ y1 dt = 2, as the mass balance of the cylinder) holds to
    # round-off: the quadrature follows the dynamic states through its Jacobian row
    assert abs(y4[0] - y4[4] - 2.0) < 1e-12
    ref = solve_ivp(lambda t, y: [y[1], MU * (1 - y[0] ** 2) * y[1] - y[0], y[0] ** 2],
                    (0, 20), [2.0, 0.0, 0.0], method="Radau", rtol=1e-11, atol=1e-12)
    # the quadrature carries the BDF error of the states it integrates (rtol 1e-6)
    assert y4[2] == pytest.approx(ref.y[2, -1], rel=1e-4)


def test_lu_solves_a_pivoting_system():
    rng = np.random.default_rng(1)
    a = rng.normal(size=(7, 7))
    a[0, 0] = 0.0                     # needs a row exchange
    b = rng.normal(size=7)
    lu = a.copy()
    piv = np.zeros(7, dtype=np.int64)
    assert lu_factor(lu, piv)
    x = b.copy()
    lu_solve(lu, piv, x)
    np.testing.assert_allclose(a @ x, b, atol=1e-12)
