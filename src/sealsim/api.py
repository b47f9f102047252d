"""One-call answers: the friction torque of a lip seal, the friction of a reciprocating seal.

Both functions take quantities as strings with units (``"60 mm"``, ``"1500 rpm"``,
``"1500 1/min"``, ``"70 degC"``, ``"6 bar"``) or as pint quantities
(:func:`sealsim.units.unit_registry`, also for numpy arrays: ``np.array([0.1, 1.0]) *
ureg("m/s")``), as case files do.  A plain number is refused for every dimensional argument:
``pressure=6`` could be bar or Pa, ``sump_temperature=80`` degC or K.  Oils and elastomers are
catalogue names (``"ISO VG 220"``, ``"NBR"``; ``sealsim oil list``, ``sealsim material list``);
an unknown name is an error that lists close matches.

Arrays of operating points are evaluated point by point (arguments broadcast against each
other, numpy style; at most :data:`MAX_POINTS` per call) and give a pandas DataFrame with one
row per point; scalar arguments give a dict.  Where a result leaves the range of its models
(a contact above the elastomer's service limit, a film outside the measured range, an
illustrative friction parameter set), the notes that ``sealsim rotary run`` and ``sealsim
friction run`` print are returned once per call: as ``result["notes"]`` (a dict) or
``frame.attrs["notes"]`` (a DataFrame), and each as a :class:`~sealsim.errors.SealsimWarning`.

The numbers are those of the long-form API: :func:`lip_seal_torque` is
:func:`sealsim.rotary.simulation.steady_state` of a :class:`~sealsim.rotary.case.RotaryCase`,
:func:`seal_friction` is ``FrictionLaw.steady_force`` of :mod:`sealsim.friction` with F_N and
b from a contact map of :mod:`sealsim.pneumatic.contact_maps`.

>>> import sealsim
>>> r = sealsim.lip_seal_torque(shaft_diameter="60 mm", speed="1500 rpm", oil="ISO VG 220",
...                             sump_temperature="70 degC")
>>> round(r["torque_Nm"], 3), round(r["power_W"], 1), round(r["T_contact_C"], 1)
(0.22, 34.5, 84.3)
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from sealsim.errors import InputError, ModelError, SealsimWarning
from sealsim.units import to_si

if TYPE_CHECKING:
    from sealsim.properties.oils import Oil

__all__ = ["friction_loop", "lip_seal_torque", "oring_gland", "seal_friction"]

#: Most operating points one call evaluates: a lip-seal point is a steady-state solve of about
#: 20 ms, a seal-friction point one vectorised evaluation of the law.
MAX_POINTS = {"lip_seal_torque": 10_000, "seal_friction": 1_000_000}

#: Columns of :func:`lip_seal_torque` (units in the names).
LIP_SEAL_COLUMNS = ["shaft_diameter_mm", "speed_rpm", "torque_Nm", "power_W", "T_contact_C",
                    "T_groove_C", "T_sump_C", "T_housing_C", "film_um", "F_lub_N", "F_material_N",
                    "bearing_power_W", "heat_oil_side_W", "heat_housing_W", "heat_air_side_W",
                    "lip_note"]
#: Columns of :func:`seal_friction` (units in the names; pressure is gauge, across the seal).
SEAL_FRICTION_COLUMNS = ["velocity_m_s", "pressure_bar", "temperature_C", "friction_N",
                         "normal_force_N", "contact_width_mm", "film_um", "asperity_share",
                         "transport_mm3_per_m"]

#: Friction law of :func:`seal_friction` when none is given: the Θ rate-and-state law (Heipl &
#: Murrenhoff, Eq. 4/5) whose steady curve comes from the seal's own contact pressure profile
#: (set ``seal_contact``: inverse hydrodynamics and mixed lubrication, cited defaults).  The
#: lumped set ``pneumatic_demo`` stays available by name; it is illustrative.
DEFAULT_LAW = {"law": "theta", "parameter_set": "seal_contact"}


def lip_seal_torque(shaft_diameter, speed, oil: str | Mapping[str, Any] | Oil = "VG68-mineral",
                    sump_temperature=None, *, material: str = "NBR", lip_style: str = "plain",
                    ambient_temperature="20 degC", radial_force=None, contact_width=None,
                    mounting_temperature=None, case: Mapping[str, Any] | None = None):
    """Steady friction torque, power, contact temperature and film of a radial lip seal.

    The seal runs at constant speed until friction and heat transfer are in equilibrium: the
    coupled rotary model of Organisciak et al. (AGMA 14FTM14, 2014) -- EHL film, lubricant
    shear, viscoelastic losses on the real contact area, axisymmetric heat conduction through
    shaft and seal, convection to oil and air -- solved by
    :func:`sealsim.rotary.simulation.steady_state`.  The seal sits in the default ``gearbox``
    set-up (:data:`sealsim.rotary.case.SETUPS`: the bearing beside it heats the shaft, the
    shaft is a rotating fin in the sump, its air side turns in a motor adapter at the housing
    temperature); ``case={"environment": {"setup": "test_rig"}}`` for a seal test rig,
    ``{"environment": {"air_side": "ambient"}}`` for a free input shaft in the room.

    Parameters
    ----------
    shaft_diameter : str, pint quantity or array
        Shaft diameter, e.g. ``"60 mm"``.  The seal's other dimensions and
        its lip force default to a DIN 3760 seal of that size (:mod:`sealsim.rotary.lip`).
    speed : str, pint quantity or array
        Shaft speed with its unit, e.g. ``"1500 rpm"``, ``"1500 1/min"`` (revolutions per
        minute, as on data sheets) or ``["500 rpm", "3000 rpm"]``; >= 0.
    oil : str, mapping or Oil
        Catalogue oil (``"ISO VG 220"``, ``"VG68-PAO"``; ``sealsim oil list``), or your oil's
        datasheet ``{"name": ..., "nu40": "220 mm^2/s", "nu100": "19 mm^2/s",
        "density15": "895 kg/m^3", "min_temperature": "-30 degC"}`` (the fields of a case's
        ``[oil]`` table, :class:`~sealsim.rotary.case.OilSpec`), or an
        :class:`~sealsim.properties.oils.Oil` (e.g. ``Oil.from_datasheet``).
    sump_temperature : str, pint quantity or array, optional
        Oil sump held at this temperature, e.g. ``"70 degC"``, as in a
        gearbox whose gears heat the oil.  ``None``: the sump is heated by the seal alone and
        finds its own temperature.
    material : str
        Catalogue elastomer of the lip (``"NBR"``, ``"HNBR"``, ``"FKM"``, ``"ACM"``,
        ``"VMQ"``).
    lip_style : {"plain", "wave"}
        Plain or wave (hydrodynamic) lip.
    ambient_temperature : str, pint quantity or array
        Air around the housing, default 20 °C.
    radial_force : str or pint quantity, optional
        Lip force at 20 °C, e.g. ``"40 N"``; default 0.15 N/mm · π·d.
    contact_width : str or pint quantity, optional
        Axial contact width of the lip, e.g. ``"0.25 mm"``; default from the diameter.
    mounting_temperature : str or pint quantity, optional
        Temperature at which the seal was mounted, e.g. ``"20 degC"`` (the default).  A lip
        running colder keeps the stress it relaxed to there; only its thermal contraction
        since meets the stiffer cold rubber (the ``lip_note`` column says so).
    case : mapping, optional
        Any further fields of a rotary case (:class:`~sealsim.rotary.case.RotaryCase`), as
        nested tables with units as in a case file: ``{"environment": {"sump_volume":
        "0.2 L"}, "friction": {...}}``.  A field that an argument sets (``seal.material``,
        ``environment.sump_temperature``, the ``oil`` table, ...) is refused here.

    Returns
    -------
    dict or pandas.DataFrame
        shaft_diameter_mm, speed_rpm, torque_Nm, power_W, T_contact_C, T_groove_C,
        T_sump_C, T_housing_C (the housing the seal sits in), film_um, F_lub_N, F_material_N,
        bearing_power_W (the bearing beside the seal), heat_oil_side_W, heat_housing_W,
        heat_air_side_W (where the heat leaves shaft and seal: into the oil side, through the
        seal's outer diameter, on the air side; they add up to power_W plus the bearing's
        shaft share), lip_note (text: the lip's mounting
        case when it runs colder than it was mounted, else ""): a dict for scalar arguments (with
        ``notes``, a list of str), a DataFrame with one row per point when any of
        shaft_diameter, speed, sump_temperature, ambient_temperature is an array (they
        broadcast against each other; notes in ``frame.attrs["notes"]``).  The notes (also
        issued as :class:`~sealsim.errors.SealsimWarning`, once per call) are those of
        ``sealsim rotary run``: a contact above the elastomer's service limit, films outside
        the measured range, a contact below a held sump (with the housing's temperature, the
        cause); in a DataFrame, a point without a steady state is a row of NaN
        and a note gives its reason.

    Raises
    ------
    InputError
        A value without a unit, a wrong unit or dimension, an unknown oil or material (with
        close matches), a value out of range (naming the case field), arrays that do not
        broadcast, more than ``MAX_POINTS["lip_seal_torque"]`` points.
    ModelError
        No steady state (a contact beyond the elastomer's range, a free sump below the oil's):
        the point of a scalar call, or every point of an array call.

    Examples
    --------
    >>> r = lip_seal_torque("60 mm", "1500 rpm", "ISO VG 220", "70 degC")
    >>> round(r["torque_Nm"], 3), round(r["film_um"], 2)
    (0.22, 0.82)
    >>> lip_seal_torque("60 mm", ["500 rpm", "3000 rpm"], "ISO VG 220",
    ...                 "70 degC")[["speed_rpm", "torque_Nm"]].round(3)
       speed_rpm  torque_Nm
    0      500.0      0.196
    1     3000.0      0.234
    >>> lip_seal_torque("60 mm", 1500, "ISO VG 220")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: speed: 1500 has no unit; a plain number is ambiguous for an \
