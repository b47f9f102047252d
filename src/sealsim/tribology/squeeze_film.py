r"""The squeeze film of a seal at rest: how fast its contact's film drains when sliding stops.

While the counter surface slides, a seal's film is set by the inlet (inverse hydrodynamics,
:mod:`.mixed_lubrication`); when it stops, nothing feeds the film and the seal, pressed on
with its contact load, squeezes it out.  Reynolds' equation with the surfaces approaching at
the speed V = −dh/dt and no sliding,

.. math:: \frac{d}{dz}\left(\frac{h^3}{12\,\eta}\frac{dp}{dz}\right) = -V,

with p = 0 at both ends of a contact zone, gives the fluid pressure
p'(z) = −12·η·V·(z − z̄)/h³ (z̄ where the flow changes direction) and the load the film
carries per unit circumference

.. math:: W'_f = \eta\,V\,R, \qquad
          R = 12\int\frac{(z-\bar z)^2}{h^3}\,dz, \qquad
          \bar z = \frac{\int z/h^3\,dz}{\int 1/h^3\,dz}                               (1)

(integrating by parts).  For a film of uniform thickness h over a width b, R = b³/h³ and
V = W'_f·h³/(η·b³), the parallel-surface squeeze film (Reynolds 1886; Hamrock, Schmid &
Jacobson 2004).  A seal pressed on as one body approaches with the same V under all of its
contact zones (an X-ring's two lobes): their resistances add.

The film carries the part of the contact load the asperities do not, W'_f = (1 − α)·F'_N
(:func:`~.mixed_lubrication.reciprocating_friction`), so a thick film drains fast, a thin one
slowly, and a film down at the roughness, whose load the asperities carry, hardly at all.
The film's thinning rate relative to its thickness at the pressure maximum h*,

.. math:: s = -\frac{1}{h^*}\frac{dh^*}{dt} = \frac{W'_f}{\eta\,R\,h^*},                 (2)

is what the friction laws' film state needs.  Their state is the speed φ the film has formed
for (:func:`sealsim.friction.kernels.film_speed_rate`), the film h*(φ) of the seal's steady
curve; at rest it falls as the film thins,

.. math:: \frac{d\varphi}{dt} = -\kappa(\varphi)\,\varphi, \qquad
          \kappa = \frac{s}{d\ln h^*/d\ln u}                                        (3)

(:func:`film_speed_decay_rate`).  In full film h* ∝ √u (inverse hydrodynamics) and
κ = 2·s.  With the IHL film h*² = 8·η·u/(9·w_max) and a film shape that does not change with
the speed, s ∝ W'·h*²/(η·R·h*³) is proportional to u and independent of the viscosity (the
same η that builds the film drains it): φ(t) = φ₀/(1 + κ(φ₀)·t) in full film, a film that
stands for 0.1 m/s is gone to the 1 mm/s one in about 100/κ(φ₀): the break-away force of a
seal rises ever more slowly with the dwell time, not with one time constant.

References
----------
.. [1] O. Reynolds, "On the theory of lubrication and its application to Mr. Beauchamp
   Tower's experiments", Phil. Trans. R. Soc. Lond. 177 (1886) 157-234 (the squeeze film
   between parallel surfaces).
.. [2] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film Lubrication,
   2nd ed., Marcel Dekker, 2004, chapter "Squeeze film bearings" (parallel-surface squeeze
   film, W' = η·b³·V/h³ per unit length of an infinitely long strip).
"""

from __future__ import annotations

import numpy as np

__all__ = ["film_speed_decay_rate", "squeeze_resistance", "squeeze_thinning_rate"]

#: smallest slope d ln h*/d ln u used by :func:`film_speed_decay_rate` [-] (where the film no
#: longer grows with the speed, a starved inlet, the speed it stands for falls at most
#: 1/0.05 = 20 times faster than the film thins)
MIN_FILM_SLOPE = 0.05


