"""A made block as data: what it does, which ROS interface it uses, its inputs and its words.

Kinds, by what a person picks in the maker:

- command: ``publish`` (a message once), ``call_service`` (statement, or an expression giving
  one field of the response when ``result`` names it), ``send_goal`` (wait for the goal; an
  expression giving the outcome when ``result`` is ``"outcome"``, with a "while waiting" part
  when ``while_waiting``);
- sensor: ``sensor_value`` (the latest value of the field ``read_field`` of a topic, as a
  number, text or yes/no) and ``wait_until`` (wait until that field compares to an input, or
  to ``target``);
- parameter: ``get_param`` and ``set_param``.

Each input of the block (``BlockInput``) fills one field of the message, request or goal
(by path, ``linear.x``), or for ``wait_until``/``set_param`` is the value compared or set.
Fields neither an input nor ``fixed`` keep the type's default. The sentence places input
number n at ``%n``.
"""
from dataclasses import asdict, dataclass, field

KIND_GROUPS = {
    "command": ("publish", "call_service", "send_goal"),
    "sensor": ("sensor_value", "wait_until"),
    "parameter": ("get_param", "set_param"),
}
KINDS = tuple(kind for kinds in KIND_GROUPS.values() for kind in kinds)
INTERFACE_KINDS = {"publish": "msg", "call_service": "srv", "send_goal": "action",
                   "sensor_value": "msg", "wait_until": "msg"}
"""The definition kind of each kind's interface type (parameters have none)."""
VALUE_KINDS = ("number", "text", "yes_no")
BLOCKLY_CHECKS = {"number": "Number", "text": "String", "yes_no": "Boolean"}
COMPARISONS = {"equal": "==", "not_equal": "!=", "below": "<", "above": ">", "at_most": "<=", "at_least": ">="}
OUTCOME = "outcome"


@dataclass(frozen=True)
class BlockInput:
    """One input on a made block: its slot name, kind of value, the field it fills, unit and bounds."""

    name: str
    kind: str = "number"          # one of VALUE_KINDS
    field: str = ""               # the message/request/goal field it fills ("" for wait_until/set_param)
    unit: str = ""                # shown in the tooltip, e.g. "m/s"
    default: object = None        # the value a new block shows (and used when nothing is plugged in)
    minimum: float = None         # a number input's bounds: a value outside stops the program on the block
    maximum: float = None

    @classmethod
    def from_data(cls, data: dict) -> "BlockInput":
        """An input from its YAML/JSON mapping (unknown keys are an error of the caller's data)."""
        return cls(**data)


@dataclass(frozen=True)
class MadeBlock:
    """Everything the maker knows about one block (see the module's docstring for ``kind``)."""

    id: str
    kind: str
    interface: str                 # the topic, service, action or parameter name
    interface_type: str = ""       # its ROS type (none for parameters), e.g. geometry_msgs/Twist
    inputs: tuple = ()             # BlockInputs, in %1..%n order
    fixed: dict = field(default_factory=dict)     # field path -> the value always sent
    sentence: dict = field(default_factory=dict)  # {"en": "drive at %1", "de": "fahre mit %1"}; either may be missing
    category: dict = field(default_factory=dict)  # the toolbox category's name per language
    colour: str = ""
    tooltip: dict = field(default_factory=dict)
    read_field: str = ""           # sensor_value / wait_until: the field read, e.g. pose.pose.position.x
    value_kind: str = "number"     # sensor_value: what the block gives
    comparison: str = "equal"      # wait_until: one of COMPARISONS
    target: object = None          # wait_until without an input: the value waited for
    result: str = ""               # call_service: the response field given; send_goal: "outcome"; "": a statement
    while_waiting: bool = False    # send_goal: a "while waiting" part run with each feedback

    @property
    def group(self) -> str:
        """``command``, ``sensor`` or ``parameter``."""
        return next((group for group, kinds in KIND_GROUPS.items() if self.kind in kinds), "")

    @property
    def is_expression(self) -> bool:
        """True when the block gives a value (plugs into an input) instead of stacking."""
        return self.kind in ("sensor_value", "get_param") or (
            self.kind in ("call_service", "send_goal") and bool(self.result))

    def to_data(self) -> dict:
        """The block as plain data (``made.yaml``), without empty optional entries."""
        data = asdict(self)
        data["inputs"] = [{key: value for key, value in entry.items() if value not in (None, "")}
                          for entry in data["inputs"]]
        defaults = MadeBlock(id="", kind="", interface="")
        return {key: value for key, value in data.items()
                if key in ("id", "kind", "interface") or value != getattr(defaults, key)}

    @classmethod
    def from_data(cls, data: dict) -> "MadeBlock":
        """A block from ``to_data``'s mapping; TypeError/ValueError when it is not one."""
        if not isinstance(data, dict):
            raise ValueError("a made block must be a mapping")
        values = dict(data)
        values["inputs"] = tuple(BlockInput.from_data(entry) for entry in values.get("inputs", ()))
        return cls(**values)
