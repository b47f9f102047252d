"""Coupled friction–thermal simulation of a radial lip seal (seed 000, Fig. 4).

Every time step (backward Euler, adaptive Δt):

1. the speed ω(t) of the duty cycle;
2. viscosity, lip force, film, contact area and μ_dry at the current contact temperature
   → friction torque T (:class:`~sealsim.rotary.friction.LipSealFriction`);
3. heat q = T·ω into the contact band of the shaft (seed Eq. 6);
4. conduction through shaft and seal, convection to oil (sump node) and air, sump ↔ housing ↔
   ambient (seed Eq. 7, :mod:`sealsim.thermal.conduction`) → new temperatures.

Step 2 uses the contact temperature of the previous step (explicit coupling).  The feedback is
weak and stabilising (a hotter contact has thinner oil and less friction), so it needs no
iteration; the time-step refinement test checks that.  Energy is booked every step: heat
generated = heat stored in cells, sump and housing + heat given to the ambient (and to a
sump held at constant temperature).

Convection coefficients depend on speed and sump temperature; the system matrix is
factorised once per (speed bin of 2 %, sump-temperature bin of 2 K, Δt) and reused.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.errors import InputError, ModelError
from sealsim.properties.elastomers import ServiceRangeWarning, get_elastomer
from sealsim.properties.oils import OilRangeWarning
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.friction import FrictionState, LipSealFriction, LipSealFrictionParameters
from sealsim.rotary.lip import LIP_STYLES, LipStyle
from sealsim.rotary.thermal_model import SealSection, build_thermal_grid
from sealsim.thermal.conduction import (
    BackwardEulerStepper,
    Link,
    Solid,
    ThermalNetwork,
    factorise,
)
from sealsim.thermal.convection import (
    air_properties,
    free_convection_horizontal_cylinder,
    rotating_cylinder_coefficient,
)
from sealsim.tribology.rubber_friction import GroschMasterCurve

__all__ = ["RotaryModel", "RotaryResult", "friction_map", "housing_defaults", "lip_seal_friction",
           "lip_style", "simulate", "steady_state"]

CELSIUS_0 = 273.15
STEEL_DENSITY, STEEL_SPECIFIC_HEAT = 7850.0, 460.0
#: Oil volumetric expansion coefficient for free convection [1/K] (mineral oil ≈ 7e-4).
OIL_EXPANSION = 7e-4
#: Temperature difference assumed for the free-convection floor of the coefficients [K].
FREE_CONVECTION_DELTA_T = 10.0
#: Housing wall thickness for the default housing mass [m].
HOUSING_WALL = 5e-3

TIMESERIES_COLUMNS = ["time_s", "speed_rpm", "torque_Nm", "power_W", "T_contact_C",
                      "T_groove_C", "T_sump_C", "film_um", "F_lub_N", "F_material_N",
                      "T_housing_C", "lip_force_N", "mu_eff", "film_ratio", "duty_parameter"]


def housing_defaults(sump_volume: float) -> tuple[float, float, float]:
    """Default housing around a sump: a cubic box filled half with oil.

    The oil level is at the shaft centre in the middle of the box, so the box holds twice the
    oil volume.  Both the outer area (to ambient) and the wetted area (oil to wall) therefore
    grow with V^(2/3): this is how the sump volume acts on heat dissipation (seed 000 Fig. 13).

    Parameters
    ----------
    sump_volume : float
        Oil volume V [m³].

    Returns
    -------
    outer_area, wetted_area, mass : float
        Outer area of the box 6·a² [m²], oil-wetted wall area a²·(1 + 4·0.5) [m²] and the mass
        of 5 mm steel walls [kg], with a = (2V)^(1/3).

    Examples
    --------
    >>> [round(x, 4) for x in housing_defaults(0.2e-3)]
    [0.0326, 0.0163, 1.2785]
    """
    edge = (2.0 * sump_volume) ** (1.0 / 3.0)
    outer = 6.0 * edge**2
    wetted = edge**2 * (1.0 + 4.0 * 0.5)
    return outer, wetted, outer * HOUSING_WALL * STEEL_DENSITY


def lip_style(case: RotaryCase) -> LipStyle:
    """The lip style of a case, with the case's wave-lip parameters."""
    seal = case.seal
    if seal.lip_style == "plain":
        return LIP_STYLES["plain"]
    w = seal.wave
    return LipStyle("wave", w.film_factor, w.track_amplitude, w.lip_heat_exchange_factor)


