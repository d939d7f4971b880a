"""The simulated HOBBIT, drawn: a room seen from above with the robot in it, and a panel
with HOBBIT's eyes, battery, tablet and the latest notices.

The view knows nothing about the simulator; it draws whatever snapshot dict it is given
(the dict ``SimHobbit.snapshot()`` returns)::

    view = HobbitSimView(language="de")
    view.set_snapshot(sim.snapshot())

It eases its drawing toward the latest snapshot at about 60 Hz, so a drive looks fluid even
when snapshots arrive less often. ``set_animation_enabled(False)`` draws every snapshot
exactly as given, without blinking or floating "z z" (for tests and screenshots).

Map frame: metres, x to the right, y up, theta counter-clockwise from +x. The room spans
x -1..5 and y -2.5..2.5; the visible area grows when the robot or its goal leaves it.
"""
import math

from PySide6.QtCore import QElapsedTimer, QPointF, QRectF, QSize, Qt, QTimer
from PySide6.QtGui import (
    QBrush, QColor, QFont, QFontMetricsF, QLinearGradient, QPainter, QPainterPath, QPainterPathStroker, QPen, QPixmap,
    QPolygonF, QRadialGradient, QTextLayout, QTextOption, QTransform,
)
from PySide6.QtWidgets import QWidget

# --- what a snapshot may say ------------------------------------------------------------

EMOTIONS = ("HAPPY", "VHAPPY", "LTIRED", "VTIRED", "CONCERNED", "SAD", "WONDERING", "NEUTRAL", "SLEEPING")
WAITING_KINDS = ("D_YES_NO", "D_OK", "D_NAME")

DEFAULT_SNAPSHOT = {
    "x": 0.0, "y": 0.0, "theta": 0.0, "trail": [], "linear": 0.0, "angular": 0.0, "motion": "idle",
    "nav_goal": None, "head": "center_center", "emotion": "NEUTRAL", "arm": "home", "arm_target": None,
    "arm_progress": 0.0, "gripper": "closed", "turntable": "stored", "turntable_angle": 0.0,
    "battery": 100.0, "volume": 50.0, "tablet": None, "notices": [], "time": 0.0,
}

# --- geometry (metres) ------------------------------------------------------------------

ROOM = (-1.0, -2.5, 5.0, 2.5)  # x0, y0, x1, y1 of the room's inside
WALL = 0.14
BASE_RADIUS = 0.275
HEAD_CENTER = (0.03, 0.0)
HEAD_RADIUS = 0.11
SHOULDER = (0.03, -0.19)
TURNTABLE = (0.40, 0.0)
TURNTABLE_RADIUS = 0.12

# Arm poses seen from above, in the robot frame (x forward, y to the robot's left):
# elbow, tip, how straight up the arm points (0..1), height of the tip over the floor (0..1).
ARM_POSES = {
    "home": ((-0.13, -0.23), (0.06, -0.24), 0.0, 0.5),
    "candle": ((0.04, -0.21), (0.05, -0.21), 1.0, 1.0),
    "floor": ((0.25, -0.29), (0.57, -0.31), 0.0, 0.0),
    "table": ((0.24, -0.25), (0.54, -0.17), 0.0, 0.8),
    "tray": ((0.07, -0.15), (-0.15, -0.05), 0.0, 0.6),
    "learning": ((0.22, -0.22), (0.35, -0.08), 0.0, 0.5),
    "joints": ((0.17, -0.34), (0.34, -0.44), 0.0, 0.5),
}

# Head positions: pan (degrees, + = robot's left), view length (m), cone opacity,
# cone half-width (degrees), tilt (-1 up .. +1 down; used by the eyes' gaze).
HEAD_LOOKS = {
    "center_center": (0.0, 1.8, 0.42, 22.0, 0.0),
    "up_center": (0.0, 2.8, 0.22, 20.0, -1.0),
    "down_center": (0.0, 0.85, 0.60, 27.0, 1.0),
    "center_right": (-50.0, 1.8, 0.42, 22.0, 0.0),
    "center_left": (50.0, 1.8, 0.42, 22.0, 0.0),
    "up_right": (-50.0, 2.8, 0.22, 20.0, -1.0),
    "up_left": (50.0, 2.8, 0.22, 20.0, -1.0),
    "down_right": (-50.0, 0.85, 0.60, 27.0, 1.0),
    "down_left": (50.0, 0.85, 0.60, 27.0, 1.0),
    "littledown_center": (0.0, 1.3, 0.50, 24.0, 0.5),
    "search_table": (0.0, 1.5, 0.38, 38.0, 0.6),
    # to_grasp and to_turntable point at the gripper and the turntable (see _head_look)
}

# --- colours ------------------------------------------------------------------------------

BASE_COLOR = QColor("#1FB3C8")       # HOBBIT's round base; nothing else uses it (tests look for it)
BASE_EDGE = QColor("#117888")
BUMPER = QColor("#FFC83D")
BODY = QColor("#FBFBFD")
BODY_EDGE = QColor("#8A93AC")
HEAD = QColor("#EEF2F8")
VISOR = QColor("#26325A")
ARM = QColor("#FF9431")
ARM_EDGE = QColor("#C2621A")
GRIPPER = QColor("#3C4560")
TRAIL = QColor("#8C5CF0")
GOAL = QColor("#FF4B6E")
VIEW_CONE = QColor("#FFD23F")
VIEW_CONE_EDGE = QColor("#F2A100")
SOS = QColor("#E5383B")

PANEL_BG = QColor("#EEF0FA")
CARD = QColor("#FFFFFF")
INK = QColor("#27304D")
INK_SOFT = QColor("#69718C")
FACE_BG = QColor("#243160")
FACE_BG_SLEEP = QColor("#161D3C")
LID_EDGE = QColor("#9FB2EA")
IRIS = QColor("#42B4F5")
IRIS_DARK = QColor("#1A6ED0")

EMOTION_ACCENT = {
    "HAPPY": "#FFC23D", "VHAPPY": "#FF6FAE", "LTIRED": "#A99BD9", "VTIRED": "#7C6CC4", "CONCERNED": "#FF9A3D",
    "SAD": "#4D8DFF", "WONDERING": "#22C2B0", "NEUTRAL": "#9AA4BA", "SLEEPING": "#4A56A6",
}

TEXTS = {
    "en": {
        "emotions": {"HAPPY": "happy", "VHAPPY": "very happy", "LTIRED": "a bit tired", "VTIRED": "very tired",
                     "CONCERNED": "worried", "SAD": "sad", "WONDERING": "wondering", "NEUTRAL": "calm",
                     "SLEEPING": "asleep"},
        "motion": {"idle": "standing", "moving": "driving", "turning": "turning", "navigating": "driving to the flag"},
        "waiting": "Waiting for your answer", "yes": "Yes", "no": "No", "ok": "OK", "type": "Type here…",
        "tablet_off": "tablet is off", "sos": "SOS",
        "arm": "Arm", "gripper": "Gripper", "head": "Head", "turntable": "Turntable",
        "open": "open", "closed": "closed", "out": "out", "stored": "stored",
    },
    "de": {
        "emotions": {"HAPPY": "fröhlich", "VHAPPY": "sehr fröhlich", "LTIRED": "etwas müde", "VTIRED": "sehr müde",
                     "CONCERNED": "besorgt", "SAD": "traurig", "WONDERING": "verwundert", "NEUTRAL": "ruhig",
                     "SLEEPING": "schläft"},
        "motion": {"idle": "steht", "moving": "fährt", "turning": "dreht sich", "navigating": "fährt zur Fahne"},
        "waiting": "Wartet auf deine Antwort", "yes": "Ja", "no": "Nein", "ok": "OK", "type": "Hier tippen…",
        "tablet_off": "Tablet ist aus", "sos": "SOS",
        "arm": "Arm", "gripper": "Greifer", "head": "Kopf", "turntable": "Drehteller",
        "open": "offen", "closed": "zu", "out": "draußen", "stored": "eingefahren",
    },
}

MOTION_COLOURS = {"idle": "#9AA4BA", "moving": "#2FBF71", "turning": "#FFB020", "navigating": "#FF4B6E"}

EASE_SECONDS = 0.07      # time constant of the easing toward the latest snapshot
SLOW_EASE = {            # things that would look abrupt if they followed as quickly
    "grip": 0.12, "tt_out": 0.3, "pan": 0.15, "look_len": 0.15, "look_alpha": 0.15, "look_width": 0.15,
    "tilt": 0.15, "bx0": 0.3, "by0": 0.3, "bx1": 0.3, "by1": 0.3,
}
TELEPORT_METRES = 2.0    # farther jumps are drawn at once, not glided
FRAME_MS = 16            # while something moves
AMBIENT_MS = 66          # blinking, floating z, pulsing hints
MIN_TEXT_PX = 11
ROBOT_MIN_PX = 44      # HOBBIT's base is drawn at least this wide (up to 1.6x its real size)


# --- small helpers --------------------------------------------------------------------------

