"""Study files: a base case, the factors that change it, and the outputs to collect.

A study file (TOML)::

    title = "O-ring rod seal: tolerance spread of F_N and friction"

    [study]
    model = "pneumatic"           # rotary | rotary_steady | friction | structure |
                                  # structure_map | pneumatic
    case = "../pneumatic/cylinder_32_fe.toml"    # or an inline [base] table
    variant = "T25C"              # when the case file has variants
    design = "latin_hypercube"    # grid | monte_carlo | latin_hypercube | sobol
    samples = 64                  # sampled designs (sobol: N of Saltelli's N·(d + 2) runs)
    seed = 1

    [set]                         # every run: fixed values, or "= expression" of factors
    "seals.rod.map.structure_case.map.temperature" = ["25 degC"]
    "seals.rod.map.structure_case.load.squeeze" = "= [1 - groove_depth / cord_diameter]"

    [[factors]]                   # a case field by its dotted path ...
    name = "cord_diameter"
    path = "seals.rod.map.structure_case.seal.cord_diameter"
    distribution = "truncnormal"  # uniform (lower, upper) | normal (mean, std) |
    mean = "2 mm"                 # truncnormal (mean, std, lower, upper)
    std = "0.027 mm"
    lower = "1.92 mm"
    upper = "2.08 mm"

    [[factors]]                   # ... or a free variable used in [set] expressions
    name = "groove_depth"
    distribution = "uniform"
    lower = "1.73 mm"
    upper = "1.79 mm"

    [[factors]]                   # a grid factor: listed values (or range = {...})
    name = "oil"
    path = "oil.name"
    values = ["VG32-mineral", "VG68-mineral"]

    [outputs]                     # name = path in the model's summary (see studies.models)
    F_N = "seals.rod.normal_force_range_N.0"
    friction = { path = "seals.rod.mean_friction_N", unit = "N" }

    [series]                      # optional: time series (or states, map arrays) per run
    variables = ["F_rod_N"]
    interval = "10 ms"

Paths (``seal.cord_diameter``, ``duty.steps.0.speed``, ``seals.rod.map...``) are those of the
case file, see :mod:`sealsim.studies.paths`.  Grid factors span one dimension each; sampled
factors share one ``sample`` dimension (crossed with the grid factors if both are given).

:func:`load_study` validates everything before a run starts: the study file, the base case,
every grid value and the bounds of every distribution *in the case* (the case models check
units and ranges), the expressions.  Each problem is one :class:`~sealsim.errors.InputError`
naming the factor (unknown field path, a distribution without bounds for a quantity that must
stay positive, a factor with no values, zero samples, ...).
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import os
import re
import stat
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import Field, ValidationError

from sealsim import __version__
from sealsim.cases import (
    CaseModel,
    dump_case_toml,
    format_validation_error,
    load_toml,
    parse_toml,
    validate_case,
)
from sealsim.errors import InputError
from sealsim.files import file_digests, read_input_text
from sealsim.studies import design as doe
from sealsim.studies import expressions
from sealsim.studies.models import MODELS
from sealsim.studies.paths import (
    LINKED_CASE_FIELDS,
    MAIN,
    Location,
    assign,
    linked_documents,
    resolve,
)
from sealsim.units import parse_quantity, ureg

__all__ = ["Factor", "Output", "Study", "load_study", "parse_study"]

#: names of factors and outputs: they become netCDF variables and CSV columns
NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]{0,63}")
#: names the result dataset uses itself
RESERVED = {"sample", "run", "status", "error", "wall_time_s", "time", "state", "worker"}
#: most runs of a study without asking (a guard against a slip such as samples = 1e6)
MAX_RUNS = 100_000
#: most runs of any study (study.max_runs): each run is a record in the work folder and a row
#: of runs.csv, all held in memory for the analysis; a million runs of the fastest model
#: (about 10 ms each) take about three hours on one core
MAX_RUNS_LIMIT = 1_000_000
#: a distribution is unbounded if the case refuses a value this many standard deviations away
_PROBE_SIGMAS = 1e6
_NUMBER_START = re.compile(r"^\s*[-+]?(\d|\.\d)")
_NUMBER = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


# -- the study file --------------------------------------------------------------------------
class RangeSpec(CaseModel):
    """Evenly spaced grid values: ``range = { start = "500 rpm", stop = "3000 rpm", num = 6 }``."""

    start: str | float
    stop: str | float
    num: int = Field(ge=0, le=MAX_RUNS)
    spacing: Literal["linear", "log"] = "linear"


class FactorSpec(CaseModel):
    """A factor: a case field (``path``) or a free variable, with grid values or a
    distribution."""

    name: str
    path: str | None = None
    description: str = ""
    values: list[Any] | None = None
    range: RangeSpec | None = None
    unit: str | None = None
    distribution: Literal[tuple(doe.DISTRIBUTIONS)] | None = None  # type: ignore[valid-type]
    mean: str | float | None = None
    std: str | float | None = None
    lower: str | float | None = None
    upper: str | float | None = None


class OutputSpec(CaseModel):
    """A named output: a path into the model's summary, its unit (default: from the name)."""

    path: str
    unit: str | None = None


