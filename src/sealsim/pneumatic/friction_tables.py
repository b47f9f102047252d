r"""A seal's steady friction table from its own contact: built on demand, cached.

For each temperature and pressure difference of the seal's contact map the static contact
pressure profile p_c(z) -- the FE map's stored profile (``contact_pressure`` of ``map.nc``),
or, for the analytic O-ring estimate, the Hertz profile of its squeeze plus the sealed
pressure -- is turned
into a Stribeck curve per stroke direction by inverse hydrodynamics and mixed lubrication
(:func:`sealsim.tribology.mixed_lubrication.reciprocating_friction`): lubricant viscosity at
the temperature (the base oil's ASTM D341 curve times a thickener factor), the rubber's
modulus at the asperity frequency u/λ_asp from the elastomer's master curve, the combined
roughness σ.  The result, a :class:`~sealsim.friction.contact_table.SteadyFrictionTable` per
unit circumference, is written as netCDF into the map cache
(:func:`~sealsim.pneumatic.contact_maps.default_cache_dir`; ``sealsim cache list``) under a hash
of the map and of every tribology parameter, and read from there next time.

**Sealed pressure.**  On the pressurised side the lubricant is at the sealed pressure Δp, so
the film's pressure rises from Δp, not from 0, into the first contact (Reynolds' boundary
condition; the FE contact pressure drops to 0 at the wetted edge because the fluid's pressure
is not part of it).

**Direction.**  The table's "+" direction is the counter surface sliding from the pressurised
side of the seal to the other (+z of an FE profile: the upstream side is z < 0): a rod seal's
outstroke.  :func:`table_orientation` maps the piston velocity of a cylinder onto it.  The
analytic O-ring estimate's profile is its squeeze's Hertz profile with the sealed pressure on
top (:func:`~sealsim.pneumatic.contact_maps.energised_contact_pressure`, the profile its force
estimate integrates): symmetric without pressure (one film both ways, no net transport), under
pressure the low-pressure edge drops from Δp to 0, a steeper inlet for the stroke that enters
there.

**Lubricant.**  Pneumatic seals run in grease; the film is that of its base oil (ASTM D341
through the datasheet's ν40, ν100) times ``thickener_factor``.  Grease films measured in EHL
contacts are thicker than their base oil's at low speed and approach it at higher speed
(Cann, Tribol. Int. 29 (1996); Vengudusamy, Enekes & Spallek, Tribol. Int. 129 (2019) 323:
"all greases form a thicker film than the base oil at low speeds"): the default factor 1 is the
base oil, the lower bound of those measurements.

**At rest.**  Per speed the table also keeps how fast the film formed for it drains when the
seal stops (:mod:`sealsim.tribology.squeeze_film`: Reynolds' squeeze film under the load the
fluid carries), as the decay rate κ of the film's speed, dφ/dt = −κ·φ, which the friction
laws' film state uses at rest.
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from sealsim.errors import InputError
from sealsim.friction.contact_table import FILM_DECAY, TABLE_VARIABLES, SteadyFrictionTable
from sealsim.pneumatic.contact_maps import (AnalyticContactMap, FEContactMap, default_cache_dir,
                                           energised_contact_pressure)
from sealsim.tribology.contact import DEFAULT_ROUGHNESS_DENSITY, DEFAULT_ROUGHNESS_SLOPE
from sealsim.tribology.mixed_lubrication import reciprocating_friction
from sealsim.tribology.rubber_friction import DEFAULT_ASPERITY_WAVELENGTH
from sealsim.tribology.squeeze_film import film_speed_decay_rate

__all__ = ["ContactTribology", "LAW_TABLE_FIELDS", "TABLE_SPEEDS", "build_friction_table",
           "contact_profiles", "friction_over_contact_force", "friction_table_for",
           "lubricant_viscosity", "sliding_diameter", "table_orientation"]

#: Version of the table builder: part of the cache key (a change of the physics gives new files;
#: 5: the inlet gradient no longer drops the secant ending on the pressure maximum for a profile
#: at negative z, e.g. the − stroke of a contact at z > 0; 6: with a limited supply, each
#: contact zone is fed by the layer the zone before it leaves)
TABLE_VERSION = 7
#: Speeds of a table [m/s]: 1e-7 to 10 m/s, six per decade
TABLE_SPEEDS = np.logspace(-7.0, 1.0, 49)
#: Largest temperature step of a table [K]: FE profiles are interpolated linearly between the
#: map's temperatures, the viscosity is evaluated at every table temperature
TEMPERATURE_STEP = 5.0
#: Points of a Hertz profile across its contact (analytic map)
_HERTZ_POINTS = 257
#: Fields of the Θ law (``steady = "contact"``) a friction table is built with: another value of
#: one of them is another table (μ_b, the dwell drop and the Θ dynamics apply when it is read)
LAW_TABLE_FIELDS = ("roughness", "film_factor", "base_oil_nu40", "base_oil_nu100",
                    "lubricant_density", "thickener_factor", "asperity_wavelength",
                    "supply_layer")


@dataclass(frozen=True)
class ContactTribology:
    """The tribology of a seal contact that a friction table needs (SI units).

    Parameters
    ----------
    roughness : float
        Combined RMS roughness of counter surface and seal σ [m].
    film_factor : float
        Multiplier of the full IHL film [-] (1: the theory; a calibration may fit it).
    base_oil_nu40, base_oil_nu100 : float
        Kinematic viscosity of the lubricant's (base) oil at 40 and 100 °C [m²/s].
    lubricant_density : float
        Density of the oil [kg/m³] (η = ρ·ν).
    thickener_factor : float
        Grease film viscosity / base-oil viscosity [-] (see the module docstring).
    asperity_wavelength : float
        Wavelength of the counter surface's roughness λ_asp [m]: the rubber's asperity
        frequency is u/λ_asp.
    elastomer : str
        Catalogue elastomer of the seal (its modulus at the asperity frequency).
    roughness_density, roughness_slope : float
        Greenwood–Williamson η_s·β·σ and σ/β [-].
    supply_layer : float
        Lubricant layer on the counter surface ahead of the seal h_s [m] (a starved inlet:
        the film is at most 2·h_s); ``inf``: fully flooded.
    """

    roughness: float = 0.3e-6
    film_factor: float = 1.0
    base_oil_nu40: float = 110e-6
    base_oil_nu100: float = 11e-6
    lubricant_density: float = 880.0
    thickener_factor: float = 1.0
    asperity_wavelength: float = DEFAULT_ASPERITY_WAVELENGTH
    elastomer: str = "NBR"
    roughness_density: float = DEFAULT_ROUGHNESS_DENSITY
    roughness_slope: float = DEFAULT_ROUGHNESS_SLOPE
    supply_layer: float = math.inf

    @classmethod
    def from_law(cls, law, elastomer: str = "NBR") -> ContactTribology:
        """The tribology fields (:data:`LAW_TABLE_FIELDS`) of a Θ law in ``steady =
        "contact"`` mode (a law without a supply layer: flooded)."""
        values = {f: getattr(law.params, f) for f in LAW_TABLE_FIELDS}
        if values["supply_layer"] is None:
            values["supply_layer"] = math.inf
        return cls(**values, elastomer=elastomer)


def lubricant_viscosity(temperature, tribology: ContactTribology):
    """η(T) = thickener factor × ρ × ν(T) [Pa·s], ν by ASTM D341 through ν40 and ν100.

    Examples
    --------
    >>> round(float(lubricant_viscosity(313.15, ContactTribology())), 4)
    0.0968
    """
    from sealsim.properties.oils import walther_constants, walther_viscosity

    a, b = walther_constants(313.15, tribology.base_oil_nu40, 373.15, tribology.base_oil_nu100)
    nu = walther_viscosity(np.asarray(temperature, dtype=float), a, b)
    return tribology.thickener_factor * tribology.lubricant_density * nu


def table_orientation(code, p1, p2, ambient_pressure):
    """+1 or −1: the sign that turns the piston velocity of a cylinder into the table's
    direction (+: the counter surface slides from the seal's pressurised side to the other).

    Rod seal (code 1): the rod moves out (v > 0) from chamber 2 to the atmosphere, +1 while
    p2 >= p_a.  Piston seal (code 0): the bore moves against the piston, towards chamber 1
    when v > 0: +1 while chamber 2 is the pressurised side (p2 > p1), else −1.  Wiper: +1.

    Examples
    --------
    >>> table_orientation(0, 7e5, 1e5, 1e5), table_orientation(1, 7e5, 3e5, 1e5)
    (-1.0, 1.0)
    """
    if code == 0:
        return 1.0 if p2 > p1 else -1.0
    if code == 1:
        return 1.0 if p2 >= ambient_pressure else -1.0
    return 1.0


def sliding_diameter(contact_map) -> float:
    """Diameter of the sliding surface of a contact map [m]: the analytic estimate's
    ``sliding_diameter``; for an FE map F_N/(π·F'_N) of its first grid point (the radius of
    the sealing surface the FE model integrated the force over)."""
    if isinstance(contact_map, FEContactMap):
        ds = contact_map.seal_map.dataset
        if "F_N_per_length" not in ds.data_vars:
            raise InputError(f"map {contact_map.source!r} has no F_N_per_length: the diameter "
                             "of its sealing surface is unknown")
        fn = float(ds["F_N"].values.reshape(-1)[0])
        per_length = float(ds["F_N_per_length"].values.reshape(-1)[0])
        return fn / (math.pi * per_length)
    return float(contact_map.sliding_diameter)


def friction_over_contact_force(table: SteadyFrictionTable, contact_map, boundary_friction,
                                temperature, max_speed=1.0) -> tuple[float, float, float]:
    """The largest steady friction over contact force F_ss/F_N [-] of a seal at a temperature,
    over its table's pressure nodes and speeds up to ``max_speed``, both strokes, and where:
    ``(ratio, speed [m/s], pressure difference [Pa])``.

    F_ss = π·D·(μ_b·L + V) of the table (:meth:`SteadyFrictionTable.steady_force`), F_N the
    contact map's force at the same Δp and temperature.  A lubricated rubber seal's friction
    stays below its contact force (boundary friction coefficients of lubricated rubber
    0.05-0.3 plus a viscous part): a ratio above 1 says the table's viscous shear has left the
    range the film model holds in (a film capped by a thin ``supply_layer`` sheared at high
    speed, or a very cold, viscous lubricant).

    Parameters
    ----------
    table : SteadyFrictionTable
        The seal's friction table (per unit circumference).
    contact_map : FEContactMap or AnalyticContactMap
        The map the table was built from (F_N).
    boundary_friction : float
        μ_b [-].
    temperature : float
        Seal temperature [K] (clamped to the table's range).
    max_speed : float
        Largest sliding speed considered [m/s].
    """
    speeds = table.speed[table.speed <= max_speed]
    uu, pp = np.meshgrid(speeds, table.pressure, indexing="ij")
    diameter = sliding_diameter(contact_map)
    force = np.maximum(*(np.abs(table.steady_force(sign * uu, pp, temperature, diameter,
                                                   boundary_friction)) for sign in (1, -1)))
    normal = np.asarray(contact_map.evaluate(table.pressure, temperature)[0], dtype=float)
    ratio = force / normal[None, :]
    i, j = np.unravel_index(int(np.argmax(ratio)), ratio.shape)
    return float(ratio[i, j]), float(speeds[i]), float(table.pressure[j])


def _energised_profile(force_per_length, width, pressure_difference):
    """(z [m], p [Pa]) of the analytic O-ring estimate's contact: its Hertz profile plus Δp
    (:func:`~sealsim.pneumatic.contact_maps.energised_contact_pressure`)."""
    a = 0.5 * width
    z = np.linspace(-1.1 * a, 1.1 * a, _HERTZ_POINTS)
    return z, energised_contact_pressure(z, force_per_length, width, pressure_difference)


def _grid(nodes, step):
    """The nodes refined so that no step exceeds ``step``."""
    nodes = np.asarray(nodes, dtype=float)
    out = [nodes[:1]]
    for lo, hi in zip(nodes[:-1], nodes[1:]):
        n = max(int(math.ceil((hi - lo) / step)), 1)
        out.append(np.linspace(lo, hi, n + 1)[1:])
    return np.concatenate(out)


def contact_profiles(contact_map):
    """Contact pressure profiles of a map: ``(temperatures [K], pressures [Pa], profile)``
    with ``profile(i, j) -> (z [m], p [Pa])`` at temperature i and pressure j; FE profiles
    are interpolated linearly between the map's temperatures.

    Raises
    ------
    InputError
        An FE map without stored contact pressure profiles.
    """
    if isinstance(contact_map, FEContactMap):
        ds = contact_map.seal_map.dataset
        if "contact_pressure" not in ds.data_vars:
            raise InputError(f"map {contact_map.source!r} has no contact pressure profile "
                             "(contact_pressure); rebuild it with this sealsim version")
        prof = ds["contact_pressure"]
        if ds.sizes["squeeze"] > 1:
            prof = prof.interp(squeeze=contact_map.squeeze)
        else:
            prof = prof.isel(squeeze=0)
        prof = prof.transpose("temperature", "pressure", "position")
        t_nodes = np.asarray(ds["temperature"].values, dtype=float)
        values = np.nan_to_num(np.clip(prof.values, 0.0, None))
        z = np.asarray(ds["position"].values, dtype=float)
        # a map at one temperature (or one pressure) allows only that value; the table's
        # interpolation needs two nodes per axis, so a second one 1 K (1 kPa) above repeats it
        temps = (_grid(t_nodes, TEMPERATURE_STEP) if t_nodes.size > 1
                 else np.array([t_nodes[0], t_nodes[0] + 1.0]))
        p_nodes = np.asarray(ds["pressure"].values, dtype=float)
        pressures = p_nodes if p_nodes.size > 1 else np.array([p_nodes[0], p_nodes[0] + 1e3])

        def profile(i, j):
            t = temps[i]
            j = min(j, p_nodes.size - 1)
            if t_nodes.size == 1:
                return z, values[0, j]
            k = min(max(int(np.searchsorted(t_nodes, t, side="right")) - 1, 0),
                    t_nodes.size - 2)
            w = (t - t_nodes[k]) / (t_nodes[k + 1] - t_nodes[k])
            return z, (1.0 - w) * values[k, j] + w * values[k + 1, j]
        return temps, pressures, profile
    if isinstance(contact_map, AnalyticContactMap):
        (plo, phi), (tlo, thi) = (contact_map.ranges["pressure"],
                                  contact_map.ranges["temperature"])
        temps = _grid([tlo, thi], 2.0 * TEMPERATURE_STEP)
        pressures = plo + (phi - plo) * np.linspace(0.0, 1.0, 9) ** 2
        tt, pp = np.meshgrid(temps, pressures, indexing="ij")
        fn, b = contact_map.evaluate(pp, tt)
        force = np.asarray(fn, dtype=float) / (np.pi * contact_map.sliding_diameter)
        width = np.asarray(b, dtype=float)
        return temps, pressures, lambda i, j: _energised_profile(force[i, j], width[i, j],
                                                                 pressures[j])
    raise InputError(f"a friction table needs a contact map with contact pressure profiles "
                     f"(an FE map or the analytic O-ring estimate), got {type(contact_map)}")


def build_friction_table(contact_map, tribology: ContactTribology,
                         speeds=TABLE_SPEEDS) -> SteadyFrictionTable:
    """Compute a seal's steady friction table from its contact map (see the module
    docstring).

    Parameters
    ----------
    contact_map : FEContactMap or AnalyticContactMap
        The seal's contact map.
    tribology : ContactTribology
        Lubricant, roughness and rubber of the contact.
    speeds : array_like
        Speed axis [m/s].

    Returns
    -------
    SteadyFrictionTable
    """
    from sealsim.properties.elastomers import get_elastomer

    temps, pressures, profile = contact_profiles(contact_map)
    speeds = np.asarray(speeds, dtype=float)
    rubber = get_elastomer(tribology.elastomer)
    values = np.zeros((temps.size, pressures.size, speeds.size, len(TABLE_VARIABLES)))
    analytic = isinstance(contact_map, AnalyticContactMap)
    kwargs = {"film_factor": tribology.film_factor, "supply_layer": tribology.supply_layer,
              "roughness_density": tribology.roughness_density,
              "roughness_slope": tribology.roughness_slope}
    import warnings

    for i, t in enumerate(temps):
        eta = float(lubricant_viscosity(t, tribology))
        with warnings.catch_warnings():       # the master curve outside the service range
            warnings.simplefilter("ignore")
            modulus = np.asarray(rubber.modulus(np.full(speeds.shape, t),
                                                speeds / tribology.asperity_wavelength))
        for j in range(pressures.size):
            z, p = profile(i, j)
            decays = []                  # the film's decay rate of each direction's film
            for k, direction in enumerate((1, -1)):
                if k == 1 and analytic and pressures[j] <= 0.0:    # symmetric: one film
                    values[i, j, :, 2:4] = values[i, j, :, 0:2]
                    values[i, j, :, 5] = values[i, j, :, 4]
                    continue
                r = reciprocating_friction(z, p, speeds, eta, tribology.roughness, modulus,
                                           1.0, direction, sealed_pressure=pressures[j],
                                           **kwargs)
                values[i, j, :, 2 * k] = r.boundary          # μ_b = 1: the asperity load
                values[i, j, :, 2 * k + 1] = r.viscous
                values[i, j, :, 4 + k] = np.where(np.isfinite(r.film), r.film, 0.0)
                decays.append(film_speed_decay_rate(speeds, r.film, r.squeeze))
            values[i, j, :, FILM_DECAY] = np.mean(decays, axis=0)     # one rate both ways
    attrs = {"tribology": asdict(tribology), "table_version": TABLE_VERSION,
             "contact_map": contact_map.describe()}
    return SteadyFrictionTable(temps, pressures, speeds, values, attrs)


def _map_identity(contact_map) -> str:
    """What identifies a map's profiles: its file's bytes (FE) or its parameters."""
    if isinstance(contact_map, FEContactMap):
        path = Path(contact_map.source)
        if path.is_file():
            return hashlib.sha256(path.read_bytes()).hexdigest() + f"|{contact_map.squeeze}"
        return json.dumps(contact_map.seal_map.dataset.attrs.get("case", ""))
    return json.dumps(contact_map.describe(), sort_keys=True, default=str)


#: tables of this process by (cache folder, cache key); the key covers the map's file bytes, so
#: a changed map is a new key: a study or a repeated ``simulate(case)`` reads each table once
_TABLES: dict[tuple[str, str], SteadyFrictionTable] = {}
_TABLES_KEPT = 8         # a large FE table holds ~16 MB of cell coefficients


def friction_table_for(contact_map, tribology: ContactTribology,
                       cache_dir: str | Path | None = None) -> SteadyFrictionTable:
    """The friction table of a seal, read from the cache or built and cached.

    The cache file ``friction-<stem>-<hash16>.nc`` sits in the map cache folder; the hash
    covers the map (its file's bytes, or the analytic parameters), the tribology, the speed
    axis and :data:`TABLE_VERSION`.  The table is also kept for this process (the last
    ``_TABLES_KEPT`` keys).
    """
    from sealsim.files import atomic_write_bytes

    key_text = json.dumps({"map": _map_identity(contact_map), "tribology": asdict(tribology),
                           "speeds": TABLE_SPEEDS.tolist(), "version": TABLE_VERSION,
                           "temperature_step": TEMPERATURE_STEP}, sort_keys=True)
    digest = hashlib.sha256(key_text.encode("utf-8")).hexdigest()[:16]
    folder = Path(cache_dir) if cache_dir is not None else default_cache_dir()
    memo_key = (str(folder), digest)
    if memo_key in _TABLES:
        return _TABLES[memo_key]
    stem = Path(getattr(contact_map, "source", "") or "analytic").stem or "analytic"
    target = folder / f"friction-{stem}-{digest}.nc"
    table = None
    if target.is_file():
        import xarray as xr

        try:
            with xr.open_dataset(target) as ds:
                table = SteadyFrictionTable.from_dataset(ds.load())
        except (OSError, ValueError, InputError):
            table = None          # a damaged cache file is rebuilt
    if table is None:
        table = build_friction_table(contact_map, tribology)
        try:
            folder.mkdir(parents=True, exist_ok=True)
            atomic_write_bytes(target, table.to_dataset().to_netcdf())
        except OSError:           # a read-only cache only costs the rebuild next time
            pass
    if len(_TABLES) >= _TABLES_KEPT:
        _TABLES.pop(next(iter(_TABLES)))
    _TABLES[memo_key] = table
    return table


def film_profiles(contact_map, tribology: ContactTribology, temperature: float,
                  speed: float = 0.1):
    """The contact pressure and film profiles of a seal at one temperature and speed, per
    pressure of its map: ``[(Δp [Pa], z [m], p_c [Pa], h_+ [m], h_− [m]), ...]`` (the films
    of the two stroke directions, inf outside the contact) -- what the friction table is made
    of, for plots.  Everything at ``temperature`` itself, not at the nearest temperature of
    the table (whose films the table interpolates between its nodes): an FE map's profiles
    interpolated linearly in T as the table's nodes are, the analytic estimate's profile of
    its force and width at T."""
    from sealsim.properties.elastomers import get_elastomer

    temps, pressures, profile = contact_profiles(contact_map)
    t = float(temperature)
    k = min(max(int(np.searchsorted(temps, t, side="right")) - 1, 0), temps.size - 2)
    w = min(max((t - temps[k]) / (temps[k + 1] - temps[k]), 0.0), 1.0)
    eta = float(lubricant_viscosity(t, tribology))
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        modulus = float(get_elastomer(tribology.elastomer).modulus(
            t, speed / tribology.asperity_wavelength))
    out = []
    for j, dp in enumerate(pressures):
        if isinstance(contact_map, AnalyticContactMap):
            fn, b = (float(np.asarray(x).reshape(-1)[0]) for x in contact_map.evaluate(dp, t))
            z, p = _energised_profile(fn / (math.pi * contact_map.sliding_diameter), b, dp)
        else:                     # the same positions at every temperature
            z, low = profile(k, j)
            p = (1.0 - w) * low + w * profile(k + 1, j)[1]
        films = [reciprocating_friction(z, p, [speed], eta, tribology.roughness, modulus, 1.0,
                                        direction, film_factor=tribology.film_factor,
                                        supply_layer=tribology.supply_layer,
                                        sealed_pressure=dp).film_profile[0]
                 for direction in (1, -1)]
        out.append((float(dp), z, p, films[0], films[1]))
    return out
