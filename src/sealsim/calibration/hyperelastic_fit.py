r"""Hyperelastic models fitted to stress-stretch curves with FElupe's strain energies.

The curves are homogeneous incompressible tests (:data:`sealsim.properties.hyperelastic.MODES`:
uniaxial tension/compression, equibiaxial tension, planar tension = pure shear), nominal
stress P vs stretch λ.  A model of :data:`sealsim.properties.hyperelastic.HYPERELASTIC_MODELS`
is evaluated in closed form (:func:`sealsim.properties.hyperelastic.nominal_stress`, the
strain energies of FElupe, which the FE model uses; tests compare the two) and fitted with scipy's ``least_squares`` (relative residuals (P_model − P)/P by default, so that
the small-strain points count as much as the large ones), from several starting points for
Ogden and Arruda–Boyce (multi-modal problems); the best is kept.

Why not ``felupe.ConstitutiveMaterial.optimize``, which does the same: in FElupe 11.3 it pairs
the model's curves, evaluated in the order uniaxial, planar, biaxial (and only those given),
with the data in the order uniaxial, biaxial, planar, so planar data are compared with the
wrong curve (or with none); the residuals here are built per mode instead.

Uncertainty: standard errors, correlations and identifiability from the Jacobian at the
optimum (:func:`sealsim.calibration.statistics.parameter_statistics`; an Ogden term the data
cannot tell from the others is reported as not identifiable, its standard error infinite).
Stability: Drucker's condition along the three test deformations over a stretch range wider
than the data (:func:`sealsim.structure.hyperelastic.stability_limits`).

Curves may be given the role ``validate``: they are not fitted, only predicted, and their
error is the honest one (e.g. Mooney–Rivlin fitted to uniaxial data predicting equibiaxial
tension).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from sealsim.calibration.statistics import compare_signals, parameter_statistics
from sealsim.errors import InputError
from sealsim.properties.hyperelastic import (
    HYPERELASTIC_MODELS,
    MODES,
    initial_shear_modulus,
    model_name,
    nominal_stress,
)
from sealsim.structure.hyperelastic import stability_limits

__all__ = ["Curve", "HyperelasticFit", "fit_hyperelastic", "model_label"]

#: stress unit of the optimisation (parameters of order 1)
_MPA = 1e6

#: |λ − 1| below which a point counts as small strain in ``rel_rmse_beyond_small_strain``:
#: there a stretch reading error of 0.005 alone changes P/(λ − 1) by 10 % or more, so the
#: relative error of those points says more about the extensometer than about the model
SMALL_STRAIN = 0.05

#: Ogden exponents to start from, per number of terms (Ogden 1972's Treloar fit: 1.3, 5, -2)
OGDEN_STARTS = {
    1: ((2.0,), (1.3,), (4.0,), (-2.0,)),
    2: ((1.3, 5.0), (2.0, -2.0), (1.5, 4.0), (3.0, -1.0)),
    3: ((1.3, 5.0, -2.0), (2.0, 4.0, -1.5), (1.0, 6.0, -3.0), (1.5, 3.0, 8.0)),
}


#: Largest stretch a curve may hold [-]: rubbers break below about 10 (Treloar's natural
#: rubber at 7.6); a strain in percent read as a plain number gives 1 + 100 and more.
MAX_STRETCH = 20.0


@dataclass(frozen=True)
class Curve:
    """One measured curve: nominal stress [Pa] vs stretch [-] of a test deformation.

    ``role`` is ``"fit"`` or ``"validate"`` (predicted only)."""

    name: str
    mode: str
    stretch: np.ndarray
    stress: np.ndarray
    role: str = "fit"

    def __post_init__(self):
        if self.mode not in MODES:
            raise InputError(f"curve {self.name!r}: mode {self.mode!r} is not known; choose "
                             f"one of {', '.join(MODES)}")
        lam = np.asarray(self.stretch, dtype=float)
        p = np.asarray(self.stress, dtype=float)
        if lam.shape != p.shape or lam.ndim != 1 or lam.size < 2:
            raise InputError(f"curve {self.name!r}: stretch and stress must be equally long "
                             f"lists of at least 2 values")
        if np.any(lam <= 0) or not np.all(np.isfinite(lam)) or not np.all(np.isfinite(p)):
            raise InputError(f"curve {self.name!r}: stretches must be finite and > 0 and "
                             "stresses finite")
        if np.any(lam > MAX_STRETCH):
            raise InputError(f"curve {self.name!r}: stretch {float(lam.max()):.4g} is beyond "
                             f"{MAX_STRETCH:g}, where every rubber has broken: a strain in "
                             "percent needs its column's unit '%'")
        if self.mode != "uniaxial" and np.any(lam < 1.0):
            raise InputError(f"curve {self.name!r}: a {self.mode} test is a tension test "
                             "(stretch >= 1); compression belongs to 'uniaxial'")
        if self.role not in ("fit", "validate"):
            raise InputError(f"curve {self.name!r}: role {self.role!r} must be 'fit' or "
                             "'validate'")
        object.__setattr__(self, "stretch", lam)
        object.__setattr__(self, "stress", p)

    @property
    def informative(self) -> np.ndarray:
        """Points that carry information (not the unloaded state λ = 1, P = 0)."""
        return (np.abs(self.stretch - 1.0) > 1e-9) & (self.stress != 0.0)

    @property
    def wrong_sign(self) -> np.ndarray:
        """Points whose stress pulls against the deformation: negative in tension (λ > 1) or
        positive in compression (λ < 1)."""
        return (self.stretch - 1.0) * self.stress < 0.0


@dataclass
class HyperelasticFit:
    """The outcome of :func:`fit_hyperelastic` (stresses in Pa)."""

    model: str
    label: str
    parameters: dict                  # {parameter: value or list}, SI
    names: list[str]                  # flat names: mu_1, alpha_1, ... or C10, ...
    values: np.ndarray                # flat SI values
    standard_errors: np.ndarray       # flat SI, inf where not identifiable
    identifiable: np.ndarray
    reasons: list[list[str]]
    modes: dict                       # {mode: {"rel_rmse", "r2", "role", "points"}}
    stability: dict                   # stability_limits + data range per mode
    fit_modes: list[str]
    relative: bool
    cost: float
    success: bool
    message: str
    notes: list[str] = field(default_factory=list)
    limits: list[str | None] = field(default_factory=list)   # "lower bound 0 MPa", ... or None

    @property
    def hyperelastic(self) -> tuple:
        """``(model, ((parameter, value), ...))`` for an elastomer file."""
        spec = HYPERELASTIC_MODELS[self.model]
        return self.model, tuple(
            (p, tuple(self.parameters[p]) if spec.terms else self.parameters[p])
            for p in spec.parameters)

    @property
    def initial_shear_modulus(self) -> float:
        return initial_shear_modulus(self.model, self.parameters)

    def stress(self, mode: str, stretch) -> np.ndarray:
        """Model nominal stress [Pa]."""
        return nominal_stress(self.model, self.parameters, mode, stretch)

    def report(self) -> dict:
        """``{"model", "parameters": {NAME: {"value", "stderr", "identifiable", "notes"}},
        "modes": {MODE: {"rel_rmse", "r2", ...}}, "stability": ...}`` (SI)."""
        params = {}
        for i, name in enumerate(self.names):
            se = float(self.standard_errors[i])
            params[name] = {"value": float(self.values[i]),
                            "stderr": se if math.isfinite(se) else None,
                            "unit": "Pa" if _is_stress(self.model, name) else "-",
                            "identifiable": bool(self.identifiable[i]),
                            "at_limit": self.limits[i] if self.limits else None,
                            "notes": list(self.reasons[i])}
        return {"model": self.label, "parameters": params, "modes": self.modes,
                "fit_modes": self.fit_modes,
                "residuals": "relative" if self.relative else "absolute",
                "initial_shear_modulus_Pa": self.initial_shear_modulus,
                "stability": self.stability, "converged": self.success,
                "optimizer": self.message, "notes": self.notes}


def _is_stress(model: str, flat_name: str) -> bool:
    return flat_name.split("_")[0] in HYPERELASTIC_MODELS[model].stresses


def model_label(model: str, terms: int | None = None) -> str:
    """A model's name in reports: ``"ogden3"``, ``"mooney_rivlin"``."""
    name = model_name(model)
    return f"{name}{terms}" if HYPERELASTIC_MODELS[name].terms else name


