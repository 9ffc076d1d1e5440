r"""The engine of the collocation eigenvalue of Eq. ``inst1``: the C kernel ``_modal_kernel``,
its loader, its contract's ctypes mirror, and what it reports about itself.

:func:`.eigensolver.lowest_eigenpair` is a fixed sequence of small dense operations per point:
the Schur complement of K - SHIFT, its factors, a few shift-and-invert steps on right and left
vectors and a convergence test. numpy runs each operation on the whole stack, but on matrices
of k = 10..30 its per-matrix loops (and LAPACK's per-matrix calls) are slow, and a C loop per
point gains little (one point's own loops are short and dependent; ``tests/bench/c_prototype``).
``_modal_kernel.c`` runs the same algorithm with the arrays laid out [index][point] for 32
points at a time, so that every inner loop is over independent points and the compiler
vectorises it, the convergence test, the mode's vectors, its tail and the pencil's quotient
too (:func:`modal_points`: both families at every point, the engine of every call shape; a
call's last few points one lane each, the same code on one lane). :func:`modal_lowest` is the
same iteration for one family, returning the eigenvectors (a family on its own, and the
batched numpy engine's comparisons). ``python tests/bench/kernel_range.py`` and
``tests/bench/work_per_point.py`` measure it against the numpy reference.

It differs from the numpy reference in two ways, both checked per point: the Schur complement's
LU has no pivoting, accepted by the probe test of :func:`.stacked_inverse.stacked_inverse`
(:data:`.stacked_inverse.BACKWARD_TOL`) or the point is returned as rejected and the numpy
reference solves it; and the arithmetic is done in another order, so results agree to rounding
(``tests/test_modal_kernel.py`` compares the two).

:func:`pencil_terms` gives the bilinear forms of the two-sided Rayleigh quotient of the pencil
(:func:`.quotient.pencil_rayleigh_quotient`) in double-double, for |Omega(L)| > LONG_TWIST
where its terms cancel to ~lambda/Omega^2 (the quotients agree with numpy's ``longdouble`` sums
to 4 eps and with 50-digit sums, ``tests/test_modal_kernel.py``).

The contract
------------
``_modal_kernel.h`` documents every entry point LAPACK-style (in/out, dimension, meaning, an
INFO return). Arguments travel as structs (:class:`ModalControl`, :class:`ModalBatch`,
:class:`ModalEigenpairs`, :class:`Family`, :class:`ModalPoints`, :class:`ModalPointResults`,
:class:`PencilForms`, the ctypes mirrors of the header's). At load the build's
``MODAL_KERNEL_ABI`` must equal :data:`ABI_VERSION` and every struct's C size its mirror's;
otherwise the kernel is refused, the numpy reference runs, and :func:`engine_info` says why.

The kernel is built at install (``setup.py``; optional). Without it, or with the environment
variable ``SPECTRAL_ROD_NO_KERNEL=1`` set before the first solve, the numpy reference is the
engine, and the first solve warns once with a :class:`spectral_rod.errors.PerformanceWarning`
(:func:`warn_if_missing`). ctypes releases the GIL during a call; the kernel allocates its own
workspace, so calls from several threads are safe.
"""

from __future__ import annotations

import ctypes
import importlib.util
import os
import warnings
from functools import lru_cache
from typing import Any, ClassVar, NamedTuple

import numpy as np
from numpy.typing import NDArray

from spectral_rod.errors import PerformanceWarning

__all__ = ["ABI_VERSION", "ABOVE", "CONVERGED", "DISABLE_ENV", "NOT_CONVERGED", "REJECTED",
           "Family", "KernelResult", "ModalBatch", "ModalControl", "ModalEigenpairs",
           "ModalPointResults", "ModalPoints", "PencilForms", "available", "engine_info",
           "engine_name", "modal_lowest", "modal_points", "pencil_terms", "warn_if_missing"]

#: Status codes of a point (MODAL_* in ``_modal_kernel.h``).
NOT_CONVERGED, CONVERGED, ABOVE, REJECTED = 0, 1, 2, -1
#: The ABI this module speaks (``MODAL_KERNEL_ABI`` in ``_modal_kernel.h``).
ABI_VERSION = 3
#: Set to 1 (before the first solve) to run the numpy reference as the engine.
DISABLE_ENV = "SPECTRAL_ROD_NO_KERNEL"


