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
    # rich wraps at the console's width, set when sealsim.cli was first imported: compare
    # without the whitespace
    assert "contact76.1°C;relativeenergybalanceerror8.2e-11" in "".join(out.output.split())
