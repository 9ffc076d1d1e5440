"""
The 3-D buckling mode
=====================

:func:`spectral_rod.buckling_mode` returns the critical mode: the body-frame curvatures
ω₁, ω₂ and the centreline displacement (x₁, x₂) in the fixed frame, on a uniform grid in s/L.
Unlike Euler's planar mode, the twisted rod's centreline leaves every plane.
"""

import matplotlib.pyplot as plt
import numpy as np

import spectral_rod as sr

mode = sr.buckling_mode(5.0, 1.5, points=301)
print(mode)
np.testing.assert_allclose(mode.x1[[0, -1]], 0.0, atol=1e-12)  # hinged ends
print(f"non-planarity σ_min/σ_max of (x₁, x₂): {sr.non_planarity(mode.x1, mode.x2):.3f}")

# %%
# The centreline in 3-D (s along the rod's axis) and its two displacement components. The
# untwisted rod's mode, x₁ ∝ sin(π s/L) in a plane, is drawn for comparison.
euler = sr.buckling_mode(0.0, 1.5, points=301)
fig = plt.figure(figsize=(9, 4.2), layout="constrained")
ax3 = fig.add_subplot(1, 2, 1, projection="3d")
ax3.plot(mode.s, mode.x1, mode.x2, label="Ω(L) = 5, ν = 1.5")
ax3.plot(euler.s, euler.x1, euler.x2, ls="--", label="Ω(L) = 0 (Euler)")
ax3.set_xlabel("s/L")
ax3.set_ylabel("x₁")
ax3.set_zlabel("x₂")
ax3.legend(loc="upper left", fontsize=8)
ax = fig.add_subplot(1, 2, 2)
ax.plot(mode.s, mode.x1, label="x₁")
ax.plot(mode.s, mode.x2, label="x₂")
ax.plot(mode.s, mode.omega1, ":", label="ω₁")
ax.plot(mode.s, mode.omega2, ":", label="ω₂")
ax.set_xlabel("s/L")
ax.legend()
ax.set_title(f"p* = {mode.p_star:.6f}, {mode.family} family", fontsize=9)
plt.show()
