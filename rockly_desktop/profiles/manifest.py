"""The profile manifest (``profile.yaml``): its schema and validation.

The manifest is static data, read without importing any profile code. Every field is
described once in ``MANIFEST_FIELDS``; validation and the written reference both come
from that table, so they cannot drift apart.
"""
import re
from dataclasses import dataclass
from pathlib import Path

from rockly_desktop.core.app_texts import languages
from rockly_desktop.core.errors import ManifestError
from rockly_desktop.core.ros_distributions import KEYS as ROS_VERSION_KEYS
from rockly_desktop.profiles.i18n import is_localized
from rockly_desktop.profiles.yaml_files import read_yaml_mapping

MANIFEST_NAME = "profile.yaml"
SCHEMA_VERSION = 1

_IDENTIFIER = re.compile(r"^[a-z][a-z0-9_]{0,39}$")
_VERSION = re.compile(r"^\d+(\.\d+){0,2}([.-][0-9A-Za-z.]+)?$")
_IMPORT_PATH = re.compile(r"^[A-Za-z_][\w]*(\.[A-Za-z_]\w*)*:[A-Za-z_]\w*$")


@dataclass(frozen=True)
class FieldSpec:
    """One manifest field: its name, kind of value, whether it is required, and what it means."""

    name: str
    kind: str
    required: bool
    description: str


MANIFEST_FIELDS = (
    FieldSpec("schema", "schema", True, f"Manifest format version; this Rockly reads {SCHEMA_VERSION}."),
    FieldSpec("id", "identifier", True, "Unique profile id: lower-case letters, digits, '_'. Saved in programs."),
    FieldSpec("name", "text", True, "Name shown to users (may be translated)."),
    FieldSpec("version", "version", True, "The profile's own version, e.g. 1.0.0."),
    FieldSpec("description", "text", False, "One sentence about the robot (may be translated)."),
    FieldSpec("languages", "languages", False, "Languages the profile's texts are written in; English first."),
    FieldSpec("blocks", "file", True, "YAML file with the block definitions and each block's Python template."),
    FieldSpec("toolbox", "file", True, "YAML file with the toolbox categories (own and shared ones by name)."),
    FieldSpec("python_path", "folder", False,
              "Folder added to the import path for the profile's modules (default: the profile folder)."),
    FieldSpec("api", "import", True, "module:Class with the robot's Python commands, bound as `robot` in programs."),
    FieldSpec("simulator", "import", False,
              "module:Class of the built-in simulated robot: Class(world, tablet=, speed=)."),
    FieldSpec("simulator_view", "import", False,
              "module:Class of the QWidget drawing the simulator (set_snapshot(dict))."),
    FieldSpec("program_menu", "program_menu", False,
              "How `rockly agent --offer-on-robot-ui` offers the robot's programs on its own UI: {hook: "
              "module:Class (an SDK ProgramMenu), stop: true (offer Stop while one runs), answer_seconds: N (how "
              "long one question waits before it is asked anew; default 60), pairing: true (a person at the robot "
              "may ask it for a one-time pairing code, shown there)}."),
    FieldSpec("lesson_goals", "import", False,
              "module:NAME of a list of the goal kinds the robot adds to lessons (SDK LessonGoal classes; "
              "docs/lessons.md)."),
    FieldSpec("messages", "folder", False, "Folder with ROS definitions the robot needs: <package>/msg|srv|action/*."),
    FieldSpec("ros_interface", "ros_interface", False,
              "The robot's ROS interface: {subscribes: {TOPIC: TYPE}, publishes: {...}, services: {NAME: TYPE}, "
              "actions: {NAME: TYPE}, streams: [TOPIC, ...], qos: {TOPIC: QOS} (ROS 2)}."),
    FieldSpec("ros_versions", "ros_versions", False,
              "Types that differ per ROS version: {NAME: {ros1|ros2|DISTRIBUTION: TYPE}}, e.g. "
              "{/cmd_vel: {jazzy: geometry_msgs/TwistStamped}}; a distribution (humble, iron, jazzy, kilted, "
              "rolling) counts from that one on; elsewhere the ros_interface type holds."),
    FieldSpec("safe_stop", "safe_stop", False,
              "What 'stop' means for this robot: a list of {publish: ...}, {cancel_goals: ACTION}."),
    FieldSpec("state", "state", False,
              "Live state panels: [{panel: TITLE, rows: [{label, topic, field, format?, transform?, values?, "
              "nothing?}]}]."),
    FieldSpec("legacy_fields", "legacy_fields", False,
              "Old field names of saved programs: {block_type: {old_field: {field: new, values: {old: new}}}}."),
    FieldSpec("velocity_topics", "velocity_topics", False,
              "The drive interface: geometry_msgs/Twist (or TwistStamped) topics (e.g. [/cmd_vel]) a teacher's "
              "speed limits clamp."),
    FieldSpec("own_speed", "own_speed", False,
              "Motions the robot makes at its own speed, which no speed limit can slow: {speed: M/S, turn: DEG/S, "
              "topics: [...], services: [...], actions: [...]}; refused while a teacher's limit is lower (the "
              "safe_stop's messages always pass)."),
    FieldSpec("capabilities", "capabilities", False,
              "Parts a teacher can switch off: [{id, name, blocks: [TYPE...], topics: [...], services: [...], "
              "actions: [...]}]; their commands are refused, their blocks hidden."),
    FieldSpec("levels", "levels", False,
              "Toolbox levels a teacher picks: [{id, name, categories: [NAME...] or all, blocks: [TYPE...]}]; "
              "a category by its English or shared name."),
)


