"""The two mode families of the hinged straight rod (Eq. ``inst1``), and the rigorous bounds.

Reflection about mid-span, s -> 1 - s, maps solutions of Eq. ``inst1`` to solutions with
(omega1, omega2)(s) -> (omega1, -omega2)(1 - s). Every mode therefore has a definite parity:

* ``"symmetric"``: omega1 even, omega2 odd about s = 1/2 (the family of Euler's mode);
* ``"antisymmetric"``: omega1 odd, omega2 even.

Bounds (Rayleigh quotient of the energy, A1 <= A2): 1 <= p* <= (1 + nu)/2 (Wirtinger below,
planar trial modes above), and each family's lowest load lies in [1, nu]. Every physical
eigenvalue lambda = pi^2 p is therefore >= pi^2, and :data:`SHIFT` = 0.95 pi^2 lies below all of
them: the shift of every shift-and-invert iteration in the package.
"""

from __future__ import annotations

import math

from spectral_rod._validation import check_choice, scalar_nu

__all__ = ["CLOSE_REL", "FAMILIES", "FAMILY_DTYPE", "SHIFT", "TIE_REL", "check_family",
           "euler_loads", "p_star_bounds"]

#: The mode families' labels (dimensionless), by the parity of (omega1, omega2) about
#: mid-span: "symmetric" (omega1 even, omega2 odd; Euler's mode) and "antisymmetric".
FAMILIES = ("symmetric", "antisymmetric")
#: The numpy string dtype of arrays of family names (every entry point returns it).
FAMILY_DTYPE = f"<U{max(map(len, FAMILIES))}"
#: Shift below every physical eigenvalue lambda = pi^2 p >= pi^2 (shift-and-invert iterations).
SHIFT = 0.95 * math.pi**2
#: The family rule's relative margins (:func:`spectral_rod.rod.collocation.driver.pick_family`):
#: the antisymmetric family is the lowest only if it is below the symmetric one by more than
#: TIE_REL (a tie to round-off goes to the symmetric family); within CLOSE_REL of each other
#: either could be the lowest, so both must be resolved (and the eigensolvers stop the
#: antisymmetric iteration early only where it is above 1 + CLOSE_REL times the symmetric
#: eigenvalue).
TIE_REL, CLOSE_REL = 1e-14, 1e-6


def check_family(family: object, name: str = "family") -> str:
    """`family` if it is one of :data:`FAMILIES`, else TypeError/ValueError naming them."""
    return check_choice(family, name, FAMILIES)


def p_star_bounds(nu: float) -> tuple[float, float]:
    """The rigorous bounds (1, (1 + nu)/2) of p* for nu = I2/I1 >= 1.

    Returns
    -------
    tuple of two float
        (lower, upper) bound of p*.

    Examples
    --------
    >>> p_star_bounds(1.5)
    (1.0, 1.25)
    """
    return 1.0, (1.0 + scalar_nu(nu)) / 2.0


def euler_loads(family: str, nu: float, top: float) -> list[float]:
    """The family's loads p at zero twist up to `top`, ascending: the uncoupled Euler loads
    (omega1 with j half-waves: p = j^2; omega2: p = nu j^2), j odd for omega1 and even for omega2
    in the symmetric family, the other way round in the antisymmetric one. Where two coincide
    (antisymmetric 4 = nu), a small twist splits them into two roots ~Omega apart.

    >>> euler_loads("antisymmetric", 4.0, 10.0)
    [4.0, 4.0]
    """
    first = 1 if family == "symmetric" else 2  # omega1's half-waves: odd / even
    loads: list[float] = [j * j for j in range(first, math.isqrt(int(top)) + 2, 2)]
    loads += [nu * j * j for j in range(3 - first, math.isqrt(int(top / nu)) + 2, 2)]
    return sorted(float(p) for p in loads if p <= top)
