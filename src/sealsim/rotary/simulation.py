"""Coupled friction–thermal simulation of a radial lip seal (Organisciak et al. 2014, Fig. 4).

Every time step (backward Euler, adaptive Δt):

1. the speed ω(t) of the duty cycle;
2. viscosity, lip force, film, contact area and μ_dry at the current contact temperature
   → friction torque T (:class:`~sealsim.rotary.friction.LipSealFriction`);
3. heat q = T·ω into the contact band of the shaft (Organisciak et al. 2014, Eq. 6);
4. conduction through shaft and seal, convection to oil (sump node) and air, sump ↔ housing ↔
   ambient (Organisciak et al. 2014, Eq. 7, :mod:`sealsim.thermal.conduction`) → new
   temperatures.

Step 2 uses the contact temperature of the previous step (explicit coupling).  The feedback is
weak and stabilising (a hotter contact has thinner oil and a lower μ_dry), so it needs no
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
from functools import cached_property
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.cases import expand_variants, load_toml
from sealsim.errors import InputError, ModelError
from sealsim.properties.elastomers import ServiceRangeWarning, get_elastomer
from sealsim.properties.oils import T_RANGE as OIL_T_RANGE
from sealsim.properties.oils import OilRangeWarning
from sealsim.rotary.case import RotaryCase, start_temperature
from sealsim.rotary.friction import FrictionState, LipSealFriction, LipSealFrictionParameters
from sealsim.rotary.lip import (
    LIP_STYLES,
    AnalyticLipForce,
    LipStyle,
    lip_mounting_note,
    wave_lip_style,
)
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
    annulus_wall_coefficient,
    free_convection_horizontal_cylinder,
    rotating_annulus_coefficient,
    rotating_cylinder_coefficient,
)
from sealsim.tribology.film import FilmRangeWarning, film_range_note
from sealsim.tribology.rolling_bearing import palmgren_viscous_moment, series_62_bearing
from sealsim.tribology.rubber_friction import (
    GroschMasterCurve,
    hysteresis_peak_speed,
    loss_peak_frequency,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["RotaryModel", "RotaryResult", "friction_map", "housing_defaults", "lip_seal_friction",
           "lip_style", "load_rotary_case", "operating_notes", "simulate", "steady_state"]

STEEL_DENSITY, STEEL_SPECIFIC_HEAT = 7850.0, 460.0
#: Temperature difference assumed for the free-convection floor of the coefficients [K].
FREE_CONVECTION_DELTA_T = 10.0
#: Housing wall thickness for the default housing mass [m].
HOUSING_WALL = 5e-3
#: Heat transfer coefficient of a shaft end held at a node's temperature [W/(m² K)]: over the
#: end face of an 80 mm shaft 50 W/K, ten times the axial conductance of 50 mm of shaft, so the
#: end sits at the node's temperature.
END_CONTACT = 1.0e4
#: :func:`steady_state` factorises anew when an iteration shrinks the update by less than this
#: factor while a free sump has moved more than :data:`STALE_SUMP_CHANGE` from the temperature
#: of the factorisation: the oil's coefficients have changed so much that the chord iteration
#: has slowed down.
STALE_CONTRACTION = 0.5
STALE_SUMP_CHANGE = 2.0  # K
#: A contact more than this below a held sump gets a note saying why [K] (0.1 K: well above
#: the steady state's 1e-8 K tolerance, below what a thermocouple resolves).
BELOW_HELD_SUMP = 0.1
#: How long the temperatures must stay below duty.steady_rate before until_steady stops [s].
STEADY_WINDOW = 60.0

TIMESERIES_COLUMNS = ["time_s", "speed_rpm", "torque_Nm", "power_W", "T_contact_C",
                      "T_groove_C", "T_sump_C", "film_um", "F_lub_N", "F_material_N",
                      "T_housing_C", "lip_force_N", "mu_eff", "film_ratio", "duty_parameter",
                      "bearing_to_shaft_W", "heat_oil_side_W", "heat_housing_W",
                      "heat_air_side_W"]


def housing_defaults(sump_volume: float) -> tuple[float, float, float]:
    """Default housing around a sump: a cubic box filled half with oil.

    The oil level is at the shaft centre in the middle of the box, so the box holds twice the
    oil volume.  Both the outer area (to ambient) and the wetted area (oil to wall) therefore
    grow with V^(2/3): this is how the sump volume acts on heat dissipation (Organisciak et al.
    2014, Fig. 13).

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
    return wave_lip_style(seal.shaft_diameter, w.track_amplitude, w.waves, w.film_factor,
                          w.lip_heat_exchange_factor)


def bearing_geometry(case: RotaryCase) -> tuple[float, float]:
    """Pitch diameter and width [m] of the bearing beside the seal: as given, else the 62xx
    deep-groove ball bearing of the shaft's bore (:func:`series_62_bearing`)."""
    bearing = case.environment.bearing
    pitch, width = series_62_bearing(case.seal.shaft_diameter)
    return (bearing.pitch_diameter or pitch, bearing.width or width)


def bearing_span(case: RotaryCase) -> tuple[float, float] | None:
    """Axial extent (z_far, z_near) [m] of the bearing's inner ring on the oil-side shaft
    (z = 0 at the contact, oil side negative), or None without a bearing."""
    bearing = case.environment.bearing
    if bearing.model == "none":
        return None
    seal = case.seal
    oil_face = SealSection(seal.shaft_diameter, seal.outer_diameter, seal.width,
                           seal.contact_width).oil_face
    near = oil_face - bearing.gap
    return near - bearing_geometry(case)[1], near


def bearing_heat(case: RotaryCase, oil, angular_speed, bearing_temperature):
    """Friction heat [W] of the bearing beside the seal at the shaft speed ω [rad/s] and its
    operating temperature [K] (:meth:`RotaryModel.bearing_temperature`): Palmgren's viscous
    moment × |ω| with the oil's viscosity at that temperature (``bearing.model =
    "palmgren"``), the given power while the shaft turns (``"power"``), or 0."""
    bearing = case.environment.bearing
    if bearing.model == "none" or angular_speed == 0:
        return 0.0
    if bearing.model == "power":
        return float(bearing.power)
    moment = palmgren_viscous_moment(oil.kinematic_viscosity(bearing_temperature),
                                     angular_speed, bearing_geometry(case)[0], bearing.f0)
    return float(moment) * abs(angular_speed)


