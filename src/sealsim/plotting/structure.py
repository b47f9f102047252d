"""Figures of the structural seal model: deformed section with stress and contact pressure,
load-state curves, characteristic maps. Figures are pyplot-free; plotting never changes
results."""

from __future__ import annotations

import numpy as np
from matplotlib.collections import PolyCollection

from sealsim.plotting import celsius_text, new_figure
from sealsim.structure.results import pressure_profile

__all__ = ["plot_map", "plot_map_profiles", "plot_section", "plot_states"]

_LABELS = {
    "sealing_surface": "sealing surface",
    "groove_bottom": "groove bottom",
    "wall_upstream": "groove wall (upstream)",
    "wall_downstream": "groove wall (downstream)",
}


def plot_section(state, title: str = ""):
    """Deformed cross-section coloured by von Mises stress, with the rigid gland lines, and
    the contact pressure profiles p(z) on the sealing surface and the groove bottom.

    Parameters
    ----------
    state : StateResult
        One load state (:func:`sealsim.structure.results.extract`).
    title : str
        Figure title.
    """
    fig, (ax, axp) = new_figure(2, 1, width=11.0, height=4.6,
                                gridspec_kw={"width_ratios": [1.0, 1.25]})
    pts = state.deformed_points * 1e3
    polys = pts[state.cells]
    vm = state.von_mises / 1e6
    coll = PolyCollection(polys, array=vm, cmap="viridis", edgecolors="face", linewidths=0.2)
    ax.add_collection(coll)
    cb = fig.colorbar(coll, ax=ax, shrink=0.85)
    cb.set_label("von Mises stress [MPa]")
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = (hi - lo).max()
    pad = 0.25 * span
    walls = [ln.point[0] * 1e3 for ln in state.lines if abs(ln.normal[0]) > 0.5]
    xlim = (min([lo[0], *walls]) - pad, max([hi[0], *walls]) + pad)
    ylim = (lo[1] - pad, hi[1] + pad)
    radial = {ln.name: ln.point[1] * 1e3 for ln in state.lines if abs(ln.normal[1]) > 0.5}
    y_seal = radial.get("sealing_surface")
    y_groove = radial.get("groove_bottom")
    hatch = 0.08 * span
    for line in state.lines:
        x0, y0 = np.array(line.point) * 1e3
        if abs(line.normal[1]) > 0.5:  # radial surface: horizontal line
            side = -np.sign(line.normal[1])
            ax.fill_between(xlim, y0, y0 + side * hatch, color="0.82", lw=0)
            ax.plot(xlim, [y0, y0], color="0.25", lw=2.0)
        else:  # groove wall: from the groove bottom to a small clearance gap at the seal side
            if y_seal is not None and y_groove is not None:
                gap = 0.04 * abs(y_groove - y_seal)
                y_end = y_seal + np.sign(y_groove - y_seal) * gap
                ys = [y_groove, y_end]
            else:
                ys = list(ylim)
            side = -np.sign(line.normal[0])
            ax.fill_betweenx(ys, x0, x0 + side * hatch, color="0.82", lw=0)
            ax.plot([x0, x0], ys, color="0.25", lw=2.0)
    if state.bonded_points is not None and len(state.bonded_points):
        b = state.bonded_points * 1e3
        ax.plot(b[:, 0], b[:, 1], "s", color="0.15", ms=2.5, label="bonded to the metal case")
    if state.spring_force > 0 and state.spring_points is not None:
        c = state.spring_points.mean(axis=0) * 1e3
        ax.plot(*c, "o", mfc="none", mec="tab:red", ms=9, mew=1.5,
                label=f"garter spring {state.spring_force:.1f} N")
    if (state.bonded_points is not None and len(state.bonded_points)) or state.spring_force > 0:
        ax.legend(fontsize=7, loc="upper left")
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal")
    shaft = len(state.lines) == 1
    ax.set_xlabel("axial position z [mm] (" + ("oil side on the left" if shaft else
                                               "fluid pressure from the left") + ")")
    ax.set_ylabel("radius r [mm]")
    ax.set_title(f"squeeze {state.squeeze * 100:.3g} %, {state.pressure / 1e5:.3g} bar, "
                 f"{celsius_text(state.temperature)}", fontsize=10)
    for name, style in (("sealing_surface", "-"), ("groove_bottom", "--")):
        s = state.surfaces.get(name)
        if s is None or s.position.size == 0:
            continue
        z = np.unique(np.concatenate([np.linspace(s.edge_low, s.edge_high, 400),
                                      s.position, [s.edge_low, s.edge_high]]))
        p = pressure_profile(s, z)
        zones = f", {s.zones} zones" if s.zones > 1 else ""
        label = (f"{_LABELS[name]}: F = {s.force:.1f} N, b = {s.width * 1e3:.3f} mm{zones}, "
                 f"p_max = {s.p_max / 1e6:.2f} MPa")
        line, = axp.plot(z * 1e3, p / 1e6, style, lw=1.2, label=label)
        _contact_nodes(axp, s, line.get_color())
    if state.pressure > 0:
        axp.axhline(state.pressure / 1e6, color="0.5", lw=0.8, ls=":",
                    label=f"fluid pressure {state.pressure / 1e5:.3g} bar")
    axp.set_xlabel("axial position z [mm]")
    axp.set_ylabel("contact pressure [MPa]")
    axp.grid(alpha=0.3)
    legend = axp.legend(fontsize=8, loc="upper left")
    _headroom(axp, legend)
    if title:
        fig.suptitle(title)
    return fig