angular speed (rpm or rad/s?): write it with its unit, e.g. '1500 rpm'
    """
    from sealsim.cases import apply_overrides, validate_case
    from sealsim.rotary.case import RotaryCase
    from sealsim.rotary.simulation import lip_seal_friction, operating_notes, steady_state
    from sealsim.tribology.film import FilmRangeWarning

    shape, points = _operating_points("lip_seal_torque", {
        "shaft_diameter": (shaft_diameter, "length"), "speed": (speed, "angular_speed"),
        "ambient_temperature": (ambient_temperature, "temperature"),
        **({} if sump_temperature is None
           else {"sump_temperature": (sump_temperature, "temperature")})})
    if np.any(points["speed"] < 0):
        raise InputError(f"speed: {speed!r} must be >= 0")
    seal: dict[str, Any] = {"material": material, "lip_style": lip_style}
    for name, value, dimension, unit in (("radial_force", radial_force, "force", "N"),
                                         ("contact_width", contact_width, "length", "m"),
                                         ("mounting_temperature", mounting_temperature,
                                          "temperature", "K")):
        if value is not None:
            seal[name] = _si_text(_scalar(value, dimension, name), unit)
    oil_table = _oil_argument(oil)
    _refuse_argument_fields(case, LIP_SEAL_ARGUMENT_FIELDS)
    base = apply_overrides({"seal": seal, "oil": oil_table}, dict(case or {}))

    cases: dict[tuple, RotaryCase] = {}  # one case per geometry and temperatures
    rows, failed = [], []
    t_sump = points.get("sump_temperature", np.full(points["speed"].shape, np.nan))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FilmRangeWarning)  # one note per call, not per point
        for k in range(points["speed"].size):
            key = (points["shaft_diameter"][k], points["ambient_temperature"][k], t_sump[k])
            if key not in cases:
                env = {"ambient_temperature": _si_text(key[1], "K")}
                if not math.isnan(key[2]):
                    env["sump_temperature"] = _si_text(key[2], "K")
                data = apply_overrides(base, {"seal": {"shaft_diameter": _si_text(key[0], "m")},
                                              "environment": env})
                cases[key] = validate_case(RotaryCase, data, "lip_seal_torque arguments")
            omega = float(points["speed"][k])
            try:
                result = steady_state(cases[key], omega)
            except ModelError as exc:
                if shape == ():
                    raise
                # one point of a sweep without a steady state: NaN with the reason, the others
                failed.append(str(exc))
                result = {**dict.fromkeys(LIP_SEAL_COLUMNS[2:], math.nan), "lip_note": ""}
            rows.append({"shaft_diameter_mm": key[0] * 1e3, "speed_rpm": omega * 30.0 / math.pi,
                         **{c: result[c] for c in LIP_SEAL_COLUMNS[2:]}})
    if len(failed) == len(rows):
        raise ModelError(f"lip_seal_torque: no point has a steady state; the first: {failed[0]}")
    first = next(iter(cases.values()))
    solved = [r for r in rows if not math.isnan(r["T_contact_C"])]
    films = [r["film_um"] for r in solved if r["speed_rpm"] != 0]
    notes = operating_notes(first, lip_seal_friction(first).elastomer,
                            [r["T_contact_C"] for r in solved], films,
                            housing_temperatures_c=[r["T_housing_C"] for r in solved])
    if failed:
        notes.append(f"{len(failed)} of {len(rows)} points have no steady state (their rows "
                     "are NaN): " + "; ".join(failed))
    return _rows_out(rows, shape, LIP_SEAL_COLUMNS, notes)


def _oil_argument(oil) -> dict[str, Any]:
    """The case's ``[oil]`` table of the ``oil`` argument of :func:`lip_seal_torque`."""
    from sealsim.properties.catalogue import oil_table
    from sealsim.properties.oils import Oil

    if isinstance(oil, str):
        return {"name": oil}
    if isinstance(oil, Oil):
        return {"name": oil.name, **oil_table(oil)}
    if isinstance(oil, Mapping):
        return dict(oil)
    raise InputError(f"oil: {oil!r} is neither a catalogue name (str), a mapping of datasheet "
                     "values (nu40, nu100, density15, ...) nor an Oil "
                     "(sealsim.properties.Oil.from_datasheet)")


