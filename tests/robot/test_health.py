"""The link's state said beside the health light comes from the same items as the light."""
from rockly_desktop.robot.health import AMBER, GREEN, RED, HealthItem, link_state, overall


def items(link, *parts):
    return [HealthItem("link", link, "")] + [HealthItem(f"/p{index}", level, "") for index, level in enumerate(parts)]


def test_the_link_state_follows_the_health_items():
    assert link_state([]) == "connecting"
    assert link_state(items(GREEN, GREEN, GREEN)) == "connected"
    assert link_state(items(GREEN)) == "connected"
    assert link_state(items(GREEN, GREEN, RED)) == "partly"
    assert link_state(items(GREEN, AMBER, RED)) == "silent"  # nothing of the robot answers now
    assert link_state(items(GREEN, RED, RED)) == "silent"
    assert link_state(items(RED)) == "lost"


def test_connected_only_when_the_light_is_green():
    for parts in ((GREEN,), (AMBER,), (RED,), (GREEN, AMBER), (AMBER, RED)):
        assert (link_state(items(GREEN, *parts)) == "connected") == (overall(items(GREEN, *parts)) == GREEN)
