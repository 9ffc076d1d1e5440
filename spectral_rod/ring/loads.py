"""What the ring's supports must restrain under each reading of the load (section "Stability of
a ring": "a radially inward-directed force per unit length q = -q e_r").

The four readings of :data:`spectral_rod.ring.second_variation.RING_LOADS` coincide on the circle
and
differ in how the force follows a displacement.  A rigid motion x of the ring stores no elastic
energy (x.K x = 0), so its second variation is -q/2 x.G x: the load lowers the potential of the
motion (the ring tips over, spins or drifts away for any q > 0) if x.G x > 0, leaves it neutral
(the ring may drift: the equilibrium is not unique) if x.G x = 0, and restores it if x.G x < 0.
:func:`rigid_motion_load_work` evaluates x.G x for the six rigid motions (three translations, a
spin about the ring's axis e_z and two tilts about diameters) with the second variation of
:mod:`spectral_rod.ring.second_variation` (the same G the solver uses).

Both solvers remove all six by the constraints int y ds = 0, int R0 x y ds = 0: a restraint of
the mean displacement and the mean rotation that does no work on any deformation of wavenumber
>= 2 (the constraints involve frequencies 0 and 1 only).  :func:`constraint_rank_on_rigid_motions`
checks that these constraints see every rigid motion.

>>> work = rigid_motion_load_work("dead")
>>> work["spin about e_z"] > 0, abs(work["translation e_x"]) < 1e-12
(True, True)
"""

from __future__ import annotations

import numpy as np

from spectral_rod.ring.second_variation import assemble, check_load, rigid_body_constraints

__all__ = ["RIGID_MOTIONS", "constraint_rank_on_rigid_motions", "rigid_motion_load_work",
           "rigid_motion_stiffness", "rigid_motion_vectors"]

#: The rigid motions of the ring (R = 1, R0 = e_r) in the fields (y_phi, y_z, alpha) of
#: :mod:`spectral_rod.ring.second_variation`: {(field, frequency, "c"|"s"): coefficient}.  A
#: translation
#: c gives y = c; a small rotation w gives y = w x e_r and the extra twist alpha = w.e_phi.
RIGID_MOTIONS: dict[str, dict[tuple[str, int, str], float]] = {
    "translation e_x": {("y_phi", 1, "s"): -1.0},  # e_x = cos s e_r - sin s e_phi
    "translation e_y": {("y_phi", 1, "c"): 1.0},  # e_y = sin s e_r + cos s e_phi
    "translation e_z": {("y_z", 0, "c"): 1.0},
    "spin about e_z": {("y_phi", 0, "c"): 1.0},  # e_z x e_r = e_phi, alpha = e_z.e_phi = 0
    "tilt about e_x": {("y_z", 1, "s"): 1.0, ("alpha", 1, "s"): -1.0},  # e_x x e_r = sin s e_z
    "tilt about e_y": {("y_z", 1, "c"): -1.0, ("alpha", 1, "c"): 1.0},  # e_y x e_r = -cos s e_z
}
#: The untwisted circular ring on frequencies 0 and 1 holds every rigid motion.
_RIGID_FREQUENCIES = [0, 1]


def rigid_motion_vectors() -> tuple[np.ndarray, np.ndarray, np.ndarray, list]:
    """(X, K, C, labels): the rigid motions as columns of X in the basis of frequencies 0 and 1
    (untwisted circular ring), K of that basis and the six constraints C of the solvers."""
    K, _, basis = assemble(0, 1.0, 1.0, "hydrostatic", _RIGID_FREQUENCIES)
    index = {lab: i for i, lab in enumerate(basis.labels)}
    X = np.zeros((basis.size, len(RIGID_MOTIONS)))
    for j, motion in enumerate(RIGID_MOTIONS.values()):
        for lab, coef in motion.items():
            X[index[lab], j] = coef
    return X, K, rigid_body_constraints(basis), basis.labels


def rigid_motion_stiffness() -> float:
    """max over the rigid motions of |x.K x| / max(diag K): zero to round-off if the vectors of
    :data:`RIGID_MOTIONS` are rigid (no bending or torsion).

    Returns
    -------
    float
        The largest relative strain energy of a rigid motion (round-off level).

    Examples
    --------
    >>> rigid_motion_stiffness() < 1e-12
    True
    """
    X, K, _, _ = rigid_motion_vectors()
    return float(np.max(np.abs(np.einsum("ij,ik,kj->j", X, K, X))) / np.max(np.diag(K)))


def rigid_motion_load_work(load: str) -> dict[str, float]:
    """x.G x / (2 pi) per rigid motion under `load` (one of
    :data:`spectral_rod.ring.second_variation.RING_LOADS`): > 0 the load destabilises the motion for
    every q > 0, 0 neutral, < 0 restoring (module docstring).

    Returns
    -------
    dict of str to float
        The load work per rigid motion, keyed by the motion's name.

    Examples
    --------
    >>> work = rigid_motion_load_work("hydrostatic")
    >>> sorted(work) == sorted(RIGID_MOTIONS)
    True
    """
    ld = check_load(load)
    X, _, _ = rigid_motion_vectors()[:3]
    _, G, _ = assemble(0, 1.0, 1.0, ld, _RIGID_FREQUENCIES)
    work = np.einsum("ij,ik,kj->j", X, G, X) / (2.0 * np.pi)
    return {name: float(w) for name, w in zip(RIGID_MOTIONS, work, strict=True)}


def constraint_rank_on_rigid_motions() -> int:
    """Rank of the solvers' constraints restricted to the rigid motions, C X (6: every rigid
    motion is restrained, none is left to drift).

    Returns
    -------
    int
        The rank (6 when every rigid motion is restrained).

    Examples
    --------
    >>> constraint_rank_on_rigid_motions()
    6
    """
    X, _, C, _ = rigid_motion_vectors()
    return int(np.linalg.matrix_rank(C @ X))
