"""Build provenance: which code, lock and software stack produced an artifact.

Every artifact the project hands out (the About page, the title page of each PDF, every
downloadable notebook's metadata and the ledger's JSON and CSV exports) names

* the commit it was built from, and whether the working tree was clean (no tracked file
  changed since that commit) or dirty;
* the commit's own date (``git log -1 --format=%cI``), never the clock's, so that two builds
  of one commit give the same bytes;
* the SHA-256 of the lock file ``requirements/lock.txt`` the environment was installed from;
* the version of Python and of the core packages (numpy, scipy, matplotlib, pandas,
  jupyter-book, navcore).

Outside a git checkout (an unpacked source archive, an installed wheel, no ``git`` program)
the commit, its date and the state of the tree are ``"unknown"``; a package that is not
installed is ``"not installed"``. Nothing here raises on a missing tool or file, and nothing
reads the clock or the checkout's path.

Examples
--------
>>> p = build_provenance()
>>> p.tree in ("clean", "dirty", "unknown")
True
>>> sorted(p.as_dict())[:3]
['commit', 'commit_date', 'lock_sha256']
"""

from __future__ import annotations

import hashlib
import os
import platform
import subprocess
from dataclasses import dataclass
from datetime import datetime
from importlib import metadata
from pathlib import Path
from typing import Any

__all__ = ["CORE_PACKAGES", "UNKNOWN", "BuildProvenance", "build_provenance", "project_root"]

UNKNOWN = "unknown"
NOT_INSTALLED = "not installed"
#: distributions whose versions every artifact names, in this order
CORE_PACKAGES = ("numpy", "scipy", "matplotlib", "pandas", "jupyter-book", "navcore")
LOCK_FILE = Path("requirements") / "lock.txt"


def project_root() -> Path:
    """The folder that holds the ``navcore`` package (the checkout, for an editable install)."""
    return Path(__file__).resolve().parents[1]


@dataclass(frozen=True)
class BuildProvenance:
    """What produced an artifact: commit, state of the tree, commit date, lock hash, versions.

    Attributes
    ----------
    commit : str
        The full hash of the checked-out commit, or ``"unknown"``.
    tree : str
        ``"clean"`` when no tracked file differs from the commit, ``"dirty"`` when one does,
        ``"unknown"`` outside a git checkout.
    commit_date : str
        The commit's committer date, ISO 8601 with its offset, or ``"unknown"``.
    lock_sha256 : str
        The SHA-256 (hex) of ``requirements/lock.txt``, or ``"unknown"`` where it is absent.
    python : str
        The Python version (``platform.python_version()``).
    packages : tuple of (str, str)
        ``(distribution, version)`` for each of :data:`CORE_PACKAGES`.
    """

    commit: str
    tree: str
    commit_date: str
    lock_sha256: str
    python: str
    packages: tuple[tuple[str, str], ...]

    def as_dict(self) -> dict[str, Any]:
        """A JSON-ready mapping (the packages as a mapping from name to version)."""
        return {
            "commit": self.commit,
            "tree": self.tree,
            "commit_date": self.commit_date,
            "lock_sha256": self.lock_sha256,
            "python": self.python,
            "packages": dict(self.packages),
        }

    def flat(self, prefix: str = "build_") -> dict[str, str]:
        """One string per field, the packages as their own keys: the columns of a CSV export.

        Examples
        --------
        >>> p = BuildProvenance("abc", "clean", "2026-01-01T00:00:00+00:00", "f0", "3.11.9",
        ...                     (("numpy", "2.4.6"), ("jupyter-book", "1.0.4")))
        >>> list(p.flat())  # doctest: +NORMALIZE_WHITESPACE
        ['build_commit', 'build_tree', 'build_commit_date', 'build_lock_sha256',
         'build_python', 'build_numpy', 'build_jupyter_book']
        """
        out = {f"{prefix}{key}": str(value) for key, value in self.as_dict().items() if key != "packages"}
        out.update({f"{prefix}{name.replace('-', '_')}": version for name, version in self.packages})
        return out

    @property
    def date(self) -> str:
        """The commit's calendar date as a reader writes it (``5 December 2026``), or ``"unknown"``."""
        try:
            when = datetime.fromisoformat(self.commit_date)
        except ValueError:
            return UNKNOWN
        return f"{when.day} {when:%B %Y}"

    def rows(self) -> list[tuple[str, str]]:
        """``(what, value)`` pairs for a reader's table (the About page, a PDF's title page)."""
        state = {"clean": "clean (as committed)", "dirty": "dirty (changed since the commit)"}
        return [
            ("Commit", self.commit),
            ("Working tree", state.get(self.tree, self.tree)),
            ("Commit date", self.commit_date),
            ("Lock file (SHA-256)", self.lock_sha256),
            ("Python", self.python),
            *self.packages,
        ]


def _git(root: Path, *args: str) -> str | None:
    """``git -C root ARGS``'s output (stripped), or None if git is missing or fails."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("GIT_")}  # not a hook's repository
    env["LC_ALL"] = "C"
    try:
        proc = subprocess.run(
            ["git", "--no-optional-locks", "-C", str(root), *args],
            capture_output=True, text=True, env=env, timeout=30, check=False,
        )  # fmt: skip
    except (OSError, subprocess.SubprocessError):
        return None
    return proc.stdout.strip() if proc.returncode == 0 else None


def _file_sha256(path: Path) -> str:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return UNKNOWN


def _version(distribution: str) -> str:
    try:
        return metadata.version(distribution)
    except metadata.PackageNotFoundError:
        return NOT_INSTALLED


def build_provenance(root: Path | str | None = None) -> BuildProvenance:
    """The provenance of a build from the checkout ``root`` (default: navcore's own).

    Parameters
    ----------
    root : path, optional
        The top of the checkout (it holds ``requirements/lock.txt``). The commit is read only
        if ``root`` is the top of a git working tree, so that a package installed inside some
        other repository does not report that repository's commit.

    Returns
    -------
    BuildProvenance
        Deterministic for one commit, one state of the tree and one environment: no field
        depends on the clock or on where the checkout lies.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as bare:
    ...     p = build_provenance(bare)
    >>> p.commit, p.tree, p.commit_date, p.lock_sha256
    ('unknown', 'unknown', 'unknown', 'unknown')
    """
    root = Path(project_root() if root is None else root).resolve()
    commit = tree = commit_date = UNKNOWN
    top = _git(root, "rev-parse", "--show-toplevel")
    if top is not None and Path(top).resolve() == root:
        head = _git(root, "rev-parse", "--verify", "HEAD")
        if head:
            commit = head
            commit_date = _git(root, "log", "-1", "--format=%cI", "HEAD") or UNKNOWN
            status = _git(root, "status", "--porcelain", "--untracked-files=no")
            if status is not None:
                tree = "dirty" if status else "clean"
    return BuildProvenance(
        commit=commit,
        tree=tree,
        commit_date=commit_date,
        lock_sha256=_file_sha256(root / LOCK_FILE),
        python=platform.python_version(),
        packages=tuple((name, _version(name)) for name in CORE_PACKAGES),
    )
