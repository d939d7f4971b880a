"""The public SDK for robot profiles: the only Rockly module profile code imports.

A profile's commands subclass ``RobotCommands`` and talk to the robot through the
``RobotBackend`` they are given (topics, services and actions by ROS names). Its
simulator subclasses ``RobotSimulator`` (lock, ordered publishing, clock thread, start
and shutdown) and asks a person through its tablet port (``TabletQuestion``), and its view
may read snapshots with ``with_defaults``, ``as_number``, ``as_point`` and ``as_points``. A
simulator declares its solid world as data (``World``, ``load_world``: walls and furniture its
footprint cannot enter, which its laser sees) and restores its start with ``reset()``. What a
laser sees in a direction ("ahead": a sector, ``AHEAD_HALF_WIDTH`` each side) is ``nearest_in_scan``
(``nearest_reading`` for bare ranges), the same for commands, views and the Robot state panel.
A profile adds goal kinds to lessons by subclassing ``LessonGoal`` (its ``fields`` are ``LessonField``s, its
``verdict`` a ``Verdict``; ``option_words`` names a dropdown's value as the block shows it) and naming the list in
the manifest's ``lesson_goals`` (``docs/lessons.md``).
A profile that can offer the agent's programs on the robot's own UI (``rockly agent --offer-on-robot-ui``)
subclasses ``ProgramMenu`` (its ``choose`` returns a ``MenuChoice``) and names it in the manifest's ``program_menu``.
Its words are its own gettext catalogue (``profile_texts(__file__)``: ``locale/messages.pot`` in
English and ``locale/LANG.po`` beside its profile.yaml); an error raised with one of them,
``RobotCommandError(TEXTS("key", value=...))``, is shown in the run's language.
Nothing here imports Qt; a view's drawing helpers are in ``rockly_desktop.sdk_view``.
"""
from pathlib import Path

from rockly_desktop.core.catalogue import Catalogue as Texts
from rockly_desktop.core.catalogue import LocalText
from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
from rockly_desktop.core.state_store import field_value
from rockly_desktop.lessons.goals import LessonGoal, Verdict, option_words
from rockly_desktop.lessons.schema import Field as LessonField
from rockly_desktop.profiles.manifest import MANIFEST_NAME
from rockly_desktop.robot.commands import RobotCommands
from rockly_desktop.robot.interface import GoalHandle, GoalOutcome, GoalStatus, RobotBackend
from rockly_desktop.robot.laser import AHEAD_HALF_WIDTH, nearest_in_scan, nearest_reading
from rockly_desktop.robot.program_menu import MenuChoice, ProgramMenu
from rockly_desktop.robot.sim.simulator import RobotSimulator, twist_velocity
from rockly_desktop.robot.sim.snapshot_values import as_number, as_point, as_points, with_defaults
from rockly_desktop.robot.sim.tablet import TabletQuestion
from rockly_desktop.robot.sim.world_map import Obstacle, World, load_world

__all__ = [
    "AHEAD_HALF_WIDTH", "GoalHandle", "GoalOutcome", "GoalStatus", "LessonField", "LessonGoal", "LocalText",
    "MenuChoice", "Obstacle", "Verdict", "option_words",
    "ProgramMenu", "RobotBackend",
    "RobotCommandError", "World", "RobotCommands", "RobotSimulator", "RobotTimeout", "TabletQuestion", "Texts",
    "as_number", "as_point", "as_points", "field_value", "load_world", "nearest_in_scan", "nearest_reading",
    "profile_texts", "twist_velocity", "with_defaults",
]


def profile_texts(module_file) -> Texts:
    """The catalogue of the profile a module belongs to (pass its ``__file__``): the ``locale/``
    folder beside the nearest profile.yaml above it (``messages.pot``, ``de.po``, ...)."""
    for folder in Path(module_file).resolve().parents:
        if (folder / MANIFEST_NAME).is_file():
            return Texts(folder / "locale")
    raise FileNotFoundError(f"no {MANIFEST_NAME} above {module_file}")