def _check_text(value):
    if isinstance(value, str) and value.strip():
        return None
    if is_localized(value) and all(isinstance(text, str) and text.strip() for text in value.values()):
        return None
    return "must be a non-empty text, or one text per language with English ('en') present"


def _check_relative_path(value, root: Path, want_dir: bool):
    if not isinstance(value, str) or not value.strip():
        return "must be a path relative to the profile folder"
    target = (root / value).resolve()
    if root.resolve() not in (target, *target.parents):
        return "must stay inside the profile folder"
    exists = target.is_dir() if want_dir else target.is_file()
    if not exists:
        return f"names '{value}', which does not exist in the profile folder"
    return None


def _check_safe_stop(value):
    if not isinstance(value, list):
        return "must be a list of actions"
    for index, action in enumerate(value):
        if not isinstance(action, dict) or len(action) != 1:
            return f"item {index + 1} must be one action: {{publish: ...}} or {{cancel_goals: ACTION}}"
        (kind, body), = action.items()
        if kind == "publish":
            if not isinstance(body, dict) or not {"topic", "type"} <= set(body):
                return f"item {index + 1}: publish needs 'topic' and 'type' (and optional 'message')"
        elif kind == "cancel_goals":
            if not isinstance(body, str) or not body:
                return f"item {index + 1}: cancel_goals needs an action name"
        else:
            return f"item {index + 1}: unknown action '{kind}' (use publish or cancel_goals)"
    return None


STATE_TRANSFORMS = ("yaw_degrees", "degrees", "percent", "goal_state", "nearest_ahead")


def _check_state(value):
    if not isinstance(value, list):
        return "must be a list of panels"
    for index, panel in enumerate(value):
        if not isinstance(panel, dict) or _check_text(panel.get("panel")) or not isinstance(panel.get("rows"), list):
            return f"panel {index + 1} needs a 'panel' title and a list of 'rows'"
        for number, row in enumerate(panel["rows"]):
            where = f"panel {index + 1}, row {number + 1}"
            if not isinstance(row, dict) or _check_text(row.get("label")):
                return f"{where} needs a 'label'"
            if not isinstance(row.get("topic"), str) or not isinstance(row.get("field"), str):
                return f"{where} needs a 'topic' and a 'field' (e.g. pose.pose.position.x)"
            if row.get("transform", "yaw_degrees") not in STATE_TRANSFORMS:
                return f"{where}: unknown transform '{row['transform']}' (use {', '.join(STATE_TRANSFORMS)})"
            values = row.get("values", {})
            if not isinstance(values, dict) or any(_check_text(text) for text in values.values()):
                return f"{where}: 'values' must name the robot's values for people ({{value: text}})"
            if "nothing" in row and _check_text(row["nothing"]):
                return f"{where}: 'nothing' must be a text"
    return None


