"""Rotary lip-seal FMU (issue 14): steady torque at and between the grid points and the
transient of the speed-cycle example against sealsim's full coupled model.

One FMU is built per session on a small grid (speed_points = 7, 5 sump temperatures, step
responses at 2 speeds per flow regime x 2 sump temperatures); the checks run the full model
independently.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import fmpy  # the test extra installs FMPy
from fmpy import simulate_fmu
from fmpy.validation import validate_fmu
from session_builds import built, session_build

from sealsim.cases import expand_variants, load_toml
from sealsim.errors import InputError, ModelError
from sealsim.fmu import LoadedFMU, build_rotary_fmu
from sealsim.fmu.case import RotarySettings
from sealsim.fmu.cosim import run_rotary
from sealsim.fmu.rotary_maps import fixed_sump_case, flow_regime_boundaries
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import simulate, steady_state

RPM = math.pi / 30.0
CYCLE = Path(__file__).resolve().parents[1] / "examples" / "rotary" / "speed_cycle.toml"
SUMPS = np.array([20.0, 45.0, 70.0, 95.0, 120.0]) + 273.15


@pytest.fixture(scope="module")
def plain_case():
    return expand_variants(RotaryCase, load_toml(CYCLE), "speed cycle")["plain"]


@session_build("rotary_fmu", cost=25)
def build_the_rotary_fmu(folder):
    # the sump of the speed cycle stays within 23-69 degC: step responses at 20 and 70 degC
    settings = RotarySettings(speed_points=7, sump_temperatures=list(SUMPS), lag_points=2,
                              lag_sump_temperatures=[SUMPS[0], SUMPS[2]],
                              check_between=False, check_duty_cycle=False)
    plain = expand_variants(RotaryCase, load_toml(CYCLE), "speed cycle")["plain"]
    result = build_rotary_fmu(plain, folder / "lip_seal.fmu", settings=settings)
    return {"path": str(result.path), "report": result.report}


@pytest.fixture(scope="module")
def rotary_fmu(tmp_path_factory, worker_id):
    fmu = built(tmp_path_factory, worker_id, "rotary_fmu")
    return SimpleNamespace(path=Path(fmu["path"]), report=fmu["report"])


def steady_fmu(fmu, speed, sump):
    fmu.reset()
    fmu.set(speed=speed, T_sump=sump)
    fmu.initialize()
    return fmu.get("torque", "T_contact")


def full_steady(case, speed, sump):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        point = steady_state(fixed_sump_case(case, sump), speed)
    return point["torque_Nm"], point["T_contact_C"] + 273.15


def test_rotary_fmu_is_valid(rotary_fmu):
    assert validate_fmu(str(rotary_fmu.path)) == []
    names = {v.name: v for v in fmpy.read_model_description(str(rotary_fmu.path)).modelVariables}
    assert names["speed"].unit == "rad/s" and names["torque"].unit == "N.m"
    assert {"T_sump", "T_ambient", "power", "T_contact", "T_rise_1", "T_rise_2"} <= set(names)
    # nominal values of the states: kelvin near 300 and the largest rise (K), not 1
    assert 240.0 < float(names["T_sump_lagged"].nominal) < 400.0
    assert 1.0 <= float(names["T_rise_1"].nominal) < 100.0
    lag = rotary_fmu.report["thermal_lag"]
    assert lag["order"] == 2 and np.all(np.array(lag["settled"]) > 0.98)
    # the oil-side convection of this case changes its flow regime (Taylor vortices) between
    # 390 rpm in oil at 20 degC and 10 rpm at 120 degC: two tables
    steady = rotary_fmu.report["steady_map"]
    assert steady["regimes"] == 2
    boundary = np.array(steady["regime_boundaries_rpm"])[0]     # over the sump grid
    assert boundary[0] > boundary[-1] and 5.0 < boundary[-1] < boundary[0] < 1000.0


def test_steady_torque_at_and_between_grid_points(plain_case, rotary_fmu):
    nodes = [np.array(w) * RPM for w in rotary_fmu.report["steady_map"]["node_speeds_rpm"]]
    grid = [(nodes[1][1, 0], SUMPS[0]), (nodes[0][-2, 2], SUMPS[2]),
            (nodes[1][3, 4], SUMPS[4]), (nodes[1][-1, 1], SUMPS[1])]
    # cell centres of the test grid and, at 32.5 degC, both sides of the flow-regime boundary
    mid = 0.5 * (SUMPS[1:] + SUMPS[:-1])
    edge = float(flow_regime_boundaries(plain_case, [mid[0]])[0, 0])
    between = [(173.2 * RPM, mid[1]), (1732.0 * RPM, mid[3]), (17.32 * RPM, mid[2]),
               (548.0 * RPM, mid[0]), (0.9 * edge, mid[0]), (1.1 * edge, mid[0])]
    with LoadedFMU(rotary_fmu.path) as fmu:
        for speed, sump in grid:
            torque, contact = steady_fmu(fmu, speed, sump)
            ref_torque, ref_contact = full_steady(plain_case, speed, sump)
            # at grid points the contact temperature is the map's node value (the node lies
            # 1e-9 inside its flow regime); the torque table (friction at speed x contact
            # temperature) adds < 0.5 % (issue 14)
            assert torque == pytest.approx(ref_torque, rel=5e-3)
            assert contact == pytest.approx(ref_contact, abs=1e-6)
        for speed, sump in between:
            torque, contact = steady_fmu(fmu, speed, sump)
            ref_torque, ref_contact = full_steady(plain_case, speed, sump)
            # between grid points: interpolated maps, within 2 % (issue 14)
            assert torque == pytest.approx(ref_torque, rel=2e-2)
            assert contact == pytest.approx(ref_contact, abs=1.5)


def test_speed_cycle_transient(plain_case, rotary_fmu):
    """The example speed cycle (10 ... 1000 rpm, 2.25 h, free 0.2 L sump heated by the seal):
    the full transient model against the FMU fed with its speed and sump temperature."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        full = simulate(plain_case).timeseries
    t = full["time_s"].to_numpy()
    with LoadedFMU(rotary_fmu.path) as fmu:
        fmu.set(start_steady=False, T_contact_start=float(full["T_contact_C"].iloc[0] + 273.15))
        run = run_rotary(fmu, t, full["speed_rpm"].to_numpy() * RPM,
                         full["T_sump_C"].to_numpy() + 273.15)
    torque_error = np.abs(run["torque"] / full["torque_Nm"].to_numpy() - 1.0)
    # issue 14: the transient within 5 %
    assert torque_error.max() < 0.05
    contact_error = np.abs(run["T_contact"] - 273.15 - full["T_contact_C"].to_numpy())
    rise = (full["T_contact_C"] - full["T_sump_C"]).max()
    # the contact temperature within a fifth of its largest rise above the sump (16 K) on
    # this coarse grid
    assert contact_error.max() < rise / 5
    assert np.allclose(run["power"], run["torque"] * full["speed_rpm"].to_numpy() * RPM)


