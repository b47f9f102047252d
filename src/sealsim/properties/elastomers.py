r"""Elastomer compounds: the :class:`Elastomer` record and the material catalogue.

An :class:`Elastomer` holds the thermal, hyperelastic and viscoelastic properties of one
compound (SI units: temperature in K, moduli and hyperelastic constants in Pa, density in
kg/m³, conductivity in W/(m·K), specific heat in J/(kg·K), linear expansion in 1/K) and
evaluates them through the laws of

* :mod:`sealsim.properties.viscoelasticity` -- WLF shift, reduced time, Prony series, fictive
  temperature;
* :mod:`sealsim.properties.rubber_modulus` -- storage modulus E(T, f) from a master curve or a
  DMA table, entropic, Mooney–Rivlin and Shore A moduli;
* :mod:`sealsim.properties.thermal_expansion` -- rubbery and glassy expansion.

The catalogue ``data/elastomers.toml`` (NBR, HNBR, FKM, ACM, VMQ) is read with
:func:`list_elastomers`, :func:`get_elastomer`, :meth:`Elastomer.from_dict` and
:func:`load_elastomer_file` (format: :mod:`sealsim.properties.catalogue`).  The functions of the
three law modules are importable from here as well (``from sealsim.properties.elastomers import
wlf_log10_shift``).

Tags after a value: [L] a typical literature or handbook value not re-checked against a primary
source; [D] derived or chosen by sealsim (reproducible from the equations shown).

The catalogue's E(T) shape
--------------------------
Same for all five materials, no DMA data at hand: master-curve location x0 = −2.0 (log10 Hz at
the WLF reference temperature T_g), width w = 1.1 decades, asymmetry ν = 4.0, E_g = 1.5–2.5 GPa,
universal WLF constants at T_g (see :mod:`sealsim.properties.rubber_modulus` for the
construction).  sealsim chose the shape [D] so that it shows the typical behaviour of filled
NBR seal compounds [L]: they lose 30–50 % of their small-strain modulus between 20 and 100 °C
at ~1 Hz and are flat above ~100 °C, with E(−25 °C, 1 Hz) ≈ 1 GPa (DSC T_g lies on the glassy
side of the 1 Hz DMA transition).  E_r,ref was then chosen per material so that
E(20 °C, 1 Hz) is the middle of the typical small-strain modulus of filled 70–80 Shore A
compounds [L] (NBR and HNBR 7–10 MPa, FKM 7–12, ACM 6–9, VMQ 5–8).  Resulting catalogue
values (1 Hz): NBR drops 39 % from 20 to 100 °C and has its minimum at ≈ 108 °C, FKM drops
52 % (minimum ≈ 120 °C), VMQ (T_g = −120 °C) is rubbery from ≈ −20 °C on and rises with T.

E(T) decreases monotonically with T from the glass up to the temperature where the decay of
the transition tail becomes slower than the entropic rise of the plateau
(:meth:`Elastomer.modulus_minimum_temperature`); above it E rises ∝ T. Because the
continuation of a_T below T_g is Arrhenius (never divergent) and S is monotone, there is a
single minimum.

References
----------
- M. L. Williams, R. F. Landel, J. D. Ferry, J. Am. Chem. Soc. 77 (1955) 3701–3707 (WLF
  universal constants).
- M. Mooney, J. Appl. Phys. 11 (1940) 582–592; R. S. Rivlin, Phil. Trans. R. Soc. A 241 (1948)
  379–397 (Mooney–Rivlin strain energy).
- R. Simha, R. F. Boyer, J. Chem. Phys. 37 (1962) 1003–1007 (glassy expansion).
"""

from __future__ import annotations

import difflib
import functools
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
from scipy.optimize import minimize_scalar

from sealsim.errors import InputError
from sealsim.properties._checks import (
    _array,
    _broadcast,
    _out,
    _outside,
    _range_text,
    _scalar,
)
from sealsim.properties.rubber_modulus import (
    DEFAULT_TRANSITION_ASYMMETRY,
    DEFAULT_TRANSITION_LOCATION,
    DEFAULT_TRANSITION_WIDTH,
    _entropic_modulus,
    _master_log10,
    entropic_modulus,
    master_curve_modulus,
    modulus_from_table,
    modulus_vs_temperature,
    mooney_rivlin_young_modulus,
    shore_a_young_modulus,
)
from sealsim.properties.thermal_expansion import (
    GLASSY_EXPANSION_RATIO,
    SIMHA_BOYER_K1,
    SIMHA_BOYER_K2,
    simha_boyer_glassy_expansion,
    thermal_strain,
)
from sealsim.properties.viscoelasticity import (
    WLF_UNIVERSAL,
    WLF_UNIVERSAL_TS,
    WLFConstants,
    _inverse_log10_shift,
    _log10_shift,
    _prony_params,
    fictive_temperature,
    fictive_temperature_step,
    prony_loss_modulus,
    prony_relaxation_modulus,
    prony_storage_modulus,
    reduced_time,
    reduced_time_history,
    wlf_log10_shift,
    wlf_shift_factor,
)

__all__ = [
    "CATALOGUE_NAMES",
    "CONSTANTS_CURVE_TOLERANCE",
    "CompoundConsistencyWarning",
    "GLASS_TRANSITION_MARGIN",
    "HELD_SEAL_TIME",
    "DEFAULT_TRANSITION_ASYMMETRY",
    "DEFAULT_TRANSITION_LOCATION",
    "DEFAULT_TRANSITION_WIDTH",
    "GLASSY_EXPANSION_RATIO",
    "SIMHA_BOYER_K1",
    "SIMHA_BOYER_K2",
    "TEMPERATURE_SCALINGS",
    "WLF_UNIVERSAL",
    "WLF_UNIVERSAL_TS",
    "Elastomer",
    "ServiceRangeWarning",
    "WLFConstants",
    "get_elastomer",
    "compound_file_digest",
    "held_frequency",
    "rubbery_limit_message",
    "entropic_modulus",
    "is_compound_file",
    "load_compound",
    "fictive_temperature",
    "fictive_temperature_step",
    "list_elastomers",
    "load_elastomer_file",
    "master_curve_modulus",
    "modulus_from_table",
    "modulus_vs_temperature",
    "mooney_rivlin_young_modulus",
    "prony_loss_modulus",
    "prony_relaxation_modulus",
    "prony_storage_modulus",
    "reduced_time",
    "reduced_time_history",
    "simha_boyer_glassy_expansion",
    "thermal_strain",
    "shore_a_young_modulus",
    "wlf_log10_shift",
    "wlf_shift_factor",
]

#: Temperature laws of the hyperelastic (sealing) stiffness, see :meth:`Elastomer.modulus_ratio`.
TEMPERATURE_SCALINGS = ("held", "entropic", "modulus", "none")

#: How long an installed seal has been held at its squeeze when it is used [s]: one hour, the
#: time scale of sealsim's convention for the stiffness of a held seal (the relaxed modulus of
#: :meth:`Elastomer.held_modulus`, the one law of the rotary lip force, the FE lip, the FE
#: maps and the analytic O-ring estimate).  One hour is the hold after installation of the
#: cooling run of Heipl & Murrenhoff's Fig. 8 (examples/structure/oring_cooling.toml) and the
#: length of a friction test's speed step (Organisciak et al. 2014, Fig. 9); on the catalogue
#: NBR the modulus keeps falling by about 10 % per decade of holding time at 20 °C.
HELD_SEAL_TIME = 3600.0


