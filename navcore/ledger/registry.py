"""The claim and erratum registry.

Claims and errata live in the modules of :mod:`navcore.papers`, one module per paper or
section, each defining module-level ``CLAIMS`` and ``ERRATA`` lists. The registry discovers
every such module, so adding a section never means editing a shared list.
"""

from __future__ import annotations

import ast
import contextlib
import hashlib
import importlib
import json
import os
import pkgutil
import time
import warnings
from collections.abc import Iterator
from functools import cache
from pathlib import Path
from typing import Any

from navcore.claims.declarations import PAPERS, STATUSES, Claim, Erratum
from navcore.claims.evaluation import Evaluation
from navcore.claims.json_coding import from_jsonable, jsonable
from navcore.claims.runs import evaluate

__all__ = [
    "cache_dir",
    "claim",
    "claim_dependencies",
    "claims",
    "counts",
    "errata",
    "erratum",
    "evaluate_claim",
    "evaluate_in_parallel",
    "evaluations",
    "ledger_tasks",
    "paper_modules",
    "validate_registry",
]


@cache
def paper_modules() -> tuple[str, ...]:
    """Names of the modules in :mod:`navcore.papers`, in the papers' reading order.

    Each module defines the ``CLAIMS`` and ``ERRATA`` of one section of a paper; the registry
    imports them on demand (:func:`claims`, :func:`errata`) in this order, which is the order of
    the ledger's rows and of the errata lists: ``navcore.papers.READING_ORDER`` (a
    module it does not list comes after, by name).

    Returns
    -------
    tuple of str
        Full module names (``"navcore.papers.kzl_mechanization"``); modules whose name starts with
        ``_`` are left out.

    Examples
    --------
    >>> names = paper_modules()
    >>> all(name.startswith("navcore.papers.") for name in names)
    True
    >>> names[0]
    'navcore.papers.wf_location_error'
    """
    import navcore.papers as pkg

    found = [m.name for m in pkgutil.iter_modules(pkg.__path__) if not m.name.startswith("_")]
    rank = {name: i for i, name in enumerate(pkg.READING_ORDER)}
    return tuple(f"{pkg.__name__}.{m}" for m in sorted(found, key=lambda m: (rank.get(m, len(rank)), m)))


def _module_paper(name: str) -> str:
    """Paper key of a module named ``<paper>_<section>`` or ``<paper>`` (lower case)."""
    return name.rsplit(".", 1)[-1].split("_", 1)[0].upper()


#: The paper module that defines each loaded claim (claim id -> module name).
_CLAIM_MODULE: dict[str, str] = {}


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
        for c in getattr(module, "CLAIMS", ()):
            _CLAIM_MODULE[c.id] = name
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
    from navcore.claims.inputs import all_inputs

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
    from navcore.claims.quotes import claim_quote, quote_has_number
    from navcore.ledger.allowlists import PUBLISHED_NOT_IN_QUOTE

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
        Paper key, one of :data:`~navcore.claims.declarations.PAPERS` (``"KZL"``); ``None`` for
        every paper. Only that paper's modules are imported.
    prefix : str or None, optional
        Keep only the claims whose id starts with it (``"KZL-eq"``); a prefix that starts
        with a paper key and a dash loads only that paper.

    Returns
    -------
    tuple of Claim
        The claims, by paper in the order of :data:`~navcore.claims.declarations.PAPERS`, then in
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
        Paper key, one of :data:`~navcore.claims.declarations.PAPERS`; ``None`` for every paper.

    Returns
    -------
    tuple of Erratum
        The errata, by paper in the order of :data:`~navcore.claims.declarations.PAPERS`, then in
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


_NAVCORE = Path(__file__).resolve().parents[1]


def _imported_navcore_modules(path: Path) -> set[str]:
    """Names of the navcore modules a source file imports anywhere (top level or in a function).

    Absolute imports only: navcore's code imports by absolute name (the lint's rule TID252 with
    ``ban-relative-imports = "all"`` refuses a relative import), so ``from . import x`` names
    nothing here.
    """
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_bytes())):
        if isinstance(node, ast.Import):
            names.update(a.name for a in node.names if a.name.startswith("navcore"))
        elif isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("navcore"):
            names.add(node.module)
            names.update(f"{node.module}.{a.name}" for a in node.names)  # a submodule imported by name
    return names


