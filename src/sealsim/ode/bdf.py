r"""A compiled variable-order BDF integrator (orders 1-5) with event location, in numba.

The algorithm is scipy's ``solve_ivp(method="BDF")`` (Shampine & Reichelt [1]_: quasi-constant
step size, the backward differences of the solution as its history, the NDF modification
κ of the order 1-4 formulas, a simplified Newton iteration with a Jacobian kept until the
iteration stalls, order and step selection after ``order + 1`` equal steps) and its dense
output, followed line by line -- a test runs both on the same problem and finds the same steps.
Two additions for the models here:

* **quadrature states**: the states ``ndyn ... n-1`` (bookkeeping integrals of boundary
  flows, energy, heat) do not feed back into the right-hand side.  They are integrated with
  the same formula and the same Newton iteration, but the LU factorisation is of the
  ``ndyn × ndyn`` block only -- a quadrature's Newton update follows from the dynamic one
  through its Jacobian row, so a linear invariant such as the mass balance holds to round-off
  as with the full matrix -- and they are excluded from the error and convergence norms (the
  RMS over the dynamic states);
* **events**: :func:`locate` finds the root of an event function on the dense output of the
  last step with Brent's method (scipy's ``brentq``, tolerance 4 ε, as ``solve_ivp``).

**Generic over the problem.**  The step functions call three problem functions by the global
names ``FUN``, ``JAC`` and ``EVENT``::

    FUN(t, y, args, dy)        # dy/dt into dy (shape (n,))
    JAC(t, y, args, J)         # ∂f/∂y_j of all states by the dynamic ones j (n × ndyn)
    EVENT(t, y, args) -> g     # the event function (any float; unused problems return 1)

``args`` is any tuple the problem needs (its tables, its mode); the integrator passes it
through.  :func:`compile_bdf` makes a copy of the step functions with the problem's compiled
functions as those globals (each copy with its own name, so numba caches each on disk), the
pattern of :func:`sealsim.pneumatic._jit.jit`.  The solver's state is a tuple of arrays
(:func:`workspace`), so a run can be stopped and resumed from Python between steps.

References
----------
.. [1] L. F. Shampine, M. W. Reichelt, "The MATLAB ODE Suite", SIAM J. Sci. Comput. 18(1),
   1-22, 1997 (NDF/BDF with quasi-constant step size; the basis of scipy's BDF).
.. [2] R. P. Brent, *Algorithms for Minimization without Derivatives*, ch. 4, 1973 (root
   finding, as scipy's ``brentq``).
"""

from __future__ import annotations

import math
import types
from dataclasses import dataclass

import numpy as np
from numba import njit

__all__ = ["BdfSolver", "compile_bdf", "workspace"]

MAX_ORDER = 5
NEWTON_MAXITER = 4
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
EPS = float(np.finfo(float).eps)
_KAPPA = np.array([0.0, -0.1850, -1.0 / 9.0, -0.0823, -0.0415, 0.0])
GAMMA = np.hstack((0.0, np.cumsum(1.0 / np.arange(1, MAX_ORDER + 1))))
ALPHA = (1.0 - _KAPPA) * GAMMA
ERROR_CONST = _KAPPA * GAMMA + 1.0 / np.arange(1, MAX_ORDER + 2)

#: float slots of the workspace: time, time before the last step, step size, tolerance,
#: largest step, Newton tolerance, end of the interval, c = h/α of the factorised matrix
(S_T, S_T_OLD, S_H_ABS, S_RTOL, S_MAX_STEP, S_NEWTON_TOL, S_T_BOUND, S_C_LU, S_NS) = range(9)
#: integer slots: order, equal steps since the last change, LU valid, counters, ndyn
(I_ORDER, I_NEQ, I_LU_OK, I_NFEV, I_NJEV, I_NLU, I_NSTEPS, I_NDYN, I_NI) = range(9)
#: step results
OK, TOO_SMALL_STEP = 0, -1


