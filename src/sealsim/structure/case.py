"""Case files of the structural seal model (pydantic models; quantities with units).

Example (``examples/structure/oring_rod.toml``)::

    [seal]
    cord_diameter = "4 mm"
    inner_diameter = "20 mm"

    [gland]
    arrangement = "rod"
    sealing_diameter = "20 mm"
    groove_width = "5.4 mm"

    [material]
    elastomer = "NBR"

    [load]
    squeeze = [0.05, 0.10, 0.15, 0.20, 0.25]
    pressure = ["0 bar", "2.5 bar", "5 bar", "7.5 bar", "10 bar"]

The load path is: installation at ``installation_temperature`` to the first squeeze, the
further squeeze values, then the pressures (at the last squeeze), then the temperatures
(at the last pressure). Every listed value is one recorded load state.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, field_validator

from sealsim.cases import CaseModel, Q
from sealsim.structure.geometry import MAX_SQUEEZE

__all__ = [
    "GlandSpec",
    "LoadSpec",
    "MapSpec",
    "MaterialSpec",
    "MeshSpec",
    "SealSection",
    "SolverSpec",
    "StructureCase",
]

Squeeze = Q("dimensionless", gt=0.0, le=MAX_SQUEEZE)
Pressure = Q("pressure", ge=0.0, le=100e6)
Temperature = Q("temperature", gt=0.0, le=773.15)


class SealSection(CaseModel):
    """The free seal. Only O-rings so far (``type = "oring"``)."""

    type: Literal["oring"] = "oring"
    cord_diameter: Q("length", gt=0.0)
    inner_diameter: Q("length", gt=0.0)


class GlandSpec(CaseModel):
    """Gland: arrangement, sealing diameter (rod or bore), groove width, metal expansion."""

    arrangement: Literal["rod", "piston"] = "rod"
    sealing_diameter: Q("length", gt=0.0)
    groove_width: Q("length", gt=0.0)
    inner_expansion: Q("thermal_expansion", ge=-1e-4, lt=1e-3) = 11.5e-6
    outer_expansion: Q("thermal_expansion", ge=-1e-4, lt=1e-3) = 11.5e-6


class MaterialSpec(CaseModel):
    """Seal material from the elastomer catalogue, optionally with constants overridden."""

    elastomer: str = "NBR"
    model: Literal["hyperelastic", "viscoelastic"] = "hyperelastic"
    temperature_scaling: Literal["entropic", "modulus", "none"] = Field(
        "entropic", description=(
            "hyperelastic constants vs temperature: 'entropic' C(T) = C(T_ref)·T/T_ref "
            "(rubber elasticity, equilibrium state; above about Tg + 30 K), 'modulus' with "
            "the catalogue's E(T) at its test frequency (includes viscoelastic softening), "
            "'none' constant"))
    c10: Q("pressure", gt=0.0) | None = None
    c01: Q("pressure", ge=0.0) | None = None
    bulk_modulus: Q("pressure", gt=0.0) | None = None
    thermal_expansion: Q("thermal_expansion", ge=0.0, lt=1e-3) | None = None
    hardness_shore_a: Annotated[float, Field(ge=10.0, le=90.0)] | None = Field(
        None, description=(
            "Shore A hardness of this compound: the elastomer's hyperelastic constants (and "
            "Prony moduli) are scaled by E(S)/E(S_catalogue) of Gent's relation "
            "(sealsim.properties.elastomers.shore_a_young_modulus), e.g. for a hardness "
            "tolerance of 70 +- 5 Shore A; not together with c10/c01"))


class MeshSpec(CaseModel):
    """Mesh density: a named level or explicit element counts."""

    level: Literal["coarse", "medium", "fine", "extra_fine"] = "medium"
    n_arc: Annotated[int, Field(ge=4, le=400)] | None = None
    n_wall: Annotated[int, Field(ge=4, le=400)] | None = None
    n_radial: Annotated[int, Field(ge=1, le=100)] | None = None


class LoadSpec(CaseModel):
    """Load path: squeeze values, then pressures, then temperatures."""

    installation_temperature: Temperature = 293.15
    squeeze: list[Squeeze] = Field(min_length=1)
    squeeze_increments: Annotated[int, Field(ge=1, le=1000)] = 5
    installation_time: Q("time", ge=0.0) = 60.0
    hold_time: Q("time", ge=0.0) = 0.0
    pressure: list[Pressure] = Field(default_factory=list)
    pressure_increments: Annotated[int, Field(ge=1, le=1000)] = 2
    pressure_time: Q("time", ge=0.0) = 1.0
    temperature: list[Temperature] = Field(default_factory=list)
    temperature_increments: Annotated[int, Field(ge=1, le=10000)] = 4
    """Temperature rate of the temperature steps (sets their duration), e.g. "1 K/min"."""
    temperature_rate: Q("temperature_rate", gt=0.0) = 1.0 / 60.0
    record_increments: bool = False


class MapSpec(CaseModel):
    """Characteristic-diagram grid."""

    pressure: list[Pressure] = Field(min_length=2)
    temperature: list[Temperature] = Field(min_length=1)
    squeeze: list[Squeeze] | None = None
    squeeze_increments: Annotated[int, Field(ge=1, le=1000)] = 8
    temperature_increments: Annotated[int, Field(ge=1, le=1000)] = 4
    pressure_increments: Annotated[int, Field(ge=1, le=100)] = 1
    workers: Annotated[int, Field(ge=1, le=64)] = 2

    @field_validator("pressure", "temperature", "squeeze")
    @classmethod
    def _ascending(cls, v):
        if v is not None and any(b <= a for a, b in zip(v, v[1:])):
            raise ValueError("grid values must be strictly ascending")
        return v


class SolverSpec(CaseModel):
    """Newton tolerance, cutbacks, contact penalty, anti-rolling spring."""

    tolerance: Annotated[float, Field(gt=0.0, lt=1e-2)] = 1e-8
    max_iterations: Annotated[int, Field(ge=3, le=200)] = 25
    max_cutbacks: Annotated[int, Field(ge=0, le=30)] = 8
    penalty: Annotated[float, Field(gt=0.0, le=1e4)] = 1.0
    rolling_stiffness: Annotated[float, Field(ge=0.0, le=1e6)] = 10.0
    positioning_pressure: Pressure = 1e3


class StructureCase(CaseModel):
    """A structural seal case: seal, gland, material, mesh, load path, optional map grid."""

    title: str = ""
    seal: SealSection
    gland: GlandSpec
    material: MaterialSpec = MaterialSpec()
    mesh: MeshSpec = MeshSpec()
    load: LoadSpec
    map: MapSpec | None = None
    solver: SolverSpec = SolverSpec()
