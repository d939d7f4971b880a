"""The Plot panel: live curves of numeric fields from a real StateStore on a controlled clock."""
import csv
import math

import numpy as np
import pytest
from PySide6.QtCore import QMimeData, QPointF, Qt
from PySide6.QtGui import QDragEnterEvent, QDropEvent, QImage
from PySide6.QtWidgets import QApplication
from screenshots import screenshot

from rockly_desktop.core.field_paths import field_mime_text
from rockly_desktop.core.state_store import StateStore
from rockly_desktop.ui.docks.plot_panel import MAX_SAMPLES, MIN_Y_SPAN, PlotPanel

X = "pose.pose.position.x"
TURN = "twist.twist.angular.z"


class Clock:
    """The store's time, moved by the test."""

    def __init__(self, start=1000.0):
        self.now = start

    def __call__(self):
        return self.now


def odom(x, turn=0.0):
    return {"pose": {"pose": {"position": {"x": x, "y": 0.0}}}, "twist": {"twist": {"angular": {"z": turn}}}}


@pytest.fixture
def clock():
    return Clock()


@pytest.fixture
def store(clock):
    return StateStore(clock=clock)


@pytest.fixture
def panel(qtbot, store):
    panel = PlotPanel(store)
    qtbot.addWidget(panel)
    return panel


def feed(store, clock, values, step=0.1, topic="/odom"):
    """Record one /odom message per value (x = value, turn = -value), ``step`` seconds apart."""
    for value in values:
        clock.now += step
        store.record(topic, "nav_msgs/Odometry", odom(value, -value))


def drawn(panel, topic, path):
    """The (x, y) arrays given to the curve (before pyqtgraph clips and downsamples them for the screen)."""
    x, y = panel.curve_item(topic, path).getOriginalDataset()
    return (np.asarray([]), np.asarray([])) if x is None else (x, y)


def test_a_curve_gets_the_samples_with_time_relative_to_now(panel, store, clock):
    feed(store, clock, [1.0, 2.0])  # before the curve exists: still in the store's history
    assert panel.add_curve("/odom", X)
    feed(store, clock, [3.0, 4.5])
    clock.now += 0.5
    panel.refresh()
    x, y = drawn(panel, "/odom", X)
    assert y.tolist() == [1.0, 2.0, 3.0, 4.5]
    assert x == pytest.approx([-0.8, -0.7, -0.6, -0.5])
    assert panel.curves() == [("/odom", X)]
    assert not panel.add_curve("/odom", X), "the same field twice"


def test_only_new_samples_are_read_even_with_equal_timestamps(panel, store, clock):
    panel.add_curve("/odom", X)
    feed(store, clock, [1.0])
    store.record("/odom", "nav_msgs/Odometry", odom(2.0))  # same time as the one before
    panel.refresh()
    store.record("/odom", "nav_msgs/Odometry", odom(3.0))  # and again, after a refresh
    store.record("/odom", "nav_msgs/Odometry", {"pose": {}})  # no such field: skipped
    panel.refresh()
    panel.refresh()
    assert drawn(panel, "/odom", X)[1].tolist() == [1.0, 2.0, 3.0]


def test_two_curves_have_their_own_colours_and_legend_entries(panel, store, clock):
    panel.add_curve("/odom", X)
    panel.add_curve("/odom", TURN)
    feed(store, clock, [1.0, 2.0, 3.0])
    panel.refresh()
    assert drawn(panel, "/odom", X)[1].tolist() == [1.0, 2.0, 3.0]
    assert drawn(panel, "/odom", TURN)[1].tolist() == [-1.0, -2.0, -3.0]
    assert panel.legend.isVisible() and not panel.plot_item.titleLabel.isVisible()
    colours = {panel.curve_item("/odom", path).opts["pen"].color().name() for path in (X, TURN)}
    assert len(colours) == 2
    assert [label.text for _, label in panel.legend.items] == [f"/odom {X}", f"/odom {TURN}"]

    assert panel.remove_curve("/odom", X) and not panel.remove_curve("/odom", X)
    assert panel.curves() == [("/odom", TURN)]
    assert [label.text for _, label in panel.legend.items] == [f"/odom {TURN}"]
    panel.add_curve("/odom", X)
    assert panel.curve_item("/odom", X).opts["pen"].color() != panel.curve_item("/odom", TURN).opts["pen"].color()
    panel.clear()
    assert panel.curves() == [] and panel.legend.items == [] and panel.plot_item.listDataItems() == []
    assert not panel.legend.isVisible() and panel.plot_item.titleLabel.isVisible()
    assert panel.plot_item.titleLabel.text.startswith("Drop a field here")