def lip_seal_friction(case: RotaryCase) -> LipSealFriction:
    """The friction model (seal + oil + elastomer + parameters) of a case; with
    ``lip.force = "fe"`` the lip force (and with ``lip.contact_width = "fe"`` the contact
    width) comes from the FE of the lip (:mod:`sealsim.rotary.lip_fe`)."""
    seal, fr = case.seal, case.friction
    models = {}
    if case.lip.force == "fe":
        from sealsim.rotary.lip_fe import lip_force_table

        table = lip_force_table(seal, case.lip, seal.radial_force_temperature)
        models = {"lip_force_model": table.force_at}
        if case.lip.contact_width == "fe":
            models["contact_width_model"] = table.contact_width_at
    return LipSealFriction(
        LipSealFrictionParameters(
            shaft_diameter=seal.shaft_diameter, contact_width=seal.contact_width,
            radial_force=seal.radial_force, radial_force_temperature=seal.radial_force_temperature,
            spring_share=seal.spring_share, film_coefficient=fr.film_coefficient_um * 1e-6,
            film_exponent=fr.film_exponent, film_floor=fr.film_floor,
            film_factor=lip_style(case).film_factor,
            roughness=math.hypot(seal.shaft_roughness, seal.lip_roughness),
            rms_slope=seal.shaft_rms_slope, asperity_wavelength=fr.asperity_wavelength,
            kappa=fr.persson_kappa,
            master_curve=GroschMasterCurve(fr.mu_peak, fr.mu_low, fr.peak_speed_at_reference,
                                           fr.master_curve_width_decades)),
        case.oil.build(), get_elastomer(seal.material), **models)


