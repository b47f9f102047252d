"""Incremental solution of a seal model along a load path, with automatic cutback.

A load path is a list of :class:`LoadStep` (squeeze, pressure, temperature and time targets,
each ramped linearly from the previous state in a number of increments). Each increment is
solved by Newton–Raphson iterations on FElupe's assembled items and partitioned solver
(:mod:`felupe.solve`); the wetted surface of the fluid pressure is updated before every
iteration, and an increment has converged when the residual is small *and* the wetted surface
no longer changes. An increment that does not converge is restored and cut in half, down
to ``0.5 ** max_cutbacks`` of the step's increment; then a
:class:`~sealsim.errors.ConvergenceError` names the step, the increment and the load (squeeze,
pressure, temperature) it failed at. After a cutback the increment grows back by 1.5 after
every two increments that converged in at most 10 Newton iterations and doubles where the load
reaches a point of the step's nominal grid, up to the nominal increment; no increment steps
over a grid point (:data:`GROWTH_FACTOR`).

The linear systems of the Newton iterations are solved by :class:`LinearSolver`: PARDISO
(Intel MKL, through ``pypardiso``, optional) with its symbolic analysis (fill-reducing
ordering) kept for every sparsity pattern and only the numerical factorisation repeated, or
without it a compiled LU (:mod:`.sparse_lu`) that likewise keeps SuperLU's ordering of the
symmetric pattern and the symbolic factorisation per pattern (the stiffness matrix is
structurally symmetric and nearly symmetric: only the follower pressure is not), or scipy's
SuperLU in every iteration; all give the reference solution (``spsolve``) to round-off.

Every converged increment is logged in ``model.increment_log`` (step, load fraction,
increment, Newton iterations, cutbacks before it).
"""

from __future__ import annotations

import functools
import glob
import math
import hashlib
import os
import sys
import warnings
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass

import felupe as fem
import numpy as np
from scipy.sparse.linalg import spsolve

from sealsim.errors import ConvergenceError
from sealsim.structure.model import LoadState, SealModel
from sealsim.structure.sparse_lu import HAVE_COMPILED_LU, PatternLU, superlu_factor
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["DEFAULT_LINEAR_SOLVER", "LINEAR_SOLVERS", "LinearSolver", "LoadStep",
           "describe_state", "solve"]

LINEAR_SOLVERS = ("auto", "pardiso", "compiled", "superlu", "reference")
"""Backends of :class:`LinearSolver`: ``auto`` (PARDISO if installed, else the compiled LU if
numba is, else SuperLU), ``pardiso``, ``compiled`` (:class:`~.sparse_lu.PatternLU`),
``superlu`` and ``reference`` (scipy ``spsolve`` with its default ordering, the implementation
the others are tested against)."""

#: Backend used when :func:`solve` is not told one: the environment variable
#: ``SEALSIM_FE_LINEAR_SOLVER`` (one of :data:`LINEAR_SOLVERS`, read at import, so that map
#: worker processes see it too), else ``"auto"``. Benchmarks set ``"reference"`` for their
#: baseline.
DEFAULT_LINEAR_SOLVER = os.environ.get("SEALSIM_FE_LINEAR_SOLVER", "auto")


@dataclass(frozen=True)
class LoadStep:
    """A step of the load path: ramp to the given targets (None keeps the current value).

    Parameters
    ----------
    name : str
        Label used in messages ("squeeze", "pressure", "temperature").
    squeeze : float, optional
        Target squeeze [-].
    pressure : float, optional
        Target fluid pressure [Pa].
    temperature : float, optional
        Target temperature [K].
    duration : float
        Duration of the step [s] (viscoelastic material; 0 = instantaneous).
    increments : int
        Number of equal increments.
    record : str
        "all": a result for every increment, "end": only the last one, "none".
    """

    name: str
    squeeze: float | None = None
    pressure: float | None = None
    temperature: float | None = None
    duration: float = 0.0
    increments: int = 10
    record: str = "all"

    def target(self, start: LoadState) -> LoadState:
        return LoadState(
            start.squeeze if self.squeeze is None else self.squeeze,
            start.pressure if self.pressure is None else self.pressure,
            start.temperature if self.temperature is None else self.temperature,
            start.time + self.duration,
        )


