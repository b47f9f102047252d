"""Figures of pneumatic cylinder results (Heipl & Murrenhoff Fig. 10, Figs. 12/13, friction vs
velocity).

All functions read the ``timeseries`` frames of :class:`sealsim.pneumatic.PneumaticResult`
(columns ``time_s``, ``x_m``, ``v_m_s``, ``p1_bar_abs``, ``p2_bar_abs``, ``F_friction_N``, per
seal ``F_<seal>_N``, ``F_N_<seal>_N``, ``theta_<seal>``, ``T_<seal>_C``) and return pyplot-free
figures.  A prescribed-position run (friction rig) starts from a dry, relaxed seal: its first
period is drawn apart ("start-up") so that the loops show the periodic state.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from sealsim.pneumatic.results import column_name
from sealsim.plotting import new_figure

__all__ = ["friction_stroke_figure", "friction_velocity_figure", "heating_figure",
           "pressure_stroke_figure", "timeseries_figure"]

_COLOURS = ["tab:blue", "tab:red", "tab:green", "tab:orange", "tab:purple", "tab:brown"]


def _colour(k: int) -> str:
    return _COLOURS[k % len(_COLOURS)]


def pressure_stroke_figure(frames: dict[str, pd.DataFrame], title: str = ""):
    """Chamber pressures and stroke against time, all variants (like Heipl & Murrenhoff
    Fig. 10).

    Upper panel: p1 (cap side, solid) and p2 (rod side, dashed) [bar abs]; lower panel: piston
    position [mm]; the valve command is shaded in the lower panel (extend: grey).
    """
    fig, axes = new_figure(1, 2, width=8.0, height=6.0, sharex=True)
    ax_p, ax_x = axes
    for k, (name, f) in enumerate(frames.items()):
        c = _colour(k)
        t = f["time_s"].to_numpy()
        ax_p.plot(t, f["p1_bar_abs"], color=c, lw=1.4, label=f"{name}: p1 (cap side)")
        ax_p.plot(t, f["p2_bar_abs"], color=c, lw=1.2, ls="--", label=f"{name}: p2 (rod side)")
        ax_x.plot(t, f["x_m"] * 1e3, color=c, lw=1.6, label=name)
    first = next(iter(frames.values()))
    t = first["time_s"].to_numpy()
    extend = first["valve_command"].to_numpy() > 0
    ax_x.fill_between(t, 0, 1, where=extend, color="0.85", alpha=0.6, lw=0,
                      transform=ax_x.get_xaxis_transform(), label="valve: extend")
    ax_p.set_ylabel("Chamber pressure [bar abs]")
    ax_x.set_ylabel("Stroke x [mm]")
    ax_x.set_xlabel("Time [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        _legend_outside(ax, ncol=1)
    if title:
        fig.suptitle(title)
    return fig


def _legend_outside(ax, **kwargs) -> None:
    """The legend right of the panel, where it covers no curve (inside, over the pressure
    plateaus and end positions, it did)."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, fontsize=7,
              **kwargs)


def _legend_above(ax) -> None:
    """The legend in one row on top of the panel (right of it stands the velocity axis)."""
    ax.legend(loc="lower right", bbox_to_anchor=(1.0, 1.0), borderaxespad=0.1, fontsize=7,
              ncol=len(ax.get_legend_handles_labels()[0]), frameon=False)


def _start_up(f: pd.DataFrame, period: float | None):
    """Mask of the samples in the first period of a periodic (prescribed) motion."""
    t = f["time_s"].to_numpy()
    if not period:
        return np.zeros(t.shape, dtype=bool)
    return t < t[0] + period


def friction_stroke_figure(frames: dict[str, pd.DataFrame], strokes: dict[str, float] | None
                           = None, title: str = "", periods: dict[str, float] | None = None):
    """Friction force against stroke, one panel per variant (like Heipl & Murrenhoff
    Figs. 12/13).

    The total friction of all seals (positive against extension); the loop is run clockwise:
    positive friction while extending, negative while retracting.  Only samples where the
    piston moves (|v| > 1 mm/s) are drawn with a line, so that the rests at the end stops do not
    add vertical strokes.  With ``periods`` (prescribed motion) the first period is drawn thin
    and grey as the start-up from the dry seal.
    """
    n = len(frames)
    fig, axes = new_figure(n, 1, width=4.2 * n + 0.8, height=4.2, sharey=True, squeeze=False)
    for k, (name, f) in enumerate(frames.items()):
        ax = axes[0][k]
        x = f["x_m"].to_numpy() * 1e3
        friction = f["F_friction_N"].to_numpy().copy()
        moving = np.abs(f["v_m_s"].to_numpy()) > 1e-3
        friction[~moving] = np.nan
        first = _start_up(f, (periods or {}).get(name))
        if first.any():
            ax.plot(x[first], friction[first], color="0.65", lw=0.9, ls="--",
                    label="start-up (first period)")
            friction[first] = np.nan
        ax.plot(x, friction, color=_colour(k), lw=1.4, label="simulated (all seals)")
        ax.axhline(0.0, color="0.6", lw=0.7)
        ax.set_xlabel("Stroke x [mm]")
        ax.set_title(name, fontsize=10)
        ax.grid(True, alpha=0.3)
        if strokes and name in strokes:
            ax.set_xlim(-0.03 * strokes[name] * 1e3, 1.03 * strokes[name] * 1e3)
    axes[0][0].set_ylabel("Friction force [N]")
    axes[0][0].legend(loc="best", fontsize=8)
    if title:
        fig.suptitle(title)
    return fig


