"""Compare a measured cylinder run -- x(t), p1(t), p2(t) -- with a simulation of its case
(what ``sealsim pneumatic compare`` computes;
:func:`sealsim.runs.calibration.run_pneumatic_compare_file` writes the result folder).

A compare file (TOML)::

    case = "../pneumatic/cylinder_32.toml"   # the pneumatic case (paths relative to this file)
    variant = "T25C"                          # when the case has variants

    [measurement]
    file = "run.csv"
    delimiter = ","
    header = true
    pressure = "gauge"                        # or "absolute": how p1, p2 were measured
    columns = { time = { column = "t", unit = "s" }, position = { column = "x", unit = "mm" },
                pressure_1 = { column = "p1", unit = "bar" },
                pressure_2 = { column = "p2", unit = "bar" } }

A logger that does not start at the simulation's t = 0 is aligned with a time offset
(``sealsim pneumatic compare --time-offset "12.5 s"``, ``time_offset`` here): the logger's
time at the simulation's t = 0, subtracted from every measured time (the report keeps it as
``time_offset_s``; the table's ``time_s`` is the simulation's time, ``logger_time_s`` the
measured one).  The model is sampled at the measured times (linear interpolation of its
output, which is sampled finer); per signal the RMSE, the largest deviation and R² are
reported, plus the extend/retract times of both (``stroke_times``, for a ``cycle`` case with a
measured position; :func:`sealsim.pneumatic.summary.stroke_times` of the measured and of the
simulated position).
Pressures are compared as they were measured: the table's and the plot's pressures are gauge
(``pressure_1_measured_bar_gauge``) or absolute (``..._bar_abs``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import numpy as np
import pandas as pd
from pydantic import Field

from sealsim.calibration.case import ColumnModel
from sealsim.calibration.statistics import compare_signals
from sealsim.cases import CaseModel, load_toml, validate_case
from sealsim.errors import InputError
from sealsim.measurements import ColumnSpec, read_table
from sealsim.pneumatic.case import case_input_files, load_pneumatic_case_file
from sealsim.pneumatic.simulation import simulate
from sealsim.pneumatic.summary import stroke_times

__all__ = ["CompareCase", "PneumaticComparison", "compare_inputs", "compare_pneumatic_file"]

SIGNALS = {"position": ("x_m", 1.0, "mm", 1e3),
           "pressure_1": ("p1_bar_abs", 1e5, "bar", 1e-5),
           "pressure_2": ("p2_bar_abs", 1e5, "bar", 1e-5)}


class CompareMeasurement(CaseModel):
    file: str
    columns: dict[str, ColumnModel]
    delimiter: str | None = None
    decimal: Literal[".", ","] = "."
    header: bool = False
    skip_rows: int = Field(0, ge=0)
    pressure: Literal["gauge", "absolute"] = "gauge"


class CompareCase(CaseModel):
    """A measured run and the pneumatic case that should reproduce it."""

    case: str
    variant: str | None = None
    measurement: CompareMeasurement


@dataclass
class PneumaticComparison:
    """A measured cylinder run against its simulation, at the measured times."""

    #: ``{"variant": NAME, "time_offset_s": OFFSET, "signals": {SIGNAL: {"unit", "rmse",
    #: "max_abs_error", "r2"}}}`` (errors in the signal's unit)
    report: dict
    #: ``time_s`` (simulation time), ``logger_time_s`` and ``<signal>_measured_<unit>``,
    #: ``<signal>_model_<unit>`` columns (pressures: ``bar_gauge`` or ``bar_abs``, as measured)
    table: pd.DataFrame
    #: ``{signal: (measured, model, unit)}`` in display units
    curves: dict
    time: np.ndarray
    title: str


def compare_inputs(path: str | Path) -> list[Path]:
    """The files a compare file reads: itself, its pneumatic case (and the map files the case
    names) and the measurement -- refused inside the result folder."""
    path = Path(path)
    spec = validate_case(CompareCase, load_toml(path), f"compare file {str(path)!r}")
    case_path = _resolve(spec.case, path.parent)
    files = [path, case_path, _resolve(spec.measurement.file, path.parent)]
    if case_path.is_file():
        for case in load_pneumatic_case_file(case_path).values():
            files += case_input_files(case, case_path.parent)
    return files


def _resolve(name: str, base: Path) -> Path:
    return Path(name) if Path(name).is_absolute() else base / name


def compare_pneumatic_file(path: str | Path, progress=None,
                           time_offset: float = 0.0) -> PneumaticComparison:
    """Simulate the case of a compare file and compare it with the measurement.

    Parameters
    ----------
    path : path
        Compare file (TOML, see the module docstring).
    progress : callable, optional
        ``progress(variant, simulated_time, end_time)``.
    time_offset : float
        The logger's time at the simulation's t = 0 [s]; subtracted from the measured times.
    """
    if not np.isfinite(time_offset):
        raise InputError(f"time offset: {time_offset!r} is not a finite time")
    path = Path(path)
    spec = validate_case(CompareCase, load_toml(path), f"compare file {str(path)!r}")
    base = path.parent
    case_path = _resolve(spec.case, base)
    cases = load_pneumatic_case_file(case_path)
    if spec.variant is None and len(cases) > 1:
        raise InputError(f"{path}: variant: the case has variants {sorted(cases)}; name one")
    name = spec.variant or next(iter(cases))
    if name not in cases:
        raise InputError(f"{path}: variant {name!r} is not in {sorted(cases)}")
    m = spec.measurement
    wanted = set(m.columns) - {"time"}
    if "time" not in m.columns or not wanted <= set(SIGNALS) or not wanted:
        raise InputError(f"{path}: measurement.columns needs time and at least one of "
                         f"{sorted(SIGNALS)} (got {sorted(m.columns)})")
    mfile = _resolve(m.file, base)
    measured = read_table(mfile, [ColumnSpec(q, c.column, c.unit, c.scale)
                                  for q, c in m.columns.items()],
                          delimiter=m.delimiter, header=m.header, skip_rows=m.skip_rows,
                          decimal=m.decimal)
    case = cases[name]
    result = simulate(case, base_dir=case_path.parent,
                      progress=None if progress is None else lambda t, e: progress(name, t, e))
    frame = result.timeseries
    t_model = frame["time_s"].to_numpy()
    t = measured.time - time_offset
    if t[0] < t_model[0] - 1e-9 or t[-1] > t_model[-1] + 1e-9:
        shifted = (f" (logger time minus the time offset {time_offset:g} s)" if time_offset
                   else "")
        hint = ("set controller.duration of the case to cover it, or --time-offset to the "
                "logger's time at the start of the simulation")
        if t[0] > t_model[0] and t[-1] - t[0] <= t_model[-1] - t_model[0] + 1e-9:
            # a logger's clock (time since power-on, a time of day): the model counts from
            # the start of the case's run, and the comparison lines the two up by time
            hint = (f"the model counts from the start of the case's run ({t_model[0]:g} s), "
                    f"the file from {t[0]:g} s: if its clock does not start with the run, give "
                    f"--time-offset '{t[0] + time_offset - t_model[0]:g} s' (the logger's time "
                    "at the start of the simulation), else " + hint.split(", or")[0])
        raise InputError(f"{mfile}: measured time {t[0]:g} … {t[-1]:g} s{shifted} lies outside "
                         f"the simulated {t_model[0]:g} … {t_model[-1]:g} s; {hint}")
    gauge = case.air.ambient_pressure if m.pressure == "gauge" else 0.0
    report = {"variant": name, "time_offset_s": time_offset, "signals": {}}
    table, curves = {"time_s": t, "logger_time_s": measured.time}, {}
    for q in sorted(wanted):
        column, si_per_model_unit, unit, display = SIGNALS[q]
        model = np.interp(t, t_model, frame[column].to_numpy() * si_per_model_unit)
        meas = measured.column(q)
        level = unit                       # the unit of the values (errors: of differences)
        if q != "position":
            model = model - gauge          # the model's pressures are absolute
            level = f"{unit}_{'gauge' if m.pressure == 'gauge' else 'abs'}"
        report["signals"][q] = {"unit": unit, **{
            k: (v * display if v is not None and k != "r2" else v)
            for k, v in compare_signals(meas, model).items()}}
        table[f"{q}_measured_{level}"] = meas * display
        table[f"{q}_model_{level}"] = model * display
        curves[q] = (meas * display, model * display, level.replace("_", " "))
    if "position" in wanted and case.controller.mode == "cycle":
        report["stroke_times"] = {
            "measured": stroke_times(t, measured.column("position"), case),
            "model": stroke_times(t_model, frame["x_m"].to_numpy(), case)}
    return PneumaticComparison(report, pd.DataFrame(table), curves, t,
                               f"{case.title or name}: measured vs model")
