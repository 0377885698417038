"""navcore: the models of four navigation and surveillance papers, and their ledger.

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
    SI inside the library: metres, seconds, radians, m/s^2, rad/s, watts, hertz.
    Conversions from the papers' units (ft, nmi, deg/h, micro-g, ppm, dB ...) happen at the
    boundary with the factors of :mod:`navcore.units`; a parameter that is not SI says its
    unit in its name (``sigma_a_ug``, ``bandwidth_hz``) or its docstring.
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
    Bad input raises ``ValueError`` naming the parameter and the constraint.

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