class LinearSolver:
    """Direct solver of the Newton systems K du = r, reusing work per sparsity pattern.

    Only one or two sparsity patterns occur along a load path, so PARDISO's analysis phase
    (METIS nested-dissection ordering and symbolic factorisation) runs once per pattern and each
    Newton iteration runs the numerical factorisation and solve only (phase 23, single-threaded:
    deterministic and no oversubscription of the map worker processes). PARDISO runs with MKL's
    defaults for non-symmetric matrices (METIS ordering, scaling, weighted matching, pivot
    perturbation 1e-13) except that iterative refinement runs only when pivots were perturbed
    (pypardiso's implicit defaults refine twice in every solve: 15 % of the time, the same
    solution to 1e-12). A matrix with the pattern arrays of the previous call (the
    :class:`~.assembly.SystemAssembly` keeps them) skips hashing its pattern. SuperLU (scipy,
    backend ``superlu``): minimum-degree ordering of A + Aᵀ with symmetric-mode diagonal
    pivoting (threshold 0.1), about 3× faster than ``spsolve``'s default COLAMD ordering on
    these matrices; scipy cannot keep a SuperLU symbolic factorisation, and re-using the
    ordering alone gained nothing (measured). The compiled LU (``compiled``, the default
    without PARDISO) keeps that ordering and the symbolic factorisation per pattern and runs
    the numerical LU with the same diagonal pivot threshold, about 2.5× faster than SuperLU
    (4552 dofs of a lip seal, medians of 15 alternating runs on a shared machine: 28 ms
    against 70 ms per factorisation; 1.1-1.3× on the medium O-ring's denser factors); a
    matrix whose diagonal pivot fails the threshold is given to SuperLU (counted in
    ``fallbacks``), and so is every matrix of a pattern whose factors are dense enough for
    SuperLU's supernodes to be faster (:data:`~.sparse_lu.DENSE_FLOPS_PER_DOF`: the
    anti-rolling spring's dense block).

    Parameters
    ----------
    backend : {"auto", "pardiso", "compiled", "superlu", "reference"}
        See :data:`LINEAR_SOLVERS`.
    max_patterns : int
        Analyses kept (PARDISO, compiled; least recently used are released).

    Examples
    --------
    >>> import scipy.sparse as sp
    >>> A = sp.csr_matrix(np.array([[4.0, 1.0], [1.0, 3.0]]))
    >>> LinearSolver("superlu")(A, np.array([1.0, 2.0])).round(6).tolist()
    [0.090909, 0.636364]
    """

    def __init__(self, backend: str = "auto", max_patterns: int = 4):
        if backend not in LINEAR_SOLVERS:
            raise ValueError(f"linear solver {backend!r}: choose one of {LINEAR_SOLVERS}")
        if backend == "pardiso" and _pypardiso() is None:
            raise ImportError("linear solver 'pardiso' needs pypardiso (pip install pypardiso)")
        if backend == "compiled" and not HAVE_COMPILED_LU:
            raise ImportError("linear solver 'compiled' needs numba")
        if backend == "auto":
            backend = ("pardiso" if _pypardiso() is not None
                       else "compiled" if HAVE_COMPILED_LU else "superlu")
        self.backend = backend
        self.max_patterns = int(max_patterns)
        self._analyses: OrderedDict = OrderedDict()
        self._last = (None, None, None)  # (indptr, indices, key) of the last call
        self.analyses = 0  # symbolic analyses run (PARDISO, compiled)
        self.fallbacks = 0  # matrices the compiled LU left to SuperLU (a failed pivot)

    def __call__(self, A, b):
        b = np.asarray(b, dtype=float).ravel()
        if self.backend == "reference":
            return spsolve(A, b)
        if self.backend == "superlu":
            return superlu_factor(A).solve(b)
        if self.backend == "compiled":
            return self._solve_compiled(A, b)
        return self._solve_pardiso(A, b)

    def _pattern_key(self, A):
        """A as sorted float CSR and the key of its pattern (not hashed again for the
        pattern arrays of the previous call)."""
        A = A.tocsr()
        if not A.has_sorted_indices:
            A.sort_indices()
        A = A.astype(float, copy=False)
        indptr, indices, key = self._last
        if A.indptr is not indptr or A.indices is not indices:
            key = (A.shape[0], hashlib.sha1(A.indptr).hexdigest(),
                   hashlib.sha1(A.indices).hexdigest())
            self._last = (A.indptr, A.indices, key)
        return A, key

    def _solve_compiled(self, A, b):
        A, key = self._pattern_key(A)
        lu = self._analyses.get(key)
        if lu is None:
            lu = self._analyses[key] = PatternLU(A)
            self.analyses += 1
            while len(self._analyses) > self.max_patterns:
                self._analyses.popitem(last=False)
        else:
            self._analyses.move_to_end(key)
        if not lu.dense and lu.factorize(A):
            return lu.solve(b)
        self.fallbacks += not lu.dense
        return superlu_factor(A).solve(b)

    def _solve_pardiso(self, A, b):
        A, key = self._pattern_key(A)
        solver = self._analyses.get(key)
        pypardiso = _pypardiso()
        try:
            if solver is None:
                solver = pypardiso.PyPardisoSolver(mtype=11)  # real, non-symmetric
                solver.libmkl.MKL_Set_Num_Threads(1)
                # iparm (1-based): own values, METIS, pivot perturbation 1e-13, scaling,
                # weighted matching; iparm 8 = 0: refinement only after perturbed pivots
                for number, value in ((1, 1), (2, 2), (10, 13), (11, 1), (13, 1)):
                    solver.set_iparm(number, value)
                solver._check_A(A)
                solver.set_phase(11)  # analysis: ordering + symbolic factorisation
                solver._call_pardiso(A, np.zeros((A.shape[0], 1)))
                self.analyses += 1
                self._analyses[key] = solver
                while len(self._analyses) > self.max_patterns:
                    self._analyses.popitem(last=False)[1].free_memory(everything=True)
            else:
                self._analyses.move_to_end(key)
            solver.set_phase(23)  # numerical factorisation + solve
            return solver._call_pardiso(A, np.asfortranarray(b.reshape(-1, 1))).ravel()
        except pypardiso.PyPardisoError as exc:  # singular matrix: the caller cuts back
            self._analyses.pop(key, None)
            self._last = (None, None, None)
            raise np.linalg.LinAlgError(f"PARDISO error {exc.value}") from None

    def release(self) -> None:
        """Free the memory of all kept analyses (PARDISO's, the compiled LU's)."""
        while self._analyses:
            analysis = self._analyses.popitem()[1]
            if self.backend == "pardiso":
                analysis.free_memory(everything=True)


