"""WF worked example: emitter location with a vibrating wing-tip aperture, end to end.

The paper stops at the local velocity accuracy (Sec. IV.D). This example closes the loop back
to Sec. II: an aircraft flies the book's 2 deg/s turn past a ground emitter while the wing-tip
aperture vibrates in its first mode. The emitter is located (WF Eqs. (2)-(4)) three times:

* with the true aperture velocity (only frequency noise: the reference),
* with the navigation-only velocity (WF Eq. (10): rigid-body velocity plus navigation error,
  blind to the vibration),
* with the federated local velocity (WF Eqs. (12)-(14) accelerometer filter at 50 Hz, fused
  with the navigation estimate by WF Eqs. (18)-(19)).

No claims: the paper publishes no number for this; the results appear as a table and a figure.
"""

from __future__ import annotations

import numpy as np

from navcore.claims import input_cache
from navcore.estimation.federated import (
    accelerometer_steady_state_isotropic,
    federated_fusion,
)
from navcore.location.emitter import doppler_frequency, emitter_gauss_newton
from navcore.papers.wf_inputs import IN, sigma_a_example
from navcore.papers.wf_location_error import ALTITUDE, EMITTER, F0, SIGMA_F, SPEED

#: measurement decimation: one frequency measurement every DECIM accelerometer steps
DECIM = 30
SEED = 2026


#: number of sinusoids making up the narrowband first-mode vibration
N_TONES = 8


