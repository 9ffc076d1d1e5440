"""The benchmark run fails below a pattern's ratio floor and passes above it.

The ratio check of ``tests/bench/test_benchmarks.py`` (``_yardstick`` then ``_new``) is run
with a stand-in for pytest-benchmark's fixture whose timings are set by the test, so the check
itself is exercised in the default run without timing anything.
"""

from __future__ import annotations

import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

sys.path.insert(0, str(Path(__file__).parent / "bench"))
import test_benchmarks as tb


class FakeBenchmark:
    """pytest-benchmark's fixture as far as the ratio check uses it, with a given min time."""

    def __init__(self, seconds: float):
        self.seconds, self.extra_info = seconds, {}

    def pedantic(self, fn, rounds, iterations, warmup_rounds):
        fn()
        self.stats = SimpleNamespace(stats=SimpleNamespace(min=self.seconds,
                                                           median=self.seconds))


@pytest.mark.parametrize(("new_seconds", "passes"), [(0.01, True), (1.0, False)])
def test_the_ratio_floor_decides(new_seconds, passes):
    pattern = "figure1 batch"
    registry: dict = {}
    tb._yardstick(FakeBenchmark(1.0), registry, pattern, lambda: None, points=10)
    bench = FakeBenchmark(new_seconds)
    call = lambda: tb._new(bench, registry, pattern, lambda: None, 10, {}, "baseline")  # noqa: E731
    if passes:  # ratio 100 >= floor
        call()
        assert bench.extra_info["ratio_min"] == pytest.approx(100.0)
        assert bench.extra_info["ratio_interleaved"] > 0  # timed for real, of no-ops
    else:  # ratio 1 < floor
        with pytest.raises(AssertionError, match="below floor"):
            call()
    assert registry[pattern]["ratio"] == pytest.approx(1.0 / new_seconds)
    assert tb.FLOORS[pattern] > 1.0
