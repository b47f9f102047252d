"""The one-call API (sealsim.lip_seal_torque, sealsim.seal_friction) against the long-form API
it wraps, its unit handling and its errors; the optional duty cycle of a rotary case."""

from __future__ import annotations

import math
import subprocess
import sys
import warnings

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from typer.testing import CliRunner

import sealsim
from sealsim.cases import validate_case
from sealsim.cli import app
from sealsim.errors import InputError, SealsimWarning
from sealsim.friction import ContactInputs, Stribeck, Theta
from sealsim.pneumatic.contact_maps import AnalyticContactMap, FEContactMap
from sealsim.pneumatic.friction_tables import ContactTribology, friction_table_for
from sealsim.properties import get_elastomer
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import simulate, steady_state
from sealsim.units import to_si, unit_registry

RPM = math.pi / 30.0
# the notes of a call (illustrative parameter set, service limit) are tested in
# test_input_meaning.py; here they would only fill the summary
pytestmark = pytest.mark.filterwarnings("ignore::sealsim.errors.SealsimWarning")


def _long_form_case(**environment) -> RotaryCase:
    return validate_case(RotaryCase, {"seal": {"shaft_diameter": "60 mm"},
                                      "oil": {"name": "VG220-mineral"},
                                      "environment": environment})


# -- lip_seal_torque ---------------------------------------------------------------------------
def test_lip_seal_torque_is_the_steady_state_of_the_case():
    r = sealsim.lip_seal_torque(shaft_diameter="60 mm", speed="1500 rpm", oil="ISO VG 220",
                                sump_temperature="70 degC")
    ref = steady_state(_long_form_case(sump_temperature="70 degC"), 1500 * RPM)
    # the same computation: identical numbers, not just close ones
    for key in ("torque_Nm", "power_W", "T_contact_C", "T_groove_C", "T_sump_C", "film_um",
                "F_lub_N", "F_material_N"):
        assert r[key] == ref[key], key
    assert r["speed_rpm"] == pytest.approx(1500.0, rel=1e-12)
    assert r["shaft_diameter_mm"] == pytest.approx(60.0, rel=1e-12)
    # physics sanity: power = torque x speed (exact up to rounding)
    assert r["power_W"] == pytest.approx(r["torque_Nm"] * 1500 * RPM, rel=1e-12)


def test_lip_seal_torque_vectorised_one_row_per_point():
    speeds = unit_registry().Quantity(np.array([500.0, 3000.0]), "rpm")
    frame = sealsim.lip_seal_torque("60 mm", speeds, "VG220-mineral",
                                    ["50 degC", "90 degC"])  # broadcast pairwise
    assert isinstance(frame, pd.DataFrame) and len(frame) == 2
    for k, (rpm, sump) in enumerate([(500.0, "50 degC"), (3000.0, "90 degC")]):
        ref = steady_state(_long_form_case(sump_temperature=sump), rpm * RPM)
        assert frame.loc[k, "torque_Nm"] == ref["torque_Nm"]
        assert frame.loc[k, "T_contact_C"] == ref["T_contact_C"]
    # a free sump (no sump_temperature) heats up by the seal alone: the case default
    free = sealsim.lip_seal_torque("60 mm", "1000 rpm", "VG220-mineral")
    assert free["torque_Nm"] == steady_state(_long_form_case(), 1000 * RPM)["torque_Nm"]


def test_lip_seal_torque_options_reach_the_case():
    r = sealsim.lip_seal_torque("80 mm", "1000 rpm", {"name": "my gear oil", "nu40": "150 mm^2/s",
                                                      "nu100": "14.7 mm^2/s",
                                                      "density15": "890 kg/m^3"},
                                "60 degC", material="FKM", lip_style="wave",
                                case={"environment": {"sump_volume": "0.2 L"}})
    case = validate_case(RotaryCase, {
        "seal": {"shaft_diameter": "80 mm", "material": "FKM", "lip_style": "wave"},
        "oil": {"name": "my gear oil", "nu40": "150 mm^2/s", "nu100": "14.7 mm^2/s",
                "density15": "890 kg/m^3"},
        "environment": {"sump_temperature": "60 degC", "sump_volume": "0.2 L"}})
    assert r["torque_Nm"] == steady_state(case, 1000 * RPM)["torque_Nm"]


