"""Validation of the axisymmetric seal FE model against independent references.

Every assertion states its reference and why the tolerance is what it is. Coarse meshes are
used where the reference allows it (the whole file runs in well under a minute).
"""

import numpy as np
import pytest

from sealsim.errors import ConvergenceError
from sealsim.structure.analytic import cylinder_between_flats_force, hertz_line_contact
from sealsim.structure.geometry import Gland, ORing, SealAssembly
from sealsim.structure.material import HyperelasticSealMaterial, material_from_elastomer
from sealsim.structure.mesh import mesh_oring
from sealsim.structure.model import SealModel
from sealsim.structure.profile_mesh import mesh_section
from sealsim.structure.solver import LoadStep, solve

C10, C01, K = 0.8e6, 0.2e6, 2e9
E = 6 * (C10 + C01)  # small-strain Young's modulus of the incompressible Mooney-Rivlin solid
RING = ORing(4e-3, 20e-3)


def hyperelastic(alpha=2e-4, t0=293.15):
    return HyperelasticSealMaterial(C10, C01, K, alpha, t0)


def rod_model(level="coarse", squeeze=0.2, material=None, **kw):
    a = SealAssembly(RING, Gland("rod", 20e-3, 5.4e-3), kw.pop("inner", 0.0),
                     kw.pop("outer", 0.0))
    mesh = mesh_oring(a.seal, a.centre, level)
    return SealModel(a, mesh, material or hyperelastic(), installation_squeeze=squeeze, **kw)


@pytest.fixture(scope="module")
def pressurised():
    """Coarse axisymmetric O-ring: squeeze 20 %, then 0 -> 10 bar in 2.5 bar steps."""
    model = rod_model()
    states = solve(model, [LoadStep("squeeze", squeeze=0.2, increments=5, record="end"),
                           LoadStep("pressure", pressure=10e5, increments=4, record="all")])
    return model, states


def test_plane_strain_cylinder_between_flats_matches_hertz():
    """Plane-strain cylinder squeezed 3 % and 5 % between two rigid flats vs Hertz/Johnson.

    Reference: Johnson, Contact Mechanics (1985), §4.2/§5.6 (line contact, rigid flats,
    incompressible). Tolerance 5 % (issue): Hertz is a small-strain theory; at 5 % squeeze
    a/R = 0.2, and the FE (finite strain, 0.027 mm elements at the contact) measured
    F +1.6 %, b +0.3 %, p_max +0.3 %.
    """
    a = SealAssembly(RING, Gland("rod", 20e-3, 8e-3))
    mesh = mesh_oring(a.seal, a.centre, n_arc=48, n_wall=16, n_radial=12, arc_grading=8)
    model = SealModel(a, mesh, hyperelastic(), installation_squeeze=0.05, axisymmetric=False,
                      walls=False)
    states = solve(model, [LoadStep("squeeze", squeeze=0.03, increments=3, record="end"),
                           LoadStep("squeeze", squeeze=0.05, increments=2, record="end")])
    for s in states:
        force = cylinder_between_flats_force(s.squeeze * RING.cord_diameter, RING.radius, E)
        half_width, p0 = hertz_line_contact(s.F_N, RING.radius, E)
        assert s.F_N == pytest.approx(force, rel=0.05)
        assert s.b == pytest.approx(2 * half_width, rel=0.05)
        assert s.p_max == pytest.approx(p0, rel=0.05)
        # both flats carry the same force (plane strain: exact equilibrium, solver tolerance)
        assert s.surfaces["groove_bottom"].force == pytest.approx(s.F_N, rel=1e-6)


