"""The HOBBIT state panels, from the manifest, fed by the built-in simulator during a run."""
from page_tools import call_page
from program_builder import block, number, stack, text, workspace
from PySide6.QtWidgets import QLabel

from rockly_desktop.core.state_store import StateStore
from rockly_desktop.ui.docks.state_panels import StatePanels


def test_each_row_shows_its_field_transformed_and_formatted(qtbot, hobbit):
    panels = StatePanels(hobbit.state_panels, "en")
    qtbot.addWidget(panels)
    store = StateStore()
    panels.set_store(store)
    assert set(panels.values().values()) == {"–"}
    store.record("/odom", "nav_msgs/Odometry", {"pose": {"pose": {"position": {"x": 1.234, "y": -0.5},
                                                                     "orientation": {"x": 0, "y": 0,
                                                                                     "z": 0.7071068, "w": 0.7071068}}},
                                                "twist": {"twist": {"linear": {"x": 0.3}, "angular": {"z": 0.0}}}})
    store.record("/battery_state", "sensor_msgs/BatteryState", {"percentage": 0.42})
    store.record("/hobbit_arm/result", "action result", {"status": {"status": 4}})
    panels.refresh()
    values = panels.values()
    assert (values["Position x"], values["Position y"], values["Heading"]) == ("1.23 m", "-0.50 m", "90°")
    assert values["Charge"] == "42 %" and values["Command state"] == "failed"


def test_a_value_the_panel_does_not_name_is_shown_as_it_comes_and_zero_has_no_minus(qtbot, hobbit):
    panels = StatePanels(hobbit.state_panels, "en")
    qtbot.addWidget(panels)
    store = StateStore()
    panels.set_store(store)
    store.record("/head/move", "std_msgs/String", {"data": "somewhere_new"})
    store.record("/odom", "nav_msgs/Odometry", {"pose": {"pose": {"position": {"x": -0.001, "y": 0.0},
                                                                     "orientation": {"x": 0, "y": 0, "z": -0.001,
                                                                                     "w": 1.0}}},
                                                "twist": {"twist": {"linear": {"x": 0.0}, "angular": {"z": -0.001}}}})
    panels.refresh()
    values = panels.values()
    assert values["Looking"] == "somewhere_new"
    assert (values["Position x"], values["Heading"], values["Turning"]) == ("0.00 m", "0°", "0 °/s")


def test_panels_follow_a_run_on_the_simulator(qtbot, window):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(
        block("hobbit_head", {"head_position": "up_left"}), block("hobbit_emo", {"emotion": "SAD"}),
        block("hobbit_arm_move", {"movement": "MoveToCandle"}),
        block("hobbit_show_info", inputs={"text": text("Hi there")}),
        block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)})))})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.run()
    panels = window.state_dock.widget()
    qtbot.waitUntil(lambda: panels.values()["Position x"] == "0.50 m" and panels.values()["Motion"] == "standing",
                    timeout=3000)
    values = panels.values()
    assert (values["Looking"], values["Emotion"]) == ("up left", "sad")
    assert (values["Last command"], values["Command state"]) == ("straight up", "done")
    assert values["Last question"] == "Hi there"
    assert float(values["Charge"].split()[0]) > 90


def test_health_is_green_on_the_simulator_with_details(qtbot, window):
    qtbot.waitUntil(lambda: window.health.level == "green", timeout=5000)
    assert [str(item.name) for item in window.health.items] == [
        "simulator", "/odom", "/battery_state", "/joint_states", "/MMUI", "hobbit_arm", "move_base"]
    assert "Connection: all good" in window.health.text()


def test_a_field_double_clicked_in_the_topic_monitor_is_plotted(qtbot, window):
    monitor, plot = window.monitor_dock.widget(), window.plot_panel()
    qtbot.waitUntil(lambda: window.robot().state.latest("/odom") is not None, timeout=5000)
    monitor.refresh()
    assert monitor.select_topic("/odom")
    monitor.refresh()
    index = monitor.field_index("pose.pose.position.x")
    assert index.isValid()
    monitor.sig_plot_requested.emit("/odom", "pose.pose.position.x")
    assert plot.curves() == [("/odom", "pose.pose.position.x")]


def test_a_long_value_wraps_in_a_narrow_dock_instead_of_being_cut(qtbot, hobbit):
    panels = StatePanels(hobbit.state_panels, "de")
    qtbot.addWidget(panels)
    panels.resize(300, 400)
    panels.show()
    store = StateStore()
    panels.set_store(store)
    question = "Was ist deine Lieblingsfarbe, wenn du an den Sommer denkst?"
    store.record("/MMUI", "service", {"request": {"params": [{}, {"value": question}]}, "response": {}})
    store.record("/hobbit_arm/goal", "action goal", {"goal": {"command": {"data": "TurnTurntableCCW"}}})
    panels.refresh()
    assert panels.values()["Letzte Frage"] == question
    assert panels.values()["Letzter Befehl"] == "Drehteller gegen den Uhrzeigersinn"
    qtbot.waitUntil(lambda: panels.widget().width() <= panels.viewport().width(), timeout=3000)
    assert all(label.wordWrap() for label in panels.findChildren(QLabel) if label.objectName().startswith("state:"))
