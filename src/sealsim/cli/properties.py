"""``sealsim oil ...`` and ``sealsim material ...``: look up, tabulate and plot properties.

The commands hold no physics: they call :mod:`sealsim.properties`, convert units for display
(°C, mm²/s, mPa·s, MPa) and write plots through :class:`sealsim.output.ResultFolder`.

JSON output (``--json``) uses one key per value with the unit in the key name:

* oils: ``name``, ``family``, ``origin``, ``nu40_mm2_s``, ``nu100_mm2_s``,
  ``viscosity_index``, ``rho15_kg_m3``, ``min_temperature_C``, ``source``; ``oil show`` adds
  ``pressure_viscosity_coefficient_1_Pa``, ``walther_A``, ``walther_B``, ``notes`` and
  ``table`` rows with ``temperature_C``, ``nu_mm2_s``, ``eta_Pa_s``, ``rho_kg_m3``,
  ``k_W_mK``, ``cp_J_kgK``.
* elastomers: ``name``, ``description``, ``origin``, ``glass_transition_C``,
  ``service_min_C``, ``service_max_C``, ``density_kg_m3``, ``hardness_shore_a``,
  ``reference_temperature_C``, ``test_frequency_Hz``, ``E_reference_Pa``, ``source``;
  ``material show`` adds ``thermal_conductivity_W_mK``, ``specific_heat_J_kgK``,
  ``thermal_expansion_1_K``, ``c10_Pa``, ``c01_Pa``, ``bulk_modulus_Pa``, ``wlf_c1``,
  ``wlf_c2_K``, ``wlf_reference_temperature_C``, ``glassy_modulus_Pa``,
  ``rubbery_modulus_Pa``, ``modulus_model``, ``frequency_Hz``, ``notes`` and ``table`` rows
  with ``temperature_C``, ``E_Pa``, ``a_T``, ``log10_a_T``.
"""

from __future__ import annotations

import math
import warnings
from enum import Enum
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import typer
from rich import box
from rich.table import Table
from rich.text import Text

from sealsim.cli._common import console, err_console, guarded, parse_celsius_list, print_json
from sealsim.errors import InputError
from sealsim.output import ResultFolder
from sealsim.plotting.properties import modulus_temperature_figure, viscosity_temperature_figure
from sealsim.properties import oils as oils_module
from sealsim.properties.elastomers import (
    Elastomer,
    ServiceRangeWarning,
    get_elastomer,
    list_elastomers,
    load_elastomer_file,
)
from sealsim.properties.oils import Oil, OilRangeWarning, get_oil, list_oils, load_oil_file

__all__ = ["material_app", "oil_app"]

ZERO_CELSIUS = 273.15  # K
DEFAULT_OIL_TEMPERATURES_C = [20.0, 40.0, 60.0, 80.0, 100.0]
VISCOSITY_PNG = "viscosity_temperature.png"
VISCOSITY_CSV = "viscosity_temperature.csv"
MODULUS_PNG = "modulus_temperature.png"
MODULUS_CSV = "modulus_temperature.csv"

oil_app = typer.Typer(
    help="Lubricating oils: catalogue, property tables (ASTM D341 viscosity) and charts.",
    no_args_is_help=True,
)
material_app = typer.Typer(
    help="Seal elastomers: catalogue, properties, modulus E(T) and WLF shift factor a_T.",
    no_args_is_help=True,
)


class Chart(str, Enum):
    """Viscosity axes of ``oil plot``."""

    d341 = "d341"
    log = "log"


# ---------------------------------------------------------------------------------------------
# shared helpers (pure: no printing)
# ---------------------------------------------------------------------------------------------


def _c(kelvin: float) -> float:
    return float(kelvin) - ZERO_CELSIUS


def _check_celsius(values: list[float], lo_k: float, hi_k: float, option: str,
                   what: str) -> np.ndarray:
    """Temperatures [degC] → K, refusing values outside [lo_k, hi_k] with a message in degC."""
    t = np.asarray(values, dtype=float) + ZERO_CELSIUS
    bad = t[(t < lo_k) | (t > hi_k)]
    if bad.size:
        raise InputError(f"{option}: {_c(bad[0]):g} degC is outside {what}; allowed: "
                         f"{_c(lo_k):.2f} to {_c(hi_k):.2f} degC")
    return t


