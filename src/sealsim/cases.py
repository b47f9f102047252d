"""Case files: TOML documents validated by pydantic models whose quantities carry units.

A case model is a :class:`CaseModel` whose physical fields are declared with :func:`Q`::

    class Seal(CaseModel):
        shaft_diameter: Q("length", gt=0)

In a case file the value is a string with a unit (``shaft_diameter = "80 mm"``); after
validation the attribute holds the SI float (0.08).  Case files are validated with
:func:`validate_case`, which requires the unit; a model built in Python also accepts a plain
number, taken as the value in SI units (``Seal(shaft_diameter=0.08)``).  Dumping a model writes the quantities back
as strings with units, so the *resolved case* (all defaults filled in) written next to every
result can be read again to reproduce it.

Every validation problem becomes one :class:`~sealsim.errors.InputError` whose message lists,
per problem, the field path (``seal.shaft_diameter``), the value given and what is allowed.
"""

from __future__ import annotations

import contextlib
import contextvars
import copy
import logging
import math
import re
import tomllib
import typing
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, TypeVar

import pydantic
import tomli_w
from pydantic import (
    BaseModel,
    ConfigDict,
    PlainSerializer,
    PlainValidator,
    ValidationInfo,
    WithJsonSchema,
)

from sealsim.errors import InputError
from sealsim.files import read_input_text
from sealsim.units import DIMENSIONS, format_like, format_quantity, parse_quantity

__all__ = [
    "CASE_KINDS",
    "JSON_SCHEMA_DIALECT",
    "MAX_TOML_DEPTH",
    "CaseKind",
    "CaseModel",
    "Q",
    "apply_overrides",
    "case_json_schema",
    "check_variant_name",
    "detect_case_kind",
    "dump_case_toml",
    "dump_variants_toml",
    "expand_variants",
    "format_validation_error",
    "load_toml",
    "one_variant_used",
    "parse_toml",
    "validate_case",
    "validation_problems",
    "wrong_kind_message",
]

ModelT = TypeVar("ModelT", bound=BaseModel)


class CaseModel(BaseModel):
    """Base of all case models: unknown fields are errors, instances are immutable."""

    # Defaults are written in SI (floats) and trusted; user input must carry units.
    model_config = ConfigDict(extra="forbid", frozen=True, validate_default=False)


def Q(dimension: str, *, gt: float | None = None, ge: float | None = None,  # noqa: N802
      lt: float | None = None, le: float | None = None):
    """Type of a case-file quantity of the given dimension with optional bounds (in SI).

    Parameters
    ----------
    dimension : str
        A key of :data:`sealsim.units.DIMENSIONS`, e.g. ``"length"``.
    gt, ge, lt, le : float, optional
        Bounds in SI units (e.g. kelvin for temperatures).

    Examples
    --------
    >>> class Shaft(CaseModel):
    ...     diameter: Q("length", gt=0)
    >>> Shaft(diameter="80 mm").diameter
    0.08
    >>> Shaft(diameter="80 mm").model_dump()
    {'diameter': '80 mm'}
    >>> Shaft(diameter=0.08).diameter   # from Python: SI
    0.08
    """
    if dimension not in DIMENSIONS:
        raise KeyError(f"unknown dimension {dimension!r}; choose from {sorted(DIMENSIONS)}")
    dim = DIMENSIONS[dimension]

    def bound_text(value: float) -> str:
        return format_quantity(value, dimension)

    def validate(value: Any, info: ValidationInfo) -> float:
        if (isinstance(value, int | float) and not isinstance(value, bool)
                and dimension != "dimensionless"
                and not (info.context or {}).get("require_units")):
            si = float(value)  # built in Python: a plain number is a value in SI units
            if not math.isfinite(si):
                raise ValueError(f"{value!r} is not a finite number")
        else:
            si = parse_quantity(value, dimension)
        for bound, ok, word in ((gt, lambda b: si > b, ">"), (ge, lambda b: si >= b, ">="),
                                (lt, lambda b: si < b, "<"), (le, lambda b: si <= b, "<=")):
            if bound is not None and not ok(bound):
                # a fraction (squeeze 0.12) given in percent (12): say how to write it
                percent = (dimension == "dimensionless" and word in ("<", "<=") and bound <= 1.0
                           and 1.0 < si <= 100.0 and not isinstance(value, str))
                raise ValueError(f"{value!r} is out of range: must be {word} "
                                 f"{format_like(bound, dimension, value)}"
                                 + (f" (a fraction: {si / 100:g} or '{si:g} %' for {si:g} %)"
                                    if percent else ""))
        return si

    rng = [f"{w} {bound_text(b)}" for b, w in ((gt, ">"), (ge, ">="), (lt, "<"), (le, "<="))
           if b is not None]
    description = f"{dim.name}, e.g. {dim.example!r}" + (f"; {', '.join(rng)}" if rng else "")
    return Annotated[
        float,
        PlainValidator(validate),
        PlainSerializer(lambda v: float(v) if dimension == "dimensionless"
                        else format_quantity(v, dimension), return_type=float | str),
        # in a file: a text with a unit ("80 mm"); a dimensionless value may be a plain number
        WithJsonSchema({"type": ["number", "string"] if dimension == "dimensionless"
                        else "string", "description": description, "examples": [dim.example]}),
    ]


