"""GNSS models: constellations and line-of-sight geometry, pseudorange, delta-range and
double-difference carrier-phase measurements, DOP, tracking loops, acquisition, jamming.

Modules
-------
architectures
    INS/GPS integration architectures as named state layouts.
"""
