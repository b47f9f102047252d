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
   its value of the increment's start; after every update of the wetted surface its edges
   inside a segment (distance from the first node in contact, and the two contact pressures
   the edge was extrapolated from).

    .venv/bin/python benchmarks/gland_fe_path.py

It first builds the whole map and counts its converged increments whose wetted surface the
solver froze *unsettled* (still changing by more than its tolerance after iteration 8). At the
40.625 bar state, at states of the 48-increment path and in the stuck increment it maps the
wetted-surface update at equilibrium (:func:`wetting_map`): the least G(d) - d over the upstream
edge's segment is negative while the update has a fixed point there and positive once it has
none.

Nothing is written; the map cache is not used.  The last line is one JSON object: the map's
converged and frozen-unsettled increments, the least G(d) - d [um] per pressure [bar], per
number of increments to 50 bar the pressure [bar] the path reached (100: through), and for the
stuck increment whether Newton converged with the wetted surface re-evaluated and held.
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
from sealsim.structure.model import SealModel
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


def unsettled_increments(case) -> tuple[int, list[float]]:
    """The map's converged increments, and the last change of the wetted length [m] of each
    one whose wetted surface the solver froze unsettled (after iteration 8, the change still
    above its tolerance): those states are not fixed points of the wetted-surface update."""
    changes = []
    count = [0]
    last = [0.0]
    update, newton = SealModel.update_wetting, solver._newton

    def update_recorded(self):
        last[0] = update(self)
        return last[0]

    def newton_counted(model, *args, **kwargs):
        last[0] = 0.0
        iterations = newton(model, *args, **kwargs)
        count[0] += 1
        if last[0] > 1e-4 * model.assembly.seal.cord_diameter:  # _newton's tolerance
            changes.append(last[0])
        return iterations

    SealModel.update_wetting, solver._newton = update_recorded, newton_counted
    try:
        compute_map(case, workers=1)
    finally:
        SealModel.update_wetting, solver._newton = update, newton
    return count[0], changes


def pressure_step(model, bar: float, increments: int) -> str:
    solver.solve(model, [solver.LoadStep("pressure", pressure=bar * 1e5,
                                         increments=increments, record="none")])
    return f"F_N {extract(model).F_N:8.2f} N"


def edges(model) -> list[str]:
    """The wetted surface's edges inside a segment: the first node in contact j, the edge's
    distance from it and the contact pressures p_j, p_k of j and the next node in contact k
    that :func:`sealsim.structure.loads.wetted_fractions` extrapolated it from."""
    pc = model.contact_pressure()
    x = model.pressure.positions()
    lengths = np.linalg.norm(np.roll(x, -1, axis=0) - x, axis=1)
    s0, s1 = model.pressure.s0, model.pressure.s1
    n = len(s0)
    out = []
    for seg in range(n):
        if s1[seg] == 1.0 and 0.0 < s0[seg] < 1.0:  # dry node seg, wet towards seg + 1
            j, k, d = seg, (seg - 1) % n, s0[seg] * lengths[seg]
        elif s0[seg] == 0.0 and 0.0 < s1[seg] < 1.0:  # wet from seg, dry node seg + 1
            j, k, d = (seg + 1) % n, (seg + 2) % n, (1.0 - s1[seg]) * lengths[seg]
        else:
            continue
        out.append(f"node {j} + {d * 1e6:5.1f} um (p_j {pc[j] / 1e5:6.2f}, "
                   f"p_k {pc[k] / 1e5:6.2f} bar)")
    return out or ["at nodes"]


def wetting_map(model, dp: float, distances_um) -> list[tuple[float, float]]:
    """The wetted-surface update at equilibrium, G(d), for the upstream edge held at each
    distance d [um] from its first node in contact (the segment it lies in after the update
    of the increment's start): Newton solved with the wetted surface held, then the edge the
    contact pressures ask for (None: Newton failed). A fixed point of the solver's update is a
    root of G(d) - d."""
    target = dataclasses.replace(model.state, pressure=model.state.pressure + dp)
    probe = copy.deepcopy(model)
    probe.set_load(target, 0.0)
    probe.update_wetting()
    s0, s1 = probe.pressure.s0, probe.pressure.s1
    seg = next(k for k in range(len(s0)) if s1[k] == 1.0 and 0.0 < s0[k] < 1.0)
    out = []
    for d in distances_um:
        trial = copy.deepcopy(model)
        ext0 = trial.set_load(target, 0.0)
        trial.update_wetting()
        x = trial.pressure.positions()
        length = np.linalg.norm(x[(seg + 1) % len(x)] - x[seg])
        trial.pressure.s0[seg] = min(d * 1e-6 / length, 1.0)
        linear = solver.LinearSolver(solver.DEFAULT_LINEAR_SOLVER)
        try:
            solver._newton(trial, ext0, 1e-8, 25, False, linear)
        except fem.NewtonConvergenceError:
            out.append((d, None))  # no equilibrium with the edge there
            continue
        finally:
            linear.release()
        trial.update_wetting()
        if trial.pressure.s1[seg] == 1.0:  # the edge is still in that segment
            out.append((d, trial.pressure.s0[seg] * length * 1e6))
    return out


