"""Inputs of the ledger's computations, each registered once with its provenance.

A claim's computation reads the numbers it needs from an :class:`InputSet` that its paper
module defines. Each input is declared once with where it comes from:

``published``
    printed in the paper; ``locator`` says where (``"Table 2.1"``).
``convention``
    a reading the text leaves open (a unit, a sign, which of two printed formulas, a value
    read from a figure against one computed, a modelling constant with a standard
    alternative); ``readings`` labels every admissible reading in words, the one used
    included (a single ``alternative`` is shorthand for two readings), and the ledger weighs
    them all (:mod:`navcore.claims.verdict`, "Readings").
``assumed``
    not in the paper; a nominal value, a plausible ``low``-``high`` range and the reason for
    both. The ledger evaluates the claim across the range and reports the band.
``fitted``
    solved from printed results; ``fitted_to`` names the claims it was fitted to, which are
    then not evidence.

Reading an input is an attribute access on its set (``SP_IN.tc_loss_js_db``). While the
ledger evaluates a claim, every read is recorded, so a claim's list of inputs is what its
computation actually read and cannot drift from the code; the same mechanism lets the
ledger re-run a claim with one input changed (:func:`overriding`).

Two rules keep verdicts honest:

* inputs may not be read while a paper module is being imported, nor while the ledger
  resolves a tolerance: a tolerance or an expected status can therefore never be computed
  from the model (the ledger's rules, "fixed before the value is computed");
* a function that memoises a result computed from inputs must use :func:`input_cache`
  (not ``functools.cache``), which keys the memo on the values the result read and
  replays those reads, so cached results are recorded and follow overrides.

Example
-------
>>> from navcore.claims.inputs import InputSet, recording
>>> IN = InputSet("WF", "doc")
>>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
>>> with recording() as reads:
...     wavelength = 3.0e8 / IN.carrier_hz
>>> sorted(reads)
['WF.doc.carrier_hz']
"""

from __future__ import annotations

import contextlib
import contextvars
import functools
import hashlib
import inspect
import math
import sys
from collections.abc import Callable, Hashable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from types import FrameType
from typing import Any, Literal, TypeVar

import numpy as np

from navcore._validate import ModelDomainError

__all__ = [
    "NOMINAL_LABEL",
    "OTHER_LABEL",
    "PROVENANCES",
    "Input",
    "InputReadError",
    "InputSet",
    "all_inputs",
    "band_ahead",
    "declaring",
    "for_each_band_run",
    "get_input",
    "input_cache",
    "overriding",
    "recording",
]

Provenance = Literal["published", "convention", "assumed", "fitted"]
PROVENANCES: tuple[str, ...] = ("published", "convention", "assumed", "fitted")

#: Labels of the two readings of a convention declared with a single ``alternative``.
NOMINAL_LABEL = "the reading used"
OTHER_LABEL = "the other reading"

F = TypeVar("F", bound=Callable[..., Any])
T = TypeVar("T")
#: the inputs a computation read, each with the value it read
Reads = tuple[tuple["Input", Any], ...]


class InputReadError(RuntimeError):
    """An input was read where no computation may run (import of a paper module, tolerance)."""


