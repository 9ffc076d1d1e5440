"""The engine's contract (``_modal_kernel.h``): the ABI version and struct sizes checked at load,
the switch to the numpy reference, the PerformanceWarning without the kernel, engine_info."""

from __future__ import annotations

import ctypes
import subprocess
import sys
import warnings

import numpy as np
import pytest

from spectral_rod.errors import PerformanceWarning
from spectral_rod.rod.collocation import modal_kernel

needs_kernel = pytest.mark.skipif(not modal_kernel.available(),
                                  reason="the C kernel is not built here")


class _FakeLibrary:
    """A stand-in for the CDLL whose ABI version or struct sizes are chosen by the test."""

    def __init__(self, version: int, sizes: dict[int, int] | None = None):
        real = modal_kernel._library()
        self._sizes = {i: ctypes.sizeof(s) for i, s in enumerate(modal_kernel._STRUCTS)}
        self._sizes.update(sizes or {})
        self.modal_abi_version = lambda: version
        self.modal_struct_size = lambda which: self._sizes.get(which, 0)
        for name in ("modal_lowest", "modal_points", "pencil_terms_dd", "modal_lanes",
                     "modal_isa"):
            setattr(self, name, getattr(real, name))


@needs_kernel
def test_the_loader_accepts_the_build_it_was_written_for():
    lib, reason = modal_kernel._checked(_FakeLibrary(modal_kernel.ABI_VERSION))
    assert lib is not None and reason == ""


@needs_kernel
def test_an_abi_mismatch_refuses_the_kernel_with_a_clear_reason():
    lib, reason = modal_kernel._checked(_FakeLibrary(modal_kernel.ABI_VERSION + 1))
    assert lib is None
    assert f"ABI version is {modal_kernel.ABI_VERSION + 1}" in reason


@needs_kernel
def test_a_struct_size_mismatch_refuses_the_kernel():
    lib, reason = modal_kernel._checked(_FakeLibrary(modal_kernel.ABI_VERSION, {3: 8}))
    assert lib is None and "Family" in reason


@needs_kernel
def test_the_build_reports_its_abi_isa_and_lanes():
    info = modal_kernel.engine_info()
    assert info["engine"] == "kernel" and info["available"] and info["reason"] == ""
    assert info["abi_version"] == info["abi_expected"] == modal_kernel.ABI_VERSION
    assert info["isa"] in ("x86-64-v4", "x86-64-v3", "default", "portable")
    assert info["lanes"] == 32


@needs_kernel
def test_an_illegal_argument_is_named_by_its_position():
    # INFO = -i for the i-th argument (_modal_kernel.h): a negative P in ModalBatch
    lib = modal_kernel._library()
    buf = np.zeros(16)
    batch = modal_kernel.ModalBatch(-1, 2, 2, *[buf.ctypes.data] * 8, None)
    control = modal_kernel.ModalControl(1.0, 1e-14, 1e-10, 0.0, 6, 40, 0)
    out = modal_kernel.ModalEigenpairs()
    assert lib.modal_lowest(ctypes.byref(batch), ctypes.byref(control), ctypes.byref(out)) == -1
    batch.P = 0
    control.first = 0  # first must be >= 1
    assert lib.modal_lowest(ctypes.byref(batch), ctypes.byref(control), ctypes.byref(out)) == -2
    control.first = 6
    assert lib.modal_lowest(ctypes.byref(batch), ctypes.byref(control), ctypes.byref(out)) == 0


_CHILD = """
import warnings, json, sys
warnings.simplefilter("always")
from spectral_rod import critical_load
from spectral_rod.rod.collocation import modal_kernel
with warnings.catch_warnings(record=True) as got:
    warnings.simplefilter("always")
    a = critical_load(3.0, 1.5)
    b = critical_load([3.0, 4.0, 5.0], 1.5)
    c = critical_load(6.0, 2.0)
perf = [str(w.message) for w in got if w.category.__name__ == "PerformanceWarning"]
print(json.dumps({"info": modal_kernel.engine_info(), "perf": perf, "p": a}))
"""


