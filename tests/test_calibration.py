"""Friction fits (sealsim.calibration): synthetic truth, identifiability, failures, the TU Delft
example through the CLI."""

from __future__ import annotations

import json
import math
import re
import statistics
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import tomli_w
from hypothesis import assume, given
from hypothesis import strategies as st
from typer.testing import CliRunner

from rig_strokes import stroke_velocity

from sealsim.calibration import fit_friction, parameter_statistics, prepare_run
from sealsim.calibration.statistics import repeat_scatter
from sealsim.calibration.case import FrictionFitCase
from sealsim.calibration.study import _contact_map, fit_run_warnings, load_fit_case
from sealsim.cases import validate_case
from sealsim.cli import app
from sealsim.errors import InputError
from sealsim.friction import ContactInputs, Theta
from sealsim.friction.case import load_friction_cases, run_friction_case
from sealsim.pneumatic.case import build_seals, load_pneumatic_cases
from sealsim.pneumatic.contact_maps import AnalyticContactMap

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "calibration" / "tudelft_oring.toml"
RUNNER = CliRunner()

#: the truth of the synthetic measurements (Θ law with bristles, SI)
TRUTH = {"tau": 0.2, "alpha": 0.005, "f_a": 0.30, "f_b": 0.08, "gamma": 1e4,
         "reference_normal_force": 100.0, "bristle_stiffness": 2e4}
#: the contact of the synthetic rig: the analytic O-ring estimate, 2 bar on the seal
CONTACT = {"sliding_diameter": "25 mm", "temperature": "20 degC",
           "map": {"analytic": {"cord_diameter": "3.5 mm", "squeeze": 0.1}}}
P_BAR = 2.0


def synthetic_contact():
    """(F_N [N], b [m]) of the synthetic rig: the analytic contact map the case names (NBR
    catalogue modulus 6·(C10 + C01)) at P_BAR and 20 °C."""
    from sealsim.properties.elastomers import get_elastomer
    nbr = get_elastomer("NBR")
    cmap = AnalyticContactMap(0.025, 3.5e-3, 0.10, 6 * (nbr.c10 + nbr.c01),
                              nbr.thermal_expansion)
    fn, b = cmap.evaluate(P_BAR * 1e5, 293.15)
    return float(fn), float(b)


def synthetic_run(path: Path, speeds, seed: int, segment=6.0, ramp=0.2, noise=0.2,
                  offset=0.7, truth=None):
    """A rig run made by the true law (``truth``, default :data:`TRUTH`): back-and-forth
    strokes at each speed [m/s], friction with a load-cell offset and seeded white noise
    (σ = ``noise`` N); columns t [ms], x [mm], v [mm/s], p [bar], F [N]."""
    dt = 0.01
    t, v = stroke_velocity(speeds, segment, ramp, dt)
    x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * dt)])
    fn, b = synthetic_contact()
    law = Theta(**(truth or TRUTH))
    inputs = ContactInputs(normal_force=fn, contact_width=b)
    z = law.trajectory(law.initial_state(1), 0.5 * (v[1:] + v[:-1]), dt, inputs)
    force = law.force(z[:, :, 0].T, v, inputs)
    force = force + offset + np.random.default_rng(seed).normal(0.0, noise, force.size)
    np.savetxt(path, np.column_stack([t * 1e3, x * 1e3, v * 1e3, np.full(t.size, P_BAR),
                                      force]), delimiter=",", header="t,x,v,p,F", comments="")
    return path


def fit_case(files: dict[str, str], parameters, **extra) -> dict:
    """A fit-case dict on synthetic files ({name: file}); all runs are fitted."""
    columns = {"time": {"column": "t", "unit": "ms"}, "position": {"column": "x", "unit": "mm"},
               "velocity": {"column": "v", "unit": "mm/s"},
               "pressure": {"column": "p", "unit": "bar"},
               "friction": {"column": "F", "unit": "N"}}
    case = {"friction": {"law": "theta", "tau": "0.2 s", "alpha": "5 mm", "f_a": 0.5,
                         "f_b": 0.2, "gamma": "1e4 Pa*s", "reference_normal_force": "100 N",
                         "bristle_stiffness": "5000 N/m"},
            "contact": CONTACT,
            "signals": {"settle": 0.5, "sliding_threshold": "2 mm/s"},
            "fit": {"loss": "linear", "parameters": parameters},
            "measurements": [{"name": n, "file": f, "role": "fit", "header": True,
                              "delimiter": ",", "columns": columns} for n, f in files.items()]}
    return {**case, **extra}


STAGED = [{"name": "f_a", "bounds": [0.01, 2.0]}, {"name": "f_b", "bounds": [0.001, 2.0]},
          {"name": "bristle_stiffness", "bounds": ["100 N/m", "1e7 N/m"], "stage": "dynamic"}]


def fitted(tmp_path: Path, data: dict):
    case = validate_case(FrictionFitCase, data, "test case")
    cmap = _contact_map(case, tmp_path, None, None)
    runs = [prepare_run(case, m, cmap, tmp_path) for m in case.measurements]
    return fit_friction(case, runs)


