"""Benchmark of the pneumatic cylinder simulation (issue 6).

10 s of the Ø32 example (examples/pneumatic/cylinder_32.toml, variant T25C: Θ-law piston and
rod seals with analytic contact maps, Coulomb wiper, rectangular command with 1 s steps) on one
core.  Target: ≥ 20× real time (stretch ≥ 100×).  The numba compilation of the right-hand side
happens once per process and is timed separately (a first, short run); the benchmark then runs
the 10 s case three times and reports the best.  For information it also runs 10 s of
cylinder_32_fe.toml, whose rod seal reads an FE characteristic map (built once with FElupe and
cached in the user's map cache, ``$SEALSIM_CACHE`` or ~/.cache/sealsim/maps).

    .venv/bin/python benchmarks/bench_pneumatic.py

The last line is one JSON object with the keys ``wall_s``, ``simulated_s``, ``realtime_factor``.
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")
os.environ.setdefault("NUMBA_NUM_THREADS", "1")

from sealsim.pneumatic import build_seals, load_pneumatic_case_file, simulate  # noqa: E402

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "pneumatic" / "cylinder_32.toml"
FE_EXAMPLE = EXAMPLE.with_name("cylinder_32_fe.toml")
SIMULATED = 10.0


def _case(duration: float, example: Path = EXAMPLE):
    case = load_pneumatic_case_file(example)["T25C"]
    controller = case.controller.model_copy(update={"duration": duration})
    return case.model_copy(update={"controller": controller})


def main() -> None:
    t0 = time.perf_counter()
    simulate(_case(0.2))                       # compiles the right-hand side (numba)
    warmup = time.perf_counter() - t0
    case = _case(SIMULATED)
    best, result = float("inf"), None
    for _ in range(3):
        t0 = time.perf_counter()
        result = simulate(case)
        best = min(best, time.perf_counter() - t0)
    stats = result.stats
    summary = result.summary()
    print(f"first call incl. compilation (0.2 s simulated): {warmup:.2f} s")
    print(f"10 s of {EXAMPLE.name} [T25C]: best of 3 = {best:.3f} s wall "
          f"(integration {stats['wall_time_s']:.3f} s, {stats['steps']} steps, "
          f"{stats['rhs_evaluations']} RHS evaluations, {stats['jacobian_evaluations']} "
          f"Jacobians, {stats['segments']} segments, method {stats['method']})")
    print(f"extend {summary['extend_time_s']:.4f} s, retract {summary['retract_time_s']:.4f} s, "
          f"energy balance error {summary['energy_balance_rel_error']:.1e}")
    print(f"real-time factor {SIMULATED / best:.1f}x")
    fe_case = _case(SIMULATED, FE_EXAMPLE)
    t0 = time.perf_counter()
    seals = build_seals(fe_case, FE_EXAMPLE.parent)      # FE map: built once, then cached
    built = time.perf_counter() - t0
    t0 = time.perf_counter()
    simulate(fe_case, seals)
    fe_wall = time.perf_counter() - t0
    print(f"with the FE map of the rod seal ({FE_EXAMPLE.name}): map ready in {built:.1f} s, "
          f"10 s simulated in {fe_wall:.3f} s, real-time factor {SIMULATED / fe_wall:.1f}x")
    print(json.dumps({"wall_s": round(best, 4), "simulated_s": SIMULATED,
                      "realtime_factor": round(SIMULATED / best, 1)}))


if __name__ == "__main__":
    main()