@functools.lru_cache(maxsize=1)
def _pypardiso():
    """The pypardiso module, or None (imported on first use: it loads Intel MKL).

    Every ``PyPardisoSolver`` (one per sparsity pattern and load path, and one at import)
    looks for MKL's runtime library with ``ctypes.util.find_library`` and then a recursive
    search of ``sys.prefix`` (about 0.2 s each) unless ``PYPARDISO_MKL_RT`` names it: it is
    set here (inherited by map worker processes) from a direct look into ``sys.prefix``.
    """
    if "PYPARDISO_MKL_RT" not in os.environ:
        found = [path for pattern in ("lib/libmkl_rt.so*", "lib/libmkl_rt*.dylib",
                                      "Library/bin/mkl_rt*.dll")
                 for path in glob.glob(os.path.join(sys.prefix, pattern))]
        if found:
            os.environ["PYPARDISO_MKL_RT"] = min(found, key=len)
    try:
        import pypardiso
    except (ImportError, OSError):  # not installed, or the MKL library is missing
        return None
    os.environ.setdefault("PYPARDISO_MKL_RT", pypardiso.ps.libmkl._name)
    return pypardiso


#: Automatic incrementation after a cutback. An increment that fails Newton is halved; the
#: size it converged at then grows by GROWTH_FACTOR after EASY_INCREMENTS consecutive
#: increments that converged within EASY_ITERATIONS Newton iterations (Abaqus/Standard's
#: automatic incrementation: the increment grows by 1.5 after two consecutive increments
#: converged in fewer than I_G iterations, Abaqus Analysis User's Guide, "Convergence criteria
#: for nonlinear problems", *CONTROLS, PARAMETERS=TIME INCREMENTATION; "few" as in FEBio's
#: auto time stepper, which grows the step while the iterations stay at or below
#: opt_iter = 10, FEBio User's Manual 3.4, §3.3.2: these contact increments take 3-9
#: iterations at any size, so Abaqus's I_G = 4 would keep most of them small). Where the load
#: reaches a point of the step's nominal grid the size doubles, as before. Never beyond the
#: nominal increment and never over a grid point: recorded states, and a viscoelastic path's
#: time steps, end there. Before, the cut-back size was kept until the load reached the grid
#: and only doubled there (the FE lip table of the tests' lip_fe build: 198 increments, 1015
#: Newton iterations; now 140 and 719).
GROWTH_FACTOR = 1.5
EASY_ITERATIONS = 10
EASY_INCREMENTS = 2


