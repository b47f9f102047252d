"""Compiled time integration of stiff ODEs (numba): the variable-order BDF method of
:mod:`.bdf` with event location, generic over the right-hand side.

Used by the pneumatic cylinder (:mod:`sealsim.pneumatic.integrate`) and the friction test
bench (:mod:`sealsim.friction.bench`); the C port that runs inside the cylinder FMU is
``sealsim/fmu/c/bdf.c``.
"""

from sealsim.ode.bdf import BdfSolver, compile_bdf, workspace

__all__ = ["BdfSolver", "compile_bdf", "workspace"]
