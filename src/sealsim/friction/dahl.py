"""Dahl friction law (Dahl 1968): rate-independent pre-sliding hysteresis.

With the bristle deflection z [m] and F = σ0·z (Dahl 1968; Canudas de Wit et al. 1995)::

    dz/dt = v·(1 − σ0·z·sgn(v)/F_C)^α          ⇔   dF/dx = σ0·(1 − F·sgn(v)/F_C)^α

The rate depends on the velocity only through the travelled distance, so the F–x hysteresis loop
does not depend on how fast it is traversed (rate independence).  With α = 1 it is the LuGre law
with F_S = F_C and σ1 = σ2 = 0.

For a velocity held over a step the travelled distance is s = |v|·dt and, with
u = 1 − σ0·z·sgn(v)/F_C, du/ds = −(σ0/F_C)·u^α has the exact solution

* α = 1: u(s) = u0·exp(−σ0·s/F_C)
* α ≠ 1: u(s) = [u0^(1−α) − (1−α)·σ0·s/F_C]^(1/(1−α))  (clipped at u = 0 for α < 1)

References
----------
.. [1] P. R. Dahl, "A solid friction model", Technical Report TOR-0158(3107-18)-1, The
   Aerospace Corporation, El Segundo, 1968 (cited by Heipl & Murrenhoff).
.. [2] C. Canudas de Wit et al., IEEE TAC 40(3), 1995 (Dahl as the special case of LuGre).
"""

from __future__ import annotations

from typing import Literal

import numpy as np

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
    validate_parameters,
)
from sealsim.friction.kernels import apply

__all__ = ["Dahl", "DahlParameters", "dahl_bristle_rate", "dahl_bristle_step"]


def dahl_bristle_rate(z, v, sigma0, coulomb_force, exponent=1.0):
    """Bristle deflection rate of the Dahl law.

    .. math:: \\dot z = v\\,\\left(1 - \\sigma_0 z\\,\\operatorname{sgn}(v)/F_C\\right)^{\\alpha}

    Parameters
    ----------
    z : array_like
        Bristle deflection [m] (F = σ0·z, |σ0·z| <= F_C).
    v : array_like
        Sliding velocity [m/s].
    sigma0 : array_like
        Rest stiffness σ0 [N/m].
    coulomb_force : array_like
        Coulomb level F_C [N], > 0.
    exponent : array_like
        Shape exponent α [-], > 0 (1 is usual).

    Returns
    -------
    ndarray
        dz/dt [m/s].

    Examples
    --------
    >>> float(dahl_bristle_rate(0.0, 0.1, 1e5, 1.0))
    0.1
    >>> float(dahl_bristle_rate(1e-5, 0.1, 1e5, 1.0))   # saturated: F = F_C
    0.0
    """
    return apply(_k._loop_dahl_bristle_rate, z, v, sigma0, coulomb_force, exponent)


def dahl_bristle_step(z, v, dt, sigma0, coulomb_force, exponent=1.0):
    """Exact Dahl bristle deflection after ``dt`` with v held constant (module docstring).

    Parameters
    ----------
    z : array_like
        Deflection at the start [m].
    v : array_like
        Velocity held over the step [m/s].
    dt : array_like
        Step length [s].
    sigma0, coulomb_force, exponent : array_like
        σ0 [N/m], F_C [N], α [-].

    Returns
    -------
    ndarray
        Deflection at the end of the step [m].

    Examples
    --------
    >>> float(dahl_bristle_step(0.0, 1.0, 1.0, 1e5, 1.0)) * 1e5   # saturated after 1 m
    1.0
    >>> round(float(dahl_bristle_step(0.0, 1e-5, 1.0, 1e5, 1.0, exponent=2.0)) * 1e5, 6)
    0.5
    """
    return apply(_k._loop_dahl_bristle_step, z, v, dt, sigma0, coulomb_force, exponent)


class DahlParameters(LawParameters):
    """Parameters of the Dahl law."""

    law: Literal["dahl"] = "dahl"
    sigma0: Q("stiffness", gt=0)
    coulomb_force: Q("force", gt=0)
    exponent: Q("dimensionless", gt=0, le=10) = 1.0


class Dahl(FrictionLaw):
    """Dahl law with one state, the bristle deflection z [m]; F = σ0·z.

    Parameters
    ----------
    params : DahlParameters, optional
        Or keyword arguments (SI): ``sigma0`` [N/m], ``coulomb_force`` [N], ``exponent`` α [-].

    Examples
    --------
    >>> law = Dahl(sigma0=1e5, coulomb_force=1.0)
    >>> law.steady_force([-0.1, 0.1])
    array([-1.,  1.])
    """

    name = "dahl"
    state_names = ("z",)

    def __init__(self, params: DahlParameters | None = None, **values):
        self.params = params if params is not None else validate_parameters(
            DahlParameters, values, "dahl parameters")

    @property
    def affine(self) -> bool:  # type: ignore[override]
        return self.params.exponent == 1.0

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(DahlParameters, {"parameter_set": name, **overrides},
                                       "dahl parameters"))

    def relaxed_storage(self, z):
        return 0.5 * self.params.sigma0 * np.asarray(z, dtype=float)[0] ** 2

    def derivatives(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        return dahl_bristle_rate(as_state(z, 1), as_velocity(v), p.sigma0, p.coulomb_force,
                                 p.exponent)

    def force(self, z, v, inputs: ContactInputs = NO_INPUTS):
        z = as_state(z, 1)[0]
        v = as_velocity(v)
        return np.broadcast_to(self.params.sigma0 * z, np.broadcast_shapes(z.shape, v.shape)
                               ).astype(float)

    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, 1)[0]
        u = np.clip(1.0 - p.sigma0 * z * np.sign(v) / p.coulomb_force, 0.0, None)
        with np.errstate(divide="ignore", invalid="ignore"):
            upow = np.where(u > 0, u ** (p.exponent - 1.0), 0.0 if p.exponent > 1 else 1.0)
        dfdz = -np.abs(v) * p.exponent * upow * p.sigma0 / p.coulomb_force
        dfdv = u ** p.exponent
        shape = np.broadcast_shapes(v.shape, z.shape)
        dfdz = np.broadcast_to(dfdz, shape)
        return Partials(dfdz[None, None, :], np.broadcast_to(dfdv, shape)[None, :],
                        np.full((1,) + shape, p.sigma0), np.zeros(shape))

    def step(self, z, v, dt, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        return dahl_bristle_step(as_state(z, 1), as_velocity(v), dt, p.sigma0, p.coulomb_force,
                                 p.exponent)

    def affine_coefficients(self, v, dt, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        a, b = apply(_k._loop_lugre_affine, v, dt, p.sigma0, p.coulomb_force, outputs=2)
        return a[:, None, :], b[:, None, :]     # α = 1: LuGre with g = F_C

    def steady_state(self, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        return (np.sign(v) * self.params.coulomb_force / self.params.sigma0)[None, :]
