"""The input gate (tools/input_gate.py) on a synthetic package with planted numbers.

The oracle is the planted package itself: each number is planted where the gate must find it
(a literal in a model, a module constant read through ``from m import X``, a dataclass field
default, a literal behind an ``input_cache``) or must leave alone (a declared input, a module
constant that feeds a declared input, an allowlisted exact constant, a number no claim runs).
"""

from __future__ import annotations

import ast
import importlib.util
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
# under its dotted name, which mutation testing's trampolines recognise (tools/mutation.py)
_spec = importlib.util.spec_from_file_location("tools.input_gate", ROOT / "tools" / "input_gate.py")
assert _spec is not None and _spec.loader is not None
gate = importlib.util.module_from_spec(_spec)
sys.modules["tools.input_gate"] = gate
_spec.loader.exec_module(gate)

PACKAGE = {
    "__init__.py": "",
    "consts.py": """
        #: planted: a modelling constant read elsewhere through ``from gatepkg.consts import``
        EARTH_R = 6371000.0
        #: an exact constant, allowlisted
        FOOT = 0.3048
        #: feeds a declared input's value: declared, not flagged
        GAIN = 3.0
        #: planted: moves its claim by a tenth of its tolerance only when changed tenfold
        INIT_SIGMA = 3.0
        #: no claim reads it
        UNUSED = 42.5
    """,
    "model.py": """
        from dataclasses import dataclass

        from gatepkg.consts import EARTH_R, FOOT


        @dataclass(frozen=True)
        class Scenario:
            speed_mps: float = 200.0  # planted: a dataclass default a claim relies on
            mass_kg: float = 80.0  # not read by any claim


        def horizon_m(height_m):
            return (2.0 * EARTH_R * height_m) ** 0.5


        def metres(length_ft):
            return length_ft * FOOT


        def drag(v):
            return 0.47 * v  # planted: a literal in a model


        def never_called():
            return 123.4
    """,
    "claims.py": """
        from navcore.ledger import EXACT, Claim, InputSet, input_cache, printed
        from gatepkg import model
        from gatepkg.consts import GAIN, INIT_SIGMA

        IN = InputSet("WF", "gate_test")
        IN.published("height_m", 100.0, locator="Table 1", unit="m")
        IN.published("length_ft", 10.0, locator="Table 1", unit="ft")
        IN.published("gain", GAIN, locator="Table 1")


        @input_cache
        def cached_drag():
            return model.drag(IN.gain)


        def _horizon():  # the number the statement compares (exposed to the gate)
            return model.horizon_m(IN.height_m)


        def _c(cid, value_text, compute):
            value, tol = printed(value_text)
            return Claim(id=cid, paper="WF", locator="Table 1", quantity="q", published=value, unit="",
                         compute=compute, tolerance=tol, expected_status="reproduced", note="synthetic")


        CLAIMS = [
            _c("WF-gate-horizon", "35696", lambda: model.horizon_m(IN.height_m)),
            _c("WF-gate-metres", "3.048", lambda: model.metres(IN.length_ft)),
            _c("WF-gate-speed", "600", lambda: model.Scenario().speed_mps * IN.gain),
            _c("WF-gate-drag-a", "1.41", lambda: cached_drag()),
            _c("WF-gate-drag-b", "2.82", lambda: 2 * cached_drag()),
            _c("WF-gate-declared", "103", lambda: IN.height_m + IN.gain),
            _c("WF-gate-rss", "100", lambda: (IN.height_m**2 + INIT_SIGMA**2) ** 0.5),
            Claim(id="WF-gate-statement", paper="WF", locator="Table 1", quantity="s", published=True,
                  unit="statement", compute=lambda: _horizon() > 35000.0,
                  tolerance=EXACT, expected_status="reproduced", note="synthetic"),
        ]
    """,
}

ALLOWLIST = """
[[allow]]
file = "gatepkg/consts.py"
name = "FOOT"
reason = "international foot, exact"
class = "exact/unit"
"""


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict:
    """Run the gate once (with --audit, so excused numbers are perturbed and reported too)."""
    tmp = tmp_path_factory.mktemp("gate")
    pkg = tmp / "gatepkg"
    pkg.mkdir()
    for name, text in PACKAGE.items():
        (pkg / name).write_text(textwrap.dedent(text))
    (tmp / "allow.toml").write_text(ALLOWLIST)
    sys.path.insert(0, str(tmp))
    try:
        target = gate.Target(
            package="gatepkg",
            root=pkg,
            claim_modules=lambda: ["gatepkg.claims"],
            repo=tmp,
            exposure_prefix="gatepkg.claims",  # the "paper module"
            allowlist=tmp / "allow.toml",
        )
        run = gate.Gate(target, jobs=2, nice=0, audit=True, workdir=tmp / "work", log=lambda s: None)
        result = run.run()
    finally:
        sys.path.remove(str(tmp))
    assert "gatepkg" not in sys.modules  # the parent never imported the package
    return result


