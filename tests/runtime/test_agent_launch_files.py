"""The ways docs/agent.md starts the agent on a robot: the ROS 1 package's node script (roslaunch adds
``__name:=`` and ``__log:=`` arguments the agent does not take) and the ROS 2 launch file."""
import ast
import os
import subprocess
import sys

from agent_tools import REPO

from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.runtime.agent.pairings import Pairings, agent_folder

DOCS = REPO / "docs" / "agent"


def test_the_ros1_node_script_starts_the_agent_without_roslaunchs_arguments(tmp_path):
    rockly_agent = tmp_path / "rockly-agent"  # as rockly-runtime installs it
    rockly_agent.write_text(f'#!/bin/sh\nexec {sys.executable} -c "import sys; from rockly_desktop.runtime.agent.'
                            f'commands import agent_main; sys.exit(agent_main())" "$@"\n')
    rockly_agent.chmod(0o755)
    node = subprocess.Popen([str(DOCS / "rockly_agent" / "rockly_agent"), "--backend", "sim", "--host", "127.0.0.1",
                             "--port", "0", "--library", str(tmp_path / "library"), "__name:=rockly_agent",
                             f"__log:={tmp_path / 'rockly_agent.log'}"],
                            env={**os.environ, "ROCKLY_AGENT": str(rockly_agent)}, cwd=REPO, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        ready = node.stdout.readline()
        assert "listening on 127.0.0.1:" in ready, node.stderr.read()
        client = AgentClient("127.0.0.1", int(ready.split("127.0.0.1:")[1].split(",")[0]))
        client.pair(Pairings(agent_folder(tmp_path / "library")).new_code().shown)
        assert client.programs() == {"programs": [], "run": None}
        client.close()
    finally:
        node.terminate()
        node.communicate(timeout=60)
    assert node.returncode == 0


def test_the_launch_files_name_the_agent():
    launch = (DOCS / "rockly_agent" / "launch" / "rockly_agent.launch").read_text()
    assert 'pkg="rockly_agent" type="rockly_agent"' in launch and "--backend ros1" in launch
    assert '<arg name="options" default=""/>' in launch and "$(arg options)" in launch  # e.g. --offer-on-robot-ui
    ros2 = parse_python((DOCS / "rockly_agent.launch.py").read_text())
    assert "generate_launch_description" in [node.name for node in ros2.body if isinstance(node, ast.FunctionDef)]
    unit = (DOCS / "rockly-agent.service").read_text()
    assert "rockly-agent --backend ros1" in unit and "KillSignal=SIGTERM" in unit
