r"""The batched engine's lowest eigenpair (Eq. ``inst1``, modal form) as a C kernel, 32 points
side by side; and the pencil's Rayleigh-quotient terms in double-double.

:func:`.eigensolver.lowest_eigenpair` is a fixed sequence of small dense operations per point:
the Schur complement of K - SHIFT, its factors, ~7 shift-and-invert steps on right and left
vectors and a convergence test. numpy runs each operation on the whole stack, but on matrices
of k = 10..30 its per-matrix loops (and LAPACK's per-matrix calls) run ~1e9 multiply-adds a
second, and a C loop per point was no faster (~1.15 times: one point's own loops are short and
dependent; ``tests/bench/c_prototype``). ``_modal_kernel.c`` runs the same algorithm with the
arrays laid out [index][point] for 32 points at a time, so that every inner loop is over
independent points and the compiler vectorises it, the convergence test too: 0.14-0.25 of the
numpy iteration's time at n = 22-40 (``tests/bench/kernel_range.py``), a family's whole solve on
Figure 1's points at n = 22 and 26 1.3-1.7 against 5.3-7.1 µs a point
(``tests/bench/work_per_point.py``; 2026-12-05, two runs each).

It differs from the numpy code in two ways, both checked per point: the Schur complement's LU
has no pivoting, accepted by the probe test of :func:`.stacked_inverse.stacked_inverse`
(:data:`.stacked_inverse.BACKWARD_TOL`) or the point is returned as rejected and the numpy code
solves it; and the arithmetic is done in another order, so results agree to rounding
(``tests/test_modal_kernel.py`` compares the two).

:func:`pencil_terms` gives the bilinear forms of the two-sided Rayleigh quotient of the pencil
(:func:`.eigensolver.pencil_rayleigh_quotient`) in double-double, for |Omega(L)| > LONG_TWIST =
10 where its terms cancel to ~lambda/Omega^2 and they were summed in numpy's ``longdouble`` (no
BLAS there: 2.8-14 µs a point at n = 24-56, against 0.4-1.6 µs here,
``tests/bench/kernel_range.py``; the quotients agree to 4 eps and with 50-digit sums,
``tests/test_modal_kernel.py``). :func:`modal_points` with ``coef_lo`` completes the quotient
of one point in double-double in C (``quotient_dd``: a second, lean implementation of the last
step of :func:`.eigensolver._rayleigh_sums`, which sums the same forms in long double; a scalar
call and an array call agree within the round-off bound, ``tests/test_safety.py``).

The kernel is built at install (``setup.py``; optional: without a C compiler the package
installs without it, and :func:`available` is False) and loaded with :mod:`ctypes` on first
use (ctypes releases the GIL during the call; the kernel allocates its own workspace, so calls
from several threads are safe).
"""

from __future__ import annotations

import ctypes
import importlib.util
from functools import lru_cache
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

__all__ = ["ABOVE", "CONVERGED", "NOT_CONVERGED", "REJECTED", "Family", "KernelResult",
           "available", "modal_lowest", "modal_points", "pencil_terms"]

#: Status codes of a point (as in ``_modal_kernel.c``).
NOT_CONVERGED, CONVERGED, ABOVE, REJECTED = 0, 1, 2, -1


class KernelResult(NamedTuple):
    """Per point: lambda (the two-sided quotient of K), the unit right and left modal vectors
    split into the eliminated (e) and Schur (s) blocks, and the status code."""

    lam: NDArray[np.float64]
    x_e: NDArray[np.float64]
    x_s: NDArray[np.float64]
    y_e: NDArray[np.float64]
    y_s: NDArray[np.float64]
    status: NDArray[np.int32]


class Family(ctypes.Structure):
    """One mode family at one degree for :func:`modal_points` (the ``Family`` struct of
    ``_modal_kernel.c``; :func:`.eigensolver.kernel_families` fills it). The arrays it points
    to must outlive it: the builder keeps them."""

    _fields_ = [("k1", ctypes.c_int), ("k2", ctypes.c_int), ("schur", ctypes.c_int),
                ("own2", ctypes.c_int * 2), ("own0", ctypes.c_int * 2),
                ("coupling", ctypes.c_int * 2)] + [
        (name, ctypes.c_void_p) for name in ("lam1", "lam2", "g12", "g21", "u1", "u2", "left1",
                                             "left2", "start")] + [
        ("tail_count", ctypes.c_int)] + [
        (name, ctypes.c_void_p) for name in ("tail_rows", "term_shape", "term_mats", "mass")]


@lru_cache(maxsize=1)
def _library() -> ctypes.CDLL | None:
    """The compiled kernel, or None where it was not built."""
    spec = importlib.util.find_spec("spectral_rod.straight_rod._modal_kernel")
    if spec is None or spec.origin is None:
        return None
    try:
        lib = ctypes.CDLL(spec.origin)
        lib.modal_lowest, lib.pencil_terms_dd, lib.modal_points  # noqa: B018 (a stale build)
    except (OSError, AttributeError):
        return None
    # arrays are passed as addresses (c_void_p): the dtypes and layouts are checked here
    ptr, c_int, c_dbl = ctypes.c_void_p, ctypes.c_int, ctypes.c_double
    lib.modal_lowest.argtypes = ([c_int] * 3 + [ptr] * 9 + [c_dbl, c_dbl, c_int, c_int, c_dbl]
                                 + [ptr] * 6)
    lib.modal_lowest.restype = c_int
    lib.pencil_terms_dd.argtypes = [c_int] * 3 + [ptr] * 6
    lib.pencil_terms_dd.restype = c_int
    lib.modal_points.argtypes = ([c_int, ctypes.POINTER(Family), c_int, ptr, ptr, c_dbl, c_dbl,
                                  c_int, c_int, c_dbl, c_dbl, c_int] + [ptr] * 3)
    lib.modal_points.restype = c_int
    return lib


