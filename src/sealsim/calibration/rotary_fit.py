"""Identification of rotary lip seal parameters from measured speed cycles (rig measurements
as in Organisciak et al., SKF, AGMA 14FTM14, 2014: speed, friction torque and spring-groove
temperature over time).

The model of a measured run is the coupled transient simulation
(:func:`sealsim.rotary.simulation.simulate`) driven by the measured speed: the speed signal is
turned into a duty cycle of constant-speed plateaus joined by its raw samples
(:func:`duty_from_speed`).  Measured and model signals are compared as Organisciak et al.
compare rig and model: by the averages over the last 30 s of every speed step
(:func:`sealsim.measurements.step_averages`), computed for both with the same windows of the
measured speed.

Fit (scipy.optimize.least_squares, trust-region reflective with bounds, robust loss) of chosen
fields of the rotary case, residuals = (model − measured)/u for the step-average torque
(u = ``fit.torque_uncertainty``) and spring-groove temperature (``temperature_uncertainty``).
Strictly positive parameters are fitted in log space.  Jacobians are forward differences of
1 % (log space) or 1 % of the bound range: a much smaller step would resolve the model's
discrete parts (its conduction matrix is reused within 2 K bins of the sump temperature)
instead of its slope.  The uncertainty comes from the Jacobian of all parameters and all
residuals at the optimum (:func:`sealsim.calibration.statistics.parameter_statistics`), with
the residual variance floored at 1: the stated uncertainties also cover model errors that do
not scatter.
"""

from __future__ import annotations

import math
import tempfile
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import least_squares

from sealsim.calibration.kept import KeptEvaluations
from sealsim.calibration.rotary_case import (
    RotaryFitCase,
    RotaryMeasurementModel,
    expand_dotted,
    parse_case_value,
)
from sealsim.calibration.statistics import (
    compare_signals,
    constraint_failure,
    drop_constrained,
    parameter_statistics,
)
from sealsim.cases import apply_overrides, validate_case
from sealsim.errors import InputError, ModelError
from sealsim.measurements import ColumnSpec, read_measurement, step_averages
from sealsim.rotary.case import CASE_TEMPERATURES, MAX_DUTY_DURATION, RotaryCase
from sealsim.rotary.simulation import simulate
from sealsim.tribology.film import FilmRangeWarning
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["PreparedRotaryRun", "RotaryFitResult", "RotaryPrediction", "check_groove_temperature",
           "check_torque_sign", "duty_from_speed",
           "fit_rotary", "model_inputs", "predict_rotary_run", "prepare_rotary_run",
           "rotary_run_metrics", "step_agreement"]

#: Largest speed of a duty cycle [rad/s] (the duty CSV's limit, 47746 rpm).
MAX_SPEED = 5000.0
#: Longest measured run [s]: the rotary model's guard against unit slips (duty.max_duration).
MAX_DURATION = MAX_DUTY_DURATION
#: Relative finite-difference step of the Jacobians (see the module docstring).
DIFFERENCE_STEP = 0.01
#: Scaled residual given to a parameter set the model cannot run (keeps the optimiser away).
PENALTY = 1.0e3
#: Residual variance (in stated uncertainties²) above which the fit warns.
MAX_RESIDUAL_VARIANCE = 4.0


