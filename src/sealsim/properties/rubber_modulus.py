r"""Small-strain modulus of rubber: master curve E(T, f), DMA tables, hardness relations.

Small, pure, vectorised functions (a scalar in gives a Python ``float`` out), SI units:
temperature in K, moduli and hyperelastic constants in Pa, frequency in Hz.

* Storage modulus vs temperature and frequency: :func:`master_curve_modulus` (glassy →
  transition → rubbery sigmoid in log E over log reduced frequency),
  :func:`modulus_vs_temperature` (adds the WLF shift of :mod:`sealsim.properties.viscoelasticity`
  and the entropic factor T/T_ref of the rubbery plateau) and :func:`modulus_from_table` (PCHIP
  through measured DMA points).
* Rubber elasticity: :func:`entropic_modulus` (equilibrium modulus ∝ T),
  :func:`mooney_rivlin_young_modulus` (E = 6(C10 + C01)), :func:`shore_a_young_modulus` (Gent).

The E(T) construction
---------------------
The small-strain storage modulus is a master curve over the reduced frequency
``f_r = f·a_T(T)`` (a_T relative to the WLF reference temperature, normally T_g):

.. math::

    \log_{10} E(T, f) = \log_{10} E_r(T) + [\log_{10} E_g - \log_{10} E_r(T)]\,S(\log_{10} f_r),
    \qquad E_r(T) = E_{r,\mathrm{ref}}\,T / T_\mathrm{ref},

with the generalised logistic (Richards 1959) sigmoid

.. math::

    S(x) = \left[1 + \nu\,\exp\!\left(-\frac{x - x_0}{w}\right)\right]^{-1/\nu}.

ν = 1 is the symmetric logistic used for asphalt master curves; ν > 1 gives the broad
low-frequency (rubbery-side) tail that filled rubbers show: S decays like
exp((x − x0)/(ν·w)) there, ν times slower than it rises to the glass (Rowe, Baumgardner &
Sharrock 2009 use the same generalised form for bituminous master curves) [L].
E_g is the glassy modulus, E_r,ref the *equilibrium* (long-time) rubbery modulus at the
material's reference temperature; the factor T/T_ref is rubber (entropy) elasticity, applied
to the rubbery part only (Treloar 1975) [L]. With ν = 4 the tail is so broad that E_r,ref is
an asymptote rather than a measurable value: for the catalogue NBR, E(23 °C, 1 Hz) ≈ 3·E_r,ref
and E(150 °C, 1 Hz) ≈ 1.4·E_r,ref·T/T_ref. The quantity that ties to measurements (and to the
hyperelastic constants, E ≈ 6·(C10 + C01)) is E at the test frequency.  The shape the catalogue
uses and how it was chosen are described in :mod:`sealsim.properties.elastomers`.

Tags after a reference: [L] a standard literature or handbook value not re-checked against the
source here; [D] derived by sealsim (reproducible from the equations shown).

References
----------
- F. J. Richards, J. Exp. Bot. 10 (1959) 290–301 (generalised logistic).
- G. Rowe, G. Baumgardner, M. Sharrock, "Functional forms for master curve analysis of
  bituminous materials", in Advanced Testing and Characterization of Bituminous Materials,
  CRC Press 2009, 81–91 [L].
- L. R. G. Treloar, The Physics of Rubber Elasticity, 3rd ed., Oxford 1975 (E ∝ T) [L].
- F. N. Fritsch, R. E. Carlson, SIAM J. Numer. Anal. 17 (1980) 238–246 (PCHIP).
- A. N. Gent, Trans. Inst. Rubber Ind. 34 (1958) 46–57 (Shore A hardness and modulus).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.interpolate import PchipInterpolator

from sealsim.errors import InputError
from sealsim.properties._checks import _array, _broadcast, _out, _scalar
from sealsim.properties.viscoelasticity import WLF_UNIVERSAL, _log10_shift, _wlf_params

__all__ = [
    "DEFAULT_TRANSITION_ASYMMETRY",
    "DEFAULT_TRANSITION_LOCATION",
    "DEFAULT_TRANSITION_WIDTH",
    "entropic_modulus",
    "master_curve_modulus",
    "modulus_from_table",
    "modulus_vs_temperature",
    "mooney_rivlin_young_modulus",
    "shore_a_young_modulus",
]

#: Master-curve shape used by the catalogue (see the module docstring) [D].
DEFAULT_TRANSITION_LOCATION = -2.0  # log10(f_r / 1 Hz) at the WLF reference temperature
DEFAULT_TRANSITION_WIDTH = 1.1  # decades
DEFAULT_TRANSITION_ASYMMETRY = 4.0  # Richards exponent nu [-]


def _log_sigmoid(x: np.ndarray, location: float, width: float, asymmetry: float) -> np.ndarray:
    """ln S for the Richards sigmoid, overflow-free."""
    u = math.log(asymmetry) - (x - location) / width
    return -np.logaddexp(0.0, u) / asymmetry


def _shape_params(location: float, width: float, asymmetry: float) -> tuple[float, float, float]:
    return (
        _scalar(location, "transition_location", "log10 Hz"),
        _scalar(width, "transition_width", "decades", lo=0.0, lo_open=True),
        _scalar(asymmetry, "transition_asymmetry", "-", lo=0.0, lo_open=True),
    )


def _master_log10(
    x: np.ndarray, log_eg: float, log_er: np.ndarray, location: float, width: float, nu: float
) -> np.ndarray:
    s = np.exp(_log_sigmoid(x, location, width, nu))
    return log_er + (log_eg - log_er) * s


def master_curve_modulus(
    reduced_frequency: Any,
    glassy_modulus: float,
    rubbery_modulus: Any,
    transition_location: float = DEFAULT_TRANSITION_LOCATION,
    transition_width: float = DEFAULT_TRANSITION_WIDTH,
    transition_asymmetry: float = DEFAULT_TRANSITION_ASYMMETRY,
) -> np.ndarray | float:
    r"""Storage modulus master curve: glassy → transition → rubbery sigmoid in log E.

    .. math::

        \log_{10} E' = \log_{10} E_r + (\log_{10} E_g - \log_{10} E_r)\,S(\log_{10} f_r),\quad
        S(x) = \left[1 + \nu\,e^{-(x - x_0)/w}\right]^{-1/\nu}

    S rises from 0 (rubbery, low f_r) to 1 (glassy, high f_r). ν = 1 is the symmetric
    logistic; ν > 1 widens the low-frequency tail (S ∝ exp((x − x0)/(ν w)) there).

    Parameters
    ----------
    reduced_frequency : array_like
        Reduced frequency f_r = f·a_T [Hz], > 0.
    glassy_modulus : float
        Glassy modulus E_g [Pa], > ``rubbery_modulus``.
    rubbery_modulus : array_like
        Rubbery (equilibrium) modulus E_r [Pa] at the temperature considered, > 0.
    transition_location : float, default -2.0
        x0 [log10 Hz]; S(x0) = (1 + ν)^(−1/ν) (0.5 for ν = 1).
    transition_width : float, default 1.1
        w [decades of frequency], > 0.
    transition_asymmetry : float, default 4.0
        ν [-], > 0.

    Returns
    -------
    float or numpy.ndarray
        Storage modulus E' [Pa].

    References
    ----------
    Richards, J. Exp. Bot. 10 (1959) 290; Rowe, Baumgardner & Sharrock (2009) [L].

    Examples
    --------
    >>> master_curve_modulus(1e10, 2e9, 3e6) / 1e9
    2.0
    >>> master_curve_modulus(1e-20, 2e9, 3e6, transition_asymmetry=1.0) / 1e6
    3.0

    With the default ν = 4 the rubbery tail is broad: 1 % above E_r even at 1e-30 Hz.

    >>> master_curve_modulus(1e-30, 2e9, 3e6) / 1e6
    3.02
    """
    f_r = _array(reduced_frequency, "reduced_frequency", "Hz", lo=0.0, lo_open=True)
    e_r = _array(rubbery_modulus, "rubbery_modulus", "Pa", lo=0.0, lo_open=True)
    e_g = _scalar(glassy_modulus, "glassy_modulus", "Pa", lo=float(np.max(e_r)), lo_open=True)
    x0, w, nu = _shape_params(transition_location, transition_width, transition_asymmetry)
    f_r, e_r = _broadcast(f_r, e_r, names="reduced_frequency and rubbery_modulus")
    return _out(10.0 ** _master_log10(np.log10(f_r), math.log10(e_g), np.log10(e_r), x0, w, nu))


def modulus_vs_temperature(
    temperature: Any,
    frequency: Any,
    *,
    glassy_modulus: float,
    rubbery_modulus: float,
    reference_temperature: float,
    glass_transition: float,
    transition_location: float = DEFAULT_TRANSITION_LOCATION,
    transition_width: float = DEFAULT_TRANSITION_WIDTH,
    transition_asymmetry: float = DEFAULT_TRANSITION_ASYMMETRY,
    c1: float = WLF_UNIVERSAL.c1,
    c2: float = WLF_UNIVERSAL.c2,
    wlf_reference_temperature: float | None = None,
) -> np.ndarray | float:
    r"""Small-strain storage modulus E(T, f) from the WLF-shifted master curve.

    .. math::

        E(T, f) = E'_\mathrm{master}\bigl(f\,a_T(T);\ E_g,\
                  E_{r,\mathrm{ref}}\,T/T_\mathrm{ref}\bigr)

    with a_T from :func:`wlf_log10_shift` (reference ``wlf_reference_temperature``, default
    T_g; Arrhenius continuation below T_g) and the master curve of
    :func:`master_curve_modulus`. Only the rubbery plateau carries the entropic factor
    T/T_ref; the glassy modulus is taken as temperature independent.

    Parameters
    ----------
    temperature : array_like
        Temperature T [K], > 0.
    frequency : array_like
        Test or excitation frequency f [Hz], > 0; broadcast with ``temperature``.
    glassy_modulus : float
        E_g [Pa].
    rubbery_modulus : float
        Equilibrium rubbery modulus E_r,ref [Pa] at ``reference_temperature``.
    reference_temperature : float
        T_ref [K] of ``rubbery_modulus``.
    glass_transition : float
        T_g [K]; the Arrhenius continuation of a_T starts there.
    transition_location, transition_width, transition_asymmetry : float
        Sigmoid x0 [log10 Hz], w [decades], ν [-] (see :func:`master_curve_modulus`).
    c1 : float, default 17.44
        WLF C1 [-].
    c2 : float, default 51.6
        WLF C2 [K].
    wlf_reference_temperature : float, optional
        WLF reference temperature [K]; default ``glass_transition``.

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    WLF 1955; Richards 1959; Treloar 1975 [L].

    Examples
    --------
    Catalogue NBR at 20 °C and 1 Hz (≈ 8.5 MPa):

    >>> kw = dict(glassy_modulus=2e9, rubbery_modulus=2.68e6,
    ...           reference_temperature=296.15, glass_transition=248.15)
    >>> modulus_vs_temperature(293.15, 1.0, **kw) / 1e6
    8.5
    """
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    f = _array(frequency, "frequency", "Hz", lo=0.0, lo_open=True)
    t, f = _broadcast(t, f, names="temperature and frequency")
    t_ref = _scalar(reference_temperature, "reference_temperature", "K", lo=0.0, lo_open=True)
    t_g = _scalar(glass_transition, "glass_transition", "K", lo=0.0, lo_open=True)
    e_r = _scalar(rubbery_modulus, "rubbery_modulus", "Pa", lo=0.0, lo_open=True)
    e_g = _scalar(glassy_modulus, "glassy_modulus", "Pa", lo=e_r, lo_open=True)
    x0, w, nu = _shape_params(transition_location, transition_width, transition_asymmetry)
    t_wlf = t_g if wlf_reference_temperature is None else wlf_reference_temperature
    t_wlf, c1, c2, t_a = _wlf_params(t_wlf, c1, c2, t_g)
    x = np.log10(f) + _log10_shift(t, t_wlf, c1, c2, t_a)
    log_er = np.log10(entropic_modulus(e_r, t, t_ref))
    return _out(10.0 ** _master_log10(x, math.log10(e_g), log_er, x0, w, nu))


def modulus_from_table(
    temperature: Any, table_temperature: Any, table_modulus: Any
) -> np.ndarray | float:
    r"""Modulus from measured DMA points: monotone PCHIP in log10 E vs T, no extrapolation.

    .. math::

        E(T) = 10^{P(T)},\qquad P = \mathrm{PCHIP}\{(T_k, \log_{10} E_k)\}

    PCHIP (Fritsch & Carlson 1980) passes through every point and is monotone between
    monotone data, so it does not overshoot at the knee of the glass transition.
    Temperatures outside [T_1, T_n] raise :class:`InputError`: a DMA curve cannot be
    extrapolated safely across a transition.

    Parameters
    ----------
    temperature : array_like
        Temperature T [K] in [table_temperature[0], table_temperature[-1]].
    table_temperature : array_like
        Strictly increasing table temperatures [K], at least 2.
    table_modulus : array_like
        Moduli [Pa] at those temperatures, > 0.

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980) 238.

    Examples
    --------
    >>> modulus_from_table(300.0, [250.0, 300.0, 350.0], [1e9, 1e7, 8e6]) / 1e6
    10.0
    """
    t_tab = _array(table_temperature, "table_temperature", "K", lo=0.0, lo_open=True)
    e_tab = _array(table_modulus, "table_modulus", "Pa", lo=0.0, lo_open=True)
    if t_tab.ndim != 1 or t_tab.size < 2 or e_tab.shape != t_tab.shape:
        raise InputError(
            "table_temperature and table_modulus must be 1-D arrays of equal length >= 2; "
            f"got shapes {t_tab.shape} and {e_tab.shape}"
        )
    if np.any(np.diff(t_tab) <= 0.0):
        raise InputError(f"table_temperature must be strictly increasing [K]; got {t_tab.tolist()}")
    t = _array(temperature, "temperature", "K", lo=float(t_tab[0]), hi=float(t_tab[-1]))
    interp = PchipInterpolator(t_tab, np.log10(e_tab), extrapolate=False)
    return _out(10.0 ** interp(t))


def mooney_rivlin_young_modulus(c10: Any, c01: Any) -> np.ndarray | float:
    r"""Small-strain Young's modulus of an incompressible Mooney–Rivlin solid.

    .. math::

        E = 6\,(C_{10} + C_{01}),\qquad G = 2\,(C_{10} + C_{01})

    Parameters
    ----------
    c10 : array_like
        C10 [Pa], > 0.
    c01 : array_like
        C01 [Pa], >= 0.

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    M. Mooney, J. Appl. Phys. 11 (1940) 582; R. S. Rivlin, Phil. Trans. R. Soc. A 241 (1948)
    379 [L].

    Examples
    --------
    >>> mooney_rivlin_young_modulus(0.8e6, 0.2e6) / 1e6
    6.0
    """
    a = _array(c10, "c10", "Pa", lo=0.0, lo_open=True)
    b = _array(c01, "c01", "Pa", lo=0.0)
    return _out(6.0 * (a + b))


def shore_a_young_modulus(hardness: Any) -> np.ndarray | float:
    r"""Small-strain Young's modulus of a rubber from its Shore A hardness (Gent 1958).

    .. math::

        E\,[\mathrm{MPa}] = \frac{0.0981\,(56 + 7.62336\,S)}{0.137505\,(254 - 2.54\,S)}

    Gent's relation follows from the elastic indentation of the Shore A durometer's truncated
    cone (ASTM D2240 / ISO 48-4 geometry and spring force): the numerator is the spring force
    [N] at reading S, the denominator the indenter geometry times its depth [mm].  Independent
    FE simulations of the durometer test with a neo-Hookean solid (Qi, Joyce & Boyce 2003)
    agree within about 5 % at 70 Shore A and 15 % at 80 Shore A.  Use it for *ratios* between
    compounds of one family (a hardness tolerance), not as a substitute for a measured
    modulus.

    Parameters
    ----------
    hardness : array_like
        Shore A hardness S [-], 0 < S < 100 (readings between 10 and 90 are meaningful,
        ASTM D2240).

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    A. N. Gent, "On the relation between indentation hardness and Young's modulus",
    Trans. Inst. Rubber Ind. 34 (1958) 46-57; H. J. Qi, K. Joyce, M. C. Boyce, "Durometer
    hardness and the stress-strain behavior of elastomeric materials", Rubber Chem. Technol.
    76 (2003) 419-435.

    Examples
    --------
    >>> round(shore_a_young_modulus(70) / 1e6, 2), round(shore_a_young_modulus(80) / 1e6, 2)
    (5.52, 9.35)
    """
    s = _array(hardness, "Shore A hardness", "", lo=0.0, hi=100.0, lo_open=True, hi_open=True)
    return _out(0.0981 * (56.0 + 7.62336 * s) / (0.137505 * (254.0 - 2.54 * s)) * 1e6)


def entropic_modulus(
    modulus: Any, temperature: Any, reference_temperature: Any
) -> np.ndarray | float:
    r"""Equilibrium modulus of rubber elasticity at temperature T: E(T) = E_0·T/T_0.

    A network of flexible chains stores elastic energy as configurational entropy, so its
    equilibrium shear modulus is G = n k T (Treloar 1975, ch. 4) and rises with T. This is the
    modulus of a seal held at constant squeeze long enough for its viscoelastic stresses to
    relax (well above T_g). The dynamic (storage) modulus at a given rate,
    :func:`modulus_vs_temperature`, instead falls with T between T_g and ≈ 100 °C because the
    glass-transition tail relaxes faster the warmer the rubber is.

    Parameters
    ----------
    modulus : array_like
        E_0 [Pa] at T_0, > 0.
    temperature : array_like
        T [K], > 0.
    reference_temperature : array_like
        T_0 [K], > 0.

    Returns
    -------
    float or numpy.ndarray
        E(T) [Pa].

    References
    ----------
    L. R. G. Treloar, The Physics of Rubber Elasticity, 3rd ed., Oxford 1975, ch. 4.

    Examples
    --------
    >>> round(entropic_modulus(8e6, 328.15, 293.15) / 1e6, 4)
    8.9551
    """
    e0 = _array(modulus, "modulus", "Pa", lo=0.0, lo_open=True)
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    t0 = _array(reference_temperature, "reference_temperature", "K", lo=0.0, lo_open=True)
    return _out(_entropic_modulus(e0, t, t0))


def _entropic_modulus(modulus, temperature, reference_temperature):
    """:func:`entropic_modulus` of validated inputs."""
    return modulus * temperature / reference_temperature
