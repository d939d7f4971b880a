"""Rockly's own channels in a recording: their topics and JSON schemas, shared by writer and reader."""

RUN = "/rockly/run"            # start, pause, resume, safe stop, end (with the error)
BLOCKS = "/rockly/blocks"      # a block entered (its time is the message's log time)
VARIABLES = "/rockly/variables"
OUTPUT = "/rockly/output"      # what the program printed; {"skipped": n}: n lines printed too fast to record
COMMANDS = "/rockly/commands"  # what the program sent to the robot, and what came back
VALUES = "/rockly/values"      # expression blocks' last values, the ones that changed (when values are on)
SIMULATOR = "/rockly/simulator"  # the simulator's snapshots, for the replay's simulator view
STATS = "/rockly/recording"    # what the recording left out (rate cap, full queue)

_TEXT = {"type": "string"}
SCHEMAS = {
    RUN: ("rockly.RunEvent", {"type": "object", "properties": {
        "event": {"enum": ["start", "pause", "resume", "safe_stop", "end"]},
        "block": _TEXT, "reason": _TEXT, "outcome": _TEXT, "message": _TEXT, "failures": {"type": "array"}},
        "required": ["event"]}),
    BLOCKS: ("rockly.BlockEntered", {"type": "object", "properties": {
        "block": _TEXT, "type": _TEXT, "sampled": {"type": "boolean"}}, "required": ["block"]}),
    VARIABLES: ("rockly.Variables", {"type": "object", "properties": {
        "values": {"type": "object", "additionalProperties": {"type": ["string", "null"]}}}}),
    VALUES: ("rockly.BlockValues", {"type": "object", "properties": {
        "values": {"type": "object", "additionalProperties": {"type": "string"}}}}),
    OUTPUT: ("rockly.Output", {"type": "object", "properties": {"text": _TEXT, "skipped": {"type": "integer"}}}),
    COMMANDS: ("rockly.Command", {"type": "object", "properties": {
        "kind": {"enum": ["publish", "call", "response", "goal", "feedback", "outcome", "cancel", "failed"]},
        "name": _TEXT, "type": _TEXT, "block": _TEXT, "data": {}, "status": _TEXT, "text": _TEXT,
        "seconds": {"type": "number"}}, "required": ["kind", "name"]}),
    SIMULATOR: ("rockly.SimulatorSnapshot", {"type": "object"}),
    STATS: ("rockly.RecordingStats", {"type": "object", "properties": {
        "capped": {"type": "object"}, "overflow": {"type": "integer"}, "dropped": {"type": "object"}}}),
}
PROGRAM_ATTACHMENT = "program.rockly"
METADATA = "rockly"

_KINDS = {"object": (dict,), "array": (list,), "string": (str,), "number": (int, float), "integer": (int,),
          "boolean": (bool,), "null": ()}


def fits(topic: str, value) -> bool:
    """Whether ``value`` is what Rockly's channel ``topic`` holds: its JSON schema's types, enums and
    required keys (the part of JSON Schema ``SCHEMAS`` use), where a null stands for "none" in it."""
    if topic not in _CHECKS:
        _CHECKS[topic] = _check(SCHEMAS[topic][1])
    return isinstance(value, dict) and _CHECKS[topic](value)


def _check(schema: dict):
    """A function telling whether a value fits ``schema`` (made once per channel: events are many)."""
    if not schema:
        return _anything
    kinds = schema.get("type", ())
    kinds = (kinds,) if isinstance(kinds, str) else tuple(kinds)
    types = tuple(python for kind in kinds for python in _KINDS[kind])
    not_bool = "boolean" not in kinds  # True is an int to Python, not a number to JSON
    enum, required = schema.get("enum"), tuple(schema.get("required", ()))
    properties = {key: _check(part) for key, part in schema.get("properties", {}).items()}
    others = schema.get("additionalProperties", {})
    other = _check(others if isinstance(others, dict) else {})

    def check(value) -> bool:
        if value is None:
            return True
        if enum is not None and value not in enum:
            return False
        if types and (not isinstance(value, types) or not_bool and isinstance(value, bool)):
            return False
        if isinstance(value, dict):
            return all(key in value for key in required) and all(
                properties.get(key, other)(item) for key, item in value.items())
        return True
    return check


def _anything(_value) -> bool:
    return True


_CHECKS = {}
