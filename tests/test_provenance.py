"""Build provenance (issue 35, item 2): what every artifact says about the build that made it.

Oracles: a throw-away git repository whose commit date, files and changes the test sets
itself (so the expected commit date, lock hash and state of the tree are known before the
function runs); ``hashlib`` on the bytes the test wrote; a folder outside any repository and a
PATH without git for the unknown cases; the same commit checked out at two paths for
"never from the checkout path".
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from navcore.ledger import Claim, Tolerance, evaluate
from navcore.ledger.tables import csv_export, json_dump, json_export
from navcore.provenance import CORE_PACKAGES, BuildProvenance, build_provenance

ROOT = Path(__file__).resolve().parents[1]
GIT = shutil.which("git")
needs_git = pytest.mark.skipif(GIT is None, reason="git is not installed")
LOCK = b"numpy==2.4.6 \\\n    --hash=sha256:00\n"
DATE = "2020-02-03T04:05:06+01:00"


def _git(repo: Path, *args: str) -> str:
    env = {k: v for k, v in os.environ.items() if not k.startswith("GIT_")}
    env.update(GIT_AUTHOR_DATE=DATE, GIT_COMMITTER_DATE=DATE)
    command = ["git", "-c", "user.name=t", "-c", "user.email=t@example.org", "-c", "init.defaultBranch=main"]
    proc = subprocess.run(
        [*command, "-C", str(repo), *args], capture_output=True, text=True, env=env, check=True
    )
    return proc.stdout.strip()


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    """A checkout with one commit: a lock file and a module."""
    root = tmp_path / "checkout"
    (root / "requirements").mkdir(parents=True)
    (root / "requirements" / "lock.txt").write_bytes(LOCK)
    (root / "model.py").write_text("X = 1\n")
    _git(root, "init", "-q")
    _git(root, "add", ".")
    _git(root, "commit", "-q", "-m", "first")
    return root


@needs_git
def test_a_clean_checkout_names_its_commit_date_and_lock(repo: Path) -> None:
    p = build_provenance(repo)
    assert p.commit == _git(repo, "rev-parse", "HEAD") and len(p.commit) == 40
    assert p.tree == "clean"
    assert p.commit_date == DATE  # the commit's date, as set above: not the clock's
    assert p.date == "3 February 2020"
    assert p.lock_sha256 == hashlib.sha256(LOCK).hexdigest()
    assert [name for name, _ in p.packages] == list(CORE_PACKAGES)
    assert dict(p.packages)["navcore"] == __import__("importlib.metadata").metadata.version("navcore")


@needs_git
def test_a_changed_tracked_file_makes_the_tree_dirty(repo: Path) -> None:
    (repo / "untracked.txt").write_text("a scratch file\n")
    assert build_provenance(repo).tree == "clean"  # an untracked file changes no tracked code
    (repo / "model.py").write_text("X = 2\n")
    dirty = build_provenance(repo)
    assert dirty.tree == "dirty" and dirty.commit == _git(repo, "rev-parse", "HEAD")
    _git(repo, "checkout", "-q", "--", "model.py")
    _git(repo, "rm", "-q", "--cached", "model.py")  # a staged deletion is a change too
    assert build_provenance(repo).tree == "dirty"


@needs_git
def test_the_same_commit_at_two_paths_gives_the_same_provenance(repo: Path, tmp_path: Path) -> None:
    other = tmp_path / "elsewhere" / "clone"
    subprocess.run(["git", "clone", "-q", str(repo), str(other)], check=True, capture_output=True)
    first, second = build_provenance(repo), build_provenance(other)
    assert first == second
    assert build_provenance(repo) == first  # and twice in a row
    assert str(repo) not in json.dumps(first.as_dict()) and str(other) not in json.dumps(second.as_dict())


@needs_git
def test_a_folder_inside_a_checkout_is_not_that_checkout(repo: Path) -> None:
    """An installed package inside some other repository must not report that repository's commit."""
    inner = repo / "site-packages"
    (inner / "requirements").mkdir(parents=True)
    p = build_provenance(inner)
    assert (p.commit, p.tree, p.commit_date, p.lock_sha256) == ("unknown",) * 4


