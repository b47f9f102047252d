"""``sealsim fmu build CASE.toml --out NAME.fmu``: export a seal model as an FMU.

The command holds no physics: :func:`sealsim.fmu.build_fmu` builds, checks and writes the
FMU; the command shows progress and prints what was built and the errors measured against
sealsim's own model.
"""

from __future__ import annotations

from pathlib import Path

import typer

from sealsim.cli._common import console, guarded, print_notes, variant_progress

fmu_app = typer.Typer(
    help="FMU export: seal friction, whole pneumatic cylinders and rotary lip seals as "
         "FMI 2.0 / 3.0 units for system-simulation tools.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


@fmu_app.callback()
def _fmu() -> None:
    """FMU export: seal friction, pneumatic cylinders and rotary lip seals as FMI 2.0 / 3.0
    units."""


@fmu_app.command("build")
@guarded
def build(
    case: Path = typer.Argument(..., help="A friction case, a pneumatic case (the whole "
                                          "cylinder, or one seal with --seal), a rotary case, "
                                          "or an FMU case (examples/fmu/)."),
    out: Path = typer.Option(..., "--out", "-o", help="The FMU file to write (NAME.fmu; must "
                                                      "not exist unless --force)."),
    fmi: int = typer.Option(2, "--fmi", help="FMI version: 2 or 3."),
    kind: str = typer.Option("both", "--kind", help="me (model exchange), cs "
                                                    "(co-simulation) or both."),
    force: bool = typer.Option(False, "--force", help="Replace an existing FMU file."),
    variant: str = typer.Option(None, "--variant", help="The variant of the case to export."),
    seal: str = typer.Option(None, "--seal", help="The seal of a pneumatic case to export "
                                                  "(without it: the whole cylinder)."),
    no_compile: bool = typer.Option(False, "--no-compile", help="Write a source-only FMU "
                                                                "(no binary)."),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar."),
) -> None:
    """Build an FMU (default FMI 2.0, model exchange and co-simulation in one file).

    The FMU holds the compiled binary of this platform, the C sources
    (sources/buildDescription.xml) and documentation/ (index.html, tables, figures, the
    errors measured against sealsim's model).
    """
    from sealsim.fmu import build_fmu

    with variant_progress("fmu", quiet, lambda _, d, n: f"{d:g}/{n:g}") as progress:
        result = build_fmu(case, out, fmi_version=fmi, kind=kind, force=force,
                           variant=variant, seal=seal, compile=not no_compile,
                           progress=progress)
    report = result.report
    interfaces = " + ".join({"me": "model exchange", "cs": "co-simulation"}[k]
                            for k in result.kinds)
    console.print(f"{result.path}: FMI {report['fmi_version']}, {interfaces}, binary "
                  f"{result.binary or 'none (source FMU)'}")
    if "c_law" in report:
        check = report.get("build_check", {}).get("max_relative_difference")
        table = report.get("contact_table")
        console.print(f"law {report['c_law']}" + (" with bristles" if report["bristles"] else "")
                      + (f"; contact table from {table['source']} (largest relative table "
                         f"error {max(table['max_relative_error'].values()):.1e})" if table
                         else ""))
        if check:
            law_diff = max(v for k, v in check.items() if k != "contact")
            console.print(f"checked against sealsim's law: largest relative difference "
                          f"{law_diff:.1e}" + (f"; F_N, b against the contact map "
                                                f"{check['contact']:.1e}" if table else ""))
    for key, label in (("grid", "steady, grid points"), ("between", "steady, between them"),
                       ("duty_cycle", "the case's duty cycle")):
        v = report.get("validation", {}).get(key)
        if v:
            console.print(f"{label}: torque error max {100 * v['max_torque_rel_error']:.2f} %, "
                          f"contact temperature error max {v['max_T_contact_error_K']:.2f} K")
    rhs_check = report.get("rhs_check")
    if rhs_check:
        worst = max(rhs_check["max_relative_difference"].values())
        console.print(f"C right-hand side checked against sealsim's compiled one: largest "
                      f"relative difference {worst:.1e}")
    cycle = report.get("cycle_check")
    if cycle:
        rel = cycle["relative_difference"]
        console.print(f"co-simulation over the case's cycle against sealsim pneumatic run: "
                      f"extend time {100 * rel['extend_time_s']:.3f} %, retract time "
                      f"{100 * rel['retract_time_s']:.3f} %")
    print_notes(report.get("notes", []), indent="")
    console.print(f"FMU written to {result.path} (documentation/index.html inside)")
