"""
Speed cycle of a radial lip seal: plain vs wave lip
===================================================

``speed_cycle.toml`` steps a Ø80 mm NBR lip seal in VG 68 from 10 to 1000 rpm and holds
1000 rpm for an hour, once with a plain lip and once with a wave lip (two variants).  The
friction torque and the temperatures come from the coupled friction and heat model; this is
what ``sealsim rotary run speed_cycle.toml --out DIR`` computes, here from Python.
"""

from sealsim.plotting.rotary import cycle_figure, variants_figure
from sealsim.rotary.simulation import simulate
from sealsim.rotary.simulation import load_rotary_case

cases = load_rotary_case("speed_cycle.toml")  # {"plain": RotaryCase, "wave": RotaryCase}
results = {name: simulate(case) for name, case in cases.items()}

# %%
# Speed, torque (lubricant shear and rubber parts) and temperatures of the wave lip:
wave = results["wave"]
fig = cycle_figure(wave.timeseries, wave.case.seal.shaft_diameter / 2, "wave lip")

# %%
# Both lips side by side:
fig = variants_figure({name: r.timeseries for name, r in results.items()}, "plain vs wave")

# %%
# The last step (averages over its last 30 s) of each variant:
for name, r in results.items():
    last = r.steps[-1]
    print(f"{name:6s} {last['speed_rpm']:.0f} rpm: torque {last['torque_Nm']:.3f} N m, "
          f"contact {last['T_contact_C']:.1f} °C, spring groove {last['T_groove_C']:.1f} °C")
