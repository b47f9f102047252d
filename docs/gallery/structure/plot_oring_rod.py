"""
O-ring rod seal: contact under squeeze and pressure
===================================================

``oring_rod.toml`` squeezes an NBR O-ring 20 × 4 mm onto a 20 mm rod and then pressurises
it (axisymmetric hyperelastic FE with FElupe).  To keep this page quick the script solves a
shortened load path on a coarse mesh: 15 % squeeze, then 6 bar.  ``sealsim structure run
oring_rod.toml --out DIR`` runs the full case.
"""

from sealsim.cases import apply_overrides, load_toml, validate_case
from sealsim.plotting.structure import plot_section, plot_states
from sealsim.structure.case import StructureCase
from sealsim.structure.results import results_frame
from sealsim.structure.run import run_case

data = apply_overrides(load_toml("oring_rod.toml"), {
    "mesh": {"level": "coarse"},
    "load": {"squeeze": [0.15], "pressure": ["0 bar", "6 bar"]}})
case = validate_case(StructureCase, data, "oring_rod.toml (shortened)")
result = run_case(case)

# %%
# The deformed section at 6 bar, coloured by von Mises stress, and the contact pressure on
# the rod and on the groove bottom:
fig = plot_section(result.states[-1], "15 % squeeze, 6 bar")

# %%
# Normal force, contact width and peak contact pressure on the rod at each load state:
frame = results_frame(result.states)
print(frame[["squeeze_percent", "pressure_bar", "F_N_N", "b_mm", "p_max_MPa"]].round(3).to_string())
