"""Characteristic maps: FE at off-grid points, netCDF round trip, smoothness, extrapolation."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from sealsim.cases import validate_case
from sealsim.errors import InputError
from sealsim.structure.case import StructureCase
from sealsim.structure.mapping import compute_map
from sealsim.structure.maps import SealMap, load_map

CASE = {
    "seal": {"cord_diameter": "4 mm", "inner_diameter": "20 mm"},
    "gland": {"arrangement": "rod", "sealing_diameter": "20 mm", "groove_width": "5.4 mm"},
    "material": {"elastomer": "NBR"},
    "mesh": {"level": "medium"},
    "load": {"squeeze": [0.15]},
    "map": {"pressure": ["0 bar", "2.5 bar", "5 bar", "7.5 bar", "10 bar"],
            "temperature": ["20 degC", "40 degC", "60 degC"],
            "squeeze_increments": 6, "temperature_increments": 2, "workers": 2},
}


@pytest.fixture(scope="module")
def case():
    return validate_case(StructureCase, CASE)


@pytest.fixture(scope="module")
def dataset(case):
    return compute_map(case, case_text="# test case\n")


def _fe_point(case, pressure, temperature):
    """Direct FE at one load (independent of the map's interpolation)."""
    from sealsim.structure.results import extract
    from sealsim.structure.build import build_material, build_model
    from sealsim.structure.solver import LoadStep, solve

    material = build_material(case, equilibrium=True)
    model = build_model(case, 0.15, material=material,
                        temperatures=[293.15, temperature])
    states = solve(model, [LoadStep("i", squeeze=0.15, increments=6, record="none"),
                           LoadStep("t", temperature=temperature, increments=2, record="none"),
                           LoadStep("p", pressure=pressure, increments=3, record="end")],
                   on_state=extract)
    return states[-1]


def test_dataset_layout(dataset):
    assert dataset["F_N"].dims == ("squeeze", "temperature", "pressure")
    assert dataset["F_N"].shape == (1, 3, 5)
    assert dataset["pressure"].attrs["units"] == "Pa"
    assert dataset["temperature"].attrs["units"] == "K"
    assert dataset["b"].attrs["units"] == "m"
    assert dataset.attrs["case"] == "# test case\n"
    assert np.all(np.isfinite(dataset["F_N"].values))
    # F_N grows with pressure at every temperature (fluid load on the upstream face)
    assert np.all(np.diff(dataset["F_N"].values, axis=-1) > 0)


def test_map_reproduces_fe_off_grid(case, dataset):
    """Interpolated F_N and b vs direct FE at two off-grid points within 2 % (issue).

    The interpolant is C1 cubic Hermite with PCHIP slopes over 2.5 bar x 20 K cells; the
    FE itself is smooth to about 0.5 % in b (edge interpolation between nodes), so 2 % leaves
    room for both.
    """
    m = SealMap(dataset)
    for p, t in ((3.75e5, 303.15), (8.75e5, 323.15)):
        fe = _fe_point(case, p, t)
        f_map, b_map = m(p, t)
        assert f_map == pytest.approx(fe.F_N, rel=0.02)
        assert b_map == pytest.approx(fe.b, rel=0.02)


def test_netcdf_round_trip_and_extrapolation(tmp_path, dataset):
    path = tmp_path / "map.nc"
    dataset.to_netcdf(path)
    m = load_map(path)
    p = dataset["pressure"].values
    t = dataset["temperature"].values
    # grid points are reproduced exactly (interpolation, not smoothing)
    f, _ = m(p[2], t[1], 0.15)
    assert f == pytest.approx(float(dataset["F_N"].values[0, 1, 2]), rel=1e-12)
    # vectorised call equals scalar calls
    pp = np.linspace(0, 10e5, 7)
    fv, _ = m(pp, 310.0)
    assert np.allclose(fv, [m(x, 310.0)[0] for x in pp], rtol=1e-12)
    # refuses to extrapolate, with the variable, value and range in the message
    with pytest.raises(InputError, match=r"pressure = 12 bar is outside.*0 \.\.\. 10 bar"):
        m(12e5, 310.0)
    with pytest.raises(InputError, match="temperature"):
        m(5e5, 200.0)
    with pytest.raises(InputError, match="squeeze"):
        m(5e5, 310.0, squeeze=0.2)
    clipped = load_map(path, extrapolate="clip")
    assert clipped(12e5, 310.0)[0] == pytest.approx(clipped(10e5, 310.0)[0])
    with pytest.raises(InputError, match="does not exist"):
        load_map(tmp_path / "missing.nc")


def test_interpolant_is_smooth_across_grid_lines(dataset):
    """No kinks: the one-sided slopes at a grid line agree (C1), unlike linear interpolation.

    Tolerance: finite-difference slopes with step 1 Pa on a ~40 N/bar slope; 1e-4 relative.
    """
    m = SealMap(dataset)
    p0 = float(dataset["pressure"].values[2])
    h = 1.0
    left = (m(p0, 310.0)[0] - m(p0 - h, 310.0)[0]) / h
    right = (m(p0 + h, 310.0)[0] - m(p0, 310.0)[0]) / h
    assert left == pytest.approx(right, rel=1e-4)


def test_compute_map_rejects_bad_input(case):
    with pytest.raises(InputError, match="no \\[map\\] table"):
        compute_map(case.model_copy(update={"map": None}))
    bad = dict(CASE, map=dict(CASE["map"], pressure=["5 bar", "1 bar"]))
    with pytest.raises(InputError, match="ascending"):
        validate_case(StructureCase, bad)


def test_dataset_is_xarray(dataset):
    assert isinstance(dataset, xr.Dataset)


def test_shared_installation_gives_the_paths_solved_from_the_start():
    """A map process solves the installation once per squeeze and starts every path from a
    copy of the installed model: the same results as paths that install themselves (to
    1e-12: the linear solver's analysis is redone from another matrix, round-off only)."""
    from sealsim.structure import mapping

    data = validate_case(StructureCase, {
        **CASE, "mesh": {"level": "coarse"},
        "map": {**CASE["map"], "pressure": ["0 bar", "5 bar"]}}).model_dump(mode="json")
    positions = np.linspace(-2e-3, 2e-3, 5)
    installed: dict = {}
    mapping._map_task(data, 0.15, 293.15, positions, installed)  # installs
    shared = mapping._map_task(data, 0.15, 333.15, positions, installed)  # from the copy
    own = mapping._map_task(data, 0.15, 333.15, positions, {})
    assert len(installed) == 1 and shared["increments"] == own["increments"]
    for key in ("F_N", "b", "contact_pressure"):
        a, b = np.asarray(shared[key]), np.asarray(own[key])
        assert np.abs(a - b).max() <= 1e-12 * np.abs(b).max()


SMALL_MAP = {**CASE, "mesh": {"level": "coarse"},
             "map": {**CASE["map"], "pressure": ["0 bar", "5 bar"], "temperature": ["20 degC"],
                     "workers": 1}}


def test_a_map_with_another_grid_reuses_the_installation(monkeypatch):
    """A second map of the same installation (seal, gland, material, mesh, solver,
    installation temperature, squeeze and its increments) with another pressure and
    temperature grid starts from the model this process installed for the first map.
    Before, the installed model was keyed by the whole case incl. the grid, and a serial
    build kept its own: every map solved the same installation again.  The second map is the
    map built from scratch (1e-12, as above)."""
    from sealsim.structure import mapping

    installs = []
    real = mapping.build_model
    monkeypatch.setattr(mapping, "build_model",
                        lambda *args, **kw: installs.append(args[1]) or real(*args, **kw))
    monkeypatch.setattr(mapping, "_INSTALLED", {})
    compute_map(validate_case(StructureCase, SMALL_MAP))
    other = validate_case(StructureCase, {**SMALL_MAP, "title": "another grid", "map": {
        **SMALL_MAP["map"], "pressure": ["0 bar", "2 bar", "4 bar"], "temperature": ["40 degC"],
        "pressure_increments": 2, "profile_points": 11}})
    second = compute_map(other)
    assert installs == [0.15]
    monkeypatch.setattr(mapping, "_INSTALLED", {})
    fresh = compute_map(other)
    assert installs == [0.15, 0.15]
    for name in ("F_N", "b", "p_max", "contact_pressure"):
        np.testing.assert_allclose(second[name].values, fresh[name].values, rtol=1e-12, atol=0)
    # another installation (squeeze increments) is solved, not taken from the first
    compute_map(validate_case(StructureCase, {**SMALL_MAP, "map": {
        **SMALL_MAP["map"], "squeeze_increments": 5}}))
    assert installs == [0.15, 0.15, 0.15]


def test_a_reused_installation_is_checked_for_the_new_temperatures(monkeypatch):
    """The installed model is shared by maps of other grids, so the gland fill of each map's
    temperatures is checked by the map itself: a 4 mm groove holds the 4 mm cord at 17 %
    squeeze at 20 degC (fill 94.6 %) but not at 100 degC (99.0 %, thermal expansion; limit
    97 %): refused after a 20 degC map of the same installation, before any FE path."""
    from sealsim.structure import mapping

    monkeypatch.setattr(mapping, "_INSTALLED", {})
    tight = {**SMALL_MAP, "gland": {**SMALL_MAP["gland"], "groove_width": "4 mm"},
             "load": {"squeeze": [0.17]}}
    compute_map(validate_case(StructureCase, tight))
    assert len(mapping._INSTALLED) == 1
    hot = validate_case(StructureCase, {**tight, "map": {**tight["map"],
                                                         "temperature": ["100 degC"]}})
    monkeypatch.setattr(mapping, "_map_task", lambda *args: pytest.fail("FE path started"))
    with pytest.raises(InputError, match="gland too small.*squeeze 17 %"):
        compute_map(hot)


KILLED_MAP = """
import os, sys, time
import sealsim.structure.mapping as mapping
from sealsim.structure.case import load_structure_cases

def held(*args, **kwargs):         # an FE path that takes long: the parent is killed meanwhile
    open(os.path.join(sys.argv[1], f"{os.getpid()}.pid"), "w").close()
    time.sleep(120)

mapping._map_task = held
case = next(iter(load_structure_cases(sys.argv[2]).values()))
mapping.compute_map(case, workers=2)
"""


def _running(pid: int) -> bool:
    """The process exists and is not a zombie (an orphan's zombie waits for init to reap it)."""
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="reads process states from /proc")
def test_map_workers_end_when_the_map_build_is_killed(tmp_path):
    # SIGKILL of `sealsim structure map` (no clean-up runs) left its pool workers behind: each
    # finished its FE path, then waited for work forever, holding its memory
    case = Path(__file__).resolve().parents[1] / "examples" / "structure" / "oring_map.toml"
    proc = subprocess.Popen([sys.executable, "-c", KILLED_MAP, str(tmp_path), str(case)])
    try:
        end = time.monotonic() + 120
        while len(list(tmp_path.glob("*.pid"))) < 2:
            assert proc.poll() is None and time.monotonic() < end, "workers did not start"
            time.sleep(0.1)
    finally:
        proc.kill()
        proc.wait()
    workers = [int(p.stem) for p in tmp_path.glob("*.pid")]
    end = time.monotonic() + 10   # the watch looks every 0.5 s; 10 s: a busy 2-core machine
    while any(map(_running, workers)) and time.monotonic() < end:
        time.sleep(0.1)
    alive = [pid for pid in workers if _running(pid)]
    for pid in alive:             # do not leave them behind on failure either
        os.kill(pid, signal.SIGKILL)
    assert alive == []


