"""The ledger machinery, on synthetic claims built in the test (not the paper registry).

Oracle: the verdict rules of LEDGER.md written out by hand for each case.
"""

from __future__ import annotations

import csv
import io
import json
import subprocess
import sys

import pytest

from navcore.claims.json_coding import from_jsonable, jsonable
from navcore.ledger import EXACT, Claim, Erratum, Tolerance, evaluate, printed, validate_registry
from navcore.ledger.tables import LedgerTable, json_dump
from navcore.provenance import build_provenance

TOL = Tolerance(reason="test", abs=0.5, policy="printed-digits")


def make(**kw):
    base = dict(
        id="WF-test",
        paper="WF",
        locator="Eq. (1)",
        quantity="q",
        published=10.0,
        unit="m",
        compute=lambda: 10.2,
        tolerance=TOL,
        expected_status="reproduced",
        note="n",
    )
    base.update(kw)
    return Claim(**base)


def test_printed_half_last_digit():
    assert printed("17.67") == (17.67, printed("17.67")[1])
    assert printed("17.67")[1].abs == pytest.approx(0.005)
    assert printed("1131")[1].abs == pytest.approx(0.5)
    assert printed("1.5e-3")[1].abs == pytest.approx(0.05e-3)
    assert printed("0.002")[1].abs == pytest.approx(0.0005)
    _, t = printed("90", extra_abs=1.0, why="rounded intermediate")
    assert t.abs == pytest.approx(1.5) and "rounded intermediate" in t.reason
    with pytest.raises(ValueError, match="printed number"):
        printed("about 5")


def test_reproduced_within_and_outside_tolerance():
    assert evaluate(make()).passes
    assert not evaluate(make(compute=lambda: 10.6)).passes


@pytest.mark.parametrize(
    ("relation", "value", "ok"),
    [(">", 131.0, True), (">", 120.0, False), ("<", 5.0, True), (">=", 9.6, True), ("<=", 10.6, False)],
)
def test_relations(relation, value, ok):
    published = 130.0 if relation == ">" else 10.0
    assert evaluate(make(relation=relation, published=published, compute=lambda: value)).passes is ok


def test_relative_tolerance():
    c = make(
        published=1000.0, compute=lambda: 1040.0, tolerance=Tolerance(reason="r", rel=0.05, policy="prose")
    )
    assert evaluate(c).passes
    c = make(
        published=1000.0, compute=lambda: 1060.0, tolerance=Tolerance(reason="r", rel=0.05, policy="prose")
    )
    assert not evaluate(c).passes


def test_statement():
    assert evaluate(make(published=True, unit="statement", compute=lambda: 3 > 2)).passes
    false = evaluate(make(published=True, unit="statement", compute=lambda: 3 < 2))
    assert not false.passes and false.status == "discrepant"


def test_discrepant_requires_erratum_and_oracle():
    with pytest.raises(ValueError, match="must name its erratum"):
        make(expected_status="discrepant", compute=lambda: 20.0)
    with pytest.raises(ValueError, match="independent oracle"):
        make(expected_status="discrepant", erratum="WF-E1", compute=lambda: 20.0)


def test_discrepant_check():
    ot = Tolerance(reason="oracle", rel=1e-6)
    ok = make(
        expected_status="discrepant",
        erratum="WF-E1",
        compute=lambda: 20.0,
        oracle=lambda: 20.0,
        oracle_tolerance=ot,
    )
    assert evaluate(ok).passes
    # the book's value drifts away from its oracle: a regression is caught
    drift = make(
        expected_status="discrepant",
        erratum="WF-E1",
        compute=lambda: 21.0,
        oracle=lambda: 20.0,
        oracle_tolerance=ot,
    )
    assert not evaluate(drift).passes
    # the discrepancy vanished: the status must be re-examined
    gone = make(
        expected_status="discrepant",
        erratum="WF-E1",
        compute=lambda: 10.0,
        oracle=lambda: 10.0,
        oracle_tolerance=ot,
    )
    assert not evaluate(gone).passes