def lip_force_source(case: RotaryCase):
    """The lip force F_tip(T) of a case: a callable of the lip temperature [K] -> [N].

    The analytic law (:class:`~sealsim.rotary.lip.AnalyticLipForce`) or, with
    ``lip.force = "fe"``, the FE table of the lip (:mod:`sealsim.rotary.lip_fe`).
    """
    seal = case.seal
    if case.lip.force == "fe":
        from sealsim.rotary.lip_fe import lip_force_table

        return lip_force_table(seal, case.lip, seal.mounting_temperature).force_at
    return AnalyticLipForce(seal.radial_force, seal.radial_force_temperature, seal.spring_share,
                            get_elastomer(seal.material), seal.hoop_prestrain,
                            case.environment.shaft_expansion, seal.mounting_temperature)


def lip_note(case: RotaryCase, lowest_temperature: float) -> str:
    """The run's note on the lip's mounting path (:func:`~sealsim.rotary.lip.lip_mounting_note`)
    for its lowest contact temperature [K]."""
    history = case.lip.force != "fe" or get_elastomer(case.seal.material).prony is not None
    return lip_mounting_note(lowest_temperature, case.seal.mounting_temperature, history)


def contact_width_source(case: RotaryCase):
    """The contact width b(T) [m] of a case from the FE of the lip (``lip.contact_width =
    "fe"``), or None for the constant ``seal.contact_width``."""
    if case.lip.contact_width != "fe":
        return None
    from sealsim.rotary.lip_fe import lip_force_table

    seal = case.seal
    return lip_force_table(seal, case.lip, seal.mounting_temperature).contact_width_at