def friction_velocity_figure(frames: dict[str, pd.DataFrame], title: str = "",
                             periods: dict[str, float] | None = None,
                             strokes: dict[str, float] | None = None):
    """Total friction force against piston velocity, all variants (the dynamic F–v loops of
    Heipl & Murrenhoff Fig. 2/3 as the cylinder runs through them); the start-up period of a
    prescribed motion is left out (see :func:`friction_stroke_figure`).

    The line is broken where the samples do not resolve the motion (:func:`_line_breaks`):
    where the piston enters or leaves an end stop (with ``strokes``) and where the velocity or
    the friction jumps between two samples, so an impact does not draw a straight line across
    the plot.
    """
    fig, ax = new_figure(width=6.6, height=4.6)
    for k, (name, f) in enumerate(frames.items()):
        keep = ~_start_up(f, (periods or {}).get(name))
        v = f["v_m_s"].to_numpy()[keep]
        friction = f["F_friction_N"].to_numpy()[keep]
        stroke = (strokes or {}).get(name)
        breaks = _line_breaks(v, friction, None if stroke is None else f["x_m"].to_numpy()[keep],
                              stroke)
        ax.plot(np.insert(v, breaks, np.nan), np.insert(friction, breaks, np.nan),
                color=_colour(k), lw=1.0, label=name)
    ax.axhline(0.0, color="0.6", lw=0.7)
    ax.axvline(0.0, color="0.6", lw=0.7)
    ax.set_xlabel("Piston velocity v [m/s]")
    ax.set_ylabel("Friction force [N]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    return fig


#: a change of velocity or friction between two samples larger than this share of the run's
#: span is a jump the samples do not resolve (an impact, a reversal): a line is broken there
JUMP_SHARE = 0.1


def _line_breaks(v: np.ndarray, friction: np.ndarray, x: np.ndarray | None = None,
                 stroke: float | None = None):
    """Indices i where a line through the (v, F) samples must not join sample i − 1 to i: the
    piston enters or leaves an end stop (x < 0 or x > stroke, the bumpers), or v or F jumps by
    more than :data:`JUMP_SHARE` of its span (for ``np.insert(values, breaks, np.nan)``)."""
    jump = np.zeros(max(v.size - 1, 0), dtype=bool)
    for values in (v, friction):
        if values.size:
            jump |= np.abs(np.diff(values)) > JUMP_SHARE * float(np.ptp(values))
    if x is not None and stroke is not None:
        in_stop = (x < 0.0) | (x > stroke)
        jump |= in_stop[1:] != in_stop[:-1]
    return np.flatnonzero(jump) + 1


def timeseries_figure(frame: pd.DataFrame, seal_names: list[str], title: str = ""):
    """Everything of one variant against time: stroke and velocity, pressures, air
    temperatures, friction per seal, normal force per seal, Θ per seal and (seal heating) the
    seal, tube and rod temperatures.  ``seal_names``: the seals' names (or column names)."""
    seal_names = [column_name(n) for n in seal_names]
    thetas = [n for n in seal_names if f"theta_{n}" in frame]
    loads = [n for n in seal_names if f"F_N_{n}_N" in frame]
    heated = [n for n in seal_names if f"T_{n}_C" in frame]
    rows = 4 + (1 if loads else 0) + (1 if thetas else 0) + (1 if heated else 0)
    fig, axes = new_figure(1, rows, width=8.0, height=1.9 * rows + 0.6, sharex=True)
    axes = np.atleast_1d(axes)
    t = frame["time_s"].to_numpy()
    ax = axes[0]
    ax.plot(t, frame["x_m"] * 1e3, color="k", lw=1.4, label="x [mm]")
    ax.set_ylabel("Stroke [mm]")
    twin = ax.twinx()
    twin.plot(t, frame["v_m_s"], color="tab:gray", lw=0.9, label="v")
    twin.set_ylabel("v [m/s]", color="tab:gray")
    axes[1].plot(t, frame["p1_bar_abs"], color="tab:blue", lw=1.3, label="p1 (cap side)")
    axes[1].plot(t, frame["p2_bar_abs"], color="tab:red", lw=1.3, label="p2 (rod side)")
    axes[1].set_ylabel("Pressure [bar abs]")
    axes[2].plot(t, frame["T1_C"], color="tab:blue", lw=1.2, label="T1 (cap side)")
    axes[2].plot(t, frame["T2_C"], color="tab:red", lw=1.2, label="T2 (rod side)")
    axes[2].set_ylabel("Air temp. [°C]")
    axes[3].plot(t, frame["F_friction_N"], color="k", lw=1.3, label="total")
    for k, n in enumerate(seal_names):
        axes[3].plot(t, frame[f"F_{n}_N"], color=_colour(k), lw=0.9, label=n)
    axes[3].set_ylabel("Friction [N]")
    row = 4
    if loads:
        for k, n in enumerate(loads):
            axes[row].plot(t, frame[f"F_N_{n}_N"], color=_colour(seal_names.index(n)), lw=1.1,
                           label=n)
        axes[row].set_ylabel("Normal force F_N [N]")
        row += 1
    if thetas:
        for n in thetas:
            axes[row].plot(t, frame[f"theta_{n}"], color=_colour(seal_names.index(n)), lw=1.1,
                           label=n)
        axes[row].set_ylabel("Θ [-] (0 dry)")
        axes[row].set_ylim(-0.02, 1.02)
        row += 1
    if heated:
        for n in heated:
            axes[row].plot(t, frame[f"T_{n}_C"], color=_colour(seal_names.index(n)), lw=1.1,
                           label=n)
        axes[row].plot(t, frame["T_tube_metal_C"], color="0.4", lw=1.0, ls="--", label="tube")
        axes[row].plot(t, frame["T_rod_metal_C"], color="0.4", lw=1.0, ls=":", label="rod")
        axes[row].set_ylabel("Temperature [°C]")
    axes[-1].set_xlabel("Time [s]")
    for a in axes:
        a.grid(True, alpha=0.3)
        _legend_above(a)
    if title:
        fig.suptitle(title)
    return fig


def heating_figure(frame: pd.DataFrame, strokes: pd.DataFrame, seal_names: list[str],
                   title: str = ""):
    """A long duty cycle with seal heating: temperatures of the seals, the tube and the rod
    against time; the mean friction and the stroke time of every stroke (``strokes``:
    :func:`sealsim.pneumatic.summary.per_stroke`), extending and retracting apart."""
    seal_names = [column_name(n) for n in seal_names]
    fig, axes = new_figure(1, 3, width=8.0, height=8.0, sharex=True)
    t = frame["time_s"].to_numpy()
    ax = axes[0]
    for k, n in enumerate(seal_names):
        if f"T_{n}_C" in frame:
            ax.plot(t, frame[f"T_{n}_C"], color=_colour(k), lw=1.3, label=f"seal {n}")
    # the metal on top: each seal follows its counterface within a few tenths of a kelvin
    ax.plot(t, frame["T_tube_metal_C"], color="k", lw=0.9, ls="--", label="tube", zorder=3)
    ax.plot(t, frame["T_rod_metal_C"], color="k", lw=0.9, ls=":", label="piston + rod",
            zorder=3)
    ax.set_ylabel("Temperature [°C]")
    for direction, name, marker in ((1, "extend", "o"), (-1, "retract", "s")):
        rows = strokes[strokes["direction"] == direction]
        axes[1].plot(rows["start_s"], rows["mean_friction_N"], marker, ms=2.5, ls="-", lw=0.8,
                     color=_colour(0 if direction > 0 else 1), label=name)
        axes[2].plot(rows["start_s"], rows["stroke_time_s"] * 1e3, marker, ms=2.5, ls="-",
                     lw=0.8, color=_colour(0 if direction > 0 else 1), label=name)
    axes[1].set_ylabel("Mean friction over\nthe distance slid [N]")
    axes[2].set_ylabel("Stroke time [ms]")
    axes[2].set_xlabel("Time [s]")
    for a in axes:
        a.grid(True, alpha=0.3)
        a.legend(loc="best", fontsize=7, ncol=2)
    if title:
        fig.suptitle(title)
    return fig