def duty_from_speed(time, speed, tolerance=0.02, min_samples=3, jump=10.0):
    """A duty cycle (break points of a piecewise-linear speed) from a measured speed signal.

    1. The signal is cut into steps like :func:`sealsim.measurements.step_averages` (a step
       ends where the speed leaves ``tolerance`` × the largest speed around its first value).
    2. A step of at least ``min_samples`` samples is a plateau at its median speed (the rig's
       set point without the noise), at 0 if that is within the tolerance (standstill: a
       creeping shaft would have the full boundary friction of the lip); its first and last
       samples further than half the tolerance from that median belong to the transitions.
       Neighbouring plateaus closer than half the tolerance are one plateau.
    3. Samples between plateaus are kept as they are (ramps), unless the transition lasts at
       most ``jump`` seconds: then it is a jump at its middle.  A short ramp heats the seal
       like a jump (the thermal response takes minutes), and a jump spares the simulation the
       small time steps it takes along a ramp.

    Parameters
    ----------
    time : array_like
        [s], strictly increasing, starting at 0.
    speed : array_like
        Angular speed [rad/s], >= 0 (negative noise within the tolerance is set to 0).
    tolerance : float
        Relative speed change that starts a new step.
    min_samples : int
        Fewest samples of a plateau.
    jump : float
        Longest transition between two plateaus that becomes a jump [s].

    Returns
    -------
    times, speeds : ndarray
        Break points [s] and speeds there [rad/s] (a jump is two points at one time).

    Raises
    ------
    InputError
        A speed below −tolerance × the largest speed, or above the model's largest speed
        (5000 rad/s).

    Examples
    --------
    >>> t = np.arange(0.0, 12.0)
    >>> n = np.array([0, 0.1, 0, 50, 100.4, 99.6, 100, 100, 100.2, 100, 100, 100])
    >>> times, speeds = duty_from_speed(t, n, jump=0.0)      # the ramp as measured
    >>> times.tolist(), speeds.tolist()
    ([0.0, 2.0, 3.0, 4.0, 11.0], [0.0, 0.0, 50.0, 100.0, 100.0])
    >>> times, speeds = duty_from_speed(t, n)                # ... or a jump in its middle
    >>> times.tolist(), speeds.tolist()
    ([0.0, 2.0, 3.0, 3.0, 11.0], [0.0, 0.0, 0.0, 100.0, 100.0])
    """
    t = np.asarray(time, dtype=float)
    w = np.asarray(speed, dtype=float)
    scale = float(np.max(np.abs(w))) if w.size else 0.0
    tol = tolerance * (scale if scale > 0 else 1.0)
    for bad, what in ((np.flatnonzero(w < -tol), "below 0"),
                      (np.flatnonzero(w > MAX_SPEED), f"above {MAX_SPEED * 30 / math.pi:.0f} rpm")):
        if bad.size:
            k = int(bad[0])
            raise InputError(
                f"measured speed {w[k] * 30 / math.pi:.4g} rpm at t = {t[k]:g} s (sample "
                f"{k + 1}) is {what}, outside the model's range 0 ... "
                f"{MAX_SPEED * 30 / math.pi:.0f} rpm (the model has no direction of rotation: "
                "give |speed|, e.g. scale = -1 on the column)")
    w = np.clip(w, 0.0, None)
    plateaus: list[list[int]] = []          # [first, last] sample of each plateau
    start = 0
    for k in range(1, w.size + 1):
        if k == w.size or abs(w[k] - w[start]) > tol:
            a, b = start, k - 1
            if k - start >= min_samples:
                level = np.median(w[start:k])
                while a < b and abs(w[a] - level) > tol / 2:
                    a += 1
                while b > a and abs(w[b] - level) > tol / 2:
                    b -= 1
                if plateaus and plateaus[-1][1] == a - 1 and abs(
                        np.median(w[plateaus[-1][0]:plateaus[-1][1] + 1]) - level) <= tol / 2:
                    plateaus[-1][1] = b
                elif b > a:
                    plateaus.append([a, b])
            start = k
    times: list[float] = []
    speeds: list[float] = []
    previous = -1                              # last sample already in the duty
    for a, b in plateaus:
        level = float(np.median(w[a:b + 1]))
        level = 0.0 if level <= tol else level
        if times and previous >= 0 and t[a] - t[previous] <= jump:
            middle = 0.5 * (t[previous] + t[a])
            times += [middle, middle, t[b]]
            speeds += [speeds[-1], level, level]
        else:
            times += [*t[previous + 1:a], t[a], t[b]]
            speeds += [*w[previous + 1:a], level, level]
        previous = b
    times += list(t[previous + 1:])
    speeds += list(w[previous + 1:])
    return np.array(times, dtype=float), np.array(speeds, dtype=float)


@dataclass
class PreparedRotaryRun:
    """A measured speed cycle ready for the model (SI arrays, time from 0)."""

    spec: RotaryMeasurementModel
    data: dict[str, Any]           # the rotary case data of this run (duty: its duty.csv)
    case: RotaryCase               # ... validated, at the start values
    time: np.ndarray               # [s] from the first sample
    time_offset: float             # time of the first sample in the file [s]
    speed: np.ndarray              # [rad/s]
    torque: np.ndarray             # [N m]
    temperature: np.ndarray | None  # spring groove [K]
    duty_times: np.ndarray
    duty_speeds: np.ndarray
    steps: list[dict]              # measured step averages
    window: float
    tolerance: float
    duty_dir: Path
    _tmp: Any = field(default=None, repr=False)

    @property
    def name(self) -> str:
        return self.spec.name

    @property
    def role(self) -> str:
        return self.spec.role

    @property
    def has_temperature(self) -> bool:
        return self.temperature is not None

    def measured(self, key: str) -> np.ndarray:
        return np.array([s[key] for s in self.steps])

    def duty_deviation(self) -> dict[str, float]:
        """How far the duty cycle is from the measured speed [rpm] in the averaging windows
        (where model and measurement are compared), and its number of break points."""
        inside = np.zeros(self.time.size, dtype=bool)
        for s in self.steps:
            inside |= (self.time >= s["t_end"] - self.window) & (self.time >= s["t_start"]) \
                & (self.time <= s["t_end"])
        dev = (np.interp(self.time, self.duty_times, self.duty_speeds) - self.speed)[inside]
        return {"window_rms_rpm": float(np.sqrt(np.mean(dev ** 2))) * 30 / math.pi,
                "window_max_rpm": float(np.max(np.abs(dev))) * 30 / math.pi,
                "break_points": int(self.duty_times.size)}