@dataclass(frozen=True)
class CaseKind:
    """A kind of case file, recognised by top-level tables that no other kind has.

    Parameters
    ----------
    name : str
        What the case is, e.g. ``"structure"``.
    model : str
        Qualified name of its case model (a string: this module never imports the models).
    command : str
        The command that runs it.
    tables : frozenset of str
        Top-level tables (fields of ``model``) that no other kind's model has.
    variants : bool
        The command reads ``[variants.NAME]`` tables (:func:`expand_variants`).
    """

    name: str
    model: str
    command: str
    tables: frozenset[str]
    variants: bool = False


#: The kinds of case file; tests check ``tables`` against the models' fields.
CASE_KINDS = (
    CaseKind("rotary", "sealsim.rotary.case.RotaryCase", "sealsim rotary run",
             frozenset({"duty", "environment", "oil", "numerics"}), variants=True),
    CaseKind("structure", "sealsim.structure.case.StructureCase",
             "sealsim structure run (or sealsim structure map)",
             frozenset({"gland", "material", "mesh", "map"}), variants=True),
    CaseKind("fmu", "sealsim.fmu.case.FMUCase", "sealsim fmu build",
             frozenset({"fmu", "table", "rotary"})),
    CaseKind("pneumatic", "sealsim.pneumatic.case.PneumaticCase", "sealsim pneumatic run",
             frozenset({"cylinder", "air", "valve", "controller", "seals",
                        "initial_position"}), variants=True),
    CaseKind("friction", "sealsim.friction.case.FrictionCase", "sealsim friction run",
             frozenset({"bench", "inputs"}), variants=True),
    # a friction fit and a rotary fit share [fit] and [[measurements]]; [model] (the rotary
    # case) or [contact]/[signals] tell them apart
    CaseKind("friction fit", "sealsim.calibration.case.FrictionFitCase", "sealsim friction fit",
             frozenset({"contact", "signals"})),
    CaseKind("rotary fit", "sealsim.calibration.rotary_case.RotaryFitCase", "sealsim rotary fit",
             frozenset({"model", "averaging"})),
    CaseKind("pneumatic compare", "sealsim.calibration.pneumatic_compare.CompareCase",
             "sealsim pneumatic compare", frozenset({"case", "variant", "measurement"})),
    CaseKind("material fit", "sealsim.calibration.material_fit.MaterialFitCase",
             "sealsim material fit",
             frozenset({"compound", "hyperelastic", "viscoelastic", "dilatometry"})),
    CaseKind("gland", "sealsim.structure.gland_case.GlandCase", "sealsim gland check",
             frozenset({"ring", "housing", "service"})),
    CaseKind("study", "sealsim.studies.spec.StudyFile", "sealsim study run",
             frozenset({"study", "base", "set", "factors", "outputs", "series"})),
)


def detect_case_kind(data: Any) -> CaseKind | None:
    """The kind of case whose own top-level tables ``data`` has, if exactly one kind matches.

    Examples
    --------
    >>> detect_case_kind({"seal": {}, "gland": {}, "load": {}}).name
    'structure'
    >>> detect_case_kind({"seal": {}}) is None   # rotary and structure cases both have a seal
    True
    """
    if not isinstance(data, dict):
        return None
    found = [kind for kind in CASE_KINDS if kind.tables & set(data)]
    return found[0] if len(found) == 1 else None


