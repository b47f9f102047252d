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
from sealsim.friction.compiled import LAW_CODES, STEP_OK, law_parameters, mass_step

__all__ = ["contact_values", "implicit_mass_step", "resolve_stick"]


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


def contact_values(law: FrictionLaw, inputs: ContactInputs, n: int):
    """The inputs of ``n`` contacts as the compiled laws take them
    (:mod:`sealsim.friction.compiled`): arrays F_N [N], b [m], p_A, p_B [Pa] and T [K]
    (T_ref of the Θ law where γ does not follow the temperature), each of shape (n,)."""
    def field(name, default, **check):
        value = default if law.name != "theta" and name in ("normal_force", "contact_width") \
            else inputs.require(name, law.name, **check)
        return np.ascontiguousarray(np.broadcast_to(np.asarray(value, dtype=float), (n,)))

    fn = field("normal_force", 1.0, positive=True)
    width = field("contact_width", 0.0, nonnegative=True)
    pa = field("pressure_a", 0.0)
    pb = field("pressure_b", 0.0)
    temp = np.full(n, float(getattr(law.params, "reference_temperature", 293.15)))
    if law.name == "theta" and law.walther[1] != 0.0 and inputs.temperature is not None:
        temp = field("temperature", 0.0, positive=True)
    return fn, width, pa, pb, temp


def implicit_mass_step(law: FrictionLaw, z0, x0, v0, dt, mass, stiffness, drive_position,
                       applied_force, inputs: ContactInputs, *, max_iter: int = 60,
                       where: str = ""):
    """One implicit step of a body on the contacts (see the module docstring); the compiled
    :func:`sealsim.friction.compiled.mass_step` for every contact.

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
    n = x0.shape[0]
    z0 = np.asarray(z0, dtype=float).reshape(law.n_states, -1)
    code, par = LAW_CODES[law.name], law_parameters(law)
    fn, width, pa, pb, temp = contact_values(law, inputs, n)
    mass, stiffness, drive_position, applied_force = (
        np.broadcast_to(np.asarray(a, dtype=float), (n,)) for a in
        (mass, stiffness, drive_position, applied_force))
    z1 = np.empty((law.n_states, n))
    x1, v1, force = np.empty(n), np.empty(n), np.empty(n)
    stuck = np.zeros(n, dtype=bool)
    zi, zo = np.empty(law.n_states), np.empty(law.n_states)
    rates = np.empty((max(law.n_states, 1), 1))
    for i in range(n):
        zi[:] = z0[:, i] if z0.shape[1] > 1 else z0[:, 0]
        x1[i], v1[i], force[i], stuck[i], status = mass_step(
            code, par, law.has_stiction, zi, x0[i], v0[i], dt, mass[i], stiffness[i],
            drive_position[i], applied_force[i], fn[i], width[i], pa[i], pb[i], temp[i], zo,
            rates, max_iter)
        if status != STEP_OK:
            raise ConvergenceError(f"friction bench: the velocity of the body did not converge "
                                   f"in {max_iter} iterations{where}; try a smaller time_step")
        z1[:, i] = zo
    return z1, x1, v1, force, stuck
