"""section_*.png of `sealsim structure run`: the contact nodes drawn with the profile."""

from pathlib import Path

import numpy as np

from sealsim.plotting import new_figure
from sealsim.structure.results import SurfaceResult


def test_a_grazing_node_outside_the_contact_width_is_drawn_hollow_and_named():
    from sealsim.plotting.structure import _contact_nodes

    # oring_rod.toml, installed: a node at z = 1.69 mm with 0.16 MPa stood as a filled dot
    # beside the profile line, which ends at the zone edge 1.52 mm (the width b ends there)
    z = np.array([-1.0, 0.0, 1.0, 1.476, 1.693]) * 1e-3
    p = np.array([0.9, 2.1, 1.6, 0.77, 0.16]) * 1e6
    surface = SurfaceResult("sealing_surface", 287.0, 2.6e-3, 2.1e6, 1.4e6, z, p, 0.01,
                            -1.1e-3, 1.52e-3, 1, zone_edges=[(-1.1e-3, 1.52e-3)])
    _, ax = new_figure()
    _contact_nodes(ax, surface, "C0")
    filled, hollow = ax.get_lines()
    assert np.allclose(filled.get_xdata(), [-1.0, 0.0, 1.0, 1.476])
    assert np.allclose(hollow.get_xdata(), [1.693])
    assert hollow.get_markerfacecolor() == "none"
    assert hollow.get_label() == "grazing node, outside b"


def test_nodes_inside_the_zones_draw_no_grazing_entry():
    from sealsim.plotting.structure import _contact_nodes

    z = np.array([0.0, 1.0]) * 1e-3
    surface = SurfaceResult("groove_bottom", 10.0, 1.5e-3, 1e6, 1e6, z, np.array([1e6, 1e6]),
                            0.01, -0.2e-3, 1.2e-3, 1, zone_edges=[(-0.2e-3, 1.2e-3)])
    _, ax = new_figure()
    _contact_nodes(ax, surface, "C1")
    assert len(ax.get_lines()) == 1


def test_section_legend_leaves_the_profiles_free(tmp_path):
    # oring_rod.toml: the legend in the upper left covered the profiles' peak (2.1 MPa at
    # z = 0 ... 0.4 mm installed, 3.1 MPa at 10 bar)
    import tomllib

    import tomli_w
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from plot_checks import covered_points

    from sealsim.cases import apply_overrides
    from sealsim.plotting.structure import plot_section
    from sealsim.structure.case import load_structure_cases
    from sealsim.structure.run import run_case

    example = Path(__file__).parents[1] / "examples" / "structure" / "oring_rod.toml"
    # 5 squeeze increments: with 2 the 12.5 % steps failed Newton and the installation went on
    # at the halved size (96 increments, 396 Newton iterations, 5.0 s of CPU; 5 take 9, 98,
    # 1.5 s); the profiles the legend must leave free move by 0.1 % (F_N 287.3 -> 287.0 N)
    data = apply_overrides(tomllib.loads(example.read_text()), {
        "mesh": {"level": "coarse"},
        "load": {"squeeze": [0.25], "squeeze_increments": 5, "pressure": ["0 bar", "10 bar"]}})
    case_file = tmp_path / "rod.toml"
    case_file.write_text(tomli_w.dumps(data))
    case, = load_structure_cases(case_file).values()
    result = run_case(case)
    for state in (result.states[0], result.states[-1]):
        fig = plot_section(state)
        FigureCanvasAgg(fig).draw()
        profile, = [ax for ax in fig.axes if ax.get_ylabel() == "contact pressure [MPa]"]
        assert covered_points(profile, fig.canvas.get_renderer()) == 0
