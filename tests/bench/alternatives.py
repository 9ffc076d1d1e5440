"""Four alternatives to the batched engine's iteration, measured and rejected (issue 14).

    python tests/bench/alternatives.py

On Figure 1's points, per degree group and mode family, each alternative against the same
iteration with the engine's own test (:func:`plain`) in one loop (:func:`iterate`: both vectors
normalised every step, so that (K - shift) x is known for the last two iterates): the steps a
point took (and the plain loop's), the share of points not converged in 40 steps, the largest
relative difference from the engine's converged eigenvalue, and the time relative to the plain
loop and to the engine's numpy iteration (``eigensolver.lowest_eigenpair`` with the C kernel
off: the alternatives are numpy code, and were measured against it before the kernel existed),
minima of ROUNDS interleaved rounds on one BLAS thread. ``README.md`` and
``tests/bench/HISTORY.md`` (2026-12-05, a later session) quote what it prints. A development
tool, not a test (pytest does not collect it).

1. ``shift``: a per-point shift, the family's converged lambda_1 less a relative margin (an
   oracle: what the shift would buy, before the cost of predicting lambda_1), a test every step.
2. ``ritz``: two-sided Rayleigh-Ritz on the last two iterates (basis orthogonalised), a test
   every step from step 3: the second eigenvector's component is removed, so the contraction is
   (lambda_1 - SHIFT)/(lambda_3 - SHIFT) rather than (lambda_1 - SHIFT)/(lambda_2 - SHIFT).
3. ``float32``: at tol 1e-4 and 1e-6, the Schur complement, its inverse (the block recursion,
   unchecked: the check's 1e-10 would reject single precision) and the steps in float32; the
   test and the quotient in float64 with true products with K.
4. ``gram``: at tol 1e-4 and 1e-2, the test's residual norms from Gram entries (row dot products
   of x, (K - shift) x and y, (K - shift)^T y, with a rounding allowance) instead of residual
   vectors; the engine's schedule (a test at steps 4, 6, ...).

It then prints the accuracy near |Omega(L)| = 50 that HISTORY quotes (:func:`near_fifty`): the
map's worst sampled point at forced degrees, and 45 random points by scalar and array calls,
against the mpmath characteristic equation.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable
from contextlib import contextmanager, nullcontext

import numpy as np
from work_per_point import contraction

from spectral_rod import critical_load, load_figure1
from spectral_rod._blas_threads import one_blas_thread
from spectral_rod.rod.characteristic import characteristic_critical_load
from spectral_rod.rod.collocation import eigensolver as E
from spectral_rod.rod.collocation import modal_form, shifted
from spectral_rod.rod.collocation.discretisation import term_coefficients
from spectral_rod.rod.collocation.driver import solve_degrees
from spectral_rod.rod.collocation.eigensolver import _rowdot
from spectral_rod.rod.collocation.modal_form import _start_vector
from spectral_rod.rod.collocation.resolution import initial_degree
from spectral_rod.rod.collocation.shifted import _ShiftedModal
from spectral_rod.rod.collocation.stacked_inverse import block_inverse
from spectral_rod.rod.families import SHIFT

ROUNDS = 15
EPS = float(np.finfo(float).eps)


def col(a: np.ndarray) -> np.ndarray:
    return a[:, None]


def unit(x: np.ndarray, kx: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    s = 1.0 / np.sqrt(_rowdot(x, x))[:, None]
    return x * s, kx * s


def iterate(sk: _ShiftedModal, size: int, shift: np.ndarray, check: Callable, rtol: float,
            first: int, every: int) -> tuple[np.ndarray, float]:
    """Shift-and-invert steps on right and left vectors, normalised every step; from step
    `first`, every `every` steps, ``check(cur, prev, active)`` gives (mu, bound) with
    lambda = shift + mu. Returns lambda (nan where not converged in 40 steps) and the mean
    steps a point."""
    points = shift.size
    x = np.broadcast_to(_start_vector(size), (points, size))
    cur = (x, None, x, None)
    lam, active, rows = np.full(points, np.nan), np.arange(points), 0
    for step in range(1, 41):
        prev = cur
        x, kx = unit(sk.solve(prev[0]), prev[0])  # (K - shift) x = kx
        y, ky = unit(sk.solve_transposed(prev[2]), prev[2])
        cur, rows = (x, kx, y, ky), rows + active.size
        if step < first or (step - first) % every:
            continue
        mu, bound = check(cur, prev, active)
        lam_a = shift[active] + mu
        conv = (bound <= rtol * np.abs(lam_a)) & (lam_a >= SHIFT)
        lam[active[conv]] = lam_a[conv]
        if conv.all():
            break
        keep = np.flatnonzero(~conv)
        active, sk = active[keep], sk.take(keep)
        cur, prev = tuple(v[keep] for v in cur), tuple(v if v is None else v[keep] for v in prev)
    return lam, rows / points


def plain(cur, prev, active):
    """The engine's test: the two-sided quotient and first-order bound |r| |l| / |y.x|."""
    x, kx, y, ky = cur
    yx = _rowdot(y, x)
    mu = _rowdot(y, kx) / yx
    rx, ry = kx - col(mu) * x, ky - col(mu) * y
    return mu, np.sqrt(_rowdot(rx, rx) * _rowdot(ry, ry)) / np.abs(yx)


