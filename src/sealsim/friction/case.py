"""Friction case files: which law, its inputs, and the test bench that drives it.

A case file (TOML, quantities with units)::

    title = "LuGre velocity hysteresis"

    [friction]                 # the law: one of coulomb, stribeck, lugre, dahl, gms, theta
    law = "lugre"
    parameter_set = "canudas1995"   # optional named set; fields given here override it

    [inputs]                   # what the law needs from the seal: F_N, b, p_A, p_B, T
    normal_force = "100 N"

    [bench]                    # mode = "velocity" | "displacement" | "mass"
    mode = "velocity"
    duration = "20 s"
    time_step = "1 ms"
    velocity = { kind = "harmonic", mean = "1.5 mm/s", amplitude = "1 mm/s",
                 angular_frequency = "1 rad/s" }

    [variants.fast]            # optional: each variant overrides fields of the base case
    bench.velocity.angular_frequency = "25 rad/s"

A bench may hold a real seal instead of a normal force and width: ``[seal]`` names it as a
pneumatic seal names its ``map`` (the analytic O-ring estimate, a ``map.nc`` or a structure
case), with the diameter it slides on; its contact gives F_N and b at the ``[inputs]``
pressure difference and temperature and, for the Θ law with ``steady = "contact"`` (parameter
set ``seal_contact``), the friction table of its own contact::

    [seal]
    sliding_diameter = "12 mm"
    map = { analytic = { cord_diameter = "2 mm", squeeze = 0.12 } }
    positive_velocity = "away_from_pressure"   # v > 0: the rod leaves the pressurised side

    [inputs]
    pressure_a = "3 bar"       # pressure difference |p_A - p_B| across the seal
    temperature = "20 degC"

:func:`load_friction_cases` validates it (every problem in one InputError naming the field),
:func:`run_friction_case` runs one variant, :func:`sealsim.cases.dump_variants_toml` writes the
resolved case (all defaults filled in) that reproduces the run.
"""

from __future__ import annotations

import warnings
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field, field_validator

from sealsim.cases import CaseModel, Q, expand_variants
from sealsim.errors import InputError
from sealsim.friction import LAWS, make_law
from sealsim.friction.base import ContactInputs, FrictionLaw
from sealsim.friction.bench import (
    BenchResult,
    profile_type,
    simulate_displacement,
    simulate_mass,
    simulate_velocity,
    summarize,
)
from sealsim.friction.dahl import DahlParameters
from sealsim.friction.gms import GMSParameters
from sealsim.friction.lugre import LuGreParameters
from sealsim.friction.stribeck import CoulombParameters, StribeckParameters
from sealsim.friction.theta import ThetaParameters
from sealsim.units import STANDARD_ATMOSPHERE_PA

__all__ = [
    "FrictionCase",
    "load_friction_cases",
    "make_inputs",
    "run_friction_case",
]

LawParameters = Annotated[
    CoulombParameters | StribeckParameters | LuGreParameters | DahlParameters | GMSParameters
    | ThetaParameters,
    Field(discriminator="law"),
]


class InputsModel(CaseModel):
    """Operating conditions of the contact (constant during a bench run)."""

    normal_force: Q("force", ge=0) | None = None
    contact_width: Q("length", ge=0) | None = None
    pressure_a: Q("pressure") = 0.0
    pressure_b: Q("pressure") = 0.0
    temperature: Q("temperature", gt=0) | None = None

    @field_validator("pressure_a", "pressure_b")
    @classmethod
    def _not_below_vacuum(cls, value: float) -> float:
        # gauge pressures (as in system tools): below -1 atm would be less than vacuum
        if value < -STANDARD_ATMOSPHERE_PA:
            raise ValueError(f"a gauge pressure below vacuum is not possible: it must be >= "
                             f"{-STANDARD_ATMOSPHERE_PA / 1e5:g} bar (-1 atm, vacuum)")
        return value


class BenchSealModel(CaseModel):
    """The seal on the bench: its contact map gives F_N and b (and the friction table of the
    Θ law on its own contact) at the ``[inputs]`` pressure difference and temperature.  The
    map is validated and built by :func:`sealsim.pneumatic.bench.bench_inputs`."""

    sliding_diameter: Q("length", gt=0)
    map: dict[str, Any] = Field(description=(
        "the seal's contact, as the map of a pneumatic seal: {analytic = {cord_diameter = "
        "'2 mm', squeeze = 0.12}}, {file = 'map.nc'} or {structure_case = 'seal.toml'}"))
    positive_velocity: Literal["away_from_pressure", "towards_pressure"] = Field(
        "away_from_pressure", description=(
            "how the counter surface slides relative to the seal when the bench velocity is "
            "positive: away from the pressurised side (a rod seal's outstroke) or towards it"))


class _BenchBase(CaseModel):
    duration: Q("time", gt=0)
    time_step: Q("time", gt=0)
    start: Literal["rest", "steady"] = "rest"


class VelocityBench(_BenchBase):
    """Prescribed sliding velocity v(t)."""

    mode: Literal["velocity"]
    velocity: profile_type("velocity")


class DisplacementBench(_BenchBase):
    """Prescribed displacement x(t) (e.g. a crank drive)."""

    mode: Literal["displacement"]
    displacement: profile_type("length")


