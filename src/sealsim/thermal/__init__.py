"""Heat transfer: axisymmetric finite-volume conduction and convection correlations.

* :mod:`.conduction` -- transient conduction on a structured (r, z) grid of ring cells with
  lumped and fixed-temperature nodes, backward Euler with exact energy bookkeeping
  (:class:`AxisymmetricConduction`, :class:`ThermalNetwork`, :class:`BackwardEulerStepper`);
* :mod:`.convection` -- heat transfer coefficients of rotating shafts in open fluid (Kays &
  Bjorklund) and in an annulus (Taylor–Couette, Staton & Cavagnino), free convection
  (Churchill & Chu), radiation, air properties.

>>> from sealsim.thermal import rotating_cylinder_coefficient
>>> round(float(rotating_cylinder_coefficient(157.0, 0.06, 1e-4, 0.13, 1200.0)))
972
"""

from sealsim.thermal.conduction import (
    AxisymmetricConduction,
    BackwardEulerStepper,
    BoundaryFaces,
    Link,
    Solid,
    ThermalNetwork,
    factorise,
    graded_edges,
)
from sealsim.thermal.convection import (
    STEFAN_BOLTZMANN,
    air_properties,
    free_convection_horizontal_cylinder,
    free_convection_vertical_plate,
    radiation_coefficient,
    rayleigh_number,
    rotating_annulus_coefficient,
    rotating_annulus_nusselt,
    rotating_cylinder_coefficient,
    rotating_cylinder_nusselt,
    taylor_number,
)

__all__ = [
    "STEFAN_BOLTZMANN",
    "AxisymmetricConduction",
    "BackwardEulerStepper",
    "BoundaryFaces",
    "Link",
    "Solid",
    "ThermalNetwork",
    "air_properties",
    "factorise",
    "free_convection_horizontal_cylinder",
    "free_convection_vertical_plate",
    "graded_edges",
    "radiation_coefficient",
    "rayleigh_number",
    "rotating_annulus_coefficient",
    "rotating_annulus_nusselt",
    "rotating_cylinder_coefficient",
    "rotating_cylinder_nusselt",
    "taylor_number",
]
