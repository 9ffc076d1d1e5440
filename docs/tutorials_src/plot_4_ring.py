"""
The ring under each load reading
================================

The paper's ring carries "a radially inward-directed force per unit length" and "radially
inwards directed pressure" without saying which. The standard readings (pressure that follows
the surface, a force toward the ring's axis, toward its centre point, a dead load of fixed
direction) agree on the circle and are different loads once the ring moves.
:data:`spectral_rod.RING_LOADS` lists the readings the package implements, and
:func:`spectral_rod.ring_critical_load` gives the converged critical load q_cr R³/(E₁I₁) for
each, against N (turns of the cross-section around the ring). Eq. ``crit2``, the paper's
one-mode estimate (:func:`spectral_rod.ring_formula_load`), is drawn for comparison.
"""

import matplotlib.pyplot as plt
import numpy as np

import spectral_rod as sr

# %%
# :func:`spectral_rod.ring_buckling` returns the mode as well: its kind (in-plane,
# out-of-plane or coupled) and the convergence record of the Fourier truncation.
print("load readings:", sr.RING_LOADS)
for load in sr.RING_LOADS:
    b = sr.ring_buckling(2, 1.5, load=load)
    print(f"{load:>12}: q = {b.load:.6f}, {b.kind}, converged={b.converged}")

# %%
# The converged load for each reading against N, beside Eq. ``crit2``, for a mildly and a
# strongly asymmetric section.
twists = np.arange(0, 9)

fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), layout="constrained", sharey=True)
markers = dict(zip(sr.RING_LOADS, "osD^v", strict=False))
for ax, nu in zip(axes, (1.5, 4.0), strict=True):
    for k, load in enumerate(sr.RING_LOADS):
        q = [sr.ring_critical_load(int(N), nu, load=load) for N in twists]
        ax.plot(twists, q, marker=markers.get(load, "o"), ms=max(7 - 2 * k, 3),
                ls="-" if k == 0 else "--",
                label=f"converged, load = {load!r}")
        print(f"nu = {nu}, {load:>12}: q_cr(N = 0..{twists[-1]}) =", np.round(q, 4))
    crit2 = [sr.ring_formula_load(int(N), nu) for N in twists]
    ax.plot(twists, crit2, "k:", label="Eq. crit2 (one-mode estimate)")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("N (turns of the cross-section, Ω = N s/R)")
    ax.set_title(f"ν = {nu}, e = E₂/E₁ = 1", fontsize=10)
    ax.set_ylim(-4, 5)
axes[0].set_ylabel("q_cr R³ / (E₁ I₁)")
handles, labels = axes[0].get_legend_handles_labels()
fig.legend(handles, labels, loc="outside lower center", ncol=3)  # below the panels: no data hidden
plt.show()
