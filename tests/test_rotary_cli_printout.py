"""What `sealsim rotary run` prints for each variant."""

from types import SimpleNamespace

from typer.testing import CliRunner

import sealsim.runs.rotary
from sealsim.cli import app


def test_the_energy_balance_error_is_called_relative(monkeypatch, tmp_path):
    # speed_cycle.toml printed 'energy balance error 8.2e-11' without saying it is
    # summary.json's energy_balance_rel_error (a fraction of the friction energy), not joules
    step = {"speed_rpm": 1000.0, "torque_Nm": 0.296, "T_groove_C": 68.0, "T_contact_C": 76.1}
    result = SimpleNamespace(steps=[step], energy={"rel_error": 8.2e-11}, notes=[])
    monkeypatch.setattr(sealsim.runs.rotary, "run_case_file",
                        lambda *args: {"wave": result})
    out = CliRunner().invoke(app, ["rotary", "run", "case.toml", "--out", str(tmp_path / "o"),
                                   "-q"], env={"COLUMNS": "300"})
    assert out.exit_code == 0, out.output
    assert "contact 76.1 °C; relative energy balance error 8.2e-11" in out.output
