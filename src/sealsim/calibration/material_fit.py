"""Material fit files: a compound's tests in, a compound file (catalogue format) out.

``sealsim material fit DATA.toml --out DIR`` and :func:`fit_material_file`.  A fit file
(``examples/materials/treloar_ogden.toml``)::

    title = "..."

    [compound]                         # the compound file's name and what was not measured
    name = "my_nbr"
    base = "NBR"                       # catalogue entry for properties not given or fitted
    reference_temperature = "23 degC"  # temperature of the stress-strain tests
    hardness_shore_a = 72              # optional; alone it gives Gent's estimate (fallback)
    density = "1230 kg/m^3"            # optional overrides of the base (any catalogue field)

    [hyperelastic]
    model = "ogden"                    # neo_hooke, mooney_rivlin, yeoh, ogden, arruda_boyce,
    terms = 3                          # third_order_deformation
    compare = [{ model = "mooney_rivlin", fit_modes = ["uniaxial"] }]

    [[hyperelastic.curves]]
    name = "uniaxial"
    mode = "uniaxial"                  # uniaxial | equibiaxial | planar
    file = "data/uniaxial.csv"
    delimiter = ","
    header = true
    columns = { stretch = { column = "stretch", unit = "1" },      # or strain, e.g. "%"
                stress = { column = "nominal_stress", unit = "kgf/cm^2" } }
    role = "fit"                       # or "validate" (predicted, not fitted)

    [viscoelastic]                     # DMA frequency sweeps at several temperatures
    files = [{ file = "dma.csv", delimiter = ",", header = true, columns = {
               frequency = { column = "f", unit = "Hz" }, temperature = { column = "T",
               unit = "degC" }, storage_modulus = { column = "E1", unit = "MPa" },
               loss_modulus = { column = "E2", unit = "MPa" } } }]
    terms_per_decade = 2

    [dilatometry]                      # optional: strain vs temperature through T_g
    file = "dil.csv"
    columns = { temperature = {...}, linear_strain = {...} }   # or volume_strain

What the compound gets from where is written next to every value in the compound file and in
its ``source``: fitted, given in the fit file, or taken from the base catalogue entry.  With
neither stress-strain curves nor DMA data, the hardness alone gives the Mooney–Rivlin
constants by Gent's relation (:func:`sealsim.properties.rubber_modulus.shore_a_young_modulus`)
-- the weakest data, and the result says so.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field, model_validator
from scipy.optimize import brentq, least_squares

from sealsim.calibration.case import ColumnModel
from sealsim.calibration.hyperelastic_fit import Curve, HyperelasticFit, fit_hyperelastic
from sealsim.calibration.statistics import parameter_statistics
from sealsim.calibration.viscoelastic_fit import (
    DMAData,
    PronyFit,
    ShiftFit,
    fit_prony,
    fit_shift_law,
    isotherm_shifts,
    law_rel_rmse,
    master_curve,
    tan_delta_peak,
    tan_delta_peak_temperature,
)
from sealsim.cases import CaseModel, Q, load_toml, validate_case
from sealsim.errors import InputError
from sealsim.measurements.readers import ColumnSpec, read_table
from sealsim.properties.hyperelastic import HYPERELASTIC_MODELS
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["ExpansionFit", "MaterialFitCase", "MaterialFitResult", "compound_storage_errors",
           "fit_expansion",
           "fit_material", "fit_material_file", "load_material_fit_case"]

#: C01/C10 of Mooney-Rivlin constants derived from a single modulus (DMA E∞, Shore A): the
#: catalogue's starting ratio for filled rubbers [D] (see data/elastomers.toml)
MR_RATIO = 0.25

#: catalogue fields a fit file may give (quantities with units) instead of the base's
GIVEN_FIELDS = ("glass_transition", "service_min", "service_max", "density",
                "thermal_conductivity", "specific_heat", "thermal_expansion", "bulk_modulus")


class TableFile(CaseModel):
    """A measurement table: file (relative to the fit file), how to read it, its columns
    (a German lab's export: ``delimiter = ";"`` with ``decimal = ","``)."""

    file: str
    columns: dict[str, ColumnModel]
    delimiter: str | None = None
    decimal: Literal[".", ","] = "."
    header: bool = False
    skip_rows: int = Field(0, ge=0)

    def read(self, base: Path, name: str):
        specs = [ColumnSpec(q, c.column, c.unit, c.scale) for q, c in self.columns.items()]
        path = Path(self.file)
        return read_table(path if path.is_absolute() else base / path, specs,
                          delimiter=self.delimiter, decimal=self.decimal, header=self.header,
                          skip_rows=self.skip_rows, name=name, index=None).data


class CurveModel(TableFile):
    """One stress-strain curve: ``stretch`` (or engineering ``strain``) and nominal
    ``stress`` columns."""

    name: str = Field(min_length=1)
    mode: Literal["uniaxial", "equibiaxial", "planar"]
    role: Literal["fit", "validate"] = "fit"

    @model_validator(mode="after")
    def _columns(self):
        keys = set(self.columns)
        if "stress" not in keys or len(keys & {"stretch", "strain"}) != 1 \
                or keys - {"stress", "stretch", "strain"}:
            raise ValueError("columns must be stress and one of stretch or strain (e.g. "
                             "strain = { column = 1, unit = '%' })")
        return self


class CompareModel(CaseModel):
    """Another model fitted for comparison (reported and plotted, not written)."""

    model: str
    terms: Annotated[int, Field(ge=1, le=6)] | None = None
    fit_modes: list[Literal["uniaxial", "equibiaxial", "planar"]] | None = None


class HyperelasticSpec(CaseModel):
    """``[hyperelastic]``: the model written to the compound, comparisons, the curves."""

    model: str = "mooney_rivlin"
    terms: Annotated[int, Field(ge=1, le=6)] | None = None
    fit_modes: list[Literal["uniaxial", "equibiaxial", "planar"]] | None = None
    residuals: Literal["relative", "absolute"] = "relative"
    stability_range: tuple[float, float] | None = Field(None, description=(
        "stretch range of the Drucker check; default half the smallest to twice the largest "
        "stretch of the data"))
    compare: list[CompareModel] = Field(default_factory=list)
    curves: list[CurveModel] = Field(min_length=1)

    @model_validator(mode="after")
    def _unique(self):
        names = [c.name for c in self.curves]
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise ValueError(f"curve names must be unique, repeated: {dupes}")
        return self


class DMAFile(TableFile):
    """DMA points: frequency, temperature and storage/loss modulus (or complex modulus and
    tan_delta) columns."""

    @model_validator(mode="after")
    def _columns(self):
        keys = set(self.columns)
        need = {"frequency", "temperature"}
        pairs = ({"storage_modulus", "loss_modulus"}, {"complex_modulus", "tan_delta"},
                 {"storage_modulus", "tan_delta"})
        if not need <= keys or not any(p <= keys for p in pairs):
            raise ValueError("columns must include frequency, temperature and storage_modulus "
                             "+ loss_modulus (or complex_modulus + tan_delta, or "
                             "storage_modulus + tan_delta)")
        return self


class ViscoelasticSpec(CaseModel):
    """``[viscoelastic]``: DMA frequency sweeps to a master curve, WLF and a Prony series."""

    files: list[DMAFile] = Field(min_length=1)
    reference_temperature: Q("temperature", gt=0) | None = Field(None, description=(
        "temperature of the master curve and the Prony series; default the compound's "
        "reference_temperature"))
    terms_per_decade: float = Field(2.0, gt=0.0, le=10.0)
    smoothing: float | None = Field(None, ge=0.0)


class DilatometrySpec(TableFile):
    """``[dilatometry]``: temperature and linear (or volume) strain through the glass
    transition."""

    @model_validator(mode="after")
    def _columns(self):
        keys = set(self.columns)
        if "temperature" not in keys or len(keys & {"linear_strain", "volume_strain"}) != 1:
            raise ValueError("columns must be temperature and one of linear_strain or "
                             "volume_strain")
        return self


class CompoundSpec(CaseModel):
    """``[compound]``: name, base catalogue entry and properties given rather than fitted."""

    name: str = Field(min_length=1, pattern=r"^[A-Za-z0-9_.-]+$")
    description: str = ""
    source: str = Field("", description="where the specimens and tests come from")
    base: str | None = Field(None, description=(
        "catalogue elastomer for the properties neither measured nor given (NBR, HNBR, FKM, "
        "ACM, VMQ)"))
    reference_temperature: Q("temperature", gt=0)
    hardness_shore_a: Annotated[float, Field(ge=10.0, le=95.0)] | None = None
    glass_transition: Q("temperature", gt=0) | None = None
    service_min: Q("temperature", gt=0) | None = None
    service_max: Q("temperature", gt=0) | None = None
    density: Q("density", gt=0) | None = None
    thermal_conductivity: Q("thermal_conductivity", gt=0) | None = None
    specific_heat: Q("specific_heat", gt=0) | None = None
    thermal_expansion: Q("thermal_expansion", gt=0) | None = None
    bulk_modulus: Q("pressure", gt=0) | None = None


class MaterialFitCase(CaseModel):
    """A material fit file (see the module docstring)."""

    title: str = ""
    compound: CompoundSpec
    hyperelastic: HyperelasticSpec | None = None
    viscoelastic: ViscoelasticSpec | None = None
    dilatometry: DilatometrySpec | None = None


def load_material_fit_case(path: str | Path) -> MaterialFitCase:
    """Read and validate a material fit file (InputError naming the field)."""
    return validate_case(MaterialFitCase, load_toml(path), f"material fit file {str(path)!r}")


@dataclass
class ExpansionFit:
    """Bilinear thermal strain through T_g (SI)."""

    glass_transition: float
    rubbery: float
    glassy: float
    standard_errors: dict
    rel_rmse: float
    temperature: np.ndarray
    strain: np.ndarray
    notes: list[str] = field(default_factory=list)

    def model(self, temperature) -> np.ndarray:
        return _bilinear(np.asarray(temperature, dtype=float), self.glass_transition,
                         self.glassy, self.rubbery, self._offset)

    _offset: float = 0.0


def _bilinear(t, tg, alpha_g, alpha_r, offset):
    return offset + np.where(t < tg, alpha_g * (t - tg), alpha_r * (t - tg))


def fit_expansion(temperature, linear_strain) -> ExpansionFit:
    """Glassy and rubbery linear expansion coefficients and T_g from a dilatometry curve: a
    continuous two-line fit ε = ε_g + α (T − T_g) with α = α_g below and α_r above T_g
    (the classical dilatometric T_g, ISO 11359-2), least squares with standard errors.

    Examples
    --------
    >>> T = np.linspace(180.0, 300.0, 61)
    >>> eps = np.where(T < 225.0, 6e-5 * (T - 225.0), 2e-4 * (T - 225.0))
    >>> fit = fit_expansion(T, eps)
    >>> round(fit.glass_transition, 3), round(fit.rubbery * 1e4, 6), round(fit.glassy * 1e5, 6)
    (225.0, 2.0, 6.0)
    """
    t = np.asarray(temperature, dtype=float)
    e = np.asarray(linear_strain, dtype=float)
    if t.size < 6:
        raise InputError("a dilatometry curve needs at least 6 points")
    order = np.argsort(t)
    t, e = t[order], e[order]
    span = float(np.ptp(e)) or 1.0

    def resid(x):
        return (_bilinear(t, x[0], x[1] * 1e-4, x[2] * 1e-4, x[3]) - e) / span

    best = None
    for tg0 in np.linspace(t[2], t[-3], 7):
        x0 = [tg0, 0.5, 2.0, float(np.interp(tg0, t, e))]
        res = least_squares(resid, x0, bounds=([t[1], 0.0, 0.0, -np.inf],
                                               [t[-2], 50.0, 50.0, np.inf]))
        if best is None or res.cost < best.cost:
            best = res
    stats = parameter_statistics(best.jac, best.fun, values=best.x)
    se = stats["standard_errors"]
    fit = ExpansionFit(float(best.x[0]), float(best.x[2] * 1e-4), float(best.x[1] * 1e-4),
                       {"glass_transition": float(se[0]), "glassy": float(se[1] * 1e-4),
                        "rubbery": float(se[2] * 1e-4)},
                       float(np.sqrt(np.mean((best.fun * span / np.where(e != 0, e, np.inf))
                                             ** 2))), t, e)
    fit._offset = float(best.x[3])
    return fit


@dataclass
class MaterialFitResult:
    """Everything a material fit found (SI), and the compound file it gives."""

    case: MaterialFitCase
    curves: list[Curve]
    hyperelastic: HyperelasticFit | None
    comparisons: dict[str, HyperelasticFit]
    dma: DMAData | None
    shift: ShiftFit | None
    arrhenius: ShiftFit | None
    prony: PronyFit | None
    tan_delta_tg: float | None
    expansion: ExpansionFit | None
    compound_table: dict
    compound_text: str
    report: dict
    notes: list[str] = field(default_factory=list)

    def compound(self):
        """The compound file as an :class:`~sealsim.properties.elastomers.Elastomer`."""
        from sealsim.properties.elastomers import Elastomer

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return Elastomer.from_dict(self.compound_table, self.case.compound.name)


def fit_material_file(path: str | Path) -> MaterialFitResult:
    """Fit everything a material fit file asks for (see the module docstring)."""
    path = Path(path)
    return fit_material(load_material_fit_case(path), path.parent, origin=path.name)


def fit_material(case: MaterialFitCase, base_dir: str | Path = ".", origin: str = "Python"
                 ) -> MaterialFitResult:
    """The fits of a validated :class:`MaterialFitCase`; files relative to ``base_dir``."""
    base_dir = Path(base_dir)
    notes: list[str] = []
    curves, hyper, comparisons = [], None, {}
    if case.hyperelastic is not None:
        spec = case.hyperelastic
        for c in spec.curves:
            data = c.read(base_dir, c.name)
            lam = data["stretch"].to_numpy() if "stretch" in data else \
                1.0 + data["strain"].to_numpy()
            curves.append(Curve(c.name, c.mode, lam, data["stress"].to_numpy(), c.role))
        kwargs = {"relative": spec.residuals == "relative",
                  "stretch_range": spec.stability_range}
        hyper = fit_hyperelastic(curves, spec.model, spec.terms, spec.fit_modes, **kwargs)
        if not hyper.initial_shear_modulus > 0:
            wrong = [f"curve {c.name!r} at stretch {c.stretch[k]:.4g}: "
                     f"{c.stress[k] / 1e6:.4g} MPa" for c in curves
                     for k in np.flatnonzero(c.wrong_sign)[:3]]
            raise InputError(
                f"hyperelastic: the fitted {hyper.label} has an initial shear modulus of "
                f"{hyper.initial_shear_modulus / 1e6:.4g} MPa (<= 0): no rubber; the nominal "
                "stress must rise with the stretch (> 0 in tension, < 0 in compression)"
                + (f"; stresses of the wrong sign: {'; '.join(wrong)} (check the sign and "
                   "the columns)" if wrong else ""))
        for cmp in spec.compare:
            fit = fit_hyperelastic(curves, cmp.model, cmp.terms, cmp.fit_modes, **kwargs)
            modes = cmp.fit_modes or fit.fit_modes
            comparisons[f"{fit.label} ({', '.join(modes)})"] = fit
    expansion = None
    if case.dilatometry is not None:
        data = case.dilatometry.read(base_dir, "dilatometry")
        strain = data["linear_strain"].to_numpy() if "linear_strain" in data else \
            data["volume_strain"].to_numpy() / 3.0
        expansion = fit_expansion(data["temperature"].to_numpy(), strain)
    dma = shift = arrhenius = prony = None
    tg_dma = None
    t_ref = case.compound.reference_temperature
    if case.viscoelastic is not None:
        v = case.viscoelastic
        dma = _read_dma(v, base_dir)
        temps, log_a, se = isotherm_shifts(dma)
        t_master = v.reference_temperature or t_ref
        tg_dma = tan_delta_peak_temperature(dma)
        if tg_dma is None:
            # the peak on the master curve, moved to a temperature by a WLF over all isotherms
            wlf = fit_shift_law(temps, log_a, se, t_master, "wlf", cumulative=True)
            f_peak = tan_delta_peak(*master_curve(dma, wlf))
            if f_peak is not None:
                tg_dma = _temperature_of_shift(wlf, math.log10(f_peak))
        # the law the compound evaluates: WLF above its T_g, Arrhenius below
        tg = _glass_transition(case.compound, expansion, tg_dma)[0]
        shift = fit_shift_law(temps, log_a, se, t_master, "wlf", cumulative=True,
                              arrhenius_below=tg)
        try:
            arrhenius = fit_shift_law(temps, log_a, se, t_master, "arrhenius",
                                      cumulative=True)
        except InputError as exc:
            notes.append(f"Arrhenius shift not fitted: {exc}")
        f_r, e1, e2 = master_curve(dma, shift)
        prony = fit_prony(f_r, e1, e2, v.terms_per_decade, v.smoothing)
    table, text, sources = _compound(case, hyper, dma, shift, prony, tg_dma, expansion, notes,
                                     origin)
    result = MaterialFitResult(case, curves, hyper, comparisons, dma, shift, arrhenius, prony,
                               tg_dma, expansion, table, text, {}, notes)
    result.report = _report(result, sources)
    return result


def _glass_transition(c: CompoundSpec, expansion: ExpansionFit | None, tg_dma: float | None,
                      fitted_by: str = "fitted") -> tuple[float | None, str]:
    """The compound's T_g [K] and its source: the dilatometric T_g, else the one given in the
    fit file, else the tan delta peak of the DMA, else the base's ((None, '') if none)."""
    from sealsim.properties.elastomers import get_elastomer

    if expansion is not None:
        return expansion.glass_transition, f"dilatometry, {fitted_by}"
    if c.glass_transition is not None:
        return c.glass_transition, "given in the fit file"
    if tg_dma is not None:
        return tg_dma, (f"tan delta peak at 1 Hz (DMA), {fitted_by}; a DMA T_g lies typically "
                        "5-15 K above the DSC value the catalogue uses")
    if c.base is not None:
        base = get_elastomer(c.base)
        return base.glass_transition, f"catalogue {base.name} [L]"
    return None, ""


def _temperature_of_shift(shift: ShiftFit, log_a: float) -> float | None:
    """Temperature [K] at which the fitted law gives log10 a_T (bisection), or None."""
    lo, hi = shift.reference_temperature - 150.0, shift.reference_temperature + 250.0
    if shift.law == "wlf":
        lo = max(lo, shift.reference_temperature - shift.parameters["c2"] + 1.0)
    f_lo, f_hi = shift.log10_shift(lo) - log_a, shift.log10_shift(hi) - log_a
    if f_lo * f_hi > 0:
        return None
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        f_mid = shift.log10_shift(mid) - log_a
        if f_lo * f_mid <= 0:
            hi = mid
        else:
            lo, f_lo = mid, f_mid
    return 0.5 * (lo + hi)


def _read_dma(v: ViscoelasticSpec, base_dir: Path) -> DMAData:
    parts = []
    for k, f in enumerate(v.files):
        d = f.read(base_dir, f"DMA file {f.file}")
        if "storage_modulus" in d and "loss_modulus" in d:
            e1, e2 = d["storage_modulus"].to_numpy(), d["loss_modulus"].to_numpy()
        elif "storage_modulus" in d:
            e1 = d["storage_modulus"].to_numpy()
            e2 = e1 * d["tan_delta"].to_numpy()
        else:
            td = d["tan_delta"].to_numpy()
            e1 = d["complex_modulus"].to_numpy() / np.sqrt(1.0 + td ** 2)
            e2 = e1 * td
        parts.append((d["temperature"].to_numpy(), d["frequency"].to_numpy(), e1, e2))
    return DMAData(*(np.concatenate([p[i] for p in parts]) for i in range(4)),
                   name=", ".join(f.file for f in v.files))


def _q(value: float, unit: str) -> str:
    """A quantity string for a compound file, e.g. '1.234 MPa'."""
    from sealsim.units import unit_registry

    if unit == "degC":
        return f"{value - ZERO_CELSIUS_K:.6g} degC"
    magnitude = unit_registry().Quantity(value, _SI[unit]).to(unit).magnitude
    return f"{magnitude:.12g} {unit}"


_SI = {"MPa": "Pa", "kg/m^3": "kg/m^3", "W/(m*K)": "W/(m*K)", "J/(kg*K)": "J/(kg*K)",
       "1/K": "1/K", "K": "K", "s": "s", "Hz": "Hz"}

_UNITS = {"glass_transition": "degC", "service_min": "degC", "service_max": "degC",
          "density": "kg/m^3", "thermal_conductivity": "W/(m*K)",
          "specific_heat": "J/(kg*K)", "thermal_expansion": "1/K", "bulk_modulus": "MPa"}


def _compound(case, hyper, dma, shift, prony, tg_dma, expansion, notes, origin):
    """The compound table (catalogue format, quantities as strings), its TOML text with a
    source tag on every value, and ``{field: source}``."""
    from sealsim.properties.elastomers import get_elastomer
    from sealsim.properties.rubber_modulus import shore_a_young_modulus

    c = case.compound
    base = get_elastomer(c.base) if c.base else None
    fitted_by = f"fitted by sealsim material fit ({origin})"
    table: dict[str, Any] = {"description": c.description or case.title or c.name}
    sources: dict[str, str] = {}
    given = c.model_dump(exclude_none=True)

    def take(key, value, source):
        table[key] = value
        sources[key] = source

    for key in GIVEN_FIELDS:
        value = getattr(c, key)
        if key == "glass_transition":
            tg, why = _glass_transition(c, expansion, tg_dma, fitted_by)
            if tg is None:
                raise InputError("compound.glass_transition: not given, not measured and no "
                                 "base catalogue entry to take it from; give it or "
                                 "compound.base")
            take(key, _q(tg, "degC"), why)
            if expansion is not None and value is not None:
                notes.append(f"glass_transition {given[key]} of the fit file replaced by the "
                             "dilatometric T_g")
            continue
        if key == "thermal_expansion" and expansion is not None:
            take(key, _q(expansion.rubbery, "1/K"), f"dilatometry, {fitted_by}")
            continue
        if value is not None:
            take(key, _q(value, _UNITS[key]), "given in the fit file")
        elif key == "service_min" and base is not None:
            # a low-temperature limit follows the glass transition (the base's WLF reference
            # and master curve are moved with T_g too); glass_transition is set above
            moved = _si_value(table["glass_transition"]) - base.glass_transition
            take(key, _q(base.service_range[0] + moved, "degC"),
                 f"catalogue {base.name} [L]" if abs(moved) < 1e-9 else
                 f"catalogue {base.name}'s {base.service_range[0] - ZERO_CELSIUS_K:g} degC "
                 f"moved with T_g by {moved:+.4g} K [D]")
        elif base is not None:
            si = {"service_min": base.service_range[0],
                  "service_max": base.service_range[1]}.get(key, getattr(base, key, None))
            take(key, _q(si, _UNITS[key]), f"catalogue {base.name} [L]")
        else:
            raise InputError(f"compound.{key}: not given, not measured and no base catalogue "
                             "entry to take it from; give it or compound.base")
    table["reference_temperature"] = _q(c.reference_temperature, "degC")
    sources["reference_temperature"] = "given in the fit file"
    if c.hardness_shore_a is not None:
        take("hardness_shore_a", c.hardness_shore_a, "given in the fit file")
    if expansion is not None:
        take("glassy_thermal_expansion", _q(expansion.glassy, "1/K"),
             f"dilatometry, {fitted_by}")
    # hyperelastic constants
    if hyper is not None:
        if hyper.model == "mooney_rivlin":
            take("c10", _q(hyper.parameters["C10"], "MPa"), fitted_by)
            take("c01", _q(hyper.parameters["C01"], "MPa"), fitted_by)
        else:
            spec = HYPERELASTIC_MODELS[hyper.model]
            sub = {"model": hyper.model}
            for p in spec.parameters:
                v = hyper.parameters[p]
                if p in spec.stresses:
                    sub[p] = [_q(x, "MPa") for x in v] if spec.terms else _q(v, "MPa")
                else:
                    sub[p] = [float(f"{x:.8g}") for x in v] if spec.terms else \
                        float(f"{v:.8g}")
            table["hyperelastic"] = sub
            sources["hyperelastic"] = fitted_by
            sources["c10"] = sources["c01"] = ("neo-Hookean equivalent of the fitted "
                                               f"{hyper.label} (mu0/2, 0) [D]")
        e_small = 3.0 * hyper.initial_shear_modulus
    elif prony is not None:
        e_small = None      # from the fitted curve at (T_ref, f_test), below
    elif c.hardness_shore_a is not None:
        e_small = float(shore_a_young_modulus(c.hardness_shore_a))
        c10 = e_small / 6.0 / (1.0 + MR_RATIO)
        why = (f"FALLBACK: Gent's Shore A relation (hardness {c.hardness_shore_a:g}), the "
               f"weakest data; C01/C10 = {MR_RATIO} [D]")
        take("c10", _q(c10, "MPa"), why)
        take("c01", _q(c10 * MR_RATIO, "MPa"), why)
        notes.append("no stress-strain curve and no DMA: the hyperelastic constants come from "
                     "the hardness alone (Gent's relation), the weakest estimate; measure a "
                     "tensile curve")
    elif base is not None:
        e_small = 6.0 * (base.c10 + base.c01)
        take("c10", _q(base.c10, "MPa"), f"catalogue {base.name} [L]")
        take("c01", _q(base.c01, "MPa"), f"catalogue {base.name} [L]")
        notes.append(f"no stress-strain data: the hyperelastic constants are the catalogue "
                     f"{base.name}'s")
    else:
        raise InputError("nothing gives the compound's stiffness: give [hyperelastic] curves, "
                         "[viscoelastic] DMA data, compound.hardness_shore_a or compound.base")
    # viscoelastic: WLF, Prony, master curve
    if shift is not None and prony is not None:
        table["wlf"] = {"c1": float(f"{shift.parameters['c1']:.8g}"),
                        "c2": _q(shift.parameters["c2"], "K"),
                        "reference_temperature": _q(shift.reference_temperature, "degC")}
        sources["wlf"] = f"WLF fitted to the DMA shift factors, {fitted_by}"
        table["prony"] = {
            "reference_temperature": _q(shift.reference_temperature, "degC"),
            "equilibrium_modulus": _q(prony.equilibrium_modulus, "MPa"),
            "moduli": [_q(e, "MPa") for e in prony.moduli],
            "relaxation_times": [f"{t:.6g} s" for t in prony.relaxation_times]}
        sources["prony"] = f"fitted to the DMA master curve, {fitted_by}"
        table["modulus"] = _master_table(dma, prony, shift, c.reference_temperature)
        sources["modulus"] = ("master-curve sigmoid: glassy modulus from the Prony series, the "
                              "rest fitted to the measured storage moduli at the fitted shift "
                              f"law's reduced frequencies [D], {fitted_by}")
    elif base is not None:
        table["wlf"] = {"c1": base.wlf_c1, "c2": _q(base.wlf_c2, "K"),
                        "reference_temperature": _q(base.wlf_reference_temperature
                                                    - base.glass_transition
                                                    + _si_value(table["glass_transition"]),
                                                    "degC")}
        sources["wlf"] = (f"catalogue {base.name}'s constants, referred to this compound's "
                          "T_g [L]")
        table["modulus"] = {"glassy": _q(base.glassy_modulus, "MPa"),
                            "rubbery": _q(base.rubbery_modulus, "MPa"),
                            "test_frequency": _q(base.test_frequency, "Hz"),
                            "transition_log10_frequency": base.transition_location,
                            "transition_width_decades": base.transition_width,
                            "transition_asymmetry": base.transition_asymmetry}
        # the rubbery plateau that puts the curve through the constants' modulus at (T_ref,
        # f_test) (the glassy modulus stays: 1-3 GPa for any rubber); the plateau ratio alone
        # misses that point once T_g has moved or the transition's tail reaches T_ref
        def miss(log_rubbery):
            table["modulus"]["rubbery"] = _q(10.0 ** log_rubbery, "MPa")
            return math.log(_curve_modulus_at_reference(table, c.name) / e_small)

        guess = math.log10(base.rubbery_modulus * e_small / (6.0 * (base.c10 + base.c01)))
        lo = max(guess - 2.0, 4.5)                                   # 32 kPa
        hi = min(guess + 2.0, math.log10(0.5 * base.glassy_modulus))
        if not (lo < hi and miss(lo) * miss(hi) < 0):
            raise InputError(
                f"the fitted constants' Young's modulus {e_small / 1e6:.4g} MPa at "
                f"{c.reference_temperature - ZERO_CELSIUS_K:g} degC is beyond what "
                f"the master curve of compound.base {base.name} reaches with a rubbery plateau "
                f"of {10 ** lo / 1e6:.3g} ... {10 ** hi / 1e6:.4g} MPa: check the curves' "
                "stress unit (a seal rubber has a few MPa)")
        rubbery = 10.0 ** brentq(miss, lo, hi, xtol=1e-10)
        table["modulus"]["rubbery"] = _q(rubbery, "MPa")
        sources["modulus"] = (f"catalogue {base.name}'s master curve moved with T_g, its rubbery "
                              f"modulus ({rubbery / 1e6:.4g} MPa) chosen so that the curve gives "
                              "the constants' small-strain modulus at the reference temperature "
                              "and test frequency [D]")
    else:
        raise InputError("the compound's modulus-temperature curve needs [viscoelastic] DMA "
                         "data or compound.base")
    if e_small is None:
        # the constants of a held seal's stiffness ratio are the test-frequency modulus at the
        # reference temperature (Elastomer.modulus_ratio), not the equilibrium E_inf
        c10 = _curve_modulus_at_reference(table, c.name) / 6.0 / (1.0 + MR_RATIO)
        why = ("the fitted modulus curve at the reference temperature and test frequency / 6, "
               f"C01/C10 = {MR_RATIO} [D]")
        take("c10", _q(c10, "MPa"), why)
        take("c01", _q(c10 * MR_RATIO, "MPa"), why)
    source = "; ".join(f"{k}: {v}" for k, v in sources.items())
    table["source"] = (c.source + "; " if c.source else "") + source
    return table, _toml(c.name, table, sources, case.title, origin), sources


def _curve_modulus_at_reference(table: dict, name: str) -> float:
    """E [Pa] of a compound table's modulus curve at its reference temperature and test
    frequency (the constants a placeholder stands for are not used)."""
    from sealsim.properties.elastomers import Elastomer

    trial = {k: v for k, v in table.items() if k != "hyperelastic"}
    trial.setdefault("c10", "1 MPa")
    trial.setdefault("c01", "0.25 MPa")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        material = Elastomer.from_dict(trial, name)
        return float(material.modulus(material.reference_temperature))


def _si_value(text: str) -> float:
    from sealsim.units import parse_quantity

    return parse_quantity(text, "temperature")


def _master_table(dma: DMAData, prony: PronyFit, shift: ShiftFit, t_ref: float) -> dict:
    """The catalogue's sigmoid master curve (glassy, rubbery at ``t_ref`` [K], x0, w, ν), in
    two steps.  First all of it fitted in log E′ to the Prony series over its relaxation
    times, which sets the glassy modulus (the series' extrapolation: DMA of a rubber in its
    service range seldom reaches the glass, and the measured points alone leave it free --
    250 GPa for such data).  Then, with that glassy modulus, x0, w, ν and the rubbery modulus
    fitted to the measured storage moduli at the reduced frequencies of the fitted shift law,
    the rubbery part times T/t_ref: the curve the compound evaluates, against every measured
    point.  The series' E∞ is not the rubbery modulus: the master curve is shifted along
    log f only, so the warm isotherms' entropic rise of the plateau goes into E∞, and the
    compound's factor T/t_ref then counted it twice.  (With the first step alone -- the
    series over 32 decades for pyvisco's polymer, most of them beyond the data -- the compound
    was 9.5 % high on the 100 °C isotherm, which the series follows within 3 %; on a rubber's
    synthetic DMA 27 % high at 100 °C.)"""
    from sealsim.properties.rubber_modulus import master_curve_modulus

    e_r = prony.equilibrium_modulus
    tau = prony.relaxation_times
    f = np.logspace(math.log10(0.1 / (2 * np.pi * tau.max())),
                    math.log10(10.0 / (2 * np.pi * tau.min())), 200)
    series = np.log10(prony.storage(f))

    def on_series(x):
        return np.log10(master_curve_modulus(f, 10 ** x[0], e_r, x[1], x[2], x[3])) - series

    e_g = e_r + float(np.sum(prony.moduli))
    x0 = [math.log10(e_g), float(np.log10(f[np.argmin(np.abs(series - 0.5 * (
        series.max() + series.min())))])), 1.0, 1.0]
    first = least_squares(on_series, x0, bounds=([math.log10(2.01 * e_r), -30, 0.05, 0.05],
                                                 [12.0, 30, 9.0, 50.0]))
    log_eg = first.x[0]
    f_r = master_curve(dma, shift, measured=False)[0]
    measured = np.log10(dma.storage)
    entropic = dma.temperature / t_ref

    def on_data(x):
        return np.log10(master_curve_modulus(f_r, 10 ** log_eg, 10 ** x[3] * entropic,
                                             *x[:3])) - measured

    top = log_eg - math.log10(2.01 * entropic.max())              # glassy > 2 x rubbery
    start = np.r_[first.x[1:], min(math.log10(e_r), top - 1e-6)]
    res = least_squares(on_data, start, bounds=([-30, 0.05, 0.05, min(4.0, top - 1.0)],
                                                [30, 9.0, 50.0, top]))
    return {"glassy": _q(10 ** log_eg, "MPa"), "rubbery": _q(10 ** res.x[3], "MPa"),
            "test_frequency": "1 Hz", "transition_log10_frequency": float(f"{res.x[0]:.6g}"),
            "transition_width_decades": float(f"{res.x[1]:.6g}"),
            "transition_asymmetry": float(f"{res.x[2]:.6g}")}


def compound_storage_errors(material, dma: DMAData) -> np.ndarray:
    """Relative error of a compound's storage modulus E′(T, f) -- as the seal models evaluate
    it (:meth:`~sealsim.properties.elastomers.Elastomer.modulus`: its master-curve sigmoid and
    shift law) -- at every measured DMA point, model/measured − 1."""
    # the unchecked evaluation: isotherms below the compound's allowed range are compared too
    return material._modulus(dma.temperature, dma.frequency) / dma.storage - 1.0


def _toml(name: str, table: dict, sources: dict, title: str, origin: str) -> str:
    """The compound file: one table ``[name]`` with the source of each value as a comment."""
    import tomli_w

    lines = [f"# Compound {name}: written by 'sealsim material fit {origin}'"
             + (f" ({title})" if title else "") + ".",
             f"# Use it as material = \"{name}.toml\" in a structure, rotary, pneumatic or study",
             "# case, or get_elastomer(\"path/to/" + name + ".toml\") in Python. The source of",
             "# every value is given next to it; [L] literature/catalogue, [D] derived by sealsim.",
             ""]
    top = {k: v for k, v in table.items() if not isinstance(v, dict)}
    subs = {k: v for k, v in table.items() if isinstance(v, dict)}
    lines.append(f"[{name}]")
    for key, value in top.items():
        text = tomli_w.dumps({key: value}).strip()
        if key in sources and key != "source":
            text += f"  # {sources[key]}"
        lines.append(text)
    for key, sub in subs.items():
        lines.append("")
        if key in sources:
            lines.append(f"# {sources[key]}")
        lines.append(f"[{name}.{key}]")
        lines.append(tomli_w.dumps(sub).strip())
    return "\n".join(lines) + "\n"


def _report(r: MaterialFitResult, sources: dict) -> dict:
    """report.json: ``{"model", "parameters": {NAME: {"value", "stderr"}}, "modes": {MODE:
    {"rel_rmse", "r2"}}}`` plus the comparisons, stability, viscoelastic and thermal details
    (SI units; the unit of each parameter is in its entry)."""
    params: dict[str, dict] = {}
    modes: dict[str, dict] = {}
    model = []
    if r.hyperelastic is not None:
        rep = r.hyperelastic.report()
        params.update(rep["parameters"])
        modes.update(rep["modes"])
        model.append(rep["model"])
    out: dict[str, Any] = {"model": " + ".join(model) if model else None,
                           "compound": r.case.compound.name, "parameters": params,
                           "modes": modes}
    if r.hyperelastic is not None:
        out["hyperelastic"] = r.hyperelastic.report()
        out["comparisons"] = {k: f.report() for k, f in r.comparisons.items()}
        unstable = {}
        for label, fit in [(r.hyperelastic.label, r.hyperelastic)] + list(r.comparisons.items()):
            where = {m: lim for m, lim in fit.stability.items() if not lim["stable"]}
            if where:
                unstable[label] = {m: {"stable_from": lim["stable_from"],
                                       "stable_to": lim["stable_to"],
                                       "unstable_at": lim["unstable_at"]}
                                   for m, lim in where.items()}
        out["unstable_models"] = unstable
    if r.shift is not None and r.prony is not None:
        model.append("prony + wlf")
        out["model"] = " + ".join(model)
        for n, v in r.shift.parameters.items():
            params[f"wlf_{n}"] = {"value": v, "stderr": r.shift.standard_errors[n],
                                  "unit": "K" if n == "c2" else "-",
                                  "identifiable": r.shift.identifiable[n]}
        params["prony_E_inf"] = {"value": r.prony.equilibrium_modulus,
                                 "stderr": _finite(r.prony.standard_errors[0]), "unit": "Pa"}
        for k, (e, tau) in enumerate(zip(r.prony.moduli, r.prony.relaxation_times)):
            params[f"prony_E_{k + 1}"] = {"value": float(e),
                                          "stderr": _finite(r.prony.standard_errors[k + 1]),
                                          "unit": "Pa", "tau_s": float(tau)}
        law = law_rel_rmse(r.dma, r.shift, r.prony)
        compound = compound_storage_errors(r.compound(), r.dma)
        modes["dma"] = {"rel_rmse": r.prony.rel_rmse["storage"],
                        "rel_rmse_loss": r.prony.rel_rmse["loss"],
                        "r2": r.prony.r2["storage"], "r2_loss": r.prony.r2["loss"],
                        "rel_rmse_law": law["storage"], "rel_rmse_loss_law": law["loss"],
                        "rel_rmse_compound": float(np.sqrt(np.mean(compound ** 2))),
                        "role": "fit"}
        out["viscoelastic"] = {
            "reference_temperature_K": r.shift.reference_temperature,
            "shift_factors": [{"temperature_K": float(t), "log10_aT": float(a),
                               "stderr": float(s), "log10_aT_law": float(law_t),
                               "storage_rel_rmse_compound": float(
                                   np.sqrt(np.mean(compound[g] ** 2)))}
                              for t, a, s, law_t, g in zip(
                r.shift.temperatures, r.shift.log_shift, r.shift.log_shift_stderr,
                r.shift.log10_shift(r.shift.temperatures), r.dma.isotherms())],
            "wlf": {"parameters": r.shift.parameters, "stderr": r.shift.standard_errors,
                    "arrhenius_below_K": r.shift.arrhenius_below, "notes": r.shift.notes},
            "arrhenius": (None if r.arrhenius is None else
                          {"parameters": r.arrhenius.parameters,
                           "stderr": r.arrhenius.standard_errors}),
            "prony_terms": int(r.prony.moduli.size),
            "prony_smoothing": r.prony.smoothing, "prony_ripple_decades": r.prony.ripple,
            "prony_smooth": r.prony.smooth, "prony_notes": r.prony.notes,
            "tan_delta_peak_temperature_K": r.tan_delta_tg}
    if r.expansion is not None:
        e = r.expansion
        modes["dilatometry"] = {"rel_rmse": e.rel_rmse, "r2": None, "role": "fit"}
        for n, v in (("glass_transition", e.glass_transition), ("alpha_rubbery", e.rubbery),
                     ("alpha_glassy", e.glassy)):
            key = {"alpha_rubbery": "rubbery", "alpha_glassy": "glassy"}.get(n, n)
            params[f"dilatometry_{n}"] = {"value": v, "stderr": _finite(
                e.standard_errors[key]), "unit": "K" if n == "glass_transition" else "1/K"}
    out["sources"] = sources
    out["notes"] = r.notes
    return out


def _finite(x) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None

