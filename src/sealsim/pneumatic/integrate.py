"""Time integration of the pneumatic model, segment by segment.

The ODE is integrated between valve switches (the spool motion has a kink there) and
stick/slip transitions (events).

* ``solver.method = "compiled"`` (the default): the variable-order BDF method of
  :mod:`sealsim.ode.bdf` (scipy's BDF algorithm, compiled), driven by one compiled function
  per valve interval (:func:`run_interval`) that also locates the stick/slip events, switches
  the mode and samples the output grid -- no Python between steps.  The bookkeeping integrals
  are its quadrature states (outside the Newton matrix and the error control).
* ``"LSODA"`` (the reference in the tests): driven step by step through scipy's own LSODA
  routine with exactly the settings, events and dense output of
  ``scipy.integrate.solve_ivp(method="LSODA", dense_output=True, events=...)`` -- the same
  steps and the same results -- without solve_ivp's per-step Python objects; the right-hand
  side and the Jacobian are compiled (:mod:`.rhs`).  If scipy's low-level LSODA routine is not
  available (a scipy version that moved it), LSODA runs through ``solve_ivp``.
* ``"BDF"`` and ``"Radau"`` run through ``solve_ivp`` itself.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numba import njit
from scipy.integrate import solve_ivp

from sealsim.errors import ConvergenceError
from sealsim.ode import bdf
from sealsim.pneumatic import rhs
from sealsim.pneumatic._jit import borrowed, jit
from sealsim.pneumatic.system import stick_tolerance
from sealsim.units import ZERO_CELSIUS_K

try:  # scipy's LSODA step routine (what solve_ivp's LSODA class calls)
    from scipy.integrate._ivp.lsoda import LsodaDenseOutput
    from scipy.integrate._odepack import lsoda as _lsoda_step
except ImportError:  # pragma: no cover - depends on the scipy version
    _lsoda_step = None

__all__ = ["Segment", "integrate", "run_interval", "segment_states"]

_MAX_SWITCHES_PER_MS = 200    # stick/slip chattering guard
_EPS = np.finfo(float).eps


@dataclass
class Segment:
    """One integration segment (constant mode, no valve switch inside).

    Attributes
    ----------
    t0, t1 : float
        Start and end time [s].
    mode : int
        Integration mode (:data:`sealsim.pneumatic.rhs.MODES`).
    y0, y1 : ndarray
        States at the start and the end.
    steps, nfev, njev : int
        Solver statistics.
    dense : object
        The dense output: LSODA step histories (:func:`segment_states`) or a scipy
        ``OdeSolution``.
    """

    t0: float
    t1: float
    mode: int
    y0: np.ndarray
    y1: np.ndarray
    steps: int
    nfev: int
    njev: int
    status: int
    dense: object = field(repr=False, default=None)


@dataclass
class _LsodaHistory:
    """Nordsieck histories of the LSODA steps of a segment (scipy's LsodaDenseOutput data)."""

    times: np.ndarray          # start of the segment, then the end of every step (event time)
    ends: np.ndarray           # the time each step's history refers to (its end)
    h: np.ndarray
    order: np.ndarray
    start: np.ndarray
    data: np.ndarray
    n: int


def segment_states(segment: Segment, ts) -> np.ndarray:
    """States (n, k) of a segment at the times ``ts`` from its dense output."""
    ts = np.ascontiguousarray(ts, dtype=float)
    dense = segment.dense
    if isinstance(dense, _LsodaHistory):
        out = np.empty((dense.n, ts.size))
        rhs.dense_values(ts, dense.times, dense.ends, dense.h, dense.order, dense.start,
                         dense.data, dense.n, out)
        return out
    return dense(ts)


def _where(system, t, y, mode) -> str:
    d = system.evaluate(t, y, mode, full=True)
    return (f"t = {t:.6g} s, x = {float(d['x'][0]) * 1e3:.4g} mm, v = {float(d['v'][0]):.4g} m/s,"
            f" p1 = {float(d['p1'][0]) / 1e5:.4g} bar, p2 = {float(d['p2'][0]) / 1e5:.4g} bar, "
            f"T1 = {float(d['T1'][0]) - ZERO_CELSIUS_K:.4g} degC, T2 = {float(d['T2'][0]) - ZERO_CELSIUS_K:.4g} "
            f"degC, mode {rhs.MODES[mode]}")


def _event_function(system, mode, speed_resolution):
    """(g(t, y), direction) of the terminal event of a mode, or None.

    In a slip mode the event is v = −d·ε (the motion has reversed by more than the speed
    resolution ε of the integration, a tenth of its absolute tolerance on v): a slip that
    starts from rest with a vanishing acceleration, or a creep at the friction limit, has
    v = 0 within the integration noise and must not stop at every step.  At rest it is the
    break-away |F_req| = F_brk."""
    if mode in (rhs.FORWARD, rhs.BACKWARD):
        d = float(mode)

        def stop(t, y):
            return d * y[1] + speed_resolution
        return stop, -1.0
    if mode == rhs.STICK:
        def breakaway(t, y):
            hold, brk = system.stick_margin(t, y)
            return abs(hold) - brk
        return breakaway, 1.0
    return None


def _solve_lsoda(system, t0, t1, y0, mode, rtol, atol, max_step):
    """One segment with scipy's LSODA routine, as solve_ivp(method="LSODA") would run it."""
    n = y0.size
    y_type = np.zeros(n)          # scipy's LSODA passes y as a C-contiguous float64 array
    f = system.rhs(mode, y_type)
    jac = system.jacobian_function(mode, y_type)

    # the work arrays and settings of scipy.integrate._ode.lsoda (with a user Jacobian) as
    # set up by solve_ivp's LSODA class: itask 5 (one step, not beyond t_bound = rwork[0])
    rwork = np.zeros(max(20 + 16 * n, 22 + 9 * n + n * n))
    rwork[0] = t1
    rwork[5] = 0.0 if max_step == np.inf else max_step
    iwork = np.zeros(20 + n, dtype=np.int32)
    iwork[5], iwork[7], iwork[8] = 500, 12, 5
    state_doubles = np.zeros(240)
    state_ints = np.zeros(48, dtype=np.int32)
    atol = np.asarray(atol, dtype=float)
    event = _event_function(system, mode, 0.1 * atol[1])
    y = np.array(y0, dtype=float)
    t = t0
    g, direction = event if event is not None else (None, 0.0)
    g_old = g(t, y) if g is not None else 0.0
    times, ends, hs, orders, chunks = [t0], [], [], [], []
    used, status, istate = 0, 0, 1
    step = _lsoda_step
    while True:
        y, t_new, istate = step(f, y, t, t1, rtol, atol, 5, istate, rwork, iwork, jac, 1, (), 1,
                                (), state_doubles, state_ints)
        if type(y) is not np.ndarray or y.dtype != np.float64 or not y.flags.c_contiguous:
            raise TypeError("scipy's LSODA returned an unexpected state array")
        if istate < 0:
            status = -1
            break
        istate = 2
        t_old, t = t, float(t_new)
        # the Nordsieck history of the step, as scipy's LSODA._dense_output_impl takes it
        order = int(iwork[13])
        h = rwork[11]
        chunk = rwork[20:20 + (order + 1) * n].copy()
        if iwork[14] < order:
            chunk[order * n:] *= (h / rwork[10]) ** iwork[13]
        t_record = t
        if g is not None:
            g_new = g(t, y)
            if (direction > 0 and g_old <= 0 <= g_new) or (direction < 0 and g_old >= 0 >= g_new):
                from scipy.optimize import brentq

                # a C-ordered copy as scipy's: np.dot sums in the same order
                sol = LsodaDenseOutput(t_old, t, h, order,
                                       chunk.reshape((n, order + 1), order="F").copy())
                t_record = brentq(lambda s: g(s, sol(s)), t_old, t, xtol=4 * _EPS, rtol=4 * _EPS)
                y = sol(t_record)
                status = 1
            g_old = g_new
        if len(times) == 1 or times[-1] != t_record:   # solve_ivp drops a step that did not
            times.append(t_record)                      # advance
            ends.append(t)
            hs.append(h)
            orders.append(order)
            chunks.append(chunk)
        if status == 1:
            t = t_record
            break
        if t >= t1:
            break
    if status < 0:
        return None, t, y, int(iwork[11])
    y_end = np.array(y, dtype=float)
    starts_arr = np.zeros(len(chunks), dtype=np.int64)
    for j, ch in enumerate(chunks):
        starts_arr[j] = used
        used += ch.size
    history = _LsodaHistory(np.asarray(times), np.asarray(ends), np.asarray(hs),
                            np.asarray(orders, dtype=np.int64), starts_arr,
                            np.concatenate(chunks) if chunks else np.zeros(0), n)
    seg = Segment(t0, t, mode, np.array(y0, dtype=float), np.asarray(y_end, dtype=float),
                  len(hs), int(iwork[11]), int(iwork[12]), status, history)
    return seg, t, y_end, int(iwork[11])


def _solve_scipy(system, t0, t1, y0, mode, method, rtol, atol, max_step):
    """One segment with scipy's solve_ivp (BDF, Radau, or LSODA without the fast driver)."""
    event = _event_function(system, mode, 0.1 * atol[1])
    events = None
    if event is not None:
        g, direction = event
        g.terminal, g.direction = True, direction
        events = [g]
    sol = solve_ivp(system.rhs(mode), (t0, t1), y0, method=method, rtol=rtol, atol=atol,
                    events=events, dense_output=True, max_step=max_step,
                    jac=system.jacobian_function(mode))
    if sol.status < 0 or not np.all(np.isfinite(sol.y)):
        return None, float(sol.t[-1]), sol.y[:, -1], sol.message
    seg = Segment(t0, float(sol.t[-1]), mode, np.array(y0, dtype=float), sol.y[:, -1].copy(),
                  len(sol.t) - 1, sol.nfev, sol.njev, sol.status, sol.sol)
    return seg, float(sol.t[-1]), sol.y[:, -1].copy(), None


# -- the compiled driver ---------------------------------------------------------------------
# args of the problem functions: (mode, tables, work), work = (diag, jacobian scale, two work
# vectors, [speed resolution], scratch state)
@njit(cache=True, inline="always")
def _fun(t, y, args, dy):
    """:func:`.rhs.derivatives`, calling the column evaluation directly (one call less per
    evaluation: it is called ten thousand times per second simulated), inlined into the
    solver's Newton iteration.  The column evaluation itself stays a call: inlined here too it
    made the integration 8 % faster and the first (cold) compile 60-110 s longer, which every
    fresh install and CI run pays (measured 77 against 140-187 s)."""
    zero = args[0] * 0
    rhs.evaluate_column(t, y[:, None], zero, args[0], args[1], dy[:, None], args[2][0],
                        zero + rhs.RATES)


@njit(cache=True)
def _jac(t, y, f, args, jac):
    """The columns of the dynamic states (forward differences, :func:`.rhs.jacobian_at`)."""
    work = args[2]
    rhs.jacobian_at(t, y, f, args[0], args[1], work[1], work[2], work[3], work[0], jac)


_tolerance = jit(stick_tolerance)


@njit(cache=True)
def _margin(t, y, args):
    """(F_req, F_brk + tolerance) at rest (:meth:`.system.PneumaticSystem.stick_margin`)."""
    work = args[2]
    hold, brk = rhs.stick_margin(t, y, args[1], work[2], work[3], work[0])
    return hold, brk + _tolerance(brk)


@njit(cache=True, inline="always")
def _event(t, y, args):
    """The event function of the mode (see :func:`_event_function`): slip ends when the
    motion has reversed by the speed resolution, sticking at the break-away."""
    mode = args[0]
    if mode == rhs.FORWARD or mode == rhs.BACKWARD:
        return mode * y[1] + args[2][4][0]
    if mode == rhs.STICK:
        hold, brk = _margin(t, y, args)
        return abs(hold) - brk
    return 1.0


@njit(cache=True)
def _growth(t, y, jac, args):
    """The growth rate of the BDF's growth limit (:mod:`sealsim.ode.bdf`) [1/s]: the piston's
    own velocity feedback ∂(dv/dt)/∂v where it is positive, a friction that falls with speed
    (0 at rest and for a prescribed motion, where dv/dt = 0).

    Why: a slip that breaks away from rest starts on the falling mixed-lubrication branch of
    a seal's friction table, F ≈ F_brk − k·√v, so v' = a₀ + c·√v with a₀ (the break-away
    tolerance over the mass, ~2e-3 m/s²) tiny and ∂(dv/dt)/∂v unbounded towards v = 0⁺ (the
    table caps it below its slowest speed, 0.1 µm/s: 2.3e5 1/s at rest in
    cylinder_32_fe.toml).  scipy's initial step, 4.5e-5 s there, gives c·λ ≈ 8.7: the
    implicit step reversed v (the Newton iteration was accepted at v = −0.85 µm/s, all of it
    below the speed tolerance, 0.3 mm/s) and the slip ran backwards to its reversal event,
    in 46 of the run's 262 segments.  With the limit the first steps are ~2.6 µs and grow as
    the motion leaves the steep branch (λ falls as 1/(2t) for v ∝ t²); the physics is
    unchanged.  The velocity's own entry is the rate: the other states couple to v through
    the stable chamber and end-stop dynamics."""
    return max(jac[1, 1], 0.0)


@njit(cache=True)
def _renew(t, y, f, args, jac):
    """The growth rate renewed with the velocity's column of the Jacobian alone (the
    :func:`_growth` the BDF's growth limit needs at almost every early step of a break-away;
    :mod:`sealsim.ode.bdf`): one right-hand side instead of one per dynamic state."""
    work = args[2]
    return max(rhs.velocity_column_at(t, y, f, args[0], args[1], work[1], work[2], work[3],
                                      work[0], jac), 0.0)


_SOLVER = bdf.compile_bdf("pneumatic", _fun, _jac, _event, _growth, _renew)
_bdf_start, _bdf_step, _bdf_locate = _SOLVER.start, _SOLVER.step, _SOLVER.locate

#: results of :func:`run_interval`
DONE, SEGMENTS_FULL, STEP_FAILED, CHATTERING = 0, 1, 2, 3


@njit(cache=True)
def _next_mode_at_rest(t, y, args):
    hold, brk = _margin(t, y, args)
    if abs(hold) <= brk:                 # resolve_stick of sealsim.friction.hybrid
        return rhs.STICK
    return rhs.FORWARD if hold > 0 else rhs.BACKWARD


@njit(inline="always")
def _borrowed_arrays(tables, work, ws):
    """The tables, work arrays and solver workspace of :func:`run_interval` as
    :func:`._jit.borrowed` arrays: the calls of the right-hand side, its Jacobian and the event
    function in the loop then count no references (10 % of the integration's time)."""
    tables = rhs.borrowed_tables(tables)
    work = (borrowed(work[0]), borrowed(work[1]), borrowed(work[2]), borrowed(work[3]),
            borrowed(work[4]), borrowed(work[5]))
    ws = (borrowed(ws[0]), borrowed(ws[1]), borrowed(ws[2]), borrowed(ws[3]), borrowed(ws[4]))
    return tables, work, ws


@njit(cache=True)
def run_interval(t, t_end, y, mode, tables, work, ws, grid, k, samples, sample_modes, seg_t,
                 seg_i, seg_y, recent):
    """Integrate from t to t_end (no valve switch inside) with the compiled BDF method.

    Segments end at stick/slip events (located on the dense output, as solve_ivp's events);
    the mode then switches as in :func:`integrate`.  ``y`` (in/out) is the state;
    ``samples[k:]`` (grid points × states) and ``sample_modes`` are filled for the grid points
    passed; per segment ``seg_t`` (start, end), ``seg_i`` (mode, steps, RHS evaluations,
    Jacobians, ended by an event) and ``seg_y`` (state at its end).  ``recent`` holds the times
    of the last transitions (chattering guard; recent[-1] is the ring index).  Returns
    (result, t, mode, k, segments): :data:`DONE`, :data:`SEGMENTS_FULL` (call again),
    :data:`STEP_FAILED` or :data:`CHATTERING`."""
    tables, work, ws = _borrowed_arrays(tables, work, ws)     # all held by the caller
    y, grid, samples, sample_modes = borrowed(y), borrowed(grid), borrowed(samples), \
        borrowed(sample_modes)                              # a sample row: no count either
    seg_t, seg_i, seg_y, recent = borrowed(seg_t), borrowed(seg_i), borrowed(seg_y), \
        borrowed(recent)
    s, iv, y_new = ws[0], ws[1], ws[2]
    y_tmp = work[5]
    cap = seg_t.shape[0]
    nseg = 0
    ring = recent.shape[0] - 1
    while t < t_end:
        if nseg == cap:
            return SEGMENTS_FULL, t, mode, k, nseg
        args = (mode, tables, work)
        steps0, nfev0, njev0 = iv[bdf.I_NSTEPS], iv[bdf.I_NFEV], iv[bdf.I_NJEV]
        _bdf_start(ws, t, y, t_end, args)
        direction = 0.0
        if mode == rhs.FORWARD or mode == rhs.BACKWARD:
            direction = -1.0
        elif mode == rhs.STICK:
            direction = 1.0
        g_old = _event(t, y, args) if direction != 0.0 else 1.0
        seg_t[nseg, 0] = t
        event = False
        t_stop = t
        while True:
            if _bdf_step(ws, args) != bdf.OK:
                for i in range(y.shape[0]):
                    y[i] = y_new[i]
                return STEP_FAILED, s[bdf.S_T], mode, k, nseg
            t_new = s[bdf.S_T]
            t_stop = t_new
            if direction != 0.0:
                g_new = _event(t_new, y_new, args)
                if (direction > 0.0 and g_old <= 0.0 <= g_new) or (
                        direction < 0.0 and g_old >= 0.0 >= g_new):
                    t_stop = _bdf_locate(ws, args, g_old, g_new, y_tmp)
                    event = True
                g_old = g_new
            while k < grid.shape[0] and grid[k] < t_stop:     # the output grid
                bdf.dense(ws, grid[k], samples[k])
                if mode == rhs.STICK:
                    samples[k, 1] = 0.0
                sample_modes[k] = mode
                k += 1
            if event:
                bdf.dense(ws, t_stop, y)
                break
            if t_new >= t_end:
                for i in range(y.shape[0]):
                    y[i] = y_new[i]
                break
        seg_t[nseg, 1] = t_stop
        seg_i[nseg, 0] = mode
        seg_i[nseg, 1] = iv[bdf.I_NSTEPS] - steps0
        seg_i[nseg, 2] = iv[bdf.I_NFEV] - nfev0
        seg_i[nseg, 3] = iv[bdf.I_NJEV] - njev0
        seg_i[nseg, 4] = 1 if event else 0
        for i in range(y.shape[0]):
            seg_y[nseg, i] = y[i]
        nseg += 1
        t = t_stop
        if event:
            if mode == rhs.FORWARD or mode == rhs.BACKWARD:
                y[1] = 0.0
                mode = _next_mode_at_rest(t, y, (mode, tables, work))
            else:
                hold, _ = _margin(t, y, args)
                mode = rhs.FORWARD if hold > 0 else rhs.BACKWARD
            # chattering guard: more than _MAX_SWITCHES_PER_MS transitions within 1 ms
            j = int(recent[ring])
            oldest = recent[j]
            recent[j] = t
            recent[ring] = (j + 1) % ring
            if oldest > t - 1e-3:
                return CHATTERING, t, mode, k, nseg
    return DONE, t, mode, k, nseg


def solver_workspace(system) -> tuple[tuple, tuple]:
    """The BDF workspace (:func:`sealsim.ode.bdf.workspace`) and the right-hand side's work
    arrays of a run of ``system``: the ``ws`` and ``work`` of :func:`run_interval`."""
    rtol = system.case.solver.rtol
    atol = system.tolerances(rtol)
    n, ndyn = system.n_states, system.n_dynamic
    ws = bdf.workspace(n, ndyn, rtol, atol, system.case.solver.max_step)
    work = (np.zeros((system.n_diag, 1)), system.tolerances(1.0)[:ndyn].copy(), np.zeros(n),
            np.zeros(n), np.array([0.1 * atol[1]]), np.zeros(n))
    return ws, work


def _integrate_compiled(system, progress, sampler) -> list[Segment]:
    """All valve intervals with :func:`run_interval`; fills ``sampler`` (a
    :class:`.results.Sampler`) with the samples on its grid; any other ``on_segment`` callable
    is called with every segment (they carry no dense output)."""
    if not hasattr(sampler, "store"):
        segments = _integrate_compiled(system, progress, _EndOnly(system.duration))
        if sampler is not None:
            for seg in segments:
                sampler(seg)
        return segments
    end = system.duration
    n = system.n_states
    ws, work = solver_workspace(system)
    grid = sampler.grid
    samples = sampler.buffer(n)
    sample_modes = np.zeros(grid.size, dtype=np.int64)
    cap = 256
    seg_t, seg_i, seg_y = np.zeros((cap, 2)), np.zeros((cap, 5), dtype=np.int64), \
        np.zeros((cap, n))
    recent = np.full(_MAX_SWITCHES_PER_MS + 2, -np.inf)
    recent[-1] = 0.0
    y = system.initial_state()
    t = 0.0
    mode = _initial_mode(system, t, y)
    breaks = sorted({float(a) for a in system.spool.arrivals if 0.0 < a < end} | {end})
    # the segments of every call, made Segments once at the end: per call, the numpy steps of
    # their assembly cost about as much as the Segments themselves
    chunks: list[tuple] = []
    k = 0
    y_first = y.copy()
    for t_next in breaks:
        if t_next <= t + 1e-12 * max(end, 1.0):
            continue
        while True:
            result, t, mode, k, nseg = run_interval(t, t_next, y, mode, system.tables, work, ws,
                                                    grid, k, samples, sample_modes, seg_t,
                                                    seg_i, seg_y, recent)
            if nseg:
                chunks.append((seg_t[:nseg].copy(), seg_i[:nseg].copy(), seg_y[:nseg].copy()))
            if result == DONE:
                break
            if result == STEP_FAILED or not np.all(np.isfinite(y)):
                y_fail = y if np.all(np.isfinite(y)) else _next_start(chunks, y_first)
                raise ConvergenceError(
                    f"pneumatic simulation: the integrator (compiled BDF) failed at "
                    f"{_where(system, float(t), y_fail, mode)}: the step size became too "
                    "small; try a smaller solver.max_step or solver.method = \"LSODA\"")
            if result == CHATTERING:
                raise ConvergenceError(
                    f"pneumatic simulation: stick/slip chattering (more than "
                    f"{_MAX_SWITCHES_PER_MS} transitions within 1 ms) at "
                    f"{_where(system, t, y, mode)}; the contact cannot decide between sticking "
                    "and sliding -- check the friction parameters")
        if progress is not None:
            progress(t, end)
    segments = _segments(chunks, y_first)
    # the last grid point (the end) from the final state
    while k < grid.size:
        samples[k] = y
        if mode == rhs.STICK:
            samples[k, 1] = 0.0
        sample_modes[k] = mode
        k += 1
    sampler.store(grid, samples.T, sample_modes)
    return segments


def _next_start(chunks, y_first) -> np.ndarray:
    """The state the segment after the recorded ones (``chunks`` of :func:`_segments`) starts
    from."""
    if not chunks:
        return y_first
    _, info, ends = chunks[-1]
    y = ends[-1].copy()
    if info[-1, 4] != 0 and info[-1, 0] in (rhs.FORWARD, rhs.BACKWARD):
        y[1] = 0.0                    # the next segment starts at rest after the slip's end
    return y


def _segments(chunks, y_first) -> list[Segment]:
    """The :class:`Segment` s of :func:`run_interval`'s records ``chunks`` (per call: times,
    info, end states) in order; ``y_first`` is the state the first one starts from.  A
    segment starts where the one before ended, at rest after a slip that ended by an event."""
    if not chunks:
        return []
    times = np.concatenate([c[0] for c in chunks])
    info = np.concatenate([c[1] for c in chunks])
    ends = np.concatenate([c[2] for c in chunks])
    starts = np.empty_like(ends)
    starts[0] = y_first
    starts[1:] = ends[:-1]
    slip_end = (info[:, 4] != 0) & ((info[:, 0] == rhs.FORWARD) | (info[:, 0] == rhs.BACKWARD))
    starts[1:, 1][slip_end[:-1]] = 0.0
    times, info = times.tolist(), info.tolist()
    return [Segment(times[j][0], times[j][1], info[j][0], starts[j], ends[j], info[j][1],
                    info[j][2], info[j][3], info[j][4]) for j in range(len(times))]


class _EndOnly:
    """A sample grid of one point, the end (a run without an output table)."""

    def __init__(self, end: float):
        self.grid = np.array([float(end)])

    def buffer(self, n_states: int) -> np.ndarray:
        return np.zeros((1, n_states))

    def store(self, times, states, modes) -> None:
        pass


def _initial_mode(system, t, y) -> int:
    if system.position is not None:
        return rhs.PRESCRIBED
    if system.sticky:
        return system.next_mode_at_rest(t, y)
    return rhs.FREE


def integrate(system, progress=None, on_segment=None) -> list[Segment]:
    """Integrate a :class:`.system.PneumaticSystem` segment by segment (valve switches,
    stick/slip transitions); ``on_segment(segment)`` and ``progress(t, end)`` after every
    segment (the compiled method: ``progress`` after every valve interval; a
    :class:`.results.Sampler` as ``on_segment`` receives the samples)."""
    case = system.case
    method = case.solver.method
    if method == "compiled":
        return _integrate_compiled(system, progress, on_segment)
    end = system.duration
    rtol = case.solver.rtol
    atol = system.tolerances(rtol)
    max_step = case.solver.max_step
    y = system.initial_state()
    t = 0.0
    breaks = sorted({float(a) for a in system.spool.arrivals if 0.0 < a < end} | {end})
    mode = _initial_mode(system, t, y)
    segments: list[Segment] = []
    recent: list[float] = []
    while t < end * (1 - 1e-12):
        t_next = next(b for b in breaks if b > t + 1e-12 * max(end, 1.0))
        try:
            if method == "LSODA" and _lsoda_step is not None:
                seg, t_fail, y_fail, _ = _solve_lsoda(system, t, t_next, y, mode, rtol, atol,
                                                      max_step)
                message = "Unexpected istate in LSODA."
            else:
                seg, t_fail, y_fail, message = _solve_scipy(system, t, t_next, y, mode, method,
                                                            rtol, atol, max_step)
        except (ValueError, FloatingPointError, ZeroDivisionError) as exc:
            raise ConvergenceError(f"pneumatic simulation failed at "
                                   f"{_where(system, t, y, mode)}: {exc}") from None
        if seg is None or not np.all(np.isfinite(seg.y1)):
            y_fail = y_fail if np.all(np.isfinite(y_fail)) else y
            raise ConvergenceError(
                f"pneumatic simulation: the integrator ({method}) failed at "
                f"{_where(system, float(t_fail), y_fail, mode)}: {message}; try a smaller "
                "solver.max_step or a different solver.method")
        segments.append(seg)
        if on_segment is not None:
            on_segment(seg)
        y = seg.y1.copy()
        t = seg.t1
        if seg.status == 1:                      # stick/slip event
            if mode in (rhs.FORWARD, rhs.BACKWARD):
                y[1] = 0.0
                mode = system.next_mode_at_rest(t, y)
            else:
                hold, _ = system.stick_margin(t, y)
                mode = rhs.FORWARD if hold > 0 else rhs.BACKWARD
            recent = [r for r in recent if r > t - 1e-3] + [t]
            if len(recent) > _MAX_SWITCHES_PER_MS:
                raise ConvergenceError(
                    f"pneumatic simulation: stick/slip chattering ({len(recent)} transitions "
                    f"within 1 ms) at {_where(system, t, y, mode)}; the contact cannot decide "
                    "between sticking and sliding -- check the friction parameters")
        if progress is not None:
            progress(t, end)
    return segments
