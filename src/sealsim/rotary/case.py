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

import csv
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import Field, field_validator, model_validator

from sealsim.cases import CaseModel, Q
from sealsim.errors import InputError
from sealsim.properties.elastomers import get_elastomer
from sealsim.properties.oils import FAMILIES, Oil, get_oil
from sealsim.rotary.lip import (
    LIP_STYLES,
    default_contact_width,
    default_outer_diameter,
    default_radial_force,
    default_width,
)
from sealsim.rotary.lip_fe import LipSpec
from sealsim.tribology.contact import PERSSON_KAPPA
from sealsim.tribology.film import EHL_EXPONENT, FILM_FLOOR, film_coefficient_matching_fit
from sealsim.tribology.rubber_friction import DEFAULT_MASTER_CURVE

__all__ = ["DutyCycle", "DutyStep", "Environment", "Friction", "Numerics", "OilSpec",
           "RotaryCase", "Seal", "ThermalSpec", "WaveLip"]

CELSIUS_0 = 273.15


class WaveLip(CaseModel):
    """How a wave lip differs from a plain lip (used when ``lip_style = "wave"``)."""

    film_factor: float = Field(LIP_STYLES["wave"].film_factor, gt=0.5, le=3.0, description=(
        "effective film thickness relative to a plain lip at the same viscosity and speed"))
    track_amplitude: Q("length", ge=0, le=5e-3) = LIP_STYLES["wave"].track_amplitude
    lip_heat_exchange_factor: float = Field(LIP_STYLES["wave"].lip_heat_exchange_factor,
                                            ge=1.0, le=10.0)


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
    spring_share: float = Field(0.45, ge=0.0, le=1.0, description=(
        "share of the garter spring in the radial force (reference notes: 30-60 % new)"))
    contact_width: Q("length", gt=10e-6, le=3e-3) | None = None
    shaft_roughness: Q("length", gt=0, le=5e-6) = Field(0.3e-6, description=(
        "RMS roughness Rq of the shaft (DIN 3760: Ra 0.2-0.8 um; Rq = 1.25 Ra)"))
    lip_roughness: Q("length", gt=0, le=10e-6) = Field(0.4e-6, description=(
        "RMS roughness of the run-in lip surface"))
    shaft_rms_slope: float = Field(0.2, gt=0.0, le=2.0, description=(
        "RMS slope of the shaft surface (ground shafts 0.1-0.3)"))
    spring_offset: Q("length", ge=-5e-3, le=5e-3) = Field(0.5e-3, description=(
        "axial offset of the garter spring plane from the contact, air side positive"))
    wave: WaveLip = WaveLip()

    @field_validator("material")
    @classmethod
    def _known_material(cls, value: str) -> str:
        return get_elastomer(value).name

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
        for key, value in values.items():
            object.__setattr__(self, key, value)
        if self.outer_diameter <= d + 4e-3:
            raise ValueError(f"outer_diameter {self.outer_diameter * 1e3:g} mm must exceed the "
                             f"shaft diameter {d * 1e3:g} mm by more than 4 mm")
        return self


class OilSpec(CaseModel):
    """The lubricant: a catalogue name, or your own oil from datasheet values."""

    name: str = "VG68-mineral"
    nu40: Q("kinematic_viscosity", gt=0) | None = None
    nu100: Q("kinematic_viscosity", gt=0) | None = None
    density15: Q("density", gt=0) | None = None
    family: Literal[FAMILIES] | None = None  # type: ignore[valid-type]

    @model_validator(mode="after")
    def _resolve(self):
        own = [self.nu40, self.nu100, self.density15]
        if any(v is not None for v in own):
            if any(v is None for v in own):
                raise ValueError("an own oil needs nu40, nu100 and density15 "
                                 "(or give only a catalogue name)")
            self.build()  # validates the datasheet values
        else:
            get_oil(self.name)  # unknown names list close matches
        return self

    def build(self) -> Oil:
        """The :class:`~sealsim.properties.oils.Oil` this spec describes."""
        if self.nu40 is None:
            return get_oil(self.name)
        return Oil.from_datasheet(self.name, self.nu40, self.nu100, self.density15,
                                  family=self.family or "mineral",
                                  source="user datasheet values (case file)")


