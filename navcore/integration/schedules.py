r"""Measurement schedules of an aided INS for the covariance engine.

A schedule is a function of the step index, ``k -> list of Measurement``
(:class:`~navcore.estimation.covariance.Measurement`, rows over the *truth* layout), the
measurements available at ``t[k]``. The schedules built here: tightly coupled pseudorange
and range rate from each tracked channel, the loosely coupled receiver position every 10 s
when at least four codes are tracked and the expected horizontal error is small enough,
barometric altitude, and Doppler ground speed in body axes. Each of them (and
:func:`combine_schedules` of them) also hands the engine
(:func:`navcore.integration.engine.run_covariance_analysis`) its rows already stacked,
``schedule.stacked(k)`` giving ``(H, R)`` or ``None``; a schedule of one's own needs only the
call ``k -> list of Measurement``.

References
----------
.. [1] G. T. Schmidt and R. E. Phillips, NATO RTO-EN-SET-116, Sec. 2.1-2.6.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from navcore._validate import (
    COUNT,
    COUNT0,
    NONNEGATIVE,
    POSITIVE,
    check_public,
    require_nonnegative,
    require_positive,
)
from navcore.estimation.covariance import Measurement
from navcore.estimation.layout import StateLayout
from navcore.inertial.trajectories import Trajectory
from navcore.integration.geometry import SatelliteGeometry
from navcore.trace import implements

__all__ = [
    "baro_schedule",
    "combine_schedules",
    "doppler_schedule",
    "loosely_coupled_schedule",
    "tightly_coupled_schedule",
    "without_step",
]

Array = NDArray[np.float64]
Schedule = Callable[[int], Sequence[Measurement]]


def stacked_measurements(schedule: Schedule) -> Callable[[int], tuple[Array, Array] | None]:
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
        Code lock per step and channel (see :func:`~navcore.integration.geometry.lock_table`).
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
    parts = [stacked_measurements(s) for s in live]
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


def without_step(schedule: Schedule, step: int) -> Schedule:
    """``schedule`` with no measurement at step ``step`` (the same measurements elsewhere).

    A phase of a covariance analysis that another phase resumes from its last sample leaves
    that sample's measurements to the resumed phase, so that they are processed once.

    Parameters
    ----------
    schedule : callable
        Schedule ``k -> list[Measurement]``.
    step : int
        The step index whose measurements are dropped (``>= 0``).

    Returns
    -------
    callable
        Schedule returning ``[]`` at ``step`` and ``schedule(k)`` at every other step.

    Raises
    ------
    ValueError
        If ``step`` is negative or not an integer.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6 (the missions of Figs. 2.4-2.8, evaluated in phases).

    Examples
    --------
    >>> from navcore.inertial.error_dynamics import ins_error_layout
    >>> baro = baro_schedule(ins_error_layout("position", "velocity"), noise_m=3.0)
    >>> cut = without_step(baro, 2)
    >>> len(cut(1)), len(cut(2))
    (1, 0)
    """

    def sched(k: int) -> Sequence[Measurement]:
        return [] if k == step else schedule(k)

    return sched


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "every": COUNT,
        "interval_steps": COUNT,
        "noise_m": NONNEGATIVE,
        "noise_mps": NONNEGATIVE,
        "pseudorange_noise": NONNEGATIVE,
        "range_rate_noise": NONNEGATIVE,
        "pseudorange_bias_sigma": NONNEGATIVE,
        "max_ehe_m": POSITIVE,
        "step": COUNT0,
    },
)
