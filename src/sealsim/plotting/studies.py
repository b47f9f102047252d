"""Figures of parameter studies: response curves and heatmaps over grid factors, histograms
with percentiles and scatter plots for samples, sensitivity indices as a tornado chart.

Every function reads the study's :class:`xarray.Dataset` (see
:mod:`sealsim.studies.results`): outputs carry ``units`` attributes, grid factors are
dimensions, sampled factors are coordinates along ``sample``.  Where a grid study also has a
``sample`` dimension, curves and maps show the median over the samples (curves with the
5-95 % band).
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from sealsim.plotting import new_figure, unit_text

__all__ = ["heatmap_figure", "histogram_figure", "response_figure", "scatter_figure",
           "sensitivity_figure"]

#: most panels of one figure (further combinations are not drawn; the title says so)
MAX_PANELS = 12
#: most curves in one panel
MAX_LINES = 10


def _label(dataset, name: str) -> str:
    units = unit_text(dataset[name].attrs.get("units", ""))
    return f"{name} [{units}]" if units else name


def _value_text(value, dataset=None, name: str = "") -> str:
    if isinstance(value, float | np.floating):
        text = f"{value:.4g}"
    else:
        text = str(value)
    if dataset is not None and name:
        units = unit_text(dataset[name].attrs.get("units", ""))
        if units:
            text += f" {units}"
    return text


def _numeric(dataset, dim: str) -> bool:
    return np.issubdtype(dataset[dim].dtype, np.number)


def _positions(dataset, dim: str):
    """x positions and tick labels of a grid factor (text values at 0, 1, 2, ...)."""
    values = dataset[dim].values
    if _numeric(dataset, dim):
        return values.astype(float), None
    return np.arange(len(values), dtype=float), [str(v) for v in values]


def _panels(combos: list, ncols_max: int = 3):
    n = max(1, min(len(combos), MAX_PANELS))
    ncols = min(n, ncols_max)
    nrows = math.ceil(n / ncols)
    return n, ncols, nrows


def _reduce(da):
    """(median, 5 %, 95 %) over ``sample`` if the array has that dimension."""
    if "sample" not in da.dims:
        return da, None, None
    return (da.median("sample"), da.quantile(0.05, "sample").drop_vars("quantile"),
            da.quantile(0.95, "sample").drop_vars("quantile"))


def response_figure(dataset, output: str, x: str, title: str = ""):
    """Output over the grid factor ``x``: one curve per value of another grid factor, one
    panel per value of a third (further factors: more panels).

    Parameters
    ----------
    dataset : xarray.Dataset
        Study results.
    output : str
        Output variable.
    x : str
        Grid factor on the horizontal axis.
    """
    da = dataset[output]
    others = [d for d in da.dims if d not in (x, "sample") and d in dataset.coords]
    line_dim = others[0] if others else None
    panel_dims = others[1:]
    combos = list(itertools.product(*(range(dataset.sizes[d]) for d in panel_dims))) or [()]
    n, ncols, nrows = _panels(combos)
    fig, axes = new_figure(ncols, nrows, width=4.2 * ncols + 1.0, height=3.4 * nrows,
                           squeeze=False, sharey=True)
    xs, ticks = _positions(dataset, x)
    for k, combo in enumerate(combos[:n]):
        ax = axes.flat[k]
        sel = da.isel(dict(zip(panel_dims, combo)))
        lines = range(dataset.sizes[line_dim]) if line_dim else [None]
        for j in list(lines)[:MAX_LINES]:
            curve = sel if j is None else sel.isel({line_dim: j})
            mid, lo, hi = _reduce(curve)
            label = None if j is None else _value_text(dataset[line_dim].values[j], dataset,
                                                       line_dim)
            line, = ax.plot(xs, mid.transpose(x).values, marker="o", ms=3.5, label=label)
            if lo is not None:
                ax.fill_between(xs, lo.transpose(x).values, hi.transpose(x).values,
                                color=line.get_color(), alpha=0.15, lw=0)
        if ticks is not None:
            ax.set_xticks(xs, ticks, rotation=20)
        ax.set_xlabel(_label(dataset, x))
        ax.grid(alpha=0.3)
        if panel_dims:
            ax.set_title(", ".join(f"{d} = {_value_text(dataset[d].values[i], dataset, d)}"
                                   for d, i in zip(panel_dims, combo)), fontsize=9)
        if line_dim and k == 0:
            ax.legend(title=line_dim, fontsize=8, title_fontsize=8)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    for ax in axes[:, 0]:
        ax.set_ylabel(_label(dataset, output))
    note = " (median, band 5-95 %)" if "sample" in da.dims else ""
    more = f" -- first {n} of {len(combos)} panels" if len(combos) > n else ""
    fig.suptitle((f"{title}\n" if title else "") + f"{output} over {x}{note}{more}")
    return fig


def heatmap_figure(dataset, output: str, x: str, y: str, title: str = ""):
    """Output over two grid factors as a colour map (one panel per value of further grid
    factors), values written in the cells of small maps."""
    da = dataset[output]
    panel_dims = [d for d in da.dims if d not in (x, y, "sample")]
    combos = list(itertools.product(*(range(dataset.sizes[d]) for d in panel_dims))) or [()]
    n, ncols, nrows = _panels(combos)
    fig, axes = new_figure(ncols, nrows, width=4.4 * ncols + 1.2, height=3.6 * nrows,
                           squeeze=False)
    mid_all, _, _ = _reduce(da)
    finite = mid_all.values[np.isfinite(mid_all.values)]
    vmin, vmax = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    image = None
    for k, combo in enumerate(combos[:n]):
        ax = axes.flat[k]
        sel, _, _ = _reduce(da.isel(dict(zip(panel_dims, combo))))
        grid = sel.transpose(y, x).values
        image = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis", vmin=vmin,
                          vmax=vmax)
        ax.set_xticks(range(dataset.sizes[x]),
                      [_value_text(v) for v in dataset[x].values], rotation=20, fontsize=8)
        ax.set_yticks(range(dataset.sizes[y]), [_value_text(v) for v in dataset[y].values],
                      fontsize=8)
        ax.set_xlabel(_label(dataset, x))
        ax.set_ylabel(_label(dataset, y))
        if grid.size <= 64:
            for (i, j), value in np.ndenumerate(grid):
                text = "failed" if not np.isfinite(value) else f"{value:.3g}"
                shade = (value - vmin) / (vmax - vmin) if vmax > vmin and np.isfinite(value) \
                    else 0.0
                ax.text(j, i, text, ha="center", va="center", fontsize=7,
                        color="k" if shade > 0.6 else "w")
        if panel_dims:
            ax.set_title(", ".join(f"{d} = {_value_text(dataset[d].values[i], dataset, d)}"
                                   for d, i in zip(panel_dims, combo)), fontsize=9)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    if image is not None:
        fig.colorbar(image, ax=axes, label=_label(dataset, output), shrink=0.9)
    note = " (median over samples)" if "sample" in da.dims else ""
    more = f" -- first {n} of {len(combos)} panels" if len(combos) > n else ""
    fig.suptitle((f"{title}\n" if title else "") + f"{output}{note}{more}")
    return fig


def histogram_figure(dataset, output: str, stats: dict, title: str = ""):
    """Histogram of an output over the samples with its 5/50/95 % percentiles and mean.

    ``stats`` is :func:`sealsim.studies.analysis.spread` of the output (all samples).  With
    grid factors as well (a mixed design), one outlined histogram per grid point instead
    (the first :data:`MAX_LINES`; their percentiles are in ``distribution.csv``).
    """
    fig, ax = new_figure(1, 1, width=6.0, height=4.0)
    da = dataset[output]
    y = np.asarray(da.values, dtype=float).ravel()
    finite = y[np.isfinite(y)]
    grid = [d for d in da.dims if d != "sample"]
    bins = np.histogram_bin_edges(finite, bins=min(40, max(8, int(np.sqrt(finite.size)) + 1))) \
        if finite.size else 10
    if grid:
        combos = list(itertools.product(*(range(dataset.sizes[d]) for d in grid)))
        for combo in combos[:MAX_LINES]:
            values = da.isel(dict(zip(grid, combo))).values
            label = ", ".join(f"{d} = {_value_text(dataset[d].values[i], dataset, d)}"
                              for d, i in zip(grid, combo))
            ax.hist(values[np.isfinite(values)], bins=bins, histtype="step", lw=1.4,
                    label=label)
    elif finite.size:
        ax.hist(finite, bins=bins, color="C0", alpha=0.75, edgecolor="white")
        for key, style in (("P5", ":"), ("P50", "-"), ("P95", ":")):
            if np.isfinite(stats.get(key, np.nan)):
                ax.axvline(stats[key], color="C3", ls=style, lw=1.2,
                           label=f"{key} = {stats[key]:.4g}")
        if np.isfinite(stats.get("mean", np.nan)):
            ax.axvline(stats["mean"], color="k", lw=0.8, ls="--",
                       label=f"mean = {stats['mean']:.4g}, std = {stats['std']:.3g}")
    failed = int(y.size - finite.size)
    ax.set_xlabel(_label(dataset, output))
    ax.set_ylabel("runs")
    if finite.size:
        ax.legend(fontsize=8, loc="best")
    ax.grid(alpha=0.3)
    ax.set_title((f"{title}\n" if title else "") + f"{output}: {finite.size} runs"
                 + (f", {failed} failed" if failed else ""), fontsize=10)
    return fig


def scatter_figure(dataset, output: str, factors: list[str], title: str = ""):
    """Output against each sampled factor (one panel per factor)."""
    n = len(factors)
    ncols = min(n, 3)
    nrows = math.ceil(n / ncols)
    fig, axes = new_figure(ncols, nrows, width=3.8 * ncols + 0.6, height=3.2 * nrows,
                           squeeze=False, sharey=True)
    y = dataset[output]
    for k, name in enumerate(factors):
        ax = axes.flat[k]
        x = dataset[name]
        xb, yb = np.broadcast_arrays(x.broadcast_like(y).values, y.values)
        ax.plot(xb.ravel(), yb.ravel(), ".", ms=4, alpha=0.6)
        ax.set_xlabel(_label(dataset, name))
        ax.grid(alpha=0.3)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    for ax in axes[:, 0]:
        ax.set_ylabel(_label(dataset, output))
    fig.suptitle((f"{title}\n" if title else "") + f"{output} against the sampled factors")
    return fig


def sensitivity_figure(table, title: str = ""):
    """Tornado chart of Sobol' indices: per output, factors sorted by their total (or, without
    totals, first-order) index; bars S1 and ST with their 95 % confidence intervals.

    ``table`` is :func:`sealsim.studies.analysis.sensitivity_table` (rows of one grid point
    per output are drawn: the first).
    """
    labels = [c for c in table.columns
              if c not in ("output", "factor", "S1", "S1_conf", "ST", "ST_conf", "method")]
    if labels:                                  # a mixed design: the first grid point
        first = table.iloc[0]
        table = table[(table[labels] == first[labels]).all(axis=1)]
        where = ", ".join(f"{c} = {_value_text(first[c])}" for c in labels)
        title = f"{title} ({where})" if title else where
    outputs = list(dict.fromkeys(table["output"]))
    n = len(outputs)
    ncols = min(n, 2)
    nrows = math.ceil(n / ncols)
    factors = list(dict.fromkeys(table["factor"]))
    fig, axes = new_figure(ncols, nrows, width=5.2 * ncols,
                           height=1.0 + 0.45 * len(factors) * nrows + 0.8 * nrows,
                           squeeze=False)
    for k, out in enumerate(outputs):
        ax = axes.flat[k]
        rows = table[table["output"] == out].drop_duplicates("factor")
        has_total = rows["ST"].notna().any()
        key = "ST" if has_total else "S1"
        rows = rows.sort_values(key, ascending=True)
        pos = np.arange(len(rows))
        height = 0.38 if has_total else 0.6
        ax.barh(pos + (height / 2 if has_total else 0.0), rows["S1"], height=height,
                xerr=rows["S1_conf"], color="C0", label="first order S1", capsize=2)
        if has_total:
            ax.barh(pos - height / 2, rows["ST"], height=height, xerr=rows["ST_conf"],
                    color="C1", label="total ST", capsize=2)
        ax.set_yticks(pos, rows["factor"])
        ax.axvline(0.0, color="k", lw=0.6)
        ax.set_xlim(min(-0.05, float(np.nanmin(rows[["S1"]].values)) - 0.05), 1.05)
        ax.set_xlabel("Sobol' index [-]")
        ax.set_title(f"{out}: {rows['method'].iloc[0]}", fontsize=9)
        ax.grid(alpha=0.3, axis="x")
        ax.legend(fontsize=8, loc="lower right")
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    fig.suptitle((f"{title}\n" if title else "") + "sensitivity of the outputs to the factors")
    return fig