@dataclass
class RotaryModel:
    """A case turned into its friction model, thermal network and coefficient laws."""

    case: RotaryCase

    def __post_init__(self):
        c = self.case
        self.friction = lip_seal_friction(c)
        self.oil, self.elastomer = self.friction.oil, self.friction.elastomer
        self.style = lip_style(c)
        seal = c.seal
        env = c.environment
        shaft = Solid("shaft", env.shaft_conductivity, env.shaft_density,
                      env.shaft_specific_heat)
        rubber = Solid(self.elastomer.name, self.elastomer.thermal_conductivity,
                       self.elastomer.density, self.elastomer.specific_heat)
        case_steel = Solid("case", 45.0, STEEL_DENSITY, STEEL_SPECIFIC_HEAT)
        self.section = SealSection(
            seal.shaft_diameter, seal.outer_diameter, seal.width,
            seal.contact_width + 2 * self.style.track_amplitude,
            env.shaft_length_oil_side, env.shaft_length_air_side, seal.spring_offset)
        self.grid = build_thermal_grid(self.section, shaft, rubber, case_steel,
                                       c.numerics.mesh_refinement)
        self.start_temperature = (env.start_temperature if env.start_temperature is not None
                                  else env.ambient_temperature)
        outer, wetted, mass = housing_defaults(env.sump_volume)
        housing_area = env.housing_area if env.housing_area is not None else outer
        housing_mass = env.housing_mass if env.housing_mass is not None else mass
        t0 = self.start_temperature
        sump_capacity = float(env.sump_volume * self.oil.density(t0) * self.oil.specific_heat(t0))
        self.sump_fixed = env.sump_temperature is not None
        # air pocket: ρ·c_p of air (1.2 kg/m³ · 1007 J/(kg K)) times its volume
        lumped = {"housing": housing_mass * STEEL_SPECIFIC_HEAT,
                  "air_pocket": 1.2 * 1007.0 * self.grid.pocket_volume}
        fixed = ["ambient"]
        if self.sump_fixed:
            fixed.append("sump")
        else:
            lumped = {"sump": sump_capacity, **lumped}
        nodes = {"shaft_oil": "sump", "shaft_air": "ambient", "shaft_end_oil": "sump",
                 "shaft_end_air": "ambient", "lip_oil": "sump", "seal_oil": "sump",
                 "seal_air": "ambient", "seal_housing": "housing",
                 "shaft_pocket": "air_pocket", "seal_pocket": "air_pocket"}
        self.network = ThermalNetwork(self.grid.conduction, lumped, fixed,
                                      {g: (faces, nodes[g]) for g, faces in
                                       self.grid.face_groups.items()})
        self.links = [
            Link("sump", "housing", env.oil_housing_heat_transfer * wetted),
            Link("housing", "ambient", env.housing_heat_transfer * housing_area),
        ]

    # -- convection ------------------------------------------------------------------------
    def coefficients(self, angular_speed: float, sump_temperature: float) -> dict[str, float]:
        """Heat transfer coefficients [W/(m² K)] of every face group.

        Shaft in oil: Kays & Bjorklund rotating cylinder in oil at the sump temperature on the
        wetted fraction of the circumference, in gearbox air (at sump temperature) on the rest;
        shaft in air: rotating cylinder in ambient air; both never below free convection
        (Churchill & Chu, ΔT = 10 K).  Shaft ends: semi-infinite fin, √(4·h·k/d).  Seal
        surfaces: a fraction of the shaft's coefficient (``[thermal]``), the lip's oil side
        times the lip style's heat exchange factor.
        """
        env, th = self.case.environment, self.case.thermal
        d = self.case.seal.shaft_diameter
        omega = abs(angular_speed)
        ts = sump_temperature
        nu_o = float(self.oil.kinematic_viscosity(ts))
        k_o = float(self.oil.thermal_conductivity(ts))
        rho_c = float(self.oil.density(ts) * self.oil.specific_heat(ts))
        alpha_o = k_o / rho_c
        h_oil = max(float(rotating_cylinder_coefficient(omega, d, nu_o, k_o, nu_o / alpha_o)),
                    float(free_convection_horizontal_cylinder(d, FREE_CONVECTION_DELTA_T, nu_o,
                                                              alpha_o, k_o, OIL_EXPANSION)))

        def h_air_at(temperature):
            nu_a, alpha_a, k_a, pr_a = (float(x) for x in air_properties(temperature))
            return max(float(rotating_cylinder_coefficient(omega, d, nu_a, k_a, pr_a)),
                       float(free_convection_horizontal_cylinder(
                           d, FREE_CONVECTION_DELTA_T, nu_a, alpha_a, k_a, 1.0 / temperature)))

        phi = env.oil_level_wetting
        h_shaft_oil = phi * h_oil + (1.0 - phi) * h_air_at(ts)
        h_air = h_air_at(env.ambient_temperature)
        k_shaft = env.shaft_conductivity
        return {
            "shaft_oil": h_shaft_oil,
            "shaft_air": h_air,
            "shaft_end_oil": math.sqrt(4.0 * h_shaft_oil * k_shaft / d),
            "shaft_end_air": (math.sqrt(4.0 * h_air * k_shaft / d)
                              if env.shaft_air_end == "fin" else 0.0),
            "lip_oil": th.seal_oil_factor * h_shaft_oil * self.style.lip_heat_exchange_factor,
            "seal_oil": th.seal_oil_factor * h_shaft_oil,
            "seal_air": th.seal_air_factor * h_air,
            "seal_housing": th.seal_housing_contact,
            "shaft_pocket": h_air,
            "seal_pocket": th.seal_air_factor * h_air,
        }

    def assemble(self, angular_speed: float, sump_temperature: float):
        """Network matrices at this speed and sump temperature.

        The air pocket exchanges with the ambient through its annular opening with the shaft's
        air-side coefficient.
        """
        h = self.coefficients(angular_speed, sump_temperature)
        pocket = Link("air_pocket", "ambient", h["shaft_air"] * self.grid.pocket_opening_area)
        return self.network.assemble(h, [*self.links, pocket])

    def fixed_temperatures(self) -> np.ndarray:
        env = self.case.environment
        values = {"ambient": env.ambient_temperature, "sump": env.sump_temperature}
        return np.array([values[n] for n in self.network.fixed_names], dtype=float)

    def source(self, power: float) -> np.ndarray:
        """Heat source vector: ``power`` [W] spread over the contact band of the shaft."""
        s = np.zeros(self.network.n)
        s[self.grid.contact_cells] = power * self.grid.contact_weights
        return s

    def contact_temperature(self, temperatures: np.ndarray) -> float:
        return float(temperatures[self.grid.contact_cells] @ self.grid.contact_weights)

    def sump_temperature(self, temperatures: np.ndarray) -> float:
        if self.sump_fixed:
            return float(self.case.environment.sump_temperature)
        return float(temperatures[self.network.node_index["sump"]])


