"""Rotary fits (sealsim.calibration.rotary_*): duty cycles from measured speed, synthetic truth,
identifiability, failures, the synthetic example through the CLI."""

from __future__ import annotations

import importlib.util
import json
import re
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest
import tomli_w
from typer.testing import CliRunner

from sealsim.calibration import duty_from_speed, fit_rotary, prepare_rotary_run
from sealsim.calibration.rotary_case import RotaryFitCase
from sealsim.cases import apply_overrides, expand_variants, validate_case
from sealsim.cli import app
from sealsim.errors import InputError, ModelError
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import simulate

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "calibration" / "rotary_synthetic.toml"
RUNNER = CliRunner()


def _maker():
    spec = importlib.util.spec_from_file_location(
        "make_rotary_synthetic", EXAMPLE.parent / "make_rotary_synthetic.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


MAKER = _maker()
EXAMPLE_DATA = tomllib.loads(EXAMPLE.read_text())
#: the example's model on mesh 0.5 with 10 s steps: on the 3 min steps of SHORT_CYCLE it is
#: within 0.0007 N m and 0.27 K of the measurements' model (mesh 1.5, 0.1-2 s steps), which
#: the uncertainties stated in fit_data cover; 2x faster than the example's mesh 1.0
MODEL = {**EXAMPLE_DATA["model"], "numerics": {"mesh_refinement": 0.5, "max_time_step": "10 s",
                                               "min_time_step": "10 s"}}
COLUMNS = EXAMPLE_DATA["measurements"][0]["columns"]
TRUTH = {"seal.radial_force": 32.0, "friction.film_coefficient_um": 2.7,
         "thermal.seal_oil_factor": 0.3}
SHORT_CYCLE = [(250, 3), (750, 3), (1500, 3)]
PARAMETERS = [p for p in EXAMPLE_DATA["fit"]["parameters"] if p["path"] in TRUTH]


def synthetic(folder: Path, name: str, steps, seeds, conditions=None, truth=None) -> list[str]:
    """Measured runs ``name_SEED.csv`` made by the measurements' model (mesh 1.5, 0.1-2 s
    steps) with the true parameters (default :data:`TRUTH`), 2 s sampling and seeded noise
    (the example's generator)."""
    case = MAKER.true_case(MODEL, conditions or {}, steps, truth=truth or TRUTH)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        frame = simulate(case).timeseries
    files = []
    for seed in seeds:
        path = folder / f"{name}_{seed}.csv"
        MAKER.write_measurement(path, MAKER.measure(frame, seed), path.stem)
        files.append(path.name)
    return files


def fit_data(files: dict[str, str], parameters, **fit) -> dict:
    """A rotary-fit case dict on synthetic files ({name: file}); all runs are fitted.  Plain
    least squares: the synthetic data have no outliers, and it needs fewer evaluations from
    a start 15 % off than the robust loss of the example (which down-weights large residuals)."""
    return {"model": MODEL,
            "fit": {"torque_uncertainty": "0.003 N*m", "temperature_uncertainty": "0.35 K",
                    "loss": "linear", "parameters": parameters, **fit},
            "measurements": [{"name": n, "file": f, "role": "fit", "delimiter": ",",
                              "header": True, "columns": COLUMNS} for n, f in files.items()]}


def fitted(folder: Path, data: dict, with_runs: bool = False):
    case = validate_case(RotaryFitCase, data, "test case")
    runs = [prepare_rotary_run(case, m, folder) for m in case.measurements]
    result = fit_rotary(case, runs)
    return (result, runs) if with_runs else result


@pytest.fixture(scope="module")
def short_runs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("rotary_synthetic")
    return folder, synthetic(folder, "short", SHORT_CYCLE, (1, 2))


def test_duty_cycle_from_a_measured_speed_signal():
    rng = np.random.default_rng(0)
    t = np.arange(0.0, 400.0, 2.0)
    # 1 min standstill, 100 rpm, a 4 s ramp to 300 rpm, a 40 s ramp down to 200 rpm
    true = np.interp(t, [0, 60, 60.001, 150, 154, 300, 340, 400],
                     [0, 0, 100, 100, 300, 300, 200, 200])
    noisy = true + rng.normal(0.0, 0.5, t.size)
    times, speeds = duty_from_speed(t, noisy * np.pi / 30)
    rpm = speeds * 30 / np.pi
    duty = np.interp(t, times, rpm)
    # standstill is exactly 0 (a creeping shaft has the lip's full boundary friction), the
    # plateaus are the medians of their samples (within 3 noise σ/√n), the short ramp is a
    # jump in its middle, the long ramp is kept sample by sample (noise 0.5 rpm, 2 σ)
    assert np.all(duty[t < 60] == 0.0)
    assert np.abs(duty[(t > 62) & (t < 150)] - 100.0).max() < 0.5
    assert np.abs(duty[(t > 160) & (t < 300)] - 300.0).max() < 0.5
    assert 150 < times[np.flatnonzero(np.diff(times) == 0)[1]] < 154
    ramp = (t > 305) & (t < 335)
    assert np.abs(duty[ramp] - true[ramp]).max() < 1.5
    # a jump of 10 s or less vs the ramp as measured: the same speed on the plateaus
    ramps, _ = duty_from_speed(t, noisy * np.pi / 30, jump=0.0)
    assert not np.any(np.diff(ramps) == 0)


def test_speeds_outside_the_model_are_refused():
    t = np.arange(0.0, 100.0, 1.0)
    with pytest.raises(InputError, match="-200 rpm at t = 50 s .*below 0.*give \\|speed\\|"):
        duty_from_speed(t, np.where(t < 50, 100.0, -200.0) * np.pi / 30)
    with pytest.raises(InputError, match="above 47746 rpm"):
        duty_from_speed(t, np.full(t.size, 6000.0))


def test_bad_cases_name_the_field(tmp_path):
    good = fit_data({"a": "a.csv"}, PARAMETERS)
    validate_case(RotaryFitCase, good, "ok")                    # the base is valid
    bad = [
        ({"fit": {**good["fit"], "parameters": [{"path": "seal.lip_stile", "bounds": [0, 1]}]}},
         "seal has no field 'lip_stile'"),
        ({"fit": {**good["fit"], "parameters": [{"path": "seal.lip_style", "bounds": [0, 1]}]}},
         "'seal.lip_style' is not a number"),
        ({"fit": {**good["fit"], "parameters": [{"path": "numerics.mesh_refinement",
                                                  "bounds": [0.5, 1]}]}},
         "no field 'numerics' that can be fitted"),
        ({"model": {**MODEL, "duty": {"steps": [{"speed": "1 rpm", "duration": "1 s"}]}}},
         "model.duty: the duty cycle of a fit is each measurement's measured speed"),
        ({"measurements": [{**good["measurements"][0], "conditions": {
            "seal.radial_force": "30 N"}}]}, "conditions set the fitted parameter"),
        ({"measurements": [{**good["measurements"][0], "conditions": {
            "environment": {"sump_volume": "3 m"}}}]}, "environment.sump_volume"),
        ({"measurements": [{**good["measurements"][0], "columns": {
            **COLUMNS, "speed": {"column": "speed_rpm", "unit": "Hz"}}}]}, "Hz is ambiguous"),
        ({"measurements": [{**good["measurements"][0], "columns": {
            k: v for k, v in COLUMNS.items() if k != "torque"}}]}, "must include \\['torque'\\]"),
        ({"measurements": [{**good["measurements"][0], "role": "validate"}]},
         "at least one measurement needs role = 'fit'"),
    ]
    for change, message in bad:
        with pytest.raises(InputError, match=message):
            validate_case(RotaryFitCase, {**good, **change}, "test case")


def test_a_groove_temperature_in_the_wrong_unit_is_refused_before_the_fit(tmp_path):
    # the example's fit file with its degC column declared as K: a spring groove at 22.9 K
    # was accepted and the fit chased it
    source = EXAMPLE.parent / EXAMPLE_DATA["measurements"][0]["file"]
    (tmp_path / "a.csv").write_text(source.read_text())
    columns = {**COLUMNS, "temperature": {"column": "T_groove_C", "unit": "K"}}
    data = fit_data({"a": "a.csv"}, PARAMETERS)
    data["measurements"][0]["columns"] = columns
    case = validate_case(RotaryFitCase, data, "test case")
    with pytest.raises(InputError, match=r"measurement 'a' .*a.csv\): measured spring-groove "
                       r"temperature 22.9 K \(-250.2 degC\) at t = 0 s \(sample 1\) is "
                       r"outside the rotary model's -73 ... 177 degC; check the temperature "
                       r"column's unit"):
        prepare_rotary_run(case, case.measurements[0], tmp_path)


def test_a_torque_of_the_other_sign_is_refused_before_the_fit(tmp_path):
    # a rig that records the reaction torque (negative): the fit ran towards the bounds
    source = EXAMPLE.parent / EXAMPLE_DATA["measurements"][0]["file"]
    lines = source.read_text().splitlines()
    flipped = [line if line.startswith("#") or line.startswith("time") else
               ",".join([*line.split(",")[:2], str(-float(line.split(",")[2])),
                         line.split(",")[3]]) for line in lines]
    (tmp_path / "a.csv").write_text("\n".join(flipped) + "\n")
    data = fit_data({"a": "a.csv"}, PARAMETERS)
    case = validate_case(RotaryFitCase, data, "test case")
    with pytest.raises(InputError, match=r"measured torque is negative on 6 of 6 steps at speed "
                                         r"\(median -0.444\d N m\).*set scale = -1 on the "
                                         r"torque column"):
        prepare_rotary_run(case, case.measurements[0], tmp_path)
    data["measurements"][0]["columns"] = {**COLUMNS, "torque": {**COLUMNS["torque"],
                                                                "scale": -1.0}}
    case = validate_case(RotaryFitCase, data, "test case")
    assert len(prepare_rotary_run(case, case.measurements[0], tmp_path).steps) == 7


def test_synthetic_truth_is_recovered_within_two_standard_errors(short_runs):
    # lip force, film coefficient and the seal's cooling in oil from one 10 min cycle made by
    # another model set-up (mesh 1.5, short steps) than the fit's, two noise seeds; with honest
    # standard errors ~95 % of the estimates lie within 2 s.e.
    folder, files = short_runs
    scores = []
    for name in files:
        result, (run,) = fitted(folder, fit_data({"short": name}, PARAMETERS), with_runs=True)
        assert result.status == "ok" and result.identifiable.all(), result.failure
        truth = np.array([TRUTH[n] for n in result.names])
        scores.append((result.values - truth) / result.standard_errors)
        # the fit reproduces its data: the moving steps' torque within 2 % (noise of a step
        # average 0.003 N m of 0.5), residuals as stated (χ²/dof < 4)
        predicted = result.predictions["short"].step_values("torque")[1:]
        assert np.abs(predicted / run.measured("torque")[1:] - 1).max() < 0.02
        assert result.residual_variance < 4.0
    assert np.abs(scores).max() < 2.0, scores
    # staged (torque parameters, then the thermal one, then all) ends at the same optimum
    staged = fitted(folder, fit_data({"short": files[-1]}, PARAMETERS, strategy="staged"))
    assert [s["stage"] for s in staged.stages] == ["torque", "thermal", "joint"]
    assert np.all(np.abs(staged.values - result.values) < 0.1 * result.standard_errors)


def test_a_parameter_the_data_cannot_determine_is_reported(tmp_path):
    # one speed with sump and housing held at 60 °C: the housing's heat transfer to the room
    # has no effect at all, and lip force and film coefficient only set the one torque value
    # (the groove temperature follows from the power, i.e. from the same torque)
    held = {"environment.sump_temperature": "60 degC", "environment.housing_temperature":
            "60 degC"}
    (name,) = synthetic(tmp_path, "one_speed", [(1000, 4)], (3,), conditions=held)
    data = fit_data({"one": name}, [
        {"path": "seal.radial_force", "bounds": ["10 N", "100 N"]},
        {"path": "friction.film_coefficient_um", "bounds": [0.5, 20.0]},
        {"path": "environment.housing_heat_transfer", "bounds": ["1 W/(m^2*K)",
                                                                 "100 W/(m^2*K)"]}],
        max_evaluations=3)
    data["measurements"][0]["conditions"] = held
    result = fitted(tmp_path, data)
    assert not result.identifiable.any()
    housing = result.reasons[2]
    assert any("do not determine it" in r for r in housing), housing
    for i, other in ((0, "friction.film_coefficient_um"), (1, "seal.radial_force")):
        assert any(f"correlated with {other}" in r for r in result.reasons[i]), result.reasons
    assert any("environment.housing_heat_transfer is not identifiable" in w
               for w in result.warnings)
    # whether or not the optimiser stops within 3 evaluations along the undetermined
    # combination (it depends on the model's numerics), a failure names the reason rather than
    # asking for more evaluations only
    assert result.status == "ok" or "do not determine" in result.failure[-1]


def test_failed_fits_say_why(tmp_path, short_runs):
    folder, files = short_runs
    # the simulation fails at the start values: where (time, speed, contact temperature)
    data = fit_data({"short": files[0]}, [{"path": "seal.radial_force",
                                           "bounds": ["10 N", "1000 N"], "initial": "1000 N"}])
    with pytest.raises(ModelError, match=r"'short' with \{seal.radial_force = 1000\}: rotary "
                                         r"simulation stopped at t = \d+\.\d s \(750 rpm"):
        fitted(folder, data)
    # no complete step: the speed never holds for 30 s
    ramp = tmp_path / "ramp.csv"
    t = np.arange(0.0, 300.0, 2.0)
    ramp.write_text("time_s,speed_rpm,torque_Nm,T_groove_C\n" + "".join(
        f"{a},{5 * a},0.3,30\n" for a in t))
    with pytest.raises(InputError, match="'ramp'.*no complete step found"):
        fitted(tmp_path, fit_data({"ramp": "ramp.csv"}, PARAMETERS))
    # bounds in the wrong unit, a start value outside the bounds
    with pytest.raises(InputError, match=r"fit.parameters\[0\].*bounds\[0\].*'1 m'"):
        fitted(folder, fit_data({"short": files[0]}, [{"path": "seal.radial_force",
                                                       "bounds": ["1 m", "2 m"]}]))
    with pytest.raises(InputError, match="start value 37.69.* outside the bounds"):
        fitted(folder, fit_data({"short": files[0]}, [{"path": "seal.radial_force",
                                                       "bounds": ["10 N", "20 N"]}]))


def test_cli_reports_a_fit_that_ends_at_a_bound_with_exit_status_1(tmp_path, short_runs):
    # the true film coefficient 2.7 lies above the upper bound: the fit stops there, says so
    folder, files = short_runs
    data = fit_data({"short": str(folder / files[0])}, [
        {"path": "friction.film_coefficient_um", "bounds": [0.5, 2.0], "initial": 1.5}])
    case = tmp_path / "bounded.toml"
    case.write_text(tomli_w.dumps(data))
    out = tmp_path / "o"
    result = RUNNER.invoke(app, ["rotary", "fit", str(case), "--out", str(out), "--quiet"])
    assert result.exit_code == 1, result.output
    assert "fit failed" in result.output and "ended at a bound" in result.output
    # the results are written all the same, with the reason
    fit = json.loads((out / "fit.json").read_text())
    assert fit["status"] == "failed" and "bound" in fit["failure"][0]
    # deterministic: a second run (replacing the first with --force) writes the same numbers
    report = (out / "report.json").read_bytes()
    again = RUNNER.invoke(app, ["rotary", "fit", str(case), "--out", str(out), "--quiet",
                                "--force"])
    assert again.exit_code == 1 and (out / "report.json").read_bytes() == report


def test_a_fit_pressed_against_a_constraint_of_the_model_says_so(tmp_path):
    # a run whose rubber friction at low speed (mu_low 1.5, under a peak of 2.0) lies above
    # the fit's master-curve peak (the default 1.0): fitting mu_low alone asks for
    # mu_low > mu_peak, which the rotary case refuses.  The optimiser stepped back from every
    # refused trial and ended on mu_low = mu_peak: reported as an "ok" fit of mu_low = 1.0
    (name,) = synthetic(tmp_path, "rubber", SHORT_CYCLE, (1,), truth={
        **TRUTH, "friction.mu_peak": 2.0, "friction.mu_low": 1.5})
    result = fitted(tmp_path, fit_data({"rubber": name}, [
        {"path": "friction.mu_low", "bounds": [0.05, 3.0]}]))
    assert result.values[0] == pytest.approx(1.0, rel=0.01)  # the peak, within the 1 % step
    assert result.status == "failed"
    assert result.limits[0].startswith("constraint: ")
    assert np.isnan(result.standard_errors[0]) and not result.identifiable[0]
    # the refused trials are one note, not one per trial (there were nine)
    refused = [n for n in result.warnings if "the optimiser stepped back" in n]
    assert len(refused) == 1, refused
    assert re.match(r"stage 'joint': the model failed at \{friction.mu_low = 1.01\d*\} \(.*"
                    r"mu_low \(1.01\d*\) must not exceed mu_peak \(1.0\)\), and at \d+ more "
                    r"parameter sets; the optimiser stepped back", refused[0])
    assert "mu_low (1.01) must not exceed mu_peak (1.0)" in result.limits[0]
    assert re.match(r"friction.mu_low = 1(\.\d+)? sits on a constraint of the rotary case",
                    result.failure[0])


def test_an_interrupted_fit_resumes_with_the_result_of_an_uninterrupted_one(
        tmp_path, short_runs, monkeypatch):
    # an interrupted rotary fit (Ctrl-C in its 8th simulation) keeps the parameter sets it
    # finished; run again with --resume it simulates only the missing ones (and the optimum
    # once more if it was one of the kept ones: the plots need its time series) and writes
    # the same results
    from sealsim.calibration import rotary_fit
    from sealsim.runs.calibration import run_rotary_fit_file

    folder, files = short_runs
    case = tmp_path / "case.toml"
    case.write_text(tomli_w.dumps(fit_data({"short": str(folder / files[0])},
                                           PARAMETERS[:2])))
    whole = run_rotary_fit_file(case, tmp_path / "whole")
    total = whole["evaluations"]["computed"]
    assert whole["evaluations"]["reused"] == 0 and total == whole["simulations"] > 8
    simulations = {"n": 0}
    model = rotary_fit.predict_rotary_run

    def interrupted(run, values):
        simulations["n"] += 1
        if simulations["n"] == 8:
            raise KeyboardInterrupt
        return model(run, values)

    monkeypatch.setattr(rotary_fit, "predict_rotary_run", interrupted)
    out = tmp_path / "o"
    with pytest.raises(KeyboardInterrupt):
        run_rotary_fit_file(case, out)
    monkeypatch.undo()
    assert len(list((tmp_path / ".o.fit" / "evaluations").glob("*.json"))) == 7
    resumed = run_rotary_fit_file(case, out, resume=True)
    assert resumed["evaluations"] == {"computed": total - 7, "reused": 7}
    assert resumed["simulations"] in (total - 7, total - 6)   # + the optimum, if it was kept
    for name in ("report.json", "fitted_parameters.toml", "predictions.csv", "steps.csv"):
        assert (out / name).read_bytes() == (tmp_path / "whole" / name).read_bytes(), name
    diagnostics = [json.loads((o / "fit.json").read_text()) for o in (out, tmp_path / "whole")]
    for d in diagnostics:
        del d["simulations"], d["evaluations_reused"]
    assert diagnostics[0] == diagnostics[1]
    assert not (tmp_path / ".o.fit").exists()


@pytest.fixture(scope="module")
def example_run(tmp_path_factory):
    """The shipped example through the CLI (fit on cycle A, 0.2 L; validate on cycle B, 3 L)."""
    out = tmp_path_factory.mktemp("rotary_example") / "out"
    result = RUNNER.invoke(app, ["rotary", "fit", str(EXAMPLE), "--out", str(out), "--quiet"])
    return out, result


def test_example_recovers_its_truth_and_predicts_the_validation_run(example_run):
    out, result = example_run
    assert result.exit_code == 0, result.output
    names = {p.name for p in out.iterdir()}
    assert {"fitted_parameters.toml", "report.json", "fit.json", "predictions.csv",
            "steps.csv", "overlay_cycle_A_0.2_L.png", "overlay_cycle_B_3_L.png", "parity.png",
            "parity_temperature.png", "duty_cycle_A_0.2_L.csv", "case_resolved.toml"} <= names
    report = json.loads((out / "report.json").read_text())
    assert set(report) == {"parameters", "measurements", "summary"}
    # the truth the CSV files were made with, within 2 standard errors
    for path, truth in MAKER.TRUTH.items():
        p = report["parameters"][path]
        assert p["identifiable"] and abs(p["value"] - truth) < 2 * p["standard_error"], (path, p)
    fit = json.loads((out / "fit.json").read_text())
    assert fit["status"] == "ok" and not fit["failure"]
    validate = report["measurements"]["cycle B, 3 L"]
    assert validate["role"] == "validate" and len(validate["steps"]) == 6
    # the calibration page of the documentation states the validation errors this command measured
    readme = (ROOT / "docs" / "guide" / "calibration.md").read_text()
    match = re.search(r"Cycle B \(3 L, not fitted\): step-average torque error mean "
                      r"(\d+\.\d) %, max (\d+\.\d) %;\s+spring-groove temperature error "
                      r"RMSE (\d+\.\d+) K, max (\d+\.\d+) K", readme)
    assert match, "docs/guide/calibration.md must state the validation errors of the rotary example"
    mean, largest, rmse, t_max = map(float, match.groups())
    assert 100 * validate["torque_rel_error_mean"] == pytest.approx(mean, abs=0.05)
    assert 100 * validate["torque_rel_error_max"] == pytest.approx(largest, abs=0.05)
    assert validate["T_groove_rmse_K"] == pytest.approx(rmse, abs=0.005)
    assert validate["T_groove_error_max_K"] == pytest.approx(t_max, abs=0.005)
    # an existing result folder is refused without --force (before any computing)
    again = RUNNER.invoke(app, ["rotary", "fit", str(EXAMPLE), "--out", str(out), "--quiet"])
    assert again.exit_code == 2 and "--force" in again.output


def test_fitted_parameters_are_a_rotary_case_overlay(example_run):
    out, _ = example_run
    overlay = tomllib.loads((out / "fitted_parameters.toml").read_text())
    report = json.loads((out / "report.json").read_text())
    base = {**EXAMPLE_DATA["model"], "duty": {"steps": [{"speed": "1000 rpm",
                                                         "duration": "10 min"}]}}
    case = validate_case(RotaryCase, apply_overrides(base, overlay), "overlay")
    assert case.seal.radial_force == pytest.approx(
        report["parameters"]["seal.radial_force"]["value"], rel=1e-9)
    assert case.environment.housing_heat_transfer == pytest.approx(
        report["parameters"]["environment.housing_heat_transfer"]["value"], rel=1e-9)
    # ... and as a variant of a case file
    cases = expand_variants(RotaryCase, {**base, "variants": {"fitted": overlay}}, "variants")
    assert cases["fitted"].friction.film_coefficient_um == pytest.approx(
        report["parameters"]["friction.film_coefficient_um"]["value"], rel=1e-9)
