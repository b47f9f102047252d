"""Lip contact tribology: film law, Couette shear, asperity load share, Grosch master curve."""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.stats import norm

from sealsim.properties.elastomers import get_elastomer
from sealsim.tribology.contact import asperity_load_share, greenwood_williamson_integral
from sealsim.tribology.film import (
    FILM_FLOOR,
    FILM_REFERENCE_LOAD,
    FILM_REFERENCE_MODULUS,
    SKF_FIT_COEFFICIENT,
    SKF_FIT_EXPONENT,
    SKF_FIT_RANGE,
    FilmRangeWarning,
    film_coefficient_matching_fit,
    film_range_note,
    film_thickness,
    soft_ehl_load_modulus_factor,
)
from sealsim.tribology.rubber_friction import (
    CATALOGUE_LOSS_PEAK_FREQUENCY,
    DEFAULT_ASPERITY_WAVELENGTH,
    DEFAULT_MASTER_CURVE,
    GROSCH_ADHESION_LENGTH,
    grosch_friction_coefficient,
    loss_peak_frequency,
)
from sealsim.tribology.shear import duty_parameter, viscous_friction_force


def test_default_film_law_reproduces_seed_measured_fit():
    # Seed 000 Eq. 8: h[µm] = 3.45 (u η)^0.68, the model uses Eq. 5 with exponent 0.66.
    x = np.geomspace(*SKF_FIT_RANGE, 200)
    model = film_thickness(x, 1.0, film_coefficient_matching_fit(), floor=0.0)
    measured = SKF_FIT_COEFFICIENT * x**SKF_FIT_EXPONENT
    # The exponents differ by 0.02: model/measured = (x/x_mid)^-0.02 around the geometric centre
    # of the range, so over ±1.70 decades it cannot get closer than 10^(1.70·0.02) - 1 = 8.1 %
    # at the ends; the least-squares coefficient reaches exactly that bound.
    half_decades = 0.5 * np.log10(SKF_FIT_RANGE[1] / SKF_FIT_RANGE[0])
    bound = 10 ** (half_decades * (SKF_FIT_EXPONENT - 0.66)) - 1
    assert np.max(np.abs(model / measured - 1)) <= bound + 1e-6
    # and the least-squares coefficient is centred: the log errors balance
    assert abs(np.mean(np.log(model / measured))) < 1e-3


def test_film_floor_and_standstill():
    h = film_thickness(0.01, np.array([0.0, 1e-6, 1.0]), film_coefficient_matching_fit())
    assert h[0] == FILM_FLOOR and h[1] == FILM_FLOOR  # boundary limit, never zero
    assert h[2] > FILM_FLOOR


def test_film_factor_scales_film():
    base = film_thickness(0.01, 5.0, 3e-6)
    assert film_thickness(0.01, 5.0, 3e-6, film_factor=1.3) == pytest.approx(1.3 * base)


@given(eta=st.floats(1e-3, 1.0), u=st.floats(1e-3, 30.0))
def test_viscous_force_follows_fit_scaling(eta, u):
    # With h = f (ηu)^0.66: F_lub = S (ηu)^0.34 / f -- check against that closed form.
    f = film_coefficient_matching_fit()
    h = film_thickness(eta, u, f, floor=0.0)
    force = viscous_friction_force(eta, u, h, 1e-4)
    assert force == pytest.approx(1e-4 * (eta * u) ** 0.34 / f, rel=1e-9)
    assert force > 0


@pytest.mark.parametrize("order", [1.0, 1.5])
def test_greenwood_williamson_integrals_against_quadrature(order):
    # F_n(Λ) = ∫_Λ^∞ (s-Λ)^n φ(s) ds evaluated numerically (independent of the closed form in
    # parabolic cylinder functions); 1e-7: quadrature accuracy, the forms are identical.
    for lam in (-1.0, 0.0, 0.5, 1.0, 2.0, 3.5):
        numeric, _ = quad(lambda s, lam=lam: (s - lam) ** order * norm.pdf(s), lam, np.inf,
                          epsabs=1e-13)
        assert greenwood_williamson_integral(order, lam) == pytest.approx(numeric, rel=1e-7)


