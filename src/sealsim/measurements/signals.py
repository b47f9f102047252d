"""Processing of measured signals: smoothed derivatives, sliding phases, levels, step averages.

Pure functions on arrays (SI).  They are the measured side of a comparison: the same functions
are applied to a model's output, so measured and predicted numbers are computed alike.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.signal import savgol_filter

from sealsim.errors import InputError

__all__ = [
    "SlidingPhase",
    "friction_level",
    "level_drift",
    "phase_mask",
    "position_velocity_ratio",
    "sliding_phases",
    "smooth_derivative",
    "step_averages",
    "stroke_levels",
]


def smooth_derivative(time, values, window=0.2, polyorder=2):
    """Derivative of a sampled signal by a Savitzky–Golay differentiator.

    The samples are interpolated onto a uniform grid at the median sampling interval (rig
    clocks jitter by a few percent), differentiated by a local least-squares polynomial of
    degree ``polyorder`` over ``window`` seconds and interpolated back to the sample times.

    Parameters
    ----------
    time : array_like
        Sample times [s], strictly increasing.
    values : array_like
        Signal, e.g. position [m].
    window : float
        Length of the smoothing window [s] (wide enough to average the noise, short against
        the changes of the signal).
    polyorder : int
        Degree of the local polynomial (2: exact for a parabola).

    Returns
    -------
    ndarray
        d(values)/dt at the sample times.

    References
    ----------
    A. Savitzky, M. J. E. Golay, "Smoothing and differentiation of data by simplified least
    squares procedures", Anal. Chem. 36(8), 1627-1639, 1964 (scipy.signal.savgol_filter).

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> v = smooth_derivative(t, 3.0 * t ** 2, window=0.1)
    >>> bool(np.allclose(v, 6.0 * t, atol=1e-9))
    True
    """
    t = np.asarray(time, dtype=float)
    y = np.asarray(values, dtype=float)
    if t.size < polyorder + 2:
        raise InputError(f"smooth_derivative: {t.size} samples are too few for a polynomial of "
                         f"degree {polyorder}")
    dt = float(np.median(np.diff(t)))
    grid = t[0] + dt * np.arange(int(np.floor((t[-1] - t[0]) / dt + 1e-6)) + 1)
    uniform = np.interp(grid, t, y)
    length = max(int(round(window / dt)) | 1, polyorder + 2 | 1)
    length = min(length, grid.size if grid.size % 2 else grid.size - 1)
    if length <= polyorder:
        raise InputError(f"smooth_derivative: window {window:g} s holds too few samples")
    derivative = savgol_filter(uniform, length, polyorder, deriv=1, delta=dt, mode="interp")
    return np.interp(t, grid, derivative)


@dataclass(frozen=True)
class SlidingPhase:
    """A stretch of steady sliding in one direction.

    Attributes
    ----------
    start, stop : int
        Sample indices [start, stop) after trimming the transient at its start.
    direction : int
        +1 or −1 (sign of the velocity).
    t_start, t_stop : float
        Times [s].
    mean_velocity : float
        Mean velocity over the phase [m/s].
    """

    start: int
    stop: int
    direction: int
    t_start: float
    t_stop: float
    mean_velocity: float


def sliding_phases(time, velocity, threshold=None, min_duration=0.5, settle=0.2):
    """Find the phases of steady sliding in a velocity signal.

    A phase is a run of samples with |v| above ``threshold`` and one sign, at least
    ``min_duration`` long; the first ``settle`` fraction of it (the transient after a reversal:
    break-away, pre-sliding, the state of a rate-and-state law evolving) is dropped.

    Parameters
    ----------
    time, velocity : array_like
        Samples [s], [m/s].
    threshold : float, optional
        Speed above which the contact slides [m/s]; default 10 % of the 90th percentile of |v|.
    min_duration : float
        Shortest phase kept [s].
    settle : float
        Fraction of each phase dropped at its start, 0 <= settle < 1.

    Returns
    -------
    list of SlidingPhase

    Raises
    ------
    InputError
        No sliding phase found (the message gives the threshold and the largest speed).

    Examples
    --------
    >>> t = np.linspace(0, 8, 801)
    >>> v = 0.01 * np.sign(np.sin(np.pi * t / 2))
    >>> [(p.direction, round(p.t_start, 1), round(p.t_stop, 1)) for p in sliding_phases(t, v)]
    [(1, 0.4, 2.0), (-1, 2.4, 4.0), (1, 4.4, 6.0), (-1, 6.4, 8.0)]
    """
    t = np.asarray(time, dtype=float)
    v = np.asarray(velocity, dtype=float)
    if not 0.0 <= settle < 1.0:
        raise InputError(f"sliding_phases: settle must be in [0, 1), got {settle!r}")
    speed = np.abs(v)
    if threshold is None:
        threshold = 0.1 * float(np.percentile(speed, 90)) if speed.size else 0.0
    sliding = (speed > threshold) & (threshold > 0)
    direction = np.where(sliding, np.sign(v), 0).astype(int)
    change = np.flatnonzero(np.diff(direction)) + 1
    bounds = np.concatenate([[0], change, [direction.size]])
    phases = []
    for a, b in zip(bounds[:-1], bounds[1:]):
        d = int(direction[a])
        if d == 0 or b - a < 3:
            continue
        duration = t[b - 1] - t[a]
        if duration < min_duration:
            continue
        a2 = a + int(np.ceil(settle * (b - a)))
        if b - a2 < 2:
            continue
        phases.append(SlidingPhase(int(a2), int(b), d, float(t[a2]), float(t[b - 1]),
                                   float(np.mean(v[a2:b]))))
    if not phases:
        raise InputError(
            f"no sliding phase found: |v| exceeds {threshold:.3g} m/s for at least "
            f"{min_duration:g} s nowhere (largest |v| = {speed.max() if speed.size else 0:.3g} "
            "m/s); check the velocity/position column and its unit")
    return phases


def phase_mask(n, phases) -> np.ndarray:
    """Boolean mask of the samples inside any of ``phases`` (length ``n``)."""
    mask = np.zeros(n, dtype=bool)
    for p in phases:
        mask[p.start:p.stop] = True
    return mask


def position_velocity_ratio(time, position, velocity, phases, window=0.2):
    """How the derivative of a measured position compares with a measured velocity.

    The median of |dx/dt| (:func:`smooth_derivative`) over the median of |v|, both over the
    sliding phases: about 1 when the time, position and velocity columns have the units they
    are declared with; a unit slip shows as its factor (a time in ms declared as s: 1/1000,
    a velocity in mm/s declared as m/s: 1/1000).

    Parameters
    ----------
    time, position, velocity : array_like
        Samples [s], [m], [m/s].
    phases : list of SlidingPhase
        Where to compare (:func:`sliding_phases`).
    window : float
        Smoothing window of the derivative [s].

    Returns
    -------
    float

    Examples
    --------
    >>> t = np.linspace(0, 8, 801)
    >>> v = 0.01 * np.sign(np.sin(np.pi * t / 2))
    >>> x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))])
    >>> round(position_velocity_ratio(t, x, v, sliding_phases(t, v)), 3)
    1.0
    >>> round(position_velocity_ratio(t * 1000, x, v, sliding_phases(t * 1000, v)), 6)
    0.001
    """
    t = np.asarray(time, dtype=float)
    v = np.asarray(velocity, dtype=float)
    mask = phase_mask(t.size, phases)
    derivative = smooth_derivative(t, position, window=window)
    return float(np.median(np.abs(derivative[mask])) / np.median(np.abs(v[mask])))


def friction_level(friction, phases):
    """Offset-free friction level of the sliding phases.

    Half the difference between the median friction in the two sliding directions, and the
    offset (their mean) that a load-cell zero error or a pressure area mismatch adds::

        F_level = (median F|v>0 − median F|v<0)/2,   F_offset = (median F|v>0 + median F|v<0)/2

    Parameters
    ----------
    friction : array_like
        Friction force [N], sealsim's sign (the sign of the velocity when sliding).
    phases : list of SlidingPhase
        From :func:`sliding_phases`; both directions needed.

    Returns
    -------
    (level, offset) : tuple of float
        [N].

    Examples
    --------
    >>> f = np.array([5.0, 5.2, 4.8, -3.0, -3.2, -2.8])
    >>> ph = [SlidingPhase(0, 3, 1, 0, 1, 0.01), SlidingPhase(3, 6, -1, 1, 2, -0.01)]
    >>> friction_level(f, ph)
    (4.0, 1.0)
    """
    f = np.asarray(friction, dtype=float)
    up = [f[p.start:p.stop] for p in phases if p.direction > 0]
    down = [f[p.start:p.stop] for p in phases if p.direction < 0]
    if not up or not down:
        raise InputError("friction level: sliding phases in both directions are needed (found "
                         f"{len(up)} forward, {len(down)} backward)")
    hi = float(np.median(np.concatenate(up)))
    lo = float(np.median(np.concatenate(down)))
    return 0.5 * (hi - lo), 0.5 * (hi + lo)


def stroke_levels(friction, phases):
    """Offset-free friction level of each pair of consecutive strokes.

    Consecutive sliding phases of one direction form a stroke (a stroke that slows below the
    sliding threshold on the way is split into phases); each pair of neighbouring strokes in
    opposite directions gives a level as :func:`friction_level` does for the whole run::

        F_k = (median F over the forward stroke − median F over the backward stroke) / 2

    so an offset of the force signal cancels in every pair, and a level that changes from
    stroke to stroke (grease wiped off, wear, heating, creep) shows as a trend of F_k.

    Parameters
    ----------
    friction : array_like
        Friction force [N], sealsim's sign (the sign of the velocity when sliding).
    phases : list of SlidingPhase
        From :func:`sliding_phases`, in time order.

    Returns
    -------
    (times, levels) : tuple of numpy.ndarray
        Mid-time of each pair [s] and its level [N]; empty without a stroke in each direction.

    Examples
    --------
    Two strokes each way on an offset of 1 N, the level growing from 4 to 5 N:

    >>> f = np.array([5.0, 5.0, -3.0, -3.0, 5.5, 5.5, -3.5, -3.5])
    >>> ph = [SlidingPhase(2 * k, 2 * k + 2, (-1) ** k, k, k + 1, 0.01 * (-1) ** k)
    ...       for k in range(4)]
    >>> stroke_levels(f, ph)[1].tolist()
    [4.0, 4.25, 4.5]
    """
    f = np.asarray(friction, dtype=float)
    strokes = []  # (direction, median friction, mid-time)
    group: list = []
    for phase in [*phases, None]:
        if group and (phase is None or phase.direction != group[0].direction):
            samples = np.concatenate([f[p.start:p.stop] for p in group])
            strokes.append((group[0].direction, float(np.median(samples)),
                            0.5 * (group[0].t_start + group[-1].t_stop)))
            group = []
        if phase is not None:
            group.append(phase)
    pairs = [(0.5 * (a[2] + b[2]), 0.5 * (a[1] - b[1]) * a[0])
             for a, b in zip(strokes, strokes[1:])]
    times = np.array([t for t, _ in pairs], dtype=float)
    return times, np.array([level for _, level in pairs], dtype=float)


def level_drift(levels, share=0.25):
    """How much a run's friction level changes from its first strokes to its last.

    The mean of the first and of the last ``share`` of the stroke-pair levels
    (:func:`stroke_levels`; at least one pair each) and their relative change
    ``(last − first) / first``: +0.29 means the run ends 29 % above where it started.

    Parameters
    ----------
    levels : array_like
        Stroke-pair levels [N] in time order.
    share : float
        Fraction of the pairs at each end, 0 < share <= 0.5.

    Returns
    -------
    (first, last, relative) : tuple of float
        [N], [N], [-]; NaN for all three without levels, ``relative`` NaN when ``first`` is 0.

    Examples
    --------
    >>> first, last, relative = level_drift([4.0, 4.1, 4.9, 5.0], share=0.5)
    >>> round(first, 2), round(last, 2), round(relative, 4)
    (4.05, 4.95, 0.2222)
    """
    if not 0.0 < share <= 0.5:
        raise InputError(f"level_drift: share must be in (0, 0.5], got {share!r}")
    values = np.asarray(levels, dtype=float)
    if values.size == 0:
        return float("nan"), float("nan"), float("nan")
    n = max(int(round(share * values.size)), 1)
    first, last = float(np.mean(values[:n])), float(np.mean(values[-n:]))
    return first, last, (last - first) / first if first else float("nan")


def step_averages(time, setpoint, signals, window=30.0, tolerance=0.02):
    """Averages over the last ``window`` seconds of each step of a stepped set-point.

    Organisciak et al. (2014) compare model and rig by the mean torque over the last 30 s of
    every speed step (the steady part of each step).  A step is a run of samples whose
    set-point stays within ``tolerance`` (relative to the largest |set-point|) of the value at
    the step's start; steps shorter than ``window`` are skipped.

    Parameters
    ----------
    time : array_like
        [s].
    setpoint : array_like
        The stepped quantity (e.g. speed [rad/s]).
    signals : dict of str -> array_like
        Signals to average (e.g. ``{"torque": ..., "temperature": ...}``).
    window : float
        Averaging window at the end of each step [s].
    tolerance : float
        Relative change that starts a new step.

    Returns
    -------
    list of dict
        One dict per step: ``t_start``, ``t_end``, ``setpoint`` (mean over the window) and the
        mean of every signal over the window.

    Examples
    --------
    >>> t = np.arange(0.0, 120.0, 0.5)
    >>> n = np.where(t < 60, 100.0, 200.0)
    >>> [round(s["torque"], 2) for s in step_averages(t, n, {"torque": n / 100}, window=30)]
    [1.0, 2.0]
    """
    t = np.asarray(time, dtype=float)
    s = np.asarray(setpoint, dtype=float)
    scale = float(np.max(np.abs(s))) if s.size else 0.0
    tol = tolerance * (scale if scale > 0 else 1.0)
    steps = []
    start = 0
    for k in range(1, s.size + 1):
        if k == s.size or abs(s[k] - s[start]) > tol:
            if t[k - 1] - t[start] >= window - 1e-9:
                sel = slice(start, k)
                mask = t[sel] >= t[k - 1] - window
                row = {"t_start": float(t[start]), "t_end": float(t[k - 1]),
                       "setpoint": float(np.mean(s[sel][mask]))}
                for key, values in signals.items():
                    row[key] = float(np.mean(np.asarray(values, dtype=float)[sel][mask]))
                steps.append(row)
            start = k
    return steps
