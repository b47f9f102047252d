"""Unit tests of the structural seal model's building blocks (no FE solves)."""

import numpy as np
import pytest
from scipy.sparse.linalg import spsolve

from sealsim.cases import validate_case
from sealsim.errors import InputError
from sealsim.structure.analytic import (
    cylinder_between_flats_approach,
    cylinder_between_flats_force,
    hertz_line_contact,
)
from sealsim.structure.case import StructureCase
from sealsim.structure.geometry import Gland, ORing, SealAssembly, gland_fill
from sealsim.structure.loads import segment_moments, wetted_fractions
from sealsim.structure.maps import HermiteGrid
from sealsim.structure.material import (
    HAVE_COMPILED_TANGENT,
    MooneyRivlinIsochoric,
    ViscoelasticMooneyRivlin,
    _mr_stress,
    _mr_tangent,
    material_from_elastomer,
    mr_stress,
    mr_tangent,
    thermal_volume_ratio,
)
from sealsim.structure.mesh import MESH_LEVELS, mesh_oring
from sealsim.structure.results import contact_width

RNG = np.random.default_rng(7)


def _energy(F, c10, c01):
    C = np.einsum("ki...,kj...->ij...", F, F)
    i1 = np.einsum("ii...", C)
    i2 = 0.5 * (i1**2 - np.einsum("ij...,ji...", C, C))
    J = np.linalg.det(np.moveaxis(F, (0, 1), (-2, -1)))
    return c10 * (J ** (-2 / 3) * i1 - 3) + c01 * (J ** (-4 / 3) * i2 - 3)


def test_mooney_rivlin_stress_and_tangent_match_finite_differences():
    # independent reference: central differences of the strain energy W(F) and of P(F);
    # step 1e-6 on O(1) entries -> truncation ~1e-12, round-off ~1e-10: tolerance 1e-7
    F = np.eye(3)[..., None, None] + 0.2 * RNG.standard_normal((3, 3, 2, 3))
    c10, c01 = 0.8, 0.3
    P, A = _mr_stress(F, c10, c01), _mr_tangent(F, c10, c01)
    h = 1e-6
    for k in range(3):
        for L in range(3):
            dF = np.zeros_like(F)
            dF[k, L] = h
            dW = (_energy(F + dF, c10, c01) - _energy(F - dF, c10, c01)) / (2 * h)
            dP = (_mr_stress(F + dF, c10, c01) - _mr_stress(F - dF, c10, c01)) / (2 * h)
            assert np.allclose(P[k, L], dW, atol=1e-7)
            assert np.allclose(A[:, :, k, L], dP, atol=1e-7)


def test_mooney_rivlin_small_strain_shear_modulus():
    # linearisation: simple shear gamma -> P_12 = G gamma with G = 2 (C10 + C01) (to O(gamma^3))
    g = 1e-5
    F = np.eye(3).copy()
    F[0, 1] = g
    P = _mr_stress(F[..., None, None], 0.8e6, 0.2e6)
    assert P[0, 1, 0, 0] == pytest.approx(2 * (0.8e6 + 0.2e6) * g, rel=1e-6)


@pytest.mark.parametrize("compiled", [False, HAVE_COMPILED_TANGENT])
def test_viscoelastic_tangent_and_limits(compiled):
    # consistent tangent (finite differences, tolerance as above), einsum and compiled kernels
    F = np.eye(3)[..., None, None] + 0.1 * RNG.standard_normal((3, 3, 1, 2))
    u = ViscoelasticMooneyRivlin(0.5, 0.1, [3.0, 10.0], compiled=compiled)
    u.xi = np.array([0.2, 2.0])
    u.theta = 0.9
    sv = RNG.standard_normal((27, 1, 2))
    A = u.hessian([F, sv])[0]
    h = 1e-6
    for k in range(3):
        for L in range(3):
            dF = np.zeros_like(F)
            dF[k, L] = h
            dP = (u.gradient([F + dF, sv])[0] - u.gradient([F - dF, sv])[0]) / (2 * h)
            assert np.allclose(A[:, :, k, L], dP, atol=1e-7)
    # glassy limit (xi = 0, no history): stiffness scaled by theta + sum(beta) (exact)
    zero = np.zeros((27, 1, 1))
    Fs = np.eye(3).copy()
    Fs[0, 1] = 1e-6
    u.xi = np.zeros(2)
    u.theta = 1.0
    P = u.gradient([Fs[..., None, None], zero])[0]
    assert P[0, 1, 0, 0] == pytest.approx(14.0 * 2 * 0.6 * 1e-6, rel=1e-5)


