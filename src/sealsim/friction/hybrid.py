"""Sticking and sliding of a driven body: the one place where stick/slip is resolved.

A body of mass m [kg] slides on the contacts; it is pulled by a spring of stiffness k [N/m]
whose end follows x_d(t) and by an applied force F_app(t)::

    m·dv/dt = F_app + k·(x_d − x) − F,     dx/dt = v

The time step is implicit (backward Euler in x and v) with the friction state updated by the
law's exact step for the new velocity, z1 = law.step(z0, v1, dt), and F = law.force(z1, v1).
Eliminating x1 = x0 + dt·v1 leaves one equation per contact for the new velocity v1::

    h(v1) = M·v1 + F(z1(v1), v1) − R = 0,   M = m/dt + k·dt,
    R = m·v0/dt + F_app(t1) + k·(x_d(t1) − x0)

**True sticking** (laws with ``has_stiction``: Coulomb, Stribeck, Θ without bristles): the
friction force at rest is set-valued, |F| <= F_brk(z).  The step first tries v1 = 0, which needs
the friction force F = R (the force that holds the body, including the impulse that stops it).
If |R| <= F_brk(z1) the body sticks: v1 = 0, x1 = x0 and F = R exactly -- no creep however long
the dwell.  Otherwise it slips in the direction of R, and h has a root in (0, R/M] (h(0+) =
F_brk − |R| < 0 and F·sgn(R) >= 0 there), found by bracketed Newton iteration.  This is the
velocity-level time stepping of Moreau (1988) for set-valued friction, and the discrete analogue
of Heipl & Murrenhoff Eq. 2 (friction balances the applied force up to F_S).

**Smooth laws** (LuGre, Dahl, GMS, Θ with bristles) have no set-valued part: h(v1) = 0 is solved
directly (bracket found by expansion from the previous velocity).  The bristle state makes the
body rest elastically in pre-sliding.

**Compiled.**  For the laws of :mod:`sealsim.friction` the same algorithm runs compiled,
one contact at a time (:func:`sealsim.friction.compiled.mass_step`; a test finds the same
bits); :func:`implicit_mass_step` is the vectorised form for any :class:`FrictionLaw` (e.g. a
law run through an FMU).

References
----------
.. [1] J. J. Moreau, "Unilateral contact and dry friction in finite freedom dynamics", in
   Nonsmooth Mechanics and Applications, CISM 302, Springer, 1988.
.. [2] D. Karnopp, "Computer simulation of stick-slip friction in mechanical dynamic systems",
   J. Dyn. Sys. Meas. Control 107, 100-103, 1985.
"""

from __future__ import annotations

import numpy as np

from sealsim.errors import ConvergenceError
from sealsim.friction.base import ContactInputs, FrictionLaw
from sealsim.friction.compiled import LAW_CODES, NO_TABLE, law_parameters

__all__ = ["compiled_law", "contact_values", "implicit_mass_step", "resolve_stick"]


def resolve_stick(required_force, breakaway_force):
    """Whether contacts at rest stick, and the friction force they then carry.

    .. math:: \\text{stick} \\iff |F_{req}| \\le F_{brk}, \\qquad F = F_{req}

    Parameters
    ----------
    required_force : array_like
        Friction force needed to keep the body at rest [N] (the applied force).
    breakaway_force : array_like
        Largest static friction force [N].

    Returns
    -------
    stick : ndarray of bool
    force : ndarray
        Friction force [N] when sticking (the required force), else ±F_brk.

    Examples
    --------
    >>> resolve_stick([1.0, -2.0], [1.5, 1.5])
    (array([ True, False]), array([ 1. , -1.5]))
    """
    required = np.asarray(required_force, dtype=float)
    brk = np.asarray(breakaway_force, dtype=float)
    stick = np.abs(required) <= brk
    return stick, np.where(stick, required, np.sign(required) * brk)


def compiled_law(law: FrictionLaw) -> bool:
    """True for the laws of :mod:`sealsim.friction` (their compiled form in
    :mod:`sealsim.friction.compiled` runs the stepper); other :class:`FrictionLaw` objects
    (e.g. an FMU) run through :func:`implicit_mass_step`."""
    return LAW_CODES.get(law.name) is not None and type(law).__module__.startswith(
        "sealsim.friction.")


def contact_values(law: FrictionLaw, inputs: ContactInputs):
    """One contact's inputs as the compiled laws take them (:mod:`sealsim.friction.compiled`):
    (parameters, contact vector [F_N, b, p_A, p_B, T, Δp, orientation], frow, fdata).  T is
    T_ref of the Θ law where nothing follows the temperature; frow, fdata the contact table of
    a Θ law with ``steady = "contact"`` (``NO_TABLE`` otherwise)."""
    theta = law.name == "theta"
    contact_law = getattr(law, "contact", False)

    def field(name, default, **check):
        if not theta and name in ("normal_force", "contact_width"):
            return float(default)
        return float(np.asarray(inputs.require(name, law.name, **check)).reshape(-1)[0])

    fn = field("normal_force", 1.0, positive=True)
    width = field("contact_width", 0.0, nonnegative=True)
    pa = field("pressure_a", 0.0)
    pb = field("pressure_b", 0.0)
    temp = float(getattr(law.params, "reference_temperature", 293.15))
    if contact_law or (theta and law.walther[1] != 0.0 and inputs.temperature is not None):
        temp = field("temperature", 0.0, positive=True)
    dp = abs(pa - pb) if inputs.pressure_difference is None else \
        float(np.asarray(inputs.pressure_difference, dtype=float).reshape(-1)[0])
    orient = float(np.asarray(inputs.table_orientation, dtype=float).reshape(-1)[0])
    frow, fdata = NO_TABLE
    diameter = 0.0
    if contact_law:
        law.contact_steady(np.zeros(1), inputs)      # an InputError names what is missing
        frow, fdata = inputs.contact_table.tables()
        diameter = field("sliding_diameter", 0.0, positive=True)
    contact = np.array([fn, width, pa, pb, temp, dp, orient])
    return law_parameters(law, diameter), contact, frow, fdata


def implicit_mass_step(law: FrictionLaw, z0, x0, v0, dt, mass, stiffness, drive_position,
                       applied_force, inputs: ContactInputs, *, max_iter: int = 60,
                       where: str = ""):
    """One implicit step of a body on the contacts (see the module docstring).

    Parameters
    ----------
    law : FrictionLaw
        The friction law.
    z0 : ndarray, shape (n_states, n)
        Friction states at the start of the step.
    x0, v0 : ndarray, shape (n,)
        Position [m] and velocity [m/s] of the body at the start.
    dt : float
        Step length [s].
    mass : float or ndarray
        Mass m [kg], > 0.
    stiffness : float or ndarray
        Drive spring stiffness k [N/m], >= 0.
    drive_position : ndarray, shape (n,)
        Position of the spring end at the end of the step x_d(t1) [m].
    applied_force : ndarray, shape (n,)
        Force applied to the body at the end of the step [N].
    inputs : ContactInputs
        Inputs of the law at the end of the step.
    max_iter : int
        Iteration limit of the velocity solve.
    where : str
        Text naming the step in a :class:`~sealsim.errors.ConvergenceError`.

    Returns
    -------
    z1 : ndarray, shape (n_states, n)
    x1, v1, force, stuck : ndarray, shape (n,)
        New position [m], velocity [m/s], friction force [N] and whether the body sticks.
    """
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
