r"""Frozen active set of the penalty contacts: Newton finishes on a fixed contact and
stick/slip state when points at a switching boundary flip between iterations.

FElupe's rigid contacts (:class:`felupe.mechanics.ContactRigidBase`) are node-to-surface
penalty contacts with Coulomb friction. A point with the gap :math:`g` is in contact when
:math:`g < 0` and carries the normal force :math:`f_n = -\lambda_n g`; its trial elastic slip
:math:`\mathbf e` (the tangential motion since the reference of the last converged
increment) gives the tangential force of the elastic-slip regularisation
(:math:`\lambda_t = \mu f_n / s`, the allowed elastic slip :math:`s`) and the return mapping

.. math::

    \mathbf f_t = \begin{cases} \mu f_n\,\mathbf e / s & |\mathbf e| \le s
    \quad\text{(stick)}\\ \mu f_n\,\hat{\mathbf e} & |\mathbf e| > s \quad\text{(slip)}
    \end{cases}

(Wriggers, *Computational Contact Mechanics*, 2nd ed., Springer 2006: penalty
regularisation of the normal and tangential contact, return mapping of the Coulomb law).
Both laws switch branch at a kink (:math:`g = 0`, :math:`|\mathbf e| = s`); Newton's method on
such a semismooth system is an active set method (Hintermüller, Ito & Kunisch, *SIAM J.
Optim.* 13 (2002) 865-888), convergent only locally, and it cycles when a point's solution
lies at the kink: with the point in contact the next iterate separates it, without it the
next iterate penetrates; a point at :math:`|\mathbf e| \approx s` likewise flips between
stick and slip, and the iterates repeat with period 2 or 3 without converging.

The remedy of active set strategies: once the state cycles (the solver detects it,
:func:`sealsim.structure.solver._newton`), freeze it -- every point keeps its branch whatever
its gap or slip -- and finish Newton on the frozen system, which is smooth
(:meth:`frozen_trial`): a point held in contact keeps the penalty force
:math:`-\lambda_n g` also at :math:`g > 0` (a tension, with the friction of its branch
continued, :math:`\propto f_n`; a point that comes into contact within the increment has none
before its first contact), a point held out of contact carries nothing, a point held in
stick or slip keeps that branch's force and tangent. The converged frozen state is then
checked (:meth:`inconsistent_points`): a point whose branch disagrees with its gap or slip
by more than a tolerance is switched to the branch its gap or slip asks for and Newton goes
on; the state is accepted when no point disagrees.
"""

from __future__ import annotations

import numpy as np

__all__ = ["FreezableContact"]