def test_statistics_match_ordinary_least_squares():
    # straight line y = a + b·x: the textbook covariance s²·(XᵀX)⁻¹ (exact for linear models)
    rng = np.random.default_rng(3)
    x = np.linspace(0.0, 2.0, 30)
    X = np.column_stack([np.ones_like(x), x])
    r = rng.normal(0.0, 0.1, x.size)
    stats = parameter_statistics(X, r)
    s2 = r @ r / (x.size - 2)
    expected = np.sqrt(np.diag(s2 * np.linalg.inv(X.T @ X)))
    assert np.allclose(stats["standard_errors"], expected, rtol=1e-10)
    corr = np.linalg.inv(X.T @ X)
    assert stats["correlation"][0, 1] == pytest.approx(
        corr[0, 1] / np.sqrt(corr[0, 0] * corr[1, 1]), rel=1e-10)


def test_repeat_scatter_against_the_standard_library():
    # mean and sample standard deviation (n − 1) of Python's statistics module, independent
    # of numpy; the model's error of the mean relative to the mean and to that deviation
    measured, predicted = [7.18, 6.07, 8.02, 5.27, 7.20], [6.9, 6.8, 7.0, 6.7, 6.85]
    r = repeat_scatter(measured, predicted)
    mean, std = statistics.mean(measured), statistics.stdev(measured)
    assert r["runs"] == 5
    assert r["F_measured_mean_N"] == pytest.approx(mean, rel=1e-12)
    assert r["F_measured_std_N"] == pytest.approx(std, rel=1e-12)
    assert r["cv"] == pytest.approx(std / mean, rel=1e-12)
    assert r["standard_error_N"] == pytest.approx(std / math.sqrt(5), rel=1e-12)
    assert (r["F_measured_min_N"], r["F_measured_max_N"]) == (5.27, 8.02)
    error = statistics.mean(predicted) - mean
    assert r["rel_error_of_mean"] == pytest.approx(error / mean, rel=1e-12)
    assert r["error_in_std"] == pytest.approx(error / std, rel=1e-12)
    # one run has no scatter: said, not a NaN
    one = repeat_scatter([4.0], [4.4])
    assert one["F_measured_std_N"] is None and one["cv"] is None and one["error_in_std"] is None
    assert one["rel_error_of_mean"] == pytest.approx(0.1)
    # runs that agree exactly (a file given twice): no scatter to measure the error in
    same = repeat_scatter([5.0, 5.0], [5.5, 5.5])
    assert same["F_measured_std_N"] == 0.0 and same["error_in_std"] is None
    assert same["rel_error_of_mean"] == pytest.approx(0.1)
    with pytest.raises(ValueError, match="2 measured and 1 predicted"):
        repeat_scatter([1.0, 2.0], [1.0])


@given(st.lists(st.floats(0.5, 50.0), min_size=2, max_size=8, unique=True),
       st.floats(0.5, 50.0), st.floats(0.01, 100.0))
def test_repeat_scatter_is_independent_of_the_force_unit(levels, prediction, scale):
    # a change of unit (N to kN, a different load cell gain) scales every level alike: the
    # relative numbers and the error in units of the scatter must not change.  Runs that
    # differ only by rounding (hypothesis found 0.5 and 0.5 + 1 ulp) have a standard deviation
    # of rounding noise, which a scaling changes: the property is about real scatter
    assume(statistics.stdev(levels) > 1e-9 * statistics.mean(levels))
    a = repeat_scatter(levels, [prediction] * len(levels))
    b = repeat_scatter([scale * x for x in levels], [scale * prediction] * len(levels))
    for key in ("cv", "rel_error_of_mean", "error_in_std"):
        assert b[key] == pytest.approx(a[key], rel=1e-9, abs=1e-12)


def test_a_fit_run_far_from_its_repeated_tests_mean_is_reported():
    # the TU Delft O-ring 25.7 at 1 bar: five runs, mean 5.01 N, s 0.76 N; its main run
    # (4.73 N, -0.37 s) is fine, the reconnected 3 run (6.28 N, +1.7 s) stopped the three-ring
    # fit at a bound when it was the fit run (docs/guide/calibration.md)
    levels = {"main": 4.727, "rec 2": 4.811, "rec 3": 6.281, "rerun 1": 4.974, "rerun 3": 4.260}
    runs = {n: {"F_measured_N": f, "F_predicted_N": 4.75} for n, f in levels.items()}

    def conditions(roles, names=tuple(levels)):
        scatter = repeat_scatter([levels[n] for n in names], [4.75] * len(names))
        return {"1 bar": {"measurements": list(names), "roles": roles, **scatter}}

    fit_main = ["fit"] + ["validate"] * 4
    assert fit_run_warnings(conditions(fit_main), runs) == []
    fit_high = ["validate", "validate", "fit", "validate", "validate"]
    (text,) = fit_run_warnings(conditions(fit_high), runs)
    assert "'rec 3' lies +1.7 standard deviations" in text and "'1 bar' (5 runs" in text
    assert fit_run_warnings(conditions(["fit"] * 5), runs) == []        # all fitted: the mean
    two = ("main", "rec 3")
    assert fit_run_warnings(conditions(["validate", "fit"], two), runs) == []   # no mean to
    #                                                                             stand out from


def test_a_repeated_condition_is_one_seal(tmp_path):
    data = fit_case({"a": "a.csv", "b": "b.csv"}, STAGED[:1])
    data["contacts"] = {"other": CONTACT}
    data["measurements"][0]["condition"] = "2 bar"
    data["measurements"][1].update(condition="2 bar", contact="other")
    with pytest.raises(InputError, match=r"condition '2 bar'.*\(a, b\).*different seals "
                                         r"\(contact, contacts\.other\)"):
        validate_case(FrictionFitCase, data, "test case")
    data["measurements"][1]["contact"] = None          # the same seal: valid
    validate_case(FrictionFitCase, data, "test case")