#: Case fields that arguments of :func:`lip_seal_torque` set (table -> {field: argument});
#: ``None``: the whole table.
LIP_SEAL_ARGUMENT_FIELDS = {
    "seal": {"shaft_diameter": "shaft_diameter", "material": "material",
             "lip_style": "lip_style", "radial_force": "radial_force",
             "contact_width": "contact_width", "mounting_temperature": "mounting_temperature"},
    "oil": None,
    "environment": {"sump_temperature": "sump_temperature",
                    "ambient_temperature": "ambient_temperature"}}


def _refuse_argument_fields(case: Mapping[str, Any] | None,
                            owned: dict[str, dict[str, str] | None]) -> None:
    """An InputError if ``case`` is not a mapping of case tables, or sets a field that an
    argument sets (one of the two would be ignored without a word)."""
    if case is not None and not isinstance(case, Mapping):
        raise InputError(f"case: {case!r} must be a mapping of case tables with units, e.g. "
                         "{'environment': {'sump_volume': '0.2 L'}} (a case file runs with "
                         "'sealsim rotary run')")
    for table, fields in owned.items():
        given = (case or {}).get(table)
        if given is None:
            continue
        if fields is None:
            raise InputError(f"case: [{table}] is the argument {table}=...; give it there")
        both = sorted(set(given) & set(fields)) if isinstance(given, Mapping) else []
        if both:
            raise InputError(f"case: {table}.{both[0]} = {given[both[0]]!r} is the argument "
                             f"{fields[both[0]]}=...; give it there (not both)")