def test_thermal_volume_ratio():
    # (1 + alpha dT)^3 by hand: alpha 2e-4, dT 100 K -> 1.02^3
    assert thermal_volume_ratio(393.15, 293.15, 2e-4) == pytest.approx(1.02**3, rel=1e-12)
    # frozen 40 K below T_0 (T_f = T_0), cooled 100 K: only the glassy 0.6e-4 acts
    assert thermal_volume_ratio(193.15, 293.15, 2e-4, 0.6e-4, 293.15) == pytest.approx(
        (1 - 0.006) ** 3, rel=1e-12)


@pytest.mark.skipif(not HAVE_COMPILED_TANGENT, reason="numba not installed")
@pytest.mark.parametrize("c01", [0.0, 0.3e6])
def test_compiled_mooney_rivlin_equals_einsum_reference(c01):
    """The compiled kernels evaluate the same equations point by point: identical to the einsum
    reference up to round-off (1e-12 relative to the largest entry; measured 5e-16)."""
    F = np.eye(3)[..., None, None] + 0.15 * RNG.standard_normal((3, 3, 4, 50))
    F[2, :2] = F[:2, 2] = 0.0  # axisymmetric layout: hoop stretch uncoupled
    for ref, fast in ((_mr_stress, mr_stress), (_mr_tangent, mr_tangent)):
        a = ref(F, 0.8e6, c01)
        b = fast(F, 0.8e6, c01, compiled=True)
        assert np.abs(b - a).max() <= 1e-12 * np.abs(a).max()
    # written into a given output array (FElupe passes its previous result)
    out = np.empty((3, 3, 3, 3, 4, 50))
    assert mr_tangent(F, 0.8e6, c01, compiled=True, out=out) is not None
    assert np.abs(out - _mr_tangent(F, 0.8e6, c01)).max() <= 1e-12 * np.abs(out).max()


@pytest.mark.skipif(not HAVE_COMPILED_TANGENT, reason="numba not installed")
def test_compiled_viscoelastic_umat_equals_einsum_reference():
    """The viscoelastic umat's compiled kernels (stress, state update, tangent; the tangent
    reduced to the components of an axisymmetric field and written into FElupe's previous
    result, as the compiled solid asks for it) against its einsum reference, 19 Prony terms
    like the catalogue NBR: equal to round-off (1e-12 of the largest entry; measured 6e-16).
    The reference inverts F with LAPACK, the kernel with the cofactor matrix."""
    F = np.eye(3)[..., None, None] + 0.15 * RNG.standard_normal((3, 3, 4, 30))
    F[2, :2] = F[:2, 2] = 0.0  # axisymmetric layout
    betas = RNG.uniform(0.1, 30.0, 19)
    sv = 1e6 * RNG.standard_normal((9 * 20, 4, 30))
    ref, fast = (ViscoelasticMooneyRivlin(0.4e6, 0.1e6, betas, compiled=c) for c in (False, True))
    for u in (ref, fast):
        u.xi, u.theta = np.geomspace(1e-3, 50.0, 19), 1.1
    (P, new), A = ref.gradient([F, sv]), ref.hessian([F, sv])[0]
    out = np.full_like(P, np.nan)
    P_fast, new_fast = fast.gradient([F, sv], out=out)
    assert P_fast is not None and new_fast.shape == sv.shape and not np.isnan(out).any()
    for a, b in ((P, P_fast), (new, new_fast), (A, fast.hessian([F, sv])[0])):
        assert np.abs(b - a).max() <= 1e-12 * np.abs(a).max()
    kept = np.zeros((3, 3), bool)
    kept[:2, :2] = kept[2, 2] = True  # the δF components of an axisymmetric field
    mask = kept[:, :, None, None] & kept[None, None, :, :]
    out = np.full_like(A, np.nan)
    reduced = fast.hessian([F, sv], out=out, reduced=True)[0]
    assert np.abs(reduced[mask] - A[mask]).max() <= 1e-12 * np.abs(A).max()
    assert not reduced[~mask].any() and not np.isnan(out).any()


