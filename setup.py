"""Build of the engine's C kernel (all metadata is in pyproject.toml).

The kernel is optional: where it does not compile (no C compiler), the package installs without
it and the engine runs its numpy reference (spectral_rod/rod/collocation/modal_kernel.py warns once
with a PerformanceWarning at the first solve). Its contract is _modal_kernel.h.
"""

import sys

from setuptools import Extension, setup

setup(ext_modules=[Extension(
    "spectral_rod.rod.collocation._modal_kernel", ["spectral_rod/rod/collocation/_modal_kernel.c"],
    depends=["spectral_rod/rod/collocation/_modal_kernel.h"],
    include_dirs=["spectral_rod/rod/collocation"],
    extra_compile_args=[] if sys.platform == "win32" else ["-O3"], optional=True)])
