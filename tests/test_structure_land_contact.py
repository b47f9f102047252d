"""Groove walls that end at a clearance gap (gland.clearance): the rigid land's distance
function against geometry and finite differences, and the FE with the gap against the FE
without it where the seal stays clear of the gap and where it does not (the TU Delft rig's
X-ring, whose downstream lobe sits on the land's edge)."""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sealsim.cases import validate_case
from sealsim.errors import InputError
from sealsim.structure.build import build_assembly
from sealsim.structure.case import StructureCase
from sealsim.structure.land_contact import land_gap
from sealsim.structure.run import run_case

NORMAL, ALONG, RADIUS = np.array([-1.0, 0.0]), np.array([0.0, 1.0]), 0.1


def boundary_polyline(radius, n_arc=4001, reach=3.0):
    """The land's boundary (wall, rounded edge, top) as a dense polyline, independent of
    land_gap's case distinction: wall x = 0 for y <= -radius, the quarter circle about
    (radius, -radius), top y = 0 for x >= radius (the land is x >= 0, y <= 0)."""
    wall = np.column_stack([np.zeros(2000), np.linspace(-reach, -radius, 2000)])
    phi = np.linspace(np.pi, 0.5 * np.pi, n_arc)
    arc = np.column_stack([radius + radius * np.cos(phi), -radius + radius * np.sin(phi)])
    top = np.column_stack([np.linspace(radius, reach, 2000), np.zeros(2000)])
    return np.vstack([wall, arc, top])


@settings(max_examples=60, deadline=None)
@given(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0))
def test_land_gap_is_the_distance_to_the_rounded_land(x, y):
    """|g| equals the distance to a densely sampled boundary, outside the land and inside it
    up to half the edge radius deep (a penalty contact's penetrations are microns; deeper
    inside g is the depth below the wall or the top, not the distance to the nearest side);
    the sign says inside or outside.  Tolerance 2e-3: the polyline's point spacing (1.5e-3
    along the flats, 4e-5 on the arc)."""
    gap = land_gap([[x, y]], NORMAL, ALONG, RADIUS)[0][0]
    line = boundary_polyline(RADIUS)
    distance = np.min(np.hypot(line[:, 0] - x, line[:, 1] - y))
    in_corner_box = x < RADIUS and y > -RADIUS
    inside = x > 0 and y < 0 and (not in_corner_box
                                  or np.hypot(x - RADIUS, y + RADIUS) < RADIUS)
    if inside and distance > 0.5 * RADIUS:
        return
    assert abs(abs(gap) - distance) < 2e-3
    if distance > 2e-3:
        assert (gap < 0) == inside


def test_land_gap_gradient_and_curvature_against_finite_differences():
    """The normal is ∂g/∂x and the curvature ∂n/∂x (FElupe's contact tangent needs both):
    central differences, step 1e-6, agree to 1e-6 (truncation ~h², round-off ~1e-10/h) at
    points on the wall side, the top side and around the edge, inside and outside."""
    pts = np.array([[-0.3, -0.5], [0.02, -0.4], [0.4, 0.1], [-0.4, 0.05], [-0.05, 0.05],
                    [0.03, -0.03], [-0.2, -0.09], [0.06, 0.2]])
    g, n, curv = land_gap(pts, NORMAL, ALONG, RADIUS)
    h = 1e-6
    for k in range(2):
        step = np.zeros(2)
        step[k] = h
        gp, np_, _ = land_gap(pts + step, NORMAL, ALONG, RADIUS)
        gm, nm, _ = land_gap(pts - step, NORMAL, ALONG, RADIUS)
        np.testing.assert_allclose((gp - gm) / (2 * h), n[:, k], atol=1e-6)
        np.testing.assert_allclose((np_ - nm) / (2 * h), curv[:, :, k], atol=1e-5)
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0)


BASE = {
    "gland": {"arrangement": "piston", "sealing_diameter": "25.7 mm",
              "groove_width": "4.53 mm"},
    "material": {"elastomer": "NBR"},
    "mesh": {"level": "coarse"},
    "load": {"squeeze": [0.10], "pressure_increments": 2},
}
RING = {"cord_diameter": "3.53 mm", "inner_diameter": "18.64 mm"}


def solve(seal, pressures, clearance=None, pressure_increments=2):
    gland = dict(BASE["gland"], **({} if clearance is None else {"clearance": clearance}))
    data = {**BASE, "seal": {**seal, **RING}, "gland": gland,
            "load": {**BASE["load"], "pressure": pressures,
                     "pressure_increments": pressure_increments}}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return run_case(validate_case(StructureCase, data))


