r"""Thermal expansion of rubber across the glass transition (Simha–Boyer, Tool).

Small, pure, vectorised functions (a scalar in gives a Python ``float`` out), SI units:
temperature in K, expansion coefficients in 1/K.

* :func:`simha_boyer_glassy_expansion`: the glassy coefficient from the rubbery one
  (:data:`GLASSY_EXPANSION_RATIO`);
* :func:`thermal_strain`: rubbery and glassy expansion through Tool's fictive temperature,
  which :func:`sealsim.properties.viscoelasticity.fictive_temperature` computes along a
  temperature history.

References
----------
- R. Simha, R. F. Boyer, J. Chem. Phys. 37 (1962) 1003–1007 (glassy vs liquid expansion).
- A. Q. Tool, J. Am. Ceram. Soc. 29 (1946) 240–253; O. S. Narayanaswamy, J. Am. Ceram. Soc.
  54 (1971) 491–498 (fictive temperature).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from sealsim.properties._checks import _array, _out

__all__ = [
    "GLASSY_EXPANSION_RATIO",
    "SIMHA_BOYER_K1",
    "SIMHA_BOYER_K2",
    "simha_boyer_glassy_expansion",
    "thermal_strain",
]

#: Simha–Boyer constants for the volumetric expansion coefficients of amorphous polymers:
#: (α_l − α_g)·T_g ≈ 0.113 and α_l·T_g ≈ 0.164 (R. Simha, R. F. Boyer, J. Chem. Phys. 37
#: (1962) 1003–1007).
SIMHA_BOYER_K1 = 0.113
SIMHA_BOYER_K2 = 0.164
#: Glassy-to-rubbery expansion ratio α_g/α_l = 1 − K1/K2 ≈ 0.31 (Simha & Boyer 1962): the
#: glass keeps only the vibrational part of the expansion; the rest, the growth of free volume,
#: freezes at T_g. Linear and volumetric coefficients have the same ratio (α_vol = 3 α_lin).
GLASSY_EXPANSION_RATIO = 1.0 - SIMHA_BOYER_K1 / SIMHA_BOYER_K2


def simha_boyer_glassy_expansion(rubbery_expansion: Any) -> np.ndarray | float:
    r"""Glassy thermal expansion coefficient estimated from the rubbery one (Simha–Boyer).

    .. math::

        \alpha_g = \alpha_r\,\left(1 - \frac{K_1}{K_2}\right) \approx 0.31\,\alpha_r,
        \qquad K_1 = (\alpha_l - \alpha_g)\,T_g = 0.113,\quad K_2 = \alpha_l T_g = 0.164

    Parameters
    ----------
    rubbery_expansion : array_like
        Linear CTE above T_g, α_r [1/K], > 0.

    Returns
    -------
    float or numpy.ndarray
        Linear CTE of the glass, α_g [1/K].

    References
    ----------
    R. Simha, R. F. Boyer, J. Chem. Phys. 37 (1962) 1003–1007.

    Examples
    --------
    >>> round(simha_boyer_glassy_expansion(1.9e-4) * 1e4, 3)
    0.591
    """
    a = _array(rubbery_expansion, "rubbery_expansion", "1/K", lo=0.0, lo_open=True)
    return _out(GLASSY_EXPANSION_RATIO * a)


def thermal_strain(
    temperature: Any,
    reference_temperature: Any,
    rubbery_expansion: Any,
    glassy_expansion: Any = None,
    fictive_temperature: Any = None,
) -> np.ndarray | float:
    r"""Free linear thermal strain of a rubber that may be (partly) glassy.

    .. math::

        \varepsilon_{th} = \alpha_g\,(T - T_0) + (\alpha_r - \alpha_g)\,(T_f - T_0)

    T_f is Tool's fictive temperature: the temperature at which the frozen structure (free
    volume) would be in equilibrium. In equilibrium (rubber, slow changes) T_f = T and the
    strain is α_r (T − T_0); in a glass T_f stays where the structure froze and only α_g
    remains. T_0 is a stress-free equilibrium state (T_f = T_0 there).

    Parameters
    ----------
    temperature : array_like
        T [K].
    reference_temperature : array_like
        T_0 [K] of zero strain (equilibrium).
    rubbery_expansion : array_like
        α_r [1/K] (equilibrium, above T_g).
    glassy_expansion : array_like, optional
        α_g [1/K]; default α_r (no glass transition).
    fictive_temperature : array_like, optional
        T_f [K]; default T (equilibrium).

    Returns
    -------
    float or numpy.ndarray
        ε_th [-].

    References
    ----------
    A. Q. Tool, J. Am. Ceram. Soc. 29 (1946) 240–253 (fictive temperature);
    O. S. Narayanaswamy, J. Am. Ceram. Soc. 54 (1971) 491–498.

    Examples
    --------
    Cooled 60 K, the last 30 K in the glass (T_f = T_0 − 30 K):

    >>> round(thermal_strain(233.15, 293.15, 1.9e-4, 0.6e-4, 263.15), 6)
    -0.0075
    """
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    t0 = _array(reference_temperature, "reference_temperature", "K", lo=0.0, lo_open=True)
    a_r = _array(rubbery_expansion, "rubbery_expansion", "1/K")
    a_g = a_r if glassy_expansion is None else _array(glassy_expansion, "glassy_expansion", "1/K")
    t_f = t if fictive_temperature is None else _array(
        fictive_temperature, "fictive_temperature", "K", lo=0.0, lo_open=True)
    return _out(a_g * (t - t0) + (a_r - a_g) * (t_f - t0))
