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
    SI inside the library: metres, seconds, radians, :math:`\mathrm{m/s^2}`, rad/s, watts, hertz. Every
    number a model function takes or returns is SI unless its name or docstring says
    otherwise, and then it says the unit: in the name (``sigma_a_ug``, ``bandwidth_hz``,
    ``cn0_dbhz``, ``mask_deg``) or in the parameter's docstring line.
    Conversions from the papers' units (ft, nmi, deg/h, micro-g, ppm, dB ...) happen once, at
    the boundary, with the factors and functions of :mod:`navcore.units` (``x * units.FT``
    to go in, ``x / units.FT`` to come out; ``units.power_ratio_from_db``); a model never
    converts silently. Sensor noise follows one convention: angle random walk and velocity
    random walk are root PSDs in SI, :math:`\mathrm{rad}/\sqrt{\mathrm{s}}` and
    :math:`(\mathrm{m/s})/\sqrt{\mathrm{s}}` (``ImuSpec``); a datasheet ARW in
    :math:`\mathrm{deg}/\sqrt{\mathrm{h}}` or :math:`\mathrm{deg/h}/\sqrt{\mathrm{Hz}}` goes
    through ``units.DEG_PER_SQRT_H`` or
    ``units.DEG_PER_H_PER_SQRT_HZ`` (and
    :func:`navcore.inertial.imu.angle_random_walk_deg_per_sqrt_h` converts the one to the
    other). A value beyond what any sensor has (``ImuSpec(gyro_bias=1.0)``, 206 000 deg/h)
    is a unit mistake and raises.
Angles and ``deg=``
    An angle argument whose name carries no unit (``lat``, ``lon``, ``lat0``, ``roll``,
    ``pitch``, ``yaw``, ``heading``, ``az``, ``el``, ``mask``) is in radians, and every
    function that takes one has a keyword-only ``deg: bool = False``: with ``deg=True`` its
    angles, in and out, are in degrees. A name that carries its unit keeps it whatever
    ``deg`` says (``mask_deg``, ``cone_half_angle_deg``, ``misalignment_rad``). An angle out
    of range for its unit raises: a latitude or elevation outside [-90, 90] deg (45 given as
    radians), a longitude or azimuth outside [-360, 360] deg, a pitch outside [-90, 90] deg.
Frames
    ``e`` Earth-centred Earth-fixed, ``n`` local level North-East-Down, ``b`` body
    (x forward, y right, z down). ``C_bn`` (``mat_bn``) maps body coordinates to navigation
    coordinates: ``v_n = C_bn @ v_b``. Geodesy on an ellipsoid passed as ``ellipsoid=``
    (:data:`navcore.frames.WGS84` by default; :class:`navcore.frames.Ellipsoid` for any
    other); local frames at a geodetic origin are NED, or ENU (east, north, up) where a
    function says so; AER is azimuth from north towards east, elevation above the local
    horizontal plane and slant range (:mod:`navcore.frames`).
Stacks
    Conversions take stacks: a vector is ``(..., 3)``, a quaternion ``(..., 4)``, a rotation
    matrix ``(..., 3, 3)``, and angles, heights and origins arrays; leading axes broadcast
    (many points from one origin, or one origin per point). A function documented for one
    matrix rejects a stack of them, naming the argument.
Attitude
    Hamilton quaternions, scalar first ``q = [w, x, y, z]``, ``q ⊗ p`` the Hamilton product,
    ``v_n = q ⊗ v_b ⊗ q*``; Euler angles are roll, pitch, yaw in the 3-2-1 (z-y-x) sequence,
    pitch in [-90, 90] deg. A quaternion that rotates must be a unit quaternion and a
    direction-cosine matrix a proper rotation (``C C^T = I``, ``det C = +1``), both to within
    :math:`10^{-6}`; the quaternion algebra (product, conjugate, normalisation) takes any quaternion.