def wrong_kind_message(model: type[BaseModel], data: Any) -> str | None:
    """A message if ``data`` is a case of another kind than ``model`` (else ``None``).

    Every ``run`` command reads its case through :func:`expand_variants` or
    :func:`validate_case`, which call this when validation fails, so a structure case given to
    ``sealsim pneumatic run`` gets "this looks like a structure case ...: run it with sealsim
    structure run" instead of a list of unknown fields.

    Examples
    --------
    >>> class PneumaticCase(CaseModel):   # stands for sealsim.pneumatic.case.PneumaticCase
    ...     cylinder: dict
    >>> PneumaticCase.__module__ = "sealsim.pneumatic.case"
    >>> wrong_kind_message(PneumaticCase, {"seal": {}, "gland": {}, "mesh": {}})
    'this looks like a structure case (it has the tables gland, mesh), not a pneumatic case: ...'
    """
    name = f"{model.__module__}.{model.__qualname__}"
    expected = next((kind for kind in CASE_KINDS if kind.model == name), None)
    found = detect_case_kind(data)
    if expected is None or found is None or found is expected:
        return None
    tables = ", ".join(sorted(found.tables & set(data)))
    return (f"this looks like a {found.name} case (it has the tables {tables}), not a "
            f"{expected.name} case: run it with {found.command}")


#: keys whose value may name a compound file (``material = "my_nbr.toml"``)
MATERIAL_KEYS = frozenset({"material", "elastomer"})


def resolve_material_files(data: Any, base: Path) -> Any:
    """``data`` with every ``material``/``elastomer`` value that is a relative path of a
    ``.toml`` compound file made absolute against ``base`` (the case file's folder), in place.

    Examples
    --------
    >>> resolve_material_files({"seal": {"material": "my.toml"}}, Path("/cases"))
    {'seal': {'material': '/cases/my.toml'}}
    """
    items = data.items() if isinstance(data, dict) else enumerate(data) \
        if isinstance(data, list) else ()
    for key, value in items:
        if (key in MATERIAL_KEYS and isinstance(value, str)
                and value.strip().lower().endswith(".toml")
                and not Path(value.strip()).is_absolute()):
            data[key] = str(base / value.strip())
        else:
            resolve_material_files(value, base)
    return data


#: deepest nesting of tables and arrays in a TOML file (the examples nest at most 6 levels);
#: deeper files are refused before any code walks them recursively
MAX_TOML_DEPTH = 32


def parse_toml(text: str, source: str) -> dict[str, Any]:
    """Parse TOML text read from ``source`` (e.g. ``"case file 'a.toml'"``); a syntax error or
    nesting deeper than :data:`MAX_TOML_DEPTH` becomes an :class:`InputError`.

    Examples
    --------
    >>> parse_toml("a = " + "[" * 40 + "]" * 40, "case file 'deep.toml'")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: case file 'deep.toml' nests tables or arrays more than 32 \
levels deep (at 'a'); a case needs only a few levels
    """
    try:
        data = tomllib.loads(text)
    except RecursionError:
        raise InputError(f"{source} nests tables or arrays more than {MAX_TOML_DEPTH} levels "
                         "deep; a case needs only a few levels") from None
    except ValueError as exc:  # TOMLDecodeError, and integers tomllib cannot convert
        raise InputError(f"{source} is not valid TOML: {exc}") from None
    stack: list[tuple[Any, int, str]] = [(data, 0, "")]
    while stack:
        node, depth, where = stack.pop()
        if depth > MAX_TOML_DEPTH:
            raise InputError(f"{source} nests tables or arrays more than {MAX_TOML_DEPTH} "
                             f"levels deep (at {where!r}); a case needs only a few levels")
        items = node.items() if isinstance(node, dict) else enumerate(node) \
            if isinstance(node, list) else ()
        for key, value in items:
            if isinstance(value, dict | list):
                stack.append((value, depth + 1, where or str(key)))
    return data


def load_toml(path: str | Path, what: str = "case file") -> dict[str, Any]:
    """Read a TOML file (:func:`sealsim.files.read_input_text`: a regular file of limited
    size); a missing file, a syntax error or too deep a nesting becomes an
    :class:`InputError` naming the file (``what`` says what it is, e.g. ``"friction file"``).

    A compound file named by a relative path (``material = "my_nbr.toml"``) is taken relative
    to this file (:func:`resolve_material_files`)."""
    path = Path(path)
    text = read_input_text(path, what)
    return resolve_material_files(parse_toml(text, f"{what} {str(path)!r}"),
                                  path.parent.absolute())


