"""Rotary-fit case files: the lip seal model, the parameters to fit (by their dotted path in a
rotary case) and the measured speed cycles (see ``examples/calibration/rotary_synthetic.toml``)::

    title = "80 mm NBR lip seal on a test rig"

    [model]                          # a rotary case without [duty]: each run's measured speed
    seal = { shaft_diameter = "80 mm", material = "NBR" }     # is its duty cycle
    environment = { setup = "test_rig", sump_volume = "0.2 L" }
    numerics = { mesh_refinement = 0.5, max_time_step = "30 s" }

    [fit]
    torque_uncertainty = "0.005 N*m"      # standard uncertainty of a step average
    temperature_uncertainty = "0.3 K"
    strategy = "staged"                   # or "joint"
    parameters = [
      { path = "seal.radial_force", bounds = ["10 N", "100 N"] },
      { path = "friction.mu_low", bounds = [0.02, 1.0] },
      { path = "thermal.seal_oil_factor", bounds = [0.02, 2.0], stage = "thermal" },
    ]

    [[measurements]]
    name = "cycle A"
    file = "cycle_a.csv"
    role = "fit"                          # or "validate": predicted, never fitted
    delimiter = ","
    header = true
    columns = { time = { column = "time_s", unit = "s" },
                speed = { column = "speed_rpm", unit = "rpm" },
                torque = { column = "torque_Nm", unit = "N*m" },
                temperature = { column = "T_groove_C", unit = "degC" } }   # spring groove
    conditions = { environment.sump_volume = "0.2 L" }   # fields of [model] for this run

Residuals are the last-``averaging.window`` step averages of torque and spring-groove
temperature (the comparison of Organisciak et al., AGMA 14FTM14, 2014), each divided by its
stated uncertainty.  Stages (strategy ``staged``): the ``torque`` parameters against the torque
averages (thermal parameters at their start values), then the ``thermal`` ones against the
temperature averages, then all together against both; strategy ``joint`` does only the last.
"""

from __future__ import annotations

import re
import types
import typing
from typing import Any, Literal

from pydantic import Field, model_validator
from pydantic.fields import FieldInfo

from sealsim.calibration.case import ColumnModel, check_measurements, parse_field_value
from sealsim.cases import CaseModel, Q, apply_overrides, validate_case
from sealsim.errors import InputError
from sealsim.rotary.case import RotaryCase

__all__ = ["AveragingSettings", "RotaryFitCase", "RotaryFitParameter", "RotaryFitSettings",
           "RotaryMeasurementModel", "case_field", "expand_dotted", "parse_case_value"]

#: Tables of a rotary case whose fields may not be fitted (no physics, or set by the data).
NOT_FITTABLE = ("duty", "numerics")
#: Default stage of a parameter by its table: friction and seal set the torque directly.
THERMAL_TABLES = ("thermal", "environment")


def expand_dotted(table: dict[str, Any]) -> dict[str, Any]:
    """Nested tables from keys written with dots (``{"environment.sump_volume": "3 L"}``).

    Examples
    --------
    >>> expand_dotted({"environment.sump_volume": "3 L", "oil": {"name": "VG220-mineral"}})
    {'environment': {'sump_volume': '3 L'}, 'oil': {'name': 'VG220-mineral'}}
    """
    out: dict[str, Any] = {}
    for key, value in table.items():
        parts = key.split(".")
        nested: Any = expand_dotted(value) if isinstance(value, dict) else value
        for part in reversed(parts[1:]):
            nested = {part: nested}
        out = apply_overrides(out, {parts[0]: nested})
    return out


