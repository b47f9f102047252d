"""contact_friction_<seal>.png of `sealsim pneumatic run`: title, film panel, legends."""

from __future__ import annotations

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from plot_checks import covered_points

from sealsim.pneumatic.contact_maps import AnalyticContactMap
from sealsim.pneumatic.friction_tables import (
    ContactTribology,
    build_friction_table,
    film_profiles,
)
from sealsim.plotting.contact_friction import contact_friction_figure

ROD = AnalyticContactMap(0.012, 2e-3, 0.12, 8e6, 1.9e-4, 293.15)   # 2 mm O-ring, 12 mm rod


@pytest.fixture(scope="module")
def figure():
    tribology = ContactTribology()
    fig = contact_friction_figure(film_profiles(ROD, tribology, 293.15, 0.1),
                                  build_friction_table(ROD, tribology), 0.012, 293.15, 0.2,
                                  0.1, "rod")
    FigureCanvasAgg(fig).draw()
    return fig


def test_title_gives_the_temperature_as_engineers_write_it(figure):
    assert figure.get_suptitle() == "seal 'rod': friction from its contact at 20 °C"


def test_film_legend_does_not_cover_the_films(figure):
    # one entry per pressure and stroke (18 here) made a legend that hid the films' inlets
    film = figure.axes[1]
    assert len(film.get_legend().get_texts()) <= 3
    assert covered_points(film, figure.canvas.get_renderer()) == 0


def test_film_axis_reads_in_plain_micrometres(figure):
    labels = [t.get_text() for t in figure.axes[1].yaxis.get_ticklabels(which="both")
              if t.get_text()]
    assert labels
    assert not [t for t in labels if "times" in t or "^" in t], labels
