"""Block packs as files: made blocks written all-or-nothing, merged into their profile (reloaded
without a restart), shown in the reader's language on the real editor page, zips checked on import,
and the fields of the types Rockly knows."""
import ast
import os
import tempfile
import zipfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from page_tools import run_js, toolbox_names
from program_builder import block, number, workspace

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.core.program import Program, parse_program
from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.profiles.blocks import block_spec
from rockly_desktop.profiles.opening import ProgramToOpen, opening_warnings, read_program_to_open, unknown_blocks_error
from rockly_desktop.profiles.packs import making
from rockly_desktop.profiles.packs.archive import export_pack, import_pack
from rockly_desktop.profiles.packs.choices import category_choices, preview_block
from rockly_desktop.profiles.packs.generate import block_definition, python_preview
from rockly_desktop.profiles.packs.interfaces import field_tree, interface_fields, known_types
from rockly_desktop.profiles.packs.making import save_block
from rockly_desktop.profiles.packs.pack import load_pack
from rockly_desktop.profiles.packs.spec import BlockInput, MadeBlock
from rockly_desktop.profiles.packs.validation import BlockMakerError, block_problems
from rockly_desktop.profiles.registry import ProfileRegistry

PACK = "hobbit_more"


def drive_block(**changes):
    values = dict(id="drive_at", kind="publish", interface="/cmd_vel", interface_type="geometry_msgs/Twist",
                  inputs=(BlockInput("speed", "number", "linear.x", "m/s", 0.1, 0, 0.3),), fixed={"angular.z": 0.0},
                  sentence={"en": "drive at %1", "de": "fahre mit %1"}, category={"en": "Made", "de": "Gemacht"},
                  colour="#4c97ff", tooltip={"en": "Drives straight on."})
    return MadeBlock(**{**values, **changes})


def arm_block(**changes):
    values = dict(id="arm_to", kind="send_goal", interface="hobbit_arm", interface_type="hobbit_msgs/ArmServerAction",
                  inputs=(BlockInput("movement", "text", "command.data", default="OpenGripper"),), result="outcome",
                  while_waiting=True, sentence={"de": "Ergebnis der Armbewegung zu %1"}, category={"en": "Arm"},
                  colour="#9966ff")
    return MadeBlock(**{**values, **changes})


def tree(folder: Path) -> dict:
    return {str(path.relative_to(folder)): path.read_bytes() for path in sorted(folder.rglob("*")) if path.is_file()}


@pytest.fixture
def fresh_registry():
    return ProfileRegistry.discover()


def test_a_saved_block_joins_the_toolbox_after_reload_without_touching_the_profile(fresh_registry):
    assert "drive_at" not in fresh_registry.get("hobbit").block_types
    save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    save_block(arm_block(), fresh_registry.get("hobbit"), PACK)
    fresh_registry.reload_packs()
    hobbit = fresh_registry.get("hobbit")
    assert {"drive_at", "arm_to"} <= hobbit.block_types and hobbit.pack_of("arm_to") == PACK
    categories = hobbit.toolbox("en")["contents"]
    names = [category["name"] for category in categories]
    assert names.index("Made") < names.index("ROS")  # after the profile's own, before the shared ones
    arm = next(category for category in categories if category["name"] == "Arm")
    assert arm["contents"][-1]["type"] == "arm_to"  # a category named like the profile's joins it
    assert "drive_at" not in fresh_registry.base_profiles["hobbit"].block_types
    assert hobbit.packs[0].version == "1.0.1"  # made, then one more block


def test_the_pack_is_an_ordinary_profile_like_folder_a_person_can_edit(fresh_registry):
    pack = save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    assert sorted(tree(pack.root)) == ["blocks.yaml", "made.yaml", "pack.yaml", "toolbox.yaml"]
    blocks = (pack.root / "blocks.yaml").read_text()
    (pack.root / "blocks.yaml").write_text(blocks.replace("drive at %1", "roll at %1"))
    fresh_registry.reload_packs()
    definition = fresh_registry.get("hobbit").block("drive_at").definition
    assert definition["message0"]["en"] == "roll at %1"
    assert load_pack(pack.root).made_block("drive_at") == drive_block()