def workspace(n: int, ndyn: int, rtol: float, atol, max_step: float = np.inf) -> tuple:
    """The solver state for ``n`` states of which the first ``ndyn`` are dynamic: a tuple of
    arrays (float scalars, int scalars, atol, differences D, J, LU, pivots, and scratch)."""
    s = np.zeros(S_NS)
    iv = np.zeros(I_NI, dtype=np.int64)
    s[S_RTOL] = rtol
    s[S_MAX_STEP] = max_step
    s[S_NEWTON_TOL] = max(10.0 * EPS / rtol, min(0.03, rtol ** 0.5))
    iv[I_NDYN] = ndyn
    atol = np.ascontiguousarray(np.broadcast_to(np.asarray(atol, dtype=float), (n,)))
    return (s, iv, atol, np.zeros((MAX_ORDER + 3, n)), np.zeros((n, ndyn)),
            np.zeros((ndyn, ndyn)), np.zeros(ndyn, dtype=np.int64), np.zeros((8, n)),
            np.zeros((3, MAX_ORDER + 1, MAX_ORDER + 1)))


# -- small dense linear algebra -------------------------------------------------------------
@njit(cache=True)
def lu_factor(a, piv):
    """LU factorisation with partial pivoting in place (LAPACK getrf, unblocked); returns
    False for a singular matrix."""
    n = a.shape[0]
    for k in range(n):
        p = k
        big = abs(a[k, k])
        for i in range(k + 1, n):
            if abs(a[i, k]) > big:
                big = abs(a[i, k])
                p = i
        piv[k] = p
        if big == 0.0:
            return False
        if p != k:
            for j in range(n):
                tmp = a[k, j]
                a[k, j] = a[p, j]
                a[p, j] = tmp
        inv = 1.0 / a[k, k]
        for i in range(k + 1, n):
            a[i, k] *= inv
            m = a[i, k]
            if m != 0.0:
                for j in range(k + 1, n):
                    a[i, j] -= m * a[k, j]
    return True


@njit(cache=True)
def lu_solve(lu, piv, b):
    """Solve with the factors of :func:`lu_factor`, b (length >= n) overwritten in its first
    n entries."""
    n = lu.shape[0]
    for k in range(n):
        p = piv[k]
        if p != k:
            tmp = b[k]
            b[k] = b[p]
            b[p] = tmp
    for i in range(n):
        acc = b[i]
        for j in range(i):
            acc -= lu[i, j] * b[j]
        b[i] = acc
    for i in range(n - 1, -1, -1):
        acc = b[i]
        for j in range(i + 1, n):
            acc -= lu[i, j] * b[j]
        b[i] = acc / lu[i, i]


@njit(cache=True)
def rms(x, scale, m):
    """RMS norm of x/scale over the first m entries (scipy's ``norm``)."""
    acc = 0.0
    for i in range(m):
        q = x[i] / scale[i]
        acc += q * q
    return math.sqrt(acc) / math.sqrt(m)


@njit(cache=True)
def change_differences(D, order, factor, R):
    """Re-express the differences D for a step size changed by ``factor`` (scipy's
    ``change_D``: D[:order+1] = (R(factor)·R(1))ᵀ·D[:order+1]); R (3, 6, 6) is scratch."""
    m = order + 1
    r, u, ru = R[0], R[1], R[2]
    for j in range(m):             # R(factor) and U = R(1): cumulative products of M
        r[0, j] = 1.0
        u[0, j] = 1.0
    for i in range(1, m):
        r[i, 0] = 0.0
        u[i, 0] = 0.0
        for j in range(1, m):
            r[i, j] = r[i - 1, j] * ((i - 1 - factor * j) / i)
            u[i, j] = u[i - 1, j] * ((i - 1 - 1.0 * j) / i)
    for i in range(m):
        for j in range(m):
            acc = 0.0
            for k in range(m):
                acc += r[i, k] * u[k, j]
            ru[i, j] = acc
    n = D.shape[1]
    for c in range(n):
        for i in range(m):
            r[0, i] = D[i, c]          # the column (row 0 of r is free now)
        for i in range(m):
            acc = 0.0
            for k in range(m):
                acc += ru[k, i] * r[0, k]
            D[i, c] = acc


