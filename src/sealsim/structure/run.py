"""Thin orchestration: case → assembly, material, mesh, model → load path → results.

Like pvlib's ModelChain it only composes the pieces of :mod:`sealsim.structure`; each of them
can be used on its own.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field

from sealsim.errors import InputError
from sealsim.structure.case import StructureCase
from sealsim.structure.geometry import Gland, ORing, SealAssembly
from sealsim.structure.material import material_from_elastomer, thermal_volume_ratio
from sealsim.structure.mesh import mesh_section
from sealsim.structure.model import SealModel
from sealsim.structure.solver import LoadStep, solve

__all__ = [
    "RunResult",
    "build_assembly",
    "build_material",
    "build_model",
    "load_steps",
    "run_case",
]


def build_assembly(case: StructureCase) -> SealAssembly:
    """Seal and gland of a case (InputError for impossible geometry)."""
    ring = ORing(case.seal.cord_diameter, case.seal.inner_diameter)
    gland = Gland(case.gland.arrangement, case.gland.sealing_diameter, case.gland.groove_width)
    assembly = SealAssembly(ring, gland, case.gland.inner_expansion, case.gland.outer_expansion,
                            case.load.installation_temperature)
    _check_placement(assembly)
    return assembly


def _check_placement(a: SealAssembly) -> None:
    d = a.seal.cord_diameter
    rs = a.gland.sealing_radius
    r_free = a.free_sealing_side_radius
    # the free ring must sit roughly on the sealing surface (stretch/compression < 15 %)
    strain = (rs - r_free) / r_free
    if abs(strain) > 0.15:
        kind = "inner" if a.gland.side < 0 else "outer"
        raise InputError(
            f"seal.inner_diameter: the free O-ring's {kind} diameter {2 * r_free * 1e3:g} mm "
            f"would be {'stretched' if strain > 0 else 'compressed'} by {abs(strain) * 100:.0f} % "
            f"onto the sealing diameter {2 * rs * 1e3:g} mm; allowed is up to 15 %")
    if a.gland.side > 0 and rs - d <= 0:
        raise InputError("gland.sealing_diameter: the bore is too small for the O-ring cord")


def build_material(case: StructureCase, *, equilibrium: bool = False):
    """Seal material of a case; ``equilibrium`` gives the relaxed hyperelastic variant."""
    from sealsim.properties.elastomers import get_elastomer

    spec = case.material
    elastomer = get_elastomer(spec.elastomer)
    overrides = {k: getattr(spec, k) for k in ("c10", "c01", "bulk_modulus", "thermal_expansion")
                 if getattr(spec, k) is not None}
    if spec.hardness_shore_a is not None:
        overrides.update(_hardness_scaled(elastomer, spec))
    if overrides:
        import dataclasses

        try:
            elastomer = dataclasses.replace(elastomer, **overrides)
        except InputError as exc:
            raise InputError(f"material: {exc}") from None
    t0 = case.load.installation_temperature
    material = material_from_elastomer(elastomer, spec.model, reference_temperature=t0,
                                       temperature_scaling=spec.temperature_scaling)
    if equilibrium:
        material = material.equilibrium()
    return material


def _hardness_scaled(elastomer, spec) -> dict:
    """Constants of a compound of another Shore A hardness: the catalogue's C10, C01 (and
    Prony moduli) times E(S)/E(S_catalogue) of Gent's relation."""
    from sealsim.properties.elastomers import shore_a_young_modulus

    if spec.c10 is not None or spec.c01 is not None:
        raise InputError("material: give either hardness_shore_a or c10/c01, not both "
                         "(the hardness scales the catalogue constants)")
    if elastomer.hardness_shore_a is None:
        raise InputError(f"material.hardness_shore_a: {elastomer.name} has no catalogue "
                         "hardness to scale from; give c10 and c01 instead")
    scale = shore_a_young_modulus(spec.hardness_shore_a) / \
        shore_a_young_modulus(elastomer.hardness_shore_a)
    scaled = {"c10": elastomer.c10 * scale, "c01": elastomer.c01 * scale,
              "hardness_shore_a": spec.hardness_shore_a}
    if elastomer.prony is not None:
        e_inf, e_i, tau_i = elastomer.prony
        scaled["prony"] = (e_inf * scale, tuple(e * scale for e in e_i), tau_i)
    return scaled


def check_temperatures(case: StructureCase, temperatures) -> None:
    """InputError for temperatures the material cannot be evaluated at."""
    from sealsim.properties.elastomers import get_elastomer

    e = get_elastomer(case.material.elastomer)
    lo, hi = e.allowed_range
    for t in temperatures:
        if not lo <= t <= hi:
            raise InputError(
                f"temperature {t - 273.15:g} degC is outside the range of {e.name}: "
                f"{lo - 273.15:g} ... {hi - 273.15:g} degC (T_g - 100 K ... service max + 50 K)")


