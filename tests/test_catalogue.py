"""Oil and elastomer files read through the pydantic/pint models of sealsim.properties.catalogue:
the catalogue is unchanged, both file formats are read, errors name file, entry and field."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest

from sealsim.errors import InputError
from sealsim.properties import (
    get_elastomer,
    get_oil,
    list_elastomers,
    list_oils,
    load_elastomer_file,
    load_oil_file,
)
from sealsim.properties.oils import _catalogue as oil_catalogue

#: every field of every catalogue oil and elastomer as read by the hand-written parsers that
#: the pydantic models replaced (written by the code of commit 9cdec80)
REFERENCE = json.loads((Path(__file__).parent / "data" / "catalogue_reference.json").read_text())


def _plain(value):
    """Tuples as lists, recursively (the JSON form of the reference)."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return [_plain(v) for v in value] if isinstance(value, tuple | list) else value


def _assert_same(expected, actual, where):
    if isinstance(expected, dict):
        assert expected.keys() == actual.keys(), where
        for key in expected:
            _assert_same(expected[key], actual[key], f"{where}.{key}")
    elif isinstance(expected, list):
        assert len(expected) == len(actual), where
        for k, (e, a) in enumerate(zip(expected, actual, strict=True)):
            _assert_same(e, a, f"{where}[{k}]")
    elif isinstance(expected, float):
        # 1e-12: the same decimal numbers through pint instead of hand-written factors; any
        # rounding difference is a few ulp (in fact they are bit-identical today)
        assert actual == pytest.approx(expected, rel=1e-12, abs=0.0), where
    else:
        assert actual == expected, where


def test_every_catalogue_entry_gives_the_same_numbers_as_before():
    assert list_oils() == list(REFERENCE["oils"])
    assert list_elastomers() == list(REFERENCE["elastomers"])
    for name in list_oils():
        for key, value in dataclasses.asdict(get_oil(name)).items():
            if key == "thermal_expansion":  # since then ASTM D1250's, not 6.4e-4 for all
                assert value == pytest.approx(0.34878 * 1.8 / get_oil(name).rho15, rel=1e-12)
                continue
            _assert_same(REFERENCE["oils"][name][key], value, f"{name}.{key}")
    for name in list_elastomers():
        for key, value in _plain(dataclasses.asdict(get_elastomer(name))).items():
            if key in ("hyperelastic", "glassy_thermal_expansion"):  # added later; unset
                assert value is None, name
                continue
            _assert_same(REFERENCE["elastomers"][name][key], value, f"{name}.{key}")
    assert oil_catalogue()[1] == REFERENCE["oil_aliases"]


NEW_OIL = """
[oils."Gear 150"]
family = "PAO"
nu40 = "150 mm^2/s"
nu100 = "19 mm^2/s"
density15 = "0.85 g/cm^3"
min_temperature = "-45 degC"
pressure_viscosity_coefficient = "16 1/GPa"
source = "datasheet X"
"""
OLD_OIL = """
[oils."Gear 150"]
family = "PAO"
nu40_mm2_s = 150.0
nu100_mm2_s = 19.0
rho15_kg_m3 = 850.0
min_temperature_degC = -45.0
pressure_viscosity_coefficient_1_GPa = 16.0
source = "datasheet X"
"""


def test_user_oil_file_with_units_and_in_the_older_format(tmp_path):
    new, old = tmp_path / "new.toml", tmp_path / "old.toml"
    new.write_text(NEW_OIL)
    old.write_text(OLD_OIL)
    a, b = load_oil_file(new)["Gear 150"], load_oil_file(old)["Gear 150"]
    _assert_same(dataclasses.asdict(b), dataclasses.asdict(a), "Gear 150")
    assert a.source == "datasheet X"
    assert a.rho15 == pytest.approx(850.0, rel=1e-12)  # g/cm^3 converted by pint
    assert a.pressure_viscosity_coefficient == pytest.approx(16e-9, rel=1e-12)
    assert a.nu100 == pytest.approx(19e-6, rel=1e-9)  # the fit passes through its points