def _initial_shear_modulus(curves: Sequence[Curve]) -> float:
    """μ0 estimate: the neo-Hookean shear modulus of each point, median over points with
    |λ − 1| < 0.5 (all points if there are none)."""
    neo = {"uniaxial": lambda l: l - l ** -2, "equibiaxial": lambda l: l - l ** -5,
           "planar": lambda l: l - l ** -3}
    est, small = [], []
    for c in curves:
        ok = c.informative
        mu = c.stress[ok] / neo[c.mode](c.stretch[ok])
        est.extend(mu.tolist())
        small.extend(mu[np.abs(c.stretch[ok] - 1.0) < 0.5].tolist())
    values = [v for v in (small or est) if v > 0]
    if not values:
        raise InputError("the fitted curves have no point with a positive stress off the "
                         "unloaded state: nothing to fit a stiffness to")
    return float(np.median(values))


def _starts(model: str, terms: int, mu0: float) -> list[dict]:
    """Starting parameter sets (MPa)."""
    m = mu0 / _MPA
    if model == "neo_hooke":
        return [{"mu": m}]
    if model == "mooney_rivlin":
        return [{"C10": 0.4 * m, "C01": 0.1 * m}]
    if model == "yeoh":
        return [{"C10": 0.5 * m, "C20": 0.0, "C30": 0.0}]
    if model == "third_order_deformation":
        return [{"C10": 0.4 * m, "C01": 0.1 * m, "C11": 0.0, "C20": 0.0, "C30": 0.0}]
    if model == "arruda_boyce":
        return [{"C1": m, "limit": lim} for lim in (3.0, 6.0, 10.0)]
    alphas = OGDEN_STARTS.get(terms) or (tuple(np.linspace(-2.0, 6.0, terms)),)
    starts = []
    for a in alphas:
        mu = [m] + [0.01 * m * (1 if ai > 0 else -1) for ai in a[1:]]
        starts.append({"mu": mu, "alpha": list(a)})
    return starts


