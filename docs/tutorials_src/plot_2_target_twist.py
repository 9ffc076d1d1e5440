"""
The twist at which p* reaches a target
======================================

p*(Ω(L)) rises from 1 at Ω(L) = 0 to its first maximum near 2π, so below that maximum every
target load between 1 and the maximum is reached at exactly one twist. A bracketing root
finder (:func:`scipy.optimize.brentq`) finds it from scalar calls of
:func:`spectral_rod.critical_load`.
"""

import matplotlib.pyplot as plt
import numpy as np
from scipy.optimize import brentq

import spectral_rod as sr

nu, target = 1.3, 1.1


def excess(twist_angle: float) -> float:
    """p* above the target: negative below the sought twist, positive above it."""
    return sr.critical_load(twist_angle, nu) - target


twist_star = brentq(excess, 0.0, 2 * np.pi, xtol=1e-13, rtol=1e-13)
print(f"Ω(L) = {twist_star:.10f} gives p* = {sr.critical_load(twist_star, nu):.12f}")

# %%
# The same search for a range of targets traces the inverse of the rising branch. The
# bracket ends at the first maximum, which :func:`spectral_rod.family_crossing` locates
# (the crossing of the two mode families near 2π).
crossing = sr.family_crossing(2 * np.pi, nu)
top_twist, top_load = float(crossing.twist), float(crossing.p_star)
print(f"first maximum: p* = {top_load:.12f} at Ω(L) = {top_twist / np.pi:.9f} π ({crossing.kind})")
targets = np.linspace(1.0 + 1e-3, top_load - 1e-6, 25)
roots = [brentq(lambda t, q=q: sr.critical_load(t, nu) - q, 0.0, top_twist)
         for q in targets]

twist = np.linspace(0.0, 2.5 * np.pi, 400)
fig, ax = plt.subplots(figsize=(7, 4), layout="constrained")
ax.plot(twist, sr.critical_load(twist, nu), color="0.6", label=f"p*(Ω(L)), ν = {nu}")
ax.plot(roots, targets, "o", ms=4, label="brentq: twist for each target")
ax.plot([twist_star], [target], "*", ms=14, color="C3", label=f"p* = {target}")
ax.set_xlabel("total twist angle Ω(L) [rad]")
ax.set_ylabel("p*")
ax.legend(loc="lower right")
plt.show()