def _resolve(path: str, base_dir: Path) -> Path:
    p = Path(path)
    return p if p.is_absolute() else base_dir / p


def prepare_rotary_run(case: RotaryFitCase, spec: RotaryMeasurementModel,
                       base_dir: str | Path = ".") -> PreparedRotaryRun:
    """Read a measured speed cycle, build its duty cycle, find its complete steps.

    Raises
    ------
    InputError
        A bad file (file/row/column named), a speed outside the model's range, no complete
        step (none lasts the averaging window at constant speed).
    """
    path = _resolve(spec.file, Path(base_dir))
    where = f"measurement {spec.name!r} ({path})"
    m = read_measurement(path, columns=[ColumnSpec(q, c.column, c.unit, c.scale)
                                        for q, c in spec.columns.items()],
                         name=spec.name, delimiter=spec.delimiter, header=spec.header,
                         skip_rows=spec.skip_rows, decimal=spec.decimal)
    t_file = m.time
    t = t_file - t_file[0]
    speed = m.column("speed")
    torque = m.column("torque")
    temperature = m.column("temperature") if m.has("temperature") else None
    if temperature is not None:
        check_groove_temperature(t, temperature, where)
    avg = case.averaging
    if t[-1] > MAX_DURATION:
        raise InputError(f"{where}: the run lasts {t[-1]:.4g} s, more than the rotary model's "
                         f"guard of {MAX_DURATION:g} s (11.6 days); check the time column's "
                         "unit")
    try:
        times, speeds = duty_from_speed(t, speed, avg.tolerance, jump=avg.jump)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    signals = {"torque": torque, "speed": speed}
    if temperature is not None:
        signals["temperature"] = temperature
    steps = step_averages(t, speed, signals, avg.window, avg.tolerance)
    if not steps:
        raise InputError(f"{where}: no complete step found: the speed stays within "
                         f"{100 * avg.tolerance:g} % of its largest value "
                         f"({float(np.max(np.abs(speed))) * 30 / math.pi:.4g} rpm) for at least "
                         f"averaging.window = {avg.window:g} s nowhere in its "
                         f"{t[-1]:g} s; check the time and speed columns and their units")
    check_torque_sign(steps, avg.tolerance, where)
    tmp = tempfile.TemporaryDirectory(prefix="sealsim-duty-")
    duty_dir = Path(tmp.name)
    write_duty_csv(duty_dir / "duty.csv", times, speeds)
    try:
        run_case, data = case.run_case(spec, {"csv": "duty.csv"})
        run_case.duty_cycle().profile(duty_dir)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    return PreparedRotaryRun(spec, data, run_case, t, float(t_file[0]), speed, torque,
                             temperature, times, speeds, steps, avg.window, avg.tolerance,
                             duty_dir, tmp)


def check_groove_temperature(time, temperature, where: str) -> None:
    """Refuse a measured spring-groove temperature [K] outside the rotary case's temperatures
    (:data:`~sealsim.rotary.case.CASE_TEMPERATURES`): the model cannot follow it, and such a
    value is a column read in the wrong unit (degC numbers declared as K) more often than a
    measurement.

    Examples
    --------
    >>> check_groove_temperature([0.0, 2.0], [296.1, 22.9], "run A")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: run A: measured spring-groove temperature 22.9 K (-250.2 degC) ...
    """
    lo, hi = CASE_TEMPERATURES
    temperature = np.asarray(temperature, dtype=float)
    bad = np.flatnonzero(~((temperature > lo) & (temperature < hi)))
    if bad.size:
        k = int(bad[0])
        raise InputError(f"{where}: measured spring-groove temperature {temperature[k]:.6g} K "
                         f"({temperature[k] - ZERO_CELSIUS_K:.4g} degC) at t = {time[k]:g} s "
                         f"(sample {k + 1}) is outside the rotary model's "
                         f"{lo - ZERO_CELSIUS_K:.0f} ... {hi - ZERO_CELSIUS_K:.0f} degC; check "
                         "the temperature column's unit (degC or K)")


