"""Frictional heating of the seals (issue 13): energy balance, adiabatic heating, steady state,
and the temperature following of the contact map and the Θ law."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sealsim.cases import apply_overrides, load_toml, validate_case
from sealsim.pneumatic import PneumaticCase, build_seals, simulate
from sealsim.pneumatic import rhs
from sealsim.pneumatic.seal_heating import (
    ambient_coefficient,
    sliding_contact_coefficient,
    steady_seal_temperature,
)
from sealsim.pneumatic.simulation import run
from sealsim.pneumatic.system import PneumaticSystem

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pneumatic"


def heated(name: str, overrides: dict | None = None, variant: str = "T25C",
           position: dict | None = None) -> PneumaticCase:
    data = load_toml(EXAMPLES / name)
    data = apply_overrides(data, data.pop("variants")[variant])
    data["thermal"] = {"seal_heating": True}
    data = apply_overrides(data, overrides or {})
    if position is not None:
        data["controller"]["position"] = position
    return validate_case(PneumaticCase, data)


def test_heat_balance_closes_and_the_seals_warm():
    # friction heat = heat stored in seals, tube and rod + heat into the air + heat to the
    # surroundings: bookkeeping states of the same ODE, so the balance is an integration check
    # (< 1 % required; it closes to round-off because every term is linear in the states)
    result = simulate(heated("cylinder_32.toml", {"controller": {"duration": "2 s"}}))
    b = result.balances
    assert b["seal_friction_heat_J"] > 1.0
    assert b["heat_balance_rel_error"] < 1e-6
    f = result.timeseries
    for seal in ("piston", "rod"):
        assert f[f"T_{seal}_C"].iloc[-1] > f[f"T_{seal}_C"].iloc[0]
    assert f["T_tube_metal_C"].iloc[-1] > 25.0 and f["T_rod_metal_C"].iloc[-1] > 25.0
    assert b["energy_balance_rel_error"] < 1e-3 and b["mass_balance_rel_error"] < 1e-12
    assert result.summary()["seals"]["piston"]["temperature_end_C"] > 25.0
    # the whole system, air + piston + seals + metal: the friction work the piston loses is
    # the heat the seals release (same F·v, two integrals: round-off), and the net enthalpy
    # of the air = the energy the air, the piston and the metal store + work on the load and
    # the atmosphere + work into the end stops + heat to the surroundings (the run's
    # integration error of the air's energy: -0.0036 J of the net 12.27 J over these 2 s,
    # 3e-4; 1e-3 required)
    assert b["friction_work_J"] == pytest.approx(b["seal_friction_heat_J"], rel=1e-9)
    stored = b["air_energy_change_J"] + b["kinetic_energy_change_J"] + b[
        "thermal_heat_stored_J"]
    out = -b["external_work_J"] - b["stop_work_J"] + b["thermal_heat_to_ambient_J"]
    assert b["enthalpy_in_J"] == pytest.approx(stored + out, rel=1e-3)


def rig_system(profile: dict, rtol: float = 1e-5) -> PneumaticSystem:
    case = heated("friction_rig.toml", {"controller": {"duration": profile.pop("duration")},
                                        "solver": {"rtol": rtol}}, position=profile)
    return PneumaticSystem(case, build_seals(case, EXAMPLES))


def test_seal_without_conductances_heats_as_friction_power_over_heat_capacity():
    # all conductances of the seal node zero: C·dT/dt = F·v, so C·ΔT equals the friction work
    # (both are integrated by the same linear steps: agreement to round-off, 1e-9)
    system = rig_system({"kind": "harmonic", "mean": "50 mm", "amplitude": "50 mm",
                         "angular_frequency": "10 rad/s", "phase": "180 deg",
                         "duration": "0.7 s"})
    therm = system.tables[5]
    for col in (rhs.ST_EFF, rhs.ST_HSTAT, rhs.ST_GGROOVE, rhs.ST_AIR1, rhs.ST_AIR2, rhs.ST_AMB):
        therm[0, col] = 0.0
    result = run(system)
    f = result.timeseries
    rise = f["T_test_seal_C"].iloc[-1] - f["T_test_seal_C"].iloc[0]
    assert rise > 1.0
    assert therm[0, rhs.ST_CAP] * rise == pytest.approx(
        result.balances["seal_friction_heat_J"], rel=1e-9)


def test_steady_seal_temperature_matches_the_closed_form():
    # constant sliding (0.05 m/s over the stroke) with the tube and rod held (huge heat
    # capacity): the seal settles at T_s = (P + Σ G_k T_k)/Σ G_k with its contact, groove, air
    # conductances at the end state (seal time constant C/G ~ 0.1 s << the 2 s run; Θ and
    # F·v change by < 0.1 % over the last C/G, hence 1 % of the rise)
    system = rig_system({"kind": "piecewise", "times": ["0 s", "2 s"],
                         "values": ["0 mm", "100 mm"], "duration": "1.9 s"}, rtol=1e-9)
    c = system.tables[0]
    c[rhs.C_TUBE_CAP] = c[rhs.C_ROD_CAP] = 1e15
    result = run(system)
    end = result.timeseries.iloc[-1]
    th = system.tables[5][0]
    v = float(end["v_m_s"])
    width = float(end["b_test_seal_mm"]) * 1e-3
    g_contact = sliding_contact_coefficient(v, width, th[rhs.ST_EFF], th[rhs.ST_HSTAT]) * (
        th[rhs.ST_AC] * width)
    t_body = 298.15
    expected = steady_seal_temperature(
        float(end["F_test_seal_N"]) * v,
        [g_contact, th[rhs.ST_GGROOVE], th[rhs.ST_AIR1], th[rhs.ST_AIR2], th[rhs.ST_AMB]],
        [t_body, t_body, end["T1_C"] + 273.15, end["T2_C"] + 273.15, 298.15])
    rise = expected - t_body
    assert rise > 0.05
    assert end["T_test_seal_C"] + 273.15 - t_body == pytest.approx(rise, rel=0.01)


def test_contact_map_and_grease_follow_the_seal_temperature():
    # a heated seal evaluates its map and γ(T) at its own temperature: a rig run whose seal
    # starts at 55 °C in a 25 °C cylinder cools towards the tube, and its F_N follows the
    # analytic map at the logged temperature (tabulated map: 1e-3 relative)
    case = heated("friction_rig.toml", {"controller": {"duration": "0.6 s"},
                                        "seals": [{"name": "test seal", "location": "piston",
                                                   "friction": {"law": "theta",
                                                                "parameter_set":
                                                                    "pneumatic_demo"},
                                                   "map": {"analytic": {
                                                       "cord_diameter": "2 mm",
                                                       "squeeze": 0.10}},
                                                   "temperature": "55 degC"}]})
    seals = build_seals(case, EXAMPLES)
    f = simulate(case, seals).timeseries
    temp = f["T_test_seal_C"].to_numpy() + 273.15
    assert temp[0] == pytest.approx(328.15) and temp[-1] < temp[0] - 5.0
    fn, _ = seals[0].contact_map.evaluate(f["dp_test_seal_bar"].to_numpy() * 1e5, temp)
    np.testing.assert_allclose(f["F_N_test_seal_N"], fn, rtol=1e-3)
    # the tabulated map is kept on the map object: a second run of the same seals uses it
    # and gives the same time series to the last bit
    assert vars(seals[0].contact_map)["_tabulated_tables"]
    np.testing.assert_array_equal(simulate(case, seals).timeseries["F_N_test_seal_N"],
                                  f["F_N_test_seal_N"])


def test_piston_faces_and_rod_surface_exchange_heat_with_the_moving_metal_node():
    # With seal heating the barrel and the cap and head faces are the tube node; the piston's
    # faces (A1 in chamber 1, the annulus A2 in chamber 2) and the rod's surface in the rod-side
    # chamber, π·d·l2, are the piston-and-rod node:
    #   q1 = h·(A_w1 − A1)·(T_tube − T1) + h·A1·(T_rod − T1)
    #   q2 = h·(A_w2 − A_rod − A2)·(T_tube − T2) + h·(A_rod + A2)·(T_rod − T2)
    # (before, the piston's faces were at the tube's temperature, the tube gave their heat).
    # Chamber air and metal nodes at different temperatures, no seals; the two metal nodes'
    # rates against the hand balances, to round-off.
    from sealsim.pneumatic.chambers import chamber_wall_areas, gas_mass, internal_energy

    case = heated("cylinder_32.toml").model_copy(update={"seals": []})
    system = PneumaticSystem(case, [])
    cyl, h, c = case.cylinder, case.air.heat_transfer_coefficient, system.tables[0]
    x, t1, t2, t_tube, t_rod = 0.04, 330.0, 260.0, 300.0, 320.0
    vol1 = cyl.dead_volume_cap + system.a1 * x
    vol2 = cyl.dead_volume_rod + system.a2 * (cyl.stroke - x)
    y = system.initial_state()
    m1, m2 = float(gas_mass(4e5, vol1, t1)), float(gas_mass(2e5, vol2, t2))
    y[:6] = [x, 0.0, m1, m2, float(internal_energy(m1, t1)), float(internal_energy(m2, t2))]
    toff = system.temperature_offset
    y[toff], y[toff + 1] = t_tube, t_rod
    d = system.evaluate(0.0, y, rhs.FORWARD, full=True)
    a1, a2 = system.a1, system.a2
    a_w1, a_w2, a_rod = chamber_wall_areas(x, cyl.stroke, cyl.bore, cyl.rod_diameter, a1, a2,
                                           cyl.dead_volume_cap, cyl.dead_volume_rod)
    q1_tube, q1_rod = h * (a_w1 - a1) * (t_tube - t1), h * a1 * (t_rod - t1)
    q2_tube, q2_rod = h * (a_w2 - a_rod - a2) * (t_tube - t2), h * (a_rod + a2) * (t_rod - t2)
    assert d["q1"][0] == pytest.approx(q1_tube + q1_rod, rel=1e-12)
    assert d["q2"][0] == pytest.approx(q2_tube + q2_rod, rel=1e-12)
    # the rod is outside the cylinder over the piston's extension x only
    h_amb = ambient_coefficient(cyl.rod_diameter, system.t_amb + 10.0, system.t_amb, 0.1)
    rod_rate = (-q1_rod - q2_rod - h_amb * np.pi * cyl.rod_diameter * x * (
        t_rod - system.t_amb)) / c[rhs.C_ROD_CAP]
    assert d["dy"][toff + 1, 0] == pytest.approx(rod_rate, rel=1e-12)
    tube_od, tube_length = cyl.bore + 2 * 4e-3, cyl.stroke + 0.05
    h_tube = ambient_coefficient(tube_od, system.t_amb + 10.0, system.t_amb, 0.82)
    tube_rate = (-q1_tube - q2_tube - h_tube * np.pi * tube_od * tube_length * (
        t_tube - system.t_amb)) / c[rhs.C_TUBE_CAP]
    assert d["dy"][toff, 0] == pytest.approx(tube_rate, rel=1e-12)


@pytest.mark.parametrize("x_frac", [0.0, 0.5, 1.0])
def test_rod_loses_heat_to_the_surroundings_over_its_extended_length_only(x_frac):
    # The rod's surface outside the cylinder is π·d·x (retracted, x = 0, it is all in the
    # rod-side chamber and the head; it was π·d·L at every position, twice the loss over a
    # cycle).  Rod node warmer than the air around it, chamber air at the rod temperature (no
    # heat to the air): C_rod·dT_rod/dt = −h·π·d·x·(T_rod − T_amb), h of a horizontal Ø12
    # chromed rod (Churchill & Chu + radiation, ε = 0.1, 10 K above ambient), to round-off.
    from sealsim.pneumatic.chambers import gas_mass, internal_energy

    case = heated("cylinder_32.toml").model_copy(update={"seals": []})
    system = PneumaticSystem(case, [])
    cyl, c = case.cylinder, system.tables[0]
    x, t_rod = x_frac * cyl.stroke, 318.15
    vol1 = cyl.dead_volume_cap + system.a1 * x
    vol2 = cyl.dead_volume_rod + system.a2 * (cyl.stroke - x)
    y = system.initial_state()
    m1, m2 = float(gas_mass(4e5, vol1, t_rod)), float(gas_mass(2e5, vol2, t_rod))
    y[:6] = [x, 0.0, m1, m2, float(internal_energy(m1, t_rod)),
             float(internal_energy(m2, t_rod))]
    toff = system.temperature_offset
    y[toff], y[toff + 1] = t_rod, t_rod
    d = system.evaluate(0.0, y, rhs.FORWARD, full=True)
    h_amb = ambient_coefficient(cyl.rod_diameter, system.t_amb + 10.0, system.t_amb, 0.1)
    expected = -h_amb * np.pi * cyl.rod_diameter * x * (t_rod - system.t_amb)
    assert d["dy"][toff + 1, 0] * c[rhs.C_ROD_CAP] == pytest.approx(expected, abs=1e-12)


def test_rod_node_holds_the_heat_capacity_of_piston_and_rod():
    # The rod node is the moving metal that the piston seal's groove and the rod seal heat:
    # piston + rod, cylinder.piston_mass = 0.35 kg of steel (c = 434 J/(kg·K), Incropera
    # Table A.1), 152 J/K; it was the rod alone (Ø12 × 150 mm, 0.13 kg, 58 J/K), so the rod
    # and rod seal warmed 2.6 times too fast.  A rod of 0.2 kg in a 0.1 kg "piston + rod"
    # keeps the rod's own capacity and says so.
    case = heated("cylinder_32.toml").model_copy(update={"seals": []})
    system = PneumaticSystem(case, [])
    assert case.cylinder.piston_mass == pytest.approx(0.35)
    assert system.tables[0][rhs.C_ROD_CAP] == pytest.approx(0.35 * 434.0, rel=1e-12)
    assert system.thermal_notes == []
    light = heated("cylinder_32.toml", {"cylinder": {"piston_mass": "0.1 kg"}}).model_copy(
        update={"seals": []})
    system = PneumaticSystem(light, [])
    rod_mass = 7832.0 * np.pi / 4 * 0.012 ** 2 * (0.1 + 0.05)
    assert system.tables[0][rhs.C_ROD_CAP] == pytest.approx(rod_mass * 434.0, rel=1e-12)
    assert "less than the rod's own mass" in system.thermal_notes[0]


def test_outer_flanks_see_the_surroundings_at_the_nominal_temperature_rise():
    # thermal.nominal_temperature_rise sets every coefficient to the surroundings: the outer
    # flank of the rod seal (half the cord outside its contacts) as well as the tube and rod;
    # the flank took a fixed 10 K whatever the case said.  30 K: h of a Ø14 mm ring of rubber
    # (ε = 0.9) 30 K above 25 °C air, Churchill & Chu + radiation, to round-off.
    from sealsim.pneumatic.seal_heating import seal_flank_area

    case = heated("cylinder_32.toml", {"thermal": {"nominal_temperature_rise": "30 K"}})
    system = PneumaticSystem(case, build_seals(case, EXAMPLES))
    rod = [s.name for s in system.seals].index("rod")
    th = system.tables[5][rod]
    ring, cord = 0.012 + 0.002, 0.002
    h_out = ambient_coefficient(ring, 298.15 + 30.0, 298.15, 0.9)
    assert th[rhs.ST_AMB] == pytest.approx(
        h_out * float(seal_flank_area(ring, cord, th[rhs.ST_WIDTH])), rel=1e-12)
