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

Seal sections (``seal.type``): ``"oring"`` (cord_diameter, inner_diameter), ``"xring"``
(cord_diameter, inner_diameter, optional lobe_radius and valley_depth as fractions of the
cord), ``"rectangular"`` (width, height, inner_diameter, corner_radius), ``"ucup"`` and
``"wiper"`` (lip_diameter, height, width; the dynamic lip is on the sealing side of the
gland), ``"radial_lip"`` (a DIN 3760 shaft seal: outer_diameter, width, garter spring; with
``gland.arrangement = "shaft"``) and ``"user"`` (a closed polyline ``points`` in
``points_unit``, optional ``bulges`` and ``tags``, or a ``dxf`` drawing; a relative path is
relative to the case file). A material needs no catalogue name: ``c10``, ``c01`` and
``bulk_modulus`` alone define a custom Mooney–Rivlin rubber; ``material = "my_nbr.toml"``
(or ``[material] elastomer = "my_nbr.toml"``) takes a compound file, e.g. one written by
``sealsim material fit``, relative to the case file.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, field_validator, model_validator

from sealsim.cases import CaseModel, Q
from sealsim.errors import InputError
from sealsim.structure.geometry import MAX_SQUEEZE

__all__ = [
    "CUSTOM_THERMAL_EXPANSION",
    "DEFAULT_GLAND_FRICTION",
    "GlandSpec",
    "LoadSpec",
    "MapSpec",
    "MaterialSpec",
    "MeshSpec",
    "SEAL_FIELDS",
    "SealSection",
    "SolverSpec",
    "StructureCase",
    "load_structure_cases",
]

Squeeze = Q("dimensionless", gt=0.0, le=MAX_SQUEEZE)
Pressure = Q("pressure", ge=0.0, le=100e6)
Temperature = Q("temperature", gt=0.0, le=773.15)
Length = Q("length", gt=0.0)

SEAL_FIELDS = {
    # type: (required fields, optional fields)
    "oring": (("cord_diameter", "inner_diameter"), ()),
    "xring": (("cord_diameter", "inner_diameter"), ("lobe_radius", "valley_depth")),
    "rectangular": (("width", "height", "inner_diameter"), ("corner_radius",)),
    "ucup": (("lip_diameter", "height", "width"),
             ("lip_thickness", "groove_depth", "flare", "edge_radius")),
    "wiper": (("lip_diameter", "height", "width"), ("lip_thickness", "flare", "edge_radius")),
    "radial_lip": (("outer_diameter", "width"),
                   ("interference", "flex_thickness", "spring_coil_diameter", "spring_offset",
                    "oil_side_angle", "air_side_angle", "flex_angle", "edge_radius",
                    "spring_rate", "spring_tension")),
    "user": ((), ("points", "bulges", "tags", "points_unit", "dxf", "dxf_layer", "dxf_unit",
                  "drawing", "spring_rate", "spring_tension")),
}
"""Fields of ``[seal]`` per section type: (required, optional)."""


