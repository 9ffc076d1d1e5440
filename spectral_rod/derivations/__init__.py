"""Executable derivations (sympy): every hand step behind a formulation, checked by machine.

* :mod:`.straight_rod` -- Eq. ``inst1`` from the energy (Euler-Lagrange) and from the paper's
  Eqs. ``Munder`` with ``constit`` (linearised about the compressed twisted rod), the decoupling
  of the force perturbation and of the rotation alpha, the hinged end conditions, and the
  misprinted variants of ``inst1`` evaluated against Figure 1;
* :mod:`.ring_linearisation` -- the second variation of the twisted ring (Eqs. ``frenini``,
  ``Munder``, ``frenet``, ``constit``) behind :mod:`spectral_rod.ring_stability`.

They ship with the package (sympy is a runtime dependency) because the claims ledger runs them:
``python -m spectral_rod.derivations.straight_rod`` prints one. The test suite runs them too.
"""
