"""Robot messages as ROS 2 writes them, for a recording's ``cdr`` channels with ``ros2msg`` schemas.

Rockly's process has no rclpy: a type's schema is its ``.msg`` file from the ROS 2 environment's
interface packages (``ros2_definition_dirs``) followed by those of the types it uses, each after
a line of 80 ``=`` and ``MSG: pkg/msg/Type`` (as rosbag2 writes them), and mcap-ros2-support's
pure-Python serialiser encodes the state store's message dicts from that text. A dict's keys the
type does not have (the ROS 1 ``secs``/``nsecs`` of a stamp) are left out.
"""
import re
from pathlib import Path

from mcap_ros2._dynamic import serialize_dynamic

from rockly_desktop.robot.ros2.environment import ros2_definition_dirs

_PRIMITIVES = {"bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
               "int32", "uint32", "int64", "uint64", "string", "wstring"}
_SEPARATOR = "=" * 80
_CONSTANT = re.compile(r"^\S+\s+[A-Za-z_]\w*\s*=")


def ros2_type_name(msg_type: str) -> str:
    """``pkg/msg/Type`` for ``pkg/Type`` (the state store's spelling) or ``pkg/msg/Type``."""
    parts = msg_type.strip("/").split("/")
    return f"{parts[0]}/msg/{parts[-1]}"


def _used_types(text: str, package: str) -> list:
    """The message types the fields of a ``.msg`` text use, as ``pkg/msg/Type``, in order."""
    used = []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line or _CONSTANT.match(line):
            continue
        field_type = re.split(r"[\[<\s]", line, maxsplit=1)[0]
        if field_type in _PRIMITIVES:
            continue
        if field_type == "Header":
            field_type = "std_msgs/Header"
        used.append(ros2_type_name(field_type if "/" in field_type else f"{package}/{field_type}"))
    return used


class Ros2Schemas:
    """The ``ros2msg`` schema texts of the message types found in ``dirs`` (``<dir>/<pkg>/msg/<Type>.msg``)."""

    def __init__(self, dirs):
        self._dirs = [Path(folder) for folder in dirs]
        self._texts = {}

    def _definition(self, full_name: str) -> str:
        if full_name not in self._texts:
            package, _msg, name = full_name.split("/")
            for folder in self._dirs:
                path = folder / package / "msg" / f"{name}.msg"
                if path.is_file():
                    self._texts[full_name] = path.read_text(encoding="utf-8")
                    break
            else:
                raise LookupError(f"no definition of {full_name} in {', '.join(map(str, self._dirs)) or 'no folder'}")
        return self._texts[full_name]

    def schema(self, full_name: str) -> str:
        """The type's definition followed by those of every type it uses (LookupError for one not found)."""
        top = self._definition(full_name)
        parts, seen, pending = [top.rstrip("\n")], {full_name}, _used_types(top, full_name.split("/")[0])
        while pending:
            used = pending.pop(0)
            if used in seen:
                continue
            seen.add(used)
            text = self._definition(used)
            parts.append(f"{_SEPARATOR}\nMSG: {used}\n{text.rstrip(chr(10))}")
            pending += _used_types(text, used.split("/")[0])
        return "\n".join(parts) + "\n"


class Ros2Encoder:
    """``encoder(msg_type, message dict) -> (schema text, CDR bytes)``, with ``message_encoding`` 'cdr',
    ``schema_encoding`` 'ros2msg' and ``schema_name(msg_type)`` ``pkg/msg/Type``; raises for a type whose
    definition is not found or a message its type cannot hold."""

    message_encoding = "cdr"
    schema_encoding = "ros2msg"

    def __init__(self, definition_dirs=None):
        self._schemas = Ros2Schemas(ros2_definition_dirs() if definition_dirs is None else definition_dirs)
        self._encoders = {}

    schema_name = staticmethod(ros2_type_name)

    def __call__(self, msg_type: str, message):
        name = ros2_type_name(msg_type)
        if name not in self._encoders:
            text = self._schemas.schema(name)
            self._encoders[name] = (text, serialize_dynamic(name, text)[name])
        text, encode = self._encoders[name]
        return text, encode(message)


def profile_encoder(profile, msg_types=()) -> Ros2Encoder:
    """The encoder of a robot on ROS 2: its schemas are ROS 2's own ``.msg`` files, whatever ``profile``
    and ``msg_types`` (read when first used). Named by the robot-link registry."""
    return Ros2Encoder()
