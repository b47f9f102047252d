"""Benchmark of the rotary lip seal model (targets in brackets).

1. A 1-hour duty cycle with the coupled friction-thermal model on a thermal mesh of >= 2000
   nodes: wall time and simulated-time / wall-time [<= 1 s, >= 3600x real time, one core].
   Baseline in the same process: the same run with a fixed time step of min_time_step, to show
   what the adaptive stepping buys.
2. A vectorised steady-state torque map (speed x contact temperature) [>= 1e5 points/s].
3. Steady operating points with the full thermal model (``steady_state``: friction, conduction,
   free sump and housing in equilibrium) [>= 3x the points per second of the
   former solver, which factorised the network matrix in every fixed-point iteration; that
   solver, kept in tests/rotary_reference.py, is the baseline measured in the same run].

4. What users and the CI run on the transient model, CPU time and wall (best of ``--repeat``):
   the speed cycle of ``examples/rotary/speed_cycle.toml`` (variant plain, 2.25 h) and the
   thermal-lag step responses of the rotary FMU, :func:`~sealsim.fmu.rotary_maps.thermal_lag`
   at two speeds and two sump temperatures as in ``tests/test_fmu_rotary.py`` (4 steady states,
   4 transient runs until settled).  No target: compare two versions by running this file
   alternately with each on ``PYTHONPATH`` (the machine's speed drifts over minutes);
   ``--transient`` runs this part only.

The last line is one JSON object with wall_s, simulated_s, realtime_factor, thermal_nodes,
steady_points_per_s (the friction map), thermal_steady_points_per_s,
thermal_steady_baseline_points_per_s, thermal_steady_speedup and thermal_steady_max_torque_diff
(relative torque difference to the baseline run to convergence), speed_cycle_cpu_s,
speed_cycle_wall_s, thermal_lag_cpu_s and thermal_lag_wall_s (``--transient``: the last four).
"""

import argparse
import json
import math
import sys
import time
import warnings
from pathlib import Path

import numpy as np

from sealsim.cases import expand_variants, load_toml, validate_case
from sealsim.fmu.rotary_maps import thermal_lag
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import RotaryModel, friction_map, simulate, steady_state

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from rotary_reference import reference_steady_state  # noqa: E402

STEPS = [("100 rpm", "10 min"), ("500 rpm", "10 min"), ("1000 rpm", "10 min"),
         ("1500 rpm", "10 min"), ("750 rpm", "10 min"), ("250 rpm", "10 min")]


def case(max_step="4 s", min_step="0.25 s"):
    return validate_case(RotaryCase, {
        "seal": {"shaft_diameter": "80 mm"}, "oil": {"name": "VG68"},
        "environment": {"sump_volume": "1 L", "ambient_temperature": "23 degC"},
        "duty": {"steps": [{"speed": s, "duration": d} for s, d in STEPS]},
        "numerics": {"max_time_step": max_step, "min_time_step": min_step}})


def timed_cpu(function, repeat):
    """Best CPU time and best wall time [s] of ``repeat`` calls, and the last result."""
    cpu = wall = np.inf
    for _ in range(repeat):
        start_cpu, start = time.process_time(), time.perf_counter()
        result = function()
        cpu = min(cpu, time.process_time() - start_cpu)
        wall = min(wall, time.perf_counter() - start)
    return cpu, wall, result


def timed(function, repeat=3):
    """Best wall time [s] of ``repeat`` calls, and the last result."""
    _, wall, result = timed_cpu(function, repeat)
    return wall, result


