"""Mesh convergence of every seal family, medium -> fine (issue 12): F_N within 1 %, b within
3 %. Slow (fine meshes): marked ``slow``, deselected by default; run with
``python -m pytest -m slow tests/test_structure_convergence.py``."""

import warnings

import pytest

from sealsim.cases import apply_overrides, validate_case
from sealsim.structure.case import StructureCase
from sealsim.structure.run import run_case

pytestmark = pytest.mark.slow

GLAND = {"sealing_diameter": "20 mm", "groove_width": "5.6 mm"}
CASES = {
    "oring": {"seal": {"type": "oring", "cord_diameter": "4 mm", "inner_diameter": "20 mm"},
              "gland": GLAND},
    "xring": {"seal": {"type": "xring", "cord_diameter": "4 mm", "inner_diameter": "20 mm"},
              "gland": GLAND},
    "rectangular": {"seal": {"type": "rectangular", "width": "3.5 mm", "height": "4 mm",
                             "inner_diameter": "20 mm"}, "gland": GLAND},
    "ucup": {"seal": {"type": "ucup", "lip_diameter": "19.4 mm", "height": "4.4 mm",
                      "width": "5 mm"}, "gland": GLAND},
    "wiper": {"seal": {"type": "wiper", "lip_diameter": "19.5 mm", "height": "3.5 mm",
                       "width": "5 mm"}, "gland": GLAND},
    "radial_lip": {"seal": {"type": "radial_lip", "outer_diameter": "101 mm", "width": "9 mm"},
                   "gland": {"arrangement": "shaft", "sealing_diameter": "80 mm"}},
}


def solve_case(name, level):
    data = apply_overrides(CASES[name], {"mesh": {"level": level}})
    if name == "radial_lip":
        data["load"] = {"squeeze_increments": 8}
    else:
        data["load"] = {"squeeze": [0.10], "squeeze_increments": 4,
                        "pressure": [] if name == "wiper" else ["5 bar"],
                        "pressure_increments": 4}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return run_case(validate_case(StructureCase, data)).states[-1]


@pytest.mark.parametrize("name", list(CASES))
def test_medium_to_fine(name):
    """Reference: the fine mesh (about 1.5 x the element density of medium at the contact).
    Tolerances from the issue: the normal force converges fast (it integrates the pressure),
    the contact width is located from the edge nodes' pressures (p² extrapolation)."""
    medium, fine = solve_case(name, "medium"), solve_case(name, "fine")
    assert medium.F_N == pytest.approx(fine.F_N, rel=0.01)
    assert medium.b == pytest.approx(fine.b, rel=0.03)
