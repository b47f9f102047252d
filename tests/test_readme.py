"""The README is the front door: at most 300 lines, and every command in it runs.

The quick start's ``make demo`` is checked through the Makefile's own recipe (running make from
the tests would install a second environment); every ``sealsim`` command line and every Python
block of the README is run as written, in a scratch folder that sees the repository's
``examples/``.
"""

from __future__ import annotations

import os
import re
import shlex
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from sealsim.cli import app

REPO = Path(__file__).resolve().parents[1]
README = REPO / "README.md"
RUNNER = CliRunner()


def code_blocks(text: str) -> list[tuple[str, str]]:
    """``(language, body)`` of every fenced code block."""
    return re.findall(r"^```(\w*)\n(.*?)^```", text, flags=re.MULTILINE | re.DOTALL)


def command_lines(text: str, program: str) -> list[str]:
    """Lines of unlabelled code blocks that start with ``program`` (comments removed)."""
    lines = []
    for language, body in code_blocks(text):
        if language:
            continue
        for line in body.splitlines():
            line = line.split("#", 1)[0].strip()
            if line.split(" ", 1)[0] == program:
                lines.append(line)
    return lines


@pytest.fixture
def scratch(tmp_path, monkeypatch):
    (tmp_path / "examples").symlink_to(REPO / "examples", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_readme_is_a_front_door():
    text = README.read_text(encoding="utf-8")
    # the limit: everything beyond the front door lives in the documentation
    assert len(text.splitlines()) <= 300
    for heading in ("## Quick start", "## Python", "## Command line", "## Status",
                    "## Documentation", "## Dependencies"):
        assert heading in text
    # the quick start is exactly the two make commands
    quick = text.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    assert command_lines(quick, "make") == ["make demo", "make test"]


def test_make_demo_runs_the_flagship_example(scratch):
    makefile = (REPO / "Makefile").read_text(encoding="utf-8")
    case = re.search(r"^DEMO_CASE := (\S+)$", makefile, flags=re.MULTILINE).group(1)
    recipe = re.search(r"^demo:.*\n\t(.+)$", makefile, flags=re.MULTILINE).group(1)
    assert recipe == "$(BIN)/sealsim rotary run $(DEMO_CASE) --out $(DEMO_OUT) --force"
    result = RUNNER.invoke(app, ["rotary", "run", case, "--out", "results/demo", "--quiet"])
    assert result.exit_code == 0, result.output
    assert (scratch / "results" / "demo" / "cycle_plain.png").is_file()


def test_every_sealsim_command_of_the_readme_runs(scratch):
    lines = command_lines(README.read_text(encoding="utf-8"), "sealsim")
    assert lines, "the README shows at least one sealsim command"
    for line in lines:
        args = shlex.split(line)[1:]
        result = RUNNER.invoke(app, args)
        assert result.exit_code == 0, (line, result.output)
        if "--out" in args:
            out = scratch / args[args.index("--out") + 1]
            assert any(out.glob("*.png")) and any(out.glob("*.csv")), line


def test_every_python_block_of_the_readme_runs(scratch):
    blocks = [body for language, body in code_blocks(README.read_text(encoding="utf-8"))
              if language == "python"]
    assert blocks
    for body in blocks:
        exec(compile(body, str(README), "exec"), {"__name__": "__readme__"})  # noqa: S102


def test_documented_make_targets_exist():
    makefile = (REPO / "Makefile").read_text(encoding="utf-8")
    for line in command_lines(README.read_text(encoding="utf-8"), "make"):
        target = line.split()[1]
        assert re.search(rf"^{target}:", makefile, flags=re.MULTILINE), line
    assert os.access(REPO / ".ci" / "run", os.X_OK)


def _run_make(folder: Path, *targets: str) -> None:
    import subprocess

    done = subprocess.run(["make", "--no-print-directory", "-C", str(folder), *targets],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.skipif(not shutil.which("make"), reason="needs make")
def test_ci_installs_the_environment_once(tmp_path):
    # .ci/run's make targets, in its order, on a copy of the Makefile whose .venv/bin/python
    # only logs its calls: one pip install (test and docs extras), then the tests and the
    # documentation, installing nothing again.  Before, `make test` installed .[test] and
    # `make docs` .[test,docs] again (sealsim's wheel rebuilt, everything resolved again).
    # Without CI, `make test` and `make docs` still install what each needs on their own.
    for name in ("Makefile", "pyproject.toml"):
        (tmp_path / name).write_bytes((REPO / name).read_bytes())
    bin_folder = tmp_path / ".venv" / "bin"
    bin_folder.mkdir(parents=True)
    log = tmp_path / "calls.log"
    python = bin_folder / "python"
    python.write_text(f'#!/bin/sh\necho "$*" >> "{log}"\n')
    python.chmod(0o755)
    ci = (REPO / ".ci" / "run").read_text(encoding="utf-8")
    ci_targets = [line.split()[1:] for line in ci.splitlines() if line.startswith("make ")]
    assert ci_targets[-2:] == [["test"], ["docs"]]
    for targets in ci_targets:
        _run_make(tmp_path, *targets)
    calls = log.read_text().splitlines()
    installs = [call for call in calls if call.startswith("-m pip install")]
    assert len(installs) == 1 and installs[0].endswith('-e .[test,docs]'), calls
    assert calls.index(installs[0]) == 0 and any(c.startswith("-m pytest") for c in calls)
    assert any(c.startswith("-m sphinx") for c in calls)
    # on their own, each target installs its extras: the README's `make test`, then `make docs`
    for stamp in (tmp_path / ".venv").glob(".sealsim*"):
        stamp.unlink()
    log.unlink()
    _run_make(tmp_path, "test")
    _run_make(tmp_path, "docs")
    installs = [c for c in log.read_text().splitlines() if c.startswith("-m pip install")]
    assert [i.rsplit(" ", 1)[-1] for i in installs] == [".[test]", ".[test,docs]"], installs
