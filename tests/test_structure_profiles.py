"""Seal contours, profile families, DXF input, profile meshes and profile case files (no FE
solve: each test runs in well under a second or two)."""

import math
from pathlib import Path

import numpy as np
import pytest

from sealsim.cases import validate_case
from sealsim.errors import InputError
from sealsim.structure.case import StructureCase, load_structure_cases
from sealsim.structure.contour import (
    Contour,
    check_contour,
    contour_from_dxf,
    contour_from_polyline,
)
from sealsim.structure.geometry import Gland, SealAssembly
from sealsim.structure.profile_mesh import gmsh_status, mesh_profile
from sealsim.structure.profiles import (
    radial_lip_profile,
    rectangular_profile,
    ucup_profile,
    wiper_profile,
    xring_profile,
)

MM = 1e-3
FAMILIES = {
    "xring": lambda: xring_profile(3.53 * MM, 18.64 * MM),
    "rectangular": lambda: rectangular_profile(3 * MM, 4 * MM, 20 * MM),
    "ucup_rod": lambda: ucup_profile("rod", 19.6 * MM, 4.4 * MM, 5 * MM),
    "ucup_piston": lambda: ucup_profile("piston", 32.4 * MM, 4.4 * MM, 5 * MM),
    "wiper": lambda: wiper_profile("rod", 19.5 * MM, 3.5 * MM, 5 * MM),
    "radial_lip": lambda: radial_lip_profile(80 * MM, 100 * MM, 10 * MM),
}
BACKENDS = ["builtin", pytest.param("gmsh", marks=pytest.mark.skipif(
    not gmsh_status()[0], reason=f"gmsh does not load here: {gmsh_status()[1]}"))]


def test_circle_of_two_arcs_has_the_circle_area():
    # reference: pi r^2; the arcs enter through their bulge tan(90°/4 * 2) = 1 (half circles)
    c = Contour(np.array([[1.0, 5.0], [-1.0, 5.0]]), np.array([1.0, 1.0]))
    assert c.area == pytest.approx(math.pi, rel=1e-12)
    assert c.bounds == pytest.approx((-1.0, 1.0, 4.0, 6.0), abs=1e-2)  # sampled every 6°


def test_contour_errors_name_the_problem():
    with pytest.raises(InputError, match="crosses itself"):
        check_contour(Contour(np.array([[0, 1], [1, 2], [1, 1], [0, 2]]) * MM), "seal.points")
    with pytest.raises(InputError, match="zero length"):
        contour_from_polyline([[0, 1e-3], [1e-3, 1e-3], [1e-3, 1e-3], [0, 2e-3]])
    with pytest.raises(InputError, match="reaches the axis"):
        contour_from_polyline([[0, -1e-3], [1e-3, -1e-3], [1e-3, 1e-3], [0, 1e-3]])
    with pytest.raises(InputError, match="at least 3 points"):
        contour_from_polyline([[0, 1e-3], [1e-3, 1e-3]])
    with pytest.raises(InputError, match="bulges"):
        contour_from_polyline([[0, 1e-3], [1e-3, 1e-3], [0, 2e-3]], bulges=[0.0])


def test_clockwise_polyline_is_turned_counter_clockwise():
    c = contour_from_polyline([[0, 10e-3], [0, 12e-3], [3e-3, 12e-3], [3e-3, 10e-3]])
    assert c.area == pytest.approx(6e-6, rel=1e-12)


def _write_dxf(path, build):
    import ezdxf

    doc = ezdxf.new(units=4)      # drawn in millimetres, and the header says so
    build(doc.modelspace())
    doc.saveas(path)
    return path


def test_dxf_polyline_with_bulge_and_chain_of_lines_and_arcs(tmp_path):
    # a 3 x 2 mm rectangle with a half circle on top (r = 1.5 mm): 6 + pi 1.5^2 / 2 mm²
    expected = (6.0 + math.pi * 1.5**2 / 2) * MM**2
    poly = _write_dxf(tmp_path / "p.dxf", lambda msp: msp.add_lwpolyline(
        [(0, 10, 0, 0, 0), (3, 10, 0, 0, 0), (3, 12, 0, 0, 1.0), (0, 12, 0, 0, 0)],
        format="xyseb", close=True))
    assert contour_from_dxf(poly).area == pytest.approx(expected, rel=1e-9)

    def chain(msp):
        msp.add_line((0, 10), (3, 10))
        msp.add_line((0, 12), (0, 10))  # reversed piece
        msp.add_line((3, 10), (3, 12))
        msp.add_arc((1.5, 12), 1.5, 0, 180)
    c = contour_from_dxf(_write_dxf(tmp_path / "c.dxf", chain))
    assert c.area == pytest.approx(expected, rel=1e-9)


