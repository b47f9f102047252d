"""Drive sealsim's FMUs from Python with FMPy: benches, a driven mass, a duty cycle.

These are small co-simulation masters -- what a system-simulation tool does with the FMUs --
used by the tests, the examples and the build checks:

* :func:`run_velocity` -- the friction FMU on a prescribed velocity (a test bench);
* :class:`FMUFrictionLaw` -- the friction FMU behind sealsim's
  :class:`~sealsim.friction.base.FrictionLaw` interface, so that sealsim's own implicit
  stick/slip stepper (:func:`sealsim.friction.bench.simulate_mass` with
  ``integrator="stepper"``) drives a mass–spring with the FMU as its friction element: every
  trial step of the stepper is a ``doStep`` from the saved FMU state (``getFMUstate`` /
  ``setFMUstate``), and sticking is decided with the FMU's ``F_breakaway`` output;
* :func:`run_rotary` -- the rotary FMU on a speed and sump-temperature history.
"""

from __future__ import annotations

import numpy as np

from sealsim.errors import InputError
from sealsim.friction.base import NO_INPUTS, ContactInputs, FrictionLaw, Partials
from sealsim.fmu.friction_export import STATE_NAMES
from sealsim.fmu.instance import LoadedFMU

__all__ = ["FMUFrictionLaw", "run_rotary", "run_velocity"]


def _contact_inputs(inputs: ContactInputs) -> dict[str, float]:
    """FMU inputs p_A, p_B, T_seal from a ContactInputs with scalar fields."""
    values = {"p_A": float(inputs.pressure_a), "p_B": float(inputs.pressure_b)}
    if inputs.temperature is not None:
        values["T_seal"] = float(inputs.temperature)
    return values


def run_velocity(fmu: LoadedFMU, time, velocity_step, velocity_sample,
                 inputs: ContactInputs = NO_INPUTS) -> dict[str, np.ndarray]:
    """The friction FMU on a prescribed velocity.

    Step k holds ``velocity_step[k]`` from ``time[k]`` to ``time[k+1]`` (the mean velocity
    of the step, as :func:`sealsim.friction.bench.simulate_velocity`); the outputs at
    ``time[k+1]`` are read with the input ``velocity_sample[k+1]``.

    Parameters
    ----------
    fmu : LoadedFMU
        A co-simulation instance, not yet initialized.
    time : array_like, shape (N + 1,)
    velocity_step : array_like, shape (N,)
    velocity_sample : array_like, shape (N + 1,)
    inputs : ContactInputs
        Constant pressures and temperature.

    Returns
    -------
    dict
        ``F`` and every exposed state (``theta``, ``z``, ``film_speed``), shape (N + 1,).
    """
    time = np.asarray(time, dtype=float)
    names = ["F"] + [n for n in STATE_NAMES if n in fmu.vr]
    out = {n: np.empty(time.size) for n in names}
    fmu.set(v=float(velocity_sample[0]), **_contact_inputs(inputs))
    fmu.initialize(float(time[0]))
    for n, value in zip(names, fmu.get(*names)):
        out[n][0] = value
    for k in range(time.size - 1):
        fmu.set(v=float(velocity_step[k]))
        fmu.do_step(float(time[k]), float(time[k + 1] - time[k]))
        fmu.set(v=float(velocity_sample[k + 1]))
        for n, value in zip(names, fmu.get(*names)):
            out[n][k + 1] = value
    return out