def held_frequency(hold_time: float = HELD_SEAL_TIME) -> float:
    """Frequency [Hz] whose storage modulus approximates the relaxation modulus after
    ``hold_time`` [s]: f = 1/(2π·t), the first-order interconversion E(t) ≈ E'(ω = 1/t)
    (J. D. Ferry, *Viscoelastic Properties of Polymers*, 3rd ed., Wiley 1980, ch. 4; within
    5 % of the catalogue NBR's Prony series at 60 s and 1 h from 0 to 60 °C, tested).

    Examples
    --------
    >>> f"{held_frequency(3600.0):.3g}"
    '4.42e-05'
    """
    return 1.0 / (2.0 * math.pi * float(hold_time))

#: Distance above T_g [K] below which a rubbery (hyperelastic) seal model -- an FE map with
#: the equilibrium material, the analytic O-ring estimate -- is refused: there the modulus at
#: the holding time scale has left its rubbery plateau (catalogue NBR: 1.5x its 20 °C value
#: at T_g + 20 K, 4x at T_g + 5 K) and the expansion turns glassy (Simha & Boyer), which only
#: the viscoelastic FE material with its fictive temperature describes.
GLASS_TRANSITION_MARGIN = 20.0

#: Names in the shipped catalogue.
CATALOGUE_NAMES = ("NBR", "HNBR", "FKM", "ACM", "VMQ")

#: Physically meaningful range around the material (see :meth:`Elastomer.check_temperature`).
BELOW_TG_LIMIT = 100.0  # K below T_g
ABOVE_SERVICE_LIMIT = 50.0  # K above the service maximum


def rubbery_limit_message(what: str, temperature: float, elastomer) -> str:
    """The refusal of a rubbery (hyperelastic) seal model at ``temperature`` [K] within
    :data:`GLASS_TRANSITION_MARGIN` of the rubber's T_g."""
    tg = elastomer.glass_transition - 273.15
    return (f"{what} is rubbery and refuses {temperature - 273.15:.4g} degC: that is "
            f"within {GLASS_TRANSITION_MARGIN:g} K of the T_g of {elastomer.name} ({tg:g} degC), "
            f"where the rubber stiffens towards the glass and shrinks with its glassy "
            f"expansion; start the range at {tg + GLASS_TRANSITION_MARGIN:g} degC or above, or "
            f"run the cooling path with the viscoelastic FE material (structure case: "
            f"material.model = 'viscoelastic', sealsim structure run)")


class ServiceRangeWarning(UserWarning):
    """A temperature is physically meaningful but outside the material's service range."""


class CompoundConsistencyWarning(UserWarning):
    """A material's hyperelastic constants and its modulus curve disagree at the reference
    point (:meth:`Elastomer.constants_modulus_mismatch`)."""


#: Largest relative difference between a material's small-strain modulus from its hyperelastic
#: constants, 6·(C10 + C01), and its modulus curve at (reference temperature, test frequency)
#: that loads without a :class:`CompoundConsistencyWarning`.  A held seal's stiffness is the
#: constants times E_h(T)/E(T_ref, f_test) of the curve (:meth:`Elastomer.modulus_ratio`):
#: the constants set the level, the curve the shape, and they must describe the same rubber
#: at that point.  The catalogue entries agree to 0.1 %; 10 % is about the spread of one
#: compound's tensile and DMA small-strain moduli (strain amplitude and rate differ).
CONSTANTS_CURVE_TOLERANCE = 0.10



def _field_error(field: str, value: Any, allowed: str, unit: str = "") -> InputError:
    shown = f"{value:g} {unit}".strip() if isinstance(value, float) else repr(value)
    err = InputError(f"{field} = {shown} is not allowed; allowed: {allowed}")
    err.field = field  # type: ignore[attr-defined]
    return err


def _check_field(
    field: str,
    value: Any,
    unit: str,
    lo: float | None = None,
    hi: float | None = None,
    lo_open: bool = False,
    hi_open: bool = False,
    why: str = "",
) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise _field_error(field, value, f"a number [{unit}]") from None
    if _outside(np.float64(v), lo, hi, lo_open, hi_open):
        allowed = _range_text(lo, hi, lo_open, hi_open, unit) + (f" ({why})" if why else "")
        raise _field_error(field, v, allowed, unit)
    return v