def test_a_failed_write_leaves_the_old_pack_as_it_was(fresh_registry, monkeypatch):
    pack = save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    before = tree(pack.root)
    written = []
    real_dump = making.dump_yaml

    def dump_then_fail(data):
        written.append(data)
        if len(written) == 3:
            raise OSError(28, "No space left on device")
        return real_dump(data)

    monkeypatch.setattr(making, "dump_yaml", dump_then_fail)
    with pytest.raises(BlockMakerError, match="was not written .nothing was changed.: No space left"):
        save_block(arm_block(), fresh_registry.get("hobbit"), PACK)
    assert tree(pack.root) == before
    assert sorted(os.listdir(pack.root.parent)) == [PACK]  # no half-written folder is left beside it


def test_bad_blocks_each_get_their_message_in_the_readers_language(fresh_registry):
    hobbit = fresh_registry.get("hobbit")
    cases = [
        (drive_block(id="hobbit_move"), "das Roboterprofil 'hobbit' hat schon einen Block 'hobbit_move'"),
        (drive_block(id="Drive!"), "die Block-ID 'Drive!' geht nicht"),
        (drive_block(sentence={"en": "drive"}), "der Satz „drive“ muss %1 bis %1 je einmal haben"),
        (drive_block(sentence={}), "schreibe den Satz für den Block auf Englisch oder Deutsch"),
        (drive_block(interface_type="geometry_msgs/Twirl"), "Rockly kennt den Typ 'geometry_msgs/Twirl' nicht"),
        (drive_block(fixed={"linear.x": 1.0}), "das Feld 'linear.x' wird zweimal gefüllt"),
        (drive_block(inputs=(BlockInput("speed", "text", "linear.x"),)),
         "die Eingabe 'speed' ist ein Text, aber das Feld 'linear.x' braucht eine Zahl"),
        (drive_block(inputs=(BlockInput("speed", "number", "linear.x", default=2, minimum=0, maximum=1),)),
         "die Eingabe 'speed': ihr Vorgabewert 2 passt nicht"),
        (drive_block(kind="dance"), "'dance' kann ein gemachter Block nicht"),
        (drive_block(colour="blue"), "'blue' ist keine Farbe"),
        (arm_block(result="maybe"), "ein Aktionsblock gibt sein Ergebnis ('outcome') oder nichts, nicht 'maybe'"),
    ]
    for made, message in cases:
        problems = [problem.in_language("de") for problem in block_problems(made, hobbit)]
        assert any(message in problem for problem in problems), (made, problems)
    assert block_problems(drive_block(), hobbit) == []
    assert block_problems(arm_block(), hobbit) == []


def test_the_german_sentence_is_shown_in_a_german_window_and_the_other_language_fills_in(
        qapp, qtbot, fresh_registry):
    from rockly_desktop.bridge.headless import HeadlessEditor

    save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    save_block(arm_block(), fresh_registry.get("hobbit"), PACK)
    fresh_registry.reload_packs()
    hobbit = fresh_registry.get("hobbit")
    shown = {}
    for language in ("de", "en"):
        editor = HeadlessEditor(language)
        try:
            program = ProgramToOpen(path=None, profile=hobbit, workspace=workspace(
                block("drive_at", inputs={"speed": number(0.2)}, id="drive"),
                block("text_print", inputs={"TEXT": block("arm_to", id="arm", inputs={"while_waiting": block(
                    "text_print", inputs={"TEXT": block("variables_get", {"VAR": {"id": "fb"}})})})})))
            program.workspace["variables"] = [{"name": "feedback", "id": "fb"}]
            python = editor.python_for(program)
            texts = "['drive', 'arm'].map(id => Blockly.getMainWorkspace().getBlockById(id).toString())"
            shown[language] = (toolbox_names(qtbot, editor.view), run_js(qtbot, editor.view, texts))
        finally:
            editor.close()
    assert "Gemacht" in shown["de"][0] and "Made" in shown["en"][0]
    assert shown["de"][1][0].startswith("fahre mit") and shown["en"][1][0].startswith("drive at")
    assert shown["en"][1][1].startswith("Ergebnis der Armbewegung zu")  # no English yet: the German stands in
    assert "beim Warten jede Rückmeldung in" in shown["de"][1][1]
    assert ("ros.send_goal('hobbit_arm', 'hobbit_msgs/ArmServerAction', {'command': {'data': 'OpenGripper'}}, "
            "while_waiting=while_waiting)") in python


