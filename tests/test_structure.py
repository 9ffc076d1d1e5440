"""Issue 10: one core. The scenes use only the public API, one router answers every entry point,
and the kernels exist once."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import numpy as np

import spectral_rod

ROOT = Path(__file__).resolve().parent.parent


def _imports(path: Path) -> list[tuple[str, list[str]]]:
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module:
            out.append((node.module, [a.name for a in node.names]))
        elif isinstance(node, ast.Import):
            out += [(a.name, []) for a in node.names]
    return out


def test_scenes_import_only_the_public_api():
    public = set(spectral_rod.__all__) | {"__version__"}
    for path in (ROOT / "reproduce").rglob("*.py"):
        for module, names in _imports(path):
            if not module.startswith("spectral_rod"):
                continue
            assert module == "spectral_rod", (path, module)
            assert set(names) <= public, (path, set(names) - public)


def test_every_public_name_resolves():
    for name in spectral_rod.__all__:
        assert getattr(spectral_rod, name) is not None


def test_the_characteristic_roots_are_written_once():
    pattern = re.compile(r"\(\s*lam\s*-\s*mu\s*\)\s*\*\*\s*2\s*\+\s*8")
    hits = [p for p in (ROOT / "spectral_rod").rglob("*.py")
            if pattern.search(p.read_text(encoding="utf-8"))]
    assert [p.name for p in hits] == ["wavenumbers.py"]


def test_one_router_for_load_and_mode():
    # buckling_mode reports the method critical_load used, at every regime
    for twist, nu in ((5.0, 1.5), (1000.0, 1.5), (3.0, 1.0 + 1e-8), (0.0, 2.0)):
        res = spectral_rod.critical_load(twist, nu, full_output=True)
        mode = spectral_rod.buckling_mode(twist, nu)
        assert mode.method == res.method == spectral_rod.choose_method(twist, nu)
        # the same route and point; at large twist the mode's array path and the load's scalar
        # path may differ by an ulp (numpy's sin/cos against libm's, depending on numpy's build)
        assert abs(mode.p_star - res.p_star) <= 4 * np.finfo(float).eps * res.p_star
        assert mode.converged
        assert 1.0 <= mode.p_star <= (1 + nu) / 2


def test_closed_form_mode_equals_the_collocation_mode():
    # the mode of the characteristic and increment routes (closed form at the router's p*)
    # against the collocation eigenvector, where both are available
    for twist, nu in ((30.0, 1.5), (-7.0, 2.0), (3.0, 1.0 + 1e-8)):
        a = spectral_rod.buckling_mode(twist, nu, method="collocation")
        b = spectral_rod.buckling_mode(twist, nu, method="characteristic")
        assert a.family == b.family
        for f in ("omega1", "omega2", "x1", "x2"):
            assert np.max(np.abs(getattr(a, f) - getattr(b, f))) < 1e-8, (twist, nu, f)


def test_large_twist_mode_is_finite_and_fast():
    m = spectral_rod.buckling_mode(1000.0, 1.3)
    assert m.method == "characteristic" and m.converged
    assert np.all(np.isfinite(m.x1)) and abs(m.x1[0]) < 1e-12 and abs(m.x1[-1]) < 1e-12


def _type_checking_names(init: Path) -> dict[str, str]:
    """Public name -> "module:attribute" as the TYPE_CHECKING block of `init` binds it (an
    import ``from spectral_rod.M import A as N`` or an assignment ``N = _M.A``)."""
    tree = ast.parse(init.read_text(encoding="utf-8"))
    block = next(node for node in tree.body if isinstance(node, ast.If)
                 and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING")
    aliases, names = {}, {}
    for node in block.body:
        if isinstance(node, ast.Import):
            aliases.update({a.asname: a.name for a in node.names if a.asname})
        elif isinstance(node, ast.ImportFrom):
            for a in node.names:
                names[a.asname or a.name] = f"{node.module}:{a.name}"
        elif isinstance(node, ast.Assign):
            value = node.value
            assert isinstance(value, ast.Attribute) and isinstance(value.value, ast.Name)
            names[node.targets[0].id] = f"{aliases[value.value.id]}:{value.attr}"
    return names


def test_type_checking_block_matches_the_lazy_exports():
    # the names type checkers see are exactly the lazy loader's, bound to the same objects
    seen = _type_checking_names(ROOT / "spectral_rod" / "__init__.py")
    expected = {}
    for name, target in spectral_rod._EXPORTS.items():
        module, _, attr = target.partition(":")
        expected[name] = f"spectral_rod.{module}:{attr or name}"
    assert seen == expected


def test_a_misspelled_public_name_is_an_attribute_error():
    import pytest

    with pytest.raises(AttributeError, match="critical_lod"):
        spectral_rod.critical_lod  # noqa: B018
