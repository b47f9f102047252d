"""``sealsim friction run CASE.toml --out DIR``: run a friction test-bench case.

Writes ``timeseries.csv`` (all variants, one ``variant`` column), ``summary.json`` (break-away
forces, loop areas, dissipated energy per variant, warnings), plots (``force_velocity.png``,
``theta_velocity.png`` for the Θ law, ``force_displacement.png``, ``timeseries.png``) and
``case_resolved.toml`` (the case with every default filled in).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import typer
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

from sealsim.cases import load_toml
from sealsim.cli._common import console, guarded
from sealsim.output import ResultFolder

friction_app = typer.Typer(
    help="Dynamic friction laws (Stribeck, LuGre, Dahl, GMS, Θ rate-and-state) on test benches.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


@friction_app.callback()
def _friction() -> None:
    """Dynamic friction laws (Stribeck, LuGre, Dahl, GMS, Θ rate-and-state) on test benches."""


@friction_app.command("run")
@guarded
def run(
    case: Path = typer.Argument(..., help="Case file (TOML), e.g. examples/friction/"
                                          "lugre_hysteresis.toml."),
    out: Path = typer.Option(..., "--out", "-o", help="Result folder (must not hold results "
                                                      "unless --force)."),
    force: bool = typer.Option(False, "--force", help="Replace an existing result folder."),
) -> None:
    """Run a friction bench case: time series, summary, plots and the resolved case."""
    from sealsim.cases import dump_variants_toml
    from sealsim.friction.case import (
        build_law,
        load_friction_cases,
        make_inputs,
        run_friction_case,
    )

    folder = ResultFolder(out, force)            # refuse an existing folder before computing
    cases = load_friction_cases(load_toml(case), source=f"case file {case.name!r}")
    laws, notes = {}, []
    for name, c in cases.items():
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            laws[name] = build_law(c)
        for w in caught:
            if str(w.message) not in notes:
                notes.append(str(w.message))
    for text in notes:
        console.print(f"[yellow]warning:[/yellow] {text}")

    results, summaries = {}, {}
    with Progress(TextColumn("{task.description}"), BarColumn(), TimeElapsedColumn(),
                  console=console, transient=True) as progress:
        for name, c in cases.items():
            task = progress.add_task(f"{name}", total=1.0)
            results[name], summaries[name] = run_friction_case(
                c, laws[name], progress=lambda f, task=task: progress.update(task, completed=f))
            progress.update(task, completed=1.0)

    steady_f, steady_theta = {}, {}
    for name, c in cases.items():
        if not c.output.steady_curve:
            continue
        law, res = laws[name], results[name]
        vmax = float(np.max(np.abs(res.velocity))) or 1e-3
        v = np.linspace(-vmax, vmax, 801) if np.min(res.velocity) < 0 else np.linspace(
            0, vmax, 401)[1:]
        inputs = make_inputs(c)
        steady_f[name] = (v, law.steady_force(v, inputs))
        if "theta" in law.state_names:
            steady_theta[name] = (v, law.steady_state(v, inputs)[0])

    from sealsim.plotting.friction import (
        last_cycles,
        plot_force_displacement,
        plot_force_velocity,
        plot_theta_velocity,
        plot_timeseries,
    )

    title = next(iter(cases.values())).title or case.stem
    max_rows = min(c.output.max_rows for c in cases.values())
    shown = {name: r.decimated(max_rows) for name, r in results.items()}
    frames = []
    for name, r in shown.items():
        frame = pd.DataFrame(r.columns())
        frame.insert(0, "variant", name)
        frames.append(frame)
    table = pd.concat(frames, ignore_index=True)
    summary = {"title": title, "case_file": str(case), "warnings": notes,
               "variants": summaries}

    with folder:
        folder.write_csv("timeseries.csv", table, float_format="%.10g")
        folder.write_json("summary.json", summary)
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
            cases, header=f"Resolved case of {case.name} (all defaults filled in); "
                          "rerun with: sealsim friction run THIS_FILE --out DIR"))
    for name, s in summaries.items():
        brk = ", ".join(f"{f:.4g}" for f in s["breakaway_forces_N"][:4]) or "-"
        console.print(f"{name}: dissipated {s['dissipated_energy_J']:.4g} J, "
                      f"break-away [N]: {brk}")
    console.print(f"results written to {out}")
