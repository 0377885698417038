"""KZL Sec. 3.6 and Table 1: the simulation scenario, as typed inputs, and the cached Monte Carlo.

Table 1's IMU block is scrambled by the OCR (numbers and labels on different lines). The
assignment used here keeps both in their printed order and moves the gyro numbers up one
line (the minimal repair):

============  ==================  ======================
sensor        parameter           value
============  ==================  ======================
gyro          bias stability      360 deg/h
gyro          scale factor        10000 ppm
gyro          noise (ARW)         180 deg/h/sqrt(Hz)
accel         bias stability      2400 micro-g
accel         scale factor        10000 ppm
accel         noise (VRW)         1000 micro-g/sqrt(Hz)
============  ==================  ======================

The swapped gyro assignment (bias 180, ARW 360) is kept as :data:`KZL_IMU_SWAPPED` so the
book can show that it contradicts the stand-alone numbers of Sec. 3.6.

Assumptions the paper does not state (each is a :class:`Scenario` field): satellite
visibility schedule (:data:`VISIBILITY_SCHEDULE`, the paper's is only in its figures),
measurement noises, initialisation averaging time, crab angle, clock model, bias
random-walk tuning.
"""

from __future__ import annotations

import hashlib
import inspect
import os
import sys
import tempfile
from dataclasses import fields
from functools import cache
from pathlib import Path

import numpy as np

from navcore.estimation.ekf_ins_gnss import GnssNoise, MonteCarloResult, Scenario, run_monte_carlo
from navcore.frames import dcm_ecef_to_ned, ecef_to_ned, geodetic_to_ecef
from navcore.gnss.constellation import elevation_azimuth, nominal_gps_constellation
from navcore.inertial.imu import ImuSpec, imu_spec_from_published
from navcore.units import DEG

__all__ = [
    "GNSS_NOISE",
    "KZL_IMU",
    "KZL_IMU_SWAPPED",
    "N_RUNS",
    "SEED",
    "TABLE1",
    "VISIBILITY_SCHEDULE",
    "monte_carlo",
    "satellite_priority",
    "table1_scenario",
]

#: Table 1 as printed (trajectory and GPS blocks), with SI conversions where needed.
TABLE1 = {
    "velocity_enu_mps": (110.0, 0.0, 0.0),
    "lat_deg": 51.0,
    "lon_deg": 8.0,
    "height_m": 3000.0,
    "attitude_deg": (0.0, 0.0, 90.0),  # roll, pitch, heading
    "duration_s": 180.0,
    "gps_rate_hz": 1.0,
    "imu_rate_hz": 100.0,
    "elevation_mask_deg": 5.0,
    "baseline_m": 2.0,
    "n_antennas": 3,
    "satellites_in_view": (2, 8),
}

KZL_IMU: ImuSpec = imu_spec_from_published(
    "KZL Table 1 consumer-grade MEMS",
    accel_bias_micro_g=2400.0,
    accel_scale_factor_ppm=10000.0,
    accel_misalignment_arcsec=0.0,
    accel_random_walk_micro_g_per_sqrt_hz=1000.0,
    gyro_bias_deg_per_h=360.0,
    gyro_scale_factor_ppm=10000.0,
    gyro_misalignment_arcsec=0.0,
    gyro_random_walk_deg_per_h_per_sqrt_hz=180.0,
    source="KZL Table 1 (OCR-scrambled; gyro values moved up one line)",
)

KZL_IMU_SWAPPED: ImuSpec = imu_spec_from_published(
    "KZL Table 1, alternative reading",
    accel_bias_micro_g=2400.0,
    accel_scale_factor_ppm=10000.0,
    accel_misalignment_arcsec=0.0,
    accel_random_walk_micro_g_per_sqrt_hz=1000.0,
    gyro_bias_deg_per_h=180.0,
    gyro_scale_factor_ppm=10000.0,
    gyro_misalignment_arcsec=0.0,
    gyro_random_walk_deg_per_h_per_sqrt_hz=360.0,
    source="KZL Table 1 with gyro bias and ARW swapped",
)

#: Assumed visibility schedule (start time s, satellites tracked): 8 -> 4 -> 3 -> 2 -> 5.
VISIBILITY_SCHEDULE = ((0.0, 8), (60.0, 4), (90.0, 3), (120.0, 2), (150.0, 5))

#: Assumed noises: 3 m code, 5 cm/s delta range, 3 mm carrier phase, 0.17 deg per Euler angle.
GNSS_NOISE = GnssNoise(pseudorange=3.0, delta_range=0.05, phase=0.003, attitude=0.003)

#: Assumed 1-sigma crab angle (heading minus GPS track), which Eq. 4 cannot observe.
HEADING_SIGMA_RAD = 0.5 * DEG
#: Assumed averaging time of the initialisation (levelling and bias calibration), s.
INIT_TIME_S = 300.0

N_RUNS = 30
SEED = 20061029


