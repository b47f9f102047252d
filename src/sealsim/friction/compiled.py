r"""Every friction law as compiled functions of a law code and a parameter vector.

The law objects of :mod:`sealsim.friction` are numpy-facing; compiled models (the pneumatic
right-hand side :mod:`sealsim.pneumatic.rhs`, the driven-mass bench) need the same laws as
scalar functions of plain numbers.  :func:`law_parameters` flattens a law object into a
parameter vector (SI), and three compiled functions evaluate it, composed of the kernels of
:mod:`sealsim.friction.kernels` (the one implementation of each law):

* :func:`law_rates` -- friction force, break-away force and the state rates (what an ODE
  integrator needs);
* :func:`law_step` -- the exact state update for a velocity held over a step (the law's
  ``step``);
* :func:`mass_step` -- one implicit step of a body driven through a spring (the stick/slip
  stepper of :mod:`sealsim.friction.hybrid`, whose module docstring gives the equations).

The contact inputs are scalars: normal force F_N [N], contact width b [m], pressures p_A, p_B
[Pa] and temperature T [K] (for γ(T) of the Θ law and the contact table; pass T_ref when it is
not known), and for the Θ law with ``steady = "contact"`` the seal's steady friction table
(``frow``, ``fdata``: :meth:`sealsim.friction.contact_table.SteadyFrictionTable.tables`), read at
the pressure difference Δp [Pa] and the velocity times the table orientation ±1
(:class:`sealsim.friction.base.ContactInputs`).  Laws without a table get :data:`NO_TABLE`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sealsim.errors import InputError
from sealsim.friction import kernels as fk
from sealsim.friction.contact_table import (FILM_DECAY, _film_cell, cell_sum, cell_sum_pair,
                                            film_decay_rate, speed_cell, table_cell)

__all__ = ["LAW_CODES", "NO_TABLE", "contact_steady", "law_parameters", "law_rates", "law_step",
           "mass_step"]

#: law codes
COULOMB, STRIBECK, LUGRE, DAHL, GMS, THETA = range(6)
LAW_CODES = {"coulomb": COULOMB, "stribeck": STRIBECK, "lugre": LUGRE, "dahl": DAHL,
             "gms": GMS, "theta": THETA}
#: results of :func:`mass_step`
STEP_OK, STEP_NOT_CONVERGED = 0, 1
#: (frow, fdata) of a contact without a friction table
NO_TABLE = (np.zeros(4, dtype=np.int64), np.zeros(1))
#: columns of the Θ law's parameters: steady curve from the contact table (1/0), μ_b, the
#: dwell drop d, the circumference π·D [m]
TH_CONTACT, TH_MU_B, TH_DROP, TH_CIRCUMFERENCE, TH_NU_REF = 12, 13, 14, 15, 16


def law_parameters(law, sliding_diameter: float = 0.0) -> np.ndarray:
    """The parameters of a friction-law object as the vector of the compiled functions, SI:

    * coulomb: F_C, F_v, f;
    * stribeck: F_C, F_S, v_S, δ, F_v, f;
    * lugre: σ0, σ1, σ2, F_C, F_S, v_S, δ;
    * dahl: σ0, F_C, α;
    * gms: N, C, σ2, F_C, F_S, v_S, δ, k_1..k_N, α_1..α_N;
    * theta: τ, α, f_a, f_b, γ, F_ref, n, σ0 (0 without bristles), σ1, T_ref, A, B (ASTM D341
      constants of the base oil, B = 0: γ constant), then 1 if the steady curve comes from the
      seal's contact table (else 0), μ_b, the dwell drop d, the circumference π·D of the
      ``sliding_diameter`` D [m] (the table is per unit circumference) and the base oil's
      viscosity ν(T_ref) [mm²/s] (ASTM D341, 0 without base-oil data): γ(T) = γ·ν(T)/ν(T_ref)
      at every evaluation of a seal whose temperature changes, with ν(T_ref) computed once
      here (by the same compiled kernel: the same number as before, two powers and a
      logarithm less per evaluation).

    Examples
    --------
    >>> from sealsim.friction import CoulombViscous
    >>> law_parameters(CoulombViscous(coulomb_force=3.0, viscous_coefficient=5.0))
    array([3., 5., 0.])
    """
    p = law.params
    name = law.name
    if name == "coulomb":
        values = [p.coulomb_force, p.viscous_coefficient, p.pressure_coefficient]
    elif name == "stribeck":
        values = [p.coulomb_force, p.static_force, p.stribeck_velocity, p.exponent,
                  p.viscous_coefficient, p.pressure_coefficient]
    elif name == "lugre":
        values = [p.sigma0, p.sigma1, p.sigma2, p.coulomb_force, p.static_force,
                  p.stribeck_velocity, p.exponent]
    elif name == "dahl":
        values = [p.sigma0, p.coulomb_force, p.exponent]
    elif name == "gms":
        values = [p.n_elements, p.attraction, p.sigma2, p.coulomb_force, p.static_force,
                  p.stribeck_velocity, p.exponent, *law.k[:, 0], *law.alpha[:, 0]]
    elif name == "theta":
        a, b = law.walther
        values = [p.tau, p.alpha, p.f_a or 0.0, p.f_b or 0.0, p.gamma,
                  p.reference_normal_force, p.load_exponent, p.bristle_stiffness or 0.0,
                  p.bristle_damping, p.reference_temperature, a, b,
                  1.0 if p.steady == "contact" else 0.0, p.boundary_friction, p.dwell_drop,
                  math.pi * sliding_diameter,
                  fk.walther_viscosity(p.reference_temperature, a, b) if b != 0.0 else 0.0]
    else:  # pragma: no cover - every law of sealsim.friction is listed
        raise InputError(f"no compiled form of the {name!r} law")
    return np.asarray(values, dtype=float)


@njit(cache=True)
def contact_steady(par, frow, fdata, temp, dp, orient, vv, film):
    """(|F_ss| [N], its boundary part π·D·μ_b·L(φ) [N], π·D·V(|v|) [N], the film's decay rate
    κ(φ) [1/s]) of a Θ law on its seal's contact table
    (:meth:`sealsim.friction.theta.Theta.contact_steady` and ``film_decay``):
    π·D·(μ_b·L(φ) + V(|v|)) in the stroke direction of orient·v, the asperity load L and the
    decay rate κ at the speed ``film`` = φ [m/s] the film has formed for
    (:func:`~sealsim.friction.kernels.film_speed_rate`; φ = |v| in steady sliding; no film,
    φ = 0: the table's slowest speed, its first node), the viscous shear V at the sliding
    speed; at rest (v = 0) π·D·μ_b times the larger asperity load of both directions at φ
    (the level the film leaves, the sliding level's limit v → 0±) -- the table lookups of
    :func:`~sealsim.friction.contact_table.contact_table_point` sharing one cell search."""
    i, wa, j, wb = table_cell(frow, fdata, temp, dp)       # one cell search for all
    speed = orient * vv
    visc = 0.0
    if speed != 0.0:
        direction = 0 if speed > 0.0 else 2                # columns of the stroke direction
        k, wc = speed_cell(frow, fdata, speed)
        visc = cell_sum(frow, fdata, i, wa, j, wb, k, wc, direction + 1)
        if film != abs(speed):
            k, wc = _film_cell(frow, fdata, film)
        load, decay = cell_sum_pair(frow, fdata, i, wa, j, wb, k, wc, direction, FILM_DECAY)
    else:                           # at rest: the larger load the film leaves of both directions
        k, wc = _film_cell(frow, fdata, film)
        up, down = cell_sum_pair(frow, fdata, i, wa, j, wb, k, wc, 0, 2)
        load = max(up, down)
        decay = cell_sum(frow, fdata, i, wa, j, wb, k, wc, FILM_DECAY)
    circumference, mu = par[TH_CIRCUMFERENCE], par[TH_MU_B]
    return (circumference * (mu * load + visc), circumference * mu * load,
            circumference * visc, decay)


@njit(cache=True)
def film_trajectory(frow, fdata, temp, dp, speed, dt, width, film0, out):
    """The film's speed φ [m/s] of a Θ law on its contact table over N steps of n contacts
    into ``out`` (shape (N + 1, n)): the exact step of
    :func:`~sealsim.friction.kernels.film_speed_affine` with the film's decay rate κ(φ) of the
    table held over each step, at its start -- the law's ``step`` one step after the other
    (the rate depends on φ, so no parallel scan).  ``temp``, ``dp``, ``speed``, ``width``:
    T [K], Δp [Pa], v [m/s], b [m] per step and contact (shape (N, n)); ``dt`` (N,) [s];
    ``film0`` (n,) the start."""
    for col in range(out.shape[1]):
        film = film0[col]
        out[0, col] = film
        for k in range(dt.shape[0]):
            decay = film_decay_rate(frow, fdata, temp[k, col], dp[k, col], film)
            a, c = fk.film_speed_affine(speed[k, col], dt[k], width[k, col], decay)
            film = a * film + c
            out[k + 1, col] = film


@njit(cache=True)
def _theta_level(par, th, vv, fn, temp, frow, fdata, dp, orient, film):
    """Friction level of the Θ law [N]: lumped g_Θ, or on the contact table with the film
    formed for the speed ``film`` [m/s] (:func:`sealsim.friction.kernels.theta_contact_level`)."""
    if par[TH_CONTACT] > 0.0:
        return _theta_contact(par, th, vv, fn, temp, frow, fdata, dp, orient, film)[0]
    return fk.theta_friction_level(th, fn, par[2], par[3])


@njit(cache=True)
def _theta_contact(par, th, vv, fn, temp, frow, fdata, dp, orient, film):
    """(friction level [N], the film's decay rate κ [1/s]) of the Θ law on its contact table
    (:func:`contact_steady`, :func:`sealsim.friction.kernels.theta_contact_level`)."""
    fss, fb, fv, decay = contact_steady(par, frow, fdata, temp, dp, orient, vv, film)
    return fk.theta_contact_level(th, vv, fss, fb, par[TH_DROP],
                                  fk.theta_steady(vv, par[0], par[1], fn, par[5], par[6]),
                                  fv), decay


@njit(cache=True)
def law_rates(law, par, z, off, vv, fn, b, pa, pb, temp, dy, col, frow, fdata, dp, orient):
    """Friction force and break-away force [N] of one contact; writes its state rates into
    dy[off:, col] (states z[off:, col]).  The break-away force is that of the laws with true
    sticking (Coulomb, Stribeck, Θ without bristles), 0 for the others.  ``frow``/``fdata``,
    ``dp``, ``orient``: the contact table of a Θ law with ``steady = "contact"`` (see the
    module docstring)."""
    force = 0.0
    brk = 0.0
    if law == COULOMB:
        fc = fk.pressure_scaled_force(par[0], par[2], pa, pb)
        force = fk.coulomb_viscous_force(vv, fc, par[1])
        brk = fc
    elif law == STRIBECK:
        fc, fs = fk.stribeck_scaled_levels(par[0], par[1], par[5], pa, pb)
        force = fk.stribeck_force(vv, fc, fs, par[2], par[4], par[3])
        brk = fs
    elif law == LUGRE:
        g = fk.stribeck_level(vv, par[3], par[4], par[5], par[6])
        zdot = fk.lugre_bristle_rate(z[off, col], vv, par[0], g)
        force = fk.lugre_force(z[off, col], zdot, vv, par[0], par[1], par[2])
        dy[off, col] = zdot
    elif law == DAHL:
        force = par[0] * z[off, col]
        dy[off, col] = fk.dahl_bristle_rate(z[off, col], vv, par[0], par[1], par[2])
    elif law == GMS:
        n = int(par[0])
        s = fk.stribeck_level(vv, par[3], par[4], par[5], par[6])
        total = 0.0
        for j in range(n):
            zj = z[off + j, col]
            total += par[7 + j] * zj
            dy[off + j, col] = fk.gms_element_rate(zj, vv, par[7 + j], par[7 + n + j],
                                                   par[1], s)
        force = total + par[2] * vv
    elif law == THETA:
        contact = par[TH_CONTACT] > 0.0
        gamma = 0.0 if contact else _theta_gamma(par, temp)   # the table holds the viscous part
        th = z[off, col]
        fn = max(fn, 1e-9)
        if contact:                             # the film's speed, the law's last state
            last = off + (2 if par[7] > 0.0 else 1)
            film = z[last, col]
            level, decay = _theta_contact(par, th, vv, fn, temp, frow, fdata, dp, orient, film)
            dy[last, col] = fk.film_speed_rate(film, vv, b, decay)
        else:
            level = fk.theta_friction_level(th, fn, par[2], par[3])
        dy[off, col] = fk.theta_rate(th, vv, par[0], par[1], fn, par[5], par[6])
        if par[7] > 0.0:                        # bristles
            zdot = fk.lugre_bristle_rate(z[off + 1, col], vv, par[7], level)
            dy[off + 1, col] = zdot
            force = par[7] * z[off + 1, col] + par[8] * zdot + gamma * b * vv
        elif contact:
            force = level * fk.sgn(vv)
            brk = level
        else:
            force = fk.theta_force(th, vv, fn, b, par[2], par[3], gamma)
            brk = level
    return force, brk


@njit(cache=True)
def _theta_gamma(par, temp):
    """γ(T) of the Θ law (γ_ref without base-oil data)."""
    if par[11] != 0.0:                          # γ(T) from the base oil (ASTM D341)
        return par[4] * (fk.walther_viscosity(temp, par[10], par[11]) / par[TH_NU_REF])
    return par[4]


#: entries of a contact vector (the stepper's and the bench's contact inputs)
K_FN, K_WIDTH, K_PA, K_PB, K_TEMP, K_DP, K_ORIENT, K_SIZE = range(8)


@njit(cache=True)
def law_step(law, par, z0, v, dt, contact, frow, fdata, z1):
    """The states z1 (n_states,) after ``dt`` [s] from z0 with v [m/s] and the contact
    (vector ``K_*``: F_N, b, p_A, p_B, T, Δp, orientation) held: the exact updates of the
    laws' ``step`` methods."""
    if law == LUGRE:
        g = fk.stribeck_level(v, par[3], par[4], par[5], par[6])
        a, b = fk.lugre_affine(v, dt, par[0], g)
        z1[0] = a * z0[0] + b
    elif law == DAHL:
        z1[0] = fk.dahl_bristle_step(z0[0], v, dt, par[0], par[1], par[2])
    elif law == GMS:
        n = int(par[0])
        s = fk.stribeck_level(v, par[3], par[4], par[5], par[6])
        for j in range(n):
            z1[j] = fk.gms_element_step(z0[j], v, dt, par[7 + j], par[7 + n + j], par[1], s)
    elif law == THETA:
        fn = contact[K_FN]
        a, b = fk.theta_affine(v, dt, par[0], par[1], fn, par[5], par[6])
        th1 = a * z0[0] + b
        film_mid = 0.0
        if par[TH_CONTACT] > 0.0:               # the film's speed (the law's last state)
            last = 2 if par[7] > 0.0 else 1
            # the film's decay rate frozen at the step's start
            decay = film_decay_rate(frow, fdata, contact[K_TEMP], contact[K_DP], z0[last])
            a, b = fk.film_speed_affine(v, dt, contact[K_WIDTH], decay)
            z1[last] = a * z0[last] + b
            film_mid = 0.5 * (z0[last] + z1[last])
        if par[7] > 0.0:        # bristles: the exact step with the level of the mid-state
            g_mid = _theta_level(par, 0.5 * (z0[0] + th1), v, max(fn, 1e-9), contact[K_TEMP],
                                 frow, fdata, contact[K_DP], contact[K_ORIENT], film_mid)
            a, b = fk.lugre_affine(v, dt, par[7], g_mid)
            z1[1] = a * z0[1] + b
        z1[0] = th1


@njit(cache=True)
def contact_rates(law, par, z, off, v, contact, frow, fdata, dy, col):
    """:func:`law_rates` with the contact inputs of a contact vector (``K_*``)."""
    return law_rates(law, par, z, off, v, contact[K_FN], contact[K_WIDTH], contact[K_PA],
                     contact[K_PB], contact[K_TEMP], dy, col, frow, fdata, contact[K_DP],
                     contact[K_ORIENT])


@njit(cache=True)
def _stepped_force(law, par, z0, v, dt, contact, frow, fdata, z1, rates):
    """(F, F_brk) after the step with v held: z1 = law_step(z0), then the force at (z1, v)."""
    law_step(law, par, z0, v, dt, contact, frow, fdata, z1)
    return contact_rates(law, par, z1[:, None], 0, v, contact, frow, fdata, rates, 0)


@njit(cache=True)
def _residual(law, par, z0, v, dt, contact, frow, fdata, z1, rates, m_eff, rhs):
    force, _ = _stepped_force(law, par, z0, v, dt, contact, frow, fdata, z1, rates)
    return m_eff * v + force - rhs


@njit(cache=True)
def _bracketed(law, par, z0, dt, contact, frow, fdata, z1, rates, m_eff, rhs, v, lo, hi,
               max_iter):
    """Safeguarded Newton (finite-difference slope) inside [lo, hi] with h(lo) <= 0 <= h(hi);
    (v, converged)."""
    for _ in range(max_iter):
        hv = _residual(law, par, z0, v, dt, contact, frow, fdata, z1, rates, m_eff, rhs)
        if abs(hv) <= 1e-12 * (abs(rhs) + m_eff * abs(v) + 1.0) or \
                hi - lo <= 1e-15 * (abs(v) + 1e-12):
            return v, True
        if hv < 0.0:
            lo = v
        if hv > 0.0:
            hi = v
        eps = 1e-7 * (abs(v) + 1e-6)
        slope = (_residual(law, par, z0, v + eps, dt, contact, frow, fdata, z1, rates, m_eff,
                           rhs) - hv) / eps
        newton = v - hv / slope if slope != 0.0 else math.nan
        if slope > 0.0 and lo < newton < hi and math.isfinite(newton):
            v = newton
        else:
            v = 0.5 * (lo + hi)
    return v, False


@njit(cache=True)
def mass_step(law, par, sticky, z0, x0, v0, dt, mass, stiffness, drive_position,
              applied_force, contact, frow, fdata, z1, rates, max_iter):
    """One implicit step of a body on one contact (:mod:`sealsim.friction.hybrid`).

    Returns (x1, v1, F, stuck, status); the states after the step in z1."""
    m_eff = mass / dt + stiffness * dt
    rhs = mass * v0 / dt + applied_force + stiffness * (drive_position - x0)
    if sticky:
        _, brk = _stepped_force(law, par, z0, 0.0, dt, contact, frow, fdata, z1, rates)
        if abs(rhs) <= brk:                      # resolve_stick: it sticks, F = R
            return x0, 0.0, rhs, True, STEP_OK
        if rhs >= 0.0:
            lo, hi = 0.0, rhs / m_eff
        else:
            lo, hi = rhs / m_eff, 0.0
        guess = min(max(v0, lo), hi)
        if guess == 0.0 or not math.isfinite(guess):
            guess = 0.5 * (lo + hi)
    else:
        scale = abs(rhs) / m_eff + abs(v0) + 1e-9
        lo = v0 - scale
        hi = v0 + scale
        for _ in range(200):             # h grows like M·v: the expansion always ends
            bad_lo = _residual(law, par, z0, lo, dt, contact, frow, fdata, z1, rates, m_eff,
                               rhs) > 0.0
            bad_hi = _residual(law, par, z0, hi, dt, contact, frow, fdata, z1, rates, m_eff,
                               rhs) < 0.0
            if not (bad_lo or bad_hi):
                break
            width = hi - lo
            if bad_lo:
                lo -= width
            if bad_hi:
                hi += width
        guess = min(max(v0, lo), hi)
    v1, ok = _bracketed(law, par, z0, dt, contact, frow, fdata, z1, rates, m_eff, rhs, guess,
                        lo, hi, max_iter)
    force, _ = _stepped_force(law, par, z0, v1, dt, contact, frow, fdata, z1, rates)
    return x0 + dt * v1, v1, force, False, STEP_OK if ok else STEP_NOT_CONVERGED


@njit(cache=True)
def mass_steps(law, par, sticky, z, x, v, t, drive_position, applied_force, k0, k1, mass,
               stiffness, contact, frow, fdata, states, xs, vs, forces, stuck, max_iter):
    """The steps k0 ... k1-1 of :func:`mass_step` on the time grid t (step k from t[k-1] to
    t[k], drive position and applied force at t[k]); z (in/out) the states, x, v the body at
    t[k0-1].  Writes row k of the outputs; returns (k reached, x, v): k < k1 when the velocity
    solve did not converge in step k."""
    z1 = np.empty_like(z)
    rates = np.empty((max(z.shape[0], 1), 1))
    for k in range(k0, k1):
        x1, v1, force, st, status = mass_step(law, par, sticky, z, x, v, t[k] - t[k - 1], mass,
                                              stiffness, drive_position[k], applied_force[k],
                                              contact, frow, fdata, z1, rates, max_iter)
        if status != STEP_OK:
            return k, x, v
        for i in range(z.shape[0]):
            z[i] = z1[i]
            states[k, i] = z1[i]
        x, v = x1, v1
        xs[k], vs[k], forces[k], stuck[k] = x1, v1, force, st
    return k1, x, v
