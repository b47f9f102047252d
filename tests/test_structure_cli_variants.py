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
    # rich wraps at the console's width, set when sealsim.cli was first imported (and may
    # break the path): compare without the whitespace
    text = "".join(result.output.split())
    assert "".join(f"results written to {out}/VARIANT/ for oring, xring (result.csv".split()) \
        in text
    assert "".join(f"case_resolved.toml in {out}/".split()) in text


def test_a_case_without_variants_names_its_folder(monkeypatch, tmp_path):
    monkeypatch.setattr(sealsim.runs.structure, "run_case_file",
                        lambda *args: {"base": solved()})
    out = tmp_path / "rod"
    result = CliRunner().invoke(structure_app, ["run", "case.toml", "--out", str(out), "-q"],
                                env={"COLUMNS": "300"})
    assert result.exit_code == 0, result.output
    assert "".join(f"results written to {out}/ (result.csv".split()) in "".join(
        result.output.split())