def gram(cur, prev, active):
    """:func:`plain` from row dot products (no residual vectors), with a rounding allowance."""
    x, kx, y, ky = cur
    yx = _rowdot(y, x)
    mu = _rowdot(y, kx) / yx
    parts = []
    for v, kv in ((x, kx), (y, ky)):
        kk, kv_v = _rowdot(kv, kv), _rowdot(kv, v)
        parts.append(np.maximum(kk - 2.0 * mu * kv_v + mu * mu + 8 * EPS * (kk + mu * mu), 0.0))
    return mu, np.sqrt(parts[0] * parts[1]) / np.abs(yx)


def _orthogonal(v, kv, vp, kvp):
    """The unit direction of vp orthogonal to v (v unit), and (K - shift) of it."""
    a = col(_rowdot(v, vp))
    d, kd = vp - a * v, kvp - a * kv
    return unit(d, kd)


def ritz(cur, prev, active):
    """Two-sided Rayleigh-Ritz on span{x, x_prev}, span{y, y_prev}: the Ritz value nearest the
    single-vector quotient, and the bound of its Ritz vectors."""
    x, kx, y, ky = cur
    dx, kdx = _orthogonal(x, kx, prev[0], prev[1])
    dy, kdy = _orthogonal(y, ky, prev[2], prev[3])
    m = [[_rowdot(w, v) for v in (x, dx)] for w in (y, dy)]
    t = [[_rowdot(w, kv) for kv in (kx, kdx)] for w in (y, dy)]
    mu0 = t[0][0] / m[0][0]
    a = m[0][0] * m[1][1] - m[0][1] * m[1][0]  # det(T - mu M) = a mu^2 + b mu + c
    b = -(t[0][0] * m[1][1] + t[1][1] * m[0][0] - t[0][1] * m[1][0] - t[1][0] * m[0][1])
    c = t[0][0] * t[1][1] - t[0][1] * t[1][0]
    q = -0.5 * (b + np.copysign(np.sqrt(np.maximum(b * b - 4 * a * c, 0.0)), b))
    with np.errstate(all="ignore"):
        roots = q / a, c / q
        mu = np.where(np.abs(roots[0] - mu0) < np.abs(roots[1] - mu0), *roots)
        e = [[t[i][j] - mu * m[i][j] for j in range(2)] for i in range(2)]
        cx = np.where(np.abs(e[0][1]) >= np.abs(e[1][1]), -e[0][0] / e[0][1], -e[1][0] / e[1][1])
        cy = np.where(np.abs(e[1][0]) >= np.abs(e[1][1]), -e[0][0] / e[1][0], -e[0][1] / e[1][1])
    cx, cy = col(np.nan_to_num(cx)), col(np.nan_to_num(cy))
    return plain((x + cx * dx, kx + cx * kdx, y + cy * dy, ky + cy * kdy), None, active)


