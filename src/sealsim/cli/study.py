"""``sealsim study run``: parameter sweeps, tolerance and sensitivity studies on Dask.

The command holds no physics: it reads the study file, calls
:func:`sealsim.runs.study.run_study` and prints a short summary; results go through
:class:`sealsim.output.ResultFolder`.
"""

from __future__ import annotations

from pathlib import Path

import typer
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.text import Text

from sealsim.cli._common import console, err_console, guarded, print_notes, sealsim_notices

#: Notes of summary.json printed after a study (the rest are counted)
MAX_NOTES_SHOWN = 8

__all__ = ["study_app"]

study_app = typer.Typer(
    no_args_is_help=True,
    help="Parameter studies: grids of case values, Monte-Carlo / Latin-hypercube tolerance "
         "samples and Sobol' sensitivity, on this machine or a Dask cluster.")


def _progress(quiet: bool) -> Progress:
    return Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                    TextColumn("[red]{task.fields[failed]}"), TextColumn("ETA"),
                    TimeRemainingColumn(), TimeElapsedColumn(), console=err_console,
                    disable=quiet, transient=True, refresh_per_second=2)  # 10 Hz: 1 % of a core


@study_app.command("run")
@guarded
def run(
    study: Path = typer.Argument(..., help="Study file (TOML), e.g. "
                                           "examples/studies/gearbox_oils.toml"),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder to create"),
    scheduler: str = typer.Option(None, "--scheduler", help=(
        "Address of a running Dask scheduler (tcp://host:8786); default: a local cluster")),
    workers: int = typer.Option(None, "--workers", "-j", min=0, help=(
        "Worker processes of the local cluster (default: the usable cores); 0 runs in this "
        "process without Dask")),
    resume: bool = typer.Option(False, "--resume", help=(
        "Continue an interrupted study: reuse its finished runs, compute only the missing "
        "ones")),
    force: bool = typer.Option(False, "--force", help=(
        "Replace an existing result folder (without --resume: also drop the finished runs of "
        "an interrupted study)")),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar"),
) -> None:
    """Run every case of a study and write study.nc, runs.csv, summary.json and figures.

    Finished runs are kept in a hidden work folder next to OUT (.OUT.study) until the study is
    complete: after Ctrl-C, a killed process or a lost cluster, run the same command with
    --resume.
    """
    from sealsim.runs.study import run_study
    from sealsim.studies import load_study

    spec = load_study(study)
    shape = " x ".join(f"{d} {n}" for d, n in zip(spec.dims, spec.shape))
    console.print(f"study {study}: model {spec.model}, design {spec.design}, "
                  f"{spec.n_runs} runs ({shape})")
    with sealsim_notices(quiet), _progress(quiet) as bar:   # notices: FE maps built here
        tasks: dict[str, int] = {}

        def progress(phase: str, done: int, total: int, failed: int) -> None:
            label = "linked cases (FE maps)" if phase == "prepare" else "runs"
            shown = f"{failed} failed" if failed else ""
            if phase not in tasks:
                tasks[phase] = bar.add_task(label, total=total, completed=done, failed=shown)
            bar.update(tasks[phase], completed=done, failed=shown)

        try:
            result = run_study(spec, out, workers=workers, scheduler=scheduler, resume=resume,
                               force=force, progress=progress)
        except KeyboardInterrupt:
            err_console.print(Text("finished runs are kept; continue with the same command "
                                   "and --resume", style="yellow"))
            raise
    from sealsim.plotting import unit_text

    s = result.summary
    runs = s["runs"]
    console.print(f"{runs['finished']} of {runs['total']} runs finished, {runs['failed']} "
                  f"failed ({runs['computed']} computed, {runs['reused']} reused) on "
                  f"{s['engine']['kind']} ({s['engine']['workers']} workers) in "
                  f"{s['wall_time_s']:.1f} s")
    for name, o in s["outputs"].items():
        if o["n"]:
            unit = f" {unit_text(o['unit'])}".rstrip()
            console.print(f"  {name}: {o['min']:.4g} ... {o['max']:.4g}{unit} (median "
                          f"{o['P50']:.4g}, P5 {o['P5']:.4g}, P95 {o['P95']:.4g})")
    for failure in s["failures"][:3]:
        print_notes([failure["error"][:200]], label=f"run {failure['run']} failed")
    notes = s.get("notes", [])
    print_notes(notes[:MAX_NOTES_SHOWN])
    if len(notes) > MAX_NOTES_SHOWN:
        console.print(f"  ({len(notes) - MAX_NOTES_SHOWN} more notes in summary.json)")
    console.print(f"results written to {out}/ (study.nc, runs.csv, summary.json, figures)")
