"""A random hunt for silent misses of every forced route of ``critical_load`` and of the
automatic route at near-degenerate points, against 40-digit mpmath references.

    python tests/bench/hunt_routes.py [--points 1000] [--seed 37] [--routes ...]

For each route, `points` random points in the range the route accepts are solved in one call
at tol 1e-14 (the tightest tol) and compared with the lowest root of the characteristic
equation in mpmath (:func:`spectral_rod.rod.characteristic.characteristic_critical_load`, 40
digits). A *silent miss* is a point whose
error exceeds tol while it is reported converged; an *estimate miss* is a point whose error
exceeds its own error estimate. The script prints, per route, the largest error, the largest
error / estimate, the counts of both misses and of flagged (unconverged) points, and exits 1 if
any silent miss is found. ``tests/test_hunt_routes.py`` runs a small sample of it.

Ranges (each route's accepted range, the twist log-uniform so that small twist is sampled):
* characteristic: |Omega(L)| in [1e-3, 1e4], nu log-uniform in [1, 1e4];
* increment: |Omega(L)| in [1e-3, 1e3], nu - 1 log-uniform in [1e-14, 1e-3];
* ritz: |Omega(L)| in [1e-3, 1e3] (its cost grows like |Omega|^3), nu log-uniform in [1, 1e4];
* near-degenerate (automatic route): Omega(L) uniform in [0, 50], nu - 1 log-uniform in
  [1e-14, 1e-3].
"""

from __future__ import annotations

import argparse
import sys
import warnings
from dataclasses import dataclass

import numpy as np

from spectral_rod import ConvergenceWarning, critical_load
from spectral_rod.rod.characteristic import characteristic_critical_load

#: The tol of the hunt: the tightest accepted, where an estimate that falls short shows first.
HUNT_TOL = 1e-14
#: Digits of the references.
REFERENCE_DPS = 40
ROUTES = ("characteristic", "increment", "ritz", "near-degenerate")


@dataclass(frozen=True)
class HuntResult:
    """The hunt's evidence for one route."""

    route: str
    points: int
    max_error: float
    max_error_over_estimate: float
    silent_misses: int
    estimate_misses: int
    flagged: int
    worst: tuple[float, float]  # (twist, nu) of the largest error / estimate


def sample(route: str, points: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Random (twist, nu) in the range `route` accepts (module docstring)."""
    if route == "near-degenerate":
        return rng.uniform(0.0, 50.0, points), 1.0 + 10.0 ** rng.uniform(-14.0, -3.0, points)
    top = 4.0 if route == "characteristic" else 3.0
    twist = 10.0 ** rng.uniform(-3.0, top, points)
    if route == "increment":
        return twist, 1.0 + 10.0 ** rng.uniform(-14.0, -3.0, points)
    return twist, 10.0 ** rng.uniform(0.0, 4.0, points)


def reference(twist: float, nu: float) -> float:
    """p* from the characteristic equation at REFERENCE_DPS digits (as a float)."""
    return float(characteristic_critical_load(twist, nu, dps=REFERENCE_DPS).p_star)


def judge(route: str, err: np.ndarray, est: np.ndarray, ok: np.ndarray, twist: np.ndarray,
          nu: np.ndarray, tol: float) -> HuntResult:
    """The hunt's evidence from relative errors `err`, estimates `est` and converged flags `ok`:
    a silent miss errs above `tol` while reported converged; an estimate miss errs above its
    own estimate (flagged or not)."""
    ratio = err / np.maximum(est, np.finfo(float).tiny)
    worst = int(np.argmax(ratio))
    return HuntResult(route, err.size, float(err.max()), float(ratio.max()),
                      int(np.sum((err > tol) & ok)), int(np.sum(err > est)), int(np.sum(~ok)),
                      (float(twist[worst]), float(nu[worst])))


def row(r: HuntResult, width: int) -> str:
    """One printed line of a hunt's table."""
    return (f"{r.route:<{width}}{r.points:>7}{r.max_error:>11.2e}"
            f"{r.max_error_over_estimate:>13.3g}{r.silent_misses:>8}{r.estimate_misses:>9}"
            f"{r.flagged:>9}  ({r.worst[0]:.6g}, {r.worst[1]:.10g})")


HEADER = "{:<{w}}{:>7}{:>11}{:>13}{:>8}{:>9}{:>9}  worst (twist, nu)"
COLUMNS = ("points", "max error", "max err/est", "silent", "err>est", "flagged")


def hunt(route: str, points: int, seed: int = 37, tol: float = HUNT_TOL) -> HuntResult:
    """Solve `points` random points of `route` at `tol` in one call; compare with the reference."""
    rng = np.random.default_rng([seed, ROUTES.index(route)])
    twist, nu = sample(route, points, rng)
    method = "auto" if route == "near-degenerate" else route
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        res = critical_load(twist, nu, tol=tol, method=method, full_output=True)
    ref = np.array([reference(float(a), float(b)) for a, b in zip(twist, nu, strict=True)])
    err = np.abs(res.p_star / ref - 1.0)
    return judge(route, err, res.error_estimate, res.converged, twist, nu, tol)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=37)
    parser.add_argument("--routes", nargs="*", default=list(ROUTES), choices=ROUTES)
    args = parser.parse_args(argv)
    silent = 0
    print(f"tol {HUNT_TOL:g}, {args.points} random points a route, seed {args.seed}")
    print(HEADER.format("route", *COLUMNS, w=16))
    for route in args.routes:
        r = hunt(route, args.points, args.seed)
        silent += r.silent_misses
        print(row(r, 16), flush=True)
    return 1 if silent else 0


if __name__ == "__main__":
    sys.exit(main())
