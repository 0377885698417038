"""SP Section 2.6.2: the jammer flyby, modelled from stated assumptions.

An aircraft cruises past a ground jammer; each satellite's effective C/N0 follows from the
free-space jammer power and the satellite's elevation-dependent antenna gain
(:mod:`navcore.gnss.jammer_geometry`). The Sec. 2.5 thresholds decide when each code and
carrier loop loses lock and reacquires; the resulting lock tables drive the covariance
engine of the other Sec. 2.6 missions (:mod:`navcore.papers.sp_missions_scenarios`).

The paper publishes the thresholds, the loop bandwidths and the outcome (about 20 min of
loosely coupled blackout), not the jammer, the antenna, the track or the satellites. Every
such input is in :class:`FlybyAssumptions`. One of them, the jammer's effective radiated
power, is *calibrated*: it is solved so that the loosely coupled blackout lasts the paper's
20 min. That claim is therefore an input here, not a reproduction.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, fields

import numpy as np

from navcore.estimation.covariance_analysis import CovarianceAnalysis, satellite_geometry
from navcore.gnss.acquisition import search_cells, search_time
from navcore.gnss.constellation import nominal_gps_constellation
from navcore.gnss.jammer_geometry import (
    LockThresholds,
    carrier_loss_threshold_dbhz,
    effective_cn0_with_jammer_dbhz,
    elevation_gain_dbi,
    hysteresis_lock,
    outage_intervals,
    received_jammer_power_dbw,
    slant_range_m,
)
from navcore.gnss.tracking import third_order_noise_bandwidth_hz
from navcore.inertial.trajectories import Segment, Trajectory, fly
from navcore.ledger import EXACT, Claim, input_cache, printed, prose
from navcore.ledger.inputs import InputSet
from navcore.papers import sp_acquisition as spa
from navcore.papers import sp_missions_scenarios as sc
from navcore.papers import sp_residual_acceleration as spr
from navcore.papers.sp_tables import GRADE_LABELS_NMI_PER_H
from navcore.units import DEG, GPS_L1_WAVELENGTH_M, GPS_P_CHIP_RATE_HZ, MINUTE

__all__ = [
    "ASSUMED_FLYBY",
    "CLAIMS",
    "ERRATA",
    "IN",
    "FlybyAssumptions",
    "blackouts_min",
    "calibrated_erp_dbw",
    "carrier_noise_bandwidth_hz",
    "channels",
    "effective_cn0",
    "errors_before_reacquisition",
    "flyby_runs",
    "flyby_trajectory",
    "jammer_position_ned",
    "jammer_range_m",
    "lock_thresholds",
    "pattern_sensitivity",
    "reacquisition_search",
]

PAGE = "sp/22-jammer-flyby"

IN = InputSet("SP", "flyby")

# --- published (Sec. 2.5 and 2.6.2) ------------------------------------------------------
_S25 = "Sec. 2.5"
IN.published("carrier_loss_dbhz", 19.0, locator=_S25 + " ('dropped below 19 dB')", unit="dB-Hz")
IN.published("code_loss_dbhz", 18.0, locator=_S25 + " ('code phase ... below 18 dB')", unit="dB-Hz")
IN.published("code_reacquisition_dbhz", 21.0, locator=_S25 + " ('at least 21 dB for the code')", unit="dB-Hz")
IN.published("carrier_reacquisition_dbhz", 22.0, locator=_S25 + " ('22 dB for the carrier')", unit="dB-Hz")
IN.published(
    "max_phase_error_deg", 90.0, locator=_S25 + " ('carrier phase error exceeded 90 deg')", unit="deg"
)
IN.published(
    "lc_carrier_bandwidth_hz",
    5.83,
    locator="Sec. 2.5 ('third-order loop with bandwidth of 5.83 Hz')",
    unit="Hz",
)
IN.published(
    "range_rate_cell_mps", 10.0, locator="Sec. 2.6.2 ('10 m/s (one Doppler shift interval)')", unit="m/s"
)

# printed results: the claims' published values (typed once, here)
LC_BLACKOUT_MIN = 20.0  # "to cause an approximate 20min outage"
BLACKOUT_REDUCTION_MIN = 2.0  # "reduced by only about 2 min from the 20-min blackout"
FIG27_M = {10.0: 3300.0, 1.0: 260.0}  # "(3300:260)"

IN.fitted(
    "erp_fit_blackout_min",
    LC_BLACKOUT_MIN,
    fitted_to=("SP-fig2.6-lc-blackout",),
    unit="min",
    quantity="loosely coupled blackout the jammer ERP is solved for",
    reason="the paper placed its jammer 'to cause an approximate 20min outage' and publishes no "
    "jammer: the book solves the jammer's effective radiated power (bisection) so that the "
    "loosely coupled blackout lasts this long, for each antenna pattern",
)
IN.assumed(
    "antenna_horizon_dbic",
    -5.0,
    low=-10.0,
    high=-2.0,
    unit="dBic",
    quantity="aircraft antenna gain towards satellites at the horizon (+3 dBic at zenith)",
    reason="not published; sets the spread of C/N0 between high and low satellites and so how "
    "much longer a receiver that needs four codes is blacked out than one that uses any code. "
    "L1 aircraft patch antennas fall 5-13 dB from zenith to horizon (-2 to -10 dBic)",
)


@dataclass(frozen=True)
class FlybyAssumptions:
    """Inputs of the flyby the paper does not publish, with the values used in this book.

    The jammer's effective radiated power is not listed: it is calibrated
    (:func:`calibrated_erp_dbw`); the horizon gain of the antenna is an assumed input with a
    range (:data:`IN`).
    """

    signal_dbw: float = -163.0  # P(Y) received power at 0 dBic
    n0_dbw_hz: float = -204.0  # thermal noise density
    antenna_zenith_dbic: float = 3.0  # satellite-direction gain at 90 deg elevation
    antenna_to_jammer_dbic: float = -10.0  # gain towards the ground jammer (below the horizon)
    spectral_separation_q: float = 2.0  # wideband jammer on the P(Y) code
    chip_rate_hz: float = GPS_P_CHIP_RATE_HZ
    heading_deg: float = 90.0  # straight leg flown east (constant latitude)
    jammer_cross_track_m: float = 10_000.0  # ground offset of the jammer, right of the track
    jammer_height_m: float = 0.0
    closest_approach_min: float = 40.0  # jammer abeam at the mission's 40th minute
    mission_min: float = 56.0
    calibration_turns_min: tuple[float, float] = (4.0, 14.0)  # 90-deg turns, right then left
    turn_rate_deg_s: float = 1.5
    jitter_k_sigma: float = 3.0  # carrier lost when 3 sigma thermal jitter exceeds 90 deg
    coherent_s: float = 0.02
    mask_deg: float = 10.0

    def table(self) -> list[tuple[str, object]]:
        """``[(field, value), ...]`` for printing."""
        return [(f.name, getattr(self, f.name)) for f in fields(self)]


ASSUMED_FLYBY = FlybyAssumptions()


@input_cache
def flyby_trajectory() -> Trajectory:
    """Cruise at the missions' altitude and speed: two 90-degree calibration turns (right,
    then left, back to the initial heading), then a straight leg past the jammer."""
    a, m = ASSUMED_FLYBY, sc.ASSUMED
    turn_s = 90.0 / a.turn_rate_deg_s
    t1, t2 = (x * MINUTE for x in a.calibration_turns_min)
    segs = [
        Segment(t1),
        Segment(turn_s, turn_rate=a.turn_rate_deg_s * DEG),
        Segment(t2 - t1 - turn_s),
        Segment(turn_s, turn_rate=-a.turn_rate_deg_s * DEG),
        Segment(a.mission_min * MINUTE - t2 - turn_s),
    ]
    return fly(
        segs,
        dt=m.step_s,
        lat0=m.latitude_deg * DEG,
        lon0=m.longitude_deg * DEG,
        h0=m.cruise_altitude_m,
        speed0=m.cruise_speed_mps,
        heading0=a.heading_deg * DEG,
    )


def jammer_position_ned() -> np.ndarray:
    """Jammer on the ground, abeam the track (to the right) at the closest-approach time."""
    a, tr = ASSUMED_FLYBY, flyby_trajectory()
    k = int(np.argmin(np.abs(tr.t - a.closest_approach_min * MINUTE)))
    p = tr.pos_ned[k].copy()
    v = tr.vel_ned[k, :2] / np.linalg.norm(tr.vel_ned[k, :2])
    p[:2] += a.jammer_cross_track_m * np.array([-v[1], v[0]])
    p[2] = sc.ASSUMED.cruise_altitude_m - a.jammer_height_m  # NED down from the start height
    return p


@input_cache
def channels() -> np.ndarray:
    """Constellation indices of the satellites above the mask for the whole mission."""
    tr = flyby_trajectory()
    con = nominal_gps_constellation()
    geo = satellite_geometry(tr, con, range(con.prn.size))
    return np.flatnonzero(np.all(geo.elevation >= ASSUMED_FLYBY.mask_deg * DEG, axis=0))


@input_cache
def _carrier_dbw(horizon_dbic: float | None = None) -> np.ndarray:
    """Received carrier power (dBW) per sample and channel; ``horizon_dbic`` overrides the
    antenna's horizon gain (pattern sensitivity)."""
    a, tr = ASSUMED_FLYBY, flyby_trajectory()
    geo = satellite_geometry(tr, nominal_gps_constellation(), [int(c) for c in channels()])
    hz = IN.antenna_horizon_dbic if horizon_dbic is None else horizon_dbic
    return a.signal_dbw + np.asarray(elevation_gain_dbi(geo.elevation, a.antenna_zenith_dbic, hz))


