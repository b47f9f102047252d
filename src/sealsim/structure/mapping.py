r"""Computing characteristic maps of any seal profile: F_N, b and the contact pressure
profile over pressure × temperature (× squeeze).

:func:`compute_map` runs one FE load path per (squeeze, temperature) -- installation to the
squeeze at the installation temperature, temperature change at the positioning pressure, then
the pressure sweep over the grid, recording every grid pressure -- in a process pool. The
installation is the same for every temperature of a squeeze: each process solves it once and
starts each of its paths from a copy of the installed model (the same state, so the same
results as a path solved from the start; tested). The
material of a map is the held (relaxed) one: a hyperelastic case with its
``temperature_scaling`` ("held" by default), a thermo-viscoelastic case with its long-time
hyperelastic constants.  Both are rubbery, so a map refuses temperatures within
:data:`~sealsim.properties.elastomers.GLASS_TRANSITION_MARGIN` of the rubber's T_g (where only
a viscoelastic load path, ``sealsim structure run``, with its glassy expansion holds).
The dataset layout is described in
:mod:`.maps` (which reads maps without importing the FE).
"""

from __future__ import annotations

import concurrent.futures as cf
import copy
import hashlib
import json
import os
import threading
import time
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import xarray as xr

from sealsim.errors import InputError, SealsimWarning
from sealsim.files import atomic_write_text
from sealsim.structure.build import (
    build_assembly,
    build_material,
    build_model,
    check_loads,
    check_rubbery,
    installation_squeeze,
)
from sealsim.structure.case import StructureCase
from sealsim.structure.maps import MAP_COORDS, MAP_VARIABLES, PROFILE_VARIABLES
from sealsim.structure.results import extract, pressure_profile
from sealsim.structure.solver import LoadStep, solve

__all__ = ["compute_map", "profile_positions"]


def profile_positions(case: StructureCase, assembly=None) -> np.ndarray:
    """Axial positions [m] where a map stores the contact pressure profile: evenly across the
    groove, and with a clearance gap one clearance beyond each wall, where the rubber bulging
    into the gap can touch the sealing surface (a shaft seal: across its width around the lip
    edge)."""
    assembly = assembly or build_assembly(case)
    n = case.map.profile_points if case.map is not None else 41
    if case.gland.arrangement == "shaft":
        lo, hi = assembly.seal.axial_range
        half = 0.5 * (hi - lo)
        return np.linspace(-0.5 * half, 0.5 * half, n)
    half = 0.5 * assembly.gland.groove_width + (assembly.gland.clearance or 0.0)
    return np.linspace(-half, half, n)


#: Installed models of this process (a pool worker's, or the process of a serial map build),
#: the last few (case, squeeze): a map solves the installation once per squeeze and process,
#: and a later map of the same installation with another grid does not solve it again.
_INSTALLED: dict = {}
_INSTALLED_KEPT = 2

#: Fields of ``[map]`` that only set the grid and the paths after the installation.
_GRID_FIELDS = ("pressure", "temperature", "squeeze", "temperature_increments",
                "pressure_increments", "workers", "profile_points")


def _installation_key(case_data: dict, squeeze: float | None) -> str:
    """What the installation at ``squeeze`` depends on: the whole case (seal, gland, material,
    mesh, solver, load incl. the installation temperature, map.squeeze_increments) without
    its title and the map's grid."""
    data = {k: v for k, v in case_data.items() if k != "title"}
    data["map"] = {k: v for k, v in (data.get("map") or {}).items() if k not in _GRID_FIELDS}
    return json.dumps([data, squeeze], sort_keys=True)


def _installed_model(case: StructureCase, case_data: dict, squeeze: float | None,
                     installed: dict):
    """A copy of the model installed to ``squeeze`` at the installation temperature (solved
    on first use and kept in ``installed``, keyed by :func:`_installation_key`: not by the
    map's grid, whose geometry checks :func:`compute_map` makes for every temperature)."""
    key = _installation_key(case_data, squeeze)
    if key not in installed:
        spec, sv = case.map, case.solver
        material = build_material(case, equilibrium=True)
        model = build_model(case, squeeze, material=material)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", category=UserWarning)
            solve(model, [LoadStep("installation", squeeze=model.installation_squeeze,
                                   increments=spec.squeeze_increments, record="none")],
                  on_state=extract, tol=sv.tolerance, maxiter=sv.max_iterations,
                  max_cutbacks=sv.max_cutbacks, increment_growth=sv.increment_growth)
        while len(installed) >= _INSTALLED_KEPT:
            installed.pop(next(iter(installed)))
        installed[key] = model
    return copy.deepcopy(installed[key])


