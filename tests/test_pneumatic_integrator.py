"""The compiled BDF driver of the pneumatic model (solver.method = "compiled", the default)
against scipy's LSODA, the reference: the same solution when both are converged, the same
stroke times at the default tolerance, and what the driver does besides integrating (the
output grid, segment records, stick/slip modes)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from pydantic import TypeAdapter
from test_pneumatic_cli import shortened

from sealsim.cases import load_toml
from sealsim.friction.case import LawParameters
from sealsim.pneumatic import build_seals, integrate, rhs, simulate
from sealsim.pneumatic.case import ThermalModel, load_pneumatic_cases
from sealsim.pneumatic.simulation import PneumaticSystem

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pneumatic"
STATES = ["x_m", "v_m_s", "p1_bar_abs", "p2_bar_abs", "T1_C", "T2_C"]


def case(duration, **solver):
    c = load_pneumatic_cases(load_toml(EXAMPLES / "cylinder_32.toml"))["T25C"]
    return c.model_copy(update={
        "controller": c.controller.model_copy(update={"duration": duration}),
        "solver": c.solver.model_copy(update=solver)})


def test_converged_states_are_lsodas():
    # both at rtol 1e-11 over an extend and a retract stroke with the stick/slip at the
    # stops: every state within 1e-6 of its range of LSODA's (issue 27; measured 1.9e-7 --
    # the rest is the sampled steep edges of the end-stop impacts, where a time shift of
    # 1e-10 s moves v by 1e-6 of its range)
    new = simulate(case(2.5, rtol=1e-11))
    ref = simulate(case(2.5, rtol=1e-11, method="LSODA"))
    assert new.stats["method"] == "compiled" and ref.stats["method"] == "LSODA"
    for name in STATES:
        a, b = new.timeseries[name].to_numpy(), ref.timeseries[name].to_numpy()
        span = np.max(np.abs(b))
        assert np.max(np.abs(a - b)) < 1e-6 * span, name
    assert new.stats["mode_switches"] == ref.stats["mode_switches"]


def test_default_tolerance_gives_lsodas_stroke_times():
    # at the default rtol = 1e-5 each method is accurate to about its tolerance: the extend
    # and retract times agree to 1e-4, the balances close as tightly as LSODA's
    new = simulate(case(4.0)).summary()
    ref = simulate(case(4.0, method="LSODA")).summary()
    for name in ("extend_time_s", "retract_time_s"):
        assert new[name] == pytest.approx(ref[name], rel=1e-4)
    assert new["mass_balance_rel_error"] < 1e-12
    assert new["energy_balance_rel_error"] < 1e-4


def test_output_grid_and_segments():
    # every output sample is written once, in order, with the mode of its segment; the
    # segments tile the run and their statistics add up
    res = simulate(case(2.0))
    t = res.timeseries["time_s"].to_numpy()
    assert t[0] == 0.0 and t[-1] == 2.0 and np.all(np.diff(t) > 0)
    assert np.allclose(np.diff(t), 1e-3)
    assert set(res.timeseries["mode"]) <= {"stick", "slip+", "slip-"}
    stuck = res.timeseries["mode"] == "stick"
    assert stuck.any() and np.all(res.timeseries["v_m_s"][stuck] == 0.0)
    assert res.stats["segments"] > res.stats["mode_switches"] > 0


def test_segments_chain_across_the_driver_calls():
    # the driver's segment records of all valve intervals become Segments once, at the end of
    # the run (per call the numpy steps of the assembly cost as much as the Segments: 178 ->
    # 111 µs for 88 segments in 11 calls): each segment starts where the one before ended --
    # across a call boundary too -- and at rest after a slip that ended by an event
    fwd, stick = rhs.FORWARD, rhs.STICK
    chunks = [(np.array([[0.0, 0.1], [0.1, 0.2]]),
               np.array([[stick, 3, 9, 1, 1], [fwd, 5, 20, 2, 1]]),
               np.array([[1.0, 0.0, 3.0], [2.0, 0.5, 4.0]])),
              (np.array([[0.2, 0.3]]), np.array([[stick, 2, 6, 1, 0]]),
               np.array([[2.0, 0.0, 5.0]]))]
    segments = integrate._segments(chunks, np.array([0.5, 0.0, 2.0]))
    assert [(s.t0, s.t1, s.mode, s.steps, s.nfev, s.njev, s.status) for s in segments] == [
        (0.0, 0.1, stick, 3, 9, 1, 1), (0.1, 0.2, fwd, 5, 20, 2, 1), (0.2, 0.3, stick, 2, 6, 1, 0)]
    np.testing.assert_array_equal([s.y0 for s in segments],
                                  [[0.5, 0.0, 2.0], [1.0, 0.0, 3.0], [2.0, 0.0, 4.0]])
    np.testing.assert_array_equal([s.y1 for s in segments],
                                  [[1.0, 0.0, 3.0], [2.0, 0.5, 4.0], [2.0, 0.0, 5.0]])
    # the state after them (the failure's state of a run that stops there)
    np.testing.assert_array_equal(integrate._next_start(chunks[:1], None), [2.0, 0.0, 4.0])
    assert integrate._segments([], np.zeros(3)) == []


def test_a_result_keeps_its_numbers_when_the_next_run_reuses_the_work_arrays():
    # run() samples and evaluates into work arrays of its thread that the next run of the
    # same size overwrites (page faults of fresh megabyte arrays were a fifth of a run's time):
    # a result must own its numbers.  Run A, then B with another seal temperature on the
    # same output grid: A's time series is unchanged, bit for bit, and shares no memory with
    # the work arrays; A run alone again gives the same numbers.
    from sealsim.pneumatic import results

    first = simulate(case(0.6))
    kept = first.timeseries.copy(deep=True)
    other = case(0.6)
    other = other.model_copy(update={"cylinder": other.cylinder.model_copy(
        update={"seal_temperature": 328.15})})
    second = simulate(other)
    assert not second.timeseries["F_friction_N"].equals(kept["F_friction_N"])
    assert first.timeseries.equals(kept)
    for column in first.timeseries.select_dtypes("number"):
        values = first.timeseries[column].to_numpy()      # a view of the frame's block
        for work in results._WORK.arrays.values():
            assert not np.shares_memory(values, work), column
    assert simulate(case(0.6)).timeseries.equals(kept)


def test_contact_friction_states_are_lsodas():
    # the default seal law takes its steady curve from the seal's contact table (issue 23):
    # heipl_rod_seal.toml at 25 degC, the compiled method at rtol 1e-11 against LSODA at
    # rtol 1e-12.  During the strokes every state within 1e-6 of its range of LSODA's.  In
    # the end stops the piston creeps into the elastic bumper against a friction that falls
    # with speed (the boundary to mixed branch of the Stribeck curve): that motion amplifies
    # any difference, and LSODA itself moves v there by 1.2e-3 of its range from rtol 1e-11
    # to 1e-12 -- so there x, p and T within 2e-6, v within 1e-4.
    # The reference is LSODA at 1e-12, not at 1e-11: in the stops LSODA at 1e-11 is itself
    # T1 1.6e-5 / v 1.2e-3 of the range from LSODA at 1e-12, further than the compiled
    # method; measured in the stops against LSODA at 1e-12: T1 1.06e-6, v 7.8e-5, during the
    # strokes 1e-8 (v 6e-8).  (Since the piston starts at rest in its stop, δ = F/k, instead
    # of at δ = 0: before, T1 6.7e-7 and LSODA's own 8.4e-7.)
    path = EXAMPLES / "heipl_rod_seal.toml"
    c = load_pneumatic_cases(load_toml(path))["T25C"]
    new, ref = (simulate(c.model_copy(update={"solver": c.solver.model_copy(update={
        "rtol": rtol, "method": m})}), base_dir=path.parent)
        for m, rtol in (("compiled", 1e-11), ("LSODA", 1e-12)))
    assert new.stats["method"] == "compiled"
    x = ref.timeseries["x_m"].to_numpy()
    stroke = (x > 0.0) & (x < c.cylinder.stroke)
    assert 0.2 < stroke.mean() < 0.9           # both strokes and both stops are sampled
    for name in STATES:
        a, b = new.timeseries[name].to_numpy(), ref.timeseries[name].to_numpy()
        error = np.abs(a - b) / np.max(np.abs(b))
        assert np.max(error[stroke]) < 1e-6, name
        assert np.max(error[~stroke]) < (1e-4 if name == "v_m_s" else 2e-6), name
    assert new.stats["mode_switches"] == ref.stats["mode_switches"]


def backward_breakaways(segments):
    """The slips that break away from rest (after a stick segment ended by its event) and end
    behind where they started."""
    return [s for before, s in zip(segments, segments[1:])
            if before.mode == rhs.STICK and before.status == 1
            and s.mode in (rhs.FORWARD, rhs.BACKWARD) and s.mode * (s.y1[0] - s.y0[0]) < 0.0]


@pytest.mark.parametrize("example", ["analytic", "heating", "contact", "fe_map"])
def test_breakaways_start_forwards(example, tmp_path):
    # a slip from rest moves in its direction (issue 27's break-away start: on a seal's
    # contact friction table, which falls like F_brk - k·sqrt(v) at break-away, the first BDF
    # step reversed v, and the slip ran backwards to the reversal event: 15 break-aways of the
    # contact-law cycle here, 21 (of 110 segments) with the coarse FE map; over 10 s 39 of
    # 227 and, with the full FE map, 46 of 262 segments).  The Ø32 cycle with the analytic
    # maps (lumped Θ law), with seal heating, with the seals' contact friction tables (set
    # seal_contact) and with a (coarse, 2 x 2) FE map of the rod seal: none, as with LSODA,
    # the reference.
    path = EXAMPLES / "cylinder_32.toml"
    if example == "fe_map":
        path = shortened(EXAMPLES / "cylinder_32_fe.toml", tmp_path, cap=4.0)
    c = load_pneumatic_cases(load_toml(path))["T25C"]
    if example == "heating":
        c = c.model_copy(update={"thermal": ThermalModel()})
    if example == "contact":
        law = TypeAdapter(LawParameters).validate_python({"law": "theta",
                                                         "parameter_set": "seal_contact"})
        c = c.model_copy(update={"seals": [s.model_copy(update={"friction": law})
                                           if s.friction.law == "theta" else s
                                           for s in c.seals]})
    seals = build_seals(c, path.parent)
    for method in ("compiled", "LSODA"):
        system = PneumaticSystem(c.model_copy(update={"solver": c.solver.model_copy(
            update={"method": method})}), seals)
        segments = integrate.integrate(system)
        breakaways = sum(1 for s in segments[:-1] if s.mode == rhs.STICK and s.status == 1)
        assert breakaways >= 4, method       # the 4 s cycle breaks away at each of its strokes
        assert backward_breakaways(segments) == [], method


def _jacobian_and_velocity_column(system, y, last_evaluated):
    """The whole Jacobian at y, and the velocity's column renewed at y (NaN elsewhere) and its
    growth rate after the right-hand side was last evaluated at ``last_evaluated``."""
    n, ndyn = system.n_states, system.n_dynamic
    scale = system.tolerances(1.0)[:ndyn].copy()
    diag = np.zeros((system.n_diag, 1))
    f0, whole, column = np.zeros(n), np.zeros((n, ndyn)), np.full((n, ndyn), np.nan)
    rhs.jacobian(0.5, y, rhs.FORWARD, system.tables, scale, np.zeros(n), np.zeros(n), f0,
                 diag, whole)
    rhs.derivatives(0.5, last_evaluated, rhs.FORWARD, system.tables, np.zeros(n), diag)
    rate = rhs.velocity_column_at(0.5, y, f0, rhs.FORWARD, system.tables, scale, np.zeros(n),
                                  np.zeros(n), diag, column)
    return whole, column, rate


@pytest.mark.parametrize("heating", [False, True])
def test_velocity_column_is_the_jacobians(heating):
    # the BDF's growth limit renews ∂f/∂v alone in a break-away (integrate._renew): the
    # column must be the whole Jacobian's, bit for bit (the same difference, the contact
    # loads of the evaluation at y kept -- v changes no Δp and no seal temperature), in a slip
    # mode just after a break-away and with the seal heating's extra states
    c = case(1.0)
    if heating:
        c = c.model_copy(update={"thermal": ThermalModel()})
    system = PneumaticSystem(c, build_seals(c, EXAMPLES))
    y = system.initial_state()
    y[0], y[1] = 0.03, 2e-6
    whole, column, rate = _jacobian_and_velocity_column(system, y, last_evaluated=y)
    assert np.array_equal(column[:, 1], whole[:, 1])
    assert np.isnan(np.delete(column, 1, axis=1)).all()      # no other column touched
    assert rate == whole[1, 1]


def test_velocity_column_takes_no_loads_of_another_state():
    # after a failed Newton iteration the BDF renews ∂f/∂v at the predicted state y while the
    # last evaluation was at the last iterate, with other pressures and so other contact
    # loads: the column must still be the Jacobian's at y (it took the iterate's loads, and
    # its difference quotient was the iterate's change of the friction force over h_v)
    c = case(1.0)
    system = PneumaticSystem(c, build_seals(c, EXAMPLES))
    y = system.initial_state()
    y[0], y[1] = 0.03, 2e-6
    iterate = y.copy()
    iterate[4] *= 1.001                      # 0.1 % more internal energy: another p1 and Δp
    whole, column, rate = _jacobian_and_velocity_column(system, y, last_evaluated=iterate)
    assert np.array_equal(column[:, 1], whole[:, 1])
    assert rate == whole[1, 1]


def test_a_seal_without_a_thermal_node_has_a_zero_temperature_column():
    # seal heating: the wiper (no cord diameter) is no thermal node; its temperature slot is
    # read by nothing, and its Jacobian column is 0 exactly -- the forward difference of the
    # full evaluation would give 0 as well, at the cost of one right-hand side
    c = case(1.0).model_copy(update={"thermal": ThermalModel()})
    system = PneumaticSystem(c, build_seals(c, EXAMPLES))
    heated = system.tables[3][:, rhs.SI_HEATED]
    assert list(heated) == [1, 1, 0]
    y = system.initial_state()
    y[0], y[1] = 0.03, 0.2
    n, ndyn = system.n_states, system.n_dynamic
    scale = system.tolerances(1.0)[:ndyn].copy()
    jac = np.full((n, ndyn), np.nan)
    rhs.jacobian(0.5, y, rhs.FORWARD, system.tables, scale, np.zeros(n), np.zeros(n),
                 np.zeros(n), np.zeros((system.n_diag, 1)), jac)
    wiper = system.temperature_offset + 2
    assert (jac[:, wiper] == 0.0).all()
    # the forward difference itself: the same zeros
    h = 1.5e-8 * max(abs(y[wiper]), scale[wiper])
    shifted = y.copy()
    shifted[wiper] += h
    f0, f1 = system.evaluate(0.5, y, rhs.FORWARD).copy(), system.evaluate(0.5, shifted,
                                                                           rhs.FORWARD)
    assert np.array_equal(f1, f0)
    assert np.isfinite(jac).all() and (jac[:, system.temperature_offset] != 0.0).any()
