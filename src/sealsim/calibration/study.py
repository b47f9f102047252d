"""Run a friction-fit case file and write its result folder (what ``sealsim friction fit``
calls; usable from Python).

The folder holds

* ``fitted_parameters.toml`` -- a ``[friction]`` table with every parameter of the law (fitted
  ones replaced), readable by any friction or pneumatic case (``[friction]`` of a bench case,
  ``friction = {...}`` of a pneumatic seal);
* ``report.json`` -- ``{"parameters": {NAME: {...}}, "measurements": {NAME: {"role",
  "pressure_bar", "F_measured_N", "F_predicted_N", "rel_error", "rmse_N", "r2"}}}``;
* ``fit.json`` -- status, reasons of a failed fit, stages, correlation matrix, warnings;
* ``predictions.csv`` -- measured (offset-free) and model friction of every run;
* ``overlay_<run>.png`` per run, ``parity.png`` (±20 % band), ``case_resolved.toml``.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
import tomli_w

from sealsim.calibration.case import FrictionFitCase
from sealsim.calibration.friction_fit import (
    FitResult,
    fit_friction,
    predict_run,
    prepare_run,
    run_metrics,
)
from sealsim.cases import dump_case_toml, load_toml, validate_case
from sealsim.errors import InputError
from sealsim.friction import make_law
from sealsim.output import ResultFolder
from sealsim.plotting.calibration import plot_overlay, plot_parity

__all__ = ["load_fit_case", "run_friction_fit_file"]

_LOADS = {"theta"}     # laws that need F_N and b from a contact map


def load_fit_case(path: str | Path) -> FrictionFitCase:
    """Read and validate a friction-fit case file (one InputError naming every field)."""
    path = Path(path)
    return validate_case(FrictionFitCase, load_toml(path), f"fit case {str(path)!r}")


def _contact_map(case: FrictionFitCase, base_dir: Path, cache_dir, progress):
    from sealsim.pneumatic.case import build_contact_map

    if case.contact is None or case.contact.map is None:
        if case.friction.law in _LOADS:
            raise InputError(f"contact.map: the {case.friction.law} law needs F_N and b; give "
                             "[contact] with map = {structure_case = 'seal.toml'}, "
                             "{file = 'map.nc'} or {analytic = {...}}")
        return None
    spec = case.contact.map
    if cache_dir is not None and spec.structure_case is not None and spec.cache_dir is None:
        spec = spec.model_copy(update={"cache_dir": str(cache_dir)})
    return build_contact_map(spec, case.contact.sliding_diameter, base_dir, "contact.map",
                             progress)


def _parameter_table(result: FitResult) -> dict:
    dumped = result.params.model_dump(mode="json")
    table = {}
    for i, name in enumerate(result.names):
        value, se = float(result.values[i]), float(result.standard_errors[i])
        table[name] = {
            "value": value, "text": dumped[name], "stage": result.stage_of[i],
            "initial": result.initial[i], "bounds": list(result.bounds[i]),
            "standard_error": se if np.isfinite(se) else None,
            "relative_standard_error": (se / abs(value) if np.isfinite(se) and value
                                        else None),
            "identifiable": bool(result.identifiable[i]),
            "notes": result.reasons[i]}
    return table


def run_friction_fit_file(path: str | Path, out: str | Path, force: bool = False,
                          progress: Callable[[str, float, float], None] | None = None,
                          cache_dir: str | Path | None = None) -> dict:
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
        Folder of the FE map cache (default: the map's own or sealsim's default cache).

    Returns
    -------
    dict
        ``{"status", "failure", "warnings", "report"}``; status "failed" when a parameter ended
        at a bound or the optimiser stopped (results are still written, with the reasons).
    """
    path = Path(path)
    folder = ResultFolder(out, force)           # refuse an existing folder before computing
    case = load_fit_case(path)
    base = path.parent
    cmap = _contact_map(case, base, cache_dir,
                        None if progress is None else lambda d, n: progress("FE map", d, n))
    runs = [prepare_run(case, spec, cmap, base) for spec in case.measurements]
    result = fit_friction(case, runs, progress)
    law = make_law(result.params)
    predictions = {r.name: predict_run(law, r) for r in runs}
    report = {"parameters": _parameter_table(result),
              "measurements": {r.name: run_metrics(r, predictions[r.name]) for r in runs}}
    diagnostics = {
        "status": result.status, "failure": result.failure, "warnings": result.warnings,
        "stages": result.stages, "parameter_names": result.names,
        "correlation": result.correlation.tolist(), "tied": dict(case.fit.tied),
        "contact_map": cmap.describe() if cmap is not None else None,
        "offsets_N": {r.name: r.offset for r in runs},
        "sliding_phases": {r.name: len(r.phases) for r in runs}}
    frames = []
    for r in runs:
        frames.append(pd.DataFrame({
            "measurement": r.name, "role": r.spec.role, "time_s": r.time,
            "position_mm": r.position * 1e3, "velocity_mm_s": r.velocity * 1e3,
            "pressure_bar": r.pressure / 1e5,
            "normal_force_N": r.normal_force if r.normal_force is not None else np.nan,
            "friction_measured_N": r.friction, "friction_model_N": predictions[r.name]}))
    fitted_text = (f"# Friction parameters fitted by 'sealsim friction fit {path.name}'\n"
                   f"# on {', '.join(r.name for r in runs if r.spec.role == 'fit')}; "
                   f"status {result.status}.\n"
                   "# Use the [friction] table in a friction case, or as friction = {...} of a "
                   "pneumatic seal.\n\n"
                   + tomli_w.dumps({"friction": _drop_none(result.params.model_dump(
                       mode="json", exclude={"parameter_set"}))}))
    title = case.title or path.stem
    with folder:
        folder.write_text("fitted_parameters.toml", fitted_text)
        folder.write_json("report.json", report)
        folder.write_json("fit.json", diagnostics)
        folder.write_csv("predictions.csv", pd.concat(frames, ignore_index=True),
                         float_format="%.8g")
        for r in runs:
            folder.savefig(f"overlay_{_slug(r.name)}.png",
                           plot_overlay(r.name, r.spec.role, r.time, r.position, r.friction,
                                        predictions[r.name], title))
        points = [(name, m["role"], m["F_measured_N"], m["F_predicted_N"])
                  for name, m in report["measurements"].items()]
        folder.savefig("parity.png", plot_parity(points, title))
        folder.write_text("case_resolved.toml", dump_case_toml(
            case, header=f"Resolved fit case of {path.name} (all defaults filled in); paths "
                         f"relative to {str(base.resolve())}"))
    return {"status": result.status, "failure": result.failure, "warnings": result.warnings,
            "report": report}


def _drop_none(data: dict) -> dict:
    return {k: v for k, v in data.items() if v is not None}


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_") or "run"
