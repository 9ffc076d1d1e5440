"""Is the batched engine's numpy the limit? The same algorithm as
:func:`spectral_rod.rod.collocation.eigensolver.lowest_eigenpair` (Schur complement of the modal
form, LU with partial pivoting, shift-and-invert steps on right and left vectors, the same
first-order convergence test: first check at step 6, then every 2) written as plain C loops per
point (``lowest.c``), against the numpy code on the Figure 1 points, interleaved. A measurement
for issue 14 (not part of the package; needs gcc):

    gcc -O3 -march=native -shared -fPIC -o /tmp/liblowest.so lowest.c
    python measure.py /tmp/liblowest.so
"""

from __future__ import annotations

import ctypes
import sys
import time

import numpy as np
from numpy.ctypeslib import ndpointer

from spectral_rod import load_figure1
from spectral_rod.rod.collocation.discretisation import term_coefficients
from spectral_rod.rod.collocation.eigensolver import lowest_eigenpair
from spectral_rod.rod.collocation.modal_form import MODAL_TERMS, _start_vector, modal_family
from spectral_rod.rod.families import SHIFT


def _library(path: str) -> ctypes.CDLL:
    lib = ctypes.CDLL(path)
    d, i = ndpointer(np.float64, flags="C"), ndpointer(np.int32, flags="C")
    lib.lowest.argtypes = ([ctypes.c_int] * 3 + [d] * 8
                           + [ctypes.c_double, ctypes.c_double, ctypes.c_int, ctypes.c_int, d, i])
    return lib


def _inputs(mf, twist, nu):
    """The Schur-complement ingredients of :class:`_ShiftedModal` (before its inverse)."""
    coef = term_coefficients(twist, nu)[:, :, None]
    (s1, z1, c1), (s2, z2, c2) = MODAL_TERMS
    d1, d2 = coef[:, z1] - coef[:, s1] * mf.lam1, coef[:, z2] - coef[:, s2] * mf.lam2
    a1, a2 = 2.0 * coef[:, c1], 2.0 * coef[:, c2]
    k1 = mf.lam1.size
    if mf.schur == 2:
        parts = (slice(0, k1), slice(k1, None), d1, d2, a1, a2, mf.g12, mf.g21)
    else:
        parts = (slice(k1, None), slice(0, k1), d2, d1, a2, a1, mf.g21, mf.g12)
    elim, kept, d_e, d_s, a, b, g_es, g_se = parts
    return (elim, kept, np.ascontiguousarray(1.0 / (d_e - SHIFT)), a.ravel().copy(),
            b.ravel().copy(), np.ascontiguousarray(d_s - SHIFT), np.ascontiguousarray(g_es),
            np.ascontiguousarray(g_se))


def main(path: str) -> None:
    lib = _library(path)
    d = load_figure1()
    tw, nu = d["twist_angle"].to_numpy(), d["nu"].to_numpy()
    for n in (22, 30):
        for fam in ("symmetric", "antisymmetric"):
            mf = modal_family(n, fam)
            st = _start_vector(mf.lam1.size + mf.lam2.size)
            st = st / np.linalg.norm(st)

            def c_run(mf=mf, st=st):
                elim, kept, r_e, a, b, d_s, g_es, g_se = _inputs(mf, tw, nu)
                lam, steps = np.empty(tw.size), np.empty(tw.size, np.int32)
                lib.lowest(tw.size, r_e.shape[1], d_s.shape[1], r_e, a, b, d_s, g_es, g_se,
                           np.ascontiguousarray(st[elim]), np.ascontiguousarray(st[kept]),
                           SHIFT, 1e-14, 6, 40, lam, steps)
                return lam

            def np_run(mf=mf):
                return lowest_eigenpair(mf, tw, nu, rtol=1e-14)[0]

            diff = np.nanmax(np.abs(c_run() / np_run() - 1))
            tc, tn = [], []
            for _ in range(25):
                t = time.perf_counter()
                c_run()
                tc.append(time.perf_counter() - t)
                t = time.perf_counter()
                np_run()
                tn.append(time.perf_counter() - t)
            print(f"n = {n} {fam}: C {min(tc) / tw.size * 1e6:.2f} us a point, numpy "
                  f"{min(tn) / tw.size * 1e6:.2f}, numpy/C {min(tn) / min(tc):.2f} "
                  f"(interleaved minima); eigenvalues agree to {diff:.1e}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "./liblowest.so")