@dataclass(frozen=True)
class Elastomer:
    """An elastomer compound: thermal, hyperelastic and viscoelastic properties (SI units).

    All temperatures in K, moduli and hyperelastic constants in Pa. Build one from the
    catalogue (:func:`get_elastomer`), from a TOML table (:meth:`from_dict`,
    :func:`load_elastomer_file`) or directly; the constructor validates every field and
    raises :class:`InputError` naming it.

    Attributes
    ----------
    name : str
        Short name, e.g. "NBR".
    description : str
        One-line description.
    glass_transition : float
        T_g (DSC) [K]; 100–400 K.
    density : float
        ρ [kg/m³]; 800–2500.
    thermal_conductivity : float
        k [W/(m·K)]; 0.05–2.
    specific_heat : float
        c_p [J/(kg·K)]; 500–3000.
    thermal_expansion : float
        Linear CTE of the rubber (equilibrium, above T_g) α_r [1/K]; 1e-5–1e-3.
    c10, c01 : float
        Mooney–Rivlin constants [Pa] at ``reference_temperature`` (C10 > 0, C01 >= 0).
    bulk_modulus : float
        K [Pa]; > 10× the shear modulus 2(C10 + C01) (nearly incompressible).
    reference_temperature : float
        T_ref [K] of c10, c01, bulk_modulus, rubbery_modulus; > T_g.
    wlf_c1, wlf_c2 : float
        WLF constants C1 [-], C2 [K] (> 0).
    wlf_reference_temperature : float
        WLF reference temperature [K]; must satisfy T_g > T_wlf − C2.
    glassy_modulus : float
        E_g [Pa]; > 2 × rubbery_modulus.
    rubbery_modulus : float
        Equilibrium rubbery modulus E_r [Pa] at ``reference_temperature`` (low-frequency
        asymptote of the master curve, below the modulus at the test frequency).
    transition_location, transition_width, transition_asymmetry : float
        Master-curve sigmoid x0 [log10 Hz at the WLF reference temperature], w [decades],
        ν [-] (see :func:`~sealsim.properties.rubber_modulus.master_curve_modulus`).
    test_frequency : float
        Frequency [Hz] at which ``modulus`` is evaluated by default and at which the
        hyperelastic constants are taken to hold.
    service_range : tuple of float
        (T_min, T_max) [K] of service.
    source : str
        Where the values come from.
    dma_table : tuple, optional
        ((T_k, ...), (E_k, ...)) [K], [Pa] measured at ``dma_frequency``; overrides the
        parametric curve.
    dma_frequency : float, optional
        Frequency [Hz] of the DMA table; default ``test_frequency``.
    prony : tuple, optional
        (E∞, (E_i, ...), (τ_i, ...)) [Pa], [Pa], [s] at ``prony_reference_temperature``.
    prony_reference_temperature : float, optional
        [K]; default ``reference_temperature``.
    hardness_shore_a : float, optional
        Shore A hardness [-] (information only).
    glassy_thermal_expansion : float, optional
        Measured linear CTE of the glass α_g [1/K] (default Simha–Boyer, see
        :attr:`glassy_expansion`).
    hyperelastic : tuple, optional
        ``(model, ((parameter, value), ...))`` of
        :func:`~sealsim.properties.hyperelastic.check_hyperelastic` (stresses in Pa, at
        ``reference_temperature``): the strain energy the FE model uses instead of
        ``c10``/``c01``, which then hold the neo-Hookean equivalent (C10 = μ0/2, C01 = 0) for
        the analytic estimates.

    Examples
    --------
    >>> nbr = get_elastomer("nbr")
    >>> nbr.modulus(293.15) / 1e6
    8.5
    """

    name: str
    description: str
    glass_transition: float
    density: float
    thermal_conductivity: float
    specific_heat: float
    thermal_expansion: float
    c10: float
    c01: float
    bulk_modulus: float
    reference_temperature: float
    wlf_c1: float
    wlf_c2: float
    wlf_reference_temperature: float
    glassy_modulus: float
    rubbery_modulus: float
    transition_location: float = DEFAULT_TRANSITION_LOCATION
    transition_width: float = DEFAULT_TRANSITION_WIDTH
    transition_asymmetry: float = DEFAULT_TRANSITION_ASYMMETRY
    test_frequency: float = 1.0
    service_range: tuple[float, float] = (233.15, 373.15)
    source: str = ""
    dma_table: tuple[tuple[float, ...], tuple[float, ...]] | None = None
    dma_frequency: float | None = None
    prony: tuple[float, tuple[float, ...], tuple[float, ...]] | None = None
    prony_reference_temperature: float | None = None
    hardness_shore_a: float | None = None
    hyperelastic: tuple | None = None
    glassy_thermal_expansion: float | None = None

    # -- validation ---------------------------------------------------------------------------

    def __post_init__(self) -> None:
        set_ = functools.partial(object.__setattr__, self)
        if not isinstance(self.name, str) or not self.name.strip():
            raise _field_error("name", self.name, "a non-empty string")
        for f in ("description", "source"):
            if not isinstance(getattr(self, f), str):
                raise _field_error(f, getattr(self, f), "a string")
        tg = _check_field("glass_transition", self.glass_transition, "K", 100.0, 400.0)
        set_("glass_transition", tg)
        set_("density", _check_field("density", self.density, "kg/m3", 800.0, 2500.0))
        set_(
            "thermal_conductivity",
            _check_field("thermal_conductivity", self.thermal_conductivity, "W/(m K)", 0.05, 2.0),
        )
        set_(
            "specific_heat",
            _check_field("specific_heat", self.specific_heat, "J/(kg K)", 500.0, 3000.0),
        )
        set_(
            "thermal_expansion",
            _check_field("thermal_expansion", self.thermal_expansion, "1/K", 1e-5, 1e-3),
        )
        t_ref = _check_field(
            "reference_temperature",
            self.reference_temperature,
            "K",
            tg,
            600.0,
            lo_open=True,
            why="above glass_transition",
        )
        set_("reference_temperature", t_ref)
        c10 = _check_field("c10", self.c10, "Pa", 0.0, 1e9, lo_open=True)
        c01 = _check_field("c01", self.c01, "Pa", 0.0, 1e9)
        set_("c10", c10)
        set_("c01", c01)
        set_(
            "bulk_modulus",
            _check_field(
                "bulk_modulus",
                self.bulk_modulus,
                "Pa",
                20.0 * (c10 + c01),
                1e11,
                lo_open=True,
                why="> 10 x shear modulus 2(c10 + c01)",
            ),
        )
        c1 = _check_field("wlf_c1", self.wlf_c1, "-", 0.0, 100.0, lo_open=True)
        c2 = _check_field("wlf_c2", self.wlf_c2, "K", 0.0, 1000.0, lo_open=True)
        set_("wlf_c1", c1)
        set_("wlf_c2", c2)
        t_wlf = _check_field(
            "wlf_reference_temperature",
            self.wlf_reference_temperature,
            "K",
            0.0,
            tg + c2,
            lo_open=True,
            hi_open=True,
            why="below glass_transition + wlf_c2, so that WLF is finite at T_g",
        )
        set_("wlf_reference_temperature", t_wlf)
        e_r = _check_field("rubbery_modulus", self.rubbery_modulus, "Pa", 1e4, 1e9)
        set_("rubbery_modulus", e_r)
        set_(
            "glassy_modulus",
            _check_field(
                "glassy_modulus",
                self.glassy_modulus,
                "Pa",
                2.0 * e_r,
                1e11,
                lo_open=True,
                why="> 2 x rubbery_modulus",
            ),
        )
        set_(
            "transition_location",
            _check_field("transition_location", self.transition_location, "log10 Hz", -30, 30),
        )
        set_(
            "transition_width",
            _check_field(
                "transition_width", self.transition_width, "decades", 0.0, 10.0, lo_open=True
            ),
        )
        set_(
            "transition_asymmetry",
            _check_field(
                "transition_asymmetry", self.transition_asymmetry, "-", 0.0, 100.0, lo_open=True
            ),
        )
        set_(
            "test_frequency",
            _check_field("test_frequency", self.test_frequency, "Hz", 0.0, None, lo_open=True),
        )
        try:
            t_min, t_max = (float(v) for v in self.service_range)
        except (TypeError, ValueError):
            raise _field_error(
                "service_range", self.service_range, "a pair (T_min, T_max) of numbers [K]"
            ) from None
        if not (math.isfinite(t_min) and math.isfinite(t_max) and 0.0 < t_min < t_max):
            raise _field_error("service_range", self.service_range, "0 < T_min < T_max [K]")
        if t_max <= tg:
            raise _field_error("service_range", self.service_range, f"T_max > T_g = {tg:g} K")
        if t_min < tg - BELOW_TG_LIMIT:
            # below it the model refuses every temperature (allowed_range): a service range
            # that starts there cannot be used
            raise _field_error("service_range", self.service_range,
                               f"T_min >= T_g - {BELOW_TG_LIMIT:g} K = {tg - BELOW_TG_LIMIT:g} K "
                               "(the lower end of the range where the model is meaningful)")
        set_("service_range", (t_min, t_max))
        if self.dma_table is not None:
            self._validate_dma(set_)
        if self.prony is not None:
            self._validate_prony(set_)
        if self.hardness_shore_a is not None:
            set_(
                "hardness_shore_a",
                _check_field("hardness_shore_a", self.hardness_shore_a, "Shore A", 0.0, 100.0),
            )
        if self.glassy_thermal_expansion is not None:
            set_("glassy_thermal_expansion", _check_field(
                "glassy_thermal_expansion", self.glassy_thermal_expansion, "1/K", 0.0,
                self.thermal_expansion, why="between 0 and thermal_expansion"))
        if self.hyperelastic is not None:
            from sealsim.properties.hyperelastic import check_hyperelastic

            try:
                model, params = self.hyperelastic
                set_("hyperelastic", check_hyperelastic(model, dict(params)))
            except (TypeError, ValueError, InputError) as exc:
                raise _field_error("hyperelastic", self.hyperelastic,
                                   f"(model, ((parameter, value), ...)): {exc}") from None

    def _validate_dma(self, set_: Any) -> None:
        try:
            t_tab, e_tab = self.dma_table  # type: ignore[misc]
            t_tab = tuple(float(v) for v in t_tab)
            e_tab = tuple(float(v) for v in e_tab)
        except (TypeError, ValueError):
            raise _field_error(
                "dma_table", self.dma_table, "a pair ((T_k, ...) [K], (E_k, ...) [Pa])"
            ) from None
        try:
            modulus_from_table(t_tab[0] if t_tab else 1.0, t_tab, e_tab)
        except InputError as exc:
            raise _field_error("dma_table", self.dma_table, str(exc)) from None
        set_("dma_table", (t_tab, e_tab))
        f = self.test_frequency if self.dma_frequency is None else self.dma_frequency
        set_("dma_frequency", _check_field("dma_frequency", f, "Hz", 0.0, None, lo_open=True))

    def _validate_prony(self, set_: Any) -> None:
        try:
            e_inf, e_i, tau_i = self.prony  # type: ignore[misc]
            e_inf, e_i, tau_i = _prony_params(e_inf, e_i, tau_i)
        except (TypeError, ValueError) as exc:
            raise _field_error(
                "prony", self.prony, f"(E_inf [Pa], (E_i, ...) [Pa], (tau_i, ...) [s]): {exc}"
            ) from None
        set_("prony", (e_inf, tuple(e_i.tolist()), tuple(tau_i.tolist())))
        t_p = (
            self.reference_temperature
            if self.prony_reference_temperature is None
            else (self.prony_reference_temperature)
        )
        set_(
            "prony_reference_temperature",
            _check_field("prony_reference_temperature", t_p, "K", self.glass_transition, 600.0),
        )

    # -- temperature range ------------------------------------------------------------------

    @property
    def allowed_range(self) -> tuple[float, float]:
        """Physically meaningful temperature range [K]: (T_g − 100 K, T_max,service + 50 K).

        Below T_g − 100 K the material is a deep glass far from any seal use; above the
        service maximum + 50 K it degrades within hours. The lower bound is also kept > 1 K.
        """
        return (
            max(self.glass_transition - BELOW_TG_LIMIT, 1.0),
            self.service_range[1] + ABOVE_SERVICE_LIMIT,
        )

    def check_temperature(self, temperature: Any, *, warn: bool = True) -> np.ndarray:
        """Validate temperatures for this material.

        Raises :class:`InputError` outside :attr:`allowed_range` (T_g − 100 K to service
        maximum + 50 K) and, if ``warn``, issues a :class:`ServiceRangeWarning` for values
        inside it but outside :attr:`service_range`.

        Parameters
        ----------
        temperature : array_like
            Temperature [K].
        warn : bool, default True
            Warn outside the service range.

        Returns
        -------
        numpy.ndarray
            The temperatures as a float array.

        Examples
        --------
        >>> get_elastomer("FKM").check_temperature(373.15)
        array(373.15)
        """
        return self._check(temperature, warn, stacklevel=3)

    def _check(self, temperature: Any, warn: bool, stacklevel: int) -> np.ndarray:
        """check_temperature; ``stacklevel`` makes the warning point at the user's call."""
        lo, hi = self.allowed_range
        t = _array(temperature, f"temperature for {self.name}", "K", lo=lo, hi=hi)
        s_lo, s_hi = self.service_range
        # a limit given in other units ("212 degF") may convert a last bit outside it
        outside = (t < s_lo * (1 - 1e-12)) | (t > s_hi * (1 + 1e-12))
        if warn and np.any(outside):
            out = t[outside]
            shown = f"{float(out.min()):.2f}" + (
                f"–{float(out.max()):.2f}" if out.min() != out.max() else ""
            )
            warnings.warn(
                f"temperature {shown} K is outside the service range {s_lo:.2f}–{s_hi:.2f} K "
                f"of {self.name}",
                ServiceRangeWarning,
                stacklevel=stacklevel,
            )
        return t

    # -- shift factor and modulus -------------------------------------------------------------

    def _log10_shift(self, t: np.ndarray) -> np.ndarray:
        return _log10_shift(
            t, self.wlf_reference_temperature, self.wlf_c1, self.wlf_c2, self.glass_transition
        )

    def log10_shift_factor(
        self, temperature: Any, reference_temperature: float | None = None
    ) -> np.ndarray | float:
        """log10 a_T [-] (WLF above T_g, Arrhenius continuation below; see
        :func:`~sealsim.properties.viscoelasticity.wlf_log10_shift`).

        Parameters
        ----------
        temperature : array_like
            T [K].
        reference_temperature : float, optional
            Temperature [K] at which a_T = 1; default the WLF reference temperature.

        Returns
        -------
        float or numpy.ndarray
            log10 a_T [-].

        Examples
        --------
        >>> get_elastomer("NBR").log10_shift_factor(373.15)
        -12.3
        """
        return _out(self._shift_checked(temperature, reference_temperature))

    def _shift_checked(self, temperature: Any, reference_temperature: float | None) -> np.ndarray:
        t = self._check(temperature, True, stacklevel=4)
        y = self._log10_shift(t)
        if reference_temperature is not None:
            t0 = self._check(reference_temperature, False, stacklevel=4)
            if t0.ndim != 0:
                raise InputError("reference_temperature must be a single number [K]")
            y = y - self._log10_shift(t0)
        return y

    def shift_factor(
        self, temperature: Any, reference_temperature: float | None = None
    ) -> np.ndarray | float:
        """Shift factor a_T [-] (10 ** :meth:`log10_shift_factor`).

        Parameters
        ----------
        temperature : array_like
            T [K].
        reference_temperature : float, optional
            Temperature [K] at which a_T = 1; default the WLF reference temperature.

        Returns
        -------
        float or numpy.ndarray
            a_T [-].

        Examples
        --------
        >>> get_elastomer("NBR").shift_factor(296.15, reference_temperature=296.15)
        1.0
        """
        return _out(10.0 ** self._shift_checked(temperature, reference_temperature))

    def _modulus(self, t: np.ndarray, f: np.ndarray,
                 log10_shift: np.ndarray | None = None) -> np.ndarray:
        """E [Pa] for validated, broadcast t [K] and f [Hz] (no warnings); ``log10_shift``:
        :meth:`_log10_shift` of t when the caller has it already."""
        if self.dma_table is not None:
            t_tab, e_tab = self.dma_table
            if np.all(f == self.dma_frequency):
                t_eq = t
            else:
                # time–temperature superposition: the table temperature with the same f·a_T
                if log10_shift is None:
                    log10_shift = self._log10_shift(t)
                y = log10_shift + np.log10(f / self.dma_frequency)
                t_eq = _inverse_log10_shift(
                    y,
                    self.wlf_reference_temperature,
                    self.wlf_c1,
                    self.wlf_c2,
                    self.glass_transition,
                )
                if np.any(~np.isfinite(t_eq)):
                    raise InputError(
                        f"frequency/temperature of {self.name} lie beyond the WLF range: no "
                        f"equivalent temperature of the DMA table exists"
                    )
            try:
                return np.asarray(modulus_from_table(t_eq, t_tab, e_tab))
            except InputError as exc:
                raise InputError(
                    f"{self.name}: the DMA table covers {t_tab[0]:.2f}–{t_tab[-1]:.2f} K at "
                    f"{self.dma_frequency:g} Hz; the requested temperature/frequency maps outside "
                    f"it ({exc})"
                ) from None
        if log10_shift is None:
            log10_shift = self._log10_shift(t)
        x = np.log10(f) + log10_shift
        # the material's fields and t are validated: the law without its input checks
        log_er = np.log10(_entropic_modulus(self.rubbery_modulus, t, self.reference_temperature))
        return 10.0 ** _master_log10(
            x,
            math.log10(self.glassy_modulus),
            log_er,
            self.transition_location,
            self.transition_width,
            self.transition_asymmetry,
        )

    def _t_f(self, temperature: Any, frequency: Any, warn: bool) -> tuple[np.ndarray, np.ndarray]:
        t = self._check(temperature, warn, stacklevel=4)
        f = self.test_frequency if frequency is None else frequency
        f = _array(f, "frequency", "Hz", lo=0.0, lo_open=True)
        t, f = _broadcast(t, f, names="temperature and frequency")
        return t, f

    def modulus(self, temperature: Any, frequency: Any = None) -> np.ndarray | float:
        r"""Small-strain Young's (storage) modulus E(T, f) [Pa].

        From the DMA table if one is given (PCHIP in log E vs T; at another frequency the
        table is read at the WLF-equivalent temperature, without vertical shift), otherwise
        from :func:`~sealsim.properties.rubber_modulus.modulus_vs_temperature` with this
        material's parameters.

        Parameters
        ----------
        temperature : array_like
            T [K], inside :attr:`allowed_range` (warning outside the service range).
        frequency : array_like, optional
            f [Hz]; default ``test_frequency``.

        Returns
        -------
        float or numpy.ndarray
            E [Pa].

        Examples
        --------
        >>> get_elastomer("NBR").modulus(373.15) / 1e6
        5.2
        """
        t, f = self._t_f(temperature, frequency, warn=True)
        return _out(self._modulus(t, f))

    def held_modulus(self, temperature: Any, hold_time: float = HELD_SEAL_TIME,
                     mounting_temperature: Any = None) -> np.ndarray | float:
        r"""Young's modulus of a seal held at its squeeze: the relaxed modulus after
        ``hold_time`` from the viscoelastic master curve [Pa].

        sealsim's one convention for the stiffness of an installed seal (rotary lip force, FE
        lip, FE maps, analytic O-ring estimate): the stress of a held squeeze relaxes, so the
        sealing force follows the relaxation modulus E(t_h, T) at the holding time t_h, taken
        from the master curve as E'(T, f = 1/(2π t_h)) (:func:`held_frequency`).  Between T_g
        and ≈ 100 °C it is nearly flat for the catalogue rubbers (NBR 4.1 MPa at 20 °C,
        3.8 MPa at 60 °C, 4.0 MPa at 100 °C), far below the 1 Hz modulus the hyperelastic
        constants hold for (NBR 8.5 MPa at 20 °C), and it climbs towards the glass near T_g.

        With ``mounting_temperature`` T_m it is the modulus of the stress that was *installed*
        at T_m and then brought to T: that stress relaxes as far as the longer of the two
        reduced times allows, t_h/a_T(T_m) and t_h/a_T(T) (Morland & Lee 1960), i.e. the
        reduced frequency min(a_T(T_m), a_T(T))/(2π t_h).  A lip mounted warm and cooled keeps
        the stress it relaxed to at T_m (only the entropic factor of the plateau follows T);
        a lip warmed after mounting relaxes further, as if mounted warm.

        Parameters
        ----------
        temperature : array_like
            T [K].
        hold_time : float
            t_h [s], > 0 (default :data:`HELD_SEAL_TIME`).
        mounting_temperature : array_like, optional
            T_m [K] at which the held stress was installed; default T.

        Returns
        -------
        float or numpy.ndarray
            E [Pa].

        Examples
        --------
        >>> nbr = get_elastomer("NBR")
        >>> round(nbr.held_modulus(293.15) / 1e6, 2), round(nbr.held_modulus(253.15) / 1e6, 1)
        (4.09, 16.5)

        Mounted at 20 °C and cooled to −20 °C, the installed stress stays at its 20 °C
        relaxation (the plateau's entropic factor aside):

        >>> round(nbr.held_modulus(253.15, mounting_temperature=293.15) / 1e6, 2)
        3.57
        """
        t_h = _scalar(hold_time, "hold_time", "s", lo=0.0, lo_open=True)
        t = self._check(temperature, False, stacklevel=3)
        if mounting_temperature is None:
            return _out(self._modulus(t, np.full(t.shape, held_frequency(t_h))))
        t_m = self._check(mounting_temperature, False, stacklevel=3)
        t, t_m = _broadcast(t, t_m, names="temperature and mounting_temperature")
        shift = self._log10_shift(t)
        return _out(self._modulus(t, self._mounted_frequency(t_h, t_m, shift), shift))

    def _mounted_frequency(self, hold_time: float, mounting_temperature: np.ndarray,
                           log10_shift: np.ndarray) -> np.ndarray:
        """Reduced frequency [Hz] of a stress installed at T_m and held at T (log10 a_T(T) =
        ``log10_shift``): min(a_T(T_m), a_T(T))/(2π t_h), see :meth:`held_modulus`."""
        return held_frequency(hold_time) * 10.0 ** np.minimum(
            self._log10_shift(mounting_temperature) - log10_shift, 0.0)

    def mounted_and_held_modulus(self, temperature: Any, mounting_temperature: Any,
                                 hold_time: float = HELD_SEAL_TIME) -> tuple:
        """Both moduli of a lip mounted at T_m and brought to T [Pa]: that of the stress
        installed at T_m, ``held_modulus(T, mounting_temperature=T_m)``, and that of the
        increment since, ``held_modulus(T)`` (the two of :func:`sealsim.rotary.lip.
        lip_stress_ratio`), evaluated together: the checks and the shift factor at T once.

        Parameters
        ----------
        temperature : array_like
            T [K].
        mounting_temperature : array_like
            T_m [K].
        hold_time : float
            t_h [s], > 0.

        Returns
        -------
        tuple of float or numpy.ndarray
            (E_m, E_h) [Pa].

        Examples
        --------
        >>> e_m, e_h = get_elastomer("NBR").mounted_and_held_modulus(253.15, 293.15)
        >>> round(e_m / 1e6, 2), round(e_h / 1e6, 1)
        (3.57, 16.5)
        """
        t_h = _scalar(hold_time, "hold_time", "s", lo=0.0, lo_open=True)
        t = self._check(temperature, False, stacklevel=3)
        t_m = self._check(mounting_temperature, False, stacklevel=3)
        t, t_m = _broadcast(t, t_m, names="temperature and mounting_temperature")
        shift = self._log10_shift(t)
        return (_out(self._modulus(t, self._mounted_frequency(t_h, t_m, shift), shift)),
                _out(self._modulus(t, np.full(t.shape, held_frequency(t_h)), shift)))

    def shear_modulus(self, temperature: Any, frequency: Any = None) -> np.ndarray | float:
        """Small-strain shear modulus G = E/3 [Pa] (incompressible).

        Parameters
        ----------
        temperature : array_like
            T [K].
        frequency : array_like, optional
            f [Hz]; default ``test_frequency``.

        Returns
        -------
        float or numpy.ndarray
            G [Pa].

        Examples
        --------
        >>> get_elastomer("NBR").shear_modulus(293.15) / 1e6
        2.83
        """
        t, f = self._t_f(temperature, frequency, warn=True)
        return _out(self._modulus(t, f) / 3.0)

    def mooney_rivlin(
        self, temperature: Any, frequency: Any = None, *, scale_bulk: bool = False
    ) -> tuple[np.ndarray | float, np.ndarray | float, np.ndarray | float]:
        r"""Mooney–Rivlin constants (C10, C01, K) [Pa] at temperature T.

        .. math::

            C_{10}(T) = C_{10}\,\frac{E(T)}{E(T_\mathrm{ref})},\quad
            C_{01}(T) = C_{01}\,\frac{E(T)}{E(T_\mathrm{ref})},\quad K(T) = K

        with E at ``frequency`` (default the test frequency). This is how temperature enters
        the hyperelastic FE model: the shape of the strain-energy function (C01/C10) is kept,
        its stiffness follows the small-strain modulus. The bulk modulus is kept constant by
        default: K of a rubber is set by intermolecular forces and changes little with T,
        whereas scaling it by E(T) would give absurd values in the glass. ``scale_bulk=True``
        scales it too (keeps the Poisson ratio constant). The hyperelastic model is only
        meaningful in the rubbery region (T above ≈ T_g + 25 K at 1 Hz).

        Parameters
        ----------
        temperature : array_like
            T [K].
        frequency : array_like, optional
            f [Hz]; default ``test_frequency``.
        scale_bulk : bool, default False
            Also scale K by E(T)/E(T_ref).

        Returns
        -------
        tuple
            (C10 [Pa], C01 [Pa], K [Pa]).

        References
        ----------
        Mooney 1940; Rivlin 1948 [L].

        Examples
        --------
        >>> c10, c01, k = get_elastomer("NBR").mooney_rivlin(296.15)
        >>> round(c10 / 1e6, 3), round(c01 / 1e6, 3), k / 1e6
        (1.064, 0.266, 2000.0)
        """
        t, f = self._t_f(temperature, frequency, warn=True)
        ratio = self._modulus(t, f) / self._modulus(np.asarray(self.reference_temperature), f)
        k = self.bulk_modulus * ratio if scale_bulk else self.bulk_modulus * np.ones_like(ratio)
        return _out(self.c10 * ratio), _out(self.c01 * ratio), _out(k)

    def modulus_ratio(
        self,
        temperature: Any,
        reference_temperature: float | None = None,
        scaling: str = "held",
        frequency: Any = None,
        mounting_temperature: float | None = None,
    ) -> np.ndarray | float:
        r"""Stiffness of the seal at T relative to T_ref, E(T)/E(T_ref), for the hyperelastic
        constants and the analytic contact estimate (one law for both).

        * ``"held"`` (sealsim's convention for an installed seal): the relaxed modulus of a seal
          held for :data:`HELD_SEAL_TIME` (:meth:`held_modulus`, installed at
          ``mounting_temperature``) relative to the modulus at the test frequency at T_ref,
          E_h(T)/E(T_ref, f_test) -- the modulus the hyperelastic constants and
          E = 6·(C10 + C01) hold for; so it scales their level too (catalogue NBR: 0.48 at
          20 °C) and follows the master curve in T (nearly flat from 0 to 100 °C; a seal
          cooled after installation keeps the stress it relaxed to).
        * ``"entropic"``: T/T_ref, the equilibrium modulus of rubber elasticity
          (:func:`~sealsim.properties.rubber_modulus.entropic_modulus`). It is the
          stiffness of a seal held at constant squeeze long enough for the viscoelastic
          stresses to relax -- an installed static or slowly moving seal well above T_g -- and
          it rises with T.
        * ``"modulus"``: E(T, f)/E(T_ref, f) of :meth:`modulus`, the dynamic (storage) modulus
          at the rate of interest f. Between T_g and ≈ 100 °C it falls with T (the
          glass-transition tail relaxes faster when warm): the stiffness of a deformation
          that lasts about 1/f, not of a long-held squeeze.
        * ``"none"``: 1.

        Parameters
        ----------
        temperature : array_like
            T [K] (allowed range of the material; no service-range warning).
        reference_temperature : float, optional
            T_ref [K]; default the material's reference temperature.
        scaling : {"held", "entropic", "modulus", "none"}
            See above.
        frequency : float, optional
            f [Hz] for ``"modulus"``; default ``test_frequency``.
        mounting_temperature : float, optional
            For ``"held"``: temperature [K] at which the seal was installed; default T.

        Returns
        -------
        float or numpy.ndarray
            E(T)/E(T_ref) [-].

        References
        ----------
        Treloar (1975), ch. 4 [L]; J. D. Ferry, Viscoelastic Properties of Polymers, 3rd ed.,
        Wiley 1980, ch. 11 and 12 (transition zone) [L].

        Examples
        --------
        From 25 to 55 °C the equilibrium stiffness of NBR rises 10 %, its 1 Hz modulus falls 26 %:

        >>> nbr = get_elastomer("NBR")
        >>> [round(nbr.modulus_ratio(328.15, 298.15, s), 3) for s in ("entropic", "modulus")]
        [1.101, 0.742]
        """
        t_ref = (self.reference_temperature if reference_temperature is None
                 else reference_temperature)
        if scaling not in TEMPERATURE_SCALINGS:
            raise InputError(f"temperature scaling {scaling!r} is not allowed; choose one of "
                             f"{', '.join(TEMPERATURE_SCALINGS)}")
        t = self._check(temperature, False, stacklevel=3)
        t0 = self._check(t_ref, False, stacklevel=3)
        if t0.ndim != 0:
            raise InputError("reference_temperature must be a single number [K]")
        if scaling == "entropic":
            return _out(entropic_modulus(1.0, t, t0))
        if scaling == "none":
            return _out(np.ones_like(t))
        if scaling == "held":
            reference = self._modulus(t0, np.asarray(self.test_frequency))
            held = self.held_modulus(t, mounting_temperature=mounting_temperature)
            return _out(np.asarray(held) / reference)
        t, f = self._t_f(t, frequency, warn=False)
        return _out(self._modulus(t, f) / self._modulus(t0, f[()] if f.ndim == 0 else f))

    def relaxation_modulus(self, time: Any, temperature: Any) -> np.ndarray | float:
        r"""Relaxation modulus E(t, T) [Pa] from the Prony series and time–temperature shift.

        .. math::

            E(t, T) = E_\infty\,\frac{T}{T_p}
                      + \sum_i E_i\,\exp\!\left(-\frac{t}{a_T\,\tau_i}\right),
            \quad a_T = \frac{a_T(T)}{a_T(T_p)}

        T_p is ``prony_reference_temperature``; as in the master curve only the equilibrium
        part carries the entropic factor.

        Parameters
        ----------
        time : array_like
            t [s], >= 0.
        temperature : array_like
            T [K] (constant during the relaxation), broadcast with ``time``.

        Returns
        -------
        float or numpy.ndarray
            E [Pa].

        Examples
        --------
        >>> nbr = get_elastomer("NBR")
        >>> nbr.relaxation_modulus(1e9, 296.15) / 1e6
        2.68
        """
        if self.prony is None:
            raise InputError(
                f"{self.name} has no Prony series: give one in the [{self.name}.prony] table"
            )
        tt = _array(time, "time", "s", lo=0.0)
        t = self._check(temperature, True, stacklevel=3)
        tt, t = _broadcast(tt, t, names="time and temperature")
        e_inf, e_i, tau_i = self.prony
        t_p = float(self.prony_reference_temperature)  # type: ignore[arg-type]
        a = 10.0 ** (self._log10_shift(t) - self._log10_shift(np.asarray(t_p)))
        xi = tt / a
        e = e_inf * t / t_p + np.sum(
            np.asarray(e_i) * np.exp(-xi[..., None] / np.asarray(tau_i)), axis=-1
        )
        return _out(e)

    def modulus_minimum_temperature(self, frequency: float | None = None) -> float:
        """Temperature [K] where E(T, f) stops decreasing (the entropic rise takes over).

        E decreases from T_g − 40 K (or the lower end of the DMA table) up to this temperature.
        Found on a 0.25 K grid over the allowed range and refined with a bounded scalar
        minimisation; if E decreases throughout, the upper end is returned.

        Parameters
        ----------
        frequency : float, optional
            f [Hz]; default ``test_frequency``.

        Returns
        -------
        float
            T* [K].

        Examples
        --------
        >>> round(get_elastomer("NBR").modulus_minimum_temperature() - 273.15)
        108
        """
        f = (
            self.test_frequency
            if frequency is None
            else _scalar(frequency, "frequency", "Hz", lo=0.0, lo_open=True)
        )
        lo, hi = self.allowed_range
        lo = max(lo, self.glass_transition - 40.0)
        if self.dma_table is not None:
            lo, hi = max(lo, self.dma_table[0][0]), min(hi, self.dma_table[0][-1])
        grid = np.linspace(lo, hi, max(int((hi - lo) / 0.25), 3) + 1)
        log_e = np.log10(self._modulus(grid, np.full_like(grid, f)))
        i = int(np.argmin(log_e))
        if i == grid.size - 1:
            return float(hi)
        if i == 0:
            return float(lo)
        res = minimize_scalar(
            lambda x: float(np.log10(self._modulus(np.asarray(x), np.asarray(f)))),
            bounds=(grid[i - 1], grid[i + 1]),
            method="bounded",
            options={"xatol": 1e-4},
        )
        return float(res.x)

    @property
    def glassy_expansion(self) -> float:
        """Linear CTE of the glassy state α_g [1/K]: ``glassy_thermal_expansion`` where given
        (measured, e.g. by dilatometry), else the Simha–Boyer estimate 0.31·α_r
        (:func:`~sealsim.properties.thermal_expansion.simha_boyer_glassy_expansion`; no
        compound of the catalogue gives a measured glassy value).

        Examples
        --------
        >>> round(get_elastomer("NBR").glassy_expansion * 1e4, 3)
        0.591
        """
        if self.glassy_thermal_expansion is not None:
            return self.glassy_thermal_expansion
        return float(simha_boyer_glassy_expansion(self.thermal_expansion))

    @property
    def structural_relaxation(self) -> tuple[np.ndarray, np.ndarray] | None:
        """Normalised weights w_i [-] and times τ_i [s] (at the Prony reference temperature)
        of the volume (structural) relaxation, or None without a Prony series.

        Assumption [D]: the volume relaxes with the spectrum of the shear relaxation,
        w_i = E_i / Σ E_j, and the same shift factor a_T(T) (thermorheologically simple, the
        x = 1 case of Narayanaswamy's shift). Check (tests): cooled at 10 K/min, the catalogue
        NBR freezes at T_f = −30 °C, 5 K below its DSC T_g of −25 °C, and the freezing
        temperature moves by 2.8 K per decade of cooling rate as Moynihan's relation
        d(1/T_f')/d log10 q = −1/B predicts for the Arrhenius shift below T_g.
        """
        if self.prony is None:
            return None
        e_i = np.asarray(self.prony[1])
        if e_i.sum() <= 0.0:
            return None
        return e_i / e_i.sum(), np.asarray(self.prony[2])

    def fictive_temperature(self, time: Any, temperature: Any) -> np.ndarray:
        r"""Fictive temperature T_f [K] along a temperature history T(t).

        :func:`~sealsim.properties.viscoelasticity.fictive_temperature` with
        :attr:`structural_relaxation` and the shift factor of this material at each interval's
        mid temperature (relative to the Prony reference temperature); equilibrium (T_f = T) at
        the start. The free thermal strain then is
        :func:`~sealsim.properties.thermal_expansion.thermal_strain` with
        α_r = ``thermal_expansion``, α_g = :attr:`glassy_expansion`.

        Parameters
        ----------
        time : array_like
            Strictly increasing times t [s], 1-D.
        temperature : array_like
            T [K] at those times (allowed range of the material).

        Returns
        -------
        numpy.ndarray
            T_f [K].

        Examples
        --------
        Cooling the catalogue NBR at 1 K/min from 20 °C to −60 °C: the structure freezes
        near −33 °C.

        >>> T = np.linspace(293.15, 213.15, 161)
        >>> t = (T[0] - T) * 60.0
        >>> round(float(get_elastomer("NBR").fictive_temperature(t, T)[-1]) - 273.15, 1)
        -33.0
        """
        spectrum = self.structural_relaxation
        if spectrum is None:
            raise InputError(
                f"{self.name} has no Prony series, so its structural relaxation (glass "
                f"transition of the thermal expansion) is not defined; give [{self.name}.prony]")
        tt = _array(time, "time", "s")
        t = self._check(temperature, False, stacklevel=3)
        if tt.ndim != 1 or t.shape != tt.shape or np.any(np.diff(tt) <= 0.0):
            raise InputError("time must be strictly increasing and match temperature (1-D)")
        t_p = float(self.prony_reference_temperature)  # type: ignore[arg-type]
        log_a = self._log10_shift(0.5 * (t[1:] + t[:-1])) - self._log10_shift(np.asarray(t_p))
        with np.errstate(over="ignore", under="ignore"):
            dxi = np.diff(tt) / 10.0**log_a
        return fictive_temperature(t, dxi, *spectrum)

    @property
    def thermal_diffusivity(self) -> float:
        """Thermal diffusivity k/(ρ c_p) [m²/s]."""
        return self.thermal_conductivity / (self.density * self.specific_heat)

    def constants_modulus_mismatch(self) -> float:
        """Relative difference 6·(C10 + C01)/E(T_ref, f_test) − 1 [-] between the small-strain
        modulus of the hyperelastic constants and the modulus curve at the reference
        temperature and the test frequency, where the constants hold
        (:data:`CONSTANTS_CURVE_TOLERANCE`).

        Examples
        --------
        >>> abs(get_elastomer("NBR").constants_modulus_mismatch()) < 0.001
        True
        """
        t, f = self._t_f(self.reference_temperature, None, warn=False)
        return float(6.0 * (self.c10 + self.c01) / float(self._modulus(t, f)) - 1.0)

    @property
    def shear_modulus_reference(self) -> float:
        """Small-strain shear modulus 2(C10 + C01) [Pa] of the hyperelastic constants."""
        return 2.0 * (self.c10 + self.c01)

    # -- TOML construction -----------------------------------------------------------------------

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], name: str | None = None) -> Elastomer:
        """Build an elastomer from a TOML table of an elastomer file.

        The format is that of ``data/elastomers.toml`` (quantities with units, see
        :class:`sealsim.properties.catalogue.ElastomerEntry`); tables in the older format
        (units in the key names, ``glass_transition_C = -30``) are read too.  Unknown,
        missing or invalid fields raise :class:`InputError` naming the field.

        Parameters
        ----------
        data : mapping
            The material's table.
        name : str, optional
            Material name; default ``data["name"]`` (the table key when read from a file).

        Returns
        -------
        Elastomer

        Examples
        --------
        >>> d = {"glass_transition": "-30 degC", "density": "1250 kg/m^3",
        ...      "thermal_conductivity": "0.25 W/(m*K)", "specific_heat": "1700 J/(kg*K)",
        ...      "thermal_expansion": "2e-4 1/K", "c10": "1.0 MPa", "c01": "0.25 MPa",
        ...      "bulk_modulus": "2000 MPa", "service_min": "-40 degC",
        ...      "service_max": "100 degC",
        ...      "modulus": {"glassy": "2000 MPa", "rubbery": "2.7 MPa"}}
        >>> Elastomer.from_dict(d, name="myNBR").wlf_reference_temperature
        243.15
        """
        return _from_dict(data, name)