def test_a_program_records_its_packs_and_opening_without_them_says_which(tmp_path, fresh_registry):
    save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    fresh_registry.reload_packs()
    hobbit = fresh_registry.get("hobbit")
    used = workspace(block("drive_at", id="drive"), block("hobbit_stop", id="stop"))
    assert hobbit.packs_used(used) == {PACK: "1.0.0"}
    assert hobbit.packs_used(workspace(block("hobbit_stop"))) == {}
    path = tmp_path / "p.rockly"
    path.write_text(Program("hobbit", used, [], hobbit.packs_used(used)).to_json())
    assert parse_program(path.read_text()).packs == {PACK: "1.0.0"}
    without = ProfileRegistry.discover()
    for child in (Path(os.environ["XDG_DATA_HOME"]) / "rockly" / "packs" / PACK).iterdir():
        child.unlink()
    without.reload_packs()
    program = read_program_to_open(path, without, without.default())
    assert program.missing_packs == ((PACK, "1.0.0"),)
    assert (f"das Programm benutzt Blöcke des Blockpakets '{PACK}' (Version 1.0.0), das nicht installiert ist"
            in opening_warnings(program, "de"))
    refusal = unknown_blocks_error(program, ["drive_at"], without)
    assert f"They come from the block pack '{PACK}' 1.0.0, which is not installed" in str(refusal)


def test_importing_a_zip_checks_every_entry_and_writes_nothing_on_a_bad_one(tmp_path, fresh_registry):
    pack = save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    good = export_pack(pack, tmp_path / "good.zip")
    packs = pack.root.parent
    shared = tmp_path / "other_laptop"
    installed = import_pack(good, fresh_registry.base_profiles, folder=shared)
    assert tree(installed.root) == tree(pack.root)

    def bad_zip(name, entries, link=None):
        path = tmp_path / name
        with zipfile.ZipFile(path, "w") as archive:
            for entry, data in entries.items():
                archive.writestr(entry, data)
            if link:
                info = zipfile.ZipInfo(link)
                info.external_attr = 0o120777 << 16
                archive.writestr(info, "/etc/passwd")
        return path

    with zipfile.ZipFile(good) as archive:
        files = {name: archive.read(name) for name in archive.namelist()}
    cases = {
        bad_zip("up.zip", {**files, "../evil.yaml": "x"}): "holds the unsafe entry '../evil.yaml'",
        bad_zip("abs.zip", {**files, "/tmp/evil.yaml": "x"}): "holds the unsafe entry '/tmp/evil.yaml'",
        bad_zip("link.zip", files, link=f"{PACK}/link"): f"holds the unsafe entry '{PACK}/link'",
        bad_zip("empty.zip", {"readme.txt": "hi"}): "is no block pack file (a zip holding pack.yaml): it holds no",
        bad_zip("manifest.zip", {**files, f"{PACK}/pack.yaml": "schema: 1\nid: x\n"}): "name: is missing",
        bad_zip("nobody.zip", {**files, f"{PACK}/pack.yaml": files[f"{PACK}/pack.yaml"].replace(
            b"adds_to: hobbit", b"adds_to: nobody")}): "adds to the robot profile 'nobody', which is not installed",
    }
    not_zip = tmp_path / "text.zip"
    not_zip.write_text("not a zip")
    cases[not_zip] = "is no block pack file"
    before = tree(packs)
    for path, message in cases.items():
        with pytest.raises(BlockMakerError) as raised:
            import_pack(path, fresh_registry.base_profiles, replace=True)
        assert message in str(raised.value), str(raised.value)
        assert tree(packs) == before and sorted(os.listdir(packs)) == [PACK]
    assert not (tmp_path / "evil.yaml").exists()


