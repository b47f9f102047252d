"""The models a study can run, each through the run function the model already has.

A model entry names its case class and a ``run(case, base_dir)`` that returns the model's
summary (nested dict, the numbers of its ``summary.json``) and its series (a table indexed by
time or load state, or the arrays of a characteristic map).  Nothing here computes physics.

========================  ==================================================================
``rotary``                duty cycle of a lip seal (:func:`sealsim.rotary.simulation.simulate`);
                          summary: ``last_step.*`` (averages over the last 30 s of the last
                          step: ``torque_Nm``, ``power_W``, ``T_contact_C``, ``T_groove_C``,
                          ``T_sump_C``), ``steps.K.*`` (step K, from 0), ``max_T_contact_C``,
                          ``energy_balance_rel_error``; series over ``time``
``rotary_steady``         steady operating point at the speed of the case's one duty step
                          (:func:`sealsim.rotary.simulation.steady_state`): ``torque_Nm``,
                          ``power_W``, ``T_contact_C``, ``T_groove_C``, ``T_sump_C``,
                          ``film_um``, ``F_lub_N``, ``F_material_N``, ``speed_rpm``
``friction``              a friction law on its test bench
                          (:func:`sealsim.friction.case.run_friction_case`):
                          ``max_friction_force_N``, ``dissipated_energy_J``,
                          ``breakaway_forces_N.0``, ...; series over ``time``
``structure``             FE load path of a seal (:func:`sealsim.structure.run.run_case`):
                          ``final.F_N_N``, ``final.b_mm``, ``final.p_max_MPa``, ...,
                          ``states.K.*``; series over load ``state``
``structure_map``         characteristic map (:func:`sealsim.structure.mapping.compute_map`):
                          ``F_N_N.min``/``.max``/``.grid.I.J.K`` (squeeze, temperature,
                          pressure indices), likewise ``b_mm``, ``p_max_MPa``; series: the map
``pneumatic``             cylinder cycle (:func:`sealsim.pneumatic.simulation.simulate`):
                          ``extend_time_s``, ``mean_friction_N``, ``air_consumption_NL``,
                          ``seals.NAME.mean_friction_N``, ``seals.NAME.normal_force_range_N.0``,
                          ...; series over ``time``
========================  ==================================================================
"""

from __future__ import annotations

import importlib
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = ["MODELS", "ModelSpec", "RunOutput", "flatten"]


@dataclass
class RunOutput:
    """What one run of a model gives: its summary and, optionally, its series."""

    summary: dict
    series: Any = None          # pandas DataFrame indexed by time/state, or xarray Dataset
    notes: tuple = ()


@dataclass(frozen=True)
class ModelSpec:
    """A model a study can run."""

    name: str
    case_class_path: str                      # "module:Class"
    run: Callable[[Any, Path], RunOutput]
    series_axis: str | None = None            # "time" (resampled), "state", or None (own dims)
    prepare: Callable[[Any, Path], None] | None = None   # once per distinct linked case
    check: Callable[[Any], None] | None = None   # what the model needs beyond a valid case

    def case_class(self) -> type:
        module, name = self.case_class_path.split(":")
        return getattr(importlib.import_module(module), name)


def flatten(tree: Any, prefix: str = "") -> dict[str, float | None]:
    """Numbers of a nested summary as ``{"a.b.0": value}`` (text is left out, None kept).

    Examples
    --------
    >>> flatten({"seals": {"rod": {"F_N": [1, 2.5]}}, "ok": True, "method": "LSODA", "x": None})
    {'seals.rod.F_N.0': 1.0, 'seals.rod.F_N.1': 2.5, 'ok': 1.0, 'x': None}
    """
    out: dict[str, float | None] = {}
    if isinstance(tree, dict):
        items = tree.items()
    elif isinstance(tree, list | tuple):
        items = enumerate(tree)
    else:
        return out
    for key, value in items:
        name = f"{prefix}{key}"
        if value is None:
            out[name] = None
        elif isinstance(value, bool | int | float) or _is_number(value):
            value = float(value)
            out[name] = value if math.isfinite(value) else None
        else:
            out.update(flatten(value, name + "."))
    return out


def _is_number(value) -> bool:
    import numpy as np

    return isinstance(value, np.number | np.bool_)


# -- run functions ---------------------------------------------------------------------------

