"""Closed forms for the ring (paper, section "Stability of a ring"): the untwisted ring in and
out of its plane under each reading of the load, and the rapidly twisted ring by homogenisation.

Loads q R^3 / (E1 I1) for a bending stiffness A (in units of E1 I1) and torsional stiffness A3.
The untwisted ring's in-plane and out-of-plane problems decouple; a mode of wavenumber n >= 2
(n = 0, 1 are rigid motions) with amplitude a makes the bending energy and the load work

* in plane (y_phi = a cos ns, theta_z = (1 - n^2) y_phi):
  x.K x = A n^2 (n^2 - 1)^2 pi a^2,  x.G x = [(n^2 - 1)^2 - L_in] pi a^2;
* out of plane (y_z = a cos ns, the twist alpha minimising the energy):
  x.K x = A n^2 (n^2 - 1)^2 pi a^2 / (n^2 + A/A3) (Timoshenko & Gere),
  x.G x = [n^2 - L_out] pi a^2,

where the hoop force gives (n^2 - 1)^2 and n^2, and the second-order load potential of
:mod:`spectral_rod.ring.second_variation` gives L_in, L_out per load:

=============  ============================  ===================  =====================  =======
load           L_in                          L_out                in plane, q(n)         n = 2
=============  ============================  ===================  =====================  =======
hydrostatic    -(n^2 - 1)  (int y_phi th_z)  0                    A (n^2 - 1)            3 A
axis           1           (int y_phi^2)     0                    A (n^2-1)^2/(n^2-2)    4.5 A
centre         1           (int y_phi^2)     1  (int y_z^2)       A (n^2-1)^2/(n^2-2)    4.5 A
dead           0                             0                    A n^2                  4 A
=============  ============================  ===================  =====================  =======

Out of plane, q(n) = A (n^2 - 1)^2/(n^2 + A/A3) for hydrostatic, axis and dead (n = 2:
9 A/(4 + A/A3)), and A n^2 (n^2 - 1)/(n^2 + A/A3) for centre (n = 2: 12 A/(4 + A/A3)).

Each q(n) increases with n for n >= 2, so the critical load is the n = 2 value: with m = n^2 >= 4
and c = A/A3 >= 0, d/dm (m - 1)^2/(m - 2) = (m - 1)(m - 3)/(m - 2)^2 > 0,
d/dm (m - 1)^2/(m + c) = (m - 1)(m + 1 + 2c)/(m + c)^2 > 0 and
d/dm m (m - 1)/(m + c) = (m^2 + 2 m c - c)/(m + c)^2 > 0 (``tests/test_ring_closed_forms.py``
scans n to confirm).  The classical in-plane values 3, 4.5 and 4 EI/R^3 for pressure normal to
the deformed ring, a centrally directed load and a load of constant direction are those of
Simitses & Hodges, *Fundamentals of Structural Stability*, ch. 8 (rings).  These closed forms
are independent of the solvers :mod:`spectral_rod.ring.second_variation` and
:mod:`spectral_rod.ring.munder` (only the input checks are shared), which are checked against
them at N = 0 for every nu and load, and in the limit N -> infinity.

At N = 0 the ring with I1 != I2 also has a closed form (:func:`untwisted_critical_load`): in
plane it bends about e_z with A1, out of plane about e_r with A2 = nu A1.

>>> [in_plane_untwisted(1.0, ld) for ld in ("hydrostatic", "axis", "centre", "dead")]
[3.0, 4.5, 4.5, 4.0]
"""

from __future__ import annotations

from spectral_rod._validation import check_int, check_real, scalar_nu
from spectral_rod.ring.formula import check_e_ratio
from spectral_rod.ring.second_variation import check_load

__all__ = ["homogenised_limit", "in_plane_mode_load", "in_plane_untwisted",
           "out_of_plane_mode_load", "out_of_plane_supremum", "out_of_plane_untwisted",
           "untwisted_critical_load"]

#: Largest wavenumber accepted by the per-mode loads.
MAX_WAVENUMBER = 10**6


def _stiffness(value: object, name: str) -> float:
    return check_real(value, name, 0.0, 1.0e12, lo_open=True)


def _wavenumber(n: object) -> int:
    return check_int(n, "n (wavenumber of the mode)", 2, MAX_WAVENUMBER)


def in_plane_mode_load(n: int, A: float, load: str = "hydrostatic") -> float:
    """Load of the untwisted ring's in-plane mode of wavenumber n >= 2 (table in the module
    docstring): A (n^2 - 1) hydrostatic, A (n^2 - 1)^2/(n^2 - 2) axis and centre, A n^2 dead.

    Returns
    -------
    float
        q R^3/(E1 I1) of that mode.

    Examples
    --------
    >>> in_plane_mode_load(2, 1.0), in_plane_mode_load(3, 1.0, "dead")
    (3.0, 9.0)
    """
    m = float(_wavenumber(n)) ** 2
    A = _stiffness(A, "A")
    ld = check_load(load)
    if ld == "hydrostatic":
        return A * (m - 1.0)
    if ld == "dead":
        return A * m
    return A * (m - 1.0) ** 2 / (m - 2.0)