def _child(env_value: str | None) -> dict:
    import json
    import os

    env = dict(os.environ)
    env.pop(modal_kernel.DISABLE_ENV, None)
    if env_value is not None:
        env[modal_kernel.DISABLE_ENV] = env_value
    # from a neutral directory: `python -c` puts the working directory first on sys.path, and
    # a source tree there (an unpacked sdist) would shadow the installed package and its kernel
    import tempfile

    with tempfile.TemporaryDirectory() as cwd:
        out = subprocess.run([sys.executable, "-c", _CHILD], env=env, capture_output=True,
                             text=True, check=True, timeout=300, cwd=cwd)
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_without_the_kernel_the_first_solve_warns_once_and_says_how_to_get_it():
    got = _child("1")
    assert got["info"]["engine"] == "numpy" and not got["info"]["available"]
    assert modal_kernel.DISABLE_ENV in got["info"]["reason"]
    assert len(got["perf"]) == 1  # three solves, one warning
    assert "C compiler" in got["perf"][0] and "reinstall" in got["perf"][0]
    assert abs(got["p"] - 1.0780926110) < 1e-9


@needs_kernel
def test_with_the_kernel_no_performance_warning():
    got = _child(None)
    assert got["info"]["engine"] == "kernel" and got["perf"] == []


