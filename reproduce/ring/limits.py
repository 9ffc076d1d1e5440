"""The ring verdicts' limits beyond the scanned range, in closed form
(:mod:`spectral_rod.ring.closed_forms`): N -> infinity (homogenisation: the rotating section
bends like an isotropic one of harmonic-mean stiffness 2 A1 A2/(A1 + A2)) and nu -> infinity.

* N -> infinity at fixed nu: q_cr(N) -> :func:`spectral_rod.homogenised_limit`, against the
  untwisted q_cr(0) = :func:`spectral_rod.untwisted_critical_load`; twist of many turns raises the
  load iff the first exceeds the second, i.e. above :func:`large_twist_threshold`.
* nu -> infinity at fixed e: A3 = e (1 + nu) -> infinity and the harmonic mean -> 2 A1, so
  q_cr(0) -> the in-plane load of A1 (the out-of-plane one grows like nu) and q_cr(N -> infinity)
  -> min(in-plane load of 2 A1, out-of-plane supremum of 2 A1): :func:`large_anisotropy_limits`.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import scipy.optimize

from spectral_rod import (
    homogenised_limit,
    in_plane_untwisted,
    out_of_plane_supremum,
    untwisted_critical_load,
)

#: Upper end of the search for the large-twist threshold (nu = I2/I1).
NU_SEARCH_MAX = 1.0e4  # the largest nu the package accepts


def large_twist_gain(nu: float, e_ratio: float, load: str) -> float:
    """q_cr(N -> infinity)/q_cr(0) - 1 at (nu, e, load), both in closed form."""
    return (homogenised_limit(nu, e_ratio, load) / untwisted_critical_load(nu, e_ratio, load)
            - 1.0)


@functools.cache  # a pure function of two scalars, asked for by every evaluation of the rows
def large_twist_threshold(e_ratio: float, load: str) -> float:
    """The nu above which a twist of many turns (N -> infinity) raises q_cr over the untwisted
    ring's: the root of :func:`large_twist_gain` in (1, NU_SEARCH_MAX) (Brent, to 1e-12
    relative), or nan if the gain keeps one sign there."""
    grid = np.geomspace(1.0 + 1e-6, NU_SEARCH_MAX * (1 - 1e-12), 400)
    gains = np.array([large_twist_gain(v, e_ratio, load) for v in grid])
    change = np.flatnonzero((gains[:-1] < 0) & (gains[1:] >= 0))
    if change.size == 0:
        return math.nan
    i = int(change[0])
    return float(scipy.optimize.brentq(large_twist_gain, grid[i], grid[i + 1],
                                       args=(e_ratio, load), rtol=1e-12))


def large_anisotropy_limits(load: str) -> dict[str, float]:
    """nu -> infinity: q_cr(0) -> in-plane load of A1 = 1; q_cr(N -> infinity) -> min(in-plane
    load of 2, out-of-plane supremum of 2); their relative drop 1 - q_inf/q_0."""
    q0 = in_plane_untwisted(1.0, load)
    q_inf = min(in_plane_untwisted(2.0, load), out_of_plane_supremum(2.0, load))
    return {"q_untwisted": q0, "q_large_twist": q_inf, "relative_drop": 1.0 - q_inf / q0}
