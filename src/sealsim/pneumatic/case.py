"""Pneumatic cylinder case files (TOML, quantities with units), validated by pydantic.

A case (see ``examples/pneumatic/cylinder_32.toml``)::

    title = "Ø32 cylinder"

    [cylinder]                       # geometry, moving mass, end stops, cushioning
    bore = "32 mm"
    rod_diameter = "12 mm"
    stroke = "100 mm"
    dead_volume_cap = "5 cm**3"      # chamber 1 (port A) at x = 0, incl. tubing to the valve
    dead_volume_rod = "5 cm**3"      # chamber 2 (port B) at x = stroke
    piston_mass = "0.4 kg"           # piston + rod
    incline = "0 deg"                # extend direction above the horizontal (gravity)
    temperature = "25 degC"          # barrel (wall heat); default air.temperature
    seal_temperature = "25 degC"     # seals; default the barrel temperature
    cushion_rod = { length = "10 mm", conductance = "0.1 dm**3/(s*bar)" }   # optional

    [load]                           # on the rod; force > 0 resists extension
    mass = "2 kg"
    force = "50 N"

    [air]
    supply_pressure = "6 bar"        # gauge
    temperature = "25 degC"          # ambient and supply air
    heat_transfer_coefficient = "38 W/(m**2*K)"   # default; or heat_transfer = "free_convection"

    [valve]
    type = "5/2"                     # or "5/3" with centre = "closed" | "exhaust" | "pressure"
    conductance = "1 dm**3/(s*bar)"  # ISO 6358 C of each path, b below
    critical_pressure_ratio = 0.3
    time_constant = "5 ms"           # spool lag; delay = dead time
    meter_out = { conductance_a = "0.2 dm**3/(s*bar)", conductance_b = "0.2 dm**3/(s*bar)" }

    [controller]                     # mode = "cycle" (PLC) or "position" (test rig)
    mode = "cycle"
    duration = "4 s"
    steps = [{ command = "extend", duration = "1 s" }, { command = "retract", duration = "1 s" }]

    [[seals]]                        # piston seal, rod seal, wiper: any friction law
    name = "piston"
    location = "piston"
    friction = { law = "theta", parameter_set = "pneumatic_demo" }
    map = { analytic = { cord_diameter = "2.5 mm", squeeze = 0.12 } }   # or file / structure_case

    [variants.T55C]
    cylinder.seal_temperature = "55 degC"

:func:`load_pneumatic_cases` validates a file (every problem in one
:class:`~sealsim.errors.InputError` naming the field); :func:`build_seals` makes the seal objects
(friction law + contact map).  From Python, numbers are SI: ``PneumaticCase(cylinder={"bore":
0.032, ...}, ...)``.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from sealsim.cases import CaseModel, Q, expand_variants, load_toml
from sealsim.errors import InputError
from sealsim.friction import make_law
from sealsim.friction.profiles import profile_type
from sealsim.friction.case import LawParameters
from sealsim.friction.parameters import parameter_set_note
from sealsim.pneumatic.chambers import DEFAULT_HEAT_TRANSFER_COEFFICIENT
from sealsim.pneumatic.contact_maps import (
    AnalyticContactMap,
    FEContactMap,
    build_or_load_fe_map,
)
from sealsim.pneumatic.seals import Seal

__all__ = [
    "AirModel",
    "CylinderModel",
    "PneumaticCase",
    "SealModel",
    "SealThermalModel",
    "ThermalModel",
    "ValveModel",
    "build_seals",
    "case_input_files",
    "load_pneumatic_case_file",
    "load_pneumatic_cases",
]


#: Temperatures of air, cylinder body and seals [K]: -60 ... +200 degC.  It covers the service
#: ranges of every seal elastomer in the catalogue (VMQ from -50 degC, FKM up to +200 degC) and
#: keeps the model's ideal gas with constant heat capacities honest: c_p of air is 1.003
#: kJ/(kg K) at 250 K and 1.025 at 475 K (Cengel & Boles, Thermodynamics, Table A-2b), i.e.
#: within 2 % of the constant value.  Beyond it the case is a typo (5000 K), not a cylinder.
TEMPERATURE_MIN, TEMPERATURE_MAX = 213.15, 473.15
#: Longest simulated time without asking [s]; ``solver.max_duration`` raises it.
MAX_DURATION = 600.0
#: Most output samples per variant without asking; ``output.max_samples`` raises it (each
#: sample is a row of about 25 numbers in memory and in timeseries.csv).
MAX_SAMPLES = 1_000_000


def _temperature():
    return Q("temperature", ge=TEMPERATURE_MIN, le=TEMPERATURE_MAX)


# -- cylinder -------------------------------------------------------------------------------
class EndStopModel(CaseModel):
    """Elastic end stops (bumper rings): stiff spring–damper contacts."""

    stiffness: Q("stiffness", gt=0) = 2.0e6
    damping: Q("damping", ge=0) = 2.0e3
    damping_depth: Q("length", gt=0) = 5.0e-5


class CushionModel(CaseModel):
    """End cushioning: over the last ``length`` of the stroke the air leaving the chamber must
    pass the cushioning needle (conductance C); air entering passes a check valve."""

    length: Q("length", gt=0)
    conductance: Q("flow_conductance", gt=0)
    entry: Q("length", gt=0) = 1.0e-3


class CylinderModel(CaseModel):
    """Double-acting single-rod cylinder (x = 0 retracted, x = stroke extended).

    ``temperature`` is the temperature of the cylinder body -- the barrel wall the chamber air
    exchanges heat with; default ``air.temperature``.  ``seal_temperature`` is the temperature
    of the seals (where their contact maps are evaluated) unless a seal gives its own; default
    the body temperature.  Heipl & Murrenhoff (Fig. 10) vary the temperature of the seals to
    show the effect of their contact force on the motion."""

    bore: Q("length", gt=0)
    rod_diameter: Q("length", gt=0)
    stroke: Q("length", gt=0)
    dead_volume_cap: Q("volume", gt=0)
    dead_volume_rod: Q("volume", gt=0)
    piston_mass: Q("mass", gt=0)
    incline: Q("angle", ge=-math.pi / 2, le=math.pi / 2) = 0.0
    temperature: _temperature() | None = None
    seal_temperature: _temperature() | None = None
    end_stops: EndStopModel = EndStopModel()
    cushion_cap: CushionModel | None = None
    cushion_rod: CushionModel | None = None

    @model_validator(mode="after")
    def _check(self):
        if self.rod_diameter >= self.bore:
            raise ValueError(f"rod_diameter ({self.rod_diameter * 1e3:g} mm) must be smaller "
                             f"than the bore ({self.bore * 1e3:g} mm)")
        for name in ("cushion_cap", "cushion_rod"):
            c = getattr(self, name)
            if c is not None and c.length >= self.stroke:
                raise ValueError(f"{name}.length ({c.length * 1e3:g} mm) must be shorter than "
                                 f"the stroke ({self.stroke * 1e3:g} mm)")
        return self


class LoadModel(CaseModel):
    """External load on the rod (force > 0 resists extension)."""

    mass: Q("mass", ge=0) = 0.0
    force: Q("force") = 0.0
    stiffness: Q("stiffness", ge=0) = 0.0
    spring_free_position: Q("length") = 0.0
    viscous: Q("damping", ge=0) = 0.0


class AirModel(CaseModel):
    """Supply, ambient and heat transfer."""

    supply_pressure: Q("pressure", gt=0)
    ambient_pressure: Q("pressure", gt=0) = 101325.0
    temperature: _temperature() = 293.15
    supply_temperature: _temperature() | None = None
    heat_transfer_coefficient: Q("heat_transfer_coefficient", ge=0) = Field(
        DEFAULT_HEAT_TRANSFER_COEFFICIENT, description=(
            "air-wall heat transfer in the chambers (default 38 W/(m**2*K): the polytropic "
            "exponent 1.2 of Richer & Hurmuzlu 2000 for a stroke of the Ø32 example, see "
            "sealsim.pneumatic.chambers); 0: adiabatic"))
    heat_transfer: Literal["constant", "free_convection"] = Field(
        "constant", description=(
            "'constant': heat_transfer_coefficient; 'free_convection': Churchill & Chu free "
            "convection at each chamber's pressure and temperature (the lower bound: no jet, "
            "no piston stirring; sealsim.pneumatic.chambers.free_convection_coefficient)"))

    @model_validator(mode="after")
    def _one_heat_transfer(self):
        if self.heat_transfer == "free_convection" and (
                "heat_transfer_coefficient" in self.model_fields_set):
            raise ValueError(
                "heat_transfer = 'free_convection' computes the coefficient; remove "
                f"heat_transfer_coefficient ({self.heat_transfer_coefficient:g} W/(m**2*K)) or "
                "set heat_transfer = 'constant'")
        return self

    @property
    def supply_absolute(self) -> float:
        return self.supply_pressure + self.ambient_pressure

    @property
    def supply_air_temperature(self) -> float:
        return self.temperature if self.supply_temperature is None else self.supply_temperature


# -- valve ------------------------------------------------------------------------------------
class MeterOutModel(CaseModel):
    """One-way flow control valves in the lines to the ports: throttle on the way out of the
    chamber, free flow (check valve) on the way in."""

    conductance_a: Q("flow_conductance", gt=0) | None = None
    conductance_b: Q("flow_conductance", gt=0) | None = None


#: Valve fields whose defaults are estimates, not data of the case's valve: a run whose case
#: leaves them out says so (:meth:`ValveModel.assumed_notes`).
VALVE_ESTIMATES = ("critical_pressure_ratio", "time_constant")


class ValveModel(CaseModel):
    """Directional valve with ISO 6358 flow paths and a switching dynamics."""

    type: Literal["5/2", "5/3"] = "5/2"
    centre: Literal["closed", "exhaust", "pressure"] = "closed"
    conductance: Q("flow_conductance", gt=0)
    critical_pressure_ratio: Q("dimensionless", ge=0, lt=1) = Field(0.3, description=(
        "ISO 6358 critical pressure ratio b of the valve's data sheet; default 0.3, an "
        "estimate within the 0.2-0.5 of directional valves (a run without it says so)"))
    subsonic_index: Q("dimensionless", gt=0, le=1) = Field(0.5, description=(
        "ISO 6358-1:2013 subsonic index m; default 0.5, the ellipse of ISO 6358:1989 that "
        "the 2013 edition generalises"))
    laminar_ratio: Q("dimensionless", gt=0, lt=1) = 0.999
    time_constant: Q("time", ge=0) = Field(0.005, description=(
        "first-order lag of the spool's opening; default 5 ms, an estimate (data sheets give "
        "switching times of a few to some tens of ms; a run without it says so)"))
    delay: Q("time", ge=0) = Field(0.0, description="dead time before the spool moves")
    meter_out: MeterOutModel | None = None

    @model_validator(mode="after")
    def _check(self):
        if self.laminar_ratio <= self.critical_pressure_ratio:
            raise ValueError(f"laminar_ratio ({self.laminar_ratio:g}) must be larger than "
                             f"critical_pressure_ratio ({self.critical_pressure_ratio:g})")
        return self

    def assumed_notes(self) -> list[str]:
        """A note naming the fields of :data:`VALVE_ESTIMATES` the case left at their
        estimated defaults (empty when it gives them)."""
        left = [f"{name} = {getattr(self, name):g}" + (" s" if name == "time_constant" else "")
                for name in VALVE_ESTIMATES if name not in self.model_fields_set]
        if not left:
            return []
        return [f"valve: {', '.join(left)} are estimates, not your valve's: give them from its "
                "data sheet ([valve] critical_pressure_ratio, the ISO 6358 b; time_constant, "
                "the switching time)"]


# -- controller -------------------------------------------------------------------------------
Command = Literal["extend", "retract", "centre"]


class StepModel(CaseModel):
    """One PLC step: a valve command held for a duration."""

    command: Command
    duration: Q("time", gt=0)


class CycleController(CaseModel):
    """PLC cycle of valve commands, repeated until ``duration``."""

    mode: Literal["cycle"] = "cycle"
    duration: Q("time", gt=0)
    steps: list[StepModel] = Field(min_length=1)
    initial_command: Command = "retract"


class PositionController(CaseModel):
    """Prescribed piston position (friction test rig), the valve held at ``command``."""

    mode: Literal["position"]
    duration: Q("time", gt=0)
    position: profile_type("length")
    command: Command = "extend"


Controller = Annotated[CycleController | PositionController, Field(discriminator="mode")]


# -- seals ------------------------------------------------------------------------------------
class AnalyticMapModel(CaseModel):
    """Engineering estimate of F_N and b of an O-ring (see AnalyticContactMap).  ``modulus``
    and ``thermal_expansion`` default to the catalogue values of ``elastomer``
    (E = 6·(C10 + C01), the modulus at the catalogue's test frequency); ``temperature_scaling``
    is the modulus law in T, as in a structure case's ``material.temperature_scaling`` ("held":
    the relaxed modulus of a seal held for an hour); ``temperature_min`` defaults to 20 K above
    the elastomer's T_g, the lowest temperature of a rubbery estimate."""

    cord_diameter: Q("length", gt=0)
    squeeze: Q("dimensionless", gt=0, lt=0.5)
    elastomer: str = "NBR"
    modulus: Q("pressure", gt=0) | None = None
    thermal_expansion: Q("thermal_expansion", ge=0) | None = None
    reference_temperature: Q("temperature", gt=0) = 293.15
    sliding_diameter: Q("length", gt=0) | None = None
    pressure_max: Q("pressure", gt=0) = 16e5
    temperature_min: Q("temperature", gt=0) | None = None
    temperature_max: Q("temperature", gt=0) = 393.15
    temperature_scaling: Literal["held", "entropic", "modulus", "none"] = "held"


