"""``sealsim rotary run``: a rotary case file with all its variants into a result folder.

:func:`run_case_file` can be used from Python as well.  The folder gets ``timeseries.csv``
(all variants, long format), ``steps.csv``, ``summary.json``, ``case_resolved.toml`` and the
figures (``cycle_<variant>.png``, ``variants.png``, ``stribeck.png``).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim import __version__
from sealsim.cases import dump_variants_toml
from sealsim.output import ResultFolder, run_variants
from sealsim.plotting.rotary import cycle_figure, stribeck_figure, variants_figure
from sealsim.rotary.simulation import RotaryResult, friction_map, load_rotary_case, simulate

__all__ = ["run_case_file", "write_results"]

#: Contact temperatures of the model curves in the Stribeck-type plot [°C].
STRIBECK_TEMPERATURES_C = (40.0, 80.0)

#: Columns required in timeseries.csv, in this order (extra diagnostics follow).
TIMESERIES_HEAD = ["variant", "time_s", "speed_rpm", "torque_Nm", "power_W", "T_contact_C",
                   "T_groove_C", "T_sump_C", "film_um", "F_lub_N", "F_material_N"]


def run_case_file(path: str | Path, out: str | Path, force: bool = False,
                  progress: Callable[[str, float, float], None] | None = None
                  ) -> dict[str, RotaryResult]:
    """Simulate every variant of a case file and write the result folder ``out``.

    The case, its duty-cycle CSV files and the output location are all checked before the
    first simulation starts (see :func:`sealsim.output.run_variants`).

    Parameters
    ----------
    path : str or Path
        Case file (TOML).
    out : str or Path
        Result folder; refused if it already holds results unless ``force``.
    force : bool
        Replace existing results.
    progress : callable, optional
        ``progress(variant, simulated_time, end_time)``.
    """
    path = Path(path)
    cases = load_rotary_case(path)
    inputs = [path]
    for case in cases.values():  # read every duty CSV now: a bad one is refused up front
        duty = case.duty_cycle()
        duty.profile(path.parent)
        if duty.csv is not None:
            inputs.append(path.parent / duty.csv)
    return run_variants(
        cases, out, lambda name, case, report: simulate(case, base_dir=path.parent,
                                                        progress=report),
        lambda folder, results: write_results(folder, results, source=str(path)),
        force=force, inputs=inputs, progress=progress)


def write_results(folder: ResultFolder, results: dict[str, RotaryResult], source: str = "") -> None:
    """Write tables, summary, resolved case and figures of a set of variants."""
    frames = {name: r.timeseries for name, r in results.items()}
    table = pd.concat([f.assign(variant=name) for name, f in frames.items()], ignore_index=True)
    extra = [c for c in table.columns if c not in TIMESERIES_HEAD]
    folder.write_csv("timeseries.csv", table[TIMESERIES_HEAD + extra], float_format="%.6g")
    steps = pd.DataFrame([{"variant": name, "step": k + 1, **step}
                          for name, r in results.items() for k, step in enumerate(r.steps)])
    folder.write_csv("steps.csv", steps, float_format="%.6g")
    first = next(iter(results.values())).case
    folder.write_json("summary.json", {
        "title": first.title, "source": source, "sealsim_version": __version__,
        "averaging": "each step's values are averages over its last 30 s",
        "variants": {name: r.summary() for name, r in results.items()}})
    folder.write_text("case_resolved.toml", dump_variants_toml(
        {name: r.case for name, r in results.items()},
        header=f"Resolved case written by sealsim {__version__} (all defaults filled in).\n"
               f"Source: {source}"))
    for name, r in results.items():
        title = f"Variant '{name}'" + (f"\n{r.case.title}" if r.case.title else "")
        folder.savefig(f"cycle_{name}.png",
                       cycle_figure(r.timeseries, r.case.seal.shaft_diameter / 2, title))
    folder.savefig("variants.png", variants_figure(frames, first.title))
    speeds = np.geomspace(1.0, 3000.0, 120)
    curves = {name: friction_map(r.case, speeds, STRIBECK_TEMPERATURES_C)
              for name, r in results.items()}
    folder.savefig("stribeck.png", stribeck_figure(frames, curves))
    fe = {name: r.case for name, r in results.items() if r.case.lip.force == "fe"}
    if fe:
        from sealsim.plotting.structure import plot_lip_force
        from sealsim.rotary.lip_fe import lip_force_table

        # the table the simulation used (cached by it): the lip mounted at its mounting
        # temperature
        tables = {name: lip_force_table(c.seal, c.lip, c.seal.mounting_temperature).frame()
                  for name, c in fe.items()}
        folder.write_csv("lip_fe.csv", pd.concat(
            [t.assign(variant=name) for name, t in tables.items()], ignore_index=True),
            float_format="%.6g")
        folder.savefig("lip_fe.png", plot_lip_force(tables, first.title))
