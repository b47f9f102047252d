"""The ``sealsim structure`` commands on the shipped examples (shortened where needed)."""

import json
import tomllib
from pathlib import Path

import pandas as pd
import pytest
import tomli_w
from typer.testing import CliRunner

from sealsim.cases import apply_overrides
from sealsim.cli.structure import structure_app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "structure"
RESULT_COLUMNS = ["squeeze_percent", "pressure_bar", "temperature_C", "F_N_N",
                  "F_N_per_length_N_per_mm", "b_mm", "p_max_MPa", "p_mean_MPa"]
runner = CliRunner()


def shortened(tmp_path, name, overrides):
    """A copy of an example with overrides (coarser mesh, fewer load states)."""
    with open(EXAMPLES / name, "rb") as fh:
        data = tomllib.load(fh)
    path = tmp_path / name
    path.write_text(tomli_w.dumps(apply_overrides(data, overrides)))
    return path


def invoke(*args):
    result = runner.invoke(structure_app, [str(a) for a in args])
    return result


def test_oring_rod_example(tmp_path):
    case = shortened(tmp_path, "oring_rod.toml", {"mesh": {"level": "coarse"}})
    out = tmp_path / "rod"
    result = invoke("run", case, "--out", out, "--quiet")
    assert result.exit_code == 0, result.output
    frame = pd.read_csv(out / "result.csv")
    assert list(frame.columns[:3]) == RESULT_COLUMNS[:3]
    assert set(RESULT_COLUMNS) <= set(frame.columns)
    assert len(frame) == 5 + 6  # five squeeze states, six pressures
    squeeze = frame.iloc[:5]
    assert squeeze["F_N_N"].is_monotonic_increasing and squeeze["b_mm"].is_monotonic_increasing
    assert frame.iloc[5:]["F_N_N"].is_monotonic_increasing
    profiles = pd.read_csv(out / "profiles.csv")
    assert {"surface", "position_mm", "contact_pressure_MPa"} <= set(profiles.columns)
    for name in ("section_installed.png", "section_final.png", "states.png",
                 "case_resolved.toml", "summary.json"):
        assert (out / name).is_file()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["max_equilibrium_error"] < 1e-6
    # the resolved case runs again unchanged (reproducible)
    again = invoke("run", out / "case_resolved.toml", "--out", tmp_path / "again", "--quiet")
    assert again.exit_code == 0, again.output
    assert pd.read_csv(tmp_path / "again" / "result.csv")["F_N_N"].iloc[-1] == pytest.approx(
        frame["F_N_N"].iloc[-1], rel=1e-9)
    # an existing result folder is refused (exit 2) unless --force
    refused = invoke("run", case, "--out", out, "--quiet")
    assert refused.exit_code == 2 and "--force" in refused.output


def test_oring_map_example(tmp_path):
    case = shortened(tmp_path, "oring_map.toml", {
        "mesh": {"level": "coarse"},
        "map": {"pressure": ["0 bar", "5 bar", "10 bar"],
                "temperature": ["20 degC", "60 degC"], "workers": 2}})
    out = tmp_path / "map"
    result = invoke("map", case, "--out", out, "--quiet")
    assert result.exit_code == 0, result.output
    from sealsim.structure import load_map

    m = load_map(out / "map.nc")
    f, b = m(7.5e5, 313.15)
    assert 0 < f and 0 < b < 4e-3
    assert "[map]" in m.dataset.attrs["case"]
    assert (out / "map.png").is_file() and (out / "map.csv").is_file()


def test_oring_cooling_example(tmp_path):
    case = shortened(tmp_path, "oring_cooling.toml", {
        "load": {"temperature": ["-45 degC"], "temperature_increments": 13}})
    out = tmp_path / "cool"
    result = invoke("run", case, "--out", out, "--quiet")
    assert result.exit_code == 0, result.output
    frame = pd.read_csv(out / "result.csv")
    cooling = frame[frame["time_s"] > 3660.0 + 1.0]
    assert cooling["temperature_C"].iloc[-1] == pytest.approx(-45.0)
    # the groove contact is lost below T_g (Heipl & Murrenhoff, Fig. 8)
    assert cooling["F_groove_bottom_N"].iloc[-1] == 0.0


