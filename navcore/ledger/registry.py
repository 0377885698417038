"""The claim and erratum registry.

Claims and errata live in the modules of :mod:`navcore.papers`, one module per paper or
section, each defining module-level ``CLAIMS`` and ``ERRATA`` lists. The registry discovers
every such module, so adding a section never means editing a shared list.
"""

from __future__ import annotations

import hashlib
import importlib
import json
import math
import os
import pkgutil
from functools import cache
from pathlib import Path
from typing import Any

from navcore.ledger.core import PAPERS, STATUSES, Claim, Erratum, Evaluation, evaluate

__all__ = [
    "cache_dir",
    "claim",
    "claims",
    "counts",
    "errata",
    "erratum",
    "evaluate_claim",
    "evaluations",
    "paper_modules",
    "validate_registry",
]


@cache
def paper_modules() -> tuple[str, ...]:
    """Names of the modules in :mod:`navcore.papers`, sorted.

    Each module defines the ``CLAIMS`` and ``ERRATA`` of one paper or section; the registry
    imports them on demand (:func:`claims`, :func:`errata`).

    Returns
    -------
    tuple of str
        Full module names (``"navcore.papers.kzl"``), sorted; modules whose name starts
        with ``_`` are left out.

    Examples
    --------
    >>> names = paper_modules()
    >>> all(name.startswith("navcore.papers.") for name in names), names == tuple(sorted(names))
    (True, True)
    """
    import navcore.papers as pkg

    return tuple(
        sorted(
            f"{pkg.__name__}.{m.name}"
            for m in pkgutil.iter_modules(pkg.__path__)
            if not m.name.startswith("_")
        )
    )


def _module_paper(name: str) -> str:
    """Paper key of a module named ``<paper>_<section>`` or ``<paper>`` (lower case)."""
    return name.rsplit(".", 1)[-1].split("_", 1)[0].upper()


@cache
def _load(paper: str | None = None) -> tuple[tuple[Claim, ...], tuple[Erratum, ...]]:
    """Import the paper modules (only those of ``paper`` if given) and collect their lists.

    Loading one paper imports only that paper's models, which keeps a chapter's notebook
    kernels from importing all four papers' dependencies.
    """
    all_claims: list[Claim] = []
    all_errata: list[Erratum] = []
    for name in paper_modules():
        if paper is not None and _module_paper(name) != paper:
            continue
        module = importlib.import_module(name)
        all_claims.extend(getattr(module, "CLAIMS", ()))
        all_errata.extend(getattr(module, "ERRATA", ()))
    if paper is not None:
        strays = [c.id for c in all_claims if c.paper != paper] + [
            e.id for e in all_errata if e.paper != paper
        ]
        if strays:
            raise ValueError(f"modules named for {paper} define items of another paper: {strays}")
    validate_registry(all_claims, all_errata)
    paper_order = {k: i for i, k in enumerate(PAPERS)}
    # stable order: by paper, then by the order of definition within the paper's modules
    all_claims.sort(key=lambda c: paper_order[c.paper])
    all_errata.sort(key=lambda e: paper_order[e.paper])
    return tuple(all_claims), tuple(all_errata)


def validate_registry(all_claims: list[Claim], all_errata: list[Erratum]) -> None:
    """Check uniqueness of ids and the links between claims and errata.

    The registry runs it on every set of claims and errata it loads; it also checks that a
    fitted input of a loaded paper names only known claims.

    Parameters
    ----------
    all_claims : list of Claim
        The claims to check together (ids and aliases must be unique among them).
    all_errata : list of Erratum
        The errata to check together (ids must be unique among them).

    Returns
    -------
    None
        The lists are consistent.

    Raises
    ------
    ValueError
        On a duplicate id or alias, a claim naming an unknown erratum, an erratum naming an
        unknown claim, a fitted input fitted to an unknown claim, or a claim whose published
        number its printed quote does not contain (published means printed: a number the
        paper does not print is the book's, so the claim must be a statement with its
        threshold a declared convention; reasoned exceptions such as unit conversions are in
        :data:`navcore.ledger.allowlists.PUBLISHED_NOT_IN_QUOTE`).

    Examples
    --------
    >>> from navcore.ledger import EXACT, Claim
    >>> c = Claim(id="KZL-doc-states", paper="KZL", locator="Eq. (1)", quantity="states",
    ...           published=15.0, unit="", compute=lambda: 15.0, tolerance=EXACT,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> validate_registry([c], [])
    >>> validate_registry([c, c], [])
    Traceback (most recent call last):
    ...
    ValueError: duplicate claim id 'KZL-doc-states'
    """
    seen: set[str] = set()
    for c in all_claims:
        if c.id in seen:
            raise ValueError(f"duplicate claim id {c.id!r}")
        seen.add(c.id)
    eseen: set[str] = set()
    for e in all_errata:
        if e.id in eseen:
            raise ValueError(f"duplicate erratum id {e.id!r}")
        eseen.add(e.id)
    for c in all_claims:
        if c.erratum and c.erratum not in eseen:
            raise ValueError(f"claim {c.id!r} names unknown erratum {c.erratum!r}")
    for c in all_claims:
        for alias in c.aliases:
            if alias in seen:
                raise ValueError(f"alias {alias!r} of claim {c.id!r} is already an id or alias")
            seen.add(alias)
    for e in all_errata:
        for cid in e.claims:
            if cid not in seen:
                raise ValueError(f"erratum {e.id!r} names unknown claim {cid!r}")
    _check_published_is_printed(all_claims)
    from navcore.ledger.inputs import all_inputs

    papers_loaded = {c.paper for c in all_claims}
    for inp in all_inputs():
        if (
            inp.provenance == "fitted"
            and inp.paper in papers_loaded
            and inp.module.startswith("navcore.papers.")
        ):
            unknown = [cid for cid in inp.fitted_to if cid not in seen]
            if unknown:
                raise ValueError(f"fitted input {inp.name} names unknown claims {unknown}")


