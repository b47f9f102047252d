"""Property tables of oils and elastomers in engineering units, ready to print or save.

What ``sealsim oil ...`` and ``sealsim material ...`` show, as plain data: catalogue rows
(dicts with the unit in each key name, e.g. ``nu40_mm2_s``), property tables at temperatures
given in °C, and curves on a temperature grid (pandas DataFrames, the CSV files of the plot
commands).  Temperatures outside the range of a model are refused with a message in °C that
names the input (``field``); values a curve cannot show are left empty (NaN), never
extrapolated.  The physics is in :mod:`sealsim.properties.oils` and
:mod:`sealsim.properties.elastomers`; this module only evaluates and converts units.

Examples
--------
>>> from sealsim.properties import get_oil
>>> rows, notes = oil_rows(get_oil("VG68"), [40.0, 100.0])
>>> [round(r["nu_mm2_s"], 2) for r in rows], notes
([68.0, 8.7], [])
"""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np
import pandas as pd

from sealsim.errors import InputError
from sealsim.properties import oils as oils_module
from sealsim.properties.elastomers import Elastomer, ServiceRangeWarning, get_elastomer
from sealsim.properties.oils import Oil, OilRangeWarning
from sealsim.units import ZERO_CELSIUS_K

__all__ = [
    "celsius",
    "check_celsius",
    "default_material_temperatures",
    "find_material",
    "material_details",
    "material_rows",
    "material_summary",
    "modulus_curves",
    "oil_property_laws",
    "oil_rows",
    "oil_summary",
    "unique_by_name",
    "viscosity_curves",
]


def celsius(kelvin: float) -> float:
    """Temperature [K] in °C.

    >>> celsius(293.15)
    20.0
    """
    return float(kelvin) - ZERO_CELSIUS_K


def check_celsius(values: list[float], lo_k: float, hi_k: float, field: str,
                  what: str) -> np.ndarray:
    """Temperatures [°C] → K, refusing values outside [lo_k, hi_k] with a message in °C.

    Parameters
    ----------
    values : list of float
        Temperatures [°C].
    lo_k, hi_k : float
        Allowed range [K].
    field : str
        Name of the input, for the message (e.g. ``"--temperatures"``).
    what : str
        What the range is, for the message.
    """
    t = np.asarray(values, dtype=float) + ZERO_CELSIUS_K
    bad = t[(t < lo_k) | (t > hi_k)]
    if bad.size:
        raise InputError(f"{field}: {celsius(bad[0]):g} degC is outside {what}; allowed: "
                         f"{celsius(lo_k):.2f} to {celsius(hi_k):.2f} degC")
    return t


def unique_by_name(items: list[Any]) -> list[Any]:
    """Items without repeats (by name), in order: ``VG68`` and ``VG68-mineral`` are one oil."""
    seen: dict[str, Any] = {}
    for item in items:
        seen.setdefault(item.name, item)
    return list(seen.values())


# -- oils ---------------------------------------------------------------------------------------

def oil_summary(oil: Oil, origin: str = "catalogue") -> dict[str, Any]:
    """Catalogue row of an oil (units in the key names).

    Keys: name, family, origin, nu40_mm2_s, nu100_mm2_s, viscosity_index, rho15_kg_m3,
    min_temperature_C, source.
    """
    return {
        "name": oil.name,
        "family": oil.family,
        "origin": origin,
        "nu40_mm2_s": oil.nu40 * 1e6,
        "nu100_mm2_s": oil.nu100 * 1e6,
        "viscosity_index": oil.viscosity_index,
        "rho15_kg_m3": oil.rho15,
        "min_temperature_C": celsius(oil.min_temperature),
        "source": oil.source,
    }


def oil_property_laws(oil: Oil) -> str:
    """Which law and which values give an oil's density, conductivity and heat capacity.

    Examples
    --------
    >>> from sealsim.properties import get_oil
    >>> print(oil_property_laws(get_oil("VG68-PAO")))
    ρ: ASTM D1250 volume correction, α15 = 7.43e-4 1/K (the tables' value for petroleum \
oils); k: constant 0.145 W/(m K) (PAO default); c_p: constant 2200 J/(kg K) (PAO default)
    """
    def constant(value, unit, default):
        if value is None:
            return "Cragoe (NBS 1929, petroleum oils)"
        return f"constant {value:g} {unit}" + (f" ({oil.family} default)"
                                               if value == default else "")

    k_default, cp_default = oils_module.DEFAULT_THERMAL.get(oil.family, (None, None))
    given = not math.isclose(oil.thermal_expansion, oils_module.expansion_d1250(oil.rho15))
    note = (" (given)" if given else "" if oil.family == "mineral"
            else " (the tables' value for petroleum oils)")
    return (f"ρ: ASTM D1250 volume correction, α15 = {oil.thermal_expansion * 1e4:.3g}e-4 1/K"
            + note
            + f"; k: {constant(oil.thermal_conductivity_value, 'W/(m K)', k_default)}"
            + f"; c_p: {constant(oil.specific_heat_value, 'J/(kg K)', cp_default)}")


