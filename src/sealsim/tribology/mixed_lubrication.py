r"""Mixed lubrication of a reciprocating elastomer seal from its contact pressure profile.

The static contact pressure p(z) of the seal (FE, or Hertz for an O-ring) sets everything:

1. **Full film** -- inverse hydrodynamics (:mod:`.inverse_hydrodynamics`): the film at the
   pressure maximum h*₀ = √(8·η·u/(9·w_max)), w_max the steepest rise of the inlet flank of the
   stroke direction (Blok 1963; Müller & Nau 1998; Kanters 1990); at most 2·h_s when a layer
   h_s on the counter surface is all the inlet gets (starved).
2. **Load sharing** -- when h*₀ is not large against the combined roughness σ, the counter
   surface's asperities carry a share α of the contact pressure and the fluid the rest
   (Johnson, Greenwood & Poon, Wear 19 (1972) 91: each carries its share, the film follows the
   fluid's part).  The fluid pressure (1 − α)·p(z) has the gradient (1 − α)·w, so the film at
   the pressure maximum grows to h* = h*₀/√(1 − α).  Dry, the asperities carry p_max at the
   separation λ_dry·σ where Greenwood–Williamson's summits do so
   (:func:`~sealsim.tribology.contact.asperity_pressure`, with the rubber's modulus at the
   asperity frequency u/λ_asp); the film lifts the rubber by h* off that position, and the
   summits then carry α·p_max.  One equation fixes α::

       (λ − λ_dry)·σ = h*₀/√(1 − α),   p_asp(λ) = α·p_max                        (1)

   As u → 0, h*₀ → 0 and α → 1: the asperities carry the whole load at the separation the
   rubber's stiffness allows ("the film never falls below what the asperities allow"), and
   the viscous shear vanishes with u.  At high speed α → 0.

   *What this choice implies.*  A soft rubber pressed on a rough counter surface sits deep in
   its roughness when dry (GW at p_max/E* = 0.03-0.06 with the default roughness: λ_dry = −3
   to −5, outside GW's range of independent summits), so the share depends on how deep:
   at the same film a higher contact pressure leaves a larger share (the TU Delft O-ring at
   1 and 7 bar: h*/σ ≈ 3.1 at both, α ≈ 0.10 and 0.25).  The lift is not the gap the fluid
   fills: at λ − λ_dry = 3.1 the mean gap of Gaussian heights
   (:func:`~sealsim.tribology.contact.mean_gap`, Patir & Cheng 1978) is only 0.27σ at λ =
   −0.3, so the flow u·ḡ/2 through the contact is smaller than the u·h*/2 of the inverse
   solution.  Taking the film as the mean gap instead, ḡ(λ) = h*₀/√(1 − α), would conserve the
   flow, but with the default roughness it leaves that O-ring in full film at the rig's
   10 mm/s (0.4 N at 1 bar and 0.6 N at 7 bar against the measured 4.0 and 8.0 N) and moves
   its Stribeck minimum from 25 to 2 mm/s.  sealsim keeps the lift, an open modelling choice
   (docs/physics/contact_friction.rst).
3. **Film shape** h(z) = H(z)·h* with H from Reynolds' equation
   (:func:`~sealsim.tribology.inverse_hydrodynamics.film_shape_factor`).
4. **Friction** per unit circumference, integrated over the contact::

       f = ∫ [ μ_b·α·p(z) + η·u/h(z) + h(z)/2·(1 − α)·dp/dz ] dz                    (2)

   boundary shear of the asperity pressure (Bowden & Tabor: the shear of the adsorbed boundary
   layer, proportional to the load it carries, μ_b the boundary friction coefficient of the
   lubricated rubber), Couette shear of the film and the shear of its pressure flow (the sign
   of dp/dz along the sliding direction).  The seal's friction is π·D·f.

The result is a Stribeck curve per stroke direction with boundary (f → μ_b·F'_N as u → 0),
mixed and hydrodynamic (f → ∫η·u/h dz + ...) branches, scaling with the circumference, and with
the lubricant's viscosity at the contact temperature.  Several contact zones (an X-ring's two
lobes) are treated as separate contacts, each fully flooded -- or, with a lubricant layer h_s on
the counter surface as the only supply, starved in the order the counter surface passes them:
the first to h*₀ ≤ 2·h_s, each next one to at most the film of the one before, whose layer h*/2
is all it gets (mass conservation,
:func:`~sealsim.tribology.inverse_hydrodynamics.starved_film`).

References
----------
.. [1] H. Blok (1963); H. K. Müller, B. S. Nau, Fluid Sealing Technology (1998), ch. 10;
   A. F. C. Kanters, PhD thesis TU Eindhoven (1990): see :mod:`.inverse_hydrodynamics`.
.. [2] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
   Proc. R. Soc. A 295 (1966) 300-319.
.. [3] J. A. Greenwood, J. H. Tripp, "The contact of two nominally flat rough surfaces",
   Proc. IMechE 185 (1970) 625-633.
.. [4] K. L. Johnson, J. A. Greenwood, S. Y. Poon, "A simple theory of asperity contact in
   elastohydrodynamic lubrication", Wear 19 (1972) 91-108.
.. [5] N. Patir, H. S. Cheng, "An average flow model for determining effects of
   three-dimensional roughness on partial hydrodynamic lubrication", J. Lubr. Technol. 100
   (1978) 12-17.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from sealsim.tribology.contact import (
    _GW_GRID,
    _LOG_F32,
    DEFAULT_ROUGHNESS_DENSITY,
    DEFAULT_ROUGHNESS_SLOPE,
    asperity_pressure,
    separation_at_asperity_pressure,
)
from sealsim.tribology.inverse_hydrodynamics import (
    film_at_pressure_maximum,
    film_shape_along,
    max_inlet_gradient,
    starved_film,
)
from sealsim.tribology.squeeze_film import squeeze_resistance, squeeze_thinning_rate

__all__ = ["ContactFriction", "contact_zone_slices", "ihl_load_share", "reciprocating_friction"]

#: Illinois iterations of :func:`_lift_at_load_share` at most (it stops when every root is
#: bracketed to 1e-13 of the lift: 5-10 iterations where 60 bisections were used before)
_MAX_ITERATIONS = 60


def _lift_at_load_share(film_ratio, dry, roughness, modulus, peak_pressure, args):
    """The lift s = λ − λ_dry [-] (in σ) at which the asperities' share α = p_asp/p_max and
    the film's, 1 − α = (k/s)² with k = h*₀/σ, add up to one: Eq. (1) in logarithms,

        G(t) = 2·t + ln(1 − α(λ_dry + e^t)) − 2·ln k = 0,   s = e^t,

    G strictly increasing and nearly linear in t (slope >= 2: α falls as s grows), bracketed
    by ln k (α >= 0) and ln(k + 12) (α ≈ 0 twelve σ above the dry position).  Bracketed regula
    falsi with the Illinois modification (Dowell & Jarratt, BIT 11 (1971) 168): superlinear on
    the nearly linear G, and never leaves its bracket.  k = 0 gives s = 0.  Compiled, one root
    per point (:func:`_lift_points`): as numpy array operations over the points the friction
    table of a fit spent most of its time in numpy's per-call overhead."""
    poisson, roughness_density, roughness_slope = args
    k, dry, sigma, e, pmax = np.broadcast_arrays(
        *(np.asarray(a, dtype=float) for a in (film_ratio, dry, roughness, modulus,
                                               peak_pressure)))
    # asperity_pressure's factor of F_3/2, its operations in its order
    stiffness = 4.0 / 3.0 * (e / (1.0 - poisson**2)) * roughness_density * np.sqrt(
        roughness_slope)
    out = np.empty(k.size)
    _lift_points(k.ravel(), dry.ravel(), sigma.ravel(), stiffness.ravel(), pmax.ravel(),
                 _GW_GRID, _LOG_F32, _MAX_ITERATIONS, out)
    return out.reshape(k.shape)