class MapModel(CaseModel):
    """Source of F_N and b: exactly one of ``file`` (a map.nc of ``sealsim structure map``),
    ``structure_case`` (a structure case file: map built on demand and cached) or
    ``analytic``."""

    file: str | None = None
    structure_case: str | None = None
    analytic: AnalyticMapModel | None = None
    squeeze: Q("dimensionless", gt=0, lt=1) | None = None
    cache_dir: str | None = None

    @model_validator(mode="after")
    def _one_source(self):
        given = [k for k in ("file", "structure_case", "analytic") if getattr(self, k) is not None]
        if len(given) != 1:
            raise ValueError("give exactly one of file = 'map.nc', structure_case = "
                             "'seal.toml' or analytic = {...}" + (f" (got {', '.join(given)})"
                                                                 if given else ""))
        return self


class SealThermalModel(CaseModel):
    """What seal heating needs to know about a seal beyond its contact map: the cord
    diameter (default: the analytic map's) and the elastomer (default: the analytic map's, else
    NBR) whose density, specific heat and conductivity the catalogue gives."""

    cord_diameter: Q("length", gt=0) | None = None
    elastomer: str | None = None


class SealModel(CaseModel):
    """A seal: where it sits, its friction law and the source of its contact load."""

    name: str = Field(min_length=1)
    location: Literal["piston", "rod", "wiper"]
    friction: LawParameters
    map: MapModel | None = None
    temperature: _temperature() | None = None
    thermal: SealThermalModel | None = None


