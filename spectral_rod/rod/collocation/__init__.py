r"""Critical load of the hinged, spontaneously twisted straight rod by Chebyshev collocation.

The physics (paper, section "Stability of a rectilinear rod", Eq. ``inst1``)
-----------------------------------------------------------------------------
With s/L in [0, 1], the total twist angle Omega = omega30 L, nu = A2/A1 = I2/I1 >= 1 and the
load lambda = P L^2 / A1 = pi^2 p*, Eq. ``inst1`` for the curvatures omega1, omega2 reads

    -omega1'' + Omega^2 omega1 + 2 nu Omega omega2'          = lambda omega1
    -nu omega2'' + nu Omega^2 omega2 - 2 Omega omega1'       = lambda omega2

(declared once, term by term, in :data:`spectral_rod.rod.collocation.discretisation.INST1`).
Hinged ends: x1 = x2 = 0 and x1'' = x2'' = 0 at s = 0, L. Since x'' is omega rotated by the
twist angle (the paper's geometric relations), x'' = 0 <=> omega1 = omega2 = 0. The conditions
x = 0 are then implied: moment balance of the rod between an end and s, with the end moments
zero, gives A1 omega1 = -P xi and A2 omega2 = -P eta, where (xi, eta) are the displacement
components along (u0, v0); omega = 0 at an end is therefore x = 0 there, and conversely any
solution of ``inst1`` with omega = 0 at both ends gives a centreline with x = x'' = 0 at both ends
(:func:`spectral_rod.buckling_mode` integrates x'' = R(Omega s) omega and a test checks this).
So:  hinged ends  <=>  omega1 = omega2 = 0 at s = 0 and s = L.

Multiplied by A1 and A2 the equations form a self-adjoint, positive definite pencil, so all
eigenvalues are real and positive, with the bounds of :mod:`spectral_rod.rod.families`.

The modules
-----------
* :mod:`.chebyshev` -- points and parity integration bases (the kernel);
* :mod:`.discretisation` -- Eq. ``inst1`` declared term by term and its collocation pencil per
  mode family;
* :mod:`.resolution` -- the a priori degree, the mode's coefficient tail and the error model;
* :mod:`.arithmetic` -- the operations those rules are written against, for arrays and for one
  point in Python floats;
* :mod:`.modal_form` -- each family in the eigenbasis of its uncoupled operators (K diagonal
  plus an Omega-proportional coupling), and K - SHIFT at a batch of points;
* :mod:`.shifted` -- (K - SHIFT)^{-1} for the numpy reference: Schur complement, dense
  inverses for a few points, one block-diagonal matrix for one point;
* :mod:`.quotient` -- the pencil's two-sided Rayleigh quotient, its precision a parameter;
* :mod:`.eigensolver` -- the engine's entry points for points of one degree
  (:func:`.eigensolver.solve_points`, :func:`.eigensolver.solve_point` for one point in Python
  floats): both families' lowest physical eigenvalue by two-sided shift-and-invert iteration,
  by the C kernel where it is built, else by its numpy reference;
* :mod:`.reference` -- the full ``eig`` with the physical-eigenvalue rule: the test
  reference, which also decides where the iteration is rejected;
* :mod:`.modal_kernel` -- the engine: that iteration in C, 32 points side by side or one point
  at a time (one code, ``iterate_lanes``), the pencil's Rayleigh quotient and the mode's tail; its
  contract is ``_modal_kernel.h`` (structs, INFO returns, an ABI version checked at load);
  :func:`.modal_kernel.engine_info` reports what runs here;
* :mod:`.stacked_inverse` -- the numpy reference's Schur inverses for large stacks;
* :mod:`.tuning` -- every speed threshold and cost-model constant, and
  :func:`.tuning.solver_settings`, the one map from ``tol`` to the solver's settings;
* :mod:`.driver` -- the one driver: p* for any call shape with automatic resolution, by one
  degree loop written against a namespace (arrays, or one point in Python floats), and the
  family rule :func:`.driver.pick_family`.

Who decides what:

============================  ===========================================================
decision                      owner
============================  ===========================================================
the method per point          :mod:`spectral_rod.rod.router`
validation, bounds, warning   :mod:`spectral_rod.rod.critical` (calls the driver once)
degree, raise, estimate       :func:`.driver._degree_loop` with the rules of :mod:`.resolution`
which family is p*            :func:`.driver.pick_family`
kernel or numpy reference     :func:`.eigensolver.solve_points` (:func:`.eigensolver.kernel_degree`:
                              built, KERNEL_MAX_SCHUR; a point the kernel rejects)
one lane or 32 lanes          the kernel's ``modal_points`` (:func:`.tuning.few_points_limit`)
dense or Schur (numpy)        :func:`.shifted._shifted` (:data:`.tuning.DENSE_ENTRIES`)
converged or not              :func:`.eigensolver.converged` (C: ``iterate_lanes``)
the eigenvalue                :func:`.quotient.pencil_rayleigh_quotient` (C:
                              ``pencil_quotient``; precision a parameter)
the mode's tail               :func:`.resolution.mode_tails` (C: ``family_lanes``)
the full ``eig``              :mod:`.reference`: the test reference; it decides where the
                              iteration is rejected
============================  ===========================================================

``CriticalLoad.engine`` records per point whether the kernel computed it.
"""

from spectral_rod.rod.collocation.driver import (
    N_MAX,
    N_MIN,
    collocation_critical_load,
    collocation_family_load,
    collocation_mode_coefficients,
)

__all__ = ["N_MAX", "N_MIN", "collocation_critical_load", "collocation_family_load",
           "collocation_mode_coefficients"]
