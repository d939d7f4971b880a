"""The definitions of ROS 2 types the robot offers but Rockly's profile has no file for, for the block maker.

First from this computer: the definition files of Rockly's ROS 2 environment (``ros2_definition_dirs``:
``.venv-ros2``'s wheels, sourced workspaces). Else, for a topic, from the robot: its publisher's node
describes the type (``~/get_type_description``, ROS 2 Iron on; asked by the helper, ``type_descriptions``).
A service's or an action's servers do not say their types' hashes on this ROS 2, so their definitions come
only from this computer.
"""
from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import DefinitionNotLearnt
from rockly_desktop.core.ros_definitions import DefinitionCatalog, LearntDefinition
from rockly_desktop.robot.ros2.environment import ros2_definition_dirs

ASK_SECONDS = 2.0
DEFINITION = {"topic": "msg", "service": "srv", "action": "action"}


def interface_definition(helper, kind: str, name: str, type_name: str, seconds: float = ASK_SECONDS):
    """The LearntDefinition of ``type_name``, the type of the topic, service or action ``name`` (``kind``),
    asking ``helper`` (a ``Ros2Helper``) within ``seconds`` when this computer has no file for it;
    DefinitionNotLearnt saying why and what to do."""
    definition = DEFINITION[kind]
    said = DefinitionCatalog(installed_dirs=ros2_definition_dirs()).said(type_name, definition)
    if said is not None:
        return LearntDefinition(type_name, definition, *said)
    if kind != "topic":
        raise DefinitionNotLearnt(app_local_text("maker_learn_ros2_not_here", type=type_name))
    described = helper.call("type_description", name, seconds, timeout=seconds + 10)
    if described is None:
        raise DefinitionNotLearnt(app_local_text("maker_learn_ros2_not_described", topic=name, type=type_name,
                                                 seconds=f"{seconds:g}"))
    texts = dict(described["texts"])
    return LearntDefinition(described["type"], definition, texts.pop(described["type"]), texts)
