"""A program using a block pack's blocks through the real window: saving records the pack, the
program opens again, and a window without the pack names it and leaves the file alone."""
import json
import shutil

from program_builder import block, number, rockly_document, stack
from window_tools import completed, error_boxes, state

from rockly_desktop.core.program import load_program
from rockly_desktop.profiles.packs.making import save_block
from rockly_desktop.profiles.packs.spec import BlockInput, MadeBlock
from rockly_desktop.profiles.registry import ProfileRegistry

DRIVE = MadeBlock(id="made_drive", kind="publish", interface="/cmd_vel", interface_type="geometry_msgs/Twist",
                  inputs=(BlockInput("speed", "number", "linear.x", "m/s", 0.1, 0, 0.3),),
                  sentence={"en": "drive at %1", "de": "fahre mit %1"}, category={"en": "Made", "de": "Gemacht"},
                  colour="#4c97ff")


def test_a_program_with_pack_blocks_saves_its_pack_opens_again_and_without_the_pack_says_which(
        qtbot, driver, tmp_path):
    pack = save_block(DRIVE, ProfileRegistry.discover().get("hobbit"), "made_for_hobbit")
    path = tmp_path / "made.rockly"
    path.write_text(rockly_document([stack(block("made_drive", inputs={"speed": number(0.2)}, id="drive"),
                                           block("hobbit_stop", id="stop"))]))
    window = driver.open_window()
    assert completed(qtbot, window.files.open, str(path))
    qtbot.waitUntil(lambda: "ros.publish_message('/cmd_vel'" in window.code_dock.view.toPlainText(), timeout=10000)
    window.document.modified = True
    assert completed(qtbot, window.files.save)
    assert json.loads(path.read_text())["packs"] == {"made_for_hobbit": "1.0.0"}
    saved = state(qtbot, window)["workspace"]

    again = driver.open_window()
    assert completed(qtbot, again.files.open, str(path))
    assert state(qtbot, again)["workspace"] == saved

    shutil.rmtree(pack.root)
    before = path.read_bytes()
    without = driver.open_window()
    without.files.open(str(path))
    qtbot.waitUntil(lambda: bool(error_boxes(without)), timeout=10000)
    message = error_boxes(without)[0]
    assert "made_drive" in message and "block pack 'made_for_hobbit' 1.0.0, which is not installed" in message
    assert path.read_bytes() == before and load_program(path).packs == {"made_for_hobbit": "1.0.0"}
