"""Every number means what it says (issue 22): unit spellings, plain numbers, conditions a fit
needs, inputs inside the output folder, escaped names, tracebacks and unbounded API calls.

Each reproduction of the issue is a test: it asserts the exit code (or the exception), one clear
message naming the field, file or argument, and -- for commands -- that nothing outside the
output folder changed and no input was removed.  The fits are a Coulomb law on a few seconds of
synthetic rig data (a second each), so the file runs in well under a minute.
"""

from __future__ import annotations

import json
import math
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest
import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

import sealsim
from sealsim.calibration import prepare_run
from sealsim.calibration.case import FrictionFitCase
from sealsim.cases import expand_variants, load_toml, validate_case
from sealsim.cli import app
from sealsim.errors import InputError, SealsimWarning
from sealsim.measurements import ColumnSpec, read_table
from sealsim.pneumatic.case import PneumaticCase
from sealsim.rotary.case import RotaryCase
from sealsim.units import parse_quantity, unit_registry

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
TUDELFT_1BAR = EXAMPLES / "data" / "tudelft_pneumatic_friction" / "O-ring_1bar.csv"
RUNNER = CliRunner()
RPM = math.pi / 30.0


def cli(*args):
    result = RUNNER.invoke(app, [str(a) for a in args])
    return result, " ".join(result.output.split())


def tree(path: Path) -> dict[str, bytes | None]:
    """Every entry below ``path`` (hidden ones too) with its content (None for folders)."""
    return {str(p.relative_to(path)): (None if p.is_dir() else p.read_bytes())
            for p in sorted(path.rglob("*"))}


def one_message(text: str, kind: str = "input error") -> None:
    assert text.count(f"{kind}:") == 1 and "Traceback" not in text, text


# -- a tiny rig and fit case --------------------------------------------------------------------
COLUMNS = {"time": {"column": "t", "unit": "s"}, "position": {"column": "x", "unit": "mm"},
           "friction": {"column": "F", "unit": "N"}}
COULOMB = {"law": "coulomb", "coulomb_force": "1 N", "viscous_coefficient": "0 N*s/m",
           "pressure_coefficient": "0 m**2"}


def rig_file(path: Path, friction=lambda v: 5.0 * np.sign(v) + 0.3, delimiter=",",
             decimal=".", pressure_bar=None, noise=0.05) -> Path:
    """8 s of strokes at +-10 mm/s (2 s each), friction in N with seeded noise (σ in N)."""
    t = np.arange(0.0, 8.0, 0.01)
    v = 0.01 * np.where((t // 2) % 2 == 0, 1.0, -1.0)
    x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * 0.01)])
    force = friction(v) + np.random.default_rng(0).normal(0.0, noise, t.size)
    columns, names = [t, x * 1e3, force], ["t", "x", "F"]
    if pressure_bar is not None:
        columns.append(np.full(t.size, pressure_bar))
        names.append("p")
    rows = [delimiter.join(f"{c:.6f}".replace(".", decimal) for c in row)
            for row in np.column_stack(columns)]
    path.write_text(delimiter.join(names) + "\n" + "\n".join(rows) + "\n")
    return path


def measurement(name: str, file: str, role: str = "fit", **extra) -> dict:
    return {"name": name, "file": file, "role": role, "header": True, "delimiter": ",",
            "columns": COLUMNS, **extra}


def fit_case(folder: Path, measurements: list[dict], friction=None, parameters=None,
             **extra) -> Path:
    data = {"friction": friction or COULOMB,
            "fit": {"parameters": parameters or [{"name": "coulomb_force",
                                                  "bounds": ["0.1 N", "50 N"]}]},
            "measurements": measurements, **extra}
    path = folder / "fit.toml"
    path.write_text(tomli_w.dumps(data))
    return path


# -- 1. reciprocal time for a rotational speed is revolutions per time --------------------------
@pytest.mark.parametrize("spelling", [
    "1500 rpm", "1500 1/min", "1500 min^-1", "1500 min**-1", "1500 min⁻¹", "1500 1 / min",
    "1500 U/min", "1500 r/min", "1500 rev/min", "25 1/s", "25 s^-1", "25 rev/s", "25 rps",
])
def test_every_spelling_of_rpm_is_revolutions(spelling):
    # DIN 1301: 1/min on a data sheet is the revolutions per minute; pint alone reads 1/min as
    # rad/min, 2*pi too low (1500 1/min was 238.7 rpm)
    assert parse_quantity(spelling, "angular_speed") == pytest.approx(1500 * RPM, rel=1e-12)


