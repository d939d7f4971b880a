"""A profile whose Python is broken: validate names every module that does not import, and
``rockly run`` says what is wrong instead of printing a traceback."""
import json
import os
import subprocess
import sys

import pytest
from profile_copies import REPO
from program_builder import block, rockly_document


def rockly(*args, env):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)],
                          capture_output=True, text=True, timeout=90, cwd=REPO, env=env)


@pytest.fixture
def mybot(tmp_path):
    """A profile made by ``rockly profiles new mybot`` in the user's folder, and the environment that finds it."""
    env = {**os.environ, "XDG_DATA_HOME": str(tmp_path / "xdg")}
    assert rockly("profiles", "new", "mybot", env=env).returncode == 0
    return tmp_path / "xdg" / "rockly" / "profiles" / "mybot", env


def break_module(folder, module, first_line):
    path = folder / "rockly_mybot" / module
    path.write_text(first_line + "\n" + path.read_text(encoding="utf-8"), encoding="utf-8")


def test_validate_names_every_module_that_does_not_import(mybot):
    folder, env = mybot
    break_module(folder, "api.py", "import sys; sys.exit(3)")
    break_module(folder, "sim.py", "def broken(:")

    result = rockly("profiles", "validate", folder, env=env)

    assert result.returncode == 1
    assert "api: cannot import rockly_mybot.api:MybotCommands: the code called sys.exit(3)" in result.stderr
    assert "simulator: cannot import rockly_mybot.sim:SimMybot: SyntaxError" in result.stderr


@pytest.mark.parametrize("module, first_line, problem", [
    ("api.py", "raise RuntimeError('boom')", "api: cannot import rockly_mybot.api:MybotCommands: RuntimeError: boom"),
    ("api.py", "import sys; sys.exit(3)", "the code called sys.exit(3)"),
    ("sim.py", "raise RuntimeError('no sim')", "simulator: cannot import rockly_mybot.sim:SimMybot"),
])
def test_run_says_which_part_of_the_profile_is_broken(mybot, tmp_path, module, first_line, problem):
    folder, env = mybot
    break_module(folder, module, first_line)
    program = tmp_path / "hello.rockly"
    document = json.loads(rockly_document([block("mybot_say")], profile="mybot"))
    program.write_text(json.dumps(document), encoding="utf-8")

    result = rockly("run", program, env=env)

    assert result.returncode == 1
    assert problem in result.stderr
    assert "Traceback" not in result.stderr
