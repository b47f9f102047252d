"""Oil and elastomer files -- the built-in catalogue and your own -- read like case files.

Quantities are strings with units, parsed by pint (:func:`sealsim.cases.Q`), and every entry
is validated by a pydantic model, so an unknown or missing field, a missing or wrong unit and
a value out of range give one :class:`~sealsim.errors.InputError` naming the file, the entry
and the field.  An oil file (``data/oils.toml``, ``--oil-file``)::

    [oils."VG68-mineral"]
    family = "mineral"                  # mineral | PAO | PAG | ester | other
    nu40 = "68 mm^2/s"                  # or walther_A, walther_B (ASTM D341, mm^2/s and K)
    nu100 = "8.7 mm^2/s"
    density15 = "880 kg/m^3"
    min_temperature = "-24 degC"        # optional, see OilEntry for the others
    source = "datasheet of ..."

An elastomer file (``data/elastomers.toml``, ``--material-file``): one table per material,
see :class:`ElastomerEntry`::

    [NBR]
    glass_transition = "-25 degC"
    service_min = "-40 degC"
    service_max = "100 degC"
    density = "1250 kg/m^3"
    ...
    [NBR.modulus]
    glassy = "2000 MPa"
    rubbery = "2.68 MPa"

Files in the older format, with plain numbers and the unit in the key name
(``nu40_mm2_s = 68.0``, ``glass_transition_C = -25``, ``c10_MPa = 1.0``), are still read: each
such key is turned into its field with a unit string (:data:`LEGACY_OIL_KEYS`,
:data:`LEGACY_ELASTOMER_KEYS`) before validation, and error messages say so.

This module holds the file models and reads the tables; :mod:`sealsim.properties.oils` and
:mod:`sealsim.properties.elastomers` build their records from them (and import this module
only when a file is read, so importing them stays free of pydantic and pint).

Examples
--------
>>> entry = OilEntry.model_validate({"family": "mineral", "nu40": "68 mm^2/s",
...                                  "nu100": "8.7 mm^2/s", "density15": "880 kg/m^3"},
...                                 context={"require_units": True})
>>> entry.nu40, entry.density15
(6.8e-05, 880.0)
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import pydantic
from pydantic import ConfigDict, Field, PrivateAttr, model_validator

from sealsim.cases import CaseModel, Q, parse_toml, validation_problems
from sealsim.errors import InputError
from sealsim.properties.oil_limits import (
    EXPANSION_MAX,
    PRESSURE_VISCOSITY_MAX,
    RHO15_RANGE,
    SPECIFIC_HEAT_RANGE,
    THERMAL_CONDUCTIVITY_RANGE,
)

__all__ = [
    "ELASTOMER_FIELD_KEYS",
    "LEGACY_ELASTOMER_KEYS",
    "LEGACY_OIL_KEYS",
    "CatalogueOilEntry",
    "DMATable",
    "ElastomerEntry",
    "HyperelasticTable",
    "ModulusTable",
    "OilEntry",
    "PronyTable",
    "WLFTable",
    "elastomer_key",
    "oil_table",
    "read_elastomer_table",
    "read_elastomer_tables",
    "read_oil_tables",
]


# -- oils -------------------------------------------------------------------------------------
#: density15 of an oil table: the range that :class:`~sealsim.properties.oils.Oil` allows, so
#: that a value outside it is named as written in the file (not as Oil's ``rho15``)
DENSITY15 = Q("density", ge=RHO15_RANGE[0], le=RHO15_RANGE[1])


class OilEntry(CaseModel):
    """One oil of an oil file (``[oils."NAME"]``): datasheet values with units.

    The viscosity-temperature line comes from ``nu40`` and ``nu100`` or from the ASTM D341
    constants ``walther_A`` and ``walther_B`` (for ν in mm²/s and T in K).  Fields left out
    get the defaults of :class:`~sealsim.properties.oils.Oil` (per family), which also checks
    the physical ranges.
    """

    family: str = Field(description="mineral, PAO, PAG, ester or other")
    nu40: Q("kinematic_viscosity", gt=0) | None = None
    nu100: Q("kinematic_viscosity", gt=0) | None = None
    walther_A: float | None = None
    walther_B: float | None = Field(None, gt=0)
    density15: DENSITY15
    min_temperature: Q("temperature", gt=0) | None = Field(
        None, description="lowest temperature of use (pour point); default per family/grade")
    pressure_viscosity_coefficient: Q("inverse_pressure", ge=0,
                                      le=PRESSURE_VISCOSITY_MAX) | None = Field(
        None, description="Barus alpha, e.g. '20 1/GPa'; default per family")
    thermal_conductivity: Q("thermal_conductivity", ge=THERMAL_CONDUCTIVITY_RANGE[0],
                            le=THERMAL_CONDUCTIVITY_RANGE[1]) | None = Field(
        None, description="constant k; default Cragoe (PAO, PAG: constants)")
    specific_heat: Q("specific_heat", ge=SPECIFIC_HEAT_RANGE[0],
                     le=SPECIFIC_HEAT_RANGE[1]) | None = Field(
        None, description="constant c_p; default Cragoe (PAO, PAG: constants)")
    thermal_expansion: Q("thermal_expansion", ge=0, le=EXPANSION_MAX) | None = Field(
        None, description=("thermal expansion coefficient at 15 degC of the density; default "
                           "ASTM D1250 for lubricating oils, 0.6278 kg/(m^3 K) / density15"))
    source: str | None = None

    @model_validator(mode="after")
    def _one_viscosity_source(self):
        has_nu = [self.nu40 is not None, self.nu100 is not None]
        has_ab = [self.walther_A is not None, self.walther_B is not None]
        if (any(has_nu) and any(has_ab)) or not (all(has_nu) or all(has_ab)):
            raise ValueError("give either nu40 and nu100, or walther_A and walther_B (not both)")
        return self

    def oil_arguments(self, origin: str = "") -> dict[str, Any]:
        """Keyword arguments of ``Oil.from_datasheet``/``Oil.from_walther`` besides the
        viscosity pair and the density (family, source and the optional values given)."""
        optional = {"pressure_viscosity_coefficient": self.pressure_viscosity_coefficient,
                    "thermal_conductivity_value": self.thermal_conductivity,
                    "specific_heat_value": self.specific_heat,
                    "thermal_expansion": self.thermal_expansion}
        kwargs: dict[str, Any] = {k: v for k, v in optional.items() if v is not None}
        if self.min_temperature is not None:
            # rounded as degC + 273.15 always was: -24 degC is 249.15 K, not 249.14999999999998
            kwargs["min_temperature"] = round(self.min_temperature, 9)
        kwargs["family"] = self.family
        kwargs["source"] = self.source if self.source is not None else f"oil file {origin}"
        return kwargs


def oil_table(oil) -> dict[str, Any]:
    """An :class:`~sealsim.properties.oils.Oil` as the table of an oil file or of a case's
    ``[oil]`` (without its name): ASTM D341 constants and every property with its unit, exact
    (``repr`` of the SI values), so that reading the table gives the same oil.

    Examples
    --------
    >>> from sealsim.properties.oils import get_oil
    >>> table = oil_table(get_oil("VG68"))
    >>> table["density15"], table["min_temperature"]
    ('880.0 kg/m^3', '249.15 K')
    """
    optional = {"thermal_conductivity": (oil.thermal_conductivity_value, "W/(m*K)"),
                "specific_heat": (oil.specific_heat_value, "J/(kg*K)")}
    return {"family": oil.family, "walther_A": oil.walther_A, "walther_B": oil.walther_B,
            "density15": f"{oil.rho15!r} kg/m^3",
            "min_temperature": f"{oil.min_temperature!r} K",
            "pressure_viscosity_coefficient": f"{oil.pressure_viscosity_coefficient!r} 1/Pa",
            "thermal_expansion": f"{oil.thermal_expansion!r} 1/K",
            **{key: f"{value!r} {unit}" for key, (value, unit) in optional.items()
               if value is not None},
            "source": oil.source}


class CatalogueOilEntry(OilEntry):
    """An oil of the built-in catalogue: may also give ``aliases`` (other names)."""

    aliases: list[str] = Field(default_factory=list)


#: older oil-file keys (unit in the name) -> (field, unit of the plain number)
LEGACY_OIL_KEYS = {
    "nu40_mm2_s": ("nu40", "mm^2/s"),
    "nu100_mm2_s": ("nu100", "mm^2/s"),
    "rho15_kg_m3": ("density15", "kg/m^3"),
    "min_temperature_degC": ("min_temperature", "degC"),
    "pressure_viscosity_coefficient_1_GPa": ("pressure_viscosity_coefficient", "1/GPa"),
    "thermal_conductivity_W_mK": ("thermal_conductivity", "W/(m*K)"),
    "specific_heat_J_kgK": ("specific_heat", "J/(kg*K)"),
    "thermal_expansion_1_K": ("thermal_expansion", "1/K"),
}


def read_oil_tables(text: str, origin: str, catalogue: bool = False
                    ) -> dict[str, tuple[OilEntry, str]]:
    """The validated entries of an oil file's text: ``{name: (entry, note)}``.

    ``note`` is empty, or says which older keys were read (to append to a later error).

    Parameters
    ----------
    text : str
        TOML text with ``[oils."NAME"]`` tables.
    origin : str
        Where the text comes from (a file name), for messages.
    catalogue : bool
        The built-in catalogue: entries may give ``aliases``.

    Raises
    ------
    InputError
        Invalid TOML or an invalid entry; the message names the oil and the field.
    """
    data = parse_toml(text, origin)
    extra = sorted(set(data) - {"oils"})
    if extra or not isinstance(data.get("oils"), dict):
        raise InputError(f"{origin}: expected only [oils.\"NAME\"] tables"
                         + (f"; unknown top-level key(s) {', '.join(extra)}" if extra else ""))
    model = CatalogueOilEntry if catalogue else OilEntry
    entries = {}
    for name, table in data["oils"].items():
        where = f"{origin}: oil {name!r}"
        if not isinstance(table, dict):
            raise InputError(f"{where}: expected a table of fields, got {table!r}")
        table, renamed = _upgrade_legacy(table, LEGACY_OIL_KEYS, where)
        names = _written_names({"": LEGACY_OIL_KEYS}) if renamed else {}
        entries[name] = (_validate(model, table, where, names), _legacy_note(renamed))
    return entries


# -- elastomers -------------------------------------------------------------------------------
class WLFTable(CaseModel):
    """``[NAME.wlf]``: WLF constants; default the universal ones (Williams, Landel & Ferry
    1955) at the glass transition."""

    c1: float | None = None
    c2: Q("temperature_difference") | None = None
    reference_temperature: Q("temperature") | None = Field(
        None, description="WLF reference temperature; default the glass transition")


class ModulusTable(CaseModel):
    """``[NAME.modulus]``: the storage-modulus master curve (see ``Elastomer``)."""

    glassy: Q("pressure")
    rubbery: Q("pressure") = Field(
        description="equilibrium rubbery plateau at the material's reference temperature")
    test_frequency: Q("frequency") = 1.0
    transition_log10_frequency: float | None = None
    transition_width_decades: float | None = None
    transition_asymmetry: float | None = None


class DMATable(CaseModel):
    """``[NAME.dma]``: measured storage moduli; overrides the parametric E(T) curve."""

    temperature: list[Q("temperature")] = Field(min_length=1)
    modulus: list[Q("pressure")] = Field(min_length=1)
    frequency: Q("frequency") | None = Field(
        None, description="frequency of the measurement; default modulus.test_frequency")


class PronyTable(CaseModel):
    """``[NAME.prony]``: Prony series E(t) = E_inf + sum E_i exp(-t/tau_i)."""

    equilibrium_modulus: Q("pressure")
    moduli: list[Q("pressure")] = Field(min_length=1)
    relaxation_times: list[Q("time")] = Field(min_length=1)
    reference_temperature: Q("temperature") | None = Field(
        None, description="default: the material's reference_temperature")


class HyperelasticTable(CaseModel):
    """``[NAME.hyperelastic]``: a strain-energy model other than the Mooney–Rivlin constants
    ``c10``/``c01`` for the FE model (:mod:`sealsim.properties.hyperelastic`), e.g.::

        [my_nbr.hyperelastic]
        model = "ogden"
        mu = ["0.55 MPa", "0.0012 MPa", "-0.008 MPa"]   # stresses with units
        alpha = [1.3, 5.0, -2.0]                         # shape parameters: plain numbers
    """

    model_config = ConfigDict(extra="allow", frozen=True)

    model: str
    _si: tuple = PrivateAttr(default=())

    @model_validator(mode="after")
    def _parameters(self):
        from sealsim.properties.hyperelastic import (
            HYPERELASTIC_MODELS,
            check_hyperelastic,
            model_name,
        )
        from sealsim.units import parse_quantity

        try:
            spec = HYPERELASTIC_MODELS[model_name(self.model)]
            given = dict(self.model_extra or {})
            values = {}
            for name, raw in given.items():
                dimension = "pressure" if name in spec.stresses else "dimensionless"
                items = raw if isinstance(raw, list) else [raw]
                si = [parse_quantity(v, dimension, name) for v in items]
                values[name] = si if isinstance(raw, list) else si[0]
            self._si = check_hyperelastic(spec.name, values)
        except InputError as exc:
            raise ValueError(str(exc)) from None
        return self

    def hyperelastic(self) -> tuple:
        """``(model, ((parameter, SI value), ...))`` of
        :func:`~sealsim.properties.hyperelastic.check_hyperelastic`."""
        return self._si


class ElastomerEntry(CaseModel):
    """One material of an elastomer file: a top-level ``[NAME]`` table with sub-tables.

    Hyperelastic constants ``c10``, ``c01``, ``bulk_modulus`` hold at ``reference_temperature``
    and the modulus test frequency.  The physical ranges (e.g. density 800-2500 kg/m³) are
    checked by :class:`~sealsim.properties.elastomers.Elastomer`.
    """

    name: str | None = Field(None, description="default: the table's key")
    description: str = ""
    source: str = "user-defined"
    hardness_shore_a: float | None = None
    glass_transition: Q("temperature")
    reference_temperature: Q("temperature") = 296.15
    service_min: Q("temperature")
    service_max: Q("temperature")
    density: Q("density")
    thermal_conductivity: Q("thermal_conductivity")
    specific_heat: Q("specific_heat")
    thermal_expansion: Q("thermal_expansion") = Field(
        description="linear thermal expansion coefficient")
    glassy_thermal_expansion: Q("thermal_expansion") | None = Field(None, description=(
        "linear expansion coefficient of the glass (e.g. from dilatometry); default the "
        "Simha-Boyer estimate 0.31 x thermal_expansion"))
    c10: Q("pressure") | None = Field(None, description=(
        "Mooney-Rivlin C10; with a [NAME.hyperelastic] table default mu0/2 of that model"))
    c01: Q("pressure") | None = Field(None, description=(
        "Mooney-Rivlin C01; with a [NAME.hyperelastic] table default 0"))
    bulk_modulus: Q("pressure")
    wlf: WLFTable = WLFTable()
    modulus: ModulusTable
    dma: DMATable | None = None
    prony: PronyTable | None = None
    hyperelastic: HyperelasticTable | None = None

    @model_validator(mode="after")
    def _mooney_rivlin_or_model(self):
        if self.hyperelastic is None:
            missing = [k for k in ("c10", "c01") if getattr(self, k) is None]
            if missing:
                raise ValueError(f"give {' and '.join(missing)} (Mooney-Rivlin constants), or "
                                 "a [NAME.hyperelastic] table with another strain energy")
            return self
        from sealsim.properties.hyperelastic import initial_shear_modulus

        model, params = self.hyperelastic.hyperelastic()
        mu0 = initial_shear_modulus(model, dict(params))
        c10 = 0.5 * mu0 if self.c10 is None else self.c10
        c01 = 0.0 if self.c01 is None else self.c01
        if abs(2.0 * (c10 + c01) - mu0) > 1e-3 * mu0:
            raise ValueError(f"c10 and c01 give the shear modulus 2(c10 + c01) = "
                             f"{2e-6 * (c10 + c01):.6g} MPa, but the [NAME.hyperelastic] "
                             f"{model} model has {mu0 * 1e-6:.6g} MPa: leave c10/c01 out "
                             "(they default to its neo-Hookean equivalent) or make them agree")
        object.__setattr__(self, "c10", c10)
        object.__setattr__(self, "c01", c01)
        return self

    def elastomer_arguments(self, name: str) -> dict[str, Any]:
        """Keyword arguments of ``Elastomer(...)``; values not given are left out (the
        Elastomer defaults apply; ``wlf_c1``/``wlf_c2`` are then the caller's)."""
        wlf, modulus = self.wlf, self.modulus
        given = {
            "name": name, "description": self.description, "source": self.source,
            "hardness_shore_a": self.hardness_shore_a, "glass_transition": self.glass_transition,
            "reference_temperature": self.reference_temperature,
            "service_range": (self.service_min, self.service_max), "density": self.density,
            "thermal_conductivity": self.thermal_conductivity,
            "specific_heat": self.specific_heat, "thermal_expansion": self.thermal_expansion,
            "glassy_thermal_expansion": self.glassy_thermal_expansion,
            "c10": self.c10, "c01": self.c01, "bulk_modulus": self.bulk_modulus,
            "wlf_c1": wlf.c1, "wlf_c2": wlf.c2,
            "wlf_reference_temperature": (self.glass_transition
                                          if wlf.reference_temperature is None
                                          else wlf.reference_temperature),
            "glassy_modulus": modulus.glassy, "rubbery_modulus": modulus.rubbery,
            "test_frequency": modulus.test_frequency,
            "transition_location": modulus.transition_log10_frequency,
            "transition_width": modulus.transition_width_decades,
            "transition_asymmetry": modulus.transition_asymmetry}
        if self.dma is not None:
            given["dma_table"] = (tuple(self.dma.temperature), tuple(self.dma.modulus))
            given["dma_frequency"] = self.dma.frequency
        if self.prony is not None:
            given["prony"] = (self.prony.equilibrium_modulus, tuple(self.prony.moduli),
                              tuple(self.prony.relaxation_times))
            given["prony_reference_temperature"] = self.prony.reference_temperature
        if self.hyperelastic is not None:
            given["hyperelastic"] = self.hyperelastic.hyperelastic()
        return {k: v for k, v in given.items() if v is not None}


#: where each Elastomer field is written in a file (for messages of its physical checks)
ELASTOMER_FIELD_KEYS = {
    "wlf_c1": "wlf.c1", "wlf_c2": "wlf.c2",
    "wlf_reference_temperature": "wlf.reference_temperature",
    "glassy_modulus": "modulus.glassy", "rubbery_modulus": "modulus.rubbery",
    "test_frequency": "modulus.test_frequency",
    "transition_location": "modulus.transition_log10_frequency",
    "transition_width": "modulus.transition_width_decades",
    "transition_asymmetry": "modulus.transition_asymmetry",
    "service_range": "service_min/service_max", "dma_table": "dma.temperature/dma.modulus",
    "dma_frequency": "dma.frequency", "prony": "prony",
    "prony_reference_temperature": "prony.reference_temperature",
}

#: older elastomer-file keys (unit in the name) -> (field, unit), per table ("" = top level)
LEGACY_ELASTOMER_KEYS = {
    "": {"glass_transition_C": ("glass_transition", "degC"),
         "reference_temperature_C": ("reference_temperature", "degC"),
         "service_min_C": ("service_min", "degC"), "service_max_C": ("service_max", "degC"),
         "density_kg_m3": ("density", "kg/m^3"),
         "thermal_conductivity_W_mK": ("thermal_conductivity", "W/(m*K)"),
         "specific_heat_J_kgK": ("specific_heat", "J/(kg*K)"),
         "thermal_expansion_per_K": ("thermal_expansion", "1/K"),
         "c10_MPa": ("c10", "MPa"), "c01_MPa": ("c01", "MPa"),
         "bulk_modulus_MPa": ("bulk_modulus", "MPa")},
    "wlf": {"c2_K": ("c2", "K"), "reference_temperature_C": ("reference_temperature", "degC")},
    "modulus": {"glassy_MPa": ("glassy", "MPa"), "rubbery_MPa": ("rubbery", "MPa"),
                "test_frequency_Hz": ("test_frequency", "Hz")},
    "dma": {"temperature_C": ("temperature", "degC"), "modulus_MPa": ("modulus", "MPa"),
            "frequency_Hz": ("frequency", "Hz")},
    "prony": {"equilibrium_modulus_MPa": ("equilibrium_modulus", "MPa"),
              "moduli_MPa": ("moduli", "MPa"), "relaxation_times_s": ("relaxation_times", "s"),
              "reference_temperature_C": ("reference_temperature", "degC")},
}


def read_elastomer_table(table: Mapping[str, Any], name: str | None = None, origin: str = ""
                         ) -> tuple[str, ElastomerEntry, str, dict[str, str]]:
    """Validate one material table of an elastomer file.

    Parameters
    ----------
    table : mapping
        The material's table (quantities with units, or the older format).
    name : str, optional
        Material name; default ``table["name"]``.
    origin : str
        Where the table comes from (a file name), for messages.

    Returns
    -------
    name, entry, where, names
        The material name, the validated entry, the place for messages
        (``"FILE: elastomer 'NAME'"``) and, for a table in the older format, the keys as
        written in it by field (``{"modulus.glassy": "modulus.glassy_MPa"}``), else ``{}``.

    Raises
    ------
    InputError
        Naming the material and the field.
    """
    if not isinstance(table, Mapping):
        raise InputError(f"an elastomer must be given as a table (mapping); got "
                         f"{type(table).__name__}")
    name = name if name is not None else table.get("name")
    if not isinstance(name, str) or not name.strip():
        raise InputError(f"elastomer field 'name' must be a non-empty string; got {name!r}")
    where = f"{origin}: elastomer {name!r}" if origin else f"elastomer {name!r}"
    data, renamed = _upgrade_legacy(table, LEGACY_ELASTOMER_KEYS[""], where)
    legacy = bool(renamed)
    for section, keys in LEGACY_ELASTOMER_KEYS.items():
        if section and isinstance(data.get(section), Mapping):
            data[section], renamed = _upgrade_legacy(data[section], keys, f"{where} [{section}]")
            legacy = legacy or bool(renamed)
    names = _written_names(LEGACY_ELASTOMER_KEYS) if legacy else {}
    return name, _validate(ElastomerEntry, data, where, names), where, names


def elastomer_key(field: str, names: Mapping[str, str]) -> str:
    """Where an :class:`~sealsim.properties.elastomers.Elastomer` field is written in a file
    (``names``: the older keys of :func:`read_elastomer_table`, or ``{}``).

    Examples
    --------
    >>> elastomer_key("glassy_modulus", {})
    'modulus.glassy'
    >>> elastomer_key("service_range", _written_names(LEGACY_ELASTOMER_KEYS))
    'service_min_C/service_max_C'
    """
    key = ELASTOMER_FIELD_KEYS.get(field, field)
    return "/".join(names.get(part, part) for part in key.split("/"))


def read_elastomer_tables(text: str, origin: str
                          ) -> dict[str, tuple[str, ElastomerEntry, str, dict[str, str]]]:
    """Every material table of an elastomer file's text, by table key (see
    :func:`read_elastomer_table`)."""
    out = {}
    for key, table in parse_toml(text, origin).items():
        if not isinstance(table, Mapping):
            raise InputError(f"{origin}: top-level key {key!r} must be a material table")
        out[key] = read_elastomer_table(table, table.get("name", key), origin)
    if not out:
        raise InputError(f"{origin} holds no material table")
    return out


# -- shared -----------------------------------------------------------------------------------
def _upgrade_legacy(table: Mapping[str, Any], legacy: Mapping[str, tuple[str, str]],
                    where: str) -> tuple[dict[str, Any], dict[str, str]]:
    """The table with older keys (``nu40_mm2_s = 68.0``) as fields with units
    (``nu40 = "68.0 mm^2/s"``), and ``{old key: field}`` of what was renamed."""
    data, renamed = dict(table), {}
    for old, (new, unit) in legacy.items():
        if old not in data:
            continue
        if new in data:
            raise InputError(f"{where}: give {new} or {old} (the older form), not both")
        value = data.pop(old)
        values = value if isinstance(value, list) else [value]
        if not values or any(isinstance(v, bool) or not isinstance(v, int | float)
                             for v in values):
            raise InputError(f"{where}: field '{old}' must be a number (or a list of numbers) "
                             f"in {unit}, got {value!r}; or write {new} = \"... {unit}\"")
        strings = [f"{v!r} {unit}" for v in values]
        data[new] = strings if isinstance(value, list) else strings[0]
        renamed[old] = new
    return data, renamed


def _legacy_note(renamed: Mapping[str, str]) -> str:
    if not renamed:
        return ""
    return (" (older file format with units in the key names, read as "
            + ", ".join(f"{old} -> {new}" for old, new in renamed.items()) + ")")


def _written_names(legacy: Mapping[str, Mapping[str, tuple[str, str]]]) -> dict[str, str]:
    """``{field path: older key path}`` of a legacy-key table (per section, "" = top)."""
    return {f"{section}.{new}" if section else new: f"{section}.{old}" if section else old
            for section, keys in legacy.items() for old, (new, _) in keys.items()}


def _validate(model, data: dict[str, Any], where: str, names: Mapping[str, str]):
    """Validate like a case file; problems in a table of the older format name the fields
    as written there (``nu40_mm2_s``, not ``nu40``)."""
    try:
        return model.model_validate(data, context={"require_units": True})
    except pydantic.ValidationError as exc:
        problems = validation_problems(exc, model)
        if names:
            for k, err in enumerate(exc.errors(include_url=False)):
                loc = ".".join(str(p) for p in err["loc"])
                if loc in names and problems[k].startswith(f"{loc}: "):
                    problems[k] = f"{names[loc]}: {problems[k][len(loc) + 2:]}"
        text = problems[0] if len(problems) == 1 else "".join(f"\n  {p}" for p in problems)
        note = (" (older file format with units in the key names; the fields are now written "
                "with units, e.g. nu40 = \"68 mm^2/s\")" if names else "")
        raise InputError(f"invalid {where}: {text}{note}") from None
