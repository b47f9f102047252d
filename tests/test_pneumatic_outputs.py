"""What a pneumatic run reports about its samples: the mean friction of the summary and of each
stroke (friction work over the distance slid), and the friction–velocity figure (no line
across an impact the samples do not resolve)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from sealsim.pneumatic.summary import per_stroke, sliding_mean
from sealsim.plotting.pneumatic import friction_velocity_figure

STROKE = 0.1


def stroke_frame(break_away_speed: float = 0.9e-3) -> pd.DataFrame:
    """An extend stroke sampled every 1 ms: rest at the cap stop, a break-away whose first
    moving sample has ``break_away_speed`` and the break-away peak of 40 N, 20 N while sliding
    at 0.4 m/s, an impact into the head stop (v 0.4 → −0.05 m/s in one sample) and rest."""
    t = np.arange(0.0, 0.5, 1e-3)
    v = np.where(t < 0.05, 0.0, np.minimum(40.0 * (t - 0.05), 0.4))
    v[t >= 0.3] = 0.0
    i = np.flatnonzero(t >= 0.05)[1]
    v[i] = break_away_speed                    # the sample at the break-away
    x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))]) - 2e-4
    x[t >= 0.3] = STROKE + 1e-4                # in the head stop's bumper
    impact = np.flatnonzero(t >= 0.3)[0]
    v[impact] = -0.05
    friction = np.where(v > 0, 20.0, 5.0)
    friction[i] = 40.0                         # break-away peak
    friction[impact] = -15.0
    return pd.DataFrame({"time_s": t, "x_m": x, "v_m_s": v, "F_friction_N": friction,
                         "valve_command": 1.0})


def test_one_sample_crossing_the_old_speed_threshold_does_not_move_the_mean():
    # Old definition: mean |F| of the samples with |v| > 1 mm/s.  The break-away sample at
    # 0.9 mm/s (not counted) or 1.1 mm/s (counted, 40 N) moved it by 0.08 N.  Over the
    # distance slid the two differ by that sample's share of the travel: 0.2 µm of 85 mm.
    slow, fast = stroke_frame(0.9e-3), stroke_frame(1.1e-3)
    means = [float(per_stroke(f, STROKE, [])["mean_friction_N"].iloc[0]) for f in (slow, fast)]
    assert abs(means[1] - means[0]) < 1e-4, means
    old = [float(np.mean(np.abs(f["F_friction_N"][np.abs(f["v_m_s"]) > 1e-3])))
           for f in (slow, fast)]
    assert abs(old[1] - old[0]) > 0.05        # the jump this definition removes


def test_sliding_mean_is_friction_work_over_distance():
    # constant speed, friction linear in x: the mean over the distance is the mid value
    t = np.linspace(0.0, 1.0, 1001)
    v = np.full_like(t, 0.2)
    assert sliding_mean(t, v, 10.0 + 100.0 * 0.2 * t) == pytest.approx(20.0, rel=1e-12)
    # uneven speed: the work ∫F·v dt over the distance ∫v dt, not the time mean
    v = np.where(t < 0.5, 0.1, 0.3)
    f = np.where(t < 0.5, 30.0, 10.0)
    work, distance = np.trapezoid(f * v, t), np.trapezoid(v, t)
    assert sliding_mean(t, v, f) == pytest.approx(work / distance, rel=1e-12)
    # (30 N · 0.05 m + 10 N · 0.15 m) / 0.2 m = 15 N; 2e-3: the step is smeared over a sample
    assert sliding_mean(t, v, f) == pytest.approx(15.0, rel=2e-3)
    # a held piston (no travel) has no mean friction
    assert np.isnan(sliding_mean(t, np.zeros_like(t), f))


def segments(line) -> list[tuple[np.ndarray, np.ndarray]]:
    """Consecutive pairs of finite points that a plotted line joins."""
    xs, ys = (np.asarray(a, dtype=float) for a in line.get_data())
    joined = np.isfinite(xs[1:]) & np.isfinite(xs[:-1])
    return [((xs[i], ys[i]), (xs[i + 1], ys[i + 1])) for i in np.flatnonzero(joined)]


@pytest.mark.parametrize("strokes", [None, {"base": STROKE}])
def test_friction_velocity_lines_do_not_cross_an_impact(strokes):
    frame = stroke_frame()
    fig = friction_velocity_figure({"base": frame}, "", None, *([strokes] if strokes else []))
    line = fig.axes[0].get_lines()[0]
    joined = segments(line)
    assert joined, "the sliding part is drawn as a line"
    # no segment from the sliding branch (0.4 m/s, 20 N) to the sample in the bumper
    # (−0.05 m/s, −15 N) or back to rest: the old figure joined every sample.  Bound: a
    # tenth of the span of v (0.45 m/s) and of F (55 N), the figure's own jump criterion
    for (v0, f0), (v1, f1) in joined:
        assert abs(v1 - v0) <= 0.1 * 0.45 and abs(f1 - f0) <= 0.1 * 55.0, (v0, f0, v1, f1)
        if strokes:                             # with the stroke: nothing joins the bumper
            assert v0 != -0.05 and v1 != -0.05
    # the sliding samples are all still on the line
    xs = np.asarray(line.get_data()[0], dtype=float)
    assert np.sum(np.isclose(xs, 0.4)) == np.sum(np.isclose(frame["v_m_s"], 0.4))


def test_unfinished_strokes_takes_each_command_window_from_its_start_up_to_the_next():
    """The samples of a command are those from its issue time up to, not including, the next
    command's (found by binary search of the ascending times): a piston that reaches the end
    only at the sample of the next command did not finish its stroke, one that is there at the
    sample of its own command did; checked against the comparison of every sample."""
    from types import SimpleNamespace

    from sealsim.pneumatic.controller import command_schedule
    from sealsim.pneumatic.summary import END_TOLERANCE, unfinished_strokes

    steps = [SimpleNamespace(command="extend", duration=1.0),
             SimpleNamespace(command="retract", duration=1.0)]
    case = SimpleNamespace(cylinder=SimpleNamespace(stroke=STROKE), controller=SimpleNamespace(
        mode="cycle", steps=steps, duration=4.0, initial_command="retract"))
    t = np.linspace(0.0, 4.0, 401)                   # samples on every command time
    x = np.where(t < 2.0, 0.3 * STROKE, 0.6 * STROKE)
    x[t == 1.0] = STROKE                             # extended at the next command's sample only
    x[t == 2.0] = STROKE * (1.0 - END_TOLERANCE)     # second extend: there at its own sample
    notes = unfinished_strokes(t, x, case)

    def brute_force(target, sign):
        reached = x >= STROKE * (1 - END_TOLERANCE) if target == "extend" else \
            x <= STROKE * END_TOLERANCE
        return sum(1 for start, end in command_schedule(case).windows(sign)
                   if ((t >= start) & (t < end)).any()
                   and not reached[(t >= start) & (t < end)].any())

    assert brute_force("extend", 1.0) == 1 and brute_force("retract", -1.0) == 2
    assert notes[0].startswith("1 of 2 extend commands did not reach the extended end: the "
                               "piston got no further than 30 mm")
    assert notes[1].startswith("2 of 2 retract commands did not reach the retracted end")