def oil_rows(oil: Oil, temperatures_c: list[float], field: str = "temperatures"
             ) -> tuple[list[dict[str, float]], list[str]]:
    """Property table of an oil at temperatures [°C] and the notes to show with it.

    Rows have temperature_C, nu_mm2_s, eta_Pa_s, rho_kg_m3, k_W_mK, cp_J_kgK.  Raises
    InputError (naming ``field``) for temperatures below the oil's minimum temperature or
    outside the range of the correlations; a viscosity below 2 mm²/s (extrapolated ASTM D341)
    is a note.
    """
    t = check_celsius(temperatures_c, *oils_module.T_RANGE, field,
                      "the range of the oil correlations")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", OilRangeWarning)
        oil.check_temperature(t, name=field)
    notes = [str(w.message) for w in caught if issubclass(w.category, OilRangeWarning)]
    nu = np.atleast_1d(oil.kinematic_viscosity(t))
    eta = np.atleast_1d(oil.dynamic_viscosity(t))
    rho = np.atleast_1d(oil.density(t))
    k = np.atleast_1d(oil.thermal_conductivity(t))
    cp = np.atleast_1d(oil.specific_heat(t))
    rows = [{"temperature_C": float(tc), "nu_mm2_s": float(nu[i] * 1e6),
             "eta_Pa_s": float(eta[i]), "rho_kg_m3": float(rho[i]), "k_W_mK": float(k[i]),
             "cp_J_kgK": float(cp[i])} for i, tc in enumerate(temperatures_c)]
    return rows, notes


def viscosity_curves(oils: list[Oil], temperatures_c: np.ndarray,
                     field: str = "temperatures") -> tuple[pd.DataFrame, list[str]]:
    """ν(T) of each oil on a grid [°C]: a DataFrame (the CSV) and notes on omitted ranges.

    Columns temperature_C and nu_NAME_mm2_s per oil.  Values below an oil's minimum
    temperature or with ν < 2 mm²/s (outside ASTM D341) are left empty (NaN) rather than
    extrapolated.
    """
    t = check_celsius(list(temperatures_c), *oils_module.T_RANGE, field,
                      "the range of the oil correlations")
    frame = pd.DataFrame({"temperature_C": temperatures_c})
    notes = []
    for oil in oils:
        with np.errstate(over="ignore"):
            nu = np.asarray(oil.kinematic_viscosity(t), dtype=float)
        cold = t < oil.min_temperature
        thin = ~cold & ~(nu >= oils_module.NU_MIN_D341)
        if cold.any():
            notes.append(f"{oil.name}: not drawn below {celsius(oil.min_temperature):.0f} degC "
                         "(its lowest temperature of use)")
        if thin.any():
            notes.append(f"{oil.name}: not drawn from {celsius(t[thin].min()):.0f} degC up "
                         "(viscosity below 2 mm^2/s, outside ASTM D341)")
        frame[f"nu_{oil.name}_mm2_s"] = np.where(cold | thin, np.nan, nu * 1e6)
    return frame, notes


# -- elastomers ---------------------------------------------------------------------------------

def find_material(name: str, extra: dict[str, Elastomer]) -> Elastomer:
    """Material ``name`` (case-insensitive) from ``extra`` first, then the catalogue."""
    for key, material in extra.items():
        if key.casefold() == name.strip().casefold():
            return material
    try:
        return get_elastomer(name)
    except InputError as exc:
        if extra:
            raise InputError(f"{exc}; the material file defines: {', '.join(extra)}") from None
        raise


