"""Every concrete command the documentation quotes can be typed as written.

The README's commands are run by ``tests/test_readme.py``; the guides, physics pages and the
example files quote many more (``sealsim structure run examples/... --out ...`` next to the
numbers it measured, ``#   sealsim ...`` at the top of each example).  Running them all takes
hours, so here each one is parsed by the CLI itself: the command exists, every required option
is given (``--out``), every option is known and every ``examples/`` file it names exists.
Six quoted commands (seal_profiles.md, status.md, contact_friction.rst) lacked ``--out`` and
failed with "Missing option '--out'".
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
import typer

from sealsim.cli import app

REPO = Path(__file__).resolve().parents[1]

#: an inline code span (Markdown `...`, reStructuredText ``...``) or a line (code block,
#: TOML/Python comment) that starts with the program's name
_SPAN = re.compile(r"``((?:sealsim|python) [^`]+)``|`((?:sealsim|python) [^`]+)`")
_LINE = re.compile(r"^\s*(?:#\s*)?((?:sealsim|python) \S.*)$")


def _documents() -> list[Path]:
    docs = [p for p in sorted((REPO / "docs").rglob("*")) if p.suffix in (".md", ".rst")
            and not {"_build", "_generated"} & set(p.parts)]
    examples = [p for p in sorted((REPO / "examples").rglob("*")) if p.suffix in (".toml", ".py")]
    return [REPO / "README.md", *docs, *examples]


def quoted_commands() -> list[tuple[str, str]]:
    """``(place, command)`` of every command that names a file under ``examples/``."""
    found = []
    for path in _documents():
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            commands = [a or b for a, b in _SPAN.findall(line)]
            if not commands and (match := _LINE.match(line)):
                commands = [match.group(1).split("  #", 1)[0]]
            for command in commands:
                command = command.strip().rstrip(".,;:)")
                if "examples/" in command:  # placeholders (CASE.toml, DIR) are synopses
                    found.append((f"{path.relative_to(REPO)}:{number}", command))
    return found


def parse_command_line(args: list[str]) -> None:
    """Parse ``sealsim ARGS`` as the CLI would, without running the command.

    Raises the CLI's usage error (unknown option, missing required option, bad value) or an
    AssertionError naming an unknown command.
    """
    command, name, rest = typer.main.get_command(app), "sealsim", list(args)
    while hasattr(command, "get_command"):  # a group: the next word names its subcommand
        context = command.make_context(name, [], resilient_parsing=True)
        assert rest, f"{' '.join(args)}: no subcommand of {name!r}"
        name, rest = rest[0], rest[1:]
        sub = command.get_command(context, name)
        assert sub is not None, f"{' '.join(args)}: no command {name!r}"
        command = sub
    command.make_context(name, rest)


COMMANDS = quoted_commands()


def test_the_documents_quote_commands():
    # the extraction itself: the demo's command, a guide's inline one and an example header
    places = {place.split(":")[0] for place, _ in COMMANDS}
    assert {"docs/getting_started.rst", "docs/guide/calibration.md",
            "examples/rotary/speed_cycle.toml"} <= places
    assert len(COMMANDS) > 40


@pytest.mark.parametrize("place, command", COMMANDS, ids=[p for p, _ in COMMANDS])
def test_quoted_command_parses_and_its_files_exist(place, command, monkeypatch):
    monkeypatch.chdir(REPO)
    words = shlex.split(command)
    for word in words:
        if word.startswith("examples/"):
            assert (REPO / word).exists(), f"{place}: {command}: {word} does not exist"
    if words[0] == "sealsim":
        parse_command_line(words[1:])
