r"""Reduced model of the rotary lip seal for its FMU: steady maps plus a thermal lag.

Heipl & Murrenhoff (IFAS RWTH Aachen) keep an expensive model out of the system simulation by
precomputing it into characteristic diagrams; here the same is done for the coupled
friction–thermal model of Organisciak et al. (SKF, AGMA 14FTM14, 2014,
:mod:`sealsim.rotary.simulation`).  Everything below is computed from whatever
``sealsim.rotary`` gives at build time -- no number of the rotary model is repeated here.

* **Steady maps** (:func:`steady_rise_map`): with the oil sump held at T_s (a thermostat, the
  FMU's input), :func:`~sealsim.rotary.simulation.steady_state` gives the contact temperature
  at each speed ω; the map stores the rise above the sump, ΔT_ss(ω, T_s) = T_c − T_s, and its
  sensitivity to the ambient temperature ∂ΔT_ss/∂T_a (a one-sided difference over
  ``ambient_step``), so that the ambient can be an input: ΔT_ss(T_a) ≈ ΔT_ss(T_a0) +
  ∂ΔT_ss/∂T_a·(T_a − T_a0).
* **Coordinates of the maps** (:class:`MapAxes`): the oil-side heat transfer of the shaft jumps
  where the flow in the annulus changes its regime (Taylor–Couette flow: laminar Couette flow
  below a critical Taylor number, Taylor vortices above, :func:`flow_regime_boundaries`), at a
  speed ω_b(T_s) ∝ ν(T_s) that moves from hundreds of rpm in cold oil to a few rpm in hot oil.
  The steady rise and the lag jump along that curve, which no table on a rectangular
  (ω, T_s) grid can follow.  So each flow regime k gets its own table over the regime
  coordinate ξ = k + (u − e_k)/(e_(k+1) − e_k) of the speed coordinate u = ln(1 + |ω|/ω_s)
  between the regime's edges e_k(T_s) (the boundaries; 0 and u(ω_max) at the ends), and over
  the sump's viscosity coordinate s = −ln(ν(T_s)/(1 mm²/s)), in which the convection
  coefficients, the film and the friction vary as powers.
* **Torque map** (:func:`torque_map`): the friction torque at speed and *contact* temperature
  (:func:`~sealsim.rotary.simulation.friction_map`, no heat transfer) -- the torque responds
  at once to the speed and through the contact temperature to the thermal state.
* **Thermal lag** (:func:`thermal_lag`): the transient model started in equilibrium (shaft,
  seal and sump at T_s, ambient T_s) and run at a constant speed ω until it settles gives the
  step response of the contact temperature to the friction heat; its normalised form
  y(t) = ΔT(t)/ΔT_ss is fitted by :func:`fit_step_response` with a sum of first-order lags,

  .. math:: y(t) = 1 - \sum_{i=1}^{N} a_i\,e^{-t/\tau_i}, \qquad \sum a_i = 1,

  one set per flow regime, speed and sump temperature (the convection coefficients, and so the
  time constants, grow with the speed and with a thinner, hotter oil, and jump at a regime
  boundary).  The FMU integrates dx_i/dt = (a_i·ΔT_ss − x_i)/τ_i and lets the contact follow
  the sump temperature through the slowest of these lags (the sump heats the contact through
  shaft and seal, the slow mode of the thermal network): ds/dt = (T_s − s)/τ_N,
  T_c = s + Σ x_i.

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
from sealsim.fmu.tables import HermiteTable, pchip_table
from sealsim.properties.elastomers import ServiceRangeWarning
from sealsim.properties.oils import OilRangeWarning
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import RotaryModel, friction_map, simulate, steady_state
from sealsim.thermal.convection import rotating_annulus_nusselt, taylor_number
from sealsim.tribology.film import FilmRangeWarning
from sealsim.units import ZERO_CELSIUS_K

#: A step response counts as settled at this fraction of its steady rise.
SETTLED_FRACTION = 0.99
#: The longest step-response run, as a multiple of the requested lag duration.
MAX_LAG_EXTENSION = 16.0
#: A jump of the oil-side Nusselt correlation by more than this factor is a regime boundary
#: of the maps (smaller jumps move the contact temperature by a fraction of a kelvin and are
#: interpolated across).
REGIME_JUMP = 1.2
#: Spacing of the temperature nodes of the map coordinates (viscosity, boundaries) [K].
AXIS_SPACING = 2.0
#: The smallest share of the speed axis a flow regime keeps when its boundary lies outside
#: the speed range (the boundary is clamped to it).
MIN_REGIME_SHARE = 0.02

__all__ = ["MapAxes", "SPEED_SCALE", "ThermalLag", "fit_step_response", "fixed_sump_case",
           "flow_regime_boundaries", "map_axes", "speed_coordinate", "steady_rise_map",
           "step_response", "thermal_lag", "torque_map"]

#: ω_s of the speed coordinate u = ln(1 + |ω|/ω_s) of the tables [rad/s] (10 rpm)
SPEED_SCALE = 10.0 * math.pi / 30.0


def speed_coordinate(speed):
    """u = ln(1 + |ω|/ω_s), the speed axis of the tables (as the C code computes it).

    Examples
    --------
    >>> float(speed_coordinate(SPEED_SCALE * (math.e - 1.0)))
    1.0
    """
    return np.log1p(np.abs(np.asarray(speed, dtype=float)) / SPEED_SCALE)


def fixed_sump_case(case: RotaryCase, sump_temperature: float, *,
                    ambient_temperature: float | None = None,
                    start_temperature: float | None = None,
                    speed: float | None = None, duration: float | None = None,
                    steady_rate: float | None = None,
                    max_duration: float | None = None) -> RotaryCase:
    """The case with its sump held at ``sump_temperature`` [K].

    Optionally another ambient and start temperature [K], and a duty cycle of one step at
    ``speed`` [rad/s] for ``duration`` [s]; with ``steady_rate`` [K/s] the speed is then held
    until every temperature changes slower than that (``duty.until_steady``), at most until
    ``max_duration`` [s].
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
        longest = max(float(duration), float(max_duration or 0.0), 1.0)
        data["duty"] = {"steps": [step], "max_duration": f"{longest!r} s"}
        if steady_rate is not None:
            data["duty"].update(until_steady=True, steady_rate=f"{float(steady_rate)!r} K/s")
    return validate_case(RotaryCase, data, "rotary case for the FMU maps")