def _flatten(table: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    out = {}
    for key, value in table.items():
        if isinstance(value, dict):
            out.update(_flatten(value, f"{prefix}{key}."))
        else:
            out[f"{prefix}{key}"] = value
    return out


def _is_number(annotation) -> bool:
    origin = typing.get_origin(annotation)
    if origin is typing.Annotated:
        return _is_number(typing.get_args(annotation)[0])
    if origin in (typing.Union, types.UnionType):
        members = [a for a in typing.get_args(annotation) if a is not type(None)]
        return len(members) == 1 and _is_number(members[0])
    return annotation in (float, int)


def _submodel(annotation) -> type[CaseModel] | None:
    if isinstance(annotation, type) and issubclass(annotation, CaseModel):
        return annotation
    members = [a for a in typing.get_args(annotation) if a is not type(None)]
    return members[0] if len(members) == 1 and _submodel(members[0]) else None


def case_field(path: str) -> FieldInfo:
    """The field of :class:`~sealsim.rotary.case.RotaryCase` at a dotted ``path``, if it is a
    number that can be fitted (an :class:`InputError` naming the choices otherwise).

    Examples
    --------
    >>> case_field("thermal.seal_oil_factor").default
    0.2
    >>> case_field("seal.lip_style")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: parameter path 'seal.lip_style' is not a number ...
    """
    model: type[CaseModel] | None = RotaryCase
    parts = path.split(".")
    for k, part in enumerate(parts):
        fields = model.model_fields
        if part not in fields or (k == 0 and part in NOT_FITTABLE):
            where = ".".join(parts[:k]) or "the rotary case"
            choices = [f for f in fields if not (k == 0 and f in NOT_FITTABLE)]
            raise InputError(f"parameter path {path!r}: {where} has no field {part!r} that can "
                             f"be fitted; choose from {', '.join(choices)}")
        field = fields[part]
        if k == len(parts) - 1:
            if not _is_number(field.annotation):
                raise InputError(f"parameter path {path!r} is not a number (it is "
                                 f"{field.annotation!r}); only numeric fields can be fitted")
            return field
        model = _submodel(field.annotation)
        if model is None:
            raise InputError(f"parameter path {path!r}: {'.'.join(parts[:k + 1])} is a value, "
                             "not a table")
    raise InputError(f"parameter path {path!r} is empty")  # pragma: no cover - split() >= 1


def parse_case_value(path: str, value, where: str) -> float:
    """A value for the rotary-case field at ``path`` (a quantity string with its unit, or a
    number for a dimensionless field) in SI, checked against the field's own range."""
    return parse_field_value(case_field(path), path, value, where)


class RotaryFitParameter(CaseModel):
    """A field of the rotary case to fit: its dotted path, bounds and start value (with units
    where the field has them) and the stage it is fitted in."""

    path: str = Field(min_length=1)
    bounds: tuple[Any, Any]
    initial: Any = None
    stage: Literal["torque", "thermal"] | None = Field(None, description=(
        "default: thermal for thermal.* and environment.*, torque otherwise"))

    @property
    def fit_stage(self) -> str:
        if self.stage is not None:
            return self.stage
        return "thermal" if self.path.split(".")[0] in THERMAL_TABLES else "torque"


class RotaryFitSettings(CaseModel):
    """Bounded robust least squares on step averages scaled by their uncertainties."""

    loss: Literal["linear", "soft_l1", "huber", "cauchy", "arctan"] = "soft_l1"
    f_scale: float = Field(3.0, gt=0, le=1e3, description=(
        "scaled residual (in standard uncertainties) where the robust loss sets in"))
    torque_uncertainty: Q("energy", gt=0) = Field(description=(
        "standard uncertainty of a measured step-average torque, e.g. '0.005 N*m'"))
    temperature_uncertainty: Q("temperature_difference", gt=0) = Field(description=(
        "standard uncertainty of a measured step-average spring-groove temperature, e.g. "
        "'0.3 K'"))
    strategy: Literal["joint", "staged"] = "joint"
    max_evaluations: int = Field(40, ge=3, le=10000, description=(
        "largest number of residual evaluations per stage (each simulates every fit run), "
        "not counting the finite-difference Jacobians"))
    parameters: list[RotaryFitParameter] = Field(min_length=1)


class AveragingSettings(CaseModel):
    """How speed steps are found, averaged (:func:`sealsim.measurements.step_averages`) and
    joined in the duty cycle (:func:`sealsim.calibration.rotary_fit.duty_from_speed`)."""

    window: Q("time", gt=0) = Field(30.0, description=(
        "averages over the last window of every step (Organisciak et al. 2014: 30 s)"))
    tolerance: float = Field(0.02, gt=0, lt=0.5, description=(
        "relative speed change (of the largest speed) that starts a new step; a step within "
        "it of 0 is standstill"))
    jump: Q("time", ge=0) = Field(10.0, description=(
        "a change between two steps that takes at most this long is simulated as a jump"))


class RotaryMeasurementModel(CaseModel):
    """A measured speed cycle: the file, its columns, its role and its conditions."""

    name: str = Field(min_length=1)
    file: str
    role: Literal["fit", "validate"]
    columns: dict[str, ColumnModel]
    delimiter: str | None = None
    decimal: Literal[".", ","] = "."
    header: bool = False
    skip_rows: int = Field(0, ge=0)
    conditions: dict[str, Any] = Field(default_factory=dict, description=(
        "fields of [model] that differ in this run, e.g. {environment.sump_volume = '3 L'}"))

    @model_validator(mode="after")
    def _check(self):
        allowed = {"time", "speed", "torque", "temperature"}
        unknown = sorted(set(self.columns) - allowed)
        if unknown:
            raise ValueError(f"unknown column quantities {unknown}; choose from "
                             f"{sorted(allowed)} (temperature: the spring-groove temperature)")
        missing = sorted({"time", "speed", "torque"} - set(self.columns))
        if missing:
            raise ValueError(f"columns must include {missing}")
        if re.search(r"hz|hertz", self.columns["speed"].unit, re.IGNORECASE):
            raise ValueError(f"columns.speed: unit {self.columns['speed'].unit!r} -- Hz is "
                             "ambiguous for a rotational speed; use rpm, rev/s or rad/s")
        if "duty" in self.conditions:
            raise ValueError("conditions: the duty cycle of a run is its measured speed; "
                             "remove duty from conditions")
        return self


class RotaryFitCase(CaseModel):
    """A rotary lip seal fit (see the module docstring)."""

    title: str = ""
    model: RotaryCase
    fit: RotaryFitSettings
    averaging: AveragingSettings = AveragingSettings()
    measurements: list[RotaryMeasurementModel] = Field(min_length=1)

    @model_validator(mode="after")
    def _check(self):
        if self.model.duty is not None:
            raise ValueError("model.duty: the duty cycle of a fit is each measurement's "
                             "measured speed; remove [model.duty]")
        check_measurements(self.measurements)
        paths = [p.path for p in self.fit.parameters]
        for p in self.fit.parameters:
            try:
                case_field(p.path)
            except InputError as exc:
                raise ValueError(str(exc)) from None
            if paths.count(p.path) > 1:
                raise ValueError(f"fit parameter {p.path!r} is listed twice")
        for m in self.measurements:
            fixed = set(_flatten(expand_dotted(m.conditions))) & set(paths)
            if fixed:
                raise ValueError(f"measurement {m.name!r}: conditions set the fitted "
                                 f"parameter(s) {sorted(fixed)}; a fitted parameter is the "
                                 "same in every run")
            try:
                self.run_case(m)
            except InputError as exc:
                raise ValueError(str(exc).removeprefix("invalid ")) from None
        return self

    def model_data(self) -> dict[str, Any]:
        """The [model] table as given (units as strings), without the defaults it derived."""
        return self.model.model_dump(mode="json", exclude_unset=True)

    def run_case(self, spec: RotaryMeasurementModel, duty: dict[str, Any] | None = None
                 ) -> tuple[RotaryCase, dict[str, Any]]:
        """The rotary case of one measurement (the model with its conditions and ``duty``) and
        the data it was validated from (parameters are applied to these data)."""
        data = apply_overrides(self.model_data(), expand_dotted(spec.conditions))
        if duty is not None:
            data["duty"] = duty
        where = f"measurement {spec.name!r}: model with its conditions"
        return validate_case(RotaryCase, data, where), data
