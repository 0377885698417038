"""Shared pytest configuration: numpy floating-point problems are errors, not warnings."""

from __future__ import annotations

import os

import matplotlib
import numpy as np
import pytest

# Every test computes for itself: the ledger's on-disk evaluation cache is off.
os.environ["NAVCORE_CACHE"] = "off"
os.environ["NAVCORE_NO_DISK_CACHE"] = "1"  # the KZL Monte Carlo's own disk cache, likewise

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _numpy_errors_raise():
    """Make numpy raise on invalid operations, division by zero and overflow in every test."""
    old = np.seterr(invalid="raise", divide="raise", over="raise", under="ignore")
    yield
    np.seterr(**old)
