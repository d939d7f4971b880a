"""The block maker in the real window (issue 22): Tools → Make a block… on the simulated HOBBIT, a
service with two fields made into a block whose preview and Python follow each edit, saved into a
block pack, in the toolbox at once, and run; the German window; bad input; the Topic monitor's menu."""
import sys
from pathlib import Path

import pytest
from json_line_node import JsonLineNode
from page_tools import call_page, run_js
from program_builder import block, number, stack, text, workspace
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QComboBox, QLineEdit, QListWidget, QPlainTextEdit, QWidget
from ros_helpers import ros_environment
from test_ros2_window import connected
from waiting import eventually
from window_tools import on_hobbit_over_ros1, state

from rockly_desktop.profiles.packs.pack import user_packs_dir
from rockly_desktop.ui.blockmaker.maker_dialog import BlockMakerDialog, pack_id_for
from rockly_desktop.ui.blockmaker.offers import Offer

PARAMS = '[{name: type, value: D_PLAIN}, {name: text, value: "made by hand"}]'


def open_maker(qtbot, window) -> BlockMakerDialog:
    """Open the maker with the Tools menu's action."""
    next(action for action in window.findChildren(QAction) if action.objectName() == "action_make_block").trigger()
    return the_maker(qtbot, window)


def the_maker(qtbot, window) -> BlockMakerDialog:
    """The window's open maker, once its preview page is ready."""
    qtbot.waitUntil(lambda: window.findChild(BlockMakerDialog) is not None, timeout=5000)
    maker = window.findChild(BlockMakerDialog)
    qtbot.waitUntil(lambda: maker.preview.is_ready, timeout=30000)
    return maker


def drawn_preview(qtbot, maker) -> dict:
    """The preview block as the maker's page draws it: its text and inputs."""
    return run_js(qtbot, maker.preview, """(() => {
        const shown = Blockly.getMainWorkspace().getTopBlocks(false);
        return shown.length === 1 ? {text: shown[0].toString(), inputs: shown[0].inputList.map(i => i.name)
                                     .filter(Boolean)} : null; })()""")


def make_mmui_block(qtbot, maker, block_id="made_say", english="ask %1 to say %2", german=""):
    """Pick /MMUI, make sessionID and requestText inputs, fix its params, write the sentence."""
    assert maker.choose_named("/MMUI")
    maker.fields.set_use("sessionID", "input", "7")
    maker.fields.set_use("requestText", "input", "hello")
    maker.fields.set_use("params", "fixed", PARAMS)
    maker.sentence["en"].setText(english)
    maker.sentence["de"].setText(german)
    maker.block_id.setText(block_id)


def test_a_service_with_two_fields_becomes_a_block_in_the_toolbox_that_runs(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker)
    assert maker.problems == []
    assert "ros.call_service('/MMUI', 'hobbit_msgs/Request'" in maker.python.toPlainText()
    assert "'sessionID': '7', 'requestText': 'hello'" in maker.python.toPlainText()
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("text", "").startswith("ask"), timeout=10000)
    assert drawn_preview(qtbot, maker)["inputs"] == ["sessionid", "requestText".lower()]

    maker.sentence["en"].setText("ask %1 please to say %2")
    qtbot.waitUntil(lambda: "please" in drawn_preview(qtbot, maker)["text"], timeout=10000)

    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_say" in window.editor.known_block_types, timeout=30000)
    assert window.statusBar().currentMessage() == "The block made_say is in the toolbox under Drive."
    assert (user_packs_dir() / pack_id_for(window.profile) / "blocks.yaml").is_file()
    toolbox = run_js(qtbot, window.editor, "JSON.stringify(Blockly.getMainWorkspace().options.languageTree)")
    assert '"made_say"' in toolbox

    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(block(
        "made_say", inputs={"sessionid": text("9"), "requesttext": text("hi")}, id="say")))})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=30000) as finished:
        assert window.runs.run()
    assert finished.args[0].outcome == "finished", finished.args[0].message
    assert window.robot().snapshot()["tablet"] == {"kind": "D_PLAIN", "text": "made by hand"}