def test_1_per_min_in_a_case_the_api_and_a_csv_column(tmp_path):
    case = validate_case(RotaryCase, {
        "seal": {"shaft_diameter": "80 mm"}, "oil": {"name": "VG220-mineral"},
        "duty": {"steps": [{"speed": "1500 1/min", "duration": "10 min"}]}})
    _, speeds, _ = case.duty_cycle().profile()
    assert speeds.max() == pytest.approx(1500 * RPM, rel=1e-12)
    r = sealsim.lip_seal_torque("80 mm", "1500 1/min", "ISO VG 220", "80 degC")
    assert r["speed_rpm"] == pytest.approx(1500.0, rel=1e-12)
    table = tmp_path / "speed.csv"
    table.write_text("t;n\n0;1000\n1;1500\n2;1500\n")
    m = read_table(table, [ColumnSpec("time", "t", "s"), ColumnSpec("speed", "n", "U/min")],
                   delimiter=";", header=True)
    assert m.column("speed") == pytest.approx(np.array([1000, 1500, 1500]) * RPM, rel=1e-12)


# spelling -> pint's canonical spelling of the same unit (None: must be refused)
SPELLINGS = {
    "angular_speed": {"rpm": "rpm", "1/min": "rpm", "min^-1": "rpm", "min**-1": "rpm",
                      "U/min": "rpm", "r/min": "rpm", "rev/min": "rpm", "1/s": "rev/s",
                      "s^-1": "rev/s", "rps": "rev/s", "U/s": "rev/s", "rad/s": "rad/s",
                      "radian/second": "rad/s", "deg/s": "deg/s",
                      "Hz": None, "kHz": None, "rpm/s": None, "bar": None, "": None},
    "pressure": {"bar": "bar", "mbar": "millibar", "kPa": "kilopascal", "MPa": "megapascal",
                 "N/mm^2": "megapascal", "N/mm**2": "megapascal", "psi": "psi", "Pa": "pascal",
                 "hPa": "hectopascal", "barg": None, "kg": None, "N": None, "": None},
    "temperature": {"degC": "degC", "°C": "degC", "celsius": "degC", "K": "kelvin",
                    "kelvin": "kelvin", "degF": "degF", "°F": "degF", "C": None, "deg": None,
                    "": None},
}
# SI ranges drawn from: inside every field the values are written to below
SI_RANGE = {"angular_speed": (10 * RPM, 3000 * RPM), "pressure": (2e5, 9e5),
            "temperature": (280.0, 350.0)}
SI_UNIT = {"angular_speed": "rad/s", "pressure": "Pa", "temperature": "K"}


def _quantity_text(data, dimension):
    spelling = data.draw(st.sampled_from(sorted(SPELLINGS[dimension])), label="spelling")
    canonical = SPELLINGS[dimension][spelling]
    si = data.draw(st.floats(*SI_RANGE[dimension]), label="si")
    ureg = unit_registry()
    if canonical is None:
        return f"{si:.6g} {spelling}", None
    magnitude = ureg.Quantity(si, SI_UNIT[dimension]).to(canonical).magnitude
    return f"{magnitude!r} {spelling}", ureg.Quantity(magnitude, canonical).to(
        SI_UNIT[dimension]).magnitude


CASE_FIELDS = {  # dimension -> (example case, dotted field, getter of the validated value)
    "angular_speed": (RotaryCase, EXAMPLES / "rotary" / "speed_cycle.toml",
                      "duty.steps", lambda c: c.duty.steps[0].speed),
    "pressure": (PneumaticCase, EXAMPLES / "pneumatic" / "cylinder_32.toml",
                 "air.supply_pressure", lambda c: c.air.supply_pressure),
    "temperature": (RotaryCase, EXAMPLES / "rotary" / "speed_cycle.toml",
                    "environment.ambient_temperature",
                    lambda c: c.environment.ambient_temperature),
}


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data(), dimension=st.sampled_from(sorted(CASE_FIELDS)))
def test_unit_spellings_in_case_files(data, dimension):
    """A quantity written in any spelling gives the SI value of pint's canonical spelling of
    that unit, or one clear refusal naming the field."""
    text, expected = _quantity_text(data, dimension)
    model, example, field, value_of = CASE_FIELDS[dimension]
    case = load_toml(example)
    case.pop("variants", None)
    table, name = field.rsplit(".", 1)
    if field == "duty.steps":
        case["duty"]["steps"] = [{"speed": text, "duration": "10 min"}]
    else:
        case[table][name] = text
    parsed = tomllib.loads(tomli_w.dumps(case))   # through TOML, as a case file
    if expected is None:
        with pytest.raises(InputError) as err:
            expand_variants(model, parsed, "case file")
        assert field in str(err.value) and str(err.value).count("\n") == 0
    else:
        (resolved,) = expand_variants(model, parsed, "case file").values()
        assert value_of(resolved) == pytest.approx(expected, rel=1e-12)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data(), dimension=st.sampled_from(sorted(CASE_FIELDS)))