@njit(cache=True)
def _interp(x, grid, values):
    """np.interp(x, grid, values) of one x on an increasing, equally spaced grid."""
    n = grid.size
    if x != x:
        return x
    if x <= grid[0]:
        return values[0]
    if x >= grid[n - 1]:
        return values[n - 1]
    j = min(max(int((x - grid[0]) / (grid[1] - grid[0])), 0), n - 2)
    while j < n - 2 and grid[j + 1] <= x:      # the cell np.interp's search finds
        j += 1
    while j > 0 and grid[j] > x:
        j -= 1
    slope = (values[j + 1] - values[j]) / (grid[j + 1] - grid[j])
    return slope * (x - grid[j]) + values[j]


@njit(cache=True)
def _excess(t, target, dry, sigma, stiffness, pmax, grid, log_f32):
    """G(t) of :func:`_lift_at_load_share` with α from :func:`~.contact.asperity_pressure`."""
    lam = (dry + math.exp(t)) * sigma / sigma
    f32 = 0.0 if lam > grid[grid.size - 1] else math.exp(_interp(lam, grid, log_f32))
    share = stiffness * f32 / pmax
    if share >= 1.0:
        share = 1.0
    return 2.0 * t + math.log1p(-share) - target


@njit(cache=True)
def _lift_points(k, dry, sigma, stiffness, pmax, grid, log_f32, max_iterations, out):
    """The lift of :func:`_lift_at_load_share` point by point into ``out``."""
    for i in range(k.size):
        if not k[i] > 0.0:
            out[i] = 0.0
            continue
        target = 2.0 * math.log(k[i])
        lo, hi = math.log(k[i]), math.log(k[i] + 12.0)
        f_lo = _excess(lo, target, dry[i], sigma[i], stiffness[i], pmax[i], grid, log_f32)
        f_hi = _excess(hi, target, dry[i], sigma[i], stiffness[i], pmax[i], grid, log_f32)
        side = 0                    # which end was kept last time (Illinois)
        for _ in range(max_iterations):
            if not (math.isfinite(lo) and hi - lo > 1e-13 and f_lo != 0.0 and f_hi != 0.0):
                break
            t = lo - f_lo * (hi - lo) / (f_hi - f_lo)
            if not (math.isfinite(t) and lo < t < hi):
                t = 0.5 * (lo + hi)
            f = _excess(t, target, dry[i], sigma[i], stiffness[i], pmax[i], grid, log_f32)
            if f < 0.0:
                lo, f_lo = t, f
                if side == 1:       # an end kept twice in a row has its value halved
                    f_hi *= 0.5
                side = 1
            else:
                hi, f_hi = t, f
                if side == -1:
                    f_lo *= 0.5
                side = -1
        t = lo if f_lo == 0.0 else (hi if f_hi == 0.0 else 0.5 * (lo + hi))
        out[i] = math.exp(t)