def validate_case(model: type[ModelT], data: Any, source: str = "case",
                  require_units: bool = True) -> ModelT:
    """Validate ``data`` against ``model``; any problem becomes one :class:`InputError`.

    Parameters
    ----------
    model : type
        The pydantic case model.
    data : dict
        Parsed case data (e.g. from :func:`load_toml`).
    source : str
        Where the data came from (a file name), shown in the error message.

    require_units : bool
        Quantities must carry units (``"80 mm"``): a plain number is refused, because in a
        file it is ambiguous.  ``False`` for values built in Python, where numbers are SI.
    """
    try:
        return model.model_validate(data, context={"require_units": require_units})
    except pydantic.ValidationError as exc:
        wrong_kind = wrong_kind_message(model, data)
        if wrong_kind:
            raise InputError(f"invalid {source}: {wrong_kind}") from None
        raise InputError(format_validation_error(exc, source, model)) from None


def format_validation_error(exc: pydantic.ValidationError, source: str,
                            model: type[BaseModel] | None = None) -> str:
    """One readable message for all problems in a pydantic ValidationError."""
    return _message(source, validation_problems(exc, model))


def _message(source: str, problems: list[str]) -> str:
    if len(problems) == 1:
        return f"invalid {source}: {problems[0]}"
    return f"invalid {source}:" + "".join(f"\n  {p}" for p in problems)


def validation_problems(exc: pydantic.ValidationError,
                        model: type[BaseModel] | None = None) -> list[str]:
    """One line per problem: the field path as written in the file, the value, what is allowed.

    A check across fields (a model validator) is reported at the table it belongs to, with its
    own message naming the fields, never with the whole table as "value".
    """
    problems = []
    for err in exc.errors(include_url=False):
        loc = ".".join(str(p) for p in _clean_location(model, err["loc"]))
        where = f"{loc}: " if loc else ""
        kind = err["type"]
        given = err.get("input")
        if kind == "missing":
            hint = _field_hint(model, err["loc"])
            problems.append(f"{where}required field is missing" + (f" ({hint})" if hint else ""))
        elif kind == "extra_forbidden":
            allowed = _allowed_fields(model, err["loc"][:-1])
            problems.append(f"{where}unknown field" +
                            (f"; allowed fields: {', '.join(allowed)}" if allowed else ""))
        elif kind == "union_tag_not_found":  # the field that selects the kind of table
            field = str(err.get("ctx", {}).get("discriminator", "")).strip("'")
            problems.append(f"{loc + '.' if loc else ''}{field}: required field is missing "
                            f"(it chooses the kind of {loc or 'table'})")
        elif kind in ("literal_error", "enum"):
            expected = err.get("ctx", {}).get("expected", "")
            problems.append(f"{where}{given!r} is not allowed; choose one of {expected}")
        else:
            msg = err["msg"].removeprefix("Value error, ").removeprefix("Assertion failed, ")
            if isinstance(given, dict) and kind in ("value_error", "assertion_error"):
                problems.append(f"{where}{msg}")  # across fields: the message names them
            elif kind in ("value_error", "assertion_error") and repr(given) in msg:
                problems.append(f"{where}{msg}")
            else:
                problems.append(f"{where}{msg} (got {_short(given)})")
    return problems


def _short(value: Any) -> str:
    text = repr(value)
    if isinstance(value, float) and math.isnan(value):
        return "nan"
    return text if len(text) <= 80 else text[:77] + "..."


def _submodel(model: type[BaseModel] | None, loc: tuple) -> type[BaseModel] | None:
    for part in loc:
        if isinstance(part, int):  # index into a list of sub-models
            continue
        if model is None or part not in model.model_fields:
            return None
        members = _models_in(model.model_fields[part].annotation)
        model = members[0] if len(members) == 1 else None
    return model


def _models_in(annotation) -> list[type[BaseModel]]:
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    return [m for arg in typing.get_args(annotation) for m in _models_in(arg)]


