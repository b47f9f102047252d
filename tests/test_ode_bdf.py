"""The compiled BDF integrator (sealsim.ode.bdf) against scipy's solve_ivp(method="BDF"), the
algorithm it follows, on stiff test problems: the same steps and the same solution; its event
location against solve_ivp's; quadrature states against their exact integral; the growth limit
on a break-away from rest against its exact solution, and the C port (sealsim/fmu/c/bdf.c)
against the numba one on it."""

from __future__ import annotations

import ctypes
import math
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest
from numba import njit
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from sealsim.fmu.builder import find_compiler
from sealsim.ode import compile_bdf, workspace
from sealsim.ode.bdf import (I_NFEV, I_NJEV, I_NRENEW, I_NSTEPS, I_ORDER, MAX_ORDER, OK, R_ONE,
                             S_H_ABS, S_NS, S_T, dense, lu_factor, lu_solve)

pytestmark = pytest.mark.xdist_group("compiled_bdf")   # one worker compiles the solvers

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


def test_dense_output_only_writes_its_output():
    # the interpolant sums each state in a register and stores it once: the compiled code
    # never reads ``out`` back (LLVM marks its data pointer write-only), where a running sum
    # in ``out`` re-read it at every order (13.9-116.7 ns per 10-state sample, orders 1-5,
    # instead of 7.6-22.3 ns); the numbers stay those of the running sum, to the bit
    @njit
    def interpolate(ws, t, out):
        dense(ws, t, out)

    n = 4
    rng = np.random.default_rng(3)
    ws = workspace(n, 2, 1e-6, 1e-8)
    ws[0][S_H_ABS], ws[0][S_T] = 0.01, 1.0
    ws[0][S_NS + n:S_NS + n + (MAX_ORDER + 1) * n] = rng.normal(size=(MAX_ORDER + 1) * n)
    out = np.empty(n)
    for order in range(1, MAX_ORDER + 1):
        ws[1][I_ORDER] = order
        for t in (0.991, 0.9957, 1.0):
            interpolate(ws, t, out)
            d = ws[0][S_NS + n:S_NS + n + (order + 1) * n].reshape(order + 1, n)
            expect, p = d[0].copy(), 1.0
            for k in range(order):
                p *= (t - (1.0 - 0.01 * k)) / (0.01 * (1 + k))
                expect += d[k + 1] * p
            np.testing.assert_array_equal(out, expect)
    ir = interpolate.inspect_llvm(interpolate.signatures[0])
    # the array's data pointer is its fifth member (meminfo, parent, size, itemsize, data)
    out_data = re.search(r"ptr ([^%,]*)%arg\.out\.4\b", ir)
    assert out_data is not None and "writeonly" in out_data.group(1)


def test_the_newton_iteration_solves_in_place():
    # the LU substitutions are inlined into the Newton iteration (as it is into the step): a
    # call at every iteration took and released a reference to each of its arrays (8 % of
    # the Ø32 cylinder's integration was lu_solve_at)
    @njit
    def one_step(ws, args):
        return step(ws, args)

    ws = workspace(2, 2, 1e-6, 1e-8)
    start(ws, 0.0, np.array([2.0, 0.0]), 1.0, (MU,))
    assert one_step(ws, (MU,)) == OK
    ir = one_step.inspect_llvm(one_step.signatures[0])
    assert re.search(r"@\S*lu_solve_at", ir) is None       # no function of that name


def test_r_one_is_scipys_r_of_factor_one():
    # change_differences takes U = R(1) from a table: scipy's compute_R(order, 1), to the bit
    from scipy.integrate._ivp.bdf import compute_R

    np.testing.assert_array_equal(R_ONE, compute_R(MAX_ORDER, 1.0))


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


