r"""Seal materials for the FE model: nearly incompressible Mooney–Rivlin with thermal expansion,
temperature-dependent constants, and a thermo-viscoelastic (Prony series + WLF) variant.

The strain energy per unit undeformed volume follows Heipl & Murrenhoff, Eq. (6)/(7):

.. math::

    W = C_{10}\,(\bar I_1 - 3) + C_{01}\,(\bar I_2 - 3) + U(J / J_\mathrm{th}),
    \qquad J_\mathrm{th} = \bigl(1 + \alpha\,(T - T_0)\bigr)^3,

with the isochoric invariants :math:`\bar I_1 = J^{-2/3} I_1`, :math:`\bar I_2 = J^{-4/3} I_2`
of :math:`C = F^T F` and the volumetric energy :math:`U = K/2\,(\bar J - 1)^2` of FElupe's
mixed (constant cell pressure) formulation. Thermal expansion is therefore a change of the
volumetric part only (Heipl & Murrenhoff: "equivalent to a change in the third invariant"): the
stress-free volume of every cell is :math:`J_\mathrm{th} V`.

The isochoric part is an FElupe *umat* (methods ``gradient([F, statevars])`` and
``hessian([F, statevars])`` on arrays of shape ``(3, 3, quadrature points, cells)``) with
analytic first Piola–Kirchhoff stress and tangent; the volumetric part is added by
:class:`felupe.SolidBodyNearlyIncompressible`.

Thermo-viscoelasticity (Heipl & Murrenhoff, Eq. (8)/(9)) is a finite-strain generalised
Maxwell model in reduced time (Simo 1987; Holzapfel 2000, §6.10): the equilibrium branch is the
Mooney–Rivlin stress :math:`\bar S_\infty` scaled with :math:`T/T_p` (rubber elasticity); each
Prony term :math:`i` carries an internal stress :math:`Q_i` (second Piola–Kirchhoff),

.. math::

    Q_i^{n+1} = e^{-\xi_i} Q_i^n + \beta_i\,e^{-\xi_i/2}\,(\bar S^{n+1} - \bar S^n), \qquad
    \xi_i = \frac{\Delta t}{a_T(T)\,\tau_i}, \qquad \beta_i = E_i / E_\infty,

and :math:`S = (T/T_p)\,\bar S + \sum_i Q_i`, where :math:`\bar S` is the isochoric
Mooney–Rivlin stress whose small-strain Young's modulus is :math:`E_\infty` at the Prony
reference temperature :math:`T_p`. Far above :math:`T_g` the shift factor
:math:`a_T \ll 1` relaxes every branch within a step (equilibrium); below :math:`T_g` the
branches freeze and strain increments meet the glassy modulus.

References
----------
- O. Heipl, H. Murrenhoff (IFAS RWTH Aachen), "Rate- and state-dependent friction model for
  elastomeric seals", Eq. (6)–(9).
- J. C. Simo, "On a fully three-dimensional finite-strain viscoelastic damage model",
  Comput. Methods Appl. Mech. Eng. 60 (1987) 153–173.
- G. A. Holzapfel, Nonlinear Solid Mechanics, Wiley 2000, §6.10.
- M. L. Williams, R. F. Landel, J. D. Ferry, J. Am. Chem. Soc. 77 (1955) 3701 (WLF).
"""

from __future__ import annotations

import math
import os
import warnings
from dataclasses import dataclass, field

import numpy as np