def check_torque_sign(steps: list[dict], tolerance: float, where: str) -> None:
    """Refuse a run whose step-average torque is negative on most steps at speed: the
    model's friction torque opposes the rotation (>= 0 for the |speed| it takes), so such a
    torque column has the other sign convention (a rig's reaction torque).

    Examples
    --------
    >>> steps = [{"speed": s, "torque": -0.4} for s in (0.0, 10.0, 50.0)]
    >>> check_torque_sign(steps, 0.02, "run A")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: run A: the measured torque is negative on 2 of 2 steps ...
    """
    fastest = max((s["speed"] for s in steps), default=0.0)
    moving = [s["torque"] for s in steps if s["speed"] > tolerance * fastest]
    if moving and float(np.median(moving)) < 0:
        negative = sum(t < 0 for t in moving)
        raise InputError(f"{where}: the measured torque is negative on {negative} of "
                         f"{len(moving)} steps at speed (median {np.median(moving):.4g} N m); "
                         "sealsim's friction torque opposes the rotation and is positive: if "
                         "the rig records it negative, set scale = -1 on the torque column")


def write_duty_csv(path: Path, times, speeds) -> None:
    """A duty-cycle CSV (time_s, speed_rpm) that :class:`sealsim.rotary.case.DutyCycle` reads;
    full precision, so equal plateau speeds stay equal."""
    rpm = np.asarray(speeds) * 30.0 / math.pi
    lines = ["time_s,speed_rpm"] + [f"{a!r},{b!r}" for a, b in zip(map(float, times),
                                                                     map(float, rpm))]
    path.write_text("\n".join(lines) + "\n")


# -- the model of a run -------------------------------------------------------------------------
@dataclass
class RotaryPrediction:
    """The model of one run at one parameter set, at the measured samples (an evaluation
    read back from a kept fit has only its steps and notes: the series are None)."""

    frame: pd.DataFrame | None     # the simulation's time series (time from the run start)
    torque: np.ndarray | None      # at the measured samples [N m]
    temperature: np.ndarray | None  # spring groove at the measured samples [K]
    steps: list[dict]              # step averages over the measured steps' windows
    notes: list[str]

    def step_values(self, key: str) -> np.ndarray:
        return np.array([s[key] for s in self.steps])


def model_inputs(run: PreparedRotaryRun) -> dict[str, Any]:
    """Everything the model of a run is computed from besides the fitted values: the
    fingerprint of a kept fit (:class:`~sealsim.calibration.kept.KeptEvaluations`)."""
    return {"name": run.name, "role": run.role, "data": run.data, "time": run.time,
            "speed": run.speed, "duty_times": run.duty_times, "duty_speeds": run.duty_speeds,
            "steps": run.steps, "window": run.window, "tolerance": run.tolerance}


def run_case_with(run: PreparedRotaryRun, values: dict[str, float]) -> RotaryCase:
    """The run's rotary case with fitted values (SI, by dotted path) set."""
    data = apply_overrides(run.data, expand_dotted(values))
    return validate_case(RotaryCase, data, f"measurement {run.name!r} with parameters "
                         f"{_show(values)}", require_units=False)


def predict_rotary_run(run: PreparedRotaryRun, values: dict[str, float]) -> RotaryPrediction:
    """Simulate a run with the given parameter values and sample it like the measurement.

    Raises
    ------
    ModelError
        The simulation failed (the message names the run, the parameters and where).
    InputError
        The values make an invalid case (e.g. mu_low above mu_peak).
    """
    case = run_case_with(run, values)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FilmRangeWarning)  # kept as a note of the result
            result = simulate(case, base_dir=run.duty_dir)
    except ModelError as exc:
        raise ModelError(f"measurement {run.name!r} with {_show(values)}: {exc}") from None
    frame = result.timeseries
    tm = frame["time_s"].to_numpy()
    torque = np.interp(run.time, tm, frame["torque_Nm"].to_numpy())
    groove = np.interp(run.time, tm, frame["T_groove_C"].to_numpy()) + ZERO_CELSIUS_K
    steps = step_averages(run.time, run.speed, {"torque": torque, "temperature": groove},
                          run.window, run.tolerance)
    return RotaryPrediction(frame, torque, groove, steps, list(result.notes))


def _show(values: dict[str, float]) -> str:
    return "{" + ", ".join(f"{k} = {v:.6g}" for k, v in values.items()) + "}"