class FreezableContact:
    """Mixin for FElupe's rigid contacts: evaluation on a frozen active set (module
    docstring). The class using it calls :meth:`frozen_trial` on FElupe's trial when
    :attr:`frozen` is set (see :class:`~.assembly.TrialOnce`)."""

    frozen = None
    """Points held in contact (bool mask over ``points``), or None: the gaps decide."""
    frozen_slip = None
    """Points held in slip (bool mask over ``points``; the others in contact stick)."""

    # -- freezing ---------------------------------------------------------------------------------
    def freeze(self, active, slip) -> None:
        """Hold the points ``active`` in contact and, of these, ``slip`` in slip."""
        self.frozen = np.array(active, dtype=bool)
        self.frozen_slip = np.array(slip, dtype=bool) & self.frozen

    def release(self) -> None:
        """Let the gaps and slips decide again."""
        self.frozen = None
        self.frozen_slip = None

    def _friction_frozen(self) -> bool:
        return self.friction > 0.0 and np.isfinite(self.friction) and \
            self.elastic_slip is not None

    # -- the law on given branches ----------------------------------------------------------------
    def _elastic_slip(self, points, dx, normal, curvature):
        """Trial elastic slip e and de/d(dx) of ``points`` (indices into ``self.points``) in
        contact, as FElupe's return mapping starts it: from the reference of the last
        converged increment, or for a point that comes into contact within the increment
        from its interpolated point of first contact."""
        statevars = self.results.statevars
        dim = dx.shape[1]
        projection = np.eye(dim) - np.einsum("ai,aj->aij", normal, normal)
        e, E = self._tangential(dx - statevars["dx_ref"][points], normal, projection,
                                curvature)
        new = ~statevars["active"][points]
        if np.any(new):
            dx_n = statevars["dx"][points][new]
            g_n = self._kinematics(dx_n)[0]
            g_new = self._kinematics(dx[new])[0]
            delta, D = self._tangential(dx[new] - dx_n, normal[new], projection[new],
                                        None if curvature is None else curvature[new])
            s = np.ones_like(g_new)
            ds = np.zeros_like(g_new)
            first = g_n > 0.0
            s[first] = -g_new[first] / (g_n[first] - g_new[first])
            ds[first] = -g_n[first] / (g_n[first] - g_new[first]) ** 2
            e[new] = s[:, None] * delta
            E[new] = s[:, None, None] * D + ds[:, None, None] * np.einsum(
                "ai,aj->aij", delta, normal[new])
        return e, E

    def friction_branch(self, points, slide):
        """Tangential force, its tangent and the trial reference gap vectors of ``points``
        (indices into ``self.points``, in contact) on the given branch (``slide``: bool per
        point; stick otherwise), the elastic-slip law of the module docstring.

        Returns
        -------
        force : numpy.ndarray
            (k, dim) tangential forces.
        stiffness : numpy.ndarray
            (k, dim, dim) their derivatives w.r.t. the gap vectors.
        dx_ref : numpy.ndarray
            (k, dim) trial reference gap vectors (the state after a converged increment).
        slip_ratio : numpy.ndarray
            (k,) |e| / s: the law slides where it is > 1.
        """
        dx = self._gap_vectors()[points]
        gap, normal, curvature = self._kinematics(dx)
        e, E = self._elastic_slip(points, dx, normal, curvature)
        lam_n = self.multipliers.normal
        mu, s = self.friction, self.elastic_slip
        f_n = -lam_n * gap
        e_norm = np.linalg.norm(e, axis=1)
        slide = np.asarray(slide, dtype=bool) & (e_norm > 0.0)
        # stick: mu f_n e / s
        force = (mu * f_n / s)[:, None] * e
        stiffness = (mu * f_n / s)[:, None, None] * E - (mu * lam_n / s) * np.einsum(
            "ai,aj->aij", e, normal)
        dx_ref = dx - e
        if np.any(slide):
            t = e[slide] / e_norm[slide, None]
            dim = dx.shape[1]
            projection = (np.eye(dim) - np.einsum("ai,aj->aij", t, t)) / e_norm[slide, None,
                                                                                   None]
            force[slide] = (mu * f_n[slide])[:, None] * t
            stiffness[slide] = mu * (f_n[slide, None, None] * projection @ E[slide]
                                     - lam_n * np.einsum("ai,aj->aij", t, normal[slide]))
            dx_ref[slide] = dx[slide] - s * t
        return force, stiffness, dx_ref, e_norm / s

    # -- the frozen trial -------------------------------------------------------------------------
    def frozen_trial(self, trial):
        """FElupe's trial (natural branches) turned into the trial on the frozen branches
        (module docstring); also sets the state variables taken after convergence."""
        frozen = self.frozen
        keep = frozen[trial.contact]
        points = trial.contact[keep]
        force = trial.force[keep].copy()
        stiffness = trial.stiffness[keep].copy()
        dx_ref = trial.dx_ref.copy()
        slip = trial.slip.copy()
        # points held out of contact: no force, reference at the current position
        dropped = trial.contact[~keep]
        dx_ref[dropped] = trial.dx[dropped]
        slip[dropped] = False
        if self._friction_frozen() and len(points):
            flip = self.frozen_slip[points] != trial.slip[points]
            if np.any(flip):
                changed = points[flip]
                natural = self.friction_branch(changed, trial.slip[changed])
                held = self.friction_branch(changed, self.frozen_slip[changed])
                force[flip] += held[0] - natural[0]
                stiffness[flip] += held[1] - natural[1]
                dx_ref[changed] = held[2]
                slip[changed] = self.frozen_slip[changed]
        # points held in contact at a positive gap: the normal penalty continued (a tension),
        # and so is the friction of a point that was in contact at the last converged
        # increment (its force, proportional to the normal force, changes sign with it)
        extra = np.flatnonzero(frozen & ~trial.active)
        gap, normal, _ = self._kinematics(trial.dx[extra])
        lam_n = self.multipliers.normal
        extra_force = lam_n * gap[:, None] * normal
        extra_stiffness = lam_n * np.einsum("ai,aj->aij", normal, normal)
        if self._friction_frozen():
            # a point coming into contact has no elastic slip before its first contact: no
            # friction, whose force and tangent vanish at g = 0 for such a point
            was = self.results.statevars["active"][extra]
            if np.any(was):
                continued = extra[was]
                branch = self.friction_branch(continued, self.frozen_slip[continued])
                extra_force[was] += branch[0]
                extra_stiffness[was] += branch[1]
                dx_ref[continued] = branch[2]
                slip[continued] = self.frozen_slip[continued]
        contact = np.concatenate([points, extra])
        force = np.concatenate([force, extra_force])
        stiffness = np.concatenate([stiffness, extra_stiffness])
        order = np.argsort(contact, kind="stable")
        self.results._statevars = {"dx": trial.dx, "dx_ref": dx_ref, "active": frozen.copy()}
        return trial._replace(contact=contact[order], force=force[order],
                              stiffness=stiffness[order], dx_ref=dx_ref, active=frozen.copy(),
                              slip=slip)

    def inconsistent_points(self, tolerance: float):
        """Points whose frozen branch disagrees with their gap or slip.

        A point held in contact with a gap above ``tolerance`` times the largest penetration
        of the contact (a tension above that fraction of the largest nodal normal force), or
        held out of contact with a penetration beyond it, disagrees; so does a point held in
        stick with |e| > (1 + tolerance) s or in slip with |e| < (1 - tolerance) s (a
        friction force off by more than ``tolerance`` of the point's Coulomb limit).

        Returns
        -------
        normal, slip : numpy.ndarray
            Bool masks over ``points`` of the points to switch.
        """
        gap = self._kinematics(self._gap_vectors())[0]
        frozen = self.frozen
        penetration = max(float(-gap[frozen].min()) if frozen.any() else 0.0, 0.0)
        limit = tolerance * penetration
        normal = np.where(frozen, gap > limit, gap < -limit)
        slip = np.zeros_like(frozen)
        if self._friction_frozen():
            points = np.flatnonzero(frozen & (gap < 0.0))
            if len(points):
                ratio = self.friction_branch(points, self.frozen_slip[points])[3]
                held = self.frozen_slip[points]
                slip[points] = np.where(held, ratio < 1.0 - tolerance, ratio > 1.0 + tolerance)
        return normal, slip

    def refreeze(self, normal, slip) -> None:
        """Switch the points ``normal`` to the contact state their gap asks for and the
        points ``slip`` to the other friction branch (new arrays: a cached trial of the old
        state is not reused)."""
        gap = self._kinematics(self._gap_vectors())[0]
        frozen = np.where(normal, gap < 0.0, self.frozen)
        frozen_slip = np.where(slip, ~self.frozen_slip, self.frozen_slip)
        self.freeze(frozen, frozen_slip)
