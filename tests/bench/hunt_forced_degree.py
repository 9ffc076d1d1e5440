"""A random hunt for silent misses of forced collocation (``method="collocation"``), automatic
and with an explicit degree ``n``, at tol 1e-14 against 40-digit mpmath references (Eq.
``inst1``'s characteristic equation).

    python tests/bench/hunt_forced_degree.py [--points 1000] [--seed 37]

Points: |Omega(L)| log-uniform in [1e-3, 1e3], nu log-uniform in [1, 1e4] (a tenth with nu - 1
log-uniform in [1e-14, 1e-3]); a third solved at the automatic degree in one call, the rest each
at a random even degree in [16, 512] (the degrees collocation accepts beyond the few that
resolve nothing), one call per degree. A *silent miss* is a point whose error exceeds tol while
it is reported converged; an *estimate miss* a converged one whose error exceeds its own
estimate (a flagged point's estimate may only say that the mode is not resolved). The
script prints, for the automatic and the explicit part, the largest error, the largest error /
estimate and the counts, and exits 1 on any silent miss. The degree's part of the error model
(:func:`spectral_rod.rod.collocation.resolution.error_estimate`) is calibrated by it;
``tests/test_accuracy_control.py`` runs a sample at n = 448..512.
"""

from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from hunt_routes import COLUMNS, HEADER, HUNT_TOL, HuntResult, judge, reference, row

from spectral_rod import ConvergenceWarning, critical_load

#: The explicit degrees drawn: even, in [DEGREES[0], DEGREES[1]].
DEGREES = (16, 512)


def sample(points: int, rng: np.random.Generator
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Random (twist, nu, n) with n = 0 for the automatic degree (module docstring)."""
    twist = 10.0 ** rng.uniform(-3.0, 3.0, points)
    nu = 10.0 ** rng.uniform(0.0, 4.0, points)
    near = rng.random(points) < 0.1
    nu[near] = 1.0 + 10.0 ** rng.uniform(-14.0, -3.0, int(near.sum()))
    n = 2 * rng.integers(DEGREES[0] // 2, DEGREES[1] // 2 + 1, points)
    n[: points // 3] = 0
    return twist, nu, n


def solve(twist: np.ndarray, nu: np.ndarray, n: np.ndarray, tol: float):
    """p*, estimate and converged flag per point: the automatic part in one call, each
    explicit degree in one call."""
    p, est, ok = np.empty(twist.size), np.empty(twist.size), np.empty(twist.size, dtype=bool)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        for deg in np.unique(n):
            sel = np.flatnonzero(n == deg)
            res = critical_load(twist[sel], nu[sel], n=int(deg) or None, tol=tol,
                                method="collocation", full_output=True)
            p[sel], est[sel], ok[sel] = res.p_star, res.error_estimate, res.converged
    return p, est, ok


def hunt(points: int, seed: int = 37, tol: float = HUNT_TOL) -> list[HuntResult]:
    """Solve `points` random points (module docstring) at `tol`; compare with the references."""
    twist, nu, n = sample(points, np.random.default_rng([seed, 5]))
    p, est, ok = solve(twist, nu, n, tol)
    ref = np.array([reference(float(a), float(b)) for a, b in zip(twist, nu, strict=True)])
    err = np.abs(p / ref - 1.0)
    return [judge(part, err[sel], est[sel], ok[sel], twist[sel], nu[sel], tol)
            for part, sel in (("automatic n", n == 0), ("explicit n", n > 0))]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=37)
    args = parser.parse_args(argv)
    print(f"forced collocation, tol {HUNT_TOL:g}, {args.points} random points, seed {args.seed}")
    print(HEADER.format("part", *COLUMNS, w=14))
    silent = 0
    for r in hunt(args.points, args.seed):
        silent += r.silent_misses
        print(row(r, 14), flush=True)
    return 1 if silent else 0


if __name__ == "__main__":
    sys.exit(main())
