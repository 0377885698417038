"""The lock pins every distribution by hash, and an install with a wrong hash fails.

The nox sessions install ``requirements/lock.txt`` with ``--require-hashes``. The second test
makes the same kind of install offline: a wheel built here, a requirements file naming it with
its true hash (the install succeeds) or with one digit changed (the install must fail).
"""

from __future__ import annotations

import base64
import hashlib
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_every_locked_distribution_carries_a_hash() -> None:
    text = (ROOT / "requirements" / "lock.txt").read_text()
    entries = re.split(r"\n(?=[A-Za-z0-9])", text.split("\n", 2)[2])  # one entry per pin
    pins = [e for e in entries if re.match(r"[A-Za-z0-9][\w.-]*==", e)]
    assert len(pins) > 100
    unhashed = [e.split()[0] for e in pins if not re.search(r"--hash=sha256:[0-9a-f]{64}", e)]
    assert unhashed == []
    for build_requirement in ("hatchling==", "editables=="):  # navcore's build backend, hash-checked too
        assert any(e.startswith(build_requirement) for e in pins)


def _wheel(folder: Path) -> Path:
    """A minimal valid wheel of a one-module distribution ``toyhash`` 0.1."""
    files = {
        "toyhash.py": b"VALUE = 1\n",
        "toyhash-0.1.dist-info/METADATA": b"Metadata-Version: 2.1\nName: toyhash\nVersion: 0.1\n",
        "toyhash-0.1.dist-info/WHEEL": (
            b"Wheel-Version: 1.0\nGenerator: test\nRoot-Is-Purelib: true\nTag: py3-none-any\n"
        ),
    }
    record = []
    for name, data in files.items():
        digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
        record.append(f"{name},sha256={digest},{len(data)}")
    record.append("toyhash-0.1.dist-info/RECORD,,")
    path = folder / "toyhash-0.1-py3-none-any.whl"
    with zipfile.ZipFile(path, "w") as zf:
        for name, data in files.items():
            zf.writestr(name, data)
        zf.writestr("toyhash-0.1.dist-info/RECORD", "\n".join(record) + "\n")
    return path


def _installer() -> list[str] | None:
    if shutil.which("uv"):
        return ["uv", "pip", "install", "--python", sys.executable]
    if subprocess.run([sys.executable, "-m", "pip", "--version"], capture_output=True).returncode == 0:
        return [sys.executable, "-m", "pip", "install", "--disable-pip-version-check"]
    return None


def test_an_install_with_a_tampered_hash_fails(tmp_path: Path) -> None:
    installer = _installer()
    if installer is None:
        pytest.skip("neither uv nor pip")
    wheel = _wheel(tmp_path)
    good = hashlib.sha256(wheel.read_bytes()).hexdigest()
    bad = good[:-1] + ("0" if good[-1] != "0" else "1")
    results = {}
    for label, digest in (("good", good), ("tampered", bad)):
        requirements = tmp_path / f"{label}.txt"
        requirements.write_text(f"toyhash==0.1 --hash=sha256:{digest}\n")
        target = tmp_path / f"target-{label}"
        cmd = [
            *installer, "--require-hashes", "--no-index", "--find-links", str(tmp_path),
            "--target", str(target), "-r", str(requirements),
        ]  # fmt: skip
        results[label] = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert results["good"].returncode == 0, results["good"].stderr
    assert (tmp_path / "target-good" / "toyhash.py").exists()
    assert results["tampered"].returncode != 0
    assert "hash" in (results["tampered"].stderr + results["tampered"].stdout).lower()
    assert not (tmp_path / "target-tampered" / "toyhash.py").exists()
