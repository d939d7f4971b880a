"""The Topic monitor: topics with types, publishers, rates and ages; the selected topic's newest
message as a tree that keeps its shape; filter, sorting, pause; dragging and plotting fields;
a note when the store's byte budget cut a topic's history."""

import array

import pytest
from PySide6.QtCore import QPoint, Qt, QTimer
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QStyle

from rockly_desktop.core.state_store import StateStore
from rockly_desktop.ui.docks.topic_models import LIST_LIMIT, RATE, TOPIC
from rockly_desktop.ui.docks.topic_monitor import TopicMonitor

ODOM = "nav_msgs/Odometry"


class FakeClock:
    """The store's clock, moved by the test (rates and ages depend on it)."""

    def __init__(self):
        self.now = 500.0

    def __call__(self):
        return self.now


def odometry(x, seq=0):
    return {
        "header": {"seq": seq, "stamp": {"secs": 1716383000, "nsecs": 0}, "frame_id": "odom"},
        "child_frame_id": "base_footprint",
        "pose": {"pose": {"position": {"x": x, "y": -0.5, "z": 0.0},
                          "orientation": {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}},
                 "covariance": [0.0] * 36},
        "twist": {"twist": {"linear": {"x": 0.25, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.3}},
                  "covariance": [0.0] * 36},
    }


def joint_states(positions):
    return {"header": {"seq": 1, "stamp": {"secs": 0, "nsecs": 0}, "frame_id": ""},
            "name": ["wheel_left", "wheel_right", "head_pan"], "position": list(positions),
            "velocity": [0.0, 0.0, 0.0], "effort": [], "status": [{"name": "motor", "level": 2}]}


@pytest.fixture
def clock():
    return FakeClock()


@pytest.fixture
def store(clock):
    return StateStore(clock=clock)


@pytest.fixture
def make_monitor(qtbot, store):
    def make(graph=None, language="en", shown=False):
        monitor = TopicMonitor(store, graph=graph, language=language)
        qtbot.addWidget(monitor)
        monitor.resize(900, 500)
        if shown:
            monitor.show()
            qtbot.waitExposed(monitor)
        return monitor
    return make


def rows(monitor) -> list:
    """The table as shown (sorted and filtered): one tuple of texts per row."""
    model = monitor.table.model()
    return [tuple(model.index(row, column).data() for column in range(model.columnCount()))
            for row in range(model.rowCount())]


def row_of(monitor, topic) -> dict:
    (found,) = [row for row in rows(monitor) if row[TOPIC] == topic]
    return dict(zip(("topic", "type", "publishers", "rate", "age"), found, strict=True))


def shown_value(monitor, path) -> str:
    index = monitor.field_index(path)
    assert index.isValid(), f"{path} is not in the tree"
    return index.siblingAtColumn(1).data()


def child_labels(monitor, path) -> list:
    index = monitor.field_index(path)
    model = monitor.message_model
    return [model.index(row, 0, index).data() for row in range(model.rowCount(index))]


# ----------------------------------------------------------------------------- the table

