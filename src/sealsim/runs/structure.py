"""``sealsim structure run`` and ``sealsim structure map``: a structure case file into a result
folder.

:func:`run_case_file` solves the load path of every variant
(:func:`sealsim.structure.run.run_case`) and writes per variant ``result.csv``,
``profiles.csv``, ``increments.csv``, ``summary.json`` and the figures;
:func:`map_case_file` computes a characteristic map (:func:`sealsim.structure.mapping.compute_map`)
and writes ``map.nc``, the tables and the figures.  Both can be used from Python as well.
"""

from __future__ import annotations

import shutil
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.cases import dump_variants_toml
from sealsim.errors import InputError
from sealsim.output import ResultFolder, run_variants
from sealsim.plotting.structure import plot_map, plot_map_profiles, plot_section, plot_states
from sealsim.structure.build import describe_seal
from sealsim.structure.case import StructureCase, load_structure_cases
from sealsim.structure.mapping import compute_map
from sealsim.structure.results import profiles_frame, results_frame
from sealsim.structure.run import SUMMARY_KEYS, RunResult, run_case
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["map_case_file", "run_case_file"]


def _resolved_text(cases: dict[str, StructureCase]) -> str:
    return dump_variants_toml(cases, header="resolved sealsim structure case (all defaults "
                                            "filled in)")


