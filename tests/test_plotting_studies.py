"""Units in the pictures and printout of `sealsim study run`."""

import numpy as np
import xarray as xr

from sealsim.plotting.studies import heatmap_figure, response_figure


def study_dataset():
    """A 2 x 3 grid study (oil x speed) of a temperature output in pint's 'degC'."""
    speed = xr.DataArray([250.0, 500.0, 1000.0], dims="speed", attrs={"units": "rpm"})
    oil = xr.DataArray(["VG32", "VG68"], dims="oil", attrs={"units": "1"})
    t = xr.DataArray(np.array([[40.0, 50.0, 60.0], [45.0, 55.0, 70.0]]), dims=("oil", "speed"),
                     coords={"oil": oil, "speed": speed}, attrs={"units": "degC"})
    return xr.Dataset({"T_contact": t})


def test_response_and_heatmap_write_degrees_celsius():
    # gearbox_oils.toml: the axis read 'T_contact [degC]'
    ds = study_dataset()
    fig = response_figure(ds, "T_contact", "speed")
    assert fig.axes[0].get_ylabel() == "T_contact [°C]"
    assert fig.axes[0].get_xlabel() == "speed [rpm]"
    fig = heatmap_figure(ds, "T_contact", "speed", "oil")
    labels = [ax.get_ylabel() for ax in fig.axes] + [ax.get_xlabel() for ax in fig.axes]
    assert "T_contact [°C]" in labels
    assert not [label for label in labels if "degC" in label]


def test_study_printout_writes_degrees_celsius(monkeypatch, tmp_path):
    # gearbox_oils.toml printed 'T_contact: 40.57 ... 123.5 degC'
    from types import SimpleNamespace

    from typer.testing import CliRunner

    import sealsim.runs.study
    from sealsim.cli import app

    study = tmp_path / "study.toml"
    study.write_text(
        '[study]\nmodel = "friction"\n[base.friction]\nlaw = "coulomb"\n'
        'coulomb_force = "10 N"\n[base.bench]\nmode = "velocity"\nduration = "0.05 s"\n'
        'time_step = "10 ms"\nvelocity = { kind = "constant", level = "0.1 m/s" }\n'
        '[outputs]\nF = "max_friction_force_N"\n[[factors]]\nname = "fc"\n'
        'path = "friction.coulomb_force"\nvalues = ["10 N", "20 N"]\n')
    summary = {"runs": {"finished": 2, "total": 2, "failed": 0, "computed": 2, "reused": 0},
               "engine": {"kind": "local", "workers": 0}, "wall_time_s": 1.0,
               "outputs": {"T_contact": {"n": 2, "unit": "degC", "min": 40.57, "max": 123.5,
                                         "P50": 64.84, "P5": 43.53, "P95": 113.1}},
               "failures": [], "notes": []}
    monkeypatch.setattr(sealsim.runs.study, "run_study",
                        lambda *args, **kwargs: SimpleNamespace(summary=summary))
    result = CliRunner().invoke(app, ["study", "run", str(study), "--out",
                                      str(tmp_path / "out"), "-q"])
    assert result.exit_code == 0, result.output
    assert "T_contact: 40.57 ... 123.5 °C (median 64.84" in result.output
