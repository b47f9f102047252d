"""The cache of FE characteristic maps built on demand: list it, clear it.

A seal whose contact map comes from a structure case (``map = { structure_case = ... }``)
gets its FE map built once and stored as ``<case stem>-<hash16>.nc`` in the cache folder
(:func:`~sealsim.pneumatic.contact_maps.default_cache_dir`: ``$SEALSIM_CACHE/maps``, else
``$XDG_CACHE_HOME/sealsim/maps``, else ``~/.cache/sealsim/maps``); the hash is that of the
resolved structure case and of the FE model's fingerprint
(:func:`sealsim.structure.fingerprint.model_fingerprint`), so a changed case or a changed FE
model gets a new file and old ones are never read again (``sealsim cache clear`` removes them).
Maps are a few hundred kB each; removing one only means it is built again when needed.

Only files this cache writes are touched: ``*.nc`` maps, the temporary files of interrupted
writes (``.NAME.nc.*.tmp``) and the finished FE load paths of builds that were interrupted
(folders ``.NAME.nc.paths``, :func:`~sealsim.pneumatic.contact_maps.kept_paths_folder`: the
next build of that map reuses them); :func:`clear_cached_maps` removes the last two once they
are an hour old (a map being built or written right now is never removed half-way).
"""

from __future__ import annotations

import os
import shutil
import time
from dataclasses import dataclass
from pathlib import Path

from sealsim.errors import InputError
from sealsim.pneumatic.contact_maps import default_cache_dir

__all__ = ["STALE_TEMPORARY_AGE", "CachedMap", "cache_folder", "clear_cached_maps",
           "list_cached_maps"]

#: Age after which a temporary file of an interrupted map write, or the kept load paths of an
#: interrupted build, are removed by a clear [s] (writing a map takes well under a second; a
#: build keeps a load path every few seconds to minutes).
STALE_TEMPORARY_AGE = 3600.0


@dataclass(frozen=True)
class CachedMap:
    """One file of the map cache.

    Attributes
    ----------
    path : Path
        The file.
    size : int
        Size [bytes].
    modified : float
        When it was written [s since the epoch].
    complete : bool
        False for a temporary file left by an interrupted write, or the folder of the kept
        load paths of an interrupted build (size: its files', modified: its newest file's).
    """

    path: Path
    size: int
    modified: float
    complete: bool = True

    def age(self, now: float | None = None) -> float:
        """Time since it was written [s]."""
        return (time.time() if now is None else now) - self.modified


def cache_folder(cache_dir: str | Path | None = None) -> Path:
    """The cache folder: ``cache_dir``, or the default one; a file at its place or at the
    place of one of its parents (``$SEALSIM_CACHE`` naming a file) is refused."""
    folder = Path(cache_dir) if cache_dir is not None else default_cache_dir()
    existing = next((p for p in (folder, *folder.parents) if p.exists()), None)
    if existing is not None and not existing.is_dir():
        given = "" if cache_dir is not None or "SEALSIM_CACHE" not in os.environ else \
            " ($SEALSIM_CACHE/maps)"
        raise InputError(f"map cache {str(folder)!r}{given} is not a folder" + (
            f": {str(existing)!r} is a file" if existing != folder else ""))
    return folder


def list_cached_maps(cache_dir: str | Path | None = None) -> list[CachedMap]:
    """The maps in the cache (and leftovers of interrupted writes), newest first.

    Parameters
    ----------
    cache_dir : path, optional
        Cache folder; default :func:`~sealsim.pneumatic.contact_maps.default_cache_dir`.
        A folder that does not exist is an empty cache.

    Returns
    -------
    list of CachedMap
    """
    folder = cache_folder(cache_dir)
    if not folder.is_dir():
        return []
    found = []
    for pattern, complete in (("*.nc", True), (".*.nc.*.tmp", False)):
        for path in folder.glob(pattern):
            try:
                stat = path.stat()
            except FileNotFoundError:  # removed meanwhile (another clear)
                continue
            if path.is_file():
                found.append(CachedMap(path, stat.st_size, stat.st_mtime, complete))
    for path in folder.glob(".*.nc.paths"):
        if path.is_dir() and not path.is_symlink():
            found.append(_kept_paths(path))
    return sorted(found, key=lambda m: (-m.modified, m.path.name))


def _kept_paths(path: Path) -> CachedMap:
    """The kept load paths of an interrupted build: their total size, the newest one's time."""
    size, modified = 0, path.stat().st_mtime
    for entry in path.iterdir():
        try:
            stat = entry.stat()
        except FileNotFoundError:
            continue
        size += stat.st_size
        modified = max(modified, stat.st_mtime)
    return CachedMap(path, size, modified, complete=False)


def clear_cached_maps(cache_dir: str | Path | None = None, older_than: float | None = None,
                      dry_run: bool = False, now: float | None = None) -> list[CachedMap]:
    """Remove cached maps, all of them or those written more than ``older_than`` ago.

    Temporary files of interrupted writes and the kept load paths of interrupted builds are
    removed when they are older than both ``older_than`` and :data:`STALE_TEMPORARY_AGE`.

    Parameters
    ----------
    cache_dir : path, optional
        Cache folder; default :func:`~sealsim.pneumatic.contact_maps.default_cache_dir`.
    older_than : float, optional
        Keep maps written within this time [s]; ``None``: remove every map.
    dry_run : bool
        Only say what would be removed.
    now : float, optional
        The current time [s since the epoch] (for tests).

    Returns
    -------
    list of CachedMap
        The files removed (or that would be removed).

    Raises
    ------
    InputError
        ``older_than`` negative or not finite; a file that cannot be removed (named).
    """
    if older_than is not None and not (older_than >= 0 and older_than < float("inf")):
        raise InputError(f"older_than: {older_than!r} s must be a finite time >= 0")
    now = time.time() if now is None else now
    removed = []
    for entry in list_cached_maps(cache_dir):
        limit = older_than or 0.0
        if not entry.complete:
            limit = max(limit, STALE_TEMPORARY_AGE)
        if (older_than is not None or not entry.complete) and entry.age(now) <= limit:
            continue
        if not dry_run:
            try:
                if entry.path.is_dir():
                    shutil.rmtree(entry.path)
                else:
                    entry.path.unlink(missing_ok=True)
            except FileNotFoundError:  # removed meanwhile (another clear, the build's end)
                pass
            except OSError as exc:
                raise InputError(f"cannot remove {str(entry.path)!r} from the map cache: "
                                 f"{exc.strerror or exc}") from None
        removed.append(entry)
    return removed
