"""Units at the edges: quantities written as strings ("80 mm", "1500 rpm", "55 degC") are
parsed with pint and converted to SI floats; everything inside sealsim works in SI.

SI units used internally: m, s, kg, K, Pa, N, W, J, rad/s for angular speed, m³ for volume,
m²/s for kinematic viscosity, Pa·s for dynamic viscosity.

Angular speed accepts ``rpm``, ``rad/s`` or ``rev/s`` (or ``rps``).  A reciprocal time given
for a rotational speed (``1/min``, ``min^-1``, ``1/s``, ``s^-1``) is revolutions per time, as in
seal and gearbox data sheets (DIN 1301-2: 1/min is the revolutions per minute), and so are
``U/min`` (German catalogues) and ``r/min`` (ISO); pint alone would read ``1/min`` as radians
per minute, 2π too low.  ``Hz`` is refused for angular speed because pint treats 1 Hz as
1 rad/s, whereas engineers mean 1 rev/s.  The other way round, a frequency (cycles per
second) given as an angular frequency (``rad/s``, ``deg/s``) or in ``rpm``/``rev/s`` is
converted with its 2π (:func:`cycles_per_time`): pint alone would read 1 rad/s as 1 Hz and
60 rpm as 6.28 Hz.  A temperature difference (a rise, an uncertainty, WLF's C2) written in
``degC`` or ``degF`` is that difference (:func:`as_difference`): ``"10 degC"`` is 10 K, not
the temperature 283.15 K.

pint is imported on first use (:func:`unit_registry`, or the module attribute ``ureg``), so
modules that only need :data:`ZERO_CELSIUS_K` stay quick to import.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass

import numpy as np

from sealsim.errors import InputError

#: 0 degC in kelvin [K] (the definition of the Celsius scale, SI Brochure, 9th ed., 2.3.1).
ZERO_CELSIUS_K = 273.15
#: The standard atmosphere [Pa] (10th CGPM 1954, Resolution 4): the lowest gauge pressure is
#: −1 atm (vacuum).
STANDARD_ATMOSPHERE_PA = 101325.0


#: A length unit with a plain exponent digit as data sheets write it (``mm2/s``, ``kg/m3``,
#: ``N/mm2``, ``W/(m2 K)``, ``cm3``): pint knows no unit ``mm2``; it is read as ``mm**2``.
_PLAIN_EXPONENT = re.compile(r"(?<![A-Za-z0-9_µ])((?:[kcdmuµ]?m)|in|ft)([23])(?![0-9A-Za-z_])")


def _plain_exponents(text: str) -> str:
    """``mm2/s`` -> ``mm**2/s``: the exponent digit of a length unit (a pint preprocessor).

    >>> _plain_exponents("W/(m2 K)"), _plain_exponents("kg/m3"), _plain_exponents("mmH2O")
    ('W/(m**2 K)', 'kg/m**3', 'mmH2O')
    """
    return _PLAIN_EXPONENT.sub(r"\1**\2", text)


@functools.cache
def unit_registry():
    """The pint ``UnitRegistry`` of sealsim (created on first use; also ``sealsim.units.ureg``).

    Offset units convert to base units automatically (``"55 degC"`` -> 328.15 K); ``rev`` and
    ``rps`` are defined; a length unit's plain exponent digit is read as its power
    (``"46 mm2/s"``, ``"880 kg/m3"``, as data sheets write them).
    """
    import pint

    registry = pint.UnitRegistry(autoconvert_offset_to_baseunit=True,
                                 preprocessors=[_plain_exponents])
    registry.define("rev = revolution")
    registry.define("rps = revolution / second")
    return registry


def __getattr__(name: str):
    if name == "ureg":
        return unit_registry()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


@dataclass(frozen=True)
class Dimension:
    """A physical dimension accepted by a case-file field.

    Parameters
    ----------
    name : str
        Human-readable name used in error messages ("length").
    si_unit : str
        Unit that values are converted to (the SI unit inside sealsim).
    example : str
        An example quantity string shown in error messages.
    display_unit : str
        Unit used when writing a resolved case back to a file.
    """

    name: str
    si_unit: str
    example: str
    display_unit: str | None = None

    @property
    def dimensionality(self):
        return unit_registry().Quantity(1.0, self.si_unit).dimensionality

    @property
    def phrase(self) -> str:
        """The name with its article, as messages write it ("an angular speed")."""
        words = self.name.replace("_", " ")
        return ("an " if words[0] in "aeiou" else "a ") + words

    @property
    def output_unit(self) -> str:
        return self.display_unit or self.si_unit


DIMENSIONS: dict[str, Dimension] = {
    d.name: d
    for d in [
        Dimension("length", "m", "80 mm", display_unit="mm"),
        Dimension("area", "m**2", "20 cm**2"),
        Dimension("volume", "m**3", "0.2 L", display_unit="L"),
        Dimension("time", "s", "30 s"),
        Dimension("mass", "kg", "1.5 kg"),
        Dimension("force", "N", "30 N"),
        Dimension("pressure", "Pa", "6 bar", display_unit="bar"),
        Dimension("temperature", "K", "55 degC", display_unit="degC"),
        Dimension("temperature_difference", "K", "10 K"),
        Dimension("temperature_rate", "K/s", "1 K/min", display_unit="K/min"),
        Dimension("angular_speed", "rad/s", "1500 rpm", display_unit="rpm"),
        Dimension("velocity", "m/s", "0.5 m/s"),
        Dimension("frequency", "Hz", "10 Hz"),
        Dimension("kinematic_viscosity", "m**2/s", "68 mm**2/s"),
        Dimension("dynamic_viscosity", "Pa*s", "12 mPa*s"),
        Dimension("density", "kg/m**3", "880 kg/m**3"),
        Dimension("stiffness", "N/m", "2 N/m"),
        Dimension("force_rate", "N/s", "20 N/s"),
        Dimension("damping", "N*s/m", "0.4 N*s/m"),
        Dimension("force_per_length", "N/m", "0.3 N/mm"),
        Dimension("thermal_conductivity", "W/(m*K)", "45 W/(m*K)"),
        Dimension("specific_heat", "J/(kg*K)", "460 J/(kg*K)"),
        Dimension("heat_transfer_coefficient", "W/(m**2*K)", "12 W/(m**2*K)"),
        Dimension("thermal_expansion", "1/K", "2e-4 1/K"),
        Dimension("power", "W", "50 W"),
        Dimension("energy", "J", "100 J"),
        Dimension("angle", "rad", "30 deg", display_unit="deg"),
        Dimension("dimensionless", "", "0.3"),
        Dimension("inverse_pressure", "1/Pa", "20 1/GPa"),
        Dimension("flow_conductance", "m**3/(s*Pa)", "2 dm**3/(s*bar)",
                  display_unit="dm**3/(s*bar)"),
    ]
}

# stacked or huge exponents (10**10**8, m**99999999), refused before pint evaluates them
_RUNAWAY_POWER = re.compile(
    r"(\*\*|\^)\s*[-+(]*\s*\d[\d.eE+-]*\s*\)?\s*(\*\*|\^)|(\*\*|\^)\s*[-+(]*\s*\d{4,}")
_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?nan|[-+]?inf)\s*(.*)$",
                     re.IGNORECASE)


def parse_quantity(value, dimension: str, field: str | None = None) -> float:
    """Parse a quantity with units and return its magnitude in SI.

    Parameters
    ----------
    value : str or float
        A string "number unit" (e.g. ``"80 mm"``), or a plain number for dimensionless
        fields.  A plain number for a dimensional field is refused: the unit must be explicit.
    dimension : str
        Key of :data:`DIMENSIONS` (e.g. ``"length"``).
    field : str, optional
        Field name that error messages start with.

    Returns
    -------
    float
        Magnitude in the SI unit of the dimension.

    Raises
    ------
    InputError
        Unknown unit, wrong dimension, missing unit, not finite.

    Examples
    --------
    >>> parse_quantity("80 mm", "length")
    0.08
    >>> round(parse_quantity("55 degC", "temperature"), 2)
    328.15
    >>> round(parse_quantity("1500 rpm", "angular_speed"), 3)
    157.08
    """
    dim = DIMENSIONS[dimension]
    prefix = f"{field}: " if field else ""
    if isinstance(value, unit_registry().Quantity):
        try:
            value = f"{float(value.magnitude)!r} {value.units:~}"
        except OverflowError:
            raise InputError(prefix + f"number too large; expected {dim.phrase} such as "
                                      f"{dim.example!r}") from None
    if isinstance(value, bool):
        raise InputError(prefix + f"{value!r} is not a quantity; expected {dim.phrase} "
                         f"such as {dim.example!r}")
    if isinstance(value, (int, float)):
        if dimension != "dimensionless":
            raise InputError(prefix + f"{value!r} has no unit; write it with {dim.phrase} unit, "
                             f"e.g. {dim.example!r}")
        try:
            magnitude = float(value)
        except OverflowError:
            raise InputError(prefix + f"number too large; expected {dim.phrase} such as "
                                      f"{dim.example!r}") from None
    elif isinstance(value, str):
        magnitude = _parse_string(value, dim, field)
    else:
        raise InputError(prefix + f"{value!r} is not a quantity; expected {dim.phrase} "
                         f"such as {dim.example!r}")
    if not math.isfinite(magnitude):
        raise InputError(prefix + f"{value!r} is not a finite number; expected {dim.phrase} "
                         f"such as {dim.example!r}")
    _above_absolute_zero(magnitude, dimension, prefix)
    return magnitude


def _above_absolute_zero(si, dimension: str, prefix: str) -> None:
    """An absolute temperature at or below 0 K ('-300 degC', a typo) is refused: passed on, it
    would be explained by whatever model met it first."""
    if dimension == "temperature" and np.any(np.asarray(si) <= 0.0):
        coldest = float(np.min(si))
        raise InputError(prefix + f"{coldest - ZERO_CELSIUS_K:.6g} degC ({coldest:.6g} K) is at "
                         "or below absolute zero (-273.15 degC)")


def _parse_string(text: str, dim: Dimension, field: str | None) -> float:
    try:
        return _string_to_si(text, dim)
    except InputError as exc:
        if not field:
            raise
        raise InputError(f"{field}: {exc}") from exc.__cause__


# A study validates the same case strings once per run; pint's parser costs ~1 ms per case.
# Errors are not cached (lru_cache does not store exceptions), so each names its field.
@functools.lru_cache(maxsize=4096)
def _string_to_si(text: str, dim: Dimension) -> float:
    import pint

    ureg = unit_registry()
    match = _NUMBER.match(text)
    if not match:
        raise InputError(f"{text!r} is not 'number unit'; expected {dim.phrase} "
                         f"such as {dim.example!r}")
    number, unit = match.group(1), match.group(2).strip()
    if re.match(r",\d", unit):      # "1,5 mm": a decimal comma
        raise InputError(f"{text!r}: write the number with a decimal point "
                         f"({number}.{unit[1:]!s}); expected {dim.phrase} such as "
                         f"{dim.example!r}")
    if _RUNAWAY_POWER.search(unit):  # pint would evaluate e.g. 10**10**8 for minutes
        raise InputError(f"unit {unit!r} in {text!r} has an exponent that is too large")
    if dim.name == "angular_speed" and re.search(r"hz|hertz", unit, re.IGNORECASE):
        raise InputError(f"{text!r} -- Hz is ambiguous for a rotational speed; "
                         "use rpm, rev/s or rad/s")
    try:
        quantity = (rotational_speed(float(number), unit) if dim.name == "angular_speed"
                    else ureg.Quantity(float(number), unit or "dimensionless"))
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError,
            AttributeError, TypeError, ValueError, AssertionError) as exc:
        raise InputError(f"unknown unit {unit!r} in {text!r}; expected {dim.phrase} "
                         f"such as {dim.example!r}") from exc
    except Exception as exc:  # pint's parser raises a variety of types on garbage input
        raise InputError(f"cannot read {text!r} as a quantity; expected {dim.phrase} "
                         f"such as {dim.example!r}") from exc
    if dim.name == "frequency" and quantity.dimensionality == dim.dimensionality:
        quantity = cycles_per_time(quantity)      # rad/s, rpm: with their 2π
    if dim.name == "temperature_difference":
        quantity = as_difference(quantity)        # "10 degC" is 10 K, not 283.15 K
    if quantity.dimensionality != dim.dimensionality:
        got = f"dimension {quantity.dimensionality}" if unit else "no unit"
        hint = (f"; {unit} is the {ureg.Unit(unit)}: write deg{unit} for degrees"
                if dim.name.startswith("temperature") and unit in ("C", "F") else "")
        raise InputError(f"{text!r} has {got}, expected {dim.phrase} "
                         f"(e.g. {dim.example!r}){hint}")
    if dim.name == "angle" and not _has_angle_unit(quantity):
        # pint counts the radian as 1: '90' or '50 %' would pass as radians
        raise InputError(f"{text!r} has {'no unit' if not unit else 'no angle unit'}; "
                         f"expected an angle such as {dim.example!r} (or rad)")
    try:
        return float(quantity.to(dim.si_unit).magnitude)
    except pint.errors.PintError as exc:  # pragma: no cover - guarded by the check above
        raise InputError(f"cannot convert {text!r} to {dim.si_unit}") from exc


#: "revolution" as catalogues write it where pint knows another unit or none: U (DIN 1301
#: "U/min"; pint's U is the enzyme unit) and r (ISO 80000 "r/min")
_REVOLUTION_WORD = re.compile(r"(?<![A-Za-z_])[Ur](?![A-Za-z_])")


def revolutions_per_time(quantity):
    """A rotational speed written as a reciprocal time (``1/min``, ``s^-1``) as revolutions per
    that time; any other quantity (``rpm``, ``rad/s``, ``deg/s``) unchanged.

    pint reads ``1/min`` as radians per minute (the radian is dimensionless), whereas a speed in
    1/min on a data sheet is revolutions per minute (DIN 1301-2).

    Examples
    --------
    >>> q = revolutions_per_time(unit_registry().Quantity(1500, "1/min"))
    >>> round(q.to("rpm").magnitude, 9), round(q.to("rad/s").magnitude, 3)
    (1500.0, 157.08)
    """
    ureg = unit_registry()
    units = quantity.unit_items()
    if units and all(ureg.Quantity(1, name).dimensionality == {"[time]": 1}
                     for name, _ in units):
        return quantity * ureg.revolution
    return quantity


def cycles_per_time(quantity):
    """A frequency written with an angle (``rad/s``, ``deg/s``, ``rpm``, ``rev/s``) as cycles
    per second [Hz]; a reciprocal time (``Hz``, ``1/s``, ``1/min``) unchanged.

    pint counts the radian as 1, so it would read the angular frequency 1 rad/s as 1 Hz and
    60 rpm (2π rad/s) as 6.28 Hz; a frequency is ω/2π (ISO 80000-3, 3-15 and 3-18).

    Examples
    --------
    >>> q = unit_registry().Quantity
    >>> round(float(cycles_per_time(q(1.0, "rad/s")).to("Hz").magnitude), 6)
    0.159155
    >>> [float(cycles_per_time(q(v, u)).to("Hz").magnitude) for v, u in
    ...  [(60.0, "rpm"), (360.0, "deg/s"), (60.0, "1/min"), (2.0, "kHz")]]
    [1.0, 1.0, 1.0, 2000.0]
    """
    if _has_angle_unit(quantity):
        return unit_registry().Quantity(quantity.to("revolution / second").magnitude, "Hz")
    return quantity


def _has_angle_unit(quantity) -> bool:
    """Whether a quantity's unit holds an angle (rad, deg, rev, rpm: radians in its root)."""
    ureg = unit_registry()
    root = ureg.Quantity(1.0, ureg.get_root_units(quantity.units)[1])
    return "radian" in dict(root.unit_items())