def satellite_priority(
    positions_ecef: np.ndarray, lat: float, lon: float, h: float, mask_deg: float
) -> np.ndarray:
    """Indices of the visible satellites in tracking priority: highest elevation first (the DD
    master), then greedily the one that most increases ``log det(G^T G + 1e-3 I)`` so that
    every prefix of the list has a good geometry."""
    r_user = geodetic_to_ecef(lat, lon, h)
    el, _ = elevation_azimuth(r_user, positions_ecef, lat, lon)
    vis = np.flatnonzero(el >= mask_deg * DEG)
    d = positions_ecef[vis] - r_user
    u = d / np.linalg.norm(d, axis=1, keepdims=True)
    G = np.hstack([-u, np.ones((len(vis), 1))])
    order = [int(np.argmax(el[vis]))]
    while len(order) < len(vis):
        best, best_val = None, -np.inf
        for c in range(len(vis)):
            if c in order:
                continue
            Gs = G[[*order, c]]
            val = np.linalg.slogdet(Gs.T @ Gs + 1e-3 * np.eye(4))[1]
            if val > best_val:
                best, best_val = c, val
        order.append(int(best))
    return vis[order]


@cache
def table1_scenario(imu: ImuSpec = KZL_IMU) -> Scenario:
    """The Table 1 flight with the nominal 24-satellite constellation and the assumed schedule."""
    lat, lon, h = TABLE1["lat_deg"] * DEG, TABLE1["lon_deg"] * DEG, TABLE1["height_m"]
    ve, vn, vu = TABLE1["velocity_enu_mps"]
    K = round(TABLE1["duration_s"] * TABLE1["gps_rate_hz"])
    t = np.arange(K + 1) / TABLE1["gps_rate_hz"]
    const = nominal_gps_constellation()
    prio = satellite_priority(const.positions_ecef(0.0), lat, lon, h, TABLE1["elevation_mask_deg"])
    pos_e = const.positions_ecef(t)[:, prio]
    vel_e = const.velocities_ecef(t)[:, prio]
    sat_pos = ecef_to_ned(pos_e, lat, lon, h)
    sat_vel = vel_e @ dcm_ecef_to_ned(lat, lon).T
    n_vis = np.zeros(K + 1, dtype=np.int64)
    for start, n in VISIBILITY_SCHEDULE:
        n_vis[t >= start] = n
    return Scenario(
        velocity_ned=np.array([vn, ve, -vu]),
        attitude=np.array(TABLE1["attitude_deg"]) * DEG,
        duration=TABLE1["duration_s"],
        imu_rate=TABLE1["imu_rate_hz"],
        gps_rate=TABLE1["gps_rate_hz"],
        imu=imu,
        sat_pos_ned=sat_pos,
        sat_vel_ned=sat_vel,
        n_visible=n_vis,
        gnss=GNSS_NOISE,
        init_time=INIT_TIME_S,
        heading_sigma=HEADING_SIGMA_RAD,
    )


def _source_key(*parts: object) -> str:
    """Hash of the sources of every module the Monte Carlo depends on, and of ``parts``."""
    import navcore.estimation.ekf_ins_gnss as m1
    import navcore.frames as m2
    import navcore.gnss.carrier_phase as m3
    import navcore.gnss.constellation as m4
    import navcore.inertial.alignment as m5
    import navcore.inertial.error_model17 as m6
    import navcore.inertial.imu as m7
    import navcore.inertial.strapdown as m8

    h = hashlib.sha256()
    for mod in (m1, m2, m3, m4, m5, m6, m7, m8, sys.modules[__name__]):
        h.update(inspect.getsource(mod).encode())
    h.update(repr((parts, N_RUNS, SEED, np.__version__)).encode())
    return h.hexdigest()[:24]


@cache
def monte_carlo(mode: str, initialise: bool = True, imu_name: str = "table1") -> MonteCarloResult:
    """Cached seeded Monte Carlo (``N_RUNS`` runs) of one configuration of the Table 1 scenario.

    Results are also kept on disk (in the system temporary directory, under a key hashed from
    the sources of every module involved), so that the chapter's notebooks, the ledger page
    and the tests share one computation per code version. Set ``NAVCORE_NO_DISK_CACHE=1`` to
    recompute.
    """
    imu = {"table1": KZL_IMU, "swapped": KZL_IMU_SWAPPED}[imu_name]
    path = (
        Path(tempfile.gettempdir())
        / "navcore-kzl-mc"
        / f"{mode}-{initialise}-{imu_name}-{_source_key(mode, initialise, imu_name)}.npz"
    )
    use_disk = not os.environ.get("NAVCORE_NO_DISK_CACHE")
    if use_disk and path.exists():
        with np.load(path) as data:
            return MonteCarloResult(**{f.name: data[f.name] for f in fields(MonteCarloResult)})
    result = run_monte_carlo(table1_scenario(imu), mode, N_RUNS, SEED, initialise=initialise)
    if use_disk:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.npz")
        np.savez(tmp, **{f.name: getattr(result, f.name) for f in fields(MonteCarloResult)})
        os.replace(tmp, path)
    return result