class KernelResult(NamedTuple):
    """Per point: lambda (the two-sided quotient of K), the unit right and left modal vectors
    split into the eliminated (e) and Schur (s) blocks, and the status code."""

    lam: NDArray[np.float64]
    x_e: NDArray[np.float64]
    x_s: NDArray[np.float64]
    y_e: NDArray[np.float64]
    y_s: NDArray[np.float64]
    status: NDArray[np.int32]


_PTR, _INT, _DBL = ctypes.c_void_p, ctypes.c_int, ctypes.c_double


class ModalControl(ctypes.Structure):
    """The iteration's settings (``ModalControl`` in ``_modal_kernel.h``)."""

    _fields_ = (("shift", _DBL), ("rtol", _DBL), ("backward_tol", _DBL), ("close_rel", _DBL),
                ("first", _INT), ("max_steps", _INT), ("loose", _INT), ("few", _INT))


class ModalBatch(ctypes.Structure):
    """K - SHIFT at P points in its Schur blocks (``ModalBatch`` in ``_modal_kernel.h``)."""

    _fields_ = [("P", _INT), ("ke", _INT), ("ks", _INT)] + [
        (name, _PTR) for name in ("r_e", "a", "b", "d_s", "g_es", "g_se", "start_e", "start_s",
                                  "ceiling")]


class ModalEigenpairs(ctypes.Structure):
    """modal_lowest's outputs (``ModalEigenpairs`` in ``_modal_kernel.h``)."""

    _fields_ = tuple((name, _PTR) for name in ("lam", "x_e", "x_s", "y_e", "y_s", "status"))


class Family(ctypes.Structure):
    """One mode family at one degree (``Family`` in ``_modal_kernel.h``;
    :func:`.eigensolver.kernel_families` fills it). The arrays it points to must outlive it:
    the builder keeps them."""

    _fields_: ClassVar[Any] = [("k1", _INT), ("k2", _INT), ("schur", _INT),
                ("own2", _INT * 2), ("own0", _INT * 2), ("coupling", _INT * 2)] + [
        (name, _PTR) for name in ("lam1", "lam2", "g12", "g21", "u1", "u2", "left1", "left2",
                                  "start")] + [
        ("tail_count", _INT)] + [
        (name, _PTR) for name in ("tail_rows", "term_shape", "term_mats", "mass")]


class ModalPoints(ctypes.Structure):
    """Points given by their INST1 coefficients (``ModalPoints`` in ``_modal_kernel.h``)."""

    _fields_ = (("P", _INT), ("terms", _INT), ("coef", _PTR), ("coef_lo", _PTR))


class ModalPointResults(ctypes.Structure):
    """modal_points' outputs (``ModalPointResults`` in ``_modal_kernel.h``)."""

    _fields_ = (("lam", _PTR), ("tail", _PTR), ("status", _PTR))


class PencilForms(ctypes.Structure):
    """pencil_terms_dd's arguments (``PencilForms`` in ``_modal_kernel.h``)."""

    _fields_ = [("P", _INT), ("m", _INT), ("T", _INT)] + [
        (name, _PTR) for name in ("shape", "mats", "x", "y", "hi", "lo")]


#: The mirrors in the order of ``modal_struct_size``'s argument.
_STRUCTS = (ModalControl, ModalBatch, ModalEigenpairs, Family, ModalPoints, ModalPointResults,
            PencilForms)


@lru_cache(maxsize=1)
def _loaded() -> tuple[ctypes.CDLL | None, str]:
    """The compiled kernel and "", or None and why it is not used."""
    if os.environ.get(DISABLE_ENV, "") not in ("", "0"):
        return None, f"disabled by the environment variable {DISABLE_ENV}"
    spec = importlib.util.find_spec("spectral_rod.rod.collocation._modal_kernel")
    if spec is None or spec.origin is None:
        return None, "not built (no C compiler at install)"
    try:
        lib = ctypes.CDLL(spec.origin)
        for name in ("modal_lowest", "modal_points", "pencil_terms_dd", "modal_abi_version",
                     "modal_lanes", "modal_isa", "modal_struct_size"):
            getattr(lib, name)
    except (OSError, AttributeError) as exc:
        return None, f"a build this package cannot use ({exc})"
    return _checked(lib)


