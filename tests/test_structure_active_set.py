"""Held contact state of the FE contacts (sealsim.structure.active_set) and the Newton solver
that holds it when it cycles (sealsim.structure.solver): the held trial is FElupe's trial when
nothing is switched, its tangent is the derivative of its force when points are held against
their gap or slip, the check of a held state finds the points that disagree, and an increment
of the X-ring map whose contact state cycles with period 2 converges without cutback."""

from __future__ import annotations

import warnings

import felupe as fem
import numpy as np
import pytest
import scipy.sparse as sp

from sealsim.errors import ConvergenceError
from sealsim.structure import solver as solver_module
from sealsim.structure.assembly import ContactRigidPlaneOnce
from sealsim.structure.solver import LoadStep, solve

SLIP = 1e-3  # elastic slip of the block's contact [m]


def _block():
    """A unit square (plane strain) on a rigid plane y = 0 with Coulomb friction; its bottom
    nodes were pressed into the plane (converged), then moved along it by 0.2 ... 3 elastic
    slips and some of them up or down: sticking, sliding, leaving and new points."""
    mesh = fem.Rectangle(n=6)
    mesh.add_points(np.array([[0.5, 0.0]]))
    field = fem.FieldContainer([fem.FieldPlaneStrain(fem.RegionQuad(mesh), dim=2)])
    bottom = np.flatnonzero(np.isclose(mesh.points[:-1, 1], 0.0))
    contact = ContactRigidPlaneOnce(field, points=bottom, centerpoint=mesh.npoints - 1,
                                    normal=[0.0, 1.0], friction=0.3, multiplier=100.0,
                                    elastic_slip=SLIP)
    u = field[0].values
    u[bottom, 1] = -1e-3 * np.array([1.0, 2.0, 1.5, 1.0, 0.0, -1.0])  # 4 in contact
    contact.assemble.vector(field)
    contact.results.update_statevars()
    u[bottom, 0] = SLIP * np.array([0.2, 0.5, 3.0, 1.3, 0.7, 2.0])
    u[bottom, 1] = -1e-3 * np.array([1.2, 2.0, 1.0, -0.5, 0.4, 0.8])
    return field, contact


def _force_and_tangent(field, contact):
    n = field[0].values.size
    force = np.asarray(contact.assemble.vector(field).toarray()).ravel()
    rows, cols, values = contact.stiffness_entries()
    return force, sp.coo_matrix((values, (rows, cols)), shape=(n, n)).tocsr()


def test_held_natural_state_is_felupes_trial():
    field, contact = _block()
    force, tangent = _force_and_tangent(field, contact)
    active, slip = contact.results.active.copy(), contact.results.slip.copy()
    # the block has sticking and sliding points in contact, one leaving and two new points
    assert active.tolist() == [True, True, True, False, True, True]
    assert slip.tolist() == [False, False, True, False, False, False]
    # the law on given branches (which the held trial switches to) is FElupe's on its own
    # branches: the tangential forces of the points in contact to round-off
    trial = contact._evaluate()
    points = trial.contact
    gap, normal, _ = contact._kinematics(trial.dx[points])
    tangential = trial.force - contact.multipliers.normal * gap[:, None] * normal
    branch = contact.friction_branch(points, slip[points])
    assert np.allclose(branch[0], tangential, rtol=1e-12, atol=1e-12 * np.abs(trial.force).max())
    assert np.allclose(branch[2], trial.dx_ref[points], rtol=0.0, atol=1e-15)
    stiffness = trial.stiffness - contact.multipliers.normal * np.einsum("ai,aj->aij", normal,
                                                                         normal)
    assert np.allclose(branch[1], stiffness, rtol=1e-12,
                       atol=1e-12 * np.abs(trial.stiffness).max())
    contact.freeze(active, slip)
    held_force, held_tangent = _force_and_tangent(field, contact)
    # nothing switched: the same arrays (the held trial is FElupe's, no arithmetic on it)
    assert np.array_equal(held_force, force)
    assert abs(held_tangent - tangent).max() == 0.0


