"""Where the batched engine's time goes: the work per point and family on Figure 1's points.

    python tests/bench/work_per_point.py

For each degree group of the Figure 1 batch at tol 1e-12 and each mode family: the Schur and
eliminated block sizes k_s, k_e; the multiply-adds a point costs (forming the Schur complement
k_e k_s^2, inverting it ~k_s^3, each two-sided shift-and-invert step 2 (2 k_e k_s + k_s^2)) with
the steps it took (counted rows of ``_ShiftedModal.solve``, the numpy iteration); the
contraction per step (lambda_1 - SHIFT)/(lambda_2 - SHIFT) from the full ``eig`` of the pencil
(median, max); the wall time per point of ``solve_family`` (minimum of 15, one BLAS thread) with
the numpy iteration and the multiply-add rate it implies, and with the C kernel
(``spectral_rod.rod.collocation.modal_kernel``, where built) and its rate. tests/bench/HISTORY.md's
account of why numpy's engine could not reach 50x the baseline, and of what the kernel changed,
quotes this. A development tool, not a test (pytest does not collect it).
"""

from __future__ import annotations

import time

import numpy as np

from spectral_rod import load_figure1
from spectral_rod._blas_threads import one_blas_thread
from spectral_rod.rod.collocation import eigensolver as E
from spectral_rod.rod.collocation import modal_form, modal_kernel, reference, shifted
from spectral_rod.rod.collocation.discretisation import family_operator
from spectral_rod.rod.collocation.driver import solve_degrees
from spectral_rod.rod.collocation.resolution import initial_degree
from spectral_rod.rod.families import FAMILIES, SHIFT


def contraction(n: int, family: str, tw: np.ndarray, nv: np.ndarray, j: int = 2
                ) -> np.ndarray:
    """(lambda_1 - SHIFT)/(lambda_j - SHIFT) per point, from the full eig with the rule (j = 3:
    the contraction once the second eigenvector's component is removed)."""
    a, b = family_operator(n, family).pencil(tw, nv)
    theta = np.linalg.eigvals(np.linalg.solve(a, np.broadcast_to(b, a.shape)))
    out = []
    for row in theta:
        ok = (np.abs(row.imag) <= reference.IMAG_REL * np.abs(row)) & (row.real > 0)
        lam = np.sort(1.0 / row.real[ok])
        out.append((lam[0] - SHIFT) / (lam[j - 1] - SHIFT))
    return np.array(out)


def steps_per_point(n: int, family: str, tw: np.ndarray, nv: np.ndarray, rtol: float) -> float:
    """Mean shift-and-invert steps a point took (rows through ``_ShiftedModal.solve``)."""
    rows = []
    solve = shifted._ShiftedModal.solve

    def counting(self, v, out=None):
        rows.append(v.shape[0])
        return solve(self, v, out)

    shifted._ShiftedModal.solve = counting
    try:
        E.solve_family(n, family, tw, nv, rtol=rtol)
    finally:
        shifted._ShiftedModal.solve = solve
    return sum(rows) / tw.size


def best_time(n: int, family: str, tw: np.ndarray, nv: np.ndarray, rtol: float,
              kernel: bool) -> float:
    """Minimum of 15 timings of solve_family, by the C kernel or by the numpy iteration."""
    library = modal_kernel._library
    if not kernel:
        modal_kernel._library = lambda: None
    try:
        best = np.inf
        for _ in range(15):
            t = time.perf_counter()
            E.solve_family(n, family, tw, nv, rtol=rtol)
            best = min(best, time.perf_counter() - t)
    finally:
        modal_kernel._library = library
    return best


def main() -> None:
    d = load_figure1()
    tw, nv = d["twist_angle"].to_numpy(), d["nu"].to_numpy()
    tol = 1e-12
    deg = solve_degrees(initial_degree(tw, tol))
    rtol = E.iteration_rtol(tol)
    print(f"{'n':>3} {'family':<14}{'points':>7}{'k_e':>5}{'k_s':>5}{'steps':>7}"
          f"{'madds':>8}{'contr. med':>11}{'max':>7}{'us/pt':>8}{'madds/s':>10}"
          f"{'kernel':>8}{'madds/s':>10}")
    kernel = modal_kernel.available()
    with one_blas_thread():
        for n in np.unique(deg).tolist():
            sel = deg == n
            for family in FAMILIES:
                mf = modal_form.modal_family(n, family)
                k1, k2 = mf.lam1.size, mf.lam2.size
                k_s, k_e = (k2, k1) if mf.schur == 2 else (k1, k2)
                library = modal_kernel._library
                modal_kernel._library = lambda: None  # the steps are counted in numpy's code
                try:
                    steps = steps_per_point(n, family, tw[sel], nv[sel], rtol)
                finally:
                    modal_kernel._library = library
                madds = k_e * k_s**2 + k_s**3 + steps * 2 * (2 * k_e * k_s + k_s**2)
                c = contraction(n, family, tw[sel], nv[sel])
                per_point = best_time(n, family, tw[sel], nv[sel], rtol, False) / sel.sum()
                line = (f"{n:>3} {family:<14}{int(sel.sum()):>7}{k_e:>5}{k_s:>5}{steps:>7.2f}"
                        f"{madds:>8.0f}{np.median(c):>11.3f}{c.max():>7.3f}"
                        f"{per_point * 1e6:>8.2f}{madds / per_point:>10.2e}")
                if kernel:
                    fast = best_time(n, family, tw[sel], nv[sel], rtol, True) / sel.sum()
                    line += f"{fast * 1e6:>8.2f}{madds / fast:>10.2e}"
                print(line)


if __name__ == "__main__":
    main()
