"""What a user reads off a bench run: break-away forces, loop areas, dissipated energy,
stick-slip period (:func:`summarize`), and the result record of a run (:class:`BenchResult`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["BenchResult", "breakaway_forces", "cycle_work", "loop_areas", "motion_onsets",
           "stick_slip_period", "summarize"]


#: column-name units of friction states (bristle deflections z, z_i are lengths)
_STATE_UNITS = {"theta": "", "film_speed": "_m_s"}


@dataclass
class BenchResult:
    """Time series of one bench run (one contact).

    Attributes
    ----------
    time, position, velocity, force : ndarray, shape (N,)
        Time [s], displacement of the sliding body [m], sliding velocity [m/s] and friction
        force [N] (opposing v).
    states : ndarray, shape (N, n_states)
        Friction states.
    state_names : tuple of str
    drive_position, applied_force : ndarray or None
        Spring-end position [m] and applied force [N] (driven mass only).
    stuck : ndarray of bool or None
        True where the body sticks (laws with true sticking on the driven mass).
    mode : str
        "velocity", "displacement" or "mass".
    period : float or None
        Period of a harmonic drive [s] (for loop areas).
    """

    time: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    force: np.ndarray
    states: np.ndarray
    state_names: tuple[str, ...]
    mode: str
    drive_position: np.ndarray | None = None
    applied_force: np.ndarray | None = None
    stuck: np.ndarray | None = None
    period: float | None = None
    stored_energy: np.ndarray | None = None
    extra: dict[str, Any] = field(default_factory=dict)

    def columns(self) -> dict[str, np.ndarray]:
        """Columns for a CSV table (names carry units)."""
        cols = {"time_s": self.time, "position_m": self.position,
                "velocity_m_s": self.velocity, "friction_force_N": self.force}
        for i, name in enumerate(self.state_names):
            cols[f"{name}{_STATE_UNITS.get(name, '_m')}"] = self.states[:, i]
        if self.drive_position is not None:
            cols["drive_position_m"] = self.drive_position
        if self.applied_force is not None:
            cols["spring_plus_applied_force_N"] = self.applied_force
        if self.stuck is not None:
            cols["stuck"] = self.stuck.astype(int)
        return cols

    def decimated(self, max_rows: int) -> BenchResult:
        """Every k-th sample so that at most ``max_rows`` remain (plots, CSV)."""
        n = self.time.size
        if n <= max_rows:
            return self
        k = int(np.ceil(n / max_rows))
        idx = np.unique(np.concatenate([np.arange(0, n, k), [n - 1]]))

        def pick(a):
            return None if a is None else a[idx]

        return BenchResult(self.time[idx], self.position[idx], self.velocity[idx],
                           self.force[idx], self.states[idx], self.state_names, self.mode,
                           pick(self.drive_position), pick(self.applied_force),
                           pick(self.stuck), self.period, pick(self.stored_energy), self.extra)


def motion_onsets(velocity, rest_velocity):
    """Indices where |v| first exceeds ``rest_velocity`` after at least one sample at rest.

    Examples
    --------
    >>> motion_onsets(np.array([0.0, 0.0, 0.2, 0.3, 0.0, -0.5]), 0.1)
    array([2, 5])
    """
    moving = np.abs(np.asarray(velocity)) > rest_velocity
    return np.where(~moving[:-1] & moving[1:])[0] + 1


def breakaway_forces(result: BenchResult, rest_velocity: float | None = None):
    """Friction force at each start of motion from rest.

    An onset is the first sample with |v| > v_rest after rest (default v_rest = 1e-3 of the
    largest |v|, at least 10 µm/s: slower creep counts as rest); its break-away force is the
    largest |F| from the sample before the onset
    until |v| reaches 10·v_rest (the force peak of the transition from stick to slip).

    Returns
    -------
    times : ndarray
        Onset times [s].
    forces : ndarray
        Break-away forces [N] (magnitudes).
    """
    v = result.velocity
    vmax = float(np.max(np.abs(v))) if v.size else 0.0
    if rest_velocity is None:
        rest_velocity = max(1e-3 * vmax, 1e-5)
    if vmax <= rest_velocity:
        return np.array([]), np.array([])
    onsets = motion_onsets(v, rest_velocity)
    times, forces = [], []
    for i in onsets:
        j = i
        while j < v.size - 1 and abs(v[j]) < 10 * rest_velocity:
            j += 1
        forces.append(float(np.max(np.abs(result.force[i - 1:j + 1]))))
        times.append(float(result.time[i]))
    return np.array(times), np.array(forces)


def cycle_work(result: BenchResult, start: float, end: float) -> float:
    """Work of the friction force from ``start`` to ``end`` [J], ∫F·v dt (trapezoid)."""
    sel = (result.time >= start - 1e-12) & (result.time <= end + 1e-12)
    p = result.force[sel] * result.velocity[sel]
    return float(np.trapezoid(p, result.time[sel]))


def loop_areas(result: BenchResult):
    """Areas of the last complete cycle of a periodic drive.

    Returns
    -------
    dict
        ``force_displacement_J``: ∮F dx over the last full period [J] (the energy dissipated
        per cycle); ``force_velocity_N_m_s``: |∮F dv| [N·m/s] (width of the F–v hysteresis
        loop); both None without a periodic drive or a complete period.
    """
    per = result.period
    t = result.time
    if not per or t[-1] - t[0] < per * (1 - 1e-9):
        return {"force_displacement_J": None, "force_velocity_N_m_s": None, "period_s": per}
    n_cycles = int(np.floor((t[-1] - t[0]) / per + 1e-9))
    start = t[0] + (n_cycles - 1) * per
    sel = (t >= start - 1e-12) & (t <= start + per + 1e-12)
    f = result.force[sel]
    fx = float(np.trapezoid(f, result.position[sel]))
    fv = float(abs(np.trapezoid(f, result.velocity[sel])))
    return {"force_displacement_J": fx, "force_velocity_N_m_s": fv, "period_s": per,
            "cycle_start_s": float(start)}


def stick_slip_period(result: BenchResult) -> float | None:
    """Mean time between successive slips of a driven mass (None if fewer than 3 slips).

    Slips are upward crossings of |v| through half the largest |v| (interpolated); the first
    interval is skipped (start-up transient).
    """
    v = np.abs(result.velocity)
    thr = 0.5 * float(np.max(v)) if v.size else 0.0
    if thr <= 0:
        return None
    idx = np.where((v[:-1] < thr) & (v[1:] >= thr))[0]
    if idx.size < 3:
        return None
    t = result.time
    cross = t[idx] + (thr - v[idx]) / (v[idx + 1] - v[idx]) * (t[idx + 1] - t[idx])
    return float(np.mean(np.diff(cross)[1:]))


def summarize(result: BenchResult) -> dict[str, Any]:
    """Numbers a user compares: break-away forces, loop areas, dissipated energy, extremes.

    The dissipated energy is the work of the friction force on the contact, ∫F·v dt, minus the
    energy still stored in the bristles at the end (equal for a relaxed end state).
    """
    times, forces = breakaway_forces(result)
    work = float(np.trapezoid(result.force * result.velocity, result.time))
    stored_end = float(result.stored_energy[-1]) if result.stored_energy is not None else 0.0
    out: dict[str, Any] = {
        "mode": result.mode,
        "duration_s": float(result.time[-1] - result.time[0]),
        "samples": int(result.time.size),
        "friction_work_J": work,
        "dissipated_energy_J": work - stored_end,
        "stored_energy_end_J": stored_end,
        "max_friction_force_N": float(np.max(result.force)),
        "min_friction_force_N": float(np.min(result.force)),
        "max_abs_velocity_m_s": float(np.max(np.abs(result.velocity))),
        "max_abs_position_m": float(np.max(np.abs(result.position))),
        "breakaway_times_s": times.tolist(),
        "breakaway_forces_N": forces.tolist(),
        "loop_areas": loop_areas(result),
    }
    if result.mode == "mass":
        out["stick_slip_period_s"] = stick_slip_period(result)
        if result.stuck is not None:
            out["stuck_fraction"] = float(np.mean(result.stuck))
    for name in result.state_names:
        i = result.state_names.index(name)
        # the film's speed carries its unit (studies read units from the keys' ends);
        # theta is dimensionless, and z_min / z_max stay as study files name them
        unit = _STATE_UNITS.get(name, "")
        out[f"{name}_min{unit}"] = float(np.min(result.states[:, i]))
        out[f"{name}_max{unit}"] = float(np.max(result.states[:, i]))
    out.update({k: v for k, v in result.extra.items()})
    return out