def seal_friction(seal, velocity, pressure="0 bar", temperature="20 degC", law=None, *,
                  diameter=None, progress=None):
    """Steady friction force of a reciprocating seal over sliding velocity.

    The seal's normal force F_N and contact width b come from a contact map at the pressure
    difference across the seal and its temperature (an FE characteristic map, Heipl &
    Murrenhoff's characteristic diagrams, or the analytic O-ring estimate of
    :class:`~sealsim.pneumatic.contact_maps.AnalyticContactMap`); the friction is that of a
    friction law after sliding at constant velocity for a long time
    (``FrictionLaw.steady_force``).  By default the Θ law's steady curve comes from the
    seal's own contact pressure profile (inverse hydrodynamic film, asperity load share,
    boundary and viscous shear: :mod:`sealsim.tribology.mixed_lubrication`, tabulated per
    seal and cached, :mod:`sealsim.pneumatic.friction_tables`); then the film at the pressure
    maximum, the asperity share of the load and the net fluid transport per metre of double
    stroke come with it.

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
    velocity : str, pint quantity or array
        Sliding velocity, e.g. ``"0.2 m/s"``, ``["0.01 m/s", "0.1 m/s"]`` or a numpy array
        times its unit, ``np.linspace(0.01, 1.0, 50) * sealsim.units.ureg("m/s")``; positive:
        the counter surface slides from the pressurised side to the other (a rod seal's
        outstroke).
    pressure : str, pint quantity or array
        Gauge pressure on the pressurised side, atmosphere on the other (a rod seal, or a
        piston seal with one chamber vented), e.g. ``"6 bar"``; default 0 bar.
    temperature : str, pint quantity or array
        Seal temperature, default 20 °C.
    law : str, mapping or FrictionLaw, optional
        The friction law: a law name whose parameters are its only named set
        (``"lugre"``: ``canudas1995``; a law with several sets, such as ``"theta"``, is
        refused with their names), a ``[friction]`` table of a case file
        (``{"law": "stribeck", "parameter_set": "pneumatic_demo", "coulomb_force": "12 N"}``)
        or a law object of :mod:`sealsim.friction`.  Default :data:`DEFAULT_LAW`: the Θ law
        whose steady curve comes from the seal's contact (set ``seal_contact``: boundary
        friction and roughness are generic literature values; fit ``boundary_friction`` to
        your seal with ``sealsim friction fit``).  The lumped set ``pneumatic_demo`` is
        illustrative, and the result's notes say so.
    diameter : str or pint quantity, optional
        Diameter of the sliding surface (rod or bore) for the analytic estimate, e.g.
        ``"12 mm"``.
    progress : callable, optional
        ``progress(done, total)`` while an FE map is built on demand (finished FE load paths).
        The build is announced before it starts at INFO level on the logger
        ``sealsim.pneumatic.contact_maps`` ("building FE map from ... cached at ...");
        ``logging.basicConfig(level=logging.INFO)`` prints it.

    Returns
    -------
    dict or pandas.DataFrame
        velocity_m_s, pressure_bar (gauge), temperature_C, friction_N (signed like the
        velocity), normal_force_N, contact_width_mm, and with a steady curve from the contact
        film_um (film at the pressure maximum in the stroke direction of the velocity),
        asperity_share (share of F_N the asperities carry) and transport_mm3_per_m (fluid
        the seal lets pass per metre of double stroke at this speed, π·D·(h*_out − h*_in)/2:
        > 0 leaks out, <= 0 is dragged back; NaN for other laws; for the analytic O-ring
        estimate (its Hertz profile plus the sealed pressure) 0 without pressure and an
        estimate under pressure -- an FE map gives each stroke its own inlet flank): a
        DataFrame with one row per point if velocity, pressure or temperature is an array
        (broadcast), else a dict.
        At velocity 0 the friction is 0 N (sliding friction has no direction at rest), the
        film, share and transport NaN, and a note gives the limit towards rest.
        Notes (an illustrative parameter set, a velocity of 0, a law whose friction does not
        change with F_N and b, such as LuGre's newtons) as for :func:`lip_seal_torque`:
        ``result["notes"]``, ``frame.attrs["notes"]`` and
        :class:`~sealsim.errors.SealsimWarning`.

    Raises
    ------
    InputError
        A value without a unit, a wrong unit, an unknown law or material, a pressure or
        temperature outside the contact map, a law that needs parameters, arrays that do not
        broadcast, more than ``MAX_POINTS["seal_friction"]`` points.

    Examples
    --------
    >>> import warnings
    >>> oring = {"cord_diameter": "2 mm", "squeeze": 0.12}
    >>> with warnings.catch_warnings(record=True):   # notes on illustrative parameters
    ...     curve = seal_friction(oring, ["0.01 m/s", "0.1 m/s", "1 m/s"], "6 bar",
    ...                           diameter="12 mm")
    >>> curve[["velocity_m_s", "friction_N", "normal_force_N", "film_um"]].round(2)
       velocity_m_s  friction_N  normal_force_N  film_um
    0          0.01        2.67           38.02     0.77
    1          0.10        0.56           38.02     1.97
    2          1.00        1.75           38.02     6.26
    """
    from sealsim.friction.base import ContactInputs
    from sealsim.units import ZERO_CELSIUS_K

    shape, points = _operating_points("seal_friction", {
        "velocity": (velocity, "velocity"), "pressure": (pressure, "pressure"),
        "temperature": (temperature, "temperature")})
    v, dp, t = points["velocity"], points["pressure"], points["temperature"]
    if np.any(dp < 0):
        raise InputError(f"pressure: {pressure!r} must be >= 0 (a gauge pressure difference)")
    contact_map = _contact_map(seal, diameter, progress)
    _check_ranges(contact_map, dp, t)
    friction_law, notes = _friction_law(DEFAULT_LAW if law is None else law)
    normal_force, width = (np.asarray(x, dtype=float) * np.ones_like(dp)
                           for x in contact_map.evaluate(dp, t))
    table, diameter_m = _contact_table(friction_law, contact_map)
    inputs = ContactInputs(normal_force=normal_force, contact_width=width, pressure_a=dp,
                           pressure_b=0.0, temperature=t, contact_table=table,
                           sliding_diameter=diameter_m)
    force = np.asarray(friction_law.steady_force(v, inputs), dtype=float).reshape(-1)
    if table is None:  # a steady curve from the contact table uses the contact
        notes = [*notes, *_contact_unused_note(friction_law, v, inputs, force)]
    film = share = transport = np.full(v.size, np.nan)
    if table is not None:
        from sealsim.pneumatic.case import excess_friction_cause
        from sealsim.tribology.inverse_hydrodynamics import stroke_transport

        ratio = np.abs(force) / normal_force
        if np.any(ratio > 1.0):
            worst = int(np.argmax(ratio))
            notes = [*notes, f"{int(np.sum(ratio > 1.0))} of {v.size} points: the steady "
                     f"friction passes the contact force (F/F_N up to {ratio[worst]:.2g} at "
                     f"{abs(v[worst]):.3g} m/s): {excess_friction_cause(friction_law)}"]

        load, _, film = table.evaluate(v, dp, t)
        share = np.pi * diameter_m * load / normal_force
        film_out = table.evaluate(np.abs(v), dp, t)[2]
        film_in = table.evaluate(-np.abs(v), dp, t)[2]
        transport = stroke_transport(diameter_m, 1.0, film_out, film_in)
    at_rest = v == 0.0
    if np.any(at_rest):
        # sliding friction has no direction at rest: the law gives 0; say what it tends to
        limit = np.abs(np.asarray(friction_law.steady_force(
            np.full(v.size, REST_LIMIT_SPEED), inputs), dtype=float).reshape(-1))[at_rest]
        notes = [*notes, f"velocity 0 m/s ({int(at_rest.sum())} of {v.size} points): the "
                 "steady friction of sliding has no direction at rest and is given as 0 N (no "
                 "film, share or transport there); as the speed falls to 0 it tends to "
                 f"{_span(limit, 'N')}; the force a seal at rest holds before it breaks away "
                 "is the friction law's static friction (sealsim friction run)"]
        film, share, transport = (np.where(at_rest, np.nan, x) for x in (film, share, transport))
    columns = {"velocity_m_s": v, "pressure_bar": dp / 1e5, "temperature_C": t - ZERO_CELSIUS_K,
               "friction_N": force, "normal_force_N": normal_force,
               "contact_width_mm": width * 1e3, "film_um": film * 1e6, "asperity_share": share,
               "transport_mm3_per_m": transport * 1e9}
    return _rows_out(columns, shape, SEAL_FRICTION_COLUMNS, notes)


