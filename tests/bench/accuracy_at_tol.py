"""What a requested tol delivers: the measurements behind ``tuning.TRUNCATION_SHARE`` and
``tuning.LONG_TWIST``.

    python tests/bench/accuracy_at_tol.py

Reference: the characteristic equation in double precision (``method="characteristic"``, an
independent formulation; its own error <= eps (8 + |Omega|), 1.3e-14 at Omega(L) = 50).

1. The collocation part of the benchmarks' 200 x 200 map (Omega(L) < 50, nu in [1, 100]) at
   tol 1e-12: the largest error and the points above 1e-13 (the issue's bound).
2. 20,000 random points (Omega(L) < 50, nu up to 1e4, 2,000 with nu - 1 in [1e-3, 1]) at tol
   1e-4 ... 1e-12: the largest error and the points above tol / 10.
3. 4,000 random points, Omega(L) in [5, 20), nu in [1.001, 100], the pencil's quotient summed
   in double everywhere against extended precision everywhere (LONG_TWIST moved): per band of
   Omega(L), the largest error over the estimate's round-off part eps (32 + 0.3 Omega^2).

Docstrings and README quote what it prints (2026-12-05). A development tool, not a test (pytest
does not collect it); ``tests/test_accuracy_control.py`` checks a sample of (2).
"""

from __future__ import annotations

import numpy as np

import spectral_rod as sr
from spectral_rod.rod.collocation import eigensolver, quotient

EPS = float(np.finfo(float).eps)


def errors(tw: np.ndarray, nv: np.ndarray, tol: float) -> np.ndarray:
    """Relative errors of critical_load at tol against the characteristic equation."""
    ref = sr.critical_load(tw, nv, method="characteristic")
    return np.abs(sr.critical_load(tw, nv, tol=tol) / ref - 1)


def the_map() -> None:
    om, nu = (a.ravel() for a in np.meshgrid(np.linspace(0.0, 100.0, 200),
                                             np.linspace(1.0, 100.0, 200)))
    keep = om < 50
    err = errors(om[keep], nu[keep], 1e-12)
    print(f"map, collocation part ({keep.sum()} points), tol 1e-12: max {err.max():.2g}, "
          f"{(err > 1e-13).sum()} above 1e-13")


def random_points() -> None:
    rng = np.random.default_rng(5)
    tw, nv = rng.uniform(0, 50, 20000), 10 ** rng.uniform(0, 4, 20000)
    nv[:2000] = 1 + 10 ** rng.uniform(-3, 0, 2000)
    for tol in (1e-4, 1e-6, 1e-8, 1e-10, 1e-12):
        err = errors(tw, nv, tol)
        print(f"20,000 random points, tol {tol:.0e}: max {err.max():.2g}, "
              f"{(err > 0.1 * tol).sum()} above tol / 10")


def long_twist() -> None:
    rng = np.random.default_rng(7)
    tw, nv = rng.uniform(5, 20, 4000), rng.uniform(1.001, 100, 4000)
    roundoff = EPS * (32 + 0.3 * tw**2)
    ratio = {}
    limit = eigensolver.LONG_TWIST
    try:
        for name, value in (("double", np.inf), ("extended", 0.0)):
            for module in (eigensolver, quotient):  # every module that reads LONG_TWIST
                module.LONG_TWIST = value
            ratio[name] = errors(tw, nv, 1e-12) / roundoff
    finally:
        for module in (eigensolver, quotient):
            module.LONG_TWIST = limit
    for lo, hi in ((5, 10), (10, 13), (13, 16), (16, 20)):
        band = (tw >= lo) & (tw < hi)
        print(f"Omega(L) in [{lo}, {hi}): error / round-off part, quotient in double "
              f"{ratio['double'][band].max():.2f}, extended {ratio['extended'][band].max():.2f}")


if __name__ == "__main__":
    the_map()
    random_points()
    long_twist()
