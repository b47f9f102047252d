"""Where the time of the Ø32 cylinder's 10 s cycle goes (the cases of bench_pneumatic.py).

For the analytic contact maps, the FE map of the rod seal and seal heating: ``simulate`` end to
end and its stages measured one by one (set-up of the system, integration with the output
grid, the diagnostics at the output samples, the result table) and inside the run
(:func:`stages_in_run`: the rest of ``run`` -- volume check, balances, notes -- is the run
minus them), the solver's counts (steps,
right-hand sides in the Newton iteration, Jacobians and the right-hand sides of their
forward-difference columns, renewals of the velocity's column by the growth limit, LU
factorisations, segments and steps at rest; per phase of the cycle -- stroke, cap and head end
stop -- and mode: segments, steps, RHS and Jacobians) and the cost of one
compiled call of each part, timed in a compiled loop: the right-hand side, the Jacobian, an LU
factorisation of the Newton matrix, the diagnostics of one output sample.  From those, the
integration's estimated split (evaluations × cost; the remainder is not the BDF bookkeeping
alone: it also holds the Newton iteration's LU solves, what the evaluations cost in the run
above their cost in a loop at one state -- a lower bound --, and the Python around the
compiled calls; a ``perf`` profile of the analytic case put the driver's own compiled code
at about 45 % of the integration's samples, the Python around it at 17 %: see
docs/guide/layout.md).  And which state limits the steps: the analytic case is run
once more by a Python copy of the compiled driver's loop (:func:`limiting_states`: the same
compiled ``start``/``step``/``locate`` calls, checked to take the driver's steps), which
records per accepted step the state with the largest term of the error norm, by phase --
strokes, the 40 ms after each impact on an end stop (the bounce), the rest in the stops --
with the steps at ``solver.max_step``.  Every time is the best of several runs in this
process (7 for the stages, 5 for the loops): on a shared machine the best run is the least
disturbed one.
The per-call costs in a loop at one fixed state are lower bounds (warm caches and branch
predictors).

    .venv/bin/python benchmarks/profile_pneumatic.py

The last line is one JSON object: per case (``analytic``, ``fe_map``, ``heating``) the stage
times [ms], the counts and the per-call costs [µs]; ``analytic_limiting_states`` per phase
the steps, RHS, Jacobians, steps at the largest step and the counts of the limiting states.

    .venv/bin/python benchmarks/profile_pneumatic.py --swap-laws

adds two cases that separate the FE map from the friction law: cylinder_32_fe.toml differs
from cylinder_32.toml in the rod seal's map *and* in both O-rings' friction (the contact
friction tables of ``seal_contact`` instead of the lumped Θ law of ``pneumatic_demo``), so
``fe_map_lumped_law`` is the FE map with the analytic example's friction laws and
``analytic_map_contact_law`` the analytic maps with the FE example's.
"""
from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path
from unittest import mock

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402
from numba import njit  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_pneumatic import EXAMPLE, FE_EXAMPLE, SIMULATED, _case  # noqa: E402

from sealsim.ode import bdf  # noqa: E402
from sealsim.pneumatic import build_seals, integrate, rhs, simulate  # noqa: E402
from sealsim.pneumatic import results as _results  # noqa: E402
from sealsim.pneumatic.case import ThermalModel  # noqa: E402
from sealsim.pneumatic.simulation import PneumaticSystem  # noqa: E402


@njit
def _rhs_loop(count, t, y, args, dy):
    for k in range(count):
        integrate._fun(t + k * 1e-12, y, args, dy)


@njit
def _jacobian_loop(count, t, y, f, args, jac):
    for k in range(count):
        integrate._jac(t + k * 1e-12, y, f, args, jac)


@njit
def _lu_loop(count, matrix, work, m, pivots):
    for _ in range(count):
        for i in range(matrix.shape[0]):
            work[i] = matrix[i]
        bdf.lu_factor_at(work, 0, m, pivots, 0)


