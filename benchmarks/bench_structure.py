"""Benchmark of the structural seal model (issue 5).

1. O-ring 20 x 4 rod seal, squeeze 0 -> 20 % in 20 increments on the "medium" mesh
   (about 3000 dofs); target <= 5 s wall.
2. Characteristic map 10 pressures x 8 temperatures on 2 worker processes (medium mesh);
   target <= 2 min wall.
3. Lip seal (issue 12): the U-cup rod seal of examples/structure/ucup_rod.toml on its default
   ("medium", gmsh) mesh, squeeze 10 % in 5 increments, then 0 -> 10 bar in 10 increments;
   target <= 10 s wall.

Run: ``.venv/bin/python benchmarks/bench_structure.py``. The last line is one JSON object with
``squeeze_wall_s``, ``dofs``, ``map_wall_s``, ``map_points``, ``lip_wall_s``, ``lip_dofs``.
"""

from __future__ import annotations

import json
import time

from sealsim.cases import validate_case
from sealsim.structure.case import StructureCase
from sealsim.structure.geometry import Gland, ORing, SealAssembly
from sealsim.structure.mapping import compute_map
from sealsim.structure.material import HyperelasticSealMaterial
from sealsim.structure.mesh import mesh_oring
from sealsim.structure.model import SealModel
from sealsim.structure.solver import LoadStep, solve


def bench_squeeze() -> tuple[float, int, float]:
    assembly = SealAssembly(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3))
    mesh = mesh_oring(assembly.seal, assembly.centre, "medium")
    material = HyperelasticSealMaterial(0.8e6, 0.2e6, 2e9, 2e-4, 293.15)
    model = SealModel(assembly, mesh, material, installation_squeeze=0.2)
    t0 = time.perf_counter()
    states = solve(model, [LoadStep("squeeze", squeeze=0.2, increments=20, record="end")])
    wall = time.perf_counter() - t0
    return wall, model.ndofs, states[-1].F_N


def bench_map(workers: int = 2) -> tuple[float, int]:
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
    return time.perf_counter() - t0, int(ds["F_N"].size)


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
    squeeze_wall, dofs, force = bench_squeeze()
    print(f"squeeze 0 -> 20 % in 20 increments: {squeeze_wall:.2f} s on {dofs} dofs "
          f"(F_N = {force:.1f} N; target <= 5 s)")
    map_wall, points = bench_map()
    print(f"map {points} points (10 pressures x 8 temperatures, 2 workers): {map_wall:.1f} s "
          "(target <= 120 s)")
    lip_wall, lip_dofs, lip_force = bench_lip_seal()
    print(f"U-cup lip seal, squeeze 10 % + 0 -> 10 bar: {lip_wall:.2f} s on {lip_dofs} dofs "
          f"(F_N = {lip_force:.1f} N at 10 bar; target <= 10 s)")
    print(json.dumps({"squeeze_wall_s": round(squeeze_wall, 3), "dofs": dofs,
                      "map_wall_s": round(map_wall, 2), "map_points": points,
                      "lip_wall_s": round(lip_wall, 3), "lip_dofs": lip_dofs}))


if __name__ == "__main__":
    main()
