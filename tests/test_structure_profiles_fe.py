"""FE of seal profiles: X-ring against O-ring, U-cup activation, the DIN 3760 lip force from
FE in the rotary model, an X-ring map in a pneumatic run, the profile examples through the
CLI (coarse meshes, short load paths)."""

import json
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import tomli_w
from typer.testing import CliRunner

from session_builds import built, session_build

from sealsim.cases import apply_overrides, validate_case
from sealsim.cli.structure import structure_app
from sealsim.structure.case import StructureCase
from sealsim.structure.run import run_case

ROOT = Path(__file__).resolve().parents[1]
RUNNER = CliRunner()


def case(data):
    return validate_case(StructureCase, data)


def quiet_run(c):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return run_case(c).states


def test_xring_against_oring_of_the_same_size():
    """X-ring and O-ring 20 x 4 in the same gland at 10 % squeeze, 0 and 2 bar.

    References: the X-ring touches each surface with two lobes (its purpose); photoelastic
    measurements of X-rings at 20 % squeeze found considerably higher contact stresses than
    for O-rings (Contact behavior analysis of X-ring under internal pressure and uniform
    squeeze rate using photoelastic experimental hybrid method, J. Mech. Sci. Technol.);
    catalogues attribute the lower friction to the smaller contact area. The FE agrees on all
    three at low pressure. At the same squeeze its F_N is higher than the O-ring's: the
    Quad-Ring section holds 4.6 % more rubber (0.8215 W² against 0.785 W², profiles.py) and
    each lobe is squeezed like a small O-ring. The lower force of X-rings in service comes
    with their own glands, which are deeper than O-ring glands (Parker O-Ring & Engineered
    Seals Division, Seal Solutions Guide, "X-rings": "the groove is designed deeper than an
    O-ring groove"), i.e. with less squeeze, not with a softer section
    (test_xring_in_its_own_gland_needs_less_force; docs/guide/seal_profiles.md discusses it).
    """
    base = {"gland": {"sealing_diameter": "20 mm", "groove_width": "5.4 mm"},
            "mesh": {"level": "coarse"},
            "load": {"squeeze": [0.10], "squeeze_increments": 3,
                     "pressure": ["0 bar", "2 bar"], "pressure_increments": 1}}
    out = {}
    for kind in ("oring", "xring"):
        out[kind] = quiet_run(case({**base, "seal": {"type": kind, "cord_diameter": "4 mm",
                                                     "inner_diameter": "20 mm"}}))
    o, x = out["oring"][1], out["xring"][1]  # installed, 0 bar
    assert x.surfaces["sealing_surface"].zones == 2 and o.surfaces["sealing_surface"].zones == 1
    assert x.b < 0.9 * o.b
    assert x.p_max > 1.2 * o.p_max
    assert x.F_N > o.F_N  # more rubber in the envelope at the same squeeze, see the docstring
    for states in out.values():  # both seal: contact pressure above the fluid pressure
        assert states[-1].p_max > states[-1].pressure


def test_xring_force_follows_its_rubber_volume():
    """The same comparison with an X-ring section of the O-ring's area (valley depth 0.125 W:
    0.784 W² against 0.785 W²): the force at equal squeeze is then the O-ring's, slightly lower,
    and it rises less with pressure.  So the extra force of the default section at equal
    squeeze is its extra rubber (the Quad-Ring area), not the four-lobe shape."""
    base = {"gland": {"sealing_diameter": "20 mm", "groove_width": "5.4 mm"},
            "mesh": {"level": "coarse"},
            "load": {"squeeze": [0.10], "squeeze_increments": 3,
                     "pressure": ["0 bar", "2 bar"], "pressure_increments": 1}}
    ring = {"cord_diameter": "4 mm", "inner_diameter": "20 mm"}
    o = quiet_run(case({**base, "seal": {"type": "oring", **ring}}))
    x = quiet_run(case({**base, "seal": {"type": "xring", "valley_depth": 0.125, **ring}}))
    # equal volume, equal force within 3 % (coarse mesh -0.2 %, medium -0.9 %); not above it
    assert 0.97 * o[1].F_N < x[1].F_N <= o[1].F_N
    assert x[2].F_N - x[1].F_N < o[2].F_N - o[1].F_N      # smaller rise with pressure
    assert x[1].surfaces["sealing_surface"].zones == 2 and x[1].b < o[1].b