# ---------------------------------------------------------------------------------------------
# TOML format (models and reading: sealsim.properties.catalogue)
# ---------------------------------------------------------------------------------------------


def _from_dict(data: Mapping[str, Any], name: str | None) -> Elastomer:
    from sealsim.properties.catalogue import read_elastomer_table

    return _build(*read_elastomer_table(data, name))


def _build(name: str, entry: Any, where: str, names: Mapping[str, str]) -> Elastomer:
    """The Elastomer of a validated file entry; a failed physical check names the field as
    written in the file."""
    from sealsim.properties.catalogue import elastomer_key

    kwargs = {"wlf_c1": WLF_UNIVERSAL.c1, "wlf_c2": WLF_UNIVERSAL.c2,
              **entry.elastomer_arguments(name)}
    try:
        material = Elastomer(**kwargs)
    except InputError as exc:
        field = getattr(exc, "field", None)
        prefix = f"{where}: field '{elastomer_key(field, names)}'" if field else where
        raise InputError(f"{prefix} (checked after conversion to SI units): {exc}") from None
    mismatch = material.constants_modulus_mismatch()
    if abs(mismatch) > CONSTANTS_CURVE_TOLERANCE:
        curve = 6.0 * (material.c10 + material.c01) / (1.0 + mismatch)
        warnings.warn(
            f"{where}: the hyperelastic constants give E = 6(C10 + C01) = "
            f"{6e-6 * (material.c10 + material.c01):.3g} MPa, the modulus curve "
            f"{curve / 1e6:.3g} MPa at the reference temperature "
            f"({material.reference_temperature - 273.15:g} degC) and the test frequency "
            f"({material.test_frequency:g} Hz), {mismatch:+.0%}: a held seal's stiffness is the "
            "constants times the curve's relative change, so the FE force level follows the "
            "constants; make the two describe the same rubber (scale the curve's moduli or "
            "the constants)",
            CompoundConsistencyWarning, stacklevel=3)
    return material