Attitude error
    The psi-angle error models (:mod:`navcore.inertial.error_dynamics`, SP's) write
    :math:`\hat C = (I - [\psi\times])\,C`, with the error defined as computed minus true;
    the 17-state model of KZL (:mod:`navcore.inertial.error_model17`) and
    :mod:`navcore.location.target_location` write :math:`\hat C = (I + [\delta\alpha\times])\,C`,
    so :math:`\delta\alpha = -\psi` (:func:`navcore.inertial.error_dynamics.psi_to_attitude_error`
    converts).
Lines of sight
    The receiver (user, aircraft, observer) is the first argument and the satellites or
    targets the second; a line of sight is the unit vector from the receiver to the
    satellite (:func:`navcore.gnss.constellation.line_of_sight`,
    :func:`navcore.location.multilateration.line_of_sight_matrix`). Dilutions of precision
    are computed in the receiver's local NED frame (:mod:`navcore.gnss.dop`).
Covariances
    Every covariance a function takes (``P``, ``P0``, ``Q``, ``R``, ``cov`` ...) is checked
    to be square, symmetric and positive semi-definite (definite where an inverse is
    needed); an infinite diagonal variance, where a function allows it, means "no
    information" (an outage). Schedules of measurements, and a time-varying transition or
    noise, are functions of the step index ``k`` alone (the time is ``t[k]``), in
    :func:`navcore.estimation.covariance.propagate_covariance` and
    :func:`navcore.integration.engine.run_covariance_analysis` alike. A Kalman
    update with no measurement (an epoch without satellites) returns the prior unchanged.
Detection
    The signal-to-noise ratio is per pulse, ``E/N0`` (signal energy over the one-sided noise
    density), a linear power ratio; the convention and the papers' mapping onto it (ATC-10's
    ``d`` is ``sqrt(2 E/N0)``) are stated once, in :mod:`navcore.detection.pulse_detection`.
Gravity
    The models take the gravity magnitude as an argument (``g``, ``gravity``); its default
    is the constant standard gravity ``units.G0``, which the papers assume. The WGS-84
    normal gravity with height is :func:`navcore.gravity.normal_gravity` (a constant is
    2.7 mg high at the equator and 2.6 mg low at the poles).
Names
    Parameters keep the paper's symbol where the model is the paper's equation (``x, P,
    Phi, Q, H, R`` in the Kalman filter; ``a3, b3`` the third-order loop coefficients of
    :math:`\omega_0 s^2` and :math:`\omega_0^2 s`, see
    :func:`navcore.gnss.tracking.third_order_noise_bandwidth_hz`). Quantities are named as
    the field names them, not as one paper does: the gyro bias (SP's "gyro drift"), the
    position dilution of precision (ATC-10's "geometric dilution"); the papers' names are
    listed on the book's notation page, not in the API. Error-state blocks have fixed names,
    enumerated by :class:`navcore.estimation.layout.InsBlock`; an unknown name (or a paper's
    name) raises and suggests the library's.
Options that remove part of a model
    are explicit keywords, never defaults that change a result silently; where one exists it
    is documented where it acts (``vertical_channel=False`` in
    :func:`navcore.inertial.error_dynamics.error_dynamics` zeroes the rows and columns of the
    vertical position and velocity errors, the horizontal-only model of an unaided INS).
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
    ranges and constraints: angles by unit, unit quaternions, rotation matrices,
    covariances); loops sized by an argument are bounded (``n_steps``, ``runs``... at most
    ``navcore._validate.MAX_LOOP_COUNT``). Each argument is checked once: the wrapper checks
    types, finiteness and the declared constraints, the body what the wrapper cannot see.
    Inner loops check their inputs once at their boundary and then call the kernels
    unchecked: with ``validate=False`` where a function offers it
    (:func:`navcore.estimation.kalman.kf_predict`), else through
    ``navcore._validate.unchecked`` (the Monte Carlo of
    :mod:`navcore.integration.ekf_ins_gnss`, the strapdown). Inputs each in range whose
    combination the model does not cover (no four satellites stay above the mask along the
    whole flight, for fixed channels) raise :class:`navcore.ModelDomainError`, a
    ``ValueError`` a caller can tell apart.
Parallel work
    Independent tasks (the ledger's claims, batches of Monte Carlo runs) go through one
    executor interface, :func:`navcore.parallel.run_tasks` (joblib: ``n_jobs=-1`` for every
    core, joblib's dask backend for a cluster); each task has its own seed, so serial,
    parallel and dask runs give the same numbers.

Subpackages
-----------
units, frames, gravity, estimation, inertial, gnss, detection, location
    the models;
papers
    one module per paper section: published inputs, claims, errata;
ledger
    the claim registry, its evaluation and rendering (``python -m navcore ledger``);
figures
    the figure registry (``python -m navcore figures``).
"""

from __future__ import annotations

from navcore._validate import ModelDomainError

__all__ = ["ModelDomainError", "__version__"]
__version__ = "0.1.0"
