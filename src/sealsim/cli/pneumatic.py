"""``sealsim pneumatic run CASE.toml --out DIR``: pneumatic cylinder with seal friction (Heipl &
Murrenhoff).

The command holds no physics: it reads the case, calls :mod:`sealsim.runs.pneumatic` and
prints a short summary; results go through :class:`sealsim.output.ResultFolder`.
"""

from __future__ import annotations

from pathlib import Path

import typer

from sealsim.cli._common import (console, guarded, notes_of_every_variant, print_notes,
                                 variant_progress)

__all__ = ["pneumatic_app"]

pneumatic_app = typer.Typer(
    help="Pneumatic cylinder system simulation (after Heipl & Murrenhoff): valve, chambers, "
         "piston and seal friction (Θ law with F_N and b from contact maps).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


@pneumatic_app.callback()
def _pneumatic() -> None:
    """Pneumatic cylinder system simulation (after Heipl & Murrenhoff)."""


@pneumatic_app.command("run")
@guarded
def run(
    case: Path = typer.Argument(..., help="Case file (TOML), e.g. "
                                          "examples/pneumatic/cylinder_32.toml"),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder to create"),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder"),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar"),
) -> None:
    """Simulate a cylinder driven by a valve and a PLC cycle (or a prescribed motion).

    Writes timeseries.csv (all variants, column 'variant'), summary.json (extend/retract times,
    friction, air consumption, mass and energy balance errors per variant), case_resolved.toml
    and figures: pressure_stroke.png (like Heipl & Murrenhoff Fig. 10), friction_stroke.png
    (Figs. 12/13), friction_velocity.png and timeseries_VARIANT.png; with seal heating
    (\\[thermal]) also heating_VARIANT.png and strokes_VARIANT.csv (temperatures, friction and
    stroke times, stroke by stroke).
    """
    from sealsim.runs.pneumatic import run_case_file

    def describe(variant: str, t: float, end: float) -> str:
        unit = "FE load paths" if variant.endswith("FE map") else "s"
        return f"{t:.3g}/{end:.3g} {unit}"

    with variant_progress("pneumatic", quiet, describe) as progress:
        results = run_case_file(case, out, force, progress)
    shared = notes_of_every_variant({name: r.notes for name, r in results.items()})
    for name, result in results.items():
        s = result.summary()
        ext, ret = s["extend_time_s"], s["retract_time_s"]
        times = (f"extend {ext:.3f} s, retract {ret:.3f} s, " if ext is not None
                 and ret is not None else "")
        mean = s["mean_friction_N"]
        heat = (f", heat {s['balances']['heat_balance_rel_error']:.1e}"
                if "heat_balance_rel_error" in s["balances"] else "")
        console.print(
            f"[bold]{name}[/]: {times}friction mean "
            f"{'-' if mean is None else f'{mean:.1f}'} N, peak {s['peak_friction_N']:.1f} N, "
            f"air {s['air_consumption_NL']:.3f} NL"
            + (f" (returned to the supply {s['air_returned_to_supply_NL']:.3f} NL)"
               if s["air_returned_to_supply_NL"] >= 5e-4 else "")
            + "; balance errors mass "
            f"{s['mass_balance_rel_error']:.1e}, energy {s['energy_balance_rel_error']:.1e}"
            f"{heat}")
        print_notes([n for n in result.notes if n not in shared])
    print_notes(shared, indent="", label="note (every variant)")
    heated = any(r.case.thermal is not None and r.case.thermal.seal_heating
                 for r in results.values())
    console.print(f"results written to {out}/ (plots: pressure_stroke.png, friction_stroke.png,"
                  " friction_velocity.png, timeseries_*.png"
                  + (", heating_*.png" if heated else "") + "; tables: timeseries.csv, "
                  + ("strokes_*.csv, " if heated else "") + "summary.json)")