class SeriesSpec(CaseModel):
    """Series to keep per run: columns of the model's time series (or state table, or map),
    resampled every ``interval`` for time series."""

    variables: list[str] = Field(min_length=1)
    interval: str | None = None


class StudyTable(CaseModel):
    """``[study]``: model, base case, design."""

    model: Literal[tuple(MODELS)]  # type: ignore[valid-type]
    case: str | None = None
    variant: str | None = None
    design: Literal[("grid", *doe.SAMPLED_DESIGNS)] = "grid"  # type: ignore[valid-type]
    samples: int | None = None
    seed: int = Field(0, ge=0)
    batch_size: int | None = Field(None, ge=1, le=MAX_RUNS, description=(
        "runs per Dask task; default: as many as take about one second"))
    max_runs: int = Field(MAX_RUNS, ge=1, le=MAX_RUNS_LIMIT, description=(
        "most runs of the study (a guard against a slip); raise it for bigger studies"))


class StudyFile(CaseModel):
    """The whole study file."""

    title: str = ""
    description: str = ""
    study: StudyTable
    base: dict | None = None
    set: dict[str, Any] = Field(default_factory=dict)
    factors: list[FactorSpec] = Field(default_factory=list)
    outputs: dict[str, str | OutputSpec] = Field(min_length=1)
    series: SeriesSpec | None = None


# -- resolved factors and outputs ------------------------------------------------------------
@dataclass
class Factor:
    """A resolved factor.

    ``kind`` is ``"grid"`` (``values``: case values, ``coords``: their numbers in ``unit`` or
    their text) or ``"sampled"`` (``distribution`` with ``params`` in ``unit``).
    """

    name: str
    path: str | None
    location: Location | None
    kind: str
    unit: str = ""
    values: list = field(default_factory=list)
    coords: list = field(default_factory=list)
    distribution: str | None = None
    params: dict[str, float] = field(default_factory=dict)
    description: str = ""

    @property
    def numeric(self) -> bool:
        return self.kind == "sampled" or all(isinstance(c, float) for c in self.coords)

    def case_value(self, x: float) -> Any:
        """Case-file value of the number ``x`` in this factor's unit."""
        return f"{x!r} {self.unit}" if self.unit else float(x)

    def quantity(self, x: Any) -> Any:
        """Value for expressions: a pint quantity, a number or a text."""
        if isinstance(x, str) or not self.unit:
            return x
        return ureg.Quantity(x, self.unit)

    def nominal(self) -> Any:
        """Number/text used for this factor while another one is checked."""
        if self.kind == "grid":
            return self.coords[0]
        p = self.params
        return p["mean"] if "mean" in p else 0.5 * (p["lower"] + p["upper"])


@dataclass(frozen=True)
class Output:
    name: str
    path: str
    unit: str


#: unit of an output from the end of its summary key (sealsim names carry their unit)
_SUFFIX_UNITS = [("_N_per_mm", "N/mm"), ("_m_s", "m/s"), ("_Nm", "N m"), ("_NL", "NL"),
                 ("_MPa", "MPa"), ("_bar", "bar"), ("_um", "um"), ("_mm", "mm"), ("_rpm", "rpm"),
                 ("_kg", "kg"), ("_W", "W"), ("_J", "J"), ("_C", "degC"), ("_K", "K"),
                 ("_s", "s"), ("_m", "m"), ("_N", "N")]