def _headroom(ax, legend) -> None:
    """Raise the top of the axes until the legend's lower edge clears the highest point drawn
    (the legend in the upper left covered the peak of a profile): measured on a drawn figure,
    for the final layout."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = ax.get_figure()
    if not isinstance(fig.canvas, FigureCanvasAgg):
        FigureCanvasAgg(fig)
    peak = max((float(np.nanmax(line.get_ydata())) for line in ax.get_lines()
                if np.any(np.isfinite(line.get_ydata()))), default=0.0)
    peak = peak if peak > 0.0 else 1.0         # no contact drawn: a 0 ... 1 MPa frame
    ax.set_ylim(0.0, 1.05 * peak)
    for _ in range(4):                     # the layout moves a little with the limits
        fig.draw_without_rendering()
        box = legend.get_window_extent(fig.canvas.get_renderer())
        clear = ax.transData.inverted().transform((box.x0, box.y0))[1]   # legend's bottom
        if clear >= 1.02 * peak:
            return
        top = ax.get_ylim()[1]
        ax.set_ylim(0.0, top + (1.04 * peak - clear))


def _contact_nodes(ax, surface, color) -> None:
    """The contact nodes of a surface as dots; hollow those outside its contact zones (a
    grazing edge node, whose nodal force stands for no contact length: the width b and the
    line end inside it, :func:`sealsim.structure.results.contact_width`)."""
    z = surface.position
    inside = np.zeros(z.shape, dtype=bool)
    for lo, hi in surface.zone_edges:
        inside |= (z >= lo) & (z <= hi)
    ax.plot(z[inside] * 1e3, surface.pressure[inside] / 1e6, "o", ms=2.0, color=color)
    if not inside.all():
        ax.plot(z[~inside] * 1e3, surface.pressure[~inside] / 1e6, "o", ms=4.0, mfc="none",
                color=color, label="grazing node, outside b")


def plot_states(frame, x: str | None = None, title: str = "", groove_bottom: bool = True):
    """F_N, b and peak pressures over the load states of a ``result.csv`` frame.

    ``x`` is the column on the horizontal axis; by default the temperature for a temperature
    history (from the installed state on, the axis running the way the temperature goes), the
    load states (labelled) for a squeeze-then-pressure path, else the varying load.
    ``groove_bottom=False`` for a seal without one (a lip bonded to its case): its columns
    hold 0, which is no contact force to draw.
    """
    labels = None
    if x is None:
        spans = {c: float(np.ptp(frame[c].to_numpy())) for c in
                 ("temperature_C", "pressure_bar", "squeeze_percent")}
        if spans["temperature_C"] > 0:
            # installation and hold sit at one temperature: start at the last of them
            temperature = frame["temperature_C"].to_numpy()
            first_change = int(np.argmax(temperature != temperature[0]))
            frame = frame.iloc[max(first_change - 1, 0):]
            x = "temperature_C"
        elif spans["squeeze_percent"] > 0 and spans["pressure_bar"] > 0:
            x = "load state"
            labels = [f"{s:.3g} %" if k == 0 or s != frame["squeeze_percent"].iloc[k - 1]
                      else f"{p:.3g} bar"
                      for k, (s, p) in enumerate(zip(frame["squeeze_percent"],
                                                     frame["pressure_bar"],
                                                     strict=True))]
        else:
            x = "pressure_bar" if spans["pressure_bar"] > 0 else "squeeze_percent"
    fig, axes = new_figure(3, 1, width=12.0, height=3.6)
    xs = np.arange(len(frame)) if x == "load state" else frame[x].to_numpy()
    axes[0].plot(xs, frame["F_N_N"], "-o", ms=3, label="sealing surface F_N")
    if groove_bottom:
        axes[0].plot(xs, frame["F_groove_bottom_N"], "--s", ms=3, label="groove bottom")
    axes[0].set_ylabel("normal force (360°) [N]")
    axes[1].plot(xs, frame["b_mm"], "-o", ms=3)
    axes[1].set_ylabel("contact width b [mm]")
    axes[2].plot(xs, frame["p_max_MPa"], "-o", ms=3, label="sealing surface")
    if groove_bottom:
        axes[2].plot(xs, frame["p_max_groove_bottom_MPa"], "--s", ms=3, label="groove bottom")
    axes[2].set_ylabel("peak contact pressure [MPa]")
    for ax in axes:
        ax.grid(alpha=0.3)
        if labels is not None:
            ax.set_xticks(xs, labels, rotation=60, fontsize=8)
            ax.set_xlabel("load state (squeeze, then pressure)")
        else:
            ax.set_xlabel({"time_s": "time [s]", "pressure_bar": "pressure [bar]",
                           "squeeze_percent": "squeeze [%]", "temperature_C": "temperature [°C]"
                           }.get(x, x))
    if x == "temperature_C" and xs[-1] < xs[0]:
        for ax in axes:          # a cooling run reads from left to right
            ax.invert_xaxis()
    axes[0].legend(fontsize=8)
    axes[2].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return fig


def plot_map(dataset, squeeze_index: int = 0, title: str = ""):
    """F_N and b over pressure for every temperature of a characteristic map."""
    fig, axes = new_figure(2, 1, width=11.0, height=4.0)
    ds = dataset.isel(squeeze=squeeze_index)
    p = ds["pressure"].values / 1e5
    for t in ds["temperature"].values:
        sel = ds.sel(temperature=t)
        label = celsius_text(t)
        axes[0].plot(p, sel["F_N"].values, "-o", ms=3, label=label)
        axes[1].plot(p, sel["b"].values * 1e3, "-o", ms=3, label=label)
    axes[0].set_ylabel("F_N (360°) [N]")
    axes[1].set_ylabel("contact width b [mm]")
    for ax in axes:
        ax.set_xlabel("pressure [bar]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8, title="temperature")
    s = float(dataset["squeeze"].values[squeeze_index])
    fig.suptitle(title or f"characteristic map, squeeze {s * 100:.3g} %")
    return fig


def plot_map_profiles(dataset, squeeze_index: int = 0, title: str = ""):
    """Contact pressure profiles p(z) of a characteristic map: every pressure at the first
    temperature, and every temperature at the highest pressure."""
    fig, axes = new_figure(2, 1, width=11.0, height=4.0)
    ds = dataset.isel(squeeze=squeeze_index)
    z = ds["position"].values * 1e3
    t0 = ds["temperature"].values[0]
    for p in ds["pressure"].values:
        axes[0].plot(z, ds["contact_pressure"].sel(temperature=t0, pressure=p).values / 1e6,
                     lw=1.2, label=f"{p / 1e5:.3g} bar")
    p_hi = ds["pressure"].values[-1]
    for t in ds["temperature"].values:
        axes[1].plot(z, ds["contact_pressure"].sel(temperature=t, pressure=p_hi).values / 1e6,
                     lw=1.2, label=celsius_text(t))
    axes[0].set_title(f"at {celsius_text(t0)}", fontsize=10)
    axes[1].set_title(f"at {p_hi / 1e5:.3g} bar", fontsize=10)
    for ax, legend in zip(axes, ("pressure", "temperature")):
        ax.set_xlabel("axial position z [mm]")
        ax.set_ylabel("contact pressure [MPa]")
        ax.set_ylim(bottom=0.0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, title=legend)
    s = float(dataset["squeeze"].values[squeeze_index])
    fig.suptitle((title + ": " if title else "") + f"contact pressure on the sealing surface, "
                 f"squeeze {s * 100:.3g} %")
    return fig


def plot_lip_force(tables: dict, title: str = ""):
    """Radial lip force (with and without the garter spring, and the spring's own radial
    force), spring share and contact width of FE lip tables vs temperature (frames of
    :meth:`sealsim.rotary.lip_fe.LipForceTable.frame`, one per variant)."""
    fig, axes = new_figure(3, 1, width=12.0, height=3.6)
    for name, t in tables.items():
        line, = axes[0].plot(t["temperature_C"], t["F_tip_N"], "-o", ms=3,
                             label=f"{name}: lip force")
        axes[0].plot(t["temperature_C"], t["F_without_spring_N"], "-s", ms=3, mfc="none",
                     color=line.get_color(), label=f"{name}: without its spring")
        axes[0].plot(t["temperature_C"], t["F_spring_N"], "--", lw=1.0, color=line.get_color(),
                     label=f"{name}: spring's own 2πT")
        axes[1].plot(t["temperature_C"], t["spring_share"], "-o", ms=3, label=name)
        axes[2].plot(t["temperature_C"], t["contact_width_mm"], "-o", ms=3, label=name)
    axes[0].set_ylabel("radial force (360°) [N]")
    axes[1].set_ylabel("spring share 1 − F_without/F [-]")
    axes[2].set_ylabel("contact width [mm]")
    for ax in axes:
        ax.set_xlabel("temperature [°C]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle((title + ": " if title else "") + "lip force from FE")
    return fig
