"""Checks of drawn figures shared by the plotting tests."""

from __future__ import annotations

import numpy as np


def covered_points(ax, renderer) -> int:
    """How many drawn data points of the axes' lines lie under its legend (display space)."""
    box = ax.get_legend().get_window_extent(renderer)
    count = 0
    for line in ax.get_lines():
        xy = line.get_xydata()
        xy = xy[np.all(np.isfinite(xy), axis=1)]
        if len(xy):
            x, y = ax.transData.transform(xy).T
            count += int(np.sum((box.x0 <= x) & (x <= box.x1) & (box.y0 <= y) & (y <= box.y1)))
    return count
