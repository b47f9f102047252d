"""The rotary lip-seal FMU: steady maps and thermal lag of :mod:`.rotary_maps` in C.

Interface (SI):

===================  ======  =============================================================
variable             unit    meaning
===================  ======  =============================================================
speed                rad/s   input: shaft speed (display unit rpm)
T_sump               K       input: oil sump temperature
T_ambient            K       input (optional): ambient temperature
torque               N m     output: friction torque (sign of the speed)
power                W       output: power loss torque·|speed| (above the maps: torque·top
                             speed, the one operating point of all outputs)
T_contact            K       output: contact temperature
T_contact_steady     K       output: contact temperature it tends to at these inputs
map_clipped          -       output: true while an input lies outside the maps (clipped)
T_rise_1 ... N       K       states: components of the contact temperature rise
T_sump_lagged        K       state: the sump temperature as the contact feels it
start_steady         -       parameter: start in steady state (default) or at
T_contact_start      K       parameter: the contact temperature to start from
===================  ======  =============================================================

:func:`rotary_spec` computes the maps from the case (a few seconds), :func:`rotary_check`
compares the compiled FMU with the full model -- steady torque and contact temperature at
the grid points, optionally between them and over the case's own duty cycle (the transient
model with its free sump, the FMU fed with that sump temperature) -- and documents the errors.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from sealsim.errors import InputError, ModelError
from sealsim.fmu.model_description import ModelSpec, Variable
from sealsim.fmu.rotary_maps import (
    MAX_LAG_EXTENSION,
    SETTLED_FRACTION,
    SPEED_SCALE,
    MapAxes,
    ThermalLag,
    fixed_sump_case,
    map_axes,
    speed_coordinate,
    steady_rise_map,
    thermal_lag,
    torque_map,
)
from sealsim.fmu.tables import pchip_table
from sealsim.properties.elastomers import ServiceRangeWarning
from sealsim.properties.oils import OilRangeWarning
from sealsim.rotary.case import CASE_TEMPERATURES, RotaryCase
from sealsim.rotary.simulation import lip_seal_friction
from sealsim.tribology.film import FilmRangeWarning
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["RPM", "RotaryMaps", "rotary_check", "rotary_maps", "rotary_spec"]

RPM = math.pi / 30.0
_QUIET = (ServiceRangeWarning, OilRangeWarning, FilmRangeWarning)


@dataclass
class RotaryMaps:
    """Everything the rotary FMU embeds, with its grids (SI).

    The steady maps and the lag are given per flow regime k over the regime coordinate
    ξ ∈ [k, k+1] and the sump temperature (:class:`~sealsim.fmu.rotary_maps.MapAxes`).

    Attributes
    ----------
    axes : MapAxes
        Viscosity coordinate and regime edges over the sump temperature.
    sump_temperatures : ndarray, shape (m,)
        T_s [K] of the steady maps.
    xi : list of ndarray
        Per regime, the ξ of its nodes (n_k,).
    speeds : list of ndarray
        Per regime, the node speeds [rad/s], shape (n_k, m).
    steady : list of dict
        Per regime, :func:`~sealsim.fmu.rotary_maps.steady_rise_map` at those nodes.
    lag : ThermalLag
        Step responses at the speeds ``lag.speeds`` (p, q): row i at ξ = ``lag_xi[i]``.
    lag_xi : ndarray, shape (p,)
        ξ of the lag rows, ascending.
    lag_regime : ndarray, shape (p,)
        Regime of the lag rows (ascending; a row on a boundary belongs to one side).
    """

    axes: MapAxes
    sump_temperatures: np.ndarray
    xi: list
    speeds: list
    steady: list
    ambient: float
    ambient_range: float
    torque_speeds: np.ndarray
    torque_temperatures: np.ndarray
    torque: np.ndarray
    lag: ThermalLag
    lag_xi: np.ndarray
    lag_regime: np.ndarray
    notes: list = field(default_factory=list)

    @property
    def n_regimes(self) -> int:
        return len(self.xi)

    @property
    def speed_max(self) -> float:
        return self.axes.speed_max


def rotary_maps(case: RotaryCase, *, speed_max: float, speed_points: int, sump_temperatures,
                torque_speed_min: float, lag_order: int = 2, lag_points: int = 2,
                lag_sump_temperatures=None, lag_duration: float = 3600.0,
                ambient_step: float | None = 10.0, ambient_range: float = 30.0,
                torque_points: tuple[int, int] = (65, 61), progress=None) -> RotaryMaps:
    """Compute the steady maps, the torque map and the thermal lag of a rotary case.

    Parameters
    ----------
    case : RotaryCase
    speed_max : float
        End of the speed axis [rad/s].
    speed_points : int
        Node spacing of the speed axis: (speed_points − 1) equal steps of u = ln(1 + ω/ω_s)
        from 0 to ``speed_max``; each flow regime gets the nodes its widest extent needs
        (at least 2), its edges included.
    sump_temperatures : array_like
        Sump temperature grid [K] (ascending, at least two).
    torque_speed_min : float
        Lowest speed of the torque table [rad/s]; below it the torque ramps to 0.
    lag_order : {1, 2, 3}
    lag_points : int
        Step responses per flow regime and lag sump temperature, at the centres of as many
        equal parts of the regime's ξ.
    lag_sump_temperatures : array_like, optional
        Sump temperatures of the step responses [K] (default: lowest, middle and highest of
        the grid).
    lag_duration : float
        Settling time scale of the step responses [s] (:func:`thermal_lag`).
    ambient_step : float or None
        Step of the ambient sensitivity [K]; None: the ambient is not an input.
    ambient_range : float
        The FMU clips the ambient to T_a0 ± this [K].
    torque_points : (int, int)
        Nodes of the torque table over speed and contact temperature.
    progress : callable, optional
        ``progress(task, done, total)``.
    """
    sumps = np.asarray(sump_temperatures, dtype=float)
    if sumps.size < 2 or np.any(np.diff(sumps) <= 0):
        raise InputError(f"rotary.sump_temperatures: {_celsius(sumps)}; give at least two "
                         "ascending temperatures")
    lo, hi = CASE_TEMPERATURES
    if sumps[0] <= lo or sumps[-1] >= hi:
        raise InputError(f"rotary.sump_temperatures: {_celsius(sumps)}; a rotary case's sump "
                         f"lies between {_celsius(lo)} and {_celsius(hi)}")
    if not speed_max > 0:
        raise InputError("rotary.max_speed must be > 0")
    if speed_points < 3:
        raise InputError("rotary.speed_points must be >= 3")
    if not 0 < torque_speed_min < speed_max:
        raise InputError("rotary.torque_speed_min must be > 0 and below the highest speed")
    if lag_points < 1:
        raise InputError("rotary.lag_points must be >= 1")
    if min(torque_points) < 2:
        raise InputError(f"rotary.torque_points: {list(torque_points)}; the torque table needs "
                         "at least 2 nodes over speed and over contact temperature")
    report = (lambda task: None if progress is None else
              (lambda done, total: progress(task, done, total)))
    if lag_sump_temperatures is None:
        lag_sump_temperatures = [sumps[0], 0.5 * (sumps[0] + sumps[-1]), sumps[-1]]
    lag_sumps = np.sort(np.asarray(lag_sump_temperatures, dtype=float))
    if lag_sumps[0] < sumps[0] or lag_sumps[-1] > sumps[-1]:
        raise InputError(f"rotary.lag_sump_temperatures: {_celsius(lag_sumps)} must lie "
                         f"between {_celsius(sumps[0])} and {_celsius(sumps[-1])}, the "
                         "lowest and highest rotary.sump_temperatures")
    axes = map_axes(case, np.concatenate([sumps, lag_sumps]), speed_max)
    _, edges = axes.at(sumps)
    step = float(speed_coordinate(speed_max)) / (speed_points - 1)
    xi, speeds, steady = [], [], []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", _QUIET)
        for k in range(axes.n_regimes):
            widest = float(np.max(edges[:, k + 1] - edges[:, k]))
            nodes = np.linspace(k, k + 1, max(2, math.ceil(widest / step - 1e-9) + 1))
            xi.append(nodes)
            speeds.append(axes.speed(k, nodes[:, None], sumps[None, :]))
        calls = sum(w.size for w in speeds) * (2 if ambient_step else 1)
        done = 0
        for w in speeds:
            part = report("steady map")
            try:
                steady.append(steady_rise_map(
                    case, w, sumps, ambient_step,
                    None if part is None else lambda d, n, base=done: part(base + d, calls)))
            except ModelError as exc:   # the map's corner: name the fields that span it
                raise ModelError(f"{exc} (the FMU's steady map spans rotary.max_speed = "
                                 f"{speed_max * 30 / math.pi:.6g} rpm and "
                                 f"rotary.sump_temperatures up to "
                                 f"{sumps[-1] - ZERO_CELSIUS_K:.6g} degC: lower them)") from None
            done += w.size * (2 if ambient_step else 1)
        lag_xi = np.concatenate([k + _lag_fractions(lag_points)
                                 for k in range(axes.n_regimes)])
        lag_regime = np.repeat(np.arange(axes.n_regimes), lag_points)
        lag_speeds = np.concatenate([axes.speed(k, (k + _lag_fractions(lag_points))[:, None],
                                                lag_sumps[None, :])
                                     for k in range(axes.n_regimes)])
        lag = thermal_lag(case, lag_speeds, lag_sumps, lag_order, lag_duration,
                          progress=report("thermal lag"))
        n_speed, n_temp = torque_points
        t_speeds = np.geomspace(torque_speed_min, speed_max, n_speed)
        contact = np.concatenate([s["T_contact"].ravel() for s in steady])
        sensitivity = max(float(np.abs(s["ambient_sensitivity"]).max()) for s in steady)
        low = min(float(contact.min()), float(sumps[0])) - 10.0 - ambient_range * sensitivity
        high = float(contact.max()) + 10.0 + ambient_range * sensitivity
        # within the temperatures the elastomer and oil models accept
        friction = lip_seal_friction(case)
        allowed_lo, allowed_hi = friction.elastomer.allowed_range
        oil_min = friction.oil.min_temperature
        low = max(low, allowed_lo, oil_min if oil_min is not None else -np.inf)
        high = min(high, allowed_hi)
        t_temps = np.linspace(low, high, n_temp)
        torque = torque_map(case, t_speeds, t_temps)
    notes = []
    if np.any(lag.settled < SETTLED_FRACTION):
        bad = [f"{w / RPM:.4g} rpm at {t - ZERO_CELSIUS_K:.4g} degC"
               for (w, t), y in zip(zip(lag.speeds.ravel(), np.broadcast_to(
                   lag.sump_temperatures, lag.speeds.shape).ravel()), lag.settled.ravel())
               if y < SETTLED_FRACTION]
        notes.append("the step responses at " + ", ".join(bad) + " had not settled (within 1 "
                     f"percent) after {MAX_LAG_EXTENSION:g} times the lag duration; raise "
                     "rotary.lag_duration")
    return RotaryMaps(axes, sumps, xi, speeds, steady,
                      float(case.environment.ambient_temperature), float(ambient_range),
                      t_speeds, t_temps, torque, lag, lag_xi, lag_regime, notes)


def _celsius(temperatures) -> str:
    """Temperatures [K] as the case files write them: '20 degC, 120 degC'."""
    return ", ".join(f"{t - ZERO_CELSIUS_K:g} degC" for t in np.ravel(temperatures))


def _lag_fractions(points: int) -> np.ndarray:
    """Where in a regime (ξ − k) the step responses are taken: at the centres of ``points``
    equal parts (not at standstill, where nothing heats, nor at the top speed, where the
    contact of a hot sump may leave the elastomer's range)."""
    return (np.arange(points) + 0.5) / points


def rotary_spec(case: RotaryCase, maps: RotaryMaps, identifier: str, *, title: str = "",
                source: str = "") -> ModelSpec:
    """The model of a rotary lip-seal FMU from its maps."""
    env = case.environment
    sump0 = float(env.sump_temperature if env.sump_temperature is not None else (
        env.start_temperature if env.start_temperature is not None
        else env.ambient_temperature))
    sump0 = float(np.clip(sump0, maps.sump_temperatures[0], maps.sump_temperatures[-1]))
    order = maps.lag.order
    # nominal values of the states: the largest steady rise (at least 1 K), the sump temperature
    rise_scale = max(1.0, max(float(np.max(part["rise"])) for part in maps.steady))
    variables = [
        Variable("time", "TIME", "independent", "simulation time", "s"),
        Variable("speed", "SPEED", "input", "shaft speed", "rad/s", 0.0),
        Variable("T_sump", "T_SUMP", "input", "oil sump temperature", "K", sump0),
        Variable("T_ambient", "T_AMBIENT", "input", "ambient temperature", "K", maps.ambient),
        Variable("torque", "TORQUE", "output", "friction torque of the seal", "N.m"),
        Variable("power", "POWER", "output", "power loss torque*|speed| (above the maps: at "
                 "their top speed, as torque and temperatures)", "W"),
        Variable("T_contact", "T_CONTACT", "output", "contact temperature of the lip", "K"),
        Variable("T_contact_steady", "T_CONTACT_STEADY", "output",
                 "contact temperature in steady state at the current inputs", "K"),
        Variable("map_clipped", "MAP_CLIPPED", "output",
                 "true while an input lies outside the maps (clipped)", boolean=True),
    ]
    for i in range(3):
        variables.append(Variable(f"T_rise_{i + 1}", f"RISE_{i + 1}", "output",
                                  f"component {i + 1} of the contact temperature rise above "
                                  "the lagged sump temperature", "K", 0.0, state=True,
                                  relative=True, nominal=rise_scale, exposed=i < order))
    variables.append(Variable("T_sump_lagged", "SUMP_LAG", "output",
                              "sump temperature as the contact feels it (slowest lag)", "K",
                              sump0, state=True, nominal=sump0))
    for i in range(3):
        variables.append(Variable(f"der(T_rise_{i + 1})", f"DER_RISE_{i + 1}", "local",
                                  f"time derivative of T_rise_{i + 1}", "K/s",
                                  derivative_of=f"T_rise_{i + 1}", exposed=i < order))
    variables.append(Variable("der(T_sump_lagged)", "DER_SUMP_LAG", "local",
                              "time derivative of T_sump_lagged", "K/s",
                              derivative_of="T_sump_lagged"))
    variables += [
        Variable("start_steady", "START_STEADY", "parameter",
                 "start in steady state at the initial inputs (else at T_contact_start)",
                 start=1.0, boolean=True),
        Variable("T_contact_start", "T_CONTACT_START", "parameter",
                 "contact temperature at the start when start_steady is false", "K", sump0,
                 lower=(">", CASE_TEMPERATURES[0]), upper=("<", CASE_TEMPERATURES[1])),
    ]
    lag = maps.lag
    sump_axis, edges = maps.axes.at(maps.sump_temperatures)
    lag_axis, _ = maps.axes.at(lag.sump_temperatures)
    lag_start = np.searchsorted(maps.lag_regime, np.arange(maps.n_regimes + 1))

    def c_array(name, values, kind="double"):
        text = (repr(float(v)) if kind == "double" else str(int(v)) for v in values)
        return f"static const {kind} {name}[{len(values)}] = {{" + ", ".join(text) + "};"

    steady_tables = [
        pchip_table(nodes, sump_axis, np.stack([part["rise"], part["ambient_sensitivity"]], -1))
        .c_source(f"STEADY_MAP_{k}") for k, (nodes, part) in enumerate(zip(maps.xi, maps.steady))]
    torque_table = pchip_table(speed_coordinate(maps.torque_speeds), maps.torque_temperatures,
                               maps.torque[..., None])
    torque_error = _torque_table_error(case, torque_table)
    tables = "\n".join([
        maps.axes.table.c_source("AXIS_TABLE"), *steady_tables,
        "static const HermiteTable *const STEADY_MAPS[NREG] = {"
        + ", ".join(f"&STEADY_MAP_{k}" for k in range(maps.n_regimes)) + "};",
        torque_table.c_source("TORQUE_MAP"),
        c_array("LAG_XI", maps.lag_xi), c_array("LAG_START", lag_start, "int"),
        c_array("LAG_S", lag_axis),
        c_array("LAG_WEIGHT", lag.weights.ravel()),
        c_array("LAG_LOG_TAU", np.log(lag.time_constants).ravel())])
    defines = {
        "NLAG": order, "NREG": maps.n_regimes, "LAG_NT": int(lag.sump_temperatures.size),
        "SPEED_SCALE": repr(SPEED_SCALE), "U_MAX": repr(float(speed_coordinate(maps.speed_max))),
        "STEADY_SPEED_HI": repr(float(maps.speed_max)),
        "STEADY_SUMP_LO": repr(float(maps.sump_temperatures[0])),
        "STEADY_SUMP_HI": repr(float(maps.sump_temperatures[-1])),
        "AMBIENT_MAP": repr(maps.ambient),
        "AMBIENT_LO": repr(maps.ambient - maps.ambient_range),
        "AMBIENT_HI": repr(maps.ambient + maps.ambient_range),
        "TORQUE_SPEED_MIN": repr(float(maps.torque_speeds[0])),
        "TORQUE_TC_LO": repr(float(maps.torque_temperatures[0])),
        "TORQUE_TC_HI": repr(float(maps.torque_temperatures[-1])),
    }
    boundaries = SPEED_SCALE * np.expm1(edges[:, 1:-1]) / RPM
    report = {
        "source": source,
        "steady_map": {"speed_max_rpm": maps.speed_max / RPM,
                       "regimes": maps.n_regimes,
                       "speed_nodes_per_regime": [int(x.size) for x in maps.xi],
                       "node_speeds_rpm": [(w / RPM).tolist() for w in maps.speeds],
                       "regime_boundaries_rpm": boundaries.T.tolist(),
                       "sump_temperatures_C": (maps.sump_temperatures - ZERO_CELSIUS_K).tolist(),
                       "ambient_C": maps.ambient - ZERO_CELSIUS_K},
        "torque_map": {"speed_range_rpm": [float(maps.torque_speeds[0] / RPM),
                                           float(maps.torque_speeds[-1] / RPM)],
                       "contact_temperature_range_C": [
                           float(maps.torque_temperatures[0] - ZERO_CELSIUS_K),
                           float(maps.torque_temperatures[-1] - ZERO_CELSIUS_K)],
                       "nodes": [int(maps.torque_speeds.size),
                                 int(maps.torque_temperatures.size)],
                       "max_relative_error_at_cell_centres": torque_error},
        "thermal_lag": {"order": order, "speeds_rpm": (lag.speeds / RPM).tolist(),
                        "xi": maps.lag_xi.tolist(), "regime": maps.lag_regime.tolist(),
                        "sump_temperatures_C": (lag.sump_temperatures - ZERO_CELSIUS_K).tolist(),
                        "weights": lag.weights.tolist(),
                        "time_constants_s": lag.time_constants.tolist(),
                        "fit_max_error": lag.max_errors.tolist(),
                        "settled": lag.settled.tolist()},
        "notes": list(maps.notes),
    }
    description = ("sealsim rotary lip seal: friction torque, power loss and contact "
                   "temperature from steady maps of the coupled friction-thermal model and a "
                   f"thermal lag of order {order}" + (f": {title}" if title else ""))
    return ModelSpec(identifier, title or identifier, description, "rotary_model.c",
                     variables, defines, tables, default_experiment=(0.0, 3600.0, 1.0),
                     report=report)


def _torque_table_error(case: RotaryCase, table) -> float:
    """Largest relative difference of the torque table from sealsim's friction model at the
    centres of its cells (the friction model has a kink where the film reaches its floor)."""
    u, temps = table.axes
    mid_u, mid_t = np.meshgrid(0.5 * (u[1:] + u[:-1]), 0.5 * (temps[1:] + temps[:-1]),
                               indexing="ij")
    speed = np.expm1(mid_u.ravel()) * SPEED_SCALE
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", _QUIET)
        exact = np.asarray(lip_seal_friction(case).evaluate(speed, mid_t.ravel()).torque)
    approx = table.evaluate(mid_u.ravel(), mid_t.ravel())[:, 0]
    return float(np.max(np.abs(approx / exact - 1.0)))


def rotary_check(case: RotaryCase, maps: RotaryMaps, spec: ModelSpec, *,
                 between: bool = True, duty_cycle: bool = True, base_dir: Path | None = None,
                 progress=None):
    """A build check: the compiled rotary FMU against the full model.

    Returns ``check(folder, token)`` for :func:`sealsim.fmu.builder.build_archive`.  It
    measures (and records in the build report) the relative error of the steady torque at
    every grid point (above the torque ramp at ``torque_speed_min``); with ``between`` also
    at the centres of the cells of every regime's table
    (new :func:`~sealsim.rotary.simulation.steady_state` runs); with ``duty_cycle`` the
    errors over the case's own duty cycle: :func:`~sealsim.rotary.simulation.simulate`
    (free or held sump as in the case) against the FMU fed with that run's speed and sump
    temperature.
    """
    from sealsim.fmu.cosim import run_rotary
    from sealsim.fmu.instance import LoadedFMU
    from sealsim.rotary.simulation import simulate, steady_state

    def steady_fmu(fmu, speed, sump):
        fmu.reset()
        fmu.set(speed=speed, T_sump=sump)
        fmu.initialize()
        torque, contact = fmu.get("torque", "T_contact")
        return torque, contact

    def check(folder: Path, token: str) -> None:
        results = {}
        with LoadedFMU(folder, "cs", "build_check") as fmu:
            errors, contact_errors = [], []
            # below torque_speed_min the FMU's torque ramps to 0 on purpose: not compared
            for speeds, part in zip(maps.speeds, maps.steady):
                for (i, j), w in np.ndenumerate(speeds):
                    if w < maps.torque_speeds[0]:
                        continue
                    torque, contact = steady_fmu(fmu, w, maps.sump_temperatures[j])
                    errors.append(abs(torque / part["torque"][i, j] - 1.0))
                    contact_errors.append(abs(contact - part["T_contact"][i, j]))
            results["grid"] = {"points": len(errors), "max_torque_rel_error": max(errors),
                               "max_T_contact_error_K": max(contact_errors)}
            if between:
                # the centres of the cells of every regime's table
                mid_t = 0.5 * (maps.sump_temperatures[1:] + maps.sump_temperatures[:-1])
                rows = []
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", _QUIET)
                    for ts in mid_t:
                        held = fixed_sump_case(case, ts)
                        for k, nodes in enumerate(maps.xi):
                            mid_xi = 0.5 * (nodes[1:] + nodes[:-1])
                            for w in maps.axes.speed(k, mid_xi, ts):
                                if w < maps.torque_speeds[0]:
                                    continue
                                full = steady_state(held, float(w))
                                torque, contact = steady_fmu(fmu, w, ts)
                                rows.append((w, ts, full["torque_Nm"], torque,
                                             full["T_contact_C"] + ZERO_CELSIUS_K, contact))
                rows = np.array(rows)
                results["between"] = {
                    "points": int(len(rows)),
                    "max_torque_rel_error": float(np.max(np.abs(rows[:, 3] / rows[:, 2] - 1))),
                    "max_T_contact_error_K": float(np.max(np.abs(rows[:, 5] - rows[:, 4])))}
                spec.data["between_points"] = rows
            if duty_cycle and case.duty is None:
                spec.report["notes"].append("the case has no duty cycle: the transient check "
                                            "was not run")
            elif duty_cycle:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", _QUIET)
                    full = simulate(case, base_dir=base_dir).timeseries
                fmu.reset()
                fmu.set(start_steady=False,
                        T_contact_start=float(full["T_contact_C"].iloc[0] + ZERO_CELSIUS_K))
                t = full["time_s"].to_numpy()
                run = run_rotary(fmu, t, full["speed_rpm"].to_numpy() * RPM,
                                 full["T_sump_C"].to_numpy() + ZERO_CELSIUS_K)
                rel = np.abs(run["torque"][1:] / full["torque_Nm"].to_numpy()[1:] - 1.0)
                d_contact = run["T_contact"] - (full["T_contact_C"].to_numpy() + ZERO_CELSIUS_K)
                rise = full["T_contact_C"] - full["T_sump_C"]
                results["duty_cycle"] = {
                    "duration_s": float(t[-1]),
                    "max_torque_rel_error": float(rel.max()),
                    "mean_torque_rel_error": float(rel.mean()),
                    "max_T_contact_error_K": float(np.abs(d_contact).max()),
                    "mean_T_contact_error_K": float(np.abs(d_contact).mean()),
                    "max_rise_above_sump_K": float(rise.max())}
                spec.data["duty_cycle"] = {
                    "time_s": t, "speed_rpm": full["speed_rpm"].to_numpy(),
                    "T_sump_C": full["T_sump_C"].to_numpy(),
                    "torque_full_Nm": full["torque_Nm"].to_numpy(),
                    "torque_fmu_Nm": run["torque"],
                    "T_contact_full_C": full["T_contact_C"].to_numpy(),
                    "T_contact_fmu_C": run["T_contact"] - ZERO_CELSIUS_K}
        spec.report["validation"] = results

    return check
