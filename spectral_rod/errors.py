"""The package's exceptions and warnings, in one hierarchy.

Every error the package raises on purpose is a :class:`SpectralRodError`; bad input raises the
built-in ``ValueError``/``TypeError`` (with the argument's name and allowed range), as Python
users expect. A result that misses its tolerance is either flagged and warned about
(:class:`ConvergenceWarning`) or, where no usable value exists, raised
(:class:`ConvergenceError` and its subclasses).

Example
-------
>>> import warnings, spectral_rod
>>> with warnings.catch_warnings():
...     warnings.simplefilter("error", spectral_rod.ConvergenceWarning)
...     spectral_rod.critical_load(5.0, 1.5)   # converges: no warning
... # doctest: +ELLIPSIS
1.1...
"""

from __future__ import annotations

__all__ = [
    "ConvergenceError",
    "ConvergenceWarning",
    "PerformanceWarning",
    "ReferenceDataError",
    "RingConvergenceError",
    "RootNotFoundError",
    "SpectralRodError",
]


class SpectralRodError(Exception):
    """Base class of the errors raised by spectral_rod (other than bad input).

    Examples
    --------
    >>> import spectral_rod as sr
    >>> issubclass(sr.ConvergenceError, SpectralRodError)
    True
    """


class ConvergenceError(SpectralRodError, RuntimeError):
    """A computation did not reach its tolerance and has no usable result.

    Examples
    --------
    >>> issubclass(ConvergenceError, RuntimeError)
    True
    """


class RingConvergenceError(ConvergenceError):
    """The ring's critical load did not converge to the requested tolerance.

    Examples
    --------
    >>> issubclass(RingConvergenceError, ConvergenceError)
    True
    """


class RootNotFoundError(SpectralRodError, RuntimeError):
    """No sign change of a characteristic determinant in the scanned load range.

    Examples
    --------
    >>> issubclass(RootNotFoundError, SpectralRodError)
    True
    """


class ReferenceDataError(SpectralRodError, ValueError):
    """The digitised Figure 1 file is unreadable or breaks its schema (message names both).

    Examples
    --------
    >>> issubclass(ReferenceDataError, ValueError)   # a bad file is bad input
    True
    """


class ConvergenceWarning(RuntimeWarning):
    """The requested tolerance was not met (resolution cap or round-off); the result is flagged
    ``converged=False`` in the full output.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", ConvergenceWarning)   # the standard filter silences it
    ...     warnings.warn("tol not met", ConvergenceWarning)
    """


class PerformanceWarning(UserWarning):
    """A computation runs on a slower engine than the package can have: the C kernel is not
    built (no C compiler at install), disabled or refused at load. Issued once per process, at
    the first solve; silence it with ``warnings.filterwarnings("ignore",
    category=spectral_rod.errors.PerformanceWarning)``.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", PerformanceWarning)   # the standard filter silences it
    ...     warnings.warn("numpy engine", PerformanceWarning)
    """