def _bounds(model: str, terms: int):
    """least_squares bounds (MPa / -) in FElupe's parameter order."""
    spec = HYPERELASTIC_MODELS[model]
    lo, hi = [], []
    for p in spec.parameters:
        n = terms if spec.terms else 1
        if p == "limit":
            lo += [1.05] * n
            hi += [np.inf] * n
        elif p in ("mu", "C10", "C1") and not spec.terms:
            lo += [0.0] * n          # the leading modulus of a non-Ogden model is positive
            hi += [np.inf] * n
        elif p == "alpha":
            lo += [-30.0] * n
            hi += [30.0] * n
        else:
            lo += [-np.inf] * n
            hi += [np.inf] * n
    return np.array(lo), np.array(hi)


def fit_hyperelastic(curves: Sequence[Curve], model: str, terms: int | None = None,
                     fit_modes: Sequence[str] | None = None, relative: bool = True,
                     stretch_range: tuple[float, float] | None = None,
                     max_evaluations: int = 2000) -> HyperelasticFit:
    """Fit a hyperelastic model to test curves with FElupe's ``optimize``.

    Parameters
    ----------
    curves : sequence of Curve
        Measured curves; those with role ``"fit"`` whose mode is in ``fit_modes`` are fitted,
        all are evaluated.
    model : str
        A model of :data:`~sealsim.properties.hyperelastic.HYPERELASTIC_MODELS`
        (``"ogden3"`` = Ogden with 3 terms).
    terms : int, optional
        Ogden terms (default from the name, else 1).
    fit_modes : sequence of str, optional
        Modes to fit (default: every mode with a ``fit`` curve).
    relative : bool
        Relative residuals (P_model − P)/P (default) or absolute ones.
    stretch_range : (float, float), optional
        Range of the stability check; default from half the smallest to twice the largest
        stretch of the data (at least 0.5 to 2).
    max_evaluations : int
        Limit of residual evaluations per start.

    Returns
    -------
    HyperelasticFit

    Examples
    --------
    >>> lam = np.linspace(1.1, 3.0, 12)
    >>> curve = Curve("ut", "uniaxial", lam, 0.8e6 * (lam - lam ** -2))
    >>> fit = fit_hyperelastic([curve], "neo_hooke")
    >>> round(fit.parameters["mu"] / 1e6, 6), fit.modes["uniaxial"]["rel_rmse"] < 1e-8
    (0.8, True)
    """
    name = model_name(model)
    spec = HYPERELASTIC_MODELS[name]
    digits = str(model).strip().lower()[5:] if name == "ogden" else ""
    if spec.terms:
        terms = terms if terms is not None else (int(digits) if digits.isdigit() else 1)
        if not 1 <= terms <= 6:
            raise InputError(f"Ogden terms = {terms!r}: choose 1 to 6")
    else:
        terms = 1
    label = model_label(name, terms)
    curves = list(curves)
    modes_with_fit = [m for m in MODES if any(c.mode == m and c.role == "fit" for c in curves)]
    fit_modes = list(fit_modes) if fit_modes is not None else modes_with_fit
    unknown = [m for m in fit_modes if m not in MODES]
    if unknown:
        raise InputError(f"fit modes {unknown} are not known; choose from {', '.join(MODES)}")
    fitted = [c for c in curves if c.role == "fit" and c.mode in fit_modes]
    if not fitted:
        raise InputError(f"{label}: no curve to fit (fit modes {fit_modes}; curves: "
                         + ", ".join(f"{c.name} ({c.mode}, {c.role})" for c in curves) + ")")
    data = {}
    for mode in MODES:
        sel = [c for c in fitted if c.mode == mode]
        if sel:
            data[mode] = (np.concatenate([c.stretch[c.informative] for c in sel]),
                          np.concatenate([c.stress[c.informative] for c in sel]) / _MPA)
    n_points = sum(v[0].size for v in data.values())
    n_params = len(spec.parameters) * (terms if spec.terms else 1)
    if n_points <= n_params:
        raise InputError(f"{label}: {n_points} data points for {n_params} parameters; give "
                         "more points or choose a model with fewer parameters")
    mu0 = _initial_shear_modulus(fitted)
    lo, hi = _bounds(name, terms)
    sizes = [terms if spec.terms else 1] * len(spec.parameters)

    def unpack(x) -> dict:
        chunks = np.split(np.asarray(x, dtype=float), np.cumsum(sizes)[:-1])
        return {p: (list(c) if spec.terms else float(c[0]))
                for p, c in zip(spec.parameters, chunks)}

    def residuals(x) -> np.ndarray:
        params = unpack(x)
        out = []
        for mode, (lam, p) in data.items():
            r = nominal_stress(name, params, mode, lam) - p
            out.append(r / p if relative else r)
        return np.concatenate(out)

    best = None
    for start in _starts(name, terms, mu0):
        x0 = np.concatenate([np.ravel(np.asarray(start[p], dtype=float))
                             for p in spec.parameters])
        x0 = np.clip(x0, lo + 1e-9, hi - 1e-9)
        try:
            with np.errstate(all="ignore"):
                res = least_squares(residuals, x0, bounds=(lo, hi), method="trf",
                                    x_scale="jac", max_nfev=max_evaluations)
        except (ValueError, FloatingPointError, np.linalg.LinAlgError):
            continue
        if not np.all(np.isfinite(res.fun)):
            continue
        if best is None or res.cost < best.cost:
            best = res
    if best is None:
        raise InputError(f"{label}: the fit failed from every starting point (the model "
                         "cannot be evaluated at these stretches)")
    res = best
    flat_names = []
    for p in spec.parameters:
        flat_names += ([f"{p}_{k + 1}" for k in range(terms)] if spec.terms else [p])
    stats = parameter_statistics(res.jac, res.fun, values=res.x, names=flat_names)
    scale = np.array([_MPA if _is_stress(name, n) else 1.0 for n in flat_names])
    values = res.x * scale
    with np.errstate(invalid="ignore"):                 # inf - inf of unbounded parameters
        at_lower = (res.active_mask < 0) | (np.isfinite(lo) & (
            res.x - lo <= 1e-6 * np.maximum(1.0, np.abs(lo))))
        at_upper = (res.active_mask > 0) | (np.isfinite(hi) & (
            hi - res.x <= 1e-6 * np.maximum(1.0, np.abs(hi))))
    if spec.terms:  # term order is arbitrary: report them by increasing exponent
        order = np.argsort(res.x[terms:2 * terms])
        perm = np.concatenate([order + k * terms for k in range(len(spec.parameters))])
        res.x, res.jac = res.x[perm], res.jac[:, perm]
        lo, hi, at_lower, at_upper = lo[perm], hi[perm], at_lower[perm], at_upper[perm]
        stats = parameter_statistics(res.jac, res.fun, values=res.x, names=flat_names)
        values = res.x * scale
    limits = [None] * len(flat_names)
    for i, n in enumerate(flat_names):
        if at_lower[i] or at_upper[i]:
            bound = (lo if at_lower[i] else hi)[i]
            unit = "MPa" if _is_stress(name, n) else "-"
            limits[i] = f"{'lower' if at_lower[i] else 'upper'} bound {bound:g} {unit}"
            # the optimum lies beyond what the model allows: no estimate, no standard error
            stats["standard_errors"][i] = np.inf
            stats["identifiable"][i] = False
            stats["reasons"][i] = [*stats["reasons"][i], f"it sits on its {limits[i]}: the "
                                   "data ask for a value beyond it, which the model does not "
                                   "allow"]
    parameters = {}
    offset = 0
    for p in spec.parameters:
        n = terms if spec.terms else 1
        chunk = values[offset:offset + n]
        parameters[p] = [float(v) for v in chunk] if spec.terms else float(chunk[0])
        offset += n
    fit = HyperelasticFit(
        model=name, label=label, parameters=parameters, names=flat_names, values=values,
        standard_errors=stats["standard_errors"] * scale, identifiable=stats["identifiable"],
        reasons=stats["reasons"], modes={}, stability={}, fit_modes=fit_modes,
        relative=relative, cost=float(res.cost), success=bool(res.success),
        message=str(res.message), limits=limits)
    fit.modes = _mode_errors(fit, curves)
    fit.stability = _stability(fit, curves, stretch_range)
    if not fit.success:
        fit.notes.append(f"the optimiser did not converge: {res.message}")
    for i, limit in enumerate(limits):
        if limit:
            fit.notes.append(f"{flat_names[i]} sits on its {limit}: the best "
                             f"{label} lies beyond what the model allows (e.g. a negative C10 "
                             "of Mooney-Rivlin); the value is the bound's, not the data's: "
                             "choose another model or fit more test modes")
    bad = [n for n, ok in zip(flat_names, fit.identifiable) if not ok]
    if bad:
        fit.notes.append(f"not identifiable from the fitted data: {', '.join(bad)} (see the "
                         "parameters' notes); a model with fewer parameters or more test "
                         "modes determines them")
    return fit