def unit_from_key(path: str) -> str:
    """Unit of a summary value from its key: ``seals.rod.mean_friction_N`` -> ``"N"``.

    Examples
    --------
    >>> unit_from_key("last_step.torque_Nm"), unit_from_key("seals.rod.normal_force_range_N.0")
    ('N m', 'N')
    >>> unit_from_key("final.b_mm"), unit_from_key("theta_max"), unit_from_key("F_N_N.max")
    ('mm', '1', 'N')
    """
    for key in reversed([p for p in path.split(".") if not p.isdigit()]):
        for suffix, unit in _SUFFIX_UNITS:
            if key.endswith(suffix):
                return unit
    return "1"


# -- the resolved study ------------------------------------------------------------------------
@dataclass
class Study:
    """A validated study: base case documents, factors, design and the table of runs."""

    source: Path
    title: str
    description: str
    model: str
    design: str
    seed: int
    samples: int | None
    batch_size: int | None
    documents: dict[tuple, dict]          # base case and linked cases, [set] constants applied
    link_files: dict[tuple, Path]
    base_dir: Path
    factors: list[Factor]
    derived: list[tuple[Location, str, Any]]    # (where, expression text, parsed)
    outputs: list[Output]
    series: SeriesSpec | None
    series_interval: float | None
    inputs: list[Path]
    text: str
    sample_values: np.ndarray | None = None     # (n_samples, n_sampled) in factor units

    # -- shape of the run table --------------------------------------------------------------
    @property
    def grid_factors(self) -> list[Factor]:
        return [f for f in self.factors if f.kind == "grid"]

    @property
    def sampled_factors(self) -> list[Factor]:
        return [f for f in self.factors if f.kind == "sampled"]

    @property
    def sampled(self) -> bool:
        return self.design != "grid"

    @property
    def n_samples(self) -> int:
        return 0 if self.sample_values is None else len(self.sample_values)

    @property
    def dims(self) -> tuple[str, ...]:
        return tuple(f.name for f in self.grid_factors) + (("sample",) if self.sampled else ())

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(f.values) for f in self.grid_factors) + (
            (self.n_samples,) if self.sampled else ())

    @property
    def n_runs(self) -> int:
        return math.prod(self.shape)

    def position(self, index: int) -> tuple[int, ...]:
        """Indices of run ``index`` along :attr:`dims` (C order, the sample index last)."""
        return tuple(int(i) for i in np.unravel_index(index, self.shape))

    def factor_values(self, index: int) -> dict[str, Any]:
        """``{factor: number or text}`` of run ``index`` (numbers in the factor's unit)."""
        pos = self.position(index)
        values = {f.name: f.coords[pos[k]] for k, f in enumerate(self.grid_factors)}
        if self.sampled:
            row = self.sample_values[pos[-1]]
            values.update({f.name: float(row[j]) for j, f in enumerate(self.sampled_factors)})
        return values

    def assignments(self, index: int) -> list[tuple[Location, Any]]:
        """Case changes of run ``index``: its factors and the derived values."""
        return self._assignments(self.factor_values(index))

    def _assignments(self, values: dict[str, Any]) -> list[tuple[Location, Any]]:
        changes = []
        by_name = {f.name: f for f in self.factors}
        for f in self.factors:
            if f.location is None:
                continue
            x = values[f.name]
            if f.kind == "grid":
                changes.append((f.location, f.values[f.coords.index(x)]))
            else:
                changes.append((f.location, f.case_value(x)))
        quantities = {name: by_name[name].quantity(x) for name, x in values.items()}
        for location, text, tree in self.derived:
            try:
                value = expressions.case_value(expressions.evaluate(tree, quantities))
            except (ArithmeticError, TypeError, ValueError, InputError) as exc:
                raise InputError(f"[set] {location.text()} = {text!r}: {exc} (factors: "
                                 f"{values})") from None
            changes.append((location, value))
        return changes

    def run_documents(self, changes: list[tuple[Location, Any]]) -> dict[tuple, dict]:
        documents = copy.deepcopy(self.documents)
        for location, value in changes:
            assign(documents, location, value)
        return documents

    # -- identity --------------------------------------------------------------------------
    def referenced_files(self) -> list[Path]:
        """Files the base case, its linked cases and the grid values name: a duty-cycle CSV, a
        ``map.nc``, a DXF drawing (not the linked cases, whose content is in
        :attr:`documents`).  Every text value of a case that is the path of a regular file
        counts (relative to the folder of the case it is in), so a field added to a case model
        later is covered without a list to keep up."""
        found: dict[Path, None] = {}
        linked = {path.resolve() for path in self.link_files.values()}

        def folder(document: tuple) -> Path:
            return self.base_dir if document == MAIN else self.link_files[document].parent

        named = [(key, doc) for key, doc in self.documents.items()]
        named += [(f.location.document, value) for f in self.grid_factors
                  if f.location is not None for value in f.values]
        for document, data in named:
            for text in _texts(data):
                path = _regular_file(folder(document), text)
                if path is not None and path not in linked:
                    found[path] = None
        return list(found)

    def file_digests(self) -> dict[str, str]:
        """``{path: sha256 of its content}`` of every file the case references
        (:meth:`referenced_files`)."""
        return file_digests(self.referenced_files())

    def fingerprint(self, digests: dict[str, str] | None = None) -> str:
        """Hash of everything that decides the runs' results (for ``--resume``): the case
        documents, the runs' values and the content of every file the case reads
        (:meth:`file_digests`, computed unless given)."""
        digests = self.file_digests() if digests is None else digests
        text = json.dumps({
            "sealsim": __version__, "model": self.model,
            "documents": {".".join(map(str, k)): v for k, v in self.documents.items()},
            "files": digests,
            "series": None if self.series is None else self.series.model_dump(),
            "runs": [[(loc.text(), value) for loc, value in self.assignments(i)]
                     for i in range(self.n_runs)],
        }, sort_keys=True, default=str)
        return hashlib.sha256(text.encode("utf-8")).hexdigest()

    def resolved_cases(self) -> dict[str, str]:
        """Resolved TOML (all defaults filled in) of the base case and its linked cases."""
        out = {}
        for key, case in _validate_documents(self.model, self.documents).items():
            label = "case" if key == MAIN else ".".join(map(str, key))
            out[label] = dump_case_toml(case, header=f"Resolved base case of the study "
                                                     f"{self.source.name} ({label}), written "
                                                     f"by sealsim {__version__}")
        return out