@dataclass(frozen=True)
class Input:
    """One registered input of a claim's computation.

    Parameters
    ----------
    name : str
        Full name, ``"<PAPER>.<set>.<attribute>"`` (``"SP.antijam.tc_loss_js_db"``).
    paper : str
        Paper key.
    value : Any
        The nominal value (published, the convention's reading, the assumption's nominal, or
        the fitted value), in ``unit``.
    provenance : str
        One of :data:`PROVENANCES`.
    unit, quantity : str
        Unit of ``value`` and what it is, in words.
    locator : str
        Where a ``published`` input is printed.
    reason : str
        Why a ``convention``, ``assumed`` or ``fitted`` input has its value (and range).
    low, high : float or None
        Plausible range of an ``assumed`` input.
    grid : int
        Number of points across ``low``-``high`` at which the band is evaluated (0: the two
        ends only; use a grid where the response is not monotone).
    admissible : bool
        ``True`` when ``low``-``high`` is every admissible value (a physical limit), so a
        disagreement across the whole band is a discrepancy, not an inconsistency.
    alternative : Any
        The other reading of a ``convention`` input declared with two readings; for more,
        the first reading that is not the one used (kept for callers that show one).
    readings : tuple of (str, Any)
        Every admissible reading of a ``convention`` input, each ``(label in words,
        value)``, the one used (``value``) included, in the declared order. Declared with
        ``alternative`` only, the labels are :data:`NOMINAL_LABEL` and :data:`OTHER_LABEL`.
    fitted_to : tuple of str
        Claim ids a ``fitted`` input was solved from.
    module : str
        The module that declared it (set by :class:`InputSet`; not compared).

    Raises
    ------
    ValueError
        If ``provenance`` is unknown, or the fields its provenance needs are missing: a
        ``locator`` (published), a ``reason`` (the others), a range ``low <= value <= high``
        (assumed), readings (convention: at least two, labelled, distinct, one of them
        ``value``) or ``fitted_to`` (fitted).

    Examples
    --------
    >>> conv = Input(name="WF.doc.c_ft_per_ns", paper="WF", value=1.0, provenance="convention",
    ...              alternative=0.98357, reason="the table's ft are ns at c = 1 ft/ns")
    >>> conv.readings
    (('the reading used', 1.0), ('the other reading', 0.98357))
    >>> inp = Input(name="WF.doc.noise_m", paper="WF", value=2.0, provenance="assumed",
    ...             unit="m", low=1.0, high=4.0, grid=4, reason="typical survey accuracy")
    >>> inp.band_points, inp.source()
    ((1.0, 2.0, 3.0, 4.0), 'typical survey accuracy')
    """

    name: str
    paper: str
    value: Any
    provenance: Provenance
    unit: str = ""
    quantity: str = ""
    locator: str = ""
    reason: str = ""
    low: float | None = None
    high: float | None = None
    grid: int = 0
    admissible: bool = False
    alternative: Any = None
    fitted_to: tuple[str, ...] = field(default_factory=tuple)
    module: str = field(default="", compare=False)
    readings: tuple[tuple[str, Any], ...] = ()

    def __post_init__(self) -> None:
        if self.provenance not in PROVENANCES:
            raise ValueError(f"Input.provenance must be one of {PROVENANCES}, got {self.provenance!r}")
        if self.provenance == "published" and not self.locator.strip():
            raise ValueError(f"published input {self.name} needs the locator where it is printed")
        if self.provenance != "published" and not self.reason.strip():
            raise ValueError(f"{self.provenance} input {self.name} needs a reason")
        if self.provenance == "assumed":
            if self.low is None or self.high is None:
                raise ValueError(f"assumed input {self.name} needs a plausible range low..high")
            if not (self.low <= float(self.value) <= self.high):
                raise ValueError(
                    f"assumed input {self.name}: nominal {self.value!r} must lie in [{self.low}, {self.high}]"
                )
        if self.provenance == "convention":
            self._check_readings()
        elif self.readings or self.alternative is not None:
            raise ValueError(f"{self.provenance} input {self.name}: only a convention has readings")
        if self.provenance == "fitted" and not self.fitted_to:
            raise ValueError(f"fitted input {self.name} must name the claims it was fitted to")

    def _check_readings(self) -> None:
        """Normalise a convention's readings (``alternative`` -> two labelled readings) and
        check them: at least two, labels in words and distinct, values distinct, the value
        used among them."""
        readings = tuple(self.readings)
        if not readings:
            if self.alternative is None:
                raise ValueError(f"convention input {self.name} needs its readings (or its alternative)")
            readings = ((NOMINAL_LABEL, self.value), (OTHER_LABEL, self.alternative))
        if len(readings) < 2:
            raise ValueError(f"convention input {self.name} needs at least two readings, got {len(readings)}")
        labels = [label for label, _ in readings]
        if any(not isinstance(label, str) or not label.strip() for label in labels):
            raise ValueError(
                f"convention input {self.name}: each reading needs a label in words, got {labels}"
            )
        if len(set(labels)) != len(labels):
            raise ValueError(f"convention input {self.name}: reading labels must be distinct, got {labels}")
        values = [v for _, v in readings]
        for i, a in enumerate(values):
            if any(_same(a, b) for b in values[:i]):
                raise ValueError(f"convention input {self.name}: two readings have the value {a!r}")
        used = [label for label, v in readings if _same(v, self.value)]
        if len(used) != 1:
            raise ValueError(
                f"convention input {self.name}: the value used ({self.value!r}) must be one of its "
                f"readings {labels}"
            )
        object.__setattr__(self, "readings", readings)
        if self.alternative is None:
            object.__setattr__(self, "alternative", next(v for _, v in readings if not _same(v, self.value)))

    @property
    def nominal_label(self) -> str:
        """The label of the reading used (conventions only; ``""`` otherwise)."""
        return next((label for label, v in self.readings if _same(v, self.value)), "")

    @property
    def other_readings(self) -> tuple[tuple[str, Any], ...]:
        """The admissible readings other than the one used, ``(label, value)`` (conventions only)."""
        return tuple((label, v) for label, v in self.readings if not _same(v, self.value))

    @property
    def band_points(self) -> tuple[Any, ...]:
        """The values at which the band is evaluated (assumed inputs only)."""
        if self.provenance != "assumed":
            return ()
        assert self.low is not None and self.high is not None
        if self.grid and self.grid > 2:
            step = (self.high - self.low) / (self.grid - 1)
            pts = [self.low + i * step for i in range(self.grid)]
        else:
            pts = [self.low, self.high]
        if isinstance(self.value, int) and not isinstance(self.value, bool):
            pts = sorted({round(p) for p in pts})
        return tuple(pts)

    def source(self) -> str:
        """The locator of a published input, else the reason."""
        return self.locator if self.provenance == "published" else self.reason


