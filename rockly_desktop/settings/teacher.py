"""A teacher's settings per robot profile: toolbox level, maximum speeds, capabilities switched
off; whether the robot choice is locked; and the PIN that guards them, kept only as a salted
PBKDF2 hash.

Wrong PINs cost time: from the third wrong one in a row the next PIN is taken only after a
wait that doubles with every further wrong one (5 s, 10 s, 20 s … at most 15 minutes), so
guessing a 4-digit PIN by script takes months instead of minutes. The count and the end of
the wait are kept in the settings file, so closing the dialog or restarting Rockly does not
shorten the wait.
"""
import hashlib
import hmac
import math
import os
import time
from dataclasses import dataclass

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.settings.group import SettingsGroup

_ITERATIONS = 200_000
MIN_PIN_LENGTH = 4
FREE_WRONG_PINS = 2      # typing slips that cost nothing
FIRST_WAIT_SECONDS = 5.0
MAX_WAIT_SECONDS = 15 * 60


def _hash(pin: str, salt: bytes) -> str:
    return hashlib.pbkdf2_hmac("sha256", pin.encode("utf-8"), salt, _ITERATIONS).hex()


def wait_after(wrong_pins: int) -> float:
    """Seconds before the next PIN is taken after ``wrong_pins`` wrong ones in a row."""
    if wrong_pins <= FREE_WRONG_PINS:
        return 0.0
    return min(MAX_WAIT_SECONDS, FIRST_WAIT_SECONDS * 2 ** min(wrong_pins - FREE_WRONG_PINS - 1, 16))


@dataclass(frozen=True)
class PinAnswer:
    """What a PIN typed got: ``right``; ``wait``, seconds before the next PIN is taken; ``refused``
    when the PIN was not looked at because an earlier wait had not passed."""

    right: bool
    wait: float = 0.0
    refused: bool = False

    def problem(self, language: str) -> str:
        """What to tell the person ("" for a right PIN)."""
        if self.right:
            return ""
        if self.refused:
            return wait_text(self.wait, language)
        wrong = app_text("teacher_wrong_pin", language)
        return f"{wrong} {wait_text(self.wait, language)}" if self.wait > 0 else wrong


def wait_text(seconds: float, language: str) -> str:
    """'Too many wrong PINs: the next one is taken in … seconds' (or '… min … s' from a minute on) in ``language``."""
    whole = max(1, math.ceil(seconds))
    if whole >= 60:
        return app_text("teacher_pin_wait_min_s", language, minutes=whole // 60, seconds=whole % 60)
    return app_text("teacher_pin_wait_second" if whole == 1 else "teacher_pin_wait_seconds", language, seconds=whole)


class TeacherSettings(SettingsGroup):
    """The teacher's part of Rockly's QSettings ``store`` (keys under ``teacher/``)."""

    prefix = "teacher"

    # --- the PIN ------------------------------------------------------------------------

    @property
    def has_pin(self) -> bool:
        """True once a PIN was set."""
        return self._get("pin") is not None

    def set_pin(self, pin: str):
        """Keep a hash of ``pin`` (with a new random salt), never the PIN itself; wrong PINs are forgotten."""
        salt = os.urandom(16)
        self._set("pin", f"pbkdf2_sha256${_ITERATIONS}${salt.hex()}${_hash(pin, salt)}")
        self._count_wrong_pins(0)

    def try_pin(self, pin: str) -> PinAnswer:
        """Check ``pin`` against the PIN that was set, unless a wait after wrong PINs has not passed."""
        wait = self.pin_wait()
        if wait > 0:
            return PinAnswer(False, wait, refused=True)
        if self._matches(pin):
            self._count_wrong_pins(0)
            return PinAnswer(True)
        wrong = self._wrong_pins() + 1
        self._count_wrong_pins(wrong)
        return PinAnswer(False, wait_after(wrong))

    def pin_wait(self) -> float:
        """Seconds until the next PIN is taken (0: now)."""
        try:
            left = float(self._get("pin_wait_until", 0)) - time.time()
        except (TypeError, ValueError):
            left = MAX_WAIT_SECONDS  # a damaged entry does not open the lock
        if left > MAX_WAIT_SECONDS:  # the clock was put back: the wait starts again, no longer than the longest
            left = MAX_WAIT_SECONDS
            self._set("pin_wait_until", time.time() + left)
        return max(0.0, left)

    def _wrong_pins(self) -> int:
        try:
            return max(0, int(self._get("wrong_pins", 0)))
        except (TypeError, ValueError):
            return FREE_WRONG_PINS + 1

    def _count_wrong_pins(self, count: int):
        self._set("wrong_pins", count)
        self._set("pin_wait_until", time.time() + wait_after(count) if count else 0)
        self._store.sync()  # on disk at once: a restart must not forget the wait

    def _matches(self, pin: str) -> bool:
        stored = str(self._get("pin", ""))
        try:
            _scheme, _iterations, salt, expected = stored.split("$")
            return hmac.compare_digest(_hash(pin, bytes.fromhex(salt)), expected)
        except ValueError:
            return False

    # --- the robot -----------------------------------------------------------------------

    @property
    def robot_locked(self) -> bool:
        """True when the teacher locked the robot choice: the Robot menu and the Run-on box stay as they
        are, and no program for another robot opens."""
        return str(self._get("robot_locked", "false")).lower() == "true"

    @robot_locked.setter
    def robot_locked(self, locked: bool):
        self._set("robot_locked", "true" if locked else "false")

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