# -- loading -----------------------------------------------------------------------------------
def load_study(path: str | Path) -> Study:
    """Read and validate a study file (see the module docstring)."""
    path = Path(path)
    text = read_input_text(path, "study file")
    return parse_study(parse_toml(text, f"study file {str(path)!r}"), path, text)


def parse_study(data: dict, source: Path, text: str = "") -> Study:
    """Validate study data read from ``source`` (relative paths are taken from its folder)."""
    where = f"study {str(source)!r}"
    try:
        spec = StudyFile.model_validate(data)
    except ValidationError as exc:
        raise InputError(format_validation_error(exc, where, StudyFile)) from None
    st = spec.study
    model = MODELS[st.model]
    documents, links, base_dir, inputs = _base_documents(spec, source, where)
    inputs = [source, *inputs, *links.values()]

    constants, derived = _set_table(spec.set, documents, {f.name for f in spec.factors}, where)
    for location, value in constants:
        assign(documents, location, value)
    # factor paths point into the case as [set] leaves it (duty.steps replaced by one step)
    factors = [_factor(f, documents, st.design, where) for f in spec.factors]
    _check_names(spec, factors, where)
    try:
        _validate_documents(st.model, documents)
    except InputError as exc:
        raise InputError(f"{where}: the base case{' with [set]' if constants else ''} is "
                         f"invalid: {_strip(exc)}") from None
    used = {node.id for _, _, tree in derived for node in _names(tree)}
    for f in factors:
        if f.location is None and f.name not in used:
            raise InputError(f"{where}: factor {f.name!r} has no path and no [set] expression "
                             "uses it; give path = 'table.field' or remove it")

    outputs = [Output(name, o if isinstance(o, str) else o.path,
                      (o.unit if not isinstance(o, str) and o.unit else unit_from_key(
                          o if isinstance(o, str) else o.path)))
               for name, o in spec.outputs.items()]
    series_interval = _series(spec.series, model, where)

    study = Study(source=source, title=spec.title, description=spec.description,
                  model=st.model, design=st.design, seed=st.seed, samples=st.samples,
                  batch_size=st.batch_size, documents=documents, link_files=links,
                  base_dir=base_dir, factors=factors, derived=derived, outputs=outputs,
                  series=spec.series, series_interval=series_interval, inputs=inputs,
                  text=text)
    _design(study, st, where)
    _check_factor_values(study, where)
    known = {Path(p).resolve() for p in study.inputs}
    study.inputs += [p for p in study.referenced_files() if p not in known]
    return study


