"""Input checks shared by the public functions: every bad value gets a ValueError or TypeError
that names the argument and its allowed range."""

from __future__ import annotations

import numbers
from typing import cast

import numpy as np
from numpy.typing import ArrayLike, NDArray


def real_array(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """`value` as a float array; non-numeric input raises TypeError, NaN/inf raises ValueError."""
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be a real number or an array of real numbers, "
                        f"got {type(value).__name__}")
    if isinstance(value, np.ma.MaskedArray) and np.ma.is_masked(value):
        raise TypeError(f"{name}: masked arrays are not supported (the mask would be ignored); "
                        f"pass the unmasked entries only")
    try:
        arr = np.asarray(value)
    except Exception as exc:  # pragma: no cover - numpy raises many things here
        raise TypeError(f"{name} must be a real number or array, got {value!r}") from exc
    if arr.dtype == object or arr.dtype.kind not in "iufc":  # bool, str, datetime, timedelta
        raise TypeError(f"{name} must be a real number or an array of real numbers, "
                        f"got dtype {arr.dtype}")
    if np.iscomplexobj(arr):
        raise TypeError(f"{name} must be real-valued, got complex input")
    arr = arr.astype(np.float64)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite (no NaN or inf), got {value!r}")
    return arr


def as_float(value: numbers.Real, name: str, allowed: str) -> float:
    """float(value), with a ValueError naming `name` and the `allowed` range for an integer
    beyond the float range (float() raises OverflowError there)."""
    try:
        return float(value)
    except OverflowError:
        raise ValueError(f"{name} must be {allowed}, got an integer of "
                         f"{len(str(abs(value)))} digits") from None


def check_choice(value: object, name: str, choices: tuple[str, ...]) -> str:
    """`value` if it is one of the strings `choices`, else TypeError/ValueError naming them."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be one of {choices}, got {type(value).__name__}")
    if value not in choices:
        raise ValueError(f"{name} must be one of {choices}, got {value!r}")
    return value


#: The admitted ranges of the straight-rod arguments (one place: the scalar fast path of
#: :func:`spectral_rod.critical_load` tests them without these functions' array machinery).
TWIST_MAX, NU_MAX, TOL_RANGE = 1.0e4, 1.0e4, (1.0e-14, 1.0e-2)


def check_twist(twist_angle: ArrayLike, name: str = "twist_angle",
                max_abs: float = TWIST_MAX) -> NDArray[np.float64]:
    """Total twist angle Omega(L) in radians, any sign (p* is even in it), |Omega(L)| <= max_abs."""
    arr = real_array(twist_angle, name)
    if np.any(np.abs(arr) > max_abs):
        raise ValueError(f"{name} must satisfy |{name}| <= {max_abs:g} rad, "
                         f"got max |{name}| = {np.max(np.abs(arr)):g}")
    return arr


def check_nu(nu: ArrayLike, name: str = "nu", max_value: float = NU_MAX) -> NDArray[np.float64]:
    """Cross-section asymmetry nu = I2/I1 in [1, max_value]; the paper's convention is A1 <= A2."""
    arr = real_array(nu, name)
    if np.any(arr < 1.0):
        raise ValueError(
            f"{name} = I2/I1 must be >= 1 (the paper sets A1 <= A2, u0 along the axis of the "
            f"smaller stiffness); for I2 < I1 swap the axes and pass 1/{name}. "
            f"Got min {name} = {np.min(arr):g}")
    if np.any(arr > max_value):
        raise ValueError(f"{name} must be <= {max_value:g}, got max {name} = {np.max(arr):g}")
    return arr