def _positive(value: float, option: str, unit: str) -> float:
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{option}: {value!r} {unit} is not allowed; give a finite value > 0")
    return float(value)


def _grid_celsius(t_min: float, t_max: float) -> np.ndarray:
    """Plot temperatures [degC]: whole-degree steps from t_min to t_max (both included)."""
    for value, name in ((t_min, "--t-min"), (t_max, "--t-max")):
        if not math.isfinite(value) or value < -ZERO_CELSIUS:
            raise InputError(f"{name}: {value!r} degC is not a valid temperature "
                             "(must be finite and >= -273.15 degC)")
    if not t_max > t_min:
        raise InputError(f"--t-max ({t_max:g} degC) must be greater than --t-min "
                         f"({t_min:g} degC)")
    step = max(1.0, math.ceil((t_max - t_min) / 400.0))  # at most ~400 rows in the CSV
    grid = np.arange(t_min, t_max, step)
    return np.append(grid, t_max)


def _extra_oils(oil_file: Path | None) -> dict[str, Oil]:
    return load_oil_file(oil_file) if oil_file is not None else {}


def _unique(items: list[Any]) -> list[Any]:
    """Items without repeats (by name), in order: ``VG68`` and ``VG68-mineral`` are one oil."""
    seen: dict[str, Any] = {}
    for item in items:
        seen.setdefault(item.name, item)
    return list(seen.values())


# -- oils ---------------------------------------------------------------------------------------

def oil_summary(oil: Oil, origin: str = "catalogue") -> dict[str, Any]:
    """JSON-ready catalogue row of an oil (units in the key names)."""
    return {
        "name": oil.name,
        "family": oil.family,
        "origin": origin,
        "nu40_mm2_s": oil.nu40 * 1e6,
        "nu100_mm2_s": oil.nu100 * 1e6,
        "viscosity_index": oil.viscosity_index,
        "rho15_kg_m3": oil.rho15,
        "min_temperature_C": _c(oil.min_temperature),
        "source": oil.source,
    }


def oil_rows(oil: Oil, temperatures_c: list[float]) -> tuple[list[dict[str, float]], list[str]]:
    """Property table of an oil at temperatures [degC] and the notes to show with it.

    Raises InputError for temperatures below the oil's minimum temperature or outside the
    range of the correlations; a viscosity below 2 mm²/s (extrapolated ASTM D341) is a note.
    """
    t = _check_celsius(temperatures_c, *oils_module.T_RANGE, "--temperatures",
                       "the range of the oil correlations")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", OilRangeWarning)
        oil.check_temperature(t, name="--temperatures")
    notes = [str(w.message) for w in caught if issubclass(w.category, OilRangeWarning)]
    nu = np.atleast_1d(oil.kinematic_viscosity(t))
    eta = np.atleast_1d(oil.dynamic_viscosity(t))
    rho = np.atleast_1d(oil.density(t))
    k = np.atleast_1d(oil.thermal_conductivity(t))
    cp = np.atleast_1d(oil.specific_heat(t))
    rows = [{"temperature_C": float(tc), "nu_mm2_s": float(nu[i] * 1e6),
             "eta_Pa_s": float(eta[i]), "rho_kg_m3": float(rho[i]), "k_W_mK": float(k[i]),
             "cp_J_kgK": float(cp[i])} for i, tc in enumerate(temperatures_c)]
    return rows, notes


def viscosity_curves(oils: list[Oil], temperatures_c: np.ndarray
                     ) -> tuple[pd.DataFrame, list[str]]:
    """ν(T) of each oil on a grid [degC]: a DataFrame (the CSV) and notes on omitted ranges.

    Values below an oil's minimum temperature or with ν < 2 mm²/s (outside ASTM D341) are
    left empty (NaN) rather than extrapolated.
    """
    t = _check_celsius(list(temperatures_c), *oils_module.T_RANGE, "--t-min/--t-max",
                       "the range of the oil correlations")
    frame = pd.DataFrame({"temperature_C": temperatures_c})
    notes = []
    for oil in oils:
        with np.errstate(over="ignore"):
            nu = np.asarray(oil.kinematic_viscosity(t), dtype=float)
        cold = t < oil.min_temperature
        thin = ~cold & ~(nu >= oils_module.NU_MIN_D341)
        if cold.any():
            notes.append(f"{oil.name}: not drawn below {_c(oil.min_temperature):.0f} degC "
                         "(its lowest temperature of use)")
        if thin.any():
            notes.append(f"{oil.name}: not drawn from {_c(t[thin].min()):.0f} degC up "
                         "(viscosity below 2 mm^2/s, outside ASTM D341)")
        frame[f"nu_{oil.name}_mm2_s"] = np.where(cold | thin, np.nan, nu * 1e6)
    return frame, notes