def test_a_broken_pack_or_one_for_a_missing_profile_is_reported_and_the_profile_still_loads(fresh_registry):
    pack = save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    (pack.root / "blocks.yaml").write_text("blocks: [")
    manifest = (pack.root / "pack.yaml").read_text()
    other = pack.root.parent / "for_nobody"
    other.mkdir()
    save_block(drive_block(id="other_drive"), fresh_registry.get("hobbit"), "for_nobody")
    (other / "pack.yaml").write_text((other / "pack.yaml").read_text().replace("adds_to: hobbit", "adds_to: nobody"))
    registry = ProfileRegistry.discover()
    assert "hobbit" in registry.profiles and registry.get("hobbit").packs == ()
    problems = " | ".join(str(error) for error in registry.pack_errors)
    assert "blocks.yaml" in problems and "this is not valid YAML" in problems
    assert "the block pack 'for_nobody' cannot be read: the block pack adds to the robot profile 'nobody'" in problems
    assert "adds_to" in manifest
    with pytest.raises(ManifestError):
        load_pack(pack.root)


def test_the_fields_of_the_types_rockly_knows_without_a_robot(fresh_registry):
    hobbit = fresh_registry.get("hobbit")
    assert "geometry_msgs/Twist" in known_types(hobbit, "msg")
    assert "hobbit_msgs/Request" in known_types(hobbit, "srv")
    assert "hobbit_msgs/ArmServerAction" in known_types(hobbit, "action")
    twist = interface_fields(hobbit, "geometry_msgs/Twist", "msg")
    assert [(field.path, field.kind) for field in twist][:2] == [("linear.x", "number"), ("linear.y", "number")]
    assert set(field_tree(twist)) == {"linear", "angular"}
    odometry = {field.path: field.ros_type for field in interface_fields(hobbit, "nav_msgs/Odometry", "msg")}
    assert odometry["pose.pose.position.x"] == "float64" and odometry["header.frame_id"] == "string"
    arm = {part: [(field.path, field.kind) for field in interface_fields(
        hobbit, "hobbit_msgs/ArmServerAction", "action", part)] for part in ("in", "out", "feedback")}
    assert arm == {"in": [("command.data", "text"), ("velocity", "number"), ("joints", "messages")],
                   "out": [("result.data", "yes_no")], "feedback": [("feedback.data", "text")]}
    assert interface_fields(hobbit, "gone_msgs/Gone", "msg") == []


def test_the_preview_is_the_python_a_new_block_becomes():
    assert python_preview(drive_block()) == ("ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', "
                                             "{'angular': {'z': 0.0}, 'linear': {'x': ros.number_in(0.1, 0, 0.3, "
                                             "'speed')}})")
    waiting = MadeBlock(id="wait_bumper", kind="wait_until", interface="/bumper", interface_type="std_msgs/Bool",
                        read_field="data", target=True)
    assert python_preview(waiting) == "while not ros.latest('/bumper', 'data') == True:\n  ros.wait(0.1)"
    assert MadeBlock.from_data(drive_block().to_data()) == drive_block()


def test_the_maker_offers_the_profiles_categories_and_previews_a_block_as_the_page_takes_it(fresh_registry):
    hobbit = fresh_registry.get("hobbit")
    choices = category_choices(hobbit, "de")
    assert ("Fahren", "Drive", "#3d7fd6") in choices and all(english != "ROS" for _, english, _ in choices)
    preview = preview_block(drive_block(), hobbit, "de")
    assert preview["definition"]["message0"] == "fahre mit %1"
    assert preview["python"]["defaults"] == {"speed": 0.1} and not preview["python"]["expression"]