def available() -> bool:
    """Whether the compiled kernel is installed and loads."""
    return _library() is not None


def _call(name: str, *args) -> None:
    """Call the kernel's function `name`; RuntimeError if it is not installed, MemoryError if it
    could not allocate its workspace (its only failure)."""
    lib = _library()
    if lib is None:
        raise RuntimeError("the compiled kernel _modal_kernel is not installed")
    if getattr(lib, name)(*args) != 0:
        raise MemoryError("the kernel could not allocate its workspace")


def _ptr(a: NDArray | None) -> int | None:
    """The address of a C-contiguous array (None for a null pointer)."""
    if a is None:
        return None
    if not a.flags.c_contiguous:
        raise ValueError("the kernel needs C-contiguous arrays")
    return a.ctypes.data


def _c_array(a: NDArray) -> NDArray[np.float64]:
    return np.ascontiguousarray(a, dtype=np.float64)


def modal_lowest(r_e: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64],
                 d_s: NDArray[np.float64], g_es: NDArray[np.float64],
                 g_se: NDArray[np.float64], start_e: NDArray[np.float64],
                 start_s: NDArray[np.float64], ceiling: NDArray[np.float64] | None, *,
                 shift: float, rtol: float, first: int, max_steps: int, backward_tol: float
                 ) -> KernelResult:
    """:func:`.eigensolver.lowest_eigenpair`'s iteration for P points by the C kernel.

    Inputs as :class:`.eigensolver._ShiftedModal` holds them: r_e (P, k_e) = 1/(D_e - SHIFT),
    a, b (P,), d_s (P, k_s) = D_s - SHIFT, G_es (k_e, k_s), G_se (k_s, k_e); the unit start
    vector's blocks; ``ceiling`` (P,) or None; the test from step ``first``, then every 2
    steps, up to ``max_steps``. Raises RuntimeError if the kernel is not available.
    """
    r_e, d_s = _c_array(r_e), _c_array(d_s)
    p, k_e = r_e.shape
    k_s = d_s.shape[1]
    out = KernelResult(np.full(p, np.nan), np.zeros((p, k_e)), np.zeros((p, k_s)),
                       np.zeros((p, k_e)), np.zeros((p, k_s)), np.zeros(p, dtype=np.int32))
    ins = [r_e, _c_array(a).ravel(), _c_array(b).ravel(), d_s, _c_array(g_es), _c_array(g_se),
           _c_array(start_e), _c_array(start_s),
           None if ceiling is None else _c_array(ceiling).ravel()]
    _call("modal_lowest", p, k_e, k_s, *map(_ptr, ins), shift, rtol, first, max_steps,
          backward_tol, *map(_ptr, out))
    return out


def pencil_terms(shape: NDArray[np.int32], mats: NDArray[np.float64], x: NDArray[np.float64],
                 y: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The bilinear forms y_e^T M_t x_f of the pencil's terms per point in double-double
    (hi + lo, each (P, T); see ``pencil_terms_dd`` in ``_modal_kernel.c``).

    ``shape`` (T, 5) gives each term's (row offset, rows, column offset, columns, offset in
    ``mats``), ``mats`` the terms' matrices (row-major, concatenated); x, y (P, m).
    """
    x, y = _c_array(x), _c_array(y)
    p, m = x.shape
    count = shape.shape[0]
    hi, lo = np.empty((p, count)), np.empty((p, count))
    shape = np.ascontiguousarray(shape, dtype=np.int32)
    mats = _c_array(mats)
    _call("pencil_terms_dd", p, m, count, _ptr(shape), _ptr(mats), _ptr(x), _ptr(y), _ptr(hi),
          _ptr(lo))
    return hi, lo


def modal_points(families: ctypes.Array, coef: NDArray[np.float64], *, shift: float,
                 rtol: float, first: int, max_steps: int, backward_tol: float,
                 close_rel: float, loose: bool, coef_lo: NDArray[np.float64] | None = None
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int32]]:
    """Both families at P points, one point at a time (``modal_points`` in ``_modal_kernel.c``):
    lambda, the mode's tail and the status, each (P, 2). ``coef`` (P, terms) are the points'
    INST1 coefficients. lambda is the pencil's two-sided quotient (unless ``loose``: the modal
    one), summed in double, or where ``coef_lo`` (P, terms), the low parts of the coefficients
    in extended precision, is given, in double-double (for |Omega| > LONG_TWIST)."""
    coef = _c_array(coef)
    p, terms = coef.shape
    lam, tail = np.empty((p, 2)), np.empty((p, 2))
    status = np.empty((p, 2), dtype=np.int32)
    lo = None if coef_lo is None else _c_array(coef_lo)
    _call("modal_points", p, families, terms, _ptr(coef), _ptr(lo), shift, rtol, first,
          max_steps, backward_tol, close_rel, int(loose), _ptr(lam), _ptr(tail), _ptr(status))
    return lam, tail, status
