"""What a ROS 1 graph offers beyond its topics: its services with their types, its actions and the
parameter server's names (for the block maker, through the state feed's thread).

A service's type is not in the master's state: its server says it when asked with a probe header
(as ``rosservice type`` asks), once while it stays listed (``ServiceTypes`` remembers it). Each ask is
bounded by PROBE_SECONDS.
"""
import io
import socket
import struct
import urllib.parse
import xmlrpc.client

from rosgraph.network import ROSHandshakeException, read_ros_handshake_header, write_ros_handshake_header

from rockly_desktop.robot.ros1.connection import ask_master

PROBE_SECONDS = 1.0
PROBES_AT_ONCE = 5  # new servers asked per call, so a graph of many mute servers holds the feed's poll up little
# the parameter server's own entries, which no robot offers
ROS_OWN_PARAMETERS = ("/rosdistro", "/rosversion", "/run_id", "/roslaunch/")


def probe_service_type(service_uri: str, name: str, timeout: float = PROBE_SECONDS) -> str:
    """The type the server at ``service_uri`` (``rosrpc://host:port``) says ``name`` has; raises
    OSError when it does not say within ``timeout`` s (ValueError, ROSHandshakeException: not a ROS header)."""
    address = urllib.parse.urlparse(service_uri)
    with socket.create_connection((address.hostname, address.port), timeout=timeout) as connection:
        connection.settimeout(timeout)
        write_ros_handshake_header(connection, {"probe": "1", "md5sum": "*", "callerid": "/rockly_graph",
                                                "service": name})
        header = read_ros_handshake_header(connection, io.BytesIO(), 65536)
    if "type" not in header:
        raise ValueError(header.get("error", "no type in the service's header"))
    return header["type"]


class ServiceTypes:
    """The types of a master's services, each asked of its server once while the service stays listed."""

    def __init__(self, master_uri: str):
        self._master_uri = master_uri
        self._known = {}  # name -> type; "" when its server did not say

    def typed(self, names) -> list:
        """(name, type) of the services ``names``, sorted; a type its server did not say (or not yet:
        PROBES_AT_ONCE are asked each call) is ""."""
        names = set(names)
        self._known = {name: type_name for name, type_name in self._known.items() if name in names}
        for name in sorted(names - set(self._known))[:PROBES_AT_ONCE]:
            try:
                self._known[name] = probe_service_type(ask_master(self._master_uri, "lookupService", name), name)
            except (OSError, ValueError, struct.error, ROSHandshakeException, xmlrpc.client.Error):  # gone, or mute
                self._known[name] = ""
        return sorted({**dict.fromkeys(names, ""), **self._known}.items())


def graph_actions(topic_types: dict) -> list:
    """(action, type as ``pkg/NameAction``) of the actionlib servers whose topics ``topic_types``
    ({topic: type}) has: an action's ``goal`` topic of a ``…ActionGoal`` type beside its ``result``."""
    actions = []
    for topic, msg_type in topic_types.items():
        action = topic[:-len("/goal")]
        if topic.endswith("/goal") and msg_type.endswith("ActionGoal") and f"{action}/result" in topic_types:
            actions.append((action, msg_type[:-len("Goal")]))
    return sorted(actions)


def parameter_names(master_uri: str) -> list:
    """The parameter server's names, without ROS's own (``/rosdistro``, ``/roslaunch/…``), sorted."""
    return sorted(name for name in ask_master(master_uri, "getParamNames")
                  if not any(name == own or name.startswith(own) for own in ROS_OWN_PARAMETERS))