def _texts(data: Any):
    """Every text value in nested case data."""
    stack = [data]
    while stack:
        node = stack.pop()
        if isinstance(node, str):
            yield node
        elif isinstance(node, dict):
            stack.extend(node.values())
        elif isinstance(node, list):
            stack.extend(node)


def _regular_file(folder: Path, text: str) -> Path | None:
    """The regular file ``text`` names (relative to ``folder``), if it is one."""
    if not text.strip() or len(text) > 4096 or "\0" in text:
        return None
    path = Path(text)
    path = (path if path.is_absolute() else folder / path).resolve()
    try:
        return path if stat.S_ISREG(os.stat(path).st_mode) else None
    except (OSError, ValueError):
        return None


def _strip(exc: Exception) -> str:
    return re.sub(r"^invalid [^:]*: ", "", str(exc))


def _names(tree):
    import ast

    return [n for n in ast.walk(tree) if isinstance(n, ast.Name)]


def _base_documents(spec: StudyFile, source: Path, where: str):
    st = spec.study
    inputs: list[Path] = []
    if (st.case is None) == (spec.base is None):
        raise InputError(f"{where}: give the base case either as study.case = 'case.toml' or "
                         "as an inline [base] table (not both)")
    if st.case is not None:
        case_path = Path(st.case)
        case_path = case_path if case_path.is_absolute() else source.parent / case_path
        data = load_toml(case_path)
        base_dir = case_path.parent.resolve()
        inputs.append(case_path)
        label = f"case {str(case_path)!r}"
    else:
        data = copy.deepcopy(spec.base)
        base_dir = source.parent.resolve()
        label = "[base]"
    variants = data.pop("variants", None)
    if st.variant is not None:
        if not isinstance(variants, dict) or st.variant not in variants:
            names = ", ".join(variants) if isinstance(variants, dict) else "(none)"
            raise InputError(f"{where}: study.variant = {st.variant!r} is not a variant of "
                             f"{label}; its variants: {names}")
        from sealsim.cases import apply_overrides

        data = apply_overrides(data, variants[st.variant])
    elif isinstance(variants, dict) and variants:
        raise InputError(f"{where}: {label} has variants ({', '.join(variants)}); choose one "
                         "with study.variant = 'NAME'")
    documents, links = linked_documents(data, base_dir, f"{where}: {label}")
    return documents, links, base_dir, inputs


def _validate_documents(model: str, documents: dict[tuple, dict]) -> dict:
    """Validate the case and its linked cases; ``{document key: case object}``."""
    import importlib

    spec = MODELS[model]
    cases = {MAIN: validate_case(spec.case_class(), documents[MAIN], "case")}
    if spec.check is not None:
        spec.check(cases[MAIN])
    for key, data in documents.items():
        if key == MAIN:
            continue
        module, name = LINKED_CASE_FIELDS[key[-1]]
        model_class = getattr(importlib.import_module(module), name)
        text = ".".join(map(str, key))
        cases[key] = validate_case(model_class, data, f"linked case {text}")
    return cases


def _quantity(value: Any, unit: str | None, where: str):
    """(magnitude, unit) of a number or quantity text; None for plain text."""
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float):
        if not math.isfinite(value):
            raise InputError(f"{where}: {value!r} is not a finite number")
        return float(value), unit or ""
    if isinstance(value, str) and _NUMBER_START.match(value):
        if unit:
            raise InputError(f"{where}: {value!r} has its own unit; with unit = {unit!r} give "
                             "plain numbers")
        try:
            q = ureg.Quantity(value)
        except Exception:
            raise InputError(f"{where}: cannot read {value!r} as a quantity such as "
                             "'2 mm'") from None
        if not isinstance(q, ureg.Quantity):
            return float(q), ""
        magnitude = float(q.magnitude)
        if not math.isfinite(magnitude):
            raise InputError(f"{where}: {value!r} is not finite")
        written = _NUMBER.sub("", value).strip()     # the unit as the user wrote it
        return magnitude, written if _same_unit(written, q) else f"{q.units:~C}"
    return None


