"""``sealsim structure run|map``: axisymmetric FE of a seal in its gland, characteristic maps.

The commands hold no physics: they read the case, call :mod:`sealsim.runs.structure` and
print a short summary; results go through :class:`sealsim.output.ResultFolder`.
"""

from __future__ import annotations

from pathlib import Path

import typer
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

from sealsim.cli._common import console, err_console, guarded

__all__ = ["structure_app"]

structure_app = typer.Typer(
    help="Seal structural mechanics: axisymmetric hyperelastic FE of any seal profile in its "
         "gland (O-ring, X-ring, rectangular ring, U-cup, wiper, DIN 3760 lip seal, your own "
         "polyline or DXF; FElupe, gmsh), normal force F_N, contact width b and pressure, "
         "characteristic maps.",
    no_args_is_help=True,
)


def _progress(quiet: bool) -> Progress:
    return Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                    TimeElapsedColumn(), console=err_console, disable=quiet, transient=True)


@structure_app.command("run")
@guarded
def run(
    case: Path = typer.Argument(
        ..., help="Case file (TOML), e.g. examples/structure/oring_rod.toml"),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder to create"),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder"),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar"),
) -> None:
    """Solve the load path (squeeze, pressure, temperature) of a seal case.

    Writes result.csv (one row per load state), profiles.csv (contact pressure p(z)),
    increments.csv (Newton iterations and cutbacks of every increment), summary.json,
    section_installed.png, section_final.png, states.png and case_resolved.toml.
    """
    from sealsim.runs.structure import run_case_file

    with _progress(quiet) as bar:
        tasks: dict[str, int] = {}

        def progress(variant: str, done: int, total: int) -> None:
            if variant not in tasks:
                tasks[variant] = bar.add_task(f"structure {variant}", total=total)
            bar.update(tasks[variant], completed=done)

        runs = run_case_file(case, out, force, progress)
    for name, result in runs.items():
        last = result.states[-1]
        console.print(
            f"[bold]{name}[/]: {len(result.states)} load states, {result.ndofs} dofs, "
            f"{result.wall_time:.1f} s; final F_N = {last.F_N:.1f} N "
            f"({last.F_N_per_length / 1e3:.3f} N/mm), b = {last.b * 1e3:.3f} mm, "
            f"p_max = {last.p_max / 1e6:.2f} MPa")
    where = f"{out}/" if len(runs) == 1 else f"{out}/VARIANT/ for {', '.join(runs)}"
    console.print(f"results written to {where} (result.csv, profiles.csv, increments.csv, "
                  "summary.json, section_*.png, states.png; case_resolved.toml in "
                  f"{out}/)")


@structure_app.command("map")
@guarded
def map_(
    case: Path = typer.Argument(..., help="Case file (TOML) with a \\[map] table"),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder to create"),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder"),
    workers: int = typer.Option(None, "--workers", "-j", min=1,
                                help="Worker processes (default: map.workers of the case)"),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar"),
) -> None:
    """Characteristic map F_N, b, p(z) over pressure x temperature (x squeeze), in parallel.

    Writes map.nc (netCDF; read it with sealsim.structure.load_map), map.csv,
    map_profiles.csv, map.png, map_profiles.png and case_resolved.toml. Finished load paths
    are kept in .OUT.map until then: after Ctrl-C or a killed process, the same command
    computes only the missing ones.
    """
    from sealsim.runs.structure import map_case_file

    with _progress(quiet) as bar:
        task = None

        def progress(done: int, total: int) -> None:
            nonlocal task
            if task is None:
                task = bar.add_task("FE load paths (squeeze x temperature)", total=total)
            bar.update(task, completed=done)

        ds = map_case_file(case, out, force, progress, workers=workers)
    f = ds["F_N"].values
    console.print(
        f"map of {f.size} points ({ds.sizes['squeeze']} squeeze x {ds.sizes['temperature']} "
        f"temperature x {ds.sizes['pressure']} pressure): F_N {f.min():.1f} ... {f.max():.1f} N, "
        f"b {ds['b'].values.min() * 1e3:.3f} ... {ds['b'].values.max() * 1e3:.3f} mm")
    console.print(f"results written to {out}/ (map.nc, map.csv, map_profiles.csv, map.png, "
                  "map_profiles.png, case_resolved.toml)")
