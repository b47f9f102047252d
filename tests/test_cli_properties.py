"""CLI: sealsim --version/--help, sealsim oil ..., sealsim material ... (via CliRunner)."""

from __future__ import annotations

import json

import pandas as pd
import pytest
from typer.testing import CliRunner

from sealsim import __version__
from sealsim.cli import app
from sealsim.properties import get_elastomer, get_oil, list_elastomers, list_oils

runner = CliRunner()

OIL_KEYS = {"name", "family", "origin", "nu40_mm2_s", "nu100_mm2_s", "viscosity_index",
            "rho15_kg_m3", "min_temperature_C", "source"}
OIL_ROW_KEYS = {"temperature_C", "nu_mm2_s", "eta_Pa_s", "rho_kg_m3", "k_W_mK", "cp_J_kgK"}
MATERIAL_KEYS = {"name", "description", "origin", "glass_transition_C", "service_min_C",
                 "service_max_C", "density_kg_m3", "hardness_shore_a", "reference_temperature_C",
                 "test_frequency_Hz", "E_reference_Pa", "source"}
MATERIAL_ROW_KEYS = {"temperature_C", "E_Pa", "a_T", "log10_a_T"}


def run(*args: str):
    return runner.invoke(app, list(args))


def ok(*args: str):
    result = run(*args)
    assert result.exit_code == 0, result.output
    assert "Traceback" not in result.output
    return result


def user_error(*args: str) -> str:
    """Run a command that must fail on bad input: exit 2, one message, no traceback."""
    result = run(*args)
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    assert result.exception is None or isinstance(result.exception, SystemExit)
    return " ".join(result.output.split())  # rich wraps lines at 80 columns


# -- top level ----------------------------------------------------------------------------------


def test_version():
    assert ok("--version").stdout.strip() == f"sealsim {__version__}"


def test_help_lists_the_command_groups():
    out = ok("--help").stdout
    assert "oil" in out and "material" in out


@pytest.mark.parametrize("group", ["oil", "material"])
def test_every_command_is_documented(group):
    out = ok(group, "--help").stdout
    for command in ("list", "show", "plot"):
        assert command in out
        sub = ok(group, command, "--help").stdout
        assert "Usage" in sub and len(sub.split()) > 20  # a real docstring, not just usage


# -- oil -------------------------------------------------------------------------------------


def test_oil_list_table_names_every_catalogue_oil():
    out = ok("oil", "list").stdout
    for name in list_oils():
        assert name in out


def test_oil_list_json():
    rows = json.loads(ok("oil", "list", "--json").stdout)
    assert [r["name"] for r in rows] == list_oils()
    assert all(set(r) == OIL_KEYS for r in rows)
    vg68 = rows[list_oils().index("VG68-mineral")]
    assert vg68["nu40_mm2_s"] == pytest.approx(68.0, rel=5e-3)  # catalogue datasheet, 0.5 %
    assert vg68["rho15_kg_m3"] == 880.0


def test_oil_show_table_has_units_and_header():
    out = ok("oil", "show", "VG68").stdout
    assert "VG68-mineral" in out and "VI = 99" in out and "source:" in out
    for unit in ("[°C]", "[mm²/s]", "[mPa·s]", "[kg/m³]", "[W/(m K)]", "[J/(kg K)]"):
        assert unit in out  # units in the headers survive (no rich markup eating [..])


def test_oil_show_says_which_law_gives_density_conductivity_and_heat_capacity(tmp_path):
    # the table gave rho, k and c_p without saying from where (ASTM D1250? Cragoe? a constant?)
    assert ("ρ: ASTM D1250 volume correction, α15 = 7.13e-4 1/K; k: Cragoe (NBS 1929, "
            "petroleum oils); c_p: Cragoe") in " ".join(ok("oil", "show", "VG68").stdout.split())
    path = tmp_path / "oils.toml"
    path.write_text('[oils."mine"]\nfamily = "ester"\nnu40 = "46 mm^2/s"\nnu100 = "8 mm^2/s"\n'
                    'density15 = "920 kg/m^3"\nthermal_expansion = "7.6e-4 1/K"\n'
                    'thermal_conductivity = "0.15 W/(m*K)"\n')
    data = json.loads(ok("oil", "show", "mine", "--oil-file", str(path), "--json").stdout)
    assert data["thermal_expansion_1_K"] == pytest.approx(7.6e-4, rel=1e-12)
    assert data["property_laws"].startswith("ρ: ASTM D1250 volume correction, α15 = 7.6e-4 1/K "
                                            "(given); k: constant 0.15 W/(m K); c_p: Cragoe")


