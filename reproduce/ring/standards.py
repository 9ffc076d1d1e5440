"""The ring scene's standards: the named tolerances every ring verdict rule uses (in its logic
and, as the named fields of its text template, in its text) and the methods the rows cite."""

from __future__ import annotations

import functools
from collections.abc import Callable

from reproduce.ledger import Method, Rule
from spectral_rod import FIGURE1_NU, RING_LOADS

SCENE = "ring"
#: "Exact": every q_cr is converged to 1e-12 relative, so 1e-9 is the solvers' accuracy with a
#: 1000x margin. "Approximately": within the 5 % expected of an engineering buckling formula (the
#: evidence reports the deviations themselves, so how close a verdict is to the line shows).
EXACT_TOL, APPROX_TOL = 1.0e-9, 0.05
#: The two formulations must agree to this (relative) for a verdict that rests on both: each q_cr
#: is converged to <= 1e-10 (Munder's tol; the second variation's is 1e-12), and the change
#: between truncations that stops the refinement may understate the error, so 1e-6 leaves 10^4
#: for that, while an error in either formulation's equations moves q_cr at the percent level.
FORMULATION_TOL = 1.0e-6
#: The smallest eigenvalue 1/q of the Jacobi-scaled pencil (G x = mu K x) is zero to round-off,
#: a few eps in magnitude; below -1e-12 it is a real eigenvalue at q <= 0, not round-off.
ZERO_INVERSE_LOAD_TOL = 1.0e-12
#: Closed forms of the untwisted ring vs the solver: both exact to ~1e-12, so 1e-9 (EXACT_TOL).
CLOSED_FORM_TOL = EXACT_TOL
#: A planar mode measures at round-off (the Euler mode: < 1e-12), so a non-planarity above
#: this is the mode's, not the solver's.
NON_PLANAR = 1.0e-3
#: Munder vs Kirchhoff's balances: both converged to 1e-10 (Munder's default tol), so 10x that
#: is agreement to their accuracy.
EQUATIONS_TOL = 1.0e-9
#: The loaded circle's residual in Eqs. Munder: zero to round-off of O(1) terms.
RESIDUAL_TOL = 1.0e-12
#: "holds" for a 3-D character if at least 9 in 10 twisted critical modes are mixed: the
#: statement is then true of the twisted ring in general, with isolated exceptions.
COUPLED_MOSTLY = 0.9
#: A critical mode is *mixed* (in-plane and out-of-plane motion both matter) if each part does at
#: least this share of the load work; below it, treating the mode as purely out-of-plane (or
#: in-plane) changes its load work by less than the ledger's own "approximately" (APPROX_TOL).
MIXED_SHARE = APPROX_TOL
#: The paper's range of nu = I2/I1 (Figure 1's curves: 1.1, 1.3, 1.5), the range a general
#: statement of the Conclusions is held to when it does not hold over the whole scan.
PAPER_NU_MAX = max(FIGURE1_NU)
#: The paper's load of the ring with a circular section, q_cr R^3/(E1 I1) = 3.
PAPER_CIRCULAR_LOAD = 3.0

SECOND_VARIATION = Method("Fourier-Galerkin of the sympy second variation "
                          "(spectral_rod.ring.second_variation)", "second variation")
MUNDER = Method("Eqs. Munder, constit, frenet linearised numerically (spectral_rod.ring.munder)",
                "Munder")
CRIT2 = Method("the paper's Eq. crit2 (one-mode Galerkin estimate)", "crit2")
CLASSICAL = Method("classical closed forms of the untwisted ring (spectral_rod.ring.closed_forms)",
                   "closed form")
ROD = Method("Chebyshev collocation of the straight rod (spectral_rod.buckling_mode)", "inst1")


def readings(ev: object) -> tuple[str, ...]:
    """The readings of the load whose numbers `ev` holds: one if it is one reading's evidence
    (``rows.single_load_evidence``), else every one of :data:`spectral_rod.RING_LOADS`."""
    override = getattr(ev, "load_override", None)
    return (override,) if override else RING_LOADS


def verdict_by_deviation(dev: float, exact: float = EXACT_TOL, approx: float = APPROX_TOL
                         ) -> str:
    """The ring's one standard for "is this number that number": holds within `exact`
    (EXACT_TOL), holds approximately within `approx` (APPROX_TOL), fails beyond; its text is
    :data:`DEVIATION_RULE_TEXT` with the same two fields."""
    if dev <= exact:
        return "holds"
    return "holds approximately" if dev <= approx else "fails"


#: The text of :func:`verdict_by_deviation`: a template whose fields are its two thresholds.
DEVIATION_RULE_TEXT = "holds if ≤ {exact:g}, holds approximately if ≤ {approx:.0%}, fails otherwise"
DEVIATION_RULE = DEVIATION_RULE_TEXT.format(exact=EXACT_TOL, approx=APPROX_TOL)


def rule_from_template(template: str, decide: Callable[..., str], **thresholds: float) -> Rule:
    """A verdict rule whose text is `template` filled with `thresholds` (named fields) and whose
    logic is ``decide(numbers, **thresholds)``: one definition of every threshold for both."""
    return Rule(template.format(**thresholds), functools.partial(decide, **thresholds))
