"""HOBBIT's house as data (``world.yaml``): the simulator bumps into it and the view draws it.

Its names and what HOBBIT says about them are texts of the profile's catalogue (``locale/``).
"""
from pathlib import Path

from rockly_desktop.sdk import load_world, profile_texts

TEXTS = profile_texts(__file__)
WORLD = load_world(Path(__file__).with_name("world.yaml"), TEXTS)

CONTACT_TOPIC = "/sim/contact"   # the simulator's own: the id of what it bumped into (a real HOBBIT has none)


def bump_text(obstacle_id=None):
    """"HOBBIT bumped into ..." (a LocalText) for the obstacle with this id (``something`` when unknown)."""
    return TEXTS("bumped_into", thing=_name(obstacle_id))


def every_language(text) -> dict:
    """{language: text} of a LocalText in every language of the profile's catalogue."""
    return {language: text.in_language(language) for language in TEXTS.languages}


def bumped(obstacle_id=None):
    """{language: "HOBBIT bumped into ..."} for the obstacle with this id (``something`` when unknown)."""
    return every_language(bump_text(obstacle_id))


def blocked_on_the_way_text(obstacle_id):
    """Why a navigation goal was aborted (a LocalText): it bumped into the obstacle on its way there."""
    return TEXTS("bumped_on_the_way", thing=_name(obstacle_id))


def blocked_on_the_way(obstacle_id):
    """{language: why a navigation goal was aborted}: it bumped into the obstacle on its way there."""
    return every_language(blocked_on_the_way_text(obstacle_id))


def goal_problem_text(x, y):
    """Why HOBBIT cannot stand at the map point (x, y) (a LocalText), or None when it can."""
    if not WORLD.in_area(x, y):
        return TEXTS("goal_outside", x=x, y=y)
    obstacle = WORLD.touching(x, y)
    return None if obstacle is None else TEXTS("goal_in_furniture", thing=obstacle.label)


def goal_problem(x, y):
    """{language: why HOBBIT cannot stand at the map point (x, y)}, or None when it can."""
    problem = goal_problem_text(x, y)
    return None if problem is None else every_language(problem)


def _name(obstacle_id):
    try:
        return WORLD.obstacle(obstacle_id).label
    except KeyError:
        return TEXTS("something")