def _same_unit(text: str, q) -> bool:
    try:
        return bool(text) and ureg.Quantity(1.0, text).units == q.units
    except Exception:
        return False


def _convert(magnitude: float, unit: str, target: str, where: str, difference=False) -> float:
    if unit == target:
        return magnitude
    try:
        if difference:
            return float(ureg.Quantity(magnitude, _delta(unit)).to(_delta(target)).magnitude)
        return float(ureg.Quantity(magnitude, unit or "").to(target or "").magnitude)
    except Exception:
        raise InputError(f"{where}: {magnitude!r} {unit} cannot be converted to "
                         f"{target or 'a plain number'}") from None


def _delta(unit: str) -> str:
    """The difference unit of an offset unit (degC -> delta_degC), else the unit itself."""
    if unit and ureg.Quantity(0.0, unit).to_base_units().magnitude != 0.0:
        return f"delta_{ureg.Unit(unit)}"
    return unit or ""


def _factor(spec: FactorSpec, documents: dict, design: str, where: str) -> Factor:
    here = f"{where}: factor {spec.name!r}"
    if not NAME.fullmatch(spec.name) or spec.name in RESERVED:
        raise InputError(f"{here}: the name must be letters, digits and '_' (not first a "
                         f"digit), not one of {', '.join(sorted(RESERVED))}")
    location = None
    if spec.path is not None:
        try:
            location = resolve(spec.path, documents)
        except InputError as exc:
            raise InputError(f"{here} (path {spec.path!r}): {exc}") from None
    kinds = [k for k in ("values", "range", "distribution") if getattr(spec, k) is not None]
    if len(kinds) != 1:
        raise InputError(f"{here}: give exactly one of values = [...], range = {{...}} or "
                         f"distribution = '...'" + (f" (got {', '.join(kinds)})" if kinds else ""))
    common = {"name": spec.name, "path": spec.path, "location": location,
              "description": spec.description}
    if spec.distribution is None:
        for p in ("mean", "std", "lower", "upper"):
            if getattr(spec, p) is not None:
                raise InputError(f"{here}: {p} belongs to a distribution; a grid factor has "
                                 "values or a range")
        values, coords, unit = _grid_values(spec, here)
        return Factor(kind="grid", unit=unit, values=values, coords=coords, **common)
    if design == "grid":
        raise InputError(f"{here}: a distribution needs a sampled design: study.design = "
                         f"'latin_hypercube', 'monte_carlo' or 'sobol' (with study.samples)")
    needed = doe.DISTRIBUTIONS[spec.distribution]
    missing = [p for p in needed if getattr(spec, p) is None]
    extra = [p for p in ("mean", "std", "lower", "upper")
             if p not in needed and getattr(spec, p) is not None]
    if missing or extra:
        raise InputError(f"{here}: distribution {spec.distribution!r} takes "
                         f"{', '.join(needed)}" + (f"; missing {', '.join(missing)}" if missing
                                                   else "")
                         + (f"; {', '.join(extra)} does not belong to it" if extra else ""))
    parsed = {}
    for p in needed:
        q = _quantity(getattr(spec, p), spec.unit, f"{here}: {p}")
        if q is None:
            raise InputError(f"{here}: {p} = {getattr(spec, p)!r} is not a number or a "
                             "quantity such as '2 mm'")
        parsed[p] = q
    unit = parsed[needed[0]][1]
    params = {p: _convert(m, u, unit, f"{here}: {p}", difference=(p == "std"))
              for p, (m, u) in parsed.items()}
    if "std" in params and not params["std"] > 0:
        raise InputError(f"{here}: std must be > 0 (got {params['std']!r} {unit})")
    if "lower" in params and not params["lower"] < params["upper"]:
        raise InputError(f"{here}: lower ({params['lower']!r} {unit}) must be below upper "
                         f"({params['upper']!r} {unit})")
    return Factor(kind="sampled", unit=unit, distribution=spec.distribution, params=params,
                  **common)


