"""
p*(Ω(L)) for chosen ν
=====================

The critical load p* = P_cr / (π² A₁ / L²) of the hinged rod against the total twist angle
Ω(L), one curve per ratio ν = I₂/I₁ of the bending stiffnesses. One array call computes a whole
curve; the router picks the method per point (collocation below Ω(L) = 50).
"""

import matplotlib.pyplot as plt
import numpy as np

import spectral_rod as sr

twist = np.linspace(0.0, 20.0, 801)
curves = {nu: sr.critical_load(twist, nu) for nu in (1.1, 1.3, 1.5, 2.0, 4.0)}

# %%
# ``full_output=True`` says how each value was obtained: the method, the Chebyshev degree,
# the error estimate and the mode family (symmetric or antisymmetric about mid-span).
result = sr.critical_load(np.array([1.0, 2 * np.pi, 60.0]), 1.5, full_output=True)
print(result.method, result.n, result.error_estimate, result.family, result.converged, sep="\n")

# %%
# The curves rise from the Euler load p* = 1 and approach the limit 2ν/(1+ν) (dotted), the
# harmonic mean of the two bending stiffnesses. The maxima near 2π, 3π, ... (grey) are corners
# where the two mode families cross.
fig, ax = plt.subplots(figsize=(7, 4.4), layout="constrained")
for k in (2, 3, 4, 5, 6):
    ax.axvline(k * np.pi, color="0.85", lw=0.6, zorder=0)
for nu, p_star in curves.items():
    (line,) = ax.plot(twist, p_star, label=f"ν = {nu}")
    ax.axhline(sr.large_twist_limit(nu), color=line.get_color(), lw=0.8, ls=":")
ax.set_xlabel("total twist angle Ω(L) [rad]")
ax.set_ylabel("p* = P_cr / (π² A₁ / L²)")
ax.set_xlim(0, 20)
ax.legend(ncol=5, loc="lower center", bbox_to_anchor=(0.5, 1.0), frameon=False)
plt.show()
