r"""Reduced model of the rotary lip seal for its FMU: steady maps plus a thermal lag.

Seed 001 keeps an expensive model out of the system simulation by precomputing it into
characteristic diagrams; here the same is done for the coupled friction–thermal model of seed
000 (:mod:`sealsim.rotary.simulation`).  Everything below is computed from whatever
``sealsim.rotary`` gives at build time -- no number of the rotary model is repeated here.

* **Steady maps** (:func:`steady_rise_map`): with the oil sump held at T_s (a thermostat, the
  FMU's input), :func:`~sealsim.rotary.simulation.steady_state` gives the contact temperature
  at each speed ω; the map stores the rise above the sump, ΔT_ss(ω, T_s) = T_c − T_s, and its
  sensitivity to the ambient temperature ∂ΔT_ss/∂T_a (a one-sided difference over
  ``ambient_step``), so that the ambient can be an input: ΔT_ss(T_a) ≈ ΔT_ss(T_a0) +
  ∂ΔT_ss/∂T_a·(T_a − T_a0).
* **Torque map** (:func:`torque_map`): the friction torque at speed and *contact* temperature
  (:func:`~sealsim.rotary.simulation.friction_map`, no heat transfer) -- the torque responds
  at once to the speed and through the contact temperature to the thermal state.
* **Thermal lag** (:func:`thermal_lag`): the transient model started in equilibrium (shaft,
  seal and sump at T_s, ambient T_s) and run at a constant speed ω gives the step response of
  the contact temperature to the friction heat; its normalised form y(t) = ΔT(t)/ΔT_ss is
  fitted by :func:`fit_step_response` with a sum of first-order lags,

  .. math:: y(t) = 1 - \sum_{i=1}^{N} a_i\,e^{-t/\tau_i}, \qquad \sum a_i = 1,

  one set per speed and sump temperature (the convection coefficients, and so the time
  constants, grow with the speed and with a thinner, hotter oil).  The FMU integrates
  dx_i/dt = (a_i·ΔT_ss − x_i)/τ_i and lets the contact follow the sump temperature through
  the slowest of these lags (the sump heats the contact through shaft and seal, the slow mode
  of the thermal network): ds/dt = (T_s − s)/τ_N, T_c = s + Σ x_i.

The reduced model assumes the housing in equilibrium with sump and ambient; its errors on a
duty cycle are measured by the build (:mod:`sealsim.fmu.rotary_export`).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from sealsim.cases import validate_case
from sealsim.errors import InputError
from sealsim.properties.elastomers import ServiceRangeWarning
from sealsim.properties.oils import OilRangeWarning
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import friction_map, simulate, steady_state
from sealsim.tribology.film import FilmRangeWarning

#: A step response counts as settled at this fraction of its steady rise.
SETTLED_FRACTION = 0.99
#: The longest step-response run, as a multiple of the requested lag duration.
MAX_LAG_EXTENSION = 16.0

__all__ = ["CELSIUS_0", "ThermalLag", "fit_step_response", "fixed_sump_case",
           "steady_rise_map", "step_response", "thermal_lag", "torque_map"]

CELSIUS_0 = 273.15


def fixed_sump_case(case: RotaryCase, sump_temperature: float, *,
                    ambient_temperature: float | None = None,
                    start_temperature: float | None = None,
                    speed: float | None = None, duration: float | None = None) -> RotaryCase:
    """The case with its sump held at ``sump_temperature`` [K].

    Optionally another ambient and start temperature [K], and a duty cycle of one step at
    ``speed`` [rad/s] for ``duration`` [s].
    """
    data = case.model_dump(mode="json")
    env = data["environment"]
    env["sump_temperature"] = f"{float(sump_temperature)!r} K"
    if ambient_temperature is not None:
        env["ambient_temperature"] = f"{float(ambient_temperature)!r} K"
    if start_temperature is not None:
        env["start_temperature"] = f"{float(start_temperature)!r} K"
    if speed is not None:
        step = {"speed": f"{float(speed)!r} rad/s", "duration": f"{float(duration)!r} s"}
        data["duty"] = {"steps": [step], "max_duration": f"{max(float(duration), 1.0)!r} s"}
    return validate_case(RotaryCase, data, "rotary case for the FMU maps")


def steady_rise_map(case: RotaryCase, speeds, sump_temperatures,
                    ambient_step: float | None = 10.0, progress=None) -> dict[str, np.ndarray]:
    """Steady contact temperature rise, its ambient sensitivity and the torque on a grid.

    Parameters
    ----------
    case : RotaryCase
        Seal, oil, environment (its ambient is the reference T_a0).
    speeds : array_like
        Shaft speeds ω [rad/s], >= 0.
    sump_temperatures : array_like
        Sump temperatures T_s [K].
    ambient_step : float or None
        ΔT_a [K] of the one-sided difference ∂ΔT_ss/∂T_a; None: no ambient sensitivity
        (zeros).
    progress : callable, optional
        ``progress(done, total)``.

    Returns
    -------
    dict
        ``rise`` ΔT_ss [K], ``ambient_sensitivity`` [-], ``torque`` [N m], ``T_contact``
        [K], each of shape (len(speeds), len(sump_temperatures)).
    """
    speeds = np.asarray(speeds, dtype=float)
    sumps = np.asarray(sump_temperatures, dtype=float)
    shape = (speeds.size, sumps.size)
    out = {k: np.zeros(shape) for k in ("rise", "ambient_sensitivity", "torque", "T_contact")}
    ambient = case.environment.ambient_temperature
    total = speeds.size * sumps.size * (2 if ambient_step else 1)
    done = 0
    for j, ts in enumerate(sumps):
        base = fixed_sump_case(case, ts)
        shifted = (fixed_sump_case(case, ts, ambient_temperature=ambient + ambient_step)
                   if ambient_step else None)
        for i, w in enumerate(speeds):
            point = steady_state(base, float(w))
            t_contact = point["T_contact_C"] + CELSIUS_0
            out["rise"][i, j] = t_contact - ts
            out["T_contact"][i, j] = t_contact
            out["torque"][i, j] = point["torque_Nm"]
            done += 1
            if shifted is not None:
                other = steady_state(shifted, float(w))["T_contact_C"] + CELSIUS_0
                out["ambient_sensitivity"][i, j] = (other - t_contact) / ambient_step
                done += 1
            if progress is not None:
                progress(done, total)
    return out


def torque_map(case: RotaryCase, speeds, contact_temperatures) -> np.ndarray:
    """Friction torque [N m] at speeds ω [rad/s] × contact temperatures [K], shape (n, m)."""
    speeds = np.asarray(speeds, dtype=float)
    temps = np.asarray(contact_temperatures, dtype=float)
    frame = friction_map(case, speeds * 30.0 / math.pi, temps - CELSIUS_0)
    # friction_map's rows run over temperature (outer) and speed (inner)
    return frame["torque_Nm"].to_numpy().reshape(temps.size, speeds.size).T


def step_response(t, weights, time_constants):
    """Normalised step response of a sum of first-order lags, y = 1 − Σ a_i·exp(−t/τ_i).

    Parameters
    ----------
    t : array_like
        Time since the step [s].
    weights : array_like
        a_i [-], summing to 1.
    time_constants : array_like
        τ_i [s], > 0.

    Examples
    --------
    >>> step_response([0.0, 1.0], [0.5, 0.5], [1.0, 1e9]).round(4)
    array([0.    , 0.3161])
    """
    t = np.asarray(t, dtype=float)
    a = np.asarray(weights, dtype=float)
    tau = np.asarray(time_constants, dtype=float)
    return 1.0 - np.sum(a[:, None] * np.exp(-t[None, :] / tau[:, None]), axis=0)


def fit_step_response(t, y, order: int = 2):
    """Least-squares fit of :func:`step_response` to a normalised step response.

    Parameters
    ----------
    t, y : array_like
        Time since the step [s] and normalised response [-] (0 before, 1 at steady state).
    order : {1, 2, 3}
        Number of first-order lags.

    Returns
    -------
    weights, time_constants : ndarray
        a_i (sum 1) and τ_i [s], sorted by τ.
    max_error : float
        Largest |y_fit − y|.

    Examples
    --------
    >>> t = np.geomspace(0.01, 100.0, 300)
    >>> a, tau, err = fit_step_response(t, step_response(t, [0.3, 0.7], [0.5, 10.0]))
    >>> a.round(3).tolist(), tau.round(3).tolist(), err < 1e-6
    ([0.3, 0.7], [0.5, 10.0], True)
    """
    if order not in (1, 2, 3):
        raise InputError(f"lag_order: {order!r} is not allowed; choose 1, 2 or 3")
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    positive = t[t > 0]
    first = positive.min() if positive.size else 1.0
    last = t.max() if t.size else 1.0

    def unpack(q):
        raw = np.concatenate([q[:order - 1], [0.0]])
        a = np.exp(raw - raw.max())
        return a / a.sum(), np.exp(q[order - 1:])

    q0 = np.concatenate([np.zeros(order - 1),
                         np.log(np.geomspace(max(first, 1e-3), max(last / 5, 1e-2), order))])
    lo = np.concatenate([np.full(order - 1, -30.0), np.full(order, math.log(1e-4))])
    hi = np.concatenate([np.full(order - 1, 30.0), np.full(order, math.log(1e7))])
    fit = least_squares(lambda q: step_response(t, *unpack(q)) - y, np.clip(q0, lo, hi),
                        bounds=(lo, hi))
    a, tau = unpack(fit.x)
    k = np.argsort(tau)
    return a[k], tau[k], float(np.max(np.abs(fit.fun))) if y.size else 0.0


@dataclass(frozen=True)
class ThermalLag:
    """Thermal lag of the contact temperature over speed × sump temperature.

    Attributes
    ----------
    speeds : ndarray
        ω [rad/s] of the step responses.
    sump_temperatures : ndarray
        T_s [K] of the step responses.
    weights, time_constants : ndarray, shape (n_speed, n_sump, order)
        a_i [-] and τ_i [s] of the response to the friction heat.
    max_errors : ndarray, shape (n_speed, n_sump)
        Largest deviation of the fit from the normalised response [-].
    settled : ndarray, shape (n_speed, n_sump)
        Normalised response of the transient model at its end (1 = steady).
    responses : dict
        (i, j) -> (t, y): the normalised responses of the transient model.
    """

    speeds: np.ndarray
    sump_temperatures: np.ndarray
    weights: np.ndarray
    time_constants: np.ndarray
    max_errors: np.ndarray
    settled: np.ndarray
    responses: dict

    @property
    def order(self) -> int:
        return int(self.time_constants.shape[-1])


def thermal_lag(case: RotaryCase, speeds, sump_temperatures, order: int = 2,
                duration: float = 3600.0, progress=None) -> ThermalLag:
    """Identify the thermal lag from step responses of the transient model.

    Each run of :func:`~sealsim.rotary.simulation.simulate` starts in equilibrium at the sump
    temperature T_s (shaft, seal and sump there, the sump held, the ambient equal to it) and
    turns at the speed ω for ``duration``; the contact temperature rise normalised by the
    steady rise is fitted by :func:`fit_step_response`.

    Parameters
    ----------
    case : RotaryCase
    speeds : array_like
        ω [rad/s] (> 0).
    sump_temperatures : array_like
        T_s [K].
    order : {1, 2, 3}
    duration : float
        Length of each run [s]; a run whose response has not settled within 1 % is repeated
        with twice the length, up to ``MAX_LAG_EXTENSION`` × ``duration`` (see ``settled``).
    progress : callable, optional
        ``progress(done, total)``.
    """
    speeds = np.asarray(speeds, dtype=float)
    sumps = np.atleast_1d(np.asarray(sump_temperatures, dtype=float))
    if np.any(speeds <= 0):
        raise InputError("lag speeds must be > 0")
    shape = (speeds.size, sumps.size)
    weights = np.zeros(shape + (order,))
    taus = np.zeros(shape + (order,))
    errors = np.zeros(shape)
    settled = np.zeros(shape)
    responses = {}
    for i, w in enumerate(speeds):
        for j, ts in enumerate(sumps):
            run_for = float(duration)
            while True:
                held = fixed_sump_case(case, ts, ambient_temperature=ts, start_temperature=ts,
                                       speed=float(w), duration=run_for)
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning,
                                                     FilmRangeWarning))
                    frame = simulate(held).timeseries
                    final = steady_state(held, float(w))["T_contact_C"] + CELSIUS_0 - ts
                if abs(final) < 1e-9:
                    raise InputError(f"lag speed {w * 30 / math.pi:.4g} rpm heats the contact "
                                     f"by {final:.2g} K only; choose a higher speed")
                t = frame["time_s"].to_numpy()[1:]
                y = (frame["T_contact_C"].to_numpy()[1:] + CELSIUS_0 - ts) / final
                # slow responses (low speed, insulated shaft ends) get longer runs, so the
                # fit sees the slowest time constant settle; ``settled`` reports the rest
                if y[-1] >= SETTLED_FRACTION or run_for >= MAX_LAG_EXTENSION * duration:
                    break
                run_for *= 2.0
            weights[i, j], taus[i, j], errors[i, j] = fit_step_response(t, y, order)
            settled[i, j] = y[-1]
            responses[(i, j)] = (t, y)
            if progress is not None:
                progress(i * sumps.size + j + 1, speeds.size * sumps.size)
    return ThermalLag(speeds, sumps, weights, taus, errors, settled, responses)
