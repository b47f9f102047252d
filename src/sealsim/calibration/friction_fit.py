"""Identification of friction-law parameters from measured friction (staged, robust, bounded).

The model of a measured run: the seal slides with the measured velocity v(t) (from the position
by a Savitzky–Golay differentiator, :func:`sealsim.measurements.smooth_derivative`); its normal
force F_N(t) and contact width b(t) come from the contact map at the measured pressure
difference; the friction law is integrated along v(t) with its exact per-step update
(:meth:`sealsim.friction.FrictionLaw.trajectory`) and gives F(t).  Measured friction carries an
offset (load-cell zero, the area the pressure acts on); every comparison is offset-free: the
offset of the sliding phases (:func:`sealsim.measurements.friction_level`, the mean of the two
directions' medians) is removed from the measured signal, and the same offset of the model's
signal from the model's (:func:`offset_free`).  Removing the measured offset makes the two
directions' friction equal by construction, so a difference between them (a model slower in
one stroke, or with a steeper inlet flank) is not in the data: compared with the model's own
offset left in, it would be fitted as an error that no parameter should remove.

Fit (scipy.optimize.least_squares, trust-region reflective with bounds, robust loss):

1. *steady* parameters against the median friction of every sliding phase (the steady sweep),
   the model's steady force at the phase's velocities and loads;
2. *dynamic* parameters against the friction time series, steady parameters fixed.

Strictly positive parameters are fitted in log space (they span decades, e.g. stiffnesses);
their standard errors are mapped back by the delta method.  The uncertainty comes from the
Jacobian (:func:`sealsim.calibration.statistics.parameter_statistics`).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections import OrderedDict
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from scipy.optimize import least_squares

from sealsim.calibration.case import (
    FrictionFitCase,
    MeasurementModel,
    contact_of,
    contact_table,
    parse_law_value,
)
from sealsim.calibration.kept import KeptEvaluations
from sealsim.calibration.statistics import (
    compare_signals,
    constraint_failure,
    drop_constrained,
    parameter_statistics,
)
from sealsim.errors import InputError
from sealsim.friction import make_law
from sealsim.friction.base import ContactInputs, FrictionLaw, validate_parameters
from sealsim.measurements import (
    Measurement,
    friction_level,
    level_drift,
    position_velocity_ratio,
    read_measurement,
    sliding_phases,
    smooth_derivative,
    stroke_levels,
)
from sealsim.pneumatic.friction_tables import (
    LAW_TABLE_FIELDS,
    ContactTribology,
    build_friction_table,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["FitResult", "PreparedRun", "fit_friction", "friction_from_rod_force", "model_inputs",
           "offset_free", "predict_run", "prepare_run", "run_metrics", "with_law_table"]

#: friction tables of the tribology values a fit tried last, kept per contact map (in memory)
_FIT_TABLES = 16


@dataclass
class PreparedRun:
    """A measured run ready for the model: SI arrays at the samples."""

    spec: MeasurementModel
    measurement: Measurement
    time: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    friction: np.ndarray           # measured, offset removed
    offset: float
    level: float
    phases: list
    pressure: np.ndarray           # gauge pressure on the pressurised side [Pa]
    pressure_difference: np.ndarray
    temperature: float | None
    normal_force: np.ndarray | None = None
    contact_width: np.ndarray | None = None
    samples: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    contact_table: Any = None          # steady friction table from the seal's contact
    contact_map: Any = None            # the map the table was built from
    tribology: Any = None              # ... and its ContactTribology
    sliding_diameter: float | None = None
    orientation: float = 1.0
    pressure_known: bool = True    # False: no pressure given and none needed (zeros)

    @property
    def name(self) -> str:
        return self.spec.name


def _resolve(path: str, base_dir: Path) -> Path:
    p = Path(path)
    return p if p.is_absolute() else base_dir / p


def prepare_run(case: FrictionFitCase, spec: MeasurementModel, contact_map=None,
                base_dir: str | Path = ".") -> PreparedRun:
    """Read a measurement, derive v(t), find the sliding phases, evaluate F_N(t), b(t) and,
    for a Θ law on the seal's own contact, its friction table.

    Raises
    ------
    InputError
        Bad file (file/row/column named), no sliding phase, a condition the model needs that
        neither the file nor the case gives (pressure, temperature), a negative friction level
        (a reversed sign convention), a pressure outside the contact map's range.
    """
    path = _resolve(spec.file, Path(base_dir))
    where = f"measurement {spec.name!r} ({path})"
    options = {"bore": spec.bore} if spec.format == "tudelft" else None
    table = {} if spec.format else {"delimiter": spec.delimiter, "header": spec.header,
                                    "decimal": spec.decimal}
    if spec.skip_rows is not None:
        table["skip_rows"] = spec.skip_rows
    m = read_measurement(path, format=spec.format,
                         columns=spec.column_specs() if spec.columns else None,
                         options=options, name=spec.name, **table)
    computed = not m.has("friction")
    if computed:  # a rig that logs the rod force and the pressure on the piston
        m.data["friction"] = friction_from_rod_force(m.column("pressure"), m.column("force"),
                                                     spec.bore)
    t = m.time
    sig = case.signals
    try:
        if m.has("position"):
            x = m.column("position")
            v = m.column("velocity") if m.has("velocity") else smooth_derivative(
                t, x, window=sig.velocity_window)
        else:
            v = m.column("velocity")
            x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))])
        phases = sliding_phases(t, v, sig.sliding_threshold, sig.min_phase_duration, sig.settle)
        level, offset = friction_level(m.column("friction"), phases)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    if level < 0:
        flip = ("the position (or velocity) column" if computed else "the friction column")
        raise InputError(
            f"{where}: the measured friction level is {level:.4g} N, negative: the friction "
            "in the file probably counts the other way than sealsim (the force the seal "
            "resists the motion with, positive while the velocity is positive); flip it with "
            f"scale = -1 on {flip}")
    if m.has("position") and m.has("velocity"):
        # a column in another unit than declared (a time in ms given as s) moves the velocity
        # by its factor: the fit ran on it
        ratio = position_velocity_ratio(t, x, v, phases, sig.velocity_window)
        if not 0.5 <= ratio <= 2.0:
            raise InputError(
                f"{where}: the position changes {ratio:.4g} times as fast as the velocity "
                "column says (median over the sliding phases): check the units of the time, "
                "position and velocity columns (a time in ms given as s makes it 0.001)")
    needs = _needed_conditions(case, contact_map)
    if m.has("pressure"):
        p = m.column("pressure")
    elif spec.pressure is not None:
        p = np.full(t.shape, spec.pressure)
    elif "pressure" in needs:
        raise InputError(f"{where}: no pressure: {needs['pressure']} needs the pressure of "
                         "every run; give a pressure column or pressure = '2 bar' (gauge) in "
                         "this measurement")
    else:
        p = None
    contact = contact_of(case, spec)
    temperature = spec.temperature if spec.temperature is not None else (
        contact.temperature if contact is not None else None)
    if temperature is None and "temperature" in needs:
        raise InputError(f"{where}: no seal temperature: {needs['temperature']} needs it; give "
                         f"temperature = '20 degC' in this measurement or in "
                         f"[{contact_table(spec.contact)}]")
    known = p is not None
    p = p if known else np.zeros(t.shape)   # the law does not use it (see _needed_conditions)
    dp = np.abs(p)          # piston seal: pressurised side | ambient; rod seal: chamber | ambient
    run = PreparedRun(spec, m, t, x, v, m.column("friction") - offset, offset, level, phases,
                      p, dp, temperature, pressure_known=known)
    if contact_map is not None:
        lo, hi = contact_map.ranges["pressure"]
        tol = 0.02 * max(hi - lo, 1.0)
        if dp.max() > hi + tol or dp.min() < lo - tol:
            raise InputError(
                f"{where}: pressure difference {dp.min() / 1e5:.3g} … {dp.max() / 1e5:.3g} bar "
                f"exceeds the contact map's range {lo / 1e5:g} … {hi / 1e5:g} bar; extend the "
                "map's pressure grid (it is never extrapolated)")
        tlo, thi = contact_map.ranges["temperature"]
        if not tlo - 1e-6 <= temperature <= thi + 1e-6:
            c = ZERO_CELSIUS_K
            raise InputError(f"{where}: temperature {temperature - c:g} degC is outside "
                             f"the contact map ({tlo - c:g} … {thi - c:g} degC)")
        fn, b = contact_map.evaluate(np.clip(dp, lo, hi), temperature)
        run.normal_force = np.asarray(fn, dtype=float)
        run.contact_width = np.asarray(b, dtype=float)
        from sealsim.pneumatic.case import map_elastomer, seal_friction_table

        law = make_law(case.friction)
        run.contact_table = seal_friction_table(law, contact_map,
                                                f"{contact_table(spec.contact)}.map")
        if run.contact_table is not None:
            run.contact_map = contact_map
            run.tribology = ContactTribology.from_law(law, map_elastomer(contact_map))
            run.sliding_diameter = contact.sliding_diameter
            run.orientation = (1.0 if contact.positive_velocity == "away_from_pressure"
                               else -1.0)
    stride = max(1, int(math.ceil(t.size / case.fit.max_samples)))
    run.samples = np.arange(0, t.size, stride)
    return run


def friction_from_rod_force(pressure, rod_force, bore: float) -> np.ndarray:
    """Friction of a piston seal from the pressure on the piston and the rod force [N].

    .. math:: F_f = p\\,A - F_{rod}, \\qquad A = \\pi D^2/4

    The force balance of a piston that the gauge pressure p drives against the rod force
    F_rod (the force the rod passes on to the load cell), with the friction resisting the
    motion: positive while the piston moves the way the pressure pushes it.  If the rig counts
    position the other way, the friction level comes out negative: flip the position (or
    velocity) column with ``scale = -1``.

    Parameters
    ----------
    pressure : array_like
        Gauge pressure on the piston [Pa].
    rod_force : array_like
        Rod force [N].
    bore : float
        Bore diameter D [m].

    Examples
    --------
    >>> round(float(friction_from_rod_force(2e5, 90.0, 0.025)), 3)   # 98.175 N - 90 N
    8.175
    """
    area = math.pi * bore ** 2 / 4.0
    return np.asarray(pressure, dtype=float) * area - np.asarray(rod_force, dtype=float)


def with_law_table(law: FrictionLaw, runs: list[PreparedRun]) -> list[PreparedRun]:
    """The runs with the friction table of ``law``'s own tribology.

    A run's table from the seal's contact is built with the starting values of the fields
    :data:`~sealsim.pneumatic.friction_tables.LAW_TABLE_FIELDS` (roughness, film_factor,
    thickener_factor, asperity_wavelength, the base oil, ...).  A fit that varies one of them
    needs the table of every value it tries: it is built in memory from the run's contact map
    (0.05-0.5 s for one map; never written to the map cache) and the last few are kept, so the
    finite-difference steps and the final evaluation reuse them.  Runs whose table already
    matches, or that have none, are returned as they are.
    """
    out = []
    for run in runs:
        if run.contact_map is None or not getattr(law, "contact", False):
            out.append(run)
            continue
        tribology = ContactTribology.from_law(law, run.tribology.elastomer)
        if tribology == run.tribology:
            out.append(run)
            continue
        memo = run.contact_map.__dict__.setdefault("_fit_friction_tables", OrderedDict())
        table = memo.pop(tribology, None)
        if table is None:
            table = build_friction_table(run.contact_map, tribology)
        memo[tribology] = table
        while len(memo) > _FIT_TABLES:
            memo.popitem(last=False)
        out.append(dataclasses.replace(run, contact_table=table, tribology=tribology))
    return out


def model_inputs(run: PreparedRun) -> dict[str, Any]:
    """Everything the model of a run is computed from besides the law's parameters: the
    fingerprint of a kept fit (:class:`~sealsim.calibration.kept.KeptEvaluations`), and how
    it meets the measurement (``comparison``: a kept fit whose residuals compared the model with
    its offset left in is not resumed)."""
    return {"name": run.name, "role": run.spec.role, "comparison": "offset-free model",
            "time": run.time,
            "velocity": run.velocity, "friction": run.friction, "pressure": run.pressure,
            "pressure_difference": run.pressure_difference, "temperature": run.temperature,
            "normal_force": run.normal_force, "contact_width": run.contact_width,
            "samples": run.samples, "phases": [(p.start, p.stop) for p in run.phases],
            "contact_table": getattr(run.contact_table, "__dict__", run.contact_table),
            "contact_map": None if run.contact_map is None else run.contact_map.describe(),
            "sliding_diameter": run.sliding_diameter,
            "orientation": run.orientation}


def _needed_conditions(case: FrictionFitCase, contact_map) -> dict[str, str]:
    """The conditions the model of a fit uses, each with what uses it."""
    needs = {}
    if contact_map is not None:
        needs["pressure"] = needs["temperature"] = "the contact map (F_N and b)"
    fitted = {p.name for p in case.fit.parameters}
    if "pressure_coefficient" in type(case.friction).model_fields and (
            getattr(case.friction, "pressure_coefficient", None) or
            "pressure_coefficient" in fitted):
        needs.setdefault("pressure", f"the pressure scaling of the {case.friction.law} law")
    return needs


def _inputs(run: PreparedRun, index=slice(None), column=False) -> ContactInputs:
    def pick(a):
        if a is None:
            return None
        a = a[index]
        return a[:, None] if column else a
    return ContactInputs(normal_force=pick(run.normal_force),
                         contact_width=pick(run.contact_width),
                         pressure_a=pick(run.pressure), pressure_b=0.0,
                         temperature=run.temperature, contact_table=run.contact_table,
                         sliding_diameter=run.sliding_diameter,
                         pressure_difference=pick(run.pressure_difference),
                         table_orientation=run.orientation)


def predict_run(law: FrictionLaw, run: PreparedRun) -> np.ndarray:
    """Model friction F(t) [N] at the samples of a run (the law driven by the measured v(t),
    starting from rest)."""
    v = run.velocity
    n = v.size
    if law.n_states == 0:
        return law.force(np.zeros((0, n)), v, _inputs(run))
    mid = slice(1, None)
    v_mid = 0.5 * (v[1:] + v[:-1])
    dt = np.diff(run.time)
    # inputs at the end of each step (the per-step arrays of trajectory, shape (N, 1))
    z = law.trajectory(law.initial_state(1), v_mid, dt, _inputs(run, mid, column=True))
    states = z[:, :, 0].T                                      # (n_states, n samples)
    return law.force(states, v, _inputs(run))


def offset_free(force, phases) -> np.ndarray:
    """A friction signal [N] less its offset, the mean of its two directions' medians over the
    sliding phases (:func:`sealsim.measurements.friction_level`): what the measured signal of
    a run is compared as, so the model's is too.

    Examples
    --------
    A model 1 N stronger in the forward stroke than in the backward one: the data, whose
    offset was removed the same way, cannot tell that from an offset of 0.5 N.

    >>> from sealsim.measurements import SlidingPhase
    >>> ph = [SlidingPhase(0, 2, 1, 0, 1, 0.01), SlidingPhase(2, 4, -1, 1, 2, -0.01)]
    >>> offset_free([5.0, 5.0, -4.0, -4.0], ph).tolist()
    [4.5, 4.5, -4.5, -4.5]
    """
    f = np.asarray(force, dtype=float)
    return f - friction_level(f, phases)[1]


def steady_phase_forces(law: FrictionLaw, run: PreparedRun) -> np.ndarray:
    """Median steady friction of the model over each sliding phase, offset-free as the
    measurement is (:func:`offset_free`) [N]."""
    steady = np.zeros(run.velocity.size)
    for ph in run.phases:
        sel = slice(ph.start, ph.stop)
        steady[sel] = law.steady_force(run.velocity[sel], _inputs(run, sel))
    steady = offset_free(steady, run.phases)
    return np.array([float(np.median(steady[ph.start:ph.stop])) for ph in run.phases])


def measured_phase_forces(run: PreparedRun) -> np.ndarray:
    """Median measured (offset-free) friction over each sliding phase [N]."""
    return np.array([float(np.median(run.friction[p.start:p.stop])) for p in run.phases])


def run_metrics(run: PreparedRun, predicted: np.ndarray) -> dict[str, Any]:
    """The comparison numbers of one run (report.json ``measurements.NAME``).

    ``F_measured_N`` / ``F_predicted_N``: offset-free friction level of the sliding phases
    (half the difference of the medians in the two directions); ``rmse_N`` and ``r2`` over all
    samples of the offset-free friction time series, measured and model
    (:func:`offset_free`); ``F_measured_first_N`` / ``F_measured_last_N``: the mean level of
    the first and the last quarter of the stroke pairs, and ``drift_measured_rel`` /
    ``drift_predicted_rel`` the relative change between them, measured and model
    (:func:`~sealsim.measurements.stroke_levels`, :func:`~sealsim.measurements.level_drift`;
    None with fewer than two stroke pairs). A steady contact law drifts only as the run's
    pressure and speed do; a measured friction that climbs from stroke to stroke (grease wiped
    off, wear, heating, creep) is compared by its median with the model's steady level.
    """
    f_pred, _ = friction_level(predicted, run.phases)
    agreement = compare_signals(run.friction, offset_free(predicted, run.phases))
    pairs = stroke_levels(run.friction, run.phases)[1]
    drifts = pairs.size >= 2
    measured = level_drift(pairs)
    model = level_drift(stroke_levels(predicted, run.phases)[1])
    return {"role": run.spec.role,
            "pressure_bar": (float(np.median(run.pressure)) / 1e5 if run.pressure_known
                             else None),
            "F_measured_N": run.level, "F_predicted_N": f_pred,
            "rel_error": (f_pred - run.level) / run.level if run.level else None,
            "rmse_N": agreement["rmse"], "r2": agreement["r2"],
            "F_measured_first_N": measured[0] if drifts else None,
            "F_measured_last_N": measured[1] if drifts else None,
            "drift_measured_rel": measured[2] if drifts else None,
            "drift_predicted_rel": model[2] if drifts else None}


# -- the fit ------------------------------------------------------------------------------------
@dataclass
class FitResult:
    """Outcome of :func:`fit_friction`."""

    params: Any                        # the law's parameter model with the fitted values
    names: list[str]
    values: np.ndarray
    standard_errors: np.ndarray
    correlation: np.ndarray
    identifiable: np.ndarray
    reasons: list[list[str]]
    stages: list[dict]
    status: str                        # "ok" or "failed"
    failure: list[str]
    warnings: list[str]
    bounds: list[tuple[float, float]]
    initial: list[float]
    stage_of: list[str]
    limits: list[str | None]           # "lower bound", "upper bound", "constraint: WHY", None


def _make(params_model, values: dict[str, float]):
    data = {**params_model.model_dump(exclude={"parameter_set"}), **values}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        params = validate_parameters(type(params_model), data, "fitted parameters")
        return params, make_law(params)


def _refusal(params_model, values: dict[str, float]) -> str | None:
    """Why the law refuses these parameter values, or None if it takes them."""
    try:
        _make(params_model, values)
    except InputError as exc:
        return str(exc).removeprefix("invalid fitted parameters: ")
    return None


def _log_space(lo: float, hi: float) -> bool:
    return lo > 0 and hi > 0


def fit_friction(case: FrictionFitCase, runs: list[PreparedRun], progress=None,
                 kept: KeptEvaluations | None = None) -> FitResult:
    """Fit the case's parameters to the runs with role ``fit`` (see the module docstring).

    Deterministic: no random start, finite-difference Jacobians of fixed step.  With ``kept``
    (started), every evaluation of the residuals is kept in its work folder, and the ones it
    already holds (from an interrupted run of the same fit) are reused.
    """
    start = case.friction
    names, bounds, initial, stage_of = [], [], [], []
    start_notes: list[str] = []
    for k, p in enumerate(case.fit.parameters):
        where = f"fit.parameters[{k}] ({p.name!r})"
        lo = parse_law_value(start, p.name, p.bounds[0], f"{where}.bounds[0]")
        hi = parse_law_value(start, p.name, p.bounds[1], f"{where}.bounds[1]")
        if not lo < hi:
            raise InputError(f"{where}.bounds: lower bound {p.bounds[0]!r} must be below the "
                             f"upper bound {p.bounds[1]!r}")
        x0 = (parse_law_value(start, p.name, p.initial, f"{where}.initial")
              if p.initial is not None else getattr(start, p.name))
        if x0 is None:
            raise InputError(f"{where}: the law has no value for {p.name}; give initial")
        if not lo <= x0 <= hi:
            if p.initial is not None:
                raise InputError(f"{where}.initial: {p.initial!r} lies outside the bounds "
                                 f"[{p.bounds[0]!r}, {p.bounds[1]!r}]; give a start value "
                                 "inside them (or widen the bounds)")
            middle = math.sqrt(lo * hi) if _log_space(lo, hi) else 0.5 * (lo + hi)
            start_notes.append(f"{p.name}: the law's value {x0:.6g} (SI) lies outside the "
                               f"bounds {p.bounds}; the fit started from {middle:.6g} (SI); "
                               "give initial to choose the start")
            x0 = middle
        names.append(p.name)
        bounds.append((lo, hi))
        initial.append(float(x0))
        stage_of.append(p.stage)
    fit_runs = [r for r in runs if r.spec.role == "fit"]
    tied = case.fit.tied
    # a varied field the friction table is built with needs the table of each value it takes
    retable = bool(set(LAW_TABLE_FIELDS) & (set(names) | set(tied)))

    def with_ties(vals):
        return {**vals, **{target: vals[source] for target, source in tied.items()}}

    values = dict(zip(names, initial))
    refused = _refusal(start, with_ties(values))
    if refused:  # every trial law is refused alike (e.g. a Θ law's f_b above its f_a)
        shown = ", ".join(f"{k} = {v:.6g}" for k, v in with_ties(values).items())
        raise InputError(f"the fit would start from a law that is not valid ({shown}; SI): "
                         f"{refused}; give fit.parameters[].initial values that are")
    stages, notes = [], start_notes
    failure: list[str] = []
    limits: list[str | None] = [None] * len(names)   # bound or constraint a value sits on
    all_jac_rows = {}
    for stage in ("steady", "dynamic"):
        idx = [i for i, s in enumerate(stage_of) if s == stage]
        if not idx:
            continue
        logs = [_log_space(*bounds[i]) for i in idx]

        def to_x(vals, idx=idx, logs=logs):
            return np.array([math.log(vals[names[i]]) if lg else vals[names[i]]
                             for i, lg in zip(idx, logs)])

        def to_values(x, idx=idx, logs=logs):
            out = dict(values)
            for xi, i, lg in zip(x, idx, logs):
                out[names[i]] = float(math.exp(xi) if lg else xi)
            return out

        def residuals(x, stage=stage, to_values=to_values):
            trial = with_ties(to_values(x))
            try:
                _, law = _make(start, trial)
            except InputError:
                return np.full(n_res, 1e6)

            def compute():
                parts = []
                for r in (with_law_table(law, fit_runs) if retable else fit_runs):
                    if stage == "steady":
                        parts.append(measured_phase_forces(r) - steady_phase_forces(law, r))
                    else:
                        model = offset_free(predict_run(law, r), r.phases)
                        parts.append((r.friction - model)[r.samples])
                res = np.concatenate(parts)
                return np.where(np.isfinite(res), res, 1e6)

            if kept is None:
                return compute()
            return np.asarray(kept.evaluate({"stage": stage, "values": trial}, compute),
                              dtype=float)

        lo = np.array([math.log(bounds[i][0]) if lg else bounds[i][0]
                       for i, lg in zip(idx, logs)])
        hi = np.array([math.log(bounds[i][1]) if lg else bounds[i][1]
                       for i, lg in zip(idx, logs)])
        x0 = np.clip(to_x(values), lo, hi)
        n_res = 1                     # size of the penalty vector, set by the first evaluation
        n_res = residuals(x0).size
        if n_res < len(idx):
            raise InputError(f"stage {stage!r}: {n_res} data points cannot determine "
                             f"{len(idx)} parameters ({', '.join(names[i] for i in idx)})")
        if progress is not None:
            progress(stage, 0.0, 1.0)
        sol = least_squares(residuals, x0, bounds=(lo, hi), loss=case.fit.loss,
                            f_scale=case.fit.f_scale, max_nfev=case.fit.max_evaluations,
                            x_scale=1.0, diff_step=1e-6, method="trf")
        values = to_values(sol.x)
        # Jacobian of the plain residuals w.r.t. the parameters themselves (delta method)
        jac = sol.jac.copy() if case.fit.loss == "linear" else _plain_jacobian(residuals, sol.x)
        for col, (i, lg) in enumerate(zip(idx, logs)):
            if lg:
                jac[:, col] /= values[names[i]]
        all_jac_rows[stage] = (idx, jac, sol.fun if case.fit.loss == "linear"
                               else residuals(sol.x))
        for i, a, xi, l_, h_ in zip(idx, sol.active_mask, sol.x, lo, hi):
            if a != 0 or min(xi - l_, h_ - xi) <= 1e-6 * max(1.0, abs(h_ - l_)):
                limits[i] = ("lower bound" if a < 0 or (a == 0 and xi - l_ <= h_ - xi)
                             else "upper bound")
                failure.append(f"{names[i]} = {values[names[i]]:.6g} ended at a bound "
                               f"{bounds[i]}: the optimum lies outside the bounds or the data "
                               "do not determine it; widen the bounds or fix the parameter")
        if not sol.success:
            failure.append(f"stage {stage!r}: least_squares stopped: {sol.message}")
        stages.append({"stage": stage, "parameters": [names[i] for i in idx],
                       "n_residuals": int(n_res), "evaluations": int(sol.nfev),
                       "cost": float(sol.cost), "message": sol.message,
                       "values": {names[i]: values[names[i]] for i in idx}})
        if progress is not None:
            progress(stage, 1.0, 1.0)
    pinned = constraint_failure(values, names, limits,
                                lambda trial: _refusal(start, with_ties(trial)), "law")
    failure += [pinned] if pinned else []
    n = len(names)
    se = np.full(n, np.nan)
    corr = np.full((n, n), np.nan)
    identifiable = np.ones(n, dtype=bool)
    reasons: list[list[str]] = [[] for _ in range(n)]
    for stage, (idx, jac, res) in all_jac_rows.items():
        stats = parameter_statistics(jac, res, values=[values[names[i]] for i in idx],
                                     names=[names[i] for i in idx])
        for a, i in enumerate(idx):
            se[i] = stats["standard_errors"][a]
            identifiable[i] = stats["identifiable"][a]
            reasons[i] = stats["reasons"][a]
            for b, j in enumerate(idx):
                corr[i, j] = stats["correlation"][a, b]
    drop_constrained(limits, se, identifiable, reasons)
    for i, name in enumerate(names):
        if not identifiable[i]:
            notes.append(f"{name} is not identifiable from the fit data: {'; '.join(reasons[i])}")
    params, _ = _make(start, with_ties(values))
    return FitResult(params, names, np.array([values[k] for k in names]), se, corr,
                     identifiable, reasons, stages, "failed" if failure else "ok", failure,
                     notes, bounds, initial, stage_of, limits)


def _plain_jacobian(fun, x, step=1e-6):
    """Central-difference Jacobian of the residuals (without the robust loss weighting)."""
    f0 = fun(x)
    jac = np.empty((f0.size, x.size))
    for k in range(x.size):
        h = step * max(1.0, abs(x[k]))
        xp, xm = x.copy(), x.copy()
        xp[k] += h
        xm[k] -= h
        jac[:, k] = (fun(xp) - fun(xm)) / (2 * h)
    return jac