def load_elastomer_file(path: str | Path) -> dict[str, Elastomer]:
    """Read every elastomer table of a TOML file in the catalogue format.

    The format (quantities with units, like case files) is described in
    :mod:`sealsim.properties.catalogue`.

    Parameters
    ----------
    path : str or pathlib.Path
        TOML file; each top-level table is one material, its key the name.

    Returns
    -------
    dict
        name → :class:`Elastomer`.

    Examples
    --------
    >>> from sealsim.properties.elastomers import _catalogue_path
    >>> sorted(load_elastomer_file(_catalogue_path()))
    ['ACM', 'FKM', 'HNBR', 'NBR', 'VMQ']
    """
    from sealsim.files import read_input_text
    from sealsim.properties.catalogue import read_elastomer_tables

    text = read_input_text(path, "elastomer file")
    return {key: _build(*table) for key, table
            in read_elastomer_tables(text, f"elastomer file {str(path)!r}").items()}


# ---------------------------------------------------------------------------------------------
# catalogue
# ---------------------------------------------------------------------------------------------


def _catalogue_path() -> Path:
    return Path(str(resources.files("sealsim.properties").joinpath("data/elastomers.toml")))


@functools.lru_cache(maxsize=1)
def _catalogue() -> dict[str, Elastomer]:
    return {k.upper(): v for k, v in load_elastomer_file(_catalogue_path()).items()}


