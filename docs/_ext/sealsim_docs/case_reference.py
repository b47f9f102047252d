"""Field reference of the case files, generated from the pydantic case models.

Every table of a case file is a section listing its fields: name, type (with the physical
dimension of a quantity and an example unit), default as it would be written in the file, and
the allowed range and description.  The models are found by :func:`discover.case_models`, so a
new case model or field is documented when it is added to the code.
"""

from __future__ import annotations

import inspect
import re
import types
import typing
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal

import tomli_w
from pydantic import BaseModel, TypeAdapter, WithJsonSchema
from pydantic.fields import FieldInfo

from . import rst
from .discover import case_command, models_in

# annotated-types constraint -> (its attribute, how it reads)
_BOUNDS = {"Gt": ("gt", ">"), "Ge": ("ge", ">="), "Lt": ("lt", "<"), "Le": ("le", "<="),
           "MinLen": ("min_length", "length at least"), "MaxLen": ("max_length", "length at most")}


def case_title(model: type[BaseModel]) -> str:
    """``RotaryCase`` -> ``Rotary case``; ``FrictionFitCase`` -> ``Friction fit case``."""
    words = re.findall(r"[A-Z]+(?![a-z])|[A-Z][a-z0-9]*|[a-z0-9]+", model.__name__)
    return " ".join([words[0]] + [w if w.isupper() else w.lower() for w in words[1:]])


def page_name(model: type[BaseModel]) -> str:
    """File name (without suffix) of the reference page of a case model."""
    return f"{model.__module__}.{model.__name__}".removeprefix("sealsim.").replace(".", "-")


# -- types ------------------------------------------------------------------------------------
def _quantity(annotation) -> str | None:
    """The JSON-schema description of a ``Q(...)`` quantity type, else None."""
    if typing.get_origin(annotation) is Annotated:
        for meta in typing.get_args(annotation)[1:]:
            if isinstance(meta, WithJsonSchema) and meta.json_schema:
                return meta.json_schema.get("description")
    return None


def _split_quantity(description: str) -> tuple[str, str]:
    """``"length, e.g. '80 mm'; > 0 mm"`` -> (type text, allowed range text)."""
    head, _, bounds = description.partition("; ")
    name, _, example = head.partition(", e.g. ")
    type_text = f"quantity: {name}"
    if example:
        type_text += f", e.g. {rst.literal(example.strip(chr(39)))}"
    return type_text, bounds


def _is_none(annotation) -> bool:
    return annotation is type(None)


def _union_members(annotation) -> list:
    origin = typing.get_origin(annotation)
    if origin is typing.Union or origin is types.UnionType:
        return list(typing.get_args(annotation))
    return [annotation]


def _strip_annotated(annotation):
    while typing.get_origin(annotation) is Annotated:
        annotation = typing.get_args(annotation)[0]
    return annotation


def type_text(annotation) -> tuple[str, str]:
    """reST text of a field type and of the range a quantity type allows."""
    quantity = _quantity(annotation)
    if quantity is not None:
        return _split_quantity(quantity)
    if typing.get_origin(annotation) is Annotated:  # e.g. Annotated[int, Field(ge=1)]
        base, *metadata = typing.get_args(annotation)
        text, bounds = type_text(base)
        return text, ", ".join(b for b in (bounds, _bounds_text(metadata)) if b)
    members = [m for m in _union_members(annotation) if not _is_none(m)]
    if len(members) > 1:
        if all(models_in(m) and isinstance(_strip_annotated(m), type) for m in members):
            return "table (one of the forms below)", ""
        texts = [type_text(m) for m in members]
        return " or ".join(t for t, _ in texts), "; ".join(b for _, b in texts if b)
    if members and members[0] is not annotation:
        return type_text(members[0])  # Optional[X]: X (the default says "not set")
    origin = typing.get_origin(annotation)
    if origin is Literal:
        return " | ".join(rst.literal(toml_value(v)) for v in typing.get_args(annotation)), ""
    if origin in (list, tuple, set, frozenset):
        args = [a for a in typing.get_args(annotation) if a is not Ellipsis]
        inner, bounds = type_text(args[0]) if args else ("value", "")
        return ("list of tables" if inner.startswith("table") else f"list of {inner}"), bounds
    if origin is dict:
        args = typing.get_args(annotation)
        inner, bounds = type_text(args[1]) if len(args) == 2 else ("value", "")
        return ("tables, one per name" if inner.startswith("table") else
                f"table of {inner} values, one per name"), bounds
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return "table", ""
    names = {str: "text", int: "integer", float: "number", bool: "true | false", Path: "path"}
    if annotation in names:
        return names[annotation], ""
    return rst.escape(getattr(annotation, "__name__", str(annotation))), ""