QOS_NAMES = ("reliable", "best_effort", "sensor_data", "transient_local")
_QOS_KEYS = {"reliability": ("reliable", "best_effort"), "durability": ("volatile", "transient_local")}


def _check_qos(qos):
    """None when ``qos`` maps topics to a QoS name or {reliability, durability, depth}; else the problem."""
    problem = (f"'qos' must map topics to one of {', '.join(QOS_NAMES)} or to "
               "{reliability: reliable|best_effort, durability: volatile|transient_local, depth: N}")
    if not isinstance(qos, dict):
        return problem
    for setting in qos.values():
        if isinstance(setting, str):
            if setting not in QOS_NAMES:
                return problem
        elif not isinstance(setting, dict) or set(setting) - {*_QOS_KEYS, "depth"} or any(
                setting[key] not in choices for key, choices in _QOS_KEYS.items() if key in setting) or not (
                isinstance(setting.get("depth", 1), int) and setting.get("depth", 1) > 0):
            return problem
    return None


def _check_ros_interface(value):
    if not isinstance(value, dict) or set(value) - {"subscribes", "publishes", "services", "actions", "streams", "qos"}:
        return "must be a mapping with subscribes, publishes, services, actions, streams and qos"
    streams = value.get("streams", [])
    if not isinstance(streams, list) or not set(streams) <= set(value.get("publishes", {})):
        return "'streams' must list published topics that arrive continuously (the health light watches them)"
    if "qos" in value and _check_qos(value["qos"]):
        return _check_qos(value["qos"])
    for part, names in value.items():
        if part in ("streams", "qos"):
            continue
        if not isinstance(names, dict) or not all(isinstance(k, str) and isinstance(v, str) and "/" in v
                                                  for k, v in names.items()):
            return f"'{part}' must map ROS names to types like geometry_msgs/Twist"
    return None


def _check_ros_versions(value, ros_interface):
    """None when ``value`` maps names declared in ``ros_interface`` to {version or distribution: type}."""
    if not isinstance(value, dict) or not value:
        return "must map ROS names to their types per version, e.g. {/cmd_vel: {jazzy: geometry_msgs/TwistStamped}}"
    declared = set()
    for part in ("subscribes", "publishes", "services", "actions"):
        names = ros_interface.get(part) if isinstance(ros_interface, dict) else None
        declared.update("/" + str(name).strip("/") for name in (names or {}))
    keys = ", ".join(ROS_VERSION_KEYS)
    for name, types in value.items():
        if not isinstance(name, str) or "/" + name.strip("/") not in declared:
            return f"'{name}' is not in ros_interface: declare it there with its usual type first"
        if not isinstance(types, dict) or not types:
            return f"'{name}' must map ROS versions or distributions ({keys}) to types"
        for key, type_name in types.items():
            if key not in ROS_VERSION_KEYS:
                return f"'{name}': unknown ROS version or distribution '{key}' (use {keys})"
            if not isinstance(type_name, str) or type_name.count("/") not in (1, 2) or not all(
                    type_name.split("/")):
                return f"'{name}.{key}' must be a type like geometry_msgs/TwistStamped, not {type_name!r}"
    return None


