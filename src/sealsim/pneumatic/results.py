"""Results of a pneumatic simulation: the sampled time series, the balances, the notes.

The time series is sampled on the output grid from the integrator's dense output; everything
besides the states is recomputed there by the compiled right-hand side (:mod:`.rhs`).
"""

from __future__ import annotations

import re
import threading
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pandas as pd

from sealsim.pneumatic import rhs
from sealsim.pneumatic.integrate import segment_states
from sealsim.pneumatic.valve import ANR_DENSITY
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["TIMESERIES_COLUMNS", "PneumaticResult", "Sampler", "column_name", "seal_columns"]

#: leading columns of the time series (pressures are absolute)
TIMESERIES_COLUMNS = ["time_s", "x_m", "v_m_s", "p1_bar_abs", "p2_bar_abs", "T1_C", "T2_C",
                      "valve_command", "spool", "mode", "F_friction_N", "F_pressure_N"]


def column_name(name: str) -> str:
    """A seal name as it appears in column names: letters, digits, ``_``, ``.`` and ``-``;
    anything else becomes ``_`` (``"test seal"`` → ``"test_seal"``).

    Examples
    --------
    >>> column_name("test seal")
    'test_seal'
    """
    return re.sub(r"[^0-9A-Za-z_.-]+", "_", name.strip()) or "seal"


def seal_columns(names) -> list[str]:
    """Column names of the seals (:func:`column_name`), made unique with a suffix ``_2``, ...

    Examples
    --------
    >>> seal_columns(["a b", "a_b", "rod"])
    ['a_b', 'a_b_2', 'rod']
    """
    out: list[str] = []
    for name in names:
        base = key = column_name(name)
        k = 2
        while key in out:
            key = f"{base}_{k}"
            k += 1
        out.append(key)
    return out


@dataclass
class PneumaticResult:
    """Result of one simulation.

    Attributes
    ----------
    case : PneumaticCase
    timeseries : pandas.DataFrame
        One row per output sample (columns: see :data:`TIMESERIES_COLUMNS` and per seal, under
        its :func:`column_name`, ``F_<seal>_N`` (friction), ``dp_<seal>_bar`` (pressure
        difference across it), with a contact map ``F_N_<seal>_N`` and ``b_<seal>_mm``, with a
        Θ state ``theta_<seal>``, with seal heating ``T_<seal>_C``, and then ``T_tube_metal_C``,
        ``T_rod_metal_C``).
    balances : dict
        Mass and energy bookkeeping (kg, J) and their relative errors (and, with seal heating,
        the heat balance of the seals and metal parts).
    stats : dict
        Solver statistics (segments, steps, RHS evaluations, wall time, mode switches).
    notes : list of str
        Things a user should know (e.g. map pressure ranges exceeded).
    seal_names : list of str
        The names of the seals as in the case.
    seal_columns : list of str
        Their names in the columns (:func:`seal_columns`).
    """

    case: Any
    timeseries: pd.DataFrame
    balances: dict
    stats: dict
    notes: list = field(default_factory=list)
    seal_names: list = field(default_factory=list)
    seal_columns: list = field(default_factory=list)

    def summary(self) -> dict[str, Any]:
        """The numbers of ``summary.json`` for this variant."""
        from sealsim.pneumatic.summary import summarize

        return summarize(self)


_WORK = threading.local()


def _work_array(name: str, shape: tuple, order: str = "C", zero: bool = True) -> np.ndarray:
    """A float array of this thread (zeroed, or as the last call left it), kept for the next
    call with the same ``name`` (one shape per name): the output arrays of a run are
    megabytes, and fresh ones cost their first-touch page faults on every run (a quarter of a
    10 s cylinder run's time).  The next call with the name overwrites it: for arrays
    consumed before the run returns."""
    arrays = _WORK.__dict__.setdefault("arrays", {})
    array = arrays.get(name)
    if array is None or array.shape != shape or not array.flags[f"{order}_CONTIGUOUS"]:
        array = arrays[name] = np.zeros(shape, order=order)
    elif zero:
        array.fill(0.0)
    return array


