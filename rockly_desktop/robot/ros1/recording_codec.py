"""Robot messages as ROS 1 writes them, for a recording's ``ros1`` channels.

A ROS feed hands over genpy messages (serialised as they are); the simulator publishes
dicts shaped like ROS messages, which become instances of the genpy classes of their
types first (``MessageTypes``: installed packages, or generated from the profile's
definitions), so a recording of the simulator reads like a recording of the robot.
"""
from io import BytesIO

import genpy

from rockly_desktop.robot.ros1.message_classes import MessageTypes
from rockly_desktop.robot.ros1.message_values import to_message


class Ros1Encoder:
    """``encoder(msg_type, message) -> (definition, bytes)``, with ``message_encoding`` 'ros1',
    ``schema_encoding`` 'ros1msg' and ``schema_name(msg_type)`` the type as it is; raises for a type
    it cannot find."""

    message_encoding = "ros1"
    schema_encoding = "ros1msg"

    def __init__(self, definition_folders=()):
        self._folders = list(definition_folders)
        self._types = None

    @staticmethod
    def schema_name(msg_type: str) -> str:
        """ROS 1 names a schema as its type (``pkg/Type``)."""
        return msg_type

    def prepare(self, msg_types):
        """Make the classes of the dict messages of ``msg_types`` now (imports and generated code: a
        tenth of a second the first time, which a recording's writer thread would otherwise spend
        beside a running program); a type that cannot be found is left to ``__call__`` to report."""
        for msg_type in msg_types:
            try:
                self._message_types().message_class(msg_type)
            except Exception:  # said when a message of it is encoded
                continue

    def _message_types(self) -> MessageTypes:
        if self._types is None:
            self._types = MessageTypes(self._folders)
        return self._types

    def __call__(self, msg_type: str, message):
        if not isinstance(message, genpy.Message):
            message = to_message(self._message_types().message_class(msg_type), message)
        buffer = BytesIO()
        message.serialize(buffer)
        return message._full_text, buffer.getvalue()


def profile_encoder(profile, msg_types=()) -> Ros1Encoder:
    """The encoder of ``profile``'s robot (its own message definitions beside the installed packages), the
    classes of ``msg_types`` made now (``Ros1Encoder.prepare``). Named by the robot-link registry."""
    encoder = Ros1Encoder(profile.message_folders)
    encoder.prepare(msg_types)
    return encoder
