"""One-call answers: the friction torque of a lip seal, the friction of a reciprocating seal.

Both functions take quantities as strings with units (``"60 mm"``, ``"1500 rpm"``,
``"70 degC"``, ``"6 bar"``), as pint quantities (:func:`sealsim.units.unit_registry`), or as
plain numbers in SI units (m, K, Pa, m/s).  A rotational speed must carry its unit: a plain
1500 could be rpm or rad/s, so it is refused.  Oils and elastomers are catalogue names
(``"ISO VG 220"``, ``"NBR"``; ``sealsim oil list``, ``sealsim material list``); an unknown name
is an error that lists close matches.

Arrays of operating points are evaluated point by point (arguments broadcast against each
other, numpy style) and give a pandas DataFrame with one row per point; scalar arguments give
a dict.  The numbers are those of the long-form API: :func:`lip_seal_torque` is
:func:`sealsim.rotary.simulation.steady_state` of a :class:`~sealsim.rotary.case.RotaryCase`,
:func:`seal_friction` is ``FrictionLaw.steady_force`` of :mod:`sealsim.friction` with F_N and
b from a contact map of :mod:`sealsim.pneumatic.contact_maps`.

>>> import sealsim
>>> r = sealsim.lip_seal_torque(shaft_diameter="60 mm", speed="1500 rpm", oil="ISO VG 220",
...                             sump_temperature="70 degC")
>>> round(r["torque_Nm"], 3), round(r["power_W"], 1), round(r["T_contact_C"], 1)
(0.229, 35.9, 79.8)
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from sealsim.errors import InputError

__all__ = ["lip_seal_torque", "seal_friction"]

#: Columns of :func:`lip_seal_torque` (units in the names).
LIP_SEAL_COLUMNS = ["shaft_diameter_mm", "speed_rpm", "torque_Nm", "power_W", "T_contact_C",
                    "T_groove_C", "T_sump_C", "film_um", "F_lub_N", "F_material_N", "lip_note"]
#: Columns of :func:`seal_friction` (units in the names; pressure is gauge, across the seal).
SEAL_FRICTION_COLUMNS = ["velocity_m_s", "pressure_bar", "temperature_C", "friction_N",
                         "normal_force_N", "contact_width_mm"]

#: Friction law of :func:`seal_friction` when none is given: the Θ rate-and-state law (Heipl &
#: Murrenhoff, Eq. 4/5) with the illustrative set ``pneumatic_demo`` (not fitted to
#: measurements).
DEFAULT_LAW = {"law": "theta", "parameter_set": "pneumatic_demo"}


def lip_seal_torque(shaft_diameter, speed, oil: str | Mapping[str, Any] = "VG68-mineral",
                    sump_temperature=None, *, material: str = "NBR", lip_style: str = "plain",
                    ambient_temperature="20 degC", radial_force=None, contact_width=None,
                    mounting_temperature=None, case: Mapping[str, Any] | None = None):
    """Steady friction torque, power, contact temperature and film of a radial lip seal.

    The seal runs at constant speed until friction and heat transfer are in equilibrium: the
    coupled rotary model of Organisciak et al. (AGMA 14FTM14, 2014) -- EHL film, lubricant
    shear, viscoelastic losses on the real contact area, axisymmetric heat conduction through
    shaft and seal, convection to oil and air -- solved by
    :func:`sealsim.rotary.simulation.steady_state`.

    Parameters
    ----------
    shaft_diameter : str, float or array
        Shaft diameter, e.g. ``"60 mm"`` (plain number: m).  The seal's other dimensions and
        its lip force default to a DIN 3760 seal of that size (:mod:`sealsim.rotary.lip`).
    speed : str, pint quantity or array
        Shaft speed with its unit, e.g. ``"1500 rpm"`` or ``["500 rpm", "3000 rpm"]``; >= 0.
    oil : str or mapping
        Catalogue oil (``"ISO VG 220"``, ``"VG68-PAO"``; ``sealsim oil list``), or your oil's
        datasheet ``{"name": ..., "nu40": "220 mm^2/s", "nu100": "19 mm^2/s",
        "density15": "895 kg/m^3"}``.
    sump_temperature : str, float or array, optional
        Oil sump held at this temperature, e.g. ``"70 degC"`` (plain number: K), as in a
        gearbox whose gears heat the oil.  ``None``: the sump is heated by the seal alone and
        finds its own temperature.
    material : str
        Catalogue elastomer of the lip (``"NBR"``, ``"HNBR"``, ``"FKM"``, ``"ACM"``,
        ``"VMQ"``).
    lip_style : {"plain", "wave"}
        Plain or wave (hydrodynamic) lip.
    ambient_temperature : str, float or array
        Air around the housing (plain number: K), default 20 °C.
    radial_force : str or float, optional
        Lip force at 20 °C (plain number: N); default 0.15 N/mm · π·d.
    contact_width : str or float, optional
        Axial contact width of the lip (plain number: m); default from the diameter.
    mounting_temperature : str or float, optional
        Temperature at which the seal was mounted (plain number: K), default 20 °C.  A lip
        running colder keeps the stress it relaxed to there; only its thermal contraction
        since meets the stiffer cold rubber (the ``lip_note`` column says so).
    case : mapping, optional
        Any further fields of a rotary case (:class:`~sealsim.rotary.case.RotaryCase`), as
        nested tables: ``{"environment": {"sump_volume": "0.2 L"}, "friction": {...}}``.

    Returns
    -------
    dict or pandas.DataFrame
        shaft_diameter_mm, speed_rpm, torque_Nm, power_W, T_contact_C, T_groove_C,
        T_sump_C, film_um, F_lub_N, F_material_N, lip_note (text: the lip's mounting case when
        it runs colder than it was mounted, else ""): a dict for scalar arguments, a DataFrame
        with one row per point when any of shaft_diameter, speed, sump_temperature,
        ambient_temperature is an array (they broadcast against each other).

    Raises
    ------
    InputError
        A speed without a unit, a wrong unit or dimension, an unknown oil or material (with
        close matches), a value out of range (naming the case field).

    Examples
    --------
    >>> r = lip_seal_torque("60 mm", "1500 rpm", "ISO VG 220", "70 degC")
    >>> round(r["torque_Nm"], 3), round(r["film_um"], 2)
    (0.229, 0.91)
    >>> lip_seal_torque("60 mm", ["500 rpm", "3000 rpm"], "ISO VG 220",
    ...                 "70 degC")[["speed_rpm", "torque_Nm"]].round(3)
       speed_rpm  torque_Nm
    0      500.0      0.200
    1     3000.0      0.242
    >>> lip_seal_torque("60 mm", 1500, "ISO VG 220")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: speed: 1500 has no unit; a plain number is ambiguous for an \