#: Speed at which :func:`seal_friction` evaluates the limit of the steady friction towards rest
#: [m/s] (the contact friction tables are flat below their slowest speed, 1e-7 m/s).
REST_LIMIT_SPEED = 1e-9


def _contact_unused_note(friction_law, velocity, inputs, force) -> list[str]:
    """A note when the law's steady force does not change with the seal's contact (F_N and b
    doubled: the same force), e.g. LuGre or Coulomb parameter sets in newtons."""
    from dataclasses import replace

    doubled = replace(inputs, normal_force=2 * np.asarray(inputs.normal_force),
                      contact_width=2 * np.asarray(inputs.contact_width))
    again = np.asarray(friction_law.steady_force(velocity, doubled), dtype=float).reshape(-1)
    if not np.array_equal(again, force):
        return []
    name = getattr(friction_law.params, "law", type(friction_law).__name__)
    return [f"the {name} law's friction does not depend on the seal's normal force and "
            "contact width: they are the seal's, the friction force comes from the law's "
            "parameters (and, with a pressure scaling, the pressure) alone; the theta law "
            "takes its friction from the contact"]


def _span(values: np.ndarray, unit: str) -> str:
    """'3.1 N' or '2.9-3.4 N' (3 significant digits)."""
    low, high = float(np.min(values)), float(np.max(values))
    return f"{low:.3g} {unit}" if f"{low:.3g}" == f"{high:.3g}" else \
        f"{low:.3g}-{high:.3g} {unit}"


def _contact_table(friction_law, contact_map):
    """(friction table, sliding diameter [m]) of a law whose steady curve comes from the
    seal's contact, else (None, None)."""
    from sealsim.pneumatic.case import seal_friction_table
    from sealsim.pneumatic.friction_tables import sliding_diameter

    if getattr(friction_law.params, "steady", "lumped") != "contact":
        return None, None
    return seal_friction_table(friction_law, contact_map, "seal"), sliding_diameter(contact_map)


def _rows_out(rows: list[dict] | dict[str, np.ndarray], shape: tuple, columns: list[str],
              notes: list[str]):
    """A dict of floats (text columns as str; and its notes) for a single point given as
    scalars, else a DataFrame (notes in ``attrs``); each note is issued once as a
    :class:`SealsimWarning`."""
    for note in notes:
        warnings.warn(note, SealsimWarning, stacklevel=3)
    import pandas as pd

    frame = pd.DataFrame(rows, columns=columns)
    if shape == ():
        first = {c: frame[c].iloc[0] for c in columns}
        return {**{c: v if isinstance(v, str) else float(v) for c, v in first.items()},
                "notes": list(notes)}
    frame.attrs["notes"] = list(notes)
    return frame


def _operating_points(function: str, arguments: dict[str, tuple[Any, str]]
                      ) -> tuple[tuple, dict[str, np.ndarray]]:
    """The shape of the broadcast point arguments and each as a flat SI array.

    ``arguments`` maps an argument's name to ``(value, dimension)``.  A value needs its unit
    (a plain number is refused); arguments that do not broadcast against each other and more
    than :data:`MAX_POINTS` points are refused before any value is converted.
    """
    shapes = {name: _shape(value) for name, (value, _) in arguments.items()}
    try:
        shape = np.broadcast_shapes(*shapes.values())
    except ValueError:
        given = ", ".join(f"{name} has shape {s}" for name, s in shapes.items() if s)
        raise InputError(f"{function}: the arrays do not broadcast against each other ({given}):"
                         " give arrays of one length, or scalars") from None
    size = math.prod(shape)
    if size > MAX_POINTS[function]:
        raise InputError(f"{function}: {size} operating points are more than the "
                         f"{MAX_POINTS[function]} one call evaluates; split them into several "
                         "calls")
    return shape, {name: np.broadcast_to(np.asarray(
        to_si(value, dimension, name, plain_is_si=False), dtype=float), shape).ravel()
        for name, (value, dimension) in arguments.items()}


