"""Executable derivations (sympy): every hand step behind a formulation, checked by machine.

* :mod:`.straight_rod` -- Eq. ``inst1`` from the energy (Euler-Lagrange) and from the paper's
  Eqs. ``Munder`` with ``constit`` (linearised about the compressed twisted rod), the decoupling
  of the force perturbation and of the rotation alpha, the hinged end conditions, and the
  misprinted variants of ``inst1`` evaluated against Figure 1;
* :mod:`.ring_linearisation` -- the second variation of the twisted ring (Eqs. ``frenini``,
  ``Munder``, ``frenet``, ``constit``) behind :mod:`spectral_rod.ring.second_variation`.

They ship with the package (sympy is a runtime dependency) because the claims ledger runs them:
``python -m spectral_rod.derivations.straight_rod`` prints one. The test suite runs them too.
"""

from __future__ import annotations

import importlib

__all__ = ["DERIVATIONS", "derivation_status", "inst1_variant_table"]

#: The derivations by name (module in this package).
DERIVATIONS = ("straight_rod", "ring_linearisation")


def derivation_status(name: str) -> str:
    """Run one derivation: "all steps checked", or "a step failed: <the step>".

    Every step is checked by :func:`._sympy.check` (not by ``assert``, so also under
    ``python -O``). A failed step is evidence (a wrong equation), not a crash, so it is
    returned as text naming the step.

    Parameters
    ----------
    name : str
        One of :data:`DERIVATIONS`.

    Returns
    -------
    str
        "all steps checked", or "a step failed: <the step>".

    Examples
    --------
    >>> derivation_status("ring_linearisation")
    'all steps checked'
    """
    from spectral_rod.derivations._sympy import DerivationError

    if not isinstance(name, str):
        raise TypeError(f"name must be one of {DERIVATIONS}, got {type(name).__name__}")
    if name not in DERIVATIONS:
        raise ValueError(f"name must be one of {DERIVATIONS}, got {name!r}")
    module = importlib.import_module(f"spectral_rod.derivations.{name}")
    try:
        module.derive()
    except DerivationError as exc:
        return f"a step failed: {exc.step}"
    return "all steps checked"


def inst1_variant_table() -> list[dict[str, object]]:
    """The misprinted variants of Eq. inst1 against Figure 1 (see :mod:`.straight_rod`).

    Returns
    -------
    list of dict
        One row per (variant, nu), nu in Figure 1's 1.1, 1.3, 1.5: the variant's coefficients,
        its largest change of p* on Omega(L) in [0, 10] against the mpmath characteristic
        equation, and its deviation from the digitised Figure 1 (keys in
        :func:`spectral_rod.derivations.straight_rod.variant_table`). Cost: about 5 s.

    Examples
    --------
    Only the printed equation and the one with the A's exchanged stay within the figure's
    resolution; a coupling factor 1 or a flipped sign moves p* by units:

    >>> rows = inst1_variant_table()
    >>> sorted({r["variant"] for r in rows if r["figure_max"] < 1e-3})
    ['A_exchanged', 'printed']
    """
    from spectral_rod.derivations.straight_rod import variant_table

    return variant_table()
