"""``sealsim oil ...`` and ``sealsim material ...``: look up, tabulate and plot properties.

The commands hold no physics: the tables come from :mod:`sealsim.properties.tables`; the
commands print them (°C, mm²/s, mPa·s, MPa) and write plots through
:class:`sealsim.output.ResultFolder`.

JSON output (``--json``) uses one key per value with the unit in the key name:

* oils: ``name``, ``family``, ``origin``, ``nu40_mm2_s``, ``nu100_mm2_s``,
  ``viscosity_index``, ``rho15_kg_m3``, ``min_temperature_C``, ``source``; ``oil show`` adds
  ``pressure_viscosity_coefficient_1_Pa``, ``walther_A``, ``walther_B``,
  ``thermal_expansion_1_K``, ``property_laws``, ``notes`` and
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
from enum import Enum
from pathlib import Path

import numpy as np
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
    get_elastomer,
    list_elastomers,
    load_elastomer_file,
)
from sealsim.properties.oils import Oil, get_oil, list_oils, load_oil_file
from sealsim.properties.tables import (
    celsius,
    default_material_temperatures,
    find_material,
    material_details,
    material_rows,
    material_summary,
    modulus_curves,
    oil_property_laws,
    oil_rows,
    oil_summary,
    unique_by_name,
    viscosity_curves,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["material_app", "oil_app"]

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


def _positive(value: float, option: str, unit: str) -> float:
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{option}: {value!r} {unit} is not allowed; give a finite value > 0")
    return float(value)


def _grid_celsius(t_min: float, t_max: float) -> np.ndarray:
    """Plot temperatures [degC]: whole-degree steps from t_min to t_max (both included)."""
    for value, name in ((t_min, "--t-min"), (t_max, "--t-max")):
        if not math.isfinite(value) or value < -ZERO_CELSIUS_K:
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


def _extra_materials(material_file: Path | None) -> dict[str, Elastomer]:
    return load_elastomer_file(material_file) if material_file is not None else {}


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
    "family, nu40 = '68 mm^2/s', nu100, density15, ...), used next to the catalogue.")
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
        help="Comma-separated temperatures in degC, or each with its unit ('-20 degC, 300 K'); "
             "default 20,40,60,80,100."),
    json: bool = JSON_OPTION,
    oil_file: Path | None = OIL_FILE_OPTION,
) -> None:
    """Properties of one oil: ν, η, ρ, k and c_p at several temperatures.

    A temperature below the oil's minimum temperature is an error; a
    viscosity below 2 mm²/s (outside ASTM D341) is shown with a note.

    --json prints one object: the keys of 'oil list' plus
    pressure_viscosity_coefficient_1_Pa, walther_A, walther_B,
    thermal_expansion_1_K, property_laws (which law gives ρ, k, c_p), notes and
    table, a list of rows with temperature_C, nu_mm2_s, eta_Pa_s,
    rho_kg_m3, k_W_mK, cp_J_kgK.
    """
    extra = _extra_oils(oil_file)
    oil = get_oil(name, extra)
    temps = parse_celsius_list(temperatures, DEFAULT_OIL_TEMPERATURES_C, "--temperatures")
    rows, notes = oil_rows(oil, temps, "--temperatures")
    origin = str(oil_file) if oil.name in extra else "catalogue"
    info = {**oil_summary(oil, origin),
            "pressure_viscosity_coefficient_1_Pa": oil.pressure_viscosity_coefficient,
            "walther_A": oil.walther_A, "walther_B": oil.walther_B,
            "thermal_expansion_1_K": oil.thermal_expansion,
            "property_laws": oil_property_laws(oil)}
    if json:
        _notes(notes)
        print_json({**info, "notes": notes, "table": rows})
        return
    _say(f"{oil.name} ({oil.family} oil)")
    _say(f"  ν40 = {info['nu40_mm2_s']:.1f} mm²/s, ν100 = {info['nu100_mm2_s']:.2f} mm²/s, "
         f"VI = {info['viscosity_index']:.0f}, ρ15 = {oil.rho15:.0f} kg/m³, "
         f"min. temperature {info['min_temperature_C']:.0f} °C, "
         f"α = {oil.pressure_viscosity_coefficient * 1e9:.0f} 1/GPa")
    _say(f"  {oil_property_laws(oil)}")
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
    oils = unique_by_name([get_oil(n, extra) for n in names])
    grid = _grid_celsius(t_min, t_max)
    folder = ResultFolder(out, force=force, inputs=[oil_file] if oil_file else [])  # before work
    frame, notes = viscosity_curves(oils, grid, "--t-min/--t-max")
    if frame.drop(columns="temperature_C").isna().all().all():
        raise InputError(f"nothing to plot between {grid[0]:g} and {grid[-1]:g} degC: "
                         + "; ".join(notes) + "; change --t-min/--t-max")
    t_k = grid + ZERO_CELSIUS_K
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
        help="Comma-separated temperatures in degC, or each with its unit ('-20 degC, 300 K'); "
             "default: the service range in 20 degC steps."),
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
    rows, notes = material_rows(m, temps, freq, "--temperatures")
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
         f"MPa, C01 = {m.c01 / 1e6:.4g} MPa, K = {m.bulk_modulus / 1e6:.0f} MPa; "
         f"6(C10 + C01) = {6e-6 * (m.c10 + m.c01):.3g} MPa, "
         f"{100 * m.constants_modulus_mismatch():+.1f} % from the curve at "
         f"{m.test_frequency:g} Hz")
    _say(f"  WLF: C1 = {m.wlf_c1:g}, C2 = {m.wlf_c2:g} K, T_ref = "
         f"{info['wlf_reference_temperature_C']:g} °C; E(T) from the {info['modulus_model']}")
    _say(f"  source: {m.source}")
    console.print(_table(
        f"E(T) at {freq:g} Hz; a_T relative to {info['wlf_reference_temperature_C']:g} °C",
        ["T\n[°C]", "E\n[MPa]", "a_T\n[-]", "log10 a_T\n[-]"],
        [[f"{r['temperature_C']:g}", _g(r["E_Pa"] / 1e6), f"{r['a_T']:.3e}",
          f"{round(r['log10_a_T'], 2) + 0.0:.2f}"] for r in rows]))   # + 0.0: no "-0.00"
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
    materials = unique_by_name([find_material(n, extra) for n in names])
    freq = _positive(frequency, "--frequency", "Hz")
    lo = min(celsius(m.glass_transition) for m in materials) - 40.0 if t_min is None else t_min
    hi = max(celsius(m.service_range[1]) for m in materials) + 20.0 if t_max is None else t_max
    grid = _grid_celsius(math.floor(lo / 10.0) * 10.0 if t_min is None else lo,
                         math.ceil(hi / 10.0) * 10.0 if t_max is None else hi)
    folder = ResultFolder(out, force=force,
                          inputs=[material_file] if material_file else [])  # before any work
    frame = modulus_curves(materials, grid, freq)
    if frame.drop(columns="temperature_C").isna().all().all():
        ranges = ", ".join(f"{m.name} {celsius(m.allowed_range[0]):.0f} to "
                           f"{celsius(m.allowed_range[1]):.0f} degC" for m in materials)
        raise InputError(f"nothing to plot between {grid[0]:g} and {grid[-1]:g} degC: the "
                         f"material models are meaningful at {ranges}; change --t-min/--t-max")
    fig = modulus_temperature_figure(
        grid + ZERO_CELSIUS_K, {m.name: frame[f"E_{m.name}_Pa"].to_numpy() for m in materials},
        glass_transition={m.name: m.glass_transition for m in materials},
        service_range={m.name: m.service_range for m in materials}, frequency=freq)
    with folder:
        folder.savefig(MODULUS_PNG, fig)
        folder.write_csv(MODULUS_CSV, frame, float_format="%.6g")
    _wrote(folder, [MODULUS_PNG, MODULUS_CSV])


@material_app.command("fit")
@guarded
def material_fit(
    data: Path = typer.Argument(..., help="Material fit file (TOML): stress-strain curves, DMA "
                                "sweeps, dilatometry, e.g. examples/materials/treloar_ogden.toml."),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder (must not hold results "
                                                      "unless --force)."),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder."),
) -> None:
    """Fit hyperelastic (and viscoelastic, thermal) models to a compound's tests.

    Writes NAME.toml (the compound in the catalogue format, usable as
    material = "NAME.toml" in cases and by 'sealsim material show NAME.toml'),
    report.json (parameters with standard errors, RMS relative error and R²
    per mode, Drucker stability), plots per mode and CSV tables.
    """
    from sealsim.runs.material import run_material_fit_file

    result = run_material_fit_file(data, out, force)
    report = result.report
    if result.hyperelastic is not None:
        _say(f"{result.hyperelastic.label}:")
        for name, p in report["hyperelastic"]["parameters"].items():
            se = p["stderr"]
            unit = p["unit"]
            scale, shown = (1e-6, "MPa") if unit == "Pa" else (1.0, unit)
            value = f"{p['value'] * scale:.6g}"
            err = f" ± {se * scale:.2g}" if se is not None else " (not determined)"
            flag = "" if p["identifiable"] else "  NOT IDENTIFIABLE"
            if p.get("at_limit"):
                flag += f" (on its {p['at_limit']}: the model allows no better fit)"
            _say(f"  {name} = {value}{err} {shown}{flag}")
        for mode, m in report["hyperelastic"]["modes"].items():
            r2 = "-" if m["r2"] is None else f"{m['r2']:.4f}"
            _say(f"  {mode} ({m['role']}): RMS relative error {100 * m['rel_rmse']:.1f} %, "
                 f"R² {r2}")
        for label, fit in report["comparisons"].items():
            errs = ", ".join(f"{mode} {100 * m['rel_rmse']:.1f} %"
                             + ("" if m["role"] == "fit" else " (predicted)")
                             for mode, m in fit["modes"].items())
            _say(f"  compare {label}: {errs}")
        for label, where in report["unstable_models"].items():
            text = "; ".join(f"{mode} stable only for λ {w['stable_from']:.3g}–"
                             f"{w['stable_to']:.3g}" for mode, w in where.items())
            _say(f"  Drucker-unstable: {label}: {text}")
    if "dma" in report["modes"]:
        m = report["modes"]["dma"]
        _say(f"DMA: Prony series {report['viscoelastic']['prony_terms']} terms, RMS relative "
             f"error E' {100 * m['rel_rmse']:.1f} %, E'' {100 * m['rel_rmse_loss']:.1f} % on "
             f"the master curve; moved by the fitted shift law E' "
             f"{100 * m['rel_rmse_law']:.1f} %, E'' {100 * m['rel_rmse_loss_law']:.1f} %; the "
             f"compound file's E'(T, f) (master-curve sigmoid and shift law, what the seal "
             f"models use) {100 * m['rel_rmse_compound']:.1f} %")
    _notes(report["notes"])
    _say(f"compound file: {Path(out) / (result.case.compound.name + '.toml')}")
    _say(f"results written to {out}")
