"""``python -m spectral_rod``: which engine solves Eq. ``inst1`` on this install, with the BLAS,
its threads and the dependency versions (:mod:`spectral_rod._engine_report`)."""

import sys

from spectral_rod._engine_report import main

if __name__ == "__main__":
    sys.exit(main())
