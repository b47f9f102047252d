"""Axisymmetric finite-volume conduction: analytic references and conservation."""

import numpy as np
import pytest
import scipy.sparse.linalg as spla
from hypothesis import given, settings
from hypothesis import strategies as st

from sealsim.thermal.conduction import (
    AxisymmetricConduction,
    BackwardEulerStepper,
    Link,
    Solid,
    ThermalNetwork,
    graded_edges,
)
from sealsim.thermal.convection import air_properties, rotating_cylinder_coefficient

STEEL = Solid("steel", 45.0, 7850.0, 460.0)


def _heated_ring_on_shaft(h=30.0, d=0.04, q=10.0, band=0.2e-3, length=0.8):
    r = graded_edges([0, d / 2], [d / 8, 0.2e-3], growth=1.3)
    z = graded_edges([-length, -band / 2, band / 2, length], [0.05, 0.05e-3, 0.05e-3, 0.05],
                     growth=1.2, coarse=0.02)
    model = AxisymmetricConduction(r, z, np.zeros((len(r) - 1, len(z) - 1), int), [STEEL])
    surface = np.nonzero(model.boundary.side == 1)[0]
    net = ThermalNetwork(model, {}, ["ambient"], {"surface": (surface, "ambient")})
    k, f = net.assemble({"surface": h})
    band_cells = model.index[-1, np.abs(model.z_centres) < band / 2]
    widths = np.diff(z)[np.abs(model.z_centres) < band / 2]
    source = np.zeros(net.n)
    source[band_cells] = q * widths / widths.sum()
    temps = spla.spsolve(k.tocsc(), source + f @ np.zeros(1))
    return model, temps, r


def test_heated_ring_matches_fin_solution():
    # Long shaft, ring heat source q, convection h to T∞ = 0: two semi-infinite fins,
    # θ(z) = q/(2√(hPkA))·exp(-m|z|), m = √(hP/(kA)) (Incropera §3.6).  Valid for Bi = hr/k
    # = 0.013 << 1, so the cross-section mean temperature is compared.
    h, d, q, k = 30.0, 0.04, 10.0, 45.0
    model, temps, r = _heated_ring_on_shaft(h, d, q)
    perimeter, area = np.pi * d, np.pi * d**2 / 4
    theta0 = q / (2 * np.sqrt(h * perimeter * k * area))
    m = np.sqrt(h * perimeter / (k * area))
    field = np.zeros(model.shape)
    field[model.index >= 0] = temps[model.index[model.index >= 0]]
    ring_area = np.pi * (r[1:] ** 2 - r[:-1] ** 2)
    mean = ring_area @ field / ring_area.sum()
    for z in (0.0, 0.02, 0.1, 0.2):
        j = int(np.argmin(np.abs(model.z_centres - z)))
        analytic = theta0 * np.exp(-m * abs(model.z_centres[j]))
        # issue requirement 5 %; the discretisation error measured here is < 0.2 %
        assert mean[j] == pytest.approx(analytic, rel=0.05)


def test_graded_edges_hit_breakpoints_exactly():
    # features are located by their breakpoints: they must be edges, bit for bit
    points = [0.0, 0.04, 0.0442, 0.0463, 0.0505]
    edges = graded_edges(points, [1e-3, 5e-6, 2e-4, 2e-4, 2e-4], growth=1.3)
    for p in points:
        assert p in edges
    assert np.all(np.diff(edges) > 0)


@settings(max_examples=30, deadline=None)
@given(power=st.floats(0, 200), dt=st.floats(0.01, 100), steps=st.integers(1, 5))
def test_backward_euler_conserves_energy(power, dt, steps):
    # heat in = heat stored + heat to fixed nodes, exactly (up to round-off), for any step
    r = graded_edges([0, 0.02], [5e-3, 1e-3])
    z = graded_edges([0, 0.05], [5e-3, 5e-3])
    model = AxisymmetricConduction(r, z, np.zeros((len(r) - 1, len(z) - 1), int), [STEEL])
    faces = np.nonzero(model.boundary.side == 1)[0]
    net = ThermalNetwork(model, {"sump": 500.0}, ["ambient"], {"surface": (faces, "sump")})
    stepper = BackwardEulerStepper(net)
    temps = np.full(net.n, 300.0)
    fixed = np.array([290.0])
    source = np.zeros(net.n)
    source[0] = power
    stored0 = net.capacity @ temps
    out = 0.0
    for _ in range(steps):
        temps, heat_out = stepper.step(temps, dt, source, fixed, "k", lambda: net.assemble(
            {"surface": 100.0}, [Link("sump", "ambient", 2.0)]))
        out += heat_out
    generated = power * dt * steps
    stored = net.capacity @ temps - stored0
    assert generated - stored - out == pytest.approx(0.0, abs=1e-8 * (1 + abs(stored)))


def test_rotating_shaft_coefficients_match_reference_notes():
    # Reference notes §7.1 (same Kays & Bjorklund correlation, their numbers): d = 80 mm,
    # 1500 rpm: VG 68 at 80 °C (ν = 14.7 mm²/s, k = 0.127, Pr ≈ 190) h ≈ 2000; air h ≈ 60.
    omega = 1500 * np.pi / 30
    assert rotating_cylinder_coefficient(omega, 0.08, 14.7e-6, 0.127, 190) == pytest.approx(
        2000, rel=0.05)
    nu, _, k, pr = air_properties(300.0)
    assert rotating_cylinder_coefficient(omega, 0.08, nu, k, pr) == pytest.approx(60, rel=0.1)
