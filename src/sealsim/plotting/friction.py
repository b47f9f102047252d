"""Figures of friction bench runs: F–v loops (Heipl & Murrenhoff Fig. 2/3/6 style), Θ–v, F–x,
time series.

Every function takes ``{variant name: BenchResult}`` and returns a pyplot-free Figure.  Axes
use readable units (µm, mm/s) chosen from the data.
"""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from sealsim.plotting import new_figure

__all__ = [
    "steady_velocity_grid",
    "plot_force_displacement",
    "plot_force_velocity",
    "plot_theta_velocity",
    "plot_timeseries",
]


def _scale(values, unit: str):
    """(factor, label) so that the largest |value| reads between 1 and 1000."""
    peak = max((float(np.max(np.abs(v))) for v in values if np.size(v)), default=0.0)
    table = {"m": [(1e-6, "µm"), (1e-3, "mm"), (1.0, "m")],
             "m/s": [(1e-6, "µm/s"), (1e-3, "mm/s"), (1.0, "m/s")]}
    if unit not in table or peak == 0.0:
        return 1.0, unit
    for factor, label in table[unit]:
        if peak < 1000 * factor:
            return 1.0 / factor, label
    return 1.0, unit


def last_cycles(results, cycles: int = 1):
    """Only the last ``cycles`` periods of runs with a periodic drive (clean loops).

    Runs without a period, or shorter than it, are returned whole.
    """
    out = {}
    for name, r in results.items():
        per = r.period
        if per and r.time[-1] - r.time[0] >= (cycles + 0.5) * per:
            sel = r.time >= r.time[-1] - cycles * per - 1e-12
            out[f"{name} (last cycle)" if cycles == 1 else name] = _select(r, sel)
        else:
            out[name] = r
    return out


def _select(r, sel):
    from dataclasses import replace

    def pick(a):
        return None if a is None else a[sel]

    return replace(r, time=r.time[sel], position=r.position[sel], velocity=r.velocity[sel],
                   force=r.force[sel], states=r.states[sel], drive_position=pick(r.drive_position),
                   applied_force=pick(r.applied_force), stuck=pick(r.stuck),
                   stored_energy=pick(r.stored_energy))


def steady_velocity_grid(v_min: float, v_max: float, n: int = 200):
    """Velocities [m/s] at which to draw a steady friction curve over the range a run visited.

    Each direction's branch is sampled linearly and geometrically down to 1e-5 of its extent,
    so the steep low-speed part of a Stribeck curve (its break-away peak, at a Stribeck
    velocity often 1000 times below the top speed) is drawn; v = 0, where the curve jumps
    from -F to +F, is left out (:func:`plot_force_velocity` breaks the line there), and so is
    a direction the run went less than 1 % as far as the other.

    >>> v = steady_velocity_grid(-0.1, 0.2)
    >>> float(v.min()), float(v.max()), bool((v == 0).any()), float(abs(v[v > 0]).min())
    (-0.1, 0.2, False, 2e-06)
    """
    branches = []
    extents = (-min(v_min, 0.0), max(v_max, 0.0))
    for sign, extent in zip((-1.0, 1.0), extents):
        if extent > 0.01 * max(extents):     # not the creep of a sticking body backwards
            speeds = np.union1d(np.geomspace(1e-5 * extent, extent, n),
                                np.linspace(extent / n, extent, n))
            branches.append(sign * speeds)
    return np.sort(np.concatenate(branches)) if branches else np.zeros(0)


def _broken_at_zero(v, y):
    """(v, y) with NaN between samples of opposite sign and at v = 0: a steady friction curve
    jumps there (sgn v), a line must not join its two branches."""
    v, y = np.asarray(v, dtype=float), np.asarray(y, dtype=float)
    y = np.where(v == 0.0, np.nan, y)
    cross = np.flatnonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0) + 1
    return np.insert(v, cross, np.nan), np.insert(y, cross, np.nan)


def _same_curves(curves) -> bool:
    items = list(curves.values())
    return len(items) > 1 and all(
        np.shape(a[0]) == np.shape(items[0][0]) and np.allclose(a[0], items[0][0])
        and np.allclose(a[1], items[0][1]) for a in items[1:])


def _draw_steady(ax, results, steady, factor, what, jumps=True):
    """Dashed analytic curves: one black curve if all variants share it, else one per run;
    ``jumps``: the curve jumps at v = 0 (a force), the line is broken there."""
    if not steady:
        return

    def xy(v, y):
        v, y = _broken_at_zero(v, y) if jumps else (np.asarray(v, dtype=float), y)
        return v * factor, y

    if _same_curves(steady):
        v, y = next(iter(steady.values()))
        ax.plot(*xy(v, y), ls="--", lw=0.9, color="k", label=what)
        return
    colors = {line.get_label(): line.get_color() for line in ax.get_lines()}
    for name, (v, y) in steady.items():
        ax.plot(*xy(v, y), ls="--", lw=0.9,
                label=f"{name.removesuffix(' (last cycle)')}: {what}",
                color=next((c for k, c in colors.items() if k.startswith(name)), None))


def _title(ax, title: str | None):
    if title:
        ax.set_title(title, fontsize=10)


