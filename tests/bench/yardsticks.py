"""The per-point routes of the package's first large-twist and near-degenerate solvers (commit
5beb5ca), condensed to what they ran: the extra columns of the benchmarks at those patterns,
whose yardstick is the baseline. They reuse the library's basis and determinant helpers, and
the benchmarks check their answers against the mpmath reference. Not part of the library.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
from numpy.polynomial.legendre import leggauss
from scipy.linalg import cho_factor, cho_solve
from scipy.optimize import brentq

from spectral_rod.rod.characteristic import DOUBLE_SCAN_STEP, SCAN_START, determinants
from spectral_rod.rod.increment import (
    _MAX_NEWTON,
    _second_derivatives,
    _tails,
    basis_size,
)

_EPS = float(np.finfo(float).eps)
MAX_SCAN_POINTS = 10_000_000


def _signs(values: Any) -> np.ndarray:
    """Signs of a (components, points) table; exact comparisons for mpmath numbers (a float
    conversion would flush values below 1e-308 to zero and fake a root)."""
    if isinstance(values, np.ndarray) and values.dtype.kind == "f":
        return np.sign(values).astype(int)
    return np.array([[(v > 0) - (v < 0) for v in row] for row in values], dtype=int)


def _lowest_root(values: Callable[[list[Any]], Sequence[Sequence[Any]]],
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


def pre_change_characteristic(twist_angle: float, nu: float) -> float:
    """The per-point large-twist route (one point): scan of 257 points, then brentq."""
    om, nu = abs(float(twist_angle)), float(nu)
    top = (1.0 + nu) / 2.0 + 1e-6

    def refine(k: int, a: float, b: float) -> float:
        return float(brentq(lambda p: float(determinants(p, om, nu)[k]), a, b, xtol=1e-16,
                            rtol=4 * _EPS, maxiter=200))

    found = _lowest_root(lambda grid: np.array(determinants(np.array(grid), om, nu)), refine,
                         SCAN_START, top, DOUBLE_SCAN_STEP, chunk=257)
    return found[0]


def pre_change_increment(twist_angle: float, nu: float, n: int | None = None
                              ) -> tuple[float, str]:
    """The per-point increment route (one point, energy form): leggauss recomputed, BLAS threads
    as set."""
    om, e = abs(float(twist_angle)), float(nu) - 1.0
    if om == 0.0 or e == 0.0:
        return 0.0, "symmetric"
    n = basis_size(om) if n is None else int(n)
    q = int(1.6 * n + 0.5 * om + 40)
    x, w = leggauss(q)
    s, w = (x + 1) / 2, w / 2
    crit, sines, sin_ks = _second_derivatives(s, n)
    tails, w_tail = _tails(s, w, sin_ks, n)
    so, co = np.sin(om * s), np.cos(om * s)
    # omega2 = cos(Om s) x2'' - sin(Om s) x1''  (columns: x1 = phi, x2 = phi)
    comp = np.concatenate([sines, tails], axis=1)
    f = np.concatenate([-(crit * so)[:, None], (crit * co)[:, None],
                        -comp * so[:, None], comp * co[:, None]], axis=1)
    f *= np.sqrt(w)[:, None]
    g = f.T @ f
    k = np.arange(2, n + 1, dtype=float)
    w_sines = k**2 - 1.0
    m1 = sines.shape[1]
    wblock = np.zeros((m1 + 2, m1 + 2))
    wblock[:m1, :m1] = np.diag(w_sines)
    wblock[m1:, m1:] = w_tail
    w22 = np.zeros((2 * (m1 + 2),) * 2)
    w22[:m1 + 2, :m1 + 2] = wblock
    w22[m1 + 2:, m1 + 2:] = wblock
    g11, g21, g22 = g[:2, :2], g[2:, :2], g[2:, 2:]
    a0 = w22 + e * g22
    eye = np.eye(a0.shape[0])

    def schur(d: float):
        cf = cho_factor(a0 - d * eye)
        y = cho_solve(cf, g21)
        return e * g11 - e * e * (g21.T @ y), cf

    t0, _ = schur(0.0)
    d, v = _min_eig2_scalar(t0)
    for _ in range(_MAX_NEWTON):
        try:
            t, cf = schur(d)
        except np.linalg.LinAlgError:  # pragma: no cover - d beyond the complement's spectrum
            d *= 0.5
            continue
        lmin, v = _min_eig2_scalar(t)
        r = cho_solve(cf, g21 @ v)
        step = (lmin - d) / (-e * e * float(r @ r) - 1.0)
        d_new = d - step
        if abs(d_new - d) <= 4e-16 * abs(d_new):
            return d_new, _mode_family_scalar(v, om)
        d = d_new
    return d, _mode_family_scalar(v, om)


def _min_eig2_scalar(t: np.ndarray) -> tuple[float, np.ndarray]:
    """The scalar 2x2 kernel (the library's is batched)."""
    a, b, c = t[0, 0], t[0, 1], t[1, 1]
    lmax = 0.5 * (a + c + math.hypot(a - c, 2 * b))
    lmin = (a * c - b * b) / lmax if lmax > 0 else 0.0
    v1, v2 = np.array([c - lmin, -b]), np.array([-b, a - lmin])
    v = v1 if np.linalg.norm(v1) >= np.linalg.norm(v2) else v2
    nv = np.linalg.norm(v)
    return lmin, (v / nv if nv > 0 else np.array([1.0, 0.0]))


def _mode_family_scalar(c1: np.ndarray, twist_angle: float) -> str:
    """The scalar parity test (the library's is batched)."""
    ang = math.atan2(c1[1], c1[0]) - twist_angle / 2
    return "symmetric" if abs(math.cos(ang)) >= abs(math.sin(ang)) else "antisymmetric"