def test_unit_spellings_in_the_api(data, dimension):
    """The same spellings through the one-call API: lip_seal_torque's speed and sump
    temperature, seal_friction's pressure (its reported operating point)."""
    text, expected = _quantity_text(data, dimension)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SealsimWarning)
        if dimension == "angular_speed":
            call = lambda: sealsim.lip_seal_torque("60 mm", text, "VG68", "60 degC")  # noqa: E731
            value = lambda r: r["speed_rpm"] * RPM  # noqa: E731
            argument = "speed"
        elif dimension == "temperature":
            call = lambda: sealsim.lip_seal_torque("60 mm", "500 rpm", "VG68", text)  # noqa: E731
            value = lambda r: r["T_sump_C"] + 273.15  # noqa: E731
            argument = "sump_temperature"
        else:
            call = lambda: sealsim.seal_friction(  # noqa: E731
                {"cord_diameter": "2 mm", "squeeze": 0.12}, "0.1 m/s", text,
                diameter="12 mm")
            value = lambda r: r["pressure_bar"] * 1e5  # noqa: E731
            argument = "pressure"
        if expected is None:
            with pytest.raises(InputError, match=rf"^{argument}: "):
                call()
        else:
            assert value(call()) == pytest.approx(expected, rel=1e-9)


# -- 2. plain numbers in the API are refused, with the unit-ful spelling ------------------------
@pytest.mark.parametrize(("function", "kwargs", "argument", "example"), [
    ("seal_friction", {"pressure": 6}, "pressure", "'6 bar'"),
    ("seal_friction", {"temperature": 80}, "temperature", "'55 degC'"),
    ("seal_friction", {"diameter": 12}, "diameter", "'80 mm'"),
    ("seal_friction", {"velocity": [0.01, 0.1]}, "velocity", "'0.5 m/s'"),
    ("seal_friction", {"velocity": np.array([0.01, 0.1])}, "velocity", "ureg('m/s')"),
    ("lip_seal_torque", {"sump_temperature": 80}, "sump_temperature", "'55 degC'"),
    ("lip_seal_torque", {"shaft_diameter": 0.08}, "shaft_diameter", "'80 mm'"),
    ("lip_seal_torque", {"case": {"environment": {"sump_volume": 0.2}}},
     "environment.sump_volume", "'0.2 L'"),
])
def test_plain_numbers_are_refused_in_the_api(function, kwargs, argument, example):
    args = ({"seal": {"cord_diameter": "2 mm", "squeeze": 0.12}, "velocity": "0.1 m/s",
             "pressure": "6 bar", "diameter": "12 mm"} if function == "seal_friction" else
            {"shaft_diameter": "80 mm", "speed": "1500 rpm", "oil": "VG68"})
    with pytest.raises(InputError) as err:
        getattr(sealsim, function)(**{**args, **kwargs})
    text = str(err.value)
    assert argument in text and "unit" in text and example in text, text


# -- 3. every condition of a fit comes from the file or the case --------------------------------
def test_a_fit_without_pressure_is_refused(tmp_path):
    # the theta law's F_N and b come from a contact map at the pressure: no pressure column and
    # no pressure key used to run at 0 bar (report.json: 0.0 for the 1 and the 7 bar run)
    rig_file(tmp_path / "run.csv")
    case = fit_case(tmp_path, [measurement("7 bar", "run.csv")],
                    friction={"law": "theta", "parameter_set": "pneumatic_demo"},
                    parameters=[{"name": "f_a", "bounds": [0.01, 2.0]}],
                    contact={"sliding_diameter": "25 mm", "temperature": "20 degC",
                             "map": {"analytic": {"cord_diameter": "3.5 mm", "squeeze": 0.1}}})
    before = tree(tmp_path)
    result, text = cli("friction", "fit", case, "--out", tmp_path / "out")
    assert result.exit_code == 2
    one_message(text)
    assert "measurement '7 bar'" in text and "no pressure" in text and "pressure = " in text
    assert tree(tmp_path) == before