# -- the growth limit: a break-away from rest (see sealsim.ode.bdf and integrate._growth) ------
#: v' = a0 + c·√v⁺ (a friction falling as F_brk − k·√v, flat for v < 0 as a slip mode's):
#: a0 [m/s²] and c [m^½/s^1.5] of the rod seal's break-away in cylinder_32_fe.toml, the
#: forward-difference scales of the cylinder's Jacobian (0.1 m, 30 m/s), its tolerances
BREAKAWAY = (2e-3, 190.0, 0.1, 30.0)
BREAKAWAY_RTOL, BREAKAWAY_ATOL = 1e-5, np.array([1e-6, 3e-4])


@njit(cache=True)
def breakaway(t, y, args, dy):
    dy[0] = y[1]
    dy[1] = args[0] + args[1] * math.sqrt(max(y[1], 0.0))


@njit(cache=True)
def breakaway_jac(t, y, f, args, J):
    shifted, rates = np.empty(2), np.empty(2)
    for j in range(2):
        h = 1.5e-8 * max(abs(y[j]), args[2 + j])
        shifted[0], shifted[1] = y[0], y[1]
        shifted[j] += h
        breakaway(t, shifted, args, rates)
        for i in range(2):
            J[i, j] = (rates[i] - f[i]) / h


@njit(cache=True)
def breakaway_event(t, y, args):
    return 1.0


@njit(cache=True)
def breakaway_growth(t, y, J, args):
    # args[4] = 0: no growth rate, scipy's steps unchanged (see run_breakaway)
    return max(J[1, 1], 0.0) * args[4]


@njit(cache=True)
def breakaway_renew(t, y, f, args, J):
    """The velocity's column of breakaway_jac alone, and the growth rate from it."""
    shifted, rates = np.empty(2), np.empty(2)
    h = 1.5e-8 * max(abs(y[1]), args[3])
    shifted[0], shifted[1] = y[0], y[1] + h
    breakaway(t, shifted, args, rates)
    for i in range(2):
        J[i, 1] = (rates[i] - f[i]) / h
    return max(J[1, 1], 0.0)


LIMITED = compile_bdf("test_breakaway", breakaway, breakaway_jac, breakaway_event,
                      breakaway_growth)
RENEWED = compile_bdf("test_breakaway_renewed", breakaway, breakaway_jac, breakaway_event,
                      breakaway_growth, breakaway_renew)
limited_start, limited_step = LIMITED.start, LIMITED.step
renewed_start, renewed_step = RENEWED.start, RENEWED.step


@njit(cache=True)
def _run_breakaway(ws, t1, args, renew):
    y0 = np.zeros(2)
    if renew:
        renewed_start(ws, 0.0, y0, t1, args)
    else:
        limited_start(ws, 0.0, y0, t1, args)
    ts, vs = [0.0], [0.0]
    while ws[0][S_T] < t1:
        status = renewed_step(ws, args) if renew else limited_step(ws, args)
        if status != OK:
            break
        ts.append(ws[0][S_T])
        vs.append(ws[2][1])
    return np.array(ts), np.array(vs)


def run_breakaway(ws, t1, args, limited):
    """The step ends (t, v) from rest to t1; ``limited`` 0: scipy's steps (a growth rate of 0
    limits nothing, as no_growth), 1: the growth limit, 2: the growth limit renewing the
    velocity's column alone.  0 and 1 share one compiled solver (a cold BDF compilation costs
    about 10 s)."""
    return _run_breakaway(ws, t1, (*args, 0.0 if limited == 0 else 1.0), limited == 2)


def exact_breakaway_speed(t):
    """v(t) of v' = a0 + c·√v from rest: with s = √v, t = 2/c·(s − a0/c·ln(1 + c·s/a0))."""
    a0, c = BREAKAWAY[:2]
    s = brentq(lambda s: 2 / c * (s - a0 / c * math.log1p(c * s / a0)) - t, 0.0, 10.0,
               xtol=1e-300, rtol=1e-15)
    return s * s