@input_cache
def jammer_range_m() -> np.ndarray:
    """Slant range (m) from the aircraft to the jammer at every sample."""
    return np.asarray(slant_range_m(flyby_trajectory().pos_ned, jammer_position_ned()))


def effective_cn0(erp_dbw: float, horizon_dbic: float | None = None) -> np.ndarray:
    """Effective C/N0 (dB-Hz), ``(N, n_channels)``, along the mission for a jammer ERP (dBW)."""
    a = ASSUMED_FLYBY
    J = received_jammer_power_dbw(erp_dbw, jammer_range_m(), GPS_L1_WAVELENGTH_M, a.antenna_to_jammer_dbic)
    return np.asarray(
        effective_cn0_with_jammer_dbhz(
            _carrier_dbw(horizon_dbic),
            np.asarray(J)[:, None],
            a.n0_dbw_hz,
            a.chip_rate_hz,
            a.spectral_separation_q,
        )
    )


def carrier_noise_bandwidth_hz(system: sc.System) -> float:
    """LC: the printed 5.83 Hz; TC: (5/6) w0 of the Table 2.6 natural frequency of its grade."""
    if system.architecture == "loose":
        return IN.lc_carrier_bandwidth_hz
    # Table 2.6 column 4, declared with the residual-acceleration claims (which own Table 2.6)
    return third_order_noise_bandwidth_hz(float(spr.col4_printed_rad_s(f"{system.grade:g}")))


