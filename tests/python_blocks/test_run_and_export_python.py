"""``rockly run`` and ``rockly export`` of a ``.py`` program: turned into blocks in memory and run or exported as
the same ``.rockly`` would be (real processes, the built-in simulator); bad input refused as ``rockly import``
refuses it, with nothing written."""
import json
import subprocess
import sys
from pathlib import Path

import pytest
from standalone_tools import environment, run_file

from rockly_desktop.recording.reading import read_recording

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((REPO / "examples").rglob("*.rockly"))
ANSWERS = ("--answer", "yes", "--answer", "Ada")  # the tablet questions of the shipped examples
PYTHON_BLOCKS = "import os\nrobot.drive(0.5, 'forward')\nprint(os.path.basename('/a/b.txt'))\n" \
                "words = [w.upper() for w in ['a', 'b']]\nprint(words)\n"  # lines 1, 3 and 4 stay Python


def rockly(folder: Path, *args) -> subprocess.CompletedProcess:
    """``rockly ARGS`` with the window's settings in ``folder`` (no teacher's limits but this test's)."""
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)], capture_output=True, text=True,
                          timeout=120, cwd=REPO, env=environment(XDG_CONFIG_HOME=str(folder / "config"),
                                                                 XDG_DATA_HOME=str(folder / "data")))


def what_ran(stdout: str) -> list:
    """The run's lines with each block's id left out (converted blocks get ids of their own)."""
    return [line.split()[2] if line.lower().startswith("block ") else line for line in stdout.splitlines()]


def steady(ran: list) -> list:
    """``what_ran`` without the arm's progress reports (``MoveToCandle 25 %``) and the block that printed each:
    which of them a program sees depends on when the simulator's feedback comes, from run to run."""
    progress = {index for index, line in enumerate(ran) if line.endswith(" %")}
    return [line for index, line in enumerate(ran) if index not in progress and index + 1 not in progress]


def files_in(folder: Path) -> set:
    return {path.name for path in folder.iterdir()}


@pytest.mark.parametrize("example", EXAMPLES, ids=[str(path.relative_to(REPO / "examples")) for path in EXAMPLES])
def test_an_exported_example_runs_as_its_rockly_file_does(tmp_path, example):
    exported = tmp_path / "program.py"
    assert rockly(tmp_path, "export", example, "-o", exported).returncode == 0
    # simulated time 10x: the examples react to the simulator (obstacles, the arm's progress), and on a busy
    # machine much faster time changes what they see, the .rockly file's run included
    as_blocks = rockly(tmp_path, "run", example, "--speed", "10", *ANSWERS)
    as_python = rockly(tmp_path, "run", exported, "--speed", "10", *ANSWERS)
    assert as_blocks.returncode == as_python.returncode == 0, (as_blocks.stderr, as_python.stderr)
    assert steady(what_ran(as_python.stdout)) == steady(what_ran(as_blocks.stdout))
    assert as_python.stdout.splitlines()[-1] == "finished" and "rockly_python" not in as_python.stdout
    assert as_python.stderr == ""  # every line became blocks: nothing to say
    assert files_in(tmp_path) <= {"program.py", "config", "data"}


def test_what_blocks_cannot_say_runs_as_python_blocks_and_is_said_once(tmp_path):
    program = tmp_path / "mixed.py"
    program.write_text(PYTHON_BLOCKS)
    result = rockly(tmp_path, "run", program, "--speed", "50", "--language", "de")
    assert result.returncode == 0, result.stderr
    ran = what_ran(result.stdout)
    assert [entry for entry in ran if not entry.startswith("Ausgabe ")] == [
        "rockly_python", "hobbit_move", "rockly_python", "rockly_python", "text_print", "fertig"]
    printed = [line.split(None, 1)[1] for line in result.stdout.splitlines() if line.startswith("Ausgabe ")]
    assert printed == ["b.txt", "['A', 'B']"]
    said = [line for line in result.stderr.splitlines() if "Python-Blöcken" in line]
    assert said == ["rockly run: Warnung: Diese Zeilen des Python-Programms wurden zu Python-Blöcken und laufen als "
                    "Python (erlaubt auf der Stufe Alles): 1, 3, 4"]
    assert files_in(tmp_path) <= {"mixed.py", "config", "data"}