@pytest.mark.parametrize(("body", "words"), [
    ('family = "mineral"\nnu40 = 68\nnu100 = "8.7 mm^2/s"\ndensity15 = "880 kg/m^3"',
     ["oil 'x'", "nu40: 68 has no unit"]),
    ('family = "mineral"\nnu40 = "68 mm"\nnu100 = "8.7 mm^2/s"\ndensity15 = "880 kg/m^3"',
     ["nu40", "expected a kinematic viscosity"]),
    (('family = "mineral"\nnu40 = "68 mm^2/s"\nnu40_mm2_s = 68.0\nnu100 = "8.7 mm^2/s"\n'
      'density15 = "880 kg/m^3"'), ["give nu40 or nu40_mm2_s"]),
    ('family = "mineral"\nnu40_mm2_s = 68.0\nnu100_mm2_s = 8.7\nrho15_kg_m3 = -1.0',
     ["rho15_kg_m3", "out of range", "older file format"]),
    (('family = "mineral"\nnu40 = "68 mm^2/s"\nnu100 = "8.7 mm^2/s"\ndensity15 = "880 kg/m^3"\n'
      'aliases = ["x2"]'), ["aliases: unknown field"]),  # aliases: the catalogue only
    ('family = "solid"\nnu40 = "68 mm^2/s"\nnu100 = "8.7 mm^2/s"\ndensity15 = "880 kg/m^3"',
     ["family = 'solid' is not one of"]),
    # a value out of Oil's range was named as Oil calls it (rho15 = 0.872 kg/m^3,
    # specific_heat_value = 2.1 J/(kg K)), not as the file writes it
    ('family = "mineral"\nnu40 = "68 mm^2/s"\nnu100 = "8.7 mm^2/s"\ndensity15 = "0.872 kg/m^3"',
     ["density15: '0.872 kg/m^3' is out of range: must be >= 600 kg/m^3"]),
    (('family = "mineral"\nnu40 = "68 mm^2/s"\nnu100 = "8.7 mm^2/s"\ndensity15 = "880 kg/m^3"\n'
      'specific_heat = "2.1 J/(kg*K)"'), ["specific_heat: '2.1 J/(kg*K)' is out of range"]),
    (('family = "mineral"\nnu40 = "68 mm^2/s"\nnu100 = "8.7 mm^2/s"\ndensity15 = "880 kg/m^3"\n'
      'thermal_conductivity = "1.3 W/(m*K)"'), ["thermal_conductivity: '1.3 W/(m*K)' is out"]),
    ('family = "mineral"\nwalther_A = 9.3\nwalther_B = -3\ndensity15 = "880 kg/m^3"',
     ["walther_B", "greater than 0"]),
])
def test_bad_oil_entries_name_file_entry_and_field(tmp_path, body, words):
    path = tmp_path / "bad.toml"
    path.write_text('[oils."x"]\n' + body + "\n")
    with pytest.raises(InputError) as info:
        load_oil_file(path)
    message = str(info.value)
    assert str(path) in message
    for word in words:
        assert word in message


ELASTOMER = """
[MYNBR]
description = "house compound"
glass_transition = "-32 degC"
service_min = "-40 degC"
service_max = "110 degC"
density = "1.23 g/cm^3"
thermal_conductivity = "0.25 W/(m*K)"
specific_heat = "1.7 kJ/(kg*K)"
thermal_expansion = "2e-4 1/K"
c10 = "1 MPa"
c01 = "250 kPa"
bulk_modulus = "2 GPa"

[MYNBR.modulus]
glassy = "2 GPa"
rubbery = "2.7 MPa"

[MYNBR.prony]
equilibrium_modulus = "2.7 MPa"
moduli = ["100 MPa", "10 MPa"]
relaxation_times = ["1 ms", "1 s"]
"""


def test_user_elastomer_file_with_units_equals_the_older_format(tmp_path):
    new = tmp_path / "new.toml"
    new.write_text(ELASTOMER)
    old = tmp_path / "old.toml"
    old.write_text(
        "[MYNBR]\ndescription = \"house compound\"\nglass_transition_C = -32\n"
        "service_min_C = -40\nservice_max_C = 110\ndensity_kg_m3 = 1230\n"
        "thermal_conductivity_W_mK = 0.25\nspecific_heat_J_kgK = 1700\n"
        "thermal_expansion_per_K = 2.0e-4\nc10_MPa = 1.0\nc01_MPa = 0.25\n"
        "bulk_modulus_MPa = 2000\n[MYNBR.modulus]\nglassy_MPa = 2000\nrubbery_MPa = 2.7\n"
        "[MYNBR.prony]\nequilibrium_modulus_MPa = 2.7\nmoduli_MPa = [100.0, 10.0]\n"
        "relaxation_times_s = [1e-3, 1.0]\n")
    a, b = load_elastomer_file(new)["MYNBR"], load_elastomer_file(old)["MYNBR"]
    _assert_same(_plain(dataclasses.asdict(b)), _plain(dataclasses.asdict(a)), "MYNBR")
    assert a.prony == (2.7e6, (100e6, 10e6), (1e-3, 1.0))
    assert a.wlf_reference_temperature == a.glass_transition  # the default: T_g


@pytest.mark.parametrize(("edit", "words"), [
    (('density = "1.23 g/cm^3"', 'density = "12.3 g/cm^3"'),
     ["elastomer 'MYNBR'", "field 'density'", "allowed"]),
    (('c10 = "1 MPa"', 'c10 = "1 MPa/s"'), ["c10", "pressure"]),
    (('rubbery = "2.7 MPa"', ''), ["modulus.rubbery: required field is missing"]),
    (('glassy = "2 GPa"', 'glassy = "2 GPa"\nglasy = "1 GPa"'), ["modulus.glasy: unknown"]),
    (('service_max = "110 degC"', 'service_max = "-50 degC"'),
     ["field 'service_min/service_max'"]),
    # below T_g - 100 K every temperature is refused: a service range starting there
    (('service_min = "-40 degC"', 'service_min = "-140 degC"'),
     ["field 'service_min/service_max'", "T_min >= T_g - 100 K = 141.15 K"]),
])
def test_bad_elastomer_entries_name_the_field(tmp_path, edit, words):
    path = tmp_path / "bad.toml"
    path.write_text(ELASTOMER.replace(*edit))
    with pytest.raises(InputError) as info:
        load_elastomer_file(path)
    for word in [str(path), *words]:
        assert word in str(info.value)
