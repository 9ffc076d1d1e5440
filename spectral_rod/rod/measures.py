"""Measures of computed curves and modes that the paper's sentences are judged on.

Each takes sampled data (a grid and values on it, or a centreline) and returns a number; the
claims ledger states its verdict rules in terms of them.

>>> import numpy as np
>>> s = np.linspace(0, 1, 101)
>>> round(non_planarity(np.sin(np.pi * s), 0.5 * np.sin(np.pi * s)), 12)  # a plane: 0
0.0
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import check_real, real_array

__all__ = ["family_switches", "increasing_up_to", "local_maxima", "non_planarity",
           "observed_order", "settling_point"]


def _curve(name_a: str, a: ArrayLike, name_b: str, b: ArrayLike, minimum: int = 2
           ) -> tuple[NDArray, NDArray]:
    """Two 1-D samples of equal length >= minimum (numeric and finite where numeric)."""
    x = real_array(a, name_a) if name_a != "family" else np.asarray(a)
    y = real_array(b, name_b) if name_b != "family" else np.asarray(b)
    if x.ndim != 1 or y.shape != x.shape or x.size < minimum:
        raise ValueError(f"{name_a} and {name_b} must be 1-D of equal length >= {minimum}, got "
                         f"shapes {x.shape} and {y.shape}")
    if name_a == "grid" and np.any(np.diff(x) <= 0):  # the measures read order as grid order
        i = int(np.flatnonzero(np.diff(x) <= 0)[0])
        raise ValueError(f"grid must be strictly increasing, got grid[{i}] = {x[i]:g} >= "
                         f"grid[{i + 1}] = {x[i + 1]:g}")
    return x, y


def non_planarity(x1: ArrayLike, x2: ArrayLike) -> float:
    """sigma_min/sigma_max of the samples (x1, x2) of a centreline's lateral displacement: 0 iff
    the centreline lies in one plane through the rod's axis (a plane containing both hinged ends
    must contain the axis), up to 1 for a circular helix-like spread.

    Returns
    -------
    float
        sigma_min/sigma_max in [0, 1].

    Examples
    --------
    >>> import numpy as np
    >>> s = np.linspace(0, 1, 101)
    >>> round(non_planarity(np.sin(np.pi * s), 2 * np.sin(np.pi * s)), 12)   # one plane
    0.0
    >>> round(non_planarity(np.sin(np.pi * s), np.sin(2 * np.pi * s)), 6)   # orthogonal shapes
    1.0
    """
    a, b = _curve("x1", x1, "x2", x2)
    m = max(np.abs(a).max(), np.abs(b).max())
    if m == 0.0:
        return 0.0
    # scaled first: the SVD of entries ~1e308 overflows (it returned 0.0, "planar", before)
    sv = np.linalg.svd(np.column_stack([a / m, b / m]), compute_uv=False)
    return float(sv[-1] / sv[0]) if sv[0] > 0 else 0.0


def local_maxima(grid: ArrayLike, values: ArrayLike) -> NDArray[np.float64]:
    """Grid points of the interior local maxima of `values` (strictly above the left neighbour,
    not below the right one).

    Returns
    -------
    ndarray of float
        The grid points of the maxima, in grid order.

    Examples
    --------
    >>> local_maxima([0, 1, 2, 3, 4], [0.0, 2.0, 1.0, 3.0, 0.0]).tolist()
    [1.0, 3.0]
    """
    g, v = _curve("grid", grid, "values", values, 1)
    idx = np.flatnonzero((v[1:-1] > v[:-2]) & (v[1:-1] >= v[2:])) + 1
    return g[idx]


def family_switches(grid: ArrayLike, family: ArrayLike) -> NDArray[np.float64]:
    """Midpoints of the grid intervals across which the labels `family` change.

    Returns
    -------
    ndarray of float
        The midpoints, in grid order (empty if the label never changes).

    Examples
    --------
    >>> family_switches([0.0, 1.0, 2.0, 3.0], ["symmetric", "symmetric", "antisymmetric",
    ...                                          "antisymmetric"]).tolist()
    [1.5]
    """
    g, f = _curve("grid", grid, "family", family, 1)
    idx = np.flatnonzero(f[1:] != f[:-1])
    return 0.5 * (g[idx] + g[idx + 1])


def increasing_up_to(grid: ArrayLike, values: ArrayLike, end: float) -> bool:
    """Whether `values` increase strictly on the grid points <= `end`.

    Returns
    -------
    bool
        True iff every step of `values` up to `end` is an increase.

    Examples
    --------
    >>> grid, values = [0, 1, 2, 3], [1.0, 2.0, 3.0, 2.5]
    >>> increasing_up_to(grid, values, 2.0), increasing_up_to(grid, values, 3.0)
    (True, False)
    """
    g, v = _curve("grid", grid, "values", values, 1)
    end = check_real(end, "end")
    return bool(np.all(np.diff(v[g <= end]) > 0))


def settling_point(grid: ArrayLike, gap: ArrayLike, level: float) -> float | None:
    """Smallest grid point beyond which |gap| < level everywhere on the grid (the first point if
    it holds throughout; None if it does not hold at the end of the grid).

    Returns
    -------
    float or None
        That grid point, or None.

    Examples
    --------
    >>> settling_point([1, 2, 3, 4], [0.5, 0.05, 0.2, 0.01], 0.1)
    4.0
    >>> settling_point([1, 2], [0.5, 0.2], 0.1) is None
    True
    """
    g, d = _curve("grid", grid, "gap", gap, 1)
    d, level = np.abs(d), check_real(level, "level", 0.0, lo_open=True)
    bad = np.flatnonzero(d >= level)
    if bad.size == 0:
        return float(g[0])
    if bad[-1] + 1 >= g.size:
        return None
    return float(g[bad[-1] + 1])


def observed_order(x: ArrayLike, err: ArrayLike) -> float:
    """Observed order p of ``|err| ~ C x**p``: the least-squares slope of log|err| against log x
    (negative for an error that decays as x grows, e.g. -2 for an O(x^-2) remainder; for a
    discretisation error against the number of intervals, minus the order of accuracy).

    `x` positive and spread (max/min > 1 + 1e-8), `err` non-zero, both 1-D of the same length
    >= 2. The slope is a fit, not a limit: it measures the order only over a range where one
    power dominates.

    Returns
    -------
    float
        The fitted exponent p.

    Examples
    --------
    >>> x = np.array([10.0, 20.0, 40.0])
    >>> round(observed_order(x, 3.0 / x**2), 12)
    -2.0
    """
    a, e = _curve("x", x, "err", err, 2)
    # a spread of log x at round-off level leaves the slope undetermined (numpy's RankWarning)
    if np.any(a <= 0) or np.ptp(np.log(a)) <= 1e-8:
        raise ValueError(f"x must be positive and spread (max/min > 1 + 1e-8), got {a!r}")
    e = np.abs(e)
    if np.any(e == 0):
        raise ValueError(f"err must be non-zero (its logarithm is fitted), got {e!r}")
    return float(np.polyfit(np.log(a), np.log(e), 1)[0])
