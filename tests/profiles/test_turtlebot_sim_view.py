"""The TurtleBot's simulator view (profiles/turtlebot/rockly_turtlebot/view/): it draws what a snapshot says.

Snapshots come from the real simulator (and a few hand-made odd ones); the view is grabbed
offscreen and its pixels are looked at.
"""
import math
import struct
import sys

import pytest
from profile_copies import REPO, SHARED_TOOLBOXES
from PySide6.QtCore import QRect
from PySide6.QtGui import QColor, QImage

from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld

PROFILE = load_profile(REPO / "profiles" / "turtlebot", SHARED_TOOLBOXES)
TurtleBotSimView = PROFILE.load_object("simulator_view")
SimTurtleBot = PROFILE.load_object("simulator")
TurtleBot = PROFILE.load_object("api")
view_module = sys.modules[TurtleBotSimView.__module__.rpartition(".")[0]]  # the view package
PLATE, PANEL_BG = view_module.PLATE, view_module.PANEL_BG


@pytest.fixture(scope="module")
def snapshots():
    """Real snapshots: at the start, after driving up to a box and turning, and bumped against a wall."""
    world = SimWorld()
    sim = SimTurtleBot(world, speed=20)
    sim.start()
    robot = TurtleBot(SimBackend(world, Interrupt()))
    taken = {"start": sim.snapshot()}
    robot.drive(1.2)
    robot.turn(60, "left")
    taken["driven"] = sim.snapshot()
    robot.turn(150, "right")
    try:
        robot.drive(3)
    except Exception:
        pass
    taken["bumped"] = sim.snapshot()
    sim.shutdown()
    assert taken["bumped"]["bumped"] is True
    return taken


@pytest.fixture
def make_view(qtbot):
    def make(snapshot, width=640, height=480, language="en"):
        view = TurtleBotSimView(language=language)
        qtbot.addWidget(view)
        view.resize(width, height)
        view.set_snapshot(snapshot)
        return view
    return make


def pixels(image):
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    data = bytes(image.constBits())
    return struct.unpack(f"<{len(data) // 4}I", data), image.width()


def grab(view, rect=None):
    return (view.grab(rect) if rect is not None else view.grab()).toImage()


def differing(a, b):
    pa, _ = pixels(a)
    pb, _ = pixels(b)
    assert len(pa) == len(pb)
    return sum(1 for x, y in zip(pa, pb, strict=True) if x != y)


def centroid(image, colour):
    values, width = pixels(image)
    target = colour.rgb() & 0xFFFFFF
    xs = ys = n = 0
    for index, value in enumerate(values):
        if value & 0xFFFFFF == target:
            xs += index % width
            ys += index // width
            n += 1
    assert n > 0, "colour not found"
    return xs / n, ys / n, n


def warm_pixels(image):
    """Pixels of a strong red-to-orange: the laser's colour for something close."""
    values, _ = pixels(image)
    count = 0
    for value in values:
        colour = QColor.fromRgb(value)
        red = colour.hsvHueF() < 0.09 or colour.hsvHueF() > 0.97
        if colour.hsvSaturationF() > 0.6 and colour.valueF() > 0.6 and red:
            count += 1
    return count


def test_each_snapshot_renders_a_colourful_room_robot_and_panel(make_view, snapshots):
    images = {}
    for name, snapshot in snapshots.items():
        view = make_view(snapshot)
        image = grab(view)
        values, _ = pixels(image)
        assert len(set(values)) > 300, name
        background = PANEL_BG.rgb() & 0xFFFFFF
        assert sum(1 for v in values if v & 0xFFFFFF == background) < 0.3 * len(values), name
        images[name] = image
    assert differing(images["start"], images["driven"]) > 2000
    assert differing(images["driven"], images["bumped"]) > 2000


@pytest.mark.parametrize("name", ["start", "driven", "bumped"])
def test_the_robot_is_drawn_where_the_snapshot_says(make_view, snapshots, name):
    snapshot = snapshots[name]
    view = make_view(snapshot)
    map_rect = view.map_rect()
    x, y, n = centroid(grab(view, map_rect), PLATE)
    assert n > 60
    where = view.map_to_widget(snapshot["x"], snapshot["y"])
    assert math.hypot(map_rect.left() + x - where.x(), map_rect.top() + y - where.y()) < 6


def test_the_robot_moves_on_screen_as_it_moves_in_the_room(make_view, snapshots):
    view = make_view(dict(snapshots["start"], x=0.0, y=0.0))
    x0, y0, _ = centroid(grab(view, view.map_rect()), PLATE)
    view.set_snapshot(dict(snapshots["start"], x=2.0, y=1.0))
    x1, y1, _ = centroid(grab(view, view.map_rect()), PLATE)
    scale = view.map_to_widget(1, 0).x() - view.map_to_widget(0, 0).x()
    assert (x1 - x0, y1 - y0) == (pytest.approx(2 * scale, abs=4), pytest.approx(-1 * scale, abs=4))


