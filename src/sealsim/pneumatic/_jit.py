"""Compilation of the numpy physics functions of the pneumatic model with numba.

The physics functions of :mod:`.valve`, :mod:`.chambers`, :mod:`.cylinder` and :mod:`.seals`
(and the air properties and free convection of :mod:`sealsim.thermal.convection` they use)
are written with arithmetic and numpy ufuncs only (no ``np.asarray``, no ``np.where``, no Python
branches on values), so one function body works on floats and on arrays in numpy *and* inside
numba's nopython mode.  :func:`jit` compiles such a function for the compiled right-hand side
(:mod:`.rhs`), where a call on floats costs nanoseconds.  The compiled code is cached on disk
(``cache=True``), so a new process loads it instead of compiling it again.
"""

from __future__ import annotations

import types

import numba

__all__ = ["jit"]


def jit(func, inline: bool = False, **compiled):
    """``numba.njit(cache=True)`` of ``func``.

    ``compiled`` names global functions that ``func`` calls and gives their compiled versions
    (numba cannot call plain Python functions): ``jit(iso6358_flow,
    iso6358_mass_flow=jit(iso6358_mass_flow))``.  The public function stays plain numpy code.
    ``inline=True`` compiles it to be inlined into its compiled callers instead of called (for
    the right-hand side's parts: a call of its own takes and releases a reference to every
    array it is passed -- atomic counts that cost more than the arithmetic of a small
    function); an inlined function is part of its callers' cached code.
    """
    if compiled:
        env = dict(func.__globals__)
        env.update(compiled)
        func = types.FunctionType(func.__code__, env, func.__name__, func.__defaults__,
                                  func.__closure__)
    if inline:
        return numba.njit(inline="always")(func)
    return numba.njit(cache=True)(func)
