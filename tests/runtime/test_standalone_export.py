"""``rockly export PROGRAM --standalone -o OUT.py``: a file that runs the program without the window
(``python3 OUT.py --backend sim``), with the teacher's limits of the export, the robot's safe stop on every
end and an event stream; real processes on the built-in simulator."""
import ast
import runpy
import signal

import pytest
from hypothesis import given
from hypothesis import strategies as st
from program_builder import block, number, rockly_document, stack
from standalone_tools import (
    end,
    events,
    export_standalone,
    exported_program,
    run_file,
    start_file,
    wait_for_event,
)

from rockly_desktop.runtime.standalone_file import data_literal, text_literal


def drive_and_tell():
    """Drive 1 m, print HOBBIT's x position, open the gripper (the arm: a capability a teacher may switch off)."""
    return stack(block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
                 block("text_print", inputs={"TEXT": block("hobbit_position", {"coordinate": "x"})}, id="where"),
                 block("hobbit_arm_gripper", {"movement": "OpenGripper"}, id="arm"))


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """The drive-and-tell program exported with no teacher's limits (a folder of its own for the settings)."""
    return exported_program(tmp_path_factory.mktemp("standalone"), drive_and_tell())[0]


def test_the_export_runs_on_the_simulator_and_moves_the_robot(exported):
    result = run_file(exported, "--backend", "sim", "--speed", "20", "--events", "-")
    assert result.returncode == 0, result.stderr
    stream = events(result.stdout)  # standard output carries the events alone
    assert stream[0]["event"] == "started" and stream[0]["program"] == "drive.rockly"
    assert (stream[0]["profile"], stream[0]["profile_version"], stream[0]["backend"]) == ("hobbit", "1.0.0", "sim")
    assert [(record["id"], record["type"]) for record in stream if record["event"] == "block"] == [
        ("drive", "hobbit_move"), ("where", "text_print"), ("arm", "hobbit_arm_gripper")]
    printed = [record["text"] for record in stream if record["event"] == "print"]
    assert len(printed) == 1 and float(printed[0]) == pytest.approx(1.0, abs=0.1)  # it drove a metre
    assert stream[-2] == {"event": "finished", "outcome": "finished", "block": None, "message": None,
                          "by_robot": False}
    assert stream[-1] == {"event": "exit", "status": 0}
    assert result.stderr.splitlines()[-1] == "finished"


def test_without_an_event_stream_the_file_prints_what_the_program_prints(exported):
    result = run_file(exported, "--speed", "20")  # the simulator by default
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith("print   ") and float(lines[0].split()[1]) == pytest.approx(1.0, abs=0.1)
    assert lines[-1] == "finished"


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "Ctrl+C"])
def test_a_signal_mid_drive_stops_the_program_with_the_safe_stop(exported, signum):
    """As a launch file (SIGTERM) or a person at the robot's terminal (Ctrl+C) ends it: slow simulated time,
    so the drive is under way when the signal comes."""
    process = start_file(exported, "--backend", "sim", "--speed", "0.05", "--events", "-")
    seen = []
    try:
        wait_for_event(process, lambda record: record.get("id") == "drive", seen)
        process.send_signal(signum)
        process.wait(60)
        seen += events(process.stdout.read())
    finally:
        end(process)
    assert process.returncode == 128 + signum
    assert seen[-2]["event"] == "finished" and seen[-2]["outcome"] == "stopped" and seen[-2]["block"] == "drive"
    assert seen[-1] == {"event": "exit", "status": 128 + signum}
    assert "stopped (the robot was stopped safely)" in process.stderr.read()