def lock_thresholds(system: sc.System) -> LockThresholds:
    """Sec. 2.5 thresholds; the carrier loss is the 19 dB-Hz floor or the jitter limit of the
    system's carrier-loop bandwidth, whichever is higher."""
    a = ASSUMED_FLYBY
    carrier = carrier_loss_threshold_dbhz(
        carrier_noise_bandwidth_hz(system),
        IN.carrier_loss_dbhz,
        max_phase_error_deg=IN.max_phase_error_deg,
        k_sigma=a.jitter_k_sigma,
        coherent_s=a.coherent_s,
    )
    return LockThresholds(
        IN.code_loss_dbhz, float(carrier), IN.code_reacquisition_dbhz, IN.carrier_reacquisition_dbhz
    )


def _locks(
    system: sc.System, erp_dbw: float, horizon_dbic: float | None = None
) -> tuple[np.ndarray, np.ndarray]:
    cn0 = effective_cn0(erp_dbw, horizon_dbic)
    code = hysteresis_lock(cn0, IN.code_loss_dbhz, IN.code_reacquisition_dbhz)
    if system.architecture == "loose":
        # the loosely coupled filter uses the receiver's position fix (codes) only: its carrier
        # loop is not modelled, so its thresholds are not read
        return code, code.copy()
    th = lock_thresholds(system)
    carrier = hysteresis_lock(cn0, th.carrier_loss, th.carrier_reacquisition) & code
    return code, carrier