def test_synthetic_truth_is_recovered_within_two_standard_errors(tmp_path):
    # steady sweep (5, 20, 80 mm/s: both ends of the Stribeck-like curve) then the pre-sliding
    # stiffness from the time series.  Five noise seeds: a fit with honest standard errors
    # puts ~95 % of the estimates within 2 s.e.; all must be within 3 s.e. and at least 80 %
    # within 2 s.e. (15 estimates: a 2-s.e. miss rate of 5 % fails this with p < 3 %).
    scores = []
    for seed in range(5):
        f = synthetic_run(tmp_path / f"sweep{seed}.csv", [0.005, 0.02, 0.08], seed)
        result = fitted(tmp_path, fit_case({"sweep": f.name}, STAGED))
        assert result.status == "ok" and result.identifiable.all() and not result.warnings
        truth = np.array([TRUTH[n] for n in result.names])
        scores.append((result.values - truth) / result.standard_errors)
    scores = np.abs(np.array(scores))
    assert scores.max() < 3.0, scores
    assert np.mean(scores < 2.0) >= 0.8, scores
    # the fit is deterministic: the same data give the same numbers bit for bit
    again = fitted(tmp_path, fit_case({"sweep": "sweep4.csv"}, STAGED))
    assert np.array_equal(again.values, result.values)
    assert np.array_equal(again.standard_errors, result.standard_errors)


def test_a_model_faster_in_one_stroke_is_compared_offset_free(tmp_path):
    # The measured friction carries an offset (load cell, pressure area) that the fit removes
    # as the mean of the two directions' medians, which makes the measured strokes equal by
    # construction.  A rig that runs one stroke twice as fast as the other (the TU Delft rig:
    # +5.5 / -11.4 mm/s at 5 bar) has a law whose friction differs between them; compared
    # with the model's own offset left in, that difference was fitted as an error: f_a came
    # out 3.5 % low and f_b 8.5 % high from noise-free data (0.2894 and 0.0868, this case
    # before the fix).  Compared offset-free, both are recovered to the optimiser's tolerance.
    dt, segment, ramp = 0.01, 6.0, 0.2
    knots_t, knots_v = [0.0], [0.0]
    for s in (0.005, 0.02, 0.08):
        for v in (s, -2.0 * s):                    # the backward stroke twice as fast
            knots_t += [knots_t[-1] + ramp, knots_t[-1] + ramp + segment]
            knots_v += [v, v]
    knots_t.append(knots_t[-1] + ramp)
    knots_v.append(0.0)
    t = np.arange(0.0, knots_t[-1], dt)
    v = np.interp(t, knots_t, knots_v)
    x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * dt)])
    fn, b = synthetic_contact()
    law = Theta(**TRUTH)
    inputs = ContactInputs(normal_force=fn, contact_width=b)
    z = law.trajectory(law.initial_state(1), 0.5 * (v[1:] + v[:-1]), dt, inputs)
    force = law.force(z[:, :, 0].T, v, inputs) + 0.7          # the load cell's offset
    np.savetxt(tmp_path / "asym.csv", np.column_stack(
        [t * 1e3, x * 1e3, v * 1e3, np.full(t.size, P_BAR), force]), delimiter=",",
        header="t,x,v,p,F", comments="")
    result = fitted(tmp_path, fit_case({"asym": "asym.csv"}, STAGED[:2]))
    assert result.status == "ok"
    # tolerance 0.1 %: noise-free data, the steady stage's phase medians of a law started
    # from rest (the Θ state settles within the first 0.5 s of each 6 s stroke)
    assert result.values == pytest.approx([TRUTH["f_a"], TRUTH["f_b"]], rel=1e-3)


def test_one_speed_cannot_separate_the_two_friction_coefficients(tmp_path):
    # at one speed the steady force is F_N·[f_a(1 − Θ) + f_b·Θ] with one Θ: only that
    # combination is determined -- both coefficients are reported as not identifiable
    f = synthetic_run(tmp_path / "one_speed.csv", [0.02], seed=1)
    result = fitted(tmp_path, fit_case({"one": f.name}, STAGED[:2]))
    assert not result.identifiable.any()
    assert any("f_a is not identifiable" in w for w in result.warnings)
    assert any("correlated with f_b" in r for r in result.reasons[0])
    # ... while the identifiable combination is right: the fitted model reproduces the level
    # at the contact the run had (Θ_ss depends on F_N, so only there is the combination fixed)
    law = Theta(**{**TRUTH, "f_a": result.values[0], "f_b": result.values[1]})
    true_law = Theta(**TRUTH)
    fn, b = synthetic_contact()
    inputs = ContactInputs(normal_force=fn, contact_width=b)
    assert law.steady_force([0.02], inputs) == pytest.approx(
        true_law.steady_force([0.02], inputs), rel=0.01)


def test_a_time_column_in_ms_declared_as_s_is_refused(tmp_path):
    # with a velocity column as well, the fit ran on a time axis 1000x too long: the steady
    # level came out, the dynamic stage ended at a bound without a word about the unit
    synthetic_run(tmp_path / "run.csv", [0.01], seed=1)
    data = fit_case({"run": "run.csv"}, STAGED)
    data["measurements"][0]["columns"]["time"]["unit"] = "s"
    case = validate_case(FrictionFitCase, data, "test case")
    with pytest.raises(InputError, match=r"measurement 'run' \(.*run.csv\): the position "
                                         r"changes 0.001 times as fast as the velocity column "
                                         r"says .*check the units of the time, position and "
                                         r"velocity columns"):
        prepare_run(case, case.measurements[0], None, tmp_path)
    # declared right, the same file passes the check (ratio 1 within the smoothing)
    data["measurements"][0]["columns"]["time"]["unit"] = "ms"
    case = validate_case(FrictionFitCase, data, "test case")
    run = prepare_run(case, case.measurements[0], None, tmp_path)
    assert run.level > 0


