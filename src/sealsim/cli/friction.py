"""``sealsim friction run CASE.toml --out DIR``: run a friction test-bench case.

The command holds no physics: :func:`sealsim.runs.friction.run_case_file` runs the case and
writes the results; the command shows progress and prints the warnings and a short summary.
"""

from __future__ import annotations

from pathlib import Path

import typer

from sealsim.cli._common import console, guarded, print_notes, variant_progress

friction_app = typer.Typer(
    help="Dynamic friction laws (Stribeck, LuGre, Dahl, GMS, Θ rate-and-state) on test benches.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


@friction_app.callback()
def _friction() -> None:
    """Dynamic friction laws (Stribeck, LuGre, Dahl, GMS, Θ rate-and-state) on test benches."""


@friction_app.command("run")
@guarded
def run(
    case: Path = typer.Argument(..., help="Case file (TOML), e.g. examples/friction/"
                                          "lugre_hysteresis.toml."),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder (must not hold results "
                                                      "unless --force)."),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder."),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar."),
) -> None:
    """Run a friction bench case: time series, summary, plots and the resolved case."""
    from sealsim.runs.friction import run_case_file

    with variant_progress("friction", quiet, lambda _, f, __: f"{100 * f:.0f} %") as progress:
        summary = run_case_file(case, out, force, progress)
    print_notes(summary["warnings"], indent="", label="warning")
    if summary["notes"]:
        console.print(f"({len(summary['notes'])} note(s) on the parameters in summary.json)")
    summaries = summary["variants"]
    for name, s in summaries.items():
        brk = ", ".join(f"{f:.4g}" for f in s["breakaway_forces_N"][:4]) or "-"
        console.print(f"{name}: dissipated {s['dissipated_energy_J']:.4g} J, "
                      f"break-away [N]: {brk}")
    console.print(f"results written to {out}")