def rotary_run_metrics(run: PreparedRotaryRun, prediction: RotaryPrediction) -> dict[str, Any]:
    """The comparison numbers of one run (report.json ``measurements.NAME``).

    Step table: per step the measured and model averages of torque and spring-groove
    temperature over the last ``window`` seconds, the relative torque error and the
    temperature error; ``moving`` is false at standstill (speed within the step tolerance of
    0), where the torque has no relative error.  Then :func:`step_agreement` of the table and
    the RMSE of the torque time series.
    """
    rows = []
    standstill = run.tolerance * float(np.max(np.abs(run.speed)))
    for k, (ms, ps) in enumerate(zip(run.steps, prediction.steps)):
        window = min(run.window, ms["t_end"] - ms["t_start"])
        moving = bool(ms["speed"] > standstill)
        row = {"step": k + 1, "t_start_s": ms["t_start"], "t_end_s": ms["t_end"],
               "t_mid_s": ms["t_end"] - window / 2, "speed_rpm": ms["speed"] * 30 / math.pi,
               "moving": moving,
               "torque_measured_Nm": ms["torque"], "torque_predicted_Nm": ps["torque"],
               "torque_rel_error": ((ps["torque"] - ms["torque"]) / ms["torque"]
                                    if moving and ms["torque"] != 0 else None)}
        if run.has_temperature:
            row.update({"T_groove_measured_C": ms["temperature"] - ZERO_CELSIUS_K,
                        "T_groove_predicted_C": ps["temperature"] - ZERO_CELSIUS_K,
                        "T_groove_error_K": ps["temperature"] - ms["temperature"]})
        rows.append(row)
    return {"role": run.role, "conditions": expand_dotted(run.spec.conditions), "steps": rows,
            **step_agreement(rows),
            "torque_timeseries_rmse_Nm": float(np.sqrt(np.mean((prediction.torque
                                                                 - run.torque) ** 2)))}


def step_agreement(rows: list[dict]) -> dict[str, Any]:
    """Agreement of step averages (rows of :func:`rotary_run_metrics`): RMSE and R² of the
    torque of the moving steps, mean and largest |relative torque error| and the share
    within ±20 % (Organisciak et al. 2014, Fig. 10), RMSE, R² and largest error of the groove
    temperature.

    Examples
    --------
    >>> rows = [{"moving": True, "torque_measured_Nm": m, "torque_predicted_Nm": p,
    ...          "torque_rel_error": (p - m) / m} for m, p in ((0.4, 0.42), (0.5, 0.45))]
    >>> a = step_agreement(rows)
    >>> [round(a[k], 4) for k in ("torque_rmse_Nm", "torque_rel_error_max", "torque_r2")]
    [0.0381, 0.1, 0.42]
    """
    moving = [r for r in rows if r["moving"]]
    out: dict[str, Any] = {"n_steps": len(rows), "n_moving_steps": len(moving)}
    out.update(_agreement([r["torque_measured_Nm"] for r in moving],
                          [r["torque_predicted_Nm"] for r in moving], "torque", "Nm"))
    rel = np.abs([r["torque_rel_error"] for r in moving if r["torque_rel_error"] is not None])
    out["torque_rel_error_mean"] = float(np.mean(rel)) if rel.size else None
    out["torque_rel_error_max"] = float(np.max(rel)) if rel.size else None
    out["torque_within_20_percent"] = float(np.mean(rel <= 0.2)) if rel.size else None
    hot = [r for r in rows if "T_groove_measured_C" in r]
    if hot:
        measured = [r["T_groove_measured_C"] for r in hot]
        predicted = [r["T_groove_predicted_C"] for r in hot]
        out.update(_agreement(measured, predicted, "T_groove", "K"))
        out["T_groove_error_max_K"] = float(np.max(np.abs(np.subtract(predicted, measured))))
    return out


def _agreement(measured, predicted, prefix: str, unit: str) -> dict[str, float | None]:
    if not np.size(measured):
        return {f"{prefix}_rmse_{unit}": None, f"{prefix}_r2": None}
    agreement = compare_signals(measured, predicted)
    return {f"{prefix}_rmse_{unit}": agreement["rmse"], f"{prefix}_r2": agreement["r2"]}


# -- the fit ------------------------------------------------------------------------------------
@dataclass
class RotaryFitResult:
    """Outcome of :func:`fit_rotary` (values SI, by dotted path)."""

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
    residual_variance: float           # Σr²/(m − n) of the scaled residuals (1: as stated)
    simulations: int
    predictions: dict[str, RotaryPrediction]
    limits: list[str | None]           # "lower bound", "upper bound", "constraint: WHY", None

    @property
    def value_dict(self) -> dict[str, float]:
        return dict(zip(self.names, map(float, self.values)))


