"""
Oil viscosity against temperature
=================================

Kinematic viscosity of catalogue gear oils on ASTM D341 chart axes, where the Walther
equation ``log log(ν + 0.7) = A − B·log T`` of each oil is a straight line through its
datasheet values at 40 and 100 °C.  The same chart comes from
``sealsim oil plot VG68-mineral VG220-mineral VG220-PAO --out DIR``.
"""

import numpy as np

from sealsim.plotting.properties import viscosity_temperature_figure
from sealsim.properties import get_oil

oils = [get_oil(name) for name in ("VG68-mineral", "VG220-mineral", "VG220-PAO")]
temperature = np.linspace(273.15, 423.15, 151)  # 0 ... 150 °C in kelvin
viscosity = {oil.name: oil.kinematic_viscosity(temperature) for oil in oils}
datasheet = {oil.name: (np.array([313.15, 373.15]), np.array([oil.nu40, oil.nu100]))
             for oil in oils}
fig = viscosity_temperature_figure(temperature, viscosity, points=datasheet)

# %%
# The viscosity index (ASTM D2270) of each oil, from the same two datasheet values:
for oil in oils:
    print(f"{oil.name:14s} nu40 = {oil.nu40 * 1e6:5.0f} mm2/s, nu100 = {oil.nu100 * 1e6:5.1f} "
          f"mm2/s, VI = {oil.viscosity_index:.0f}")
