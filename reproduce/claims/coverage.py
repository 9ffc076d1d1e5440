"""The paper read sentence by sentence: every checkable statement of Drozdov & Rabin with the
ledger rows that check it, or the documented reason it has none.

:data:`COVERAGE` is the list, in the paper's order (abstract, introduction, Sec. 'Equilibrium
equations' with Eqs. ``frenini``, ``radfin``, ``frenet``, ``constit``, ``Munder``, Sec. 'Stability
of a rectilinear rod' with Eq. ``inst1``, Sec. 'Stability of a ring' with Eq. ``crit2``,
'Conclusions', the caption of Figure 1). A statement has ``rows`` (ids of ledger rows, of any
scene) or a ``reason`` (why no row: a definition, a convention, history, a statement the package
cannot test, or a ring sentence whose row the ring scene owns). :func:`coverage_markdown` renders
it into ``coverage.md`` (written by the claims scene, :data:`reproduce.ledger.COVERAGE_FILE`);
tests/test_coverage.py checks that every listed row id is declared by a scene and that every
statement has a row or a reason.
"""

from __future__ import annotations

from dataclasses import dataclass

from reproduce.tables import markdown_table

#: Where a statement sits in the paper.
ABSTRACT, INTRO = "Abstract", "Introduction"
SEC1 = "Sec. 'Equilibrium equations'"
SEC2 = "Sec. 'Stability of a rectilinear rod'"
SEC3 = "Sec. 'Stability of a ring'"
CONCL, CAPTION = "Sec. 'Conclusions'", "Figure 1 caption"

#: Reasons shared by several statements.
DEFINITION = "a definition or notation: nothing to check beyond its use in the rows that rely on it"
HISTORY = "history or literature context: not a statement the package can compute"


@dataclass(frozen=True)
class Statement:
    """One checkable sentence (abridged) of the paper, with its rows or the reason for none."""

    where: str
    text: str
    rows: tuple[str, ...] = ()
    reason: str | None = None

    def __post_init__(self) -> None:
        if not self.rows and not self.reason:
            raise ValueError(f"statement {self.text!r} needs a row id or a reason")