def transient_runs(repeat: int) -> dict:
    """Part 4: the speed-cycle example and the rotary FMU's thermal-lag step responses."""
    example = Path(__file__).resolve().parents[1] / "examples" / "rotary" / "speed_cycle.toml"
    plain = expand_variants(RotaryCase, load_toml(example), "speed cycle")["plain"]
    sumps = np.array([20.0, 70.0]) + 273.15
    speeds = np.array([[100.0, 100.0], [1000.0, 1000.0]]) * math.pi / 30.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        simulate(plain)  # warm-up
        cycle_cpu, cycle_wall, cycle = timed_cpu(lambda: simulate(plain), repeat)
        lag_cpu, lag_wall, lag = timed_cpu(lambda: thermal_lag(plain, speeds, sumps), repeat)
    print(f"speed cycle example (plain, {cycle.statistics['time_steps']} steps, "
          f"{cycle.statistics['factorisations']} factorisations): CPU {cycle_cpu:.2f} s, "
          f"wall {cycle_wall:.2f} s")
    print(f"thermal lag of the rotary FMU (2 speeds x 2 sump temperatures, "
          f"{sum(len(t) for t, _ in lag.responses.values())} steps): CPU {lag_cpu:.2f} s, "
          f"wall {lag_wall:.2f} s")
    return {"speed_cycle_cpu_s": round(cycle_cpu, 3), "speed_cycle_wall_s": round(cycle_wall, 3),
            "thermal_lag_cpu_s": round(lag_cpu, 3), "thermal_lag_wall_s": round(lag_wall, 3)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--transient", action="store_true", help="part 4 only")
    parser.add_argument("--repeat", type=int, default=3, help="runs of part 4 (best of)")
    args = parser.parse_args()
    if args.transient:
        print(json.dumps(transient_runs(args.repeat)))
        return
    adaptive = case()
    simulate(adaptive)  # warm-up: imports, first-call overheads
    wall, result = timed(lambda: simulate(adaptive))
    simulated = float(result.timeseries["time_s"].iloc[-1])
    nodes = RotaryModel(adaptive).network.n_cells
    base_wall, base = timed(lambda: simulate(case("0.25 s", "0.25 s")), repeat=1)
    print(f"1-hour duty cycle: {nodes} thermal nodes, {result.statistics['time_steps']} steps, "
          f"{result.statistics['factorisations']} factorisations")
    print(f"  adaptive steps : wall {wall:.3f} s, {simulated / wall:.0f}x real time")
    print(f"  fixed 0.25 s   : wall {base_wall:.3f} s ({base.statistics['time_steps']} steps); "
          f"adaptive is {base_wall / wall:.1f}x faster")
    torque_error = max(abs(a["torque_Nm"] / b["torque_Nm"] - 1)
                       for a, b in zip(result.steps, base.steps, strict=True))
    print(f"  step-averaged torque, adaptive vs fixed step: max difference {torque_error:.2e}")

    speeds = np.linspace(10.0, 6000.0, 1000)
    temps = np.linspace(-10.0, 140.0, 200)
    friction_map(adaptive, speeds[:10], temps[:10])  # warm-up
    map_wall, frame = timed(lambda: friction_map(adaptive, speeds, temps))
    points = len(frame)
    print(f"steady-state torque map: {points} points in {map_wall:.3f} s = "
          f"{points / map_wall:.3g} points/s")

    omegas = np.array([100.0, 300.0, 500.0, 700.0, 1000.0, 1200.0, 1500.0]) * math.pi / 30.0
    steady_state(adaptive, omegas[0])  # warm-up
    new_wall = base_wall = np.inf
    for _ in range(5):  # interleaved, best of 5: both see the same machine load
        wall_new, new = timed(lambda: [steady_state(adaptive, w) for w in omegas], repeat=1)
        wall_base, base = timed(lambda: [reference_steady_state(adaptive, w) for w in omegas],
                                repeat=1)
        new_wall, base_wall = min(new_wall, wall_new), min(base_wall, wall_base)
    converged = [reference_steady_state(adaptive, w, tol=1e-9, max_iter=400) for w in omegas]
    diff = max(abs(a["torque_Nm"] / b["torque_Nm"] - 1) for a, b in zip(new, converged,
                                                                       strict=True))
    diff_default = max(abs(a["torque_Nm"] / b["torque_Nm"] - 1) for a, b in zip(
        base, converged, strict=True))
    rate, base_rate = len(omegas) / new_wall, len(omegas) / base_wall
    print(f"steady operating points with the thermal model ({len(omegas)} speeds 100-1500 rpm, "
          f"free 1 L sump): {rate:.1f} points/s ({np.mean([r['iterations'] for r in new]):.1f} "
          f"iterations); former solver {base_rate:.1f} points/s "
          f"({np.mean([r['iterations'] for r in base]):.1f} factorisations); "
          f"{rate / base_rate:.1f}x")
    print(f"  torque vs the former solver run to convergence (tol 1e-9 K): max relative "
          f"difference {diff:.1e} (the former solver at its default tol 1e-4 K: "
          f"{diff_default:.1e})")
    transient = transient_runs(args.repeat)
    print(json.dumps({"wall_s": round(wall, 4), "simulated_s": simulated,
                      "realtime_factor": round(simulated / wall, 1), "thermal_nodes": nodes,
                      "steady_points_per_s": round(points / map_wall),
                      "thermal_steady_points_per_s": round(rate, 2),
                      "thermal_steady_baseline_points_per_s": round(base_rate, 2),
                      "thermal_steady_speedup": round(rate / base_rate, 2),
                      "thermal_steady_max_torque_diff": float(f"{diff:.2e}"), **transient}))


if __name__ == "__main__":
    main()