def test_oil_show_json_has_si_values():
    data = json.loads(ok("oil", "show", "iso vg 68", "--json", "-t", "40,100").stdout)
    assert set(data) >= OIL_KEYS | {"table", "notes", "pressure_viscosity_coefficient_1_Pa"}
    assert [r["temperature_C"] for r in data["table"]] == [40.0, 100.0]
    row40, row100 = data["table"]
    assert set(row40) == OIL_ROW_KEYS
    # the oil reproduces its datasheet: 0.5 % is the catalogue test tolerance
    assert row40["nu_mm2_s"] == pytest.approx(68.0, rel=5e-3)
    assert row100["nu_mm2_s"] == pytest.approx(8.7, rel=5e-3)
    # eta = rho * nu in Pa s (SI): consistent to rounding of the JSON floats
    assert row40["eta_Pa_s"] == pytest.approx(row40["rho_kg_m3"] * row40["nu_mm2_s"] * 1e-6,
                                              rel=1e-9)
    assert data["notes"] == []


def test_oil_show_default_temperatures():
    data = json.loads(ok("oil", "show", "VG220", "--json").stdout)
    assert [r["temperature_C"] for r in data["table"]] == [20.0, 40.0, 60.0, 80.0, 100.0]


def test_unknown_oil_lists_close_matches():
    msg = user_error("oil", "show", "VG6")
    assert "unknown oil 'VG6'" in msg and "close matches" in msg and "'VG68'" in msg


@pytest.mark.parametrize("temps", ["20,abc", "", "nan", "20,,40", "-300", "20 m", "-300 degC"])
def test_bad_temperatures_are_a_clean_error(temps):
    msg = user_error("oil", "show", "VG68", "--temperatures", temps)
    assert "--temperatures" in msg


def test_temperatures_may_carry_their_units():
    # plain numbers are degC (the option says so); an item with a unit is converted
    data = json.loads(ok("oil", "show", "VG68", "-t", "-20 degC, 300 K,212 degF", "--json").stdout)
    assert [r["temperature_C"] for r in data["table"]] == pytest.approx([-20.0, 26.85, 100.0])


def test_temperature_below_the_oil_minimum_is_an_error():
    msg = user_error("oil", "show", "VG68", "-t", "-30")
    assert "-30.0 degC" in msg and "minimum temperature" in msg


def test_temperature_beyond_the_correlations_is_an_error_in_celsius():
    msg = user_error("oil", "show", "VG68", "-t", "500")
    assert "500 degC" in msg and "426.85" in msg  # 700 K, the upper limit, said in degC


def test_thin_oil_is_a_note_not_a_traceback():
    result = ok("oil", "show", "VG32", "-t", "200", "--json")
    data = json.loads(result.stdout)  # the note goes to stderr: stdout stays valid JSON
    assert any("below 2 mm^2/s" in n for n in data["notes"])
    assert "note:" in result.stderr


def test_user_oil_file(tmp_path):
    path = tmp_path / "my_oils.toml"
    path.write_text('[oils."Gear 150"]\nfamily = "PAO"\nnu40_mm2_s = 150.0\n'
                    'nu100_mm2_s = 19.0\nrho15_kg_m3 = 850.0\nsource = "datasheet X"\n')
    rows = json.loads(ok("oil", "list", "--json", "--oil-file", str(path)).stdout)
    assert rows[-1]["name"] == "Gear 150" and rows[-1]["origin"] == str(path)
    data = json.loads(ok("oil", "show", "gear 150", "--oil-file", str(path), "--json",
                         "-t", "40").stdout)
    assert data["table"][0]["nu_mm2_s"] == pytest.approx(150.0, rel=1e-9)  # fit through it