def test_xring_in_its_own_gland_needs_less_force():
    """X-ring and O-ring of 3.53 mm cord on a 20 mm rod, each at the squeeze of its
    dynamic gland: Quad-Ring 7.9 % (gland depth 3.25 mm, Minnesota Rubber Quad-Ring Brand
    Design Guide, groove table for static and non-rotary dynamic seals, series Q4201), O-ring
    12.9 % (3.07 mm, AS568 dynamic gland, e.g. Daemar's groove design table).

    Reference: X-rings seal with less squeeze in their deeper glands and so with less force
    and friction (Parker Seal Solutions Guide, "X-rings"; "less squeeze is required to
    maintain an effective seal, thus causing less friction", Fridle, X-rings).  The FE gives
    about 40 % less F_N at 0 bar (medium mesh: 48 N against 81 N) and 25 % less at 10 bar,
    with two lobes and a shorter contact width.  Asserted: lower F_N at both pressures by
    more than 15 % (the smallest squeeze difference of the tables' sizes, 13 % against 9 %
    for 2.62 mm, would still give a clear difference), lower b, two zones."""
    ring = {"cord_diameter": "3.53 mm", "inner_diameter": "20 mm"}
    runs = {}
    for kind, squeeze in (("oring", 0.129), ("xring", 0.079)):
        runs[kind] = quiet_run(case({
            "gland": {"sealing_diameter": "20 mm", "groove_width": "4.7 mm"},
            "mesh": {"level": "coarse"}, "seal": {"type": kind, **ring},
            "load": {"squeeze": [squeeze], "squeeze_increments": 3,
                     "pressure": ["0 bar", "10 bar"], "pressure_increments": 2}}))[1:]
    for o, x in zip(runs["oring"], runs["xring"]):
        assert x.F_N < 0.85 * o.F_N
        assert x.b < o.b
        assert x.surfaces["sealing_surface"].zones == 2


def test_ucup_is_pressure_activated():
    """U-cup rod seal 20 mm: the pressure fills the groove between the lips and presses the
    dynamic lip on the rod. Reference: a pressure-energised lip seals when its peak contact
    pressure exceeds the fluid pressure (Müller & Nau, Fluid Sealing Technology, 1998,
    ch. 'lip seals'); F_N then grows with p at least by p times the projected lip length."""
    c = case(apply_overrides(tomllib.loads((ROOT / "examples/structure/ucup_rod.toml")
                                           .read_text()),
                             {"mesh": {"level": "coarse"},
                              "load": {"squeeze_increments": 3,
                                       "pressure": ["0 bar", "4 bar", "8 bar"]}}))
    states = quiet_run(c)[1:]
    for s in states[1:]:
        assert s.p_max > s.pressure
    dfdp = (states[-1].F_N - states[0].F_N) / (states[-1].pressure - states[0].pressure)
    # the lip (about 2.5 mm of the 5 mm seal) is pressed by p over its length on the 20 mm rod
    assert dfdp > np.pi * 20e-3 * 1.0e-3