def test_global_equilibrium_and_penetration(pressurised):
    """Sum of all reactions + fluid load = 0 axially, = hoop force 2π∫P_θθ dA radially.

    Reference: equilibrium of the axisymmetric section (∮ r t_r ds = ∫ σ_θθ da), evaluated
    from the stresses independently of the assembled forces. Tolerance 1e-6 of F_N: the Newton
    tolerance is 1e-8 of the reactions. The rod and groove-bottom forces differ by the hoop
    force (here > 10 % of F_N, so the check is not trivial).
    """
    _, states = pressurised
    for s in states:
        assert abs(s.axial_imbalance) < 1e-6
        assert abs(s.radial_imbalance) < 1e-6
        gap = s.surfaces["groove_bottom"].force - s.F_N
        assert abs(gap) > 0.1 * s.F_N
        # penalty penetration: below 2 µm = 0.25 % of the 0.8 mm squeeze displacement
        # (measured 0.3-0.7 µm on this coarse mesh, 0.13-0.25 µm on the fine one)
        assert s.max_penetration < 2e-6
        # the anti-rolling spring (in place of static friction) carries a small moment: as a
        # friction force at the cord radius it is < 2 % of F_N (measured 0.1-0.5 %), far below
        # what static friction (mu 0.1-0.5) can hold
        assert abs(s.rolling_moment) / RING.radius < 0.02 * s.F_N


def test_pressure_raises_normal_force(pressurised):
    """The sealed pressure adds to the contact pressure: a nearly incompressible ring
    transmits it like a fluid.

    Reference: hydrostatic transmission ("the O-ring acts like a fluid": contact stress =
    squeeze stress + system pressure, Parker O-Ring Handbook ORD 5700, §1).  A uniform stress
    −Δp·I added to the squeezed state keeps the body in equilibrium with Δp on its wetted
    surface and on its contacts, so the peak contact pressure rises by Δp (the ring is also
    pushed into the groove corner: measured 1.006-1.027 Δp per 2.5 bar step, asserted within
    5 %), and F_N by at least Δp·2πR_rod·b over the contact width b at the start of a step
    (measured 1.18-1.23 times that: the contact also widens; asserted 1 to 1.5).  A fluid
    load that stops short of the contact edges or misses a part of the wetted surface gives
    less.
    """
    _, states = pressurised
    forces = np.array([s.F_N for s in states])
    pressures = np.array([s.pressure for s in states])
    widths = np.array([s.b for s in states])
    peaks = np.array([s.p_max for s in states])
    dp = np.diff(pressures)
    assert np.diff(peaks) / dp == pytest.approx(np.ones(dp.size), rel=0.05)
    hydrostatic = dp * 2 * np.pi * 10e-3 * widths[:-1]
    assert np.all((np.diff(forces) > hydrostatic) & (np.diff(forces) < 1.5 * hydrostatic))
    # the downstream wall takes the axial fluid load
    assert states[-1].surfaces["wall_downstream"].force > states[0].surfaces[
        "wall_downstream"].force


def test_pressure_adds_to_contact_pressure_of_rectangular_ring():
    """A square ring (3 x 3 mm, corner radius 0.3 mm, 10 % squeeze on a 20 mm rod, 4.5 mm
    groove, frictionless gland) pressurised 0 -> 5 -> 10 bar.

    References: (1) hydrostatic transmission (see above): away from the ring's dry corners
    the contact pressure on the rod rises by exactly Δp -- the mean over the middle half of the
    contact, measured 1.013 and 1.001 Δp, asserted within 3 % (the dry downstream corners
    disturb the uniform stress near the contact's ends). (2) Axial equilibrium of the
    frictionless ring: the downstream wall's force rises by Δp times the wetted upstream
    face projected on the axis, π(R_groove² − R_rod²) -- the fluid wets it from the rod's
    contact edge to the groove bottom's (measured 0.2 % off, asserted 1 %: Newton tolerance
    and the contact edges' interpolation).  Coarse mesh, about 2 s.
    """
    from sealsim.structure.profiles import rectangular_profile

    ring = rectangular_profile(3e-3, 3e-3, 20e-3, corner_radius=0.3e-3)
    a = SealAssembly(ring, Gland("rod", 20e-3, 4.5e-3))
    model = SealModel(a, mesh_section(a.seal, a.centre, "coarse"), hyperelastic(),
                      installation_squeeze=0.1, friction=0.0, rolling_stiffness=10.0)
    states = solve(model, [LoadStep("squeeze", squeeze=0.1, increments=3, record="end"),
                           LoadStep("pressure", pressure=5e5, increments=2, record="end"),
                           LoadStep("pressure", pressure=10e5, increments=2, record="end")])

    def middle_pressure(state):
        rod = state.surfaces["sealing_surface"]
        centre = 0.5 * (rod.edge_low + rod.edge_high)
        return np.mean(rod.pressure[np.abs(rod.position - centre) < 0.25 * rod.width])

    groove_face = np.pi * ((10e-3 + 0.9 * 3e-3) ** 2 - 10e-3 ** 2)
    for before, after in zip(states[:-1], states[1:]):
        dp = after.pressure - before.pressure
        assert (middle_pressure(after) - middle_pressure(before)) / dp == pytest.approx(
            1.0, rel=0.03)
        wall = (after.surfaces["wall_downstream"].force
                - before.surfaces["wall_downstream"].force)
        assert wall == pytest.approx(dp * groove_face, rel=0.01)