def test_a_drawing_in_inches_is_not_read_as_millimetres(tmp_path):
    # The D-ring of examples/structure/user_profile.toml drawn in inches, the header saying so
    # ($INSUNITS = 1): it was read as millimetres (a 0.12 x 0.12 mm ring, refused only later
    # as 'stretched by 2440 %'); now the case must say which unit its numbers are in.
    import ezdxf

    doc = ezdxf.new(units=1)
    points = [(1.5, 13.0, 0.0), (-1.5, 13.0, 0.0), (-1.5, 11.5, 1.0), (1.5, 11.5, 0.0)]
    doc.modelspace().add_lwpolyline([(z / 25.4, r / 25.4, 0, 0, b) for z, r, b in points],
                                    format="xyseb", close=True)
    doc.saveas(tmp_path / "dring.dxf")
    examples = Path(__file__).resolve().parents[1] / "examples" / "structure"
    text = (examples / "user_profile.toml").read_text()
    text = text.replace('points_unit = "mm"\n', "").replace(
        'bulges = [0.0, 0.0, 1.0, 0.0]', "").replace(
        "points = [[1.5, 13.0], [-1.5, 13.0], [-1.5, 11.5], [1.5, 11.5]]", 'dxf = "dring.dxf"')
    (tmp_path / "case.toml").write_text(text)
    with pytest.raises(InputError, match=r"declares its unit as 'in' \(\$INSUNITS\); give "
                                         r"seal.dxf_unit = 'in'"):
        load_structure_cases(tmp_path / "case.toml")
    (tmp_path / "case.toml").write_text(text.replace('dxf = "dring.dxf"',
                                                     'dxf = "dring.dxf"\ndxf_unit = "in"'))
    seal = load_structure_cases(tmp_path / "case.toml")["base"].seal
    assert seal.points[0] == pytest.approx((1.5, 13.0), rel=1e-9)    # in points_unit mm


def test_dxf_errors(tmp_path):
    def open_chain(msp):
        msp.add_line((0, 10), (3, 10))
        msp.add_line((3, 10), (3, 12))
        msp.add_line((3, 12), (0, 12))
    with pytest.raises(InputError, match="contour is open"):
        contour_from_dxf(_write_dxf(tmp_path / "o.dxf", open_chain))
    with pytest.raises(InputError, match="2 polylines"):
        contour_from_dxf(_write_dxf(tmp_path / "two.dxf", lambda m: [
            m.add_lwpolyline([(0, 10), (1, 10), (1, 11)], close=True),
            m.add_lwpolyline([(2, 10), (3, 10), (3, 11)], close=True)]))
    with pytest.raises(InputError, match="does not exist"):
        contour_from_dxf(tmp_path / "missing.dxf")
    bad = tmp_path / "bad.dxf"
    bad.write_text("not a drawing")
    with pytest.raises(InputError, match="not a readable DXF"):
        contour_from_dxf(bad)


def test_xring_geometry():
    x = xring_profile(3.53 * MM, 18.64 * MM)
    # square envelope like the O-ring of the same cord (ISO 3601 / AS568 sizes)
    assert x.radial_extent == pytest.approx(3.53 * MM, rel=1e-9)
    assert x.axial_extent == pytest.approx(3.53 * MM, rel=1e-9)
    assert math.pi / 4 < x.area / (3.53 * MM) ** 2 < 1.0
    # two lobes per side: the radius along the inner side has two minima with a valley
    s, _ = x.contour.sample(0.01 * MM)
    inner = s[s[:, 1] < x.inner_radius + 0.3 * MM]
    order = np.argsort(inner[:, 0])
    y = inner[order, 1]
    minima = np.nonzero((y[1:-1] < y[:-2]) & (y[1:-1] <= y[2:]))[0]
    assert len(minima) == 2
    with pytest.raises(InputError, match="lobe_radius"):
        xring_profile(3.53 * MM, 18.64 * MM, lobe_radius=0.5)


def test_family_geometry():
    rod = FAMILIES["ucup_rod"]()
    piston = FAMILIES["ucup_piston"]()
    # the dynamic lip is on the sealing side: the rod seal's lip at its inside, the piston's
    # at its outside (the edge radius rounds the lip edge by a few hundredths of a mm)
    assert rod.inner_radius == pytest.approx(9.8 * MM, abs=0.03 * MM)
    assert piston.outer_radius == pytest.approx(16.2 * MM, abs=0.03 * MM)
    assert rod.area == pytest.approx(piston.area, rel=1e-9)  # the mirror image
    lip = FAMILIES["radial_lip"]()
    assert lip.has_bonded_edges and "spring" in lip.contour.tags
    assert lip.spring_radius > lip.inner_radius
    with pytest.raises(InputError, match="radial section"):
        radial_lip_profile(80 * MM, 81 * MM, 10 * MM)
    with pytest.raises(InputError, match="arrangement"):
        ucup_profile("shaft", 19.6 * MM, 4.4 * MM, 5 * MM)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("family", list(FAMILIES))
