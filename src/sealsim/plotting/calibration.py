"""Figures of fits against measurements: overlays (friction vs time and vs stroke; a rotary
speed cycle like Fig. 9 of Organisciak et al., SKF, AGMA 14FTM14, 2014), the parity plot of
measured vs predicted levels with a ±20 % band (in the style of their Fig. 10) and the scatter
of repeated tests against the model."""

from __future__ import annotations

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg

from sealsim.calibration.statistics import compare_signals
from sealsim.plotting import new_figure

__all__ = ["plot_overlay", "plot_parity", "plot_repeats", "plot_rotary_overlay", "plot_signals"]


def plot_overlay(name: str, role: str, time, position, measured, predicted, title: str = ""):
    """Measured and model friction of one run: vs time (left) and vs stroke (right).

    Parameters
    ----------
    time, position : array_like
        [s], [m].
    measured, predicted : array_like
        Offset-free friction [N].
    """
    fig, (ax_t, ax_x) = new_figure(2, 1, width=11.0, height=4.0)
    t = np.asarray(time)
    x = np.asarray(position) * 1e3
    ax_t.plot(t, measured, lw=0.7, color="0.45", label="measured")
    ax_t.plot(t, predicted, lw=1.0, color="C3", label="model")
    ax_t.set_xlabel("time [s]")
    ax_t.set_ylabel("friction force [N]")
    ax_t.legend(loc="best")
    ax_x.plot(x, measured, lw=0.5, color="0.45", label="measured")
    ax_x.plot(x, predicted, lw=0.8, color="C3", label="model")
    ax_x.set_xlabel("position [mm]")
    ax_x.set_ylabel("friction force [N]")
    for ax in (ax_t, ax_x):
        ax.axhline(0.0, color="k", lw=0.5)
        ax.grid(alpha=0.3)
    kind = "fitted" if role == "fit" else "predicted (not fitted)"
    fig.suptitle(f"{title}\n{name}: {kind}" if title else f"{name}: {kind}")
    return fig


def plot_repeats(conditions: dict, measurements: dict, title: str = ""):
    """Repeated tests: each condition's measured levels (one dot per run, filled if fitted),
    their mean ± one standard deviation of a single run, and the model's prediction.

    Parameters
    ----------
    conditions : dict
        report.json ``conditions`` (:func:`sealsim.calibration.study.repeat_conditions`).
    measurements : dict
        report.json ``measurements`` (the runs' measured and predicted levels [N]).
    """
    fig, ax = new_figure(1, 1, width=max(5.0, 1.1 * len(conditions) + 2.5), height=4.5)
    for k, (name, c) in enumerate(conditions.items()):
        runs = [measurements[m] for m in c["measurements"]]
        spread = np.linspace(-0.15, 0.15, len(runs)) if len(runs) > 1 else np.zeros(1)
        for dx, run, role in zip(spread, runs, c["roles"]):
            ax.plot(k + dx, run["F_measured_N"], "o", color="0.3",
                    mfc="0.3" if role == "fit" else "white", zorder=3)
            ax.plot(k + dx, run["F_predicted_N"], "x", color="C3", zorder=4)
        if c["F_measured_std_N"] is not None:
            ax.errorbar(k + 0.3, c["F_measured_mean_N"], yerr=c["F_measured_std_N"], fmt="s",
                        color="C0", capsize=4, zorder=2)
    ax.plot([], [], "o", color="0.3", label="measured run (filled: fitted)")
    ax.plot([], [], "x", color="C3", label="model, same run")
    ax.errorbar([], [], yerr=[], fmt="s", color="C0", capsize=4,
                label="mean ± 1 std of a run")
    ax.set_xticks(range(len(conditions)))
    ax.set_xticklabels(list(conditions), rotation=20, ha="right", fontsize=8)
    ax.set_ylabel("friction level [N]")
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(f"{title}\nrepeated tests" if title else "repeated tests", fontsize=10)
    return fig


