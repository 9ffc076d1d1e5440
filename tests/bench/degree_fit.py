"""The fit behind ``resolution.DEGREE_FIT``: the a priori degree of the collocation solver.

    python tests/bench/degree_fit.py

On a grid (Omega(L) = 0, 1, ..., 49; nu in {1.05, 1.5, 2, 4, 10, 100}) the mode's tail at every
even degree 8..122 gives, for tol = 1e-2, ..., 1e-12, the degree ``need`` from which on the
tail's part of the estimate stays <= truncation_share(tol) tol (what the degree loop asks for). A
formula n0 costs about n0^2 a point, plus a second solve at the raised degree where n0 < need;
the search minimises that cost over ``need``^2, averaged over the points and then over the tols,
with at most 0.5 % of the points short at any tol (each raise is a second call, whose fixed
cost a small batch feels: at 5.5 % short, 66 of Figure 1's points, the Figure 1 batch at tol
1e-4 took 14 % longer). It prints the formula before this fit and the fit, per tol: the share
of points short and the cost over the ideal. ``resolution.initial_degree``'s docstring quotes
what it prints (2026-12-05). A development tool, not a test (pytest does not collect it).
"""

from __future__ import annotations

import itertools

import numpy as np

from spectral_rod.rod.collocation.driver import pick_family
from spectral_rod.rod.collocation.eigensolver import solve_points
from spectral_rod.rod.collocation.resolution import _big_l, truncation_error
from spectral_rod.rod.collocation.tuning import truncation_share

TOLS = 10.0 ** -np.arange(2, 13)
LIMIT = 0.005  # the largest share of points short of `need` at any tol


def tail_parts() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """|Omega| of the grid's points, the degrees, and the tail's part of the estimate at each
    (degrees x points)."""
    om, nu = (a.ravel() for a in np.meshgrid(np.arange(50.0), [1.05, 1.5, 2.0, 4.0, 10.0, 100.0]))
    degrees = np.arange(8, 124, 2)
    part = np.array([truncation_error(pick_family(*solve_points(n, om, nu, 1e-14)[:2])[2], n)
                     for n in degrees])
    return om, degrees, part


def needed_degrees(degrees: np.ndarray, part: np.ndarray) -> np.ndarray:
    """The needed degree per tol and point (tols x points)."""
    need = []
    for tol in TOLS:
        short = part > truncation_share(tol) * tol
        last = np.where(short.any(0), short.shape[0] - 1 - np.argmax(short[::-1], axis=0), -1)
        need.append(degrees[np.minimum(last + 1, degrees.size - 1)])
    return np.array(need)


def step_gain(part: np.ndarray) -> np.ndarray:
    """What a step of 2 in the degree divides the tail's part by, where it is in [1e-14, 1e-3]
    (where the raise rule works: 2 per factor 10 short)."""
    now, after = part[:-1], part[1:]
    sel = (now >= 1e-14) & (now <= 1e-3) & (after > 0)
    return now[sel] / after[sel]


#: L per tol (a column): log10(1/t) >= 3.5, t = truncation_share(tol) tol, at tol <= TIGHT_TOL;
#: less LOOSE_L_OFFSET, >= LOOSE_L_MIN, above (resolution._big_l).
BIG_L = np.array([_big_l(float(tol)) for tol in TOLS])[:, None]


def fitted_degrees(om: np.ndarray, fit) -> np.ndarray:
    """n0 = |Omega|/2 + c0 + c1 L + (c2 L + c3) (1 + |Omega|)^(1/3), rounded up to even (tols x
    points)."""
    big_l, (c0, c1, c2, c3) = BIG_L, fit
    x = om / 2 + c0 + c1 * big_l + (c2 * big_l + c3) * np.cbrt(1.0 + om)
    return np.clip(2 * np.ceil(x / 2), 8, 512)


def previous(om: np.ndarray) -> np.ndarray:
    """The formula before this fit: |Omega|/2 + 3.5 + 0.5 L + 1.3 (1 + |Omega|)^(1/3) sqrt(L)."""
    big_l = BIG_L
    x = om / 2 + 3.5 + 0.5 * big_l + 1.3 * np.cbrt(1.0 + om) * np.sqrt(big_l)
    return np.clip(2 * np.ceil(x / 2), 8, 512)


def scores(n0: np.ndarray, need: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per tol: the share of points short and the mean cost over the ideal."""
    short = n0 < need
    cost = (n0**2 + short * np.maximum(need, n0 + 2) ** 2) / need**2
    return short.mean(axis=1), cost.mean(axis=1)


def objective(n0: np.ndarray, need: np.ndarray) -> float:
    short, cost = scores(n0, need)
    return float(cost.mean() + 10.0 * np.maximum(short - LIMIT, 0.0).sum())


def report(label: str, n0: np.ndarray, need: np.ndarray) -> None:
    short, cost = scores(n0, need)
    print(f"{label}: mean cost / ideal {cost.mean():.3f}")
    for tol, s, c in zip(TOLS, short, cost, strict=True):
        print(f"   tol {tol:.0e}: short {100 * s:5.1f} %, cost / ideal {c:.3f}")


def main() -> None:
    om, degrees, part = tail_parts()
    need = needed_degrees(degrees, part)
    gain = step_gain(part)
    print(f"a step of 2 divides the tail's part by {gain.min():.1f} at least, median "
          f"{np.median(gain):.0f} ({gain.size} steps)")
    report("at the tols' L (resolution._big_l)", fitted_degrees(om, (5.0, 0.4, 0.3, 1.0)), need)
    report("before (at t = truncation_share(tol) tol)", previous(om), need)
    grid = itertools.product(np.arange(-2.0, 8.01, 0.5), np.arange(-0.5, 1.01, 0.1),
                             np.arange(0.0, 0.81, 0.05), np.arange(-1.0, 2.01, 0.25))
    best = min(grid, key=lambda fit: objective(fitted_degrees(om, fit), need))
    report(f"fit {tuple(round(float(c), 2) for c in best)}", fitted_degrees(om, best), need)


if __name__ == "__main__":
    main()