def test_growth_limit_starts_a_breakaway_forwards():
    # 2 ms from rest.  scipy's steps (no growth rate): the first step has c·λ ≈ 8 and
    # reverses v; it stays at -0.2 µm/s (below the 0.3 mm/s tolerance of v, flat for v < 0)
    # and never breaks away -- at 2 ms the exact speed is 36 mm/s.  With the growth limit every
    # step has v >= 0 and v is the exact one within the tolerance of v (measured 2.6e-4 m/s,
    # the local errors of the order-1 steps where v'' = c²/2 is largest).
    ws = workspace(2, 2, BREAKAWAY_RTOL, BREAKAWAY_ATOL)
    ts, vs = run_breakaway(ws, 2e-3, BREAKAWAY, False)
    assert ts[-1] == 2e-3 and vs.min() < 0.0 and vs[-1] < 0.0
    ws = workspace(2, 2, BREAKAWAY_RTOL, BREAKAWAY_ATOL)
    ts, vs = run_breakaway(ws, 2e-3, BREAKAWAY, True)
    assert ts[-1] == 2e-3 and vs.min() >= 0.0
    assert np.all(np.diff(vs) > 0.0)                  # v' >= a0 > 0
    exact = np.array([exact_breakaway_speed(t) for t in ts])
    assert np.max(np.abs(vs - exact)) < BREAKAWAY_ATOL[1]
    assert vs[-1] == pytest.approx(exact[-1], rel=1e-2)
    assert ws[1][I_NSTEPS] < 40                         # measured 17 steps, 8 Jacobians


def test_growth_limit_renewing_the_growing_column_alone():
    # the same break-away with RENEW (the pneumatic piston's: ∂f/∂v alone, one right-hand
    # side instead of one per state and one at y).  The growth limit holds as with whole
    # Jacobians -- v >= 0 at every step and the exact v within its tolerance -- and the
    # break-away's Jacobians are renewals of the one column: whole Jacobians only at the start
    # and where the iteration stalls with the renewed column (measured: the same 17 steps and
    # speeds as with whole Jacobians, 2 whole Jacobians and 7 renewals instead of 8 whole)
    ws = workspace(2, 2, BREAKAWAY_RTOL, BREAKAWAY_ATOL)
    ts, vs = run_breakaway(ws, 2e-3, BREAKAWAY, 2)
    assert ts[-1] == 2e-3 and vs.min() >= 0.0
    assert np.all(np.diff(vs) > 0.0)
    exact = np.array([exact_breakaway_speed(t) for t in ts])
    assert np.max(np.abs(vs - exact)) < BREAKAWAY_ATOL[1]
    assert vs[-1] == pytest.approx(exact[-1], rel=1e-2)
    whole = workspace(2, 2, BREAKAWAY_RTOL, BREAKAWAY_ATOL)
    run_breakaway(whole, 2e-3, BREAKAWAY, 1)
    assert ws[1][I_NRENEW] > 0 and whole[1][I_NRENEW] == 0
    assert ws[1][I_NJEV] <= whole[1][I_NJEV] // 2
    assert ws[1][I_NSTEPS] < 40