def _entry(report: dict, file: str, text: str, binding: str | None = None) -> dict:
    hits = [
        e
        for e in report["numbers"]
        if e["file"] == file and e["text"] == text and (binding is None or e["binding"] == binding)
    ]
    assert len(hits) == 1, (file, text, [(e["file"], e["text"]) for e in report["numbers"]])
    return hits[0]


def test_finds_a_literal_in_a_model(report: dict) -> None:
    e = _entry(report, "gatepkg/model.py", "0.47")
    assert e["status"] == "flagged"
    assert e["scope"] == "drag"
    assert set(e["flagged_claims"]) == {"WF-gate-drag-a", "WF-gate-drag-b"}


def test_finds_a_module_constant_read_through_from_import(report: dict) -> None:
    e = _entry(report, "gatepkg/consts.py", "6371000.0")
    assert e["status"] == "flagged"
    assert e["binding"] == "EARTH_R"
    # horizon ~ sqrt(R): a 10 % change moves it 5 % of 35696 m, thousands of half-metres
    assert e["effects"]["WF-gate-horizon"]["tolerances_per_scale"] > 1000
    # the statement's number moves with R (elasticity 1/2), and its truth (horizon > 35000 m)
    # flips when R changes by 10 %
    statement = e["effects"]["WF-gate-statement"]
    assert statement["statement_numbers_rel"] == pytest.approx(0.5 * gate.DELTA, rel=0.01)
    assert not statement["flipped"] and statement["flipped_at_scale"]
    assert "WF-gate-statement" in e["flips"]


def test_finds_a_dataclass_default(report: dict) -> None:
    e = _entry(report, "gatepkg/model.py", "200.0")
    assert e["status"] == "flagged"
    assert e["where"] == "class" and e["binding"] == "speed_mps"
    assert e["flagged_claims"] == ["WF-gate-speed"]


def test_input_cache_is_cold_in_every_evaluation(report: dict) -> None:
    """Both claims call one input_cache'd function: each claim's trace starts from cold caches,
    so the second claim also ran drag(), and each perturbed child recomputes it."""
    e = _entry(report, "gatepkg/model.py", "0.47")
    b = e["effects"]["WF-gate-drag-b"]
    assert b["tolerances_per_scale"] == pytest.approx(
        2 * e["effects"]["WF-gate-drag-a"]["tolerances_per_scale"]
    )


def test_finds_a_number_that_matters_only_tenfold(report: dict) -> None:
    """sqrt(100^2 + 3^2) against a printed 100 (+-0.5): 3 m matters only when it is 30 m."""
    e = _entry(report, "gatepkg/consts.py", "3.0", binding="INIT_SIGMA")
    rss = e["effects"]["WF-gate-rss"]
    assert e["status"] == "flagged"
    # oracle: d/dsigma sqrt(h^2 + sigma^2) = sigma / 100.045; 10 % of 3 m moves it 0.0090 m
    assert rss["tolerances_per_scale"] == pytest.approx(0.3 * 3.0 / 100.045 / 0.5, rel=0.05)
    assert rss["tolerances_per_scale"] < gate.FLAG_TOLERANCES
    # x10: sqrt(100^2 + 30^2) - 100.045 = 4.36 m; /10 moves it -0.0445 m; the worst counts
    assert rss["tolerances_at_factor"] == pytest.approx((104.4031 - 100.0450) / 0.5, rel=1e-3)


def test_does_not_flag_declared_inputs(report: dict) -> None:
    gain = _entry(report, "gatepkg/consts.py", "3.0", binding="GAIN")  # GAIN feeds IN.gain
    assert gain["status"] == "declared"
    assert gain["flagged_claims"] == []
    height = _entry(report, "gatepkg/claims.py", "100.0")  # the declaration's own literal
    assert height["rule"] == "declared-input"
    assert height["status"] != "flagged"
    flagged_claims = {c for e in report["numbers"] if e["status"] == "flagged" for c in e["flagged_claims"]}
    assert "WF-gate-declared" not in flagged_claims


def test_does_not_flag_an_allowlisted_exact_constant(report: dict) -> None:
    e = _entry(report, "gatepkg/consts.py", "0.3048")
    assert e["status"] == "allowlisted"
    assert e["allowlist_reason"] == "international foot, exact"


