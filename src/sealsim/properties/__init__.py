"""Material and lubricant properties: oils (ASTM D341) and elastomers (WLF, E(T)).

The public API of :mod:`sealsim.properties.oils` and :mod:`sealsim.properties.elastomers` (the
elastomer record and catalogue, with the laws of :mod:`~sealsim.properties.viscoelasticity`,
:mod:`~sealsim.properties.rubber_modulus` and :mod:`~sealsim.properties.thermal_expansion`) is
re-exported here, so ``from sealsim.properties import get_oil, get_elastomer`` works.  The oil
function ``density`` is deliberately *not* re-exported (the bare name would be ambiguous next to
elastomer densities); use ``sealsim.properties.oils.density`` or :meth:`Oil.density`.

Examples
--------
>>> from sealsim.properties import get_oil, get_elastomer
>>> round(get_oil("VG68").nu40 * 1e6, 1)
68.0
>>> get_elastomer("NBR").glass_transition
248.15
"""

from sealsim.properties import elastomers, oils
from sealsim.properties.elastomers import (
    CATALOGUE_NAMES,
    DEFAULT_TRANSITION_ASYMMETRY,
    DEFAULT_TRANSITION_LOCATION,
    DEFAULT_TRANSITION_WIDTH,
    WLF_UNIVERSAL,
    WLF_UNIVERSAL_TS,
    Elastomer,
    ServiceRangeWarning,
    WLFConstants,
    get_elastomer,
    list_elastomers,
    load_elastomer_file,
    master_curve_modulus,
    modulus_from_table,
    modulus_vs_temperature,
    mooney_rivlin_young_modulus,
    prony_loss_modulus,
    prony_relaxation_modulus,
    prony_storage_modulus,
    reduced_time,
    reduced_time_history,
    wlf_log10_shift,
    wlf_shift_factor,
)
from sealsim.properties.oils import (
    FAMILIES,
    Oil,
    OilRangeWarning,
    barus_viscosity,
    get_oil,
    list_oils,
    load_oil_file,
    specific_heat_cragoe,
    thermal_conductivity_cragoe,
    viscosity_index,
    walther_constants,
    walther_viscosity,
)

__all__ = [
    # modules
    "elastomers",
    "oils",
    # oils
    "FAMILIES",
    "Oil",
    "OilRangeWarning",
    "barus_viscosity",
    "get_oil",
    "list_oils",
    "load_oil_file",
    "specific_heat_cragoe",
    "thermal_conductivity_cragoe",
    "viscosity_index",
    "walther_constants",
    "walther_viscosity",
    # elastomers
    "CATALOGUE_NAMES",
    "DEFAULT_TRANSITION_ASYMMETRY",
    "DEFAULT_TRANSITION_LOCATION",
    "DEFAULT_TRANSITION_WIDTH",
    "WLF_UNIVERSAL",
    "WLF_UNIVERSAL_TS",
    "Elastomer",
    "ServiceRangeWarning",
    "WLFConstants",
    "get_elastomer",
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
    "wlf_log10_shift",
    "wlf_shift_factor",
]