def test_failed_fits_say_why(tmp_path):
    f = synthetic_run(tmp_path / "sweep.csv", [0.005, 0.02, 0.08], seed=0)
    # the truth f_a = 0.3 lies above the upper bound: the fit stops at it and says so
    bounded = [{"name": "f_a", "bounds": [0.01, 0.2], "initial": 0.15},
               {"name": "f_b", "bounds": [0.001, 2.0], "initial": 0.1}]
    result = fitted(tmp_path, fit_case({"sweep": f.name}, bounded))
    assert result.status == "failed"
    assert "f_a" in result.failure[0] and "bound" in result.failure[0]
    # a start the law refuses (f_a from the middle of its bounds, 0.0447, below the case's
    # f_b = 0.2): said before the fit, not a fit against a wall of refused trial laws
    unset = [{k: v for k, v in p.items() if k != "initial"} for p in bounded]
    with pytest.raises(InputError, match=r"the fit would start from a law that is not valid "
                                         r"\(f_a = 0.0447214; SI\): f_b = 0.2 is "
                                         r"larger than f_a = 0.0447214.*give "
                                         r"fit.parameters\[\].initial values that are"):
        fitted(tmp_path, fit_case({"sweep": f.name}, unset[:1]))
    # no motion: no sliding phase
    still = tmp_path / "still.csv"
    np.savetxt(still, np.column_stack([np.arange(100) * 10.0, np.zeros(100), np.zeros(100),
                                       np.full(100, 2.0), np.ones(100)]),
               delimiter=",", header="t,x,v,p,F", comments="")
    with pytest.raises(InputError, match="'still'.*no sliding phase found"):
        fitted(tmp_path, fit_case({"still": still.name}, STAGED[:1]))
    # a pressure beyond the contact map: never extrapolated
    data = fit_case({"sweep": f.name}, STAGED[:1])
    data["contact"] = {**CONTACT, "map": {"analytic": {"cord_diameter": "3.5 mm",
                                                       "squeeze": 0.1,
                                                       "pressure_max": "1 bar"}}}
    with pytest.raises(InputError, match="exceeds the contact map's range"):
        fitted(tmp_path, data)
    # a parameter the law does not have
    with pytest.raises(InputError, match="not a parameter of the theta law"):
        validate_case(FrictionFitCase, fit_case({"sweep": f.name}, [{"name": "mu",
                                                                     "bounds": [0, 1]}]), "t")
    # bounds in the wrong unit
    with pytest.raises(InputError, match="bounds"):
        fitted(tmp_path, fit_case({"sweep": f.name}, [{"name": "bristle_stiffness",
                                                       "bounds": ["1 N", "2 N"]}]))


def test_cli_reports_a_failed_fit_with_exit_status_1(tmp_path):
    synthetic_run(tmp_path / "sweep.csv", [0.005, 0.02, 0.08], seed=0)
    case = tmp_path / "case.toml"
    data = fit_case({"sweep": "sweep.csv"}, [{"name": "f_a", "bounds": [0.01, 0.2],
                                             "initial": 0.15}])
    data["friction"]["f_b"] = 0.08             # the truth; a valid law needs f_b <= f_a
    case.write_text(tomli_w.dumps(data))
    result = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(tmp_path / "o"),
                                 "--quiet"])
    assert result.exit_code == 1
    assert "fit failed" in result.output and "bound" in result.output
    # the report says which parameter sits on which bound
    assert "f_a = 0.2 ± " in result.output and "-- at its upper bound" in result.output
    report = json.loads((tmp_path / "o" / "report.json").read_text())
    assert report["parameters"]["f_a"]["at_limit"] == "upper bound"


def test_a_fit_pressed_against_a_constraint_of_the_law_says_so(tmp_path):
    # data whose friction rises with speed 3x more steeply than the case's viscous term
    # (gamma) makes it: the fit of f_a and f_b asks for f_b > f_a, a sliding friction above
    # the break-away level, which the Θ law refuses.  The optimiser stops on f_b = f_a (its
    # trial laws beyond are refused), within its tolerance; that is no estimate of either
    # coefficient, and was reported as an "ok" fit
    synthetic_run(tmp_path / "rising.csv", [0.005, 0.02, 0.08], seed=0,
                  truth={**TRUTH, "f_a": 0.1, "f_b": 0.1, "gamma": 3e4})
    case = tmp_path / "case.toml"
    case.write_text(tomli_w.dumps(fit_case({"rising": "rising.csv"}, STAGED[:2])))
    result = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(tmp_path / "o"),
                                 "--quiet"])
    assert result.exit_code == 1, result.output
    fit = json.loads((tmp_path / "o" / "fit.json").read_text())
    report = json.loads((tmp_path / "o" / "report.json").read_text())
    f_a, f_b = (report["parameters"][n]["value"] for n in ("f_a", "f_b"))
    assert 0 <= f_a - f_b < 1e-5 * f_a             # on the constraint, within the tolerance
    assert fit["status"] == "failed"
    assert re.search(r"f_a = 0.11\d+ and f_b = 0.11\d+ sit on a constraint of the law \(one "
                     r"step beyond: f_b = .* is larger than f_a", fit["failure"][0])
    for name in ("f_a", "f_b"):
        assert report["parameters"][name]["at_limit"].startswith("constraint: f_b = ")
        # no standard error: the Jacobian's steps beyond the constraint made it 1e-13
        assert report["parameters"][name]["standard_error"] is None
        assert not report["parameters"][name]["identifiable"]
    assert result.output.count("(not determined) -- set by a constraint of the model") == 2
    # a fit of the same law to data it can follow has no limit
    synthetic_run(tmp_path / "sweep.csv", [0.005, 0.02, 0.08], seed=0)
    ok = fitted(tmp_path, fit_case({"sweep": "sweep.csv"}, STAGED[:2]))
    assert ok.status == "ok" and ok.limits == [None, None]