def _tags(model: type[BaseModel]) -> set[str]:
    """Names pydantic may put in an error location for this member of a union."""
    tags = {model.__name__}
    for field in model.model_fields.values():
        if typing.get_origin(field.annotation) is typing.Literal:
            tags.update(str(v) for v in typing.get_args(field.annotation))
    return tags


def _clean_location(model: type[BaseModel] | None, loc: tuple) -> tuple:
    """Error location as written in the file: drop the tags pydantic inserts for unions.

    ``friction.lugre.sigma0`` (tag ``lugre`` of a discriminated union) becomes
    ``friction.sigma0``; ``seal.material`` stays as it is.
    """
    out: list = []
    current: list[type[BaseModel]] = [model] if model is not None else []
    for part in loc:
        if isinstance(part, int):
            out.append(part)
            continue
        if len(current) > 1:  # a union: the part may be the member's tag
            chosen = [m for m in current if part in _tags(m)]
            if chosen:
                current = chosen[:1]
                continue
        if len(current) == 1 and part in current[0].model_fields:
            out.append(part)
            current = _models_in(current[0].model_fields[part].annotation)
            continue
        out.append(part)
        current = []
    return tuple(out)


def _allowed_fields(model, loc) -> list[str]:
    sub = _submodel(model, tuple(loc))
    return sorted(sub.model_fields) if sub is not None else []


def _field_hint(model, loc) -> str:
    sub = _submodel(model, tuple(loc[:-1]))
    if sub is None or loc[-1] not in sub.model_fields:
        return ""
    schema = sub.model_json_schema().get("properties", {}).get(loc[-1], {})
    return schema.get("description", "")


def apply_overrides(base: dict[str, Any], overrides: dict[str, Any]) -> dict[str, Any]:
    """Deep-merge ``overrides`` into a copy of ``base`` (tables merge, values replace).

    Examples
    --------
    >>> apply_overrides({"seal": {"lip_style": "plain", "d": "80 mm"}},
    ...                 {"seal": {"lip_style": "wave"}})
    {'seal': {'lip_style': 'wave', 'd': '80 mm'}}
    """
    merged = copy.deepcopy(base)
    for key, value in overrides.items():
        if isinstance(value, dict) and isinstance(merged.get(key), dict):
            merged[key] = apply_overrides(merged[key], value)
        else:
            merged[key] = copy.deepcopy(value)
    return merged


def dump_case_toml(case: BaseModel, header: str | None = None) -> str:
    """TOML text of a case with every default filled in, readable by the same model."""
    data = _drop_none(case.model_dump(mode="json"))
    text = tomli_w.dumps(data)
    if header:
        text = "".join(f"# {line}\n" for line in header.splitlines()) + "\n" + text
    return text


def _drop_none(value):
    # TOML has no null: absent optional fields stay absent (their default is None).
    if isinstance(value, dict):
        return {k: _drop_none(v) for k, v in value.items() if v is not None}
    if isinstance(value, list):
        return [_drop_none(v) for v in value]
    return value


DEFAULT_VARIANT = "base"

#: allowed variant names: they become file and folder names of the results
VARIANT_NAME = re.compile(r"[A-Za-z0-9_-][A-Za-z0-9._-]{0,63}")


def check_variant_name(name: Any, source: str = "case") -> str:
    """``name`` if it is a safe variant name, else an :class:`InputError` naming it.

    Letters, digits, ``-``, ``_`` and ``.`` (not first), at most 64 characters: variant names
    become file names (``cycle_NAME.png``) and folders (``NAME/result.csv``), so a name like
    ``a/../../victim`` must never reach a writer.

    Examples
    --------
    >>> check_variant_name("sump_0.2L")
    'sump_0.2L'
    >>> check_variant_name("../x")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: invalid case: variant name '../x' is not allowed; use letters, \
digits, '-', '_' and '.' (not first), at most 64 characters, e.g. [variants.wave_lip]
    """
    if not isinstance(name, str) or not VARIANT_NAME.fullmatch(name):
        raise InputError(f"invalid {source}: variant name {name!r} is not allowed; use "
                         "letters, digits, '-', '_' and '.' (not first), at most 64 "
                         "characters, e.g. [variants.wave_lip]")
    return name


