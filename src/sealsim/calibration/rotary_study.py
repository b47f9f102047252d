"""Run a rotary-fit case file and write its result folder (what ``sealsim rotary fit`` calls;
usable from Python).

The folder holds

* ``fitted_parameters.toml`` -- the fitted fields as rotary-case tables (``[seal]``,
  ``[friction]``, ...): merge them into a rotary case or paste them as a ``[variants.NAME]``
  table;
* ``report.json`` -- ``{"parameters": {PATH: {...}}, "measurements": {NAME: {"role",
  "conditions", "steps": [...], and the agreement of the step averages:
  "torque_rmse_Nm", "torque_r2", "torque_rel_error_mean", "torque_rel_error_max",
  "torque_within_20_percent", "T_groove_rmse_K", "T_groove_r2", "T_groove_error_max_K";
  "torque_timeseries_rmse_Nm"}}, "summary": {ROLE: {the same agreement over all its steps}}}``
  (standstill steps have no relative error and are not in the torque numbers);
* ``fit.json`` -- status, reasons of a failed fit, stages, correlation matrix, warnings, the
  duty cycle built from each measured speed;
* ``predictions.csv`` (measured and model at every sample), ``steps.csv`` (step averages),
  ``duty_<run>.csv`` (the duty cycle of each run, readable as ``duty.csv`` of a rotary case);
* ``overlay_<run>.png`` (speed | torque | groove temperature, like seed 000 Fig. 9),
  ``parity.png`` (step-average torque, ±20 % band, R², like Fig. 10),
  ``parity_temperature.png``, ``case_resolved.toml``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
import tomli_w

from sealsim.calibration.rotary_case import RotaryFitCase, expand_dotted
from sealsim.calibration.rotary_fit import (
    PreparedRotaryRun,
    RotaryFitResult,
    fit_rotary,
    prepare_rotary_run,
    rotary_run_metrics,
    run_case_with,
    step_agreement,
)
from sealsim.cases import dump_case_toml, load_toml, validate_case
from sealsim.output import ResultFolder
from sealsim.plotting.calibration import plot_parity, plot_rotary_overlay

__all__ = ["fitted_overlay", "load_rotary_fit_case", "run_rotary_fit_file"]

#: Half-width of the band of the temperature parity plot [K].
TEMPERATURE_BAND = 2.0


def load_rotary_fit_case(path: str | Path) -> RotaryFitCase:
    """Read and validate a rotary-fit case file (one InputError naming every field)."""
    path = Path(path)
    return validate_case(RotaryFitCase, load_toml(path), f"rotary fit case {str(path)!r}")


def fitted_overlay(run: PreparedRotaryRun, values: dict[str, float]) -> dict:
    """The fitted fields as rotary-case tables with units (``{"seal": {"radial_force":
    "32.1 N"}, ...}``), as the case model writes them."""
    dumped = run_case_with(run, values).model_dump(mode="json")
    flat = {}
    for path in values:
        node = dumped
        for part in path.split("."):
            node = node[part]
        flat[path] = node
    return expand_dotted(flat)


def _parameter_table(result: RotaryFitResult, overlay: dict) -> dict:
    table = {}
    for i, name in enumerate(result.names):
        value, se = float(result.values[i]), float(result.standard_errors[i])
        text = overlay
        for part in name.split("."):
            text = text[part]
        table[name] = {
            "value": value, "text": text, "stage": result.stage_of[i],
            "initial": result.initial[i], "bounds": list(result.bounds[i]),
            "standard_error": se if np.isfinite(se) else None,
            "relative_standard_error": (se / abs(value) if np.isfinite(se) and value
                                        else None),
            "identifiable": bool(result.identifiable[i]),
            "notes": result.reasons[i]}
    return table


def _summary(measurements: dict) -> dict:
    """Agreement of all step averages of each role (the parity plots' numbers)."""
    return {role: step_agreement([s for m in measurements.values() if m["role"] == role
                                  for s in m["steps"]])
            for role in ("fit", "validate")
            if any(m["role"] == role for m in measurements.values())}


def run_rotary_fit_file(path: str | Path, out: str | Path, force: bool = False,
                        progress: Callable[[str, float, float], None] | None = None) -> dict:
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

    Returns
    -------
    dict
        ``{"status", "failure", "warnings", "report", "simulations"}``; status "failed" when a
        parameter ended at a bound or the optimiser stopped (results are still written, with
        the reasons).
    """
    path = Path(path)
    case = load_rotary_fit_case(path)
    base = path.parent
    inputs = [path] + [base / m.file for m in case.measurements]
    folder = ResultFolder(out, force, inputs=inputs)   # refused before anything is computed
    runs = [prepare_rotary_run(case, spec, base) for spec in case.measurements]
    result = fit_rotary(case, runs, progress)
    values = result.value_dict
    overlay = fitted_overlay(runs[0], values)
    measurements = {r.name: rotary_run_metrics(r, result.predictions[r.name]) for r in runs}
    report = {"parameters": _parameter_table(result, overlay), "measurements": measurements,
              "summary": _summary(measurements)}
    diagnostics = {
        "status": result.status, "failure": result.failure, "warnings": result.warnings,
        "stages": result.stages, "strategy": case.fit.strategy,
        "parameter_names": result.names, "correlation": result.correlation.tolist(),
        "residual_variance": result.residual_variance,
        "uncertainties": {"torque_Nm": case.fit.torque_uncertainty,
                          "temperature_K": case.fit.temperature_uncertainty},
        "simulations": result.simulations,
        "numerics": runs[0].case.numerics.model_dump(mode="json"),
        "duty": {r.name: r.duty_deviation() for r in runs},
        "steps": {r.name: len(r.steps) for r in runs},
        "standstill_steps": {r.name: sum(not s["moving"] for s in measurements[r.name]["steps"])
                             for r in runs}}
    fit_names = ", ".join(r.name for r in runs if r.role == "fit")
    fitted_text = (f"# Rotary parameters fitted by 'sealsim rotary fit {path.name}' on "
                   f"{fit_names}; status {result.status}.\n"
                   "# Merge these tables into a rotary case (or put them under "
                   "[variants.fitted]).\n\n" + tomli_w.dumps(overlay))
    title = case.title or path.stem
    frames, step_rows = [], []
    for r in runs:
        p = result.predictions[r.name]
        model_at = {c: np.interp(r.time, p.frame["time_s"], p.frame[c])
                    for c in ("speed_rpm", "T_contact_C", "T_sump_C")}
        frames.append(pd.DataFrame({
            "measurement": r.name, "role": r.role, "time_s": r.time + r.time_offset,
            "speed_measured_rpm": r.speed * 30 / math.pi, "speed_model_rpm": model_at["speed_rpm"],
            "torque_measured_Nm": r.torque, "torque_model_Nm": p.torque,
            "T_groove_measured_C": (r.temperature - 273.15 if r.has_temperature else np.nan),
            "T_groove_model_C": p.temperature - 273.15,
            "T_contact_model_C": model_at["T_contact_C"], "T_sump_model_C": model_at["T_sump_C"]}))
        step_rows += [{"measurement": r.name, "role": r.role, **s}
                      for s in measurements[r.name]["steps"]]
    with folder:
        folder.write_text("fitted_parameters.toml", fitted_text)
        folder.write_json("report.json", report)
        folder.write_json("fit.json", diagnostics)
        folder.write_csv("predictions.csv", pd.concat(frames, ignore_index=True),
                         float_format="%.8g")
        folder.write_csv("steps.csv", pd.DataFrame(step_rows), float_format="%.8g")
        for r, slug in zip(runs, _slugs([r.name for r in runs])):
            p = result.predictions[r.name]
            folder.write_csv(f"duty_{slug}.csv", pd.DataFrame(
                {"time_s": r.duty_times, "speed_rpm": r.duty_speeds * 30 / math.pi}),
                float_format="%.10g")
            measured = {"speed_rpm": r.speed * 30 / math.pi, "torque_Nm": r.torque}
            if r.has_temperature:
                measured["T_groove_C"] = r.temperature - 273.15
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
            "report": report, "simulations": result.simulations}


def _slugs(names: list[str]) -> list[str]:
    """File-name parts of the run names, unique (``cycle A, 0.2 L`` -> ``cycle_A_0.2_L``)."""
    out: list[str] = []
    for name in names:
        slug = re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_.") or "run"
        base, k = slug, 2
        while slug.lower() in (o.lower() for o in out):
            slug, k = f"{base}_{k}", k + 1
        out.append(slug)
    return out
