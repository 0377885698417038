r"""Linear covariance analysis of an aided INS: truth model versus filter model.

The filter estimates the states of a *filter layout*; the world evolves according to a
larger *truth layout* (every filter block plus unmodelled ones: misalignments, gravity
anomalies, per-satellite biases...). With :math:`E` the embedding of filter states into
truth states, the true estimation error :math:`e = x_t - E\hat x_f` obeys

.. math::

    \begin{aligned}
    P_t^- &= \Phi_t P_t \Phi_t^T + Q_t,\qquad
    P_f^- = \Phi_f P_f \Phi_f^T + Q_f,\\
    K &= P_f^- H_f^T (H_f P_f^- H_f^T + R_f)^{-1},\\
    P_f^+ &= (I-KH_f)P_f^-(I-KH_f)^T + K R_f K^T,\\
    P_t^+ &= (I - EKH_t) P_t^- (I - EKH_t)^T + EK R_t K^T E^T,
    \end{aligned}

valid when the filter's dynamics are the truth dynamics restricted to the filter states
and filter states do not drive unmodelled ones (:math:`\Phi_t E = E\Phi_f`), which holds
for the block structure of :mod:`navcore.inertial.error_dynamics`; :math:`H_f = H_t E`.
The filter accounts for unmodelled measurement errors by inflating its noise with their
a-priori covariance, :math:`R_f = R_t + H_u P_{0,uu} H_u^T`. When both layouts coincide the
two covariances are identical (the optimal filter).

Measurements are supplied per time step as :class:`~navcore.estimation.covariance.Measurement`
objects over the *truth* layout by schedule functions built here: tightly coupled
pseudorange and range rate from each tracked channel, the loosely coupled receiver
position every 10 s when at least four codes are tracked and the expected horizontal
error is small enough, barometric altitude, and Doppler ground speed in body axes. Each of
them (and :func:`combine_schedules` of them) also hands the engine its rows already stacked,
``schedule.stacked(k)`` giving ``(H, R)`` or ``None``; a schedule of one's own needs only the
call ``k -> list of Measurement``.

Discretisation: :math:`\Phi = \sum_{j\le 4} (F\Delta t)^j/j!` (exact for the
nilpotent chains gyro bias -> attitude -> velocity -> position) and
:math:`Q = \int_0^{\Delta t}\Phi(s)\,GQG^T\Phi(s)^T ds` by Gauss-Legendre quadrature,
relinearised whenever the flight condition changes (1-s and 10-s steps are far below the
84-min Schuler period).

References
----------
.. [1] A. Gelb (ed.), Applied Optimal Estimation (1974), Sec. 7.2 (sensitivity and
   suboptimal-filter error analysis).
.. [2] P. S. Maybeck, Stochastic Models, Estimation, and Control, Vol. 1 (1979), Ch. 6.
.. [3] G. T. Schmidt and R. E. Phillips, NATO RTO-EN-SET-116, Sec. 2.1-2.6.
"""

from __future__ import annotations

import dataclasses
import hashlib
import itertools
from collections import OrderedDict
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    COVARIANCE,
    COVARIANCE_STACK,
    NONNEGATIVE,
    OPEN_PROBABILITY,
    POSITIVE,
    ModelDomainError,
    Range,
    check_public,
    require_nonnegative,
    require_positive,
    require_symmetric_psd,
)
from navcore.estimation.covariance import Measurement
from navcore.estimation.kalman import joseph_rows_unchecked
from navcore.estimation.layout import StateLayout
from navcore.gnss.constellation import Constellation
from navcore.inertial.error_dynamics import (
    ErrorSources,
    _error_dynamics_stack,
    _process_noise_diag_stack,
    earth_rate_ned,
    transport_rate_ned,
)
from navcore.inertial.trajectories import Trajectory
from navcore.trace import implements