class _Objective:
    """Residuals of the fit runs at parameter values (cached: least_squares asks twice; with
    ``kept``, every evaluation's step averages, notes or failure are also kept on disk, and
    those of an interrupted run of the same fit are reused)."""

    def __init__(self, case: RotaryFitCase, runs: list[PreparedRotaryRun],
                 kept: KeptEvaluations | None = None):
        self.runs = runs
        self.kept = kept
        self.sigma = {"torque": case.fit.torque_uncertainty,
                      "temperature": case.fit.temperature_uncertainty}
        self.cache: dict[tuple, dict[str, RotaryPrediction] | Exception] = {}
        self.simulations = 0
        self.failures: dict[str, list[str]] = {}   # stage: where the model failed

    def _simulate(self, values: dict[str, float]) -> dict[str, RotaryPrediction] | Exception:
        try:
            out = {}
            for run in self.runs:
                self.simulations += 1
                out[run.name] = predict_rotary_run(run, values)
            return out
        except (ModelError, InputError) as exc:
            return exc

    def _evaluate(self, values: dict[str, float]) -> dict[str, RotaryPrediction] | Exception:
        if self.kept is None:
            return self._simulate(values)
        simulated = []

        def record():
            found = self._simulate(values)
            simulated.append(found)
            if isinstance(found, Exception):
                return {"failed": {"error": type(found).__name__, "message": str(found)}}
            return {"runs": {name: {"steps": p.steps, "notes": p.notes}
                             for name, p in found.items()}}

        value = self.kept.evaluate({"values": values}, record)
        if simulated:
            return simulated[0]
        if "failed" in value:
            kind = InputError if value["failed"]["error"] == "InputError" else ModelError
            return kind(value["failed"]["message"])
        # kept: the step averages (all the fit uses), no time series (see full_predictions)
        return {name: RotaryPrediction(None, None, None, p["steps"], p["notes"])
                for name, p in value["runs"].items()}

    def predictions(self, values: dict[str, float]) -> dict[str, RotaryPrediction]:
        key = tuple(sorted(values.items()))
        if key not in self.cache:
            self.cache[key] = self._evaluate(values)
        found = self.cache[key]
        if isinstance(found, Exception):
            raise found
        return found

    def full_predictions(self, values: dict[str, float]) -> dict[str, RotaryPrediction]:
        """:meth:`predictions` with the time series (simulated again if they were kept)."""
        found = self.predictions(values)
        if all(p.frame is not None for p in found.values()):
            return found
        simulated = self._simulate(values)
        if isinstance(simulated, Exception):
            raise simulated
        return simulated

    def residuals(self, values: dict[str, float], kinds: tuple[str, ...]) -> np.ndarray:
        preds = self.predictions(values)
        parts = []
        for run in self.runs:
            for kind in kinds:
                if kind == "temperature" and not run.has_temperature:
                    continue
                parts.append((preds[run.name].step_values(kind) - run.measured(kind))
                             / self.sigma[kind])
        return np.concatenate(parts) if parts else np.zeros(0)


def _parameters(case: RotaryFitCase, start: RotaryCase):
    names, bounds, initial, stage_of = [], [], [], []
    for k, p in enumerate(case.fit.parameters):
        where = f"fit.parameters[{k}] ({p.path!r})"
        lo = parse_case_value(p.path, p.bounds[0], f"{where}.bounds[0]")
        hi = parse_case_value(p.path, p.bounds[1], f"{where}.bounds[1]")
        if not lo < hi:
            raise InputError(f"{where}.bounds: lower bound {p.bounds[0]!r} must be below the "
                             f"upper bound {p.bounds[1]!r}")
        if p.initial is not None:
            x0 = parse_case_value(p.path, p.initial, f"{where}.initial")
        else:
            x0 = _get(start, p.path)
            if x0 is None:
                raise InputError(f"{where}: the model has no value for {p.path} (its default "
                                 "is derived); give initial")
        if not lo <= x0 <= hi:
            raise InputError(f"{where}: the start value {x0:.6g} (SI units) lies outside the "
                             f"bounds {list(p.bounds)}; give initial or widen the bounds")
        names.append(p.path)
        bounds.append((lo, hi))
        initial.append(float(x0))
        stage_of.append(p.fit_stage)
    return names, bounds, initial, stage_of


def _get(model, path: str):
    for part in path.split("."):
        model = getattr(model, part)
    return model


