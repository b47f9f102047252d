"""Helpers shared by the CLI commands: consoles, error handling, JSON output."""

from __future__ import annotations

import functools
import json
import logging
import math
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import typer
from rich.console import Console
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
from rich.text import Text

from sealsim.errors import SealsimError, Terminated
from sealsim.output import JSON_DIGITS, committed_folders, json_ready
from sealsim.units import ZERO_CELSIUS_K

console = Console(highlight=False)
err_console = Console(stderr=True, highlight=False)


def guarded(func):
    """Turn sealsim errors into one printed message and the documented exit status.

    Bad input exits with 2, a failed model or an unwritable file with 1 (an ``OSError`` no
    sealsim code anticipated is reported the same way, naming the file).  Ctrl-C (130) and
    SIGTERM (143) say truthfully whether new results had already been committed.
    """

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        committed_before = len(committed_folders())
        try:
            return func(*args, **kwargs)
        except SealsimError as exc:
            _fail(*error_parts(exc))
            raise typer.Exit(exc.exit_code) from None
        except OSError as exc:
            where = f" {exc.filename!r}" if exc.filename else ""
            _fail("error", f"cannot access{where}: {exc.strerror or exc}")
            raise typer.Exit(1) from None
        except KeyboardInterrupt as exc:
            written = committed_folders()[committed_before:]
            what = "terminated (SIGTERM)" if isinstance(exc, Terminated) else "interrupted"
            if written:
                text = (f"{what} after the results were written: "
                        f"{', '.join(str(p) for p in written)} holds the complete new results")
            else:
                text = f"{what}: no results were written; the --out folder or file is unchanged"
            err_console.print(Text(text, style="bold red"))
            raise typer.Exit(getattr(exc, "exit_code", 130)) from None

    return wrapper


def error_parts(exc: SealsimError) -> tuple[str, str]:
    """(kind, message) of a sealsim error as the CLI prints it ("input error: ..."); the app
    shows the same text."""
    return ("input error" if exc.exit_code == 2 else "error"), str(exc)


def _fail(kind: str, message: str) -> None:
    err_console.print(Text(f"{kind}: ", style="bold red") + Text(message))


def print_json(data: Any) -> None:
    """Print JSON to stdout (plain text, no rich markup); NaN is written as null, floats with
    :data:`~sealsim.files.JSON_DIGITS` significant digits (32.0, not 31.999999999999808), as
    in the result files."""
    typer.echo(json.dumps(json_ready(data, JSON_DIGITS), indent=2))


def parse_celsius_list(text: str | None, default: list[float], option: str) -> list[float]:
    """Parse a comma-separated list of temperatures in °C (``"20,40,100"``); an item may carry
    its own temperature unit (``"-20 degC, 300 K, 212 degF"``)."""
    from sealsim.errors import InputError
    from sealsim.units import parse_quantity

    if text is None:
        return default
    values = []
    for part in text.split(","):
        try:
            value = float(part)
        except ValueError:
            try:
                value = parse_quantity(part.strip(), "temperature") - ZERO_CELSIUS_K
            except InputError:
                raise InputError(f"{option}: {part.strip()!r} is not a temperature; give "
                                 "numbers in degC separated by commas, e.g. '20,40,100', or "
                                 "each with its unit, e.g. '-20 degC, 300 K'") from None
        if not math.isfinite(value) or value < -ZERO_CELSIUS_K:
            raise InputError(f"{option}: {value!r} degC is not a valid temperature "
                             "(must be finite and >= -273.15 degC)")
        values.append(value)
    return values


class _NoticeHandler(logging.Handler):
    """Prints log records on stderr (above a running progress bar)."""

    def emit(self, record: logging.LogRecord) -> None:
        err_console.print(Text(self.format(record), style="cyan"))


@contextmanager
def sealsim_notices(quiet: bool) -> Iterator[None]:
    """Show the INFO records of the ``sealsim`` loggers on stderr while the block runs (e.g.
    "building FE map for seal 'rod' ..., cached at ..." before a long FE computation)."""
    if quiet:
        yield
        return
    logger = logging.getLogger("sealsim")
    handler, level = _NoticeHandler(logging.INFO), logger.level
    logger.addHandler(handler)
    if logger.getEffectiveLevel() > logging.INFO:
        logger.setLevel(logging.INFO)
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.setLevel(level)


@contextmanager
def variant_progress(label: str, quiet: bool,
                     describe: Callable[[str, float, float], str]
                     ) -> Iterator[Callable[[str, float, float], None]]:
    """A progress bar (on stderr) with one task per variant of a case, and the notices of
    :func:`sealsim_notices` above it.

    Yields ``progress(variant, done, total)`` for the study runners; ``describe`` renders the
    text after the bar, e.g. ``"12/90 min"``.
    """
    with sealsim_notices(quiet), Progress(
            TextColumn("{task.description}"), BarColumn(), TextColumn("{task.fields[t]}"),
            TimeElapsedColumn(), console=err_console, disable=quiet, transient=True) as bar:
        tasks: dict[str, Any] = {}

        def progress(variant: str, done: float, total: float) -> None:
            if variant not in tasks:
                tasks[variant] = bar.add_task(f"{label} {variant}", total=total, t="")
            # the total may change (a second seal's FE map reports under the same name)
            bar.update(tasks[variant], completed=done, total=total,
                       t=describe(variant, done, total))

        yield progress


def print_notes(notes: list[str], indent: str = "  ", label: str = "note") -> None:
    """Print a run's notes as written (library text is not rich markup)."""
    for note in notes:
        console.print(Text(f"{indent}{label}: ", style="yellow") + Text(note))


def notes_of_every_variant(notes_by_variant: dict[str, list[str]]) -> list[str]:
    """The notes every variant of a case has (in the first variant's order): printed once
    after the variants instead of under each (a case of four temperatures repeated the
    parameter set's four-line note four times)."""
    lists = list(notes_by_variant.values())
    if len(lists) < 2:
        return []
    return [n for n in lists[0] if all(n in other for other in lists[1:])]
