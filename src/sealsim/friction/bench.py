"""Friction test benches: drive a law and record what a test rig would measure.

Three benches (Heipl & Murrenhoff Fig. 11; Canudas de Wit et al. 1995 §4):

* **prescribed velocity** v(t) -- the contact slides at a given speed (``simulate_velocity``);
* **prescribed displacement** x(t) -- e.g. a crank drive (``simulate_displacement``);
* **driven mass** -- a body of mass m on the contacts, pulled by a spring k whose end moves with
  a drive velocity profile (stick-slip; dwell phases are zero-velocity segments) and/or pushed
  by an applied force F_app(t) (pre-sliding, break-away) (``simulate_mass``).

Prescribed motion uses the law's exact step with the mean velocity of every step,
v_k = (x(t_{k+1}) − x(t_k))/dt, so the displacement is exact and the states are second-order
accurate; laws whose step is affine in the state run as a vectorised scan (no Python loop).

The driven mass is integrated, for smooth laws, as one compiled ODE with the variable-order BDF
method of :mod:`sealsim.ode` (the default) or with scipy's implicit ``solve_ivp`` (Radau or BDF,
analytic Jacobian from the law's ``partials``); laws with true sticking (Coulomb, Stribeck, Θ)
and GMS, whose element switching does not suit an error-controlled integrator, run with the
implicit stick/slip stepper of :mod:`sealsim.friction.hybrid` (compiled:
:func:`sealsim.friction.compiled.mass_steps`).

The profiles (constant, harmonic, piecewise linear) are in :mod:`.profiles`, the result record
and the numbers read off a run (:func:`summarize`: break-away forces, loop areas, dissipated
energy) in :mod:`.bench_results`; both are re-exported here.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sealsim.errors import ConvergenceError, InputError
from sealsim.friction.base import NO_INPUTS, ContactInputs, FrictionLaw
from sealsim.friction.bench_results import (  # noqa: F401  (re-exported)
    BenchResult,
    breakaway_forces,
    cycle_work,
    loop_areas,
    motion_onsets,
    stick_slip_period,
    summarize,
)
from sealsim.friction.compiled import LAW_CODES, contact_rates, mass_steps
from sealsim.friction.hybrid import compiled_law, contact_values, implicit_mass_step
from sealsim.friction.profiles import (
    _constant,
    profile_integral,
    profile_type,
    profile_value,
)
from sealsim.ode import bdf, compile_bdf

__all__ = [
    "BenchResult",
    "breakaway_forces",
    "loop_areas",
    "profile_type",
    "simulate_displacement",
    "simulate_mass",
    "simulate_velocity",
    "stick_slip_period",
    "summarize",
]


def _grid(duration: float, time_step: float) -> np.ndarray:
    if not (np.isfinite(duration) and duration > 0):
        raise InputError(f"bench.duration: must be > 0, got {duration!r}")
    if not (np.isfinite(time_step) and 0 < time_step <= duration):
        raise InputError(f"bench.time_step: must be > 0 and <= the duration ({duration:g} s), "
                         f"got {time_step!r}")
    n = int(np.ceil(duration / time_step - 1e-9))
    if n > 50_000_000:
        raise InputError(f"bench.time_step: {time_step:g} s gives {n} steps for "
                         f"{duration:g} s; use a larger time_step (at most 5e7 steps)")
    return np.linspace(0.0, n * time_step, n + 1)


# --------------------------------------------------------------------------------------------
# Prescribed motion
# --------------------------------------------------------------------------------------------
def simulate_displacement(law: FrictionLaw, position, duration: float, time_step: float,
                          inputs: ContactInputs = NO_INPUTS, initial_state=None,
                          _velocity_profile=None) -> BenchResult:
    """Prescribed displacement x(t) (e.g. a crank drive, Heipl & Murrenhoff Fig. 11).

    Parameters
    ----------
    law : FrictionLaw
    position : profile
        x(t) [m], any profile of :func:`profile_type` ("length").
    duration, time_step : float
        [s].
    inputs : ContactInputs
        Constant inputs (shape () or (1,)).
    initial_state : array_like, optional
        States at t = 0 (default: ``law.initial_state(1)``, relaxed and dry).

    Returns
    -------
    BenchResult
    """
    t = _grid(duration, time_step)
    if _velocity_profile is None:
        x = position.value(t)
        v_sample = position.derivative(t)
    else:
        x = _velocity_profile.integral(t)
        v_sample = _velocity_profile.value(t)
    dt = np.diff(t)
    v_step = np.diff(x) / dt
    z0 = law.initial_state(1) if initial_state is None else np.asarray(initial_state, float)
    states = law.trajectory(z0, v_step, dt, inputs)[:, :, 0]
    force = law.force(states.T, v_sample, inputs)
    stored = law.relaxed_storage(states.T)
    return BenchResult(t, x, v_sample, force, states, tuple(law.state_names),
                       "velocity" if _velocity_profile is not None else "displacement",
                       period=(_velocity_profile or position).period(), stored_energy=stored)


def simulate_velocity(law: FrictionLaw, velocity, duration: float, time_step: float,
                      inputs: ContactInputs = NO_INPUTS, initial_state=None) -> BenchResult:
    """Prescribed sliding velocity v(t) (profile of :func:`profile_type` ("velocity")).

    Same parameters as :func:`simulate_displacement`; the displacement is the exact integral
    of v(t) and every step uses its mean velocity.

    Examples
    --------
    >>> import warnings
    >>> from sealsim.friction import LuGre
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     law = LuGre.from_parameter_set("canudas1995")
    >>> res = simulate_velocity(law, _constant(0.01), 0.1, 1e-3)
    >>> round(float(res.force[-1]), 6)                    # steady: g(v) + σ2·v
    1.004
    """
    return simulate_displacement(law, None, duration, time_step, inputs, initial_state,
                                 _velocity_profile=velocity)


# --------------------------------------------------------------------------------------------
# Driven mass
# --------------------------------------------------------------------------------------------
def simulate_mass(law: FrictionLaw, mass: float, duration: float, time_step: float, *,
                  stiffness: float = 0.0, drive_velocity=None, applied_force=None,
                  inputs: ContactInputs = NO_INPUTS, initial_state=None,
                  integrator: str = "auto", rtol: float = 1e-7, max_step: float | None = None,
                  progress=None) -> BenchResult:
    """A body of mass m on the contacts, pulled by a spring and/or pushed by a force.

    .. math:: m\\,\\dot v = F_{app}(t) + k\\,(x_d(t) - x) - F, \\qquad \\dot x = v,
              \\qquad \\dot x_d = v_d(t)

    Parameters
    ----------
    law : FrictionLaw
    mass : float
        m [kg], > 0.
    duration : float
        [s].
    time_step : float
        Step of the stick/slip stepper and output interval of solve_ivp [s].
    stiffness : float
        Spring stiffness k [N/m], >= 0.
    drive_velocity : profile, optional
        Velocity of the spring end v_d(t) [m/s] (zero segments are dwells).
    applied_force : profile, optional
        Force on the body F_app(t) [N].
    inputs : ContactInputs
        Constant law inputs.
    initial_state : array_like, optional
        Friction states at t = 0 (body at rest at x = 0, spring relaxed).
    integrator : {"auto", "compiled", "radau", "bdf", "stepper"}
        "auto": the compiled BDF integrator ("compiled") for smooth laws, the stick/slip
        stepper for laws with true sticking and GMS; "radau", "bdf": scipy's solve_ivp.
    rtol : float
        Relative tolerance of the ODE integrator.
    max_step : float, optional
        Largest step of the ODE integrator [s] (default: a quarter of the shortest profile
        segment).
    progress : callable, optional
        Called with the fraction done (0..1) now and then.

    Returns
    -------
    BenchResult
    """
    if not (np.isfinite(mass) and mass > 0):
        raise InputError(f"bench.mass: must be > 0, got {mass!r}")
    if not (np.isfinite(stiffness) and stiffness >= 0):
        raise InputError(f"bench.stiffness: must be >= 0, got {stiffness!r}")
    if integrator not in ("auto", "compiled", "radau", "bdf", "stepper"):
        raise InputError(f"bench.integrator: {integrator!r} is not allowed; choose one of "
                         "'auto', 'compiled', 'radau', 'bdf', 'stepper'")
    if drive_velocity is None:
        drive_velocity = _constant(0.0)
    if applied_force is None:
        applied_force = _constant(0.0)
    t = _grid(duration, time_step)
    z0 = law.initial_state(1) if initial_state is None else np.asarray(initial_state, float)
    use_stepper = integrator == "stepper" or (integrator == "auto" and (
        law.has_stiction or law.name == "gms"))
    if law.has_stiction and not use_stepper:
        raise InputError(f"bench.integrator: {integrator!r} cannot resolve the true sticking of "
                         f"the {law.name} law; use 'auto' or 'stepper'")
    xd = drive_velocity.integral(t)
    fa = applied_force.value(t)
    if use_stepper:
        res = _mass_stepper(law, mass, stiffness, t, xd, fa, inputs, z0, progress)
    else:
        res = _mass_ivp(law, mass, stiffness, t, drive_velocity, applied_force, inputs, z0,
                        {"auto": "compiled", "compiled": "compiled", "radau": "Radau",
                         "bdf": "BDF"}[integrator], rtol, max_step)
    period = drive_velocity.period() or applied_force.period()
    res.period = period
    return res


def _mass_stepper(law, mass, stiffness, t, xd, fa, inputs, z0, progress):
    n = t.size
    states = np.empty((n, law.n_states))
    x = np.zeros(n)
    v = np.zeros(n)
    force = np.zeros(n)
    stuck = np.zeros(n, dtype=bool)
    z = np.array(z0, dtype=float)
    states[0] = z[:, 0]
    # force at t = 0: the body is at rest, friction holds the initial spring/applied force
    f_ext0 = fa[0] + stiffness * xd[0]
    if law.has_stiction:
        brk = law.breakaway_force(z, inputs)[0]
        force[0] = float(np.clip(f_ext0, -brk, brk))
        stuck[0] = abs(f_ext0) <= brk
    else:
        force[0] = law.force(z, np.zeros(1), inputs)[0]
    if compiled_law(law):
        _compiled_steps(law, mass, stiffness, t, xd, fa, inputs, z, states, x, v, force, stuck,
                        progress)
    else:                               # any other law object: the vectorised stepper
        xi = np.zeros(1)
        vi = np.zeros(1)
        every = max(1, n // 50)
        for k in range(1, n):
            dt = t[k] - t[k - 1]
            z, xi, vi, fk, st = implicit_mass_step(
                law, z, xi, vi, dt, mass, stiffness, np.array([xd[k]]), np.array([fa[k]]),
                inputs, where=f" at t = {t[k]:.6g} s")
            states[k] = z[:, 0]
            x[k] = xi[0]
            v[k] = vi[0]
            force[k] = fk[0]
            stuck[k] = st[0]
            if progress is not None and k % every == 0:
                progress(k / (n - 1))
    return BenchResult(t, x, v, force, states, tuple(law.state_names), "mass",
                       drive_position=xd, applied_force=fa + stiffness * (xd - x),
                       stuck=stuck if law.has_stiction else None,
                       stored_energy=law.relaxed_storage(states.T))


# -- the driven mass as one compiled ODE (smooth laws) -------------------------------------
# args: (law code, parameters, mass, stiffness, drive kind, drive table, force kind, force
#        table, contact vector (sealsim.friction.compiled.K_*), state scales for the Jacobian,
#        contact table row and data)
@njit(cache=True)
def _mass_fun(t, y, args, dy):
    """d/dt [x, v, z...] of the body: m·dv/dt = F_app + k·(x_d − x) − F."""
    x_drive = profile_integral(args[4], args[5], t)
    f_ext = profile_value(args[6], args[7], t) + args[3] * (x_drive - y[0])
    force, _ = contact_rates(args[0], args[1], y[:, None], 2, y[1], args[8], args[10],
                             args[11], dy[:, None], 0)
    dy[0] = y[1]
    dy[1] = (f_ext - force) / args[2]


@njit(cache=True)
def _mass_jac(t, y, f0, args, jac):
    """Forward differences from f0 = f(t, y), h_j = 1.5e-8·max(|y_j|, scale_j)."""
    n = y.shape[0]
    f1, shifted = np.empty(n), y.copy()
    for j in range(n):
        h = 1.5e-8 * max(abs(y[j]), args[9][j])
        shifted[j] = y[j] + h
        _mass_fun(t, shifted, args, f1)
        shifted[j] = y[j]
        for i in range(n):
            jac[i, j] = (f1[i] - f0[i]) / h


@njit(cache=True)
def _no_event(t, y, args):
    return 1.0


_MASS = compile_bdf("friction_mass", _mass_fun, _mass_jac, _no_event)
_mass_start, _mass_step = _MASS.start, _MASS.step


@njit(cache=True)
def _mass_run(ws, grid, y0, args, out):
    """Integrate over the grid, the states at every grid time into out (rows); returns the
    number of rows filled (< grid size: the step size became too small)."""
    _mass_start(ws, grid[0], y0, grid[-1], args)
    for i in range(y0.shape[0]):
        out[0, i] = y0[i]
    k = 1
    s = ws[0]
    while s[bdf.S_T] < grid[-1]:
        if _mass_step(ws, args) != bdf.OK:
            return k
        while k < grid.shape[0] and grid[k] <= s[bdf.S_T]:
            bdf.dense(ws, grid[k], out[k])
            k += 1
    return k


def _mass_compiled(law, mass, stiffness, t, drive_velocity, applied_force, inputs, z0, rtol,
                   atol, max_step, y0):
    """States (N, n) on the grid t with the compiled BDF of :mod:`sealsim.ode`."""
    par, contact, frow, fdata = contact_values(law, inputs)
    drive_kind, drive_table = drive_velocity.table()
    force_kind, force_table = applied_force.table()
    args = (LAW_CODES[law.name], par, float(mass), float(stiffness), drive_kind, drive_table,
            force_kind, force_table, contact, atol / rtol, frow, fdata)
    ws = bdf.workspace(y0.size, y0.size, rtol, atol, max_step)
    out = np.zeros((t.size, y0.size))
    done = _mass_run(ws, t, y0, args, out)
    if done < t.size:
        raise ConvergenceError(f"friction bench: the compiled BDF integrator failed at "
                               f"t = {t[done - 1]:.6g} s (step size too small)")
    stats = {"solver_rhs_evaluations": int(ws[1][bdf.I_NFEV]),
             "solver_jacobians": int(ws[1][bdf.I_NJEV])}
    return out.T, stats


def _compiled_steps(law, mass, stiffness, t, xd, fa, inputs, z, states, x, v, force, stuck,
                    progress):
    """The steps of :func:`_mass_stepper` with the compiled stepper
    (:func:`sealsim.friction.compiled.mass_steps`), in chunks for the progress callback."""
    n = t.size
    code = LAW_CODES[law.name]
    par, contact, frow, fdata = contact_values(law, inputs)
    zk = np.ascontiguousarray(z[:, 0])
    xk = vk = 0.0
    every = max(1, n // 50)
    for k0 in range(1, n, every):
        k1 = min(k0 + every, n)
        reached, xk, vk = mass_steps(code, par, law.has_stiction, zk, xk, vk, t, xd, fa, k0,
                                     k1, float(mass), float(stiffness), contact, frow, fdata,
                                     states, x, v, force, stuck, 60)
        if reached < k1:
            raise ConvergenceError(f"friction bench: the velocity of the body did not converge "
                                   f"in 60 iterations at t = {t[reached]:.6g} s; try a "
                                   "smaller time_step")
        if progress is not None:
            progress((k1 - 1) / (n - 1))


def _mass_ivp(law, mass, stiffness, t, drive_velocity, applied_force, inputs, z0, method, rtol,
              max_step):
    from scipy.integrate import solve_ivp

    ns = law.n_states

    def rhs(time, y):
        x, v = y[0], y[1:2]
        z = y[2:].reshape(ns, 1)
        xd = drive_velocity.integral(time)
        f_ext = applied_force.value(time) + stiffness * (xd - x)
        f = law.force(z, v, inputs)[0]
        out = np.empty_like(y)
        out[0] = v[0]
        out[1] = (f_ext - f) / mass
        out[2:] = law.derivatives(z, v, inputs)[:, 0]
        return out

    def jac(time, y):
        v = y[1:2]
        z = y[2:].reshape(ns, 1)
        p = law.partials(z, v, inputs)
        j = np.zeros((ns + 2, ns + 2))
        j[0, 1] = 1.0
        j[1, 0] = -stiffness / mass
        j[1, 1] = -p.dforce_dv[0] / mass
        j[1, 2:] = -p.dforce_dz[:, 0] / mass
        j[2:, 1] = p.dzdot_dv[:, 0]
        j[2:, 2:] = p.dzdot_dz[:, :, 0]
        return j

    bps = np.concatenate([drive_velocity.breakpoints(), applied_force.breakpoints()])
    seg = np.diff(np.unique(np.concatenate([[t[0], t[-1]], bps[(bps > t[0]) & (bps < t[-1])]])))
    if max_step is None:
        max_step = float(np.min(seg)) / 4.0 if seg.size else np.inf
        per = drive_velocity.period() or applied_force.period()
        if per:
            max_step = min(max_step, per / 20.0)
    y0 = np.concatenate([[0.0, 0.0], np.asarray(z0, dtype=float)[:, 0]])
    zscale = np.abs(law.steady_state(np.array([1.0]), inputs)[:, 0])
    atol = np.concatenate([[1e-12, 1e-12], np.maximum(zscale, 1e-12) * 1e-9])
    if method == "compiled" and not compiled_law(law):
        method = "Radau"                 # a law object without a compiled form: scipy
    if method == "compiled":
        ys, extra = _mass_compiled(law, mass, stiffness, t, drive_velocity, applied_force,
                                   inputs, z0, rtol, atol, max_step, y0)
    else:
        sol = solve_ivp(rhs, (t[0], t[-1]), y0, method=method, jac=jac, t_eval=t, rtol=rtol,
                        atol=atol, max_step=max_step)
        if not sol.success:
            raise ConvergenceError(f"friction bench: solve_ivp ({method}) failed at t = "
                                   f"{sol.t[-1] if sol.t.size else t[0]:.6g} s: {sol.message}")
        ys = sol.y
        extra = {"solver_rhs_evaluations": int(sol.nfev), "solver_jacobians": int(sol.njev)}
    x, v = ys[0], ys[1]
    states = ys[2:].T
    force = law.force(states.T, v, inputs)
    xd = drive_velocity.integral(t)
    return BenchResult(t, x, v, force, states, tuple(law.state_names), "mass",
                       drive_position=xd,
                       applied_force=applied_force.value(t) + stiffness * (xd - x),
                       stored_energy=law.relaxed_storage(states.T), extra=extra)