class Sampler:
    """Collects the states on the output grid segment by segment while the integration runs,
    so that the dense output of a segment can be dropped as soon as the next one starts (a long
    duty cycle keeps hundreds of thousands of steps).  ``sampler(segment)`` after each segment,
    :meth:`finish` at the end.

    With ``reuse`` the compiled integrator's sample array (:meth:`buffer`) is a work array of
    this thread that the next reusing sampler overwrites: for a caller that is done with the
    samples before it simulates again (:func:`sealsim.pneumatic.simulation.run`, whose time
    series are copies).
    """

    def __init__(self, system, reuse: bool = False):
        dt = system.case.output.sample_interval
        end = system.duration
        grid = np.arange(0.0, end + 0.5 * dt, dt)
        self.grid = np.minimum(grid[grid <= end * (1 + 1e-12)], end)   # last sample at the end
        self.times, self.states, self.modes = [], [], []
        self.pending = None
        self.reuse = reuse

    def buffer(self, n_states: int) -> np.ndarray:
        """Array (samples, states) for the compiled integrator, which writes every row."""
        shape = (self.grid.size, n_states)
        return _work_array("samples", shape, zero=False) if self.reuse else np.zeros(shape)

    def __call__(self, segment) -> None:
        if self.pending is not None:
            self._take(self.pending, last=False)
            self.pending.dense = None
        self.pending = segment

    def _take(self, seg, last: bool) -> None:
        sel = (self.grid >= seg.t0) & ((self.grid <= seg.t1) if last else (self.grid < seg.t1))
        ts = self.grid[sel]
        if ts.size == 0:
            return
        ys = segment_states(seg, ts)
        if seg.mode == rhs.STICK:
            ys[1] = 0.0
        self.times.append(ts)
        self.states.append(ys)
        self.modes.append(np.full(ts.shape, seg.mode, dtype=np.int64))

    def store(self, times, states, modes) -> None:
        """All samples at once (the compiled integrator samples the grid itself)."""
        self.times, self.states, self.modes = [times], [states], [modes]

    def finish(self):
        """(times, states, modes) of all samples."""
        if self.pending is not None:
            self._take(self.pending, last=True)
            self.pending = None
        if len(self.states) == 1:       # stored at once: no copy (keeps the column-major
            return self.times[0], self.states[0], self.modes[0]     # layout of the samples)
        return np.concatenate(self.times), np.hstack(self.states), np.concatenate(self.modes)


def sample(system, sampler: Sampler):
    """The output time series: the collected states, everything else recomputed there.
    Returns (DataFrame, diagnostics dict); with a reusing sampler the diagnostics are views of
    this thread's work arrays too (the DataFrame is a copy)."""
    ts, ys, modes = sampler.finish()
    diag = _diagnostics(system, ts, ys, modes, sampler.reuse)
    return _frame(system, diag), diag


def _diagnostics(system, ts, ys, modes, reuse: bool = False) -> dict[str, np.ndarray]:
    buffers = None
    if reuse:
        # not zeroed again: only this outputs-only evaluation writes into them, and it writes
        # every entry except those it leaves at 0 (the derivatives, a heated seal's friction
        # power), which stay 0 from the arrays' creation (4 MB of zeros: 2 % of a run)
        buffers = (_work_array("derivatives", ys.shape, "F", zero=False),
                   _work_array("diagnostics", (system.n_diag, ts.size), "F", zero=False))
    d = system.evaluate(ts, ys, modes, full=True, outputs_only=True, out=buffers)
    out = {"time": ts, "x": d["x"], "v": d["v"], "p1": d["p1"], "p2": d["p2"], "T1": d["T1"],
           "T2": d["T2"], "spool": np.asarray(d["spool"], dtype=float),
           "command": system.schedule.command_at(ts), "mode": modes,
           "f_fric": d["f_fric"], "f_press": d["f_press"], "f_seal": d["f_seal"],
           "T_tube": d["T_tube"], "T_rod": d["T_rod"]}
    for i, s in enumerate(system.seals):
        fn, b, dp = d["loads"][i]
        out[f"fn{i}"], out[f"b{i}"], out[f"dp{i}"] = fn, b, dp
        out[f"tseal{i}"] = d["seal_temperature"][i]
        out[f"clip{i}"] = d["temperature_clipped"][i]
        names = s.law.state_names
        if "theta" in names:
            out[f"theta{i}"] = ys[system.offsets[i] + names.index("theta")]
        if "film_speed" in names:                # the contact law's film state [m/s]
            out[f"film{i}"] = ys[system.offsets[i] + names.index("film_speed")]
    return out


_MODE_CODES = np.array(sorted(rhs.MODES))
_MODE_NAMES = np.array([rhs.MODES[k] for k in _MODE_CODES], dtype=object)