def test_not_reproducible_has_no_compute():
    c = make(expected_status="not-reproducible", compute=None)
    assert evaluate(c).passes and evaluate(c).reproduced is None
    assert evaluate(c).status == "not-reproducible"
    # a computed claim may expect not-reproducible (a band too wide to decide), but a claim
    # that reads no assumed input derives its verdict from the value, so the pin fails
    assert not evaluate(make(expected_status="not-reproducible")).passes
    # nothing computed is not-reproducible, whatever was expected
    assert evaluate(make(compute=None)).status == "not-reproducible"
    assert not evaluate(make(compute=None)).passes


def test_compute_failure_and_nan_fail_the_check():
    def boom():
        raise RuntimeError("x")

    assert not evaluate(make(compute=boom)).passes
    assert not evaluate(make(compute=lambda: float("nan"))).passes


@pytest.mark.parametrize(
    ("field", "value", "match"),
    [
        ("id", "XX-1", "must start with its paper key"),
        ("id", "SP-1", "must start with 'WF-'"),
        ("paper", "ZZ", "paper must be one of"),
        ("expected_status", "fine", "expected_status must be one of"),
        ("kind", "guess", "kind must be one of"),
        ("relation", "~", "relation must be one of"),
        ("note", " ", "note must state"),
    ],
)
def test_claim_validation(field, value, match):
    with pytest.raises(ValueError, match=match):
        make(**{field: value})


def test_tolerance_needs_reason_and_policy():
    with pytest.raises(ValueError, match="reason"):
        Tolerance(reason="", abs=1.0, policy="exact")
    with pytest.raises(ValueError, match="abs must be finite"):
        Tolerance(reason="r", abs=-1.0, policy="prose")
    with pytest.raises(ValueError, match="policy must be one of"):
        Tolerance(reason="r", abs=1.0, policy="generous")
    # a tolerance without a policy fails the claim's evaluation
    ev = evaluate(make(tolerance=Tolerance(reason="r", abs=1.0)))
    assert not ev.passes and "policy" in ev.detail


def test_registry_validation():
    c = make(
        expected_status="discrepant",
        erratum="WF-E9",
        compute=lambda: 1.0,
        oracle=lambda: 1.0,
        oracle_tolerance=TOL,
    )
    with pytest.raises(ValueError, match="unknown erratum"):
        validate_registry([c], [])
    e = Erratum(
        id="WF-E9",
        paper="WF",
        locator="Eq. (1)",
        printed="p",
        finding="f",
        evidence="e",
        claims=("WF-nope",),
        kind="typography",
        basis="text-only",
    )
    with pytest.raises(ValueError, match="unknown claim"):
        validate_registry([c], [e])
    with pytest.raises(ValueError, match="duplicate claim"):
        validate_registry([make(), make()], [])


def test_json_has_exactly_the_documented_fields():
    out = json.loads(
        json_dump(
            [
                evaluate(make()),
                evaluate(make(id="WF-b", published=True, unit="statement", compute=lambda: True)),
            ]
        )
    )
    fields = {
        "id",
        "paper",
        "locator",
        "quantity",
        "published",
        "relation",
        "unit",
        "printed",
        "errata",
        "kind",
        "inputs",
        "reproduced",
        "band",
        "readings",
        "tolerance",
        "status",
        "note",
    }
    assert all(set(o) == fields for o in out)
    assert out[0]["published"] == 10.0 and out[0]["reproduced"] == 10.2
    assert out[0]["tolerance"] == {
        "abs": 0.5,
        "rel": None,
        "reason": "test",
        "policy": "printed-digits",
        "loose_abs": None,
    }
    assert out[0]["kind"] == "reproduction" and out[1]["kind"] == "statement"
    assert out[0]["band"] is None and out[0]["inputs"] == []
    assert out[1]["published"] is True
    assert out[0]["readings"] == [] and out[0]["errata"] == []