@pytest.mark.parametrize("backend", ["superlu", "pardiso", "compiled"])
def test_linear_solvers_reuse_the_analysis_and_match_spsolve(backend):
    """Non-symmetric matrices of one sparsity pattern (a stiffness-like 2-d Laplacian plus a
    small skew part, like the follower pressure): every backend gives scipy's ``spsolve``
    solution to round-off (1e-12), and PARDISO and the compiled LU analyse the pattern
    once."""
    import scipy.sparse as sp

    from sealsim.structure.solver import LinearSolver, _pypardiso

    if backend == "pardiso" and _pypardiso() is None:
        pytest.skip("pypardiso not installed")
    n = 30
    lap = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(n, n))
    base = (sp.kron(lap, sp.eye(n)) + sp.kron(sp.eye(n), lap)).tocsr()
    skew = sp.diags([0.05, -0.05], [-1, 1], shape=(n * n, n * n))
    solver = LinearSolver(backend)
    for k in range(3):
        A = (base * (1.0 + 0.3 * k) + skew + sp.eye(n * n) * 1e-3).tocsr()
        b = RNG.standard_normal(n * n)
        x = solver(A, b)
        ref = spsolve(A, b)
        assert np.abs(x - ref).max() <= 1e-12 * np.abs(ref).max()
    assert solver.analyses == (0 if backend == "superlu" else 1)
    solver.release()


def test_compiled_lu_keeps_the_analysis_per_pattern_and_falls_back_on_a_bad_pivot():
    """The compiled LU (sealsim.structure.sparse_lu) against scipy's ``spsolve`` (1e-12 of
    the solution, round-off): its fill equals SuperLU's with the same ordering (same symbolic
    factorisation), a second pattern gets its own analysis and the first is reused when it
    comes back; a matrix with a zero diagonal (a pivot no diagonal-pivoting LU can take) is
    solved by SuperLU with partial pivoting instead, and counted."""
    import scipy.sparse as sp

    from sealsim.structure.solver import LinearSolver
    from sealsim.structure.sparse_lu import PatternLU, superlu_factor

    n = 20
    lap = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(n, n))
    base = (sp.kron(lap, sp.eye(n)) + sp.kron(sp.eye(n), lap)
            + sp.diags([0.05, -0.05], [-1, 1], shape=(n * n, n * n))).tocsr()
    lu = PatternLU(base)
    superlu = superlu_factor(base)
    assert lu.fill == superlu.L.nnz + superlu.U.nnz - n * n
    other = (base + sp.diags([0.3], [7], shape=(n * n, n * n))).tocsr()  # a new entry
    solver = LinearSolver("compiled")
    for A in (base, other, base * 2.0):
        b = RNG.standard_normal(n * n)
        ref = spsolve(A, b)
        assert np.abs(solver(A, b) - ref).max() <= 1e-12 * np.abs(ref).max()
    assert solver.analyses == 2 and solver.fallbacks == 0
    swap = sp.csr_matrix(np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]))
    x = solver(swap, np.array([1.0, 2.0, 3.0]))
    assert x.tolist() == [2.0, 1.0, 3.0] and solver.fallbacks == 1
    assert not PatternLU(swap).factorize(swap)
    # factors dense enough for SuperLU's supernodes (a full block): left to SuperLU
    block = sp.csr_matrix(np.eye(150) * 160.0 + RNG.random((150, 150)))  # 15000 flops/dof
    b = RNG.standard_normal(150)
    assert PatternLU(block).dense and not lu.dense
    ref = spsolve(block, b)
    assert np.abs(solver(block, b) - ref).max() <= 1e-12 * np.abs(ref).max()
    assert solver.fallbacks == 1