def _blackout(system: sc.System, erp_dbw: float, horizon_dbic: float | None = None) -> tuple[float, float]:
    """(start, end) in s of the GPS blackout: fewer than four codes for the loosely coupled
    receiver (no position solution), no code at all for the tightly coupled filter."""
    code, _ = _locks(system, erp_dbw, horizon_dbic)
    need = 4 if system.architecture == "loose" else 1
    iv = outage_intervals(flyby_trajectory().t, code.sum(axis=1) >= need)
    if not iv:
        return (np.nan, np.nan)
    return max(iv, key=lambda x: x[1] - x[0])


@input_cache
def calibrated_erp_dbw(horizon_dbic: float | None = None) -> float:
    """Jammer ERP (dBW) that gives the loosely coupled receiver the paper's 20-min blackout
    (bisection on the 1-s lock history; the blackout grows monotonically with the power)."""
    lc = sc.SYSTEMS[0]

    def length(erp: float) -> float:
        s, e = _blackout(lc, erp, horizon_dbic)
        return 0.0 if np.isnan(s) else (e - s) / MINUTE

    target = IN.erp_fit_blackout_min
    lo, hi = 0.0, 80.0
    if not length(lo) < target < length(hi):
        raise ValueError("the 20-min blackout is not bracketed by 0-80 dBW")
    while hi - lo > 1e-4:  # dB
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if length(mid) < target else (lo, mid)
    return hi


def lc_blackout_min() -> float:
    """Loosely coupled blackout (min, C/N0 crossings) at the calibrated ERP."""
    s, e = _blackout(sc.SYSTEMS[0], calibrated_erp_dbw())
    return float(e - s) / MINUTE


def blackout_reduction_min() -> float:
    """Blackout shortening (min) of the best tightly coupled system (0.2 nmi/h) relative to
    the loosely coupled one, reacquisition search included (:func:`blackouts_min`)."""
    b = blackouts_min()
    return b["LC 1 nmi/h"] - b["TC 0.2 nmi/h"]


def blackouts_min() -> dict[str, float]:
    """Blackout length (min) of each system at the calibrated ERP, from the C/N0 crossings
    (reacquisition search time added: :func:`reacquisition_search`)."""
    erp = calibrated_erp_dbw()
    out = {}
    for s in sc.SYSTEMS:
        b0, b1 = _blackout(s, erp)
        out[s.label] = (b1 - b0 + reacquisition_search()[s.label]["first_search_s"]) / MINUTE
    return out


def pattern_sensitivity(
    horizon_dbic: tuple[float, ...] = (3.0, 1.0, -1.0, -3.0, -5.0, -7.0, -10.0),
) -> list[dict]:
    """Blackout shortening (TC vs LC, C/N0 crossings only) for antenna patterns whose horizon
    gain is ``horizon_dbic`` (zenith fixed), the ERP recalibrated to the 20-min LC blackout
    for each pattern."""
    rows = []
    lc, tc = sc.SYSTEMS[0], sc.SYSTEMS[1]
    for hz in horizon_dbic:
        erp = calibrated_erp_dbw(hz)
        b_lc, b_tc = (np.subtract(*_blackout(s, erp, hz)[::-1]) / MINUTE for s in (lc, tc))
        rows.append(
            {
                "zenith minus horizon gain (dB)": ASSUMED_FLYBY.antenna_zenith_dbic - hz,
                "ERP (dBW)": erp,
                "LC blackout (min)": float(b_lc),
                "TC blackout (min)": float(b_tc),
                "shortening (min)": float(b_lc - b_tc),
            }
        )
    return rows


