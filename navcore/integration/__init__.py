"""Integration: the INS/GNSS filter and the covariance analysis of an aided INS.

Above :mod:`navcore.inertial` and :mod:`navcore.gnss`, which it combines with the generic
filtering of :mod:`navcore.estimation`.

Modules
-------
ekf_ins_gnss
    tightly coupled indirect feedback INS/GNSS EKF, batched over Monte Carlo runs.
measurement_rows
    the rows of the 17-state error model for code, Doppler, Euler-angle attitude and
    double-difference carrier-phase measurements.
engine
    truth-versus-filter covariance analysis of an aided INS over a flight (and the CEP of
    its horizontal covariance).
schedules
    measurement schedules of the engine: tightly and loosely coupled GPS, barometer, Doppler.
geometry
    GPS geometry along a flight: lines of sight, lock table, best channels.

Each module is imported from its own path (``from navcore.integration.engine import ...``).
"""