def ihl_load_share(full_film, peak_pressure, roughness, asperity_modulus, poisson=0.5,
                   roughness_density=DEFAULT_ROUGHNESS_DENSITY,
                   roughness_slope=DEFAULT_ROUGHNESS_SLOPE, film_limit=np.inf):
    """Asperity share α of the contact load and the film h* at the pressure maximum, Eq. (1).

    Solves h(λ) = h*₀/√(1 − α), p_asp(λ) = α·p_max for the separation λ (both sides
    monotone: one root, :func:`_lift_at_load_share`), with h(λ) = (λ − λ_dry)·σ the lift of
    the rubber off its dry position λ_dry, where the asperities alone carry p_max.

    Parameters
    ----------
    full_film : array_like
        Full-film IHL film h*₀ [m] (:func:`~.inverse_hydrodynamics.film_at_pressure_maximum`),
        >= 0.
    peak_pressure : array_like
        Largest contact pressure of the zone p_max [Pa], > 0.
    roughness : array_like
        Combined RMS roughness σ [m].
    asperity_modulus : array_like
        Young's modulus of the rubber at the asperity frequency [Pa].
    poisson, roughness_density, roughness_slope : float
        See :func:`~sealsim.tribology.contact.asperity_pressure`.
    film_limit : array_like
        Largest film the inlet's supply allows [m] (2·h_s of a starved inlet,
        :func:`~.inverse_hydrodynamics.starved_film`; ``full_film`` must not exceed it): the
        lift stops there and the asperities carry what the film at that separation cannot.

    Returns
    -------
    share : numpy.ndarray
        α in [0, 1] [-].
    film : numpy.ndarray
        h* [m], h*₀ <= h* <= ``film_limit``.

    Examples
    --------
    A thick film carries everything, a vanishing one nothing:

    >>> share, film = ihl_load_share([5e-6, 1e-12], 1e6, 0.3e-6, 10e6)
    >>> share.round(3).tolist(), (film * 1e6).round(3).tolist()
    ([0.0, 1.0], [5.0, 0.0])
    """
    h0 = np.asarray(full_film, dtype=float)
    pmax = np.asarray(peak_pressure, dtype=float)
    sigma = np.asarray(roughness, dtype=float)
    modulus = np.asarray(asperity_modulus, dtype=float)
    h0, pmax, sigma, modulus = np.broadcast_arrays(h0, pmax, sigma, modulus)
    args = (poisson, roughness_density, roughness_slope)
    dry = separation_at_asperity_pressure(pmax, sigma, modulus, *args) / sigma
    dry = np.clip(dry, -30.0, 12.0)

    lift = _lift_at_load_share(h0 / sigma, dry, sigma, modulus, pmax, args)
    lam = dry + np.minimum(lift, np.asarray(film_limit, dtype=float) / sigma)
    share = np.clip(asperity_pressure(lam * sigma, sigma, modulus, *args) / pmax, 0.0, 1.0)
    return share, np.maximum((lam - dry) * sigma, h0)