def plot_stroke_levels(runs: dict, title: str = "", limit: float = 0.10):
    """Friction level per pair of strokes along each run, each line relative to its own median
    (measured: solid, the model on the same run: dashed; the level itself is the parity
    plot's), so that a run whose friction climbs or falls over its strokes stands out from the
    steady ones. The runs whose measured level
    changes by more than ``limit`` from their first to their last quarter of pairs are drawn
    in colour and named; the others are grey.

    Parameters
    ----------
    runs : dict
        ``{name: (measured levels [N], model levels [N], drift_measured [-])}`` per run, the
        levels of :func:`sealsim.measurements.stroke_levels` in time order.
    """
    fig, ax = new_figure(1, 1, width=6.5, height=4.5)
    colour = 0
    for name, (measured, model, drift) in runs.items():
        measured, model = np.asarray(measured, float), np.asarray(model, float)
        if measured.size < 2 or not np.median(measured):
            continue
        scale = np.median(measured)
        pairs = np.arange(1, measured.size + 1)
        drifting = drift is not None and abs(drift) > limit
        style = {"color": f"C{colour % 10}", "lw": 1.5, "zorder": 3} if drifting else \
            {"color": "0.7", "lw": 0.8, "zorder": 2}
        ax.plot(pairs, measured / scale, "-", **style,
                label=f"{name} ({100 * drift:+.0f} %)" if drifting else None)
        if model.size == measured.size and np.median(model):
            ax.plot(pairs, model / np.median(model), "--", **{**style, "lw": 0.8})
        colour += drifting
    ax.plot([], [], "-", color="0.7", lw=0.8,
            label=f"runs within ±{100 * limit:.0f} % (measured)")
    ax.plot([], [], "--", color="0.4", lw=0.8, label="model on the same run")
    ax.axhline(1.0, color="0.3", lw=0.6)
    ax.xaxis.get_major_locator().set_params(integer=True)
    ax.set_xlabel("pair of strokes")
    ax.set_ylabel("friction level / its median over the run [-]")
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=7)
    head = "friction level along each run (offset-free per pair of strokes)"
    ax.set_title(f"{title}\n{head}" if title else head, fontsize=10)
    return fig


def plot_fitted_steady_curves(curves, run_speeds, measured_levels: dict, title: str = ""):
    """The fitted law's steady friction over speed, one panel per seal, one colour per pressure
    (solid: + stroke, dashed: − stroke), the contact force F_N as a dotted line of the same
    colour (F = F_N, μ_eff = 1), the measured runs' levels as points at their speeds, and the
    measured speed range shaded: how far the fitted curve is carried beyond the data.

    Parameters
    ----------
    curves, run_speeds : pandas.DataFrame
        :func:`sealsim.calibration.study.fitted_steady_curves`.
    measured_levels : dict
        ``{measurement: friction level [N]}``.
    """
    contacts = list(dict.fromkeys(curves["contact"]))
    fig, axes = new_figure(len(contacts), 1, width=4.2 * len(contacts) + 0.6, height=4.4,
                           squeeze=False, sharey=True)
    lo, hi = run_speeds["speed_m_s"].min(), run_speeds["speed_m_s"].max()
    for ax, contact in zip(axes[0], contacts):
        ax.axvspan(lo, hi, color="0.9", zorder=0)
        own = curves[curves["contact"] == contact]
        for k, (bar, c) in enumerate(own.groupby("pressure_bar", sort=True)):
            colour = f"C{k}"
            ax.plot(c["speed_m_s"], c["F_plus_N"], "-", color=colour, label=f"{bar:g} bar")
            ax.plot(c["speed_m_s"], c["F_minus_N"], "--", color=colour, lw=0.9)
            ax.axhline(c["F_normal_N"].iloc[0], color=colour, ls=":", lw=0.8)
            runs = run_speeds[(run_speeds["contact"] == contact)
                              & (run_speeds["pressure_bar"] == bar)]
            ax.plot(runs["speed_m_s"], [measured_levels[m] for m in runs["measurement"]],
                    "o", color=colour, ms=4, mec="k", mew=0.5)
        ax.set(xscale="log", yscale="log", xlabel="sliding speed [m/s]", title=contact)
        ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("steady friction [N]")
    axes[0][0].plot([], [], "k-", label="fitted law, + stroke")
    axes[0][0].plot([], [], "k--", lw=0.9, label="fitted law, − stroke")
    axes[0][0].plot([], [], "k:", lw=0.8, label="contact force F_N (F/F_N = 1)")
    axes[0][0].plot([], [], "o", color="0.5", mec="k", mew=0.5, ms=4,
                    label="measured level at the run's speed")
    axes[0][0].fill_between([], [], color="0.9", label="measured speeds")
    axes[0][0].legend(loc="upper left", fontsize=7)
    head = "the fitted law's steady friction beyond the measured speeds"
    fig.suptitle(f"{title}\n{head}" if title else head, fontsize=10)
    return fig