def test_a_fit_without_seal_temperature_is_refused(tmp_path):
    rig_file(tmp_path / "run.csv", pressure_bar=2.0)
    columns = {**COLUMNS, "pressure": {"column": "p", "unit": "bar"}}
    case = validate_case(FrictionFitCase, {
        "friction": {"law": "theta", "parameter_set": "pneumatic_demo"},
        "contact": {"sliding_diameter": "25 mm",
                    "map": {"analytic": {"cord_diameter": "3.5 mm", "squeeze": 0.1}}},
        "fit": {"parameters": [{"name": "f_a", "bounds": [0.01, 2.0]}]},
        "measurements": [measurement("warm", "run.csv", columns=columns)]})
    from sealsim.calibration.study import _contact_map
    with pytest.raises(InputError, match=r"measurement 'warm' .*no seal temperature.*"
                                         r"temperature = '20 degC'"):
        prepare_run(case, case.measurements[0], _contact_map(case, tmp_path, None, None),
                    tmp_path)


def test_a_law_without_pressure_dependence_reports_no_pressure(tmp_path):
    # the Coulomb law without pressure scaling needs no pressure: it runs, and the report says
    # the pressure is unknown (null), not 0 bar
    rig_file(tmp_path / "run.csv")
    case = validate_case(FrictionFitCase, load_toml(fit_case(tmp_path, [
        measurement("r", "run.csv")])))
    run = prepare_run(case, case.measurements[0], None, tmp_path)
    from sealsim.calibration.friction_fit import run_metrics
    assert run_metrics(run, run.friction)["pressure_bar"] is None


# -- 5. underscores, initial outside the bounds, the base case of variants ----------------------
def test_underscores_in_numbers_are_refused(tmp_path):
    table = tmp_path / "run.csv"
    table.write_text("t,F\n0,1.5\n0.1,20_0.1234\n0.2,1.4\n")  # float() would read 200.1234
    with pytest.raises(InputError) as err:
        read_table(table, [ColumnSpec("time", "t", "s"), ColumnSpec("friction", "F", "N")],
                   delimiter=",", header=True)
    assert str(err.value) == (f"{table}, row 3, column 2 (friction): '20_0.1234' is not a "
                              "number")


def test_initial_outside_the_bounds_is_refused(tmp_path):
    rig_file(tmp_path / "run.csv")
    case = fit_case(tmp_path, [measurement("r", "run.csv")], parameters=[
        {"name": "coulomb_force", "bounds": ["0.1 N", "50 N"], "initial": "80 N"}])
    before = tree(tmp_path)
    result, text = cli("friction", "fit", case, "--out", tmp_path / "out")
    assert result.exit_code == 2
    one_message(text)
    assert "fit.parameters[0] ('coulomb_force').initial: '80 N' lies outside the bounds" in text
    assert tree(tmp_path) == before


def test_a_start_value_outside_the_bounds_is_reported(tmp_path):
    rig_file(tmp_path / "run.csv")
    case = validate_case(FrictionFitCase, load_toml(fit_case(tmp_path, [
        measurement("r", "run.csv")], parameters=[
        {"name": "coulomb_force", "bounds": ["2 N", "50 N"]}])))     # the law says 1 N
    from sealsim.calibration import fit_friction
    result = fit_friction(case, [prepare_run(case, case.measurements[0], None, tmp_path)])
    assert any("coulomb_force: the law's value 1 (SI) lies outside the bounds" in w
               for w in result.warnings)


def test_the_base_case_of_variants_is_said_not_to_run(tmp_path, caplog):
    caplog.set_level("INFO", logger="sealsim.cases")
    expand_variants(RotaryCase, load_toml(EXAMPLES / "rotary" / "sump_volume.toml"), "sv")
    assert ("sv: runs the variants sump_0.2L, sump_3L; the base case only gives their common "
            "fields and is not run on its own") in caplog.text
    caplog.clear()
    expand_variants(RotaryCase, {k: v for k, v in load_toml(
        EXAMPLES / "rotary" / "sump_volume.toml").items() if k != "variants"}, "plain")
    assert "base case" not in caplog.text


