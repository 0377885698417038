"""GNSS models.

Modules
-------
constellation
    a nominal 24-satellite GPS constellation, line of sight, elevation/azimuth, visibility.
dop
    dilution of precision (GDOP, PDOP, HDOP, VDOP, TDOP) with weights and an elevation mask.
measurements
    pseudorange and pseudorange-rate models and their Jacobians.
carrier_phase
    multi-antenna attitude: double-difference carrier phase and its covariance, the Euler-rate
    matrix (the 17-state rows are in :mod:`navcore.integration.measurement_rows`).
tracking
    third-order tracking loop responses to acceleration steps and jerks, aided bandwidth.
acquisition
    acquisition search time over a code-phase by Doppler uncertainty region.
antijam
    correlation and discriminators, effective :math:`C/N_0` and loss of lock under jamming,
    free-space J/S along a trajectory, CEP under jamming.
architectures
    INS/GPS integration architectures as named state layouts.
"""
