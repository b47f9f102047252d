"""Frozen copy of the pre-issue-13 implementation (commit 9cdec80, friction_laws), kept as the
reference that the compiled code is tested against and as the benchmark baseline.
Docstrings removed; physics unchanged.  Do not edit."""
# ruff: noqa
from __future__ import annotations
import numpy as np
from sealsim.friction.base import NO_INPUTS, ContactInputs, FrictionLaw, Partials, affine_scan, as_state, as_velocity, sign, validate_parameters
from sealsim.friction.dahl import DahlParameters
from sealsim.friction.gms import GMSParameters, default_fractions
from sealsim.friction.lugre import LuGreParameters
from sealsim.friction.stribeck import CoulombParameters, StribeckParameters
from sealsim.friction.theta import ThetaParameters

def pressure_scaled_force(force_at_zero_pressure, pressure_coefficient, pressure_a=0.0, pressure_b=0.0):
    return np.asarray(force_at_zero_pressure, dtype=float) + np.asarray(pressure_coefficient, dtype=float) * (np.asarray(pressure_a, dtype=float) + np.asarray(pressure_b, dtype=float))

def stribeck_level(v, coulomb_force, static_force, stribeck_velocity, exponent=2.0):
    v = np.asarray(v, dtype=float)
    ratio = np.abs(v / stribeck_velocity)
    return coulomb_force + (np.asarray(static_force) - coulomb_force) * np.exp(-ratio ** exponent)

def stribeck_level_derivative(v, coulomb_force, static_force, stribeck_velocity, exponent=2.0):
    v = np.asarray(v, dtype=float)
    ratio = np.abs(v / stribeck_velocity)
    with np.errstate(divide='ignore', invalid='ignore'):
        power = np.where(ratio > 0, ratio ** (np.asarray(exponent) - 1.0), np.where(np.asarray(exponent) == 1.0, 1.0, 0.0))
    return -(np.asarray(static_force) - coulomb_force) * exponent * power * np.exp(-ratio ** exponent) * np.sign(v) / stribeck_velocity

def stribeck_force(v, coulomb_force, static_force, stribeck_velocity, viscous_coefficient=0.0, exponent=2.0):
    v = np.asarray(v, dtype=float)
    return stribeck_level(v, coulomb_force, static_force, stribeck_velocity, exponent) * np.sign(v) + viscous_coefficient * v

def coulomb_viscous_force(v, coulomb_force, viscous_coefficient=0.0):
    v = np.asarray(v, dtype=float)
    return coulomb_force * np.sign(v) + viscous_coefficient * v

