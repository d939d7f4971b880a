"""What runs on a robot's own Python (rockly-runtime, and the built-in profiles' robot code) needs no more
than Python 3.8 (Ubuntu 20.04 with ROS Noetic): no newer syntax (ruff's per-file target in pyproject.toml)
and no newer standard library call (vermin, here)."""
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
VERMIN = Path(sys.executable).with_name("vermin")
ON_THE_ROBOT = ["rockly_desktop/__init__.py", "rockly_desktop/sdk.py", "rockly_desktop/core", "rockly_desktop/executor",
                "rockly_desktop/lessons",
                "rockly_desktop/profiles", "rockly_desktop/recording", "rockly_desktop/robot", "rockly_desktop/runtime",
                *sorted(str(path.relative_to(REPO)) for path in REPO.glob("profiles/*/rockly_*/*.py"))]


def vermin(*paths, cwd=REPO):
    return subprocess.run([str(VERMIN), "--target=3.8-", "--violations", "--eval-annotations", "--no-tips",
                           "--no-parse-comments", *map(str, paths)], capture_output=True, text=True, cwd=cwd,
                          timeout=300)


def test_the_runtime_needs_no_python_newer_than_3_8():
    result = vermin(*ON_THE_ROBOT)
    assert result.returncode == 0, result.stdout + result.stderr


def test_the_check_sees_a_call_python_3_8_lacks(tmp_path):
    (tmp_path / "newer.py").write_text("import functools\n\n@functools.cache\ndef f():\n    return zip('a', 'b', "
                                       "strict=True)\n")
    result = vermin(tmp_path / "newer.py")
    assert result.returncode != 0 and "functools.cache" in result.stdout and "zip(strict)" in result.stdout
