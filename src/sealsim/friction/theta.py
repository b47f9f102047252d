"""The Θ rate-and-state friction law of Heipl & Murrenhoff (Carlson–Batista type).

A lubrication state Θ ∈ [0, 1] per contact moves between dry/boundary friction (Θ = 0) and
full hydrodynamic friction (Θ = 1)::

    dΘ/dt = −Θ/τ + (|v|/α)·(F_ref/F_N)^n·(1 − Θ)       (Heipl & Murrenhoff Eq. 4, [R])
    F     = F_N·[f_a·(1 − Θ) + f_b·Θ]·sgn(v) + γ·b·v  (Heipl & Murrenhoff Eq. 5, [R])

The paper's equations are only partly legible in the available text; this is sealsim's
reconstruction with the following choices (each marked [R], to be checked against
the original paper):

* **State term −Θ/τ** ("melting of the film defined by a time constant"): at rest the film is
  squeezed out and Θ relaxes towards the dry state with time constant τ [s], so the break-away
  force grows with dwell time and saturates: F_brk(t_d) = F_N·[f_a − (f_a − f_b)·Θ0·e^(−t_d/τ)].
* **Rate term (|v|/α)(1 − Θ)**: shear builds the film over a characteristic sliding length α [m].
* **Load F_N in the rate term** as (F_ref/F_N)^n (n = 1 by default): the sliding length needed
  to build the film grows with the load, α_eff = α·(F_N/F_ref)^n.  Higher load → lower steady
  Θ at every speed and a transition velocity v* = (α/τ)·(F_N/F_ref)^n that grows with load →
  the "weakly developed transition" of Heipl & Murrenhoff Fig. 6 (upper loop).  Reason for the
  rate term and not τ: the paper names F_N as a factor added to the description of the rate
  term, and a load that only changed τ would also change the dwell-time behaviour, which the
  paper attributes to τ alone.  F_ref only fixes the unit (α is the sliding length at
  F_N = F_ref).
* **Force**: the paper distinguishes a static part F_a and a dynamic part F_b, with F_N and b as
  the interfaces to the FE model.  Here F_a, F_b are *friction coefficients* f_a, f_b [-] that
  multiply F_N (so the FE maps F_N(Δp, T) set the friction level, replacing the linear pressure
  scaling of Heipl & Murrenhoff Eq. 3), weighted by the state: dry part f_a·(1 − Θ),
  mixed/boundary part f_b·Θ; the viscous part γ·b·v with γ [N·s/m²] the grease/viscosity
  coefficient of the paper.
* **Convention Θ = 0 dry, 1 hydrodynamic** (θ = 0 is the solid-like, pinned lubricant in
  Carlson & Batista [2]).  The labels of Heipl & Murrenhoff Fig. 6 (dry at the top of the state
  axis) suggest the paper plots the complementary variable 1 − Θ; the physics is the same.

Steady state (closed form): Θ_ss(v) = |v|/(|v| + v*), v* = (α/τ)·(F_N/F_ref)^n, so
F_ss(v) = F_N·[f_a·v* + f_b·|v|]/(|v| + v*)·sgn(v) + γ·b·v -- a Stribeck-shaped curve without an
explicit Stribeck exponential.  The state lags behind the velocity with the time constant
τ_eff = 1/(1/τ + |v|/α_eff), so F–v loops open up (hysteresis) more the faster v changes.

**Sticking.**  At v = 0 the friction force balances the applied force up to the break-away level
F_N·[f_a(1 − Θ) + f_b·Θ] (true sticking, no creep; resolved for all laws in
:mod:`sealsim.friction.hybrid`).  Alternatively, with ``bristle_stiffness`` σ0 set, the law gets
a second state, a LuGre bristle z [m] that saturates at that level::

    dz/dt = v − σ0·|v|·z/g_Θ,   g_Θ = F_N·[f_a(1 − Θ) + f_b·Θ],   F = σ0·z + σ1·dz/dt + γ·b·v

(the structure of Yanada's lubricant-film LuGre [3]).  This smooth variant has the same steady
curve, adds pre-sliding, and suits implicit ODE solvers of coupled models (no switching).

Θ stays in [0, 1] exactly: for constant v the state equation is linear and the exact step is a
convex combination of the old Θ and Θ_ss ∈ [0, 1).

**Temperature.**  γ is the (equivalent) viscosity of the grease (Heipl & Murrenhoff Eq. 5): the
viscous force γ·b·v is the shear of the film, so γ follows the viscosity of the grease's base
oil,

    γ(T) = γ_ref·ν(T)/ν(T_ref),   log10 log10(ν + 0.7) = A − B·log10 T   (ASTM D341)

with A, B through the base-oil viscosities at 40 and 100 °C of the grease's datasheet
(``base_oil_nu40``, ``base_oil_nu100``; :func:`theta_viscous_coefficient`).  ASTM D341 rather
than an Arrhenius law: through 30 and 100 °C it predicts the measured 60 °C viscosity of the
machine oils of Stachowiak & Batchelor (Engineering Tribology, Table 2.3) within about 2 %, an
Arrhenius law only within 10-20 % (a test checks this).  No public source gives the temperature
dependence of f_a, f_b, τ or α of a pneumatic seal (Heipl & Murrenhoff Fig. 3 shows only the net
effect), so they are constants; the temperature also acts through F_N and b of the contact maps.

**Steady curve from the seal's own contact** (``steady = "contact"``, the parameter set
``seal_contact``).  The lumped levels f_a, f_b and γ belong to one seal at one condition.  With
``steady = "contact"`` the steady friction F_ss(v) comes instead from the seal's contact
pressure profile by inverse hydrodynamics and mixed lubrication, tabulated per seal over
temperature, pressure difference, speed and stroke direction
(:mod:`sealsim.friction.contact_table`, passed in ``inputs.contact_table``)::

    F_ss(v) = π·D·[μ_b·L(|v|) + V(|v|)]·sgn(v)

(L the asperity-carried load, V the viscous friction, per unit circumference; μ_b the boundary
friction coefficient of the lubricated rubber).  The film does not form at once: the fluid at
the contact's pressure maximum entered its inlet about one contact width earlier (Sugimura,
Jones & Spikes [6] measured such film transients; Sugimura et al. [8]: the film formed at the
inlet moves through the contact with little change, so it is the one of the entrainment speed
at the time its fluid entered -- both on hard EHD contacts, for a seal's soft contact an
assumption), so the asperities carry the load of the speed φ [m/s]
that the film has formed for, a state (``film_speed``, the law's last) that follows the
sliding speed over a sliding distance of the contact width b and falls at rest as the seal
squeezes the film out, at the decay rate κ(φ) of the seal's friction table (Reynolds'
squeeze film under the load the fluid carries, :mod:`sealsim.tribology.squeeze_film`)::

    dφ/dt = (|v| − φ)·(|v|/b + κ(φ)),    F_ss,φ(v) = π·D·[μ_b·L(φ) + V(|v|)]·sgn(v)

(a first-order lag is sealsim's simplest form of that delay [M]).  In steady sliding φ = |v|.
Without the lag the friction fell the instant the speed rose, dF/dv → −∞ as the film
h* ∝ √|v| (inverse hydrodynamics) lifted the asperities: a piston creeping into its end stop
chattered between stick and slip at µm/s; with it the friction's instant response to the
speed is the film's viscous shear and Θ's rate term, both rising with speed -- the positive
direct effect that makes steady sliding stable against a stiff spring (Rice & Ruina [7]),
while the steady curve still falls through the mixed regime.  The Θ state keeps the dynamics
on top of it, scaling the boundary friction of the asperities (the film φ sets the load they
carry)::

    F = max(F_ss,φ(v) + ΔF·(Θ_ss(v) − Θ), π·D·V(|v|))·sgn(v),   ΔF = d·π·D·μ_b·L(φ)

with the same state equation: in steady sliding Θ = Θ_ss, φ = |v| and F = F_ss exactly; Θ lagging
behind Θ_ss while the speed rises gives more friction than steady, less while it falls, either
way by at most the fraction d of the asperities' friction, so nothing once the film carries the
load (a Θ still building up over α adds nothing in full film; a quick reversal keeps (1 − d) of
the boundary friction at the film it carries through zero speed; with ΔF the long dwell's
d·μ_b·F_N on top of a film that had already lifted the asperities, the friction after a
1 m/s² reversal of a 2 mm O-ring fell to its film's viscous shear, 0.002 N instead of 0.14 N,
and a Θ building up added up to d·μ_b·F_N in full film); at rest the
break-away force F_ss,φ(0⁺)·(1 − d·Θ) (F_ss,φ(0⁺) = π·D·μ_b·L(φ), the larger direction: the
sliding level's limit v → 0±, so breaking away after a short dwell, the film still there, does
not drop the friction by a step) grows with the dwell time, as Θ and φ decay, to the boundary
level F_ss(0⁺) ≈ μ_b·F_N (the asperities carry the whole load).
d = ``dwell_drop`` is the fraction by which the break-away force just after sliding (Θ = 1,
the film squeezed out, φ = 0) lies below the one after a long dwell -- 1 − f_b/f_a of the
lumped law.  With bristles the same level g is the LuGre bristles'
saturation level.

References
----------
.. [1] O. Heipl, H. Murrenhoff, "Rate- and state-dependent friction model for elastomeric
   seals", Eq. 4 and 5, Fig. 6.
.. [2] J. M. Carlson, A. A. Batista, "Constitutive relation for the friction between lubricated
   surfaces", Phys. Rev. E 53, 4153, 1996 (model structure [M]).
.. [3] H. Yanada, Y. Sekikawa, "Modeling of dynamic behaviors of friction", Mechatronics 18,
   330-339, 2008 (lubricant-film LuGre, the structure of the bristle variant) [M].
.. [4] ASTM D341-20, viscosity-temperature equations (Walther).
.. [5] G. W. Stachowiak, A. W. Batchelor, Engineering Tribology, 3rd ed., Elsevier 2005,
   Table 2.3 (viscosities of mineral oils at 30, 60, 100 °C).
.. [6] J. Sugimura, W. R. Jones, H. A. Spikes, "EHD film thickness in non-steady state
   contacts", J. Tribol. 120(3), 442-452, 1998 (film transients in acceleration, stop-start
   and reciprocation).
.. [7] J. R. Rice, A. L. Ruina, "Stability of steady frictional slipping", J. Appl. Mech. 50,
   343-349, 1983 (for laws with a positive instantaneous velocity dependence, steady sliding
   against a spring is stable above a critical stiffness, which inertia raises).
.. [8] J. Sugimura, T. Okumura, Y. Yamamoto, H. A. Spikes, "Simple equation for
   elastohydrodynamic film thickness under acceleration", Tribol. Int. 32(2), 117-123, 1999
   (the film formed at the inlet moves through the contact with little change).
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from pydantic import Field, model_validator

from sealsim.cases import Q
from sealsim.errors import InputError
from sealsim.friction import kernels as _k
from sealsim.friction.base import (
    NO_INPUTS,
    ContactInputs,
    FrictionLaw,
    LawParameters,
    Partials,
    affine_scan,
    as_state,
    as_velocity,
    validate_parameters,
)
from sealsim.friction.kernels import apply
from sealsim.friction.lugre import _lugre_affine, lugre_bristle_rate

__all__ = [
    "Theta",
    "ThetaParameters",
    "theta_breakaway_after_dwell",
    "theta_force",
    "theta_friction_level",
    "theta_rate",
    "theta_steady",
    "theta_steady_force",
    "theta_step",
    "theta_transition_velocity",
    "theta_viscous_coefficient",
]


# --------------------------------------------------------------------------------------------
# Pure functions
# --------------------------------------------------------------------------------------------
def _load_factor(normal_force, reference_normal_force, load_exponent):
    """(F_N/F_ref)^n [-] (:func:`sealsim.friction.kernels.theta_load_factor`)."""
    return apply(_k._loop_theta_load_factor, normal_force, reference_normal_force,
                 load_exponent)


def theta_transition_velocity(tau, alpha, normal_force, reference_normal_force,
                              load_exponent=1.0):
    """Transition velocity of the steady Θ curve, v* = (α/τ)·(F_N/F_ref)^n.

    Parameters
    ----------
    tau : array_like
        Film relaxation time constant τ [s].
    alpha : array_like
        Characteristic sliding length α [m] at F_N = F_ref.
    normal_force : array_like
        Normal force F_N [N].
    reference_normal_force : array_like
        Reference load F_ref [N].
    load_exponent : array_like
        Load exponent n [-].

    Returns
    -------
    ndarray
        v* [m/s]; Θ_ss(v*) = 1/2.

    Examples
    --------
    >>> float(theta_transition_velocity(2.0, 0.1, 200.0, 100.0))
    0.1
    """
    return apply(_k._loop_theta_transition_velocity, tau, alpha, normal_force,
                 reference_normal_force, load_exponent)


def theta_rate(theta, v, tau, alpha, normal_force, reference_normal_force, load_exponent=1.0):
    """dΘ/dt of the reconstructed Heipl & Murrenhoff Eq. 4.

    .. math:: \\dot\\Theta = -\\frac{\\Theta}{\\tau}
              + \\frac{|v|}{\\alpha}\\left(\\frac{F_{ref}}{F_N}\\right)^n (1 - \\Theta)

    Parameters
    ----------
    theta : array_like
        Lubrication state Θ [-] (0 dry, 1 hydrodynamic).
    v : array_like
        Sliding velocity [m/s].
    tau : array_like
        Film relaxation time constant τ [s].
    alpha : array_like
        Characteristic sliding length α [m].
    normal_force : array_like
        Normal force F_N [N], > 0.
    reference_normal_force : array_like
        Reference load F_ref [N].
    load_exponent : array_like
        Load exponent n [-].

    Returns
    -------
    ndarray
        dΘ/dt [1/s].

    Examples
    --------
    >>> float(theta_rate(0.5, 0.0, 2.0, 0.1, 100.0, 100.0))        # at rest: −Θ/τ
    -0.25
    >>> float(theta_rate(0.5, 0.05, 2.0, 0.1, 100.0, 100.0))       # v = v*: steady at 1/2
    0.0
    """
    return apply(_k._loop_theta_rate, theta, v, tau, alpha, normal_force, reference_normal_force,
                 load_exponent)


def theta_steady(v, tau, alpha, normal_force, reference_normal_force, load_exponent=1.0):
    """Steady lubrication state at constant velocity (closed form of Eq. 4).

    .. math:: \\Theta_{ss}(v) = \\frac{|v|}{|v| + v^*}, \\qquad
              v^* = \\frac{\\alpha}{\\tau}\\left(\\frac{F_N}{F_{ref}}\\right)^n

    Parameters are those of :func:`theta_rate`.

    Returns
    -------
    ndarray
        Θ_ss [-] in [0, 1).

    Examples
    --------
    >>> theta_steady([0.0, 0.05, 0.45], 2.0, 0.1, 100.0, 100.0)
    array([0. , 0.5, 0.9])
    """
    return apply(_k._loop_theta_steady, v, tau, alpha, normal_force, reference_normal_force,
                 load_exponent)


def theta_step(theta, v, dt, tau, alpha, normal_force, reference_normal_force,
               load_exponent=1.0):
    """Exact Θ after ``dt`` with v and F_N held constant.

    .. math:: \\Theta(t+\\Delta t) = \\Theta_{ss} + (\\Theta - \\Theta_{ss})\\,
              e^{-(1/\\tau + r)\\Delta t}, \\qquad r = \\frac{|v|}{\\alpha}
              \\left(\\frac{F_{ref}}{F_N}\\right)^n

    A convex combination of Θ and Θ_ss: Θ stays in [0, 1] for any dt >= 0.

    Parameters are those of :func:`theta_rate` plus ``dt`` [s].

    Returns
    -------
    ndarray
        Θ at the end of the step [-].

    Examples
    --------
    >>> float(theta_step(0.8, 0.0, 2.0, 2.0, 0.1, 100.0, 100.0))   # dwell of one τ
    0.294...
    """
    a, b = _theta_affine(v, dt, tau, alpha, normal_force, reference_normal_force,
                         load_exponent)
    return a * np.asarray(theta, dtype=float) + b


def _theta_affine(v, dt, tau, alpha, normal_force, reference_normal_force, load_exponent):
    """(a, b) of the exact step Θ1 = a·Θ0 + b (:func:`sealsim.friction.kernels.theta_affine`)."""
    return apply(_k._loop_theta_affine, v, dt, tau, alpha, normal_force, reference_normal_force,
                 load_exponent, outputs=2)


def theta_friction_level(theta, normal_force, f_a, f_b):
    """Boundary-friction level g_Θ = F_N·[f_a·(1 − Θ) + f_b·Θ] [N] (Heipl & Murrenhoff Eq. 5,
    [R]).

    This is the sliding force without the viscous part and, at rest, the break-away force.

    Parameters
    ----------
    theta : array_like
        Lubrication state Θ [-].
    normal_force : array_like
        Normal force F_N [N].
    f_a : array_like
        Dry (static) friction coefficient f_a [-] (F_a of Heipl & Murrenhoff).
    f_b : array_like
        Friction coefficient with a full film f_b [-] (F_b of Heipl & Murrenhoff).

    Returns
    -------
    ndarray
        g_Θ [N].

    Examples
    --------
    >>> theta_friction_level([0.0, 1.0], 100.0, 0.5, 0.1)
    array([50., 10.])
    """
    return apply(_k._loop_theta_friction_level, theta, normal_force, f_a, f_b)


def theta_force(theta, v, normal_force, contact_width, f_a, f_b, gamma):
    """Sliding friction force of the Θ law (Heipl & Murrenhoff Eq. 5, reconstructed).

    .. math:: F = F_N\\,[f_a(1-\\Theta) + f_b\\Theta]\\operatorname{sgn}(v) + \\gamma\\,b\\,v

    Parameters
    ----------
    theta : array_like
        Lubrication state Θ [-].
    v : array_like
        Sliding velocity [m/s].
    normal_force : array_like
        Normal force F_N [N].
    contact_width : array_like
        Contact width b [m].
    f_a, f_b : array_like
        Dry and full-film friction coefficients [-].
    gamma : array_like
        Viscous coefficient γ [N·s/m²] (force per contact width and velocity).

    Returns
    -------
    ndarray
        Friction force [N] (0 at v = 0; the force at rest is resolved by the hybrid logic).

    Examples
    --------
    >>> float(theta_force(0.5, 1.0, 100.0, 1e-3, 0.5, 0.1, 1e4))
    40.0
    """
    return apply(_k._loop_theta_force, theta, v, normal_force, contact_width, f_a, f_b, gamma)


def theta_steady_force(v, normal_force, contact_width, tau, alpha, f_a, f_b, gamma,
                       reference_normal_force, load_exponent=1.0):
    """Steady friction force of the Θ law (closed form).

    .. math:: F_{ss}(v) = F_N\\,\\frac{f_a v^* + f_b |v|}{|v| + v^*}\\operatorname{sgn}(v)
              + \\gamma\\,b\\,v

    Parameters are those of :func:`theta_force` and :func:`theta_rate`.

    Returns
    -------
    ndarray
        Steady friction force [N].

    Examples
    --------
    >>> theta_steady_force([0.05, 1.0], 100.0, 1e-3, 2.0, 0.1, 0.5, 0.1, 1e4, 100.0)
    array([30.5 , 21.9047619])
    """
    theta = theta_steady(v, tau, alpha, normal_force, reference_normal_force, load_exponent)
    return theta_force(theta, v, normal_force, contact_width, f_a, f_b, gamma)


def theta_breakaway_after_dwell(dwell, theta0, tau, normal_force, f_a, f_b):
    """Break-away force after resting for ``dwell`` [s] from the state Θ0.

    .. math:: F_{brk}(t_d) = F_N\\,[f_a - (f_a - f_b)\\,\\Theta_0\\,e^{-t_d/\\tau}]

    Grows with the dwell time and saturates at F_N·f_a (the dry level).

    Parameters
    ----------
    dwell : array_like
        Dwell (rest) time t_d [s].
    theta0 : array_like
        Lubrication state when the motion stopped [-].
    tau : array_like
        Film relaxation time constant [s].
    normal_force : array_like
        Normal force F_N [N].
    f_a, f_b : array_like
        Dry and full-film friction coefficients [-].

    Returns
    -------
    ndarray
        Break-away force [N].

    Examples
    --------
    >>> theta_breakaway_after_dwell([0.0, 2.0, 1e3], 0.8, 2.0, 100.0, 0.5, 0.1)
    array([18. , 38.227..., 50. ])
    """
    theta = np.asarray(theta0, dtype=float) * np.exp(-np.asarray(dwell, dtype=float) / tau)
    return theta_friction_level(theta, normal_force, f_a, f_b)


def theta_viscous_coefficient(temperature, gamma, reference_temperature, walther_a=0.0,
                              walther_b=0.0):
    """Viscous coefficient of the Θ law at temperature T, γ(T) = γ_ref·ν(T)/ν(T_ref).

    .. math:: \\gamma(T) = \\gamma_{ref}\\,\\frac{\\nu(T)}{\\nu(T_{ref})}, \\qquad
              \\log_{10}\\log_{10}(\\nu + 0.7) = A - B\\log_{10} T

    ν is the kinematic viscosity of the grease's base oil (ASTM D341, ν in mm²/s, T in K);
    B = 0 gives a constant γ.

    Parameters
    ----------
    temperature : array_like
        Contact temperature T [K].
    gamma : array_like
        γ_ref [N·s/m²] at ``reference_temperature``.
    reference_temperature : array_like
        T_ref [K].
    walther_a, walther_b : array_like
        ASTM D341 constants A, B of the base oil [-]
        (:func:`sealsim.properties.oils.walther_constants`).

    Returns
    -------
    ndarray
        γ(T) [N·s/m²].

    Examples
    --------
    Base oil 110 mm²/s at 40 °C, 11 mm²/s at 100 °C (SKF LGMT 2): γ at 40 °C is
    γ_ref·ν(40 °C)/ν(25 °C):

    >>> from sealsim.properties.oils import walther_constants
    >>> A, B = walther_constants(313.15, 110e-6, 373.15, 11e-6)
    >>> round(float(theta_viscous_coefficient(313.15, 1e4, 298.15, A, B)), 0)
    3899.0
    """
    return np.asarray(gamma, dtype=float) * apply(
        _k._loop_walther_viscosity_ratio, temperature, reference_temperature, walther_a,
        walther_b)


# --------------------------------------------------------------------------------------------
# Parameters and law object
# --------------------------------------------------------------------------------------------
#: fields only the steady curve from the seal's contact uses (``steady = "contact"``)
CONTACT_ONLY_FIELDS = ("boundary_friction", "dwell_drop", "roughness", "film_factor",
                       "lubricant_density", "thickener_factor", "asperity_wavelength",
                       "supply_layer")
#: fields only the lumped steady curve uses (``steady = "lumped"``)
LUMPED_ONLY_FIELDS = ("f_a", "f_b", "gamma")


class ThetaParameters(LawParameters):
    """Parameters of the Θ law (Heipl & Murrenhoff Eq. 4/5 as reconstructed, see module
    docstring)."""

    law: Literal["theta"] = "theta"
    steady: Literal["lumped", "contact"] = Field("lumped", description=(
        "where the steady curve comes from: 'lumped' f_a, f_b and gamma, or 'contact' the "
        "seal's own contact pressure profile (mixed lubrication, a friction table per seal)"))
    tau: Q("time", gt=0)
    alpha: Q("length", gt=0)
    f_a: Q("dimensionless", ge=0) | None = None
    f_b: Q("dimensionless", ge=0) | None = None
    gamma: Q("dynamic_viscosity", ge=0) = 0.0
    reference_normal_force: Q("force", gt=0)
    load_exponent: Q("dimensionless", ge=0, le=10) = 1.0
    bristle_stiffness: Q("stiffness", gt=0) | None = None
    bristle_damping: Q("damping", ge=0) = 0.0
    reference_temperature: Q("temperature", gt=0) = Field(293.15, description=(
        "temperature at which gamma holds (and the other values were identified)"))
    base_oil_nu40: Q("kinematic_viscosity", gt=0) | None = Field(None, description=(
        "kinematic viscosity of the grease's base oil at 40 degC (datasheet); with "
        "base_oil_nu100 it makes gamma follow the base oil's viscosity (ASTM D341)"))
    base_oil_nu100: Q("kinematic_viscosity", gt=0) | None = Field(None, description=(
        "kinematic viscosity of the grease's base oil at 100 degC (datasheet)"))
    boundary_friction: Q("dimensionless", ge=0) = Field(0.2, description=(
        "contact: boundary friction coefficient mu_b of the lubricated rubber on the asperity "
        "load"))
    dwell_drop: Q("dimensionless", ge=0, lt=1) = Field(0.5, description=(
        "contact: break-away force just after sliding (Theta = 1) below the long-dwell one, "
        "as a fraction of the asperities' boundary friction (mu_b*F_N after a long dwell); "
        "a Theta above its steady value lowers that friction by at most this fraction"))
    roughness: Q("length", gt=0) = Field(0.3e-6, description=(
        "contact: combined RMS roughness of counter surface and seal"))
    film_factor: Q("dimensionless", gt=0) = Field(1.0, description=(
        "contact: multiplier of the inverse-hydrodynamic film"))
    lubricant_density: Q("density", gt=0) = Field(880.0, description=(
        "contact: density of the (base) oil"))
    thickener_factor: Q("dimensionless", gt=0) = Field(1.0, description=(
        "contact: grease film viscosity / base-oil viscosity"))
    asperity_wavelength: Q("length", gt=0) = Field(50e-6, description=(
        "contact: roughness wavelength of the counter surface (rubber frequency u/lambda)"))
    supply_layer: Q("length", gt=0) | None = Field(None, description=(
        "contact: lubricant layer on the counter surface ahead of the seal, the inlet's only "
        "supply (starved: film at most twice this); not given: fully flooded. With a thick "
        "(cold) oil the viscous shear of the capped film can exceed the contact pressure: the "
        "model has no limiting shear stress"))

    def unused_fields(self) -> tuple[str, ...]:
        """Fields the chosen steady curve does not use: the contact's (μ_b, dwell drop and the
        friction-table fields) with ``steady = "lumped"``, f_a, f_b and γ with ``"contact"``.

        >>> ThetaParameters(law="theta", parameter_set="seal_contact").unused_fields()
        ('f_a', 'f_b', 'gamma')
        """
        if self.steady == "contact":
            return LUMPED_ONLY_FIELDS
        return CONTACT_ONLY_FIELDS

    @model_validator(mode="after")
    def _check(self):
        if self.steady == "lumped" and (self.f_a is None or self.f_b is None):
            raise ValueError("the lumped steady curve needs f_a and f_b (or steady = "
                             "'contact': the seal's own contact)")
        if self.steady == "lumped" and self.f_b > self.f_a:
            # f_a is the dry level (Θ = 0, the break-away force after a long dwell), f_b the
            # full-film one: with f_b > f_a the seal would break away below its sliding level
            raise ValueError(f"f_b = {self.f_b:g} is larger than f_a = {self.f_a:g}: f_b (the "
                             "full-film friction coefficient, Theta = 1) must be <= f_a (the "
                             "dry one, Theta = 0, the break-away level after a long dwell)")
        if self.steady == "contact":
            if self.base_oil_nu40 is None:
                raise ValueError("steady = 'contact' needs the lubricant: base_oil_nu40 and "
                                 "base_oil_nu100")
        if (self.base_oil_nu40 is None) != (self.base_oil_nu100 is None):
            raise ValueError("give both base_oil_nu40 and base_oil_nu100 (or neither)")
        if self.base_oil_nu40 is not None and self.base_oil_nu40 <= self.base_oil_nu100:
            raise ValueError(f"base_oil_nu40 ({self.base_oil_nu40 * 1e6:g} mm**2/s) must be "
                             f"larger than base_oil_nu100 ({self.base_oil_nu100 * 1e6:g} "
                             "mm**2/s): an oil thins when it is heated")
        if self.bristle_stiffness is not None and self.steady == "lumped" and (
                self.f_a <= 0 or self.f_b <= 0):
            raise ValueError("with bristle_stiffness the friction coefficients f_a and f_b must "
                             f"be > 0 (the bristles saturate at F_N*f), got f_a = {self.f_a:g}, "
                             f"f_b = {self.f_b:g}")
        if self.bristle_stiffness is None and self.bristle_damping:
            raise ValueError("bristle_damping needs bristle_stiffness")
        return self


class Theta(FrictionLaw):
    """The Θ rate-and-state law of Heipl & Murrenhoff (see the module docstring for the equations).

    States: ``("theta",)``, or ``("theta", "z")`` with bristles (``bristle_stiffness``); with
    ``steady = "contact"`` the film's speed φ [m/s] last (``"film_speed"``).
    Inputs: ``normal_force`` F_N [N] (> 0) and ``contact_width`` b [m] (>= 0).

    Parameters
    ----------
    params : ThetaParameters, optional
        Or keyword arguments (SI): ``tau`` τ [s], ``alpha`` α [m], ``f_a``, ``f_b`` [-],
        ``gamma`` γ [N·s/m²], ``reference_normal_force`` F_ref [N], ``load_exponent`` n [-],
        ``bristle_stiffness`` σ0 [N/m] (optional), ``bristle_damping`` σ1 [N·s/m],
        ``reference_temperature`` T_ref [K], ``base_oil_nu40``, ``base_oil_nu100`` [m²/s].

    Examples
    --------
    >>> law = Theta.from_parameter_set("pneumatic_demo")
    >>> inputs = ContactInputs(normal_force=100.0, contact_width=1e-3)
    >>> law.steady_state([0.05], inputs)
    array([[0.5]])
    >>> law.steady_force([0.05], inputs)
    array([23.])
    >>> law.breakaway_force(np.array([[0.0]]), inputs)
    array([30.])

    The viscous part follows the grease's base oil: at 55 °C γ is about a fifth of its
    25 °C value.

    >>> hot = ContactInputs(normal_force=100.0, contact_width=1e-3, temperature=328.15)
    >>> round(float(law.gamma(hot)), 0)
    1831.0
    """

    name = "theta"

    def __init__(self, params: ThetaParameters | None = None, **values):
        self.params = params if params is not None else validate_parameters(
            ThetaParameters, values, "theta parameters")
        p = self.params
        #: ASTM D341 constants (A, B) of the base oil; (0, 0): γ independent of temperature
        self.walther = (0.0, 0.0)
        if p.base_oil_nu40 is not None:
            from sealsim.properties.oils import walther_constants

            a, b = walther_constants(313.15, p.base_oil_nu40, 373.15, p.base_oil_nu100)
            self.walther = (float(a), float(b))

    @classmethod
    def from_parameter_set(cls, name: str, **overrides):
        return cls(validate_parameters(ThetaParameters, {"parameter_set": name, **overrides},
                                       "theta parameters"))

    @property
    def bristles(self) -> bool:
        """True for the variant with a pre-sliding bristle state."""
        return self.params.bristle_stiffness is not None

    @property
    def contact(self) -> bool:
        """True if the steady curve comes from the seal's contact table."""
        return self.params.steady == "contact"

    @property
    def state_names(self):  # type: ignore[override]
        names = ("theta", "z") if self.bristles else ("theta",)
        return names + ("film_speed",) if self.contact else names

    @property
    def has_stiction(self) -> bool:  # type: ignore[override]
        return not self.bristles

    affine = True

    # -- inputs --------------------------------------------------------------------------
    def _fn(self, inputs: ContactInputs):
        return inputs.require("normal_force", "theta", positive=True)

    def _b(self, inputs: ContactInputs):
        return inputs.require("contact_width", "theta", nonnegative=True)

    def _rate_args(self, inputs):
        p = self.params
        return (p.tau, p.alpha, self._fn(inputs), p.reference_normal_force, p.load_exponent)

    def gamma(self, inputs: ContactInputs = NO_INPUTS):
        """Viscous coefficient γ [N·s/m²] at the contact temperature of ``inputs``
        (:func:`theta_viscous_coefficient`; γ_ref without a temperature or base-oil data)."""
        p = self.params
        if inputs.temperature is None or self.walther[1] == 0.0:
            return p.gamma
        temperature = inputs.require("temperature", "theta", positive=True)
        return theta_viscous_coefficient(temperature, p.gamma, p.reference_temperature,
                                         *self.walther)

    @staticmethod
    def _table_conditions(inputs: ContactInputs):
        """(the seal's friction table, T [K], Δp [Pa]) of ``inputs`` (``steady = "contact"``)."""
        table = inputs.contact_table
        if table is None:
            raise InputError("inputs.contact_table: the theta law with steady = 'contact' needs "
                             "the seal's friction table (sealsim.pneumatic.friction_tables), "
                             "but none was given")
        temperature = inputs.require("temperature", "theta (contact)", positive=True)
        dp = inputs.pressure_difference
        if dp is None:
            dp = np.abs(np.asarray(inputs.pressure_a, float) - np.asarray(inputs.pressure_b,
                                                                           float))
        return table, temperature, dp

    def contact_steady(self, v, inputs: ContactInputs, film=None):
        """(|F_ss(v)| [N], its boundary part π·D·μ_b·L(φ) [N], its viscous part π·D·V(|v|)
        [N]) from the contact table of ``inputs`` (``steady = "contact"``):
        F_ss = π·D·(μ_b·L(φ) + V(|v|)) in the stroke direction of v, the asperity load at the
        speed ``film`` = φ [m/s] the film has formed for (the state ``film_speed``; φ = 0:
        the table's slowest speed; not given: the steady film, φ = |v|).  At rest (v = 0) the
        level F_ss,φ(0⁺) that the film leaves: π·D·μ_b times the larger asperity load of both
        directions at φ (φ not given: at the slowest speed) -- the sliding level's limit
        v → 0±, so breaking away after a short dwell, the film still there, does not drop the
        friction by a step; the larger direction, so sliding from rest never starts with more
        friction than held the seal (with the mean, a pressurised analytic O-ring, whose
        low-pressure inlet is steeper, chattered between stick and slip in its stronger
        direction)."""
        table, temperature, dp = self._table_conditions(inputs)
        diameter = inputs.require("sliding_diameter", "theta (contact)", positive=True)
        orient = np.asarray(inputs.table_orientation, dtype=float)
        mu = self.params.boundary_friction
        speed = orient * np.asarray(v, dtype=float)
        load, viscous, _ = table.evaluate(speed, dp, temperature)
        # the film's speed; below the table's slowest speed (or NaN, as the compiled law) and
        # at rest without a film given: that speed
        formed = table.speed[0] if film is None else np.asarray(film, dtype=float)
        formed = np.where(formed > table.speed[0], formed, table.speed[0])
        formed_up = table.evaluate(formed, dp, temperature)[0]
        formed_down = table.evaluate(-formed, dp, temperature)[0]
        if film is not None:           # the asperities carry the load of the film's speed
            load = np.where(speed > 0.0, formed_up, np.where(speed < 0.0, formed_down, load))
        load = np.where(speed != 0.0, load, np.maximum(formed_up, formed_down))
        viscous = np.where(speed != 0.0, viscous, 0.0)
        circumference = np.pi * diameter
        return (circumference * (mu * load + viscous), circumference * mu * load,
                circumference * viscous)

    def film_decay(self, v, inputs: ContactInputs, film):
        """Decay rate κ [1/s] of the film formed for the speed ``film`` = φ [m/s] (the state
        ``film_speed``) from the seal's friction table (``steady = "contact"``): dφ/dt = −κ·φ
        at rest (Reynolds' squeeze film, :mod:`sealsim.tribology.squeeze_film`; the mean of
        both stroke directions' films, so independent of the sign of v); φ below the table's
        slowest speed (or no film): that speed."""
        table, temperature, dp = self._table_conditions(inputs)
        return np.broadcast_to(table.film_decay(film, dp, temperature),
                               np.broadcast_shapes(np.shape(v), np.shape(film))).copy()

    def level(self, theta, inputs: ContactInputs, v=None, film=None):
        """Friction level [N] without the sign: the break-away force at rest.

        Lumped: g_Θ = F_N·[f_a(1 − Θ) + f_b·Θ] (the viscous γ·b·v comes on top).  Contact:
        |F_ss(v)| + ΔF·(Θ_ss(v) − Θ) with the asperity load of the film's speed ``film``
        (:meth:`contact_steady`), not below the film's viscous part π·D·V(|v|), at rest
        F_ss,φ(0⁺)·(1 − d·Θ) (the boundary friction of the asperity load the film φ leaves:
        the sliding level's limit v → 0±); ΔF = d·π·D·μ_b·L(φ), the dwell drop of the
        boundary part (:func:`~sealsim.friction.kernels.theta_contact_level`).
        """
        p = self.params
        if not self.contact:
            return theta_friction_level(theta, self._fn(inputs), p.f_a, p.f_b)
        v = np.zeros(np.shape(theta)) if v is None else np.asarray(v, dtype=float)
        steady, boundary, viscous = self.contact_steady(v, inputs, film)
        theta_ss = theta_steady(v, *self._rate_args(inputs))
        return apply(_k._loop_theta_contact_level, theta, v, steady, boundary, p.dwell_drop,
                     theta_ss, viscous)

    def relaxed_storage(self, z):
        z = np.asarray(z, dtype=float)
        if not self.bristles:
            return np.zeros(z.shape[-1])
        return 0.5 * self.params.bristle_stiffness * z[1] ** 2

    def initial_state(self, n: int = 1):
        """Dry, relaxed contacts (Θ = 0 after a long rest; z = 0; no film, φ = 0)."""
        return np.zeros((self.n_states, n))

    def _viscous(self, v, inputs):
        """γ·b·v of the lumped law [N]; 0 in contact mode (the table holds the viscous part)."""
        if self.contact:
            return 0.0 * np.asarray(v, dtype=float)
        return self.gamma(inputs) * self._b(inputs) * v

    # -- interface -----------------------------------------------------------------------
    def _film(self, z):
        """The film's speed φ [m/s] of states z (the last state), None for the lumped law."""
        return z[-1] if self.contact else None

    def _film_rate(self, z, v, inputs):
        return apply(_k._loop_film_speed_rate, z[-1], v, self._b(inputs),
                     self.film_decay(v, inputs, z[-1]))

    def derivatives(self, z, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        rates = [theta_rate(z[0], v, *self._rate_args(inputs))]
        if self.bristles:
            rates.append(lugre_bristle_rate(z[1], v, self.params.bristle_stiffness,
                                            self.level(z[0], inputs, v, self._film(z))))
        if self.contact:
            rates.append(self._film_rate(z, v, inputs))
        return np.stack(np.broadcast_arrays(*rates))

    def force(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        if not self.bristles:
            if self.contact:
                return self.level(z[0], inputs, v, z[1]) * np.sign(v)
            return theta_force(z[0], v, self._fn(inputs), self._b(inputs), p.f_a, p.f_b,
                               self.gamma(inputs))
        zdot = lugre_bristle_rate(z[1], v, p.bristle_stiffness,
                                  self.level(z[0], inputs, v, self._film(z)))
        return (p.bristle_stiffness * z[1] + p.bristle_damping * zdot
                + self._viscous(v, inputs))

    def partials(self, z, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        fn = self._fn(inputs)
        load = _load_factor(fn, p.reference_normal_force, p.load_exponent)
        r = np.abs(v) / (p.alpha * load)
        shape = np.broadcast_shapes(v.shape, z.shape[1:], np.shape(fn))
        n = self.n_states
        jac = np.zeros((n, n) + shape)
        dzdv = np.zeros((n,) + shape)
        dfdz = np.zeros((n,) + shape)
        jac[0, 0] = -1.0 / p.tau - r
        dzdv[0] = np.sign(v) / (p.alpha * load) * (1.0 - z[0])
        film = self._film(z)
        if self.contact:
            # ∂g/∂Θ = −ΔF (0 where the level rests on the film's viscous part); ∂g/∂v (film
            # held) and ∂g/∂φ by central differences of the tabulated curve
            steady, boundary, viscous = self.contact_steady(v, inputs, film)
            theta_ss = theta_steady(v, *self._rate_args(inputs))
            free = np.where(v != 0.0, steady + p.dwell_drop * boundary * (theta_ss - z[0])
                            > np.maximum(viscous, 1e-9), True)
            dlevel = np.where(free, -p.dwell_drop * boundary, 0.0)
            h = 1e-6 * np.maximum(np.abs(v), 1e-6)
            dg_dv = (self.level(z[0], inputs, v + h, film)
                     - self.level(z[0], inputs, v - h, film)) / (2 * h)
            viscous_dv = np.broadcast_to(np.where(v != 0.0, dg_dv * np.sign(v), 0.0), shape)
            hf = 1e-6 * np.maximum(film, 1e-6)
            dg_df = (self.level(z[0], inputs, v, film + hf)
                     - self.level(z[0], inputs, v, np.maximum(film - hf, 0.0))) / (
                         film + hf - np.maximum(film - hf, 0.0))
            # the film's speed: dφ/dt = (|v| − φ)·(|v|/b + κ(φ)), κ's slope by central
            # differences of the table
            length = np.maximum(self._b(inputs), _k.FILM_MIN_LENGTH)
            rate = np.abs(v) / length + self.film_decay(v, inputs, film)
            low = np.maximum(film - hf, 0.0)
            dk_df = (self.film_decay(v, inputs, film + hf)
                     - self.film_decay(v, inputs, low)) / (film + hf - low)
            jac[-1, -1] = -rate + (np.abs(v) - film) * dk_df
            dzdv[-1] = np.sign(v) * (rate + (np.abs(v) - film) / length)
        else:
            dlevel = fn * (p.f_b - p.f_a)                       # ∂g_Θ/∂Θ
            dg_df = 0.0
            viscous_dv = np.broadcast_to(self.gamma(inputs) * self._b(inputs), shape)
        if not self.bristles:
            dfdz[0] = dlevel * np.sign(v)
            if self.contact:
                dfdz[-1] = dg_df * np.sign(v)
            return Partials(jac, dzdv, dfdz, np.array(viscous_dv, dtype=float))
        s0, s1 = p.bristle_stiffness, p.bristle_damping
        g = self.level(z[0], inputs, v, film)
        d_zt = s0 * np.abs(v) * z[1] * dlevel / g ** 2
        d_zz = -s0 * np.abs(v) / g
        d_zv = 1.0 - s0 * np.sign(v) * z[1] / g
        if self.contact:       # the level moves with v and φ, and with it the bristles' target
            d_zv = d_zv + s0 * np.abs(v) * z[1] / g ** 2 * viscous_dv * np.sign(v)
            jac[1, -1] = s0 * np.abs(v) * z[1] * dg_df / g ** 2
            dfdz[-1] = s1 * jac[1, -1]
            viscous_dv = np.zeros(shape)
        jac[1, 0] = d_zt
        jac[1, 1] = d_zz
        dzdv[1] = d_zv
        dfdz[0] = s1 * d_zt
        dfdz[1] = s0 + s1 * d_zz
        return Partials(jac, dzdv, dfdz, np.broadcast_to(s1 * d_zv + viscous_dv, shape).copy())

    def _film_step(self, z_film, v, dt, inputs):
        """φ after dt [s], exact for v, b and the film's decay rate κ held (κ frozen at the
        step's start, as the compiled ``law_step``)."""
        a, c = apply(_k._loop_film_speed_affine, v, dt, self._b(inputs),
                     self.film_decay(v, inputs, z_film), outputs=2)
        return a * z_film + c

    def step(self, z, v, dt, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        z = as_state(z, self.n_states)
        new = [theta_step(z[0], v, dt, *self._rate_args(inputs))]
        film_mid = None
        if self.contact:
            film1 = self._film_step(z[-1], v, dt, inputs)
            film_mid = 0.5 * (z[-1] + film1)
        if self.bristles:
            g_mid = self.level(0.5 * (z[0] + new[0]), inputs, v, film_mid)
            a, b = _lugre_affine(v, dt, self.params.bristle_stiffness, g_mid)
            new.append(a * z[1] + b)
        if self.contact:
            new.append(film1)
        return np.stack(np.broadcast_arrays(*new))

    def _film_trajectory(self, z0_film, v, dt, inputs):
        """φ over the steps (shape (N + 1, n)), as :meth:`_film_step` one step after the
        other (:func:`sealsim.friction.compiled.film_trajectory`: its decay rate depends on
        φ, so no affine scan)."""
        from sealsim.friction.compiled import film_trajectory

        table, temperature, dp = self._table_conditions(inputs)
        shape = np.broadcast_shapes(v.shape, np.shape(z0_film)[-1:])
        temperature, dp, v, width = (
            np.ascontiguousarray(np.broadcast_to(np.asarray(x, dtype=float), shape))
            for x in (temperature, dp, v, self._b(inputs)))
        out = np.empty((shape[0] + 1, shape[1]))
        film0 = np.ascontiguousarray(np.broadcast_to(np.asarray(z0_film, dtype=float),
                                                     shape[1:]))
        film_trajectory(*table.tables(), temperature, dp, v,
                        np.ascontiguousarray(dt, dtype=float), width, film0, out)
        return out

    def _affine_trajectory(self, z0, v, dt, inputs):
        a, b = _theta_affine(v, dt[:, None], *self._rate_args(inputs))
        theta = affine_scan(a, b, z0[0])
        states = [theta]
        film = film_mid = None
        if self.contact:
            film = self._film_trajectory(z0[-1], v, dt, inputs)
            film_mid = 0.5 * (film[:-1] + film[1:])
        if self.bristles:
            g_mid = self.level(0.5 * (theta[:-1] + theta[1:]), inputs, v, film_mid)
            a_z, b_z = _lugre_affine(v, dt[:, None], self.params.bristle_stiffness, g_mid)
            states.append(affine_scan(a_z, b_z, z0[1]))
        if self.contact:
            states.append(film)
        return np.stack(np.broadcast_arrays(*states), axis=1)

    def steady_state(self, v, inputs: ContactInputs = NO_INPUTS):
        v = as_velocity(v)
        theta = theta_steady(v, *self._rate_args(inputs))
        states = [theta]
        if self.bristles:
            states.append(np.sign(v) * self.level(theta, inputs, v) / self.params.bristle_stiffness)
        if self.contact:
            states.append(np.abs(v))
        return np.atleast_2d(np.stack(np.broadcast_arrays(*states)))

    def steady_force(self, v, inputs: ContactInputs = NO_INPUTS):
        p = self.params
        v = as_velocity(v)
        if self.contact:
            steady, _, _ = self.contact_steady(v, inputs)
            return steady * np.sign(v)
        return theta_steady_force(v, self._fn(inputs), self._b(inputs), p.tau,
                                  p.alpha, p.f_a, p.f_b, self.gamma(inputs),
                                  p.reference_normal_force, p.load_exponent)

    def breakaway_force(self, z, inputs: ContactInputs = NO_INPUTS):
        z = as_state(z, self.n_states)
        return self.level(z[0], inputs, film=self._film(z))
