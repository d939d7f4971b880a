"""HOBBIT's simulator view (profiles/hobbit/rockly_hobbit/view/): it draws what a snapshot says, at any size."""
import itertools
import math
import struct
import sys

import pytest
from profile_copies import HOBBIT_DIR, SHARED_TOOLBOXES
from PySide6.QtCore import QRect, QRectF
from PySide6.QtGui import QFontMetricsF, QImage

from rockly_desktop import sdk_view
from rockly_desktop.profiles.profile import load_profile


def _load_sim_view_module():
    """Import the view package the way Rockly does (through the profile: it reads the house's data)."""
    PROFILE.simulator_view_class()
    return sys.modules["rockly_hobbit.view"]


PROFILE = load_profile(HOBBIT_DIR, SHARED_TOOLBOXES)
sim_view = _load_sim_view_module()
HobbitSimView = sim_view.HobbitSimView


def snapshot(**changes):
    return dict(sim_view.DEFAULT_SNAPSHOT, **changes)


@pytest.fixture
def make_view(qtbot):
    def make(width=640, height=480, language="en", **changes):
        view = HobbitSimView(language=language)
        qtbot.addWidget(view)
        view.set_animation_enabled(False)
        view.resize(width, height)
        view.set_snapshot(snapshot(**changes))
        return view
    return make


