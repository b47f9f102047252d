"""Friction test benches: drive a law and record what a test rig would measure.

Three benches (seed 001 Fig. 11; Canudas de Wit et al. 1995 §4):

* **prescribed velocity** v(t) -- the contact slides at a given speed (``simulate_velocity``);
* **prescribed displacement** x(t) -- e.g. a crank drive (``simulate_displacement``);
* **driven mass** -- a body of mass m on the contacts, pulled by a spring k whose end moves with
  a drive velocity profile (stick-slip; dwell phases are zero-velocity segments) and/or pushed
  by an applied force F_app(t) (pre-sliding, break-away) (``simulate_mass``).

Prescribed motion uses the law's exact step with the mean velocity of every step,
v_k = (x(t_{k+1}) − x(t_k))/dt, so the displacement is exact and the states are second-order
accurate; laws whose step is affine in the state run as a vectorised scan (no Python loop).

The driven mass is integrated either with scipy's implicit ``solve_ivp`` (Radau or BDF, analytic
Jacobian from the law's ``partials``) for smooth laws, or with the implicit stick/slip stepper of
:mod:`sealsim.friction.hybrid` for laws with true sticking (Coulomb, Stribeck, Θ) and for GMS,
whose element switching does not suit an error-controlled integrator.

Profiles (constant, harmonic, piecewise linear) are case-file models with units; the summary
(:func:`summarize`) extracts break-away forces, loop areas and dissipated energy.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field, create_model, model_validator

from sealsim.cases import CaseModel, Q
from sealsim.errors import ConvergenceError, InputError
from sealsim.friction.base import NO_INPUTS, ContactInputs, FrictionLaw
from sealsim.friction.hybrid import implicit_mass_step

__all__ = [
    "BenchResult",
    "profile_type",
    "simulate_displacement",
    "simulate_mass",
    "simulate_velocity",
    "summarize",
]


# --------------------------------------------------------------------------------------------
# Profiles
# --------------------------------------------------------------------------------------------
class _ConstantBase(CaseModel):
    """A constant value."""

    def value(self, t):
        return np.full(np.shape(t), self.value_, dtype=float)

    def integral(self, t):
        return self.value_ * np.asarray(t, dtype=float)

    def derivative(self, t):
        return np.zeros(np.shape(t))

    @property
    def value_(self) -> float:
        return self.level  # type: ignore[attr-defined]

    def breakpoints(self):
        return np.array([])

    def period(self):
        return None


class _HarmonicBase(CaseModel):
    """mean + amplitude·cos(ω·t + phase)."""

    def value(self, t):
        t = np.asarray(t, dtype=float)
        return self.mean + self.amplitude * np.cos(self.angular_frequency * t + self.phase)

    def integral(self, t):
        t = np.asarray(t, dtype=float)
        w = self.angular_frequency
        return self.mean * t + self.amplitude / w * (np.sin(w * t + self.phase)
                                                      - np.sin(self.phase))

    def derivative(self, t):
        t = np.asarray(t, dtype=float)
        w = self.angular_frequency
        return -self.amplitude * w * np.sin(w * t + self.phase)

    def breakpoints(self):
        return np.array([])

    def period(self):
        return 2.0 * np.pi / self.angular_frequency


class _PiecewiseBase(CaseModel):
    """Linear interpolation between (times, values); constant outside."""

    @model_validator(mode="after")
    def _check(self):
        t = np.asarray(self.times, dtype=float)
        if len(self.times) != len(self.values):
            raise ValueError(f"times and values must have the same length "
                             f"(got {len(self.times)} and {len(self.values)})")
        if len(t) < 1 or np.any(np.diff(t) <= 0):
            raise ValueError("times must be increasing, e.g. ['0 s', '1 s', '3 s']")
        return self

    def value(self, t):
        return np.interp(np.asarray(t, dtype=float), self.times, self.values)

    def integral(self, t):
        t = np.asarray(t, dtype=float)
        tp = np.asarray(self.times, dtype=float)
        vp = np.asarray(self.values, dtype=float)
        # extend with the held values before the first and after the last point
        cum = np.concatenate([[0.0], np.cumsum(0.5 * (vp[1:] + vp[:-1]) * np.diff(tp))])
        before = vp[0] * np.minimum(t, tp[0])          # constant vp[0] from 0 to tp[0]
        inside_t = np.clip(t, tp[0], tp[-1])
        idx = np.clip(np.searchsorted(tp, inside_t, side="right") - 1, 0, len(tp) - 1)
        seg_t0 = tp[idx]
        v0 = vp[idx]
        v_at = np.interp(inside_t, tp, vp)
        inside = cum[idx] + 0.5 * (v0 + v_at) * (inside_t - seg_t0)
        after = vp[-1] * np.maximum(t - tp[-1], 0.0)
        return before + inside + after

    def derivative(self, t):
        t = np.asarray(t, dtype=float)
        tp = np.asarray(self.times, dtype=float)
        vp = np.asarray(self.values, dtype=float)
        if len(tp) < 2:
            return np.zeros(t.shape)
        slopes = np.diff(vp) / np.diff(tp)
        idx = np.searchsorted(tp, t, side="right") - 1
        inside = (idx >= 0) & (idx < len(slopes))
        return np.where(inside, slopes[np.clip(idx, 0, len(slopes) - 1)], 0.0)

    def breakpoints(self):
        return np.asarray(self.times, dtype=float)

    def period(self):
        return None


_PROFILE_CACHE: dict[str, Any] = {}


def profile_type(dimension: str):
    """Case-file type of a time profile whose values have ``dimension``.

    A discriminated union on ``kind``:

    * ``kind = "constant"``: ``level``;
    * ``kind = "harmonic"``: ``mean + amplitude·cos(angular_frequency·t + phase)``
      (``phase`` in degrees or radians, e.g. ``"-90 deg"``);
    * ``kind = "piecewise"``: ``times`` and ``values`` lists, linear in between, held constant
      outside.

    Examples
    --------
    >>> from pydantic import TypeAdapter
    >>> p = TypeAdapter(profile_type("velocity")).validate_python(
    ...     {"kind": "piecewise", "times": ["0 s", "1 s"], "values": ["0 m/s", "2 m/s"]})
    >>> p.value([0.5, 3.0]), p.integral([1.0])
    (array([1., 2.]), array([1.]))
    """
    if dimension in _PROFILE_CACHE:
        return _PROFILE_CACHE[dimension]
    tag = dimension.title().replace("_", "")
    constant = create_model(
        f"Constant{tag}Profile", __base__=_ConstantBase,
        kind=(Literal["constant"], ...), level=(Q(dimension), ...))
    harmonic = create_model(
        f"Harmonic{tag}Profile", __base__=_HarmonicBase,
        kind=(Literal["harmonic"], ...), mean=(Q(dimension), 0.0),
        amplitude=(Q(dimension), ...),
        angular_frequency=(Q("angular_speed", gt=0), ...),
        phase=(Q("dimensionless"), 0.0))
    piecewise = create_model(
        f"Piecewise{tag}Profile", __base__=_PiecewiseBase,
        kind=(Literal["piecewise"], ...), times=(list[Q("time", ge=0)], ...),
        values=(list[Q(dimension)], ...))
    union = Annotated[constant | harmonic | piecewise, Field(discriminator="kind")]
    _PROFILE_CACHE[dimension] = union
    return union


def _constant(level: float):
    from pydantic import TypeAdapter

    return TypeAdapter(profile_type("velocity")).validate_python(
        {"kind": "constant", "level": level})


# --------------------------------------------------------------------------------------------
# Results
# --------------------------------------------------------------------------------------------
@dataclass
class BenchResult:
    """Time series of one bench run (one contact).

    Attributes
    ----------
    time, position, velocity, force : ndarray, shape (N,)
        Time [s], displacement of the sliding body [m], sliding velocity [m/s] and friction
        force [N] (opposing v).
    states : ndarray, shape (N, n_states)
        Friction states.
    state_names : tuple of str
    drive_position, applied_force : ndarray or None
        Spring-end position [m] and applied force [N] (driven mass only).
    stuck : ndarray of bool or None
        True where the body sticks (laws with true sticking on the driven mass).
    mode : str
        "velocity", "displacement" or "mass".
    period : float or None
        Period of a harmonic drive [s] (for loop areas).
    """

    time: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    force: np.ndarray
    states: np.ndarray
    state_names: tuple[str, ...]
    mode: str
    drive_position: np.ndarray | None = None
    applied_force: np.ndarray | None = None
    stuck: np.ndarray | None = None
    period: float | None = None
    stored_energy: np.ndarray | None = None
    extra: dict[str, Any] = field(default_factory=dict)

    def columns(self) -> dict[str, np.ndarray]:
        """Columns for a CSV table (names carry units)."""
        cols = {"time_s": self.time, "position_m": self.position,
                "velocity_m_s": self.velocity, "friction_force_N": self.force}
        for i, name in enumerate(self.state_names):
            unit = "" if name == "theta" else "_m"
            cols[f"{name}{unit}"] = self.states[:, i]
        if self.drive_position is not None:
            cols["drive_position_m"] = self.drive_position
        if self.applied_force is not None:
            cols["spring_plus_applied_force_N"] = self.applied_force
        if self.stuck is not None:
            cols["stuck"] = self.stuck.astype(int)
        return cols

    def decimated(self, max_rows: int) -> BenchResult:
        """Every k-th sample so that at most ``max_rows`` remain (plots, CSV)."""
        n = self.time.size
        if n <= max_rows:
            return self
        k = int(np.ceil(n / max_rows))
        idx = np.unique(np.concatenate([np.arange(0, n, k), [n - 1]]))

        def pick(a):
            return None if a is None else a[idx]

        return BenchResult(self.time[idx], self.position[idx], self.velocity[idx],
                           self.force[idx], self.states[idx], self.state_names, self.mode,
                           pick(self.drive_position), pick(self.applied_force),
                           pick(self.stuck), self.period, pick(self.stored_energy), self.extra)


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
    """Prescribed displacement x(t) (e.g. a crank drive, seed 001 Fig. 11).

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
    integrator : {"auto", "radau", "bdf", "stepper"}
        "auto": solve_ivp Radau for smooth laws, the stick/slip stepper for laws with true
        sticking and GMS.
    rtol : float
        Relative tolerance of solve_ivp.
    max_step : float, optional
        Largest solve_ivp step [s] (default: a quarter of the shortest profile segment).
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
    if integrator not in ("auto", "radau", "bdf", "stepper"):
        raise InputError(f"bench.integrator: {integrator!r} is not allowed; choose one of "
                         "'auto', 'radau', 'bdf', 'stepper'")
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
                        "Radau" if integrator in ("auto", "radau") else "BDF", rtol, max_step)
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
    xi = np.zeros(1)
    vi = np.zeros(1)
    every = max(1, n // 50)
    for k in range(1, n):
        dt = t[k] - t[k - 1]
        z, xi, vi, fk, st = implicit_mass_step(
            law, z, xi, vi, dt, mass, stiffness, np.array([xd[k]]), np.array([fa[k]]), inputs,
            where=f" at t = {t[k]:.6g} s")
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
    sol = solve_ivp(rhs, (t[0], t[-1]), y0, method=method, jac=jac, t_eval=t, rtol=rtol,
                    atol=atol, max_step=max_step)
    if not sol.success:
        raise ConvergenceError(f"friction bench: solve_ivp ({method}) failed at "
                               f"t = {sol.t[-1] if sol.t.size else t[0]:.6g} s: {sol.message}")
    x, v = sol.y[0], sol.y[1]
    states = sol.y[2:].T
    force = law.force(states.T, v, inputs)
    xd = drive_velocity.integral(t)
    return BenchResult(t, x, v, force, states, tuple(law.state_names), "mass",
                       drive_position=xd,
                       applied_force=applied_force.value(t) + stiffness * (xd - x),
                       stored_energy=law.relaxed_storage(states.T),
                       extra={"solver_rhs_evaluations": int(sol.nfev),
                              "solver_jacobians": int(sol.njev)})


# --------------------------------------------------------------------------------------------
# Summary
# --------------------------------------------------------------------------------------------
def motion_onsets(velocity, rest_velocity):
    """Indices where |v| first exceeds ``rest_velocity`` after at least one sample at rest.

    Examples
    --------
    >>> motion_onsets(np.array([0.0, 0.0, 0.2, 0.3, 0.0, -0.5]), 0.1)
    array([2, 5])
    """
    moving = np.abs(np.asarray(velocity)) > rest_velocity
    return np.where(~moving[:-1] & moving[1:])[0] + 1


def breakaway_forces(result: BenchResult, rest_velocity: float | None = None):
    """Friction force at each start of motion from rest.

    An onset is the first sample with |v| > v_rest after rest (default v_rest = 1e-3 of the
    largest |v|, at least 10 µm/s: slower creep counts as rest); its break-away force is the
    largest |F| from the sample before the onset
    until |v| reaches 10·v_rest (the force peak of the transition from stick to slip).

    Returns
    -------
    times : ndarray
        Onset times [s].
    forces : ndarray
        Break-away forces [N] (magnitudes).
    """
    v = result.velocity
    vmax = float(np.max(np.abs(v))) if v.size else 0.0
    if rest_velocity is None:
        rest_velocity = max(1e-3 * vmax, 1e-5)
    if vmax <= rest_velocity:
        return np.array([]), np.array([])
    onsets = motion_onsets(v, rest_velocity)
    times, forces = [], []
    for i in onsets:
        j = i
        while j < v.size - 1 and abs(v[j]) < 10 * rest_velocity:
            j += 1
        forces.append(float(np.max(np.abs(result.force[i - 1:j + 1]))))
        times.append(float(result.time[i]))
    return np.array(times), np.array(forces)


def cycle_work(result: BenchResult, start: float, end: float) -> float:
    """Work of the friction force from ``start`` to ``end`` [J], ∫F·v dt (trapezoid)."""
    sel = (result.time >= start - 1e-12) & (result.time <= end + 1e-12)
    p = result.force[sel] * result.velocity[sel]
    return float(np.trapezoid(p, result.time[sel]))


def loop_areas(result: BenchResult):
    """Areas of the last complete cycle of a periodic drive.

    Returns
    -------
    dict
        ``force_displacement_J``: ∮F dx over the last full period [J] (the energy dissipated
        per cycle); ``force_velocity_N_m_s``: |∮F dv| [N·m/s] (width of the F–v hysteresis
        loop); both None without a periodic drive or a complete period.
    """
    per = result.period
    t = result.time
    if not per or t[-1] - t[0] < per * (1 - 1e-9):
        return {"force_displacement_J": None, "force_velocity_N_m_s": None, "period_s": per}
    n_cycles = int(np.floor((t[-1] - t[0]) / per + 1e-9))
    start = t[0] + (n_cycles - 1) * per
    sel = (t >= start - 1e-12) & (t <= start + per + 1e-12)
    f = result.force[sel]
    fx = float(np.trapezoid(f, result.position[sel]))
    fv = float(abs(np.trapezoid(f, result.velocity[sel])))
    return {"force_displacement_J": fx, "force_velocity_N_m_s": fv, "period_s": per,
            "cycle_start_s": float(start)}


def stick_slip_period(result: BenchResult) -> float | None:
    """Mean time between successive slips of a driven mass (None if fewer than 3 slips).

    Slips are upward crossings of |v| through half the largest |v| (interpolated); the first
    interval is skipped (start-up transient).
    """
    v = np.abs(result.velocity)
    thr = 0.5 * float(np.max(v)) if v.size else 0.0
    if thr <= 0:
        return None
    idx = np.where((v[:-1] < thr) & (v[1:] >= thr))[0]
    if idx.size < 3:
        return None
    t = result.time
    cross = t[idx] + (thr - v[idx]) / (v[idx + 1] - v[idx]) * (t[idx + 1] - t[idx])
    return float(np.mean(np.diff(cross)[1:]))


def summarize(result: BenchResult) -> dict[str, Any]:
    """Numbers a user compares: break-away forces, loop areas, dissipated energy, extremes.

    The dissipated energy is the work of the friction force on the contact, ∫F·v dt, minus the
    energy still stored in the bristles at the end (equal for a relaxed end state).
    """
    times, forces = breakaway_forces(result)
    work = float(np.trapezoid(result.force * result.velocity, result.time))
    stored_end = float(result.stored_energy[-1]) if result.stored_energy is not None else 0.0
    out: dict[str, Any] = {
        "mode": result.mode,
        "duration_s": float(result.time[-1] - result.time[0]),
        "samples": int(result.time.size),
        "friction_work_J": work,
        "dissipated_energy_J": work - stored_end,
        "stored_energy_end_J": stored_end,
        "max_friction_force_N": float(np.max(result.force)),
        "min_friction_force_N": float(np.min(result.force)),
        "max_abs_velocity_m_s": float(np.max(np.abs(result.velocity))),
        "max_abs_position_m": float(np.max(np.abs(result.position))),
        "breakaway_times_s": times.tolist(),
        "breakaway_forces_N": forces.tolist(),
        "loop_areas": loop_areas(result),
    }
    if result.mode == "mass":
        out["stick_slip_period_s"] = stick_slip_period(result)
        if result.stuck is not None:
            out["stuck_fraction"] = float(np.mean(result.stuck))
    for name in result.state_names:
        i = result.state_names.index(name)
        out[f"{name}_min"] = float(np.min(result.states[:, i]))
        out[f"{name}_max"] = float(np.max(result.states[:, i]))
    out.update({k: v for k, v in result.extra.items()})
    return out
