"""
Pneumatic cylinder with seal friction at 25 and 55 °C
=====================================================

``cylinder_32.toml``: a Ø32 mm double-acting cylinder driven by a 5/2 valve and a PLC cycle;
its piston and rod seals follow the Θ rate-and-state friction law with F_N and b from an
analytic O-ring contact map, at two seal temperatures (two variants).  This is what
``sealsim pneumatic run cylinder_32.toml --out DIR`` computes, here from Python.
"""

from sealsim.pneumatic.case import load_pneumatic_case_file
from sealsim.pneumatic.simulation import run_cases
from sealsim.plotting.pneumatic import pressure_stroke_figure, timeseries_figure

cases = load_pneumatic_case_file("cylinder_32.toml")
results = run_cases(cases)
frames = {name: r.timeseries for name, r in results.items()}

# %%
# Chamber pressures and stroke over time, both seal temperatures:
fig = pressure_stroke_figure(frames, next(iter(cases.values())).title)

# %%
# Everything the simulation records for the first variant:
name, result = next(iter(results.items()))
fig = timeseries_figure(result.timeseries, result.seal_names, name)

# %%
# The summary numbers of each variant:
for name, result in results.items():
    s = result.summary()
    print(f"{name}: extend {s['extend_time_s']:.3f} s, retract {s['retract_time_s']:.3f} s, "
          f"mean friction {s['mean_friction_N']:.1f} N")
