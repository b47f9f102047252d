"""Derived case values: small arithmetic expressions of a study's factors, with units.

A study may set a case field from its factors, e.g. the squeeze of an O-ring from sampled cord
diameter and groove depth::

    [set]
    "seals.rod.map.structure_case.load.squeeze" = "= [1 - groove_depth / cord_diameter]"

An expression (after ``=``) may use the factor names, numbers, ``+ - * / **``, parentheses,
``[...]`` lists and the functions ``min``, ``max``, ``abs``, ``sqrt``.  Factors with units are
pint quantities, so ``groove_depth / cord_diameter`` is a pure number even when one is in mm
and the other in µm.  Nothing else is evaluated: no attributes, no other names, no calls.

The work an expression can cause is bounded, so a slip or a hostile study file is refused in
microseconds instead of hanging or exhausting the memory: at most :data:`MAX_LENGTH`
characters and :data:`MAX_DEPTH` levels of nesting; numbers are floats, so a power overflows
instead of computing a huge integer, and an exponent is at most :data:`MAX_EXPONENT` in
magnitude; a list (``[x] * 3``) holds at most :data:`MAX_ITEMS` values.  (A general evaluator
such as simpleeval bounds powers and sizes too, but allows attribute access and string
operations that a case value never needs, and does not bound the nesting.)
"""

from __future__ import annotations

import ast
import math
import operator
from typing import Any

from sealsim.errors import InputError
from sealsim.units import ureg

__all__ = ["MAX_DEPTH", "MAX_EXPONENT", "MAX_ITEMS", "MAX_LENGTH", "case_value",
           "check_expression", "evaluate"]

#: longest expression [characters]
MAX_LENGTH = 1000
#: deepest nesting of operations, calls and lists (``a + b + c`` is 2 levels)
MAX_DEPTH = 50
#: largest magnitude of an exponent (``x ** 2``, ``x ** (1/3)``)
MAX_EXPONENT = 64.0
#: most values in a list an expression gives
MAX_ITEMS = 10_000


def _power(base, exponent):
    x = exponent.to("dimensionless").magnitude if isinstance(exponent, ureg.Quantity) \
        else exponent
    if isinstance(x, list) or not abs(x) <= MAX_EXPONENT:
        raise InputError(f"the exponent {exponent!r} is out of range: at most {MAX_EXPONENT:g} "
                         "in magnitude")
    return operator.pow(base, x)


def _times(a, b):
    if isinstance(a, list) or isinstance(b, list):
        items, n = (a, b) if isinstance(a, list) else (b, a)
        if isinstance(n, list) or float(n) != int(n) or not 0 <= n * len(items) <= MAX_ITEMS:
            raise InputError(f"a list can be repeated by a whole number, giving at most "
                             f"{MAX_ITEMS} values (got {len(items)} values x {n!r})")
        return items * int(n)
    return operator.mul(a, b)


def _plus(a, b):
    if isinstance(a, list) and isinstance(b, list) and len(a) + len(b) > MAX_ITEMS:
        raise InputError(f"a list may hold at most {MAX_ITEMS} values")
    return operator.add(a, b)


_BINARY = {ast.Add: _plus, ast.Sub: operator.sub, ast.Mult: _times,
           ast.Div: operator.truediv, ast.Pow: _power}
_UNARY = {ast.UAdd: operator.pos, ast.USub: operator.neg}


def _sqrt(x):
    return x ** 0.5


_FUNCTIONS = {"min": min, "max": max, "abs": abs, "sqrt": _sqrt}