def out_of_plane_mode_load(n: int, A: float, A3: float, load: str = "hydrostatic") -> float:
    """Load of the untwisted ring's out-of-plane mode of wavenumber n >= 2 (module docstring):
    A (n^2 - 1)^2/(n^2 + A/A3), or A n^2 (n^2 - 1)/(n^2 + A/A3) for the centre load.

    Returns
    -------
    float
        q R^3/(E1 I1) of that mode.

    Examples
    --------
    >>> out_of_plane_mode_load(2, 1.0, 2.0)   # 9/(4 + 1/2)
    2.0
    >>> round(out_of_plane_mode_load(2, 1.0, 1e12), 9) == out_of_plane_supremum(1.0)   # A3 -> inf
    True
    """
    m = float(_wavenumber(n)) ** 2
    A, A3 = _stiffness(A, "A"), _stiffness(A3, "A3")
    work = m - 1.0 if check_load(load) == "centre" else (m - 1.0) ** 2 / m
    return A * A3 * m * work / (m * A3 + A)  # = A m work/(m + A/A3) without overflow of A/A3


def in_plane_untwisted(A: float, load: str) -> float:
    """Untwisted ring, in plane: the n = 2 load of :func:`in_plane_mode_load` (the smallest),
    3 A (hydrostatic), 4.5 A (axis, centre), 4 A (dead).

    Returns
    -------
    float
        The untwisted ring's in-plane critical load q R^3/(E1 I1).

    Examples
    --------
    >>> in_plane_untwisted(1.0, "hydrostatic"), in_plane_untwisted(1.0, "axis")
    (3.0, 4.5)
    """
    A = _stiffness(A, "A")
    return {"hydrostatic": 3.0, "axis": 4.5, "centre": 4.5, "dead": 4.0}[check_load(load)] * A


def out_of_plane_untwisted(A: float, A3: float, load: str = "hydrostatic") -> float:
    """Timoshenko & Gere: the n = 2 load of :func:`out_of_plane_mode_load` (the smallest),
    9 A/(4 + A/A3) (hydrostatic, axis, dead) or 12 A/(4 + A/A3) (centre).

    Returns
    -------
    float
        The untwisted ring's out-of-plane critical load q R^3/(E1 I1).

    Examples
    --------
    >>> out_of_plane_untwisted(1.0, 2.0)   # circular section, e = 1: A3 = 2 A
    2.0
    """
    A, A3 = _stiffness(A, "A"), _stiffness(A3, "A3")
    top = 12.0 if check_load(load) == "centre" else 9.0
    return top * A * A3 / (4.0 * A3 + A)  # = top A/(4 + A/A3) without overflow of A/A3


def out_of_plane_supremum(A: float, load: str = "hydrostatic") -> float:
    """sup over A3 of the out-of-plane load (A3 -> infinity), the n = 2 value: 9A/4, or 3A for
    the centre load.

    Returns
    -------
    float
        The supremum, q R^3/(E1 I1).

    Examples
    --------
    >>> out_of_plane_supremum(1.0), out_of_plane_supremum(1.0, "centre")
    (2.25, 3.0)
    """
    return (3.0 if check_load(load) == "centre" else 2.25) * _stiffness(A, "A")


def untwisted_critical_load(nu: float, e_ratio: float, load: str) -> float:
    """Critical load of the untwisted ring (N = 0) for any nu = I2/I1 >= 1: the smaller of the
    in-plane load (bending about e_z, A1 = 1) and the out-of-plane load (bending about e_r,
    A2 = nu; torsion A3 = e (1 + nu)).

    Returns
    -------
    float
        q_cr R^3/(E1 I1) of the untwisted ring.

    Examples
    --------
    >>> untwisted_critical_load(1.0, 1.0, "hydrostatic"), untwisted_critical_load(4.0, 1.0, "dead")
    (2.0, 4.0)
    """
    nu, e_ratio = scalar_nu(nu), check_e_ratio(e_ratio)
    return min(in_plane_untwisted(1.0, load),
               out_of_plane_untwisted(nu, e_ratio * (1.0 + nu), load))


def homogenised_limit(nu: float, e_ratio: float, load: str) -> float:
    """N -> infinity: the rotating bending stiffness homogenises to the isotropic harmonic mean
    2 A1 A2/(A1 + A2) (1-D homogenisation of the curvature energy), A3 = e (1 + nu) unchanged;
    the load is the smaller of the in-plane and out-of-plane loads of that ring.

    Returns
    -------
    float
        The limit of q_cr R^3/(E1 I1) as N -> infinity.

    Examples
    --------
    >>> homogenised_limit(1.0, 1.0, "hydrostatic")   # circular: 9 A / (4 + A/A3), A3 = 2 A
    2.0
    >>> import spectral_rod as sr   # a circular section does not feel the twist
    >>> round(sr.ring_critical_load(8, 1.0), 12)
    2.0
    """
    nu, e_ratio = scalar_nu(nu), check_e_ratio(e_ratio)
    a_h = 2.0 * nu / (1.0 + nu)
    return min(in_plane_untwisted(a_h, load),
               out_of_plane_untwisted(a_h, e_ratio * (1.0 + nu), load))
