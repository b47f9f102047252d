"""``sealsim friction fit``, ``sealsim rotary fit`` and ``sealsim pneumatic compare``: a fit or
compare file into a result folder.

The fits and the comparison are computed by :mod:`sealsim.calibration`
(:func:`~sealsim.calibration.study.friction_fit_study`,
:func:`~sealsim.calibration.rotary_study.rotary_fit_study`,
:func:`~sealsim.calibration.pneumatic_compare.compare_pneumatic_file`); this module checks the
result folder before anything is computed and writes the tables, reports and figures.

``sealsim friction fit`` writes

* ``fitted_parameters.toml`` -- a ``[friction]`` table with every parameter of the law, readable
  by any friction or pneumatic case;
* ``report.json`` (fitted parameters, per measurement the friction level measured and
  predicted, RMSE, R²), ``fit.json`` (status, reasons of a failed fit, stages, correlation
  matrix, warnings);
* ``predictions.csv`` (measured, offset-free, and model friction of every run);
* ``overlay_<run>.png`` per run, ``parity.png`` (±20 % band), ``case_resolved.toml``;
* with repeated tests (measurements sharing a ``condition``): ``conditions.csv`` (per condition
  the runs, the mean, standard deviation and coefficient of variation of the measured level,
  the model's error of the mean, also in units of that standard deviation) and
  ``repeatability.png``.

``sealsim rotary fit`` writes

* ``fitted_parameters.toml`` -- the fitted fields as rotary-case tables;
* ``report.json``, ``fit.json`` (see :mod:`sealsim.calibration.rotary_study`);
* ``predictions.csv``, ``steps.csv`` (step averages), ``duty_<run>.csv`` (the duty cycle built
  from each measured speed, readable as ``duty.csv`` of a rotary case);
* ``overlay_<run>.png`` (speed | torque | groove temperature, like Fig. 9 of Organisciak et
  al., AGMA 14FTM14, 2014), ``parity.png`` (step-average torque, ±20 % band, like their
  Fig. 10), ``parity_temperature.png``, ``case_resolved.toml``.

``sealsim pneumatic compare`` writes ``report.json`` (per signal: rmse, max_abs_error, r2 in
the signal's unit), ``comparison.csv`` and ``comparison.png`` (x, p1, p2 over time, measured
and model).
"""

from __future__ import annotations

import contextlib
import math
import re
from collections.abc import Callable, Iterator
from pathlib import Path

import pandas as pd
import tomli_w

