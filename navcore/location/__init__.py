"""Location.

Modules
-------
emitter
    frequency-of-arrival (Doppler) emitter location from a single moving aperture.
multilateration
    satellite multilateration geometry: unit vectors, the matrix F and its invariants.
clock_model
    stochastic model of a free-running aircraft clock.
clock_tracking
    tracking the aircraft clock to improve multilateration; three-satellite coasting.
target_location
    target location error from position error and attitude error over a lever arm.
"""