def test_the_german_window_shows_the_german_sentence(qtbot, german_window):
    maker = open_maker(qtbot, german_window)
    assert maker.windowTitle() == "Einen Block bauen"
    assert maker.choose_named("/MMUI")  # the simulated robot serves it now
    assert maker.offers.currentItem().text() == "Dienst: /MMUI  (hobbit_msgs/Request)  · jetzt am Roboter"
    assert maker.offers.currentItem().toolTip() == (  # the whole row, then what being on the robot means
        "Dienst: /MMUI  (hobbit_msgs/Request)  · jetzt am Roboter\n"
        "Der Roboter bietet das gerade an: Ein Block daraus kann sofort laufen.")
    make_mmui_block(qtbot, maker, "made_sag", "ask %1 to say %2", "frag %1 und sag %2")
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("text", "").startswith("frag"), timeout=10000)
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_sag" in german_window.editor.known_block_types, timeout=30000)
    call_page(qtbot, german_window.editor, "load", {"workspace": workspace(stack(block("made_sag", id="sag")))})
    shown = run_js(qtbot, german_window.editor, "Blockly.getMainWorkspace().getBlockById('sag').toString()")
    assert shown.startswith("frag")


def test_bad_input_says_what_is_wrong_and_writes_nothing(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker, block_id="hobbit_stop", english="ask %1")
    problems = "\n".join(maker.problems)
    assert "already has a block 'hobbit_stop'" in problems
    assert "must have each of %1 to %2 once" in problems
    assert maker.problem_label.isVisibleTo(maker) and "hobbit_stop" in maker.problem_label.text()
    assert not maker.save_button.isEnabled()
    maker.save()  # even asked directly, nothing is written
    assert not (user_packs_dir() / pack_id_for(window.profile)).exists()
    assert maker.isVisible()


def test_the_topic_monitors_menu_opens_the_maker_with_that_topic_chosen(qtbot, window):
    monitor = window.monitor_dock.widget()
    qtbot.waitUntil(lambda: monitor.select_topic("/odom"), timeout=10000)
    menu = monitor.topic_menu("/odom")
    menu.actions()[0].trigger()
    maker = the_maker(qtbot, window)
    assert maker.interface.text() == "/odom" and maker.interface_type.text() == "nav_msgs/Odometry"
    assert maker.kind.currentData() == "publish"


@pytest.mark.parametrize(("name", "kind", "made"), [("/MMUI", "service", "call_service"),
                                                   ("move_base", "action", "send_goal")])
def test_the_topic_monitor_lists_services_and_actions_whose_menu_opens_the_maker_with_one_chosen(
        qtbot, german_window, name, kind, made):
    monitor = german_window.monitor_dock.widget()
    qtbot.waitUntil(lambda: (name, kind) in monitor.interfaces.names(), timeout=10000)
    assert monitor.interfaces.title.text().startswith("Dienste und Aktionen: ")
    menu = monitor.interfaces.menu(name, kind)
    assert [action.text() for action in menu.actions()] == ["Einen Block daraus bauen…"]
    menu.actions()[0].trigger()
    maker = the_maker(qtbot, german_window)
    assert maker.interface.text() == name and maker.kind.currentData() == made
    assert maker.offers.currentItem().data(Qt.ItemDataRole.UserRole).kind == kind


def test_try_it_runs_the_previewed_block_once_on_the_simulator_before_it_is_saved(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker, block_id="made_try")
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("text", "").startswith("ask"), timeout=10000)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=30000) as finished:
        maker.try_button.click()
    assert finished.args[0].outcome == "finished", finished.args[0].message
    assert window.robot().snapshot()["tablet"] == {"kind": "D_PLAIN", "text": "made by hand"}
    assert not (user_packs_dir() / pack_id_for(window.profile)).exists()  # tried, not saved


def test_a_block_saved_while_a_program_runs_reaches_the_toolbox_once_the_run_ends(qtbot, window):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(block(
        "controls_whileUntil", {"MODE": "WHILE"}, {"BOOL": block("logic_boolean", {"BOOL": "TRUE"}),
                                                   "DO": block("hobbit_wait", inputs={"seconds": number(0.05)})},
        id="loop"))})
    assert window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "running", timeout=15000)
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker, block_id="made_later")
    maker.save_button.click()
    assert (user_packs_dir() / pack_id_for(window.profile) / "blocks.yaml").is_file()
    state(qtbot, window)  # a round trip to the page: it was not replaced meanwhile
    assert window.runs.state == "running" and "made_later" not in window.editor.known_block_types
    with qtbot.waitSignal(window.runs.sig_finished, timeout=15000) as finished:
        window.runs.stop()
    assert finished.args[0].outcome == "stopped"
    qtbot.waitUntil(lambda: "made_later" in window.editor.known_block_types, timeout=30000)
    assert state(qtbot, window)["workspace"]["blocks"]["blocks"][0]["id"] == "loop"  # the program stayed


