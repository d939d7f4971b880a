"""A block pack made from a type Rockly knew only because the robot said it carries that type's definition:
made by ``rockly blocks make`` from a plain rospy node whose type is generated at run time, the pack holds
the definition files and validates; a new ``rockly run`` with nothing publishing the type (a command topic
that only has a subscriber) publishes what the node decodes with its own class, and so does one on a clean
data folder after export and import."""
import os
import subprocess
import sys
from pathlib import Path

import pytest
from json_line_node import JsonLineNode
from program_builder import block, rockly_document, stack, text
from ros_helpers import ros_environment
from waiting import eventually

from rockly_desktop.core import ros_definitions
from rockly_desktop.profiles.packs.making import save_block
from rockly_desktop.profiles.packs.spec import BlockInput, MadeBlock
from rockly_desktop.robot.ros1.live_definitions import topic_definition

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

    more = rockly(ros_master, "blocks", "make", "--profile", "hobbit", "--pack", PACK, "--id", "gadget_name",
                  "--kind", "sensor_value", "--interface", "/gadget/state", "--type", GADGET, "--read-field", "name",
                  "--value-kind", "text", "--sentence-en", "the gadget's name", "--colour", "#4c97ff",
                  "--category-en", "Gadget")  # no robot: the pack's own definitions say the fields
    assert more.returncode == 0, more.stderr

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


def test_a_block_the_maker_saves_from_a_type_it_learnt_carries_the_type_into_a_new_run(
        ros_master, registry, tmp_path, monkeypatch):
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})
    publisher = gadget_node(ros_master)
    try:
        learnt = topic_definition(ros_master.uri, "/gadget/state")  # what the maker's learning asks
    finally:
        publisher.stop()
    ros_definitions.learn_definition(GADGET, "msg", learnt.text, learnt.nested)  # and learns
    made = MadeBlock(id="gadget_named", kind="publish", interface="/gadget/state", interface_type=GADGET,
                     inputs=(BlockInput("name", "text", "name"),), fixed={"left_eye.open": True},
                     sentence={"en": "name the gadget %1"}, category={"en": "Gadget"}, colour="#4c97ff")
    pack = save_block(made, registry.get("hobbit"), PACK)  # as the maker's dialog saves
    program = tmp_path / "named.rockly"
    program.write_text(rockly_document([stack(block("gadget_named", inputs={"name": text("saved by the maker")}))]))
    assert shown_on_the_gadget(ros_master, program, "saved by the maker")["brightness"] == 0.0
    assert (pack.root / "messages" / "rockly_test_custom" / "msg" / "Gadget.msg").is_file()


def test_a_type_rockly_does_not_know_without_a_robot_to_ask_is_a_clear_message_and_writes_nothing(ros_master):
    result = make_show_block(ros_master)
    assert result.returncode == 1
    assert f"Rockly does not know the type '{GADGET}'" in result.stderr and "--backend ros1" in result.stderr
    assert not (Path(os.environ["XDG_DATA_HOME"]) / "rockly" / "packs" / PACK).exists()


def test_making_a_block_from_the_robot_puts_nothing_on_cmd_vel_while_a_runs_end_still_stops_it(ros_master, tmp_path):
    """Learning a type for ``rockly blocks make`` only reads the robot: it must not stop a program another
    client runs (HOBBIT's safe stop is a zero /cmd_vel); a run's end, heard by the same plain node, still does."""
    from wire_recorder import WireRecorder

    recorder = WireRecorder(ros_master, ["/cmd_vel"])
    publisher = gadget_node(ros_master)
    try:
        made = rockly(ros_master, "blocks", "make", "--profile", "hobbit", "--pack", "gadget_quiet", "--id",
                      "gadget_quiet_show", "--kind", "publish", "--interface", "/gadget/state", "--type", GADGET,
                      "--input", "name=name", "--sentence-en", "show %1 on the gadget", "--colour", "#4c97ff",
                      "--category-en", "Gadget", "--backend", "ros1", "--master", ros_master.uri,
                      data_home=tmp_path / "data")
        assert made.returncode == 0, made.stderr
        heard_while_making = len(recorder.on("/cmd_vel"))
        program = tmp_path / "nothing.rockly"
        program.write_text(rockly_document([stack(block("text_print", inputs={"TEXT": text("done")}))]))
        ran = rockly(ros_master, "run", program, "--backend", "ros1", "--master", ros_master.uri)
        assert ran.returncode == 0, ran.stderr
        eventually(lambda: recorder.on("/cmd_vel"), timeout=15)  # the run's end: its safe stop
        assert heard_while_making == 0
    finally:
        publisher.stop()
        recorder.stop()
