"""A random hunt for misses of collocation's error estimate at every tol, against 40-digit
mpmath references (Eq. ``inst1``'s characteristic equation): the evidence that the loose-tol
error model of :func:`spectral_rod.rod.collocation.resolution.error_estimate` stays a bound.

    python tests/bench/hunt_tol.py [--points 2000] [--seed 37]

Points: Omega(L) uniform in [0, 50] (seven tenths) or log-uniform in [50, 800] (the rest: where
the automatic degree still covers them, n <= 512 at every tol); nu log-uniform in [1, 1e4] (half)
or 1 + 10^u, u uniform in [-3, 4] (nu - 1 log-spaced). Each tol of TOLS solves all points in
one call of forced collocation (``method="collocation"``, the automatic degree), whose estimate
this is. A *silent miss* errs above tol while reported converged; an *estimate miss* is a
converged point whose error exceeds its own estimate. Per tol the script prints the largest
error, the largest error / estimate, both counts, the flagged points, and the largest error of
a converged point over tol (how close the knob delivers), and exits 1 on any silent or estimate
miss. ``tests/test_accuracy_control.py`` checks a sample in the default run.
"""

from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from hunt_routes import COLUMNS, HEADER, judge, reference, row

from spectral_rod import ConvergenceWarning, critical_load

TOLS = (1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12)


def sample(points: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Random (twist, nu) (module docstring)."""
    far = rng.random(points) < 0.3
    twist = np.where(far, 10.0 ** rng.uniform(np.log10(50.0), np.log10(800.0), points),
                     rng.uniform(0.0, 50.0, points))
    near = rng.random(points) < 0.5
    nu = np.where(near, 1.0 + 10.0 ** rng.uniform(-3.0, 4.0, points),
                  10.0 ** rng.uniform(0.0, 4.0, points))
    return twist, np.minimum(nu, 1e4)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=37)
    args = parser.parse_args(argv)
    twist, nu = sample(args.points, np.random.default_rng(args.seed))
    ref = np.array([reference(float(a), float(b)) for a, b in zip(twist, nu, strict=True)])
    print(f"{args.points} random points, seed {args.seed}, forced collocation, 40-digit "
          "references")
    print(HEADER.format("tol", *COLUMNS, w=10) + "  max err/tol (converged)")
    misses = 0
    for tol in TOLS:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ConvergenceWarning)
            res = critical_load(twist, nu, tol=tol, method="collocation", full_output=True)
        err = np.abs(res.p_star / ref - 1.0)
        ok = res.converged
        r = judge(f"{tol:g}", err, res.error_estimate, ok, twist, nu, tol)
        estimate_misses = int(np.sum(ok & (err > res.error_estimate)))
        misses += r.silent_misses + estimate_misses
        closest = float(np.max(err[ok]) / tol) if ok.any() else float("nan")
        print(row(r, 10) + f"  {closest:.3g}", flush=True)
    return 1 if misses else 0


if __name__ == "__main__":
    sys.exit(main())