def _num(value, default=0.0, lo=None, hi=None):
    """``value`` as a finite float (else ``default``), clamped to lo..hi."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        return default
    if not math.isfinite(number):
        return default
    if lo is not None:
        number = max(lo, number)
    if hi is not None:
        number = min(hi, number)
    return number


def _point(value):
    """An (x, y) pair of finite floats, or None."""
    try:
        x, y = float(value[0]), float(value[1])
    except (TypeError, ValueError, IndexError, KeyError):
        return None
    return (x, y) if math.isfinite(x) and math.isfinite(y) else None


def _wrap_pi(angle):
    return (angle + math.pi) % (2 * math.pi) - math.pi


def _wrap_180(degrees):
    return (degrees + 180.0) % 360.0 - 180.0


def _lerp(a, b, t):
    return a + (b - a) * t


def _smooth(t):
    return t * t * (3 - 2 * t)


def _with_alpha(color, alpha):
    c = QColor(color)
    c.setAlphaF(max(0.0, min(1.0, alpha)))
    return c


def _clean_text(text):
    """Text safe to lay out: newlines kept, tabs as spaces, other control characters dropped."""
    text = str(text).replace("\r\n", "\n").replace("\r", "\n").replace("\t", "    ")
    return "".join(ch for ch in text if ch == "\n" or ord(ch) >= 32)


_WRAP_CACHE = {}


def _wrap_lines(text, font, width):
    """``text`` broken into lines no wider than ``width`` pixels (at words, else anywhere)."""
    key = (text, font.toString(), round(width, 1))
    if key not in _WRAP_CACHE:
        if len(_WRAP_CACHE) > 256:
            _WRAP_CACHE.clear()
        _WRAP_CACHE[key] = _layout_lines(text, font, width)
    return list(_WRAP_CACHE[key])


def _layout_lines(text, font, width):
    option = QTextOption()
    option.setWrapMode(QTextOption.WrapMode.WrapAtWordBoundaryOrAnywhere)
    lines = []
    for paragraph in text.split("\n"):
        if not paragraph.strip():
            lines.append("")
            continue
        layout = QTextLayout(paragraph, font)
        layout.setTextOption(option)
        layout.beginLayout()
        while True:
            line = layout.createLine()
            if not line.isValid():
                break
            line.setLineWidth(max(1.0, width))
            lines.append(paragraph[line.textStart():line.textStart() + line.textLength()].rstrip())
        layout.endLayout()
    while lines and not lines[-1]:
        lines.pop()
    return lines


def _arc(cx, cy, r, start_deg, end_deg, steps=24, y_down=True):
    """Points on a circle from ``start_deg`` to ``end_deg`` (counter-clockwise as seen)."""
    sign = -1.0 if y_down else 1.0
    return [QPointF(cx + r * math.cos(math.radians(a)), cy + sign * r * math.sin(math.radians(a)))
            for a in (start_deg + (end_deg - start_deg) * i / steps for i in range(steps + 1))]


def _head_look(head, tip):
    """(pan degrees, length, opacity, half-width degrees, tilt) for a head position name."""
    hx, hy = HEAD_CENTER
    if head == "to_grasp":
        dx, dy = tip[0] - hx, tip[1] - hy
        return math.degrees(math.atan2(dy, dx)), math.hypot(dx, dy) + 0.18, 0.6, 18.0, 1.0
    if head == "to_turntable":
        dx, dy = TURNTABLE[0] - hx, TURNTABLE[1] - hy
        return math.degrees(math.atan2(dy, dx)), math.hypot(dx, dy) + 0.2, 0.6, 24.0, 1.0
    return HEAD_LOOKS.get(head, HEAD_LOOKS["center_center"])


def _targets(snapshot):
    """The drawn quantities a snapshot asks for, as floats the view can ease toward."""
    get = snapshot.get
    targets = {"x": _num(get("x")), "y": _num(get("y")), "theta": _num(get("theta"))}
    pose = ARM_POSES.get(get("arm"), ARM_POSES["home"])
    goal = ARM_POSES.get(get("arm_target"))
    if goal is not None and goal is not pose:
        k = _smooth(_num(get("arm_progress"), 0.0, 0.0, 1.0))
        pose = ((_lerp(pose[0][0], goal[0][0], k), _lerp(pose[0][1], goal[0][1], k)),
                (_lerp(pose[1][0], goal[1][0], k), _lerp(pose[1][1], goal[1][1], k)),
                _lerp(pose[2], goal[2], k), _lerp(pose[3], goal[3], k))
    (targets["ex"], targets["ey"]), (targets["tx"], targets["ty"]), targets["up"], targets["height"] = pose
    targets["grip"] = 1.0 if get("gripper") == "open" else 0.0
    targets["tt_out"] = 1.0 if get("turntable") == "out" else 0.0
    targets["tt_angle"] = _num(get("turntable_angle"))
    look = _head_look(get("head"), pose[1])
    targets["pan"], targets["look_len"], targets["look_alpha"], targets["look_width"], targets["tilt"] = look
    targets["pan"] = math.radians(targets["pan"])
    # visible area: the room with its walls, grown to keep the robot and its goal in sight
    margin = WALL + 0.3
    x0, y0, x1, y1 = ROOM[0] - margin, ROOM[1] - margin, ROOM[2] + margin, ROOM[3] + margin
    for point in ((targets["x"], targets["y"]), _point(get("nav_goal"))):
        if point is not None:
            x0, y0 = min(x0, point[0] - 0.8), min(y0, point[1] - 0.8)
            x1, y1 = max(x1, point[0] + 0.8), max(y1, point[1] + 0.8)
    targets.update(bx0=x0, by0=y0, bx1=x1, by1=y1)
    return targets


ANGLE_KEYS = {"theta", "pan"}
DEGREE_KEYS = {"tt_angle"}


class _Layout:
    """Where things go for one widget size."""

    def __init__(self, map_rect, panel_rect, vertical, u):
        self.map, self.panel, self.vertical, self.u = map_rect, panel_rect, vertical, u


class HobbitSimView(QWidget):
    """A simulated HOBBIT seen from above, with its eyes, battery, tablet and notices."""

    def __init__(self, parent=None, language="en"):
        super().__init__(parent)
        self._language = language if language in TEXTS else "en"
        self._snapshot = dict(DEFAULT_SNAPSHOT)
        self._target = _targets(self._snapshot)
        self._shown = dict(self._target)
        self._animate = True
        self._settled = True
        self._clock = QElapsedTimer()
        self._clock.start()
        self._last_tick = 0.0
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.timeout.connect(self._tick)
        self._room_cache = (None, None)
        self._text_cache = {}
        self.setAttribute(Qt.WidgetAttribute.WA_OpaquePaintEvent)
        self.setMinimumSize(200, 150)

    # --- public -------------------------------------------------------------------------

    @property
    def language(self):
        """'en' or 'de': the language of the few texts shown."""
        return self._language

    @language.setter
    def language(self, language):
        self._language = language if language in TEXTS else "en"
        self._text_cache.clear()
        self.update()

    def snapshot(self):
        """The latest snapshot given (a copy)."""
        return dict(self._snapshot)

    def set_snapshot(self, snapshot):
        """Show ``snapshot`` (a dict as ``SimHobbit.snapshot()`` returns; missing keys keep their defaults)."""
        merged = dict(DEFAULT_SNAPSHOT)
        if isinstance(snapshot, dict):
            merged.update(snapshot)
        self._snapshot = merged
        self._target = _targets(merged)
        jump = math.hypot(self._target["x"] - self._shown["x"], self._target["y"] - self._shown["y"])
        if not self._animate or not self.isVisible() or jump > TELEPORT_METRES:
            self._shown = dict(self._target)
            self.update()
            return
        # the panel shows the news now; the room follows on the next animation frame
        if self._settled:
            self._last_tick = self._clock.elapsed() / 1000.0 - FRAME_MS / 1000.0
        self._settled = False
        self._run_timer(FRAME_MS)
        self.update(self._layout().panel.toAlignedRect())

    def set_animation_enabled(self, enabled):
        """False: draw each snapshot exactly, nothing moves by itself (tests, screenshots)."""
        self._animate = bool(enabled)
        if not self._animate:
            self._timer.stop()
            self._shown = dict(self._target)
        elif self.isVisible():
            self._settled = False
            self._last_tick = self._clock.elapsed() / 1000.0
            self._run_timer(FRAME_MS)
        self.update()

    def animation_enabled(self):
        return self._animate

    def displayed_pose(self):
        """(x, y, theta) as drawn right now; trails the latest snapshot while easing toward it."""
        return self._shown["x"], self._shown["y"], self._shown["theta"]

    def eyes_rect(self):
        """Where HOBBIT's eyes are drawn, in widget pixels."""
        layout = self._layout()
        return self._panel_sections(layout)["face"].toAlignedRect()

    def map_rect(self):
        """Where the room is drawn, in widget pixels."""
        return self._layout().map.toAlignedRect()

    def map_to_widget(self, x, y):
        """Widget pixel position of the map point (x, y) metres, for the current size."""
        return self._map_transform(self._layout().map).map(QPointF(x, y))

    def sizeHint(self):
        return QSize(640, 480)

    def minimumSizeHint(self):
        return QSize(320, 240)

    # --- animation ----------------------------------------------------------------------

    def showEvent(self, event):
        super().showEvent(event)
        if self._animate:
            self._last_tick = self._clock.elapsed() / 1000.0
            self._run_timer(FRAME_MS if not self._settled else AMBIENT_MS)

    def _run_timer(self, interval):
        """Tick every ``interval`` ms; a running timer is not restarted (that would starve it)."""
        if not self._timer.isActive():
            self._timer.start(interval)
        elif self._timer.interval() != interval:
            self._timer.setInterval(interval)

    def hideEvent(self, event):
        super().hideEvent(event)
        self._timer.stop()

    def _phase(self):
        """Seconds on the view's own clock; 0 when animation is off (nothing moves by itself)."""
        return self._clock.elapsed() / 1000.0 if self._animate else 0.0

    def _tick(self):
        now = self._clock.elapsed() / 1000.0
        dt = min(0.1, max(0.0, now - self._last_tick))
        self._last_tick = now
        if not self._settled:
            gaze_moving = any(self._shown[key] != self._target[key] for key in ("pan", "tilt"))
            self._settled = self._ease(dt)
            self._run_timer(AMBIENT_MS if self._settled else FRAME_MS)
            layout = self._layout()
            self.update(layout.map.adjusted(-2, -2, 2, 2).toAlignedRect())
            if gaze_moving:   # the eyes in the panel look where the head turns
                self.update(layout.panel.toAlignedRect())
            return
        # settled: only the gentle ambient motions need drawing
        if self._snapshot.get("nav_goal") is not None or self._sos_active():
            self.update()
        else:
            self.update(self._layout().panel.toAlignedRect())

    def _ease(self, dt):
        """Move the drawn values ``dt`` seconds' worth toward the targets; True when all have arrived."""
        settled = True
        for key, target in self._target.items():
            k = 1.0 - math.exp(-dt / SLOW_EASE.get(key, EASE_SECONDS))
            shown = self._shown.get(key, target)
            if key in ANGLE_KEYS:
                diff, eps = _wrap_pi(target - shown), 1e-3
            elif key in DEGREE_KEYS:
                diff, eps = _wrap_180(target - shown), 0.05
            else:
                diff, eps = target - shown, 1e-3
            if abs(diff) <= eps:
                self._shown[key] = target
            else:
                self._shown[key] = shown + diff * k
                settled = False
        return settled

    # --- layout ---------------------------------------------------------------------------

    def _layout(self):
        w, h = max(1, self.width()), max(1, self.height())
        u = max(0.5, min(2.5, min(w / 640.0, h / 480.0)))
        gap = max(4.0, 6.0 * u)
        if w >= 1.05 * h:
            pw = max(130.0, min(0.31 * w, 560.0))
            map_rect = QRectF(gap, gap, w - pw - gap, h - 2 * gap)
            panel = QRectF(w - pw, 0, pw, h)
            return _Layout(map_rect, panel, True, u)
        ph = max(120.0, min(0.36 * h, 320.0))
        map_rect = QRectF(gap, gap, w - 2 * gap, h - ph - gap)
        panel = QRectF(0, h - ph, w, ph)
        return _Layout(map_rect, panel, False, u)

    def _font(self, px, bold=False):
        font = QFont(self.font())
        font.setPixelSize(max(MIN_TEXT_PX, int(round(px))))
        font.setBold(bold)
        return font

    def _map_transform(self, rect):
        s = self._shown
        bw, bh = max(0.1, s["bx1"] - s["bx0"]), max(0.1, s["by1"] - s["by0"])
        scale = max(1e-3, min(rect.width() / bw, rect.height() / bh))
        cx, cy = rect.center().x(), rect.center().y()
        mx, my = (s["bx0"] + s["bx1"]) / 2, (s["by0"] + s["by1"]) / 2
        return QTransform(scale, 0, 0, -scale, cx - scale * mx, cy + scale * my)

    def _panel_sections(self, layout):
        """Rects of the panel's parts: eyes card, face, label, status row, tablet, notices, details."""
        u, panel = layout.u, layout.panel
        pad = max(6.0, 8.0 * u)
        label_h = QFontMetricsF(self._font(13 * u, True)).height()
        status_h = max(24.0, 30.0 * u)
        sections = {}
        if layout.vertical:
            inner = panel.adjusted(0, pad, -pad, -pad)
            width = inner.width()
            face_h = min(width * 0.5, panel.height() * 0.3)
            card_pad = max(5.0, 7.0 * u)
            card = QRectF(inner.left(), inner.top(), width, face_h + label_h + 2.5 * card_pad)
            top = card.bottom() + pad
            sections["status"] = QRectF(inner.left(), top, width, status_h)
            top += status_h + pad
            rest = QRectF(inner.left(), top, width, max(0.0, inner.bottom() - top))
        else:
            inner = panel.adjusted(pad, 0, -pad, -pad)
            card_pad = max(5.0, 7.0 * u)
            room_h = max(40.0, inner.height() - status_h - pad)
            left_w = min(inner.width() * 0.44, (room_h - label_h - 2.5 * card_pad) * 2.0 + 2 * card_pad)
            face_h = min(room_h - label_h - 2.5 * card_pad, (left_w - 2 * card_pad) * 0.55)
            card = QRectF(inner.left(), inner.top(), left_w, face_h + label_h + 2.5 * card_pad)
            sections["status"] = QRectF(inner.left(), card.bottom() + pad, left_w, status_h)
            rest = QRectF(card.right() + pad, inner.top(), inner.right() - card.right() - pad, inner.height())
        sections["card"] = card
        face = QRectF(card.left() + card_pad, card.top() + card_pad, card.width() - 2 * card_pad, max(10.0, face_h))
        sections["face"] = face
        sections["label"] = QRectF(card.left(), face.bottom() + card_pad * 0.4, card.width(), label_h)
        # tablet first (it may be a question someone must answer), notices below it
        notices = self._notices()[-3:][::-1]
        chip_h = QFontMetricsF(self._font(12 * u)).height() + max(6.0, 8.0 * u)
        tablet_h = min(rest.height(), self._tablet_height(rest.width(), u))
        room_for_notices = rest.height() - tablet_h - (pad if tablet_h > 0 else 0)
        n = min(len(notices), int((room_for_notices + pad * 0.5) // (chip_h + pad * 0.5))) if notices else 0
        if notices and n == 0 and tablet_h > 0 and self._snapshot.get("tablet") is None:
            tablet_h, n = 0.0, min(len(notices), int((rest.height() + pad * 0.5) // (chip_h + pad * 0.5)))
        sections["tablet"] = QRectF(rest.left(), rest.top(), rest.width(), tablet_h) if tablet_h > 0 else None
        top = rest.top() + (tablet_h + pad if tablet_h > 0 else 0)
        sections["notices"] = [(QRectF(rest.left(), top + i * (chip_h + pad * 0.5), rest.width(), chip_h), notices[i])
                               for i in range(n)]
        # what the arm, gripper, head and turntable are doing, at the bottom when there is room
        top += n * (chip_h + pad * 0.5)
        details_h = 4 * QFontMetricsF(self._font(12 * u)).lineSpacing() + 2 * max(5.0, 7.0 * u) + 4
        sections["details"] = None
        if layout.vertical and rest.bottom() - top >= details_h + pad:
            sections["details"] = QRectF(rest.left(), rest.bottom() - details_h, rest.width(), details_h)
        return sections

    # --- reading the snapshot -------------------------------------------------------------

    def _texts(self):
        return TEXTS.get(self._language, TEXTS["en"])

    def _notices(self):
        notices = self._snapshot.get("notices") or []
        if isinstance(notices, str):
            notices = [notices]
        try:
            return [_clean_text(n).replace("\n", " ") for n in list(notices)[-20:]]
        except TypeError:
            return []

    def _sos_active(self):
        notices = self._notices()
        return bool(notices) and "sos" in notices[-1].lower()

    def _tablet(self):
        """(kind, text) on the tablet, or None."""
        tablet = self._snapshot.get("tablet")
        if not isinstance(tablet, dict):
            return None
        kind = str(tablet.get("kind") or "D_PLAIN")
        return kind, _clean_text(tablet.get("text") or "")

    def _emotion(self):
        emotion = str(self._snapshot.get("emotion") or "NEUTRAL").upper()
        return emotion if emotion in EMOTIONS else "NEUTRAL"

    # --- painting -----------------------------------------------------------------------

    def paintEvent(self, event):
        if self.width() < 10 or self.height() < 10:
            return
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setRenderHint(QPainter.RenderHint.TextAntialiasing)
        painter.setRenderHint(QPainter.RenderHint.SmoothPixmapTransform)
        layout = self._layout()
        dirty = event.rect()
        painter.fillRect(dirty, PANEL_BG)
        if dirty.intersects(layout.map.adjusted(-2, -2, 2, 2).toAlignedRect()):
            self._paint_map(painter, layout)
        if dirty.intersects(layout.panel.toAlignedRect()):
            self._paint_panel(painter, layout)
        painter.end()

    # --- the room ---------------------------------------------------------------------------

    def _paint_map(self, p, layout):
        rect = layout.map
        if rect.width() < 4 or rect.height() < 4:
            return
        transform = self._map_transform(rect)
        scale = transform.m11()
        p.drawPixmap(rect.topLeft(), self._room_pixmap(rect, transform))
        radius = max(8.0, 12.0 * layout.u)
        clip = QPainterPath()
        clip.addRoundedRect(rect, radius, radius)
        p.save()
        p.setClipPath(clip)
        p.setTransform(transform)
        phase = self._phase()
        self._paint_trail(p, scale)
        goal = _point(self._snapshot.get("nav_goal"))
        if goal is not None:
            self._paint_goal_ground(p, goal)
        self._paint_robot(p, scale, phase)
        p.resetTransform()
        if goal is not None:
            self._paint_flag(p, transform.map(QPointF(*goal)), scale, phase)
        self._paint_map_chips(p, rect, layout.u)
        p.restore()
        pen = QPen(QColor("#C9CEE6"), max(1.0, 1.5 * layout.u))
        p.setPen(pen)
        p.setBrush(Qt.BrushStyle.NoBrush)
        p.drawRoundedRect(rect, radius, radius)

    def _room_pixmap(self, rect, transform):
        """The floor, walls and furniture for this size and visible area (cached)."""
        s = self._shown
        dpr = self.devicePixelRatioF()
        key = (int(rect.width()), int(rect.height()), round(s["bx0"], 3), round(s["by0"], 3),
               round(s["bx1"], 3), round(s["by1"], 3), dpr)
        if self._room_cache[0] == key:
            return self._room_cache[1]
        pixmap = QPixmap(max(1, int(math.ceil(rect.width() * dpr))), max(1, int(math.ceil(rect.height() * dpr))))
        pixmap.setDevicePixelRatio(dpr)
        pixmap.fill(Qt.GlobalColor.transparent)
        p = QPainter(pixmap)
        p.setRenderHint(QPainter.RenderHint.Antialiasing)
        local = QRectF(0, 0, rect.width(), rect.height())
        radius = max(8.0, 12.0 * self._layout().u)
        clip = QPainterPath()
        clip.addRoundedRect(local, radius, radius)
        p.setClipPath(clip)
        _paint_lawn(p, local)
        p.setTransform(transform * QTransform.fromTranslate(-rect.left(), -rect.top()))
        scale = transform.m11()
        _paint_garden(p, s)
        _paint_floor(p)
        _paint_furniture(p)
        _paint_walls(p)
        _paint_grid(p, s, scale)
        _paint_origin(p, scale)
        p.end()
        self._room_cache = (key, pixmap)
        return pixmap

    def _paint_trail(self, p, scale):
        trail = self._snapshot.get("trail") or []
        try:
            points = [pt for pt in (_point(v) for v in list(trail)[-500:]) if pt is not None]
        except TypeError:
            return
        if len(points) < 2:
            return
        spacing = max(0.07, 9.0 / scale)
        dots, carry = [points[0]], 0.0
        for (ax, ay), (bx, by) in zip(points, points[1:]):
            length = math.hypot(bx - ax, by - ay)
            if length == 0:
                continue
            d = spacing - carry
            while d <= length:
                dots.append((ax + (bx - ax) * d / length, ay + (by - ay) * d / length))
                d += spacing
            carry = length - (d - spacing)
        # older dots are fainter and smaller; dots of similar age are drawn as one path
        radius = max(0.024, 2.2 / scale)
        p.setPen(Qt.PenStyle.NoPen)
        n, buckets = len(dots), 10
        for bucket in range(buckets):
            lo, hi = n * bucket // buckets, n * (bucket + 1) // buckets
            if lo >= hi:
                continue
            t = hi / n
            r = radius * (0.65 + 0.35 * t)
            path = QPainterPath()
            path.setFillRule(Qt.FillRule.WindingFill)
            for x, y in dots[lo:hi]:
                path.addEllipse(QPointF(x, y), r, r)
            p.setBrush(_with_alpha(TRAIL, 0.12 + 0.78 * t))
            p.drawPath(path)

    def _paint_goal_ground(self, p, goal):
        gx, gy = goal
        s = self._shown
        if self._snapshot.get("motion") == "navigating":
            pen = QPen(_with_alpha(GOAL, 0.65), 2.0)
            pen.setCosmetic(True)
            pen.setDashPattern([4, 4])
            pen.setCapStyle(Qt.PenCapStyle.RoundCap)
            p.setPen(pen)
            p.drawLine(QPointF(s["x"], s["y"]), QPointF(gx, gy))
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor(0, 0, 0, 28))
        p.drawEllipse(QPointF(gx + 0.02, gy - 0.03), 0.22, 0.22)
        for radius, color in ((0.21, GOAL), (0.15, QColor("#FFFFFF")), (0.09, GOAL), (0.035, QColor("#FFFFFF"))):
            p.setBrush(color)
            p.drawEllipse(QPointF(gx, gy), radius, radius)

    def _paint_flag(self, p, base, scale, phase):
        pole = max(24.0, 0.62 * scale)
        top = QPointF(base.x(), base.y() - pole)
        pen = QPen(QColor("#4A4F66"), max(2.0, 0.028 * scale))
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
        p.setPen(pen)
        p.drawLine(base, top)
        fw, fh = pole * 0.62, pole * 0.4
        wave = math.sin(phase * 4.0) * fh * 0.12
        flag = QPainterPath(top)
        flag.cubicTo(QPointF(top.x() + fw * 0.35, top.y() - wave), QPointF(top.x() + fw * 0.65, top.y() + wave),
                     QPointF(top.x() + fw, top.y() + fh * 0.5))
        flag.cubicTo(QPointF(top.x() + fw * 0.65, top.y() + fh * 0.5 + wave),
                     QPointF(top.x() + fw * 0.35, top.y() + fh - wave), QPointF(top.x(), top.y() + fh))
        flag.closeSubpath()
        p.setPen(QPen(QColor("#C81E45"), max(1.0, 0.01 * scale)))
        p.setBrush(GOAL)
        p.drawPath(flag)
        _paint_star(p, QPointF(top.x() + fw * 0.38, top.y() + fh * 0.5), fh * 0.24, QColor("#FFE066"))
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor("#FFD23F"))
        p.drawEllipse(top, max(2.5, 0.03 * scale), max(2.5, 0.03 * scale))

    def _paint_robot(self, p, scale, phase):
        s = self._shown
        x, y, theta = s["x"], s["y"], s["theta"]
        # on a small map HOBBIT is drawn up to 1.6x its size, so a child can still see it
        grow = max(1.0, min(1.6, ROBOT_MIN_PX / (2 * BASE_RADIUS * scale)))
        p.save()
        p.translate(x, y)
        p.scale(grow, grow)
        scale *= grow
        p.setPen(Qt.PenStyle.NoPen)
        if self._sos_active():
            pulse = 0.5 + 0.5 * math.sin(phase * 6.0)
            p.setBrush(_with_alpha(SOS, 0.18 + 0.22 * pulse))
            p.drawEllipse(QPointF(0, 0), BASE_RADIUS + 0.16 + 0.06 * pulse, BASE_RADIUS + 0.16 + 0.06 * pulse)
        p.setBrush(QColor(20, 30, 60, 55))
        p.drawEllipse(QPointF(0.035, -0.05), BASE_RADIUS + 0.01, BASE_RADIUS + 0.01)
        p.rotate(math.degrees(theta))
        self._paint_motion_hints(p, scale)
        line = max(0.012, 1.4 / scale)
        # base, bumper and a chevron: the front is where the yellow is
        p.setPen(QPen(BASE_EDGE, line))
        p.setBrush(BASE_COLOR)
        p.drawEllipse(QPointF(0, 0), BASE_RADIUS, BASE_RADIUS)
        bumper = QPen(BUMPER, 0.045)
        bumper.setCapStyle(Qt.PenCapStyle.RoundCap)
        p.setPen(bumper)
        p.setBrush(Qt.BrushStyle.NoBrush)
        p.drawPolyline(QPolygonF(_arc(0, 0, BASE_RADIUS - 0.03, -55, 55, 20, y_down=False)))
        p.setPen(QPen(QColor("#E0A100"), line * 0.8))
        p.setBrush(BUMPER)
        p.drawPolygon(QPolygonF([QPointF(0.235, 0), QPointF(0.155, 0.06), QPointF(0.155, -0.06)]))
        # body column with the tray on its back
        p.setPen(QPen(BODY_EDGE, line))
        p.setBrush(BODY)
        p.drawRoundedRect(QRectF(-0.235, -0.16, 0.345, 0.32), 0.07, 0.07)
        p.setPen(QPen(QColor("#B98A5C"), line * 0.8))
        p.setBrush(QColor("#F1D3A8"))
        p.drawRoundedRect(QRectF(-0.215, -0.125, 0.105, 0.25), 0.03, 0.03)
        self._paint_turntable(p, line)
        self._paint_view_cone(p, grow)
        self._paint_arm(p, line, theta)
        self._paint_head(p, line)
        p.restore()

    def _paint_motion_hints(self, p, scale):
        snap = self._snapshot
        linear, angular = _num(snap.get("linear")), _num(snap.get("angular"))
        pen = QPen(_with_alpha(BASE_EDGE, 0.55), max(0.02, 2.0 / scale))
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
        p.setPen(pen)
        p.setBrush(Qt.BrushStyle.NoBrush)
        if abs(linear) > 0.02:
            back = -1.0 if linear > 0 else 1.0
            for dy, length in ((-0.14, 0.12), (0.0, 0.18), (0.14, 0.12)):
                start = back * (BASE_RADIUS + 0.06)
                p.drawLine(QPointF(start, dy), QPointF(start + back * length, dy))
        if abs(angular) > 0.05:
            sign = 1.0 if angular > 0 else -1.0
            points = _arc(0, 0, BASE_RADIUS + 0.09, 120, 240, 16, y_down=False)
            if sign < 0:
                points = points[::-1]
            p.drawPolyline(QPolygonF(points))
            end, before = points[-1], points[-3]
            dx, dy = end.x() - before.x(), end.y() - before.y()
            norm = math.hypot(dx, dy) or 1.0
            dx, dy = dx / norm * 0.07, dy / norm * 0.07
            p.drawLine(end, QPointF(end.x() - dx - dy * 0.8, end.y() - dy + dx * 0.8))
            p.drawLine(end, QPointF(end.x() - dx + dy * 0.8, end.y() - dy - dx * 0.8))

    def _paint_turntable(self, p, line):
        out = self._shown["tt_out"]
        if out < 0.02:
            return
        cx = _lerp(0.18, TURNTABLE[0], out)
        radius = TURNTABLE_RADIUS * (0.6 + 0.4 * out)
        p.save()
        p.setOpacity(min(1.0, out * 1.5))
        p.translate(cx, TURNTABLE[1])
        p.setPen(QPen(QColor("#6E5BB8"), line))
        p.setBrush(QColor("#C9BDF5"))
        p.drawEllipse(QPointF(0, 0), radius, radius)
        p.rotate(self._shown["tt_angle"])
        p.setPen(QPen(QColor("#8C7AD6"), line * 0.8))
        for k in range(6):
            a = math.radians(k * 60)
            p.drawLine(QPointF(0, 0), QPointF(math.cos(a) * radius * 0.85, math.sin(a) * radius * 0.85))
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor("#FF5D8F"))
        p.drawEllipse(QPointF(radius * 0.55, 0), radius * 0.22, radius * 0.22)
        p.setBrush(QColor("#FFFFFF"))
        p.drawEllipse(QPointF(0, 0), radius * 0.16, radius * 0.16)
        p.restore()

    def _paint_arm(self, p, line, theta):
        s = self._shown
        shoulder, elbow, tip = QPointF(*SHOULDER), QPointF(s["ex"], s["ey"]), QPointF(s["tx"], s["ty"])
        up, height = s["up"], s["height"]
        # the shadow falls down-right on screen, farther the higher the arm
        off = 0.015 + 0.06 * height
        sx = off * (math.cos(-theta) * 0.6 - math.sin(-theta) * -0.8)
        sy = off * (math.sin(-theta) * 0.6 + math.cos(-theta) * -0.8)
        shadow = QPen(QColor(20, 30, 60, 45), 0.06)
        shadow.setCapStyle(Qt.PenCapStyle.RoundCap)
        shadow.setJoinStyle(Qt.PenJoinStyle.RoundJoin)
        p.setPen(shadow)
        p.setBrush(Qt.BrushStyle.NoBrush)
        p.drawPolyline(QPolygonF([shoulder + QPointF(sx, sy), elbow + QPointF(sx, sy), tip + QPointF(sx, sy)]))
        for width, color in ((0.062, ARM_EDGE), (0.045, ARM)):
            pen = QPen(color, width)
            pen.setCapStyle(Qt.PenCapStyle.RoundCap)
            pen.setJoinStyle(Qt.PenJoinStyle.RoundJoin)
            p.setPen(pen)
            p.drawPolyline(QPolygonF([shoulder, elbow, tip]))
        p.setPen(QPen(ARM_EDGE, line))
        p.setBrush(QColor("#FFC27A"))
        p.drawEllipse(elbow, 0.032, 0.032)
        p.setBrush(QColor("#9AA3BA"))
        p.drawEllipse(shoulder, 0.04, 0.04)
        # gripper: two fingers along the forearm, spread when open
        dx, dy = tip.x() - elbow.x(), tip.y() - elbow.y()
        norm = math.hypot(dx, dy)
        direction = math.atan2(dy, dx) if norm > 0.02 else 0.0
        fingers = 1.0 - up
        if fingers > 0.05:
            spread = math.radians(7 + 26 * s["grip"])
            length = 0.075 * fingers
            pen = QPen(GRIPPER, 0.022)
            pen.setCapStyle(Qt.PenCapStyle.RoundCap)
            p.setPen(pen)
            for side in (-1, 1):
                a = direction + side * spread
                mid = QPointF(tip.x() + math.cos(a) * length * 0.6, tip.y() + math.sin(a) * length * 0.6)
                end = QPointF(mid.x() + math.cos(direction) * length * 0.5,
                              mid.y() + math.sin(direction) * length * 0.5)
                p.drawPolyline(QPolygonF([tip, mid, end]))
            p.setPen(QPen(GRIPPER, line))
            p.setBrush(QColor("#5B6584"))
            p.drawEllipse(tip, 0.028, 0.028)
        if up > 0.05:
            # arm straight up ("candle"): a round cap with an arrow pointing at the sky
            r = 0.06 * up
            p.setPen(QPen(ARM_EDGE, line))
            p.setBrush(ARM)
            p.drawEllipse(tip, r, r)
            p.setPen(Qt.PenStyle.NoPen)
            p.setBrush(QColor("#FFFFFF"))
            p.drawEllipse(tip, r * 0.55, r * 0.55)
            p.setBrush(ARM_EDGE)
            p.drawEllipse(tip, r * 0.25, r * 0.25)

    def _paint_view_cone(self, p, grow):
        s = self._shown
        if self._emotion() == "SLEEPING":
            return
        hx, hy = HEAD_CENTER
        length, half = s["look_len"] / grow, s["look_width"]
        pan = math.degrees(s["pan"])
        gradient = QRadialGradient(QPointF(hx, hy), length)
        gradient.setColorAt(0.0, _with_alpha(VIEW_CONE, s["look_alpha"] + 0.25))
        gradient.setColorAt(0.55, _with_alpha(VIEW_CONE, s["look_alpha"]))
        gradient.setColorAt(1.0, _with_alpha(VIEW_CONE, 0.0))
        path = QPainterPath(QPointF(hx, hy))
        for point in _arc(hx, hy, length, pan - half, pan + half, 20, y_down=False):
            path.lineTo(point)
        path.closeSubpath()
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QBrush(gradient))
        p.drawPath(path)
        edge = QLinearGradient(QPointF(hx, hy), QPointF(hx + length * math.cos(math.radians(pan)),
                                                        hy + length * math.sin(math.radians(pan))))
        edge.setColorAt(0.0, _with_alpha(VIEW_CONE_EDGE, 0.9))
        edge.setColorAt(1.0, _with_alpha(VIEW_CONE_EDGE, 0.0))
        pen = QPen(QBrush(edge), 0.018 / grow)
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
        p.setPen(pen)
        for a in (pan - half, pan + half):
            p.drawLine(QPointF(hx, hy), QPointF(hx + length * math.cos(math.radians(a)),
                                                hy + length * math.sin(math.radians(a))))

    def _paint_head(self, p, line):
        s = self._shown
        hx, hy = HEAD_CENTER
        pan = math.degrees(s["pan"])
        p.setPen(QPen(BODY_EDGE, line))
        p.setBrush(HEAD)
        p.drawEllipse(QPointF(hx, hy), HEAD_RADIUS, HEAD_RADIUS)
        visor = QPainterPath(QPointF(hx, hy))
        for point in _arc(hx, hy, HEAD_RADIUS * 0.86, pan - 58, pan + 58, 16, y_down=False):
            visor.lineTo(point)
        visor.closeSubpath()
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(VISOR)
        p.drawPath(visor)
        sleeping = self._emotion() == "SLEEPING"
        p.setBrush(QColor("#7FE3FF") if not sleeping else QColor("#4B5A8C"))
        for side in (-1, 1):
            a = math.radians(pan + side * 24)
            center = QPointF(hx + math.cos(a) * HEAD_RADIUS * 0.55, hy + math.sin(a) * HEAD_RADIUS * 0.55)
            p.drawEllipse(center, 0.018, 0.018)

    def _paint_map_chips(self, p, rect, u):
        snap, texts = self._snapshot, self._texts()
        font = self._font(12 * u, True)
        small = self._font(11 * u)
        fm, fm_small = QFontMetricsF(font), QFontMetricsF(small)
        pad = max(4.0, 6.0 * u)
        motion = str(snap.get("motion") or "idle")
        label = texts["motion"].get(motion, motion)
        linear, angular = _num(snap.get("linear")), _num(snap.get("angular"))
        if abs(linear) > 0.005:
            label += f"  {abs(linear):.2f} m/s"
        elif abs(angular) > 0.01:
            label += f"  {abs(math.degrees(angular)):.0f}°/s"
        dot = fm.height() * 0.55
        chip_h = fm.height() + pad
        chip_w = min(rect.width() - 2 * pad, fm.horizontalAdvance(label) + dot + 3 * pad + 4)
        chip = QRectF(rect.left() + pad, rect.bottom() - pad - chip_h, chip_w, chip_h)
        _chip(p, chip)
        colour = MOTION_COLOURS.get(motion, MOTION_COLOURS["idle"])
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor(colour))
        p.drawEllipse(QPointF(chip.left() + pad + dot / 2, chip.center().y()), dot / 2, dot / 2)
        p.setPen(INK)
        p.setFont(font)
        text_rect = chip.adjusted(pad * 2 + dot, 0, -pad, 0)
        p.drawText(text_rect, Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft,
                   fm.elidedText(label, Qt.TextElideMode.ElideRight, text_rect.width()))
        # where exactly, for the grown-ups
        s = self._target
        where = f"x {s['x']:.2f}  y {s['y']:.2f} m  θ {math.degrees(_wrap_pi(s['theta'])):.0f}°"
        clock = f"t {_num(snap.get('time')):.1f} s"
        where_w = fm_small.horizontalAdvance(where) + 2 * pad
        if chip.right() + pad + where_w <= rect.right() - pad:
            box = QRectF(rect.right() - pad - where_w, rect.bottom() - pad - chip_h, where_w, chip_h)
            _chip(p, box)
            p.setPen(INK_SOFT)
            p.setFont(small)
            p.drawText(box, Qt.AlignmentFlag.AlignCenter, where)
        clock_w = fm_small.horizontalAdvance(clock) + 2 * pad
        if rect.width() > 3 * clock_w:
            box = QRectF(rect.right() - pad - clock_w, rect.top() + pad, clock_w, fm_small.height() + pad)
            _chip(p, box)
            p.setPen(INK_SOFT)
            p.setFont(small)
            p.drawText(box, Qt.AlignmentFlag.AlignCenter, clock)

    # --- the panel --------------------------------------------------------------------------

    def _paint_panel(self, p, layout):
        sections = self._panel_sections(layout)
        u, phase = layout.u, self._phase()
        emotion = self._emotion()
        # eyes card
        card = sections["card"]
        accent = QColor(EMOTION_ACCENT[emotion])
        radius = max(8.0, 12.0 * u)
        _card(p, card, radius, accent)
        self._paint_eyes(p, sections["face"], emotion, phase)
        label = sections["label"]
        font = self._font(13 * u, True)
        fm = QFontMetricsF(font)
        text = self._texts()["emotions"][emotion]
        dot = fm.height() * 0.5
        text_w = min(fm.horizontalAdvance(text), label.width() - dot - 16)
        left = label.center().x() - (text_w + dot + 6) / 2
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(accent)
        p.drawEllipse(QPointF(left + dot / 2, label.center().y()), dot / 2, dot / 2)
        p.setPen(INK)
        p.setFont(font)
        p.drawText(QRectF(left + dot + 6, label.top(), text_w + 2, label.height()),
                   Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft,
                   fm.elidedText(text, Qt.TextElideMode.ElideRight, text_w + 1))
        self._paint_status(p, sections["status"], u, phase)
        if sections["tablet"] is not None:
            p.save()
            p.setClipRect(sections["tablet"].adjusted(-4, -4, 4, 4))
            self._paint_tablet(p, sections["tablet"], u, phase)
            p.restore()
        for index, (rect, notice) in enumerate(sections["notices"]):
            self._paint_notice(p, rect, notice, u, index == 0)
        if sections["details"] is not None:
            self._paint_details(p, sections["details"], u)

    def _paint_details(self, p, rect, u):
        snap, texts = self._snapshot, self._texts()
        _card(p, rect, max(8.0, 10.0 * u))
        font, bold = self._font(12 * u), self._font(12 * u, True)
        fm, fm_bold = QFontMetricsF(font), QFontMetricsF(bold)
        pad = max(5.0, 7.0 * u)
        arm, target = str(snap.get("arm") or "home"), snap.get("arm_target")
        progress = _num(snap.get("arm_progress"), 0.0, 0.0, 1.0) if target else None
        rows = [(texts["arm"], f"{arm} → {target}" if target else arm, progress),
                (texts["gripper"], texts["open"] if snap.get("gripper") == "open" else texts["closed"], None),
                (texts["head"], str(snap.get("head") or "center_center"), None),
                (texts["turntable"], f"{texts['out']} {_num(snap.get('turntable_angle')):.0f}°"
                 if snap.get("turntable") == "out" else texts["stored"], None)]
        label_w = max(fm.horizontalAdvance(row[0]) for row in rows) + pad
        y = rect.top() + pad
        for label, value, progress in rows:
            line = QRectF(rect.left() + pad, y, rect.width() - 2 * pad, fm.height())
            p.setFont(font)
            p.setPen(INK_SOFT)
            p.drawText(line, Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft,
                       fm.elidedText(label, Qt.TextElideMode.ElideRight, line.width() * 0.45))
            value_rect = line.adjusted(min(label_w, line.width() * 0.45), 0, 0, 0)
            if progress is not None:
                bar = QRectF(value_rect.left(), line.bottom() - 1, value_rect.width(), 3)
                p.setPen(Qt.PenStyle.NoPen)
                p.setBrush(QColor("#E3E6F3"))
                p.drawRoundedRect(bar, 1.5, 1.5)
                bar.setWidth(bar.width() * progress)
                p.setBrush(ARM)
                p.drawRoundedRect(bar, 1.5, 1.5)
            p.setFont(bold)
            p.setPen(INK)
            p.drawText(value_rect, Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignRight,
                       fm_bold.elidedText(value, Qt.TextElideMode.ElideRight, value_rect.width()))
            y += fm.lineSpacing()

    def _paint_status(self, p, rect, u, phase):
        snap = self._snapshot
        battery = _num(snap.get("battery"), 100.0, 0.0, 100.0)
        volume = _num(snap.get("volume"), 50.0, 0.0, 100.0)
        radius = max(8.0, 10.0 * u)
        _card(p, rect, radius)
        font = self._font(13 * u, True)
        fm = QFontMetricsF(font)
        pad = max(5.0, 8.0 * u)
        icon_h = min(rect.height() * 0.5, 16 * u + 4)
        icon_w = icon_h * 1.9
        show_volume = rect.width() >= 2 * (icon_w + fm.horizontalAdvance("100%") + 2.5 * pad) - pad
        half = rect.width() / 2 if show_volume else rect.width()
        # battery
        body = QRectF(rect.left() + pad, rect.center().y() - icon_h / 2, icon_w, icon_h)
        if battery >= 50:
            colour = QColor("#2FBF71")
        elif battery >= 20:
            colour = QColor("#FFB020")
        else:
            colour = QColor("#F04444")
        blink = 1.0
        if battery < 15 and self._animate:
            blink = 0.45 + 0.55 * (0.5 + 0.5 * math.sin(phase * 5.0))
        p.setPen(QPen(INK, max(1.5, 2.0 * u)))
        p.setBrush(QColor("#FFFFFF"))
        p.drawRoundedRect(body, icon_h * 0.22, icon_h * 0.22)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(INK)
        nub = QRectF(body.right() + 1, body.center().y() - icon_h * 0.2, icon_h * 0.16, icon_h * 0.4)
        p.drawRoundedRect(nub, 1.5, 1.5)
        inset = max(2.5, 3.0 * u)
        fill = body.adjusted(inset, inset, -inset, -inset)
        fill.setWidth(max(0.0, fill.width() * battery / 100.0))
        if fill.width() > 0.5:
            p.setBrush(_with_alpha(colour, blink))
            p.drawRoundedRect(fill, 2, 2)
        p.setPen(colour.darker(135) if battery < 50 else INK)
        p.setFont(font)
        p.drawText(QRectF(body.right() + pad * 0.9, rect.top(), half - icon_w - 1.9 * pad, rect.height()),
                   Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft, f"{battery:.0f}%")
        if not show_volume:
            return
        # volume: a loudspeaker with up to three waves
        left = rect.left() + half + pad * 0.5
        cy = rect.center().y()
        h = icon_h
        speaker = QPolygonF([QPointF(left, cy - h * 0.2), QPointF(left + h * 0.3, cy - h * 0.2),
                             QPointF(left + h * 0.65, cy - h * 0.5), QPointF(left + h * 0.65, cy + h * 0.5),
                             QPointF(left + h * 0.3, cy + h * 0.2), QPointF(left, cy + h * 0.2)])
        p.setPen(QPen(INK, 1.2))
        p.setBrush(INK)
        p.drawPolygon(speaker)
        waves = 0 if volume <= 0 else 1 if volume < 34 else 2 if volume < 67 else 3
        pen = QPen(INK, max(1.5, 1.8 * u))
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
        p.setPen(pen)
        p.setBrush(Qt.BrushStyle.NoBrush)
        for k in range(waves):
            p.drawPolyline(QPolygonF(_arc(left + h * 0.6, cy, h * (0.3 + 0.22 * k), -45, 45, 10)))
        if waves == 0:
            x = left + h * 0.9
            p.drawLine(QPointF(x, cy - h * 0.2), QPointF(x + h * 0.4, cy + h * 0.2))
            p.drawLine(QPointF(x, cy + h * 0.2), QPointF(x + h * 0.4, cy - h * 0.2))
        p.setPen(INK)
        p.setFont(font)
        p.drawText(QRectF(left + h * 1.45 + pad * 0.4, rect.top(), half - h * 1.45 - pad, rect.height()),
                   Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft, f"{volume:.0f}%")

    # tablet --------------------------------------------------------------------------------

    def _tablet_metrics(self, width, u):
        bezel = max(5.0, 7.0 * u)
        inner_pad = max(5.0, 8.0 * u)
        text_w = width - 2 * (bezel + inner_pad)
        return bezel, inner_pad, text_w

    def _hint_height(self, kind, text_w, u):
        if kind not in WAITING_KINDS:
            return 0.0
        small = self._font(11 * u, True)
        fm = QFontMetricsF(small)
        lines = len(_wrap_lines(self._texts()["waiting"] + " ...", small, text_w - fm.height() * 0.8 - 4)[:2])
        return lines * fm.lineSpacing() + max(4.0, 6.0 * u) + self._button_height(u) + max(4.0, 6.0 * u)

    def _tablet_height(self, width, u):
        tablet = self._tablet()
        bezel, inner_pad, text_w = self._tablet_metrics(width, u)
        if tablet is None:
            return QFontMetricsF(self._font(11 * u)).height() + 2 * (bezel + inner_pad)
        kind, text = tablet
        font = self._font(15 * u, True)
        lines = max(1, len(_wrap_lines(text, font, text_w)))
        text_h = lines * QFontMetricsF(font).lineSpacing()
        return text_h + self._hint_height(kind, text_w, u) + 2 * (bezel + inner_pad)

    def _fitted_text(self, text, width, height, max_px):
        """(font, lines) for ``text`` in width x height: the biggest size that fits, else elided."""
        key = (text, int(width), int(height), int(max_px), self._language)
        if key in self._text_cache:
            return self._text_cache[key]
        size = int(max(MIN_TEXT_PX, max_px))
        while True:
            font = self._font(size, bold=True)
            fm = QFontMetricsF(font)
            lines = _wrap_lines(text, font, width)
            if len(lines) * fm.lineSpacing() <= height + 0.5 or size <= MIN_TEXT_PX:
                break
            size -= 1
        fit = max(1, int((height + 0.5) // fm.lineSpacing()))
        if len(lines) > fit:
            lines = lines[:fit]
            lines[-1] = fm.elidedText(lines[-1] + " …………", Qt.TextElideMode.ElideRight, width)
        if len(self._text_cache) > 64:
            self._text_cache.clear()
        self._text_cache[key] = (font, lines)
        return font, lines

    def _paint_tablet(self, p, rect, u, phase):
        tablet = self._tablet()
        bezel, inner_pad, text_w = self._tablet_metrics(rect.width(), u)
        radius = max(8.0, 12.0 * u)
        waiting = tablet is not None and tablet[0] in WAITING_KINDS
        if waiting:
            glow = 0.35 + 0.35 * (0.5 + 0.5 * math.sin(phase * 4.0)) if self._animate else 0.6
            p.setPen(QPen(_with_alpha(QColor("#FFC83D"), glow), max(3.0, 4.0 * u)))
            p.setBrush(Qt.BrushStyle.NoBrush)
            p.drawRoundedRect(rect.adjusted(1, 1, -1, -1), radius, radius)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor("#343B52"))
        p.drawRoundedRect(rect.adjusted(2, 2, -2, -2), radius, radius)
        screen = rect.adjusted(bezel, bezel, -bezel, -bezel)
        screen_radius = max(4.0, radius - bezel * 0.6)
        if tablet is None:
            p.setBrush(QColor("#4A5270"))
            p.drawRoundedRect(screen, screen_radius, screen_radius)
            small = self._font(11 * u)
            p.setPen(QColor("#AEB5CE"))
            p.setFont(small)
            p.drawText(screen, Qt.AlignmentFlag.AlignCenter,
                       QFontMetricsF(small).elidedText(self._texts()["tablet_off"], Qt.TextElideMode.ElideRight,
                                                       screen.width() - 4))
            return
        kind, text = tablet
        gradient = QLinearGradient(screen.topLeft(), screen.bottomLeft())
        gradient.setColorAt(0, QColor("#FFFFFF"))
        gradient.setColorAt(1, QColor("#EEF4FF"))
        p.setBrush(QBrush(gradient))
        p.drawRoundedRect(screen, screen_radius, screen_radius)
        content = screen.adjusted(inner_pad, inner_pad, -inner_pad, -inner_pad)
        # in a small dock the hint shrinks to its buttons, then goes: the question comes first
        hint_h, caption = self._hint_height(kind, text_w, u), True
        one_line = QFontMetricsF(self._font(MIN_TEXT_PX, True)).lineSpacing()
        if hint_h and content.height() < hint_h + one_line:
            hint_h, caption = self._button_height(u) + max(4.0, 6.0 * u), False
            if content.height() < hint_h + one_line:
                hint_h = 0.0
        text_box = QRectF(content.left(), content.top(), content.width(), max(0.0, content.height() - hint_h))
        font, lines = self._fitted_text(text, text_box.width(), text_box.height(), 15 * u)
        fm = QFontMetricsF(font)
        p.setFont(font)
        p.setPen(INK)
        y = text_box.top()
        for line in lines:
            if y + fm.height() > text_box.bottom() + fm.descent() + 1:
                break
            p.drawText(QRectF(text_box.left(), y, text_box.width(), fm.height()),
                       Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, line)
            y += fm.lineSpacing()
        if kind in WAITING_KINDS and hint_h > 0:
            self._paint_answer_hint(p, QRectF(content.left(), content.bottom() - hint_h, content.width(), hint_h),
                                    kind, u, phase, caption)

    def _button_height(self, u):
        return QFontMetricsF(self._font(13 * u, True)).height() + max(6.0, 8.0 * u)

    def _paint_answer_hint(self, p, rect, kind, u, phase, caption=True):
        texts = self._texts()
        small = self._font(11 * u, True)
        fm = QFontMetricsF(small)
        gap = max(4.0, 6.0 * u)
        if caption:
            # hourglass + "waiting for your answer" with dots that come and go
            icon = fm.height() * 0.8
            top = rect.top() + gap
            self._paint_hourglass(p, QRectF(rect.left(), top + (fm.height() - icon) / 2, icon * 0.7, icon))
            dots = int(phase * 2.5) % 4 if self._animate else 3
            lines = _wrap_lines(texts["waiting"] + " ...", small, rect.width() - icon - 4)[:2]
            if lines and lines[-1].endswith("..."):
                lines[-1] = lines[-1][:-3] + "." * dots
            p.setPen(QColor("#6A4FD8"))
            p.setFont(small)
            for i, line in enumerate(lines):
                p.drawText(QRectF(rect.left() + icon, top + i * fm.lineSpacing(), rect.width() - icon, fm.height()),
                           Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, line)
        button_font = self._font(13 * u, True)
        bfm = QFontMetricsF(button_font)
        button_h = self._button_height(u)
        row = QRectF(rect.left(), rect.bottom() - button_h - gap * 0.3, rect.width(), button_h)
        p.setFont(button_font)
        if kind == "D_YES_NO":
            half = (row.width() - gap) / 2
            _button(p, QRectF(row.left(), row.top(), half, button_h), QColor("#2FBF71"), texts["yes"], bfm)
            _button(p, QRectF(row.left() + half + gap, row.top(), half, button_h), QColor("#FF5A5F"), texts["no"], bfm)
        elif kind == "D_OK":
            width = min(row.width(), max(bfm.horizontalAdvance(texts["ok"]) + 4 * gap, row.width() * 0.55))
            box = QRectF(row.center().x() - width / 2, row.top(), width, button_h)
            _button(p, box, QColor("#4D8DFF"), texts["ok"], bfm)
        else:
            p.setPen(QPen(QColor("#8E9BC4"), max(1.2, 1.5 * u)))
            p.setBrush(QColor("#FFFFFF"))
            p.drawRoundedRect(row, button_h * 0.3, button_h * 0.3)
            caret_on = (int(phase * 2) % 2 == 0) if self._animate else True
            x = row.left() + gap
            if caret_on:
                p.setPen(QPen(QColor("#6A4FD8"), 2))
                p.drawLine(QPointF(x, row.top() + button_h * 0.22), QPointF(x, row.bottom() - button_h * 0.22))
            hint_font = self._font(12 * u)
            p.setFont(hint_font)
            p.setPen(QColor("#9AA1B9"))
            p.drawText(row.adjusted(gap + 5, 0, -gap, 0), Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft,
                       QFontMetricsF(hint_font).elidedText(texts["type"], Qt.TextElideMode.ElideRight,
                                                           row.width() - 2 * gap - 5))

    def _paint_hourglass(self, p, rect):
        p.setPen(QPen(QColor("#6A4FD8"), 1.4))
        p.setBrush(QColor("#D9D0FF"))
        l, r, t, b, cx, cy = rect.left(), rect.right(), rect.top(), rect.bottom(), rect.center().x(), rect.center().y()
        p.drawPolygon(QPolygonF([QPointF(l, t), QPointF(r, t), QPointF(cx + 1, cy), QPointF(r, b), QPointF(l, b),
                                 QPointF(cx - 1, cy)]))

    def _paint_notice(self, p, rect, text, u, newest):
        sos = "sos" in text.lower()
        radius = rect.height() * 0.35
        font = self._font(12 * u, bold=sos or newest)
        fm = QFontMetricsF(font)
        pad = max(5.0, 7.0 * u)
        p.save()
        if not newest and not sos:
            p.setOpacity(0.78)
        if sos:
            p.setPen(Qt.PenStyle.NoPen)
            p.setBrush(SOS)
            p.drawRoundedRect(rect, radius, radius)
            badge = rect.height() * 0.62
            center = QPointF(rect.left() + pad + badge / 2, rect.center().y())
            p.setBrush(QColor("#FFFFFF"))
            p.drawEllipse(center, badge / 2, badge / 2)
            mark = QPen(SOS, max(2.0, badge * 0.14))
            mark.setCapStyle(Qt.PenCapStyle.RoundCap)
            p.setPen(mark)
            p.drawLine(QPointF(center.x(), center.y() - badge * 0.24), QPointF(center.x(), center.y() + badge * 0.05))
            p.drawPoint(QPointF(center.x(), center.y() + badge * 0.24))
            text_rect = rect.adjusted(pad * 1.6 + badge, 0, -pad, 0)
            p.setPen(QColor("#FFFFFF"))
        else:
            _card(p, rect, radius)
            p.setPen(Qt.PenStyle.NoPen)
            p.setBrush(QColor("#8C5CF0"))
            p.drawRoundedRect(QRectF(rect.left() + pad * 0.6, rect.top() + rect.height() * 0.25, max(3.0, 4 * u),
                                     rect.height() * 0.5), 2, 2)
            text_rect = rect.adjusted(pad * 1.2 + max(3.0, 4 * u), 0, -pad, 0)
            p.setPen(INK)
        p.setFont(font)
        p.drawText(text_rect, Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft,
                   fm.elidedText(text, Qt.TextElideMode.ElideRight, text_rect.width()))
        p.restore()

    # eyes ---------------------------------------------------------------------------------

    def _paint_eyes(self, p, face, emotion, phase):
        sleeping = emotion == "SLEEPING"
        radius = min(face.height() * 0.22, face.width() * 0.1)
        gradient = QLinearGradient(face.topLeft(), face.bottomLeft())
        base = FACE_BG_SLEEP if sleeping else FACE_BG
        gradient.setColorAt(0, base.lighter(118))
        gradient.setColorAt(1, base)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QBrush(gradient))
        p.drawRoundedRect(face, radius, radius)
        p.save()
        clip = QPainterPath()
        clip.addRoundedRect(face, radius, radius)
        p.setClipPath(clip)
        e = min(face.width() * 0.135, face.height() * 0.28)
        cy = face.center().y() + face.height() * 0.07
        s = self._shown
        look_x = max(-1.0, min(1.0, s["pan"] / math.radians(50))) * 0.35
        look_y = s["tilt"] * 0.3
        blink = 0.0
        if self._animate and emotion in ("NEUTRAL", "CONCERNED", "WONDERING", "LTIRED", "SAD"):
            t = phase % 3.7
            if t < 0.18:
                blink = 1.0 - abs(t - 0.09) / 0.09
        for side in (-1, 1):
            c = QPointF(face.center().x() + side * face.width() * 0.23, cy)
            self._paint_eye(p, c, e, side, emotion, look_x, look_y, blink)
        if emotion == "WONDERING":
            font = QFont(self.font())
            font.setPixelSize(max(MIN_TEXT_PX, int(e * 1.05)))
            font.setBold(True)
            p.setFont(font)
            p.setPen(QColor("#FFD84D"))
            p.drawText(QRectF(face.right() - face.width() * 0.13, face.top() + face.height() * 0.05,
                              face.width() * 0.12, e * 1.3), Qt.AlignmentFlag.AlignCenter, "?")
        if sleeping:
            rise = (phase * 0.35) % 1.0 if self._animate else 0.3
            for k, (size, dx) in enumerate(((0.7, 0.0), (1.0, 0.5))):
                t = (rise + k * 0.5) % 1.0
                font = QFont(self.font())
                font.setPixelSize(max(MIN_TEXT_PX, int(e * size)))
                font.setBold(True)
                p.setFont(font)
                p.setPen(_with_alpha(QColor("#C9D3FF"), 0.25 + 0.75 * math.sin(math.pi * t) if self._animate else 1.0))
                x = face.right() - face.width() * (0.24 - 0.14 * dx) + t * e * 0.2
                y = cy - e * (0.5 + 0.6 * k) - t * e * 0.35
                p.drawText(QPointF(x, y), "z" if k == 0 else "Z")
        p.restore()

    def _paint_eye(self, p, c, e, side, emotion, look_x, look_y, blink):
        """One eye at ``c`` with radius ``e``; ``side`` -1 = the left one on screen."""
        white = QColor("#FFFFFF")
        if emotion in ("HAPPY", "VHAPPY"):
            very = emotion == "VHAPPY"
            r = e * (1.2 if very else 1.1)
            center_y = c.y() + e * (0.55 if very else 0.5)
            pen = QPen(white, e * (0.38 if very else 0.33))
            pen.setCapStyle(Qt.PenCapStyle.RoundCap)
            p.setPen(pen)
            p.setBrush(Qt.BrushStyle.NoBrush)
            p.drawPolyline(QPolygonF(_arc(c.x(), center_y, r, 12 if very else 25, 168 if very else 155, 24)))
            if very:
                p.setPen(Qt.PenStyle.NoPen)
                p.setBrush(QColor(255, 120, 160, 185))
                p.drawEllipse(QPointF(c.x() + side * e * 0.35, c.y() + e * 0.95), e * 0.48, e * 0.24)
                _paint_star(p, QPointF(c.x() + side * e * 1.25, c.y() - e * 0.75), e * 0.28, QColor("#FFE066"))
            return
        if emotion == "SLEEPING":
            pen = QPen(QColor("#AFC0F2"), e * 0.2)
            pen.setCapStyle(Qt.PenCapStyle.RoundCap)
            p.setPen(pen)
            p.setBrush(Qt.BrushStyle.NoBrush)
            center_y = c.y() - e * 0.25
            p.drawPolyline(QPolygonF(_arc(c.x(), center_y, e * 0.8, 200, 340, 24)))
            lash = QPen(QColor("#AFC0F2"), e * 0.1)
            lash.setCapStyle(Qt.PenCapStyle.RoundCap)
            p.setPen(lash)
            for a in (230, 270, 310):
                rad = math.radians(a)
                inner = QPointF(c.x() + e * 0.8 * math.cos(rad), center_y - e * 0.8 * math.sin(rad))
                outer = QPointF(c.x() + e * 1.08 * math.cos(rad), center_y - e * 1.08 * math.sin(rad))
                p.drawLine(inner, outer)
            return
        # open eyes: sclera, iris, pupil, highlights, then lids and brows
        iris, pupil, gaze_x, gaze_y = 0.56, 0.3, look_x, look_y
        lid, slant, lower = 0.06, 0.0, 0.0
        size = e
        if emotion == "LTIRED":
            lid, gaze_y = 0.46, gaze_y + 0.2
        elif emotion == "VTIRED":
            lid, lower, gaze_y = 0.68, 0.16, gaze_y + 0.3
        elif emotion == "CONCERNED":
            pupil, gaze_y = 0.26, gaze_y - 0.15
        elif emotion == "SAD":
            lid, slant, gaze_y = 0.3, 0.42, gaze_y + 0.35
        elif emotion == "WONDERING":
            size, iris, pupil = e * 1.08, 0.7, 0.42
            gaze_x, gaze_y = gaze_x + 0.3, gaze_y - 0.3
        lid = max(lid, blink)
        gaze_x, gaze_y = max(-0.6, min(0.6, gaze_x)), max(-0.6, min(0.6, gaze_y))
        # the visible part of the eye: the ball minus the lids, so no white seams remain
        eye = QPainterPath()
        eye.addEllipse(c, size, size * 1.04)
        top, bottom = c.y() - size * 1.05, c.y() + size * 1.05
        visible = QPainterPath(eye)
        lid_lines = []
        if lid > 0.08:
            # "slant" lowers the lid's outer end (sad)
            a = QPointF(c.x() - side * size * 1.2, top + 2.1 * size * max(0.0, lid - slant * 0.5))
            b = QPointF(c.x() + side * size * 1.2, top + 2.1 * size * min(1.0, lid + slant * 0.5))
            cover = QPainterPath()
            cover.addPolygon(QPolygonF([QPointF(a.x(), top - 2), QPointF(b.x(), top - 2), b, a]))
            cover.closeSubpath()
            visible = visible.subtracted(cover)
            lid_lines.append((a, b))
        if lower > 0:
            y = bottom - 2.1 * size * lower
            cover = QPainterPath()
            cover.addRect(QRectF(c.x() - size * 1.2, y, size * 2.4, bottom - y + 2))
            visible = visible.subtracted(cover)
            lid_lines.append((QPointF(c.x() - size * 1.2, y), QPointF(c.x() + size * 1.2, y)))
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(white)
        p.drawPath(visible)

        def disc(center, radius, brush):
            shape = QPainterPath()
            shape.addEllipse(center, radius, radius)
            p.setBrush(brush)
            p.drawPath(shape.intersected(visible))

        ic = QPointF(c.x() + gaze_x * size * 0.55, c.y() + gaze_y * size * 0.55)
        gradient = QRadialGradient(ic, size * iris)
        gradient.setColorAt(0, IRIS)
        gradient.setColorAt(1, IRIS_DARK)
        disc(ic, size * iris, QBrush(gradient))
        disc(ic, size * pupil, QColor("#0E1630"))
        disc(QPointF(ic.x() - size * iris * 0.35, ic.y() - size * iris * 0.38), size * 0.16, white)
        disc(QPointF(ic.x() + size * iris * 0.35, ic.y() + size * iris * 0.35), size * 0.07, white)
        stroker = QPainterPathStroker()
        stroker.setWidth(size * 0.12)
        p.setBrush(LID_EDGE)
        for a, b in lid_lines:
            line = QPainterPath(a)
            line.lineTo(b)
            p.drawPath(stroker.createStroke(line).intersected(eye))
        brow = None
        if emotion == "CONCERNED":
            brow = (-0.42, 0.12, 0.0)
        elif emotion == "SAD":
            brow = (-0.3, 0.2, 0.0)
        elif emotion == "WONDERING":
            brow = (-0.45, -0.45, -0.22) if side > 0 else (0.05, 0.05, 0.0)
        if brow is not None:
            inner_dy, outer_dy, bend = brow
            base_y = c.y() - size * 1.38
            inner = QPointF(c.x() - side * size * 0.75, base_y + inner_dy * size)
            outer = QPointF(c.x() + side * size * 0.75, base_y + outer_dy * size)
            control = QPointF(c.x(), (inner.y() + outer.y()) / 2 - size * (0.15 - bend))
            path = QPainterPath(inner)
            path.quadTo(control, outer)
            pen = QPen(QColor("#E6ECFF"), size * 0.24)
            pen.setCapStyle(Qt.PenCapStyle.RoundCap)
            p.setPen(pen)
            p.setBrush(Qt.BrushStyle.NoBrush)
            p.drawPath(path)
        if emotion == "SAD" and side < 0:
            # a tear under the outer corner of one eye
            x, y, r = c.x() - size * 0.7, c.y() + size * 1.05, size * 0.2
            path = QPainterPath(QPointF(x, y - size * 0.32))
            path.cubicTo(QPointF(x + r * 0.25, y - size * 0.15), QPointF(x + r, y - size * 0.02), QPointF(x + r, y + r * 0.4))
            path.arcTo(QRectF(x - r, y - r * 0.6, 2 * r, 2 * r), 0, -180)
            path.cubicTo(QPointF(x - r, y - size * 0.02), QPointF(x - r * 0.25, y - size * 0.15), QPointF(x, y - size * 0.32))
            p.setPen(Qt.PenStyle.NoPen)
            p.setBrush(QColor("#7CC8FF"))
            p.drawPath(path)


