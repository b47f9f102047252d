"""Case files of the O-ring gland design check (``sealsim gland check``).

Example (``examples/gland/piston_static.toml``)::

    [ring]
    cord_diameter = "3.53 mm"
    inner_diameter = "20.22 mm"
    material = "NBR"

    [housing]
    type = "piston"
    motion = "static"
    bore = { nominal = "25 mm", fit = "H8" }
    groove_diameter = { nominal = "19.6 mm", fit = "h9" }
    groove_width = { nominal = "4.8 mm", upper = "0.2 mm", lower = "0 mm" }
    piston_diameter = { nominal = "25 mm", fit = "f7" }

    [service]
    pressure = "100 bar"
    temperature = ["-20 degC", "100 degC"]

A dimension is its nominal size with an ISO 286 tolerance class (``fit = "H8"``) or explicit
signed deviations (``upper``, ``lower``); the ring's tolerances default to ISO 3601-1.  Which
dimensions a housing needs depends on its type (:data:`HOUSING_DIMENSIONS`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

from pydantic import Field, model_validator

from sealsim.cases import CaseModel, Q

__all__ = ["HOUSING_DIMENSIONS", "DimensionSpec", "FESpec", "GlandCase", "HousingSpec",
           "LimitsSpec", "RingSpec", "ServiceSpec", "load_gland_case"]

STEEL_EXPANSION = 11.5e-6
"""Linear thermal expansion of carbon steel [1/K] near room temperature (11-13e-6 1/K,
e.g. Callister & Rethwisch, Materials Science and Engineering, 9th ed., Table 19.1: 1020
steel 11.7e-6 1/K); the default of both metal parts, as in the structure case."""


class DimensionSpec(CaseModel):
    """A toleranced size: nominal with an ISO 286 class or explicit signed deviations."""

    nominal: Q("length", ge=0.0)
    fit: str | None = Field(None, description=(
        "ISO 286 tolerance class, e.g. 'H8' (hole) or 'f7' (shaft); D-H, JS holes and "
        "d-h, js shafts, grades 5-11, sizes up to 500 mm"))
    upper: Q("length", ge=-0.01, le=0.01) | None = Field(None, description=(
        "upper deviation (signed), e.g. '0.2 mm'"))
    lower: Q("length", ge=-0.01, le=0.01) | None = Field(None, description=(
        "lower deviation (signed), e.g. '-0.05 mm'"))

    @model_validator(mode="after")
    def _one_tolerance(self):
        explicit = (self.upper, self.lower)
        if self.fit is not None and any(v is not None for v in explicit):
            raise ValueError("give either fit (an ISO 286 class) or upper and lower "
                             "deviations, not both")
        if self.fit is None and None in explicit:
            raise ValueError("a dimension needs its tolerance: fit = 'H8' (ISO 286) or "
                             "upper and lower deviations, e.g. upper = '0.1 mm', "
                             "lower = '0 mm'")
        if self.fit is None and self.upper < self.lower:
            raise ValueError(f"upper deviation {self.upper * 1e3:g} mm is below the lower "
                             f"deviation {self.lower * 1e3:g} mm")
        return self

    def limits(self, field: str) -> tuple[float, float]:
        """(smallest, largest) size [m]."""
        if self.fit is not None:
            from sealsim.structure.tolerances import iso286_deviations

            lo, hi = iso286_deviations(self.nominal, self.fit, f"{field}.fit")
        else:
            lo, hi = self.lower, self.upper
        return self.nominal + lo, self.nominal + hi


class RingSpec(CaseModel):
    """The O-ring (or X-ring): size, tolerances, material."""

    type: Literal["oring", "xring"] = "oring"
    cord_diameter: Q("length", gt=0.0, le=0.05)
    inner_diameter: Q("length", gt=0.0, le=2.0)
    cord_tolerance: Q("length", ge=0.0, le=1e-3) | None = Field(None, description=(
        "± tolerance of the cross-section (default: ISO 3601-1)"))
    inner_diameter_tolerance: Q("length", ge=0.0, le=0.02) | None = Field(None, description=(
        "± tolerance of the inside diameter (default: ISO 3601-1)"))
    material: str = Field(description="catalogue elastomer (sealsim material list), e.g. 'NBR'")
    hardness_shore_a: float | None = Field(None, ge=30.0, le=95.0, description=(
        "Shore A hardness (default: the catalogue's)"))
    thermal_expansion: Q("thermal_expansion", gt=0.0, lt=1e-3) | None = Field(None, description=(
        "linear thermal expansion of the rubber (default: the catalogue's)"))


#: Dimensions of each housing type (all required).
HOUSING_DIMENSIONS = {
    "piston": ("bore", "groove_diameter", "groove_width", "piston_diameter"),
    "rod": ("rod", "groove_diameter", "groove_width", "bore"),
    "face": ("groove_depth", "groove_width", "groove_inner_diameter", "gap"),
}

_DIMENSION_HELP = {
    "bore": "piston gland: cylinder bore the ring seals on; rod gland: bore the rod passes "
            "through (sets the extrusion gap)",
    "rod": "rod the ring seals on (rod gland)",
    "piston_diameter": "piston outer diameter next to the groove (sets the extrusion gap)",
    "groove_diameter": "groove bottom diameter (piston: inner; rod: outer)",
    "groove_width": "axial groove width (face gland: radial width)",
    "groove_depth": "face gland: axial groove depth",
    "groove_inner_diameter": "face gland: inner diameter of the groove",
    "gap": "face gland: flange separation under pressure (0 for metal-to-metal contact)",
}


class HousingSpec(CaseModel):
    """The gland: type (piston, rod or face), motion, toleranced dimensions, metal expansion."""

    type: Literal["piston", "rod", "face"]
    motion: Literal["static", "reciprocating"]
    bore: DimensionSpec | None = Field(None, description=_DIMENSION_HELP["bore"])
    rod: DimensionSpec | None = Field(None, description=_DIMENSION_HELP["rod"])
    piston_diameter: DimensionSpec | None = Field(
        None, description=_DIMENSION_HELP["piston_diameter"])
    groove_diameter: DimensionSpec | None = Field(
        None, description=_DIMENSION_HELP["groove_diameter"])
    groove_width: DimensionSpec | None = Field(None, description=_DIMENSION_HELP["groove_width"])
    groove_depth: DimensionSpec | None = Field(None, description=_DIMENSION_HELP["groove_depth"])
    groove_inner_diameter: DimensionSpec | None = Field(
        None, description=_DIMENSION_HELP["groove_inner_diameter"])
    gap: DimensionSpec | None = Field(None, description=_DIMENSION_HELP["gap"])
    inner_expansion: Q("thermal_expansion", ge=-1e-4, lt=1e-3) = Field(
        STEEL_EXPANSION, description="linear expansion of the inner part (rod, or piston with "
                                     "the groove; face gland: the flange with the groove)")
    outer_expansion: Q("thermal_expansion", ge=-1e-4, lt=1e-3) = Field(
        STEEL_EXPANSION, description="linear expansion of the outer part (housing with the "
                                     "groove, or cylinder; not used by a face gland)")

    @model_validator(mode="after")
    def _dimensions_of_type(self):
        needed = HOUSING_DIMENSIONS[self.type]
        given = {name for names in HOUSING_DIMENSIONS.values() for name in names
                 if getattr(self, name) is not None}
        missing = [n for n in needed if getattr(self, n) is None]
        if missing:
            raise ValueError(f"a {self.type} gland needs {', '.join(missing)} "
                             f"({'; '.join(f'{n}: {_DIMENSION_HELP[n]}' for n in missing)})")
        extra = sorted(given - set(needed))
        if extra:
            raise ValueError(f"{', '.join(extra)} do(es) not belong to a {self.type} gland; it "
                             f"takes {', '.join(needed)}")
        if self.type == "face" and self.motion != "static":
            raise ValueError("a face gland is static: housing.motion = 'static'")
        self._check_fits(self.dimension_limits())
        return self

    def _check_fits(self, limits: dict[str, tuple[float, float, float]]) -> None:
        """Refuse a gland whose parts do not go together at some tolerance limit: a piston or
        rod larger than its bore, a groove bottom outside its land, a groove without width
        or depth, flanges closer than touching."""
        def mm(x):
            return f"{x * 1e3:.4g} mm"

        def lo(name):
            return limits[name][0]

        def hi(name):
            return limits[name][2]

        problems = []
        if self.type in ("piston", "rod"):
            inner = "piston_diameter" if self.type == "piston" else "rod"
            if hi(inner) > lo("bore"):
                problems.append(
                    f"housing.{inner}: up to {mm(hi(inner))} does not fit the bore from "
                    f"{mm(lo('bore'))}: the diametral clearance must be >= 0 at every tolerance "
                    "limit (a clearance fit, e.g. bore H8 with f7)")
            if self.type == "piston" and hi("groove_diameter") >= lo("piston_diameter"):
                problems.append(
                    f"housing.groove_diameter: up to {mm(hi('groove_diameter'))} is not below "
                    f"the piston diameter from {mm(lo('piston_diameter'))}: the groove bottom "
                    "must lie inside the piston")
            if self.type == "rod" and lo("groove_diameter") <= hi("bore"):
                problems.append(
                    f"housing.groove_diameter: from {mm(lo('groove_diameter'))} is not above "
                    f"the rod bore up to {mm(hi('bore'))}: the groove bottom must lie outside "
                    "the bore the rod passes through")
        else:
            for name in ("groove_depth", "groove_inner_diameter"):
                if lo(name) <= 0.0:
                    problems.append(f"housing.{name}: from {mm(lo(name))}; it must be > 0 mm")
            if lo("gap") < 0.0:
                problems.append(f"housing.gap: from {mm(lo('gap'))}; the flange separation "
                                "is >= 0 mm (0: metal to metal)")
        if lo("groove_width") <= 0.0:
            problems.append(f"housing.groove_width: from {mm(lo('groove_width'))}; it must be "
                            "> 0 mm")
        if problems:
            raise ValueError(f"a {self.type} gland whose parts do not go together: "
                             + "; ".join(problems))

    def dimension_limits(self) -> dict[str, tuple[float, float, float]]:
        """{name: (smallest, middle, largest)} [m] of the housing's dimensions (the middle of
        the tolerance band is what the gland check calls nominal)."""
        out = {}
        for name in HOUSING_DIMENSIONS[self.type]:
            lo, hi = getattr(self, name).limits(f"housing.{name}")
            out[name] = (lo, 0.5 * (lo + hi), hi)
        return out


class ServiceSpec(CaseModel):
    """Operating conditions: pressure, temperature range, fluid swell."""

    pressure: Q("pressure", ge=0.0, le=1e9) = Field(description=(
        "highest pressure difference across the seal, e.g. '100 bar'"))
    temperature: list[Q("temperature", gt=0.0, le=673.15)] = Field(
        min_length=1, max_length=2, description=(
            "lowest and highest service temperature, e.g. ['-20 degC', '100 degC']"))
    assembly_temperature: Q("temperature", gt=0.0, le=673.15) = Field(293.15, description=(
        "temperature at which the dimensions are given and the gland is assembled (ISO 1: "
        "20 degC)"))
    fluid_swell: Q("dimensionless", ge=-0.2, le=1.0) = Field(0.0, description=(
        "volume change of the ring in the fluid, e.g. '5 %' (or 0.05); the ring is checked "
        "both unswollen (at assembly) and swollen"))

    @model_validator(mode="after")
    def _ordered(self):
        if len(self.temperature) == 2 and self.temperature[1] < self.temperature[0]:
            raise ValueError("service.temperature: give [lowest, highest]")
        return self


class FESpec(CaseModel):
    """FE contact force and friction at nominal (``--fe``)."""

    velocity: Q("velocity", gt=0.0, le=20.0) = Field(description=(
        "sliding velocity at which the friction is evaluated, e.g. '0.1 m/s'"))
    law: dict[str, Any] | None = Field(None, description=(
        "friction law as a [friction] table of a friction case (default: the one-call API's "
        "default law, sealsim.api.DEFAULT_LAW)"))
    mesh: Literal["coarse", "medium", "fine"] = "coarse"


class LimitsSpec(CaseModel):
    """Your own design limits, replacing the published ones (each is reported as yours)."""

    squeeze_min: Q("dimensionless", ge=0.0, le=1.0) | None = Field(
        None, description="e.g. '8 %' (or 0.08)")
    squeeze_max: Q("dimensionless", ge=0.0, le=1.0) | None = None
    stretch_max: Q("dimensionless", ge=0.0, le=1.0) | None = None
    stretch_min: Q("dimensionless", ge=-1.0, le=1.0) | None = Field(None, description=(
        "piston glands, at assembly: e.g. 0.01 (1 %); below 0 allows a floating ring"))
    gland_fill_max: Q("dimensionless", ge=0.0, le=1.2) | None = None
    extrusion_gap_max: Q("length", ge=0.0, le=0.01) | None = Field(None, description=(
        "largest diametral extrusion gap, e.g. '0.1 mm'"))


class GlandCase(CaseModel):
    """An O-ring gland to check: ring, housing, service, optional FE and own limits."""

    title: str = ""
    ring: RingSpec
    housing: HousingSpec
    service: ServiceSpec
    fe: FESpec | None = None
    limits: LimitsSpec = LimitsSpec()


def load_gland_case(path: str | Path, source: str | None = None) -> GlandCase:
    """Read and validate a gland case file (no variants: one gland per file)."""
    from sealsim.cases import load_toml, validate_case
    from sealsim.errors import InputError

    data = load_toml(path)
    if "variants" in data:
        raise InputError(f"{path}: a gland case checks one gland; remove the [variants] "
                         "tables (write one file per gland)")
    return validate_case(GlandCase, data, source or str(path))
