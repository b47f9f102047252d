"""Make the synthetic rig measurements that ``rotary_synthetic.toml`` fits and validates on.

No public lip-seal rig data exist, so the "measurements" come from sealsim's rotary model with a
different set-up than the fit uses -- the truth the fit has to find back:

* parameters away from the fit's start values (:data:`TRUTH`: lip force, film coefficient and
  two heat-transfer factors);
* another model set-up: thermal mesh refinement 1.5 and time steps of 0.1-2 s (the fit uses
  mesh 1.0 and 10 s steps);
* a rig's sampling (every 2 s) with seeded white noise on speed, torque and temperature
  (:data:`NOISE`) and 5 s speed ramps between the steps.

The model, the conditions of each run and the file names are read from the example case, so
the two cannot drift apart.  Run from anywhere::

    python examples/calibration/make_rotary_synthetic.py

It rewrites ``rotary_synthetic_fit.csv`` and ``rotary_synthetic_validate.csv`` (about 50 kB
each) bit for bit: the noise is seeded.  With ``--numerics`` it instead measures what the fit's
numerics cost: the step averages of both runs with the true parameters on the fit's mesh and
time steps, on mesh 0.5, and on mesh 2.5, against the measurements' model.
"""

from __future__ import annotations

import argparse
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from sealsim.calibration.rotary_case import expand_dotted
from sealsim.cases import apply_overrides, validate_case
from sealsim.measurements import step_averages
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import simulate

HERE = Path(__file__).resolve().parent
CASE = HERE / "rotary_synthetic.toml"

#: The true values (SI) of the parameters the example fits; its start values are the model's
#: defaults (37.7 N, 3.1464, 0.2, 6 W/(m² K)).
TRUTH = {"seal.radial_force": 32.0, "friction.film_coefficient_um": 2.7,
         "thermal.seal_oil_factor": 0.3, "environment.housing_heat_transfer": 8.0}
#: The model that makes the measurements: a finer mesh and shorter time steps than the fit's.
TRUE_NUMERICS = {"mesh_refinement": 1.5, "max_time_step": "2 s", "min_time_step": "0.1 s"}
#: Standard deviations of the white noise on each sample: speed [rpm], torque [N m],
#: spring-groove temperature [K] (a torque flange of 0.5 % of 2 N m full scale, a type-K
#: thermocouple with a good amplifier).
NOISE = {"speed_rpm": 0.5, "torque_Nm": 0.01, "T_groove_C": 0.1}
SAMPLE_INTERVAL = 2.0
RAMP = 5.0
#: Speed steps [rpm, min] of the two cycles, after 1 min at standstill; the measurements of
#: the case are matched by their role.
CYCLES = {
    "fit": [(100, 10), (250, 10), (500, 10), (750, 10), (1000, 10), (1500, 10)],
    "validate": [(1500, 12), (300, 12), (1000, 12), (600, 12), (1200, 12)],
}
SEEDS = {"fit": 11, "validate": 12}


def true_case(model: dict, conditions: dict, steps, truth=None, numerics=None) -> RotaryCase:
    """The case that makes a measurement: the fit's model with the run's conditions, the true
    parameters, the finer numerics and the speed cycle (1 min standstill first)."""
    duty = {"steps": [{"speed": "0 rpm", "duration": "1 min"}]
            + [{"speed": f"{n} rpm", "duration": f"{d} min", "ramp": f"{RAMP} s"}
               for n, d in steps]}
    data = apply_overrides(model, expand_dotted(conditions))
    data = apply_overrides(data, {"duty": duty, "numerics": numerics or TRUE_NUMERICS})
    data = apply_overrides(data, expand_dotted(truth if truth is not None else TRUTH))
    return validate_case(RotaryCase, data, "synthetic truth", require_units=False)


def measure(case: RotaryCase | pd.DataFrame, seed: int, interval: float = SAMPLE_INTERVAL,
            noise: dict | None = None) -> np.ndarray:
    """Sample a simulated run (a case, or its time series) like a rig: every ``interval`` s,
    with seeded white noise.

    Returns the columns time_s, speed_rpm, torque_Nm, T_groove_C.
    """
    noise = NOISE if noise is None else noise
    if isinstance(case, pd.DataFrame):
        frame = case
    else:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            frame = simulate(case).timeseries
    t = np.arange(0.0, frame["time_s"].iloc[-1] + 1e-9, interval)
    rng = np.random.default_rng(seed)
    columns = [t]
    for name in ("speed_rpm", "torque_Nm", "T_groove_C"):
        clean = np.interp(t, frame["time_s"], frame[name])
        columns.append(clean + rng.normal(0.0, noise[name], t.size))
    return np.column_stack(columns)


def write_measurement(path: Path, table: np.ndarray, title: str) -> None:
    header = (f"# {title}\n# synthetic: made by make_rotary_synthetic.py (sealsim rotary model, "
              "see its docstring)\n# truth: " + ", ".join(f"{k} = {v:g}" for k, v in
                                                         TRUTH.items()) + " (SI)\n"
              "time_s,speed_rpm,torque_Nm,T_groove_C\n")
    rows = "".join(f"{t:.1f},{n:.2f},{q:.4f},{g:.2f}\n" for t, n, q, g in table)
    path.write_text(header + rows)


def numerics_error() -> None:
    """Largest step-average differences of the fit's numerics (and of a finer mesh) from the
    model that made the measurements, with the true parameters and no noise."""
    spec = tomllib.loads(CASE.read_text())
    model = spec["model"]
    others = {"fit": model["numerics"],
              "mesh 0.5": {**model["numerics"], "mesh_refinement": 0.5},
              "mesh 2.5": {**TRUE_NUMERICS, "mesh_refinement": 2.5}}
    for m in spec["measurements"]:
        steps = {}
        for label, numerics in (("reference", TRUE_NUMERICS), *others.items()):
            table = measure(true_case(model, m.get("conditions", {}), CYCLES[m["role"]],
                                      numerics=numerics), 0, noise=dict.fromkeys(NOISE, 0.0))
            rows = step_averages(table[:, 0], table[:, 1], {"torque": table[:, 2],
                                                            "groove": table[:, 3]})
            steps[label] = np.array([[r["torque"], r["groove"]] for r in rows])
        for label, numerics in others.items():
            diff = np.abs(steps[label] - steps["reference"])
            rel = diff[:, 0] / np.maximum(steps["reference"][:, 0], 1e-3)
            print(f"{m['name']}: {label} {numerics} vs the measurements' model: torque within "
                  f"{diff[:, 0].max():.4f} N m ({100 * rel.max():.2f} %), groove temperature "
                  f"within {diff[:, 1].max():.2f} K")


def main() -> None:
    spec = tomllib.loads(CASE.read_text())
    model = spec["model"]
    for m in spec["measurements"]:
        case = true_case(model, m.get("conditions", {}), CYCLES[m["role"]])
        table = measure(case, SEEDS[m["role"]])
        path = HERE / m["file"]
        write_measurement(path, table, f"{m['name']} ({m['role']})")
        print(f"{path.name}: {len(table)} samples, {table[-1, 0] / 60:.0f} min, "
              f"{path.stat().st_size / 1e3:.0f} kB")
    print("truth (SI):", ", ".join(f"{k} = {v:g}" for k, v in TRUTH.items()))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--numerics", action="store_true",
                        help="measure the error of the fit's coarse numerics instead")
    if parser.parse_args().numerics:
        numerics_error()
    else:
        main()