def contact_zone_slices(pressure) -> list[slice]:
    """Index ranges of the separate contact zones of a profile (runs of p > 0, each with the
    zero-pressure point on either side).

    Examples
    --------
    >>> contact_zone_slices([0, 1, 2, 0, 0, 3, 0])
    [slice(0, 4, None), slice(4, 7, None)]
    """
    p = np.asarray(pressure, dtype=float)
    wet = np.concatenate([[False], p > 0.0, [False]])
    edges = np.flatnonzero(np.diff(wet.astype(int)))
    return [slice(max(int(a) - 1, 0), min(int(b) + 1, p.size))
            for a, b in zip(edges[0::2], edges[1::2])]


class ContactFriction(NamedTuple):
    """Friction of a reciprocating contact per unit circumference over sliding speed.

    Every field has the shape of the speed array, except ``film_profile`` (speeds × points).

    Attributes
    ----------
    friction : numpy.ndarray
        f = boundary + viscous [N/m].
    boundary : numpy.ndarray
        ∫ μ_b·α·p dz [N/m].
    viscous : numpy.ndarray
        ∫ η·u/h + h/2·(1 − α)·dp/dz dz [N/m].
    share : numpy.ndarray
        Asperity share of the contact load α [-] (load-weighted over the zones).
    film : numpy.ndarray
        Film at the pressure maximum h* of the main zone (largest peak pressure) [m].
    full_film : numpy.ndarray
        Its full-film IHL value h*₀ [m], before the asperities take a share (the flooded
        film of the module's item 1, or the starved one, at most 2·h_s, when ``supply_layer`` is
        finite).
    flow : numpy.ndarray
        Flow through the main zone per unit circumference q = u·h*/2 [m²/s].
    max_gradient : float
        Steepest inlet gradient of the main zone w_max [Pa/m].
    film_profile : numpy.ndarray
        Film h(z) [m] at every point of the profile (inf outside the contact).
    squeeze : numpy.ndarray
        The film's relative thinning rate when sliding stops, s = −(dh*/dt)/h* [1/s]: the
        load the film carries, (1 − α)·F'_N, squeezing it out of all zones at once
        (:func:`~.squeeze_film.squeeze_thinning_rate`; 0 where the asperities carry it all).
    """

    friction: np.ndarray
    boundary: np.ndarray
    viscous: np.ndarray
    share: np.ndarray
    film: np.ndarray
    full_film: np.ndarray
    flow: np.ndarray
    max_gradient: float
    film_profile: np.ndarray
    squeeze: np.ndarray


