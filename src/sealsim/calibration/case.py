"""Friction-fit case files: one friction law, its contact source, the parameters to fit and the
measurements (see ``examples/calibration/tudelft_oring.toml``)::

    title = "O-ring 25 mm, TU Delft rig"

    [friction]                        # any law of sealsim.friction with its starting values
    law = "theta"
    parameter_set = "pneumatic_demo"
    bristle_stiffness = "5000 N/m"

    [contact]                         # where F_N and b come from (laws that use them: Θ)
    location = "piston"               # the seal separates the pressurised side from ambient
    sliding_diameter = "25 mm"
    temperature = "20 degC"
    map = { structure_case = "oring_25_piston.toml" }   # or file = "map.nc", or analytic = {...}

    [fit]
    loss = "soft_l1"                  # robust loss of scipy.optimize.least_squares
    f_scale = "0.5 N"                 # residual size where the robust loss sets in
    parameters = [
      { name = "f_a", bounds = [0.001, 2.0], stage = "steady" },
      { name = "bristle_stiffness", bounds = ["100 N/m", "1e6 N/m"], stage = "dynamic" },
    ]
    tied = { f_b = "f_a" }            # optional: law fields that follow a fitted parameter

    [[measurements]]
    name = "1 bar"
    file = "../data/tudelft_pneumatic_friction/O-ring_1bar.csv"
    format = "tudelft"                # or columns = { time = { column = 1, unit = "ms" }, ... }
    bore = "25 mm"
    role = "fit"                      # or "validate": predicted, never fitted

Several seals with one law (the same rubber, lubricant and counter surface, e.g. two rings on
one rig): each further seal is a ``[contacts.NAME]`` table like ``[contact]``, and its
measurements say ``contact = "NAME"``; the law's parameters are fitted to all runs with role
``fit`` together, each run with its own seal's contact map.

Repeated tests (the same seal at the same pressure, temperature and speed, run again or after
taking the rig apart) share a ``condition = "NAME"``; the report gives their scatter next to
the model's error (:func:`sealsim.calibration.study.repeat_conditions`).

Every condition the model needs comes from the file or the case, never from a default: the
pressure (a ``pressure`` column, or ``pressure = "2 bar"`` of the measurement) when a contact
map or a pressure-scaled law uses it, the seal temperature (``temperature`` of the measurement
or of ``[contact]``) when a contact map uses it; without them the fit is refused, naming the
measurement and the missing quantity.

Sign convention: the friction force is the force the seal resists the motion with, positive
while the velocity is positive.  A measured friction level that comes out negative means the
file counts it the other way: ``scale = -1`` on the friction column flips it (on the position
or velocity column when the friction is computed from the rod force and the pressure).

Stages: ``steady`` parameters are fitted first to the friction level of every sliding phase
(the steady sweep); ``dynamic`` parameters then to the whole friction time series with the
steady ones fixed (the literature's staged identification, e.g. Canudas de Wit et al. 1995,
Heipl & Murrenhoff).
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import Field, TypeAdapter, ValidationError, model_validator

from sealsim.cases import CaseModel, Q, validation_problems
from sealsim.errors import InputError
from sealsim.friction.case import LawParameters
from sealsim.measurements.readers import QUANTITIES, ColumnSpec
from sealsim.pneumatic.case import MapModel

__all__ = ["ContactModel", "FitParameter", "FrictionFitCase", "MeasurementModel",
           "check_measurements", "contact_of", "contact_table", "parse_field_value",
           "parse_law_value", "repeated_conditions"]


class FitParameter(CaseModel):
    """A parameter of the law to fit: its field name, bounds (quantities) and stage."""

    name: str
    bounds: tuple[Any, Any]
    initial: Any = None
    stage: Literal["steady", "dynamic"] = "steady"


class FitSettings(CaseModel):
    """Robust bounded least squares (scipy.optimize.least_squares, method 'trf')."""

    loss: Literal["linear", "soft_l1", "huber", "cauchy", "arctan"] = "soft_l1"
    f_scale: Q("force", gt=0) = 0.5
    max_evaluations: int = Field(200, ge=5, le=100000)
    max_samples: int = Field(4000, ge=50, le=1_000_000)
    parameters: list[FitParameter] = Field(min_length=1)
    tied: dict[str, str] = Field(default_factory=dict, description=(
        "law fields that take the value of a fitted parameter, e.g. {f_b = 'f_a'}"))


class SignalSettings(CaseModel):
    """How the measured signals are processed (:mod:`sealsim.measurements.signals`)."""

    velocity_window: Q("time", gt=0) = 0.2
    sliding_threshold: Q("velocity", gt=0) | None = None
    min_phase_duration: Q("time", gt=0) = 0.5
    settle: Q("dimensionless", ge=0, lt=0.95) = 0.2


class ContactModel(CaseModel):
    """Source of F_N and b of the seal (the ``map`` table of a pneumatic seal)."""

    location: Literal["piston", "rod"] = "piston"
    sliding_diameter: Q("length", gt=0)
    temperature: Q("temperature", gt=0) | None = Field(None, description=(
        "seal temperature of every measurement that gives none; a contact map needs one"))
    map: MapModel | None = None
    positive_velocity: Literal["away_from_pressure", "towards_pressure"] = Field(
        "away_from_pressure", description=(
            "how the counter surface slides relative to the seal when the measured velocity "
            "is positive: away from the pressurised side (a rod seal's outstroke) or towards "
            "it; sets the stroke direction of a friction table from the seal's contact"))


class ColumnModel(CaseModel):
    """One column of a measurement table: 1-based index or header name, pint unit."""

    column: int | str
    unit: str
    scale: float = 1.0


class MeasurementModel(CaseModel):
    """A measured run: a file, how to read it, its role and the conditions not measured.

    Sign convention: the friction is the force the seal resists the motion with, positive
    while the velocity is positive.  A file that counts it the other way gives a negative
    friction level, which is refused with a hint: flip it with ``scale = -1`` on the friction
    column, or on the position (or velocity) column when the friction is computed from the
    rod force and the pressure (columns ``force`` and ``pressure`` with ``bore``: friction =
    p·π·D²/4 − F_rod, the force balance of a piston the pressure drives against its rod).

    Conditions: the pressure (a ``pressure`` column or ``pressure``) is needed when a contact
    map or a pressure-scaled law uses it, the seal temperature (``temperature`` here or in
    ``[contact]``) when a contact map does; a fit without them is refused, never run at a
    default.  German rigs' files: ``delimiter = ";"`` with ``decimal = ","``.
    """

    name: str = Field(min_length=1)
    file: str
    role: Literal["fit", "validate"]
    format: Literal["tudelft"] | None = None
    bore: Q("length", gt=0) | None = Field(None, description=(
        "bore diameter D: friction = p*pi*D^2/4 - F_rod from pressure and rod force columns "
        "(format 'tudelft', or columns force and pressure without friction)"))
    columns: dict[str, ColumnModel] | None = None
    delimiter: str | None = None
    decimal: Literal[".", ","] = "."
    header: bool = False
    skip_rows: int | None = Field(None, ge=0)
    pressure: Q("pressure") | None = None
    temperature: Q("temperature", gt=0) | None = None
    contact: str | None = Field(None, description=(
        "the seal of this run when one fit spans several seals with the same law parameters "
        "(the same rubber, lubricant and counter surface): the name of a [contacts.NAME] "
        "table; default [contact]"))
    condition: str | None = Field(None, min_length=1, description=(
        "runs that repeat one test (the same seal at the same pressure, temperature and "
        "speed: run again, or after taking the rig apart) share a name here; the report gives "
        "the scatter of their measured friction and the model's error of their mean in units "
        "of it (report.json 'conditions', conditions.csv, repeatability.png)"))

    @model_validator(mode="after")
    def _check(self):
        if (self.format is None) == (self.columns is None):
            raise ValueError("give exactly one of format = 'tudelft' or a columns table")
        if self.format == "tudelft" and self.bore is None:
            raise ValueError("format 'tudelft' needs bore (e.g. bore = '25 mm')")
        if self.columns is not None:
            unknown = sorted(set(self.columns) - set(QUANTITIES))
            if unknown:
                raise ValueError(f"unknown column quantities {unknown}; choose from "
                                 f"{sorted(QUANTITIES)}")
            if "time" not in self.columns:
                raise ValueError("columns must include ['time']")
            if "friction" not in self.columns and not {"force", "pressure"} <= set(self.columns):
                raise ValueError("columns must include friction, or force (the rod force) and "
                                 "pressure with bore, to compute friction = p*A - F_rod")
            if "friction" not in self.columns and self.bore is None:
                raise ValueError("friction from the force and pressure columns needs bore "
                                 "(e.g. bore = '25 mm'), the diameter the pressure acts on")
            if "position" not in self.columns and "velocity" not in self.columns:
                raise ValueError("columns must include position or velocity")
        return self

    def column_specs(self) -> list[ColumnSpec]:
        return [ColumnSpec(q, c.column, c.unit, c.scale) for q, c in (self.columns or {}).items()]


class FrictionFitCase(CaseModel):
    """A friction-law fit (see the module docstring)."""

    title: str = ""
    friction: LawParameters
    contact: ContactModel | None = None
    contacts: dict[str, ContactModel] = Field(default_factory=dict, description=(
        "further seals by name, each the contact of the measurements that name it "
        "(contact = NAME); one law, fitted to all of them"))
    signals: SignalSettings = SignalSettings()
    fit: FitSettings
    measurements: list[MeasurementModel] = Field(min_length=1)

    @model_validator(mode="after")
    def _check(self):
        check_measurements(self.measurements)
        for m in self.measurements:
            if m.contact is not None and m.contact not in self.contacts:
                raise ValueError(f"measurement {m.name!r}: contact = {m.contact!r} names no "
                                 f"[contacts.NAME] table (given: {sorted(self.contacts)})")
        for name, runs in repeated_conditions(self.measurements).items():
            seals = sorted({contact_table(m.contact) for m in runs})
            if len(seals) > 1:
                raise ValueError(f"condition {name!r}: its runs ({', '.join(m.name for m in runs)})"
                                 f" name different seals ({', '.join(seals)}); a repeated test "
                                 "is one seal at one condition")
        fields = type(self.friction).model_fields
        unused = getattr(self.friction, "unused_fields", tuple)()
        pnames = [p.name for p in self.fit.parameters]
        for p in self.fit.parameters:
            if p.name in ("law", "parameter_set") or p.name not in fields:
                allowed = sorted(f for f in fields if f not in ("law", "parameter_set"))
                raise ValueError(f"fit parameter {p.name!r} is not a parameter of the "
                                 f"{self.friction.law} law; choose from {allowed}")
            if p.name in unused:
                allowed = sorted(f for f in fields if f not in (
                    "law", "parameter_set", "steady", *unused))
                raise ValueError(
                    f"fit parameter {p.name!r} is not used by the {self.friction.law} law with "
                    f"steady = {self.friction.steady!r} (unused: {', '.join(unused)}), so the "
                    f"fit could not determine it; fit one of {allowed}")
            if pnames.count(p.name) > 1:
                raise ValueError(f"fit parameter {p.name!r} is listed twice")
        for target, source in self.fit.tied.items():
            if target not in fields or target in ("law", "parameter_set"):
                raise ValueError(f"fit.tied: {target!r} is not a parameter of the "
                                 f"{self.friction.law} law")
            if source not in pnames:
                raise ValueError(f"fit.tied.{target}: {source!r} is not a fitted parameter "
                                 f"(fitted: {pnames})")
            if target in pnames:
                raise ValueError(f"fit.tied.{target}: it is fitted itself; remove one of the two")
        return self


def contact_of(case: FrictionFitCase, spec: MeasurementModel) -> ContactModel | None:
    """The contact of a measurement: its ``[contacts.NAME]``, else the case's ``[contact]``."""
    return case.contacts[spec.contact] if spec.contact is not None else case.contact