# -- elastomers ---------------------------------------------------------------------------------

def _extra_materials(material_file: Path | None) -> dict[str, Elastomer]:
    return load_elastomer_file(material_file) if material_file is not None else {}


def find_material(name: str, extra: dict[str, Elastomer]) -> Elastomer:
    """Material ``name`` (case-insensitive) from ``extra`` first, then the catalogue."""
    for key, material in extra.items():
        if key.casefold() == name.strip().casefold():
            return material
    try:
        return get_elastomer(name)
    except InputError as exc:
        if extra:
            raise InputError(f"{exc}; the material file defines: {', '.join(extra)}") from None
        raise


def material_summary(m: Elastomer, origin: str = "catalogue") -> dict[str, Any]:
    """JSON-ready catalogue row of an elastomer (units in the key names)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ServiceRangeWarning)
        e_ref = m.modulus(m.reference_temperature)
    return {
        "name": m.name,
        "description": m.description,
        "origin": origin,
        "glass_transition_C": _c(m.glass_transition),
        "service_min_C": _c(m.service_range[0]),
        "service_max_C": _c(m.service_range[1]),
        "density_kg_m3": m.density,
        "hardness_shore_a": m.hardness_shore_a,
        "reference_temperature_C": _c(m.reference_temperature),
        "test_frequency_Hz": m.test_frequency,
        "E_reference_Pa": float(e_ref),
        "source": m.source,
    }


def material_details(m: Elastomer, origin: str = "catalogue") -> dict[str, Any]:
    """All properties of ``material show`` (without the table)."""
    return {
        **material_summary(m, origin),
        "thermal_conductivity_W_mK": m.thermal_conductivity,
        "specific_heat_J_kgK": m.specific_heat,
        "thermal_expansion_1_K": m.thermal_expansion,
        "c10_Pa": m.c10,
        "c01_Pa": m.c01,
        "bulk_modulus_Pa": m.bulk_modulus,
        "wlf_c1": m.wlf_c1,
        "wlf_c2_K": m.wlf_c2,
        "wlf_reference_temperature_C": _c(m.wlf_reference_temperature),
        "glassy_modulus_Pa": m.glassy_modulus,
        "rubbery_modulus_Pa": m.rubbery_modulus,
        "modulus_model": "DMA table" if m.dma_table is not None else "master curve",
    }


def default_material_temperatures(m: Elastomer) -> list[float]:
    """Service range in 20 degC steps [degC] (both ends included)."""
    lo, hi = round(_c(m.service_range[0]), 2), round(_c(m.service_range[1]), 2)
    inner = np.arange(math.ceil(lo / 20.0) * 20.0, hi, 20.0)
    return [lo] + [float(v) for v in inner if lo + 5.0 < v < hi - 5.0] + [hi]


def material_rows(m: Elastomer, temperatures_c: list[float], frequency: float
                  ) -> tuple[list[dict[str, float]], list[str]]:
    """E(T) and a_T of a material at temperatures [degC]; notes for values outside service."""
    lo, hi = m.allowed_range
    t = _check_celsius(temperatures_c, lo, hi, "--temperatures",
                       f"the range where the {m.name} model is meaningful (T_g - 100 K to the "
                       "service maximum + 50 K)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ServiceRangeWarning)  # reported below, in degC
        e = np.atleast_1d(m.modulus(t, frequency))
        log_at = np.atleast_1d(m.log10_shift_factor(t))
    s_lo, s_hi = m.service_range
    outside = [tc for tc, tk in zip(temperatures_c, t, strict=True) if not s_lo <= tk <= s_hi]
    notes = []
    if outside:
        notes.append(f"{m.name}: {', '.join(f'{v:g}' for v in outside)} degC outside the service "
                     f"range {_c(s_lo):g} to {_c(s_hi):g} degC; values shown for information")
    rows = [{"temperature_C": float(tc), "E_Pa": float(e[i]), "a_T": float(10.0 ** log_at[i]),
             "log10_a_T": float(log_at[i])} for i, tc in enumerate(temperatures_c)]
    return rows, notes


def modulus_curves(materials: list[Elastomer], temperatures_c: np.ndarray, frequency: float
                   ) -> pd.DataFrame:
    """E(T) [Pa] of each material on a grid [degC]; empty (NaN) outside its allowed range."""
    t = np.asarray(temperatures_c, dtype=float) + ZERO_CELSIUS
    frame = pd.DataFrame({"temperature_C": temperatures_c})
    for m in materials:
        lo, hi = m.allowed_range
        ok = (t >= lo) & (t <= hi)
        e = np.full(t.shape, np.nan)
        if ok.any():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ServiceRangeWarning)  # shown dashed in the plot
                e[ok] = m.modulus(t[ok], frequency)
        frame[f"E_{m.name}_Pa"] = e
    return frame


# ---------------------------------------------------------------------------------------------
# printing helpers
# ---------------------------------------------------------------------------------------------


def _say(text: str) -> None:
    console.print(text, markup=False, soft_wrap=True)


def _notes(notes: list[str]) -> None:
    for note in notes:
        err_console.print(Text("note: ", style="bold yellow") + Text(note))


def _wrote(folder: ResultFolder, names: list[str]) -> None:
    _say(f"wrote {len(names)} files to {folder.final_path()}:")
    for name in names:
        _say(f"  {folder.final_path(name)}")


def _table(title: str | None, headers: list[str], rows: list[list[str]],
           last_truncated: bool = False) -> Table:
    """A rich table; all text is literal (no markup), so ``[mm²/s]`` is printed as written.

    With ``last_truncated`` the last column (a long text) is cut to one line with an ellipsis
    to fit the terminal, instead of squeezing the numeric columns.
    """
    table = Table(title=Text(title) if title else None, box=box.SIMPLE_HEAD)
    for i, header in enumerate(headers):
        last = i == len(headers) - 1
        text = last_truncated and (i == 0 or last)  # names and descriptions: left
        table.add_column(Text(header), justify="left" if text else "right",
                         no_wrap=not (last and last_truncated))
    for row in rows:
        cells = [Text(c) for c in row]
        if last_truncated:
            cells[-1] = Text(row[-1], no_wrap=True, overflow="ellipsis")
        table.add_row(*cells)
    return table


def _g(value: float | None, digits: int = 4) -> str:
    if value is None or not math.isfinite(value):
        return "-"
    return f"{value:.{digits}g}"


# ---------------------------------------------------------------------------------------------
# oil commands
# ---------------------------------------------------------------------------------------------

OIL_FILE_OPTION = typer.Option(
    None, "--oil-file", help="TOML file with your own oils (one table oils.NAME each, with "
    "family, nu40_mm2_s, nu100_mm2_s, rho15_kg_m3, ...), used next to the catalogue.")
JSON_OPTION = typer.Option(False, "--json", help="Print machine-readable JSON instead of a table.")


@oil_app.command("list")
@guarded
def oil_list(json: bool = JSON_OPTION, oil_file: Path | None = OIL_FILE_OPTION) -> None:
    """List the catalogue oils (and those of --oil-file).

    --json prints a list of objects with the keys name, family, origin,
    nu40_mm2_s, nu100_mm2_s, viscosity_index, rho15_kg_m3,
    min_temperature_C, source.
    """
    extra = _extra_oils(oil_file)
    rows = [oil_summary(get_oil(n)) for n in list_oils()]
    rows += [oil_summary(oil, str(oil_file)) for oil in extra.values()]
    if json:
        print_json(rows)
        return
    console.print(_table(
        "sealsim oils (details: sealsim oil show NAME)",
        ["name", "family", "ν40\n[mm²/s]", "ν100\n[mm²/s]", "VI", "ρ15\n[kg/m³]", "source"],
        [[r["name"], r["family"], f"{r['nu40_mm2_s']:.1f}", f"{r['nu100_mm2_s']:.2f}",
          f"{r['viscosity_index']:.0f}", f"{r['rho15_kg_m3']:.0f}", r["source"]] for r in rows],
        last_truncated=True))


@oil_app.command("show")
@guarded
def oil_show(
    name: str = typer.Argument(..., help="Oil name or alias, e.g. VG68, 'ISO VG 220', "
                               "VG68-PAO (case-insensitive)."),
    temperatures: str | None = typer.Option(
        None, "--temperatures", "-t",
        help="Comma-separated temperatures in degC (default 20,40,60,80,100)."),
    json: bool = JSON_OPTION,
    oil_file: Path | None = OIL_FILE_OPTION,
) -> None:
    """Properties of one oil: ν, η, ρ, k and c_p at several temperatures.

    A temperature below the oil's minimum temperature is an error; a
    viscosity below 2 mm²/s (outside ASTM D341) is shown with a note.

    --json prints one object: the keys of 'oil list' plus
    pressure_viscosity_coefficient_1_Pa, walther_A, walther_B, notes and
    table, a list of rows with temperature_C, nu_mm2_s, eta_Pa_s,
    rho_kg_m3, k_W_mK, cp_J_kgK.
    """
    extra = _extra_oils(oil_file)
    oil = get_oil(name, extra)
    temps = parse_celsius_list(temperatures, DEFAULT_OIL_TEMPERATURES_C, "--temperatures")
    rows, notes = oil_rows(oil, temps)
    origin = str(oil_file) if oil.name in extra else "catalogue"
    info = {**oil_summary(oil, origin),
            "pressure_viscosity_coefficient_1_Pa": oil.pressure_viscosity_coefficient,
            "walther_A": oil.walther_A, "walther_B": oil.walther_B}
    if json:
        _notes(notes)
        print_json({**info, "notes": notes, "table": rows})
        return
    _say(f"{oil.name} ({oil.family} oil)")
    _say(f"  ν40 = {info['nu40_mm2_s']:.1f} mm²/s, ν100 = {info['nu100_mm2_s']:.2f} mm²/s, "
         f"VI = {info['viscosity_index']:.0f}, ρ15 = {oil.rho15:.0f} kg/m³, "
         f"min. temperature {info['min_temperature_C']:.0f} °C, "
         f"α = {oil.pressure_viscosity_coefficient * 1e9:.0f} 1/GPa")
    _say(f"  source: {oil.source}")
    console.print(_table(
        None, ["T\n[°C]", "ν\n[mm²/s]", "η\n[mPa·s]", "ρ\n[kg/m³]", "k\n[W/(m K)]",
               "c_p\n[J/(kg K)]"],
        [[f"{r['temperature_C']:g}", _g(r["nu_mm2_s"]), _g(r["eta_Pa_s"] * 1e3),
          f"{r['rho_kg_m3']:.1f}", f"{r['k_W_mK']:.4f}", f"{r['cp_J_kgK']:.0f}"] for r in rows]))
    _notes(notes)


@oil_app.command("plot")
@guarded
def oil_plot(
    names: list[str] = typer.Argument(..., metavar="NAME",
                                      help="One or more oil names, e.g. VG32 VG68 VG220."),
    out: Path = typer.Option(..., "--out", "-o", help="Output folder for the PNG and CSV."),
    force: bool = typer.Option(False, "--force", help="Replace an output folder that already "
                               "holds results."),
    chart: Chart = typer.Option(Chart.d341, "--chart", help="Viscosity axes: d341 = ASTM D341 "
                                "chart (straight lines), log = log ν vs linear T."),
    t_min: float = typer.Option(0.0, "--t-min", help="Lowest temperature in degC."),
    t_max: float = typer.Option(150.0, "--t-max", help="Highest temperature in degC."),
    oil_file: Path | None = OIL_FILE_OPTION,
) -> None:
    """Viscosity-temperature chart of oils: viscosity_temperature.png and .csv.

    The CSV has the column temperature_C and one column nu_NAME_mm2_s per
    oil; values below the oil's minimum temperature or below 2 mm²/s are
    left empty (not extrapolated).
    """
    extra = _extra_oils(oil_file)
    oils = _unique([get_oil(n, extra) for n in names])
    grid = _grid_celsius(t_min, t_max)
    folder = ResultFolder(out, force=force)  # refuse an existing folder before any work
    frame, notes = viscosity_curves(oils, grid)
    if frame.drop(columns="temperature_C").isna().all().all():
        raise InputError(f"nothing to plot between {grid[0]:g} and {grid[-1]:g} degC: "
                         + "; ".join(notes) + "; change --t-min/--t-max")
    t_k = grid + ZERO_CELSIUS
    curves = {oil.name: frame[f"nu_{oil.name}_mm2_s"].to_numpy() * 1e-6 for oil in oils}
    ref = np.array([oils_module.T40, oils_module.T100])
    shown = (ref >= t_k[0]) & (ref <= t_k[-1])
    points = {oil.name: (ref[shown], np.array([oil.nu40, oil.nu100])[shown]) for oil in oils}
    fig = viscosity_temperature_figure(t_k, curves, chart=chart.value, points=points)
    with folder:
        folder.savefig(VISCOSITY_PNG, fig)
        folder.write_csv(VISCOSITY_CSV, frame, float_format="%.6g")
    _notes(notes)
    _wrote(folder, [VISCOSITY_PNG, VISCOSITY_CSV])


# ---------------------------------------------------------------------------------------------
# material commands
# ---------------------------------------------------------------------------------------------

MATERIAL_FILE_OPTION = typer.Option(
    None, "--material-file", help="TOML file with your own elastomers (catalogue format, "
    "e.g. with a [NAME.dma] table of measured moduli), used next to the catalogue.")
FREQUENCY_OPTION = typer.Option(1.0, "--frequency", "-f", help="Frequency of E(T) in Hz.")


@material_app.command("list")
@guarded
def material_list(json: bool = JSON_OPTION,
                  material_file: Path | None = MATERIAL_FILE_OPTION) -> None:
    """List the catalogue elastomers (and those of --material-file).

    --json prints a list of objects with the keys name, description,
    origin, glass_transition_C, service_min_C, service_max_C,
    density_kg_m3, hardness_shore_a, reference_temperature_C,
    test_frequency_Hz, E_reference_Pa (E at the reference temperature and
    test frequency), source.
    """
    extra = _extra_materials(material_file)
    rows = [material_summary(get_elastomer(n)) for n in list_elastomers()]
    rows += [material_summary(m, str(material_file)) for m in extra.values()]
    if json:
        print_json(rows)
        return
    console.print(_table(
        "sealsim elastomers (details: sealsim material show NAME)",
        ["name", "T_g\n[°C]", "service\n[°C]", "ρ\n[kg/m³]", "E(T_ref)\n[MPa]", "Shore\nA",
         "description"],
        [[r["name"], f"{r['glass_transition_C']:g}",
          f"{r['service_min_C']:g} to {r['service_max_C']:g}", f"{r['density_kg_m3']:.0f}",
          f"{r['E_reference_Pa'] / 1e6:.3g}", _g(r["hardness_shore_a"], 3), r["description"]]
         for r in rows],
        last_truncated=True))


@material_app.command("show")
@guarded
def material_show(
    name: str = typer.Argument(..., help="Material name: NBR, HNBR, FKM, ACM, VMQ "
                               "(case-insensitive) or one of --material-file."),
    temperatures: str | None = typer.Option(
        None, "--temperatures", "-t",
        help="Comma-separated temperatures in degC (default: the service range in 20 degC "
             "steps)."),
    frequency: float = FREQUENCY_OPTION,
    json: bool = JSON_OPTION,
    material_file: Path | None = MATERIAL_FILE_OPTION,
) -> None:
    """Properties of one elastomer with a table of modulus E(T) and shift factor a_T.

    a_T is the WLF shift factor relative to the WLF reference temperature
    (T_g for the catalogue materials).

    --json prints one object: the keys of 'material list' plus
    thermal_conductivity_W_mK, specific_heat_J_kgK, thermal_expansion_1_K,
    c10_Pa, c01_Pa, bulk_modulus_Pa, wlf_c1, wlf_c2_K,
    wlf_reference_temperature_C, glassy_modulus_Pa, rubbery_modulus_Pa,
    modulus_model, frequency_Hz, notes and table, a list of rows with
    temperature_C, E_Pa, a_T, log10_a_T.
    """
    extra = _extra_materials(material_file)
    m = find_material(name, extra)
    freq = _positive(frequency, "--frequency", "Hz")
    temps = parse_celsius_list(temperatures, default_material_temperatures(m), "--temperatures")
    rows, notes = material_rows(m, temps, freq)
    origin = str(material_file) if m in extra.values() else "catalogue"
    info = {**material_details(m, origin), "frequency_Hz": freq}
    if json:
        _notes(notes)
        print_json({**info, "notes": notes, "table": rows})
        return
    _say(f"{m.name}: {m.description}")
    _say(f"  T_g = {info['glass_transition_C']:g} °C, service {info['service_min_C']:g} to "
         f"{info['service_max_C']:g} °C, ρ = {m.density:.0f} kg/m³, "
         f"k = {m.thermal_conductivity:g} W/(m K), c_p = {m.specific_heat:.0f} J/(kg K), "
         f"α = {m.thermal_expansion:.3g} 1/K")
    _say(f"  Mooney-Rivlin at {info['reference_temperature_C']:g} °C: C10 = {m.c10 / 1e6:.4g} "
         f"MPa, C01 = {m.c01 / 1e6:.4g} MPa, K = {m.bulk_modulus / 1e6:.0f} MPa")
    _say(f"  WLF: C1 = {m.wlf_c1:g}, C2 = {m.wlf_c2:g} K, T_ref = "
         f"{info['wlf_reference_temperature_C']:g} °C; E(T) from the {info['modulus_model']}")
    _say(f"  source: {m.source}")
    console.print(_table(
        f"E(T) at {freq:g} Hz; a_T relative to {info['wlf_reference_temperature_C']:g} °C",
        ["T\n[°C]", "E\n[MPa]", "a_T\n[-]", "log10 a_T\n[-]"],
        [[f"{r['temperature_C']:g}", _g(r["E_Pa"] / 1e6), f"{r['a_T']:.3e}",
          f"{r['log10_a_T']:.2f}"] for r in rows]))
    _notes(notes)


@material_app.command("plot")
@guarded
def material_plot(
    names: list[str] = typer.Argument(..., metavar="NAME",
                                      help="One or more material names, e.g. NBR FKM."),
    out: Path = typer.Option(..., "--out", "-o", help="Output folder for the PNG and CSV."),
    force: bool = typer.Option(False, "--force", help="Replace an output folder that already "
                               "holds results."),
    frequency: float = FREQUENCY_OPTION,
    t_min: float | None = typer.Option(None, "--t-min", help="Lowest temperature in degC "
                                       "(default: 40 K below the lowest T_g)."),
    t_max: float | None = typer.Option(None, "--t-max", help="Highest temperature in degC "
                                       "(default: 20 K above the highest service maximum)."),
    material_file: Path | None = MATERIAL_FILE_OPTION,
) -> None:
    """Modulus-temperature chart of elastomers: modulus_temperature.png and .csv.

    log E vs T (glassy, transition, rubbery) with T_g marked; dashed outside
    the service range. The CSV has the column temperature_C and one column
    E_NAME_Pa per material, empty outside the range where the material
    model is meaningful.
    """
    extra = _extra_materials(material_file)
    materials = _unique([find_material(n, extra) for n in names])
    freq = _positive(frequency, "--frequency", "Hz")
    lo = min(_c(m.glass_transition) for m in materials) - 40.0 if t_min is None else t_min
    hi = max(_c(m.service_range[1]) for m in materials) + 20.0 if t_max is None else t_max
    grid = _grid_celsius(math.floor(lo / 10.0) * 10.0 if t_min is None else lo,
                         math.ceil(hi / 10.0) * 10.0 if t_max is None else hi)
    folder = ResultFolder(out, force=force)  # refuse an existing folder before any work
    frame = modulus_curves(materials, grid, freq)
    if frame.drop(columns="temperature_C").isna().all().all():
        ranges = ", ".join(f"{m.name} {_c(m.allowed_range[0]):.0f} to "
                           f"{_c(m.allowed_range[1]):.0f} degC" for m in materials)
        raise InputError(f"nothing to plot between {grid[0]:g} and {grid[-1]:g} degC: the "
                         f"material models are meaningful at {ranges}; change --t-min/--t-max")
    fig = modulus_temperature_figure(
        grid + ZERO_CELSIUS, {m.name: frame[f"E_{m.name}_Pa"].to_numpy() for m in materials},
        glass_transition={m.name: m.glass_transition for m in materials},
        service_range={m.name: m.service_range for m in materials}, frequency=freq)
    with folder:
        folder.savefig(MODULUS_PNG, fig)
        folder.write_csv(MODULUS_CSV, frame, float_format="%.6g")
    _wrote(folder, [MODULUS_PNG, MODULUS_CSV])