def test_an_interrupted_map_build_computes_only_the_missing_paths(dataset, tmp_path,
                                                                  computed_map_paths):
    # Ctrl-C (or SIGKILL) of `sealsim structure map` lost every finished FE load path: the
    # next run computed the whole map again
    import tomli_w

    from sealsim.runs.structure import map_case_file

    path = tmp_path / "map.toml"
    out, kept = tmp_path / "out", tmp_path / ".out.map"
    computed = computed_map_paths

    def ctrl_c_after(paths):
        def progress(done, total):
            if done == paths:
                raise KeyboardInterrupt
        return progress

    path.write_text(tomli_w.dumps(CASE))
    with pytest.raises(KeyboardInterrupt):
        map_case_file(path, out, progress=ctrl_c_after(2), workers=1)
    assert not out.exists() and len(list(kept.glob("*.json"))) == 2
    # a changed case reuses none of them: another temperature grid computes its 20 degC again
    # (its first path; stopped there, a second path would only cost time)
    path.write_text(tomli_w.dumps({**CASE, "map": {**CASE["map"],
                                                   "temperature": ["20 degC", "50 degC"]}}))
    computed.clear()
    with pytest.raises(KeyboardInterrupt):
        map_case_file(path, out, progress=ctrl_c_after(1), workers=1)
    assert computed == [293.15]
    # the first case again: only the path its interruption left out (60 degC)
    path.write_text(tomli_w.dumps(CASE))
    computed.clear()
    ds = map_case_file(path, out, workers=1)
    assert computed == [333.15]
    assert not kept.exists()              # removed once the map is written
    # the kept paths give the map of an uninterrupted build (JSON keeps every float; 1e-12:
    # the serial build reuses one installed model where the fixture's two workers install
    # their own)
    for name in ("F_N", "b", "p_max", "contact_pressure"):
        np.testing.assert_allclose(ds[name].values, dataset[name].values, rtol=1e-12, atol=0)