def test_an_interrupted_fit_resumes_with_the_result_of_an_uninterrupted_one(tmp_path,
                                                                           monkeypatch):
    # the rule for long work: what finished is kept and reused.  The fit is interrupted in its
    # dynamic stage (Ctrl-C in the objective after 4 model runs); run again with --resume it
    # computes only the evaluations it had not finished and writes the same results, byte for
    # byte, as a fit that was never interrupted
    from sealsim.calibration import friction_fit
    from sealsim.runs.calibration import run_friction_fit_file

    synthetic_run(tmp_path / "sweep.csv", [0.005, 0.02, 0.08], seed=2)
    case = tmp_path / "case.toml"
    case.write_text(tomli_w.dumps(fit_case({"sweep": "sweep.csv"}, STAGED)))
    whole = run_friction_fit_file(case, tmp_path / "whole")
    total = whole["evaluations"]["computed"]
    assert whole["evaluations"]["reused"] == 0 and total > 10
    assert not (tmp_path / ".whole.fit").exists()      # dropped once the results are written

    out = tmp_path / "o"
    runs = {"n": 0}
    model = friction_fit.predict_run

    def interrupted(law, run):
        runs["n"] += 1
        if runs["n"] > 4:
            raise KeyboardInterrupt
        return model(law, run)

    monkeypatch.setattr(friction_fit, "predict_run", interrupted)
    stopped = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(out), "--quiet"])
    monkeypatch.undo()
    assert stopped.exit_code == 130 and not out.exists()
    kept = len(list((tmp_path / ".o.fit" / "evaluations").glob("*.json")))
    assert 4 < kept < total        # the steady stage and the dynamic stage's first runs
    assert f"{kept} finished evaluations are kept; continue with the same command and " \
           "--resume" in stopped.output.replace("\n", " ")
    # run again without --resume: refused, saying how to go on
    again = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(out), "--quiet"])
    assert again.exit_code == 2
    assert re.search(rf"an interrupted fit left {kept} finished evaluations in .*\.o\.fit.*"
                     r"pass --resume", again.output.replace("\n", ""))
    # a measurement that changed since: no resume, the file is named
    synthetic_run(tmp_path / "sweep.csv", [0.005, 0.02, 0.08], seed=3)
    changed = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(out), "--quiet",
                                  "--resume"])
    assert changed.exit_code == 2
    assert re.search(r"cannot resume: .*changed since: '.*sweep\.csv'",
                     changed.output.replace("\n", ""))
    synthetic_run(tmp_path / "sweep.csv", [0.005, 0.02, 0.08], seed=2)     # as it was
    resumed = run_friction_fit_file(case, out, resume=True)
    assert resumed["evaluations"] == {"computed": total - kept, "reused": kept}
    for name in ("report.json", "fit.json", "fitted_parameters.toml", "predictions.csv"):
        assert (out / name).read_bytes() == (tmp_path / "whole" / name).read_bytes(), name
    assert not (tmp_path / ".o.fit").exists()


@pytest.fixture(scope="module")
def tudelft_map_cache(tmp_path_factory):
    """One fresh map cache for the TU Delft fits of this module: the O-ring 25's fine FE map
    (in both the one-ring example and the three-ring fit) is built once, by the first."""
    return tmp_path_factory.mktemp("tudelft_maps")


@pytest.fixture(scope="module")
def example_run(tmp_path_factory, tudelft_map_cache):
    """The TU Delft example through the CLI (its FE map built on demand unless the three-ring
    fit built it already)."""
    tmp = tmp_path_factory.mktemp("tudelft")
    data = tomllib.loads(EXAMPLE.read_text())
    data["contact"]["map"]["cache_dir"] = str(tudelft_map_cache)
    for m in data["measurements"]:
        m["file"] = str((EXAMPLE.parent / m["file"]).resolve())
    data["contact"]["map"]["structure_case"] = str(EXAMPLE.parent / "oring_25_piston.toml")
    case = tmp / "tudelft_oring.toml"
    case.write_text(tomli_w.dumps(data))
    out = tmp / "out"
    result = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(out), "--quiet"])
    return case, out, result


