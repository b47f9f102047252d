"""contact_friction_<seal>.png of `sealsim pneumatic run`: title, film panel, legends."""

from __future__ import annotations

import numpy as np
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


def test_film_panel_is_at_the_seal_temperature_not_at_a_table_node():
    # The analytic table's temperatures are 9.6 K apart (14.2 and 23.8 degC around 20 degC);
    # the film panel took the films at the nearest node, 23.8 degC, and titled them 20 degC:
    # 11 % thinner than the table's film at 20 degC at 0 bar (1.58 against 1.77 µm).  Now
    # viscosity, modulus and profile are those at 20 degC: the film at each pressure maximum
    # is the table's within 2 % (the table's own interpolation between its nodes).
    tribology = ContactTribology()
    table = build_friction_table(ROD, tribology)
    for dp, z, p, h_pos, h_neg in film_profiles(ROD, tribology, 293.15, 0.1):
        peak = int(np.argmax(p))
        _, _, film = table.evaluate([0.1, -0.1], dp, 293.15)
        assert [h_pos[peak], h_neg[peak]] == pytest.approx(film, rel=0.02), dp
