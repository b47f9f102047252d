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
