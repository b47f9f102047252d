"""Speed and accuracy of the friction laws.

1. 10 s of LuGre (1995 Table I set) and of the Θ law (pneumatic_demo set) under a sinusoidal
   velocity that reverses, run with the bench (exact step per time step, vectorised scan).
   Error: max |F − F_ref| / max |F_ref| against scipy solve_ivp (Radau, rtol 1e-10) of the
   same ODE written out here.  Real-time factor: simulated time / wall time (best of 5).
2. One vectorised evaluation of 1e6 contacts: derivatives + force (+ an exact step) of the Θ
   law with per-contact normal forces, and of LuGre; the slower of the two is reported.

3. The stick-slip examples (see :func:`mass_cases`) against the integrators of before.

Targets: real-time factor >= 200 on one core, error <= 1 %, 1e6 contacts <= 0.1 s and (issue
27) <= the numpy implementation they replaced, the stick-slip examples >= 100x real time.  The
laws run through their compiled scalar kernels (sealsim.friction.kernels); the 1e6-contact
figures are also measured for the frozen numpy implementation of before (tests/reference_v0) in
the same run.  The last line printed is one JSON object.
"""

from __future__ import annotations

import json
import os
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


class _NumpyTheta(Theta):
    """The Θ law as an object of its own class: simulate_mass runs it through the vectorised
    stepper of sealsim.friction.hybrid (the stepper of before issue 27)."""


def mass_cases():
    """The stick-slip examples: examples/friction/lugre_stick_slip.toml (25 s, compiled BDF, with
    solve_ivp Radau -- the integrator before issue 27 -- as the baseline in the same run) and
    the dwell_5s variant of theta_dwell.toml (9 s, the compiled stick/slip stepper at 1 ms,
    against the vectorised stepper of sealsim.friction.hybrid -- the stepper of before issue
    27, numpy calls per step -- in the same run)."""
    from sealsim.friction.bench import simulate_mass, summarize

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        lugre = LuGre.from_parameter_set("canudas1995")
    drive = V.validate_python({"kind": "constant", "level": 0.1})

    def lugre_run(integrator):
        return simulate_mass(lugre, 1.0, 25.0, 1e-3, stiffness=2.0, drive_velocity=drive,
                             integrator=integrator)

    lugre_run("auto")                                   # load the compiled code
    t_ss, new = best_of(lambda: lugre_run("auto"), repeat=3)
    t_ss_old, old = best_of(lambda: lugre_run("radau"), repeat=1)
    period_diff = abs(summarize(new)["stick_slip_period_s"] / summarize(old)[
        "stick_slip_period_s"] - 1.0)
    force_diff = abs(new.force.max() / old.force.max() - 1.0)
    theta = Theta.from_parameter_set("pneumatic_demo")
    inputs = ContactInputs(normal_force=100.0, contact_width=1e-3)
    drive = V.validate_python({"kind": "piecewise", "times": [0, 2, 2.001, 7, 7.001],
                               "values": [0.02, 0.02, 0.0, 0.0, 0.02]})

    def dwell_run():
        return simulate_mass(theta, 1.0, 9.0, 1e-3, stiffness=2000.0, drive_velocity=drive,
                             inputs=inputs)

    dwell_run()
    t_dw, dwell = best_of(dwell_run, repeat=3)
    old_theta = _NumpyTheta(theta.params)
    t_dw_old, dwell_old = best_of(lambda: simulate_mass(old_theta, 1.0, 9.0, 1e-3,
                                                        stiffness=2000.0, drive_velocity=drive,
                                                        inputs=inputs), repeat=1)
    dwell_diff = float(np.max(np.abs(dwell.force - dwell_old.force)))
    print(f"LuGre stick-slip, 25 s (compiled BDF, rtol 1e-7): real-time factor "
          f"{25.0 / t_ss:.0f}x (solve_ivp Radau before: {25.0 / t_ss_old:.1f}x); period and "
          f"largest force differ by {period_diff:.1e} and {force_diff:.1e} (relative)")
    print(f"Theta dwell, 9 s (compiled stick/slip stepper, 1 ms): real-time factor "
          f"{9.0 / t_dw:.0f}x (stepper before: {9.0 / t_dw_old:.1f}x); largest force "
          f"difference {dwell_diff:.1e} N")
    return {"lugre_stick_slip_realtime_factor": round(25.0 / t_ss, 1),
            "lugre_stick_slip_baseline_realtime_factor": round(25.0 / t_ss_old, 2),
            "lugre_stick_slip_period_rel_difference": float(f"{period_diff:.2e}"),
            "theta_dwell_realtime_factor": round(9.0 / t_dw, 1),
            "theta_dwell_baseline_realtime_factor": round(9.0 / t_dw_old, 2),
            "theta_dwell_force_difference_N": float(f"{dwell_diff:.2e}")}


def main():
    print(f"load average (1 min) {os.getloadavg()[0]:.2f}")
    mass = mass_cases()
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
        **{f"{name}_1e6_s": float(f"{t:.4f}") for name, t in vec.items()},
        **{f"{name}_1e6_baseline_s": float(f"{t:.4f}") for name, t in vec_old.items()},
        **mass,
        "load_average": round(os.getloadavg()[0], 2),
    }
    print(json.dumps(result))


if __name__ == "__main__":
    main()