def _critical_taylor_numbers(prandtl: float, min_jump: float = REGIME_JUMP) -> np.ndarray:
    """Taylor numbers where :func:`~sealsim.thermal.convection.rotating_annulus_nusselt`
    jumps by more than ``min_jump`` (found numerically: scan, then bisection)."""
    ta = np.geomspace(1.0, 1e8, 4001)

    def nusselt(x):
        return np.asarray(rotating_annulus_nusselt(x, prandtl), dtype=float)

    nu = nusselt(ta)
    ratio = nu[1:] / nu[:-1]
    found = []
    for i in np.flatnonzero((ratio > min_jump) | (ratio < 1.0 / min_jump)):
        lo, hi = ta[i], ta[i + 1]
        for _ in range(80):
            mid = math.sqrt(lo * hi)
            if abs(math.log(nusselt(mid) / nu[i])) < abs(math.log(nusselt(mid) / nu[i + 1])):
                lo = mid
            else:
                hi = mid
        found.append(hi)
    return np.array(found)


def flow_regime_boundaries(case: RotaryCase, sump_temperatures) -> np.ndarray:
    """Shaft speeds [rad/s] where the oil-side convection of the shaft changes its flow regime.

    With ``environment.shaft_oil_convection = "annulus"`` the oil-side coefficient of the shaft
    follows the Taylor–Couette correlation
    (:func:`~sealsim.thermal.convection.rotating_annulus_nusselt`) at the Taylor number of the
    shaft speed, the annulus gap and the oil's viscosity at the sump temperature
    (:meth:`~sealsim.rotary.simulation.RotaryModel.coefficients`).  Where the correlation
    jumps by more than :data:`REGIME_JUMP` (laminar Couette flow to Taylor vortices at the
    critical Taylor number), the steady contact temperature and the thermal lag jump too:
    at ω_b(T_s) = Ta_c/Ta(1 rad/s, ν(T_s)) ∝ ν(T_s).  A quiescent bath (``"open"``) has no
    regime boundary.

    Parameters
    ----------
    case : RotaryCase
    sump_temperatures : array_like
        T_s [K].

    Returns
    -------
    ndarray, shape (n_boundaries, n_temperatures)
        ω_b [rad/s], ascending along the first axis.
    """
    temps = np.atleast_1d(np.asarray(sump_temperatures, dtype=float))
    if case.environment.shaft_oil_convection != "annulus":
        return np.zeros((0, temps.size))
    model = RotaryModel(case)
    oil = model.oil
    mid = float(np.mean(temps))
    prandtl = float(oil.kinematic_viscosity(mid) * oil.density(mid) * oil.specific_heat(mid)
                    / oil.thermal_conductivity(mid))
    critical = _critical_taylor_numbers(prandtl)
    per_rad_s = taylor_number(1.0, case.seal.shaft_diameter / 2.0, model.oil_gap,
                              oil.kinematic_viscosity(temps))
    return critical[:, None] / np.asarray(per_rad_s, dtype=float)[None, :]