@pytest.fixture
def ros_window(window, ros_master, hobbit_on_ros, monkeypatch):
    """The window on HOBBIT over ROS 1 (the ROS-level simulator in its own process, a real master)."""
    return on_hobbit_over_ros1(window, ros_master.uri, monkeypatch)


def test_on_ros_1_the_maker_offers_the_live_graph_and_a_made_sensor_block_reads_the_robot(qtbot, ros_window):
    qtbot.waitUntil(lambda: "/rosout" in [topic for topic, *_ in ros_window.robot().graph_topics()], timeout=15000)
    maker = open_maker(qtbot, ros_window)
    assert maker.choose_named("/rosout")  # in the live graph only: no profile declares it
    assert maker.interface_type.text() == "rosgraph_msgs/Log"
    assert maker.choose_named("/odom")
    maker.kind.setCurrentIndex(maker.kind.findData("sensor_value"))
    maker.read_field.setCurrentIndex(maker.read_field.findText("pose.pose.position.x"))
    maker.sentence["en"].setText("how far forward")
    maker.block_id.setText("made_forward")
    assert maker.problems == []
    assert "pose.pose.position.x" in maker.python.toPlainText()
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_forward" in ros_window.editor.known_block_types, timeout=30000)
    call_page(qtbot, ros_window.editor, "load", {"workspace": workspace(stack(
        block("text_print", inputs={"TEXT": block("made_forward")}, id="say")))})
    with qtbot.waitSignal(ros_window.runs.sig_finished, timeout=30000) as finished:
        assert ros_window.runs.run()
    assert finished.args[0].outcome == "finished", finished.args[0].message
    printed = ros_window.console.lines()[-2]
    # HOBBIT stands wherever earlier tests left the session's ROS-level robot: its /odom, heard here, says where
    import rospy
    from nav_msgs.msg import Odometry

    odom = rospy.wait_for_message("/odom", Odometry, timeout=10)
    assert float(printed) == pytest.approx(odom.pose.pose.position.x, abs=0.05)


@pytest.fixture
def lamp_on_ros(ros_master):
    """A plain rospy node serving /lamp/switch (std_srvs/SetBool) with the parameter /lamp/brightness."""
    lamp = JsonLineNode([sys.executable, Path(__file__).parents[1] / "robot" / "ros1" / "ros1_lamp_node.py"],
                        ros_environment(ros_master.uri, ros_master.home / "lamp"), "the lamp node")
    yield lamp
    lamp.stop()


def made_and_run(qtbot, window, program) -> None:
    """Save the open maker's block, wait for it in the toolbox, run ``program`` once: it must finish."""
    maker = window.findChild(BlockMakerDialog)
    block_id = maker.block_id.text()
    assert maker.problems == []
    maker.save_button.click()
    qtbot.waitUntil(lambda: block_id in window.editor.known_block_types, timeout=30000)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(program))})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=30000) as finished:
        assert window.runs.run()
    assert finished.args[0].outcome == "finished", finished.args[0].message