def _check_published_is_printed(all_claims: list[Claim]) -> None:
    """Refuse a number claim whose quote (the claim's own, or the digits given to ``printed``)
    does not print its published value, unless it is a reasoned exception."""
    from navcore.ledger.allowlists import PUBLISHED_NOT_IN_QUOTE
    from navcore.ledger.core import claim_quote, quote_has_number

    for c in all_claims:
        if c.is_statement or c.id in PUBLISHED_NOT_IN_QUOTE:
            continue
        quote, source = claim_quote(c)
        if source in ("claim", "digits") and not quote_has_number(quote, float(c.published)):
            raise ValueError(
                f"claim {c.id!r}: its published value {c.published!r} is not printed in its quote "
                f"{quote!r}; a number the paper does not print is the book's, so the claim is a "
                "statement whose threshold is a declared convention"
            )


def claims(paper: str | None = None, prefix: str | None = None) -> tuple[Claim, ...]:
    """Registered claims, optionally filtered by paper key and id prefix.

    Importing a paper's modules declares its claims; nothing is computed.

    Parameters
    ----------
    paper : str or None, optional
        Paper key, one of :data:`~navcore.ledger.core.PAPERS` (``"KZL"``); ``None`` for
        every paper. Only that paper's modules are imported.
    prefix : str or None, optional
        Keep only the claims whose id starts with it (``"KZL-eq"``); a prefix that starts
        with a paper key and a dash loads only that paper.

    Returns
    -------
    tuple of Claim
        The claims, by paper in the order of :data:`~navcore.ledger.core.PAPERS`, then in
        the order their modules define them.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.

    Examples
    --------
    >>> kzl = claims("KZL")
    >>> all(c.paper == "KZL" for c in kzl), claims(prefix="KZL-") == kzl
    (True, True)
    """
    if paper is not None and paper not in PAPERS:
        raise ValueError(f"paper must be one of {list(PAPERS)}, got {paper!r}")
    if paper is None and prefix is not None and prefix.split("-", 1)[0] in PAPERS and "-" in prefix:
        paper = prefix.split("-", 1)[0]  # ids start with their paper key
    out = _load(paper)[0]
    if prefix is not None:
        out = tuple(c for c in out if c.id.startswith(prefix))
    return out


def errata(paper: str | None = None) -> tuple[Erratum, ...]:
    """Registered errata, optionally filtered by paper key.

    Parameters
    ----------
    paper : str or None, optional
        Paper key, one of :data:`~navcore.ledger.core.PAPERS`; ``None`` for every paper.

    Returns
    -------
    tuple of Erratum
        The errata, by paper in the order of :data:`~navcore.ledger.core.PAPERS`, then in
        the order their modules define them.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.

    Examples
    --------
    >>> all(e.paper == "KZL" for e in errata("KZL"))
    True
    """
    if paper is not None and paper not in PAPERS:
        raise ValueError(f"paper must be one of {list(PAPERS)}, got {paper!r}")
    return _load(paper)[1]


def claim(claim_id: str) -> Claim:
    """The claim with id ``claim_id``.

    Parameters
    ----------
    claim_id : str
        The claim's id, or one of its former ids (``aliases``).

    Returns
    -------
    Claim
        The registered claim (under its current id).

    Raises
    ------
    ValueError
        If no claim has that id or alias.

    Examples
    --------
    >>> first = claims("KZL")[0]
    >>> claim(first.id) is first
    True
    >>> claim("KZL-no-such-claim")
    Traceback (most recent call last):
    ...
    ValueError: claim_id 'KZL-no-such-claim' is not in the ledger
    """
    key = claim_id.split("-", 1)[0]
    for c in _load(key if key in PAPERS else None)[0]:
        if c.id == claim_id or claim_id in c.aliases:
            return c
    raise ValueError(f"claim_id {claim_id!r} is not in the ledger")


