"""Thin orchestration: case → model (:mod:`.build`) → load path → results and result folders;
``structure map`` through :mod:`.mapping`.

Like pvlib's ModelChain it only composes the pieces of :mod:`sealsim.structure`; each of them
can be used on its own.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field

from sealsim.errors import InputError
from sealsim.structure.build import build_model, describe_seal, load_steps
from sealsim.structure.case import StructureCase, load_structure_cases
from sealsim.structure.model import SealModel
from sealsim.structure.solver import solve

__all__ = ["RunResult", "map_case_file", "run_case", "run_case_file"]


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
    model = build_model(case, None if ld.squeeze is None else ld.squeeze[0],
                        squeezes=(ld.squeeze or [])[1:],
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


# -- case files → result folders -------------------------------------------------------------------

SUMMARY_KEYS = ("F_N_N", "F_N_per_length_N_per_mm", "b_mm", "p_max_MPa", "p_mean_MPa")


def _load_cases(path):
    return load_structure_cases(path)


def _resolved_text(cases) -> str:
    from sealsim.cases import dump_variants_toml

    return dump_variants_toml(cases, header="resolved sealsim structure case (all defaults "
                                            "filled in)")


def run_case_file(path, out, force: bool = False, progress=None) -> dict:
    """``sealsim structure run``: solve every variant of a case file, write the result folder.

    Files (per variant in a sub-folder if the case has variants): ``result.csv`` (one row per
    load state), ``profiles.csv`` (contact pressure profiles), ``increments.csv`` (every
    converged increment: step, load fraction, Newton iterations, cutbacks), ``summary.json``,
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

    import pandas as pd

    frame = results_frame(result.states)
    folder.write_csv(prefix + "result.csv", frame)
    folder.write_csv(prefix + "profiles.csv", profiles_frame(result.states))
    increments = pd.DataFrame(result.model.increment_log)
    folder.write_csv(prefix + "increments.csv", increments)
    title = case.title or describe_seal(case)
    installed = len(case.load.squeeze or [0]) - 1 + (1 if case.load.hold_time > 0 else 0)
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
        "increments": len(increments),
        "newton_iterations": int(increments["newton_iterations"].sum()) if len(increments) else 0,
        "cutbacks": int(increments["cutbacks"].sum()) if len(increments) else 0,
        "max_rolling_moment_Nm": float(frame["rolling_moment_Nm"].abs().max()),
    })


def map_case_file(path, out, force: bool = False, progress=None, workers: int | None = None):
    """``sealsim structure map``: characteristic map of a case (its ``[map]`` table).

    Writes ``map.nc`` (xarray/netCDF, SI units, the resolved case as attribute ``case``),
    ``map.csv`` (flat table in engineering units), ``map_profiles.csv`` (contact pressure
    p(z) at every grid point), ``map.png``, ``map_profiles.png`` and ``case_resolved.toml``.
    Only cases without variants.
    """
    from sealsim.output import run_variants
    from sealsim.plotting.structure import plot_map, plot_map_profiles
    from sealsim.structure.mapping import compute_map

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
        flat = ds.drop_dims("position").to_dataframe().reset_index()
        table = flat.assign(
            squeeze=flat["squeeze"], pressure_bar=flat["pressure"] / 1e5,
            temperature_C=flat["temperature"] - 273.15, F_N_N=flat["F_N"],
            F_N_per_length_N_per_mm=flat["F_N_per_length"] / 1e3, b_mm=flat["b"] * 1e3,
            p_max_MPa=flat["p_max"] / 1e6, p_mean_MPa=flat["p_mean"] / 1e6,
            F_groove_bottom_N=flat["F_groove_bottom"], contact_zones=flat["contact_zones"],
            b_span_mm=flat["b_span"] * 1e3)[
            ["squeeze", "pressure_bar", "temperature_C", "F_N_N", "F_N_per_length_N_per_mm",
             "b_mm", "p_max_MPa", "p_mean_MPa", "F_groove_bottom_N", "contact_zones",
             "b_span_mm"]]
        folder.write_csv("map.csv", table)
        prof = ds["contact_pressure"].to_dataframe().reset_index()
        folder.write_csv("map_profiles.csv", prof.assign(
            pressure_bar=prof["pressure"] / 1e5, temperature_C=prof["temperature"] - 273.15,
            position_mm=prof["position"] * 1e3,
            contact_pressure_MPa=prof["contact_pressure"] / 1e6)[
            ["squeeze", "temperature_C", "pressure_bar", "position_mm",
             "contact_pressure_MPa"]])
        title = case.title or describe_seal(case)
        for i in range(ds.sizes["squeeze"]):
            name = "map.png" if ds.sizes["squeeze"] == 1 else f"map_squeeze{i}.png"
            folder.savefig(name, plot_map(ds, i, title=title))
            name = "map_profiles.png" if ds.sizes["squeeze"] == 1 \
                else f"map_profiles_squeeze{i}.png"
            folder.savefig(name, plot_map_profiles(ds, i, title=title))
        folder.write_text("case_resolved.toml", text)

    return run_variants({"map": case}, out, compute, write, force=force, inputs=[path])["map"]

