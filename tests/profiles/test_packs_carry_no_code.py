"""A block pack is data: a shared zip cannot run Python of its own, redefine Blockly's blocks, crash
the importer with deep YAML, or hide a second copy of a file; real ``rockly`` processes on real files
in the test's own data folder (issue 30, "Packs and files carry no code")."""
import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from rockly_desktop.profiles.packs.template_check import TemplateRefused, check_template

REPO = Path(__file__).resolve().parents[2]
PACK_YAML = ("schema: 1\nid: {id}\nname: Extras\nversion: 1.0.0\nadds_to: hobbit\nblocks: blocks.yaml\n"
             "toolbox: toolbox.yaml\n")
TOOLBOX_YAML = "categories:\n  - name: Extras\n    colour: '#4c97ff'\n    blocks:\n{contents}"


def rockly(*args, env=None, timeout=240):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)], capture_output=True,
                          text=True, timeout=timeout, cwd=REPO, env=env or dict(os.environ))


def packs_folder(env) -> Path:
    return Path(env["XDG_DATA_HOME"]) / "rockly" / "packs"


@pytest.fixture
def env(tmp_path):
    """Settings and data folders of the test's own (no pack installed)."""
    return {**os.environ, "XDG_DATA_HOME": str(tmp_path / "data"), "XDG_CONFIG_HOME": str(tmp_path / "config"),
            "XDG_CACHE_HOME": str(tmp_path / "cache")}


def blocks_yaml(blocks: dict) -> str:
    """A blocks.yaml of ``{type: python code}`` statement blocks."""
    entries = "".join(f"  - type: {block_type}\n    message0: 'do it'\n    previousStatement: null\n"
                      f"    nextStatement: null\n    python: {code!r}\n" for block_type, code in blocks.items())
    return "blocks:\n" + entries


def pack_files(blocks: dict, pack_id="extras") -> dict:
    contents = "".join(f"      - type: {block_type}\n" for block_type in blocks)
    return {"pack.yaml": PACK_YAML.format(id=pack_id), "blocks.yaml": blocks_yaml(blocks),
            "toolbox.yaml": TOOLBOX_YAML.format(contents=contents)}


def zipped(path: Path, files: dict, pack_id="extras", extra=()) -> Path:
    with zipfile.ZipFile(path, "w") as archive:
        for name, text in files.items():
            archive.writestr(f"{pack_id}/{name}", text)
        for name, text in extra:
            archive.writestr(f"{pack_id}/{name}", text)
    return path


def test_a_pack_whose_template_runs_python_is_refused_on_import_with_its_line(tmp_path, env):
    marker = tmp_path / "ran"
    hostile = zipped(tmp_path / "extras.zip",
                     pack_files({"extras_go": f"__import__('os').system('touch {marker}')"}))
    result = rockly("blocks", "import", hostile, "--language", "en", env=env)
    assert result.returncode == 1
    assert "blocks.yaml: blocks[0].python.code: line 1" in result.stderr
    assert "may only call robot." in result.stderr
    assert not marker.exists()
    assert not (packs_folder(env) / "extras").exists()
    assert not list(packs_folder(env).glob(".import-*"))  # a failed import leaves nothing behind


@pytest.mark.parametrize("block_type", ["math_number", "controls_repeat_ext", "text_print", "logic_boolean",
                                        "procedures_defnoreturn", "variables_set"])
def test_a_pack_may_not_define_one_of_blocklys_own_blocks(tmp_path, env, block_type):
    hostile = zipped(tmp_path / "extras.zip", pack_files({block_type: "ros.wait(0)"}))
    result = rockly("blocks", "import", hostile, "--language", "en", env=env)
    assert result.returncode == 1
    assert f"'{block_type}' is one of Blockly's own block types" in result.stderr
    assert not (packs_folder(env) / "extras").exists()


def test_a_pack_may_not_define_a_block_of_its_profile(tmp_path, env):
    hostile = zipped(tmp_path / "extras.zip", pack_files({"hobbit_move": "ros.wait(0)"}))
    result = rockly("blocks", "import", hostile, "--language", "en", env=env)
    assert result.returncode == 1 and "hobbit_move" in result.stderr
    assert not (packs_folder(env) / "extras").exists()


