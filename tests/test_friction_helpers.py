"""Shared constructors for the friction tests (no tests in this module)."""

from __future__ import annotations

import warnings

import numpy as np

from sealsim.friction import GMS, ContactInputs, CoulombViscous, Dahl, LuGre, Stribeck, Theta

THETA_INPUTS = ContactInputs(normal_force=100.0, contact_width=1e-3)
NO = ContactInputs()


def classic_lugre() -> LuGre:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return LuGre.from_parameter_set("canudas1995")


def passive_lugre() -> LuGre:
    """Table I with σ2 raised above σ1(F_S−F_C)/F_C = 158 N·s/m (Åström 2008 Eq. 7)."""
    return LuGre(sigma0=1e5, sigma1=np.sqrt(1e5), sigma2=200.0, coulomb_force=1.0,
                 static_force=1.5, stribeck_velocity=1e-3)


def all_laws():
    """(id, law, inputs) for every law, with parameters that make each passive."""
    return [
        ("coulomb", CoulombViscous(coulomb_force=1.0, viscous_coefficient=0.4), NO),
        ("stribeck", Stribeck(coulomb_force=1.0, static_force=1.5, stribeck_velocity=1e-3,
                              exponent=2.0, viscous_coefficient=0.4,
                              pressure_coefficient=1e-6),
         ContactInputs(pressure_a=2e5, pressure_b=1e5)),
        ("lugre", passive_lugre(), NO),
        ("lugre_sigma1_0", LuGre(sigma0=1e5, sigma1=0.0, sigma2=0.4, coulomb_force=1.0,
                                 static_force=1.5, stribeck_velocity=1e-3), NO),
        ("dahl", Dahl(sigma0=1e5, coulomb_force=1.0), NO),
        ("dahl_alpha2", Dahl(sigma0=1e5, coulomb_force=1.0, exponent=2.0), NO),
        ("gms", GMS.from_parameter_set("canudas1995"), NO),
        ("theta", Theta.from_parameter_set("pneumatic_demo"), THETA_INPUTS),
        ("theta_bristle", Theta.from_parameter_set("pneumatic_demo", bristle_stiffness=1e6),
         THETA_INPUTS),
    ]


def velocity_scale(law_id: str) -> float:
    """A typical sliding speed of each law's parameter set [m/s]."""
    return 0.1 if law_id.startswith("theta") else 1e-3