def _best(fn, repeat=7):
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def _integrate_counting(system):
    """Integration with the output grid; also the solver's counters (its workspace)."""
    made, original = [], bdf.workspace

    def workspace(*a, **k):
        made.append(original(*a, **k))
        return made[-1]

    sampler = _results.Sampler(system)
    with mock.patch.object(integrate.bdf, "workspace", workspace):
        segments = integrate.integrate(system, None, sampler)
    return sampler, segments, made[-1][1]


def phases(segments, stroke) -> dict:
    """Segments, steps, RHS and Jacobians per phase of the cycle -- in a stroke, or in the
    cap or head end stop (the piston inside the elastic stop: x < 0 or x > stroke at the
    segment's midpoint) -- and per mode."""
    out = {}
    for s in segments:
        x = 0.5 * (s.y0[0] + s.y1[0])
        key = ("cap" if x < 0.0 else "head" if x > stroke else "stroke") + " " \
            + rhs.MODES[s.mode]
        row = out.setdefault(key, {"segments": 0, "steps": 0, "rhs": 0, "jacobians": 0,
                                   "time_s": 0.0})
        row["segments"] += 1
        row["steps"] += int(s.steps)
        row["rhs"] += int(s.nfev)
        row["jacobians"] += int(s.njev)
        row["time_s"] += s.t1 - s.t0
    return dict(sorted(out.items()))


STATE_NAMES = ("x", "v", "m1", "m2", "U1", "U2")
#: how long after an impact a step counts as the bounce [s]
BOUNCE = 0.04


def limiting_states(system) -> dict:
    """Per phase (stroke; bounce: the ``BOUNCE`` after the piston enters an end stop from a
    stroke; rest: the rest of the time in the stops and before the first stroke) the steps,
    right-hand sides, Jacobians, steps at ``solver.max_step`` and how often each dynamic state
    has the largest term |ERROR_CONST·d_i/scale_i| of the error norm of an accepted step.

    The loop is :func:`sealsim.pneumatic.integrate.run_interval`'s, in Python, calling the
    same compiled start/step/locate/event functions (so the same steps; the caller checks the
    totals against the compiled driver's); d (the step's Newton correction) and the scale
    are read from the solver's workspace after each step."""
    case = system.case
    n, ndyn = system.n_states, system.n_dynamic
    ws, work = integrate.solver_workspace(system)
    o_d, o_scale = bdf._offsets(n, ndyn)[6:8]
    w, iv = ws[0], ws[1]
    names = list(STATE_NAMES) + [f"state {j}" for j in range(len(STATE_NAMES), ndyn)]
    y, t = system.initial_state(), 0.0
    mode = integrate._initial_mode(system, t, y)
    end = system.duration
    breaks = sorted({float(a) for a in system.spool.arrivals if 0.0 < a < end} | {end})
    stroke, max_step = system.stroke, float(case.solver.max_step)
    out: dict = {}
    impact, was_in_stroke = -np.inf, None
    for t_next in breaks:
        while t < t_next:
            args = (mode, system.tables, work)
            integrate._bdf_start(ws, t, y, t_next, args)
            direction = -1.0 if mode in (rhs.FORWARD, rhs.BACKWARD) else \
                (1.0 if mode == rhs.STICK else 0.0)
            g_old = integrate._event(t, y, args) if direction else 1.0
            event = False
            while True:
                order, nfev, njev = iv[bdf.I_ORDER], iv[bdf.I_NFEV], iv[bdf.I_NJEV]
                if integrate._bdf_step(ws, args) != bdf.OK:
                    raise RuntimeError("step failed")
                t_new, y_new = w[bdf.S_T], ws[2]
                terms = np.abs(bdf.ERROR_CONST[order] * w[o_d:o_d + ndyn]
                               / w[o_scale:o_scale + ndyn])
                in_stroke = 0.0 <= y_new[0] <= stroke
                if was_in_stroke and not in_stroke:
                    impact = t_new
                was_in_stroke = in_stroke
                phase = "stroke" if in_stroke else (
                    "bounce" if t_new <= impact + BOUNCE else "rest")
                row = out.setdefault(phase, {"steps": 0, "rhs": 0, "jacobians": 0,
                                             "at_max_step": 0, "limited_by": {}})
                row["steps"] += 1
                row["rhs"] += int(iv[bdf.I_NFEV] - nfev)
                row["jacobians"] += int(iv[bdf.I_NJEV] - njev)
                row["at_max_step"] += int(abs(w[bdf.S_T] - w[bdf.S_T_OLD] - max_step)
                                          <= 1e-12 * max_step)
                name = names[int(np.argmax(terms))]
                row["limited_by"][name] = row["limited_by"].get(name, 0) + 1
                if direction:
                    g_new = integrate._event(t_new, y_new, args)
                    if (direction > 0 and g_old <= 0.0 <= g_new) or (
                            direction < 0 and g_old >= 0.0 >= g_new):
                        t_stop = integrate._bdf_locate(ws, args, g_old, g_new, work[5])
                        event = True
                    g_old = g_new
                if event:
                    bdf.dense(ws, t_stop, y)
                    t = t_stop
                    break
                if t_new >= t_next:
                    y[:] = y_new
                    t = t_new
                    break
            if event:
                if mode in (rhs.FORWARD, rhs.BACKWARD):
                    y[1] = 0.0
                    mode = integrate._next_mode_at_rest(t, y, (mode, system.tables, work))
                else:
                    hold, _ = integrate._margin(t, y, args)
                    mode = rhs.FORWARD if hold > 0 else rhs.BACKWARD
    for row in out.values():
        row["limited_by"] = dict(sorted(row["limited_by"].items(), key=lambda kv: -kv[1]))
    totals = (sum(r["steps"] for r in out.values()), int(iv[bdf.I_NFEV]), int(iv[bdf.I_NJEV]))
    return {"phases": out, "totals": totals}