@input_cache
def flyby_runs() -> dict[sc.System, CovarianceAnalysis]:
    """Covariance analysis of the five systems through the flyby (systems sharing a lock
    table run as one batch), with full covariance snapshots at every code reacquisition."""
    erp = calibrated_erp_dbw()
    tr = flyby_trajectory()
    ch = channels()
    groups: dict[bytes, list] = {}
    tables = {}
    for s in sc.SYSTEMS:
        code, carrier = _locks(s, erp)
        key = code.tobytes() + carrier.tobytes() + s.architecture.encode()
        groups.setdefault(key, []).append(s)
        tables[key] = (code, carrier)
    out: dict[sc.System, CovarianceAnalysis] = {}
    for key, group in groups.items():
        code, carrier = tables[key]
        back = np.flatnonzero((code[1:] & ~code[:-1]).any(axis=1)) + 1
        snaps = (*(int(k) - 1 for k in back), -1)
        out.update(sc._run(tuple(group), tr, code, carrier, ch, snapshots=snaps))
    return {s: out[s] for s in sc.SYSTEMS}


@input_cache
def reacquisition_search() -> dict[str, dict]:
    """Per system and satellite, at the sample before each code reacquisition: the 1-sigma
    range and range-rate uncertainty (true covariance: line of sight, clock, pseudorange
    bias), the Sec. 2.5 search cells and search time; and the first satellite's search time."""
    erp = calibrated_erp_dbw()
    tr = flyby_trajectory()
    geo = satellite_geometry(tr, nominal_gps_constellation(), [int(c) for c in channels()])
    out = {}
    for s, r in flyby_runs().items():
        code, _ = _locks(s, erp)
        lay = r.truth_layout
        p, v = lay.slice("position"), lay.slice("velocity")
        rows = []
        loose = s.architecture == "loose"
        b0, b1 = _blackout(s, erp)
        T = b1 - b0
        # the loosely coupled receiver keeps its own clock, not in this covariance: it has run
        # free through the blackout (the assumed clock's random walks over T)
        m = sc.ASSUMED
        clock_var = (
            m.clock_bias_psd_m2_s * T + m.clock_drift_psd_m2_s3 * T**3 / 3.0,
            m.clock_drift_psd_m2_s3 * T,
        )
        for c in range(code.shape[1]):
            back = np.flatnonzero(code[1:, c] & ~code[:-1, c]) + 1
            if back.size == 0:
                continue
            k = int(back[0]) - 1
            P = r.snapshots[k]
            u = geo.u_ned[k, c]
            h = np.zeros(lay.size)
            h[p] = -u
            h[lay.index("pseudorange bias", c)] = 1.0
            hv = np.zeros(lay.size)
            hv[v] = -u
            hv[lay.index("range-rate bias", c)] = 1.0
            if not loose:
                h[lay.index("clock bias")] = 1.0
                hv[lay.index("clock drift")] = 1.0
            extra = clock_var if loose else (0.0, 0.0)
            sr, srr = float(np.sqrt(h @ P @ h + extra[0])), float(np.sqrt(hv @ P @ hv + extra[1]))
            rows.append((int(nominal_gps_constellation().prn[channels()[c]]), k + 1, sr, srr))
        rows.sort(key=lambda x: x[1])
        sr_all = np.array([x[2] for x in rows])
        srr_all = np.array([x[3] for x in rows])
        out[s.label] = {
            "prn": [x[0] for x in rows],
            "step": [x[1] for x in rows],
            "sigma_range_m": sr_all,
            "sigma_range_rate_mps": srr_all,
            "range_cells": np.asarray(search_cells(sr_all, spa.IN.range_cell_m)),
            "search_s": np.asarray(_search_time(sr_all, srr_all)),
            "first_search_s": float(np.asarray(_search_time(sr_all, srr_all))[0]),
        }
    return out


def _search_time(sr, srr):
    """Sec. 2.5 search time with the paper's 20 ms dwell, 30 m and 10 m/s cells (the dwell and
    the range cell are declared with the acquisition claims, :mod:`navcore.papers.sp_acquisition`)."""
    return search_time(
        sr,
        srr,
        dwell_s=spa.IN.dwell_s,
        range_cell_m=spa.IN.range_cell_m,
        rate_cell_mps=IN.range_rate_cell_mps,
    )


