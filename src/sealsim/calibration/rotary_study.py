"""A rotary-fit case from measured speed cycles to fitted parameters, report and predictions
(what ``sealsim rotary fit`` computes; :func:`sealsim.runs.calibration.run_rotary_fit_file`
writes the result folder).

:func:`rotary_fit_study` returns a :class:`RotaryFitStudy` with

* ``overlay`` -- the fitted fields as rotary-case tables (``[seal]``, ``[friction]``, ...):
  merge them into a rotary case or paste them as a ``[variants.NAME]`` table;
* ``report`` -- ``{"parameters": {PATH: {...}}, "measurements": {NAME: {"role",
  "conditions", "steps": [...], and the agreement of the step averages:
  "torque_rmse_Nm", "torque_r2", "torque_rel_error_mean", "torque_rel_error_max",
  "torque_within_20_percent", "T_groove_rmse_K", "T_groove_r2", "T_groove_error_max_K";
  "torque_timeseries_rmse_Nm"}}, "summary": {ROLE: {the same agreement over all its steps}}}``
  (standstill steps have no relative error and are not in the torque numbers);
* ``diagnostics`` -- status, reasons of a failed fit, stages, correlation matrix, warnings, the
  duty cycle built from each measured speed;
* :meth:`RotaryFitStudy.predictions_frame` (measured and model at every sample),
  :meth:`RotaryFitStudy.steps_frame` (step averages).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.calibration.kept import KeptEvaluations
from sealsim.calibration.rotary_case import RotaryFitCase, expand_dotted
from sealsim.calibration.rotary_fit import (
    PreparedRotaryRun,
    RotaryFitResult,
    fit_rotary,
    model_inputs,
    prepare_rotary_run,
    rotary_run_metrics,
    run_case_with,
    step_agreement,
)
from sealsim.calibration.statistics import parameter_report
from sealsim.cases import load_toml, validate_case
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["RotaryFitStudy", "fitted_overlay", "load_rotary_fit_case", "rotary_fit_study"]


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


def _overlay_texts(names: list[str], overlay: dict) -> dict[str, str]:
    """Each fitted field as written in the overlay (the case-file text of its value)."""
    texts = {}
    for name in names:
        node = overlay
        for part in name.split("."):
            node = node[part]
        texts[name] = node
    return texts


def _summary(measurements: dict) -> dict:
    """Agreement of all step averages of each role (the parity plots' numbers)."""
    return {role: step_agreement([s for m in measurements.values() if m["role"] == role
                                  for s in m["steps"]])
            for role in ("fit", "validate")
            if any(m["role"] == role for m in measurements.values())}


@dataclass
class RotaryFitStudy:
    """Everything a rotary fit found (see the module docstring for the parts)."""

    case: RotaryFitCase
    runs: list[PreparedRotaryRun]
    result: RotaryFitResult
    overlay: dict
    report: dict
    diagnostics: dict

    def predictions_frame(self) -> pd.DataFrame:
        """Measured and model signals of every run at the measured samples (time from the
        start of the measurement file, engineering units)."""
        frames = []
        for r in self.runs:
            p = self.result.predictions[r.name]
            model_at = {c: np.interp(r.time, p.frame["time_s"], p.frame[c])
                        for c in ("speed_rpm", "T_contact_C", "T_sump_C")}
            frames.append(pd.DataFrame({
                "measurement": r.name, "role": r.role, "time_s": r.time + r.time_offset,
                "speed_measured_rpm": r.speed * 30 / math.pi,
                "speed_model_rpm": model_at["speed_rpm"],
                "torque_measured_Nm": r.torque, "torque_model_Nm": p.torque,
                "T_groove_measured_C": (r.temperature - ZERO_CELSIUS_K if r.has_temperature
                                        else np.nan),
                "T_groove_model_C": p.temperature - ZERO_CELSIUS_K,
                "T_contact_model_C": model_at["T_contact_C"],
                "T_sump_model_C": model_at["T_sump_C"]}))
        return pd.concat(frames, ignore_index=True)

    def step_rows(self) -> list[dict]:
        """The step averages of every run, measured and predicted, one dict per step."""
        return [{"measurement": r.name, "role": r.role, **s}
                for r in self.runs for s in self.report["measurements"][r.name]["steps"]]


def rotary_fit_study(case: RotaryFitCase, base_dir: str | Path,
                     progress: Callable[[str, float, float], None] | None = None,
                     kept: KeptEvaluations | None = None) -> RotaryFitStudy:
    """Fit rotary-case parameters to the measured speed cycles of a fit case and evaluate it.

    Parameters
    ----------
    case : RotaryFitCase
        Validated rotary-fit case (:func:`load_rotary_fit_case`).
    base_dir : path
        Folder the case's relative paths (measurement files) start from.
    progress : callable, optional
        ``progress(stage, evaluations, max_evaluations)``.
    kept : KeptEvaluations, optional
        Where the fit keeps its finished evaluations (and finds those of an interrupted run
        of the same fit): started here, once the runs are prepared.

    Returns
    -------
    RotaryFitStudy
        ``result.status`` is "failed" when a parameter ended at a bound or the optimiser
        stopped (the other parts are still complete, with the reasons).
    """
    base = Path(base_dir)
    runs = [prepare_rotary_run(case, spec, base) for spec in case.measurements]
    if kept is not None:
        kept.start("rotary fit", case, [model_inputs(r) for r in runs])
    result = fit_rotary(case, runs, progress, kept)
    overlay = fitted_overlay(runs[0], result.value_dict)
    measurements = {r.name: rotary_run_metrics(r, result.predictions[r.name]) for r in runs}
    report = {"parameters": parameter_report(result, _overlay_texts(result.names, overlay)),
              "measurements": measurements,
              "summary": _summary(measurements)}
    diagnostics = {
        "status": result.status, "failure": result.failure, "warnings": result.warnings,
        "stages": result.stages, "strategy": case.fit.strategy,
        "parameter_names": result.names, "correlation": result.correlation.tolist(),
        "residual_variance": result.residual_variance,
        "uncertainties": {"torque_Nm": case.fit.torque_uncertainty,
                          "temperature_K": case.fit.temperature_uncertainty},
        "simulations": result.simulations,      # run by this call
        "evaluations_reused": 0 if kept is None else kept.reused,  # from an interrupted fit
        "numerics": runs[0].case.numerics.model_dump(mode="json"),
        "duty": {r.name: r.duty_deviation() for r in runs},
        "steps": {r.name: len(r.steps) for r in runs},
        "standstill_steps": {r.name: sum(not s["moving"] for s in measurements[r.name]["steps"])
                             for r in runs}}
    return RotaryFitStudy(case, runs, result, overlay, report, diagnostics)