@njit(cache=True)
def dense(ws, t, out):
    """The solution at ``t`` (within the last step) from the BDF interpolant (scipy's
    ``BdfDenseOutput``)."""
    s, iv, D = ws[0], ws[1], ws[3]
    order = iv[I_ORDER]
    h = s[S_H_ABS]
    t_end = s[S_T]
    n = D.shape[1]
    for i in range(n):
        out[i] = D[0, i]
    p = 1.0
    for k in range(order):
        p *= (t - (t_end - h * k)) / (h * (1 + k))
        for i in range(n):
            out[i] += D[k + 1, i] * p


# -- the problem-dependent functions (copied per problem by compile_bdf) --------------------
def _newton(ws, args, t_new, c):
    """Simplified Newton iteration of the BDF system; (converged, iterations)."""
    s, iv, atol, D, J, LU, piv, buf = ws[0], ws[1], ws[2], ws[3], ws[4], ws[5], ws[6], ws[7]
    y_pred, psi, y, d, f, dy, scale = buf[0], buf[1], buf[2], buf[3], buf[4], buf[5], buf[6]
    n = y.shape[0]
    ndyn = iv[I_NDYN]
    tol = s[S_NEWTON_TOL]
    for i in range(n):
        y[i] = y_pred[i]
        d[i] = 0.0
    dy_norm_old = -1.0
    converged = False
    iterations = 0
    for k in range(NEWTON_MAXITER):
        iterations = k + 1
        FUN(t_new, y, args, f)  # noqa: F821 - set by compile_bdf
        iv[I_NFEV] += 1
        finite = True
        for i in range(n):
            if not math.isfinite(f[i]):
                finite = False
        if not finite:
            break
        for i in range(n):
            dy[i] = c * f[i] - psi[i] - d[i]
        lu_solve(LU, piv, dy)
        c_lu = s[S_C_LU]        # the quadrature rows of the matrix that was factorised
        for i in range(ndyn, n):              # quadratures: (dy - c·J·dy)_q = r_q
            acc = 0.0
            for j in range(ndyn):
                acc += J[i, j] * dy[j]
            dy[i] += c_lu * acc
        dy_norm = rms(dy, scale, ndyn)
        rate = -1.0
        if dy_norm_old >= 0.0:
            rate = dy_norm / dy_norm_old
        if rate >= 0.0 and (rate >= 1.0 or rate ** (NEWTON_MAXITER - k) / (1.0 - rate)
                            * dy_norm > tol):
            break
        for i in range(n):
            y[i] += dy[i]
            d[i] += dy[i]
        if dy_norm == 0.0 or (rate >= 0.0 and rate / (1.0 - rate) * dy_norm < tol):
            converged = True
            break
        dy_norm_old = dy_norm
    return converged, iterations


def start(ws, t0, y0, t_bound, args):
    """Start (or restart) at (t0, y0) towards t_bound: order 1, the initial step of scipy's
    ``select_initial_step``, a fresh Jacobian."""
    s, iv, atol, D, J, buf = ws[0], ws[1], ws[2], ws[3], ws[4], ws[7]
    f0, y1, f1, scale = buf[4], buf[5], buf[3], buf[6]
    n = y0.shape[0]
    ndyn = iv[I_NDYN]
    rtol = s[S_RTOL]
    s[S_T] = t0
    s[S_T_OLD] = t0
    s[S_T_BOUND] = t_bound
    FUN(t0, y0, args, f0)  # noqa: F821
    iv[I_NFEV] += 1
    interval = abs(t_bound - t0)
    if interval == 0.0:
        h_abs = 0.0
    else:
        for i in range(n):
            scale[i] = atol[i] + abs(y0[i]) * rtol
        d0 = rms(y0, scale, ndyn)
        d1 = rms(f0, scale, ndyn)
        h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
        h0 = min(h0, interval)
        for i in range(n):
            y1[i] = y0[i] + h0 * f0[i]
        FUN(t0 + h0, y1, args, f1)  # noqa: F821
        iv[I_NFEV] += 1
        for i in range(n):
            y1[i] = f1[i] - f0[i]
        d2 = rms(y1, scale, ndyn) / h0
        if d1 <= 1e-15 and d2 <= 1e-15:
            h1 = max(1e-6, h0 * 1e-3)
        else:
            h1 = (0.01 / max(d1, d2)) ** 0.5
        h_abs = min(100.0 * h0, h1, interval, s[S_MAX_STEP])
    s[S_H_ABS] = h_abs
    for i in range(n):
        D[0, i] = y0[i]
        D[1, i] = f0[i] * h_abs
    JAC(t0, y0, args, J)  # noqa: F821
    iv[I_NJEV] += 1
    iv[I_ORDER] = 1
    iv[I_NEQ] = 0
    iv[I_LU_OK] = 0