_C_HARNESS = r"""
#include "bdf.h"
typedef struct { double a0, c, scale[2]; } Par;
static void fun(void *ctx, double t, const double *y, double *dy) {
    const Par *p = (const Par *)ctx;
    (void)t;
    dy[0] = y[1];
    dy[1] = p->a0 + p->c * sqrt(fmax(y[1], 0.0));
}
/* forward differences from f = fun(t, y), which the integrator hands over (as the numba JAC) */
static void jac(void *ctx, double t, const double *y, const double *f0, double *J) {
    const Par *p = (const Par *)ctx;
    double f1[2], z[2];
    for (int j = 0; j < 2; j++) {
        double h = 1.5e-8 * fmax(fabs(y[j]), p->scale[j]);
        z[0] = y[0];
        z[1] = y[1];
        z[j] += h;
        fun(ctx, t, z, f1);
        for (int i = 0; i < 2; i++) J[i * BDF_MAXN + j] = (f1[i] - f0[i]) / h;
    }
}
static double event(void *ctx, double t, const double *y) { return 1.0; }
static double growth(void *ctx, double t, const double *y, const double *J) {
    return fmax(J[1 * BDF_MAXN + 1], 0.0);
}
static double renew(void *ctx, double t, const double *y, const double *f0, double *J) {
    const Par *p = (const Par *)ctx;
    double f1[2], z[2] = {y[0], y[1]};
    double h = 1.5e-8 * fmax(fabs(y[1]), p->scale[1]);
    z[1] += h;
    fun(ctx, t, z, f1);
    for (int i = 0; i < 2; i++) J[i * BDF_MAXN + 1] = (f1[i] - f0[i]) / h;
    return fmax(J[1 * BDF_MAXN + 1], 0.0);
}
int run(const double *par, double t1, double rtol, const double *atol, int limited, int cap,
        double *ts, double *vs) {
    Par p = {par[0], par[1], {par[2], par[3]}};
    BdfProblem bp = {&p, fun, jac, event, limited ? growth : 0, limited == 2 ? renew : 0};
    Bdf b;
    double y0[2] = {0.0, 0.0};
    bdf_init(&b, 2, rtol, atol, INFINITY);
    bdf_start(&b, 0.0, y0, t1, &bp);
    int k = 0;
    ts[0] = 0.0;
    vs[0] = 0.0;
    while (b.t < t1 && k + 1 < cap) {
        if (bdf_step(&b, &bp) != BDF_OK) return -1;
        k++;
        ts[k] = b.t;
        vs[k] = b.y_new[1];
    }
    return k;
}
"""


@pytest.mark.skipif(find_compiler() is None, reason="no C compiler")
@pytest.mark.parametrize("limited", [0, 1, 2])
def test_c_port_takes_the_same_steps(tmp_path, limited):
    # sealsim/fmu/c/bdf.c (the integrator of the cylinder FMU) on the break-away: the steps
    # of the numba integrator, without and with the growth limit (renewing whole Jacobians or
    # the growing column alone), to round-off
    sources = Path(__file__).resolve().parents[1] / "src" / "sealsim" / "fmu" / "c"
    (tmp_path / "harness.c").write_text(_C_HARNESS)
    lib = tmp_path / "harness.so"
    subprocess.run([find_compiler(), "-shared", "-fPIC", "-O2", "-std=c99",
                    "-ffp-contract=off", "-I", str(sources), str(tmp_path / "harness.c"),
                    str(sources / "bdf.c"), "-o", str(lib), "-lm"], check=True, timeout=120)
    run_c = ctypes.CDLL(str(lib)).run
    dbl = ctypes.POINTER(ctypes.c_double)
    run_c.argtypes = [dbl, ctypes.c_double, ctypes.c_double, dbl, ctypes.c_int, ctypes.c_int,
                      dbl, dbl]
    par, cap = np.array(BREAKAWAY), 1000
    ts_c, vs_c = np.zeros(cap), np.zeros(cap)
    k = run_c(par.ctypes.data_as(dbl), 2e-3, BREAKAWAY_RTOL,
              BREAKAWAY_ATOL.ctypes.data_as(dbl), int(limited), cap,
              ts_c.ctypes.data_as(dbl), vs_c.ctypes.data_as(dbl))
    ws = workspace(2, 2, BREAKAWAY_RTOL, BREAKAWAY_ATOL)
    ts, vs = run_breakaway(ws, 2e-3, BREAKAWAY, limited)
    assert k == ts.size - 1
    np.testing.assert_allclose(ts_c[:k + 1], ts, rtol=1e-12, atol=0.0)
    np.testing.assert_allclose(vs_c[:k + 1], vs, rtol=1e-9, atol=1e-15)