def _checked(lib: ctypes.CDLL) -> tuple[ctypes.CDLL | None, str]:
    """`lib` with its signatures declared if its ABI version and struct sizes match this
    module's, else None and the mismatch."""
    lib.modal_abi_version.restype = _INT
    version = lib.modal_abi_version()
    if version != ABI_VERSION:
        return None, f"its ABI version is {version}, this package needs {ABI_VERSION}"
    lib.modal_struct_size.argtypes, lib.modal_struct_size.restype = [_INT], ctypes.c_size_t
    for which, struct in enumerate(_STRUCTS):
        if lib.modal_struct_size(which) != ctypes.sizeof(struct):
            return None, (f"struct {struct.__name__} is {lib.modal_struct_size(which)} bytes "
                          f"in C, {ctypes.sizeof(struct)} in its ctypes mirror")
    ref = ctypes.POINTER
    lib.modal_lowest.argtypes = [ref(ModalBatch), ref(ModalControl), ref(ModalEigenpairs)]
    lib.modal_points.argtypes = [ref(Family), ref(ModalPoints), ref(ModalControl),
                                 ref(ModalPointResults)]
    lib.pencil_terms_dd.argtypes = [ref(PencilForms)]
    for name in ("modal_lowest", "modal_points", "pencil_terms_dd", "modal_lanes"):
        getattr(lib, name).restype = _INT
    lib.modal_isa.restype = ctypes.c_char_p
    return lib, ""


def _library() -> ctypes.CDLL | None:
    """The compiled kernel, or None where it is not built, disabled or refused."""
    return _loaded()[0]


def available() -> bool:
    """Whether the compiled kernel is installed, enabled and accepted at load."""
    return _library() is not None


def engine_name() -> str:
    """The engine of the collocation eigenvalue: "kernel" or "numpy" (its reference)."""
    return "kernel" if available() else "numpy"


def engine_info() -> dict[str, Any]:
    """What runs the collocation eigenvalue here, for ``python -m spectral_rod info``.

    Keys: ``engine`` ("kernel" or "numpy"), ``available`` (bool), ``reason`` (why the kernel is
    not used, "" if it is), ``isa`` (the instruction-set variant the loader picked, e.g.
    "x86-64-v3"; None without the kernel), ``abi_version`` (the build's; None without it),
    ``abi_expected`` (:data:`ABI_VERSION`), ``lanes`` (points iterated side by side; None
    without it), ``disable_env`` (:data:`DISABLE_ENV`).

    >>> sorted(engine_info())[:3]
    ['abi_expected', 'abi_version', 'available']
    """
    lib, reason = _loaded()
    info: dict[str, Any] = {"engine": engine_name(), "available": lib is not None,
                            "reason": reason, "isa": None, "abi_version": None,
                            "abi_expected": ABI_VERSION, "lanes": None,
                            "disable_env": DISABLE_ENV}
    if lib is not None:
        info.update(isa=lib.modal_isa().decode(), abi_version=lib.modal_abi_version(),
                    lanes=lib.modal_lanes())
    return info


_warned = False


def warn_if_missing() -> None:
    """Warn once per process, at the first solve, that the numpy reference is the engine
    (a :class:`spectral_rod.errors.PerformanceWarning`, silenceable by the warnings filter)."""
    global _warned
    if _warned or available():
        return
    _warned = True
    reason = _loaded()[1] or "not loaded"
    warnings.warn(
        f"spectral_rod runs its numpy engine, 2-5 times slower than the C kernel (the kernel "
        f"is {reason}). To get it, install a C compiler (e.g. gcc) and reinstall the "
        f"package (pip install --force-reinstall --no-deps .), unset {DISABLE_ENV}; "
        f"spectral_rod.rod.collocation.modal_kernel.engine_info() shows the engine",
        PerformanceWarning, stacklevel=3)


def _call(name: str, *args: Any) -> None:
    """Call the kernel's function `name`; RuntimeError if it is not available, ValueError on an
    illegal argument (INFO < 0), MemoryError if it could not allocate its workspace."""
    lib = _library()
    if lib is None:
        raise RuntimeError("the compiled kernel _modal_kernel is not used: "
                           f"{_loaded()[1] or 'not loaded'}")
    info = getattr(lib, name)(*(ctypes.byref(a) for a in args))
    if info < 0:
        raise ValueError(f"{name}: argument {-info} has an illegal value (_modal_kernel.h)")
    if info > 0:
        raise MemoryError("the kernel could not allocate its workspace")