class FMUFrictionLaw(FrictionLaw):
    """A friction FMU as a :class:`~sealsim.friction.base.FrictionLaw` of one contact.

    Only what sealsim's implicit stick/slip stepper needs is offered: ``initial_state``,
    ``step``, ``force``, ``breakaway_force``.  The states handed around are the values of
    the FMU's states; each distinct state the stepper starts a trial from is saved as an FMU
    state and restored for the next trial.  Inputs (pressures, temperature) are the FMU's
    current inputs (set them with ``fmu.set`` before :meth:`start`).

    Parameters
    ----------
    fmu : LoadedFMU
        A co-simulation instance of a friction FMU (not yet initialized).
    """

    affine = False

    def __init__(self, fmu: LoadedFMU):
        if fmu.kind != "cs":
            raise InputError("FMUFrictionLaw needs the co-simulation interface of the FMU")
        self.fmu = fmu
        self.name = "fmu"
        self._states = tuple(n for n in STATE_NAMES if n in fmu.vr)
        self._stiction = "F_breakaway" in fmu.vr
        self._saved: dict[bytes, object] = {}
        self._times: dict[bytes, float] = {}       # communication point of each state
        self._current: bytes | None = None
        self.params = None

    # -- FrictionLaw interface ------------------------------------------------------------
    @property
    def state_names(self):  # type: ignore[override]
        return self._states

    @property
    def has_stiction(self) -> bool:  # type: ignore[override]
        return self._stiction

    def start(self, start_time: float = 0.0) -> None:
        """Initialize the FMU (after its parameters and inputs are set)."""
        self.fmu.initialize(start_time)
        self._current = self._key(self._values())
        self._times[self._current] = start_time

    def initial_state(self, n: int = 1) -> np.ndarray:
        if n != 1:
            raise InputError("an FMU friction law models one contact (n = 1)")
        return self._values()

    def _values(self) -> np.ndarray:
        values = self.fmu.get(*self._states) if self._states else []
        return np.array(values, dtype=float).reshape(len(self._states), 1)

    @staticmethod
    def _key(z) -> bytes:
        return np.ascontiguousarray(z, dtype=float).tobytes()

    def _goto(self, z) -> None:
        """Put the FMU into the state with values z (saved earlier or current)."""
        key = self._key(z)
        if key == self._current:
            return
        saved = self._saved.get(key)
        if saved is None:
            raise InputError("FMUFrictionLaw: a state that was never reached by the FMU")
        self.fmu.set_state(saved)
        self._current = key

    def _remember_current(self) -> None:
        if self._current is not None and self._current not in self._saved:
            if len(self._saved) >= 4:              # the stepper only returns to its last step
                for key in list(self._saved)[:-2]:
                    self.fmu.free_state(self._saved.pop(key))
            self._saved[self._current] = self.fmu.get_state()

    def step(self, z, v, dt, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        self._goto(z)
        self._remember_current()
        t0 = self._times.get(self._current, 0.0)
        self.fmu.set(v=float(np.ravel(v)[0]))
        self.fmu.do_step(t0, float(dt))
        z1 = self._values()
        self._current = self._key(z1)
        self._times = {k: t for k, t in self._times.items() if k in self._saved}
        self._times[self._current] = t0 + float(dt)
        return z1

    def force(self, z, v, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        self._goto(z)
        self.fmu.set(v=float(np.ravel(v)[0]))
        return np.array(self.fmu.get("F"))

    def breakaway_force(self, z, inputs: ContactInputs = NO_INPUTS) -> np.ndarray:
        self._goto(z)
        return np.array(self.fmu.get("F_breakaway"))

    def derivatives(self, z, v, inputs: ContactInputs = NO_INPUTS):
        raise NotImplementedError("use the model-exchange FMU for derivatives")

    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS) -> Partials:
        raise NotImplementedError("an FMU gives no analytic partials")

    def steady_state(self, v, inputs: ContactInputs = NO_INPUTS):
        raise NotImplementedError("drive the FMU at constant v instead")


def run_rotary(fmu: LoadedFMU, time, speed, sump_temperature,
               ambient_temperature=None) -> dict[str, np.ndarray]:
    """The rotary FMU on a history of speed [rad/s] and sump temperature [K].

    Step k goes from ``time[k]`` to ``time[k+1]`` with the speed of its end ``speed[k+1]``
    and the sump temperature of its start, and the torque of the step is read at its start
    (with the contact temperature there) -- the explicit coupling of
    :func:`sealsim.rotary.simulation.simulate`, whose rows hold the torque at the contact
    temperature of the previous step; ``T_contact`` is read at the end of the step.  The FMU
    starts in steady state at the first inputs unless its ``start_steady`` parameter was set
    to false.

    Returns
    -------
    dict
        ``torque`` [N m], ``power`` [W], ``T_contact`` [K], ``T_contact_steady`` [K].
    """
    time = np.asarray(time, dtype=float)
    speed = np.asarray(speed, dtype=float)
    sump = np.asarray(sump_temperature, dtype=float)
    out = {n: np.empty(time.size) for n in ("torque", "power", "T_contact", "T_contact_steady")}
    ambient = (None if ambient_temperature is None else
               np.broadcast_to(np.asarray(ambient_temperature, dtype=float), time.shape))

    def inputs(k_speed, k_sump):
        values = {"speed": speed[k_speed], "T_sump": sump[k_sump]}
        if ambient is not None:
            values["T_ambient"] = ambient[k_sump]
        fmu.set(**values)

    inputs(0, 0)
    fmu.initialize(float(time[0]))
    for k in range(time.size):
        if k:
            inputs(k, k - 1)
        out["torque"][k], out["power"][k] = fmu.get("torque", "power")
        if k:
            fmu.do_step(float(time[k - 1]), float(time[k] - time[k - 1]))
        out["T_contact"][k], out["T_contact_steady"][k] = fmu.get("T_contact",
                                                                  "T_contact_steady")
    return out