def errors_before_reacquisition() -> dict[str, float]:
    """Horizontal position error (rss 1 sigma, m) of each system 1 s before its blackout ends."""
    erp = calibrated_erp_dbw()
    out = {}
    for s, r in flyby_runs().items():
        _, end = _blackout(s, erp)
        out[s.label] = float(r.horizontal_position[r.at(end - 1.0)])
    return out


def _tc_shorter() -> bool:
    b = blackouts_min()
    return all(b[f"TC {g:g} nmi/h"] < b["LC 1 nmi/h"] for g in GRADE_LABELS_NMI_PER_H)


def _monotone_errors() -> bool:
    e = errors_before_reacquisition()
    return all(
        e[f"TC {a:g} nmi/h"] > e[f"TC {b:g} nmi/h"] for a, b in itertools.pairwise(GRADE_LABELS_NMI_PER_H)
    )


def _range_rate_within_cell() -> bool:
    return all(
        float(np.max(v["sigma_range_rate_mps"])) < IN.range_rate_cell_mps
        for v in reacquisition_search().values()
    )


_CAL = (
    "Jammer flyby modelled on the page: free-space jammer power, elevation-dependent antenna "
    "gain, effective $C/N_0$ against the Sec. 2.5 thresholds (code 18/21 dB-Hz, carrier 19/22 dB-Hz "
    "or the 90-deg jitter limit of the loop bandwidth); the jammer ERP is calibrated to the "
    "loosely coupled 20-min blackout (a fit); antenna pattern (+3 dBic zenith, -5 dBic horizon "
    "with a band of -10 to -2 dBic, -10 dBic towards the jammer), P(Y) code at -163 dBW, Q = 2, "
    "10 km cross-track offset from a straight eastbound leg, 7 km altitude, 200 m/s, nominal "
    "24-satellite constellation are assumptions."
)

ERRATA: list = []

_FIT = (
    " The computation reads the fitted ERP target (SP-fig2.6-lc-blackout) and the assumed horizon "
    "gain (band -10 to -2 dBic, the ERP recalibrated at each)."
)

