"""The claim registry (``navcore.ledger.registry``) on a synthetic registry (issue 31, mutation
survivors): loading and looking up claims and errata, the parallel ledger's tasks, evaluating
in this process and across workers, the counts, and the on-disk evaluation cache (its folder,
its JSON round trip, its key over a claim's dependencies).

No paper module is imported and no real claim is evaluated: each test installs a handful of
synthetic paper modules (closed-form claims, in ``sys.modules``), a small source tree standing
for ``navcore/`` (the files a claim's stored evaluation depends on) and an empty cache folder
under ``tmp_path``. Each test names its oracle.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
import types
from dataclasses import fields
from pathlib import Path
from typing import Any

import joblib
import numpy as np
import pytest

from navcore.claims import declarations as claim_declarations
from navcore.claims import inputs as ledger_inputs
from navcore.claims.json_coding import from_jsonable, jsonable
from navcore.ledger import EXACT, Claim, Erratum, InputSet, evaluate, printed, registry

IN = InputSet("WF", "mutation_registry")
IN.published("arr", np.array([1.0, 2.5]), locator="Eq. (2)")

P = "navcore.papers."


def _claim(cid: str, value: float = 15.0, **kw: Any) -> Claim:
    base: dict[str, Any] = dict(
        id=cid,
        paper=cid.split("-", 1)[0],
        locator="Eq. (1)",
        quantity="states",
        published=15.0,
        unit="",
        compute=lambda: value,
        tolerance=EXACT,
        expected_status="reproduced",
        note="a synthetic claim",
    )
    base.update(kw)
    return Claim(**base)


def _fails() -> float:
    raise RuntimeError("the model failed")


def _module(name: str, claims: list[Claim], errata: list[Erratum] = ()) -> types.ModuleType:  # type: ignore[assignment]
    module = types.ModuleType(name)
    module.CLAIMS = list(claims)  # type: ignore[attr-defined]
    module.ERRATA = list(errata)  # type: ignore[attr-defined]
    return module


class _Exploding(types.ModuleType):
    """A paper module that must not be loaded: reading its lists raises."""

    def __getattr__(self, name: str) -> Any:
        raise RuntimeError(f"{self.__name__} was loaded")


# the synthetic source tree: paper module -> navcore.models.a -> navcore.models.b (in a
# function); a claims module imports navcore.models.c, which is not followed
SOURCES = {
    "__init__.py": "",
    "claims/__init__.py": "",
    "claims/runs.py": "import navcore.models.c\n",
    "ledger/__init__.py": "",
    "papers/__init__.py": "",
    "models/__init__.py": "",
    "models/a.py": "import os\n\n\ndef f():\n    from navcore.models import b\n    return b, os\n",
    "models/b.py": "X = 1\n",
    "models/c.py": "X = 2\n",
    "models/unused.py": "X = 3\n",
    "data/table.json": "{}\n",
    "data/rows.csv": "a,b\n",
    "data/read.txt": "text\n",
    "data/notes.md": "not data\n",
}


@pytest.fixture(autouse=True)
def _own_errata(monkeypatch):
    """Every erratum constructed registers itself (``claim_errata``): the synthetic ones here only."""
    monkeypatch.setattr(claim_declarations, "_ERRATA_BY_ID", dict(claim_declarations._ERRATA_BY_ID))


@pytest.fixture
def synthetic(monkeypatch, tmp_path):
    """Install a synthetic registry; yield a function that installs one set of modules."""
    root = tmp_path / "src" / "navcore"
    for rel, text in SOURCES.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    monkeypatch.setattr(registry, "_NAVCORE", root)
    monkeypatch.setattr(registry, "_CLAIM_MODULE", {})
    monkeypatch.setattr(registry, "_MEMO", {})
    monkeypatch.setattr(registry, "_SHARED_RUNS", ((P + "kzl_delta", P + "wf_gamma"),))
    monkeypatch.setattr(
        registry, "_TASK_SECONDS", {P + "wf_beta": 5.0, P + "kzl_delta": 0.5, P + "wf_gamma": 0.2}
    )
    monkeypatch.setattr(ledger_inputs, "all_inputs", lambda paper=None: ())
    monkeypatch.setenv("NAVCORE_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv("NAVCORE_CACHE_REFRESH", raising=False)
    monkeypatch.delenv("NAVCORE_LEDGER_STRICT", raising=False)

    def install(modules: dict[str, types.ModuleType]) -> Path:
        for name, module in modules.items():
            monkeypatch.setitem(sys.modules, name, module)
            (root / "papers" / f"{name.rsplit('.', 1)[-1]}.py").write_text("import navcore.models.a\n")
        monkeypatch.setattr(registry, "paper_modules", lambda: tuple(sorted(modules)))
        registry._load.cache_clear()
        return root

    def clear() -> None:
        for f in (registry._load, registry._module_dependencies, registry._file_digest):
            f.cache_clear()

    clear()
    yield install
    clear()


def _errata() -> tuple[Erratum, Erratum]:
    slip = Erratum(
        id="WF-E901-slip", locator="Eq. (3)", printed="2", finding="1", evidence="the derivation",
        claims=("WF-b2",), kind="typography", basis="text-only",
    )  # fmt: skip
    typo = Erratum(
        id="KZL-E901-typo", locator="Eq. (4)", printed="p", finding="f", evidence="e",
        claims=("KZL-d1",), kind="typography", basis="text-only",
    )  # fmt: skip
    return slip, typo


def standard_modules() -> dict[str, types.ModuleType]:
    """WF: alpha (a reproduced claim with a former id, one whose model fails), beta (a
    reproduced claim, a discrepancy and its erratum), gamma (run with KZL's delta); KZL: delta."""
    slip, typo = _errata()
    return {
        P + "wf_alpha": _module(
            P + "wf_alpha",
            [_claim("WF-a1", aliases=("WF-old-a1",)), _claim("WF-a2", compute=_fails)],
        ),
        P + "wf_beta": _module(
            P + "wf_beta",
            [
                _claim("WF-b1", compute=lambda: float(IN.arr.sum()), published=3.5),
                _claim(
                    "WF-b2",
                    1.0,
                    published=2.0,
                    expected_status="discrepant",
                    erratum="WF-E901-slip",
                    oracle=lambda: 1.0,
                    oracle_tolerance=EXACT,
                ),
            ],
            [slip],
        ),
        P + "wf_gamma": _module(P + "wf_gamma", [_claim("WF-c1")]),
        P + "kzl_delta": _module(P + "kzl_delta", [_claim("KZL-d1")], [typo]),
    }


ALL_IDS = ["WF-a1", "WF-a2", "WF-b1", "WF-b2", "WF-c1", "KZL-d1"]


def _same(a, b) -> None:
    for f in fields(a):
        assert getattr(a, f.name) == getattr(b, f.name), f.name


# --- loading and looking up --------------------------------------------------------------------


def test_module_paper_is_the_first_word_of_the_module_name():
    """Oracle: the module naming rule ``<paper>_<section>``, read off the names."""
    assert registry._module_paper("navcore.papers.atc10_roc_bounds") == "ATC10"
    assert registry._module_paper("navcore.papers.wf") == "WF"
    assert registry._module_paper("kzl_a_b") == "KZL"


def test_claims_errata_and_lookups(synthetic):
    """Claims by paper (in PAPERS order), by prefix, by id and former id; errata likewise.
    Oracle: the synthetic modules' lists, written out."""
    synthetic(standard_modules())
    assert [c.id for c in registry.claims()] == ALL_IDS
    assert [c.id for c in registry.claims("KZL")] == ["KZL-d1"]
    assert [c.id for c in registry.claims(prefix="WF-b")] == ["WF-b1", "WF-b2"]
    assert [c.id for c in registry.claims("WF", prefix="WF-a")] == ["WF-a1", "WF-a2"]
    assert registry.claims("SP") == ()
    assert registry.claim("WF-old-a1") is registry.claim("WF-a1")
    assert registry.claim("KZL-d1").published == 15.0
    assert [e.id for e in registry.errata()] == ["WF-E901-slip", "KZL-E901-typo"]
    assert [e.id for e in registry.errata("KZL")] == ["KZL-E901-typo"]
    assert registry.erratum("WF-E901-slip").claims == ("WF-b2",)
    assert registry.erratum("KZL-E901-typo").paper == "KZL"
    for bad in ("SPX", "wf", ""):
        with pytest.raises(ValueError, match="paper must be one of"):
            registry.claims(bad)
        with pytest.raises(ValueError, match="paper must be one of"):
            registry.errata(bad)
    with pytest.raises(ValueError, match=r"claim_id 'WF-zz' is not in the ledger"):
        registry.claim("WF-zz")
    with pytest.raises(ValueError, match=r"claim_id 'XX-a1' is not in the ledger"):
        registry.claim("XX-a1")
    with pytest.raises(ValueError, match=r"erratum_id 'WF-E902' is not in the ledger"):
        registry.erratum("WF-E902")
    with pytest.raises(ValueError, match=r"erratum_id 'slip' is not in the ledger"):
        registry.erratum("slip")
    with pytest.raises(ValueError, match=r"erratum_id 'WF-E901-slip-x' is not in the ledger"):
        registry.erratum("WF-E901-slip-x")


def test_a_paper_key_loads_only_that_papers_modules(synthetic):
    """A paper key, an id or a prefix ``<paper>-`` imports only that paper's modules; anything
    else imports them all. Oracle: a module of another paper that raises when it is read."""
    mods = standard_modules()
    mods[P + "atc10_eps"] = _Exploding(P + "atc10_eps")
    mods[P + "kzl_zeta"] = _module(P + "kzl_zeta", [_claim("KZL-z-1")])
    synthetic(mods)
    assert [c.id for c in registry.claims(prefix="KZL-z-")] == ["KZL-z-1"]  # the key before the first dash
    assert len(registry.claims("WF")) == 5
    assert [c.id for c in registry.claims(prefix="KZL-")] == ["KZL-d1", "KZL-z-1"]
    assert registry.claim("WF-old-a1").id == "WF-a1"
    assert registry.erratum("KZL-E901-typo").paper == "KZL"
    assert registry.errata("WF")[0].id == "WF-E901-slip"
    for load_all in (
        lambda: registry.claims(),
        lambda: registry.claims(prefix="WF"),  # no dash: not known to be a paper's
        lambda: registry.claims(prefix="XX-"),
        lambda: registry.errata(),
        lambda: registry.claim("a1"),
        lambda: registry.erratum("E901"),
    ):
        with pytest.raises(RuntimeError, match="atc10_eps was loaded"):
            load_all()


def test_a_module_named_for_one_paper_may_not_define_another_papers_items(synthetic):
    """Oracle: the stray rule of ``_load``; loading every paper does not apply it."""
    synthetic({P + "wf_odd": _module(P + "wf_odd", [_claim("KZL-x")])})
    with pytest.raises(ValueError, match=r"modules named for WF define items of another paper: \['KZL-x'\]"):
        registry.claims("WF")
    assert [c.id for c in registry.claims()] == ["KZL-x"]


def test_validate_registry_links_and_fitted_inputs(monkeypatch):
    """Duplicate ids and aliases, links between claims and errata, fitted inputs of a loaded
    paper naming unknown claims. Oracle: the rules of ``validate_registry``'s docstring."""
    slip, _ = _errata()
    b2 = _claim("WF-b2", 1.0, published=2.0, expected_status="discrepant", erratum="WF-E901-slip",
                oracle=lambda: 1.0, oracle_tolerance=EXACT)  # fmt: skip
    monkeypatch.setattr(ledger_inputs, "all_inputs", lambda paper=None: ())
    registry.validate_registry([b2], [slip])
    with pytest.raises(ValueError, match="duplicate erratum id 'WF-E901-slip'"):
        registry.validate_registry([b2], [slip, slip])
    with pytest.raises(ValueError, match="names unknown erratum"):
        registry.validate_registry([b2], [])
    with pytest.raises(ValueError, match="alias 'WF-b2' of claim 'WF-x' is already an id or alias"):
        registry.validate_registry([b2, _claim("WF-x", aliases=("WF-b2",))], [slip])
    with pytest.raises(ValueError, match="alias 'WF-y' of claim 'WF-z'"):
        registry.validate_registry([_claim("WF-x", aliases=("WF-y",)), _claim("WF-z", aliases=("WF-y",))], [])
    # an erratum may name a claim by a former id
    registry.validate_registry([_claim("WF-b3", aliases=("WF-b2",))], [slip])

    def fitted(paper, module, to, provenance="fitted"):
        return types.SimpleNamespace(
            provenance=provenance, paper=paper, module=module, fitted_to=to, name="g"
        )

    known = [_claim("WF-a1", aliases=("WF-old",))]
    cases = [
        (fitted("WF", P + "wf_x", ("WF-a1", "WF-old")), None),
        (fitted("WF", P + "wf_x", ("WF-a1", "WF-q")), r"fitted input g names unknown claims \['WF-q'\]"),
        (fitted("SP", P + "sp_x", ("SP-q",)), None),  # SP not loaded
        (fitted("WF", "tests.x", ("WF-q",)), None),  # not a paper module's
        (fitted("WF", P + "wf_x", ("WF-q",), provenance="assumed"), None),  # not fitted
    ]  # fmt: skip
    for inp, error in cases:
        monkeypatch.setattr(ledger_inputs, "all_inputs", lambda paper=None, inp=inp: (inp,))
        if error is None:
            registry.validate_registry(known, [])
        else:
            with pytest.raises(ValueError, match=error):
                registry.validate_registry(known, [])


def test_published_value_must_be_printed_in_the_quote(monkeypatch):
    """Oracle: a quote (the claim's own, or the digits given to ``printed``) that prints 15
    passes, one that prints 16 is refused, unless the claim is a statement or on the allowlist."""
    from navcore.ledger import allowlists

    monkeypatch.setattr(ledger_inputs, "all_inputs", lambda paper=None: ())
    registry.validate_registry([_claim("WF-q", printed="the filter has 15 states")], [])
    bad = _claim("WF-q", printed="the filter has 16 states")
    with pytest.raises(
        ValueError, match=r"claim 'WF-q': its published value 15.0 is not printed in its quote"
    ):
        registry.validate_registry([bad], [])
    # every claim is checked, also after a statement or an allowlisted claim
    statement = _claim("WF-s", published=True, unit="statement", compute=lambda: True)
    with pytest.raises(ValueError, match="claim 'WF-q'"):
        registry.validate_registry([statement, bad], [])
    # the digits given to printed() are the quote when the claim has none
    registry.validate_registry([_claim("WF-r", tolerance=printed("15")[1])], [])
    digits = _claim("WF-r", tolerance=printed("16")[1])
    with pytest.raises(
        ValueError, match=r"claim 'WF-r': its published value 15.0 is not printed in its quote '16'"
    ):
        registry.validate_registry([digits], [])
    monkeypatch.setattr(allowlists, "PUBLISHED_NOT_IN_QUOTE", {"WF-q": "a unit conversion"})
    registry.validate_registry([bad], [])
    with pytest.raises(ValueError, match="claim 'WF-r'"):
        registry.validate_registry([bad, digits], [])


# --- dependencies and the cache key ------------------------------------------------------------


def test_imported_navcore_modules_at_any_level(tmp_path):
    """Oracle: the imports of a small source file, listed by hand."""
    src = tmp_path / "m.py"
    src.write_text(
        "import os\nimport navcore.a\nimport navcore.e as E, json\nfrom os import path\n"
        "from navcore.b import c, d\nfrom . import x\nfrom .y import z\n\n\n"
        "def f():\n    import navcore.f\n    from navcore.g import h\n"
    )
    assert registry._imported_navcore_modules(src) == {
        "navcore.a", "navcore.e", "navcore.b", "navcore.b.c", "navcore.b.d", "navcore.f",
        "navcore.g", "navcore.g.h",
    }  # fmt: skip


def test_module_file_and_dependencies(synthetic):
    """The files a claim's evaluation depends on: its module, what it imports through other
    modules (with each package's ``__init__``), the claims' and the ledger's files (not their imports) and the
    data files. Oracle: the synthetic tree's import graph, followed by hand."""
    root = synthetic(standard_modules())
    assert registry._module_file("navcore.models.a") == root / "models" / "a.py"
    assert registry._module_file("navcore.models") == root / "models" / "__init__.py"
    assert registry._module_file("navcore") == root / "__init__.py"
    assert registry._module_file("navcore.models.nothing") is None
    assert registry._module_file("navcore.data") is None
    expected = (
        "__init__.py", "claims/__init__.py", "claims/runs.py", "data/read.txt", "data/rows.csv",
        "data/table.json", "ledger/__init__.py", "models/__init__.py", "models/a.py", "models/b.py",
        "papers/__init__.py", "papers/wf_alpha.py",
    )  # fmt: skip
    assert registry.claim_dependencies("WF-old-a1") == expected
    assert registry._module_dependencies(P + "wf_alpha") == tuple(root / p for p in expected)
    with pytest.raises(ValueError, match="not in the ledger"):
        registry.claim_dependencies("WF-zz")


def test_claim_key_follows_the_dependencies_contents(synthetic):
    """The key changes with a dependency's contents, with which file holds which contents, and
    with the libraries' versions; not with a file the claim does not depend on. Oracle: the
    key's definition (sha256 of the dependencies' paths and contents), by edits of the tree."""
    root = synthetic(standard_modules())
    registry.claims()
    import numpy
    import scipy

    assert registry._libraries_key() == f"numpy {numpy.__version__} scipy {scipy.__version__}"
    assert registry._file_digest(root / "models" / "b.py") == hashlib.sha256(b"X = 1\n").hexdigest()

    def key() -> str:
        for f in (registry._module_dependencies, registry._file_digest):
            f.cache_clear()
        return registry._claim_key("WF-a1")

    first = key()
    assert len(first) == 24 and int(first, 16) >= 0
    assert key() == first and registry._claim_key("WF-a2") == first  # one module, one key
    (root / "models" / "unused.py").write_text("X = 4\n")
    (root / "models" / "c.py").write_text("X = 5\n")  # imported by the ledger only
    assert key() == first
    (root / "models" / "b.py").write_text("X = 6\n")
    assert key() != first
    (root / "models" / "b.py").write_text("X = 1\n")
    assert key() == first
    # the same two contents, swapped between two files: another key
    rows, read = root / "data" / "rows.csv", root / "data" / "read.txt"
    rows.write_text("text\n")
    read.write_text("a,b\n")
    assert key() != first
    rows.write_text("a,b\n")
    read.write_text("text\n")
    assert key() == first
    registry._libraries_key.cache_clear()
    try:
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(numpy, "__version__", "0.0")
            assert key() != first
    finally:
        registry._libraries_key.cache_clear()
    assert key() == first


# --- the cache folder and the JSON round trip ---------------------------------------------------


def test_cache_dir_settings(monkeypatch, tmp_path):
    """Oracle: the settings of ``cache_dir``'s docstring, one by one (the default checkout and
    home folders given by a stand-in module path and HOME)."""
    for off in ("off", "OFF", "0", "no", "False"):
        monkeypatch.setenv("NAVCORE_CACHE", off)
        assert registry.cache_dir() is None
    monkeypatch.setenv("NAVCORE_CACHE", str(tmp_path / "c"))
    assert registry.cache_dir() == tmp_path / "c" / "claims"
    monkeypatch.setenv("NAVCORE_CACHE", "")
    checkout = tmp_path / "checkout"
    (checkout / "navcore" / "ledger").mkdir(parents=True)
    monkeypatch.setattr(registry, "__file__", str(checkout / "navcore" / "ledger" / "registry.py"))
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    writable: list[Any] = []
    monkeypatch.setattr(
        os, "access", lambda path, mode: writable.append((Path(path), mode)) or mode == os.W_OK
    )
    home = tmp_path / "home" / ".cache" / "navcore" / "claims"
    assert registry.cache_dir() == home  # not a source checkout
    (checkout / "pyproject.toml").write_text("")
    monkeypatch.delenv("NAVCORE_CACHE")
    assert registry.cache_dir() == checkout / "_build" / "navcore-cache" / "claims"
    assert writable == [(checkout, os.W_OK)]
    monkeypatch.setattr(os, "access", lambda path, mode: False)  # read-only checkout
    assert registry.cache_dir() == home


@pytest.mark.parametrize(
    ("value", "stored"),
    [
        (None, None),
        (True, True),
        ("text", "text"),
        (3, 3),
        (np.int64(3), 3.0),
        (np.float64(2.5), 2.5),
        (float("inf"), {"float": "inf"}),
        (-float("inf"), {"float": "-inf"}),
        ((1, (2.5, "a")), [1, [2.5, "a"]]),
        ({"k": [np.float64(-np.inf), None]}, {"k": [{"float": "-inf"}, None]}),
    ],
)
def test_jsonable_round_trip(value, stored):
    """Oracle: the JSON forms written out by hand (types included)."""
    out = jsonable(value, round_trip=True)
    assert out == stored and type(out) is type(stored)
    assert json.loads(json.dumps(out)) == stored


def test_from_jsonable_undoes_jsonable():
    """Oracle: the values before ``jsonable``, with arrays as tuples (or lists, when asked)."""
    assert np.isnan(from_jsonable(jsonable(float("nan"), round_trip=True)))
    assert from_jsonable({"float": "-inf"}) == -float("inf")
    assert from_jsonable({"float": "1.5", "other": [1]}) == {"float": "1.5", "other": (1,)}
    assert from_jsonable([1, [2, {"a": [3]}]]) == (1, (2, {"a": (3,)}))
    out = from_jsonable([1, [2, {"a": [3]}]], sequence=list)
    assert out == [1, [2, {"a": [3]}]] and isinstance(out[1], list) and isinstance(out[1][1]["a"], list)
    assert from_jsonable("x") == "x" and from_jsonable(None) is None


def test_strict_evaluation_setting(monkeypatch):
    """Oracle: the values ``NAVCORE_LEDGER_STRICT`` documents as on."""
    for on in ("1", "yes", "TRUE", "true"):
        monkeypatch.setenv("NAVCORE_LEDGER_STRICT", on)
        assert registry._strict_evaluation() is True
    for off in ("", "0", "no", "2"):
        monkeypatch.setenv("NAVCORE_LEDGER_STRICT", off)
        assert registry._strict_evaluation() is False
    monkeypatch.delenv("NAVCORE_LEDGER_STRICT")
    assert registry._strict_evaluation() is False


def test_store_and_read_back(synthetic, tmp_path, monkeypatch):
    """A stored evaluation reads back equal to the fresh one (an error, a discrepancy, a
    recorded array input as a list); the file holds the key, the strict flag and the
    dependencies; nothing else is left in the folder. Oracle: ``evaluate`` of the same
    synthetic claim, and the file's JSON."""
    synthetic(standard_modules())
    folder = tmp_path / "cache" / "claims"
    for cid in ("WF-a2", "WF-b1", "WF-b2"):
        fresh = evaluate(registry.claim(cid))
        registry._store(fresh)
        data = json.loads((folder / f"{cid}.json").read_text())
        assert data["key"] == registry._claim_key(cid)
        assert data["strict"] is False
        assert data["dependencies"] == list(registry.claim_dependencies(cid))
        assert set(data) == {*registry._RECORD_FIELDS, "key", "strict", "dependencies"}
        back = registry._cached(cid)
        assert back is not None
        _same(back, fresh)
    assert sorted(p.name for p in folder.iterdir()) == ["WF-a2.json", "WF-b1.json", "WF-b2.json"]
    back = registry._cached("WF-b1")
    assert back.inputs == evaluate(registry.claim("WF-b1")).inputs and isinstance(back.inputs, tuple)
    assert isinstance(back.inputs[0]["value"], list)
    assert back.status == "reproduced" and registry._cached("WF-a2").status == "error"
    assert registry._cached("WF-a1") is None  # never stored


def test_when_a_stored_evaluation_is_not_read(synthetic, tmp_path, monkeypatch):
    """Not read: caching off, a refresh asked for, a changed dependency, a lenient evaluation in
    a strict process, a damaged or incomplete file. Oracle: the rules of ``cache_dir`` and
    ``evaluate_claim``'s docstrings, one case each."""
    root = synthetic(standard_modules())
    cid = "WF-c1"
    registry._store(evaluate(registry.claim(cid)))
    stored = tmp_path / "cache" / "claims" / f"{cid}.json"
    assert registry._cached(cid) is not None
    for refresh in ("1", "yes", "TRUE"):
        monkeypatch.setenv("NAVCORE_CACHE_REFRESH", refresh)
        assert registry._cached(cid) is None
    monkeypatch.setenv("NAVCORE_CACHE_REFRESH", "0")
    assert registry._cached(cid) is not None
    monkeypatch.setenv("NAVCORE_LEDGER_STRICT", "1")
    assert registry._cached(cid) is None
    monkeypatch.delenv("NAVCORE_LEDGER_STRICT")
    (root / "models" / "b.py").write_text("X = 7\n")
    registry._file_digest.cache_clear()
    assert registry._cached(cid) is None
    (root / "models" / "b.py").write_text("X = 1\n")
    registry._file_digest.cache_clear()
    assert registry._cached(cid) is not None
    good = stored.read_text()
    for damaged in ("{", json.dumps({k: v for k, v in json.loads(good).items() if k != "band"})):
        stored.write_text(damaged)
        assert registry._cached(cid) is None
    stored.write_text(good)
    monkeypatch.setenv("NAVCORE_CACHE", "off")
    assert registry._cached(cid) is None
    registry._store(evaluate(registry.claim(cid)))  # nothing written
    assert stored.read_text() == good
    # a stored evaluation made strictly is read by a strict process
    monkeypatch.setenv("NAVCORE_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("NAVCORE_LEDGER_STRICT", "1")
    registry._store(evaluate(registry.claim(cid)))
    assert json.loads(stored.read_text())["strict"] is True
    assert registry._cached(cid) is not None
    # a location that cannot be written costs only the file
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("NAVCORE_CACHE", str(blocker))
    registry._store(evaluate(registry.claim(cid)))
    assert registry._cached(cid) is None


# --- evaluating --------------------------------------------------------------------------------


def test_evaluate_claim_memoises_and_stores(synthetic, tmp_path, monkeypatch):
    """One evaluation per claim and process (a former id gives the same object), stored on
    disk and read from there by a new process (an empty memo). Oracle: a counter in the
    synthetic model, and ``evaluate`` of the same claim."""
    calls = []

    def model() -> float:
        calls.append(1)
        return 15.0

    synthetic({P + "wf_one": _module(P + "wf_one", [_claim("WF-m", compute=model, aliases=("WF-m0",))])})
    first = registry.evaluate_claim("WF-m0")
    assert first.claim.id == "WF-m" and first.reproduced == 15.0 and calls == [1]
    assert registry.evaluate_claim("WF-m") is first and calls == [1]
    assert (tmp_path / "cache" / "claims" / "WF-m.json").is_file()
    registry._MEMO.clear()
    again = registry.evaluate_claim("WF-m")
    assert calls == [1] and again is not first
    _same(again, first)
    monkeypatch.setenv("NAVCORE_CACHE_REFRESH", "1")
    registry._MEMO.clear()
    registry.evaluate_claim("WF-m")
    assert calls == [1, 1]


def test_evaluate_claim_runs_strictly_when_asked(synthetic, monkeypatch):
    """Under NAVCORE_LEDGER_STRICT a division by zero in the model is an error; without it a
    value. Oracle: numpy's errstate rules."""

    def model() -> float:
        return float(np.float64(1.0) / np.float64(0.0) > 1.0)

    synthetic({P + "wf_one": _module(P + "wf_one", [_claim("WF-s", compute=model, published=1.0)])})
    with np.errstate(all="ignore"):
        assert registry.evaluate_claim("WF-s").status == "reproduced"
        registry._MEMO.clear()
        monkeypatch.setenv("NAVCORE_LEDGER_STRICT", "1")
        assert registry.evaluate_claim("WF-s").status == "error"


class _Clock:
    """A stand-in for ``time``: ``perf_counter`` returns the given readings in turn."""

    def __init__(self, *readings: float) -> None:
        self.readings = list(readings)

    def perf_counter(self) -> float:
        return self.readings.pop(0)


def test_group_records(synthetic, monkeypatch):
    """A worker's task: each claim's recorded fields and its seconds. Oracle: ``evaluate`` of
    each claim and the differences of a stand-in clock's readings."""
    synthetic(standard_modules())
    monkeypatch.setattr(registry, "time", _Clock(10.0, 10.5, 100.0, 101.25))
    out = registry._group_records(("WF-a1", "WF-b2"))
    assert [(cid, s) for cid, _, s in out] == [("WF-a1", 0.5), ("WF-b2", 1.25)]
    for cid, record, _ in out:
        fresh = evaluate(registry.claim(cid))
        assert record == {k: getattr(fresh, k) for k in registry._RECORD_FIELDS}


def test_ledger_tasks_group_and_order(synthetic):
    """A claim's task is its module, or the first module of its shared-runs group; tasks come
    longest first by their measured seconds (0.1 s for a module not measured). Oracle: the
    stand-in seconds (beta 5, delta 0.5, alpha unmeasured, gamma 0.2 but run in delta's task)."""
    synthetic(standard_modules())
    assert registry.ledger_task("WF-old-a1") == P + "wf_alpha"
    assert registry.ledger_task("WF-c1") == P + "kzl_delta"
    assert registry.ledger_task("KZL-d1") == P + "kzl_delta"
    tasks = registry.ledger_tasks(["KZL-d1", "WF-a1", "WF-c1", "WF-b1", "WF-a2"])
    assert tasks == [("WF-b1",), ("KZL-d1", "WF-c1"), ("WF-a1", "WF-a2")]
    assert registry.ledger_tasks([]) == []


def test_claims_of_a_claim_task_leave_their_module_task(synthetic, monkeypatch):
    """A claim whose module and id prefix a ``_CLAIM_TASKS`` entry names runs in that task; the
    prefix in a module the entry does not name, and the module's other claims, stay where they
    were. Oracle: the entry read by hand (alpha's WF-a2 only; beta's WF-b1 matches the prefix
    but not the modules)."""
    synthetic(standard_modules())
    monkeypatch.setattr(registry, "_CLAIM_TASKS", (("own runs", (P + "wf_alpha",), ("WF-a2", "WF-b")),))
    monkeypatch.setitem(registry._TASK_SECONDS, "own runs", 9.0)
    assert registry.ledger_task("WF-a2") == "own runs"
    assert registry.ledger_task("WF-a1") == P + "wf_alpha"
    assert registry.ledger_task("WF-b1") == P + "wf_beta"
    tasks = registry.ledger_tasks(["WF-a1", "WF-a2", "WF-b1"])
    assert tasks == [("WF-a2",), ("WF-b1",), ("WF-a1",)]


@pytest.mark.parametrize("n_jobs", [1, 2])
def test_evaluate_in_parallel_gives_the_serial_evaluations(synthetic, monkeypatch, n_jobs):
    """The evaluations made in tasks equal the serial ones; claims already memoised or stored
    are not evaluated again; each claim once however often (or under whichever id) it is
    asked for. Oracle: ``evaluate`` of each synthetic claim in this process, and the tasks
    handed to a recording ``run_tasks`` (joblib's threading backend for two workers, so the
    synthetic modules are visible)."""
    import navcore.parallel

    synthetic(standard_modules())
    serial = {cid: evaluate(registry.claim(cid)) for cid in ALL_IDS}
    registry._store(serial["WF-b1"])  # on disk
    registry._MEMO["WF-c1"] = memo = evaluate(registry.claim("WF-c1"))
    handed: list[Any] = []
    run_tasks = navcore.parallel.run_tasks

    def recording(function, tasks, *, n_jobs=None):
        handed.append(([tuple(t) for t in tasks], n_jobs))
        with joblib.parallel_config(backend="threading"):
            return run_tasks(function, handed[-1][0], n_jobs=n_jobs)

    monkeypatch.setattr(navcore.parallel, "run_tasks", recording)
    asked = ["WF-c1", "KZL-d1", "WF-old-a1", "WF-b1", "WF-a1", "WF-a2", "WF-b2", "KZL-d1"]
    seconds = registry.evaluate_in_parallel(asked, n_jobs=n_jobs)
    assert handed == [([(("WF-b2",),), (("KZL-d1",),), (("WF-a1", "WF-a2"),)], n_jobs)]
    assert sorted(seconds) == ["KZL-d1", "WF-a1", "WF-a2", "WF-b2"]
    assert all(isinstance(s, float) and 0.0 <= s < 60.0 for s in seconds.values())
    assert registry._MEMO["WF-c1"] is memo
    for cid in ALL_IDS:
        _same(registry.evaluate_claim(cid), serial[cid])
        assert registry.evaluate_claim(cid).tolerance is EXACT
    # everything known now: nothing handed out
    assert registry.evaluate_in_parallel(asked, n_jobs=n_jobs) == {}
    assert len(handed) == 1


def test_evaluate_in_parallel_seconds_are_the_workers(synthetic, monkeypatch):
    """Oracle: the differences of a stand-in clock's readings, per claim."""
    synthetic(standard_modules())
    monkeypatch.setattr(registry, "time", _Clock(1.0, 1.5, 2.0, 4.0, 7.0, 7.25))
    assert registry.evaluate_in_parallel(["WF-b1", "KZL-d1", "WF-c1"], n_jobs=1) == {
        "WF-b1": 0.5, "KZL-d1": 2.0, "WF-c1": 0.25,
    }  # fmt: skip


def test_evaluations_and_counts(synthetic, monkeypatch):
    """``evaluations`` in the order of ``claims``, through the workers only when ``n_jobs``
    asks for more than one; ``counts`` per paper, every status with its zero, an ``error``
    counted, and the total. Oracle: the synthetic claims' verdicts, counted by hand."""
    synthetic(standard_modules())
    parallel_calls: list[Any] = []
    real = registry.evaluate_in_parallel

    def recording(ids, n_jobs=-1):
        parallel_calls.append((list(ids), n_jobs))
        return real(ids, n_jobs=1)

    monkeypatch.setattr(registry, "evaluate_in_parallel", recording)
    for n_jobs in (None, 0, 1):
        evs = registry.evaluations("WF", prefix="WF-a", n_jobs=n_jobs)
        assert [e.claim.id for e in evs] == ["WF-a1", "WF-a2"]
    assert parallel_calls == []
    evs = registry.evaluations(prefix="WF-b", n_jobs=2)
    assert parallel_calls == [(["WF-b1", "WF-b2"], 2)]
    assert [e.status for e in evs] == ["reproduced", "discrepant"]
    assert [e.claim.id for e in registry.evaluations(n_jobs=-1)] == ALL_IDS
    assert parallel_calls[-1] == (ALL_IDS, -1)
    assert registry.evaluations("KZL", "KZL-none") == []

    zero = dict.fromkeys(claim_declarations.STATUSES, 0)
    wf = zero | {"reproduced": 3, "discrepant": 1, "error": 1, "total": 5}
    assert registry.counts("WF") == {"WF": wf}
    assert list(registry.counts("WF")["WF"]) == [*claim_declarations.STATUSES, "error", "total"]
    everything = registry.counts()
    assert list(everything) == list(claim_declarations.PAPERS)
    assert everything == {
        "WF": wf,
        "SP": zero | {"total": 0},
        "ATC10": zero | {"total": 0},
        "KZL": zero | {"reproduced": 1, "total": 1},
    }
    assert registry.counts("") == everything