@pytest.mark.parametrize(("case", "words"), [
    ({"seal": {"material": "FKM"}}, ["case: seal.material = 'FKM'", "argument material="]),
    ({"seal": {"shaft_diameter": "100 mm"}}, ["seal.shaft_diameter", "shaft_diameter="]),
    ({"environment": {"sump_temperature": "90 degC"}}, ["sump_temperature="]),
    ({"oil": {"name": "VG68-mineral"}}, ["[oil] is the argument oil="]),
])
def test_lip_seal_torque_refuses_a_case_field_that_an_argument_sets(case, words):
    # One of the two was dropped without a word: the case's seal.material won over
    # material='HNBR', the argument shaft_diameter over the case's, the argument
    # sump_temperature over the case's.
    with pytest.raises(InputError) as info:
        sealsim.lip_seal_torque("60 mm", "1500 rpm", "VG220", "70 degC", material="HNBR",
                                case=case)
    for word in words:
        assert word in str(info.value)


@pytest.mark.parametrize(("kwargs", "words"), [
    ({"speed": 1500}, ["speed", "no unit", "rpm or rad/s"]),
    ({"speed": [1000, 2000]}, ["speed", "without a unit"]),
    ({"speed": "25 Hz"}, ["Hz is ambiguous"]),
    ({"speed": "-10 rpm"}, ["speed", ">= 0"]),
    ({"speed": "1500 m"}, ["speed", "angular speed"]),
    ({"oil": "ISO VG 230"}, ["unknown oil", "close matches", "VG320"]),
    ({"material": "NRB"}, ["unknown elastomer", "NBR"]),
    ({"shaft_diameter": "2 mm"}, ["seal.shaft_diameter", "out of range"]),
    ({"sump_temperature": "70 degF", "oil": "VG32"}, []),  # valid: 21 degC
    # a case file's name or a list: AttributeError 'str' object has no attribute 'get'
    ({"case": "gearbox.toml"}, ["case: 'gearbox.toml' must be a mapping of case tables"]),
    ({"oil": None}, ["oil: None is neither a catalogue name"]),
    ({"mounting_temperature": "-280 degC"}, ["mounting_temperature: -280 degC", "absolute zero"]),
])
def test_lip_seal_torque_errors_name_the_argument(kwargs, words):
    args = {"shaft_diameter": "60 mm", "speed": "1500 rpm", "oil": "VG220",
            "sump_temperature": "70 degC", **kwargs}
    if not words:
        assert sealsim.lip_seal_torque(**args)["T_sump_C"] == pytest.approx(21.111, abs=1e-3)
        return
    with pytest.raises(InputError) as info:
        sealsim.lip_seal_torque(**args)
    for word in words:
        assert word in str(info.value)


def test_lip_seal_torque_takes_an_oil_built_in_python():
    # A notebook user's Oil.from_datasheet went into lip_seal_torque as dict(oil): TypeError
    # 'Oil' object is not iterable.  The Oil and the same datasheet as a table: one result.
    from sealsim.properties import Oil

    oil = Oil.from_datasheet("my VG 46", 46e-6, 6.8e-6, 872.0, min_temperature=234.15)
    table = {"name": "my VG 46", "nu40": "46 mm^2/s", "nu100": "6.8 mm^2/s",
             "density15": "872 kg/m^3", "min_temperature": "-39 degC"}
    by_object = sealsim.lip_seal_torque("80 mm", "1000 rpm", oil, "60 degC")
    by_table = sealsim.lip_seal_torque("80 mm", "1000 rpm", table, "60 degC")
    # the table's nu40/nu100 pass through pint (mm^2/s): the same oil to a few ulp
    assert by_object["torque_Nm"] == pytest.approx(by_table["torque_Nm"], rel=1e-9)
    with pytest.raises(InputError, match=r"oil: 46 is neither a catalogue name"):
        sealsim.lip_seal_torque("80 mm", "1000 rpm", 46, "60 degC")