def _ptr(a: Any) -> int | None:
    """The address of a C-contiguous array (None for a null pointer). A writable, non-empty
    array's address is read through ``ctypes.c_char.from_buffer`` (~0.2 us; ``a.ctypes.data``
    builds a helper object, ~0.8 us, a few percent of a scalar call per pointer)."""
    if a is None:
        return None
    if not a.flags.c_contiguous:
        raise ValueError("the kernel needs C-contiguous arrays")
    if a.flags.writeable and a.nbytes:
        return ctypes.addressof(ctypes.c_char.from_buffer(a))
    return a.ctypes.data


def _c_array(a: NDArray) -> NDArray[np.float64]:
    return np.ascontiguousarray(a, dtype=np.float64)


def _control(shift: float, rtol: float, first: int, max_steps: int, backward_tol: float,
             close_rel: float = 0.0, loose: bool = False, few: int = 0) -> ModalControl:
    return ModalControl(shift, rtol, backward_tol, close_rel, first, max_steps, int(loose),
                        few)


def modal_lowest(r_e: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64],
                 d_s: NDArray[np.float64], g_es: NDArray[np.float64],
                 g_se: NDArray[np.float64], start_e: NDArray[np.float64],
                 start_s: NDArray[np.float64], ceiling: NDArray[np.float64] | None, *,
                 shift: float, rtol: float, first: int, max_steps: int, backward_tol: float
                 ) -> KernelResult:
    """:func:`.eigensolver.lowest_eigenpair`'s iteration for P points by the C kernel
    (``modal_lowest`` in ``_modal_kernel.h``).

    Inputs as :class:`.shifted._ShiftedModal` holds them: r_e (P, k_e) = 1/(D_e - SHIFT),
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
    _call("modal_lowest", ModalBatch(p, k_e, k_s, *map(_ptr, ins)),
          _control(shift, rtol, first, max_steps, backward_tol),
          ModalEigenpairs(*map(_ptr, out)))
    return out


def pencil_terms(shape: NDArray[np.int32], mats: NDArray[np.float64], x: NDArray[np.float64],
                 y: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The bilinear forms y_e^T M_t x_f of the pencil's terms per point in double-double
    (hi + lo, each (P, T); ``pencil_terms_dd`` in ``_modal_kernel.h``).

    ``shape`` (T, 5) gives each term's (row offset, rows, column offset, columns, offset in
    ``mats``), ``mats`` the terms' matrices (row-major, concatenated); x, y (P, m).
    """
    x, y = _c_array(x), _c_array(y)
    p, m = x.shape
    count = shape.shape[0]
    hi, lo = np.empty((p, count)), np.empty((p, count))
    shape = np.ascontiguousarray(shape, dtype=np.int32)
    mats = _c_array(mats)
    _call("pencil_terms_dd", PencilForms(p, m, count, *map(_ptr, (shape, mats, x, y, hi, lo))))
    return hi, lo


def modal_points(families: ctypes.Array, coef: NDArray[np.float64], *, shift: float,
                 rtol: float, first: int, max_steps: int, backward_tol: float,
                 close_rel: float, loose: bool, few: int,
                 coef_lo: NDArray[np.float64] | None = None
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int32]]:
    """Both families at P points, 32 side by side (``modal_points`` in ``_modal_kernel.h``;
    a last group of at most ``few`` points one lane each): lambda, the mode's tail and the
    status, each (P, 2). ``coef`` (P, terms) are the points' INST1 coefficients. lambda is the
    pencil's two-sided quotient (unless ``loose``: the modal one), summed in double, or where
    ``coef_lo`` (P, terms), the low parts of the coefficients in extended precision, is given,
    in double-double (for |Omega| > LONG_TWIST)."""
    coef = _c_array(coef)
    p, terms = coef.shape
    lam, tail = np.empty((p, 2)), np.empty((p, 2))
    status = np.empty((p, 2), dtype=np.int32)
    lo = None if coef_lo is None else _c_array(coef_lo)
    lib = _library()
    if lib is None:
        raise RuntimeError("the compiled kernel _modal_kernel is not used: "
                           f"{_loaded()[1] or 'not loaded'}")
    info = lib.modal_points(families, ctypes.byref(ModalPoints(p, terms, _ptr(coef), _ptr(lo))),
                            ctypes.byref(_control(shift, rtol, first, max_steps, backward_tol,
                                                  close_rel, loose, few)),
                            ctypes.byref(ModalPointResults(_ptr(lam), _ptr(tail), _ptr(status))))
    if info < 0:
        raise ValueError(f"modal_points: argument {-info} has an illegal value (_modal_kernel.h)")
    if info > 0:
        raise MemoryError("the kernel could not allocate its workspace")
    return lam, tail, status