def describe_state(state: LoadState) -> str:
    """Human-readable load, e.g. 'squeeze 20 %, pressure 3.5 bar, temperature 20 degC'."""
    return (f"squeeze {state.squeeze * 100:.4g} %, pressure {state.pressure / 1e5:.4g} bar, "
            f"temperature {state.temperature - ZERO_CELSIUS_K:.4g} degC")


def _assemble(model: SealModel):
    """Residual vector and tangent matrix of all items (FElupe assembly)."""
    field = model.field
    f = None
    K = None
    for item in model.items:
        item.field.link(field)
        r = item.assemble.vector(field=item.field)
        k = item.assemble.matrix()
        f = r if f is None else f + r
        K = k if K is None else K + k
    return np.asarray(f.toarray()).ravel(), K.tocsr()


def _solve_partitioned(field, K11, system, f, ext0, linear):
    """Newton correction of the partitioned system (as :func:`felupe.solve.solve`):
    K11 du1 = -r1 - K10 (ext0 - u0), du0 = ext0 - u0."""
    u = field[0].values
    du0 = ext0 - u.ravel()[system.dof0]
    du = np.empty(u.size)
    du[system.dof1] = linear(K11, -f[system.dof1] - system.coupling(du0))
    du[system.dof0] = du0
    return du.reshape(u.shape)


def _newton(model: SealModel, ext0, tol: float, maxiter: int, update_wetting: bool,
            linear: LinearSolver) -> int:
    """Newton–Raphson iterations with FElupe's partitioned solver.

    The wetted surface of the fluid pressure (its edges follow the contact edges) is
    re-evaluated before every iteration until it has settled -- its length changes by less
    than 1e-4 of the cord diameter -- and is then frozen, so that an edge node flickering in
    and out of contact cannot keep Newton from converging. Convergence: settled wetted surface
    and a residual of the free dofs below ``tol`` relative to the reactions. Raises
    NewtonConvergenceError otherwise (the caller cuts the increment back).
    """
    scale = 1e-6 * model.force_scale
    field = model.field
    wet_tol = 1e-4 * model.assembly.seal.cord_diameter
    frozen = not update_wetting
    for iteration in range(maxiter):
        if not frozen and iteration > 0:
            # once the wetted surface has settled (or after 8 iterations) it is frozen, so
            # that a flickering edge node cannot keep Newton from converging
            frozen = model.update_wetting() <= wet_tol or iteration >= 8
        with np.errstate(all="ignore"):
            if model.system is not None:
                f, K11 = model.system.assemble(model.items, field)
            else:
                f, K = _assemble(model)
        if not np.all(np.isfinite(f)):
            raise fem.NewtonConvergenceError(f"non-finite residual in iteration {iteration}")
        if iteration > 0:
            fnorm = np.linalg.norm(f[model.dof1]) / max(np.linalg.norm(f[model.dof0]), scale)
            if fnorm < tol and frozen:
                for item in model.items:
                    item.results.update_statevars()
                return iteration
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            if model.system is not None:
                du = _solve_partitioned(field, K11, model.system, f, ext0, linear)
            else:
                system = fem.solve.partition(field, K, model.dof1, model.dof0, f)
                du = fem.solve.solve(*system, ext0, solver=linear)
        if not np.all(np.isfinite(du)):
            raise fem.NewtonConvergenceError(f"singular system in iteration {iteration}")
        field[0].values[:] += du.reshape(field[0].values.shape)
    raise fem.NewtonConvergenceError(f"not converged in {maxiter} iterations")


def _increment(model: SealModel, target: LoadState, tol, maxiter, linear):
    dt = target.time - model.state.time
    ext0 = model.set_load(target, dt)
    model.update_wetting()
    iterations = _newton(model, ext0, tol, maxiter, update_wetting=True, linear=linear)
    model.newton_iterations.append(iterations)
    model.state = target
    return iterations