class MassBench(_BenchBase):
    """A mass on the contacts, pulled by a spring whose end moves, and/or pushed by a force."""

    mode: Literal["mass"]
    mass: Q("mass", gt=0)
    stiffness: Q("stiffness", ge=0) = 0.0
    drive_velocity: profile_type("velocity") | None = None
    applied_force: profile_type("force") | None = None
    integrator: Literal["auto", "compiled", "radau", "bdf", "stepper"] = "auto"
    rtol: float = Field(1e-7, gt=0, lt=1)


Bench = Annotated[VelocityBench | DisplacementBench | MassBench, Field(discriminator="mode")]


class OutputModel(CaseModel):
    """What is written."""

    max_rows: int = Field(20000, ge=10, le=2_000_000)
    steady_curve: bool = True


class FrictionCase(CaseModel):
    """A friction test-bench case (see the module docstring)."""

    title: str = ""
    friction: LawParameters
    seal: BenchSealModel | None = None
    inputs: InputsModel = InputsModel()
    bench: Bench
    output: OutputModel = OutputModel()


def load_friction_cases(data: dict[str, Any], source: str = "case") -> dict[str, FrictionCase]:
    """Validate case data with optional ``[variants.NAME]`` overrides (units required).

    Returns ``{"base": case}`` without variants, else one case per variant.
    """
    return expand_variants(FrictionCase, data, source)


def make_inputs(case: FrictionCase) -> ContactInputs:
    """The law inputs of a case's ``[inputs]`` table (a case with a ``[seal]`` gets its
    contact's from :func:`sealsim.pneumatic.bench.bench_inputs`)."""
    i = case.inputs
    return ContactInputs(normal_force=i.normal_force, contact_width=i.contact_width,
                         pressure_a=i.pressure_a, pressure_b=i.pressure_b,
                         temperature=i.temperature)


def build_law(case: FrictionCase) -> FrictionLaw:
    """The law object of a case (LuGre may warn about passivity)."""
    return make_law(case.friction)


def run_friction_case(case: FrictionCase, law: FrictionLaw | None = None,
                      progress=None, inputs: ContactInputs | None = None
                      ) -> tuple[BenchResult, dict[str, Any]]:
    """Run one case: the bench time series and its summary.

    ``inputs``: the law inputs, default those of the ``[inputs]`` table (:func:`make_inputs`);
    a case with a ``[seal]`` needs its contact's (:func:`sealsim.pneumatic.bench.bench_inputs`,
    which ``sealsim friction run`` uses).

    Returns
    -------
    result : BenchResult
    summary : dict
        :func:`sealsim.friction.bench.summarize` plus the law parameters.
    """
    if law is None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            law = build_law(case)
    if inputs is None:
        if case.seal is not None:
            raise InputError("seal: a bench with a seal needs the inputs of its contact map "
                             "(sealsim.pneumatic.bench.bench_inputs; sealsim friction run "
                             "builds them)")
        inputs = make_inputs(case)
    _check_inputs(law, inputs)
    bench = case.bench
    z0 = law.initial_state(1)
    if bench.start == "steady":
        v_start = _start_velocity(bench)
        z0 = law.steady_state(np.array([v_start]), inputs)
    if bench.mode == "velocity":
        result = simulate_velocity(law, bench.velocity, bench.duration, bench.time_step, inputs,
                                   z0)
    elif bench.mode == "displacement":
        result = simulate_displacement(law, bench.displacement, bench.duration,
                                       bench.time_step, inputs, z0)
    else:
        result = simulate_mass(law, bench.mass, bench.duration, bench.time_step,
                               stiffness=bench.stiffness, drive_velocity=bench.drive_velocity,
                               applied_force=bench.applied_force, inputs=inputs,
                               initial_state=z0, integrator=bench.integrator, rtol=bench.rtol,
                               progress=progress)
    summary = summarize(result)
    summary["law"] = law.describe()
    summary["passive"] = law.is_passive()
    return result, summary


def _start_velocity(bench) -> float:
    if bench.mode == "velocity":
        return float(bench.velocity.value(0.0))
    if bench.mode == "displacement":
        return float(bench.displacement.derivative(0.0))
    return 0.0


def _check_inputs(law: FrictionLaw, inputs: ContactInputs) -> None:
    """Fail early, naming the case field, if the law lacks an input."""
    if getattr(law, "contact", False) and inputs.contact_table is None:
        raise InputError(
            "seal: the theta law with steady = 'contact' takes its steady friction from the "
            "seal's own contact, so the bench needs the seal: give [seal] with "
            "sliding_diameter = '12 mm' and map = {analytic = {cord_diameter = '2 mm', "
            "squeeze = 0.12}} (or {file = 'map.nc'}, {structure_case = 'seal.toml'}) and the "
            "[inputs] temperature and pressures; or use the lumped steady curve (steady = "
            "'lumped', e.g. parameter_set = 'pneumatic_demo') with [inputs] normal_force and "
            "contact_width")
    try:
        law.force(law.initial_state(1), np.array([1e-3]), inputs)
    except InputError as exc:
        raise InputError(f"{exc} -- set it in the [inputs] table of the case") from None


__all__ += ["LAWS", "build_law"]