def _map_task(case_data: dict, squeeze: float | None, temperature: float,
              positions: np.ndarray, installed: dict | None = None) -> dict:
    """One FE load path: install to ``squeeze`` (or copy the installed model, see
    :func:`_installed_model`), change to ``temperature``, sweep the pressures."""
    case = StructureCase.model_validate(case_data)
    spec = case.map
    model = _installed_model(case, case_data, squeeze,
                             _INSTALLED if installed is None else installed)
    steps = [LoadStep("temperature", temperature=temperature,
                      increments=spec.temperature_increments, record="none")]
    steps += [LoadStep("pressure", pressure=p, increments=spec.pressure_increments, record="end")
              for p in spec.pressure]
    sv = case.solver
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        states = solve(model, steps, on_state=extract, tol=sv.tolerance,
                       maxiter=sv.max_iterations, max_cutbacks=sv.max_cutbacks,
                       increment_growth=sv.increment_growth)
    seal = [s.surfaces["sealing_surface"] for s in states]
    return {
        "F_N": [s.F_N for s in states],
        "F_N_per_length": [s.F_N_per_length for s in states],
        "b": [s.b for s in states],
        "p_max": [s.p_max for s in states],
        "p_mean": [s.p_mean for s in states],
        "F_groove_bottom": [s.surfaces["groove_bottom"].force
                            if "groove_bottom" in s.surfaces else 0.0 for s in states],
        "contact_zones": [float(s.zones) for s in seal],
        "b_span": [s.span for s in seal],
        "contact_pressure": [pressure_profile(s, positions) for s in seal],
        "ndofs": model.ndofs,
        "increments": len(model.increment_log),
        "cutbacks": int(sum(r["cutbacks"] for r in model.increment_log)),
    }


def _end_with_parent() -> None:
    """Pool-worker initializer: the worker ends itself once the process that started it is
    gone.  A parent killed by SIGKILL (no clean-up runs) left its workers to finish their FE
    path and then wait for work forever; a parent's Ctrl-C is handled by the pool itself.
    (The parent is whoever started the worker: the map's process, or a forkserver that ends
    with it.)"""
    parent = os.getppid()

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(1)

    threading.Thread(target=watch, name="end-with-parent", daemon=True).start()


class _KeptPaths:
    """Finished FE load paths of a map kept in a folder, so that a build that is interrupted
    (Ctrl-C, SIGKILL, power loss) computes only the missing paths when it is run again.

    Each path is one JSON file named by a hash of everything its values depend on -- the
    key of the case's FE results (:func:`~sealsim.structure.fingerprint.results_key`: the
    resolved case, the FE model's fingerprint, a compound file's content; the map cache's key
    too) with the stored profile positions, and the path's (squeeze, temperature) -- so a
    changed case or model never reuses a path.  JSON keeps every float exactly (shortest
    repr).
    """

    def __init__(self, folder: str | Path, case: StructureCase, positions: np.ndarray):
        from sealsim.structure.fingerprint import results_key

        self.folder = Path(folder)
        self._salt = results_key(case, positions.tolist())

    def _file(self, key: tuple) -> Path:
        text = f"{self._salt}|{key[0]!r}|{key[1]!r}"
        return self.folder / f"{hashlib.sha256(text.encode('utf-8')).hexdigest()[:32]}.json"

    def load(self, key: tuple) -> dict | None:
        try:
            return json.loads(self._file(key).read_text(encoding="utf-8"))
        except (OSError, ValueError):   # not computed yet, or a damaged file: compute it
            return None

    def save(self, key: tuple, out: dict) -> None:
        self.folder.mkdir(parents=True, exist_ok=True)
        atomic_write_text(self._file(key), json.dumps(
            {k: np.asarray(v).tolist() for k, v in out.items()}))