def test_on_ros_1_the_maker_offers_a_plain_nodes_service_and_parameter_and_their_blocks_reach_it(
        qtbot, ros_window, lamp_on_ros):
    robot = ros_window.robot()
    maker = open_maker(qtbot, ros_window)  # the open maker wishes the parameters listed
    eventually(lambda: ("/lamp/switch", "std_srvs/SetBool") in robot.graph_services()
               and "/lamp/brightness" in robot.graph_parameters(), timeout=20)
    assert ("/move_base", "move_base_msgs/MoveBaseAction") in robot.graph_actions()  # the simulated HOBBIT's
    qtbot.waitUntil(lambda: maker.choose_named("/lamp/brightness"), timeout=10000)
    assert maker.choose_named("/lamp/switch")  # in the live graph only: no profile declares it
    assert maker.interface_type.text() == "std_srvs/SetBool"
    assert maker.offers.currentItem().text() == "Service: /lamp/switch  (std_srvs/SetBool)  · on the robot now"
    assert maker.choose_named("move_base") and maker.offers.currentItem().text().endswith("on the robot now")
    assert maker.choose_named("/lamp/switch")
    maker.fields.set_use("data", "input", "true")
    maker.sentence["en"].setText("switch the lamp on: %1")
    maker.block_id.setText("made_lamp")
    made_and_run(qtbot, ros_window, block("made_lamp", inputs={"data": block("logic_boolean", {"BOOL": "TRUE"})}))
    eventually(lambda: {"service": "/lamp/switch", "request": {"data": True}} in lamp_on_ros.lines, timeout=10)

    maker = open_maker(qtbot, ros_window)
    qtbot.waitUntil(lambda: maker.choose_named("/lamp/brightness"), timeout=15000)  # listed again once wished again
    assert maker.offers.currentItem().text() == "Parameter: /lamp/brightness  · on the robot now"
    maker.kind.setCurrentIndex(maker.kind.findData("get_param"))
    maker.sentence["en"].setText("the lamp's brightness")
    maker.block_id.setText("made_brightness")
    made_and_run(qtbot, ros_window, block("text_print", inputs={"TEXT": block("made_brightness")}, id="say"))
    assert ros_window.console.lines()[-2] == "7"


def test_on_ros_2_the_maker_offers_the_live_graph_and_a_block_made_from_a_known_type_publishes(
        qtbot, window, test_robot, ros2_settings, monkeypatch):
    ros2_window = connected(window, ros2_settings, monkeypatch)
    qtbot.waitUntil(lambda: "/map_name" in [topic for topic, *_ in ros2_window.robot().graph_topics()], timeout=20000)
    maker = open_maker(qtbot, ros2_window)
    assert maker.choose_named("/map_name")  # the test node's: in the live graph only
    assert maker.interface_type.text() == "std_msgs/String"
    known_string = Offer("topic", "", "std_msgs/String")
    string_type = next(row for row in range(maker.offers.count())
                       if maker.offers.item(row).data(Qt.ItemDataRole.UserRole) == known_string)
    maker.offers.setCurrentRow(string_type)  # a type Rockly knows without a robot; the topic is typed in
    maker.interface.setText("/chatter")
    maker.fields.set_use("data", "input", "hello")
    maker.sentence["en"].setText("chat %1")
    maker.block_id.setText("made_chat")
    assert maker.problems == []
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_chat" in ros2_window.editor.known_block_types, timeout=30000)
    call_page(qtbot, ros2_window.editor, "load", {"workspace": workspace(stack(
        block("made_chat", inputs={"data": text("made without code")}, id="chat")))})
    with qtbot.waitSignal(ros2_window.runs.sig_finished, timeout=30000) as finished:
        assert ros2_window.runs.run()
    assert finished.args[0].outcome == "finished", finished.args[0].message
    eventually(lambda: {"data": "made without code"} in [line["message"] for line in test_robot.received("/chatter")],
               timeout=10)


def test_on_ros_2_the_maker_offers_a_plain_nodes_service_action_and_parameter_and_their_blocks_reach_it(
        qtbot, window, test_robot, ros2_settings, monkeypatch):
    ros2_window = connected(window, ros2_settings, monkeypatch)
    robot = ros2_window.robot()
    maker = open_maker(qtbot, ros2_window)  # the open maker wishes the parameters listed
    eventually(lambda: ("/set_light", "std_srvs/SetBool") in robot.graph_services()
               and "/test_robot:max_speed" in robot.graph_parameters(), timeout=30)
    assert ("/fibonacci", "test_msgs/FibonacciAction") in robot.graph_actions()
    assert not [name for name, _type in robot.graph_services() if name.endswith("_parameters")]
    qtbot.waitUntil(lambda: maker.choose_named("/test_robot:max_speed"), timeout=10000)
    assert maker.choose_named("/set_light")  # the test node's: no profile declares it
    assert maker.offers.currentItem().text() == "Service: /set_light  (std_srvs/SetBool)  · on the robot now"
    assert maker.choose_named("/fibonacci") and maker.interface_type.text() == "test_msgs/FibonacciAction"
    assert maker.choose_named("/set_light")
    maker.fields.set_use("data", "input", "true")
    maker.sentence["en"].setText("switch the light on: %1")
    maker.block_id.setText("made_light")
    made_and_run(qtbot, ros2_window, block("made_light", inputs={"data": block("logic_boolean", {"BOOL": "TRUE"})}))
    eventually(lambda: {"data": True} in [line["message"] for line in test_robot.received("/set_light")], timeout=10)

    maker = open_maker(qtbot, ros2_window)
    qtbot.waitUntil(lambda: maker.choose_named("/test_robot:max_speed"), timeout=15000)  # listed once wished again
    maker.kind.setCurrentIndex(maker.kind.findData("get_param"))
    maker.sentence["en"].setText("the top speed")
    maker.block_id.setText("made_max_speed")
    made_and_run(qtbot, ros2_window, block("text_print", inputs={"TEXT": block("made_max_speed")}, id="say"))
    assert float(ros2_window.console.lines()[-2]) == pytest.approx(0.22)


