"""Dynamic friction laws of seals behind one state-space interface.

=================  ================================================  ===========  ===========
law (case name)    class                                             states       true stick
=================  ================================================  ===========  ===========
``coulomb``        :class:`CoulombViscous` (+ pressure scaling)      none         yes
``stribeck``       :class:`Stribeck` (Heipl & Murrenhoff Eq. 2/3)    none         yes
``lugre``          :class:`LuGre` (Canudas de Wit et al. 1995)       z            no
``dahl``           :class:`Dahl` (Dahl 1968)                         z            no
``gms``            :class:`GMS` (Al-Bender et al. 2005)              z_1..z_N     no
``theta``          :class:`Theta` (Heipl & Murrenhoff Eq. 4/5, [R])  Θ (, z)      yes (no with
                                                                                  bristles)
=================  ================================================  ===========  ===========

Every law is a :class:`~sealsim.friction.base.FrictionLaw`: ``initial_state(n)``,
``derivatives(z, v, inputs)``, ``force(z, v, inputs)``, ``partials(...)``, ``step(z, v, dt,
inputs)`` (exact for a velocity held over the step), ``trajectory(...)``, ``steady_force(v,
inputs)`` and, with true sticking, ``breakaway_force(z, inputs)``.  The physics lives in small
pure functions in each module (``lugre_bristle_rate``, ``theta_rate``, ...), which the law objects
compose.  :mod:`sealsim.friction.hybrid` resolves sticking, :mod:`sealsim.friction.bench`
simulates test benches, :mod:`sealsim.friction.case` reads case files.

>>> import numpy as np
>>> from sealsim.friction import Theta, ContactInputs
>>> law = Theta.from_parameter_set("pneumatic_demo")
>>> inputs = ContactInputs(normal_force=np.array([60.0, 150.0]), contact_width=1e-3)
>>> law.steady_state([0.1, 0.1], inputs).round(3)   # the higher load stays drier
array([[0.769, 0.571]])
"""

from sealsim.friction.base import (
    ContactInputs,
    FrictionLaw,
    FrictionWarning,
    Partials,
    PassivityWarning,
    affine_scan,
)
from sealsim.friction.dahl import Dahl, DahlParameters
from sealsim.friction.gms import GMS, GMSParameters
from sealsim.friction.lugre import LuGre, LuGreParameters
from sealsim.friction.parameters import PARAMETER_SETS
from sealsim.friction.stribeck import (
    CoulombParameters,
    CoulombViscous,
    Stribeck,
    StribeckParameters,
)
from sealsim.friction.theta import Theta, ThetaParameters

#: law name -> (law class, parameter model)
LAWS = {
    "coulomb": (CoulombViscous, CoulombParameters),
    "stribeck": (Stribeck, StribeckParameters),
    "lugre": (LuGre, LuGreParameters),
    "dahl": (Dahl, DahlParameters),
    "gms": (GMS, GMSParameters),
    "theta": (Theta, ThetaParameters),
}


def make_law(params, **kwargs) -> FrictionLaw:
    """The law object for a validated parameter model (any of the ``*Parameters``)."""
    cls, _ = LAWS[params.law]
    return cls(params, **kwargs)


__all__ = [
    "LAWS",
    "PARAMETER_SETS",
    "ContactInputs",
    "CoulombParameters",
    "CoulombViscous",
    "Dahl",
    "DahlParameters",
    "FrictionLaw",
    "FrictionWarning",
    "GMS",
    "GMSParameters",
    "LuGre",
    "LuGreParameters",
    "Partials",
    "PassivityWarning",
    "Stribeck",
    "StribeckParameters",
    "Theta",
    "ThetaParameters",
    "affine_scan",
    "make_law",
]
