"""Calibration commands, registered on the model apps: ``sealsim friction fit``,
``sealsim rotary fit``, ``sealsim pneumatic compare``.

The commands hold no physics: :mod:`sealsim.calibration` fits, :mod:`sealsim.runs.calibration`
writes the results; the command shows progress, prints the fitted values, the prediction
errors and why a fit failed.
"""

from __future__ import annotations

import contextlib
from pathlib import Path

import typer
from rich.text import Text

from sealsim.cli._common import console, err_console, guarded, print_notes, variant_progress
from sealsim.cli.friction import friction_app
from sealsim.cli.pneumatic import pneumatic_app
from sealsim.cli.rotary import rotary_app

FORCE_HELP = ("Replace an existing result folder (without --resume: also drop the finished "
              "evaluations of an interrupted fit).")
RESUME_HELP = ("Continue an interrupted fit: reuse its finished evaluations, compute only the "
               "missing ones.")


@friction_app.command("fit")
@guarded
def fit(
    case: Path = typer.Argument(..., help="Fit case file (TOML), e.g. examples/calibration/"
                                          "tudelft_oring.toml."),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder (must not hold results "
                                                      "unless --force)."),
    force: bool = typer.Option(False, "--force", help=FORCE_HELP),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar."),
    resume: bool = typer.Option(False, "--resume", help=RESUME_HELP),
) -> None:
    """Fit friction-law parameters to measurements; report the error on held-out runs.

    Finished evaluations are kept in a hidden work folder next to OUT (.OUT.fit) until the
    results are written: after Ctrl-C or a killed process, run the same command with --resume.
    """
    from sealsim.runs.calibration import run_friction_fit_file

    with variant_progress("fit", quiet, lambda _, d, n: f"{d:g}/{n:g}") as progress, \
            _resumable(out):
        summary = run_friction_fit_file(case, out, force, progress, resume=resume)
    report = summary["report"]
    for name, p in report["parameters"].items():
        value, se, unit = _in_case_unit(p)
        console.print((f"{name} = {value:.6g} ± {se:.2g}{unit} (1 s.e.)" if se is not None
                       else f"{name} = {value:.6g}{unit} (not determined)") + _limit(p))
    for name, m in report["measurements"].items():
        error = "-" if m["rel_error"] is None else f"{100 * m['rel_error']:+.1f} %"
        r2 = "-" if m["r2"] is None else f"{m['r2']:.3f}"
        console.print(f"{name} ({m['role']}): friction level measured {m['F_measured_N']:.3f} N,"
                      f" model {m['F_predicted_N']:.3f} N, error {error}, "
                      f"RMSE {m['rmse_N']:.3f} N, R² {r2}")
        if m.get("ratio_without_fit") is not None:
            console.print(f"  without fitting: {m['F_predicted_without_fit_N']:.3f} N, "
                          f"{m['ratio_without_fit']:.2f} x measured")
        if m.get("proportional_rel_error") is not None:
            console.print(f"  friction ∝ F_N (F_N {m['F_normal_N']:.1f} N, μ = F/F_N "
                          f"{m['mu_measured']:.4f} measured): {m['F_proportional_N']:.3f} N, "
                          f"error {100 * m['proportional_rel_error']:+.1f} %")
    for name, c in report.get("conditions", {}).items():
        if c["F_measured_std_N"] is None:
            continue
        error = "-" if c["rel_error_of_mean"] is None else f"{100 * c['rel_error_of_mean']:+.1f} %"
        in_std = ("no scatter" if c["error_in_std"] is None
                  else f"{c['error_in_std']:+.2f} std")
        cv = "-" if c["cv"] is None else f"{100 * c['cv']:.1f} %"
        console.print(f"{name} ({c['runs']} runs): measured {c['F_measured_mean_N']:.3f} ± "
                      f"{c['F_measured_std_N']:.3f} N (1 std of a run, cv {cv}), model "
                      f"{c['F_predicted_mean_N']:.3f} N, error of the mean {error} ({in_std})")
    print_notes(summary["warnings"], indent="", label="warning")
    if summary["evaluations"]["reused"]:
        console.print(f"{summary['evaluations']['reused']} evaluations reused from the "
                      "interrupted fit")
    console.print(f"results written to {out}")
    if summary["status"] != "ok":
        for text in summary["failure"]:
            err_console.print(Text("fit failed: ", style="bold red") + Text(text))
        raise typer.Exit(1)


@contextlib.contextmanager
def _resumable(out: Path):
    """After Ctrl-C (or SIGTERM) during a fit: say whether evaluations were kept."""
    from sealsim.calibration.kept import KeptEvaluations, work_folder_for

    try:
        yield
    except KeyboardInterrupt:
        kept = KeptEvaluations(work_folder_for(out), resume=True).count()
        if kept:
            err_console.print(Text(f"{kept} finished evaluations are kept; continue with the "
                                   "same command and --resume", style="yellow"))
        raise