def test_a_made_block_using_a_part_the_teacher_switched_off_leaves_the_toolbox(fresh_registry):
    save_block(drive_block(), fresh_registry.get("hobbit"), PACK)
    save_block(arm_block(), fresh_registry.get("hobbit"), PACK)
    fresh_registry.reload_packs()
    hobbit = fresh_registry.get("hobbit")

    def shown(switched_off):
        return {entry["type"] for category in hobbit.toolbox("en", switched_off=switched_off)["contents"]
                for entry in category.get("contents", [])}

    assert {"drive_at", "arm_to"} <= shown(())
    assert "arm_to" not in shown({"arm"}) and "drive_at" in shown({"arm"})


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(value=st.text(), sentence=st.text(alphabet=st.characters(blacklist_characters="%", blacklist_categories=("Cs",)),
                                        max_size=30))  # half characters are refused (the next test)
@example(value="\x85", sentence="\x85")  # YAML's NEL line break: in single quotes PyYAML read it back as a space
@example(value="a\u2028b", sentence="\u2029")
def test_any_fixed_text_and_sentence_make_a_block_whose_python_sends_exactly_that_text(
        value, sentence, fresh_registry, tmp_path):
    made = MadeBlock(id="say_fixed", kind="publish", interface="/say", interface_type="std_msgs/String",
                     fixed={"data": value}, sentence={"en": sentence + "!"}, category={"en": "Made"},
                     colour="#4c97ff")
    spec = block_spec(block_definition(made), Path("fuzz.yaml"))  # the template reads back as a profile's would
    call = parse_python(python_preview(made), mode="eval").body
    assert spec.type == "say_fixed" and ast.literal_eval(call.args[2]) == {"data": value}
    folder = Path(tempfile.mkdtemp(dir=tmp_path))
    pack = save_block(made, fresh_registry.get("hobbit"), PACK, folder=folder)  # and YAML keeps it exactly
    assert pack.made_block("say_fixed") == made and pack.blocks[0].code == spec.code


@pytest.mark.parametrize("where", ["sentence", "fixed"])
def test_a_text_with_half_a_character_is_refused_with_a_clear_message_and_nothing_is_written(
        where, fresh_registry, tmp_path):
    from rockly_desktop.profiles.packs.validation import BlockMakerError

    broken = "say \udcff"  # what a command line gives for a byte it cannot decode
    made = MadeBlock(id="say_fixed", kind="publish", interface="/say", interface_type="std_msgs/String",
                     fixed={"data": broken if where == "fixed" else "hi"},
                     sentence={"en": broken if where == "sentence" else "say"}, category={"en": "Made"},
                     colour="#4c97ff")
    with pytest.raises(BlockMakerError) as refused:
        save_block(made, fresh_registry.get("hobbit"), PACK, folder=tmp_path)
    assert "the text 'say \\udcff' holds a character that is not one" in refused.value.in_language("en")
    assert list(tmp_path.iterdir()) == []


def test_the_python_preview_sends_what_a_new_block_from_the_toolbox_sends_for_an_input_without_a_default():
    from rockly_desktop.profiles.packs.generate import python_preview, toolbox_entry
    from rockly_desktop.profiles.packs.spec import BlockInput, MadeBlock

    block = MadeBlock("made_say", "call_service", "/MMUI", "hobbit_msgs/Request",
                      inputs=(BlockInput("sessionid", "text", "sessionID"), BlockInput("count", "number", "count"),
                              BlockInput("on", "yes_no", "on")), sentence={"en": "say %1 %2 %3"})
    assert "{'sessionID': '', 'count': 0, 'on': False}" in python_preview(block)
    shadows = toolbox_entry(block)["inputs"]
    assert [shadows[name]["shadow"]["fields"] for name in ("sessionid", "count", "on")] == [
        {"TEXT": ""}, {"NUM": 0}, {"BOOL": "FALSE"}]