def contact_table(name: str | None) -> str:
    """The case's table of a contact, for messages: ``contacts.NAME``, or ``contact`` (None)."""
    return "contact" if name is None else f"contacts.{name}"


def repeated_conditions(measurements) -> dict[str, list]:
    """The measurements grouped by their ``condition`` (those without one left out), in the
    order of the case."""
    groups: dict[str, list] = {}
    for m in measurements:
        if m.condition is not None:
            groups.setdefault(m.condition, []).append(m)
    return groups


def check_measurements(measurements) -> None:
    """The measurements of a fit case: unique names, at least one with role 'fit' (ValueError
    otherwise, which the case validation reports with the table it belongs to)."""
    names = [m.name for m in measurements]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise ValueError(f"measurement names must be unique, repeated: {dupes}")
    if not any(m.role == "fit" for m in measurements):
        raise ValueError("at least one measurement needs role = 'fit'")


def parse_field_value(field, label: str, value, where: str) -> float:
    """A value for the pydantic ``field`` (a quantity string with its unit, or a number for a
    dimensionless field) in SI, checked with the field's own type: its units and range.
    ``label`` names the field in the error message."""
    try:
        parsed = TypeAdapter(field.rebuild_annotation()).validate_python(
            value, context={"require_units": True})
    except ValidationError as exc:  # one readable line per problem, without pydantic's URL
        detail = "; ".join(validation_problems(exc))
        raise InputError(f"{where}: {value!r} is not a valid {label}: {detail}") from None
    if parsed is None or isinstance(parsed, bool) or not isinstance(parsed, int | float):
        raise InputError(f"{where}: {value!r} is not a number for {label}")
    return float(parsed)


def parse_law_value(params, name: str, value, where: str) -> float:
    """A value of the law field ``name`` (a quantity string with its unit) in SI.

    Uses the field's own type, so the units and the range are those of the law model.
    """
    return parse_field_value(type(params).model_fields[name], name, value, where)
