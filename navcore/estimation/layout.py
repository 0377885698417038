"""Named state layouts: a state vector as an ordered list of named blocks.

One layout object replaces the index constants that filters otherwise scatter around
(``IDX_POS = slice(0, 3)``...). Blocks are named, sized and ordered; a layout knows its
slices, its size and its set of blocks, and layouts combine by concatenation.

Examples
--------
>>> ins = StateLayout.of(("position", 3), ("velocity", 3), ("misalignment", 3))
>>> ins.size, ins.slice("velocity")
(9, slice(3, 6, None))
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from enum import StrEnum

from navcore._validate import check_public

__all__ = ["INS_BLOCK_SYNONYMS", "InsBlock", "StateBlock", "StateLayout", "ins_block_name"]


class InsBlock(StrEnum):
    """The names of the INS/GNSS error-state blocks that navcore's error models know.

    A member is a ``str``, so ``InsBlock.GYRO_BIAS == "gyro bias"`` and either spelling
    may be passed wherever a block name is expected (for instance to
    :func:`navcore.inertial.error_dynamics.ins_error_layout`). The sizes and units are in
    the table of :mod:`navcore.inertial.error_dynamics`. The names are the field's: the
    papers' "gyro drift" is the random-constant gyro bias (rad/s), named ``gyro bias`` here
    (the papers' names are aliases on the book's notation page, not in the API: a paper name
    raises and suggests navcore's).
    """

    POSITION = "position"
    VELOCITY = "velocity"
    MISALIGNMENT = "misalignment"
    GYRO_BIAS = "gyro bias"
    GYRO_SCALE_FACTOR = "gyro scale factor"
    GYRO_MISALIGNMENT = "gyro misalignment"
    ACCEL_BIAS = "accel bias"
    ACCEL_SCALE_FACTOR = "accel scale factor"
    ACCEL_MISALIGNMENT = "accel misalignment"
    GRAVITY = "gravity"
    ALTIMETER_BIAS = "altimeter bias"
    CLOCK_BIAS = "clock bias"
    CLOCK_DRIFT = "clock drift"
    CLOCK_G_SENSITIVITY = "clock g-sensitivity"
    PSEUDORANGE_BIAS = "pseudorange bias"
    RANGE_RATE_BIAS = "range-rate bias"
    DOPPLER_BIAS = "doppler bias"
    DOPPLER_SCALE_FACTOR = "doppler scale factor"
    DOPPLER_MISALIGNMENT = "doppler misalignment"


#: Common other names of the INS blocks (and the papers' names), mapped to navcore's name;
#: used in error messages ("did you mean ...?"), never substituted silently.
INS_BLOCK_SYNONYMS: dict[str, InsBlock] = {
    "gyro drift": InsBlock.GYRO_BIAS,
    "gyro drifts": InsBlock.GYRO_BIAS,
    "gyro biases": InsBlock.GYRO_BIAS,
    "accelerometer bias": InsBlock.ACCEL_BIAS,
    "accel drift": InsBlock.ACCEL_BIAS,
    "attitude": InsBlock.MISALIGNMENT,
    "attitude error": InsBlock.MISALIGNMENT,
    "tilt": InsBlock.MISALIGNMENT,
    "psi": InsBlock.MISALIGNMENT,
    "accelerometer scale factor": InsBlock.ACCEL_SCALE_FACTOR,
    "accelerometer misalignment": InsBlock.ACCEL_MISALIGNMENT,
    "clock offset": InsBlock.CLOCK_BIAS,
    "clock frequency": InsBlock.CLOCK_DRIFT,
}


def _suggestion(name: str, known: list[str]) -> str:
    hint = INS_BLOCK_SYNONYMS.get(name.strip().lower()) if isinstance(name, str) else None
    if hint is not None and hint.value in known:
        return f"; did you mean {hint.value!r}?"
    close = difflib.get_close_matches(name, known, n=1) if isinstance(name, str) else []
    return f"; did you mean {close[0]!r}?" if close else ""


def ins_block_name(name: str, *, argument: str = "name") -> InsBlock:
    """Return the :class:`InsBlock` called ``name``, or raise naming the closest one.

    Parameters
    ----------
    name : str
        A block name (``"gyro bias"``) or an :class:`InsBlock` member.
    argument : str, default "name"
        How the caller's parameter is spelled, for the error message.

    Returns
    -------
    InsBlock
        The block.

    Raises
    ------
    TypeError
        If ``name`` is not a string.
    ValueError
        If ``name`` is not a block name; the message suggests the closest one, and the
        navcore name of common synonyms and of the papers' names (``"gyro drift"`` is
        ``"gyro bias"``).

    Examples
    --------
    >>> ins_block_name("gyro bias")
    <InsBlock.GYRO_BIAS: 'gyro bias'>
    >>> try:
    ...     ins_block_name("gyro drift")
    ... except ValueError as exc:
    ...     print(str(exc).split("; ")[1])
    did you mean 'gyro bias'?
    """
    if not isinstance(name, str):
        raise TypeError(f"{argument} must be a string (a block name), got {name!r}")
    try:
        return InsBlock(name)
    except ValueError:
        known = [b.value for b in InsBlock]
        raise ValueError(
            f"{argument} must be among {known}, got {name!r}{_suggestion(name, known)}"
        ) from None


@dataclass(frozen=True)
class StateBlock:
    """A named block of ``size`` consecutive states (``unit`` of each component).

    Attributes
    ----------
    name : str
        Block name (an :class:`InsBlock` value for INS error states).
    size : int
        Number of states.
    unit : str
        Unit of each component (e.g. ``"m"``, ``"rad"``).
    description : str
        Free text.
    """

    name: str
    size: int
    unit: str = ""
    description: str = ""

    def __post_init__(self) -> None:
        # the public-API check has made sure that name is a str and size an int (not a bool)
        if not self.name:
            raise ValueError(f"StateBlock.name must be a non-empty string, got {self.name!r}")
        if self.size < 1:
            raise ValueError(f"StateBlock.size must be an integer >= 1, got {self.size!r}")


@dataclass(frozen=True)
class StateLayout:
    """An ordered tuple of uniquely named :class:`~navcore.estimation.layout.StateBlock` objects.

    Attributes
    ----------
    blocks : tuple of StateBlock
        The blocks in state order.
    name : str
        Name of the layout.
    """

    blocks: tuple[StateBlock, ...]
    name: str = ""

    def __post_init__(self) -> None:
        names = [b.name for b in self.blocks]
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise ValueError(f"blocks must have unique names, duplicated: {sorted(dup)}")

    @classmethod
    def of(cls, *blocks: tuple[str, int] | StateBlock, name: str = "") -> StateLayout:
        """Build a layout from ``(name, size)`` pairs or blocks."""
        return cls(tuple(b if isinstance(b, StateBlock) else StateBlock(*b) for b in blocks), name)

    @property
    def size(self) -> int:
        """Total number of states."""
        return sum(b.size for b in self.blocks)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(b.name for b in self.blocks)

    def block(self, name: str) -> StateBlock:
        for b in self.blocks:
            if b.name == name:
                return b
        raise ValueError(
            f"name must be one of {list(self.names)}, got {name!r}{_suggestion(name, list(self.names))}"
        )

    def slice(self, name: str) -> slice:
        """The slice of block ``name`` in the state vector."""
        start = 0
        for b in self.blocks:
            if b.name == name:
                return slice(start, start + b.size)
            start += b.size
        raise ValueError(
            f"name must be one of {list(self.names)}, got {name!r}{_suggestion(name, list(self.names))}"
        )

    def index(self, name: str, component: int = 0) -> int:
        """Index of component ``component`` of block ``name``."""
        sl = self.slice(name)
        if not 0 <= component < sl.stop - sl.start:
            raise ValueError(f"component must be in [0, {sl.stop - sl.start}), got {component}")
        return sl.start + component

    def __add__(self, other: StateLayout) -> StateLayout:
        return StateLayout(self.blocks + other.blocks, f"{self.name}+{other.name}")

    def __contains__(self, name: object) -> bool:
        return name in self.names

    def issubset(self, other: StateLayout) -> bool:
        """True if every block of ``self`` appears in ``other`` with the same size."""
        return all(b.name in other and other.block(b.name).size == b.size for b in self.blocks)

    def union(self, other: StateLayout) -> StateLayout:
        """Blocks of ``self`` followed by the blocks of ``other`` not already present."""
        extra = tuple(b for b in other.blocks if b.name not in self)
        return StateLayout(self.blocks + extra, f"{self.name}|{other.name}")

    def table(self) -> list[tuple[str, int]]:
        """``[(block name, size), ...]`` in order."""
        return [(b.name, b.size) for b in self.blocks]


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
# ins_block_name checks its own name argument, to name it as its caller spells it (argument=)
check_public(globals(), ins_block_name={"skip": ("name",)})
