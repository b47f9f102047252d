"""Cost of one communication step of the seal friction FMU.

The Θ-law piston seal of ``examples/pneumatic/cylinder_32.toml`` (``pneumatic_demo`` set,
analytic contact map embedded as a table) is built as an FMI 2.0 co-simulation FMU.  Then, in
the same run and on the same signal (sliding at 0.2 m/s, 3 bar on side A, 25 °C):

1. ``fmu_step_us``: one ``doStep`` of 1 ms through FMPy's low-level API
   (``FMU2Slave.doStep``), best of 5 runs of 100 000 steps;
2. ``host_step_us`` (extra): what a Python host pays per step for set v + doStep + get F
   through FMPy's function wrappers (``fmi2SetReal``/``fmi2DoStep``/``fmi2GetReal``);
3. ``python_step_us``: the same step through sealsim's Python objects -- contact map
   evaluation at (Δp, T), ``Theta.step`` and ``Theta.force`` -- best of 5 runs of 2 000 steps;
4. ``ratio`` = python_step_us / fmu_step_us.

Targets: fmu_step_us <= 2 µs and ratio >= 20.

Then the whole-cylinder FMU of the same case (variant T25C, FMI 2.0 co-simulation) over 10 s
of its command cycle (1 s extend, 1 s retract), in the same run:

5. ``cylinder_fmpy_realtime_factor``: ``fmpy.simulate_fmu`` (FMPy's own co-simulation loop,
   a host that knows nothing of sealsim) with 20 ms communication steps, best of 7; and the
   largest difference of the position at the communication points from ``sealsim pneumatic
   run`` (relative to the stroke);
6. ``cylinder_core_realtime_factor``: the same 10 s as ten 1 s ``doStep`` calls through FMPy's
   low-level API (the C integrator and right-hand side alone: the FMU is loaded, instantiated
   and initialised before the clock starts), and ``cylinder_core_20ms_realtime_factor`` as
   500 ``doStep`` calls of 20 ms (the integrator does not cut its steps at communication
   points: about the same, plus ctypes' and FMPy's wrapper per call); ``cylinder_load_ms``:
   what loading does, which item 5 pays in every run (reading modelDescription.xml, loading
   the library, instantiating and initialising); the rest of item 5 is FMPy's own loop;
7. ``cylinder_python_realtime_factor``: ``sealsim pneumatic run`` of the same case (simulate,
   with its 1 ms output table), best of 7.

Items 5 and 6 also give the CPU time of this process (``time.process_time``, best of 7:
``cylinder_fmpy_cpu_ms``, ``cylinder_core_20ms_cpu_ms``), which other work on a shared
machine disturbs less than the wall time.

Target (issue 27): >= 500x real time as co-simulation in FMPy.  The last line printed is one
JSON object; the load average of the machine is printed with it.
"""

from __future__ import annotations

import ctypes
import json
import tempfile
import time
from pathlib import Path

import numpy as np

from sealsim.fmu import LoadedFMU, build_fmu
from sealsim.friction import ContactInputs

CASE = Path(__file__).resolve().parents[1] / "examples" / "pneumatic" / "cylinder_32.toml"
DT = 1e-3
V, P_A, T_SEAL = 0.2, 3e5, 298.15


def best_of(fn, repeat=5, clock=time.perf_counter):
    best = np.inf
    for _ in range(repeat):
        t0 = clock()
        fn()
        best = min(best, clock() - t0)
    return best


def best_of_steps(open_fmu, steps, repeat=7, clock=time.perf_counter):
    """Best time of ``steps(fmu)`` on a freshly opened and initialised FMU each time
    (``open_fmu()``: a LoadedFMU, closed afterwards); opening is not timed."""
    best = np.inf
    for _ in range(repeat):
        with open_fmu() as fmu:
            t0 = clock()
            steps(fmu)
            best = min(best, clock() - t0)
    return best