_REGISTRY: dict[str, Input] = {}

# the reads of the innermost active recording; None when nothing records
_RECORDER: contextvars.ContextVar[dict[str, Input] | None] = contextvars.ContextVar(
    "navcore_input_recorder", default=None
)
_NO_OVERRIDES: dict[str, Any] = {}  # never mutated: overriding() sets a fresh dict
_OVERRIDES: contextvars.ContextVar[dict[str, Any]] = contextvars.ContextVar(
    "navcore_input_overrides",
    default=_NO_OVERRIDES,
)
_DECLARING: contextvars.ContextVar[bool] = contextvars.ContextVar("navcore_input_declaring", default=False)
# the band runs the ledger is about to make: the overrides outside the band, each run's
# overrides, and the keys of the models that already took this batch (for_each_band_run)
_BandAhead = tuple[dict[str, Any], tuple[dict[str, Any], ...], set[Any]]
_BAND_AHEAD: contextvars.ContextVar[_BandAhead] = contextvars.ContextVar(
    "navcore_band_ahead", default=(_NO_OVERRIDES, (), set())
)


def _importing_paper_module() -> str | None:
    """Name of a ``navcore.papers`` module whose top level is executing on this stack."""
    frame = sys._getframe(2)
    while frame is not None:
        if frame.f_code.co_name == "<module>":
            mod = frame.f_globals.get("__name__", "")
            if mod.startswith("navcore.papers."):
                return mod
        frame = frame.f_back  # type: ignore[assignment]
    return None


def _guard(name: str, recorded: bool) -> None:
    if _DECLARING.get():
        raise InputReadError(
            f"input {name} read while a tolerance was resolved: tolerances are fixed by the "
            "printed text before anything is computed"
        )
    if not recorded:
        module = _importing_paper_module()
        if module is not None:
            raise InputReadError(
                f"input {name} read while {module} was imported: a paper module declares its "
                "claims (tolerance, expected status) before anything is computed; compute inside "
                "a claim's compute function"
            )


def _read(inp: Input) -> Any:
    rec = _RECORDER.get()
    _guard(inp.name, rec is not None)
    if rec is not None:
        rec[inp.name] = inp
    overrides = _OVERRIDES.get()
    return overrides[inp.name] if inp.name in overrides else inp.value


def _declaring_module() -> str:
    """The module whose code made an :class:`InputSet`: the caller of ``InputSet.__init__``.

    The wrapper that mutation testing puts between a function and its caller is skipped (mutmut
    calls the mutated ``__init__`` from a trampoline of its own, module ``mutmut.*``, reached
    from a stand-in ``__init__`` in this module): under it every input would otherwise be
    declared by the trampoline, and the registry's checks of the paper modules' inputs (which
    select them by module) would find none. No code of this module makes an input set.
    """
    frame = sys._getframe(2)

    def wrapper(f: FrameType) -> bool:
        name = str(f.f_globals.get("__name__", ""))
        return name.startswith("mutmut.") or name == __name__

    while frame.f_back is not None and wrapper(frame):
        frame = frame.f_back
    return str(frame.f_globals.get("__name__", ""))


