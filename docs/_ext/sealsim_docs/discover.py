"""Find what the documentation describes by walking the installed ``sealsim`` package.

Nothing here is a hand-written list: a new module, case model or example file appears in the
documentation when it is added to the package or to ``examples/``.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import sys
import typing
import warnings
from pathlib import Path

from pydantic import BaseModel


def sealsim_modules() -> list[str]:
    """Names of all modules of the ``sealsim`` package, each imported once (sorted)."""
    import sealsim

    names = ["sealsim"]
    for info in pkgutil.walk_packages(sealsim.__path__, "sealsim."):
        names.append(info.name)
    for name in names:
        importlib.import_module(name)  # an import error must fail the build, not hide a page
    return sorted(names)


def _subclasses(cls: type) -> list[type]:
    found: list[type] = []
    for sub in cls.__subclasses__():
        found.append(sub)
        found.extend(_subclasses(sub))
    return list(dict.fromkeys(found))


def models_in(annotation) -> list[type[BaseModel]]:
    """Pydantic models named by a type annotation (through unions, lists, Annotated...)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    return [m for arg in typing.get_args(annotation) for m in models_in(arg)]


def _is_module_attribute(cls: type) -> bool:
    """Defined at the top of a sealsim module (not in a doctest or a function)."""
    module = sys.modules.get(cls.__module__)
    return (cls.__module__.startswith("sealsim")
            and getattr(module, cls.__qualname__, None) is cls)


def case_models() -> list[type[BaseModel]]:
    """Every top-level case model: a public ``CaseModel`` no other model uses as a field type,
    or one that ``sealsim.cases.CASE_KINDS`` registers.

    These are the documents a user writes (a rotary case, a friction fit, an entry of an oil
    file...); their tables are the sub-models reached through the fields.  Not documents:
    private helpers (``_Name``) and bases whose subclasses are all used as field types (the
    parameters base of the friction laws, whose subclasses are the forms of ``[friction]``).
    """
    from sealsim.cases import CaseModel

    sealsim_modules()
    models = _subclasses(CaseModel)
    used = {sub for m in models for f in m.model_fields.values() for sub in models_in(f.annotation)}

    def union_base(model) -> bool:
        subs = _subclasses(model)
        return bool(subs) and all(sub in used for sub in subs)

    # a registered case kind is a document even when another case embeds it (a rotary fit
    # case holds a rotary case as its [model])
    kinds = getattr(importlib.import_module("sealsim.cases"), "CASE_KINDS", ())
    registered = {getattr(kind, "model", None) for kind in kinds}
    roots = [m for m in models
             if (m not in used or f"{m.__module__}.{m.__qualname__}" in registered)
             and not m.__name__.startswith("_") and not union_base(m)
             and _is_module_attribute(m)]
    return sorted(roots, key=lambda m: (m.__module__, m.__name__))


def case_command(model: type[BaseModel]) -> str | None:
    """The command that runs a case model, if ``sealsim.cases.CASE_KINDS`` registers it."""
    kinds = getattr(importlib.import_module("sealsim.cases"), "CASE_KINDS", ())
    name = f"{model.__module__}.{model.__qualname__}"
    return next((kind.command for kind in kinds if getattr(kind, "model", None) == name), None)


def one_call_functions() -> list[tuple[str, object]]:
    """Functions exported by the package itself (``sealsim.NAME``), in ``__all__`` order."""
    import sealsim

    found = []
    for name in getattr(sealsim, "__all__", []):
        obj = getattr(sealsim, name, None)
        if inspect.isfunction(obj):
            found.append((name, obj))
    return found


def example_files(examples_dir: Path, suffix: str) -> list[Path]:
    """Files of ``examples/`` with this suffix, sorted, outside hidden folders."""
    return sorted(p for p in examples_dir.rglob(f"*{suffix}")
                  if not any(part.startswith(".") for part in p.relative_to(examples_dir).parts))


def classify_examples(examples_dir: Path,
                      models: list[type[BaseModel]]) -> dict[Path, list[type[BaseModel]]]:
    """For every example TOML file, the case models that accept it (validated, no run)."""
    from sealsim.cases import expand_variants, load_toml

    found = {}
    for path in example_files(examples_dir, ".toml"):
        data = load_toml(path)
        accepted = []
        for model in models:
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")  # e.g. "parameter set is not passive"
                    expand_variants(model, data, str(path))
            except Exception:  # noqa: BLE001 - not this kind (the test suite checks that every
                continue       # example is accepted by exactly one model)
            accepted.append(model)
        found[path] = accepted
    return found