def test_the_performance_warning_is_silenceable(monkeypatch):
    monkeypatch.setattr(modal_kernel, "_library", lambda: None)
    monkeypatch.setattr(modal_kernel, "_warned", False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", category=PerformanceWarning)
        modal_kernel.warn_if_missing()  # filtered: no error
    monkeypatch.setattr(modal_kernel, "_warned", False)
    with pytest.warns(PerformanceWarning):
        modal_kernel.warn_if_missing()
    assert issubclass(PerformanceWarning, UserWarning)


# --- which engine ran: CriticalLoad.engine -----------------------------------------------------

def _figure1_sample():
    from spectral_rod import load_figure1

    d = load_figure1()
    return d["twist_angle"].to_numpy()[::11], d["nu"].to_numpy()[::11]


@needs_kernel
def test_full_output_names_the_kernel_where_it_ran():
    from spectral_rod import critical_load

    twist, nu = _figure1_sample()
    res = critical_load(twist, nu, full_output=True)
    assert set(res.engine.tolist()) == {"kernel"}
    one = critical_load(float(twist[3]), float(nu[3]), full_output=True)  # the scalar path
    assert one.engine == "kernel"
    # above the kernel's range (Schur block > KERNEL_MAX_SCHUR) numpy iterates: the record moves
    forced = critical_load(twist[:20], nu[:20], n=200, full_output=True)
    assert set(forced.engine.tolist()) == {"numpy"}


def test_full_output_names_numpy_without_the_kernel(monkeypatch):
    from spectral_rod import critical_load

    monkeypatch.setattr(modal_kernel, "_library", lambda: None)
    monkeypatch.setattr(modal_kernel, "_warned", True)  # the warning has its own test
    twist, nu = _figure1_sample()
    assert set(critical_load(twist, nu, full_output=True).engine.tolist()) == {"numpy"}
    assert critical_load(3.0, 1.5, full_output=True).engine == "numpy"


@needs_kernel
def test_points_the_kernel_rejects_are_recorded_as_numpy(monkeypatch):
    from spectral_rod.rod.collocation.driver import collocation_critical_load

    twist, nu = _figure1_sample()
    real_points, real_lowest = modal_kernel.modal_points, modal_kernel.modal_lowest

    def reject_some(*args, **kwargs):  # modal_points: both families
        lam, tail, status = real_points(*args, **kwargs)
        status[::3] = modal_kernel.REJECTED
        return lam, tail, status

    def reject_all(*args, **kwargs):  # modal_lowest, where the rejected points go next
        res = real_lowest(*args, **kwargs)
        res.status[:] = modal_kernel.REJECTED
        return res

    clean = collocation_critical_load(twist, nu)
    monkeypatch.setattr(modal_kernel, "modal_points", reject_some)
    monkeypatch.setattr(modal_kernel, "modal_lowest", reject_all)
    res = collocation_critical_load(twist, nu)
    assert (res.engine == "numpy").any() and (res.engine == "kernel").any()
    assert np.max(np.abs(res.p_star / clean.p_star - 1)) <= 1e-14


def test_other_routes_name_their_method():
    from spectral_rod import critical_load

    res = critical_load(np.array([300.0, 3.0]), 1.5, full_output=True)
    assert res.engine.tolist()[0] == res.method.tolist()[0] == "characteristic"


# --- one algorithm: the kernel's modal_points against the numpy reference --------------------

@needs_kernel
@pytest.mark.parametrize("tol", [1e-12, 1e-4])
@pytest.mark.parametrize("size", [9, 75])
@pytest.mark.parametrize("n", [16, 22, 40, 56])
def test_kernel_points_match_the_numpy_reference(n, size, tol):
    # the kernel's convergence test, pencil quotient (double-double above LONG_TWIST) and tail,
    # on groups of 32 lanes (a last group of a few points one lane each, or padded: 75 points
    # are 2 groups and 11 points, one lane each up to n = 30, a padded group above; 9 points
    # one lane each), against the numpy reference's iteration, pencil_rayleigh_quotient and
    # mode_tails on the same points: eigenvalues within the round-off part of the error model
    # (at tol 1e-4, the modal quotient of both: within the iteration's rtol), error estimates
    # (what the tail decides) within 1e-3 of each other
    from spectral_rod.rod.collocation.eigensolver import _accepted, _solve_lanes
    from spectral_rod.rod.collocation.resolution import error_estimate
    from spectral_rod.rod.collocation.tuning import iteration_rtol

    rng = np.random.default_rng(n)
    tw, nv = rng.uniform(0.0, max(1.0, 1.8 * (n - 16)), size), rng.uniform(1.1, 20.0, size)
    rtol = iteration_rtol(tol)
    lam, tail, status = _solve_lanes(n, tw, nv, rtol)
    ok = _accepted(status[:, 0], status[:, 1])
    library = modal_kernel._library
    modal_kernel._library = lambda: None
    try:
        ref = [_numpy_reference(n, family, tw, nv, rtol)
               for family in ("symmetric", "antisymmetric")]
    finally:
        modal_kernel._library = library
    assert ok.all()
    round_off = np.maximum(np.finfo(float).eps * (32 + 0.3 * tw**2), 0.0 if tol < 1e-8 else rtol)
    assert np.max(np.abs(lam[:, 0] / ref[0][0] - 1) / round_off) <= 1.0
    est, ref_est = error_estimate(tail[:, 0], tw, n), error_estimate(ref[0][1], tw, n)
    assert np.max(np.abs(est / ref_est - 1)) <= 1e-3
    both = np.isfinite(tail[:, 1]) & np.isfinite(ref[1][1])  # antisymmetric resolved by both
    assert np.max(np.abs(lam[both, 1] / ref[1][0][both] - 1) / round_off[both], initial=0) <= 1.0


def _numpy_reference(n, family, tw, nv, rtol):
    from spectral_rod.rod.collocation.eigensolver import solve_family

    return solve_family(n, family, tw, nv, rtol=rtol)[:2]


# --- durable text: contracts and provenance, no history -------------------------------------

_HISTORY = r"\b20\d\d-\d\d-\d\d\b|\bnot kept\b|\bad hoc\b|\ba later\b|\bsession\b|\bissue \d+|" \
           r"\buntil this\b|\bwas measured\b"


def test_the_solver_stack_carries_no_history():
    # dates and narrating words belong in CHANGELOG.md and tests/bench/HISTORY.md
    import re
    from pathlib import Path

    import spectral_rod

    root = Path(spectral_rod.__file__).parent
    files = [*(path for pattern in ("*.py", "*.c", "*.h")
               for path in sorted((root / "rod" / "collocation").glob(pattern))),
             *(root / name for name in ("rod/critical.py", "rod/results.py",
                                        "rod/families.py", "errors.py"))]
    found = [f"{path.name}:{i}: {line.strip()}" for path in files
             for i, line in enumerate(path.read_text().splitlines(), 1)
             if re.search(_HISTORY, line, re.IGNORECASE)]
    assert len(files) >= 14 and found == []
    assert re.search(_HISTORY, "measured 2026-12-05, not kept", re.IGNORECASE)  # it can fail
