"""The ``rockly`` command, run as a user runs it (a real process)."""
import argparse
import json
import os
import shutil
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from program_builder import block, rockly_document, stack, text

REPO = Path(__file__).resolve().parents[1]


def rockly(*args, timeout=90):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, cwd=REPO)


def user_profiles(home: Path) -> Path:
    return home / "data" / "rockly" / "profiles"


def test_profiles_list_shows_hobbit():
    result = rockly("profiles", "list")
    assert result.returncode == 0, result.stderr
    assert result.stdout.split()[:4] == ["hobbit", "HOBBIT", "1.0.0", "built-in"]


def test_profiles_list_names_a_broken_profile_and_still_lists_the_others(isolated_user_folders):
    broken = user_profiles(isolated_user_folders) / "mybot"
    broken.mkdir(parents=True)
    (broken / "profile.yaml").write_text("schema: 1\nid: My Bot\n")
    result = rockly("profiles", "list")
    assert result.returncode == 1
    assert "hobbit" in result.stdout
    assert f"{broken / 'profile.yaml'}: id: must be lower-case letters" in result.stderr


def test_profiles_list_finds_a_profile_in_the_users_folder(isolated_user_folders):
    copy = user_profiles(isolated_user_folders) / "hobbit2"
    shutil.copytree(REPO / "profiles" / "hobbit", copy, ignore=shutil.ignore_patterns("__pycache__"))
    manifest = copy / "profile.yaml"
    manifest.write_text(manifest.read_text().replace("id: hobbit", "id: hobbit2"))
    result = rockly("profiles", "list")
    assert result.returncode == 0, result.stderr
    assert any(line.split()[:1] == ["hobbit2"] and line.split()[3] == "user" for line in result.stdout.splitlines())


def test_profiles_validate_accepts_hobbit():
    result = rockly("profiles", "validate", REPO / "profiles" / "hobbit")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("OK  hobbit 1.0.0: 26 blocks")


def test_profiles_validate_finds_a_template_calling_a_missing_command(tmp_path):
    copy = tmp_path / "hobbit"
    shutil.copytree(REPO / "profiles" / "hobbit", copy, ignore=shutil.ignore_patterns("__pycache__"))
    blocks = copy / "blocks.yaml"
    blocks.write_text(blocks.read_text().replace('python: "robot.call_sos()"', 'python: "robot.call_sos_now()"'))
    result = rockly("profiles", "validate", copy)
    assert result.returncode == 1
    assert "blocks[hobbit_sos].python.code: calls robot.call_sos_now(), which Hobbit does not have" in result.stderr


def test_profiles_validate_reports_a_profile_whose_code_does_not_import(tmp_path):
    copy = tmp_path / "hobbit"
    shutil.copytree(REPO / "profiles" / "hobbit", copy, ignore=shutil.ignore_patterns("__pycache__"))
    manifest = copy / "profile.yaml"
    manifest.write_text(manifest.read_text().replace("rockly_hobbit.api:Hobbit", "rockly_hobbit.api:Hobbot"))
    result = rockly("profiles", "validate", copy)
    assert result.returncode == 1
    assert "api: cannot import rockly_hobbit.api:Hobbot" in result.stderr


def test_profiles_validate_an_empty_folder(tmp_path):
    result = rockly("profiles", "validate", tmp_path)
    assert result.returncode == 1
    assert "profile.yaml is missing" in result.stderr


def test_export_writes_python_from_a_rockly_file(tmp_path):
    program = tmp_path / "hello.rockly"
    program.write_text(rockly_document([stack(block("hobbit_emo", {"emotion": "HAPPY"}),
                                              block("hobbit_show_info", inputs={"text": text("Hi 'you'\n")}))]))
    output = tmp_path / "hello.py"
    result = rockly("export", program, "-o", output)
    assert result.returncode == 0, result.stderr
    code = output.read_text()
    assert code.endswith("robot.show_emotion('HAPPY')\nrobot.show_info('Hi \\'you\\'\\n')\n")
    assert "for the robot profile 'hobbit'" in code


def test_export_reads_first_rockly_xml(tmp_path):
    program = tmp_path / "old.xml"
    program.write_text('<xml xmlns="https://developers.google.com/blockly/xml"><block type="hobbit_arm_gripper">'
                       '<field name="gripper_position">close</field></block></xml>')
    output = tmp_path / "old.py"
    result = rockly("export", program, "-o", output)
    assert result.returncode == 0, result.stderr
    assert output.read_text().endswith("robot.gripper('close')\n")


