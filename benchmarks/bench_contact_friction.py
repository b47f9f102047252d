"""Benchmark of friction from the seal's own contact (issue 23).

1. Building one seal's friction table (inverse hydrodynamics + mixed lubrication over the map's
   temperatures x pressures x 49 speeds x 2 directions) from a cached FE map: the TU Delft
   O-ring gland (examples/calibration/oring_25_piston.toml; the FE map is built first if it is
   not cached yet, that time is not counted).  Target <= 10 s on 2 cores.  Baseline in the same
   run: reading the cached FE map.
2. 10 s of the Ø32 cylinder (examples/pneumatic/cylinder_32.toml, variant T25C) with its piston
   and rod seals on the contact law (set seal_contact, tables cached), against the same case
   with the lumped illustrative set pneumatic_demo, both on one core, best of three after a
   warm-up.  Target >= 200x real time.  Measured twice: with the seals built once
   (``simulate(case, seals)``) and end to end (``simulate(case)``: maps and friction tables
   read, as ``sealsim pneumatic run`` and every study run do).

    .venv/bin/python benchmarks/bench_contact_friction.py

The last line is one JSON object: ``table_build_s``, ``map_read_s``, ``realtime_factor``
(contact law, wall), ``baseline_realtime_factor`` (lumped law), ``end_to_end_realtime_factor``,
``baseline_end_to_end_realtime_factor``, ``slowdown``.
"""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("NUMBA_NUM_THREADS", "1")

ROOT = Path(__file__).resolve().parents[1]

from sealsim.friction.case import LawParameters  # noqa: E402
from sealsim.pneumatic import build_seals, load_pneumatic_case_file, simulate  # noqa: E402
from sealsim.pneumatic.case import map_elastomer  # noqa: E402
from sealsim.pneumatic.contact_maps import build_or_load_fe_map  # noqa: E402
from sealsim.pneumatic.friction_tables import ContactTribology, build_friction_table  # noqa: E402

STRUCTURE = ROOT / "examples" / "calibration" / "oring_25_piston.toml"
CYLINDER = ROOT / "examples" / "pneumatic" / "cylinder_32.toml"
SIMULATED = 10.0


def _best(fn, repeat=3):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def _cylinder(parameter_set: str):
    from pydantic import TypeAdapter

    case = load_pneumatic_case_file(CYLINDER)["T25C"]
    law = TypeAdapter(LawParameters).validate_python({"law": "theta",
                                                     "parameter_set": parameter_set})
    seals = [s.model_copy(update={"friction": law}) if s.friction.law == "theta" else s
             for s in case.seals]
    controller = case.controller.model_copy(update={"duration": SIMULATED})
    return case.model_copy(update={"seals": seals, "controller": controller})


def main() -> None:
    fe_map = build_or_load_fe_map(STRUCTURE)                 # built once, then cached
    map_read, _ = _best(lambda: build_or_load_fe_map(STRUCTURE))
    tribology = ContactTribology(elastomer=map_elastomer(fe_map))
    build_friction_table(fe_map, tribology)                  # warm-up (numba, imports)
    table_s, table = _best(lambda: build_friction_table(fe_map, tribology))
    print(f"friction table of {STRUCTURE.name}: {table.values.shape[:3]} (T x p x u) x 2 "
          f"directions in {table_s:.3f} s (target <= 10 s); reading the cached FE map "
          f"{map_read:.3f} s")
    rates, end_to_end = {}, {}
    for name in ("pneumatic_demo", "seal_contact"):
        case = _cylinder(name)
        seals = build_seals(case)
        simulate(case, seals)                                # warm-up
        wall, _ = _best(lambda case=case, seals=seals: simulate(case, seals))
        rates[name] = SIMULATED / wall
        whole, _ = _best(lambda case=case: simulate(case))  # seals, maps and tables set up
        end_to_end[name] = SIMULATED / whole
        print(f"Ø32 cylinder, {SIMULATED:g} s with theta/{name}: {wall:.3f} s wall, "
              f"{rates[name]:.0f}x real time; with the seals' set-up (simulate(case), "
              f"as pneumatic run and studies call it) {whole:.3f} s, "
              f"{end_to_end[name]:.0f}x")
    print(f"contact law vs lumped law: {rates['pneumatic_demo'] / rates['seal_contact']:.2f}x "
          "slower (target >= 200x real time)")
    print(json.dumps({"table_build_s": table_s, "map_read_s": map_read,
                      "realtime_factor": rates["seal_contact"],
                      "baseline_realtime_factor": rates["pneumatic_demo"],
                      "end_to_end_realtime_factor": end_to_end["seal_contact"],
                      "baseline_end_to_end_realtime_factor": end_to_end["pneumatic_demo"],
                      "slowdown": rates["pneumatic_demo"] / rates["seal_contact"]}))


if __name__ == "__main__":
    sys.exit(main())