class SealSection(CaseModel):
    """The free seal section: a parametric family or a user contour (``type``)."""

    type: Literal["oring", "xring", "rectangular", "ucup", "wiper", "radial_lip", "user"] = \
        "oring"
    cord_diameter: Length | None = None
    inner_diameter: Length | None = None
    outer_diameter: Length | None = None
    lip_diameter: Length | None = Field(None, description=(
        "diameter of the dynamic lip edge of the free seal (U-cup, wiper)"))
    width: Length | None = None
    height: Length | None = None
    corner_radius: Q("length", ge=0.0) | None = None
    lobe_radius: Annotated[float, Field(ge=0.1, le=0.35)] | None = None
    valley_depth: Annotated[float, Field(ge=0.02, le=0.2)] | None = None
    lip_thickness: Length | None = None
    groove_depth: Length | None = None
    flare: Q("length", ge=0.0) | None = None
    edge_radius: Q("length", ge=0.0) | None = None
    interference: Length | None = None
    flex_thickness: Length | None = None
    spring_coil_diameter: Length | None = None
    spring_offset: Q("length", ge=-5e-3, le=5e-3) | None = None
    oil_side_angle: Annotated[float, Field(gt=20.0, lt=80.0)] | None = None
    air_side_angle: Annotated[float, Field(gt=5.0, lt=60.0)] | None = None
    flex_angle: Annotated[float, Field(ge=30.0, le=90.0)] | None = None
    spring_rate: Q("stiffness", ge=0.0) | None = Field(None, description=(
        "axial rate of the straight garter spring (default from its coil and wire size)"))
    spring_tension: Q("force", ge=0.0) | None = Field(None, description=(
        "hoop pre-tension of the garter spring in the free seal"))
    points: list[tuple[float, float]] | None = Field(None, description=(
        "closed polyline [[z, r], ...] in points_unit (z axial, r radius)"))
    bulges: list[float] | None = None
    tags: list[Literal["", "bonded", "spring", "contact"]] | None = None
    points_unit: str = "mm"
    dxf: str | None = None
    dxf_layer: str | None = None
    dxf_unit: str = Field("mm", description=(
        "length unit of the drawing's numbers; default: millimetres when the drawing "
        "declares mm or no unit ($INSUNITS), any other declared unit must be confirmed here"))
    drawing: str | None = Field(None, description="the DXF file the points were read from")

    @model_validator(mode="after")
    def _fields_of_type(self):
        required, optional = SEAL_FIELDS[self.type]
        given = {k for k in type(self).model_fields if k != "type"
                 and getattr(self, k) is not None
                 and getattr(self, k) != type(self).model_fields[k].default}
        missing = [k for k in required if getattr(self, k) is None]
        if missing:
            raise ValueError(f"seal.type = {self.type!r} needs {', '.join(missing)}")
        extra = sorted(given - set(required) - set(optional))
        if extra:
            raise ValueError(f"{', '.join(extra)} do(es) not belong to seal.type = "
                             f"{self.type!r}; it takes {', '.join(required + optional)}")
        if self.type == "user":
            if (self.points is None) == (self.dxf is None):
                raise ValueError("seal.type = 'user' needs either points (a closed polyline) "
                                 "or dxf (a drawing)")
            for name in ("points_unit", "dxf_unit"):
                _unit_factor(getattr(self, name), f"seal.{name}")
        return self

    def unit_factor(self) -> float:
        """Metres per unit of ``points``."""
        return _unit_factor(self.points_unit, "seal.points_unit")


def _unit_factor(unit: str, field: str) -> float:
    from sealsim.units import parse_quantity

    try:
        return parse_quantity(f"1 {unit}", "length")
    except (InputError, ValueError) as exc:
        raise ValueError(f"{field}: {unit!r} is not a length unit ({exc})") from None


DEFAULT_GLAND_FRICTION = 0.2
"""Coulomb friction coefficient of the seal on the groove bottom and walls [-]: greased rubber
on machined steel at rest, in the 0.1–0.3 range of boundary-lubricated rubber friction
(Moore, The Friction and Lubrication of Elastomers, Pergamon 1972). It holds the section in
the groove like the static friction of a real gland (no anti-rolling spring needed). The
sealing surface is frictionless by default: the friction there is the friction law's job."""


class GlandSpec(CaseModel):
    """Gland: arrangement, sealing diameter (rod, bore or shaft), groove width, walls,
    friction, metal expansion."""

    arrangement: Literal["rod", "piston", "shaft"] = "rod"
    sealing_diameter: Q("length", gt=0.0)
    groove_width: Q("length", gt=0.0) | None = None
    walls: bool = Field(True, description=(
        "groove side walls; without them the section bulges freely and is held axially by "
        "symmetry (no pressure load then)"))
    friction: Annotated[float, Field(ge=0.0, le=2.0)] = Field(DEFAULT_GLAND_FRICTION,
        description="Coulomb coefficient on the groove bottom and walls")
    sealing_friction: Annotated[float, Field(ge=0.0, le=2.0)] = Field(0.0, description=(
        "Coulomb coefficient on the sealing surface (rod, bore, shaft)"))
    wall_friction: Annotated[float, Field(ge=0.0, le=2.0)] | None = Field(None, description=(
        "Coulomb coefficient on the groove walls (default: friction)"))
    clearance: Q("length", gt=0.0) | None = Field(None, description=(
        "radial gap between the sealing surface and the groove's lands, e.g. '0.5 mm' (piston: "
        "(bore - piston diameter)/2): the walls end at the lands' edges and the seal can bulge "
        "into the gap; not given: the walls reach the sealing surface"))
    land_edge_radius: Q("length", gt=0.0) | None = Field(None, description=(
        "radius of the lands' edges next to the clearance gap (default 0.1 mm)"))
    inner_expansion: Q("thermal_expansion", ge=-1e-4, lt=1e-3) = 11.5e-6
    outer_expansion: Q("thermal_expansion", ge=-1e-4, lt=1e-3) = 11.5e-6

    @model_validator(mode="after")
    def _groove(self):
        if self.groove_width is None and self.arrangement != "shaft":
            raise ValueError(f"gland.groove_width is needed for arrangement = "
                             f"{self.arrangement!r}")
        if self.arrangement == "shaft" and self.clearance is not None:
            raise ValueError("gland.clearance is for rod and piston grooves, not for "
                             "arrangement = 'shaft'")
        if self.land_edge_radius is not None and self.clearance is None:
            raise ValueError("gland.land_edge_radius needs gland.clearance (without a "
                             "clearance the walls reach the sealing surface)")
        return self