def test_topics_are_listed_with_type_and_publishers_from_the_graph(store, make_monitor):
    store.record("/odom", ODOM, odometry(1.0))
    store.record("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
    graph = [("/odom", ODOM, 1), ("/scan", "sensor_msgs/LaserScan", 2)]
    monitor = make_monitor(graph=lambda: graph)
    assert [row[TOPIC] for row in rows(monitor)] == ["/cmd_vel", "/odom", "/scan"]
    assert row_of(monitor, "/odom")["type"] == ODOM
    assert row_of(monitor, "/odom")["publishers"] == "1"
    silent = row_of(monitor, "/scan")  # nothing received yet, still listed
    shown = (silent["type"], silent["publishers"], silent["rate"], silent["age"])
    assert shown == ("sensor_msgs/LaserScan", "2", "–", "–")
    assert row_of(monitor, "/cmd_vel")["publishers"] == "0"  # heard before, no publisher in the graph now
    assert monitor.count_label.text() == "Topics: 3"

    graph.append(("/battery_state", "sensor_msgs/BatteryState", 1))
    graph[0] = ("/odom", ODOM, 3)
    monitor.refresh()
    assert row_of(monitor, "/battery_state")["publishers"] == "1"
    assert row_of(monitor, "/odom")["publishers"] == "3"


def test_without_a_graph_the_store_topics_are_listed_with_unknown_publishers(store, make_monitor):
    store.record("/odom", ODOM, odometry(1.0))
    monitor = make_monitor()
    assert rows(monitor)[0][:3] == ("/odom", ODOM, "–")


def test_a_failing_graph_keeps_the_last_list(store, make_monitor):
    answers = [[("/scan", "sensor_msgs/LaserScan", 1)]]

    def graph():
        if not answers:
            raise ConnectionRefusedError("master gone")
        return answers.pop()
    monitor = make_monitor(graph=graph)
    monitor.refresh()
    assert [row[TOPIC] for row in rows(monitor)] == ["/scan"]


def test_rate_and_age_of_a_50_hz_stream(store, clock, make_monitor):
    monitor = make_monitor()
    for seq in range(101):
        store.record("/odom", ODOM, odometry(0.01 * seq, seq))
        clock.now += 0.02
    clock.now += 0.28
    monitor.refresh()
    row = row_of(monitor, "/odom")
    assert float(row["rate"]) == pytest.approx(50.0, rel=0.01)
    assert row["rate"] == "50.0"  # one decimal
    assert float(row["age"]) == pytest.approx(0.3, abs=0.051)


def test_the_filter_matches_topics_and_types(store, make_monitor, qtbot):
    store.record("/odom", ODOM, odometry(1.0))
    store.record("/joint_states", "sensor_msgs/JointState", joint_states([0.0, 0.0, 0.0]))
    store.record("/battery_state", "sensor_msgs/BatteryState", {"percentage": 0.8})
    monitor = make_monitor()
    qtbot.keyClicks(monitor.filter_edit, "ODO")
    assert [row[TOPIC] for row in rows(monitor)] == ["/odom"]
    assert monitor.count_label.text() == "Topics: 1 of 3"
    monitor.filter_edit.setText("sensor_msgs")
    assert [row[TOPIC] for row in rows(monitor)] == ["/battery_state", "/joint_states"]
    monitor.filter_edit.clear()
    assert len(rows(monitor)) == 3


def test_clicking_a_header_sorts(store, clock, make_monitor, qtbot):
    for step in range(1, 101):  # one second: /a at 100 Hz, /b at 4 Hz, /c at 20 Hz
        clock.now += 0.01
        for topic, every in (("/a", 1), ("/b", 25), ("/c", 5)):
            if step % every == 0:
                store.record(topic, "std_msgs/Float64", {"data": 1.0})
    monitor = make_monitor(shown=True)
    header = monitor.table.horizontalHeader()

    def click(column):
        x = header.sectionViewportPosition(column) + header.sectionSize(column) // 2
        qtbot.mouseClick(header.viewport(), Qt.MouseButton.LeftButton, pos=QPoint(x, header.height() // 2))
        return [row[TOPIC] for row in rows(monitor)]

    assert [row[TOPIC] for row in rows(monitor)] == ["/a", "/b", "/c"]  # by name at first
    assert [row[RATE] for row in rows(monitor)] == ["100.0", "4.0", "20.0"]
    assert click(RATE) == ["/b", "/c", "/a"]
    assert click(RATE) == ["/a", "/c", "/b"]
    assert click(TOPIC) == ["/a", "/b", "/c"]


# ----------------------------------------------------------------------------- the message tree

def test_selecting_a_topic_shows_its_message_as_a_tree(store, make_monitor, qtbot):
    store.record("/odom", ODOM, odometry(1.5))
    store.record("/joint_states", "sensor_msgs/JointState", joint_states([0.25, -1.0, 3]))
    monitor = make_monitor(shown=True)
    assert monitor.selected_topic() is None
    assert monitor.select_topic("/odom")
    assert monitor.selected_topic() == "/odom"
    assert monitor.table.selectionModel().selectedRows()[0].data() == "/odom"
    assert monitor.message_title.text() == "/odom" and monitor.message_type.text() == ODOM
    assert child_labels(monitor, "pose.pose.position") == ["x", "y", "z"]
    assert shown_value(monitor, "pose.pose.position.x") == "1.5"
    assert shown_value(monitor, "header.frame_id") == '"odom"'
    assert shown_value(monitor, "header.seq") == "0"

    # a click in the table selects too
    table = monitor.table
    index = next(table.model().index(row, 0) for row in range(table.model().rowCount())
                 if table.model().index(row, 0).data() == "/joint_states")
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=table.visualRect(index).center())
    assert monitor.selected_topic() == "/joint_states"
    assert child_labels(monitor, "position") == ["[0]", "[1]", "[2]"]
    assert [shown_value(monitor, f"position[{i}]") for i in range(3)] == ["0.25", "-1.0", "3"]
    assert shown_value(monitor, "name[1]") == '"wheel_right"'
    assert shown_value(monitor, "status[0].level") == "2"
    assert shown_value(monitor, "effort") == "[]"
    assert monitor.select_topic("/nowhere") is False


def test_a_topic_without_messages_says_so(store, make_monitor):
    monitor = make_monitor(graph=lambda: [("/scan", "sensor_msgs/LaserScan", 1)])
    monitor.select_topic("/scan")
    assert monitor.placeholder.text() == "No messages on /scan yet"
    store.record("/scan", "sensor_msgs/LaserScan", {"ranges": [1.0, 2.0]})
    monitor.refresh()
    assert shown_value(monitor, "ranges[1]") == "2.0"


def test_long_lists_are_cut_with_a_more_row(store, make_monitor):
    store.record("/scan", "sensor_msgs/LaserScan", {"ranges": [float(i) for i in range(720)]})
    monitor = make_monitor()
    monitor.select_topic("/scan")
    labels = child_labels(monitor, "ranges")
    assert len(labels) == LIST_LIMIT + 1
    assert labels[LIST_LIMIT - 1] == f"[{LIST_LIMIT - 1}]"
    assert labels[-1] == f"… {720 - LIST_LIMIT} more"
    store.record("/scan", "sensor_msgs/LaserScan", {"ranges": [float(i) for i in range(700)]})
    monitor.refresh()
    assert child_labels(monitor, "ranges")[-1] == f"… {700 - LIST_LIMIT} more"


def test_the_tree_keeps_its_expanded_branches_and_is_updated_in_place(store, make_monitor):
    store.record("/odom", ODOM, odometry(1.0))
    store.record("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
    monitor = make_monitor(shown=True)
    monitor.select_topic("/odom")
    for path in ("pose", "pose.pose", "pose.pose.position"):
        monitor.tree.expand(monitor.field_index(path))
    model = monitor.message_model
    structure_changes = []
    model.rowsInserted.connect(lambda *args: structure_changes.append("inserted"))
    model.rowsRemoved.connect(lambda *args: structure_changes.append("removed"))
    model.modelReset.connect(lambda: structure_changes.append("reset"))
    for step in range(5):
        store.record("/odom", ODOM, odometry(2.0 + step, seq=step))
        monitor.refresh()
    assert shown_value(monitor, "pose.pose.position.x") == "6.0"
    assert shown_value(monitor, "header.seq") == "4"
    assert structure_changes == []
    for path in ("pose", "pose.pose", "pose.pose.position"):
        assert monitor.tree.isExpanded(monitor.field_index(path)), path
    assert not monitor.tree.isExpanded(monitor.field_index("twist"))

    # and when the user comes back to the topic
    monitor.select_topic("/cmd_vel")
    monitor.select_topic("/odom")
    assert monitor.tree.isExpanded(monitor.field_index("pose.pose.position"))


def test_the_same_message_costs_the_tree_nothing(store, make_monitor):
    store.record("/odom", ODOM, odometry(1.0))
    monitor = make_monitor()
    monitor.select_topic("/odom")
    signals = []
    model = monitor.message_model
    for signal in (model.dataChanged, model.rowsInserted, model.rowsRemoved, model.layoutChanged):
        signal.connect(lambda *args: signals.append(args))
    calls = []
    original = model.show_message
    model.show_message = lambda *args: (calls.append(args), original(*args))
    for _ in range(3):
        monitor.refresh()
    assert (calls, signals) == ([], [])
    store.record("/odom", ODOM, odometry(1.0))  # a new message, same values: looked at, nothing redrawn
    monitor.refresh()
    assert len(calls) == 1 and signals == []


def test_only_rows_that_changed_are_redrawn(store, clock, make_monitor):
    store.record("/odom", ODOM, odometry(1.0))
    store.record("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
    monitor = make_monitor()
    changed = []
    monitor.table_model.dataChanged.connect(
        lambda first, last, roles: changed.append(monitor.table_model.topic_at(first.row())))
    monitor.refresh()
    assert changed == []
    clock.now += 0.02
    store.record("/odom", ODOM, odometry(2.0))
    monitor.refresh()
    assert changed == ["/odom"]  # /cmd_vel's age grew by less than the 0.1 s shown


def test_pause_freezes_the_display_while_the_store_records(store, clock, make_monitor, qtbot):
    store.record("/odom", ODOM, odometry(1.0))
    monitor = make_monitor(shown=True)
    monitor.select_topic("/odom")
    qtbot.mouseClick(monitor.pause_button, Qt.MouseButton.LeftButton)
    assert monitor.is_paused() and monitor.pause_button.text() == "Resume"
    before = rows(monitor)
    for step in range(20):
        clock.now += 0.1
        store.record("/odom", ODOM, odometry(9.0 + step))
    store.record("/new_topic", "std_msgs/Bool", {"data": True})
    monitor.refresh()
    with qtbot.waitSignal(monitor.findChild(QTimer).timeout, timeout=2000):
        pass  # its timer ticks too
    assert rows(monitor) == before
    assert shown_value(monitor, "pose.pose.position.x") == "1.0"
    assert store.value("/odom", "pose.pose.position.x") == 28.0  # the store kept recording

    qtbot.mouseClick(monitor.pause_button, Qt.MouseButton.LeftButton)
    assert not monitor.is_paused() and monitor.pause_button.text() == "Pause"
    assert shown_value(monitor, "pose.pose.position.x") == "28.0"
    assert "/new_topic" in [row[TOPIC] for row in rows(monitor)]


def test_a_1_khz_topic_stays_correct_and_cheap(store, clock, make_monitor):
    store.record("/battery_state", "sensor_msgs/BatteryState", {"percentage": 0.5})
    monitor = make_monitor()
    monitor.select_topic("/imu")  # not there yet
    monitor.select_topic("/battery_state")
    monitor.select_topic("/battery_state")
    for seq in range(10_000):
        clock.now += 0.001
        store.record("/imu", "sensor_msgs/Imu", {"header": {"seq": seq},
                                                 "angular_velocity": {"x": 0.0, "y": 0.0, "z": seq * 0.5}})
    assert monitor.select_topic("/imu")
    monitor.refresh()
    row = row_of(monitor, "/imu")
    assert float(row["rate"]) == pytest.approx(1000.0, rel=0.01)
    assert row["age"] == "0.0"
    assert shown_value(monitor, "header.seq") == "9999"
    assert shown_value(monitor, "angular_velocity.z") == "4999.5"
    index = monitor.table_model.index(monitor.table_model.row_of("/imu"), TOPIC)
    assert "10000 messages" in index.data(Qt.ItemDataRole.ToolTipRole)


def test_the_timer_runs_only_while_the_panel_is_visible(store, make_monitor, qtbot):
    monitor = make_monitor()
    assert not monitor._timer.isActive()
    monitor.show()
    qtbot.waitExposed(monitor)
    assert monitor._timer.isActive() and monitor._timer.interval() >= 100
    store.record("/odom", ODOM, odometry(1.0))
    qtbot.waitUntil(lambda: [row[TOPIC] for row in rows(monitor)] == ["/odom"], timeout=2000)
    monitor.hide()
    assert not monitor._timer.isActive()


def test_german_texts(store, make_monitor):
    store.record("/odom", ODOM, odometry(1.0))
    monitor = make_monitor(language="de")
    model = monitor.table.model()
    headers = [model.headerData(column, Qt.Orientation.Horizontal) for column in range(model.columnCount())]
    assert headers == ["Topic", "Typ", "Publisher", "Rate (Hz)", "Alter (s)"]
    assert monitor.pause_button.text() == "Anhalten"
    assert monitor.filter_edit.placeholderText() == "Topics oder Typen filtern…"
    monitor.select_topic("/odom")
    tree_headers = [monitor.message_model.headerData(column, Qt.Orientation.Horizontal) for column in range(2)]
    assert tree_headers == ["Feld", "Wert"]
    assert shown_value(monitor, "pose.covariance").startswith("(36) [0.0, 0.0")


# ----------------------------------------------------------------------------- dragging and plotting

def test_numeric_fields_drag_as_topic_and_path(store, make_monitor):
    store.record("/odom", ODOM, odometry(1.5))
    store.record("/joint_states", "sensor_msgs/JointState", joint_states([0.25, -1.0, 3]))
    monitor = make_monitor()
    monitor.select_topic("/odom")
    model = monitor.message_model
    x = monitor.field_index("pose.pose.position.x")
    assert model.flags(x) & Qt.ItemFlag.ItemIsDragEnabled
    assert model.flags(x.siblingAtColumn(1)) & Qt.ItemFlag.ItemIsDragEnabled
    assert model.mimeData([x]).text() == "/odom|pose.pose.position.x"
    assert model.mimeData([x.siblingAtColumn(1)]).text() == "/odom|pose.pose.position.x"
    assert "text/plain" in model.mimeTypes()
    frame = monitor.field_index("header.frame_id")
    assert not model.flags(frame) & Qt.ItemFlag.ItemIsDragEnabled
    assert model.mimeData([frame]) is None
    assert not model.flags(monitor.field_index("pose.pose")) & Qt.ItemFlag.ItemIsDragEnabled
    assert monitor.tree.dragEnabled()

    monitor.select_topic("/joint_states")
    assert monitor.message_model.mimeData([monitor.field_index("position[1]")]).text() == "/joint_states|position[1]"
    assert monitor.message_model.mimeData([monitor.field_index("status[0].level")]).text() == \
        "/joint_states|status[0].level"


def test_double_clicking_a_numeric_field_asks_for_a_plot(store, make_monitor, qtbot):
    store.record("/odom", ODOM, odometry(1.5))
    monitor = make_monitor(shown=True)
    monitor.select_topic("/odom")
    for path in ("pose", "pose.pose", "pose.pose.position"):
        monitor.tree.expand(monitor.field_index(path))
    tree = monitor.tree

    def double_click(path):
        index = monitor.field_index(path).siblingAtColumn(1)
        tree.scrollTo(index)
        centre = tree.visualRect(index).center()
        qtbot.mouseClick(tree.viewport(), Qt.MouseButton.LeftButton, pos=centre)  # a double-click starts with a click
        qtbot.mouseDClick(tree.viewport(), Qt.MouseButton.LeftButton, pos=centre)
        qtbot.mouseRelease(tree.viewport(), Qt.MouseButton.LeftButton, pos=centre)  # (mouseDClick leaves it down)

    with qtbot.waitSignal(monitor.sig_plot_requested, timeout=2000) as blocker:
        double_click("pose.pose.position.x")
    assert blocker.args == ["/odom", "pose.pose.position.x"]
    with qtbot.assertNotEmitted(monitor.sig_plot_requested):
        double_click("child_frame_id")
    assert not monitor.field_index("no.such.field").isValid()


# ----------------------------------------------------------------------------- a camera's history

def camera_image(number):
    """A 1 MB image as the ROS 2 helper hands it over: its pixels compact (array.array)."""
    return {"header": {"frame_id": "camera", "seq": number}, "height": 1024, "width": 1024, "encoding": "mono8",
            "data": array.array("B", bytes([number % 256]) * (1 << 20))}


@pytest.mark.parametrize("language, words", [("en", "only the last 1"), ("de", "nur die letzten 1")])
def test_the_monitor_says_when_the_byte_budget_cut_a_topics_history(store, make_monitor, language, words):
    store.record("/odom", ODOM, odometry(1.0))
    for number in range(40):
        store.record("/camera", "sensor_msgs/Image", camera_image(number))
    monitor = make_monitor(language=language, shown=True)
    assert monitor.select_topic("/odom")
    assert monitor.history_note.isHidden()
    assert monitor.select_topic("/camera")
    note = monitor.history_note.text()
    assert not monitor.history_note.isHidden()
    assert words in note and "/camera" in note and "16 MB" in note  # 15 or 16 messages of 1 MB
    assert shown_value(monitor, "data").startswith("(1048576) [39, 39, 39")  # a compact array, not 1 M rows
    labels = child_labels(monitor, "data")
    assert len(labels) == LIST_LIMIT + 1 and str((1 << 20) - LIST_LIMIT) in labels[-1]  # … and "N more"
    monitor.select_topic("/odom")
    assert monitor.history_note.isHidden()


def show_the_interfaces(qtbot, monitor):
    """Click the tab of the services and actions, as a person does."""
    bar = monitor.lists.tabBar()
    QTest.mouseClick(bar, Qt.MouseButton.LeftButton, pos=bar.tabRect(1).center())
    qtbot.waitUntil(monitor.interfaces.isVisible, timeout=3000)


def test_the_robots_services_and_actions_are_listed_beside_the_topics_filtered_with_them(qtbot, store):
    offers = [("action", "/move_base", "move_base_msgs/MoveBaseAction"), ("service", "/MMUI", "hobbit_msgs/Request")]
    monitor = TopicMonitor(store, graph=lambda: [], offers=lambda: offers)
    qtbot.addWidget(monitor)
    monitor.show()
    qtbot.waitExposed(monitor)
    assert monitor.lists.tabText(1) == "Services and actions"
    show_the_interfaces(qtbot, monitor)
    assert monitor.interfaces.title.text() == "Services and actions: 2"
    assert monitor.interfaces.names() == [("/MMUI", "service"), ("/move_base", "action")]
    assert monitor.interfaces.tree.topLevelItem(0).text(0) == "Service"
    monitor.filter_edit.setText("MoveBase")
    shown = [item.text(1) for item in (monitor.interfaces.tree.topLevelItem(row) for row in range(2))
             if not item.isHidden()]
    assert shown == ["/move_base"]
    with qtbot.waitSignal(monitor.sig_make_block_requested) as asked:
        monitor.interfaces.menu("/move_base", "action").actions()[0].trigger()
    assert asked.args == ["/move_base", "action"]


def test_without_services_and_actions_given_the_monitor_lists_topics_only(make_monitor):
    monitor = make_monitor(shown=True)
    assert not monitor.interfaces.isVisible() and not monitor.lists.tabBar().isVisible()


HOBBIT_TOPICS = [("/battery_state", "sensor_msgs/BatteryState", 1), ("/bumper", "std_msgs/Bool", 1),
                 ("/DiscreteMotionState", "std_msgs/String", 1), ("/joint_states", "sensor_msgs/JointState", 1),
                 ("/move_base_simple/goal", "geometry_msgs/PoseStamped", 1), ("/odom", ODOM, 1)]
DOCK_SIZES = [(806, 240), (1254, 320)]  # the Topic monitor in the window at 1280×800 and at 1920×1080


def drawn_text(table, row: int, column: int) -> str:
    """The cell's text as the table draws it: cut to the cell's room with the table's elide mode."""
    text = table.model().index(row, column).data()
    room = table.columnWidth(column) - 2 * (table.style().pixelMetric(QStyle.PixelMetric.PM_FocusFrameHMargin) + 1)
    return table.fontMetrics().elidedText(text, table.textElideMode(), room)


@pytest.mark.parametrize("size", DOCK_SIZES)
@pytest.mark.parametrize("language", ["en", "de"])
def test_topic_names_are_shown_whole_at_the_docks_sizes_and_a_longer_one_is_cut_at_its_end(
        qtbot, store, size, language):
    monitor = TopicMonitor(store, graph=lambda: HOBBIT_TOPICS, language=language, offers=lambda: [])
    qtbot.addWidget(monitor)
    monitor.resize(*size)
    monitor.show()
    qtbot.waitExposed(monitor)
    table = monitor.table
    assert [drawn_text(table, row, TOPIC) for row in range(6)] == [table.model().index(row, TOPIC).data()
                                                                    for row in range(6)]
    long_name = "/hobbit/perception/people_detector/tracked_persons_with_their_faces"
    monitor._graph = lambda: [*HOBBIT_TOPICS, (long_name, "std_msgs/String", 1)]
    monitor.refresh()
    row = next(row for row in range(7) if table.model().index(row, TOPIC).data() == long_name)
    drawn = drawn_text(table, row, TOPIC)
    assert drawn.endswith("…") and long_name.startswith(drawn[:-1]) and len(drawn) > 12, drawn
    assert drawn_text(table, row, 1) != ""   # the type keeps a place


@pytest.mark.parametrize("size", DOCK_SIZES)
def test_the_services_and_actions_show_at_least_four_rows_at_the_docks_sizes(qtbot, store, size):
    offers = [("service", f"/service_{number}", "std_srvs/Trigger") for number in range(6)]
    monitor = TopicMonitor(store, graph=lambda: HOBBIT_TOPICS, offers=lambda: offers)
    qtbot.addWidget(monitor)
    monitor.resize(*size)
    monitor.show()
    qtbot.waitExposed(monitor)
    show_the_interfaces(qtbot, monitor)
    tree = monitor.interfaces.tree
    whole = [row for row in range(tree.topLevelItemCount())
             if tree.viewport().rect().contains(tree.visualItemRect(tree.topLevelItem(row)))]
    assert len(whole) >= 4, (whole, tree.viewport().size())


def test_every_topic_a_program_publishes_on_the_simulator_says_rockly(qtbot, window):
    from rockly_desktop.robot.interrupt import Interrupt

    robot = window.robot()
    backend = robot.backend(Interrupt())
    backend.publish("/head/emo", "std_msgs/String", {"data": "HAPPY"})   # as a program's block does
    backend.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.0}})
    monitor = window.findChild(TopicMonitor)
    monitor.refresh()
    qtbot.waitUntil(lambda: "/head/emo" in [row[TOPIC] for row in rows(monitor)], timeout=5000)
    assert row_of(monitor, "/head/emo")["publishers"] == "1 (Rockly)"
    assert row_of(monitor, "/cmd_vel")["publishers"] == "1 (Rockly)"
    assert row_of(monitor, "/odom")["publishers"] == "1"   # the simulated robot's own