def test_numbers_no_claim_runs_are_not_perturbed(report: dict) -> None:
    texts = {(e["file"], e["text"]) for e in report["numbers"]}
    assert ("gatepkg/consts.py", "42.5") not in texts
    assert ("gatepkg/model.py", "123.4") not in texts
    assert ("gatepkg/model.py", "80.0") not in texts  # a field no claim relies on moves nothing
    flagged = {(e["file"], e["text"]) for e in report["numbers"] if e["status"] == "flagged"}
    assert flagged == {
        ("gatepkg/model.py", "0.47"),
        ("gatepkg/consts.py", "6371000.0"),
        ("gatepkg/model.py", "200.0"),
        ("gatepkg/consts.py", "3.0"),
        ("gatepkg/claims.py", "35000.0"),  # the statement's threshold is the book's number
    }


def _rule(source: str, literal: str, where: str = "body") -> str:
    """The rule the gate applies to the first literal written ``literal`` in ``source``."""
    tree = ast.parse(textwrap.dedent(source))
    parents = {c: p for p in ast.walk(tree) for c in ast.iter_child_nodes(p)}
    lines = textwrap.dedent(source).splitlines()
    for node in ast.walk(tree):
        if gate._literal_value(node) is not None and hasattr(node, "lineno"):
            text = lines[node.lineno - 1].encode()[node.col_offset : node.end_col_offset].decode()
            if text == literal:
                return gate.classify_rule(node, parents, where, "")
    raise AssertionError(f"{literal} not in source")


@pytest.mark.parametrize(
    ("source", "literal", "rule"),
    [
        ("y = x ** 2", "2", "exponent"),
        ("y = x ** 1.5", "1.5", "exponent"),
        ("y = x ** 0.8", "0.8", ""),  # a fitted power law stays a candidate
        ("y = x[3]", "3", "index"),
        ("y = x[:, 0:3]", "3", "index"),
        ("y = np.zeros((3, 3))", "3", "index"),
        ("for i in range(8): pass", "8", "index"),
        ("y = 2 * np.pi * f", "2", "formula-coefficient"),
        ("y = 0.5 * a * t", "0.5", "formula-coefficient"),
        ("y = 10 * np.log10(p)", "10", "decibel"),
        ("y = 10 ** (x / 10)", "10", "decibel"),
        ("y = t / 3600.0", "3600.0", "unit-conversion"),
        ("y = 8.0 / 27.0 * x", "27.0", "formula-coefficient"),
        ("h = sp.Rational(1, 2)", "2", "exact-symbolic"),
        ("s = sp.series(f, x, 0, 7)", "7", "exact-symbolic"),
        ("y = np.sqrt(27000.0 / g)", "27000.0", ""),  # a rule of thumb is a candidate
        ("y = 1.0 - p", "1.0", "identity"),
        ("rng = np.random.default_rng(12345)", "12345", "seed"),
        ("IN.assumed('x', 3.0, low=1.0, high=5.0)", "3.0", "declared-input"),
        ("y = f(x, sigma=3.0)", "3.0", ""),  # a keyword value stays a candidate
        ("raise ValueError(f'x > {2.5}')", "2.5", "text"),
        ("c = Claim(id='SP-x', published=2.5)", "2.5", "claim-metadata"),
        ("c = Claim.statement(id='SP-x', note='n', kind=3.5)", "3.5", "claim-metadata"),
        ("c = Claim.statement(id='SP-x', compute=lambda: f(3.5))", "3.5", ""),  # a compute is code
        ("c = report.statement(x, 3.5)", "3.5", ""),  # another object's statement is no claim
    ],
)
def test_rules(source: str, literal: str, rule: str) -> None:
    assert _rule(source, literal) == rule


def test_every_rule_and_allowlist_entry_has_a_reason() -> None:
    assert all(reason.strip() for reason in gate.RULES.values())
    entries = gate.load_allowlist(gate.ALLOWLIST)
    assert entries and all(e["reason"].strip() for e in entries)
    index = gate.index_package(gate.navcore_target())
    # entries name a number by file and name, or by file, scope and text
    matched = {tuple(sorted(c.allow.items())) for c in index.candidates if c.allow is not None}
    for e in entries:  # every entry still names a number of the package
        assert tuple(sorted(e.items())) in matched, e


def test_perturbed_values() -> None:
    assert gate.perturbed_value(2.0, +1) == pytest.approx(2.002)
    assert gate.perturbed_value(27000, -1) == 26973
    assert gate.perturbed_value(8, +1) == 9  # an integer moves by a whole step at least
    assert gate.perturbed_value(0.0, -1) == -gate.ZERO_STEP
    assert gate.perturbed_value(0, +1) == 1


def test_merging_runs_keeps_every_flagged_number(report: dict) -> None:
    merged = gate.merge_reports([report, report])
    assert merged["counts"]["flagged"] == report["counts"]["flagged"]
    assert merged["counts"]["claims"] == 2 * report["counts"]["claims"]
    assert "## WF" in gate.render_markdown(merged)
