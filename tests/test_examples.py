"""Every example program runs headless to its end on its robot's simulator; the German ones
(``examples/de/``) are the English ones with German texts."""
import json
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
    "de/hobbit/Aufräumen.rockly": ["yes"],
    "de/hobbit/arm-mit-Fortschritt.rockly": [],
    "de/hobbit/fahre-ein-Quadrat.rockly": ["Mia", "yes"],
    "de/turtlebot/Hindernissen-ausweichen.rockly": [],
}
GERMAN = {"de/hobbit/Aufräumen.rockly": "hobbit/tidy-up.rockly",
          "de/hobbit/arm-mit-Fortschritt.rockly": "hobbit/arm-with-progress.rockly",
          "de/hobbit/fahre-ein-Quadrat.rockly": "hobbit/drive-a-square.rockly",
          "de/turtlebot/Hindernissen-ausweichen.rockly": "turtlebot/avoid-obstacles.rockly"}
# texts that are code (ROS names, a goal's status), the same in every language
CODE_TEXTS = {"", "/cmd_vel", "hobbit_arm", "MoveToCandle", "feedback.data", "succeeded"}
EXAMPLES = sorted(str(path.relative_to(REPO / "examples")) for path in (REPO / "examples").rglob("*.rockly"))


def test_every_example_is_listed_here():
    assert EXAMPLES == sorted(ANSWERS)


@pytest.mark.parametrize("example", EXAMPLES)
def test_example_runs_to_its_end(example):
    answers = [argument for answer in ANSWERS[example] for argument in ("--answer", answer)]
    language = "de" if example.startswith("de/") else "en"
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(REPO / "examples" / example),
                             "--speed", "25", "--language", language, *answers],
                            capture_output=True, text=True, cwd=REPO, timeout=240)
    assert result.returncode == 0, result.stderr[-2000:]
    assert "warning" not in result.stderr.lower()  # opens as written: its profile, every field value kept
    assert result.stdout.splitlines()[-1] == ("fertig" if language == "de" else "finished")


def _blocks_and_texts(example):
    """(the block types in file order, the TEXT field values, the variable names) of an example."""
    types, texts = [], []

    def walk(value):
        if isinstance(value, dict):
            if isinstance(value.get("type"), str):
                types.append(value["type"])
            if isinstance(value.get("fields"), dict) and "TEXT" in value["fields"]:
                texts.append(value["fields"]["TEXT"])
            for item in value.values():
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)

    workspace = json.loads((REPO / "examples" / example).read_text(encoding="utf-8"))["workspace"]
    walk(workspace)
    return types, texts, [variable["name"] for variable in workspace.get("variables", [])]


@pytest.mark.parametrize(("german", "english"), sorted(GERMAN.items()))
def test_a_german_example_is_its_english_one_with_every_text_in_german(german, english):
    german_types, german_texts, german_variables = _blocks_and_texts(german)
    english_types, english_texts, english_variables = _blocks_and_texts(english)
    assert german_types == english_types
    for said, original in zip(german_texts, english_texts, strict=True):
        assert said != original or said in CODE_TEXTS, said
    assert len(german_variables) == len(english_variables)
    assert not set(german_variables) & set(english_variables)


def test_every_english_example_has_a_german_one():
    assert sorted(GERMAN.values()) == sorted(example for example in EXAMPLES if not example.startswith("de/"))


@pytest.mark.parametrize("example", [example for example in EXAMPLES if "turtlebot/" in example])
def test_a_turtlebot_example_runs_unchanged_on_a_robot_declared_jazzy(example, monkeypatch, capsys):
    """The same program on a TurtleBot that wants TwistStamped on /cmd_vel (ROS 2 Jazzy on): it runs to
    its end, and everything it (and its safe stop) sends on /cmd_vel is a TwistStamped."""
    from rockly_desktop import run_command
    from rockly_desktop.robot.wrappers.limits import Limits
    from rockly_desktop.runtime import run as runtime_run

    sent_types = []

    def open_link(*arguments, **options):
        robot = real_open_link(*arguments, **options)
        robot.world.tap(lambda topic, msg_type, _message: sent_types.append(msg_type) if topic == "/cmd_vel" else None)
        return robot

    real_open_link = runtime_run.open_link
    monkeypatch.setattr(runtime_run, "open_link", open_link)
    language = "de" if example.startswith("de/") else "en"
    lines = []
    # 10, not the CLI tests' 25: in this process, under load, the example's laser loop saw the box too late
    status = run_command.run_program(REPO / "examples" / example, speed=10, language=language, out=lines.append,
                                     connection={"ros_distribution": "jazzy"},
                                     teacher=type("NoLimits", (), {"limits": lambda self, _id: Limits()})())
    assert status == 0 and capsys.readouterr().out.splitlines()[-1] == ("fertig" if language == "de" else "finished")
    assert any("turtlebot_drive" in line for line in lines)
    assert sent_types and set(sent_types) == {"geometry_msgs/TwistStamped"}