def test_viscoelastic_material_expansion_follows_the_fictive_temperature():
    """The FE material's thermal volume follows the same structural relaxation as the
    elastomer's fictive temperature along the same history (one law, exact to round-off), and
    a cut-back increment restores it."""
    from sealsim.properties.elastomers import get_elastomer, thermal_strain

    nbr = get_elastomer("NBR")
    m = material_from_elastomer(nbr, "viscoelastic", reference_temperature=293.15)
    temps = np.linspace(293.15, 220.0, 38)  # 1 K/min
    times = (293.15 - temps) * 60.0
    for k in range(1, temps.size):
        m.set_state(temps[k], times[k] - times[k - 1])
    t_f = nbr.fictive_temperature(times, temps)[-1]
    assert m.fictive_temperature == pytest.approx(t_f, abs=1e-9)
    assert -45.0 < t_f - 273.15 < -25.0  # frozen near T_g, not at T
    strain = thermal_strain(temps[-1], 293.15, nbr.thermal_expansion, nbr.glassy_expansion, t_f)
    assert m.volume_ratio == pytest.approx((1 + strain) ** 3, rel=1e-12)
    cp = m.checkpoint()
    m.set_state(200.0, 600.0)
    m.restore(cp)
    assert m.fictive_temperature == cp["fictive_temperature"]
    assert np.array_equal(m.departures, cp["departures"])


def test_hertz_formulas_are_consistent():
    # the inverse of the approach formula returns the force (brentq tolerance 1e-12)
    d = cylinder_between_flats_approach(800.0, 2e-3, 6e6)
    assert cylinder_between_flats_force(d, 2e-3, 6e6) == pytest.approx(800.0, rel=1e-9)
    a, p0 = hertz_line_contact(800.0, 2e-3, 6e6)
    assert np.pi * a * p0 / 2 == pytest.approx(800.0, rel=1e-12)  # elliptic pressure integral


def test_geometry_input_errors():
    with pytest.raises(InputError, match="cord_diameter"):
        ORing(-4e-3, 20e-3)
    with pytest.raises(InputError, match="too narrow"):
        SealAssembly(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 3.5e-3))
    a = SealAssembly(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 4.2e-3))
    with pytest.raises(InputError, match="100 %"):
        a.check_squeeze(1.0)
    with pytest.raises(InputError, match="gland too small"):
        a.check_fill(0.3, 1.0)
    with pytest.raises(InputError, match="arrangement"):
        Gland("wiper", 20e-3, 5e-3)
    # gland fill by hand: pi*2^2 / (3.2 * 5.4) mm^2
    assert gland_fill(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3), 0.2) == pytest.approx(
        np.pi * 4 / (3.2 * 5.4), rel=1e-12)


def test_installation_path_keeps_gland_depth():
    a = SealAssembly(ORing(4e-3, 19e-3), Gland("rod", 20e-3, 5.4e-3))
    for s in (0.0, 0.05, 0.1, 0.2):
        lines = a.lines(s, 293.15, installation_squeeze=0.1)
        h = lines[1].point[1] - lines[0].point[1]
        assert h == pytest.approx(4e-3 * (1 - s), rel=1e-12)
    assert a.lines(0.0, 293.15, 0.1)[0].point[1] == pytest.approx(9.5e-3)  # free ID / 2
    assert a.lines(0.1, 293.15, 0.1)[0].point[1] == pytest.approx(10e-3)  # on the rod