# --- room pieces (map frame, metres) --------------------------------------------------------

LAWN = QColor("#D3EDC5")
WOOD = (QColor("#F5DDB6"), QColor("#F1D6A9"), QColor("#F7E3C1"), QColor("#F2D9AF"))
SEAM = QColor(196, 150, 95, 90)
WALL_FILL = QColor("#8E86CF")
WALL_EDGE = QColor("#6C64AE")
GRID = QColor(110, 80, 40, 42)
DOOR = (2.3, 3.2)          # gap in the bottom wall, x from..to
WINDOW = (2.7, 4.5)        # glass in the top wall, x from..to


def _paint_lawn(p, rect):
    p.fillRect(rect, LAWN)


def _paint_garden(p, shown):
    """Grass tufts and little flowers on the lawn around the house."""
    x0, y0, x1, y1 = ROOM
    step = 0.55
    tuft = QPen(QColor("#9CD18A"), 0.022)
    tuft.setCapStyle(Qt.PenCapStyle.RoundCap)
    petals = (QColor("#FFFFFF"), QColor("#FFD166"), QColor("#FF9EC4"), QColor("#B9A5FF"))
    for ix in range(math.floor(shown["bx0"] / step) - 1, math.ceil(shown["bx1"] / step) + 2):
        for iy in range(math.floor(shown["by0"] / step) - 1, math.ceil(shown["by1"] / step) + 2):
            h = ((ix * 73856093) ^ (iy * 19349663)) & 0xFFFF
            x = (ix + (h % 97) / 97.0) * step
            y = (iy + ((h >> 7) % 89) / 89.0) * step
            if x0 - WALL - 0.08 < x < x1 + WALL + 0.08 and y0 - WALL - 0.08 < y < y1 + WALL + 0.08:
                continue
            if h % 5 == 0:
                p.setPen(Qt.PenStyle.NoPen)
                p.setBrush(petals[(h >> 3) % len(petals)])
                for k in range(5):
                    a = math.radians(k * 72 + h % 60)
                    p.drawEllipse(QPointF(x + 0.035 * math.cos(a), y + 0.035 * math.sin(a)), 0.028, 0.028)
                p.setBrush(QColor("#FFB020"))
                p.drawEllipse(QPointF(x, y), 0.022, 0.022)
            else:
                p.setPen(tuft)
                for dx, lean in ((-0.03, -0.03), (0.0, 0.0), (0.03, 0.03)):
                    p.drawLine(QPointF(x + dx, y), QPointF(x + dx + lean, y + 0.07 - abs(dx)))