def solve(model: SealModel, steps: list[LoadStep], *,
          on_state: Callable | None = None, tol: float = 1e-8, maxiter: int = 25,
          max_cutbacks: int = 8, linear_solver: str | None = None,
          increment_growth: bool = True) -> list:
    """Drive ``model`` through ``steps``; return the recorded results.

    Parameters
    ----------
    model : SealModel
        The model, in its current state (a fresh model starts unloaded at the installation
        temperature).
    steps : list of LoadStep
        The load path.
    on_state : callable, optional
        ``on_state(model)`` → result object for each recorded state (default
        :func:`sealsim.structure.results.extract`).
    tol : float
        Newton tolerance: norm of the residual of the free dofs relative to the reactions.
    maxiter : int
        Newton iterations per attempt.
    max_cutbacks : int
        An increment is halved at most this many times in a row (smallest increment
        ``0.5 ** max_cutbacks`` of the step's increment).
    linear_solver : str, optional
        Backend of :class:`LinearSolver` (default :data:`DEFAULT_LINEAR_SOLVER`).
    increment_growth : bool
        A cut-back increment grows back after easy increments (:data:`GROWTH_FACTOR`) and
        doubles at the step's nominal grid points; False: the previous control, in which it
        only doubles at the grid points (a path whose converged states depend on the
        increments taken keeps its increments).

    Returns
    -------
    list
        One result per recorded increment.

    Raises
    ------
    ConvergenceError
        If an increment cannot be solved even after ``max_cutbacks`` halvings.
    """
    if on_state is None:
        from sealsim.structure.results import extract as on_state
    records = []
    linear = LinearSolver(linear_solver or DEFAULT_LINEAR_SOLVER)
    try:
        _solve_steps(model, steps, on_state, tol, maxiter, max_cutbacks, linear, records,
                     increment_growth)
    finally:
        linear.release()
    return records


def _material_checkpoint(material):
    """State of a material with history beyond its temperature (None if it has none)."""
    checkpoint = getattr(material, "checkpoint", None)
    return checkpoint() if callable(checkpoint) else None


def _solve_steps(model, steps, on_state, tol, maxiter, max_cutbacks, linear, records,
                 growth=True):
    for number, step in enumerate(steps):
        start = model.state
        target = step.target(start)
        n = max(int(step.increments), 1)
        nominal = 1.0 / n
        smallest = nominal * 0.5 ** max_cutbacks
        size = nominal   # the increment the next one aims at
        grid = 0         # nominal grid points reached
        done = 0.0       # load fraction of the step reached
        easy = 0         # consecutive easy increments since the size last changed
        cutbacks = 0     # failed attempts before the next increment
        while done < 1.0 - 1e-12:
            if growth:
                # the rest of the grid interval in equal increments of at most `size` (no
                # sliver before the grid point)
                end = (grid + 1) / n if grid + 1 < n else 1.0
                parts = max(1, math.ceil((end - done) / size - 1e-9))
                frac = end if parts == 1 else done + (end - done) / parts
                on_grid = parts == 1
            else:
                frac = min(done + size, 1.0)
                on_grid = abs(frac * n - round(frac * n)) < 1e-9
            state = start.interpolate(target, frac)
            cp = model.checkpoint()
            material_cp = _material_checkpoint(model.material)
            try:
                iterations = _increment(model, state, tol, maxiter, linear)
            except (fem.NewtonConvergenceError, ArithmeticError, np.linalg.LinAlgError,
                    RuntimeError, ValueError) as exc:
                model.restore(cp)
                if material_cp is not None:
                    # the material's history (fictive temperature) of the failed attempt
                    model.material.restore(material_cp)
                cutbacks += 1
                tried = frac - done if growth else size
                if tried * 0.5 < smallest * (1 - 1e-9) and (not growth or
                                                            tried <= smallest * (1 + 1e-9)):
                    raise ConvergenceError(
                        f"the FE model did not converge in step {number + 1} "
                        f"({step.name}) at {describe_state(state)} (load fraction "
                        f"{frac:.4g} of the step, increment {tried:.3g} after {max_cutbacks} "
                        f"cutbacks); last converged state: {describe_state(model.state)}. "
                        "Try more increments, a coarser load step, a smaller squeeze or "
                        f"another mesh ({type(exc).__name__}: {str(exc).strip()[:120]})"
                    ) from None
                # halved; with growth at least the smallest increment is tried before giving
                # up, also when growth left the size off the powers of two
                size = max(0.5 * tried, smallest) if growth else 0.5 * size
                easy = 0
                continue
            model.increment_log.append({
                "step": number + 1, "step_name": step.name, "load_fraction": frac,
                "increment": frac - done, "newton_iterations": iterations,
                "cutbacks": cutbacks})
            cutbacks = 0
            done = frac
            if growth and size < nominal:
                easy = easy + 1 if iterations <= EASY_ITERATIONS else 0
                if easy >= EASY_INCREMENTS:
                    size, easy = min(nominal, GROWTH_FACTOR * size), 0
            if on_grid:
                grid += 1
                # at a grid point the cut-back size doubles (the previous control; with growth
                # also between grid points)
                size = min(nominal, 2 * size)
                last = done >= 1.0 - 1e-12
                if step.record == "all" or (step.record == "end" and last):
                    records.append(on_state(model))
