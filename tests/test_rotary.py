"""Rotary lip seal model (seed 000): claims of the seed, references, invariants, interface."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from sealsim.cases import validate_case
from sealsim.cli import app
from sealsim.errors import InputError
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.lip import default_radial_force, lip_force
from sealsim.rotary.simulation import friction_map, lip_seal_friction, simulate, steady_state
from sealsim.rotary.study import load_rotary_case

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "rotary"
RPM = math.pi / 30


def _case(**sections) -> RotaryCase:
    data = {"seal": {"shaft_diameter": "80 mm"},
            "duty": {"steps": [{"speed": "1000 rpm", "duration": "5 min"}]}}
    for key, value in sections.items():  # merge into the seal, replace other sections
        data[key] = {**data["seal"], **value} if key == "seal" else value
    return validate_case(RotaryCase, data)


@pytest.fixture(scope="module")
def speed_cycle():
    return {name: simulate(case) for name, case in
            load_rotary_case(EXAMPLES / "speed_cycle.toml").items()}


@pytest.fixture(scope="module")
def sump_volume():
    return {name: simulate(case) for name, case in
            load_rotary_case(EXAMPLES / "sump_volume.toml").items()}


def test_wave_lip_has_less_torque_and_runs_cooler(speed_cycle):
    # Seed 000 ("Comparison between molded wave and trimmed plain lips"): the wave lip reduces
    # the torque by about 20 % and the self-induced temperature by more than 10 °C.  The issue
    # asks 15-25 % (mean over the steps >= 100 rpm, last-30-s averages) and >= 10 K.
    plain, wave = speed_cycle["plain"].steps, speed_cycle["wave"].steps
    reductions = [1 - w["torque_Nm"] / p["torque_Nm"] for p, w in zip(plain, wave, strict=True)
                  if p["speed_rpm"] >= 100]
    assert 0.15 <= np.mean(reductions) <= 0.25
    assert plain[-1]["T_groove_C"] - wave[-1]["T_groove_C"] >= 10.0


def test_bigger_sump_is_cooler_and_has_more_friction(sump_volume):
    # Seed 000 Fig. 13: 3 L runs cooler than 0.2 L, its oil is more viscous, friction is higher
    small, big = sump_volume["sump_0.2L"].steps, sump_volume["sump_3L"].steps
    for s, b in zip(small, big, strict=True):
        assert b["T_sump_C"] < s["T_sump_C"]
        assert b["T_groove_C"] < s["T_groove_C"]
        assert b["torque_Nm"] > s["torque_Nm"]


def test_energy_balance_closes(speed_cycle, sump_volume):
    # heat generated = stored + dissipated; backward Euler conserves it exactly, so the 1 %
    # requirement is met with a margin of many orders of magnitude
    for result in [*speed_cycle.values(), *sump_volume.values()]:
        assert result.energy["rel_error"] < 1e-6
        assert result.energy["generated"] > 0


def test_temperatures_finite_and_friction_non_negative(speed_cycle):
    for result in speed_cycle.values():
        frame = result.timeseries
        assert np.all(np.isfinite(frame.select_dtypes("number").to_numpy()))
        assert (frame["torque_Nm"] >= 0).all() and (frame["power_W"] >= 0).all()
        assert (frame["F_lub_N"] >= 0).all() and (frame["F_material_N"] >= 0).all()


ISO_CASES = [(d, n) for d in (40, 80, 120) for n in (1000, 2000, 3000)]


@pytest.mark.parametrize(("diameter_mm", "rpm"), ISO_CASES)
def test_torque_within_factor_1p5_of_iso_tr_14179_2(diameter_mm, rpm):
    # ISO/TR 14179-2: P = 7.69e-6·d²·n [W] (d mm, n rpm), the gearbox-efficiency standard's seal
    # loss; VG 68, sump held at 80 °C, steady state, default seal of that size.  The issue
    # accepts a factor 1.5 (the ISO value is one constant for all seals, oils and temperatures).
    case = _case(seal={"shaft_diameter": f"{diameter_mm} mm"}, oil={"name": "VG68-mineral"},
                 environment={"sump_temperature": "80 degC"})
    result = steady_state(case, rpm * RPM)
    iso = 7.69e-6 * diameter_mm**2 * rpm
    assert 1 / 1.5 <= result["power_W"] / iso <= 1.5


def test_torque_rises_only_weakly_with_speed_in_lubricated_range():
    # Lubricated (hydrodynamic) branch, above the Stribeck minimum (≈ 1000 rpm at 80 °C):
    # F_lub ∝ (ηu)^0.34 at constant temperature (seed Eq. 4 and 5) while the rubber part falls
    # as the film grows, so the total rises, but by less than the viscous part's 3^0.34 = 1.45
    # from 1000 to 3000 rpm.
    frame = friction_map(_case(), [1000.0, 2000.0, 3000.0], [80.0])
    torque = frame["torque_Nm"].to_numpy()
    assert np.all(np.diff(torque) > 0)
    assert torque[-1] / torque[0] < 3**0.34


@pytest.mark.filterwarnings("ignore::sealsim.properties.elastomers.ServiceRangeWarning")
@settings(max_examples=60, deadline=None)
@given(rpm=st.floats(-6000, 6000), temperature=st.floats(-20, 140))
def test_friction_opposes_sliding(rpm, temperature):
    friction = lip_seal_friction(_case())
    state = friction.evaluate(rpm * RPM, temperature + 273.15)
    assert float(state.torque) * rpm >= 0  # torque has the sign of the speed: it opposes it
    assert float(state.power) >= 0  # dissipation is never negative
    assert float(state.force_lubricant) >= 0 and float(state.force_material) >= 0


def test_lip_force_spring_share_stays():
    # spring share constant, rubber share ∝ E(T)/E(Tref)
    assert lip_force(30.0, 0.45, 0.0) == pytest.approx(0.45 * 30.0)
    friction = lip_seal_friction(_case())
    forces = friction.lip_force(np.array([20.0, 60.0, 100.0]) + 273.15)
    assert np.all(np.diff(forces) < 0)  # the rubber softens from 20 to 100 °C
    assert forces[0] == pytest.approx(float(default_radial_force(0.08)), rel=1e-3)


def test_transient_approaches_steady_state():
    # independent check of the time integration: a long constant-speed run must end at the
    # steady state solved directly (K·T = F·T_fixed + s); 1 % of the temperature rise.
    case = _case(environment={"sump_temperature": "60 degC", "start_temperature": "60 degC"},
                 duty={"steps": [{"speed": "1500 rpm", "duration": "3 h"}]},
                 numerics={"max_time_step": "20 s"})
    transient = simulate(case).timeseries.iloc[-1]
    steady = steady_state(case, 1500 * RPM)
    assert transient["torque_Nm"] == pytest.approx(steady["torque_Nm"], rel=0.01)
    for column in ("T_contact_C", "T_groove_C"):
        assert transient[column] - 60 == pytest.approx(steady[column] - 60, rel=0.01)


def _step_values(result):
    return np.array([[s["torque_Nm"], s["T_contact_C"] - 23, s["T_groove_C"] - 23,
                      s["T_sump_C"] - 23] for s in result.steps])


@pytest.mark.parametrize("numerics", [{"mesh_refinement": 2.0},
                                      {"max_time_step": "1 s", "min_time_step": "0.05 s"}])
def test_mesh_and_time_step_refinement_change_results_below_1_percent(numerics):
    # torque and temperature rises (above the 23 °C start) of every step: < 1 % change when
    # the mesh is refined 2x or the time step 4-5x (issue requirement)
    duty = {"steps": [{"speed": "300 rpm", "duration": "10 min"},
                      {"speed": "1500 rpm", "duration": "10 min"},
                      {"speed": "100 rpm", "duration": "5 min"}]}
    env = {"sump_volume": "0.2 L", "ambient_temperature": "23 degC"}
    coarse = simulate(_case(environment=env, duty=duty))
    fine = simulate(_case(environment=env, duty=duty, numerics=numerics))
    assert np.max(np.abs(_step_values(fine) / _step_values(coarse) - 1)) < 0.01


def test_duty_cycle_from_csv_with_ramps_and_standstill(tmp_path):
    (tmp_path / "cycle.csv").write_text(
        "time_s,speed_rpm\n0,0\n60,0\n120,1500\n300,1500\n360,0\n420,0\n")
    case = _case(duty={"csv": "cycle.csv"})
    result = simulate(case, base_dir=tmp_path)
    frame = result.timeseries
    assert frame["time_s"].iloc[-1] == pytest.approx(420.0)
    assert np.all(np.isfinite(frame.select_dtypes("number").to_numpy()))
    standing = frame[frame["speed_rpm"] == 0]
    assert (standing["power_W"] == 0).all()  # no sliding, no heat
    # plateaus of constant speed are the summary steps: 0, 1500, 0 rpm
    assert [round(s["speed_rpm"]) for s in result.steps] == [0, 1500, 0]
    assert result.energy["rel_error"] < 1e-6


@pytest.mark.parametrize(("section", "values", "field"), [
    ("seal", {"shaft_diameter": "80 kg"}, "seal.shaft_diameter"),
    ("seal", {"shaft_diameter": "-80 mm"}, "seal.shaft_diameter"),
    ("seal", {"material": "NRB"}, "seal.material"),
    ("seal", {"lip_style": "wavy"}, "seal.lip_style"),
    ("oil", {"name": "VG86"}, "oil"),
    ("environment", {"sump_volume": "nan L"}, "environment.sump_volume"),
    ("environment", {"start_temperature": "-60 degC"}, "start_temperature"),
    ("duty", {"steps": [{"speed": "100 Hz", "duration": "1 min"}]}, "duty.steps.0.speed"),
])
def test_bad_input_names_the_field(section, values, field):
    with pytest.raises(InputError, match=field.replace(".", r"\.")):
        _case(**{section: values})


def test_cli_run_writes_results_and_refuses_overwrite(tmp_path):
    case = tmp_path / "short.toml"
    case.write_text((EXAMPLES / "speed_cycle.toml").read_text().replace(
        'duration = "15 min"', 'duration = "1 min"').replace('duration = "60 min"',
                                                             'duration = "2 min"'))
    runner = CliRunner()
    out = tmp_path / "out"
    result = runner.invoke(app, ["rotary", "run", str(case), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    for name in ("timeseries.csv", "steps.csv", "summary.json", "case_resolved.toml",
                 "cycle_plain.png", "cycle_wave.png", "variants.png", "stribeck.png"):
        assert (out / name).is_file(), name
    summary = json.loads((out / "summary.json").read_text())
    step = summary["variants"]["wave"]["steps"][0]
    assert {"start_s", "end_s", "speed_rpm", "torque_Nm", "power_W", "T_contact_C",
            "T_groove_C", "T_sump_C"} <= set(step)
    assert summary["variants"]["plain"]["energy_balance_rel_error"] < 0.01
    header = (out / "timeseries.csv").read_text().splitlines()[0].split(",")
    assert header[:11] == ["variant", "time_s", "speed_rpm", "torque_Nm", "power_W",
                           "T_contact_C", "T_groove_C", "T_sump_C", "film_um", "F_lub_N",
                           "F_material_N"]
    # the resolved case reproduces the run
    rerun = load_rotary_case(out / "case_resolved.toml")
    assert set(rerun) == {"plain", "wave"} and rerun["wave"].seal.lip_style == "wave"
    assert rerun["plain"].seal.radial_force == pytest.approx(float(default_radial_force(0.08)))
    again = runner.invoke(app, ["rotary", "run", str(case), "--out", str(out), "-q"])
    assert again.exit_code == 2 and "--force" in again.output


def test_cli_bad_case_is_one_clear_message(tmp_path):
    case = tmp_path / "bad.toml"
    case.write_text('[seal]\nshaft_diameter = "80 kg"\n[duty]\nsteps = []\n')
    result = CliRunner().invoke(app, ["rotary", "run", str(case), "--out", str(tmp_path / "o")])
    assert result.exit_code == 2
    assert "seal.shaft_diameter" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "o").exists()


def test_duty_steps_with_ramp_interpolate_speed():
    # a step with ramp = 60 s rises linearly from the previous speed, then holds
    case = _case(duty={"steps": [{"speed": "500 rpm", "duration": "2 min"},
                                 {"speed": "1500 rpm", "duration": "3 min", "ramp": "60 s"}]})
    times, speeds, steps = case.duty.profile()
    assert steps == [(0.0, 120.0), (120.0, 300.0)]
    mid_ramp = np.interp(150.0, times, speeds) * 30 / math.pi
    assert mid_ramp == pytest.approx(1000.0)  # halfway between 500 and 1500 rpm
    frame = simulate(case).timeseries
    during = frame[(frame["time_s"] > 120) & (frame["time_s"] < 180)]
    assert len(during) >= 5 and np.all(np.diff(during["speed_rpm"]) > 0)
