"""Static friction laws: Coulomb + viscous, and Stribeck with stiction and pressure scaling.

These are the "state of the art" laws of system-simulation tools that Heipl & Murrenhoff start
from (their Eq. 2 and 3).  They have no internal state: the force is a function of the
velocity (and of the chamber pressures), with true sticking at v = 0 -- at rest the friction
force balances the applied force up to the break-away level (Heipl & Murrenhoff Eq. 2, second and
third line).  That set-valued part is resolved by :mod:`sealsim.friction.hybrid`.

References
----------
.. [1] O. Heipl, H. Murrenhoff, "Rate- and state-dependent friction model for elastomeric
   seals", Eq. 2 (Stribeck curve with stiction) and Eq. 3 (linear pressure scaling).
.. [2] B. Armstrong-Hélouvry, P. Dupont, C. Canudas de Wit, "A survey of models, analysis tools
   and compensation methods for the control of machines with friction", Automatica 30(7),
   1083-1138, 1994 (Stribeck exponent δ).
.. [3] MathWorks Simscape "Cylinder Friction": F_C = F_pr + f_cfr·(p_A + p_B) with a constant
   break-away ratio K_brk = F_S/F_C (MathWorks documentation).
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
    as_velocity,
    require_static_at_least_coulomb,
    sign,
    validate_parameters,
)
from sealsim.friction.kernels import apply

__all__ = [
    "CoulombParameters",
    "CoulombViscous",
    "Stribeck",
    "StribeckParameters",
    "coulomb_viscous_force",
    "pressure_scaled_force",
    "stribeck_force",
    "stribeck_level",
    "stribeck_level_derivative",
    "stribeck_scaled_levels",
]


# --------------------------------------------------------------------------------------------
# Pure functions
# --------------------------------------------------------------------------------------------
def pressure_scaled_force(force_at_zero_pressure, pressure_coefficient, pressure_a=0.0,
                          pressure_b=0.0):
    """Friction level scaled linearly with the chamber pressures (Heipl & Murrenhoff Eq. 3).

    .. math:: F_C = F_{pr} + f\\,(p_A + p_B)

    Parameters
    ----------
    force_at_zero_pressure : array_like
        Force level F_pr without pressure (seal pre-load) [N].
    pressure_coefficient : array_like
        Pressure scaling factor f [N/Pa] (= [m²]).
    pressure_a, pressure_b : array_like
        Chamber pressures p_A, p_B [Pa] (gauge, as in system tools).

    Returns
    -------
    ndarray
        Pressure-scaled force level [N].

    References
    ----------
    Heipl & Murrenhoff Eq. 3; Simscape Cylinder Friction (MathWorks documentation).

    Examples
    --------
    >>> float(pressure_scaled_force(15.0, 1.5e-5, 6e5, 0.0))
    24.0
    """
    return apply(_k._loop_pressure_scaled_force, force_at_zero_pressure, pressure_coefficient,
                 pressure_a, pressure_b)


def stribeck_level(v, coulomb_force, static_force, stribeck_velocity, exponent=2.0):
    """Magnitude of the Stribeck curve g(v) without the viscous part.

    .. math:: g(v) = F_C + (F_S - F_C)\\,\\exp\\left(-|v/v_S|^{\\delta}\\right)

    Parameters
    ----------
    v : array_like
        Sliding velocity [m/s].
    coulomb_force : array_like
        Coulomb (kinetic) friction level F_C [N].
    static_force : array_like
        Static (break-away) friction level F_S [N], F_S >= F_C.
    stribeck_velocity : array_like
        Stribeck velocity v_S [m/s], > 0.
    exponent : array_like
        Stribeck exponent δ [-]: 2 in LuGre (1995) and Armstrong (1994), 1 in Heipl & Murrenhoff
        Eq. 2.

    Returns
    -------
    ndarray
        g(v) [N], between F_C and F_S.

    References
    ----------
    Heipl & Murrenhoff Eq. 2; Canudas de Wit et al. (1995) Eq. 3; Armstrong-Hélouvry et al. (1994).

    Examples
    --------
    >>> stribeck_level([0.0, 1e-3, 1.0], 1.0, 1.5, 1e-3)
    array([1.5 , 1.18393972, 1. ])
    """
    return apply(_k._loop_stribeck_level, v, coulomb_force, static_force, stribeck_velocity,
                 exponent)


def stribeck_level_derivative(v, coulomb_force, static_force, stribeck_velocity, exponent=2.0):
    """dg/dv of :func:`stribeck_level` [N·s/m] (odd in v; 0 at v = 0 for δ > 1).

    .. math:: g'(v) = -(F_S - F_C)\\,\\delta\\,|v/v_S|^{\\delta-1}\\,e^{-|v/v_S|^\\delta}
              \\,\\operatorname{sgn}(v)/v_S

    Parameters are those of :func:`stribeck_level`.

    Examples
    --------
    >>> float(stribeck_level_derivative(1e-3, 1.0, 1.5, 1e-3))
    -367.879...
    """
    return apply(_k._loop_stribeck_level_derivative, v, coulomb_force, static_force,
                 stribeck_velocity, exponent)


def stribeck_force(v, coulomb_force, static_force, stribeck_velocity, viscous_coefficient=0.0,
                   exponent=2.0):
    """Sliding friction force of the Stribeck law (Heipl & Murrenhoff Eq. 2, first line).

    .. math:: F(v) = g(v)\\,\\operatorname{sgn}(v) + F_v\\,v

    At v = 0 this returns 0: the force at rest is set-valued (|F| <= F_S) and resolved by the
    hybrid stick logic in :mod:`sealsim.friction.hybrid`.

    Parameters
    ----------
    v : array_like
        Sliding velocity [m/s].
    coulomb_force, static_force : array_like
        F_C and F_S [N].
    stribeck_velocity : array_like
        v_S [m/s].
    viscous_coefficient : array_like
        F_v [N·s/m].
    exponent : array_like
        δ [-].

    Returns
    -------
    ndarray
        Friction force [N], opposing v.

    Examples
    --------
    >>> stribeck_force([-0.01, 0.01], 15.0, 25.0, 0.02, 8.0, exponent=1.0)
    array([-21.145..., 21.145...])
    """
    return apply(_k._loop_stribeck_force, v, coulomb_force, static_force, stribeck_velocity,
                 viscous_coefficient, exponent)


def stribeck_scaled_levels(coulomb_force, static_force, pressure_coefficient, pressure_a=0.0,
                           pressure_b=0.0):
    """Coulomb and static levels of the Stribeck law after pressure scaling (Heipl & Murrenhoff Eq.
    3).

    .. math:: F_C(p) = F_C + f\\,(p_A + p_B), \\qquad F_S(p) = F_S\\,F_C(p)/F_C

    The break-away ratio F_S/F_C stays constant, as in Simscape's Cylinder Friction; with
    F_C = 0 the static level is shifted by the same amount instead, F_S + (F_C(p) − F_C).

    Parameters
    ----------
    coulomb_force, static_force : array_like
        F_C and F_S without pressure [N].
    pressure_coefficient : array_like
        f [N/Pa] (= [m²]).
    pressure_a, pressure_b : array_like
        Gauge pressures p_A, p_B [Pa].

    Returns
    -------
    f_c, f_s : ndarray
        Scaled levels [N].

    Examples
    --------
    >>> [float(f) for f in stribeck_scaled_levels(15.0, 25.0, 1.5e-5, 6e5)]
    [24.0, 40.0]
    """
    return apply(_k._loop_stribeck_scaled_levels, coulomb_force, static_force,
                 pressure_coefficient, pressure_a, pressure_b, outputs=2)


def coulomb_viscous_force(v, coulomb_force, viscous_coefficient=0.0):
    """Coulomb plus viscous friction, F = F_C·sgn(v) + F_v·v.

    Parameters
    ----------
    v : array_like
        Sliding velocity [m/s].
    coulomb_force : array_like
        Coulomb level F_C [N] (also the break-away level of this law).
    viscous_coefficient : array_like
        F_v [N·s/m].

    Returns
    -------
    ndarray
        Friction force [N] (0 at v = 0; the force at rest is resolved by the hybrid logic).

    Examples
    --------
    >>> coulomb_viscous_force([-1.0, 0.0, 2.0], 1.0, 0.5)
    array([-1.5,  0. ,  2. ])
    """
    return apply(_k._loop_coulomb_viscous_force, v, coulomb_force, viscous_coefficient)


# --------------------------------------------------------------------------------------------
# Parameter models
# --------------------------------------------------------------------------------------------
class CoulombParameters(LawParameters):
    """Coulomb + viscous friction with pressure scaling (Heipl & Murrenhoff Eq. 3)."""

    law: Literal["coulomb"] = "coulomb"
    coulomb_force: Q("force", ge=0)
    viscous_coefficient: Q("damping", ge=0) = 0.0
    pressure_coefficient: Q("area", ge=0) = 0.0


class StribeckParameters(LawParameters):
    """Stribeck curve with stiction and pressure scaling (Heipl & Murrenhoff Eq. 2/3)."""

    law: Literal["stribeck"] = "stribeck"
    coulomb_force: Q("force", ge=0)
    static_force: Q("force", ge=0)
    stribeck_velocity: Q("velocity", gt=0)
    exponent: Q("dimensionless", gt=0, le=10) = 1.0
    viscous_coefficient: Q("damping", ge=0) = 0.0
    pressure_coefficient: Q("area", ge=0) = 0.0

    @model_validator(mode="after")
    def _static_above_coulomb(self):
        require_static_at_least_coulomb(self.static_force, self.coulomb_force)
        return self


# --------------------------------------------------------------------------------------------
# Laws
# --------------------------------------------------------------------------------------------
class _StaticLaw(FrictionLaw):
    has_stiction = True
    affine = True

    def derivatives(self, z, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        return np.zeros((0, v.shape[-1]))

    def step(self, z, v, dt, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        return np.zeros((0, v.shape[-1]))

    def steady_state(self, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        return np.zeros((0, v.shape[-1]))

    def _levels(self, inputs: ContactInputs):
        """(F_C, F_S) after pressure scaling [N]."""
        raise NotImplementedError


class CoulombViscous(_StaticLaw):
    """Coulomb + viscous friction, F = F_C(p)·sgn(v) + F_v·v, F_C(p) = F_pr + f·(p_A + p_B).

    Parameters
    ----------
    params : CoulombParameters, optional
        Validated parameters; or give the fields as keyword arguments (SI floats):
        ``coulomb_force`` F_pr [N], ``viscous_coefficient`` F_v [N·s/m],
        ``pressure_coefficient`` f [N/Pa].

    Examples
    --------
    >>> law = CoulombViscous(coulomb_force=1.0, viscous_coefficient=0.5)
    >>> law.force(law.initial_state(2), [-1.0, 2.0])
    array([-1.5,  2. ])
    >>> law.breakaway_force(law.initial_state(1))
    array([1.])
    """

    name = "coulomb"

    def __init__(self, params: CoulombParameters | None = None, **values):
        self.params = params if params is not None else validate_parameters(
            CoulombParameters, values, "coulomb parameters")

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(CoulombParameters,
                                       {"parameter_set": name, **overrides},
                                       "coulomb parameters"))

    def _levels(self, inputs: ContactInputs):
        p = self.params
        f_c = pressure_scaled_force(p.coulomb_force, p.pressure_coefficient,
                                    inputs.require("pressure_a", self.name),
                                    inputs.require("pressure_b", self.name))
        return f_c, f_c

    def force(self, z, v, inputs: ContactInputs = NO_INPUTS):
        f_c, _ = self._levels(inputs)
        return coulomb_viscous_force(as_velocity(v), f_c, self.params.viscous_coefficient)

    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        n = v.shape[-1]
        return Partials(np.zeros((0, 0, n)), np.zeros((0, n)), np.zeros((0, n)),
                        np.full(n, self.params.viscous_coefficient))

    def breakaway_force(self, z, inputs: ContactInputs = NO_INPUTS):
        n = np.shape(z)[-1]
        return np.broadcast_to(self._levels(inputs)[1], (n,)).astype(float)


class Stribeck(_StaticLaw):
    """Stribeck curve with stiction and pressure scaling (Heipl & Murrenhoff Eq. 2 and 3).

    Sliding (v ≠ 0)::

        F = [F_C + (F_S − F_C)·exp(−|v/v_S|^δ)]·sgn(v) + F_v·v

    At rest the friction force balances the applied force up to F_S (true sticking, resolved
    by :mod:`sealsim.friction.hybrid`).  Pressure scaling (Heipl & Murrenhoff Eq. 3): the Coulomb
    level is ``F_C(p) = F_C + f·(p_A + p_B)`` and the static level keeps the break-away ratio,
    ``F_S(p) = F_S·F_C(p)/F_C`` (as Simscape's Cylinder Friction, where K_brk = F_S/F_C is a
    constant).  With F_C = 0 the static level is shifted by the same amount instead.

    Parameters
    ----------
    params : StribeckParameters, optional
        Validated parameters, or keyword arguments (SI floats): ``coulomb_force`` F_C [N],
        ``static_force`` F_S [N], ``stribeck_velocity`` v_S [m/s], ``exponent`` δ [-]
        (default 1, Heipl & Murrenhoff Eq. 2), ``viscous_coefficient`` F_v [N·s/m],
        ``pressure_coefficient`` f [N/Pa].

    Examples
    --------
    >>> law = Stribeck(coulomb_force=1.0, static_force=1.5, stribeck_velocity=1e-3,
    ...                exponent=2.0, viscous_coefficient=0.4)
    >>> law.steady_force([1e-3, 1.0])
    array([1.184..., 1.4 ])
    """

    name = "stribeck"

    def __init__(self, params: StribeckParameters | None = None, **values):
        self.params = params if params is not None else validate_parameters(
            StribeckParameters, values, "stribeck parameters")

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(StribeckParameters,
                                       {"parameter_set": name, **overrides},
                                       "stribeck parameters"))

    def _levels(self, inputs: ContactInputs):
        p = self.params
        return stribeck_scaled_levels(p.coulomb_force, p.static_force, p.pressure_coefficient,
                                      inputs.require("pressure_a", self.name),
                                      inputs.require("pressure_b", self.name))

    def force(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        f_c, f_s = self._levels(inputs)
        return stribeck_force(as_velocity(v), f_c, f_s, p.stribeck_velocity,
                              p.viscous_coefficient, p.exponent)

    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        f_c, f_s = self._levels(inputs)
        dg = stribeck_level_derivative(v, f_c, f_s, p.stribeck_velocity, p.exponent)
        n = v.shape[-1]
        return Partials(np.zeros((0, 0, n)), np.zeros((0, n)), np.zeros((0, n)),
                        dg * sign(v) + p.viscous_coefficient)

    def breakaway_force(self, z, inputs: ContactInputs = NO_INPUTS):
        n = np.shape(z)[-1]
        return np.broadcast_to(self._levels(inputs)[1], (n,)).astype(float)
