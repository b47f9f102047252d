"""Viscous (Couette) shear of the lubricant film in the lip contact (Organisciak et al., AGMA
14FTM14, 2014, Eq. 4)."""

from __future__ import annotations

import numpy as np

__all__ = ["duty_parameter", "viscous_friction_force"]


def viscous_friction_force(viscosity, speed, film, area):
    """Couette shear force of the film, F_lub = η·u/h_e·S_contact (Organisciak et al.
    2014, Eq. 4).

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity in the contact η [Pa·s].
    speed : array_like
        Sliding speed u [m/s]; the force has the sign of u (it opposes the shaft's motion
        relative to the lip when applied to the shaft with a minus sign).
    film : array_like
        Effective film thickness h_e [m] (> 0).
    area : array_like
        Sheared contact area S_contact = π·D·b [m²].

    Returns
    -------
    numpy.ndarray
        F_lub [N].

    Examples
    --------
    >>> round(float(viscous_friction_force(0.0124, 6.28, 0.61e-6, 3.77e-5)), 2)
    4.81
    """
    return (np.asarray(viscosity, dtype=float) * np.asarray(speed, dtype=float)
            / np.asarray(film, dtype=float) * np.asarray(area, dtype=float))


def duty_parameter(viscosity, angular_speed, contact_width, load_per_length):
    """Duty parameter G = η·ω·b / W' of lip seal friction (Gümbel number η·ω/p̄).

    Used to plot lip seal friction as a Stribeck-type curve μ_eff(G) (Horve 1992; Haas, cited
    in Organisciak et al. 2014, Fig. 1); G equals η·ω/p̄ because p̄ = W'/b.

    Parameters
    ----------
    viscosity : array_like
        η [Pa·s].
    angular_speed : array_like
        ω [rad/s].
    contact_width : array_like
        b [m].
    load_per_length : array_like
        Radial lip load per unit circumference W' = F_r/(π·D) [N/m].

    Returns
    -------
    numpy.ndarray
        G [-].

    Examples
    --------
    >>> f"{float(duty_parameter(0.0124, 157.1, 0.15e-3, 119.4)):.2e}"
    '2.45e-06'
    """
    return (np.asarray(viscosity, dtype=float) * np.asarray(angular_speed, dtype=float)
            * np.asarray(contact_width, dtype=float) / np.asarray(load_per_length, dtype=float))
