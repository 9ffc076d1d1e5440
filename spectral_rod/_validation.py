"""Input checks shared by the public functions: every bad value gets a ValueError or TypeError
that names the argument and its allowed range."""

from __future__ import annotations

import numbers

import numpy as np
from numpy.typing import ArrayLike, NDArray


def real_array(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """`value` as a float array; non-numeric input raises TypeError, NaN/inf raises ValueError."""
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be a real number or an array of real numbers, "
                        f"got {type(value).__name__}")
    try:
        arr = np.asarray(value)
    except Exception as exc:  # pragma: no cover - numpy raises many things here
        raise TypeError(f"{name} must be a real number or array, got {value!r}") from exc
    if arr.dtype == object or np.issubdtype(arr.dtype, np.bool_) \
            or not np.issubdtype(arr.dtype, np.number):
        raise TypeError(f"{name} must be a real number or an array of real numbers, "
                        f"got dtype {arr.dtype}")
    if np.iscomplexobj(arr):
        raise TypeError(f"{name} must be real-valued, got complex input")
    arr = arr.astype(np.float64)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite (no NaN or inf), got {value!r}")
    return arr


def check_choice(value: object, name: str, choices: tuple[str, ...]) -> str:
    """`value` if it is one of the strings `choices`, else TypeError/ValueError naming them."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be one of {choices}, got {type(value).__name__}")
    if value not in choices:
        raise ValueError(f"{name} must be one of {choices}, got {value!r}")
    return value


def check_twist(twist_angle: ArrayLike, name: str = "twist_angle",
                max_abs: float = 1.0e4) -> NDArray[np.float64]:
    """Total twist angle Omega(L) in radians, any sign (p* is even in it), |Omega(L)| <= max_abs."""
    arr = real_array(twist_angle, name)
    if np.any(np.abs(arr) > max_abs):
        raise ValueError(f"{name} must satisfy |{name}| <= {max_abs:g} rad, "
                         f"got max |{name}| = {np.max(np.abs(arr)):g}")
    return arr


def check_nu(nu: ArrayLike, name: str = "nu", max_value: float = 1.0e4) -> NDArray[np.float64]:
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
    """A relative tolerance in [1e-14, 1e-2]."""
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real):
        raise TypeError(f"{name} must be a real number, got {type(tol).__name__}")
    tol = float(tol)
    if not (1.0e-14 <= tol <= 1.0e-2):
        raise ValueError(f"{name} must be in [1e-14, 1e-2], got {tol!r}")
    return tol


def scalar_value(arr: NDArray[np.float64], name: str) -> float:
    """The float in a 0-d array; TypeError naming the argument for an array of any other shape."""
    if arr.ndim != 0:
        raise TypeError(f"{name} must be a scalar (a real number), got an array of shape "
                        f"{arr.shape}")
    return float(arr)