def _labelled(points, band: float, absolute_band: float | None, most: int = 6) -> list:
    """The points of a parity plot worth a label: all of up to ``most``; beyond that those
    outside the band, the ``most`` farthest from it first (more labels would cover each other;
    :func:`plot_parity` drops a label that still covers one before it)."""
    if len(points) <= most:
        return list(points)

    def excess(point):
        _, _, m, p = point
        half = band * abs(m) if absolute_band is None else absolute_band
        return abs(p - m) - half

    outside = [pt for pt in points if excess(pt) > 0]
    return sorted(outside, key=excess, reverse=True)[:most]


def plot_parity(points, title: str = "", quantity: str = "friction level", unit: str = "N",
                band: float = 0.2, absolute_band: float | None = None,
                band_unit: str | None = None, annotate: bool = True,
                reference=None, reference_label: str = "reference"):
    """Predicted vs measured with the ±``band`` relative band and R².

    Parameters
    ----------
    points : list of (label, role, measured, predicted)
        One point per measurement (or step); role "fit" or "validate".
    absolute_band : float, optional
        A band of ± this value (in ``unit``) instead of the relative one; the axes then span
        the data instead of starting at 0 (temperatures).
    band_unit : str, optional
        Unit shown for the absolute band (default ``unit``; "K" for a band in °C).
    annotate : bool
        Write the points' labels next to them: every label up to six points, beyond that the
        six farthest outside the band (more would cover each other).
    reference : list of (measured, predicted), optional
        A simpler model's predictions of the same measurements, drawn as hollow diamonds
        (``reference_label`` in the legend; R² stays that of ``points``).
    """
    fig, ax = new_figure(1, 1, width=5.5, height=5.0)
    meas = np.array([p[2] for p in points], dtype=float)
    pred = np.array([p[3] for p in points], dtype=float)
    ref = np.array(reference if reference else np.zeros((0, 2)), dtype=float).reshape(-1, 2)
    if absolute_band is None:
        bottom = 0.0
        top = 1.15 * max(float(np.max(meas)), float(np.max(pred)),
                         float(np.max(ref)) if ref.size else 0.0, 1e-12)
    else:
        low = min(float(np.min(meas)), float(np.min(pred)))
        high = max(float(np.max(meas)), float(np.max(pred)))
        margin = max(0.08 * (high - low), 2 * absolute_band)
        bottom, top = low - margin, high + margin
    line = np.array([bottom, top])
    ax.plot(line, line, "k-", lw=0.8, label="1:1")
    if absolute_band is None:
        ax.fill_between(line, (1 - band) * line, (1 + band) * line, color="C0", alpha=0.12,
                        label=f"±{100 * band:g} %")
    else:
        ax.fill_between(line, line - absolute_band, line + absolute_band, color="C0",
                        alpha=0.12, label=f"±{absolute_band:g} {band_unit or unit}")
    for role, marker, color in (("fit", "o", "C0"), ("validate", "s", "C3")):
        sel = [i for i, p in enumerate(points) if p[1] == role]
        if sel:
            ax.scatter(meas[sel], pred[sel], marker=marker, color=color, zorder=3,
                       label="fitted" if role == "fit" else "validation (not fitted)")
    if ref.size:
        ax.scatter(ref[:, 0], ref[:, 1], marker="D", facecolors="none", edgecolors="0.35",
                   zorder=2, label=reference_label)
    notes = [ax.annotate(str(label), (m, p), textcoords="offset points", xytext=(5, -10),
                         fontsize=8)
             for label, _, m, p in (_labelled(points, band, absolute_band) if annotate else ())]
    r2 = compare_signals(meas, pred)["r2"]
    r2 = float("nan") if r2 is None else r2
    ax.set_xlim(bottom, top)
    ax.set_ylim(bottom, top)
    ax.set_aspect("equal")
    ax.set_xlabel(f"measured {quantity} [{unit}]")
    ax.set_ylabel(f"predicted {quantity} [{unit}]")
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=8)          # not over a point far off the 1:1 line
    ax.set_title((f"{title}\n" if title else "") + _r2_text(r2, points) if np.isfinite(r2)
                 else title)
    _drop_covered(fig, notes)
    return fig


