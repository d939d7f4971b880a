"""Where ROS 2 comes from (``.venv-ros2``) and the link settings the helper process gets.

ROS 2 is installed by ``make ros2`` (``scripts/setup-ros2.sh``) into ``.venv-ros2`` beside
Rockly's own venv; ``ROCKLY_ROS2_PYTHON`` names another Python with rclpy instead.
"""
import os
import re
from dataclasses import dataclass
from pathlib import Path

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.catalogue import LocalText
from rockly_desktop.core.ros_distributions import DISTRIBUTIONS
from rockly_desktop.robot.link import RobotUnavailable

PROJECT_ROOT = Path(__file__).resolve().parents[3]
SETUP_STEP = "make ros2"
DISCOVERY_RANGES = ("localhost", "subnet", "off", "system_default")


class Ros2Unavailable(RobotUnavailable):
    """ROS 2 is not set up here, its helper process did not start, or a link setting is wrong.

    ``reason`` names the case for a window that says it in its own language ('no_ros2':
    ``.venv-ros2`` is missing; 'helper_failed': it did not start; 'bad_domain': the domain id is
    not 0 to 232; 'bad_discovery', 'bad_distribution': a name it does not know); ``values`` are
    what the message names (``step``, ``python``, ``detail``, ``domain``, …).
    """


def declared_distribution(connection: dict) -> "str | None":
    """The ROS 2 distribution ``connection`` declares for the robot (``ros_distribution``, e.g. 'jazzy'), or
    None for 'auto' or none (the robot's graph decides, see ``robot/wrappers/ros_versions.py``). Ros2Unavailable
    ('bad_distribution') for a name Rockly does not know."""
    name = (connection.get("ros_distribution") or "").strip().lower()
    if name in ("", "auto"):
        return None
    if name not in DISTRIBUTIONS:
        raise Ros2Unavailable(f"Rockly knows the ROS 2 distributions {', '.join(DISTRIBUTIONS)}, not '{name}'",
                              "bad_distribution", distribution=name, known=", ".join(("auto",) + DISTRIBUTIONS))
    return name


def ros2_name(distribution: str = None) -> str:
    """'ROS 2', or 'ROS 2 Jazzy' for a declared distribution."""
    return f"ROS 2 {distribution.capitalize()}" if distribution else "ROS 2"


@dataclass(frozen=True)
class Ros2Settings:
    """How the link reaches the ROS 2 graph: domain id, discovery range and static peers.

    ``None`` keeps what the environment says (``ROS_DOMAIN_ID`` etc., else ROS 2's defaults:
    domain 0, subnet). ``peers`` are host names or addresses of robots to reach beyond
    the range (``ROS_STATIC_PEERS``).
    """

    domain_id: int = None
    discovery: str = None
    peers: tuple = ()

    def __post_init__(self):
        if self.domain_id is not None and not 0 <= int(self.domain_id) <= 232:
            raise ValueError(f"a ROS 2 domain id is 0 to 232, not {self.domain_id}")
        if self.discovery is not None and self.discovery not in DISCOVERY_RANGES:
            raise ValueError(f"the discovery range is one of {', '.join(DISCOVERY_RANGES)}, not {self.discovery!r}")

    @classmethod
    def from_connection(cls, connection: dict) -> "Ros2Settings":
        """The settings the connection dialog or the command line gave (``domain_id``, ``discovery``,
        ``peers`` as texts; a missing one keeps the environment's). Ros2Unavailable ('bad_domain',
        'bad_discovery') for a value ROS 2 cannot take."""
        domain = (connection.get("domain_id") or "").strip()
        if domain and not (domain.isdigit() and 0 <= int(domain) <= 232):
            raise Ros2Unavailable(f"a ROS 2 domain id is a whole number from 0 to 232, not '{domain}'",
                                  "bad_domain", domain=domain)
        discovery = (connection.get("discovery") or "").strip().lower() or None
        if discovery is not None and discovery not in DISCOVERY_RANGES:
            raise Ros2Unavailable(f"the discovery range is one of {', '.join(DISCOVERY_RANGES)}, not '{discovery}'",
                                  "bad_discovery", discovery=discovery, known=", ".join(DISCOVERY_RANGES))
        peers = tuple(peer for peer in re.split(r"[;,\s]+", connection.get("peers") or "") if peer)
        return cls(int(domain) if domain else None, discovery, peers)

    def environment(self, base=None) -> dict:
        """``base`` (the process's environment) with these settings as ROS 2's variables."""
        env = dict(os.environ if base is None else base)
        if self.domain_id is not None:
            env["ROS_DOMAIN_ID"] = str(int(self.domain_id))
        if self.discovery is not None:
            env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = self.discovery.upper()
        if self.peers:
            env["ROS_STATIC_PEERS"] = ";".join(self.peers)
        return env

    def describe(self, environment=None) -> LocalText:
        """'domain 7, localhost' (the range as ROS names it) as the status bar and health light say it,
        in their language."""
        env = self.environment(environment)
        where = {"domain": env.get("ROS_DOMAIN_ID") or 0,
                 "range": env.get("ROS_AUTOMATIC_DISCOVERY_RANGE", "subnet").lower()}
        peers = env.get("ROS_STATIC_PEERS")
        if peers:
            return app_local_text("ros2_where_peers", peers=peers.replace(";", ", "), **where)
        return app_local_text("ros2_where", **where)


def ros2_python() -> Path:
    """The Python that runs the helper; Ros2Unavailable naming the set-up step when there is none."""
    configured = os.environ.get("ROCKLY_ROS2_PYTHON")
    python = Path(configured) if configured else PROJECT_ROOT / ".venv-ros2" / "bin" / "python"
    if not python.exists():
        raise Ros2Unavailable(
            f"ROS 2 is not set up on this computer (no {python}): run '{SETUP_STEP}' in Rockly's folder "
            f"({PROJECT_ROOT}), which installs the pinned ROS 2 wheels into .venv-ros2",
            "no_ros2", step=SETUP_STEP, python=str(python))
    return python


def ros2_definition_dirs() -> list:
    """Folders with the ROS 2 environment's interface definitions (``<dir>/<pkg>/msg/*.msg``), for a
    ``DefinitionCatalog(profile.message_folders, installed_dirs=...)`` of the typed ROS blocks:
    the wheels' ``share`` of ``.venv-ros2`` (read without starting the helper) and any sourced
    ROS 2 workspaces (``AMENT_PREFIX_PATH``) — what the helper's own ``hello`` lists."""
    configured = os.environ.get("ROCKLY_ROS2_PYTHON")
    prefix = Path(configured).parents[1] if configured else PROJECT_ROOT / ".venv-ros2"
    prefixes = [prefix] + [Path(entry) for entry in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if entry]
    return [path / "share" for path in prefixes if (path / "share").is_dir()]