# -- 6. inputs inside --out are never removed ---------------------------------------------------
def test_friction_fit_into_the_folder_of_its_inputs_is_refused(tmp_path):
    project = tmp_path / "proj"
    project.mkdir()
    rig_file(project / "run.csv")
    case = fit_case(project, [measurement("r", "run.csv")])
    before = tree(tmp_path)
    result, text = cli("friction", "fit", case, "--out", project, "--force")
    assert result.exit_code == 2
    one_message(text)
    assert "input file" in text and "lies inside the output folder" in text
    assert tree(tmp_path) == before


def test_pneumatic_compare_into_the_folder_of_its_inputs_is_refused(tmp_path):
    project = tmp_path / "proj"
    project.mkdir()
    (project / "cylinder.toml").write_text((EXAMPLES / "pneumatic" / "cylinder_32.toml")
                                           .read_text())
    (project / "run.csv").write_text("t,x\n0,0\n0.1,1\n0.2,2\n")
    (project / "compare.toml").write_text(tomli_w.dumps({
        "case": "cylinder.toml", "variant": "T25C", "measurement": {
            "file": "run.csv", "delimiter": ",", "header": True,
            "columns": {"time": {"column": "t", "unit": "s"},
                        "position": {"column": "x", "unit": "mm"}}}}))
    before = tree(tmp_path)
    result, text = cli("pneumatic", "compare", project / "compare.toml", "--out", project,
                       "--force")
    assert result.exit_code == 2
    one_message(text)
    assert "lies inside the output folder" in text
    assert tree(tmp_path) == before