def expand_variants(model: type[ModelT], data: dict[str, Any],
                    source: str = "case") -> dict[str, ModelT]:
    """Validate a case with optional ``[variants.NAME]`` tables that override base fields.

    Without variants the case is one variant named ``"base"``.  With variants, each variant is
    the base deep-merged with its overrides (:func:`apply_overrides`) and validated on its own;
    the base case itself is not a run (add an empty ``[variants.base]`` to run it), which an
    INFO record on the ``sealsim.cases`` logger says (the CLI prints it).
    A problem shared by every variant (usually one in the base case) is reported once; others
    name their variant (``variant 'wave': seal.lip_style: ...``).  Variant names are checked
    by :func:`check_variant_name` (they become file names), and two names that differ only in
    case are refused (they would be one file on Windows and macOS).

    Examples
    --------
    >>> class Lip(CaseModel):
    ...     width: Q("length", gt=0)
    ...     style: str = "plain"
    >>> cases = expand_variants(Lip, {"width": "0.15 mm", "variants": {"w": {"style": "wave"}}})
    >>> {name: case.style for name, case in cases.items()}
    {'w': 'wave'}
    """
    data = dict(data)
    variants = data.pop("variants", None)
    if variants is None:
        return {DEFAULT_VARIANT: validate_case(model, data, source)}
    wrong_kind = wrong_kind_message(model, data)
    if wrong_kind:  # a case of another model: one clear message, not one per variant
        raise InputError(f"invalid {source}: {wrong_kind}")
    if not isinstance(variants, dict) or not variants:
        raise InputError(f"invalid {source}: variants must be a table of named overrides, "
                         f"e.g. [variants.wave] seal.lip_style = 'wave' (got {variants!r})")
    seen: dict[str, str] = {}
    for name in variants:
        check_variant_name(name, source)
        if name.lower() in seen:
            raise InputError(f"invalid {source}: variant names {seen[name.lower()]!r} and "
                             f"{name!r} differ only in upper/lower case; they would be one "
                             "result file on some systems")
        seen[name.lower()] = name
    cases: dict[str, ModelT] = {}
    problems: dict[str, list[str]] = {}
    for name, overrides in variants.items():
        if not isinstance(overrides, dict):
            problems[name] = [f"expected a table of overrides, got {_short(overrides)}"]
            continue
        try:
            cases[name] = model.model_validate(apply_overrides(data, overrides),
                                               context={"require_units": True})
        except pydantic.ValidationError as exc:
            problems[name] = validation_problems(exc, model)
    if problems:
        shared = [p for p in next(iter(problems.values()))
                  if len(problems) == len(variants) and all(p in v for v in problems.values())]
        lines = shared + [f"variant {name!r}: {p}" for name, found in problems.items()
                          for p in found if p not in shared]
        raise InputError(_message(source, lines))
    _say_base_not_run(cases, source)
    return cases


#: False inside :func:`one_variant_used`
_ANNOUNCE_RUNS: contextvars.ContextVar[bool] = contextvars.ContextVar("announce_runs",
                                                                      default=True)


@contextlib.contextmanager
def one_variant_used() -> Iterator[None]:
    """Within the block, a case with variants is loaded without announcing that its variants
    run: for a command that uses one of them (an FMU build), which says itself which one."""
    token = _ANNOUNCE_RUNS.set(False)
    try:
        yield
    finally:
        _ANNOUNCE_RUNS.reset(token)


def _say_base_not_run(cases: dict[str, Any], source: str) -> None:
    """Announce (INFO on the ``sealsim.cases`` logger, which the CLI prints) that a case with
    variants runs the variants only, not its base case (not within :func:`one_variant_used`)."""
    if not _ANNOUNCE_RUNS.get():
        return
    logging.getLogger(__name__).info(
        "%s: runs the variants %s; the base case only gives their common fields and is not run "
        "on its own (add an empty [variants.%s] table to run it too)", source, ", ".join(cases),
        DEFAULT_VARIANT)


def dump_variants_toml(cases: dict[str, BaseModel], header: str | None = None) -> str:
    """Resolved TOML for a set of variants; :func:`expand_variants` reads it back unchanged.

    A single variant named ``"base"`` (a case without variants) is written as a plain case.
    """
    if list(cases) == [DEFAULT_VARIANT]:
        return dump_case_toml(cases[DEFAULT_VARIANT], header)
    data = {"variants": {name: _drop_none(case.model_dump(mode="json"))
                         for name, case in cases.items()}}
    text = tomli_w.dumps(data)
    if header:
        text = "".join(f"# {line}\n" for line in header.splitlines()) + "\n" + text
    return text


