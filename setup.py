"""Build of the engine's C kernel (all metadata is in pyproject.toml).

The kernel is optional: where it does not compile (no C compiler), the package installs without
it and the engine runs its numpy reference (spectral_rod/rod/collocation/modal_kernel.py warns once
with a PerformanceWarning at the first solve). Its contract is _modal_kernel.h.
"""

import sys

from setuptools import Extension, setup

# -O3, and -fno-wrapv against CPython's -fwrapv (the kernel's index arithmetic never overflows;
# defined wrapping keeps the compiler from simplifying its loops: one-lane calls took ~10 % longer
# at n = 30..50 with it, tests/bench/kernel_range.py)
FLAGS = [] if sys.platform == "win32" else ["-O3", "-fno-wrapv"]

setup(ext_modules=[Extension(
    "spectral_rod.rod.collocation._modal_kernel", ["spectral_rod/rod/collocation/_modal_kernel.c"],
    depends=["spectral_rod/rod/collocation/_modal_kernel.h"],
    include_dirs=["spectral_rod/rod/collocation"],
    extra_compile_args=FLAGS, optional=True)])