def test_the_time_window_shows_the_last_seconds(panel, store, clock):
    assert [panel.window_box.itemText(i) for i in range(panel.window_box.count())] == ["10 s", "30 s", "60 s", "5 min"]
    panel.add_curve("/odom", X)
    feed(store, clock, range(400))  # 40 s at 10 Hz
    panel.set_window(10)
    panel.refresh()
    x, y = drawn(panel, "/odom", X)
    assert len(y) == 101 and y[0] == 299 and y[-1] == 399  # -10 s .. 0 s
    assert x.min() >= -10 - 1e-9 and x.max() <= 0
    assert panel.plot_item.viewRange()[0][0] < -10 < -9.5 and -0.5 < 0 < panel.plot_item.viewRange()[0][1]

    panel.window_box.setCurrentIndex(panel.window_box.findData(60))  # as a person picks it
    assert panel.window_seconds == 60
    assert len(drawn(panel, "/odom", X)[1]) == 400
    with pytest.raises(ValueError):
        panel.set_window(42)


def test_pause_freezes_the_view_while_the_store_keeps_recording(qtbot, panel, store, clock):
    panel.show()
    panel.add_curve("/odom", X)
    feed(store, clock, [1.0, 2.0])
    panel.refresh()
    assert panel.timer.isActive()

    qtbot.mouseClick(panel.pause_button, Qt.MouseButton.LeftButton)
    assert panel.paused and not panel.timer.isActive()
    assert panel.pause_button.text() == "Resume"
    before = drawn(panel, "/odom", X)
    feed(store, clock, [3.0, 4.0])
    clock.now += 5
    panel.refresh()
    after = drawn(panel, "/odom", X)
    assert after[0].tolist() == before[0].tolist() and after[1].tolist() == [1.0, 2.0]
    assert store.value("/odom", X) == 4.0
    panel.set_window(60)  # a paused plot can still be widened, around the frozen moment
    assert drawn(panel, "/odom", X)[1].tolist() == [1.0, 2.0]

    panel.resume()
    assert not panel.pause_button.isChecked() and panel.pause_button.text() == "Pause"
    assert panel.timer.isActive()
    assert drawn(panel, "/odom", X)[1].tolist() == [1.0, 2.0, 3.0, 4.0]
    assert drawn(panel, "/odom", X)[0][-1] == pytest.approx(-5.0)


def test_the_timer_runs_only_while_visible_unpaused_and_plotting(qtbot, panel, store, clock):
    assert panel.timer.interval() <= 34
    panel.show()
    assert not panel.timer.isActive(), "nothing to plot"
    panel.add_curve("/odom", X)
    assert panel.timer.isActive()
    feed(store, clock, [7.0])
    qtbot.waitUntil(lambda: drawn(panel, "/odom", X)[1].tolist() == [7.0], timeout=2000)
    panel.hide()
    assert not panel.timer.isActive()
    panel.show()
    assert panel.timer.isActive()
    panel.clear()
    assert not panel.timer.isActive()


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as file:
        return list(csv.reader(file))


def test_csv_export_has_one_row_per_shown_sample(panel, store, clock, tmp_path):
    panel.add_curve("/odom", X)
    panel.add_curve("/odom", TURN)
    store.record("/imu", "sensor_msgs/Imu", {"angular_velocity": {"z": 0.125}})
    panel.add_curve("/imu", "angular_velocity.z")
    feed(store, clock, [0.5, 1.25, 2.0], step=0.25)
    clock.now += 0.25
    store.record("/imu", "sensor_msgs/Imu", {"angular_velocity": {"z": -0.75}})

    path = tmp_path / "plot.csv"
    assert panel.export_csv(path) == 8
    assert read_csv(path) == [
        ["time", "topic", "field", "value"],
        ["0.000000", "/imu", "angular_velocity.z", "0.125"],
        ["0.250000", "/odom", X, "0.5"],
        ["0.250000", "/odom", TURN, "-0.5"],
        ["0.500000", "/odom", X, "1.25"],
        ["0.500000", "/odom", TURN, "-1.25"],
        ["0.750000", "/odom", X, "2.0"],
        ["0.750000", "/odom", TURN, "-2.0"],
        ["1.000000", "/imu", "angular_velocity.z", "-0.75"],
    ]