def _shape(value) -> tuple:
    """Shape of an argument (a pint array's magnitude, a nested list)."""
    magnitude = getattr(value, "magnitude", value)
    if not isinstance(magnitude, list | tuple | np.ndarray):
        return ()
    return np.asarray(magnitude, dtype=object).shape   # a ragged list: refused by to_si


def _scalar(value, dimension: str, name: str) -> float:
    """One SI value of an argument that takes no array."""
    si = to_si(value, dimension, name, plain_is_si=False)
    if np.ndim(si) != 0:
        raise InputError(f"{name}: one value is expected, got an array of shape {np.shape(si)}")
    return float(si)


def _si_text(value: float, unit: str) -> str:
    """A case-file quantity string of an SI value, exact (``repr`` of the float)."""
    return f"{float(value)!r} {unit}"


_MAP_SOURCES = ("analytic", "file", "structure_case")


def _contact_map(seal, diameter, progress=None):
    """The contact map of a ``seal`` argument (see :func:`seal_friction`)."""
    from sealsim.cases import validate_case
    from sealsim.pneumatic.case import MapModel, build_contact_map

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
    spec = validate_case(MapModel, table, "seal")
    sliding = None if diameter is None else _scalar(diameter, "length", "diameter")
    if sliding is not None and sliding <= 0:
        raise InputError(f"diameter: {diameter!r} must be > 0 (the diameter of the sliding "
                         "surface, rod or bore)")
    if spec.analytic is not None and spec.analytic.sliding_diameter is None and sliding is None:
        raise InputError("seal: the analytic estimate needs the diameter of the sliding "
                         "surface (rod or bore): give diameter='12 mm'")
    return build_contact_map(spec, sliding or 0.0, Path.cwd(), "seal", progress)


def _check_ranges(contact_map, pressure: np.ndarray, temperature: np.ndarray) -> None:
    """Refuse points outside the map (its evaluate would clamp them silently)."""
    from sealsim.pneumatic.contact_maps import glassy_reason
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
            value = float(values[np.argmax(bad)])
            shown = value * scale + offset
            hint = ""
            if name == "pressure" and hasattr(contact_map, "pressure_max"):
                hint = ("; the analytic estimate's range: seal={..., 'pressure_max': "
                        f"'{shown:.6g} bar'}}")
            raise InputError(f"{name}: {shown:.6g} {unit} is outside the seal's contact map "
                             f"({lo * scale + offset:.6g} ... {hi * scale + offset:.6g} {unit})"
                             + (glassy_reason(contact_map, value) if name == "temperature"
                                else hint))


def _friction_law(law):
    """A friction law object from a name, a ``[friction]`` table or a law object, and its notes
    (an illustrative parameter set)."""
    from sealsim.friction import PARAMETER_SETS, make_law
    from sealsim.friction.base import FrictionLaw, PassivityWarning
    from sealsim.friction.parameters import parameter_set_note

    if isinstance(law, FrictionLaw):
        return law, []
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
    note = parameter_set_note(params)
    with warnings.catch_warnings():
        # passivity concerns fast velocity changes, not the steady friction computed here
        warnings.simplefilter("ignore", PassivityWarning)
        return make_law(params), [note] if note else []


def _law_parameters(table: Mapping[str, Any]):
    from pydantic import TypeAdapter, ValidationError

    from sealsim.cases import format_validation_error
    from sealsim.friction.case import LawParameters

    try:
        return TypeAdapter(LawParameters).validate_python(dict(table),
                                                          context={"require_units": True})
    except ValidationError as exc:
        raise InputError(format_validation_error(exc, "law")) from None


def oring_gland(gland, *, fe: bool = False, progress=None) -> dict[str, Any]:
    """Design check of an O-ring (or X-ring) gland: squeeze, stretch, gland fill and extrusion
    gap from the worst-case tolerance stack, at the lowest and highest service temperature,
    against the published design ranges; with ``fe=True`` also the FE contact force and the
    friction at nominal.

    The stack and the checks are :func:`sealsim.structure.gland_check.check_gland` (ISO 286
    fits and ISO 3601-1 ring tolerances, rubber and metal expansion, fluid swell; every limit
    with its source).  The FE force is the structure model's (:mod:`sealsim.structure`) for
    the nominal gland (every size at the middle of its band), the friction
    :func:`seal_friction`'s with that FE map.

    Parameters
    ----------
    gland : str, path, mapping or GlandCase
        A gland case file (``examples/gland/piston_static.toml``), its tables as a mapping
        with quantities as strings with units (``{"ring": {...}, "housing": {...},
        "service": {...}}``, see the gland case reference) or a validated
        :class:`~sealsim.structure.gland_case.GlandCase`.
    fe : bool
        Also run the FE model at nominal (needs the case's ``[fe]`` table with the sliding
        velocity; piston and rod glands only).
    progress : callable, optional
        ``progress(done, total)`` while the FE map is built.

    Returns
    -------
    dict
        The ``report.json`` of ``sealsim gland check``: ``squeeze_percent``,
        ``stretch_percent``, ``gland_fill_percent``, ``extrusion_gap_mm`` (each ``{"min",
        "nominal", "max"}``), ``by_temperature``, ``extrusion``, ``checks`` (``{"name",
        "value", "limit", "ok", "source", ...}``), ``ok``, ``failed``, ``notes`` and, with
        ``fe``, ``fe``: normal force and contact width (``{"unpressurised", "at_pressure"}``)
        and the friction of both strokes, ``friction_N = {"outstroke": {"unpressurised",
        "at_pressure"}, "instroke": {...}}`` -- outstroke: the sealed surface slides from the
        pressurised side to the other (a rod moving out; a piston moving towards its
        pressurised side), its film enters over the pressurised flank; instroke: the other
        way, over the flank where the contact pressure drops from the sealed pressure to 0,
        usually a thinner film and more friction.

    Examples
    --------
    >>> r = oring_gland("examples/gland/piston_static.toml")
    >>> r["ok"], [round(r["squeeze_percent"][k], 1) for k in ("min", "nominal", "max")]
    (True, [17.0, 21.2, 25.7])
    """
    from sealsim.cases import validate_case
    from sealsim.structure.gland_case import GlandCase, load_gland_case
    from sealsim.structure.gland_check import check_gland

    if isinstance(gland, GlandCase):
        case = gland
    elif isinstance(gland, str | Path):
        case = load_gland_case(gland)
    elif isinstance(gland, Mapping):
        case = validate_case(GlandCase, dict(gland), "gland")
    else:
        raise InputError(f"gland: {gland!r} is neither a gland case file nor a mapping of its "
                         "tables")
    report = check_gland(case)
    out = report.to_dict()
    if fe:
        out["fe"] = _gland_fe(report, progress)
    return out


