"""How healthy the connection to the robot is: green, amber or red per part, with details.

A part is the link itself (the ROS master, or the built-in simulator), each topic the
robot streams (fresh, late or silent), each of its services and action servers.
"""
from dataclasses import dataclass

from rockly_desktop.core.app_texts import app_local_text

GREEN, AMBER, RED = "green", "amber", "red"
FRESH_SECONDS, LATE_SECONDS = 2.0, 10.0


@dataclass(frozen=True)
class HealthItem:
    """One part of the robot's link: its name, level (green | amber | red) and a detail text (a
    ``LocalText``, said in the window's language; ``str()`` is English, as the command line says it)."""

    name: object
    level: str
    detail: object


def topic_health(interface: dict, topics: list, unreadable: dict = None) -> list:
    """Items for the topics the robot streams continuously, from the state store's TopicInfo list;
    ``unreadable`` names the interface package each topic Rockly cannot read here lacks."""
    seen = {info.topic: info for info in topics}
    unreadable = unreadable or {}
    items = []
    for topic in interface.get("streams", []):
        info = seen.get(topic)
        if info is None and topic in unreadable:
            items.append(HealthItem(topic, AMBER, app_local_text("health_missing_package", package=unreadable[topic])))
        elif info is None:
            items.append(HealthItem(topic, RED, app_local_text("health_no_message")))
        else:
            level = GREEN if info.age < FRESH_SECONDS else AMBER if info.age < LATE_SECONDS else RED
            items.append(HealthItem(topic, level, app_local_text("health_topic_rate", rate=round(info.rate, 1),
                                                                 age=round(info.age, 1))))
    return items


def server_health(interface: dict, available) -> list:
    """Items for the robot's services and action servers; ``available(kind, name)`` says if one is up."""
    items = []
    for kind in ("services", "actions"):
        for name in interface.get(kind, {}):
            up = available(kind, name)
            items.append(HealthItem(name, GREEN if up else RED,
                                    app_local_text("health_available" if up else "health_not_available")))
    return items


def link_state(items: list) -> str:
    """The link as a whole, said beside the health light and derived from the same ``items`` (the link's
    own item first), so the two always agree: 'connecting' (nothing known yet), 'lost' (the link itself
    is red), 'connected' (all green), 'silent' (the link works but no part of the robot answers now)
    or 'partly' (some parts answer)."""
    if not items:
        return "connecting"
    link, parts = items[0], items[1:]
    if link.level == RED:
        return "lost"
    if overall(items) == GREEN:
        return "connected"
    return "partly" if any(part.level == GREEN for part in parts) else "silent"


def overall(items: list) -> str:
    """The worst level among ``items`` (green when there are none)."""
    levels = {item.level for item in items}
    return RED if RED in levels else AMBER if AMBER in levels else GREEN
