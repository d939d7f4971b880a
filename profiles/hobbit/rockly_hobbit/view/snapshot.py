"""What a snapshot may say, its defaults, and reading it without trusting it.

Any value may be missing, of the wrong type, NaN or endless; the readers here turn each
into something drawable (a default, a clamped float, cleaned text) and never raise.
"""
from rockly_desktop.sdk import as_number, as_point, as_points, with_defaults

num = as_number    # value as a finite float, clamped: num(value, default=0.0, lo=None, hi=None)
point = as_point   # an (x, y) pair of finite floats, or None

EMOTIONS = ("HAPPY", "VHAPPY", "LTIRED", "VTIRED", "CONCERNED", "SAD", "WONDERING", "NEUTRAL", "SLEEPING")
WAITING_KINDS = ("D_YES_NO", "D_OK", "D_NAME")

DEFAULT_SNAPSHOT = {
    "x": 0.0, "y": 0.0, "theta": 0.0, "trail": [], "linear": 0.0, "angular": 0.0, "motion": "idle",
    "nav_goal": None, "head": "center_center", "emotion": "NEUTRAL", "arm": "home", "arm_target": None,
    "arm_progress": 0.0, "gripper": "closed", "turntable": "stored", "turntable_angle": 0.0,
    "battery": 100.0, "volume": 50.0, "tablet": None, "notices": [], "time": 0.0,
}


def merged(snapshot):
    """The defaults overlaid with ``snapshot`` (anything but a dict counts as empty)."""
    return with_defaults(snapshot, DEFAULT_SNAPSHOT)


def clean_text(text):
    """Text safe to lay out: newlines kept, tabs as spaces, other control characters dropped."""
    text = str(text).replace("\r\n", "\n").replace("\r", "\n").replace("\t", "    ")
    return "".join(ch for ch in text if ch == "\n" or ord(ch) >= 32)


def trail(snapshot):
    """The last 500 valid trail points, oldest first."""
    return as_points(snapshot.get("trail"), 500)


def emotion(snapshot):
    """One of EMOTIONS; anything else is NEUTRAL."""
    name = str(snapshot.get("emotion") or "NEUTRAL").upper()
    return name if name in EMOTIONS else "NEUTRAL"


def notices(snapshot):
    """The last 20 notices as one-line texts, oldest first."""
    items = snapshot.get("notices") or []
    if isinstance(items, str):
        items = [items]
    try:
        return [clean_text(n).replace("\n", " ") for n in list(items)[-20:]]
    except TypeError:
        return []


def is_sos(notice):
    return "sos" in notice.lower()


def sos_active(snapshot):
    """True while the newest notice is about an SOS call."""
    items = notices(snapshot)
    return bool(items) and is_sos(items[-1])


def tablet(snapshot):
    """(kind, text) on the tablet, or None when it is off."""
    value = snapshot.get("tablet")
    if not isinstance(value, dict):
        return None
    return str(value.get("kind") or "D_PLAIN"), clean_text(value.get("text") or "")
