"""The summary numbers of a pneumatic run (``summary.json``) and how they are defined."""

from __future__ import annotations

from typing import Any

import numpy as np

from sealsim.pneumatic.controller import command_schedule

__all__ = ["DEFINITIONS", "END_TOLERANCE", "MIN_SLIDING_DISTANCE", "end_position_times",
           "per_stroke", "sliding_mean", "summarize"]

#: the end positions count as reached within this fraction of the stroke
END_TOLERANCE = 0.01
#: a mean friction needs at least this sliding distance [m]; less is the creep of a held piston
MIN_SLIDING_DISTANCE = 1e-6

#: how the summary numbers are defined (written into summary.json)
DEFINITIONS = {
    "extend_time_s": "mean over the extend commands of the time from the command to the "
                     f"piston reaching {100 * (1 - END_TOLERANCE):g} % of the stroke",
    "retract_time_s": "mean over the retract commands of the time from the command to the "
                      f"piston reaching {100 * END_TOLERANCE:g} % of the stroke",
    "mean_friction_N": "mean of |total friction of all seals| over the distance the piston "
                       "slid: friction work / sliding distance, integral |F|*|v| dt / integral "
                       "|v| dt (no speed threshold; None below "
                       f"{MIN_SLIDING_DISTANCE * 1e6:g} um of travel)",
    "peak_friction_N": "largest |total friction of all seals| over the run (at rest: the "
                       "part of the holding force the seals carry)",
    "air_consumption_NL": "free air delivered by the supply (ISO 6358 flow out of the supply "
                          "port, integrated), normal litres at the ISO 8778 reference "
                          "atmosphere (ANR: 20 degC, 100 kPa); air flowing back is not "
                          "subtracted",
    "air_returned_to_supply_NL": "air pushed back into the supply by a chamber above supply "
                                 "pressure (warmed or compressed air), normal litres (ANR)",
    "pressure_range_bar_abs": "lowest and highest absolute chamber pressure",
    "heat_balance_rel_error": "(seal heating) |friction heat - (heat stored in the seals, tube "
                              "and rod + heat into the chamber air + heat to the surroundings)| "
                              "/ friction heat",
    "mass_balance_rel_error": "|change of the air mass - (supply - exhaust)| / (mass "
                              "throughput, at least the initial air mass)",
    "energy_balance_rel_error": "|change of (air internal energy + kinetic energy) - "
                                "(enthalpy + wall heat + work of load, atmosphere and stops - "
                                "friction work)| / (energy throughput, at least the initial "
                                "internal energy of the air)",
}


def _end_reached(position, stroke, target):
    """(level [m], samples at or beyond it) of the end position ``target`` drives to."""
    level = stroke * (1.0 - END_TOLERANCE) if target == "extend" else stroke * END_TOLERANCE
    return level, (position >= level if target == "extend" else position <= level)


def sliding_mean(time, velocity, force):
    """Mean |F| over the distance slid: the friction work divided by the sliding distance,

        F̄ = ∫|F|·|v| dt / ∫|v| dt   (trapezoidal rule over the samples).

    Each sample counts with the distance slid around it, so a sample at the break-away, where
    the speed passes any threshold, changes the mean by its own tiny share of the travel, not by
    a whole sample's weight.

    Parameters
    ----------
    time : ndarray
        t [s].
    velocity : ndarray
        v [m/s].
    force : ndarray
        Friction force F [N].

    Returns
    -------
    float
        F̄ [N]; NaN if the piston slid less than :data:`MIN_SLIDING_DISTANCE`.

    Examples
    --------
    A stroke at constant speed with friction rising along it from 10 to 30 N; the rest at the
    end (v = 0, 50 N held) does not count:

    >>> t = np.linspace(0.0, 2.0, 201)
    >>> v = np.where(t <= 1.0, 0.1, 0.0)
    >>> f = np.where(t <= 1.0, 10.0 + 20.0 * t, 50.0)
    >>> round(sliding_mean(t, v, f), 2)
    20.05
    """
    speed = np.abs(np.asarray(velocity, dtype=float))
    distance = np.trapezoid(speed, time)
    if not distance >= MIN_SLIDING_DISTANCE:
        return float("nan")
    return float(np.trapezoid(np.abs(force) * speed, time) / distance)


