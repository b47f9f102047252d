"""Generalized Maxwell-slip (GMS) friction law (Al-Bender, Lampaert, Swevers 2005).

N elasto-slide elements in parallel, element i with stiffness k_i and deflection z_i [m]
(element force F_i = k_i·z_i), all driven by the same sliding velocity v::

    stick (F_i·sgn(v) < α_i·s(v)):   dz_i/dt = v
    slip  (otherwise):               dF_i/dt = C·(α_i·sgn(v) − F_i/s(v))
    F = Σ_i k_i·z_i + σ2·v

s(v) is the Stribeck level g(v) = F_C + (F_S − F_C)·exp(−|v/v_s|^δ), α_i the element's
fraction of it (Σ α_i = 1) and C [N/s] the attraction parameter.  In steady sliding every
element slips at F_i = α_i·s(v)·sgn(v), so F_ss = g(v)·sgn(v) + σ2·v.  Elements that break
away at different displacements give the non-local-memory pre-sliding hysteresis that Tran et
al. measured on pneumatic cylinders (Tran, Pham, Do & Ngo, Vietnam Journal of Mechanics: non-local
memory of the pre-sliding hysteresis).

**Choice made here.**  In the paper an element, once slipping, keeps slipping until the
velocity reverses (a hidden mode).  Here the mode is a function of the state (stick while the
element force is inside its slip limit or points against the motion, slip otherwise), so the law
is a plain state-space model without hidden switches and the exact step below is well defined.
The two differ only when s(v) rises during slip (decelerating towards the Stribeck peak): the
element then re-sticks and rises with k_i·v instead of C to its limit.  No micro-damping term.

Exact step for a velocity held over dt: a sticking element moves elastically and is capped at
its limit (where the slip rate is zero); a slipping element relaxes exponentially to its limit
with rate C/s(v).

References
----------
.. [1] F. Al-Bender, V. Lampaert, J. Swevers, "The generalized Maxwell-slip model: a novel model
   for friction simulation and compensation", IEEE TAC 50(11), 1883-1887, 2005.
.. [2] jchristopherson/friction and FrictionModels.jl (open-source implementations).
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from pydantic import Field, model_validator

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
    validate_parameters,
)
from sealsim.friction.kernels import apply
from sealsim.friction.stribeck import stribeck_level, stribeck_level_derivative

__all__ = ["GMS", "GMSParameters", "default_fractions", "gms_element_rate", "gms_element_step"]


def default_fractions(n_elements: int) -> np.ndarray:
    """Break-away fractions α_i = 2i/(N(N+1)), i = 1..N (Σ α_i = 1).

    With equal element stiffnesses the elements then break away at evenly spaced
    displacements, which approximates a smooth virgin pre-sliding curve.

    Examples
    --------
    >>> default_fractions(4)
    array([0.1, 0.2, 0.3, 0.4])
    """
    i = np.arange(1, n_elements + 1, dtype=float)
    return 2.0 * i / (n_elements * (n_elements + 1))


def gms_element_rate(z, v, stiffness, fraction, attraction, s):
    """Deflection rate of GMS elements (state-determined stick/slip, see module docstring).

    .. math::
        \\dot z_i = v \\;\\text{(stick)}, \\qquad
        \\dot z_i = \\frac{C}{k_i}\\left(\\alpha_i\\operatorname{sgn}(v)
        - \\frac{k_i z_i}{s(v)}\\right) \\;\\text{(slip)}

    Parameters
    ----------
    z : array_like, shape (N, n)
        Element deflections [m].
    v : array_like, shape (n,)
        Sliding velocity [m/s].
    stiffness : array_like, shape (N, 1)
        Element stiffnesses k_i [N/m].
    fraction : array_like, shape (N, 1)
        Break-away fractions α_i [-].
    attraction : float
        Attraction parameter C [N/s].
    s : array_like, shape (n,)
        Stribeck level s(v) [N].

    Returns
    -------
    ndarray, shape (N, n)
        dz_i/dt [m/s].

    Examples
    --------
    >>> gms_element_rate(np.array([[0.0], [2e-5]]), np.array([0.1]), np.array([[5e4], [5e4]]),
    ...                  np.array([[0.5], [0.5]]), 20.0, np.array([1.0]))
    array([[ 0.1   ],
           [-0.0002]])
    """
    return apply(_k._loop_gms_element_rate, z, v, stiffness, fraction, attraction, s)


def gms_element_step(z, v, dt, stiffness, fraction, attraction, s):
    """Exact GMS element deflections after ``dt`` with v held constant.

    Parameters are those of :func:`gms_element_rate` plus ``dt`` [s].

    Returns
    -------
    ndarray, shape (N, n)
        Element deflections at the end of the step [m].

    Examples
    --------
    >>> z = gms_element_step(np.zeros((2, 1)), np.array([1e-3]), 1e-2, np.array([[5e4], [5e4]]),
    ...                      np.array([[0.25], [0.75]]), 20.0, np.array([1.0]))
    >>> (z * 5e4).round(6)   # element 1 capped at its limit 0.25 N, element 2 elastic: 0.5 N
    array([[0.25],
           [0.5 ]])
    """
    return apply(_k._loop_gms_element_step, z, v, dt, stiffness, fraction, attraction, s)


class GMSParameters(LawParameters):
    """Parameters of the GMS law."""

    law: Literal["gms"] = "gms"
    n_elements: int = Field(4, ge=1, le=200)
    stiffness: Q("stiffness", gt=0)
    fractions: list[float] | None = None
    attraction: Q("force_rate", gt=0) = 20.0
    sigma2: Q("damping", ge=0) = 0.0
    coulomb_force: Q("force", gt=0)
    static_force: Q("force", gt=0)
    stribeck_velocity: Q("velocity", gt=0)
    exponent: Q("dimensionless", gt=0, le=10) = 2.0

    @model_validator(mode="after")
    def _check(self):
        require_static_at_least_coulomb(self.static_force, self.coulomb_force)
        if self.fractions is not None:
            fr = np.asarray(self.fractions, dtype=float)
            if fr.size != self.n_elements or np.any(~np.isfinite(fr)) or np.any(fr <= 0) or abs(
                    fr.sum() - 1.0) > 1e-9:
                raise ValueError(f"fractions must be {self.n_elements} positive numbers "
                                 f"(n_elements) adding up to 1, got {self.fractions}")
        return self


class GMS(FrictionLaw):
    """GMS law with ``n_elements`` states (element deflections z_i [m]).

    Parameters
    ----------
    params : GMSParameters, optional
        Or keyword arguments (SI): ``n_elements`` N, ``stiffness`` total stiffness Σk_i [N/m]
        (split equally, k_i = K/N), ``fractions`` α_i (default :func:`default_fractions`),
        ``attraction`` C [N/s], ``sigma2`` [N·s/m], ``coulomb_force``, ``static_force`` [N],
        ``stribeck_velocity`` [m/s], ``exponent`` [-].

    Examples
    --------
    >>> law = GMS(n_elements=4, stiffness=1e5, attraction=20.0, sigma2=0.4, coulomb_force=1.0,
    ...           static_force=1.5, stribeck_velocity=1e-3)
    >>> law.n_states
    4
    >>> law.steady_force([0.1])
    array([1.04])
    """

    name = "gms"

    def __init__(self, params: GMSParameters | None = None, **values):
        self.params = params if params is not None else validate_parameters(
            GMSParameters, values, "gms parameters")
        p = self.params
        n = p.n_elements
        self.k = np.full((n, 1), p.stiffness / n)
        fr = default_fractions(n) if p.fractions is None else np.asarray(p.fractions, float)
        self.alpha = fr.reshape(n, 1)

    @property
    def state_names(self):  # type: ignore[override]
        return tuple(f"z_{i + 1}" for i in range(self.params.n_elements))

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(GMSParameters, {"parameter_set": name, **overrides},
                                       "gms parameters"))

    def s(self, v):
        """Stribeck level s(v) [N]."""
        p = self.params
        return stribeck_level(v, p.coulomb_force, p.static_force, p.stribeck_velocity,
                              p.exponent)

    def relaxed_storage(self, z):
        z = np.asarray(z, dtype=float)
        return 0.5 * np.sum(self.k * z ** 2, axis=0)

    def derivatives(self, z, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        return gms_element_rate(z, v, self.k, self.alpha, self.params.attraction, self.s(v))

    def force(self, z, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        return np.sum(self.k * z, axis=0) + self.params.sigma2 * v

    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        s = self.s(v)
        ds = stribeck_level_derivative(v, p.coulomb_force, p.static_force,
                                       p.stribeck_velocity, p.exponent)
        force = self.k * z
        stick = force * np.sign(v) < self.alpha * s
        shape = np.broadcast_shapes(z.shape, (1,) + v.shape)
        diag = np.broadcast_to(np.where(stick, 0.0, -p.attraction / s), shape)
        dzdot_dz = np.zeros((shape[0],) + shape)
        idx = np.arange(shape[0])
        dzdot_dz[idx, idx] = diag
        dzdot_dv = np.broadcast_to(np.where(stick, 1.0, p.attraction * z * ds / s ** 2), shape)
        return Partials(dzdot_dz, np.array(dzdot_dv), np.broadcast_to(self.k, shape).copy(),
                        np.full(shape[1:], p.sigma2))

    def step(self, z, v, dt, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        return gms_element_step(z, v, dt, self.k, self.alpha, self.params.attraction, self.s(v))

    def steady_state(self, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        return self.alpha * self.s(v) * np.sign(v) / self.k