def build_model(case: StructureCase, installation_squeeze: float, *, material=None,
                squeezes=(), temperatures=()) -> SealModel:
    """Assembly, mesh and FE model for a case (geometry checks for the given loads)."""
    assembly = build_assembly(case)
    assembly.check_squeeze(installation_squeeze, "load.squeeze")
    if material is None:
        material = build_material(case)
    alpha = material.thermal_expansion
    temps = list(temperatures) or [case.load.installation_temperature]
    check_temperatures(case, temps)
    for s in [installation_squeeze, *squeezes]:
        assembly.check_squeeze(s, "load.squeeze")
        j = max(thermal_volume_ratio(t, case.load.installation_temperature, alpha) for t in temps)
        assembly.check_fill(s, j)
    m = case.mesh
    kwargs = {k: getattr(m, k) for k in ("n_arc", "n_wall", "n_radial") if getattr(m, k)}
    mesh = mesh_section(assembly.seal, assembly.centre, m.level, **kwargs)
    sv = case.solver
    return SealModel(assembly, mesh, material, installation_squeeze=installation_squeeze,
                     penalty=sv.penalty, positioning_pressure=sv.positioning_pressure,
                     rolling_stiffness=sv.rolling_stiffness)


def load_steps(case: StructureCase) -> list[LoadStep]:
    """The load path of a case: installation, squeeze, pressure, temperature steps."""
    ld = case.load
    rec = "all" if ld.record_increments else "end"
    steps = [LoadStep("installation", squeeze=ld.squeeze[0], increments=ld.squeeze_increments,
                      duration=ld.installation_time, record=rec)]
    if ld.hold_time > 0:
        steps.append(LoadStep("hold", duration=ld.hold_time, increments=2, record=rec))
    for s in ld.squeeze[1:]:
        steps.append(LoadStep("squeeze", squeeze=s, increments=ld.squeeze_increments,
                              duration=ld.installation_time, record=rec))
    for p in ld.pressure:
        steps.append(LoadStep("pressure", pressure=p, increments=ld.pressure_increments,
                              duration=ld.pressure_time, record=rec))
    previous = ld.installation_temperature
    for t in ld.temperature:
        steps.append(LoadStep("temperature", temperature=t,
                              increments=ld.temperature_increments,
                              duration=abs(t - previous) / ld.temperature_rate,
                              record="all" if ld.record_increments else "end"))
        previous = t
    return steps


@dataclass
class RunResult:
    """Results of :func:`run_case`: one :class:`~.results.StateResult` per load state."""

    states: list
    ndofs: int
    wall_time: float
    model: SealModel = field(repr=False)


def run_case(case: StructureCase, progress=None) -> RunResult:
    """Solve the load path of a case.

    Parameters
    ----------
    case : StructureCase
        Validated case.
    progress : callable, optional
        ``progress(done, total)`` after every recorded state.
    """
    from sealsim.structure.results import extract

    ld = case.load
    model = build_model(case, ld.squeeze[0], squeezes=ld.squeeze[1:],
                        temperatures=[ld.installation_temperature, *ld.temperature])
    steps = load_steps(case)
    total = sum(s.increments if s.record == "all" else 1 for s in steps)
    states = []

    def record(m):
        r = extract(m)
        states.append(r)
        if progress is not None:
            progress(len(states), total)
        return r

    t0 = time.perf_counter()
    sv = case.solver
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        solve(model, steps, on_state=record, tol=sv.tolerance, maxiter=sv.max_iterations,
              max_cutbacks=sv.max_cutbacks)
    return RunResult(states, model.ndofs, time.perf_counter() - t0, model)


__all__ += ["check_temperatures"]


# -- case files → result folders -------------------------------------------------------------------

SUMMARY_KEYS = ("F_N_N", "F_N_per_length_N_per_mm", "b_mm", "p_max_MPa", "p_mean_MPa")


def _load_cases(path):
    from sealsim.cases import expand_variants, load_toml

    data = load_toml(path)
    return expand_variants(StructureCase, data, source=str(path))


def _resolved_text(cases) -> str:
    from sealsim.cases import dump_variants_toml

    return dump_variants_toml(cases, header="resolved sealsim structure case (all defaults "
                                            "filled in)")


