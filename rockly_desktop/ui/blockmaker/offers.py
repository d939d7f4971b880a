"""What the maker offers to make a block from: the robot's topics, services, actions and parameters.

With a robot, topics come from its live graph (``RobotLink.graph_topics``, on the simulator, ROS 1
and ROS 2 alike) and services and actions from the interface its profile declares; without one,
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

    @property
    def text_key(self) -> str:
        """The catalogue key of its kind in the list: a topic, or a topic's type without a robot."""
        return f"maker_offer_{self.kind}" if self.name else f"maker_offer_{self.kind}_type"

    def label(self) -> str:
        """How the list shows it after its kind: ``/cmd_vel  (geometry_msgs/Twist)``; a type alone without a
        robot; nothing for a parameter still to be named."""
        return f"{self.name}  ({self.type})" if self.name and self.type else self.name or self.type


def robot_offers(profile, graph_topics=()) -> list:
    """The Offers of ``profile``'s robot: ``graph_topics`` ((topic, type, publishers) of the live graph)
    with the topics, services and actions the profile declares, each once, sorted by kind and name."""
    interface = profile.ros_interface or {}
    topics = {topic: msg_type for topic, msg_type, *_ in graph_topics}
    for part in ("subscribes", "publishes"):
        for topic, msg_type in (interface.get(part) or {}).items():
            topics.setdefault(topic, msg_type)
    offers = [Offer("topic", name, msg_type) for name, msg_type in topics.items()]
    offers += [Offer("service", name, srv_type) for name, srv_type in (interface.get("services") or {}).items()]
    offers += [Offer("action", name, action_type) for name, action_type in (interface.get("actions") or {}).items()]
    return _sorted(offers)


def known_offers(profile) -> list:
    """Without a robot: every type ``profile`` knows, offered by its type (the person names the topic,
    service or action after choosing it), and a parameter to name."""
    return _sorted([Offer(kind, "", type_name) for kind, definition in DEFINITION.items()
                    for type_name in known_types(profile, definition)] + [Offer("parameter", "")])


def _sorted(offers) -> list:
    order = list(KINDS_OF)
    return sorted(offers, key=lambda offer: (order.index(offer.kind), offer.name, offer.type))