CLAIMS = [
    Claim(
        id="SP-fig2.6-lc-blackout",
        paper="SP",
        locator="Sec. 2.6.2 (Fig. 2.6)",
        quantity="loss-of-lock (blackout) duration of the loosely coupled system in the jammer flyby",
        published=LC_BLACKOUT_MIN,
        unit="min",
        compute=lc_blackout_min,
        tolerance=prose("approximately", why="'an approximate 20min outage'"),
        expected_status="consistent",
        kind="fit",
        note="Used as calibration: the paper placed its jammer to cause this outage and does not "
        "publish the jammer, so the book solves the jammer's effective radiated power for a "
        "20-min loosely coupled blackout (C/N0 crossings). The value is a fit, not evidence. "
        "Verdict changed from not-reproducible: the book computes it (kind fit). " + _CAL,
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-sec2.6.2-blackout-reduction",
        paper="SP",
        locator="Sec. 2.6.2 (Fig. 2.6)",
        quantity="blackout shortening by the best tightly coupled IMU relative to the loosely coupled one",
        published=BLACKOUT_REDUCTION_MIN,
        unit="min",
        compute=blackout_reduction_min,
        tolerance=prose("about", why="'reduced by only about 2 min'"),
        expected_status="inconsistent",
        note="With the Sec. 2.5 thresholds the tightly coupled blackout is shorter because the "
        "filter uses any tracked code while the loosely coupled receiver needs four; by how much "
        "depends on the spread of C/N0 between satellites, i.e. on the unpublished antenna pattern. "
        "Across horizon gains of -10 to -2 dBic the book's shortening is several times 2 min; "
        "2 min needs a pattern within about 2-3 dB from zenith to horizon (horizon gain near "
        "+0.5 dBic, the page's pattern table), flatter than aircraft L1 antennas. The carrier-loop "
        "bandwidth, which the paper names, does not bind. Verdict changed from not-reproducible: "
        "the book computes it under declared assumptions." + _FIT + " " + _CAL,
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-sec2.6.2-tc-shorter",
        paper="SP",
        locator="Sec. 2.6.2 (Fig. 2.6)",
        quantity="every tightly coupled system has a shorter blackout than the loosely coupled one",
        published=True,
        unit="statement",
        compute=_tc_shorter,
        tolerance=EXACT,
        expected_status="consistent",
        note="Blackout: fewer than four codes (loosely coupled, no receiver solution) or no code at "
        "all (tightly coupled), plus the reacquisition search of Sec. 2.5." + _FIT + " " + _CAL,
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig2.7-tc10",
        paper="SP",
        locator="Sec. 2.6.2 (Fig. 2.7)",
        quantity="tightly coupled 10 nmi/h horizontal position error just before reacquisition",
        published=printed("3300")[0],
        unit="m",
        compute=lambda: errors_before_reacquisition()["TC 10 nmi/h"],
        tolerance=printed("3300")[1],
        expected_status="inconsistent",
        note="The book's flyby value is below 3300 m: its tightly coupled blackout is several "
        "minutes shorter than the paper's (SP-sec2.6.2-blackout-reduction), and the 10 nmi/h error, "
        "dominated by the gyro random walk, grows faster than linearly with the outage. The "
        "flatter the antenna pattern, the longer the tightly coupled blackout and the larger this "
        "error." + _FIT + " Verdict changed from not-reproducible: the book computes it under "
        "declared assumptions (tolerance now the printed digits; was +-25 %). " + _CAL,
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig2.7-tc1",
        paper="SP",
        locator="Sec. 2.6.2 (Fig. 2.7)",
        quantity="tightly coupled 1 nmi/h horizontal position error just before reacquisition",
        published=printed("260")[0],
        unit="m",
        compute=lambda: errors_before_reacquisition()["TC 1 nmi/h"],
        tolerance=printed("260")[1],
        expected_status="inconsistent",
        note="Taken after a tightly coupled blackout several minutes shorter than the paper's (see "
        "SP-fig2.7-tc10 and SP-sec2.6.2-blackout-reduction): the book's value is below 260 m across "
        "the antenna band (it reaches about 230 m at -2 dBic); 260 m needs a flatter pattern, i.e. "
        "a longer tightly coupled blackout, as for SP-fig2.7-tc10."
        + _FIT
        + " Verdict changed from not-reproducible: the book computes it under declared assumptions "
        "(tolerance now the printed digits; was +-25 %). " + _CAL,
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig2.7-tc1-below-lc1",
        paper="SP",
        locator="Sec. 2.6.2 (Fig. 2.7)",
        quantity="just before reacquisition the tightly coupled 1 nmi/h error is below the loosely "
        "coupled 1 nmi/h error",
        published=True,
        unit="statement",
        compute=lambda: (
            errors_before_reacquisition()["TC 1 nmi/h"] < errors_before_reacquisition()["LC 1 nmi/h"]
        ),
        tolerance=EXACT,
        expected_status="consistent",
        note="The paper attributes the difference to better in-flight calibration; in the book's run "
        "the loosely coupled blackout is also longer (it needs four codes), which contributes."
        + _FIT
        + " "
        + _CAL,
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig2.7-monotone-grade",
        paper="SP",
        locator="Sec. 2.6.2 (Fig. 2.7)",
        quantity="tightly coupled errors just before reacquisition fall with IMU quality "
        "(10, 1, 0.5, 0.2 nmi/h)",
        published=True,
        unit="statement",
        compute=_monotone_errors,
        tolerance=EXACT,
        expected_status="consistent",
        note=_CAL + _FIT,
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-sec2.6.2-range-rate-cell",
        paper="SP",
        locator="Sec. 2.6.2 (Table 2.7 text)",
        quantity="at reacquisition no satellite's range-rate uncertainty exceeds 10 m/s (one Doppler cell)",
        published=True,
        unit="statement",
        compute=_range_rate_within_cell,
        tolerance=EXACT,
        expected_status="consistent",
        note="$1\\sigma$ range-rate uncertainty along each line of sight (velocity, clock drift and "
        "range-rate bias of the true covariance) at the sample before each code reacquisition, all "
        "systems and satellites." + _FIT + " " + _CAL,
        discussed_in=PAGE,
    ),
]
