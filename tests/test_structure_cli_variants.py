"""What `sealsim structure run` says about where a case with variants wrote its files."""

from types import SimpleNamespace

from typer.testing import CliRunner

import sealsim.runs.structure
from sealsim.cli.structure import structure_app


def solved():
    last = SimpleNamespace(F_N=200.0, F_N_per_length=3.2e3, b=2e-3, p_max=2e6)
    return SimpleNamespace(states=[last], ndofs=10, wall_time=1.0)


def test_a_case_with_variants_names_the_variant_folders(monkeypatch, tmp_path):
    # each variant writes into OUT/<variant>/ (sealsim.runs.structure); the printout said
    # OUT/ (result.csv, ...), where there is no result.csv
    monkeypatch.setattr(sealsim.runs.structure, "run_case_file",
                        lambda *args: {"oring": solved(), "xring": solved()})
    out = tmp_path / "cmp"
    result = CliRunner().invoke(structure_app, ["run", "case.toml", "--out", str(out), "-q"],
                                env={"COLUMNS": "300"})
    assert result.exit_code == 0, result.output
    assert f"results written to {out}/VARIANT/ for oring, xring (result.csv" in result.output
    assert f"case_resolved.toml in {out}/" in result.output


def test_a_case_without_variants_names_its_folder(monkeypatch, tmp_path):
    monkeypatch.setattr(sealsim.runs.structure, "run_case_file",
                        lambda *args: {"base": solved()})
    out = tmp_path / "rod"
    result = CliRunner().invoke(structure_app, ["run", "case.toml", "--out", str(out), "-q"],
                                env={"COLUMNS": "300"})
    assert result.exit_code == 0, result.output
    assert f"results written to {out}/ (result.csv" in result.output
