"""The crossovers behind the speed constants that no other script measures: DENSE_ENTRIES,
LEAN_MAX_DEGREE, BLOCK_ENTRIES, POINT_SCHUR_DEGREE and SMALL_CALL of
``spectral_rod/rod/collocation/tuning.py``, and FEW_BRACKETS of
``spectral_rod/rod/characteristic.py``.

    python tests/bench/tuning_crossovers.py

Each line is the ratio of two ways to the same result, minimum of ROUNDS interleaved rounds on
one BLAS thread, on random points (Omega(L) up to 1.8 (n - 16), nu in [1.1, 10]); a ratio < 1
favours the first. Times are machine-dependent: re-run this script on the machine being tuned
for and move each constant to where its ratio crosses 1.

1. DENSE_ENTRIES: the numpy reference (no kernel) with dense shifted inverses / with the Schur
   complement (``eigensolver.solve_points``), both families, 1..16 points at n = 22..48; the
   threshold is the entries count points (n - 1)^2 where it crosses 1.
2. LEAN_MAX_DEGREE: the kernel on one lane / on 32 lanes (``eigensolver.solve_points`` with
   ``few_points_limit`` forced), 4 points at n = 40..128.
3. BLOCK_ENTRIES: ``stacked_inverse`` by blocks (checked) / ``numpy.linalg.inv``, per stack of
   `count` matrices k x k; the threshold is the entries count k^2 where it crosses 1.
4. POINT_SCHUR_DEGREE: the one-point numpy path's inverse of K - SHIFT
   (``shifted._point_inverse``) through the Schur complement / whole, n = 16..64, the
   symmetric family at Omega(L) = 0.9 n, nu = 3; the threshold is the degree where it crosses 1.
5. FEW_BRACKETS: the certified brackets of the characteristic route one point at a time in
   Python floats / on arrays (``characteristic._family_bound_point`` / ``_family_bound_batch``,
   nu - 1 log-uniform in [1e-9, 1e-3], Omega(L) in [0, 50]; ``_bracketed_point`` /
   ``_bracketed_batch``, Omega(L) in [50, 1000], nu in [1, 100]), 1..128 points; the
   threshold is the count where it crosses 1.
6. SMALL_CALL: ``critical_load`` on an array of k points by the general path / a loop of its
   scalar calls, on the collocation route (Omega(L) in [0, 10] and [40, 50], nu in [1.1,
   100]), near nu = 1 and at large twist (as in part 5); the threshold is the count where it
   crosses 1. The collocation routes once more with degree pooling's ``CALL_COST`` set to 0 (the
   groups of a few points then solved one engine call each): what that constant buys.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

from spectral_rod._blas_threads import one_blas_thread
from spectral_rod.rod import characteristic as C
from spectral_rod.rod import critical
from spectral_rod.rod.collocation import driver, modal_kernel, quotient, shifted, tuning
from spectral_rod.rod.collocation import eigensolver as E
from spectral_rod.rod.collocation import stacked_inverse as S

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


def dense_entries(rng: np.random.Generator) -> None:
    print(f"1. numpy reference: dense inverses / Schur complement, both families "
          f"(DENSE_ENTRIES = {tuning.DENSE_ENTRIES:,})")
    rtol = tuning.iteration_rtol(1e-12)
    library, limit = modal_kernel._library, tuning.DENSE_ENTRIES
    modal_kernel._library = lambda: None  # the numpy reference answers every call

    def solve(entries: int, n: int, tw, nv) -> None:
        for module in (E, shifted, quotient):  # every module that reads DENSE_ENTRIES
            module.DENSE_ENTRIES = entries
        E.solve_points(n, tw, nv, rtol)

    try:
        for n in (22, 28, 40, 48):
            row = []
            for count in (1, 2, 4, 8, 16):
                tw, nv = _points(n, count, rng)
                row.append((count * (n - 1) ** 2, best_ratio(
                    lambda n=n, tw=tw, nv=nv: solve(10**9, n, tw, nv),
                    lambda n=n, tw=tw, nv=nv: solve(-1, n, tw, nv))))
            print(f"   n = {n:3d}: " + "  ".join(f"{e:>6,} entries {r:5.2f}" for e, r in row))
    finally:
        modal_kernel._library = library
        for module in (E, shifted, quotient):
            module.DENSE_ENTRIES = limit


def lean_max_degree(rng: np.random.Generator) -> None:
    print(f"2. kernel: one lane / 32 lanes, 4 points (LEAN_MAX_DEGREE = "
          f"{tuning.LEAN_MAX_DEGREE})")
    if not modal_kernel.available():
        print("   (the C kernel is not built here)")
        return
    limit = E.few_points_limit
    rtol = tuning.iteration_rtol(1e-12)

    def solve(cap: int, n: int, tw, nv) -> None:
        E.few_points_limit = lambda _n: cap
        E.solve_points(n, tw, nv, rtol)

    try:
        for n in (40, 56, 64, 80, 128):
            tw, nv = _points(n, 4, rng)
            ratio = best_ratio(lambda n=n, tw=tw, nv=nv: solve(10**6, n, tw, nv),
                               lambda n=n, tw=tw, nv=nv: solve(0, n, tw, nv))
            print(f"   n = {n:3d}: {ratio:5.2f}")
    finally:
        E.few_points_limit = limit


def block_entries(rng: np.random.Generator) -> None:
    print(f"3. block recursion (checked) / LAPACK per stack (BLOCK_ENTRIES = "
          f"{tuning.BLOCK_ENTRIES})")
    for k in (6, 10, 14, 20, 28):
        row = []
        for count in (100, 300, 1200):
            a = rng.standard_normal((count, k, k)) + 4.0 * np.eye(k)
            row.append((count * k * k, best_ratio(lambda a=a: _blocks(a),
                                                  lambda a=a: np.linalg.inv(a))))
        print(f"   k = {k:2d}: " + "  ".join(f"{e:>7,} entries {r:5.2f}" for e, r in row))
    row = []
    for k in (64, 128, 255):  # one matrix, as a scalar call above the kernel's range
        a = rng.standard_normal((1, k, k)) + 4.0 * np.sqrt(k) * np.eye(k)
        row.append((k, best_ratio(lambda a=a: _blocks(a), lambda a=a: np.linalg.inv(a))))
    print("   one matrix: " + "  ".join(f"k = {k}: {r:5.2f}" for k, r in row))


def _blocks(a: np.ndarray) -> np.ndarray:
    limit = S.BLOCK_ENTRIES
    try:
        S.BLOCK_ENTRIES = 0  # always by blocks
        return S.stacked_inverse(a)
    finally:
        S.BLOCK_ENTRIES = limit


def point_schur_degree() -> None:
    print(f"4. one point's inverse: Schur complement / whole (POINT_SCHUR_DEGREE = "
          f"{tuning.POINT_SCHUR_DEGREE})")
    row = []
    limit = shifted.POINT_SCHUR_DEGREE
    for n in (16, 22, 28, 34, 40, 44, 48, 56, 64):
        pf = shifted._point_family(n, "symmetric")
        coef = E.term_coefficients(0.9 * n, 3.0).tolist()

        def inverse(schur: bool, pf=pf, coef=coef) -> None:
            shifted.POINT_SCHUR_DEGREE = 0 if schur else 10**6
            try:
                for _ in range(50):
                    shifted._point_inverse(pf, coef)
            finally:
                shifted.POINT_SCHUR_DEGREE = limit

        ratio = best_ratio(lambda f=inverse: f(True), lambda f=inverse: f(False))
        row.append(f"n = {n}: {ratio:.2f}")
    print("   " + "  ".join(row))


def _route_points(route: str, count: int, rng: np.random.Generator):
    """`count` random points of one route (part 5 and 6)."""
    if route == "near-degenerate":
        return rng.uniform(0.0, 50.0, count), 1.0 + 10.0 ** rng.uniform(-9.0, -3.0, count)
    if route == "large twist":
        return rng.uniform(50.0, 1000.0, count), rng.uniform(1.0, 100.0, count)
    low, high = {"Omega(L) < 10": (0.0, 10.0), "Omega(L) in [40, 50]": (40.0, 50.0)}[route]
    return rng.uniform(low, high, count), rng.uniform(1.1, 100.0, count)


def few_brackets(rng: np.random.Generator) -> None:
    print(f"5. certified brackets: one point at a time in floats / on arrays (FEW_BRACKETS = "
          f"{C.FEW_BRACKETS})")
    for name, batch, point, route in (
            ("family bounds", C._family_bound_batch, C._family_bound_point, "near-degenerate"),
            ("large twist", C._bracketed_batch, C._bracketed_point, "large twist")):
        row = []
        for count in (1, 4, 8, 16, 24, 32, 64, 128):
            om, nv = _route_points(route, count, rng)
            floats = list(zip(om.tolist(), nv.tolist(), strict=True))
            ratio = best_ratio(lambda f=point, x=floats: [f(a, b) for a, b in x],
                               lambda f=batch, om=om, nv=nv: f(om, nv))
            row.append(f"{count}: {ratio:.2f}")
        print(f"   {name}: " + "  ".join(row))


def small_call(rng: np.random.Generator) -> None:
    print(f"6. critical_load on k points: general path / loop of scalar calls (SMALL_CALL = "
          f"{tuning.SMALL_CALL}; the collocation routes also with pooling's CALL_COST = 0)")
    small, call_cost = critical._few_points, driver.CALL_COST
    try:
        critical._few_points = lambda *args: None  # the general path answers every array
        for route, cost in (("Omega(L) < 10", call_cost), ("Omega(L) < 10", 0.0),
                            ("Omega(L) in [40, 50]", call_cost), ("Omega(L) in [40, 50]", 0.0),
                            ("near-degenerate", call_cost), ("large twist", call_cost)):
            driver.CALL_COST = cost
            row = []
            for count in (2, 4, 6, 8, 10, 12, 16, 24):
                om, nv = _route_points(route, count, rng)
                floats = list(zip(om.tolist(), nv.tolist(), strict=True))
                ratio = best_ratio(lambda om=om, nv=nv: critical.critical_load(om, nv),
                                   lambda x=floats: [critical.critical_load(a, b) for a, b in x])
                row.append(f"{count}: {ratio:.2f}")
            label = route if cost == call_cost else f"{route}, CALL_COST = 0"
            print(f"   {label}: " + "  ".join(row))
    finally:
        critical._few_points, driver.CALL_COST = small, call_cost


def main() -> None:
    rng = np.random.default_rng(7)
    with one_blas_thread():
        dense_entries(rng)
        lean_max_degree(rng)
        block_entries(rng)
        point_schur_degree()
        few_brackets(rng)
    small_call(rng)  # critical_load limits the BLAS threads itself


if __name__ == "__main__":
    main()
