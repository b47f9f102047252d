r"""The coupled model: cylinder + chambers + valve + controller + seal friction, one stiff ODE.

States::

    y = [x, v, m1, m2, U1, U2, z_seal1..., z_sealN, (T_seal1..., T_tube, T_rod), bookkeeping...]

x, v: piston position and velocity (:mod:`.cylinder`); m_i, U_i: mass and internal energy of the
air in chamber i (:mod:`.chambers`); z: the friction states of each seal's law (Θ, bristles,
...); with seal heating the seal, tube and rod temperatures.  Each evaluation computes, in this
order: chamber volumes, pressures and temperatures; the spool position of the valve
(:class:`.valve.SpoolMotion`) and the ISO 6358 flows of the paths P→A, A→R, P→B, B→R with meter-out
throttles and end cushioning in series; wall heat; the pressure difference across every seal and
F_N, b from its contact map; the friction laws; the piston force balance.

**Integration.**  A stiff method -- by default the compiled variable-order BDF of
:mod:`sealsim.ode.bdf`, or scipy's LSODA, BDF or Radau (``solver.method``) -- restarted at
every valve switch (the spool motion has a kink there) and at every stick/slip transition.
End stops are stiff spring–damper contacts (no velocity resets).

**Sticking.**  Laws without true stiction (LuGre, Dahl, GMS, Θ with bristles) are smooth ODEs
and run in the mode ``free``.  Seals whose law has true sticking (Coulomb, Stribeck, Θ without
bristles: the friction force at rest is set-valued, |F| <= F_brk) make the system hybrid, the
switched model of Karnopp (1985) with the stick test of :func:`sealsim.friction.hybrid.
resolve_stick`:

* *slip* in direction d = ±1: the sticking laws are evaluated with the slip direction held
  (their force keeps the sign d down to v = 0, so the right-hand side stays smooth); the
  event "the motion has reversed", d·v = −ε (ε a tenth of the absolute speed tolerance, so
  that integration noise around v = 0 does not count), ends the mode;
* at rest the body *sticks* if the force needed to hold it, F_req = F_pressure − F_load +
  F_stop − F_smooth seals, is within the break-away force Σ F_brk (+ :func:`stick_tolerance`)
  -- then v ≡ 0, x fixed, and the sticking seals carry F_req shared in proportion to their
  break-away forces: no creep; otherwise it slips in the direction of F_req;
* *stick* ends when |F_req| reaches Σ F_brk (event), e.g. when the valve has switched and the
  pressures have built up: the break-away of Heipl & Murrenhoff.

**Prescribed position** (test rig): x(t), v(t) follow the profile, the chambers and the
friction states are integrated, and the friction force is what the rig's sensor reads.

**Balances.**  The time integrals of what crosses the system boundary -- supply and exhaust
mass flows, enthalpy, wall heat, the work of the load, the atmosphere on the rod, the end
stops and the friction -- are integrated as extra (bookkeeping) states of the same ODE.  At the
end they are compared with the change of the stored mass (m1 + m2) and energy (U1 + U2 + ½Mv²):
``mass_balance_rel_error`` (relative to the mass throughput) and ``energy_balance_rel_error``
(relative to the energy throughput; each at least the initial mass and internal energy of the
air, so that a run in which nothing flows is not judged by its round-off).  Mass is linear in the states, so its balance holds to
round-off for any step sequence (a test of the bookkeeping); the energy balance also tests the
consistency of the model -- the work p·dV the gas does is what drives the piston -- and the
accuracy of the integration (the kinetic energy is not linear in v).  The bookkeeping states are
excluded from the error control and from the Jacobian (they do not feed back).

**Seal heating** (optional, ``[thermal]``): a lumped thermal node per seal heated by its
friction power F·v, and nodes for the tube and the rod (:mod:`.seal_heating`); the contact map
and the friction law of a heated seal follow its temperature, and the chamber walls are at the
tube temperature.  The heat balance (friction heat = heat stored + heat into the air + heat to
the surroundings) is checked like the others (``heat_balance_rel_error``).

**Jacobian.**  Forward differences of all dynamic states, h_j = 1.5e-8·max(|y_j|, scale_j),
compiled (:func:`.rhs.jacobian`).

**Speed.**  The whole right-hand side is one compiled function (:mod:`.rhs`) of the states and
a few preallocated tables (:class:`.system.PneumaticSystem`), composed of the physics functions
of the modules and the friction-law kernels of :mod:`sealsim.friction.kernels`; the default
integrator is compiled too and runs a whole valve interval -- steps, stick/slip events, mode
switches, output samples -- in one call (:func:`.integrate.run_interval`); LSODA is driven step
by step through scipy's own routine with solve_ivp's settings, so its results are those of
``solve_ivp(method="LSODA")``.  The modules:

* :mod:`.system` -- the model of a case: constants, state layout, compiled tables;
* :mod:`.rhs` -- the compiled right-hand side, Jacobian and dense output;
* :mod:`.integrate` -- segments, events, the compiled driver and the LSODA driver;
* :mod:`.results` -- sampling, time series, balances, notes;
* :mod:`.summary` -- the numbers of ``summary.json``.

References
----------
.. [1] D. Karnopp, "Computer simulation of stick-slip friction in mechanical dynamic systems",
   J. Dyn. Sys. Meas. Control 107, 100-103, 1985.
.. [2] O. Heipl, H. Murrenhoff, "Rate- and state-dependent friction model for elastomeric
   seals" (coupling of system simulation, Θ friction model and FE characteristic diagrams,
   Fig. 4/9).
"""

