"""The frictionless cylinder: static force A·Δp, motion against an independent integration, end
stops and the initial state."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from sealsim.cases import apply_overrides, load_toml, validate_case
from sealsim.errors import InputError, ModelError
from sealsim.pneumatic import PneumaticCase, simulate
from sealsim.pneumatic.case import load_pneumatic_cases
from sealsim.pneumatic.chambers import (
    AIR_GAS_CONSTANT,
    chamber_wall_area,
    pressure_rate,
    temperature_rate,
)
from sealsim.pneumatic.cylinder import end_stop_force, piston_areas
from sealsim.pneumatic.valve import (
    ANR_DENSITY,
    ANR_TEMPERATURE,
    iso6358_flow,
    port_openings,
    series_conductance,
    spool_response,
)

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pneumatic"


def frictionless(overrides: dict) -> PneumaticCase:
    """cylinder_32.toml without seals, with overrides (nested dict, units as in files)."""
    data = load_toml(EXAMPLES / "cylinder_32.toml")
    data.pop("variants")
    data["seals"] = []
    return validate_case(PneumaticCase, apply_overrides(data, overrides))


def test_static_force_is_area_times_pressure_difference():
    # A frictionless piston pushes a load spring k = 2e4 N/m (with a damper to settle it).  At
    # rest p1 = supply, p2 = ambient, so k·x = p1·A1 − p2·A2 − p_a·A_rod = A1·Δp (Δp = 6 bar):
    # x = 24.13 mm.  Tolerance 1e-5 relative (pressures settle exponentially through the
    # laminar region of the valve, time constant ms).  Adiabatic chambers (h = 0): with wall
    # heat the hot filled air would still be cooling (time constant ≈ 1 s) and refilling.
    case = frictionless({"load": {"mass": "1 kg", "force": "0 N", "stiffness": "2e4 N/m",
                                  "viscous": "300 N*s/m"},
                         "air": {"heat_transfer_coefficient": "0 W/(m**2*K)"},
                         "controller": {"duration": "2 s",
                                        "steps": [{"command": "extend", "duration": "2 s"}]}})
    result = simulate(case)
    end = result.timeseries.iloc[-1]
    a1, _, _ = piston_areas(0.032, 0.012)
    force = a1 * case.air.supply_pressure
    assert end["F_pressure_N"] == pytest.approx(force, rel=1e-5)
    assert end["x_m"] == pytest.approx(force / 2e4, rel=1e-5)
    assert end["p1_bar_abs"] == pytest.approx(case.air.supply_absolute / 1e5, rel=1e-6)
    assert abs(end["v_m_s"]) < 1e-6


def test_static_force_with_gravity():
    # vertical, extending upwards: k·x = A1·Δp − M·g (M = piston 0.35 kg + load 5 kg)
    case = frictionless({"cylinder": {"incline": "90 deg"},
                         "load": {"mass": "5 kg", "force": "0 N", "stiffness": "2e4 N/m",
                                  "viscous": "300 N*s/m"},
                         "air": {"heat_transfer_coefficient": "0 W/(m**2*K)"},
                         "controller": {"duration": "2 s",
                                        "steps": [{"command": "extend", "duration": "2 s"}]}})
    end = simulate(case).timeseries.iloc[-1]
    a1, _, _ = piston_areas(0.032, 0.012)
    expected = (a1 * case.air.supply_pressure - 5.35 * 9.80665) / 2e4
    assert end["x_m"] == pytest.approx(expected, rel=1e-5)


def test_meter_out_speed_is_the_choked_exhaust_flow():
    # One-way flow control valves (C = 0.1 dm³/(s·bar)) throttle the exhaust of the rod side:
    # the chain valve path + throttle is choked, so the volume flow leaving chamber 2 at its
    # own state is Q = C_s·ρ0·R·sqrt(T0·T2) (ISO 6358, C_s the series conductance) whatever its
    # pressure, and the piston speed is v = Q/A2 -- for a light and a heavy load.  Mid-stroke
    # the simulated speed matches within 6 % (the compressibility of chamber 2 adds
    # (V2/(γ·p2))·dp2/dt while its pressure still changes: adiabatic walls, so that this is the
    # whole correction); without throttles it is 2.5× faster.
    a1, a2, _ = piston_areas(0.032, 0.012)
    c_s = series_conductance(3e-9, 1e-9)
    for load in (20, 200):
        base = {"load": {"force": f"{load} N"},
                "air": {"heat_transfer_coefficient": "0 W/(m**2*K)"},
                "controller": {"duration": "1.2 s",
                               "steps": [{"command": "extend", "duration": "2 s"}]}}
        throttled = frictionless({**base, "valve": {"meter_out": {
            "conductance_a": "0.1 dm**3/(s*bar)", "conductance_b": "0.1 dm**3/(s*bar)"}}})
        f = simulate(throttled).timeseries
        mid = (f["x_m"] > 0.03) & (f["x_m"] < 0.07)
        t2 = f["T2_C"][mid] + 273.15
        v_choked = c_s * ANR_DENSITY * AIR_GAS_CONSTANT * np.sqrt(ANR_TEMPERATURE * t2) / a2
        assert np.all(np.abs(f["v_m_s"][mid] / v_choked - 1.0) < 0.06)
        free = simulate(frictionless(base)).timeseries
        mid_free = (free["x_m"] > 0.03) & (free["x_m"] < 0.07)
        assert free["v_m_s"][mid_free].mean() > 2.5 * f["v_m_s"][mid].mean()


def independent_extension(case: PneumaticCase, t_end: float, samples: np.ndarray):
    """The same cylinder written in pressure–temperature states (Richer & Hurmuzlu, J. Dyn.
    Syst. Meas. Control 122 (2000) 416) and integrated with a different method (Radau, rtol 1e-8).  Shares only
    the validated component functions (ISO 6358 flow, spool lag, stop force)."""
    cyl, air, valve, load = case.cylinder, case.air, case.valve, case.load
    a1, a2, ar = piston_areas(cyl.bore, cyl.rod_diameter)
    mass = cyl.piston_mass + load.mass
    ps, pa, ta = air.supply_absolute, air.ambient_pressure, air.temperature
    h, length = air.heat_transfer_coefficient, cyl.stroke
    es = cyl.end_stops

    def rhs(t, s):
        x, v, p1, p2, t1, t2 = s
        spool = spool_response(t, [0.0], [1.0], valve.time_constant, valve.delay, -1.0)
        o_pa, o_ar, o_pb, o_br = port_openings(spool, "5/2")
        c, b = valve.conductance, valve.critical_pressure_ratio
        g_pa = iso6358_flow(ps, ta, p1, t1, c * o_pa, b)      # supply → chamber 1
        g_ar = iso6358_flow(p1, t1, pa, ta, c * o_ar, b)      # chamber 1 → exhaust
        g_pb = iso6358_flow(ps, ta, p2, t2, c * o_pb, b)
        g_br = iso6358_flow(p2, t2, pa, ta, c * o_br, b)
        v1 = cyl.dead_volume_cap + a1 * x
        v2 = cyl.dead_volume_rod + a2 * (length - x)
        q1 = h * chamber_wall_area(x + cyl.dead_volume_cap / a1, cyl.bore, a1) * (ta - t1)
        q2 = h * chamber_wall_area(length - x + cyl.dead_volume_rod / a2, cyl.bore, a2,
                                   cyl.rod_diameter) * (ta - t2)

        def split(g_in_path, g_out_path, t_chamber):
            inflow = max(g_in_path, 0.0) + max(-g_out_path, 0.0)
            outflow = max(-g_in_path, 0.0) + max(g_out_path, 0.0)
            t_in = (max(g_in_path, 0.0) * ta + max(-g_out_path, 0.0) * ta) / inflow \
                if inflow > 0 else ta
            return inflow, t_in, outflow

        in1, tin1, out1 = split(g_pa, g_ar, t1)
        in2, tin2, out2 = split(g_pb, g_br, t2)
        force = (p1 * a1 - p2 * a2 - pa * ar - load.force
                 + end_stop_force(x, v, length, es.stiffness, es.damping, es.damping_depth))
        return [v, force / mass,
                pressure_rate(p1, v1, a1 * v, in1, tin1, out1, t1, q1),
                pressure_rate(p2, v2, -a2 * v, in2, tin2, out2, t2, q2),
                temperature_rate(p1, v1, a1 * v, in1, tin1, out1, t1, q1),
                temperature_rate(p2, v2, -a2 * v, in2, tin2, out2, t2, q2)]

    # at rest in the cap stop, which carries the pressure force and the load
    start = [(pa * a1 - ps * a2 - pa * ar - load.force) / es.stiffness, 0.0, pa, ps, ta, ta]
    sol = solve_ivp(rhs, (0.0, t_end), start, method="Radau", rtol=1e-8, atol=1e-10,
                    t_eval=samples, max_step=1e-3)
    assert sol.success
    return sol.y


def test_frictionless_motion_matches_an_independent_integration():
    # Extension of the Ø32 cylinder (1 kg, 20 N load, valve C = 0.3 dm³/(s·bar), wall heat) to
    # the end stop: the sealsim model in (m, U) states with LSODA and the independent (p, T)
    # formulation with Radau agree within 1 % (the tolerance) of the stroke and of the
    # supply pressure -- in fact within 0.05 % of the stroke.
    case = frictionless({"controller": {"duration": "0.6 s",
                                        "steps": [{"command": "extend", "duration": "1 s"}]}})
    result = simulate(case)
    f = result.timeseries
    ref = independent_extension(case, 0.6, f["time_s"].to_numpy())
    stroke, supply = case.cylinder.stroke, case.air.supply_absolute
    assert np.max(np.abs(f["x_m"] - ref[0])) < 0.01 * stroke
    assert np.max(np.abs(f["p1_bar_abs"] * 1e5 - ref[2])) < 0.01 * supply
    assert np.max(np.abs(f["p2_bar_abs"] * 1e5 - ref[3])) < 0.01 * supply
    assert np.max(np.abs(f["T1_C"] + 273.15 - ref[4])) < 0.01 * 298.15
    # the tighter statement actually achieved (rtol 1e-5 of the default solver settings)
    assert np.max(np.abs(f["x_m"] - ref[0])) < 5e-4 * stroke
    assert f["x_m"].iloc[-1] > 0.99 * stroke          # it did reach the end stop


def test_piston_rests_against_the_end_stop_with_its_static_deflection():
    # at the end of the extension the pressure force A1·Δp + 20 N load... presses the piston
    # into the elastic stop: δ = F/k (k = 2e6 N/m) within 1e-3 relative
    case = frictionless({"controller": {"duration": "1.5 s",
                                        "steps": [{"command": "extend", "duration": "2 s"}]}})
    end = simulate(case).timeseries.iloc[-1]
    a1, _, _ = piston_areas(0.032, 0.012)
    force = a1 * case.air.supply_pressure - case.load.force
    assert end["x_m"] - case.cylinder.stroke == pytest.approx(force / 2e6, rel=1e-3)


def test_initial_state_follows_the_rest_position_of_the_valve():
    # initial command retract: the piston starts retracted with the rod side at supply, at
    # rest in the cap stop, which carries the pressure force and the load: δ = F/k
    case = frictionless({"controller": {"duration": "0.01 s"}})
    frame = simulate(case).timeseries
    first = frame.iloc[0]
    _, a2, a_rod = piston_areas(0.032, 0.012)
    force = (a2 * case.air.supply_absolute + a_rod * case.air.ambient_pressure
             - case.air.ambient_pressure * (a2 + a_rod) + case.load.force)   # 434.7 N
    assert first["x_m"] == pytest.approx(-force / 2e6, rel=1e-12)
    assert first["p2_bar_abs"] == pytest.approx(case.air.supply_absolute / 1e5, rel=1e-12)
    assert first["p1_bar_abs"] == pytest.approx(case.air.ambient_pressure / 1e5, rel=1e-12)
    # and stays there until the valve moves (6 ms dead time).  Started at x = 0 the piston
    # was thrown into the stop at 0.15 m/s within 1 ms, with a start-up friction peak (seals
    # on) that the summary reported as the run's peak friction.
    before = frame[frame["time_s"] <= 0.006]
    assert np.abs(before["v_m_s"]).max() < 1e-12
    assert np.ptp(before["x_m"]) < 1e-12


def test_a_run_with_seals_starts_at_rest_and_its_peak_friction_is_the_break_away():
    # cylinder_32 (Θ-law seals, at rest on the stop for 6 ms): no motion before the valve
    # switches, and the largest friction of the run comes after that, at the break-away
    data = load_toml(EXAMPLES / "cylinder_32.toml")
    data = apply_overrides(data, data.pop("variants")["T25C"])
    data["controller"]["duration"] = "0.05 s"
    result = simulate(load_pneumatic_cases(data)["base"])
    frame = result.timeseries
    before = frame[frame["time_s"] <= 0.006]
    assert np.abs(before["v_m_s"]).max() == 0.0 and (before["mode"] == "stick").all()
    assert np.abs(before["F_friction_N"]).max() < 1e-6
    peak = frame.loc[frame["F_friction_N"].abs().idxmax()]
    assert peak["time_s"] > 0.006 and peak["F_friction_N"] > 0      # against the extension


def test_end_cushion_brakes_the_piston_before_the_stop():
    # Over the last 10 mm the rod-side air must leave through the cushioning needle
    # (C = 0.05 dm³/(s·bar)): the trapped air is compressed above the supply pressure and the
    # piston reaches the stop at about a third of its speed (asserted: < 50 %); without it, it
    # hits the stop at full speed (0.42 m/s).
    def run(cushion):
        over = {"controller": {"duration": "1 s",
                               "steps": [{"command": "extend", "duration": "2 s"}]}}
        if cushion:
            over["cylinder"] = {"cushion_rod": {"length": "10 mm",
                                                "conductance": "0.05 dm**3/(s*bar)"}}
        f = simulate(frictionless(over)).timeseries
        before = f[f["x_m"] < 0.0995]
        return before["v_m_s"].iloc[-1], f["p2_bar_abs"].max()

    v_free, p_free = run(False)
    v_cushioned, p_cushioned = run(True)
    assert v_cushioned < 0.5 * v_free
    assert p_cushioned > 7.013 > p_free - 0.5        # the cushion pressure exceeds the supply


def test_a_stalled_piston_is_noted():
    # 6 bar on the Ø32 piston push with A1·Δp = 483 N: against 600 N the piston cannot extend,
    # the extend time is None and a note says that no extend command reached the end and how
    # far the piston got; 20 N (the example's load) completes every stroke and has no such note
    stalled = simulate(frictionless({"load": {"force": "600 N"}}))
    assert stalled.summary()["extend_time_s"] is None
    assert [n for n in stalled.notes if n.startswith(
        "2 of 2 extend commands did not reach the extended end: the piston got no further "
        "than 0 mm of the 100 mm stroke")]
    free = simulate(frictionless({}))
    assert free.summary()["extend_time_s"] is not None
    assert not [n for n in free.notes if "did not reach" in n]


def test_a_run_in_which_nothing_moves_closes_its_balances():
    # retract only: the piston rests in the cap stop and no air flows.  The energy throughput
    # is ~1e-14 J, the round-off of U1 + U2 (~100 J) about as large: scaled by the initial
    # internal energy (as the mass by the initial mass) the error is round-off, not the 1.28
    # it was relative to the throughput alone
    case = frictionless({"controller": {"duration": "0.5 s", "steps": [
        {"command": "retract", "duration": "0.5 s"}]}})
    result = simulate(case)
    assert np.ptp(result.timeseries["x_m"]) < 1e-12
    assert result.balances["mass_balance_rel_error"] < 1e-12
    assert result.balances["energy_balance_rel_error"] < 1e-12


def test_a_dead_volume_smaller_than_the_bumper_travel_is_refused():
    # 0.1 cm^3 at the cap: resting in the stop under 435 N (delta = 0.22 mm) the piston
    # sweeps 0.17 cm^3 -- the chamber had a negative volume, p1 -1536 bar and T1 -253 degC,
    # and the run "completed" with a peak friction of 118 kN
    with pytest.raises(InputError, match=r"cylinder.dead_volume_cap: 0.1 cm\^3 .* 0.2173 mm"):
        simulate(frictionless({"cylinder": {"dead_volume_cap": "0.1 cm**3"}}))
    # 0.1 cm^3 at the rod end: the piston runs into the head stop at speed (2.4 mm deep)
    with pytest.raises(ModelError, match="cylinder.dead_volume_rod"):
        simulate(frictionless({"cylinder": {"dead_volume_rod": "0.1 cm**3"},
                               "controller": {"duration": "1 s"}}))
