"""``sealsim gland check``: a gland case file into a result folder.

:func:`check_case_file` can be used from Python as well.  The folder gets ``report.json``
(the result of :func:`sealsim.oring_gland`), ``checks.csv`` (one row per design check),
``stack.csv`` (min/nominal/max of squeeze, stretch, gland fill and extrusion gap per
temperature and swell), ``section.png`` (the section in its groove with the tolerance
extremes) and ``case_resolved.toml``.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pandas as pd

from sealsim import __version__
from sealsim.cases import dump_case_toml
from sealsim.output import ResultFolder, run_variants
from sealsim.plotting.gland import plot_gland_section
from sealsim.structure.gland_case import load_gland_case

__all__ = ["check_case_file", "stack_frame", "write_results"]


def check_case_file(path: str | Path, out: str | Path, force: bool = False, fe: bool = False,
                    progress: Callable[[str, float, float], None] | None = None
                    ) -> dict[str, Any]:
    """Check the gland of a case file and write the result folder ``out``.

    Parameters
    ----------
    path : str or Path
        Gland case file (TOML).
    out : str or Path
        Result folder; refused if it already holds results unless ``force``.
    force : bool
        Replace existing results.
    fe : bool
        Also the FE contact force and friction at nominal (the case's ``[fe]`` table).
    progress : callable, optional
        ``progress("gland", done, total)`` while the FE map is built.

    Returns
    -------
    dict
        The report (as written to ``report.json``).
    """
    from sealsim.api import oring_gland

    path = Path(path)
    case = load_gland_case(path)

    def check(name, case, report):
        return oring_gland(case, fe=fe, progress=report)

    def write(folder, results):
        write_results(folder, case, results["gland"], source=str(path))

    return run_variants({"gland": case}, out, check, write, force=force, inputs=[path],
                        progress=progress)["gland"]


def stack_frame(report: dict[str, Any]) -> pd.DataFrame:
    """The stack per temperature and swell as a table (one row per condition and
    quantity)."""
    rows = []
    for s in report["by_temperature"]:
        for quantity in ("squeeze_percent", "stretch_percent", "gland_fill_percent",
                         "extrusion_gap_mm"):
            rows.append({"temperature_C": s["temperature_C"], "fluid_swell": s["fluid_swell"],
                         "quantity": quantity, **s[quantity]})
    return pd.DataFrame(rows, columns=["temperature_C", "fluid_swell", "quantity", "min",
                                       "nominal", "max"])


def write_results(folder: ResultFolder, case, report: dict[str, Any], source: str = "") -> None:
    """report.json, checks.csv, stack.csv, section.png and case_resolved.toml."""
    folder.write_json("report.json", {"source": source, "sealsim_version": __version__,
                                      **report})
    folder.write_csv("checks.csv", pd.DataFrame(report["checks"])[
        ["name", "value", "limit", "unit", "bound", "ok", "maker", "source"]],
        float_format="%.6g")
    folder.write_csv("stack.csv", stack_frame(report), float_format="%.6g")
    folder.savefig("section.png", plot_gland_section(case, report))
    folder.write_text("case_resolved.toml", dump_case_toml(
        case, header=f"Resolved gland case written by sealsim {__version__}.\nSource: {source}"))
