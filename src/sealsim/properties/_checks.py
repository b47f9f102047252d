"""Input checks of the elastomer property functions: float arrays within a range.

A value that is not a finite number in the allowed range raises one
:class:`~sealsim.errors.InputError` that names the argument, the value and what is allowed.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from sealsim.errors import InputError

__all__: list[str] = []


def _range_text(lo: float | None, hi: float | None, lo_open: bool, hi_open: bool, unit: str) -> str:
    if lo is not None and hi is not None:
        return f"{lo:g} {'<' if lo_open else '<='} value {'<' if hi_open else '<='} {hi:g} {unit}"
    if lo is not None:
        return f"{'>' if lo_open else '>='} {lo:g} {unit}"
    if hi is not None:
        return f"{'<' if hi_open else '<='} {hi:g} {unit}"
    return "finite"


def _outside(arr: np.ndarray | float, lo: float | None, hi: float | None, lo_open: bool,
             hi_open: bool) -> np.ndarray | bool:
    """Mask of the values that are not finite or lie outside the (open or closed) range; for a
    float, one bool (without numpy: the scalar check of every time step)."""
    bad = not math.isfinite(arr) if isinstance(arr, float) else ~np.isfinite(arr)
    if lo is not None:
        bad |= (arr <= lo) if lo_open else (arr < lo)
    if hi is not None:
        bad |= (arr >= hi) if hi_open else (arr > hi)
    return bad


def _array(
    value: Any,
    name: str,
    unit: str,
    *,
    lo: float | None = None,
    hi: float | None = None,
    lo_open: bool = False,
    hi_open: bool = False,
) -> np.ndarray:
    """Float array of ``value``; InputError naming ``name`` if not finite or out of range."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(
            f"{name} must be a number or an array of numbers [{unit}]; got {value!r}"
        ) from exc
    if arr.ndim == 0 and not _outside(float(arr), lo, hi, lo_open, hi_open):
        return arr          # the common scalar call of a time step: no array reductions
    bad = _outside(arr, lo, hi, lo_open, hi_open)
    if np.any(bad):
        first = arr[bad].flat[0]
        n_bad = int(np.count_nonzero(bad))
        where = "" if arr.ndim == 0 else f" ({n_bad} of {arr.size} values, first shown)"
        raise InputError(
            f"{name} = {first:g} {unit}{where} is not allowed; allowed: "
            f"{_range_text(lo, hi, lo_open, hi_open, unit)}"
        )
    return arr


def _scalar(value: Any, name: str, unit: str, **kw: Any) -> float:
    arr = _array(value, name, unit, **kw)
    if arr.ndim != 0:
        raise InputError(
            f"{name} must be a single number [{unit}]; got an array of shape {arr.shape}"
        )
    return float(arr)


def _out(arr: np.ndarray) -> np.ndarray | float:
    """Return a Python float for a 0-d result, the array otherwise."""
    arr = np.asarray(arr)
    return float(arr) if arr.ndim == 0 else arr


def _broadcast(*arrays: np.ndarray, names: str) -> list[np.ndarray]:
    try:
        return list(np.broadcast_arrays(*arrays))
    except ValueError as exc:
        shapes = ", ".join(str(a.shape) for a in arrays)
        raise InputError(f"{names} cannot be broadcast together (shapes {shapes})") from exc