def _gland_fe(report, progress=None) -> dict[str, Any]:
    """FE normal force, contact width and friction of the nominal gland of a gland report."""
    import tempfile

    import tomli_w

    from sealsim.units import ZERO_CELSIUS_K

    case, geometry = report.case, report.geometry
    if case.fe is None:
        raise InputError("fe: the FE check needs the case's [fe] table with the sliding "
                         "velocity, e.g. [fe] velocity = '0.1 m/s'")
    housing = case.housing
    if housing.type == "face":
        raise InputError("fe: the structure model has rod, piston and shaft glands; a face "
                         "gland (axial squeeze) has no FE model yet")
    nominal = geometry.nominal()
    t_ref = case.service.assembly_temperature
    state = geometry.state(nominal, t_ref)
    squeeze_nominal = float(state["squeeze"])
    # the installed ring: its section after stretch, sitting on its seat (the FE closes both
    # radial surfaces on the free section to the nominal squeeze)
    seat = nominal["groove_diameter"] if housing.type == "piston" else nominal["rod"]
    sealing = nominal["bore"] if housing.type == "piston" else nominal["rod"]
    pressure = case.service.pressure
    grid = [0.0, 0.5 * pressure, pressure] if pressure > 0 else [0.0, 1e5]
    mm = lambda x: f"{x * 1e3:.6g} mm"  # noqa: E731
    structure = {
        "title": f"nominal gland of {case.title or 'a gland check'}",
        "seal": {"type": case.ring.type, "cord_diameter": mm(float(state["cord"])),
                 "inner_diameter": mm(seat)},
        "gland": {"arrangement": housing.type, "sealing_diameter": mm(sealing),
                  "groove_width": mm(nominal["groove_width"]),
                  "inner_expansion": f"{housing.inner_expansion:.6g} 1/K",
                  "outer_expansion": f"{housing.outer_expansion:.6g} 1/K"},
        "material": {"elastomer": case.ring.material, "hardness_shore_a": report.hardness},
        "mesh": {"level": case.fe.mesh},
        "load": {"installation_temperature": f"{t_ref - ZERO_CELSIUS_K:.6g} degC",
                 "squeeze": [round(squeeze_nominal, 6)]},
        "map": {"pressure": [f"{p / 1e5:.6g} bar" for p in grid],
                "temperature": [f"{t_ref - ZERO_CELSIUS_K:.6g} degC"], "workers": 1},
        # the rod example's path gets past the wetted surface's fold near 50 bar only on the
        # increments of the previous control (docs/guide/validation_structure.md, "Newton and
        # the wetted surface"); with growing increments it stops at 64.1 bar
        "solver": {"increment_growth": False},
    }
    with tempfile.TemporaryDirectory(prefix="sealsim-gland-") as tmp:
        path = Path(tmp) / "gland_nominal.toml"
        path.write_text(tomli_w.dumps(structure), encoding="utf-8")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            u = case.fe.velocity
            curve = seal_friction(str(path), [f"{v:.6g} m/s" for v in (u, -u, u, -u)],
                                  [f"{p / 1e5:.6g} bar" for p in (0.0, 0.0, pressure, pressure)],
                                  f"{t_ref - ZERO_CELSIUS_K:.6g} degC", law=case.fe.law,
                                  progress=progress)
    notes = list(dict.fromkeys(str(w.message) for w in caught
                               if w.category.__module__.startswith("sealsim")))
    notes += [n for n in (getattr(curve, "attrs", {}) or {}).get("notes", []) if n not in notes]
    rest, loaded = curve.iloc[0], curve.iloc[2]
    friction = np.abs(curve["friction_N"].to_numpy(dtype=float))
    return {"squeeze_percent": squeeze_nominal * 100.0,
            "temperature_C": t_ref - ZERO_CELSIUS_K,
            "velocity_m_s": case.fe.velocity,
            "pressure_bar": pressure / 1e5,
            "normal_force_N": {"unpressurised": float(rest["normal_force_N"]),
                               "at_pressure": float(loaded["normal_force_N"])},
            "contact_width_mm": {"unpressurised": float(rest["contact_width_mm"]),
                                 "at_pressure": float(loaded["contact_width_mm"])},
            "friction_N": {"outstroke": {"unpressurised": float(friction[0]),
                                         "at_pressure": float(friction[2])},
                           "instroke": {"unpressurised": float(friction[1]),
                                        "at_pressure": float(friction[3])}},
            "law": case.fe.law or DEFAULT_LAW, "mesh": case.fe.mesh,
            "structure_case": structure, "notes": notes}


