r"""FElupe's hyperelastic models for the seal FE and for material fits: umats, the homogeneous
test deformations, Drucker stability.

A model of :data:`sealsim.properties.hyperelastic.HYPERELASTIC_MODELS` is evaluated by FElupe
(``felupe.Hyperelastic`` with the function of the same name, automatic differentiation by
tensortrax), so the fit (:mod:`sealsim.calibration.hyperelastic_fit`) and the FE model use
the very same strain energy.

The three homogeneous incompressible test deformations (principal stretches):

* ``uniaxial`` tension/compression: :math:`(\lambda, \lambda^{-1/2}, \lambda^{-1/2})`;
* ``equibiaxial`` tension: :math:`(\lambda, \lambda, \lambda^{-2})`;
* ``planar`` tension (pure shear): :math:`(\lambda, 1, \lambda^{-1})`;

the measured quantity is the nominal (engineering) stress :math:`P_1` = force per undeformed
area in the stretch direction, with the lateral stress free (:math:`P_3 = 0`, the pressure
eliminated; FElupe's ``ViewMaterialIncompressible``).

Drucker stability (the check of Abaqus, *Analysis User's Guide*, "Hyperelastic behavior of
rubberlike materials"): a material is stable at a deformation when every strain increment
does positive work with its stress increment, :math:`d\tau : d\varepsilon > 0`, with the
Kirchhoff stress :math:`\tau` and the logarithmic strain :math:`\varepsilon`.  In principal
axes, with :math:`f(\varepsilon) = W(e^{\varepsilon_1}, e^{\varepsilon_2}, e^{\varepsilon_3})`
and incompressible increments :math:`\sum_i d\varepsilon_i = 0` (the pressure does no work on
them), the condition is that the Hessian

.. math::

    D_{ij} = \frac{\partial^2 f}{\partial\varepsilon_i\,\partial\varepsilon_j}
           = \lambda_i \lambda_j \frac{\partial^2 W}{\partial\lambda_i\,\partial\lambda_j}
             + \delta_{ij}\,\lambda_i \frac{\partial W}{\partial\lambda_i}

projected onto the plane :math:`\sum_i d\varepsilon_i = 0` is positive definite.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from sealsim.errors import InputError
from sealsim.properties.hyperelastic import (
    HYPERELASTIC_MODELS,
    MODES,
    model_name,
    principal_stretches,
)

__all__ = [
    "MODES",
    "ScaledIsochoric",
    "drucker_stable",
    "felupe_nominal_stress",
    "felupe_umat",
    "stability_limits",
]

#: orthonormal basis of the incompressible strain increments (Σ dε_i = 0)
_DEVIATORIC = np.array([[1.0, -1.0, 0.0], [1.0, 1.0, -2.0]]) / np.array([[math.sqrt(2.0)],
                                                                         [math.sqrt(6.0)]])


def felupe_umat(model: str, parameters: Mapping[str, Any], scale: float = 1.0):
    """FElupe's isochoric hyperelastic umat of a model (stresses in Pa, times ``scale``).

    Parameters
    ----------
    model : str
        A name of :data:`~sealsim.properties.hyperelastic.HYPERELASTIC_MODELS`.
    parameters : mapping
        ``{parameter: value}``; stresses in Pa (lists for Ogden).
    scale : float
        Factor on the stress parameters (a temperature law of the stiffness).

    Returns
    -------
    felupe.Hyperelastic

    Examples
    --------
    >>> umat = felupe_umat("neo_hooke", {"mu": 1e6})
    >>> F = np.eye(3).reshape(3, 3, 1, 1)
    >>> float(np.abs(umat.gradient([F, None])[0]).max()) < 1e-9
    True
    """
    import felupe as fem
    from felupe.constitution.tensortrax.models import hyperelastic as models

    name = model_name(model)
    spec = HYPERELASTIC_MODELS[name]
    kwargs = {}
    for p in spec.parameters:
        value = parameters[p]
        if p in spec.stresses:
            value = (np.asarray(value, dtype=float) * scale if spec.terms
                     else float(value) * scale)
        elif spec.terms:
            value = np.asarray(value, dtype=float)
        kwargs[p] = value
    return fem.Hyperelastic(_ogden if name == "ogden" else getattr(models, name), **kwargs)


def _ogden(C, mu, alpha):
    """FElupe's Ogden energy; one term may be given as scalars (FElupe's ``optimize`` passes
    a one-element parameter as a scalar)."""
    from felupe.constitution.tensortrax.models.hyperelastic import ogden

    return ogden(C, np.atleast_1d(mu), np.atleast_1d(alpha))


class ScaledIsochoric:
    """An isochoric FElupe umat whose stress and tangent are multiplied by :attr:`scale`
    (the temperature factor of the stress parameters; set before each increment).

    Examples
    --------
    >>> umat = ScaledIsochoric(felupe_umat("mooney_rivlin", {"C10": 0.4e6, "C01": 0.1e6}))
    >>> umat.scale = 2.0
    >>> F = np.diag([1.1, 1 / 1.1 ** 0.5, 1 / 1.1 ** 0.5]).reshape(3, 3, 1, 1)
    >>> P2 = umat.gradient([F, None])[0]
    >>> umat.scale = 1.0
    >>> bool(np.allclose(P2, 2 * umat.gradient([F, None])[0]))
    True
    """

    def __init__(self, umat, scale: float = 1.0):
        self.umat = umat
        self.scale = float(scale)
        self.x = getattr(umat, "x", [np.eye(3), np.zeros(0)])

    def gradient(self, x):
        P, statevars = self.umat.gradient(x)
        return [self.scale * P, statevars]

    def hessian(self, x):
        return [self.scale * self.umat.hessian(x)[0]]


def felupe_nominal_stress(model: str, parameters: Mapping[str, Any], mode: str, stretch
                          ) -> np.ndarray:
    """Nominal stress P1 [Pa] of a homogeneous incompressible test at the given stretches,
    evaluated by FElupe (``ViewMaterialIncompressible``; the reference of the closed forms of
    :func:`sealsim.properties.hyperelastic.nominal_stress`).

    Examples
    --------
    Neo-Hooke in uniaxial tension, P1 = μ (λ − λ⁻²):

    >>> float(felupe_nominal_stress("neo_hooke", {"mu": 1e6}, "uniaxial", [2.0])[0]) / 1e6
    1.75
    """
    principal_stretches(mode, stretch)  # checks mode and stretches
    lam = np.atleast_1d(np.asarray(stretch, dtype=float))
    cases = {"ux": None, "bx": None, "ps": None}
    cases[{"uniaxial": "ux", "equibiaxial": "bx", "planar": "ps"}[mode]] = lam
    view = felupe_umat(model, parameters).view(incompressible=True, **cases)
    return np.asarray(view.evaluate()[0][1], dtype=float)


def drucker_stable(model: str, parameters: Mapping[str, Any], mode: str, stretch
                   ) -> np.ndarray:
    """Drucker stability (see the module docstring) along a test deformation: bool per
    stretch.

    Examples
    --------
    Mooney–Rivlin with a negative C01 loses stability in large equibiaxial stretch:

    >>> mr = {"C10": 0.5e6, "C01": -0.1e6}
    >>> drucker_stable("mooney_rivlin", mr, "equibiaxial", [1.0, 1.5, 3.0]).tolist()
    [True, True, False]
    """
    lam = principal_stretches(mode, stretch)
    n = lam.shape[1]
    F = np.zeros((3, 3, 1, n))
    for a in range(3):
        F[a, a, 0] = lam[a]
    umat = felupe_umat(model, parameters)
    P = umat.gradient([F, None])[0][:, :, 0]
    A = umat.hessian([F, None])[0][:, :, :, :, 0]
    D = np.empty((3, 3, n))
    for i in range(3):
        for j in range(3):
            D[i, j] = lam[i] * lam[j] * A[i, i, j, j] + (lam[i] * P[i, i] if i == j else 0.0)
    # projected onto Σ dε = 0: a symmetric 2 x 2 matrix per stretch
    M = np.einsum("ai,ijn,bj->nab", _DEVIATORIC, D, _DEVIATORIC)
    M = 0.5 * (M + np.swapaxes(M, 1, 2))
    eig = np.linalg.eigvalsh(M)
    scale = np.max(np.abs(eig), axis=1)
    return eig.min(axis=1) > -1e-12 * np.where(scale > 0, scale, 1.0)


def stability_limits(model: str, parameters: Mapping[str, Any],
                     stretch_range: tuple[float, float] = (0.1, 10.0), points: int = 400
                     ) -> dict[str, dict]:
    """Where a model is Drucker-stable, per test deformation, on a log-spaced stretch grid.

    Parameters
    ----------
    model, parameters
        The model (stresses in Pa).
    stretch_range : (float, float)
        Smallest and largest stretch checked (both sides of 1; compression in ``uniaxial``
        is the same state as equibiaxial tension of λ^(-1/2)).
    points : int
        Grid points.

    Returns
    -------
    dict
        ``{mode: {"stable": bool (everywhere on the grid), "stable_from": λ_lo,
        "stable_to": λ_hi (the interval around λ = 1 where it is stable),
        "unstable_at": [first unstable λ below 1 or None, first above 1 or None]}}``.

    Examples
    --------
    >>> limits = stability_limits("neo_hooke", {"mu": 1e6})
    >>> limits["equibiaxial"]["stable"]
    True
    """
    lo, hi = stretch_range
    if not 0 < lo < 1 < hi:
        raise InputError(f"stretch_range {stretch_range!r} must enclose 1 and be > 0")
    grid = np.unique(np.concatenate([np.geomspace(lo, hi, points), [1.0]]))
    i1 = int(np.argmin(np.abs(grid - 1.0)))
    out = {}
    for mode in MODES:
        ok = drucker_stable(model, parameters, mode, grid)
        below = np.flatnonzero(~ok[:i1 + 1])
        above = np.flatnonzero(~ok[i1:]) + i1
        first_below = float(grid[below[-1]]) if below.size else None
        first_above = float(grid[above[0]]) if above.size else None
        out[mode] = {
            "stable": bool(ok.all()),
            "stable_from": float(grid[below[-1] + 1]) if below.size else float(lo),
            "stable_to": float(grid[above[0] - 1]) if above.size else float(hi),
            "unstable_at": [first_below, first_above],
        }
    return out