@dataclass(frozen=True)
class MapAxes:
    """Coordinates of the steady maps and the lag (see the module docstring).

    Attributes
    ----------
    table : HermiteTable
        Over (T_s [K], [0, 1]) -- constant along the second axis, a 1-D table in the format of
        the FMU's tables -- the viscosity coordinate s and the inner regime edges
        e_1 ... e_N (speed coordinates of the flow-regime boundaries, clamped to the speed
        range), PCHIP between nodes every :data:`AXIS_SPACING`.
    speed_max : float
        ω_max [rad/s], the end of the speed axis.
    """

    table: HermiteTable
    speed_max: float

    @property
    def n_regimes(self) -> int:
        return int(self.table.data.shape[-1])

    @property
    def temperature_range(self) -> tuple[float, float]:
        axis = self.table.axes[0]
        return float(axis[0]), float(axis[-1])

    def at(self, temperature):
        """(s, edges) at T_s [K]: s shape (n,), edges (n, n_regimes + 1) from 0 to u_max."""
        t = np.clip(np.atleast_1d(np.asarray(temperature, dtype=float)),
                    *self.temperature_range)
        values = self.table.evaluate(t, np.zeros_like(t))
        u_max = float(speed_coordinate(self.speed_max))
        edges = np.column_stack([np.zeros(t.size), values[:, 1:], np.full(t.size, u_max)])
        return values[:, 0], edges

    def speed(self, regime: int, xi, temperature):
        """Speeds [rad/s] at coordinates ξ ∈ [k, k+1] of regime k and sump temperatures [K]
        (broadcast); a point on an inner regime edge lies a relative 1e-9 inside the regime
        (the boundary itself belongs to the regime above)."""
        xi, temperature = np.broadcast_arrays(np.asarray(xi, dtype=float),
                                              np.asarray(temperature, dtype=float))
        _, edges = self.at(temperature.ravel())
        lo, hi = edges[:, regime], edges[:, regime + 1]
        f = xi.ravel() - regime
        u = lo + f * (hi - lo)
        if regime > 0:
            u = np.where(f <= 0.0, lo * (1.0 + 1e-9), u)
        if regime < self.n_regimes - 1:
            u = np.where(f >= 1.0, hi * (1.0 - 1e-9), u)
        return (SPEED_SCALE * np.expm1(u)).reshape(xi.shape)


