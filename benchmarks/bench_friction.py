"""Speed and accuracy of the friction laws.

1. 10 s of LuGre (1995 Table I set) and of the Θ law (pneumatic_demo set) under a sinusoidal
   velocity that reverses, run with the bench (exact step per time step, vectorised scan).
   Error: max |F − F_ref| / max |F_ref| against scipy solve_ivp (Radau, rtol 1e-10) of the
   same ODE written out here.  Real-time factor: simulated time / wall time (best of 5).
2. One vectorised evaluation of 1e6 contacts: derivatives + force (+ an exact step) of the Θ
   law with per-contact normal forces, and of LuGre; the slower of the two is reported.

Targets: real-time factor >= 200 on one core, error <= 1 %, 1e6 contacts <= 0.1 s.  The laws
run through their compiled scalar kernels (sealsim.friction.kernels); the 1e6-contact figures are
also measured for the frozen numpy implementation of before (tests/reference_v0) in the same run.
The last line printed is one JSON object.
"""

from __future__ import annotations

import json
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from pydantic import TypeAdapter
from scipy.integrate import solve_ivp

from sealsim.friction import ContactInputs, LuGre, Theta
from sealsim.friction.bench import profile_type, simulate_velocity

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from reference_v0 import friction_laws as reference  # noqa: E402

DURATION = 10.0
V = TypeAdapter(profile_type("velocity"))


def best_of(fn, repeat=5):
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def lugre_case():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        law = LuGre.from_parameter_set("canudas1995")
    amp, w = 5e-3, np.pi                   # 5 mm/s, 0.5 Hz: Stribeck region and reversals
    prof = V.validate_python({"kind": "harmonic", "amplitude": amp, "angular_frequency": w,
                              "phase": -np.pi / 2})
    dt = 1e-3
    wall, res = best_of(lambda: simulate_velocity(law, prof, DURATION, dt))
    s0, s1, s2, fc, fs, vs = 1e5, np.sqrt(1e5), 0.4, 1.0, 1.5, 1e-3

    def rhs(t, z):
        v = amp * np.sin(w * t)
        g = fc + (fs - fc) * np.exp(-(v / vs) ** 2)
        return [v - s0 * abs(v) * z[0] / g]

    sol = solve_ivp(rhs, (0, DURATION), [0.0], method="Radau", rtol=1e-10, atol=1e-16,
                    t_eval=res.time, max_step=1e-3)
    v = res.velocity            # the sampled velocity (same value at the zero crossings)
    g = fc + (fs - fc) * np.exp(-(v / vs) ** 2)
    z = sol.y[0]
    f_ref = s0 * z + s1 * (v - s0 * np.abs(v) * z / g) + s2 * v
    err = np.max(np.abs(res.force - f_ref)) / np.max(np.abs(f_ref))
    return DURATION / wall, err, res.time.size - 1


def theta_case():
    law = Theta.from_parameter_set("pneumatic_demo")
    inputs = ContactInputs(normal_force=100.0, contact_width=1e-3)
    amp, w = 0.5, np.pi                    # 0.5 m/s, 0.5 Hz
    prof = V.validate_python({"kind": "harmonic", "amplitude": amp, "angular_frequency": w,
                              "phase": -np.pi / 2})
    dt = 1e-3
    wall, res = best_of(lambda: simulate_velocity(law, prof, DURATION, dt, inputs))
    p = law.params

    def rhs(t, th):
        v = amp * np.sin(w * t)
        return [-th[0] / p.tau + abs(v) / p.alpha * (1 - th[0])]

    sol = solve_ivp(rhs, (0, DURATION), [0.0], method="Radau", rtol=1e-10, atol=1e-14,
                    t_eval=res.time, max_step=1e-3)
    v = res.velocity            # sgn(v) at v = ±1e-16 must match: use the sampled velocity
    th = sol.y[0]
    f_ref = 100.0 * (p.f_a * (1 - th) + p.f_b * th) * np.sign(v) + p.gamma * 1e-3 * v
    err = np.max(np.abs(res.force - f_ref)) / np.max(np.abs(f_ref))
    return DURATION / wall, err, res.time.size - 1