def list_elastomers() -> list[str]:
    """Names of the catalogue elastomers.

    Returns
    -------
    list of str

    Examples
    --------
    >>> list_elastomers()
    ['NBR', 'HNBR', 'FKM', 'ACM', 'VMQ']
    """
    return list(_catalogue())


def is_compound_file(name: Any) -> bool:
    """True if a material reference names a compound file (``"my_nbr.toml"``), not a
    catalogue name."""
    return isinstance(name, str) and name.strip().lower().endswith(".toml")


def compound_file_digest(name: Any) -> str:
    """SHA-256 (16 hex digits) of a compound file's bytes, ``""`` for a catalogue name: for
    cache keys of results that depend on the file's content, not only on its path."""
    if not is_compound_file(name):
        return ""
    import hashlib

    try:
        return hashlib.sha256(Path(name.strip()).read_bytes()).hexdigest()[:16]
    except OSError:
        return ""


@functools.lru_cache(maxsize=32)
def _compound(path: str, mtime_ns: int, size: int) -> Elastomer:
    materials = load_elastomer_file(path)
    if len(materials) != 1:
        raise InputError(f"compound file {path!r} holds {len(materials)} materials "
                         f"({', '.join(materials)}); a material given by its file must be "
                         "the only table in it (or use --material-file and its name)")
    return next(iter(materials.values()))


