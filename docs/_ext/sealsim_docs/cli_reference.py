"""Command-line reference generated from the typer application.

The command tree is walked from ``typer.main.get_command(app)``; each command's section shows
its ``--help`` exactly as a terminal shows it (run through typer's test runner), so a new
command or option is documented as soon as it is registered, with nothing to keep in sync.
"""

from __future__ import annotations

from collections.abc import Iterator

from . import rst

WIDTH = 100  # columns of the rendered help, wide enough for the option tables


def commands(app) -> Iterator[tuple[list[str], object]]:
    """``(["rotary", "run"], command)`` for every visible command, depth first."""
    import typer

    root = typer.main.get_command(app)
    yield from _walk(root, [], root.make_context("sealsim", [], resilient_parsing=True))


def _walk(command, path: list[str], ctx) -> Iterator[tuple[list[str], object]]:
    yield path, command
    if not hasattr(command, "list_commands"):
        return
    for name in command.list_commands(ctx):
        sub = command.get_command(ctx, name)
        if sub is None or getattr(sub, "hidden", False):
            continue
        sub_ctx = sub.make_context(name, [], parent=ctx, resilient_parsing=True)
        yield from _walk(sub, [*path, name], sub_ctx)


def help_text(app, path: list[str]) -> str:
    """What ``sealsim PATH --help`` prints, without colour, ``WIDTH`` columns wide."""
    from typer.testing import CliRunner

    env = {"COLUMNS": str(WIDTH), "TERMINAL_WIDTH": str(WIDTH), "NO_COLOR": "1", "TERM": "dumb"}
    result = CliRunner().invoke(app, [*path, "--help"], prog_name="sealsim", env=env)
    if result.exit_code != 0:
        raise RuntimeError(f"'sealsim {' '.join(path)} --help' failed "
                           f"(exit {result.exit_code}):\n{result.output}")
    return result.output


def _summary(command) -> str:
    text = getattr(command, "short_help", None) or getattr(command, "help", None) or ""
    return text.strip().split("\n\n")[0].replace("\n", " ")


def page(app) -> str:
    """The CLI reference page: an overview table, then every command's help."""
    found = list(commands(app))
    rows = [[f":ref:`{rst.escape(' '.join(['sealsim', *path]))} <cli-{'-'.join(path)}>`",
             rst.escape(_summary(command))]
            for path, command in found if path and not hasattr(command, "list_commands")]
    out = [".. _cli-reference:\n", rst.title("Command line", "="),
           "Every command and option of ``sealsim``, generated from the command-line "
           "application itself: each section is the command's ``--help``.\n",
           rst.list_table(["Command", "What it does"], rows, widths=[30, 70])]
    for path, command in found:
        anchor = "-".join(path) or "sealsim"
        name = " ".join(["sealsim", *path])
        level = "-" if len(path) <= 1 else "~"
        out.append(f".. _cli-{anchor}:\n")
        out.append(rst.title(rst.literal(name), level))
        out.append(rst.literal_block(help_text(app, path)))
    return "\n".join(out)
