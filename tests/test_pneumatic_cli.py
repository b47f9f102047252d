"""`sealsim pneumatic run`: every example through the CLI (shortened), the result folder,
errors with exit status 2, reproducibility of the resolved case."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import tomli_w
from typer.testing import CliRunner

from sealsim.cases import expand_variants, load_toml
from sealsim.cli.pneumatic import pneumatic_app
from sealsim.output import ResultFolder
from sealsim.pneumatic.results import column_name

EXAMPLE_DIR = Path(__file__).resolve().parents[1] / "examples" / "pneumatic"
#: pneumatic cases (rod_seal_12.toml is the structure case cylinder_32_fe.toml builds its map from)
EXAMPLES = sorted(p for p in EXAMPLE_DIR.glob("*.toml") if p.name != "rod_seal_12.toml")
RUNNER = CliRunner()
SUMMARY_KEYS = {"extend_time_s", "retract_time_s", "mean_friction_N", "peak_friction_N",
                "air_consumption_NL", "mass_balance_rel_error", "energy_balance_rel_error"}


def shortened(path: Path, tmp_path: Path, cap: float = 1.2) -> Path:
    """The example with its simulated time cut to ``cap`` seconds; an FE map built on demand
    comes from a coarse 2 x 2 version of its structure case, cached in ``tmp_path``."""
    data = tomllib.loads(path.read_text())
    ctrl = data["controller"]
    seconds = float(ctrl["duration"].split()[0])
    ctrl["duration"] = f"{min(seconds, cap)} s"
    for seal in data.get("seals", []):
        structure = seal.get("map", {}).get("structure_case")
        if structure:
            spec = tomllib.loads((path.parent / structure).read_text())
            spec["mesh"] = {"level": "coarse"}
            spec["map"].update(pressure=["0 bar", "8 bar"], temperature=["20 degC", "60 degC"],
                               squeeze_increments=4, temperature_increments=1, workers=1)
            (tmp_path / structure).write_text(tomli_w.dumps(spec))
            seal["map"]["cache_dir"] = str(tmp_path / "cache")
    out = tmp_path / path.name
    out.write_text(tomli_w.dumps(data))
    return out


def run(*args):
    return RUNNER.invoke(pneumatic_app, ["run", *map(str, args)])


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_example_runs_through_the_cli(example, tmp_path):
    case = shortened(example, tmp_path)
    out = tmp_path / "out"
    result = run(case, "--out", out)
    assert result.exit_code == 0, result.output
    # an FE map built on demand (cylinder_32_fe: a 2 x 2 map in a fresh cache) is announced
    # once before its FE computation starts; the second variant reads it from the cache
    cached = sorted((tmp_path / "cache").glob("rod_seal_12-*.nc"))
    notices = [f"building FE map for seal 'rod' from rod_seal_12.toml (2 pressures x 2 "
               f"temperatures, 2 FE load paths), cached at {path}" for path in cached]
    text = "".join(result.output.split())            # rich wraps long lines anywhere
    assert text.count("buildingFEmap") == len(notices) == (example.stem == "cylinder_32_fe")
    assert all("".join(notice.split()) in text for notice in notices)
    # a note every variant has is printed once, after the variants (heipl_rod_seal's four
    # temperatures printed the parameter set's note four times)
    generic = "".join("theta parameter set 'seal_contact'".split())
    assert text.count(generic) <= len({s["name"] for s in tomllib.loads(
        example.read_text())["seals"]})
    names = {p.name for p in out.iterdir()}
    assert {"timeseries.csv", "summary.json", "case_resolved.toml", "pressure_stroke.png",
            "friction_stroke.png", "friction_velocity.png"} <= names
    variants = list(tomllib.loads(example.read_text()).get("variants", {"base": {}}))
    assert {f"timeseries_{v}.png" for v in variants} <= names
    summary = json.loads((out / "summary.json").read_text())
    assert list(summary["variants"]) == variants
    for s in summary["variants"].values():
        assert SUMMARY_KEYS <= set(s)
        assert s["mass_balance_rel_error"] < 1e-12
        assert s["energy_balance_rel_error"] < 1e-3
        assert s["peak_friction_N"] > 0
        # integrals of flows that are never negative (heipl_rod_seal's T25C reported
        # -1.6e-7 NL returned to the supply: the integrator's error on a zero flow)
        assert s["air_consumption_NL"] >= 0 and s["air_returned_to_supply_NL"] >= 0
    table = pd.read_csv(out / "timeseries.csv")
    assert list(table.columns[:8]) == ["variant", "time_s", "x_m", "v_m_s", "p1_bar_abs",
                                       "p2_bar_abs", "T1_C", "T2_C"]
    assert "valve_command" in table and "F_friction_N" in table
    for seal in tomllib.loads(example.read_text())["seals"]:
        name = column_name(seal["name"])            # "test seal" -> "test_seal"
        assert " " not in name and f"F_{name}_N" in table
        if seal["friction"]["law"] == "theta":
            assert f"F_N_{name}_N" in table and f"theta_{name}" in table
            # the contact law's film state with its unit (not in the table before)
            contact = (seal["friction"].get("parameter_set") == "seal_contact"
                       or seal["friction"].get("steady") == "contact")
            assert (f"film_speed_{name}_m_s" in table) == contact
            if contact:
                assert table[f"film_speed_{name}_m_s"].max() > 0.0
    assert set(table["variant"]) == set(variants)
    assert np.all(np.isfinite(table.select_dtypes("number").to_numpy()))
    for png in out.glob("*.png"):
        assert png.stat().st_size > 10_000
    # the resolved case reproduces the variants (all defaults written out)
    resolved = load_toml(out / "case_resolved.toml")
    from sealsim.pneumatic.case import PneumaticCase
    again = expand_variants(PneumaticCase, resolved)
    original = expand_variants(PneumaticCase, load_toml(case))
    assert {k: v.model_dump() for k, v in again.items()} == \
        {k: v.model_dump() for k, v in original.items()}


def test_existing_folder_and_force(tmp_path):
    case = shortened(EXAMPLE_DIR / "friction_rig.toml", tmp_path, cap=0.2)
    out = tmp_path / "out"
    with ResultFolder(out) as folder:       # the results of an earlier run
        folder.write_text("old.txt", "keep me")
    refused = run(case, "--out", out, "-q")
    assert refused.exit_code == 2 and "--force" in refused.output
    assert (out / "old.txt").read_text() == "keep me"
    mine = tmp_path / "mine"                # a folder sealsim did not write: not even --force
    mine.mkdir()
    (mine / "notes.txt").write_text("keep me")
    refused = run(case, "--out", mine, "-q", "--force")
    assert refused.exit_code == 2
    assert "was not written by sealsim" in " ".join(refused.output.split())
    assert (mine / "notes.txt").read_text() == "keep me"
    forced = run(case, "--out", out, "-q", "--force")
    assert forced.exit_code == 0, forced.output
    assert not (out / "old.txt").exists() and (out / "summary.json").is_file()


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["cylinder"].update(bore="32"), "cylinder.bore: '32' has no unit"),
    (lambda d: d["seals"][0]["friction"].update(tau="-2 s"), "seals.0.friction.tau"),
    (lambda d: d["seals"][0].pop("map"), "the theta law needs"),
    (lambda d: d["valve"].update(type="4/2"), "valve.type"),
    (lambda d: d.update(speed="fast"), "speed: unknown field"),
])
def test_bad_case_exits_2_with_one_message(edit, message, tmp_path):
    data = tomllib.loads((EXAMPLE_DIR / "cylinder_32.toml").read_text())
    edit(data)
    case = tmp_path / "bad.toml"
    case.write_text(tomli_w.dumps(data))
    result = run(case, "--out", tmp_path / "out", "-q")
    assert result.exit_code == 2, result.output
    assert message in " ".join(result.output.split())
    assert "Traceback" not in result.output
    assert not (tmp_path / "out").exists()


def test_notices_are_shown_while_a_command_runs_unless_quiet(capsys):
    import logging

    from sealsim.cli._common import sealsim_notices

    log = logging.getLogger("sealsim.pneumatic.contact_maps")
    with sealsim_notices(quiet=True):
        log.info("building FE map (quiet)")
    with sealsim_notices(quiet=False):
        log.info("building FE map (shown)")
    log.info("building FE map (after the command)")   # handler removed, level restored
    err = capsys.readouterr().err
    assert "(shown)" in err and "(quiet)" not in err and "(after" not in err


def test_missing_case_file_exits_2(tmp_path):
    result = run(tmp_path / "nope.toml", "--out", tmp_path / "out")
    assert result.exit_code == 2 and "does not exist" in " ".join(result.output.split())


def test_structure_case_of_the_fe_example_is_valid():
    # rod_seal_12.toml is read by cylinder_32_fe.toml to build its map: it must be a valid
    # structure case with a [map] grid covering the example (6 bar supply, 25 and 55 °C)
    from sealsim.structure.case import StructureCase

    case = expand_variants(StructureCase, load_toml(EXAMPLE_DIR / "rod_seal_12.toml"))["base"]
    assert case.map is not None
    assert max(case.map.pressure) >= 6e5 + 1e5
    assert min(case.map.temperature) <= 298.15 and max(case.map.temperature) >= 328.15


def test_help_names_the_thermal_table():
    # the help is rich markup: "[thermal]" unescaped was taken for a style tag and vanished
    # ("with seal heating () also heating_VARIANT.png")
    result = RUNNER.invoke(pneumatic_app, ["run", "--help"], terminal_width=200)
    assert result.exit_code == 0
    assert "seal heating ([thermal]) also" in " ".join(result.output.split())
