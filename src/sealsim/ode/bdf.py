r"""A compiled variable-order BDF integrator (orders 1-5) with event location, in numba.

The algorithm is scipy's ``solve_ivp(method="BDF")`` (Shampine & Reichelt [1]_: quasi-constant
step size, the backward differences of the solution as its history, the NDF modification
κ of the order 1-4 formulas, a simplified Newton iteration with a Jacobian kept until the
iteration stalls, order and step selection after ``order + 1`` equal steps) and its dense
output, followed line by line -- a test runs both on the same problem and finds the same steps.
Three additions for the models here:

* **quadrature states**: the states ``ndyn ... n-1`` (bookkeeping integrals of boundary
  flows, energy, heat) do not feed back into the right-hand side.  They are integrated with
  the same formula and the same Newton iteration, but the LU factorisation is of the
  ``ndyn × ndyn`` block only -- a quadrature's Newton update follows from the dynamic one
  through its Jacobian row, so a linear invariant such as the mass balance holds to round-off
  as with the full matrix -- and they are excluded from the error and convergence norms (the
  RMS over the dynamic states);
* **events**: :func:`locate` finds the root of an event function on the dense output of the
  last step with Brent's method (scipy's ``brentq``, tolerance 4 ε, as ``solve_ivp``);
* **a growth limit** for locally unstable problems: a problem may give a growth rate
  λ⁺ >= 0 of its Jacobian (``GROWTH``, evaluated with every Jacobian), the rate at which a
  state feeds itself.  An implicit step multiplies such a component by 1/(1 − c·λ) to first
  order (c = h/α_k; for order 1 the stability function R(z) = 1/(1 − z) of the implicit
  Euler method, Hairer & Wanner [3]_): singular at c·λ = 1 and *negative* beyond, where the
  exact factor e^(hλ) > 1.  A step with c·λ > 1 therefore reverses the sign of a component
  the exact solution makes grow, and the simplified Newton iteration, whose matrix I − c·J
  is near that pole, may even be accepted by its rate test on a diverging iterate.  The error
  estimate does not see it while the component is below its tolerance (a motion that starts
  from rest).  So every step keeps c·λ⁺ <= ``GROWTH_LIMIT`` = 1/2 (halfway to the pole), and
  a Jacobian limits one step: where the limit would bind again, the Jacobian is renewed at
  the current state first, since λ⁺ changes as the motion grows (for v' ∝ √v it falls as
  1/(2t): the limited steps grow geometrically).  Problems without one (``GROWTH`` = 0, the default
  :func:`no_growth`) take scipy's steps unchanged.  A problem whose growth sits in a few
  columns of J (the pneumatic piston: ∂f/∂v) may renew only those (``RENEW``, one FUN
  evaluation instead of one per dynamic state): a break-away renews λ⁺ at almost every one of
  its first steps, and the other columns, which change slowly, serve the simplified Newton
  iteration as they are.  With a RENEW, a Newton iteration that stalls while λ⁺ > 0 renews
  those columns first (the whole Jacobian if it stalls again), and a renewed λ⁺ that the
  step's c·λ⁺ exceeds the limit of shrinks the step to the limit instead of halving it.
  Problems without a RENEW (the default :func:`no_renewal`) take the steps they took before.

**Generic over the problem.**  The step functions call five problem functions by the global
names ``FUN``, ``JAC``, ``EVENT``, ``GROWTH`` and ``RENEW``::

    FUN(t, y, args, dy)        # dy/dt into dy (shape (n,))
    JAC(t, y, f, args, J)      # ∂f/∂y_j of all states by the dynamic ones j (n × ndyn);
                               # f = FUN(t, y), which the solver has evaluated already
    EVENT(t, y, args) -> g     # the event function (any float; unused problems return 1)
    GROWTH(t, y, J, args) -> λ⁺  # growth rate [1/time] of the Jacobian J (n × ndyn) at
                               # (t, y), >= 0 (optional, default 0: see the growth limit)
    RENEW(t, y, f, args, J) -> λ⁺  # renews the columns of J that GROWTH reads at (t, y),
                               # f = FUN(t, y), with one FUN evaluation, and returns GROWTH
                               # (optional, default -1: the whole Jacobian is renewed)

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
.. [3] E. Hairer, G. Wanner, *Solving Ordinary Differential Equations II: Stiff and
   Differential-Algebraic Problems*, 2nd ed., Springer 1996, sect. IV.3 (stability function
   R(z) = 1/(1 − z) of the implicit Euler method) and sect. V.1 (BDF methods).
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
#: largest c·λ⁺ of a step (c = h/α_k, λ⁺ the growth rate of GROWTH): the Newton matrix
#: I − c·J is singular at c·λ = 1 (see the module docstring)
GROWTH_LIMIT = 0.5
EPS = float(np.finfo(float).eps)
_KAPPA = np.array([0.0, -0.1850, -1.0 / 9.0, -0.0823, -0.0415, 0.0])
GAMMA = np.hstack((0.0, np.cumsum(1.0 / np.arange(1, MAX_ORDER + 1))))
ALPHA = (1.0 - _KAPPA) * GAMMA
ERROR_CONST = _KAPPA * GAMMA + 1.0 / np.arange(1, MAX_ORDER + 2)

#: float slots of the workspace: time, time before the last step, step size, tolerance,
#: largest step, Newton tolerance, end of the interval, c = h/α of the factorised matrix
#: the growth rate λ⁺ [1/s] of the Jacobian J (GROWTH)
(S_T, S_T_OLD, S_H_ABS, S_RTOL, S_MAX_STEP, S_NEWTON_TOL, S_T_BOUND, S_C_LU, S_GROWTH,
 S_NS) = range(10)
#: integer slots: order, equal steps since the last change, LU valid, counters, ndyn, the
#: Jacobian's growth rate has limited a step, growth columns renewed (RENEW; each one FUN
#: evaluation, also counted in I_NFEV)
(I_ORDER, I_NEQ, I_LU_OK, I_NFEV, I_NJEV, I_NLU, I_NSTEPS, I_NDYN, I_LIMITED, I_NRENEW,
 I_NI) = range(11)
#: step results
OK, TOO_SMALL_STEP = 0, -1


def workspace(n: int, ndyn: int, rtol: float, atol, max_step: float = np.inf) -> tuple:
    """The solver state for ``n`` states of which the first ``ndyn`` are dynamic.

    A tuple ``(w, iv, y, f, dy)``: one float array ``w`` with the float slots ``S_*`` first,
    then atol, the differences D, J, the LU factors and scratch (offsets: :func:`_offsets`);
    the int slots ``I_*`` and the pivots in ``iv``; the state after the last step ``y`` and two
    work vectors.  Few arrays, and no views of them in the steps: numba counts references
    of every array it hands around, which cost more than the arithmetic of a small system."""
    size = _offsets(n, ndyn)[-1]
    w = np.zeros(size)
    iv = np.zeros(I_NI + ndyn, dtype=np.int64)
    w[S_RTOL] = rtol
    w[S_MAX_STEP] = max_step
    w[S_NEWTON_TOL] = max(10.0 * EPS / rtol, min(0.03, rtol ** 0.5))
    iv[I_NDYN] = ndyn
    o_atol = _offsets(n, ndyn)[0]
    w[o_atol:o_atol + n] = np.broadcast_to(np.asarray(atol, dtype=float), (n,))
    return (w, iv, np.zeros(n), np.zeros(n), np.zeros(n))


@njit(cache=True)
def _offsets(n, ndyn):
    """Offsets in ``w`` of atol, D, J (n × ndyn), LU (ndyn × ndyn), y_pred, psi, d, scale,
    err, f(y_pred), the scratch of :func:`change_differences` (3 × 6 × 6), and the size."""
    o_atol = S_NS
    o_d = o_atol + n
    o_j = o_d + (MAX_ORDER + 3) * n
    o_lu = o_j + n * ndyn
    o_pred = o_lu + ndyn * ndyn
    o_psi = o_pred + n
    o_dd = o_psi + n
    o_scale = o_dd + n
    o_err = o_scale + n
    o_fpred = o_err + n
    o_r = o_fpred + n
    return (o_atol, o_d, o_j, o_lu, o_pred, o_psi, o_dd, o_scale, o_err, o_fpred, o_r,
            o_r + 108)


# -- small dense linear algebra -------------------------------------------------------------
@njit(cache=True)
def lu_factor_at(a, o, m, piv, po):
    """LU factorisation with partial pivoting (LAPACK getrf, unblocked) in place of the m × m
    matrix a[o:o + m·m] (row-major), pivots into piv[po:po + m]; False when singular."""
    for k in range(m):
        p = k
        big = abs(a[o + k * m + k])
        for i in range(k + 1, m):
            if abs(a[o + i * m + k]) > big:
                big = abs(a[o + i * m + k])
                p = i
        piv[po + k] = p
        if big == 0.0:
            return False
        if p != k:
            for j in range(m):
                tmp = a[o + k * m + j]
                a[o + k * m + j] = a[o + p * m + j]
                a[o + p * m + j] = tmp
        inv = 1.0 / a[o + k * m + k]
        for i in range(k + 1, m):
            a[o + i * m + k] *= inv
            f = a[o + i * m + k]
            if f != 0.0:
                for j in range(k + 1, m):
                    a[o + i * m + j] -= f * a[o + k * m + j]
    return True


@njit(cache=True, inline="always")
def lu_solve_at(a, o, m, piv, po, b):
    """Solve with the factors of :func:`lu_factor_at`; b (length >= m) overwritten in its
    first m entries.  Inlined into the Newton iteration, which solves at every iteration: as a
    call it took and released a reference to each of its three arrays (8 % of the Ø32
    cylinder's integration in lu_solve_at, its substitutions being a few dozen flops)."""
    for k in range(m):
        p = piv[po + k]
        if p != k:
            tmp = b[k]
            b[k] = b[p]
            b[p] = tmp
    for i in range(m):
        acc = b[i]
        for j in range(i):
            acc -= a[o + i * m + j] * b[j]
        b[i] = acc
    for i in range(m - 1, -1, -1):
        acc = b[i]
        for j in range(i + 1, m):
            acc -= a[o + i * m + j] * b[j]
        b[i] = acc / a[o + i * m + i]


def lu_factor(a, piv):
    """LU factorisation with partial pivoting of the square array ``a`` in place
    (:func:`lu_factor_at`); returns False for a singular matrix."""
    flat = a.reshape(-1)
    ok = lu_factor_at(flat, 0, a.shape[0], piv, 0)
    return ok


def lu_solve(lu, piv, b):
    """Solve with the factors of :func:`lu_factor` (b overwritten)."""
    lu_solve_at(lu.reshape(-1), 0, lu.shape[0], piv, 0, b)


@njit(cache=True)
def _rms(w, o, scale_o, m):
    """RMS norm of w[o + i]/w[scale_o + i] over i < m (scipy's ``norm``)."""
    acc = 0.0
    for i in range(m):
        q = w[o + i] / w[scale_o + i]
        acc += q * q
    return math.sqrt(acc) / math.sqrt(m)


@njit(cache=True)
def _rms_vec(x, w, scale_o, m):
    """RMS norm of x[i]/w[scale_o + i] over i < m."""
    acc = 0.0
    for i in range(m):
        q = x[i] / w[scale_o + i]
        acc += q * q
    return math.sqrt(acc) / math.sqrt(m)


def _r_one() -> np.ndarray:
    """U = R(1) of :func:`change_differences` for every order (6 × 6; the top-left
    (order + 1)² block is that order's): the cumulative products of M with factor 1, computed
    with the operations of R(factor) in floating point, so the same numbers."""
    u = np.zeros((MAX_ORDER + 1, MAX_ORDER + 1))
    u[0, :] = 1.0
    for i in range(1, MAX_ORDER + 1):
        for j in range(1, MAX_ORDER + 1):
            u[i, j] = u[i - 1, j] * ((i - 1 - 1.0 * j) / i)
    return u


#: R(1) of scipy's ``change_D``, a constant of the compiled code (:func:`_r_one`)
R_ONE = _r_one()


@njit(cache=True)
def change_differences(w, od, n, order, factor, o_r):
    """Re-express the differences D = w[od:] (rows of n) for a step size changed by
    ``factor`` (scipy's ``change_D``: D[:order+1] = (R(factor)·U)ᵀ·D[:order+1], U = R(1):
    :data:`R_ONE`); scratch w[o_r:o_r + 108]."""
    m = order + 1
    r, ru = o_r, o_r + 72        # two 6 × 6 matrices
    for j in range(m):             # R(factor): cumulative products of M
        w[r + j] = 1.0
    for i in range(1, m):
        w[r + 6 * i] = 0.0
        for j in range(1, m):
            w[r + 6 * i + j] = w[r + 6 * (i - 1) + j] * ((i - 1 - factor * j) / i)
    for i in range(m):
        for j in range(m):
            acc = 0.0
            for k in range(m):
                acc += w[r + 6 * i + k] * R_ONE[k, j]
            w[ru + 6 * i + j] = acc
    for c in range(n):
        for i in range(m):
            w[r + i] = w[od + i * n + c]          # the column (row 0 of r is free now)
        for i in range(m):
            acc = 0.0
            for k in range(m):
                acc += w[ru + 6 * k + i] * w[r + k]
            w[od + i * n + c] = acc


@njit(cache=True, inline="always")
def dense(ws, t, out):
    """The solution at ``t`` (within the last step) from the BDF interpolant (scipy's
    ``BdfDenseOutput``); inlined into compiled callers (it runs at every output sample).

    The products p_k = Π_{j<k} (t − (t_end − j·h))/((j + 1)·h) first, then each state summed
    in a register, D_0 + D_1·p_1 + D_2·p_2 + ... (the operations and their order of the
    running sum in ``out``, so the same numbers): a read-modify-write of ``out`` per order
    cost more than the arithmetic, since the compiler cannot keep ``out[i]`` in a register
    while ``out`` might share memory with the workspace."""
    w, iv = ws[0], ws[1]
    n = out.shape[0]
    od = S_NS + n
    order = iv[I_ORDER]
    h = w[S_H_ABS]
    t_end = w[S_T]
    p1 = p2 = p3 = p4 = p5 = 0.0
    p = 1.0
    for k in range(order):
        p *= (t - (t_end - h * k)) / (h * (1 + k))
        if k == 0:
            p1 = p
        elif k == 1:
            p2 = p
        elif k == 2:
            p3 = p
        elif k == 3:
            p4 = p
        else:
            p5 = p
    for i in range(n):
        acc = w[od + i]
        if order >= 1:
            acc += w[od + n + i] * p1
            if order >= 2:
                acc += w[od + 2 * n + i] * p2
                if order >= 3:
                    acc += w[od + 3 * n + i] * p3
                    if order >= 4:
                        acc += w[od + 4 * n + i] * p4
                        if order >= 5:
                            acc += w[od + 5 * n + i] * p5
        out[i] = acc


# -- the problem-dependent functions (copied per problem by compile_bdf) --------------------
def _newton(w, iv, y, f, dy, args, t_new, c, n, ndyn):
    """Simplified Newton iteration of the BDF system; (converged, iterations)."""
    o_atol, od, oj, olu, opred, opsi, odd, oscale, oerr, ofp, o_r, _ = _offsets(n, ndyn)
    tol = w[S_NEWTON_TOL]
    for i in range(n):
        y[i] = w[opred + i]
        w[odd + i] = 0.0
    dy_norm_old = -1.0
    converged = False
    iterations = 0
    for k in range(NEWTON_MAXITER):
        iterations = k + 1
        FUN(t_new, y, args, f)  # noqa: F821 - set by compile_bdf
        iv[I_NFEV] += 1
        if k == 0:                  # f(y_pred): what a new Jacobian at y_pred starts from
            for i in range(n):
                w[ofp + i] = f[i]
        finite = True
        for i in range(n):
            if not math.isfinite(f[i]):
                finite = False
        if not finite:
            break
        for i in range(n):
            dy[i] = c * f[i] - w[opsi + i] - w[odd + i]
        lu_solve_at(w, olu, ndyn, iv, I_NI, dy)
        c_lu = w[S_C_LU]        # the quadrature rows of the matrix that was factorised
        for i in range(ndyn, n):              # quadratures: (dy - c·J·dy)_q = r_q
            acc = 0.0
            for j in range(ndyn):
                acc += w[oj + i * ndyn + j] * dy[j]
            dy[i] += c_lu * acc
        dy_norm = _rms_vec(dy, w, oscale, ndyn)
        rate = -1.0
        if dy_norm_old >= 0.0:
            rate = dy_norm / dy_norm_old
        if rate >= 0.0 and (rate >= 1.0 or rate ** (NEWTON_MAXITER - k) / (1.0 - rate)
                            * dy_norm > tol):
            break
        for i in range(n):
            y[i] += dy[i]
            w[odd + i] += dy[i]
        if dy_norm == 0.0 or (rate >= 0.0 and rate / (1.0 - rate) * dy_norm < tol):
            converged = True
            break
        dy_norm_old = dy_norm
    return converged, iterations


def _jacobian(w, iv, t, y, f, args, n, ndyn):
    """JAC at (t, y) with f = FUN(t, y) into the J block of w, counted; its growth rate
    GROWTH into w[S_GROWTH]."""
    oj = _offsets(n, ndyn)[2]
    jac = w[oj:oj + n * ndyn].reshape(n, ndyn)
    JAC(t, y, f, args, jac)  # noqa: F821
    w[S_GROWTH] = GROWTH(t, y, jac, args)  # noqa: F821
    iv[I_LIMITED] = 0
    iv[I_NJEV] += 1


def _renew_growth(w, iv, t, y, f, args, n, ndyn):
    """λ⁺ renewed at (t, y), f = FUN(t, y): the columns of J that GROWTH reads (RENEW, one
    FUN evaluation) or, without a RENEW, the whole Jacobian."""
    oj = _offsets(n, ndyn)[2]
    jac = w[oj:oj + n * ndyn].reshape(n, ndyn)
    growth = RENEW(t, y, f, args, jac)  # noqa: F821
    if growth < 0.0:
        _jacobian(w, iv, t, y, f, args, n, ndyn)
        return
    w[S_GROWTH] = growth
    iv[I_LIMITED] = 0
    iv[I_NRENEW] += 1
    iv[I_NFEV] += 1


def start(ws, t0, y0, t_bound, args):
    """Start (or restart) at (t0, y0) towards t_bound: order 1, the initial step of scipy's
    ``select_initial_step``, a fresh Jacobian."""
    w, iv, y1, f0, f1 = ws[0], ws[1], ws[2], ws[3], ws[4]
    n = y0.shape[0]
    ndyn = iv[I_NDYN]
    o_atol, od, oj, olu, opred, opsi, odd, oscale, oerr, ofp, o_r, _ = _offsets(n, ndyn)
    rtol = w[S_RTOL]
    w[S_T] = t0
    w[S_T_OLD] = t0
    w[S_T_BOUND] = t_bound
    FUN(t0, y0, args, f0)  # noqa: F821
    iv[I_NFEV] += 1
    interval = abs(t_bound - t0)
    if interval == 0.0:
        h_abs = 0.0
    else:
        for i in range(n):
            w[oscale + i] = w[o_atol + i] + abs(y0[i]) * rtol
        d0 = _rms_vec(y0, w, oscale, ndyn)
        d1 = _rms_vec(f0, w, oscale, ndyn)
        h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
        h0 = min(h0, interval)
        for i in range(n):
            y1[i] = y0[i] + h0 * f0[i]
        FUN(t0 + h0, y1, args, f1)  # noqa: F821
        iv[I_NFEV] += 1
        for i in range(n):
            y1[i] = f1[i] - f0[i]
        d2 = _rms_vec(y1, w, oscale, ndyn) / h0
        if d1 <= 1e-15 and d2 <= 1e-15:
            h1 = max(1e-6, h0 * 1e-3)
        else:
            h1 = (0.01 / max(d1, d2)) ** 0.5
        h_abs = min(100.0 * h0, h1, interval, w[S_MAX_STEP])
    w[S_H_ABS] = h_abs
    for i in range(n):
        w[od + i] = y0[i]
        w[od + n + i] = f0[i] * h_abs
        y1[i] = y0[i]
    _jacobian(w, iv, t0, y0, f0, args, n, ndyn)
    iv[I_ORDER] = 1
    iv[I_NEQ] = 0
    iv[I_LU_OK] = 0


def step(ws, args):
    """One accepted step (scipy's ``BDF._step_impl``); returns :data:`OK` or
    :data:`TOO_SMALL_STEP`.  Afterwards ws[2] holds the new state and :func:`dense`
    interpolates over the step."""
    w, iv, y, f, dy = ws[0], ws[1], ws[2], ws[3], ws[4]
    n = y.shape[0]
    ndyn = iv[I_NDYN]
    o_atol, od, oj, olu, opred, opsi, odd, oscale, oerr, ofp, o_r, _ = _offsets(n, ndyn)
    rtol = w[S_RTOL]
    t = w[S_T]
    t_bound = w[S_T_BOUND]
    max_step = w[S_MAX_STEP]
    order = iv[I_ORDER]
    min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
    h_abs = w[S_H_ABS]
    if h_abs > max_step:
        change_differences(w, od, n, order, max_step / h_abs, o_r)
        h_abs = max_step
        iv[I_NEQ] = 0
    elif h_abs < min_step:
        change_differences(w, od, n, order, min_step / h_abs, o_r)
        h_abs = min_step
        iv[I_NEQ] = 0
    # the growth limit c·λ⁺ <= GROWTH_LIMIT (module docstring); a Jacobian limits one step:
    # where the limit would bind again, λ⁺ is renewed at the current state first (it changes
    # as the motion grows)
    if w[S_GROWTH] > 0.0:
        h_growth = GROWTH_LIMIT * ALPHA[order] / w[S_GROWTH]
        if h_abs > h_growth and iv[I_LIMITED] != 0:
            for i in range(n):
                dy[i] = w[od + i]
            FUN(t, dy, args, f)  # noqa: F821
            iv[I_NFEV] += 1
            _renew_growth(w, iv, t, dy, f, args, n, ndyn)
            iv[I_LU_OK] = 0
            h_growth = GROWTH_LIMIT * ALPHA[order] / w[S_GROWTH] if w[S_GROWTH] > 0.0 \
                else np.inf
        if h_abs > h_growth and h_growth >= min_step:
            change_differences(w, od, n, order, h_growth / h_abs, o_r)
            h_abs = h_growth
            iv[I_NEQ] = 0
            iv[I_LU_OK] = 0
            iv[I_LIMITED] = 1
    current_jac = False
    renewed = False
    n_iter = 0
    error_norm = 0.0
    safety = 0.0
    while True:
        if h_abs < min_step:
            return TOO_SMALL_STEP
        t_new = t + h_abs
        if t_new - t_bound > 0.0:
            t_new = t_bound
            change_differences(w, od, n, order, abs(t_new - t) / h_abs, o_r)
            iv[I_NEQ] = 0
            iv[I_LU_OK] = 0
        h = t_new - t
        h_abs = abs(h)
        for i in range(n):
            acc = 0.0
            for k in range(order + 1):
                acc += w[od + k * n + i]
            w[opred + i] = acc
            w[oscale + i] = w[o_atol + i] + rtol * abs(acc)
            acc = 0.0
            for k in range(1, order + 1):
                acc += w[od + k * n + i] * GAMMA[k]
            w[opsi + i] = acc / ALPHA[order]
        c = h / ALPHA[order]
        converged = False
        while not converged:
            if iv[I_LU_OK] == 0:
                for i in range(ndyn):
                    for j in range(ndyn):
                        w[olu + i * ndyn + j] = -c * w[oj + i * ndyn + j]
                    w[olu + i * ndyn + i] += 1.0
                lu_factor_at(w, olu, ndyn, iv, I_NI)
                w[S_C_LU] = c
                iv[I_NLU] += 1
                iv[I_LU_OK] = 1
            converged, n_iter = _newton(w, iv, y, f, dy, args, t_new, c, n, ndyn)
            if not converged:
                if current_jac:
                    break
                for i in range(n):
                    dy[i] = w[opred + i]
                    f[i] = w[ofp + i]
                iv[I_LU_OK] = 0
                if RENEWS and w[S_GROWTH] > 0.0 and not renewed:  # noqa: F821
                    # a growing state (a break-away) stalls the iteration: its columns
                    # first; the step stays within the growth limit of the renewed λ⁺
                    _renew_growth(w, iv, t_new, dy, f, args, n, ndyn)
                    renewed = True
                    if c * w[S_GROWTH] > GROWTH_LIMIT:
                        h_growth = GROWTH_LIMIT * ALPHA[order] / w[S_GROWTH]
                        if h_growth >= min_step:
                            break
                else:
                    _jacobian(w, iv, t_new, dy, f, args, n, ndyn)
                    current_jac = True
        if not converged:
            factor = 0.5
            if RENEWS and renewed and c * w[S_GROWTH] > GROWTH_LIMIT:  # noqa: F821
                factor = min(0.5, GROWTH_LIMIT * ALPHA[order] / w[S_GROWTH] / h_abs)
                iv[I_LIMITED] = 1
            h_abs *= factor
            change_differences(w, od, n, order, factor, o_r)
            iv[I_NEQ] = 0
            iv[I_LU_OK] = 0
            continue
        safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + n_iter)
        for i in range(n):
            w[oscale + i] = w[o_atol + i] + rtol * abs(y[i])
            w[oerr + i] = ERROR_CONST[order] * w[odd + i]
        error_norm = _rms(w, oerr, oscale, ndyn)
        if error_norm > 1.0:
            factor = max(MIN_FACTOR, safety * error_norm ** (-1.0 / (order + 1)))
            h_abs *= factor
            change_differences(w, od, n, order, factor, o_r)
            iv[I_NEQ] = 0
        else:
            break
    iv[I_NEQ] += 1
    iv[I_NSTEPS] += 1
    w[S_T_OLD] = t
    w[S_T] = t_new
    w[S_H_ABS] = h_abs
    for i in range(n):
        w[od + (order + 2) * n + i] = w[odd + i] - w[od + (order + 1) * n + i]
        w[od + (order + 1) * n + i] = w[odd + i]
    for k in range(order, -1, -1):
        for i in range(n):
            w[od + k * n + i] += w[od + (k + 1) * n + i]
    if iv[I_NEQ] < order + 1:
        return OK
    if order > 1:
        for i in range(n):
            w[oerr + i] = ERROR_CONST[order - 1] * w[od + order * n + i]
        error_m = _rms(w, oerr, oscale, ndyn)
    else:
        error_m = np.inf
    if order < MAX_ORDER:
        for i in range(n):
            w[oerr + i] = ERROR_CONST[order + 1] * w[od + (order + 2) * n + i]
        error_p = _rms(w, oerr, oscale, ndyn)
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
    w[S_H_ABS] = h_abs * factor
    change_differences(w, od, n, order, factor, o_r)
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


