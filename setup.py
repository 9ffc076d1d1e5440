"""Build of the batched engine's C kernel (all metadata is in pyproject.toml).

The kernel is optional: where it does not compile (no C compiler), the package installs without
it and the engine runs its numpy code (spectral_rod/straight_rod/modal_kernel.py).
"""

import sys

from setuptools import Extension, setup

setup(ext_modules=[Extension(
    "spectral_rod.straight_rod._modal_kernel", ["spectral_rod/straight_rod/_modal_kernel.c"],
    extra_compile_args=[] if sys.platform == "win32" else ["-O3"], optional=True)])