class _StaticLaw(FrictionLaw):
    has_stiction = True
    affine = True

    def derivatives(self, z, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        return np.zeros((0, v.shape[-1]))

    def step(self, z, v, dt, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        return np.zeros((0, v.shape[-1]))

    def steady_state(self, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        return np.zeros((0, v.shape[-1]))

    def _levels(self, inputs: ContactInputs):
        raise NotImplementedError

class CoulombViscous(_StaticLaw):
    name = 'coulomb'

    def __init__(self, params: CoulombParameters | None=None, **values):
        self.params = params if params is not None else validate_parameters(CoulombParameters, values, 'coulomb parameters')

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(CoulombParameters, {'parameter_set': name, **overrides}, 'coulomb parameters'))

    def _levels(self, inputs: ContactInputs):
        p = self.params
        f_c = pressure_scaled_force(p.coulomb_force, p.pressure_coefficient, inputs.require('pressure_a', self.name), inputs.require('pressure_b', self.name))
        return (f_c, f_c)

    def force(self, z, v, inputs: ContactInputs=NO_INPUTS):
        f_c, _ = self._levels(inputs)
        return coulomb_viscous_force(as_velocity(v), f_c, self.params.viscous_coefficient)

    def partials(self, z, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        n = v.shape[-1]
        return Partials(np.zeros((0, 0, n)), np.zeros((0, n)), np.zeros((0, n)), np.full(n, self.params.viscous_coefficient))

    def breakaway_force(self, z, inputs: ContactInputs=NO_INPUTS):
        n = np.shape(z)[-1]
        return np.broadcast_to(self._levels(inputs)[1], (n,)).astype(float)

class Stribeck(_StaticLaw):
    name = 'stribeck'

    def __init__(self, params: StribeckParameters | None=None, **values):
        self.params = params if params is not None else validate_parameters(StribeckParameters, values, 'stribeck parameters')

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(StribeckParameters, {'parameter_set': name, **overrides}, 'stribeck parameters'))

    def _levels(self, inputs: ContactInputs):
        p = self.params
        f_c = pressure_scaled_force(p.coulomb_force, p.pressure_coefficient, inputs.require('pressure_a', self.name), inputs.require('pressure_b', self.name))
        if p.coulomb_force > 0:
            f_s = p.static_force * f_c / p.coulomb_force
        else:
            f_s = p.static_force + (f_c - p.coulomb_force)
        return (f_c, f_s)

    def force(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        f_c, f_s = self._levels(inputs)
        return stribeck_force(as_velocity(v), f_c, f_s, p.stribeck_velocity, p.viscous_coefficient, p.exponent)

    def partials(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        f_c, f_s = self._levels(inputs)
        dg = stribeck_level_derivative(v, f_c, f_s, p.stribeck_velocity, p.exponent)
        n = v.shape[-1]
        return Partials(np.zeros((0, 0, n)), np.zeros((0, n)), np.zeros((0, n)), dg * sign(v) + p.viscous_coefficient)

    def breakaway_force(self, z, inputs: ContactInputs=NO_INPUTS):
        n = np.shape(z)[-1]
        return np.broadcast_to(self._levels(inputs)[1], (n,)).astype(float)

def lugre_bristle_rate(z, v, sigma0, g):
    v = np.asarray(v, dtype=float)
    return v - sigma0 * np.abs(v) * np.asarray(z, dtype=float) / g

def lugre_force(z, zdot, v, sigma0, sigma1, sigma2):
    return sigma0 * np.asarray(z, dtype=float) + sigma1 * np.asarray(zdot) + sigma2 * np.asarray(v)

def lugre_steady_force(v, coulomb_force, static_force, stribeck_velocity, sigma2, exponent=2.0):
    v = np.asarray(v, dtype=float)
    g = stribeck_level(v, coulomb_force, static_force, stribeck_velocity, exponent)
    return g * np.sign(v) + sigma2 * v

def lugre_bristle_step(z, v, dt, sigma0, g):
    z = np.asarray(z, dtype=float)
    v = np.asarray(v, dtype=float)
    a, b = _lugre_affine(v, dt, sigma0, g)
    return a * z + b

def _lugre_affine(v, dt, sigma0, g):
    decay = -np.expm1(-sigma0 * np.abs(v) * dt / g)
    z_ss = np.sign(v) * g / sigma0
    return (1.0 - decay, z_ss * decay)

def lugre_passivity_margin(sigma1, sigma2, coulomb_force, static_force):
    return np.asarray(sigma2) - np.asarray(sigma1) * (np.asarray(static_force) - coulomb_force) / coulomb_force

def lugre_damping_bound(mass, sigma0, sigma2, coulomb_force, static_force):
    return np.asarray(sigma2) / (2.0 * np.sqrt(np.asarray(sigma0) * mass)) * (coulomb_force / (np.asarray(static_force) - coulomb_force) + 1.0)

class LuGre(FrictionLaw):
    name = 'lugre'
    state_names = ('z',)
    affine = True

    def __init__(self, params: LuGreParameters | None=None, *, warn: bool=True, **values):
        self.params = params if params is not None else validate_parameters(LuGreParameters, values, 'lugre parameters')
        if warn and (not self.is_passive()):
            p = self.params
            _warn_passivity(f'LuGre parameters are not passive (Åström & Canudas de Wit 2008, Eq. 7): sigma2 = {p.sigma2:g} N*s/m <= sigma1*(F_S - F_C)/F_C = {p.sigma1 * (p.static_force - p.coulomb_force) / p.coulomb_force:g} N*s/m; the friction force can supply energy during fast velocity changes')

    @classmethod
    def from_parameter_set(cls, name: str, *, warn: bool=True, **overrides):
        return cls(validate_parameters(LuGreParameters, {'parameter_set': name, **overrides}, 'lugre parameters'), warn=warn)

    def g(self, v):
        p = self.params
        return stribeck_level(v, p.coulomb_force, p.static_force, p.stribeck_velocity, p.exponent)

    def is_passive(self) -> bool:
        p = self.params
        return bool(lugre_passivity_margin(p.sigma1, p.sigma2, p.coulomb_force, p.static_force) > 0) or p.sigma1 == 0.0

    def relaxed_storage(self, z):
        z = np.asarray(z, dtype=float)
        return 0.5 * self.params.sigma0 * z[0] ** 2

    def derivatives(self, z, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, 1)
        return lugre_bristle_rate(z, v, self.params.sigma0, self.g(v))

    def force(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, 1)
        zdot = lugre_bristle_rate(z[0], v, p.sigma0, self.g(v))
        return lugre_force(z[0], zdot, v, p.sigma0, p.sigma1, p.sigma2)

    def partials(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, 1)[0]
        g = self.g(v)
        dg = stribeck_level_derivative(v, p.coulomb_force, p.static_force, p.stribeck_velocity, p.exponent)
        dfdz = -p.sigma0 * np.abs(v) / g
        dfdv = 1.0 - p.sigma0 * z * (sign(v) / g - np.abs(v) * dg / g ** 2)
        shape = np.broadcast_shapes(v.shape, z.shape)
        dfdz = np.broadcast_to(dfdz, shape)
        dfdv = np.broadcast_to(dfdv, shape)
        return Partials(dfdz[None, None, :], dfdv[None, :], (p.sigma0 + p.sigma1 * dfdz)[None, :], p.sigma1 * dfdv + p.sigma2)

    def step(self, z, v, dt, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, 1)
        return lugre_bristle_step(z, v, dt, self.params.sigma0, self.g(v))

    def affine_coefficients(self, v, dt, inputs: ContactInputs=NO_INPUTS):
        v = np.asarray(v, dtype=float)
        a, b = _lugre_affine(v, dt, self.params.sigma0, self.g(v))
        return (a[:, None, :], b[:, None, :])

    def steady_state(self, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        return (sign(v) * self.g(v) / self.params.sigma0)[None, :]

    def steady_force(self, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        return lugre_steady_force(as_velocity(v), p.coulomb_force, p.static_force, p.stribeck_velocity, p.sigma2, p.exponent)

def _u(z, v, sigma0, coulomb_force):
    return 1.0 - sigma0 * np.asarray(z, dtype=float) * np.sign(v) / coulomb_force

def dahl_bristle_rate(z, v, sigma0, coulomb_force, exponent=1.0):
    u = np.clip(_u(z, v, sigma0, coulomb_force), 0.0, None)
    return np.asarray(v, dtype=float) * u ** exponent

def dahl_bristle_step(z, v, dt, sigma0, coulomb_force, exponent=1.0):
    z = np.asarray(z, dtype=float)
    v = np.asarray(v, dtype=float)
    s = np.abs(v) * dt
    u0 = np.clip(_u(z, v, sigma0, coulomb_force), 0.0, None)
    k = sigma0 * s / coulomb_force
    exponent = np.asarray(exponent, dtype=float)
    if np.all(exponent == 1.0):
        u1 = u0 * np.exp(-k)
    else:
        one_minus = 1.0 - exponent
        with np.errstate(divide='ignore', invalid='ignore', over='ignore'):
            base = u0 ** one_minus - one_minus * k
            u1 = np.where(base > 0, base, 0.0) ** (1.0 / one_minus)
            u1 = np.where(exponent == 1.0, u0 * np.exp(-k), u1)
            u1 = np.where(u0 > 0, u1, 0.0)
    z1 = (1.0 - u1) * coulomb_force * np.sign(v) / sigma0
    return np.where(v == 0, z, z1)

class Dahl(FrictionLaw):
    name = 'dahl'
    state_names = ('z',)

    def __init__(self, params: DahlParameters | None=None, **values):
        self.params = params if params is not None else validate_parameters(DahlParameters, values, 'dahl parameters')

    @property
    def affine(self) -> bool:
        return self.params.exponent == 1.0

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(DahlParameters, {'parameter_set': name, **overrides}, 'dahl parameters'))

    def relaxed_storage(self, z):
        return 0.5 * self.params.sigma0 * np.asarray(z, dtype=float)[0] ** 2

    def derivatives(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        return dahl_bristle_rate(as_state(z, 1), as_velocity(v), p.sigma0, p.coulomb_force, p.exponent)

    def force(self, z, v, inputs: ContactInputs=NO_INPUTS):
        z = as_state(z, 1)[0]
        v = as_velocity(v)
        return np.broadcast_to(self.params.sigma0 * z, np.broadcast_shapes(z.shape, v.shape)).astype(float)

    def partials(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, 1)[0]
        u = np.clip(_u(z, v, p.sigma0, p.coulomb_force), 0.0, None)
        with np.errstate(divide='ignore', invalid='ignore'):
            upow = np.where(u > 0, u ** (p.exponent - 1.0), 0.0 if p.exponent > 1 else 1.0)
        dfdz = -np.abs(v) * p.exponent * upow * p.sigma0 / p.coulomb_force
        dfdv = u ** p.exponent
        shape = np.broadcast_shapes(v.shape, z.shape)
        dfdz = np.broadcast_to(dfdz, shape)
        return Partials(dfdz[None, None, :], np.broadcast_to(dfdv, shape)[None, :], np.full((1,) + shape, p.sigma0), np.zeros(shape))

    def step(self, z, v, dt, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        return dahl_bristle_step(as_state(z, 1), as_velocity(v), dt, p.sigma0, p.coulomb_force, p.exponent)

    def affine_coefficients(self, v, dt, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = np.asarray(v, dtype=float)
        decay = -np.expm1(-p.sigma0 * np.abs(v) * dt / p.coulomb_force)
        z_ss = np.sign(v) * p.coulomb_force / p.sigma0
        return ((1.0 - decay)[:, None, :], (z_ss * decay)[:, None, :])

    def steady_state(self, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        return (np.sign(v) * self.params.coulomb_force / self.params.sigma0)[None, :]

def gms_element_rate(z, v, stiffness, fraction, attraction, s):
    z = np.asarray(z, dtype=float)
    v = np.asarray(v, dtype=float)
    force = stiffness * z
    sgn = np.sign(v)
    stick = force * sgn < fraction * s
    slip_rate = attraction / stiffness * (fraction * sgn - force / s)
    return np.where(stick, v, slip_rate)

def gms_element_step(z, v, dt, stiffness, fraction, attraction, s):
    z = np.asarray(z, dtype=float)
    v = np.asarray(v, dtype=float)
    force = stiffness * z
    sgn = np.sign(v)
    limit = fraction * s
    stick = force * sgn < limit
    trial = force + stiffness * v * dt
    stuck = np.where(trial * sgn > limit, limit * sgn, trial)
    target = limit * sgn
    slipped = target + (force - target) * np.exp(-attraction * dt / s)
    new_force = np.where(stick, stuck, slipped)
    new_force = np.where(v == 0, force, new_force)
    return new_force / stiffness

class GMS(FrictionLaw):
    name = 'gms'

    def __init__(self, params: GMSParameters | None=None, **values):
        self.params = params if params is not None else validate_parameters(GMSParameters, values, 'gms parameters')
        p = self.params
        n = p.n_elements
        self.k = np.full((n, 1), p.stiffness / n)
        fr = default_fractions(n) if p.fractions is None else np.asarray(p.fractions, float)
        self.alpha = fr.reshape(n, 1)

    @property
    def state_names(self):
        return tuple((f'z_{i + 1}' for i in range(self.params.n_elements)))

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(GMSParameters, {'parameter_set': name, **overrides}, 'gms parameters'))

    def s(self, v):
        p = self.params
        return stribeck_level(v, p.coulomb_force, p.static_force, p.stribeck_velocity, p.exponent)

    def relaxed_storage(self, z):
        z = np.asarray(z, dtype=float)
        return 0.5 * np.sum(self.k * z ** 2, axis=0)

    def derivatives(self, z, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        return gms_element_rate(z, v, self.k, self.alpha, self.params.attraction, self.s(v))

    def force(self, z, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        return np.sum(self.k * z, axis=0) + self.params.sigma2 * v

    def partials(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        s = self.s(v)
        ds = stribeck_level_derivative(v, p.coulomb_force, p.static_force, p.stribeck_velocity, p.exponent)
        force = self.k * z
        stick = force * np.sign(v) < self.alpha * s
        shape = np.broadcast_shapes(z.shape, (1,) + v.shape)
        diag = np.broadcast_to(np.where(stick, 0.0, -p.attraction / s), shape)
        dzdot_dz = np.zeros((shape[0],) + shape)
        idx = np.arange(shape[0])
        dzdot_dz[idx, idx] = diag
        dzdot_dv = np.broadcast_to(np.where(stick, 1.0, p.attraction * z * ds / s ** 2), shape)
        return Partials(dzdot_dz, np.array(dzdot_dv), np.broadcast_to(self.k, shape).copy(), np.full(shape[1:], p.sigma2))

    def step(self, z, v, dt, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        return gms_element_step(z, v, dt, self.k, self.alpha, self.params.attraction, self.s(v))

    def steady_state(self, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        return self.alpha * self.s(v) * np.sign(v) / self.k

def _load_factor(normal_force, reference_normal_force, load_exponent):
    return (np.asarray(normal_force, dtype=float) / reference_normal_force) ** load_exponent

def _shear_rate(v, tau, alpha, normal_force, reference_normal_force, load_exponent):
    speed = np.abs(np.asarray(v, dtype=float))
    p = _load_factor(normal_force, reference_normal_force, load_exponent)
    with np.errstate(divide='ignore', invalid='ignore'):
        r = speed / (alpha * p)
    return np.where(speed > 0, np.where(p > 0, r, np.inf), 0.0)

def theta_transition_velocity(tau, alpha, normal_force, reference_normal_force, load_exponent=1.0):
    return np.asarray(alpha, dtype=float) / tau * _load_factor(normal_force, reference_normal_force, load_exponent)

def theta_rate(theta, v, tau, alpha, normal_force, reference_normal_force, load_exponent=1.0):
    theta = np.asarray(theta, dtype=float)
    p = _load_factor(normal_force, reference_normal_force, load_exponent)
    return -theta / tau + np.abs(np.asarray(v, dtype=float)) / (alpha * p) * (1.0 - theta)

def theta_steady(v, tau, alpha, normal_force, reference_normal_force, load_exponent=1.0):
    speed = np.abs(np.asarray(v, dtype=float))
    v_star = theta_transition_velocity(tau, alpha, normal_force, reference_normal_force, load_exponent)
    with np.errstate(divide='ignore', invalid='ignore'):
        return np.where(speed > 0, speed / (speed + v_star), 0.0)

def theta_step(theta, v, dt, tau, alpha, normal_force, reference_normal_force, load_exponent=1.0):
    a, b = _theta_affine(v, dt, tau, alpha, normal_force, reference_normal_force, load_exponent)
    return a * np.asarray(theta, dtype=float) + b

def _theta_affine(v, dt, tau, alpha, normal_force, reference_normal_force, load_exponent):
    r = _shear_rate(v, tau, alpha, normal_force, reference_normal_force, load_exponent)
    decay = -np.expm1(-(1.0 / tau + r) * dt)
    theta_ss = theta_steady(v, tau, alpha, normal_force, reference_normal_force, load_exponent)
    return (1.0 - decay, theta_ss * decay)

def theta_friction_level(theta, normal_force, f_a, f_b):
    theta = np.asarray(theta, dtype=float)
    return np.asarray(normal_force, dtype=float) * (f_a * (1.0 - theta) + f_b * theta)

def theta_force(theta, v, normal_force, contact_width, f_a, f_b, gamma):
    v = np.asarray(v, dtype=float)
    return theta_friction_level(theta, normal_force, f_a, f_b) * np.sign(v) + gamma * np.asarray(contact_width, dtype=float) * v

def theta_steady_force(v, normal_force, contact_width, tau, alpha, f_a, f_b, gamma, reference_normal_force, load_exponent=1.0):
    theta = theta_steady(v, tau, alpha, normal_force, reference_normal_force, load_exponent)
    return theta_force(theta, v, normal_force, contact_width, f_a, f_b, gamma)

def theta_breakaway_after_dwell(dwell, theta0, tau, normal_force, f_a, f_b):
    theta = np.asarray(theta0, dtype=float) * np.exp(-np.asarray(dwell, dtype=float) / tau)
    return theta_friction_level(theta, normal_force, f_a, f_b)

class Theta(FrictionLaw):
    name = 'theta'

    def __init__(self, params: ThetaParameters | None=None, **values):
        self.params = params if params is not None else validate_parameters(ThetaParameters, values, 'theta parameters')

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(ThetaParameters, {'parameter_set': name, **overrides}, 'theta parameters'))

    @property
    def bristles(self) -> bool:
        return self.params.bristle_stiffness is not None

    @property
    def state_names(self):
        return ('theta', 'z') if self.bristles else ('theta',)

    @property
    def has_stiction(self) -> bool:
        return not self.bristles
    affine = True

    def _fn(self, inputs: ContactInputs):
        return inputs.require('normal_force', 'theta', positive=True)

    def _b(self, inputs: ContactInputs):
        return inputs.require('contact_width', 'theta', nonnegative=True)

    def _rate_args(self, inputs):
        p = self.params
        return (p.tau, p.alpha, self._fn(inputs), p.reference_normal_force, p.load_exponent)

    def level(self, theta, inputs: ContactInputs):
        p = self.params
        return theta_friction_level(theta, self._fn(inputs), p.f_a, p.f_b)

    def relaxed_storage(self, z):
        z = np.asarray(z, dtype=float)
        if not self.bristles:
            return np.zeros(z.shape[-1])
        return 0.5 * self.params.bristle_stiffness * z[1] ** 2

    def initial_state(self, n: int=1):
        return np.zeros((self.n_states, n))

    def derivatives(self, z, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        dtheta = theta_rate(z[0], v, *self._rate_args(inputs))
        if not self.bristles:
            return dtheta[None, :]
        dz = lugre_bristle_rate(z[1], v, self.params.bristle_stiffness, self.level(z[0], inputs))
        return np.stack(np.broadcast_arrays(dtheta, dz))

    def force(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        if not self.bristles:
            return theta_force(z[0], v, self._fn(inputs), self._b(inputs), p.f_a, p.f_b, p.gamma)
        zdot = lugre_bristle_rate(z[1], v, p.bristle_stiffness, self.level(z[0], inputs))
        return p.bristle_stiffness * z[1] + p.bristle_damping * zdot + p.gamma * self._b(inputs) * v

    def partials(self, z, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        fn = self._fn(inputs)
        b = self._b(inputs)
        load = _load_factor(fn, p.reference_normal_force, p.load_exponent)
        r = np.abs(v) / (p.alpha * load)
        shape = np.broadcast_shapes(v.shape, z.shape[1:], np.shape(fn), np.shape(b))
        d_tt = np.broadcast_to(-1.0 / p.tau - r, shape)
        d_tv = np.broadcast_to(np.sign(v) / (p.alpha * load) * (1.0 - z[0]), shape)
        dlevel = fn * (p.f_b - p.f_a)
        if not self.bristles:
            return Partials(d_tt[None, None], d_tv[None], np.broadcast_to(dlevel * np.sign(v), shape)[None].copy(), np.broadcast_to(p.gamma * b, shape).copy())
        s0, s1 = (p.bristle_stiffness, p.bristle_damping)
        g = self.level(z[0], inputs)
        d_zt = s0 * np.abs(v) * z[1] * dlevel / g ** 2
        d_zz = -s0 * np.abs(v) / g
        d_zv = 1.0 - s0 * np.sign(v) * z[1] / g
        jac = np.zeros((2, 2) + shape)
        jac[0, 0] = d_tt
        jac[1, 0] = d_zt
        jac[1, 1] = d_zz
        dzdv = np.stack([d_tv, np.broadcast_to(d_zv, shape)])
        dfdz = np.stack([np.broadcast_to(s1 * d_zt, shape), np.broadcast_to(s0 + s1 * d_zz, shape)])
        return Partials(jac, dzdv, dfdz, np.broadcast_to(s1 * d_zv + p.gamma * b, shape).copy())

    def step(self, z, v, dt, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        theta1 = theta_step(z[0], v, dt, *self._rate_args(inputs))
        if not self.bristles:
            return theta1[None, :]
        g_mid = self.level(0.5 * (z[0] + theta1), inputs)
        a, b = _lugre_affine(v, dt, self.params.bristle_stiffness, g_mid)
        z1 = a * z[1] + b
        return np.stack(np.broadcast_arrays(theta1, z1))

    def _affine_trajectory(self, z0, v, dt, inputs):
        a, b = _theta_affine(v, dt[:, None], *self._rate_args(inputs))
        theta = affine_scan(a, b, z0[0])
        if not self.bristles:
            return theta[:, None, :]
        g_mid = self.level(0.5 * (theta[:-1] + theta[1:]), inputs)
        a_z, b_z = _lugre_affine(v, dt[:, None], self.params.bristle_stiffness, g_mid)
        zb = affine_scan(a_z, b_z, z0[1])
        return np.stack(np.broadcast_arrays(theta, zb), axis=1)

    def steady_state(self, v, inputs: ContactInputs=NO_INPUTS):
        v = as_velocity(v)
        theta = theta_steady(v, *self._rate_args(inputs))
        if not self.bristles:
            return np.atleast_2d(theta)
        z = np.sign(v) * self.level(theta, inputs) / self.params.bristle_stiffness
        return np.stack(np.broadcast_arrays(theta, z))

    def steady_force(self, v, inputs: ContactInputs=NO_INPUTS):
        p = self.params
        return theta_steady_force(as_velocity(v), self._fn(inputs), self._b(inputs), p.tau, p.alpha, p.f_a, p.f_b, p.gamma, p.reference_normal_force, p.load_exponent)

    def breakaway_force(self, z, inputs: ContactInputs=NO_INPUTS):
        z = as_state(z, self.n_states)
        return self.level(z[0], inputs)

def _warn_passivity(message):
    pass

def _noop(*args):
    pass