def test_what_the_live_graph_gains_while_the_maker_is_open_is_offered_and_the_block_being_made_stays(
        qtbot, window):
    maker = open_maker(qtbot, window)
    assert maker.choose_named("/MMUI")
    maker.sentence["en"].setText("ask %1 to say %2")
    offered = lambda: [maker.offers.item(row).text() for row in range(maker.offers.count())]  # noqa: E731
    assert "Parameter: /lamp_level  · on the robot now" not in offered()
    window.robot().world.params["/lamp_level"] = 3  # the simulated robot gains a parameter
    qtbot.waitUntil(lambda: "Parameter: /lamp_level  · on the robot now" in offered(), timeout=10000)
    assert maker.offers.currentItem().data(Qt.ItemDataRole.UserRole).name == "/MMUI"
    assert maker.sentence["en"].text() == "ask %1 to say %2" and maker.interface.text() == "/MMUI"


def test_every_control_of_the_maker_has_a_name_a_screen_reader_reads_in_the_windows_language(qtbot, german_window):
    maker = open_maker(qtbot, german_window)
    assert maker.choose_named("/MMUI")
    controls = [widget for widget in maker.findChildren(QWidget)
                if widget.focusPolicy() != Qt.FocusPolicy.NoFocus and widget.isVisibleTo(maker)
                and isinstance(widget, (QLineEdit, QComboBox, QListWidget, QPlainTextEdit))
                and not isinstance(widget.parentWidget(), QComboBox)]  # an editable box's own line is the box's
    assert len(controls) > 15
    assert [widget.objectName() for widget in controls if not widget.accessibleName()] == []
    assert maker.sentence["de"].accessibleName() == "Satz (Deutsch)"
    assert maker.fields.cellWidget(2, 2).accessibleName() == "sessionID: Verwendung"


def test_the_filter_narrows_the_offers_and_a_parameter_is_named_and_set(qtbot, window):
    maker = open_maker(qtbot, window)
    maker.offer_filter.setText("twist geometry")
    shown = [maker.offers.item(row).text() for row in range(maker.offers.count())
             if not maker.offers.item(row).isHidden()]
    assert "Topic: /cmd_vel  (geometry_msgs/Twist)" in shown and all("Twist" in text for text in shown)
    maker.offer_filter.clear()
    parameter = next(row for row in range(maker.offers.count())
                     if maker.offers.item(row).text() == "Parameter (name it above)")
    maker.offers.setCurrentRow(parameter)
    maker.interface.setText("/max_speed")
    maker.kind.setCurrentIndex(maker.kind.findData("set_param"))
    maker.sentence["en"].setText("set the top speed to %1")
    maker.block_id.setText("made_top_speed")
    assert maker.problems == []
    assert "ros.set_param('/max_speed'" in maker.python.toPlainText()
    qtbot.waitUntil(lambda: "top speed" in (drawn_preview(qtbot, maker) or {}).get("text", ""), timeout=10000)


def test_the_robots_parameters_are_wished_while_the_maker_is_open_and_no_longer(qtbot, window, monkeypatch):
    robot = window.robot()
    wishes = []
    monkeypatch.setattr(robot, "want_parameters", wishes.append)
    maker = open_maker(qtbot, window)
    qtbot.waitUntil(lambda: wishes == [True], timeout=5000)
    maker.reject()
    qtbot.waitUntil(lambda: wishes == [True, False], timeout=5000)


