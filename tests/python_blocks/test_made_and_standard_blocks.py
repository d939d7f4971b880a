"""Round trips through the real editor page of every made-block kind and of Blockly's standard blocks as
Rockly offers them (functions, loops, conditions, variables, lists, text, logic and math)."""
import pytest
from block_round_trip import generated, round_trip
from program_builder import block, number, rockly_document, stack, text

from rockly_desktop.bridge.headless import HeadlessEditor
from rockly_desktop.profiles.packs.making import save_block
from rockly_desktop.profiles.packs.spec import KINDS, BlockInput, MadeBlock
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.python_blocks.convert import python_to_program
from rockly_desktop.python_blocks.source import parse_source

WORDS = {"sentence": {"en": "made %1"}, "category": {"en": "Made"}, "colour": "#4c97ff"}
NUMBER_IN = (BlockInput("speed", "number", "linear.x", "m/s", 0.1, 0, 0.3),)
MADE = [
    MadeBlock("made_publish", "publish", "/cmd_vel", "geometry_msgs/Twist", NUMBER_IN, {"angular.z": 0.5}, **WORDS),
    MadeBlock("made_service", "call_service", "/hobbit/request", "hobbit_msgs/Request",
              (BlockInput("words", "text", "requestText", default="hi"),), **WORDS),
    MadeBlock("made_goal", "send_goal", "hobbit_arm", "hobbit_msgs/ArmServerAction",
              (BlockInput("movement", "text", "command.data", default="OpenGripper"),), result="outcome",
              while_waiting=True, **WORDS),
    MadeBlock("made_sensor", "sensor_value", "/odom", "nav_msgs/Odometry", read_field="pose.pose.position.x",
              **{**WORDS, "sentence": {"en": "made x"}}),
    MadeBlock("made_wait", "wait_until", "/odom", "nav_msgs/Odometry", NUMBER_IN[:0] + (
        BlockInput("at", "number", "pose.pose.position.x"),), read_field="pose.pose.position.x",
              comparison="at_least", **WORDS),
    MadeBlock("made_get", "get_param", "/speed", **{**WORDS, "sentence": {"en": "made speed"}}),
    MadeBlock("made_set", "set_param", "/speed", inputs=(BlockInput("value", "number", ""),), **WORDS),
]


def test_there_is_a_made_block_of_every_kind():
    assert sorted({made.kind for made in MADE}) == sorted(KINDS)


@pytest.fixture
def made_registry(qapp):
    registry = ProfileRegistry.discover()
    for made in MADE:
        save_block(made, registry.get("hobbit"), "round_trip")
    registry.reload_packs()
    editor = HeadlessEditor("en")
    yield registry, editor
    editor.close()


def _made_program(registry) -> list:
    hobbit = registry.get("hobbit")
    statements, values = [], []
    for made in MADE:
        spec = next(spec for spec in hobbit.blocks + hobbit.shared_blocks if spec.type == made.id)
        inputs = {name: number(0.2) for name, slot in spec.slots.items() if slot == "value"}
        if made.kind == "call_service":
            inputs = {name: text("hello") for name in inputs}
        if made.kind == "send_goal":
            inputs = {name: text("MoveToCandle") for name in inputs}
        made_block = block(made.id, inputs=inputs or None)
        if made.is_expression:
            values.append(block("variables_set", {"VAR": {"id": "v"}}, {"VALUE": made_block}))
        else:
            statements.append(made_block)
    return [stack(*statements, *values)]


def test_every_made_block_kind_round_trips(made_registry, tmp_path):
    registry, editor = made_registry
    path = tmp_path / "made.rockly"
    document = rockly_document(_made_program(registry))
    path.write_text(document)
    conversion, python, python_again, tree, tree_again = round_trip(editor, registry, path, tmp_path)
    assert all(made.id in tree for made in MADE)
    assert conversion.lossless, (conversion.kept_python, python)
    assert python_again == python
    assert tree_again == tree


STANDARD = """\
from numbers import Number
import math
import random

x = None
y = None
total = None
items = None
item = None
i = None
j = None
k = None

# Describe this function...
def add(x, y):
  global total, items, item, i, j, k
  total = x + y
  return total

# Move a little.
def step():
  global x, y, total, items, item, i, j, k
  robot.drive(0.5, 'forward')


total = 0
items = [1, 2.5, -3]
for item in items:
  if item > 2 or not item < -2:
    total = (total if isinstance(total, Number) else 0) + item
  elif item == 1:
    continue
  else:
    break
# Count down.
while not total <= 0:
  total = total - 1
while True:
  step()
  break
for count in range(int(add(1, 2))):
  robot.show_info('total: ' + str(total if total % 2 == 0 else -total))
robot.show_info(str((add(2, 3) * 2) / 4 ** 2))
x = None
y = 'a' + 'b'
print(''.join([str(x2) for x2 in [round(math.sqrt(2)), math.ceil(math.pi), math.floor(math.e)]]))
print([random.randint(1, 6)] * 3)
for i in range(5):
  for j in range(1, 11, 2):
    for k in range(10, 0, -1):
      print(i + j * k)
print(math.sin(random.random() / 180.0 * math.pi) + math.pow(10,math.fabs(-2)))
"""


def test_the_standard_blocks_as_blockly_writes_them_round_trip(headless_editor, registry, tmp_path):
    conversion = python_to_program(parse_source(STANDARD), registry.get("hobbit"))
    assert conversion.lossless, conversion.kept_python
    path = tmp_path / "standard.rockly"
    path.write_text(conversion.program.to_json())
    _, python, _ = generated(headless_editor, registry, path)
    assert python == STANDARD
    conversion, python, python_again, tree, tree_again = round_trip(headless_editor, registry, path, tmp_path)
    assert conversion.lossless and python_again == python and tree_again == tree