def end_position_times(time, position, stroke, windows, target):
    """Times from each command to the end position it drives to.

    Parameters
    ----------
    time, position : ndarray
        Samples t [s], x [m].
    stroke : float
        L [m].
    windows : list of (start, end)
        Issue time of each command and the time of the next one [s].
    target : {"extend", "retract"}
        End position (x >= (1 − tol)·L, or x <= tol·L).

    Returns
    -------
    list of float
        One time [s] per command that started away from the end position and reached it
        before the next command.

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> x = np.clip(0.2 * t, 0.0, 0.1)
    >>> end_position_times(t, x, 0.1, [(0.0, 1.0)], "extend")
    [0.5]
    """
    level, reached = _end_reached(position, stroke, target)
    out = []
    for start, end in windows:
        inside = (time >= start) & (time < end)
        if not inside.any() or reached[np.argmax(inside)]:
            continue
        hits = np.flatnonzero(inside & reached)
        if hits.size:
            i = hits[0]   # linear interpolation of the crossing between samples i-1 and i
            t_hit = time[i] - (time[i] - time[i - 1]) * (position[i] - level) / (
                position[i] - position[i - 1])
            out.append(round(float(t_hit - start), 9))
    return out


def _samples_between(time, windows) -> list[slice]:
    """Per window (start, end) the samples with start <= t < end of the ascending times
    ``time``, as slices: binary searches of all windows at once instead of two comparisons of
    every sample per window.

    Examples
    --------
    >>> _samples_between(np.array([0.0, 0.5, 1.0, 1.5]), [(0.5, 1.5), (1.5, np.inf)])
    [slice(1, 3, None), slice(3, 4, None)]
    """
    if not windows:
        return []
    bounds = np.searchsorted(time, np.asarray(windows, dtype=float).ravel(), side="left")
    return [slice(int(a), int(b)) for a, b in bounds.reshape(-1, 2)]


def unfinished_strokes(time, position, case) -> list[str]:
    """Notes on the commands of a ``cycle`` case after which the piston did not reach its end
    position (within :data:`END_TOLERANCE` of the stroke) before the next command: a load or
    friction the supply pressure cannot overcome, or a command too short for the stroke.
    ``time`` ascending (the samples of a run).

    Examples
    --------
    A piston that creeps 30 mm in 1 s of a 100 mm stroke (an extend command from t = 0):

    >>> from types import SimpleNamespace
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> c = SimpleNamespace(cylinder=SimpleNamespace(stroke=0.1), controller=SimpleNamespace(
    ...     mode="cycle", steps=[SimpleNamespace(command="extend", duration=1.0)],
    ...     duration=1.0, initial_command="retract"))
    >>> print(unfinished_strokes(t, 0.03 * t, c)[0])
    1 of 1 extend commands did not reach the extended end: the piston got no further than 30 mm
    of the 100 mm stroke (the load and friction against the supply pressure, or a command too
    short); the extend time counts complete strokes only
    """
    if case.controller.mode != "cycle":
        return []
    schedule = command_schedule(case)
    stroke = case.cylinder.stroke
    out = []
    for target, sign, end_name in (("extend", 1.0, "extended"), ("retract", -1.0, "retracted")):
        windows = schedule.windows(sign)
        _, reached = _end_reached(position, stroke, target)
        missed = []
        for inside in _samples_between(time, windows):
            if inside.start < inside.stop and not reached[inside].any():
                x = position[inside]
                missed.append(float(x.max() if target == "extend" else x.min()))
        if missed:
            furthest = max(missed) if target == "extend" else min(missed)
            furthest = min(max(furthest, 0.0), stroke)     # in an end stop's bumper: its end
            out.append(f"{len(missed)} of {len(windows)} {target} commands did not reach the "
                       f"{end_name} end: the piston got no further than "
                       f"{furthest * 1e3:.3g} mm of the {stroke * 1e3:.4g} mm stroke (the load "
                       f"and friction against the supply pressure, or a command too short); "
                       f"the {target} time counts complete strokes only")
    return out


def stroke_times(time, position, case) -> dict[str, Any]:
    """Extend and retract times of a run of a ``cycle`` case (:data:`DEFINITIONS`): their
    means ``extend_time_s``, ``retract_time_s`` (None without a complete stroke) and the
    single strokes ``extend_times_s``, ``retract_times_s``."""
    schedule = command_schedule(case)
    stroke = case.cylinder.stroke
    ext = end_position_times(time, position, stroke, schedule.windows(1.0), "extend")
    ret = end_position_times(time, position, stroke, schedule.windows(-1.0), "retract")
    return {"extend_time_s": float(np.mean(ext)) if ext else None,
            "retract_time_s": float(np.mean(ret)) if ret else None,
            "extend_times_s": ext, "retract_times_s": ret}


