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
from numba.core import cgutils
from numba.extending import intrinsic

__all__ = ["borrowed", "jit"]


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


@intrinsic
def borrowed(typingctx, array):
    """The array ``array`` without its reference count (compiled code only): the same data,
    shape and strides, no memory-info pointer -- as ``numba.carray`` of its data.

    Every compiled call that receives an array, and every row or slice taken of it, increments
    and decrements the array's reference count with atomic instructions, which serialise the
    processor's pipeline: with the ten tables of the right-hand side that is about a tenth of
    the integration's time.  An array without a memory-info pointer is not counted.  Only for
    arrays that live longer than everything made of them: the arguments of the compiled
    function that borrows them, whose caller holds them until it returns, and no borrowed array
    is stored or returned."""
    def codegen(context, builder, signature, args):
        source = context.make_array(signature.args[0])(context, builder, value=args[0])
        out = context.make_array(signature.return_type)(context, builder)
        for name in ("nitems", "itemsize", "data", "shape", "strides"):
            setattr(out, name, getattr(source, name))
        out.meminfo = cgutils.get_null_value(out.meminfo.type)
        out.parent = cgutils.get_null_value(out.parent.type)
        return out._getvalue()
    return array(array), codegen