def compute_map(case: StructureCase, *, workers: int | None = None,
                progress: Callable[[int, int], None] | None = None,
                case_text: str = "", keep: str | Path | None = None) -> xr.Dataset:
    """Compute the characteristic map of a case with a ``[map]`` table.

    Parameters
    ----------
    case : StructureCase
        Validated case (``case.map`` must be given).
    workers : int, optional
        Processes (default ``case.map.workers``); 1 runs in this process.
    progress : callable, optional
        ``progress(done, total)`` after each finished (squeeze, temperature) path.
    case_text : str
        Resolved case (TOML) stored as the ``case`` attribute.
    keep : path, optional
        Folder where every finished load path is kept (:class:`_KeptPaths`): a build run
        again after an interruption reuses them and computes only the missing paths (the
        paths the worker processes were solving when the build was stopped are kept too,
        since it waits for them anyway).  The caller removes the folder once the map is
        stored.

    Returns
    -------
    xarray.Dataset
        See :mod:`.maps`; attributes also hold the dofs, the increments and the cutbacks.
    """
    from sealsim import __version__

    if case.map is None:
        raise InputError("the case has no [map] table: give map.pressure and map.temperature")
    spec = case.map
    assembly = build_assembly(case)
    squeezes = spec.squeeze or [installation_squeeze(case, assembly)
                                if case.load.squeeze is None else case.load.squeeze[-1]]
    # every (squeeze, temperature) of the grid fits the gland (also for an installation a
    # previous map of this process solved: _installed_model)
    check_loads(case, assembly, build_material(case, equilibrium=True), squeezes,
                [case.load.installation_temperature, *spec.temperature], field="map.squeeze")
    check_rubbery(case, spec.temperature)
    positions = profile_positions(case, assembly)
    tasks = [(s, t) for s in squeezes for t in spec.temperature]
    data = case.model_dump(mode="json")
    shape = (len(squeezes), len(spec.temperature), len(spec.pressure))
    scalars = [*MAP_VARIABLES, *PROFILE_VARIABLES]
    arrays = {v: np.full(shape, np.nan) for v in scalars}
    profile = np.full(shape + (len(positions),), np.nan)
    totals = {"ndofs": 0, "increments": 0, "cutbacks": 0}

    def store(key, out):
        i, j = squeezes.index(key[0]), spec.temperature.index(key[1])
        for v in scalars:
            arrays[v][i, j, :] = out[v]
        profile[i, j] = np.asarray(out["contact_pressure"])
        totals["ndofs"] = out["ndofs"]
        totals["increments"] += out["increments"]
        totals["cutbacks"] += out["cutbacks"]

    kept = None if keep is None else _KeptPaths(keep, case, positions)
    done, todo = 0, []
    for key in tasks:
        out = None if kept is None else kept.load(key)
        if out is None:
            todo.append(key)
        else:
            store(key, out)
            done += 1

    def finished(key, out):
        nonlocal done
        if kept is not None:
            kept.save(key, out)
        store(key, out)
        done += 1
        if progress:
            progress(done, len(tasks))

    if progress and done:
        progress(done, len(tasks))
    n_workers = max(1, min(workers or spec.workers, len(todo)))
    if n_workers == 1:
        for key in todo:
            finished(key, _map_task(data, *key, positions))
    else:
        with cf.ProcessPoolExecutor(max_workers=n_workers,
                                    initializer=_end_with_parent) as pool:
            futures = {pool.submit(_map_task, data, *key, positions): key for key in todo}
            handled = set()
            try:
                for fut in cf.as_completed(futures):
                    handled.add(fut)
                    finished(futures[fut], fut.result())
            except BaseException:
                for f in futures:
                    f.cancel()
                if kept is not None:  # the pool waits for the paths being solved: keep them
                    for f, key in futures.items():
                        if f not in handled and not f.cancelled() and f.exception() is None:
                            kept.save(key, f.result())
                raise
    if np.any(profile[..., [0, -1]] > 0.0):
        warnings.warn(SealsimWarning(
            f"map: the contact reaches the end of the stored pressure profile (±"
            f"{positions[-1] * 1e3:.3g} mm around the groove's centre): the profile misses "
            "the part beyond it (the seal extrudes far into the clearance gap)"), stacklevel=2)
    coords = {"squeeze": np.asarray(squeezes, float),
              "temperature": np.asarray(spec.temperature, float),
              "pressure": np.asarray(spec.pressure, float)}
    dims = ("squeeze", "temperature", "pressure")
    variables = {v: (dims, arrays[v], {"units": unit, "long_name": text})
                 for v, (unit, text) in {**MAP_VARIABLES, **PROFILE_VARIABLES}.items()}
    variables["contact_pressure"] = (
        dims + ("position",), profile,
        {"units": "Pa", "long_name": "contact pressure on the sealing surface"})
    all_coords = {d: (d, coords[d], {"units": MAP_COORDS[d][0], "long_name": MAP_COORDS[d][1]})
                  for d in coords}
    all_coords["position"] = ("position", positions,
                              {"units": "m", "long_name": "axial position on the sealing "
                                                          "surface (gland centre at 0)"})
    return xr.Dataset(
        variables, coords=all_coords,
        attrs={
            "title": "sealsim characteristic map of a seal (axisymmetric FE, FElupe)",
            "case": case_text,
            "sealsim_version": __version__,
            "seal_type": case.seal.type,
            "elastomer": case.material.elastomer or "custom Mooney-Rivlin",
            "material_model": "hyperelastic (equilibrium constants)",
            "dofs": int(totals["ndofs"]),
            "increments": int(totals["increments"]),
            "cutbacks": int(totals["cutbacks"]),
            "conventions": "forces for the full circumference; pressure is the gauge pressure "
                           "on the upstream side; temperature in K; squeeze = 1 - h/h0 (h0 the "
                           "free radial height of the section)",
        },
    )