def _mode_errors(fit: HyperelasticFit, curves: Sequence[Curve]) -> dict:
    """Per mode: RMS relative error, R², role (fit/validate) and the number of points."""
    out = {}
    for mode in MODES:
        sel = [c for c in curves if c.mode == mode]
        if not sel:
            continue
        lam = np.concatenate([c.stretch[c.informative] for c in sel])
        p = np.concatenate([c.stress[c.informative] for c in sel])
        model = fit.stress(mode, lam)
        rel = (model - p) / p
        stats = compare_signals(p, model)
        roles = {c.role for c in sel}
        fitted = mode in fit.fit_modes and "fit" in roles
        beyond = np.abs(lam - 1.0) >= SMALL_STRAIN
        out[mode] = {"rel_rmse": float(np.sqrt(np.mean(rel ** 2))),
                     "rel_rmse_beyond_small_strain": (float(np.sqrt(np.mean(rel[beyond] ** 2)))
                                                      if beyond.any() else None),
                     "max_rel_error": float(np.max(np.abs(rel))),
                     "r2": stats["r2"], "rmse_Pa": stats["rmse"],
                     "role": "fit" if fitted else "validate", "points": int(lam.size),
                     "stretch_range": [float(lam.min()), float(lam.max())]}
    return out


def _stability(fit: HyperelasticFit, curves: Sequence[Curve],
               stretch_range: tuple[float, float] | None) -> dict:
    lam = np.concatenate([c.stretch for c in curves])
    if stretch_range is None:
        stretch_range = (min(0.5, 0.5 * float(lam.min())), max(2.0, 2.0 * float(lam.max())))
    limits = stability_limits(fit.model, fit.parameters, stretch_range)
    for mode, lim in limits.items():
        sel = [c.stretch for c in curves if c.mode == mode]
        if sel:
            lo, hi = float(np.min(np.concatenate(sel))), float(np.max(np.concatenate(sel)))
            lim["data_range"] = [lo, hi]
            lim["stable_over_data"] = bool(lim["stable_from"] <= lo and hi <= lim["stable_to"])
        lim["checked_range"] = [float(stretch_range[0]), float(stretch_range[1])]
    return limits