def step(ws, args):
    """One accepted step (scipy's ``BDF._step_impl``); returns :data:`OK` or
    :data:`TOO_SMALL_STEP`.  Afterwards ws[7][2] holds the new state and :func:`dense`
    interpolates over the step."""
    s, iv, atol, D, J, LU, piv, buf, R = (ws[0], ws[1], ws[2], ws[3], ws[4], ws[5], ws[6],
                                          ws[7], ws[8])
    y_pred, psi, y_new, d, scale, err = buf[0], buf[1], buf[2], buf[3], buf[6], buf[7]
    n = D.shape[1]
    ndyn = iv[I_NDYN]
    rtol = s[S_RTOL]
    t = s[S_T]
    t_bound = s[S_T_BOUND]
    max_step = s[S_MAX_STEP]
    order = iv[I_ORDER]
    min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
    h_abs = s[S_H_ABS]
    if h_abs > max_step:
        change_differences(D, order, max_step / h_abs, R)
        h_abs = max_step
        iv[I_NEQ] = 0
    elif h_abs < min_step:
        change_differences(D, order, min_step / h_abs, R)
        h_abs = min_step
        iv[I_NEQ] = 0
    current_jac = False
    n_iter = 0
    error_norm = 0.0
    safety = 0.0
    while True:
        if h_abs < min_step:
            return TOO_SMALL_STEP
        t_new = t + h_abs
        if t_new - t_bound > 0.0:
            t_new = t_bound
            change_differences(D, order, abs(t_new - t) / h_abs, R)
            iv[I_NEQ] = 0
            iv[I_LU_OK] = 0
        h = t_new - t
        h_abs = abs(h)
        for i in range(n):
            acc = 0.0
            for k in range(order + 1):
                acc += D[k, i]
            y_pred[i] = acc
            scale[i] = atol[i] + rtol * abs(acc)
            acc = 0.0
            for k in range(1, order + 1):
                acc += D[k, i] * GAMMA[k]
            psi[i] = acc / ALPHA[order]
        c = h / ALPHA[order]
        converged = False
        while not converged:
            if iv[I_LU_OK] == 0:
                for i in range(ndyn):
                    for j in range(ndyn):
                        LU[i, j] = -c * J[i, j]
                    LU[i, i] += 1.0
                lu_factor(LU, piv)
                s[S_C_LU] = c
                iv[I_NLU] += 1
                iv[I_LU_OK] = 1
            converged, n_iter = _newton(ws, args, t_new, c)
            if not converged:
                if current_jac:
                    break
                JAC(t_new, y_pred, args, J)  # noqa: F821
                iv[I_NJEV] += 1
                iv[I_LU_OK] = 0
                current_jac = True
        if not converged:
            h_abs *= 0.5
            change_differences(D, order, 0.5, R)
            iv[I_NEQ] = 0
            iv[I_LU_OK] = 0
            continue
        safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + n_iter)
        for i in range(n):
            scale[i] = atol[i] + rtol * abs(y_new[i])
            err[i] = ERROR_CONST[order] * d[i]
        error_norm = rms(err, scale, ndyn)
        if error_norm > 1.0:
            factor = max(MIN_FACTOR, safety * error_norm ** (-1.0 / (order + 1)))
            h_abs *= factor
            change_differences(D, order, factor, R)
            iv[I_NEQ] = 0
        else:
            break
    iv[I_NEQ] += 1
    iv[I_NSTEPS] += 1
    s[S_T_OLD] = t
    s[S_T] = t_new
    s[S_H_ABS] = h_abs
    for i in range(n):
        D[order + 2, i] = d[i] - D[order + 1, i]
        D[order + 1, i] = d[i]
    for k in range(order, -1, -1):
        for i in range(n):
            D[k, i] += D[k + 1, i]
    if iv[I_NEQ] < order + 1:
        return OK
    if order > 1:
        for i in range(n):
            err[i] = ERROR_CONST[order - 1] * D[order, i]
        error_m = rms(err, scale, ndyn)
    else:
        error_m = np.inf
    if order < MAX_ORDER:
        for i in range(n):
            err[i] = ERROR_CONST[order + 1] * D[order + 2, i]
        error_p = rms(err, scale, ndyn)
    else:
        error_p = np.inf
    # factors = error_norms ** (-1 / [order, order + 1, order + 2]); 0 ** -x = inf
    f_m = _factor(error_m, order)
    f_0 = _factor(error_norm, order + 1)
    f_p = _factor(error_p, order + 2)
    best = f_0
    delta = 0
    if f_m > best:
        best = f_m
        delta = -1
    if f_p > best:
        best = f_p
        delta = 1
    order += delta
    iv[I_ORDER] = order
    factor = min(MAX_FACTOR, safety * best)
    s[S_H_ABS] = h_abs * factor
    change_differences(D, order, factor, R)
    iv[I_NEQ] = 0
    iv[I_LU_OK] = 0
    return OK


