"""The twisted ring (paper's Eqs. ``Munder``, ``constit``, ``frenet``, ``crit2``): the
formula and threshold twist, the classical closed forms, the two formulations (second
variation, Munder)."""
