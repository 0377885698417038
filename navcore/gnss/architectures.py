"""INS/GPS integration architectures as named state layouts.

The state vectors of the three filters that Schmidt & Phillips compare (SP Tables 2.1-2.3)
are assembled here from reusable components, so that their sizes are computed rather than
typed: a GPS receiver's position-velocity-acceleration (PVA) filter, the loosely coupled
integration filter fed by that receiver's position, and the tightly coupled filter fed by
pseudorange and range rate.

Component blocks
----------------
``PVA``           position, velocity, acceleration (3 each)
``CLOCK``         user clock bias and drift (1 each)
``ALTIMETER``     barometric altimeter bias (1)
``INS_CORE``      position, velocity and misalignment error (3 each)
``IMU_ERRORS``    gyro bias, gyro scale factor, accelerometer bias and scale factor (3 each)

References
----------
.. [SP] G. T. Schmidt and R. E. Phillips, "INS/GPS Integration Architecture Performance
   Comparisons", NATO RTO-EN-SET-116, Sec. 2.1-2.2, Tables 2.1-2.3.
"""

from __future__ import annotations

from navcore._validate import check_public
from navcore.estimation.layout import StateBlock, StateLayout
from navcore.trace import implements

__all__ = [
    "ALTIMETER",
    "CLOCK",
    "IMU_ERRORS",
    "INS_CORE",
    "PVA",
    "loosely_coupled_layout",
    "receiver_pva_layout",
    "tightly_coupled_layout",
]

PVA = StateLayout.of(
    StateBlock("position", 3, "m"),
    StateBlock("velocity", 3, "m/s"),
    StateBlock("acceleration", 3, "m/s^2"),
    name="PVA",
)
CLOCK = StateLayout.of(StateBlock("clock bias", 1, "m"), StateBlock("clock drift", 1, "m/s"), name="clock")
ALTIMETER = StateLayout.of(StateBlock("altimeter bias", 1, "m"), name="altimeter")
INS_CORE = StateLayout.of(
    StateBlock("position", 3, "m"),
    StateBlock("velocity", 3, "m/s"),
    StateBlock("misalignment", 3, "rad"),
    name="INS core",
)
IMU_ERRORS = StateLayout.of(
    StateBlock("gyro bias", 3, "rad/s"),
    StateBlock("gyro scale factor", 3, "-"),
    StateBlock("accel bias", 3, "m/s^2"),
    StateBlock("accel scale factor", 3, "-"),
    name="IMU errors",
)


@implements("SP Table 2.1")
def receiver_pva_layout() -> StateLayout:
    """States of a GPS receiver's own PVA Kalman filter (SP Table 2.1).

    Position, velocity and acceleration, the user clock, and an altimeter bias.

    Returns
    -------
    StateLayout
        Named blocks with sizes and units.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Table 2.1.

    Examples
    --------
    >>> receiver_pva_layout().size
    12
    """
    return StateLayout((PVA + CLOCK + ALTIMETER).blocks, "GPS receiver (PVA)")


@implements("SP Table 2.2")
def loosely_coupled_layout() -> StateLayout:
    """Error states of the loosely coupled integration filter (SP Table 2.2).

    The INS core errors, the IMU sensor errors and the altimeter bias; the clock stays in
    the receiver's filter, which is why it is absent here.

    Returns
    -------
    StateLayout
        Named blocks with sizes and units.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Table 2.2.

    Examples
    --------
    >>> loosely_coupled_layout().size
    22
    """
    return StateLayout((INS_CORE + IMU_ERRORS + ALTIMETER).blocks, "loosely coupled")


@implements("SP Table 2.3")
def tightly_coupled_layout() -> StateLayout:
    """Error states of the tightly coupled integration filter (SP Table 2.3).

    The loosely coupled states plus the user clock bias and drift, which the pseudorange and
    range-rate measurements observe directly. The paper's row order (clock after velocity)
    is kept.

    Returns
    -------
    StateLayout
        Named blocks with sizes and units.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Table 2.3.

    Examples
    --------
    >>> tightly_coupled_layout().size - loosely_coupled_layout().size
    2
    """
    core = INS_CORE.blocks
    return StateLayout(
        core[:2] + CLOCK.blocks + core[2:] + IMU_ERRORS.blocks + ALTIMETER.blocks, "tightly coupled"
    )


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals())
