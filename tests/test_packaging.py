"""What a user expects of the package (issue 13, items 2 and 5): licence, typing marker, the
data sidecar, Python scalars from scalar input, short reprs, the console script."""

from __future__ import annotations

import csv
import json
import math
import subprocess
import sys
from importlib import metadata, resources
from pathlib import Path

import numpy as np
import pytest

import spectral_rod
from spectral_rod import buckling_mode, critical_load
from spectral_rod.figure1.data import figure1_path, figure1_schema

ROOT = Path(__file__).resolve().parent.parent
META = metadata.metadata("spectral_rod")  # the installed metadata, built from pyproject.toml


def test_license_matches_pyproject():
    assert META["License-Expression"] == "MIT"
    assert (ROOT / "LICENSE").read_text(encoding="utf-8").startswith("MIT License")


def test_typed_and_data_ship_in_the_package():
    data = resources.files("spectral_rod")
    for name in ("py.typed", "data/figure1_digitised.csv", "data/figure1_digitised.json",
                 "data/figure1_digitised.md"):
        assert (data / name).is_file(), name


def test_every_dependency_declares_a_floor():
    reqs = metadata.requires("spectral_rod")
    assert reqs and all(">=" in r for r in reqs), reqs


def test_digitised_csv_matches_its_schema():
    # read with the csv module (not the package's loader) and check against the sidecar
    meta = figure1_schema()
    fields = meta["schema"]["fields"]
    with figure1_path().open(encoding="utf-8", newline="") as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == [f["name"] for f in fields]
    assert meta["path"] == figure1_path().name and meta["schema"]["primaryKey"]
    body = rows[1:]
    for j, f in enumerate(fields):
        values = [float(r[j]) for r in body]
        c = f["constraints"]
        assert all(c.get("minimum", -math.inf) <= v <= c.get("maximum", math.inf)
                   for v in values), f["name"]
        if "enum" in c:
            assert set(values) <= set(c["enum"]), f["name"]
        if f["type"] == "integer":
            assert all(r[j].isdigit() for r in body), f["name"]
        assert f["unit"] and f["description"]
    counts = {s["curve"]: s["points"] for s in meta["x-figure1"]["curves"]}
    assert {c: sum(r[0] == str(c) for r in body) for c in counts} == counts
    key = [(r[0], r[2]) for r in body]
    assert len(set(key)) == len(key)
    q = meta["x-figure1"]["quantisation"]
    assert q["twist_angle_step"] == q["picture_unit_step"] / 10
    assert q["p_star_step"] == q["picture_unit_step"] / 400


def test_scalar_full_output_gives_python_scalars():
    res = critical_load(5.0, 1.5, full_output=True)
    for name in ("p_star", "error_estimate", "tol"):
        assert type(getattr(res, name)) is float, name
    assert type(res.n) is int and type(res.converged) is bool and type(res.method) is str
    mode = buckling_mode(5.0, 1.5)
    assert type(mode.p_star) is float and type(mode.beta1) is float


def test_reprs_of_array_results_are_short():
    res = critical_load(np.linspace(0.0, 10.0, 2000), 1.5, full_output=True)
    assert len(repr(res)) < 600 and "shape=(2000,)" in repr(res)
    assert len(repr(buckling_mode(5.0, 1.5))) < 900


def test_console_script_and_version():
    scripts = metadata.entry_points(group="console_scripts")
    assert [e.value for e in scripts if e.name == "spectral-rod"] == [
        "reproduce.__main__:entry_point"]
    proc = subprocess.run([sys.executable, "-m", "reproduce", "--version"], capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 0
    assert proc.stdout.strip() == f"spectral_rod {spectral_rod.__version__}"
    json.dumps(figure1_schema())  # the sidecar is plain JSON


def test_the_c_kernel_is_built_where_a_compiler_is():
    # setup.py builds it as optional (a failed build still installs the package, with the
    # numpy engine alone): where a C compiler is on PATH a missing kernel is a build failure
    import shutil
    import sysconfig

    from spectral_rod.rod.collocation import modal_kernel

    compiler = (sysconfig.get_config_var("CC") or "cc").split()[0]
    if shutil.which(compiler) is None:
        import pytest

        pytest.skip(f"no C compiler ({compiler}) here")
    assert modal_kernel.available()


def test_one_source_for_the_version():
    # pyproject.toml reads the version from spectral_rod.__version__ (no second literal)
    tomllib = pytest.importorskip("tomllib")  # Python >= 3.11

    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "version" not in project["project"] and "version" in project["project"]["dynamic"]
    assert project["tool"]["setuptools"]["dynamic"]["version"] == {
        "attr": "spectral_rod.__version__"}
    assert META["Version"] == spectral_rod.__version__


def _cff_field(text: str, key: str) -> str:
    """A top-level scalar of a CITATION.cff (YAML), without a YAML parser."""
    for line in text.splitlines():
        if line.startswith(f"{key}:"):
            return line.partition(":")[2].strip().strip('"')
    raise AssertionError(f"CITATION.cff has no {key!r}")


def test_citation_names_the_package_version_and_the_paper():
    text = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    assert _cff_field(text, "cff-version") == "1.2.0"
    assert _cff_field(text, "version") == spectral_rod.__version__
    assert _cff_field(text, "license") == META["License-Expression"]
    assert 'title: "Buckling of rods with spontaneous twist and curvature"' in text
    assert "family-names: Drozdov" in text and "family-names: Rabin" in text


def test_changelog_has_unreleased_and_the_current_version():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert "## [Unreleased]" in text
    assert f"## [{spectral_rod.__version__}]" in text


def test_classifiers_name_every_supported_python():
    classifiers = META.get_all("Classifier") or []
    low = int(META["Requires-Python"].removeprefix(">=3."))
    for minor in range(low, 14):
        assert f"Programming Language :: Python :: 3.{minor}" in classifiers
    assert "Typing :: Typed" in classifiers