def fit_rotary(case: RotaryFitCase, runs: list[PreparedRotaryRun],
               progress=None, kept: KeptEvaluations | None = None) -> RotaryFitResult:
    """Fit the case's parameters to the step averages of the runs with role ``fit`` and
    predict every run with the result (see the module docstring).

    Deterministic: no random start, finite-difference Jacobians of fixed steps.  With ``kept``
    (started), every evaluation of the fit runs is kept in its work folder, and the ones it
    already holds (from an interrupted run of the same fit) are reused.

    Raises
    ------
    ModelError
        The model fails at the start values (names the run, the parameters and where).
    InputError
        Bounds or start values that are not valid for their field; a stage without data.
    """
    fit_runs = [r for r in runs if r.role == "fit"]
    names, bounds, initial, stage_of = _parameters(case, fit_runs[0].case)
    logs = [lo > 0 for lo, _ in bounds]
    objective = _Objective(case, fit_runs, kept)
    values = dict(zip(names, initial))
    objective.predictions(values)            # the start must run: else say where it fails
    both = ("torque", "temperature")
    if case.fit.strategy == "joint":
        plan = [("joint", list(range(len(names))), both)]
    else:
        plan = [(s, [i for i, g in enumerate(stage_of) if g == s], (k,))
                for s, k in (("torque", "torque"), ("thermal", "temperature"))]
        plan = [p for p in plan if p[1]] + [("joint", list(range(len(names))), both)]
    stages, failure, notes = [], [], []
    last_jacobian: dict = {}
    for k, (stage, idx, kinds) in enumerate(plan):
        if not objective.residuals(values, kinds).size:
            raise InputError(f"stage {stage!r}: no fit run has a temperature column, so "
                             f"{', '.join(names[i] for i in idx)} cannot be fitted to "
                             "temperatures; add temperature columns or use strategy 'joint'")
        values, record, problems = _run_stage(objective, case, stage, idx, kinds, names,
                                              bounds, logs, values, progress, last_jacobian)
        stages.append(record)
        if k == len(plan) - 1:
            failure += problems
        else:  # an intermediate stage only gives the last one its start values
            notes += [f"{p} (the next stage starts from here)" for p in problems]
    # uncertainty: all parameters, all residuals (the last stage's) at the optimum; the
    # optimiser's last Jacobian is at the optimum unless the model failed there
    x = _to_x(values, names, logs)
    res = objective.residuals(values, both)
    if (last_jacobian.get("x") is not None and np.array_equal(last_jacobian["x"], x)
            and last_jacobian["jac"].shape == (res.size, len(names))):
        jac_x = last_jacobian["jac"]
    else:
        jac_x = _jacobian(lambda xx: objective.residuals(_to_values(xx, values, names, logs),
                                                         both), x, *_x_bounds(bounds, logs),
                          logs, f0=res)
    jac = jac_x.copy()
    for k, lg in enumerate(logs):
        if lg:
            jac[:, k] /= values[names[k]]
    raw_variance = float(res @ res) / max(res.size - len(names), 1)
    stats = parameter_statistics(jac, res, values=[values[n] for n in names], names=names,
                                 min_residual_variance=1.0)
    limits = [stages[-1]["at_bound"].get(name) for name in names]
    # within the Jacobians' step of a constraint, the optimiser cannot tell it from one on it
    pinned = constraint_failure(values, names, limits, lambda trial: _refusal(fit_runs, trial),
                                "rotary case", tolerance=DIFFERENCE_STEP)
    failure += [pinned] if pinned else []
    drop_constrained(limits, stats["standard_errors"], stats["identifiable"], stats["reasons"])
    for i, name in enumerate(names):
        if not stats["identifiable"][i]:
            notes.append(f"{name} is not identifiable from the fit data: "
                         f"{'; '.join(stats['reasons'][i])}")
    undetermined = [n for n, ok in zip(names, stats["identifiable"]) if not ok]
    if undetermined and failure:
        failure.append(f"the data do not determine {', '.join(undetermined)} (see the "
                       "warnings): fix one of them or add measurements that do, rather than "
                       "widening bounds or raising fit.max_evaluations")
    if raw_variance > MAX_RESIDUAL_VARIANCE:
        notes.append(f"the residuals are {math.sqrt(raw_variance):.2g} times the stated "
                     "uncertainties (rms): the model does not reproduce the fit data within "
                     "them (a model error, or uncertainties stated too small); the standard "
                     "errors are scaled up by this factor")
    for stage, where in objective.failures.items():   # one note per stage, not per trial
        more = f", and at {len(where) - 1} more parameter sets" if len(where) > 1 else ""
        notes.append(f"stage {stage!r}: the model failed at {where[0]}{more}; the optimiser "
                     "stepped back")
    predictions = dict(objective.full_predictions(values))
    for run in runs:
        if run.name not in predictions:
            predictions[run.name] = predict_rotary_run(run, values)
    for run in runs:
        notes += [f"{run.name}: {n}" for n in predictions[run.name].notes]
    return RotaryFitResult(names, np.array([values[n] for n in names]),
                           np.asarray(stats["standard_errors"], dtype=float),
                           np.asarray(stats["correlation"], dtype=float),
                           np.asarray(stats["identifiable"], dtype=bool), stats["reasons"],
                           stages, "failed" if failure else "ok", failure, notes, bounds,
                           initial, stage_of, raw_variance, objective.simulations, predictions,
                           limits)


def _refusal(runs: list[PreparedRotaryRun], values: dict[str, float]) -> str | None:
    """Why the rotary case refuses these values (for one of the runs), or None."""
    try:
        for run in runs:
            run_case_with(run, values)
    except InputError as exc:
        return str(exc)
    return None


def _to_x(values, names, logs, idx=None):
    idx = range(len(names)) if idx is None else idx
    return np.array([math.log(values[names[i]]) if logs[i] else values[names[i]] for i in idx])


