"""Numerical building blocks shared by the rod and the ring: the sign scan with its
bracketed refinement, Gauss-Legendre quadrature."""