def _paint_floor(p):
    x0, y0, x1, y1 = ROOM
    plank = 0.2
    p.setPen(Qt.PenStyle.NoPen)
    rows = int(round((y1 - y0) / plank))
    for row in range(rows):
        y = y0 + row * plank
        x = x0 - (row * 0.73) % 1.6
        k = 0
        while x < x1:
            length = 1.1 + ((row * 7 + k * 3) % 5) * 0.18
            left, right = max(x, x0), min(x + length, x1)
            if right > left:
                p.setBrush(WOOD[(row * 3 + k) % len(WOOD)])
                p.drawRect(QRectF(left, y, right - left, plank))
            x += length
            k += 1
    seam = QPen(SEAM, 1.0)
    seam.setCosmetic(True)
    p.setPen(seam)
    for row in range(1, rows):
        y = y0 + row * plank
        p.drawLine(QPointF(x0, y), QPointF(x1, y))
    for row in range(rows):
        y = y0 + row * plank
        x = x0 - (row * 0.73) % 1.6
        k = 0
        while x < x1:
            x += 1.1 + ((row * 7 + k * 3) % 5) * 0.18
            k += 1
            if x0 < x < x1:
                p.drawLine(QPointF(x, y), QPointF(x, y + plank))


def _shadowed(p, draw, offset=(0.035, -0.05)):
    """Draw a shape once as a soft shadow, then for real."""
    p.save()
    p.translate(*offset)
    draw(p, True)
    p.restore()
    draw(p, False)


