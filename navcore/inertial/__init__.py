r"""Inertial navigation.

Modules
-------
imu
    IMU error specifications as data (SI units).
strapdown
    strapdown mechanization in a local-level NED frame, batched over runs.
alignment
    accelerometer levelling and heading from GPS velocity.
error_dynamics
    :math:`\psi`-angle INS error dynamics with Schuler, Earth rate, transport rate, sensor and
    Gauss-Markov states.
error_model17
    the 17-state error model of a low-cost tightly coupled INS/GNSS filter.
residual_acceleration
    residual acceleration seen by an aided tracking loop; Gaussian sphere radii.
trajectories
    vehicle trajectories built from kinematic segments.
"""
