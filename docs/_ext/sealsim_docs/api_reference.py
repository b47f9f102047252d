"""Python API reference: one autodoc page per public module, found by walking the package.

Each object is documented once, on the page of the module that defines it; a package that
re-exports names (``from sealsim.properties import get_oil``) lists them with a link to that
page.  So a re-export never makes two targets of one name, and a function moved to another
module moves its documentation with it.
"""

from __future__ import annotations

import importlib
import inspect
from pathlib import Path

from . import rst


#: documented elsewhere: the command line has its own reference, generated from the app
EXCLUDED = ("sealsim.cli",)


def public(name: str) -> bool:
    """Modules with a page: no ``_private`` part in the name, not under :data:`EXCLUDED`."""
    return not any(part.startswith("_") for part in name.split(".")) and not any(
        name == e or name.startswith(e + ".") for e in EXCLUDED)


def _documented_data(module_name: str) -> set[str]:
    """Module-level names with a doc-comment (``#: ...`` above, or a string below them).

    Only these constants are documented: autodoc would show an undocumented constant with
    the docstring of its type (``dict``'s, for a table), which explains nothing.
    """
    from sphinx.pycode import ModuleAnalyzer

    try:
        docs = ModuleAnalyzer.for_module(module_name).find_attr_docs()
    except Exception:  # noqa: BLE001 - no source available: document no constants
        return set()
    return {name for (scope, name) in docs if scope == ""}


def members(module_name: str) -> tuple[list[tuple[str, str]], list[tuple[str, str]]]:
    """The module's public names split into ``(own, re-exported)`` lists of
    ``(name, directive)`` and ``(name, defining module)``.

    Public means listed in ``__all__`` or, without ``__all__``, not starting with ``_``.
    """
    module = importlib.import_module(module_name)
    names = list(getattr(module, "__all__", None) or
                 [n for n in vars(module) if not n.startswith("_")])
    documented = _documented_data(module_name)
    own, reexported = [], []
    for name in names:
        obj = getattr(module, name, None)
        if obj is None or inspect.ismodule(obj):
            continue  # submodules have their own pages
        if inspect.isclass(obj) or inspect.isroutine(obj):
            origin = getattr(obj, "__module__", None)
            if origin == module_name:
                kind = ("autoexception" if inspect.isclass(obj) and issubclass(obj, BaseException)
                        else "autoclass" if inspect.isclass(obj) else "autofunction")
                own.append((name, kind))
            elif origin and origin.startswith("sealsim"):
                reexported.append((name, f"{origin}.{obj.__qualname__}"))
        elif name in documented:
            own.append((name, "autodata"))
    return own, reexported


def module_page(name: str, children: list[str]) -> str:
    own, reexported = members(name)
    out = [rst.title(rst.literal(name)), f".. automodule:: {name}\n   :no-members:\n"]
    if children:
        out.append(".. toctree::\n   :maxdepth: 1\n\n" + "\n".join(f"   {c}" for c in children)
                   + "\n")
    if reexported:
        rows = [[rst.literal(n), f":py:obj:`{target}`"] for n, target in reexported]
        out.append(rst.title("Available here", "-"))
        out.append(f"Import these from ``{name}``; each is documented where it is defined.\n")
        out.append(rst.list_table(["Name", "Defined as"], rows, widths=[30, 70]))
    if own:
        out.append(rst.title("Reference", "-"))
    for member, directive in own:
        options = ("   :members:\n   :show-inheritance:\n"
                   "   :exclude-members: model_config, model_fields, model_computed_fields\n"
                   if directive in ("autoclass", "autoexception") else "")
        out.append(f".. {directive}:: {name}.{member}\n{options}")
    return "\n".join(out) + "\n"


def write(out_dir: Path, modules: list[str]) -> None:
    """``index.rst`` and one page per public module into ``out_dir``.

    The index lists the package and its top-level modules and subpackages; a subpackage's
    page lists its modules.
    """
    out_dir.mkdir(parents=True, exist_ok=True)
    names = [m for m in modules if public(m)]
    for name in names:
        children = [] if name == "sealsim" else [
            m for m in names if m.startswith(name + ".") and m.count(".") == name.count(".") + 1]
        (out_dir / f"{name}.rst").write_text(module_page(name, children), encoding="utf-8")
    top = [m for m in names if m.count(".") <= 1]
    (out_dir / "index.rst").write_text(
        ".. _api-reference:\n\n" + rst.title("Python API") +
        "\nThe public functions and classes of every module, from their docstrings: the "
        "equation and its source, every parameter with its unit, and an example.  Each object "
        "is documented in the module that defines it; packages list what they re-export.\n\n"
        ".. toctree::\n   :maxdepth: 2\n\n" + "".join(f"   {m}\n" for m in top),
        encoding="utf-8")


def one_call_section(functions: list[tuple[str, object]]) -> str:
    """A table of the top-level functions (empty text when the package exports none)."""
    if not functions:
        return ""
    rows = [[f":py:func:`sealsim.{name} <{f.__module__}.{f.__qualname__}>`",
             rst.escape((inspect.getdoc(f) or "").split("\n\n")[0].replace("\n", " "))]
            for name, f in functions]
    return (rst.title("One call from Python", "-") +
            "\nThese functions answer a question in one call, with quantities as strings "
            "with units:\n\n" + rst.list_table(["Function", "What it returns"], rows,
                                                widths=[30, 70]))
