"""Thin orchestration: case → model (:mod:`.build`) → load path → results (:mod:`.results`).

Like pvlib's ModelChain it only composes the pieces of :mod:`sealsim.structure`; each of them
can be used on its own.  Maps are computed by :mod:`.mapping`; the result folders of
``sealsim structure run`` and ``map`` are written by :mod:`sealsim.runs.structure`.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field

from sealsim.structure.build import build_model, load_steps
from sealsim.structure.case import StructureCase
from sealsim.structure.model import SealModel
from sealsim.structure.solver import solve

__all__ = ["SUMMARY_KEYS", "RunResult", "run_case"]


@dataclass
class RunResult:
    """Results of :func:`run_case`: one :class:`~.results.StateResult` per load state."""

    states: list
    ndofs: int
    wall_time: float
    model: SealModel = field(repr=False)


def run_case(case: StructureCase, progress=None) -> RunResult:
    """Solve the load path of a case.

    Parameters
    ----------
    case : StructureCase
        Validated case.
    progress : callable, optional
        ``progress(done, total)`` after every recorded state.
    """
    from sealsim.structure.results import extract

    ld = case.load
    model = build_model(case, None if ld.squeeze is None else ld.squeeze[0],
                        squeezes=(ld.squeeze or [])[1:],
                        temperatures=[ld.installation_temperature, *ld.temperature])
    steps = load_steps(case)
    total = sum(s.increments if s.record == "all" else 1 for s in steps)
    states = []

    def record(m):
        r = extract(m)
        states.append(r)
        if progress is not None:
            progress(len(states), total)
        return r

    t0 = time.perf_counter()
    sv = case.solver
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        solve(model, steps, on_state=record, tol=sv.tolerance, maxiter=sv.max_iterations,
              max_cutbacks=sv.max_cutbacks, increment_growth=sv.increment_growth)
    return RunResult(states, model.ndofs, time.perf_counter() - t0, model)


#: The final-state results a summary reports (columns of :func:`~.results.results_frame`).
SUMMARY_KEYS = ("F_N_N", "F_N_per_length_N_per_mm", "b_mm", "p_max_MPa", "p_mean_MPa")