def test_mesh_levels_are_valid():
    ring = ORing(4e-3, 20e-3)
    for level in MESH_LEVELS:
        m = mesh_oring(ring, (0.0, 12e-3), level)
        assert len(np.unique(m.cells)) == m.npoints  # no orphan nodes
        r = np.linalg.norm(m.points[m.boundary] - [0.0, 12e-3], axis=1)
        assert np.allclose(r, 2e-3, rtol=1e-12)  # boundary nodes on the circle
        area = 0.5 * np.abs(np.sum(
            m.points[m.boundary, 0] * np.roll(m.points[m.boundary, 1], -1)
            - np.roll(m.points[m.boundary, 0], -1) * m.points[m.boundary, 1]))
        n = len(m.boundary)
        assert area == pytest.approx(0.5 * n * 4e-6 * np.sin(2 * np.pi / n), rel=0.05)


def test_segment_moments_and_wetting():
    m, _ = segment_moments(np.array([0.25]), np.array([0.75]))
    assert m[:, 0] == pytest.approx([0.25, 0.25])
    pc = np.array([0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 1.0, 0.0])
    s0, s1 = wetted_fractions(pc, np.ones(8), 0)
    # forward edge: p^2 from (1, 4) over length 1 -> zero 1/3 before node 3
    assert s1[2] == pytest.approx(1 - 1 / 3)
    assert s0[6] == pytest.approx(1 / 3) and s1[6] == 1.0
    assert np.all(s1[3:6] == 0.0)


def test_contact_width_hertz_profile():
    # exact for an elliptic (Hertz) profile sampled on any grid
    x = np.linspace(-1.0, 1.0, 17)
    p = np.sqrt(np.clip(0.63**2 - x**2, 0.0, None))
    b, _, _ = contact_width(x, p)
    # p^2 is taken linear next to the edge: for the elliptic profile the error is O(h^2 / a),
    # here 0.1 %
    assert b == pytest.approx(1.26, rel=2e-3)
    assert contact_width(x, np.zeros_like(x))[0] == 0.0


def test_hermite_grid_reproduces_cubic_and_nodes():
    x = np.array([0.0, 0.3, 0.7, 1.0])
    y = np.array([250.0, 300.0, 320.0, 400.0])
    f = (np.sin(3 * x)[:, None] + (y[None, :] / 100) ** 2)[..., None]
    g = HermiteGrid([x, y], f)
    X, Y = np.meshgrid(x, y, indexing="ij")
    assert np.allclose(g.evaluate(np.c_[X.ravel(), Y.ravel()])[:, 0], f.ravel(), rtol=1e-13)
    lin = (2 * x[:, None] - 0.01 * y[None, :])[..., None]  # linear data: exact everywhere
    gl = HermiteGrid([x, y], lin)
    assert gl.evaluate_scalar((0.41, 333.3))[0] == pytest.approx(0.82 - 3.333, abs=1e-12)


def test_case_validation_messages():
    base = {"seal": {"cord_diameter": "4 mm", "inner_diameter": "20 mm"},
            "gland": {"sealing_diameter": "20 mm", "groove_width": "5.4 mm"},
            "load": {"squeeze": [0.1]}}
    validate_case(StructureCase, base)
    bad = dict(base, load={"squeeze": [1.0]})
    with pytest.raises(InputError, match=r"load.squeeze.0.*out of range"):
        validate_case(StructureCase, bad)
    bad = dict(base, seal={"cord_diameter": "-4 mm", "inner_diameter": "20 mm"})
    with pytest.raises(InputError, match="seal.cord_diameter"):
        validate_case(StructureCase, bad)
    bad = dict(base, load={"squeeze": [0.1], "temperature_rate": "fast"})
    with pytest.raises(InputError, match="temperature_rate"):
        validate_case(StructureCase, bad)