__all__ = [
    "CovarianceAnalysis",
    "SatelliteGeometry",
    "baro_schedule",
    "best_geometry_channels",
    "circular_error_probable",
    "combine_schedules",
    "concatenate_analyses",
    "discrete_noise",
    "doppler_schedule",
    "embedding",
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
    """Truth-state index of each filter state (blocks matched by name and size).

    Parameters
    ----------
    filter_layout : StateLayout
        Filter states.
    truth_layout : StateLayout
        Truth states (a superset of the filter blocks).

    Returns
    -------
    (n_f,) ndarray of int
        ``idx[i]`` is the truth index of filter state ``i`` (the matrix :math:`E` of the module
        docstring as an index map).

    Raises
    ------
    ValueError
        If a filter block is not a truth block of the same size.

    Examples
    --------
    >>> from navcore.inertial.error_dynamics import ins_error_layout
    >>> truth = ins_error_layout("position", "velocity", "misalignment", "gyro bias")
    >>> embedding(ins_error_layout("position", "gyro bias"), truth)
    array([ 0,  1,  2,  9, 10, 11])
    """
    if not filter_layout.issubset(truth_layout):
        raise ValueError("filter_layout must be a subset of truth_layout (same block names and sizes)")
    idx = [np.arange(truth_layout.size)[truth_layout.slice(b.name)] for b in filter_layout.blocks]
    return np.concatenate(idx).astype(np.int64)


@dataclass(frozen=True)
class CovarianceAnalysis:
    r"""Result of :func:`run_covariance_analysis`.

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
        True rss 1-:math:`\sigma` horizontal position error (m).
    horizontal_velocity : (N,) array
        True rss 1-:math:`\sigma` horizontal velocity error (m/s).
    n_updates : (N,) int array
        Scalar measurements processed at each time.
    snapshots : dict
        Full true covariance at requested step indices.
    final_true, final_filter : arrays
        Full true and filter covariances at the last step (to resume an analysis, e.g. with
        a different step size, via ``P0`` and ``P0_filter``).
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
    final_true: Array | None = None
    final_filter: Array | None = None

    def sigma(self, block: str, *, filter_model: bool = False) -> Array:
        r"""1-:math:`\sigma` time series of a block (``(N, size)``), true or as the filter believes."""
        layout = self.filter_layout if filter_model else self.truth_layout
        var = self.filter_var if filter_model else self.true_var
        return np.sqrt(np.clip(var[:, layout.slice(block)], 0.0, None))

    def at(self, time: float) -> int:
        """Index of the sample closest to ``time``."""
        return int(np.argmin(np.abs(self.t - time)))


@implements("SP Sec. 2.6")
def run_covariance_analysis(
    trajectory: Trajectory,
    truth_layout: StateLayout,
    filter_layout: StateLayout,
    sources: ErrorSources | Sequence[ErrorSources],
    P0: ArrayLike,
    schedule: Schedule | None = None,
    *,
    snapshots: Sequence[int] = (),
    relinearize_every: int = 120,
    inflate_filter_noise: bool = True,
    vertical_channel: bool = True,
    P0_filter: ArrayLike | None = None,
    P0_apriori: ArrayLike | None = None,
    measurement_steps: ArrayLike | None = None,
    stride: int = 10,
    filter_added_psd: ArrayLike | None = None,
) -> CovarianceAnalysis | list[CovarianceAnalysis]:
    r"""Propagate the true and the filter covariance along a trajectory.

    Parameters
    ----------
    trajectory : Trajectory
        Sampled flight condition; the analysis steps at its interval.
    truth_layout, filter_layout : StateLayout
        Truth and filter states (filter blocks must all be truth blocks).
    sources : ErrorSources or sequence of ErrorSources
        Error-source magnitudes (process noise, Gauss-Markov constants). A sequence runs
        a batch of systems that share the trajectory, the layouts and the schedule (for
        instance several IMU grades) in one pass; their Gauss-Markov constants must agree.
    P0 : (n_t, n_t) or (B, n_t, n_t) array
        Initial truth covariance (one per batch member); the filter starts from its
        restriction.
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
    P0_filter : (n_f, n_f) or (B, n_f, n_f) array, optional
        Initial filter covariance when resuming an analysis (default: restriction of
        ``P0``, right at the start of a mission).
    P0_apriori : array like ``P0``, optional
        The mission's a-priori truth covariance, whose unmodelled block inflates the filter's
        measurement noise (default ``P0``; pass the original one when resuming).
    measurement_steps : (N,) bool array, optional
        ``True`` where ``schedule`` may return measurements. Where it is known to be
        ``False`` for ``stride - 1`` consecutive steps and the flight condition does not
        change, the engine takes one composite step :math:`\Phi^L` (cached per linearisation)
        and computes the variances of the skipped samples exactly,
        :math:`\operatorname{diag}(\Phi^i P \Phi^{iT} + Q_i)` for :math:`i < L` (the saw-tooth
        growth between fixes, not an interpolation).
        Default: every step is a single step.
    stride : int
        Length of a composite step.
    filter_added_psd : (n_f,) array, optional
        Extra white-noise PSD the filter adds to its own model (tuning for unmodelled
        processes, e.g. gravity anomalies on the velocity states); the truth is unchanged.

    Returns
    -------
    CovarianceAnalysis or list of CovarianceAnalysis
        Variances of the true error and of the filter's own estimate per step (state
        units squared), horizontal position (m) and velocity (m/s) 1-:math:`\sigma`, update counts,
        snapshots and final covariances; a list (one per source) for a batch of sources.

    Raises
    ------
    ValueError
        If ``sources`` is empty or a batch disagrees in its Gauss-Markov constants, a
        covariance has the wrong shape or is not symmetric positive semi-definite, the
        filter layout is not part of the truth layout, or ``relinearize_every`` is not
        positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6 (covariance analysis); Gelb (1974), Sec. 7.2 (reference 1 of the module).

    Examples
    --------
    An unaided INS with an accelerometer bias of 1 mg (1-:math:`\sigma`) per axis: after 60 s the
    horizontal position error is close to :math:`\sqrt{2}\, b t^2 / 2`.

    >>> import numpy as np
    >>> from navcore.inertial.error_dynamics import ErrorSources, initial_covariance, ins_error_layout
    >>> from navcore.inertial.imu import ImuSpec
    >>> from navcore.inertial.trajectories import straight_and_level
    >>> lay = ins_error_layout("position", "velocity", "misalignment", "accel bias")
    >>> src = ErrorSources(imu=ImuSpec("example", accel_bias=1e-3))
    >>> P0 = initial_covariance(lay, src)
    >>> res = run_covariance_analysis(straight_and_level(60.0), lay, lay, src, P0)
    >>> round(float(res.horizontal_position[-1]), 2)
    2.54
    """
    batch = not isinstance(sources, ErrorSources)
    src_list: list[ErrorSources] = [sources] if isinstance(sources, ErrorSources) else list(sources)
    if not src_list:
        raise ValueError("sources must not be empty")
    for s_ in src_list[1:]:
        if (s_.gravity, s_.altimeter) != (src_list[0].gravity, src_list[0].altimeter):
            raise ValueError("sources in a batch must share their Gauss-Markov constants")
    B = len(src_list)
    n_t = truth_layout.size
    Pt = np.array(P0, dtype=float)
    if Pt.ndim == 2:
        Pt = np.broadcast_to(Pt, (B, n_t, n_t)).copy()
    if Pt.shape != (B, n_t, n_t):
        raise ValueError(f"P0 must have shape ({n_t}, {n_t}) or ({B}, {n_t}, {n_t}), got {Pt.shape}")
    for b in range(B):
        require_symmetric_psd("P0", Pt[b])
    require_positive("relinearize_every", relinearize_every)
    idx = embedding(filter_layout, truth_layout)
    n_f = idx.size
    unmodelled = np.setdiff1d(np.arange(n_t), idx)
    Pa = Pt if P0_apriori is None else np.broadcast_to(np.asarray(P0_apriori, dtype=float), Pt.shape)
    P0_uu = Pa[:, unmodelled[:, None], unmodelled]
    if P0_filter is None:
        Pf = Pt[:, idx[:, None], idx].copy()
    else:
        Pf = np.array(P0_filter, dtype=float)
        if Pf.ndim == 2:
            Pf = np.broadcast_to(Pf, (B, n_f, n_f)).copy()
        if Pf.shape != (B, n_f, n_f):
            raise ValueError(
                f"P0_filter must have shape ({n_f}, {n_f}) or ({B}, {n_f}, {n_f}), got {Pf.shape}"
            )
    N = len(trajectory)
    dt = trajectory.dt
    counts = np.zeros(N, dtype=np.int64)
    snaps: list[dict[int, Array]] = [{} for _ in range(B)]
    want = {k % N for k in snapshots}
    speed = trajectory.speed
    omega_in = earth_rate_ned(trajectory.lat) + transport_rate_ned(
        trajectory.vel_ned, trajectory.lat, trajectory.h
    )
    omega_ib_b = trajectory.omega_nb_b + np.einsum("nji,nj->ni", trajectory.C_bn, omega_in)
    # relinearise when the flight condition moves by more than: 1e-4 m/s^2 of specific force,
    # 1e-2 m/s of velocity, 1e-5 in a direction cosine, 1e-8 rad/s of body rate
    tol = np.concatenate([np.full(3, 1e-4), np.full(3, 1e-2), np.full(9, 1e-5), np.full(3, 1e-8)])
    conds = np.concatenate(
        [trajectory.f_ned, trajectory.vel_ned, trajectory.C_bn.reshape(N, 9), omega_ib_b], axis=1
    )
    free = None if measurement_steps is None else ~np.asarray(measurement_steps, dtype=bool)
    # The control flow (where to relinearise, where a composite step fits) depends on the
    # flight condition alone: decide it first, then compute the transitions and noises of
    # every linearisation point in batches, and run the sequential loop on covariances only.
    plan, lin = _plan_steps(conds, tol, relinearize_every, free, stride, want)
    lin_arr = np.asarray(lin, dtype=np.intp)
    added = None if filter_added_psd is None else np.diag(np.asarray(filter_added_psd, dtype=float)) * dt

    def transitions(lo: int, working: bool = False) -> tuple[Array, Array, Array, Array]:
        """Transitions and discrete noises (truth, filter) of linearisation points ``lo:lo+chunk``
        in the layouts' own order, or with ``working`` in the working order defined below (the
        same values, computed from the permuted dynamics), shared with every other run whose
        linearisation points read the same values."""
        js = lin_arr[lo : lo + _LIN_CHUNK]
        args = {
            "f_ned": trajectory.f_ned[js],
            "C_bn": trajectory.C_bn[js],
            "omega_ib_b": omega_ib_b[js],
            "v_ned": trajectory.vel_ned[js],
            "lat": np.asarray(trajectory.lat, dtype=float)[js],
            "h": np.broadcast_to(np.asarray(trajectory.h, dtype=float), (N,))[js],
        }
        speed_js = speed[js]
        # every value the computation below reads, so two runs share a result only when it
        # would be the same
        order = order_t if working else None
        key = _digest((args, speed_js, truth_layout, src_list, vertical_channel, dt, idx, added, order))
        if key is not None and key in _TRANSITIONS:
            _TRANSITIONS.move_to_end(key)
            return _TRANSITIONS[key]
        F = _error_dynamics_stack(
            truth_layout, **args, sources=src_list[0], vertical_channel=vertical_channel
        )
        q = np.stack([_process_noise_diag_stack(truth_layout, s_, speed_js) for s_ in src_list], axis=1)
        if working:
            # permuting the dynamics permutes the transition and the noise (the working order
            # holds the filter's states as the block rows_f, in the filter's working order)
            F = F[:, order_t[:, None], order_t]
            q = q[:, :, order_t]
        Phi = _taylor_stack(F, dt)
        Q = _discrete_noise_diag(F, q, dt)  # (M, B, n_t, n_t)
        if working:
            Phi_f_ = np.ascontiguousarray(Phi[:, rows_f, rows_f])
            Qf = Q[:, :, rows_f, rows_f] + (0.0 if added is None else added[order_f[:, None], order_f])
        else:
            Phi_f_ = Phi[:, idx[:, None], idx]
            Qf = Q[:, :, idx[:, None], idx] + (0.0 if added is None else added)
        out = (Phi, Q, Phi_f_, Qf)
        if key is not None:
            _remember_transitions(key, out)
        return out

    # Work in a reordered state vector: the truth's unmodelled states whose transition or noise
    # is not trivial (ED), then the filter's states, those whose transition or noise is not
    # trivial in either model first (FD, then FS), then the remaining unmodelled states (ES).
    # The states after the first d of each model are random constants (unit transition row, no
    # noise), so a propagation transforms only the first d rows:
    # (Phi P Phi^T)[:d, :d] = X Phi_D^T, [:d, d:] = X[:, d:] with X = Phi[:d] P, and [d:, d:]
    # is P[d:, d:]: O(d n^2) instead of O(n^3). The filter's rows stay one contiguous block.
    # A chunk of linearisation points whose structure differs propagates in full.
    first = transitions(0)
    dyn_t = ~_static_states(first[0], first[1])
    dyn_f = ~_static_states(first[2], first[3]) | dyn_t[idx]
    order_f = np.r_[np.flatnonzero(dyn_f), np.flatnonzero(~dyn_f)]
    ext_dyn, ext_static = unmodelled[dyn_t[unmodelled]], unmodelled[~dyn_t[unmodelled]]
    order_t = np.r_[ext_dyn, idx[order_f], ext_static].astype(np.intp)
    back_t, back_f = np.argsort(order_t), np.argsort(order_f)
    d_f = int(dyn_f.sum())
    d_t = ext_dyn.size + d_f
    f0 = ext_dyn.size
    rows_f = slice(f0, f0 + n_f)
    unmod_p = np.r_[np.arange(f0), np.arange(f0 + n_f, n_t)].astype(np.intp)
    Pt = Pt[:, order_t[:, None], order_t]
    Pf = Pf[:, order_f[:, None], order_f]
    P0_uu = Pa[:, order_t[unmod_p][:, None], order_t[unmod_p]]

    def reordered(chunk: tuple[Array, Array, Array, Array], working: bool) -> tuple[Any, ...]:
        """A chunk's transitions in the working order (``working``: they already are), each
        model's with its transposed dynamic rows, or ``None`` where the chunk does not fit the
        structure."""
        Phi, Q, Phi_f_, Qf = chunk
        if not working:
            Phi = Phi[:, order_t[:, None], order_t]
            Q = Q[:, :, order_t[:, None], order_t]
            Phi_f_ = Phi_f_[:, order_f[:, None], order_f]
            Qf = Qf[:, :, order_f[:, None], order_f]
        if not (_static_states(Phi, Q)[d_t:].all() and _static_states(Phi_f_, Qf)[d_f:].all()):
            return Phi, Q, Phi_f_, Qf, None, None
        return (
            Phi,
            Q,
            Phi_f_,
            Qf,
            np.ascontiguousarray(np.swapaxes(Phi[:, :d_t, :], -1, -2)),
            np.ascontiguousarray(np.swapaxes(Phi_f_[:, :d_f, :], -1, -2)),
        )

    schedule_stacked = None if schedule is None else _stacked(schedule)
    L = stride
    lo, hi = 0, 0
    chunk: Any = None
    Phi_t: Any = None  # the transitions of the current linearisation (set at k = 1)
    Q_t: Any = None
    Phi_f: Any = None
    Q_f: Any = None
    DT_t: Any = None  # the transposed dynamic rows, or None (full propagation)
    DT_f: Any = None
    stride_cache: Any = None
    tv_p = np.empty((N, B, n_t))
    fv_p = np.empty((N, B, n_f))
    for k, li, kind in plan:
        if li >= 0:
            if li >= hi:
                lo, hi = li, li + _LIN_CHUNK
                chunk = reordered(first, False) if lo == 0 else reordered(transitions(lo, True), True)
            i = li - lo
            Phi_t, Q_t, Phi_f, Q_f = chunk[0][i], chunk[1][i], chunk[2][i], chunk[3][i]
            DT_t = None if chunk[4] is None else chunk[4][i]
            DT_f = None if chunk[5] is None else chunk[5][i]
            stride_cache = None
        if kind == 1:
            Pt = _propagate(Pt, Phi_t, Q_t, DT_t, d_t)
            Pf = _propagate(Pf, Phi_f, Q_f, DT_f, d_f)
        elif kind == 2:
            # L measurement-free steps under one linearisation: one composite step, and
            # the variances of the L - 1 samples it skips propagated exactly from its start
            j = k - L
            if stride_cache is None:
                PhiL, QL, QLf = np.eye(n_t), np.zeros_like(Q_t), np.zeros_like(Q_f)
                pw, qt, qf = [], [], []
                for _ in range(L):
                    PhiL = Phi_t @ PhiL
                    QL = Phi_t @ QL @ Phi_t.T + Q_t
                    QLf = Phi_f @ QLf @ Phi_f.T + Q_f
                    pw.append(PhiL)
                    qt.append(np.diagonal(QL, axis1=-2, axis2=-1))
                    qf.append(np.diagonal(QLf, axis1=-2, axis2=-1))
                powers = np.stack(pw[:-1])
                PhiLf = PhiL[rows_f, rows_f]
                stride_cache = (
                    _Propagator(PhiL, QL),
                    _Propagator(PhiLf, QLf),
                    powers,
                    np.ascontiguousarray(powers[:, rows_f, rows_f]),
                    np.stack(qt[:-1]),
                    np.stack(qf[:-1]),
                    None if DT_t is None else np.ascontiguousarray(PhiL[:d_t].T),
                    None if DT_f is None else np.ascontiguousarray(PhiLf[:d_f].T),
                )
            comp_t, comp_f, pw_t, pw_f, qd_t, qd_f, LT_t, LT_f = stride_cache
            tv_p[j + 1 : k] = comp_t.diagonals(Pt, pw_t, qd_t).transpose(1, 0, 2)
            fv_p[j + 1 : k] = comp_f.diagonals(Pf, pw_f, qd_f).transpose(1, 0, 2)
            Pt = _propagate(Pt, comp_t.Phi, comp_t.Q, LT_t, d_t)
            Pf = _propagate(Pf, comp_f.Phi, comp_f.Q, LT_f, d_f)
        if schedule_stacked is not None:
            meas = schedule_stacked(k)
            if meas is not None:
                Ht = meas[0][:, order_t]
                Rt = meas[1]
                Hf = Ht[:, rows_f]
                if inflate_filter_noise and unmod_p.size:
                    Hu = Ht[:, unmod_p]
                    Rf = Rt + Hu @ P0_uu @ Hu.T
                else:
                    Rf = Rt  # broadcast over the members in the sum below
                HP = Hf @ Pf  # (B, m, n_f)
                Sf = HP @ Hf.T + Rf
                K = np.linalg.solve(Sf, HP).transpose(0, 2, 1)  # (B, n_f, m)
                # optimal gain for the filter's own model: P+ = P - K S K^T (rank-m downdate)
                Pf = Pf - K @ HP
                # any gain for the truth: the Joseph form with the gain E K (K on the filter's
                # rows of the truth, zero elsewhere), expanded so that only those rows and
                # columns change; Pt is this step's own array, so it is changed in place, and
                # symmetrised below
                joseph_rows_unchecked(Pt, K, Ht, Rt, rows_f)
                counts[k] = Ht.shape[0]
        Pt = 0.5 * (Pt + Pt.transpose(0, 2, 1))
        Pf = 0.5 * (Pf + Pf.transpose(0, 2, 1))
        tv_p[k] = np.diagonal(Pt, axis1=1, axis2=2)
        fv_p[k] = np.diagonal(Pf, axis1=1, axis2=2)
        if k in want:
            for b in range(B):
                snaps[b][k] = Pt[b][np.ix_(back_t, back_t)]
    tv = tv_p[:, :, back_t].transpose(1, 0, 2)
    fv = fv_p[:, :, back_f].transpose(1, 0, 2)
    Pt = Pt[:, back_t[:, None], back_t]
    Pf = Pf[:, back_f[:, None], back_f]
    p = truth_layout.slice("position").start
    v = truth_layout.slice("velocity").start
    out = []
    for b in range(B):
        hp = np.sqrt(np.clip(tv[b, :, p] + tv[b, :, p + 1], 0.0, None))
        hv = np.sqrt(np.clip(tv[b, :, v] + tv[b, :, v + 1], 0.0, None))
        out.append(
            CovarianceAnalysis(
                trajectory.t,
                truth_layout,
                filter_layout,
                tv[b],
                fv[b],
                hp,
                hv,
                counts,
                snaps[b],
                Pt[b],
                Pf[b],
            )
        )
    return out if batch else out[0]


#: Transitions and discrete noises of linearisation points already computed, keyed on a digest
#: of every value they are computed from (:func:`_digest`); bounded in bytes, least recently
#: used first out. The band of a ledger claim runs a mission many times with inputs that leave
#: the flight, and so these matrices, unchanged (noise levels, the satellites tracked).
_TRANSITIONS: OrderedDict[bytes, tuple[Array, Array, Array, Array]] = OrderedDict()
_TRANSITIONS_MAX_BYTES = 192 * 2**20


def _remember_transitions(key: bytes, value: tuple[Array, Array, Array, Array]) -> None:
    for a in value:
        a.flags.writeable = False  # shared between runs: no run may change them in place
    _TRANSITIONS[key] = value
    total = sum(a.nbytes for v in _TRANSITIONS.values() for a in v)
    while total > _TRANSITIONS_MAX_BYTES and len(_TRANSITIONS) > 1:
        _, old = _TRANSITIONS.popitem(last=False)
        total -= sum(a.nbytes for a in old)


def _digest(obj: Any) -> bytes | None:
    """A digest of ``obj``'s exact value (arrays by dtype, shape and bytes, floats by their bits,
    dataclasses field by field), or ``None`` for a value it cannot spell exactly (no caching)."""
    h = hashlib.blake2b(digest_size=20)

    def feed(o: Any) -> None:
        if o is None or isinstance(o, bool | int | str):
            h.update(f"{type(o).__name__}:{o!r};".encode())
        elif isinstance(o, float):
            h.update(f"f:{o.hex()};".encode())
        elif isinstance(o, np.ndarray | np.generic):
            a = np.ascontiguousarray(o)
            if a.dtype.hasobject:
                raise TypeError
            h.update(f"a:{a.dtype.str}:{a.shape};".encode())
            h.update(a.tobytes())
        elif isinstance(o, tuple | list):
            h.update(f"{type(o).__name__}:{len(o)}(".encode())
            for x in o:
                feed(x)
            h.update(b")")
        elif isinstance(o, dict):
            h.update(f"d:{len(o)}(".encode())
            for k, v in o.items():
                feed(k)
                feed(v)
            h.update(b")")
        elif dataclasses.is_dataclass(o) and not isinstance(o, type):
            h.update(f"{type(o).__module__}.{type(o).__qualname__}(".encode())
            for f in dataclasses.fields(o):
                h.update(f.name.encode())
                feed(getattr(o, f.name))
            h.update(b")")
        else:
            raise TypeError

    try:
        feed(obj)
    except TypeError:
        return None
    return h.digest()


_GAUSS3 = np.polynomial.legendre.leggauss(3)
# linearisation points whose transitions are computed in one batch (bounds the memory of the
# (chunk, B, n, n) noise stack)
_LIN_CHUNK = 128


def _plan_steps(
    conds: Array,
    tol: Array,
    relinearize_every: int,
    free: NDArray[np.bool_] | None,
    stride: int,
    want: set[int],
) -> tuple[list[tuple[int, int, int]], list[int]]:
    """The control flow of :func:`run_covariance_analysis`, decided from the flight condition.

    Returns the steps ``(k, li, kind)`` the engine visits (``kind`` 0: the first sample, 1: a
    single step from ``k - 1``, 2: a composite step of ``stride`` samples ending at ``k``;
    ``li >= 0``: relinearise first, at the ``li``-th linearisation point) and the sample
    index ``j`` of each linearisation point. A step relinearises at the first sample, after
    ``relinearize_every`` steps, or when the condition ``conds[j]`` moves from the one of the
    last linearisation by more than ``tol``; a composite step needs ``stride - 1``
    measurement-free samples, no snapshot inside, and the condition within ``tol`` throughout.
    """
    N = conds.shape[0]
    L = stride
    plan: list[tuple[int, int, int]] = [(0, -1, 0)]
    lin: list[int] = []
    key_j, since = -1, 0
    moved: Any = None  # moved[i]: the condition at key_j + i is out of tolerance
    kept: Any = None  # kept[i]: the condition at key_j + i is within tolerance
    wants = sorted(want)
    k = 1
    while k < N:
        j = k - 1
        li = -1
        if key_j < 0 or since >= relinearize_every or moved[since]:
            lin.append(j)
            li = len(lin) - 1
            key_j, since = j, 0
            dev = np.abs(conds[j : j + relinearize_every + 1] - conds[j])
            moved = np.any(dev > tol, axis=1).tolist()
            kept = np.all(dev <= tol, axis=1)
        if (
            free is not None
            and L > 1
            and j + L < N
            and since + L <= relinearize_every
            and free[j + 1 : j + L].all()
            and not any(j < w < j + L for w in wants)
            and kept[since : since + L].all()
        ):
            since += L
            k = j + L
            plan.append((k, li, 2))
        else:
            since += 1
            plan.append((k, li, 1))
        k += 1
    return plan, lin


def _static_states(Phi: Array, Q: Array) -> NDArray[np.bool_]:
    """States whose transition row is the unit row and whose noise row is zero (random
    constants of the layout): their variances and mutual covariances do not propagate.
    ``Phi`` is one transition ``(n, n)`` or a stack ``(..., n, n)`` (the row must be the
    unit row in every member), ``Q`` one noise or a stack of them."""
    n = Phi.shape[-1]
    unit = np.all(Phi.reshape(-1, n, n) == np.eye(n), axis=(0, 2))
    quiet = ~np.any(Q.reshape(-1, n, n) != 0.0, axis=(0, 2))
    return unit & quiet


def _propagate(P: Array, Phi: Array, Q: Array, dyn_T: Array | None, d: int) -> Array:
    """``Phi P Phi^T + Q`` for a stack ``P`` ``(B, n, n)``, unchecked.

    With ``dyn_T`` (the transposed first ``d`` rows of ``Phi``, ``(n, d)``), the rows from
    ``d`` on are unit rows with no noise (:func:`_static_states`), and only the first ``d``
    rows and columns change: ``O(d n^2)`` instead of ``O(n^3)``; ``dyn_T=None`` propagates
    in full.
    """
    if dyn_T is None:
        return Phi @ P @ Phi.T + Q
    X = Phi[:d] @ P  # (B, d, n): the first d rows of Phi P
    out = P.copy()
    out[:, :d, :d] = X @ dyn_T + Q[..., :d, :d]
    out[:, :d, d:] = X[:, :, d:]
    out[:, d:, :d] = X[:, :, d:].transpose(0, 2, 1)
    return out


def _stacked(schedule: Schedule) -> Callable[[int], tuple[Array, Array] | None]:
    """``k -> (H, R)`` of the measurements ``schedule`` returns at step ``k`` (rows stacked,
    ``R`` block-diagonal), or ``None`` when there is none; a schedule built here supplies it
    directly as its ``stacked`` attribute."""
    direct = getattr(schedule, "stacked", None)
    if direct is not None:
        return direct

    def stacked(k: int) -> tuple[Array, Array] | None:
        meas = schedule(k)
        if not meas:
            return None
        return _stack_rows([(np.atleast_2d(m.H), np.atleast_2d(m.R)) for m in meas])

    return stacked


def _stack_rows(parts: Sequence[tuple[Array, Array]]) -> tuple[Array, Array]:
    """Rows of several measurements stacked, their noises on a block diagonal."""
    if len(parts) == 1:
        return parts[0]
    H = np.vstack([h for h, _ in parts])
    m_tot = H.shape[0]
    R = np.zeros((m_tot, m_tot))
    r0 = 0
    for _, Rb in parts:
        R[r0 : r0 + Rb.shape[0], r0 : r0 + Rb.shape[0]] = Rb
        r0 += Rb.shape[0]
    return H, R


class _Propagator:
    """A composite step's transition and noise (``Phi``, ``Q``; the step itself goes through
    :func:`_propagate`) and the diagonals of its intermediate samples (only the rows of the
    dynamic states are transformed there: a static state, with a unit transition row and no
    noise, keeps its variance exactly)."""

    def __init__(self, Phi: Array, Q: Array) -> None:
        self.n = Phi.shape[0]
        self.Phi, self.Q = Phi, Q
        self.D = np.flatnonzero(~_static_states(Phi, Q))

    def diagonals(self, P: Array, powers: Array, noise_diag: Array) -> Array:
        """``diag(Phi^i P Phi^iT) + diag(Q_i)`` for the stacked ``powers`` ``(L, n, n)`` of the
        transition and the diagonals ``(L, B, n)`` of their noise: ``(B, L, n)``."""
        B, n = P.shape[0], self.n
        L, D = powers.shape[0], self.D
        out = np.broadcast_to(np.diagonal(P, axis1=1, axis2=2)[:, None, :], (B, L, n)).copy()
        if D.size:
            rows = powers[:, D, :]  # the dynamic rows of every power, (L, d, n)
            # one small product per power and member ((d, n) by (n, n)), not one large one: a
            # large product goes multi-threaded in BLAS, which on a loaded machine waits for
            # cores far longer than it computes
            Y = rows[:, None] @ P[None]  # (L, B, d, n)
            var = np.einsum("lbkn,lkn->blk", Y, rows)
            out[:, :, D] = var + noise_diag.transpose(1, 0, 2)[:, :, D]
        return out


def discrete_noise(F: ArrayLike, S: ArrayLike, dt: float) -> Array:
    r""":math:`Q = \int_0^{\Delta t} \Phi(s) S \Phi(s)^T ds` by 3-point Gauss-Legendre quadrature.

    The 3-point rule integrates polynomials of degree 5 exactly, i.e. every term of the
    integrand up to the third power of ``F s``; the neglected terms are of relative size
    :math:`(\|F\| \Delta t)^6`.

    Parameters
    ----------
    F : (n, n) array
        Continuous-time system matrix, 1/s.
    S : (n, n) or (B, n, n) array
        White-noise PSD :math:`G Q G^T` (state unit squared per second), or a stack of them.
    dt : float
        Step, s.

    Returns
    -------
    ndarray
        Discrete process-noise covariance over ``dt``, same shape as ``S``, exactly symmetric.

    Notes
    -----
    The discretisation of the module docstring (Maybeck 1979, Ch. 4, reference 2 of the
    module).

    Examples
    --------
    A double integrator driven by white acceleration of PSD ``q``:

    >>> import numpy as np
    >>> Q = discrete_noise([[0.0, 1.0], [0.0, 0.0]], [[0.0, 0.0], [0.0, 2.0]], 0.5)
    >>> np.allclose(Q, 2.0 * np.array([[0.5**3 / 3, 0.5**2 / 2], [0.5**2 / 2, 0.5]]))
    True
    """
    return _discrete_noise(np.asarray(F, dtype=float), np.asarray(S, dtype=float), dt)


def _discrete_noise(F: Array, S: Array, dt: float) -> Array:
    """:func:`discrete_noise` without the argument checks (the engine's inner loop)."""
    x, w = _GAUSS3
    Q = np.zeros(S.shape)
    for xi, wi in zip(x, w, strict=True):
        P = _taylor(F, 0.5 * dt * (xi + 1.0))
        Q = Q + (0.5 * dt * wi) * (P @ S @ P.T)
    return 0.5 * (Q + np.swapaxes(Q, -1, -2))


def _discrete_noise_diag(F: Array, q: Array, dt: float) -> Array:
    """:func:`discrete_noise` of ``M`` systems ``F`` ``(M, n, n)``, each driven by ``B``
    diagonal PSDs ``diag(q[m, b])`` (``q``: ``(M, B, n)``), unchecked: ``(M, B, n, n)``.

    The same quadrature as :func:`discrete_noise` (``P S = P * q`` for a diagonal ``S``, exactly),
    computed where it can differ from zero: ``Phi(s) S Phi(s)^T`` reads only the driven columns
    of ``Phi(s)``, which are zero outside the rows of ``F`` that are not zero (the dynamic rows)
    and the driven states' own unit entries; the three nodes' products are one product over
    their stacked columns.
    """
    x, w = _GAUSS3
    M, B, n = q.shape
    Q = np.zeros((M, B, n, n))
    driven = np.flatnonzero(np.any(q != 0.0, axis=(0, 1)))  # only these columns of S are not 0
    if driven.size == 0:
        return Q
    dyn = np.flatnonzero(np.any(F != 0.0, axis=(0, 2)))
    rows = np.union1d(dyn, driven)  # the rows of Phi(s)[:, driven] that can be non-zero
    at_dyn = np.searchsorted(rows, dyn)
    static_driven = np.setdiff1d(driven, dyn)
    cols, parts = [], []
    for xi, wi in zip(x, w, strict=True):
        part = np.zeros((M, rows.size, driven.size))
        part[:, at_dyn, :] = _taylor_rows(F, 0.5 * dt * (xi + 1.0), dyn)[:, :, driven]
        # a driven random constant or random walk keeps its unit row
        part[:, np.searchsorted(rows, static_driven), np.searchsorted(driven, static_driven)] = 1.0
        parts.append(part)
        cols.append((0.5 * dt * wi) * q[:, :, None, driven])
    P = np.concatenate(parts, axis=-1)[:, None]  # (M, 1, r, 3 d)
    Qr = (P * np.concatenate(cols, axis=-1)) @ np.swapaxes(P, -1, -2)  # (M, B, r, r)
    Q[:, :, rows[:, None], rows] = 0.5 * (Qr + np.swapaxes(Qr, -1, -2))
    return Q


#: Highest power of the transition series the engine keeps (4 is exact for the nilpotent INS
#: error chains; a resolution, not an input: the tests check that 12 moves nothing).
_SERIES_ORDER = 4


def _taylor_rows(F: Array, dt: float, dyn: NDArray[np.intp]) -> Array:
    """The rows ``dyn`` of :func:`_taylor` of a stack ``(M, n, n)`` whose other rows are zero
    in every member (a zero row of ``F``, a random constant's, is a unit row of ``Phi``):
    ``(M, d, n)``.

    With ``F = [[a, b], [0, 0]]`` (dynamic rows first) the Horner step
    ``Phi <- I + F dt Phi / j`` keeps ``Phi = [[x, y], [0, I]]`` and updates
    ``[x, y] <- [I, 0] + (a dt [x, y] + [0, b dt]) / j``.
    """
    n = F.shape[-1]
    A = F[:, dyn, :] * dt  # (M, d, n)
    A_dd = A[:, :, dyn]
    A_ds = A.copy()
    A_ds[:, :, dyn] = 0.0  # the columns of the static states
    rows = np.eye(n)[dyn]
    X = rows
    for j in range(_SERIES_ORDER, 0, -1):
        X = rows + (A_dd @ X + A_ds) / j
    return X


def _taylor_stack(F: Array, dt: float) -> Array:
    """:func:`_taylor` of a stack ``(M, n, n)``, transforming only the rows of ``F`` that are
    not zero in any member (:func:`_taylor_rows`)."""
    n = F.shape[-1]
    dyn = np.flatnonzero(np.any(F != 0.0, axis=(0, 2)))
    Phi = np.zeros(F.shape)
    Phi[:, np.arange(n), np.arange(n)] = 1.0
    Phi[:, dyn, :] = _taylor_rows(F, dt, dyn)
    return Phi


def taylor_transition(F: ArrayLike, dt: float, order: int = 4) -> Array:
    r"""Transition :math:`\sum_{j \le \mathrm{order}} (F \Delta t)^j / j!` (Horner form).

    Parameters
    ----------
    F : (n, n) array
        Continuous-time system matrix, 1/s.
    dt : float
        Step, s.
    order : int, default 4
        Highest power kept (4 is exact for the nilpotent INS error chains).

    Returns
    -------
    (n, n) ndarray
        Truncated series of :math:`e^{F\,dt}`.

    Notes
    -----
    The discretisation of the module docstring (Maybeck 1979, Ch. 4, reference 2 of the
    module).

    Examples
    --------
    >>> taylor_transition([[0.0, 1.0], [0.0, 0.0]], 2.0).tolist()
    [[1.0, 2.0], [0.0, 1.0]]
    """
    return _taylor(np.asarray(F, dtype=float), dt, order)


def _taylor(F: Array, dt: float, order: int = 4) -> Array:
    """:func:`taylor_transition` without the argument checks (also of a stack ``(..., n, n)``)."""
    A = F * dt
    eye = np.eye(A.shape[-1])
    Phi = eye
    for j in range(order, 0, -1):
        Phi = eye + (A @ Phi) / j
    return Phi


def concatenate_analyses(parts: Sequence[CovarianceAnalysis]) -> CovarianceAnalysis:
    """Join consecutive analyses into one time series.

    Each part is resumed from the previous one's final covariances, so its first sample is the
    previous part's last one with that sample's measurements (if any) applied by the later
    part: the joined series takes the shared sample from the later part. A part that another
    resumes should therefore apply no measurement at its last sample, or the sample's
    measurements are applied twice. Snapshots keep their steps on the joined time axis (the
    later part's where both hold one at the shared sample).

    Parameters
    ----------
    parts : sequence of CovarianceAnalysis
        Analyses in time order, each starting where the previous ends.

    Returns
    -------
    CovarianceAnalysis
        The joined analysis (snapshot indices shifted to the joined time axis; final
        covariances of the last part).

    Raises
    ------
    ValueError
        If ``parts`` is empty or not consecutive in time.

    Examples
    --------
    >>> import dataclasses
    >>> import numpy as np
    >>> from navcore.inertial.error_dynamics import ErrorSources, ins_error_layout
    >>> from navcore.inertial.imu import ImuSpec
    >>> from navcore.inertial.trajectories import straight_and_level
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> src = ErrorSources(imu=ImuSpec("example", accel_bias=1e-3))
    >>> tr = straight_and_level(20.0, dt=1.0)
    >>> a = run_covariance_analysis(tr, lay, lay, src, np.eye(9))
    >>> later = dataclasses.replace(tr, t=tr.t + tr.t[-1])  # the next 20 s
    >>> b = run_covariance_analysis(later, lay, lay, src, a.final_true)
    >>> len(concatenate_analyses([a, b]).t) == 2 * len(a.t) - 1
    True
    """
    if not parts:
        raise ValueError("parts must not be empty")
    for a, b in itertools.pairwise(parts):
        if abs(b.t[0] - a.t[-1]) > 1e-9:
            raise ValueError("parts must be consecutive: each starts where the previous ends")

    def join(attr: str) -> Any:
        return np.concatenate([getattr(p, attr)[:-1] for p in parts[:-1]] + [getattr(parts[-1], attr)])

    snaps: dict[int, Array] = {}
    offset = 0
    for j, p in enumerate(parts):
        for k, v in p.snapshots.items():
            snaps[offset + k] = v
        offset += len(p.t) - 1
        if j == 0:
            offset = len(p.t) - 1
    last = parts[-1]
    return CovarianceAnalysis(
        join("t"),
        parts[0].truth_layout,
        parts[0].filter_layout,
        join("true_var"),
        join("filter_var"),
        join("horizontal_position"),
        join("horizontal_velocity"),
        join("n_updates"),
        snaps,
        last.final_true,
        last.final_filter,
    )


# --------------------------------------------------------------------------- GPS geometry


@dataclass(frozen=True)
class SatelliteGeometry:
    """Line-of-sight unit vectors (NED) and elevations of tracked channels over a trajectory.

    ``u_ned[k, c]`` points from the vehicle to the satellite of channel ``c`` at step ``k``.

    Attributes
    ----------
    prn : (c,) ndarray of int
        PRN of each channel.
    u_ned : (N, c, 3) ndarray
        Unit line-of-sight vectors in NED.
    elevation : (N, c) ndarray
        Elevations, rad.
    """

    prn: NDArray[np.int64]
    u_ned: Array
    elevation: Array


def satellite_geometry(
    trajectory: Trajectory, constellation: Constellation, channels: Sequence[int]
) -> SatelliteGeometry:
    """Vectorised line-of-sight geometry of satellites along a trajectory.

    Parameters
    ----------
    trajectory : Trajectory
        Sampled flight path (geodetic latitude and longitude in rad, height in m).
    constellation : Constellation
        Satellite orbits.
    channels : sequence of int
        Indices into the constellation of the tracked satellites.

    Returns
    -------
    SatelliteGeometry
        PRNs, NED unit vectors from vehicle to satellite ``(N, c, 3)`` and elevations ``(N, c)``
        in rad.

    Examples
    --------
    >>> from navcore.gnss.constellation import nominal_gps_constellation
    >>> from navcore.inertial.trajectories import straight_and_level
    >>> geo = satellite_geometry(straight_and_level(2.0), nominal_gps_constellation(), [0, 1])
    >>> geo.u_ned.shape, geo.elevation.shape
    ((3, 2, 3), (3, 2))
    """
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
        Times, s.
    n_channels : int
        Number of receiver channels.
    events : sequence of ``(time, channel, "code" | "carrier", locked)``
        From ``time`` (s) on, the channel's code or carrier is (un)locked. Events apply in
        time order, whatever their order in the list; events at the same time apply in the
        order listed, so the last of them sets the state.
    start_locked : bool, default True
        Lock state of every channel before its first event.

    Returns
    -------
    code : (N, n_channels) bool ndarray
        Code lock per step and channel.
    carrier : (N, n_channels) bool ndarray
        Carrier lock per step and channel.

    Raises
    ------
    ValueError
        If an event's kind is not ``"code"`` or ``"carrier"``.

    Examples
    --------
    >>> code, carrier = lock_table([0.0, 1.0, 2.0], 2, [(1.0, 0, "carrier", False)])
    >>> carrier.tolist()
    [[True, True], [False, True], [False, True]]
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


@implements("SP Sec. 2.2")
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
    g_load: NDArray[np.float64] | None = None,
) -> Schedule:
    r"""Pseudorange (code lock) and range rate (carrier lock) from each channel every ``every`` steps.

    Rows (truth layout): :math:`\delta\rho = -u \cdot \delta r + \delta b + b_{pr}[c]`, :math:`\delta\dot\rho
    = -u \cdot \delta v + \delta\dot b + b_{rr}[c]`,
    with ``u`` the NED line-of-sight unit vector to the satellite, ``dr`` (m) and ``dv`` (m/s)
    the NED position and velocity errors, ``db`` the clock bias error (m) and ``d(b_dot)`` the
    clock drift error (m/s). ``g_load`` enters the range-rate rows through the clock's
    g-sensitivity state, consistently with the clock-bias dynamics.

    Parameters
    ----------
    layout : StateLayout
        Truth layout (needs ``"position"`` and ``"velocity"``; clock, bias and g-sensitivity
        blocks enter when present).
    geometry : SatelliteGeometry
        Line-of-sight vectors and elevations of the channels.
    code : (N, n_channels) bool array
        Code lock per step and channel.
    carrier : (N, n_channels) bool array
        Carrier lock per step and channel.
    pseudorange_noise : float
        1-:math:`\sigma` white pseudorange noise per measurement, m (``> 0``).
    range_rate_noise : float
        1-:math:`\sigma` white range-rate noise per measurement, m/s (``> 0``).
    every : int, default 1
        Measure at every ``every``-th step.
    mask_rad : float, default 0.0
        Elevation mask, rad.
    g_load : (N,) array, optional
        Specific-force magnitude at each step, in g (dimensionless).

    Returns
    -------
    callable
        Schedule ``k -> list[Measurement]`` (one measurement with a pseudorange row per
        code-locked and a range-rate row per carrier-locked channel).

    Raises
    ------
    ValueError
        If ``pseudorange_noise`` or ``range_rate_noise`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.2 (tightly coupled architecture).

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.inertial.error_dynamics import ins_error_layout
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> u = np.array([[0.0, 0.0, -1.0], [0.6, 0.0, -0.8], [-0.6, 0.0, -0.8], [0.0, 0.6, -0.8],
    ...               [0.0, -0.6, -0.8]])
    >>> geo = SatelliteGeometry(np.arange(1, 6), u[None], np.arcsin(-u[None, :, 2]))
    >>> lock = np.ones((1, 5), dtype=bool)
    >>> m = tightly_coupled_schedule(lay, geo, lock, lock, pseudorange_noise=5.0,
    ...                              range_rate_noise=0.1)(0)[0]
    >>> m.H.shape
    (10, 9)
    """
    require_positive("pseudorange_noise", pseudorange_noise)
    require_positive("range_rate_noise", range_rate_noise)
    n = layout.size
    names = layout.names
    p0, v0 = layout.slice("position").start, layout.slice("velocity").start
    n_ch = geometry.u_ned.shape[1]
    i_b = layout.index("clock bias") if "clock bias" in names else None
    i_d = layout.index("clock drift") if "clock drift" in names else None
    i_pb = layout.slice("pseudorange bias").start if "pseudorange bias" in names else None
    i_rb = layout.slice("range-rate bias").start if "range-rate bias" in names else None
    i_g = (
        layout.index("clock g-sensitivity") if "clock g-sensitivity" in names and g_load is not None else None
    )
    use_code = code & (geometry.elevation >= mask_rad)
    use_carr = carrier & (geometry.elevation >= mask_rad)
    ch = np.arange(n_ch)
    # the rows that do not depend on the geometry, and R, per pattern of tracked channels
    patterns: dict[bytes, tuple[Array, Array, NDArray[np.intp], NDArray[np.intp]]] = {}

    def pattern(k: int) -> tuple[Array, Array, NDArray[np.intp], NDArray[np.intp]]:
        key = use_code[k].tobytes() + use_carr[k].tobytes()
        if key not in patterns:
            cc, cr = ch[use_code[k]], ch[use_carr[k]]
            H0 = np.zeros((cc.size + cr.size, n))
            rows = np.arange(cc.size)
            if i_b is not None:
                H0[rows, i_b] = 1.0
            if i_pb is not None:
                H0[rows, i_pb + cc] = 1.0
            rows = cc.size + np.arange(cr.size)
            if i_d is not None:
                H0[rows, i_d] = 1.0
            if i_rb is not None:
                H0[rows, i_rb + cr] = 1.0
            R = np.diag(np.r_[np.full(cc.size, pseudorange_noise**2), np.full(cr.size, range_rate_noise**2)])
            patterns[key] = (H0, R, cc, cr)
        return patterns[key]

    def stacked(k: int) -> tuple[Array, Array] | None:
        if k % every:
            return None
        H0, R, cc, cr = pattern(k)
        if cc.size + cr.size == 0:
            return None
        H = H0.copy()
        u = geometry.u_ned[k]
        H[: cc.size, p0 : p0 + 3] = -u[cc]
        H[cc.size :, v0 : v0 + 3] = -u[cr]
        if i_g is not None:
            H[cc.size :, i_g] = g_load[k]  # type: ignore[index]  # i_g is None when g_load is
        return H, R

    def sched(k: int) -> list[Measurement]:
        rows = stacked(k)
        return [] if rows is None else [Measurement._unchecked(*rows)]

    sched.stacked = stacked  # type: ignore[attr-defined]  # the engine's form: (H, R) or None
    return sched


