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

Measurements are supplied per time step by schedule functions
(:mod:`navcore.integration.schedules`, ``k -> list of Measurement`` over the *truth* layout);
the satellites they read come from :mod:`navcore.integration.geometry`. The truth's update
is the Joseph form of :func:`navcore.estimation.kalman.joseph_update` with the filter's gain on
the filter's rows of the truth. The circular error probable of a horizontal covariance,
:func:`circular_error_probable`, summarises the engine's output.

Discretisation: :math:`\Phi = \sum_{j\le 4} (F\Delta t)^j/j!` (exact for the
nilpotent chains gyro bias -> attitude -> velocity -> position) and
:math:`Q = \int_0^{\Delta t}\Phi(s)\,GQG^T\Phi(s)^T ds` by Gauss-Legendre quadrature
(:func:`navcore.estimation.discretize.discretize` with ``method="series"``, in its row-sparse
form for diagonal noise and the rows that move, ``discretize_unchecked(..., sparse=True)``: the
engine holds no series or quadrature of its own), relinearised whenever the flight condition
changes (1-s and 10-s steps are far below the 84-min Schuler period).

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
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    COVARIANCE,
    COVARIANCE_STACK,
    OPEN_PROBABILITY,
    check_public,
    require_positive,
    require_symmetric_psd,
)
from navcore.estimation.discretize import discretize_unchecked
from navcore.estimation.kalman import joseph_rows_unchecked
from navcore.estimation.layout import StateLayout
from navcore.inertial.error_dynamics import (
    ErrorSources,
    _error_dynamics_stack,
    _process_noise_diag_stack,
    earth_rate_ned,
    transport_rate_ned,
)
from navcore.inertial.trajectories import Trajectory
from navcore.integration.schedules import Schedule, stacked_measurements
from navcore.trace import implements

__all__ = [
    "CovarianceAnalysis",
    "circular_error_probable",
    "concatenate_analyses",
    "embedding",
    "run_covariance_analysis",
]

Array = NDArray[np.float64]


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
        # the series discretisation in its row-sparse form: Phi (M, 1, n_t, n_t), Q (M, B, n_t, n_t)
        Phi, Q = discretize_unchecked(
            F[:, None], q, dt, method="series", diagonal=True, sparse=True, order=_SERIES_ORDER
        )
        Phi = Phi[:, 0]
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

    schedule_stacked = None if schedule is None else stacked_measurements(schedule)
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


#: Highest power of the transition series the engine keeps (4 is exact for the nilpotent INS
#: error chains; a resolution, not an input: the tests check that 12 moves nothing).
_SERIES_ORDER = 4


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


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "p": OPEN_PROBABILITY,
        "relinearize_every": COUNT,
        "stride": COUNT,
        "P2": COVARIANCE,
        "P0_filter": COVARIANCE_STACK,
        "P0_apriori": COVARIANCE_STACK,
    },
)
