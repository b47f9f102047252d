"""``sealsim pneumatic compare``: a measured cylinder run against a simulation of its case."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest
import tomli_w
from typer.testing import CliRunner

from sealsim.cli import app
from sealsim.pneumatic import simulate
from sealsim.pneumatic.case import load_pneumatic_cases

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "pneumatic" / "cylinder_32.toml"
RUNNER = CliRunner()


def short_case(tmp_path: Path, load_force: str) -> Path:
    data = tomllib.loads(EXAMPLE.read_text())
    data.pop("variants", None)
    data["controller"]["duration"] = "0.6 s"
    data["load"]["force"] = load_force
    path = tmp_path / f"case_{load_force.split()[0]}.toml"
    path.write_text(tomli_w.dumps(data))
    return path


def measured_file(case_path: Path, out: Path, noise_bar=0.0, noise_mm=0.0, seed=0):
    """A 'measurement' made by simulating a case: every 5th sample, gauge pressures, noise."""
    (case,) = load_pneumatic_cases(tomllib.loads(case_path.read_text())).values()
    frame = simulate(case).timeseries.iloc[::5]
    rng = np.random.default_rng(seed)
    n = len(frame)
    ambient = case.air.ambient_pressure / 1e5
    table = np.column_stack([frame["time_s"], frame["x_m"] * 1e3 + rng.normal(0, noise_mm, n) if
                             noise_mm else frame["x_m"] * 1e3,
                             frame["p1_bar_abs"] - ambient + rng.normal(0, noise_bar, n),
                             frame["p2_bar_abs"] - ambient + rng.normal(0, noise_bar, n)])
    np.savetxt(out, table, delimiter=",", header="t,x,p1,p2", comments="")
    return out


def compare_file(tmp_path: Path, case_path: Path, data_path: Path) -> Path:
    spec = {"case": case_path.name, "measurement": {
        "file": data_path.name, "delimiter": ",", "header": True,
        "columns": {"time": {"column": "t", "unit": "s"},
                    "position": {"column": "x", "unit": "mm"},
                    "pressure_1": {"column": "p1", "unit": "bar"},
                    "pressure_2": {"column": "p2", "unit": "bar"}}}}
    path = tmp_path / f"compare_{data_path.stem}.toml"
    path.write_text(tomli_w.dumps(spec))
    return path


def test_compare_reproduces_its_own_run_and_sees_a_different_load(tmp_path):
    base = short_case(tmp_path, "20 N")
    same = measured_file(base, tmp_path / "same.csv")
    out = tmp_path / "same"
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(compare_file(tmp_path, base, same)),
                                 "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    report = json.loads((out / "report.json").read_text())
    # the model's own samples: only the CSV rounding (%.18e) and gauge conversion remain
    for s in report["signals"].values():
        assert s["rmse"] < 1e-9 and s["r2"] == pytest.approx(1.0, abs=1e-12)
    assert {"report.json", "comparison.csv", "comparison.png"} <= {p.name for p in out.iterdir()}
    # pressures as measured: gauge (before: plain "bar" for either); the extend/retract times
    # of the measured and the simulated position (the module promised them, the report had
    # none): the measurement is the model sampled every 5 ms, the end crossings interpolated
    # between samples (the position is nearly linear there: 1 ms)
    columns = (out / "comparison.csv").read_text().splitlines()[0].split(",")
    assert "pressure_1_measured_bar_gauge" in columns and "pressure_2_model_bar_gauge" in columns
    for key in ("extend_time_s", "retract_time_s"):
        assert report["stroke_times"]["measured"][key] == pytest.approx(
            report["stroke_times"]["model"][key], abs=1e-3)
    assert "extend time: measured" in result.output
    # a run with twice the load, measured with 20 mbar / 0.05 mm noise: the comparison sees it
    heavy = measured_file(short_case(tmp_path, "200 N"), tmp_path / "heavy.csv", 0.02, 0.05)
    out2 = tmp_path / "heavy"
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(compare_file(tmp_path, base, heavy)),
                                 "--out", str(out2), "--quiet"])
    assert result.exit_code == 0, result.output
    report2 = json.loads((out2 / "report.json").read_text())
    # the noise alone gives an RMSE of 0.02 bar; the other load gives much more
    assert report2["signals"]["pressure_1"]["rmse"] > 0.1
    assert report2["signals"]["position"]["rmse"] > 1.0


def test_compare_refuses_a_measurement_longer_than_the_run(tmp_path):
    base = short_case(tmp_path, "20 N")
    data = tmp_path / "long.csv"
    np.savetxt(data, np.column_stack([np.linspace(0, 3, 10), np.zeros(10), np.zeros(10),
                                      np.zeros(10)]), delimiter=",", header="t,x,p1,p2",
               comments="")
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(compare_file(tmp_path, base, data)),
                                 "--out", str(tmp_path / "o"), "--quiet"])
    assert result.exit_code == 2 and "controller.duration" in result.output
    # a logger's clock that does not start with the run: a run of 0.5 s logged at 100 s was
    # told to simulate 100 s
    np.savetxt(data, np.column_stack([np.linspace(100, 100.5, 10), np.zeros(10), np.zeros(10),
                                      np.zeros(10)]), delimiter=",", header="t,x,p1,p2",
               comments="")
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(compare_file(tmp_path, base, data)),
                                 "--out", str(tmp_path / "o"), "--quiet"])
    assert result.exit_code == 2
    assert ("the model counts from the start of the case's run (0 s), the file from 100 s: if "
            "its clock does not start with the run, give --time-offset '100 s'") in " ".join(
                result.output.split())


def test_compare_of_absolute_pressures_says_so(tmp_path):
    # pressures measured absolute: the table's columns say bar_abs (before: plain "bar")
    base = short_case(tmp_path, "20 N")
    same = measured_file(base, tmp_path / "same.csv")
    compare_file(tmp_path, base, same)
    spec = tomllib.loads((tmp_path / "compare_same.toml").read_text())
    spec["measurement"]["pressure"] = "absolute"
    ambient = 1.01325
    table = np.loadtxt(same, delimiter=",", skiprows=1)
    table[:, 2:] += ambient
    np.savetxt(tmp_path / "abs.csv", table, delimiter=",", header="t,x,p1,p2", comments="")
    spec["measurement"]["file"] = "abs.csv"
    (tmp_path / "compare_abs.toml").write_text(tomli_w.dumps(spec))
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(tmp_path / "compare_abs.toml"),
                                 "--out", str(tmp_path / "abs"), "--quiet"])
    assert result.exit_code == 0, result.output
    frame = np.genfromtxt(tmp_path / "abs" / "comparison.csv", delimiter=",", names=True)
    assert frame["pressure_2_model_bar_abs"][0] == pytest.approx(7.01325, rel=1e-9)


def test_a_logger_that_starts_later_is_aligned_with_a_time_offset(tmp_path):
    # The same run logged from t = 12.5 s: with --time-offset "12.5 s" it compares as well as
    # the run logged from 0 (only the CSV rounding remains); without, it lies outside the
    # simulation and is refused with a hint; a plain number has no unit and is refused.
    base = short_case(tmp_path, "20 N")
    same = measured_file(base, tmp_path / "late.csv")
    table = np.loadtxt(same, delimiter=",", skiprows=1)
    table[:, 0] += 12.5
    np.savetxt(same, table, delimiter=",", header="t,x,p1,p2", comments="")
    spec = compare_file(tmp_path, base, same)
    out = tmp_path / "late"
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(spec), "--out", str(out),
                                 "--quiet", "--time-offset", "12500 ms"])
    assert result.exit_code == 0, result.output
    report = json.loads((out / "report.json").read_text())
    assert report["time_offset_s"] == 12.5
    for s in report["signals"].values():      # 1e-9: the CSV's %.18e rounding, as above
        assert s["rmse"] < 1e-9 and s["r2"] == pytest.approx(1.0, abs=1e-12)
    frame = np.genfromtxt(out / "comparison.csv", delimiter=",", names=True)
    assert frame["time_s"][0] == pytest.approx(0.0, abs=1e-12)
    assert frame["logger_time_s"][0] == pytest.approx(12.5, abs=1e-12)
    for key in ("extend_time_s", "retract_time_s"):   # the strokes are found in model time
        assert report["stroke_times"]["measured"][key] == pytest.approx(
            report["stroke_times"]["model"][key], abs=1e-3)
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(spec), "--out",
                                 str(tmp_path / "no_offset"), "--quiet"])
    assert result.exit_code == 2 and "--time-offset" in result.output
    result = RUNNER.invoke(app, ["pneumatic", "compare", str(spec), "--out",
                                 str(tmp_path / "plain"), "--quiet", "--time-offset", "12.5"])
    assert result.exit_code == 2 and "--time-offset" in result.output and "unit" in result.output
