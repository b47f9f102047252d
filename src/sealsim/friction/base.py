"""The common interface of all friction laws: a vectorised state-space model.

A friction law describes the friction force ``F`` [N] of one or many contacts (arrays of shape
``(n,)``) as a state-space model::

    dz/dt = f(z, v, inputs)          (states z, shape (n_states, n))
    F     = g(z, v, inputs)          (friction force opposing the sliding velocity v)

``inputs`` (:class:`ContactInputs`) carries what a law may need from the rest of a simulation:
the normal force F_N and contact width b of the seal (from FE maps in the pneumatic model), the
chamber pressures p_A, p_B and the temperature.  Sign convention: ``v`` is the sliding velocity
of the moving body relative to the seal, ``F`` acts *against* the body, so the body's equation
of motion reads ``m·dv/dt = F_applied − F`` and the power dissipated is ``F·v``.

Every law offers the same methods (see :class:`FrictionLaw`):

* ``initial_state(n)``, ``derivatives(z, v, inputs)``, ``force(z, v, inputs)`` and
  ``partials(z, v, inputs)`` (analytic partial derivatives for Jacobians) -- everything an ODE
  integrator (scipy ``solve_ivp`` Radau/BDF, or an implicit stepper) needs;
* ``step(z, v, dt, inputs)`` -- the exact (or semi-analytic) state update for a velocity held
  constant over ``dt``: unconditionally stable, so stiff bristles (σ0 = 1e5 N/m) and long
  dwells need no tiny steps;
* ``trajectory(z0, v, dt, inputs)`` -- the states for a whole sequence of step velocities, done
  as a vectorised parallel scan where the update is affine in the state (LuGre, Dahl α = 1, Θ);
* ``steady_state(v, inputs)`` / ``steady_force(v, inputs)`` -- the analytic steady curve;
* for laws with true sticking (``has_stiction``) ``breakaway_force(z, inputs)``: the largest
  friction force the contact holds at rest.  How sticking is resolved when a body is driven is
  in :mod:`sealsim.friction.hybrid` (one place for all laws).
"""

from __future__ import annotations

import warnings
from abc import ABC, abstractmethod
from dataclasses import dataclass, fields
from typing import Any, ClassVar, NamedTuple

import numpy as np

from sealsim.errors import InputError

__all__ = [
    "ContactInputs",
    "FrictionLaw",
    "FrictionWarning",
    "PassivityWarning",
    "Partials",
    "affine_scan",
]


class FrictionWarning(UserWarning):
    """A friction-law parameter set is valid but questionable (e.g. not passive)."""


class PassivityWarning(FrictionWarning):
    """The parameters violate a passivity (dissipativity) condition of the law."""


def require_static_at_least_coulomb(static_force: float, coulomb_force: float) -> None:
    """Parameter check shared by the laws with a Stribeck curve: F_S ≥ F_C.

    The Stribeck curve falls from the break-away level F_S to the Coulomb level F_C [N].
    """
    if static_force < coulomb_force:
        raise ValueError(f"static_force ({static_force:g} N) must be >= coulomb_force "
                         f"({coulomb_force:g} N)")


def validate_parameters(model, values: dict[str, Any], source: str):
    """Build a parameter model from Python values (SI numbers allowed) or one InputError."""
    from sealsim.cases import validate_case

    return validate_case(model, values, source, require_units=False)