def locate(ws, args, g_old, g_new, y_tmp):
    """The time of the event (EVENT = 0) within the last step, by Brent's method on the dense
    output (xtol = rtol = 4 ε, as solve_ivp); ``g_old``, ``g_new`` its values at the ends."""
    s = ws[0]
    xtol = 4.0 * EPS
    rtol = 4.0 * EPS
    xpre, xcur = s[S_T_OLD], s[S_T]
    fpre, fcur = g_old, g_new
    xblk = 0.0
    fblk = 0.0
    spre = 0.0
    scur = 0.0
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    for _ in range(100):
        if fpre != 0.0 and fcur != 0.0 and (fpre < 0.0) != (fcur < 0.0):
            xblk = xpre
            fblk = fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre = xcur
            xcur = xblk
            xblk = xpre
            fpre = fcur
            fcur = fblk
            fblk = fpre
        delta = (xtol + rtol * abs(xcur)) / 2.0
        sbis = (xblk - xcur) / 2.0
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
                spre = scur
                scur = stry
            else:
                spre = sbis
                scur = sbis
        else:
            spre = sbis
            scur = sbis
        xpre = xcur
        fpre = fcur
        if abs(scur) > delta:
            xcur += scur
        else:
            xcur += delta if sbis > 0.0 else -delta
        dense(ws, xcur, y_tmp)
        fcur = EVENT(xcur, y_tmp, args)  # noqa: F821
    return xcur


@njit(cache=True)
def _factor(error_norm, power):
    """error_norm ** (-1/power), inf at 0 (numpy's ``0 ** -x``)."""
    if error_norm == 0.0:
        return np.inf
    return error_norm ** (-1.0 / power)


@dataclass(frozen=True)
class BdfSolver:
    """The compiled step functions of one problem (:func:`compile_bdf`)."""

    start: object
    step: object
    locate: object
    dense: object = dense


def compile_bdf(name: str, fun, jac, event) -> BdfSolver:
    """The BDF step functions for one problem: ``fun``, ``jac``, ``event`` are numba-compiled
    functions with the signatures of the module docstring; ``name`` (a Python identifier)
    names the compiled copies in numba's disk cache."""
    env = dict(globals())
    env.update(FUN=fun, JAC=jac, EVENT=event)
    for func in (_newton, start, step, locate):
        copy = types.FunctionType(func.__code__, env, func.__name__, func.__defaults__,
                                  func.__closure__)
        copy.__qualname__ = f"{func.__qualname__}__{name}"
        env[func.__name__] = njit(cache=True)(copy)
    return BdfSolver(env["start"], env["step"], env["locate"])