def lip_seal_friction(case: RotaryCase) -> LipSealFriction:
    """The friction model (seal + oil + elastomer + lip force + parameters) of a case."""
    seal, fr = case.seal, case.friction
    elastomer = get_elastomer(seal.material)
    peak = fr.peak_speed_at_reference
    if peak is None:
        peak = float(hysteresis_peak_speed(fr.asperity_wavelength, loss_peak_frequency(elastomer)))
    return LipSealFriction(
        LipSealFrictionParameters(
            shaft_diameter=seal.shaft_diameter, contact_width=seal.contact_width,
            film_coefficient=fr.film_coefficient_um * 1e-6,
            film_exponent=fr.film_exponent, film_floor=fr.film_floor,
            film_factor=lip_style(case).film_factor,
            roughness=math.hypot(seal.shaft_roughness, seal.lip_roughness),
            master_curve=GroschMasterCurve(fr.mu_peak, fr.mu_low, peak,
                                           fr.master_curve_width_decades)),
        case.oil.build(), elastomer, lip_force_source(case), contact_width_source(case))


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
        band = seal.contact_width + 2 * self.style.track_amplitude
        self.bearing_span = bearing_span(c)
        length_oil = env.shaft_length_oil_side
        if length_oil is None:  # through the bearing and a quarter diameter beyond it
            length_oil = (-self.bearing_span[0] if self.bearing_span else 0.0) + \
                seal.shaft_diameter / 4.0
        if self.bearing_span is not None and -self.bearing_span[0] >= length_oil:
            raise InputError(f"environment.shaft_length_oil_side "
                             f"{length_oil * 1e3:g} mm ends before the bearing beside the seal "
                             f"(it reaches {-self.bearing_span[0] * 1e3:.1f} mm from the "
                             f"contact): model a longer shaft or set bearing.model = 'none'")
        self.section = SealSection(
            seal.shaft_diameter, seal.outer_diameter, seal.width, band, length_oil,
            env.shaft_length_air_side, seal.spring_offset, self.bearing_span)
        self.grid = build_thermal_grid(self.section, shaft, rubber, case_steel,
                                       c.numerics.mesh_refinement)
        self.start_temperature = start_temperature(env)
        self.oil_gap = env.oil_gap if env.oil_gap is not None else (
            seal.outer_diameter - seal.shaft_diameter) / 2.0
        outer, wetted, mass = housing_defaults(env.sump_volume)
        housing_area = env.housing_area if env.housing_area is not None else outer
        housing_mass = env.housing_mass if env.housing_mass is not None else mass
        t0 = self.start_temperature
        sump_capacity = float(env.sump_volume * self.oil.density(t0) * self.oil.specific_heat(t0))
        self.sump_fixed = env.sump_temperature is not None
        # air pocket: ρ·c_p of air (1.2 kg/m³ · 1007 J/(kg K)) times its volume
        lumped = {"air_pocket": 1.2 * 1007.0 * self.grid.pocket_volume}
        fixed = ["ambient"]
        if env.housing_temperature is not None:
            fixed.append("housing")
        else:
            lumped = {"housing": housing_mass * STEEL_SPECIFIC_HEAT, **lumped}
        if self.sump_fixed:
            fixed.append("sump")
        else:
            lumped = {"sump": sump_capacity, **lumped}
        self.air_node = "housing" if env.air_side == "adapter" else "ambient"
        air_end_node = "housing" if env.shaft_air_end == "housing" else self.air_node
        nodes = {"shaft_oil": "sump", "shaft_air": self.air_node, "shaft_end_oil": "sump",
                 "shaft_end_air": air_end_node, "lip_oil": "sump", "seal_oil": "sump",
                 "seal_air": self.air_node, "seal_housing": "housing",
                 "shaft_pocket": "air_pocket", "seal_pocket": "air_pocket"}
        self.network = ThermalNetwork(self.grid.conduction, lumped, fixed,
                                      {g: (faces, nodes[g]) for g, faces in
                                       self.grid.face_groups.items()})
        faces = self.grid.face_groups["shaft_oil"]
        self.shaft_oil_z = self.grid.conduction.boundary.z[faces]
        # the annulus's outer wall: the housing bore from the seal's oil face to the bearing
        # (or the modelled shaft's end), radius R + oil_gap
        in_annulus = self.shaft_oil_z < self.section.oil_face
        if self.bearing_span is not None:
            in_annulus &= self.shaft_oil_z >= self.bearing_span[1]
        radius = seal.shaft_diameter / 2.0
        self.annulus_bore_area = float(
            self.grid.conduction.boundary.area[faces][in_annulus].sum()
            * (radius + self.oil_gap) / radius) if env.shaft_oil_convection == "annulus" else 0.0
        self.links = [
            Link("sump", "housing", env.oil_housing_heat_transfer * wetted),
            Link("housing", "ambient", env.housing_heat_transfer * housing_area),
        ]

    # -- convection ------------------------------------------------------------------------
    def coefficients(self, angular_speed: float, sump_temperature: float) -> dict:
        """Heat transfer coefficients [W/(m² K)] of every face group (scalar or per face).

        Shaft in oil, on the wetted fraction of the circumference: between the seal and the
        bearing, Taylor–Couette flow in the annulus between shaft and housing bore
        (``environment.shaft_oil_convection = "annulus"``, gap ``oil_gap``; the correlation's
        h is across the gap, so the shaft's layer to the oil is
        :func:`~sealsim.thermal.convection.annulus_wall_coefficient` of it and the oil's layer
        to the bore, ``annulus_bore`` [W/(m² K) of bore area, wetted fraction], links the sump
        to the housing in :meth:`matrices`) or a cylinder in a
        quiescent bath (``"open"``, Kays & Bjorklund); from the bearing on, in the gear case,
        always the open bath; oil at the sump temperature; on the rest of the circumference
        gearbox air at sump temperature.  Shaft in air: rotating cylinder (Kays & Bjorklund) in
        the air of the air side (``environment.air_side``: the room's air at the ambient
        temperature, or a motor adapter's air at the housing temperature, its properties taken
        at a held housing's temperature, else at the sump's, which a lumped housing follows
        within about 10 K);
        all never below free convection (Churchill & Chu, ΔT = 10 K).  Shaft ends
        (``environment.shaft_oil_end`` / ``shaft_air_end``): held at the sump or housing
        temperature (:data:`END_CONTACT`), a semi-infinite rotating fin √(4·h·k/d) (in the
        sump: the open-bath coefficient; in air: the air side's), or insulated.  Seal surfaces: a
        fraction of the shaft's coefficient (``[thermal]``), the lip's oil side times the lip
        style's heat exchange factor.
        """
        env, th = self.case.environment, self.case.thermal
        d = self.case.seal.shaft_diameter
        omega = abs(angular_speed)
        ts = sump_temperature
        nu_o = float(self.oil.kinematic_viscosity(ts))
        k_o = float(self.oil.thermal_conductivity(ts))
        rho_c = float(self.oil.density(ts) * self.oil.specific_heat(ts))
        alpha_o = k_o / rho_c
        free = float(free_convection_horizontal_cylinder(d, FREE_CONVECTION_DELTA_T, nu_o,
                                                         alpha_o, k_o, self.oil.thermal_expansion))
        h_open = max(float(rotating_cylinder_coefficient(omega, d, nu_o, k_o, nu_o / alpha_o)),
                     free)
        if env.shaft_oil_convection == "annulus":
            # Staton & Cavagnino's h is across the gap, shaft to bore; the oil between is the
            # sump node, so each wall has its own layer to it (the bore's: annulus_bore; where
            # free convection is the floor, the same on both walls)
            across = float(rotating_annulus_coefficient(omega, d, self.oil_gap, nu_o, k_o,
                                                        nu_o / alpha_o))
            h_near = max(annulus_wall_coefficient(across, d, self.oil_gap), free)
        else:
            h_near = h_open

        def h_air_at(temperature):
            nu_a, alpha_a, k_a, pr_a = (float(x) for x in air_properties(temperature))
            return max(float(rotating_cylinder_coefficient(omega, d, nu_a, k_a, pr_a)),
                       float(free_convection_horizontal_cylinder(
                           d, FREE_CONVECTION_DELTA_T, nu_a, alpha_a, k_a, 1.0 / temperature)))

        phi = env.oil_level_wetting
        h_gearbox_air = (1.0 - phi) * h_air_at(ts)
        h_shaft_near = phi * h_near + h_gearbox_air
        h_shaft_case = phi * h_open + h_gearbox_air
        h_shaft_oil = h_shaft_near
        if self.bearing_span is not None:  # in the gear case from the bearing on
            h_shaft_oil = np.where(self.shaft_oil_z < self.bearing_span[1], h_shaft_case,
                                   h_shaft_near)
        adapter_air = env.housing_temperature if env.housing_temperature is not None else ts
        h_air = h_air_at(adapter_air if env.air_side == "adapter" else env.ambient_temperature)
        k_shaft = env.shaft_conductivity
        ends = {"sump": END_CONTACT, "housing": END_CONTACT, "insulated": 0.0}
        return {
            "shaft_oil": h_shaft_oil,
            "shaft_air": h_air,
            "shaft_end_oil": ends.get(env.shaft_oil_end,
                                      math.sqrt(4.0 * h_shaft_case * k_shaft / d)),
            "shaft_end_air": ends.get(env.shaft_air_end, math.sqrt(4.0 * h_air * k_shaft / d)),
            "lip_oil": th.seal_oil_factor * h_shaft_near * self.style.lip_heat_exchange_factor,
            "seal_oil": th.seal_oil_factor * h_shaft_near,
            "seal_air": th.seal_air_factor * h_air,
            "seal_housing": th.seal_housing_contact,
            "shaft_pocket": h_air,
            "seal_pocket": th.seal_air_factor * h_air,
            "annulus_bore": phi * h_near if env.shaft_oil_convection == "annulus" else 0.0,
        }

    def assemble(self, angular_speed: float, sump_temperature: float):
        """Network matrices (K, F) at this speed and sump temperature (:meth:`matrices`)."""
        return self.matrices(angular_speed, sump_temperature)[:2]

    def matrices(self, angular_speed: float, sump_temperature: float) -> tuple:
        """Network matrices (K, F) at this speed and sump temperature, and the face
        conductances they were assembled from (for :meth:`heat_paths`).

        The air pocket exchanges with the air side's air (:attr:`air_node`) through its
        annular opening with the shaft's air-side coefficient; the oil in the annulus with the
        housing bore around it (``annulus_bore`` of :meth:`coefficients` times
        :attr:`annulus_bore_area`).
        """
        h = self.coefficients(angular_speed, sump_temperature)
        pocket = Link("air_pocket", self.air_node,
                      h["shaft_air"] * self.grid.pocket_opening_area)
        bore = Link("sump", "housing", h["annulus_bore"] * self.annulus_bore_area)
        conductances = self.network.face_conductances(h)
        return (*self.network.assemble_faces(conductances, [*self.links, pocket, bore]),
                conductances)

    def fixed_temperatures(self) -> np.ndarray:
        env = self.case.environment
        values = {"ambient": env.ambient_temperature, "sump": env.sump_temperature,
                  "housing": env.housing_temperature}
        return np.array([values[n] for n in self.network.fixed_names], dtype=float)

    def source(self, power: float) -> np.ndarray:
        """Heat source vector: ``power`` [W] spread over the contact band of the shaft."""
        s = np.zeros(self.network.n)
        s[self.grid.contact_cells] = power * self.grid.contact_weights
        return s

    def bearing_temperature(self, temperatures: np.ndarray) -> float:
        """Operating temperature of the bearing beside the seal [K]: the mean of its inner
        ring, the shaft surface under it, and its outer ring, the housing it sits in (the sump
        temperature without a bearing).

        Palmgren's moment takes the oil's viscosity at the bearing's operating temperature
        (Harris & Kotzalas 2007, ch. 9), not at the sump's: the bearing's own friction heats
        its rings, and the thinner oil there limits that heat.  At the sump's temperature a
        cold oil would feed the shaft without that limit (VG 68 with the sump held at 0 °C:
        285 W at 1000 rpm on 80 mm, a contact hotter than with a 20 °C sump)."""
        probe, held = self._bearing_probe
        return float(probe @ temperatures) + held

    @cached_property
    def _bearing_probe(self) -> tuple[np.ndarray, float]:
        """T_bearing = probe·T + held [K]: the weights of the network's temperatures in
        :meth:`bearing_temperature` and the part of the held nodes (housing, sump)."""
        probe, held = np.zeros(self.network.n), 0.0
        nodes, env = self.network.node_index, self.case.environment
        if self.grid.bearing_cells.size:
            probe[self.grid.bearing_cells] = 0.5 * self.grid.bearing_weights
            if env.housing_temperature is None:
                probe[nodes["housing"]] = 0.5
            else:
                held = 0.5 * float(env.housing_temperature)
        elif self.sump_fixed:
            held = float(env.sump_temperature)
        else:
            probe[nodes["sump"]] = 1.0
        return probe, held

    def heat_feedback(self) -> tuple[np.ndarray, np.ndarray]:
        """The two heats that depend on the temperatures, as the network sees them: unit
        sources (n × 2: the seal's friction on the contact band, :meth:`source`; the bearing's,
        :meth:`bearing_source`) and the linear parts of the temperatures they depend on
        (n × 2 probes: the contact-band mean, :meth:`contact_temperature`; the bearing's
        temperature, :meth:`bearing_temperature`, whose held housing is a constant)."""
        probes = np.zeros((self.network.n, 2))
        probes[self.grid.contact_cells, 0] = self.grid.contact_weights
        probes[:, 1] = self._bearing_probe[0]
        return np.stack([self.source(1.0), self.bearing_source(1.0)], axis=1), probes

    def bearing_heat(self, angular_speed: float, temperatures: np.ndarray) -> float:
        """Friction heat of the bearing beside the seal [W] at the network's temperatures
        (:func:`bearing_heat` at :meth:`bearing_temperature`)."""
        return bearing_heat(self.case, self.oil, angular_speed,
                            self.bearing_temperature(temperatures))

    def bearing_source(self, heat: float) -> np.ndarray:
        """Heat source vector of the bearing's friction heat [W] (:meth:`bearing_heat`): its
        shaft share spread over the shaft under the inner ring, the rest into the housing (a
        lumped node) or, with a held housing, into the sump node when that is lumped (else it
        leaves with the held nodes)."""
        s = np.zeros(self.network.n)
        if heat == 0.0:
            return s
        share = self.case.environment.bearing.shaft_share
        s[self.grid.bearing_cells] = heat * share * self.grid.bearing_weights
        for node in ("housing", "sump"):
            if node in self.network.node_index:
                s[self.network.node_index[node]] += heat * (1.0 - share)
                break
        return s

    #: Face groups of each heat path out of shaft and seal (:meth:`heat_paths`)
    HEAT_PATHS = {"oil_side": ("shaft_oil", "shaft_end_oil", "lip_oil", "seal_oil"),
                  "housing": ("seal_housing",),
                  "air_side": ("shaft_air", "seal_air", "shaft_end_air", "shaft_pocket",
                               "seal_pocket")}

    def heat_paths(self, temperatures: np.ndarray, conductances: dict) -> dict[str, float]:
        """Heat [W] leaving shaft and seal by each path: ``oil_side`` (the shaft and the
        seal's faces into the oil and the gear case, the shaft's continuation in the sump),
        ``housing`` (through the seal's outer diameter into its bore) and ``air_side`` (the
        air-side shaft, the seal's air face and the air pocket under it, and the shaft's end
        there: coupling or motor shaft).  In a steady state they add up to the seal's
        friction heat plus the bearing's shaft share.  ``conductances``: the network's
        :meth:`~sealsim.thermal.conduction.ThermalNetwork.face_conductances` of the
        :meth:`coefficients` the temperatures were solved with."""
        groups = self.network.group_heat(temperatures, self.fixed_temperatures(), conductances)
        return {path: sum(groups[g] for g in names) for path, names in self.HEAT_PATHS.items()}

    def contact_temperature(self, temperatures: np.ndarray) -> float:
        return float(temperatures[self.grid.contact_cells] @ self.grid.contact_weights)

    def sump_temperature(self, temperatures: np.ndarray) -> float:
        if self.sump_fixed:
            return float(self.case.environment.sump_temperature)
        return float(temperatures[self.network.node_index["sump"]])

    def housing_temperature(self, temperatures: np.ndarray) -> float:
        held = self.case.environment.housing_temperature
        if held is not None:
            return float(held)
        return float(temperatures[self.network.node_index["housing"]])

    def watched_temperatures(self, temperatures: np.ndarray) -> np.ndarray:
        """Contact, spring groove, sump and housing temperatures [K] (steady-state check)."""
        return np.array([self.contact_temperature(temperatures),
                         temperatures[self.grid.groove_cell],
                         self.sump_temperature(temperatures),
                         self.housing_temperature(temperatures)])


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

    With ``duty.until_steady`` the last speed is held after the cycle until every temperature
    (contact, spring groove, sump, housing) changes slower than ``duty.steady_rate`` for
    :data:`STEADY_WINDOW`, at most until ``duty.max_duration``; the last step then ends there.
    A run whose film leaves the measured range of lip seal films gets a note and one
    :class:`~sealsim.tribology.film.FilmRangeWarning`.

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
    times, speeds, steps = case.duty_cycle().profile(base_dir)
    end = float(times[-1])
    extend = case.duty.until_steady
    limit = max(float(case.duty.max_duration), end) if extend else end
    breaks = np.unique(times)
    num = case.numerics
    feedback_sources, feedback_probes = model.heat_feedback()
    stepper = BackwardEulerStepper(model.network, feedback_sources=feedback_sources,
                                   feedback_probes=feedback_probes)
    feedback_totals = feedback_sources.sum(axis=0)   # W in the network per W of each heat
    temps = np.full(model.network.n, model.start_temperature)
    fixed = model.fixed_temperatures()
    capacity = model.network.capacity
    stored0 = capacity @ temps
    watched = model.watched_temperatures

    rows: list[tuple] = []
    t = 0.0
    t_contact = model.contact_temperature(temps)
    dt = num.min_time_step
    generated = generated_bearing = dissipated = 0.0
    notes: list[str] = []
    k_break = 1
    last_report = -1.0
    calm_since, steady = None, False
    # (ω, T, heat) of the last evaluation of the friction (T_contact) and of the bearing
    # (T_bearing): their secants are the slopes of the linearly implicit step
    last, friction_slope, last_bearing, bearing_slope = None, 0.0, None, 0.0
    # a step's row holds the temperatures at its end and the friction there (the heat the
    # linearly implicit step applied), so each row waits for the next step's evaluation
    pending = None

    def finish(step: tuple, state: FrictionState | None, bearing: float | None) -> tuple:
        t1, omega, temps, t_contact, payload = step
        if state is None:
            state = friction_at(omega, t_contact, t1)
        if bearing is None:
            bearing = model.bearing_heat(omega, temps)
        return _row(model, state, t1, omega, temps, t_contact, payload, bearing)

    def friction_at(omega: float, t_contact: float, t1: float) -> FrictionState:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
                return model.friction.evaluate(omega, t_contact)
        except InputError as exc:
            raise ModelError(f"rotary simulation stopped at t = {t1:.1f} s "
                             f"({omega * 30 / math.pi:.0f} rpm, contact temperature "
                             f"{t_contact - ZERO_CELSIUS_K:.1f} degC): {exc}") from None

    while t < end - 1e-9 or (extend and not steady and t < limit - 1e-9):
        while k_break < len(breaks) and breaks[k_break] <= t + 1e-9:
            k_break += 1
        t_next_break = breaks[k_break] if k_break < len(breaks) else limit
        ramping = abs(_speed_profile(times, speeds, t_next_break - 1e-9)
                      - _speed_profile(times, speeds, t + 1e-9)) > 1e-9
        h = min(dt, t_next_break - t)
        if ramping:
            h = min(h, max((t_next_break - t) / 10.0, num.min_time_step))
        t1 = t + h
        omega = _speed_profile(times, speeds, t1 - 1e-12 if t1 >= t_next_break else t1)
        t_sump = model.sump_temperature(temps)
        state = friction_at(omega, t_contact, t1)
        power = float(state.power)
        t_bearing = model.bearing_temperature(temps)
        bearing_w = bearing_heat(case, model.oil, omega, t_bearing)
        if pending is not None:  # the last step's row: the heats at its end
            same = pending[1] == omega
            rows.append(finish(pending, state if same else None, bearing_w if same else None))
        # the heats' slopes for the linearly implicit step: from the last evaluation at the
        # same speed (a secant), else from a 1 K difference
        if last is not None and last[0] == omega and abs(t_contact - last[1]) > 1e-6:
            friction_slope = (power - last[2]) / (t_contact - last[1])
        elif last is None or last[0] != omega:
            friction_slope = float(friction_at(omega, t_contact + 1.0, t1).power) - power
        last = (omega, t_contact, power)
        if (last_bearing is not None and last_bearing[0] == omega
                and abs(t_bearing - last_bearing[1]) > 1e-6):
            bearing_slope = (bearing_w - last_bearing[2]) / (t_bearing - last_bearing[1])
        elif last_bearing is None or last_bearing[0] != omega:
            bearing_slope = bearing_heat(case, model.oil, omega, t_bearing + 1.0) - bearing_w
        last_bearing = (omega, t_bearing, bearing_w)
        key = (round(math.log1p(abs(omega)) / 0.02), round(t_sump / 2.0))
        before = watched(temps) if extend else None
        bearing = model.bearing_source(bearing_w)
        # the face conductances ride with the factorisation: the heat paths of the row are
        # those of the matrices the step was solved with
        temps, heat_out = stepper.step(temps, h, model.source(power) + bearing, fixed, key,
                                       lambda o=omega, s=t_sump: model.matrices(o, s),
                                       slopes=np.array([friction_slope, bearing_slope]))
        if not np.all(np.isfinite(temps)):
            raise ModelError(f"rotary simulation: temperatures became non-finite at t = {t1:.1f} s")
        added = feedback_totals * stepper.feedback_heat
        generated += (power + added[0]) * h
        generated_bearing += (float(bearing.sum()) + added[1]) * h
        dissipated += heat_out
        t_contact = model.contact_temperature(temps)
        pending = (t1, omega, temps, t_contact, stepper.payload)
        t = t1
        if extend and t >= end - 1e-9:
            calm = float(np.max(np.abs(watched(temps) - before))) / h < case.duty.steady_rate
            calm_since = (t - h if calm_since is None else calm_since) if calm else None
            steady = calm_since is not None and t - calm_since >= STEADY_WINDOW
        at_break = abs(t - t_next_break) < 1e-9
        jump = at_break and abs(_speed_profile(times, speeds, t + 1e-9)
                                - _speed_profile(times, speeds, t - 1e-9)) > 1e-9
        dt = num.min_time_step if jump else min(max(dt, h) * 1.5, num.max_time_step)
        if progress is not None and t - last_report >= end / 100:
            progress(t, max(end, t))
            last_report = t
    if pending is not None:
        rows.append(finish(pending, None, None))
    if progress is not None:
        progress(t, t)
    if extend:
        steps = [*steps[:-1], (steps[-1][0], t)]
        notes.append(f"held {omega * 30 / math.pi:.0f} rpm for {(t - end) / 60:.1f} min after "
                     f"the cycle: " + (
                         f"steady (all temperatures change < "
                         f"{case.duty.steady_rate * 60:g} K/min)" if steady else
                         f"NOT steady by duty.max_duration = {limit:g} s"))

    frame = pd.DataFrame(rows, columns=TIMESERIES_COLUMNS)
    start = np.full(model.network.n, model.start_temperature)
    omega0, sump0 = float(speeds[0]), model.sump_temperature(start)
    first = _row(model, model.friction.evaluate(omega0, model.start_temperature), 0.0, omega0,
                 start, model.start_temperature,
                 model.network.face_conductances(model.coefficients(omega0, sump0)),
                 model.bearing_heat(omega0, start))
    frame = pd.concat([pd.DataFrame([first], columns=TIMESERIES_COLUMNS), frame],
                      ignore_index=True)

    stored = float(capacity @ temps - stored0)
    heat_in = generated + generated_bearing
    energy = {"generated": generated, "generated_bearing": generated_bearing, "stored": stored,
              "dissipated": dissipated,
              "rel_error": abs(heat_in - stored - dissipated) / max(abs(heat_in), 1e-12)}
    sliding = frame.loc[frame["speed_rpm"] != 0, "film_um"]
    found = operating_notes(case, model.elastomer, frame["T_contact_C"], sliding,
                            frame["T_sump_C"], frame["T_housing_C"])
    notes += found
    for film in (n for n in found if n.startswith("film ")):
        warnings.warn(film, FilmRangeWarning, stacklevel=2)
    mounting = lip_note(model.case, frame["T_contact_C"].min() + ZERO_CELSIUS_K)
    if mounting:
        notes.append(mounting)
    result = RotaryResult(case, frame, _step_summary(frame, steps, speeds, times), energy, notes,
                          {"time_steps": len(rows), "factorisations": stepper.factorisations,
                           "thermal_nodes": model.network.n_cells})
    return result