def squeeze_resistance(position, film):
    """Squeeze resistance R = W'_f/(η·V) [-] of a contact's film, Eq. (1): the sum over its
    contact zones (the runs of finite film).

    Parameters
    ----------
    position : array_like
        Axial positions z [m], ascending, shape (m,).
    film : array_like
        Film h(z) [m], shape (..., m); ``inf`` (or nan) outside the contact zones.

    Returns
    -------
    numpy.ndarray
        R [-], shape (...); 0 where no zone has two finite points.

    Examples
    --------
    A uniform film of 1 µm over 1 mm: R = b³/h³ = 1e9.

    >>> z = np.linspace(0.0, 1e-3, 2001)
    >>> float(squeeze_resistance(z, np.full(z.size, 1e-6))) / 1e9
    1.0

    Two such zones side by side approach with the same speed: twice the resistance.

    >>> z2 = np.linspace(0.0, 3e-3, 6001)
    >>> h2 = np.where((z2 <= 1e-3) | (z2 >= 2e-3), 1e-6, np.inf)
    >>> round(float(squeeze_resistance(z2, h2)) / 1e9, 3)
    2.0
    """
    z = np.asarray(position, dtype=float)
    h = np.asarray(film, dtype=float)
    finite = np.isfinite(h) & (h > 0)
    weight = np.where(finite, 1.0 / np.where(finite, h, 1.0) ** 3, 0.0).reshape(-1, z.size)
    out = np.zeros(weight.shape[0])
    # the zones: runs of points with a finite film in any row (the rows are speeds of one
    # profile, whose zones are the same)
    edges = np.flatnonzero(np.diff(np.concatenate(
        ([0], finite.reshape(-1, z.size).any(axis=0).astype(np.int8), [0]))))
    for start, stop in zip(edges[::2], edges[1::2]):
        if stop - start < 2:
            continue
        zz, w = z[start:stop], weight[:, start:stop]
        total = np.trapezoid(w, zz, axis=-1)
        carried = total > 0
        centre = np.trapezoid(zz * w, zz, axis=-1) / np.where(carried, total, 1.0)
        out += np.where(carried, 12.0 * np.trapezoid((zz - centre[:, None]) ** 2 * w, zz,
                                                     axis=-1), 0.0)
    return out.reshape(h.shape[:-1])


def squeeze_thinning_rate(fluid_load, viscosity, resistance, film):
    """Relative thinning rate s = −(dh*/dt)/h* = W'_f/(η·R·h*) [1/s] of a seal's film at rest,
    Eq. (2).

    Parameters
    ----------
    fluid_load : array_like
        Load the film carries per unit circumference W'_f = (1 − α)·F'_N [N/m] (>= 0).
    viscosity : array_like
        Dynamic viscosity of the lubricant in the contact η [Pa·s].
    resistance : array_like
        Squeeze resistance R of the film's shape [-] (:func:`squeeze_resistance`).
    film : array_like
        Film at the pressure maximum h* [m].

    Returns
    -------
    numpy.ndarray
        s [1/s]; 0 where the film carries nothing or has no finite resistance.

    Examples
    --------
    A uniform 1 µm film 1 mm wide under 500 N/m of an oil of 0.1 Pa·s thins at first at
    W'·h²/(η·b³) = 5 /s (0.5 % per millisecond):

    >>> float(squeeze_thinning_rate(500.0, 0.1, 1e9, 1e-6))
    5.0
    """
    w = np.maximum(np.asarray(fluid_load, dtype=float), 0.0)
    r = np.asarray(resistance, dtype=float)
    h = np.asarray(film, dtype=float)
    denominator = np.asarray(viscosity, dtype=float) * r * h
    ok = (denominator > 0) & np.isfinite(denominator)
    return np.where(ok, w / np.where(ok, denominator, 1.0), 0.0)


def film_speed_decay_rate(speed, film, thinning_rate, min_slope=MIN_FILM_SLOPE):
    """Decay rate κ = s/(d ln h*/d ln u) [1/s] of the speed φ a film stands for when the seal
    is at rest, Eq. (3): dφ/dt = −κ(φ)·φ.

    Parameters
    ----------
    speed : array_like
        Sliding speeds u [m/s] of the steady curve, ascending, > 0, shape (..., n).
    film : array_like
        Film at the pressure maximum h*(u) [m], same shape (0 or inf: no film, κ = 0).
    thinning_rate : array_like
        s(u) [1/s] (:func:`squeeze_thinning_rate`), same shape.
    min_slope : float
        Smallest slope d ln h*/d ln u [-] used (:data:`MIN_FILM_SLOPE`).

    Returns
    -------
    numpy.ndarray
        κ [1/s], the shape of ``film``.

    Examples
    --------
    In full film h* ∝ √u and κ = 2·s:

    >>> u = np.array([0.01, 0.1, 1.0])
    >>> film_speed_decay_rate(u, 1e-6 * np.sqrt(u / 0.01), 50.0 * u).round(6).tolist()
    [1.0, 10.0, 100.0]
    """
    u = np.asarray(speed, dtype=float)
    h = np.asarray(film, dtype=float)
    s = np.asarray(thinning_rate, dtype=float)
    present = np.isfinite(h) & (h > 0)
    log_h = np.log(np.where(present, h, 1.0))
    slope = np.gradient(log_h, np.log(u), axis=-1) if u.shape[-1] > 1 else np.full(h.shape,
                                                                                    0.5)
    return np.where(present, s / np.maximum(slope, min_slope), 0.0)
