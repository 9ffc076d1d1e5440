"""Small dense linear algebra on one BLAS thread (a speed policy of the whole library).

The package's matrices are small (tens to a few hundred rows). Handed to a multithreaded BLAS,
each call wakes worker threads whose start-up and spinning cost more than the work; on a
machine whose cores are busy with other jobs that varies wildly (measured on a shared 2-core
machine: the near-degenerate increment solved point by point takes 2.7 ms a
point on one thread and 24 ms on two). The
public entry points therefore run their solvers inside :func:`one_blas_thread`, which sets the
BLAS libraries loaded in the process (numpy's, and scipy's once scipy.linalg is imported) to
one thread through threadpoolctl and restores the caller's setting on exit. The setting is
process-wide: a caller running the package from several threads at once sees one BLAS thread
while any call is inside.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

__all__ = ["one_blas_thread"]

_CONTROLLERS: dict[bool, list[Any]] = {}


def _blas_controllers() -> list[Any]:
    """threadpoolctl's controllers of the loaded BLAS libraries (inspecting the process costs
    ~1 ms, so it is done once, and once more after scipy.linalg, which brings its own copy)."""
    key = "scipy.linalg" in sys.modules
    found = _CONTROLLERS.get(key)
    if found is None:
        from threadpoolctl import ThreadpoolController

        found = ThreadpoolController().select(user_api="blas").lib_controllers
        _CONTROLLERS[key] = found
    return found


@contextmanager
def one_blas_thread() -> Iterator[None]:
    """Run the body with every loaded BLAS on one thread; restore the previous counts after.

    >>> with one_blas_thread():
    ...     pass
    """
    changed = []
    for lib in _blas_controllers():
        n = lib.get_num_threads()
        if n != 1:
            lib.set_num_threads(1)
            changed.append((lib, n))
    try:
        yield
    finally:
        for lib, n in changed:
            lib.set_num_threads(n)