def _check_legacy_fields(value):
    if not isinstance(value, dict):
        return "must map block types to their old field names"
    for block_type, fields in value.items():
        if not isinstance(fields, dict):
            return f"'{block_type}' must map old field names to {{field: NEW, values: {{...}}}}"
        for old_name, alias in fields.items():
            if not isinstance(alias, dict) or not isinstance(alias.get("field"), str):
                return f"'{block_type}.{old_name}' needs 'field: NEW_NAME'"
            if not isinstance(alias.get("values", {}), dict):
                return f"'{block_type}.{old_name}.values' must map old values to new ones"
    return None


def _check_names(entry: dict, keys, where: str):
    for key in keys:
        names = entry.get(key, [])
        if not isinstance(names, list) or not all(isinstance(name, str) and name for name in names):
            return f"{where}: '{key}' must be a list of names"
    return None


def _check_entries(value, what: str, keys):
    """Problems common to capabilities and levels: a list of {id, name, ...} with unique ids."""
    if not isinstance(value, list) or not value:
        return f"must be a non-empty list of {what}"
    seen = set()
    for index, entry in enumerate(value):
        where = f"item {index + 1}"
        if not isinstance(entry, dict):
            return f"{where} must be a mapping with 'id' and 'name'"
        unknown = set(entry) - {"id", "name", *keys}
        if unknown:
            return f"{where}: unknown key(s) {sorted(unknown)} (use id, name, {', '.join(keys)})"
        if not isinstance(entry.get("id"), str) or not _IDENTIFIER.fullmatch(entry["id"]):
            return f"{where} needs an 'id' of lower-case letters, digits and '_'"
        if entry["id"] in seen:
            return f"{where}: the id '{entry['id']}' is used twice"
        seen.add(entry["id"])
        if _check_text(entry.get("name")):
            return f"{where} ('{entry['id']}') needs a 'name' (a text, or one per language with 'en')"
    return None


def _check_capabilities(value):
    problem = _check_entries(value, "capabilities", ("blocks", "topics", "services", "actions"))
    if problem:
        return problem
    for index, entry in enumerate(value):
        where = f"item {index + 1} ('{entry['id']}')"
        problem = _check_names(entry, ("blocks", "topics", "services", "actions"), where)
        if problem:
            return problem
        if not any(entry.get(key) for key in ("topics", "services", "actions")):
            return f"{where} must name the topics, services or actions it covers"
    return None


def _check_own_speed(value):
    if not isinstance(value, dict):
        return "must be a mapping with speed, turn, topics, services, actions"
    unknown = set(value) - {"speed", "turn", "topics", "services", "actions"}
    if unknown:
        return f"unknown key(s) {sorted(unknown)} (use speed, turn, topics, services, actions)"
    for key in ("speed", "turn"):
        speed = value.get(key)
        if speed is not None and (isinstance(speed, bool) or not isinstance(speed, (int, float)) or not speed > 0):
            return f"'{key}' must be a number above zero"
    return _check_names(value, ("topics", "services", "actions"), "own_speed")


def _check_levels(value):
    problem = _check_entries(value, "levels", ("categories", "blocks"))
    if problem:
        return problem
    for index, entry in enumerate(value):
        where = f"item {index + 1} ('{entry['id']}')"
        if entry.get("categories") != "all":
            problem = _check_names(entry, ("categories", "blocks"), where)
            if problem:
                return problem.replace("a list of names", "a list of names (or, for categories, all)")
            if not entry.get("categories") and not entry.get("blocks"):
                return f"{where} must list 'categories' or 'blocks' (or say categories: all)"
    return None


def _check_program_menu(value):
    if not isinstance(value, dict) or not isinstance(value.get("hook"), str) \
            or not _IMPORT_PATH.fullmatch(value["hook"]):
        return "must say its hook: {hook: 'package.module:Class', stop: true|false, answer_seconds: N, pairing: " \
               "true|false}"
    unknown = set(value) - {"hook", "stop", "answer_seconds", "pairing"}
    if unknown:
        return f"unknown key(s) {sorted(unknown)} (use hook, stop, answer_seconds, pairing)"
    for flag in ("stop", "pairing"):
        if not isinstance(value.get(flag, False), bool):
            return f"'{flag}' must be true or false"
    seconds = value.get("answer_seconds", 60)
    if isinstance(seconds, bool) or not isinstance(seconds, (int, float)) or not 0 < seconds <= 3600:
        return "'answer_seconds' must be a number of seconds above 0 and at most 3600"
    return None