@pytest.mark.parametrize(("content", "message"), [
    ('{"format": "rockly-program", "version": 1, "prof', "broken JSON"),
    ('{"format": "rockly-program", "version": 7, "profile": "hobbit", "workspace": {}}', "newer Rockly"),
    (rockly_document([block("hobbit_fly")]), "hobbit_fly"),
    (rockly_document([block("math_number", {"NUM": 1})]).replace('1}', 'NaN}'), "NaN is not a number"),
    (rockly_document([block("math_number", {"NUM": 1})]).replace('1}', '1e400}'), "1e400 is too large"),
    (rockly_document([block("text_join", extraState={"itemCount": 100_000_000})]), "asks for 100,000,000"),
    (rockly_document([block("text", {"TEXT": ["a"]})]), "block 1 (text): its field TEXT holds list"),
])
def test_export_of_a_bad_program_fails_with_a_message_and_writes_nothing(tmp_path, content, message):
    program = tmp_path / "bad.rockly"
    program.write_text(content)
    output = tmp_path / "bad.py"
    result = rockly("export", program, "-o", output)
    assert result.returncode == 1
    assert result.stderr.startswith("rockly export: "), result.stderr
    assert message in result.stderr
    assert not output.exists()


PROGRAM_TEXT_END = "robot.show_emotion('HAPPY')\n"


def hello_program(tmp_path, emotion="HAPPY", profile="hobbit"):
    program = tmp_path / "hello.rockly"
    program.write_text(rockly_document([block("hobbit_emo", {"emotion": emotion})], profile=profile))
    return program


def test_export_to_dash_writes_the_python_to_standard_output_only(tmp_path):
    result = rockly("export", hello_program(tmp_path), "-o", "-")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("# Generated by Rockly") and result.stdout.endswith(PROGRAM_TEXT_END)
    assert "Wrote" not in result.stdout and result.stderr == ""
    assert sorted(path.name for path in tmp_path.iterdir()) == ["hello.rockly"]  # no file called "-"


def test_export_to_dev_stdout_streams_instead_of_replacing_it(tmp_path):
    result = rockly("export", hello_program(tmp_path), "-o", "/dev/stdout")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("# Generated by Rockly") and result.stdout.endswith(PROGRAM_TEXT_END)


def test_export_through_a_symlink_writes_its_target_and_keeps_the_link(tmp_path):
    target = tmp_path / "real" / "hello.py"
    target.parent.mkdir()
    target.write_text("old\n")
    link = tmp_path / "link.py"
    link.symlink_to(Path("real") / "hello.py")
    result = rockly("export", hello_program(tmp_path), "-o", link)
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and os.readlink(link) == str(Path("real") / "hello.py")
    assert target.read_text().endswith(PROGRAM_TEXT_END)


def test_export_into_a_fifo_writes_into_it(tmp_path):
    fifo = tmp_path / "python.fifo"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_text()), daemon=True)
    reader.start()
    result = rockly("export", hello_program(tmp_path), "-o", fifo)
    reader.join(10)
    assert result.returncode == 0, result.stderr
    assert received and received[0].endswith(PROGRAM_TEXT_END)
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)


def test_export_warns_about_a_value_its_block_does_not_offer(tmp_path):
    result = rockly("export", hello_program(tmp_path, emotion="FURIOUS"), "-o", "-")
    assert result.returncode == 0, result.stderr
    assert result.stderr == ("rockly export: warning: block 1 (hobbit_emo): emotion 'FURIOUS' is not a value this "
                             "block accepts; it was replaced by 'HAPPY'\n")
    assert result.stdout.endswith(PROGRAM_TEXT_END)


def test_export_warns_when_the_programs_profile_is_not_installed(tmp_path):
    result = rockly("export", hello_program(tmp_path, profile="pepper"), "-o", "-")
    assert result.returncode == 0, result.stderr
    assert "rockly export: warning: the program was made for the robot profile 'pepper', which is not installed" \
        in result.stderr
    assert "(installed: hobbit, turtlebot)" in result.stderr and "used with 'hobbit' instead" in result.stderr
    assert "for the robot profile 'hobbit'" in result.stdout


def test_export_of_a_block_without_a_type_calls_the_file_broken(tmp_path):
    program = tmp_path / "untyped.rockly"
    program.write_text(rockly_document([stack(block("hobbit_sos"), {"fields": {"emotion": "HAPPY"}})]))
    result = rockly("export", program, "-o", tmp_path / "out.py")
    assert result.returncode == 1
    assert result.stderr == f"rockly export: {program}: the file is broken: block 2 has no type\n"
    assert "undefined" not in result.stderr and not (tmp_path / "out.py").exists()


def test_export_of_a_missing_file(tmp_path):
    result = rockly("export", tmp_path / "nope.rockly", "-o", tmp_path / "x.py")
    assert result.returncode == 1 and "does not exist" in result.stderr


def test_usage_errors_exit_non_zero():
    assert rockly("export").returncode == 2
    assert rockly("profiles", "frobnicate").returncode == 2


def test_sim_help_documents_the_window_and_no_window():
    result = rockly("sim", "hobbit", "--ros", "--help")
    assert result.returncode == 0
    help_text = " ".join(result.stdout.split())
    assert "--no-window" in help_text and "--answer" in help_text
    assert "when they run out, the window asks" in help_text
    assert "tablet questions are then answered only from --answer" in help_text