def plot_force_velocity(results, steady=None, title: str | None = None):
    """Friction force against sliding velocity, one loop per variant.

    Parameters
    ----------
    results : dict of str to BenchResult
    steady : dict of str to (v, F), optional
        Analytic steady curves drawn dashed.
    title : str, optional
    """
    fig, ax = new_figure(width=6.4, height=4.4)
    vf, vl = _scale([r.velocity for r in results.values()], "m/s")
    for name, r in results.items():
        ax.plot(r.velocity * vf, r.force, lw=1.2, label=name)
    _draw_steady(ax, results, steady, vf, "steady curve")
    ax.axhline(0, color="0.7", lw=0.6)
    ax.axvline(0, color="0.7", lw=0.6)
    ax.set_xlabel(f"sliding velocity v [{vl}]")
    ax.set_ylabel("friction force F [N]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    _title(ax, title)
    return fig


def plot_theta_velocity(results, steady=None, title: str | None = None):
    """Lubrication state Θ against velocity (Heipl & Murrenhoff Fig. 6 style); None without
    a Θ state.

    Θ = 0 is dry (boundary) friction, Θ = 1 hydrodynamic.
    """
    with_theta = {k: r for k, r in results.items() if "theta" in r.state_names}
    if not with_theta:
        return None
    fig, ax = new_figure(width=6.4, height=4.4)
    vf, vl = _scale([r.velocity for r in with_theta.values()], "m/s")
    for name, r in with_theta.items():
        i = r.state_names.index("theta")
        ax.plot(r.velocity * vf, r.states[:, i], lw=1.2, label=name)
    _draw_steady(ax, with_theta, steady, vf, "steady Θ", jumps=False)
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel(f"sliding velocity v [{vl}]")
    ax.set_ylabel("lubrication state Θ [-]  (0 dry, 1 hydrodynamic)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    _title(ax, title)
    return fig


def plot_force_displacement(results, title: str | None = None):
    """Friction force against displacement (F–x loops, pre-sliding, Heipl & Murrenhoff
    Fig. 12/13)."""
    fig, ax = new_figure(width=6.4, height=4.4)
    xf, xl = _scale([r.position for r in results.values()], "m")
    for name, r in results.items():
        ax.plot(r.position * xf, r.force, lw=1.2, label=name)
    ax.axhline(0, color="0.7", lw=0.6)
    ax.set_xlabel(f"displacement x [{xl}]")
    ax.set_ylabel("friction force F [N]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    _title(ax, title)
    return fig


def plot_timeseries(results, title: str | None = None):
    """Velocity, friction force, displacement and states against time."""
    any_states = sorted({s for r in results.values() for s in r.state_names
                         if not s.startswith("z_")} | (
        {"z_i"} if any(s.startswith("z_") for r in results.values() for s in r.state_names)
        else set()))
    rows = 3 + len(any_states)
    fig, axes = new_figure(nrows=rows, width=7.0, height=1.9 * rows, sharex=True)
    axes = np.atleast_1d(axes)
    vf, vl = _scale([r.velocity for r in results.values()], "m/s")
    xf, xl = _scale([r.position for r in results.values()], "m")
    for name, r in results.items():
        line, = axes[0].plot(r.time, r.velocity * vf, lw=1.0, label=name)
        axes[1].plot(r.time, r.force, lw=1.0, color=line.get_color())
        if r.applied_force is not None:
            axes[1].plot(r.time, r.applied_force, lw=0.8, ls=":", color=line.get_color())
        axes[2].plot(r.time, r.position * xf, lw=1.0, color=line.get_color())
        for k, state in enumerate(any_states):
            ax = axes[3 + k]
            if state == "z_i":
                cols = [i for i, s in enumerate(r.state_names) if s.startswith("z_")]
                for c in cols:
                    ax.plot(r.time, r.states[:, c] * 1e6, lw=0.8, color=line.get_color())
            elif state in r.state_names:
                i = r.state_names.index(state)
                # the film's speed in the velocity panel's unit, so φ reads against |v|
                scale = {"z": 1e6, "film_speed": vf}.get(state, 1.0)
                ax.plot(r.time, r.states[:, i] * scale, lw=1.0, color=line.get_color())
    axes[0].set_ylabel(f"v [{vl}]")
    axes[1].set_ylabel("force [N]")
    axes[2].set_ylabel(f"x [{xl}]")
    for k, state in enumerate(any_states):
        label = {"theta": "film state Θ [-]", "z": "bristles z [µm]",
                 "z_i": "bristles z_i [µm]",
                 "film_speed": f"film formed for φ [{vl}]"}.get(state, state)
        axes[3 + k].set_ylabel(label)
    axes[-1].set_xlabel("time t [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    # legends above the panels, where they cover no curve (inside, the force legend hid the
    # spring force's minima); the colours name the runs, the line styles the forces
    axes[0].legend(fontsize=7, loc="lower left", bbox_to_anchor=(0.0, 1.0), frameon=False,
                   ncol=min(len(results), 5), borderaxespad=0.1)
    if any(r.applied_force is not None for r in results.values()):
        axes[1].legend(handles=[Line2D([], [], color="k", lw=1.0, label="friction"),
                                Line2D([], [], color="k", lw=0.8, ls=":",
                                       label="spring + applied")],
                       fontsize=7, loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=2,
                       frameon=False, borderaxespad=0.1)
    if title:
        fig.suptitle(title, fontsize=10)
    return fig