def test_tudelft_example_runs_through_the_cli(example_run):
    case, out, result = example_run
    assert result.exit_code == 0, result.output
    names = {p.name for p in out.iterdir()}
    assert {"fitted_parameters.toml", "report.json", "fit.json", "predictions.csv",
            "overlay_1_bar.png", "overlay_7_bar.png", "parity.png", "stroke_levels.png",
            "measurements.csv", "case_resolved.toml"} <= names
    report = json.loads((out / "report.json").read_text())
    assert set(report) == {"parameters", "measurements", "conditions"}
    assert report["conditions"] == {}          # no repeated tests in this case
    # the per-run numbers as a table too, row for row
    table = pd.read_csv(out / "measurements.csv").set_index("measurement")
    for name, m in report["measurements"].items():
        assert table.loc[name, "drift_measured_rel"] == pytest.approx(m["drift_measured_rel"],
                                                                      rel=1e-5)
        assert table.loc[name, "F_measured_N"] == pytest.approx(m["F_measured_N"], rel=1e-5)
    assert set(report["measurements"]) == {"1 bar", "7 bar"}
    for m in report["measurements"].values():
        assert set(m) == {"role", "pressure_bar", "F_measured_N", "F_predicted_N",
                          "rel_error", "rmse_N", "r2", "F_predicted_without_fit_N",
                          "ratio_without_fit", "F_normal_N", "mu_measured",
                          "F_proportional_N", "proportional_rel_error", "F_measured_first_N",
                          "F_measured_last_N", "drift_measured_rel", "drift_predicted_rel"}
    fit_run, held_out = report["measurements"]["1 bar"], report["measurements"]["7 bar"]
    assert held_out["role"] == "validate" and fit_run["role"] == "fit"
    # the measured levels (offset-free, half the difference of the direction medians)
    assert fit_run["F_measured_N"] == pytest.approx(3.99, abs=0.01)
    assert held_out["F_measured_N"] == pytest.approx(8.04, abs=0.01)
    # the fitted run is matched (one coefficient for one level; the time-series loss also
    # weighs the reversals, which the model takes more slowly than the rig, so the level sits
    # +2.0 % above the measured one, +2.6 % before the film had its own state): within 4 %;
    # every parameter determined
    assert abs(fit_run["rel_error"]) < 0.04
    assert all(p["identifiable"] for p in report["parameters"].values())
    # the calibration page of the documentation states the 7 bar error this command measured
    readme = (ROOT / "docs" / "guide" / "calibration.md").read_text()
    match = re.search(r"7 bar run \(not fitted\): ([+-]\d+\.\d) %", readme)
    assert match, "docs/guide/calibration.md must state the 7 bar prediction error"
    assert 100 * held_out["rel_error"] == pytest.approx(float(match.group(1)), abs=0.05)
    # the Amontons reference F = μ̄·F_N (F_N from the same FE map, μ̄ from the 1 bar run): it
    # reproduces the fit run exactly, and its 7 bar error is the share of the held-out error
    # that the contact force alone explains (F_N x2.43 from 1 to 7 bar, friction x2.02); the
    # calibration page states it
    for m in (fit_run, held_out):
        assert m["mu_measured"] == pytest.approx(m["F_measured_N"] / m["F_normal_N"])
    assert fit_run["proportional_rel_error"] == pytest.approx(0.0, abs=1e-9)  # JSON digits
    ratio = (held_out["F_normal_N"] / fit_run["F_normal_N"]) / (
        held_out["F_measured_N"] / fit_run["F_measured_N"])
    assert 1.0 + held_out["proportional_rel_error"] == pytest.approx(ratio, rel=1e-9)
    match = re.search(r"friction ∝ F_N: 7 bar ([+-]\d+\.\d) %", readme)
    assert match, "docs/guide/calibration.md must state the proportional reference at 7 bar"
    assert 100 * held_out["proportional_rel_error"] == pytest.approx(float(match.group(1)),
                                                                   abs=0.05)
    # the fitted law's steady curve beyond the rig's speeds (stribeck_fitted.csv): flooded, its
    # film grows like √u and the friction stays below the contact force from 0.1 mm/s to
    # 1 m/s (measured: μ_eff 0.36 at 0.1 mm/s, the fitted μ_b = 0.59 on the asperities' share;
    # 0.07 at 1 m/s and 1 bar, all of it viscous): no warning
    curves = pd.read_csv(out / "stribeck_fitted.csv")
    assert sorted(set(curves["pressure_bar"])) == [1.0, 7.0]
    assert curves["mu_eff"].max() < 1.0 and (out / "stribeck_fitted.png").is_file()
    assert curves[curves["speed_m_s"] == 1.0]["mu_eff"].max() < 0.1
    assert not [w for w in json.loads((out / "fit.json").read_text())["warnings"]
                if "exceeds the contact force" in w]
    # an existing result folder is refused without --force
    again = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(out), "--quiet"])
    assert again.exit_code == 2 and "--force" in again.output


def test_fitted_parameters_load_in_friction_and_pneumatic_cases(example_run):
    _, out, _ = example_run
    law_table = tomllib.loads((out / "fitted_parameters.toml").read_text())["friction"]
    report = json.loads((out / "report.json").read_text())
    assert law_table["boundary_friction"] == pytest.approx(
        report["parameters"]["boundary_friction"]["value"])
    # a friction bench case without a [seal]: the law on the seal's contact is refused there
    # with a clear message (it needs the seal's contact map; tests/test_contact_friction.py
    # runs it on a bench with a seal)
    bench = {"friction": law_table, "inputs": {"normal_force": "100 N",
                                               "contact_width": "1 mm"},
             "bench": {"mode": "velocity", "duration": "1 s", "time_step": "1 ms",
                       "velocity": {"kind": "constant", "level": "10 mm/s"}}}
    (case,) = load_friction_cases(bench).values()
    with pytest.raises(InputError, match="steady = 'contact'.*give \\[seal\\]"):
        run_friction_case(case)
    # a pneumatic seal with the fitted law: the case validates and its seal gets the law
    data = tomllib.loads((ROOT / "examples" / "pneumatic" / "friction_rig.toml").read_text())
    data.pop("variants")
    data["seals"][0]["friction"] = law_table
    (pcase,) = load_pneumatic_cases(data).values()
    (seal,) = build_seals(pcase)
    assert seal.law.params.bristle_stiffness == pytest.approx(
        report["parameters"]["bristle_stiffness"]["value"])