def material_summary(m: Elastomer, origin: str = "catalogue") -> dict[str, Any]:
    """Catalogue row of an elastomer (units in the key names).

    Keys: name, description, origin, glass_transition_C, service_min_C, service_max_C,
    density_kg_m3, hardness_shore_a, reference_temperature_C, test_frequency_Hz,
    E_reference_Pa (E at the reference temperature and test frequency), source.
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ServiceRangeWarning)
        e_ref = m.modulus(m.reference_temperature)
    return {
        "name": m.name,
        "description": m.description,
        "origin": origin,
        "glass_transition_C": celsius(m.glass_transition),
        "service_min_C": celsius(m.service_range[0]),
        "service_max_C": celsius(m.service_range[1]),
        "density_kg_m3": m.density,
        "hardness_shore_a": m.hardness_shore_a,
        "reference_temperature_C": celsius(m.reference_temperature),
        "test_frequency_Hz": m.test_frequency,
        "E_reference_Pa": float(e_ref),
        "source": m.source,
    }


def material_details(m: Elastomer, origin: str = "catalogue") -> dict[str, Any]:
    """All properties of an elastomer: :func:`material_summary` plus thermal, hyperelastic,
    WLF and master-curve values and the modulus model (``"DMA table"``/``"master curve"``)."""
    return {
        **material_summary(m, origin),
        "thermal_conductivity_W_mK": m.thermal_conductivity,
        "specific_heat_J_kgK": m.specific_heat,
        "thermal_expansion_1_K": m.thermal_expansion,
        "c10_Pa": m.c10,
        "c01_Pa": m.c01,
        "bulk_modulus_Pa": m.bulk_modulus,
        "wlf_c1": m.wlf_c1,
        "wlf_c2_K": m.wlf_c2,
        "wlf_reference_temperature_C": celsius(m.wlf_reference_temperature),
        "glassy_modulus_Pa": m.glassy_modulus,
        "rubbery_modulus_Pa": m.rubbery_modulus,
        "modulus_model": "DMA table" if m.dma_table is not None else "master curve",
    }


def default_material_temperatures(m: Elastomer) -> list[float]:
    """Service range in 20 °C steps [°C] (both ends included).

    >>> from sealsim.properties import get_elastomer
    >>> default_material_temperatures(get_elastomer("NBR"))
    [-40.0, -20.0, 0.0, 20.0, 40.0, 60.0, 80.0, 100.0]
    """
    # to 0.01 K inwards: a limit rounded outwards (59.6911 -> 59.69 degC) is outside service
    lo = math.ceil(round(celsius(m.service_range[0]) * 100.0, 6)) / 100.0
    hi = math.floor(round(celsius(m.service_range[1]) * 100.0, 6)) / 100.0
    inner = np.arange(math.ceil(lo / 20.0) * 20.0, hi, 20.0)
    return [lo] + [float(v) for v in inner if lo + 5.0 < v < hi - 5.0] + [hi]


def material_rows(m: Elastomer, temperatures_c: list[float], frequency: float,
                  field: str = "temperatures") -> tuple[list[dict[str, float]], list[str]]:
    """E(T) and a_T of a material at temperatures [°C]; notes for values outside service.

    Rows have temperature_C, E_Pa (at ``frequency`` [Hz]), a_T and log10_a_T (WLF shift
    relative to the WLF reference temperature).
    """
    lo, hi = m.allowed_range
    t = check_celsius(temperatures_c, lo, hi, field,
                      f"the range where the {m.name} model is meaningful (T_g - 100 K to the "
                      "service maximum + 50 K)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ServiceRangeWarning)  # reported below, in degC
        e = np.atleast_1d(m.modulus(t, frequency))
        log_at = np.atleast_1d(m.log10_shift_factor(t))
    s_lo, s_hi = m.service_range
    outside = [tc for tc, tk in zip(temperatures_c, t, strict=True) if not s_lo <= tk <= s_hi]
    notes = []
    if outside:
        notes.append(f"{m.name}: {', '.join(f'{v:g}' for v in outside)} degC outside the service "
                     f"range {celsius(s_lo):g} to {celsius(s_hi):g} degC; values shown for "
                     "information")
    rows = [{"temperature_C": float(tc), "E_Pa": float(e[i]), "a_T": float(10.0 ** log_at[i]),
             "log10_a_T": float(log_at[i])} for i, tc in enumerate(temperatures_c)]
    return rows, notes


def modulus_curves(materials: list[Elastomer], temperatures_c: np.ndarray, frequency: float
                   ) -> pd.DataFrame:
    """E(T) [Pa] of each material on a grid [°C] (columns temperature_C, E_NAME_Pa); empty
    (NaN) outside its allowed range."""
    t = np.asarray(temperatures_c, dtype=float) + ZERO_CELSIUS_K
    frame = pd.DataFrame({"temperature_C": temperatures_c})
    for m in materials:
        lo, hi = m.allowed_range
        ok = (t >= lo) & (t <= hi)
        e = np.full(t.shape, np.nan)
        if ok.any():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ServiceRangeWarning)  # shown dashed in the plot
                e[ok] = m.modulus(t[ok], frequency)
        frame[f"E_{m.name}_Pa"] = e
    return frame
