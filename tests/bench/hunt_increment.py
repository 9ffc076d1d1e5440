"""A random hunt of :func:`spectral_rod.critical_load_increment` over its documented range
against mpmath references: p* - 1 to GAIN_TOL relative?

    python tests/bench/hunt_increment.py [--points 1000] [--seed 36]

Points: nu - 1 log-uniform in [1e-10, 1e4], |Omega(L)| log-uniform in [1e-6, 1e3] (the
function's range; the increment's leading behaviour (nu - 1) Omega^2 makes the small values the
hard ones). Reference: the lowest root of the characteristic equation in mpmath
(:func:`spectral_rod.rod.characteristic.characteristic_critical_load`) at REFERENCE_DPS digits plus
the digits p* - 1 lies below 1, so that p* - 1 keeps >= 30 significant digits. Prints the
largest relative error of p* - 1, the number of points above GAIN_TOL, the worst points and
the error by decade of nu - 1 and of Omega(L); exits 1 if any point misses.
``tests/test_increment.py`` runs a small sample of it.
"""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass

import numpy as np

from spectral_rod import critical_load_increment
from spectral_rod.rod.characteristic import characteristic_critical_load

#: The accuracy the hunt checks (issue 37 item 6).
GAIN_TOL = 1e-12
REFERENCE_DPS = 30


@dataclass(frozen=True)
class IncrementHunt:
    """The hunt's evidence: points, relative errors of p* - 1, and the points' coordinates."""

    twist: np.ndarray
    nu: np.ndarray
    error: np.ndarray

    @property
    def misses(self) -> int:
        return int(np.sum(self.error > GAIN_TOL))


def sample(points: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Random (twist, nu) over the documented range (module docstring)."""
    return 10.0 ** rng.uniform(-6.0, 3.0, points), 1.0 + 10.0 ** rng.uniform(-10.0, 4.0, points)


def reference_gain(twist: float, nu: float, gain: float) -> float:
    """p* - 1 from the mpmath characteristic equation, at REFERENCE_DPS digits plus those that
    p* - 1 (`gain`, the value under test, sets only the working precision) lies below 1."""
    dps = REFERENCE_DPS + max(0, math.ceil(-math.log10(max(gain, 1e-300))))
    with_digits = characteristic_critical_load(twist, nu, dps=min(dps, 200)).p_star
    return float(with_digits - 1)


def hunt(points: int, seed: int = 36) -> IncrementHunt:
    """critical_load_increment at `points` random points in one call, against the references."""
    twist, nu = sample(points, np.random.default_rng(seed))
    gain = critical_load_increment(twist, nu)
    ref = np.array([reference_gain(float(a), float(b), float(g))
                    for a, b, g in zip(twist, nu, gain, strict=True)])
    return IncrementHunt(twist, nu, np.abs(gain / ref - 1.0))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=36)
    args = parser.parse_args(argv)
    h = hunt(args.points, args.seed)
    print(f"critical_load_increment: {args.points} random points, seed {args.seed}: max relative "
          f"error of p* - 1 {h.error.max():.3g}; {h.misses} above {GAIN_TOL:g}")
    for i in np.argsort(h.error)[-5:][::-1]:
        print(f"  twist {h.twist[i]:.6g}, nu - 1 {h.nu[i] - 1:.6g}: {h.error[i]:.3g}")
    e = np.log10(h.nu - 1.0)
    for lo in range(-10, 4, 2):
        m = (e >= lo) & (e < lo + 2)
        print(f"  nu - 1 in [1e{lo}, 1e{lo + 2}): {m.sum():4d} points, max {h.error[m].max():.3g}")
    w = np.log10(h.twist)
    for lo in range(-6, 3, 2):
        m = (w >= lo) & (w < lo + 2)
        if m.any():
            print(f"  Omega in [1e{lo}, 1e{lo + 2}): {m.sum():4d} points, max "
                  f"{h.error[m].max():.3g}")
    return 1 if h.misses else 0


if __name__ == "__main__":
    sys.exit(main())
