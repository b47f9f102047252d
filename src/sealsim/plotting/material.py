"""Figures of material fits: stress-stretch data vs models per deformation mode, the DMA
master curve with its Prony series, the shift factors with WLF/Arrhenius, dilatometry.

The figures receive arrays and fitted objects' evaluations; they compute nothing physical
beyond evaluating the fitted models on a plotting grid."""

from __future__ import annotations

import numpy as np

from sealsim.plotting import new_figure

__all__ = ["plot_dilatometry", "plot_master_curve", "plot_shift_factors", "plot_stress_mode"]

_MPA = 1e-6


def plot_stress_mode(mode: str, data, models, title: str = ""):
    """Nominal stress vs stretch of one deformation mode: measured points and model curves.

    Parameters
    ----------
    data : list of (label, role, stretch, stress [Pa])
    models : list of (label, fitted, stretch grid, stress [Pa], rel_rmse)
        ``fitted``: whether this mode was used in the model's fit (else a prediction).
    """
    fig, (ax, ax_rel) = new_figure(2, 1, width=11.0, height=4.6)
    for label, role, lam, p in data:
        kind = "" if role == "fit" else " (validation)"
        ax.plot(lam, p * _MPA, "o", ms=4, mfc="none", color="k", label=f"{label}{kind}")
    for k, (label, fitted, lam, p, err) in enumerate(models):
        style = "-" if fitted else "--"
        what = "fitted" if fitted else "predicted"
        ax.plot(lam, p * _MPA, style, color=f"C{k}", lw=1.4,
                label=f"{label}: {what}, RMS rel. error {100 * err:.1f} %")
    pts = [(lam, p) for _, _, lam, p in data]
    for k, (label, fitted, lam_m, p_m, _) in enumerate(models):
        for lam, p in pts:
            ok = p != 0
            rel = np.interp(lam[ok], lam_m, p_m) / p[ok] - 1.0
            ax_rel.plot(lam[ok], 100 * rel, "o-" if fitted else "o--", ms=3, lw=0.8,
                        color=f"C{k}")
    ax.set_xlabel("stretch λ [-]")
    ax.set_ylabel("nominal stress [MPa]")
    ax.legend(loc="best", fontsize=7)
    ax_rel.axhline(0.0, color="k", lw=0.6)
    for y in (-5, 5):
        ax_rel.axhline(y, color="0.6", lw=0.6, ls=":")
    ax_rel.set_xlabel("stretch λ [-]")
    ax_rel.set_ylabel("model / measured − 1 [%]")
    lim = ax_rel.get_ylim()
    ax_rel.set_ylim(max(lim[0], -60), min(lim[1], 60))
    for a in (ax, ax_rel):
        a.grid(alpha=0.3)
    fig.suptitle(f"{title}\n{mode}" if title else mode)
    return fig


def plot_master_curve(f_r, storage, loss, grid, storage_model, loss_model, reference_c,
                      title: str = "", compound_storage=None):
    """Master curve at the reference temperature: E′ and E″ points (shifted with the measured
    shift factors), the Prony series and (``compound_storage`` on ``grid``) the compound
    file's E′, the master-curve sigmoid the seal models use."""
    fig, ax = new_figure(1, 1, width=7.5, height=5.0)
    ax.loglog(f_r, storage * _MPA, "o", ms=3, mfc="none", color="C0", label="E′ measured")
    ax.loglog(f_r, loss * _MPA, "s", ms=3, mfc="none", color="C3", label="E″ measured")
    ax.loglog(grid, storage_model * _MPA, "-", color="C0", label="E′ Prony")
    ax.loglog(grid, loss_model * _MPA, "-", color="C3", label="E″ Prony")
    if compound_storage is not None:
        ax.loglog(grid, np.asarray(compound_storage) * _MPA, "--", color="k", lw=1.0,
                  label="E′ compound file (sigmoid, used by the seal models)")
    ax.set_xlabel(f"reduced frequency f·a_T at {reference_c:g} °C [Hz]")
    ax.set_ylabel("modulus [MPa]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="best", fontsize=8)
    ax.set_title(title or "DMA master curve")
    return fig


def plot_shift_factors(temperature_c, log_a, stderr, grid_c, curves, title: str = ""):
    """Measured log10 a_T (±1 s.e.) and the fitted laws ``curves`` = [(label, log a)]."""
    fig, ax = new_figure(1, 1, width=7.0, height=4.6)
    ax.errorbar(temperature_c, log_a, yerr=stderr, fmt="o", ms=4, color="k", capsize=2,
                label="measured (pairwise shifts)")
    for k, (label, y) in enumerate(curves):
        ax.plot(grid_c, y, "-", color=f"C{k}", label=label)
    ax.set_xlabel("temperature [°C]")
    ax.set_ylabel("log10 a_T [-]")
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(title or "time-temperature shift factors")
    return fig


def plot_dilatometry(temperature_c, strain, grid_c, model, tg_c, title: str = ""):
    """Linear thermal strain vs temperature with the two-line fit and T_g."""
    fig, ax = new_figure(1, 1, width=7.0, height=4.6)
    ax.plot(temperature_c, strain * 1e3, "o", ms=3, mfc="none", color="k", label="measured")
    ax.plot(grid_c, model * 1e3, "-", color="C3", label="glassy / rubbery lines")
    ax.axvline(tg_c, color="0.5", ls=":", label=f"T_g = {tg_c:.1f} °C")
    ax.set_xlabel("temperature [°C]")
    ax.set_ylabel("linear thermal strain [‰]")
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(title or "dilatometry")
    return fig
