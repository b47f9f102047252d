"""Co-simulation: FMPy drives the friction FMU together with a mass-spring (stick-slip).

The LuGre benchmark of Canudas de Wit et al. (1995), ``examples/friction/lugre_stick_slip.toml``:
a 1 kg body on the contact is pulled through a spring k = 2 N/m whose end moves at 0.1 m/s.
The friction law is exported as an FMU and run by two co-simulation masters written here in
Python with FMPy, both with a 1 ms communication step:

* **explicit** -- what any co-simulation host does: each step the mass-spring is advanced
  with the friction force of the last step (semi-implicit Euler), the new velocity is the
  FMU's input for its ``doStep``;
* **implicit** -- sealsim's own stick/slip stepper (``simulate_mass(integrator="stepper")``)
  with the FMU as its friction element (:class:`sealsim.fmu.cosim.FMUFrictionLaw`): each
  trial velocity is a ``doStep`` from the saved FMU state (``getFMUstate``/``setFMUstate``).

Both are compared with the native sealsim model (``sealsim friction run`` on the same case:
Radau with rtol 1e-7), the implicit one also with the native model on the same stepper (the
C law against the Python law, same master).  Run::

    python examples/fmu/stick_slip_cosim.py --out results/stick_slip_cosim

It writes ``stick_slip.png``, ``timeseries.csv`` and ``summary.json`` and prints the stick-slip
periods and the largest differences.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.cases import load_toml
from sealsim.fmu import LoadedFMU, build_fmu
from sealsim.fmu.cosim import FMUFrictionLaw
from sealsim.friction.bench import BenchResult, simulate_mass, stick_slip_period
from sealsim.friction.case import build_law, load_friction_cases, make_inputs

CASE = Path(__file__).resolve().parents[1] / "friction" / "lugre_stick_slip.toml"


def load_case():
    """The bench case and its law (LuGre, 1995 Table I set)."""
    case = next(iter(load_friction_cases(load_toml(CASE), f"case file {CASE.name}").values()))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")            # the Table I set is not passive (documented)
        law = build_law(case)
    return case, law


def explicit_cosimulation(fmu_path, case, duration: float, step: float) -> BenchResult:
    """A host's explicit coupling: mass-spring with the last friction force, FMU with the
    new velocity."""
    bench = case.bench
    n = int(round(duration / step))
    t = np.arange(n + 1) * step
    drive = bench.drive_velocity.integral(t)
    x = np.zeros(n + 1)
    v = np.zeros(n + 1)
    force = np.zeros(n + 1)
    with LoadedFMU(fmu_path) as fmu:
        fmu.initialize()
        force[0] = fmu.get("F")[0]
        for k in range(n):
            spring = bench.stiffness * (drive[k + 1] - x[k])
            v[k + 1] = v[k] + step * (spring - force[k]) / bench.mass
            x[k + 1] = x[k] + step * v[k + 1]
            fmu.set(v=v[k + 1])
            fmu.do_step(t[k], step)
            force[k + 1] = fmu.get("F")[0]
    return BenchResult(t, x, v, force, np.zeros((n + 1, 0)), (), "mass", drive_position=drive)


def implicit_cosimulation(fmu_path, case, duration: float, step: float) -> BenchResult:
    """sealsim's implicit stick/slip stepper with the FMU as the friction element."""
    bench = case.bench
    with LoadedFMU(fmu_path) as fmu:
        law = FMUFrictionLaw(fmu)
        law.start()
        return simulate_mass(law, bench.mass, duration, step, stiffness=bench.stiffness,
                             drive_velocity=bench.drive_velocity, integrator="stepper")


def native(case, law, duration: float, integrator: str = "auto") -> BenchResult:
    """The native sealsim model of the bench (Radau by default)."""
    bench = case.bench
    return simulate_mass(law, bench.mass, duration, bench.time_step, stiffness=bench.stiffness,
                         drive_velocity=bench.drive_velocity, inputs=make_inputs(case),
                         integrator=integrator, rtol=bench.rtol)


def compare(result: BenchResult, reference: BenchResult) -> dict:
    """Stick-slip period and the largest differences of velocity and force."""
    v_ref = np.interp(result.time, reference.time, reference.velocity)
    f_ref = np.interp(result.time, reference.time, reference.force)
    period, period_ref = stick_slip_period(result), stick_slip_period(reference)
    return {"stick_slip_period_s": period, "period_rel_difference": (
        None if period is None or period_ref is None else abs(period / period_ref - 1)),
        "max_velocity_difference_m_s": float(np.max(np.abs(result.velocity - v_ref))),
        "max_force_difference_N": float(np.max(np.abs(result.force - f_ref))),
        "peak_force_N": float(np.max(result.force))}


def main(out: Path, duration: float | None = None) -> dict:
    from sealsim.output import ResultFolder
    from sealsim.plotting.friction import plot_timeseries

    case, law = load_case()
    duration = duration or case.bench.duration
    folder = ResultFolder(out, force=True, inputs=[CASE])
    with tempfile.TemporaryDirectory() as scratch:
        fmu_path = Path(scratch) / "lugre.fmu"
        build_fmu(CASE, fmu_path, kind="cs")
        runs = {"native": native(case, law, duration),
                "native, stepper": native(case, law, duration, "stepper"),
                "FMU, explicit host": explicit_cosimulation(fmu_path, case, duration,
                                                            case.bench.time_step),
                "FMU, implicit (state rollback)": implicit_cosimulation(
                    fmu_path, case, duration, case.bench.time_step)}
    summary = {"case": str(CASE), "duration_s": duration,
               "native": {"stick_slip_period_s": stick_slip_period(runs["native"]),
                          "peak_force_N": float(np.max(runs["native"].force))},
               "FMU, explicit host": compare(runs["FMU, explicit host"], runs["native"]),
               "FMU, implicit (state rollback)": compare(
                   runs["FMU, implicit (state rollback)"], runs["native"]),
               "FMU, implicit vs native stepper": compare(
                   runs["FMU, implicit (state rollback)"], runs["native, stepper"])}
    frames = [pd.DataFrame({"run": name, "time_s": r.time, "velocity_m_s": r.velocity,
                            "friction_force_N": r.force}) for name, r in runs.items()]
    with folder:
        folder.write_csv("timeseries.csv", pd.concat(frames), float_format="%.9g")
        folder.write_json("summary.json", summary)
        shown = ("native", "FMU, explicit host", "FMU, implicit (state rollback)")
        folder.savefig("stick_slip.png", plot_timeseries(
            {k: runs[k] for k in shown}, "LuGre stick-slip: native sealsim vs the FMU driven "
                                         "by FMPy"))
    return summary


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="results/stick_slip_cosim", type=Path)
    parser.add_argument("--duration", type=float, default=None,
                        help="simulated time [s] (default: the case's 25 s)")
    args = parser.parse_args()
    print(json.dumps(main(args.out, args.duration), indent=2))
