r"""Every speed threshold and cost-model constant of the collocation solver of Eq. ``inst1``, and
the one map from a requested ``tol`` to the solver's settings (:func:`solver_settings`).

These constants decide how fast an answer comes, not what it is: each engine returns the same
eigenvalue to within the error estimate, and the tests hold that for every path. Each constant
names the script that measures it; re-tuning for another machine is a run of those scripts and
an edit of this module only.

What ``tol`` sets (:func:`solver_settings`)
--------------------------------------------
* the tail target ``truncation_share(tol) tol``: the degree holds the tail's part of the error
  estimate to it (:func:`.resolution.initial_degree`, :func:`.resolution.shortfall`): a tenth
  (TRUNCATION_SHARE) up to TIGHT_TOL, LOOSE_SHARE above (:func:`truncation_share`);
* the iteration's ``rtol = max(0.01 tol, POWER_RTOL)``: the accepted first-order error bound of
  the eigenvalue iteration (:func:`iteration_rtol`);
* the ``allowance`` the iteration may add beyond the calibrated error model, ``rtol`` less the
  ``rtol`` of CALIBRATED_TOL (:func:`iteration_allowance`), added to the error estimate;
* the loose quotient: from ``rtol >= LOOSE_RTOL`` on and up to degree LOOSE_DEGREE the
  eigenvalue is the modal quotient instead of the pencil's (:func:`loose_quotient`);
* the first convergence check: step FIRST_CHECK, LOOSE_FIRST_CHECK from LOOSE_RTOL on, at most
  4 where a ceiling may stop the iteration (:func:`first_check`);
* the extended-precision quotient: above |Omega| = LONG_TWIST unless the quotient is loose.

>>> s = solver_settings(1e-4)
>>> s.tail_target, round(s.iteration_rtol, 12), round(s.allowance, 12), s.loose_rtol
(9e-05, 1e-06, 1e-06, True)
>>> solver_settings(1e-12).allowance
0.0
"""

from __future__ import annotations

from typing import NamedTuple

__all__ = ["BLOCK_ENTRIES", "CALIBRATED_TOL", "CALL_COST", "CHUNK", "DENSE_ENTRIES", "FEW_POINTS",
           "FIRST_CHECK", "FIXED_COST", "KERNEL_MAX_SCHUR", "LEAN_FACTOR", "LEAN_MAX_DEGREE",
           "LONG_TWIST", "LOOSE_DEGREE", "LOOSE_FIRST_CHECK", "LOOSE_RTOL", "LOOSE_SHARE",
           "POINT_COST", "POINT_SCHUR_DEGREE", "POWER_RTOL", "POWER_STEPS", "SMALL_CALL",
           "TIGHT_TOL", "TRUNCATION_SHARE",
           "SolverSettings",
           "few_points_limit", "first_check", "iteration_allowance", "iteration_rtol",
           "loose_quotient", "solver_settings", "truncation_share"]

# --- what tol sets -------------------------------------------------------------------------