def k_products(mf: modal_form.ModalFamily, twist, nu) -> Callable:
    """A test in float64 with true products K z, K^T w (for the float32 iteration)."""
    coef = term_coefficients(twist, nu)[:, :, None]
    (s1, z1, c1), (s2, z2, c2) = modal_form.MODAL_TERMS
    d = (coef[:, z1] - coef[:, s1] * mf.lam1, coef[:, z2] - coef[:, s2] * mf.lam2)
    a1, a2, k1 = 2.0 * coef[:, c1], 2.0 * coef[:, c2], mf.lam1.size

    def check(cur, prev, active):
        z, w = (v.astype(float) for v in (cur[0], cur[2]))
        d1, d2, b1, b2 = d[0][active], d[1][active], a1[active], a2[active]
        kz = np.hstack([d1 * z[:, :k1] + b1 * (z[:, k1:] @ mf.g12.T),
                        d2 * z[:, k1:] + b2 * (z[:, :k1] @ mf.g21.T)])
        kw = np.hstack([d1 * w[:, :k1] + b2 * (w[:, k1:] @ mf.g21),
                        d2 * w[:, k1:] + b1 * (w[:, :k1] @ mf.g12)])
        return plain((z, kz - SHIFT * z, w, kw - SHIFT * w), None, active)

    return check


@contextmanager
def per_point_shift(shift: np.ndarray):
    """_ShiftedModal.at with a shift per point (a column broadcasts where SHIFT stood)."""
    modules = (E, modal_form, shifted)  # every module that reads SHIFT on this path
    for module in modules:
        module.SHIFT = shift[:, None]
    try:
        yield
    finally:
        for module in modules:
            module.SHIFT = SHIFT


def single(mf: modal_form.ModalFamily) -> modal_form.ModalFamily:
    """The modal family in float32."""
    arrays = {f.name: getattr(mf, f.name).astype(np.float32)
              for f in dataclasses.fields(mf) if isinstance(getattr(mf, f.name), np.ndarray)}
    return dataclasses.replace(mf, **arrays)


def at_single(mf32: modal_form.ModalFamily, twist, nu) -> _ShiftedModal:
    """_ShiftedModal.at in float32, its Schur complements inverted by unchecked blocks."""
    real = shifted.stacked_inverse
    shifted.stacked_inverse = block_inverse
    try:
        return _ShiftedModal.at(mf32, twist.astype(np.float32), nu.astype(np.float32))
    finally:
        shifted.stacked_inverse = real


def minima(fns: list[Callable], rounds: int = ROUNDS) -> list[float]:
    """Minimum wall time of each function over `rounds` interleaved rounds."""
    best = [np.inf] * len(fns)
    for _ in range(rounds):
        for i, fn in enumerate(fns):
            t = time.perf_counter()
            fn()
            best[i] = min(best[i], time.perf_counter() - t)
    return best


def groups(tol: float):
    d = load_figure1()
    tw, nv = d["twist_angle"].to_numpy(), d["nu"].to_numpy()
    deg = solve_degrees(initial_degree(tw, tol))
    for n in np.unique(deg).tolist():
        for family in ("symmetric", "antisymmetric"):
            yield n, family, modal_form.modal_family(n, family), tw[deg == n], nv[deg == n]


