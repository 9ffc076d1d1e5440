"""Closed forms for the ring (paper, section "Stability of a ring"): the untwisted ring in and
out of its plane, and the rapidly twisted ring by homogenisation.

Loads q R^3 / (E1 I1) for a bending stiffness A (in units of E1 I1) and torsional stiffness A3;
the minimum is over the wavenumber n >= 2 of the mode (n = 0, 1 are rigid motions). They are
independent of :mod:`spectral_rod.ring_stability` (classical results), which is checked against
them at N = 0 and nu = 1, and in the limit N -> infinity.

>>> in_plane_untwisted(1.0, "hydrostatic"), in_plane_untwisted(1.0, "axis")
(3.0, 4.5)
"""

from __future__ import annotations

import numpy as np

from spectral_rod._validation import check_choice, check_real, scalar_nu

__all__ = ["homogenised_limit", "in_plane_untwisted", "out_of_plane_supremum",
           "out_of_plane_untwisted"]

_N = np.arange(2, 60, dtype=float)  # the minima are at n = 2 or 3; 60 is ample


def _stiffness(value: object, name: str) -> float:
    return check_real(value, name, 0.0, 1.0e12, lo_open=True)


def in_plane_untwisted(A: float, load: str) -> float:
    """Untwisted ring, in-plane, min over n >= 2: A (n^2 - 1) (hydrostatic: pressure on the
    ring) and A (n^2 - 1)^2/(n^2 - 2) (force toward the axis); both at n = 2: 3 A and 4.5 A."""
    A = _stiffness(A, "A")
    check_choice(load, "load", ("hydrostatic", "axis"))
    vals = A * (_N**2 - 1) if load == "hydrostatic" else A * (_N**2 - 1) ** 2 / (_N**2 - 2)
    return float(vals.min())


def out_of_plane_untwisted(A: float, A3: float) -> float:
    """Timoshenko & Gere: A (n^2 - 1)^2/(n^2 + A/A3), min over n >= 2 (both load models)."""
    A, A3 = _stiffness(A, "A"), _stiffness(A3, "A3")
    return float(np.min(A * (_N**2 - 1) ** 2 / (_N**2 + A / A3)))


def out_of_plane_supremum(A: float) -> float:
    """sup over A3 of the out-of-plane load (A3 -> infinity): A min_n (n^2 - 1)^2/n^2 = 9A/4."""
    A = _stiffness(A, "A")
    return float(np.min(A * (_N**2 - 1) ** 2 / _N**2))


def homogenised_limit(nu: float, e_ratio: float, load: str) -> float:
    """N -> infinity: the rotating bending stiffness homogenises to the isotropic harmonic mean
    2 A1 A2/(A1 + A2) (1-D homogenisation of the curvature energy), A3 = e (1 + nu) unchanged;
    the load is the smaller of the in-plane and out-of-plane loads of that ring."""
    nu, e_ratio = scalar_nu(nu), check_real(e_ratio, "e_ratio", 1e-6, 1e6)
    a_h = 2.0 * nu / (1.0 + nu)
    return min(in_plane_untwisted(a_h, load), out_of_plane_untwisted(a_h, e_ratio * (1.0 + nu)))
