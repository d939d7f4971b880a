"""The laptop's side of pairing: the key each robot's agent gave this laptop, in the user's config folder
(``$XDG_CONFIG_HOME/rockly/robot-keys.json``, else ``~/.config/rockly/robot-keys.json``), mode 0600, written whole
or not at all. ``AgentClient`` finds its key here by the agent's address and proves it holds it."""
import base64
import binascii
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

from rockly_desktop.runtime.agent.private_files import read_json, write_private_json


def tcp_address(host: str, port: int) -> str:
    """The address of an agent reached over TCP: ``tcp:HOST:PORT``."""
    return f"tcp:{host}:{port}"


def ros_address(kind: str, where, namespace: str) -> str:
    """The address of an agent reached over ROS: ``ros1:MASTER_URI NAMESPACE``, ``ros2:DOMAIN NAMESPACE``."""
    return f"{kind}:{where} {namespace}"


@dataclass
class RobotKey:
    """What pairing with one robot's agent gave this laptop."""

    address: str  # ``tcp:HOST:PORT``, ``ros1:MASTER_URI NAMESPACE``, ``ros2:DOMAIN NAMESPACE``
    agent: str  # the agent's name (its computer's)
    client: str  # this laptop's id at that agent
    key: bytes = field(repr=False)
    role: str  # "teacher" or "student"
    fingerprint: str  # SHA-256 of the agent's TLS certificate, hex ("" over ROS): another one is refused


def default_path() -> Path:
    """``$XDG_CONFIG_HOME/rockly/robot-keys.json`` (``~/.config`` without it)."""
    config = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"), ".config")
    return Path(config) / "rockly" / "robot-keys.json"


class RobotKeys:
    """The laptop's robot keys in ``path`` (``default_path()`` when None, read when used: a test's or a user's
    config folder of the moment)."""

    def __init__(self, path: Path = None):
        self._path = Path(path) if path is not None else None

    @property
    def path(self) -> Path:
        return self._path if self._path is not None else default_path()

    def all(self) -> list:
        """Every key kept, by address."""
        try:
            data = read_json(self.path, {})
        except (OSError, ValueError):
            return []
        found = []
        for entry in data.get("robots", []) if isinstance(data, dict) else []:
            try:
                found.append(RobotKey(str(entry["address"]), str(entry["agent"]), str(entry["client"]),
                                      base64.b64decode(entry["key"], validate=True), str(entry["role"]),
                                      str(entry["fingerprint"])))
            except (TypeError, KeyError, ValueError, binascii.Error):
                continue
        return sorted(found, key=lambda key: key.address)

    def get(self, address: str) -> Optional[RobotKey]:
        """The key for the agent at ``address``, None when this laptop is not paired with it."""
        return next((key for key in self.all() if key.address == address), None)

    def save(self, key: RobotKey):
        """Keep ``key`` (in place of one for the same address)."""
        self._write([kept for kept in self.all() if kept.address != key.address] + [key])

    def forget(self, address: str) -> bool:
        """Forget the key for ``address``; False when there was none."""
        kept = self.all()
        left = [key for key in kept if key.address != address]
        if len(left) != len(kept):
            self._write(left)
        return len(left) != len(kept)

    def _write(self, keys: list):
        write_private_json(self.path, {"robots": [
            {"address": key.address, "agent": key.agent, "client": key.client,
             "key": base64.b64encode(key.key).decode("ascii"), "role": key.role, "fingerprint": key.fingerprint}
            for key in sorted(keys, key=lambda key: key.address)]})