def test_a_hostile_pack_put_in_the_folder_by_hand_is_skipped_and_the_example_runs_its_own_loop(tmp_path, env):
    """The unchanged drive-a-square example, with a pack in the packs folder (bypassing the import) that
    redefines its loop block with code of its own: the pack is refused, the example's own loop runs."""
    marker = tmp_path / "ran"
    code = f"__import__('pathlib').Path({str(marker)!r}).write_text('pack code ran')"
    folder = packs_folder(env) / "extras"
    folder.mkdir(parents=True)
    for name, text in pack_files({"controls_repeat_ext": code, "extras_go": code}).items():
        (folder / name).write_text(text)
    result = rockly("run", REPO / "examples" / "hobbit" / "drive-a-square.rockly", "--speed", "25",
                    "--answer", "Mia", "--answer", "yes", env=env)
    assert result.returncode == 0, result.stderr[-2000:]
    assert not marker.exists()  # the pack's loop would have written it instead of driving the square
    assert result.stdout.splitlines()[-1] == "finished"


def test_deep_yaml_in_a_pack_is_refused_without_a_crash_and_leaves_nothing(tmp_path, env):
    files = pack_files({"extras_go": "ros.wait(0)"})
    files["blocks.yaml"] = "blocks: " + "[" * 100_000 + "]" * 100_000 + "\n"
    deep = zipped(tmp_path / "extras.zip", files)
    result = rockly("blocks", "import", deep, "--language", "en", env=env)
    assert result.returncode == 1, (result.returncode, result.stderr[-500:])  # -11 was a segfault
    assert "nests up to 100001 levels deep" in result.stderr
    assert not (packs_folder(env) / "extras").exists()
    assert not list(packs_folder(env).glob(".import-*"))


def test_a_zip_with_one_name_twice_is_refused(tmp_path, env):
    files = pack_files({"extras_go": "ros.wait(0)"})
    twice = zipped(tmp_path / "extras.zip", files,
                   extra=[("blocks.yaml", blocks_yaml({"extras_go": "__import__('os').getcwd()"}))])
    with pytest.warns(UserWarning):  # zipfile itself warns about a duplicate name when writing it
        zipped(tmp_path / "check.zip", files, extra=[("pack.yaml", files["pack.yaml"])])
    result = rockly("blocks", "import", twice, "--language", "en", env=env)
    assert result.returncode == 1
    assert "blocks.yaml twice" in result.stderr
    assert not (packs_folder(env) / "extras").exists()


@pytest.mark.parametrize("template", [
    "__import__('os').system('x')",
    "robot.backend.publish('/cmd_vel', {})",
    "robot.backend._inner.publish('/cmd_vel', {})",
    "import os",
    "x = ros.latest('/odom', 'pose')",
    "ros.wait(open('/etc/hostname').read())",
    "ros.publish_message('/a', 'std_msgs/String', {{'data': [c for c in 'ab']}})",
    "ros.wait((lambda: 0)())",
    "robot._commands()",
    "robot.__class__()",
    "ros.wait(*[1])",
    "ros.publish_message('/a', 'std_msgs/String', {{**{{}}}})",
    "print('hi')",
    "ros.wait(0)\ndef f():\n  pass",
    "while ros.latest('/odom', 'x') < 1:\n  ros.wait(0.1)\nelse:\n  exec('1')",
    "ros.latest('/odom', 'x')[0]",
])
def test_a_template_that_does_more_than_call_rocklys_commands_is_refused(template):
    with pytest.raises(TemplateRefused):
        check_template(template)


@pytest.mark.parametrize("template, slots, handlers", [
    ("robot.drive({speed}, {direction})", {"speed": "value", "direction": "field"}, {}),
    ("ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {{'linear': {{'x': ros.number_in({speed}, 0, 0.3, "
     "'speed')}}}})", {"speed": "value"}, {}),
    ("ros.field(ros.call_service('/MMUI', 'hobbit_msgs/Request', {{}}), 'result')", {}, {}),
    ("ros.send_goal('hobbit_arm', 'hobbit_msgs/ArmServerAction', {{}}, while_waiting={while_waiting})",
     {"while_waiting": "statement"}, {"while_waiting": "feedback"}),
    ("while not ros.latest('/odom', 'pose.pose.position.x') > {metres}:\n  ros.wait(0.1)", {"metres": "value"}, {}),
    ("while True:\n{do}", {"do": "statement"}, {}),
    ("ros.publish('/x', 'std_msgs/Float64', {fields})", {"fields": "typed_fields"}, {}),
    ("ros.set_param('/made/level', -1)", {}, {}),
])
def test_the_templates_rockly_makes_pass(template, slots, handlers):
    check_template(template, slots, handlers)