#: The share of tol the degree holds the tail's part of the estimate to, up to TIGHT_TOL: where
#: the estimate lands just below tol the error itself can come close to it (at tol 1e-12 the
#: default's sampled errors must stay <= 1e-13), so the tail is held to a tenth there. Above
#: TIGHT_TOL it is LOOSE_SHARE: the estimate is a calibrated bound there (the error at most
#: 0.88 of its tail part on the calibration grid, ``python tests/bench/tol_model_fit.py``), and a
#: tenth would deliver errors ~1e3-1e4 below tol; the rest of tol is the iteration's allowance
#: (0.01 tol) and round-off. ``python tests/bench/accuracy_at_tol.py`` measures what each tol
#: delivers; ``python tests/bench/hunt_tol.py`` hunts for misses at every tol. TIGHT_TOL keeps
#: the degrees of tol <= 1e-10 as they were fitted and measured.
TRUNCATION_SHARE, LOOSE_SHARE, TIGHT_TOL = 0.1, 0.9, 1e-10
#: The eigenvalue iteration's smallest accepted first-order error bound (relative), its step
#: cap, and the step of its first convergence check (then every 2 steps; a check costs about a
#: step). ``python tests/bench/work_per_point.py`` prints the steps taken.
POWER_RTOL, POWER_STEPS, FIRST_CHECK = 1.0e-15, 40, 6
#: From this rtol on the iteration is checked from step LOOSE_FIRST_CHECK, and up to degree
#: LOOSE_DEGREE the eigenvalue is the modal quotient w^T K z / w^T z instead of the pencil's:
#: K's round-off (eps n^4 in its diagonal) puts that quotient within 1.1e-10 of the pencil's up
#: to n = 64 (``tests/test_accuracy_control.py`` measures it), <= 0.011 of such an rtol and
#: inside :func:`iteration_allowance`. The Figure 1 batch at tol 1e-2..1e-6 in
#: ``python -m pytest -m bench -k tol_trade`` times the first check.
LOOSE_RTOL, LOOSE_DEGREE, LOOSE_FIRST_CHECK = 1.0e-8, 64, 4
#: Above this |Omega| the pencil's Rayleigh quotient is accumulated in extended precision (its
#: Omega^2 terms cancel to ~lambda/Omega^2): in double the error reached 0.96 of the
#: estimate's round-off part eps (32 + 0.3 Omega^2) at Omega(L) in [16, 20), in extended
#: precision at most 0.24 (``python tests/bench/accuracy_at_tol.py``, against the
#: characteristic equation).
LONG_TWIST = 10.0
#: The tol at which the error model of :func:`.resolution.error_estimate` was calibrated (the
#: default of :func:`spectral_rod.critical_load`): the iteration error at its iteration_rtol
#: (1e-14) is inside the model's measured round-off part.
CALIBRATED_TOL = 1e-12


def truncation_share(tol: float) -> float:
    """The share of `tol` the degree holds the tail's part of the error estimate to:
    TRUNCATION_SHARE up to TIGHT_TOL, LOOSE_SHARE above (their comment says why).

    >>> truncation_share(1e-12), truncation_share(1e-4)
    (0.1, 0.9)
    """
    return TRUNCATION_SHARE if tol <= TIGHT_TOL else LOOSE_SHARE


def iteration_rtol(tol: float) -> float:
    """The accepted relative error of the eigenvalue iteration for a requested `tol`: 1 % of it
    (negligible beside the discretisation error the estimate covers), at least POWER_RTOL."""
    return max(0.01 * tol, POWER_RTOL)


_CALIBRATED_RTOL = iteration_rtol(CALIBRATED_TOL)


def iteration_allowance(tol: float) -> float:
    """What the eigenvalue iteration may add to p*'s relative error beyond the calibrated error
    model, for a requested `tol`: iteration_rtol(tol) less that of CALIBRATED_TOL (0 for
    tol <= 1e-12; 0.01 tol - 1e-14 above). The collocation error estimate adds it.

    The iteration stops where its first-order error bound is <= iteration_rtol(tol) (the loose
    quotients of LOOSE_RTOL are inside it too). The tail alone does not see that error: at a
    degree above the a priori one (pooled or forced) the tail part can be far below it (at tol
    1e-4, forced collocation at Omega(L) 55-82 pooled at n = 64: errors up to 1.5e-8 against
    tail estimates of 2e-13; ``tests/test_accuracy_control.py`` holds the estimate with it).

    >>> iteration_allowance(1e-12), round(iteration_allowance(1e-4), 12)
    (0.0, 1e-06)
    """
    return max(0.0, iteration_rtol(tol) - _CALIBRATED_RTOL)


def loose_quotient(rtol: float, n: int) -> bool:
    """Whether the eigenvalue is the modal quotient rather than the pencil's (LOOSE_RTOL and
    LOOSE_DEGREE: the iteration's own quotient is accurate enough there)."""
    return rtol >= LOOSE_RTOL and n <= LOOSE_DEGREE


