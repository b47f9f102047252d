"""
LuGre velocity hysteresis (Canudas de Wit et al. 1995)
======================================================

The benchmark of Canudas de Wit et al. (1995), Fig. 3: the sliding velocity oscillates
without reversing at three frequencies.  The friction lags behind the velocity, so the
force-velocity loop around the steady Stribeck curve (dashed) opens up as the frequency grows.
"""

import warnings

import numpy as np

from sealsim.cases import load_toml
from sealsim.friction.case import build_law, load_friction_cases, make_inputs, run_friction_case
from sealsim.plotting.friction import last_cycles, plot_force_velocity

cases = load_friction_cases(load_toml("lugre_hysteresis.toml"))
results = {}
for name, case in cases.items():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the published set is not passive (see the case file)
        law = build_law(case)
    results[name], _ = run_friction_case(case, law)

case = next(iter(cases.values()))
v = np.linspace(0.0, max(r.velocity.max() for r in results.values()), 200)[1:]
steady = {name: (v, law.steady_force(v, make_inputs(case))) for name in last_cycles(results)}
fig = plot_force_velocity(last_cycles(results), steady, case.title)