def test_example_case_validates_with_its_relative_paths():
    case = load_fit_case(EXAMPLE)
    assert [m.role for m in case.measurements] == ["fit", "validate"]
    for m in case.measurements:
        assert (EXAMPLE.parent / m.file).is_file()


RINGS = ROOT / "examples" / "calibration" / "tudelft_rings.toml"


def _assert_profiles_carry_the_contact_force(case, base_dir):
    """The friction table integrates each map's contact pressure profile (boundary friction
    μ_b·α·π·D·∫p dz), so at every node of the map the profile must carry the contact force
    F_N of the same FE state (equilibrium).  On the coarse mesh the TU Delft glands had, it
    did not: the X-ring's profile carried 145.4 N of F_N = 153.7 N at 6 bar (−5.4 %) and 55.6
    of 58.0 N at 0 bar (−4.1 %), the O-ring 25's 46.3 of 47.9 N at 0 bar (−3.3 %) -- the
    profile interpolates the contact nodes' pressures, and coarse contact elements cut the
    edges of the lobes.  The cases' fine mesh: within 2.1 % (the X-ring at 0 bar, its
    narrowest lobes).  Tolerance 3 %: above that, below the coarse mesh's errors.  (Checked
    on the maps the fit has just built: no FE of its own.)"""
    from sealsim.pneumatic.friction_tables import contact_profiles, sliding_diameter

    for name in (None, *case.contacts):
        fe_map = _contact_map(case, base_dir, None, None, name)
        temps, pressures, profile = contact_profiles(fe_map)
        for i, t in enumerate(temps):
            for j, dp in enumerate(pressures):
                z, p = profile(i, j)
                carried = math.pi * sliding_diameter(fe_map) * np.trapezoid(p, z)
                force = float(fe_map.evaluate(dp, t)[0])
                assert carried == pytest.approx(force, rel=0.03), (name, t, dp, carried, force)