def stages_in_run(case, seals, repeat=7) -> dict:
    """The stages of ``simulate`` timed inside the run [s] -- set-up, integration, outputs at
    the samples, result table, and the rest of ``run`` (volume check, balances, notes,
    statistics) as the run minus them -- each the best of ``repeat`` runs: inside a run, after
    the integration, a stage can cost more than alone."""
    from sealsim.pneumatic import simulation

    timed: dict = {}

    def timer(name, fn):
        def timed_call(*args, **kwargs):
            t0 = time.perf_counter()
            out = fn(*args, **kwargs)
            timed[name] = timed.get(name, 0.0) + time.perf_counter() - t0
            return out
        return timed_call

    best: dict = {}
    with mock.patch.object(simulation, "PneumaticSystem",
                           timer("setup", simulation.PneumaticSystem)), \
            mock.patch.object(simulation, "integrate", timer("integration",
                                                             simulation.integrate)), \
            mock.patch.object(_results, "_diagnostics", timer("outputs",
                                                              _results._diagnostics)), \
            mock.patch.object(_results, "_frame", timer("table", _results._frame)):
        for _ in range(repeat):
            timed.clear()
            t0 = time.perf_counter()
            simulate(case, seals)
            timed["rest"] = time.perf_counter() - t0 - sum(timed.values())
            for name, value in timed.items():
                best[name] = min(best.get(name, np.inf), value)
    return best


