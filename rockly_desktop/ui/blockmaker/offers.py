"""What the maker offers to make a block from: the robot's topics, services, actions and parameters.

With a robot, topics, services, actions and parameters come from its live graph (``LiveGraph``, read
from ``RobotLink.graph_topics``, ``graph_services``, ``graph_actions`` and ``graph_parameters`` on the
simulator, ROS 1 and ROS 2 alike; each marked ``live``), with what its profile declares; without one,
from the ROS types Rockly knows (``profiles.packs.interfaces.known_types``), named by their type.
"""
from dataclasses import dataclass

from rockly_desktop.profiles.packs.interfaces import known_types

KINDS_OF = {
    "topic": ("publish", "sensor_value", "wait_until"),
    "service": ("call_service",),
    "action": ("send_goal",),
    "parameter": ("get_param", "set_param"),
}
"""The block kinds each kind of offer can make."""
DEFINITION = {"topic": "msg", "service": "srv", "action": "action"}


@dataclass(frozen=True)
class Offer:
    """One thing to make a block from: its kind (a key of KINDS_OF), ROS name and type ("" for a parameter)."""

    kind: str
    name: str
    type: str = ""
    live: bool = False  # the robot's live graph has it now

    @property
    def text_key(self) -> str:
        """The catalogue key of its kind in the list: a topic, or a topic's type without a robot."""
        return f"maker_offer_{self.kind}" if self.name else f"maker_offer_{self.kind}_type"

    def label(self) -> str:
        """How the list shows it after its kind: ``/cmd_vel  (geometry_msgs/Twist)``; a type alone without a
        robot; nothing for a parameter still to be named."""
        return f"{self.name}  ({self.type})" if self.name and self.type else self.name or self.type


@dataclass(frozen=True)
class LiveGraph:
    """What a robot's live graph has: (topic, type, publishers), (service, type), (action, type), parameter names."""

    topics: tuple = ()
    services: tuple = ()
    actions: tuple = ()
    parameters: tuple = ()

    @classmethod
    def of(cls, link) -> "LiveGraph":
        """What ``link`` (a ``RobotLink``) last learnt of its graph (its reads never wait)."""
        return cls(tuple(link.graph_topics()), tuple(link.graph_services()), tuple(link.graph_actions()),
                   tuple(link.graph_parameters()))


def robot_offers(profile, graph: LiveGraph = LiveGraph()) -> list:
    """The Offers of ``profile``'s robot: what its live ``graph`` has (marked ``live``), with the topics,
    services and actions the profile declares, each once (typed as the graph says, else as declared),
    sorted by kind and name."""
    interface = profile.ros_interface or {}
    declared = {"topic": {**(interface.get("subscribes") or {}), **(interface.get("publishes") or {})},
                "service": interface.get("services") or {}, "action": interface.get("actions") or {}}
    live = {"topic": {topic: msg_type for topic, msg_type, *_ in graph.topics},
            "service": dict(graph.services), "action": dict(graph.actions)}
    offers = []
    for kind, names in declared.items():
        live_types = {global_name(name): type_name for name, type_name in live[kind].items()}
        offers += [Offer(kind, name, live_types.get(global_name(name)) or type_name, global_name(name) in live_types)
                   for name, type_name in names.items()]
        known = {global_name(name) for name in names}  # "move_base" declared is "/move_base" live
        offers += [Offer(kind, name, type_name, True) for name, type_name in live[kind].items()
                   if global_name(name) not in known]
    offers += [Offer("parameter", name, "", True) for name in graph.parameters]
    return _sorted(offers)


def global_name(name: str) -> str:
    """A ROS name as the graph lists it: ``move_base`` → ``/move_base``."""
    return "/" + name.strip("/")


def known_offers(profile) -> list:
    """Without a robot: every type ``profile`` knows, offered by its type (the person names the topic,
    service or action after choosing it), and a parameter to name."""
    return _sorted([Offer(kind, "", type_name) for kind, definition in DEFINITION.items()
                    for type_name in known_types(profile, definition)] + [Offer("parameter", "")])


def _sorted(offers) -> list:
    order = list(KINDS_OF)
    return sorted(offers, key=lambda offer: (order.index(offer.kind), offer.name, offer.type))