from __future__ import annotations

import time as _time
from collections.abc import Callable
from pathlib import Path

from sealsim.pneumatic import results as _results
from sealsim.pneumatic.case import build_seals
from sealsim.pneumatic.integrate import integrate
from sealsim.pneumatic.results import TIMESERIES_COLUMNS, PneumaticResult, seal_columns
from sealsim.pneumatic.rhs import BACKWARD, BOOKKEEPING, FORWARD, FREE, MODES, PRESCRIBED, STICK
from sealsim.pneumatic.seals import Seal
from sealsim.pneumatic.summary import unfinished_strokes
from sealsim.pneumatic.system import PneumaticSystem, stick_tolerance

__all__ = ["BACKWARD", "BOOKKEEPING", "FORWARD", "FREE", "MODES", "PRESCRIBED", "STICK",
           "TIMESERIES_COLUMNS", "PneumaticResult", "PneumaticSystem",
           "run", "run_cases", "simulate", "simulate_variant", "stick_tolerance"]


def simulate(case, seals: list[Seal] | None = None, base_dir: str | Path = ".",
             progress=None) -> PneumaticResult:
    """Simulate a pneumatic cylinder case.

    Parameters
    ----------
    case : PneumaticCase
        Validated case (:func:`sealsim.pneumatic.case.load_pneumatic_cases` or built in Python).
    seals : list of Seal, optional
        Seal objects; default :func:`sealsim.pneumatic.case.build_seals` of the case.
    base_dir : path
        Folder that relative map paths in the case refer to.
    progress : callable, optional
        ``progress(simulated_time, end_time)`` after every integration segment.

    Returns
    -------
    PneumaticResult

    Raises
    ------
    InputError
        Inconsistent input (e.g. a contact map that does not cover the operating range).
    ConvergenceError
        The integrator failed; the message gives the time and the state.
    """
    if seals is None:
        seals = build_seals(case, base_dir)
    return run(PneumaticSystem(case, seals), progress)


def run(system: PneumaticSystem, progress=None) -> PneumaticResult:
    """Integrate an assembled :class:`PneumaticSystem` and sample its results."""
    wall0 = _time.perf_counter()
    sampler = _results.Sampler(system, reuse=True)      # its samples are copied below
    segments = integrate(system, progress, sampler)
    wall = _time.perf_counter() - wall0
    frame, diag = _results.sample(system, sampler)
    # the sampled times and positions, of which the frame's columns are copies
    time, position = diag["time"], diag["x"]
    system.check_chamber_volumes(time, position)
    balances = _results.balances(system, segments)
    seals = system.seals
    notes = (system.case.valve.assumed_notes()
             + [f"seal {s.name!r}: {n}" for s in seals for n in s.notes] + system.thermal_notes
             + _results.notes(system, diag)
             + unfinished_strokes(time, position, system.case))
    stats = {
        "segments": len(segments),
        "steps": int(sum(s.steps for s in segments)),
        "rhs_evaluations": int(sum(s.nfev for s in segments)),
        "jacobian_evaluations": int(sum(s.njev for s in segments)),
        "mode_switches": int(sum(1 for a, b in zip(segments, segments[1:])
                                 if a.mode != b.mode)),
        "wall_time_s": wall,
        "method": system.case.solver.method,
    }
    names = [s.name for s in seals]
    return PneumaticResult(system.case, frame, balances, stats, notes, names,
                           seal_columns(names))


def run_cases(cases: dict, base_dir: str | Path = ".",
              progress: Callable[[str, float, float], None] | None = None
              ) -> dict[str, PneumaticResult]:
    """Simulate every variant of a case file (``{variant: PneumaticCase}``).

    Parameters
    ----------
    cases : dict
        ``{variant: PneumaticCase}``, e.g. from
        :func:`sealsim.pneumatic.case.load_pneumatic_case_file`.
    base_dir : path
        Folder that relative paths in the cases refer to (the case file's folder).
    progress : callable, optional
        ``progress(variant, simulated_time, end_time)``; while a seal's FE map is built on
        demand, ``progress("<variant>: FE map", finished_load_paths, load_paths)``.

    Returns
    -------
    dict
        ``{variant: PneumaticResult}``.
    """
    return {name: simulate_variant(name, case, base_dir, progress)
            for name, case in cases.items()}


def simulate_variant(name: str, case, base_dir: str | Path = ".",
                     progress: Callable[[str, float, float], None] | None = None
                     ) -> PneumaticResult:
    """One variant of :func:`run_cases`: its seals (FE maps built on demand) and the run."""
    maps = None if progress is None else (
        lambda done, total: progress(f"{name}: FE map", done, total))
    seals = build_seals(case, base_dir, maps)
    callback = None if progress is None else (lambda t, end: progress(name, t, end))
    return simulate(case, seals, base_dir, progress=callback)