def test_asperity_load_share_is_the_greenwood_williamson_load_ratio():
    # Finding 3: what multiplies a friction coefficient is a share of the LOAD (GW: ∝ F_3/2),
    # not an area fraction.  Dry limit Λ = 0: the whole load on the asperities, so
    # F_material = μ_dry·F_tip exactly (Amontons/Bowden-Tabor: μ_dry already holds the real
    # area).  Full film: no asperity load.  Exact limits, then GW's ratio F_3/2(Λ)/F_3/2(0).
    lam = np.linspace(0, 5, 200)
    share = asperity_load_share(lam)
    assert share[0] == pytest.approx(1.0, abs=1e-12)
    assert np.all(np.diff(share) < 0) and np.all(share > 0)
    assert asperity_load_share(-0.3) == pytest.approx(1.0, abs=1e-12)  # no film: dry
    numeric = quad(lambda s: (s - 1.0) ** 1.5 * norm.pdf(s), 1.0, np.inf)[0] / quad(
        lambda s: s**1.5 * norm.pdf(s), 0.0, np.inf)[0]
    assert asperity_load_share(1.0) == pytest.approx(numeric, rel=1e-6)
    # the tabulated share against the closed form everywhere (1e-5: the tabulation's bound)
    lam = np.linspace(0, 12, 2001)
    exact = greenwood_williamson_integral(1.5, lam) / greenwood_williamson_integral(1.5, 0.0)
    assert np.allclose(asperity_load_share(lam), exact, rtol=1e-5, atol=0)


def test_soft_ehl_film_scaling_matches_hamrock_dowson():
    # Finding 5: Hamrock & Dowson (J. Lubr. Technol. 100 (1978) 236), soft EHL central film
    # H_c = 7.32(1 - 0.72 e^-0.28k) U^0.64 W^-0.22, H = h/R, U = ηu/(E'R), W = w/(E'R²),
    # evaluated dimensionally for a lip-like contact: the film ratios for 2x load and 2x
    # modulus must equal sealsim's factor.  Tolerance 1e-9: same exponents, round-off only;
    # what is checked is the derivation E' exponent = -0.64 + 0.22.
    def hamrock_dowson(eta_u, e_prime, radius, load, k=20.0):
        u_dim = eta_u / (e_prime * radius)
        w_dim = load / (e_prime * radius**2)
        return radius * 7.32 * (1 - 0.72 * np.exp(-0.28 * k)) * u_dim**0.64 * w_dim**-0.22

    base = hamrock_dowson(0.05, 6.7e6, 0.3e-3, 30.0)
    assert hamrock_dowson(0.05, 6.7e6, 0.3e-3, 60.0) / base == pytest.approx(
        float(soft_ehl_load_modulus_factor(2 * FILM_REFERENCE_LOAD, FILM_REFERENCE_MODULUS)),
        rel=1e-9)
    assert hamrock_dowson(0.05, 13.4e6, 0.3e-3, 30.0) / base == pytest.approx(
        float(soft_ehl_load_modulus_factor(FILM_REFERENCE_LOAD, 2 * FILM_REFERENCE_MODULUS)),
        rel=1e-9)
    assert soft_ehl_load_modulus_factor(FILM_REFERENCE_LOAD, FILM_REFERENCE_MODULUS) == 1.0


def test_film_range_note_and_warning_class():
    # Finding 5: the measured range of lip seal films is 0.25-2.5 µm (Jagger 1957; Poll &
    # Gabelli 1992); a note (and FilmRangeWarning in the simulation) outside it, none inside.
    assert film_range_note(0.25e-6, 2.5e-6) == ""
    assert "above the measured range" in film_range_note(0.3e-6, 4e-6)
    assert "below the measured range" in film_range_note(0.02e-6, 1e-6)
    assert issubclass(FilmRangeWarning, UserWarning)