def _annotation(field: FieldInfo):
    """The field's full type: pydantic keeps ``Annotated`` metadata apart from the type."""
    return Annotated[(field.annotation, *field.metadata)] if field.metadata else field.annotation


def _bounds_text(metadata) -> str:
    """``>= 1, <= 1000`` from annotated-types constraints (also inside a ``Field(...)``)."""
    parts = []
    for meta in metadata:
        if isinstance(meta, FieldInfo):
            parts.append(_bounds_text(meta.metadata))
            continue
        kind = type(meta).__name__
        if kind in _BOUNDS:
            attribute, word = _BOUNDS[kind]
            value = getattr(meta, attribute)
            parts.append(f"{word} {value:g}" if isinstance(value, float) else f"{word} {value}")
    return ", ".join(p for p in parts if p)


# -- values -----------------------------------------------------------------------------------
def toml_value(value: Any) -> str:
    """A value as it is written in a TOML file (``"NBR"``, ``0.45``, ``true``)."""
    return tomli_w.dumps({"x": value}).strip().removeprefix("x = ")


def default_text(field: FieldInfo) -> str:
    """The default as it would be written in the case file, or *required* / *not set*."""
    if field.is_required():
        return "**required**"
    value = field.get_default(call_default_factory=True)
    if value is None:
        return "not set"
    if isinstance(value, BaseModel):
        return "see its table"
    dumped = TypeAdapter(_annotation(field)).dump_python(value, mode="json")
    if dumped in ("", [], {}):
        return rst.literal(toml_value(dumped)) or '``""``'
    return rst.literal(toml_value(dumped))


# -- tables -----------------------------------------------------------------------------------
@dataclass
class Table:
    """One table of a case file: its TOML header and the model that validates it."""

    path: str            # "seal.wave"; "" for the top level
    model: type[BaseModel]
    repeated: bool = False       # [[path]]: a list of tables
    variant: str = ""            # 'law = "lugre"' for a member of a tagged union

    @property
    def header(self) -> str:
        if not self.path:
            return "Top level"
        text = f"[[{self.path}]]" if self.repeated else f"[{self.path}]"
        return f"{text} with {self.variant}" if self.variant else text


def _discriminator(field: FieldInfo, members: list[type[BaseModel]]) -> str | None:
    if isinstance(field.discriminator, str):
        return field.discriminator
    for arg in _union_members(field.annotation):  # e.g. Optional[Annotated[A | B, Field(...)]]
        if typing.get_origin(arg) is Annotated:
            for meta in typing.get_args(arg)[1:]:
                if isinstance(meta, FieldInfo) and isinstance(meta.discriminator, str):
                    return meta.discriminator
    common = set.intersection(*(
        {n for n, f in m.model_fields.items() if typing.get_origin(f.annotation) is Literal
         and len(typing.get_args(f.annotation)) == 1} for m in members))
    return sorted(common)[0] if common else None


def _tag(model: type[BaseModel], discriminator: str | None) -> str:
    if discriminator and discriminator in model.model_fields:
        values = typing.get_args(model.model_fields[discriminator].annotation)
        if values:
            return f"{discriminator} = {toml_value(values[0])}"
    return model.__name__


def tables(model: type[BaseModel], path: str = "", repeated: bool = False, variant: str = "",
           depth: int = 0) -> Iterator[Table]:
    """The table of ``model`` and, depth first, every table below it."""
    yield Table(path, model, repeated, variant)
    if depth > 12:  # a self-referencing model: document the first levels only
        return
    for name, field in model.model_fields.items():
        members = models_in(field.annotation)
        if not members:
            continue
        sub_path = f"{path}.{name}" if path else name
        containers = {typing.get_origin(_strip_annotated(m))
                      for m in _union_members(_strip_annotated(field.annotation))}
        is_list = bool(containers & {list, tuple})
        if dict in containers:  # a table of named tables: [path.name.KEY]
            sub_path += ".NAME"
        discriminator = _discriminator(field, members) if len(members) > 1 else None
        for member in members:
            tag = _tag(member, discriminator) if len(members) > 1 else ""
            yield from tables(member, sub_path, is_list, tag, depth + 1)