# -- JSON Schema of a case file -----------------------------------------------------------------
#: dialect of the schemas: draft 7 is what editors' TOML and JSON tooling supports most widely
JSON_SCHEMA_DIALECT = "http://json-schema.org/draft-07/schema#"


def case_json_schema(model: type[BaseModel], *, variants: bool = False,
                     title: str | None = None) -> dict[str, Any]:
    """JSON Schema (draft 7) of a case file read by ``model``, for editors that check TOML.

    Quantities are texts with a unit (``"80 mm"``; a dimensionless one may be a plain number),
    as the file needs them.  With ``variants``, a ``[variants.NAME]`` table holds overrides:
    any part of the case, nothing required (:func:`expand_variants` merges it into the base
    case).  Checks across fields (one of two fields given, a lower bound below an upper one)
    are the case model's; the schema checks names, types and the bounds of single fields.

    Examples
    --------
    >>> class Lip(CaseModel):
    ...     width: Q("length", gt=0)
    >>> schema = case_json_schema(Lip, variants=True)
    >>> schema["else"], schema["definitions"]["Lip"]["required"]
    ({'$ref': '#/definitions/Lip'}, ['width'])
    >>> with_variants = schema["definitions"]["LipWithVariants"]
    >>> "required" in with_variants, with_variants["properties"]["variants"]["type"]
    (False, 'object')
    """
    schema = model.model_json_schema(ref_template="#/definitions/{model}")
    definitions = schema.pop("$defs", {})
    out: dict[str, Any] = {"$schema": JSON_SCHEMA_DIALECT}
    if title:
        out["title"] = title
    if variants:
        # with [variants], the base case is completed by each variant: nothing is required
        override = {name: _override(d) for name, d in definitions.items()}
        definitions.update({f"{name}Override": d for name, d in override.items()})
        partial = _override(schema)
        partial["properties"]["variants"] = {
            "type": "object", "minProperties": 1,
            "description": "named variants, each run on its own: a table of fields that "
                           "override the base case, e.g. [variants.wave] seal.lip_style = "
                           "'wave'",
            "propertyNames": {"pattern": f"^{VARIANT_NAME.pattern}$"},
            "additionalProperties": _override(schema),
        }
        name = model.__name__
        definitions[name], definitions[f"{name}WithVariants"] = schema, partial
        out.update({"description": schema.get("description", ""),
                    "if": {"required": ["variants"]},
                    "then": {"$ref": f"#/definitions/{name}WithVariants"},
                    "else": {"$ref": f"#/definitions/{name}"}})
    else:
        own = _draft7(schema)
        if title:
            own.pop("title", None)  # the model's class name would replace the kind's title
        out.update(own)
    if definitions:
        out["definitions"] = {name: _draft7(d) for name, d in definitions.items()}
    return out


def _override(schema: Any) -> Any:
    """``schema`` with nothing required (at any depth) and references to the override
    definitions: what a variant may give."""
    if isinstance(schema, list):
        return [_override(item) for item in schema]
    if not isinstance(schema, dict):
        return schema
    out = {}
    for key, value in schema.items():
        if key in ("required", "title", "discriminator"):
            continue
        if key == "$ref" and isinstance(value, str) and value.startswith("#/definitions/"):
            out[key] = value + "Override"
        elif key == "oneOf":       # several partial alternatives may match: any of them
            out["anyOf"] = _override(value)
        elif key == "anyOf" and all(set(v) == {"required"} for v in value):
            continue               # alternatives of what is required (a law's parameter set)
        elif key == "properties":
            out[key] = {k: _override(v) for k, v in value.items()}
        else:
            out[key] = _override(value)
    return out


def _draft7(schema: Any) -> Any:
    """A draft-7 schema: a ``$ref`` with siblings (a field's description) goes into ``allOf``
    (draft 7 ignores the siblings of ``$ref``); pydantic's ``discriminator`` is dropped."""
    if isinstance(schema, list):
        return [_draft7(item) for item in schema]
    if not isinstance(schema, dict):
        return schema
    out = {k: _draft7(v) for k, v in schema.items() if k != "discriminator"}
    if "$ref" in out and len(out) > 1:
        out["allOf"] = [{"$ref": out.pop("$ref")}]
    return out