def _module_file(name: str) -> Path | None:
    parts = name.split(".")[1:]
    for candidate in (_NAVCORE.joinpath(*parts).with_suffix(".py"), _NAVCORE.joinpath(*parts, "__init__.py")):
        if candidate.is_file():
            return candidate
    return None


#: The ledger's modules that present evaluations (text, tables, the interactive table,
#: summaries): no field of a stored evaluation is computed by them, and no claim's computation
#: imports them (``tests/test_ledger_registry_keys.py`` checks both in a fresh process).
_PRESENTATION = ("summary.py", "text.py", "tables.py", "interactive.py")


@cache
def _module_dependencies(module: str) -> tuple[Path, ...]:
    """The files a claim of ``module`` can execute or read: the navcore modules it imports,
    directly or through other navcore modules, at any level (with each package's
    ``__init__``), the claims' and the ledger's own modules that evaluate (they compute no model value, so
    their own imports are not followed; the modules of :data:`_PRESENTATION` compute no stored
    field and are left out), and navcore's data files.

    A claim's computation reaches navcore's code through these static imports; the modules
    loaded by a computed name (the traceability registry's walk over every module) serve the
    book's indexes, never a claim.
    """
    # the evaluation itself; the modules that present evaluations compute none of a stored
    # evaluation's fields, so a change to them re-renders pages without re-evaluating a claim
    # (unless a module that computes imports them: the walk below adds them then)
    seen: set[Path] = {p for p in _NAVCORE.joinpath("ledger").glob("*.py") if p.name not in _PRESENTATION}
    seen.update(_NAVCORE.joinpath("claims").glob("*.py"))
    todo = [module]
    while todo:
        name = todo.pop()
        for prefix in [".".join(name.split(".")[:i]) for i in range(1, name.count(".") + 2)]:
            path = _module_file(prefix)
            if path is None or path in seen:
                continue
            seen.add(path)
            todo.extend(_imported_navcore_modules(path))
    seen.update(p for p in _NAVCORE.rglob("*") if p.is_file() and p.suffix in (".json", ".csv", ".txt"))
    return tuple(sorted(seen))


@cache
def _file_digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@cache
def _libraries_key() -> str:
    import numpy
    import scipy

    return f"numpy {numpy.__version__} scipy {scipy.__version__}"


def claim_dependencies(claim_id: str) -> tuple[str, ...]:
    """The navcore files (and data files) whose contents key a claim's stored evaluation.

    They are the files of the modules the claim's paper module imports, directly or through
    other navcore modules (imports inside functions included), the ledger's modules that
    evaluate (not those that only present evaluations) and navcore's data files; an evaluation
    can execute or read nothing else of navcore. The
    on-disk cache stores this list with each evaluation, so a change to one model module
    re-evaluates only the claims whose modules import it.

    Parameters
    ----------
    claim_id : str
        The claim's id, or one of its former ids.

    Returns
    -------
    tuple of str
        Paths relative to the ``navcore`` package, sorted.

    Raises
    ------
    ValueError
        If no claim has that id or alias.

    Examples
    --------
    >>> deps = claim_dependencies(claims("KZL")[0].id)
    >>> "claims/runs.py" in deps, "integration/ekf_ins_gnss.py" in deps, "detection/roc.py" in deps
    (True, True, False)
    >>> "ledger/tables.py" in deps
    False
    """
    c = claim(claim_id)
    return tuple(p.relative_to(_NAVCORE).as_posix() for p in _module_dependencies(_CLAIM_MODULE[c.id]))


def _claim_key(claim_id: str) -> str:
    """Hash of the contents of the claim's dependencies and of the numerical libraries' versions."""
    h = hashlib.sha256(_libraries_key().encode())
    for path in _module_dependencies(_CLAIM_MODULE[claim_id]):
        h.update(path.relative_to(_NAVCORE).as_posix().encode())
        h.update(_file_digest(path).encode())
    return h.hexdigest()[:24]