def run_case_file(path, out, force: bool = False, progress=None) -> dict:
    """``sealsim structure run``: solve every variant of a case file, write the result folder.

    Files (per variant in a sub-folder if the case has variants): ``result.csv`` (one row per
    load state), ``profiles.csv`` (contact pressure profiles), ``summary.json``,
    ``section_installed.png`` and ``section_final.png`` (deformed section with von Mises
    stress and contact pressure), ``states.png``; ``case_resolved.toml`` at the top.

    Parameters
    ----------
    path : path-like
        Case file (TOML).
    out : path-like
        Result folder (refused if it holds results unless ``force``).
    progress : callable, optional
        ``progress(variant, done, total)``.
    """
    from sealsim.output import run_variants

    cases = _load_cases(path)
    many = len(cases) > 1

    def write_variant(folder, name, result):
        _write_variant(folder, f"{name}/" if many else "", name, cases[name], result)

    return run_variants(
        cases, out, lambda name, case, report: run_case(case, progress=report),
        lambda folder, runs: folder.write_text("case_resolved.toml", _resolved_text(cases)),
        force=force, inputs=[path], progress=progress, write_each=write_variant)


def _write_variant(folder, prefix: str, name: str, case: StructureCase, result: RunResult):
    """Tables, figures and summary of one solved variant (into sub-folder ``prefix``)."""
    from sealsim.plotting.structure import plot_section, plot_states
    from sealsim.structure.results import profiles_frame, results_frame

    frame = results_frame(result.states)
    folder.write_csv(prefix + "result.csv", frame)
    folder.write_csv(prefix + "profiles.csv", profiles_frame(result.states))
    title = case.title or f"{case.seal.cord_diameter * 1e3:g} mm O-ring, " \
                          f"{case.gland.arrangement} seal, {case.material.elastomer}"
    installed = len(case.load.squeeze) - 1 + (1 if case.load.hold_time > 0 else 0)
    if case.load.record_increments:
        installed = case.load.squeeze_increments - 1
    first = result.states[min(installed, len(result.states) - 1)] \
        if len(result.states) > 1 else result.states[0]
    folder.savefig(prefix + "section_installed.png", plot_section(first, title))
    folder.savefig(prefix + "section_final.png", plot_section(result.states[-1], title))
    folder.savefig(prefix + "states.png", plot_states(frame, title=title))
    last = frame.iloc[-1]
    folder.write_json(prefix + "summary.json", {
        "variant": name,
        "dofs": result.ndofs,
        "wall_time_s": round(result.wall_time, 3),
        "load_states": len(frame),
        "final": {k: float(last[k]) for k in SUMMARY_KEYS},
        "max_equilibrium_error": float(max(
            max(abs(s.axial_imbalance), abs(s.radial_imbalance))
            for s in result.states)),
        "max_penetration_um": float(frame["max_penetration_um"].max()),
    })


def map_case_file(path, out, force: bool = False, progress=None, workers: int | None = None):
    """``sealsim structure map``: characteristic map of a case (its ``[map]`` table).

    Writes ``map.nc`` (xarray/netCDF, SI units, the resolved case as attribute ``case``),
    ``map.csv`` (flat table in engineering units), ``map.png`` and ``case_resolved.toml``.
    Only cases without variants.
    """
    from sealsim.output import run_variants
    from sealsim.plotting.structure import plot_map
    from sealsim.structure.maps import compute_map

    cases = _load_cases(path)
    if len(cases) != 1:
        raise InputError("structure map: the case has variants; map one case at a time "
                         "(remove the [variants] tables)")
    case = next(iter(cases.values()))
    if case.map is None:
        raise InputError(f"{path}: the case has no [map] table with map.pressure and "
                         "map.temperature grids")
    text = _resolved_text(cases)

    def compute(name, case, report):
        return compute_map(case, workers=workers, progress=progress, case_text=text)

    def write(folder, results):
        ds = results["map"]
        folder.write_netcdf("map.nc", ds)
        flat = ds.to_dataframe().reset_index()
        table = flat.assign(
            squeeze=flat["squeeze"], pressure_bar=flat["pressure"] / 1e5,
            temperature_C=flat["temperature"] - 273.15, F_N_N=flat["F_N"],
            F_N_per_length_N_per_mm=flat["F_N_per_length"] / 1e3, b_mm=flat["b"] * 1e3,
            p_max_MPa=flat["p_max"] / 1e6, p_mean_MPa=flat["p_mean"] / 1e6,
            F_groove_bottom_N=flat["F_groove_bottom"])[
            ["squeeze", "pressure_bar", "temperature_C", "F_N_N", "F_N_per_length_N_per_mm",
             "b_mm", "p_max_MPa", "p_mean_MPa", "F_groove_bottom_N"]]
        folder.write_csv("map.csv", table)
        for i in range(ds.sizes["squeeze"]):
            name = "map.png" if ds.sizes["squeeze"] == 1 else f"map_squeeze{i}.png"
            folder.savefig(name, plot_map(ds, i, title=case.title))
        folder.write_text("case_resolved.toml", text)

    return run_variants({"map": case}, out, compute, write, force=force, inputs=[path])["map"]


__all__ += ["map_case_file", "run_case_file"]
