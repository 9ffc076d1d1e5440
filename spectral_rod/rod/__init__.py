"""The straight rod (paper's Eq. ``inst1``, hinged ends): the public solvers, the router, the
methods (collocation in :mod:`.collocation`, the characteristic equation, the increment,
Rayleigh-Ritz, finite differences, the baseline) and the closed forms."""
