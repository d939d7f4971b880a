"""The definitions of ROS 1 types the robot offers but Rockly has no file for, learnt from the robot.

A topic's publisher says its type's whole definition when a subscriber connects: the TCPROS
connection header carries ``message_definition`` (the type's text and every nested type's) beside
``type`` and ``md5sum``. ``topic_definition`` connects as rostopic would, reads that header and
hangs up, each step bounded in time. An action is topics: its goal's definition comes from a
publisher of its ``goal`` topic (a client), its result's from the server's ``result`` topic.

A service's server says only its type and md5sum (rospy's and roscpp's probe answer has no
definition), so a service's definition comes from this computer: the type's installed Python
package, as ``roslib`` finds it.
"""
import io
import socket
import struct
import time
import xmlrpc.client

from rosgraph.network import ROSHandshakeException, read_ros_handshake_header, write_ros_handshake_header

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import DefinitionNotLearnt
from rockly_desktop.core.ros_definitions import LearntDefinition, split_full_text
from rockly_desktop.robot.ros1.connection import ask_master

ASK_SECONDS = 2.0
_FAILED = (OSError, ValueError, struct.error, ROSHandshakeException, xmlrpc.client.Error)


def publisher_header(master_uri: str, topic: str, timeout: float = ASK_SECONDS) -> dict:
    """The connection header the first answering publisher of ``topic`` sends a subscriber;
    DefinitionNotLearnt when none publishes it or none answers within ``timeout`` s (all of them)."""
    deadline = time.monotonic() + timeout
    try:
        publishers = next((nodes for name, nodes in ask_master(master_uri, "getSystemState")[0] if name == topic), [])
    except _FAILED as error:
        raise DefinitionNotLearnt(app_local_text("maker_learn_no_master", error=str(error))) from error
    if not publishers:
        raise DefinitionNotLearnt(app_local_text("maker_learn_no_publisher", topic=topic))
    for node in publishers:
        left = deadline - time.monotonic()
        if left <= 0:
            break
        try:
            _protocol, host, port = ask_master(ask_master(master_uri, "lookupNode", node), "requestTopic",
                                               topic, [["TCPROS"]])
            with socket.create_connection((host, port), timeout=left) as connection:
                connection.settimeout(max(0.01, deadline - time.monotonic()))
                write_ros_handshake_header(connection, {"topic": topic, "md5sum": "*", "type": "*",
                                                        "callerid": "/rockly_definitions"})
                header = read_ros_handshake_header(connection, io.BytesIO(), 1 << 20)
        except _FAILED:
            continue  # gone or mute: ask the next
        if "message_definition" in header and "type" in header:
            return header
    raise DefinitionNotLearnt(app_local_text("maker_learn_no_answer", topic=topic, seconds=f"{timeout:g}"))


def topic_definition(master_uri: str, topic: str, timeout: float = ASK_SECONDS) -> LearntDefinition:
    """The message definition of ``topic`` as its publisher says it (see ``publisher_header``)."""
    header = publisher_header(master_uri, topic, timeout)
    texts = split_full_text(header["type"], header["message_definition"])
    return LearntDefinition(header["type"], "msg", texts.pop(header["type"]), texts, header["message_definition"])


def action_definition(master_uri: str, action: str, action_type: str, timeout: float = ASK_SECONDS):
    """The definition of ``action_type`` (``pkg/NameAction``) from its ``goal`` topic's publisher and its
    server's ``result`` topic: goal, result and (as far as said) feedback, as an ``.action`` text."""
    goal = topic_definition(master_uri, action.rstrip("/") + "/goal", timeout)
    result = topic_definition(master_uri, action.rstrip("/") + "/result", timeout)
    base = action_type[:-len("Action")] if action_type.endswith("Action") else action_type
    nested = {**goal.nested, **result.nested}
    text = "\n---\n".join(nested.pop(f"{base}{part}", "") for part in ("Goal", "Result", "Feedback"))
    return LearntDefinition(action_type, "action", text, nested)


def service_definition(type_name: str) -> LearntDefinition:
    """The definition of the service ``type_name`` from its installed Python package; DefinitionNotLearnt
    naming why when the package is not installed here (a service's server does not say its definition)."""
    import roslib.message

    try:
        service_class = roslib.message.get_service_class(type_name, reload_on_error=True)
    except (ImportError, ValueError, AttributeError, TypeError):
        service_class = None
    if service_class is None:
        raise DefinitionNotLearnt(app_local_text("maker_learn_service_unknown", type=type_name))
    request = split_full_text(type_name + "Request", service_class._request_class._full_text)
    response = split_full_text(type_name + "Response", service_class._response_class._full_text)
    text = request.pop(type_name + "Request") + "\n---\n" + response.pop(type_name + "Response")
    return LearntDefinition(type_name, "srv", text, {**request, **response})
