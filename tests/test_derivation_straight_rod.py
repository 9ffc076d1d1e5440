"""Eq. ``inst1`` derived by machine (derivations/straight_rod.py), and the variants a misprint
would be: each step's result, the derivation failing on a wrong equation, the small variant
solver against the mpmath reference and closed forms, and each variant against Figure 1."""

from __future__ import annotations

import math
from types import ModuleType

import numpy as np
import pytest
import sympy as sp

import spectral_rod.derivations.straight_rod as straight_rod
from reproduce.figure1 import MAX_LIMIT, RMS_LIMIT
from spectral_rod.derivations._sympy import DerivationError
from spectral_rod.figure1.data import FIGURE1_NU

WRONG = ("factor_one", "sign_flipped", "A_exchanged")
CHANGES_P = ("factor_one", "sign_flipped")


@pytest.fixture(scope="module")
def mod() -> ModuleType:
    return straight_rod


@pytest.fixture(scope="module")
def derived(mod: ModuleType) -> dict:
    return mod.derive()


@pytest.fixture(scope="module")
def table(mod: ModuleType) -> dict[tuple[str, float], dict]:
    return {(r["variant"], r["nu"]): r for r in mod.variant_table()}


# ---------------------------------------------------------------- the derivation, step by step

def test_reference_state_and_first_order_torsions(mod: ModuleType, derived: dict) -> None:
    assert derived["w0"] == (0, 0, mod.omega30)
    om, s = mod.omega30 * mod.s, mod.s
    x1pp, x2pp = mod.x1.diff(s, 2), mod.x2.diff(s, 2)
    want = (x1pp * sp.cos(om) + x2pp * sp.sin(om), -x1pp * sp.sin(om) + x2pp * sp.cos(om),
            mod.alpha.diff(s))
    for got, w in zip(derived["w_first"], want, strict=True):
        assert mod._z(got - w)


def test_munder_first_order_is_the_printed_inst1(mod: ModuleType, derived: dict) -> None:
    lin = derived["munder_first"]
    # the printed inst1 written out by hand (not through mod.inst1; derive() compares with it)
    A1, A2, P, om, s = mod.A1, mod.A2, mod.P, mod.omega30, mod.s
    w1, w2 = mod.w1, mod.w2
    assert mod._z(lin[2] - (A1 * w1.diff(s, 2) + (P - A1 * om**2) * w1
                            - 2 * A2 * om * w2.diff(s)))
    assert mod._z(lin[3] + (A2 * w2.diff(s, 2) + (P - A2 * om**2) * w2
                            + 2 * A1 * om * w1.diff(s)))


@pytest.mark.parametrize("variant", WRONG)
def test_munder_first_order_rejects_each_variant(mod: ModuleType, derived: dict,
                                                 variant: str) -> None:
    c1, c2 = mod.SYMBOLIC_VARIANTS[variant]
    V1, V2 = mod.coupling_operator(c1, c2)
    lin = derived["munder_first"]
    assert not (mod._z(lin[2] - V1) and mod._z(lin[3] + V2))


def test_energy_route_is_inst1_in_the_body_frame(mod: ModuleType, derived: dict) -> None:
    en = derived["energy"]
    F = mod.frames()
    xv = mod.x1 * F["e1"] + mod.x2 * F["e2"]
    k1, k2 = xv.diff(mod.s, 2).dot(F["u0"]), xv.diff(mod.s, 2).dot(F["v0"])
    # natural end condition A1 w1 u0 + A2 w2 v0 = 0: its body components are the end moments
    nat = en["natural_bc"]
    assert mod._z(nat.dot(F["u0"]) - mod.A1 * k1) and mod._z(nat.dot(F["v0"]) - mod.A2 * k2)


def test_hinged_centreline_vanishes_where_w_does(mod: ModuleType, derived: dict) -> None:
    xw = derived["x_hinged"]
    # (x_w''.u0 - w1 = -I1/P is checked by derive(), step 6)
    # at the ends w = 0 makes x_w = 0: x_w is linear in (w1, w2) with no free term
    assert all(mod._z(c.subs({mod.w1: 0, mod.w2: 0})) for c in xw)


