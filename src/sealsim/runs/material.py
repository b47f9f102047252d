"""``sealsim material fit``: a material fit file into a result folder.

The fits are computed by :mod:`sealsim.calibration.material_fit`; this module checks the
result folder before anything is computed (the fit file and its data files, if inside the
folder, are refused: committing the results would remove them) and writes

* ``<name>.toml`` -- the compound in the catalogue format with a source tag on every value,
  usable as ``material = "<name>.toml"`` in structure, rotary, pneumatic and study cases, in the
  one-call API and by ``sealsim material show <name>.toml``;
* ``report.json`` -- ``{"model", "parameters": {NAME: {"value", "stderr", ...}},
  "modes": {MODE: {"rel_rmse", "r2", ...}}}``, plus the comparison models, the Drucker
  stability of every model (``unstable_models``: where), the viscoelastic and dilatometric
  details and the source of every compound value;
* ``hyperelastic_<mode>.png`` (data and models, relative error), ``curves.csv`` (every point
  with each model's stress), ``dma_master_curve.png``, ``shift_factors.png``, ``prony.csv``,
  ``shift_factors.csv``, ``dilatometry.png``, ``case_resolved.toml``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.calibration.material_fit import (
    MaterialFitResult,
    fit_material,
    load_material_fit_case,
)
from sealsim.cases import dump_case_toml
from sealsim.output import ResultFolder
from sealsim.plotting.material import (
    plot_dilatometry,
    plot_master_curve,
    plot_shift_factors,
    plot_stress_mode,
)
from sealsim.properties.hyperelastic import MODES, nominal_stress
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["run_material_fit_file"]


def _inputs(path: Path, case) -> list[Path]:
    """The fit file and every data file it reads (refused inside the result folder)."""
    files = [path]
    tables = []
    if case.hyperelastic is not None:
        tables += case.hyperelastic.curves
    if case.viscoelastic is not None:
        tables += case.viscoelastic.files
    if case.dilatometry is not None:
        tables.append(case.dilatometry)
    for t in tables:
        p = Path(t.file)
        files.append(p if p.is_absolute() else path.parent / p)
    return files


def run_material_fit_file(path: str | Path, out: str | Path, force: bool = False
                          ) -> MaterialFitResult:
    """Fit a material fit file and write the result folder ``out`` (see the module)."""
    path = Path(path)
    case = load_material_fit_case(path)
    folder = ResultFolder(out, force, inputs=_inputs(path, case))  # before computing
    result = fit_material(case, path.parent, origin=path.name)
    title = case.title or case.compound.name
    with folder:
        folder.write_text(f"{case.compound.name}.toml", result.compound_text)
        folder.write_json("report.json", result.report)
        if result.hyperelastic is not None:
            _write_hyperelastic(folder, result, title)
        if result.shift is not None and result.prony is not None:
            _write_dma(folder, result, title)
        if result.expansion is not None:
            e = result.expansion
            grid = np.linspace(e.temperature.min(), e.temperature.max(), 200)
            folder.savefig("dilatometry.png", plot_dilatometry(
                e.temperature - ZERO_CELSIUS_K, e.strain, grid - ZERO_CELSIUS_K,
                e.model(grid), e.glass_transition - ZERO_CELSIUS_K, title))
        folder.write_text("case_resolved.toml", dump_case_toml(
            case, header=f"Resolved material fit file {path.name} (all defaults filled in); "
                         f"paths relative to {str(path.parent.resolve())}"))
    return result


def _models(result: MaterialFitResult):
    return [(result.hyperelastic.label + " (compound)", result.hyperelastic)] + \
        list(result.comparisons.items())


def _write_hyperelastic(folder: ResultFolder, result: MaterialFitResult, title: str) -> None:
    rows = []
    for mode in MODES:
        curves = [c for c in result.curves if c.mode == mode]
        if not curves:
            continue
        lam_all = np.concatenate([c.stretch for c in curves])
        grid = np.linspace(lam_all.min(), lam_all.max(), 200)
        models = []
        for label, fit in _models(result):
            models.append((label, mode in fit.fit_modes, grid,
                           nominal_stress(fit.model, fit.parameters, mode, grid),
                           fit.modes[mode]["rel_rmse"]))
        data = [(c.name, c.role, c.stretch, c.stress) for c in curves]
        folder.savefig(f"hyperelastic_{mode}.png", plot_stress_mode(mode, data, models, title))
        for c in curves:
            row = {"curve": c.name, "mode": mode, "role": c.role, "stretch": c.stretch,
                   "stress_Pa": c.stress}
            for label, fit in _models(result):
                row[f"model_{label}_Pa"] = nominal_stress(fit.model, fit.parameters, mode,
                                                          c.stretch)
            rows.append(pd.DataFrame(row))
    folder.write_csv("curves.csv", pd.concat(rows, ignore_index=True), float_format="%.8g")


def _write_dma(folder: ResultFolder, result: MaterialFitResult, title: str) -> None:
    from sealsim.calibration.viscoelastic_fit import master_curve

    shift, prony = result.shift, result.prony
    f_r, e1, e2 = master_curve(result.dma, shift)
    grid = np.logspace(np.log10(f_r.min()), np.log10(f_r.max()), 300)
    ref_c = shift.reference_temperature - ZERO_CELSIUS_K
    compound = result.compound()._modulus(np.full(grid.shape, shift.reference_temperature),
                                          grid)
    folder.savefig("dma_master_curve.png", plot_master_curve(
        f_r, e1, e2, grid, prony.storage(grid), prony.loss(grid), ref_c, title,
        compound_storage=compound))
    t = shift.temperatures
    tgrid = np.linspace(t.min(), t.max(), 200)
    law = f"WLF: C1 = {shift.parameters['c1']:.3g}, C2 = {shift.parameters['c2']:.3g} K"
    if shift.arrhenius_below is not None and shift.arrhenius_below > t.min():
        law += (f" above T_g = {shift.arrhenius_below - ZERO_CELSIUS_K:.3g} °C, Arrhenius "
                "below (the compound's law)")
    curves = [(law, shift.log10_shift(tgrid))]
    if result.arrhenius is not None:
        curves.append((f"Arrhenius: E_a = "
                       f"{result.arrhenius.parameters['activation_energy'] / 1e3:.0f} kJ/mol",
                       result.arrhenius.log10_shift(tgrid)))
    folder.savefig("shift_factors.png", plot_shift_factors(
        t - ZERO_CELSIUS_K, shift.log_shift, shift.log_shift_stderr, tgrid - ZERO_CELSIUS_K,
        curves, title))
    folder.write_csv("shift_factors.csv", pd.DataFrame({
        "temperature_C": t - ZERO_CELSIUS_K, "log10_aT": shift.log_shift,
        "log10_aT_stderr": shift.log_shift_stderr,
        "log10_aT_law": shift.log10_shift(t),
        "storage_rel_rmse_compound": [
            f["storage_rel_rmse_compound"]
            for f in result.report["viscoelastic"]["shift_factors"]]}), float_format="%.8g")
    folder.write_csv("prony.csv", pd.DataFrame({
        "relaxation_time_s": np.r_[np.inf, prony.relaxation_times],
        "modulus_Pa": np.r_[prony.equilibrium_modulus, prony.moduli],
        "stderr_Pa": prony.standard_errors}), float_format="%.8g")
