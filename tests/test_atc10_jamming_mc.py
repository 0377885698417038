"""The seeded first-stage Monte Carlo lies above the Sec. 2 bounds."""

from __future__ import annotations

import numpy as np

from navcore.papers import atc10_jamming_mc as mc


def test_simulated_rates_exceed_bounds() -> None:
    """Oracle: seeded Monte Carlo of matched-filter samples and the list logic (the bounds must
    lie below the simulated rates, within three binomial standard errors)."""
    for r in mc.simulate():
        sigma = mc.binomial_sigma(r.false_alarm, r.trials)
        assert np.all(r.false_alarm_bound <= r.false_alarm + 3 * sigma)
        sigma_d = mc.binomial_sigma(r.detection, r.trials)
        assert np.all(r.detection_bound <= r.detection + 3 * sigma_d)
        assert np.all(np.isfinite(r.false_alarm_bound)) and np.all(r.false_alarm_bound > 0)