def _check(spec: FieldSpec, value, root: Path):
    """Return a problem description for one field's value, or None if it is fine."""
    kind = spec.kind
    if kind == "schema":
        if isinstance(value, bool) or value != SCHEMA_VERSION:
            return f"must be {SCHEMA_VERSION} (this Rockly does not read schema {value!r})"
    elif kind == "identifier":
        if not isinstance(value, str) or not _IDENTIFIER.fullmatch(value):
            return "must be lower-case letters, digits and '_', starting with a letter (at most 40)"
    elif kind == "text":
        return _check_text(value)
    elif kind == "version":
        if not isinstance(value, str) or not _VERSION.fullmatch(value):
            return "must be a version text like '1.0.0' (quote it in YAML)"
    elif kind == "languages":
        if not isinstance(value, list) or not value or value[0] != "en":
            return "must be a list of language codes starting with 'en'"
        unknown = [lang for lang in value if lang not in languages()]
        if unknown:
            return f"unsupported language(s) {unknown}; Rockly speaks {list(languages())}"
    elif kind == "file":
        return _check_relative_path(value, root, want_dir=False)
    elif kind == "folder":
        return _check_relative_path(value, root, want_dir=True)
    elif kind == "import":
        if not isinstance(value, str) or not _IMPORT_PATH.fullmatch(value):
            return "must be 'package.module:Name'"
    elif kind == "list":
        if not isinstance(value, list):
            return "must be a list"
    elif kind == "safe_stop":
        return _check_safe_stop(value)
    elif kind == "legacy_fields":
        return _check_legacy_fields(value)
    elif kind == "state":
        return _check_state(value)
    elif kind == "ros_interface":
        return _check_ros_interface(value)
    elif kind == "velocity_topics":
        if not isinstance(value, list) or not all(isinstance(topic, str) and topic.startswith("/") for topic in value):
            return "must be a list of topic names like /cmd_vel"
    elif kind == "own_speed":
        return _check_own_speed(value)
    elif kind == "capabilities":
        return _check_capabilities(value)
    elif kind == "levels":
        return _check_levels(value)
    elif kind == "program_menu":
        return _check_program_menu(value)
    return None


def read_fields(path: Path, fields, root: Path, check=None) -> dict:
    """Read the manifest-like YAML file at ``path`` whose fields are ``fields`` (FieldSpecs; files they
    name are relative to ``root``); raise ManifestError on the first unknown, missing or wrong field.
    ``check(spec, value, data)`` may say a field's problem itself (None: the usual check)."""
    data = read_yaml_mapping(path)
    known = [spec.name for spec in fields]
    for name in data:
        if name not in known:
            raise ManifestError(path, name, f"unknown field (known fields: {', '.join(known)})")
    for spec in fields:
        if spec.name not in data:
            if spec.required:
                raise ManifestError(path, spec.name, f"is missing: {spec.description}")
            continue
        problem = (check and check(spec, data[spec.name], data)) or _check(spec, data[spec.name], root)
        if problem:
            raise ManifestError(path, spec.name, problem)
    return data


def read_manifest(profile_dir: Path) -> dict:
    """Read and validate ``profile.yaml`` in ``profile_dir``; raise ManifestError on the first problem."""
    def ros_versions(spec, value, data):
        return _check_ros_versions(value, data.get("ros_interface", {})) if spec.kind == "ros_versions" else None

    return read_fields(profile_dir / MANIFEST_NAME, MANIFEST_FIELDS, profile_dir, ros_versions)