def test_lip_seal_torque_takes_the_datasheet_pour_point_of_your_oil():
    # An own oil could give nu40, nu100, density15 and family only: its pour point was the
    # typical one of its grade (VG 46 mineral: -27 degC), so a cold start at -33 degC of an oil
    # rated to -39 degC was refused with no way to say so.
    own = {"name": "HVI 46", "nu40": "46 mm^2/s", "nu100": "8.0 mm^2/s",
           "density15": "872 kg/m^3"}
    cold = {"sump_temperature": "-33 degC", "ambient_temperature": "-33 degC"}
    with pytest.raises(InputError, match=r"-27.0 degC\); if your oil's datasheet gives a lower "
                                         r"pour point, set it as oil.min_temperature"):
        sealsim.lip_seal_torque("80 mm", "300 rpm", own, **cold)
    r = sealsim.lip_seal_torque("80 mm", "300 rpm", {**own, "min_temperature": "-39 degC"},
                                **cold)
    assert r["T_sump_C"] == pytest.approx(-33.0, abs=1e-9) and r["torque_Nm"] > 0


# -- rotary case without a duty cycle ----------------------------------------------------------
def test_rotary_case_needs_no_duty_for_steady_state(tmp_path):
    case = RotaryCase(seal={"shaft_diameter": 0.06})
    assert case.duty is None
    assert steady_state(case, 100.0)["torque_Nm"] > 0
    with pytest.raises(InputError, match="duty: a transient run needs a duty cycle"):
        simulate(case)
    path = tmp_path / "no_duty.toml"
    path.write_text('[seal]\nshaft_diameter = "60 mm"\n')
    result = CliRunner().invoke(app, ["rotary", "run", str(path), "--out", str(tmp_path / "o")])
    assert result.exit_code == 2 and "duty" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "o").exists()


# -- seal_friction -----------------------------------------------------------------------------
def _nbr_oring_map(diameter=0.012) -> AnalyticContactMap:
    nbr = get_elastomer("NBR")
    return AnalyticContactMap(sliding_diameter=diameter, cord_diameter=2e-3, squeeze=0.12,
                              modulus=6.0 * (nbr.c10 + nbr.c01),
                              thermal_expansion=nbr.thermal_expansion)


def test_seal_friction_is_the_steady_force_of_the_law_on_the_map():
    # the default: the Θ law whose steady curve comes from the seal's own contact
    v = np.array([-0.5, 0.01, 0.1, 1.0])
    frame = sealsim.seal_friction({"cord_diameter": "2 mm", "squeeze": 0.12},
                                  v * unit_registry()("m/s"), "6 bar", "40 degC",
                                  diameter="12 mm")
    contact_map = _nbr_oring_map()
    fn, b = contact_map.evaluate(np.full(4, 6e5), np.full(4, 313.15))
    law = Theta.from_parameter_set("seal_contact")
    table = friction_table_for(contact_map, ContactTribology.from_law(law, "NBR"))
    ref = law.steady_force(v, ContactInputs(normal_force=fn, contact_width=b,
                                            pressure_a=np.full(4, 6e5), pressure_b=0.0,
                                            temperature=np.full(4, 313.15),
                                            contact_table=table, sliding_diameter=0.012))
    np.testing.assert_array_equal(frame["friction_N"], ref)  # same computation
    _, _, film = table.evaluate(v, 6e5, 313.15)
    np.testing.assert_array_equal(frame["film_um"], film * 1e6)
    assert np.all((frame["asperity_share"] >= 0) & (frame["asperity_share"] <= 1))
    np.testing.assert_array_equal(frame["normal_force_N"], fn)
    assert list(frame["pressure_bar"]) == [6.0] * 4
    assert frame["temperature_C"].to_numpy() == pytest.approx(40.0, abs=1e-12)
    assert frame.loc[0, "friction_N"] < 0 < frame.loc[1, "friction_N"]  # opposes the motion


def test_seal_friction_at_rest_is_zero_with_the_limit_named():
    # At v = 0 the steady sliding friction has no direction: 0 N, no film or asperity share
    # (before: film 0 and share 0 -- the asperities carry everything as u -> 0, Eq. (1) of
    # mixed_lubrication); the note gives the limit towards rest, which for the contact's
    # Stribeck curve is the boundary friction mu_b * F_N (0.2 * 38.0 N; the table is flat
    # below 1e-7 m/s, where the viscous term and the film are 1e-3 of it: 2 %).
    with pytest.warns(SealsimWarning, match=r"velocity 0 m/s \(1 of 2 points\).* tends to "
                                            r"7\.[45]\d? N"):
        frame = sealsim.seal_friction({"cord_diameter": "2 mm", "squeeze": 0.12},
                                      ["0 m/s", "1e-6 m/s"], "6 bar", diameter="12 mm")
    assert frame.loc[0, "friction_N"] == 0.0
    assert frame.loc[0, ["film_um", "asperity_share", "transport_mm3_per_m"]].isna().all()
    assert 0.2 * frame.loc[0, "normal_force_N"] == pytest.approx(7.6, abs=0.05)
    assert frame.loc[1, "asperity_share"] > 0.95