def vectorised_case(n=1_000_000):
    rng = np.random.default_rng(0)
    v = rng.normal(0.0, 0.3, n)
    theta = Theta.from_parameter_set("pneumatic_demo")
    inputs = ContactInputs(normal_force=rng.uniform(50, 200, n), contact_width=1e-3)
    z = rng.uniform(0, 1, (1, n))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        lugre = LuGre.from_parameter_set("canudas1995")
    zl = rng.uniform(-1.5e-5, 1.5e-5, (1, n))
    vl = v * 1e-2
    inputs.require("normal_force", "theta", positive=True)   # input check once, as a solver

    def theta_eval():
        return theta.derivatives(z, v, inputs), theta.force(z, v, inputs)

    def theta_step():
        return theta.step(z, v, 1e-3, inputs)

    def lugre_eval():
        return lugre.derivatives(zl, vl), lugre.force(zl, vl)

    old_theta, old_lugre = reference.Theta(theta.params), reference.LuGre(lugre.params)

    def theta_eval_old():
        return old_theta.derivatives(z, v, inputs), old_theta.force(z, v, inputs)

    def theta_step_old():
        return old_theta.step(z, v, 1e-3, inputs)

    def lugre_eval_old():
        return old_lugre.derivatives(zl, vl), old_lugre.force(zl, vl)

    times = {name: best_of(fn)[0] for name, fn in
             [("theta_derivatives_force", theta_eval), ("theta_step", theta_step),
              ("lugre_derivatives_force", lugre_eval)]}
    baseline = {name: best_of(fn)[0] for name, fn in
                [("theta_derivatives_force", theta_eval_old), ("theta_step", theta_step_old),
                 ("lugre_derivatives_force", lugre_eval_old)]}
    return times, baseline


def mass_cases():
    """For information: the driven-mass benches (solve_ivp Radau; stick/slip stepper)."""
    from sealsim.friction.bench import simulate_mass

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        lugre = LuGre.from_parameter_set("canudas1995")
    drive = V.validate_python({"kind": "constant", "level": 0.1})
    t_ss, _ = best_of(lambda: simulate_mass(lugre, 1.0, 25.0, 1e-3, stiffness=2.0,
                                            drive_velocity=drive), repeat=2)
    theta = Theta.from_parameter_set("pneumatic_demo")
    inputs = ContactInputs(normal_force=100.0, contact_width=1e-3)
    drive = V.validate_python({"kind": "piecewise", "times": [0, 2, 2.001, 7, 7.001],
                               "values": [0.02, 0.02, 0.0, 0.0, 0.02]})
    t_dw, _ = best_of(lambda: simulate_mass(theta, 1.0, 9.0, 1e-3, stiffness=2000.0,
                                            drive_velocity=drive, inputs=inputs), repeat=2)
    print(f"LuGre stick-slip, 25 s (Radau, rtol 1e-7): real-time factor {25.0 / t_ss:.0f}x")
    print(f"Theta dwell, 9 s (stick/slip stepper, 1 ms): real-time factor {9.0 / t_dw:.0f}x")


def main():
    mass_cases()
    lugre_rt, lugre_err, lugre_steps = lugre_case()
    theta_rt, theta_err, theta_steps = theta_case()
    vec, vec_old = vectorised_case()
    print(f"LuGre : {lugre_steps} steps of 1 ms, real-time factor {lugre_rt:,.0f}x, "
          f"max rel. force error {lugre_err:.2e}")
    print(f"Theta : {theta_steps} steps of 1 ms, real-time factor {theta_rt:,.0f}x, "
          f"max rel. force error {theta_err:.2e}")
    for name, t in vec.items():
        print(f"1e6 contacts, {name}: {t * 1e3:.1f} ms (numpy implementation before: "
              f"{vec_old[name] * 1e3:.1f} ms)")
    result = {
        "lugre_realtime_factor": round(lugre_rt, 1),
        "theta_realtime_factor": round(theta_rt, 1),
        "lugre_max_rel_error": float(f"{lugre_err:.3e}"),
        "theta_max_rel_error": float(f"{theta_err:.3e}"),
        "vectorised_1e6_s": float(f"{max(vec.values()):.4f}"),
        "vectorised_1e6_baseline_s": float(f"{max(vec_old.values()):.4f}"),
    }
    print(json.dumps(result))


if __name__ == "__main__":
    main()
