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

ROS 2's definitions (the files ``.venv-ros2/share`` holds, see ``robot.ros2.environment``)
read the same way, with what ROS 2 adds: bounded strings (``string<=10``) and arrays
(``int32[<=5]``), which ``check`` holds a value to, and default values (``int32 x 5``),
which a new block shows. Constants (``X=1``) are no fields, on either ROS.

``check`` holds a program's message dict against its type before it is sent, so a wrong
value gets the same clear message on the simulator as on a real robot.

A type the robot offers but no file defines can be taught (``learn_definition``) with the text the
robot said: ROS 1's ``message_definition`` (the type's text and each nested one's, see
``split_full_text``). What is learnt holds for every catalogue of this process (a type's name means
one type on a robot's graph), after the files: a file's definition wins. ``learnt_files`` gives what a
catalogue knows only that way as definition files, so a block pack can carry them (``profiles.packs``);
``definition_problem`` says what is wrong with such a file's text.
"""
import ast
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path

from rockly_desktop.core.errors import RobotCommandError

COMMON_PACKAGES = ("std_msgs", "geometry_msgs", "sensor_msgs", "nav_msgs", "std_srvs")

_NUMBERS = ("int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64",
            "float32", "float64", "byte", "char", "time", "duration")
_CHECKS = {**{name: "Number" for name in _NUMBERS}, "string": "String", "wstring": "String", "bool": "Boolean"}
_FIELD_LINE = re.compile(r"^(?P<type>[A-Za-z_][\w/]*)(?:<=(?P<length>\d+))?"
                         r"(?P<array>\[(?P<bounded><=)?(?P<size>\d*)\])?\s+(?P<name>[A-Za-z_]\w*)"
                         r"(?:\s+(?P<default>\S.*?))?\s*$")
_MAX_DEPTH = 6
_EXPECTED = {"Number": "a number", "String": "a text", "Boolean": "true or false"}
_STARTS = {"Number": 0, "String": "", "Boolean": False}


@dataclass(frozen=True)
class FieldInput:
    """One input of a typed block: the field's path, its ROS type, the editor's check, and
    the value a new block shows (ROS's default, except a quaternion's w: 1, turning nowhere)."""

    path: str
    ros_type: str
    check: str  # Number, String, Boolean or Array
    start: object = None


def installed_definition_dirs() -> list:
    """Folders holding installed ROS packages' definitions: ``ROS_PACKAGE_PATH``, then ``/usr/share``."""
    dirs = [entry for entry in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if entry]
    dirs.append("/usr/share")
    return [Path(entry) for entry in dict.fromkeys(dirs)]


@dataclass(frozen=True)
class _Declaration:
    """One field line: its type, whether it is an array, its name, and what ROS 2 may add."""

    ros_type: str
    is_array: bool
    name: str
    default: object = None     # a ROS 2 default value
    max_length: int = None     # string<=N
    max_items: int = None      # T[<=N] (and T[N], a fixed size)


def _declarations(text: str) -> list:
    """The ``_Declaration`` of each field line of one definition section (constants skipped)."""
    fields = []
    for raw in text.splitlines():
        line = _without_comment(raw).strip()
        if not line or re.match(r"^\S+\s+[A-Za-z_]\w*\s*=", line):
            continue
        match = _FIELD_LINE.match(line)
        if match:
            size = match["size"]
            fields.append(_Declaration(
                match["type"], bool(match["array"]), match["name"], _literal(match["default"]),
                int(match["length"]) if match["length"] else None, int(size) if size else None))
    return fields


def _without_comment(line: str) -> str:
    """``line`` up to its ``#`` comment (a ``#`` inside a quoted default value stays)."""
    quote = None
    for index, char in enumerate(line):
        if quote:
            quote = None if char == quote and line[index - 1] != "\\" else quote
        elif char in "'\"":
            quote = char
        elif char == "#":
            return line[:index]
    return line


def _literal(text):
    """A default value as written in a ROS 2 definition, as Python (None when there is none)."""
    if text is None:
        return None
    words = {"true": True, "false": False}
    if text.lower() in words:
        return words[text.lower()]
    try:
        return ast.literal_eval(re.sub(r"\b(true|false)\b", lambda m: m[1].capitalize(), text, flags=re.IGNORECASE))
    except (ValueError, SyntaxError):
        return text


@dataclass(frozen=True)
class LearntDefinition:
    """A type's definition as the robot said it: ``type_name`` (``pkg/Type``; an action ``pkg/NameAction``),
    its ``kind`` (msg, srv, action), its own ``text`` and the types nested in it (``{pkg/Type: text}``);
    a message's ``full_text`` as its publisher sent it."""

    type_name: str
    kind: str
    text: str
    nested: dict = field(default_factory=dict)
    full_text: str = ""


_LEARNT = {}  # (package, name, kind) -> a definition a robot said, for types no file defines


def learn_definition(type_name: str, kind: str, text: str, nested=None) -> None:
    """Know ``type_name`` (a ``kind``: msg, srv or action; an action named ``pkg/NameAction`` or
    ``pkg/Name``) by its definition ``text`` and the messages nested in it (``nested``: ``{pkg/Type: text}``),
    as a robot said them, in every catalogue of this process."""
    for full, definition, its_kind in [*((name, body, "msg") for name, body in (nested or {}).items()),
                                       (type_name, text, kind)]:
        package, _, name = full.partition("/")
        if its_kind == "action" and name.endswith("Action"):
            name = name[:-len("Action")]
        _LEARNT[(package, name, its_kind)] = definition


_NESTED_MARK = re.compile(r"^={10,}\s*\nMSG:\s*(\S+)\s*$", re.MULTILINE)


def split_full_text(type_name: str, text: str) -> dict:
    """``{type: its definition}`` of ``type_name`` and each type nested in it, from a definition's full
    text as ROS 1 sends it (``message_definition``: the type's own, then each nested type's after a line
    of ``=`` and ``MSG: package/Type``)."""
    parts = _NESTED_MARK.split(text)
    found = {type_name: parts[0]}
    found.update(zip(parts[1::2], parts[2::2]))
    return found


def _sections(text: str) -> list:
    return re.split(r"^---\s*$", text, flags=re.MULTILINE)


DEFINITION_KINDS = ("msg", "srv", "action")
_PART_COUNTS = {"msg": 1, "srv": 2, "action": 3}
_CONSTANT = re.compile(r"^[A-Za-z_][\w/]*\s+[A-Za-z_]\w*\s*=")


def definition_problem(text: str, kind: str):
    """What is wrong with ``text`` as the definition of a ``kind`` (msg, srv, action), in words
    naming the line; None when every line is a field, a constant, a comment or ``---`` where one belongs."""
    sections = _sections(text)
    if len(sections) != _PART_COUNTS[kind]:
        return (f"a .{kind} definition has {_PART_COUNTS[kind] - 1} '---' line(s) between its parts, "
                f"this one has {len(sections) - 1}")
    for number, raw in enumerate(text.splitlines(), 1):
        line = _without_comment(raw).strip()
        if line and line != "---" and not _CONSTANT.match(line) and not _FIELD_LINE.match(line):
            return f"line {number} is neither a field ('TYPE NAME') nor a constant ('TYPE NAME=VALUE'): {raw.strip()!r}"
    return None


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
        return self._files[key] if self._files[key] is not None else _LEARNT.get(key)

    def _types(self, kind: str) -> list:
        names = []
        for package in sorted(self._offered):
            directory = self._package_dir(package)
            if directory and (directory / kind).is_dir():
                names += [f"{package}/{path.stem}" for path in sorted((directory / kind).glob(f"*.{kind}"))]
        return names

    def _resolve(self, ros_type: str, package: str):
        """``(full type name, declarations)`` of a field's message type, or None when not found."""
        full = "std_msgs/Header" if ros_type == "Header" else ros_type if "/" in ros_type else f"{package}/{ros_type}"
        text = self._definition(*full.split("/", 1), "msg")
        return (full, _declarations(text)) if text is not None else None

    def _top(self, type_name: str, kind: str, section: int = 0):
        """``(package, declarations)`` of a message, a service's request or an action's goal (``section``
        1: a response or result, 2: an action's feedback), or None."""
        package, _, name = type_name.partition("/")
        if kind == "action":
            name = name[:-len("Action")] if name.endswith("Action") else name
        text = self._definition(package, name, kind)
        if text is None:
            return None
        sections = _sections(text)
        return (package, _declarations(sections[section])) if section < len(sections) else (package, [])

    def said(self, type_name: str, kind: str = "msg"):
        """``type_name``'s definition as ``learn_definition`` takes it, ``(text, {nested pkg/Type: text})``
        (every message type it uses, however deep), or None when it is not found."""
        package, _, name = str(type_name).partition("/")
        if kind == "action" and name.endswith("Action"):
            name = name[:-len("Action")]
        text = self._definition(package, name, kind)
        if text is None:
            return None
        nested = {}
        pending = [(declaration, package) for section in _sections(text) for declaration in _declarations(section)]
        while pending:
            declaration, owner = pending.pop()
            resolved = None if declaration.ros_type in _CHECKS else self._resolve(declaration.ros_type, owner)
            if resolved is not None and resolved[0] not in nested:
                full, declarations = resolved
                nested[full] = self._definition(*full.split("/", 1), "msg")
                pending += [(inner, full.split("/")[0]) for inner in declarations]
        return text, nested

    def learnt_files(self, type_name: str, kind: str = "msg", into=None) -> dict:
        """``{"package/kind/Name.kind": text}`` of ``type_name`` and the types nested in it that this catalogue
        knows only because a robot said them (``learn_definition``): no file defines them and no folder but
        ``into`` (the one they are to be written to) holds their package (a new file of it elsewhere would hide
        that folder's others). {} for a type not found."""
        said = self.said(type_name, kind)
        if said is None:
            return {}
        package, _, name = str(type_name).partition("/")
        if kind == "action" and name.endswith("Action"):
            name = name[:-len("Action")]
        files = {}
        for key in [(package, name, kind), *((*full.split("/", 1), "msg") for full in said[1])]:
            folder = self._package_dir(key[0])
            if self._definition(*key) is not None and self._files.get(key) is None and key in _LEARNT \
                    and (folder is None or (into is not None and folder.parent == Path(into))):
                files[f"{key[0]}/{key[2]}/{key[1]}.{key[2]}"] = _LEARNT[key]
        return files

    def knows(self, type_name: str, kind: str = "msg") -> bool:
        """True when the definition of ``type_name`` (a ``kind``: msg, srv or action) is found."""
        return "/" in str(type_name) and self._top(str(type_name), kind) is not None

    def type_names(self, kind: str = "msg") -> list:
        """The types of ``kind`` offered: the common installed packages' and the profile's own
        (actions named ``<package>/<Name>Action``, as programs name them)."""
        names = self._types(kind)
        return [name + "Action" for name in names] if kind == "action" else names

    def _flatten(self, declarations, package: str, prefix: str = "", depth: int = 0) -> list:
        inputs = []
        for declaration in declarations:
            ros_type, is_array, path = declaration.ros_type, declaration.is_array, prefix + declaration.name
            if ros_type in _CHECKS:
                check = "Array" if is_array else _CHECKS[ros_type]
                start = _STARTS.get(check) if declaration.default is None else declaration.default
                inputs.append(FieldInput(path, ros_type + ("[]" if is_array else ""), check, start))
                continue
            resolved = None if is_array or depth >= _MAX_DEPTH else self._resolve(ros_type, package)
            if resolved is None:
                continue
            full, nested_declarations = resolved
            nested = self._flatten(nested_declarations, full.split("/")[0], path + ".", depth + 1)
            if full == "std_msgs/Header":
                nested = [field for field in nested if field.path != path + ".seq"]
            if full == "geometry_msgs/Quaternion":  # all zeros is no rotation at all, but an invalid one
                nested = [replace(field, start=1) if field.path == path + ".w" else field for field in nested]
            inputs += nested
        return inputs

    def fields(self, type_name: str, kind: str = "msg", section: int = 0) -> list:
        """The inputs of a message type (``kind='msg'``), a service's request (``'srv'``)
        or an action's goal (``'action'``); ``section`` 1 gives a response's or result's
        fields, 2 an action's feedback's.

        Action types are named as programs name them, ``<package>/<Name>Action``.
        Returns [] for a type that is not found.
        """
        top = self._top(type_name, kind, section)
        return self._flatten(top[1], top[0]) if top else []

    def message_arrays(self, type_name: str, kind: str = "msg", section: int = 0) -> list:
        """The top-level fields of ``type_name`` (as ``fields`` names its parts) that are arrays of
        messages, which blocks cannot build field by field: ``[(name, "package/Type[]")]``."""
        top = self._top(type_name, kind, section)
        if top is None:
            return []
        package, declarations = top
        found = []
        for declaration in declarations:
            if declaration.is_array and declaration.ros_type not in _CHECKS:
                resolved = self._resolve(declaration.ros_type, package)
                full = resolved[0] if resolved else declaration.ros_type
                found.append((declaration.name, full + "[]"))
        return found

    def check(self, type_name: str, kind: str, data) -> None:
        """Raise RobotCommandError naming the field when ``data`` does not fit the type.

        A type (or a nested type) that is not found is not checked: the robot's side
        decides then.
        """
        top = self._top(str(type_name), kind)
        if top is not None:
            self._check_message(top[1], top[0], data, str(type_name), "")

    def _check_message(self, declarations, package, data, type_name, prefix):
        if not isinstance(data, Mapping):
            raise RobotCommandError(f"{prefix.rstrip('.') or 'the message'} must be a {type_name} "
                                    f"(a mapping of its fields), not {data!r}")
        by_name = {declaration.name: declaration for declaration in declarations}
        for key, value in data.items():
            if key not in by_name:
                subject = f"{prefix.rstrip('.')} (a {type_name})" if prefix else type_name
                raise RobotCommandError(f"{subject} has no field '{key}' (it has: {', '.join(by_name) or 'none'})")
            declaration = by_name[key]
            path = prefix + key
            if declaration.is_array:
                if not isinstance(value, (list, tuple)):
                    raise RobotCommandError(f"the field {path} needs a list, not {value!r}")
                if declaration.max_items is not None and len(value) > declaration.max_items:
                    raise RobotCommandError(f"the field {path} holds at most {declaration.max_items} items, "
                                            f"not {len(value)}")
                for index, item in enumerate(value):
                    self._check_value(declaration, package, item, f"{path}[{index}]")
            else:
                self._check_value(declaration, package, value, path)

    def _check_value(self, declaration, package, value, path):
        ros_type = declaration.ros_type
        check = _CHECKS.get(ros_type)
        if check is None:
            resolved = self._resolve(ros_type, package)
            if resolved is not None:
                full, declarations = resolved
                self._check_message(declarations, full.split("/")[0], value, full, path + ".")
            return
        fits = {"Number": isinstance(value, (int, float)) and not isinstance(value, bool),
                "String": isinstance(value, str),
                "Boolean": isinstance(value, bool) or value in (0, 1)}[check]
        if ros_type in ("time", "duration") and isinstance(value, Mapping):
            fits = set(value) <= {"secs", "nsecs"}
        if not fits:
            raise RobotCommandError(f"the field {path} needs {_EXPECTED[check]}, not {value!r}")
        if declaration.max_length is not None and len(value) > declaration.max_length:
            raise RobotCommandError(f"the field {path} holds at most {declaration.max_length} characters, "
                                    f"not {len(value)}")

    @cached_property
    def editor_catalog(self) -> dict:
        """For the editor page: ``{messages|services|actions: {type: [[path, check, start], ...]}}``
        (read once: the definition files are not expected to change while Rockly runs)."""
        def table(kind, names):
            return {name: [[field.path, field.check, field.start] for field in self.fields(name, kind)]
                    for name in names}

        return {
            "messages": table("msg", self._types("msg")),
            "services": table("srv", self._types("srv")),
            "actions": table("action", [name + "Action" for name in self._types("action")]),
        }