# --------------------------------------------------------------------------------------------
# Inputs from the rest of a simulation
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactInputs:
    """Operating conditions of the contacts; every field broadcasts against shape ``(n,)``.

    Parameters
    ----------
    normal_force : array_like, optional
        Normal (radial) force of the seal on its counter surface F_N [N], e.g. from an FE map
        at the current pressure difference.  Needed by the Θ law.
    contact_width : array_like, optional
        Axial contact width b [m].  Needed by the Θ law's viscous term γ·b·v.
    pressure_a, pressure_b : array_like
        Chamber pressures p_A, p_B [Pa] for the pressure scaling of Heipl & Murrenhoff Eq. 3
        (Stribeck / Coulomb laws).  Default 0.
    temperature : array_like, optional
        Temperature T [K] (the contact table's lubricant viscosity and rubber modulus, γ(T)
        of the Θ law; F_N and b through the FE maps, Heipl & Murrenhoff Fig. 4).
    contact_table : SteadyFrictionTable, optional
        The seal's steady friction table from its own contact
        (:mod:`sealsim.friction.contact_table`): the Θ law with ``steady = "contact"`` takes
        its steady curve from it.
    sliding_diameter : float, optional
        Diameter of the sliding surface D [m] (the table is per unit circumference).
    pressure_difference : array_like, optional
        Pressure difference across the seal Δp [Pa] for the table; default |p_A − p_B|.
    table_orientation : array_like
        +1 if a positive v slides the counter surface from the seal's pressurised side to the
        other (the table's "+" direction), −1 if the other way round.
    """

    normal_force: Any = None
    contact_width: Any = None
    pressure_a: Any = 0.0
    pressure_b: Any = 0.0
    temperature: Any = None
    contact_table: Any = None
    sliding_diameter: Any = None
    pressure_difference: Any = None
    table_orientation: Any = 1.0

    def require(self, name: str, law: str, *, positive: bool = False,
                nonnegative: bool = False) -> np.ndarray:
        """The named input as a float array, checked finite (and > 0 / >= 0 if asked).

        The checked array is cached on the (immutable) inputs object, so a solver that calls
        a law many times with the same inputs pays for the check once.
        """
        key = (name, positive, nonnegative)
        cache = self.__dict__.setdefault("_checked", {})
        if key in cache:
            return cache[key]
        value = getattr(self, name)
        if value is None:
            raise InputError(f"inputs.{name}: the {law} law needs {name.replace('_', ' ')} "
                             f"(see ContactInputs), but none was given")
        arr = np.array(value, dtype=float)
        if not np.all(np.isfinite(arr)):
            raise InputError(f"inputs.{name}: must be finite, got {_show(arr)}")
        if positive and np.any(arr <= 0):
            raise InputError(f"inputs.{name}: must be > 0, got {_show(arr)}")
        if nonnegative and np.any(arr < 0):
            raise InputError(f"inputs.{name}: must be >= 0, got {_show(arr)}")
        arr.setflags(write=False)
        cache[key] = arr
        return arr

    def at(self, index) -> ContactInputs:
        """The inputs of one time step ``index`` when fields are given per step (axis 0)."""
        values = {}
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "contact_table":
                values[f.name] = value
                continue
            if value is not None and np.ndim(value) >= 1 and np.shape(value)[0] > 1:
                value = np.asarray(value)[index]
            values[f.name] = value
        return ContactInputs(**values)


def _show(arr: np.ndarray) -> str:
    flat = np.ravel(arr)
    bad = flat[~np.isfinite(flat)] if not np.all(np.isfinite(flat)) else flat[flat <= 0]
    if bad.size:
        return f"{float(bad[0])!r}" + (f" (and {bad.size - 1} more)" if bad.size > 1 else "")
    return repr(flat[:3].tolist())


NO_INPUTS = ContactInputs()


class Partials(NamedTuple):
    """Analytic partial derivatives of a law at (z, v), for Jacobians of coupled ODEs.

    Attributes
    ----------
    dzdot_dz : ndarray, shape (n_states, n_states, n)
        ∂f_i/∂z_j [1/s].
    dzdot_dv : ndarray, shape (n_states, n)
        ∂f_i/∂v [1/m·(unit of z_i)].
    dforce_dz : ndarray, shape (n_states, n)
        ∂F/∂z_j [N per unit of z_j].
    dforce_dv : ndarray, shape (n,)
        ∂F/∂v [N·s/m].
    """

    dzdot_dz: np.ndarray
    dzdot_dv: np.ndarray
    dforce_dz: np.ndarray
    dforce_dv: np.ndarray