def first_check(rtol: float, ceiling: bool) -> int:
    """The step of the iteration's first convergence test: FIRST_CHECK, LOOSE_FIRST_CHECK from
    LOOSE_RTOL on, at most 4 where a ceiling may stop the iteration early."""
    first = FIRST_CHECK if rtol < LOOSE_RTOL else LOOSE_FIRST_CHECK
    return min(first, 4) if ceiling else first


class SolverSettings(NamedTuple):
    """What a requested tol sets (module docstring): the tail target, the iteration's rtol, the
    allowance added to the error estimate, whether the modal quotient is accepted (up to
    LOOSE_DEGREE) and the first check's step."""

    tail_target: float
    iteration_rtol: float
    allowance: float
    loose_rtol: bool
    first_check: int


def solver_settings(tol: float) -> SolverSettings:
    """Every setting of the collocation solver that follows from `tol` (module docstring)."""
    rtol = iteration_rtol(tol)
    return SolverSettings(truncation_share(tol) * tol, rtol, iteration_allowance(tol),
                          rtol >= LOOSE_RTOL, first_check(rtol, False))


# --- which engine answers a call shape -------------------------------------------------------

#: The C kernel iterates where the Schur block has at most this many unknowns (degree
#: n <= ~128); above, its unblocked loops lose to LAPACK's blocked ones (kernel / numpy time
#: 0.50 at n = 128, 0.8 at 160, 1.2 at 256). ``python tests/bench/kernel_range.py``, part 1.
KERNEL_MAX_SCHUR = 64
#: The kernel (``modal_points``) solves points of one degree 32 lanes at a time; a last group
#: of at most FEW_POINTS points (:func:`few_points_limit`) one lane each, a larger one as a
#: group of 32 lanes with the last point repeated (one lane / group time 0.43-1.01 for 2-4
#: points, 0.90-1.18 for 5, 1.26-1.60 for 8, at n = 12..64 and tol 1e-12 and 1e-4).
#: ``python tests/bench/kernel_range.py``, part 2.
FEW_POINTS = 4
#: Above this degree 32 lanes answer even a single point. One lane stays the faster for 4
#: points up to n = 128 (one lane / 32 lanes 0.57 at n = 40, 0.67 at 64, 0.81 at 128), so the
#: limit is conservative: it bounds where degree pooling treats a solve as free of fixed cost.
#: ``python tests/bench/tuning_crossovers.py``, part 2.
LEAN_MAX_DEGREE = 64
#: Up to this many matrix entries (points m^2, m = n - 1 unknowns) the numpy reference applies
#: (K - SHIFT)^{-1} as dense inverses (one batched product a step), above it through the Schur
#: complement (~16 calls a step, less arithmetic): with a few points numpy's per-call cost
#: decides (dense / Schur time 0.52-0.83 up to 12,168 entries, 0.94 at 17,672, 1.49 at
#: 24,336). ``python tests/bench/tuning_crossovers.py``, part 1. The same bound admits a
#: scalar call to the numpy reference's one-point path (n <= 127) and the pencil quotient's
#: split products (:func:`.quotient._split_terms`).
DENSE_ENTRIES = 16_000
#: The numpy reference's one-point path (:func:`.eigensolver.solve_point` without the kernel)
#: inverts K - SHIFT whole up to this degree, through its Schur complement above: the whole
#: LU costs fewer numpy calls, the Schur complement a quarter of the arithmetic (Schur / whole
#: time 1.60 at n = 16, 1.09 at 34, 1.01 at 40, 0.97 at 44, 0.80 at 56, 0.73 at 64).
#: ``python tests/bench/tuning_crossovers.py``, part 4.
POINT_SCHUR_DEGREE = 42
#: The cost model of degree pooling (:func:`.collocation.solve_degrees`): a batched solve of
#: both families costs FIXED_COST seconds whatever its size plus POINT_COST (n/22)^2 a point;
#: one lane (:func:`few_points_limit`) costs CALL_COST whatever its size and LEAN_FACTOR times
#: as much a point. Only the ratios decide. ``python -m pytest -m bench -k pooling_cost_model``
#: measures FIXED_COST and POINT_COST (with the kernel, random points: 30, 80 and 160 us and
#: 1.4, 1.4 and 1.3 us at n = 16, 22 and 36; a solve of 30 points is one group of 32 lanes, so
#: the "fixed" part grows with n); LEAN_FACTOR from the kernel's one lane against its full
#: groups on Figure 1's points (5.4, 6.1, 6.0, 6.0 and 6.0 at n = 16, 22, 30, 40 and 56,
#: ``tests/bench/kernel_range.py``, part 2).
FIXED_COST, POINT_COST, LEAN_FACTOR = 60e-6, 1.35e-6, 6.0
#: The numpy and Python of one engine call, its points aside (the coefficients, the kernel's
#: call, the group's index arrays; part of FIXED_COST where measured): what pooling a small
#: group saves. The same bench test times one more group, of one point at n = 12, as the
#: degree loop solves it beside another: 31.5-34.2 us in three runs (the model's lean cost of
#: the point, LEAN_FACTOR POINT_COST (12/22)^2 = 2.4 us, included). Without this term each
#: degree group of a small call is solved on its own: an array of 10 points at Omega(L) < 10
#: then costs 1.43 of a loop of scalar calls, 0.81 with it (``python
#: tests/bench/tuning_crossovers.py``, part 6).
CALL_COST = 30e-6
#: :func:`.stacked_inverse.stacked_inverse` (the numpy engine's Schur inverses) uses the block
#: recursion for stacks of at least this many matrix entries (count k^2), LAPACK below: the
#: recursion's cost is mostly numpy calls per stack, LAPACK's a call per matrix. On the
#: reference machine (numpy 2, OpenBLAS 0.3.31) LAPACK was the faster at every measured stack
#: (blocks / LAPACK 1.13-2.37 for k = 6..20 and 100..1,200 matrices, 0.96-1.26 at k = 28; 1.9-10
#: for one matrix of k = 64..255, the degrees above the kernel's range), so the limit lies
#: above the measured range (940,800 entries); the Figure 1 batch without the kernel took 0.93
#: of its time with it there. ``tests/test_stacked_inverse.py`` checks the accuracy;
#: ``python tests/bench/tuning_crossovers.py``, part 3, times the two.
BLOCK_ENTRIES = 1_000_000
#: Points :func:`spectral_rod.critical_load` solves together at most: bounds the memory of a
#: large call (the batched engine holds ~k^2 doubles per point and family, the large-twist scan
#: ~20 grid columns of 257 doubles per point); ``tests/test_safety.py`` measures the peak.
CHUNK = 1 << 12
#: Array calls of :func:`spectral_rod.critical_load` with at most this many points are answered
#: point by point by the scalar path (``critical._few_points``): the general path's numpy calls
#: cost more than a loop of scalar calls on a few points (general / loop time at 2, 8 and 16
#: points: 2.45, 1.08 and 0.57 at Omega(L) < 10; 1.72, 0.76 and 0.39 at Omega(L) in [40, 50];
#: 2.28, 1.14 and 0.97 at nu - 1 <= 1e-3; 2.27, 1.17 and 0.96 at Omega(L) >= 50: the
#: collocation routes cross at 6-9 points, the characteristic ones at ~14).
#: ``python tests/bench/tuning_crossovers.py``, part 6.
SMALL_CALL = 8


def few_points_limit(n: int) -> int:
    """Most points of degree n (a call's last group of fewer than 32) the kernel solves one
    lane at a time: FEW_POINTS, none above :data:`LEAN_MAX_DEGREE`.

    >>> few_points_limit(22), few_points_limit(66)
    (4, 0)
    """
    return FEW_POINTS if n <= LEAN_MAX_DEGREE else 0