def test_table_renders_html_and_markdown():
    t = LedgerTable([evaluate(make())])
    assert "<table" in t._repr_html_() and "WF-test" in t._repr_html_()
    md = t._repr_markdown_()
    # the PDF book gets a raw-LaTeX longtable whose columns add up to the text width
    assert md.startswith("```{raw} latex\n") and md.endswith("\n```")
    assert r"\begin{longtable}" in md and "reproduced" in md
    assert r"WF-\allowbreak{}test" in md


def test_latex_escaping_of_ledger_text():
    """Oracle: LaTeX's ten special characters written out by hand."""
    from navcore.ledger.text import tex_escape

    assert tex_escape("50 % & $x_1$ #2 {a} ~ ^ \\") == (
        r"50 \% \& \$x\_1\$ \#2 \{a\} \textasciitilde{} \textasciicircum{} \textbackslash{}"
    )


def test_long_printed_formula_is_math_scaled_to_its_column(tmp_path):
    """A long formula in a printed claim-table cell is set as math, in a box that is scaled
    down to the column only when wider than it; both preambles define the macro.

    Oracle: XeLaTeX itself, which reports an overfull box in a 3 cm column when the formula is
    set unscaled, and none when set by the macro (nor for a short formula in it)."""
    import shutil
    from pathlib import Path

    from navcore.ledger.tables import latex_table
    from navcore.ledger.text import FIT_MATH_PREAMBLE, _printed_tex
    from navcore.report import Report, build_provenance, to_latex

    formula = r"\hat{\tau}_1 = \gamma_1^{-1} (I - F_1 (F_1' F_1)^{-1} F_1') [\hat{T}_1 - k_1]"
    cell = _printed_tex(f"$${formula} \\quad (4.5.10)$$")
    assert cell == r"\navcorefitmath{" + formula + "}" and "ttfamily" not in cell
    assert r"\navcorefitmath{" + formula + "}" in latex_table(["Printed"], [[f"${formula}$"]])
    config = (Path(__file__).resolve().parents[1] / "_config.yml").read_text(encoding="utf-8")
    assert FIT_MATH_PREAMBLE in config
    assert FIT_MATH_PREAMBLE in to_latex(Report("WF", "t", "r", build_provenance(), ()))
    if shutil.which("xelatex") is None:
        pytest.skip("xelatex is not installed")

    def overfull(body: str) -> bool:
        doc = (
            "\\documentclass{article}\\usepackage{amsmath,graphicx,array}\n" + FIT_MATH_PREAMBLE + "\n"
            "\\begin{document}\\begin{tabular}{|p{3cm}|}" + body + "\\end{tabular}\\end{document}\n"
        )
        (tmp_path / "t.tex").write_text(doc, encoding="utf-8")
        run = subprocess.run(
            ["xelatex", "-interaction=nonstopmode", "-halt-on-error", "t.tex"],
            cwd=tmp_path, capture_output=True, text=True, timeout=120,
        )  # fmt: skip
        assert run.returncode == 0, run.stdout[-2000:]
        return "Overfull \\hbox" in (tmp_path / "t.log").read_text(encoding="utf-8", errors="replace")

    assert overfull(f"${formula}$")  # the formula unscaled runs over the column
    assert not overfull(cell)  # scaled to it, it does not
    assert not overfull(r"\navcorefitmath{x_1}")