def map_axes(case: RotaryCase, temperatures, speed_max: float) -> MapAxes:
    """The coordinates of the maps of a case up to ``speed_max`` [rad/s]: the oil's
    viscosity and the flow-regime boundaries (:func:`flow_regime_boundaries`) every
    :data:`AXIS_SPACING` over the range of ``temperatures`` [K] and at each of them (the
    nodes of the maps, where the table then holds the exact boundaries)."""
    given = np.asarray(temperatures, dtype=float)
    lo, hi = float(given.min()), float(given.max())
    spaced = np.linspace(lo, hi, max(2, math.ceil((hi - lo) / AXIS_SPACING) + 1))
    apart = np.min(np.abs(spaced[:, None] - given[None, :]), axis=1) > 1e-3
    temps = np.unique(np.concatenate([spaced[apart], given]))
    oil = RotaryModel(case).oil
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilRangeWarning)
        viscosity = -np.log(np.asarray(oil.kinematic_viscosity(temps), dtype=float) * 1e6)
    u_max = float(speed_coordinate(speed_max))
    boundaries = speed_coordinate(flow_regime_boundaries(case, temps))
    # a boundary outside the speed range is clamped to it (the regime beyond then holds values
    # of its neighbour: a node line, no jump); each regime keeps a share of the axis
    gap = MIN_REGIME_SHARE * u_max
    edges = np.zeros_like(boundaries)
    below = np.zeros(temps.size)
    n = boundaries.shape[0]
    for k in range(n):
        edges[k] = np.clip(boundaries[k], below + gap, u_max - (n - k) * gap)
        below = edges[k]
    values = np.concatenate([viscosity[None, :], edges])
    table = pchip_table(temps, [0.0, 1.0], np.repeat(values.T[:, None, :], 2, axis=1))
    return MapAxes(table, float(speed_max))


def steady_rise_map(case: RotaryCase, speeds, sump_temperatures,
                    ambient_step: float | None = 10.0, progress=None) -> dict[str, np.ndarray]:
    """Steady contact temperature rise, its ambient sensitivity and the torque on a grid.

    Parameters
    ----------
    case : RotaryCase
        Seal, oil, environment (its ambient is the reference T_a0).
    speeds : array_like, shape (n,) or (n, m)
        Shaft speeds ω [rad/s], >= 0: the same at every sump temperature, or one column per
        sump temperature.
    sump_temperatures : array_like, shape (m,)
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
        [K], each of shape (n, m).
    """
    sumps = np.atleast_1d(np.asarray(sump_temperatures, dtype=float))
    speeds = _per_sump(speeds, sumps.size)
    shape = speeds.shape
    out = {k: np.zeros(shape) for k in ("rise", "ambient_sensitivity", "torque", "T_contact")}
    ambient = case.environment.ambient_temperature
    total = speeds.size * (2 if ambient_step else 1)
    done = 0
    for j, ts in enumerate(sumps):
        base = fixed_sump_case(case, ts)
        shifted = (fixed_sump_case(case, ts, ambient_temperature=ambient + ambient_step)
                   if ambient_step else None)
        for i, w in enumerate(speeds[:, j]):
            with warnings.catch_warnings():   # the film range is the rotary model's note
                warnings.simplefilter("ignore", FilmRangeWarning)
                point = steady_state(base, float(w))
            t_contact = point["T_contact_C"] + ZERO_CELSIUS_K
            out["rise"][i, j] = t_contact - ts
            out["T_contact"][i, j] = t_contact
            out["torque"][i, j] = point["torque_Nm"]
            done += 1
            if shifted is not None:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", FilmRangeWarning)
                    other = steady_state(shifted, float(w))["T_contact_C"] + ZERO_CELSIUS_K
                out["ambient_sensitivity"][i, j] = (other - t_contact) / ambient_step
                done += 1
            if progress is not None:
                progress(done, total)
    return out


