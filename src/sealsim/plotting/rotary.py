"""Figures of rotary lip seal results (Organisciak et al. 2014, Fig. 9, Fig. 12 and a
Stribeck-type plot)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from sealsim.plotting import new_figure

__all__ = ["cycle_figure", "stribeck_figure", "variants_figure"]

_COLOURS = ["tab:red", "tab:blue", "tab:green", "tab:orange", "tab:purple", "tab:brown"]


def _minutes(frame: pd.DataFrame) -> np.ndarray:
    return frame["time_s"].to_numpy() / 60.0


def cycle_figure(frame: pd.DataFrame, shaft_radius: float, title: str = ""):
    """Speed | torque | temperatures | heat over time for one variant (the first three like
    Organisciak et al. 2014, Fig. 9).

    The torque panel splits the torque into its lubricant-shear and rubber parts (forces times
    the shaft radius [m]); the temperature panel shows the spring-groove temperature (the
    paper's thermocouple), the contact temperature and the sump in three colours and line
    styles, so lines that lie on top of each other (a groove in oil at the sump temperature)
    stay distinguishable; the heat panel shows the friction heat (with a bearing beside the
    seal, also what enters shaft and seal with its share) and where heat leaves shaft and
    seal (oil side, the seal's bore, air side; negative: heat coming in; in a warm-up the
    difference is stored).
    """
    fig, axes = new_figure(4, 1, width=17.0, height=4.0)
    t = _minutes(frame)
    axes[0].plot(t, frame["speed_rpm"], color="k")
    axes[0].set_ylabel("Speed [rpm]")
    axes[1].plot(t, frame["torque_Nm"], color="tab:red", lw=1.8, label="total")
    axes[1].plot(t, frame["F_lub_N"] * shaft_radius, color="tab:blue", lw=1, ls="--",
                 label="lubricant shear")
    axes[1].plot(t, frame["F_material_N"] * shaft_radius, color="tab:green", lw=1, ls=":",
                 label="rubber (material)")
    axes[1].legend(loc="best", fontsize=8)
    axes[1].set_ylabel("Friction torque [N m]")
    axes[1].set_ylim(bottom=0)
    axes[2].plot(t, frame["T_contact_C"], color="tab:orange", lw=1.4, ls="--", label="contact")
    axes[2].plot(t, frame["T_groove_C"], color="tab:red", lw=2.4, alpha=0.8,
                 label="spring groove")
    axes[2].plot(t, frame["T_sump_C"], color="tab:blue", lw=1.2, ls="-.", label="oil sump",
                 zorder=3)
    axes[2].set_ylabel("Temperature [°C]")
    axes[2].legend(loc="best", fontsize=8)
    axes[3].plot(t, frame["power_W"], color="k", lw=1.8, label="seal friction heat")
    if frame["bearing_to_shaft_W"].any():
        axes[3].plot(t, frame["power_W"] + frame["bearing_to_shaft_W"], color="0.4", lw=1.4,
                     label="in: seal + bearing into the shaft")
    for column, colour, style, label in (
            ("heat_oil_side_W", "tab:blue", "-", "out: oil side"),
            ("heat_air_side_W", "tab:orange", "--", "out: air side"),
            ("heat_housing_W", "tab:green", ":", "out: seal bore")):
        axes[3].plot(t, frame[column], color=colour, lw=1.3, ls=style, label=label)
    axes[3].axhline(0.0, color="0.5", lw=0.8)
    axes[3].set_ylabel("Heat [W]")
    axes[3].legend(loc="best", fontsize=8)
    for ax in axes:
        ax.set_xlabel("Time [min]")
        ax.grid(True, alpha=0.3)
    if title:
        fig.suptitle(title)
    return fig


def variants_figure(frames: dict[str, pd.DataFrame], title: str = ""):
    """Speed, torque and temperatures of all variants (like Organisciak et al. 2014, Fig. 12/13)."""
    fig, axes = new_figure(3, 1, width=14.0, height=4.2)
    for k, (name, frame) in enumerate(frames.items()):
        colour = _COLOURS[k % len(_COLOURS)]
        t = _minutes(frame)
        axes[0].plot(t, frame["speed_rpm"], color=colour, lw=1.6, ls=["-", "--", ":"][k % 3],
                     label=name)
        axes[1].plot(t, frame["torque_Nm"], color=colour, lw=1.6, label=name)
        axes[2].plot(t, frame["T_groove_C"], color=colour, lw=1.6, label=f"{name}: groove")
        axes[2].plot(t, frame["T_contact_C"], color=colour, lw=1.0, ls="--",
                     label=f"{name}: contact")
    axes[0].set_ylabel("Speed [rpm]")
    axes[1].set_ylabel("Friction torque [N m]")
    axes[1].set_ylim(bottom=0)
    axes[2].set_ylabel("Temperature [°C]")
    for ax in axes:
        ax.set_xlabel("Time [min]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    if title:
        fig.suptitle(title)
    return fig


def stribeck_figure(frames: dict[str, pd.DataFrame], curves: dict[str, pd.DataFrame],
                    title: str = ""):
    """Effective friction coefficient μ_eff = F_friction/F_radial against G = η·ω·b/W'.

    Lines: the friction model at constant contact temperatures over a speed sweep (``curves``:
    per variant a frame with T_contact_C, duty_parameter, mu_eff); dots: the operating points
    the simulated duty cycle went through.
    """
    fig, ax = new_figure(1, 1, width=7.0, height=4.8)
    styles = ["-", "--", ":", "-."]
    for k, (name, frame) in enumerate(frames.items()):
        colour = _COLOURS[k % len(_COLOURS)]
        for j, (temp, curve) in enumerate(curves[name].groupby("T_contact_C")):
            ax.plot(curve["duty_parameter"], curve["mu_eff"], color=colour,
                    ls=styles[j % len(styles)], lw=1.2, label=f"{name}, {temp:.0f} °C")
        moving = frame["speed_rpm"] > 0
        ax.scatter(frame.loc[moving, "duty_parameter"], frame.loc[moving, "mu_eff"], s=5,
                   color=colour, alpha=0.6, zorder=3, label=f"{name}: duty cycle")
    ax.set_xscale("log")
    ax.set_xlabel(r"Duty parameter $G = \eta\,\omega\,b / W'$ [-]")
    ax.set_ylabel(r"$\mu_{eff} = F_{friction} / F_{radial}$ [-]")
    ax.set_ylim(bottom=0)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    ax.set_title(title or "Stribeck-type curve of the lip contact (speed 1-3000 rpm)")
    return fig