def operating_notes(case: RotaryCase, elastomer, contact_temperatures_c, sliding_films_um,
                    sump_temperatures_c=(), housing_temperatures_c=()) -> list[str]:
    """Where a run left the range of its models: a contact above the elastomer's service
    limit or outside the FE lip table's temperatures (``lip.force`` or ``lip.contact_width =
    "fe"``: held at its end values), a sump below the oil's lowest usable temperature (its
    viscosity law extrapolated),
    films outside the measured range of lip seal films
    (:func:`~sealsim.tribology.film.film_range_note`); and a result that looks wrong but is
    not: a contact below a held sump, with the cause (the housing colder than the oil that
    the held sump's heat leaves through, :data:`BELOW_HELD_SUMP`).  The notes of
    ``sealsim rotary run`` and of :func:`sealsim.lip_seal_torque` (one set per call, over all
    its points); the lip's mounting path has its own note (:func:`lip_note`).

    Parameters
    ----------
    case : RotaryCase
    elastomer : Elastomer
        The lip's elastomer (``RotaryModel.elastomer``).
    contact_temperatures_c : array_like
        Contact temperatures of the run [°C].
    sliding_films_um : array_like
        Films of the samples with the shaft turning [µm] (may be empty).
    sump_temperatures_c : array_like
        Sump temperatures of the run [°C] (may be empty).
    housing_temperatures_c : array_like
        Housing temperatures of the run [°C] (may be empty).
    """
    contact = np.asarray(contact_temperatures_c, dtype=float)
    films = np.asarray(sliding_films_um, dtype=float)
    sump = np.asarray(sump_temperatures_c, dtype=float)
    housing = np.asarray(housing_temperatures_c, dtype=float)
    notes = []
    held = case.environment.sump_temperature
    if held is not None and contact.size and \
            contact.min() < held - ZERO_CELSIUS_K - BELOW_HELD_SUMP:
        held_c = held - ZERO_CELSIUS_K
        where = (f" (down to {housing.min():.1f} degC)" if housing.size else "")
        notes.append(
            f"contact down to {contact.min():.1f} degC, {held_c - contact.min():.1f} K below the "
            f"sump held at {held_c:.1f} degC: the heat that holds the sump leaves through the "
            f"housing{where}, so the housing and the air side are colder than the oil, and a "
            "seal with little friction runs between them; environment.housing_temperature "
            "holds the housing (a gear case whose walls are at the oil's temperature)")
    oil = case.oil.build()
    if sump.size and oil.min_temperature is not None and \
            sump.min() < oil.min_temperature - ZERO_CELSIUS_K:
        notes.append(f"sump cooled to {sump.min():.1f} degC, below the lowest usable "
                     f"temperature of {oil.name} ({oil.min_temperature - ZERO_CELSIUS_K:.1f} "
                     "degC): its viscosity is extrapolated there and the torque means little")
    lip = case.lip
    if "fe" in (lip.force, lip.contact_width):
        # the FE lip table holds its end values outside its grid (LipForceTable)
        low, high = (float(t) - ZERO_CELSIUS_K for t in (lip.temperatures[0],
                                                         lip.temperatures[-1]))
        if contact.max() > high + 0.05 or contact.min() < low - 0.05:
            notes.append(f"contact temperature {contact.min():.0f} ... {contact.max():.0f} degC "
                         f"left the FE lip table's {low:.0f} ... {high:.0f} degC: the lip force "
                         "and contact width are held at the table's end values there; extend "
                         "lip.temperatures to cover it")
    service_max = elastomer.service_range[1] - ZERO_CELSIUS_K
    if contact.max() > service_max:
        notes.append(f"contact temperature reached {contact.max():.0f} degC, above the service "
                     f"limit of {elastomer.name} ({service_max:.0f} degC)")
    if films.size:
        film = film_range_note(films.min() * 1e-6, films.max() * 1e-6)
        if film:
            notes.append(film)
    return notes


