"""The measurements behind two empirical round-off models (2026-12-04), rerunnable:

    python tests/bench/measure_error_floors.py            # ~10 minutes on a shared 2-core machine

* the large-twist route's estimate eps (8 + |Omega|) (:func:`spectral_rod.rod.characteristic.
  double_error_estimate`): 3,000 random points, Omega(L) log-uniform in [50, 1e4], nu in
  [1, 1e4], against 40-digit roots (printed then: max err/(eps Omega) 0.577, err/estimate 0.532);
* the Rayleigh-Ritz floor eps (8 + 2 sqrt(nu) + |Omega|/40) (:func:`spectral_rod.rod.ritz.
  roundoff_floor`): random values for 300 s, Omega(L) in [400, 1000], nu - 1 in [1e-7, 1e-5]
  (then 1,589 values: |err| <= 29 eps, err/estimate <= 0.84, shortfall <= 0.57 floors, 2.9
  times the floor without the twist term).
"""

from __future__ import annotations

import time
import warnings

import numpy as np

import spectral_rod as sr
from spectral_rod.rod.ritz import roundoff_floor

EPS = float(np.finfo(float).eps)


def large_twist(points: int = 3000) -> None:
    rng = np.random.default_rng(20261204)
    om = np.exp(rng.uniform(np.log(50), np.log(1e4), points))
    nu = np.exp(rng.uniform(0, np.log(1e4), points))
    res = sr.critical_load(om, nu, full_output=True)
    ref = np.array([float(sr.characteristic_critical_load(float(a), float(b), dps=40).p_star)
                    for a, b in zip(om, nu, strict=True)])
    err = np.abs(res.p_star / ref - 1)
    print(f"large twist, {points} points: max err/(eps Omega) {np.max(err / (EPS * om)):.3f}, "
          f"max err/estimate {np.max(err / res.error_estimate):.3f}")


def ritz_floor(seconds: float = 300.0) -> None:
    rng, t0, rows = np.random.default_rng(7), time.time(), []
    while time.time() - t0 < seconds:
        om, nu = float(rng.uniform(400, 1000)), 1 + float(10 ** rng.uniform(-7, -5))
        fam = ("symmetric", "antisymmetric")[int(rng.integers(2))]
        r = sr.ritz_critical_load(om, nu, family=fam, full_output=True)
        err = r.p_star / float(sr.family_critical_load(fam, om, nu, dps=50).p_star) - 1
        rows.append((abs(err) / EPS, err / r.error_estimate, -err / roundoff_floor(nu, om),
                     abs(err) / (EPS * (8 + 2 * np.sqrt(nu)))))
    a = np.array(rows)
    print(f"ritz, {len(a)} values: max |err|/eps {a[:, 0].max():.1f}, err/estimate "
          f"{a[:, 1].max():.2f}, shortfall/floor {a[:, 2].max():.2f}, |err|/floor without the "
          f"twist term {a[:, 3].max():.2f}")


if __name__ == "__main__":
    warnings.simplefilter("ignore")
    large_twist()
    ritz_floor()