def test_no_repository_and_no_git_say_unknown(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "requirements").mkdir()
    (tmp_path / "requirements" / "lock.txt").write_bytes(LOCK)
    p = build_provenance(tmp_path)  # an unpacked archive: no .git
    assert (p.commit, p.tree, p.commit_date, p.date) == ("unknown",) * 4
    assert p.lock_sha256 == hashlib.sha256(LOCK).hexdigest()
    monkeypatch.setenv("PATH", str(tmp_path / "no-such-bin"))  # no git program at all
    assert build_provenance(ROOT).commit == "unknown"
    assert build_provenance(ROOT).tree == "unknown"


def test_flat_columns_and_rows_follow_the_fields() -> None:
    p = BuildProvenance(
        "c" * 40, "dirty", DATE, "f" * 64, "3.11.7", (("numpy", "2.4.6"), ("jupyter-book", "1.0"))
    )
    assert p.flat() == {
        "build_commit": "c" * 40,
        "build_tree": "dirty",
        "build_commit_date": DATE,
        "build_lock_sha256": "f" * 64,
        "build_python": "3.11.7",
        "build_numpy": "2.4.6",
        "build_jupyter_book": "1.0",
    }
    assert dict(p.rows())["Working tree"] == "dirty (changed since the commit)"
    assert p.as_dict()["packages"] == {"numpy": "2.4.6", "jupyter-book": "1.0"}


# --- the ledger's exports ---------------------------------------------------------------------

PROV = BuildProvenance("a" * 40, "clean", DATE, "b" * 64, "3.11.7", (("numpy", "2.4.6"),))


def _evals():
    tol = Tolerance(reason="test", abs=0.5, policy="printed-digits")
    claim = Claim(
        id="WF-prov", paper="WF", locator="Eq. (1)", quantity="q", published=10.0, unit="m",
        compute=lambda: 10.2, tolerance=tol, expected_status="reproduced", note="synthetic",
    )  # fmt: skip
    return [evaluate(claim)]


def test_the_json_export_carries_the_provenance_beside_the_claims() -> None:
    evals = _evals()
    data = json.loads(json_export(evals, PROV))
    assert list(data) == ["provenance", "claims"]
    assert data["provenance"] == PROV.as_dict()
    assert data["claims"] == json.loads(json_dump(evals))  # the claim records themselves unchanged
    assert json_export(evals, PROV) == json_export(evals, PROV)


def test_the_csv_export_carries_the_provenance_on_every_row() -> None:
    import csv
    import io

    table = list(csv.DictReader(io.StringIO(csv_export(_evals() * 2, PROV))))
    assert len(table) == 2
    for row in table:
        assert row["id"] == "WF-prov" and row["status"] == "reproduced"
        assert {k: row[k] for k in PROV.flat()} == PROV.flat()


def test_the_command_line_export_names_this_checkout(tmp_path: Path) -> None:
    out = tmp_path / "ledger.json"
    env = {**os.environ, "NAVCORE_CACHE": "off"}
    command = [sys.executable, "-m", "navcore", "ledger", "--claim", "WF-eq3-normal"]
    proc = subprocess.run([*command, "--json-out", str(out)], capture_output=True, env=env, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    data = json.loads(out.read_text())
    assert data["provenance"] == build_provenance().as_dict()
    assert len(data["claims"]) == 1


# --- the book: the downloadable notebooks, the About page, the PDF's title page ---------------


def _load(name: str):
    spec = importlib.util.spec_from_file_location(f"book._ext.{name}", ROOT / "book" / "_ext" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def test_a_downloadable_notebook_carries_the_provenance_in_its_metadata(tmp_path: Path) -> None:
    import nbformat

    book_downloads = _load("book_downloads")
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("1 + 1")])
    path = tmp_path / "page.ipynb"
    nbformat.write(nb, path)
    written = book_downloads.executed_notebook(path)
    assert written.metadata["navcore_provenance"] == build_provenance().as_dict()
    assert nbformat.reads(nbformat.writes(written), as_version=4).metadata["navcore_provenance"]["commit"]