def test_a_standalone_export_of_a_py_program_runs(tmp_path):
    program = tmp_path / "mixed.py"
    program.write_text(PYTHON_BLOCKS)
    exported = tmp_path / "out" / "standalone.py"
    exported.parent.mkdir()
    result = rockly(tmp_path, "export", program, "--standalone", "-o", exported, "--language", "en")
    assert result.returncode == 0, result.stderr
    assert "became Python blocks and run as Python (allowed at the Full level): 1, 3, 4" in result.stderr
    ran = run_file(exported, "--backend", "sim", "--speed", "50")
    assert ran.returncode == 0, ran.stderr
    assert [line.split(None, 1)[1] for line in ran.stdout.splitlines() if line.startswith("print ")] == [
        "b.txt", "['A', 'B']"]
    assert ran.stdout.splitlines()[-1] == "finished"


def test_a_plain_export_of_a_py_program_is_rocklys_python_for_it(tmp_path):
    program = tmp_path / "drive.py"
    program.write_text("robot.drive(0.5, 'forward')\n")
    exported = tmp_path / "again.py"
    assert rockly(tmp_path, "export", program, "-o", exported).returncode == 0
    text = exported.read_text()
    assert text.startswith("# Generated by Rockly from 'drive.py' for the robot profile 'hobbit'.")
    assert text.endswith("\nrobot.drive(0.5, 'forward')\n")
    assert program.read_text() == "robot.drive(0.5, 'forward')\n"


@pytest.mark.parametrize("command", ["run", "export"])
def test_bad_python_is_refused_as_import_refuses_it_and_nothing_is_written(tmp_path, command):
    cases = {
        "syntax": ("x = 1\n" * 899 + "if x =\n", "Line 900,"),
        "json": ('{"format": "rockly-program"}', "not a Python program"),
        "other_robot": ("if robot.obstacle_closer_than(0.4, 'ahead'):\n  robot.turn(90, 'left')\n",
                        "written for the robot 'turtlebot', not for 'hobbit'"),
        "unknown_robot": ("# Generated by Rockly for the robot profile 'r2d2'.\nx = 1\n",
                          "'r2d2', which is not installed"),
        "too_big": ("x = 1\n" * 400_000, "larger than 2 MB"),
    }
    for name, (text, said) in cases.items():
        program = tmp_path / f"{name}.py"
        program.write_text(text)
        extra = ["-o", tmp_path / "out.py"] if command == "export" else []
        result = rockly(tmp_path, command, program, *extra, "--language", "en")
        assert result.returncode == 1, name
        assert result.stderr.startswith(f"rockly {command}: {program}: ") and said in result.stderr, (name, result)
        assert result.stdout == ""
    binary = tmp_path / "binary.py"
    binary.write_bytes(b"\x7fELF\x00\x01\xff")
    result = rockly(tmp_path, command, binary, *(["-o", tmp_path / "out.py"] if command == "export" else []),
                    "--language", "de")
    assert result.returncode == 1 and "Text" in result.stderr
    assert not (tmp_path / "out.py").exists()
    assert files_in(tmp_path) <= {f"{name}.py" for name in cases} | {"binary.py", "config", "data"}


def test_profile_chooses_the_robot_of_a_py_program_and_is_refused_for_a_rockly_file(tmp_path):
    program = tmp_path / "turtle.py"
    program.write_text("# Generated by Rockly for the robot profile 'turtlebot'.\nprint('hi')\n")
    refused = rockly(tmp_path, "run", program, "--profile", "hobbit", "--language", "en")
    assert refused.returncode == 1 and "written for the robot 'turtlebot', not for 'hobbit'" in refused.stderr
    ran = rockly(tmp_path, "run", program, "--profile", "turtlebot", "--speed", "50")
    assert ran.returncode == 0 and ran.stdout.splitlines()[-2:] == ["print   hi", "finished"], ran.stderr
    for_a_file = rockly(tmp_path, "run", EXAMPLES[0], "--profile", "hobbit")
    assert for_a_file.returncode == 2 and "--profile is for a .py program only" in for_a_file.stderr


def test_a_recorded_run_of_a_py_program_keeps_the_blocks_it_became(tmp_path):
    program = tmp_path / "mixed.py"
    program.write_text(PYTHON_BLOCKS)
    recording = tmp_path / "run.mcap"
    result = rockly(tmp_path, "run", program, "--speed", "50", "--record", recording)
    assert result.returncode == 0, result.stderr
    recorded = read_recording(recording)
    assert recorded.metadata["program"] == "mixed.py"
    document = json.loads(recorded.program)
    assert document["profile"] == "hobbit"
    top = document["workspace"]["blocks"]["blocks"][0]
    assert (top["type"], top["next"]["block"]["type"]) == ("rockly_python", "hobbit_move")