def _drop_covered(fig, notes) -> None:
    """Remove each label that would print over one kept before it (the labels come farthest
    outside the band first): close points' labels overlapped into an unreadable smear."""
    FigureCanvasAgg(fig)                     # a renderer to measure the texts with
    fig.draw_without_rendering()            # the final (constrained) layout
    renderer = fig.canvas.get_renderer()
    kept = []
    for note in notes:
        box = note.get_window_extent(renderer)
        if any(box.overlaps(other) for other in kept):
            note.remove()
        else:
            kept.append(box)


def _r2_text(r2: float, points) -> str:
    """R² with what it is taken over: a pooled R² of fitted and held-out points, or of two
    points, read alone looks like a validation score it is not.

    >>> _r2_text(0.98, [("a", "fit", 1, 1), ("b", "validate", 2, 2), ("c", "fit", 3, 3)])
    'R² = 0.980 over all 3 points, fitted and not fitted'
    """
    roles = {p[1] for p in points}
    which = {frozenset({"fit"}): "fitted", frozenset({"validate"}): "not fitted"}.get(
        frozenset(roles), "fitted and not fitted")
    return f"R² = {r2:.3f} over all {len(points)} points, {which}"


def plot_signals(time, curves, title: str = ""):
    """Measured and model signals over time, one panel each.

    Parameters
    ----------
    time : array_like
        [s].
    curves : dict of name -> (measured, model, unit)
        Signals in display units.
    """
    fig, axes = new_figure(1, len(curves), width=8.0, height=2.4 * len(curves), sharex=True,
                           squeeze=False)
    for ax, (name, (meas, model, unit)) in zip(axes[:, 0], curves.items()):
        ax.plot(time, meas, lw=0.8, color="0.45", label="measured")
        ax.plot(time, model, lw=1.0, color="C3", label="model")
        ax.set_ylabel(f"{name.replace('_', ' ')} [{unit}]")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(loc="best")
    axes[-1, 0].set_xlabel("time [s]")
    if title:
        fig.suptitle(title)
    return fig


def plot_rotary_overlay(name: str, role: str, time, measured, model, steps, title: str = ""):
    """Speed | torque | spring-groove temperature of one rotary run over time, measured and
    model (like Organisciak et al., AGMA 14FTM14, 2014, Fig. 9), with the step averages compared.

    Parameters
    ----------
    time : array_like
        Measured sample times [s].
    measured : dict
        ``speed_rpm``, ``torque_Nm`` and (optional) ``T_groove_C`` at the samples.
    model : pandas.DataFrame
        The simulation's time series (``time_s``, ``speed_rpm``, ``torque_Nm``,
        ``T_groove_C``).
    steps : list of dict
        Per step ``t_mid_s`` (middle of its averaging window) and the measured and predicted
        averages ``torque_measured_Nm``, ``torque_predicted_Nm``, ``T_groove_measured_C``,
        ``T_groove_predicted_C``.
    """
    fig, axes = new_figure(3, 1, width=13.0, height=4.0)
    t = np.asarray(time) / 60.0
    tm = model["time_s"].to_numpy() / 60.0
    t_steps = np.array([s["t_mid_s"] for s in steps]) / 60.0
    panels = [("speed_rpm", "Speed [rpm]", None),
              ("torque_Nm", "Friction torque [N m]", ("torque_measured_Nm",
                                                      "torque_predicted_Nm")),
              ("T_groove_C", "Spring-groove temperature [°C]", ("T_groove_measured_C",
                                                                "T_groove_predicted_C"))]
    for ax, (column, label, averages) in zip(axes, panels):
        if column in measured:
            ax.plot(t, measured[column], color="0.55", lw=0.6, label="measured")
        ax.plot(tm, model[column], color="tab:red", lw=1.4,
                label="model duty" if averages is None else "model")
        if averages is not None and steps and averages[0] in steps[0]:
            ax.plot(t_steps, [s[averages[0]] for s in steps], "ko", ms=4,
                    label="measured, last-30-s average")
            ax.plot(t_steps, [s[averages[1]] for s in steps], "x", color="tab:red", ms=7,
                    mew=1.6, label="model, same window")
        ax.set_ylabel(label)
        ax.set_xlabel("Time [min]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    axes[1].set_ylim(bottom=0)
    kind = "fitted" if role == "fit" else "predicted (not fitted)"
    fig.suptitle(f"{title}\n{name}: {kind}" if title else f"{name}: {kind}")
    return fig
