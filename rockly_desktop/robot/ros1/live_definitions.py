"""The definitions of ROS 1 types the robot offers but Rockly has no file for, learnt from the robot.

A topic's publisher says its type's whole definition when a subscriber connects: the TCPROS
connection header carries ``message_definition`` (the type's text and every nested type's) beside
``type`` and ``md5sum``. ``topic_definition`` connects as rostopic would, reads that header and
hangs up, each step bounded in time.

A service's server says only its type and md5sum (rospy's and roscpp's probe answer has no
definition), and an action server only subscribes to its goals (its result and feedback topics do not
carry the goal's definition), so their definitions come from this computer: the type's installed
Python package, as ``roslib`` finds it; so does a topic's that nothing publishes now.
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


def installed_definition(type_name: str, kind: str):
    """The LearntDefinition of ``type_name`` (a ``kind``: msg, srv, or action as ``pkg/NameAction``) from its
    Python package installed on this computer (as ``roslib`` finds it), or None when it is not installed."""
    import roslib.message

    base = type_name[:-len("Action")] if kind == "action" and type_name.endswith("Action") else type_name
    try:
        if kind == "srv":
            service = roslib.message.get_service_class(type_name, reload_on_error=True)
            parts = service and [(type_name + "Request", service._request_class),
                                 (type_name + "Response", service._response_class)]
        else:
            parts = [(base + part, roslib.message.get_message_class(base + part, reload_on_error=True))
                     for part in (("Goal", "Result", "Feedback") if kind == "action" else ("",))]
    except (ImportError, ValueError, AttributeError, TypeError):  # roslib's ways of not finding it
        return None
    if not parts or any(found is None for _name, found in parts):
        return None
    texts, nested = [], {}
    for name, found in parts:
        said = split_full_text(name, found._full_text)
        texts.append(said.pop(name))
        nested.update(said)
    return LearntDefinition(type_name, kind, "\n---\n".join(texts), nested, parts[0][1]._full_text)


def interface_definition(master_uri: str, kind: str, name: str, type_name: str, timeout: float = ASK_SECONDS):
    """The LearntDefinition of ``type_name``, the type of the topic, service or action ``name`` (``kind``):
    a topic's from its publisher (``topic_definition``), else, and a service's or an action's always (their
    servers do not say it), from its installed package; DefinitionNotLearnt saying why and what to do."""
    if kind == "topic":
        try:
            return topic_definition(master_uri, name, timeout)
        except DefinitionNotLearnt:
            installed = installed_definition(type_name, "msg")
            if installed is None:
                raise
            return installed
    definition = {"service": "srv", "action": "action"}[kind]
    installed = installed_definition(type_name, definition)
    if installed is None:
        raise DefinitionNotLearnt(app_local_text(f"maker_learn_{kind}_unknown", type=type_name))
    return installed