def _grid_values(spec: FactorSpec, here: str) -> tuple[list, list, str]:
    if spec.range is not None:
        r = spec.range
        if r.num == 0:
            raise InputError(f"{here}: range.num = 0 gives no runs; give num >= 1")
        start = _quantity(r.start, spec.unit, f"{here}: range.start")
        stop = _quantity(r.stop, spec.unit, f"{here}: range.stop")
        if start is None or stop is None:
            raise InputError(f"{here}: range.start and range.stop must be numbers or "
                             "quantities such as '500 rpm'")
        unit = start[1]
        a, b = start[0], _convert(*stop, unit, f"{here}: range.stop")
        if r.spacing == "log":
            if a <= 0 or b <= 0:
                raise InputError(f"{here}: a log range needs positive start and stop")
            numbers = np.geomspace(a, b, r.num)
        else:
            numbers = np.linspace(a, b, r.num)
        coords = [float(x) for x in numbers]
        return [f"{x!r} {unit}" if unit else x for x in coords], coords, unit
    values = spec.values
    if not values:
        raise InputError(f"{here}: values is empty, which gives zero runs; list at least one "
                         "value")
    if any(isinstance(v, list | dict) for v in values):   # whole lists or tables
        if spec.unit:
            raise InputError(f"{here}: unit = {spec.unit!r} needs numbers as values")
        coords = [json.dumps(v, sort_keys=True) for v in values]
        if len(set(coords)) != len(coords):
            raise InputError(f"{here}: values must be distinct (got {values!r})")
        return list(values), coords, ""
    parsed = [_quantity(v, spec.unit, f"{here}: values") for v in values]
    if all(p is None for p in parsed):            # text, e.g. oil names
        if spec.unit:
            raise InputError(f"{here}: unit = {spec.unit!r} needs numbers as values")
        if not all(isinstance(v, str) for v in values):
            raise InputError(f"{here}: values must all be numbers, quantities or texts")
        if len(set(values)) != len(values):
            raise InputError(f"{here}: values must be distinct (got {values!r})")
        return list(values), list(values), ""
    if any(p is None for p in parsed):
        raise InputError(f"{here}: values mix numbers and texts: {values!r}")
    bare = [v for v, (_, u) in zip(values, parsed) if not u]
    if bare and len(bare) < len(values):
        with_unit = next(v for v, (_, u) in zip(values, parsed) if u)
        raise InputError(f"{here}: values: {bare[0]!r} has no unit, {with_unit!r} has one; "
                         "give every value its unit (or unit = '...' and plain numbers)")
    unit = parsed[0][1]
    coords = [_convert(m, u, unit, f"{here}: values") for m, u in parsed]
    if spec.unit:
        values = [f"{v!r} {spec.unit}" for v in values]
    if len(set(coords)) != len(coords):
        raise InputError(f"{here}: values must be distinct (got {values!r})")
    return list(values), coords, unit


def _check_names(spec: StudyFile, factors: list[Factor], where: str) -> None:
    if not factors:
        raise InputError(f"{where}: the study has no [[factors]], which gives nothing to "
                         "vary; add at least one")
    seen: set[str] = set()
    for f in factors:
        if f.name in seen:
            raise InputError(f"{where}: factor {f.name!r} is defined twice")
        seen.add(f.name)
    paths = [f.location.text() for f in factors if f.location is not None]
    for p in paths:
        if paths.count(p) > 1:
            raise InputError(f"{where}: two factors change the same field {p!r}")
    for name in spec.outputs:
        if not NAME.fullmatch(name) or name in RESERVED or name in seen:
            raise InputError(f"{where}: output name {name!r} must be letters, digits and '_' "
                             "and differ from the factor names and from "
                             f"{', '.join(sorted(RESERVED))}")


def _flat_set(table: dict, prefix: str = "") -> list[tuple[str, Any]]:
    out = []
    for key, value in table.items():
        if isinstance(value, dict):
            out += _flat_set(value, f"{prefix}{key}.")
        else:
            out.append((f"{prefix}{key}", value))
    return out


