"""The FE map cache: sealsim.pneumatic.map_cache and sealsim cache list|clear."""

from __future__ import annotations

import json
import os
import time

import pytest
from typer.testing import CliRunner

from sealsim.cli import app
from sealsim.errors import InputError
from sealsim.pneumatic.contact_maps import default_cache_dir
from sealsim.pneumatic.map_cache import (
    STALE_TEMPORARY_AGE,
    cache_folder,
    clear_cached_maps,
    list_cached_maps,
)

DAY = 86400.0


@pytest.fixture
def cache(tmp_path):
    """A cache with maps of age 0, 2 and 10 days, a fresh and a stale temporary file, and a
    file that is not the cache's."""
    folder = tmp_path / "maps"
    folder.mkdir()
    now = time.time()
    for name, age in (("a-0000000000000000.nc", 0.0), ("b-1111111111111111.nc", 2 * DAY),
                      ("c-2222222222222222.nc", 10 * DAY), (".d.nc.x1.tmp", 60.0),
                      (".e.nc.x2.tmp", 2 * STALE_TEMPORARY_AGE), ("notes.txt", 30 * DAY)):
        path = folder / name
        path.write_bytes(b"x" * 100)
        os.utime(path, (now - age, now - age))
    return folder, now


def test_list_newest_first_with_incomplete_writes(cache):
    folder, now = cache
    maps = list_cached_maps(folder)
    assert [m.path.name for m in maps] == ["a-0000000000000000.nc", ".d.nc.x1.tmp",
                                           ".e.nc.x2.tmp", "b-1111111111111111.nc",
                                           "c-2222222222222222.nc"]
    assert [m.complete for m in maps] == [True, False, False, True, True]
    assert maps[3].age(now) == pytest.approx(2 * DAY, abs=1.0) and maps[0].size == 100
    assert list_cached_maps(folder / "missing") == []  # no cache yet: empty


def test_clear_older_than_keeps_recent_maps_and_writes_in_progress(cache):
    folder, now = cache
    dry = clear_cached_maps(folder, older_than=DAY, dry_run=True, now=now)
    assert len(list(folder.iterdir())) == 6  # a dry run removes nothing
    removed = clear_cached_maps(folder, older_than=DAY, now=now)
    assert [m.path.name for m in removed] == [m.path.name for m in dry] == [
        "b-1111111111111111.nc", "c-2222222222222222.nc"]
    removed = clear_cached_maps(folder, now=now)  # everything the cache owns ...
    assert [m.path.name for m in removed] == ["a-0000000000000000.nc", ".e.nc.x2.tmp"]
    # ... but a temporary file that may still be written, and foreign files, stay
    assert sorted(p.name for p in folder.iterdir()) == [".d.nc.x1.tmp", "notes.txt"]
    with pytest.raises(InputError, match="older_than"):
        clear_cached_maps(folder, older_than=float("nan"))


def test_default_folder_follows_sealsim_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("SEALSIM_CACHE", str(tmp_path))
    assert cache_folder() == default_cache_dir() == tmp_path / "maps"
    (tmp_path / "file").write_text("")
    with pytest.raises(InputError, match="not a folder"):
        cache_folder(tmp_path / "file")
    # SEALSIM_CACHE naming a file: 'cache list' showed an empty cache at FILE/maps
    monkeypatch.setenv("SEALSIM_CACHE", str(tmp_path / "file"))
    with pytest.raises(InputError, match=r"maps' \(\$SEALSIM_CACHE/maps\) is not a folder: "
                                         r"'.*file' is a file"):
        cache_folder()


def test_cli_list_and_clear(cache, monkeypatch):
    folder, _ = cache
    monkeypatch.setenv("SEALSIM_CACHE", str(folder.parent))
    runner = CliRunner()
    listed = runner.invoke(app, ["cache", "list", "--json"])
    assert listed.exit_code == 0, listed.output
    data = json.loads(listed.stdout)
    assert data["cache_dir"] == str(folder) and len(data["maps"]) == 5
    table = " ".join(runner.invoke(app, ["cache", "list"]).stdout.split())
    assert "5 file(s)" in table and "b-1111111111111111.nc" in table and "(incomplete)" in table
    cleared = runner.invoke(app, ["cache", "clear", "--older-than", "1 week"])
    assert cleared.exit_code == 0 and "removed 1 file(s)" in cleared.stdout
    assert not (folder / "c-2222222222222222.nc").exists()
    bad = runner.invoke(app, ["cache", "clear", "--older-than", "7"])
    assert bad.exit_code == 2 and "no unit" in bad.output  # 7 what? days, hours?
    # a negative age named the function's argument in seconds ('older_than: -432000.0 s')
    bad = runner.invoke(app, ["cache", "clear", "--older-than", "-5 days"])
    assert bad.exit_code == 2
    assert "--older-than: '-5 days' is negative; give an age >= 0" in " ".join(bad.output.split())
    assert (folder / "a-0000000000000000.nc").exists()


def test_kept_paths_of_interrupted_builds_are_listed_and_cleared_once_stale(tmp_path):
    # the finished FE load paths an interrupted on-demand build keeps (.NAME.nc.paths) were
    # invisible to 'cache list' and never removed by 'cache clear'
    now = time.time()
    for name, age in ((".a-0000000000000000.nc.paths", 60.0),
                      (".b-1111111111111111.nc.paths", 2 * STALE_TEMPORARY_AGE)):
        kept = tmp_path / name
        kept.mkdir()
        for k in range(2):
            (kept / f"{k}.json").write_bytes(b"x" * 50)
            os.utime(kept / f"{k}.json", (now - age - k, now - age - k))
        os.utime(kept, (now - 10 * DAY, now - 10 * DAY))    # the folder's time is not used
    maps = list_cached_maps(tmp_path)
    assert [(m.path.name, m.size, m.complete) for m in maps] == [
        (".a-0000000000000000.nc.paths", 100, False),
        (".b-1111111111111111.nc.paths", 100, False)]
    assert maps[0].age(now) == pytest.approx(60.0, abs=1.0)   # its newest path
    removed = clear_cached_maps(tmp_path, now=now)
    assert [m.path.name for m in removed] == [".b-1111111111111111.nc.paths"]
    assert [p.name for p in tmp_path.iterdir()] == [".a-0000000000000000.nc.paths"]
