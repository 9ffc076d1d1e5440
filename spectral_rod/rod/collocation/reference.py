r"""The reference for the collocation eigenvalue of Eq. ``inst1``: the full ``eig`` of the
inverse pencil A^{-1} B with the physical-eigenvalue rule.

Choosing the physical eigenvalue (the rule)
-------------------------------------------
The continuous spectrum is real and >= pi^2. Collocation adds spurious eigenvalues that are
complex or very large (theta = 1/lambda near 0). The rule: from each family keep theta with
|Im theta| <= IMAG_REL |theta| and Re theta > 0 and take the largest (the smallest lambda); p*
is the smaller of the two families. The engine (:mod:`.eigensolver`) returns the eigenvalue
nearest above SHIFT, which is the rule's choice unless a spurious eigenvalue is nearer to SHIFT;
there the iteration is rejected and :func:`solve_family_eig` decides. It is also the test
reference of the engine (``tests/test_accuracy_control.py``, ``tests/test_two_solvers.py``).
"""

from __future__ import annotations

import math
from typing import cast

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.collocation.discretisation import family_operator
from spectral_rod.rod.collocation.resolution import mode_tails

__all__ = ["ISOLATION_GAP", "lowest_gap", "physical_eig", "solve_family_eig"]


#: Eigenvalues with |Im| above this fraction of |lambda| are complex, i.e. not physical.
IMAG_REL = 1.0e-8


def _lowest_physical(theta: NDArray[np.complex128]) -> NDArray[np.int_]:
    """Index of the largest real positive theta = 1/lambda in each row (the rule above)."""
    ok = (np.abs(theta.imag) <= IMAG_REL * np.abs(theta)) & (theta.real > 0)
    return np.argmax(np.where(ok, theta.real, -np.inf), axis=-1)


def physical_eig(m: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Largest real positive theta of each matrix and its eigenvector by full ``eig`` (the rule).

    theta = nan where no eigenvalue passes the rule.
    """
    theta, vec = np.linalg.eig(m)
    idx = _lowest_physical(theta)
    rows = np.arange(theta.shape[0])
    th = theta[rows, idx]
    valid = (np.abs(th.imag) <= IMAG_REL * np.abs(th)) & (th.real > 0)
    return np.where(valid, th.real, np.nan), vec[rows, :, idx].real


def solve_family_eig(n: int, family: str, twist: NDArray[np.float64], nu: NDArray[np.float64]
                      ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """:func:`solve_family` by the full ``eig`` of A^{-1} B and the rule (the reference path).

    Unlike the iteration it needs no gap below the family's next eigenvalue (but its round-off
    is larger: the inverse pencil carries cond(A) ~ n^4)."""
    op = family_operator(n, family)
    a, b = op.pencil(twist, nu)
    # B broadcast to A's stack: numpy < 2.0 would read a (m, m) right-hand side against a
    # (k, m, m) stack as a stack of m-vectors, not as one right-hand matrix per system
    theta, vec = physical_eig(cast(NDArray[np.float64],
                                   np.linalg.solve(a, np.broadcast_to(b, a.shape))))
    valid = np.isfinite(theta) & (theta > 0)
    lam = np.where(valid, 1.0 / np.where(valid, theta, 1.0), np.inf)
    return lam, np.where(valid, mode_tails(op, vec), np.inf), vec


#: The family's lowest eigenvalue counts as isolated, so that the iteration's convergence test
#: holds, if the next physical one is at least this far above it, relatively: the test passes a
#: mixed vector once the gap is below ~sqrt(rtol / lambda) (2e-8 at POWER_RTOL); a margin of 50.
ISOLATION_GAP = 1e-6


def lowest_gap(n: int, family: str, twist: float, nu: float) -> tuple[float, float]:
    """(lambda_1, (lambda_2 - lambda_1) / lambda_1) of one point: the family's two lowest
    physical eigenvalues by the full ``eig`` of A^{-1} B and the rule (inf gap if only one)."""
    a, b = family_operator(n, family).pencil(np.array([twist]), np.array([nu]))
    theta = np.linalg.eigvals(np.linalg.solve(a[0], b))
    ok = (np.abs(theta.imag) <= IMAG_REL * np.abs(theta)) & (theta.real > 0)
    lam = np.sort(1.0 / theta.real[ok])
    if not lam.size:
        return math.inf, math.inf
    return float(lam[0]), float((lam[1] - lam[0]) / lam[0]) if lam.size > 1 else math.inf
