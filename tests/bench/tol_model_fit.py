"""The fit behind ``resolution.ERR_QUADRATIC`` and ``TAIL_UNRESOLVED``: the quadratic term of
collocation's error model, which decides the degree at loose tols.

    python tests/bench/tol_model_fit.py

Grid: Omega(L) in {0, 0.5, ..., 49.5}, nu in 14 values from 1.0011 to 1e4, every even degree
8..60 (37,800 cases); reference: the characteristic equation in double precision (an
independent formulation; its own error <= eps (8 + |Omega|), far below the errors fitted here,
which are taken where they exceed 1e-13). It prints, for tails below TAIL_UNRESOLVED and below
0.3, the largest (error - ERR_LINEAR tail) / (n tail)^2 (the coefficient the model needs; its
ratio to ERR_QUADRATIC is the safety factor), the same per degree, and the largest error over
the model's tail part. ``resolution.error_estimate``'s docstring quotes what it prints. A
development tool, not a test (pytest does not collect it).
"""

from __future__ import annotations

import numpy as np

import spectral_rod as sr
from spectral_rod.rod.collocation.driver import pick_family
from spectral_rod.rod.collocation.eigensolver import solve_points
from spectral_rod.rod.collocation.resolution import (
    ERR_LINEAR,
    ERR_QUADRATIC,
    TAIL_UNRESOLVED,
    truncation_error,
)

NUS = (1.0011, 1.002, 1.01, 1.05, 1.1, 1.3, 1.5, 2.0, 4.0, 10.0, 30.0, 100.0, 1000.0, 1e4)
DEGREES = np.arange(8, 62, 2)


def grid() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tails and relative errors (degrees x points) on the grid, and the degrees as an array of
    the same shape."""
    om, nu = (a.ravel() for a in np.meshgrid(np.arange(0.0, 50.0, 0.5), NUS))
    ref = sr.critical_load(om, nu, method="characteristic")
    tails, errors = [], []
    for n in DEGREES:
        lam, family_tails, _ = solve_points(int(n), om, nu, 1e-14)
        p, _, tail = pick_family(lam, family_tails)
        tails.append(tail)
        errors.append(np.abs(p / ref - 1.0))
    tails_a = np.array(tails)
    return tails_a, np.array(errors), np.broadcast_to(DEGREES[:, None], tails_a.shape)


def needed_coefficient(tails, errors, degrees, below: float) -> np.ndarray:
    """(error - ERR_LINEAR tail) / (n tail)^2 where the tail is below `below` and the error above
    1e-13 (else -inf)."""
    sel = (tails < below) & (errors > 1e-13)
    with np.errstate(divide="ignore", invalid="ignore"):
        need = (errors - ERR_LINEAR * tails) / (degrees * tails) ** 2
    return np.where(sel, need, -np.inf)


def main() -> None:
    tails, errors, degrees = grid()
    print(f"{tails.size} cases; ERR_LINEAR {ERR_LINEAR:g}, ERR_QUADRATIC {ERR_QUADRATIC:g}, "
          f"TAIL_UNRESOLVED {TAIL_UNRESOLVED:g}")
    for below in (TAIL_UNRESOLVED, 0.3):
        need = needed_coefficient(tails, errors, degrees, below)
        i = np.unravel_index(np.argmax(need), need.shape)
        print(f"tail < {below:g}: needed coefficient {need.max():.3g} (safety factor "
              f"{ERR_QUADRATIC / need.max():.2f}) at n = {degrees[i]}, tail {tails[i]:.2e}")
    need = needed_coefficient(tails, errors, degrees, TAIL_UNRESOLVED)
    print("per degree:", ", ".join(f"{n}: {v:.2g}" for n, v in zip(DEGREES, need.max(axis=1),
                                                                     strict=True)
                                   if np.isfinite(v)))
    nus = np.broadcast_to(np.meshgrid(np.arange(0.0, 50.0, 0.5), NUS)[1].ravel(), need.shape)
    print("per nu:", ", ".join(f"{v:g}: {need[nus == v].max():.2g}" for v in NUS))
    part = truncation_error(tails, degrees)
    ok = np.isfinite(part) & (errors > 1e-13)
    print(f"error / tail part: max {np.max(errors[ok] / part[ok]):.3g} (tail < "
          f"{TAIL_UNRESOLVED:g}, error > 1e-13)")


if __name__ == "__main__":
    main()