# --------------------------------------------------------------------------------------------
# Parallel scan of affine recurrences
# --------------------------------------------------------------------------------------------
def affine_scan(a: np.ndarray, b: np.ndarray, z0: np.ndarray) -> np.ndarray:
    """Solve ``z[k+1] = a[k]·z[k] + b[k]`` for all k at once (a vectorised parallel scan).

    Composition of affine maps is associative, so a Hillis–Steele scan needs ⌈log2 N⌉
    vectorised passes instead of N Python iterations.  With ``0 <= a <= 1`` (the exact updates
    of the laws here) every partial product stays in [0, 1]: no overflow, and underflow to 0 is
    the exact limit.

    Parameters
    ----------
    a, b : ndarray, shape (N, ...)
        Per-step coefficients [-] and offsets [unit of z].
    z0 : ndarray, shape (...)
        State before the first step.

    Returns
    -------
    ndarray, shape (N + 1, ...)
        ``z[0] = z0`` followed by the N updated states.

    Examples
    --------
    >>> affine_scan(np.array([0.5, 0.5, 1.0]), np.array([1.0, 1.0, 2.0]), np.array(0.0))
    array([0. , 1. , 1.5, 3.5])
    """
    a = np.array(a, dtype=float, copy=True)
    b = np.array(b, dtype=float, copy=True)
    z0 = np.asarray(z0, dtype=float)
    a, b = np.broadcast_arrays(a, b)
    a, b = a.copy(), b.copy()
    n = a.shape[0]
    shift = 1
    while shift < n:
        b[shift:] = a[shift:] * b[:-shift] + b[shift:]
        a[shift:] = a[shift:] * a[:-shift]
        shift *= 2
    out = np.empty((n + 1,) + np.broadcast_shapes(a.shape[1:], z0.shape))
    out[0] = z0
    out[1:] = a * z0 + b
    return out


def sign(v):
    """sgn(v) with sgn(0) = 0 (numpy's convention), as a float array."""
    return np.sign(np.asarray(v, dtype=float))