def field_rows(model: type[BaseModel]) -> list[list[str]]:
    """Rows (field, type, default, allowed and meaning) of one table."""
    rows = []
    for name, field in model.model_fields.items():
        kind, bounds = type_text(_annotation(field))
        allowed = rst.escape(bounds)
        description = rst.escape(field.description) if field.description else ""
        if models_in(field.annotation):
            description = " ".join(x for x in (description, "(see below)") if x)
        meaning = "; ".join(x for x in (allowed, description) if x)
        rows.append([rst.literal(name), kind, default_text(field), meaning])
    return rows


def _docstring(model: type[BaseModel]) -> str:
    doc = inspect.getdoc(model) or ""
    inherited = {inspect.getdoc(base) for base in model.__mro__[1:]}
    return "" if doc in inherited else doc  # e.g. the docstring of CaseModel itself


def model_page(model: type[BaseModel], examples: list[Path], repo: Path) -> str:
    """The reference page of one case model."""
    full_name = f"{model.__module__}.{model.__name__}"
    out = [f".. _case-{page_name(model)}:\n", rst.title(case_title(model))]
    command = case_command(model)
    out.append(f"Validated by :class:`{full_name}` (module :mod:`{model.__module__}`)" +
               (f"; run with {rst.literal(command)}" if command else "") + ".\n")
    doc = _docstring(model)
    if doc:
        out.append(rst.paragraph(doc) + "\n")
    if examples:
        names = ", ".join(f":download:`{p.relative_to(repo).as_posix()} "
                          f"</../{p.relative_to(repo).as_posix()}>`" for p in examples)
        out.append(f"Example files (each validated against this model when these pages were "
                   f"built): {names}.\n")
        first = examples[0].relative_to(repo).as_posix()
        out.append(f".. literalinclude:: /../{first}\n   :language: toml\n"
                   f"   :caption: {first}\n")
    out.append("Quantities are strings with a unit (``\"80 mm\"``); a field or table that "
               "is *not set* is optional and gets the value its description names.  In a case "
               "file, any field can be changed per variant in a ``[variants.NAME]`` table.\n")
    for table in tables(model):
        out.append(rst.title(rst.literal(table.header) if table.path else table.header, "-"))
        if table.path:
            doc = _docstring(table.model)
            if doc:
                out.append(rst.paragraph(doc) + "\n")
        rows = field_rows(table.model)
        if rows:
            out.append(rst.list_table(["Field", "Type", "Default", "Allowed, meaning"], rows,
                                      widths=[18, 24, 16, 42], css_class="case-fields"))
        else:
            out.append("No fields.\n")
    return "\n".join(out)


def index_page(models: list[type[BaseModel]], examples: dict[type[BaseModel], list[Path]],
               repo: Path) -> str:
    """The overview: one row per case model with its example files."""
    rows = []
    for model in models:
        doc = _docstring(model).split("\n\n")[0].replace("\n", " ")
        files = ", ".join(rst.literal(p.relative_to(repo).as_posix()) for p in examples[model])
        rows.append([f":doc:`/_generated/cases/{page_name(model)}`", rst.escape(doc),
                     rst.literal(case_command(model) or "") or "--", files or "--"])
    out = [rst.list_table(["Case file", "What it describes", "Command", "Examples"], rows,
                          widths=[18, 32, 18, 32]),
           ".. toctree::\n   :hidden:\n\n" + "\n".join(f"   /_generated/cases/{page_name(m)}"
                                                   for m in models)]
    return "\n".join(out) + "\n"


def write(out_dir: Path, repo: Path, models: list[type[BaseModel]],
          classified: dict[Path, list[type[BaseModel]]]) -> list[Path]:
    """Write one page per case model and ``index.rst`` into ``out_dir``; returns the pages."""
    out_dir.mkdir(parents=True, exist_ok=True)
    examples = {m: [p for p, accepted in classified.items() if m in accepted] for m in models}
    pages = []
    for model in models:
        page = out_dir / f"{page_name(model)}.rst"
        page.write_text(model_page(model, examples[model], repo), encoding="utf-8")
        pages.append(page)
    (out_dir / "index.rst").write_text(index_page(models, examples, repo), encoding="utf-8")
    return pages
