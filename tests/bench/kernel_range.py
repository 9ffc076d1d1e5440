"""Where the C kernel wins: the measurements behind two constants of the collocation solver.

    python tests/bench/kernel_range.py

1. ``tuning.KERNEL_MAX_SCHUR``: ``lowest_eigenpair`` by the C kernel against its numpy
   iteration (the kernel switched off), per degree n and mode family, on random points
   (Omega(L) up to 1.8 (n - 16), nu in [1.1, 10]) at tol 1e-12, with the limit lifted; the
   ratio kernel / numpy time.
2. ``tuning.few_points_limit`` and ``LEAN_FACTOR``: the kernel's ``modal_points`` on k random
   Figure 1 points at degree n, one point at a time (one lane) against a group of 32 lanes
   (``few_points_limit`` forced to either), us a point; the cheaper one.
3. The pencil's Rayleigh-quotient terms at |Omega(L)| > LONG_TWIST (``quotient._rayleigh_sums``
   in ``longdouble``): the kernel's double-double products against numpy's ``longdouble`` ones,
   us a point on 500 random points, n = 24, 44, 56; and for one point (a scalar call) the
   kernel's, the numpy engine's split products (``quotient._split_terms``, its choice up to
   ``tuning.DENSE_ENTRIES``) and ``longdouble`` products, us a call.

Minima of interleaved rounds on one BLAS thread. The docstrings of those constants quote what
it prints (2026-12-05). A development tool, not a test (pytest does not collect it).
"""

from __future__ import annotations

import numpy as np
from alternatives import minima

from spectral_rod import load_figure1
from spectral_rod._blas_threads import one_blas_thread
from spectral_rod.rod.collocation import eigensolver as E
from spectral_rod.rod.collocation import modal_form, modal_kernel, quotient
from spectral_rod.rod.collocation.discretisation import family_operator
from spectral_rod.rod.collocation.tuning import iteration_rtol


def numpy_only(fn):
    """fn with the kernel switched off (the numpy iteration answers)."""
    def run():
        library = modal_kernel._library
        modal_kernel._library = lambda: None
        try:
            return fn()
        finally:
            modal_kernel._library = library
    return run


def kernel_against_numpy() -> None:
    rng = np.random.default_rng(1)
    print("kernel / numpy time of lowest_eigenpair (tol 1e-12)")
    limit, E.KERNEL_MAX_SCHUR = E.KERNEL_MAX_SCHUR, 10**6
    try:
        _kernel_against_numpy(rng)
    finally:
        E.KERNEL_MAX_SCHUR = limit


def _kernel_against_numpy(rng: np.random.Generator) -> None:
    for n, points in ((22, 1200), (22, 100), (40, 400), (64, 200), (100, 100), (128, 60),
                      (144, 60), (160, 40), (256, 20)):
        for family in ("symmetric", "antisymmetric"):
            mf = modal_form.modal_family(n, family)
            tw = rng.uniform(0, max(1.0, 1.8 * (n - 16)), points)
            nv = rng.uniform(1.1, 10.0, points)
            def fast(mf=mf, tw=tw, nv=nv):
                return E.lowest_eigenpair(mf, tw, nv, rtol=E.POWER_RTOL)

            t_kernel, t_numpy = minima([fast, numpy_only(fast)], 7)
            print(f"  n = {n:3d}, {points:4d} points, {family:<13}: {t_kernel / t_numpy:.2f}")


def few_points_crossover() -> None:
    d = load_figure1()
    tw_all, nv_all = np.abs(d["twist_angle"].to_numpy()), d["nu"].to_numpy()
    rng = np.random.default_rng(0)
    limit = E.few_points_limit
    rtol = iteration_rtol(1e-12)
    print("one lane / 32 lanes, us a point (Figure 1 points at degree n)")
    try:
        for n in (16, 22, 30, 40, 56):
            for k in (8, 12, 16, 24, 32, 48):
                idx = rng.choice(tw_all.size, k, replace=False)
                tw, nv = tw_all[idx], nv_all[idx]

                def solve(cap, n=n, tw=tw, nv=nv):
                    E.few_points_limit = lambda _n, cap=cap: cap
                    E.solve_points(n, tw, nv, rtol)
                few, batched = minima([lambda: solve(10**6), lambda: solve(0)], 30)
                print(f"  n = {n}, {k:2d} points: {few / k * 1e6:6.1f} / {batched / k * 1e6:6.1f}"
                      f"  -> {'one lane' if few < batched else '32 lanes'}")
    finally:
        E.few_points_limit = limit


def extended_quotient() -> None:
    rng = np.random.default_rng(0)
    print("pencil quotient terms at |Omega(L)| > LONG_TWIST, us a point: double-double / "
          "longdouble")
    for n in (24, 44, 56):
        for family in ("symmetric", "antisymmetric"):
            op = family_operator(n, family)
            m = op.sizes[0] + op.sizes[1]
            tw, nv = rng.uniform(20, 50, 500), rng.uniform(1, 100, 500)
            x, y = rng.standard_normal((500, m)), rng.standard_normal((500, m))

            def terms(op=op, tw=tw, nv=nv, x=x, y=y):
                return quotient._rayleigh_sums(op, tw, nv, y, x, np.longdouble)

            t_dd, t_ld = minima([terms, numpy_only(terms)], 7)
            print(f"  n = {n}, {family:<13}: {t_dd / 500 * 1e6:5.2f} / {t_ld / 500 * 1e6:5.2f}")
    print("one point, us a call: double-double (kernel) / split products / longdouble")
    for n in (24, 44, 56):
        op = family_operator(n, "symmetric")
        m = op.sizes[0] + op.sizes[1]
        tw, nv = rng.uniform(20, 50, 1), rng.uniform(1, 100, 1)
        x, y = rng.standard_normal((1, m)), rng.standard_normal((1, m))

        def one(op=op, tw=tw, nv=nv, x=x, y=y):
            return quotient._rayleigh_sums(op, tw, nv, y, x, np.longdouble)

        split = numpy_only(one)

        def longdouble(fn=split):
            limit = quotient.DENSE_ENTRIES
            quotient.DENSE_ENTRIES = 0  # the longdouble products, as for many points
            try:
                return fn()
            finally:
                quotient.DENSE_ENTRIES = limit

        times = minima([lambda fn=fn: [fn() for _ in range(100)]
                        for fn in (one, split, longdouble)], 7)
        print(f"  n = {n}: " + " / ".join(f"{t / 100 * 1e6:5.1f}" for t in times))


if __name__ == "__main__":
    if not modal_kernel.available():
        raise SystemExit("the C kernel is not built here: nothing to compare")
    with one_blas_thread():
        kernel_against_numpy()
        few_points_crossover()
        extended_quotient()