# --------------------------------------------------------------------------------------------
# The interface
# --------------------------------------------------------------------------------------------
class FrictionLaw(ABC):
    """Base class of all friction laws (see the module docstring for the conventions).

    Subclasses set :attr:`name`, :attr:`state_names`, :attr:`has_stiction` and implement the
    physics by calling the pure functions of their module.
    """

    #: short name used in case files (``law = "lugre"``)
    name: ClassVar[str] = ""
    #: names of the states (rows of z); empty for static laws
    state_names: ClassVar[tuple[str, ...]] = ()
    #: True if the law has true sticking at v = 0 (resolved by :mod:`sealsim.friction.hybrid`)
    has_stiction: ClassVar[bool] = False
    #: True if every state update is affine in the state (then trajectory() is a scan)
    affine: ClassVar[bool] = False

    params: Any

    # -- sizes and states ---------------------------------------------------------------
    @property
    def n_states(self) -> int:
        """Number of states per contact."""
        return len(self.state_names)

    def initial_state(self, n: int = 1) -> np.ndarray:
        """States of n relaxed contacts (after a long rest), shape (n_states, n)."""
        return np.zeros((self.n_states, n))

    # -- the model -----------------------------------------------------------------------
    @abstractmethod
    def derivatives(self, z, v, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        """dz/dt, shape (n_states, n)."""

    @abstractmethod
    def force(self, z, v, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        """Friction force F [N], shape (n,); opposes v.  Laws with stiction return the
        sliding force (0 at v = 0); the force at rest is resolved in :mod:`.hybrid`."""

    @abstractmethod
    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS) -> Partials:
        """Analytic partial derivatives (see :class:`Partials`)."""

    @abstractmethod
    def step(self, z, v, dt, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        """States after ``dt`` [s] with the velocity ``v`` [m/s] held constant."""

    @abstractmethod
    def steady_state(self, v, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        """States after sliding at constant v for a long time, shape (n_states, n)."""

    def steady_force(self, v, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        """Friction force [N] after sliding at constant v for a long time (analytic)."""
        v = np.atleast_1d(np.asarray(v, dtype=float))
        return self.force(self.steady_state(v, inputs), v, inputs)

    def breakaway_force(self, z, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        """Largest friction force [N] the contact holds at rest (laws with stiction)."""
        raise NotImplementedError(f"the {self.name} law has no true sticking")

    def is_passive(self) -> bool:
        """True if the map v → F is passive (dissipative) with these parameters."""
        return True

    def relaxed_storage(self, z) -> np.ndarray:
        """Energy [J] stored elastically in the states (0 for laws without bristles)."""
        return np.zeros(np.shape(z)[-1] if np.ndim(z) else 1)

    # -- sequences ---------------------------------------------------------------------
    def affine_coefficients(self, v, dt, inputs: ContactInputs = NO_INPUTS):
        """(a, b) with z1 = a·z0 + b for the step (affine laws only)."""
        raise NotImplementedError

    def trajectory(self, z0, v, dt, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        """States along a sequence of steps.

        Parameters
        ----------
        z0 : array_like, shape (n_states, n)
            Initial states.
        v : array_like, shape (N,) or (N, n)
            Velocity [m/s] held during each step (best: the velocity at the step's midpoint,
            which makes the sequence second-order accurate for a smooth v(t)).
        dt : float or array_like, shape (N,)
            Step lengths [s].
        inputs : ContactInputs
            Fields broadcast against (N, n) (per step along axis 0) or (n,).

        Returns
        -------
        ndarray, shape (N + 1, n_states, n)
        """
        z0 = np.asarray(z0, dtype=float)
        v = np.asarray(v, dtype=float)
        if v.ndim == 1:
            v = v[:, None]
        nsteps = v.shape[0]
        dt = np.broadcast_to(np.asarray(dt, dtype=float), (nsteps,))
        if np.any(dt < 0) or not np.all(np.isfinite(dt)):
            raise InputError("time step: must be finite and >= 0")
        if self.n_states == 0:
            return np.zeros((nsteps + 1, 0, np.broadcast_shapes(v.shape[1:], z0.shape[1:])[0]))
        if self.affine:
            return self._affine_trajectory(z0, v, dt, inputs)
        out = np.empty((nsteps + 1,) + np.broadcast_shapes(z0.shape, (1, v.shape[1])))
        out[0] = z0
        z = out[0]
        for k in range(nsteps):
            z = self.step(z, v[k], dt[k], inputs.at(k))
            out[k + 1] = z
        return out

    def _affine_trajectory(self, z0, v, dt, inputs):
        a, b = self.affine_coefficients(v, dt[:, None], inputs)
        return affine_scan(a, b, z0)

    # -- misc ---------------------------------------------------------------------------
    def describe(self) -> dict[str, Any]:
        """Parameters as a JSON-friendly dict (SI floats)."""
        return {"law": self.name, **{k: v for k, v in self.params.model_dump().items()
                                     if k != "law"}}

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.params!r})"


def warn_passivity(message: str) -> None:
    """Issue a :class:`PassivityWarning` (shown once per message)."""
    warnings.warn(message, PassivityWarning, stacklevel=3)


def as_velocity(v) -> np.ndarray:
    """Velocity as a float array of at least one dimension."""
    return np.atleast_1d(np.asarray(v, dtype=float))


def as_state(z, n_states: int, n: int | None = None) -> np.ndarray:
    """States as a float array of shape (n_states, n)."""
    z = np.asarray(z, dtype=float)
    if z.ndim == 1 and n_states == 1:
        z = z[None, :]
    elif z.ndim == 0:
        z = np.full((n_states, 1 if n is None else n), float(z))
    if z.shape[0] != n_states:
        raise InputError(f"state: expected {n_states} state rows (shape (n_states, n)), "
                         f"got shape {z.shape}")
    return z


# --------------------------------------------------------------------------------------------
# Parameter models
# --------------------------------------------------------------------------------------------
from pydantic import ConfigDict, model_validator  # noqa: E402

from sealsim.cases import CaseModel  # noqa: E402


def _fields_or_parameter_set(schema: dict, model: type) -> None:
    """JSON Schema of a law's parameters: its fields are required unless a ``parameter_set``
    gives them."""
    required = schema.pop("required", None)
    if required:
        schema["anyOf"] = [{"required": required}, {"required": ["parameter_set"]}]


class LawParameters(CaseModel):
    """Base of the parameter models of all laws.

    ``parameter_set`` names a set from :mod:`sealsim.friction.parameters`; its values fill
    every field the user did not give (explicit fields override the set).
    """

    model_config = ConfigDict(json_schema_extra=_fields_or_parameter_set)

    parameter_set: str | None = None

    @model_validator(mode="before")
    @classmethod
    def _fill_from_parameter_set(cls, data: Any) -> Any:
        if isinstance(data, dict) and data.get("parameter_set") is not None:
            from sealsim.friction.parameters import parameter_set_values

            law = cls.model_fields["law"].default
            values = parameter_set_values(law, data["parameter_set"])
            data = {**values, **data}
        return data