def _row(model: RotaryModel, state: FrictionState, t, omega, temps, t_contact,
         conductances, bearing_heat) -> tuple:
    """One timeseries row; the heat paths with the face conductances of the step, the
    bearing's heat [W] into the shaft (its shaft share)."""
    torque = float(state.torque)
    lip_force = float(state.lip_force)
    mu_eff = abs(torque) * 2 / model.case.seal.shaft_diameter / lip_force
    g = float(model.friction.duty_parameter(state, omega))
    return (t, omega * 30 / math.pi, torque, float(state.power), t_contact - ZERO_CELSIUS_K,
            float(temps[model.grid.groove_cell]) - ZERO_CELSIUS_K,
            model.sump_temperature(temps) - ZERO_CELSIUS_K, float(state.film) * 1e6,
            float(state.force_lubricant), float(state.force_material),
            model.housing_temperature(temps) - ZERO_CELSIUS_K, lip_force, mu_eff,
            float(state.film_ratio), g,
            bearing_heat * model.case.environment.bearing.shaft_share,
            *model.heat_paths(temps, conductances).values())


#: The validation convention of Organisciak et al. (2014): average over the last 30 s of each
#: speed step.
AVERAGING_WINDOW = 30.0


def _step_summary(frame: pd.DataFrame, steps, speeds, times) -> list[dict]:
    out = []
    t = frame["time_s"].to_numpy()
    for start, stop in steps:
        lo = max(start, stop - AVERAGING_WINDOW)
        entry = {"start_s": float(start), "end_s": float(stop),
                 "speed_rpm": round(float(np.interp(stop - 1e-9, times, speeds)) * 30 / math.pi,
                                    6)}
        for column in ("torque_Nm", "power_W", "T_contact_C", "T_groove_C", "T_sump_C",
                       "heat_oil_side_W", "heat_housing_W", "heat_air_side_W"):
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


