"""The compiled right-hand side and LSODA driver against the pre-issue-13 implementation
(tests/reference_v0): the same steps and the same states to < 1e-9 relative, for every friction
law, sticking and sliding, a 5/3 valve, a prescribed position and an FE map; and the compiled
Hermite map kernel against the structure package's interpolant.

Why a subprocess: numpy evaluates ``exp`` with its own SIMD code on CPUs with AVX-512, which
differs from the C library's ``exp`` (used by the compiled kernels, and by C code) in the last
bit for about 5 % of the arguments.  Stick/slip events amplify such a bit into ~1e-6 of the
states.  The comparison therefore runs with numpy's dispatched SIMD code switched off
(``NPY_DISABLE_CPU_FEATURES``), so both implementations compute the same exp; the Θ-law case,
which has no exp, also agrees without that switch (benchmarks/bench_pneumatic.py prints it).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from session_builds import built, session_build

from sealsim.pneumatic.contact_maps import FEContactMap, hermite_grid_point

ROOT = Path(__file__).resolve().parents[1]

SCRIPT = textwrap.dedent(r'''
    import json, sys
    import numpy as np
    import xarray as xr
    sys.path.insert(0, sys.argv[1])
    from reference_v0.pneumatic_simulation import simulate_reference
    from sealsim.cases import apply_overrides, load_toml
    from sealsim.pneumatic import build_seals, simulate
    from sealsim.pneumatic.case import load_pneumatic_cases

    EX = sys.argv[2]
    THETA = {"law": "theta", "tau": "2 s", "alpha": "0.1 m", "f_a": 0.5, "f_b": 0.1,
             "gamma": "1e4 N*s/m**2", "reference_normal_force": "100 N"}
    LUGRE = {"law": "lugre", "sigma0": "1e5 N/m", "sigma1": "300 N*s/m",
             "sigma2": "10 N*s/m", "coulomb_force": "10 N", "static_force": "14 N",
             "stribeck_velocity": "0.01 m/s"}
    STATES = [("x_m", "x_m"), ("v_m_s", "v_m_s"), ("p1_bar_abs", "p1_bar"),
              ("p2_bar_abs", "p2_bar"), ("T1_C", "T1_C"), ("T2_C", "T2_C"),
              ("F_friction_N", "F_friction_N")]

    def case(name, duration, laws=None, overrides=None, variant="T25C"):
        data = load_toml(f"{EX}/{name}")
        data = apply_overrides(data, data.pop("variants")[variant])
        for k, s in enumerate(data["seals"]):
            if s["friction"].get("parameter_set") == "pneumatic_demo":
                s["friction"] = dict(THETA)
            if laws and k in laws:
                s["friction"] = laws[k]
        data = apply_overrides(data, overrides or {})
        data["controller"]["duration"] = f"{duration} s"
        data["solver"] = {"method": "LSODA"}      # the LSODA driver against the reference
        return load_pneumatic_cases(data)["base"]

    def fe_map(path):
        p = np.linspace(0.0, 8e5, 9)
        t = np.array([283.15, 303.15, 333.15])
        pp, tt = np.meshgrid(p, t, indexing="ij")
        fn = 30.0 + 6e-5 * pp + 0.2 * (tt - 293.15) + 5e-12 * pp ** 2
        b = 5e-4 + 4e-10 * pp + 1e-6 * (tt - 293.15)
        coords = {"squeeze": [0.12], "temperature": t, "pressure": p}
        dims = ("squeeze", "temperature", "pressure")
        ds = xr.Dataset({"F_N": (dims, fn.T[None]), "b": (dims, b.T[None])}, coords=coords)
        ds.to_netcdf(path)
        return path

    runs = {
        "theta": case("cylinder_32.toml", 1.1),
        "theta_bristles": case("cylinder_32.toml", 0.6, {0: {
            **THETA, "bristle_stiffness": "2e5 N/m", "bristle_damping": "400 N*s/m"}}),
        "stribeck_5_3": case("cylinder_32.toml", 1.0, {0: {"law": "stribeck", "parameter_set":
                                                           "pneumatic_demo"}},
                             {"valve": {"type": "5/3", "centre": "closed"},
                              "controller": {"steps": [
                                  {"command": "extend", "duration": "0.2 s"},
                                  {"command": "centre", "duration": "0.3 s"},
                                  {"command": "retract", "duration": "0.5 s"}]}}),
        "lugre_gms_dahl": case("cylinder_32.toml", 0.12, {
            0: LUGRE, 1: {"law": "gms", "parameter_set": "canudas1995", "stiffness": "1e5 N/m",
                          "coulomb_force": "8 N", "static_force": "10 N",
                          "stribeck_velocity": "0.01 m/s"},
                               2: {"law": "dahl", "sigma0": "1e5 N/m", "coulomb_force": "3 N"}}),
        "rig": case("friction_rig.toml", 0.5),
    }
    data = load_toml(f"{EX}/cylinder_32.toml")
    data = apply_overrides(data, data.pop("variants")["T25C"])
    data["seals"][0]["friction"] = dict(THETA)
    data["seals"][1]["friction"] = dict(THETA)
    data["seals"][1]["map"] = {"file": str(fe_map(sys.argv[3]))}
    data["controller"]["duration"] = "0.5 s"
    data["solver"] = {"method": "LSODA"}
    runs["fe_map"] = load_pneumatic_cases(data)["base"]
    out = {}
    for label, c in runs.items():
        seals = build_seals(c, EX)
        new, ref = simulate(c, seals), simulate_reference(c, seals)
        n = min(len(new.timeseries), len(ref.timeseries))     # (the reference may lack the
        errors = [float(np.max(np.abs(new.timeseries[a].to_numpy()[:n]   # sample at the end)
                                      - ref.timeseries[b].to_numpy()[:n]))
                        / max(np.max(np.abs(ref.timeseries[b].to_numpy())), 1e-300))
                  for a, b in STATES]
        out[label] = {"max_rel": max(errors), "steps": [new.stats["steps"], ref.stats["steps"]],
                      "switches": new.stats["mode_switches"]}
    print(json.dumps(out))
''')


def _numpy_without_simd_dispatch() -> str:
    """The value of NPY_DISABLE_CPU_FEATURES that leaves numpy on its baseline code."""
    try:
        from numpy._core import _multiarray_umath as umath
    except ImportError:  # pragma: no cover - numpy 1.x
        from numpy.core import _multiarray_umath as umath
    return " ".join(getattr(umath, "__cpu_dispatch__", []))


@session_build("compiled_comparison", cost=20, needs=("pneumatic_numba",))
def compare_with_the_reference(folder):
    env = dict(os.environ, NPY_DISABLE_CPU_FEATURES=_numpy_without_simd_dispatch())
    src = str(ROOT / "src")
    env["PYTHONPATH"] = src + os.pathsep + env.get("PYTHONPATH", "")
    map_file = folder / "map.nc"
    done = subprocess.run([sys.executable, "-c", SCRIPT, str(ROOT / "tests"),
                           str(ROOT / "examples" / "pneumatic"), str(map_file)],
                          capture_output=True, text=True, env=env, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def comparison(tmp_path_factory, worker_id):
    return built(tmp_path_factory, worker_id, "compiled_comparison")


@pytest.mark.parametrize("label", ["theta", "theta_bristles", "stribeck_5_3", "lugre_gms_dahl",
                                   "rig", "fe_map"])
def test_compiled_model_reproduces_the_reference(comparison, label):
    # the states of the compiled model and the frozen numpy model, relative to their largest
    # value: the same steps, differences of a few ulp (1e-9 is the project's limit)
    run = comparison[label]
    assert run["steps"][0] == run["steps"][1]
    assert run["max_rel"] < 1e-9
    if label == "stribeck_5_3":
        assert run["switches"] >= 3          # the case does stick and slip


def test_hermite_kernel_is_the_structure_packages_interpolant():
    """The compiled map kernel against SealMap.evaluate (HermiteGrid.evaluate_scalar) of the
    structure package on a 3-axis map (several squeezes): same cells and coefficients, a few
    ulp; values are clamped to the map, never extrapolated."""
    import xarray as xr

    from sealsim.structure.maps import SealMap

    rng = np.random.default_rng(3)
    s, t, p = np.array([0.08, 0.12, 0.16]), np.array([263.15, 293.15, 353.15]), \
        np.linspace(0.0, 1e6, 6)
    ss, tt, pp = np.meshgrid(s, t, p, indexing="ij")
    fn = 100 * ss + 0.1 * tt + 5e-5 * pp + 1e-11 * pp ** 2 * ss
    b = 1e-3 * ss + 1e-6 * tt + 1e-10 * pp
    ds = xr.Dataset({"F_N": (("squeeze", "temperature", "pressure"), fn),
                     "b": (("squeeze", "temperature", "pressure"), b)},
                    coords={"squeeze": s, "temperature": t, "pressure": p})
    ref = SealMap(ds, extrapolate="clip")
    m = FEContactMap(ref, squeeze=0.1)
    row, data = m.tables()
    for dp, temp in zip(rng.uniform(-1e5, 1.2e6, 50), rng.uniform(250.0, 370.0, 50)):
        fn_k, b_k, clipped = hermite_grid_point(row, data, dp, temp)
        fn_r, b_r = ref.evaluate(min(max(dp, 0.0), 1e6), min(max(temp, 263.15), 353.15), 0.1)
        assert fn_k == pytest.approx(fn_r, rel=1e-13) and b_k == pytest.approx(b_r, rel=1e-13)
        assert clipped == float(not 263.15 <= temp <= 353.15)
    # the vectorised path of the map object gives the same numbers
    fn_v, b_v = m.evaluate(np.array([0.0, 3e5, 2e6]), 300.0)
    assert fn_v[1] == pytest.approx(ref.evaluate(3e5, 300.0, 0.1)[0], rel=1e-13)
    assert fn_v[2] == pytest.approx(ref.evaluate(1e6, 300.0, 0.1)[0], rel=1e-13)


def test_the_column_evaluation_is_compiled_once_and_called():
    """The Jacobian's compiled functions call :func:`rhs.evaluate_column` instead of inlining
    a copy of it: numba types, lowers and optimises every inlined copy again, 18-28 s of CPU
    each on an empty cache (every CI run); the three copies were 70 s of the cylinder chain's
    133 s (``benchmarks/compile_pneumatic.py``, 2026-11-28).  Only
    :func:`rhs.evaluate_many` (the output samples, where a call costs ~250 ns per column)
    keeps one.  Checked on uncached copies of the callers (cached code has no LLVM IR): their
    code calls the function (an inlined copy has no call of it)."""
    import re

    import numba

    from sealsim.cases import load_toml
    from sealsim.pneumatic import build_seals, rhs
    from sealsim.pneumatic.case import load_pneumatic_cases
    from sealsim.pneumatic.simulation import PneumaticSystem

    example = ROOT / "examples" / "pneumatic" / "cylinder_32.toml"
    c = load_pneumatic_cases(load_toml(example))["T25C"]
    system = PneumaticSystem(c, build_seals(c, example.parent))
    n, ndyn = system.n_states, system.n_dynamic
    args = (0.0, system.initial_state(), np.zeros(n), rhs.FORWARD, system.tables,
            system.tolerances(1.0)[:ndyn].copy(), np.zeros(n), np.zeros(n),
            np.zeros((system.n_diag, 1)), np.zeros((n, ndyn)))
    call = re.compile(r"call [^\n]*@\"?_ZN7sealsim9pneumatic3rhs15evaluate_column")
    for dispatcher in (rhs.jacobian_at, rhs.velocity_column_at):
        copy = numba.njit(dispatcher.py_func)
        copy(*args)
        llvm = copy.inspect_llvm(copy.signatures[0])
        assert call.search(llvm), f"{dispatcher.__name__} inlines the column evaluation"