def test_the_laser_scan_is_drawn_warm_where_things_are_close(make_view, snapshots):
    close = snapshots["bumped"]                 # the wall is right at the robot
    view = make_view(dict(close, boxes=[]))
    with_scan = grab(view, view.map_rect())
    view.set_snapshot(dict(close, boxes=[], scan=[]))
    without_scan = grab(view, view.map_rect())
    assert differing(with_scan, without_scan) > 3000
    assert warm_pixels(with_scan) > warm_pixels(without_scan) + 30


def test_far_things_are_drawn_cooler_than_near_ones():
    palette = sys.modules[view_module.__name__ + ".palette"]
    hues = [palette.distance_colour(d).hsvHueF() for d in (0.12, 0.5, 1.0, 1.5, 2.0, 3.0)]
    assert hues == sorted(hues) and hues[0] < 0.05 and hues[-1] > 0.5   # red when close, blue when far


@pytest.mark.parametrize("size", [(200, 150), (320, 240), (360, 300), (1600, 1200), (300, 700), (1200, 260)])
def test_scales_to_small_large_and_odd_sizes(make_view, snapshots, size):
    view = make_view(snapshots["driven"], *size)
    image = grab(view)
    assert (image.width(), image.height()) == size
    values, _ = pixels(image)
    assert len(set(values)) > 50
    assert QRect(0, 0, *size).contains(view.map_rect())
    where = view.map_to_widget(snapshots["driven"]["x"], snapshots["driven"]["y"])
    assert view.map_rect().contains(int(where.x()), int(where.y()))


def test_language_is_english_or_german_and_changes_the_words(make_view, snapshots):
    english = make_view(snapshots["driven"], language="en")
    german = make_view(snapshots["driven"], language="de")
    assert (english.language, german.language) == ("en", "de")
    assert TurtleBotSimView(language="xx").language == "en"
    assert differing(grab(english), grab(german)) > 100
    german.language = "en"
    assert differing(grab(english), grab(german)) == 0


def test_odd_snapshots_draw_without_failing(make_view):
    view = make_view({"x": "here", "y": math.nan, "theta": None, "scan": [None, "x", math.nan, -math.inf, 1e9],
                      "boxes": [(1, 2), "box", (2, 2, 1, 1), (0.5, 0.5, 0.8, 0.8)], "trail": 5, "room": None,
                      "battery": -40, "voltage": "lots", "time": math.inf, "bumped": "yes", "linear": 1e9})
    assert len(set(pixels(grab(view))[0])) > 50
    view.set_snapshot(None)
    assert view.snapshot()["x"] == 0.0
    assert len(set(pixels(grab(view))[0])) > 50


def test_size_hints():
    view = TurtleBotSimView()
    assert view.minimumSizeHint().width() <= 320 and view.minimumSizeHint().height() <= 240
    assert view.sizeHint().width() >= 320


def test_ahead_is_one_sector_in_the_commands_the_view_and_the_robot_state_panel(qtbot, make_view):
    from rockly_desktop.core.state_store import StateStore
    from rockly_desktop.ui.docks.state_panels import StatePanels

    world = SimWorld()
    sim = SimTurtleBot(world, speed=20)
    sim.start()
    robot = TurtleBot(SimBackend(world, Interrupt()))
    robot.drive(1.2)
    robot.turn(20, "left")      # a box's corner to the right of the beam straight ahead
    sim.shutdown()              # one moment: the snapshot and the last scan agree
    snapshot, scan = sim.snapshot(), world.latest("/scan")
    assert snapshot["scan"] == scan["ranges"]
    store = StateStore()
    store.record("/scan", "sensor_msgs/LaserScan", scan)
    panels = StatePanels(PROFILE.state_panels, "en")
    qtbot.addWidget(panels)
    panels.set_store(store)
    ahead = robot.distance("ahead")
    assert math.isfinite(ahead) and ahead < scan["ranges"][0]   # the sector sees what one beam misses
    assert panels.values()["Nearest obstacle ahead"] == f"{ahead:.2f} m"
    assert make_view(snapshot).panel_texts()["ahead"] == f"ahead {ahead:.2f} m"


def test_turning_is_in_degrees_per_second(make_view):
    view = make_view({"angular": 0.5}, language="de")
    assert view.panel_texts()["turning"] == "+29 °/s"
    assert view.panel_texts()["driving"] == "0,00 m/s"