class ThermalModel(CaseModel):
    """Frictional heating of the seals (:mod:`sealsim.pneumatic.seal_heating`): a lumped node
    per seal, the tube and the rod.  Off by default (the seals keep their temperature, right
    for short runs: the metal parts heat with time constants of minutes).

    The tube and rod geometry beyond the case's cylinder are engineering estimates [R] that a
    user should replace: an aluminium profile tube ``tube_wall_thickness`` thick and ``stroke
    + head_length`` long, a steel rod of the same length; piston and rod are one node of the
    rod's metal with the mass ``cylinder.piston_mass``; the free convection and radiation to
    the surroundings are evaluated for ``nominal_temperature_rise`` above the body."""

    seal_heating: bool = True
    tube_material: Literal["aluminium", "steel"] = "aluminium"
    rod_material: Literal["aluminium", "steel"] = "steel"
    tube_wall_thickness: Q("length", gt=0) = 4e-3
    head_length: Q("length", ge=0) = 0.05
    nominal_temperature_rise: Q("temperature_difference", gt=0) = 10.0


# -- numerics and output ----------------------------------------------------------------------
class SolverModel(CaseModel):
    """Time integration (implicit/stiff methods): "compiled" (variable-order BDF compiled with
    numba, :mod:`sealsim.ode.bdf`), or scipy's LSODA, BDF or Radau."""

    method: Literal["compiled", "LSODA", "BDF", "Radau"] = "compiled"
    rtol: float = Field(1e-5, gt=0, le=1e-2)
    max_step: Q("time", gt=0) = 0.05
    max_duration: Q("time", gt=0) = Field(MAX_DURATION, description=(
        "longest controller.duration that is run (default 600 s, several minutes of "
        "computing): a guard against a unit slip; raise it for longer runs"))