@pytest.mark.parametrize("variant", WRONG)
@pytest.mark.parametrize("route", ["linearised_munder", "energy_route"])
def test_each_route_fails_on_a_misprinted_inst1(mod: ModuleType, derived: dict,
                                                monkeypatch: pytest.MonkeyPatch,
                                                variant: str, route: str) -> None:
    """The steps compare against mod.inst1; replaced by a variant, both routes must fail, at
    the step that compares with inst1."""
    c1, c2 = mod.SYMBOLIC_VARIANTS[variant]

    def wrong(v1: sp.Expr, v2: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
        return mod.coupling_operator(c1, c2, v1=v1, v2=v2)

    monkeypatch.setattr(mod, "inst1", wrong)
    arg = derived["w_first"] if route == "linearised_munder" else mod.frames()
    step = {"linearised_munder": "4: line 3 of Eq. Munder at order eps^1 is I1 of inst1",
            "energy_route": "5: E.u0 = I1, E.v0 = I2 (inst1 in the body frame)"}[route]
    with pytest.raises(DerivationError) as info:
        getattr(mod, route)(arg)
    assert info.value.step == step


def test_variant_structure(mod: ModuleType, derived: dict) -> None:
    v = derived["variants"]
    A1, A2 = mod.A1, mod.A2
    A, om = sp.Symbol("A", positive=True), mod.omega30
    expect = {"printed": (-4 * A1 * A2, A2 / A1, 0),
              "factor_one": (-A1 * A2, A2 / A1, sp.Rational(3, 4) * A * om**2),
              "sign_flipped": (4 * A1 * A2, -A2 / A1, 2 * A * om**2),
              "A_exchanged": (-4 * A1 * A2, A1 / A2, 0)}
    for name, (prod, weight, shift) in expect.items():
        got = v[name]
        assert sp.simplify(got["product"] - prod) == 0, name
        assert sp.simplify(got["weight"] - weight) == 0, name
        assert sp.simplify(got["nu1_shift"] - shift) == 0, name


# ---------------------------------------------------------------- the small variant solver

SOLVER_POINTS = [(0.3, 1.1), (1.0, 1.5), (2.8, 1.5), (3.0, 1.3), (2 * math.pi, 1.1),
                 (2 * math.pi, 1.5), (7.5, 1.3), (10.0, 1.5), (10.0, 4.0), (15.0, 2.0)]


@pytest.mark.parametrize(("twist_angle", "nu"), SOLVER_POINTS)
def test_solver_on_printed_inst1_matches_reference(mod: ModuleType, reference, twist_angle: float,
                                                   nu: float) -> None:
    root = mod.variant_critical_load(mod.variant_coefficients("printed", nu), twist_angle)
    assert root.p_star == pytest.approx(reference(twist_angle, nu), abs=1e-9)
    assert root.error < 1e-9 and root.lowest_complex is None


@pytest.mark.parametrize("twist_angle", [0.5, 2.0, 5.0, 10.0])
def test_solver_on_variants_matches_isotropic_closed_forms(mod: ModuleType,
                                                           twist_angle: float) -> None:
    """At nu = 1 (step 7): p* = 1 + shift/(A pi^2) with shift 0, 3/4 Om^2, 2 Om^2, 0."""
    shift = {"printed": 0.0, "factor_one": 0.75, "sign_flipped": 2.0, "A_exchanged": 0.0}
    for name, k in shift.items():
        root = mod.variant_critical_load(mod.variant_coefficients(name, 1.0), twist_angle)
        assert root.p_star == pytest.approx(1 + k * twist_angle**2 / math.pi**2, abs=1e-9), name


def test_exchanged_variant_only_rescales_the_mode(mod: ModuleType) -> None:
    nu, om = 1.5, 3.0
    p, a1, a2 = mod.coupled_mode(mod.variant_coefficients("printed", nu), om)
    q, b1, b2 = mod.coupled_mode(mod.variant_coefficients("A_exchanged", nu), om)
    assert q == pytest.approx(p, abs=1e-12)
    # exchanged mode = (w1, nu w2) of the printed one, up to normalisation
    v, u = np.r_[a1, nu * a2], np.r_[b1, b2]
    u = u * (v @ u) / (u @ u)
    assert np.max(np.abs(u - v)) < 1e-10 * np.max(np.abs(v))
    assert np.max(np.abs(b2 / np.max(np.abs(b1)) - a2 / np.max(np.abs(a1)))) > 0.1


def test_bad_input_is_named(mod: ModuleType) -> None:
    with pytest.raises(ValueError, match="name"):
        mod.variant_coefficients("nonsense", 1.1)
    with pytest.raises(ValueError, match="nu"):
        mod.variant_coefficients("printed", -1.0)
    coeffs = mod.variant_coefficients("printed", 1.1)
    with pytest.raises(ValueError, match="n must"):
        mod.variant_critical_load(coeffs, 1.0, n=4)
    with pytest.raises(ValueError, match="twist_angle"):
        mod.variant_critical_load(coeffs, float("nan"))


# ---------------------------------------------------------------- variants against Figure 1

def test_printed_inst1_matches_every_digitised_point(mod: ModuleType) -> None:
    for nu in FIGURE1_NU:
        dev = mod.figure1_deviation("printed", nu, every=1)
        assert dev["max"] <= MAX_LIMIT and dev["rms"] <= RMS_LIMIT, (nu, dev)


@pytest.mark.parametrize("nu", [1.1, 1.3, 1.5])
def test_variants_against_reference_and_figure(table: dict, nu: float) -> None:
    printed = table[("printed", nu)]
    assert printed["max_change"] < 1e-10 and printed["figure_max"] <= MAX_LIMIT
    for name in CHANGES_P:
        row = table[(name, nu)]
        # measured: figure_max 7.8-14.9, figure_rms 3.5-7.1, onset 0.05-0.085 rad
        assert row["figure_max"] > 1e4 * MAX_LIMIT and row["figure_rms"] > 1e4 * RMS_LIMIT
        assert row["max_change"] > 5.0 and row["onset_twist"] < 0.1
        assert row["p_star_at_2pi"] > (1 + nu) / 2  # beyond the Rayleigh bound of inst1
    exch = table[("A_exchanged", nu)]
    assert exch["max_change"] < 1e-10 and exch["onset_twist"] is None
    assert exch["figure_max"] == pytest.approx(printed["figure_max"], abs=1e-10)


@pytest.mark.parametrize("nu", [1.1, 1.3, 1.5])
def test_only_the_non_self_adjoint_variant_has_complex_eigenvalues(table: dict,
                                                                   nu: float) -> None:
    for name in ("printed", "factor_one", "A_exchanged"):
        assert table[(name, nu)]["self_adjoint_weight"] > 0
        assert not table[(name, nu)]["complex_eigenvalues"], name
    flip = table[("sign_flipped", nu)]
    assert flip["self_adjoint_weight"] < 0 and flip["complex_eigenvalues"]
    assert all(r["max_solver_error"] < 1e-10 for r in table.values())