angular speed (rpm or rad/s?): write it with its unit, e.g. '1500 rpm'
    """
    from sealsim.cases import apply_overrides, validate_case
    from sealsim.rotary.case import RotaryCase
    from sealsim.rotary.simulation import steady_state
    from sealsim.units import to_si

    d = to_si(shaft_diameter, "length", "shaft_diameter")
    omega = to_si(speed, "angular_speed", "speed", plain_is_si=False)
    if np.any(np.asarray(omega) < 0):
        raise InputError(f"speed: {speed!r} must be >= 0")
    t_sump = (None if sump_temperature is None
              else to_si(sump_temperature, "temperature", "sump_temperature"))
    t_amb = to_si(ambient_temperature, "temperature", "ambient_temperature")
    seal: dict[str, Any] = {"material": material, "lip_style": lip_style}
    if radial_force is not None:
        seal["radial_force"] = to_si(radial_force, "force", "radial_force")
    if contact_width is not None:
        seal["contact_width"] = to_si(contact_width, "length", "contact_width")
    if mounting_temperature is not None:
        seal["mounting_temperature"] = to_si(mounting_temperature, "temperature",
                                             "mounting_temperature")
    oil_table = {"name": oil} if isinstance(oil, str) else dict(oil)
    base = apply_overrides({"seal": seal, "oil": oil_table}, dict(case or {}))

    vectors = {"d": d, "omega": omega, "t_amb": t_amb,
               "t_sump": np.nan if t_sump is None else t_sump}
    shape = np.broadcast_shapes(*(np.shape(v) for v in vectors.values()))
    points = {k: np.broadcast_to(np.asarray(v, dtype=float), shape).ravel()
              for k, v in vectors.items()}
    cases: dict[tuple, RotaryCase] = {}  # one case per geometry and temperatures
    rows = []
    for k in range(int(np.prod(shape))):
        key = (points["d"][k], points["t_amb"][k], points["t_sump"][k])
        if key not in cases:
            env = {"ambient_temperature": key[1]}
            if not math.isnan(key[2]):
                env["sump_temperature"] = key[2]
            data = apply_overrides(base, {"seal": {"shaft_diameter": key[0]},
                                          "environment": env})
            cases[key] = validate_case(RotaryCase, data, "lip_seal_torque arguments",
                                       require_units=False)
        result = steady_state(cases[key], float(points["omega"][k]))
        rows.append({"shaft_diameter_mm": key[0] * 1e3,
                     "speed_rpm": float(points["omega"][k]) * 30.0 / math.pi,
                     **{c: result[c] for c in LIP_SEAL_COLUMNS[2:]}})
    return _rows_out(rows, shape, LIP_SEAL_COLUMNS)


def seal_friction(seal, velocity, pressure=0.0, temperature="20 degC", law=None, *,
                  diameter=None, progress=None):
    """Steady friction force of a reciprocating seal over sliding velocity.

    The seal's normal force F_N and contact width b come from a contact map at the pressure
    difference across the seal and its temperature (an FE characteristic map, Heipl &
    Murrenhoff's characteristic diagrams, or the analytic O-ring estimate of
    :class:`~sealsim.pneumatic.contact_maps.AnalyticContactMap`); the friction is that of a
    friction law after sliding at constant velocity for a long time
    (``FrictionLaw.steady_force``), e.g. the Θ rate-and-state law's Stribeck curve.

    Parameters
    ----------
    seal : str, path, mapping or contact map
        Where F_N and b come from:

        * a structure case file (``.toml`` with a ``[map]`` table): its FE map, built on
          demand (FElupe, tens of seconds; announced on the ``sealsim`` logger, see
          ``progress``) and cached (``sealsim cache list``);
        * a ``map.nc`` written by ``sealsim structure map``;
        * an O-ring for the analytic estimate: ``{"cord_diameter": "2 mm", "squeeze": 0.12}``
          (with ``diameter``, or ``"sliding_diameter"`` in the mapping; ``"elastomer"``
          defaults to NBR), or any ``map`` table of a pneumatic case (``{"analytic": {...}}``,
          ``{"file": ...}``, ``{"structure_case": ...}``);
        * a contact map object (``AnalyticContactMap``, ``FEContactMap``).
    velocity : str, float or array
        Sliding velocity, e.g. ``[0.01, 0.1, 1.0]`` (plain numbers: m/s) or ``"0.2 m/s"``.
    pressure : str, float or array
        Gauge pressure on the pressurised side, atmosphere on the other (a rod seal, or a
        piston seal with one chamber vented), e.g. ``"6 bar"`` (plain number: Pa).
    temperature : str, float or array
        Seal temperature (plain number: K), default 20 °C.
    law : str, mapping or FrictionLaw, optional
        The friction law: a law name whose parameters are its only named set
        (``"theta"``: ``pneumatic_demo``), a ``[friction]`` table of a case file
        (``{"law": "stribeck", "parameter_set": "pneumatic_demo", "coulomb_force": "12 N"}``)
        or a law object of :mod:`sealsim.friction`.  Default :data:`DEFAULT_LAW` (the Θ law
        with illustrative parameters, not fitted to measurements).
    diameter : str or float, optional
        Diameter of the sliding surface (rod or bore) for the analytic estimate (plain
        number: m).
    progress : callable, optional
        ``progress(done, total)`` while an FE map is built on demand (finished FE load paths).
        The build is announced before it starts at INFO level on the logger
        ``sealsim.pneumatic.contact_maps`` ("building FE map from ... cached at ...");
        ``logging.basicConfig(level=logging.INFO)`` prints it.

    Returns
    -------
    dict or pandas.DataFrame
        velocity_m_s, pressure_bar (gauge), temperature_C, friction_N (signed like the
        velocity), normal_force_N, contact_width_mm: a DataFrame with one row per point if
        velocity, pressure or temperature is an array (broadcast), else a dict.

    Raises
    ------
    InputError
        A wrong unit, an unknown law or material, a pressure or temperature outside the
        contact map, a law that needs parameters.

    Examples
    --------
    >>> oring = {"cord_diameter": "2 mm", "squeeze": 0.12}
    >>> curve = seal_friction(oring, [0.01, 0.1, 1.0], "6 bar", diameter="12 mm")
    >>> curve[["velocity_m_s", "friction_N", "normal_force_N"]].round(2)
       velocity_m_s  friction_N  normal_force_N
    0          0.01        9.58           38.02
    1          0.10        8.01           38.02
    2          1.00       19.80           38.02
    """
    from sealsim.friction.base import ContactInputs
    from sealsim.units import ZERO_CELSIUS_K, to_si

    v = to_si(velocity, "velocity", "velocity")
    dp = to_si(pressure, "pressure", "pressure")
    t = to_si(temperature, "temperature", "temperature")
    shape = np.broadcast_shapes(np.shape(v), np.shape(dp), np.shape(t))
    v, dp, t = (np.broadcast_to(np.asarray(x, dtype=float), shape).ravel() for x in (v, dp, t))
    if np.any(dp < 0):
        raise InputError(f"pressure: {pressure!r} must be >= 0 (a gauge pressure difference)")
    contact_map = _contact_map(seal, diameter, progress)
    _check_ranges(contact_map, dp, t)
    friction_law = _friction_law(DEFAULT_LAW if law is None else law)
    normal_force, width = (np.asarray(x, dtype=float) * np.ones_like(dp)
                           for x in contact_map.evaluate(dp, t))
    inputs = ContactInputs(normal_force=normal_force, contact_width=width, pressure_a=dp,
                           pressure_b=0.0, temperature=t)
    force = np.asarray(friction_law.steady_force(v, inputs), dtype=float).reshape(-1)
    rows = [{"velocity_m_s": v[k], "pressure_bar": dp[k] / 1e5,
             "temperature_C": t[k] - ZERO_CELSIUS_K, "friction_N": force[k],
             "normal_force_N": normal_force[k], "contact_width_mm": width[k] * 1e3}
            for k in range(v.size)]
    return _rows_out(rows, shape, SEAL_FRICTION_COLUMNS)


def _rows_out(rows: list[dict], shape: tuple, columns: list[str]):
    """A dict of floats for a single point given as scalars, else a DataFrame."""
    if shape == ():
        return {c: v if isinstance(v := rows[0][c], str) else float(v) for c in columns}
    import pandas as pd

    return pd.DataFrame(rows, columns=columns)


_MAP_SOURCES = ("analytic", "file", "structure_case")


def _contact_map(seal, diameter, progress=None):
    """The contact map of a ``seal`` argument (see :func:`seal_friction`)."""
    from sealsim.cases import validate_case
    from sealsim.pneumatic.case import MapModel, build_contact_map
    from sealsim.units import to_si

    if hasattr(seal, "evaluate") and hasattr(seal, "ranges"):
        return seal
    if isinstance(seal, str | Path):
        path = Path(seal)
        if path.suffix.lower() not in (".toml", ".nc"):
            raise InputError(f"seal: {str(seal)!r} is neither a structure case (.toml) nor a "
                             "map file (.nc); for the analytic estimate give "
                             "{'cord_diameter': '2 mm', 'squeeze': 0.12}")
        table = {"structure_case" if path.suffix.lower() == ".toml" else "file": str(path)}
    elif isinstance(seal, Mapping):
        table = dict(seal)
        if not set(table) & set(_MAP_SOURCES):
            table = {"analytic": table}
    else:
        raise InputError(f"seal: {seal!r} is not a structure case, a map file, an O-ring "
                         "table or a contact map")
    spec = validate_case(MapModel, table, "seal", require_units=False)
    sliding = None if diameter is None else to_si(diameter, "length", "diameter")
    if spec.analytic is not None and spec.analytic.sliding_diameter is None and sliding is None:
        raise InputError("seal: the analytic estimate needs the diameter of the sliding "
                         "surface (rod or bore): give diameter='12 mm'")
    return build_contact_map(spec, sliding or 0.0, Path.cwd(), "seal", progress)


def _check_ranges(contact_map, pressure: np.ndarray, temperature: np.ndarray) -> None:
    """Refuse points outside the map (its evaluate would clamp them silently)."""
    from sealsim.units import ZERO_CELSIUS_K

    ranges = getattr(contact_map, "ranges", {})
    for name, values, scale, unit, offset in (
            ("pressure", pressure, 1e-5, "bar", 0.0),
            ("temperature", temperature, 1.0, "degC", -ZERO_CELSIUS_K)):
        if name not in ranges:
            continue
        lo, hi = ranges[name]
        tol = 1e-9 * max(abs(lo), abs(hi), 1.0)
        bad = (values < lo - tol) | (values > hi + tol)
        if np.any(bad):
            shown = float(values[np.argmax(bad)]) * scale + offset
            raise InputError(f"{name}: {shown:.6g} {unit} is outside the seal's contact map "
                             f"({lo * scale + offset:.6g} ... {hi * scale + offset:.6g} {unit})")


def _friction_law(law):
    """A friction law object from a name, a ``[friction]`` table or a law object."""
    from sealsim.friction import PARAMETER_SETS, make_law
    from sealsim.friction.base import FrictionLaw, PassivityWarning

    if isinstance(law, FrictionLaw):
        return law
    if isinstance(law, str):
        sets = sorted(PARAMETER_SETS.get(law, {}))
        if len(sets) != 1:
            known = ", ".join(sorted(PARAMETER_SETS))
            raise InputError(
                f"law: {law!r} " + (f"has the parameter sets {', '.join(sets)}: give law = "
                                    f"{{'law': {law!r}, 'parameter_set': {sets[0]!r}}}"
                                    if sets else f"is not a friction law; choose from {known}"))
        law = {"law": law, "parameter_set": sets[0]}
    if not isinstance(law, Mapping):
        raise InputError(f"law: {law!r} is not a law name, a [friction] table or a law object")
    params = _law_parameters(law)
    with warnings.catch_warnings():
        # passivity concerns fast velocity changes, not the steady friction computed here
        warnings.simplefilter("ignore", PassivityWarning)
        return make_law(params)


def _law_parameters(table: Mapping[str, Any]):
    from pydantic import TypeAdapter, ValidationError

    from sealsim.cases import format_validation_error
    from sealsim.friction.case import LawParameters

    try:
        return TypeAdapter(LawParameters).validate_python(dict(table),
                                                          context={"require_units": False})
    except ValidationError as exc:
        raise InputError(format_validation_error(exc, "law")) from None