class OutputModel(CaseModel):
    """What is written."""

    sample_interval: Q("time", gt=0) = 1e-3
    max_samples: int = Field(MAX_SAMPLES, gt=0, description=(
        "most samples (rows of timeseries.csv) per variant, controller.duration / "
        "sample_interval + 1; raise it, or choose a longer sample_interval"))


class PneumaticCase(CaseModel):
    """A pneumatic cylinder system case (see the module docstring)."""

    title: str = ""
    cylinder: CylinderModel
    load: LoadModel = LoadModel()
    air: AirModel
    valve: ValveModel
    controller: Controller
    seals: list[SealModel] = []
    initial_position: Q("length") | None = None
    solver: SolverModel = SolverModel()
    output: OutputModel = OutputModel()
    thermal: ThermalModel | None = None

    @model_validator(mode="after")
    def _check(self):
        names = [s.name for s in self.seals]
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise ValueError(f"seals: the names must be unique, repeated: {', '.join(dupes)}")
        if self.valve.type == "5/2":
            used = ({s.command for s in self.controller.steps} | {
                self.controller.initial_command} if self.controller.mode == "cycle"
                else {self.controller.command})
            if "centre" in used:
                raise ValueError("controller: command 'centre' needs a 5/3 valve "
                                 "(valve.type = '5/3')")
        if self.initial_position is not None and not (
                0.0 <= self.initial_position <= self.cylinder.stroke):
            raise ValueError(f"initial_position ({self.initial_position * 1e3:g} mm) must lie "
                             f"within cylinder.stroke (0 ... {self.cylinder.stroke * 1e3:g} mm)")
        duration, interval = self.controller.duration, self.output.sample_interval
        if interval > duration:
            raise ValueError("output.sample_interval must not exceed controller.duration")
        if duration > self.solver.max_duration:
            raise ValueError(f"controller.duration ({duration:.6g} s) exceeds solver.max_duration "
                             f"({self.solver.max_duration:.6g} s); raise solver.max_duration "
                             f"(e.g. max_duration = '{duration:.3g} s') for a longer run")
        samples = duration / interval + 1
        if samples > self.output.max_samples:
            raise ValueError(f"controller.duration / output.sample_interval gives {samples:.3g} "
                             f"samples, more than output.max_samples ({self.output.max_samples}"
                             "); choose a longer output.sample_interval or raise "
                             "output.max_samples")
        return self


