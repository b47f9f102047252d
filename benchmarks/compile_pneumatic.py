"""Cold numba compile of the pneumatic cylinder chain: what a fresh clone (every CI run) pays.

Runs 0.2 s of the Ø32 example (examples/pneumatic/cylinder_32.toml, variant T25C) with the
default compiled BDF, then with the FE map of the rod seal, with seal heating and with LSODA,
in one process with an EMPTY numba cache (a temporary ``NUMBA_CACHE_DIR``; the FE map itself
comes from ``$SEALSIM_CACHE`` or ~/.cache/sealsim/maps, or is built first).  numba's compile
events give the CPU time of every compiled function, exclusive of the functions it compiles
in turn (an inlined function is part of its caller's time), and the disk cache each one wrote
(a function's cache holds the machine code of everything it calls as well).

    .venv/bin/python benchmarks/compile_pneumatic.py [--top 20]

The last line is one JSON object: ``cpu_s`` (the whole process), ``compile_cpu_s`` (sum of
the compile events), ``phases_cpu_s`` (per run), ``cache_mb``, ``functions`` (the largest:
name, exclusive CPU [s], cache [MB]).
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

CACHE = tempfile.TemporaryDirectory(prefix="sealsim-numba-")
os.environ["NUMBA_CACHE_DIR"] = CACHE.name          # before numba is imported

from numba.core import event  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "pneumatic" / "cylinder_32.toml"


class _Compiles(event.Listener):
    """(module, qualified name, exclusive CPU [s]) of every numba compilation, nested ones
    subtracted."""

    def __init__(self):
        self.stack, self.done = [], []

    def on_start(self, ev):
        self.stack.append([time.process_time(), 0.0])

    def on_end(self, ev):
        start, nested = self.stack.pop()
        total = time.process_time() - start
        if self.stack:
            self.stack[-1][1] += total
        func = ev.data["dispatcher"].py_func
        self.done.append((func.__module__, func.__qualname__, total - nested))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=20, help="functions to list")
    top = parser.parse_args().top
    compiles = _Compiles()
    event.register("numba:compile", compiles)
    cpu0 = time.process_time()
    from sealsim.pneumatic import build_seals, load_pneumatic_case_file, simulate
    from sealsim.pneumatic.case import ThermalModel

    def case(example, **updates):
        c = load_pneumatic_case_file(example)["T25C"]
        controller = c.controller.model_copy(update={"duration": 0.2})
        return c.model_copy(update={"controller": controller, **updates})

    runs = {"compiled": case(EXAMPLE), "fe_map": case(EXAMPLE.with_name("cylinder_32_fe.toml")),
            "heating": case(EXAMPLE, thermal=ThermalModel())}
    runs["lsoda"] = runs["compiled"].model_copy(update={
        "solver": runs["compiled"].solver.model_copy(update={"method": "LSODA"})})
    phases = {}
    for name, c in runs.items():
        t0 = time.process_time()
        simulate(c, build_seals(c, EXAMPLE.parent))
        phases[name] = round(time.process_time() - t0, 2)
    cpu = time.process_time() - cpu0
    per_function = defaultdict(float)
    for module, qualname, seconds in compiles.done:
        per_function[module, qualname] += seconds
    # <package>_<hash>/<module>.<qualname>-<line>.py3xx.nbi and .<n>.nbc
    size = defaultdict(int)
    for f in Path(CACHE.name).rglob("*.nb[ic]"):
        size[f.parent.name.rsplit("_", 1)[0], f.name.rsplit("-", 1)[0]] += f.stat().st_size

    def cache_of(module, qualname):
        parts = module.split(".")
        return size.get((parts[-2] if len(parts) > 1 else "", f"{parts[-1]}.{qualname}"), 0)

    rows = sorted(per_function.items(), key=lambda kv: -kv[1])
    print(f"cold numba compile, 0.2 s of {EXAMPLE.name} [T25C] per run, one process: "
          f"{cpu:.1f} s CPU ({', '.join(f'{k} {v:.1f} s' for k, v in phases.items())})")
    print(f"compile events: {sum(per_function.values()):.1f} s CPU in {len(compiles.done)} "
          f"compilations; disk cache {sum(size.values()) / 1e6:.2f} MB")
    print(f"{'exclusive CPU':>14} {'cache':>8}  function")
    for (module, qualname), seconds in rows[:top]:
        print(f"{seconds:12.1f} s {cache_of(module, qualname) / 1e6:6.2f} MB  "
              f"{module}.{qualname}")
    print(json.dumps({"cpu_s": round(cpu, 1),
                      "compile_cpu_s": round(sum(per_function.values()), 1),
                      "phases_cpu_s": phases, "cache_mb": round(sum(size.values()) / 1e6, 2),
                      "functions": [[f"{m}.{q}", round(s, 2), round(cache_of(m, q) / 1e6, 3)]
                                    for (m, q), s in rows[:top]]}))
    sys.stdout.flush()


if __name__ == "__main__":
    main()
