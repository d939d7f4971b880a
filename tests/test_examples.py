"""Every example program runs headless to its end on its robot's simulator."""
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
# What a person would answer on the tablet, in order, for each example that asks.
ANSWERS = {
    "hobbit/tidy-up.rockly": ["yes"],
    "hobbit/arm-with-progress.rockly": [],
    "hobbit/drive-a-square.rockly": ["Mia", "yes"],
    "turtlebot/avoid-obstacles.rockly": [],
}
EXAMPLES = sorted(str(path.relative_to(REPO / "examples")) for path in (REPO / "examples").rglob("*.rockly"))


def test_every_example_is_listed_here():
    assert EXAMPLES == sorted(ANSWERS)


@pytest.mark.parametrize("example", EXAMPLES)
def test_example_runs_to_its_end(example):
    answers = [argument for answer in ANSWERS[example] for argument in ("--answer", answer)]
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(REPO / "examples" / example),
                             "--speed", "25", *answers], capture_output=True, text=True, cwd=REPO, timeout=240)
    assert result.returncode == 0, result.stderr[-2000:]
    assert "warning" not in result.stderr  # opens as written: its profile, every field value kept
    assert result.stdout.splitlines()[-1] == "finished"