def load_pneumatic_cases(data: dict[str, Any], source: str = "case") -> dict[str, PneumaticCase]:
    """Validate case data with optional ``[variants.NAME]`` tables (units required)."""
    return expand_variants(PneumaticCase, data, source)


def load_pneumatic_case_file(path: str | Path) -> dict[str, PneumaticCase]:
    """Read and validate a pneumatic case file; returns ``{variant: PneumaticCase}``."""
    path = Path(path)
    return load_pneumatic_cases(load_toml(path), f"pneumatic case {str(path)!r}")


def body_temperature(case: PneumaticCase) -> float:
    """Temperature of the cylinder body [K]: ``cylinder.temperature`` or ``air.temperature``."""
    t = case.cylinder.temperature
    return case.air.temperature if t is None else t


# -- building the seals -----------------------------------------------------------------------
_USES_LOAD = {"theta"}


def _analytic_map(spec: AnalyticMapModel, diameter: float, where: str) -> AnalyticContactMap:
    modulus, expansion = spec.modulus, spec.thermal_expansion
    if modulus is None or expansion is None:
        from sealsim.properties.elastomers import get_elastomer

        try:
            elastomer = get_elastomer(spec.elastomer)
        except Exception as exc:  # unknown name: InputError or KeyError from the catalogue
            raise InputError(f"{where}.analytic.elastomer: {exc}") from None
        if modulus is None:
            modulus = 6.0 * (elastomer.c10 + elastomer.c01)
        if expansion is None:
            expansion = elastomer.thermal_expansion
    from sealsim.properties.elastomers import GLASS_TRANSITION_MARGIN, get_elastomer

    try:
        lowest = get_elastomer(spec.elastomer).glass_transition + GLASS_TRANSITION_MARGIN
    except Exception as exc:  # unknown name: InputError or KeyError from the catalogue
        raise InputError(f"{where}.analytic.elastomer: {exc}") from None
    t_min = lowest if spec.temperature_min is None else spec.temperature_min
    if t_min >= spec.temperature_max:
        raise InputError(f"{where}.analytic: temperature_min must be below temperature_max")
    try:
        return AnalyticContactMap(
            sliding_diameter=spec.sliding_diameter or diameter, cord_diameter=spec.cord_diameter,
            squeeze=spec.squeeze, modulus=modulus, thermal_expansion=expansion,
            reference_temperature=spec.reference_temperature, pressure_max=spec.pressure_max,
            temperature_range=(t_min, spec.temperature_max),
            temperature_scaling=spec.temperature_scaling, elastomer=spec.elastomer)
    except InputError as exc:
        raise InputError(f"{where}.analytic.temperature_min: {exc}") from None