def _frame(system, diag) -> pd.DataFrame:
    # (name, values, conversion to the column's unit: a divisor, a subtrahend or a factor)
    cols = [("time_s", diag["time"], None), ("x_m", diag["x"], None),
            ("v_m_s", diag["v"], None), ("p1_bar_abs", diag["p1"], ("/", 1e5)),
            ("p2_bar_abs", diag["p2"], ("/", 1e5)), ("T1_C", diag["T1"], ("-", ZERO_CELSIUS_K)),
            ("T2_C", diag["T2"], ("-", ZERO_CELSIUS_K)), ("valve_command", diag["command"], None),
            ("spool", diag["spool"], None), ("mode", None, None),
            ("F_friction_N", diag["f_fric"], None), ("F_pressure_N", diag["f_press"], None)]
    for i, (s, name) in enumerate(zip(system.seals, seal_columns(s.name for s in
                                                                 system.seals))):
        cols.append((f"F_{name}_N", diag["f_seal"][i], None))
        if s.contact_map is not None:          # F_N and b exist where a map gives them
            cols.append((f"F_N_{name}_N", diag[f"fn{i}"], None))
            cols.append((f"b_{name}_mm", diag[f"b{i}"], ("*", 1e3)))
        cols.append((f"dp_{name}_bar", diag[f"dp{i}"], ("/", 1e5)))
        if f"theta{i}" in diag:
            cols.append((f"theta_{name}", diag[f"theta{i}"], None))
        if f"film{i}" in diag:
            cols.append((f"film_speed_{name}_m_s", diag[f"film{i}"], None))
        if system.heating and system.tables[3][i, rhs.SI_HEATED]:
            cols.append((f"T_{name}_C", diag[f"tseal{i}"], ("-", ZERO_CELSIUS_K)))
    if system.heating:
        cols.append(("T_tube_metal_C", diag["T_tube"], ("-", ZERO_CELSIUS_K)))
        cols.append(("T_rod_metal_C", diag["T_rod"], ("-", ZERO_CELSIUS_K)))
    # the float columns as one block that the frame keeps without a copy (a frame built from a
    # dict of columns copies them all into a new block once more); each converted straight
    # into its row (the same IEEE operation as ``values / 1e5``, no temporary array)
    floats = [c for c in cols if c[0] != "mode"]
    block = np.empty((len(floats), diag["time"].size))
    for row, (_, values, unit) in zip(block, floats):
        if unit is None:
            row[:] = values
        else:
            _CONVERT[unit[0]](values, unit[1], out=row)
    frame = pd.DataFrame(block.T, columns=[c[0] for c in floats], copy=False)
    # the column of pandas' type for the five names (str with pandas 3, object before),
    # inferred from them once, not from the 10^4 samples
    modes = pd.Series(_MODE_NAMES).array.take(np.searchsorted(_MODE_CODES, diag["mode"]))
    frame.insert([c[0] for c in cols].index("mode"), "mode", modes)
    return frame


_CONVERT = {"/": np.divide, "-": np.subtract, "*": np.multiply}


