"""Figures of the one-call answers (:mod:`sealsim.api`) as the app shows them: lip seal curves
over speed, a seal's Stribeck curve and hysteresis loop.  Pyplot-free; plotting never changes
results."""

from __future__ import annotations

import io

from sealsim.plotting import new_figure

__all__ = ["figure_png", "friction_figure", "lip_seal_speed_figure"]


def figure_png(figure, dpi: int = 110) -> bytes:
    """A figure as PNG bytes."""
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=dpi, bbox_inches="tight")
    return buffer.getvalue()


def lip_seal_speed_figure(curve, point=None, title: str = ""):
    """Torque, power, contact temperature and film of :func:`sealsim.lip_seal_torque` over
    speed (a DataFrame), with the operating point marked."""
    fig, axes = new_figure(2, 2, width=9.0, height=5.6, sharex=True)
    panels = (("torque_Nm", "torque [N·m]"), ("power_W", "power [W]"),
              ("T_contact_C", "temperature [°C]"), ("film_um", "film [µm]"))
    for ax, (column, label) in zip(axes.ravel(), panels):
        ax.plot(curve["speed_rpm"], curve[column], "-o", ms=3, color="#2b6cb0",
                label="contact" if column == "T_contact_C" else None)
        if column == "T_contact_C":
            ax.plot(curve["speed_rpm"], curve["T_sump_C"], "--", color="#718096", label="sump")
            ax.legend(fontsize=8)
        if point is not None:
            ax.plot([point["speed_rpm"]], [point[column]], "s", color="#c53030", ms=7)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("speed [rpm]")
    fig.suptitle(title, fontsize=10)
    return fig


def friction_figure(curve, loop, title: str = ""):
    """Steady friction over velocity (:func:`sealsim.seal_friction`) and the friction over
    displacement and velocity of a harmonic stroke (:func:`sealsim.friction_loop`)."""
    fig, (ax_curve, ax_x, ax_v) = new_figure(3, 1, width=12.0, height=3.8)
    ax_curve.semilogx(curve["velocity_m_s"], curve["friction_N"], "-", color="#2b6cb0")
    ax_curve.set_xlabel("sliding velocity [m/s]")
    ax_curve.set_ylabel("steady friction [N]")
    ax_curve.set_title("Stribeck curve", fontsize=9)
    ax_x.plot(loop["displacement_mm"], loop["friction_N"], color="#2f855a", lw=1.0)
    ax_x.set_xlabel("displacement [mm]")
    ax_x.set_ylabel("friction [N]")
    ax_x.set_title("friction over displacement", fontsize=9)
    ax_v.plot(loop["velocity_m_s"] * 1e3, loop["friction_N"], color="#c05621", lw=1.0)
    ax_v.set_xlabel("velocity [mm/s]")
    ax_v.set_ylabel("friction [N]")
    ax_v.set_title("hysteresis loop", fontsize=9)
    for ax in (ax_curve, ax_x, ax_v):
        ax.grid(alpha=0.3)
    fig.suptitle(title, fontsize=10)
    return fig