def test_grosch_peak_is_the_hysteresis_peak_of_the_asperities():
    # Finding 4.  Grosch (1963): the friction peak lies at v_max = λ·f_max, λ ≈ 6 nm on smooth
    # glass (adhesion) and of the order of the asperity spacing (≈ 0.15 mm) on rough silicon
    # carbide (hysteresis).  The oil-wetted lip keeps only the hysteresis part, so the
    # default's λ must be an asperity spacing (10-200 µm), not the adhesion length.
    wavelength = DEFAULT_MASTER_CURVE.peak_speed_reference / CATALOGUE_LOSS_PEAK_FREQUENCY
    assert wavelength == pytest.approx(DEFAULT_ASPERITY_WAVELENGTH, rel=1e-12)
    assert 10e-6 <= wavelength <= 200e-6 and wavelength > 1e3 * GROSCH_ADHESION_LENGTH


@pytest.mark.parametrize("material", ["NBR", "FKM"])
def test_loss_peak_frequency_is_where_the_storage_modulus_rises_fastest(material):
    # Kramers-Kronig approximation tan δ ≈ (π/2) d ln E'/d ln f (Booij & Thoone 1982): the
    # loss peak sits at the steepest point of the storage-modulus master curve, found here
    # numerically on a 0.01-decade grid (tolerance: 0.02 decades, the grid).
    elastomer = get_elastomer(material)
    f = np.logspace(-8, 4, 1201)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        e = elastomer.modulus(np.full_like(f, elastomer.wlf_reference_temperature), f)
    steepest = f[np.argmax(np.gradient(np.log(e), np.log(f)))]
    assert np.log10(steepest) == pytest.approx(np.log10(loss_peak_frequency(elastomer)),
                                               abs=0.02)


@pytest.mark.parametrize("material", ["NBR", "FKM"])
def test_mu_dry_falls_with_temperature_at_lip_seal_speeds(material):
    # Finding 4: with the hysteresis peak, lip seal speeds (0.04-13 m/s) lie on the rubbery
    # flank of the master curve from 20 °C up, so a hotter contact has a lower μ_dry: the
    # friction-temperature feedback is stabilising (the adhesion-peak default rose with
    # temperature between 20 and 60 °C).  Exact sign check on a grid.
    elastomer = get_elastomer(material)
    temps = np.linspace(293.15, 413.15, 25)[:, None]
    speeds = np.geomspace(0.04, 13.0, 30)[None, :]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        shift = elastomer.log10_shift_factor(temps)
    peak = DEFAULT_MASTER_CURVE.peak_speed_reference * loss_peak_frequency(
        elastomer) / CATALOGUE_LOSS_PEAK_FREQUENCY
    curve = DEFAULT_MASTER_CURVE.__class__(DEFAULT_MASTER_CURVE.mu_peak,
                                           DEFAULT_MASTER_CURVE.mu_low, peak,
                                           DEFAULT_MASTER_CURVE.width_decades)
    mu = grosch_friction_coefficient(speeds, shift, curve)
    assert np.all(np.diff(mu, axis=0) <= 0)
    # and the peak itself is far above operating speeds at 80-120 °C (> 1 km/s)
    assert np.all(peak / 10 ** shift[temps[:, 0] >= 353.15] > 1e3)


def test_grosch_peak_and_time_temperature_superposition():
    c = DEFAULT_MASTER_CURVE
    # the peak lies at a_T·v = v_peak,ref (exact: the bell's centre)
    assert grosch_friction_coefficient(c.peak_speed_reference * 1e8, -8.0) == pytest.approx(
        c.mu_peak)
    # time-temperature superposition: shifting log a_T by one decade = speed x 10
    v = np.geomspace(1e-4, 10, 30)
    assert np.allclose(grosch_friction_coefficient(v, -9.0),
                       grosch_friction_coefficient(10 * v, -10.0))
    mu = grosch_friction_coefficient(np.geomspace(1e-9, 1e9, 500), -8.0)
    assert np.all(mu >= c.mu_low) and np.all(mu <= c.mu_peak)


def test_duty_parameter_equals_guembel_number():
    # G = η ω b / W' is η ω / p̄ with p̄ = W'/b (the Gümbel number of lip seal Stribeck curves)
    eta, omega, b, w = 0.0124, 157.1, 0.15e-3, 119.4
    assert duty_parameter(eta, omega, b, w) == pytest.approx(eta * omega / (w / b))


