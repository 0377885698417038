r"""Linear covariance analysis of an aided INS: truth model versus filter model.

The filter estimates the states of a *filter layout*; the world evolves according to a
larger *truth layout* (every filter block plus unmodelled ones: misalignments, gravity
anomalies, per-satellite biases...). With :math:`E` the embedding of filter states into
truth states, the true estimation error :math:`e = x_t - E\hat x_f` obeys

.. math::

    \begin{aligned}
    P_t^- &= \Phi_t P_t \Phi_t^T + Q_t, &
    P_f^- &= \Phi_f P_f \Phi_f^T + Q_f,\\
    K &= P_f^- H_f^T (H_f P_f^- H_f^T + R_f)^{-1}, &
    P_f^+ &= (I-KH_f)P_f^-(I-KH_f)^T + K R_f K^T,\\
    P_t^+ &= (I - EKH_t) P_t^- (I - EKH_t)^T + EK R_t K^T E^T,
    \end{aligned}

valid when the filter's dynamics are the truth dynamics restricted to the filter states
and filter states do not drive unmodelled ones (:math:`\Phi_t E = E\Phi_f`), which holds
for the block structure of :mod:`navcore.inertial.error_dynamics`; :math:`H_f = H_t E`.
The filter accounts for unmodelled measurement errors by inflating its noise with their
a-priori covariance, :math:`R_f = R_t + H_u P_{0,uu} H_u^T`. When both layouts coincide the
two covariances are identical (the optimal filter).

Measurements are supplied per time step as :class:`~navcore.estimation.Measurement`
objects over the *truth* layout by schedule functions built here: tightly coupled
pseudorange and range rate from each tracked channel, the loosely coupled receiver
position every 10 s when at least four codes are tracked and the expected horizontal
error is small enough, barometric altitude, and Doppler ground speed in body axes.

Discretisation: :math:`\Phi = \sum_{j\le 4} (F\Delta t)^j/j!` (exact for the
nilpotent chains gyro drift -> attitude -> velocity -> position) and
:math:`Q = (\Phi\,GQG^T\Phi^T + GQG^T)\Delta t/2`, relinearised whenever the flight
condition changes (a 1-s step is far below the 84-min Schuler period).

References
----------
.. [1] A. Gelb (ed.), Applied Optimal Estimation (1974), Sec. 7.2 (sensitivity and
   suboptimal-filter error analysis).
.. [2] P. S. Maybeck, Stochastic Models, Estimation, and Control, Vol. 1 (1979), Ch. 6.
.. [3] G. T. Schmidt and R. E. Phillips, NATO RTO-EN-SET-116, Sec. 2.1-2.6.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import require_nonnegative, require_positive, require_symmetric_psd
from navcore.estimation.covariance import Measurement
from navcore.estimation.layout import StateLayout
from navcore.gnss.constellation import Constellation
from navcore.inertial.error_dynamics import (
    ErrorSources,
    earth_rate_ned,
    error_dynamics,
    process_noise_psd,
    transport_rate_ned,
)
from navcore.inertial.trajectories import Trajectory

__all__ = [
    "CovarianceAnalysis",
    "SatelliteGeometry",
    "baro_schedule",
    "circular_error_probable",
    "combine_schedules",
    "doppler_schedule",
    "embedding",
    "horizontal_sigma",
    "lock_table",
    "loosely_coupled_schedule",
    "run_covariance_analysis",
    "satellite_geometry",
    "taylor_transition",
    "tightly_coupled_schedule",
]

Array = NDArray[np.float64]
Schedule = Callable[[int], Sequence[Measurement]]


def embedding(filter_layout: StateLayout, truth_layout: StateLayout) -> NDArray[np.int64]:
    """Truth-state index of each filter state (blocks matched by name and size)."""
    if not filter_layout.issubset(truth_layout):
        raise ValueError("filter_layout must be a subset of truth_layout (same block names and sizes)")
    idx = [np.arange(truth_layout.size)[truth_layout.slice(b.name)] for b in filter_layout.blocks]
    return np.concatenate(idx).astype(np.int64)


@dataclass(frozen=True)
class CovarianceAnalysis:
    """Result of :func:`run_covariance_analysis`.

    Attributes
    ----------
    t : (N,) array
        Times (s).
    truth_layout, filter_layout : StateLayout
    true_var : (N, n_t) array
        Diagonal of the true error covariance after the updates at each time.
    filter_var : (N, n_f) array
        Diagonal of the filter's own covariance.
    horizontal_position : (N,) array
        True rss 1-sigma horizontal position error (m).
    horizontal_velocity : (N,) array
        True rss 1-sigma horizontal velocity error (m/s).
    n_updates : (N,) int array
        Scalar measurements processed at each time.
    snapshots : dict
        Full true covariance at requested step indices.
    """

    t: Array
    truth_layout: StateLayout
    filter_layout: StateLayout
    true_var: Array
    filter_var: Array
    horizontal_position: Array
    horizontal_velocity: Array
    n_updates: NDArray[np.int64]
    snapshots: dict[int, Array]

    def sigma(self, block: str, *, filter_model: bool = False) -> Array:
        """1-sigma time series of a block (``(N, size)``), true or as the filter believes."""
        layout = self.filter_layout if filter_model else self.truth_layout
        var = self.filter_var if filter_model else self.true_var
        return np.sqrt(np.clip(var[:, layout.slice(block)], 0.0, None))

    def at(self, time: float) -> int:
        """Index of the sample closest to ``time``."""
        return int(np.argmin(np.abs(self.t - time)))


def horizontal_sigma(P: ArrayLike, layout: StateLayout, block: str = "position") -> float:
    """rss 1-sigma of the north and east components of ``block`` in covariance ``P``."""
    P = np.asarray(P, dtype=float)
    i = layout.slice(block).start
    return float(np.sqrt(max(P[i, i] + P[i + 1, i + 1], 0.0)))


def run_covariance_analysis(
    trajectory: Trajectory,
    truth_layout: StateLayout,
    filter_layout: StateLayout,
    sources: ErrorSources,
    P0: ArrayLike,
    schedule: Schedule | None = None,
    *,
    snapshots: Sequence[int] = (),
    relinearize_every: int = 30,
    inflate_filter_noise: bool = True,
    vertical_channel: bool = True,
) -> CovarianceAnalysis:
    """Propagate the true and the filter covariance along a trajectory.

    Parameters
    ----------
    trajectory : Trajectory
        Sampled flight condition; the analysis steps at its interval.
    truth_layout, filter_layout : StateLayout
        Truth and filter states (filter blocks must all be truth blocks).
    sources : ErrorSources
        Error-source magnitudes (process noise, Gauss-Markov constants).
    P0 : (n_t, n_t) array
        Initial truth covariance; the filter starts from its restriction.
    schedule : callable ``k -> sequence of Measurement``
        Measurements (over the truth layout) at step ``k``.
    snapshots : sequence of int
        Step indices at which to keep the full true covariance (``-1`` for the last).
    relinearize_every : int
        Recompute the transition at least every this many steps (and whenever the
        specific force, velocity or attitude changes).
    inflate_filter_noise : bool
        Add the a-priori covariance of unmodelled measurement states to the filter's R.
    vertical_channel : bool
        Passed to :func:`~navcore.inertial.error_dynamics.error_dynamics` (``False`` for a
        horizontal-only unaided analysis).

    Returns
    -------
    CovarianceAnalysis
    """
    Pt = np.array(P0, dtype=float)
    n_t = truth_layout.size
    if Pt.shape != (n_t, n_t):
        raise ValueError(f"P0 must have shape ({n_t}, {n_t}), got {Pt.shape}")
    require_symmetric_psd("P0", Pt)
    require_positive("relinearize_every", relinearize_every)
    idx = embedding(filter_layout, truth_layout)
    unmodelled = np.setdiff1d(np.arange(n_t), idx)
    P0_uu = Pt[np.ix_(unmodelled, unmodelled)]
    Pf = Pt[np.ix_(idx, idx)].copy()
    N = len(trajectory)
    dt = trajectory.dt
    tv = np.empty((N, n_t))
    fv = np.empty((N, idx.size))
    counts = np.zeros(N, dtype=np.int64)
    snaps: dict[int, Array] = {}
    want = {k % N for k in snapshots}
    eye_t = np.eye(n_t)
    eye_f = np.eye(idx.size)
    key = None
    since = 0
    Phi_t = Q_t = Phi_f = Q_f = None
    speed = trajectory.speed
    omega_in = earth_rate_ned(trajectory.lat) + transport_rate_ned(
        trajectory.vel_ned, trajectory.lat, trajectory.h
    )
    omega_ib_b = trajectory.omega_nb_b + np.einsum("nji,nj->ni", trajectory.C_bn, omega_in)
    for k in range(N):
        if k > 0:
            j = k - 1
            cond = np.concatenate(
                [trajectory.f_ned[j], trajectory.vel_ned[j], trajectory.C_bn[j].ravel(), omega_ib_b[j]]
            )
            if key is None or since >= relinearize_every or np.max(np.abs(cond - key)) > 1e-9:
                F = error_dynamics(
                    truth_layout,
                    f_ned=trajectory.f_ned[j],
                    C_bn=trajectory.C_bn[j],
                    omega_ib_b=omega_ib_b[j],
                    v_ned=trajectory.vel_ned[j],
                    lat=float(trajectory.lat[j]),
                    h=float(trajectory.h[j]),
                    sources=sources,
                    vertical_channel=vertical_channel,
                )
                S = process_noise_psd(truth_layout, sources, speed_mps=float(speed[j]))
                Phi_t = taylor_transition(F, dt)
                Q_t = 0.5 * (Phi_t @ S @ Phi_t.T + S) * dt
                Q_t = 0.5 * (Q_t + Q_t.T)
                Phi_f = Phi_t[np.ix_(idx, idx)]
                Q_f = Q_t[np.ix_(idx, idx)]
                key, since = cond, 0
            since += 1
            Pt = Phi_t @ Pt @ Phi_t.T + Q_t
            Pf = Phi_f @ Pf @ Phi_f.T + Q_f
        if schedule is not None:
            meas = list(schedule(k))
            if meas:
                Ht = np.vstack([np.atleast_2d(m.H) for m in meas])
                blocks = [np.atleast_2d(m.R) for m in meas]
                m_tot = Ht.shape[0]
                Rt = np.zeros((m_tot, m_tot))
                r0 = 0
                for B in blocks:
                    Rt[r0 : r0 + B.shape[0], r0 : r0 + B.shape[0]] = B
                    r0 += B.shape[0]
                Hf = Ht[:, idx]
                Rf = Rt
                if inflate_filter_noise and unmodelled.size:
                    Hu = Ht[:, unmodelled]
                    Rf = Rt + Hu @ P0_uu @ Hu.T
                Sf = Hf @ Pf @ Hf.T + Rf
                K = np.linalg.solve(Sf, Hf @ Pf).T
                A = eye_f - K @ Hf
                Pf = A @ Pf @ A.T + K @ Rf @ K.T
                EK = np.zeros((n_t, m_tot))
                EK[idx] = K
                At = eye_t - EK @ Ht
                Pt = At @ Pt @ At.T + EK @ Rt @ EK.T
                counts[k] = m_tot
        Pt = 0.5 * (Pt + Pt.T)
        Pf = 0.5 * (Pf + Pf.T)
        tv[k] = np.diagonal(Pt)
        fv[k] = np.diagonal(Pf)
        if k in want:
            snaps[k] = Pt.copy()
    p = truth_layout.slice("position").start
    v = truth_layout.slice("velocity").start
    hp = np.sqrt(np.clip(tv[:, p] + tv[:, p + 1], 0.0, None))
    hv = np.sqrt(np.clip(tv[:, v] + tv[:, v + 1], 0.0, None))
    return CovarianceAnalysis(trajectory.t, truth_layout, filter_layout, tv, fv, hp, hv, counts, snaps)


def taylor_transition(F: ArrayLike, dt: float, order: int = 4) -> Array:
    """Transition ``sum_{j <= order} (F dt)^j / j!`` (Horner form).

    Examples
    --------
    >>> taylor_transition([[0.0, 1.0], [0.0, 0.0]], 2.0).tolist()
    [[1.0, 2.0], [0.0, 1.0]]
    """
    A = np.asarray(F, dtype=float) * dt
    n = A.shape[0]
    Phi = np.eye(n)
    for j in range(order, 0, -1):
        Phi = np.eye(n) + (A @ Phi) / j
    return Phi


# --------------------------------------------------------------------------- GPS geometry


@dataclass(frozen=True)
class SatelliteGeometry:
    """Line-of-sight unit vectors (NED) and elevations of tracked channels over a trajectory.

    ``u_ned[k, c]`` points from the vehicle to the satellite of channel ``c`` at step ``k``.
    """

    prn: NDArray[np.int64]
    u_ned: Array
    elevation: Array


def satellite_geometry(
    trajectory: Trajectory, constellation: Constellation, channels: Sequence[int]
) -> SatelliteGeometry:
    """Vectorised line-of-sight geometry of the satellites ``channels`` (indices into the
    constellation) along ``trajectory``."""
    ch = np.asarray(channels, dtype=np.int64)
    lat, lon, h = trajectory.lat, trajectory.lon, trajectory.h
    from navcore.frames import geodetic_to_ecef

    r_user = geodetic_to_ecef(lat, lon, h)  # (N, 3)
    r_sat = constellation.positions_ecef(trajectory.t)[:, ch]  # (N, c, 3)
    d = r_sat - r_user[:, None, :]
    u = d / np.linalg.norm(d, axis=-1, keepdims=True)
    sl, cl, so, co = np.sin(lat), np.cos(lat), np.sin(lon), np.cos(lon)
    C_en = np.stack(
        [
            np.stack([-sl * co, -sl * so, cl], -1),
            np.stack([-so, co, np.zeros_like(lat)], -1),
            np.stack([-cl * co, -cl * so, -sl], -1),
        ],
        -2,
    )  # (N, 3, 3) ECEF -> NED
    u_ned = np.einsum("nij,ncj->nci", C_en, u)
    el = np.arcsin(np.clip(-u_ned[..., 2], -1.0, 1.0))
    return SatelliteGeometry(constellation.prn[ch], u_ned, el)


def lock_table(
    t: ArrayLike,
    n_channels: int,
    events: Sequence[tuple[float, int, str, bool]],
    *,
    start_locked: bool = True,
) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """Code and carrier lock of each channel over time from a list of events.

    Parameters
    ----------
    t : (N,) array
        Times (s).
    n_channels : int
    events : sequence of ``(time, channel, "code" | "carrier", locked)``
        From ``time`` on, the channel's code or carrier is (un)locked.

    Returns
    -------
    code, carrier : (N, n_channels) bool arrays
    """
    t = np.asarray(t, dtype=float)
    code = np.full((t.size, n_channels), start_locked)
    carrier = np.full((t.size, n_channels), start_locked)
    for time, c, kind, locked in sorted(events, key=lambda e: e[0]):
        if kind not in ("code", "carrier"):
            raise ValueError(f"event kind must be 'code' or 'carrier', got {kind!r}")
        target = code if kind == "code" else carrier
        target[t >= time, c] = locked
    return code, carrier


def tightly_coupled_schedule(
    layout: StateLayout,
    geometry: SatelliteGeometry,
    code: NDArray[np.bool_],
    carrier: NDArray[np.bool_],
    *,
    pseudorange_noise: float,
    range_rate_noise: float,
    every: int = 1,
    mask_rad: float = 0.0,
) -> Schedule:
    """Pseudorange (code lock) and range rate (carrier lock) from each channel every ``every`` steps.

    Rows (truth layout): ``d rho = -u . dr + db + b_pr[c]``, ``d rho_dot = -u . dv + d(b_dot) + b_rr[c]``.
    """
    require_positive("pseudorange_noise", pseudorange_noise)
    require_positive("range_rate_noise", range_rate_noise)
    n = layout.size
    names = layout.names
    p, v = layout.slice("position"), layout.slice("velocity")

    def sched(k: int) -> list[Measurement]:
        if k % every:
            return []
        out = []
        for c in range(geometry.u_ned.shape[1]):
            if geometry.elevation[k, c] < mask_rad:
                continue
            u = geometry.u_ned[k, c]
            if code[k, c]:
                H = np.zeros((1, n))
                H[0, p] = -u
                if "clock bias" in names:
                    H[0, layout.slice("clock bias")] = 1.0
                if "pseudorange bias" in names:
                    H[0, layout.index("pseudorange bias", c)] = 1.0
                out.append(Measurement(H, np.array([[pseudorange_noise**2]])))
            if carrier[k, c]:
                H = np.zeros((1, n))
                H[0, v] = -u
                if "clock drift" in names:
                    H[0, layout.slice("clock drift")] = 1.0
                if "range-rate bias" in names:
                    H[0, layout.index("range-rate bias", c)] = 1.0
                out.append(Measurement(H, np.array([[range_rate_noise**2]])))
        return out

    return sched


def loosely_coupled_schedule(
    layout: StateLayout,
    geometry: SatelliteGeometry,
    code: NDArray[np.bool_],
    *,
    pseudorange_noise: float,
    pseudorange_bias_sigma: float = 0.0,
    interval_steps: int = 10,
    max_ehe_m: float = 100.0,
    mask_rad: float = 0.0,
) -> Schedule:
    """The receiver's position solution every ``interval_steps`` steps, if >= 4 codes are
    tracked and the expected horizontal error is below ``max_ehe_m``.

    The receiver solves position and clock by least squares from the tracked pseudoranges,
    ``dr_meas = (G^T G)^{-1} G^T (b_pr + noise)`` with ``G = [-u, 1]``: its position error is
    the position rows of that map applied to the per-channel biases (truth states) and to
    the noise, so the measurement is correlated with the pseudorange-bias states exactly as
    in the tightly coupled case. EHE is ``sigma_UERE * HDOP``.
    """
    require_positive("pseudorange_noise", pseudorange_noise)
    require_nonnegative("pseudorange_bias_sigma", pseudorange_bias_sigma)
    n = layout.size
    p = layout.slice("position")
    has_bias = "pseudorange bias" in layout.names
    uere2 = pseudorange_noise**2 + pseudorange_bias_sigma**2

    def sched(k: int) -> list[Measurement]:
        if k % interval_steps:
            return []
        ok = code[k] & (geometry.elevation[k] >= mask_rad)
        chans = np.flatnonzero(ok)
        if chans.size < 4:
            return []
        u = geometry.u_ned[k, chans]
        G = np.hstack([-u, np.ones((chans.size, 1))])
        GtG_inv = np.linalg.inv(G.T @ G)
        ehe = np.sqrt(uere2 * (GtG_inv[0, 0] + GtG_inv[1, 1]))
        if ehe >= max_ehe_m:
            return []
        A = (GtG_inv @ G.T)[:3]  # position rows
        # the LS solution maps -u.dr onto -dr: measured position error minus INS error
        H = np.zeros((3, n))
        H[:, p] = np.eye(3)
        if has_bias:
            for j, c in enumerate(chans):
                H[:, layout.index("pseudorange bias", int(c))] = -A[:, j]
        R = pseudorange_noise**2 * GtG_inv[:3, :3]
        return [Measurement(H, 0.5 * (R + R.T))]

    return sched


def baro_schedule(layout: StateLayout, *, noise_m: float, every: int = 1) -> Schedule:
    """Barometric altitude: ``dz = -dr_D - b_alt + noise`` (height = minus down)."""
    require_positive("noise_m", noise_m)
    H = np.zeros((1, layout.size))
    H[0, layout.index("position", 2)] = -1.0
    if "altimeter bias" in layout.names:
        H[0, layout.slice("altimeter bias")] = -1.0
    R = np.array([[noise_m**2]])

    def sched(k: int) -> list[Measurement]:
        return [] if k % every else [Measurement(H, R)]

    return sched


def doppler_schedule(
    layout: StateLayout,
    trajectory: Trajectory,
    *,
    noise_mps: float,
    every: int = 1,
    active: NDArray[np.bool_] | None = None,
) -> Schedule:
    """Doppler ground velocity in body axes.

    With the computed attitude :math:`\\hat C^n_b = (I-[\\psi\\times])C^n_b`, the INS-predicted
    body velocity minus the Doppler reading is

    .. math::

        \\delta z = C^b_n\\,\\delta v - C^b_n [v^n\\times]\\,\\psi - b_d - \\mathrm{diag}(v^b)\\,s_d
        - [v^b\\times]\\,\\mu_d + w.
    """
    require_positive("noise_mps", noise_mps)
    n = layout.size
    names = layout.names
    R = noise_mps**2 * np.eye(3)
    from navcore.inertial.error_dynamics import skew_stack

    def sched(k: int) -> list[Measurement]:
        if k % every or (active is not None and not active[k]):
            return []
        C = trajectory.C_bn[k]
        vn = trajectory.vel_ned[k]
        vb = C.T @ vn
        H = np.zeros((3, n))
        H[:, layout.slice("velocity")] = C.T
        H[:, layout.slice("misalignment")] = -C.T @ skew_stack(vn)
        if "doppler bias" in names:
            H[:, layout.slice("doppler bias")] = -np.eye(3)
        if "doppler scale factor" in names:
            H[:, layout.slice("doppler scale factor")] = -np.diag(vb)
        if "doppler misalignment" in names:
            H[:, layout.slice("doppler misalignment")] = -skew_stack(vb)
        return [Measurement(H, R)]

    return sched


def combine_schedules(*schedules: Schedule | None) -> Schedule:
    """A schedule that returns the measurements of all given schedules at each step."""
    live = [s for s in schedules if s is not None]

    def sched(k: int) -> list[Measurement]:
        out: list[Measurement] = []
        for s in live:
            out.extend(s(k))
        return out

    return sched


def circular_error_probable(P2: ArrayLike, p: float = 0.5) -> float:
    """Radius containing probability ``p`` of a zero-mean 2-D Gaussian with covariance ``P2``.

    With eigenvalues :math:`a, b` the probability inside radius :math:`r` is
    :math:`\\frac{1}{2\\pi\\sqrt{ab}}\\int_0^{2\\pi}\\frac{1-e^{-r^2c(\\theta)/2}}{c(\\theta)}d\\theta`,
    :math:`c = \\cos^2\\theta/a + \\sin^2\\theta/b`; the radius is found by bisection.
    For a circular Gaussian the CEP is :math:`\\sigma\\sqrt{2\\ln 2}`:

    >>> round(circular_error_probable(np.eye(2)), 6)
    1.17741
    """
    from scipy.optimize import brentq

    P2 = np.asarray(P2, dtype=float)
    if P2.shape != (2, 2):
        raise ValueError(f"P2 must be 2x2, got {P2.shape}")
    if not 0.0 < p < 1.0:
        raise ValueError(f"p must be in (0, 1), got {p}")
    a, b = np.clip(np.linalg.eigvalsh(0.5 * (P2 + P2.T)), 1e-300, None)
    th = np.linspace(0.0, 2 * np.pi, 2049)[:-1]
    c = np.cos(th) ** 2 / a + np.sin(th) ** 2 / b

    def prob(r: float) -> float:
        return float(np.mean(-np.expm1(-(r**2) * c / 2) / c) / np.sqrt(a * b))

    hi = 10.0 * np.sqrt(max(a, b))
    return float(brentq(lambda r: prob(r) - p, 0.0, hi, xtol=1e-12 * hi))