@implements("SP Sec. 2.1")
def loosely_coupled_schedule(
    layout: StateLayout,
    geometry: SatelliteGeometry,
    code: NDArray[np.bool_],
    *,
    pseudorange_noise: float,
    interval_steps: int,
    max_ehe_m: float,
    pseudorange_bias_sigma: float = 0.0,
    mask_rad: float = 0.0,
) -> Schedule:
    r"""The receiver's position solution every ``interval_steps`` steps.

    A fix is used when at least four codes are tracked and the expected horizontal error is
    below ``max_ehe_m``. The receiver solves position and clock by least squares from the
    tracked pseudoranges, :math:`\delta r_{meas} = (G^T G)^{-1} G^T (b_{pr} + \text{noise})` with ``G = [-u,
    1]``: its
    position error is the position rows of that map applied to the per-channel biases (truth
    states) and to the noise, so the measurement is correlated with the pseudorange-bias
    states exactly as in the tightly coupled case. EHE is ``sigma_UERE * HDOP``.

    Parameters
    ----------
    layout : StateLayout
        Truth layout (needs ``"position"``; a ``"pseudorange bias"`` block enters when
        present).
    geometry : SatelliteGeometry
        Line-of-sight vectors and elevations of the channels.
    code : (N, n_channels) bool array
        Code lock per step and channel (see :func:`lock_table`).
    pseudorange_noise : float
        1-:math:`\sigma` white pseudorange noise, m (``> 0``).
    interval_steps : int
        Steps between fixes (``>= 1``; SP Sec. 2.1's filter takes one every 10 s).
    max_ehe_m : float
        Largest expected horizontal error accepted, m (``> 0``; SP Sec. 2.1: 100 m).
    pseudorange_bias_sigma : float, default 0.0
        1-:math:`\sigma` per-channel pseudorange bias, m (counts in the UERE of the EHE test).
    mask_rad : float, default 0.0
        Elevation mask, rad.

    Returns
    -------
    callable
        Schedule ``k -> list[Measurement]`` (one 3-row position measurement per fix).

    Raises
    ------
    ValueError
        If ``pseudorange_noise`` is not positive or ``pseudorange_bias_sigma`` is negative.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.1 (loosely coupled architecture).

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.inertial.error_dynamics import ins_error_layout
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> u = np.array([[0.0, 0.0, -1.0], [0.6, 0.0, -0.8], [-0.6, 0.0, -0.8], [0.0, 0.6, -0.8],
    ...               [0.0, -0.6, -0.8]])
    >>> geo = SatelliteGeometry(np.arange(1, 6), u[None], np.arcsin(-u[None, :, 2]))
    >>> lock = np.ones((1, 5), dtype=bool)
    >>> sched = loosely_coupled_schedule(lay, geo, lock, pseudorange_noise=5.0, interval_steps=10,
    ...                                  max_ehe_m=100.0)
    >>> m = sched(0)[0]
    >>> m.H.shape, round(float(m.R[2, 2]), 2)
    ((3, 9), 781.25)
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
        return [Measurement._unchecked(H, 0.5 * (R + R.T))]

    return sched


def baro_schedule(layout: StateLayout, *, noise_m: float, every: int = 1) -> Schedule:
    r"""Barometric altitude: ``dz = -dr_D - b_alt + noise`` (height = minus down).

    Parameters
    ----------
    layout : StateLayout
        Truth layout the rows refer to (needs a ``"position"`` block; an ``"altimeter bias"``
        block, if present, enters the row).
    noise_m : float
        1-:math:`\sigma` white altitude noise, m (``> 0``).
    every : int, default 1
        Measure at every ``every``-th step.

    Returns
    -------
    callable
        Schedule ``k -> list[Measurement]`` (one 1-row measurement on the steps it measures).

    Raises
    ------
    ValueError
        If ``noise_m`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6 (baro-aided INS).

    Examples
    --------
    >>> from navcore.inertial.error_dynamics import ins_error_layout
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> m = baro_schedule(lay, noise_m=3.0, every=10)
    >>> len(m(5)), m(10)[0].H[0, :3], m(10)[0].R
    (0, array([ 0.,  0., -1.]), array([[9.]]))
    """
    require_positive("noise_m", noise_m)
    H = np.zeros((1, layout.size))
    H[0, layout.index("position", 2)] = -1.0
    if "altimeter bias" in layout.names:
        H[0, layout.slice("altimeter bias")] = -1.0
    R = np.array([[noise_m**2]])

    def sched(k: int) -> list[Measurement]:
        return [] if k % every else [Measurement._unchecked(H, R)]

    sched.stacked = lambda k: None if k % every else (H, R)  # type: ignore[attr-defined]
    return sched


@implements("SP Table 2.8")
def doppler_schedule(
    layout: StateLayout,
    trajectory: Trajectory,
    *,
    noise_mps: float,
    every: int = 1,
    active: NDArray[np.bool_] | None = None,
) -> Schedule:
    r"""Doppler ground velocity in body axes.

    With the computed attitude :math:`\hat C^n_b = (I-[\psi\times])C^n_b`, the INS-predicted
    body velocity minus the Doppler reading is

    .. math::

        \delta z = C^b_n\,\delta v - C^b_n [v^n\times]\,\psi - b_d - \mathrm{diag}(v^b)\,s_d
        - [v^b\times]\,\mu_d + w.

    Parameters
    ----------
    layout : StateLayout
        Truth layout (needs ``"velocity"`` and ``"misalignment"``; the Doppler bias, scale
        factor and misalignment blocks enter when present).
    trajectory : Trajectory
        Flight path giving the attitude and velocity at each step.
    noise_mps : float
        1-:math:`\sigma` white noise per body axis, m/s (``> 0``).
    every : int, default 1
        Measure at every ``every``-th step.
    active : (N,) bool array, optional
        Steps at which the Doppler is available (default: all).

    Returns
    -------
    callable
        Schedule ``k -> list[Measurement]`` (one 3-row measurement on the steps it measures).

    Raises
    ------
    ValueError
        If ``noise_mps`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Table 2.8 (Doppler-aided INS).

    Examples
    --------
    >>> from navcore.inertial.trajectories import straight_and_level
    >>> from navcore.inertial.error_dynamics import ins_error_layout
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> tr = straight_and_level(10.0, speed=100.0)
    >>> m = doppler_schedule(lay, tr, noise_mps=0.1)(0)[0]
    >>> m.H.shape, round(float(m.R[0, 0]), 6)
    ((3, 9), 0.01)
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
        return [Measurement._unchecked(H, R)]

    return sched