def load_compound(path: str | Path) -> Elastomer:
    """The one material of a compound file (the catalogue format, e.g. written by
    ``sealsim material fit``); read again when the file changes.

    Raises
    ------
    InputError
        A missing file, invalid content, or not exactly one material table.
    """
    p = Path(str(path).strip())
    try:
        stat = p.stat()
    except OSError:
        raise InputError(f"compound file {str(p)!r} cannot be read: it does not exist "
                         "(a relative path is relative to the case file, or to the current "
                         "folder from Python)") from None
    return _compound(str(p), stat.st_mtime_ns, stat.st_size)


def get_elastomer(name: str) -> Elastomer:
    """Catalogue elastomer by name (case-insensitive), or the compound of a file.

    Parameters
    ----------
    name : str
        "NBR", "HNBR", "FKM", "ACM" or "VMQ"; or the path of a compound file ending in
        ``.toml`` (one material table in the catalogue format, :func:`load_compound`).

    Returns
    -------
    Elastomer

    Raises
    ------
    InputError
        Unknown name; the message lists close matches and the available names.

    Examples
    --------
    >>> get_elastomer("fkm").glass_transition
    255.15
    """
    cat = _catalogue()
    if not isinstance(name, str):
        raise InputError(f"elastomer name must be a string; got {name!r}")
    if is_compound_file(name):
        return load_compound(name)
    key = name.strip().upper()
    if key in cat:
        return cat[key]
    close = difflib.get_close_matches(key, list(cat), n=3, cutoff=0.4)
    hint = f" Did you mean {', '.join(close)}?" if close else ""
    raise InputError(
        f"unknown elastomer {name!r}.{hint} Available: {', '.join(cat)} ('sealsim material "
        f"list'), or the path of a compound file ending in .toml (e.g. written by 'sealsim "
        f"material fit')"
    )