from sealsim.errors import InputError
from sealsim.properties.elastomers import (
    TEMPERATURE_SCALINGS,
    entropic_modulus,
    fictive_temperature_step,
    thermal_strain,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = [
    "HyperelasticSealMaterial",
    "ModelHyperelasticSealMaterial",
    "MooneyRivlinIsochoric",
    "ViscoelasticMooneyRivlin",
    "ViscoelasticSealMaterial",
    "material_from_elastomer",
    "mooney_rivlin_young_modulus",
    "thermal_volume_ratio",
]


def thermal_volume_ratio(temperature, reference_temperature, expansion, glassy_expansion=None,
                         fictive_temperature=None):
    r"""Stress-free volume ratio of free thermal expansion, :math:`(1 + \varepsilon_{th})^3`.

    ε_th = α ΔT in the rubber; with a glassy coefficient and a fictive temperature T_f the
    strain of :func:`sealsim.properties.elastomers.thermal_strain`,
    α_g (T − T_0) + (α − α_g)(T_f − T_0).

    Parameters
    ----------
    temperature : float or array_like
        T [K].
    reference_temperature : float
        T_0 [K] at which the seal geometry is given (stress-free, J_th = 1).
    expansion : float
        Linear coefficient of thermal expansion of the rubber α [1/K].
    glassy_expansion : float, optional
        α_g [1/K] of the glass (default α).
    fictive_temperature : float or array_like, optional
        T_f [K] (default T: equilibrium).

    Returns
    -------
    float or numpy.ndarray
        J_th [-].

    Examples
    --------
    >>> round(thermal_volume_ratio(373.15, 293.15, 2e-4), 6)
    1.048772
    """
    strain = thermal_strain(temperature, reference_temperature, expansion, glassy_expansion,
                            fictive_temperature)
    ratio = (1.0 + np.asarray(strain)) ** 3
    return float(ratio) if np.ndim(ratio) == 0 else ratio


def mooney_rivlin_young_modulus(c10, c01):
    """Small-strain Young's modulus of an incompressible Mooney–Rivlin solid, E = 6 (C10 + C01).

    Parameters
    ----------
    c10, c01 : float
        Mooney–Rivlin constants [Pa].

    Returns
    -------
    float
        E [Pa].

    Examples
    --------
    >>> mooney_rivlin_young_modulus(0.8e6, 0.2e6)
    6000000.0
    """
    return 6.0 * (c10 + c01)


# -- isochoric Mooney–Rivlin umat ---------------------------------------------------------------

def _kinematics(F):
    """Invariants and inverse of F (3, 3, ...)."""
    C = np.einsum("ki...,kj...->ij...", F, F)
    I1 = np.einsum("ii...->...", C)
    trCC = np.einsum("ij...,ji...->...", C, C)
    I2 = 0.5 * (I1**2 - trCC)
    J = np.linalg.det(np.moveaxis(F, (0, 1), (-2, -1)))
    iF = np.moveaxis(np.linalg.inv(np.moveaxis(F, (0, 1), (-2, -1))), (-2, -1), (0, 1))
    iFT = np.swapaxes(iF, 0, 1)
    return C, I1, I2, J, iFT


def _mr_stress(F, c10, c01):
    """First Piola–Kirchhoff stress of the isochoric Mooney–Rivlin energy."""
    C, I1, I2, J, iFT = _kinematics(F)
    j23 = J ** (-2.0 / 3.0)
    j43 = j23 * j23
    FC = np.einsum("ik...,kj...->ij...", F, C)
    dI2 = 2.0 * (I1 * F - FC)
    P = c10 * j23 * (2.0 * F - (2.0 / 3.0) * I1 * iFT)
    if c01 != 0.0:
        P = P + c01 * j43 * (dI2 - (4.0 / 3.0) * I2 * iFT)
    return P


def _mr_tangent(F, c10, c01):
    """dP/dF (3, 3, 3, 3, ...) of the isochoric Mooney–Rivlin energy."""
    C, I1, I2, J, iFT = _kinematics(F)
    j23 = J ** (-2.0 / 3.0)
    j43 = j23 * j23
    eye = np.eye(3)
    extra = (None,) * (F.ndim - 2)
    II = np.einsum("ik,jl->ijkl", eye, eye)[(...,) + extra]  # δ_ik δ_JL
    iFT_iFT = np.einsum("ij...,kl...->ijkl...", iFT, iFT)
    iFT_x = np.einsum("il...,kj...->ijkl...", iFT, iFT)  # F^-T_iL F^-T_kJ
    F_iFT = np.einsum("ij...,kl...->ijkl...", F, iFT)
    iFT_F = np.einsum("ij...,kl...->ijkl...", iFT, F)
    A = c10 * j23 * (2.0 * II - (4.0 / 3.0) * (iFT_F + F_iFT)
                     + (4.0 / 9.0) * I1 * iFT_iFT + (2.0 / 3.0) * I1 * iFT_x)
    if c01 != 0.0:
        b = np.einsum("iK...,kK...->ik...", F, F)
        FC = np.einsum("ik...,kj...->ij...", F, C)
        B2 = 2.0 * (I1 * F - FC)
        dB2 = (4.0 * np.einsum("ij...,kl...->ijkl...", F, F) + 2.0 * I1 * II
               - 2.0 * np.einsum("ik,lj...->ijkl...", eye, C)
               - 2.0 * np.einsum("il...,kj...->ijkl...", F, F)
               - 2.0 * np.einsum("ik...,jl->ijkl...", b, eye))
        A = A + c01 * j43 * (dB2 - (4.0 / 3.0) * (np.einsum("ij...,kl...->ijkl...", B2, iFT)
                                                   + np.einsum("ij...,kl...->ijkl...", iFT, B2))
                             + (16.0 / 9.0) * I2 * iFT_iFT + (4.0 / 3.0) * I2 * iFT_x)
    return A


# compiled kernels: the same equations point by point (numba, cached on disk); the einsum
# functions above are the reference they are tested against and the fallback without numba
try:  # pragma: no cover - depends on the environment
    import numba
except ImportError:  # pragma: no cover
    numba = None


def _point_kinematics(F, C, b, iFT):
    """C = F^T F, b = F F^T and F^-T of one 3×3 F (written into C, b, iFT); (I1, I2, J)."""
    for i in range(3):
        for j in range(3):
            c = 0.0
            d = 0.0
            for k in range(3):
                c += F[k, i] * F[k, j]
                d += F[i, k] * F[j, k]
            C[i, j] = c
            b[i, j] = d
    I1 = C[0, 0] + C[1, 1] + C[2, 2]
    trCC = 0.0
    for i in range(3):
        for j in range(3):
            trCC += C[i, j] * C[j, i]
    I2 = 0.5 * (I1 * I1 - trCC)
    # cofactor matrix = J F^-T
    iFT[0, 0] = F[1, 1] * F[2, 2] - F[1, 2] * F[2, 1]
    iFT[0, 1] = F[1, 2] * F[2, 0] - F[1, 0] * F[2, 2]
    iFT[0, 2] = F[1, 0] * F[2, 1] - F[1, 1] * F[2, 0]
    iFT[1, 0] = F[0, 2] * F[2, 1] - F[0, 1] * F[2, 2]
    iFT[1, 1] = F[0, 0] * F[2, 2] - F[0, 2] * F[2, 0]
    iFT[1, 2] = F[0, 1] * F[2, 0] - F[0, 0] * F[2, 1]
    iFT[2, 0] = F[0, 1] * F[1, 2] - F[0, 2] * F[1, 1]
    iFT[2, 1] = F[0, 2] * F[1, 0] - F[0, 0] * F[1, 2]
    iFT[2, 2] = F[0, 0] * F[1, 1] - F[0, 1] * F[1, 0]
    J = F[0, 0] * iFT[0, 0] + F[0, 1] * iFT[0, 1] + F[0, 2] * iFT[0, 2]
    for i in range(3):
        for j in range(3):
            iFT[i, j] /= J
    return I1, I2, J


def _point_FC(F, C, FC):
    for i in range(3):
        for j in range(3):
            s = 0.0
            for k in range(3):
                s += F[i, k] * C[k, j]
            FC[i, j] = s


def _mr_stress_points(F, c10, c01, out):
    """P (3, 3, n) of the isochoric Mooney–Rivlin energy for F (3, 3, n), point by point."""
    Fp = np.empty((3, 3))
    C = np.empty((3, 3))
    b = np.empty((3, 3))
    iFT = np.empty((3, 3))
    FC = np.empty((3, 3))
    for q in range(F.shape[2]):
        for i in range(3):
            for j in range(3):
                Fp[i, j] = F[i, j, q]
        I1, I2, J = _point_kinematics(Fp, C, b, iFT)
        j23 = J ** (-2.0 / 3.0)
        j43 = j23 * j23
        _point_FC(Fp, C, FC)
        for i in range(3):
            for j in range(3):
                P = c10 * j23 * (2.0 * Fp[i, j] - (2.0 / 3.0) * I1 * iFT[i, j])
                if c01 != 0.0:
                    dI2 = 2.0 * (I1 * Fp[i, j] - FC[i, j])
                    P += c01 * j43 * (dI2 - (4.0 / 3.0) * I2 * iFT[i, j])
                out[i, j, q] = P
    return out


def _mr_tangent_points(F, c10, c01, out, reduced=False):
    """dP/dF (3, 3, 3, 3, n) for F (3, 3, n), point by point (see :func:`_mr_tangent`);
    ``reduced``: only the components :func:`mr_tangent` names, the others set to zero."""
    Fp = np.empty((3, 3))
    C = np.empty((3, 3))
    b = np.empty((3, 3))
    iFT = np.empty((3, 3))
    FC = np.empty((3, 3))
    for q in range(F.shape[2]):
        for i in range(3):
            for j in range(3):
                Fp[i, j] = F[i, j, q]
        I1, I2, J = _point_kinematics(Fp, C, b, iFT)
        a10 = c10 * J ** (-2.0 / 3.0)
        a01 = c01 * J ** (-2.0 / 3.0) * J ** (-2.0 / 3.0)
        _point_FC(Fp, C, FC)
        for i in range(3):
            for j in range(3):
                B2ij = 2.0 * (I1 * Fp[i, j] - FC[i, j])
                need_ij = (i < 2 and j < 2) or (i == 2 and j == 2)
                for k in range(3):
                    for l in range(3):  # noqa: E741 - index names of the formula
                        if reduced and not (need_ij and ((k < 2 and l < 2)
                                                         or (k == 2 and l == 2))):
                            out[i, j, k, l, q] = 0.0
                            continue
                        dik = 1.0 if i == k else 0.0
                        djl = 1.0 if j == l else 0.0
                        ii = dik * djl
                        t_tt = iFT[i, j] * iFT[k, l]
                        t_x = iFT[i, l] * iFT[k, j]
                        A = a10 * (2.0 * ii - (4.0 / 3.0) * (iFT[i, j] * Fp[k, l]
                                                             + Fp[i, j] * iFT[k, l])
                                   + (4.0 / 9.0) * I1 * t_tt + (2.0 / 3.0) * I1 * t_x)
                        if c01 != 0.0:
                            B2kl = 2.0 * (I1 * Fp[k, l] - FC[k, l])
                            dB2 = (4.0 * Fp[i, j] * Fp[k, l] + 2.0 * I1 * ii
                                   - 2.0 * dik * C[l, j] - 2.0 * Fp[i, l] * Fp[k, j]
                                   - 2.0 * b[i, k] * djl)
                            A += a01 * (dB2 - (4.0 / 3.0) * (B2ij * iFT[k, l]
                                                              + iFT[i, j] * B2kl)
                                        + (16.0 / 9.0) * I2 * t_tt + (4.0 / 3.0) * I2 * t_x)
                        out[i, j, k, l, q] = A
    return out


def _ve_history(statevars, decay, half, H, S, new, update):
    """H = Σ_i e^{-ξ_i} Q_i^n − β_i e^{-ξ_i/2} S^n (3, 3, points) of the state variables
    (n + 1, 3, 3, points): S^n, Q_1^n ... Q_n^n; with ``update`` also the branch stresses
    Q_i^{n+1} = e^{-ξ_i} Q_i^n + β_i e^{-ξ_i/2} (S − S^n) of the new isochoric stress S into
    ``new[1:]`` (one pass over the state; the loops run along the points: contiguous)."""
    npoints = statevars.shape[3]
    for i in range(3):
        for j in range(3):
            for q in range(npoints):
                H[i, j, q] = 0.0
            for t in range(decay.shape[0]):
                d = decay[t]
                e = half[t]
                for q in range(npoints):
                    q_old = statevars[t + 1, i, j, q]
                    s_old = statevars[0, i, j, q]
                    H[i, j, q] += d * q_old - e * s_old
                    if update:
                        new[t + 1, i, j, q] = d * q_old + e * (S[i, j, q] - s_old)
    return H


def _ve_stress_points(F, P_inf, statevars, decay, half, gamma, P, new):
    """Viscoelastic stress P = γ P_inf + F H and the new state variables (n + 1, 3, 3,
    points) of F (3, 3, points) and the equilibrium stress P_inf (see
    :meth:`ViscoelasticMooneyRivlin.gradient`)."""
    npoints = F.shape[2]
    Fp = np.empty((3, 3))
    C = np.empty((3, 3))
    b = np.empty((3, 3))
    iFT = np.empty((3, 3))
    S = new[0]
    for q in range(npoints):  # S^{n+1} = F^-1 P_inf
        for i in range(3):
            for j in range(3):
                Fp[i, j] = F[i, j, q]
        _point_kinematics(Fp, C, b, iFT)
        for i in range(3):
            for j in range(3):
                S[i, j, q] = (iFT[0, i] * P_inf[0, j, q] + iFT[1, i] * P_inf[1, j, q]
                              + iFT[2, i] * P_inf[2, j, q])
    H = _ve_history(statevars, decay, half, np.empty((3, 3, npoints)), S, new, True)
    for i in range(3):
        for j in range(3):
            for q in range(npoints):
                P[i, j, q] = gamma * P_inf[i, j, q] + (F[i, 0, q] * H[0, j, q]
                                                       + F[i, 1, q] * H[1, j, q]
                                                       + F[i, 2, q] * H[2, j, q])
    return P, new


def _ve_tangent_points(A, statevars, decay, half, gamma, reduced):
    """Viscoelastic tangent γ A_inf + δ_ik H_LJ (written into A_inf, (3, 3, 3, 3, points));
    ``reduced``: only the components :func:`mr_tangent` keeps (the others stay zero)."""
    npoints = A.shape[4]
    H = np.empty((3, 3, npoints))
    _ve_history(statevars, decay, half, H, H, statevars, False)
    for i in range(3):
        for J in range(3):
            for k in range(3):
                for L in range(3):
                    if reduced and not (((i < 2 and J < 2) or (i == 2 and J == 2))
                                        and ((k < 2 and L < 2) or (k == 2 and L == 2))):
                        continue  # zero already
                    if i == k:
                        for q in range(npoints):
                            A[i, J, k, L, q] = gamma * A[i, J, k, L, q] + H[L, J, q]
                    else:
                        for q in range(npoints):
                            A[i, J, k, L, q] = gamma * A[i, J, k, L, q]
    return A


HAVE_COMPILED_TANGENT = numba is not None
#: Use the compiled kernels when a umat is not told otherwise: numba installed and the
#: environment variable ``SEALSIM_FE_COMPILED`` not "0" (benchmarks set False for their
#: baseline, the einsum reference).
USE_COMPILED = HAVE_COMPILED_TANGENT and os.environ.get("SEALSIM_FE_COMPILED", "1") != "0"
if HAVE_COMPILED_TANGENT:  # pragma: no branch
    _point_kinematics = numba.njit(cache=True)(_point_kinematics)
    _point_FC = numba.njit(cache=True)(_point_FC)
    _mr_stress_points = numba.njit(cache=True)(_mr_stress_points)
    _mr_tangent_points = numba.njit(cache=True)(_mr_tangent_points)
    _ve_history = numba.njit(cache=True)(_ve_history)
    _ve_stress_points = numba.njit(cache=True)(_ve_stress_points)
    _ve_tangent_points = numba.njit(cache=True)(_ve_tangent_points)


def _flat_out(out, shape):
    """``out`` as a flat C-contiguous view of the given shape, or a new array."""
    if out is not None and out.shape[:-2] + (out.shape[-2] * out.shape[-1],) == shape \
            and out.flags.c_contiguous and out.dtype == np.float64:
        return out.reshape(shape)
    return np.empty(shape)


def mr_stress(F, c10, c01, compiled=None, out=None):
    """First Piola–Kirchhoff stress (3, 3, ...) of the isochoric Mooney–Rivlin energy.

    ``compiled`` (default :data:`USE_COMPILED`) runs the point-by-point kernel, writing into
    ``out`` if it fits; otherwise the einsum reference :func:`_mr_stress`. Both agree to
    round-off (tests: 1e-12).
    """
    if not (USE_COMPILED if compiled is None else compiled):
        return _mr_stress(F, c10, c01)
    shape = F.shape[2:]
    flat = np.ascontiguousarray(F, dtype=float).reshape(3, 3, -1)
    res = _flat_out(out if len(shape) == 2 else None, flat.shape)
    return _mr_stress_points(flat, float(c10), float(c01), res).reshape(3, 3, *shape)


def mr_tangent(F, c10, c01, compiled=None, out=None, reduced=False):
    """dP/dF (3, 3, 3, 3, ...) of the isochoric Mooney–Rivlin energy (see :func:`mr_stress`).

    ``reduced`` (compiled kernel only): just the 25 components A_ijkl with ij and kl in
    {11, 12, 21, 22, 33} -- those that meet a non-zero δF of an axisymmetric or plane-strain
    field (F block-diagonal) -- the others are set to zero; about 3× faster.
    """
    if not (USE_COMPILED if compiled is None else compiled):
        return _mr_tangent(F, c10, c01)
    shape = F.shape[2:]
    flat = np.ascontiguousarray(F, dtype=float).reshape(3, 3, -1)
    res = _flat_out(out if len(shape) == 2 else None, (3, 3, 3, 3, flat.shape[2]))
    return _mr_tangent_points(flat, float(c10), float(c01), res,
                              bool(reduced)).reshape(3, 3, 3, 3, *shape)


class MooneyRivlinIsochoric:
    r"""Isochoric Mooney–Rivlin FElupe umat with analytic stress and tangent.

    :math:`\hat\psi = C_{10}(\bar I_1 - 3) + C_{01}(\bar I_2 - 3)`; the volumetric part is
    added by :class:`felupe.SolidBodyNearlyIncompressible`. The constants may be changed
    between load increments (temperature dependence).

    Parameters
    ----------
    c10, c01 : float
        Mooney–Rivlin constants [Pa].
    compiled : bool, optional
        Use the compiled kernels or the einsum reference (default :data:`USE_COMPILED`).

    Examples
    --------
    >>> umat = MooneyRivlinIsochoric(0.8e6, 0.2e6)
    >>> F = np.eye(3).reshape(3, 3, 1, 1)
    >>> float(np.abs(umat.gradient([F, None])[0]).max())
    0.0
    """

    def __init__(self, c10: float, c01: float, compiled: bool | None = None):
        self.c10 = float(c10)
        self.c01 = float(c01)
        self.compiled = compiled

    def gradient(self, x, out=None):
        F, statevars = x[0], x[-1]
        return [mr_stress(F, self.c10, self.c01, self.compiled, out), statevars]

    def hessian(self, x, out=None, reduced=False):
        return [mr_tangent(x[0], self.c10, self.c01, self.compiled, out, reduced)]


class ViscoelasticMooneyRivlin:
    r"""Finite-strain generalised Maxwell (Prony) model on the isochoric Mooney–Rivlin stress.

    State variables per quadrature point: the previous isochoric stress :math:`\bar S^n` and
    the branch stresses :math:`Q_i^n` (9 components each). Set :attr:`xi` (the reduced time
    increments :math:`\Delta t / (a_T \tau_i)`) and :attr:`theta` (T/T_p) before each
    increment. See the module docstring for the update.

    Parameters
    ----------
    c10, c01 : float
        Mooney–Rivlin constants [Pa] of the equilibrium branch at the Prony reference
        temperature (6 (C10 + C01) = E∞).
    betas : array_like
        Relative branch moduli β_i = E_i / E∞ [-].
    compiled : bool, optional
        Compiled kernels or the einsum reference (see :class:`MooneyRivlinIsochoric`).

    Examples
    --------
    >>> umat = ViscoelasticMooneyRivlin(0.4e6, 0.1e6, betas=[10.0])
    >>> umat.x[-1].shape
    (18,)
    """

    def __init__(self, c10: float, c01: float, betas, compiled: bool | None = None):
        self.c10 = float(c10)
        self.c01 = float(c01)
        self.compiled = compiled
        self.betas = np.asarray(betas, dtype=float)
        self.nterms = self.betas.size
        self.xi = np.zeros(self.nterms)  # relaxed nothing: glassy response by default
        self.theta = 1.0
        self.x = [np.eye(3), np.zeros(9 * (self.nterms + 1))]

    def _history(self, statevars, shape):
        sv = statevars.reshape(self.nterms + 1, 3, 3, *shape)
        s_old = sv[0]
        q_old = sv[1:]
        decay, half, gamma = self._factors()
        decay = decay.reshape(-1, *([1] * (q_old.ndim - 1)))
        half = half.reshape(-1, *([1] * (q_old.ndim - 1)))
        H = np.sum(decay * q_old - half * s_old[None], axis=0)
        return s_old, q_old, decay, half, H, gamma

    def _compiled(self):
        return USE_COMPILED if self.compiled is None else self.compiled

    def _factors(self):
        """exp(-ξ_i), β_i exp(-ξ_i/2) and γ = θ + Σ β_i exp(-ξ_i/2) of the increment."""
        decay = np.exp(-self.xi)
        half = self.betas * np.exp(-0.5 * self.xi)
        return decay, half, self.theta + float(np.sum(half))

    def gradient(self, x, out=None):
        F, statevars = x[0], x[-1]
        shape = F.shape[2:]
        if self._compiled():
            flat = np.ascontiguousarray(F, dtype=float).reshape(3, 3, -1)
            n = flat.shape[2]
            sv = np.ascontiguousarray(statevars, dtype=float).reshape(self.nterms + 1, 3, 3, n)
            P_inf = _mr_stress_points(flat, self.c10, self.c01, np.empty((3, 3, n)))
            P = _flat_out(out if len(shape) == 2 else None, (3, 3, n))
            new = np.empty_like(sv)
            decay, half, gamma = self._factors()
            _ve_stress_points(flat, P_inf, sv, decay, half, gamma, P, new)
            return [P.reshape(3, 3, *shape), new.reshape(statevars.shape)]
        P_inf = mr_stress(F, self.c10, self.c01, self.compiled)
        iF = np.moveaxis(np.linalg.inv(np.moveaxis(F, (0, 1), (-2, -1))), (-2, -1), (0, 1))
        S_new = np.einsum("iK...,Kj...->ij...", iF, P_inf)
        s_old, q_old, decay, half, H, gamma = self._history(statevars, shape)
        q_new = decay * q_old + half * (S_new[None] - s_old[None])
        P = gamma * P_inf + np.einsum("iK...,KJ...->iJ...", F, H)
        new = np.concatenate([S_new[None], q_new], axis=0).reshape(statevars.shape)
        return [P, new]

    def hessian(self, x, out=None, reduced=False):
        """dP/dF; ``reduced`` (compiled only): the components of :func:`mr_tangent`'s."""
        F, statevars = x[0], x[-1]
        shape = F.shape[2:]
        if self._compiled():
            A = mr_tangent(F, self.c10, self.c01, True, out, reduced)
            n = A.reshape(3, 3, 3, 3, -1).shape[4]
            sv = np.ascontiguousarray(statevars, dtype=float).reshape(self.nterms + 1, 3, 3, n)
            decay, half, gamma = self._factors()
            _ve_tangent_points(A.reshape(3, 3, 3, 3, n), sv, decay, half, gamma, bool(reduced))
            return [A]
        _, _, _, _, H, gamma = self._history(statevars, shape)
        A = gamma * mr_tangent(F, self.c10, self.c01, self.compiled)
        A = A + np.einsum("ik,LJ...->iJkL...", np.eye(3), H)
        return [A]


# -- seal materials: constants as functions of temperature --------------------------------------

@dataclass
class HyperelasticSealMaterial:
    r"""Nearly incompressible Mooney–Rivlin seal material with thermal expansion.

    Parameters
    ----------
    c10, c01 : float or callable
        Mooney–Rivlin constants [Pa], constants or functions of temperature T [K].
    bulk_modulus : float or callable
        K [Pa] (constant or function of T).
    thermal_expansion : float
        Linear CTE α [1/K] of the rubber. This material is the rubbery (equilibrium) state at
        every temperature: it has no glass transition, in its stiffness or its expansion; use
        :class:`ViscoelasticSealMaterial` for paths through T_g.
    reference_temperature : float
        T_0 [K]: the geometry is stress-free at this temperature.
    name : str
        Label for outputs.

    Examples
    --------
    >>> m = HyperelasticSealMaterial(0.8e6, 0.2e6, 2e9, 2e-4, 293.15)
    >>> m.set_state(293.15, 0.0)
    >>> m.umat.c10, round(m.volume_ratio, 3)
    (800000.0, 1.0)
    """

    c10: object
    c01: object
    bulk_modulus: object
    thermal_expansion: float
    reference_temperature: float
    name: str = "Mooney-Rivlin"
    temperature: float = field(init=False, default=float("nan"))
    volume_ratio: float = field(init=False, default=1.0)
    kind: str = field(init=False, default="hyperelastic")

    def __post_init__(self):
        self.temperature = self.reference_temperature
        c10, c01, k = self.constants(self.reference_temperature)
        _check_constants(c10, c01, k, self.reference_temperature)
        self.umat = MooneyRivlinIsochoric(c10, c01)

    def constants(self, temperature: float) -> tuple[float, float, float]:
        """(C10, C01, K) [Pa] at temperature T [K]."""
        def ev(v):
            return float(v(temperature)) if callable(v) else float(v)
        return ev(self.c10), ev(self.c01), ev(self.bulk_modulus)

    def bulk(self, temperature: float) -> float:
        return self.constants(temperature)[2]

    def shear_modulus(self, temperature: float | None = None) -> float:
        """Small-strain shear modulus 2 (C10 + C01) [Pa]."""
        c10, c01, _ = self.constants(self.temperature if temperature is None else temperature)
        return 2.0 * (c10 + c01)

    def set_state(self, temperature: float, time_increment: float) -> None:
        """Set the temperature [K] of the next increment (time increment [s] unused)."""
        c10, c01, k = self.constants(temperature)
        _check_constants(c10, c01, k, temperature)
        self.umat.c10, self.umat.c01 = c10, c01
        self.temperature = float(temperature)
        self.volume_ratio = thermal_volume_ratio(temperature, self.reference_temperature,
                                                 self.thermal_expansion)

    def checkpoint(self) -> dict:
        return {"temperature": self.temperature, "volume_ratio": self.volume_ratio}

    def restore(self, cp: dict) -> None:
        self.temperature = cp["temperature"]
        self.volume_ratio = cp["volume_ratio"]

    def equilibrium(self) -> HyperelasticSealMaterial:
        return self


@dataclass
class ModelHyperelasticSealMaterial(HyperelasticSealMaterial):
    r"""Nearly incompressible seal material with any isochoric strain energy of FElupe
    (:mod:`sealsim.structure.hyperelastic`: Yeoh, Ogden, Arruda–Boyce, ...) and thermal
    expansion; the stress parameters scale with temperature by ``stiffness(T)``.

    ``c10``/``c01`` hold the neo-Hookean equivalent μ0/2 and 0 (for :meth:`shear_modulus`
    and the constant checks); the FE stress comes from ``model`` and ``parameters``.

    Parameters
    ----------
    model : str
        A name of :data:`sealsim.properties.hyperelastic.HYPERELASTIC_MODELS`.
    parameters : tuple
        ``((parameter, value), ...)`` at the reference temperature, stresses in Pa.
    stiffness : callable, optional
        r(T) [-], the factor on the stress parameters at T [K] (default 1).

    Examples
    --------
    >>> m = ModelHyperelasticSealMaterial(0.5e6, 0.0, 2e9, 2e-4, 293.15, model="ogden",
    ...                                   parameters=(("mu", (1e6,)), ("alpha", (2.0,))))
    >>> m.set_state(303.15, 0.0)
    >>> m.umat.scale
    1.0
    """

    model: str = "neo_hooke"
    parameters: tuple = ()
    stiffness: object = None

    def __post_init__(self):
        from sealsim.structure.hyperelastic import ScaledIsochoric, felupe_umat

        self.temperature = self.reference_temperature
        c10, c01, k = self.constants(self.reference_temperature)
        _check_constants(c10, c01, k, self.reference_temperature)
        self.umat = ScaledIsochoric(felupe_umat(self.model, dict(self.parameters)),
                                    self._scale(self.reference_temperature))

    def _scale(self, temperature: float) -> float:
        return 1.0 if self.stiffness is None else float(self.stiffness(temperature))

    def set_state(self, temperature: float, time_increment: float) -> None:
        """Set the temperature [K] of the next increment (time increment [s] unused)."""
        c10, c01, k = self.constants(temperature)
        _check_constants(c10, c01, k, temperature)
        self.umat.scale = self._scale(temperature)
        self.temperature = float(temperature)
        self.volume_ratio = thermal_volume_ratio(temperature, self.reference_temperature,
                                                 self.thermal_expansion)


@dataclass
class ViscoelasticSealMaterial:
    r"""Thermo-viscoelastic seal material: Mooney–Rivlin equilibrium branch + Prony series in
    reduced time with a shift factor a_T(T) (WLF above T_g).

    Parameters
    ----------
    c10, c01 : float
        Mooney–Rivlin constants [Pa] of the *equilibrium* branch at ``prony_temperature``.
    bulk_modulus : float
        K [Pa].
    moduli : array_like
        Prony moduli E_i [Pa].
    relaxation_times : array_like
        τ_i [s] at ``prony_temperature``.
    equilibrium_modulus : float
        E∞ [Pa] at ``prony_temperature`` (β_i = E_i / E∞).
    shift : callable
        log10 a_T(T) relative to ``prony_temperature`` (T [K] → [-]).
    thermal_expansion : float
        Rubbery (equilibrium) linear CTE α_r [1/K].
    reference_temperature : float
        T_0 [K] of the stress-free geometry (an equilibrium state: T_f = T_0).
    prony_temperature : float
        T_p [K] of the Prony series.
    glassy_expansion : float, optional
        Glassy linear CTE α_g [1/K]; default α_r (no glass transition in the expansion).

    Notes
    -----
    The free thermal strain follows the state of the rubber: ε_th = α_g (T − T_0) +
    (α_r − α_g)(T_f − T_0) (:func:`sealsim.properties.elastomers.thermal_strain`), with the
    fictive temperature T_f relaxing towards T in the same reduced time as the Prony branches,
    with the normalised Prony weights E_i / Σ E_j
    (:func:`~sealsim.properties.elastomers.fictive_temperature_step`). Slow cooling above
    T_g keeps T_f = T (rubbery α_r); when the branches freeze so does T_f, and the glass
    shrinks with α_g only.

    Examples
    --------
    >>> m = ViscoelasticSealMaterial(0.4e6, 0.1e6, 2e9, [30e6], [1.0], 3e6,
    ...                              lambda T: -(T - 250.0) / 10.0, 2e-4, 293.15, 293.15)
    >>> m.set_state(293.15, 1.0)
    >>> float(m.umat.xi[0])  # a_T = 10**-4.3: relaxed within the step (capped)
    700.0
    """

    c10: float
    c01: float
    bulk_modulus: float
    moduli: object
    relaxation_times: object
    equilibrium_modulus: float
    shift: object
    thermal_expansion: float
    reference_temperature: float
    prony_temperature: float
    name: str = "thermo-viscoelastic Mooney-Rivlin"
    glassy_expansion: float | None = None
    temperature: float = field(init=False, default=float("nan"))
    fictive_temperature: float = field(init=False, default=float("nan"))
    volume_ratio: float = field(init=False, default=1.0)
    kind: str = field(init=False, default="viscoelastic")

    def __post_init__(self):
        self.moduli = np.asarray(self.moduli, dtype=float)
        self.relaxation_times = np.asarray(self.relaxation_times, dtype=float)
        if self.moduli.shape != self.relaxation_times.shape or self.moduli.ndim != 1:
            raise InputError("Prony series: moduli and relaxation_times must be equally long "
                             f"lists (got {self.moduli.size} and {self.relaxation_times.size})")
        if np.any(self.moduli < 0) or np.any(self.relaxation_times <= 0):
            raise InputError("Prony series: moduli must be >= 0 Pa and relaxation times > 0 s")
        _check_constants(self.c10, self.c01, self.bulk_modulus, self.prony_temperature)
        self.umat = ViscoelasticMooneyRivlin(self.c10, self.c01,
                                             self.moduli / self.equilibrium_modulus)
        if self.glassy_expansion is None:
            self.glassy_expansion = self.thermal_expansion
        if not 0.0 <= self.glassy_expansion <= self.thermal_expansion:
            raise InputError(f"glassy thermal expansion {self.glassy_expansion!r} 1/K must lie "
                             f"between 0 and the rubbery {self.thermal_expansion!r} 1/K")
        total = float(self.moduli.sum())
        self.structural_weights = (self.moduli / total if total > 0
                                   else np.full(self.moduli.size, 1.0 / self.moduli.size))
        self.departures = np.zeros(self.moduli.size)  # δ_i [K]: T_f = T − Σ δ_i
        self.temperature = self.reference_temperature
        self.fictive_temperature = self.reference_temperature

    def bulk(self, temperature: float) -> float:
        return float(self.bulk_modulus)

    def shear_modulus(self, temperature: float | None = None) -> float:
        """Current small-strain tangent shear modulus [Pa] (equilibrium + unrelaxed branches)."""
        u = self.umat
        g = u.theta + float(np.sum(u.betas * np.exp(-0.5 * u.xi)))
        return 2.0 * (self.c10 + self.c01) * g

    def log10_shift(self, temperature: float) -> float:
        value = float(self.shift(temperature))
        if not math.isfinite(value):
            value = 300.0  # frozen: no relaxation within any step
        return min(value, 300.0)

    def set_state(self, temperature: float, time_increment: float) -> None:
        """Set temperature [K] and time increment [s] of the next increment.

        The reduced time increment uses a_T at the mid-increment temperature.
        """
        t_mid = 0.5 * (float(temperature) + self.temperature)
        log_a = self.log10_shift(t_mid)
        dt = max(float(time_increment), 0.0)
        with np.errstate(over="ignore", under="ignore", divide="ignore"):
            reduced = dt / 10.0 ** log_a if log_a < 300 else 0.0
            x = reduced / self.relaxation_times
            self.umat.xi = np.minimum(x, 700.0)
            self.departures = fictive_temperature_step(
                self.departures, float(temperature) - self.temperature, x,
                self.structural_weights)
        self.umat.theta = float(temperature) / self.prony_temperature
        self.temperature = float(temperature)
        self.fictive_temperature = self.temperature - float(self.departures.sum())
        self.volume_ratio = thermal_volume_ratio(
            temperature, self.reference_temperature, self.thermal_expansion,
            self.glassy_expansion, self.fictive_temperature)

    def checkpoint(self) -> dict:
        """The state that :meth:`set_state` changes (restored when an increment is cut back)."""
        return {"temperature": self.temperature, "departures": self.departures.copy(),
                "fictive_temperature": self.fictive_temperature,
                "volume_ratio": self.volume_ratio}

    def restore(self, cp: dict) -> None:
        self.temperature = cp["temperature"]
        self.departures = cp["departures"].copy()
        self.fictive_temperature = cp["fictive_temperature"]
        self.volume_ratio = cp["volume_ratio"]

    def equilibrium(self) -> HyperelasticSealMaterial:
        """The fully relaxed (long-time) hyperelastic material (for characteristic maps)."""
        tp = self.prony_temperature
        return HyperelasticSealMaterial(lambda T: entropic_modulus(self.c10, T, tp),
                                        lambda T: entropic_modulus(self.c01, T, tp),
                                        self.bulk_modulus, self.thermal_expansion,
                                        self.reference_temperature, name=self.name + " (relaxed)")


def _check_constants(c10, c01, k, temperature):
    ok = all(math.isfinite(v) for v in (c10, c01, k)) and c10 > 0 and c01 >= 0
    if not ok or k <= 10 * 2 * (c10 + c01) / 3:
        raise InputError(
            f"material constants at {temperature - ZERO_CELSIUS_K:.1f} degC are invalid: "
            f"C10 = {c10!r} Pa (must be > 0), C01 = {c01!r} Pa (>= 0), bulk modulus K = {k!r} Pa "
            "(must be finite and well above the shear modulus for a nearly incompressible "
            "rubber)")


def material_from_elastomer(elastomer, model: str = "hyperelastic", *,
                            reference_temperature: float,
                            temperature_scaling: str = "held",
                            frequency: float | None = None):
    """Build a seal material from a catalogue :class:`~sealsim.properties.elastomers.Elastomer`.

    Parameters
    ----------
    elastomer : Elastomer
        Catalogue entry (``get_elastomer("NBR")``).
    model : {"hyperelastic", "viscoelastic"}
        ``"hyperelastic"``: Mooney–Rivlin with the catalogue constants, scaled with
        temperature as ``temperature_scaling`` says.
        ``"viscoelastic"``: equilibrium Mooney–Rivlin with 6 (C10 + C01) = E∞ (same C01/C10
        as the catalogue), the catalogue Prony series and its WLF/Arrhenius shift.
    reference_temperature : float
        T_0 [K] at which the geometry is stress-free (installation temperature).
    temperature_scaling : {"held", "entropic", "modulus", "none"}
        Hyperelastic only: C(T) = C(T_ref)·r(T) with r from
        :meth:`~sealsim.properties.elastomers.Elastomer.modulus_ratio` (the same law as the
        analytic contact estimate of :mod:`sealsim.pneumatic.contact_maps`).
        ``"held"`` (default): r = E_h(T)/E(T_ref, f_test), the relaxed modulus of a seal held
        for :data:`~sealsim.properties.elastomers.HELD_SEAL_TIME` from the master curve,
        installed at ``reference_temperature``, relative to the test-frequency modulus the
        constants hold for (sealsim's convention for an installed seal; the rotary lip force
        uses the same modulus for its mounted stress).
        ``"entropic"``: r = T/T_ref, the equilibrium modulus of rubber elasticity,
        G = n·k·T (Treloar, *The Physics of Rubber Elasticity*, 1975, ch. 4). A seal held at
        constant squeeze relaxes to it, which is also what Heipl & Murrenhoff assume for slow
        cooling above Tg; valid above ≈ T_g + 30 K, below that use ``model = "viscoelastic"``.
        ``"modulus"``: the catalogue's E(T) at ``frequency``, which includes the viscoelastic
        softening of the glass-transition tail (the dynamic modulus at that rate, not the
        stiffness of a long-held squeeze). ``"none"``: constant.
    frequency : float, optional
        Frequency [Hz] of E(T) for ``"modulus"`` (default: the catalogue's test frequency).
    """
    e = elastomer
    if model == "hyperelastic":
        if temperature_scaling not in TEMPERATURE_SCALINGS:
            raise InputError(f"material.temperature_scaling: {temperature_scaling!r} is not "
                             "allowed; choose 'entropic', 'modulus' or 'none'")

        mounted = reference_temperature if temperature_scaling == "held" else None

        def stiffness(T):
            return e.modulus_ratio(T, scaling=temperature_scaling, frequency=frequency,
                                   mounting_temperature=mounted)

        def c10(T):
            return e.c10 * stiffness(T)

        def c01(T):
            return e.c01 * stiffness(T)

        if e.hyperelastic is not None:
            model, parameters = e.hyperelastic
            return ModelHyperelasticSealMaterial(
                c10, c01, e.bulk_modulus, e.thermal_expansion, reference_temperature,
                name=f"{e.name} ({model})", model=model, parameters=parameters,
                stiffness=stiffness)
        return HyperelasticSealMaterial(c10, c01, e.bulk_modulus, e.thermal_expansion,
                                        reference_temperature, name=e.name)
    if model == "viscoelastic":
        if e.prony is None:
            raise InputError(f"material.model = 'viscoelastic' needs a Prony series, but "
                             f"{e.name} has none; use model = 'hyperelastic' or another material")
        if e.hyperelastic is not None:
            raise InputError(f"material.model = 'viscoelastic' is a Prony series on "
                             f"Mooney-Rivlin; {e.name} has the {e.hyperelastic[0]} strain "
                             "energy: use model = 'hyperelastic', or fit Mooney-Rivlin")
        e_inf, e_i, tau_i = e.prony
        tp = float(e.prony_reference_temperature or e.reference_temperature)
        ratio = e.c01 / e.c10
        c10 = e_inf / 6.0 / (1.0 + ratio)
        c01 = c10 * ratio

        def shift(T):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return float(e.log10_shift_factor(T, reference_temperature=tp))
        return ViscoelasticSealMaterial(c10, c01, e.bulk_modulus, e_i, tau_i, e_inf, shift,
                                        e.thermal_expansion, reference_temperature, tp,
                                        name=e.name + " (Prony/WLF)",
                                        glassy_expansion=e.glassy_expansion)
    raise InputError(f"material.model: {model!r} is not allowed; choose 'hyperelastic' or "
                     "'viscoelastic'")