def test_clearance_leaves_a_seal_that_stays_clear_of_the_gap_unchanged():
    """The rig's O-ring 18.64 x 3.53 at 4 bar touches the downstream wall only up to 0.4 mm
    below the land's edge (no gap: the wall contact ends at r = 11.95 mm, the edge is at
    12.35 mm), so ending the wall there changes nothing: F_N and b within 0.1 % (the two
    contact items are different code on the same geometry; measured: identical to 1e-6)."""
    plane = solve({"type": "oring"}, ["0 bar", "4 bar"]).states[-1]
    land = solve({"type": "oring"}, ["0 bar", "4 bar"], clearance="0.5 mm").states[-1]
    assert land.F_N == pytest.approx(plane.F_N, rel=1e-3)
    assert land.b == pytest.approx(plane.b, rel=1e-3)


def test_xring_lobe_is_no_longer_held_over_the_gap():
    """The rig's X-ring at 8 bar: with infinite walls 29 % of the downstream wall's contact
    force lies beyond the land's edge (r > 12.35 mm), i.e. over the 0.5 mm gap where the real
    gland has no wall.  With the clearance no wall force is there (the land's edge is the
    limit, up to the edge radius of 0.1 mm), the rubber bulges past the wall plane into the
    gap, and the sealing contact's downstream lobe reaches further out (larger b)."""
    half, land_edge = 0.5 * 4.53e-3, 0.5 * 25.7e-3 - 0.5e-3
    # 8 pressure increments: with 2 the 4 bar steps failed Newton and the 8 bar went on at
    # the halved size (26 and 88 increments, 12.3 s of CPU for both runs; 8 take 20 and 47,
    # 6.4 s); the quantities below move by 0.2 % at most (share beyond the edge 0.2913 ->
    # 0.2907, b 1.8086 -> 1.8088 mm)
    run_plane = solve({"type": "xring"}, ["0 bar", "8 bar"], pressure_increments=8)
    run_land = solve({"type": "xring"}, ["0 bar", "8 bar"], clearance="0.5 mm",
                     pressure_increments=8)
    plane, land = run_plane.states[-1], run_land.states[-1]
    wall = plane.surfaces["wall_downstream"]
    beyond = np.trapezoid(np.where(wall.position > land_edge, wall.pressure, 0), wall.position)
    assert beyond / np.trapezoid(wall.pressure, wall.position) > 0.15
    wall = land.surfaces["wall_downstream"]
    assert wall.position.max() <= land_edge + 1e-9
    assert land.max_penetration < 0.01e-3       # penalty contact: microns at most
    assert land.deformed_points[:, 0].max() > half + 0.1e-3     # bulges into the gap
    assert plane.deformed_points[:, 0].max() < half + 0.01e-3
    assert land.b > plane.b


def test_clearance_must_leave_a_wall():
    data = {**BASE, "seal": {"type": "oring", **RING},
            "gland": {**BASE["gland"], "clearance": "1.8 mm"},
            "load": {**BASE["load"], "pressure": ["0 bar"]}}
    with pytest.raises(InputError, match="gland.clearance"):
        build_assembly(validate_case(StructureCase, data))
    with pytest.raises(InputError, match="land_edge_radius needs gland.clearance"):
        validate_case(StructureCase, {**data, "gland": {**BASE["gland"],
                                                        "land_edge_radius": "0.1 mm"}})


def test_map_profile_covers_the_clearance_gaps():
    """With a clearance the stored contact pressure profile reaches one clearance beyond each
    wall (the rubber in the gap can touch the sealing surface there); without, the groove."""
    from sealsim.structure.mapping import profile_positions

    data = {**BASE, "seal": {"type": "xring", **RING},
            "load": {**BASE["load"], "pressure": ["0 bar"]},
            "map": {"pressure": ["0 bar", "1 bar"], "temperature": ["20 degC", "30 degC"],
                    "profile_points": 51}}
    plain = profile_positions(validate_case(StructureCase, data))
    gap = profile_positions(validate_case(StructureCase, {
        **data, "gland": {**BASE["gland"], "clearance": "0.5 mm"}}))
    assert plain[-1] == pytest.approx(0.5 * 4.53e-3) and plain[0] == pytest.approx(-plain[-1])
    assert gap[-1] == pytest.approx(0.5 * 4.53e-3 + 0.5e-3) and len(gap) == 51
