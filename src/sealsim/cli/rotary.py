"""``sealsim rotary ...``: radial lip seal friction and temperature (Organisciak et al. 2014)."""

from __future__ import annotations

import warnings
from pathlib import Path

import typer
from sealsim.cli._common import (console, guarded, notes_of_every_variant, print_notes,
                                 variant_progress)

rotary_app = typer.Typer(no_args_is_help=True, help=(
    "Radial lip seals in gearboxes (after Organisciak et al., AGMA 14FTM14, 2014): friction "
    "torque and temperatures over speed cycles, plain vs wave lips, oil sump volume."))


@rotary_app.command("run")
@guarded
def run(
    case: Path = typer.Argument(..., help="Case file (TOML), e.g. examples/rotary/speed_cycle.toml"),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder to create"),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder"),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar"),
) -> None:
    """Simulate a duty cycle with coupled friction and heat transfer.

    Writes timeseries.csv, steps.csv, summary.json (averages over the last 30 s of each step),
    case_resolved.toml and figures (cycle_VARIANT.png like Organisciak et al. 2014, Fig. 9,
    variants.png like Fig. 12, stribeck.png).
    """
    from sealsim.runs.rotary import run_case_file
    from sealsim.tribology.film import FilmRangeWarning

    with variant_progress("rotary", quiet,
                          lambda _, t, end: f"{t / 60:.0f}/{end / 60:.0f} min") as progress, \
            warnings.catch_warnings():
        warnings.simplefilter("ignore", FilmRangeWarning)  # printed below as a note
        results = run_case_file(case, out, force, progress)
    shared = notes_of_every_variant({name: r.notes for name, r in results.items()})
    for name, result in results.items():
        last = result.steps[-1]
        console.print(f"[bold]{name}[/]: end of cycle {last['speed_rpm']:.0f} rpm, torque "
                      f"{last['torque_Nm']:.3f} N m, groove {last['T_groove_C']:.1f} °C, contact "
                      f"{last['T_contact_C']:.1f} °C; relative energy balance error "
                      f"{result.energy['rel_error']:.1e}")
        print_notes([n for n in result.notes if n not in shared])
    print_notes(shared, indent="", label="note (every variant)")
    console.print(f"results written to {out}/ (plots: cycle_*.png, variants.png, stribeck.png; "
                  "tables: timeseries.csv, steps.csv, summary.json)")