def test_states_plot_of_a_cooling_run_is_over_temperature():
    import matplotlib.pyplot as plt

    from sealsim.plotting.structure import plot_states

    # installation (squeeze ramp) and hold at 20 degC, then cooling to -40 degC
    temperature = [20.0, 20.0, 20.0, 0.0, -20.0, -40.0]
    frame = pd.DataFrame({
        "squeeze_percent": [5.0, 15.0, 15.0, 15.0, 15.0, 15.0], "pressure_bar": 0.0,
        "temperature_C": temperature, "time_s": [0, 30, 3660, 4860, 6060, 7260],
        "F_N_N": [40, 130, 120, 100, 60, 200], "F_groove_bottom_N": [50, 170, 160, 120, 0, 0],
        "b_mm": 1.0, "p_max_MPa": 1.0, "p_max_groove_bottom_MPa": 1.0})
    fig = plot_states(frame)
    for ax in fig.axes:
        assert ax.get_xlabel() == "temperature [°C]"
        assert ax.xaxis_inverted()                 # the cooling reads from left to right
    # from the installed and held state on: the squeeze ramp at 20 degC is not drawn
    assert list(fig.axes[0].lines[0].get_xdata()) == temperature[2:]
    plt.close(fig)
    # a lip bonded to its case has no groove bottom (its columns hold 0): not drawn as a
    # contact force of 0 N (radial_lip_80's states.png had a flat 'groove bottom' line)
    lip = plot_states(frame, groove_bottom=False)
    assert [line.get_label() for line in lip.axes[0].lines] == ["sealing surface F_N"]
    assert [line.get_label() for line in lip.axes[2].lines] == ["sealing surface"]
    plt.close(lip)


def test_map_plots_label_temperatures_given_in_degf_without_conversion_noise():
    import numpy as np
    import xarray as xr

    from sealsim.plotting.structure import plot_map, plot_map_profiles
    from sealsim.units import parse_quantity

    # "32 degF" parses to 273.15 K + 6e-14 K: the legend said "5.684e-14 °C"
    temps = [parse_quantity(t, "temperature") for t in ("32 degF", "104 degF", "100 degF")]
    shape = (1, 3, 2)
    ds = xr.Dataset({"F_N": (("squeeze", "temperature", "pressure"), np.ones(shape)),
                     "b": (("squeeze", "temperature", "pressure"), np.ones(shape)),
                     "contact_pressure": (("squeeze", "temperature", "pressure", "position"),
                                          np.ones(shape + (4,)))},
                    coords={"squeeze": [0.15], "temperature": temps, "pressure": [0.0, 1e5],
                            "position": np.linspace(-1e-3, 1e-3, 4)})
    labels = [t.get_text() for t in plot_map(ds).axes[0].get_legend().get_texts()]
    assert labels == ["0 °C", "40 °C", "37.78 °C"]
    profiles = plot_map_profiles(ds)
    assert profiles.axes[0].get_title() == "at 0 °C"
    assert [line.get_label() for line in profiles.axes[1].lines] == labels


@pytest.mark.parametrize("overrides, message", [
    ({"load": {"squeeze": [1.0]}}, "load.squeeze"),
    ({"seal": {"cord_diameter": "-4 mm"}}, "seal.cord_diameter"),
    ({"gland": {"groove_width": "3 mm"}}, "too narrow"),
    ({"material": {"elastomer": "XYZ"}}, "XYZ"),
])
def test_bad_input_exits_2(tmp_path, overrides, message):
    case = shortened(tmp_path, "oring_rod.toml", overrides)
    result = invoke("run", case, "--out", tmp_path / "bad", "--quiet")
    assert result.exit_code == 2
    assert message in result.output
    assert not (tmp_path / "bad").exists()  # nothing written


def test_map_without_grid_is_refused(tmp_path):
    result = invoke("map", EXAMPLES / "oring_rod.toml", "--out", tmp_path / "m", "--quiet")
    assert result.exit_code == 2 and "[map]" in result.output


def test_registered_in_main_app():
    from sealsim.cli import app

    names = [g.name for g in app.registered_groups]
    if "structure" not in names:
        pytest.skip("structure_app is not registered in sealsim.cli yet (lead's step)")
    result = runner.invoke(app, ["structure", "--help"])
    assert result.exit_code == 0 and "run" in result.output and "map" in result.output
