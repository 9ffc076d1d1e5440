"""The lowest root of a function by a sign scan on a grid and a refinement in the bracket.

One routine for every characteristic-determinant root in the package (mpmath for one point,
numpy for batches of points): the paper computed its curves this way, and the scan is what
guarantees the *lowest* root (a root finder started anywhere else may converge to a higher one).
The guarantee holds when no two roots of one component lie within one step; the callers' steps
are chosen for that (see them). :func:`lowest_roots` scans a batch of functions f_p (one per
point p) together, each on its own grid; :func:`bracketed_roots` refines brackets of a batch at
once (the double-precision refinement), :func:`bracketed_root` one bracket in Python floats (the
same iteration, for a caller with only a few brackets, where numpy's per-call cost on arrays of
one or two entries would be most of the time).

>>> import math
>>> lowest_root(lambda g: [[math.cos(x) for x in g]], lambda k, a, b: math.pi / 2, 0.0, 3.0, 0.25)
(1.5707963267948966, 0)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray

__all__ = ["MAX_SCAN_POINTS", "bracketed_root", "bracketed_roots", "lowest_root", "lowest_roots"]

#: Largest number of grid points a scan may evaluate per point before it gives up (a bound on
#: its cost; the scans stop at the first root, which for the characteristic equation lies
#: below p ~ 2 on every grid tested).
MAX_SCAN_POINTS = 10_000_000
_EPS = float(np.finfo(float).eps)


def _signs(values: NDArray[Any]) -> NDArray[np.int_]:
    """Signs of a table of values by exact comparisons (for mpmath numbers a float conversion
    would flush values below 1e-308 to zero and fake a root)."""
    if values.dtype.kind == "f":
        return np.sign(values).astype(int)
    return (values > 0).astype(int) - (values < 0).astype(int)


def lowest_roots(values: Callable[[NDArray[np.int_], NDArray[Any]], Any],
                 refine: Callable[[NDArray[np.int_], NDArray[np.int_], NDArray[Any],
                                   NDArray[Any]], NDArray[Any]],
                 lo: Any, hi: Any, step: Any, chunk: int = 1
                 ) -> tuple[NDArray[Any], NDArray[np.int_]]:
    """Lowest root of any component of f_p on [lo_p, hi_p], and the component, for each point p.

    ``values(points, grid)`` returns f_p at the abscissae ``grid`` (one row per entry of
    ``points``), shape (len(points), components, grid columns); ``refine(points, k, a, b)``
    returns the roots of component k[j] of f_{points[j]} in [a[j], b[j]]. ``lo``, ``hi``,
    ``step`` are 1-d arrays (one entry per point; float or mpmath object arrays). The grid of
    point p is lo_p, lo_p + step_p, ... (hi_p last), evaluated ``chunk`` columns at a time for all
    points still scanning: 1 for expensive scalar functions (mpmath), tens to hundreds for
    vectorised ones. A component that is exactly zero at a grid point counts as a sign change
    there. Where several components change sign in a point's first bracket, every one is refined
    and the smallest root wins. Returns (roots, components); component -1 and root nan where a
    point has no sign change.
    """
    lo, hi, step = (np.atleast_1d(np.asarray(v)) for v in (lo, hi, step))
    # the scan stops at the first root, so its cost is the points below it, not the interval's
    count = np.ceil(((hi - lo) / step).astype(float)).astype(np.int64) + 1
    roots = np.full(lo.size, np.nan, dtype=lo.dtype if lo.dtype.kind == "O" else float)
    comp = np.full(lo.size, -1)
    active = np.arange(lo.size)
    prev_x = prev = None
    for start in range(0, int(count.max(initial=0)), chunk):  # no points: nothing to scan
        if start >= MAX_SCAN_POINTS:
            raise ValueError(f"scan in steps of {float(step.min()):g} found no root in "
                             f"{MAX_SCAN_POINTS} points (from {float(lo.min()):g})")
        cols = np.arange(start, start + chunk)
        xs = lo[active, None] + cols * step[active, None]
        xs = np.where(xs < hi[active, None], xs, hi[active, None])
        vals = np.asarray(values(active, xs))
        if prev is not None:
            xs, vals = np.concatenate([prev_x, xs], axis=1), np.concatenate([prev, vals], axis=2)
        sign = _signs(vals)
        change = sign[:, :, :-1] * sign[:, :, 1:] <= 0  # (points, components, brackets)
        # change is 3-d, so any over one axis is an array (the stubs also allow a scalar)
        any_change = cast(NDArray[np.bool_], change.any(axis=1))
        hit = np.flatnonzero(any_change.any(axis=1))
        if hit.size:
            first = np.argmax(any_change[hit], axis=1)
            roots[active[hit]], comp[active[hit]] = _refine_first(
                refine, active[hit], xs[hit, first], xs[hit, first + 1],
                change[hit, :, first], sign[hit, :, first])
        keep = np.ones(active.size, dtype=bool)
        keep[hit] = False
        keep &= count[active] > start + chunk
        active, prev_x, prev = active[keep], xs[keep, -1:], vals[keep, :, -1:]
        if not active.size:
            break
    return roots, comp


def _refine_first(refine, points, a, b, change, sign_a) -> tuple[NDArray[Any], NDArray[np.int_]]:
    """The smallest root over the components changing sign in each point's first bracket."""
    rows, ks = np.nonzero(change)
    found = np.empty(rows.size, dtype=a.dtype)
    exact = sign_a[rows, ks] == 0
    found[exact] = a[rows[exact]]
    ref = np.flatnonzero(~exact)
    if ref.size:
        found[ref] = refine(points[rows[ref]], ks[ref], a[rows[ref]], b[rows[ref]])
    best_root = np.empty(points.size, dtype=a.dtype)
    best_comp = np.full(points.size, -1)
    for j in range(rows.size):  # a handful: one or two components per point
        r = rows[j]
        if best_comp[r] < 0 or found[j] < best_root[r]:
            best_root[r], best_comp[r] = found[j], ks[j]
    return best_root, best_comp


