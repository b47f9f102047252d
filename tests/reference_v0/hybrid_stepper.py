"""Frozen copy of the stick/slip stepper of before issue 27 (commit 96150dc,
sealsim/friction/hybrid.py: ``implicit_mass_step`` vectorised over contacts, one numpy call of
the law per evaluation), kept as the reference that the compiled stepper
(sealsim.friction.compiled.mass_step) is tested against and as the benchmark baseline.
Docstrings shortened; algorithm unchanged.  Do not edit."""
# ruff: noqa
from __future__ import annotations

import numpy as np

from sealsim.errors import ConvergenceError
from sealsim.friction.hybrid import resolve_stick


def implicit_mass_step(law: FrictionLaw, z0, x0, v0, dt, mass, stiffness, drive_position,
                       applied_force, inputs: ContactInputs, *, max_iter: int = 60,
                       where: str = ""):
    """One implicit step of a body on the contacts (vectorised)."""
    x0 = np.asarray(x0, dtype=float)
    v0 = np.asarray(v0, dtype=float)
    m_eff = mass / dt + stiffness * dt
    rhs = mass * v0 / dt + applied_force + stiffness * (drive_position - x0)

    def h(v):
        z1 = law.step(z0, v, dt, inputs)
        return m_eff * v + law.force(z1, v, inputs) - rhs

    n = x0.shape[0]
    stuck = np.zeros(n, dtype=bool)
    if law.has_stiction:
        z_rest = law.step(z0, np.zeros(n), dt, inputs)
        stuck, _ = resolve_stick(rhs, law.breakaway_force(z_rest, inputs))
        if stuck.all():                                  # fast path: everything sticks
            return z_rest, x0.copy(), np.zeros(n), rhs, stuck
        direction = np.where(rhs >= 0, 1.0, -1.0)
        lo = np.where(direction > 0, 0.0, rhs / m_eff)
        hi = np.where(direction > 0, rhs / m_eff, 0.0)
        guess = np.clip(v0, lo, hi)
        guess = np.where((guess == 0) | ~np.isfinite(guess), 0.5 * (lo + hi), guess)
        v1 = _solve_bracketed(h, guess, lo, hi, max_iter, where, m_eff, rhs,
                              active=~stuck)
        v1 = np.where(stuck, 0.0, v1)
    else:
        v1 = _solve_expanding(h, v0, m_eff, rhs, max_iter, where)
    z1 = law.step(z0, v1, dt, inputs)
    force = np.where(stuck, rhs, law.force(z1, v1, inputs)) if law.has_stiction else \
        law.force(z1, v1, inputs)
    x1 = x0 + dt * v1
    return z1, x1, v1, force, stuck


def _tolerance(m_eff, rhs, v):
    return 1e-12 * (np.abs(rhs) + m_eff * np.abs(v) + 1.0)


def _solve_bracketed(h, v, lo, hi, max_iter, where, m_eff, rhs, active):
    """Safeguarded Newton (finite-difference slope) inside [lo, hi] with h(lo) <= 0 <= h(hi)."""
    v = np.array(v, dtype=float)
    lo = np.array(lo, dtype=float)
    hi = np.array(hi, dtype=float)
    if not np.any(active):
        return v
    for _ in range(max_iter):
        hv = h(v)
        done = (np.abs(hv) <= _tolerance(m_eff, rhs, v)) | (hi - lo <= 1e-15 * (
            np.abs(v) + 1e-12)) | ~active
        if np.all(done):
            return v
        lo = np.where(hv < 0, v, lo)
        hi = np.where(hv > 0, v, hi)
        eps = 1e-7 * (np.abs(v) + 1e-6)
        slope = (h(v + eps) - hv) / eps
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = v - hv / slope
        ok = (slope > 0) & (newton > lo) & (newton < hi) & np.isfinite(newton)
        v = np.where(done, v, np.where(ok, newton, 0.5 * (lo + hi)))
    raise ConvergenceError(f"friction bench: the velocity of the body did not converge in "
                           f"{max_iter} iterations{where}; try a smaller time_step")


def _solve_expanding(h, v0, m_eff, rhs, max_iter, where):
    """Bracket the root of h by expansion around v0, then solve it with safeguarded Newton."""
    v0 = np.asarray(v0, dtype=float)
    scale = np.abs(rhs) / m_eff + np.abs(v0) + 1e-9
    lo = v0 - scale
    hi = v0 + scale
    for _ in range(200):
        h_lo, h_hi = h(lo), h(hi)
        bad_lo, bad_hi = h_lo > 0, h_hi < 0
        if not (np.any(bad_lo) or np.any(bad_hi)):
            break
        width = hi - lo
        lo = np.where(bad_lo, lo - width, lo)
        hi = np.where(bad_hi, hi + width, hi)
    else:  # pragma: no cover - h grows like M·v, so the expansion always ends
        raise ConvergenceError(f"friction bench: no bracket for the body velocity{where}")
    guess = np.clip(v0, lo, hi)
    return _solve_bracketed(h, guess, lo, hi, max_iter, where, m_eff, rhs,
                            active=np.ones(v0.shape, dtype=bool))



def dwell_stepper(law, t, drive_velocity, inputs, mass=1.0, stiffness=2000.0):
    """The friction force of the driven-mass bench (no applied force) on the grid t."""
    xd = drive_velocity.integral(t)
    z = law.initial_state(1)
    x = np.zeros(1)
    v = np.zeros(1)
    force = np.zeros(t.size)
    brk = law.breakaway_force(z, inputs)[0]
    force[0] = float(np.clip(stiffness * xd[0], -brk, brk))
    for k in range(1, t.size):
        z, x, v, f, _ = implicit_mass_step(law, z, x, v, t[k] - t[k - 1], mass, stiffness,
                                           np.array([xd[k]]), np.zeros(1), inputs)
        force[k] = f[0]
    return force
