"""The operations the collocation solver's rules are written against, for arrays and for one point.

Each rule of the degree loop (the a priori degree, the error estimate, the shortfall, the raise,
the family choice) is written once, against a namespace ``xp`` of the few operations it uses:
:data:`ARRAYS` (numpy, for flat arrays of points) or :data:`FLOATS` (Python's own functions, for
one point given as Python floats: a scalar call's cost is mostly numpy's per-call overhead, ~1 us
a call on a tiny array). Both namespaces perform the same IEEE operations in the same order, so a
rule gives the same bits either way (``tests/test_arithmetic.py`` compares them), except
``cbrt``: numpy's cube root and ``v ** (1/3)`` may differ in the last bit, which moves a degree
only where the a priori formula lands within an ulp of an even integer.

>>> import numpy as np
>>> from spectral_rod.rod.collocation.arithmetic import ARRAYS, FLOATS
>>> FLOATS.where(True, 1.0, 2.0), ARRAYS.where(np.array([True, False]), 1.0, 2.0).tolist()
(1.0, [1.0, 2.0])
"""

from __future__ import annotations

import math
from types import SimpleNamespace
from typing import Any

import numpy as np

__all__ = ["ARRAYS", "FLOATS", "Namespace"]

#: The type of :data:`ARRAYS` and :data:`FLOATS` (attributes: abs, maximum, minimum, ceil, log10,
#: cbrt, where, clip, asfloat, to_int).
Namespace = SimpleNamespace


def _ceil(v: float) -> float:
    """math.ceil as a float, and inf for inf (numpy's ``ceil`` does both)."""
    return float(math.ceil(v)) if math.isfinite(v) else v


def _where(condition: bool, a: Any, b: Any) -> Any:
    return a if condition else b


def _clip(v: float, lo: float, hi: float) -> float:
    return min(hi, max(lo, v))


#: numpy's functions, for flat arrays of points (``asfloat`` makes an array of float,
#: ``to_int`` an array of int).
ARRAYS = SimpleNamespace(
    abs=np.abs, maximum=np.maximum, minimum=np.minimum, ceil=np.ceil, log10=np.log10,
    cbrt=np.cbrt, where=np.where, clip=lambda v, lo, hi: np.minimum(hi, np.maximum(lo, v)),
    asfloat=lambda v: np.asarray(v, dtype=float), to_int=lambda v: np.asarray(v).astype(int))

#: Python's functions, for one point in Python floats.
FLOATS = SimpleNamespace(
    abs=abs, maximum=max, minimum=min, ceil=_ceil, log10=math.log10,
    cbrt=lambda v: v ** (1.0 / 3.0), where=_where, clip=_clip, asfloat=float, to_int=int)
