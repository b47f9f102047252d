"""Figures for results, one module per topic.

Figures are :class:`matplotlib.figure.Figure` objects created without pyplot (no GUI backend,
nothing to close).  Plotting reads results; it never changes them.
"""

from matplotlib.figure import Figure


def new_figure(ncols: int = 1, nrows: int = 1, width: float = 6.0, height: float = 4.0,
               **kwargs):
    """A pyplot-free figure with a grid of axes (``squeeze=False`` semantics off)."""
    fig = Figure(figsize=(width, height), layout="constrained")
    axes = fig.subplots(nrows, ncols, **kwargs)
    return fig, axes