def test_csv_export_writes_only_what_the_window_shows(panel, store, clock, tmp_path):
    panel.add_curve("/odom", X)
    feed(store, clock, [math.pi, 1 / 3, 2.0], step=20.0)  # at -40 s, -20 s, 0 s
    panel.set_window(30)
    assert panel.export_csv(tmp_path / "a.csv") == 2
    assert read_csv(tmp_path / "a.csv")[1:] == [["0.000000", "/odom", X, repr(1 / 3)], ["20.000000", "/odom", X, "2.0"]]

    panel.pause()
    feed(store, clock, [5.0])
    panel.set_window(60)
    assert read_csv(tmp_path / "a.csv")[0] == ["time", "topic", "field", "value"]
    panel.export_csv(tmp_path / "b.csv")  # paused: the frozen view, nothing newer
    assert [row[3] for row in read_csv(tmp_path / "b.csv")[1:]] == [repr(math.pi), repr(1 / 3), "2.0"]

    panel.clear()
    assert panel.export_csv(tmp_path / "empty.csv") == 0
    assert read_csv(tmp_path / "empty.csv") == [["time", "topic", "field", "value"]]


def test_png_export_writes_the_plot(panel, store, clock, tmp_path):
    panel.resize(800, 400)
    panel.add_curve("/odom", X)
    feed(store, clock, [math.sin(i / 10) for i in range(300)])
    panel.refresh()
    path = tmp_path / "plot.png"
    panel.export_png(path)
    image = QImage(str(path))
    assert not image.isNull() and image.width() > 600 and image.height() > 250
    curve_colour = panel.curve_item("/odom", X).opts["pen"].color()
    colours, curve_pixels = set(), 0
    for y in range(0, image.height(), 2):
        for x in range(0, image.width(), 2):
            pixel = image.pixelColor(x, y)
            colours.add(pixel.rgb())
            curve_pixels += pixel.rgb() == curve_colour.rgb()
    assert len(colours) > 10, "not a blank image"
    assert curve_pixels > 100, "the curve is in the image"
    with pytest.raises(OSError):
        panel.export_png(tmp_path / "no-such-folder" / "plot.png")


def send_drag(panel, text):
    """Drag ``text`` over the panel and drop it, as Qt delivers a drag; True if the panel accepted it."""
    mime = QMimeData()
    mime.setText(text)
    position = QPointF(panel.width() / 2, panel.height() / 2)
    enter = QDragEnterEvent(position.toPoint(), Qt.DropAction.CopyAction, mime, Qt.MouseButton.LeftButton,
                            Qt.KeyboardModifier.NoModifier)
    QApplication.sendEvent(panel, enter)
    if not enter.isAccepted():
        return False
    drop = QDropEvent(position, Qt.DropAction.CopyAction, mime, Qt.MouseButton.LeftButton,
                      Qt.KeyboardModifier.NoModifier)
    QApplication.sendEvent(panel, drop)
    return drop.isAccepted()


def test_dropping_topic_and_field_adds_a_curve(panel, store, clock):
    panel.resize(600, 300)
    feed(store, clock, [1.5])
    # Drags over the graph land on the panel: the graphics view does not take them.
    assert panel.acceptDrops()
    assert not panel.plot_widget.acceptDrops() and not panel.plot_widget.viewport().acceptDrops()

    assert send_drag(panel, field_mime_text("/odom", X))
    assert panel.curves() == [("/odom", X)]
    assert drawn(panel, "/odom", X)[1].tolist() == [1.5]
    assert not send_drag(panel, "just some text")
    assert send_drag(panel, f"/odom|{TURN}\n/odom|{X}\n")
    assert panel.curves() == [("/odom", X), ("/odom", TURN)]


def test_the_add_form_offers_the_store_topics_and_their_numeric_fields(qtbot, panel, store, clock):
    feed(store, clock, [1.0])
    store.record("/scan", "sensor_msgs/LaserScan", {"ranges": [1.0, 2.0], "header": {"frame_id": "laser"}, "ok": True})
    panel.reload_topics()
    assert [panel.topic_box.itemText(i) for i in range(panel.topic_box.count())] == ["/odom", "/scan"]
    panel.topic_box.setCurrentText("/scan")
    model = panel.field_completer.model()
    assert [model.index(i, 0).data() for i in range(model.rowCount())] == ["ranges[0]", "ranges[1]"]

    panel.topic_box.setCurrentText("/odom")
    panel.field_edit.setText(X)
    qtbot.mouseClick(panel.add_form_button, Qt.MouseButton.LeftButton)
    assert panel.curves() == [("/odom", X)] and panel.field_edit.text() == ""
    panel.field_edit.setText("   ")
    qtbot.mouseClick(panel.add_form_button, Qt.MouseButton.LeftButton)
    assert panel.curves() == [("/odom", X)]