COVERAGE: tuple[Statement, ...] = (
    # abstract
    Statement(ABSTRACT, "A thin inextensible elastic rod with non-vanishing spontaneous "
              "generalised torsions in its stress-free state.", reason=DEFINITION),
    Statement(ABSTRACT, "A planar circular ring subjected to uniform radial pressure on its outer "
              "perimeter.", rows=("caveat-load-model",)),
    Statement(ABSTRACT, "Spontaneous twist stabilises a rectilinear rod against buckling.",
              rows=("rod-stabilising",)),
    Statement(ABSTRACT, "Its presence has an opposite effect on a closed ring.",
              rows=("ring-destabilises",)),
    # introduction
    Statement(INTRO, "The history of buckling goes back to Euler [Lov44], who laid the "
              "foundations of elastic stability [TG63].", reason=HISTORY),
    Statement(INTRO, "A renaissance of interest in the stability of thin filaments [GL92-GF00], "
              "prompted by single-molecule manipulation of DNA and protein assemblies "
              "[SCB96-FESL97].", reason=HISTORY),
    Statement(INTRO, "Double-stranded DNA molecules are helices with strongly curved regions "
              "[BFKS95]; modelled as rods they need spontaneous curvature and twist.",
              rows=("caveat-dna-scale",)),
    Statement(INTRO, "Kirchhoff already considered naturally curved rods [Lov44]; little is known "
              "about spontaneous curvature and twist in buckling.", reason=HISTORY),
    Statement(INTRO, "Nonlinear equilibrium equations are derived for a rod under external forces "
              "and moments.", rows=("eq-munder",)),
    Statement(INTRO, "Both problems have well-known solutions without spontaneous twist [Lov44]: "
              "Euler's load of the straight rod, the ring under radial pressure.",
              rows=("rod-zero-twist", "ring-in-out-coincide")),
    Statement(INTRO, "Spontaneous twist stabilises the straight rod and destabilises the ring.",
              rows=("rod-stabilising", "ring-destabilises")),
    Statement(INTRO, "In both cases buckling takes place through a three-dimensional "
              "instability.", rows=("intro-three-dimensional", "rod-three-dimensional",
                                    "ring-three-dimensional")),
    # Sec. 1
    Statement(SEC1, "L ≫ a, a the largest dimension of the cross-section.",
              rows=("caveat-dna-scale",)),
    Statement(SEC1, "Eq. frenini: the reference frame's derivatives define ω_k0.",
              rows=("eq-inst1",)),
    Statement(SEC1, "u0, v0 are physical attributes of the rod and differ in general from the "
              "normal and binormal of the centreline.", reason=DEFINITION),
    Statement(SEC1, "Eq. radfin: cross-sections stay planar and perpendicular to the centreline.",
              reason="the Kirchhoff assumption of the model; every row inherits it"),
    Statement(SEC1, "Eq. frenet defines the generalised torsions ω_k of the deformed rod.",
              rows=("eq-inst1", "eq-munder")),
    Statement(SEC1, "Displacement gradient, strain tensor and a quadratic energy by the methods of "
              "[DR00].", reason="the method of another paper; the package derives inst1 from "
                                "its own quadratic energy instead (eq-inst1)"),
    Statement(SEC1, "Eq. constit with A1 = E1I1, A2 = E1I2, A3 = E2(I1 + I2).",
              rows=("eq-munder", "caveat-torsional-stiffness")),
    Statement(SEC1, "Eq. Munder: eliminating the cross-sectional forces gives the equilibrium "
              "conditions.", rows=("eq-munder",)),
    Statement(SEC1, "Given boundary conditions, Munder with constit uniquely determine F_t, ω1, "
              "ω2, ω3.", rows=("eq-unique",)),
    Statement(SEC1, "Eq. frenet, resolved with the ω_k, gives the centreline and the twist.",
              reason=DEFINITION),
    Statement(SEC1, "F_t is a Lagrange multiplier enforcing inextensibility.",
              rows=("rod-decoupling",)),
    # Sec. 2
    Statement(SEC2, "The rectilinear rod's sections rotate by Ω(s) about the centreline; A1 < A2, "
              "u0 along the smaller principal axis.", reason=DEFINITION),
    Statement(SEC2, "u0 = cos Ω e1 + sin Ω e2, v0 = −sin Ω e1 + cos Ω e2, so ω10 = ω20 = 0, "
              "ω30 = dΩ/ds (taken constant).", rows=("eq-inst1",)),
    Statement(SEC2, "Below the critical load the rod does not deform, the moments vanish and the "
              "internal force is −P.", rows=("eq-inst1",)),
    Statement(SEC2, "The perturbed moments M_u, M_v, M_t in terms of x1'', x2'', α'.",
              rows=("eq-inst1",)),
    Statement(SEC2, "The equations for the force perturbation and for α decouple from those for "
              "ω1, ω2.", rows=("rod-decoupling",)),
    Statement(SEC2, "Buckling is the first appearance of a non-vanishing solution of the "
              "unforced equations (adjacent equilibrium).",
              rows=("eq-inst1",)),
    Statement(SEC2, "Eq. inst1 with the geometric relations and hinged ends.",
              rows=("eq-inst1",)),
    Statement(SEC2, "Without spontaneous twist, inst1 are the conventional beam equations "
              "[TG63].", rows=("rod-zero-twist",)),
    Statement(SEC2, "Each ω_k obeys a fourth-order equation with even derivatives only, a "
              "combination of sin(β_k s) and cos(β_k s).", rows=("rod-even-order",
                                                                 "rod-beta-real")),
    Statement(SEC2, "β1, β2 are the positive roots of a characteristic equation.",
              rows=("rod-beta-real",)),
    Statement(SEC2, "p* = P_cr/P_cr with P_cr = π²A1/L² Euler's force of the untwisted rod "
              "[Lov44].", rows=("typo-p-star", "rod-zero-twist")),
    Statement(SEC2, "Ω(L) = ω30 L is the total spontaneous twist angle.", reason=DEFINITION),
    Statement(SEC2, "The numerical solutions for various ν are plotted in Figure 1.",
              rows=("fig1-curves",)),
    Statement(SEC2, "At the instability all generalised torsions are non-zero: buckling is "
              "intrinsically three-dimensional.", rows=("rod-three-dimensional",)),
    Statement(SEC2, "For ν = 1 the Euler result holds for every twist.",
              rows=("rod-isotropic",)),
    Statement(SEC2, "For ν > 1 p* increases initially and reaches a maximum at Ω(L) = 2π.",
              rows=("rod-first-maximum",)),
    Statement(SEC2, "Beyond it p* oscillates with maxima at integer multiples of π.",
              rows=("rod-further-maxima", "rod-twist-raises-load")),
    Statement(SEC2, "p* tends to a limiting value that depends on ν.", rows=("rod-limit",)),
    Statement(SEC2, "β2 − β1 oscillates with maxima at integer multiples of π and tends to 2π.",
              rows=("rod-beta-difference",)),
    Statement(SEC2, "Asymptotically β_k L → ω30 L ± π (resonance).", rows=("rod-resonance",)),
    Statement(SEC2, "The oscillation of p* arises from the interplay between the two modes.",
              rows=("rod-two-mode-interplay",)),
    Statement(SEC2, "At total twist kπ the end sections' symmetry axes are aligned, as without "
              "twist.", rows=("rod-end-alignment",)),
    # Sec. 3 (the ring scene's rows)
    Statement(SEC3, "The ring's reference frame: u0 = −cos Ω e_r + sin Ω e_z, ..., so ω10 = "
              "cos Ω/R0, ω20 = −sin Ω/R0, ω30 = dΩ/ds.",
              rows=("ring-spontaneous-torsions", "ring-hoop-force")),
    Statement(SEC3, "The load is a radially inward force per unit length q = −q e_r on the outer "
              "perimeter.", rows=("caveat-load-model",)),
    Statement(SEC3, "Below the critical value it is balanced by F_t = −qR0 and no displacement "
              "arises.", rows=("ring-hoop-force",)),
    Statement(SEC3, "y_r is eliminated by inextensibility; three coupled equations with variable "
              "coefficients for y_φ, y_z, α.", rows=("ring-three-coupled-equations",)),
    Statement(SEC3, "An analytical solution is possible only for I1 = I2.",
              rows=("ring-analytic-only-circular",)),
    Statement(SEC3, "For I1 = I2 the ring buckles at q_cr = 3E1I1/R0³.",
              rows=("ring-circular-limit",)),
    Statement(SEC3, "For a circular rod the critical force does not depend on the twist.",
              rows=("ring-circular-twist-independent",)),
    Statement(SEC3, "In-plane and out-of-plane buckling of a circular rod set in together.",
              rows=("ring-in-out-coincide",)),
    Statement(SEC3, "Ω(s) = Ns/R0 with N a positive integer.",
              rows=("caveat-admissible-twists",)),
    Statement(SEC3, "A Galerkin estimate [TG63] is expected to capture the qualitative effect of "
              "the twist.", rows=("ring-crit2",)),
    Statement(SEC3, "The perturbations are X_n sin(ns/R0) with a fixed n, averaged over the "
              "contour.", rows=("ring-fixed-n-ansatz", "ring-crit2-galerkin")),
    Statement(SEC3, "The adjacent-equilibrium criterion applies to the ring under the loads "
              "used.", rows=("ring-adjacent-equilibrium", "caveat-ring-supports")),
    Statement(SEC3, "Eq. crit2.", rows=("ring-crit2", "ring-crit2-galerkin",
                                         "ring-crit2-torsion-scaling")),
    Statement(SEC3, "For N² ≥ 3(I1 + I2)/(I2 − I1) − 1 the ring is unstable without external "
              "forces.", rows=("ring-spontaneous-instability",)),
    Statement(SEC3, "The perturbation equations are coupled, so the instability is "
              "three-dimensional.", rows=("ring-three-dimensional",)),
    Statement(SEC3, "[GT97] found no non-trivial solutions for the stress-free ring with periodic "
              "boundary conditions; the discrepancy stems from different problems.",
              rows=("ring-gt97-comparison",)),
    # conclusions
    Statement(CONCL, "Rods with spontaneous twist and non-circular sections, straight and ring.",
              reason=DEFINITION),
    Statement(CONCL, "For the straight rod an increase in twist raises the critical force and "
              "stabilises the rod.", rows=("rod-twist-raises-load", "rod-stabilising")),
    Statement(CONCL, "The effect increases with ν = I2/I1 > 1.", rows=("rod-stabilising",)),
    Statement(CONCL, "For the ring an increase in twist decreases the critical force "
              "monotonically.", rows=("ring-monotone-decrease", "ring-destabilises")),
    Statement(CONCL, "The rate of the decrease grows with ν.", rows=("ring-rate-grows-with-nu",)),
    Statement(CONCL, "For large twist the ring may buckle without external forces.",
              rows=("ring-spontaneous-instability",)),
    # figure
    Statement(CAPTION, "p* against Ω(L); curves 1, 2, 3 for ν = 1.1, 1.3, 1.5.",
              rows=("fig1-curves",)),
    Statement(SEC2, "'determine it stability' (for 'its').",
              reason="a spelling slip with no bearing on any result"),
)

def coverage_rows(known_ids: set[str]) -> list[list[str]]:
    """Table rows (where, statement, rows or reason) with unknown row ids marked."""
    out = []
    for s in COVERAGE:
        ids = ", ".join(f"`{r}`" + ("" if r in known_ids else " (not in this ledger)")
                        for r in s.rows)
        out.append([s.where, s.text, ids or "—", s.reason or ""])
    return out


def coverage_markdown(known_ids: set[str]) -> str:
    """``coverage.md``: the list as a table, with counts."""
    with_rows = sum(1 for s in COVERAGE if s.rows)
    lines = ["# The paper, sentence by sentence", "",
             f"{len(COVERAGE)} checkable statements of Drozdov & Rabin in the paper's order: "
             f"{with_rows} have ledger rows (`claims.md`), {len(COVERAGE) - with_rows} have a "
             "stated reason for none. Generated from `reproduce/claims/coverage.py`.", "",
             markdown_table(["where", "statement (abridged)", "ledger rows", "why no row"],
                            coverage_rows(known_ids))]
    return "\n".join(lines) + "\n"