def _set_table(table: dict, documents: dict, names: set[str], where: str):
    constants, derived = [], []
    for path, value in _flat_set(table):
        here = f"{where}: [set] {path!r}"
        try:
            location = resolve(path, documents)
        except InputError as exc:
            raise InputError(f"{here}: {exc}") from None
        if isinstance(value, str) and value.lstrip().startswith("="):
            text = value.lstrip()[1:]
            derived.append((location, text, expressions.check_expression(text, names, here)))
        else:
            constants.append((location, value))
    return constants, derived


def _series(spec: SeriesSpec | None, model, where: str) -> float | None:
    if spec is None:
        return None
    if model.series_axis is None and model.name != "structure_map":
        raise InputError(f"{where}: model {model.name!r} has no series; remove [series]")
    if model.series_axis == "time":
        if spec.interval is None:
            raise InputError(f"{where}: series.interval is required for model "
                             f"{model.name!r} (time series are resampled), e.g. '10 ms'")
        return parse_quantity(spec.interval, "time", "series.interval")
    if spec.interval is not None:
        raise InputError(f"{where}: series.interval applies to time series only; model "
                         f"{model.name!r} has none")
    return None


def _design(study: Study, st: StudyTable, where: str) -> None:
    sampled = study.sampled_factors
    if study.design == "grid":
        if st.samples is not None:
            raise InputError(f"{where}: study.samples applies to sampled designs; with "
                             "design = 'grid' the runs are the grid values")
    else:
        if not sampled:
            raise InputError(f"{where}: design {study.design!r} samples factors, but no factor "
                             "has a distribution")
        if st.samples is None or st.samples < 1:
            raise InputError(f"{where}: study.samples = {st.samples!r} gives zero runs; design "
                             f"{study.design!r} needs study.samples >= 1")
        if study.design == "sobol" and (st.samples & (st.samples - 1)):
            raise InputError(f"{where}: study.samples = {st.samples} for design 'sobol' must "
                             "be a power of 2 (Sobol' sequence), e.g. 64")
    # the size is checked before anything is generated (samples = 1e10 is a slip, not a job)
    grid = math.prod(len(f.values) for f in study.grid_factors)
    n_runs = grid * (doe.sample_count(study.design, st.samples, len(sampled))
                     if study.sampled else 1)
    if n_runs > st.max_runs:
        shape = " x ".join([*(f"{len(f.values)} {f.name}" for f in study.grid_factors),
                            *([f"{n_runs // grid} samples"] if study.sampled else [])])
        raise InputError(f"{where}: the study has {n_runs} runs ({shape}), more than "
                         f"study.max_runs = {st.max_runs}; raise max_runs (at most "
                         f"{MAX_RUNS_LIMIT}) to run it")
    if study.sampled:
        u = doe.unit_samples(study.design, st.samples, len(sampled), st.seed)
        study.sample_values = np.column_stack([
            doe.ppf(u[:, j], f.distribution, **f.params) for j, f in enumerate(sampled)])


def _check_factor_values(study: Study, where: str) -> None:
    """Validate the case with every grid value and with each distribution's bounds (the
    other factors at their nominal values); an unbounded distribution must be accepted
    everywhere."""
    nominal = {f.name: f.nominal() for f in study.factors}

    def check(f: Factor, x: Any, why: str = "") -> None:
        values = dict(nominal, **{f.name: x})
        try:
            documents = study.run_documents(study._assignments(values))
            _validate_documents(study.model, documents)
        except InputError as exc:
            shown = f"{x!r} {f.unit}".strip() if not isinstance(x, str) else repr(x)
            path = f" ({f.path})" if f.path else ""
            raise InputError(f"{where}: factor {f.name!r}{path} = {shown}: {why}"
                             f"{_strip(exc)}") from None

    for f in study.factors:
        if f.kind == "grid":
            for x in f.coords:
                check(f, x)
            continue
        p = f.params
        if f.distribution == "normal":
            reach = _PROBE_SIGMAS * p["std"]
            for x in (p["mean"] - reach, p["mean"] + reach):
                check(f, x, "distribution 'normal' has no bounds, but the case does not take "
                            "every value (use 'truncnormal' with lower and upper, or "
                            "'uniform'): ")
        else:
            for x in (p["lower"], p["upper"]):
                check(f, x)