def test_three_rings_fitted_at_1_bar_predict_the_other_pressures(tmp_path, tudelft_map_cache):
    # Three seals of the TU Delft rig, one law (μ_b and a starved inlet's grease layer), fitted
    # on the three 1 bar runs only, each with its own FE map (built on demand in the module's
    # fresh cache, which the one-ring example shares).
    # Held to issue 23's targets where the model meets them (the X-ring's 3 bar within 15 %),
    # to the second O-ring's runs within 15 % and to the tables of docs/guide/calibration.md
    # for every run and every repeated test (what the page states is what this measures).
    # The O-ring 25's 7 bar within 10 % is not met (-16.2 %): it was (-7.3 %) only while the
    # fit compared the offset-free measurement with the model's friction, offset left in, and
    # so fitted the model's slower stroke (lower viscous friction) as an error.
    data = tomllib.loads(RINGS.read_text())
    for contact in (data["contact"], *data["contacts"].values()):
        contact["map"]["structure_case"] = str(RINGS.parent / contact["map"]["structure_case"])
        contact["map"]["cache_dir"] = str(tudelft_map_cache)
    for m in data["measurements"]:
        m["file"] = str((RINGS.parent / m["file"]).resolve())
    case = tmp_path / "rings.toml"
    case.write_text(tomli_w.dumps(data))
    out = tmp_path / "out"
    result = RUNNER.invoke(app, ["friction", "fit", str(case), "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    _assert_profiles_carry_the_contact_force(load_fit_case(case), tmp_path)
    report = json.loads((out / "report.json").read_text())
    assert all(p["identifiable"] for p in report["parameters"].values())
    runs = report["measurements"]
    assert abs(runs["X-ring 25.7 3 bar"]["rel_error"]) < 0.15
    for bar in (3, 5, 7):
        assert abs(runs[f"O-ring 25.7 {bar} bar"]["rel_error"]) < 0.15
    # the source's repeatability runs of the second O-ring: five runs per pressure, none
    # fitted (the fit is that of the three main 1 bar runs).  Their scatter is the rig's own
    # (one standard deviation of a run 12-16 %, measured), and the model must predict the mean
    # of each pressure within one standard deviation of a run -- what the rig can resolve
    # (measured: within 0.46 of it, the mean within 6 %).
    conditions = report["conditions"]
    assert list(conditions) == [f"O-ring 25.7, {bar} bar" for bar in (1, 3, 5, 7)]
    for name, c in conditions.items():
        assert c["runs"] == 5 and c["roles"].count("fit") == (1 if name.endswith(" 1 bar")
                                                              else 0)
        levels = [runs[m]["F_measured_N"] for m in c["measurements"]]
        assert c["F_measured_mean_N"] == pytest.approx(np.mean(levels), rel=1e-9)
        assert c["F_measured_std_N"] == pytest.approx(np.std(levels, ddof=1), rel=1e-9)
        assert 0.05 < c["cv"] < 0.25
        assert abs(c["error_in_std"]) < 1.0
    assert (out / "conditions.csv").is_file() and (out / "repeatability.png").is_file()
    # the main 1 bar run is 0.37 standard deviations below its test's mean: no warning
    warnings = json.loads((out / "fit.json").read_text())["warnings"]
    assert not any("standard deviations from the mean" in w for w in warnings)
    # the runs whose friction climbs from stroke to stroke are named (tests/test_measurements.py
    # checks the drifts themselves against an independent reading of the files); the model's
    # steady contact changes only with the run's own pressure and speed (measured: < 2 %)
    drifting = [w for w in warnings if "change their friction level by more than 10 %" in w]
    assert len(drifting) == 1
    assert "'X-ring 25.7 7 bar' +18 %" in drifting[0] and "'X-ring 25.7 1 bar'" not in drifting[0]
    assert runs["X-ring 25.7 7 bar"]["drift_measured_rel"] > 0.15
    assert abs(runs["X-ring 25.7 1 bar"]["drift_measured_rel"]) < 0.02
    assert all(abs(m["drift_predicted_rel"]) < 0.03 for m in runs.values())
    # What the fit implies beyond the rig's 6-15 mm/s (stribeck_fitted.csv, one curve per ring
    # and pressure): the fitted grease layer caps the film at 2·h_s = 0.14 µm at every speed
    # above a few mm/s, so the viscous part is Couette shear of a fixed film, η·u/h: tenfold
    # from 0.1 to 1 m/s (1 %: the cap holds at both speeds, the inlet's own film being far
    # thicker there), and the friction passes the contact force (μ_eff 3.7 at 1 m/s and 1 bar,
    # measured) -- said in a warning.  μ_eff is the larger stroke's |F| over the FE contact
    # force, which is the report's F_N of the same run (its median over the sliding samples).
    curves = pd.read_csv(out / "stribeck_fitted.csv")
    assert sorted(set(curves["contact"])) == ["contact", "oring257", "xring257"]
    for (contact, bar), c in curves.groupby(["contact", "pressure_bar"]):
        assert bar in (1.0, 3.0, 5.0, 7.0)
        fast = c.set_index("speed_m_s")
        for column in ("F_viscous_plus_N", "F_viscous_minus_N"):
            assert fast.loc[1.0, column] / fast.loc[0.1, column] == pytest.approx(10.0,
                                                                                 rel=0.01)
        assert c["mu_eff"].to_numpy() == pytest.approx(
            np.maximum(c["F_plus_N"], c["F_minus_N"]) / c["F_normal_N"], rel=1e-5)
    one_bar = curves[(curves["contact"] == "contact") & (curves["pressure_bar"] == 1.0)]
    assert one_bar["F_normal_N"].iloc[0] == pytest.approx(runs["O-ring 25 1 bar"]["F_normal_N"],
                                                         rel=0.01)
    assert one_bar["mu_eff"].iloc[-1] > 1.0
    (fast_warning,) = [w for w in warnings if "exceeds the contact force" in w]
    assert "supply_layer" in fast_warning and "stribeck_fitted.png" in fast_warning
    assert (out / "stribeck_fitted.png").is_file()
    page = (ROOT / "docs" / "guide" / "calibration.md").read_text()
    for name, c in conditions.items():     # the page's table of the repeated tests
        row = re.search(rf"\| {name} \| 5 \| ([\d.]+) ± ([\d.]+) \| ([\d.]+) % \|[^|]*\| "
                        r"([\d.]+) \| ([+−-][\d.]+) % \| ([+−-][\d.]+) \|", page)
        assert row, f"docs/guide/calibration.md has no row for {name}"
        assert float(row.group(1)) == pytest.approx(c["F_measured_mean_N"], abs=0.0015)
        assert float(row.group(2)) == pytest.approx(c["F_measured_std_N"], abs=0.0015)
        assert float(row.group(4)) == pytest.approx(c["F_predicted_mean_N"], abs=0.0015)
        assert float(row.group(5).replace("−", "-")) == pytest.approx(
            100 * c["rel_error_of_mean"], abs=0.05)
        assert float(row.group(6).replace("−", "-")) == pytest.approx(c["error_in_std"],
                                                                      abs=0.005)
    for name, m in runs.items():
        if "," in name:                     # a repeat run: in the table of its condition
            continue
        seal, size, bar = name.split()[0], name.split()[1], name.split()[2]
        row = re.search(rf"\| {seal} {size}, {bar} bar[^|]*\| ([\d.]+) \| ([\d.]+) \| "
                        r"([+−-][\d.]+) % \|", page)
        assert row, f"docs/guide/calibration.md has no row for {name}"
        assert float(row.group(2)) == pytest.approx(m["F_predicted_N"], abs=0.0015)
        error = float(row.group(3).replace("−", "-"))
        assert error == pytest.approx(100 * m["rel_error"], abs=0.05)


def test_cli_prints_fitted_parameters_in_their_case_unit():
    # report.json holds SI values and the case's unit in "text"; the CLI printed the SI
    # number with the case's unit: "supply_layer = 8.27717e-08 ± 7.3e-09 mm" for a
    # 0.083 µm grease layer (tudelft_rings.toml)
    from sealsim.cli.calibration import _in_case_unit

    value, se, unit = _in_case_unit({"value": 8.27717e-08, "standard_error": 7.3e-09,
                                     "text": "8.27717e-05 mm"})
    assert (value, se, unit) == (pytest.approx(8.27717e-05), pytest.approx(7.3e-06), " mm")
    assert _in_case_unit({"value": 0.04, "standard_error": None, "text": 0.04}) == (0.04, None,
                                                                                   "")
    value, se, unit = _in_case_unit({"value": 2.0, "standard_error": 0.1, "text": "2 s"})
    assert (value, se, unit) == (2.0, pytest.approx(0.1), " s")
