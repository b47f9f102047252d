"""timeseries_<variant>.png and pressure_stroke.png of `sealsim pneumatic run`: legends."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from plot_checks import covered_points

from sealsim.plotting.pneumatic import (
    heating_figure,
    pressure_stroke_figure,
    timeseries_figure,
)


def run_frame(shift: float = 0.0) -> pd.DataFrame:
    """Two strokes of a cylinder (cylinder_32.toml's shapes): both chambers at the 7 bar supply
    at the end of the run, the top right corner where the legends were."""
    t = np.linspace(0.0, 4.0, 801)
    phase = (t % 2.0) < 1.0
    theta = 0.9 - 0.2 * np.cos(np.pi * t)
    return pd.DataFrame({
        "time_s": t, "x_m": np.where(phase, 0.1, 0.0), "v_m_s": np.gradient(t),
        "p1_bar_abs": np.where(phase, 7.0, 1.0 + 6.0 * (t > 3.5)) + shift,
        "p2_bar_abs": np.where(phase, 1.0, 7.0) + shift,
        "T1_C": 25 + 10 * np.sin(t), "T2_C": 25 - 10 * np.sin(t),
        "F_friction_N": np.where(phase, 20.0, -20.0), "F_piston_N": np.where(phase, 12.0, -12.0),
        "F_rod_N": np.where(phase, 8.0, -8.0), "F_N_piston_N": np.where(phase, 87.0, 33.0),
        "F_N_rod_N": np.where(phase, 38.0, 16.0), "theta_piston": theta, "theta_rod": theta,
        "valve_command": np.where(phase, 1.0, -1.0)})


def drawn(fig):
    FigureCanvasAgg(fig).draw()
    return fig.canvas.get_renderer()


@pytest.mark.parametrize("figure", ["timeseries", "pressure_stroke"])
def test_legends_cover_no_curve(figure):
    # the legends in the upper right corner hid p2's rise to 7 bar, F_N's last plateau and
    # Θ's last maximum (cylinder_32.toml, friction_rig.toml, heipl_rod_seal.toml)
    if figure == "timeseries":
        fig = timeseries_figure(run_frame(), ["piston", "rod"], "run")
    else:
        frames = {}
        for k in (0, 25, 55, 85):          # pressures that rise and decay all over the panel
            f = run_frame()
            wave = 0.5 + 0.5 * np.sin(2 * np.pi * (3 + 0.01 * k) * f["time_s"])
            f["p1_bar_abs"], f["p2_bar_abs"] = 1 + 6 * wave, 7 - 6 * wave
            frames[f"T{k}C"] = f
        fig = pressure_stroke_figure(frames)
    renderer = drawn(fig)
    legends = [ax for ax in fig.axes if ax.get_legend() is not None]
    assert len(legends) >= 2
    assert {ax.get_ylabel(): covered_points(ax, renderer) for ax in legends} == {
        ax.get_ylabel(): 0 for ax in legends}


def test_air_temperatures_name_their_chambers():
    fig = timeseries_figure(run_frame(), ["piston", "rod"], "run")
    air, = [ax for ax in fig.axes if ax.get_ylabel() == "Air temp. [°C]"]
    assert [t.get_text() for t in air.get_legend().get_texts()] == ["T1 (cap side)",
                                                                    "T2 (rod side)"]


def test_heating_figure_names_the_metal_nodes():
    # the rod's thermal node is the moving metal, piston and rod (seal_heating): its curve
    # says so ("rod" next to "seal rod" read as the seal's counterface alone)
    t = np.linspace(0.0, 4.0, 9)
    frame = pd.DataFrame({"time_s": t, "T_piston_C": 25 + t, "T_rod_C": 25 + 2 * t,
                          "T_tube_metal_C": 25 + t, "T_rod_metal_C": 25 + 2 * t})
    strokes = pd.DataFrame({"start_s": [0.0, 1.0], "direction": [1, -1],
                            "mean_friction_N": [20.0, 21.0], "stroke_time_s": [0.3, 0.35]})
    fig = heating_figure(frame, strokes, ["piston", "rod"])
    labels = [text.get_text() for text in fig.axes[0].get_legend().get_texts()]
    assert labels == ["seal piston", "seal rod", "tube", "piston + rod"]