class InputSet:
    """The registered inputs of one paper module, read as attributes.

    Parameters
    ----------
    paper : str
        Paper key (``"SP"``).
    section : str
        A short name for the module's set (``"antijam"``); full input names are
        ``"<paper>.<section>.<attribute>"``.

    Notes
    -----
    Declaring an input registers it for the whole process (:func:`all_inputs`); declaring a
    name twice in one set, or the same full name with another declaration, raises
    ``ValueError``. Inputs cannot be assigned: ``IN.x = 1`` raises ``AttributeError``.

    Examples
    --------
    >>> IN = InputSet("WF", "doc_set")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> IN.assumed("noise_m", 2.0, low=1.0, high=4.0, unit="m", reason="typical survey accuracy")
    >>> IN.carrier_hz, IN.nominal("noise_m"), [i.provenance for i in IN]
    (1000000000.0, 2.0, ['published', 'assumed'])
    """

    def __init__(self, paper: str, section: str) -> None:
        object.__setattr__(self, "_module", _declaring_module())
        object.__setattr__(self, "_paper", paper)
        object.__setattr__(self, "_section", section)
        object.__setattr__(self, "_inputs", {})

    # -- declaration ---------------------------------------------------------------------
    def _add(self, attr: str, **kw: Any) -> None:
        if not attr.isidentifier() or attr.startswith("_"):
            raise ValueError(f"input name must be a public identifier, got {attr!r}")
        inputs: dict[str, Input] = object.__getattribute__(self, "_inputs")
        if attr in inputs:
            raise ValueError(f"input {attr!r} is declared twice in {self!r}")
        full = f"{self._paper}.{self._section}.{attr}"
        if full in _REGISTRY and _REGISTRY[full] != Input(name=full, paper=self._paper, **kw):
            raise ValueError(f"input {full} is registered twice with different declarations")
        inp = Input(name=full, paper=self._paper, module=self._module, **kw)
        inputs[attr] = inp
        _REGISTRY[full] = inp

    def published(self, attr: str, value: Any, *, locator: str, unit: str = "", quantity: str = "") -> None:
        """Declare an input printed in the paper at ``locator``.

        Parameters
        ----------
        attr : str
            Attribute name (a public identifier, unit as suffix: ``carrier_hz``).
        value : Any
            The printed value, in ``unit``.
        locator : str
            Where it is printed (``"Table 2.1"``); not empty.
        unit, quantity : str, optional
            Unit of ``value`` and what it is, in words.
        """
        self._add(attr, value=value, provenance="published", locator=locator, unit=unit, quantity=quantity)

    def convention(
        self,
        attr: str,
        value: Any,
        *,
        reason: str,
        readings: Mapping[str, Any] | None = None,
        alternative: Any = None,
        unit: str = "",
        quantity: str = "",
    ) -> None:
        """Declare a reading the text leaves open, with every admissible reading.

        The ledger evaluates each claim that reads it under every reading and weighs them
        (:mod:`navcore.claims.verdict`, "Readings"): a claim is discrepant only if every
        admissible reading disagrees.

        Parameters
        ----------
        attr : str
            Attribute name.
        value : Any
            The reading used (the nominal one); one of ``readings``.
        reason : str
            Why the text leaves it open and why this reading is used.
        readings : mapping of str to Any, optional
            Every admissible reading, labelled in words (the one used included), e.g.
            ``{"1 ft per ns, as the table's units imply": 1.0, "the physical speed of
            light": 0.98357}``. Give either ``readings`` or ``alternative``.
        alternative : Any, optional
            The other reading, for a convention with exactly two (labelled "the reading
            used" and "the other reading").
        unit, quantity : str, optional
            Unit of ``value`` and what it is, in words.

        Raises
        ------
        ValueError
            If both or neither of ``readings`` and ``alternative`` are given, fewer than two
            readings, a label is empty or repeated, two readings have one value, or
            ``value`` is not among the readings.

        Examples
        --------
        >>> IN = InputSet("WF", "doc_convention")
        >>> IN.convention("c_ft_per_ns", 1.0, quantity="speed of light in ft/ns",
        ...               readings={"1 ft per ns, as the table's units imply": 1.0,
        ...                         "the physical speed of light": 0.98357},
        ...               reason="the table prints ns times a factor as ft")
        >>> [label for label, _ in IN.input("c_ft_per_ns").other_readings]
        ['the physical speed of light']
        """
        if (readings is None) == (alternative is None):
            raise ValueError(
                f"convention {attr!r}: give one of readings= and alternative=, not both or neither"
            )
        self._add(
            attr,
            value=value,
            provenance="convention",
            alternative=alternative,
            readings=tuple(readings.items()) if readings is not None else (),
            reason=reason,
            unit=unit,
            quantity=quantity,
        )

    def assumed(
        self,
        attr: str,
        value: Any,
        *,
        low: float,
        high: float,
        reason: str,
        unit: str = "",
        quantity: str = "",
        grid: int = 0,
        admissible: bool = False,
    ) -> None:
        """Declare an input the paper does not give: nominal, plausible range and reason.

        Parameters
        ----------
        attr : str
            Attribute name.
        value : Any
            The nominal value, within ``low``-``high``.
        low, high : float
            The plausible range, across which the ledger evaluates the band.
        reason : str
            Why the nominal and the range have their values.
        unit, quantity : str, optional
            Unit of ``value`` and what it is, in words.
        grid : int, optional
            Points across the range (0: its two ends; use a grid where the response is not
            monotone).
        admissible : bool, optional
            The range is every admissible value, so disagreement across it is a
            discrepancy.
        """
        self._add(
            attr,
            value=value,
            provenance="assumed",
            low=low,
            high=high,
            reason=reason,
            unit=unit,
            quantity=quantity,
            grid=grid,
            admissible=admissible,
        )

    def fitted(
        self,
        attr: str,
        value: Any,
        *,
        fitted_to: Sequence[str],
        reason: str,
        unit: str = "",
        quantity: str = "",
    ) -> None:
        """Declare a parameter solved from printed results, naming the claims it was fitted to.

        Parameters
        ----------
        attr : str
            Attribute name.
        value : Any
            The fitted value.
        fitted_to : sequence of str
            Ids of the claims it was solved from (not empty; they are then not evidence).
        reason : str
            How it was solved.
        unit, quantity : str, optional
            Unit of ``value`` and what it is, in words.
        """
        self._add(
            attr,
            value=value,
            provenance="fitted",
            fitted_to=tuple(fitted_to),
            reason=reason,
            unit=unit,
            quantity=quantity,
        )

    # -- reading -------------------------------------------------------------------------
    def __getattr__(self, attr: str) -> Any:
        inputs: dict[str, Input] = object.__getattribute__(self, "_inputs")
        try:
            inp = inputs[attr]
        except KeyError:
            raise AttributeError(f"{self!r} has no input {attr!r}") from None
        return _read(inp)

    def __setattr__(self, attr: str, value: Any) -> None:
        raise AttributeError("inputs are declared with published(), convention(), assumed() or fitted()")

    def nominal(self, attr: str) -> Any:
        """The declared value without recording a read: for labels and ids only, never a computation."""
        return object.__getattribute__(self, "_inputs")[attr].value

    def input(self, attr: str) -> Input:
        """The :class:`Input` record of ``attr``."""
        return object.__getattribute__(self, "_inputs")[attr]

    def __iter__(self) -> Iterator[Input]:
        return iter(object.__getattribute__(self, "_inputs").values())

    def __repr__(self) -> str:
        return f"InputSet({self._paper!r}, {self._section!r})"