def test_the_teachers_limits_of_the_export_are_in_the_file_and_kept(tmp_path, isolated_user_folders):
    """Limits set in the window when exporting travel in the file; changing them later changes nothing."""
    from rockly_desktop.settings.app_settings import AppSettings

    settings = AppSettings(isolated_user_folders / "config" / "Rockly" / "Rockly.conf")  # where the window keeps them
    settings.teacher.set_limits("hobbit", max_speed=0.1, switched_off={"arm"})
    settings.sync()
    source = tmp_path / "drive.rockly"
    source.write_text(rockly_document([drive_and_tell()]))
    exported = export_standalone(source, tmp_path / "drive.py", "--language", "en")
    assert runpy.run_path(str(exported))["PROGRAM"]["limits"] == {"max_speed": 0.1, "max_turn": None,
                                                                  "switched_off": ["arm"]}
    settings.teacher.set_limits("hobbit")  # open again: the file keeps what was in force
    settings.sync()
    result = run_file(exported, "--speed", "20")
    assert result.returncode == 1
    assert result.stdout.splitlines()[0] == ("The teacher's limits apply: driving at most 0.1 m/s; switched off: "
                                             "Arm and gripper.")
    assert result.stderr.splitlines()[-1] == ("error in block arm (hobbit_arm_gripper): The robot could not do this: "
                                              "the teacher switched off “Arm and gripper” for this robot")


@pytest.mark.parametrize("language, expected", [
    ("en", "this program was made for the robot profile 'nobody' 1.0.0, which is not installed on this computer"),
    ("de", "dieses Programm wurde für das Roboterprofil 'nobody' 1.0.0 gemacht, das auf diesem Rechner nicht "
           "installiert ist"),
])
def test_a_program_for_a_profile_not_installed_says_so(exported, tmp_path, language, expected):
    other = tmp_path / "other.py"
    other.write_text(exported.read_text().replace("'id': 'hobbit'", "'id': 'nobody'"))
    result = run_file(other, "--language", language)
    assert result.returncode == 3 and result.stdout == ""
    assert result.stderr.startswith(f"drive.rockly: {expected} (") and "hobbit 1.0.0" in result.stderr


def test_a_program_for_another_version_of_the_profile_says_so_and_runs_only_when_asked(exported, tmp_path):
    other = tmp_path / "newer.py"
    other.write_text(exported.read_text().replace("'version': '1.0.0'", "'version': '2.0.0'"))
    refused = run_file(other)
    assert refused.returncode == 3 and refused.stdout == ""
    assert refused.stderr == ("drive.rockly: this program was made for the robot profile 'hobbit' 2.0.0, but this "
                              "computer has version 1.0.0; install 2.0.0 here, or run it anyway with "
                              "--any-profile-version\n")
    anyway = run_file(other, "--any-profile-version", "--speed", "20")
    assert anyway.returncode == 0, anyway.stderr
    assert "it runs anyway (--any-profile-version)" in anyway.stderr and anyway.stdout.splitlines()[-1] == "finished"


def test_an_events_path_that_cannot_be_written_is_said_before_the_robot_moves(exported, tmp_path):
    result = run_file(exported, "--events", tmp_path / "missing" / "events.jsonl", "--language", "de")
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.startswith(f"drive.rockly: die Ereignisse lassen sich nicht nach {tmp_path / 'missing'}")


@given(st.text(st.characters(codec=None, categories=None)))
def test_any_generated_code_survives_the_files_literal(code):
    """The file runs exactly the code the window would: quotes, backslashes, carriage returns, control
    characters and half an emoji included."""
    assert ast.literal_eval(text_literal(code)) == code


@given(st.dictionaries(st.text(), st.one_of(st.none(), st.floats(allow_nan=False, allow_infinity=False), st.text(),
                                            st.lists(st.text()), st.dictionaries(st.text(), st.text()))))
def test_any_program_data_survives_the_files_literal(data):
    assert ast.literal_eval(data_literal(data)) == data


def test_a_caller_in_its_own_process_gets_the_same_records_through_a_hook(exported):
    """What the robot's agent will do: load the file's program and run it with ``on_event``."""
    from rockly_desktop.runtime.standalone import main

    loaded = runpy.run_path(str(exported))
    records = []
    assert main(loaded["PROGRAM"], loaded["RUN_CODE"], ["--speed", "20"], on_event=records.append) == 0
    assert records[0]["event"] == "started" and records[-1] == {"event": "exit", "status": 0}
    assert [record["id"] for record in records if record["event"] == "block"] == ["drive", "where", "arm"]
