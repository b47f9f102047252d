"""Expensive test fixtures built once per test session, also under pytest-xdist.

Each xdist worker runs its own module fixtures, and the scheduler deals the tests of one module
to both workers at once, so each worker built its own copy (the FE lip table about 64 s, the
cold numba compile of the cylinder model about 60 s, FMUs 10-60 s), or one worker waited idle
on a lock while the other built. A build registered here with ``@session_build(name)`` is
made once per session: tests/conftest.py starts the builds the selected tests need when the
session starts, spread over the workers (each worker takes the builds nobody has started, then
runs tests; a test module waits for the builds of its file, :func:`await_builds`), and the
fixtures read the results back with :func:`built`. Without xdist a fixture builds on first
use.

A build is ``build(folder) -> JSON-able result`` (paths become strings); it writes its files
into ``folder``, which the session keeps until it ends.

The workers do not compile the same numba kernels twice: a cold session (empty
``NUMBA_CACHE_DIR``, every real compile logged per process through ``numba.core.event``)
compiled 263 signatures of sealsim's and the tests' kernels, none of the cached ones in both
workers (repeated were only numba's own overloads, part of each caller's code, and the
deliberately uncached copies of tests/test_pneumatic_compiled.py); the same session with
those caches warm took 237 s less CPU (1253 → 1015 s user, ``/usr/bin/time`` on
``pytest -n 2 --dist loadgroup``, load 7-9, 2026-11-29; still compiled there: the uncached
kernels of test_pneumatic_compiled.py and test_ode_bdf.py, 20 s): the cost of compiling,
not of compiling twice.  The gallery of ``make docs`` compiles nothing after the tests (its
eight ``plot_*.py`` scripts run with that cache: no compile).
"""

from __future__ import annotations

import contextlib
import fnmatch
import inspect
import json
from dataclasses import dataclass
from pathlib import Path

from sealsim.output import json_ready

TESTS = Path(__file__).resolve().parent


@dataclass(frozen=True)
class SessionBuild:
    name: str
    build: object
    used_by: tuple[str, ...]   # test file names (glob patterns) whose tests need the build
    needs: tuple[str, ...]     # builds that must be complete first
    cost: float                # rough duration [s] on one idle core: the longest start first


BUILDS: dict[str, SessionBuild] = {}
_results: dict[str, object] = {}      # this process's results (read or built)
_session_wants: list[str] = []        # the builds of this session's tests (prebuild)


def session_build(name: str, *, cost: float, used_by: tuple[str, ...] = (),
                  needs: tuple[str, ...] = ()):
    """Register ``build(folder)`` under ``name``, taking about ``cost`` seconds; used by the
    test file that defines it, or by the files matching ``used_by``."""
    def register(build):
        users = tuple(used_by) or (Path(inspect.getfile(build)).name,)
        BUILDS[name] = SessionBuild(name, build, users, tuple(needs), cost)
        return build
    return register


def _text(result) -> str:
    return json.dumps(json_ready(result), default=str)


@contextlib.contextmanager
def _locked(path: Path, wait: bool = True):
    """An exclusive lock on ``path`` (yields False when ``wait`` is False and another process
    holds it)."""
    try:
        import fcntl
    except ImportError:          # no POSIX locks (Windows): every worker builds its own
        yield True
        return
    with open(path, "a") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | (0 if wait else fcntl.LOCK_NB))
        except BlockingIOError:
            yield False
            return
        try:
            yield True
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def _shared_root(tmp_path_factory) -> Path:
    # the parent of the workers' base temporaries: one folder per session, shared by them
    return tmp_path_factory.getbasetemp().parent