def all_inputs(paper: str | None = None) -> tuple[Input, ...]:
    """Every registered input (of ``paper`` if given), in declaration order.

    Only the inputs of paper modules already imported are registered; the ledger's registry
    imports them all.

    Parameters
    ----------
    paper : str or None, optional
        Paper key (``"SP"``); ``None`` for the inputs of every paper.

    Returns
    -------
    tuple of Input
        The registered inputs, in the order they were declared.

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> "WF.doc_inputs.carrier_hz" in [i.name for i in all_inputs("WF")]
    True
    """
    return tuple(i for i in _REGISTRY.values() if paper is None or i.paper == paper)


def get_input(name: str) -> Input:
    """The registered input with full name ``name``.

    Parameters
    ----------
    name : str
        Full name, ``"<PAPER>.<set>.<attribute>"`` (``"SP.antijam.tc_loss_js_db"``).

    Returns
    -------
    Input
        Its registered declaration.

    Raises
    ------
    ValueError
        If no input of that name is registered (its paper module is not imported, or the
        name is wrong).

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> inp = get_input("WF.doc_inputs.carrier_hz")
    >>> inp.provenance, inp.locator, inp.value
    ('published', 'Sec. IV', 1000000000.0)
    """
    try:
        return _REGISTRY[name]
    except KeyError:
        raise ValueError(f"name {name!r} is not a registered input") from None


def _label_and_unit(name: str) -> tuple[str, str]:
    """How a claim's text names an input: its quantity in words (else the last part of its
    name, spaced) and its unit ("" for none or a pure number); unregistered names too."""
    fallback = name.rsplit(".", 1)[-1].replace("_", " ")
    try:
        inp = get_input(name)
    except (KeyError, ValueError):
        return fallback, ""
    unit = "" if inp.unit in ("", "1", "-", "statement") else inp.unit
    return inp.quantity or fallback, unit