def test_held_tangent_is_the_derivative_of_the_held_force():
    field, contact = _block()
    _force_and_tangent(field, contact)
    active, slip = contact.results.active.copy(), contact.results.slip.copy()
    held, held_slip = active.copy(), slip.copy()
    held[3] = True             # held in contact at a positive gap (it was in contact before)
    held[4] = False            # held out of contact while it penetrates
    held_slip[[0, 1]] = True   # sticking points held in slip
    held_slip[2] = False       # a sliding point held in stick
    contact.freeze(held, held_slip)
    force, tangent = _force_and_tangent(field, contact)
    rng = np.random.default_rng(3)
    u = field[0].values.copy()
    du = 1e-9 * rng.standard_normal(u.shape)
    field[0].values[:] = u + du
    plus = _force_and_tangent(field, contact)[0]
    field[0].values[:] = u - du
    minus = _force_and_tangent(field, contact)[0]
    field[0].values[:] = u
    difference = (plus - minus) / 2.0
    # central differences of a smooth force: truncation ~ (1e-9 / 1e-3)^2, round-off
    # ~ 1e-16 / 1e-6 of the force; 1e-6 leaves room for both
    assert np.linalg.norm(tangent @ du.ravel() - difference) <= 1e-6 * np.linalg.norm(
        difference)
    # the held branches are used, not the gaps' and slips': the point held out carries no
    # force, the point held in (positive gap) pulls, the held-slip points carry mu f_n
    dof = field[0].indices.dof[contact.points]
    assert np.all(force[dof[4]] == 0.0)
    assert force[dof[3, 1]] > 0.0
    normal_force = -force[dof[[0, 1], 1]]
    assert np.allclose(np.abs(force[dof[[0, 1], 0]]), 0.3 * np.abs(normal_force), rtol=1e-12)


def test_the_check_of_a_held_state_finds_the_points_that_disagree():
    field, contact = _block()
    _force_and_tangent(field, contact)
    active, slip = contact.results.active.copy(), contact.results.slip.copy()
    contact.freeze(active, slip)
    normal, sliding = contact.inconsistent_points(1e-2)
    assert not normal.any() and not sliding.any()   # the gaps' and slips' own state
    held, held_slip = active.copy(), slip.copy()
    held[3] = True          # gap +0.5 mm against a largest penetration of 2 mm: 25 % > 1 %
    held_slip[0] = True     # |e| = 0.2 s held in slip
    held_slip[2] = False    # |e| = 3 s held in stick
    contact.freeze(held, held_slip)
    normal, sliding = contact.inconsistent_points(1e-2)
    assert np.flatnonzero(normal).tolist() == [3]
    assert np.flatnonzero(sliding).tolist() == [0, 2]
    # within a tolerance of 30 % the held tension of point 3 is accepted
    assert not contact.inconsistent_points(0.3)[0].any()
    contact.refreeze(normal, sliding)
    assert np.array_equal(contact.frozen, active)
    assert np.array_equal(contact.frozen_slip, slip & active)


@pytest.fixture(scope="module")
def installed_xring():
    """The X-ring of the TU Delft map (examples/calibration/xring_257_piston.toml) installed
    to 10 % squeeze at 20 degC, as the map solves it."""
    from sealsim.structure.build import build_material, build_model
    from sealsim.structure.case import load_structure_cases
    from sealsim.structure.results import extract

    path = "examples/calibration/xring_257_piston.toml"
    case = next(iter(load_structure_cases(path, path).values()))
    model = build_model(case, 0.10, material=build_material(case, equilibrium=True))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        solve(model, [LoadStep("installation", squeeze=0.10, increments=4, record="none")],
              on_state=extract)
    return model


def _pressurise(model, increments, monkeypatch, hold):
    import copy

    from sealsim.structure.results import extract

    model = copy.deepcopy(model)
    monkeypatch.setattr(solver_module, "FREEZE_CYCLING_CONTACT", hold, raising=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        state = solve(model, [LoadStep("pressure", pressure=0.5e5, increments=increments,
                                       record="end")],
                      on_state=extract, max_cutbacks=0)[-1]
    return model, state


def test_cycling_increment_of_the_xring_map_converges(installed_xring, monkeypatch):
    # 0 -> 0.5 bar in one increment: the ring's lobe at the downstream land's rounded edge
    # has one point flipping in and out of contact and its neighbour between stick and slip,
    # Newton's residual alternating between 0.95 and 0.15 of the reactions for 25 iterations
    # (in the map the second cutback of its 0 -> 2 bar step, failing as well); with the
    # cycling state frozen it converges
    with pytest.raises(ConvergenceError):
        _pressurise(installed_xring, 1, monkeypatch, hold=False)
    model, state = _pressurise(installed_xring, 1, monkeypatch, hold=True)
    assert model.increment_log[-1]["cutbacks"] == 0
    # the same solution as a path the state does not cycle on (two increments, Newton on
    # the gaps' and slips' own state): the friction on the groove makes the result depend on
    # the path a little; the map's differences between the two were <= 3e-4 in F_N and b
    _, reference = _pressurise(installed_xring, 2, monkeypatch, hold=False)
    assert state.F_N == pytest.approx(reference.F_N, rel=1e-3)
    assert state.b == pytest.approx(reference.b, rel=1e-3)
    # and a solution of the contact problem itself: with the gaps and slips deciding again,
    # the residual of the converged state is within the check's 1 % of a nodal force
    for contact in model.contacts.values():
        contact.release()
    f, _ = model.system.assemble(model.items, model.field)
    reactions = np.linalg.norm(f[model.dof0])
    assert np.linalg.norm(f[model.dof1]) <= 1e-2 * reactions