def test_mesh_refinement_changes_force_and_width_less_than_two_percent():
    """Medium vs fine mesh at squeeze 20 %, 0 and 10 bar: F_N and b change < 2 % (issue).

    Measured: F_N 0.1-0.2 %, b 0.03-0.6 %. The coarse level is not converged in b (2.4 %
    at 10 bar) and is only used where a reference allows it.
    """
    out = {}
    for level in ("medium", "fine"):
        model = rod_model(level)
        out[level] = solve(model, [
            LoadStep("squeeze", squeeze=0.2, increments=5, record="end"),
            LoadStep("pressure", pressure=10e5, increments=5, record="end")])
    for m, f in zip(out["medium"], out["fine"]):
        assert m.F_N == pytest.approx(f.F_N, rel=0.02)
        assert m.b == pytest.approx(f.b, rel=0.02)


def test_heating_raises_force_through_expansion():
    """Heating 20 -> 100 °C with temperature-independent constants and rigid metal parts.

    Reference: without thermal expansion the state does not change (same energy; up to the
    settling tolerance of the wetted surface, 1e-4 of the cord: measured 3e-5 relative);
    with α = 1.9e-4 1/K the ring's volume grows by 4.6 % in a gland of fixed size, so F_N must
    rise clearly (> 5 %; measured about +25 %).
    """
    forces = {}
    for alpha in (0.0, 1.9e-4):
        model = rod_model(material=hyperelastic(alpha))
        states = solve(model, [LoadStep("squeeze", squeeze=0.15, increments=4, record="end"),
                               LoadStep("heat", temperature=373.15, increments=4,
                                        record="end")])
        forces[alpha] = (states[0].F_N, states[1].F_N)
    cold, hot = forces[0.0]
    assert hot == pytest.approx(cold, rel=1e-4)
    cold, hot = forces[1.9e-4]
    assert hot > 1.05 * cold


@pytest.mark.parametrize("scaling", ["entropic", "held"])
def test_material_force_follows_its_temperature_law(scaling):
    """Catalogue NBR heated 20 -> 80 °C at 15 % squeeze.

    References: for the same deformation of a nearly incompressible solid the force scales
    with the shear modulus, so without thermal expansion F_N(80 °C)/F_N(20 °C) is the modulus
    ratio (2 %: the bulk modulus, 1000x the shear modulus, is not scaled): (1) "entropic",
    rubber elasticity G ∝ T (Treloar): 353.15/293.15; (2) "held", the default since issue 24:
    the relaxed modulus of a seal held an hour, E_h(80 °C)/E_h(20 °C) = 0.93 (installed at
    20 °C and warmed).  Thermal expansion adds to either (seed 001: a warmer seal presses
    harder than its modulus alone would make it).
    """
    from sealsim.properties.elastomers import get_elastomer

    nbr = get_elastomer("NBR")
    expected = (353.15 / 293.15 if scaling == "entropic"
                else nbr.held_modulus(353.15) / nbr.held_modulus(293.15))
    steps = [LoadStep("squeeze", squeeze=0.15, increments=4, record="end"),
             LoadStep("heat", temperature=353.15, increments=3, record="end")]
    forces = {}
    for label, expansion in (("no expansion", 0.0), ("catalogue", nbr.thermal_expansion)):
        material = material_from_elastomer(nbr, reference_temperature=293.15,
                                           temperature_scaling=scaling)
        material.thermal_expansion = expansion
        cold, hot = solve(rod_model(squeeze=0.15, material=material), steps)
        forces[label] = hot.F_N / cold.F_N
    assert forces["no expansion"] == pytest.approx(expected, rel=0.02)
    assert forces["catalogue"] > forces["no expansion"]