def summarize(result) -> dict[str, Any]:
    """The numbers of ``summary.json`` for one variant (see :data:`DEFINITIONS`)."""
    frame = result.timeseries
    case = result.case
    t = frame["time_s"].to_numpy()
    x = frame["x_m"].to_numpy()
    v = frame["v_m_s"].to_numpy()
    friction = frame["F_friction_N"].to_numpy()
    summary: dict[str, Any] = {}
    if case.controller.mode == "cycle":
        summary.update(stroke_times(t, x, case))
    else:
        summary["extend_time_s"] = summary["retract_time_s"] = None
    summary["mean_friction_N"] = _none_if_nan(sliding_mean(t, v, friction))
    summary["peak_friction_N"] = float(np.max(np.abs(friction)))
    b = result.balances
    summary["air_consumption_NL"] = b["air_consumption_NL"]
    summary["air_returned_to_supply_NL"] = b["air_returned_to_supply_NL"]
    summary["mass_balance_rel_error"] = b["mass_balance_rel_error"]
    summary["energy_balance_rel_error"] = b["energy_balance_rel_error"]
    summary["friction_work_J"] = b["friction_work_J"]
    summary["peak_speed_m_s"] = float(np.max(np.abs(v)))
    summary["pressure_range_bar_abs"] = [
        float(min(frame["p1_bar_abs"].min(), frame["p2_bar_abs"].min())),
        float(max(frame["p1_bar_abs"].max(), frame["p2_bar_abs"].max()))]
    summary["air_temperature_range_C"] = [float(min(frame["T1_C"].min(), frame["T2_C"].min())),
                                          float(max(frame["T1_C"].max(), frame["T2_C"].max()))]
    seals = {}
    for name, col in zip(result.seal_names, result.seal_columns):
        f = frame[f"F_{col}_N"].to_numpy()
        entry = {"mean_friction_N": _none_if_nan(sliding_mean(t, v, f)),
                 "peak_friction_N": float(np.max(np.abs(f)))}
        if f"F_N_{col}_N" in frame:
            fn = frame[f"F_N_{col}_N"].to_numpy()
            entry["normal_force_range_N"] = [float(fn.min()), float(fn.max())]
            entry["contact_width_range_mm"] = [float(frame[f"b_{col}_mm"].min()),
                                               float(frame[f"b_{col}_mm"].max())]
        if f"theta_{col}" in frame:
            entry["theta_range"] = [float(frame[f"theta_{col}"].min()),
                                    float(frame[f"theta_{col}"].max())]
        if f"T_{col}_C" in frame:
            temperature = frame[f"T_{col}_C"].to_numpy()
            entry["temperature_range_C"] = [float(temperature.min()),
                                            float(temperature.max())]
            entry["temperature_end_C"] = float(temperature[-1])
        seals[name] = entry
    summary["seals"] = seals
    summary["balances"] = b
    summary["solver"] = {k: (round(v, 4) if isinstance(v, float) else v)
                         for k, v in result.stats.items()}
    summary["notes"] = list(result.notes)
    return summary


def _none_if_nan(value: float) -> float | None:
    return None if np.isnan(value) else value


def per_stroke(frame, stroke: float, seal_columns):
    """One row per valve command (stroke) of a cycle run: start time [s], direction (+1
    extend, −1 retract), the time to the end position [s] (:func:`end_position_times`; NaN if
    not reached), the mean |friction| over the distance slid [N] (:func:`sliding_mean`) and the
    seal temperatures at the end of the stroke [°C] (with seal heating) -- how a long duty
    cycle drifts.

    Examples
    --------
    >>> import pandas as pd
    >>> t = np.linspace(0.0, 2.0, 201)
    >>> x = np.clip(np.where(t < 1.0, 0.2 * t, 0.1 - 0.2 * (t - 1.0)), 0.0, 0.1)
    >>> f = pd.DataFrame({"time_s": t, "x_m": x, "v_m_s": np.gradient(x, t),
    ...                   "valve_command": np.where(t < 1.0, 1.0, -1.0),
    ...                   "F_friction_N": np.where(t < 1.0, 20.0, -18.0)})
    >>> per_stroke(f, 0.1, [])[["direction", "stroke_time_s", "mean_friction_N"]]
       direction  stroke_time_s  mean_friction_N
    0          1          0.495             20.0
    1         -1          0.495             18.0
    """
    import pandas as pd

    t = frame["time_s"].to_numpy()
    x = frame["x_m"].to_numpy()
    v = frame["v_m_s"].to_numpy()
    friction = frame["F_friction_N"].to_numpy()
    command = frame["valve_command"].to_numpy()
    starts = np.flatnonzero(np.r_[True, command[1:] != command[:-1]])
    rows = []
    for k, i in enumerate(starts):
        j = starts[k + 1] if k + 1 < len(starts) else len(t)
        direction = int(np.sign(command[i]))
        if direction == 0:
            continue
        window = [(float(t[i]), float(t[j]) if j < len(t) else np.inf)]
        times = end_position_times(t, x, stroke, window,
                                   "extend" if direction > 0 else "retract")
        sel = slice(i, j)
        row = {"start_s": float(t[i]), "direction": direction,
               "stroke_time_s": times[0] if times else np.nan,
               "mean_friction_N": sliding_mean(t[sel], v[sel], friction[sel])}
        for name in seal_columns:
            if f"T_{name}_C" in frame:
                row[f"T_{name}_C"] = float(frame[f"T_{name}_C"].iloc[j - 1])
        rows.append(row)
    return pd.DataFrame(rows)
