"""Case description of a rotary lip seal run: seal, oil, environment, duty cycle, numerics.

A case is a TOML file (or the same structure built in Python)::

    [seal]
    shaft_diameter = "80 mm"
    lip_style = "plain"            # plain | wave
    material = "NBR"

    [oil]
    name = "VG68-mineral"

    [environment]
    sump_volume = "0.2 L"
    ambient_temperature = "23 degC"

    [duty]
    steps = [{speed = "100 rpm", duration = "10 min"}, {speed = "1000 rpm", duration = "10 min"}]

    [variants.wave]
    seal.lip_style = "wave"

Every field not given gets the documented default; the resolved case written next to the
results lists them all.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import Field, field_validator, model_validator

from sealsim.cases import CaseModel, Q
from sealsim.errors import InputError
from sealsim.properties.catalogue import DENSITY15, OilEntry
from sealsim.properties.elastomers import get_elastomer, is_compound_file
from sealsim.properties.oils import FAMILIES, Oil, get_oil
from sealsim.rotary.lip import (
    DEFAULT_HOOP_PRESTRAIN,
    DEFAULT_WAVE_AMPLITUDE,
    DEFAULT_WAVES,
    STEEL_EXPANSION,
    default_contact_width,
    default_outer_diameter,
    default_radial_force,
    default_width,
)
from sealsim.rotary.lip_fe import LipSpec
from sealsim.tables import ColumnSpec, read_table
from sealsim.tribology.film import EHL_EXPONENT, FILM_FLOOR, film_coefficient_matching_fit
from sealsim.tribology.rolling_bearing import DEEP_GROOVE_OIL_BATH_F0
from sealsim.tribology.rubber_friction import DEFAULT_ASPERITY_WAVELENGTH, DEFAULT_MASTER_CURVE
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["SETUPS", "Bearing", "DutyCycle", "DutyStep", "Environment", "Friction", "Numerics",
           "OilSpec",
           "RotaryCase", "Seal", "ShaftSetup", "ThermalSpec", "WaveLip"]


class WaveLip(CaseModel):
    """Geometry of a wave lip (used when ``lip_style = "wave"``); see sealsim.rotary.lip."""

    track_amplitude: Q("length", ge=0, le=5e-3) = Field(DEFAULT_WAVE_AMPLITUDE, description=(
        "axial amplitude of the sinusoidal contact line (assumption: 0.5 mm)"))
    waves: float = Field(DEFAULT_WAVES, ge=1, le=200, description=(
        "number of waves around the circumference (assumption: 8)"))
    film_factor: float | None = Field(None, gt=0.5, le=3.0, description=(
        "film thickness relative to a plain lip at the same viscosity and speed; default: "
        "from the inclination of the contact line, 1 + <|sin phi|^0.66>; set it to calibrate"))
    lip_heat_exchange_factor: float = Field(1.0, ge=1.0, le=10.0, description=(
        "multiplier of the lip's oil-side heat transfer (default 1: the oil the wave pumps "
        "carries a negligible heat flow; calibratable)"))


class Seal(CaseModel):
    """The radial lip seal and the shaft surface it runs on."""

    shaft_diameter: Q("length", gt=5e-3, le=1.0)
    outer_diameter: Q("length", gt=0) | None = None
    width: Q("length", gt=1e-3, le=0.1) | None = None
    lip_style: Literal["plain", "wave"] = "plain"
    material: str = "NBR"
    radial_force: Q("force", gt=0, le=1000.0) | None = Field(
        None, description="lip force at radial_force_temperature; default 0.15 N/mm x pi d")
    radial_force_temperature: Q("temperature", gt=200.0, lt=450.0) = 293.15
    mounting_temperature: Q("temperature", gt=200.0, lt=450.0) | None = Field(None, description=(
        "temperature at which the seal was mounted on the shaft and its lip stress relaxed "
        "(held for an hour); a lip cooled below it keeps that stress and only the contraction "
        "increment meets the stiffer cold rubber (rotary/lip.py Eq. 1); default "
        "radial_force_temperature"))
    spring_share: float = Field(0.45, ge=0.0, le=1.0, description=(
        "share of the garter spring in the radial force (typically 30-60 % for a new "
        "DIN 3760 NBR lip; handbook range, not checked against one measured source)"))
    hoop_prestrain: float = Field(DEFAULT_HOOP_PRESTRAIN, gt=0.005, le=0.5, description=(
        "hoop strain of the lip ring stretched onto the shaft (radial interference / shaft "
        "radius) at radial_force_temperature; sets how much interference the rubber's thermal "
        "expansion takes away (estimate: 0.08)"))
    contact_width: Q("length", gt=10e-6, le=3e-3) | None = None
    shaft_roughness: Q("length", gt=0, le=5e-6) = Field(0.3e-6, description=(
        "RMS roughness Rq of the shaft (DIN 3760: Ra 0.2-0.8 um; Rq = 1.25 Ra)"))
    lip_roughness: Q("length", gt=0, le=10e-6) = Field(0.4e-6, description=(
        "RMS roughness of the run-in lip surface"))
    spring_offset: Q("length", ge=-5e-3, le=5e-3) = Field(0.5e-3, description=(
        "axial offset of the garter spring plane from the contact, air side positive"))
    wave: WaveLip = WaveLip()

    @field_validator("material")
    @classmethod
    def _known_material(cls, value: str) -> str:
        name = get_elastomer(value).name
        return value if is_compound_file(value) else name

    @model_validator(mode="after")
    def _defaults(self):
        d = self.shaft_diameter
        values = {}
        if self.outer_diameter is None:
            values["outer_diameter"] = default_outer_diameter(d)
        if self.width is None:
            values["width"] = default_width(d)
        if self.radial_force is None:
            values["radial_force"] = float(default_radial_force(d))
        if self.contact_width is None:
            values["contact_width"] = default_contact_width(d)
        if self.mounting_temperature is None:
            values["mounting_temperature"] = self.radial_force_temperature
        for key, value in values.items():
            object.__setattr__(self, key, value)
        if self.outer_diameter <= d + 4e-3:
            raise ValueError(f"outer_diameter {self.outer_diameter * 1e3:g} mm must exceed the "
                             f"shaft diameter {d * 1e3:g} mm by more than 4 mm")
        return self


class OilSpec(OilEntry):
    """The lubricant: a catalogue name, or your own oil from its datasheet.

    Your own oil gives ``nu40`` and ``nu100`` (or ASTM D341 ``walther_A`` and ``walther_B``)
    and ``density15``, and may give every other field of an oil file (as for ``sealsim oil
    list --oil-file``): ``family`` (default mineral),
    ``min_temperature`` (the datasheet pour point), ``pressure_viscosity_coefficient``,
    ``thermal_conductivity``, ``specific_heat``, ``thermal_expansion``, ``source``.  A
    catalogue oil takes those optional values too, as corrections from your datasheet (e.g.
    ``name = "VG68"`` with ``min_temperature = "-36 degC"``); its viscosities and family are
    the catalogue's.
    """

    name: str = "VG68-mineral"
    family: Literal[FAMILIES] | None = None  # type: ignore[valid-type]
    density15: DENSITY15 | None = None

    @model_validator(mode="after")
    def _one_viscosity_source(self):  # replaces OilEntry's: a catalogue name needs none
        own = [k for k in OWN_OIL_FIELDS if getattr(self, k) is not None]
        nu = [self.nu40 is not None, self.nu100 is not None]
        ab = [self.walther_A is not None, self.walther_B is not None]
        if own and not (self.density15 is not None and (all(nu) and not any(ab)
                                                         or all(ab) and not any(nu))):
            raise ValueError(
                f"{', '.join(own)} given: your own oil needs nu40 and nu100 (or walther_A and "
                "walther_B, not both) and density15; a catalogue oil is given by its name "
                "alone (its optional values, such as min_temperature, may be corrected)")
        if own and "name" not in self.model_fields_set:  # not the default catalogue name
            raise ValueError(f"{', '.join(own)} given: your own oil needs its name, e.g. "
                             "name = \"my gear oil\" (without one it was called "
                             f"{type(self).model_fields['name'].default!r}, a catalogue oil)")
        self.build()  # validates the values (an unknown name lists close matches)
        return self

    def build(self) -> Oil:
        """The :class:`~sealsim.properties.oils.Oil` this spec describes."""
        kwargs = self.oil_arguments()
        kwargs.pop("family")
        if self.density15 is None:  # a catalogue oil, perhaps with datasheet corrections
            oil = get_oil(self.name)
            kwargs.pop("source")
            if not kwargs:
                return oil
            given = [k for k in CORRECTABLE_OIL_FIELDS if getattr(self, k) is not None]
            return replace(oil, **kwargs, source=f"{oil.source.rstrip('.')}; {', '.join(given)} "
                           f"from {self.source or 'the case'}")
        kwargs["family"] = self.family or "mineral"
        if self.source is None:
            kwargs["source"] = "user datasheet values (case file)"
        if self.nu40 is not None:
            return Oil.from_datasheet(self.name, self.nu40, self.nu100, self.density15,
                                      **kwargs)
        return Oil.from_walther(self.name, self.walther_A, self.walther_B, self.density15,
                                **kwargs)


#: Fields of an [oil] table that only your own oil gives (a catalogue oil has them).
OWN_OIL_FIELDS = ("family", "nu40", "nu100", "walther_A", "walther_B", "density15")
#: Fields of an [oil] table that correct a catalogue oil (from your oil's datasheet).
CORRECTABLE_OIL_FIELDS = ("min_temperature", "pressure_viscosity_coefficient",
                          "thermal_conductivity", "specific_heat", "thermal_expansion")


@dataclass(frozen=True)
class ShaftSetup:
    """Defaults of a shaft environment (see :data:`SETUPS`), SI units."""

    shaft_length_oil_side: float | None
    shaft_length_air_side: float
    shaft_oil_end: str
    shaft_air_end: str
    air_side: str
    housing_heat_transfer: float
    bearing: str


#: Shaft environments.  Lengths are measured from the contact line.
#:
#: * ``gearbox``: the seal sits in a bearing cap of a gear unit.  On the oil side the shaft
#:   passes the deep-groove ball bearing beside the seal -- a heat source: Palmgren's friction
#:   of a 62xx bearing of the shaft's bore in the sump oil, half of it into the shaft through
#:   the inner ring (:mod:`sealsim.tribology.rolling_bearing`) -- and continues into the gear
#:   case as a rotating fin in the sump (Kays & Bjorklund's rotating cylinder on the wetted
#:   fraction of the circumference); the modelled shaft reaches a quarter diameter beyond the
#:   bearing, the fin continues from there.  No boundary of fixed temperature on the oil side.
#:   On the air side the shaft leads to the coupling of a motor flanged to the housing (an
#:   industrial gear motor, the application of Organisciak et al. 2014).  Shaft and coupling
#:   turn inside the motor adapter, the closed bell housing (IEC adapter or lantern) bolted
#:   between gear case and motor flange: the air-side shaft, the seal's air face and the air
#:   pocket under the seal exchange heat with the adapter's air, taken at the housing
#:   temperature (the adapter is metal bolted to the housing and shields the shaft from the
#:   room; ``air_side = "ambient"`` for a free input shaft in the room).  50 mm from the
#:   contact the shaft continues through the coupling into the motor as a rotating fin in
#:   that air: the motor's own heat, which warms its shaft, is not known here, so no
#:   temperature is imposed there (``shaft_air_end = "housing"`` holds it at the housing
#:   temperature, ``"insulated"`` makes the motor shaft as warm as the seal's end; the two
#:   bracket the default).
#:   Housing to ambient 12 W/(m² K): radiation 6.3 (grey body, ε = 0.9, a 60 °C wall in a 20 °C
#:   room; 7.6 at 80 °C in a 40 °C room) + free convection 5.2 (Churchill & Chu, a 0.3 m
#:   vertical wall 40 K above ambient), :mod:`sealsim.thermal.convection`.
#: * ``test_rig``: the friction rig of Organisciak et al. (AGMA 14FTM14, 2014): a motor-driven
#:   shaft, the seal in a compact test head with a small oil bath, the friction measured on an
#:   air-bearing spindle (no rolling bearing beside the seal).  30 mm of shaft on each side;
#:   the shaft end in the oil bath and the drive coupling take no heat (insulated); the
#:   air-side shaft in the room's air; bare aluminium test head 6 W/(m² K) (free convection
#:   ≈ 5 + radiation ≈ 1, a bright metal surface with emissivity ≈ 0.1).
SETUPS: dict[str, ShaftSetup] = {
    "gearbox": ShaftSetup(shaft_length_oil_side=None, shaft_length_air_side=0.05,
                          shaft_oil_end="fin", shaft_air_end="fin", air_side="adapter",
                          housing_heat_transfer=12.0, bearing="palmgren"),
    "test_rig": ShaftSetup(shaft_length_oil_side=0.03, shaft_length_air_side=0.03,
                           shaft_oil_end="insulated", shaft_air_end="insulated",
                           air_side="ambient", housing_heat_transfer=6.0, bearing="none"),
}


class Bearing(CaseModel):
    """The rolling bearing beside the seal on the oil side: a heat source in the shaft.

    ``model``: ``"palmgren"`` (Palmgren's load-independent friction of a deep-groove ball
    bearing in the sump oil, :func:`~sealsim.tribology.rolling_bearing.palmgren_viscous_moment`
    at the bearing's operating temperature, the mean of the shaft under its inner ring and the
    housing), ``"power"`` (the heat ``power`` you give, e.g. from a bearing
    catalogue's friction model including the load) or ``"none"``; default from the set-up
    (gearbox: palmgren, test_rig: none).
    """

    model: Literal["palmgren", "power", "none"] | None = None
    power: Q("power", ge=0.0, le=1e5) | None = Field(None, description=(
        "bearing friction heat for model = 'power' [W] (constant)"))
    pitch_diameter: Q("length", gt=0.0, le=2.0) | None = Field(None, description=(
        "pitch diameter d_m; default: the 62xx bearing of the shaft's bore (ISO 15)"))
    width: Q("length", gt=0.0, le=0.5) | None = Field(None, description=(
        "bearing width B; default: the 62xx bearing of the shaft's bore (ISO 15)"))
    f0: float = Field(DEEP_GROOVE_OIL_BATH_F0, gt=0.0, le=20.0, description=(
        "Palmgren's f0 (2: deep-groove ball bearing, oil bath; Harris & Kotzalas 2007)"))
    shaft_share: float = Field(0.5, ge=0.0, le=1.0, description=(
        "share of the bearing heat that enters the shaft through the inner ring; the rest "
        "goes to the housing and the oil (0.5: the heat of the rolling contacts split "
        "equally between the rings, the usual assumption of bearing thermal networks)"))
    gap: Q("length", ge=0.0, le=0.5) = Field(5e-3, description=(
        "axial distance from the seal's oil-side face to the bearing (a shoulder or spacer "
        "in the bearing cap; estimate 5 mm)"))

    @model_validator(mode="after")
    def _power_given(self):
        if self.model == "power" and self.power is None:
            raise ValueError("bearing.model = 'power' needs bearing.power, e.g. '20 W'")
        if self.model != "power" and self.power is not None:
            raise ValueError("bearing.power is used with bearing.model = 'power' only")
        return self


#: Open range [K] of the temperatures a rotary case starts at or holds (environment's
#: start_temperature, sump_temperature, housing_temperature), of the rotary FMU's parameter
#: T_contact_start and of a measured spring-groove temperature (sealsim rotary fit).
CASE_TEMPERATURES = (200.0, 450.0)


class Environment(CaseModel):
    """Oil sump, housing, ambient, shaft.

    ``setup`` chooses the shaft environment (:data:`SETUPS`): its shaft lengths, shaft-end
    conditions and housing heat transfer are the defaults of the fields left out.
    """

    setup: Literal["gearbox", "test_rig"] = Field("gearbox", description=(
        "shaft environment: 'gearbox' (seal in a gear unit's bearing cap: the bearing beside "
        "it heats the shaft, the shaft continues as a rotating fin in the sump, shaft and "
        "coupling turn in a motor adapter at the housing temperature, the motor shaft a fin "
        "in it) or 'test_rig' "
        "(Organisciak et al.'s rig: short shaft, small oil bath, insulated ends)"))
    ambient_temperature: Q("temperature", gt=200.0, lt=400.0) = 293.15
    start_temperature: Q("temperature", gt=CASE_TEMPERATURES[0],
                         lt=CASE_TEMPERATURES[1]) | None = Field(
        None, description="initial temperature of shaft, seal, oil and housing; default: the "
                          "held sump temperature, else ambient")
    sump_volume: Q("volume", gt=1e-6, le=10.0) = 1e-3
    sump_temperature: Q("temperature", gt=CASE_TEMPERATURES[0],
                         lt=CASE_TEMPERATURES[1]) | None = Field(
        None, description="if given, the sump is held at this temperature (thermostat); "
                          "otherwise it heats up from the seal's friction")
    housing_temperature: Q("temperature", gt=CASE_TEMPERATURES[0],
                            lt=CASE_TEMPERATURES[1]) | None = Field(
        None, description="if given, the housing is held at this temperature (a heated test "
                          "head, a gearbox at its operating temperature); otherwise it is a "
                          "heat capacity between sump and ambient")
    oil_level_wetting: float = Field(0.5, ge=0.0, le=1.0, description=(
        "fraction of the shaft circumference under oil on the oil side "
        "(0.5: oil level at the shaft centre, as in the rig of Organisciak et al., AGMA "
        "14FTM14, 2014)"))
    shaft_oil_convection: Literal["annulus", "open"] = Field("annulus", description=(
        "flow around the oil-side shaft: 'annulus' (Taylor-Couette flow in the annular space "
        "between the shaft and the bore the seal sits in -- a bearing cap, a test head -- after "
        "Staton & Cavagnino 2008; its coefficient is across the gap, so the sump's oil sits "
        "between the shaft's and the bore's wall layers) or 'open' (a shaft turning in a large "
        "quiescent oil bath, Kays & Bjorklund)"))
    oil_gap: Q("length", gt=0, le=1.0) | None = Field(None, description=(
        "radial width of that annulus; default: the seal's radial section (the housing bore "
        "of the seal continued on its oil side)"))
    housing_area: Q("area", gt=0) | None = Field(
        None, description="outer housing area to ambient; default: a box twice the sump volume")
    housing_mass: Q("mass", gt=0) | None = Field(
        None, description="housing metal mass; default: 5 mm steel walls of housing_area")
    housing_heat_transfer: Q("heat_transfer_coefficient", gt=0, le=1000.0) | None = Field(
        None, description="housing to ambient; default from the setup (gearbox 12, test_rig 6 "
                          "W/(m2 K))")
    oil_housing_heat_transfer: Q("heat_transfer_coefficient", gt=0, le=10000.0) = Field(
        100.0, description=(
            "oil to the wetted housing wall below the oil level; 100: free convection of still "
            "gear oil on that wall (Churchill & Chu's vertical plate, VG 68 at 75-80 degC, 6 cm "
            "of oil, 11 K: 96-100), the lower end of the 1e2-1e3 W/(m2 K) of splashed walls"))
    shaft_length_oil_side: Q("length", gt=1e-3, le=2.0) | None = Field(
        None, description="modelled shaft from the contact into the oil side; default from the "
                          "setup (gearbox: through the bearing and a quarter diameter beyond "
                          "it; test_rig: 30 mm)")
    shaft_length_air_side: Q("length", gt=1e-3, le=2.0) | None = Field(
        None, description="modelled shaft from the contact to the air-side end; default from "
                          "the setup (gearbox 50 mm, test_rig 30 mm)")
    shaft_oil_end: Literal["sump", "fin", "insulated"] | None = Field(None, description=(
        "beyond shaft_length_oil_side the shaft continues as a rotating fin in the sump (fin: "
        "Kays & Bjorklund's rotating cylinder on the wetted circumference), is held at the sump "
        "temperature (sump), or ends (insulated); default from the setup"))
    shaft_air_end: Literal["housing", "fin", "insulated"] | None = Field(None, description=(
        "beyond shaft_length_air_side the shaft enters a coupling or bearing at the housing "
        "temperature (housing), continues as a rotating fin in the air side's air (fin: "
        "through a coupling into a motor whose temperature is not known), or enters a part "
        "that takes no heat, e.g. a test-rig spindle (insulated); default from the setup "
        "(gearbox: fin, test_rig: insulated)"))
    air_side: Literal["ambient", "adapter"] | None = Field(None, description=(
        "what the air-side shaft, the seal's air face and the air pocket under the seal give "
        "their heat to: the room's air at the ambient temperature (ambient: a free input "
        "shaft, a test rig) or the air inside a closed motor adapter bolted to the housing, "
        "taken at the housing temperature (adapter: a gear motor); default from the setup "
        "(gearbox: adapter, test_rig: ambient)"))
    shaft_conductivity: Q("thermal_conductivity", gt=0) = 45.0
    shaft_density: Q("density", gt=0) = 7850.0
    shaft_specific_heat: Q("specific_heat", gt=0) = 460.0
    shaft_expansion: Q("thermal_expansion", ge=0, le=1e-4) = Field(
        STEEL_EXPANSION, description="linear thermal expansion of the shaft (steel 11-13e-6 1/K)")

    bearing: Bearing = Field(default_factory=Bearing, description=(
        "the rolling bearing beside the seal (a heat source in the shaft)"))

    @model_validator(mode="after")
    def _setup_defaults(self):
        setup = SETUPS[self.setup]
        for item in fields(ShaftSetup):
            if item.name == "bearing":
                if self.bearing.model is None:
                    object.__setattr__(self.bearing, "model", setup.bearing)
            elif getattr(self, item.name) is None:
                object.__setattr__(self, item.name, getattr(setup, item.name))
        return self


class ThermalSpec(CaseModel):
    """Heat transfer coefficients of the seal surfaces relative to the shaft's."""

    seal_oil_factor: float = Field(0.2, gt=0, le=5, description=(
        "seal surfaces in oil: this fraction of the rotating shaft's coefficient; the lip "
        "flanks and the spring cavity sit in the recirculating corner flow beside the seal, "
        "not in the shaft's own boundary layer"))
    seal_air_factor: float = Field(0.5, gt=0, le=5)
    seal_housing_contact: Q("heat_transfer_coefficient", gt=0) = Field(
        2000.0, description="thermal contact of the seal's outer diameter with the bore")


class Friction(CaseModel):
    """Parameters of the friction model (defaults documented in sealsim.tribology)."""

    film_coefficient_um: float = Field(
        round(film_coefficient_matching_fit() * 1e6, 4), gt=0, le=100,
        description="f of h = f (eta u)^0.66 in um/(Pa m)^0.66; default: least-squares match "
                    "to the h = 3.45 (u eta)^0.68 measured by Organisciak "
                    "et al. (SKF, AGMA 14FTM14, 2014)")
    film_exponent: float = Field(EHL_EXPONENT, gt=0.3, lt=1.0)
    film_floor: Q("length", gt=0, le=1e-6) = FILM_FLOOR
    mu_peak: float = Field(DEFAULT_MASTER_CURVE.mu_peak, gt=0, le=5)
    mu_low: float = Field(DEFAULT_MASTER_CURVE.mu_low, ge=0, le=5)
    master_curve_width_decades: float = Field(DEFAULT_MASTER_CURVE.width_decades, gt=0, le=10)
    peak_speed_at_reference: Q("velocity", gt=0) | None = Field(None, description=(
        "speed of the friction peak at the elastomer's WLF reference temperature; default: "
        "the hysteresis peak asperity_wavelength x loss-peak frequency of the elastomer"))
    asperity_wavelength: Q("length", gt=0, le=1e-3) = Field(
        DEFAULT_ASPERITY_WAVELENGTH, description="wavelength of the shaft roughness that "
                                                 "deforms the lip rubber (ground shaft 50 um)")

    @model_validator(mode="after")
    def _ordered(self):
        if self.mu_low > self.mu_peak:
            raise ValueError(f"mu_low ({self.mu_low}) must not exceed mu_peak ({self.mu_peak})")
        return self


class DutyStep(CaseModel):
    """A speed step: ramp from the previous speed over ``ramp``, then hold."""

    speed: Q("angular_speed", ge=0, le=5000.0)
    duration: Q("time", gt=0, le=1e7)
    ramp: Q("time", ge=0) = 0.0

    @model_validator(mode="after")
    def _ramp_within(self):
        if self.ramp > self.duration:
            raise ValueError(f"ramp ({self.ramp:g} s) must not exceed duration "
                             f"({self.duration:g} s)")
        return self


#: Longest duty cycle run without asking [s] (about 11.6 days); ``duty.max_duration`` raises it.
MAX_DUTY_DURATION = 1.0e6


class DutyCycle(CaseModel):
    """Speed over time: a list of steps, or a CSV file of time and speed, their units in the
    header (``time [s], speed [1/min]``, or the names ``time_s, speed_rpm``)."""

    steps: list[DutyStep] | None = None
    csv: str | None = Field(None, description=(
        "CSV of time and speed, a piecewise-linear profile (two rows at one time: a jump); "
        "the header states the units, e.g. 'time [s]', 'n [1/min]' (or the names time_s, "
        "speed_rpm); relative paths: from the case file"))
    time_column: int | str = Field(1, description=(
        "the CSV's time column: its header name or 1-based index"))
    speed_column: int | str = Field(2, description=(
        "the CSV's speed column: its header name or 1-based index"))
    delimiter: Literal[",", ";", "\t"] = Field(",", description="the CSV's column separator")
    decimal: Literal[".", ","] = Field(".", description=(
        "the CSV's decimal separator (',' needs delimiter = ';' or a tab)"))
    max_duration: Q("time", gt=0) = Field(MAX_DUTY_DURATION, description=(
        "longest duty cycle that is run (default 1e6 s, about 11.6 days, a few minutes of "
        "computing): a guard against a unit slip such as '1000 h' for '1000 s'; raise it "
        "for longer runs"))
    until_steady: bool = Field(False, description=(
        "hold the last speed after the cycle until the temperatures are steady (all change "
        "slower than steady_rate), at most until max_duration"))
    steady_rate: Q("temperature_rate", gt=0) = Field(
        0.05 / 60.0, description="temperature rate below which until_steady stops (0.05 K/min)")

    @model_validator(mode="after")
    def _one_source(self):
        if (self.steps is None) == (self.csv is None):
            raise ValueError("give either steps = [...] or csv = 'file.csv'")
        if self.decimal == "," and self.delimiter == ",":
            raise ValueError("decimal = ',' needs another delimiter, e.g. delimiter = ';'")
        if self.steps is not None and not self.steps:
            raise ValueError("steps must not be empty")
        if self.steps is not None:
            too_long = self._too_long(sum(s.duration for s in self.steps), "the steps last")
            if too_long:
                raise ValueError(too_long)
        return self

    def _too_long(self, total: float, what: str) -> str:
        if total <= self.max_duration:
            return ""
        return (f"{what} {total:.6g} s in total, more than duty.max_duration = "
                f"{self.max_duration:.6g} s; raise duty.max_duration (e.g. max_duration = "
                f"'{total:.3g} s') to run it")

    def profile(self, base_dir: Path | None = None) -> tuple[np.ndarray, np.ndarray,
                                                              list[tuple[float, float]]]:
        """Piecewise-linear speed profile and the constant-speed steps for the summary.

        Returns
        -------
        times : ndarray
            Break points [s].
        speeds : ndarray
            Angular speed at the break points [rad/s] (a jump is two points at one time).
        steps : list of (start, end)
            Intervals of the duty steps [s].
        """
        if self.steps is not None:
            times, speeds, steps = [0.0], [self.steps[0].speed], []
            t, previous = 0.0, self.steps[0].speed
            for step in self.steps:
                if step.ramp > 0:
                    times += [t, t + step.ramp]
                    speeds += [previous, step.speed]
                else:
                    times.append(t)
                    speeds.append(step.speed)
                times.append(t + step.duration)
                speeds.append(step.speed)
                steps.append((t, t + step.duration))
                t += step.duration
                previous = step.speed
            return np.array(times), np.array(speeds), steps
        path = Path(self.csv) if base_dir is None else base_dir / self.csv
        times, speeds, steps = _read_duty_csv(path, self.time_column, self.speed_column,
                                              self.delimiter, self.decimal)
        too_long = self._too_long(float(times[-1]), f"the CSV {str(path)!r} lasts")
        if too_long:
            raise InputError(f"duty: {too_long}")
        return times, speeds, steps


#: Header names of a duty-cycle CSV that say their unit without brackets.
DUTY_CSV_NAMES = {"time_s": "s", "speed_rpm": "rpm"}


def _read_duty_csv(path: Path, time_column: int | str = 1, speed_column: int | str = 2,
                   delimiter: str = ",", decimal: str = "."):
    """Break points, speeds and constant-speed steps of a duty-cycle CSV, read by
    :func:`sealsim.tables.read_table` (every problem an InputError naming the file, row and
    column).  The columns' units are those their header names state (``t [s]``,
    ``n [1/min]``); ``time_s`` and ``speed_rpm`` are read as seconds and rpm."""
    where = f"duty.csv: {path}"
    specs = [ColumnSpec("time", time_column, None), ColumnSpec("speed", speed_column, None)]
    try:
        table = read_table(path, specs, delimiter=delimiter, decimal=decimal, header=True,
                           min_rows=2, what="duty.csv file", index_may_repeat=True,
                           header_units=DUTY_CSV_NAMES)
    except InputError as exc:
        raise InputError(f"duty.csv: {exc}") from None
    times, speeds = table.time, table.column("speed")
    if times[0] != 0:
        raise InputError(f"{where}: the time must start at 0 (the first row has "
                         f"{times[0]:g} s)")
    if times[-1] <= 0:
        raise InputError(f"{where}: every row is at time 0; the duty cycle needs a duration "
                         "(the last row's time > 0)")
    if np.any(speeds < 0) or np.any(speeds > 5000.0):
        raise InputError(f"{where}: the speed must be within 0-47746 rpm (0-5000 rad/s)")
    steps, start = [], 0
    for k in range(1, len(times) + 1):  # plateaus of constant speed are the summary steps
        if k == len(times) or speeds[k] != speeds[start]:
            if times[k - 1] > times[start]:
                steps.append((float(times[start]), float(times[k - 1])))
            start = k
    if not steps:  # a measured trace without exact plateaus: summarise it as one step
        steps = [(0.0, float(times[-1]))]
    return times, speeds, steps


class Numerics(CaseModel):
    """Discretisation of the thermal model and time stepping."""

    mesh_refinement: float = Field(1.0, ge=0.5, le=4.0)
    max_time_step: Q("time", gt=0, le=60.0) = 4.0
    min_time_step: Q("time", gt=0, le=10.0) = 0.25

    @model_validator(mode="after")
    def _ordered(self):
        if self.min_time_step > self.max_time_step:
            raise ValueError("min_time_step must not exceed max_time_step")
        return self


def start_temperature(env: Environment) -> float:
    """Initial temperature of a run [K]: as given, else the held sump temperature, else ambient."""
    if env.start_temperature is not None:
        return env.start_temperature
    if env.sump_temperature is not None:
        return env.sump_temperature
    return env.ambient_temperature


class RotaryCase(CaseModel):
    """A complete rotary lip seal case (the model of Organisciak et al., SKF, AGMA 14FTM14,
    2014)."""

    title: str = ""
    seal: Seal
    lip: LipSpec = LipSpec()
    oil: OilSpec = OilSpec()
    environment: Environment = Environment()
    thermal: ThermalSpec = ThermalSpec()
    friction: Friction = Friction()
    duty: DutyCycle | None = Field(None, description=(
        "speed over time, needed by a transient run (sealsim rotary run, simulate); "
        "steady_state needs none"))
    numerics: Numerics = Numerics()

    def duty_cycle(self) -> DutyCycle:
        """The duty cycle; an :class:`InputError` if the case has none (a transient run needs
        one, a steady operating point does not)."""
        if self.duty is None:
            raise InputError("duty: a transient run needs a duty cycle: give [duty] with "
                             "steps = [{speed = '1000 rpm', duration = '10 min'}] or "
                             "csv = 'file.csv'")
        return self.duty

    @model_validator(mode="after")
    def _temperatures_in_oil_range(self):
        oil = self.oil.build()
        env = self.environment
        # the start temperature matters to a transient run only: a steady operating point
        # (no duty cycle) does not start anywhere
        start = start_temperature(env) if self.duty is not None else None
        start_name = ("environment.start_temperature" if env.start_temperature is not None
                      else "environment.sump_temperature" if env.sump_temperature is not None
                      else "environment.ambient_temperature (the start temperature)")
        for name, value in ((start_name, start),
                            ("environment.sump_temperature", env.sump_temperature),
                            ("environment.housing_temperature", env.housing_temperature)):
            if value is not None and oil.min_temperature is not None and \
                    value < oil.min_temperature:
                hint = ("" if self.oil.min_temperature is not None else
                        "; if your oil's datasheet gives a lower pour point, set it as "
                        "oil.min_temperature")
                raise ValueError(f"{name} {value - ZERO_CELSIUS_K:.1f} degC is below the lowest "
                                 f"usable temperature of {oil.name} "
                                 f"({oil.min_temperature - ZERO_CELSIUS_K:.1f} degC){hint}")
        return self