def test_cooling_below_glass_transition_lowers_force_faster():
    """Thermo-viscoelastic NBR (catalogue Prony series, WLF/Arrhenius), squeeze 15 %, 1 h
    hold, cooling 20 -> -60 °C at 1 K/min (seed 001, Fig. 8), with the state-dependent
    thermal expansion (glassy α_g = 0.31 α_r below the structure's freezing) and, for
    comparison, with the rubbery α_r throughout (the model before issue 10, finding 7).

    References: (1) seed 001: the sealing force falls slowly while the rubber can relax, much
    faster below T_g (-25 °C), the groove contact is lost, afterwards the rod force rises by
    thermal shrinkage. Asserted: mean slope between T_g and T_g - 10 K at least 3x the mean
    slope between 10 and -10 °C (measured 7.7x), groove-bottom force reaching zero below T_g,
    rod force at -60 °C above its minimum. (2) Equilibrium above T_g: the fictive temperature
    follows T, so both expansion models give the same forces at 15 °C (1e-5: the slowest
    Prony terms, 4e-4 of the weight, lag by millikelvins). (3) Linear elasticity of the frozen
    ring once the groove contact is lost: it shrinks onto the rigid steel rod, so the rate of
    the rod force is proportional to the mismatch of the expansion coefficients; the ratio of
    the two runs must be (α_g − α_steel)/(α_r − α_steel) = 0.267 (5 %: the glassy stiffness
    is the same in both runs only up to the relaxation left at -45 to -60 °C; measured 0.265).
    Seed 001 reports the gap at about -80 °C; this model opens it at -35 °C (coarse mesh),
    2 K later than with α_r: the gap follows the mechanical freezing of the catalogue
    NBR (see docs/guide/validation_structure.md).
    """
    from sealsim.properties.elastomers import get_elastomer

    nbr = get_elastomer("NBR")
    steel = 11.5e-6
    runs = {}
    for label in ("glassy", "rubbery"):
        material = material_from_elastomer(nbr, "viscoelastic", reference_temperature=293.15)
        if label == "rubbery":
            material.glassy_expansion = material.thermal_expansion
        model = rod_model(material=material, squeeze=0.15, inner=steel, outer=steel)
        states = solve(model, [
            LoadStep("installation", squeeze=0.15, increments=4, duration=60.0, record="end"),
            LoadStep("hold", duration=3600.0, increments=2, record="end"),
            LoadStep("cooling", temperature=213.15, duration=80 * 60.0, increments=16,
                     record="all")])
        runs[label] = (np.array([s.temperature for s in states]),
                       np.array([s.F_N for s in states]),
                       np.array([s.surfaces["groove_bottom"].force for s in states]))
    t, f, groove = runs["glassy"]

    def slope(force, hi, lo):
        i, j = np.argmin(abs(t - hi)), np.argmin(abs(t - lo))
        return (force[i] - force[j]) / (t[i] - t[j])

    tg = nbr.glass_transition
    assert slope(f, tg, tg - 10.0) > 3 * slope(f, 283.15, 263.15) > 0
    lost = t[groove == 0.0]
    assert lost.size and lost.max() < tg
    assert f[-1] > f.min() * 1.5
    f_rubbery = runs["rubbery"][1]
    warm = np.argmin(abs(t - 288.15))
    assert f[warm] == pytest.approx(f_rubbery[warm], rel=1e-5)
    ratio = slope(f, 228.15, 213.15) / slope(f_rubbery, 228.15, 213.15)
    expected = (nbr.glassy_expansion - steel) / (nbr.thermal_expansion - steel)
    assert ratio == pytest.approx(expected, rel=0.05)