@dataclass
class RotaryResult:
    """Result of :func:`simulate`."""

    case: RotaryCase
    timeseries: pd.DataFrame
    steps: list[dict]
    energy: dict[str, float]
    notes: list[str] = field(default_factory=list)
    statistics: dict[str, float] = field(default_factory=dict)

    def summary(self) -> dict:
        """The per-variant entry of ``summary.json``."""
        return {"steps": self.steps,
                "energy_balance_rel_error": self.energy["rel_error"],
                "energy_J": {k: v for k, v in self.energy.items() if k != "rel_error"},
                "max_T_contact_C": float(self.timeseries["T_contact_C"].max()),
                "notes": self.notes}


def _speed_profile(times, speeds, t):
    return float(np.interp(t, times, speeds, right=speeds[-1]))


def simulate(case: RotaryCase, base_dir: Path | None = None, progress=None) -> RotaryResult:
    """Run the coupled transient simulation of a rotary lip seal case.

    Parameters
    ----------
    case : RotaryCase
        The validated case.
    base_dir : Path, optional
        Folder that a relative ``duty.csv`` path is taken from.
    progress : callable, optional
        Called as ``progress(simulated_time, end_time)`` now and then.

    Returns
    -------
    RotaryResult
    """
    model = RotaryModel(case)
    times, speeds, steps = case.duty.profile(base_dir)
    end = float(times[-1])
    breaks = np.unique(times)
    num = case.numerics
    stepper = BackwardEulerStepper(model.network)
    temps = np.full(model.network.n, model.start_temperature)
    fixed = model.fixed_temperatures()
    capacity = model.network.capacity
    stored0 = capacity @ temps

    rows: list[tuple] = []
    t = 0.0
    t_contact = model.contact_temperature(temps)
    dt = num.min_time_step
    generated = dissipated = 0.0
    notes: list[str] = []
    service_max = model.elastomer.service_range[1]
    k_break = 1
    last_report = -1.0
    while t < end - 1e-9:
        while k_break < len(breaks) and breaks[k_break] <= t + 1e-9:
            k_break += 1
        t_next_break = breaks[k_break] if k_break < len(breaks) else end
        ramping = abs(_speed_profile(times, speeds, t_next_break - 1e-9)
                      - _speed_profile(times, speeds, t + 1e-9)) > 1e-9
        h = min(dt, t_next_break - t)
        if ramping:
            h = min(h, max((t_next_break - t) / 10.0, num.min_time_step))
        t1 = t + h
        omega = _speed_profile(times, speeds, t1 - 1e-12 if t1 >= t_next_break else t1)
        t_sump = model.sump_temperature(temps)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
                state = model.friction.evaluate(omega, t_contact)
        except InputError as exc:
            raise ModelError(f"rotary simulation stopped at t = {t1:.1f} s "
                             f"({omega * 30 / math.pi:.0f} rpm, contact temperature "
                             f"{t_contact - CELSIUS_0:.1f} degC): {exc}") from None
        power = float(state.power)
        key = (round(math.log1p(abs(omega)) / 0.02), round(t_sump / 2.0))
        temps, heat_out = stepper.step(temps, h, model.source(power), fixed, key,
                                       lambda o=omega, s=t_sump: model.assemble(o, s))
        if not np.all(np.isfinite(temps)):
            raise ModelError(f"rotary simulation: temperatures became non-finite at t = {t1:.1f} s")
        generated += power * h
        dissipated += heat_out
        t_contact = model.contact_temperature(temps)
        rows.append(_row(model, state, t1, omega, temps, t_contact))
        t = t1
        at_break = abs(t - t_next_break) < 1e-9
        jump = at_break and abs(_speed_profile(times, speeds, t + 1e-9)
                                - _speed_profile(times, speeds, t - 1e-9)) > 1e-9
        dt = num.min_time_step if jump else min(max(dt, h) * 1.5, num.max_time_step)
        if progress is not None and t - last_report >= end / 100:
            progress(t, end)
            last_report = t
    if progress is not None:
        progress(end, end)

    frame = pd.DataFrame(rows, columns=TIMESERIES_COLUMNS)
    frame = pd.concat([pd.DataFrame([_row(model, model.friction.evaluate(
        float(speeds[0]), model.start_temperature), 0.0, float(speeds[0]),
        np.full(model.network.n, model.start_temperature), model.start_temperature)],
        columns=TIMESERIES_COLUMNS), frame], ignore_index=True)

    stored = float(capacity @ temps - stored0)
    energy = {"generated": generated, "stored": stored, "dissipated": dissipated,
              "rel_error": abs(generated - stored - dissipated) / max(abs(generated), 1e-12)}
    if frame["T_contact_C"].max() > service_max - CELSIUS_0:
        notes.append(f"contact temperature reached {frame['T_contact_C'].max():.0f} degC, above "
                     f"the service limit of {model.elastomer.name} "
                     f"({service_max - CELSIUS_0:.0f} degC)")
    result = RotaryResult(case, frame, _step_summary(frame, steps, speeds, times), energy, notes,
                          {"time_steps": len(rows), "factorisations": stepper.factorisations,
                           "thermal_nodes": model.network.n_cells})
    return result