def _paint_furniture(p):
    thin = QPen(QColor(0, 0, 0, 60), 1.0)
    thin.setCosmetic(True)
    shadow = QColor(40, 30, 20, 40)

    # rug in front of the sofa
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor("#CDEBDF"))
    p.drawRoundedRect(QRectF(0.2, 0.45, 1.8, 0.95), 0.3, 0.3)
    dots = QPen(QColor("#FFFFFF"), 0.035)
    dots.setDashPattern([0.4, 1.6])
    dots.setCapStyle(Qt.PenCapStyle.RoundCap)
    p.setPen(dots)
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawRoundedRect(QRectF(0.3, 0.55, 1.6, 0.75), 0.22, 0.22)

    def sofa(p, is_shadow):
        p.setPen(Qt.PenStyle.NoPen if is_shadow else thin)
        p.setBrush(shadow if is_shadow else QColor("#F2857A"))
        p.drawRoundedRect(QRectF(0.1, 1.6, 2.0, 0.82), 0.12, 0.12)
        if is_shadow:
            return
        p.setBrush(QColor("#DD6C62"))
        p.drawRoundedRect(QRectF(0.1, 2.17, 2.0, 0.25), 0.1, 0.1)
        p.drawRoundedRect(QRectF(0.1, 1.6, 0.24, 0.82), 0.1, 0.1)
        p.drawRoundedRect(QRectF(1.86, 1.6, 0.24, 0.82), 0.1, 0.1)
        p.setBrush(QColor("#F8A196"))
        p.drawRoundedRect(QRectF(0.38, 1.66, 0.7, 0.5), 0.08, 0.08)
        p.drawRoundedRect(QRectF(1.12, 1.66, 0.7, 0.5), 0.08, 0.08)
        p.setBrush(QColor("#FFD166"))
        p.save()
        p.translate(0.55, 2.02)
        p.rotate(-12)
        p.drawRoundedRect(QRectF(-0.13, -0.1, 0.26, 0.2), 0.06, 0.06)
        p.restore()
        p.setBrush(QColor("#8FD3F0"))
        p.save()
        p.translate(1.66, 2.02)
        p.rotate(10)
        p.drawRoundedRect(QRectF(-0.13, -0.1, 0.26, 0.2), 0.06, 0.06)
        p.restore()

    def table(p, is_shadow):
        p.setPen(Qt.PenStyle.NoPen if is_shadow else thin)
        for cx in (3.4, 4.0):   # chairs tucked in on the wall side
            p.setBrush(shadow if is_shadow else QColor("#7DC4E4"))
            p.drawRoundedRect(QRectF(cx - 0.2, 1.55, 0.4, 0.45), 0.08, 0.08)
            if not is_shadow:
                p.setBrush(QColor("#5AA8CC"))
                p.drawRoundedRect(QRectF(cx - 0.2, 1.9, 0.4, 0.1), 0.04, 0.04)
        p.setBrush(shadow if is_shadow else QColor("#C98A57"))
        p.drawRoundedRect(QRectF(3.1, 0.75, 1.2, 0.9), 0.08, 0.08)
        if is_shadow:
            return
        p.setBrush(QColor("#D9A06D"))
        p.drawRoundedRect(QRectF(3.16, 0.81, 1.08, 0.78), 0.06, 0.06)
        # a fruit bowl
        p.setBrush(QColor("#FFFFFF"))
        p.drawEllipse(QPointF(3.7, 1.2), 0.17, 0.17)
        p.setPen(Qt.PenStyle.NoPen)
        for (dx, dy), colour in (((-0.06, 0.04), "#FF5D5D"), ((0.06, 0.05), "#FFB020"), ((0.0, -0.06), "#6CCB5F")):
            p.setBrush(QColor(colour))
            p.drawEllipse(QPointF(3.7 + dx, 1.2 + dy), 0.055, 0.055)

    def shelf(p, is_shadow):
        p.setPen(Qt.PenStyle.NoPen if is_shadow else thin)
        p.setBrush(shadow if is_shadow else QColor("#A8764E"))
        p.drawRect(QRectF(4.58, -2.0, 0.42, 1.5))
        if is_shadow:
            return
        p.setBrush(QColor("#C79466"))
        p.drawRect(QRectF(4.62, -1.96, 0.34, 1.42))
        p.setPen(Qt.PenStyle.NoPen)
        colours = ("#FF6B6B", "#4D8DFF", "#FFD166", "#2EC4B6", "#B084F5", "#FF9F43", "#6CCB5F")
        y = -1.93
        k = 0
        while y < -0.6:
            h = 0.06 + (k * 5 % 4) * 0.02
            p.setBrush(QColor(colours[k % len(colours)]))
            depth = 0.24 + (k % 3) * 0.03
            p.drawRect(QRectF(4.95 - depth, y, depth, h))
            y += h + 0.012
            k += 1

    def plant(p, is_shadow, at=(-0.62, 2.1)):
        x, y = at
        p.setPen(Qt.PenStyle.NoPen)
        if is_shadow:
            p.setBrush(shadow)
            p.drawEllipse(QPointF(x, y), 0.3, 0.3)
            return
        p.setBrush(QColor("#E07A4F"))
        p.drawEllipse(QPointF(x, y), 0.17, 0.17)
        for k in range(7):
            a = math.radians(k * 360 / 7 + 10)
            p.setBrush(QColor("#4CB862") if k % 2 else QColor("#6FD07B"))
            p.save()
            p.translate(x + math.cos(a) * 0.13, y + math.sin(a) * 0.13)
            p.rotate(math.degrees(a))
            p.drawEllipse(QPointF(0, 0), 0.17, 0.075)
            p.restore()
        p.setBrush(QColor("#3A9E50"))
        p.drawEllipse(QPointF(x, y), 0.06, 0.06)

    def ball(p, is_shadow, at=(-0.55, -2.05)):
        x, y = at
        p.setPen(Qt.PenStyle.NoPen)
        if is_shadow:
            p.setBrush(shadow)
            p.drawEllipse(QPointF(x, y), 0.14, 0.14)
            return
        for k, colour in enumerate(("#FF5D5D", "#FFFFFF", "#4D8DFF", "#FFFFFF", "#FFD166", "#FFFFFF")):
            path = QPainterPath(QPointF(x, y))
            for point in _arc(x, y, 0.14, k * 60, (k + 1) * 60, 6, y_down=False):
                path.lineTo(point)
            path.closeSubpath()
            p.setBrush(QColor(colour))
            p.drawPath(path)

    _shadowed(p, sofa)
    _shadowed(p, table)
    _shadowed(p, shelf)
    _shadowed(p, plant)
    _shadowed(p, lambda painter, s: plant(painter, s, at=(4.65, 2.1)))
    _shadowed(p, ball)


