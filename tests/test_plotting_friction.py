"""The pictures of `sealsim friction run`: what the steady curve in force_velocity.png shows."""

from __future__ import annotations

import numpy as np
import pytest

import sealsim.runs.friction as runs_friction

CASE = """
title = "LuGre sweep"
[friction]
law = "lugre"
parameter_set = "canudas1995"   # F_C = 1 N, F_S = 1.5 N, v_s = 1 mm/s
[bench]
mode = "velocity"
start = "steady"
duration = "2 s"
time_step = "1 ms"
velocity = { kind = "piecewise", times = ["0 s", "2 s"], values = ["-0.4 m/s", "0.4 m/s"] }
"""


@pytest.fixture(scope="module")
def drawn(tmp_path_factory):
    """The force_velocity.png figure of a LuGre sweep through v = 0 (Stribeck velocity 1 mm/s,
    400 times below the top speed), caught on its way to the file."""
    return caught_figure(CASE, "plot_force_velocity", tmp_path_factory.mktemp("lugre"))


def caught_figure(case_text: str, plot: str, folder):
    """The figure that ``sealsim.runs.friction``'s ``plot`` draws for a friction case."""
    case = folder / "case.toml"
    case.write_text(case_text)
    draw = getattr(runs_friction, plot)
    figures = []

    def catch(*args, **kwargs):
        figures.append(draw(*args, **kwargs))
        return figures[-1]

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(runs_friction, plot, catch)
        runs_friction.run_case_file(case, folder / "out")
    return figures[0]


def steady_line(fig):
    ax = fig.axes[0]
    line, = [ln for ln in ax.get_lines() if ln.get_label().endswith("steady curve")]
    return line.get_xdata(), line.get_ydata()


def test_steady_curve_shows_the_breakaway_peak(drawn):
    # the LuGre steady curve tends to F_S = 1.5 N as v -> 0 (Canudas de Wit 1995, Eq. 4); at
    # 1 % of v_s it is F_C + 0.5 N * exp(-1e-4) = 1.49995 N.  A linear grid of 801 points over
    # +-0.4 m/s (1 mm/s apart) drew the peak at 1.18 N.
    _, force = steady_line(drawn)
    assert np.nanmax(force) == pytest.approx(1.5, abs=0.005)
    assert np.nanmin(force) == pytest.approx(-1.5, abs=0.005)


def test_steady_curve_is_not_joined_across_the_jump_at_zero(drawn):
    # F_ss = sgn(v)*(...) jumps from -F_S to +F_S: no drawn segment may join the two branches
    # (the old line ran through a point (0, 0) between them)
    v, force = steady_line(drawn)
    v, force = np.asarray(v, float), np.asarray(force, float)
    drawn_segment = np.isfinite(force[:-1]) & np.isfinite(force[1:])
    crosses = np.sign(v[:-1]) != np.sign(v[1:])
    assert not np.any(drawn_segment & crosses)
    assert not np.any(np.isfinite(force) & (v == 0.0))


STICK_SLIP = """
title = "LuGre stick-slip"
[friction]
law = "lugre"
parameter_set = "canudas1995"
[bench]
mode = "mass"
mass = "1 kg"
stiffness = "2 N/m"
duration = "25 s"
time_step = "1 ms"
drive_velocity = { kind = "constant", level = "0.1 m/s" }
[variants.native]
[variants.second]
"""


def test_timeseries_legends_cover_no_curve(tmp_path):
    # lugre_stick_slip.toml, stick_slip_cosim.py: the force panel's legend ('NAME: friction',
    # 'NAME: spring + applied' per run) hid the spring force's minima near 0.75 N
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from plot_checks import covered_points

    fig = caught_figure(STICK_SLIP, "plot_timeseries", tmp_path)
    FigureCanvasAgg(fig).draw()
    renderer = fig.canvas.get_renderer()
    with_legend = [ax for ax in fig.axes if ax.get_legend() is not None]
    assert [ax.get_ylabel() for ax in with_legend] == ["v [mm/s]", "force [N]"]
    assert [covered_points(ax, renderer) for ax in with_legend] == [0, 0]
    assert [t.get_text() for t in with_legend[1].get_legend().get_texts()] == [
        "friction", "spring + applied"]
    assert fig.axes[-1].get_ylabel() == "bristles z [µm]"      # was 'z [µm]': of what?
