"""The crossovers behind four constants of ``spectral_rod/rod/collocation/tuning.py`` that no other
script measures: SMALL_BATCH / SMALL_DEGREE, LEAN_MAX_DEGREE, SQUARING_MAX and BLOCK_ENTRIES.

    python tests/bench/tuning_crossovers.py

Each line is the ratio of two ways to the same result, minimum of ROUNDS interleaved rounds on
one BLAS thread, on random points (Omega(L) up to 1.8 (n - 16), nu in [1.1, 10]); a ratio < 1
favours the first. Times are machine-dependent: re-run this script on the machine being tuned
for and move each constant to where its ratio crosses 1.

1. SMALL_BATCH, SMALL_DEGREE: the full ``eig`` (``solve_family_eig``) / the iteration
   (``solve_family`` with SMALL_BATCH lifted), per family, for 1..8 points at n = 20..48.
2. LEAN_MAX_DEGREE: the few-point path (``solve_few``) / the batched engine (``_solve_points``
   forced to it) for 4 points at n = 40..128.
3. SQUARING_MAX: powers of M by squaring / by products with the vectors (``few_points.
   _power_iterates``), one point, both families, m = n - 1 = 15..47.
4. BLOCK_ENTRIES: ``stacked_inverse`` by blocks (checked) / ``numpy.linalg.inv``, per stack of
   `count` matrices k x k; the threshold is the entries count k^2 where it crosses 1.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

from spectral_rod._blas_threads import one_blas_thread
from spectral_rod.rod.collocation import driver as C
from spectral_rod.rod.collocation import eigensolver as E
from spectral_rod.rod.collocation import few_points as F
from spectral_rod.rod.collocation import stacked_inverse as S
from spectral_rod.rod.collocation import tuning

ROUNDS = 15


def best_ratio(first: Callable[[], object], second: Callable[[], object]) -> float:
    """min time of `first` / min time of `second`, interleaved rounds (after one warm call)."""
    first(), second()
    t1 = t2 = float("inf")
    for _ in range(ROUNDS):
        start = time.perf_counter()
        first()
        t1 = min(t1, time.perf_counter() - start)
        start = time.perf_counter()
        second()
        t2 = min(t2, time.perf_counter() - start)
    return t1 / t2


def _points(n: int, count: int, rng: np.random.Generator):
    return rng.uniform(0.0, max(1.0, 1.8 * (n - 16)), count), rng.uniform(1.1, 10.0, count)


def small_batch(rng: np.random.Generator) -> None:
    print(f"1. eig / iteration per family (SMALL_BATCH = {tuning.SMALL_BATCH}, "
          f"SMALL_DEGREE = {tuning.SMALL_DEGREE})")
    limit, E.SMALL_BATCH = E.SMALL_BATCH, 0  # the iteration answers every batch
    try:
        for n in (20, 28, 40, 48):
            row = []
            for count in (1, 2, 4, 8):
                tw, nv = _points(n, count, rng)
                row.append(best_ratio(
                    lambda n=n, tw=tw, nv=nv: E.solve_family_eig(n, "symmetric", tw, nv),
                    lambda n=n, tw=tw, nv=nv: E.solve_family(n, "symmetric", tw, nv)))
            print(f"   n = {n:3d}: " + "  ".join(f"{c} pts {r:5.2f}"
                                                for c, r in zip((1, 2, 4, 8), row, strict=True)))
    finally:
        E.SMALL_BATCH = limit


def lean_max_degree(rng: np.random.Generator) -> None:
    print(f"2. few-point path / batched engine, 4 points (LEAN_MAX_DEGREE = "
          f"{tuning.LEAN_MAX_DEGREE})")
    limit = C.few_points_limit
    rtol = tuning.iteration_rtol(1e-12)
    for n in (40, 56, 64, 80, 128):
        tw, nv = _points(n, 4, rng)
        deg = np.full(4, n)
        try:
            C.few_points_limit = lambda _n: 0
            ratio = best_ratio(lambda n=n, tw=tw, nv=nv: F.solve_few(n, tw, nv, rtol),
                               lambda tw=tw, nv=nv, deg=deg: C._solve_points(tw, nv, deg))
        finally:
            C.few_points_limit = limit
        print(f"   n = {n:3d}: {ratio:5.2f}")


def squaring_max(rng: np.random.Generator) -> None:
    print(f"3. squaring / vector products, one point (SQUARING_MAX = {tuning.SQUARING_MAX})")
    for n in (16, 22, 28, 32, 40, 48):
        dp = F.dense_pencils(n)
        m = dp.mass.shape[1]
        mat = rng.standard_normal((2, m, m)) / m
        steps = tuning.power_steps(1e-14)
        limit = F.SQUARING_MAX

        def powers(cap: int, mat=mat, dp=dp, steps=steps) -> None:
            F.SQUARING_MAX = cap
            F._power_iterates(mat, dp.start, steps)

        try:
            ratio = best_ratio(lambda: powers(10**6), lambda: powers(-1))
        finally:
            F.SQUARING_MAX = limit
        print(f"   m = {m:3d}: {ratio:5.2f}")


def block_entries(rng: np.random.Generator) -> None:
    print(f"4. block recursion (checked) / LAPACK per stack (BLOCK_ENTRIES = "
          f"{tuning.BLOCK_ENTRIES})")
    for k in (6, 10, 14, 20, 28):
        row = []
        for count in (100, 300, 1200):
            a = rng.standard_normal((count, k, k)) + 4.0 * np.eye(k)
            row.append((count * k * k, best_ratio(lambda a=a: _blocks(a),
                                                  lambda a=a: np.linalg.inv(a))))
        print(f"   k = {k:2d}: " + "  ".join(f"{e:>7,} entries {r:5.2f}" for e, r in row))


def _blocks(a: np.ndarray) -> np.ndarray:
    limit = S.BLOCK_ENTRIES
    try:
        S.BLOCK_ENTRIES = 0  # always by blocks
        return S.stacked_inverse(a)
    finally:
        S.BLOCK_ENTRIES = limit


def main() -> None:
    rng = np.random.default_rng(7)
    with one_blas_thread():
        small_batch(rng)
        lean_max_degree(rng)
        squaring_max(rng)
        block_entries(rng)


if __name__ == "__main__":
    main()