class Environment(CaseModel):
    """Oil sump, housing, ambient, shaft."""

    ambient_temperature: Q("temperature", gt=200.0, lt=400.0) = 293.15
    start_temperature: Q("temperature", gt=200.0, lt=450.0) | None = Field(
        None, description="initial temperature of shaft, seal, oil and housing; "
                          "default: ambient")
    sump_volume: Q("volume", gt=1e-6, le=10.0) = 1e-3
    sump_temperature: Q("temperature", gt=200.0, lt=450.0) | None = Field(
        None, description="if given, the sump is held at this temperature (thermostat); "
                          "otherwise it heats up from the seal's friction")
    oil_level_wetting: float = Field(0.5, ge=0.0, le=1.0, description=(
        "fraction of the shaft circumference under oil on the oil side "
        "(0.5: oil level at the shaft centre, as in seed 000's rig)"))
    housing_area: Q("area", gt=0) | None = Field(
        None, description="outer housing area to ambient; default: a box twice the sump volume")
    housing_mass: Q("mass", gt=0) | None = Field(
        None, description="housing metal mass; default: 5 mm steel walls of housing_area")
    housing_heat_transfer: Q("heat_transfer_coefficient", gt=0, le=1000.0) = Field(
        12.0, description="housing to ambient: radiation 7.5 + natural convection 4.8 "
                          "W/(m2 K) for a 0.3 m wall 40 K above ambient (notes 7.3)")
    oil_housing_heat_transfer: Q("heat_transfer_coefficient", gt=0, le=10000.0) = Field(
        100.0, description="oil to the wetted housing wall (splashed walls 1e2-1e3 W/(m2 K))")
    shaft_length_oil_side: Q("length", gt=1e-3, le=2.0) = 0.06
    shaft_length_air_side: Q("length", gt=1e-3, le=2.0) = 0.08
    shaft_air_end: Literal["fin", "insulated"] = Field("fin", description=(
        "beyond shaft_length_air_side the shaft either continues bare in air (fin) or enters "
        "a part that takes no heat, e.g. a test-rig spindle or a plastic coupling (insulated)"))
    shaft_conductivity: Q("thermal_conductivity", gt=0) = 45.0
    shaft_density: Q("density", gt=0) = 7850.0
    shaft_specific_heat: Q("specific_heat", gt=0) = 460.0


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
                    "to seed 000's measured h = 3.45 (u eta)^0.68")
    film_exponent: float = Field(EHL_EXPONENT, gt=0.3, lt=1.0)
    film_floor: Q("length", gt=0, le=1e-6) = FILM_FLOOR
    mu_peak: float = Field(DEFAULT_MASTER_CURVE.mu_peak, gt=0, le=5)
    mu_low: float = Field(DEFAULT_MASTER_CURVE.mu_low, ge=0, le=5)
    master_curve_width_decades: float = Field(DEFAULT_MASTER_CURVE.width_decades, gt=0, le=10)
    peak_speed_at_reference: Q("velocity", gt=0) = DEFAULT_MASTER_CURVE.peak_speed_reference
    persson_kappa: float = Field(PERSSON_KAPPA, gt=0, le=10)
    asperity_wavelength: Q("length", gt=0, le=1e-3) = 50e-6

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
    """Speed over time: a list of steps, or a CSV file with columns time_s, speed_rpm."""

    steps: list[DutyStep] | None = None
    csv: str | None = Field(None, description="CSV with columns time_s, speed_rpm "
                                              "(relative paths: from the case file)")
    max_duration: Q("time", gt=0) = Field(MAX_DUTY_DURATION, description=(
        "longest duty cycle that is run (default 1e6 s, about 11.6 days, a few minutes of "
        "computing): a guard against a unit slip such as '1000 h' for '1000 s'; raise it "
        "for longer runs"))

    @model_validator(mode="after")
    def _one_source(self):
        if (self.steps is None) == (self.csv is None):
            raise ValueError("give either steps = [...] or csv = 'file.csv'")
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
        times, speeds, steps = _read_duty_csv(path)
        too_long = self._too_long(float(times[-1]), f"the CSV {str(path)!r} lasts")
        if too_long:
            raise InputError(f"duty: {too_long}")
        return times, speeds, steps