def check_expression(text: str, names: set[str], where: str) -> ast.Expression:
    """Parse an expression and check that it uses only allowed syntax and known names, and
    is at most :data:`MAX_LENGTH` characters long and :data:`MAX_DEPTH` levels deep.

    Examples
    --------
    >>> check_expression(" + ".join(["h"] * 60), {"h"}, "[set] x")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: [set] x: the expression nests more than 50 operations, calls or \
lists; split it or simplify it
    """
    if len(text) > MAX_LENGTH:
        raise InputError(f"{where}: the expression is {len(text)} characters long; at most "
                         f"{MAX_LENGTH} are allowed")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        raise InputError(f"{where}: {text!r} is not a valid expression ({exc.msg})") from None
    except (RecursionError, MemoryError):
        tree = None
    if tree is None or _depth(tree) > MAX_DEPTH:
        raise InputError(f"{where}: the expression nests more than {MAX_DEPTH} operations, "
                         "calls or lists; split it or simplify it")
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            if node.id not in names and node.id not in _FUNCTIONS:
                raise InputError(f"{where}: {node.id!r} in {text!r} is not a factor; known "
                                 f"factors: {', '.join(sorted(names)) or '(none)'}")
        elif isinstance(node, ast.Call):
            if not (isinstance(node.func, ast.Name) and node.func.id in _FUNCTIONS) \
                    or node.keywords:
                raise InputError(f"{where}: only {', '.join(_FUNCTIONS)} may be called in "
                                 f"{text!r}")
        elif isinstance(node, ast.Constant):
            if not isinstance(node.value, int | float) or isinstance(node.value, bool):
                raise InputError(f"{where}: {node.value!r} in {text!r}: only numbers are "
                                 "allowed as constants")
            if not _finite(node.value):  # 1e999, or an integer beyond floats
                raise InputError(f"{where}: a number in the expression is not finite (larger "
                                 "than 1.8e308)")
        elif not isinstance(node, ast.Expression | ast.BinOp | ast.UnaryOp | ast.List
                            | ast.Tuple | ast.Load | ast.operator | ast.unaryop):
            raise InputError(f"{where}: {type(node).__name__} is not allowed in {text!r}")
        if isinstance(node, ast.BinOp) and type(node.op) not in _BINARY:
            raise InputError(f"{where}: operator {type(node.op).__name__} is not allowed in "
                             f"{text!r}")
        if isinstance(node, ast.UnaryOp) and type(node.op) not in _UNARY:
            raise InputError(f"{where}: operator {type(node.op).__name__} is not allowed in "
                             f"{text!r}")
    return tree


def _finite(number: int | float) -> bool:
    try:
        return math.isfinite(float(number))
    except OverflowError:
        return False


def _depth(tree: ast.AST) -> int:
    """Levels of operations, calls and lists (iterative: a deep tree cannot overflow)."""
    deepest, stack = 0, [(tree, 0)]
    while stack:
        node, depth = stack.pop()
        if isinstance(node, ast.BinOp | ast.UnaryOp | ast.Call | ast.List | ast.Tuple):
            depth += 1
            deepest = max(deepest, depth)
        stack.extend((child, depth) for child in ast.iter_child_nodes(node))
    return deepest


def evaluate(tree: ast.Expression, values: dict[str, Any]) -> Any:
    """Value of a checked expression (:func:`check_expression`) for the given factor values.

    Examples
    --------
    >>> tree = check_expression("[1 - h / d]", {"h", "d"}, "set")
    >>> value = evaluate(tree, {"h": ureg.Quantity(1.76, "mm"), "d": ureg.Quantity(2.0, "mm")})
    >>> [round(float(v.magnitude), 6) for v in value]
    [0.12]
    """
    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant):
            return float(node.value)   # floats: a power overflows instead of growing forever
        if isinstance(node, ast.Name):
            return values[node.id] if node.id in values else _FUNCTIONS[node.id]
        if isinstance(node, ast.BinOp):
            return _BINARY[type(node.op)](ev(node.left), ev(node.right))
        if isinstance(node, ast.UnaryOp):
            return _UNARY[type(node.op)](ev(node.operand))
        if isinstance(node, ast.List | ast.Tuple):
            return [ev(e) for e in node.elts]
        if isinstance(node, ast.Call):
            return ev(node.func)(*[ev(a) for a in node.args])
        raise InputError(f"{type(node).__name__} is not allowed")  # pragma: no cover

    return ev(tree)


def case_value(value: Any) -> Any:
    """An expression's value as a case-file value: ``"1.76 mm"``, a number, or a list.

    Examples
    --------
    >>> case_value(ureg.Quantity(1.5, "mm"))
    '1.5 mm'
    >>> case_value(ureg.Quantity(3.0, "mm") / ureg.Quantity(2.0, "m"))
    0.0015
    """
    if isinstance(value, list):
        return [case_value(v) for v in value]
    if isinstance(value, ureg.Quantity):
        if value.dimensionless:
            return float(value.to("dimensionless").magnitude)
        magnitude = float(value.magnitude)
        if not math.isfinite(magnitude):
            raise InputError(f"the expression gives {magnitude!r}")
        return f"{magnitude!r} {value.units:~}"
    if isinstance(value, int | float) and not isinstance(value, bool):
        if not math.isfinite(value):
            raise InputError(f"the expression gives {value!r}")
        return float(value)
    raise InputError(f"the expression gives {value!r}, not a number or a quantity")