def _row(model: RotaryModel, state: FrictionState, t, omega, temps, t_contact) -> tuple:
    torque = float(state.torque)
    lip_force = float(state.lip_force)
    mu_eff = abs(torque) * 2 / model.case.seal.shaft_diameter / lip_force
    g = float(model.friction.duty_parameter(state, omega))
    return (t, omega * 30 / math.pi, torque, float(state.power), t_contact - CELSIUS_0,
            float(temps[model.grid.groove_cell]) - CELSIUS_0,
            model.sump_temperature(temps) - CELSIUS_0, float(state.film) * 1e6,
            float(state.force_lubricant), float(state.force_material),
            float(temps[model.network.node_index["housing"]]) - CELSIUS_0, lip_force, mu_eff,
            float(state.film_ratio), g)


#: The seed's validation convention: average over the last 30 s of each speed step.
AVERAGING_WINDOW = 30.0


def _step_summary(frame: pd.DataFrame, steps, speeds, times) -> list[dict]:
    out = []
    t = frame["time_s"].to_numpy()
    for start, stop in steps:
        lo = max(start, stop - AVERAGING_WINDOW)
        entry = {"start_s": float(start), "end_s": float(stop),
                 "speed_rpm": round(float(np.interp(stop - 1e-9, times, speeds)) * 30 / math.pi,
                                    6)}
        for column in ("torque_Nm", "power_W", "T_contact_C", "T_groove_C", "T_sump_C"):
            entry[column] = _time_average(t, frame[column].to_numpy(), lo, stop)
        out.append(entry)
    return out