def _to_values(x, values, names, logs, idx=None):
    idx = range(len(names)) if idx is None else idx
    out = dict(values)
    for xi, i in zip(x, idx):
        out[names[i]] = float(math.exp(xi) if logs[i] else xi)
    return out


def _x_bounds(bounds, logs, idx=None):
    idx = range(len(bounds)) if idx is None else idx
    lo = np.array([math.log(bounds[i][0]) if logs[i] else bounds[i][0] for i in idx])
    hi = np.array([math.log(bounds[i][1]) if logs[i] else bounds[i][1] for i in idx])
    return lo, hi


def _steps(lo, hi, logs):
    return np.array([DIFFERENCE_STEP if lg else DIFFERENCE_STEP * (h - l)
                     for lg, l, h in zip(logs, lo, hi)])


def _jacobian(fun, x, lo, hi, logs, f0):
    """Forward-difference Jacobian in x space (``logs``: which entries are logarithms),
    backward where the upper bound is within a step."""
    h = _steps(lo, hi, logs)
    jac = np.empty((f0.size, x.size))
    for k in range(x.size):
        step = x.copy()
        step[k] = min(x[k] + h[k], hi[k])
        if step[k] <= x[k]:
            step[k] = max(x[k] - h[k], lo[k])
        jac[:, k] = (fun(step) - f0) / (step[k] - x[k])
    return jac


def _run_stage(objective: _Objective, case: RotaryFitCase, stage, idx, kinds, names, bounds,
               logs, values, progress, last_jacobian):
    lo, hi = _x_bounds(bounds, logs, idx)
    logs_sel = [logs[i] for i in idx]
    x0 = np.clip(_to_x(values, names, logs, idx), lo, hi)
    n_res = objective.residuals(values, kinds).size
    if n_res < len(idx):
        raise InputError(f"stage {stage!r}: {n_res} step averages cannot determine "
                         f"{len(idx)} parameters ({', '.join(names[i] for i in idx)}); "
                         "measure more speed steps")
    count = {"n": 0}

    def residuals(x, counted=True):
        trial = _to_values(x, values, names, logs, idx)
        if counted and progress is not None:
            count["n"] += 1
            progress(stage, min(count["n"], case.fit.max_evaluations), case.fit.max_evaluations)
        try:
            return objective.residuals(trial, kinds)
        except (ModelError, InputError) as exc:
            where = objective.failures.setdefault(stage, [])
            if f"{_show(trial)} ({exc})" not in where:
                where.append(f"{_show(trial)} ({exc})")
            return np.full(n_res, PENALTY)

    def jacobian(x):
        jac = _jacobian(residuals, x, lo, hi, logs_sel, f0=residuals(x, counted=False))
        last_jacobian.update(x=_to_x(_to_values(x, values, names, logs, idx), names, logs),
                             jac=jac)
        return jac

    sol = least_squares(residuals, x0, jac=jacobian, bounds=(lo, hi), loss=case.fit.loss,
                        f_scale=case.fit.f_scale, max_nfev=case.fit.max_evaluations,
                        x_scale=1.0, method="trf", xtol=1e-4, ftol=1e-6, gtol=1e-8)
    values = _to_values(sol.x, values, names, logs, idx)
    failure = []
    at_bound = {}
    for j, i in enumerate(idx):
        near = min(sol.x[j] - lo[j], hi[j] - sol.x[j]) <= 1e-3 * (hi[j] - lo[j])
        if sol.active_mask[j] != 0 or near:
            lower = sol.active_mask[j] < 0 or (sol.active_mask[j] == 0
                                               and sol.x[j] - lo[j] <= hi[j] - sol.x[j])
            at_bound[names[i]] = "lower bound" if lower else "upper bound"
            failure.append(f"{names[i]} = {values[names[i]]:.6g} (SI) ended at a bound "
                           f"{list(case.fit.parameters[i].bounds)} in stage {stage!r}: the "
                           "optimum lies outside the bounds or the data do not determine it; "
                           "widen the bounds or fix the parameter")
    if sol.status == 0:
        failure.append(f"stage {stage!r}: least_squares stopped after {sol.nfev} evaluations "
                       f"without converging ({sol.message}); raise fit.max_evaluations")
    elif not sol.success:
        failure.append(f"stage {stage!r}: least_squares failed: {sol.message}")
    record = {"stage": stage, "parameters": [names[i] for i in idx], "residuals": list(kinds),
              "n_residuals": int(n_res), "evaluations": int(sol.nfev),
              "jacobians": int(sol.njev or 0), "cost": float(sol.cost),
              "message": sol.message,
              "values": {names[i]: values[names[i]] for i in idx}, "at_bound": at_bound}
    return values, record, failure
