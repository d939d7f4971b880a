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
        """The limits a run on this profile's robot keeps to."""
        return Limits(self._number(f"{profile_id}/max_speed"), self._number(f"{profile_id}/max_turn"),
                      frozenset(self.switched_off(profile_id)))

    def set_limits(self, profile_id: str, max_speed=None, max_turn=None, switched_off=()):
        """Remember maximum speeds (m/s, °/s; None: no limit) and the capability ids switched off."""
        self._set(f"{profile_id}/max_speed", max_speed or "")
        self._set(f"{profile_id}/max_turn", max_turn or "")
        self._set(f"{profile_id}/switched_off", ",".join(sorted(switched_off)))

    def switched_off(self, profile_id: str) -> list:
        """Ids of the capabilities switched off for the profile."""
        return [name for name in str(self._get(f"{profile_id}/switched_off", "")).split(",") if name]
