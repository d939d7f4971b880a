"""Badges on the blocks that talk to the robot: their state and time, live in a run and in a replay.

The states come from ``recording/badges.py``; this module words them in the window's language
and says whether they are shown: not at a profile's Starter level (``starter``), where the
blocks stay as plain as the toolbox.
"""
from rockly_desktop.core.numbers import number_format
from rockly_desktop.ui.texts import tr

STARTER_LEVEL = "starter"


def badges_shown(settings, profile_id: str) -> bool:
    """False at the Starter level the teacher chose for this robot; True otherwise (badges, and the
    expression blocks' values on hover, alike)."""
    return settings.teacher.level(profile_id) != STARTER_LEVEL


def badge_texts(states: dict, language: str) -> dict:
    """The page's ``setBadges`` argument for ``states`` (block id -> (state, seconds or None))."""
    badges = {}
    for block, (state, seconds) in states.items():
        key = f"badge_{state}"
        took = number_format(language).format("{:.1f} s", seconds) if isinstance(seconds, (int, float)) else ""
        text = tr(key, language, seconds=took) if key != "badge_running" else tr(key, language)
        badges[block] = {"text": text.strip(), "state": state}
    return badges
