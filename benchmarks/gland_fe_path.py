"""Newton on the FE load path of the gland check's nominal rod gland between 40 and 60 bar.

``sealsim.oring_gland("examples/gland/rod_reciprocating.toml", fe=True)`` (the CI test
``test_fe_at_nominal_is_the_structure_model_of_the_nominal_gland``) builds the FE map of the
nominal gland: O-ring 3.54 mm at 13.1 % squeeze on a 20 mm rod, coarse mesh, 0 / 50 / 100 bar.
This script solves that map's load path (in one process) up to its converged state at
40.625 bar and from there:

1. the step to 50 bar in 6, 12, 24 and 48 increments (cutbacks as the map's solver makes
   them), then on to 100 bar in the map's increments: F_N at 50 and 100 bar, or where the
   solver gave up -- whether the path gets through depends on the increments;
2. in the increment the 48-increment path cannot get past (a pressure rise of 100 Pa from its
   last converged state), Newton's residual and the change of the wetted length per
   iteration, with the wetted surface re-evaluated in iterations 1-8 (the solver) and held at
   its value of the increment's start.

    .venv/bin/python benchmarks/gland_fe_path.py

Nothing is written; the map cache is not used.  The last line is one JSON object: per number
of increments to 50 bar the pressure [bar] the path reached (100: through), and for the stuck
increment whether Newton converged with the wetted surface re-evaluated and held.
"""

from __future__ import annotations

import copy
import dataclasses
import json
import shutil
import tempfile
import warnings
from pathlib import Path

import felupe as fem
import numpy as np

import sealsim
import sealsim.api as api
from sealsim.errors import ConvergenceError
from sealsim.structure import solver
from sealsim.structure.case import load_structure_cases
from sealsim.structure.mapping import compute_map
from sealsim.structure.results import extract

GLAND = "examples/gland/rod_reciprocating.toml"
START = 40.625e5  # a converged state of the map's path (Pa)


class _Stop(Exception):
    pass


def gland_structure_case(folder: Path):
    """The structure case ``oring_gland(GLAND, fe=True)`` builds (its TOML copied to
    ``folder``)."""
    real = api.seal_friction

    def capture(path, *args, **kwargs):
        shutil.copy(path, folder / "gland_nominal.toml")
        raise _Stop

    api.seal_friction = capture
    try:
        sealsim.oring_gland(GLAND, fe=True)
    except _Stop:
        pass
    finally:
        api.seal_friction = real
    path = folder / "gland_nominal.toml"
    return next(iter(load_structure_cases(path, str(path)).values()))


def state_on_map_path(case, pressure: float):
    """A copy of the model at its converged state ``pressure`` on the map's load path."""
    captured = {}
    increment = solver._increment

    def hook(model, target, *args):
        if abs(model.state.pressure - pressure) < 1.0 and target.pressure > pressure:
            captured["model"] = copy.deepcopy(model)
            raise _Stop
        return increment(model, target, *args)

    solver._increment = hook
    try:
        compute_map(case, workers=1)
    except _Stop:
        pass
    finally:
        solver._increment = increment
    if "model" not in captured:
        raise SystemExit(f"the map's path has no converged state at {pressure / 1e5} bar")
    return captured["model"]


def pressure_step(model, bar: float, increments: int) -> str:
    solver.solve(model, [solver.LoadStep("pressure", pressure=bar * 1e5,
                                         increments=increments, record="none")])
    return f"F_N {extract(model).F_N:8.2f} N"


def newton_log(model, dp: float, update_wetting: bool) -> list[str]:
    """Newton's residual (relative to the reactions) and the change of the wetted length made
    before it, per iteration of a pressure rise ``dp`` [Pa]; the last line is the outcome."""
    rows = []
    change = [0.0]
    assemble, update = model.system.assemble, model.update_wetting

    def assemble_logged(items, field):
        f, K11 = assemble(items, field)
        r = np.linalg.norm(f[model.dof1]) / np.linalg.norm(f[model.dof0])
        rows.append(f"    iteration {len(rows):2d}: residual {r:9.3e}, "
                    f"wetted length changed by {change[0] * 1e6:6.2f} um before it")
        change[0] = 0.0
        return f, K11

    def update_logged():
        change[0] = update()
        return change[0]

    target = dataclasses.replace(model.state, pressure=model.state.pressure + dp)
    ext0 = model.set_load(target, 0.0)
    update()  # as the solver's increment does before Newton
    model.system.assemble = assemble_logged
    model.update_wetting = update_logged
    linear = solver.LinearSolver(solver.DEFAULT_LINEAR_SOLVER)
    try:
        iterations = solver._newton(model, ext0, 1e-8, 25, update_wetting, linear)
        rows.append(f"    converged (iteration {iterations})")
    except fem.NewtonConvergenceError as exc:
        rows.append(f"    failed: {exc}")
    finally:
        linear.release()
    return rows


def main() -> None:
    folder = Path(tempfile.mkdtemp(prefix="sealsim-gland-path-"))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            case = gland_structure_case(folder)
            start = state_on_map_path(case, START)
            print(f"map path at {START / 1e5} bar: F_N {extract(start).F_N:.2f} N")
            stuck = None
            summary = {"reached_bar": {}, "stuck_increment_converges": {}}
            for n in (6, 12, 24, 48):
                model = copy.deepcopy(start)
                line = []
                try:
                    line.append("50 bar: " + pressure_step(model, 50.0, n))
                    line.append("100 bar: " + pressure_step(
                        model, 100.0, case.map.pressure_increments))
                except ConvergenceError as exc:
                    line.append(f"stopped at {model.state.pressure / 1e5:.4g} bar "
                                f"({str(exc).rsplit('(', 1)[-1].rstrip(')')})")
                    if n == 48:
                        stuck = model
                print(f"{START / 1e5} -> 50 bar in {n:2d} increments: " + "; ".join(line))
                summary["reached_bar"][n] = round(model.state.pressure / 1e5, 4)
            if stuck is not None:
                print(f"\nfrom the 48-increment path's last state ({stuck.state.pressure / 1e5:.4g}"
                      " bar), +100 Pa:")
                for held in (False, True):
                    print("  wetted surface " + ("held at the increment's start" if held
                                                 else "re-evaluated in iterations 1-8") + ":")
                    log = newton_log(copy.deepcopy(stuck), 100.0, update_wetting=not held)
                    print("\n".join(log))
                    summary["stuck_increment_converges"]["held" if held else "re-evaluated"] = \
                        "converged" in log[-1]
            print(json.dumps(summary))
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