def as_difference(quantity):
    """A temperature difference written in a scale with an offset (``degC``, ``degF``) as the
    difference it means: ``"10 degC"`` is 10 K (pint alone reads it as the temperature
    283.15 K), ``"18 degF"`` 10 K; any other quantity unchanged.

    Examples
    --------
    >>> q = unit_registry().Quantity
    >>> [round(float(as_difference(q(v, u)).to("K").magnitude), 9)
    ...  for v, u in [(10.0, "degC"), (18.0, "degF"), (10.0, "K")]]
    [10.0, 10.0, 10.0]
    """
    if quantity._is_multiplicative:
        return quantity
    return unit_registry().Quantity(quantity.magnitude, f"delta_{quantity.units}")


def rotational_speed(magnitude, unit: str):
    """A pint quantity of a rotational speed written in ``unit`` as data sheets write it.

    ``U`` and ``r`` stand for revolutions (``U/min``, ``r/min``) and a reciprocal time
    (``1/min``, ``s^-1``) is revolutions per time (:func:`revolutions_per_time`).

    Examples
    --------
    >>> round(rotational_speed(1500.0, "U/min").to("rpm").magnitude, 9)
    1500.0
    """
    unit = _REVOLUTION_WORD.sub("rev", unit)
    return revolutions_per_time(unit_registry().Quantity(magnitude, unit or "dimensionless"))