def _rotary(case, base_dir: Path) -> RunOutput:
    from sealsim.rotary.simulation import simulate

    result = simulate(case, base_dir=base_dir)
    summary = {k: v for k, v in result.summary().items() if k != "notes"}
    summary["last_step"] = result.steps[-1]
    return RunOutput(summary, result.timeseries.set_index("time_s"), tuple(result.notes))


def _one_duty_step(case) -> None:
    from sealsim.errors import InputError

    duty = getattr(case, "duty", None)
    if duty is None or duty.steps is None or len(duty.steps) != 1:
        raise InputError("model 'rotary_steady' evaluates one speed: the case needs a duty "
                         "cycle of one step, e.g. [set] \"duty.steps\" = [{ speed = "
                         "\"1000 rpm\", duration = \"1 h\" }] (its duration is not used)")


def _rotary_steady(case, base_dir: Path) -> RunOutput:
    from sealsim.rotary.simulation import steady_state

    _one_duty_step(case)
    speed = float(case.duty.steps[0].speed)
    result = steady_state(case, speed)
    note = result.pop("lip_note")
    return RunOutput({"speed_rpm": speed * 30.0 / math.pi, **result}, notes=(note,) if note else ())


def _friction(case, base_dir: Path) -> RunOutput:
    import pandas as pd

    from sealsim.friction.case import build_law, run_friction_case
    from sealsim.pneumatic.bench import bench_inputs

    law = inputs = None
    if case.seal is not None:          # a real seal on the bench: its contact's inputs
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            law = build_law(case)
        inputs = bench_inputs(case, law, base_dir)[0]
    result, summary = run_friction_case(case, law, inputs=inputs)
    return RunOutput(summary, pd.DataFrame(result.columns()).set_index("time_s"))


def _structure(case, base_dir: Path) -> RunOutput:
    from sealsim.structure.results import results_frame
    from sealsim.structure.run import SUMMARY_KEYS, run_case

    result = run_case(case)
    frame = results_frame(result.states)
    last = frame.iloc[-1]
    summary = {"final": {k: float(last[k]) for k in SUMMARY_KEYS},
               "max_penetration_um": float(frame["max_penetration_um"].max()),
               "dofs": result.ndofs,
               "states": frame.select_dtypes("number").to_dict("records")}
    return RunOutput(summary, frame.select_dtypes("number").rename_axis("state"))


#: map variables in the summary: name with unit -> (variable, factor to the unit)
_MAP_SUMMARY = {"F_N_N": ("F_N", 1.0), "F_N_per_length_N_per_mm": ("F_N_per_length", 1e-3),
                "b_mm": ("b", 1e3), "p_max_MPa": ("p_max", 1e-6), "p_mean_MPa": ("p_mean", 1e-6)}


def _structure_map(case, base_dir: Path) -> RunOutput:
    from sealsim.structure.mapping import compute_map

    dataset = compute_map(case, workers=1)
    summary = {}
    for name, (variable, scale) in _MAP_SUMMARY.items():
        values = dataset[variable].values * scale
        summary[name] = {"min": float(values.min()), "max": float(values.max()),
                         "grid": values.tolist()}
    return RunOutput(summary, dataset.drop_attrs())


def _pneumatic_seals(case, base_dir: Path, map_workers: int | None = 1):
    from sealsim.pneumatic.case import build_seals

    return build_seals(case, base_dir, map_workers=map_workers)


def _pneumatic(case, base_dir: Path) -> RunOutput:
    from sealsim.pneumatic.simulation import simulate

    result = simulate(case, _pneumatic_seals(case, base_dir), base_dir)
    summary = result.summary()
    notes = tuple(summary.pop("notes", ()))
    return RunOutput(summary, result.timeseries.set_index("time_s"), notes)


MODELS: dict[str, ModelSpec] = {m.name: m for m in [
    ModelSpec("rotary", "sealsim.rotary.case:RotaryCase", _rotary, "time"),
    ModelSpec("rotary_steady", "sealsim.rotary.case:RotaryCase", _rotary_steady,
              check=_one_duty_step),
    ModelSpec("friction", "sealsim.friction.case:FrictionCase", _friction, "time"),
    ModelSpec("structure", "sealsim.structure.case:StructureCase", _structure, "state"),
    ModelSpec("structure_map", "sealsim.structure.case:StructureCase", _structure_map),
    ModelSpec("pneumatic", "sealsim.pneumatic.case:PneumaticCase", _pneumatic, "time",
              prepare=_pneumatic_seals),
]}
