"""Property charts: oil viscosity vs temperature and elastomer modulus vs temperature.

Pure functions: SI arrays in, a :class:`matplotlib.figure.Figure` out (no pyplot, no files).
Units are converted for display only (°C, mm²/s, MPa); NaN values are gaps in a curve.

* :func:`viscosity_temperature_figure` -- kinematic viscosity of one or more oils, on ASTM D341
  chart axes (log log(ν + 0.7) against log T, where each oil is a straight line) or on a plain
  log-viscosity axis; like Organisciak et al. (2014) Fig. 2.
* :func:`modulus_temperature_figure` -- storage modulus E(T) of one or more elastomers on a
  log axis, glassy → transition → rubbery, T_g marked; like Organisciak et al. (2014) Fig. 3.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.ticker import FixedLocator, FuncFormatter, LogLocator, NullLocator

from sealsim.plotting import new_figure
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["CHARTS", "modulus_temperature_figure", "viscosity_temperature_figure"]

#: Viscosity scales of :func:`viscosity_temperature_figure`.
CHARTS = ("d341", "log")
#: Major ticks of the viscosity axis [mm²/s], as on ASTM D341 chart paper, in order of
#: preference: the 1-2-5 series first, the others where there is room (see _d341_ticks).
_NU_TICKS_PREFERRED = (2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 1e4, 2e4, 5e4, 1e5,
                       1e6)
_NU_TICKS_EXTRA = (3, 4, 6, 8, 15, 30, 40, 75, 150, 300)
_NU_TICKS = tuple(sorted(_NU_TICKS_PREFERRED + _NU_TICKS_EXTRA))


# -- ASTM D341 axes ---------------------------------------------------------------------------

def _d341_forward(nu_mm2_s):
    # log10 log10(nu + 0.7); clipped so that matplotlib's probing of limits never gives NaN.
    nu = np.maximum(np.asarray(nu_mm2_s, dtype=float), 0.35)
    return np.log10(np.log10(nu + 0.7))


def _d341_inverse(y):
    with np.errstate(over="ignore"):
        return 10.0 ** (10.0 ** np.asarray(y, dtype=float)) - 0.7


def _log_kelvin_forward(t_c):
    t = np.maximum(np.asarray(t_c, dtype=float) + ZERO_CELSIUS_K, 1.0)
    return np.log10(t)


def _log_kelvin_inverse(x):
    return 10.0 ** np.asarray(x, dtype=float) - ZERO_CELSIUS_K


def _d341_ticks(lo: float, hi: float, min_gap: float = 0.04) -> list[float]:
    """Ticks in [lo, hi] at least ``min_gap`` (axis fraction) apart on the D341 scale.

    The D341 scale compresses high viscosities, so a fixed tick list crowds at the top.
    """
    y_lo, y_hi = float(_d341_forward(lo)), float(_d341_forward(hi))
    kept: list[float] = []
    for tick in (*_NU_TICKS_PREFERRED, *_NU_TICKS_EXTRA):
        if not lo <= tick <= hi:
            continue
        y = (float(_d341_forward(tick)) - y_lo) / (y_hi - y_lo)
        if all(abs(y - (float(_d341_forward(k)) - y_lo) / (y_hi - y_lo)) >= min_gap
               for k in kept):
            kept.append(tick)
    return sorted(kept)


def _number_label(value, _pos=None) -> str:
    return f"{value:g}"


def _nice_limits(values: np.ndarray, floor: float | None = None) -> tuple[float, float]:
    """Positive axis limits that enclose ``values`` on the tick grid of a viscosity chart."""
    finite = values[np.isfinite(values) & (values > 0)]
    lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (2.0, 1000.0)
    below = [t for t in _NU_TICKS if t <= lo]
    above = [t for t in _NU_TICKS if t >= hi * 1.05]
    lo = below[-1] if below else lo / 1.5
    hi = above[0] if above else hi * 1.5
    if floor is not None:
        lo = max(lo, floor)
    return lo, hi


# -- figures ----------------------------------------------------------------------------------

def viscosity_temperature_figure(
    temperature,
    viscosity: Mapping[str, np.ndarray],
    *,
    chart: str = "d341",
    points: Mapping[str, tuple[np.ndarray, np.ndarray]] | None = None,
    title: str | None = None,
):
    """Kinematic viscosity against temperature for several oils.

    Parameters
    ----------
    temperature : array_like
        Temperatures [K] shared by all curves.
    viscosity : mapping of str to array_like
        Oil name → kinematic viscosity [m²/s] at ``temperature`` (NaN = not drawn).
    chart : {"d341", "log"}
        ``"d341"``: ASTM D341 chart axes (log log(ν + 0.7) vs log T), where a Walther oil is a
        straight line; ``"log"``: log-viscosity vs linear temperature.
    points : mapping of str to (array, array), optional
        Oil name → (temperatures [K], viscosities [m²/s]) drawn as open markers, e.g. the
        datasheet values at 40 and 100 °C.
    title : str, optional
        Figure title; a default names the chart type.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> t = np.linspace(273.15, 423.15, 5)
    >>> fig = viscosity_temperature_figure(t, {"oil": 1e-4 * (273.15 / t) ** 8})
    >>> ax = fig.axes[0]
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('Temperature T [°C]', 'Kinematic viscosity ν [mm²/s]')
    """
    if chart not in CHARTS:
        raise ValueError(f"chart must be one of {CHARTS}, got {chart!r}")
    t_c = np.asarray(temperature, dtype=float) - ZERO_CELSIUS_K
    fig, ax = new_figure(width=7.0, height=5.0)
    colors = [f"C{i}" for i in range(10)]
    all_nu = []
    for i, (name, nu) in enumerate(viscosity.items()):
        nu_mm2 = np.asarray(nu, dtype=float) * 1e6
        all_nu.append(nu_mm2)
        color = colors[i % len(colors)]
        ax.plot(t_c, nu_mm2, color=color, lw=2.0, label=name)
        if points and name in points:
            tp, nup = points[name]
            ax.plot(np.asarray(tp) - ZERO_CELSIUS_K, np.asarray(nup) * 1e6, ls="none", marker="o",
                    ms=6, mfc="white", mec=color, mew=1.5, zorder=3)
    values = np.concatenate(all_nu) if all_nu else np.array([])

    if chart == "d341":
        ax.set_yscale("function", functions=(_d341_forward, _d341_inverse))
        ax.set_xscale("function", functions=(_log_kelvin_forward, _log_kelvin_inverse))
        lo, hi = _nice_limits(values, floor=2.0)
        ax.yaxis.set_major_locator(FixedLocator(_d341_ticks(lo, hi)))
        ax.yaxis.set_major_formatter(FuncFormatter(_number_label))
        ax.yaxis.set_minor_locator(NullLocator())
        ax.set_ylim(lo, hi)
        default_title = "Viscosity–temperature chart (ASTM D341 axes)"
    else:
        ax.set_yscale("log")
        lo, hi = _nice_limits(values)
        ax.yaxis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
        ax.yaxis.set_major_formatter(FuncFormatter(_number_label))
        ax.set_ylim(lo, hi)
        default_title = "Kinematic viscosity vs temperature"
    ax.set_xlim(float(np.nanmin(t_c)), float(np.nanmax(t_c)))
    for ref in (40.0, 100.0):  # the two datasheet temperatures of ISO VG / VI
        if t_c.min() <= ref <= t_c.max():
            ax.axvline(ref, color="0.55", lw=0.8, ls="--", zorder=1)
    ax.grid(True, which="major", color="0.85", lw=0.8)
    ax.set_xlabel("Temperature T [°C]")
    ax.set_ylabel("Kinematic viscosity ν [mm²/s]")
    ax.set_title(title or default_title)
    handles, labels = ax.get_legend_handles_labels()
    if points:
        handles.append(Line2D([], [], ls="none", marker="o", mfc="white", mec="0.2", mew=1.5))
        labels.append("datasheet ν40, ν100")
    ax.legend(handles, labels, loc="upper right", frameon=True, framealpha=0.95)
    return fig


def modulus_temperature_figure(
    temperature,
    modulus: Mapping[str, np.ndarray],
    *,
    glass_transition: Mapping[str, float],
    service_range: Mapping[str, tuple[float, float]] | None = None,
    frequency: float | None = None,
    title: str | None = None,
):
    """Storage modulus E(T) of elastomers on a log axis, with T_g marked.

    Inside a material's service range the curve is solid, outside dashed.  With a single
    material the glassy, transition and rubbery regions are labelled.

    Parameters
    ----------
    temperature : array_like
        Temperatures [K] shared by all curves.
    modulus : mapping of str to array_like
        Material name → Young's (storage) modulus [Pa] at ``temperature`` (NaN = not drawn).
    glass_transition : mapping of str to float
        Material name → T_g [K], marked on its curve.
    service_range : mapping of str to (float, float), optional
        Material name → (T_min, T_max) [K]; without it every curve is solid.
    frequency : float, optional
        Frequency [Hz] of the moduli, shown in the title.
    title : str, optional
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> t = np.linspace(200.0, 400.0, 50)
    >>> e = 3e6 + 2e9 / (1 + np.exp((t - 250.0) / 5.0))
    >>> fig = modulus_temperature_figure(t, {"X": e}, glass_transition={"X": 250.0})
    >>> fig.axes[0].get_yscale(), fig.axes[0].get_ylabel()
    ('log', "Young's modulus E [MPa]")
    """
    t_k = np.asarray(temperature, dtype=float)
    t_c = t_k - ZERO_CELSIUS_K
    fig, ax = new_figure(width=7.0, height=5.0)
    single = len(modulus) == 1
    for i, (name, e) in enumerate(modulus.items()):
        color = f"C{i % 10}"
        e_mpa = np.asarray(e, dtype=float) / 1e6
        if service_range and name in service_range:
            s_lo, s_hi = service_range[name]
            inside = (t_k >= s_lo) & (t_k <= s_hi)
            ax.plot(t_c, np.where(_grow(~inside), e_mpa, np.nan), color=color, lw=1.5, ls="--")
        tg = glass_transition.get(name)
        label = name if single or tg is None else f"{name} ($T_g$ = {_celsius(tg)})"
        if service_range and name in service_range:
            ax.plot(t_c, np.where(inside, e_mpa, np.nan), color=color, lw=2.2, label=label)
        else:
            ax.plot(t_c, e_mpa, color=color, lw=2.2, label=label)
        if tg is not None and np.nanmin(t_k) <= tg <= np.nanmax(t_k):
            ok = np.isfinite(e_mpa)
            e_tg = float(np.exp(np.interp(tg, t_k[ok], np.log(e_mpa[ok]))))
            ax.axvline(tg - ZERO_CELSIUS_K, color=color, lw=0.8, ls=":", zorder=1)
            ax.plot([tg - ZERO_CELSIUS_K], [e_tg], marker="o", ms=7, mfc="white", mec=color,
                    mew=1.8, zorder=3)
            if single:  # several materials: T_g is in the legend, labels would overlap
                ax.annotate(f"$T_g$ = {_celsius(tg)}", (tg - ZERO_CELSIUS_K, e_tg), xytext=(8, 4),
                            textcoords="offset points", color=color, fontsize=10)
        if single:
            _label_regions(ax, t_c, e_mpa)
    ax.set_yscale("log")
    ax.yaxis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
    ax.yaxis.set_major_formatter(FuncFormatter(_number_label))
    ax.grid(True, which="major", color="0.85", lw=0.8)
    ax.set_xlim(float(np.nanmin(t_c)), float(np.nanmax(t_c)))
    ax.set_xlabel("Temperature T [°C]")
    ax.set_ylabel("Young's modulus E [MPa]")
    at = f" at {frequency:g} Hz" if frequency is not None else ""
    ax.set_title(title or f"Storage modulus vs temperature{at}")
    handles, labels = ax.get_legend_handles_labels()
    if service_range:
        handles += [Line2D([], [], color="0.3", lw=2.2), Line2D([], [], color="0.3", lw=1.5,
                                                               ls="--")]
        labels += ["in service range", "outside service range"]
    handles.append(Line2D([], [], ls="none", marker="o", mfc="white", mec="0.3", mew=1.8))
    labels.append("glass transition $T_g$")
    ax.legend(handles, labels, loc="upper right", frameon=True, framealpha=0.95)
    return fig


def _celsius(kelvin: float) -> str:
    return f"{kelvin - ZERO_CELSIUS_K:.0f} °C".replace("-", "\u2212")  # typographic minus


def _grow(mask: np.ndarray) -> np.ndarray:
    """``mask`` widened by one sample each side, so that a dashed part meets the solid one."""
    grown = mask.copy()
    grown[1:] |= mask[:-1]
    grown[:-1] |= mask[1:]
    return grown


def _label_regions(ax, t_c: np.ndarray, e_mpa: np.ndarray) -> None:
    """Write 'glassy', 'transition' and 'rubbery' next to a single E(T) curve."""
    ok = np.isfinite(e_mpa)
    if ok.sum() < 3:
        return
    t, log_e = t_c[ok], np.log10(e_mpa[ok])
    top, bottom = log_e.max(), log_e.min()
    if top - bottom < 1.0:  # no visible transition in the plotted range
        return
    style = {"fontsize": 10, "color": "0.25", "style": "italic"}
    ax.text(t[0] + 0.03 * (t[-1] - t[0]), 10 ** (top - 0.25), "glassy", va="top", **style)
    mid = int(np.argmin(np.abs(log_e - 0.5 * (top + bottom))))
    ax.text(t[mid] + 0.02 * (t[-1] - t[0]), 10 ** (0.5 * (top + bottom)), "transition",
            va="center", ha="left", **style)
    ax.text(t[-1] - 0.03 * (t[-1] - t[0]), 10 ** (log_e[-1] + 0.25), "rubbery", va="bottom",
            ha="right", **style)