def profile(case, base_dir) -> dict:
    seals = build_seals(case, base_dir)
    simulate(case, seals)                             # compiled code loaded
    system = PneumaticSystem(case, seals)
    total = _best(lambda: simulate(case, seals))
    in_run = stages_in_run(case, seals)
    setup = _best(lambda: PneumaticSystem(case, seals))
    integration = _best(lambda: integrate.integrate(system, None, _results.Sampler(system)))
    sampler, segments, counters = _integrate_counting(system)
    ts, ys, modes = sampler.finish()
    outputs = _best(lambda: system.evaluate(ts, ys, modes, full=True, outputs_only=True))
    diag = _results._diagnostics(system, ts, ys, modes)
    table = _best(lambda: _results._frame(system, diag))
    n, ndyn = system.n_states, system.n_dynamic
    # per-call costs at a state in the middle of a slip segment
    slip = [s for s in segments if s.mode in (rhs.FORWARD, rhs.BACKWARD)]
    seg = slip[len(slip) // 2]
    y = seg.y0.copy()
    y[1] = 0.05 * seg.mode
    t = 0.5 * (seg.t0 + seg.t1)
    _, work = integrate.solver_workspace(system)
    args = (seg.mode, system.tables, work)
    dy, jac = np.zeros(n), np.zeros((n, ndyn))
    count = 20000
    _rhs_loop(1, t, y, args, dy)
    _jacobian_loop(1, t, y, dy, args, jac)
    rhs_us = _best(lambda: _rhs_loop(count, t, y, args, dy), 5) / count * 1e6
    jac_count = count // 10
    jac_us = _best(lambda: _jacobian_loop(jac_count, t, y, dy, args, jac), 5) / jac_count * 1e6
    matrix = (np.eye(ndyn) - 1e-3 * jac[:ndyn]).ravel()
    lu_work, pivots = matrix.copy(), np.zeros(ndyn, dtype=np.int64)
    _lu_loop(1, matrix, lu_work, ndyn, pivots)
    lu_us = _best(lambda: _lu_loop(count, matrix, lu_work, ndyn, pivots), 5) / count * 1e6
    steps, nfev = int(counters[bdf.I_NSTEPS]), int(counters[bdf.I_NFEV])
    njev, nlu = int(counters[bdf.I_NJEV]), int(counters[bdf.I_NLU])
    nrenew = int(counters[bdf.I_NRENEW])
    return {
        "total_ms": total * 1e3, "realtime_factor": SIMULATED / total,
        "setup_ms": setup * 1e3, "integration_ms": integration * 1e3,
        "outputs_ms": outputs * 1e3, "table_ms": table * 1e3,
        "in_run_ms": {k: round(v * 1e3, 3) for k, v in in_run.items()},
        "steps": steps, "rhs_newton": nfev, "jacobians": njev,
        "rhs_jacobian_columns": njev * ndyn, "lu_factorisations": nlu,
        "velocity_column_renewals": nrenew, "phases": phases(segments, system.stroke),
        "segments": len(segments),
        "segments_at_rest": sum(1 for s in segments if s.mode == rhs.STICK),
        "steps_at_rest": sum(s.steps for s in segments if s.mode == rhs.STICK),
        "n_dynamic": ndyn, "output_samples": int(ts.size),
        "rhs_us": rhs_us, "jacobian_us": jac_us, "lu_us": lu_us,
        "output_sample_us": outputs / ts.size * 1e6,
    }


def swapped_law_cases() -> dict:
    """The FE example with the analytic example's friction laws and the other way round: each
    seal takes the ``friction`` of the seal of the same name in the other example (the law
    with its parameters as loaded), keeping its own contact map."""
    analytic, fe = _case(SIMULATED), _case(SIMULATED, FE_EXAMPLE)

    def swap(case, donor):
        friction = {s.name: s.friction for s in donor.seals}
        return case.model_copy(update={"seals": [
            s.model_copy(update={"friction": friction[s.name]}) for s in case.seals]})
    return {"fe_map_lumped_law": swap(fe, analytic),
            "analytic_map_contact_law": swap(analytic, fe)}


def main() -> None:
    print(f"load average (1 min) {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    cases = {"analytic": _case(SIMULATED),
             "fe_map": _case(SIMULATED, FE_EXAMPLE),
             "heating": _case(SIMULATED, thermal=ThermalModel())}
    if "--swap-laws" in sys.argv[1:]:
        cases.update(swapped_law_cases())
    out = {}
    seals = build_seals(cases["analytic"], EXAMPLE.parent)
    system = PneumaticSystem(cases["analytic"], seals)
    limits = limiting_states(system)
    _, _, counters = _integrate_counting(system)
    compiled = (int(counters[bdf.I_NSTEPS]), int(counters[bdf.I_NFEV]),
                int(counters[bdf.I_NJEV]))
    if limits["totals"] != compiled:
        raise RuntimeError(f"the Python copy of the driver took {limits['totals']} (steps, "
                           f"RHS, Jacobians), the compiled driver {compiled}")
    print(f"analytic: the state with the largest error term per accepted step ({compiled[0]} "
          f"steps, the compiled driver's), by phase (bounce: {BOUNCE * 1e3:.0f} ms after an "
          "impact on an end stop):")
    for phase, row in limits["phases"].items():
        print(f"    {phase:7s}: {row['steps']:5d} steps, {row['rhs']:5d} RHS, "
              f"{row['jacobians']:4d} Jacobians, {row['at_max_step']:3d} at max_step; "
              "limited by " + ", ".join(f"{k} {v}" for k, v in row["limited_by"].items()))
    out["analytic_limiting_states"] = limits["phases"]
    for label, case in cases.items():
        p = profile(case, EXAMPLE.parent)
        out[label] = {k: round(v, 3) if isinstance(v, float) else v for k, v in p.items()
                      if k != "phases"}
        rest = p["total_ms"] - p["setup_ms"] - p["integration_ms"] - p["outputs_ms"] \
            - p["table_ms"]
        est = {"RHS (Newton)": p["rhs_newton"] * p["rhs_us"] / 1e3,
               "Jacobians": p["jacobians"] * p["jacobian_us"] / 1e3,
               "LU": p["lu_factorisations"] * p["lu_us"] / 1e3}
        driver = p["integration_ms"] - sum(est.values())
        print(f"{label}: simulate {p['total_ms']:.2f} ms ({p['realtime_factor']:.0f}x real "
              f"time) = set-up {p['setup_ms']:.2f} + integration {p['integration_ms']:.2f} "
              f"+ output diagnostics {p['outputs_ms']:.2f} ({p['output_samples']} samples, "
              f"{p['output_sample_us']:.3f} us each) + table {p['table_ms']:.2f} + rest "
              f"{rest:.2f} ms")
        r = p["in_run_ms"]
        print(f"  inside a run (each the best of 7): set-up {r['setup']:.2f} + integration "
              f"{r['integration']:.2f} + output diagnostics {r['outputs']:.2f} + table "
              f"{r['table']:.2f} + the rest of run (volume check, balances, notes) "
              f"{r['rest']:.2f} ms")
        print(f"  {p['steps']} steps, {p['rhs_newton']} RHS in the Newton iteration, "
              f"{p['jacobians']} Jacobians ({p['rhs_jacobian_columns']} RHS, {p['n_dynamic']}"
              f" columns), {p['velocity_column_renewals']} renewals of the velocity's column,"
              f" {p['lu_factorisations']} LU, {p['segments']} segments "
              f"({p['segments_at_rest']} at rest, {p['steps_at_rest']} steps at rest)")
        for key, row in p["phases"].items():
            print(f"    {key:14s}: {row['segments']:4d} segments, {row['steps']:5d} steps, "
                  f"{row['rhs']:6d} RHS, {row['jacobians']:5d} Jacobians, "
                  f"{row['time_s']:.3f} s simulated")
        print(f"  per call: RHS {p['rhs_us']:.3f} us, Jacobian {p['jacobian_us']:.3f} us, LU "
              f"{p['lu_us']:.3f} us; integration estimated as "
              + ", ".join(f"{k} {v:.2f} ms ({v / p['integration_ms'] * 100:.0f} %)"
                          for k, v in est.items())
              + f", rest (steps, LU solves, events, dense output, Python) {driver:.2f} ms "
              f"({driver / p['integration_ms'] * 100:.0f} %)")
    print(json.dumps(out))


if __name__ == "__main__":
    main()