def _time_average(t: np.ndarray, y: np.ndarray, lo: float, hi: float) -> float:
    """Time average of a step-wise signal (value at t_k holds over (t_{k-1}, t_k])."""
    if hi <= lo:
        return float(np.interp(hi, t, y))
    edges = np.clip(t, lo, hi)
    widths = np.diff(edges)
    return float(np.sum(y[1:] * widths) / (hi - lo))


def steady_state(case: RotaryCase, angular_speed: float, tol: float = 1e-4,
                 max_iter: int = 100) -> dict[str, float]:
    """Steady operating point at constant speed: friction and temperatures in equilibrium.

    Solves K·T = F·T_fixed + s(q) with q = P(ω, T_contact) by fixed-point iteration on the
    contact temperature (the friction–temperature feedback is weak, so it converges in a few
    iterations).

    Parameters
    ----------
    case : RotaryCase
        The case (its duty cycle is ignored).
    angular_speed : float
        ω [rad/s].
    tol : float
        Convergence tolerance on the contact temperature [K].

    Returns
    -------
    dict
        torque_Nm, power_W, T_contact_C, T_groove_C, T_sump_C, film_um, F_lub_N,
        F_material_N, iterations.
    """
    model = RotaryModel(case)
    fixed = model.fixed_temperatures()
    t_sump = model.sump_temperature(np.full(model.network.n, model.start_temperature))
    t_contact = t_sump
    for iteration in range(1, max_iter + 1):
        k, f = model.assemble(angular_speed, t_sump)
        lu = factorise(k.tocsc())
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
            state = model.friction.evaluate(angular_speed, t_contact)
        temps = lu.solve(f @ fixed + model.source(float(state.power)))
        new_contact = model.contact_temperature(temps)
        new_sump = model.sump_temperature(temps)
        converged = abs(new_contact - t_contact) < tol and abs(new_sump - t_sump) < tol
        # under-relaxation keeps the iteration monotone when the sump is free
        t_contact = 0.5 * (t_contact + new_contact) if iteration > 20 else new_contact
        t_sump = new_sump
        if converged:
            break
    else:
        raise ModelError(f"steady state at {angular_speed * 30 / math.pi:.0f} rpm did not "
                         f"converge in {max_iter} iterations")
    return {"torque_Nm": float(state.torque), "power_W": float(state.power),
            "T_contact_C": t_contact - CELSIUS_0,
            "T_groove_C": float(temps[model.grid.groove_cell]) - CELSIUS_0,
            "T_sump_C": t_sump - CELSIUS_0, "film_um": float(state.film) * 1e6,
            "F_lub_N": float(state.force_lubricant), "F_material_N": float(state.force_material),
            "iterations": iteration}


def friction_map(case: RotaryCase, speeds_rpm, temperatures_c) -> pd.DataFrame:
    """Friction of the case's seal over a speed × contact-temperature grid (no heat transfer).

    Vectorised: one call evaluates the whole grid.

    Parameters
    ----------
    case : RotaryCase
        Seal, oil and friction parameters are used; environment and duty are ignored.
    speeds_rpm : array_like
        Shaft speeds [rpm] (> 0).
    temperatures_c : array_like
        Contact temperatures [°C].

    Returns
    -------
    pandas.DataFrame
        One row per grid point: speed_rpm, T_contact_C, torque_Nm, power_W, film_um,
        F_lub_N, F_material_N, mu_eff, duty_parameter.
    """
    friction = lip_seal_friction(case)
    n, t = np.meshgrid(np.asarray(speeds_rpm, float), np.asarray(temperatures_c, float))
    omega = n.ravel() * np.pi / 30.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
        state = friction.evaluate(omega, t.ravel() + CELSIUS_0)
    return pd.DataFrame({
        "speed_rpm": n.ravel(), "T_contact_C": t.ravel(), "torque_Nm": state.torque,
        "power_W": state.power, "film_um": state.film * 1e6, "F_lub_N": state.force_lubricant,
        "F_material_N": state.force_material,
        "mu_eff": np.abs(state.torque) * 2 / case.seal.shaft_diameter / state.lip_force,
        "duty_parameter": friction.duty_parameter(state, omega)})
