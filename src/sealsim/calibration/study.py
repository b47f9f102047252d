"""A friction-fit case from measurements to fitted parameters, report and predictions (what
``sealsim friction fit`` computes; :func:`sealsim.runs.calibration.run_friction_fit_file`
writes the result folder).

:func:`friction_fit_study` returns a :class:`FrictionFitStudy` with

* ``fitted`` -- a ``[friction]`` table with every parameter of the law (fitted ones replaced),
  readable by any friction or pneumatic case (``[friction]`` of a bench case,
  ``friction = {...}`` of a pneumatic seal);
* ``report`` -- ``{"parameters": {NAME: {...}}, "measurements": {NAME: {"role",
  "pressure_bar", "F_measured_N", "F_predicted_N", "rel_error", "rmse_N", "r2"}},
  "conditions": {CONDITION: {"measurements", "roles", ...}}}`` (``conditions``: the runs
  that repeat one test, :func:`repeat_conditions`);
* ``diagnostics`` -- status, reasons of a failed fit, stages, correlation matrix, warnings;
* ``predictions`` -- measured and model friction of every run (the frame and the plots
  show both offset-free, :func:`~sealsim.calibration.friction_fit.offset_free`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.calibration.case import FrictionFitCase, contact_table, repeated_conditions
from sealsim.calibration.friction_fit import (
    FitResult,
    PreparedRun,
    fit_friction,
    model_inputs,
    offset_free,
    predict_run,
    prepare_run,
    run_metrics,
    with_law_table,
)
from sealsim.calibration.kept import KeptEvaluations
from sealsim.calibration.statistics import parameter_report, repeat_scatter
from sealsim.cases import load_toml, validate_case
from sealsim.errors import InputError
from sealsim.friction import make_law
from sealsim.measurements import friction_level, stroke_levels

__all__ = ["FrictionFitStudy", "drift_warnings", "fit_run_warnings", "fitted_steady_curves",
           "friction_fit_study", "load_fit_case", "repeat_conditions",
           "speed_extrapolation_warnings"]

_LOADS = {"theta"}     # laws that need F_N and b from a contact map

#: Speeds of the fitted law's steady curve [m/s]: 0.1 mm/s to 1 m/s, about the range of
#: standard pneumatic cylinders (ISO 15552 catalogues rate them up to 1-1.5 m/s)
STEADY_CURVE_SPEEDS = np.logspace(-4.0, 0.0, 41)


def load_fit_case(path: str | Path) -> FrictionFitCase:
    """Read and validate a friction-fit case file (one InputError naming every field)."""
    path = Path(path)
    return validate_case(FrictionFitCase, load_toml(path), f"fit case {str(path)!r}")


def _contact_map(case: FrictionFitCase, base_dir: Path, cache_dir, progress, name=None):
    """The contact map of the case's ``[contact]`` (or of ``[contacts.NAME]``), or None."""
    contact = case.contact if name is None else case.contacts[name]
    return _seal_map(contact, contact_table(name), case.friction.law, base_dir, cache_dir,
                     progress)


def _seal_map(contact, where: str, law: str, base_dir: Path, cache_dir, progress):
    """The contact map of one ``[contact]`` (or ``[contacts.NAME]``) table, or None."""
    from sealsim.pneumatic.case import build_contact_map

    if contact is None or contact.map is None:
        if law in _LOADS:
            raise InputError(f"{where}.map: the {law} law needs F_N and b; give [{where}] "
                             "with map = {structure_case = 'seal.toml'}, {file = 'map.nc'} or "
                             "{analytic = {...}}")
        return None
    spec = contact.map
    if cache_dir is not None and spec.structure_case is not None and spec.cache_dir is None:
        spec = spec.model_copy(update={"cache_dir": str(cache_dir)})
    return build_contact_map(spec, contact.sliding_diameter, base_dir, f"{where}.map",
                             progress)


