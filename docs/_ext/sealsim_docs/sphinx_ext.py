"""Sphinx extension: docstrings written for engineers read as they are meant.

* A constant's doc-comment is shown as written (napoleon does not parse it).
* A pydantic model is shown without its constructor signature (the field validators).
* ``|v|`` in a docstring is an absolute value, not a reST substitution: bars in prose are
  escaped before the docstring is parsed (not in literals, math, code or doctest blocks).
* A reference by a public import path (``sealsim.properties.get_oil``) links to the object's
  documentation in the module that defines it, so references survive moving code between
  modules as long as the public name stays.
* An ambiguous short name resolves the way Python does: ``seals : list of Seal`` in
  ``sealsim.pneumatic.simulation`` means the ``Seal`` that module imports
  (``sealsim.pneumatic.seals.Seal``), not ``sealsim.rotary.case.Seal``.  Sphinx's fuzzy search
  finds both and warns; this picks the object the name is bound to in the referring module,
  else the one sharing the longest package prefix with it.
"""

from __future__ import annotations

import importlib
import re
import sys

from sphinx.domains.python import PythonDomain

_find_obj = PythonDomain.find_obj


def _bound_name(modname: str | None, name: str) -> str | None:
    module = sys.modules.get(modname or "")
    obj = getattr(module, name.split(".")[-1], None) if module else None
    if obj is None or not hasattr(obj, "__qualname__"):
        return None
    return f"{getattr(obj, '__module__', '')}.{obj.__qualname__}"


def _common_prefix(a: str, b: str) -> int:
    n = 0
    for x, y in zip(a.split("."), b.split(".")):
        if x != y:
            break
        n += 1
    return n


def find_obj(self, env, modname, classname, name, type, searchmode=0):  # noqa: A002
    matches = _find_obj(self, env, modname, classname, name, type, searchmode)
    if len(matches) <= 1 or not modname:
        return matches
    bound = _bound_name(modname, name)
    exact = [m for m in matches if m[0] == bound]
    if len(exact) == 1:
        return exact
    best = max(_common_prefix(modname, m[0]) for m in matches)
    closest = [m for m in matches if _common_prefix(modname, m[0]) == best]
    return closest if len(closest) == 1 else matches


_BACKTICKS = re.compile(r"(`+[^`]*`+)")


def escape_bars(lines: list[str]) -> None:
    """Escape ``|`` in prose lines in place; blocks (``::``, directives, doctests) are kept."""
    block_indent = None   # indentation of the line that opened a literal/directive block
    in_doctest = False
    for k, line in enumerate(lines):
        stripped = line.strip()
        indent = len(line) - len(line.lstrip())
        if block_indent is not None:
            if not stripped or indent > block_indent:
                continue
            block_indent = None
        if in_doctest:
            if stripped:
                continue
            in_doctest = False
        if stripped.startswith(">>>"):
            in_doctest = True
            continue
        if stripped.endswith("::") or stripped.startswith(".. "):
            block_indent = indent
        if "|" in line and not stripped.startswith(".. "):
            parts = _BACKTICKS.split(line)
            lines[k] = "".join(part.replace("|", "\\|") if i % 2 == 0 else part
                               for i, part in enumerate(parts))


def _import_dotted(path: str):
    """The object a dotted path names (``sealsim.properties.get_oil``), or None."""
    parts = path.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        try:
            for attr in parts[cut:]:
                obj = getattr(obj, attr)
        except AttributeError:
            return None
        return obj
    return None


def _resolve_public_path(app, env, node, contnode):
    """``missing-reference``: follow a re-export to where the object is documented."""
    target = node.get("reftarget", "")
    if node.get("refdomain") != "py" or not target.startswith("sealsim."):
        return None
    obj = _import_dotted(target)
    module, qualname = getattr(obj, "__module__", None), getattr(obj, "__qualname__", None)
    if not (module and qualname) or f"{module}.{qualname}" == target:
        return None
    return env.get_domain("py").resolve_xref(env, node["refdoc"], app.builder, node["reftype"],
                                            f"{module}.{qualname}", node, contnode)


_held: dict[str, list[str]] = {}


def _hide_from_napoleon(app, what, name, obj, options, lines):
    """Runs before napoleon: a constant's doc-comment is prose, but napoleon would read
    ``Thinnest film [m]: 0.02 µm ...`` as "type: description"."""
    if what in ("data", "attribute"):
        _held[name] = lines[:]
        lines[:] = []


def _process_docstring(app, what, name, obj, options, lines):
    if name in _held:
        lines[:] = _held.pop(name)
    escape_bars(lines)
    from sealsim.cases import CaseModel

    if what == "class" and isinstance(obj, type) and issubclass(obj, CaseModel):
        lines.extend(["", "Its fields, with units, defaults and ranges, are listed in the "
                      ":doc:`case-file reference </case_files>`."])


def _model_signature(app, what, name, obj, options, signature, return_annotation):
    """No constructor signature for pydantic models: it would spell out every validator of
    every field; the fields are listed in the case-file reference."""
    from pydantic import BaseModel

    if what == "class" and isinstance(obj, type) and issubclass(obj, BaseModel):
        return "", None
    return None


def setup(app):
    PythonDomain.find_obj = find_obj
    app.connect("autodoc-process-docstring", _hide_from_napoleon, priority=100)
    app.connect("autodoc-process-docstring", _process_docstring, priority=900)
    app.connect("missing-reference", _resolve_public_path)
    app.connect("autodoc-process-signature", _model_signature)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
