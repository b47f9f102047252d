"""``sealsim friction run``: a friction test-bench case file with all its variants into a
result folder.

:func:`run_case_file` can be used from Python as well.  The folder gets ``timeseries.csv``
(all variants, one ``variant`` column), ``summary.json`` (break-away forces, loop areas,
dissipated energy per variant, warnings), plots (``force_velocity.png``, ``theta_velocity.png``
for the Θ law, ``force_displacement.png``, ``timeseries.png``) and ``case_resolved.toml`` (the
case with every default filled in).  A case with a ``[seal]`` runs the law on that seal's
contact (:func:`sealsim.pneumatic.bench.bench_inputs`); its F_N, b and map are in the summary
(``variants.NAME.seal``).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim import __version__
from sealsim.cases import dump_variants_toml, load_toml
from sealsim.friction import make_law
from sealsim.friction.base import PassivityWarning
from sealsim.friction.case import (
    build_law,
    load_friction_cases,
    make_inputs,
    run_friction_case,
)
from sealsim.friction.parameters import parameter_set_note
from sealsim.output import ResultFolder, run_variants
from sealsim.pneumatic.bench import bench_inputs
from sealsim.plotting.friction import (
    last_cycles,
    plot_force_displacement,
    plot_force_velocity,
    plot_theta_velocity,
    plot_timeseries,
    steady_velocity_grid,
)

__all__ = ["run_case_file"]


def run_case_file(path: str | Path, out: str | Path, force: bool = False,
                  progress: Callable[[str, float, float], None] | None = None) -> dict:
    """Run every variant of a friction case file and write the result folder ``out``.

    Parameters
    ----------
    path : str or Path
        Case file (TOML).
    out : str or Path
        Result folder; refused if it already holds results unless ``force``.
    force : bool
        Replace existing results.
    progress : callable, optional
        ``progress(variant, fraction_done, 1.0)``.

    Returns
    -------
    dict
        The summary written to ``summary.json`` (``title``, ``source``: the case file,
        ``sealsim_version``, ``warnings``: parameter warnings such as a non-passive LuGre set,
        ``variants``: per-variant summaries) -- the same keys as the other models' summaries.
    """
    case = Path(path)
    cases = load_friction_cases(load_toml(case), source=f"case file {case.name!r}")
    laws, inputs, seals, alarms, notes = {}, {}, {}, [], []
    for name, c in cases.items():
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            laws[name] = build_law(c)
        for w in caught:
            known = _documented(c, laws[name], w)
            target = notes if known else alarms
            text = known or str(w.message)
            if text not in target:
                target.append(text)
        unfitted = parameter_set_note(c.friction)
        if unfitted and unfitted not in notes:
            notes.append(unfitted)
        if c.seal is not None:    # before any run: a bad map fails the whole case at once
            inputs[name], seals[name] = bench_inputs(c, laws[name], case.parent)
        else:
            inputs[name] = make_inputs(c)
    title = next(iter(cases.values())).title or case.stem
    summary = {"title": title, "source": str(case), "sealsim_version": __version__,
               "warnings": alarms, "notes": notes, "variants": {}}

    def simulate(name, c, report):
        result, summary["variants"][name] = run_friction_case(c, laws[name], progress=(
            None if report is None else lambda f: report(f, 1.0)), inputs=inputs[name])
        if name in seals:
            summary["variants"][name]["seal"] = seals[name]
        if report is not None:
            report(1.0, 1.0)
        return result

    def write(folder: ResultFolder, results: dict) -> None:
        _write_results(folder, cases, laws, inputs, results, summary)

    run_variants(cases, out, simulate, write, force=force, inputs=[case], progress=progress)
    return summary


def _documented(case, law, caught) -> str | None:
    """A warning that only restates a documented property of a published parameter set (the
    Canudas de Wit 1995 LuGre set is not passive) becomes a note for the summary; anything else
    stays a warning."""
    name = case.friction.parameter_set
    if name is None or not issubclass(caught.category, PassivityWarning):
        return None
    published = make_law(type(case.friction).model_validate(
        {"law": law.name, "parameter_set": name}), **({"warn": False} if law.name == "lugre"
                                                      else {}))
    if published.params != law.params:      # the user changed the published values
        return None
    return (f"the published parameter set {name!r} is not passive in the sense of Åström & "
            "Canudas de Wit (2008, Eq. 7): its friction force can supply energy during fast "
            "velocity changes (documented with the set; it reproduces the paper's benchmarks)")


#: names of the laws in legends
LAW_LABELS = {"coulomb": "Coulomb", "stribeck": "Stribeck", "lugre": "LuGre", "dahl": "Dahl",
              "gms": "GMS", "theta": "Θ"}


def _write_results(folder: ResultFolder, cases: dict, laws: dict, inputs: dict,
                   results: dict, summary: dict) -> None:
    """Table, summary, figures and resolved case of the variants of a friction case."""
    steady_f, steady_theta = {}, {}
    for name, c in cases.items():
        if not c.output.steady_curve:
            continue
        law, res = laws[name], results[name]
        v = steady_velocity_grid(float(np.min(res.velocity)), float(np.max(res.velocity)))
        if v.size == 0:                      # the body never moved
            v = np.linspace(1e-5, 1e-3, 200)
        steady_f[name] = (v, law.steady_force(v, inputs[name]))
        if "theta" in law.state_names:
            steady_theta[name] = (v, law.steady_state(v, inputs[name])[0])

    title = summary["title"]
    max_rows = min(c.output.max_rows for c in cases.values())
    shown = {name: r.decimated(max_rows) for name, r in results.items()}
    frames = []
    for name, r in shown.items():
        frame = pd.DataFrame(r.columns())
        frame.insert(0, "variant", name)
        frames.append(frame)
    table = pd.concat(frames, ignore_index=True)

    folder.write_csv("timeseries.csv", table, float_format="%.10g")
    folder.write_json("summary.json", summary)
    if list(shown) == ["base"]:              # no variants: the legends name the law
        label = f"{LAW_LABELS.get(laws['base'].name, laws['base'].name)} law"
        shown = {label: shown["base"]}
        steady_f = {label: v for v in steady_f.values()}
        steady_theta = {label: v for v in steady_theta.values()}
    loops = last_cycles(shown)
    steady_f = {k2: steady_f[k1] for k1, k2 in zip(shown, loops) if k1 in steady_f}
    steady_theta = {k2: steady_theta[k1] for k1, k2 in zip(shown, loops)
                    if k1 in steady_theta}
    folder.savefig("force_velocity.png", plot_force_velocity(loops, steady_f, title))
    fig = plot_theta_velocity(loops, steady_theta, title)
    if fig is not None:
        folder.savefig("theta_velocity.png", fig)
    folder.savefig("force_displacement.png", plot_force_displacement(loops, title))
    folder.savefig("timeseries.png", plot_timeseries(shown, title))
    folder.write_text("case_resolved.toml", dump_variants_toml(
        cases, header=f"Resolved case of {summary['source']} written by sealsim "
                      f"{__version__} (all defaults filled in); "
                      "rerun with: sealsim friction run THIS_FILE --out DIR"))
