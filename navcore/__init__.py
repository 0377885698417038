r"""navcore: the models of four navigation and surveillance papers, and their ledger.

The package implements, by model rather than by paper, what the verification book
re-derives from

- [WF]    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy";
- [SP]    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons";
- [ATC10] Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
          Management System", MIT Lincoln Laboratory ATC-10 (1972);
- [KZL]   Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing
          with Bistatic SAR" (2009).

Conventions (every module follows them unless its docstring says otherwise)
---------------------------------------------------------------------------
Units
    SI inside the library: metres, seconds, radians, m/s^2, rad/s, watts, hertz. Every
    number a model function takes or returns is SI unless its name or docstring says
    otherwise, and then it says the unit: in the name (``sigma_a_ug``, ``bandwidth_hz``,
    ``cn0_dbhz``, ``mask_deg``) or in the parameter's docstring line.
    Conversions from the papers' units (ft, nmi, deg/h, micro-g, ppm, dB ...) happen once, at
    the boundary, with the factors and functions of :mod:`navcore.units` (``x * units.FT``
    to go in, ``x / units.FT`` to come out; ``units.power_ratio_from_db``); a model never
    converts silently. Sensor noise follows one convention: angle random walk and velocity
    random walk are root PSDs in SI, rad/sqrt(s) and (m/s)/sqrt(s) (``ImuSpec``); a datasheet
    ARW in deg/sqrt(h) or deg/h/sqrt(Hz) goes through ``units.DEG_PER_SQRT_H`` or
    ``units.DEG_PER_H_PER_SQRT_HZ`` (and
    :func:`navcore.inertial.imu.angle_random_walk_deg_per_sqrt_h` converts the one to the
    other).
Names
    Parameters keep the paper's symbol where the model is the paper's equation (``x, P,
    Phi, Q, H, R`` in the Kalman filter; ``a3, b3`` the third-order loop coefficients of
    :math:`\omega_0 s^2` and :math:`\omega_0^2 s`, see
    :func:`navcore.gnss.tracking.third_order_noise_bandwidth_hz`). Error-state blocks have
    fixed names, enumerated by :class:`navcore.estimation.layout.InsBlock` ("gyro drift" is
    the gyro bias); an unknown name raises and suggests the closest one.
Options that remove part of a model
    are explicit keywords, never defaults that change a result silently; where one exists it
    is documented where it acts (``vertical_channel=False`` in
    :func:`navcore.inertial.error_dynamics.error_dynamics` zeroes the rows and columns of the
    vertical position and velocity errors, the horizontal-only model of an unaided INS).
Frames
    ``e`` Earth-centred Earth-fixed (WGS-84), ``n`` local level North-East-Down, ``b`` body
    (x forward, y right, z down). ``C_bn`` (``mat_bn``) maps body coordinates to navigation
    coordinates: ``v_n = C_bn @ v_b``.
Attitude
    Hamilton quaternions, scalar first ``q = [w, x, y, z]``, ``q ⊗ p`` the Hamilton product,
    ``v_n = q ⊗ v_b ⊗ q*``; Euler angles are roll, pitch, yaw in the 3-2-1 (z-y-x) sequence.
Noise
    White-noise intensities are power spectral densities (two-sided, per Hz) unless stated;
    random walks are given by their root PSD.
Randomness
    Only ``numpy.random.default_rng(seed)``; every stochastic function takes a ``seed`` or a
    ``Generator`` and results record the seed.
Errors
    Bad input raises ``ValueError`` (a value out of range, a NaN, a wrong shape) or
    ``TypeError`` (a wrong type) whose message names the parameter as the caller spelled it
    and the constraint. Every public function of the models checks its arguments at entry
    (``navcore._validate.checked``, from the annotations and a per-module table of
    ranges); loops sized by an argument are bounded (``n_steps``, ``runs``... at most
    ``navcore._validate.MAX_LOOP_COUNT``). Each argument is checked once: the wrapper checks
    types and finiteness, the body what the wrapper cannot see (shapes, symmetry,
    definiteness). Inner loops check their inputs once at their boundary and then call the
    kernels unchecked: with ``validate=False`` where a function offers it
    (:func:`navcore.estimation.kalman.kf_predict`), else through
    ``navcore._validate.unchecked`` (the Monte Carlo of
    :mod:`navcore.estimation.ekf_ins_gnss`, the strapdown).
Parallel work
    Independent tasks (the ledger's claims, batches of Monte Carlo runs) go through one
    executor interface, :func:`navcore.parallel.run_tasks` (joblib: ``n_jobs=-1`` for every
    core, joblib's dask backend for a cluster); each task has its own seed, so serial,
    parallel and dask runs give the same numbers.

Subpackages
-----------
units, frames, estimation, inertial, gnss, detection, location
    the models;
papers
    one module per paper section: published inputs, claims, errata;
ledger
    the claim registry, its evaluation and rendering (``python -m navcore ledger``);
figures
    the figure registry (``python -m navcore figures``).
"""

from __future__ import annotations

__all__ = ["__version__"]
__version__ = "0.1.0"
