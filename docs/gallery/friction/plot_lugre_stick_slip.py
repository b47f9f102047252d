"""
LuGre stick-slip (Canudas de Wit et al. 1995)
=============================================

The benchmark of Canudas de Wit et al. (1995), Fig. 7: a 1 kg body is pulled through a soft
spring whose end moves at constant speed.  The spring force builds up while the body sticks,
the body breaks away near the static friction force, slips and sticks again: a stick-slip
limit cycle.
"""

import warnings

from sealsim.cases import load_toml
from sealsim.friction.case import build_law, load_friction_cases, run_friction_case
from sealsim.plotting.friction import plot_timeseries

cases = load_friction_cases(load_toml("lugre_stick_slip.toml"))
results, summaries = {}, {}
for name, case in cases.items():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the published set is not passive (see the case file)
        law = build_law(case)
    results[name], summaries[name] = run_friction_case(case, law)
fig = plot_timeseries(results, next(iter(cases.values())).title)

# %%
# The stick-slip period and the break-away forces found in the time series:
for name, summary in summaries.items():
    print(name, {key: summary[key] for key in ("stick_slip_period_s", "breakaway_forces_N")
                 if key in summary})
