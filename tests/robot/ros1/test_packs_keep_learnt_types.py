"""A block pack made from a type Rockly knew only because the robot said it carries that type's definition:
made by ``rockly blocks make`` from a plain rospy node whose type is generated at run time, the pack holds
the definition files and validates; a new ``rockly run`` with nothing publishing the type (a command topic
that only has a subscriber) publishes what the node decodes with its own class, and so does one on a clean
data folder after export and import. A broken definition file names itself and costs only its own pack."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from json_line_node import JsonLineNode
from program_builder import block, rockly_document, stack, text
from ros_helpers import ros_environment
from waiting import eventually

from rockly_desktop.profiles.packs.pack import discover_packs

REPO = Path(__file__).resolve().parents[3]
GADGET_NODE = Path(__file__).parent / "ros1_gadget_node.py"
GADGET = "rockly_test_custom/Gadget"
PACK = "gadget_made"


def rockly(master, *args, data_home=None):
    env = ros_environment(master.uri, master.home / "rockly")
    if data_home is not None:
        env["XDG_DATA_HOME"] = str(data_home)
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)], capture_output=True, text=True,
                          timeout=180, cwd=REPO, env=env)


def gadget_node(master, *args):
    return JsonLineNode([sys.executable, GADGET_NODE, *args], ros_environment(master.uri, master.home / "gadget"),
                        "the gadget node")


def make_show_block(master, *robot):
    return rockly(master, "blocks", "make", "--profile", "hobbit", "--pack", PACK, "--id", "gadget_show",
                  "--kind", "publish", "--interface", "/gadget/state", "--type", GADGET, "--input", "name=name",
                  "--fixed", "left_eye.brightness=0.5", "--sentence-en", "show %1 on the gadget",
                  "--colour", "#4c97ff", "--category-en", "Gadget", "--language", "en", *robot)


@pytest.fixture
def made_pack(ros_master):
    """The pack, made while the gadget node published its type; the node is gone afterwards."""
    publisher = gadget_node(ros_master)
    try:
        result = make_show_block(ros_master, "--backend", "ros1", "--master", ros_master.uri)
    finally:
        publisher.stop()
    assert result.returncode == 0, result.stderr
    return Path(os.environ["XDG_DATA_HOME"]) / "rockly" / "packs" / PACK


def shown_on_the_gadget(master, program, name, data_home=None):
    """Run ``program`` in a new process while only the node's listener is on /gadget/state; what it heard."""
    listener = gadget_node(master, "listen")
    try:
        result = rockly(master, "run", program, "--backend", "ros1", "--master", master.uri, data_home=data_home)
        assert result.returncode == 0, result.stderr
        eventually(lambda: any(line["heard"]["name"] == name for line in listener.lines), timeout=15)
        return next(line["heard"] for line in listener.lines if line["heard"]["name"] == name)
    finally:
        listener.stop()


def test_a_pack_made_from_a_learnt_type_works_in_a_new_process_without_its_publisher_and_after_export_and_import(
        ros_master, made_pack, tmp_path):
    definitions = made_pack / "messages" / "rockly_test_custom" / "msg"
    assert sorted(path.name for path in definitions.iterdir()) == ["Eye.msg", "Gadget.msg"]
    assert "rockly_test_custom/Eye left_eye" in (definitions / "Gadget.msg").read_text()
    assert not (made_pack / "messages" / "std_msgs").exists()  # installed here: not carried
    validated = rockly(ros_master, "profiles", "validate", made_pack)
    assert validated.returncode == 0 and "OK  block pack gadget_made" in validated.stdout, validated.stderr

    program = tmp_path / "gadget.rockly"
    program.write_text(rockly_document([stack(block("gadget_show", inputs={"name": text("after a restart")}))]))
    heard = shown_on_the_gadget(ros_master, program, "after a restart")
    assert heard["brightness"] == 0.5  # decoded by the node's own class: same md5sum, same layout

    archive = tmp_path / "gadget.zip"
    assert rockly(ros_master, "blocks", "export", PACK, "-o", archive).returncode == 0
    clean = tmp_path / "clean-data"
    imported = rockly(ros_master, "blocks", "import", archive, data_home=clean)
    assert imported.returncode == 0, imported.stderr
    assert (clean / "rockly" / "packs" / PACK / "messages" / "rockly_test_custom" / "msg" / "Gadget.msg").is_file()
    program.write_text(rockly_document([stack(block("gadget_show", inputs={"name": text("on another laptop")}))]))
    assert shown_on_the_gadget(ros_master, program, "on another laptop", data_home=clean)["brightness"] == 0.5


def test_a_type_rockly_does_not_know_without_a_robot_to_ask_is_a_clear_message_and_writes_nothing(ros_master):
    result = make_show_block(ros_master)
    assert result.returncode == 1
    assert f"Rockly does not know the type '{GADGET}'" in result.stderr and "--backend ros1" in result.stderr
    assert not (Path(os.environ["XDG_DATA_HOME"]) / "rockly" / "packs" / PACK).exists()


def test_a_broken_definition_file_in_a_pack_names_itself_and_costs_nothing_else(ros_master, made_pack, tmp_path):
    other = tmp_path / "packs"
    shutil.copytree(made_pack, other / PACK)
    broken = other / PACK / "messages" / "rockly_test_custom" / "msg" / "Eye.msg"
    broken.write_text("float64 brightness\nbool\n")
    packs, errors = discover_packs(other)
    assert not packs and len(errors) == 1
    assert str(broken) in str(errors[0]) and "line 2" in str(errors[0])
    validated = rockly(ros_master, "profiles", "validate", other / PACK)
    assert validated.returncode == 1 and str(broken) in validated.stderr
    assert broken.read_text() == "float64 brightness\nbool\n"  # nothing of it is lost
    assert set(discover_packs(made_pack.parent)[0]) == {PACK}  # the intact copy still loads
