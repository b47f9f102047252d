"""``sealsim pneumatic run``: a pneumatic case file with all its variants into a result folder.

:func:`run_case_file` can be used from Python as well.  The folder gets ``timeseries.csv``
(all variants, long format with a ``variant`` column), ``summary.json``
(``{"variants": {NAME: {...}}}``), ``case_resolved.toml`` and the figures
(``pressure_stroke.png`` like Heipl & Murrenhoff Fig. 10, ``friction_stroke.png`` like
Figs. 12/13, ``friction_velocity.png``, ``timeseries_<variant>.png``; with seal heating also
``heating_<variant>.png`` and ``strokes_<variant>.csv``, the drift stroke by stroke).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pandas as pd

from sealsim import __version__
from sealsim.cases import dump_variants_toml
from sealsim.output import ResultFolder, run_variants
from sealsim.pneumatic.case import case_input_files, load_pneumatic_case_file
from sealsim.pneumatic.results import TIMESERIES_COLUMNS, PneumaticResult
from sealsim.pneumatic.simulation import simulate_variant
from sealsim.pneumatic.summary import DEFINITIONS, per_stroke
from sealsim.plotting.pneumatic import (
    friction_stroke_figure,
    friction_velocity_figure,
    heating_figure,
    pressure_stroke_figure,
    timeseries_figure,
)

__all__ = ["run_case_file", "write_results"]


def run_case_file(path: str | Path, out: str | Path, force: bool = False,
                  progress: Callable[[str, float, float], None] | None = None
                  ) -> dict[str, PneumaticResult]:
    """Simulate every variant of a case file and write the result folder ``out``.

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
    cases = load_pneumatic_case_file(path)
    inputs = [path] + [f for case in cases.values() for f in case_input_files(case, path.parent)]
    return run_variants(
        cases, out, lambda name, case, _: simulate_variant(name, case, path.parent, progress),
        lambda folder, results: write_results(folder, results, source=str(path)),
        force=force, inputs=inputs)


def write_results(folder: ResultFolder, results: dict[str, PneumaticResult],
                  source: str = "") -> None:
    """Write the table, summary, resolved case and figures of a set of variants."""
    frames = {name: r.timeseries for name, r in results.items()}
    table = pd.concat([f.assign(variant=name) for name, f in frames.items()], ignore_index=True)
    head = ["variant"] + TIMESERIES_COLUMNS
    extra = [c for c in table.columns if c not in head]
    folder.write_csv("timeseries.csv", table[head + extra], float_format="%.7g")
    first = next(iter(results.values())).case
    folder.write_json("summary.json", {
        "title": first.title, "source": source, "sealsim_version": __version__,
        "definitions": DEFINITIONS,
        "variants": {name: r.summary() for name, r in results.items()}})
    folder.write_text("case_resolved.toml", dump_variants_toml(
        {name: r.case for name, r in results.items()},
        header=f"Resolved case written by sealsim {__version__} (all defaults filled in).\n"
               f"Source: {source}\nRerun with: sealsim pneumatic run THIS_FILE --out DIR"))
    title = first.title
    strokes = {name: r.case.cylinder.stroke for name, r in results.items()}
    folder.savefig("pressure_stroke.png", pressure_stroke_figure(frames, title))
    periods = {name: r.case.controller.position.period() for name, r in results.items()
               if r.case.controller.mode == "position"}
    folder.savefig("friction_stroke.png", friction_stroke_figure(frames, strokes, title,
                                                                 periods))
    folder.savefig("friction_velocity.png", friction_velocity_figure(frames, title, periods,
                                                                     strokes))
    _contact_friction_figures(folder, first, Path(source).parent if source else Path("."))
    for name, r in results.items():
        heated = r.case.thermal is not None and r.case.thermal.seal_heating
        if heated and r.case.controller.mode == "cycle":
            strokes = per_stroke(r.timeseries, r.case.cylinder.stroke, r.seal_columns)
            folder.write_csv(f"strokes_{name}.csv", strokes, float_format="%.7g")
            folder.savefig(f"heating_{name}.png", heating_figure(
                r.timeseries, strokes, r.seal_columns,
                f"{title} -- {name}" if title else name))
        folder.savefig(f"timeseries_{name}.png",
                       timeseries_figure(r.timeseries, r.seal_columns,
                                         f"{title} -- {name}" if title else name))


def _contact_friction_figures(folder: ResultFolder, case, base_dir: Path) -> None:
    """``contact_friction_<seal>.png`` for every seal whose steady friction comes from its
    contact: p_c(z), h(z) and the Stribeck curve per pressure (maps and tables are cached)."""
    from sealsim.pneumatic.case import build_seals
    from sealsim.pneumatic.friction_tables import ContactTribology, film_profiles
    from sealsim.plotting.contact_friction import contact_friction_figure

    for seal in build_seals(case, base_dir):
        if seal.friction_table is None:
            continue
        cyl = case.cylinder
        diameter = cyl.bore if seal.location == "piston" else cyl.rod_diameter
        tribology = ContactTribology(**seal.friction_table.attrs["tribology"])
        profiles = film_profiles(seal.contact_map, tribology, seal.temperature, 0.1)
        folder.savefig(f"contact_friction_{seal.name}.png", contact_friction_figure(
            profiles, seal.friction_table, diameter, seal.temperature,
            seal.law.params.boundary_friction, 0.1, seal.name))