def combine_schedules(*schedules: Schedule | None) -> Schedule:
    """A schedule that returns the measurements of all given schedules at each step.

    Parameters
    ----------
    *schedules : callable or None
        Schedules ``k -> list[Measurement]``; ``None`` entries are skipped.

    Returns
    -------
    callable
        Schedule returning, at step ``k``, the concatenated measurements of all schedules.

    Examples
    --------
    >>> from navcore.inertial.error_dynamics import ins_error_layout
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> both = combine_schedules(baro_schedule(lay, noise_m=3.0), None, baro_schedule(lay, noise_m=5.0))
    >>> len(both(0))
    2
    """
    live = [s for s in schedules if s is not None]
    parts = [_stacked(s) for s in live]
    # the block-diagonal noise of each combination of the parts' noise matrices (a schedule
    # built here returns the same R object for the same pattern; the key holds them alive)
    noises: dict[tuple[int, ...], tuple[tuple[Array, ...], Array]] = {}

    def sched(k: int) -> list[Measurement]:
        out: list[Measurement] = []
        for s in live:
            out.extend(s(k))
        return out

    def stacked(k: int) -> tuple[Array, Array] | None:
        rows = [r for r in (part(k) for part in parts) if r is not None]
        if len(rows) <= 1:
            return rows[0] if rows else None
        key = tuple(id(R) for _, R in rows)
        hit = noises.get(key)
        if hit is None or any(a is not b for a, (_, b) in zip(hit[0], rows, strict=True)):
            hit = (tuple(R for _, R in rows), _stack_rows(rows)[1])
            noises[key] = hit
        return np.vstack([H for H, _ in rows]), hit[1]

    sched.stacked = stacked  # type: ignore[attr-defined]  # the engine's form: (H, R) or None
    return sched


