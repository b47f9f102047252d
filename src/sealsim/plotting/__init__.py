"""Figures for results, one module per topic.

Figures are :class:`matplotlib.figure.Figure` objects created without pyplot (no GUI backend,
nothing to close).  Plotting reads results; it never changes them.
"""

import re

from matplotlib.figure import Figure

from sealsim.units import ZERO_CELSIUS_K


def new_figure(ncols: int = 1, nrows: int = 1, width: float = 6.0, height: float = 4.0,
               **kwargs):
    """A pyplot-free figure with a grid of axes (``squeeze=False`` semantics off)."""
    fig = Figure(figsize=(width, height), layout="constrained")
    axes = fig.subplots(nrows, ncols, **kwargs)
    return fig, axes


def celsius_text(temperature: float) -> str:
    """A temperature [K] as a label in °C, to 4 significant digits; the rounding noise of a
    unit conversion ("32 degF" is 273.15 K + 6e-14 K) does not show as "5.684e-14 °C".

    >>> celsius_text(273.15 + 5.684e-14), celsius_text(310.92777777777775)
    ('0 °C', '37.78 °C')
    """
    return f"{round(temperature - ZERO_CELSIUS_K, 6) + 0.0:.4g} °C"


def unit_text(unit: str) -> str:
    """A unit as engineers write it on an axis or in a printout, from the pint-style string a
    study or case carries: °C, not "degC"; K for a temperature difference; µm, dm³.

    >>> unit_text("degC"), unit_text("delta_degC"), unit_text("um"), unit_text("N m")
    ('°C', 'K', 'µm', 'N m')
    >>> unit_text("dm ** 3 / bar / s"), unit_text("1")
    ('dm³ / bar / s', '')
    """
    if unit in ("", "1", "dimensionless"):
        return ""
    text = re.sub(r"\bdelta_deg[CF]\b", "K", unit)
    text = re.sub(r"\bdegC\b", "°C", text)
    text = re.sub(r"\bdegF\b", "°F", text)
    text = re.sub(r"\bum\b", "µm", text)
    return re.sub(r"\s*\*\*\s*([23])", lambda m: "²" if m.group(1) == "2" else "³", text)