@contextlib.contextmanager
def recording() -> Iterator[dict[str, Input]]:
    """Record every input read inside the block into the yielded dict (name -> Input).

    Recordings nest: only the innermost one receives the reads. The ledger evaluates each
    claim's computation in one, so a claim's inputs are what it actually read.

    Yields
    ------
    dict of str to Input
        Filled, as the block runs, with each input read, keyed by its full name.

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> with recording() as reads:
    ...     wavelength_m = 3.0e8 / IN.carrier_hz
    >>> sorted(reads), round(wavelength_m, 3)
    (['WF.doc_inputs.carrier_hz'], 0.3)
    """
    reads: dict[str, Input] = {}
    token = _RECORDER.set(reads)
    try:
        yield reads
    finally:
        _RECORDER.reset(token)


@contextlib.contextmanager
def overriding(values: dict[str, Any]) -> Iterator[None]:
    """Read the inputs named in ``values`` (full names) with those values inside the block.

    Overrides nest: an inner block adds to (and may replace) the outer block's values. The
    ledger uses it to evaluate a claim across an assumed input's range and at a convention's
    other reading (the ledger's rules, "Provenance of an input").

    Parameters
    ----------
    values : dict of str to Any
        Full input name to the value every read of that input returns inside the block.

    Yields
    ------
    None
        Control of the block; the overrides are undone when it exits.

    Raises
    ------
    ValueError
        If a name in ``values`` is not a registered input.

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> with overriding({"WF.doc_inputs.carrier_hz": 1.5e9}):
    ...     print(IN.carrier_hz)
    1500000000.0
    >>> IN.carrier_hz
    1000000000.0
    """
    for name in values:
        get_input(name)  # unknown names are an error, not a silent no-op
    merged = {**_OVERRIDES.get(), **values}
    token = _OVERRIDES.set(merged)
    try:
        yield
    finally:
        _OVERRIDES.reset(token)


@contextlib.contextmanager
def declaring() -> Iterator[None]:
    """Forbid every input read inside the block (the ledger resolves tolerances in one).

    A tolerance is fixed by the printed text before anything is computed (the ledger's rules,
    "Tolerance: fixed before the value is computed"); a read inside the block raises
    :class:`InputReadError`.

    Yields
    ------
    None
        Control of the block; reads are allowed again when it exits.

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> with declaring():  # doctest: +ELLIPSIS
    ...     IN.carrier_hz
    Traceback (most recent call last):
    ...
    navcore.claims.inputs.InputReadError: input WF.doc_inputs.carrier_hz read while a tolerance ...
    """
    token = _DECLARING.set(True)
    try:
        yield
    finally:
        _DECLARING.reset(token)


def _same(a: Any, b: Any) -> bool:
    if a is b:
        return True
    try:
        eq = a == b
        if isinstance(eq, bool):
            return eq
        return bool(eq.all())
    except Exception:
        return repr(a) == repr(b)


def _current(inp: Input) -> Any:
    overrides = _OVERRIDES.get()
    return overrides[inp.name] if inp.name in overrides else inp.value


def _same_reads(a: Reads, b: Reads) -> bool:
    return len(a) == len(b) and all(i is j and _same(x, y) for (i, x), (j, y) in zip(a, b, strict=True))


def _hashable(obj: Any) -> Any:
    """``obj`` itself if it can be hashed, else a key that equal contents share.

    An array is keyed by its dtype, shape and a digest of its bytes (its repr elides the middle
    of a large array, so two different arrays would share it); a list or tuple by its items'
    keys; anything else by its repr.
    """
    try:
        hash(obj)
        return obj
    except TypeError:
        pass
    if isinstance(obj, np.ndarray) and not obj.dtype.hasobject:
        digest = hashlib.blake2b(np.ascontiguousarray(obj).tobytes(), digest_size=16).hexdigest()
        return ("ndarray", obj.dtype.str, obj.shape, digest)
    if isinstance(obj, (list, tuple)):
        return (type(obj).__name__, tuple(_hashable(item) for item in obj))
    return repr(obj)


