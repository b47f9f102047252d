"""
Elastomer modulus against temperature
=====================================

Storage modulus E(T) of the catalogue elastomers: glassy below the glass transition T_g,
a transition region, rubbery above it.  Outside a material's service range the curve is
dashed.  The same chart comes from ``sealsim material plot NBR FKM VMQ --out DIR``.
"""

import warnings

import numpy as np

from sealsim.plotting.properties import modulus_temperature_figure
from sealsim.properties import get_elastomer

materials = [get_elastomer(name) for name in ("NBR", "FKM", "VMQ")]
temperature = np.linspace(123.15, 473.15, 351)  # -150 ... 200 °C in kelvin
modulus = {}
for m in materials:
    low, high = m.allowed_range  # where the material model is meaningful
    inside = (temperature >= low) & (temperature <= high)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # outside the service range: drawn dashed
        modulus[m.name] = np.full(temperature.shape, np.nan)  # NaN: not drawn
        modulus[m.name][inside] = m.modulus(temperature[inside])
fig = modulus_temperature_figure(
    temperature, modulus,
    glass_transition={m.name: m.glass_transition for m in materials},
    service_range={m.name: m.service_range for m in materials})
