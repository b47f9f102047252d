"""``sealsim gland check``: O-ring gland design check (squeeze, stretch, fill, extrusion gap).

The command holds no physics: it calls :mod:`sealsim.runs.gland` (which calls
:func:`sealsim.oring_gland`) and prints the stack and the checks.
"""

from __future__ import annotations

from pathlib import Path

import typer

from sealsim.cli._common import console, guarded, print_notes, variant_progress

__all__ = ["gland_app"]

gland_app = typer.Typer(
    help="O-ring and X-ring glands (static, rod, piston, face): squeeze, stretch, gland fill "
         "and extrusion gap from the worst-case tolerance stack (ISO 3601-1 rings, ISO 286 "
         "fits) at the service temperatures, against the published design ranges.",
    no_args_is_help=True,
)


@gland_app.command("check")
@guarded
def check(
    case: Path = typer.Argument(..., help="Gland case (TOML), e.g. "
                                          "examples/gland/piston_static.toml"),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder to create"),
    fe: bool = typer.Option(False, "--fe", help="Also the FE contact force and friction at "
                                                "nominal (the case's \\[fe] table)"),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder"),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar"),
) -> None:
    """Check a gland: worst-case squeeze, stretch, gland fill and extrusion gap.

    Writes report.json, checks.csv, stack.csv, section.png and case_resolved.toml.  A failed
    check is a result: it is written and named (report.json "ok": false, "failed": [...]),
    and the command exits with status 1, so a script or build step stops at a gland that
    fails (0: all checks pass; 2: bad input).
    """
    from sealsim.plotting.gland import check_label
    from sealsim.runs.gland import check_case_file

    with variant_progress("FE", quiet, lambda _, done, total: f"{done:.0f}/{total:.0f}") \
            as progress:
        report = check_case_file(case, out, force, fe, progress)
    for key, label, unit in (("squeeze_percent", "squeeze", "%"),
                             ("stretch_percent", "stretch", "%"),
                             ("gland_fill_percent", "gland fill", "%"),
                             ("extrusion_gap_mm", "extrusion gap", "mm")):
        s = report[key]
        console.print(f"{label:<14} {s['min']:8.3g} ... {s['max']:8.3g} {unit} "
                      f"(nominal {s['nominal']:.3g})")
    for c in report["checks"]:
        mark = "[green]ok  [/]" if c["ok"] else "[bold red]FAIL[/]"
        sign = ">=" if c["bound"] == "min" else "<="
        console.print(f"{mark} {check_label(c):<26} {c['value']:.3g} {c['unit']} {sign} "
                      f"{c['limit']:.3g} {c['unit']}")
    if "fe" in report:
        f = report["fe"]
        out_, in_ = f["friction_N"]["outstroke"], f["friction_N"]["instroke"]
        console.print(f"FE at nominal ({f['squeeze_percent']:.1f} % squeeze): F_N "
                      f"{f['normal_force_N']['unpressurised']:.1f} N, at "
                      f"{f['pressure_bar']:g} bar {f['normal_force_N']['at_pressure']:.1f} N; "
                      f"friction at {f['velocity_m_s']:g} m/s outstroke / instroke "
                      f"{out_['unpressurised']:.1f} / {in_['unpressurised']:.1f} N, at "
                      f"{f['pressure_bar']:g} bar {out_['at_pressure']:.1f} / "
                      f"{in_['at_pressure']:.1f} N")
    print_notes(report["notes"])
    verdict = "all checks pass" if report["ok"] else f"FAILED: {', '.join(report['failed'])}"
    console.print(f"[bold]{verdict}[/]; results written to {out}/ (report.json, checks.csv, "
                  "stack.csv, section.png, case_resolved.toml)")
    if not report["ok"]:
        raise typer.Exit(1)