def test_a_law_that_ignores_the_contact_says_so():
    # LuGre (canudas1995, newtons) on an O-ring at 6 bar: 1.04 N whatever F_N = 101 N and b
    # the result showed beside it, without a word; the Θ law on the contact has no such note
    seal = {"cord_diameter": "2 mm", "squeeze": 0.12}
    with pytest.warns(SealsimWarning, match=r"the lugre law's friction does not depend on the "
                                            r"seal's normal force and contact width"):
        out = sealsim.seal_friction(seal, "0.1 m/s", "6 bar", diameter="32 mm", law="lugre")
    assert out["normal_force_N"] > 50.0 and out["friction_N"] < 2.0
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        theta = sealsim.seal_friction(seal, "0.1 m/s", "6 bar", diameter="32 mm")
    assert not any("does not depend" in str(w.message) for w in caught)
    assert not any("does not depend" in n for n in theta["notes"])


def test_seal_friction_pressure_scaling_and_broadcasting():
    # the Stribeck law's F_C = F_pr + f (p_A + p_B) gets the gauge pressure as p_A
    law = {"law": "stribeck", "parameter_set": "pneumatic_demo"}
    out = sealsim.seal_friction(_nbr_oring_map(), "0.05 m/s", ["0 bar", "4 bar", "8 bar"],
                                law=law)
    ref = Stribeck.from_parameter_set("pneumatic_demo").steady_force(
        np.full(3, 0.05), ContactInputs(pressure_a=np.array([0.0, 4e5, 8e5])))
    np.testing.assert_allclose(out["friction_N"], ref, rtol=1e-14)
    one = sealsim.seal_friction(_nbr_oring_map(), "0.05 m/s", "4 bar", law=law)
    assert isinstance(one, dict) and one["friction_N"] == pytest.approx(ref[1], rel=1e-14)


def test_seal_friction_from_an_fe_map_file(tmp_path):
    # a small characteristic map in the format of sealsim structure map (F_N, b over p, T)
    p, t = np.array([0.0, 4e5, 8e5]), np.array([283.15, 333.15])
    fn = 30.0 + 5e-5 * p[None, None, :] + 0.1 * (t[None, :, None] - 283.15)
    ds = xr.Dataset({"F_N": (("squeeze", "temperature", "pressure"), fn),
                     "b": (("squeeze", "temperature", "pressure"), 1e-3 + 0 * fn)},
                    coords={"squeeze": [0.12], "temperature": t, "pressure": p})
    path = tmp_path / "map.nc"
    ds.to_netcdf(path)
    v = [0.02, 0.2]
    speeds = ["0.02 m/s", "0.2 m/s"]
    # a map without contact pressure profiles: the contact law cannot be used, say so
    with pytest.raises(InputError, match="no contact pressure profile"):
        sealsim.seal_friction(path, speeds, "5 bar", "30 degC")
    lumped = {"law": "theta", "parameter_set": "pneumatic_demo"}
    out = sealsim.seal_friction(path, speeds, "5 bar", "30 degC", law=lumped)
    assert out["film_um"].isna().all()
    fe = FEContactMap.from_file(path)
    f_n, b = fe.evaluate(np.full(2, 5e5), np.full(2, 303.15))
    ref = Theta.from_parameter_set("pneumatic_demo").steady_force(
        np.array(v), ContactInputs(normal_force=f_n, contact_width=b,
                                   pressure_a=np.full(2, 5e5), temperature=np.full(2, 303.15)))
    np.testing.assert_allclose(out["friction_N"], ref, rtol=1e-14)
    # linear data: the Hermite map reproduces it (interpolation round-off only)
    assert out["normal_force_N"].to_numpy() == pytest.approx(30.0 + 25.0 + 2.0, rel=1e-9)
    with pytest.raises(InputError, match=r"pressure: 9 bar is outside .* \(0 \.\.\. 8 bar\)"):
        sealsim.seal_friction(path, "0.2 m/s", "9 bar", "30 degC", law=lumped)
    with pytest.raises(InputError, match="temperature: 80 degC is outside"):
        sealsim.seal_friction(path, "0.2 m/s", "5 bar", "80 degC", law=lumped)