def erratum(erratum_id: str) -> Erratum:
    """The erratum with id ``erratum_id``.

    Parameters
    ----------
    erratum_id : str
        The erratum's id (``"ATC10-E2-erf-argument"``).

    Returns
    -------
    Erratum
        The registered erratum.

    Raises
    ------
    ValueError
        If no erratum has that id.

    Examples
    --------
    >>> first = errata("KZL")[0]
    >>> erratum(first.id) is first
    True
    """
    key = erratum_id.split("-", 1)[0]
    for e in _load(key if key in PAPERS else None)[1]:
        if e.id == erratum_id:
            return e
    raise ValueError(f"erratum_id {erratum_id!r} is not in the ledger")


@cache
def _source_key() -> str:
    """Hash of navcore's sources and the numerical libraries' versions.

    Every claim is a deterministic (seeded) function of these, so an evaluation stored under
    this key can be reused until any of them changes.
    """
    import numpy
    import scipy

    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256(f"numpy {numpy.__version__} scipy {scipy.__version__}".encode())
    for f in sorted(root.rglob("*.py")):
        h.update(str(f.relative_to(root)).encode())
        h.update(f.read_bytes())
    return h.hexdigest()[:20]


def cache_dir() -> Path | None:
    """Folder of the on-disk evaluation cache, or ``None`` when caching is off.

    ``NAVCORE_CACHE=off`` disables it (the test suite and the determinism check do);
    ``NAVCORE_CACHE=<folder>`` chooses its parent folder. By default it lives in
    ``_build/navcore-cache`` of a source checkout, else in ``~/.cache/navcore``. The folder
    is named by a hash of navcore's sources, so a change to any of them starts afresh.

    Returns
    -------
    pathlib.Path or None
        The folder (it need not exist yet), or ``None`` when ``NAVCORE_CACHE`` is ``off``,
        ``0``, ``no`` or ``false``.

    Examples
    --------
    >>> import os
    >>> from unittest import mock
    >>> with mock.patch.dict(os.environ, {"NAVCORE_CACHE": "off"}):
    ...     print(cache_dir())
    None
    >>> with mock.patch.dict(os.environ, {"NAVCORE_CACHE": "/tmp/ledger-cache"}):
    ...     print(cache_dir().parent)
    /tmp/ledger-cache
    """
    setting = os.environ.get("NAVCORE_CACHE", "")
    if setting.lower() in ("off", "0", "no", "false"):
        return None
    if setting:
        parent = Path(setting)
    else:
        checkout = Path(__file__).resolve().parents[2]
        if (checkout / "pyproject.toml").exists() and os.access(checkout, os.W_OK):
            parent = checkout / "_build" / "navcore-cache"
        else:
            parent = Path.home() / ".cache" / "navcore"
    return parent / _source_key()


def _to_json(value: Any) -> Any:
    if value is None or isinstance(value, bool | str):
        return value
    if isinstance(value, list | tuple):
        return [_to_json(v) for v in value]
    if isinstance(value, dict):
        return {k: _to_json(v) for k, v in value.items()}
    if isinstance(value, int):
        return value
    v = float(value)
    return {"float": repr(v)} if not math.isfinite(v) else v


def _from_json(value: Any, sequence: type = tuple) -> Any:
    """Undo :func:`_to_json`; JSON arrays become ``sequence`` (tuples, as the evaluation fields
    hold them; the recorded input values are plain JSON with lists, see ``core.jsonable``)."""
    if isinstance(value, dict):
        if set(value) == {"float"}:
            return float(value["float"])
        return {k: _from_json(v, sequence) for k, v in value.items()}
    if isinstance(value, list):
        return sequence(_from_json(v, sequence) for v in value)
    return value


_RECORD_FIELDS = (
    "reproduced",
    "passes",
    "detail",
    "oracle_value",
    "status",
    "inputs",
    "band",
    "sensitivity",
    "readings",
    "band_too_wide",
)


def _cached(claim_id: str) -> Evaluation | None:
    folder = cache_dir()
    if folder is None:
        return None
    try:
        data = json.loads((folder / f"{claim_id}.json").read_text())
        c = claim(claim_id)
        from navcore.ledger.core import resolve_tolerance

        fields = {k: _from_json(data[k]) for k in _RECORD_FIELDS if k != "inputs"}
        inputs = tuple(_from_json(data["inputs"], sequence=list))
    except (OSError, ValueError, KeyError):
        return None
    return Evaluation(c, **fields, inputs=inputs, tolerance=resolve_tolerance(c))


