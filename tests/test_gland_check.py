"""O-ring gland design check (sealsim.structure.gland_check, sealsim.oring_gland,
``sealsim gland check``): hand calculations, the worst-case stack against brute force over the
tolerance corners, the ISO 286 tables against the standard's formulas, the result folder."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

import sealsim
from sealsim.cases import apply_overrides, load_toml, validate_case
from sealsim.cli import app
from sealsim.errors import InputError
from sealsim.structure.gland_case import GlandCase
from sealsim.structure.gland_check import (
    corner_values,
    extrusion_gap_limit,
    geometry_of,
    installed_cord,
    worst_case,
)
from sealsim.structure.tolerances import (
    FUNDAMENTAL_DEVIATIONS_UM,
    IT_GRADES_UM,
    SIZE_STEPS_MM,
    iso286_deviations,
    iso3601_inner_diameter_tolerance,
)
from sealsim.units import parse_quantity

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "gland"
#: hand calculations are written to 4-5 digits: agreement to 0.1 percentage points (the
#: issue's target) leaves room for that rounding only
PP = 0.1


def _case(name: str, overrides: dict | None = None) -> GlandCase:
    data = apply_overrides(load_toml(EXAMPLES / name), overrides or {})
    return validate_case(GlandCase, data, name)


def test_piston_gland_of_a_seal_makers_housing_table_by_hand():
    # O-Rings Ltd's housing table (orings.co.uk/o-ring-housing) for d2 = 3.55 mm: static radial
    # depth 2.70 mm, width 4.80 +0.25 mm; 25 H8 bore, 19.5 h9 groove (example file), at the
    # assembly temperature only (no thermal effect), ring 19 x 3.55 with ISO 3601-1 tolerances.
    # By hand:
    #   bore 25 H8: 25.000 ... 25.033; groove 19.5 h9 (IT9 = 52 um): 19.448 ... 19.500
    #   d2 = 3.55 +- 0.10; d1 = 19 +- (0.009 * 19^0.95 + 0.11) = 19 +- 0.2576
    #   nominal: groove 19.474, bore 25.0165 -> h = 2.77125; d1 19 stretched onto 19.474:
    #     (19.474 + x) x^2 = (19 + 3.55) * 3.55^2 = 284.189 -> x = 3.5142
    #     squeeze = (3.5142 - 2.77125) / 3.5142 = 21.14 %
    #   min: d2 3.45, d1 18.7424, groove 19.448 (deeper gland wins over more stretch),
    #     bore 25.033 -> h = 2.7925; (19.448 + x) x^2 = 22.1924 * 3.45^2 -> x = 3.3972
    #     squeeze = (3.3972 - 2.7925) / 3.3972 = 17.80 %
    #   max: d2 3.65, d1 19.2576 (least stretch), groove 19.500 (shallower gland wins over
    #     more stretch), bore 25.000 -> h = 2.75; stretched onto 19.5:
    #     (19.5 + x) x^2 = (19.2576 + 3.65) * 3.65^2 = 305.192 -> x = 3.6313
    #     squeeze = (3.6313 - 2.75) / 3.6313 = 24.27 %
    #   fill max: largest section 3.6313 (as above) in the smallest groove 2.75 x 4.80:
    #     pi/4 * 3.6313^2 / (2.75 * 4.80) = 10.3564 / 13.2 = 78.46 %
    #   stretch max: d1 18.7424 on 19.5: (19.5 - 18.7424) / 18.7424 = 4.042 %
    #   gap max: 25.033 - 24.959 = 0.074 mm
    case = _case("piston_static.toml", {"service": {"temperature": ["20 degC"]}})
    r = sealsim.oring_gland(case)
    assert r["squeeze_percent"]["nominal"] == pytest.approx(21.14, abs=PP)
    assert r["squeeze_percent"]["min"] == pytest.approx(17.80, abs=PP)
    assert r["squeeze_percent"]["max"] == pytest.approx(24.27, abs=PP)
    assert r["gland_fill_percent"]["max"] == pytest.approx(78.46, abs=PP)
    assert r["stretch_percent"]["max"] == pytest.approx(4.042, abs=PP)
    assert r["extrusion_gap_mm"]["max"] == pytest.approx(0.074, abs=1e-6)
    assert r["ok"]


def test_flange_gland_of_a_seal_suppliers_worked_example():
    # NH O-Ring's O-ring lexicon, "Sealing effect" (nh-oring.de/en/sealing-effect-o-ring-lexicon,
    # read 2026-11-27), worked example of a standard flange seal: cord 3 mm in a groove 2.3 mm
    # deep, "the O-ring is therefore 0.7 mm larger" -> squeeze 0.7 / 3 = 23.33 %.  The source
    # gives only cord and depth; the ring sits unstretched on the groove's inner diameter and
    # the flanges touch (gap 0), so nothing else enters the squeeze.  The fill is not in the
    # source: by hand, pi/4 * 3^2 / (2.3 * 4.0) = 7.0686 / 9.2 = 76.83 % in a 4.0 mm groove.
    case = _case("face_static.toml", {
        "ring": {"cord_diameter": "3 mm", "inner_diameter": "30 mm"},
        "housing": {"groove_depth": {"nominal": "2.3 mm", "upper": "0 mm", "lower": "0 mm"},
                    "groove_width": {"nominal": "4 mm", "upper": "0 mm", "lower": "0 mm"},
                    "groove_inner_diameter": {"nominal": "30 mm", "upper": "0 mm",
                                              "lower": "0 mm"},
                    "gap": {"nominal": "0 mm", "upper": "0 mm", "lower": "0 mm"}},
        "service": {"temperature": ["20 degC"], "fluid_swell": 0.0}})
    r = sealsim.oring_gland(case)
    assert r["squeeze_percent"]["nominal"] == pytest.approx(100 * 0.7 / 3.0, abs=PP)
    assert r["stretch_percent"]["nominal"] == pytest.approx(0.0, abs=1e-9)
    assert r["gland_fill_percent"]["nominal"] == pytest.approx(76.83, abs=PP)


def test_a_flange_separation_deepens_the_face_gland():
    # The same flange gland with the flanges 0.2 mm apart: the ring is squeezed between the
    # groove bottom and the cover flange, h = 2.3 + 0.2 = 2.5 mm (squeeze "is measured from
    # the bottom of the groove to the mating surface and includes the clearance gap", US Seal,
    # General design and gland dimensions).  By hand, no tolerances, at 20 degC:
    #   squeeze (3 - 2.5) / 3 = 16.67 %;  fill pi/4 * 3^2 / (2.5 * 4.0) = 7.0686 / 10 = 70.69 %
    # Before, the separation entered the extrusion gap only: 23.33 % and 76.83 %, as if the
    # flanges touched.
    exact = {"upper": "0 mm", "lower": "0 mm"}
    case = _case("face_static.toml", {
        "ring": {"cord_diameter": "3 mm", "inner_diameter": "30 mm", "cord_tolerance": "0 mm",
                 "inner_diameter_tolerance": "0 mm"},
        "housing": {"groove_depth": {"nominal": "2.3 mm", **exact},
                    "groove_width": {"nominal": "4 mm", **exact},
                    "groove_inner_diameter": {"nominal": "30 mm", **exact},
                    "gap": {"nominal": "0.2 mm", **exact}},
        "service": {"temperature": ["20 degC"], "fluid_swell": 0.0}})
    r = sealsim.oring_gland(case)
    for bound in ("min", "nominal", "max"):
        assert r["squeeze_percent"][bound] == pytest.approx(100 * 0.5 / 3.0, abs=PP)
        assert r["gland_fill_percent"][bound] == pytest.approx(70.69, abs=PP)
    assert r["extrusion_gap_mm"]["max"] == pytest.approx(0.4, abs=1e-9)   # diametral: 2 x 0.2


def test_rod_gland_with_thermal_contraction_by_hand():
    # rod_reciprocating.toml at its lowest temperature, 0 degC (20 K below assembly):
    #   rubber 1 + 1.9e-4 * (-20) = 0.9962; steel 1 - 11.5e-6 * 20 = 0.99977
    #   d2 min = (3.55 - 0.05) * 0.9962 = 3.48670; d1 min = (19.8 - 0.26349) * 0.9962 = 19.46227
    #   rod 20 f7 (19.959 ... 19.980): smallest for the deepest gland: 19.959 * 0.99977
    #     = 19.95441; groove 26.1 H8 (+0.033): 26.133 * 0.99977 = 26.12699
    #   h = (26.12699 - 19.95441) / 2 = 3.08629
    #   stretched onto the rod: (19.95441 + x) x^2 = (19.46227 + 3.48670) * 3.48670^2
    #     -> x = 3.45243;  squeeze = (3.45243 - 3.08629) / 3.45243 = 10.605 %
    r = sealsim.oring_gland(EXAMPLES / "rod_reciprocating.toml")
    cold = next(s for s in r["by_temperature"]
                if s["temperature_C"] == pytest.approx(0.0) and s["fluid_swell"] == 0.0)
    assert cold["squeeze_percent"]["min"] == pytest.approx(10.605, abs=PP)
    assert r["squeeze_percent"]["min"] == pytest.approx(10.605, abs=PP)  # the cold end rules
    assert r["ok"], r["notes"]


def test_installed_cord_keeps_the_volume_of_the_torus():
    d2, d1 = 3.53e-3, 20.0e-3
    for inner, outer in ((21.5e-3, None), (None, 26.0e-3)):
        x = float(installed_cord(d2, d1, seat_inner=inner, seat_outer=outer))
        centre = inner + x if inner is not None else outer - x
        assert centre * x**2 == pytest.approx((d1 + d2) * d2**2, rel=1e-9)
    assert float(installed_cord(d2, d1, seat_inner=19e-3)) == d2  # loose: unchanged


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.name)
def test_worst_case_equals_brute_force_over_the_tolerance_corners(path):
    case = validate_case(GlandCase, load_toml(path), path.name)
    geometry, _, _ = geometry_of(case)
    service = case.service
    for t in sorted({service.assembly_temperature, *service.temperature}):
        for swell in sorted({0.0, service.fluid_swell}):
            stack = worst_case(geometry, t, swell)
            corners = corner_values(geometry, t, swell)
            for q in ("squeeze", "stretch", "fill", "gap"):
                assert stack[q]["min"] == pytest.approx(corners[q].min(), rel=1e-12, abs=1e-15)
                assert stack[q]["max"] == pytest.approx(corners[q].max(), rel=1e-12, abs=1e-15)


@settings(max_examples=40, deadline=None)
@given(groove=st.floats(19.3, 19.8), d1=st.floats(18.5, 19.6), cord_tol=st.floats(0.0, 0.15),
       t_low=st.floats(-40.0, 20.0), swell=st.floats(0.0, 0.2))
def test_worst_case_holds_for_any_piston_gland_and_no_inner_point_exceeds_it(groove, d1,
                                                                             cord_tol, t_low,
                                                                             swell):
    case = _case("piston_static.toml", {
        "ring": {"inner_diameter": f"{d1} mm", "cord_tolerance": f"{cord_tol} mm"},
        "housing": {"groove_diameter": {"nominal": f"{groove} mm", "fit": "h9"}},
        "service": {"temperature": [f"{t_low} degC", "100 degC"], "fluid_swell": swell}})
    geometry, _, _ = geometry_of(case)
    t = t_low + 273.15
    stack = worst_case(geometry, t, swell)
    corners = corner_values(geometry, t, swell)
    rng = np.random.default_rng(0)
    inner = {k: rng.uniform(lo, hi, 500) for k, (lo, _, hi) in geometry.limits.items()}
    inside = geometry.state(inner, t, swell)
    for q in ("squeeze", "stretch", "fill", "gap"):
        assert stack[q]["min"] == pytest.approx(corners[q].min(), rel=1e-12, abs=1e-15)
        assert stack[q]["max"] == pytest.approx(corners[q].max(), rel=1e-12, abs=1e-15)
        assert inside[q].min() >= stack[q]["min"] - 1e-12
        assert inside[q].max() <= stack[q]["max"] + 1e-12


def test_iso286_tables_follow_the_standards_formulas():
    # ISO 286-1: IT = k * i with i = 0.45 D^(1/3) + 0.001 D [um], D the geometric mean of the
    # size step; fundamental deviations d, e, f, g: -16 D^0.44, -11 D^0.41, -5.5 D^0.41,
    # -2.5 D^0.34.  The tables are these values rounded by the standard's rules (within 1 um
    # or 5 %); the first step (up to 3 mm) is set apart in the standard and not compared.
    lower = [1, *SIZE_STEPS_MM[:-1]]
    factor = {5: 7, 6: 10, 7: 16, 8: 25, 9: 40, 10: 64, 11: 100}
    formula = {"d": (16.0, 0.44), "e": (11.0, 0.41), "f": (5.5, 0.41), "g": (2.5, 0.34)}
    for k in range(1, len(SIZE_STEPS_MM)):
        mean = math.sqrt(lower[k] * SIZE_STEPS_MM[k])
        unit = 0.45 * mean ** (1 / 3) + 0.001 * mean
        for grade, row in IT_GRADES_UM.items():
            assert abs(row[k] - factor[grade] * unit) <= max(1.0, 0.05 * row[k]), (grade, k)
        for letter, (a, b) in formula.items():
            table = FUNDAMENTAL_DEVIATIONS_UM[letter][k]
            assert abs(table + a * mean**b) <= max(1.0, 0.05 * abs(table)), (letter, k)


def test_fits_and_ring_tolerances():
    assert [round(x * 1e6) for x in iso286_deviations(0.025, "H8")] == [0, 33]
    assert [round(x * 1e6) for x in iso286_deviations(0.020, "f7")] == [-41, -20]
    assert [round(x * 1e6) for x in iso286_deviations(0.020, "G7")] == [7, 28]
    assert [round(x * 1e6, 1) for x in iso286_deviations(0.050, "JS9")] == [-31.0, 31.0]
    # the seal maker's tabulation of ISO 3601-1 (R.T. Dygert): 20 mm +-0.26, 80 mm +-0.69
    assert iso3601_inner_diameter_tolerance(0.020) * 1e3 == pytest.approx(0.26, abs=0.005)
    assert iso3601_inner_diameter_tolerance(0.080) * 1e3 == pytest.approx(0.69, abs=0.005)
    for bad in ("X7", "H", "h14", "k6"):
        with pytest.raises(InputError, match="fit"):
            iso286_deviations(0.02, bad)
    with pytest.raises(InputError, match="500 mm"):
        iso286_deviations(0.6, "H8")


def test_extrusion_limit_follows_the_published_table():
    inch = 0.0254
    assert float(extrusion_gap_limit(30e5, 70)) == pytest.approx(0.016 * inch)   # < 500 psi
    assert float(extrusion_gap_limit(30e5, 90)) == pytest.approx(0.028 * inch)
    assert float(extrusion_gap_limit(200e5, 80)) == pytest.approx(0.006 * inch)  # 2900 psi
    assert float(extrusion_gap_limit(250e5, 90)) == 0.0                          # > 3000 psi
    p = np.linspace(0, 200e5, 50)
    assert np.all(np.diff(extrusion_gap_limit(p, 75)) <= 0)                      # monotone


def test_limits_given_in_other_units_are_inside_their_rows_and_ranges():
    # "1500 psi" converts to a last bit above 1500 * 6894.757 Pa and "212 degF" above
    # 373.15 K: a limit of the table or of the service range must still count as inside
    # (before: the 1500-2000 psi row, 0.004 in, was used, and both notes were given)
    inch = 0.0254
    p = parse_quantity("1500 psi", "pressure")
    assert float(extrusion_gap_limit(p, 70)) == pytest.approx(0.006 * inch)   # <= 1500 psi
    assert float(extrusion_gap_limit(p * 1.001, 70)) == pytest.approx(0.004 * inch)
    r = sealsim.oring_gland(_case("piston_static.toml", {"service": {
        "pressure": "1500 psi", "temperature": ["-40 degF", "212 degF"]}}))
    check = next(c for c in r["checks"] if c["name"] == "extrusion_gap")
    # NBR 75 Shore A: between 0.006 (70) and 0.020 in (90) at a quarter
    assert check["limit"] == pytest.approx((0.006 + 0.25 * 0.014) * inch * 1e3)
    assert not any("back-up" in n or "service range" in n for n in r["notes"]), r["notes"]
    r = sealsim.oring_gland(_case("piston_static.toml", {"service": {
        "pressure": "1501 psi", "temperature": ["-41 degF", "213 degF"]}}))
    assert any("above 103.4 bar" in n for n in r["notes"])
    assert any("service range" in n for n in r["notes"])


def test_the_failing_example_names_its_failed_check_and_why():
    r = sealsim.oring_gland(EXAMPLES / "rod_extrusion_fails.toml")
    assert not r["ok"] and r["failed"] == ["extrusion_gap"]
    check = next(c for c in r["checks"] if c["name"] == "extrusion_gap")
    assert check["value"] > check["limit"] and "Parker" in check["source"]
    assert any(n.startswith("extrusion_gap fails") for n in r["notes"])
    for c in r["checks"]:
        assert set(c) >= {"name", "value", "limit", "ok", "source"} and c["source"]


def test_a_piston_ring_larger_than_its_groove_fails_the_stretch_check():
    # ring 30 x 3.55 on a 19.5 mm groove in a 25 mm bore: it is compressed 36 % around its
    # circumference and cannot be installed -- before, every check passed ("stretch_max
    # -33.8 <= 5").  Apple Rubber: the ID must be smaller than the piston groove diameter.
    r = sealsim.oring_gland(_case("piston_static.toml", {"ring": {"inner_diameter": "30 mm"}}))
    check = next(c for c in r["checks"] if c["name"] == "stretch_min")
    assert not check["ok"] and r["failed"] == ["stretch_min"]
    # by hand at 20 degC: smallest groove 19.448 mm, largest ring ID 30 + 0.338 mm
    assert check["value"] == pytest.approx((19.448 - 30.338) / 30.338 * 100, abs=PP)
    assert check["limit"] == 0.0 and "Apple Rubber" in check["source"]
    # the example's ring (stretch 0.99 ... 4.0 % at assembly) passes; it loosens to -0.43 %
    # at 100 degC in service, which the check leaves alone (at assembly only)
    ok = sealsim.oring_gland(EXAMPLES / "piston_static.toml")
    check = next(c for c in ok["checks"] if c["name"] == "stretch_min")
    assert ok["ok"] and check["value"] == pytest.approx((19.448 - 19.2576) / 19.2576 * 100,
                                                        abs=PP)
    assert ok["stretch_percent"]["min"] < 0.0
    # a floating ring on purpose: the case's own limit
    floating = sealsim.oring_gland(_case("piston_static.toml", {
        "ring": {"inner_diameter": "19.6 mm"}, "limits": {"stretch_min": -0.05}}))
    assert floating["ok"]
    # rod and face glands have no such check
    rod = sealsim.oring_gland(EXAMPLES / "rod_reciprocating.toml")
    assert "stretch_min" not in {c["name"] for c in rod["checks"]}


def test_a_clearance_closed_by_the_metals_expansion_fails():
    # an aluminium piston (23e-6 1/K) 25 g6 in the steel 25 H8 bore (11.5e-6 1/K) at 150 degC,
    # 130 K above assembly.  By hand: bore from 25.000 * (1 + 11.5e-6 * 130) = 25.03738 mm,
    # piston g6 (es -7 um, IT6 13 um) up to 24.993 * (1 + 23e-6 * 130) = 25.06773 mm:
    # clearance -0.03035 mm, the piston seizes.  Before, every check passed (the stack's gap
    # minimum, -0.0304 mm, was checked against nothing).
    r = sealsim.oring_gland(_case("piston_static.toml", {
        "housing": {"inner_expansion": "23e-6 1/K",
                    "piston_diameter": {"nominal": "25 mm", "fit": "g6"}},
        "service": {"temperature": ["-20 degC", "150 degC"]}}))
    check = next(c for c in r["checks"] if c["name"] == "clearance_min")
    assert r["failed"] == ["clearance_min"] and not check["ok"]
    assert check["value"] == pytest.approx(-0.03035, abs=2e-5) and check["unit"] == "mm"
    assert r["worst_case_corners"]["gap_min"]["temperature_C"] == pytest.approx(150.0)
    assert any(n.startswith("clearance_min fails: worst case -0.0304 mm") for n in r["notes"])
    # the example's steel piston keeps its H8/f7 clearance: 0.020 mm at assembly, shrunk with
    # the steel at -20 degC to 0.020 * (1 - 11.5e-6 * 40) = 0.019991 mm
    ok = sealsim.oring_gland(EXAMPLES / "piston_static.toml")
    check = next(c for c in ok["checks"] if c["name"] == "clearance_min")
    assert ok["ok"] and check["value"] == pytest.approx(0.020 * (1 - 11.5e-6 * 40), abs=1e-9)
    face = sealsim.oring_gland(EXAMPLES / "face_static.toml")
    assert "clearance_min" not in {c["name"] for c in face["checks"]}


def test_own_limits_replace_the_published_ones_and_say_so():
    r = sealsim.oring_gland(_case("xring_piston.toml", {"limits": {"squeeze_min": 0.01}}))
    check = next(c for c in r["checks"] if c["name"] == "squeeze_min")
    assert check["ok"] and check["limit"] == pytest.approx(1.0) and "your limit" in check["source"]


def test_fractions_are_read_as_engineers_write_them(tmp_path):
    # swell and own limits in percent ("5 %") as well as fractions (0.05); before, "5 %" was
    # refused ("unable to parse string as a number"); a plain 5 is still refused, naming both
    as_percent = sealsim.oring_gland(_case("piston_static.toml", {
        "service": {"fluid_swell": "5 %"}, "limits": {"squeeze_min": "18 %"}}))
    as_fraction = sealsim.oring_gland(_case("piston_static.toml", {
        "service": {"fluid_swell": 0.05}, "limits": {"squeeze_min": 0.18}}))
    assert as_percent["squeeze_percent"] == as_fraction["squeeze_percent"]
    assert as_percent["checks"] == as_fraction["checks"]
    check = next(c for c in as_percent["checks"] if c["name"] == "squeeze_min")
    assert check["limit"] == pytest.approx(18.0) and not check["ok"]      # 17.0 % < 18 %
    with pytest.raises(InputError, match=r"service\.fluid_swell: 5 is out of range.*'5 %'"):
        _case("piston_static.toml", {"service": {"fluid_swell": 5}})
    # the resolved case reads back
    out = tmp_path / "g"
    result = CliRunner().invoke(app, ["gland", "check", str(EXAMPLES / "face_static.toml"),
                                      "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    again = sealsim.oring_gland(out / "case_resolved.toml")
    assert again["gland_fill_percent"] == pytest.approx(
        sealsim.oring_gland(EXAMPLES / "face_static.toml")["gland_fill_percent"])


def test_bad_gland_cases_are_refused_naming_the_field():
    data = load_toml(EXAMPLES / "piston_static.toml")
    del data["housing"]["piston_diameter"]
    with pytest.raises(InputError, match="piston_diameter"):
        sealsim.oring_gland(data)
    with pytest.raises(InputError, match="fit"):
        sealsim.oring_gland(_case("piston_static.toml", {
            "housing": {"bore": {"nominal": "25 mm", "fit": "Q8"}}}))
    with pytest.raises(InputError, match="face gland is static"):
        _case("face_static.toml", {"housing": {"motion": "reciprocating"}})
    with pytest.raises(InputError, match=r"\[fe\]"):
        sealsim.oring_gland(EXAMPLES / "piston_static.toml", fe=True)


def test_glands_whose_parts_do_not_go_together_are_refused():
    # before, a piston 25.2 f7 (up to 25.18 mm) in a 25 H8 bore passed every check with an
    # extrusion gap of -0.153 ... -0.126 mm, and a groove bottom of 26 mm in that bore gave a
    # squeeze of 115 % and a gland fill of -325 %
    cases = (
        ("piston_static.toml", {"piston_diameter": {"nominal": "25.2 mm", "fit": "f7"}},
         r"housing\.piston_diameter: up to 25\.18 mm does not fit the bore from 25 mm"),
        ("piston_static.toml", {"groove_diameter": {"nominal": "26 mm", "fit": "h9"}},
         r"housing\.groove_diameter: up to 26 mm is not below the piston diameter"),
        ("rod_reciprocating.toml", {"bore": {"nominal": "19.5 mm", "fit": "H8"}},
         r"housing\.rod: up to 19\.98 mm does not fit the bore from 19\.5 mm"),
        ("rod_reciprocating.toml", {"groove_diameter": {"nominal": "19 mm", "fit": "H8"}},
         r"housing\.groove_diameter: from 19 mm is not above the rod bore"),
        ("piston_static.toml", {"groove_width": {"nominal": "0 mm", "upper": "0 mm",
                                                 "lower": "0 mm"}},
         r"housing\.groove_width: from 0 mm; it must be > 0 mm"),
        ("face_static.toml", {"gap": {"nominal": "0 mm", "upper": "0.02 mm",
                                      "lower": "-0.01 mm"}},
         r"housing\.gap: from -0\.01 mm"),
    )
    for name, housing, message in cases:
        with pytest.raises(InputError, match=message):
            _case(name, {"housing": housing})
    # a line-to-line fit (zero clearance at a limit) is allowed
    _case("piston_static.toml", {"housing": {"piston_diameter": {"nominal": "25 mm",
                                                                 "fit": "h7"}}})


def test_cli_writes_the_result_folder(tmp_path):
    out = tmp_path / "gland"
    result = CliRunner().invoke(app, ["gland", "check", str(EXAMPLES / "rod_extrusion_fails.toml"),
                                      "--out", str(out), "-q"])
    # a failing gland is written and named, and exits with 1 (before: 0, so `sealsim gland
    # check g.toml && next-step` went on with a gland that fails); a passing one with 0
    assert result.exit_code == 1, result.output
    assert "FAILED: extrusion_gap" in " ".join(result.output.split())
    report = json.loads((out / "report.json").read_text())
    assert report["failed"] == ["extrusion_gap"]
    for key in ("squeeze_percent", "stretch_percent", "gland_fill_percent"):
        assert set(report[key]) == {"min", "nominal", "max"}
    assert {"checks.csv", "stack.csv", "section.png", "case_resolved.toml"} <= {
        p.name for p in out.iterdir()}
    # the resolved case reads back to the same report
    again = sealsim.oring_gland(out / "case_resolved.toml")
    assert again["squeeze_percent"] == pytest.approx(report["squeeze_percent"])
    second = CliRunner().invoke(app, ["gland", "check", str(EXAMPLES / "face_static.toml"),
                                      "--out", str(out), "-q"])
    assert second.exit_code == 2 and "--force" in second.output
    passing = CliRunner().invoke(app, ["gland", "check", str(EXAMPLES / "face_static.toml"),
                                       "--out", str(tmp_path / "face"), "-q"])
    assert passing.exit_code == 0 and "all checks pass" in passing.output, passing.output


def test_fe_at_nominal_is_the_structure_model_of_the_nominal_gland(tmp_path, monkeypatch):
    # one coarse FE load path (about 15 s); the map is cached in tmp_path
    monkeypatch.setenv("SEALSIM_CACHE", str(tmp_path))
    r = sealsim.oring_gland(EXAMPLES / "rod_reciprocating.toml", fe=True)
    fe = r["fe"]
    structure = fe["structure_case"]
    # the FE gland is the nominal gland: its depth d2'(1 - s) is the nominal gland depth
    # (26.1165 H8 middle - 19.9695 f7 middle) / 2 = 3.0735 mm
    cord = float(structure["seal"]["cord_diameter"].split()[0])
    assert cord * (1 - structure["load"]["squeeze"][0]) == pytest.approx(3.0735, abs=1e-4)
    assert fe["squeeze_percent"] == pytest.approx(r["squeeze_percent"]["nominal"], abs=1e-6)
    rest, loaded = fe["normal_force_N"]["unpressurised"], fe["normal_force_N"]["at_pressure"]
    # pressure energises the ring: F_N(100 bar) > F_N(0) + a share of p·b·π·d
    b = fe["contact_width_mm"]["unpressurised"] * 1e-3
    assert loaded > rest + 0.5 * 100e5 * b * math.pi * 0.02
    # Lindley's empirical law for the same cord and squeeze (the analytic estimate) is within
    # a factor 2: it is a free-compression fit, the FE has the groove, friction and the rod
    analytic = sealsim.seal_friction({"cord_diameter": f"{cord} mm",
                                      "squeeze": structure["load"]["squeeze"][0]},
                                     "0.1 m/s", "0 bar", "20 degC",
                                     diameter=structure["gland"]["sealing_diameter"])
    assert 0.5 < rest / analytic["normal_force_N"] < 2.0
    # both strokes (the gland check reported the outstroke only: 8.9 N at 100 bar, μ = 0.005,
    # where the instroke gives 187 N): unpressurised the two are alike (within 10 %: the FE
    # profile's flanks differ a little), at 100 bar the instroke's film enters where the
    # contact pressure drops from 10 MPa to 0 -- a steep inlet, a thin film, more friction
    out, in_ = fe["friction_N"]["outstroke"], fe["friction_N"]["instroke"]
    assert in_["unpressurised"] == pytest.approx(out["unpressurised"], rel=0.10)
    assert in_["at_pressure"] > 5.0 * out["at_pressure"] > 0.0
    assert out["at_pressure"] > out["unpressurised"] > 0.0


def test_cli_help_and_notes_keep_their_table_names(monkeypatch, tmp_path):
    # rich reads "[fe]" as a markup tag and dropped it: the help said "the case's  table";
    # library notes naming a table ("[fe]") are printed as written
    import sealsim.runs.gland as gland_runs

    help_text = CliRunner().invoke(app, ["gland", "check", "--help"]).output
    assert "[fe] table" in " ".join(help_text.split())
    real = gland_runs.check_case_file

    def with_note(*args, **kwargs):
        report = real(*args, **kwargs)
        report["notes"].append("set [fe] pressure to check it")
        return report
    monkeypatch.setattr(gland_runs, "check_case_file", with_note)
    result = CliRunner().invoke(app, ["gland", "check", str(EXAMPLES / "face_static.toml"),
                                      "--out", str(tmp_path / "g"), "-q"])
    assert result.exit_code == 0, result.output
    assert "set [fe] pressure" in " ".join(result.output.split()), result.output
