"""Allowed ranges of an oil's values, shared by the :class:`~sealsim.properties.oils.Oil`
record and the oil-file model of :mod:`sealsim.properties.catalogue` (which names a value
outside them as the file writes it, ``density15``, not as the record does, ``rho15``)."""

from __future__ import annotations

__all__ = ["EXPANSION_MAX", "PRESSURE_VISCOSITY_MAX", "RHO15_RANGE", "SPECIFIC_HEAT_RANGE",
           "THERMAL_CONDUCTIVITY_RANGE"]

#: Density at 15 degC [kg/m^3].
RHO15_RANGE = (600.0, 1300.0)
#: A constant thermal conductivity [W/(m K)] and specific heat [J/(kg K)].
THERMAL_CONDUCTIVITY_RANGE = (0.05, 0.5)
SPECIFIC_HEAT_RANGE = (1000.0, 4000.0)
#: Upper limits of the thermal expansion coefficient [1/K] and of Barus' alpha [1/Pa] (oils:
#: 1e-8 to 3.5e-8).
EXPANSION_MAX = 2e-3
PRESSURE_VISCOSITY_MAX = 1e-7
