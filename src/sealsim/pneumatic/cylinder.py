r"""Double-acting cylinder: geometry, piston dynamics, end stops, external load.

Conventions: the piston position x [m] runs from 0 (retracted, against the cap) to the stroke L
(extended); v = dx/dt > 0 extends.  Chamber 1 (port A) is the cap side with the full piston area
A1 = π/4·D²; chamber 2 (port B) the rod side with the annulus A2 = π/4·(D² − d²).  The rod leaves
the cylinder into the atmosphere, which pushes on the rod cross-section A_r = A1 − A2.

Piston dynamics (Heipl & Murrenhoff Eq. 1; Richer & Hurmuzlu 2000)::

    M·dv/dt = p1·A1 − p2·A2 − p_a·A_r − F_load(x, v) − F_friction + F_stop(x, v)

with the moving mass M = piston and rod + load mass, the load force F_load (constant force,
spring, gravity with the orientation of the axis) and the end-stop contact force F_stop.

**End stops** are stiff spring–damper contacts (elastic bumper rings), not velocity resets (the
reinit approach of Modelica's MassWithStopAndFriction is fragile: Modelica Standard Library
issues #20 and #4403).  With the penetration δ > 0 into a stop::

    F_stop = max(0, k·δ + c·δ̇·δ/(δ + δ_c))

The damping is faded in over the depth δ_c (Hunt & Crossley 1975 idea: no force jump at
contact, the force vanishes with δ) and the contact never pulls (max(0, ·)).  A piston resting
against a stop under a force F sits at δ = F/k.

References
----------
.. [1] O. Heipl, H. Murrenhoff, "Rate- and state-dependent friction model for elastomeric
   seals", Eq. 1.
.. [2] E. Richer, Y. Hurmuzlu, J. Dyn. Sys. Meas. Control 122(3), 416-425, 2000.
.. [3] K. H. Hunt, F. R. E. Crossley, "Coefficient of restitution interpreted as damping in
   vibroimpact", J. Appl. Mech. 42(2), 440-445, 1975.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "GRAVITY",
    "chamber_volumes",
    "end_stop_force",
    "load_force",
    "piston_areas",
    "piston_force",
    "rest_position",
]

#: Standard gravity [m/s²]
GRAVITY = 9.80665


def piston_areas(bore, rod_diameter):
    """Effective areas of a double-acting cylinder with a single rod.

    Parameters
    ----------
    bore : float
        Bore (piston diameter) D [m].
    rod_diameter : float
        Rod diameter d [m], 0 <= d < D.

    Returns
    -------
    a1, a2, a_rod : float
        Cap-side area π/4·D², rod-side annulus π/4·(D² − d²), rod section π/4·d² [m²].

    Examples
    --------
    >>> [round(a * 1e4, 3) for a in piston_areas(0.032, 0.012)]   # [cm²]
    [8.042, 6.912, 1.131]
    """
    a1 = math.pi / 4.0 * bore ** 2
    a_rod = math.pi / 4.0 * rod_diameter ** 2
    return a1, a1 - a_rod, a_rod


def chamber_volumes(x, stroke, a1, a2, dead_volume_1, dead_volume_2):
    """Volumes of the two chambers at the piston position x.

    .. math:: V_1 = V_{01} + A_1 x, \\qquad V_2 = V_{02} + A_2 (L - x)

    Parameters
    ----------
    x : float or ndarray
        Piston position [m] (0 retracted, L extended).
    stroke : float
        L [m].
    a1, a2 : float
        Piston areas [m²].
    dead_volume_1, dead_volume_2 : float
        Dead volumes at the end positions (ports, tubing to the valve, cushion) [m³].

    Returns
    -------
    v1, v2 : ndarray
        [m³].

    Examples
    --------
    >>> v1, v2 = chamber_volumes(0.05, 0.1, 8e-4, 7e-4, 5e-6, 5e-6)
    >>> round(float(v1) * 1e6, 3), round(float(v2) * 1e6, 3)
    (45.0, 40.0)
    """
    return dead_volume_1 + a1 * x, dead_volume_2 + a2 * (stroke - x)


def piston_force(p1, p2, ambient_pressure, a1, a2, a_rod):
    """Net pressure force on the piston in the extend direction, p1·A1 − p2·A2 − p_a·A_r.

    Parameters
    ----------
    p1, p2 : float or ndarray
        Absolute chamber pressures [Pa].
    ambient_pressure : float
        p_a [Pa] acting on the rod end.
    a1, a2, a_rod : float
        Areas [m²].

    Returns
    -------
    ndarray
        Force [N].

    Examples
    --------
    >>> a1, a2, ar = piston_areas(0.032, 0.012)
    >>> round(float(piston_force(7.013e5, 1.013e5, 1.013e5, a1, a2, ar)), 1)   # 6 bar gauge
    482.5
    """
    return p1 * a1 - p2 * a2 - ambient_pressure * a_rod


def end_stop_force(x, v, stroke, stiffness, damping, damping_depth=5e-5):
    """Contact force of the two end stops on the piston (positive pushes towards extension).

    .. math:: F = \\max\\left(0,\\; k\\delta + c\\,\\dot\\delta\\,\\frac{\\delta}{\\delta
              + \\delta_c}\\right)

    for the penetration δ = −x into the cap stop (force +) and δ = x − L into the head stop
    (force −).

    Parameters
    ----------
    x, v : float or ndarray
        Piston position [m] and velocity [m/s].
    stroke : float
        L [m].
    stiffness : float
        Contact stiffness k [N/m].
    damping : float
        Contact damping c [N·s/m] (reached for δ >> δ_c).
    damping_depth : float
        Depth δ_c [m] over which the damping fades in (Hunt–Crossley), > 0.

    Returns
    -------
    ndarray
        F_stop [N].

    Examples
    --------
    >>> end_stop_force(np.array([-1e-4, 0.05, 0.1001]), 0.0, 0.1, 1e6, 2e3).round(6)
    array([ 100.,    0., -100.])
    """
    d_cap = np.maximum(-x, 0.0)
    d_head = np.maximum(x - stroke, 0.0)
    f_cap = np.maximum(stiffness * d_cap - damping * v * d_cap / (d_cap + damping_depth), 0.0)
    f_head = np.maximum(stiffness * d_head + damping * v * d_head / (d_head + damping_depth), 0.0)
    return f_cap - f_head


def rest_position(end, stroke, force, stop_stiffness, load_stiffness=0.0):
    """Position [m] of a piston at rest against the end stop at ``end`` under a static force.

    The stop's spring carries the net static force F (pressures, load, gravity; positive
    extends) where it points into the stop: δ = F/(k + k_L) with the stop stiffness k and a
    load spring k_L that relaxes as the piston goes in (:func:`end_stop_force` at rest,
    F_stop = k·δ, balances F − k_L·δ).  The seals carry nothing (their friction states
    relaxed).  A force pointing away from the stop leaves the piston at ``end``.  Started at
    ``end`` with δ = 0 instead, the piston would be thrown into the stop at the first step
    (at 6 bar on a Ø32 piston: 0.15 m/s within 1 ms, with a friction peak that is an artefact
    of the start).

    Parameters
    ----------
    end : float
        The end position [m]: 0 (cap stop) or ``stroke`` (head stop).
    stroke : float
        L [m].
    force : float
        Net static force on the piston at ``end`` [N], positive extends.
    stop_stiffness, load_stiffness : float
        k, k_L [N/m].

    Returns
    -------
    float
        x [m]: below 0 in the cap stop, above L in the head stop.

    Examples
    --------
    >>> a1, a2, ar = piston_areas(0.032, 0.012)
    >>> f = float(piston_force(1.013e5, 7.013e5, 1.013e5, a1, a2, ar))   # rod side at 6 bar
    >>> round(rest_position(0.0, 0.1, f - 20.0, 2e6) * 1e3, 4)          # and a 20 N load
    -0.2173
    >>> rest_position(0.0, 0.1, +50.0, 2e6)                              # pulled off the stop
    0.0
    """
    into = -force if end < 0.5 * stroke else force
    if into <= 0.0:
        return float(end)
    deflection = into / (stop_stiffness + load_stiffness)
    return float(end - deflection if end < 0.5 * stroke else end + deflection)


def load_force(x, v, force=0.0, stiffness=0.0, spring_free_position=0.0, mass=0.0,
               incline=0.0, viscous=0.0):
    """External load on the rod, positive against extension.

    .. math:: F_{load} = F_0 + k\\,(x - x_0) + M g \\sin\\varphi + c_v v

    Parameters
    ----------
    x, v : float or ndarray
        Piston position [m] and velocity [m/s].
    force : float
        Constant load force F_0 [N] (positive resists extension).
    stiffness : float
        Load spring k [N/m], compressed by extension.
    spring_free_position : float
        Position x_0 [m] where the spring is relaxed.
    mass : float
        Total moving mass M [kg] (for gravity).
    incline : float
        Angle φ [rad] of the extend direction above the horizontal (π/2: extending upwards
        against gravity, −π/2: downwards).
    viscous : float
        Viscous load (e.g. a damper) c_v [N·s/m].

    Returns
    -------
    ndarray
        F_load [N].

    Examples
    --------
    >>> round(float(load_force(0.05, 0.0, force=20.0, stiffness=1e3, mass=2.0,
    ...                        incline=np.pi / 2)), 4)
    89.6133
    """
    return (force + stiffness * (x - spring_free_position) + mass * GRAVITY * np.sin(incline)
            + viscous * v)