def test_german_labels(qtbot, store):
    panel = PlotPanel(store, "de")
    qtbot.addWidget(panel)
    assert panel.pause_button.text() == "Anhalten"
    assert panel.clear_button.text() == "Leeren"
    assert panel.add_button.text() == "Hinzufügen…"
    assert panel.export_button.text() == "Exportieren…"
    assert panel.window_label.text() == "Zeige die letzten"
    assert panel.add_form_button.text() == "Hinzufügen"
    assert panel.field_edit.placeholderText() == "z. B. pose.pose.position.x"
    assert panel.export_csv_action.text() == "Daten als CSV speichern…"
    assert panel.plot_item.getAxis("bottom").labelText == "Zeit"
    assert panel.plot_item.getAxis("left").labelText == "Wert"
    panel.pause()
    assert panel.pause_button.text() == "Weiter"


def test_memory_stays_bounded_after_100000_samples(qtbot, clock):
    store = StateStore(history=2000, clock=clock)
    panel = PlotPanel(store, max_samples=5000)
    qtbot.addWidget(panel)
    panel.set_window(300)
    panel.add_curve("/odom", X)
    buffer = panel.buffer("/odom", X)
    capacity = buffer.capacity
    for chunk in range(100):  # 100,000 samples at 1 kHz, read every 1,000
        feed(store, clock, range(chunk * 1000, chunk * 1000 + 1000), step=0.001)
        panel.refresh()
        assert len(buffer) <= buffer.bound == 5000
    assert buffer.capacity == capacity, "no new memory"
    assert buffer.values.tolist() == list(range(95000, 100000))
    assert len(drawn(panel, "/odom", X)[1]) == 5000

    # The default bound holds 5 minutes at 1 kHz; older samples go anyway (no window shows them).
    slow = PlotPanel(store)
    qtbot.addWidget(slow)
    slow.add_curve("/odom", X)
    for chunk in range(100):  # 100,000 samples at 100 Hz: 1,000 s
        feed(store, clock, range(chunk * 1000, chunk * 1000 + 1000), step=0.01)
        slow.refresh()
    assert slow.buffer("/odom", X).bound == MAX_SAMPLES
    kept = slow.buffer("/odom", X)
    assert 29999 <= len(kept) <= 30001 and kept.times[-1] - kept.times[0] <= 300  # the last 300 s


def test_a_1khz_minute_is_kept_whole_but_drawn_downsampled(qtbot, clock):
    """60 s at 1 kHz on two curves: every sample is kept, a few thousand points are drawn.

    Its speed is measured in benchmarks/state.py.
    """
    store = StateStore(history=2000, clock=clock)
    panel = PlotPanel(store)
    qtbot.addWidget(panel)
    panel.resize(800, 400)
    panel.show()
    panel.set_window(60)
    panel.add_curve("/odom", X)
    panel.add_curve("/odom", TURN)
    for _frame in range(1800):
        for _ in range(33):
            clock.now += 0.001
            store.record("/odom", "nav_msgs/Odometry", odom(math.sin(clock.now), math.cos(clock.now * 7)))
        panel.refresh()
        panel.plot_widget.viewport().repaint()
    item = panel.curve_item("/odom", X)
    assert len(item.getOriginalDataset()[0]) == 59400
    assert len(item.curve.getData()[0]) < 8000, "downsampled for the screen"


def test_a_value_that_stops_changing_keeps_a_readable_range_not_floating_point_noise(qtbot, panel, store, clock):
    panel.resize(600, 300)
    panel.show()
    panel.add_curve("/odom", X)
    feed(store, clock, [0.1 + 0.2, 0.3] * 20)  # the same value but for its last bit
    panel.refresh()
    assert not panel.plot_widget.grab().isNull()  # drawn: the view took the curve's range
    low, high = panel.plot_item.getViewBox().viewRange()[1]
    assert low < 0.3 < high and high - low >= MIN_Y_SPAN
    assert panel.plot_item.getAxis("left").autoSIPrefixScale == 1  # no "(x1e-15)" or "(x1000)" beside the axis
    screenshot(panel, "plot_of_a_constant_value")
