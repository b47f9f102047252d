"""Figure of a seal's friction from its own contact: contact pressure p_c(z), film h(z) and
the Stribeck curve per pressure (drawing only; the numbers come from
:mod:`sealsim.pneumatic.friction_tables`)."""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.ticker import LogFormatter

from sealsim.plotting import celsius_text, new_figure

__all__ = ["contact_friction_figure"]


def contact_friction_figure(profiles, table, diameter: float, temperature: float,
                            boundary_friction: float, speed: float, seal_name: str = ""):
    """Three panels: p_c(z) per pressure; h(z) of both strokes at ``speed``; the steady
    friction over speed per pressure (solid: + stroke, dashed: − stroke).

    Parameters
    ----------
    profiles : list
        ``film_profiles(...)`` output: (Δp [Pa], z [m], p [Pa], h_+ [m], h_− [m]) per pressure.
    table : SteadyFrictionTable
        The seal's friction table.
    diameter : float
        Sliding diameter D [m].
    temperature : float
        Seal temperature [K].
    boundary_friction : float
        μ_b [-].
    speed : float
        Speed of the film panel [m/s].
    seal_name : str
        The seal's name in the figure title.

    The pressures' colours are named in the first and the last panel; the film panel's legend
    names the line styles of the strokes (one entry per pressure and stroke covered its
    curves).
    """
    fig, axes = new_figure(3, 1, width=15.0, height=4.6)
    colors = [f"C{k}" for k in range(len(profiles))]
    for (dp, z, p, h_pos, h_neg), c in zip(profiles, colors):
        label = f"{dp / 1e5:g} bar"
        axes[0].plot(z * 1e3, p / 1e6, color=c, label=label)
        axes[1].plot(z * 1e3, np.where(np.isfinite(h_pos), h_pos * 1e6, np.nan), color=c)
        axes[1].plot(z * 1e3, np.where(np.isfinite(h_neg), h_neg * 1e6, np.nan), color=c,
                     ls="--")
        u = table.speed
        for sign, ls in ((1.0, "-"), (-1.0, "--")):
            force = np.abs(table.steady_force(sign * u, dp, temperature, diameter,
                                              boundary_friction))
            axes[2].plot(u, force, color=c, ls=ls, label=label if sign > 0 else None)
    axes[0].set(xlabel="axial position z [mm] (pressurised side z < 0)",
                ylabel="contact pressure p_c [MPa]", title="contact pressure profile")
    axes[1].set(xlabel="axial position z [mm]", ylabel="film h [µm]", yscale="log",
                title=f"inverse-hydrodynamic film at {speed:g} m/s")
    axes[2].set(xlabel="sliding speed [m/s]", ylabel="steady friction [N]", xscale="log",
                title="Stribeck curve (solid + stroke, dashed − stroke)")
    axes[1].yaxis.set_major_formatter(LogFormatter(labelOnlyBase=False))  # 3, not 3×10⁰
    axes[1].yaxis.set_minor_formatter(LogFormatter(labelOnlyBase=False,
                                                   minor_thresholds=(2, 0.5)))
    axes[1].legend(handles=[Line2D([], [], color="k", label="+ stroke"),
                            Line2D([], [], color="k", ls="--", label="− stroke")],
                   fontsize=7, title="colours: pressures", title_fontsize=7)
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7)
    axes[2].legend(fontsize=7)
    name = f"seal {seal_name!r}: " if seal_name else ""
    fig.suptitle(f"{name}friction from its contact at {celsius_text(temperature)}")
    return fig
