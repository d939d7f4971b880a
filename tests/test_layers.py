"""The layering contracts in pyproject.toml hold, and they do catch a violation."""
import shutil
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
LINT_IMPORTS = Path(sys.executable).with_name("lint-imports")


def lint_imports(cwd: Path):
    return subprocess.run([str(LINT_IMPORTS), "--no-cache"], capture_output=True, text=True, cwd=cwd,
                          env={"PYTHONPATH": str(cwd), "PATH": "/usr/bin:/bin"}, timeout=120)


def test_layer_contracts_are_kept():
    result = lint_imports(REPO)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "Contracts: 4 kept, 0 broken." in result.stdout


def test_a_core_module_importing_qt_breaks_the_contracts(tmp_path):
    shutil.copytree(REPO / "rockly_desktop", tmp_path / "rockly_desktop", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(REPO / "pyproject.toml", tmp_path)
    (tmp_path / "rockly_desktop" / "core" / "sneaky.py").write_text(
        "from PySide6.QtWidgets import QWidget\nfrom rockly_desktop.ui import main_window\n")
    result = lint_imports(tmp_path)
    assert result.returncode == 1
    assert "rockly_desktop.core.sneaky -> rockly_desktop.ui.main_window" in result.stdout
    assert "BROKEN" in result.stdout


def test_no_rockly_module_mentions_a_particular_robot():
    """Robots are profiles: Rockly's own code must not know any of them by name."""
    robots = [folder.name for folder in (REPO / "profiles").iterdir() if (folder / "profile.yaml").exists()]
    assert len(robots) >= 2
    for path in (REPO / "rockly_desktop").rglob("*.py"):
        text = path.read_text(encoding="utf-8").lower()
        for robot in robots:
            assert robot not in text, f"{path.relative_to(REPO)} mentions {robot}"
