"""Inverse hydrodynamics and mixed lubrication of a reciprocating seal against closed forms."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sealsim.tribology.contact import (
    asperity_pressure,
    greenwood_williamson_integral,
    separation_at_asperity_pressure,
)
from sealsim.tribology.inverse_hydrodynamics import (
    film_at_pressure_maximum,
    film_shape_factor,
    ihl_film_profile,
    max_inlet_gradient,
    starved_film,
    stroke_transport,
)
from sealsim.tribology.mixed_lubrication import (
    contact_zone_slices,
    ihl_load_share,
    reciprocating_friction,
)

ETA, SIGMA, MODULUS, MU_B = 0.1, 0.3e-6, 10e6, 0.2


def parabola(p0=1e6, a=0.5e-3, n=2001):
    z = np.linspace(-1.2 * a, 1.2 * a, n)
    return z, p0 * np.clip(1.0 - (z / a) ** 2, 0.0, None)


def triangle(p0=1e6, rise=0.4e-3, fall=1.2e-3):
    """Inlet (low z) rising over ``rise``, outlet falling over ``fall``, zero around."""
    z = np.array([-0.1e-3, 0.0, rise, rise + fall, rise + fall + 0.1e-3])
    return z, np.array([0.0, 0.0, p0, 0.0, 0.0])


def refine(z, p, n=4001):
    """The same piecewise-linear profile on a fine grid (keeping every kink)."""
    fine = np.union1d(np.linspace(z[0], z[-1], n), z)
    return fine, np.interp(fine, z, p)


def test_parabolic_profile_film_matches_closed_form():
    # Hertzian (parabolic) p = p0(1 - z²/a²): steepest inlet gradient 2·p0/a at the edge;
    # the secant over Δ underestimates it by Δ/(2a): 1e-4 here
    p0, a = 1e6, 0.5e-3
    z, p = parabola(p0, a, 20001)
    w = max_inlet_gradient(z, p, +1, resolution=1e-4 * a)
    assert w == pytest.approx(2 * p0 / a, rel=2e-4)
    u = np.array([1e-3, 0.1, 1.0])
    h = film_at_pressure_maximum(ETA, u, w)
    assert h == pytest.approx(np.sqrt(8 * ETA * u / (9 * 2 * p0 / a)), rel=2e-4)
    # symmetric profile: both strokes see the same film
    assert max_inlet_gradient(z, p, -1, resolution=1e-4 * a) == pytest.approx(w, rel=1e-9)


def test_triangular_profile_stroke_films_in_ratio_sqrt_of_gradients():
    z, p = triangle(1e6, 0.4e-3, 1.2e-3)
    w1, w2 = 1e6 / 0.4e-3, 1e6 / 1.2e-3
    assert max_inlet_gradient(z, p, +1) == pytest.approx(w1, rel=1e-12)
    assert max_inlet_gradient(z, p, -1) == pytest.approx(w2, rel=1e-12)
    h_out = film_at_pressure_maximum(ETA, 0.2, max_inlet_gradient(z, p, +1))
    h_in = film_at_pressure_maximum(ETA, 0.2, max_inlet_gradient(z, p, -1))
    assert h_out / h_in == pytest.approx(np.sqrt(w2 / w1), rel=1e-12)
    # the steep flank as inlet gives the thinner film: the instroke (shallow inlet) drags
    # back more than the outstroke leaves -> no net leakage
    assert stroke_transport(0.012, 0.1, h_out, h_in) < 0


def test_inlet_gradient_does_not_depend_on_where_the_profile_lies_on_the_z_axis():
    # A convex inlet (a lip's steep flank next to its pressure maximum): p = p0·(s/L)³ over
    # L = 1 mm, 31 points, Δ = two spacings = 0.1 mm.  The steepest secant ends on the peak:
    # p0·(1 − 0.9³)/Δ = 2.71 GPa/m.  The − stroke mirrors z, so a profile at z > 0 (an FE
    # map's contact off the gland centre) is searched at negative z: the old bound
    # z + Δ <= z_peak·(1 + 1e-15) dropped the secant ending on the peak there by rounding
    # (2.43 GPa/m, −10 %).
    z = np.linspace(0.0, 1.5e-3, 31)
    s = z / 1e-3
    p = 1e6 * np.where(s <= 1.0, s**3, (1.5 - s) / 0.5)
    expected = 1e6 * (1.0 - 0.9**3) / 0.1e-3
    for offset in (0.0, 2e-3, -2e-3, -5e-3):
        assert max_inlet_gradient(z + offset, p, +1) == pytest.approx(expected, rel=1e-9)
        mirrored = -(z + offset)[::-1]
        assert max_inlet_gradient(mirrored, p[::-1], -1) == pytest.approx(expected, rel=1e-9)


def test_film_shape_solves_reynolds_cubic():
    r = np.linspace(-5.0, 1.0, 61)
    for upstream in (False, True):
        h = film_shape_factor(r, upstream)
        ok = np.isfinite(h)
        residual = 4 / 27 * r[ok] * h[ok] ** 3 - h[ok] + 1
        assert np.max(np.abs(residual)) < 1e-10
    assert film_shape_factor(1.0) == pytest.approx(1.5)
    assert film_shape_factor(0.0) == 1.0
    assert np.all(film_shape_factor(r[r < 0]) < 1.0)


def outlet_film_ratio(w_in, w_out):
    """H on a straight outlet flank: root in (0, 1) of (4/27)(-w_out/w_in)H³ - H + 1 = 0."""
    roots = np.roots([-4 / 27 * w_out / w_in, 0.0, -1.0, 1.0])
    real = roots[np.abs(roots.imag) < 1e-12].real
    return float(real[(real > 0) & (real < 1)][0])


def test_hydrodynamic_limit_of_a_triangular_contact():
    # no asperity contact (smooth surfaces): the friction is the shear of the IHL film, with
    # h = 3/2 h* on the straight inlet flank and H2·h* on the straight outlet flank
    p0, rise, fall = 1e6, 0.4e-3, 1.2e-3
    z, p = refine(*triangle(p0, rise, fall))
    u = np.array([0.05, 0.5])
    r = reciprocating_friction(z, p, u, ETA, 1e-15, MODULUS, MU_B, +1, resolution=1e-9)
    w1, w2 = p0 / rise, p0 / fall
    h = np.sqrt(8 * ETA * u / (9 * w1))
    h2 = outlet_film_ratio(w1, w2)
    couette = ETA * u * (rise / (1.5 * h) + fall / (h2 * h))      # η·u·∫dz/h
    pressure_term = 0.5 * h * (1.5 * p0 - h2 * p0)                 # ∫ h/2·dp/dz dz
    assert np.all(r.share < 1e-12)
    assert r.boundary == pytest.approx(0.0, abs=1e-9)
    # trapezoid rule across the kink at the apex: one grid cell of 4000
    assert r.viscous == pytest.approx(couette + pressure_term, rel=2e-3)
    assert r.film == pytest.approx(h, rel=1e-9)
    # the seal: F = π·D·f
    diameter = 0.032
    assert np.pi * diameter * r.viscous == pytest.approx(
        np.pi * diameter * (couette + pressure_term), rel=2e-3)


def test_boundary_limit_and_a_friction_minimum_between():
    z, p = parabola(1e6, 0.5e-3, 2001)
    load = np.trapezoid(p, z)                                       # F'_N [N/m]
    u = np.logspace(-12, 1, 53)
    r = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B)
    # u -> 0: the asperities carry the load, f -> μ_b·F'_N (the film, and with it the share
    # of the fluid, vanishes like u^(1/3): 1e-12 m/s leaves 0.1 % of the load to the fluid)
    assert r.friction[0] == pytest.approx(MU_B * load, rel=2e-3)
    assert r.share[0] > 0.998
    # hydrodynamic at high speed: no asperity load, f grows like √u
    assert r.share[-1] < 1e-12
    assert r.friction[-1] / r.friction[-5] == pytest.approx(np.sqrt(u[-1] / u[-5]), rel=0.02)
    # a minimum strictly between the branches
    k = int(np.argmin(r.friction))
    assert 0 < k < u.size - 1
    assert r.friction[k] < 0.2 * r.friction[0] and r.friction[k] < 0.2 * r.friction[-1]
    # the share falls monotonically with speed
    assert np.all(np.diff(r.share) <= 1e-12)


def test_load_share_solves_its_two_conditions():
    h0 = np.array([1e-8, 1e-7, 3e-7, 1e-6])
    pmax = 1.2e6
    share, film = ihl_load_share(h0, pmax, SIGMA, MODULUS)
    dry = separation_at_asperity_pressure(pmax, SIGMA, MODULUS)
    lift = film                                         # lift of the rubber off its dry place
    # the asperities carry α·p_max at the separation dry + lift
    assert asperity_pressure(dry + lift, SIGMA, MODULUS) == pytest.approx(share * pmax,
                                                                           rel=1e-6, abs=1e-3)
    # the fluid's share (1 - α) sets the film: h* = h*0/√(1 - α)
    assert film == pytest.approx(h0 / np.sqrt(1 - share), rel=1e-6)
    assert np.all(np.diff(share) < 0)
    # a stiffer rubber needs a thinner film to lift off its asperities
    stiff, _ = ihl_load_share(h0, pmax, SIGMA, 10 * MODULUS)
    assert np.all(stiff < share)


@settings(max_examples=200, deadline=None)
@given(log_film=st.floats(-11.0, -4.5), log_pressure=st.floats(4.0, 7.5),
       log_roughness=st.floats(-7.5, -5.5), log_modulus=st.floats(6.0, 9.0))
def test_load_share_is_the_root_a_plain_bisection_finds(log_film, log_pressure, log_roughness,
                                                        log_modulus):
    # Eq. (1) has one root (both sides monotone in the separation): a 200-step bisection of
    # its plain form α_asp(λ) − (1 − (h*0/h(λ))²), independent of the solver's logarithmic
    # regula falsi, finds the same lift.  1e-9 relative: the bisection's own round-off at
    # λ_dry ≈ −5 (the lift is a difference of two separations) stays below it.
    h0, pmax, sigma, modulus = 10.0 ** np.array([log_film, log_pressure, log_roughness,
                                                 log_modulus])
    share, film = ihl_load_share(h0, pmax, sigma, modulus)
    dry = separation_at_asperity_pressure(pmax, sigma, modulus) / sigma
    lo, hi = dry, dry + h0 / sigma + 12.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        excess = (asperity_pressure(mid * sigma, sigma, modulus) / pmax
                  - (1.0 - (h0 / ((mid - dry) * sigma)) ** 2))
        lo, hi = (mid, hi) if excess > 0 else (lo, mid)
    assert float(film) == pytest.approx((0.5 * (lo + hi) - dry) * sigma, rel=1e-9)
    assert float(film) == pytest.approx(h0 / np.sqrt(1.0 - float(share)), rel=1e-9)


def test_compiled_interpolation_is_numpys():
    # the compiled root finder reads F_3/2 from the table as asperity_pressure does with
    # np.interp: the same value to the last bit (grid points, cells, both ends, beyond them)
    from sealsim.tribology.contact import _GW_GRID, _LOG_F32
    from sealsim.tribology.mixed_lubrication import _interp

    rng = np.random.default_rng(7)
    x = np.concatenate([rng.uniform(-31.0, 13.0, 20000), _GW_GRID[::97], _GW_GRID[[0, -1]],
                        np.nextafter(_GW_GRID[1:50], -np.inf), [-1e9, 1e9]])
    ours = np.array([_interp(v, _GW_GRID, _LOG_F32) for v in x])
    assert np.array_equal(ours, np.interp(x, _GW_GRID, _LOG_F32))
    assert np.isnan(_interp(np.nan, _GW_GRID, _LOG_F32))


def test_a_starved_inlet_passes_what_arrives_and_no_more():
    # Mass conservation: a layer h_s on the counter surface brings u·h_s; the contact passes
    # u·h*/2.  Where the flooded film would pass more, the starved contact passes exactly the
    # supply (the flow of the main zone within 1e-12), its film is 2·h_s at most, and the
    # asperities take the load the thinner film leaves them.  A supply thicker than the
    # flooded film at every speed changes nothing (bitwise).
    z, p = parabola(1e6, 0.5e-3, 2001)
    u = np.logspace(-6, 0, 25)
    flooded = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B)
    h_s = 0.1e-6
    starved = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B, supply_layer=h_s)
    short = flooded.film > 2 * h_s
    assert short.any() and (~short).any()            # both regimes on this speed range
    np.testing.assert_allclose(starved.flow[short], u[short] * h_s, rtol=1e-12)
    assert np.all(starved.film <= 2 * h_s * (1 + 1e-12))
    np.testing.assert_array_equal(starved.friction[~short], flooded.friction[~short])
    assert np.all(starved.share[short] > flooded.share[short])
    # less supply, more asperity load and more friction at every speed
    thinner = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B, supply_layer=h_s / 4)
    assert np.all(thinner.friction >= starved.friction * (1 - 1e-12))
    assert np.all(thinner.share >= starved.share - 1e-12)
    wide = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B, supply_layer=1.0)
    np.testing.assert_array_equal(wide.friction, flooded.friction)
    assert starved_film(flooded.full_film, h_s) == pytest.approx(starved.full_film)


def test_a_starved_second_zone_gets_only_what_the_first_leaves():
    # Two lobes in series (an X-ring), fed by a layer h_s = 0.5 µm on the counter surface and
    # nothing else: the first lobe the surface reaches passes u·h*_1/2 and leaves the layer
    # h*_1/2, all the second one gets, so h*_2 <= h*_1 (mass conservation).  The narrow lobe
    # (steep inlet) builds the thinner film, 0.06-0.85 µm flooded from 1e-5 to 0.03 m/s
    # against the wide lobe's 0.09-1.4 µm: sliding from the narrow lobe to the wide one, the
    # wide lobe used to be starved to 2·h_s only and passed up to 1.7x what reached it.
    z = np.linspace(0.0, 4e-3, 4001)
    narrow = 1e6 * np.clip(1 - ((z - 0.8e-3) / 0.3e-3) ** 2, 0, None)
    wide = 0.8e6 * np.clip(1 - ((z - 2.6e-3) / 1.0e-3) ** 2, 0, None)
    p = narrow + wide
    at_narrow, at_wide = int(np.argmax(narrow)), int(np.argmax(wide))
    u = np.logspace(-5, -1, 9)
    h_s = 0.5e-6
    flooded = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B, +1)
    thinner = flooded.film_profile[:, at_narrow] < flooded.film_profile[:, at_wide]
    assert thinner.all()
    for direction, first, second in ((+1, at_narrow, at_wide), (-1, at_wide, at_narrow)):
        r = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B, direction,
                                   supply_layer=h_s)
        h_first, h_second = r.film_profile[:, first], r.film_profile[:, second]
        assert np.all(h_first <= 2 * h_s * (1 + 1e-12))
        assert np.all(h_second <= h_first * (1 + 1e-12))
        # a zone that gets more than it passes keeps its own (flooded) film
        full = flooded.film_profile[:, second] <= h_first
        np.testing.assert_allclose(h_second[full], flooded.film_profile[full, second],
                                   rtol=1e-12)
    # from the narrow lobe to the wide one the wide lobe is starved by the narrow one's layer
    r = reciprocating_friction(z, p, u, ETA, SIGMA, MODULUS, MU_B, +1, supply_layer=h_s)
    assert np.all(r.film_profile[:, at_wide] < flooded.film_profile[:, at_wide])


def test_asperity_pressure_is_greenwood_williamson():
    lam = np.array([-3.0, 0.0, 1.5])
    e_star = MODULUS / 0.75
    expected = 4 / 3 * e_star * 0.04 * np.sqrt(0.01) * greenwood_williamson_integral(1.5, lam)
    assert asperity_pressure(lam * SIGMA, SIGMA, MODULUS) == pytest.approx(expected, rel=1e-5)
    back = separation_at_asperity_pressure(expected, SIGMA, MODULUS)
    assert back == pytest.approx(lam * SIGMA, abs=1e-4 * SIGMA)


def test_two_zones_add_and_the_film_profile_follows_reynolds():
    z = np.linspace(0.0, 3e-3, 3001)
    lobe = lambda c: 1e6 * np.clip(1 - ((z - c) / 0.4e-3) ** 2, 0, None)   # noqa: E731
    p = lobe(0.8e-3) + 0.7 * lobe(2.2e-3)
    assert len(contact_zone_slices(p)) == 2
    both = reciprocating_friction(z, p, [0.01, 1.0], ETA, SIGMA, MODULUS, MU_B)
    one = reciprocating_friction(z, lobe(0.8e-3), [0.01, 1.0], ETA, SIGMA, MODULUS, MU_B)
    other = reciprocating_friction(z, 0.7 * lobe(2.2e-3), [0.01, 1.0], ETA, SIGMA, MODULUS,
                                   MU_B)
    assert both.friction == pytest.approx(one.friction + other.friction, rel=1e-9)
    assert both.film == pytest.approx(one.film, rel=1e-12)     # main zone: the higher lobe
    # the film profile of a single zone equals the IHL film shape times h*
    zz, pp = parabola(1e6, 0.5e-3, 401)
    r = reciprocating_friction(zz, pp, [0.5], ETA, 1e-15, MODULUS, MU_B, -1)
    shape = ihl_film_profile(zz, pp, r.film, -1)[0]
    wet = np.isfinite(r.film_profile[0])
    assert wet.sum() > 150
    assert r.film_profile[0, wet] == pytest.approx(shape[wet], rel=1e-9)


def test_sealed_pressure_softens_the_pressurised_inlet():
    # an FE contact pressure drops from Δp to 0 over one element at the wetted edge (the fluid's
    # pressure is not part of it); the film's pressure starts at the sealed pressure, so the
    # inlet on that side rises from Δp: gradient 0.5 MPa/0.4 mm instead of 0.5 MPa/0.01 mm;
    # the other stroke (inlet on the +z flank) and the contact load are unchanged
    z0 = np.array([-0.1e-3, 0.0, 0.01e-3, 0.41e-3, 1.61e-3, 1.7e-3])
    p0 = np.array([0.0, 0.0, 0.5e6, 1e6, 0.0, 0.0])
    z, p = refine(z0, p0, 8001)
    u = np.array([0.01])
    plain = reciprocating_friction(z, p, u, ETA, 1e-15, MODULUS, MU_B, +1, resolution=1e-9)
    sealed = reciprocating_friction(z, p, u, ETA, 1e-15, MODULUS, MU_B, +1, resolution=1e-9,
                                    sealed_pressure=0.5e6)
    assert plain.max_gradient == pytest.approx(0.5e6 / 0.01e-3, rel=1e-6)
    assert sealed.max_gradient == pytest.approx(0.5e6 / 0.4e-3, rel=1e-6)
    assert sealed.film == pytest.approx(np.sqrt(40.0) * plain.film, rel=1e-6)
    back = reciprocating_friction(z, p, u, ETA, 1e-15, MODULUS, MU_B, -1, resolution=1e-9,
                                  sealed_pressure=0.5e6)
    back_plain = reciprocating_friction(z, p, u, ETA, 1e-15, MODULUS, MU_B, -1,
                                        resolution=1e-9)
    assert back.film == pytest.approx(back_plain.film, rel=1e-12)
    rough = dict(roughness=SIGMA, asperity_modulus=MODULUS, boundary_friction=MU_B)
    slow = reciprocating_friction(z, p, [1e-12], ETA, direction=1, sealed_pressure=0.5e6,
                                  **rough)
    assert slow.boundary[0] == pytest.approx(MU_B * np.trapezoid(p, z), rel=5e-3)
