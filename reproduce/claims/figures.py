"""The straight-rod claims' figures: p* to 20 pi with its limit, the wavenumbers, the mode."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from reproduce.claims.evidence import CURVE_TOL, DETAIL_NU, TWIST_MAX, StraightRodEvidence
from spectral_rod import (
    beta_difference,
    critical_load,
    critical_wavenumbers,
    large_twist_coefficients,
    large_twist_limit,
)

#: Curves drawn in claims_load.png.
CURVE_NUS = (1.1, 1.5, 2.0, 5.0)
COLORS = {1.1: "tab:blue", 1.3: "tab:purple", 1.5: "tab:green", 2.0: "tab:orange",
          5.0: "tab:red", 10.0: "tab:brown"}


#: The x label of every panel drawn against the twist.
TWIST_LABEL = "total twist angle Ω(L)"


def _pi_ticks(ax, top: int, every: int) -> None:
    ticks = np.arange(0, top + 1, every)
    ax.set_xticks(ticks * np.pi)
    ax.set_xticklabels(["0" if k == 0 else ("π" if k == 1 else f"{k}π") for k in ticks])


def figure_load(ev: StraightRodEvidence):
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8.0, 8.2),
                                  gridspec_kw={"height_ratios": [1.25, 1], "hspace": 0.3})
    for nu in CURVE_NUS:
        mx = ev.maxima_for(nu)
        om = np.concatenate([ev.grid, [m.twist_mp for m in mx]])
        p = np.concatenate([ev.p[nu], [m.p_mp for m in mx]])
        order = np.argsort(om)
        ax.plot(om[order], p[order], color=COLORS[nu], lw=1.2, label=f"ν = {nu}")
        ax.axhline(large_twist_limit(nu), color=COLORS[nu], ls="--", lw=0.9)
        ax.plot([m.twist_mp for m in mx], [m.p_mp for m in mx], "v", ms=3.5, color="k")
        ax.text(TWIST_MAX * 1.005, large_twist_limit(nu),
                f"2ν/(1+ν)\n= {large_twist_limit(nu):.4f}", va="center", fontsize=7,
                color=COLORS[nu])
    ax.plot([], [], "k--", lw=0.9, label="limit p∞ = 2ν/(1+ν)")
    ax.plot([], [], "kv", ms=3.5, label="maxima = family crossings (mpmath)")
    ax.set_xlim(0, TWIST_MAX)
    ax.set_ylim(0.98, 1.72)
    _pi_ticks(ax, 20, 2)
    ax.set_xlabel("total twist angle Ω(L) = ω₃₀L")
    ax.set_ylabel("p* = P_cr / (π²A₁/L²)")
    ax.set_title("Critical load to Ω(L) = 20π: corners near nπ (n ≥ 2) and the limit 2ν/(1+ν)",
                 fontsize=10)
    # in the empty band between the nu = 2 and nu = 5 limits, right of the first maxima: the
    # legend covers no curve there
    ax.legend(loc="center right", bbox_to_anchor=(0.99, 0.70), fontsize=7.5, ncol=2,
              frameon=False)
    # approach to the limit
    om = ev.grid[ev.grid >= 3.0]
    for nu in CURVE_NUS:
        sel = ev.grid >= 3.0
        gap = large_twist_limit(nu) - ev.p[nu][sel]
        ax2.loglog(om, gap, color=COLORS[nu], lw=1.0, label=f"ν = {nu}")
        c = large_twist_coefficients(nu)
        ax2.loglog(om, -c.a2 / om**2, color=COLORS[nu], ls=":", lw=1.0)
    for r in ev.limit:
        if r["nu"] in CURVE_NUS:
            ax2.loglog(r["twist"], r["limit"] - r["p_mp"], "o", ms=3, mfc="none",
                       color=COLORS[r["nu"]])
    ax2.plot([], [], "k:", label="leading term −a₂/Ω² = π²δ²p∞³/(4Ω²)")
    ax2.plot([], [], "ko", mfc="none", ms=3, label="mpmath at Ω = π/2 + 2πj")
    ax2.set_xlabel("Ω(L)")
    ax2.set_ylabel("p∞ − p*")
    ax2.set_xlim(3, TWIST_MAX * 2.2)
    ax2.set_title("Approach to the limit: p∞ − p* ≈ −a₂/Ω² with a |sin Ω|/Ω³ ripple",
                  fontsize=10)
    ax2.legend(fontsize=7, frameon=False, loc="lower left", ncol=2)
    ax2.grid(True, which="both", lw=0.3, alpha=0.5)
    fig.subplots_adjust(right=0.86, top=0.95, bottom=0.07)
    return fig


def figure_wavenumbers(ev: StraightRodEvidence):
    fig, axes = plt.subplots(3, 1, figsize=(8.0, 10.5),
                             gridspec_kw={"height_ratios": [1, 1, 1], "hspace": 0.45})
    ax, ax2, ax3 = axes
    nu = DETAIL_NU
    om = np.linspace(0.0, 3 * np.pi, 361)
    b1, b2 = critical_wavenumbers(critical_load(om, nu, tol=CURVE_TOL), om, nu)
    xm, xp = (np.asarray(b1) ** 2).real, b2**2
    w = {r["nu"]: r for r in ev.windows}
    ax.axvspan(w[nu]["omega_a"], w[nu]["omega_b"], color="0.85", label="β₁ imaginary")
    ax.plot(om, np.sqrt(xp), color="tab:red", lw=1.3, label="β₂L")
    ax.plot(om, np.where(xm >= 0, np.sqrt(np.clip(xm, 0, None)), np.nan), color="tab:blue",
            lw=1.3, label="β₁L (real)")
    ax.plot(om, np.where(xm < 0, np.sqrt(np.clip(-xm, 0, None)), np.nan), color="tab:blue",
            lw=1.3, ls="--", label="|β₁L| (β₁ imaginary)")
    ax.plot(om, om + np.pi, "k:", lw=0.9, label="Ω ± π")
    ax.plot(om, np.maximum(om - np.pi, 0), "k:", lw=0.9)
    ax.set_xlim(0, 3 * np.pi)
    _pi_ticks(ax, 3, 1)
    ax.set_xlabel(TWIST_LABEL)
    ax.set_ylabel("wavenumber × L")
    ax.set_title(f"Critical wavenumbers along p*(Ω), ν = {nu}", fontsize=10)
    ax.legend(fontsize=7.5, frameon=False, loc="upper left")
    # beta2 - beta1
    om2 = np.linspace(0.0, 4 * np.pi, 481)
    for k, nu2 in enumerate((1.1, 1.5, 10.0)):
        d = beta_difference(critical_load(om2, nu2, tol=CURVE_TOL), om2, nu2)
        ax2.plot(om2, d, color=COLORS[nu2], lw=1.2, label=f"ν = {nu2}")
        ax2.plot([w[nu2]["omega_a"], w[nu2]["omega_b"]], [0.25 + 0.3 * k] * 2,
                 color=COLORS[nu2], lw=4, solid_capstyle="butt", alpha=0.6)
        ax2.plot(w[nu2]["omega_b"], 2 * np.pi, "^", color=COLORS[nu2], ms=5)
        mx = ev.maxima_for(nu2)
        ax2.plot([m.twist_mp for m in mx if m.twist_mp < 4 * np.pi],
                 [m.dbeta_mp for m in mx if m.twist_mp < 4 * np.pi], "v", color="k", ms=3.5)
    ax2.axhline(2 * np.pi, color="k", lw=0.8, ls="--", label="2π")
    ax2.plot([], [], "k^", ms=5, label="Ω_b = 2π√(ν/(3ν+1)): β₁ = 0, β₂ = 2π")
    ax2.plot([], [], "kv", ms=3.5, label="p* maxima: β₁L = (n−1)π, β₂L = (n+1)π")
    ax2.plot([], [], color="0.5", lw=4, alpha=0.6, label="window Ω_a < Ω < Ω_b: β₁ imaginary")
    ax2.set_xlim(0, 4 * np.pi)
    ax2.set_ylim(0, 7)
    _pi_ticks(ax2, 4, 1)
    ax2.set_xlabel(TWIST_LABEL)
    ax2.set_ylabel("Re(β₂ − β₁) L")
    ax2.set_title("β₂ − β₁ (Re β₁ = 0 where β₁ is imaginary)", fontsize=10)
    ax2.legend(fontsize=7, frameon=False, loc="center right", ncol=1)
    # distance to 2 pi, log scale
    for nu2 in (1.1, 1.5, 10.0):
        sel3 = ev.grid >= 4.0
        d = beta_difference(ev.p[nu2][sel3], ev.grid[sel3], nu2)
        ax3.semilogy(ev.grid[sel3], np.abs(2 * np.pi - d), color=COLORS[nu2], lw=1.0,
                     label=f"ν = {nu2}")
        lam = np.pi**2 * large_twist_limit(nu2)
        delta = 0.5 * (1 - 1 / nu2)
        g = ev.grid[sel3]
        ax3.semilogy(g, np.pi * lam * delta / g**3, color=COLORS[nu2], ls=":", lw=1.0)
        mx = ev.maxima_for(nu2)
        ax3.semilogy([m.twist_mp for m in mx], [1e-12] * len(mx), "v", color="k", ms=3.5)
    ax3.plot([], [], "k:", label="envelope πλδ/Ω³ (asymptotics)")
    ax3.plot([], [], "kv", ms=3.5, label="p* maxima, where 2π − (β₂ − β₁) = 0 (drawn at 1e-12)")
    ax3.set_xlim(4.0, TWIST_MAX)
    _pi_ticks(ax3, 20, 2)
    ax3.set_xlabel(TWIST_LABEL)
    ax3.set_ylabel("|2π − (β₂ − β₁)L|")
    ax3.set_title("β₂ − β₁ → 2π from below; exactly 2π at every p* maximum", fontsize=10)
    ax3.set_ylim(3e-13, 1e2)  # headroom for the legend above the curves
    ax3.legend(fontsize=7, frameon=False, loc="upper right", ncol=2)
    fig.subplots_adjust(top=0.96, bottom=0.05)
    return fig


def figure_mode(ev: StraightRodEvidence):
    fig = plt.figure(figsize=(10.5, 5.0))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    ax2 = fig.add_subplot(1, 2, 2)
    colors = ["k", "tab:green", "tab:purple", "tab:red"]
    for m, c in zip(ev.modes, colors, strict=False):
        lab = ("Euler, Ω = 0 (planar)" if m["twist"] == 0 else
               f"Ω = {m['twist']:g}, ν = {m['nu']:g} ({m['family']})")
        ax.plot(m["x1"], m["x2"], m["s"], color=c, lw=1.6, label=lab)
        ax2.plot(m["x1"], m["x2"], color=c, lw=1.4, label=lab)
        if "x1_mp" in m:
            k = slice(None, None, 10)
            ax.plot(m["x1_mp"][k], m["x2_mp"][k], np.asarray(m["s"])[k], "o", color=c, ms=2.5,
                    mfc="none")
            ax2.plot(m["x1_mp"][k], m["x2_mp"][k], "o", color=c, ms=3, mfc="none")
    ax.plot([0, 0], [0, 0], [0, 1], color="0.6", lw=0.8, ls="--")
    ax.set_xticks([-1, -0.5, 0, 0.5, 1])
    ax.set_yticks([-0.5, 0, 0.5])
    ax.set_xlabel("x₁ / max|x|")
    ax.set_ylabel("x₂ / max|x|")
    ax.set_zlabel("s / L")
    ax.set_title("Buckling mode: centreline in 3-D", fontsize=10)
    ax.view_init(elev=18, azim=-60)
    ax2.plot([], [], "ko", mfc="none", ms=3, label="closed form (mpmath), every 10th point")
    ax2.axhline(0, color="0.8", lw=0.6, zorder=0)
    ax2.axvline(0, color="0.8", lw=0.6, zorder=0)
    ax2.set_aspect("equal")
    ax2.set_xlim(-1.1, 1.1)
    ax2.set_ylim(-1.1, 1.1)
    ax2.set_xlabel("x₁ / max|x|")
    ax2.set_ylabel("x₂ / max|x|")
    ax2.set_title("End view along the rod axis (a plane mode is a line)", fontsize=10)
    ax2.legend(fontsize=7, frameon=False, loc="lower left")
    fig.subplots_adjust(left=0.02, right=0.98, wspace=0.15)
    return fig
