"""Seals of the cylinder: a friction law plus the source of its contact load.

Heipl & Murrenhoff Fig. 1: piston seals separate the chambers, the rod seal separates chamber 2
from the atmosphere, the wiper keeps dirt out (no pressure across it).  Every seal is a
:class:`~sealsim.friction.base.FrictionLaw` of :mod:`sealsim.friction` (Coulomb, Stribeck,
LuGre, Dahl, GMS, Θ) with the inputs of :class:`~sealsim.friction.base.ContactInputs`:

* ``normal_force`` F_N and ``contact_width`` b from the seal's contact map
  (:mod:`.contact_maps`) at the pressure difference across the seal
  (:func:`seal_pressure_difference`) and the seal temperature;
* ``pressure_a``, ``pressure_b``: the gauge pressures on the two sides
  (:func:`seal_side_pressures`, for the pressure scaling F_C = F_pr + f·(p_A + p_B) of Heipl &
  Murrenhoff Eq. 3 in the Stribeck and Coulomb laws);
* ``temperature``: the seal temperature.

All seals slide with the piston velocity v.  Seal temperature: by default the seal bulk keeps
the temperature of the cylinder (the test rig of Heipl & Murrenhoff heats the whole assembly), a
constant per seal -- right for short runs, since the metal parts that set the seal temperature heat
with time constants of minutes; with seal heating (:mod:`.seal_heating`) each seal is a thermal node
heated by its friction.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from sealsim.friction.base import FrictionLaw

__all__ = ["LOCATIONS", "Seal", "pressure_difference", "seal_pressure_difference",
           "seal_side_pressures", "side_pressures", "smooth_abs"]

#: where a seal sits: the piston (between the chambers), the rod (chamber 2 | atmosphere), or
#: the wiper (atmosphere on both sides)
LOCATIONS = ("piston", "rod", "wiper")


def smooth_abs(x, eps):
    """|x| rounded at 0 over the width eps: x·tanh(x/ε) (C∞, >= 0, exact for |x| >> ε).

    The error |x| − x·tanh(x/ε) is at most 0.28·ε (near |x| ≈ ε) and decays like
    2|x|·exp(−2|x|/ε).

    Parameters
    ----------
    x : array_like
        Value.
    eps : float
        Rounding width ε > 0 (same unit as x).

    Examples
    --------
    >>> smooth_abs(np.array([-6e5, 0.0, 1e3]), 1e3).round(1).tolist()
    [600000.0, 0.0, 761.6]
    """
    return x * np.tanh(x / eps)


def seal_pressure_difference(location, p1, p2, ambient_pressure, eps=1e3):
    """Pressure difference across a seal [Pa] (>= 0, smooth).

    * piston seal: |p1 − p2|;
    * rod seal: |p2 − p_a|;
    * wiper: 0.

    The magnitude is taken smoothly (:func:`smooth_abs`, ε = 1 kPa) so that F_N(Δp) has no
    kink when the pressures cross (e.g. at every valve switch) -- an O-ring is energised from
    whichever side has the higher pressure.

    Parameters
    ----------
    location : {"piston", "rod", "wiper"}
        Where the seal sits.
    p1, p2 : float or ndarray
        Absolute chamber pressures (cap side, rod side) [Pa].
    ambient_pressure : float
        Atmospheric pressure [Pa].
    eps : float
        Rounding width [Pa].

    Examples
    --------
    >>> float(seal_pressure_difference("rod", 3e5, 7e5, 1e5))
    600000.0
    """
    return pressure_difference(LOCATIONS.index(location), p1, p2, ambient_pressure, eps)


def pressure_difference(code, p1, p2, ambient_pressure, eps=1e3):
    """:func:`seal_pressure_difference` for a location code (index in :data:`LOCATIONS`)."""
    return ((code == 0) * smooth_abs(p1 - p2, eps)
            + (code == 1) * smooth_abs(p2 - ambient_pressure, eps))


def seal_side_pressures(location, p1, p2, ambient_pressure):
    """Gauge pressures (p_A, p_B) on the two sides of a seal [Pa] (Heipl & Murrenhoff Eq. 3 inputs).

    Piston seal: (p1 − p_a, p2 − p_a); rod seal: (p2 − p_a, 0); wiper: (0, 0).

    Examples
    --------
    >>> [float(p) for p in seal_side_pressures("rod", 3e5, 7e5, 1e5)]
    [600000.0, 0.0]
    """
    return side_pressures(LOCATIONS.index(location), p1, p2, ambient_pressure)


def side_pressures(code, p1, p2, ambient_pressure):
    """:func:`seal_side_pressures` for a location code (index in :data:`LOCATIONS`)."""
    piston, rod = code == 0, code == 1
    return (piston * (p1 - ambient_pressure) + rod * (p2 - ambient_pressure),
            piston * (p2 - ambient_pressure))


@dataclass
class Seal:
    """One seal of the cylinder.

    Parameters
    ----------
    name : str
        Label used in the results (column names ``F_N_<name>_N`` etc.).
    location : {"piston", "rod", "wiper"}
        Where it sits (decides the pressure difference across it).
    law : FrictionLaw
        The friction law.
    contact_map : ContactMap, optional
        Source of F_N and b; required by laws that use them (Θ).
    temperature : float
        Seal temperature [K].
    notes : list of str
        Warnings raised when the law was built (e.g. LuGre passivity), reported with the
        results.
    friction_table : SteadyFrictionTable, optional
        The seal's steady friction from its contact (a Θ law with ``steady = "contact"``,
        :mod:`sealsim.pneumatic.friction_tables`).
    """

    name: str
    location: str
    law: FrictionLaw
    contact_map: Any = None
    temperature: float = 293.15
    notes: list = field(default_factory=list)
    friction_table: Any = None

    @property
    def n_states(self) -> int:
        return self.law.n_states

    @property
    def has_stiction(self) -> bool:
        return bool(self.law.has_stiction)

    @property
    def location_code(self) -> int:
        return LOCATIONS.index(self.location)

    def loads(self, p1, p2, ambient_pressure):
        """(F_N [N], b [m], Δp [Pa]) at the chamber pressures; (nan, nan, Δp) without a map."""
        return self.loads_at(seal_pressure_difference(self.location, p1, p2, ambient_pressure))

    def loads_at(self, dp):
        """(F_N [N], b [m], Δp [Pa]) at the pressure difference Δp across the seal."""
        if self.contact_map is None:
            nan = np.full(np.shape(dp), np.nan)
            return nan, nan, dp
        fast = self.__dict__.get("_loads")
        if fast is None or fast[0] != self.temperature:
            bind = getattr(self.contact_map, "loads_function", None)
            fast = self.__dict__["_loads"] = (self.temperature, bind(self.temperature) if bind
                                              else lambda p: self.contact_map.evaluate(
                                                  p, self.temperature))
        fn, b = fast[1](dp)
        return fn, b, dp