def compare(name: str, n: int, family: str, mf: modal_form.ModalFamily, tw, nv,
            rtol: float) -> None:
    """Run alternative `name` and its plain loop on one degree group; print a row."""
    exact = E.lowest_eigenpair(mf, tw, nv, rtol=E.POWER_RTOL)[0]
    size, fixed = mf.lam1.size + mf.lam2.size, np.full(tw.size, SHIFT)
    shift, setup, check, first, every = fixed, nullcontext, plain, 2, 1
    base_first, base_every = 2, 1  # the plain loop: a test every step, as the alternative's
    if name.startswith("shift"):
        shift = exact * (1.0 - float(name.split()[1]))
        setup = lambda: per_point_shift(shift)  # noqa: E731
    elif name == "ritz":
        check, first = ritz, 3
    elif name == "float32":
        mf32 = single(mf)
        check, first, every = k_products(mf, tw, nv), 4, 2
        base_first, base_every = 4, 2
    else:  # gram: the engine's schedule
        check, first, every = gram, 4, 2
        base_first, base_every = 4, 2

    def alternative():
        with setup():
            sk = at_single(mf32, tw, nv) if name == "float32" else _ShiftedModal.at(mf, tw, nv)
        return iterate(sk, size, shift, check, rtol, first, every)

    def baseline():
        return iterate(_ShiftedModal.at(mf, tw, nv), size, fixed, plain, rtol, base_first,
                       base_every)

    lam, steps = alternative()
    plain_steps = baseline()[1]
    if name == "ritz":
        print(f"  contraction median (lambda_1 - SHIFT)/(lambda_j - SHIFT): j = 2 "
              f"{np.median(contraction(n, family, tw, nv, 2)):.3f}, j = 3 "
              f"{np.median(contraction(n, family, tw, nv, 3)):.3f}")
    times = minima([alternative, baseline,
                    lambda: E.lowest_eigenpair(mf, tw, nv, rtol=rtol)])
    diff = np.nanmax(np.abs(lam / exact - 1)) if np.isfinite(lam).any() else np.nan
    print(f"{name:<14}{n:>3} {family:<14}{steps:>6.2f}{plain_steps:>7.2f}"
          f"{np.isnan(lam).mean():>9.3f}{diff:>10.1e}"
          f"{times[0] / times[1]:>8.2f}{times[0] / times[2]:>8.2f}")


def main() -> None:
    print(f"{'alternative':<14}{'n':>3} {'family':<14}{'steps':>6}{'plain':>7}{'unconv.':>9}"
          f"{'max diff':>10}{'/plain':>8}{'/engine':>8}")
    plan = ((1e-12, ("shift 1e-4", "shift 1e-3", "shift 1e-2", "ritz")),
            (1e-4, ("float32", "gram")), (1e-6, ("float32",)), (1e-2, ("gram",)))
    with one_blas_thread():
        for tol, names in plan:
            for n, family, mf, tw, nv in groups(tol):
                if tol == 1e-12 and n not in (20, 24):  # the large groups
                    continue
                for name in names:
                    compare(name, n, family, mf, tw, nv, E.iteration_rtol(tol))


def near_fifty() -> None:
    """Relative errors against the mpmath reference near |Omega(L)| = 50 (tol 1e-12)."""
    def ref(om, nu):
        return float(characteristic_critical_load(float(om), float(nu)).p_star)

    # the map's (tests/bench/test_benchmarks.py) worst sampled point
    om, nu = float(np.linspace(0.0, 100.0, 200)[94]), float(np.linspace(1.0, 100.0, 200)[97])
    res = critical_load(om, nu, full_output=True)
    print(f"\nmap point ({om:.2f}, {nu:.2f}): auto n = {res.n}, error "
          f"{abs(res.p_star / ref(om, nu) - 1):.2e}, estimate {res.error_estimate:.1e}; forced n:",
          ", ".join(f"{n}: {abs(critical_load(om, nu, n=n) / ref(om, nu) - 1):.1e}"
                    for n in (50, 56, 66, 80)))
    rng = np.random.default_rng(1)
    tw = np.concatenate([rng.uniform(40, 50, 30), rng.uniform(20, 40, 15)])
    nv = np.exp(rng.uniform(0, np.log(100), tw.size))
    exact = np.array([ref(a, b) for a, b in zip(tw, nv, strict=True)])
    batch = np.abs(critical_load(tw, nv) / exact - 1)
    one = [critical_load(float(a), float(b), full_output=True) for a, b in zip(tw, nv, strict=True)]
    err = np.abs(np.array([r.p_star for r in one]) / exact - 1)
    print(f"45 random points, Omega(L) in [20, 50]: array call max {batch.max():.1e}; scalar calls "
          f"max {err.max():.1e}, max error/estimate "
          f"{(err / np.array([r.error_estimate for r in one])).max():.2f}")


if __name__ == "__main__":
    from spectral_rod.rod.collocation import modal_kernel

    modal_kernel._library = lambda: None  # the numpy iteration (module docstring)
    main()
    near_fifty()