def test_the_about_table_and_the_title_page_show_every_field() -> None:
    ext = _load("build_provenance")
    p = BuildProvenance("a" * 40, "clean", DATE, "b" * 64, "3.11.7", (("jupyter-book", "1.0_rc#1"),))
    table = ext.provenance_table(p.rows())
    cells = [entry.astext() for entry in table.findall(lambda n: n.tagname == "entry")]
    assert cells[2:] == [text for row in p.rows() for text in row]
    latex = ext.title_page_latex(p)
    assert "a" * 40 in latex and "b" * 64 in latex and r"1.0\_rc\#1" in latex
    assert latex.count(r"\\") == len(p.rows()) + 1  # one line per field, under its heading


def test_a_page_with_the_interactive_ledger_carries_the_provenance_its_downloads_take() -> None:
    from types import SimpleNamespace

    ext = _load("build_provenance")
    app = SimpleNamespace(builder=SimpleNamespace(format="html"))
    ledger_page = {"body": '<div data-ledger-app="1">...</div>', "metatags": "<meta>"}
    other_page = {"body": "<p>prose</p>", "metatags": "<meta>"}
    ext._ledger_page(app, "ledger", "page.html", ledger_page, None)
    ext._ledger_page(app, "about", "page.html", other_page, None)
    assert other_page["metatags"] == "<meta>"
    head = ledger_page["metatags"]
    assert head.startswith('<meta><script type="application/json" id="navcore-provenance">')
    data = head[head.index(">", len("<meta><script")) + 1 : head.index("</script>")]
    assert json.loads(data) == build_provenance().as_dict()


def test_a_toy_book_build_names_its_build(tmp_path: Path) -> None:
    """The real build tool on a toy book: the About table and every downloaded notebook name the build."""
    from _toybook import build_command, build_env, make_book

    book, config = make_book(tmp_path, {"b": {"1-quick.md": "1 + 1"}})
    ext = ROOT / "book" / "_ext"
    config.write_text(
        config.read_text().replace(
            "    toy_phases: book/_ext\n",
            f"    toy_phases: book/_ext\n    book_downloads: {ext}\n    build_provenance: {ext}\n",
        )
    )
    (book / "intro.md").write_text("# Toy\n\n```{build-provenance}\n```\n")
    out = tmp_path / "out"
    proc = subprocess.run(
        build_command(book, config, out), cwd=tmp_path, env=build_env(tmp_path),
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    html = out / "_build" / "html"
    expected = build_provenance()
    notebook = json.loads((html / "_sources" / "b" / "1-quick.ipynb").read_text())
    assert notebook["metadata"]["navcore_provenance"] == expected.as_dict()
    about = (html / "intro.html").read_text()
    assert expected.commit in about and expected.lock_sha256 in about
    gate = subprocess.run([sys.executable, str(ROOT / "tools" / "check_book.py"), "html", str(html)])
    assert gate.returncode == 0


@pytest.mark.skipif(shutil.which("node") is None, reason="node is not installed")
def test_the_ledger_pages_csv_download_has_the_command_lines_build_columns() -> None:
    """Oracle: the page's script (run by node) against BuildProvenance.flat, key for key, in order."""
    from navcore.ledger.interactive import _LEDGER_JS

    start, end = _LEDGER_JS.index("  function buildColumns"), _LEDGER_JS.index("  function download")
    p = build_provenance()
    script = (
        _LEDGER_JS[start:end] + f"\nconsole.log(JSON.stringify(buildColumns({json.dumps(p.as_dict())})));"
    )
    out = subprocess.run(["node", "-e", script], capture_output=True, text=True, check=True).stdout
    assert list(json.loads(out).items()) == list(p.flat().items())
