"""parity.png of `sealsim friction fit` / `sealsim rotary fit`: what its R² is taken over."""

from sealsim.plotting.calibration import plot_parity


def test_parity_title_says_what_its_r2_pools():
    # tudelft_oring.toml: 1 bar fitted (3.99 N -> 4.11 N), 7 bar predicted (8.04 N -> 26.07 N);
    # the title read 'R² = -38.608' with nothing saying it pools a fitted and a held-out point
    fig = plot_parity([("1 bar", "fit", 3.985, 4.110), ("7 bar", "validate", 8.037, 26.068)],
                      title="TU Delft O-ring")
    title = fig.axes[0].get_title()
    assert title.startswith("TU Delft O-ring\nR² = -38.6")
    assert title.endswith("over all 2 points, fitted and not fitted")


def test_parity_title_of_held_out_points_only():
    fig = plot_parity([("a", "validate", 1.0, 1.1), ("b", "validate", 2.0, 1.9),
                       ("c", "validate", 3.0, 3.2)])
    assert fig.axes[0].get_title().endswith("over all 3 points, not fitted")


def test_parity_labels_do_not_print_over_each_other():
    # tudelft_rings.toml: 'O-ring 25.7 5 bar, rerun 1' printed over 'X-ring 25.7 5 bar'
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    points = [("fit", "fit", 4.0, 3.9)] + [
        (f"ring {k} at 5 bar, rerun {k}", "validate", 6.0 + 0.05 * k, 8.0 - 0.05 * k)
        for k in range(8)]
    fig = plot_parity(points)
    FigureCanvasAgg(fig).draw()
    renderer = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(renderer) for t in fig.axes[0].texts]
    assert boxes                                 # the farthest point keeps its label
    assert not [(i, j) for i in range(len(boxes)) for j in range(i)
                if boxes[i].overlaps(boxes[j])]