def input_cache(fn: F) -> F:
    """Memoise ``fn`` keyed on its arguments and on the values of the inputs it read.

    The first call records the inputs ``fn`` reads; a later call with the same arguments
    (after binding them to ``fn``'s signature with its defaults, so ``f(1)``, ``f(x=1)`` and
    ``f(1, flag=True)`` with ``flag=True`` its default are one call) returns the stored
    result only if those inputs still have the same values (overrides included), and
    replays the reads into the caller's recording. Use it instead of ``functools.cache`` for
    anything that reads inputs.

    Parameters
    ----------
    fn : callable
        The function to memoise; an unhashable argument is keyed by its contents (an array by
        its dtype, shape and bytes, a list by its items), anything else by its ``repr``.

    Returns
    -------
    callable
        A wrapper with the signature of ``fn``, a ``cache_clear()`` method and a
        ``prime(entries, *args, **kwargs)`` method that stores results a batched band
        computed (:func:`for_each_band_run`). Up to 256 results (for differing input values)
        are kept per argument key.

    Raises
    ------
    InputReadError
        When the wrapper is called outside a recording while a paper module is imported, or
        inside :func:`declaring` (as a direct read would).

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> calls = []
    >>> @input_cache
    ... def wavelength_m(c_m_s):
    ...     calls.append(c_m_s)
    ...     return c_m_s / IN.carrier_hz
    >>> with recording() as reads:
    ...     first = wavelength_m(3.0e8)
    >>> with recording() as again:
    ...     second = wavelength_m(3.0e8)
    >>> first == second, len(calls), sorted(again)
    (True, 1, ['WF.doc_inputs.carrier_hz'])
    >>> with overriding({"WF.doc_inputs.carrier_hz": 1.5e9}):
    ...     round(wavelength_m(3.0e8), 3), len(calls)
    (0.2, 2)
    """
    store: dict[Any, list[tuple[tuple[tuple[Input, Any], ...], Any]]] = {}
    # per argument key, the stored variants indexed by the names of the inputs they read, then
    # by those inputs' values: a lookup costs one probe per distinct set of inputs read, not a
    # scan of up to 256 variants (a deterministic computation has at most one variant that
    # matches the current values: the one whose path it would take now). A value that cannot
    # be hashed is indexed by a key of its contents (an array's bytes) or its repr, which equal
    # values need not share (-0.0 and 0.0): the keys holding one are also scanned on a miss.
    index: dict[Any, dict[tuple[str, ...], dict[tuple[Any, ...], tuple[Reads, Any]]]] = {}
    scanned: set[Any] = set()
    signature = inspect.signature(fn)

    def index_key(reads: Reads) -> tuple[tuple[str, ...], tuple[Any, ...]]:
        return tuple(inp.name for inp, _ in reads), tuple(_hashable(value) for _, value in reads)

    def remember(key: Any, reads: Reads, result: Any) -> None:
        variants = store.setdefault(key, [])
        variants.append((reads, result))
        names, values = index_key(reads)
        index.setdefault(key, {}).setdefault(names, {}).setdefault(values, (reads, result))
        if any(v is not h for v, (_, h) in zip(values, reads, strict=True)):
            scanned.add(key)
        if len(variants) > 256:  # bounded: perturbation runs and batched bands create variants
            for old in variants[:-256]:
                names, values = index_key(old[0])
                by_values = index[key].get(names, {})
                if values in by_values and by_values[values][0] is old[0]:
                    del by_values[values]
            del variants[:-256]

    def lookup(key: Any) -> tuple[Reads, Any] | None:
        for by_values in index.get(key, {}).values():
            if not by_values:
                continue
            reads, _ = next(iter(by_values.values()))
            hit = by_values.get(tuple(_hashable(_current(inp)) for inp, _ in reads))
            if hit is not None and all(_same(_current(inp), value) for inp, value in hit[0]):
                return hit
        if key in scanned:
            for reads, result in store.get(key, ()):
                if all(_same(_current(inp), value) for inp, value in reads):
                    return reads, result
        return None

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:  # one key per call, however it spells its arguments: f("ins") is f("ins", True)
            bound = signature.bind(*args, **kwargs)
        except TypeError:
            return fn(*args, **kwargs)  # let the function report the bad call
        bound.apply_defaults()
        key = tuple((k, _hashable(v)) for k, v in bound.arguments.items())
        outer = _RECORDER.get()
        _guard(getattr(fn, "__qualname__", "a cached computation"), outer is not None)
        hit = lookup(key)
        if hit is not None:
            if outer is not None:
                for inp, _ in hit[0]:
                    _read(inp)
            return hit[1]
        with recording() as inner:
            result = fn(*args, **kwargs)
        reads = tuple((inp, _current(inp)) for inp in inner.values())
        if outer is not None:
            for inp, _ in reads:
                _read(inp)
        remember(key, reads, result)
        return result

    def prime(entries: Sequence[tuple[Reads, Any]], *args: Any, **kwargs: Any) -> None:
        """Store results computed elsewhere (a batched band) for the call ``fn(*args, **kwargs)``.

        ``entries`` holds ``(reads, result)`` pairs, the reads as :func:`for_each_band_run`
        returns them; they must be every input ``fn`` reads for that call (a later call
        returns a stored result when those inputs have those values). An entry already stored
        is kept.
        """
        bound = signature.bind(*args, **kwargs)
        bound.apply_defaults()
        key = tuple((k, _hashable(v)) for k, v in bound.arguments.items())
        for reads, result in entries:
            if not any(_same_reads(r, reads) for r, _ in store.get(key, ())):
                remember(key, tuple(reads), result)

    def cache_clear() -> None:
        store.clear()
        index.clear()
        scanned.clear()

    wrapper.cache_clear = cache_clear  # type: ignore[attr-defined]
    wrapper.prime = prime  # type: ignore[attr-defined]
    return wrapper  # type: ignore[return-value]


