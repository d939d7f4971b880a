"""ROS message, service and action definitions read as text: the fields a typed block offers.

The typed ROS blocks show one input per field of the type a person picks. Their fields
come from the definition files themselves (``<dir>/<package>/msg/*.msg``, ``srv/*.srv``,
``action/*.action``), so the editor needs neither ROS nor any generated code: the
installed common packages (Debian's ros-*-msgs put them under ``/usr/share``) and a
profile's own definitions folder.

A type's fields are flattened to paths (``linear.x``); each leaf is a primitive the editor
can check (a number, a text, a yes/no) or an array of primitives (a list). Arrays of
messages cannot be built from blocks and are left out, as is ``header.seq``, which ROS
fills in itself.
"""
import os
import re
from dataclasses import dataclass
from pathlib import Path

COMMON_PACKAGES = ("std_msgs", "geometry_msgs", "sensor_msgs", "nav_msgs", "std_srvs")

_NUMBERS = ("int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64",
            "float32", "float64", "byte", "char", "time", "duration")
_CHECKS = {**{name: "Number" for name in _NUMBERS}, "string": "String", "bool": "Boolean"}
_FIELD_LINE = re.compile(r"^(?P<type>[A-Za-z_][\w/]*)(?P<array>\[\d*\])?\s+(?P<name>[A-Za-z_]\w*)\s*$")
_MAX_DEPTH = 6


@dataclass(frozen=True)
class FieldInput:
    """One input of a typed block: the field's path, its ROS type, and the editor's check."""

    path: str
    ros_type: str
    check: str  # Number, String, Boolean or Array


def installed_definition_dirs() -> list:
    """Folders holding installed ROS packages' definitions: ``ROS_PACKAGE_PATH``, then ``/usr/share``."""
    dirs = [entry for entry in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if entry]
    dirs.append("/usr/share")
    return [Path(entry) for entry in dict.fromkeys(dirs)]


def _declarations(text: str) -> list:
    """``(type, is_array, name)`` for each field line of one definition section (constants skipped)."""
    fields = []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line or "=" in line:
            continue
        match = _FIELD_LINE.match(line)
        if match:
            fields.append((match["type"], bool(match["array"]), match["name"]))
    return fields


def _sections(text: str) -> list:
    return re.split(r"^---\s*$", text, flags=re.MULTILINE)


class DefinitionCatalog:
    """The message, service and action types found in some folders, and their flattened fields.

    ``packages`` limits which installed packages are offered (all of a profile's own are);
    a type that refers to a package outside them is still resolved wherever it is found.
    """

    def __init__(self, own_dirs=(), installed_dirs=None, packages=COMMON_PACKAGES):
        self._roots = [Path(d) for d in own_dirs]
        self._installed = [Path(d) for d in (installed_dirs if installed_dirs is not None
                                             else installed_definition_dirs())]
        self._offered = {p.name for root in self._roots if root.is_dir() for p in root.iterdir() if p.is_dir()}
        self._offered |= set(packages)
        self._files = {}

    def _package_dir(self, package: str):
        for root in self._roots + self._installed:
            candidate = root / package
            if candidate.is_dir() and any((candidate / kind).is_dir() for kind in ("msg", "srv", "action")):
                return candidate
        return None

    def _definition(self, package: str, name: str, kind: str):
        key = (package, name, kind)
        if key not in self._files:
            directory = self._package_dir(package)
            path = directory / kind / f"{name}.{kind}" if directory else None
            self._files[key] = path.read_text(encoding="utf-8", errors="replace") if path and path.is_file() else None
        return self._files[key]

    def _types(self, kind: str) -> list:
        names = []
        for package in sorted(self._offered):
            directory = self._package_dir(package)
            if directory and (directory / kind).is_dir():
                names += [f"{package}/{path.stem}" for path in sorted((directory / kind).glob(f"*.{kind}"))]
        return names

    def _flatten(self, declarations, package: str, prefix: str = "", depth: int = 0) -> list:
        inputs = []
        for ros_type, is_array, name in declarations:
            path = prefix + name
            if ros_type in _CHECKS:
                inputs.append(FieldInput(path, ros_type + ("[]" if is_array else ""), "Array" if is_array else _CHECKS[ros_type]))
                continue
            if is_array or depth >= _MAX_DEPTH:
                continue
            full = "std_msgs/Header" if ros_type == "Header" else ros_type if "/" in ros_type else f"{package}/{ros_type}"
            sub_package, sub_name = full.split("/", 1)
            text = self._definition(sub_package, sub_name, "msg")
            if text is None:
                continue
            nested = self._flatten(_declarations(text), sub_package, path + ".", depth + 1)
            if full == "std_msgs/Header":
                nested = [field for field in nested if field.path != path + ".seq"]
            inputs += nested
        return inputs

    def fields(self, type_name: str, kind: str = "msg") -> list:
        """The inputs of a message type (``kind='msg'``), a service's request (``'srv'``) or an action's goal (``'action'``).

        Action types are named as programs name them, ``<package>/<Name>Action``.
        Returns [] for a type that is not found.
        """
        package, _, name = type_name.partition("/")
        if kind == "action":
            name = name[:-len("Action")] if name.endswith("Action") else name
        text = self._definition(package, name, kind)
        if text is None:
            return []
        return self._flatten(_declarations(_sections(text)[0]), package)

    def editor_catalog(self) -> dict:
        """For the editor page: ``{messages|services|actions: {type: [[path, check], ...]}}``."""
        def table(kind, names):
            return {name: [[field.path, field.check] for field in self.fields(name, kind)] for name in names}

        return {
            "messages": table("msg", self._types("msg")),
            "services": table("srv", self._types("srv")),
            "actions": table("action", [name + "Action" for name in self._types("action")]),
        }
