r"""Inverse hydrodynamic lubrication (IHL) of a reciprocating elastomer seal.

A soft seal pressed on a sliding rod or bore keeps the contact pressure profile p(z) of its dry
(static) contact almost unchanged when a lubricant film builds up: the film is thin compared
with the elastic deflections, so the film pressure *is* the contact pressure and the film
shape follows from Reynolds' equation run backwards (Blok 1963; Müller & Nau 1998, ch. 10;
Kanters 1990, ch. 4).  With the counter surface sliding at speed u along +z and the seal at
rest, the volume flow per unit circumference through the film of thickness h is

    q = u·h/2 − h³/(12·η)·dp/dz                                              (1)

(Couette minus pressure flow).  At the pressure maximum dp/dz = 0, so q = u·h*/2 with h* the
film there; at every other point of the contact the same q passes, hence

    dp/dz = 6·η·u·(h − h*)/h³.                                               (2)

The right-hand side, as a function of h, is largest at h = 3/2·h*, where it equals
8·η·u/(9·h*²).  The steepest pressure rise w_max of the seal's inlet flank must not exceed it,
and the film adjusts until it just does (Blok's inverse solution):

    h* = √(8·η·u / (9·w_max))                                                (3)

(Müller & Nau 1998, Eq. 10.6; Kanters 1990, Eq. 4.9).  The inlet is the flank the counter
surface enters through, so the two stroke directions see the two flanks of the profile and two
films, in the ratio h*_1/h*_2 = √(w_max,2 / w_max,1).  The flow (1) at the pressure maximum,
q = u·h*/2, leaves a film of thickness h*/2 on the counter surface behind the seal; on the
return stroke the seal can drag back at most u·h*_back/2, so the net fluid transported out per
double stroke of length L and seal diameter D is

    V = π·D·L·(h*_out − h*_in)/2                                             (4)

-- the classic leak-tightness criterion of a rod seal: no net leakage while the instroke film
is at least the outstroke film (Müller & Nau 1998, §10.3; Kanters 1990, ch. 4).

Elsewhere in the contact (2) gives the film shape h(z) = H·h* through the cubic

    W·H³ − H + 1 = 0,   W = (4/27)·w(z)/w_max                                (5)

(w the pressure gradient along the sliding direction): H = 3/2 where the inlet is steepest,
H > 3/2 upstream of it (the gap opening towards the inlet edge), 1 < H < 3/2 downstream up to
the pressure maximum (H = 1) and H < 1 on the outlet flank (w < 0).

**The steepest gradient.**  A smooth profile (parabolic, triangular) has a finite w_max.  A
Hertzian (elliptic) profile -- and the FE profile of an O-ring, which is Hertz-like at its
edges -- has a square-root edge p ≈ p0·√(2s/a) (s the distance from the edge) whose gradient
is unbounded, so the inverse theory needs the gradient over a finite length Δ.  In the real
contact that length is set by the elasto-hydrodynamics of the inlet: the film pressure leaves
the dry profile where the gap the rubber opens just outside the contact edge,
g(s) ≈ (4√2/3)·(p0·a/E*)·(s/a)^(3/2) for a Hertz line contact (Johnson, *Contact Mechanics*,
1985, ch. 4, line contact), is comparable with the film, over a length
ℓ ≈ a·(3·h·E*/(4√2·p0·a))^(2/3) that shrinks with the film (this is why a lubricated Hertzian contact of a soft solid has
h ∝ u^(3/5), not u^(1/2): Snoeijer, Eggers & Venner, Phys. Fluids 25 (2013) 101705).
sealsim does not resolve that inlet: it measures w_max as the largest *secant* slope of the
inlet flank over a fixed length (:func:`max_inlet_gradient`),

    Δ = max(width/16, 2·s_max)                                               (6)

with ``width`` the contact zone's width and s_max the largest spacing of the profile's points
on the inlet flank, so that every secant spans at least three samples.  It is a documented
regularisation, not a law: exact for a flank that is straight over Δ (a triangle), within
Δ/(2a) = 1/16 of the true maximum for a parabola of half-width a, 4·p0/a for a square-root
edge (the film then depends on Δ only as Δ^(1/4)).  What it buys is a w_max that does not
depend on the mesh or on where the edge falls between two samples of an FE profile: on the FE
maps of a 2 mm O-ring on 12, 48 and 192 mm rods (181 profile points over 2.7 mm, 15 µm apart)
it lies within 9 % of its fine-mesh value on the medium mesh and within 17 % on the coarse one
(one coarse contact edge that itself moves, 29 %), where the former secant of width/64 --
shorter than the sample spacing -- scattered between 0.46 and 1.66 times the fine-mesh value
(``tests/test_contact_friction.py``).  Δ is longer than the physical inlet: for the O-ring
of the TU Delft rig (h* ≈ 1 µm, p0 ≈ 1 MPa, E* ≈ 5.5 MPa, a ≈ 0.55 mm) ℓ ≈ 17 µm against
Δ ≈ 70 µm, so the regularised film is of the right order but may be up to (Δ/ℓ)^(1/4) ≈ 1.4
times thicker than a resolved inlet would give; ℓ is also below the FE profile's sample
spacing, which is why a mapped profile cannot give it.

References
----------
.. [1] H. Blok, "Inverse problems in hydrodynamic lubrication and design directives for
   lubricated flexible surfaces", Proc. Int. Symp. Lubrication and Wear, Houston, 1963, 7-79.
.. [2] H. K. Müller, B. S. Nau, Fluid Sealing Technology, Marcel Dekker, New York, 1998,
   ch. 10 (reciprocating seals, inverse hydrodynamic theory).
.. [3] A. F. C. Kanters, "On the calculation of leakage and friction of reciprocating
   elastomeric seals", PhD thesis, TU Eindhoven, 1990, ch. 4 (the stationary, isothermal
   inverse hydrodynamic lubrication theory).
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "DEFAULT_GRADIENT_RESOLUTION",
    "MIN_GRADIENT_INTERVALS",
    "film_at_pressure_maximum",
    "film_left_on_surface",
    "starved_film",
    "film_shape_along",
    "film_shape_factor",
    "flow_per_circumference",
    "ihl_film_profile",
    "max_inlet_gradient",
    "stroke_transport",
]

#: Length over which the steepest inlet gradient is measured, as a fraction of the contact
#: zone's width [-] (Eq. 6 of the module docstring).
DEFAULT_GRADIENT_RESOLUTION = 1.0 / 16.0
#: ... and at least this many intervals of the profile's points on the inlet flank [-]
MIN_GRADIENT_INTERVALS = 2
#: W at the steepest point of the inlet, Eq. (5) [-]
_W_MAX = 4.0 / 27.0


def _oriented(position, pressure, direction):
    """(z, p) along the sliding direction: +1 as given, −1 mirrored (z → −z, reversed)."""
    z = np.asarray(position, dtype=float)
    p = np.asarray(pressure, dtype=float)
    if direction not in (1, -1):
        raise ValueError(f"direction must be +1 or -1, got {direction!r}")
    if direction < 0:
        return -z[::-1], p[::-1]
    return z, p


def max_inlet_gradient(position, pressure, direction=1, resolution=None):
    """Steepest pressure rise w_max on the inlet flank of a contact pressure profile.

    The largest secant slope (p(z + Δ) − p(z))/Δ with z + Δ up to the pressure maximum, the
    profile linear between its points, Δ from Eq. (6) of the module docstring.

    Parameters
    ----------
    position : array_like
        Axial positions z [m], strictly ascending (one contact zone, with its edges where
        p = 0, or a profile with one pressure maximum).
    pressure : array_like
        Contact pressure p(z) [Pa], >= 0.
    direction : {1, -1}
        Sliding direction of the counter surface relative to the seal: +1 towards +z (the
        inlet is the flank at low z), −1 towards −z.
    resolution : float, optional
        Secant length Δ [m]; default Eq. (6): :data:`DEFAULT_GRADIENT_RESOLUTION` times the
        width of the zone where p > 0 (with the zero points on either side), at least
        :data:`MIN_GRADIENT_INTERVALS` times the largest spacing of the points on the inlet
        flank.

    Returns
    -------
    float
        w_max [Pa/m] (> 0 for a profile with a pressure maximum inside it; 0 if the pressure
        maximum is at the inlet edge).

    Examples
    --------
    A triangle rising at 2 MPa/mm and falling at 1 MPa/mm:

    >>> z = np.array([0.0, 0.5e-3, 1.5e-3])
    >>> p = np.array([0.0, 1e6, 0.0])
    >>> float(max_inlet_gradient(z, p, +1)), float(max_inlet_gradient(z, p, -1))
    (2000000000.0, 1000000000.0)
    """
    z, p = _oriented(position, pressure, direction)
    if z.ndim != 1 or z.size < 2 or np.any(np.diff(z) <= 0):
        raise ValueError("position must be strictly ascending with >= 2 points")
    peak = int(np.argmax(p))
    if peak == 0 or p[peak] <= 0.0:
        return 0.0
    wet = np.nonzero(p > 0.0)[0]
    lo = max(int(wet[0]) - 1, 0)
    span = z[peak] - z[lo]
    if resolution is None:
        width = z[min(int(wet[-1]) + 1, z.size - 1)] - z[lo]
        spacing = float(np.max(np.diff(z[lo:peak + 1])))
        delta = max(DEFAULT_GRADIENT_RESOLUTION * width, MIN_GRADIENT_INTERVALS * spacing)
    else:
        delta = float(resolution)
    if delta >= span:           # flank shorter than Δ: its mean slope
        return float((p[peak] - p[lo]) / span)
    # the secant of a piecewise-linear function is extremal with one end on a node: secants
    # starting on a node and secants ending on one, each node's end taken exactly (a bound
    # like z + Δ <= z[peak] drops the secant ending on the peak by rounding, depending on
    # where the profile lies on the z axis)
    nodes = np.arange(lo, peak + 1)
    first = nodes[z[nodes] + delta <= z[peak]]
    last = nodes[z[nodes] - delta >= z[lo]]
    rise = np.concatenate([np.interp(z[first] + delta, z, p) - p[first],
                           p[last] - np.interp(z[last] - delta, z, p)])
    return float(max(np.max(rise) / delta, 0.0))


def film_at_pressure_maximum(viscosity, speed, max_gradient):
    """Film thickness at the pressure maximum by inverse hydrodynamics, Eq. (3).

    ``h* = √(8·η·|u| / (9·w_max))`` (Blok 1963; Müller & Nau 1998; Kanters 1990).

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity of the lubricant in the contact η [Pa·s].
    speed : array_like
        Sliding speed u [m/s]; its magnitude is used.
    max_gradient : array_like
        Steepest pressure rise of the inlet flank w_max [Pa/m], > 0
        (:func:`max_inlet_gradient`).

    Returns
    -------
    numpy.ndarray
        h* [m].

    Examples
    --------
    Oil of 0.1 Pa·s at 0.1 m/s on an inlet rising at 10 MPa/mm:

    >>> round(float(film_at_pressure_maximum(0.1, 0.1, 1e10)) * 1e6, 4)
    0.9428
    """
    eta = np.asarray(viscosity, dtype=float)
    u = np.abs(np.asarray(speed, dtype=float))
    return np.sqrt(8.0 * eta * u / (9.0 * np.asarray(max_gradient, dtype=float)))


def flow_per_circumference(speed, film):
    """Volume flow through the contact per unit circumference, q = |u|·h*/2, Eq. (1) at the
    pressure maximum.

    Parameters
    ----------
    speed : array_like
        Sliding speed u [m/s]; its magnitude is used.
    film : array_like
        Film at the pressure maximum h* [m].

    Returns
    -------
    numpy.ndarray
        q [m²/s].

    Examples
    --------
    >>> float(flow_per_circumference(0.2, 1e-6))
    1e-07
    """
    return 0.5 * np.abs(np.asarray(speed, dtype=float)) * np.asarray(film, dtype=float)


def starved_film(full_film, supply_layer):
    """Film at the pressure maximum of an inlet fed by a limited layer of lubricant.

    A layer h_s that the counter surface carries towards the seal brings the flow |u|·h_s per
    unit circumference; the contact passes |u|·h*/2 at its pressure maximum (Eq. 1).  When the
    fully flooded film h*₀ would pass more than arrives, the inlet is starved and mass
    conservation sets the film: ``h* = min(h*₀, 2·h_s)`` (the same balance that makes the
    layer left behind a seal h*/2, :func:`film_left_on_surface`; Müller & Nau, *Fluid Sealing
    Technology*, 1998, ch. 10, for the rod seal's outstroke and instroke films).  A greased
    seal with no other supply runs on what the strokes leave on the surface.

    Parameters
    ----------
    full_film : array_like
        Fully flooded film h*₀ [m] (:func:`film_at_pressure_maximum`).
    supply_layer : array_like
        Lubricant layer on the counter surface ahead of the seal h_s [m], > 0; ``inf`` for a
        flooded inlet.

    Returns
    -------
    numpy.ndarray
        h* [m].

    Examples
    --------
    >>> starved_film([0.9e-6, 0.1e-6], 0.2e-6) * 1e6
    array([0.4, 0.1])
    """
    return np.minimum(np.asarray(full_film, dtype=float),
                      2.0 * np.asarray(supply_layer, dtype=float))


def film_left_on_surface(film):
    """Thickness of the fluid layer the counter surface carries away behind the seal, h*/2.

    The flow q = u·h*/2 leaves the contact attached to the surface moving at u.

    Parameters
    ----------
    film : array_like
        Film at the pressure maximum h* [m].

    Returns
    -------
    numpy.ndarray
        Layer thickness [m].

    Examples
    --------
    >>> float(film_left_on_surface(0.8e-6))
    4e-07
    """
    return 0.5 * np.asarray(film, dtype=float)


def stroke_transport(diameter, stroke, film_out, film_in):
    """Net fluid volume carried out per double stroke, V = π·D·L·(h*_out − h*_in)/2, Eq. (4).

    Positive: the outstroke leaves more fluid on the counter surface than the instroke can drag
    back (leakage); negative or zero: the seal can take back all it leaves (Müller & Nau
    1998, §10.3).  Assumes the seal is fully flooded on both sides.

    Parameters
    ----------
    diameter : array_like
        Diameter of the sliding surface D [m].
    stroke : array_like
        Stroke length L [m].
    film_out, film_in : array_like
        Films at the pressure maximum on the outstroke and on the instroke [m].

    Returns
    -------
    numpy.ndarray
        V [m³] per double stroke.

    Examples
    --------
    >>> round(float(stroke_transport(0.012, 0.1, 0.6e-6, 0.4e-6)) * 1e9, 4)   # mm³
    0.377
    """
    return (np.pi * np.asarray(diameter, dtype=float) * np.asarray(stroke, dtype=float)
            * 0.5 * (np.asarray(film_out, dtype=float) - np.asarray(film_in, dtype=float)))


def film_shape_factor(gradient_ratio, upstream=False):
    """Film H = h/h* from the pressure gradient by Reynolds' equation, Eq. (5).

    Solves (4/27)·r·H³ − H + 1 = 0 (closed form, Cardano/Viète, then two Newton steps).

    Parameters
    ----------
    gradient_ratio : array_like
        r = w(z)/w_max [-], the local pressure gradient along the sliding direction relative
        to the steepest inlet gradient; values above 1 are taken as 1.
    upstream : array_like of bool
        For 0 < r < 1 two films satisfy (5): True picks the wider one (H > 3/2, upstream of
        the steepest point), False the narrower one (1 < H < 3/2, between it and the pressure
        maximum).  Ignored where r <= 0 (one film, H <= 1).

    Returns
    -------
    numpy.ndarray
        H [-] (inf where r = 0 upstream).

    Examples
    --------
    >>> film_shape_factor([1.0, 0.0, -1.0]).round(4).tolist()
    [1.5, 1.0, 0.8941]
    >>> round(float(film_shape_factor(0.5, upstream=True)), 4)
    3.0
    """
    r = np.minimum(np.asarray(gradient_ratio, dtype=float), 1.0)
    up = np.broadcast_to(np.asarray(upstream, dtype=bool), r.shape)
    w = _W_MAX * r
    h = np.ones_like(r)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        pos = w > 1e-12
        if np.any(pos):
            wp = w[pos]
            scale = 2.0 * np.sqrt(1.0 / (3.0 * wp))
            phi = np.arccos(np.clip(-1.5 * np.sqrt(3.0 * wp), -1.0, 1.0))
            big = scale * np.cos(phi / 3.0)
            mid = scale * np.cos(phi / 3.0 - 2.0 * np.pi / 3.0)
            h[pos] = np.where(up[pos], big, mid)
        neg = w < -1e-12
        if np.any(neg):
            wn = -w[neg]
            scale = 2.0 * np.sqrt(1.0 / (3.0 * wn))
            h[neg] = scale * np.sinh(np.arcsinh(1.5 * np.sqrt(3.0 * wn)) / 3.0)
        small = np.abs(w) <= 1e-12
        h[small] = 1.0 + w[small]
        h[small & up & (r > 0)] = np.inf
        h[(r == 0) & up] = np.inf
        for _ in range(2):                                   # Newton polish
            f = w * h**3 - h + 1.0
            df = 3.0 * w * h**2 - 1.0
            ok = np.isfinite(h) & (np.abs(df) > 1e-9) & (np.abs(r - 1.0) > 1e-9)
            h = np.where(ok, h - f / np.where(ok, df, 1.0), h)
    return h


def film_shape_along(position, pressure, direction=1, max_gradient=None, resolution=None):
    """Film shape H(z) = h/h* and the pressure gradient along the sliding direction, Eq. (5).

    The profile is taken as linear between its points: each point on the inlet flank gets
    the slope of the segment after it, each point from the pressure maximum on that of the
    segment before it.

    Parameters
    ----------
    position, pressure, direction, resolution
        As in :func:`max_inlet_gradient` (one contact zone).
    max_gradient : float, optional
        w_max [Pa/m]; default :func:`max_inlet_gradient` of the profile.

    Returns
    -------
    shape : numpy.ndarray
        H at ``position`` [-] (inf upstream of an inlet whose gradient vanishes).
    gradient : numpy.ndarray
        dp/dz along the sliding direction at ``position`` [Pa/m] (> 0 on the inlet).

    Examples
    --------
    >>> shape, grad = film_shape_along([0.0, 1.0, 3.0], [0.0, 2.0, 0.0])
    >>> shape.round(4).tolist(), grad.tolist()
    ([1.5, 1.0, 0.9387], [2.0, 0.0, -1.0])
    """
    z, p = _oriented(position, pressure, direction)
    w_max = max_inlet_gradient(z, p, 1, resolution) if max_gradient is None else max_gradient
    seg = np.diff(p) / np.diff(z)
    peak = int(np.argmax(p))
    grad = np.concatenate([seg, seg[-1:]])
    grad[peak:] = np.concatenate([[0.0], seg[peak:]])[:z.size - peak]
    ratio = grad / w_max if w_max > 0 else np.zeros_like(p)
    index = np.arange(p.size)
    steepest = int(np.argmax(np.where(index < peak, ratio, -np.inf))) if peak > 0 else 0
    shape = film_shape_factor(ratio, index < steepest)
    if direction < 0:
        return shape[::-1], grad[::-1]
    return shape, grad


def ihl_film_profile(position, pressure, film, direction=1, resolution=None):
    """Film thickness h(z) = H(z)·h* across a contact pressure profile, Eq. (5)
    (:func:`film_shape_along`).

    Parameters
    ----------
    position : array_like
        Axial positions z [m], strictly ascending (one contact zone).
    pressure : array_like
        Contact pressure p(z) [Pa].
    film : array_like
        Film at the pressure maximum h* [m]; an array of shape (k,) gives k profiles.
    direction : {1, -1}
        Sliding direction of the counter surface (+1 towards +z).
    resolution : float, optional
        Secant length of :func:`max_inlet_gradient` [m].

    Returns
    -------
    numpy.ndarray
        h [m] at ``position`` (shape (n,) or (k, n)).

    Examples
    --------
    A parabola sampled at five points: 3/2·h* at the inlet edge (the steepest segment), h* at
    the pressure maximum, thinner on the outlet:

    >>> z = np.linspace(-1e-3, 1e-3, 5)
    >>> p = 1e6 * (1 - (z / 1e-3) ** 2)
    >>> (ihl_film_profile(z, p, 1e-6, resolution=1e-9) * 1e6).round(3).tolist()
    [1.5, 1.059, 1.0, 0.957, 0.894]
    """
    shape, _ = film_shape_along(position, pressure, direction, resolution=resolution)
    return np.asarray(film, dtype=float)[..., None] * shape