def test_rotary_inputs_out_of_range_are_clipped_and_me_settles(rotary_fmu):
    with LoadedFMU(rotary_fmu.path) as fmu:
        fmu.set(speed=5000 * RPM, T_sump=300.0)
        fmu.initialize()
        torque, clipped = fmu.get("torque", "map_clipped")
        assert np.isfinite(torque) and clipped == 1.0
        assert any("shaft speed" in m and "clipped" in m for s, _, m in fmu.messages
                   if s == "WARNING")
        fmu.set(speed=0.0)
        assert fmu.get("torque", "power") == [0.0, 0.0]      # at standstill: no friction
    # model exchange: from an equilibrium at 40 degC the contact settles to its steady value
    result = simulate_fmu(str(rotary_fmu.path), fmi_type="ModelExchange", stop_time=20000.0,
                          start_values={"speed": 1000 * RPM, "T_sump": 340.0,
                                        "start_steady": False, "T_contact_start": 313.15},
                          output=["T_contact", "T_contact_steady"], output_interval=100.0)
    assert result["T_contact"][0] == pytest.approx(313.15, abs=1e-9)
    # after > 20 slow time constants: steady within the solver tolerance
    assert result["T_contact"][-1] == pytest.approx(result["T_contact_steady"][-1], abs=1e-3)