@contextlib.contextmanager
def band_ahead(runs: Sequence[dict[str, Any]]) -> Iterator[None]:
    """Announce, inside the block, the band runs about to be made (each run's overrides).

    The ledger wraps each batch of a band's runs (the one-at-a-time runs, then the corners) in
    this block, so that a model can compute them all in one batched call when the first of
    them asks for its result (:func:`for_each_band_run`), instead of one call per run. A model
    that batches must give each run the result it gives that run alone (the ledger's values
    may not depend on the batching).

    Parameters
    ----------
    runs : sequence of dict of str to Any
        Each run's overrides (full input name to value), as :func:`overriding` takes them;
        they apply on top of the overrides active where the block opens.

    Yields
    ------
    None
        Control of the block.

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> with band_ahead([{"WF.doc_inputs.carrier_hz": 1.5e9}]):
    ...     [value for _, value in for_each_band_run("carrier", lambda: IN.carrier_hz)]
    [1500000000.0]
    """
    for values in runs:
        for name in values:
            get_input(name)
    token = _BAND_AHEAD.set((_OVERRIDES.get(), tuple(dict(v) for v in runs), set()))
    try:
        yield
    finally:
        _BAND_AHEAD.reset(token)


def for_each_band_run(key: Hashable, fn: Callable[[], T]) -> list[tuple[Reads, T]]:
    """Call ``fn`` under each announced band run's overrides (:func:`band_ahead`), once per model.

    For a model that batches a band: ``fn`` reads the inputs and builds one run's
    parameters without running the model; the model then runs every parameter set in one call
    and stores each result with :meth:`input_cache`'s ``prime`` under the reads returned here.
    Outside an announced band, and for a ``key`` that already took the announced batch, it
    returns ``[]``. A run whose parameters raise
    :class:`~navcore.ModelDomainError` is left out (its own unbatched call will
    raise it again, and the ledger leaves that run out of the band).

    Parameters
    ----------
    key : hashable
        Names the model run (its function and arguments), so that the first run of a batch
        that asks computes the batch, and the runs after it find their results stored.
    fn : callable
        Takes no argument; returns one run's parameters.

    Returns
    -------
    list of (reads, value)
        For each run that ``fn`` accepted: the inputs ``fn`` read with their values in that
        run, and what ``fn`` returned. The caller's recording receives none of these reads.

    Examples
    --------
    >>> IN = InputSet("WF", "doc_inputs")
    >>> IN.published("carrier_hz", 1.0e9, unit="Hz", locator="Sec. IV", quantity="carrier frequency")
    >>> for_each_band_run("wavelength", lambda: IN.carrier_hz)
    []
    >>> runs = [{"WF.doc_inputs.carrier_hz": 1.5e9}, {"WF.doc_inputs.carrier_hz": 2.0e9}]
    >>> with band_ahead(runs):
    ...     first = [value for _, value in for_each_band_run("wavelength", lambda: IN.carrier_hz)]
    ...     again = for_each_band_run("wavelength", lambda: IN.carrier_hz)
    >>> first, again
    ([1500000000.0, 2000000000.0], [])
    """
    outer, runs, taken = _BAND_AHEAD.get()
    if key in taken:
        return []
    taken.add(key)
    out: list[tuple[Reads, T]] = []
    for values in runs:
        token = _OVERRIDES.set({**outer, **values})
        try:
            with recording() as reads:
                value = fn()
            out.append((tuple((inp, _current(inp)) for inp in reads.values()), value))
        except ModelDomainError:
            continue
        finally:
            _OVERRIDES.reset(token)
    return out


def is_number(value: Any) -> bool:
    """True for a real scalar (not a bool)."""
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(float(value))
