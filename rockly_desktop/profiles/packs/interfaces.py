"""The ROS types Rockly knows without a robot, and their fields: what the maker offers.

Types come from the profile's ``messages`` folder and the common installed packages (the
same ``DefinitionCatalog`` the typed ROS blocks use). Fields are flattened to paths
(``pose.pose.position.x``), as the Plot and the typed blocks name them.
"""
from dataclasses import dataclass

from rockly_desktop.profiles.packs.spec import INTERFACE_KINDS

PARTS = {"in": 0, "out": 1, "feedback": 2}
"""Which part of a type: a message, request or goal (``in``); a response or result (``out``);
an action's feedback."""
_KINDS = {"Number": "number", "String": "text", "Boolean": "yes_no", "Array": "list"}


@dataclass(frozen=True)
class InterfaceField:
    """One field of a type: its path, ROS type (``float64``, ``string[]``), the kind of value
    a block gives it (``number``, ``text``, ``yes_no``, ``list``, or ``messages`` for an array of
    messages) and its default."""

    path: str
    ros_type: str
    kind: str
    default: object = None


def known_types(profile, kind: str) -> list:
    """The type names of ``kind`` (``msg``, ``srv``, ``action``) that ``profile`` knows without a robot."""
    return profile.ros_types.type_names(kind)


def knows_type(profile, type_name: str, kind: str) -> bool:
    """True when ``profile`` knows the definition of ``type_name`` (a ``kind``)."""
    return profile.ros_types.knows(type_name, kind)


def interface_fields(profile, type_name: str, kind: str, part: str = "in") -> list:
    """The fields of ``type_name`` (``kind`` msg, srv or action) in ``part`` (see PARTS), nested
    fields by path; [] for a type ``profile`` does not know. A top-level array of messages is one
    field of kind ``messages`` (it can only be given a fixed value: a list of mappings)."""
    catalog = profile.ros_types
    fields = [InterfaceField(entry.path, entry.ros_type, _KINDS[entry.check], entry.start)
              for entry in catalog.fields(type_name, kind, PARTS[part])]
    return fields + [InterfaceField(name, ros_type, "messages", [])
                     for name, ros_type in catalog.message_arrays(type_name, kind, PARTS[part])]


def fields_of_block_kind(profile, block_kind: str, type_name: str) -> list:
    """The fields a made block of ``block_kind`` can fill (publish, call_service, send_goal) or
    read (sensor_value, wait_until) on ``type_name``; [] for parameters."""
    kind = INTERFACE_KINDS.get(block_kind)
    return interface_fields(profile, type_name, kind) if kind else []


def field_tree(fields) -> dict:
    """``fields`` as a nested mapping, for a tree view: ``{"linear": {"x": InterfaceField}}``."""
    tree = {}
    for entry in fields:
        *parents, leaf = entry.path.split(".")
        node = tree
        for name in parents:
            node = node.setdefault(name, {})
        node[leaf] = entry
    return tree