# -- squeeze film at rest --------------------------------------------------------------------
def test_squeeze_resistance_of_a_cylinder_near_a_plane():
    # Independent closed form: a long cylinder of radius R_c at the gap h0 from a plane, its
    # film h = h0 + z²/(2·R_c), carries W' = 3·√2·π·η·V·(R_c/h0)^(3/2) per unit length when
    # squeezed at V (Hamrock, Schmid & Jacobson 2004, normal squeeze film of a long cylinder;
    # p = 0 far from the gap).  The zone is cut at ±30·√(2·R_c·h0) (the integrand's tail
    # beyond is 1e-4 of the total) and integrated on 20001 points: 1e-3.
    from sealsim.tribology.squeeze_film import squeeze_resistance

    radius, gap = 5e-3, 1e-6
    half = 30.0 * np.sqrt(2.0 * radius * gap)
    z = np.linspace(-half, half, 20001)
    film = gap + z ** 2 / (2.0 * radius)
    want = 3.0 * np.sqrt(2.0) * np.pi * (radius / gap) ** 1.5
    assert float(squeeze_resistance(z, film)) == pytest.approx(want, rel=1e-3)
    # off-centre the same (z̄ follows the gap), and rows are independent films
    both = squeeze_resistance(z + 1e-3, np.stack([film, 2.0 * film]))
    assert both == pytest.approx([want, want / 8.0], rel=1e-3)


@settings(max_examples=25, deadline=None)
@given(st.floats(0.2e-6, 5e-6), st.floats(0.1e-3, 3e-3), st.floats(10.0, 5e3),
       st.floats(0.01, 1.0))
def test_parallel_squeeze_film_thins_as_reynolds_closed_form(h0, width, load, eta):
    # A uniform film squeezed by a constant load: dh/dt = −W'·h³/(η·b³), so
    # h(t) = h0/√(1 + 2·W'·h0²·t/(η·b³)) (Reynolds 1886).  The thinning rate s = −(dh/dt)/h
    # from squeeze_resistance and squeeze_thinning_rate, integrated (RK45, rtol 1e-10) to the
    # time the film halves: 1e-4 (the trapezoidal rule on 201 points overestimates R = b³/h³
    # by 1/(2·200²) = 1.25e-5, which shifts h at t_half by about that much).
    from scipy.integrate import solve_ivp

    from sealsim.tribology.squeeze_film import squeeze_resistance, squeeze_thinning_rate

    z = np.linspace(0.0, width, 201)

    def rate(t, h):
        resistance = squeeze_resistance(z, np.full(z.size, h[0]))
        return [-h[0] * float(squeeze_thinning_rate(load, eta, resistance, h[0]))]

    t_half = 3.0 * eta * width ** 3 / (2.0 * load * h0 ** 2)
    sol = solve_ivp(rate, (0.0, t_half), [h0], rtol=1e-10, atol=1e-20)
    closed = h0 / np.sqrt(1.0 + 2.0 * load * h0 ** 2 * t_half / (eta * width ** 3))
    assert closed == pytest.approx(0.5 * h0, rel=1e-12)
    assert sol.y[0, -1] == pytest.approx(closed, rel=1e-4)


def test_film_decay_rate_follows_the_film_slope():
    # κ = s/(d ln h*/d ln u): 2·s in full film (h* ∝ √u), larger where the film grows more
    # slowly with the speed (the mixed range), bounded where it does not grow at all
    # (a starved inlet: MIN_FILM_SLOPE); 0 without a film
    from sealsim.tribology.squeeze_film import MIN_FILM_SLOPE, film_speed_decay_rate

    u = np.geomspace(1e-4, 1.0, 41)
    s = 30.0 * u
    assert film_speed_decay_rate(u, 1e-6 * np.sqrt(u), s) == pytest.approx(2.0 * s, rel=1e-9)
    assert film_speed_decay_rate(u, 1e-6 * u ** 0.25, s) == pytest.approx(4.0 * s, rel=1e-9)
    assert film_speed_decay_rate(u, np.full(u.size, 1e-6), s) == pytest.approx(
        s / MIN_FILM_SLOPE, rel=1e-12)
    assert np.all(film_speed_decay_rate(u, np.zeros(u.size), s) == 0.0)
