"""examples/turtlebot/avoid-obstacles.rockly: a valid program that drives the simulated TurtleBot around
the boxes without touching any, headless (`rockly run`) and through the editor page and runner in this process."""
import json
import math
import subprocess
import sys

import pytest
from profile_copies import REPO

from rockly_desktop.core.program import load_program
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.lessons.stepping import SteppedClock, SteppedRobot
from rockly_desktop.profiles.opening import read_program_to_open
from rockly_desktop.profiles.registry import ProfileRegistry

EXAMPLE = REPO / "examples" / "turtlebot" / "avoid-obstacles.rockly"
RADIUS = 0.105


def test_the_example_is_a_rockly_document_for_the_turtlebot():
    document = json.loads(EXAMPLE.read_text(encoding="utf-8"))
    assert set(document) == {"format", "version", "profile", "workspace", "breakpoints"}
    assert (document["format"], document["version"], document["profile"], document["breakpoints"]) == (
        "rockly-program", 1, "turtlebot", [])
    program = load_program(EXAMPLE)
    assert program.profile_id == "turtlebot"
    types = sorted(set(block_types_by_id(program.workspace).values()))
    assert types == ["controls_if", "controls_repeat_ext", "math_number", "turtlebot_drive", "turtlebot_obstacle",
                     "turtlebot_turn"]


def test_rockly_run_drives_it_headless_and_exits_0():
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(EXAMPLE.relative_to(REPO)),
                             "--speed", "20"], capture_output=True, text=True, timeout=120, cwd=REPO)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[-1] == "finished"
    entered = [line.split()[-1] for line in lines if line.startswith("block ")]
    assert entered.count("controls_if") == 20
    assert entered.count("turtlebot_turn") == 3          # one turn at each of the three boxes
    assert entered.count("turtlebot_drive") == 17


@pytest.fixture(scope="module")
def editor(qapp):
    from rockly_desktop.bridge.headless import HeadlessEditor

    editor = HeadlessEditor("en")
    yield editor
    editor.close()


def test_the_same_program_in_the_editor_and_runner_never_touches_a_box_or_a_wall(editor):
    registry = ProfileRegistry.discover()
    program = read_program_to_open(EXAMPLE, registry, registry.default())
    assert program.profile.id == "turtlebot"
    python = editor.python_for(program)
    assert python.strip().splitlines() == [
        "for count in range(20):",
        "  if robot.obstacle_closer_than(0.4, 'ahead'):",
        "    robot.turn(90, 'left')",
        "  else:",
        "    robot.drive(0.2, 'forward')",
    ]
    run_code = editor.call_and_wait("getRunCode")

    # stepped simulated time (as a lesson's check): at 20x real time a loaded machine's late ticks let the robot
    # drive on past its laser's look (0.18 m from a wall once in a shuffled run beside other suites)
    robot = SteppedRobot(program.profile)
    robot.use_clock(SteppedClock(robot.simulator, robot.world, 600.0, lambda: None, lambda: None))
    arena = robot.simulator._arena
    clearances = []
    robot.world.tap(lambda topic, _type, message: clearances.append(arena.clearance(
        message["pose"]["pose"]["position"]["x"], message["pose"]["pose"]["position"]["y"]))
        if topic == "/odom" else None)
    try:
        result = make_runner(program.profile, robot, run_code, RunControl(), lambda event: None).run()
        end = robot.snapshot()
    finally:
        robot.shutdown()
    assert (result.outcome, result.message) == ("finished", None)
    assert end["bumps"] == 0 and end["bumped"] is False
    assert min(clearances) > RADIUS + 0.1, "it came close to touching something"
    # along the first box, up to the second, back to the third, then down the room
    assert (end["x"], end["y"]) == (pytest.approx(1.2, abs=0.03), pytest.approx(0.2, abs=0.03))
    assert math.degrees(end["theta"]) == pytest.approx(-90, abs=2)
    assert (end["linear"], end["angular"]) == (0.0, 0.0)