def built(tmp_path_factory, worker_id: str, name: str, *, wait: bool = True):
    """The result of build ``name``: read back if this session made it already, else built
    now (by this worker, while the others wait for it). With ``wait=False`` a build another
    worker is making is left to it (returns None)."""
    if name in _results:
        return _results[name]
    spec = BUILDS[name]
    for need in spec.needs:
        built(tmp_path_factory, worker_id, need)
    if worker_id == "master":
        result = json.loads(_text(spec.build(tmp_path_factory.mktemp(name))))
    else:
        root = _shared_root(tmp_path_factory)
        folder, done = root / name, root / f"{name}.json"
        with _locked(root / f"{name}.lock", wait) as mine:
            if not mine:
                return None
            if not done.exists():
                folder.mkdir(exist_ok=True)
                done.write_text(_text(spec.build(folder)))
        result = json.loads(done.read_text())
    _results[name] = result
    return result


def _done(tmp_path_factory, name: str) -> bool:
    return name in _results or (_shared_root(tmp_path_factory) / f"{name}.json").exists()


def builds_for(test_file) -> list[str]:
    """The builds the tests of ``test_file`` use (their ``used_by`` patterns), the costliest
    first."""
    name = Path(test_file).name
    return [b.name for b in sorted(BUILDS.values(), key=lambda b: -b.cost)
            if any(fnmatch.fnmatch(name, pattern) for pattern in b.used_by)]


def prebuild(tmp_path_factory, worker_id: str, test_files) -> None:
    """Start the builds the tests in ``test_files`` need, shared among the xdist workers: each
    worker starts at another build and takes every build nobody has started whose needs are
    complete, until none is left; then it runs tests (:func:`await_builds` holds a test until
    the builds of its file are complete). A build that fails is left to its fixture, which
    builds again and reports it."""
    wanted = list(dict.fromkeys(n for f in sorted(map(str, test_files)) for n in builds_for(f)))
    wanted.sort(key=lambda n: -BUILDS[n].cost)
    _session_wants[:] = wanted
    if not wanted:
        return
    index = int(worker_id[2:]) if worker_id[2:].isdigit() else 0
    start = index % len(wanted)
    pending = wanted[start:] + wanted[:start]
    started = True
    while started:               # builds nobody has started whose needs are complete
        started = False
        for name in list(pending):
            if all(_done(tmp_path_factory, n) for n in BUILDS[name].needs):
                with contextlib.suppress(Exception):
                    built(tmp_path_factory, worker_id, name, wait=False)
                pending.remove(name)      # made here, or being made by another worker
                started = True


def await_builds(tmp_path_factory, worker_id: str, test_file) -> None:
    """Wait for the builds of ``test_file`` (made by another worker, or here if nobody has
    started one), and for the cylinder's numba compile whenever the session makes it: a test
    that runs the cylinder while the compile is under way would compile it again (~60 s)."""
    first = ("pneumatic_numba",) if "pneumatic_numba" in _session_wants else ()
    for name in dict.fromkeys((*first, *builds_for(test_file))):
        with contextlib.suppress(Exception):      # a failed build: the fixture reports it
            built(tmp_path_factory, worker_id, name)


@session_build("pneumatic_numba", cost=60, used_by=(
    "test_pneumatic_*.py", "test_calibration*.py", "test_fmu*.py", "test_api.py",
    "test_app.py", "test_studies*.py", "test_contact_fit.py", "test_reliability.py",
    "test_readme.py", "test_structure_profiles_fe.py", "test_friction_cli.py"))
def compile_cylinder_model(folder):
    """The cold numba compile of the cylinder model (about 60 s), written to numba's cache
    beside the sources, where every worker and every subprocess then reads it: a short run
    of the Ø32 example and the full right-hand side of its chambers."""
    from sealsim.cases import load_toml
    from sealsim.pneumatic import simulate
    from sealsim.pneumatic.case import load_pneumatic_cases
    from sealsim.pneumatic.simulation import FORWARD, PneumaticSystem

    data = load_toml(TESTS.parent / "examples" / "pneumatic" / "cylinder_32.toml")
    data.pop("variants", None)
    data["controller"]["duration"] = "0.1 s"
    (case,) = load_pneumatic_cases(data).values()
    simulate(case)
    system = PneumaticSystem(case.model_copy(update={"seals": []}), [])
    system.evaluate(0.0, system.initial_state(), FORWARD, full=True)
    return None