#: Columns of :func:`friction_loop` (units in the names).
FRICTION_LOOP_COLUMNS = ["time_s", "velocity_m_s", "displacement_mm", "friction_N"]


def friction_loop(seal, velocity_amplitude, frequency, pressure="0 bar",
                  temperature="20 degC", law=None, *, mean_velocity="0 m/s", diameter=None,
                  cycles: int = 3, steps_per_cycle: int = 400, progress=None):
    """Friction of a reciprocating seal over a harmonic sliding velocity: the hysteresis loop.

    The velocity v(t) = v_mean + v_a·sin(2π f t) drives the friction law's states from rest
    (``FrictionLaw.trajectory``, exact for the velocity held over each step, taken at the
    step's midpoint); F_N and b come from the seal's contact map at the pressure and
    temperature, as in :func:`seal_friction`.  A law without states (Coulomb, Stribeck)
    follows its steady curve; LuGre, Dahl, GMS and Θ lag behind the velocity and open a loop
    (Canudas de Wit et al., IEEE TAC 40 (1995) 419, Fig. 3).

    Parameters
    ----------
    seal, pressure, temperature, law, diameter, progress
        As for :func:`seal_friction`.
    velocity_amplitude : str or pint quantity
        v_a, e.g. ``"5 mm/s"``.
    frequency : str or pint quantity
        f, e.g. ``"1 Hz"``.
    mean_velocity : str or pint quantity
        v_mean (default 0: the sliding reverses, a force-displacement loop).
    cycles : int
        Periods simulated; all are returned (the first starts from rest).
    steps_per_cycle : int
        Time steps per period.

    Returns
    -------
    pandas.DataFrame
        time_s, velocity_m_s, displacement_mm, friction_N; notes as for
        :func:`seal_friction` (``frame.attrs["notes"]`` and :class:`SealsimWarning`).

    Examples
    --------
    >>> oring = {"cord_diameter": "2 mm", "squeeze": 0.12}
    >>> loop = friction_loop(oring, "5 mm/s", "1 Hz", "6 bar", diameter="12 mm",
    ...                      law={"law": "lugre", "parameter_set": "canudas1995"})
    >>> len(loop), round(float(loop["displacement_mm"].max()), 3)
    (1201, 1.592)
    """
    import pandas as pd

    from sealsim.friction.base import ContactInputs

    v_a = to_si(velocity_amplitude, "velocity", "velocity_amplitude", plain_is_si=False)
    v_m = to_si(mean_velocity, "velocity", "mean_velocity", plain_is_si=False)
    f = to_si(frequency, "frequency", "frequency", plain_is_si=False)
    dp = to_si(pressure, "pressure", "pressure", plain_is_si=False)
    temp = to_si(temperature, "temperature", "temperature", plain_is_si=False)
    for name, value in (("velocity_amplitude", v_a), ("mean_velocity", v_m),
                        ("frequency", f), ("pressure", dp), ("temperature", temp)):
        if np.ndim(value) != 0 or not math.isfinite(float(value)):
            raise InputError(f"{name}: {value!r} must be one finite value")
    for name, value, ok, allowed in (
            ("velocity_amplitude", velocity_amplitude, v_a > 0, "> 0"),
            ("frequency", frequency, f > 0, "> 0"), ("pressure", pressure, dp >= 0, ">= 0")):
        if not ok:
            raise InputError(f"{name}: {value!r} must be {allowed}")
    for name, value, low, high in (("cycles", cycles, 1, 50),
                                   ("steps_per_cycle", steps_per_cycle, 20, 20000)):
        # a count: 2.5 cycles were run as 2, the string '400' was read as 400
        if isinstance(value, bool) or not isinstance(value, int | np.integer) \
                or not low <= value <= high:
            raise InputError(f"{name} = {value!r} must be a whole number from {low} to {high}")
    contact_map = _contact_map(seal, diameter, progress)
    _check_ranges(contact_map, np.array([dp]), np.array([temp]))
    friction_law, notes = _friction_law(DEFAULT_LAW if law is None else law)
    normal_force, width = (float(np.asarray(x, dtype=float).reshape(-1)[0])
                           for x in contact_map.evaluate(dp, temp))
    table, diameter_m = _contact_table(friction_law, contact_map)
    n = int(cycles) * int(steps_per_cycle)
    t = np.linspace(0.0, int(cycles) / f, n + 1)
    dt = np.diff(t)
    omega = 2.0 * math.pi * f
    velocity = v_m + v_a * np.sin(omega * t)
    displacement = v_m * t + v_a / omega * (1.0 - np.cos(omega * t))
    mid = v_m + v_a * np.sin(omega * (t[:-1] + 0.5 * dt))
    inputs = ContactInputs(normal_force=np.array([normal_force]), contact_width=width,
                           pressure_a=dp, pressure_b=0.0, temperature=temp,
                           contact_table=table, sliding_diameter=diameter_m)
    states = friction_law.trajectory(friction_law.initial_state(1), mid, dt, inputs)
    z = np.moveaxis(states[:, :, 0], 0, -1)           # (n_states, n + 1)
    force = np.asarray(friction_law.force(z, velocity, inputs), dtype=float).reshape(-1)
    for note in notes:
        warnings.warn(note, SealsimWarning, stacklevel=2)
    frame = pd.DataFrame({"time_s": t, "velocity_m_s": velocity,
                          "displacement_mm": displacement * 1e3, "friction_N": force},
                         columns=FRICTION_LOOP_COLUMNS)
    frame.attrs["notes"] = list(notes)
    return frame