@njit(cache=True)
def no_growth(t, y, jac, args):
    """The GROWTH of a problem without a locally unstable state: 0 (no step limit)."""
    return 0.0


@njit(cache=True)
def no_renewal(t, y, f, args, jac):
    """The RENEW of a problem without its own: -1 (the whole Jacobian is renewed)."""
    return -1.0


def compile_bdf(name: str, fun, jac, event, growth=no_growth, renew=no_renewal) -> BdfSolver:
    """The BDF step functions for one problem: ``fun``, ``jac``, ``event``, ``growth`` and
    ``renew`` are numba-compiled functions with the signatures of the module docstring;
    ``name`` (a Python identifier) names the compiled copies in numba's disk cache."""
    env = dict(globals())
    env.update(FUN=fun, JAC=jac, EVENT=event, GROWTH=growth, RENEW=renew,
               RENEWS=renew is not no_renewal)
    for func in (_newton, _jacobian, _renew_growth, start, step, locate):
        copy = types.FunctionType(func.__code__, env, func.__name__, func.__defaults__,
                                  func.__closure__)
        copy.__qualname__ = f"{func.__qualname__}__{name}"
        # the Newton iteration inlined into the step and the step into the caller's loop: as
        # calls of their own they would take and release a reference to every array of
        # ``args`` on each call (atomic counts, which cost more than a small system's algebra)
        env[func.__name__] = (njit(inline="always")(copy) if func in (_newton, step)
                              else njit(cache=True)(copy))
    return BdfSolver(env["start"], env["step"], env["locate"])
