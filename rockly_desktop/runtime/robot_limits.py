"""The robot's own limits: a file on the robot that every run there keeps, whatever the program says.

A program carries the limits of the window it was exported from (``PROGRAM['limits']``), and whoever sends a
program writes those. So a robot keeps limits of its own, set on the robot (``rockly agent limits``) in a file
the programs' user cannot write (``docs/agent/rockly-agent.service`` keeps it read-only to the agent): a run
on the robot (the agent's, a standalone file's) keeps the stricter of the robot's and the program's.

    {"max_speed": 0.2, "max_turn": 45, "switched_off": ["arm"]}     (m/s, degrees a second; null: no limit)

No file: the robot limits nothing itself. A file that cannot be read or holds anything else refuses every run
(``RobotLimitsError``): a broken file must not lift the limits it held.
"""
import json
import math
import os
import tempfile
from pathlib import Path

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.robot.wrappers.limits import Limits

ENVIRONMENT = "ROCKLY_ROBOT_LIMITS"  # a path instead of the default


class RobotLimitsError(RocklyError):
    """The robot's limits file cannot be read: no run starts."""

    def __init__(self, path, problem):
        self.text = app_local_text("robot_limits_broken", path=path, problem=problem)
        super().__init__(str(self.text))

    def in_language(self, language: str) -> str:
        return self.text.in_language(language)


def default_path() -> Path:
    """``$ROCKLY_ROBOT_LIMITS``, else ``$XDG_CONFIG_HOME/rockly/robot-limits.json``."""
    if os.environ.get(ENVIRONMENT):
        return Path(os.environ[ENVIRONMENT])
    config = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"), ".config")
    return Path(config) / "rockly" / "robot-limits.json"


def _speed(value, name, path):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
        raise RobotLimitsError(path, f"{name} must be a number of 0 or more, or null")
    return float(value)


def read_robot_limits(path=None) -> Limits:
    """The limits in the robot's file (``default_path()`` when ``path`` is None); none without a file."""
    path = Path(path) if path is not None else default_path()
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        return Limits()
    except (OSError, UnicodeDecodeError) as error:
        raise RobotLimitsError(path, getattr(error, "strerror", None) or str(error)) from None
    try:
        data = json.loads(text)
    except ValueError as error:
        raise RobotLimitsError(path, str(error)) from None
    return robot_limits_from_data(data, path)


def robot_limits_from_data(data, path) -> Limits:
    """The ``Limits`` a limits file's ``data`` (or the agent's ``robot_limits`` request) holds; RobotLimitsError
    (naming ``path``: where the data came from) when it holds anything else."""
    if not isinstance(data, dict) or set(data) - {"max_speed", "max_turn", "switched_off"}:
        raise RobotLimitsError(path, "it must hold max_speed, max_turn and switched_off only")
    off = data.get("switched_off", [])
    if not isinstance(off, list) or not all(isinstance(name, str) for name in off):
        raise RobotLimitsError(path, "switched_off must be a list of capability ids")
    return Limits(_speed(data.get("max_speed"), "max_speed", path), _speed(data.get("max_turn"), "max_turn", path),
                  frozenset(off))


def robot_limits_data(limits: Limits) -> dict:
    """``limits`` as the file (and the agent's ``robot_limits`` answer) holds them."""
    return {"max_speed": limits.max_speed, "max_turn": limits.max_turn, "switched_off": sorted(limits.switched_off)}


def write_robot_limits(limits: Limits, path=None) -> Path:
    """Keep ``limits`` as the robot's (all or nothing); returns the file's path."""
    path = Path(path) if path is not None else default_path()
    path.parent.mkdir(parents=True, exist_ok=True)
    data = robot_limits_data(limits)
    with tempfile.NamedTemporaryFile("w", encoding="utf-8", dir=path.parent, prefix=".robot-limits-",
                                     delete=False) as stream:
        stream.write(json.dumps(data, indent=1) + "\n")
    os.chmod(stream.name, 0o644)
    os.replace(stream.name, path)
    return path