def _vibration(t: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Narrowband first-mode vibration: vertical displacement (m) and velocity (m/s) at times t.

    A sum of N_TONES sinusoids with frequencies uniform within +-0.5 Hz of the assumed first-mode
    frequency (``IN.vib_hz``) and random phases, scaled so that the displacement RMS is that of a
    sinusoid of the assumed amplitude (``IN.vib_amplitude_m``).
    """
    f = IN.vib_hz + rng.uniform(-0.5, 0.5, N_TONES)
    ph = rng.uniform(0, 2 * np.pi, N_TONES)
    a = IN.vib_amplitude_m / np.sqrt(N_TONES)
    arg = 2 * np.pi * np.outer(t, f) + ph
    return (a * np.sin(arg)).sum(axis=1), (a * 2 * np.pi * f * np.cos(arg)).sum(axis=1)


def _rigid(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    w = np.deg2rad(IN.turn_rate_deg_s)
    radius = SPEED / w
    pos = np.column_stack([radius * np.sin(w * t), radius * (1 - np.cos(w * t)), np.full(t.size, ALTITUDE)])
    vel = np.column_stack([SPEED * np.cos(w * t), SPEED * np.sin(w * t), np.zeros(t.size)])
    return pos, vel


@input_cache
def run(trials: int = 20, sigma_a: float | None = None) -> dict:
    """Monte Carlo of the worked example (seeded, all trials vectorised).

    The accelerometer output is modelled as the average acceleration over each 20 ms interval
    (a delta-velocity output) plus white noise of standard deviation ``sigma_a``, so the Euler
    integration of WF Eq. (12) adds no discretisation error; the local velocity measurement
    ``y_L`` is the aperture velocity plus white noise ``sigma_L = 200 sigma_a``.

    Returns
    -------
    dict
        ``errors[case]``: (trials, 3) emitter position errors (m) for cases ``"true"``,
        ``"navigation"``, ``"federated"``; ``vel_err[case]``: (trials, M, 3) aperture-velocity
        errors at the measurement times (m/s); ``t``: measurement times (s).
    """
    sigma_a = sigma_a_example() if sigma_a is None else sigma_a
    TS, SIGMA_N = IN.ts, IN.sigma_n
    rng = np.random.default_rng(SEED)
    n_steps = round(IN.aperture_duration_s / TS)
    t_all = np.arange(n_steps + 1) * TS
    idx = np.arange(0, n_steps + 1, DECIM)
    t = t_all[idx]
    sigma_l = IN.sigma_l_per_sigma_a * sigma_a
    ss = accelerometer_steady_state_isotropic(sigma_a, TS, sigma_l)
    pos_rigid, vel_rigid = _rigid(t_all)
    vib = [_vibration(t_all, rng) for _ in range(trials)]
    vel_ap = np.repeat(vel_rigid[None], trials, axis=0)
    pos_ap = np.repeat(pos_rigid[None], trials, axis=0)
    vel_ap[:, :, 2] += np.array([vv for _, vv in vib])
    pos_ap[:, :, 2] += np.array([pp for pp, _ in vib])
    vib_rms = float(np.sqrt(np.mean(vel_ap[:, :, 2] ** 2)))
    # designer's covariances: navigation mapped to the aperture, with the vibration as Q_T (vertical)
    P_dn = np.diag([SIGMA_N**2, SIGMA_N**2, SIGMA_N**2 + vib_rms**2])
    P_dl = ss.posterior * np.eye(3)
    # accelerometer filter, WF Eqs. (12)-(14) with the corrected innovation, steady-state gain
    y_a = np.diff(vel_ap, axis=1) / TS + rng.normal(0, sigma_a, (trials, n_steps, 3))
    y_l = vel_ap + rng.normal(0, sigma_l, vel_ap.shape)
    x = vel_ap[:, 0] + rng.normal(0, np.sqrt(ss.posterior), (trials, 3))
    x_dl = np.empty_like(vel_ap)
    x_dl[:, 0] = x
    K = ss.gain
    for k in range(1, n_steps + 1):
        x = x + y_a[:, k - 1] * TS  # time update
        x = x + K * (y_l[:, k] - x)  # measurement update
        x_dl[:, k] = x
    errors = {c: np.empty((trials, 3)) for c in ("true", "navigation", "federated")}
    vel_err = {c: np.empty((trials, idx.size, 3)) for c in ("navigation", "federated")}
    start = np.r_[EMITTER, F0]
    # WF Eqs. (18)-(19): the weights P_D P_i^-1 are constant here, so apply them to all samples
    _, P_d = federated_fusion([np.zeros(3), np.zeros(3)], [P_dn, P_dl])
    A_n, A_l = P_d @ np.linalg.inv(P_dn), P_d @ np.linalg.inv(P_dl)
    for i in range(trials):
        v_true = vel_ap[i, idx]
        v_nav = vel_rigid[idx] + rng.normal(0, SIGMA_N, (idx.size, 3))
        v_fed = v_nav @ A_n.T + x_dl[i, idx] @ A_l.T
        p = pos_ap[i, idx]
        m = doppler_frequency(F0, EMITTER, p, v_true) + rng.normal(0, SIGMA_F, idx.size)
        for case, v in (("true", v_true), ("navigation", v_nav), ("federated", v_fed)):
            errors[case][i] = emitter_gauss_newton(m, p, v, start).estimate[:3] - EMITTER
        vel_err["navigation"][i] = v_nav - v_true
        vel_err["federated"][i] = v_fed - v_true
    return {
        "errors": errors,
        "vel_err": vel_err,
        "t": t,
        "sigma_dl": float(np.sqrt(ss.posterior)),
        "vib_rms": vib_rms,
    }


def summary_rows() -> list[tuple[str, float, float, float]]:
    """(case, velocity RMS per axis m/s, horizontal RMS m, vertical RMS m) for the table."""
    r = run()
    rows = []
    for case in ("true", "navigation", "federated"):
        e = r["errors"][case]
        v = 0.0 if case == "true" else float(np.sqrt(np.mean(r["vel_err"][case] ** 2)))
        rows.append(
            (
                case,
                v,
                float(np.sqrt(np.mean(np.sum(e[:, :2] ** 2, axis=1)))),
                float(np.sqrt(np.mean(e[:, 2] ** 2))),
            )
        )
    return rows
