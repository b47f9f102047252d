"""Units at the edges: sealsim.units.parse_quantity / format_quantity."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sealsim.cases import load_toml
from sealsim.errors import InputError
from sealsim.measurements import ColumnSpec, read_table
from sealsim.pneumatic.case import load_pneumatic_cases
from sealsim.units import DIMENSIONS, format_quantity, parse_quantity, to_si, ureg

# Conversions are exact up to float rounding of the conversion factors: 1e-12 relative.
REL = 1e-12


@pytest.mark.parametrize(
    ("text", "dimension", "si"),
    [
        ("80 mm", "length", 0.08),
        ("3.5 in", "length", 3.5 * 0.0254),
        ("1500 rpm", "angular_speed", 1500 * 2 * math.pi / 60),
        ("2 rev/s", "angular_speed", 4 * math.pi),
        ("2 rps", "angular_speed", 4 * math.pi),  # sealsim defines rps = rev/s
        ("10 rad/s", "angular_speed", 10.0),
        ("55 degC", "temperature", 328.15),
        ("300 K", "temperature", 300.0),
        ("0.2 L", "volume", 2e-4),
        ("6 bar", "pressure", 6e5),
        ("12 mPa*s", "dynamic_viscosity", 0.012),
        ("68 mm**2/s", "kinematic_viscosity", 68e-6),
        # a length's exponent as data sheets write it: 'mm2' is mm², not an unknown unit
        ("46 mm2/s", "kinematic_viscosity", 46e-6),
        ("880 kg/m3", "density", 880.0),
        ("12 W/(m2 K)", "heat_transfer_coefficient", 12.0),
        ("2.5 N/mm2", "pressure", 2.5e6),
        ("15 cm3", "volume", 15e-6),
        ("100 mmH2O", "pressure", 980.665),       # a unit whose name holds a digit stays
        ("10 Hz", "frequency", 10.0),  # Hz is fine where a frequency is meant
        ("  -1.5e3 N  ", "force", -1500.0),  # sign, exponent, surrounding blanks
        ("0.3", "dimensionless", 0.3),
    ],
)
def test_parse_quantity_converts_to_si(text, dimension, si):
    assert parse_quantity(text, dimension) == pytest.approx(si, rel=REL)


def test_plain_number_is_fine_for_dimensionless():
    assert parse_quantity(0.25, "dimensionless") == 0.25
    assert parse_quantity(2, "dimensionless") == 2.0


@pytest.mark.parametrize(
    ("text", "dimension", "expected_words"),
    [
        ("80 kg", "length", ["'80 kg'", "length", "80 mm"]),  # names value, dimension, example
        ("6 m", "pressure", ["'6 m'", "pressure"]),
        ("55 degC", "length", ["length"]),
        # the dimension as words, with its article (was "expected a angular_speed")
        ("3 m", "angular_speed", ["expected an angular speed", "1500 rpm"]),
        ("1 m", "inverse_pressure", ["expected an inverse pressure"]),
        # C and F are pint's coulomb and farad: the message says to write degC / degF
        ("23 C", "temperature", ["'23 C'", "temperature", "coulomb", "degC"]),
        ("73 F", "temperature", ["farad", "degF"]),
        ("5 C", "temperature_difference", ["temperature difference", "degC"]),
    ],
)
def test_wrong_dimension_is_an_input_error(text, dimension, expected_words):
    with pytest.raises(InputError) as err:
        parse_quantity(text, dimension)
    for word in expected_words:
        assert word in str(err.value)


@pytest.mark.parametrize("text", ["80 furlongz", "3 mmm", "5 m/(s"])
def test_unknown_unit_is_an_input_error(text):
    with pytest.raises(InputError, match="unknown unit|cannot read"):
        parse_quantity(text, "length")


@pytest.mark.parametrize("value", ["80", 80, 80.0])
def test_missing_unit_is_an_input_error(value):
    # a bare number for a dimensional field is ambiguous (mm? m?): refused, with an example
    with pytest.raises(InputError, match="no unit") as err:
        parse_quantity(value, "length")
    assert "80 mm" in str(err.value)


@pytest.mark.parametrize(
    ("value", "dimension"),
    [("nan mm", "length"), ("inf bar", "pressure"), ("-inf K", "temperature"),
     (float("nan"), "dimensionless"), (float("inf"), "dimensionless"), ("1e400 m", "length")],
)
def test_non_finite_values_are_refused(value, dimension):
    with pytest.raises(InputError, match="finite"):
        parse_quantity(value, dimension)


@pytest.mark.parametrize("text", [
    "25 Hz", "25 hertz", "25 1/s*Hz/Hz Hz",
    "25 kHz",
])
def test_hz_is_refused_for_angular_speed(text):
    # pint takes 1 Hz = 1 rad/s whereas engineers mean 1 rev/s: ambiguous, so refused
    with pytest.raises(InputError, match="rpm"):
        parse_quantity(text, "angular_speed")


@pytest.mark.parametrize(("text", "hz"), [
    ("1 rad/s", 1 / (2 * math.pi)), ("60 rpm", 1.0), ("360 deg/s", 1.0), ("2 rev/s", 2.0),
    ("60 1/min", 1.0), ("1 kHz", 1000.0), ("3 1/s", 3.0),
])
def test_a_frequency_given_as_an_angular_frequency_keeps_its_2_pi(text, hz):
    # pint counts the radian as 1: it read 1 rad/s as 1 Hz and 60 rpm as 6.28 Hz (friction
    # loops, DMA test frequencies, rheometer files in rad/s); f = omega / 2 pi
    assert parse_quantity(text, "frequency") == pytest.approx(hz, rel=REL)
    assert to_si(ureg.Quantity([1.0, 2.0], text.split(" ", 1)[1]), "frequency")[1] == \
        pytest.approx(2 * hz / float(text.split(" ")[0]), rel=REL)


@pytest.mark.parametrize(("text", "kelvin"), [
    ("10 degC", 10.0), ("18 degF", 10.0), ("10 K", 10.0), ("-5 degC", -5.0),
    ("10 delta_degC", 10.0),
])
def test_a_temperature_difference_in_degc_is_that_difference(text, kelvin):
    # a rise, an uncertainty, WLF's C2 written "10 degC": 10 K, not the temperature 283.15 K
    assert parse_quantity(text, "temperature_difference") == pytest.approx(kelvin, rel=REL)
    assert to_si([text], "temperature_difference")[0] == pytest.approx(kelvin, rel=REL)
    assert parse_quantity("10 degC", "temperature") == pytest.approx(283.15, rel=REL)


@pytest.mark.parametrize("value", ["-300 degC", "0 K", ["20 degC", "-500 degF"]])
def test_a_temperature_at_or_below_absolute_zero_is_refused(value):
    # '-300 degC' (a typo for -30) went on as -26.85 K into whatever model met it first
    with pytest.raises(InputError, match=r"^T: .* is at or below absolute zero"):
        to_si(value, "temperature", "T")
    if isinstance(value, str):
        with pytest.raises(InputError, match="absolute zero"):
            parse_quantity(value, "temperature")
    assert to_si("-5 degC", "temperature_difference") == pytest.approx(-5.0)   # a difference


def test_a_decimal_comma_is_named():
    # '1,5 mm' (a German engineer's decimal comma) was 'unknown unit ',5 mm''
    with pytest.raises(InputError, match=re.escape("decimal point (1.5 mm)")):
        parse_quantity("1,5 mm", "length")


def test_an_angle_needs_an_angle_unit():
    # pint counts the radian as 1: a cylinder's incline of '90' or '50 %' was taken as 90 rad
    # (refused only by the range, 'must be <= 1.57') and 0.5 rad; a plain 1 as 57 degrees
    assert parse_quantity("90 deg", "angle") == pytest.approx(math.pi / 2, rel=REL)
    assert parse_quantity("-1.2 rad", "angle") == pytest.approx(-1.2, rel=REL)
    for text, words in (("90", "no unit"), ("50 %", "no angle unit"), ("3 m", "[length]")):
        with pytest.raises(InputError, match=re.escape(words)):
            parse_quantity(text, "angle")
    with pytest.raises(InputError, match="an angle unit"):
        parse_quantity(1, "angle")
    case = load_toml(Path(__file__).resolve().parents[1] / "examples/pneumatic/cylinder_32.toml")
    case["cylinder"]["incline"] = "30"
    with pytest.raises(InputError, match="cylinder.incline: '30' has no unit"):
        load_pneumatic_cases(case)


def test_a_measured_frequency_column_in_rad_s_is_read_as_hz(tmp_path):
    # a rheometer writes the angular frequency: 6.283 rad/s is 1 Hz
    path = tmp_path / "dma.csv"
    path.write_text("t,omega\n0,6.283185307179586\n1,62.83185307179586\n2,1\n")
    m = read_table(path, [ColumnSpec("time", "t", "s"), ColumnSpec("frequency", "omega",
                                                                    "rad/s")],
                   delimiter=",", header=True)
    assert m.column("frequency") == pytest.approx([1.0, 10.0, 1 / (2 * math.pi)], rel=REL)


@pytest.mark.parametrize("value", [True, None, [80, "mm"], {"value": 80}, b"80 mm"])
def test_non_quantity_types_are_refused(value):
    with pytest.raises(InputError, match="not a quantity"):
        parse_quantity(value, "length")


def test_field_name_starts_the_message():
    with pytest.raises(InputError) as err:
        parse_quantity("80 kg", "length", field="seal.shaft_diameter")
    assert str(err.value).startswith("seal.shaft_diameter: ")


@pytest.mark.parametrize(
    ("si", "dimension", "text"),
    [(0.08, "length", "80 mm"), (328.15, "temperature", "55 degC"),
     (6e5, "pressure", "6 bar"), (2e-4, "volume", "0.2 L"), (0.3, "dimensionless", "0.3")],
)
def test_format_quantity_writes_display_units(si, dimension, text):
    assert format_quantity(si, dimension) == text


def _si_values(dimension: str):
    if dimension == "temperature":
        # absolute temperatures; near 0 K the degC offset would cost relative precision
        return st.floats(min_value=1.0, max_value=1e4)
    magnitude = st.floats(min_value=1e-12, max_value=1e12)
    return st.one_of(magnitude, magnitude.map(lambda v: -v), st.just(0.0))


@settings(max_examples=200, deadline=None)
@given(data=st.data(), dimension=st.sampled_from(sorted(DIMENSIONS)))
def test_format_then_parse_round_trips(data, dimension):
    value = data.draw(_si_values(dimension))
    back = parse_quantity(format_quantity(value, dimension), dimension)
    # format_quantity keeps 12 significant digits: 1e-9 relative leaves room for the unit
    # conversion (e.g. K -> degC -> K); abs 1e-300 only for the exact zero
    assert back == pytest.approx(value, rel=1e-9, abs=1e-300)


def test_parsed_strings_are_cached_but_each_error_names_its_field():
    """The string cache (a study re-validates the same case strings every run) returns the
    same SI value and never a stale error: errors are raised afresh with the field's name."""
    from sealsim.units import _string_to_si

    assert parse_quantity("80 mm", "length") == parse_quantity("80 mm", "length") == 0.08
    hits = _string_to_si.cache_info().hits
    parse_quantity("80 mm", "length", field="seal.diameter")
    assert _string_to_si.cache_info().hits == hits + 1
    for field in ("cylinder.bore", "cylinder.stroke"):
        with pytest.raises(InputError, match=rf"^{field}: '3 kg' has dimension"):
            parse_quantity("3 kg", "length", field=field)