# -- 7, 8, 11. names that inject TOML or collide; a fit whose statistics are None ---------------
def test_fit_names_are_escaped_and_overlays_do_not_collide(tmp_path):
    rig_file(tmp_path / "run.csv")
    injected = 'run 1\n[oil]\nname = "VG220-mineral"'
    case = fit_case(tmp_path, [measurement(injected, "run.csv"),
                               measurement("run 1", "run.csv", "validate"),
                               measurement("run_1", "run.csv", "validate")])
    result, text = cli("friction", "fit", case, "--out", tmp_path / "out")
    assert result.exit_code == 0, text
    fitted = (tmp_path / "out" / "fitted_parameters.toml").read_text()
    assert list(tomllib.loads(fitted)) == ["friction"]     # no [oil] table injected
    assert "\\n[oil]" in fitted.splitlines()[1]            # the name shown, escaped
    overlays = sorted(p.name for p in (tmp_path / "out").glob("overlay_*.png"))
    assert overlays == ["overlay_run_1.png", "overlay_run_1_2.png",
                        "overlay_run_1_oil_name_VG220-mineral.png"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fit.toml", "out", "run.csv"]


def test_a_fit_with_a_constant_friction_column_reports_instead_of_crashing(tmp_path):
    rig_file(tmp_path / "run.csv", friction=lambda v: np.full(v.shape, 2.0), noise=0.0)
    case = fit_case(tmp_path, [measurement("flat", "run.csv")])
    result, text = cli("friction", "fit", case, "--out", tmp_path / "out")
    assert result.exception is None or isinstance(result.exception, SystemExit), text
    assert result.exit_code == 1 and "fit failed" in text
    assert "error -" in text          # the relative error of a zero level is not a number
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["measurements"]["flat"]["rel_error"] is None
    assert report["measurements"]["flat"]["r2"] is None


# -- 11. the one-call API on ragged, mismatched, huge and overflowing arrays --------------------
ORING = {"cord_diameter": "2 mm", "squeeze": 0.12}


@pytest.mark.parametrize(("kwargs", "words"), [
    ({"velocity": [["0.1 m/s"], ["0.1 m/s", "0.2 m/s"]]}, ["velocity:", "ragged"]),
    ({"velocity": ["0.1 m/s", "0.2 m/s"], "pressure": ["1 bar", "2 bar", "3 bar"]},
     ["seal_friction:", "velocity has shape (2,)", "pressure has shape (3,)"]),
    ({"velocity": 10 ** 400}, ["velocity:", "no unit"]),
    ({"velocity": unit_registry().Quantity(10 ** 400, "m/s")}, ["velocity:", "too large"]),
    ({"velocity": "1e400 m/s"}, ["velocity:", "not a finite number"]),
    ({"velocity": np.zeros(2_000_000) * unit_registry()("m/s")},
     ["2000000 operating points", "1000000"]),
    ({"diameter": "-12 mm"}, ["diameter: '-12 mm' must be > 0"]),
])
def test_bad_api_arrays_name_the_argument(kwargs, words):
    args = {"seal": ORING, "velocity": "0.1 m/s", "pressure": "2 bar", "diameter": "12 mm",
            **kwargs}
    with pytest.raises(InputError) as err:
        sealsim.seal_friction(**args)
    for word in words:
        assert word in str(err.value), str(err.value)


def test_lip_seal_torque_caps_its_points_before_computing():
    with pytest.raises(InputError, match=r"lip_seal_torque: 20000 operating points"):
        sealsim.lip_seal_torque("60 mm", np.linspace(100, 3000, 20000) * unit_registry()("rpm"),
                                "VG68")


# -- 12. messages that name the cause -----------------------------------------------------------
def test_a_byte_order_mark_in_the_header_is_not_part_of_a_name(tmp_path):
    table = tmp_path / "bom.csv"
    table.write_bytes("t,x,F\n0,0,1\n1,1,1\n2,2,1\n".encode("utf-8-sig"))
    m = read_table(table, [ColumnSpec("time", "t", "s"), ColumnSpec("friction", "F", "N")],
                   delimiter=",", header=True)
    assert m.time.tolist() == [0.0, 1.0, 2.0]


def test_a_three_row_file_is_named(tmp_path):
    (tmp_path / "short.csv").write_text("t,x,F\n0,0,1\n0.1,1,1\n0.2,2,1\n")
    case = validate_case(FrictionFitCase, load_toml(fit_case(tmp_path, [
        measurement("short", "short.csv")])))
    with pytest.raises(InputError, match=r"^measurement 'short' \(.*short\.csv\): "
                                         r"smooth_derivative: 3 samples are too few"):
        prepare_run(case, case.measurements[0], None, tmp_path)


def test_huge_bounds_name_the_parameter_without_a_url(tmp_path):
    rig_file(tmp_path / "run.csv")
    case = fit_case(tmp_path, [measurement("r", "run.csv")], parameters=[
        {"name": "coulomb_force", "bounds": ["0.1 N", "1e400 N"]}])
    result, text = cli("friction", "fit", case, "--out", tmp_path / "out")
    assert result.exit_code == 2
    one_message(text)
    assert ("fit.parameters[0] ('coulomb_force').bounds[1]: '1e400 N' is not a valid "
            "coulomb_force: '1e400 N' is not a finite number") in text
    assert "pydantic" not in text and not (tmp_path / "out").exists()


# -- 13. a real rig's file: ';' and decimal commas, rod force and pressure, the sign -----------
def test_semicolons_and_decimal_commas(tmp_path):
    path = rig_file(tmp_path / "de.csv", delimiter=";", decimal=",")
    spec = [ColumnSpec("time", "t", "s"), ColumnSpec("friction", "F", "N")]
    m = read_table(path, spec, delimiter=";", header=True, decimal=",")
    reference = rig_file(tmp_path / "en.csv")
    assert m.column("friction").tolist() == read_table(
        reference, spec, delimiter=",", header=True).column("friction").tolist()
    with pytest.raises(InputError, match="the line contains ';': set delimiter = ';' "
                                         r"\(and decimal = ','"):
        read_table(path, spec, delimiter=",", header=True)


def test_rod_force_and_pressure_columns_give_the_friction_of_the_tudelft_reader(tmp_path):
    # the TU Delft rig logs the rod force and the pressure: a column mapping computes
    # p*A - F_rod as format = "tudelft" does; the rig counts position the other way, so the
    # mapping flips it (scale = -1) and gets the reader's friction level exactly
    columns = {"time": {"column": 1, "unit": "ms"},
               "position": {"column": 5, "unit": "mm", "scale": -1.0},
               "pressure": {"column": 6, "unit": "bar"}, "force": {"column": 7, "unit": "N"}}
    common = {"file": str(TUDELFT_1BAR), "role": "fit", "bore": "25 mm", "skip_rows": 15,
              "pressure": None}
    common.pop("pressure")
    data = {"friction": COULOMB, "fit": {"parameters": [
        {"name": "coulomb_force", "bounds": ["0.1 N", "50 N"]}]},
        "measurements": [{"name": "reader", "format": "tudelft", **common},
                         {"name": "mapping", "columns": columns, **common}]}
    case = validate_case(FrictionFitCase, data)
    reader, mapping = (prepare_run(case, m, None, tmp_path) for m in case.measurements)
    assert mapping.level == pytest.approx(reader.level, rel=1e-12)
    assert reader.level > 0
    # without the flip the level is negative: refused with the way to flip it
    unflipped = {**columns, "position": {"column": 5, "unit": "mm"}}
    data["measurements"] = [{"name": "mapping", "columns": unflipped, **common}]
    case = validate_case(FrictionFitCase, data)
    with pytest.raises(InputError, match=r"measurement 'mapping' .* negative: .* scale = -1 on "
                                         r"the position \(or velocity\) column"):
        prepare_run(case, case.measurements[0], None, tmp_path)


def test_a_reversed_friction_column_is_refused_with_the_flip(tmp_path):
    rig_file(tmp_path / "run.csv", friction=lambda v: -5.0 * np.sign(v))
    case = fit_case(tmp_path, [measurement("reversed", "run.csv")])
    result, text = cli("friction", "fit", case, "--out", tmp_path / "out")
    assert result.exit_code == 2
    one_message(text)
    assert "measurement 'reversed'" in text and "negative" in text
    assert "scale = -1 on the friction column" in text and "widen the bounds" not in text


# -- 14. the one-call API returns the notes of the CLI, once per call ---------------------------
def test_lip_seal_torque_notes_once_per_call():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        # up to 3500 rpm: at 4000 rpm the gearbox contact (motor adapter on the air side)
        # reaches 152.8 degC, beyond NBR's property range, and the steady state says so
        frame = sealsim.lip_seal_torque("80 mm", ["2500 rpm", "3000 rpm", "3500 rpm"],
                                        "ISO VG 220", "115 degC")
    assert frame["T_contact_C"].min() > 121.0
    notes = frame.attrs["notes"]
    assert any("above the service limit of NBR (100 degC)" in n for n in notes)
    ours = [w for w in caught if issubclass(w.category, SealsimWarning)]
    assert [str(w.message) for w in ours] == notes
    assert not [w for w in caught if not issubclass(w.category, SealsimWarning)]  # none per point


def test_seal_friction_says_an_illustrative_law_is_not_fitted():
    with pytest.warns(SealsimWarning, match="'pneumatic_demo' holds illustrative"):
        r = sealsim.seal_friction(ORING, "0.1 m/s", "2 bar", diameter="12 mm",
                                  law={"law": "theta", "parameter_set": "pneumatic_demo"})
    assert r["notes"] and "not fitted to measurements" in r["notes"][0]


def test_friction_run_summary_notes_an_illustrative_set(tmp_path):
    case = tmp_path / "theta.toml"
    case.write_text('[friction]\nlaw = "theta"\nparameter_set = "pneumatic_demo"\n'
                    '[inputs]\nnormal_force = "60 N"\ncontact_width = "1 mm"\n'
                    '[bench]\nmode = "velocity"\nduration = "0.05 s"\ntime_step = "1 ms"\n'
                    'velocity = { kind = "constant", level = "0.1 m/s" }\n')
    result, text = cli("friction", "run", case, "--out", tmp_path / "out")
    assert result.exit_code == 0, text
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert any("'pneumatic_demo' holds illustrative" in n for n in summary["notes"])


def test_oil_plot_into_the_folder_of_its_oil_file_is_refused(tmp_path):
    project = tmp_path / "proj"
    project.mkdir()
    (project / "oils.toml").write_text(
        '[oils."Gear 150"]\nfamily = "PAO"\nnu40_mm2_s = 150.0\nnu100_mm2_s = 19.0\n'
        'rho15_kg_m3 = 850.0\nsource = "datasheet X"\n')
    before = tree(tmp_path)
    result, text = cli("oil", "plot", "Gear 150", "--oil-file", project / "oils.toml",
                       "--out", project, "--force")
    assert result.exit_code == 2
    one_message(text)
    assert "input file" in text and "lies inside the output folder" in text
    assert tree(tmp_path) == before


def test_pneumatic_seals_note_an_illustrative_set():
    from sealsim.pneumatic.case import build_seals, load_pneumatic_case_file

    cases = load_pneumatic_case_file(EXAMPLES / "pneumatic" / "friction_rig.toml")
    (seal,) = build_seals(next(iter(cases.values())))
    assert any("'pneumatic_demo' holds illustrative" in n for n in seal.notes)