def _paint_walls(p):
    x0, y0, x1, y1 = ROOM
    t = WALL
    edge = QPen(WALL_EDGE, 1.2)
    edge.setCosmetic(True)
    pieces = [QRectF(x0 - t, y1, x1 - x0 + 2 * t, t), QRectF(x0 - t, y0 - t, t, y1 - y0 + 2 * t),
              QRectF(x1, y0 - t, t, y1 - y0 + 2 * t),
              QRectF(x0 - t, y0 - t, DOOR[0] - x0 + t, t), QRectF(DOOR[1], y0 - t, x1 + t - DOOR[1], t)]
    p.setPen(edge)
    p.setBrush(WALL_FILL)
    for piece in pieces:
        p.drawRect(piece)
    # window in the top wall
    p.setBrush(QColor("#BFE6FF"))
    p.drawRect(QRectF(WINDOW[0], y1 + t * 0.25, WINDOW[1] - WINDOW[0], t * 0.5))
    glass = QPen(QColor("#FFFFFF"), 1.5)
    glass.setCosmetic(True)
    p.setPen(glass)
    mid = (WINDOW[0] + WINDOW[1]) / 2
    p.drawLine(QPointF(mid, y1 + t * 0.3), QPointF(mid, y1 + t * 0.7))
    # door, swung open into the room
    width = DOOR[1] - DOOR[0]
    swing = QPen(QColor(110, 100, 170, 110), 1.2)
    swing.setCosmetic(True)
    swing.setDashPattern([3, 3])
    p.setPen(swing)
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawPolyline(QPolygonF(_arc(DOOR[0], y0, width, 0, 90, 16, y_down=False)))
    p.setPen(edge)
    p.setBrush(QColor("#C79466"))
    p.drawRect(QRectF(DOOR[0] - 0.02, y0, 0.05, width))