def test_sim_without_a_display_says_to_use_no_window():
    env = {name: value for name, value in os.environ.items()
           if name not in ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM")}
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "sim", "hobbit", "--ros", "--master", "http://127.0.0.1:9"],
                            capture_output=True, text=True, timeout=90, cwd=REPO, env=env)
    assert result.returncode == 2 and "--no-window" in result.stderr


def test_the_older_plugins_verb_still_lists_the_profiles():
    result = rockly("plugins", "list")
    assert result.returncode == 0
    assert "hobbit" in result.stdout


def test_a_program_of_600_blocks_in_one_stack_exports_and_runs(tmp_path):
    blocks = [block("text_print", inputs={"TEXT": text(f"line {i}")}) for i in range(600)]
    source = tmp_path / "long.rockly"
    source.write_text(rockly_document([stack(*blocks)]), encoding="utf-8")

    exported = rockly("export", source, "-o", "-")
    ran = rockly("run", source)

    assert exported.returncode == 0, exported.stderr
    assert exported.stdout.count("print(") == 600
    assert ran.returncode == 0, ran.stderr
    assert "print   line 599" in ran.stdout


def test_half_an_emoji_in_a_comment_exports_to_standard_output(tmp_path):
    commented = block("hobbit_stop", icons={"comment": {"text": "half \ud83d an emoji", "pinned": False}})
    source = tmp_path / "comment.rockly"
    source.write_text(rockly_document([commented]), encoding="utf-8")

    result = rockly("export", source, "-o", "-")

    assert result.returncode == 0, result.stderr
    assert "half \ufffd an emoji" in result.stdout


@pytest.mark.parametrize("name", ["robot", "ros", "__rockly__"])
def test_a_variable_named_like_what_a_run_binds_does_not_break_the_program(tmp_path, name):
    document = json.loads(rockly_document([stack(
        block("variables_set", {"VAR": {"id": "v1"}}, inputs={"VALUE": block("math_number", {"NUM": 5})}),
        block("hobbit_emo", {"emotion": "HAPPY"}),
        block("ros_wait", inputs={"seconds": block("math_number", {"NUM": 0})}),
        block("text_print", inputs={"TEXT": block("variables_get", {"VAR": {"id": "v1"}})}),
    )]))
    document["workspace"]["variables"] = [{"name": name, "id": "v1"}]
    source = tmp_path / "names.rockly"
    source.write_text(json.dumps(document), encoding="utf-8")

    result = rockly("run", source)

    assert result.returncode == 0, result.stderr
    assert "print   5" in result.stdout


def test_a_whole_number_too_large_to_keep_exactly_is_warned_about(tmp_path):
    source = tmp_path / "big-number.rockly"
    source.write_text(rockly_document([block("text_print", inputs={"TEXT": block("math_number", {"NUM": 1})})])
                      .replace('"NUM": 1', '"NUM": 12345678901234567890'), encoding="utf-8")

    result = rockly("run", source)

    assert result.returncode == 0, result.stderr
    assert ("warning: block 2 (math_number): NUM 12345678901234567890 is too large to keep exactly; "
            "it became 12345678901234567000") in result.stderr


def test_a_power_too_large_to_compute_ends_the_run_with_a_plain_error(tmp_path):
    power = block("math_arithmetic", {"OP": "POWER"}, inputs={"A": block("math_number", {"NUM": 9}),
                                                              "B": block("math_number", {"NUM": 999999999})})
    source = tmp_path / "power.rockly"
    source.write_text(rockly_document([block("text_print", inputs={"TEXT": power})]), encoding="utf-8")

    ran = rockly("run", source, timeout=60)
    exported = rockly("export", source, "-o", "-")

    assert ran.returncode == 1
    assert "The number is too big." in ran.stderr
    assert "print(9 ** 999999999)" in exported.stdout  # exported Python keeps the plain operator


def test_a_program_of_thousands_of_blocks_gets_the_time_it_needs_to_load(tmp_path):
    prints = [block("text_print", inputs={"TEXT": text(f"line {i}")}, x=0, y=40 * i) for i in range(6000)]
    source = tmp_path / "many.rockly"
    source.write_text(rockly_document(prints), encoding="utf-8")

    result = rockly("export", source, "-o", "-", timeout=110)

    assert result.returncode == 0, result.stderr
    assert result.stdout.count("print(") == 6000


def test_help_names_every_command_with_a_line_of_its_own():
    from rockly_desktop.cli import SUBCOMMANDS, _tool_parser

    commands = next(action for action in _tool_parser()._actions if isinstance(action, argparse._SubParsersAction))
    assert set(commands.choices) == set(SUBCOMMANDS)  # main() hands every registered command to the tools
    result = rockly("--help")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    for choice in commands._choices_actions:  # one per command; its aliases are named in its own line
        name = choice.dest.split()[0]
        assert any(line.split()[:2] == ["rockly", name] for line in lines), f"rockly --help does not name {name}"
    assert "older name: plugins" in result.stdout
