"""Benchmark of the structural seal model.

1. O-ring 20 x 4 rod seal, squeeze 0 -> 20 % in 20 increments on the "medium" mesh
   (2738 dofs); target <= 1.6 s wall.
2. Characteristic map 10 pressures x 8 temperatures on 2 worker processes (medium mesh);
   target <= 8 s wall.
3. Lip seal: the U-cup rod seal of examples/structure/ucup_rod.toml on its default
   ("medium", gmsh) mesh, squeeze 10 % in 5 increments, then 0 -> 10 bar in 10 increments;
   target <= 10 s wall (current implementation only).
4. Thermo-viscoelastic O-ring (examples/structure/oring_cooling.toml, catalogue NBR with its
   19 Prony terms, coarse mesh): installation, an hour's hold, cooling 20 -> -20 degC at
   1 K/min in 20 increments; best of two, reference and current (the viscoelastic umat's
   kernels and the linear solver are the difference).

Each is measured in this process for the reference implementation (einsum Mooney–Rivlin
tangent, FElupe's assembly, scipy ``spsolve`` in every Newton iteration; the map with every
(squeeze, temperature) path solving its own installation: the former code, kept as the
reference the tests compare against) and for the current one (compiled Mooney–Rivlin and
assembly kernels into a cached sparsity pattern, PARDISO with the symbolic analysis kept per
pattern if pypardiso is installed, else the compiled LU of sealsim.structure.sparse_lu, which
keeps SuperLU's symmetric-pattern ordering and the symbolic factorisation per pattern; the map
solving the installation once per squeeze and worker process). The squeeze also runs with
SuperLU in every iteration and with the compiled LU; each squeeze is the best of three runs. The results must agree to 1e-9
(checked here too). Ratios are same-run: a busy machine slows both sides; the load average
and the squeeze's CPU time are printed to judge a shared machine.

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
from sealsim.structure import mapping
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


def bench_squeeze(increments: int = 20, repeat: int = 1):
    """Best wall time of ``repeat`` runs, its CPU time, dofs, F_N and b."""
    best = None
    for _ in range(repeat):
        assembly = SealAssembly(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3))
        mesh = mesh_oring(assembly.seal, assembly.centre, "medium")
        material = HyperelasticSealMaterial(0.8e6, 0.2e6, 2e9, 2e-4, 293.15)
        model = SealModel(assembly, mesh, material, installation_squeeze=0.2)
        t0, c0 = time.perf_counter(), time.process_time()
        states = solve(model, [LoadStep("squeeze", squeeze=0.2, increments=increments,
                                        record="end")])
        run = (time.perf_counter() - t0, time.process_time() - c0)
        best = run if best is None or run[0] < best[0] else best
    return (*best, model.ndofs, states[-1].F_N, states[-1].b)


def _map_task_own_installation(*args):
    """A map path that solves its own installation (the former map)."""
    return _map_task(*args[:4], {})


_map_task = mapping._map_task


def bench_map(workers: int = 2, shared_installation: bool = True):
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
    # forked workers see the module attribute
    mapping._map_task = _map_task if shared_installation else _map_task_own_installation
    try:
        t0 = time.perf_counter()
        ds = compute_map(case, workers=workers)
        return time.perf_counter() - t0, ds
    finally:
        mapping._map_task = _map_task


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


def bench_viscoelastic(repeat: int = 2):
    """Best wall and CPU time of ``repeat`` runs of the viscoelastic O-ring, dofs, F_N at
    -20 degC."""
    import tomllib
    from pathlib import Path

    from sealsim.cases import apply_overrides
    from sealsim.structure.run import run_case

    example = Path(__file__).resolve().parents[1] / "examples/structure/oring_cooling.toml"
    case = validate_case(StructureCase, apply_overrides(
        tomllib.loads(example.read_text()),
        {"load": {"temperature": ["-20 degC"], "temperature_increments": 20}}))
    best = None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        result = run_case(case)
        run = (time.perf_counter() - t0, time.process_time() - c0)
        best = run if best is None or run[0] < best[0] else best
    return (*best, result.ndofs, result.states[-1].F_N)


def main() -> None:
    load_start = os.getloadavg()[0]
    # warm-up: numba kernels (compiled once, then read from numba's disk cache), imports
    current = use("auto")
    bench_squeeze(increments=2)
    results = {}
    names = ["reference", "superlu", "compiled"] + (["pardiso"] if current == "pardiso" else [])
    for name in names:
        backend = use(name)
        wall, cpu, dofs, force, width = bench_squeeze(repeat=3)
        results[name] = (wall, force, width, cpu)
        print(f"squeeze 0 -> 20 % in 20 increments, {name} ({backend}): {wall:.2f} s "
              f"(CPU {cpu:.2f} s) on {dofs} dofs (F_N = {force:.4f} N)")
    results["auto"] = results[current]
    ref_wall, ref_force, ref_width, ref_cpu = results["reference"]
    deviation = max(max(abs(r[1] - ref_force) / ref_force, abs(r[2] - ref_width) / ref_width)
                    for r in results.values())
    backend = use("reference")
    map_ref, ds_ref = bench_map(shared_installation=False)
    print(f"map 80 points (10 pressures x 8 temperatures, 2 workers), reference: "
          f"{map_ref:.1f} s")
    backend = use("auto")
    map_new, ds_new = bench_map()
    map_deviation = float(abs(ds_new["F_N"] - ds_ref["F_N"]).max() / abs(ds_ref["F_N"]).max())
    print(f"map, current ({backend}): {map_new:.1f} s")
    squeeze_new, squeeze_cpu = results["auto"][0], results["auto"][3]
    print(f"squeeze {squeeze_new:.2f} s (target <= 1.6 s), {ref_wall / squeeze_new:.2f}x the "
          f"reference; SuperLU in every iteration {results['superlu'][0]:.2f} s "
          f"({ref_wall / results['superlu'][0]:.2f}x), compiled LU "
          f"{results['compiled'][0]:.2f} s ({ref_wall / results['compiled'][0]:.2f}x); "
          f"map {map_new:.1f} s (target <= 8 s), "
          f"{map_ref / map_new:.2f}x; largest deviation from the reference: F_N, b "
          f"{deviation:.1e} (squeeze), F_N {map_deviation:.1e} (map)")
    lip_wall, lip_dofs, lip_force = bench_lip_seal()
    print(f"U-cup lip seal, squeeze 10 % + 0 -> 10 bar: {lip_wall:.2f} s on {lip_dofs} dofs "
          f"(F_N = {lip_force:.1f} N at 10 bar; target <= 10 s)")
    use("reference")
    ve_ref = bench_viscoelastic()
    use("auto")
    ve_new = bench_viscoelastic()
    ve_deviation = abs(ve_new[3] - ve_ref[3]) / abs(ve_ref[3])
    print(f"viscoelastic O-ring, hold and cooling to -20 degC: {ve_new[0]:.2f} s (CPU "
          f"{ve_new[1]:.2f} s) on {ve_new[2]} dofs, {ve_ref[0] / ve_new[0]:.2f}x the reference's "
          f"{ve_ref[0]:.2f} s (CPU {ve_ref[1]:.2f} s); F_N = {ve_new[3]:.4f} N, deviation "
          f"{ve_deviation:.1e}")
    load_end = os.getloadavg()[0]
    print(f"load average (1 min) {load_start:.1f} at the start, {load_end:.1f} at the end "
          f"(2 cores: above 2 the times are those of a shared machine)")
    print(json.dumps({
        "dofs": dofs, "linear_solver": backend,
        "squeeze_wall_s": round(squeeze_new, 3), "squeeze_cpu_s": round(squeeze_cpu, 3),
        "squeeze_reference_wall_s": round(ref_wall, 3),
        "squeeze_reference_cpu_s": round(ref_cpu, 3),
        "squeeze_speedup": round(ref_wall / squeeze_new, 2),
        "squeeze_superlu_wall_s": round(results["superlu"][0], 3),
        "squeeze_superlu_speedup": round(ref_wall / results["superlu"][0], 2),
        "squeeze_compiled_lu_wall_s": round(results["compiled"][0], 3),
        "squeeze_compiled_lu_speedup": round(ref_wall / results["compiled"][0], 2),
        "map_wall_s": round(map_new, 2), "map_reference_wall_s": round(map_ref, 2),
        "map_speedup": round(map_ref / map_new, 2), "map_points": int(ds_new["F_N"].size),
        "max_rel_deviation": max(deviation, map_deviation, ve_deviation),
        "lip_wall_s": round(lip_wall, 3), "lip_dofs": lip_dofs,
        "viscoelastic_wall_s": round(ve_new[0], 3),
        "viscoelastic_reference_wall_s": round(ve_ref[0], 3),
        "viscoelastic_speedup": round(ve_ref[0] / ve_new[0], 2),
        "load_average_start": round(load_start, 2), "load_average_end": round(load_end, 2),
    }))


if __name__ == "__main__":
    main()