def test_the_maker_opens_only_through_the_teachers_gate(qtbot, window):
    """In kiosk mode the gate asks for the teacher's PIN (tests/ui/test_kiosk_lock.py): a visitor makes no blocks."""
    held = []
    window.teacher_gate = held.append
    next(action for action in window.findChildren(QAction) if action.objectName() == "action_make_block").trigger()
    monitor = window.monitor_dock.widget()
    monitor.topic_menu("/odom").actions()[0].trigger()
    assert len(held) == 2 and window.findChild(BlockMakerDialog) is None
    held[1]()  # the teacher gave the PIN
    assert the_maker(qtbot, window).interface.text() == "/odom"


def test_an_action_block_gives_its_outcome_and_has_a_while_waiting_part_and_runs_on_the_simulator(qtbot, window):
    maker = open_maker(qtbot, window)
    assert maker.choose_named("hobbit_arm")
    assert not maker.read_field.isVisibleTo(maker) and maker.while_waiting.isVisibleTo(maker)
    maker.fields.set_use("command.data", "input", "MoveToTray")
    maker.result.setCurrentIndex(maker.result.findData("outcome"))
    maker.while_waiting.setChecked(True)
    maker.sentence["en"].setText("arm to %1")
    maker.block_id.setText("made_arm")
    assert maker.problems == []
    assert "while_waiting=None" in maker.python.toPlainText()
    qtbot.waitUntil(lambda: "while_waiting" in (drawn_preview(qtbot, maker) or {}).get("inputs", []), timeout=10000)
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_arm" in window.editor.known_block_types, timeout=30000)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(
        block("text_print", inputs={"TEXT": block("made_arm", inputs={"command_data": text("MoveToTray")})},
              id="say")))})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=30000) as finished:
        assert window.runs.run()
    assert finished.args[0].outcome == "finished", finished.args[0].message
    assert window.console.lines()[-2] == "succeeded"
    assert window.robot().snapshot()["arm"] == "tray"


def test_the_preview_shows_the_inputs_before_the_sentence_is_written_and_keeps_a_drawing_while_it_is_wrong(
        qtbot, window):
    maker = open_maker(qtbot, window)
    assert maker.choose_named("/MMUI")
    maker.fields.set_use("sessionID", "input", "7")
    maker.fields.set_use("requestText", "input", "hello")
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("inputs") == ["sessionid", "requesttext"],
                    timeout=10000)
    assert drawn_preview(qtbot, maker)["text"].startswith("/MMUI")
    maker.sentence["en"].setText("ask %1")  # half written: the places do not match yet
    assert any("must have each of %1 to %2" in problem for problem in maker.problems)
    qtbot.waitUntil(lambda: maker.preview.drawn is not None and not maker.preview.is_drawing, timeout=10000)
    assert drawn_preview(qtbot, maker)["inputs"] == ["sessionid", "requesttext"]


def test_a_new_categorys_colour_is_chosen_with_a_swatch_and_written_to_the_pack(qtbot, german_window):
    maker = open_maker(qtbot, german_window)
    make_mmui_block(qtbot, maker, block_id="made_lamp_say")
    first = maker.category.itemText(0)
    maker.category.setCurrentIndex(0)  # a category of the profile's brings its colour
    assert maker.colour.colour() == maker.category.itemData(0)[1] == maker.block().colour
    colours = [maker.colour.box.itemText(row) for row in range(maker.colour.box.count())]
    assert colours[0] == f"{first}  {maker.category.itemData(0)[1]}" and "Grün  #43a047" in colours
    maker.category.setEditText("Lampen")  # a new category keeps the colour chosen
    maker.colour.set_colour("#43a047")
    assert maker.colour.swatch.styleSheet().startswith("background: #43a047")
    assert maker.block().colour == "#43a047" and maker.problems == []
    qtbot.waitUntil(lambda: run_js(qtbot, maker.preview, "(() => { const shown = Blockly.getMainWorkspace()"
                                   ".getTopBlocks(false); return shown.length ? shown[0].getColour() : ''; })()")
                    == "#43a047", timeout=10000)
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_lamp_say" in german_window.editor.known_block_types, timeout=30000)
    import yaml

    toolbox = yaml.safe_load((user_packs_dir() / pack_id_for(german_window.profile) / "toolbox.yaml").read_text())
    assert [(category["name"], category["colour"]) for category in toolbox["categories"]] == [
        ({"en": "Lampen", "de": "Lampen"}, "#43a047")]


EDIT_ITEM = "Blockly.ContextMenuRegistry.registry.getItem('rocklyEditMadeBlock')"