def test_profile_meshes_are_valid_and_conform_to_the_contour(family, backend):
    profile = FAMILIES[family]()
    mesh = mesh_profile(profile, "coarse", backend=backend)
    p = mesh.points[mesh.cells]
    area = 0.5 * np.sum(p[..., 0] * np.roll(p[..., 1], -1, axis=1)
                        - np.roll(p[..., 0], -1, axis=1) * p[..., 1], axis=1)
    assert np.all(area > 0)
    # reference: the contour's own area (arcs exact); the mesh's chords miss at most the arc
    # segments between boundary nodes, < 0.5 % at the coarse level
    assert area.sum() == pytest.approx(profile.area, rel=5e-3)
    # the boundary loop is closed, counter-clockwise and every boundary node is on the contour
    b = mesh.points[mesh.boundary]
    assert 0.5 * np.sum(b[:, 0] * np.roll(b[:, 1], -1) - np.roll(b[:, 0], -1) * b[:, 1]) > 0
    s, _ = profile.contour.sample(0.002 * profile.radial_extent)
    d = np.min(np.linalg.norm(b[:, None, :] - s[None, :, :], axis=2), axis=1)
    assert d.max() < 0.01 * profile.radial_extent
    if family == "radial_lip":
        assert len(mesh.node_sets["bonded"]) > 4 and len(mesh.node_sets["spring"]) > 2


def test_mesh_levels_refine():
    profile = FAMILIES["xring"]()
    n = [mesh_profile(profile, level, backend="builtin").npoints
         for level in ("coarse", "medium")]
    assert n[1] > 1.5 * n[0]
    with pytest.raises(InputError, match="mesh.backend"):
        mesh_profile(profile, "coarse", backend="xyz")


def test_assembly_checks_for_profiles():
    lip = FAMILIES["radial_lip"]()
    a = SealAssembly(lip, Gland("shaft", 80 * MM, 10 * MM))
    assert 0 < a.shaft_squeeze < 0.2
    with pytest.raises(InputError, match="no contact candidate"):
        SealAssembly(lip, Gland("shaft", 76 * MM, 10 * MM))
    with pytest.raises(InputError, match="bonded"):
        SealAssembly(lip, Gland("rod", 80 * MM, 10 * MM))
    with pytest.raises(InputError, match="metal case"):
        SealAssembly(FAMILIES["xring"](), Gland("shaft", 18.64 * MM, 5 * MM))


BASE = {"gland": {"sealing_diameter": "20 mm", "groove_width": "5.4 mm"},
        "load": {"squeeze": [0.1]}}


@pytest.mark.parametrize("seal, gland, message", [
    ({"type": "xring", "cord_diameter": "4 mm"}, {}, "needs inner_diameter"),
    ({"type": "oring", "cord_diameter": "4 mm", "inner_diameter": "20 mm", "height": "3 mm"},
     {}, "height do"),
    ({"type": "user"}, {}, "either points"),
    ({"type": "radial_lip", "outer_diameter": "30 mm", "width": "7 mm"}, {},
     "needs gland.arrangement = 'shaft'"),
    ({"type": "oring", "cord_diameter": "4 mm", "inner_diameter": "20 mm"},
     {"arrangement": "shaft"}, "radial lip seals"),
    ({"type": "user", "points": [[0, 10], [3, 10], [3, 13]], "points_unit": "parsec/s"}, {},
     "not a length unit"),
])
def test_profile_case_errors(seal, gland, message):
    data = {**BASE, "seal": seal, "gland": {**BASE["gland"], **gland}}
    with pytest.raises(InputError, match=message):
        validate_case(StructureCase, data)


def test_walls_and_pressure_and_custom_material():
    seal = {"type": "rectangular", "width": "3 mm", "height": "4 mm", "inner_diameter": "20 mm"}
    with pytest.raises(InputError, match="needs the groove walls"):
        validate_case(StructureCase, {**BASE, "seal": seal,
                                      "gland": {**BASE["gland"], "walls": False},
                                      "load": {"squeeze": [0.1], "pressure": ["1 bar"]}})
    case = validate_case(StructureCase, {**BASE, "seal": seal, "material": {
        "c10": "0.7 MPa", "c01": "0.1 MPa", "bulk_modulus": "2 GPa"}})
    assert case.material.custom and case.material.elastomer is None
    case = validate_case(StructureCase, {**BASE, "seal": seal})
    assert case.material.elastomer == "NBR" and not case.material.custom
    with pytest.raises(InputError, match="custom material"):
        validate_case(StructureCase, {**BASE, "seal": seal, "material": {
            "c10": "0.7 MPa", "c01": "0.1 MPa", "bulk_modulus": "2 GPa",
            "model": "viscoelastic"}})


def test_dxf_case_file_holds_the_geometry_after_loading(tmp_path):
    _write_dxf(tmp_path / "ring.dxf", lambda msp: msp.add_lwpolyline(
        [(-1.5, 10), (1.5, 10), (1.5, 13), (-1.5, 13)], close=True))
    case_file = tmp_path / "case.toml"
    case_file.write_text('[seal]\ntype = "user"\ndxf = "ring.dxf"\n'
                         '[gland]\nsealing_diameter = "20 mm"\ngroove_width = "4 mm"\n'
                         '[load]\nsqueeze = [0.1]\n')
    case = load_structure_cases(case_file)["base"]
    assert case.seal.dxf is None and case.seal.drawing == "ring.dxf"
    assert np.array(case.seal.points).tolist() == [[-1.5, 10.0], [1.5, 10.0], [1.5, 13.0],
                                                   [-1.5, 13.0]]