@session_build("lip_fe", cost=30)
def build_lip_fe(folder):
    """The shortened FE speed-cycle example (lip table at 20 and 100 °C, coarse mesh) and the
    cache folder in which its FE lip table was built."""
    from sealsim.rotary.lip_fe import lip_force_table
    from sealsim.rotary.simulation import load_rotary_case

    cache = folder / "cache"
    example = ROOT / "examples/rotary/speed_cycle_fe.toml"
    data = tomllib.loads(example.read_text())
    lip = {"temperatures": ["20 degC", "100 degC"], "mesh": "coarse"}
    data = apply_overrides(data, {"lip": lip, "duty": {"steps": [
        {"speed": "100 rpm", "duration": "1 min"}, {"speed": "1000 rpm", "duration": "2 min"}]}})
    path = folder / "speed_cycle_fe.toml"
    path.write_text(tomli_w.dumps(data))
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("SEALSIM_CACHE", str(cache))
        fe = load_rotary_case(path)["fe"]
        lip_force_table(fe.seal, fe.lip, fe.seal.mounting_temperature)
    return {"case": path, "cache": cache}


@pytest.fixture(scope="module")
def lip_fe(tmp_path_factory, worker_id):
    """The example of build_lip_fe, its FE lip table (read from the cache the build filled:
    the FE ran once per session) and that cache folder."""
    from sealsim.rotary.lip_fe import lip_force_table
    from sealsim.rotary.simulation import load_rotary_case

    lip_case = built(tmp_path_factory, worker_id, "lip_fe")
    path, cache = Path(lip_case["case"]), Path(lip_case["cache"])
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("SEALSIM_CACHE", str(cache))
        cases = load_rotary_case(path)
        seal = cases["fe"].seal
        table = lip_force_table(seal, cases["fe"].lip, seal.mounting_temperature)
    return path, cases, table, cache