def test_a_made_block_opens_again_from_its_menu_is_changed_and_the_program_using_it_keeps_working(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker)
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_say" in window.editor.known_block_types, timeout=30000)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(
        block("made_say", inputs={"sessionid": text("9"), "requesttext": text("hi")}, id="say"),
        block("hobbit_wait", inputs={"seconds": number(0.05)}, id="wait")))})
    qtbot.waitUntil(lambda: "made_say" in str(window.editor.workspace), timeout=10000)
    shown = run_js(qtbot, window.editor, f"""(() => {{ const ws = Blockly.getMainWorkspace();
        return [{EDIT_ITEM}.preconditionFn({{block: ws.getBlockById('say')}}),
                {EDIT_ITEM}.preconditionFn({{block: ws.getBlockById('wait')}}),
                {EDIT_ITEM}.displayText()]; }})()""")
    assert shown == ["enabled", "hidden", "Edit this block…"]
    run_js(qtbot, window.editor, f"{EDIT_ITEM}.callback({{block: Blockly.getMainWorkspace().getBlockById('say')}})")
    maker = the_maker(qtbot, window)
    assert maker.editing == pack_id_for(window.profile) and maker.windowTitle() == "Change the block made_say"
    assert maker.block_id.text() == "made_say" and maker.block_id.isReadOnly()
    assert maker.interface.text() == "/MMUI" and maker.sentence["en"].text() == "ask %1 to say %2"
    assert [(entry.name, entry.default) for entry in maker.block().inputs] == [("sessionid", "7"),
                                                                               ("requesttext", "hello")]
    assert maker.block().fixed == {"params": [{"name": "type", "value": "D_PLAIN"},
                                              {"name": "text", "value": "made by hand"}]}
    assert maker.problems == [] and not maker.warning_label.isVisibleTo(maker)

    maker.fields.set_use("requestText", "fixed", "bye")  # an input the open program fills goes away
    assert maker.warning_label.isVisibleTo(maker) and "requestText" in maker.warning_label.text()
    maker.sentence["en"].setText("let %1 speak")
    maker.colour.set_colour("#d64541")
    assert maker.problems == []
    maker.save_button.click()
    qtbot.waitUntil(lambda: window.findChild(BlockMakerDialog) is None or not window.findChild(
        BlockMakerDialog).isVisible(), timeout=10000)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "(() => { const b = Blockly.getMainWorkspace()"
                                   ".getBlockById('say'); return b ? b.toString() : ''; })()").startswith("let"),
                    timeout=30000)
    kept = run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getBlockById('say')"
                                        ".getInputTargetBlock('sessionid').getFieldValue('TEXT')")
    assert kept == "9" and run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getBlockById('wait') !== null")
    import yaml

    pack = user_packs_dir() / pack_id_for(window.profile)
    made = yaml.safe_load((pack / "made.yaml").read_text())["blocks"]
    assert [(entry["id"], entry["sentence"], entry["colour"]) for entry in made] == [
        ("made_say", {"en": "let %1 speak"}, "#d64541")]
    assert yaml.safe_load((pack / "pack.yaml").read_text())["version"] == "1.0.1"
    with qtbot.waitSignal(window.runs.sig_finished, timeout=30000) as finished:
        assert window.runs.run()
    assert finished.args[0].outcome == "finished", finished.args[0].message


def test_tools_edit_a_made_block_asks_which_and_says_when_there_is_none(qtbot, german_window, monkeypatch):
    from PySide6.QtWidgets import QInputDialog, QMessageBox

    told = []
    monkeypatch.setattr(QMessageBox, "exec", lambda box: told.append(box.text()) or 0)
    edit = next(action for action in german_window.findChildren(QAction)
                if action.objectName() == "action_edit_made_block")
    assert edit.text() == "Gebauten Block &ändern…"
    edit.trigger()
    assert told == ["Für diesen Roboter wurde noch kein Block gebaut (Werkzeuge → Block bauen…)."]
    maker = open_maker(qtbot, german_window)
    make_mmui_block(qtbot, maker, "made_sag", "ask %1 to say %2", "frag %1 und sag %2")
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_sag" in german_window.editor.known_block_types, timeout=30000)
    asked = []
    monkeypatch.setattr(QInputDialog, "getItem", lambda *args: asked.append(args[3]) or ("made_sag", True))
    edit.trigger()
    assert asked == [["made_sag"]]
    maker = the_maker(qtbot, german_window)
    assert maker.windowTitle() == "Den Block made_sag ändern" and maker.save_button.text() == "Änderungen &speichern"
    assert maker.sentence["de"].text() == "frag %1 und sag %2"