def test_above_the_speed_table_all_outputs_are_those_of_its_top_speed(rotary_fmu):
    # torque and temperatures were clipped to the table's top speed while power was that
    # torque times the real speed: outputs of no single operating point
    import re
    import zipfile

    with zipfile.ZipFile(rotary_fmu.path) as archive:         # the table's top speed, exactly
        config = archive.read("sources/config.h").decode()
    top = float(re.search(r"#define STEADY_SPEED_HI (\S+)", config).group(1))
    assert top < 0.9 * 5000 * RPM                              # the test is above the table
    names = ("torque", "power", "T_contact", "T_contact_steady", "map_clipped")
    with LoadedFMU(rotary_fmu.path) as fmu:
        fmu.set(speed=-5000 * RPM, T_sump=330.0)
        fmu.initialize()
        above = dict(zip(names, fmu.get(*names)))
        assert any("shaft speed" in m and "clipped" in m for s, _, m in fmu.messages
                   if s == "WARNING")
        fmu.reset()
        fmu.set(speed=-top, T_sump=330.0)
        fmu.initialize()
        at_top = dict(zip(names, fmu.get(*names)))
    assert above["map_clipped"] == 1.0 and at_top["map_clipped"] == 0.0
    assert above["torque"] < 0.0                                   # against the speed
    # the same operating point (exactly: the same table values), power = |torque| * top
    for name in ("torque", "power", "T_contact", "T_contact_steady"):
        assert above[name] == at_top[name], name
    assert above["power"] == pytest.approx(-above["torque"] * top, rel=1e-15)


@pytest.mark.parametrize(("value", "bound"), [(80.0, "> 200 K"), (5000.0, "< 450 K")])
def test_a_start_temperature_outside_the_cases_range_is_refused(rotary_fmu, value, bound):
    # T_contact_start was only required > 0 K: 80 (meant as degC) started the contact at
    # 80 K and 5000 K at 5000 K, with a clip warning only.  Its range is now that of the
    # rotary case's environment.start_temperature.
    names = {v.name: v for v in fmpy.read_model_description(str(rotary_fmu.path)).modelVariables}
    assert names["T_contact_start"].unit == "K"
    with LoadedFMU(rotary_fmu.path) as fmu:
        fmu.set(speed=1000 * RPM, T_sump=330.0, start_steady=False, T_contact_start=value)
        with pytest.raises(ModelError, match=rf"parameter T_contact_start = {value:g} K is not "
                                             rf"allowed: it must be {bound}"):
            fmu.initialize()


def test_a_steady_map_beyond_the_rubber_names_the_fmu_fields_to_lower(plain_case):
    # 20000 rpm over a 120 degC sump: the NBR contact would pass 150 degC.  The rotary
    # model's message said "try a lower speed" but not which field of the FMU case sets it.
    from sealsim.errors import ModelError
    from sealsim.fmu.rotary_export import rotary_maps

    with pytest.raises(ModelError, match=r"outside the .* NBR model covers.*rotary.max_speed = "
                                         r"20000 rpm and rotary.sump_temperatures up to 120 "
                                         r"degC: lower them"):
        rotary_maps(plain_case, speed_max=20000 * RPM, speed_points=3,
                    sump_temperatures=[SUMPS[0], SUMPS[-1]], torque_speed_min=1 * RPM,
                    lag_points=1)


@pytest.mark.parametrize(("settings", "message"), [
    # torque_points = [1, 1] stopped after the maps (a minute) with "table axis 0: needs at
    # least two strictly ascending finite values, got [0.0953...]", no field named
    ({"torque_points": (1, 1)}, r"rotary.torque_points: \[1, 1\]; the torque table needs at "
                                r"least 2 nodes"),
    # the two messages named neither the values nor the range
    ({"lag_sump_temperatures": [473.15]}, r"rotary.lag_sump_temperatures: 200 degC must lie "
                                          r"between 20 degC and 120 degC"),
    ({"sump_temperatures": [333.15]}, r"rotary.sump_temperatures: 60 degC; give at least two"),
    # 500 degC went on to the steady states
    ({"sump_temperatures": [773.15, 873.15]}, r"rotary.sump_temperatures: 500 degC, 600 degC; "
                                              r"a rotary case's sump lies between -73.15 degC"),
])
def test_bad_rotary_map_settings_are_refused_before_the_maps_with_their_values(
        plain_case, settings, message):
    from sealsim.fmu.rotary_export import rotary_maps

    arguments = {"speed_max": 3000 * RPM, "speed_points": 3, "sump_temperatures": SUMPS,
                 "torque_speed_min": 1 * RPM, "lag_points": 1, **settings}
    with pytest.raises(InputError, match=message):
        rotary_maps(plain_case, **arguments)