def format_quantity(value: float, dimension: str) -> str:
    """Format an SI value as a quantity string that :func:`parse_quantity` reads back.

    Examples
    --------
    >>> format_quantity(0.08, "length")
    '80 mm'
    >>> format_quantity(328.15, "temperature")
    '55 degC'
    """
    dim = DIMENSIONS[dimension]
    if dimension == "dimensionless":
        return f"{value:.12g}"
    magnitude = unit_registry().Quantity(value, dim.si_unit).to(dim.output_unit).magnitude
    unit = dim.output_unit.replace("**", "^")
    return f"{magnitude:.12g} {unit}"


def format_like(value: float, dimension: str, given) -> str:
    """An SI value in the unit a quantity string ``given`` was written in (a range bound in
    the user's unit), else :func:`format_quantity`'s display unit; angular speeds always in
    the display unit (pint reads ``1/min`` as radians).

    Examples
    --------
    >>> format_like(0.0, "pressure", "-0.7 MPa"), format_like(1e-6, "volume", "0 L")
    ('0 MPa', '0.001 L')
    >>> format_like(200.0, "temperature", "-400 degF"), format_like(0.0, "pressure", 5)
    ('-99.67 degF', '0 bar')
    """
    import pint

    match = _NUMBER.match(given) if isinstance(given, str) else None
    unit = match.group(2).strip() if match else ""
    if unit and dimension not in ("angular_speed", "dimensionless"):
        try:
            magnitude = unit_registry().Quantity(value, DIMENSIONS[dimension].si_unit).to(unit)
            return f"{float(magnitude.magnitude):.6g} {unit}"
        except (pint.errors.PintError, AttributeError, TypeError, ValueError, AssertionError):
            pass
    return format_quantity(value, dimension)