def test_broken_oil_file_is_a_clean_error(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('[oils."X"]\nfamily = "mineral"\nnu40 = 68\n')
    msg = user_error("oil", "list", "--oil-file", str(path))
    assert "nu40: 68 has no unit" in msg and "density15: required field is missing" in msg
    assert "does not exist" in user_error("oil", "list", "--oil-file", str(tmp_path / "no.toml"))


# -- plots ---------------------------------------------------------------------------------------


def _png(path):
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_oil_plot_writes_png_and_csv_and_says_where(tmp_path):
    out = tmp_path / "visc"
    result = ok("oil", "plot", "VG32", "VG68", "VG220", "--out", str(out))
    assert sorted(p.name for p in out.iterdir()) == [".sealsim-results",
                                                    "viscosity_temperature.csv",
                                                    "viscosity_temperature.png"]
    _png(out / "viscosity_temperature.png")
    assert str(out / "viscosity_temperature.png") in result.stdout
    frame = pd.read_csv(out / "viscosity_temperature.csv")
    assert list(frame.columns) == ["temperature_C", "nu_VG32-mineral_mm2_s",
                                   "nu_VG68-mineral_mm2_s", "nu_VG220-mineral_mm2_s"]
    assert frame["temperature_C"].iloc[[0, -1]].tolist() == [0.0, 150.0]
    at40 = frame.set_index("temperature_C").loc[40.0]
    assert at40["nu_VG68-mineral_mm2_s"] == pytest.approx(68.0, rel=5e-3)  # datasheet, 0.5 %
    assert frame["nu_VG32-mineral_mm2_s"].is_monotonic_decreasing


def test_oil_plot_leaves_invalid_ranges_empty(tmp_path):
    out = tmp_path / "wide"
    result = ok("oil", "plot", "VG32", "--out", str(out), "--t-min", "-40", "--t-max", "200",
                "--chart", "log")
    frame = pd.read_csv(out / "viscosity_temperature.csv").set_index("temperature_C")
    nu = frame["nu_VG32-mineral_mm2_s"]
    assert nu.loc[-40.0:-31.0].isna().all()  # below its -30 degC minimum temperature
    assert nu.loc[200.0] != nu.loc[200.0]  # NaN: thinner than 2 mm2/s, not extrapolated
    assert nu.dropna().min() >= 2.0
    assert "not drawn" in result.stderr


def test_plot_refuses_existing_results_without_force(tmp_path):
    out = tmp_path / "visc"
    ok("oil", "plot", "VG68", "--out", str(out))
    before = (out / "viscosity_temperature.csv").read_text()
    msg = user_error("oil", "plot", "VG32", "--out", str(out))
    assert "--force" in msg
    assert (out / "viscosity_temperature.csv").read_text() == before  # untouched
    ok("oil", "plot", "VG32", "--out", str(out), "--force")
    assert "nu_VG32-mineral_mm2_s" in (out / "viscosity_temperature.csv").read_text()


def test_plot_with_unknown_oil_writes_nothing(tmp_path):
    out = tmp_path / "visc"
    user_error("oil", "plot", "VG68", "VG999", "--out", str(out))
    assert list(tmp_path.iterdir()) == []  # no folder, no staging folder


def test_plot_bad_temperature_range(tmp_path):
    assert "--t-max" in user_error("oil", "plot", "VG68", "--out", str(tmp_path / "o"),
                                   "--t-min", "100", "--t-max", "50")
    # a range where no curve is valid is refused rather than drawing an empty chart
    msg = user_error("oil", "plot", "VG32", "--out", str(tmp_path / "o"), "--t-min", "180",
                     "--t-max", "200")
    assert "nothing to plot" in msg and "2 mm^2/s" in msg
    msg = user_error("material", "plot", "NBR", "--out", str(tmp_path / "o"), "--t-min", "200",
                     "--t-max", "300")
    assert "nothing to plot" in msg and "NBR -125 to 150 degC" in msg
    assert list(tmp_path.iterdir()) == []  # refused before anything was written


def test_material_plot_writes_png_and_csv(tmp_path):
    out = tmp_path / "mod"
    result = ok("material", "plot", "NBR", "FKM", "--out", str(out))
    _png(out / "modulus_temperature.png")
    assert str(out / "modulus_temperature.csv") in result.stdout
    frame = pd.read_csv(out / "modulus_temperature.csv").set_index("temperature_C")
    assert list(frame.columns) == ["E_NBR_Pa", "E_FKM_Pa"]
    e = frame["E_NBR_Pa"].dropna()
    # glassy (~GPa) well below T_g, rubbery (~MPa) at room temperature: the Fig. 3 shape
    assert e.loc[-60.0] > 1e9 and 3e6 < e.loc[20.0] < 2e7
    assert e.loc[:100.0].is_monotonic_decreasing  # E falls up to its minimum at ~108 degC
    assert user_error("material", "plot", "NBR", "--out", str(out)).count("--force") >= 1
    ok("material", "plot", "VMQ", "--out", str(out), "--force", "--frequency", "10")
    assert list(pd.read_csv(out / "modulus_temperature.csv").columns) == ["temperature_C",
                                                                          "E_VMQ_Pa"]


# -- material --------------------------------------------------------------------------------


def test_material_list_table_and_json():
    out = ok("material", "list").stdout
    assert all(name in out for name in list_elastomers())
    rows = json.loads(ok("material", "list", "--json").stdout)
    assert [r["name"] for r in rows] == list_elastomers()
    assert all(set(r) == MATERIAL_KEYS for r in rows)
    nbr = rows[0]
    assert nbr["glass_transition_C"] == pytest.approx(-25.0, abs=1e-9)  # K -> degC only
    assert nbr["density_kg_m3"] == 1250.0


def test_material_show_json():
    data = json.loads(ok("material", "show", "nbr", "--json", "-t", "-25,20,100").stdout)
    nbr = get_elastomer("NBR")
    assert set(data) >= MATERIAL_KEYS | {"c10_Pa", "c01_Pa", "bulk_modulus_Pa", "wlf_c1",
                                         "table", "notes", "frequency_Hz"}
    assert data["c10_Pa"] == nbr.c10 and data["frequency_Hz"] == 1.0
    rows = {r["temperature_C"]: r for r in data["table"]}
    assert set(rows[20.0]) == MATERIAL_ROW_KEYS
    assert rows[20.0]["E_Pa"] == pytest.approx(8.5e6, rel=1e-3)  # catalogue E(20 degC, 1 Hz)
    assert rows[-25.0]["a_T"] == pytest.approx(1.0, rel=1e-12)  # a_T = 1 at T_ref,WLF = T_g
    assert rows[100.0]["log10_a_T"] == pytest.approx(-12.34, abs=0.01)  # WLF at T_g + 125 K
    assert data["notes"] == []  # all inside the service range


def test_material_show_default_table_is_the_service_range():
    data = json.loads(ok("material", "show", "FKM", "--json").stdout)
    temps = [r["temperature_C"] for r in data["table"]]
    assert temps[0] == -25.0 and temps[-1] == 200.0  # FKM service range
    assert data["notes"] == []


def test_material_show_table_and_frequency():
    out = ok("material", "show", "HNBR", "--frequency", "100").stdout
    assert "E(T) at 100 Hz" in out and "[MPa]" in out and "Mooney-Rivlin" in out
    # at the WLF reference temperature log10 a_T is 0, shown so (it read "-0.00")
    out = ok("material", "show", "NBR", "-t", "-25").stdout
    assert "1.000e+00        0.00" in out and "-0.00" not in out


def test_material_outside_service_range_is_a_note():
    result = ok("material", "show", "NBR", "-t", "120", "--json")
    assert "outside the service range" in json.loads(result.stdout)["notes"][0]


@pytest.mark.parametrize(
    ("args", "words"),
    [(("material", "show", "NBX"), ["unknown elastomer", "NBR"]),
     (("material", "show", "NBR", "-t", "400"), ["400 degC", "allowed"]),
     (("material", "show", "NBR", "-t", "x"), ["--temperatures"]),
     (("material", "show", "NBR", "--frequency", "0"), ["--frequency"]),
     (("material", "show", "NBR", "--frequency", "inf"), ["--frequency"])],
)
def test_material_bad_input(args, words):
    msg = user_error(*args)
    for word in words:
        assert word in msg


def test_user_material_file_with_dma_table(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text(
        "[MyNBR]\nglass_transition_C = -30\ndensity_kg_m3 = 1250\n"
        "thermal_conductivity_W_mK = 0.25\nspecific_heat_J_kgK = 1700\n"
        "thermal_expansion_per_K = 2e-4\nc10_MPa = 1.0\nc01_MPa = 0.25\n"
        "bulk_modulus_MPa = 2000\nservice_min_C = -40\nservice_max_C = 100\n"
        "[MyNBR.modulus]\nglassy_MPa = 2000\nrubbery_MPa = 2.7\n"
        "[MyNBR.dma]\ntemperature_C = [-40, 0, 50, 100]\nmodulus_MPa = [1500, 30, 9, 7]\n")
    # its constants (7.5 MPa) and its DMA table (14.2 MPa at 23 degC) disagree: said on load
    with pytest.warns(UserWarning, match=r"7\.5 MPa.*14\.2 MPa.*-47%"):
        data = json.loads(ok("material", "show", "mynbr", "--material-file", str(path),
                             "--json", "-t", "0,50").stdout)
    assert data["origin"] == str(path) and data["modulus_model"] == "DMA table"
    # at the table's frequency the measured points are returned (PCHIP interpolates exactly)
    assert [r["E_Pa"] for r in data["table"]] == pytest.approx([30e6, 9e6], rel=1e-9)
    with pytest.warns(UserWarning, match="14\\.2 MPa"):
        msg = user_error("material", "show", "other", "--material-file", str(path))
    assert "MyNBR" in msg  # the names of the file are offered too


def test_oil_json_values_match_the_python_api():
    data = json.loads(ok("oil", "show", "VG220-PAG", "--json", "-t", "80").stdout)
    oil = get_oil("VG220-PAG")
    # the CLI only converts units: identical to the API up to the 12 significant digits of
    # its JSON (JSON_DIGITS: a relative rounding of at most 5e-12)
    assert data["table"][0]["eta_Pa_s"] == pytest.approx(oil.dynamic_viscosity(353.15),
                                                         rel=5e-12)
    assert data["viscosity_index"] == pytest.approx(oil.viscosity_index, rel=5e-12)
