"""The seal friction FMU: a friction law of :mod:`sealsim.friction` and its contact map in C.

Interface of the FMU (all SI):

============  ========  ===========================================================
variable      unit      meaning
============  ========  ===========================================================
v             m/s       input: sliding velocity of the body relative to the seal
p_A, p_B      Pa        inputs: gauge pressures on the two sides of the seal
T_seal        K         input: seal temperature (contact table, γ(T) of the Θ law)
F             N         output: friction force, acts against v (m dv/dt = F_app - F)
F_breakaway   N         output (laws with true sticking): largest friction at rest
F_N, b        N, m      outputs: normal force and contact width (Θ law, or a table)
dp            Pa        output: pressure difference across the seal (with a table)
map_clipped   -         output: true while dp or T_seal lies outside the table
theta, z      -, m      states: lubrication state Θ, bristle deflection z
film_speed    m/s       state (Θ law on its contact): the speed φ the film has formed for
============  ========  ===========================================================

plus every parameter of the law (the field names of the case files, with units) and, for a
constant contact, ``normal_force`` and ``contact_width``.  The contact table holds F_N and b
over (T, Δp): an FE characteristic map keeps its own grid and its PCHIP slopes (the same
interpolant as :class:`sealsim.structure.maps.SealMap`); the analytic estimate
(:class:`sealsim.pneumatic.contact_maps.AnalyticContactMap`) is tabulated with exact node
derivatives on a grid of ``temperature_points`` × ``pressure_points``.

The C code implements the laws ``coulomb``, ``stribeck``, ``lugre`` and ``theta`` (with or
without bristles, with a constant γ or γ(T) = γ·ν(T)/ν(T_ref) from the base oil's ASTM D341
viscosity, or with ``steady = "contact"``: the steady curve from the seal's own contact) -- the
equations of the compiled kernels of :mod:`sealsim.friction.kernels`, in their argument order;
any other law, or a parameter the C code does not know, is refused with an
:class:`~sealsim.errors.InputError`.

**The Θ law on the seal's contact** (``steady = "contact"``) needs the contact map (F_N, b) and
carries the seal's steady friction table (:mod:`sealsim.friction.contact_table`, its node
layout in ``config.h``, read by ``c/contact_table.c``: the numba interpolant in C) at
the pressure difference dp and ``T_seal``.  Its parameters are ``boundary_friction`` μ_b and
``dwell_drop`` (applied when the table is read), ``sliding_diameter`` D (the table is per unit
circumference) and ``velocity_direction``: +1 if a positive v slides the counter surface from
side A to side B of the seal (a rod seal with A the chamber), −1 the other way (a piston seal
with A the cap-end chamber); with it the table's stroke direction is
``velocity_direction·(p_A >= p_B ? 1 : −1)·sgn(v)`` ("+": from the pressurised side to the
other, :func:`sealsim.pneumatic.friction_tables.table_orientation`).  Its asperity load is
read at the speed φ the contact's film has formed for, the state ``film_speed``
(dφ/dt = (|v| − φ)·(|v|/b + κ(φ)), :func:`sealsim.friction.kernels.film_speed_rate`, κ the
film's decay rate at rest from the table; start value 0: no film), stepped exactly for κ held
at the step's start (:func:`~sealsim.friction.kernels.film_speed_affine`).

A new law parameter needs its entry (unit, description, bounds) in ``_PARAMETERS`` and
``_LAW_PARAMETERS`` below, which makes it an FMU parameter ``VR_<NAME>``, and its use in
``c/friction_model.c``.  After compiling,
:func:`friction_check` runs the binary against sealsim's own law object (``step``,
``force``, ``breakaway_force``, ``derivatives``) and refuses an FMU that does not reproduce
it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from sealsim.errors import InputError, ModelError
from sealsim.friction.base import ContactInputs, FrictionLaw
from sealsim.friction.contact_table import SteadyFrictionTable
from sealsim.fmu.model_description import ModelSpec, Variable
from sealsim.fmu.tables import HermiteTable, pchip_table, smooth_table
from sealsim.units import STANDARD_ATMOSPHERE_PA

__all__ = ["C_LAWS", "PRESSURE_ROUNDING", "STATE_NAMES", "ContactTable", "SteadyTable",
           "c_parameters", "contact_table", "friction_check", "friction_spec",
           "model_identifier", "steady_table"]

#: laws with a C implementation (friction_model.c)
C_LAWS = ("coulomb", "stribeck", "lugre", "theta")
_LAW_CODE = {"coulomb": 1, "stribeck": 2, "lugre": 3, "theta": 4}

#: the friction FMU's possible states, in state order (that of the laws' ``state_names``)
STATE_NAMES = ("theta", "z", "film_speed")
#: units of the states' time derivatives
_DERIVATIVE_UNITS = {"theta": None, "z": "m/s", "film_speed": "m/s2"}

#: rounding width of |p_A - p_B| (sealsim.pneumatic.seals.seal_pressure_difference) [Pa]
PRESSURE_ROUNDING = 1e3

_GE0, _GT0 = (">=", 0.0), (">", 0.0)
#: a gauge pressure input: not below vacuum (-1 atm)
_ABOVE_VACUUM = (">=", -STANDARD_ATMOSPHERE_PA)
# parameter -> (unit, description); bounds per law below (those of the pydantic models)
_PARAMETERS = {
    "coulomb_force": ("N", "Coulomb (kinetic) friction level F_C without pressure"),
    "static_force": ("N", "static (break-away) friction level F_S without pressure"),
    "stribeck_velocity": ("m/s", "Stribeck velocity v_S"),
    "exponent": (None, "Stribeck exponent delta"),
    "viscous_coefficient": ("N.s/m", "viscous coefficient F_v"),
    "pressure_coefficient": ("m2", "pressure scaling f of F_C(p) = F_C + f (p_A + p_B)"),
    "sigma0": ("N/m", "bristle stiffness sigma0"),
    "sigma1": ("N.s/m", "bristle micro-damping sigma1"),
    "sigma2": ("N.s/m", "viscous coefficient sigma2"),
    "tau": ("s", "film relaxation time constant tau"),
    "alpha": ("m", "characteristic sliding length alpha at F_N = F_ref"),
    "f_a": (None, "dry friction coefficient f_a (Theta = 0)"),
    "f_b": (None, "full-film friction coefficient f_b (Theta = 1)"),
    "gamma": ("Pa.s", "viscous coefficient gamma: force per contact width and velocity"),
    "reference_normal_force": ("N", "reference load F_ref of the film build-up"),
    "load_exponent": (None, "load exponent n of (F_N/F_ref)^n"),
    "bristle_stiffness": ("N/m", "pre-sliding bristle stiffness sigma0"),
    "bristle_damping": ("N.s/m", "bristle damping sigma1"),
    "reference_temperature": ("K", "temperature T_ref at which gamma holds"),
    "base_oil_nu40": ("m2/s", "kinematic viscosity of the grease's base oil at 40 degC: "
                      "gamma(T) = gamma nu(T)/nu(T_ref), ASTM D341 (Walther)"),
    "base_oil_nu100": ("m2/s", "kinematic viscosity of the grease's base oil at 100 degC"),
    "boundary_friction": (None, "boundary friction coefficient mu_b on the asperity load of "
                          "the contact table"),
    "dwell_drop": (None, "break-away force just after sliding (Theta = 1) below the long-dwell "
                   "one, as a fraction of it"),
}
_EXPONENT = ((">", 0.0), ("<=", 10.0))
_LAW_PARAMETERS = {
    "coulomb": {"coulomb_force": (_GE0, None), "viscous_coefficient": (_GE0, None),
                "pressure_coefficient": (_GE0, None)},
    "stribeck": {"coulomb_force": (_GE0, None), "static_force": (_GE0, None),
                 "stribeck_velocity": (_GT0, None), "exponent": _EXPONENT,
                 "viscous_coefficient": (_GE0, None), "pressure_coefficient": (_GE0, None)},
    "lugre": {"sigma0": (_GT0, None), "sigma1": (_GE0, None), "sigma2": (_GE0, None),
              "coulomb_force": (_GT0, None), "static_force": (_GT0, None),
              "stribeck_velocity": (_GT0, None), "exponent": _EXPONENT},
    "theta": {"tau": (_GT0, None), "alpha": (_GT0, None), "f_a": (_GE0, None),
              "f_b": (_GE0, None), "gamma": (_GE0, None),
              "reference_normal_force": (_GT0, None),
              "load_exponent": (_GE0, ("<=", 10.0)), "bristle_stiffness": (_GT0, None),
              "bristle_damping": (_GE0, None), "reference_temperature": (_GT0, None),
              "base_oil_nu40": (_GT0, None), "base_oil_nu100": (_GT0, None),
              "boundary_friction": (_GE0, None), "dwell_drop": (_GE0, ("<", 1.0))},
}
_STICTION = {"coulomb", "stribeck"}


def model_identifier(name: str) -> str:
    """A valid C identifier (FMI model identifier) from a file name.

    Examples
    --------
    >>> model_identifier("theta seal-32.fmu")
    'theta_seal_32'
    """
    stem = re.sub(r"\.fmu$", "", Path(name).name, flags=re.IGNORECASE)
    ident = re.sub(r"[^A-Za-z0-9_]", "_", stem).strip("_") or "sealsim_model"
    if ident[0].isdigit():
        ident = "m_" + ident
    return ident[:64]


# -- the contact table ----------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactTable:
    """F_N [N] and b [m] over (temperature [K], pressure difference [Pa]).

    Attributes
    ----------
    table : HermiteTable
        Axes (temperature, pressure difference), variables (F_N, b).
    temperature_range, pressure_range : (float, float)
        Where the table is valid; inputs outside are clipped (and reported) by the FMU.
    source : str
        Where the numbers come from.
    max_relative_error : dict
        Largest relative difference between the table and its source at the cell centres
        ({"F_N": ..., "b": ...}); 0 for FE maps (the same interpolant).
    """

    table: HermiteTable
    temperature_range: tuple[float, float]
    pressure_range: tuple[float, float]
    source: str
    max_relative_error: dict


#: half width of the cells around a kink of a contact map's F_N(T), as a fraction of the
#: temperature range: 5x the finite-difference step of the node derivatives (1e-5 of the range,
#: :func:`~sealsim.fmu.tables.smooth_table`), so the nodes beside a kink get its one-sided
#: slopes and the rounded-off kink spans 2e-4 of the range (0.025 K over 125 K)
KINK_CELL = 1e-4


def _with_kinks(axis: np.ndarray, kinks) -> np.ndarray:
    """``axis`` with nodes at each kink and at ± :data:`KINK_CELL` of the range beside it
    (kinks closer than that to the ends are left out)."""
    lo, hi = float(axis[0]), float(axis[-1])
    half = KINK_CELL * (hi - lo)
    extra = [k + s * half for k in kinks if lo + 2 * half < k < hi - 2 * half
             for s in (-1.0, 0.0, 1.0)]
    if not extra:
        return axis
    axis = np.union1d(axis, extra)
    keep = np.concatenate([[True], np.diff(axis) > 0.5 * half])   # no near-duplicate nodes
    return axis[keep]


def _axis(lo: float, hi: float, points: int) -> tuple[np.ndarray, tuple[float, float]]:
    """Node coordinates over [lo, hi]; a single value gets a second node 1 unit above (the
    table is then constant along the axis and the FMU clips to the single value)."""
    if hi > lo:
        return np.linspace(lo, hi, points), (lo, hi)
    return np.array([lo, lo + 1.0]), (lo, lo)


def contact_table(contact_map, temperature_points: int = 13,
                  pressure_points: int = 33) -> ContactTable:
    """The contact table of a seal's contact map (FE, analytic or any ContactMap).

    Parameters
    ----------
    contact_map : ContactMap
        ``evaluate(dp, T) -> (F_N, b)`` and ``ranges`` (see
        :mod:`sealsim.pneumatic.contact_maps`).
    temperature_points, pressure_points : int
        Grid of a map that is not an FE map (an FE map keeps its nodes).
    """
    from sealsim.pneumatic.contact_maps import FEContactMap

    if temperature_points < 2 or pressure_points < 2:
        raise InputError("contact table: temperature_points and pressure_points must be >= 2")
    ranges = contact_map.ranges
    (tlo, thi), (plo, phi) = ranges["temperature"], ranges["pressure"]

    def sample(temperature, pressure):
        fn, b = contact_map.evaluate(np.ravel(pressure), np.ravel(temperature))
        return np.stack([np.reshape(fn, np.shape(pressure)), np.reshape(b, np.shape(pressure))],
                        axis=-1)

    if isinstance(contact_map, FEContactMap):
        coords = contact_map.seal_map.coords
        t_axis, t_range = ((coords["temperature"], (tlo, thi)) if coords["temperature"].size > 1
                           else _axis(tlo, tlo, 2))
        p_axis, p_range = ((coords["pressure"], (plo, phi)) if coords["pressure"].size > 1
                           else _axis(plo, plo, 2))
        grid_t, grid_p = np.meshgrid(t_axis, p_axis, indexing="ij")
        values = sample(np.clip(grid_t, tlo, thi), np.clip(grid_p, plo, phi))
        table = pchip_table(t_axis, p_axis, values)
        source = contact_map.describe()["source"]
    else:
        t_axis, t_range = _axis(tlo, thi, temperature_points)
        if thi > tlo:   # F_N(T) of a held seal peaks at its mounting temperature
            t_axis = _with_kinks(t_axis, getattr(contact_map, "temperature_kinks", ()))
        p_axis, p_range = _axis(plo, phi, pressure_points)
        clip_t, clip_p = t_range, p_range
        table = smooth_table(lambda t, p: sample(np.clip(t, *clip_t), np.clip(p, *clip_p)),
                             t_axis, p_axis)
        describe = getattr(contact_map, "describe", None)
        source = describe()["source"] if describe else type(contact_map).__name__
    error = _table_error(table, sample, t_range, p_range)
    return ContactTable(table, (float(t_range[0]), float(t_range[1])),
                        (float(p_range[0]), float(p_range[1])), source, error)


def _table_error(table, sample, t_range, p_range) -> dict:
    """Largest relative table error at the cell centres (and mid-edges) inside the range."""
    x0, x1 = table.axes
    mid0 = np.clip(np.concatenate([x0, 0.5 * (x0[1:] + x0[:-1])]), *t_range)
    mid1 = np.clip(np.concatenate([x1, 0.5 * (x1[1:] + x1[:-1])]), *p_range)
    a, b = (g.ravel() for g in np.meshgrid(mid0, mid1, indexing="ij"))
    exact = sample(a, b)
    approx = table.evaluate(a, b)
    rel = np.abs(approx - exact) / np.maximum(np.abs(exact), 1e-300)
    return {"F_N": float(rel[:, 0].max()), "b": float(rel[:, 1].max())}


# -- the seal's friction table (Θ law with steady = "contact") ---------------------------------
@dataclass(frozen=True)
class SteadyTable:
    """The steady friction table a Θ law with ``steady = "contact"`` reads in the FMU.

    Attributes
    ----------
    table : SteadyFrictionTable
        The seal's table (:mod:`sealsim.friction.contact_table`).
    sliding_diameter : float
        Diameter of the sliding surface D [m].
    velocity_direction : float
        +1: a positive v slides the counter surface from side A to side B; −1: from B to A.
    """

    table: SteadyFrictionTable
    sliding_diameter: float
    velocity_direction: float = 1.0

    def inputs(self, normal_force, contact_width, pressure_a, pressure_b, temperature,
               pressure_difference=None) -> ContactInputs:
        """The law inputs of the FMU's contact (the table's orientation from the pressures)."""
        side = 1.0 if pressure_a >= pressure_b else -1.0
        return ContactInputs(normal_force=normal_force, contact_width=contact_width,
                             pressure_a=pressure_a, pressure_b=pressure_b,
                             temperature=temperature, contact_table=self.table,
                             sliding_diameter=self.sliding_diameter,
                             pressure_difference=pressure_difference,
                             table_orientation=self.velocity_direction * side)


def steady_table(law: FrictionLaw, contact_map, sliding_diameter: float | None = None,
                 velocity_direction: float = 1.0) -> SteadyTable | None:
    """The :class:`SteadyTable` of a Θ law with ``steady = "contact"`` on its contact map
    (built or read from the cache, :func:`sealsim.pneumatic.case.seal_friction_table`); None
    for other laws.  ``sliding_diameter`` default: the map's
    (:func:`sealsim.pneumatic.friction_tables.sliding_diameter`)."""
    from sealsim.pneumatic.case import seal_friction_table
    from sealsim.pneumatic.friction_tables import sliding_diameter as map_diameter

    if not getattr(law, "contact", False):
        return None
    if contact_map is None:
        raise InputError("friction: the theta law with steady = 'contact' takes its steady "
                         "friction from the seal's own contact: the FMU needs the seal's "
                         "contact map (map = {...} of the seal, [seal] of a friction case or "
                         "[seal_contact] map of an FMU case)")
    table = seal_friction_table(law, contact_map, "map")
    diameter = map_diameter(contact_map) if sliding_diameter is None else sliding_diameter
    return SteadyTable(table, float(diameter), float(velocity_direction))


# -- the model ---------------------------------------------------------------------------------


def c_parameters(law: FrictionLaw) -> tuple[str, dict[str, float], bool]:
    """(law name, parameters for the C code, bristles) of a law; an InputError for a law or a
    parameter the C code does not implement."""
    name = law.name
    if name not in C_LAWS:
        raise InputError(f"friction.law: the {name!r} law has no C implementation in the FMU "
                         f"export; choose one of {', '.join(C_LAWS)}")
    values = {k: getattr(law.params, k) for k in type(law.params).model_fields}
    if name == "theta":
        from sealsim.friction.theta import CONTACT_ONLY_FIELDS, LUMPED_ONLY_FIELDS
        from sealsim.pneumatic.friction_tables import LAW_TABLE_FIELDS

        contact = values.pop("steady") == "contact"
        unused = LUMPED_ONLY_FIELDS if contact else CONTACT_ONLY_FIELDS
        if contact:   # what builds the table (base oil included) is in it; γ(T) is not used
            unused += LAW_TABLE_FIELDS + ("reference_temperature",)
        for field in unused:
            values.pop(field, None)
    known = _LAW_PARAMETERS[name]
    unknown = sorted(k for k, v in values.items()
                     if k not in known and k not in ("law", "parameter_set") and v is not None)
    if unknown:
        raise InputError(f"friction: the {name} law's field(s) {', '.join(unknown)} are not "
                         "implemented in the FMU's C code yet (sealsim/fmu/c/friction_model.c)")
    bristles = name == "theta" and values.get("bristle_stiffness") is not None
    params = {k: float(v) for k, v in values.items() if k in known and v is not None}
    if name == "theta" and not bristles:
        params.pop("bristle_damping", None)
    if name == "theta" and "base_oil_nu40" not in params:
        params.pop("reference_temperature", None)      # gamma without base oil: constant
    return name, params, bristles


def _deflection_scale(name: str, params: dict[str, float], normal_force: float | None,
                      table: ContactTable | None) -> float:
    """Typical bristle deflection z [m], the FMU's ``nominal`` of the state z: the largest
    steady deflection F_s/σ0 of LuGre (Canudas de Wit et al. 1995), max(f_a, f_b)·F_N/σ0 of
    the Θ law with bristles, μ_b·F_N on a contact table (F_N: the constant normal force, else
    the table's largest)."""
    if name == "lugre":
        return params["static_force"] / params["sigma0"]
    if normal_force is None and table is not None:
        normal_force = float(np.max(table.table.values[..., 0]))
    force = max(params.get("f_a", 0.0), params.get("f_b", 0.0),
                params.get("boundary_friction", 0.0)) * (normal_force or 0.0)
    return force / params["bristle_stiffness"] if force > 0 else 1e-5


def friction_spec(law: FrictionLaw, identifier: str, *, table: ContactTable | None = None,
                  normal_force: float | None = None, contact_width: float | None = None,
                  seal_temperature: float | None = None, steady: SteadyTable | None = None,
                  title: str = "", source: str = "") -> ModelSpec:
    """The model of a seal friction FMU.

    Parameters
    ----------
    law : FrictionLaw
        One of :data:`C_LAWS`.
    identifier : str
        FMI model identifier.
    table : ContactTable, optional
        Contact table F_N, b (Δp, T).
    normal_force, contact_width : float, optional
        Constant contact [N], [m] when there is no table (required by the Θ law).
    seal_temperature : float, optional
        Start value of the input T_seal [K]; default the law's ``reference_temperature`` (where
        the Θ law's γ is γ_ref, as sealsim's law without a temperature), else 293.15 K.
    steady : SteadyTable, optional
        The seal's friction table (required by the Θ law with ``steady = "contact"``,
        :func:`steady_table`).
    title, source : str
        Text for the description and documentation (the case it came from).
    """
    name, params, bristles = c_parameters(law)
    viscosity = "base_oil_nu40" in params
    contact = getattr(law, "contact", False)
    if contact and (steady is None or table is None):
        raise InputError("friction: the theta law with steady = 'contact' needs the seal's "
                         "contact map and its friction table (steady_table)")
    if seal_temperature is None:
        seal_temperature = float(getattr(law.params, "reference_temperature", 293.15))
    uses_load = name == "theta"
    if uses_load and table is None and (normal_force is None or contact_width is None):
        raise InputError("the theta law needs the seal's normal force and contact width: give "
                         "a contact map (map = {...}) or normal_force and contact_width (the "
                         "[inputs] of a friction case, the [seal_contact] of an FMU case)")
    stiction = name in _STICTION or (name == "theta" and not bristles)
    has_theta, has_z = name == "theta", name == "lugre" or bristles
    constant = table is None and uses_load
    variables = [
        Variable("time", "TIME", "independent", "simulation time", "s"),
        Variable("v", "V", "input", "sliding velocity of the body relative to the seal",
                 "m/s", 0.0),
        Variable("p_A", "P_A", "input", "gauge pressure on side A of the seal", "Pa", 0.0,
                 lower=_ABOVE_VACUUM),
        Variable("p_B", "P_B", "input", "gauge pressure on side B of the seal", "Pa", 0.0,
                 lower=_ABOVE_VACUUM),
        Variable("T_seal", "T_SEAL", "input", "seal temperature", "K", seal_temperature),
        Variable("F", "F", "output", "friction force, acting against v", "N"),
        Variable("F_breakaway", "F_BREAKAWAY", "output",
                 "largest friction force the contact holds at rest (true sticking)", "N",
                 exposed=stiction),
        Variable("F_N", "F_N", "output", "normal force of the seal", "N",
                 exposed=uses_load or table is not None),
        Variable("b", "B", "output", "contact width of the seal", "m",
                 exposed=uses_load or table is not None),
        Variable("dp", "DP", "output", "pressure difference across the seal, "
                 "dp = x tanh(x/eps), x = p_A - p_B", "Pa", exposed=table is not None),
        Variable("map_clipped", "MAP_CLIPPED", "output",
                 "true while dp or T_seal lies outside the contact table (clipped)",
                 boolean=True, exposed=table is not None),
        Variable("theta", "THETA", "output", "lubrication state Theta (0 dry, 1 full film)",
                 None, 0.0, state=True, exposed=has_theta),
        Variable("z", "Z", "output", "bristle deflection", "m", 0.0, state=True,
                 nominal=_deflection_scale(name, params, normal_force, table) if has_z
                 else None, exposed=has_z),
        Variable("film_speed", "FILM_SPEED", "output",
                 "speed the contact's film has formed for (0: no film)", "m/s", 0.0,
                 state=True, exposed=contact),
    ]
    states = [v.name for v in variables if v.state and v.exposed]
    variables += [Variable(f"der({s})", f"DER_{s.upper()}", "local", f"time derivative of {s}",
                           _DERIVATIVE_UNITS[s], derivative_of=s) for s in STATE_NAMES]
    bounds = _LAW_PARAMETERS[name]
    for pname, (unit, text) in _PARAMETERS.items():
        lower, upper = bounds.get(pname, (None, None))
        variables.append(Variable(pname, pname.upper(), "parameter", text, unit,
                                  params.get(pname, 0.0), lower=lower, upper=upper,
                                  exposed=pname in params))
    variables += [
        Variable("normal_force", "NORMAL_FORCE", "parameter",
                 "normal force F_N of the seal (constant contact)", "N",
                 normal_force if normal_force is not None else 0.0, lower=_GT0,
                 exposed=constant),
        Variable("contact_width", "CONTACT_WIDTH", "parameter",
                 "contact width b of the seal (constant contact)", "m",
                 contact_width if contact_width is not None else 0.0, lower=_GE0,
                 exposed=constant),
        Variable("pressure_rounding", "PRESSURE_ROUNDING", "parameter",
                 "rounding width eps of dp = x tanh(x/eps) (no kink when the pressures "
                 "cross)", "Pa", PRESSURE_ROUNDING, lower=_GT0),
        Variable("sliding_diameter", "SLIDING_DIAMETER", "parameter",
                 "diameter D of the sliding surface (the friction table is per unit "
                 "circumference)", "m", steady.sliding_diameter if contact else 0.0,
                 lower=_GT0, exposed=contact),
        Variable("velocity_direction", "VELOCITY_DIRECTION", "parameter",
                 "+1: a positive v slides the counter surface from side A to side B of the "
                 "seal, -1: from B to A (the friction table's direction)", None,
                 steady.velocity_direction if contact else 1.0, lower=(">=", -1.0),
                 upper=("<=", 1.0), exposed=contact),
    ]
    variables = [v if not (v.derivative_of and v.derivative_of not in states) else
                 _hidden(v) for v in variables]
    defines = {"FRICTION_LAW": _LAW_CODE[name], "THETA_BRISTLES": int(bristles),
               "THETA_VISCOSITY": int(viscosity), "THETA_CONTACT": int(contact),
               "CONTACT_TABLE": int(table is not None)}
    tables = ""
    report = {"law": law.describe(), "c_law": name, "bristles": bristles,
              "gamma_of_temperature": viscosity}
    if table is not None:
        defines.update({"MAP_T_LO": repr(table.temperature_range[0]),
                        "MAP_T_HI": repr(table.temperature_range[1]),
                        "MAP_P_LO": repr(table.pressure_range[0]),
                        "MAP_P_HI": repr(table.pressure_range[1])})
        tables = table.table.c_source("CONTACT_MAP")
        report["contact_table"] = {
            "source": table.source, "temperature_range_K": list(table.temperature_range),
            "pressure_range_Pa": list(table.pressure_range),
            "nodes": [int(a.size) for a in table.table.axes],
            "max_relative_error": table.max_relative_error}
    elif constant:
        report["contact"] = {"normal_force_N": normal_force, "contact_width_m": contact_width}
    if contact:
        row, data = steady.table.node_tables()
        tables += "\n" + "\n".join([
            f"static const long FRIC_ROW[] = {{{', '.join(str(int(n)) for n in row)}}};",
            "static const double FRIC_DATA[] = {" + ", ".join(repr(float(x)) for x in data)
            + "};"])
        report["friction_table"] = {
            "source": steady.table.attrs, "nodes": [int(n) for n in row[:3]],
            "ranges": steady.table.ranges, "sliding_diameter_m": steady.sliding_diameter,
            "velocity_direction": steady.velocity_direction}
    description = (f"sealsim seal friction, {name} law"
                   + (" with bristles" if bristles else "")
                   + (", contact table F_N, b (dp, T)" if table is not None else "")
                   + (", steady friction from the seal's contact" if contact else "")
                   + (f": {title}" if title else ""))
    return ModelSpec(identifier, title or identifier, description, "friction_model.c",
                     variables, defines, tables, report=report | {"source": source})


def _hidden(v: Variable) -> Variable:
    from dataclasses import replace

    return replace(v, exposed=False)


# -- build-time check against sealsim's law --------------------------------------------------------
def _test_signal(table: ContactTable | None):
    """(v, dt, p_A, p_B, T) per step: rest, acceleration, slow and fast sliding, reversal,
    dwell, and pressures and temperatures across the table."""
    v = np.concatenate([np.zeros(3), np.linspace(1e-4, 0.5, 12), np.full(4, 0.5),
                        np.linspace(0.4, -0.3, 10), np.full(3, -2e-3), np.zeros(4),
                        [1e-5, -1e-5, 3e-3]])
    n = v.size
    dt = np.resize([1e-3, 1e-2, 1e-4, 0.1, 2e-3], n)
    if table is not None:
        (tlo, thi), (plo, phi) = table.temperature_range, table.pressure_range
        temperature = tlo + (thi - tlo) * (0.5 + 0.5 * np.sin(np.arange(n) * 0.7))
        pressure_a = plo + (phi - plo) * (0.5 + 0.5 * np.cos(np.arange(n) * 0.45))
    else:               # the temperature varies too: a law that uses it must agree
        temperature = 263.15 + 110.0 * (0.5 + 0.5 * np.sin(np.arange(n) * 0.7))
        pressure_a = np.linspace(0.0, 6e5, n)
    pressure_b = 0.3 * pressure_a[::-1]
    return v, dt, pressure_a, pressure_b, temperature


def friction_check(law: FrictionLaw, spec: ModelSpec, contact_map=None,
                   table: ContactTable | None = None, kinds=("me", "cs"),
                   steady: SteadyTable | None = None):
    """A build check: the compiled FMU against sealsim's law object.

    Returns ``check(folder, token)`` for :func:`sealsim.fmu.builder.build_archive`.  It
    drives the co-simulation interface through a test signal (rest, sliding at 1e-4 ... 0.5
    m/s, reversal, dwell; steps of 0.1 ms ... 0.1 s; pressures and temperatures across the
    table) and compares the states, F and F_breakaway with ``law.step``/``law.force``/
    ``law.breakaway_force`` fed with the FMU's F_N and b; model exchange derivatives with
    ``law.derivatives``.  Tolerance 1e-9 relative (the C code evaluates the same formulas;
    differences are rounding).  The FMU's F_N, b are compared with the contact map itself.
    A Θ law on its contact reads its friction table at the FMU's dp (``steady``).
    """
    from sealsim.fmu.instance import LoadedFMU

    def check(folder: Path, token: str) -> None:
        worst = {"force": 0.0, "states": 0.0, "derivatives": 0.0, "contact": 0.0}
        v, dt, pa, pb, temp = _test_signal(table)
        names_out = ["F"] + [n for n in ("F_breakaway", "F_N", "b", "dp", *STATE_NAMES)
                             if _exposed(spec, n)]
        if "cs" in kinds:
            with LoadedFMU(folder, "cs", "build_check") as fmu:
                fmu.set(v=v[0], p_A=pa[0], p_B=pb[0], T_seal=temp[0])
                fmu.initialize()
                z = law.initial_state(1)
                t = 0.0
                for k in range(v.size):
                    fmu.set(v=v[k], p_A=pa[k], p_B=pb[k], T_seal=temp[k])
                    fmu.do_step(t, dt[k])
                    t += dt[k]
                    out = dict(zip(names_out, fmu.get(*names_out)))
                    inputs = _inputs(out, pa[k], pb[k], temp[k], steady)
                    z = law.step(z, np.array([v[k]]), dt[k], inputs)
                    force = float(law.force(z, np.array([v[k]]), inputs)[0])
                    worst["force"] = max(worst["force"], _rel(out["F"], force))
                    if "F_breakaway" in out:
                        brk = float(law.breakaway_force(z, inputs)[0])
                        worst["force"] = max(worst["force"], _rel(out["F_breakaway"], brk))
                    for i, sname in enumerate(law.state_names):
                        worst["states"] = max(worst["states"], _rel(out[sname], z[i, 0]))
                    z = np.array([[out[s]] for s in law.state_names]).reshape(z.shape)
                    if contact_map is not None:
                        dp = float(fmu.get("dp")[0])
                        fn, b = contact_map.evaluate(np.clip(dp, *table.pressure_range),
                                                     np.clip(temp[k], *table.temperature_range))
                        worst["contact"] = max(worst["contact"], _rel(out["F_N"], float(fn)),
                                               _rel(out["b"], float(b)))
        if "me" in kinds and law.n_states:
            with LoadedFMU(folder, "me", "build_check") as fmu:
                fmu.initialize()
                rng = np.random.default_rng(1)
                for k in range(v.size):
                    fmu.set(v=v[k], p_A=pa[k], p_B=pb[k], T_seal=temp[k])
                    inputs = _inputs(dict(zip(names_out, fmu.get(*names_out))), pa[k], pb[k],
                                     temp[k], steady)
                    z = law.steady_state(np.array([v[(k + 5) % v.size]]), inputs)
                    z = z * (0.5 + rng.random(z.shape))
                    fmu.set_continuous_states(z[:, 0])
                    dz = law.derivatives(z, np.array([v[k]]), inputs)[:, 0]
                    scale = np.abs(z[:, 0]) / 1e-3 + np.abs(dz)
                    for got, want, s in zip(fmu.derivatives(), dz, scale):
                        worst["derivatives"] = max(worst["derivatives"],
                                                   abs(got - want) / max(s, 1e-300))
        spec.report["build_check"] = {"max_relative_difference": worst, "steps": int(v.size)}
        bad = {k: x for k, x in worst.items() if k != "contact" and x > 1e-9}
        if bad:
            raise ModelError(f"the compiled FMU does not reproduce sealsim's {law.name} law "
                             f"(largest relative differences {bad}); the C code in "
                             "sealsim/fmu/c/friction_model.c must follow the Python law")
        if worst["contact"] > max(1e-3, 10 * max(table.max_relative_error.values())
                                  if table is not None else 0.0):
            raise ModelError(f"the FMU's contact table differs from the contact map by "
                             f"{worst['contact']:.3g} (relative)")

    return check


def _exposed(spec: ModelSpec, name: str) -> bool:
    return any(v.name == name and v.exposed for v in spec.variables)


def _inputs(out: dict, pa: float, pb: float, temperature: float,
            steady: SteadyTable | None = None):
    """The law inputs the FMU used at this step (F_N, b and dp from the FMU's own outputs)."""
    if "F_N" in out:
        fn, b = out["F_N"], out["b"]
    else:
        fn = b = None
    if steady is not None:
        return steady.inputs(fn, b, pa, pb, temperature, out["dp"])
    return ContactInputs(normal_force=fn, contact_width=b, pressure_a=pa, pressure_b=pb,
                         temperature=temperature)


def _rel(a: float, b: float) -> float:
    return abs(a - b) / max(abs(b), 1e-12 * max(abs(a), 1.0), 1e-300) if a != b else 0.0