def _shown(value) -> str:
    """``repr`` of a value, shortened to 40 characters (an int of 400 digits)."""
    text = (np.array2string(value, threshold=6, separator=", ") if isinstance(value, np.ndarray)
            else repr(value))
    return text if len(text) <= 40 else text[:37] + "..."


def to_si(value, dimension: str, field: str | None = None, *, plain_is_si: bool = True):
    """A quantity, or an array of quantities, as SI magnitudes (the Python API's inputs).

    Parameters
    ----------
    value : str, float, pint.Quantity, or a list/array of these
        ``"1500 rpm"``, a pint quantity (scalar or array, of :func:`unit_registry`), a list
        such as ``["1000 rpm", "2000 rpm"]``, or plain numbers, which are SI values when
        ``plain_is_si``.
    dimension : str
        Key of :data:`DIMENSIONS`.
    field : str, optional
        Argument name that error messages start with.
    plain_is_si : bool
        Accept plain numbers as SI values.  ``False`` where a plain number is ambiguous (a
        rotational speed: rpm or rad/s?); it is then an error that asks for a unit.

    Returns
    -------
    float or numpy.ndarray
        A float for a scalar input, a float array (same shape) for a list or an array.

    Raises
    ------
    InputError
        No unit where one is required, a wrong dimension, an unknown unit, a value that is not
        finite.

    Examples
    --------
    >>> to_si(["1 bar", "6 bar"], "pressure").tolist()
    [100000.0, 600000.0]
    >>> to_si(0.06, "length")
    0.06
    >>> to_si(1500, "angular_speed", "speed", plain_is_si=False)
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: speed: 1500 has no unit; a plain number is ambiguous for an \
angular speed (rpm or rad/s?): write it with its unit, e.g. '1500 rpm'
    """
    dim = DIMENSIONS[dimension]
    prefix = f"{field}: " if field else ""
    quantity_type = unit_registry().Quantity
    if isinstance(value, quantity_type) and np.ndim(value.magnitude) > 0:
        if dimension == "angular_speed":
            if "hertz" in str(value.units):
                raise InputError(prefix + "Hz is ambiguous for a rotational speed; use rpm, "
                                 "rev/s or rad/s")
            value = revolutions_per_time(value)   # 1/min given for a speed: rpm
        if dimension == "frequency" and value.dimensionality == dim.dimensionality:
            value = cycles_per_time(value)        # rad/s, rpm given for a frequency
        if dimension == "temperature_difference":
            value = as_difference(value)          # degC, degF: a difference
        if value.dimensionality != dim.dimensionality:
            raise InputError(prefix + f"unit {value.units:~} has dimension "
                             f"{value.dimensionality}, expected {dim.phrase} (e.g. "
                             f"{dim.example!r})")
        si = np.asarray(value.to(dim.si_unit).magnitude, dtype=float)
    elif isinstance(value, list | tuple | np.ndarray):
        array = np.asarray(value, dtype=object)
        items = array.ravel()
        if any(isinstance(v, list | tuple | np.ndarray) or np.ndim(getattr(v, "magnitude", 0))
               for v in items):
            raise InputError(prefix + "a ragged list (rows of different lengths, or arrays "
                             "inside a list) is not an array of values; give a rectangular "
                             "list or one pint array")
        if (not plain_is_si and dimension != "dimensionless" and items.size
                and all(isinstance(v, int | float | np.number) for v in items)):
            raise InputError(prefix + f"numbers without a unit ({_shown(value)}); write each "
                             f"with its unit, e.g. [{dim.example!r}, ...], or give a pint "
                             f"array: numpy array * sealsim.units.ureg("
                             f"{dim.example.split(' ', 1)[1]!r})")
        return np.array([to_si(v, dimension, field, plain_is_si=plain_is_si)
                         for v in items], dtype=float).reshape(array.shape)
    elif isinstance(value, int | float | np.number) and not isinstance(value, bool | np.bool_):
        if not plain_is_si and dimension != "dimensionless":
            why = (" a plain number is ambiguous for an angular speed (rpm or rad/s?):"
                   if dimension == "angular_speed" else "")
            raise InputError(prefix + f"{_shown(value)} has no unit;{why} write it with its "
                             f"unit, e.g. {dim.example!r}")
        try:
            si = np.asarray(float(value))
        except OverflowError:
            raise InputError(prefix + f"{_shown(value)} is too large; expected {dim.phrase} "
                             f"such as {dim.example!r}") from None
    else:
        return parse_quantity(value, dimension, field)
    if not np.all(np.isfinite(si)):
        raise InputError(prefix + f"{value!r} is not finite; expected {dim.phrase} such as "
                         f"{dim.example!r}")
    _above_absolute_zero(si, dimension, prefix)
    return float(si) if si.ndim == 0 else si