def reciprocating_friction(position, pressure, speed, viscosity, roughness, asperity_modulus,
                           boundary_friction, direction=1, *, film_factor=1.0,
                           supply_layer=np.inf, sealed_pressure=0.0, resolution=None,
                           poisson=0.5,
                           roughness_density=DEFAULT_ROUGHNESS_DENSITY,
                           roughness_slope=DEFAULT_ROUGHNESS_SLOPE) -> ContactFriction:
    """Steady friction of a lubricated seal contact per unit circumference, Eq. (2).

    Parameters
    ----------
    position : array_like
        Axial positions z [m], strictly ascending, covering the contact with p = 0 around it.
    pressure : array_like
        Static contact pressure p(z) [Pa] (FE or Hertz).
    speed : array_like
        Sliding speeds u [m/s], > 0 (1-D).
    viscosity : array_like
        Lubricant viscosity in the contact η [Pa·s] (scalar or per speed).
    roughness : float
        Combined RMS roughness σ [m].
    asperity_modulus : array_like
        Rubber modulus at the asperity frequency E [Pa] (scalar or per speed).
    boundary_friction : float
        μ_b [-].
    direction : {1, -1}
        Sliding direction of the counter surface relative to the seal (+1 towards +z).
    film_factor : float
        Multiplier of the full film h*₀ [-] (1: the IHL film; a calibration may fit it).
    supply_layer : float
        Lubricant layer on the counter surface ahead of the seal h_s [m], its only supply:
        the first contact zone the counter surface reaches gets a full film of at most 2·h_s
        (a starved inlet, :func:`~.inverse_hydrodynamics.starved_film`), each next zone at
        most the film h* of the zone before it, which leaves the layer h*/2 (mass
        conservation); ``inf``: every zone fully flooded.
    sealed_pressure : float
        Fluid pressure on the −z side of the profile Δp [Pa] (the pressurised side of an FE
        map's profile).  The film's pressure there starts at Δp, not at 0: Reynolds' equation
        is solved for the film pressure max(p, Δp) up to the first contact zone's peak, whose
        inlet on that side rises from Δp (the contact pressure, the solid part of the load
        that the asperity share and the boundary friction act on, is unchanged).
    resolution : float, optional
        Secant length of :func:`~.inverse_hydrodynamics.max_inlet_gradient` [m].
    poisson, roughness_density, roughness_slope : float
        See :func:`~sealsim.tribology.contact.asperity_pressure`.

    Returns
    -------
    ContactFriction

    Examples
    --------
    A parabolic 1 MPa contact 1 mm wide (F'_N = 667 N/m), oil of 0.1 Pa·s, σ = 0.3 µm,
    μ_b = 0.2: nearly boundary friction at 1 µm/s (0.2 × 667 N/m = 133 N/m, the asperities
    carry 97.4 %), mixed at 1 cm/s, hydrodynamic at 1 m/s:

    >>> z = np.linspace(-0.6e-3, 0.6e-3, 241)
    >>> p = 1e6 * np.clip(1 - (z / 0.5e-3) ** 2, 0, None)
    >>> r = reciprocating_friction(z, p, [1e-6, 1e-2, 1.0], 0.1, 0.3e-6, 10e6, 0.2)
    >>> r.friction.round(1).tolist(), r.share.round(3).tolist()
    ([129.9, 66.1, 20.8], [0.974, 0.484, 0.0])
    """
    z = np.asarray(position, dtype=float)
    p = np.asarray(pressure, dtype=float)
    u = np.abs(np.atleast_1d(np.asarray(speed, dtype=float)))
    eta = np.broadcast_to(np.asarray(viscosity, dtype=float), u.shape)
    modulus = np.broadcast_to(np.asarray(asperity_modulus, dtype=float), u.shape)
    args = (poisson, roughness_density, roughness_slope)
    n = u.size
    boundary = np.zeros(n)
    viscous = np.zeros(n)
    share_load = np.zeros(n)
    h_profile = np.full((n, z.size), np.inf)
    main = None
    total_load = 0.0
    zones = list(enumerate(contact_zone_slices(p)))
    # in the order the counter surface passes them: with a limited supply each zone is fed
    # by the layer h*/2 the one before leaves (the first by h_s)
    supply = np.full(n, float(supply_layer))
    for number, zone in (zones if direction > 0 else zones[::-1]):
        zz, pz = z[zone], p[zone]
        if zz.size < 2:
            continue
        load = float(np.trapezoid(pz, zz))
        total_load += load
        pmax = float(pz.max())
        if number == 0 and sealed_pressure > 0.0:
            # the film's pressure: the sealed pressure up to the first contact's peak
            peak = int(np.argmax(pz))
            pz = np.concatenate([np.maximum(pz[:peak], min(sealed_pressure, pmax)),
                                 pz[peak:]])
        w_max = max_inlet_gradient(zz, pz, direction, resolution)
        flooded = film_factor * film_at_pressure_maximum(eta, u, w_max) if w_max > 0 else \
            np.full(n, np.inf)
        h0 = starved_film(flooded, supply)
        alpha, film = ihl_load_share(h0, pmax, roughness, modulus, *args,
                                     film_limit=2.0 * supply)
        if np.isfinite(supply_layer):
            supply = np.minimum(supply, 0.5 * film)
        shape, grad = film_shape_along(zz, pz, direction, w_max)
        h = film[:, None] * shape[None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            couette = eta[:, None] * u[:, None] / h
            poiseuille = np.where(np.isfinite(h),
                                  0.5 * h * (1.0 - alpha[:, None]) * grad[None, :], 0.0)
        viscous += np.trapezoid(couette + poiseuille, zz, axis=-1)
        boundary += boundary_friction * alpha * load
        share_load += alpha * load
        h_profile[:, zone] = h
        if main is None or pmax > main[0] or (pmax == main[0] and direction < 0):
            main = (pmax, film, h0, w_max)
    if main is None:
        zero = np.zeros(n)
        return ContactFriction(zero, zero, zero, zero, np.full(n, np.inf), np.full(n, np.inf),
                               zero, 0.0, h_profile, zero)
    _, film, h0, w_max = main
    squeeze = squeeze_thinning_rate(total_load - share_load, eta,
                                    squeeze_resistance(z, h_profile), film)
    return ContactFriction(boundary + viscous, boundary, viscous,
                           share_load / total_load if total_load > 0 else share_load,
                           film, h0, 0.5 * u * film, w_max, h_profile, squeeze)
