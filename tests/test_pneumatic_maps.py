"""Contact maps of the seals: the analytic O-ring estimate and the FE characteristic maps of the
structure package (read from map.nc, built on demand and cached)."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from sealsim.cases import apply_overrides, load_toml, validate_case
from sealsim.errors import InputError
from sealsim.pneumatic import PneumaticCase, simulate
from sealsim.pneumatic import contact_maps as cm
from sealsim.structure.analytic import hertz_line_contact

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pneumatic"

TINY_STRUCTURE_CASE = """
title = "tiny rod seal map for tests"
[seal]
cord_diameter = "2 mm"
inner_diameter = "12 mm"
[gland]
arrangement = "rod"
sealing_diameter = "12 mm"
groove_width = "2.7 mm"
[material]
elastomer = "NBR"
[mesh]
level = "coarse"
[load]
installation_temperature = "20 degC"
squeeze = [0.12]
[map]
pressure = ["0 bar", "8 bar"]
temperature = ["20 degC", "60 degC"]
squeeze_increments = 4
temperature_increments = 1
workers = 1
"""


def test_analytic_pieces_against_their_references():
    # Hertz line contact (Johnson 1985 §4.2) as implemented in sealsim.structure.analytic:
    # b = 2a, same numbers to round-off
    a, _ = hertz_line_contact(1200.0, 1e-3, 8e6)
    assert float(cm.hertz_contact_width(1200.0, 2e-3, 8e6)) == pytest.approx(2 * a, rel=1e-14)
    # Lindley (1967): F' = E·d·(1.25·c^1.5 + 50·c^6)
    assert float(cm.lindley_force_per_length(0.2, 2e-3, 8e6)) == pytest.approx(
        8e6 * 2e-3 * (1.25 * 0.2 ** 1.5 + 50 * 0.2 ** 6), rel=1e-14)
    # the energised force solves F' = F'_0 + Δp·b(F') (fixed point, to round-off)
    f0, dp = 900.0, np.array([0.0, 3e5, 1e6])
    f = cm.energised_force_per_length(f0, dp, 2e-3, 8e6)
    assert np.allclose(f, f0 + dp * cm.hertz_contact_width(f, 2e-3, 8e6), rtol=1e-12)
    # free thermal expansion: at ΔT = 0 the squeeze is c0; the cord grows by α·ΔT
    assert float(cm.thermal_squeeze(0.12, 1.9e-4, 293.15, 293.15)) == pytest.approx(0.12)
    c = float(cm.thermal_squeeze(0.12, 1.9e-4, 353.15, 293.15))
    assert (1 - 0.12) / (1 - c) == pytest.approx(1 + 1.9e-4 * 60, rel=1e-14)


def test_analytic_map_rises_with_pressure_and_temperature():
    # seed 001: pressure energises the seal; the contact force falls on cooling (Fig. 8) and
    # rises on heating through the cord's thermal expansion.  Issue 24: the held modulus (a
    # seal installed at 20 °C and held an hour) -- below the installation temperature the
    # installed stress stays relaxed, above it the modulus is nearly flat.  Smooth and monotone
    # in pressure over the whole grid, from T_g + 20 K (-5 °C for NBR) to 100 °C.
    from sealsim.properties.elastomers import get_elastomer

    m = cm.AnalyticContactMap(0.032, 2e-3, 0.10, 7.98e6, 1.9e-4, 293.15)
    assert m.ranges["temperature"][0] == pytest.approx(268.15)
    dp, temps = np.meshgrid(np.linspace(0.0, 10e5, 41), np.linspace(268.15, 373.15, 12),
                            indexing="ij")
    fn, b = (v.reshape(dp.shape) for v in m.evaluate(dp.ravel(), temps.ravel()))
    assert np.all(np.diff(fn, axis=0) > 0)
    assert np.all(np.diff(b, axis=0) > 0)
    assert np.all(fn[:, 0] < fn[:, 4]) and np.all(fn[:, -1] > fn[:, 4])  # -5 < 23 < 100 °C
    # at the installation temperature: Lindley with the held modulus of the catalogue NBR
    # (E0 = 6·(C10 + C01) is its 1 Hz modulus at 23 °C, the held one is 4.09 of 7.98 MPa)
    nbr = get_elastomer("NBR")
    held = 7.98e6 * nbr.held_modulus(293.15) / nbr.modulus(nbr.reference_temperature)
    fn0, b0 = m.evaluate(0.0, 293.15)
    assert fn0 == pytest.approx(math.pi * 0.032 * held * 2e-3 * (1.25 * 0.1 ** 1.5
                                                                 + 50 * 0.1 ** 6), rel=1e-12)
    assert 0.3e-3 < b0 < 1.0e-3
    # the fast path at a fixed temperature gives the same numbers
    assert m.loads_function(320.0)(4e5) == pytest.approx(m.evaluate(4e5, 320.0), rel=1e-14)
    # the rubbery estimate refuses a range reaching within 20 K of T_g (issue 24, finding 4)
    with pytest.raises(InputError, match="within 20 K of the T_g of NBR"):
        cm.AnalyticContactMap(0.032, 2e-3, 0.10, 7.98e6, 1.9e-4, 293.15,
                              temperature_range=(243.15, 373.15))


def test_analytic_map_source_shown_to_users_has_no_internal_tag():
    # describe()["source"] names the map in the FMU's documentation and contact-table plot
    # title and in `sealsim fmu build` output; it ended in the docstrings' verification tag
    # "[R]", which means nothing to a user
    from sealsim.fmu.friction_export import contact_table

    m = cm.AnalyticContactMap(0.012, 2e-3, 0.12, 7.98e6, 1.9e-4, 293.15)
    source = m.describe()["source"]
    assert source.startswith("analytic") and "Lindley" in source
    assert not re.search(r"\[[A-Z]\]", source)
    assert contact_table(m, 5, 5).source == source


@pytest.fixture(scope="module")
def tiny_structure_case(tmp_path_factory):
    path = tmp_path_factory.mktemp("structure") / "tiny_rod_seal.toml"
    path.write_text(TINY_STRUCTURE_CASE)
    return path


@pytest.fixture(scope="module")
def fe_cache(tiny_structure_case, tmp_path_factory):
    """A cache folder in which the tiny FE map was built on demand (FElupe, ≈ 1.5 s)."""
    cache = tmp_path_factory.mktemp("cache")
    cm.build_or_load_fe_map(tiny_structure_case, cache_dir=cache)
    return cache


def test_fe_map_is_built_on_demand_and_cached(tiny_structure_case, fe_cache, tmp_path,
                                              monkeypatch):
    cache = fe_cache
    m = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=cache)
    files = list(cache.glob("tiny_rod_seal-*.nc"))
    assert len(files) == 1
    # FE contact force of the 12 x 2 O-ring on a 12 mm rod: energised by pressure; the same
    # order as the analytic estimate for that seal (rod seal of cylinder_32: 31 N at 0 bar)
    fn0, b0 = m.evaluate(0.0, 293.15)
    fn8, _ = m.evaluate(8e5, 293.15)
    assert 15.0 < fn0 < 80.0 and fn8 > fn0 and 0.2e-3 < b0 < 1.5e-3
    # the adapter evaluates the structure package's map object (same numbers)
    from sealsim.structure.maps import load_map
    ref = load_map(files[0])
    assert m.evaluate(3e5, 310.0) == pytest.approx(ref.evaluate(3e5, 310.0), rel=1e-14)
    # second time: read from the cache, no FE
    monkeypatch.setattr("sealsim.structure.mapping.compute_map",
                        lambda *a, **k: pytest.fail("the cached map was recomputed"))
    again = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=cache)
    assert again.evaluate(3e5, 310.0) == m.evaluate(3e5, 310.0)
    assert len(list(cache.glob("*.nc"))) == 1
    # a changed structure case is a different map (new hash)
    changed = tmp_path / "tiny_rod_seal.toml"
    changed.write_text(TINY_STRUCTURE_CASE.replace('squeeze = [0.12]', 'squeeze = [0.13]'))
    with pytest.raises(pytest.fail.Exception, match="recomputed"):
        cm.build_or_load_fe_map(changed, cache_dir=cache)
    # so is the same case computed by a changed FE model (issue 13, C.3): the key holds the
    # model's fingerprint (version, FElupe, source of the structure model and the catalogue)
    from sealsim.structure import fingerprint

    monkeypatch.setattr(fingerprint, "model_fingerprint", lambda: "another-fe-model")
    with pytest.raises(pytest.fail.Exception, match="recomputed"):
        cm.build_or_load_fe_map(tiny_structure_case, cache_dir=cache)


def test_a_damaged_cached_map_is_built_again(tiny_structure_case, fe_cache, tmp_path, caplog):
    # a cache file damaged on disk stopped every run of the case with "map file ... is not a
    # readable netCDF map: did not find a match in any of xarray's currently installed IO
    # backends ... Consider ... installing additional" -- the cache is rebuilt instead
    [cached] = fe_cache.glob("tiny_rod_seal-*.nc")
    damaged = tmp_path / cached.name
    damaged.write_bytes(cached.read_bytes()[:100])
    with caplog.at_level("INFO", logger="sealsim.pneumatic.contact_maps"):
        m = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=tmp_path)
    assert any(r.levelname == "WARNING" and "cannot be read (a damaged file); it is built "
               "again" in r.getMessage() for r in caplog.records)
    ref = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=fe_cache)
    assert m.evaluate(3e5, 310.0) == pytest.approx(ref.evaluate(3e5, 310.0), rel=1e-12)
    assert [p.name for p in tmp_path.glob("*.nc")] == [cached.name]


def test_an_interrupted_on_demand_map_build_computes_only_the_missing_paths(
        tiny_structure_case, fe_cache, tmp_path, computed_map_paths):
    # a map built on demand (pneumatic run, fits, studies) kept none of its finished FE load
    # paths: after Ctrl-C or a killed process the next run computed the whole map again
    from sealsim.pneumatic.map_cache import list_cached_maps

    computed = computed_map_paths

    def ctrl_c_after_one_path(done, total):
        if done == 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        cm.build_or_load_fe_map(tiny_structure_case, cache_dir=tmp_path,
                                progress=ctrl_c_after_one_path)
    assert computed == [293.15] and list(tmp_path.glob("*.nc")) == []
    [entry] = list_cached_maps(tmp_path)          # 'sealsim cache list' shows what is kept
    assert not entry.complete and entry.path.name.endswith(".nc.paths") and entry.size > 0
    assert len(list(entry.path.glob("*.json"))) == 1
    computed.clear()
    m = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=tmp_path)
    assert computed == [333.15]                   # only the path the interruption left out
    assert sorted(p.name for p in tmp_path.iterdir()) == [p.name for p in fe_cache.glob("*.nc")]
    # the same map as an uninterrupted build (JSON keeps every float; 1e-12: the resumed
    # build installs the seal again for its one path)
    ref = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=fe_cache)
    for p, t in ((0.0, 293.15), (3e5, 310.0), (8e5, 333.15)):
        np.testing.assert_allclose(m.evaluate(p, t), ref.evaluate(p, t), rtol=1e-12)


def test_an_interrupted_parallel_map_build_keeps_the_paths_being_solved(
        tiny_structure_case, fe_cache, tmp_path, request):
    # stopping a map built by worker processes waited for the paths they were solving, then
    # threw those away: only the paths handed back before the interruption were kept
    def stop_after_one_path(done, total):
        if done == 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        cm.build_or_load_fe_map(tiny_structure_case, cache_dir=tmp_path, workers=2,
                                progress=stop_after_one_path)
    [kept] = tmp_path.glob(".*.nc.paths")
    assert len(list(kept.glob("*.json"))) == 2        # both paths (2 workers, 2 paths)
    computed = request.getfixturevalue("computed_map_paths")   # counts in this process
    m = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=tmp_path, workers=1)
    assert computed == [] and not kept.exists()       # nothing was left to compute
    ref = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=fe_cache)
    np.testing.assert_allclose(m.evaluate(3e5, 310.0), ref.evaluate(3e5, 310.0), rtol=1e-12)

def test_build_notice_of_a_lip_seal_map():
    # a shaft (lip) case has no load.squeeze: announcing its map raised "TypeError:
    # 'NoneType' object is not subscriptable" before any FE was computed
    from sealsim.structure.case import StructureCase

    data = load_toml(EXAMPLES.parent / "structure" / "radial_lip_80.toml")
    data.pop("variants", None)
    case = validate_case(StructureCase, apply_overrides(data, {"map": {
        "pressure": ["0 bar", "0.5 bar"], "temperature": ["20 degC", "60 degC", "100 degC"]}}))
    assert case.load.squeeze is None
    assert cm._build_notice(case, Path("lip.toml"), Path("cache/lip-0.nc")) == (
        "building FE map from lip.toml (2 pressures x 3 temperatures, 3 FE load paths), cached "
        "at cache/lip-0.nc")

def test_fingerprint_follows_the_model_version(monkeypatch):
    from sealsim.structure import fingerprint

    before = fingerprint.model_fingerprint()
    fingerprint.model_fingerprint.cache_clear()
    monkeypatch.setattr(fingerprint, "FE_MODEL_VERSION", fingerprint.FE_MODEL_VERSION + 1)
    try:
        assert fingerprint.model_fingerprint() != before
    finally:
        fingerprint.model_fingerprint.cache_clear()


@pytest.mark.parametrize("scaling", ["held", "entropic", "modulus"])
def test_analytic_and_fe_maps_agree_on_the_temperature_trend(scaling, tiny_structure_case,
                                                             fe_cache, tmp_path):
    """Issue 10, finding 8: the analytic estimate and the FE map of the same gland (12 x 2 mm
    O-ring on a 12 mm rod, 12 % squeeze, NBR) take the modulus from one law
    (Elastomer.modulus_ratio), so F_N changes with temperature in the same direction and by
    about as much, 20 -> 60 °C:

    * "held" (the relaxed modulus of a seal held an hour, the default since issue 24): nearly
      flat, FE +1.6 %, analytic +0.5 % at 0 bar (the modulus dips 7 %, the cord's thermal
      expansion adds about as much);
    * "entropic" (equilibrium modulus ∝ T): F_N rises, FE +24.6 %, analytic +23.3 % at 0 bar;
    * "modulus" (catalogue dynamic modulus at 1 Hz): F_N falls, FE −28.0 %, analytic −28.9 %.

    Unpressurised (the preload, where the law acts) the two relative changes must agree within
    10 % of the change, or for the nearly flat "held" law within 2 % of the force: the
    remaining part comes from thermal expansion of the cord in a fixed groove, which Lindley's
    free-compression law and the FE (groove walls) treat differently. At 8 bar only the sign is
    required to agree, and the size within a factor 2.5: the analytic energisation Δp·b with
    the Hertz width b ∝ E^−1/2 depends on the modulus, the FE's pressure contribution hardly
    does (measured: held +4.3 vs +2.8 %, entropic +12.6 vs +15.6 %, modulus −7.4 vs −15.0 %).
    """
    from sealsim.properties.elastomers import get_elastomer

    if scaling == "held":  # the default of the tiny case
        fe = cm.build_or_load_fe_map(tiny_structure_case, cache_dir=fe_cache)
    else:
        case = tmp_path / f"tiny_rod_seal_{scaling}.toml"
        case.write_text(TINY_STRUCTURE_CASE.replace(
            'elastomer = "NBR"', f'elastomer = "NBR"\ntemperature_scaling = "{scaling}"'))
        fe = cm.build_or_load_fe_map(case, cache_dir=tmp_path)
    nbr = get_elastomer("NBR")
    analytic = cm.AnalyticContactMap(12e-3, 2e-3, 0.12, 6 * (nbr.c10 + nbr.c01),
                                     nbr.thermal_expansion, 293.15, temperature_scaling=scaling)

    def change(contact_map, dp):
        return contact_map.evaluate(dp, 333.15)[0] / contact_map.evaluate(dp, 293.15)[0] - 1

    fe0, an0 = change(fe, 0.0), change(analytic, 0.0)
    if scaling == "held":
        assert abs(an0 - fe0) < 0.02
    else:
        assert np.sign(fe0) == np.sign(an0) == (1 if scaling == "entropic" else -1)
        assert an0 == pytest.approx(fe0, rel=0.10)
    fe8, an8 = change(fe, 8e5), change(analytic, 8e5)
    assert np.sign(fe8) == np.sign(an8)
    assert 0.4 < an8 / fe8 < 2.5


def test_fe_map_input_errors(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        cm.FEContactMap.from_file(tmp_path / "missing.nc")
    no_map = tmp_path / "no_map.toml"
    no_map.write_text(TINY_STRUCTURE_CASE.split("[map]")[0])
    with pytest.raises(InputError, match=r"no \[map\] table"):
        cm.build_or_load_fe_map(no_map, cache_dir=tmp_path)


def test_cylinder_with_an_fe_map_file(fe_cache):
    # the rod seal reads a map.nc; F_N in the results is the map at the logged Δp, T (the
    # cylinder runs 6 bar: inside the 0...8 bar grid), and the seal temperature outside the
    # map's 20...60 °C is refused
    map_file = next(fe_cache.glob("*.nc"))
    data = load_toml(EXAMPLES / "cylinder_32.toml")
    data = apply_overrides(data, data.pop("variants")["T25C"])
    data["seals"][1]["map"] = {"file": str(map_file)}
    data["controller"]["duration"] = "1 s"
    case = validate_case(PneumaticCase, data)
    result = simulate(case)
    f = result.timeseries
    fe = cm.FEContactMap.from_file(map_file)
    expected, _ = fe.evaluate(f["dp_rod_bar"].to_numpy() * 1e5, 298.15)
    assert np.allclose(f["F_N_rod_N"], expected, rtol=1e-12)
    assert result.summary()["extend_time_s"] is not None
    hot = validate_case(PneumaticCase, apply_overrides(data, {
        "cylinder": {"seal_temperature": "80 degC"}}))
    with pytest.raises(InputError, match=r"seals\[1\] \('rod'\).*80 degC is outside"):
        simulate(hot)


def test_fe_map_built_for_seal_friction_is_announced_and_reports_progress(
        tiny_structure_case, tmp_path, monkeypatch, caplog):
    # sealsim.seal_friction with a structure case builds its FE map on demand (here the tiny
    # 2 x 2 map, FElupe, about 1.5 s): one INFO notice (grid, cache file) before the build,
    # then progress(done, total) per FE load path (one per temperature here).
    import logging

    import sealsim

    monkeypatch.setenv("SEALSIM_CACHE", str(tmp_path))
    reports = []
    with caplog.at_level(logging.INFO, logger="sealsim"):
        row = sealsim.seal_friction(tiny_structure_case, "0.1 m/s", "6 bar", "40 degC",
                                    progress=lambda done, total: reports.append((done, total)))
    assert reports == [(1, 2), (2, 2)]
    cached = next((tmp_path / "maps").glob("tiny_rod_seal-*.nc"))
    assert [r.getMessage() for r in caplog.records] == [
        f"building FE map from tiny_rod_seal.toml (2 pressures x 2 temperatures, 2 FE load "
        f"paths), cached at {cached}"]
    assert row["friction_N"] > 0 and row["normal_force_N"] > 0
    caplog.clear()
    again = sealsim.seal_friction(tiny_structure_case, "0.1 m/s", "6 bar", "40 degC")  # cached
    assert caplog.records == [] and again == row


def test_cold_seal_below_the_rubbery_map_says_why():
    # the analytic O-ring map of catalogue NBR starts 20 K above its T_g (-25 degC): a cylinder
    # with its seals at -10 degC is refused with that reason and the remedy (a compound with
    # a lower T_g), not with "extend its temperature grid", which a rubbery map must not do
    data = load_toml(EXAMPLES / "cylinder_32.toml")
    data = apply_overrides(data, data.pop("variants")["T25C"])
    cold = validate_case(PneumaticCase, apply_overrides(data, {
        "cylinder": {"seal_temperature": "-10 degC"}}))
    with pytest.raises(InputError, match=r"seals\[0\] \('piston'\): seal temperature -10 degC "
                       r"is outside its contact map \(-5 \.\.\. 120 degC\); .*T_g of NBR "
                       r"\(-25 degC\).*lower T_g") as error:
        simulate(cold)
    assert "extend its temperature grid" not in str(error.value)
