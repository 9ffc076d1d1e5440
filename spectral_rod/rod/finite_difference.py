r"""Second-order finite differences for Eq. ``inst1`` -- the method an engineer writes first.

Same equations and normalisation as :mod:`spectral_rod.rod.collocation` (paper, section "Stability
of a rectilinear rod", Eq. ``inst1``; s/L in [0, 1], Omega = omega30 L, nu = A2/A1 >= 1,
lambda = P L^2 / A1 = pi^2 p*):

    -omega1'' + Omega^2 omega1 + 2 nu Omega omega2'     = lambda omega1
    -nu omega2'' + nu Omega^2 omega2 - 2 Omega omega1'  = lambda omega2,   omega = 0 at s = 0, 1

(hinged ends <=> omega1 = omega2 = 0 at the ends). On the uniform grid s_j = j h, h = 1/N,
the unknowns are omega at the N - 1 interior points, with the central differences
(w_{j+1} - 2 w_j + w_{j-1}) / h^2 and (w_{j+1} - w_{j-1}) / (2 h): truncation error O(h^2),
eigenvalue error ~ C(Omega) h^2, round-off ~ eps / h^2 (the matrix norm is 4 / h^2).

The central first difference D1 is antisymmetric, so with W = diag(1, nu) the scaled operator
W^(1/2) L W^(-1/2) = [[-D2 + Omega^2, 2 sqrt(nu) Omega D1], [-2 sqrt(nu) Omega D1,
nu (-D2 + Omega^2)]] is symmetric (the discrete form of the self-adjointness of ``inst1``), and
its lowest eigenvalue is found by sparse shift-and-invert Lanczos (``scipy.sparse.linalg.eigsh``)
with the shift 0.95 pi^2 below every physical eigenvalue (p* >= 1).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import eigsh

from spectral_rod._validation import check_int, scalar_nu, scalar_twist
from spectral_rod.rod.families import SHIFT

#: Largest grid (the sparse factorisation of 2^21 unknowns takes seconds and ~1 GB).
MAX_INTERVALS = 1 << 20



def fd_operator(twist_angle: float, nu: float, intervals: int) -> sp.csc_matrix:
    """The symmetric scaled operator W^(1/2) L W^(-1/2) of ``inst1`` on N = `intervals` cells.

    Unknowns: (omega1, sqrt(nu) omega2) at the interior points s_j = j / N, j = 1..N-1.
    """
    n = int(intervals)
    if n < 4:
        raise ValueError(f"intervals must be an integer >= 4, got {intervals!r}")
    h = 1.0 / n
    m = n - 1
    ones = np.ones(m - 1)
    d2 = sp.diags([ones, -2.0 * np.ones(m), ones], [-1, 0, 1]) / h**2
    d1 = sp.diags([-ones, ones], [-1, 1]) / (2.0 * h)
    eye = sp.identity(m)
    om, root_nu = float(twist_angle), math.sqrt(float(nu))
    return sp.bmat([[-d2 + om**2 * eye, 2.0 * root_nu * om * d1],
                           [-2.0 * root_nu * om * d1, nu * (-d2 + om**2 * eye)]],
                          format="csc")


def fd_critical_load(twist_angle: float, nu: float, intervals: int) -> float:
    """p* = lambda_min / pi^2 of the finite-difference discretisation with N = `intervals`.

    Relative error ~ C h^2 (h = 1/N) until round-off ~ eps N^2 takes over (see the
    ``convergence`` scene); no error control -- that is the point of the comparison.

    Parameters
    ----------
    twist_angle : float
        Omega(L) = omega30 L in radians (p* is even in it).
    nu : float
        I2/I1 >= 1.
    intervals : int
        Number N of grid intervals on s/L in [0, 1], 4 <= N <= ``MAX_INTERVALS``.

    Returns
    -------
    float
        The discrete critical load, p* to O(h^2).

    Examples
    --------
    Halving h quarters the error against collocation (an independent discretisation):

    >>> import spectral_rod as sr
    >>> p = sr.critical_load(5.0, 1.5)
    >>> e100 = abs(fd_critical_load(5.0, 1.5, 100) / p - 1)
    >>> e200 = abs(fd_critical_load(5.0, 1.5, 200) / p - 1)
    >>> round(e100 / e200, 1)
    4.0
    """
    om, nu = scalar_twist(twist_angle), scalar_nu(nu)
    op = fd_operator(abs(om), nu, check_int(intervals, "intervals", 4, MAX_INTERVALS))
    lam = eigsh(op, k=1, sigma=SHIFT, which="LM", return_eigenvectors=False,
                v0=np.ones(op.shape[0]))
    return float(lam[0] / math.pi**2)
