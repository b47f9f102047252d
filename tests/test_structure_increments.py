"""Automatic incrementation of the FE load path (sealsim.structure.solver): how a step's
increment grows back after a cutback, where recorded states fall, and that the converged
states do not depend on the increments taken (hyperelastic, frictionless)."""

import numpy as np
import pytest

import sealsim.structure.solver as solver
from sealsim.structure.model import LoadState
from sealsim.structure.solver import LoadStep


class HardSpotModel:
    """Stand-in for a SealModel whose increments fail when they are larger than ``limit``
    (a fraction of the step) and overlap the load fractions ``spot`` (e.g. contact that
    changes over a short stretch of the load path): the incrementation alone is tested."""

    def __init__(self, spot=(0.10, 0.20), limit=0.5 / 16, iterations=5):
        self.spot, self.limit, self.iterations = spot, limit, iterations
        self.state = LoadState(0.0, 0.0, 293.15, 0.0)
        self.material = None
        self.increment_log = []
        self.attempts = []          # (start, end) of every attempt, failed or not

    def checkpoint(self):
        return self.state

    def restore(self, state):
        self.state = state


def fake_increment(model, target, tol, maxiter, linear):
    start, end = model.state.squeeze, target.squeeze
    model.attempts.append((start, end))
    lo, hi = model.spot
    if end - start > model.limit * (1 + 1e-9) and start < hi and end > lo:
        raise solver.fem.NewtonConvergenceError("too large an increment at the hard spot")
    model.state = target
    return model.iterations


def run_fake(monkeypatch, model, increments=2, record="all", maxiter=25, growth=True):
    monkeypatch.setattr(solver, "_increment", fake_increment)
    records = []
    solver._solve_steps(model, [LoadStep("squeeze", squeeze=1.0, increments=increments,
                                         record=record)],
                        lambda m: m.state.squeeze, 1e-8, maxiter, 8, None, records, growth)
    return records


def test_increment_grows_back_after_a_hard_spot(monkeypatch):
    """A step in one nominal increment with a hard spot at 10-20 % of the load that needs
    increments of 1/32 of it.  Before, the cut-back size was kept until the load reached the
    nominal grid (here the end of the step): 31 increments, 30 of them after the first
    halvings at 1/32.  Growing by 1.5 after every two easy increments (Abaqus/Standard's
    time incrementation controls) passes the spot at its size and grows after it: 19
    increments.  Bound 22: well below the old 31."""
    model = HardSpotModel(limit=1 / 32)
    records = run_fake(monkeypatch, model, increments=1)
    log = model.increment_log
    assert len(log) <= 22
    # the log is truthful: contiguous increments covering the step, the failed attempts
    # counted as the cutbacks before the increment that then converged
    fractions = [r["load_fraction"] for r in log]
    assert np.allclose(np.diff([0.0, *fractions]), [r["increment"] for r in log])
    assert fractions[-1] == 1.0 and records == [1.0]
    assert sum(r["cutbacks"] for r in log) == len(model.attempts) - len(log)
    assert max(r["increment"] for r in log if 0.1 < r["load_fraction"] <= 0.2) \
        <= model.limit * (1 + 1e-9)


def test_previous_control_on_request(monkeypatch):
    """increment_growth=False (solver.increment_growth = false in a case) keeps the previous
    control exactly: the cut-back size is kept to the nominal grid, where it doubles (the same
    hard spot: 31 increments, the last 30 of 1/32)."""
    model = HardSpotModel(limit=1 / 32)
    run_fake(monkeypatch, model, increments=1, growth=False)
    sizes = [r["increment"] for r in model.increment_log]
    assert len(sizes) == 31 and sizes[1:] == [1 / 32] * 30


def test_recorded_states_stay_on_the_nominal_grid(monkeypatch):
    """record="all" after a cutback: a state at every nominal grid point, exactly there, and
    no increment steps over a grid point (a viscoelastic path's steps end on them too)."""
    model = HardSpotModel(limit=1 / 64)
    records = run_fake(monkeypatch, model, increments=4)
    assert records == [0.25, 0.5, 0.75, 1.0]
    fractions = [r["load_fraction"] for r in model.increment_log]
    assert {0.25, 0.5, 0.75, 1.0} <= set(fractions)
    assert len(model.increment_log) > 4            # it did cut back


def test_increment_does_not_grow_after_hard_increments(monkeypatch):
    """Increments that converge only in many Newton iterations (more than EASY_ITERATIONS)
    keep the cut-back size (a hard stretch of the path: growing would fail again)."""
    model = HardSpotModel(iterations=solver.EASY_ITERATIONS + 1)
    run_fake(monkeypatch, model)
    after = [r["increment"] for r in model.increment_log if 0.2 < r["load_fraction"] <= 0.5]
    assert max(after) <= model.limit * (1 + 1e-9)


def test_step_without_cutback_takes_the_nominal_increments(monkeypatch):
    """Nothing fails: exactly the nominal increments, as before (same states, same log)."""
    model = HardSpotModel(limit=1.0)
    records = run_fake(monkeypatch, model, increments=4, record="end")
    assert [r["load_fraction"] for r in model.increment_log] == [0.25, 0.5, 0.75, 1.0]
    assert records == [1.0]


def test_smallest_increment_is_tried_before_giving_up(monkeypatch):
    """With max_cutbacks halvings the increment 1/n * 0.5**max_cutbacks is tried (and the
    error names the load) also when growth left the size off the powers of two."""
    model = HardSpotModel(limit=0.0)
    with pytest.raises(solver.ConvergenceError, match=r"squeeze .* increment 0.00195"):
        run_fake(monkeypatch, model)
    assert min(end - start for start, end in model.attempts) == pytest.approx(0.5 * 0.5 ** 8)


def test_cut_back_fe_path_converges_to_the_fine_path():
    """Frictionless hyperelastic O-ring (20 x 4 mm, coarse): 20 % squeeze, then heating to
    100 degC, each in one increment with at most 6 Newton iterations, so that both steps are
    cut back (6 cutbacks).  Before, the halved increments were kept up to the end of each
    step: 34 increments; now 14.  The converged states are the solution of a path-independent
    problem: against the same path in 16 fixed increments per step (no cutback) F_N and p_max
    agree within 1e-4 and b within 1e-5.  The reference for these tolerances: the wetted
    surface of the positioning pressure is settled to 1e-4 of the cord diameter only
    (solver._newton), which leaves the fixed paths of 1 and 16 squeeze increments 1.2e-4
    apart in F_N (measured: 273.331 and 273.364 N); the cut-back path is 1.2e-5 (squeezed)
    and 2.4e-5 (heated) from the fine one, the previous incrementation's 6e-6 and 2.4e-5."""
    from test_structure_validation import rod_model

    from sealsim.structure.solver import solve

    def path(increments, maxiter):
        model = rod_model()
        states = solve(model, [
            LoadStep("squeeze", squeeze=0.2, increments=increments, record="end"),
            LoadStep("temperature", temperature=373.15, increments=increments, record="end")],
            maxiter=maxiter)
        return states, model.increment_log

    auto, log = path(1, 6)
    fine, fine_log = path(16, 25)
    assert sum(r["cutbacks"] for r in log) > 0 and sum(r["cutbacks"] for r in fine_log) == 0
    assert len(log) <= 20
    for a, f in zip(auto, fine, strict=True):
        assert a.F_N == pytest.approx(f.F_N, rel=1e-4)
        assert a.p_max == pytest.approx(f.p_max, rel=1e-4)
        assert a.b == pytest.approx(f.b, rel=1e-5)
