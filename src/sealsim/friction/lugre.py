"""LuGre friction law (Canudas de Wit, Olsson, Åström, Lischinsky 1995).

The contact is modelled by elastic bristles of average deflection z [m]::

    dz/dt = v − σ0·|v|·z / g(v)                       (1995, Eq. 1)
    g(v)  = F_C + (F_S − F_C)·exp(−|v/v_s|^δ)         (1995, Eq. 3, δ = 2)
    F     = σ0·z + σ1·dz/dt + σ2·v                    (1995, Eq. 4)

Steady state: z_ss = g(v)·sgn(v)/σ0 and F_ss = g(v)·sgn(v) + σ2·v.

For a velocity held constant over a step, dz/dt is linear in z, so the step is exact::

    z(t + dt) = z_ss + (z − z_ss)·exp(−σ0·|v|·dt / g(v))

which is unconditionally stable however stiff the bristles are (σ0 = 1e5 N/m).

Passivity (Åström & Canudas de Wit 2008, Eq. 7): the map v → F is passive if
σ2 > σ1·(F_S − F_C)/F_C.  The classic Table I set violates it (it would need
σ2 > 158 N·s/m); :class:`LuGre` warns (:class:`~sealsim.friction.base.PassivityWarning`).

References
----------
.. [1] C. Canudas de Wit, H. Olsson, K. J. Åström, P. Lischinsky, "A new model for control of
   systems with friction", IEEE TAC 40(3), 419-425, 1995.
.. [2] K. J. Åström, C. Canudas de Wit, "Revisiting the LuGre friction model", IEEE Control
   Systems Magazine 28(6), 101-114, 2008 (Eq. 7 passivity, Eq. 8 damping).
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from pydantic import model_validator

from sealsim.cases import Q
from sealsim.friction import kernels as _k
from sealsim.friction.base import (
    NO_INPUTS,
    ContactInputs,
    FrictionLaw,
    LawParameters,
    Partials,
    as_state,
    as_velocity,
    require_static_at_least_coulomb,
    sign,
    validate_parameters,
    warn_passivity,
)
from sealsim.friction.kernels import apply
from sealsim.friction.stribeck import stribeck_force, stribeck_level, stribeck_level_derivative

__all__ = [
    "LuGre",
    "LuGreParameters",
    "lugre_bristle_rate",
    "lugre_bristle_step",
    "lugre_damping_bound",
    "lugre_force",
    "lugre_passivity_margin",
    "lugre_steady_force",
]


# --------------------------------------------------------------------------------------------
# Pure functions
# --------------------------------------------------------------------------------------------
def lugre_bristle_rate(z, v, sigma0, g):
    """Bristle deflection rate of the LuGre law (1995, Eq. 1).

    .. math:: \\dot z = v - \\sigma_0\\,|v|\\,z / g(v)

    Parameters
    ----------
    z : array_like
        Mean bristle deflection [m].
    v : array_like
        Sliding velocity [m/s].
    sigma0 : array_like
        Bristle stiffness σ0 [N/m].
    g : array_like
        Stribeck level g(v) [N] (:func:`sealsim.friction.stribeck.stribeck_level`), > 0.

    Returns
    -------
    ndarray
        dz/dt [m/s].

    Examples
    --------
    >>> float(lugre_bristle_rate(1e-5, 1e-2, 1e5, 1.0))
    0.0
    """
    return apply(_k._loop_lugre_bristle_rate, z, v, sigma0, g)


def lugre_force(z, zdot, v, sigma0, sigma1, sigma2):
    """LuGre friction force (1995, Eq. 4).

    .. math:: F = \\sigma_0 z + \\sigma_1 \\dot z + \\sigma_2 v

    Parameters
    ----------
    z : array_like
        Bristle deflection [m].
    zdot : array_like
        Bristle deflection rate [m/s] (:func:`lugre_bristle_rate`).
    v : array_like
        Sliding velocity [m/s].
    sigma0, sigma1, sigma2 : array_like
        Stiffness σ0 [N/m], micro-damping σ1 [N·s/m], viscous coefficient σ2 [N·s/m].

    Returns
    -------
    ndarray
        Friction force [N].

    Examples
    --------
    >>> float(lugre_force(1e-5, 0.0, 1e-2, 1e5, 316.2, 0.4))
    1.004
    """
    return apply(_k._loop_lugre_force, z, zdot, v, sigma0, sigma1, sigma2)


def lugre_steady_force(v, coulomb_force, static_force, stribeck_velocity, sigma2, exponent=2.0):
    """Steady-state LuGre force (1995, Eq. 5), F_ss = g(v)·sgn(v) + σ2·v.

    Parameters
    ----------
    v : array_like
        Sliding velocity [m/s].
    coulomb_force, static_force : array_like
        F_C, F_S [N].
    stribeck_velocity : array_like
        v_s [m/s].
    sigma2 : array_like
        Viscous coefficient σ2 [N·s/m].
    exponent : array_like
        Stribeck exponent δ [-] (2 in the 1995 paper).

    Returns
    -------
    ndarray
        Steady friction force [N].

    Examples
    --------
    >>> lugre_steady_force([-1e-3, 0.1], 1.0, 1.5, 1e-3, 0.4)
    array([-1.18433972,  1.04      ])
    """
    return stribeck_force(v, coulomb_force, static_force, stribeck_velocity, sigma2, exponent)


def lugre_bristle_step(z, v, dt, sigma0, g):
    """Exact bristle deflection after ``dt`` with v held constant.

    .. math:: z(t+\\Delta t) = z_{ss} + (z - z_{ss})\\,e^{-\\sigma_0 |v| \\Delta t/g(v)},
              \\qquad z_{ss} = \\operatorname{sgn}(v)\\,g(v)/\\sigma_0

    This is the solution of 1995 Eq. 1 for constant v: unconditionally stable.

    Parameters
    ----------
    z : array_like
        Bristle deflection at the start of the step [m].
    v : array_like
        Velocity held over the step [m/s].
    dt : array_like
        Step length [s], >= 0.
    sigma0 : array_like
        Bristle stiffness σ0 [N/m].
    g : array_like
        Stribeck level g(v) [N].

    Returns
    -------
    ndarray
        Bristle deflection at the end of the step [m].

    Examples
    --------
    >>> float(lugre_bristle_step(0.0, 1e-2, 1.0, 1e5, 1.0))   # fully developed: z = g/σ0
    1e-05
    >>> float(lugre_bristle_step(2e-6, 0.0, 10.0, 1e5, 1.5))  # at rest nothing changes
    2e-06
    """
    a, b = _lugre_affine(v, dt, sigma0, g)
    return a * np.asarray(z, dtype=float) + b


def _lugre_affine(v, dt, sigma0, g):
    """(a, b) of the exact step z1 = a·z0 + b (:func:`sealsim.friction.kernels.lugre_affine`)."""
    return apply(_k._loop_lugre_affine, v, dt, sigma0, g, outputs=2)


def lugre_passivity_margin(sigma1, sigma2, coulomb_force, static_force):
    """Margin of the passivity condition of Åström & Canudas de Wit (2008), Eq. 7.

    .. math:: \\sigma_2 - \\sigma_1\\,(F_S - F_C)/F_C \\; > 0 \\Rightarrow \\text{passive}

    Parameters
    ----------
    sigma1, sigma2 : array_like
        Micro-damping σ1 and viscous coefficient σ2 [N·s/m].
    coulomb_force, static_force : array_like
        F_C (> 0) and F_S [N].

    Returns
    -------
    ndarray
        Margin [N·s/m]; passive if > 0.

    Examples
    --------
    >>> float(lugre_passivity_margin(np.sqrt(1e5), 0.4, 1.0, 1.5))   # 1995 Table I set
    -157.7...
    """
    return np.asarray(sigma2) - np.asarray(sigma1) * (np.asarray(static_force) - coulomb_force
                                                      ) / coulomb_force


def lugre_damping_bound(mass, sigma0, sigma2, coulomb_force, static_force):
    """Largest relative damping ζ for which a mass on LuGre bristles is well damped (2008, Eq. 8).

    .. math:: \\zeta \\le \\frac{\\sigma_2}{2\\sqrt{\\sigma_0 m}}
              \\left(\\frac{F_C}{F_S - F_C} + 1\\right)

    Parameters
    ----------
    mass : array_like
        Moving mass m [kg].
    sigma0 : array_like
        Bristle stiffness [N/m].
    sigma2 : array_like
        Viscous coefficient [N·s/m].
    coulomb_force, static_force : array_like
        F_C, F_S [N] (F_S > F_C).

    Returns
    -------
    ndarray
        Upper bound of ζ [-].

    Examples
    --------
    >>> float(lugre_damping_bound(1.0, 1e5, 0.4, 1.0, 1.5))
    0.00189...
    """
    return (np.asarray(sigma2) / (2.0 * np.sqrt(np.asarray(sigma0) * mass))
            * (coulomb_force / (np.asarray(static_force) - coulomb_force) + 1.0))


# --------------------------------------------------------------------------------------------
# Parameters and law object
# --------------------------------------------------------------------------------------------
class LuGreParameters(LawParameters):
    """Parameters of the LuGre law (1995 notation)."""

    law: Literal["lugre"] = "lugre"
    sigma0: Q("stiffness", gt=0)
    sigma1: Q("damping", ge=0)
    sigma2: Q("damping", ge=0)
    coulomb_force: Q("force", gt=0)
    static_force: Q("force", gt=0)
    stribeck_velocity: Q("velocity", gt=0)
    exponent: Q("dimensionless", gt=0, le=10) = 2.0

    @model_validator(mode="after")
    def _static_above_coulomb(self):
        require_static_at_least_coulomb(self.static_force, self.coulomb_force)
        return self


class LuGre(FrictionLaw):
    """LuGre law: one bristle state z [m] per contact (see the module docstring).

    Parameters
    ----------
    params : LuGreParameters, optional
        Validated parameters, or keyword arguments in SI: ``sigma0`` [N/m], ``sigma1``
        [N·s/m], ``sigma2`` [N·s/m], ``coulomb_force`` [N], ``static_force`` [N],
        ``stribeck_velocity`` [m/s], ``exponent`` [-].
    warn : bool
        Warn (:class:`~sealsim.friction.base.PassivityWarning`) when the parameters violate
        the passivity condition (2008, Eq. 7).

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     law = LuGre.from_parameter_set("canudas1995")
    >>> law.is_passive()
    False
    >>> z = law.steady_state([0.1])
    >>> law.force(z, [0.1])
    array([1.04])
    >>> float(law.step(law.initial_state(1), [0.0], 1.0)[0, 0])
    0.0
    """

    name = "lugre"
    state_names = ("z",)
    affine = True

    def __init__(self, params: LuGreParameters | None = None, *, warn: bool = True, **values):
        self.params = params if params is not None else validate_parameters(
            LuGreParameters, values, "lugre parameters")
        if warn and not self.is_passive():
            p = self.params
            warn_passivity(
                f"LuGre parameters are not passive (Åström & Canudas de Wit 2008, Eq. 7): "
                f"sigma2 = {p.sigma2:g} N*s/m <= sigma1*(F_S - F_C)/F_C = "
                f"{p.sigma1 * (p.static_force - p.coulomb_force) / p.coulomb_force:g} N*s/m; "
                "the friction force can supply energy during fast velocity changes")

    @classmethod
    def from_parameter_set(cls, name: str, *, warn: bool = True, **overrides):
        """Law from a named set of :mod:`sealsim.friction.parameters` (fields override it)."""
        return cls(validate_parameters(LuGreParameters, {"parameter_set": name, **overrides},
                                       "lugre parameters"), warn=warn)

    # -- helpers -------------------------------------------------------------------------
    def g(self, v):
        """Stribeck level g(v) [N]."""
        p = self.params
        return stribeck_level(v, p.coulomb_force, p.static_force, p.stribeck_velocity,
                              p.exponent)

    def is_passive(self) -> bool:
        p = self.params
        return bool(lugre_passivity_margin(p.sigma1, p.sigma2, p.coulomb_force,
                                           p.static_force) > 0) or p.sigma1 == 0.0

    def relaxed_storage(self, z):
        z = np.asarray(z, dtype=float)
        return 0.5 * self.params.sigma0 * z[0] ** 2

    # -- interface -----------------------------------------------------------------------
    def derivatives(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, 1)
        # lugre_bristle_rate with g(v), in one compiled pass
        return apply(_k._loop_lugre_rate, z, v, p.sigma0, p.coulomb_force, p.static_force,
                     p.stribeck_velocity, p.exponent)

    def force(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, 1)
        # lugre_force of lugre_bristle_rate with g(v), in one compiled pass
        return apply(_k._loop_lugre_state_force, z[0], v, p.sigma0, p.sigma1, p.sigma2,
                     p.coulomb_force, p.static_force, p.stribeck_velocity, p.exponent)

    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, 1)[0]
        g = self.g(v)
        dg = stribeck_level_derivative(v, p.coulomb_force, p.static_force,
                                       p.stribeck_velocity, p.exponent)
        dfdz = -p.sigma0 * np.abs(v) / g
        dfdv = 1.0 - p.sigma0 * z * (sign(v) / g - np.abs(v) * dg / g ** 2)
        shape = np.broadcast_shapes(v.shape, z.shape)
        dfdz = np.broadcast_to(dfdz, shape)
        dfdv = np.broadcast_to(dfdv, shape)
        return Partials(dfdz[None, None, :], dfdv[None, :],
                        (p.sigma0 + p.sigma1 * dfdz)[None, :], p.sigma1 * dfdv + p.sigma2)

    def step(self, z, v, dt, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, 1)
        return lugre_bristle_step(z, v, dt, self.params.sigma0, self.g(v))

    def affine_coefficients(self, v, dt, inputs: ContactInputs = NO_INPUTS):
        v = np.asarray(v, dtype=float)
        a, b = _lugre_affine(v, dt, self.params.sigma0, self.g(v))
        return a[:, None, :], b[:, None, :]

    def steady_state(self, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        return (sign(v) * self.g(v) / self.params.sigma0)[None, :]

    def steady_force(self, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        return lugre_steady_force(as_velocity(v), p.coulomb_force, p.static_force,
                                  p.stribeck_velocity, p.sigma2, p.exponent)
