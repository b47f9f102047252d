"""Compilation of the pneumatic model's right-hand side with numba (when installed).

The physics functions of :mod:`.valve`, :mod:`.chambers` and :mod:`.cylinder` are written with
arithmetic and numpy ufuncs only (no ``np.asarray``, no ``np.where``, no Python branches on
values), so one function body works on floats and on arrays in numpy *and* inside numba's
nopython mode.  :func:`jit` compiles such a function for the per-column loop of the ODE
right-hand side (:func:`sealsim.pneumatic.simulation._core`), where a call on floats costs well
under a microsecond instead of the tens of microseconds of numpy on one-element arrays.
Without numba the same code runs as plain Python (correct, about 50× slower).
"""

from __future__ import annotations

import types

try:  # pragma: no cover - depends on the environment
    import numba
except ImportError:  # pragma: no cover
    numba = None

__all__ = ["HAVE_NUMBA", "jit"]

HAVE_NUMBA = numba is not None


def jit(func, **compiled):
    """``numba.njit`` of ``func``, or ``func`` itself without numba.

    ``compiled`` names global functions that ``func`` calls and gives their compiled versions
    (numba cannot call plain Python functions): ``jit(iso6358_flow,
    iso6358_mass_flow=jit(iso6358_mass_flow))``.  The public function stays plain numpy code.
    """
    if numba is None:  # pragma: no cover
        return func
    if compiled:
        env = dict(func.__globals__)
        env.update(compiled)
        func = types.FunctionType(func.__code__, env, func.__name__, func.__defaults__,
                                  func.__closure__)
    return numba.njit(cache=False)(func)
