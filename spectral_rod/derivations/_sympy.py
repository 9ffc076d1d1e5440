"""Helpers shared by the derivations: the arc length symbol, exact zero tests and the step check.

A derivation step is checked with :func:`check`, not with ``assert``: the checks must run under
``python -O`` too (``assert`` statements are stripped there), and a failure names the step.
"""

from __future__ import annotations

import sympy as sp

#: Arc length and the perturbation parameter (the same symbols in every derivation).
s = sp.Symbol("s", real=True)
eps = sp.Symbol("epsilon")


class DerivationError(AssertionError):
    """A checked step of a derivation does not hold (the algebra, or an equation, is wrong).

    Subclasses ``AssertionError`` (a failed check is a failed assertion), but is raised
    explicitly, so it is not disabled by ``python -O``. ``step`` names the failed step.
    """

    def __init__(self, step: str) -> None:
        super().__init__(f"derivation step failed: {step}")
        self.step = step


def check(condition: object, step: str) -> None:
    """Raise :class:`DerivationError` naming ``step`` unless ``condition`` is true."""
    if not condition:
        raise DerivationError(step)


def vec(*c: sp.Expr) -> sp.Matrix:
    """Column vector of the components c."""
    return sp.Matrix(c)


def d(v: sp.Matrix | sp.Expr, n: int = 1) -> sp.Matrix | sp.Expr:
    """n-th derivative with respect to the arc length s."""
    return sp.sympify(v).diff(s, n)


def z(expr: sp.Expr) -> bool:
    """Exact zero test: trig functions rewritten as exponentials cancel under expansion."""
    e = sp.expand(sp.expand(expr).rewrite(sp.exp))
    return e == 0 or sp.simplify(e) == 0


def zv(v: sp.Matrix) -> bool:
    """Every component of v is exactly zero (:func:`z`)."""
    return all(z(c) for c in v)
