"""`python -m spectral_rod` / `spectral_rod.engine_report`: the engine that will solve Eq. inst1
(compiled kernel or numpy), its instruction-set variant, the BLAS and the versions; and the
engine line of `python -m reproduce`'s report."""

from __future__ import annotations

import pytest

import spectral_rod
from spectral_rod import _engine_report
from spectral_rod.rod.collocation import modal_kernel


def test_the_report_follows_the_kernel(monkeypatch):
    monkeypatch.setattr(modal_kernel, "available", lambda: False)
    engine = spectral_rod.engine_report()["engine"]
    assert engine["kernel"] is False and "variant" not in engine
    assert engine["engine"].startswith("numpy (no compiled kernel: install a C compiler")
    monkeypatch.setattr(modal_kernel, "available", lambda: True)
    engine = spectral_rod.engine_report()["engine"]
    assert engine["kernel"] is True and engine["engine"].startswith("C kernel")
    assert "variant" in engine


def test_engine_info_of_the_kernel_module_is_reported_as_it_is(monkeypatch):
    # the kernel module's own description, where it offers one, wins over the CPU's flags
    monkeypatch.setattr(modal_kernel, "available", lambda: True)
    monkeypatch.setattr(modal_kernel, "engine_info", lambda: {"engine": "kernel",
                                                              "isa": "x86-64-v3", "lanes": 32},
                        raising=False)
    engine = spectral_rod.engine_report()["engine"]
    assert engine["kernel"] is True and engine["engine"].startswith("C kernel")
    assert engine["variant"].startswith("x86-64-v3") and engine["lanes"] == 32


@pytest.mark.parametrize(("flags", "level"), [
    ("avx2 fma bmi1 bmi2 movbe f16c abm xsave avx512f avx512bw avx512cd avx512dq avx512vl",
     "x86-64-v4"),
    ("avx2 fma bmi1 bmi2 movbe f16c abm xsave avx512f", "x86-64-v3"),  # v4 needs all five
    ("avx2 fma bmi1 bmi2 movbe f16c abm", "default"),  # no xsave: not v3
])
def test_cpu_level_needs_every_feature_of_a_level(flags, level):
    assert _engine_report.cpu_level(f"flags\t\t: sse2 {flags}\n") == level


def test_the_text_names_the_engine_blas_and_versions():
    report = spectral_rod.engine_report()
    text = _engine_report._format(report)
    assert f"engine: {report['engine']['engine']}" in text
    assert "BLAS / OpenMP (threadpoolctl):" in text and "policy:" in text
    for name, version in report["dependencies"].items():
        assert f"  {name}: {version}" in text


def test_the_reproduce_report_records_the_engine():
    from reproduce._runner import versions

    assert versions()["engine"] == spectral_rod.engine_report()["summary"]


def test_format_engine_report_is_the_formatted_report():
    text = spectral_rod.format_engine_report()
    assert text.startswith(f"spectral_rod {spectral_rod.__version__} (Python ")
    assert f"kernel: {modal_kernel.available()}" in text
