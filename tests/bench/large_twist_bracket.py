"""The remainder of the large-twist expansion to Omega^-4, which sizes the large-twist bracket
(:data:`spectral_rod.rod.characteristic.BRACKET_REMAINDER`).

    python tests/bench/large_twist_bracket.py [--points 4000] [--seed 3]

Each family's lowest root from the sign scan of the double-precision determinants
(:func:`spectral_rod.rod.characteristic.family_double_batch`, which does not use the expansion)
against :func:`spectral_rod.rod.closed_form.family_expansions`, at random points with Omega(L)
log-uniform in [20, 1e4] and nu log-uniform in [1, 1e4]. Prints max |p_family - expansion|
Omega^5 by band of Omega(L) (above ~1e3 the scan's own rounding, a few eps, dominates it) and the
fraction of points whose bracket (:func:`spectral_rod.rod.characteristic._bracketed_batch`) is
certified.
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

from spectral_rod.rod.characteristic import BRACKET_REMAINDER, _bracketed_batch, family_double_batch
from spectral_rod.rod.closed_form import family_expansions


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=4000)
    parser.add_argument("--seed", type=int, default=3)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    om = np.exp(rng.uniform(np.log(20.0), np.log(1e4), args.points))
    nv = np.exp(rng.uniform(0.0, np.log(1e4), args.points))
    scanned = family_double_batch(om, nv)
    worst = 0.0
    for name, p, asym in zip(("symmetric", "antisymmetric"), scanned, family_expansions(om, nv),
                             strict=True):
        r = np.abs(p - asym) * om**5
        print(f"{name}:")
        for lo, hi in ((20, 50), (50, 100), (100, 1e3), (1e3, 1e4)):
            m = (om >= lo) & (om < hi)
            print(f"  Omega(L) in [{lo:g}, {hi:g}): max |p - expansion| Omega^5 = {r[m].max():.4g}")
        worst = max(worst, float(r[om < 1e3].max()))
    large = om >= 50.0
    ok = _bracketed_batch(om[large], nv[large])[2]
    print(f"max below Omega(L) = 1e3: {worst:.4g} (BRACKET_REMAINDER = {BRACKET_REMAINDER:g}); "
          f"brackets certified at {ok.mean():.1%} of {ok.size} points with Omega(L) >= 50")
    return 0 if worst <= BRACKET_REMAINDER and ok.all() else 1


if __name__ == "__main__":
    sys.exit(main())