def pixels(image):
    """The image's pixels as 0xAARRGGBB ints, row by row, and its width."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    data = bytes(image.constBits())
    return struct.unpack(f"<{len(data) // 4}I", data), image.width()


def grab(view, rect=None):
    return (view.grab(rect) if rect is not None else view.grab()).toImage()


def differing(a, b):
    """How many pixels differ between two images of the same size."""
    pa, _ = pixels(a)
    pb, _ = pixels(b)
    assert len(pa) == len(pb)
    return sum(1 for x, y in zip(pa, pb, strict=True) if x != y)


def centroid(image, color):
    """Mean (x, y) of the pixels of exactly ``color``, and how many there are."""
    values, width = pixels(image)
    target = color.rgb() & 0xFFFFFF
    xs = ys = n = 0
    for index, value in enumerate(values):
        if value & 0xFFFFFF == target:
            xs += index % width
            ys += index // width
            n += 1
    assert n > 0, "colour not found"
    return xs / n, ys / n, n


# --- it draws ---------------------------------------------------------------------------------

def test_default_snapshot_draws_a_colourful_room_robot_and_panel(make_view):
    view = make_view()
    values, _ = pixels(grab(view))
    assert len(set(values)) > 200
    background = sim_view.PANEL_BG.rgb() & 0xFFFFFF
    assert sum(1 for v in values if v & 0xFFFFFF == background) < 0.3 * len(values)
    _, _, base_pixels = centroid(grab(view), sim_view.BASE_COLOR)
    assert base_pixels > 100


def test_size_hints_allow_320x240_and_an_unknown_language_falls_back_to_english(make_view):
    view = make_view()
    assert view.minimumSizeHint().width() <= 320 and view.minimumSizeHint().height() <= 240
    assert view.sizeHint().width() >= 320
    assert view.language == "en"
    assert HobbitSimView(language="de").language == "de"
    assert HobbitSimView(language="xx").language == "en"


@pytest.mark.parametrize("size", [(200, 150), (320, 240), (360, 300), (1600, 1200), (300, 700), (1200, 260)])
def test_at_small_large_and_odd_sizes_the_eyes_and_the_map_are_inside_the_view(make_view, size):
    view = make_view(*size, emotion="WONDERING", arm="floor", gripper="open", turntable="out", nav_goal=(3, -1),
                     trail=[(i * 0.05, 0.0) for i in range(60)], notices=["hello", "SOS call started"],
                     tablet={"kind": "D_YES_NO", "text": "Shall I bring you the red cup?"})
    image = grab(view)
    assert (image.width(), image.height()) == size
    values, _ = pixels(image)
    assert len(set(values)) > 20
    assert view.eyes_rect().intersects(QRect(0, 0, *size))
    assert QRect(0, 0, *size).contains(view.map_rect())


def test_each_emotion_draws_its_own_eyes(make_view):
    view = make_view()
    rect = view.eyes_rect()
    assert rect.width() > 100 and rect.height() > 50
    images = {}
    for emotion in sim_view.EMOTIONS:
        view.set_snapshot(snapshot(emotion=emotion))
        images[emotion] = grab(view, rect)
    area = rect.width() * rect.height()
    for a, b in itertools.combinations(sim_view.EMOTIONS, 2):
        assert differing(images[a], images[b]) > 0.01 * area, f"{a} and {b} look alike"


def test_unknown_emotion_is_drawn_as_neutral(make_view):
    view = make_view(emotion="NEUTRAL")
    neutral = grab(view, view.eyes_rect())
    view.set_snapshot(snapshot(emotion="GRUMPY"))
    assert differing(neutral, grab(view, view.eyes_rect())) == 0


# --- the robot ----------------------------------------------------------------------------------

def test_robot_is_drawn_where_x_and_y_say(make_view):
    view = make_view(x=0.0, y=0.0)
    x0, y0, _ = centroid(grab(view), sim_view.BASE_COLOR)
    view.set_snapshot(snapshot(x=2.0, y=0.0))
    x1, y1, _ = centroid(grab(view), sim_view.BASE_COLOR)
    expected = view.map_to_widget(2.0, 0.0).x() - view.map_to_widget(0.0, 0.0).x()
    assert expected > 50
    assert x1 - x0 == pytest.approx(expected, abs=3)
    assert y1 == pytest.approx(y0, abs=2)
    view.set_snapshot(snapshot(x=0.0, y=1.0))
    x2, y2, _ = centroid(grab(view), sim_view.BASE_COLOR)
    assert x2 == pytest.approx(x0, abs=2)
    assert y2 < y0 - 40   # map y points up


def test_the_yellow_front_follows_theta(make_view):
    view = make_view(x=1.0, y=0.0, theta=0.0, head="up_center")
    center = view.map_to_widget(1.0, 0.0)
    image = grab(view, view.map_rect())
    offset = view.map_rect().topLeft()
    fx, fy, _ = centroid(image, sim_view.BUMPER)
    assert fx + offset.x() > center.x() + 5
    view.set_snapshot(snapshot(x=1.0, y=0.0, theta=math.pi / 2, head="up_center"))
    fx, fy, _ = centroid(grab(view, view.map_rect()), sim_view.BUMPER)
    assert fy + offset.y() < center.y() - 5


def test_arm_pose_gripper_turntable_head_and_trail_change_the_picture(make_view):
    view = make_view(x=1.0)
    rect = view.map_rect()
    base = grab(view, rect)
    changes = [
        {"arm": "floor"}, {"arm": "candle"}, {"arm": "tray"},
        {"arm": "home", "arm_target": "floor", "arm_progress": 0.5},
        {"gripper": "open"}, {"turntable": "out", "turntable_angle": 30.0},
        {"head": "center_left"}, {"head": "down_center"}, {"head": "to_grasp"},
        {"trail": [(i * 0.02, 0.5) for i in range(100)]}, {"nav_goal": (3.0, -1.0)},
        {"linear": 0.3, "motion": "moving"}, {"angular": 0.5, "motion": "turning"},
    ]
    for change in changes:
        view.set_snapshot(snapshot(x=1.0, **change))
        assert differing(base, grab(view, rect)) > 20, change


def test_arm_interpolates_between_poses(make_view):
    view = make_view(x=1.0, arm="home")
    rect = view.map_rect().adjusted(0, 0, -2, 0)   # the details card's edge (its height follows its words)
    home = grab(view, rect)
    view.set_snapshot(snapshot(x=1.0, arm="floor"))
    floor = grab(view, rect)
    view.set_snapshot(snapshot(x=1.0, arm="home", arm_target="floor", arm_progress=0.5))
    middle = grab(view, rect)
    view.set_snapshot(snapshot(x=1.0, arm="home", arm_target="floor", arm_progress=1.0))
    assert differing(floor, grab(view, rect)) == 0
    assert differing(home, middle) > 20 and differing(floor, middle) > 20


def test_visible_area_grows_to_keep_the_robot_and_goal_in_sight(make_view):
    view = make_view()
    rect = view.map_rect()
    origin = view.map_to_widget(0.0, 0.0)
    view.set_snapshot(snapshot(x=9.0, y=-4.0, nav_goal=(-4.0, 5.0)))
    assert view.map_to_widget(0.0, 0.0) != origin
    for x, y in ((9.0, -4.0), (-4.0, 5.0)):
        assert rect.contains(view.map_to_widget(x, y).toPoint())


# --- panel: tablet, battery, notices -------------------------------------------------------------

@pytest.mark.parametrize("kind", ["D_PLAIN", "D_OK", "D_YES_NO", "D_NAME"])
def test_tablet_text_with_newlines_quotes_and_unicode_is_shown(make_view, kind):
    view = make_view()
    without = grab(view)
    text = 'Hallo "Anna"!\nIt\'s 5 °C – schön ☀ 日本語 😀\n\n\ttab\r\nend \x07bell'
    view.set_snapshot(snapshot(tablet={"kind": kind, "text": text}))
    assert differing(without, grab(view)) > 200


def test_waiting_tablet_shows_an_answer_hint(make_view):
    text = "Shall I bring you the red cup?"
    view = make_view(tablet={"kind": "D_PLAIN", "text": text})
    plain = grab(view)
    for kind in ("D_YES_NO", "D_OK", "D_NAME"):
        view.set_snapshot(snapshot(tablet={"kind": kind, "text": text}))
        assert differing(plain, grab(view)) > 200, kind


class _TextMeasuringPainter:
    """A real QPainter that notes, for every ``drawText(rect, flags, text)``, where that text's laid-out
    lines lie (``QFontMetricsF.boundingRect`` in the painter's font at that moment)."""

    def __init__(self, painter, drawn):
        self._painter, self._drawn = painter, drawn

    def __getattr__(self, name):
        return getattr(self._painter, name)

    def drawText(self, *args):
        assert len(args) == 3 and isinstance(args[0], QRectF), f"text drawn without a rect to measure: {args}"
        rect, flags, text = args
        bounds = QFontMetricsF(self._painter.font()).boundingRect(rect, int(getattr(flags, "value", flags)), text)
        self._drawn.append((text, bounds))
        self._painter.drawText(*args)


@pytest.fixture
def tablet_texts(monkeypatch):
    """``{"rect": the tablet's rect, "drawn": [(text, its bounding rect)]}`` of the view's latest paint."""
    panel = sys.modules["rockly_hobbit.view.panel"]
    paint_tablet, seen = panel.paint_tablet, {}

    def measured(painter, scene, rect, layout):
        seen.update(rect=QRectF(rect), drawn=[])
        paint_tablet(_TextMeasuringPainter(painter, seen["drawn"]), scene, rect, layout)

    monkeypatch.setattr(panel, "paint_tablet", measured)
    return seen


LONG_TABLET_TEXT = "word " * 400 + "x" * 300


@pytest.mark.parametrize("kind", ["D_PLAIN", "D_YES_NO", "D_OK", "D_NAME"])
def test_every_line_of_a_long_tablet_text_lies_inside_the_tablet_at_every_size(make_view, tablet_texts, kind):
    """No drawn line is wider or lower than the tablet's screen (its bezel is at least 5 px), at any size."""
    sizes = itertools.product((200, 320, 460, 640, 1024, 1600), (150, 240, 480, 700, 1200))
    for size in sizes:
        tablet_texts.clear()
        grab(make_view(*size, tablet={"kind": kind, "text": LONG_TABLET_TEXT}))
        assert tablet_texts, f"no tablet drawn at {size}"
        screen = tablet_texts["rect"].adjusted(5, 5, -5, -5)
        drawn = tablet_texts["drawn"]
        assert any(text.startswith("word word") for text, _bounds in drawn), (size, drawn)
        for text, bounds in drawn:
            assert screen.adjusted(-0.5, -0.5, 0.5, 0.5).contains(bounds), \
                f"at {size}, {text[:30]!r}… lies at {bounds}, outside the tablet's screen {screen}"


def test_german_texts_differ_from_english_and_switching_back_draws_english_again(make_view):
    tablet = {"kind": "D_YES_NO", "text": "Soll ich kommen?"}
    english = grab(make_view(tablet=tablet))
    view = make_view(language="de", tablet=tablet)
    german = grab(view)
    assert differing(english, german) > 50
    view.language = "en"
    assert differing(english, grab(view)) == 0


def test_numbers_on_the_map_use_the_languages_decimal_mark():
    """As the Robot state panels write them: 1,60 in German, 1.60 in English."""
    motion_label, texts, decimal = sim_view.map_painter._motion_label, sim_view.texts.TEXTS, sdk_view.decimal
    snapshot = {"motion": "moving", "linear": -0.3}
    assert motion_label(snapshot, texts["de"], "de") == ("moving", "fährt  0,30 m/s")
    assert motion_label(snapshot, texts["en"], "en") == ("moving", "driving  0.30 m/s")
    assert (decimal(1.6, 2, "de"), decimal(1.6, 2, "en"), decimal(12.25, 1, "de")) == ("1,60", "1.60", "12,2")


def test_battery_levels_and_sos_notice_change_the_panel(make_view):
    view = make_view(battery=80)
    full = grab(view)
    view.set_snapshot(snapshot(battery=30))
    amber = grab(view)
    view.set_snapshot(snapshot(battery=5))
    red = grab(view)
    assert differing(full, amber) > 20 and differing(amber, red) > 20
    view.set_snapshot(snapshot(notices=["Arm moved"]))
    plain = grab(view)
    view.set_snapshot(snapshot(notices=["Arm moved", "SOS call started"]))
    sos = grab(view)
    _, _, red_pixels = centroid(sos, sim_view.SOS)
    assert red_pixels > 200
    assert differing(plain, sos) > 200


def test_malformed_snapshot_values_are_drawn_without_raising(make_view):
    view = make_view()
    for weird in (
        {"x": float("nan"), "y": "far", "theta": None, "battery": "full", "volume": -5},
        {"trail": [(1,), None, (2, 3), "xy", (float("inf"), 0)], "nav_goal": "kitchen"},
        {"emotion": None, "head": "sideways", "arm": None, "arm_target": "moon", "arm_progress": 7},
        {"tablet": "just text", "notices": None}, {"tablet": {"kind": None, "text": None}, "notices": "SOS!"},
        {"trail": 5, "notices": [1, 2, None]}, {},
    ):
        view.set_snapshot(snapshot(**weird))
        grab(view)
    view.set_snapshot(None)
    grab(view)


# --- animation ------------------------------------------------------------------------------------

def test_animation_eases_toward_the_latest_snapshot(qtbot):
    view = HobbitSimView()
    qtbot.addWidget(view)
    view.resize(640, 480)
    view.set_snapshot(snapshot(x=0.0))
    view.show()
    qtbot.waitExposed(view)
    view.set_snapshot(snapshot(x=1.0, theta=1.0))
    assert view.displayed_pose()[0] < 0.5
    qtbot.waitUntil(lambda: 0.05 < view.displayed_pose()[0] < 0.95, timeout=2000)
    qtbot.waitUntil(lambda: view.displayed_pose() == (1.0, 0.0, 1.0), timeout=3000)


def test_far_jumps_and_disabled_animation_are_drawn_at_once(qtbot):
    view = HobbitSimView()
    qtbot.addWidget(view)
    view.show()
    qtbot.waitExposed(view)
    view.set_snapshot(snapshot(x=4.0))
    assert view.displayed_pose()[0] == 4.0      # a teleport, not a drive
    view.set_snapshot(snapshot(x=4.5))
    view.set_animation_enabled(False)
    assert view.displayed_pose()[0] == 4.5
    view.set_snapshot(snapshot(x=3.9, theta=-2.0))
    assert view.displayed_pose() == (3.9, 0.0, -2.0)


# --- words for people, never cut off -------------------------------------------------------------

def _joined(lines):
    return " ".join(line.strip() for line in lines)


def test_details_name_places_and_directions_in_german_and_never_cut_them(make_view):
    view = make_view(640, 560, language="de", head="center_center", arm="home", arm_target="table",
                     arm_progress=0.5, turntable="stored")
    details = dict((label, _joined(values)) for label, values in view.panel_texts()["details"])
    assert details == {"Arm": "eingeklappt → bereit für den Tisch", "Greifer": "zu", "Kopf": "geradeaus",
                       "Drehteller": "eingefahren"}
    view.set_snapshot(snapshot(head="littledown_center", arm="candle"))
    details = dict((label, _joined(values)) for label, values in view.panel_texts()["details"])
    assert (details["Kopf"], details["Arm"]) == ("etwas nach unten", "gerade nach oben")
    view.language = "en"
    details = dict((label, _joined(values)) for label, values in view.panel_texts()["details"])
    assert (details["Head"], details["Arm"]) == ("a little down", "straight up")


def test_an_unknown_head_position_is_shown_as_it_comes(make_view):
    view = make_view(640, 560, head="somewhere_new")
    assert ("Head", ["somewhere_new"]) in view.panel_texts()["details"]


def test_a_question_is_shown_whole_even_when_the_tablet_is_small(make_view):
    question = "What is your favourite colour when you think of summer?"
    view = make_view(460, 289, tablet={"kind": "D_YES_NO", "text": question})
    lines = view.panel_texts()["tablet"]
    assert _joined(lines).startswith(question) and "…" not in _joined(lines)


def test_a_waiting_tablet_says_where_to_answer(make_view):
    view = make_view(640, 480, language="de", tablet={"kind": "D_YES_NO", "text": "Soll ich kommen?"})
    assert "".join(view.panel_texts()["tablet"]) == "Soll ich kommen?Antworte im Tablet-Fenster"


def test_notices_are_shown_whole_in_two_lines(make_view):
    view = make_view(460, 289, language="de", notices=["Etwas ist schiefgegangen"])
    assert [_joined(lines) for lines in view.panel_texts()["notices"]] == ["Etwas ist schiefgegangen"]