def balances(system, segments) -> dict[str, float]:
    """Mass and energy bookkeeping from the bookkeeping states (see
    :mod:`sealsim.pneumatic.simulation`)."""
    y0 = segments[0].y0
    y1 = segments[-1].y1.copy()
    if segments[-1].mode == rhs.STICK:
        y1[1] = 0.0
    book = {name: float(y1[i] - y0[i]) for name, i in system.book.items()}
    if system.position is not None:
        v0 = float(system.position.derivative(segments[0].t0))
        v1 = float(system.position.derivative(segments[-1].t1))
    else:
        v0, v1 = float(y0[1]), float(y1[1])
    stored_mass = float(y1[2] + y1[3] - y0[2] - y0[3])
    stored_energy = float(y1[4] + y1[5] - y0[4] - y0[5])
    kinetic = 0.5 * system.mass * (v1 ** 2 - v0 ** 2)
    mass_in = book["supply_mass"] - book["exhaust_mass"]
    mass_scale = max(book["mass_throughput"], float(y0[2] + y0[3]))
    if system.position is None:
        # air + piston: enthalpy, wall heat, work of load, atmosphere and stops, friction
        energy_in = (book["enthalpy"] + book["heat"] + book["work_external"]
                     + book["work_stop"] - book["work_friction"])
        energy_change = stored_energy + kinetic
        throughput = (book["enthalpy_throughput"] + abs(book["heat"])
                      + abs(book["work_external"]) + abs(book["work_stop"])
                      + abs(book["work_friction"]) + abs(kinetic))
    else:
        # the rig drives the piston: balance of the air alone (work p·dV on the piston)
        energy_in = book["enthalpy"] + book["heat"] - book["gas_work"]
        energy_change = stored_energy
        throughput = book["enthalpy_throughput"] + abs(book["heat"]) + abs(book["gas_work"])
    returned = max(book["supply_return_mass"], 0.0)
    out = {
        "air_mass_change_kg": stored_mass,
        "supply_mass_kg": book["supply_mass"],
        "supply_return_mass_kg": book["supply_return_mass"],
        "exhaust_mass_kg": book["exhaust_mass"],
        "air_energy_change_J": stored_energy,
        "kinetic_energy_change_J": kinetic,
        "enthalpy_in_J": book["enthalpy"],
        "wall_heat_J": book["heat"],
        "gas_work_J": book["gas_work"],
        "external_work_J": book["work_external"],
        "stop_work_J": book["work_stop"],
        "friction_work_J": book["work_friction"],
        "mass_balance_rel_error": abs(stored_mass - mass_in) / max(mass_scale, 1e-300),
        # scaled like the mass: a run in which nothing moves has no throughput, and its
        # round-off of U1 + U2 is no balance error
        "energy_balance_rel_error": abs(energy_change - energy_in) / max(
            throughput, float(y0[4] + y0[5]), 1e-300),
        # what the supply delivered (ISO 6358 / ISO 8778 free air); air a chamber pushed back
        # into the supply line is its own number, not netted against it.  Both integrate a
        # flow that is never negative: a negative total is the integrator's error on a flow
        # that stays zero (about -1e-7 NL), not air, and is reported as none
        "air_consumption_NL": max(book["supply_mass"] + returned, 0.0) / ANR_DENSITY * 1e3,
        "air_returned_to_supply_NL": returned / ANR_DENSITY * 1e3,
    }
    if system.heating:
        out.update(thermal_balance(system, y0, y1, book))
    return out


def thermal_balance(system, y0, y1, book) -> dict[str, float]:
    """Heat balance of the seal, tube and rod nodes: friction heat = heat stored + heat into
    the chamber air + heat to the surroundings."""
    c = system.tables[0]
    t0, nseal = system.temperature_offset, len(system.seals)
    caps = np.concatenate([system.tables[5][:, rhs.ST_CAP],
                           [c[rhs.C_TUBE_CAP], c[rhs.C_ROD_CAP]]])
    stored = float(np.sum(caps * (y1[t0:t0 + nseal + 2] - y0[t0:t0 + nseal + 2])))
    friction_heat = book["friction_heat"]
    removed = book["heat_to_air"] + book["heat_to_ambient"]
    scale = max(abs(friction_heat), abs(stored) + abs(book["heat_to_air"])
                + abs(book["heat_to_ambient"]), 1e-300)
    return {
        "seal_friction_heat_J": friction_heat,
        "thermal_heat_stored_J": stored,
        "thermal_heat_to_air_J": book["heat_to_air"],
        "thermal_heat_to_ambient_J": book["heat_to_ambient"],
        "heat_balance_rel_error": abs(friction_heat - stored - removed) / scale,
    }


def notes(system, diag) -> list[str]:
    """Notes of a run: pressure differences beyond a contact map, seal temperatures clamped
    to a map."""
    out = []
    names = [s.name for s in system.seals]
    for i, s in enumerate(system.seals):
        if s.contact_map is None:
            continue
        hi = s.contact_map.ranges["pressure"][1]
        over = diag[f"dp{i}"] > hi * (1 + 1e-9)
        if np.any(over):
            out.append(
                f"seal {names[i]!r}: the pressure difference exceeded its contact map "
                f"({hi / 1e5:.4g} bar) by up to {(diag[f'dp{i}'].max() - hi) / 1e5:.3g} bar in "
                f"{over.mean() * 100:.2g} % of the samples; F_N and b were held at the map edge")
        clipped = diag[f"clip{i}"] > 0.5
        if system.heating and np.any(clipped):
            lo, up = s.contact_map.ranges["temperature"]
            out.append(
                f"seal {names[i]!r}: its temperature left the contact map ({lo - ZERO_CELSIUS_K:.4g} "
                f"... {up - ZERO_CELSIUS_K:.4g} degC) in {clipped.mean() * 100:.2g} % of the samples "
                f"(up to {diag[f'tseal{i}'].max() - ZERO_CELSIUS_K:.4g} degC); F_N and b were held at the "
                "map edge")
    return out