@dataclass
class FrictionFitStudy:
    """Everything a friction fit found (see the module docstring for the parts)."""

    case: FrictionFitCase
    runs: list[PreparedRun]
    result: FitResult
    predictions: dict[str, np.ndarray]
    report: dict
    diagnostics: dict
    fitted: dict
    steady_curves: pd.DataFrame      # :func:`fitted_steady_curves`
    run_speeds: pd.DataFrame

    def predictions_frame(self) -> pd.DataFrame:
        """Measured and model signals of every run, one row per sample (engineering units)."""
        return pd.concat([pd.DataFrame({
            "measurement": r.name, "role": r.spec.role, "time_s": r.time,
            "position_mm": r.position * 1e3, "velocity_mm_s": r.velocity * 1e3,
            "pressure_bar": r.pressure / 1e5 if r.pressure_known else np.nan,
            "normal_force_N": r.normal_force if r.normal_force is not None else np.nan,
            "friction_measured_N": r.friction, "friction_model_N": self.predictions[r.name]})
            for r in self.runs], ignore_index=True)

    def stroke_levels(self) -> dict[str, tuple[np.ndarray, np.ndarray]]:
        """Offset-free friction level per pair of strokes of every run, measured and model
        (:func:`~sealsim.measurements.stroke_levels`; their drifts are report.json's
        ``drift_measured_rel`` and ``drift_predicted_rel``)."""
        return {r.name: (stroke_levels(r.friction, r.phases)[1],
                         stroke_levels(self.predictions[r.name], r.phases)[1])
                for r in self.runs}


def friction_fit_study(case: FrictionFitCase, base_dir: str | Path,
                       progress: Callable[[str, float, float], None] | None = None,
                       cache_dir: str | Path | None = None,
                       kept: KeptEvaluations | None = None) -> FrictionFitStudy:
    """Fit a friction law to the measurements of a fit case and evaluate the fit.

    Parameters
    ----------
    case : FrictionFitCase
        Validated fit case (:func:`load_fit_case`).
    base_dir : path
        Folder the case's relative paths (measurements, contact map) start from.
    progress : callable, optional
        ``progress(task, done, total)``.
    cache_dir : path, optional
        Folder of the FE map cache (default: the map's own or sealsim's default cache).
    kept : KeptEvaluations, optional
        Where the fit keeps its finished evaluations (and finds those of an interrupted run
        of the same fit): started here, once the runs are prepared.

    Returns
    -------
    FrictionFitStudy
        ``result.status`` is "failed" when a parameter ended at a bound or the optimiser
        stopped (the other parts are still complete, with the reasons).
    """
    base = Path(base_dir)
    report_map = None if progress is None else lambda d, n: progress("FE map", d, n)
    maps = {None: None}
    for name in dict.fromkeys(m.contact for m in case.measurements):
        maps[name] = _contact_map(case, base, cache_dir, report_map, name)
    runs = [prepare_run(case, spec, maps[spec.contact], base) for spec in case.measurements]
    if kept is not None:
        kept.start("friction fit", case, [model_inputs(r) for r in runs])
    result = fit_friction(case, runs, progress, kept)
    law = make_law(result.params)
    # fitted roughness, film factor, ...: the friction table of the fitted values
    # offset-free as the measured signals are: the model's own offset is not in the data
    fitted_runs = with_law_table(law, runs)
    predictions = {r.name: offset_free(predict_run(law, r), r.phases) for r in fitted_runs}
    report = {"parameters": parameter_report(result, result.params.model_dump(mode="json")),
              "measurements": {r.name: run_metrics(r, predictions[r.name]) for r in runs}}
    # the starting parameters' prediction: how far the law is off before any fitting
    start = make_law(case.friction)
    for r in runs:
        level, _ = friction_level(predict_run(start, r), r.phases)
        report["measurements"][r.name]["F_predicted_without_fit_N"] = level
        report["measurements"][r.name]["ratio_without_fit"] = (level / r.level if r.level
                                                               else None)
    proportional_baseline(runs, report["measurements"])
    report["conditions"] = repeat_conditions(case, report["measurements"])
    steady_curves, run_speeds = fitted_steady_curves(law, fitted_runs)
    result.warnings.extend(fit_run_warnings(report["conditions"], report["measurements"]))
    result.warnings.extend(drift_warnings(report["measurements"]))
    result.warnings.extend(speed_extrapolation_warnings(steady_curves, run_speeds, law))
    diagnostics = {
        "status": result.status, "failure": result.failure, "warnings": result.warnings,
        "stages": result.stages, "parameter_names": result.names,
        "correlation": result.correlation.tolist(), "tied": dict(case.fit.tied),
        "contact_map": maps[None].describe() if maps[None] is not None else None,
        **({"contact_maps": {name: m.describe() for name, m in maps.items()
                             if name is not None and m is not None}} if case.contacts else {}),
        "offsets_N": {r.name: r.offset for r in runs},
        "sliding_phases": {r.name: len(r.phases) for r in runs}}
    fitted = {"friction": _drop_none(result.params.model_dump(
        mode="json", exclude={"parameter_set"}))}
    return FrictionFitStudy(case, runs, result, predictions, report, diagnostics, fitted,
                            steady_curves, run_speeds)


