"""A teacher's settings per robot profile: toolbox level, maximum speeds, capabilities switched
off; and the PIN that guards them, kept only as a salted PBKDF2 hash."""
import hashlib
import hmac
import os

from rockly_desktop.robot.limits import Limits

_ITERATIONS = 200_000
MIN_PIN_LENGTH = 4


def _hash(pin: str, salt: bytes) -> str:
    return hashlib.pbkdf2_hmac("sha256", pin.encode("utf-8"), salt, _ITERATIONS).hex()


class TeacherSettings:
    """The teacher's part of Rockly's QSettings ``store`` (keys under ``teacher/``)."""

    def __init__(self, store):
        self._store = store

    def _get(self, key, default=None):
        value = self._store.value(f"teacher/{key}")
        return default if value is None or value == "" else value

    def _set(self, key, value):
        self._store.setValue(f"teacher/{key}", value)

    # --- the PIN ------------------------------------------------------------------------

    @property
    def has_pin(self) -> bool:
        """True once a PIN was set."""
        return self._get("pin") is not None

    def set_pin(self, pin: str):
        """Keep a hash of ``pin`` (with a new random salt), never the PIN itself."""
        salt = os.urandom(16)
        self._set("pin", f"pbkdf2_sha256${_ITERATIONS}${salt.hex()}${_hash(pin, salt)}")

    def check_pin(self, pin: str) -> bool:
        """True when ``pin`` is the PIN that was set."""
        stored = str(self._get("pin", ""))
        try:
            _scheme, _iterations, salt, expected = stored.split("$")
            return hmac.compare_digest(_hash(pin, bytes.fromhex(salt)), expected)
        except ValueError:
            return False

    # --- per profile ----------------------------------------------------------------------

    def level(self, profile_id: str):
        """The toolbox level chosen for the profile, or None (the whole toolbox)."""
        return self._get(f"{profile_id}/level")

    def set_level(self, profile_id: str, level_id):
        """Remember the toolbox level (None: the whole toolbox)."""
        self._set(f"{profile_id}/level", level_id or "")

    def _number(self, key):
        try:
            value = float(self._get(key))
        except (TypeError, ValueError):
            return None
        return value if value > 0 else None

    def limits(self, profile_id: str) -> Limits:
        """The limits a run on this profile's robot keeps to: its own, or, for a profile the teacher
        set none for (a new one, a copy under another id), ``default_limits``."""
        if not self.has_own_limits(profile_id):
            return self.default_limits()
        return self._own_limits(profile_id)

    def _own_limits(self, profile_id: str) -> Limits:
        return Limits(self._number(f"{profile_id}/max_speed"), self._number(f"{profile_id}/max_turn"),
                      frozenset(self._own_switched_off(profile_id)))

    def has_own_limits(self, profile_id: str) -> bool:
        """True once limits were set for this profile (even none at all: the teacher's choice)."""
        return self._store.value(f"teacher/{profile_id}/switched_off") is not None

    def limited_profiles(self) -> list:
        """Ids of the profiles limits were set for."""
        listed = [name for name in str(self._get("limited_profiles", "")).split(",") if name]
        keys = getattr(self._store, "allKeys", list)()  # settings kept before the list was
        found = [key.split("/")[1] for key in keys if key.startswith("teacher/") and key.endswith("/switched_off")]
        return sorted({*listed, *found})

    def default_limits(self) -> Limits:
        """The limits of a profile without its own: the strictest any profile has (the lowest speeds,
        every capability id switched off anywhere: it holds wherever a profile has that id, so a copy
        of a robot's profile keeps its parts off). Nothing limited while no profile is."""
        own = [self._own_limits(profile_id) for profile_id in self.limited_profiles()]
        speeds = [limits.max_speed for limits in own if limits.max_speed is not None]
        turns = [limits.max_turn for limits in own if limits.max_turn is not None]
        return Limits(min(speeds, default=None), min(turns, default=None),
                      frozenset().union(*(limits.switched_off for limits in own)))

    def set_limits(self, profile_id: str, max_speed=None, max_turn=None, switched_off=()):
        """Remember maximum speeds (m/s, °/s; None: no limit) and the capability ids switched off."""
        self._set(f"{profile_id}/max_speed", max_speed or "")
        self._set(f"{profile_id}/max_turn", max_turn or "")
        self._set(f"{profile_id}/switched_off", ",".join(sorted(switched_off)))
        self._set("limited_profiles", ",".join(sorted({*self.limited_profiles(), profile_id})))

    def switched_off(self, profile_id: str) -> list:
        """Ids of the capabilities switched off for the profile (``default_limits``' when it has none of its own)."""
        return sorted(self.limits(profile_id).switched_off)

    def _own_switched_off(self, profile_id: str) -> list:
        return [name for name in str(self._get(f"{profile_id}/switched_off", "")).split(",") if name]