def main() -> dict:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "piston_seal.fmu"
        build_fmu(CASE, path, seal="piston", kind="cs")
        with LoadedFMU(path) as fmu:
            fmu.set(v=V, p_A=P_A, T_seal=T_SEAL)
            fmu.initialize()
            raw = fmu.raw
            n_fmu = 100_000
            t = [0.0]

            def fmu_steps():
                do_step = raw.doStep
                time_now = t[0]
                for _ in range(n_fmu):
                    do_step(time_now, DT)
                    time_now += DT
                t[0] = time_now

            fmu_wall = best_of(fmu_steps)
            force_fmu = fmu.get("F")[0]

            vr_v = (ctypes.c_uint * 1)(fmu.vr["v"])
            vr_f = (ctypes.c_uint * 1)(fmu.vr["F"])
            value = (ctypes.c_double * 1)(V)
            out = (ctypes.c_double * 1)()
            set_real, get_real = raw.fmi2SetReal, raw.fmi2GetReal
            component = raw.component

            def host_steps():
                do_step = raw.fmi2DoStep
                time_now = t[0]
                for _ in range(n_fmu):
                    set_real(component, vr_v, 1, value)
                    do_step(component, time_now, DT, 1)
                    get_real(component, vr_f, 1, out)
                    time_now += DT
                t[0] = time_now

            host_wall = best_of(host_steps)

        from sealsim.cases import load_toml
        from sealsim.friction import make_law
        from sealsim.pneumatic.case import build_contact_map, load_pneumatic_cases

        case = next(iter(load_pneumatic_cases(load_toml(CASE)).values()))
        seal = next(s for s in case.seals if s.name == "piston")
        law = make_law(seal.friction)
        contact_map = build_contact_map(seal.map, case.cylinder.bore, CASE.parent, "map")
        n_py = 2_000
        state = {"z": law.initial_state(1)}

        def python_steps():
            z = state["z"]
            v = np.array([V])
            for _ in range(n_py):
                dp = P_A * np.tanh(P_A / 1e3)
                fn, b = contact_map.evaluate(dp, T_SEAL)
                inputs = ContactInputs(normal_force=fn, contact_width=b, pressure_a=P_A)
                z = law.step(z, v, DT, inputs)
                law.force(z, v, inputs)
            state["z"] = z

        python_wall = best_of(python_steps)
        fn, b = contact_map.evaluate(P_A * np.tanh(P_A / 1e3), T_SEAL)
        force_py = float(law.steady_force(np.array([V]), ContactInputs(
            normal_force=fn, contact_width=b))[0])

    result = {
        "fmu_step_us": 1e6 * fmu_wall / n_fmu,
        "host_step_us": 1e6 * host_wall / n_fmu,
        "python_step_us": 1e6 * python_wall / n_py,
    }
    result["ratio"] = result["python_step_us"] / result["fmu_step_us"]
    result["steady_force_rel_difference"] = abs(force_fmu / force_py - 1.0)
    print(f"Θ-law piston seal FMU (analytic contact table), 1 ms steps at {V} m/s, "
          f"{P_A / 1e5:g} bar, {T_SEAL - 273.15:g} degC")
    print(f"  doStep through FMPy (FMU2Slave.doStep): {result['fmu_step_us']:.3f} µs/step "
          f"(target <= 2)")
    print(f"  host loop set v + doStep + get F (FMPy's fmi2* wrappers): "
          f"{result['host_step_us']:.3f} µs")
    print(f"  sealsim Python (map + Theta.step + Theta.force): {result['python_step_us']:.1f} "
          f"µs/step")
    print(f"  ratio {result['ratio']:.0f}x (target >= 20); after {t[0]:.0f} s of sliding the "
          f"FMU's force is the steady force within {result['steady_force_rel_difference']:.1e}")
    return result