def scan_line(scan) -> str:
    return "  upstream edge, G(d) - d [um] at d [um] = " + ", ".join(
        f"{d}: " + ("Newton fails" if g is None else f"{g - d:+.2f}") for d, g in scan)


def least(scan) -> float:
    return min(g - d for d, g in scan if g is not None)


def states_on_path(start, bar: float, increments: int, marks_bar) -> list:
    """Copies of the model at its first converged states at or above each of ``marks_bar``
    on the path from ``start`` to ``bar`` in ``increments`` increments."""
    marks = sorted(m * 1e5 for m in marks_bar)
    states = []
    increment = solver._increment

    def hook(model, target, *args):
        if marks and model.state.pressure >= marks[0]:
            states.append(copy.deepcopy(model))
            marks.pop(0)
        return increment(model, target, *args)

    solver._increment = hook
    try:
        pressure_step(copy.deepcopy(start), bar, increments)
    except ConvergenceError:
        pass
    finally:
        solver._increment = increment
    return states


def newton_log(model, dp: float, update_wetting: bool) -> list[str]:
    """Newton's residual (relative to the reactions) and the change of the wetted length made
    before it, per iteration of a pressure rise ``dp`` [Pa], with the edges after each update
    of the wetted surface (:func:`edges`); the last line is the outcome."""
    rows = []
    change = [0.0]
    assemblies = [0]
    assemble, update = model.system.assemble, model.update_wetting

    def assemble_logged(items, field):
        f, K11 = assemble(items, field)
        r = np.linalg.norm(f[model.dof1]) / np.linalg.norm(f[model.dof0])
        rows.append(f"    iteration {assemblies[0]:2d}: residual {r:9.3e}, "
                    f"wetted length changed by {change[0] * 1e6:6.2f} um before it")
        change[0] = 0.0
        assemblies[0] += 1
        return f, K11

    def update_logged():
        change[0] = update()
        rows.append("      edges " + "; ".join(edges(model)))
        return change[0]

    target = dataclasses.replace(model.state, pressure=model.state.pressure + dp)
    ext0 = model.set_load(target, 0.0)
    update()  # as the solver's increment does before Newton
    rows.append("      edges " + "; ".join(edges(model)))
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
            count, unsettled = unsettled_increments(case)
            summary = {"map_increments": count, "frozen_unsettled": len(unsettled)}
            print(f"map: {count} converged increments, {len(unsettled)} with the wetted "
                  "surface frozen unsettled (last change " + ", ".join(
                      f"{c * 1e6:.2g}" for c in unsettled) + " um)")
            start = state_on_map_path(case, START)
            print(f"map path at {START / 1e5} bar: F_N {extract(start).F_N:.2f} N")
            grid = (0, 5, 10, 15, 20, 25, 30, 32, 34, 36, 40, 50, 60, 80)
            scan = wetting_map(start, 0.0, grid)
            print(scan_line(scan))
            summary["min_G_minus_d_um"] = {START / 1e5: round(least(scan), 3)}
            for state in states_on_path(start, 50.0, 48, (42, 43.5, 45, 46, 47, 48)):
                scan = wetting_map(state, 0.0, grid)
                print(f"  48-increment path at {state.state.pressure / 1e5:.4g} bar: least "
                      f"G(d) - d {least(scan):+.2f} um")
                summary["min_G_minus_d_um"][round(state.state.pressure / 1e5, 4)] = round(
                    least(scan), 3)
            stuck = None
            summary.update({"reached_bar": {}, "stuck_increment_converges": {}})
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
                scan = wetting_map(stuck, 100.0, grid + (120, 135, 140))
                print(scan_line(scan))
                summary["min_G_minus_d_um"][round(stuck.state.pressure / 1e5, 4)] = round(
                    least(scan), 3)
                for held in (False, True):
                    print("  wetted surface " + ("held at the increment's start" if held
                                                 else "re-evaluated in iterations 1-8") + ":")
                    log = newton_log(copy.deepcopy(stuck), 100.0, update_wetting=not held)
                    print("\n".join(log))
                    summary["stuck_increment_converges"]["held" if held else "re-evaluated"] = \
                        log[-1].strip().startswith("converged")
            print(json.dumps(summary))
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