def _read_duty_csv(path: Path):
    """Break points, speeds and constant-speed steps of a duty-cycle CSV (every problem an
    InputError naming the file and row)."""
    where = f"duty.csv: {str(path)!r}"
    try:
        # utf-8-sig: a byte-order mark (spreadsheet export) is not part of the first header
        with path.open(newline="", encoding="utf-8-sig") as fh:
            reader = csv.DictReader(fh)
            header = reader.fieldnames or []
            rows = list(reader)
    except FileNotFoundError:
        raise InputError(f"{where} does not exist") from None
    except IsADirectoryError:
        raise InputError(f"{where} is a folder, expected a CSV file") from None
    except UnicodeDecodeError:
        raise InputError(f"{where} is not a UTF-8 text file (a CSV with columns time_s, "
                         "speed_rpm)") from None
    except (OSError, csv.Error) as exc:  # no permission, NUL bytes of a binary file
        raise InputError(f"{where} cannot be read as CSV: "
                         f"{getattr(exc, 'strerror', None) or exc}") from None
    header = [h.strip() for h in header if h is not None]
    if not {"time_s", "speed_rpm"} <= set(header):
        raise InputError(f"{where} needs the columns time_s, speed_rpm; its header is "
                         f"{', '.join(header) or '(empty)'}")
    if not rows:
        raise InputError(f"{where} has a header but no data rows")
    rows = [{(k or "").strip(): v for k, v in r.items()} for r in rows]
    try:
        times = np.array([float(r["time_s"]) for r in rows])
        rpm = np.array([float(r["speed_rpm"]) for r in rows])
    except (TypeError, ValueError) as exc:
        raise InputError(f"{where} has a non-numeric or missing value ({exc})") from None
    if len(times) < 2 or not np.all(np.isfinite(times)) or not np.all(np.isfinite(rpm)):
        raise InputError(f"{where} needs at least two finite rows")
    if times[0] != 0 or np.any(np.diff(times) < 0):
        raise InputError(f"{where}: time_s must start at 0 and not decrease")
    if times[-1] <= 0:
        raise InputError(f"{where}: every row is at time_s = 0; the duty cycle needs a "
                         "duration (time_s of the last row > 0)")
    if np.any(rpm < 0) or np.any(rpm > 5000 * 60 / (2 * np.pi)):
        raise InputError(f"{where}: speed_rpm must be within 0-47746 rpm")
    speeds = rpm * np.pi / 30.0
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


class RotaryCase(CaseModel):
    """A complete rotary lip seal case (seed 000)."""

    title: str = ""
    seal: Seal
    lip: LipSpec = LipSpec()
    oil: OilSpec = OilSpec()
    environment: Environment = Environment()
    thermal: ThermalSpec = ThermalSpec()
    friction: Friction = Friction()
    duty: DutyCycle
    numerics: Numerics = Numerics()

    @model_validator(mode="after")
    def _temperatures_in_oil_range(self):
        oil = self.oil.build()
        env = self.environment
        start = env.start_temperature if env.start_temperature is not None \
            else env.ambient_temperature
        for name, value in (("environment.start_temperature", start),
                            ("environment.sump_temperature", env.sump_temperature)):
            if value is not None and oil.min_temperature is not None and \
                    value < oil.min_temperature:
                raise ValueError(f"{name} {value - CELSIUS_0:.1f} degC is below the lowest "
                                 f"usable temperature of {oil.name} "
                                 f"({oil.min_temperature - CELSIUS_0:.1f} degC)")
        return self
