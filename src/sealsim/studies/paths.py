"""Dotted paths into case data: ``seal.cord_diameter``, ``duty.steps.0.speed``,
``seals.rod.map.structure_case.seal.cord_diameter``.

A study names the case fields it changes by the path a user would write in the case file.
Parts are table keys; in a list a part is an index (``steps.0``) or the ``name`` of an element
(``seals.rod``).  A part after a field that names another case file -- today a pneumatic seal's
``map.structure_case`` -- continues inside that file (a *linked case*): the study changes the
linked case and every run gets its own copy of it.

Paths are resolved once, against the base case, into a :class:`Location`: which document (the
case or one linked case) and the key of every level, list names turned into indices.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sealsim.errors import InputError

__all__ = ["LINKED_CASE_FIELDS", "Location", "assign", "linked_documents", "resolve"]

#: fields whose value is the path of another case file, and the case model of that file
#: (module, class): a dotted path may continue inside the linked file
LINKED_CASE_FIELDS = {"structure_case": ("sealsim.structure.case", "StructureCase")}

#: key of the base case among the documents of a study
MAIN = ()


@dataclass(frozen=True)
class Location:
    """Where a dotted path points: ``document`` (``()`` for the case itself, else the keys of
    the field that links the file) and ``keys`` inside that document."""

    document: tuple
    keys: tuple

    def text(self) -> str:
        return ".".join(str(k) for k in (*self.document, *self.keys))


def _step(node: Any, part: str, walked: str, create: bool) -> tuple[Any, Any]:
    """The key of ``part`` inside ``node`` and the child it leads to (None if absent)."""
    if isinstance(node, dict):
        return part, node.get(part)
    if isinstance(node, list):
        if part.isdigit():
            index = int(part)
            if index >= len(node):
                raise InputError(f"'{walked}' has {len(node)} element{'s' * (len(node) != 1)}, "
                                 f"no index {index}")
            return index, node[index]
        names = [item.get("name") for item in node if isinstance(item, dict)]
        if part in names:
            index = names.index(part)
            return index, node[index]
        shown = ", ".join(repr(n) for n in names if n is not None)
        raise InputError(f"'{walked}' has no element named {part!r}"
                         + (f" (names: {shown})" if shown else "")
                         + "; give an index, e.g. '{walked}.0'".format(walked=walked))
    if create:
        return part, None
    raise InputError(f"'{walked}' is a value ({node!r}), not a table: '{part}' cannot follow it")


def resolve(path: str, documents: dict[tuple, dict]) -> Location:
    """Resolve a dotted ``path`` against the base case and its linked cases.

    Parameters
    ----------
    path : str
        Dotted path as written in a study file.
    documents : dict
        ``{MAIN: case data, link keys: linked case data}`` from :func:`linked_documents`.

    Raises
    ------
    InputError
        An empty part, an index out of range, no list element of that name, a path that
        continues below a plain value.  (A key that the case model does not know is found by
        validating the case with the value set, which names the allowed fields.)

    Examples
    --------
    >>> docs = {(): {"seals": [{"name": "piston"}, {"name": "rod", "map": {}}]}}
    >>> resolve("seals.rod.map.squeeze", docs)
    Location(document=(), keys=('seals', 1, 'map', 'squeeze'))
    """
    parts = path.split(".")
    if not path or any(not p.strip() for p in parts):
        raise InputError(f"path {path!r} has an empty part; write it like 'seal.cord_diameter'")
    document: tuple = MAIN
    node: Any = documents[MAIN]
    keys: list = []
    for k, part in enumerate(parts):
        walked = ".".join(parts[:k]) or "the case"
        key, child = _step(node, part, walked, create=node is None)
        keys.append(key)
        rest = parts[k + 1:]
        if rest and part in LINKED_CASE_FIELDS and isinstance(child, str):
            document = (*document, *keys)
            if document not in documents:
                raise InputError(f"'{'.'.join(parts[:k + 1])}' names a case file that was not "
                                 "loaded")
            node, keys = documents[document], []
            continue
        node = child
    return Location(document, tuple(keys))


def linked_documents(data: dict, base_dir: Path, source: str) -> tuple[dict[tuple, dict],
                                                                      dict[tuple, Path]]:
    """The case and every case file it links (``structure_case = "seal.toml"``), read.

    Returns ``({MAIN: data, link keys: linked data}, {link keys: file path})``.  Only one level:
    a linked case does not link further.
    """
    from sealsim.cases import load_toml

    documents: dict[tuple, dict] = {MAIN: data}
    files: dict[tuple, Path] = {}

    def walk(node: Any, keys: tuple) -> None:
        items = node.items() if isinstance(node, dict) else enumerate(node) \
            if isinstance(node, list) else ()
        for key, value in items:
            if key in LINKED_CASE_FIELDS and isinstance(value, str):
                path = Path(value)
                path = path if path.is_absolute() else base_dir / path
                try:
                    documents[(*keys, key)] = load_toml(path)
                except InputError as exc:
                    raise InputError(f"{source}: {'.'.join(map(str, (*keys, key)))}: {exc}") \
                        from None
                files[(*keys, key)] = path
            else:
                walk(value, (*keys, key))

    walk(data, ())
    return documents, files


def assign(documents: dict[tuple, dict], location: Location, value: Any) -> None:
    """Set ``value`` at ``location`` in ``documents`` (in place), creating missing tables.

    Examples
    --------
    >>> docs = {(): {"seal": {"d": "2 mm"}}}
    >>> assign(docs, Location((), ("oil", "name")), "VG32-mineral")
    >>> docs[()]
    {'seal': {'d': '2 mm'}, 'oil': {'name': 'VG32-mineral'}}
    """
    node = documents[location.document]
    *parents, last = location.keys
    for key in parents:
        if isinstance(node, dict) and not isinstance(node.get(key), dict | list):
            node[key] = {}
        node = node[key]
    node[last] = copy.deepcopy(value)