def steady_state(case: RotaryCase, angular_speed: float, tol: float = 1e-8,
                 max_iter: int = 100) -> dict:
    """Steady operating point at constant speed: friction and temperatures in equilibrium.

    Solves K(T_sump)·T = F·T_fixed + e·P(ω, T_contact) + b·Q(ω, T_bearing) for the temperatures
    T (e spreads the friction power P over the contact band, b the bearing's heat Q over the
    shaft under its inner ring and the housing; K depends on the sump temperature through the
    oil's convection coefficients).  The network matrix K₀ is factorised once, at the start
    temperature, and reused: each iteration solves K₀·δ = r for the residual
    r = F·T_fixed + e·P + b·Q − K(T_sump)·T (a chord iteration; Kelley, *Iterative Methods for
    Linear and Nonlinear Equations*, SIAM 1995, ch. 5).  The heats' feedback enters through the
    Woodbury formula with the secant slopes of the last two iterates of the two heats that
    depend on the temperatures, the seal's friction P(T_contact) and the bearing's heat
    Q(T_bearing) (source b, :meth:`RotaryModel.bearing_temperature`):
    δ = x + U·S·a with x = K₀⁻¹r, U = K₀⁻¹[e b], S = diag(s_P, s_Q) and (I − C(U)·S)·a = C(x),
    C(·) the contact-band mean and the bearing temperature's linear part (with only the friction
    the Sherman–Morrison formula δ = x + u·s·c(x)/(1 − s·c(u))), so the couplings converge
    like a secant method instead of a fixed-point sweep.
    Only when a free sump heats far from the temperature of the factorisation and the
    iteration slows down (:data:`STALE_CONTRACTION`) is the matrix factorised anew.

    Parameters
    ----------
    case : RotaryCase
        The case (its duty cycle is ignored).
    angular_speed : float
        ω [rad/s].
    tol : float
        Convergence tolerance on the contact and sump temperature updates [K].
    max_iter : int
        Most iterations before a :class:`~sealsim.errors.ModelError`.

    Returns
    -------
    dict
        torque_Nm, power_W, T_contact_C, T_groove_C, T_sump_C, T_housing_C, film_um, F_lub_N,
        F_material_N, lip_force_N, mu_dry, asperity_share, bearing_power_W (friction heat of
        the bearing beside the seal), heat_oil_side_W, heat_housing_W, heat_air_side_W (where
        the heat leaves shaft and seal, :meth:`RotaryModel.heat_paths`), iterations,
        lip_note (which mounting case the lip
        force is when the lip runs colder than it was mounted, else "").  A film outside the
        measured range of lip seal films gives a
        :class:`~sealsim.tribology.film.FilmRangeWarning`.
    """
    model = RotaryModel(case)
    fixed = model.fixed_temperatures()
    temps = np.full(model.network.n, model.start_temperature)
    # the seal's friction (on the contact band) and the bearing's heat (inner ring, housing)
    unit_sources, probes = model.heat_feedback()

    def factorised(k):
        lu = factorise(k)
        responses = np.stack([lu.solve(unit_sources[:, j]) for j in range(2)], axis=1)
        return lu, responses, probes.T @ responses

    factorised_at = model.sump_temperature(temps)
    k, f = model.assemble(angular_speed, factorised_at)
    lu, responses, coupling = factorised(k)

    rubber = model.friction.elastomer
    lowest, highest = rubber.allowed_range

    def friction_at(t_contact: float) -> FrictionState:
        # an iterate may overshoot the rubber's temperature range on its way: its friction is
        # taken at the range's end; a steady state outside the range is refused below
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
                return model.friction.evaluate(angular_speed,
                                               min(max(t_contact, lowest), highest))
        except InputError as exc:
            raise ModelError(f"steady state at {angular_speed * 30 / math.pi:.0f} rpm: contact "
                             f"temperature {t_contact - ZERO_CELSIUS_K:.1f} degC: {exc}") from None

    def heats(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(contact, bearing temperature), (friction power, bearing heat) at x."""
        where = np.array([model.contact_temperature(x), model.bearing_temperature(x)])
        return where, np.array([float(friction_at(where[0]).power),
                                bearing_heat(case, model.oil, angular_speed, where[1])])

    sump = None if model.sump_fixed else model.network.node_index["sump"]
    remedy = ("a lower speed or another elastomer" if model.sump_fixed else
              "a lower speed, a held sump (environment.sump_temperature) or a housing "
              "that sheds more heat (environment.housing_area, housing_heat_transfer)")
    # the first slopes from a 1 K difference, then secants through the iterates
    try:
        previous = heats(temps + 1.0)
        slopes, converged, last_update, stale = np.zeros(2), False, np.inf, False
        for iteration in range(1, max_iter + 1):
            where, power = heats(temps)
            moved = where != previous[0]
            slopes[moved] = (power - previous[1])[moved] / (where - previous[0])[moved]
            previous = (where, power)
            if sump is not None:  # the oil's coefficients follow the sump temperature
                k, f = model.assemble(angular_speed, temps[sump])
                if stale and abs(temps[sump] - factorised_at) > STALE_SUMP_CHANGE:
                    factorised_at = temps[sump]
                    lu, responses, coupling = factorised(k)
            step = lu.solve(f @ fixed + unit_sources @ power - k @ temps)
            # Woodbury: the heats' feedback (P + s·Δ) through the two probes, (I − C·S)·a = C(x)
            system = np.eye(2) - coupling * slopes[None, :]
            if np.linalg.det(system) > 0.1:  # else a heat outgrows the network's cooling
                step += responses @ (slopes * np.linalg.solve(system, probes.T @ step))
            temps += step
            if not np.all(np.isfinite(temps)):
                break
            update = max(abs(model.contact_temperature(step)),
                         0.0 if sump is None else abs(step[sump]))
            if update < tol:
                converged = True
                break
            stale, last_update = update > STALE_CONTRACTION * last_update, update
    except InputError:  # an iterate took the oil beyond its property model's range
        raise ModelError(
            f"steady state at {angular_speed * 30 / math.pi:.0f} rpm: none found; on the way "
            f"the oil at the bearing or in the sump passed "
            f"{OIL_T_RANGE[1] - ZERO_CELSIUS_K:.0f} degC, the end of the oil model's range "
            f"(the contact's limit with {rubber.name}: {highest - ZERO_CELSIUS_K:.0f} degC); "
            f"try {remedy}") from None
    if not converged:
        raise ModelError(f"steady state at {angular_speed * 30 / math.pi:.0f} rpm did not "
                         f"converge in {max_iter} iterations")
    t_contact = model.contact_temperature(temps)
    t_sump = model.sump_temperature(temps)
    if not lowest <= t_contact <= highest:
        raise ModelError(
            f"steady state at {angular_speed * 30 / math.pi:.0f} rpm: the contact would run at "
            f"about {t_contact - ZERO_CELSIUS_K:.0f} degC (sump {t_sump - ZERO_CELSIUS_K:.0f} "
            f"degC), "
            f"outside the {lowest - ZERO_CELSIUS_K:.0f} to {highest - ZERO_CELSIUS_K:.0f} degC "
            f"that the {rubber.name} model covers (service limit "
            f"{rubber.service_range[1] - ZERO_CELSIUS_K:.0f} degC): the seal has no steady "
            f"state there; try {remedy}")
    oil = model.oil
    if not model.sump_fixed and oil.min_temperature is not None and t_sump < oil.min_temperature:
        raise ModelError(
            f"steady state at {angular_speed * 30 / math.pi:.0f} rpm: the free sump would "
            f"settle at {t_sump - ZERO_CELSIUS_K:.1f} degC, below the lowest usable temperature "
            f"of {oil.name} ({oil.min_temperature - ZERO_CELSIUS_K:.1f} degC), where its "
            "viscosity law no longer holds; try a warmer ambient, a held sump "
            "(environment.sump_temperature) or an oil for lower temperatures")
    state = friction_at(t_contact)
    film = float(state.film)
    paths = model.heat_paths(temps, model.network.face_conductances(
        model.coefficients(angular_speed, t_sump)))
    if angular_speed != 0 and film_range_note(film, film):
        warnings.warn(film_range_note(film, film), FilmRangeWarning, stacklevel=2)
    return {"torque_Nm": float(state.torque), "power_W": float(state.power),
            "T_contact_C": t_contact - ZERO_CELSIUS_K,
            "T_groove_C": float(temps[model.grid.groove_cell]) - ZERO_CELSIUS_K,
            "T_sump_C": t_sump - ZERO_CELSIUS_K,
            "T_housing_C": model.housing_temperature(temps) - ZERO_CELSIUS_K, "film_um": film * 1e6,
            "F_lub_N": float(state.force_lubricant), "F_material_N": float(state.force_material),
            "lip_force_N": float(state.lip_force), "mu_dry": float(state.mu_dry),
            "asperity_share": float(state.asperity_share),
            "bearing_power_W": model.bearing_heat(angular_speed, temps),
            **{f"heat_{path}_W": heat for path, heat in paths.items()},
            "iterations": iteration, "lip_note": lip_note(case, t_contact)}


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
        F_lub_N, F_material_N, mu_dry, asperity_share, mu_eff, duty_parameter.
    """
    friction = lip_seal_friction(case)
    n, t = np.meshgrid(np.asarray(speeds_rpm, float), np.asarray(temperatures_c, float))
    omega = n.ravel() * np.pi / 30.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", (ServiceRangeWarning, OilRangeWarning))
        state = friction.evaluate(omega, t.ravel() + ZERO_CELSIUS_K)
    return pd.DataFrame({
        "speed_rpm": n.ravel(), "T_contact_C": t.ravel(), "torque_Nm": state.torque,
        "power_W": state.power, "film_um": state.film * 1e6, "F_lub_N": state.force_lubricant,
        "F_material_N": state.force_material, "mu_dry": state.mu_dry,
        "asperity_share": state.asperity_share,
        "mu_eff": np.abs(state.torque) * 2 / case.seal.shaft_diameter / state.lip_force,
        "duty_parameter": friction.duty_parameter(state, omega)})


def load_rotary_case(path: str | Path) -> dict[str, RotaryCase]:
    """Read and validate a rotary case file; returns ``{variant: RotaryCase}``.

    Relative paths in the case (a duty-cycle CSV) refer to the case file's folder: simulate
    with ``simulate(case, base_dir=Path(path).parent)``.
    """
    path = Path(path)
    return expand_variants(RotaryCase, load_toml(path), f"rotary case {str(path)!r}")
