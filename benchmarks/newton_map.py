"""Newton work of an FE map built on an empty cache: calls, failures, iterations, assemblies.

Builds the characteristic map of a structure case the way a calibration builds it
(:func:`sealsim.pneumatic.contact_maps.build_or_load_fe_map`, in one process: ``workers=1``,
so that the counts are this process's) into an empty temporary cache, and counts the Newton
calls of :func:`sealsim.structure.solver._newton` (one per attempted increment), the failed
ones (cut back), their iterations, and the assemblies of the FE system (one per iteration).
``--fixed-state`` runs Newton on the contact state the gaps and slips decide in every
iteration (:data:`sealsim.structure.solver.FREEZE_CYCLING_CONTACT` = False, the solver
before the cycling state was frozen); ``--save FILE`` keeps the map (netCDF) for a comparison.

    .venv/bin/python benchmarks/newton_map.py examples/calibration/xring_257_piston.toml

The last line is one JSON object: ``calls``, ``failures``, ``iterations_converged``,
``iterations_failed``, ``assemblies``, ``cpu_s``, ``wall_s``, ``increments``, ``cutbacks``
(the map's attributes) and ``failure_reasons`` (message without its iteration -> count).
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import tempfile
import time
import warnings
from collections import Counter
from pathlib import Path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", help="structure case with a [map] table")
    parser.add_argument("--fixed-state", action="store_true",
                        help="do not freeze a cycling contact state (the previous solver)")
    parser.add_argument("--save", help="write the map to this netCDF file")
    args = parser.parse_args()

    import felupe as fem
    import xarray as xr

    from sealsim.pneumatic.contact_maps import build_or_load_fe_map
    from sealsim.structure import assembly, solver

    solver.FREEZE_CYCLING_CONTACT = not args.fixed_state
    counts = Counter()
    reasons = Counter()
    assemble = assembly.SystemAssembly.assemble
    newton = solver._newton

    def counted_assemble(self, items, field):
        counts["assemblies"] += 1
        return assemble(self, items, field)

    def counted_newton(*a, **k):
        counts["calls"] += 1
        before = counts["assemblies"]
        try:
            iterations = newton(*a, **k)
        except fem.NewtonConvergenceError as exc:
            counts["failures"] += 1
            counts["iterations_failed"] += counts["assemblies"] - before
            reasons[re.sub(r"\s*\(?(in )?iteration \d+\)?", "", str(exc))] += 1
            raise
        counts["iterations_converged"] += iterations
        return iterations

    assembly.SystemAssembly.assemble = counted_assemble
    solver._newton = counted_newton
    cache = Path(tempfile.mkdtemp(prefix="sealsim-newton-map-"))
    try:
        wall, cpu = time.perf_counter(), time.process_time()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            build_or_load_fe_map(args.case, cache_dir=cache, workers=1)
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        dataset = xr.load_dataset(next(cache.glob("*.nc")))
    finally:
        shutil.rmtree(cache, ignore_errors=True)
    if args.save:
        dataset.to_netcdf(args.save)
    print(json.dumps({
        "case": args.case, "fixed_state": args.fixed_state,
        **{k: counts[k] for k in ("calls", "failures", "iterations_converged",
                                  "iterations_failed", "assemblies")},
        "cpu_s": round(cpu, 2), "wall_s": round(wall, 2),
        "increments": int(dataset.attrs["increments"]),
        "cutbacks": int(dataset.attrs["cutbacks"]),
        "failure_reasons": dict(reasons)}))


if __name__ == "__main__":
    main()