@pytest.mark.parametrize("axisymmetric", [True, False])
@pytest.mark.parametrize("viscoelastic", [False, True])
def test_compiled_solid_body_equals_felupe(axisymmetric, viscoelastic):
    """The compiled nearly incompressible solid (sealsim.structure.assembly) against FElupe's
    SolidBodyNearlyIncompressible, the same formulation: residual, tangent, cell pressure and
    stress for a deformed O-ring section, after a second evaluation and after a restore (the
    state follows FElupe's linearised volume update). Tolerance 1e-10 of the largest entry:
    round-off of a different summation order (measured ~1e-14)."""
    import felupe as fem

    from sealsim.structure.assembly import CompiledSolidBody

    ring = ORing(4e-3, 20e-3)
    a = SealAssembly(ring, Gland("rod", 20e-3, 5.4e-3))
    mesh = mesh_oring(ring, a.centre, "coarse")
    region = fem.RegionQuad(fem.Mesh(mesh.points, mesh.cells, "quad"))
    kind = fem.FieldAxisymmetric if axisymmetric else fem.FieldPlaneStrain
    umat = (ViscoelasticMooneyRivlin(0.4e6, 0.1e6, betas=[2.0, 0.5]) if viscoelastic
            else MooneyRivlinIsochoric(0.8e6, 0.2e6))
    solids = {}
    for compiled in (False, True):
        field = fem.FieldContainer([kind(region, dim=2)])
        cls = CompiledSolidBody if compiled else fem.SolidBodyNearlyIncompressible
        solids[compiled] = (cls(umat, field, bulk=5e8), field)
    x = mesh.points
    u1 = np.stack([0.02 * (x[:, 1] - x[:, 1].mean()), -0.05 * (x[:, 1] - x[:, 1].min())], 1)
    u2 = u1 + 1e-5 * RNG.standard_normal(u1.shape)
    out = {}
    for compiled, (solid, field) in solids.items():
        cp = solid.checkpoint()
        res = []
        for u in (u1, u2, None):
            if u is None:
                solid.restore(cp)
                u = field[0].values
            field[0].values[:] = u
            f = np.asarray(solid.assemble.vector(field=field).toarray()).ravel()
            K = solid.assemble.matrix().toarray()
            res.append((f, K, solid.results.state.p.copy(), solid.results.stress[0].copy()))
        out[compiled] = res
    for ref, new in zip(out[False], out[True], strict=True):
        for r, n in zip(ref, new, strict=True):
            assert np.abs(n - r).max() <= 1e-10 * np.abs(r).max()


def test_result_tables_give_the_squeeze_in_percent_as_the_gland_check_does():
    """result.csv and profiles.csv carry the squeeze as ``squeeze_percent`` (the gland
    check's ``squeeze_percent`` convention, the unit in the header); they gave a bare
    fraction headed ``squeeze`` (0.15 next to the gland check's 15 %)."""
    from sealsim.structure.results import (
        StateResult,
        SurfaceResult,
        profiles_frame,
        results_frame,
    )

    surface = SurfaceResult("sealing_surface", 10.0, 1e-3, 1e6, 5e5, np.array([0.0, 1e-3]),
                            np.array([1e6, 0.0]), 0.01)
    state = StateResult(squeeze=0.15, pressure=6e5, temperature=293.15, time=0.0, F_N=10.0,
                        F_N_per_length=100.0, b=1e-3, p_max=1e6, p_mean=5e5,
                        surfaces={"sealing_surface": surface}, axial_imbalance=0.0,
                        radial_imbalance=0.0, hoop_force=0.0, fluid_force=(0.0, 0.0),
                        max_penetration=0.0, wetted_length=0.0, rolling_moment=0.0)
    for frame in (results_frame([state]), profiles_frame([state])):
        assert "squeeze" not in frame.columns
        assert frame["squeeze_percent"].tolist() == pytest.approx([15.0] * len(frame))