CUSTOM_THERMAL_EXPANSION = 2.0e-4
"""Linear thermal expansion [1/K] of a custom material when none is given: the middle of
1.5–2.5e-4 1/K of filled NBR, HNBR, FKM and EPDM (Gent, Engineering with Rubber, 3rd ed.,
Hanser 2012, ch. 2)."""


class MaterialSpec(CaseModel):
    """Seal material: a catalogue elastomer (optionally with constants overridden), or a
    custom Mooney–Rivlin rubber given only by ``c10``, ``c01`` and ``bulk_modulus``."""

    elastomer: str | None = None
    model: Literal["hyperelastic", "viscoelastic"] = "hyperelastic"
    temperature_scaling: Literal["held", "entropic", "modulus", "none"] | None = Field(
        None, description=(
            "hyperelastic constants vs temperature: 'held' (default for a catalogue rubber) "
            "C(T) = C_ref·E_h(T)/E(T_ref, f_test), the relaxed modulus of a seal held for an "
            "hour from the catalogue's master curve (sealsim's convention for an installed "
            "seal, also of the rotary lip force); 'entropic' C(T) = C(T_ref)·T/T_ref (rubber "
            "elasticity, equilibrium state; default for a custom rubber); 'modulus' with the "
            "catalogue's E(T) at a frequency (the dynamic modulus at that rate); 'none' "
            "constant"))
    modulus_frequency: Q("frequency", gt=0.0) | None = Field(None, description=(
        "frequency of E(T) for temperature_scaling = 'modulus' (default: the catalogue's)"))
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
    constants_temperature: Temperature | None = Field(None, description=(
        "custom material: temperature at which c10 and c01 hold (default: installation)"))

    @model_validator(mode="after")
    def _catalogue_or_custom(self):
        if self.elastomer is None:
            if self.custom:
                if self.model != "hyperelastic" or self.temperature_scaling in ("modulus",
                                                                                 "held"):
                    raise ValueError("a custom material (no elastomer name) is hyperelastic "
                                     "with temperature_scaling 'entropic' or 'none': the "
                                     "catalogue supplies the viscoelastic data")
            else:
                object.__setattr__(self, "elastomer", "NBR")
        if self.temperature_scaling is None:
            object.__setattr__(self, "temperature_scaling",
                               "entropic" if self.custom else "held")
        elif self.constants_temperature is not None:
            raise ValueError("material.constants_temperature is for a custom material only "
                             "(no elastomer name)")
        return self

    @property
    def custom(self) -> bool:
        """True for a custom Mooney–Rivlin rubber without a catalogue entry."""
        return self.elastomer is None and None not in (self.c10, self.c01, self.bulk_modulus)


class MeshSpec(CaseModel):
    """Mesh density: a named level, or explicit element counts (O-ring) or sizes (profiles)."""

    level: Literal["coarse", "medium", "fine", "extra_fine"] = "medium"
    n_arc: Annotated[int, Field(ge=4, le=400)] | None = None
    n_wall: Annotated[int, Field(ge=4, le=400)] | None = None
    n_radial: Annotated[int, Field(ge=1, le=100)] | None = None
    size_contact: Q("length", gt=0.0) | None = None
    size_body: Q("length", gt=0.0) | None = None
    backend: Literal["auto", "gmsh", "builtin"] = Field("auto", description=(
        "mesher of profiles: gmsh where it loads, else the built-in one"))


class LoadSpec(CaseModel):
    """Load path: squeeze values, then pressures, then temperatures."""

    installation_temperature: Temperature = 293.15
    squeeze: list[Squeeze] | None = Field(None, min_length=1, description=(
        "squeeze values; a shaft seal's squeeze is its interference (leave it out)"))
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
    profile_points: Annotated[int, Field(ge=3, le=1001)] = Field(41, description=(
        "positions across the groove where the contact pressure profile is stored"))

    @field_validator("pressure", "temperature", "squeeze")
    @classmethod
    def _ascending(cls, v):
        if v is not None and any(b <= a for a, b in zip(v, v[1:])):
            raise ValueError("grid values must be strictly ascending")
        return v


