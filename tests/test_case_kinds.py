"""A case file run with the wrong command says which kind of case it is and how to run it
(sealsim.cases.CASE_KINDS, detect_case_kind, wrong_kind_message)."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from sealsim.cases import CASE_KINDS, detect_case_kind, expand_variants, load_toml
from sealsim.cli import app
from sealsim.errors import InputError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _model(kind):
    module, name = kind.model.rsplit(".", 1)
    return getattr(importlib.import_module(module), name)


def test_the_kinds_match_the_case_models():
    # the registry names the models as strings (cases.py imports no model); it must not drift
    models = {kind.name: _model(kind) for kind in CASE_KINDS}
    for kind in CASE_KINDS:
        fields = set(models[kind.name].model_fields)
        assert kind.tables <= fields, kind.name
        for other, model in models.items():
            if other != kind.name:
                assert not kind.tables & set(model.model_fields), (kind.name, other)


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*/*.toml")), ids=lambda p: p.name)
def test_every_example_is_recognised_as_the_kind_its_model_reads(path):
    data = load_toml(path)
    kind = detect_case_kind(data)
    assert kind is not None
    expand_variants(_model(kind), data, str(path))  # validates: it is that kind of case


@pytest.mark.parametrize(("command", "case", "kind", "hint"), [
    ("pneumatic run", "pneumatic/rod_seal_12.toml", "structure", "sealsim structure run"),
    ("rotary run", "pneumatic/cylinder_32.toml", "pneumatic", "sealsim pneumatic run"),
    ("structure run", "rotary/speed_cycle.toml", "rotary", "sealsim rotary run"),
    ("friction run", "calibration/tudelft_oring.toml", "friction fit", "sealsim friction fit"),
    ("friction fit", "friction/theta_dwell.toml", "friction", "sealsim friction run"),
])
def test_wrong_command_names_the_kind_and_the_command(tmp_path, command, case, kind, hint):
    result = CliRunner().invoke(app, [*command.split(), str(EXAMPLES / case),
                                      "--out", str(tmp_path / "out")])
    message = " ".join(result.output.split())
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert f"this looks like a {kind} case" in message and hint in message
    assert "unknown field" not in message  # instead of a list of every table
    assert message.count("looks like") == 1  # once, not once per variant


def test_a_broken_case_of_the_right_kind_still_lists_its_problems():
    from sealsim.pneumatic.case import PneumaticCase

    data = load_toml(EXAMPLES / "pneumatic" / "cylinder_32.toml")
    data["cylinder"] = {**data["cylinder"], "bore": "32 kg"}
    with pytest.raises(InputError, match="cylinder.bore") as info:
        expand_variants(PneumaticCase, data, "case")
    assert "looks like" not in str(info.value)