def test_lip_force_from_fe_and_the_speed_cycle(lip_fe, monkeypatch):
    """DIN 3760 80 x 101 x 9 NBR lip on an 80 mm shaft at 20 and 100 °C (coarse mesh), mounted
    at 20 °C, held an hour, warmed at 1 K/min (thermo-viscoelastic catalogue NBR).

    References: the garter spring's radial force is 2π T (thin ring) and hardly changes; the
    lip force falls as the rubber softens and the warm ring expands off the shaft. The contact
    band of the new lip is checked against the band the rotary model documents. Then the speed
    cycle example runs with lip.force = "fe" (shortened), the contact width from the FE too.
    (What the rubber carries: test_fe_lip_rubber_share, test_fe_lip_force_is_affine_in_the_
    rubber_modulus.)"""
    from sealsim.rotary.lip_fe import LipSpec

    path, cases, table, cache = lip_fe
    monkeypatch.setenv("SEALSIM_CACHE", str(cache))
    t = table.frame()
    assert np.all(np.diff(t["F_tip_N"]) < 0)  # the lip force falls with temperature
    # the lip without its spring (the rubber's force) falls too; the spring carries a growing
    # share; the steel spring's force hardly changes
    assert np.all(np.diff(t["F_without_spring_N"]) < 0)
    assert np.all(np.diff(t["spring_share"]) > 0)
    assert t["F_spring_N"].max() / t["F_spring_N"].min() < 1.05
    assert isinstance(cases["fe"].lip, LipSpec) and cases["constant"].lip.force == "constant"
    # the FE width goes with the FE force unless the case asks for the constant one
    assert cases["fe"].lip.contact_width == "fe"
    assert cases["constant"].lip.contact_width == "constant"
    assert LipSpec(force="fe", contact_width="constant").contact_width == "constant"
    # New lips touch over 0.1-0.2 mm (rotary/lip.py default_contact_width); the sharp edge
    # must give a band of that order, not a face lying on the shaft (the earlier 2 mm).
    assert 0.08 < t["contact_width_mm"].iloc[0] < 0.3

    from sealsim.cli import app

    out = path.parent / "out"
    result = RUNNER.invoke(app, ["rotary", "run", str(path), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    assert (out / "lip_fe.csv").is_file() and (out / "lip_fe.png").is_file()
    # the run writes the table its simulation used
    written = pd.read_csv(out / "lip_fe.csv")
    assert np.allclose(written["F_tip_N"], t["F_tip_N"], rtol=1e-5)
    ts = pd.read_csv(out / "timeseries.csv")
    fe = ts[ts["variant"] == "fe"]
    # each row holds the friction (here its FE lip force) at the contact temperature at the end
    # of its step (rotary/simulation.py); the table is interpolated, the run's force too
    expected = table.force_at(fe["T_contact_C"].to_numpy() + 273.15)
    assert np.allclose(fe["lip_force_N"].to_numpy(), expected, rtol=2e-3)


def test_fe_lip_rubber_share(lip_fe):
    """The rubber of the new lip, mounted at 20 °C and held an hour, carries a positive share
    of its force, F_without/F (the lip on the same path without its spring, as a split-shaft
    measurement with and without the spring gives it), of roughly half: 30-60 % (the handbook
    figure for new DIN 3760 lips; no primary source found, rotary/case.py spring_share). Its
    force falls from 20 to 100 °C faster than the held modulus E_h, because the warm ring also
    expands off the shaft. The garter spring's own radial force 2πT does not all reach the
    shaft (0 < α < 1): its seat lies behind the contact edge, and the flex takes part of it
    to the case (rotary/lip_fe.py)."""
    from sealsim.properties.elastomers import get_elastomer

    t = lip_fe[2].frame()
    rubber = t["F_without_spring_N"] / t["F_tip_N"]
    assert np.all(rubber > 0)
    assert 0.3 < rubber.iloc[0] < 0.6
    e = get_elastomer("NBR")
    e_ratio = e.held_modulus(373.15) / e.held_modulus(293.15)
    assert t["F_without_spring_N"].iloc[-1] / t["F_without_spring_N"].iloc[0] < e_ratio
    alpha = (t["F_tip_N"] - t["F_without_spring_N"]) / t["F_spring_N"]
    assert np.all((alpha > 0.5) & (alpha < 0.9))


def test_fe_lip_force_is_affine_in_the_rubber_modulus():
    """The 80 mm lip (coarse mesh, 20 °C, hyperelastic catalogue NBR constants scaled by 1 and
    0.5) with and without its spring. References: a body whose supports are given
    displacements carries a force ∝ its modulus (the hyperelastic stress scales with c10, c01;
    the bulk modulus is kept, so to within the small volume change); and the share of an
    applied force (the spring's) that goes to each support of an elastic body does not depend
    on its modulus. So F = α·2πT + F_without(E): the spring's contribution to the contact,
    F − F_without, is the same at both moduli, and a fraction α < 1 of the spring's own force
    (its seat is behind the contact edge). The former measure of the rubber's share, F − 2πT,
    falls far faster than the modulus and goes to zero near half the constants, which looked
    like a defect of the lip model at the held modulus (0.51 of the constants)."""
    from sealsim.properties.elastomers import get_elastomer

    c10, c01, bulk = get_elastomer("NBR").mooney_rivlin(293.15)
    force = {}
    for scale in (1.0, 0.5):
        for spring in (True, False):
            seal = {"type": "radial_lip", "outer_diameter": "101 mm", "width": "9 mm"}
            if not spring:
                seal.update(spring_rate="0 N/m", spring_tension="0 N")
            s = quiet_run(case({
                "seal": seal, "gland": {"arrangement": "shaft", "sealing_diameter": "80 mm"},
                "material": {"c10": f"{c10 * scale} Pa", "c01": f"{c01 * scale} Pa",
                             "bulk_modulus": f"{bulk} Pa", "temperature_scaling": "none"},
                "mesh": {"level": "coarse"}, "load": {"squeeze_increments": 8}}))[-1]
            force[scale, spring] = (s.F_N, s.spring_force)
    bare = {k: force[k, False][0] for k in (1.0, 0.5)}
    from_spring = {k: force[k, True][0] - bare[k] for k in (1.0, 0.5)}
    # 2 %: the bulk modulus is not scaled, and the spring's seat moves 0.03 mm less on the
    # softer lip (2πT 23.35 vs 23.08 N)
    assert bare[0.5] / bare[1.0] == pytest.approx(0.5, rel=0.02)
    assert from_spring[0.5] / from_spring[1.0] == pytest.approx(1.0, rel=0.02)
    for k in (1.0, 0.5):
        alpha = from_spring[k] / force[k, True][1]
        assert 0.5 < alpha < 0.9
    # the rubber's share of the lip with its spring, both ways: F_without/F stays near half,
    # F - 2πT drops to a few per cent of F
    assert bare[0.5] / force[0.5, True][0] > 0.3
    share_old = {k: (force[k, True][0] - force[k, True][1]) / force[k, True][0]
                 for k in (1.0, 0.5)}
    assert share_old[0.5] < 0.1 < share_old[1.0]


@pytest.mark.xfail(strict=True, reason=(
    "the generic 80 mm lip held an hour (held modulus, 0.51 of the constants' 1 Hz level) "
    "presses with 23.4 N = 0.093 N/mm at 20 degC, 7 % below the 100-200 N/m design range "
    "(0.13 N/mm with the constants themselves): the moulded interference (1 mm) and spring "
    "pre-tension (34 N/m x d) are estimates, not tuned to a secondary design range"))
def test_fe_lip_load_per_length(lip_fe):
    """The lip presses 100-200 N/m at 20 °C: the only published range found for oil seals (a
    seal maker's technical article, secondary; rotary/lip.py DEFAULT_LOAD_PER_LENGTH), whose
    middle is the rotary model's constant. Band check, not a validation (generic section,
    moulded interference estimated)."""
    t = lip_fe[2].frame()
    assert 0.10 < t["F_tip_per_length_N_per_mm"].iloc[0] < 0.20


def test_radial_lip_contact_band():
    """DIN 3760 80 x 101 x 9 lip installed on its shaft (coarse mesh): one narrow contact band
    at the sharp edge with the pressure peak on the oil side.

    Reference: the oil-side cone is steeper than the air-side one (45° against 25°) and the
    spring sits on the air side of the edge, so the contact pressure rises steeply from the
    oil side and falls gently to the air side -- the asymmetry that pumps back (Kammüller,
    Zum Abdichtverhalten von Radial-Wellendichtringen, Diss. Stuttgart 1986; Salant, Proc.
    IMechE J 213 (1999) 189). New lips touch over 0.1-0.2 mm (rotary/lip.py)."""
    s = quiet_run(case({"seal": {"type": "radial_lip", "outer_diameter": "101 mm",
                                 "width": "9 mm"},
                        "gland": {"arrangement": "shaft", "sealing_diameter": "80 mm"},
                        "mesh": {"level": "coarse"}, "load": {"squeeze_increments": 8}}))[-1]
    surf = s.surfaces["sealing_surface"]
    assert surf.zones == 1
    assert 0.08e-3 < s.b < 0.3e-3
    z, p = surf.position, surf.pressure
    z_peak = z[np.argmax(p)]
    centroid = np.trapezoid(p * z, z) / np.trapezoid(p, z)
    # the peak lies in the oil-side third of the band, the load's centroid air-side of it
    assert z_peak < surf.edge_low + (surf.edge_high - surf.edge_low) / 3
    assert centroid > z_peak + 0.1 * s.b


def test_xring_map_feeds_a_pneumatic_run(tmp_path):
    """X-ring 12 x 2 rod seal: `sealsim structure map` (coarse, 2 x 2 grid) writes map.nc
    with F_N, b and the contact pressure profile; the Ø32 cylinder example runs with it as
    the rod seal's contact map."""
    from sealsim.cli.pneumatic import pneumatic_app
    from sealsim.structure import load_map

    structure = {
        "title": "X-ring 12 x 2 rod seal", "seal": {"type": "xring", "cord_diameter": "2 mm",
                                                    "inner_diameter": "12 mm"},
        "gland": {"sealing_diameter": "12 mm", "groove_width": "2.7 mm"},
        "mesh": {"level": "coarse"}, "load": {"squeeze": [0.10]},
        "map": {"pressure": ["0 bar", "8 bar"], "temperature": ["20 degC", "40 degC"],
                "squeeze_increments": 3, "temperature_increments": 1, "workers": 1}}
    (tmp_path / "xring.toml").write_text(tomli_w.dumps(structure))
    result = RUNNER.invoke(structure_app, ["map", str(tmp_path / "xring.toml"), "--out",
                                           str(tmp_path / "map"), "--quiet"])
    assert result.exit_code == 0, result.output
    ds = load_map(tmp_path / "map" / "map.nc").dataset
    assert ds["contact_pressure"].dims == ("squeeze", "temperature", "pressure", "position")
    assert (ds["contact_zones"].values >= 1).all()
    assert {"map.csv", "map_profiles.csv", "map_profiles.png"} <= \
        {p.name for p in (tmp_path / "map").iterdir()}
    # the profile integrates to the normal force: F_N = 2 pi R ∫ p dz (trapezoid on the
    # 41-point grid across the groove; 10 %: the grid is coarse against b of about 0.5 mm)
    z = ds["position"].values
    p = ds["contact_pressure"].isel(squeeze=0, temperature=0, pressure=-1).values
    fn = float(ds["F_N"].isel(squeeze=0, temperature=0, pressure=-1))
    assert 2 * np.pi * 6e-3 * np.trapezoid(p, z) == pytest.approx(fn, rel=0.1)

    data = tomllib.loads((ROOT / "examples/pneumatic/cylinder_32.toml").read_text())
    data["controller"]["duration"] = "0.5 s"
    for seal in data["seals"]:
        if seal["name"] == "rod":
            seal["map"] = {"file": str(tmp_path / "map" / "map.nc")}
    data.pop("variants", None)
    (tmp_path / "cyl.toml").write_text(tomli_w.dumps(data))
    result = RUNNER.invoke(pneumatic_app, ["run", str(tmp_path / "cyl.toml"), "--out",
                                           str(tmp_path / "cyl"), "--quiet"])
    assert result.exit_code == 0, result.output
    summary = json.loads((tmp_path / "cyl" / "summary.json").read_text())
    assert summary


def test_profile_examples_through_the_cli(tmp_path):
    """The U-cup and the user D-ring (custom Mooney–Rivlin rubber) examples, shortened: the
    result folder holds the per-increment log (Newton iterations, cutbacks) and the contact
    zones."""
    for name, overrides in (
            ("ucup_rod.toml", {"load": {"pressure": ["0 bar", "2 bar"],
                                        "pressure_increments": 1}}),
            ("user_profile.toml", {"load": {"squeeze": [0.10], "pressure": ["0 bar"]}})):
        data = apply_overrides(tomllib.loads((ROOT / "examples/structure" / name).read_text()),
                               {"mesh": {"level": "coarse"}, **overrides})
        path = tmp_path / name
        path.write_text(tomli_w.dumps(data))
        out = tmp_path / name.replace(".toml", "")
        result = RUNNER.invoke(structure_app, ["run", str(path), "--out", str(out), "--quiet"])
        assert result.exit_code == 0, result.output
        inc = pd.read_csv(out / "increments.csv")
        assert {"step", "step_name", "load_fraction", "newton_iterations",
                "cutbacks"} <= set(inc.columns)
        assert inc["newton_iterations"].min() >= 1
        summary = json.loads((out / "summary.json").read_text())
        assert summary["increments"] == len(inc)
        assert summary["cutbacks"] == int(inc["cutbacks"].sum())
        assert summary["max_equilibrium_error"] < 1e-6
        res = pd.read_csv(out / "result.csv")
        assert {"contact_zones", "b_span_mm", "F_friction_sealing_N"} <= set(res.columns)