def _paint_grid(p, shown, scale):
    pen = QPen(GRID, 1.0)
    pen.setCosmetic(True)
    p.setPen(pen)
    for x in range(math.ceil(shown["bx0"]), math.floor(shown["bx1"]) + 1):
        p.drawLine(QPointF(x, shown["by0"] - 1), QPointF(x, shown["by1"] + 1))
    for y in range(math.ceil(shown["by0"]), math.floor(shown["by1"]) + 1):
        p.drawLine(QPointF(shown["bx0"] - 1, y), QPointF(shown["bx1"] + 1, y))


def _paint_origin(p, scale):
    """Small x (red) and y (green) arrows at the map origin, for whoever wants coordinates."""
    length = 0.38
    for (dx, dy), colour in (((1, 0), QColor(230, 70, 70, 150)), ((0, 1), QColor(40, 170, 90, 150))):
        pen = QPen(colour, max(0.018, 2.0 / scale))
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
        p.setPen(pen)
        end = QPointF(dx * length, dy * length)
        p.drawLine(QPointF(0, 0), end)
        head = 0.07
        p.drawLine(end, QPointF(end.x() - dx * head - dy * head * 0.6, end.y() - dy * head - dx * head * 0.6))
        p.drawLine(end, QPointF(end.x() - dx * head + dy * head * 0.6, end.y() - dy * head + dx * head * 0.6))