@pneumatic_app.command("compare")
@guarded
def compare(
    compare_file: Path = typer.Argument(..., help="Compare file (TOML): the pneumatic case and "
                                                  "the measured x(t), p1(t), p2(t)."),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder (must not hold results "
                                                      "unless --force)."),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder."),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar."),
    time_offset: str = typer.Option(
        "0 s", "--time-offset", help="The logger's time at the simulation's t = 0, with a "
        "unit: '12.5 s', '1500 ms'; subtracted from the measured times."),
) -> None:
    """Simulate a cylinder case and compare it with a measured run (RMSE, R², overlays)."""
    from sealsim.runs.calibration import run_pneumatic_compare_file
    from sealsim.units import parse_quantity

    offset = parse_quantity(time_offset, "time", "--time-offset")
    with variant_progress("pneumatic", quiet, lambda _, t, e: f"{t:.3g}/{e:.3g} s") as progress:
        report = run_pneumatic_compare_file(compare_file, out, force, progress, offset)
    for name, s in report["signals"].items():
        r2 = "-" if s["r2"] is None else f"{s['r2']:.4f}"
        console.print(f"{name}: RMSE {s['rmse']:.4g} {s['unit']}, max error "
                      f"{s['max_abs_error']:.4g} {s['unit']}, R² {r2}")
    times = report.get("stroke_times")
    for key in ("extend_time_s", "retract_time_s") if times else ():
        shown = ["-" if t[key] is None else f"{t[key]:.4g} s"
                 for t in (times["measured"], times["model"])]
        console.print(f"{key.split('_')[0]} time: measured {shown[0]}, model {shown[1]}")
    console.print(f"results written to {out}")


@rotary_app.command("fit")
@guarded
def rotary_fit(
    case: Path = typer.Argument(..., help="Rotary fit case file (TOML), e.g. examples/"
                                          "calibration/rotary_synthetic.toml."),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder (must not hold results "
                                                      "unless --force)."),
    force: bool = typer.Option(False, "--force", help=FORCE_HELP),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar."),
    resume: bool = typer.Option(False, "--resume", help=RESUME_HELP),
) -> None:
    """Fit lip seal parameters to measured speed cycles (torque, spring-groove temperature);
    report the step-average errors, also on held-out runs.

    Finished simulations are kept in a hidden work folder next to OUT (.OUT.fit) until the
    results are written: after Ctrl-C or a killed process, run the same command with --resume.
    """
    from sealsim.runs.calibration import run_rotary_fit_file

    with variant_progress("stage", quiet, lambda _, d, n: f"{d:g}/{n:g} evaluations") \
            as progress, _resumable(out):
        summary = run_rotary_fit_file(case, out, force, progress, resume=resume)
    report = summary["report"]
    for name, p in report["parameters"].items():
        shown = f"{name} = {_rounded(p['text'], p['value'])}"
        if p["relative_standard_error"] is None:
            console.print(f"{shown} (not determined)" + _limit(p))
        else:
            console.print(f"{shown} ± {100 * p['relative_standard_error']:.2g} % (1 s.e.)"
                          + ("" if p["identifiable"] else " -- not identifiable") + _limit(p))
    for name, m in report["measurements"].items():
        if m["torque_rel_error_mean"] is None:  # standstill only: no relative error
            line = f"{name} ({m['role']}): no step with the shaft turning"
        else:
            line = (f"{name} ({m['role']}): step-average torque error mean "
                    f"{100 * m['torque_rel_error_mean']:.1f} %, max "
                    f"{100 * m['torque_rel_error_max']:.1f} %, RMSE "
                    f"{m['torque_rmse_Nm']:.4f} N m")
        if "T_groove_rmse_K" in m:
            line += (f"; groove temperature RMSE {m['T_groove_rmse_K']:.2f} K, max "
                     f"{m['T_groove_error_max_K']:.2f} K")
        console.print(line)
    print_notes(summary["warnings"], indent="", label="warning")
    reused = summary["evaluations"]["reused"]
    console.print(f"{summary['simulations']} simulations"
                  + (f" ({reused} parameter sets reused from the interrupted fit)" if reused
                     else "") + f"; results written to {out}")
    if summary["status"] != "ok":
        for text in summary["failure"]:
            err_console.print(Text("fit failed: ", style="bold red") + Text(text))
        raise typer.Exit(1)


def _limit(parameter) -> str:
    """" -- at its upper bound" (or lower bound, or on a constraint) of a fitted parameter the
    data did not determine, else ""."""
    limit = parameter.get("at_limit")
    if not limit:
        return ""
    return (" -- set by a constraint of the model, not by the data"
            if limit.startswith("constraint") else f" -- at its {limit}")


def _rounded(text, value: float) -> str:
    """A fitted value for the terminal: 4 significant digits, with the case file's unit."""
    if isinstance(text, str):
        number, _, unit = text.partition(" ")
        try:
            return f"{float(number):.4g} {unit}"
        except ValueError:
            return text
    return f"{value:.4g}"


def _in_case_unit(parameter):
    """(value, standard error, " unit") of a fitted parameter in the unit of its ``text``
    ("8.3e-05 mm"; value and standard error are SI): the SI numbers with the case's unit
    printed 8.3e-08 "mm" for a 0.083 µm grease layer."""
    from sealsim.units import unit_registry

    value, se, text = parameter["value"], parameter["standard_error"], parameter.get("text")
    if not (isinstance(text, str) and " " in text):
        return value, se, ""
    unit = text.split(" ", 1)[1]
    si_per_unit = unit_registry().Quantity(1.0, unit).to_base_units().magnitude
    return (value / si_per_unit, None if se is None else se / si_per_unit, f" {unit}")
