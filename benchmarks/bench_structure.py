"""Benchmark of the structural seal model.

1. O-ring 20 x 4 rod seal, squeeze 0 -> 20 % in 20 increments on the "medium" mesh
   (2738 dofs); target <= 1.6 s wall.
2. Characteristic map 10 pressures x 8 temperatures on 2 worker processes (medium mesh);
   target <= 8 s wall.
3. Lip seal: the U-cup rod seal of examples/structure/ucup_rod.toml on its default
   ("medium", gmsh) mesh, squeeze 10 % in 5 increments, then 0 -> 10 bar in 10 increments;
   target <= 10 s wall (current implementation only).

Each is measured twice in this process: first the reference implementation (einsum
Mooney–Rivlin tangent, scipy ``spsolve`` in every Newton iteration: the former code,
kept as the reference the tests compare against), then the current one (compiled kernels,
PARDISO with the symbolic analysis kept per sparsity pattern if pypardiso is installed, else
SuperLU with the symmetric-pattern ordering). The squeeze also runs with the SuperLU fallback.
The results must agree to 1e-9 (checked here too). Ratios are same-run: a busy machine slows
both sides.

Run: ``.venv/bin/python benchmarks/bench_structure.py``. The last line is one JSON object.
"""

from __future__ import annotations

import json
import os
import time

from sealsim.cases import validate_case
from sealsim.structure import material as material_module
from sealsim.structure import solver as solver_module
from sealsim.structure.case import StructureCase
from sealsim.structure.geometry import Gland, ORing, SealAssembly
from sealsim.structure.mapping import compute_map
from sealsim.structure.material import HyperelasticSealMaterial
from sealsim.structure.mesh import mesh_oring
from sealsim.structure.model import SealModel
from sealsim.structure.solver import LoadStep, solve


def use(implementation: str) -> str:
    """Select the reference or the current implementation for this process and the map
    workers (module defaults for forked workers, environment for spawned ones)."""
    reference = implementation == "reference"
    backend = "reference" if reference else implementation
    material_module.USE_COMPILED = material_module.HAVE_COMPILED_TANGENT and not reference
    solver_module.DEFAULT_LINEAR_SOLVER = backend
    os.environ["SEALSIM_FE_COMPILED"] = "0" if reference else "1"
    os.environ["SEALSIM_FE_LINEAR_SOLVER"] = backend
    return solver_module.LinearSolver(backend).backend


def bench_squeeze(increments: int = 20) -> tuple[float, int, float, float]:
    assembly = SealAssembly(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3))
    mesh = mesh_oring(assembly.seal, assembly.centre, "medium")
    material = HyperelasticSealMaterial(0.8e6, 0.2e6, 2e9, 2e-4, 293.15)
    model = SealModel(assembly, mesh, material, installation_squeeze=0.2)
    t0 = time.perf_counter()
    states = solve(model, [LoadStep("squeeze", squeeze=0.2, increments=increments,
                                    record="end")])
    wall = time.perf_counter() - t0
    return wall, model.ndofs, states[-1].F_N, states[-1].b


def bench_map(workers: int = 2):
    case = validate_case(StructureCase, {
        "seal": {"cord_diameter": "4 mm", "inner_diameter": "20 mm"},
        "gland": {"sealing_diameter": "20 mm", "groove_width": "5.4 mm"},
        "mesh": {"level": "medium"},
        "load": {"squeeze": [0.15]},
        "map": {"pressure": [f"{p} bar" for p in range(10)],
                "temperature": [f"{t} degC" for t in range(20, 101, 80 // 7)][:8],
                "squeeze_increments": 8, "temperature_increments": 2,
                "workers": workers},
    })
    t0 = time.perf_counter()
    ds = compute_map(case, workers=workers)
    return time.perf_counter() - t0, ds


def bench_lip_seal() -> tuple[float, int, float]:
    """U-cup rod seal, medium mesh: squeeze, then 0 -> 10 bar (wall time, dofs, F_N at 10 bar)."""
    from sealsim.structure.build import build_model

    case = validate_case(StructureCase, {
        "seal": {"type": "ucup", "lip_diameter": "19.4 mm", "height": "4.4 mm",
                 "width": "5 mm"},
        "gland": {"sealing_diameter": "20 mm", "groove_width": "5.6 mm"},
        "load": {"squeeze": [0.10]}})
    model = build_model(case)
    t0 = time.perf_counter()
    states = solve(model, [LoadStep("squeeze", squeeze=0.10, increments=5, record="end"),
                           LoadStep("pressure", pressure=10e5, increments=10, record="end")])
    return time.perf_counter() - t0, model.ndofs, states[-1].F_N


def main() -> None:
    # warm-up: numba kernels (compiled once, then read from numba's disk cache), imports
    use("auto")
    bench_squeeze(increments=2)
    results = {}
    for name in ("reference", "superlu", "auto"):
        backend = use(name)
        wall, dofs, force, width = bench_squeeze()
        results[name] = (wall, force, width)
        print(f"squeeze 0 -> 20 % in 20 increments, {name} ({backend}): {wall:.2f} s on "
              f"{dofs} dofs (F_N = {force:.4f} N)")
    ref_wall, ref_force, ref_width = results["reference"]
    deviation = max(max(abs(r[1] - ref_force) / ref_force, abs(r[2] - ref_width) / ref_width)
                    for r in results.values())
    backend = use("reference")
    map_ref, ds_ref = bench_map()
    print(f"map 80 points (10 pressures x 8 temperatures, 2 workers), reference: "
          f"{map_ref:.1f} s")
    backend = use("auto")
    map_new, ds_new = bench_map()
    map_deviation = float(abs(ds_new["F_N"] - ds_ref["F_N"]).max() / abs(ds_ref["F_N"]).max())
    print(f"map, current ({backend}): {map_new:.1f} s")
    squeeze_new = results["auto"][0]
    print(f"squeeze {squeeze_new:.2f} s (target <= 1.6 s), {ref_wall / squeeze_new:.2f}x the "
          f"reference; SuperLU fallback {results['superlu'][0]:.2f} s "
          f"({ref_wall / results['superlu'][0]:.2f}x); map {map_new:.1f} s (target <= 8 s), "
          f"{map_ref / map_new:.2f}x; largest deviation from the reference: F_N, b "
          f"{deviation:.1e} (squeeze), F_N {map_deviation:.1e} (map)")
    lip_wall, lip_dofs, lip_force = bench_lip_seal()
    print(f"U-cup lip seal, squeeze 10 % + 0 -> 10 bar: {lip_wall:.2f} s on {lip_dofs} dofs "
          f"(F_N = {lip_force:.1f} N at 10 bar; target <= 10 s)")
    print(json.dumps({
        "dofs": dofs, "linear_solver": backend,
        "squeeze_wall_s": round(squeeze_new, 3),
        "squeeze_reference_wall_s": round(ref_wall, 3),
        "squeeze_speedup": round(ref_wall / squeeze_new, 2),
        "squeeze_superlu_wall_s": round(results["superlu"][0], 3),
        "squeeze_superlu_speedup": round(ref_wall / results["superlu"][0], 2),
        "map_wall_s": round(map_new, 2), "map_reference_wall_s": round(map_ref, 2),
        "map_speedup": round(map_ref / map_new, 2), "map_points": int(ds_new["F_N"].size),
        "max_rel_deviation": max(deviation, map_deviation),
        "lip_wall_s": round(lip_wall, 3), "lip_dofs": lip_dofs,
    }))


if __name__ == "__main__":
    main()