def circular_error_probable(P2: ArrayLike, p: float = 0.5) -> float:
    r"""Radius containing probability ``p`` of a zero-mean 2-D Gaussian with covariance ``P2``.

    With eigenvalues :math:`a, b` the probability inside radius :math:`r` is
    :math:`\frac{1}{2\pi}\int_0^{2\pi}\left(1-e^{-r^2/(2\rho^2(\phi))}\right)d\phi`,
    :math:`\rho^2 = a\cos^2\phi + b\sin^2\phi` (write the error as
    :math:`(\sqrt a\,s\cos\phi, \sqrt b\,s\sin\phi)` with a Rayleigh :math:`s` and a uniform
    :math:`\phi`); the integrand is smooth for any ellipse, a degenerate one included, so the
    rectangle rule over :math:`\phi` converges fast; the radius is found by bisection.

    Parameters
    ----------
    P2 : (2, 2) array
        Horizontal covariance, m².
    p : float, default 0.5
        Probability inside the circle, in (0, 1); 0.5 gives the CEP.

    Returns
    -------
    float
        Radius, m.

    Raises
    ------
    ValueError
        If ``P2`` is not 2x2 or ``p`` is not in (0, 1).

    Notes
    -----
    For a circular Gaussian the CEP is :math:`\sigma\sqrt{2\ln 2}` (Gelb 1974, reference 1 of
    the module, for the error-ellipse probabilities).

    Examples
    --------
    >>> import numpy as np
    >>> round(circular_error_probable(np.eye(2)), 6)
    1.17741
    """
    from scipy.optimize import brentq

    P2 = np.asarray(P2, dtype=float)
    if P2.shape != (2, 2):
        raise ValueError(f"P2 must be 2x2, got {P2.shape}")
    a, b = np.clip(np.linalg.eigvalsh(0.5 * (P2 + P2.T)), 0.0, None)
    if b == 0.0:
        return 0.0  # no error at all
    phi = np.linspace(0.0, 2 * np.pi, 2049)[:-1]
    rho2 = a * np.cos(phi) ** 2 + b * np.sin(phi) ** 2  # > 0 except along a degenerate axis

    def prob(r: float) -> float:
        arg = np.divide(r * r, 2.0 * rho2, out=np.full_like(rho2, np.inf), where=rho2 > 0.0)
        return float(np.mean(-np.expm1(-arg)))

    hi = 10.0 * np.sqrt(b)
    return float(brentq(lambda r: prob(r) - p, 0.0, hi, xtol=1e-12 * hi))


