"""
Θ law: steady Stribeck-like curve
=================================

A slow velocity sweep follows the closed-form steady curve of the Θ rate-and-state law
(dashed); a fast sweep shows the frictional lag of the film state around it.
"""

import numpy as np

from sealsim.cases import load_toml
from sealsim.friction.case import build_law, load_friction_cases, make_inputs, run_friction_case
from sealsim.plotting.friction import plot_force_velocity, plot_theta_velocity

cases = load_friction_cases(load_toml("theta_stribeck.toml"))
results, steady_force, steady_theta = {}, {}, {}
for name, case in cases.items():
    law = build_law(case)
    results[name], _ = run_friction_case(case, law)
    vmax = np.abs(results[name].velocity).max()
    v = np.linspace(-vmax, vmax, 401)
    steady_force[name] = (v, law.steady_force(v, make_inputs(case)))
    steady_theta[name] = (v, law.steady_state(v, make_inputs(case))[0])

title = next(iter(cases.values())).title
fig = plot_force_velocity(results, steady_force, title)

# %%
# The film state Θ (0 dry, 1 full film) against the velocity:
fig = plot_theta_velocity(results, steady_theta, title)