# --- little drawing helpers (widget pixels) ----------------------------------------------

def _card(p, rect, radius, accent=None):
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor(60, 70, 120, 28))
    p.drawRoundedRect(rect.translated(0, 2), radius, radius)
    p.setBrush(CARD)
    if accent is not None:
        p.setPen(QPen(accent, 2.5))
    p.drawRoundedRect(rect, radius, radius)


def _chip(p, rect):
    p.setPen(QPen(QColor(60, 70, 120, 40), 1))
    p.setBrush(QColor(255, 255, 255, 225))
    p.drawRoundedRect(rect, rect.height() / 2, rect.height() / 2)


def _button(p, rect, colour, label, fm):
    radius = rect.height() / 2
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(colour.darker(125))
    p.drawRoundedRect(rect.translated(0, 2), radius, radius)
    p.setBrush(colour)
    p.drawRoundedRect(rect, radius, radius)
    p.setPen(QColor("#FFFFFF"))
    p.drawText(rect, Qt.AlignmentFlag.AlignCenter, fm.elidedText(label, Qt.TextElideMode.ElideRight, rect.width() - 6))


def _paint_star(p, center, radius, colour):
    points = []
    for k in range(8):
        r = radius if k % 2 == 0 else radius * 0.38
        a = math.radians(90 + k * 45)
        points.append(QPointF(center.x() + r * math.cos(a), center.y() - r * math.sin(a)))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(colour)
    p.drawPolygon(QPolygonF(points))