def case_input_files(case: PneumaticCase, base_dir: str | Path) -> list[Path]:
    """The files a pneumatic case reads besides itself: its seals' map files and structure
    cases (relative to ``base_dir``, the case file's folder)."""
    files = []
    for seal in case.seals:
        if seal.map is not None:
            files += [Path(base_dir) / f for f in (seal.map.file, seal.map.structure_case)
                      if f is not None]
    return files


def build_contact_map(spec: MapModel, diameter: float, base_dir: Path, where: str,
                      progress=None, map_workers: int | None = None, label: str = ""):
    """The contact map object of a seal's ``map`` table (paths relative to ``base_dir``).

    For an FE map built on demand: ``progress(done, total)`` reports its FE load paths,
    ``label`` names the seal in the notice before the build
    (:func:`~sealsim.pneumatic.contact_maps.build_or_load_fe_map`), ``map_workers`` are its
    processes (default: the structure case's ``map.workers``; 1 inside a worker process that
    may not start processes of its own)."""
    if spec.analytic is not None:
        return _analytic_map(spec.analytic, diameter, where)
    if spec.file is not None:
        path = Path(spec.file)
        path = path if path.is_absolute() else base_dir / path
        try:
            return FEContactMap.from_file(path, squeeze=spec.squeeze)
        except InputError as exc:
            raise InputError(f"{where}.file: {exc}") from None
    path = Path(spec.structure_case)
    path = path if path.is_absolute() else base_dir / path
    cache = None
    if spec.cache_dir is not None:
        cache = Path(spec.cache_dir)
        cache = cache if cache.is_absolute() else base_dir / cache
    try:
        return build_or_load_fe_map(path, squeeze=spec.squeeze, cache_dir=cache,
                                    progress=progress, workers=map_workers, label=label)
    except InputError as exc:
        raise InputError(f"{where}.structure_case: {exc}") from None