from sealsim.calibration.kept import KeptEvaluations, work_folder_for
from sealsim.calibration.pneumatic_compare import compare_inputs, compare_pneumatic_file
from sealsim.calibration.rotary_study import load_rotary_fit_case, rotary_fit_study
from sealsim.calibration.study import friction_fit_study, load_fit_case
from sealsim.cases import dump_case_toml
from sealsim.files import file_digests
from sealsim.output import ResultFolder
from sealsim.plotting.calibration import (
    plot_fitted_steady_curves,
    plot_overlay,
    plot_parity,
    plot_repeats,
    plot_rotary_overlay,
    plot_signals,
    plot_stroke_levels,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["run_friction_fit_file", "run_pneumatic_compare_file", "run_rotary_fit_file"]

#: Half-width of the band of the rotary temperature parity plot [K].
TEMPERATURE_BAND = 2.0


def run_friction_fit_file(path: str | Path, out: str | Path, force: bool = False,
                          progress: Callable[[str, float, float], None] | None = None,
                          cache_dir: str | Path | None = None, resume: bool = False) -> dict:
    """Fit a friction law to measurements and write the result folder ``out``.

    Parameters
    ----------
    path : path
        Fit case file (TOML), see :mod:`sealsim.calibration.case`.
    out : path
        Result folder (refused if it holds results, unless ``force``).
    force : bool
        Replace existing results.
    progress : callable, optional
        ``progress(task, done, total)``.
    cache_dir : path, optional
        Cache folder of FE contact maps built from a structure case.
    resume : bool
        Continue an interrupted fit: reuse the evaluations it kept (:func:`keep_evaluations`).

    Returns
    -------
    dict
        ``{"status", "failure", "warnings", "report", "evaluations"}``; status "failed" when a
        parameter ended at a bound or the optimiser stopped (results are still written, with
        the reasons); ``evaluations``: how many were ``computed`` and ``reused``.
    """
    path = Path(path)
    case = load_fit_case(path)
    inputs = fit_case_inputs(case, path)
    folder = ResultFolder(out, force, inputs=inputs)  # before computing
    kept = KeptEvaluations(work_folder_for(out), resume=resume, discard=force,
                           source=str(path), files=file_digests(inputs))
    with keep_evaluations(kept), folder:
        study = friction_fit_study(case, path.parent, progress, cache_dir, kept)
        result = study.result
        fit_names = ", ".join(r.name for r in study.runs if r.spec.role == "fit")
        fitted_text = (f"# Friction parameters fitted by 'sealsim friction fit "
                       f"{_comment(path.name)}'\n# on {_comment(fit_names)}; status "
                       f"{result.status}.\n# Use the [friction] table in a friction case, or "
                       "as friction = {...} of a pneumatic seal.\n\n"
                       + tomli_w.dumps(study.fitted))
        title = case.title or path.stem
        folder.write_text("fitted_parameters.toml", fitted_text)
        folder.write_json("report.json", study.report)
        folder.write_json("fit.json", study.diagnostics)
        folder.write_csv("predictions.csv", study.predictions_frame(), float_format="%.8g")
        folder.write_csv("measurements.csv", pd.DataFrame(
            [{"measurement": name, **m} for name, m in study.report["measurements"].items()]),
            float_format="%.6g")
        for r, slug in zip(study.runs, _unique_slugs([r.name for r in study.runs])):
            folder.savefig(f"overlay_{slug}.png",
                           plot_overlay(r.name, r.spec.role, r.time, r.position, r.friction,
                                        study.predictions[r.name], title))
        folder.savefig("stroke_levels.png", plot_stroke_levels(
            {name: (*levels, study.report["measurements"][name]["drift_measured_rel"])
             for name, levels in study.stroke_levels().items()}, title))
        points = [(name, m["role"], m["F_measured_N"], m["F_predicted_N"])
                  for name, m in study.report["measurements"].items()]
        proportional = [(m["F_measured_N"], m["F_proportional_N"])
                        for m in study.report["measurements"].values()
                        if m.get("F_proportional_N") is not None]
        folder.savefig("parity.png", plot_parity(
            points, title, reference=proportional,
            reference_label="friction ∝ F_N (μ from the fitted runs)"))
        if not study.steady_curves.empty:
            folder.write_csv("stribeck_fitted.csv", study.steady_curves, float_format="%.6g")
            folder.savefig("stribeck_fitted.png", plot_fitted_steady_curves(
                study.steady_curves, study.run_speeds,
                {name: m["F_measured_N"] for name, m in study.report["measurements"].items()},
                title))
        conditions = study.report["conditions"]
        if conditions:
            folder.write_csv("conditions.csv", pd.DataFrame(
                [{"condition": name, **{k: v for k, v in c.items()
                                        if k not in ("measurements", "roles")},
                  "measurements": "; ".join(c["measurements"])}
                 for name, c in conditions.items()]), float_format="%.6g")
            folder.savefig("repeatability.png", plot_repeats(
                conditions, study.report["measurements"], title))
        folder.write_text("case_resolved.toml", dump_case_toml(
            case, header=f"Resolved fit case of {path.name} (all defaults filled in); paths "
                         f"relative to {str(path.parent.resolve())}"))
    return {"status": result.status, "failure": result.failure, "warnings": result.warnings,
            "report": study.report, "evaluations": kept.counts()}


def run_rotary_fit_file(path: str | Path, out: str | Path, force: bool = False,
                        progress: Callable[[str, float, float], None] | None = None,
                        resume: bool = False) -> dict:
    """Fit rotary-case parameters to measured speed cycles and write the result folder ``out``.

    Parameters
    ----------
    path : path
        Rotary-fit case file (TOML), see :mod:`sealsim.calibration.rotary_case`.
    out : path
        Result folder (refused if it holds results, unless ``force``).
    force : bool
        Replace existing results.
    progress : callable, optional
        ``progress(stage, evaluations, max_evaluations)``.
    resume : bool
        Continue an interrupted fit: reuse the simulations it kept (:func:`keep_evaluations`).

    Returns
    -------
    dict
        ``{"status", "failure", "warnings", "report", "simulations", "evaluations"}``; status
        "failed" when a parameter ended at a bound or the optimiser stopped (results are still
        written, with the reasons); ``simulations``: those run by this call; ``evaluations``:
        how many parameter sets were ``computed`` and ``reused``.
    """
    path = Path(path)
    case = load_rotary_fit_case(path)
    base = path.parent
    inputs = [path] + [base / m.file for m in case.measurements]
    folder = ResultFolder(out, force, inputs=inputs)   # refused before anything is computed
    kept = KeptEvaluations(work_folder_for(out), resume=resume, discard=force,
                           source=str(path), files=file_digests(inputs))
    with keep_evaluations(kept), folder:
        study = rotary_fit_study(case, base, progress, kept)
        result, runs, measurements = study.result, study.runs, study.report["measurements"]
        fit_names = ", ".join(r.name for r in runs if r.role == "fit")
        fitted_text = (f"# Rotary parameters fitted by 'sealsim rotary fit "
                       f"{_comment(path.name)}' on {_comment(fit_names)}; status "
                       f"{result.status}.\n# Merge these tables into a rotary case (or put "
                       "them under [variants.fitted]).\n\n" + tomli_w.dumps(study.overlay))
        title = case.title or path.stem
        step_rows = study.step_rows()
        folder.write_text("fitted_parameters.toml", fitted_text)
        folder.write_json("report.json", study.report)
        folder.write_json("fit.json", study.diagnostics)
        folder.write_csv("predictions.csv", study.predictions_frame(), float_format="%.8g")
        folder.write_csv("steps.csv", pd.DataFrame(step_rows), float_format="%.8g")
        for r, slug in zip(runs, _unique_slugs([r.name for r in runs])):
            p = result.predictions[r.name]
            folder.write_csv(f"duty_{slug}.csv", pd.DataFrame(
                {"time_s": r.duty_times, "speed_rpm": r.duty_speeds * 30 / math.pi}),
                float_format="%.10g")
            measured = {"speed_rpm": r.speed * 30 / math.pi, "torque_Nm": r.torque}
            if r.has_temperature:
                measured["T_groove_C"] = r.temperature - ZERO_CELSIUS_K
            folder.savefig(f"overlay_{slug}.png", plot_rotary_overlay(
                r.name, r.role, r.time, measured, p.frame, measurements[r.name]["steps"],
                title))
        torque_points = [(s["step"], s["role"], s["torque_measured_Nm"],
                          s["torque_predicted_Nm"]) for s in step_rows if s["moving"]]
        if torque_points:
            folder.savefig("parity.png", plot_parity(
                torque_points, title, quantity="step-average torque", unit="N m",
                annotate=False))
        groove_points = [(s["step"], s["role"], s["T_groove_measured_C"],
                          s["T_groove_predicted_C"]) for s in step_rows
                         if "T_groove_measured_C" in s]
        if groove_points:
            folder.savefig("parity_temperature.png", plot_parity(
                groove_points, title, quantity="spring-groove temperature", unit="°C",
                absolute_band=TEMPERATURE_BAND, band_unit="K", annotate=False))
        folder.write_text("case_resolved.toml", dump_case_toml(
            case, header=f"Resolved rotary fit case of {path.name} (all defaults filled in); "
                         f"paths relative to {str(base.resolve())}"))
    return {"status": result.status, "failure": result.failure, "warnings": result.warnings,
            "report": study.report, "simulations": result.simulations,
            "evaluations": kept.counts()}


def run_pneumatic_compare_file(path: str | Path, out: str | Path, force: bool = False,
                               progress: Callable[[str, float, float], None] | None = None,
                               time_offset: float = 0.0) -> dict:
    """Simulate the case of a compare file, compare it with the measurement, write ``out``.

    Parameters
    ----------
    path : path
        Compare file (TOML), see :mod:`sealsim.calibration.pneumatic_compare`.
    out : path
        Result folder (refused if it holds results, unless ``force``).
    force : bool
        Replace existing results.
    progress : callable, optional
        ``progress(variant, simulated_time, end_time)``.
    time_offset : float
        The logger's time at the simulation's t = 0 [s], subtracted from the measured times.

    Returns
    -------
    dict
        The report written to ``report.json``.
    """
    folder = ResultFolder(out, force, inputs=compare_inputs(path))  # before computing
    comparison = compare_pneumatic_file(path, progress, time_offset)
    with folder:
        folder.write_json("report.json", comparison.report)
        folder.write_csv("comparison.csv", comparison.table, float_format="%.8g")
        folder.savefig("comparison.png", plot_signals(comparison.time, comparison.curves,
                                                      comparison.title))
    return comparison.report


@contextlib.contextmanager
def keep_evaluations(kept: KeptEvaluations) -> Iterator[None]:
    """While a fit computes (inside its result folder's lock), its finished evaluations are
    kept in the work folder ``.OUT.fit`` next to the result folder
    (:class:`~sealsim.calibration.kept.KeptEvaluations`): a fit interrupted by Ctrl-C, a
    killed process or a failure continues with the same command and ``--resume``.  The work
    folder is dropped once the results are committed, or if the fit kept nothing in it."""
    try:
        yield
    except BaseException:
        if kept.started:         # else it may be another run's (this one never held the lock)
            kept.remove_if_empty()
        raise
    kept.remove()


def _comment(text: str) -> str:
    """Text for a TOML comment line: control characters (a newline in a run name) escaped, so
    nothing a name holds can start a table of the file."""
    return "".join(repr(c)[1:-1] if not c.isprintable() else c for c in text)


def fit_case_inputs(case, path: Path) -> list[Path]:
    """The files a friction-fit case reads: itself, its measurements, its contact map file or
    structure case (refused inside the result folder, where committing would delete them)."""
    base = path.parent
    files = [path] + [base / m.file for m in case.measurements]
    for contact in (case.contact, *case.contacts.values()):
        spec = contact.map if contact is not None else None
        if spec is not None:
            files += [base / f for f in (spec.file, spec.structure_case) if f is not None]
    return files


def _unique_slugs(names: list[str]) -> list[str]:
    """File-name parts of run names (``cycle A, 0.2 L`` -> ``cycle_A_0.2_L``), unique ignoring
    case (a number appended: ``run 1`` and ``run_1`` become ``run_1`` and ``run_1_2``)."""
    out: list[str] = []
    for name in names:
        slug = re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_.") or "run"
        base, k = slug, 2
        while slug.lower() in (o.lower() for o in out):
            slug, k = f"{base}_{k}", k + 1
        out.append(slug)
    return out