def test_cli_ledger_json_and_exit_status(monkeypatch, capsys):
    """The command line prints valid JSON with the documented fields and exits 0 when all pass.

    The registry is replaced by synthetic evaluations (every real claim is evaluated by
    test_claims.py); the module entry point itself is exercised by a subprocess with --help.
    """
    from navcore import __main__ as cli
    from navcore import ledger

    evals = [
        evaluate(make()),
        evaluate(make(id="WF-b", published=True, unit="statement", compute=lambda: True)),
    ]
    monkeypatch.setattr(ledger, "evaluations", lambda paper=None, prefix=None, n_jobs=None: evals)
    assert cli.main(["ledger", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [d["id"] for d in data["claims"]] == ["WF-test", "WF-b"]
    assert data["provenance"] == build_provenance().as_dict()  # what computed them
    assert cli.main(["ledger", "--csv"]) == 0
    table = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert [r["id"] for r in table] == ["WF-test", "WF-b"]
    assert all(r.items() >= build_provenance().flat().items() for r in table)
    proc = subprocess.run(
        [sys.executable, "-m", "navcore", "ledger", "--help"], capture_output=True, text=True
    )
    assert proc.returncode == 0 and "--json" in proc.stdout


def test_cli_times_sums_each_tasks_claims(monkeypatch, capsys):
    """``--times`` prints, on stderr, each parallel task's seconds, longest first: the sum of its
    claims' seconds (two SP flyby claims, a figure's and a Table 2.7 cell's, make one task, a WF
    claim another).
    Oracle: the sums by hand from the seconds the stub reports."""
    from navcore import __main__ as cli
    from navcore import ledger
    from navcore.ledger import registry

    seconds = {"SP-fig2.7-tc10": 1.5, "SP-tab2.7-tc10-sv3": 2.0, "WF-eq3-normal": 0.25}
    monkeypatch.setattr(registry, "evaluate_in_parallel", lambda ids, n_jobs=-1: seconds)
    one = [evaluate(make())]
    monkeypatch.setattr(ledger, "evaluations", lambda paper=None, prefix=None, n_jobs=None: one)
    assert cli.main(["ledger", "--times"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == ["     3.5 s  navcore.papers.sp_flyby", "     0.2 s  navcore.papers.wf_location_error"]


def test_cli_exit_status_nonzero_on_failure(monkeypatch, capsys):
    """Oracle: a registry with one failing claim must make `ledger` exit with status 1."""
    from navcore import __main__ as cli
    from navcore import ledger

    failing = make(compute=lambda: 99.0)
    monkeypatch.setattr(
        ledger, "evaluations", lambda paper=None, prefix=None, n_jobs=None: [evaluate(failing)]
    )
    assert cli.main(["ledger"]) == 1
    assert "FAIL WF-test" in capsys.readouterr().err


def test_evaluation_cache_round_trip(tmp_path, monkeypatch):
    """A stored evaluation reads back identical to the fresh one, including infinities and the
    recorded input values (a page renders them, so a cached read must not change their form).

    Oracle: the fresh evaluation of the same claim with the cache off.
    """
    from navcore.ledger import registry

    fresh = registry.evaluate(registry.claim("SP-tab2.3-total"))
    monkeypatch.setenv("NAVCORE_CACHE", str(tmp_path))
    registry.evaluate_claim.cache_clear()
    try:
        first = registry.evaluate_claim("SP-tab2.3-total")
        assert list(registry.cache_dir().glob("*.json"))
        registry.evaluate_claim.cache_clear()
        second = registry.evaluate_claim("SP-tab2.3-total")
        for ev in (first, second):
            assert (ev.reproduced, ev.passes, ev.detail) == (fresh.reproduced, fresh.passes, fresh.detail)
            assert ev.inputs == fresh.inputs
        assert any(isinstance(i["value"], list) for i in fresh.inputs)  # the case that differed
        for value in (float("inf"), -float("inf"), 1.5, None, True):
            assert from_jsonable(jsonable(value, round_trip=True)) == value
    finally:
        registry.evaluate_claim.cache_clear()


def test_strict_evaluation_raises_on_floating_point_errors_and_warnings(monkeypatch):
    """NAVCORE_LEDGER_STRICT=1 evaluates under the test suite's rules, whatever the caller's.

    Oracle: numpy's documented errstate behaviour (1/0 warns under 'warn', raises under
    'raise') and Python's warnings filters, outside and inside the strict context.
    """
    import warnings

    import numpy as np

    from navcore.ledger import registry

    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        monkeypatch.delenv("NAVCORE_LEDGER_STRICT", raising=False)
        with registry._strictly():
            assert np.float64(1.0) / 0.0 == np.inf
            warnings.warn("lenient", RuntimeWarning, stacklevel=1)  # ignored
        monkeypatch.setenv("NAVCORE_LEDGER_STRICT", "1")
        with registry._strictly():
            with pytest.raises(FloatingPointError):
                np.float64(1.0) / 0.0
            with pytest.raises(RuntimeWarning):
                warnings.warn("strict", RuntimeWarning, stacklevel=1)
            assert np.float64(1e-300) * 1e-300 == 0.0  # underflow stays quiet, as in the tests


def test_a_strict_process_reads_only_evaluations_stored_under_the_strict_rules(tmp_path, monkeypatch):
    """A lenient evaluation on disk (the book's, say) may hide a warning: a strict process (the
    tests, CI's ledger gate) evaluates the claim again; a strict one is read by every process.

    Oracle: the stored files' ``strict`` field and whether a read found them.
    """
    from navcore.ledger import registry

    cid = "WF-eq20-PNG"
    monkeypatch.setenv("NAVCORE_CACHE", str(tmp_path))
    monkeypatch.delenv("NAVCORE_LEDGER_STRICT", raising=False)
    registry.evaluate_claim.cache_clear()
    try:
        registry.evaluate_claim(cid)
        stored = registry.cache_dir() / f"{cid}.json"
        assert json.loads(stored.read_text())["strict"] is False
        assert registry._cached(cid) is not None
        monkeypatch.setenv("NAVCORE_LEDGER_STRICT", "1")
        assert registry._cached(cid) is None
        registry.evaluate_claim.cache_clear()
        registry.evaluate_claim(cid)  # evaluated again, strictly, and stored
        assert json.loads(stored.read_text())["strict"] is True
        assert registry._cached(cid) is not None
        monkeypatch.delenv("NAVCORE_LEDGER_STRICT")
        assert registry._cached(cid) is not None
    finally:
        registry.evaluate_claim.cache_clear()


def test_a_claim_and_an_erratum_take_their_paper_from_their_id():
    """The paper has one home, the id's key: left out it is derived, given it must agree."""
    common = dict(
        locator="Eq. (1)", quantity="q", published=1.0, unit="", compute=None,
        tolerance=Tolerance(abs=0.0, reason="exact"), expected_status="not-reproducible", note="n",
    )  # fmt: skip
    assert Claim(id="ATC10-x", **common).paper == "ATC10"
    assert Claim(id="KZL-x", paper="KZL", **common).paper == "KZL"
    with pytest.raises(ValueError, match=r"Claim\.id must start with 'WF-'"):
        Claim(id="SP-x", paper="WF", **common)
    texts = dict(
        locator="Eq. (1)", printed="p", finding="f", evidence="e", kind="typography", basis="text-only"
    )
    assert Erratum(id="SP-E9-x", **texts).paper == "SP"
    with pytest.raises(ValueError, match=r"Erratum\.id must start with 'KZL-'"):
        Erratum(id="SP-E9-x", paper="KZL", **texts)
    with pytest.raises(ValueError, match=r"Erratum\.paper must be one of"):
        Erratum(id="XX-E9-x", **texts)


def test_a_statement_claim_is_the_claim_written_out():
    """Oracle: the same claim with every field written out (Claim.statement only fills the
    fixed ones); published and unit cannot be given, other fields pass through."""

    def holds() -> bool:
        return True

    short = Claim.statement(
        id="SP-x", locator="Sec. 2.1", quantity="q", compute=holds, note="n", discussed_in="sp/01",
        kind="cross-check",
    )  # fmt: skip
    long = Claim(
        id="SP-x", locator="Sec. 2.1", quantity="q", published=True, unit="statement", compute=holds,
        tolerance=EXACT, expected_status="reproduced", note="n", discussed_in="sp/01", kind="cross-check",
    )  # fmt: skip
    assert short == long
    own = Tolerance(abs=0.0, reason="exact")
    other = Claim.statement(
        id="SP-y", locator="Sec. 2.1", quantity="q", compute=None, note="n", tolerance=own,
        expected_status="not-reproducible",
    )  # fmt: skip
    assert (other.tolerance, other.expected_status) == (own, "not-reproducible")
    with pytest.raises(ValueError, match=r"Claim\.statement fixes published"):
        Claim.statement(id="SP-z", locator="L", quantity="q", compute=None, note="n", published=False)
