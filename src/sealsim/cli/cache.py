"""``sealsim cache ...``: list and clear the cache of FE maps built on demand."""

from __future__ import annotations

import datetime
from pathlib import Path

import typer
from rich import box
from rich.table import Table
from rich.text import Text

from sealsim.cli._common import console, guarded, print_json
from sealsim.errors import InputError

__all__ = ["cache_app"]

cache_app = typer.Typer(no_args_is_help=True, help=(
    "The cache of FE characteristic maps that pneumatic and fit cases build on demand "
    "(map = { structure_case = ... }): $SEALSIM_CACHE/maps, else ~/.cache/sealsim/maps."))

CACHE_DIR_OPTION = typer.Option(None, "--cache-dir", help="Cache folder (default: "
                                "$SEALSIM_CACHE/maps, $XDG_CACHE_HOME/sealsim/maps or "
                                "~/.cache/sealsim/maps).")


def _when(timestamp: float) -> str:
    return datetime.datetime.fromtimestamp(timestamp).isoformat(sep=" ", timespec="seconds")


def _age(seconds: float) -> str:
    for unit, size in (("d", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.1f} {unit}"
    return f"{max(seconds, 0.0):.0f} s"


@cache_app.command("list")
@guarded
def cache_list(json: bool = typer.Option(False, "--json", help="Print JSON instead of a table."),
               cache_dir: Path | None = CACHE_DIR_OPTION) -> None:
    """List the cached maps, newest first: file, size, when it was built.

    --json prints an object with cache_dir and maps, a list of objects with the keys file,
    size_bytes, modified (ISO time), age_s and complete (false: left by an interrupted write).
    """
    from sealsim.pneumatic.map_cache import cache_folder, list_cached_maps

    folder = cache_folder(cache_dir)
    maps = list_cached_maps(folder)
    if json:
        print_json({"cache_dir": str(folder), "maps": [
            {"file": m.path.name, "size_bytes": m.size, "modified": _when(m.modified),
             "age_s": round(m.age(), 1), "complete": m.complete} for m in maps]})
        return
    total = sum(m.size for m in maps)
    console.print(Text(f"map cache {folder}: {len(maps)} file(s), {total / 1e6:.2f} MB"))
    if not maps:
        return
    table = Table(box=box.SIMPLE_HEAD)
    for header, justify in (("file", "left"), ("size [kB]", "right"), ("built", "left"),
                            ("age", "right")):
        table.add_column(Text(header), justify=justify)
    for m in maps:
        name = m.path.name + ("" if m.complete else " (incomplete)")
        table.add_row(Text(name), f"{m.size / 1e3:.0f}", _when(m.modified), _age(m.age()))
    console.print(table)


@cache_app.command("clear")
@guarded
def cache_clear(
    older_than: str | None = typer.Option(
        None, "--older-than", help="Remove only maps built more than this long ago, with a "
        "unit: '30 days', '12 h', '2 weeks'."),
    dry_run: bool = typer.Option(False, "--dry-run", help="Only list what would be removed."),
    cache_dir: Path | None = CACHE_DIR_OPTION,
) -> None:
    """Remove cached maps (all, or those older than --older-than).

    A removed map is built again the next time a case needs it. Only the cache's own files
    are touched (*.nc maps, stale temporary files of interrupted writes).
    """
    from sealsim.pneumatic.map_cache import cache_folder, clear_cached_maps
    from sealsim.units import parse_quantity

    age = None if older_than is None else parse_quantity(older_than, "time", "--older-than")
    if age is not None and not age >= 0:
        raise InputError(f"--older-than: {older_than!r} is negative; give an age >= 0, "
                         "e.g. '30 days'")
    folder = cache_folder(cache_dir)
    removed = clear_cached_maps(folder, older_than=age, dry_run=dry_run)
    verb = "would remove" if dry_run else "removed"
    console.print(Text(f"{verb} {len(removed)} file(s), "
                       f"{sum(m.size for m in removed) / 1e6:.2f} MB, from {folder}"))
    for m in removed:
        console.print(Text(f"  {m.path.name}"))
