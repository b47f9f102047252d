"""Run a pneumatic case file with all its variants and write the results folder.

``run_case_file`` is what ``sealsim pneumatic run`` calls; it can be used from Python as well.
The folder gets ``timeseries.csv`` (all variants, long format with a ``variant`` column),
``summary.json`` (``{"variants": {NAME: {...}}}``), ``case_resolved.toml`` and the figures
(``pressure_stroke.png`` like seed 001 Fig. 10, ``friction_stroke.png`` like Figs. 12/13,
``friction_velocity.png``, ``timeseries_<variant>.png``).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from sealsim import __version__
from sealsim.cases import dump_variants_toml
from sealsim.output import ResultFolder, run_variants
from sealsim.pneumatic.case import PneumaticCase, build_seals, load_pneumatic_case_file
from sealsim.pneumatic.simulation import TIMESERIES_COLUMNS, PneumaticResult, simulate

__all__ = ["DEFINITIONS", "end_position_times", "run_case_file", "run_cases", "summarize",
           "write_results"]

#: the end positions count as reached within this fraction of the stroke
END_TOLERANCE = 0.01
#: the piston counts as moving above this speed [m/s] (for the mean friction)
MOVING_SPEED = 1e-3

#: how the summary numbers are defined (written into summary.json)
DEFINITIONS = {
    "extend_time_s": "mean over the extend commands of the time from the command to the "
                     f"piston reaching {100 * (1 - END_TOLERANCE):g} % of the stroke",
    "retract_time_s": "mean over the retract commands of the time from the command to the "
                      f"piston reaching {100 * END_TOLERANCE:g} % of the stroke",
    "mean_friction_N": "mean of |total friction of all seals| while the piston moves "
                       f"(|v| > {MOVING_SPEED * 1e3:g} mm/s)",
    "peak_friction_N": "largest |total friction of all seals| over the run (at rest: the "
                       "part of the holding force the seals carry)",
    "air_consumption_NL": "air taken from the supply, normal litres at the ISO 8778 reference "
                          "atmosphere (ANR: 20 degC, 100 kPa)",
    "mass_balance_rel_error": "|change of the air mass - (supply - exhaust)| / mass "
                              "throughput",
    "energy_balance_rel_error": "|change of (air internal energy + kinetic energy) - "
                                "(enthalpy + wall heat + work of load, atmosphere and stops - "
                                "friction work)| / energy throughput",
}


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
    level = stroke * (1.0 - END_TOLERANCE) if target == "extend" else stroke * END_TOLERANCE
    reached = position >= level if target == "extend" else position <= level
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


def summarize(result: PneumaticResult) -> dict[str, Any]:
    """The numbers of ``summary.json`` for one variant (see :data:`DEFINITIONS`)."""
    frame = result.timeseries
    case = result.case
    t = frame["time_s"].to_numpy()
    x = frame["x_m"].to_numpy()
    v = frame["v_m_s"].to_numpy()
    friction = frame["F_friction_N"].to_numpy()
    moving = np.abs(v) > MOVING_SPEED
    summary: dict[str, Any] = {}
    if case.controller.mode == "cycle":
        from sealsim.pneumatic.simulation import PneumaticSystem

        schedule = PneumaticSystem.schedule_of(case)
        ext = end_position_times(t, x, case.cylinder.stroke, schedule.windows(1.0), "extend")
        ret = end_position_times(t, x, case.cylinder.stroke, schedule.windows(-1.0), "retract")
        summary["extend_time_s"] = float(np.mean(ext)) if ext else None
        summary["retract_time_s"] = float(np.mean(ret)) if ret else None
        summary["extend_times_s"] = ext
        summary["retract_times_s"] = ret
    else:
        summary["extend_time_s"] = summary["retract_time_s"] = None
    summary["mean_friction_N"] = float(np.mean(np.abs(friction[moving]))) if moving.any() \
        else None
    summary["peak_friction_N"] = float(np.max(np.abs(friction)))
    b = result.balances
    summary["air_consumption_NL"] = b["air_consumption_NL"]
    summary["mass_balance_rel_error"] = b["mass_balance_rel_error"]
    summary["energy_balance_rel_error"] = b["energy_balance_rel_error"]
    summary["friction_work_J"] = b["friction_work_J"]
    summary["peak_speed_m_s"] = float(np.max(np.abs(v)))
    summary["pressure_range_bar"] = [float(min(frame["p1_bar"].min(), frame["p2_bar"].min())),
                                     float(max(frame["p1_bar"].max(), frame["p2_bar"].max()))]
    summary["air_temperature_range_C"] = [float(min(frame["T1_C"].min(), frame["T2_C"].min())),
                                          float(max(frame["T1_C"].max(), frame["T2_C"].max()))]
    seals = {}
    for name in result.seal_names:
        f = frame[f"F_{name}_N"].to_numpy()
        entry = {"mean_friction_N": float(np.mean(np.abs(f[moving]))) if moving.any() else None,
                 "peak_friction_N": float(np.max(np.abs(f)))}
        if f"F_N_{name}_N" in frame:
            fn = frame[f"F_N_{name}_N"].to_numpy()
            entry["normal_force_range_N"] = [float(fn.min()), float(fn.max())]
            entry["contact_width_range_mm"] = [float(frame[f"b_{name}_mm"].min()),
                                               float(frame[f"b_{name}_mm"].max())]
        if f"theta_{name}" in frame:
            entry["theta_range"] = [float(frame[f"theta_{name}"].min()),
                                    float(frame[f"theta_{name}"].max())]
        seals[name] = entry
    summary["seals"] = seals
    summary["balances"] = b
    summary["solver"] = {k: (round(v, 4) if isinstance(v, float) else v)
                         for k, v in result.stats.items()}
    summary["notes"] = list(result.notes)
    return summary


def run_cases(cases: dict[str, PneumaticCase], base_dir: str | Path = ".",
              progress: Callable[[str, float, float], None] | None = None
              ) -> dict[str, PneumaticResult]:
    """Simulate every variant; ``progress(variant, simulated_time, end_time)`` (and
    ``progress("<variant>: FE map", done, total)`` while a seal's FE map is built)."""
    return {name: _run_variant(name, case, base_dir, progress) for name, case in cases.items()}


def _run_variant(name: str, case: PneumaticCase, base_dir: str | Path,
                 progress: Callable[[str, float, float], None] | None) -> PneumaticResult:
    maps = None if progress is None else (
        lambda done, total: progress(f"{name}: FE map", done, total))
    seals = build_seals(case, base_dir, maps)
    callback = None if progress is None else (lambda t, end: progress(name, t, end))
    return simulate(case, seals, base_dir, progress=callback)


def run_case_file(path: str | Path, out: str | Path, force: bool = False,
                  progress: Callable[[str, float, float], None] | None = None
                  ) -> dict[str, PneumaticResult]:
    """Simulate every variant of a case file and write the result folder ``out``.

    Parameters
    ----------
    path : str or Path
        Case file (TOML).
    out : str or Path
        Result folder; refused if it already holds results unless ``force``.
    force : bool
        Replace existing results.
    progress : callable, optional
        ``progress(variant, simulated_time, end_time)``.
    """
    path = Path(path)
    cases = load_pneumatic_case_file(path)
    return run_variants(
        cases, out, lambda name, case, _: _run_variant(name, case, path.parent, progress),
        lambda folder, results: write_results(folder, results, source=str(path)),
        force=force, inputs=[path])


def write_results(folder: ResultFolder, results: dict[str, PneumaticResult],
                  source: str = "") -> None:
    """Write the table, summary, resolved case and figures of a set of variants."""
    from sealsim.plotting.pneumatic import (
        friction_stroke_figure,
        friction_velocity_figure,
        pressure_stroke_figure,
        timeseries_figure,
    )

    frames = {name: r.timeseries for name, r in results.items()}
    table = pd.concat([f.assign(variant=name) for name, f in frames.items()], ignore_index=True)
    head = ["variant"] + TIMESERIES_COLUMNS
    extra = [c for c in table.columns if c not in head]
    folder.write_csv("timeseries.csv", table[head + extra], float_format="%.7g")
    first = next(iter(results.values())).case
    folder.write_json("summary.json", {
        "title": first.title, "source": source, "sealsim_version": __version__,
        "definitions": DEFINITIONS,
        "variants": {name: r.summary() for name, r in results.items()}})
    folder.write_text("case_resolved.toml", dump_variants_toml(
        {name: r.case for name, r in results.items()},
        header=f"Resolved case written by sealsim {__version__} (all defaults filled in).\n"
               f"Source: {source}\nRerun with: sealsim pneumatic run THIS_FILE --out DIR"))
    title = first.title
    strokes = {name: r.case.cylinder.stroke for name, r in results.items()}
    folder.savefig("pressure_stroke.png", pressure_stroke_figure(frames, title))
    folder.savefig("friction_stroke.png", friction_stroke_figure(frames, strokes, title))
    folder.savefig("friction_velocity.png", friction_velocity_figure(frames, title))
    for name, r in results.items():
        folder.savefig(f"timeseries_{name}.png",
                       timeseries_figure(r.timeseries, r.seal_names,
                                         f"{title} -- {name}" if title else name))