def test_speed_ups_do_not_change_results():
    """Compiled Mooney–Rivlin kernels, compiled assembly (:mod:`sealsim.structure.assembly`)
    and the fast linear solvers against the reference implementation (einsum tangent,
    FElupe's assembly, scipy ``spsolve``) on the same load path: squeeze, heating, 0 -> 10 bar
    with the wetted surface moving, at most 9 Newton iterations so that increments fail and
    are cut back (restored states). F_N and b to 1e-9 relative (issue 13; the differences
    are round-off, measured < 1e-13), the same Newton iterations and cutbacks."""
    from sealsim.structure.solver import _pypardiso

    steps = [LoadStep("squeeze", squeeze=0.2, increments=1, record="end"),
             LoadStep("temperature", temperature=330.0, increments=1, record="end"),
             LoadStep("pressure", pressure=10e5, increments=2, record="all")]
    backends = ["superlu", "compiled"] + (["pardiso"] if _pypardiso() is not None else [])
    runs = {}
    for backend in ["reference", *backends]:
        reference = backend == "reference"
        model = rod_model(compiled=not reference)
        model.material.umat.compiled = not reference
        runs[backend] = (solve(model, steps, linear_solver=backend, maxiter=9),
                         [(r["newton_iterations"], r["cutbacks"]) for r in model.increment_log])
    ref, ref_log = runs["reference"]
    assert sum(cutbacks for _, cutbacks in ref_log) > 0  # the path covers a restore
    for states, log in [runs[b] for b in backends]:
        assert log == ref_log
        for s, r in zip(states, ref, strict=True):
            assert s.F_N == pytest.approx(r.F_N, rel=1e-9, abs=0.0)
            assert s.b == pytest.approx(r.b, rel=1e-9, abs=0.0)


def test_convergence_error_names_the_load():
    """A squeeze of 30 % in one increment with 2 Newton iterations and no cutback cannot
    converge: the error must say at which load."""
    model = rod_model(squeeze=0.3)
    with pytest.raises(ConvergenceError, match=r"squeeze 30 %.*pressure 0 bar.*20 degC"):
        solve(model, [LoadStep("squeeze", squeeze=0.3, increments=1)], maxiter=2,
              max_cutbacks=0)


def test_piston_seal_arrangement():
    """Piston seal (groove in the piston, sealing on the bore, outside the ring).

    Reference: global equilibrium as above (tolerance 1e-6 of F_N, Newton tolerance 1e-8);
    the bore stays at its radius (rigid, no temperature change: exact); both contacts carry
    load and the bore force rises with the pressure."""
    a = SealAssembly(ORing(3e-3, 44e-3), Gland("piston", 50e-3, 4e-3))
    mesh = mesh_oring(a.seal, a.centre, "coarse")
    model = SealModel(a, mesh, hyperelastic(), installation_squeeze=0.15)
    states = solve(model, [LoadStep("squeeze", squeeze=0.15, increments=4, record="end"),
                           LoadStep("pressure", pressure=6e5, increments=2, record="end")])
    for s in states:
        assert abs(s.axial_imbalance) < 1e-6 and abs(s.radial_imbalance) < 1e-6
        assert s.surfaces["groove_bottom"].force > 0 and s.F_N > 0
        assert s.surfaces["sealing_surface"].radius == pytest.approx(25e-3, rel=1e-9)
    assert states[1].F_N > states[0].F_N
