r"""Compiled scalar kernels of the friction laws: the one implementation of each law.

Every law of :mod:`sealsim.friction` is computed by the small scalar functions below, compiled
with numba (``njit``, ``cache=True``, IEEE arithmetic: no fastmath, numpy error model, so a
division by zero gives ``inf`` as in C).  They are used three ways:

* by the vectorised public functions of the law modules (``theta_rate``, ``lugre_force``, ...)
  through the array loops at the end of this module -- and so by the law classes;
* directly by the compiled right-hand side of the pneumatic cylinder
  (:mod:`sealsim.pneumatic.rhs`);
* as the reference that C ports (FMU export) are tested against: each kernel takes and returns
  plain doubles in the argument order documented here, SI units, and is a few lines long.

Conventions (all kernels): v is the sliding velocity [m/s] of the body relative to the seal,
the friction force F [N] opposes it (power dissipated F·v >= 0 when sliding);
sgn(0) = 0 (:func:`sgn`).  Parameters that a kernel does not check (e.g. τ > 0) are validated
by the parameter models of the law modules.

Kernels and their equations (H&M: Heipl & Murrenhoff [1]_)
------------------------------------------------------------
=================================================  ===============================================
kernel (arguments)                                 returns
=================================================  ===============================================
``sgn(x)``                                         +1, −1 or 0
``power(x, e)``                                    x^e (exact products for e = 2, 1, 0)
``pressure_scaled_force(f0, f, pa, pb)``           F_pr + f·(p_A + p_B)              (H&M Eq. 3)
``stribeck_scaled_levels(fc, fs, f, pa, pb)``      (F_C(p), F_S(p)), F_S(p) = F_S·F_C(p)/F_C
``stribeck_level(v, fc, fs, vs, d)``               g = F_C + (F_S − F_C)·exp(−|v/v_S|^δ)
``stribeck_level_derivative(v, fc, fs, vs, d)``    dg/dv
``stribeck_force(v, fc, fs, vs, fv, d)``           g(v)·sgn(v) + F_v·v             (H&M Eq. 2)
``coulomb_viscous_force(v, fc, fv)``               F_C·sgn(v) + F_v·v
``lugre_bristle_rate(z, v, s0, g)``                dz/dt = v − σ0·|v|·z/g     (Canudas 1995 Eq. 1)
``lugre_force(z, zdot, v, s0, s1, s2)``            σ0·z + σ1·ż + σ2·v          (Canudas 1995 Eq. 4)
``lugre_affine(v, dt, s0, g)``                     (a, b): z(t+dt) = a·z + b, exact for constant v
``dahl_bristle_rate(z, v, s0, fc, a)``             v·max(1 − σ0·z·sgn(v)/F_C, 0)^α   (Dahl 1968)
``dahl_bristle_step(z, v, dt, s0, fc, a)``         z(t+dt), exact for constant v
``gms_element_rate(z, v, k, frac, c, s)``          dz_i/dt of one GMS element (Al-Bender 2005)
``gms_element_step(z, v, dt, k, frac, c, s)``      z_i(t+dt), exact for constant v
``theta_load_factor(fn, fref, n)``                 (F_N/F_ref)^n
``theta_rate(th, v, tau, al, fn, fref, n)``        dΘ/dt = −Θ/τ + |v|/α·(F_ref/F_N)^n·(1 − Θ)
``theta_transition_velocity(tau, al, fn, ...)``    v* = α/τ·(F_N/F_ref)^n
``theta_steady(v, tau, al, fn, fref, n)``          Θ_ss = |v|/(|v| + v*)
``theta_affine(v, dt, tau, al, fn, fref, n)``      (a, b): Θ(t+dt) = a·Θ + b, exact for constant v
``theta_friction_level(th, fn, fa, fb)``           g_Θ = F_N·[f_a·(1 − Θ) + f_b·Θ]   (H&M Eq. 5)
``theta_force(th, v, fn, b, fa, fb, gamma)``       g_Θ·sgn(v) + γ·b·v                (H&M Eq. 5)
``theta_contact_level(th, v, fss, ...)``           level of the Θ law on a contact table:
                                                   max(fss + d·fb·(Θ_ss − Θ), fv), at rest
                                                   fss − d·fb·Θ
``film_speed_rate(phi, v, b, decay)``              dφ/dt = (|v| − φ)·(|v|/b + κ): the speed
                                                   the contact's film has formed for
``film_speed_affine(v, dt, b, decay)``             (a, c): φ(t+dt) = a·φ + c, exact for constant
                                                   v and κ
``walther_viscosity(t, wa, wb)``                   ν(T) [mm²/s], ASTM D341 (Walther)
``walther_viscosity_ratio(t, tref, wa, wb)``       ν(T)/ν(T_ref), ASTM D341 (Walther)
=================================================  ===============================================

References
----------
.. [1] O. Heipl, H. Murrenhoff, "Rate- and state-dependent friction model for elastomeric
   seals", Eq. 2-5 (Stribeck, pressure scaling, Θ law as reconstructed in
   :mod:`sealsim.friction.theta`).
.. [2] C. Canudas de Wit, H. Olsson, K. J. Åström, P. Lischinsky, IEEE TAC 40(3), 419-425, 1995.
.. [3] P. R. Dahl, "A solid friction model", Aerospace Corp. TOR-0158(3107-18)-1, 1968.
.. [4] F. Al-Bender, V. Lampaert, J. Swevers, IEEE TAC 50(11), 1883-1887, 2005.
.. [5] ASTM D341-20, viscosity-temperature equations (Ubbelohde-Walther).
.. [6] J. Sugimura, W. R. Jones, H. A. Spikes, "EHD film thickness in non-steady state
   contacts", J. Tribol. 120(3), 442-452, 1998; J. Sugimura, T. Okumura, Y. Yamamoto,
   H. A. Spikes, "Simple equation for elastohydrodynamic film thickness under acceleration",
   Tribol. Int. 32(2), 117-123, 1999 (the film formed at the inlet moves through the contact
   with little change: the film is the one of the entrainment speed of the time its fluid
   entered the inlet, a delay of the contact's transit time; hard EHD contacts).
.. [7] O. Reynolds, Phil. Trans. R. Soc. Lond. 177 (1886) 157-234; B. J. Hamrock,
   S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed., 2004
   (squeeze film between parallel surfaces).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import overload

__all__ = ["apply"]

#: compile options of every kernel: cached on disk, IEEE results (division by zero -> inf)
_OPTIONS = {"cache": True, "error_model": "numpy"}
kernel = njit(**_OPTIONS)


# --------------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------------
@kernel
def sgn(x):
    """sgn(x): +1.0 for x > 0, −1.0 for x < 0, 0.0 at 0 (numpy's ``sign``)."""
    if x > 0.0:
        return 1.0
    if x < 0.0:
        return -1.0
    return 0.0 * x          # 0.0 (nan stays nan)


@kernel
def power(x, e):
    """x**e [-] with the exact products for e = 2, 1 and 0 (what numpy's ``array ** 2.0``
    computes): no call to the C library's ``pow`` for the exponents the laws use by default."""
    if e == 2.0:
        return x * x
    if e == 1.0:
        return x
    if e == 0.0:
        return 1.0
    return x ** e


# --------------------------------------------------------------------------------------------
# Coulomb, Stribeck (Heipl & Murrenhoff Eq. 2/3)
# --------------------------------------------------------------------------------------------
@kernel
def pressure_scaled_force(f0, f, pa, pb):
    """F_C(p) = F_pr + f·(p_A + p_B) [N]: f0 = F_pr [N], f [m²], pa, pb gauge [Pa]."""
    return f0 + f * (pa + pb)


@kernel
def stribeck_scaled_levels(fc, fs, f, pa, pb):
    """(F_C(p), F_S(p)) [N] of the Stribeck law with pressure scaling.

    F_C(p) = F_C + f·(p_A + p_B); F_S(p) = F_S·F_C(p)/F_C (constant break-away ratio, as
    Simscape's Cylinder Friction), or F_S + (F_C(p) − F_C) when F_C = 0.
    Arguments: fc = F_C, fs = F_S [N], f [m²], pa, pb [Pa].
    """
    fcp = pressure_scaled_force(fc, f, pa, pb)
    if fc > 0.0:
        return fcp, fs * fcp / fc
    return fcp, fs + (fcp - fc)


@kernel
def stribeck_level(v, fc, fs, vs, d):
    """g(v) = F_C + (F_S − F_C)·exp(−|v/v_S|^δ) [N]: v [m/s], fc, fs [N], vs [m/s], d = δ."""
    ratio = abs(v / vs)
    return fc + (fs - fc) * math.exp(-power(ratio, d))


@kernel
def stribeck_level_derivative(v, fc, fs, vs, d):
    """dg/dv = −(F_S − F_C)·δ·|v/v_S|^(δ−1)·exp(−|v/v_S|^δ)·sgn(v)/v_S [N·s/m].

    At v = 0 the power |v/v_S|^(δ−1) is taken as 1 for δ = 1 and 0 otherwise."""
    ratio = abs(v / vs)
    if ratio > 0.0:
        slope = power(ratio, d - 1.0)
    elif d == 1.0:
        slope = 1.0
    else:
        slope = 0.0
    return -(fs - fc) * d * slope * math.exp(-power(ratio, d)) * sgn(v) / vs


@kernel
def stribeck_force(v, fc, fs, vs, fv, d):
    """F = g(v)·sgn(v) + F_v·v [N] (0 at v = 0: sticking is resolved outside)."""
    return stribeck_level(v, fc, fs, vs, d) * sgn(v) + fv * v


@kernel
def coulomb_viscous_force(v, fc, fv):
    """F = F_C·sgn(v) + F_v·v [N]: fc = F_C [N], fv = F_v [N·s/m]."""
    return fc * sgn(v) + fv * v


# --------------------------------------------------------------------------------------------
# LuGre (Canudas de Wit et al. 1995)
# --------------------------------------------------------------------------------------------
@kernel
def lugre_bristle_rate(z, v, s0, g):
    """dz/dt = v − σ0·|v|·z/g [m/s]: z [m], v [m/s], s0 = σ0 [N/m], g = g(v) [N]."""
    return v - s0 * abs(v) * z / g


@kernel
def lugre_force(z, zdot, v, s0, s1, s2):
    """F = σ0·z + σ1·dz/dt + σ2·v [N]: s0 [N/m], s1, s2 [N·s/m]."""
    return s0 * z + s1 * zdot + s2 * v


@kernel
def lugre_affine(v, dt, s0, g):
    """(a, b) with z(t + dt) = a·z(t) + b for v held over dt [s] (exact solution of Eq. 1).

    a = exp(−σ0·|v|·dt/g) (computed as 1 − d, d = −expm1(·)), b = sgn(v)·g/σ0·d."""
    decay = -math.expm1(-s0 * abs(v) * dt / g)
    return 1.0 - decay, sgn(v) * g / s0 * decay


# --------------------------------------------------------------------------------------------
# Dahl (1968)
# --------------------------------------------------------------------------------------------
@kernel
def dahl_bristle_rate(z, v, s0, fc, a):
    """dz/dt = v·u^α, u = max(1 − σ0·z·sgn(v)/F_C, 0): s0 [N/m], fc [N], a = α [-]."""
    u = 1.0 - s0 * z * sgn(v) / fc
    if u < 0.0:
        u = 0.0
    return v * power(u, a)


@kernel
def dahl_bristle_step(z, v, dt, s0, fc, a):
    """Dahl deflection after dt with v held (exact): u1 = u0·exp(−k) for α = 1, else
    u1 = max(u0^(1−α) − (1−α)·k, 0)^(1/(1−α)), k = σ0·|v|·dt/F_C; z1 = (1 − u1)·F_C·sgn(v)/σ0."""
    if v == 0.0:
        return z
    u0 = 1.0 - s0 * z * sgn(v) / fc
    if u0 < 0.0:
        u0 = 0.0
    k = s0 * (abs(v) * dt) / fc
    if a == 1.0:
        u1 = u0 * math.exp(-k)
    elif u0 > 0.0:
        one_minus = 1.0 - a
        base = u0 ** one_minus - one_minus * k
        u1 = (base if base > 0.0 else 0.0) ** (1.0 / one_minus)
    else:
        u1 = 0.0
    return (1.0 - u1) * fc * sgn(v) / s0


# --------------------------------------------------------------------------------------------
# GMS (Al-Bender, Lampaert, Swevers 2005), one element
# --------------------------------------------------------------------------------------------
@kernel
def gms_element_rate(z, v, k, frac, c, s):
    """dz_i/dt of a GMS element: v while it sticks (k·z·sgn(v) < α_i·s), else
    C/k·(α_i·sgn(v) − k·z/s).  z [m], k [N/m], frac = α_i [-], c = C [N/s], s = s(v) [N]."""
    force = k * z
    sv = sgn(v)
    if force * sv < frac * s:
        return v
    return c / k * (frac * sv - force / s)


@kernel
def gms_element_step(z, v, dt, k, frac, c, s):
    """GMS element deflection after dt with v held (exact): a sticking element moves
    elastically, capped at its limit α_i·s; a slipping one relaxes to it at rate C/s."""
    force = k * z
    if v == 0.0:
        return force / k
    sv = sgn(v)
    limit = frac * s
    if force * sv < limit:
        new = force + k * v * dt
        if new * sv > limit:
            new = limit * sv
    else:
        target = limit * sv
        new = target + (force - target) * math.exp(-c * dt / s)
    return new / k


# --------------------------------------------------------------------------------------------
# Θ rate-and-state law (Heipl & Murrenhoff Eq. 4/5 as reconstructed in sealsim.friction.theta)
# --------------------------------------------------------------------------------------------
@kernel
def theta_load_factor(fn, fref, n):
    """(F_N/F_ref)^n [-]: fn, fref [N], n [-]."""
    return power(fn / fref, n)


@kernel
def theta_rate(th, v, tau, al, fn, fref, n):
    """dΘ/dt = −Θ/τ + |v|/(α·(F_N/F_ref)^n)·(1 − Θ) [1/s]: tau [s], al = α [m], fn [N]."""
    p = theta_load_factor(fn, fref, n)
    return -th / tau + abs(v) / (al * p) * (1.0 - th)


@kernel
def theta_transition_velocity(tau, al, fn, fref, n):
    """v* = α/τ·(F_N/F_ref)^n [m/s] (Θ_ss(v*) = 1/2)."""
    return al / tau * theta_load_factor(fn, fref, n)


@kernel
def theta_steady(v, tau, al, fn, fref, n):
    """Θ_ss = |v|/(|v| + v*) [-] (0 at rest)."""
    speed = abs(v)
    if speed > 0.0:
        return speed / (speed + theta_transition_velocity(tau, al, fn, fref, n))
    return 0.0


@kernel
def theta_affine(v, dt, tau, al, fn, fref, n):
    """(a, b) with Θ(t + dt) = a·Θ(t) + b for v and F_N held over dt [s] (exact):
    a = exp(−(1/τ + r)·dt), b = Θ_ss·(1 − a), r = |v|/(α·(F_N/F_ref)^n) (inf for F_N = 0)."""
    speed = abs(v)
    p = theta_load_factor(fn, fref, n)
    if speed > 0.0:
        r = speed / (al * p) if p > 0.0 else math.inf
    else:
        r = 0.0
    decay = -math.expm1(-(1.0 / tau + r) * dt)
    return 1.0 - decay, theta_steady(v, tau, al, fn, fref, n) * decay


@kernel
def theta_friction_level(th, fn, fa, fb):
    """g_Θ = F_N·[f_a·(1 − Θ) + f_b·Θ] [N]: the sliding force without the viscous part and
    the break-away force at rest."""
    return fn * (fa * (1.0 - th) + fb * th)


@kernel
def theta_force(th, v, fn, b, fa, fb, gamma):
    """F = g_Θ·sgn(v) + γ·b·v [N]: b [m], gamma = γ [N·s/m²] (0 at v = 0)."""
    return theta_friction_level(th, fn, fa, fb) * sgn(v) + gamma * b * v


@kernel
def theta_contact_level(th, v, fss, fb, d, thss, fv):
    """Friction level [N] of the Θ law whose steady curve is a contact table
    (:mod:`sealsim.friction.theta`, ``steady = "contact"``): |F_ss(v)| + ΔF·(Θ_ss − Θ) while
    sliding, but not below the film's viscous shear fv, F_ss,φ(0⁺)·(1 − d·Θ) at rest;
    ΔF = d·fb, the dwell drop d [-] of the boundary part fb = π·D·μ_b·L(φ) [N] of the level
    (the asperity load L at the speed φ the film has formed for): Θ scales the boundary
    friction of the asperities, the film φ sets the load they carry.  fss = |F_ss(v)| [N], at
    rest (v = 0) F_ss,φ(0⁺) = fb, the boundary level the film leaves (the sliding level's
    limit v → 0±); fv = π·D·V(|v|) the viscous part of fss [N]; thss = Θ_ss(v)
    (:func:`sealsim.friction.compiled.contact_steady`); at least 1e-9 N.  Θ above Θ_ss
    (while the speed falls) lowers the asperities' friction by at most the fraction d, so a
    quick reversal keeps (1 − d) of the boundary friction at the film it carries."""
    drop = d * fb
    floor = 1e-9
    if v != 0.0:
        level = fss + drop * (thss - th)
        floor = fv if fv > floor else floor
    else:
        level = fss - drop * th
    return level if level > floor else floor


#: shortest length [m] over which a contact's film follows the sliding speed: a contact
#: narrower than 1 µm (lost contact, b = 0) lets the film follow at once instead of dividing by 0
FILM_MIN_LENGTH = 1e-6


@kernel
def film_speed_rate(phi, v, b, decay):
    """dφ/dt = (|v| − φ)·(|v|/b + κ) [m/s²]: the speed φ [m/s] that the contact's film has
    formed for follows the sliding speed |v| [m/s] over a sliding distance of the contact width
    b [m] (at least :data:`FILM_MIN_LENGTH`; the fluid at the contact's pressure maximum
    entered its inlet one contact width earlier, Sugimura et al. 1998, 1999 [6]_: a
    first-order lag over that distance is sealsim's simplest form of their delay) and, at rest,
    falls as the seal squeezes the film out: dφ/dt = −κ·φ with the decay rate κ [1/s] of the
    film formed for φ (Reynolds' squeeze film, :mod:`sealsim.tribology.squeeze_film` [7]_; read
    from the seal's friction table at φ).  κ also speeds the film's return to the steady one
    while sliding (the squeeze flow of a film thicker than the inlet makes, less of one that
    is thinner: the linearised transient Reynolds equation).  Steady: φ = |v|."""
    speed = abs(v)
    return (speed - phi) * (speed / max(b, FILM_MIN_LENGTH) + decay)


@kernel
def film_speed_affine(v, dt, b, decay):
    """(a, c) with φ(t + dt) = a·φ(t) + c for v, b and the decay rate κ [1/s] held over
    dt [s] (exact solution of :func:`film_speed_rate` with κ frozen, e.g. at the step's start):
    a = exp(−(|v|/b + κ)·dt), c = |v|·(1 − a)."""
    speed = abs(v)
    rate = -math.expm1(-(speed / max(b, FILM_MIN_LENGTH) + decay) * dt)
    return 1.0 - rate, speed * rate


@kernel
def walther_viscosity(t, wa, wb):
    """ν(T) [mm²/s] with the ASTM D341 (Walther) equation log10 log10(ν + 0.7) = A − B·log10 T
    (T in K): wa = A, wb = B.

    The same equation as :func:`sealsim.properties.oils.walther_viscosity` (which returns
    m²/s; a test checks that they agree), in scalar compiled form."""
    return 10.0 ** (10.0 ** (wa - wb * math.log10(t))) - 0.7


@kernel
def walther_viscosity_ratio(t, tref, wa, wb):
    """ν(T)/ν(T_ref) [-] with the ASTM D341 (Walther) equation (:func:`walther_viscosity`),
    for the Θ law's viscous coefficient γ(T)."""
    return walther_viscosity(t, wa, wb) / walther_viscosity(tref, wa, wb)


# --------------------------------------------------------------------------------------------
# Array loops: the vectorised numpy API of the law modules runs the kernels through these.
# Every argument is a contiguous 1-D float array of length n or a float (a broadcast scalar,
# see :func:`apply`): numba compiles a loop once per combination, so the loop body indexes
# only the arrays, has no branch on the argument shapes and vectorises (SIMD) where the kernel
# has no call into the C library.  The loops are serial on purpose: on the shared 2-core
# machine a ``prange`` version was 2x slower than the serial one whenever another process
# held a core (the slower thread sets the pace).
# --------------------------------------------------------------------------------------------
def _at(a, i):  # pragma: no cover - compiled through the overload below
    return a[i]


@overload(_at, inline="always")
def _overload_at(a, i):
    if isinstance(a, types.Array):
        return lambda a, i: a[i]
    return lambda a, i: a


@kernel
def _loop_pressure_scaled_force(f0, f, pa, pb, out):
    for i in range(out.shape[0]):
        out[i] = pressure_scaled_force(_at(f0, i), _at(f, i), _at(pa, i), _at(pb, i))


@kernel
def _loop_stribeck_scaled_levels(fc, fs, f, pa, pb, out, out2):
    for i in range(out.shape[0]):
        out[i], out2[i] = stribeck_scaled_levels(_at(fc, i), _at(fs, i), _at(f, i),
                                                 _at(pa, i), _at(pb, i))


@kernel
def _loop_stribeck_level(v, fc, fs, vs, d, out):
    for i in range(out.shape[0]):
        out[i] = stribeck_level(_at(v, i), _at(fc, i), _at(fs, i), _at(vs, i), _at(d, i))


@kernel
def _loop_stribeck_level_derivative(v, fc, fs, vs, d, out):
    for i in range(out.shape[0]):
        out[i] = stribeck_level_derivative(_at(v, i), _at(fc, i), _at(fs, i), _at(vs, i),
                                           _at(d, i))


@kernel
def _loop_stribeck_force(v, fc, fs, vs, fv, d, out):
    for i in range(out.shape[0]):
        out[i] = stribeck_force(_at(v, i), _at(fc, i), _at(fs, i), _at(vs, i), _at(fv, i),
                                _at(d, i))


@kernel
def _loop_coulomb_viscous_force(v, fc, fv, out):
    for i in range(out.shape[0]):
        out[i] = coulomb_viscous_force(_at(v, i), _at(fc, i), _at(fv, i))


@kernel
def _loop_lugre_bristle_rate(z, v, s0, g, out):
    for i in range(out.shape[0]):
        out[i] = lugre_bristle_rate(_at(z, i), _at(v, i), _at(s0, i), _at(g, i))


@kernel
def _loop_lugre_force(z, zdot, v, s0, s1, s2, out):
    for i in range(out.shape[0]):
        out[i] = lugre_force(_at(z, i), _at(zdot, i), _at(v, i), _at(s0, i), _at(s1, i),
                             _at(s2, i))


@kernel
def _loop_lugre_rate(z, v, s0, fc, fs, vs, d, out):
    """dz/dt of LuGre with g(v) of its Stribeck curve (one pass: LuGre.derivatives)."""
    for i in range(out.shape[0]):
        vi = _at(v, i)
        g = stribeck_level(vi, _at(fc, i), _at(fs, i), _at(vs, i), _at(d, i))
        out[i] = lugre_bristle_rate(_at(z, i), vi, _at(s0, i), g)


@kernel
def _loop_lugre_state_force(z, v, s0, s1, s2, fc, fs, vs, d, out):
    """F of LuGre from the state and v (one pass: LuGre.force)."""
    for i in range(out.shape[0]):
        vi = _at(v, i)
        zi = _at(z, i)
        g = stribeck_level(vi, _at(fc, i), _at(fs, i), _at(vs, i), _at(d, i))
        zdot = lugre_bristle_rate(zi, vi, _at(s0, i), g)
        out[i] = lugre_force(zi, zdot, vi, _at(s0, i), _at(s1, i), _at(s2, i))


@kernel
def _loop_lugre_affine(v, dt, s0, g, out, out2):
    for i in range(out.shape[0]):
        out[i], out2[i] = lugre_affine(_at(v, i), _at(dt, i), _at(s0, i), _at(g, i))


@kernel
def _loop_dahl_bristle_rate(z, v, s0, fc, a, out):
    for i in range(out.shape[0]):
        out[i] = dahl_bristle_rate(_at(z, i), _at(v, i), _at(s0, i), _at(fc, i), _at(a, i))


@kernel
def _loop_dahl_bristle_step(z, v, dt, s0, fc, a, out):
    for i in range(out.shape[0]):
        out[i] = dahl_bristle_step(_at(z, i), _at(v, i), _at(dt, i), _at(s0, i), _at(fc, i),
                                   _at(a, i))


@kernel
def _loop_gms_element_rate(z, v, k, frac, c, s, out):
    for i in range(out.shape[0]):
        out[i] = gms_element_rate(_at(z, i), _at(v, i), _at(k, i), _at(frac, i), _at(c, i),
                                  _at(s, i))


@kernel
def _loop_gms_element_step(z, v, dt, k, frac, c, s, out):
    for i in range(out.shape[0]):
        out[i] = gms_element_step(_at(z, i), _at(v, i), _at(dt, i), _at(k, i), _at(frac, i),
                                  _at(c, i), _at(s, i))


@kernel
def _loop_theta_load_factor(fn, fref, n, out):
    for i in range(out.shape[0]):
        out[i] = theta_load_factor(_at(fn, i), _at(fref, i), _at(n, i))


@kernel
def _loop_theta_rate(th, v, tau, al, fn, fref, n, out):
    for i in range(out.shape[0]):
        out[i] = theta_rate(_at(th, i), _at(v, i), _at(tau, i), _at(al, i), _at(fn, i),
                            _at(fref, i), _at(n, i))


@kernel
def _loop_theta_transition_velocity(tau, al, fn, fref, n, out):
    for i in range(out.shape[0]):
        out[i] = theta_transition_velocity(_at(tau, i), _at(al, i), _at(fn, i), _at(fref, i),
                                           _at(n, i))


@kernel
def _loop_theta_steady(v, tau, al, fn, fref, n, out):
    for i in range(out.shape[0]):
        out[i] = theta_steady(_at(v, i), _at(tau, i), _at(al, i), _at(fn, i), _at(fref, i),
                              _at(n, i))


@kernel
def _loop_theta_affine(v, dt, tau, al, fn, fref, n, out, out2):
    for i in range(out.shape[0]):
        out[i], out2[i] = theta_affine(_at(v, i), _at(dt, i), _at(tau, i), _at(al, i),
                                       _at(fn, i), _at(fref, i), _at(n, i))


@kernel
def _loop_theta_friction_level(th, fn, fa, fb, out):
    for i in range(out.shape[0]):
        out[i] = theta_friction_level(_at(th, i), _at(fn, i), _at(fa, i), _at(fb, i))


@kernel
def _loop_theta_force(th, v, fn, b, fa, fb, gamma, out):
    for i in range(out.shape[0]):
        out[i] = theta_force(_at(th, i), _at(v, i), _at(fn, i), _at(b, i), _at(fa, i),
                             _at(fb, i), _at(gamma, i))


@kernel
def _loop_theta_contact_level(th, v, fss, fb, d, thss, fv, out):
    for i in range(out.shape[0]):
        out[i] = theta_contact_level(_at(th, i), _at(v, i), _at(fss, i), _at(fb, i), _at(d, i),
                                     _at(thss, i), _at(fv, i))


@kernel
def _loop_film_speed_rate(phi, v, b, decay, out):
    for i in range(out.shape[0]):
        out[i] = film_speed_rate(_at(phi, i), _at(v, i), _at(b, i), _at(decay, i))


@kernel
def _loop_film_speed_affine(v, dt, b, decay, a, c):
    for i in range(a.shape[0]):
        a[i], c[i] = film_speed_affine(_at(v, i), _at(dt, i), _at(b, i), _at(decay, i))


@kernel
def _loop_walther_viscosity_ratio(t, tref, wa, wb, out):
    for i in range(out.shape[0]):
        out[i] = walther_viscosity_ratio(_at(t, i), _at(tref, i), _at(wa, i), _at(wb, i))


def _flat(value, shape):
    """``value`` as a float (a scalar, broadcast by the loop) or a contiguous 1-D float array
    of length prod(shape).

    Large read-only arrays (e.g. checked contact inputs) are passed as they are -- a second
    compiled variant instead of copying megabytes on every call."""
    a = np.asarray(value, dtype=float)
    if a.size == 1:
        return float(a.reshape(-1)[0])
    if a.shape != shape:
        a = np.broadcast_to(a, shape)
    a = np.ascontiguousarray(a).reshape(-1)
    return a if a.flags.writeable or a.size > 4096 else a.copy()


def apply(loop, *args, outputs: int = 1):
    """Run an array loop of this module on broadcast numpy arguments.

    Returns an array of the broadcast shape (a numpy scalar for scalar arguments), or a tuple of
    ``outputs`` of them."""
    shape = np.broadcast_shapes(*(np.shape(a) for a in args))
    flat = [_flat(a, shape) for a in args]
    n = 1
    for s in shape:
        n *= s
    outs = [np.empty(n) for _ in range(outputs)]
    loop(*flat, *outs)
    res = [o.reshape(shape) if shape else o[0] for o in outs]
    if not shape:
        res = [np.float64(r) for r in res]
    return res[0] if outputs == 1 else tuple(res)
