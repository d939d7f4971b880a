"""HOBBIT's house as data (``world.yaml``): the simulator bumps into it and the view draws it."""
from pathlib import Path

from rockly_desktop.sdk import load_world

WORLD = load_world(Path(__file__).with_name("world.yaml"))

CONTACT_TOPIC = "/sim/contact"   # the simulator's own: the id of what it bumped into (a real HOBBIT has none)


def bumped(obstacle_id=None):
    """{language: "HOBBIT bumped into ..."} for the obstacle with this id (``something`` when unknown)."""
    obstacle = _known(obstacle_id)
    if obstacle is None:
        return {"en": "HOBBIT bumped into something", "de": "HOBBIT ist gegen etwas gestoßen"}
    return {"en": f"HOBBIT bumped into {obstacle.name('en')}", "de": f"HOBBIT ist gegen {obstacle.name('de')} gestoßen"}


def blocked_on_the_way(obstacle_id):
    """{language: why a navigation goal was aborted}: it bumped into the obstacle on its way there."""
    obstacle = _known(obstacle_id)
    name_en, name_de = (obstacle.name("en"), obstacle.name("de")) if obstacle else ("something", "etwas")
    return {"en": f"HOBBIT bumped into {name_en} on the way", "de": f"HOBBIT ist unterwegs gegen {name_de} gestoßen"}


def goal_problem(x, y):
    """{language: why HOBBIT cannot stand at the map point (x, y)}, or None when it can."""
    if not WORLD.in_area(x, y):
        return {"en": f"the goal ({x:.2f}, {y:.2f}) is outside the map",
                "de": f"das Ziel ({x:.2f}, {y:.2f}) liegt außerhalb der Karte"}
    obstacle = WORLD.touching(x, y)
    if obstacle is None:
        return None
    return {"en": f"at the goal HOBBIT would bump into {obstacle.name('en')}",
            "de": f"am Ziel würde HOBBIT gegen {obstacle.name('de')} stoßen"}


def _known(obstacle_id):
    try:
        return WORLD.obstacle(obstacle_id)
    except KeyError:
        return None