def check_resolution(n: object, name: str = "n", minimum: int = 4, maximum: int = 1024) -> int:
    """An even integer Chebyshev degree in [minimum, maximum]."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"{name} must be an integer (even, {minimum}..{maximum}) or None, "
                        f"got {type(n).__name__}")
    n = int(n)
    if n < minimum or n > maximum or n % 2:
        raise ValueError(f"{name} must be an even integer in [{minimum}, {maximum}], got {n}")
    return n


def check_tol(tol: object, name: str = "tol") -> float:
    """A relative tolerance in TOL_RANGE = [1e-14, 1e-2]."""
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real):
        raise TypeError(f"{name} must be a real number, got {type(tol).__name__}")
    tol = as_float(tol, name, f"in [{TOL_RANGE[0]:g}, {TOL_RANGE[1]:g}]")
    if not (TOL_RANGE[0] <= tol <= TOL_RANGE[1]):
        raise ValueError(f"{name} must be in [{TOL_RANGE[0]:g}, {TOL_RANGE[1]:g}], "
                         f"got {tol!r}")
    return tol


def scalar_value(arr: NDArray[np.float64], name: str) -> float:
    """The float in a 0-d array; TypeError naming the argument for an array of any other shape."""
    if arr.ndim != 0:
        raise TypeError(f"{name} must be a scalar (a real number), got an array of shape "
                        f"{arr.shape}")
    return float(arr)


def check_real(value: object, name: str, lo: float = -np.inf, hi: float = np.inf, *,
               lo_open: bool = False, hi_open: bool = False) -> float:
    """A real scalar in [lo, hi] (open ends if asked) as a float.

    Any ``numbers.Real`` is accepted (numpy scalars and 0-d arrays included); bool, str,
    complex and arrays of other shapes are TypeErrors ("must be a scalar"), NaN/inf and values
    out of range ValueErrors; every message names the argument and the range.

    >>> check_real(np.float32(0.5), "tol", 0.0, 1.0)
    0.5
    """
    rng = f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        what = (f"an array of shape {np.shape(value)}" if isinstance(value, (list, tuple,
                                                                          np.ndarray))
                else type(value).__name__)
        raise TypeError(f"{name} must be a scalar real number in {rng}, got {what}")
    v = as_float(value, name, f"in {rng}")
    if not np.isfinite(v):
        raise ValueError(f"{name} must be finite, in {rng}, got {v!r}")
    if v < lo or v > hi or (lo_open and v == lo) or (hi_open and v == hi):
        raise ValueError(f"{name} must be in {rng}, got {v!r}")
    return v


def check_int(value: object, name: str, lo: int, hi: int) -> int:
    """An integer scalar in [lo, hi] (numpy integers accepted; bool, float and str are not).

    >>> check_int(np.int64(201), "points", 2, 100_000)
    201
    """
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer in [{lo}, {hi}], got {type(value).__name__}")
    v = int(value)
    if not lo <= v <= hi:
        raise ValueError(f"{name} must be an integer in [{lo}, {hi}], got {v}")
    return v


def check_bool(value: object, name: str) -> bool:
    """True or False (numpy booleans accepted; 0, 1, 'no' are not)."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be True or False, got {type(value).__name__}")
    return bool(value)


def broadcast_points(**arrays: NDArray[np.float64]) -> tuple[int, ...]:
    """The common broadcast shape of the named arrays; ValueError naming them and their shapes
    if they do not broadcast."""
    try:
        return np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
        raise ValueError(f"{', '.join(arrays)} must broadcast to one shape, got {shapes}"
                         ) from None


def _scalar(value: object, name: str, what: str) -> float:
    """`value` unwrapped from a 0-d array; TypeError for arrays, bool, str, complex."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        got = (f"an array of shape {np.shape(value)}" if isinstance(value, (list, tuple,
                                                                         np.ndarray))
               else type(value).__name__)
        raise TypeError(f"{name} must be a scalar ({what}), got {got}")
    return cast(float, value)  # a numbers.Real: numpy converts it as it does a float


def scalar_nu(nu: object, name: str = "nu", max_value: float = 1.0e4) -> float:
    """A scalar nu = I2/I1 in [1, max_value], with :func:`check_nu`'s messages (the A1 <= A2
    convention)."""
    return float(check_nu(_scalar(nu, name, f"nu = I2/I1 in [1, {max_value:g}]"), name,
                          max_value))


def scalar_twist(twist_angle: object, name: str = "twist_angle", max_abs: float = 1.0e4
                 ) -> float:
    """A scalar total twist angle Omega(L) in [-max_abs, max_abs] radians."""
    return float(check_twist(_scalar(twist_angle, name, f"|{name}| <= {max_abs:g} rad"), name,
                             max_abs))