def test_the_suggested_block_id_follows_the_offer_chosen_until_the_person_types_one(qtbot, window):
    maker = open_maker(qtbot, window)
    assert maker.focusWidget() is maker.offer_filter and maker.interface.text() == ""  # nothing chosen by itself
    assert maker.choose_named("/odom") and maker.block_id.text() == "made_odom"
    assert maker.choose_named("/MMUI") and maker.block_id.text() == "made_mmui"
    maker.block_id.setText("made_say")
    assert maker.choose_named("/odom") and maker.block_id.text() == "made_say"


def test_a_fixed_field_left_empty_keeps_its_default_which_its_placeholder_shows(qtbot, german_window):
    maker = open_maker(qtbot, german_window)
    assert maker.choose_named("/cmd_vel")
    maker.fields.set_use("linear.x", "input", "0,1")  # a German window writes 0.1 so
    maker.fields.set_use("angular.z", "fixed", "")
    assert maker.findChild(QLineEdit, "maker_value_angular.z").placeholderText() == "Vorgabe: 0"
    maker.sentence["de"].setText("fahre mit %1")
    maker.block_id.setText("made_default_kept")
    assert maker.problems == []
    assert "None" not in maker.python.toPlainText()
    assert "'angular'" not in maker.python.toPlainText()
    made_and_run(qtbot, german_window, block("made_default_kept", inputs={"linear_x": number(0.1)}))


def test_editing_a_made_block_away_from_an_input_the_program_filled_marks_the_program_changed(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker, block_id="made_ask")
    maker.save_button.click()
    qtbot.waitUntil(lambda: "made_ask" in window.editor.known_block_types, timeout=30000)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(
        block("made_ask", inputs={"sessionid": text("9"), "requesttext": text("hi")}, id="ask")))})
    qtbot.waitUntil(lambda: "made_ask" in str(window.editor.workspace), timeout=10000)

    def edited(change):
        window.document.modified = False  # as if just saved
        window.edit_made_block("made_ask")
        maker = the_maker(qtbot, window)
        change(maker)
        assert maker.problems == []
        maker.save_button.click()
        qtbot.waitUntil(lambda: not window.findChild(BlockMakerDialog).isVisible(), timeout=10000)
        sentence = maker.sentence["en"].text().split("%")[0]
        qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "(() => { const b = Blockly.getMainWorkspace()"
                                       ".getBlockById('ask'); return b ? b.toString() : ''; })()").startswith(
            sentence), timeout=30000)

    edited(lambda maker: maker.sentence["en"].setText("please ask %1 to say %2"))  # nothing the program held is lost
    assert not window.document.modified and not window.isWindowModified()

    def drop_the_text(maker):
        maker.fields.set_use("requestText", "fixed", "bye")  # the program's "hi" in it goes with the input
        maker.sentence["en"].setText("let %1 speak")
    edited(drop_the_text)
    assert window.document.modified and window.isWindowModified()  # the title's mark; closing asks to save


@pytest.mark.parametrize("which, live", [("window", "· on the robot now"), ("german_window", "· jetzt am Roboter")])
def test_the_offers_say_in_full_what_is_on_the_robot_now_at_the_makers_default_size(qtbot, request, which, live):
    from PySide6.QtWidgets import QStyleOptionViewItem

    maker = open_maker(qtbot, request.getfixturevalue(which))
    offers = maker.offers
    width = offers.viewport().width()
    rows = [offers.item(row) for row in range(offers.count())]
    assert any(item.text().endswith(live) for item in rows)

    def drawn(item):  # the text the row is drawn with
        index = offers.indexFromItem(item)
        option = QStyleOptionViewItem()
        option.rect = offers.visualRect(index)
        offers.itemDelegate().initStyleOption(option, index)
        return option.text, option.fontMetrics.horizontalAdvance(option.text) < width - option.rect.left()
    assert [drawn(item) for item in rows if not drawn(item)[1]] == []  # each fits the list: none is cut off
    assert [item.text() for item in rows if drawn(item)[0].endswith(live) != item.text().endswith(live)] == []
    assert all(item.text() in item.toolTip() for item in rows)  # the whole of it, with an elided type
