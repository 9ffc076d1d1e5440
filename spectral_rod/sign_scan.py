"""The lowest root of a function by a sign scan on a grid and a refinement in the bracket.

One routine for every characteristic-determinant root in the package (mpmath and numpy): the
paper computed its curves this way, and the scan is what guarantees the *lowest* root (a root
finder started anywhere else may converge to a higher one). The guarantee holds when no two
roots of one component lie within one step; the callers' steps are chosen for that (see them).

>>> import math
>>> lowest_root(lambda g: [[math.cos(x) for x in g]], lambda k, a, b: math.pi / 2, 0.0, 3.0, 0.25)
(1.5707963267948966, 0)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

__all__ = ["MAX_SCAN_POINTS", "lowest_root"]

#: Largest number of grid points a scan may take (a bound on its cost).
MAX_SCAN_POINTS = 10_000_000


def _signs(values: Any) -> np.ndarray:
    """Signs of a (components, points) table; exact comparisons for mpmath numbers (a float
    conversion would flush values below 1e-308 to zero and fake a root)."""
    if isinstance(values, np.ndarray) and values.dtype.kind == "f":
        return np.sign(values).astype(int)
    return np.array([[(v > 0) - (v < 0) for v in row] for row in values], dtype=int)


def lowest_root(values: Callable[[list[Any]], Sequence[Sequence[Any]]],
                refine: Callable[[int, Any, Any], Any], lo: Any, hi: Any, step: Any,
                chunk: int = 1) -> tuple[Any, int] | None:
    """Lowest root of any component of f on [lo, hi] and the component's index, or None.

    ``values(grid)`` returns f at the grid points, shape (components, len(grid));
    ``refine(k, a, b)`` returns the root of component k in the bracket [a, b]. The grid is
    lo, lo + step, ... (hi last), evaluated ``chunk`` points at a time: 1 for expensive scalar
    functions (mpmath), a few hundred for vectorised ones. A component that is exactly zero at
    a grid point counts as a sign change there. Where several components change sign in the
    first bracket, every one is refined and the smallest root wins.
    """
    count = int(np.ceil(float((hi - lo) / step))) + 1
    if count > MAX_SCAN_POINTS:
        raise ValueError(f"scan of [{float(lo):g}, {float(hi):g}] in steps of {float(step):g} "
                         f"needs {count} points (at most {MAX_SCAN_POINTS})")
    prev_x, prev = None, None
    for start in range(0, count, chunk):
        grid = [min(lo + i * step, hi) for i in range(start, min(start + chunk, count))]
        xs = ([prev_x] if prev_x is not None else []) + grid
        vals = values(grid)
        if prev is not None:
            vals = (np.concatenate([prev, vals], axis=1) if isinstance(vals, np.ndarray)
                    else [[p, *v] for p, v in zip(prev, vals, strict=True)])
        sign = _signs(vals)
        change = sign[:, :-1] * sign[:, 1:] <= 0
        hit = np.flatnonzero(change.any(axis=0))
        if hit.size:
            i = int(hit[0])
            roots = [(xs[i] if sign[k, i] == 0 else refine(k, xs[i], xs[i + 1]), k)
                     for k in map(int, np.flatnonzero(change[:, i]))]
            return min(roots, key=lambda r: r[0])
        prev_x = xs[-1]
        prev = (vals[:, -1:] if isinstance(vals, np.ndarray) else [v[-1] for v in vals])
    return None
