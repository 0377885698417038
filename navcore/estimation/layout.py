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

from dataclasses import dataclass

from navcore._validate import check_public

__all__ = ["StateBlock", "StateLayout"]


@dataclass(frozen=True)
class StateBlock:
    """A named block of ``size`` consecutive states (``unit`` of each component)."""

    name: str
    size: int
    unit: str = ""
    description: str = ""

    def __post_init__(self) -> None:
        if not self.name:
            raise ValueError("StateBlock.name must not be empty")
        if isinstance(self.size, bool) or not isinstance(self.size, int) or self.size < 1:
            raise ValueError(f"StateBlock.size must be an integer >= 1, got {self.size!r}")


@dataclass(frozen=True)
class StateLayout:
    """An ordered tuple of uniquely named :class:`~navcore.estimation.layout.StateBlock` objects."""

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
        raise ValueError(f"name must be one of {list(self.names)}, got {name!r}")

    def slice(self, name: str) -> slice:
        """The slice of block ``name`` in the state vector."""
        start = 0
        for b in self.blocks:
            if b.name == name:
                return slice(start, start + b.size)
            start += b.size
        raise ValueError(f"name must be one of {list(self.names)}, got {name!r}")

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
check_public(globals())
