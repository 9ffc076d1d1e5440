"""Ties of the mode family of Eq. ``inst1``: where the two families' lowest loads agree within
the accuracy a solve promises, which family a solver names is not a result, and
``python -m reproduce check`` compares the label as a tie (:class:`reproduce.compare.Tie`).

The loads come from the paper's characteristic equation per family in mpmath
(:func:`spectral_rod.family_critical_load`), not from the collocation solver that named the
family, and only for the rows whose label changed.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from reproduce.compare import Tie

__all__ = ["TIE_DPS", "families_tie", "family_tie"]

#: Digits of the per-family reference: the two loads must be resolved far below any tol.
TIE_DPS = 30


def families_tie(twist_angle: float, nu: float, tol: float) -> bool:
    """Whether the symmetric and antisymmetric families' lowest loads at (`twist_angle`, `nu`)
    agree within relative `tol` (so either may be named the lowest by a solve at that tol).

    >>> families_tie(1000.0, 1 + 1e-12, 1e-12), families_tie(3.0, 1.5, 1e-12)
    (True, False)
    """
    from spectral_rod import FAMILIES, family_critical_load

    low, high = sorted(float(family_critical_load(f, twist_angle, nu, dps=TIE_DPS).p_star)
                       for f in FAMILIES)
    return high - low <= tol * low


def family_tie(tol: float, twist: str = "twist_angle", nu: str = "nu") -> Tie:
    """The :class:`~reproduce.compare.Tie` rule of a family label in rows holding the twist
    and nu in columns `twist` and `nu`, solved at relative accuracy `tol`."""

    def tied(row: Mapping[str, Any]) -> bool:
        try:
            return families_tie(float(row[twist]), float(row[nu]), tol)
        except (KeyError, TypeError, ValueError):  # a garbled row: the label is compared exactly
            return False

    return Tie(tied, f"the families' loads agree within tol {tol:g}")
