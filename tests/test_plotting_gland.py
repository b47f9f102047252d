"""The picture and printout of `sealsim gland check`: what section.png and the terminal show."""

from __future__ import annotations

from pathlib import Path

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_hex
from typer.testing import CliRunner

from sealsim.api import oring_gland
from sealsim.cli import app
from sealsim.plotting.gland import plot_gland_section
from sealsim.structure.gland_case import load_gland_case

EXAMPLES = Path(__file__).parents[1] / "examples" / "gland"
METAL = "#c8ccd2"           # the grooved part's face colour in plotting.gland


@pytest.fixture(scope="module", params=["piston_static", "xring_piston", "face_static",
                                        "rod_extrusion_fails"])
def section(request):
    case = load_gland_case(EXAMPLES / f"{request.param}.toml")
    fig = plot_gland_section(case, oring_gland(case))
    FigureCanvasAgg(fig).draw()
    return fig


def test_the_grooved_part_is_one_outline(section):
    # three rectangles drew their inner edges as lines through the steel, down from the groove
    # walls to the edge of the picture
    ax = section.axes[0]
    metal = [p for p in ax.patches if to_hex(p.get_facecolor()) == METAL]
    assert len(metal) == 1


def test_tolerance_lines_name_their_unit(section):
    labels = [line.get_label() for line in section.axes[0].get_lines()
              if line.get_label().startswith(("groove", "bore", "rod"))]
    assert labels
    assert all(label.endswith(" mm)") for label in labels), labels


def test_extrusion_gap_note_stays_inside_the_section(section):
    # on one line it ran past the right edge of the axes (xring_piston)
    ax = section.axes[0]
    renderer = section.canvas.get_renderer()
    note, = [t for t in ax.texts if t.get_text().startswith("extrusion gap")]
    box, frame = note.get_window_extent(renderer), ax.get_window_extent(renderer)
    assert frame.x0 <= box.x0 and box.x1 <= frame.x1


def test_printed_checks_carry_units_and_where_stretch_min_is_taken(tmp_path):
    # the stack prints the stretch minimum of a warm ring (-0.43 % at 100 degC), the check the
    # ring at assembly (0.99 % at 20 degC): the printout says which
    result = CliRunner().invoke(app, ["gland", "check", str(EXAMPLES / "piston_static.toml"),
                                      "--out", str(tmp_path / "out"), "-q"],
                                env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    lines = {line.split()[1]: line for line in result.output.splitlines()
             if line.startswith(("ok ", "FAIL"))}
    assert "(at assembly)" in lines["stretch_min"]
    assert lines["squeeze_min"].split()[2:] == ["17", "%", ">=", "10", "%"]
    assert lines["extrusion_gap"].split()[2:] == ["0.0741", "mm", "<=", "0.241", "mm"]
    header = (tmp_path / "out" / "checks.csv").read_text().splitlines()[0]
    assert header.startswith("name,value,limit,unit,")
