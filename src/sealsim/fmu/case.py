"""FMU case files: which sealsim model to export and how (TOML, quantities with units).

``sealsim fmu build`` takes a friction case, a pneumatic case (one of its seals), a rotary
case, or an FMU case that points at one of them and adds settings::

    title = "Θ-law piston seal of the Ø32 cylinder"

    [fmu]
    name = "PistonSeal"                      # model identifier (default: the .fmu file name)
    source = "../pneumatic/cylinder_32.toml" # a friction, pneumatic or rotary case
    variant = "T55C"                         # optional: one variant of the source
    seal = "piston"                          # pneumatic cases: the seal to export
    friction_file = "fitted_parameters.toml" # optional: a [friction] table replacing the law

    [table]                                  # grid of an analytic contact map
    temperature_points = 13
    pressure_points = 33

    [rotary]                                 # rotary FMUs: grids of the maps, thermal lag
    max_speed = "3000 rpm"
    speed_points = 9
    sump_temperatures = ["20 degC", "60 degC", "100 degC"]
    lag_order = 2

Without a ``source`` the FMU case gives the law itself (``[friction]``) and its contact
(``[seal_contact]``: ``normal_force`` and ``contact_width``, or ``map`` and
``sliding_diameter``).
"""

from __future__ import annotations

from pydantic import Field, field_validator, model_validator

from sealsim.cases import CaseModel, Q
from sealsim.fmu.model_description import xml_text_problem
from sealsim.friction.case import LawParameters
from sealsim.pneumatic.case import MapModel

__all__ = ["ContactSettings", "FMUCase", "FMUSettings", "FrictionTable", "RotarySettings",
           "TableSettings"]


class TableSettings(CaseModel):
    """Grid of a contact table tabulated from an analytic map (FE maps keep their nodes)."""

    temperature_points: int = Field(13, ge=2, le=200)
    pressure_points: int = Field(33, ge=2, le=400)


class ContactSettings(CaseModel):
    """The contact of a seal given in the FMU case itself."""

    normal_force: Q("force", gt=0) | None = None
    contact_width: Q("length", ge=0) | None = None
    sliding_diameter: Q("length", gt=0) | None = None
    map: MapModel | None = None
    temperature: Q("temperature", gt=0) | None = Field(None, description=(
        "start value of the FMU's seal temperature input; default the law's "
        "reference_temperature (else 20 degC)"))

    @model_validator(mode="after")
    def _one_kind(self):
        constant = self.normal_force is not None or self.contact_width is not None
        if constant and self.map is not None:
            raise ValueError("give either normal_force and contact_width or a map, not both")
        if constant and (self.normal_force is None or self.contact_width is None):
            raise ValueError("a constant contact needs both normal_force and contact_width")
        if self.map is not None and self.map.analytic is not None and \
                self.sliding_diameter is None and self.map.analytic.sliding_diameter is None:
            raise ValueError("an analytic map needs the sliding_diameter of the seal")
        return self


class RotarySettings(CaseModel):
    """Grids of the rotary maps, the thermal lag and the checks against the full model."""

    max_speed: Q("angular_speed", gt=0) | None = Field(None, description=(
        "end of the speed axis of the maps; default 3000 rpm (or 1.2 x the highest speed of "
        "the duty cycle)"))
    speed_points: int = Field(9, ge=3, le=200, description=(
        "node spacing of the speed axis: speed_points - 1 equal steps of ln(1 + speed/10 rpm) "
        "from 0 to max_speed; each flow regime of the oil-side convection gets the nodes its "
        "widest extent needs (at least 2)"))
    sump_temperatures: list[Q("temperature", gt=0)] | None = Field(None, description=(
        "sump temperature grid; default 6 temperatures from 20 to 120 degC (widened to the "
        "case's sump temperature)"))
    torque_speed_min: Q("angular_speed", gt=0) = Field(
        0.1047197551196598, description="below this speed (default 1 rpm) the torque ramps "
                                        "linearly to 0 at standstill")
    lag_order: int = Field(2, ge=1, le=3)
    lag_points: int = Field(3, ge=1, le=8, description=(
        "step responses per flow regime and lag sump temperature"))
    lag_sump_temperatures: list[Q("temperature", gt=0)] | None = Field(None, description=(
        "sump temperatures of the step responses; default lowest, middle and highest of the "
        "grid"))
    lag_duration: Q("time", gt=0, le=1e6) = Field(3600.0, description=(
        "settling time scale of the step responses: a response changing by less than 1 % of "
        "its rise per lag_duration has settled (each run ends then, at the latest after 16 x "
        "lag_duration)"))
    ambient_input: bool = True
    ambient_step: Q("temperature_difference", gt=0, le=100) = 10.0
    ambient_range: Q("temperature_difference", gt=0, le=200) = 30.0
    torque_points: tuple[int, int] = (65, 61)
    check_between: bool = Field(True, description=(
        "compare the FMU with new steady states between the grid points"))
    check_duty_cycle: bool = Field(True, description=(
        "compare the FMU with the transient model over the case's duty cycle"))


class FMUSettings(CaseModel):
    """Which model to export."""

    name: str | None = Field(None, pattern=r"^[A-Za-z_][A-Za-z0-9_]{0,63}$")
    source: str | None = None
    variant: str | None = None
    seal: str | None = None
    friction_file: str | None = None


class FMUCase(CaseModel):
    """An FMU case file (see the module docstring)."""

    title: str = ""
    fmu: FMUSettings
    friction: LawParameters | None = None
    seal_contact: ContactSettings | None = None
    table: TableSettings = TableSettings()
    rotary: RotarySettings = RotarySettings()

    @field_validator("title")
    @classmethod
    def _xml_title(cls, title: str) -> str:
        problem = xml_text_problem(title)
        if problem:
            raise ValueError(problem)
        return title

    @model_validator(mode="after")
    def _source_or_law(self):
        if self.fmu.source is None and self.friction is None and self.fmu.friction_file is None:
            raise ValueError("give fmu.source (a friction, pneumatic or rotary case) or a "
                             "[friction] table with a [seal_contact] table")
        return self


class FrictionTable(CaseModel):
    """A file with a ``[friction]`` table (``fitted_parameters.toml`` of a fit)."""

    friction: LawParameters