def _store(ev: Evaluation) -> None:
    folder = cache_dir()
    if folder is None:
        return
    data = {k: _to_json(getattr(ev, k)) for k in _RECORD_FIELDS}
    try:
        folder.mkdir(parents=True, exist_ok=True)
        tmp = folder / f".{ev.claim.id}.{os.getpid()}.tmp"
        tmp.write_text(json.dumps(data))
        tmp.replace(folder / f"{ev.claim.id}.json")  # atomic: readers never see half a file
    except OSError:
        pass  # a read-only location only costs speed


def evaluate_claim(claim_id: str) -> Evaluation:
    """Evaluate one claim (memoised in the process and, unless disabled, on disk).

    ``claim_id`` may be a former id of the claim (one of its ``aliases``); the evaluation
    is the claim's under its current id. The on-disk cache (:func:`cache_dir`) is keyed by
    a hash of navcore's sources, so a stored evaluation is exactly what a fresh evaluation
    would give. A first evaluation runs the claim's model (and its band): from a moment for
    arithmetic to minutes for a Monte Carlo claim.

    Parameters
    ----------
    claim_id : str
        The claim's id, or one of its former ids.

    Returns
    -------
    Evaluation
        The claim's evaluation (:func:`~navcore.ledger.core.evaluate`); the same object on
        every later call in the process.

    Raises
    ------
    ValueError
        If no claim has that id or alias.

    Examples
    --------
    Evaluating a real claim runs its model; an id that is not in the ledger is refused
    before anything runs:

    >>> evaluate_claim("KZL-no-such-claim")
    Traceback (most recent call last):
    ...
    ValueError: claim_id 'KZL-no-such-claim' is not in the ledger
    """
    return _evaluate_claim(claim(claim_id).id)


@cache
def _evaluate_claim(claim_id: str) -> Evaluation:
    hit = _cached(claim_id)
    if hit is not None:
        return hit
    ev = evaluate(claim(claim_id))
    _store(ev)
    return ev


evaluate_claim.cache_clear = _evaluate_claim.cache_clear  # type: ignore[attr-defined]


def evaluations(paper: str | None = None, prefix: str | None = None) -> list[Evaluation]:
    """Evaluate every claim selected by ``paper`` and ``prefix``.

    Each claim goes through :func:`evaluate_claim` (memoised in the process and on disk), so
    the first call for a paper runs all its models: seconds to minutes.

    Parameters
    ----------
    paper : str or None, optional
        Paper key, one of :data:`~navcore.ledger.core.PAPERS`; ``None`` for every paper.
    prefix : str or None, optional
        Keep only the claims whose id starts with it.

    Returns
    -------
    list of Evaluation
        One per selected claim, in the order of :func:`claims`.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.

    Examples
    --------
    A selection without claims evaluates nothing:

    >>> evaluations(paper="KZL", prefix="KZL-no-such-claim")
    []
    """
    return [evaluate_claim(c.id) for c in claims(paper, prefix)]


def counts(paper: str | None = None) -> dict[str, dict[str, int]]:
    """Derived-verdict counts per paper: ``{paper: {status: n, ..., "total": n}}``.

    Every claim of the paper (of every paper, by default) is evaluated through
    :func:`evaluations`.

    Parameters
    ----------
    paper : str or None, optional
        Paper key, one of :data:`~navcore.ledger.core.PAPERS`; ``None`` (or ``""``) for
        every paper.

    Returns
    -------
    dict of str to dict of str to int
        For each paper, the number of claims with each derived verdict of
        :data:`~navcore.ledger.core.STATUSES` (zero included), any other status met (an
        ``error`` of a claim whose evaluation failed) and ``total``.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.

    Examples
    --------
    With the evaluations replaced by the one of a synthetic claim (the real ones take
    minutes):

    >>> from unittest import mock
    >>> from navcore.ledger import EXACT, Claim, evaluate
    >>> c = Claim(id="KZL-doc-states", paper="KZL", locator="Eq. (1)", quantity="states",
    ...           published=15.0, unit="", compute=lambda: 15.0, tolerance=EXACT,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> with mock.patch("navcore.ledger.registry.evaluations", return_value=[evaluate(c)]):
    ...     row = counts("KZL")["KZL"]
    >>> row["reproduced"], row["discrepant"], row["total"]
    (1, 0, 1)
    """
    papers = [paper] if paper else list(PAPERS)
    out: dict[str, dict[str, int]] = {}
    for p in papers:
        row = {s: 0 for s in STATUSES}
        for e in evaluations(p):
            row[e.status] = row.get(e.status, 0) + 1
        row["total"] = sum(v for k, v in row.items())
        out[p] = row
    return out
