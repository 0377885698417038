"""Shared pytest configuration: numpy floating-point problems are errors, not warnings."""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from hypothesis import settings

# Property tests: random exploration on a developer's machine, a fixed example sequence in CI
# (CI runs .ci/run with CI=true), so that a CI run is reproducible and cannot fail on
# an example no earlier run saw. HYPOTHESIS_PROFILE=ci selects it by hand. No deadline in
# CI: the shared runners are too loaded for per-example timing to mean anything.
settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
settings.register_profile("dev")
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))

# Every test session computes for itself: the ledger's on-disk evaluation cache starts empty
# in a folder of its own, which the session's processes (pytest-xdist workers, the kernels of
# the exercise pages and the strict-build tests) share, so that a claim is evaluated once per
# session, not once per process. NAVCORE_TEST_CACHE=off turns the cache off altogether.
# NAVCORE_TEST_CACHE_FROM=<folder> starts the session's folder as a copy of the evaluations
# stored in <folder> (CI: the ledger gate's, made from the same checkout and lock just before);
# the session's own evaluations never go back there. Claims are evaluated under the tests'
# numerical rules (NAVCORE_LEDGER_STRICT: floating-point errors raise, warnings are errors),
# and only evaluations stored under those rules are read, whoever stored them.
os.environ["NAVCORE_LEDGER_STRICT"] = "1"
if os.environ.get("NAVCORE_TEST_CACHE", "") == "off":
    os.environ["NAVCORE_CACHE"] = "off"
elif "NAVCORE_TEST_CACHE" not in os.environ:  # the controller: the workers inherit the folder
    os.environ["NAVCORE_TEST_CACHE"] = tempfile.mkdtemp(prefix="navcore-test-ledger-")
    os.environ["NAVCORE_CACHE"] = os.environ["NAVCORE_TEST_CACHE"]
    _SESSION_CACHE_OWNER = True
    if os.environ.get("NAVCORE_TEST_CACHE_FROM"):
        stored = Path(os.environ["NAVCORE_TEST_CACHE_FROM"], "claims")
        if stored.is_dir():
            shutil.copytree(stored, Path(os.environ["NAVCORE_TEST_CACHE"], "claims"))
os.environ["NAVCORE_NO_DISK_CACHE"] = "1"  # the KZL Monte Carlo's own disk cache is off


def pytest_unconfigure(config):
    """The process that made the session's ledger cache removes it."""
    if globals().get("_SESSION_CACHE_OWNER") and not hasattr(config, "workerinput"):
        shutil.rmtree(os.environ.get("NAVCORE_TEST_CACHE", ""), ignore_errors=True)


matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _numpy_errors_raise():
    """Make numpy raise on invalid operations, division by zero and overflow in every test."""
    old = np.seterr(invalid="raise", divide="raise", over="raise", under="ignore")
    yield
    np.seterr(**old)