def run_case_file(path: str | Path, out: str | Path, force: bool = False,
                  progress: Callable[[str, int, int], None] | None = None
                  ) -> dict[str, RunResult]:
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
    force : bool
        Replace existing results.
    progress : callable, optional
        ``progress(variant, done, total)``.
    """
    cases = load_structure_cases(path)
    many = len(cases) > 1

    def write_variant(folder, name, result):
        _write_variant(folder, f"{name}/" if many else "", name, cases[name], result)

    return run_variants(
        cases, out, lambda name, case, report: run_case(case, progress=report),
        lambda folder, runs: folder.write_text("case_resolved.toml", _resolved_text(cases)),
        force=force, inputs=_inputs(path, cases), progress=progress, write_each=write_variant)


def _inputs(path, cases: dict[str, StructureCase]) -> list[Path]:
    """The case file and the DXF drawings it read (refused inside the result folder)."""
    path = Path(path)
    return [path] + [path.parent / c.seal.drawing for c in cases.values()
                     if getattr(c.seal, "drawing", None)]


def material_description(case: StructureCase, material) -> str:
    """What the run's rubber was: the FE material's name, its model and, for a hyperelastic
    one, its temperature law (results are reported with it, e.g. where a cooled seal loses
    its groove contact)."""
    spec = case.material
    if spec.model == "viscoelastic":
        return f"{material.name}: thermo-viscoelastic (Prony series, WLF/Arrhenius shift, " \
               "glassy expansion below T_g)"
    return f"{material.name}: hyperelastic, temperature_scaling = {spec.temperature_scaling!r}"


def groove_contact_lost_at(frame: pd.DataFrame) -> float | None:
    """Temperature [°C] of the first recorded state without groove-bottom contact after one
    with it (a seal shrinking off its groove on cooling), or None."""
    if "F_groove_bottom_N" not in frame:
        return None
    touching = frame["F_groove_bottom_N"].to_numpy() > 0.0
    lost = np.nonzero(~touching[1:] & touching[:-1])[0]
    return None if not len(lost) else float(frame["temperature_C"].iloc[lost[0] + 1])


def _write_variant(folder: ResultFolder, prefix: str, name: str, case: StructureCase,
                   result: RunResult) -> None:
    """Tables, figures and summary of one solved variant (into sub-folder ``prefix``)."""
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
    folder.savefig(prefix + "states.png", plot_states(
        frame, title=title, groove_bottom="groove_bottom" in result.states[0].surfaces))
    last = frame.iloc[-1]
    folder.write_json(prefix + "summary.json", {
        "variant": name,
        "material": material_description(case, result.model.material),
        "groove_contact_lost_at_C": groove_contact_lost_at(frame),
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


def map_case_file(path: str | Path, out: str | Path, force: bool = False,
                  progress: Callable[[int, int], None] | None = None,
                  workers: int | None = None):
    """``sealsim structure map``: characteristic map of a case (its ``[map]`` table).

    Writes ``map.nc`` (xarray/netCDF, SI units, the resolved case as attribute ``case``),
    ``map.csv`` (flat table in engineering units), ``map_profiles.csv`` (contact pressure
    p(z) at every grid point), ``map.png``, ``map_profiles.png`` and ``case_resolved.toml``.
    Only cases without variants.  Finished load paths are kept in ``.OUT.map`` next to
    ``out`` until the results are written: run the same command again after an interruption
    (Ctrl-C, a killed process) and only the missing paths are computed.

    Returns
    -------
    xarray.Dataset
        The map (as written to ``map.nc``).
    """
    cases = load_structure_cases(path)
    if len(cases) != 1:
        raise InputError("structure map: the case has variants; map one case at a time "
                         "(remove the [variants] tables)")
    case = next(iter(cases.values()))
    if case.map is None:
        raise InputError(f"{path}: the case has no [map] table with map.pressure and "
                         "map.temperature grids")
    text = _resolved_text(cases)

    target = Path(out).resolve()
    kept = target.with_name(f".{target.name}.map")

    def compute(name, case, report):
        return compute_map(case, workers=workers, progress=progress, case_text=text,
                           keep=kept)

    def write(folder, results):
        ds = results["map"]
        folder.write_netcdf("map.nc", ds)
        flat = ds.drop_dims("position").to_dataframe().reset_index()
        table = flat.assign(
            squeeze_percent=flat["squeeze"] * 100.0, pressure_bar=flat["pressure"] / 1e5,
            temperature_C=flat["temperature"] - ZERO_CELSIUS_K, F_N_N=flat["F_N"],
            F_N_per_length_N_per_mm=flat["F_N_per_length"] / 1e3, b_mm=flat["b"] * 1e3,
            p_max_MPa=flat["p_max"] / 1e6, p_mean_MPa=flat["p_mean"] / 1e6,
            F_groove_bottom_N=flat["F_groove_bottom"], contact_zones=flat["contact_zones"],
            b_span_mm=flat["b_span"] * 1e3)[
            ["squeeze_percent", "pressure_bar", "temperature_C", "F_N_N", "F_N_per_length_N_per_mm",
             "b_mm", "p_max_MPa", "p_mean_MPa", "F_groove_bottom_N", "contact_zones",
             "b_span_mm"]]
        folder.write_csv("map.csv", table)
        prof = ds["contact_pressure"].to_dataframe().reset_index()
        folder.write_csv("map_profiles.csv", prof.assign(
            squeeze_percent=prof["squeeze"] * 100.0, pressure_bar=prof["pressure"] / 1e5,
            temperature_C=prof["temperature"] - ZERO_CELSIUS_K,
            position_mm=prof["position"] * 1e3,
            contact_pressure_MPa=prof["contact_pressure"] / 1e6)[
            ["squeeze_percent", "temperature_C", "pressure_bar", "position_mm",
             "contact_pressure_MPa"]])
        title = case.title or describe_seal(case)
        for i in range(ds.sizes["squeeze"]):
            name = "map.png" if ds.sizes["squeeze"] == 1 else f"map_squeeze{i}.png"
            folder.savefig(name, plot_map(ds, i, title=title))
            name = "map_profiles.png" if ds.sizes["squeeze"] == 1 \
                else f"map_profiles_squeeze{i}.png"
            folder.savefig(name, plot_map_profiles(ds, i, title=title))
        folder.write_text("case_resolved.toml", text)

    ds = run_variants({"map": case}, out, compute, write, force=force,
                      inputs=_inputs(path, cases))["map"]
    shutil.rmtree(kept, ignore_errors=True)   # the map is written: its paths are not needed
    return ds
