"""Closed forms for the ring (paper, section "Stability of a ring"): the untwisted ring in and
out of its plane, and the rapidly twisted ring by homogenisation.

Loads q R^3 / (E1 I1) for a bending stiffness A (in units of E1 I1) and torsional stiffness A3.
A mode of wavenumber n >= 2 (n = 0, 1 are rigid motions) buckles at

* in plane, pressure ("hydrostatic"):       A (n^2 - 1),
* in plane, force towards the axis ("axis"): A (n^2 - 1)^2 / (n^2 - 2),
* out of plane (both load models, Timoshenko & Gere):  A (n^2 - 1)^2 / (n^2 + A/A3).

Each increases with n for n >= 2, so the critical load is the n = 2 value: with m = n^2 >= 4,
d/dm (m - 1)^2/(m - 2) = (m - 1)(m - 3)/(m - 2)^2 > 0 and, for c = A/A3 >= 0,
d/dm (m - 1)^2/(m + c) = (m - 1)(m + 1 + 2c)/(m + c)^2 > 0 (``tests/test_ring_closed_forms.py``
scans n to confirm).  These are classical results, independent of the solvers
:mod:`spectral_rod.ring_stability` and :mod:`spectral_rod.ring_munder` (only the input checks
are shared), which are checked against them at N = 0 and nu = 1, and in the limit N -> infinity.

>>> in_plane_untwisted(1.0, "hydrostatic"), in_plane_untwisted(1.0, "axis")
(3.0, 4.5)
"""

from __future__ import annotations

from spectral_rod._validation import check_real, scalar_nu
from spectral_rod.ring_formula import check_e_ratio
from spectral_rod.ring_stability import check_load

__all__ = ["homogenised_limit", "in_plane_untwisted", "out_of_plane_supremum",
           "out_of_plane_untwisted"]


def _stiffness(value: object, name: str) -> float:
    return check_real(value, name, 0.0, 1.0e12, lo_open=True)


def in_plane_untwisted(A: float, load: str) -> float:
    """Untwisted ring, in plane: A (n^2 - 1) ("hydrostatic": pressure on the ring) or
    A (n^2 - 1)^2/(n^2 - 2) ("axis": force toward the axis), both increasing in n, so the
    critical n = 2 values 3 A and 4.5 A (module docstring)."""
    A = _stiffness(A, "A")
    return 3.0 * A if check_load(load) == "hydrostatic" else 4.5 * A


def out_of_plane_untwisted(A: float, A3: float) -> float:
    """Timoshenko & Gere: A (n^2 - 1)^2/(n^2 + A/A3) (both load models), increasing in n, so
    the critical n = 2 value 9 A/(4 + A/A3) (module docstring)."""
    A, A3 = _stiffness(A, "A"), _stiffness(A3, "A3")
    return 9.0 * A * A3 / (4.0 * A3 + A)  # = 9 A/(4 + A/A3) without overflow of A/A3


def out_of_plane_supremum(A: float) -> float:
    """sup over A3 of the out-of-plane load (A3 -> infinity): A (n^2 - 1)^2/n^2 at n = 2, 9A/4."""
    return 2.25 * _stiffness(A, "A")


def homogenised_limit(nu: float, e_ratio: float, load: str) -> float:
    """N -> infinity: the rotating bending stiffness homogenises to the isotropic harmonic mean
    2 A1 A2/(A1 + A2) (1-D homogenisation of the curvature energy), A3 = e (1 + nu) unchanged;
    the load is the smaller of the in-plane and out-of-plane loads of that ring."""
    nu, e_ratio = scalar_nu(nu), check_e_ratio(e_ratio)
    a_h = 2.0 * nu / (1.0 + nu)
    return min(in_plane_untwisted(a_h, load), out_of_plane_untwisted(a_h, e_ratio * (1.0 + nu)))