def fitted_steady_curves(law, runs: list[PreparedRun],
                         speeds=STEADY_CURVE_SPEEDS) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The fitted law's steady friction over speed at each seal and pressure the runs measured,
    and the speed each run was measured at: what the fit implies beyond the rig's speeds.

    For a Θ law on the seal's own contact (``steady = "contact"``; other laws give two empty
    frames): per contact and run pressure (rounded to 0.5 bar; the median Δp and the temperature
    of its runs) the steady friction F_ss(±u) of both stroke directions
    (:meth:`~sealsim.friction.theta.Theta.contact_steady`), its viscous part, and
    F_ss/F_N with the contact force F_N of the map at that pressure (the median over the
    runs' sliding samples).

    Parameters
    ----------
    law : FrictionLaw
        The fitted law.
    runs : list of PreparedRun
        The runs, with the friction tables of ``law``'s tribology
        (:func:`~sealsim.calibration.friction_fit.with_law_table`).
    speeds : array_like
        Sliding speeds [m/s], > 0.

    Returns
    -------
    curves : pandas.DataFrame
        ``contact, pressure_bar, temperature_C, speed_m_s, F_plus_N, F_minus_N,
        F_viscous_plus_N, F_viscous_minus_N, F_normal_N, mu_eff`` (μ_eff: the larger
        direction's |F_ss| / F_N).
    run_speeds : pandas.DataFrame
        ``measurement, contact, pressure_bar, speed_m_s`` (the run's median |v| while
        sliding).
    """
    from sealsim.friction import ContactInputs

    curve_columns = ["contact", "pressure_bar", "temperature_C", "speed_m_s", "F_plus_N",
                     "F_minus_N", "F_viscous_plus_N", "F_viscous_minus_N", "F_normal_N",
                     "mu_eff"]
    empty = (pd.DataFrame(columns=curve_columns),
             pd.DataFrame(columns=["measurement", "contact", "pressure_bar", "speed_m_s"]))
    runs = [r for r in runs if r.contact_table is not None and r.normal_force is not None]
    if not getattr(law, "contact", False) or not runs:
        return empty
    u = np.asarray(speeds, dtype=float)
    groups: dict[tuple, list[PreparedRun]] = {}
    speed_rows = []
    for r in runs:
        sliding = np.concatenate([np.arange(p.start, p.stop) for p in r.phases])
        contact = r.spec.contact or "contact"
        # to 0.5 bar: repeats of one test (the rig's 6.99-7.04 bar) share a curve
        bar = round(2.0 * float(np.median(r.pressure_difference[sliding])) / 1e5) / 2.0
        groups.setdefault((contact, bar), []).append((r, sliding))
        speed_rows.append({"measurement": r.name, "contact": contact, "pressure_bar": bar,
                           "speed_m_s": float(np.median(np.abs(r.velocity[sliding])))})
    rows = []
    for (contact, bar), members in groups.items():
        first = members[0][0]
        dp = float(np.median(np.concatenate([r.pressure_difference[s] for r, s in members])))
        normal = float(np.median(np.concatenate([r.normal_force[s] for r, s in members])))
        inputs = ContactInputs(pressure_difference=dp, temperature=first.temperature,
                               contact_table=first.contact_table,
                               sliding_diameter=first.sliding_diameter,
                               table_orientation=first.orientation)
        plus, _, viscous_plus = law.contact_steady(u, inputs)
        minus, _, viscous_minus = law.contact_steady(-u, inputs)
        mu = np.maximum(np.abs(plus), np.abs(minus)) / normal
        rows.append(pd.DataFrame({
            "contact": contact, "pressure_bar": bar,
            "temperature_C": first.temperature - 273.15, "speed_m_s": u,
            "F_plus_N": np.abs(plus), "F_minus_N": np.abs(minus),
            "F_viscous_plus_N": viscous_plus, "F_viscous_minus_N": viscous_minus,
            "F_normal_N": normal, "mu_eff": mu}))
    return pd.concat(rows, ignore_index=True)[curve_columns], pd.DataFrame(speed_rows)


def speed_extrapolation_warnings(curves: pd.DataFrame, run_speeds: pd.DataFrame, law,
                                 limit: float = 1.0) -> list[str]:
    """A warning when the fitted law's steady friction exceeds ``limit`` times the contact
    force at a speed up to 1 m/s (:func:`fitted_steady_curves`): a lubricated rubber seal's
    friction stays below its contact force (boundary friction coefficients of lubricated
    rubber 0.05-0.3, plus a viscous part; issue 23's criterion μ_eff < 1), so such a law
    holds only near the speeds it was fitted at.

    Examples
    --------
    >>> curves = pd.DataFrame({"contact": "ring", "pressure_bar": 1.0,
    ...                        "speed_m_s": [0.01, 0.1, 1.0], "mu_eff": [0.07, 0.4, 3.7]})
    >>> speeds = pd.DataFrame({"speed_m_s": [0.010, 0.014]})
    >>> print(speed_extrapolation_warnings(curves, speeds, None)[0][:80])
    the fitted law's steady friction exceeds the contact force (F/F_N up to 3.7 at 1
    """
    if curves.empty:
        return []
    over = curves[curves["mu_eff"] > limit]
    if over.empty:
        return []
    worst = curves.loc[curves["mu_eff"].idxmax()]
    first = float(over["speed_m_s"].min())
    from sealsim.pneumatic.case import excess_friction_cause

    measured = run_speeds["speed_m_s"]
    return [f"the fitted law's steady friction exceeds the contact force (F/F_N up to "
            f"{worst['mu_eff']:.2g} at {worst['speed_m_s']:.3g} m/s, {worst['contact']} at "
            f"{worst['pressure_bar']:g} bar; above {first:.2g} m/s) while the runs were measured "
            f"at {1e3 * measured.min():.3g}-{1e3 * measured.max():.3g} mm/s: "
            f"{excess_friction_cause(law)}. Use the fitted parameters only near the measured "
            "speeds (stribeck_fitted.png, stribeck_fitted.csv)"]


def proportional_baseline(runs: list[PreparedRun], measurements: dict) -> float | None:
    """The simplest contact model as a reference for the fitted law: friction proportional
    to the seal's normal force, F = μ̄·F_N (Amontons), with F_N from the same contact map and
    μ̄ = ΣF_measured/ΣF_N over the fit runs.

    Adds to each run's entry of ``measurements`` (report.json): ``F_normal_N`` (median
    contact force of the run, from the map at the measured pressure), ``mu_measured``
    (F_measured/F_N), ``F_proportional_N`` (μ̄·F_N) and ``proportional_rel_error``.  A
    law derived from the contact earns its detail where it predicts the held-out runs better
    than this line.  Runs without a normal force (no contact map) get nothing.

    Returns
    -------
    float or None
        μ̄ [-], or None without a contact map or without fit runs.
    """
    forces = {r.name: float(np.median(r.normal_force)) for r in runs
              if r.normal_force is not None and np.size(r.normal_force)}
    fit = [r for r in runs if r.name in forces and r.spec.role == "fit" and r.level]
    if not fit:
        return None
    mu = sum(r.level for r in fit) / sum(forces[r.name] for r in fit)
    for r in runs:
        if r.name not in forces or not forces[r.name]:
            continue
        entry = measurements[r.name]
        entry["F_normal_N"] = forces[r.name]
        entry["mu_measured"] = r.level / forces[r.name] if r.level else None
        entry["F_proportional_N"] = mu * forces[r.name]
        entry["proportional_rel_error"] = ((mu * forces[r.name] - r.level) / r.level
                                           if r.level else None)
    return mu


def repeat_conditions(case: FrictionFitCase, measurements: dict) -> dict:
    """The scatter of every repeated test of the case (measurements sharing a ``condition``)
    and the fitted law's error against it (:func:`~sealsim.calibration.statistics.
    repeat_scatter` of the runs' measured and predicted levels, report.json ``measurements``).

    Returns
    -------
    dict
        ``{CONDITION: {"measurements": [names], "roles": [fit/validate of each], ...the
        numbers of repeat_scatter}}`` in the order of the case.
    """
    table = {}
    for name, specs in repeated_conditions(case.measurements).items():
        entries = [measurements[m.name] for m in specs]
        table[name] = {"measurements": [m.name for m in specs],
                       "roles": [m.role for m in specs],
                       **repeat_scatter([e["F_measured_N"] for e in entries],
                                        [e["F_predicted_N"] for e in entries])}
    return table


def drift_warnings(measurements: dict, limit: float = 0.10) -> list[str]:
    """A warning naming the runs whose measured friction level changes over the run by more
    than ``limit`` (relative, first to last quarter of the stroke pairs, report.json
    ``drift_measured_rel``) and by more than ``limit`` more than the model's does: such a run
    is not at one steady level, and its median is what the model's steady level is compared
    with (on the TU Delft rig the X-ring's 7 bar run climbs by 18 %, its 1 and 3 bar runs
    stay within 0.3 %; docs/guide/calibration.md, "Time dependence").

    Examples
    --------
    >>> runs = {"7 bar": {"F_measured_first_N": 14.5, "F_measured_last_N": 17.1,
    ...                   "drift_measured_rel": 0.18, "drift_predicted_rel": 0.008},
    ...         "1 bar": {"F_measured_first_N": 4.56, "F_measured_last_N": 4.57,
    ...                   "drift_measured_rel": 0.003, "drift_predicted_rel": 0.0}}
    >>> print(drift_warnings(runs)[0][:81])
    1 measured run changes its friction level by more than 10 % from its first to its
    """
    drifting = []
    for name, m in measurements.items():
        measured, model = m.get("drift_measured_rel"), m.get("drift_predicted_rel")
        if measured is None or model is None or not np.isfinite(measured):
            continue
        if abs(measured) > limit and abs(measured - model) > limit:
            drifting.append(f"{name!r} {round(100 * measured):+d} % "
                            f"({m['F_measured_first_N']:.3g} → {m['F_measured_last_N']:.3g} N; "
                            f"model {round(100 * model):+d} %)")
    if not drifting:
        return []
    runs = ("run changes its", "its") if len(drifting) == 1 else ("runs change their", "their")
    return [f"{len(drifting)} measured {runs[0]} friction level by more than "
            f"{100 * limit:.0f} % from {runs[1]} first to {runs[1]} last strokes, the model's "
            f"steady contact does not: "
            f"{'; '.join(drifting)}. Not one steady level (grease wiped off, wear, heating or "
            "creep): the median over all strokes is what the model is compared with "
            "(report.json: drift_measured_rel)"]


def fit_run_warnings(conditions: dict, measurements: dict, limit: float = 1.0) -> list[str]:
    """Warnings for fit runs that lie far from the mean of their repeated test: a fit on one
    run of several inherits that run's deviation (on the TU Delft rig, one 1 bar run 1.7
    standard deviations above its test's mean stopped the three-ring fit at a bound; docs/
    guide/calibration.md, "Which run the fit sees").

    Parameters
    ----------
    conditions, measurements : dict
        report.json ``conditions`` (:func:`repeat_conditions`) and ``measurements``.
    limit : float
        Distance from the condition's mean, in standard deviations of a run, above which a fit
        run is reported (conditions of at least three runs: two runs give no mean to stand out
        from).

    Examples
    --------
    >>> runs = {n: {"F_measured_N": f} for n, f in [("a", 4.7), ("b", 4.8), ("c", 6.3),
    ...                                               ("d", 5.0), ("e", 4.3)]}
    >>> c = {"1 bar": {"measurements": list(runs), "roles": ["validate"] * 2 + ["fit"]
    ...                + ["validate"] * 2, "runs": 5, "F_measured_mean_N": 5.02,
    ...                "F_measured_std_N": 0.76}}
    >>> fit_run_warnings(c, runs)[0][:60]
    "fit run 'c' lies +1.7 standard deviations from the mean of i"
    """
    texts = []
    for name, c in conditions.items():
        std = c["F_measured_std_N"]
        if not std or c["runs"] < 3 or c["roles"].count("fit") in (0, c["runs"]):
            continue                      # no mean to stand out from, or the mean is fitted
        for run, role in zip(c["measurements"], c["roles"]):
            z = (measurements[run]["F_measured_N"] - c["F_measured_mean_N"]) / std
            if role == "fit" and abs(z) > limit:
                texts.append(f"fit run {run!r} lies {z:+.1f} standard deviations from the mean "
                             f"of its repeated test {name!r} ({c['runs']} runs, "
                             f"{c['F_measured_mean_N']:.3g} ± {std:.2g} N): the fitted "
                             "parameters carry that run's deviation; fit all runs of the test "
                             "(role = 'fit') to make them depend less on one run")
    return texts


def _drop_none(data: dict) -> dict:
    return {k: v for k, v in data.items() if v is not None}

