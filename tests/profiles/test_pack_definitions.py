"""A block pack carries the definitions of the types its blocks use that Rockly knew only because the robot
said them: written with the block (all or nothing), known again after a restart (the catalogue, ROS 1's
classes with the robot's md5sum), carried by export and import; a broken definition file names itself."""
import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

from rockly_desktop.core import ros_definitions
from rockly_desktop.profiles.packs.archive import export_pack, import_pack
from rockly_desktop.profiles.packs.making import save_block
from rockly_desktop.profiles.packs.pack import user_packs_dir
from rockly_desktop.profiles.packs.spec import BlockInput, MadeBlock
from rockly_desktop.profiles.packs.validation import BlockMakerError
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.robot.ros1.message_classes import MessageTypes

REPO = Path(__file__).resolve().parents[2]
GADGET_NODE = REPO / "tests" / "robot" / "ros1" / "ros1_gadget_node.py"
GADGET = "rockly_test_custom/Gadget"
PACK = "gadget_pack"


def gadget_node():
    spec = importlib.util.spec_from_file_location("ros1_gadget_node", GADGET_NODE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture
def learnt(monkeypatch):
    """The gadget's type learnt as the maker learns it from the node's publisher (its full text, split)."""
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})
    classes = gadget_node().gadget_classes()
    texts = ros_definitions.split_full_text(GADGET, classes[GADGET]._full_text)
    ros_definitions.learn_definition(GADGET, "msg", texts.pop(GADGET), texts)
    return classes


def show_block(**changes):
    values = dict(id="gadget_show", kind="publish", interface="/gadget/state", interface_type=GADGET,
                  inputs=(BlockInput("name", "text", "name"),), fixed={"left_eye.brightness": 0.5},
                  sentence={"en": "show %1"}, category={"en": "Gadget"}, colour="#4c97ff")
    return MadeBlock(**{**values, **changes})


def forget_learnt(monkeypatch):
    """As after a restart: nothing learnt from a robot in this process."""
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})


def test_a_block_of_a_learnt_type_carries_its_definitions_and_after_a_restart_its_profile_knows_them(
        learnt, monkeypatch, tmp_path):
    pack = save_block(show_block(), ProfileRegistry.discover().get("hobbit"), PACK)
    folder = pack.root / "messages" / "rockly_test_custom" / "msg"
    assert sorted(path.name for path in folder.iterdir()) == ["Eye.msg", "Gadget.msg"]
    assert pack.manifest["messages"] == "messages" and not (pack.root / "messages" / "std_msgs").exists()

    forget_learnt(monkeypatch)
    profile = ProfileRegistry.discover().get("hobbit")
    assert profile.ros_types.knows(GADGET) and GADGET in profile.ros_types.type_names("msg")
    assert [entry.path for entry in profile.ros_types.fields(GADGET)] == [
        "header.stamp", "header.frame_id", "name", "left_eye.brightness", "left_eye.open", "levels"]
    made = MessageTypes(profile.message_folders, cache_dir=tmp_path / "cache").message_class(GADGET)
    assert made._md5sum == learnt[GADGET]._md5sum  # what the robot's own class says on the wire

    # after the restart: another block of that type needs no robot, and a new learnt type of the same
    # package joins the pack's folder beside the others
    ros_definitions.learn_definition("rockly_test_custom/Lamp", "msg", "bool on\n")
    save_block(show_block(id="gadget_eye", kind="sensor_value", inputs=(), fixed={}, read_field="left_eye.open",
                          value_kind="yes_no", sentence={"en": "the gadget's eye is open"}), profile, PACK)
    pack = save_block(show_block(id="lamp_on", interface="/lamp", interface_type="rockly_test_custom/Lamp", fixed={},
                                 inputs=(BlockInput("on", "yes_no", "on"),), sentence={"en": "lamp %1"}),
                      ProfileRegistry.discover().get("hobbit"), PACK)
    assert sorted(path.name for path in folder.iterdir()) == ["Eye.msg", "Gadget.msg", "Lamp.msg"]
    assert pack.block_types == {"gadget_show", "gadget_eye", "lamp_on"}


def test_a_learnt_definition_that_cannot_be_read_is_not_written_and_the_pack_stays_as_it_was(learnt):
    pack = save_block(show_block(), ProfileRegistry.discover().get("hobbit"), PACK)
    before = {str(path.relative_to(pack.root)): path.read_bytes() for path in pack.root.rglob("*") if path.is_file()}
    ros_definitions.learn_definition("rockly_test_custom/Garbled", "msg", "float64 level\nbool\n")
    with pytest.raises(BlockMakerError, match="Garbled.msg: line 2"):
        save_block(show_block(id="garbled", interface="/garbled", interface_type="rockly_test_custom/Garbled",
                              inputs=(BlockInput("level", "number", "level"),), fixed={}, sentence={"en": "level %1"}),
                   ProfileRegistry.discover().get("hobbit"), PACK)
    after = {str(path.relative_to(pack.root)): path.read_bytes() for path in pack.root.rglob("*") if path.is_file()}
    assert after == before and [path.name for path in user_packs_dir().iterdir()] == [PACK]


def test_export_and_import_carry_the_definitions_to_a_clean_data_folder(learnt, monkeypatch, tmp_path):
    pack = save_block(show_block(), ProfileRegistry.discover().get("hobbit"), PACK)
    archive = export_pack(pack, tmp_path / "gadget.zip")
    forget_learnt(monkeypatch)
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "clean"))
    imported = import_pack(archive, ProfileRegistry.discover().base_profiles)
    assert (imported.root / "messages" / "rockly_test_custom" / "msg" / "Eye.msg").is_file()
    assert ProfileRegistry.discover().get("hobbit").ros_types.knows(GADGET)


def test_a_broken_definition_file_names_itself_costs_only_its_pack_and_is_kept(learnt, monkeypatch, tmp_path):
    pack = save_block(show_block(), ProfileRegistry.discover().get("hobbit"), PACK)
    archive = export_pack(pack, tmp_path / "intact.zip")
    broken = pack.root / "messages" / "rockly_test_custom" / "msg" / "Eye.msg"
    broken.write_text("float64 brightness\nbool\n")
    forget_learnt(monkeypatch)
    registry = ProfileRegistry.discover()
    assert PACK not in registry.packs and "hobbit" in registry.profiles
    assert [f"{broken}: line 2" in str(error) for error in registry.pack_errors] == [True]
    validated = subprocess.run([sys.executable, "-m", "rockly_desktop", "profiles", "validate", str(pack.root)],
                               capture_output=True, text=True, timeout=120, cwd=REPO)
    assert validated.returncode == 1 and f"INVALID  {broken}: line 2" in validated.stderr
    assert broken.read_text() == "float64 brightness\nbool\n"  # nothing of it is lost

    broken_zip = export_pack(pack, tmp_path / "broken.zip")
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "clean"))
    with pytest.raises(BlockMakerError, match="messages/rockly_test_custom/msg/Eye.msg: line 2"):
        import_pack(broken_zip, registry.base_profiles)
    assert not (user_packs_dir() / PACK).exists()  # nothing written half
    import_pack(archive, registry.base_profiles)  # the intact one goes in
