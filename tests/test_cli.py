"""The ``rockly`` command, run as a user runs it (a real process)."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from program_builder import block, rockly_document, stack, text

REPO = Path(__file__).resolve().parents[1]


def rockly(*args, timeout=90):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, cwd=REPO)


def user_profiles(home: Path) -> Path:
    return home / "data" / "rockly" / "profiles"


def test_plugins_list_shows_hobbit():
    result = rockly("plugins", "list")
    assert result.returncode == 0, result.stderr
    assert result.stdout.split()[:4] == ["hobbit", "HOBBIT", "1.0.0", "built-in"]


def test_plugins_list_names_a_broken_profile_and_still_lists_the_others(isolated_user_folders):
    broken = user_profiles(isolated_user_folders) / "mybot"
    broken.mkdir(parents=True)
    (broken / "profile.yaml").write_text("schema: 1\nid: My Bot\n")
    result = rockly("plugins", "list")
    assert result.returncode == 1
    assert "hobbit" in result.stdout
    assert f"{broken / 'profile.yaml'}: id: must be lower-case letters" in result.stderr


def test_plugins_list_finds_a_profile_in_the_users_folder(isolated_user_folders):
    copy = user_profiles(isolated_user_folders) / "hobbit2"
    shutil.copytree(REPO / "plugins" / "hobbit", copy, ignore=shutil.ignore_patterns("__pycache__"))
    manifest = copy / "profile.yaml"
    manifest.write_text(manifest.read_text().replace("id: hobbit", "id: hobbit2"))
    result = rockly("plugins", "list")
    assert result.returncode == 0, result.stderr
    assert any(line.split()[:1] == ["hobbit2"] and line.split()[3] == "user" for line in result.stdout.splitlines())


def test_plugins_validate_accepts_hobbit():
    result = rockly("plugins", "validate", REPO / "plugins" / "hobbit")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("OK  hobbit 1.0.0: 26 blocks")


def test_plugins_validate_finds_a_template_calling_a_missing_command(tmp_path):
    copy = tmp_path / "hobbit"
    shutil.copytree(REPO / "plugins" / "hobbit", copy, ignore=shutil.ignore_patterns("__pycache__"))
    blocks = copy / "blocks.yaml"
    blocks.write_text(blocks.read_text().replace('python: "robot.call_sos()"', 'python: "robot.call_sos_now()"'))
    result = rockly("plugins", "validate", copy)
    assert result.returncode == 1
    assert "blocks[hobbit_sos].python.code: calls robot.call_sos_now(), which Hobbit does not have" in result.stderr


def test_plugins_validate_reports_a_profile_whose_code_does_not_import(tmp_path):
    copy = tmp_path / "hobbit"
    shutil.copytree(REPO / "plugins" / "hobbit", copy, ignore=shutil.ignore_patterns("__pycache__"))
    manifest = copy / "profile.yaml"
    manifest.write_text(manifest.read_text().replace("rockly_hobbit.api:Hobbit", "rockly_hobbit.api:Hobbot"))
    result = rockly("plugins", "validate", copy)
    assert result.returncode == 1
    assert "api: cannot import rockly_hobbit.api:Hobbot" in result.stderr


def test_plugins_validate_an_empty_folder(tmp_path):
    result = rockly("plugins", "validate", tmp_path)
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


def test_export_of_a_missing_file(tmp_path):
    result = rockly("export", tmp_path / "nope.rockly", "-o", tmp_path / "x.py")
    assert result.returncode == 1 and "does not exist" in result.stderr


def test_usage_errors_exit_non_zero():
    assert rockly("export").returncode == 2
    assert rockly("plugins", "frobnicate").returncode == 2


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