def best_geometry_channels(
    trajectory: Trajectory, constellation: Constellation, n: int = 4, mask_deg: float = 10.0
) -> NDArray[np.int64]:
    """The ``n`` satellites with the smallest mean PDOP above ``mask_deg`` for the whole trajectory.

    Brute force over the combinations of the satellites that stay visible; the PDOP is
    averaged over 12 samples spread evenly from the trajectory's first sample to its last
    (indices ``linspace(0, N - 1, 12)`` rounded down).

    Parameters
    ----------
    trajectory : Trajectory
        Sampled flight path.
    constellation : Constellation
        Satellite orbits.
    n : int, default 4
        Number of channels to choose (``> 0``).
    mask_deg : float, default 10.0
        Elevation mask, degrees.

    Returns
    -------
    (n,) ndarray of int
        Indices into the constellation of the chosen satellites.

    Raises
    ------
    ValueError
        If ``n`` is not positive.
    ModelDomainError
        If fewer than ``n`` satellites stay above the mask for the whole trajectory, or no
        combination of them gives a usable geometry (a ``ValueError``: the fixed channels this
        selection models do not exist for that flight).

    Examples
    --------
    >>> from navcore.gnss.constellation import nominal_gps_constellation
    >>> from navcore.inertial.trajectories import straight_and_level
    >>> tr = straight_and_level(60.0, speed=100.0, dt=10.0, lat0=0.5)
    >>> best_geometry_channels(tr, nominal_gps_constellation(), n=4).size
    4
    """
    from itertools import combinations

    require_positive("n", n)
    geo = satellite_geometry(trajectory, constellation, range(constellation.prn.size))
    always = np.flatnonzero(np.all(geo.elevation >= mask_deg * np.pi / 180, axis=0))
    if always.size < n:
        raise ModelDomainError(
            f"only {always.size} satellites stay above mask_deg={mask_deg} for the whole trajectory",
            case=(
                f"only {always.size} satellites stay above the {mask_deg:g} deg elevation mask "
                "for the whole flight"
            ),
        )
    ks = np.linspace(0, len(trajectory) - 1, 12).astype(int)
    best, best_val = None, np.inf
    for combo in combinations(always.tolist(), n):
        u = geo.u_ned[np.ix_(ks, np.asarray(combo, dtype=np.intp))]  # (K, n, 3)
        G = np.concatenate([-u, np.ones((*u.shape[:2], 1))], axis=-1)
        GtG = np.einsum("kni,knj->kij", G, G)
        if np.any(np.abs(np.linalg.det(GtG)) < 1e-9):
            continue
        Q = np.linalg.inv(GtG)
        val = float(np.mean(np.sqrt(Q[:, 0, 0] + Q[:, 1, 1] + Q[:, 2, 2])))
        if val < best_val:
            best, best_val = combo, val
    if best is None:
        raise ModelDomainError(
            "no satellite combination gives a usable geometry",
            case=f"no {n} satellites that stay above the mask give a usable geometry throughout the flight",
        )
    return np.asarray(best, dtype=np.int64)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "dt": POSITIVE,
        "mask_deg": Range(-90.0, 90.0),
        "p": OPEN_PROBABILITY,
        "n_channels": COUNT,
        "every": COUNT,
        "relinearize_every": COUNT,
        "stride": COUNT,
        "interval_steps": COUNT,
        "order": COUNT,
        "noise_m": NONNEGATIVE,
        "noise_mps": NONNEGATIVE,
        "pseudorange_noise": NONNEGATIVE,
        "range_rate_noise": NONNEGATIVE,
        "pseudorange_bias_sigma": NONNEGATIVE,
        "max_ehe_m": POSITIVE,
        "P2": COVARIANCE,
        "S": COVARIANCE_STACK,
        "P0_filter": COVARIANCE_STACK,
        "P0_apriori": COVARIANCE_STACK,
    },
)
