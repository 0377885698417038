"""Which paper items each navcore model implements: the ``@implements`` decorator.

A model function names the paper equations (or tables, figures, sections) it implements::

    @implements("WF 13", "WF 14")
    def accelerometer_filter_step(...): ...

A reference is ``"<PAPER> <item>"``: the paper key (``WF``, ``SP``, ``ATC10``, ``KZL``) and
either an equation number as the paper prints it (``13``, ``2.4.2``, ``A.18``) or a labelled
item (``Table 2.6``, ``Fig. 2.1``, ``Sec. 2.5``). The decorator only records the references;
it returns the function itself, unchanged. :func:`recorded` returns what the modules imported
so far have recorded; :func:`navcore.traceability.implementations` imports every navcore
module first, builds the book's index from the records and checks them against the book's
pages and the ledger's locators.

This module imports nothing (it sits below every model module that uses it).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import TypeVar

__all__ = ["PAPER_KEYS", "Implementation", "Ref", "implements", "parse_ref", "recorded"]

PAPER_KEYS = ("WF", "SP", "ATC10", "KZL")
_EQUATION = re.compile(r"^(?:[A-H]\.?)?\d+(?:\.\d+)*[a-z]?$")
_LABELLED = re.compile(r"^(Table|Fig\.|Sec\.|Appendix|Theorem) [A-H0-9][0-9.]*$")

F = TypeVar("F", bound=Callable)


@dataclass(frozen=True, order=True)
class Ref:
    """One paper item: ``paper`` key and ``item`` (``"13"``, ``"A.18"``, ``"Table 2.6"``).

    Built by :func:`parse_ref`, which checks both parts.

    Attributes
    ----------
    paper : str
        Paper key, one of :data:`PAPER_KEYS`.
    item : str
        An equation number as the paper prints it (``"13"``, ``"2.4.2"``, ``"A.18"``) or a
        labelled item (``"Table 2.6"``, ``"Fig. 2.1"``, ``"Sec. 2.5"``).

    Examples
    --------
    >>> ref = Ref("WF", "13")
    >>> str(ref), ref.is_equation, Ref("SP", "Table 2.6").is_equation
    ('WF 13', True, False)
    """

    paper: str
    item: str

    @property
    def is_equation(self) -> bool:
        return _EQUATION.match(self.item) is not None

    def __str__(self) -> str:
        return f"{self.paper} {self.item}"


@dataclass(frozen=True)
class Implementation:
    """A model function and the paper items it implements (recorded by :func:`implements`).

    Attributes
    ----------
    module : str
        The function's module (``"navcore.location.emitter"``).
    qualname : str
        Its qualified name within the module.
    refs : tuple of Ref
        The paper items it implements, in the order given.

    Examples
    --------
    >>> impl = Implementation("navcore.units.db", "db_to_ratio", (Ref("SP", "Table 2.6"),))
    >>> impl.name, [str(r) for r in impl.refs]
    ('navcore.units.db.db_to_ratio', ['SP Table 2.6'])
    """

    module: str
    qualname: str
    refs: tuple[Ref, ...]

    @property
    def name(self) -> str:
        return f"{self.module}.{self.qualname}"


_REGISTRY: dict[str, Implementation] = {}


def parse_ref(ref: str) -> Ref:
    """Parse ``"<PAPER> <item>"``; raise ``ValueError`` naming what is wrong.

    Parameters
    ----------
    ref : str
        ``"<PAPER> <item>"``: a key of :data:`PAPER_KEYS`, a space, and an equation number
        as printed (``"2.4.2"``, ``"A.18"``, ``"A18"``) or ``"Table N"``, ``"Fig. N"``,
        ``"Sec. N"``, ``"Appendix X"``, ``"Theorem N"``.

    Returns
    -------
    Ref
        The parsed reference; an appendix equation written ``"A18"`` becomes ``"A.18"``, as
        the papers print it.

    Raises
    ------
    ValueError
        If ``ref`` is not a string with a space, the paper key is unknown, or the item is
        neither an equation number nor a labelled item.

    Examples
    --------
    >>> parse_ref("ATC10 A18")
    Ref(paper='ATC10', item='A.18')
    >>> parse_ref("XY 13")
    Traceback (most recent call last):
    ...
    ValueError: ref 'XY 13': the paper key must be one of ('WF', 'SP', 'ATC10', 'KZL'), got 'XY'
    """
    if not isinstance(ref, str) or " " not in ref.strip():
        raise ValueError(f"ref must be '<PAPER> <item>' such as 'WF 13', got {ref!r}")
    paper, item = ref.strip().split(" ", 1)
    if paper not in PAPER_KEYS:
        raise ValueError(f"ref {ref!r}: the paper key must be one of {PAPER_KEYS}, got {paper!r}")
    item = item.strip()
    if not (_EQUATION.match(item) or _LABELLED.match(item)):
        raise ValueError(
            f"ref {ref!r}: the item must be an equation number as printed ('13', '2.4.2', 'A.18') "
            f"or 'Table N', 'Fig. N', 'Sec. N', 'Appendix X'; got {item!r}"
        )
    if _EQUATION.match(item) and item[0].isalpha() and item[1] != ".":
        item = f"{item[0]}.{item[1:]}"  # 'A18' -> 'A.18', as the papers print appendix numbers
    return Ref(paper, item)


def implements(*refs: str) -> Callable[[F], F]:
    """Record that the decorated function implements the given paper items.

    Parameters
    ----------
    *refs : str
        ``"<PAPER> <item>"`` references, at least one (see the module docstring).

    Returns
    -------
    callable
        A decorator that registers the function and returns it unchanged.

    Raises
    ------
    ValueError
        If no reference is given, or one does not parse (:func:`parse_ref`).

    Examples
    --------
    ``@implements("WF 13", "WF 14")`` above a model function records it; the references are
    checked when the decorator is made:

    >>> callable(implements("WF 13", "WF 14"))
    True
    >>> implements("WF thirteen")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: ref 'WF thirteen': the item must be an equation number as printed ...
    """
    if not refs:
        raise ValueError("refs: give at least one paper item, e.g. implements('WF 13')")
    parsed = tuple(parse_ref(r) for r in refs)

    def register(func: F) -> F:
        impl = Implementation(func.__module__, func.__qualname__, parsed)
        _REGISTRY[impl.name] = impl
        return func

    return register


def recorded() -> tuple[Implementation, ...]:
    """The implementations recorded by the modules imported so far, sorted by full name.

    Returns
    -------
    tuple of Implementation
        One per decorated function of an imported module, sorted by full name; every
        module's records: :func:`navcore.traceability.implementations`.

    Examples
    --------
    >>> from navcore.detection.roc_bounds import chernoff_log_tail
    >>> impl = next(i for i in recorded() if i.qualname == "chernoff_log_tail")
    >>> [str(r) for r in impl.refs]
    ['ATC10 3.5.5', 'ATC10 3.5.6', 'ATC10 3.5.7']
    """
    return tuple(_REGISTRY[k] for k in sorted(_REGISTRY))