def _per_sump(speeds, n_sumps: int) -> np.ndarray:
    """Speeds as an (n, n_sumps) array: a 1-D list is the same for every sump temperature."""
    speeds = np.asarray(speeds, dtype=float)
    if speeds.ndim == 1:
        return np.repeat(speeds[:, None], n_sumps, axis=1)
    if speeds.ndim != 2 or speeds.shape[1] != n_sumps:
        raise InputError(f"speeds: expected one column per sump temperature ({n_sumps}), got "
                         f"the shape {speeds.shape}")
    return speeds


def torque_map(case: RotaryCase, speeds, contact_temperatures) -> np.ndarray:
    """Friction torque [N m] at speeds ω [rad/s] × contact temperatures [K], shape (n, m)."""
    speeds = np.asarray(speeds, dtype=float)
    temps = np.asarray(contact_temperatures, dtype=float)
    frame = friction_map(case, speeds * 30.0 / math.pi, temps - ZERO_CELSIUS_K)
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
    speeds : ndarray, shape (n_speed, n_sump)
        ω [rad/s] of the step responses (a column per sump temperature).
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
    turns at the speed ω until every temperature changes by less than
    1 − :data:`SETTLED_FRACTION` of the steady rise per ``duration`` (``duty.until_steady``),
    at most for :data:`MAX_LAG_EXTENSION` × ``duration``; the contact temperature rise
    normalised by the steady rise (:func:`~sealsim.rotary.simulation.steady_state`) is fitted
    by :func:`fit_step_response`.

    Parameters
    ----------
    case : RotaryCase
    speeds : array_like, shape (n,) or (n, m)
        ω [rad/s] (> 0): the same at every sump temperature, or a column per sump temperature.
    sump_temperatures : array_like, shape (m,)
        T_s [K].
    order : {1, 2, 3}
    duration : float
        The time scale of settling [s]: a response that changes by less than 1 % of its rise
        per ``duration`` has settled (within 1 % if its slowest time constant is shorter).
    progress : callable, optional
        ``progress(done, total)``.
    """
    sumps = np.atleast_1d(np.asarray(sump_temperatures, dtype=float))
    speeds = _per_sump(speeds, sumps.size)
    if np.any(speeds <= 0):
        raise InputError("lag speeds must be > 0")
    shape = speeds.shape
    weights = np.zeros(shape + (order,))
    taus = np.zeros(shape + (order,))
    errors = np.zeros(shape)
    settled = np.zeros(shape)
    responses = {}
    for j, ts in enumerate(sumps):
        for i, w in enumerate(speeds[:, j]):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning,
                                                 FilmRangeWarning))
                rise = steady_state(fixed_sump_case(case, ts, ambient_temperature=ts),
                                    float(w))["T_contact_C"] + ZERO_CELSIUS_K - ts
                if abs(rise) < 1e-9:
                    raise InputError(f"lag speed {w * 30 / math.pi:.4g} rpm heats the contact "
                                     f"by {rise:.2g} K only; choose a higher speed")
                # the run ends once settled: no fixed length to guess for slow responses
                # (low speed, insulated shaft ends), no time spent on settled fast ones
                held = fixed_sump_case(
                    case, ts, ambient_temperature=ts, start_temperature=ts, speed=float(w),
                    duration=min(float(duration), 60.0),
                    steady_rate=(1.0 - SETTLED_FRACTION) * abs(rise) / float(duration),
                    max_duration=MAX_LAG_EXTENSION * float(duration))
                frame = simulate(held).timeseries
            t = frame["time_s"].to_numpy()[1:]
            y = (frame["T_contact_C"].to_numpy()[1:] + ZERO_CELSIUS_K - ts) / rise
            weights[i, j], taus[i, j], errors[i, j] = fit_step_response(t, y, order)
            settled[i, j] = y[-1]
            responses[(i, j)] = (t, y)
            if progress is not None:
                progress(j * shape[0] + i + 1, speeds.size)
    return ThermalLag(speeds, sumps, weights, taus, errors, settled, responses)
