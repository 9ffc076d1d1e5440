"""The ring scene's outputs: the table of crit2 vs the converged loads, the threshold table, the
two-formulation table and the figure."""

from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.lines import Line2D

from reproduce.ring.evidence import E_RATIOS, NUS, TITLES, TWISTS, RingEvidence
from reproduce.tables import markdown_table
from spectral_rod import crit2, threshold_twist

#: The words of the tables and the figure: templates with named fields (:func:`_text`).
TEXTS = {
    "table-title": "# Ring: Eq. crit2 vs the converged critical load",
    "table-caption": (
        "q_cr R³/(E₁I₁); each cell: crit2 / numerical hydrostatic / numerical axis (kind of the "
        "hydrostatic mode: i in-plane, o out-of-plane, c coupled); the centre and dead readings "
        "are in `ring_table.csv`."),
    "table-cell": "{crit2:.3f} / {q_hydrostatic:.4f} / {q_axis:.4f} ({kind})",
    "table-section": "## {label} (e = E₂/E₁ = {e:.4f})",
    "table-column": "ν = {nu:g}",
    "threshold-title": "# Threshold twist of Eq. crit2",
    "threshold-caption": (
        "N*² = 3(I₁+I₂)/(I₂−I₁) − 1 = (2ν+4)/(ν−1); the integer is the smallest N with "
        "crit2 ≤ 0 (independent of e). The numerical q_cr R³/(E₁I₁) at that N stays positive."),
    "curve": "ν = {nu:g}",
    "panel": "{title}: e = E₂/E₁ = {e:.3f}",
    "reading-marker": "numerical, {load}",
    "suptitle": ("Twisted ring: the paper's Eq. crit2 (dashed, leaves the plot below −2) vs the "
                 "converged Fourier-Galerkin critical load"),
}


def _text(name: str, **fields: object) -> str:
    """The text `name` of :data:`TEXTS` with its named fields."""
    return TEXTS[name].format(**fields)


def table_markdown(ev: RingEvidence) -> str:
    lines = [_text("table-title"), "", _text("table-caption"), ""]
    for label, e in E_RATIOS.items():
        t = ev.table[ev.table["e_label"] == label]
        rows = []
        for N in TWISTS:
            cells = [N]
            for nu in NUS:
                r = t[(t["nu"] == nu) & (t["N"] == N)].iloc[0]
                cells.append(_text("table-cell", crit2=r["crit2"],
                                   q_hydrostatic=r["q_hydrostatic"], q_axis=r["q_axis"],
                                   kind=r["kind_hydrostatic"][0]))
            rows.append(cells)
        lines += [_text("table-section", label=label, e=e), "",
                  markdown_table(["N", *(_text("table-column", nu=nu) for nu in NUS)], rows),
                  ""]
    return "\n".join(lines)


def threshold_markdown(ev: RingEvidence) -> str:
    lines = [_text("threshold-title"), "", _text("threshold-caption"), ""]
    rows = []
    for _, r in ev.thresholds.iterrows():
        if math.isinf(r["N_integer"]):
            rows.append([f"{r['nu']:g}", "∞", "∞", "–", "–", "–", "–"])
            continue
        rows.append([f"{r['nu']:g}", f"{r['N_continuous']:.4f}", int(r["N_integer"]),
                     f"{r['crit2_at_N_e=1']:.4f}", f"{r['q_hydrostatic_at_N_e=1']:.4f}",
                     f"{r['q_axis_at_N_e=1']:.4f}", f"{r['q_hydrostatic_at_N_isotropic']:.4f}"])
    lines.append(markdown_table(["ν", "N*", "integer N", "crit2 there (e = 1)",
                                 "q_cr hydrostatic (e = 1)", "q_cr axis (e = 1)",
                                 "q_cr hydrostatic (isotropic)"], rows))
    return "\n".join(lines) + "\n"


def formulations_markdown(ev: RingEvidence) -> str:
    """The two formulations side by side: the table of their agreement in the report."""
    f = ev.formulations
    rows = [[r.N, f"{r.nu:g}", f"{r.e_ratio:.4f}", r.load, f"{r.q_galerkin:.12f}",
             f"{r.q_munder:.12f}", f"{r.rel_diff:.1e}", r.kind_galerkin, r.max_frequency]
            for r in f.itertuples()]
    return markdown_table(["N", "ν", "e", "load", "q (second variation)", "q (Munder)",
                           "relative difference", "mode", "Munder resolution"], rows)


#: Markers (and sizes) of the readings of the load other than "hydrostatic" (drawn as lines).
OTHER_READINGS = {"axis": ("s", 6), "centre": ("^", 5), "dead": ("D", 3.5)}


def draw(ev: RingEvidence):
    fig, axes = plt.subplots(1, 2, figsize=(12.0, 5.2), sharey=True)
    colors = dict(zip(NUS, plt.cm.viridis(np.linspace(0.0, 0.9, len(NUS))), strict=True))
    n_fine = np.linspace(0.0, 10.0, 401)
    for ax, (label, e) in zip(axes, E_RATIOS.items(), strict=True):
        t = ev.table[ev.table["e_label"] == label]
        ax.axhline(0.0, color="0.3", lw=0.8)
        for nu in NUS:
            c = colors[nu]
            g = t[t["nu"] == nu].sort_values("N")
            ax.plot(n_fine, crit2(n_fine, nu, e), ls="--", color=c, lw=1.2)
            ax.plot(g["N"], g["q_hydrostatic"], "o-", color=c, ms=4, lw=1.4,
                    label=_text("curve", nu=nu))
            for load, (marker, size) in OTHER_READINGS.items():
                ax.plot(g["N"], g[f"q_{load}"], marker, color=c, ms=size, mfc="none", lw=0)
            th = threshold_twist(nu)
            if not math.isinf(th.continuous) and th.continuous <= 10:
                ax.plot([th.continuous], [0.0], marker="x", color=c, ms=9, mew=2)
        ax.set_title(_text("panel", title=TITLES[label], e=e))
        ax.set_xlabel("twist N (turns of the cross-section around the ring)")
        ax.set_xlim(-0.3, 10.3)
        ax.set_ylim(-2.0, 7.8)  # room for the style legend above the loads
        ax.set_xticks(range(11))
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("critical load  q_cr R³ / (E₁ I₁)")
    style = [Line2D([], [], color="k", ls="--", label="Eq. crit2 (paper)"),
             Line2D([], [], color="k", marker="o", ms=4, label="numerical, hydrostatic"),
             *(Line2D([], [], color="k", marker=m, ms=sz, mfc="none", lw=0,
                      label=_text("reading-marker", load=load))
               for load, (m, sz) in OTHER_READINGS.items()),
             Line2D([], [], color="k", marker="x", mew=2, lw=0,
                    label="crit2 = 0 (threshold twist)")]
    first = axes[0].legend(handles=style, loc="upper right", fontsize=8, framealpha=0.9)
    axes[0].add_artist(first)
    axes[1].legend(loc="lower left", fontsize=8, ncol=2, framealpha=0.9)
    fig.suptitle(_text("suptitle"), fontsize=11)
    fig.tight_layout()
    return fig