class SolverSpec(CaseModel):
    """Newton tolerance, cutbacks, contact penalty, friction regularisation, anti-rolling
    spring."""

    tolerance: Annotated[float, Field(gt=0.0, lt=1e-2)] = 1e-8
    max_iterations: Annotated[int, Field(ge=3, le=200)] = 25
    max_cutbacks: Annotated[int, Field(ge=0, le=30)] = 8
    penalty: Annotated[float, Field(gt=0.0, le=1e4)] = 1.0
    elastic_slip: Annotated[float, Field(gt=0.0, le=0.1)] = Field(1e-3, description=(
        "allowed elastic slip of sticking contact nodes as a fraction of the section's "
        "contact size (FElupe's penalty friction)"))
    rolling_stiffness: Annotated[float, Field(ge=0.0, le=1e6)] = Field(0.0, description=(
        "anti-rolling spring in units of G·A·2πR (0: off; the gland friction holds the "
        "section)"))
    positioning_pressure: Pressure = 1e3
    increment_growth: bool = Field(True, description=(
        "a cut-back increment grows back after easy increments (false: it only doubles where "
        "the load reaches the step's nominal grid, the control before sealsim's FE model 6)"))


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

    @field_validator("material", mode="before")
    @classmethod
    def _material_name(cls, value):
        # material = "NBR" or "my_nbr.toml": shorthand for [material] elastomer = ...
        return {"elastomer": value} if isinstance(value, str) else value

    @model_validator(mode="after")
    def _consistent(self):
        shaft = self.gland.arrangement == "shaft"
        if shaft and self.seal.type not in ("radial_lip", "user"):
            raise ValueError("gland.arrangement = 'shaft' is for radial lip seals: seal.type "
                             "'radial_lip' or a 'user' profile with bonded edges")
        if self.seal.type == "radial_lip" and not shaft:
            raise ValueError("seal.type = 'radial_lip' needs gland.arrangement = 'shaft'")
        if shaft and self.load.squeeze is not None:
            raise ValueError("load.squeeze: a shaft seal's squeeze is set by its interference "
                             "on the shaft; leave load.squeeze out")
        if not shaft and self.load.squeeze is None:
            raise ValueError("load.squeeze is needed (a list of squeeze values)")
        if shaft and self.map is not None and self.map.squeeze is not None:
            raise ValueError("map.squeeze: not for a shaft seal (its interference is fixed)")
        if not self.gland.walls and (any(p > 0 for p in self.load.pressure)
                                     or (self.map is not None
                                         and any(p > 0 for p in self.map.pressure))):
            raise ValueError("a pressure load needs the groove walls (gland.walls = true): "
                             "without walls nothing holds the seal against the pressure")
        return self


def _resolve_drawing(seal, base: Path) -> None:
    """Read a ``seal.dxf`` drawing into ``seal.points``/``bulges`` (in place)."""
    if not isinstance(seal, dict) or seal.get("dxf") is None:
        return
    from sealsim.structure.contour import contour_from_dxf, dxf_declared_unit

    path = Path(str(seal["dxf"]))
    path = path if path.is_absolute() else base / path
    unit_text = seal.get("dxf_unit")
    if unit_text is None:
        declared = dxf_declared_unit(path, name=f"seal.dxf {str(path)!r}")
        if declared not in (None, "mm"):
            raise InputError(f"seal.dxf {str(path)!r}: the drawing declares its unit as "
                             f"{declared!r} ($INSUNITS); give seal.dxf_unit = '{declared}' to "
                             "read it so, or seal.dxf_unit = 'mm' if its numbers are "
                             "millimetres")
        unit_text = "mm"   # declared mm, or no unit declared: millimetres
    unit = _unit_factor(str(unit_text), "seal.dxf_unit")
    out_unit = str(seal.get("points_unit", "mm"))
    scale = _unit_factor(out_unit, "seal.points_unit")
    contour = contour_from_dxf(path, layer=seal.get("dxf_layer"), unit=unit,
                               name=f"seal.dxf {str(path)!r}")
    seal["points"] = [[float(x / scale), float(y / scale)] for x, y in contour.points]
    seal["bulges"] = [float(b) for b in contour.bulges]
    seal["drawing"] = str(seal.pop("dxf"))
    seal.pop("dxf_layer", None)
    seal.pop("dxf_unit", None)


def load_structure_cases(path, source: str | None = None) -> dict[str, StructureCase]:
    """Read and validate a structure case file with its variants; a ``seal.dxf`` drawing
    (relative to the case file) is read into ``seal.points``, so the resolved case holds the
    geometry itself."""
    from sealsim.cases import expand_variants, load_toml

    path = Path(path)
    data = load_toml(path)
    base = path.parent
    _resolve_drawing(data.get("seal"), base)
    for overrides in (data.get("variants") or {}).values():
        if isinstance(overrides, dict):
            _resolve_drawing(overrides.get("seal"), base)
    return expand_variants(StructureCase, data, source=source or str(path))
