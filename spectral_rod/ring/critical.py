"""The ring's public solvers: the critical load in either formulation, and whether and where
spontaneous twist raises or lowers it (the paper's Sec. on the ring, Eq. ``crit2``'s claims).

:func:`ring_critical_load` dispatches to the second variation
(:mod:`spectral_rod.ring.second_variation`, the default) or to the paper's equilibrium equations
(:mod:`spectral_rod.ring.munder`); :func:`twist_raises_load` is the one predicate behind "twist
destabilises the ring" and :func:`destabilisation_threshold` scans nu for where it turns.
Both formulations import nothing from here, so the ring's modules form no import cycle.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.linalg
import scipy.optimize
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import (
    check_choice,
    check_nu,
    check_real,
    real_array,
)
from spectral_rod.ring.formula import check_e_ratio, check_twist_count
from spectral_rod.ring.second_variation import MAX_SOLVER_TWIST, check_load, ring_buckling

#: The formulations of the ring problem (``method=`` of :func:`ring_critical_load`):
#: "second-variation" -- this module (the sympy second variation of the energy, Fourier-Galerkin);
#: "munder" -- :mod:`spectral_rod.ring.munder` (the paper's equilibrium equations Eq. ``Munder``
#: with ``constit`` and ``frenet``, linearised numerically about the loaded circle).
RING_METHODS = ("second-variation", "munder")


def ring_critical_load(N: object, nu: object, *, e_ratio: object = 1.0,
                       load: object = "hydrostatic", tol: float = 1.0e-12,
                       method: str = "second-variation") -> float:
    """Converged critical load q_cr R^3/(E1 I1) of the twisted ring (Omega = N s/R).

    N >= 0 integer turns of the cross-section, nu = I2/I1 >= 1, e = E2/E1 > 0 (A3 = e (1+nu)
    E1 I1), load "hydrostatic" (pressure on the ring's projection, force q e_z x R') or "axis"
    (force -q e_r at the displaced point: horizontal, toward the ring's axis); see the module
    docstring. ``method``: one of :data:`RING_METHODS` (two formulations that share no hand
    derivation). Raises :class:`spectral_rod.RingConvergenceError` if not converged to ``tol``:
    ``tol`` in :data:`spectral_rod._validation.TOL_RANGE` for "second-variation",
    :data:`spectral_rod.ring.munder.TOL_RANGE` for "munder" (outside it a ValueError names it).
    Use :func:`ring_buckling` for the mode, its kind and the convergence record.

    Returns
    -------
    float
        The converged q_cr R^3/(E1 I1).

    Examples
    --------
    >>> round(ring_critical_load(0, 1.0), 12)   # untwisted circular ring: out of plane, 2
    2.0
    """
    if check_choice(method, "method", RING_METHODS) == "munder":
        from spectral_rod.ring.munder import munder_critical_load

        return munder_critical_load(N, nu, e_ratio=e_ratio, load=load, tol=tol)
    return ring_buckling(N, nu, e_ratio=e_ratio, load=load, tol=tol).load


def _max_twist(method: str) -> int:
    """The largest N the formulation `method` solves."""
    if method == "munder":
        from spectral_rod.ring.munder import MAX_TWIST

        return MAX_TWIST
    return MAX_SOLVER_TWIST


def _check_twists(twists: object, maximum: int = MAX_SOLVER_TWIST) -> tuple[int, ...]:
    if isinstance(twists, (str, bytes)) or not hasattr(twists, "__iter__") or (
            isinstance(twists, np.ndarray) and twists.ndim == 0):  # iterating a 0-d array fails
        raise TypeError(f"twists must be a sequence of integers N >= 0 including 0, got "
                        f"{type(twists).__name__}")
    out = tuple(check_twist_count(N, "twists", maximum)
                for N in twists)
    if 0 not in out or len(set(out)) < 2 or len(set(out)) != len(out):
        raise ValueError(f"twists must hold 0 and at least one N > 0, each once, got {out}")
    return out


def _check_nus(nus: object) -> NDArray[np.float64]:
    grid = np.atleast_1d(check_nu(nus, "nus"))  # type: ignore[arg-type]
    if grid.ndim != 1 or grid.size < 2 or np.any(np.diff(grid) <= 0):
        raise ValueError(f"nus must be >= 2 increasing values of nu = I2/I1 >= 1, got {nus!r}")
    return grid


#: Relative margin of :func:`twist_raises_load`: q_cr(N) counts as raised by twist if it is at
#: least q_cr(0) (1 - RAISE_TOL). An empirical round-off margin, not a physical one: each q_cr
#: is converged to 1e-12 (second variation) or 1e-10 (Munder's default), the circular ring
#: (nu = 1, where twist cannot change q_cr) gives |q_cr(N)/q_cr(0) - 1| ~ 1e-15, and the
#: smallest genuine gap on the ring scene's scans (nu > 1) is ~8e-4 (dead load, nu = 50); 1e-9
#: lies well between.
RAISE_TOL = 1.0e-9


def twist_raises_load(q_twisted: ArrayLike, q_untwisted: object) -> bool | NDArray[np.bool_]:
    """Whether twist raises the ring's critical load: q_cr(N) >= q_cr(0) to round-off.

    The one predicate behind "twist destabilises the ring" (its negation: twist lowers q_cr)
    and :func:`destabilisation_threshold`: True iff ``q_twisted >= q_untwisted * (1 -
    RAISE_TOL)``. The tolerance :data:`RAISE_TOL` (public: ``spectral_rod.RING_RAISE_TOL``) =
    1e-9 relative is an empirical round-off margin: the converged loads are accurate to 1e-12
    (second variation) ... 1e-10 (Munder), twist-independent loads (nu = 1) agree to ~1e-15,
    while the changes twist makes on the ring scene's scans (nu > 1) are ~8e-4 and more. A load
    equal to q_cr(0) to round-off therefore counts as raised (twist does not lower it).

    ``q_twisted``: q_cr(N) R^3/(E1 I1), a real number or an array (then an array of bools);
    ``q_untwisted``: q_cr(0), a positive real number (the reference of the relative margin).

    Returns
    -------
    bool or ndarray of bool
        True where twist does not lower the load.

    Examples
    --------
    >>> twist_raises_load(3.0 * (1 - 1e-12), 3.0), twist_raises_load(2.9, 3.0)
    (True, False)
    >>> twist_raises_load([2.9, 3.1], 3.0).tolist()
    [False, True]
    """
    q = real_array(q_twisted, "q_twisted")
    q0 = check_real(q_untwisted, "q_untwisted", 0.0, math.inf, lo_open=True)
    raised = q >= q0 * (1.0 - RAISE_TOL)
    return bool(raised) if raised.ndim == 0 else raised


def _highest_twisted(q: NDArray[np.float64], twists: tuple[int, ...]) -> tuple[float, float]:
    """(max over N > 0 of q(N), q(0)) for loads `q` ordered like `twists`."""
    return (float(max(q[i] for i, N in enumerate(twists) if N > 0)),
            float(q[twists.index(0)]))


def _twist_gain(q: NDArray[np.float64], twists: tuple[int, ...]) -> float:
    """max over N > 0 of q(N)/q(0) - 1 for loads `q` ordered like `twists`."""
    q_max, q0 = _highest_twisted(q, twists)
    return q_max / q0 - 1.0


def _check_grid_loads(loads: object, shape: tuple[int, int]) -> NDArray[np.float64] | None:
    if loads is None:
        return None
    arr = real_array(loads, "loads")  # type: ignore[arg-type]
    if arr.shape != shape:
        raise ValueError(f"loads must be critical loads of shape (len(nus), len(twists)) = "
                         f"{shape}, got shape {arr.shape}")
    if np.any(arr <= 0):
        raise ValueError(f"loads must be positive critical loads, got min {np.min(arr):g}")
    return arr


def destabilisation_threshold(e_ratio: object, load: object, nus: object, *,
                              twists: object = tuple(range(11)), xtol: float = 1.0e-3,
                              loads: object = None, method: str = "second-variation") -> float:
    """The asymmetry nu* above which some spontaneous twist raises the ring's critical load.

    Some twist raises q_cr at nu if :func:`twist_raises_load` holds for the largest q_cr(N, nu)
    over N > 0 in ``twists`` against q_cr(0, nu) (q_cr(N) >= q_cr(0) to the round-off margin
    :data:`RAISE_TOL`, public as ``spectral_rod.RING_RAISE_TOL``); otherwise every twist lowers
    q_cr (twist destabilises). The grid ``nus`` (increasing, nu >= 1) is scanned for the first
    interval from a nu where every twist lowers q_cr to one where some twist raises it, and nu*
    is refined there by Brent's method to ``xtol`` in nu as the root of the twist gain g(nu) =
    max over N > 0 of q_cr(N)/q_cr(0) - 1 (the interval's upper end itself if it is raised
    within the margin only, g in [-RAISE_TOL, 0)); ``math.nan`` if there is no such interval on
    the grid. A node at nu = 1 (the circular ring, where twist changes nothing: g = 0 to
    round-off) counts as raised and so opens no interval: start the grid above 1 (e.g. 1.01).
    ``loads``: q_cr already solved on the grid (shape (len(nus), len(twists)), e.g. a
    scan of the caller's), so that the scan solves nothing again; otherwise the scan solves them.
    ``method``: one of :data:`RING_METHODS` (the formulation of every solve). e = E2/E1 and the
    load model as in :func:`ring_critical_load`.

    Returns
    -------
    float
        nu* (to ``xtol``), or ``math.nan`` if no such interval lies on the grid.

    Examples
    --------
    >>> nu_star = destabilisation_threshold(1.0, "hydrostatic", [2.0, 4.0], twists=(0, 1))
    >>> 2.0 < nu_star < 4.0
    True
    """
    e, ld = check_e_ratio(e_ratio), check_load(load)
    method = check_choice(method, "method", RING_METHODS)
    grid = _check_nus(nus)
    Ns = _check_twists(twists, _max_twist(method))
    xtol = check_real(xtol, "xtol", 1e-12, 1.0)
    known = _check_grid_loads(loads, (grid.size, len(Ns)))

    def solve(nu: float) -> NDArray[np.float64]:
        return np.array([ring_critical_load(N, nu, e_ratio=e, load=ld, method=method)
                         for N in Ns])

    loads_at = [known[i] if known is not None else solve(float(nu)) for i, nu in enumerate(grid)]
    raised = [bool(twist_raises_load(*_highest_twisted(q, Ns))) for q in loads_at]
    i = next((i for i in range(grid.size - 1) if not raised[i] and raised[i + 1]), None)
    if i is None:
        return math.nan
    a, b = float(grid[i]), float(grid[i + 1])
    ends = {a: _twist_gain(loads_at[i], Ns), b: _twist_gain(loads_at[i + 1], Ns)}
    if ends[b] < 0:  # raised at b within the round-off margin only: b is nu* to round-off
        return b
    # Brent evaluates both ends first: their gains are known already
    return float(scipy.optimize.brentq(
        lambda v: ends[v] if v in ends else _twist_gain(solve(v), Ns), a, b, xtol=xtol))
