r"""Hyperelastic strain-energy models of a compound: names, parameters, small-strain modulus.

The models are those of FElupe (``felupe.constitution.tensortrax.models.hyperelastic``), which
the FE model evaluates (:mod:`sealsim.structure.hyperelastic`); this module only holds their
names and parameters as plain data, so that an elastomer file can name one
(``[NAME.hyperelastic]``, see :mod:`sealsim.properties.catalogue`) without importing FElupe.
Every model is written with the isochoric invariants :math:`\bar I_1 = J^{-2/3} I_1`,
:math:`\bar I_2 = J^{-4/3} I_2` and stretches :math:`\bar\lambda_i = J^{-1/3}\lambda_i`
(the volumetric part belongs to the FE body):

* ``neo_hooke``: :math:`W = \mu/2\,(\bar I_1 - 3)` (Treloar 1943);
* ``mooney_rivlin``: :math:`W = C_{10}(\bar I_1 - 3) + C_{01}(\bar I_2 - 3)` (Mooney 1940,
  Rivlin 1948);
* ``yeoh``: :math:`W = C_{10}(\bar I_1 - 3) + C_{20}(\bar I_1 - 3)^2 + C_{30}(\bar I_1 - 3)^3`
  (Yeoh 1993);
* ``ogden`` (N terms): :math:`W = \sum_i 2\mu_i/\alpha_i^2\,(\bar\lambda_1^{\alpha_i} +
  \bar\lambda_2^{\alpha_i} + \bar\lambda_3^{\alpha_i} - 3)` (Ogden 1972, in the convention of
  FElupe and Abaqus: the initial shear modulus is :math:`\sum_i \mu_i`; Ogden's own
  :math:`\mu_i^{O}` are :math:`2\mu_i/\alpha_i`);
* ``arruda_boyce``: :math:`W = C_1 \sum_{i=1}^5 a_i \lambda_m^{2-2i}(\bar I_1^i - 3^i)`,
  :math:`a = (1/2, 1/20, 11/1050, 19/7000, 519/673750)` (Arruda & Boyce 1993);
* ``third_order_deformation``: :math:`W = C_{10}(\bar I_1-3) + C_{01}(\bar I_2-3) +
  C_{11}(\bar I_1-3)(\bar I_2-3) + C_{20}(\bar I_1-3)^2 + C_{30}(\bar I_1-3)^3`
  (James, Green & Simpson 1975).

Parameters that carry a stress (unit Pa) scale the whole energy; the others (Ogden's
exponents, the locking stretch) are dimensionless.  So a temperature law of the stiffness
multiplies the stress parameters and leaves the shape parameters alone.

References
----------
- L. R. G. Treloar, Trans. Faraday Soc. 39 (1943) 241-246.
- M. Mooney, J. Appl. Phys. 11 (1940) 582-592; R. S. Rivlin, Phil. Trans. R. Soc. A 241
  (1948) 379-397.
- O. H. Yeoh, Rubber Chem. Technol. 66 (1993) 754-771.
- R. W. Ogden, Proc. R. Soc. Lond. A 326 (1972) 565-584.
- E. M. Arruda, M. C. Boyce, J. Mech. Phys. Solids 41 (1993) 389-412.
- A. G. James, A. Green, G. M. Simpson, J. Appl. Polym. Sci. 19 (1975) 2033-2058.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from sealsim.errors import InputError

__all__ = [
    "HYPERELASTIC_MODELS",
    "MODES",
    "HyperelasticModel",
    "check_hyperelastic",
    "initial_shear_modulus",
    "model_name",
    "nominal_stress",
    "principal_stretches",
]

#: The homogeneous incompressible test deformations (names used in fit files and reports).
MODES = ("uniaxial", "equibiaxial", "planar")

#: Arruda-Boyce series coefficients a_i (five terms of the inverse Langevin expansion).
ARRUDA_BOYCE_COEFFICIENTS = (1 / 2, 1 / 20, 11 / 1050, 19 / 7000, 519 / 673750)


@dataclass(frozen=True)
class HyperelasticModel:
    """A strain-energy family: its FElupe function name and parameters.

    Attributes
    ----------
    name : str
        sealsim's (and FElupe's) name, e.g. ``"yeoh"``.
    stresses : tuple of str
        Parameters with the unit of a stress [Pa].
    shapes : tuple of str
        Dimensionless parameters [-].
    terms : bool
        Parameters are lists of N terms (Ogden).
    """

    name: str
    stresses: tuple[str, ...]
    shapes: tuple[str, ...] = ()
    terms: bool = False

    @property
    def parameters(self) -> tuple[str, ...]:
        return self.stresses + self.shapes


#: The models an elastomer file may name (FElupe's functions of the same names).
HYPERELASTIC_MODELS: dict[str, HyperelasticModel] = {m.name: m for m in (
    HyperelasticModel("neo_hooke", ("mu",)),
    HyperelasticModel("mooney_rivlin", ("C10", "C01")),
    HyperelasticModel("yeoh", ("C10", "C20", "C30")),
    HyperelasticModel("ogden", ("mu",), ("alpha",), terms=True),
    HyperelasticModel("arruda_boyce", ("C1",), ("limit",)),
    HyperelasticModel("third_order_deformation", ("C10", "C01", "C11", "C20", "C30")),
)}


def model_name(model: str) -> str:
    """The registered name of a model (``"Ogden"``, ``"ogden3"`` -> ``"ogden"``).

    Examples
    --------
    >>> model_name("Mooney-Rivlin"), model_name("ogden3")
    ('mooney_rivlin', 'ogden')
    """
    key = str(model).strip().lower().replace("-", "_").replace(" ", "_")
    if key.startswith("ogden") and key[5:].isdigit():
        key = "ogden"
    if key not in HYPERELASTIC_MODELS:
        raise InputError(f"hyperelastic model {model!r} is not known; choose one of "
                         f"{', '.join(HYPERELASTIC_MODELS)}")
    return key


def check_hyperelastic(model: str, parameters: Mapping[str, Any]
                       ) -> tuple[str, tuple[tuple[str, float | tuple[float, ...]], ...]]:
    """Validate a model name and its parameters (SI: stresses in Pa).

    Returns
    -------
    (name, ((parameter, value), ...))
        Hashable, in the model's parameter order; Ogden's values are tuples of N terms.

    Raises
    ------
    InputError
        Unknown model, a missing or unknown parameter, a value that is not finite, Ogden lists
        of different lengths or an exponent of 0, an Arruda-Boyce locking stretch <= 1, an
        initial shear modulus <= 0.

    Examples
    --------
    >>> check_hyperelastic("ogden", {"mu": [4e5, 1e3], "alpha": [1.3, 5.0]})
    ('ogden', (('mu', (400000.0, 1000.0)), ('alpha', (1.3, 5.0))))
    """
    name = model_name(model)
    spec = HYPERELASTIC_MODELS[name]
    given = dict(parameters)
    unknown = sorted(set(given) - set(spec.parameters))
    missing = [p for p in spec.parameters if p not in given]
    if unknown or missing:
        raise InputError(f"hyperelastic model {name!r} has the parameters "
                         f"{', '.join(spec.parameters)}"
                         + (f"; missing {', '.join(missing)}" if missing else "")
                         + (f"; unknown {', '.join(unknown)}" if unknown else ""))
    values: list[tuple[str, Any]] = []
    for p in spec.parameters:
        raw = given[p]
        items = list(raw) if isinstance(raw, list | tuple) else [raw]
        if spec.terms != isinstance(raw, list | tuple) or not items:
            shape = "a list of N numbers (one per term)" if spec.terms else "one number"
            raise InputError(f"hyperelastic parameter {p} of {name!r} must be {shape}; "
                             f"got {raw!r}")
        try:
            numbers = tuple(float(v) for v in items)
        except (TypeError, ValueError):
            raise InputError(f"hyperelastic parameter {p} of {name!r}: {raw!r} is not a "
                             "number") from None
        if not all(math.isfinite(v) for v in numbers):
            raise InputError(f"hyperelastic parameter {p} of {name!r}: {raw!r} is not finite")
        values.append((p, numbers if spec.terms else numbers[0]))
    table = dict(values)
    if spec.terms and len({len(v) for v in table.values()}) != 1:
        raise InputError(f"hyperelastic model {name!r}: " + " and ".join(
            f"{p} ({len(v)} terms)" for p, v in table.items()) + " must have equal lengths")
    if name == "ogden" and any(a == 0.0 for a in table["alpha"]):
        raise InputError("hyperelastic model 'ogden': an exponent alpha of 0 is not allowed")
    if name == "arruda_boyce" and not table["limit"] > 1.0:
        raise InputError(f"hyperelastic model 'arruda_boyce': the locking stretch limit = "
                         f"{table['limit']!r} must be > 1")
    mu0 = initial_shear_modulus(name, table)
    if not mu0 > 0.0:
        raise InputError(f"hyperelastic model {name!r}: the initial shear modulus "
                         f"{mu0:g} Pa of these parameters must be > 0")
    return name, tuple(values)


def initial_shear_modulus(model: str, parameters: Mapping[str, Any]) -> float:
    r"""Small-strain shear modulus :math:`\mu_0 = 2\,(\partial W/\partial\bar I_1 +
    \partial W/\partial\bar I_2)` at the undeformed state [Pa].

    neo-Hooke μ; Mooney–Rivlin and third-order 2(C10 + C01); Yeoh 2 C10; Ogden Σ μ_i;
    Arruda–Boyce :math:`2 C_1 \sum_i i\,a_i\,3^{i-1}\lambda_m^{2-2i}`.

    Parameters
    ----------
    model : str
        Model name (see :data:`HYPERELASTIC_MODELS`).
    parameters : mapping
        Its parameters, stresses in Pa.

    Returns
    -------
    float
        μ0 [Pa]; Young's modulus of the incompressible solid is 3 μ0.

    Examples
    --------
    >>> initial_shear_modulus("mooney_rivlin", {"C10": 0.8e6, "C01": 0.2e6})
    2000000.0
    >>> round(initial_shear_modulus("arruda_boyce", {"C1": 1e6, "limit": 1e6}))
    1000000
    """
    name = model_name(model)
    p = parameters
    if name == "neo_hooke":
        return float(p["mu"])
    if name in ("mooney_rivlin", "third_order_deformation"):
        return 2.0 * (float(p["C10"]) + float(p["C01"]))
    if name == "yeoh":
        return 2.0 * float(p["C10"])
    if name == "ogden":
        return float(sum(p["mu"]))
    beta = 1.0 / float(p["limit"]) ** 2
    return 2.0 * float(p["C1"]) * sum(i * a * 3.0 ** (i - 1) * beta ** (i - 1)
                                      for i, a in enumerate(ARRUDA_BOYCE_COEFFICIENTS, 1))


def principal_stretches(mode: str, stretch) -> np.ndarray:
    """Principal stretches (3, n) of a homogeneous incompressible test deformation:
    uniaxial (λ, λ^-1/2, λ^-1/2), equibiaxial (λ, λ, λ^-2), planar (λ, 1, 1/λ).

    Examples
    --------
    >>> principal_stretches("planar", [2.0]).ravel().tolist()
    [2.0, 1.0, 0.5]
    """
    lam = np.atleast_1d(np.asarray(stretch, dtype=float))
    if np.any(~np.isfinite(lam)) or np.any(lam <= 0):
        raise InputError(f"stretches must be finite and > 0; got {stretch!r}")
    if mode == "uniaxial":
        return np.array([lam, lam ** -0.5, lam ** -0.5])
    if mode == "equibiaxial":
        return np.array([lam, lam, lam ** -2.0])
    if mode == "planar":
        return np.array([lam, np.ones_like(lam), 1.0 / lam])
    raise InputError(f"deformation mode {mode!r} is not known; choose one of "
                     f"{', '.join(MODES)}")


def _invariant_derivatives(name: str, p: Mapping[str, Any], i1, i2):
    """∂W/∂I1, ∂W/∂I2 of the invariant-based models."""
    if name == "neo_hooke":
        return 0.5 * p["mu"] + 0.0 * i1, 0.0 * i1
    if name == "mooney_rivlin":
        return p["C10"] + 0.0 * i1, p["C01"] + 0.0 * i1
    if name == "yeoh":
        x = i1 - 3.0
        return p["C10"] + 2.0 * p["C20"] * x + 3.0 * p["C30"] * x ** 2, 0.0 * i1
    if name == "third_order_deformation":
        x, y = i1 - 3.0, i2 - 3.0
        return (p["C10"] + p["C11"] * y + 2.0 * p["C20"] * x + 3.0 * p["C30"] * x ** 2,
                p["C01"] + p["C11"] * x)
    beta = 1.0 / float(p["limit"]) ** 2   # arruda_boyce
    w1 = sum(i * a * beta ** (i - 1) * i1 ** (i - 1)
             for i, a in enumerate(ARRUDA_BOYCE_COEFFICIENTS, 1))
    return p["C1"] * w1, 0.0 * i1


def nominal_stress(model: str, parameters: Mapping[str, Any], mode: str, stretch
                   ) -> np.ndarray:
    r"""Nominal (engineering) stress P1 [Pa] of a homogeneous incompressible test.

    With the principal stretches of :func:`principal_stretches` and the lateral direction 3
    free of stress (the pressure eliminated),

    .. math::

        P_1 = \frac{\partial W}{\partial\lambda_1}
              - \frac{\lambda_3}{\lambda_1}\frac{\partial W}{\partial\lambda_3},
        \qquad \frac{\partial W}{\partial\lambda_i} = 2\lambda_i\left(W_1 +
        W_2\,(I_1 - \lambda_i^2)\right)

    for invariant-based energies (:math:`W_k = \partial W/\partial I_k`; Treloar 1975,
    ch. 10), and :math:`\partial W/\partial\lambda_i = \sum_k (2\mu_k/\alpha_k)
    \lambda_i^{\alpha_k - 1}` for Ogden.  The same energies as FElupe's (tests compare with
    ``felupe.ViewMaterialIncompressible`` to 1e-9).

    Parameters
    ----------
    model : str
        A name of :data:`HYPERELASTIC_MODELS`.
    parameters : mapping
        Its parameters, stresses in Pa.
    mode : {"uniaxial", "equibiaxial", "planar"}
        Test deformation.
    stretch : array_like
        λ [-] in the loading direction.

    Returns
    -------
    numpy.ndarray
        P1 [Pa].

    Examples
    --------
    Neo-Hooke in uniaxial tension, P1 = μ (λ − λ⁻²):

    >>> float(nominal_stress("neo_hooke", {"mu": 1e6}, "uniaxial", [2.0])[0]) / 1e6
    1.75
    """
    name = model_name(model)
    lam = principal_stretches(mode, stretch)
    if name == "ogden":
        def dw(li):
            return sum(2.0 * m / a * li ** (a - 1.0)
                       for m, a in zip(np.atleast_1d(parameters["mu"]),
                                       np.atleast_1d(parameters["alpha"])))
    else:
        sq = lam ** 2
        i1 = sq.sum(axis=0)
        i2 = 0.5 * (i1 ** 2 - (sq ** 2).sum(axis=0))
        w1, w2 = _invariant_derivatives(name, parameters, i1, i2)

        def dw(li):
            return 2.0 * li * (w1 + w2 * (i1 - li ** 2))
    return dw(lam[0]) - lam[2] / lam[0] * dw(lam[2])
