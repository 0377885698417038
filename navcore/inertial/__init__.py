"""Inertial navigation: IMU error specifications, strapdown mechanization, INS error-state
dynamics, initial alignment."""