def cylinder() -> dict:
    """The whole-cylinder FMU against sealsim pneumatic run (items 5-7 above)."""
    import fmpy

    from sealsim.fmu.cylinder_export import cylinder_system, run_fmu
    from sealsim.pneumatic.case import load_pneumatic_case_file
    from sealsim.pneumatic.simulation import run

    case = load_pneumatic_case_file(CASE)["T25C"]
    case = case.model_copy(update={"controller": case.controller.model_copy(
        update={"duration": 10.0})})
    system = cylinder_system(case, CASE.parent)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "cylinder.fmu"
        build_fmu(CASE, path, variant="T25C", kind="cs")
        unpacked = Path(folder) / "unpacked"
        fmpy.extract(str(path), str(unpacked))
        run_fmu(system, unpacked, "cs", output_interval=0.02)         # warm-up
        host_wall = best_of(lambda: run_fmu(system, unpacked, "cs", output_interval=0.02), 7)
        host_cpu = best_of(lambda: run_fmu(system, unpacked, "cs", output_interval=0.02), 7,
                           time.process_time)
        res = run_fmu(system, unpacked, "cs", output_interval=0.02)

        def open_fmu():
            fmu = LoadedFMU(unpacked)
            fmu.set(valve_command=1.0)
            fmu.initialize()
            return fmu

        def core(fmu):
            for k in range(10):
                fmu.set(valve_command=1.0 if k % 2 == 0 else -1.0)
                fmu.do_step(float(k), 1.0)

        def core_20ms(fmu):
            for k in range(500):
                fmu.set(valve_command=1.0 if (k // 50) % 2 == 0 else -1.0)
                fmu.do_step(0.02 * k, 0.02)

        def load():
            open_fmu().close()

        core_wall = best_of_steps(open_fmu, core)
        core_20ms_wall = best_of_steps(open_fmu, core_20ms)
        core_20ms_cpu = best_of_steps(open_fmu, core_20ms, clock=time.process_time)
        load_wall = best_of(load, 7)
    python_wall = best_of(lambda: run(system), 7)
    ref = run(system).timeseries
    x_ref = np.interp(res["time"], ref["time_s"].to_numpy(), ref["x_m"].to_numpy())
    x_diff = float(np.max(np.abs(res["x"] - x_ref)) / system.stroke)
    out = {"cylinder_fmpy_realtime_factor": 10.0 / host_wall,
           "cylinder_core_realtime_factor": 10.0 / core_wall,
           "cylinder_core_20ms_realtime_factor": 10.0 / core_20ms_wall,
           "cylinder_fmpy_cpu_ms": 1e3 * host_cpu,
           "cylinder_core_20ms_cpu_ms": 1e3 * core_20ms_cpu,
           "cylinder_load_ms": 1e3 * load_wall,
           "cylinder_python_realtime_factor": 10.0 / python_wall,
           "cylinder_x_difference_of_stroke": x_diff}
    print("whole-cylinder FMU (cylinder_32.toml, T25C), 10 s of the command cycle:")
    print(f"  FMPy simulate_fmu, co-simulation, 20 ms steps: {host_wall * 1e3:.1f} ms, "
          f"{out['cylinder_fmpy_realtime_factor']:.0f}x real time (target >= 500; CPU "
          f"{out['cylinder_fmpy_cpu_ms']:.1f} ms); position at the communication points "
          f"within {x_diff:.1e} of the stroke of sealsim")
    print(f"  ten 1 s doSteps (C integrator and right-hand side): {core_wall * 1e3:.2f} ms, "
          f"{out['cylinder_core_realtime_factor']:.0f}x real time")
    print(f"  500 doSteps of 20 ms (the same through FMPy's low-level API): "
          f"{core_20ms_wall * 1e3:.2f} ms, {out['cylinder_core_20ms_realtime_factor']:.0f}x "
          f"real time (CPU {out['cylinder_core_20ms_cpu_ms']:.2f} ms)")
    print(f"  loading the FMU (modelDescription.xml, library, instantiate, initialise; "
          f"simulate_fmu pays it in every run): {out['cylinder_load_ms']:.2f} ms")
    print(f"  sealsim pneumatic run (simulate, 1 ms output): {python_wall * 1e3:.1f} ms, "
          f"{out['cylinder_python_realtime_factor']:.0f}x real time")
    return out


if __name__ == "__main__":
    import os

    load = os.getloadavg()[0]
    results = main() | cylinder()
    print(json.dumps({**results, "load_average": round(load, 2)}))
