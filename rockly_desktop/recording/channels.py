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
        "capped": {"type": "object"}, "overflow": {"type": "integer"}}}),
}
PROGRAM_ATTACHMENT = "program.rockly"
METADATA = "rockly"