def cache_dir() -> Path | None:
    """Folder of the on-disk evaluation cache, or ``None`` when caching is off.

    ``NAVCORE_CACHE=off`` disables it (the test suite and the determinism check do);
    ``NAVCORE_CACHE_REFRESH=1`` evaluates every claim afresh and stores it, never reading a
    stored evaluation (the determinism check's first run does, so that the book reuses it);
    ``NAVCORE_CACHE=<folder>`` chooses its parent folder. By default it lives in
    ``_build/navcore-cache`` of a source checkout, else in ``~/.cache/navcore``. Each claim's
    stored evaluation is keyed by the contents of the files it depends on
    (:func:`claim_dependencies`) and the numerical libraries' versions, so a change to one
    model module re-evaluates only the claims that import it.

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
    return parent / "claims"


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
    "left_out",
    "envelope",
)


def _strict_evaluation() -> bool:
    """Whether claims are evaluated under the test suite's numerical rules (``NAVCORE_LEDGER_STRICT=1``).

    Then every evaluation runs with numpy's floating-point errors raising (invalid, divide,
    overflow; underflow ignored) and every warning an error, as each test runs: a computation
    that divides by zero or warns evaluates to an ``error``; every other value is the same.
    The test suite and CI's ledger gate set it. A stored evaluation records whether it was
    made so, and a strict process reads only strict ones (a lenient process reads both).
    """
    return os.environ.get("NAVCORE_LEDGER_STRICT", "").lower() in ("1", "yes", "true")


@contextlib.contextmanager
def _strictly() -> Iterator[None]:
    """Floating-point errors raise and warnings are errors inside, if :func:`_strict_evaluation`."""
    if not _strict_evaluation():
        yield
        return
    import numpy as np

    with warnings.catch_warnings(), np.errstate(all="raise", under="ignore"):
        warnings.simplefilter("error")
        yield


def _cached(claim_id: str) -> Evaluation | None:
    folder = cache_dir()
    if folder is None or os.environ.get("NAVCORE_CACHE_REFRESH", "").lower() in ("1", "yes", "true"):
        return None
    try:
        data = json.loads((folder / f"{claim_id}.json").read_text())
        if data.get("key") != _claim_key(claim_id):
            return None  # a file it depends on changed since it was stored
        if _strict_evaluation() and data.get("strict") is not True:
            return None  # made without the strict rules: it may hide a warning
        c = claim(claim_id)
        from navcore.claims.declarations import resolve_tolerance

        fields = {k: from_jsonable(data[k]) for k in _RECORD_FIELDS if k != "inputs"}
        inputs = tuple(from_jsonable(data["inputs"], sequence=list))
    except (OSError, ValueError, KeyError):
        return None
    return Evaluation(c, **fields, inputs=inputs, tolerance=resolve_tolerance(c))


def _store(ev: Evaluation) -> None:
    folder = cache_dir()
    if folder is None:
        return
    data = {k: jsonable(getattr(ev, k), round_trip=True) for k in _RECORD_FIELDS}
    data["key"] = _claim_key(ev.claim.id)
    data["strict"] = _strict_evaluation()
    data["dependencies"] = list(claim_dependencies(ev.claim.id))
    try:
        folder.mkdir(parents=True, exist_ok=True)
        tmp = folder / f".{ev.claim.id}.{os.getpid()}.tmp"
        tmp.write_text(json.dumps(data))
        tmp.replace(folder / f"{ev.claim.id}.json")  # atomic: readers never see half a file
    except OSError:
        pass  # a read-only location only costs speed


#: Evaluations made (or read from disk) in this process, by claim id.
_MEMO: dict[str, Evaluation] = {}


def evaluate_claim(claim_id: str) -> Evaluation:
    """Evaluate one claim (memoised in the process and, unless disabled, on disk).

    ``claim_id`` may be a former id of the claim (one of its ``aliases``); the evaluation
    is the claim's under its current id. The on-disk cache (:func:`cache_dir`) is keyed by
    the contents of the files the claim depends on (:func:`claim_dependencies`), so a stored
    evaluation is exactly what a fresh evaluation would give. A first evaluation runs the
    claim's model (and its band): from a moment for arithmetic to seconds for a Monte Carlo
    claim. With ``NAVCORE_LEDGER_STRICT=1`` (the test suite, CI's ledger gate) it runs with
    numpy's floating-point errors raising and warnings as errors, and reads only stored
    evaluations made that way.

    Parameters
    ----------
    claim_id : str
        The claim's id, or one of its former ids.

    Returns
    -------
    Evaluation
        The claim's evaluation (:func:`~navcore.claims.runs.evaluate`); the same object on
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
    cid = claim(claim_id).id
    if cid not in _MEMO:
        hit = _cached(cid)
        if hit is None:
            with _strictly():
                hit = evaluate(claim(cid))
            _store(hit)
        _MEMO[cid] = hit
    return _MEMO[cid]


evaluate_claim.cache_clear = _MEMO.clear  # type: ignore[attr-defined]


def _group_records(claim_ids: tuple[str, ...]) -> list[tuple[str, dict[str, Any], float]]:
    """Evaluate claims one after another in this process (a worker's task): their fields and seconds.

    The claims of one task share this process's memoised model runs (``input_cache``).
    """
    out = []
    for cid in claim_ids:
        start = time.perf_counter()
        ev = evaluate_claim(cid)
        out.append((cid, {k: getattr(ev, k) for k in _RECORD_FIELDS}, time.perf_counter() - start))
    return out


#: Paper modules whose claims read the same model runs, evaluated in one task (the first module
#: names it) so that each shared run is made once. None today: the claims that read SP's flyby
#: runs (Table 2.7 cell by cell among them) all live in its flyby module.
_SHARED_RUNS: tuple[tuple[str, ...], ...] = ()

#: Claims that read model runs shared with no other claim of their modules, in a task of their
#: own (its name, the modules, the claim-id prefixes), so that the two longest modules split
#: across the cores: SP's helicopter mission (Sec. 2.6.4's claims and Fig. 2.9's helicopter
#: curve, whose runs the rest of the missions module does not read).
_CLAIM_TASKS: tuple[tuple[str, tuple[str, ...], tuple[str, ...]], ...] = (
    (
        "SP helicopter mission",
        ("navcore.papers.sp_missions",),
        ("SP-sec2.6.4-", "SP-fig2.9-heli"),
    ),
)

#: Seconds of CPU each task's claims took to evaluate afresh with their bands, measured on the
#: reference machine (2 cores, the CI simulation's ledger gate): only the order in which the
#: parallel ledger hands out its tasks (longest first) uses them. ``python -m navcore ledger
#: --times`` prints the current ones.
_TASK_SECONDS = {
    "navcore.papers.sp_flyby": 151.0,
    "SP helicopter mission": 73.0,
    "navcore.papers.sp_missions": 108.0,
    "navcore.papers.kzl_simulation": 97.0,
    "navcore.papers.atc10_jamming_appendices": 10.0,
    "navcore.papers.atc10_gaussian_comparison": 5.2,
    "navcore.papers.atc10_multiple_access": 3.1,
    "navcore.papers.atc10_roc_bounds": 2.2,
    "navcore.papers.sp_antijam": 5.7,
    "navcore.papers.wf_location_error": 4.4,
    "navcore.papers.atc10_clock_tracking": 1.8,
    "navcore.papers.atc10_zakai_bandwidth": 1.0,
    "navcore.papers.atc10_tracking_examples": 0.4,
    "navcore.papers.sp_tracking": 0.7,
    "navcore.papers.atc10_tracking_lists": 1.9,
    "navcore.papers.atc10_system_tables": 1.2,
    "navcore.papers.atc10_single_pulse": 1.1,
}


def ledger_task(claim_id: str) -> str:
    """The parallel ledger's task of a claim: the ``_CLAIM_TASKS`` task it belongs to, else its
    paper module, or the first module of the ``_SHARED_RUNS`` group the module belongs to.

    Parameters
    ----------
    claim_id : str
        A claim id (current or former).

    Returns
    -------
    str
        The task's name (a module name, or the name of a ``_CLAIM_TASKS`` task).

    Examples
    --------
    >>> ledger_task("SP-fig2.7-tc10") == ledger_task("SP-tab2.7-tc10-sv3")
    True
    >>> ledger_task("SP-sec2.6.4-doppler-improves") == ledger_task("SP-fig2.9-heli-1nmi")
    True
    """
    cid = claim(claim_id).id
    module = _CLAIM_MODULE[cid]
    for name, modules, prefixes in _CLAIM_TASKS:
        if module in modules and cid.startswith(prefixes):
            return name
    return next((group[0] for group in _SHARED_RUNS if module in group), module)


def ledger_tasks(claim_ids: list[str]) -> list[tuple[str, ...]]:
    """Split claims into the parallel ledger's tasks (``ledger_task``), longest first.

    The claims of a paper module read the same model runs (one flyby, one Monte Carlo, one
    mission), so they run in one process, which computes each shared run once.

    Parameters
    ----------
    claim_ids : list of str
        Current claim ids.

    Returns
    -------
    list of tuple of str
        The claim ids of each task, in the order given within a task (registry order when
        called through :func:`evaluations`); tasks ordered by their usual evaluation time
        (measured seconds kept in the module), longest first.

    Examples
    --------
    >>> ids = [c.id for c in claims("KZL")]
    >>> tasks = ledger_tasks(ids)
    >>> sorted(i for t in tasks for i in t) == sorted(ids)
    True
    """
    groups: dict[str, list[str]] = {}
    for cid in claim_ids:
        groups.setdefault(ledger_task(cid), []).append(cid)
    order = sorted(groups, key=lambda m: -_TASK_SECONDS.get(m, 0.1))
    return [tuple(groups[m]) for m in order]


def evaluate_in_parallel(claim_ids: list[str], n_jobs: int | None = -1) -> dict[str, float]:
    """Evaluate claims across worker processes and keep the evaluations in this process.

    The claims that are neither memoised nor on disk go to :func:`navcore.parallel.run_tasks`
    in the tasks of :func:`ledger_tasks`; each evaluation is the one a serial run gives, bit
    for bit (the workers run the same :func:`~navcore.claims.runs.evaluate`, and the fields
    come back pickled). Later calls of :func:`evaluate_claim` return them.

    Parameters
    ----------
    claim_ids : list of str
        Claim ids (current or former).
    n_jobs : int or None, optional
        Workers, as :func:`navcore.parallel.run_tasks` takes them (default every core).

    Returns
    -------
    dict of str to float
        Seconds each evaluated claim took in its worker (claims already known: absent).

    Examples
    --------
    >>> evaluate_in_parallel([], n_jobs=2)
    {}
    """
    from navcore.parallel import run_tasks

    todo = []
    for cid in dict.fromkeys(claim(i).id for i in claim_ids):
        if cid in _MEMO:
            continue
        hit = _cached(cid)
        if hit is not None:
            _MEMO[cid] = hit
        else:
            todo.append(cid)
    seconds: dict[str, float] = {}
    if not todo:
        return seconds
    from navcore.claims.declarations import resolve_tolerance

    for records in run_tasks(_group_records, [(t,) for t in ledger_tasks(todo)], n_jobs=n_jobs):
        for cid, fields, elapsed in records:
            c = claim(cid)
            fields = {k: v for k, v in fields.items() if k != "inputs"} | {"inputs": fields["inputs"]}
            _MEMO[cid] = Evaluation(c, **fields, tolerance=resolve_tolerance(c))  # the worker stored it
            seconds[cid] = elapsed
    return seconds


def evaluations(
    paper: str | None = None, prefix: str | None = None, *, n_jobs: int | None = None
) -> list[Evaluation]:
    """Evaluate every claim selected by ``paper`` and ``prefix``.

    Each claim goes through :func:`evaluate_claim` (memoised in the process and on disk), so
    the first call for a paper runs all its models: seconds to minutes. With ``n_jobs`` the
    claims not yet known are evaluated in worker processes first
    (:func:`evaluate_in_parallel`); the evaluations are the same, bit for bit.

    Parameters
    ----------
    paper : str or None, optional
        Paper key, one of :data:`~navcore.claims.declarations.PAPERS`; ``None`` for every paper.
    prefix : str or None, optional
        Keep only the claims whose id starts with it.
    n_jobs : int or None, optional
        ``None`` (default): evaluate in this process; ``-1`` on every core, ``k`` on ``k``
        workers (:func:`navcore.parallel.run_tasks`).

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
    selected = claims(paper, prefix)
    if n_jobs not in (None, 0, 1):
        evaluate_in_parallel([c.id for c in selected], n_jobs)
    return [evaluate_claim(c.id) for c in selected]


def counts(paper: str | None = None) -> dict[str, dict[str, int]]:
    """Derived-verdict counts per paper: ``{paper: {status: n, ..., "total": n}}``.

    Every claim of the paper (of every paper, by default) is evaluated through
    :func:`evaluations`.

    Parameters
    ----------
    paper : str or None, optional
        Paper key, one of :data:`~navcore.claims.declarations.PAPERS`; ``None`` (or ``""``) for
        every paper.

    Returns
    -------
    dict of str to dict of str to int
        For each paper, the number of claims with each derived verdict of
        :data:`~navcore.claims.declarations.STATUSES` (zero included), any other status met (an
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
