"""``rockly agent --offer-on-robot-ui PROFILE`` where it cannot offer anything says why plainly, in the agent's
language, and does not start (exit 2): a profile that declares no ``program_menu``, the agent's own simulator
(nobody sees its UI), a profile that is not installed."""
import subprocess
import sys

import pytest
from agent_tools import REPO


def agent(tmp_path, *options, language="en"):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--host", "127.0.0.1", "--port", "0",
                           "--library", str(tmp_path / "library"), "--language", language, *options],
                          cwd=REPO, capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("language, says", [
    ("en", "rockly agent: offering the programs on the robot's own UI is not offered for this robot: its profile "
           "(TurtleBot) does not say how\n"),
    ("de", "rockly agent: Programme auf der eigenen Oberfläche des Roboters anzubieten gibt es für diesen Roboter "
           "nicht: sein Profil (TurtleBot) sagt nicht, wie\n"),
])
def test_a_profile_without_a_program_menu_says_it_is_not_offered_for_this_robot(tmp_path, language, says):
    result = agent(tmp_path, "--backend", "ros1", "--offer-on-robot-ui", "turtlebot", language=language)
    assert (result.returncode, result.stdout, result.stderr) == (2, "", says)


def test_the_agents_own_simulator_is_refused_with_the_way_to_try_it_without_a_robot(tmp_path):
    result = agent(tmp_path, "--backend", "sim", "--offer-on-robot-ui", "hobbit")
    assert result.returncode == 2 and result.stdout == ""
    assert "needs a robot ('--backend ros1' or 'ros2')" in result.stderr
    assert "'rockly sim hobbit --ros'" in result.stderr


def test_a_profile_that_is_not_installed_is_named_with_those_that_are(tmp_path):
    result = agent(tmp_path, "--backend", "ros1", "--offer-on-robot-ui", "dalek")
    assert result.returncode == 2
    assert result.stderr == ("rockly agent: there is no robot profile 'dalek' here (installed: hobbit, turtlebot), "
                             "so --offer-on-robot-ui cannot offer anything\n")


def test_a_robot_that_cannot_be_reached_is_said_in_the_agents_language(tmp_path):
    result = agent(tmp_path, "--backend", "ros1", "--master", "http://127.0.0.1:1", "--offer-on-robot-ui", "hobbit",
                   language="de")
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr == ("rockly agent: die Programme können nicht auf der eigenen Oberfläche des Roboters "
                             "angeboten werden: Unter http://127.0.0.1:1 antwortet kein ROS-Master.\n")