def test_seal_friction_follows_the_pressure_range_of_an_analytic_map(tmp_path, monkeypatch):
    # the contact friction table is cached per map; the analytic map's pressure_max was not
    # part of the key, so a table built for 0 ... 16 bar served a map up to 100 bar and the
    # friction stayed at its 16 bar value (0.51 N at 20, 50 and 100 bar, F_N 120 -> 3552 N)
    monkeypatch.setenv("SEALSIM_CACHE", str(tmp_path))
    oring = {"cord_diameter": "2 mm", "squeeze": 0.12}
    at_16 = sealsim.seal_friction(oring, "0.1 m/s", "16 bar", diameter="12 mm")
    wide = sealsim.seal_friction({**oring, "pressure_max": "100 bar"}, "0.1 m/s",
                                 ["16 bar", "50 bar", "100 bar"], diameter="12 mm")
    # the same point from both tables (grids of 9 nodes over 0-16 and 0-100 bar)
    assert wide["friction_N"].iloc[0] == pytest.approx(at_16["friction_N"], rel=0.01)
    assert wide["friction_N"].is_monotonic_increasing
    assert wide["friction_N"].iloc[2] > 10 * at_16["friction_N"]
    with pytest.raises(InputError, match="pressure_max"):
        sealsim.seal_friction(oring, "0.1 m/s", "20 bar", diameter="12 mm")


@pytest.mark.parametrize(("kwargs", "words"), [
    ({"law": "stribeck"}, ["parameter sets", "modelica_friction_example"]),
    ({"law": "theta"}, ["parameter sets", "pneumatic_demo", "seal_contact"]),
    ({"law": "friction"}, ["not a friction law", "theta"]),
    ({"law": {"law": "coulomb"}}, ["law", "coulomb_force"]),
    ({"diameter": None}, ["diameter of the sliding surface"]),
    ({"seal": "seal.stl"}, ["neither a structure case"]),
    ({"seal": {"cord_diameter": "2 mm", "squeeze": 0.12, "elastomer": "NRB"}},
     ["unknown elastomer", "NBR"]),
    ({"velocity": "1 rpm"}, ["velocity", "velocity"]),
    ({"pressure": "-1 bar"}, ["pressure", ">= 0"]),
    # -300 degC went on as -26.85 K, and was refused as 'within 20 K of the T_g of NBR'
    ({"temperature": ["20 degC", "-300 degC"]},
     ["temperature: -300 degC (-26.85 K) is at or below absolute zero"]),
])
def test_seal_friction_errors(kwargs, words):
    args = {"seal": {"cord_diameter": "2 mm", "squeeze": 0.12}, "velocity": ["0.1 m/s"],
            "pressure": "2 bar", "diameter": "12 mm", **kwargs}
    with pytest.raises(InputError) as info:
        sealsim.seal_friction(**args)
    for word in words:
        assert word in str(info.value)


# -- units at the edge -------------------------------------------------------------------------
def test_to_si_arrays_and_quantities():
    q = unit_registry().Quantity
    assert to_si(q(np.array([1.0, 2.0]), "bar"), "pressure").tolist() == [1e5, 2e5]
    assert to_si(np.array([[1.0], [2.0]]), "length").shape == (2, 1)
    assert to_si("20 degC", "temperature") == pytest.approx(293.15, abs=1e-12)
    for bad, match in ((q(np.array([1.0]), "Hz"), "Hz is ambiguous"),
                       (q(np.array([1.0]), "m"), "expected an angular speed"),
                       ([float("nan")], "not finite"), (True, "not a quantity")):
        with pytest.raises(InputError, match=match):
            to_si(bad, "angular_speed", plain_is_si=True)


def test_import_sealsim_stays_light():
    code = ("import sys, sealsim; heavy = [m for m in ('sealsim.api', 'pint', 'pandas', "
            "'scipy') if m in sys.modules]; print(','.join(heavy))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == ""  # the one-call functions are imported on first use
    assert callable(sealsim.lip_seal_torque) and "seal_friction" in dir(sealsim)
