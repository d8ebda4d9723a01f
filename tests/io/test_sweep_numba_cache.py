"""A sweep with Numba installed works where Numba cannot cache compiled code on disk.

Numba's ``cache=True`` looks for a writable ``__pycache__`` beside the source, then a
user-wide cache under ``HOME``; with neither it raised at import ("no locator
available"), so ``spinimpact.io.sweep`` could not even be imported from a read-only
installation (a system package, a container image) by a user whose ``HOME`` is read-only.
"""

import os
import shutil
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

import spinimpact

pytest.importorskip("numba", reason="the [fast] extra (numba) is not installed")

CHILD = """
import os, pathlib, sys, tempfile
pkg, home = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
for where in (pkg / "spinimpact" / "core", home):  # the environment really is read-only
    try:
        tempfile.TemporaryFile(dir=where).close()
    except OSError:
        continue
    print("WRITABLE", where)
    sys.exit(3)
import spinimpact.io.sweep as s
from spinimpact import Body
from spinimpact.core import fused
assert pathlib.Path(s.__file__).is_relative_to(pkg), s.__file__
assert fused.HAVE_NUMBA
axes = {n: s.parse_axis(n, v) for n, v in
        dict(vx="-2:2:5", vy="-1", omega="0", mu="0.5", kappa="0.8").items()}
r = s.run_sweep(s.Sweep(Body.solid_sphere(mass=1.0, radius=0.1), axes))
print("points", r.points)
"""


def _folders(root: Path) -> list[Path]:
    return [root, *(p for p in root.rglob("*") if p.is_dir())]


def _make_read_only(root: Path) -> None:
    """Read-only for an ordinary user; root writes anyway, so its folders are also made
    immutable where the file system allows it (``chattr +i``: not even root may add a file)."""
    for path in [root, *root.rglob("*")]:
        path.chmod(0o555 if path.is_dir() else 0o444)
    if os.geteuid() == 0 and shutil.which("chattr"):
        subprocess.run(["chattr", "+i", *map(str, _folders(root))], capture_output=True)


def _undo(root: Path) -> None:
    if os.geteuid() == 0 and shutil.which("chattr"):
        subprocess.run(["chattr", "-i", *map(str, _folders(root))], capture_output=True)
    for path in _folders(root):
        path.chmod(path.stat().st_mode | stat.S_IWUSR)
    shutil.rmtree(root)


@pytest.mark.slow
def test_sweep_runs_without_a_writable_package_folder_or_home():
    root = Path(tempfile.mkdtemp(prefix="spinimpact-ro-"))  # not under pytest's 0700 tmp
    try:
        pkg, home = root / "pkg", root / "home"
        source = Path(spinimpact.__file__).parent
        shutil.copytree(source, pkg / "spinimpact", ignore=shutil.ignore_patterns("__pycache__"))
        home.mkdir()
        _make_read_only(root)
        env = {k: v for k, v in os.environ.items()
               if k not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME", "PYTHONPATH")}  # fmt: skip
        env |= {"HOME": str(home), "PYTHONPATH": str(pkg), "PYTHONDONTWRITEBYTECODE": "1"}
        out = subprocess.run(
            [sys.executable, "-c", CHILD, str(pkg), str(home)],
            capture_output=True,
            text=True,
            env=env,
            cwd=root,
            timeout=300,
        )
        if out.returncode == 3:
            pytest.skip(f"cannot make a read-only environment here: {out.stdout.strip()}")
        assert out.returncode == 0, out.stderr[-2000:]
        assert out.stdout.strip() == "points 5"
        assert "no locator" not in out.stderr
    finally:
        _undo(root)