def build_seals(case: PneumaticCase, base_dir: str | Path = ".", progress=None,
                map_workers: int | None = None) -> list[Seal]:
    """Seal objects of a case: friction law (one object per distinct parameter set, so seals
    with the same law are evaluated together) and contact map (``progress(done, total)``
    while an FE map is built on demand, ``map_workers``: see :func:`build_contact_map`)."""
    base_dir = Path(base_dir)
    laws: dict[str, Any] = {}
    seals = []
    for k, spec in enumerate(case.seals):
        where = f"seals[{k}] ({spec.name!r})"
        key = repr(spec.friction)      # SI field values (model_dump formats every quantity)
        if key not in laws:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")     # e.g. LuGre passivity: kept as notes
                law = make_law(spec.friction)
            unfitted = parameter_set_note(spec.friction)
            laws[key] = (law, [str(w.message) for w in caught] + ([unfitted] if unfitted
                                                                   else []))
        law, notes = laws[key]
        diameter = case.cylinder.bore if spec.location == "piston" else case.cylinder.rod_diameter
        contact_map = None
        if spec.map is not None:
            contact_map = build_contact_map(spec.map, diameter, base_dir, f"{where}.map",
                                            progress, map_workers, f"seal {spec.name!r}")
        elif law.name in _USES_LOAD:
            raise InputError(f"{where}.map: the {law.name} law needs the normal force and "
                             "contact width of the seal; give map = {analytic = {cord_diameter "
                             "= '2.5 mm', squeeze = 0.12}} or map = {file = 'map.nc'}")
        temperature = spec.temperature
        if temperature is None:
            temperature = case.cylinder.seal_temperature
        if temperature is None:
            temperature = body_temperature(case)
        table = seal_friction_table(law, contact_map, f"{where}.map")
        seal_notes = notes + ([] if table is None else
                              contact_friction_notes(table, contact_map, law, temperature))
        seals.append(Seal(spec.name, spec.location, law, contact_map, temperature, seal_notes,
                          table))
    return seals


def seal_friction_table(law, contact_map, where: str = "map"):
    """The steady friction table of a seal whose Θ law takes its steady curve from the
    contact (``steady = "contact"``), built from its contact map or read from the cache
    (:func:`sealsim.pneumatic.friction_tables.friction_table_for`); None for other laws."""
    from sealsim.pneumatic.friction_tables import ContactTribology, friction_table_for

    if getattr(law.params, "steady", "lumped") != "contact":
        return None
    if contact_map is None:
        raise InputError(f"{where}: the theta law with steady = 'contact' needs the seal's "
                         "contact map (its contact pressure profile)")
    return friction_table_for(contact_map,
                              ContactTribology.from_law(law, map_elastomer(contact_map)))


def contact_friction_notes(table, contact_map, law, temperature: float) -> list[str]:
    """A note when a seal's steady friction from its contact passes its contact force at the
    seal's temperature at a speed up to 1 m/s
    (:func:`~sealsim.pneumatic.friction_tables.friction_over_contact_force`): the table's
    viscous shear is then outside what its film model holds for, and the cylinder's friction
    with it."""
    from sealsim.pneumatic.friction_tables import friction_over_contact_force

    ratio, speed, dp = friction_over_contact_force(table, contact_map,
                                                   law.params.boundary_friction, temperature)
    if ratio <= 1.0:
        return []
    return [f"its steady friction passes its contact force (F/F_N up to {ratio:.2g} at "
            f"{speed:.2g} m/s, Δp {dp / 1e5:.3g} bar, {temperature - 273.15:.4g} °C): "
            f"{excess_friction_cause(law)}"]


def excess_friction_cause(law) -> str:
    """Why a Θ law on its seal's contact gives more friction than the contact force, and what
    that means (the end of the notes of :func:`contact_friction_notes` and
    :func:`sealsim.seal_friction`, and of a friction fit's warning)."""
    layer = getattr(getattr(law, "params", None), "supply_layer", None)
    cause = (f"the film that its supply_layer of {layer * 1e6:.3g} µm caps, sheared "
             "in proportion to the speed" if layer is not None and math.isfinite(layer) else
             "the viscous shear of its film")
    return (f"{cause}, beyond what a lubricated rubber seal shows (F/F_N < 1); its friction "
            "at such speeds is not to be trusted")


def map_elastomer(contact_map) -> str:
    """Catalogue elastomer of a contact map (FE: the map's ``elastomer`` attribute; analytic:
    its ``elastomer``); NBR for an FE map of a custom material."""
    from sealsim.properties.elastomers import get_elastomer

    name = getattr(contact_map, "elastomer", None)
    if name is None and hasattr(contact_map, "seal_map"):
        name = contact_map.seal_map.dataset.attrs.get("elastomer")
    try:
        get_elastomer(name)
    except (InputError, TypeError, KeyError):
        return "NBR"
    return name