def lowest_root(values: Callable[[list[Any]], Sequence[Sequence[Any]]],
                refine: Callable[[int, Any, Any], Any], lo: Any, hi: Any, step: Any,
                chunk: int = 1) -> tuple[Any, int] | None:
    """:func:`lowest_roots` for one function: ``values(grid)`` gives (components, len(grid)),
    ``refine(k, a, b)`` one root; returns (root, component) or None."""
    def batch_values(_points, grid):
        return np.array([values(list(grid[0]))], dtype=object)

    def batch_refine(_points, k, a, b):
        return np.array([refine(int(kj), aj, bj) for kj, aj, bj in zip(k, a, b, strict=True)],
                        dtype=object)

    root, comp = lowest_roots(batch_values, batch_refine, np.array([lo], dtype=object),
                              np.array([hi], dtype=object), np.array([step], dtype=object),
                              chunk)
    return None if comp[0] < 0 else (root[0], int(comp[0]))


def bracketed_roots(f: Callable[[NDArray[np.int_], NDArray[np.float64]], NDArray[np.float64]],
                    a: NDArray[np.float64], b: NDArray[np.float64],
                    rtol: float = 4 * _EPS, max_iter: int = 200) -> NDArray[np.float64]:
    """Roots of a batch of functions, each in its bracket [a_j, b_j] (f changes sign there), to
    |bracket| <= 1e-16 + 2 rtol |x| (the tolerance of :func:`scipy.optimize.brentq` with
    xtol=1e-16).

    ``f(j, x)`` evaluates the functions of entries j at x (arrays). Anderson-Bjorck regula falsi:
    superlinear, and the bracket is kept. Measured on 500 large-twist determinant roots
    (brackets 1/256 wide): 11 evaluations median, 24 at most (Illinois: 12, 25; Chandrupatla's
    method: 11, 80; a bisection safeguard only added evaluations).
    """
    a, b = np.array(a, dtype=float), np.array(b, dtype=float)
    idx = np.arange(a.size)
    fa, fb = f(idx, a), f(idx, b)
    out = np.where(fa == 0, a, b)
    active = np.flatnonzero((fa != 0) & (fb != 0))
    for _ in range(max_iter):
        if not active.size:
            break
        aa, bb, ffa, ffb = a[active], b[active], fa[active], fb[active]
        c = bb - ffb * (bb - aa) / (ffb - ffa)
        fc = f(active, c)
        flip = fc * ffb < 0  # the root is between b and c: b becomes the other end
        m = 1.0 - fc / ffb  # otherwise the kept end's value is scaled down (Anderson-Bjorck)
        ffa = np.where(flip, ffb, ffa * np.where(m > 0, m, 0.5))
        aa = np.where(flip, bb, aa)
        a[active], fa[active], b[active], fb[active] = aa, ffa, c, fc
        out[active] = c
        done = (fc == 0) | (np.abs(c - aa) <= 1e-16 + 2 * rtol * np.abs(c))
        active = active[~done]
    return out


def bracketed_root(f: Callable[[float], float], a: float, b: float, rtol: float = 4 * _EPS,
                   max_iter: int = 200) -> float:
    """:func:`bracketed_roots` for one function of Python floats: the same Anderson-Bjorck
    iteration and stopping rule, without arrays (``tests/test_speed_paths.py`` checks that the
    two agree).

    >>> abs(bracketed_root(lambda x: float(np.cos(x)), 1.0, 2.0) - np.pi / 2) < 1e-15
    True
    """
    fa, fb = f(a), f(b)
    if fa == 0:
        return a
    out = b
    if fb == 0:
        return out
    for _ in range(max_iter):
        c = b - fb * (b - a) / (fb - fa)
        fc = f(c)
        if fc * fb < 0:  # the root is between b and c: b becomes the other end
            a, fa = b, fb
        else:  # the kept end's value is scaled down (Anderson-Bjorck)
            m = 1.0 - fc / fb
            fa *= m if m > 0 else 0.5
        b, fb, out = c, fc, c
        if fc == 0 or abs(c - a) <= 1e-16 + 2 * rtol * abs(c):
            break
    return out
